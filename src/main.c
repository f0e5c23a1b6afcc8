/* main.c - the utak command: reads a world, runs Utak in it, prints what happened.
 *
 * The only file that sees both sides of the wall (impression.h): it owns the body
 * (World, Table: the simulator) and hands the mind only impressions. It alone
 * prints diagnostics and chooses the exit status: 0 done, 1 a task was not
 * achieved, 2 bad usage or bad input. */
#include <getopt.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "utak/act.h"
#include "utak/eye.h"
#include "utak/motion.h"
#include "utak/regions.h"
#include "utak/retina.h"
#include "utak/table.h"
#include "utak/task.h"
#include "utak/util.h"
#include "utak/world.h"
#include "utak/worldmodel.h"

#define UTAK_VERSION "0.1.0"

static const char usage_text[] =
	"usage: utak [OPTIONS] WORLD [TASK]\n"
	"Runs Utak, the robot of Rosenberg and Jenkin's TABLETOP, in the world file WORLD.\n"
	"\n"
	"  --act SCRIPT   carry out motor commands, e.g. \"move 3 0; grasp; push 0 5; turn 90; release\"\n"
	"  --dump LIST    print dumps after the commands, comma-separated:\n"
	"                 table, retina, touch, regions, model\n"
	"  -o FILE        write the final state as a world file\n"
	"  -n, --dry-run  read WORLD and TASK, say how the task reads, and stop\n"
	"  -h, --help     this text\n"
	"  -V, --version  the version\n"
	"See utak(1) and, for the world file, utak(5).\n";

/* The dumps, in the order they are printed whatever order --dump names them. */
typedef struct Body {
	World world;
	Table table;
	Impression sensed;	/* what the senses gave after the last halt */
} Body;

/* The mind: the controller side. It is handed impressions and the commands it
 * gave, nothing else (impression.h). */
typedef struct Mind {
	Impression impression;	/* the last impression received */
	Regions regions;	/* its regions and their reading (paper 3.4.1-3.4.2) */
	WorldModel model;	/* what Utak believes (paper 3.3-3.5) */
} Mind;

/* mind_start: initialization steps 1-5 of paper 3.1. */
static void mind_start(Mind *m, const Impression *first)
{
	worldmodel_init(&m->model);
	m->impression = *first;
	regions_find(&m->regions, first);
	worldmodel_accommodate_first(&m->model, first);
}

/* mind_perceive: step 11 of paper 3.1, after the command it gave. */
static void mind_perceive(Mind *m, const MotorCommand *cmd, const Impression *imp)
{
	m->impression = *imp;
	regions_find(&m->regions, imp);
	worldmodel_accommodate(&m->model, cmd, imp);
}

typedef void DumpFn(const Body *b, const Mind *m, FILE *f);

static void dump_table(const Body *b, const Mind *m, FILE *f)
{
	(void)m;
	fprintf(f, "TABLE %d x %d, north at the top:\n", (int)b->table.w, (int)b->table.h);
	table_dump(&b->table, &b->world, f);
}

static void dump_retina(const Body *b, const Mind *m, FILE *f)
{
	(void)m;
	fputs("retina, ahead at the top:\n", f);
	eye_print_picture(b->sensed.level, f);
}

static void dump_touch(const Body *b, const Mind *m, FILE *f)
{
	(void)m;
	fputs("touch, ahead at the top:\n", f);
	retina_print_touch(&b->sensed, f);
}

static void dump_regions(const Body *b, const Mind *m, FILE *f)
{
	(void)b;
	regions_dump(&m->regions, f);
}

static void dump_model(const Body *b, const Mind *m, FILE *f)
{
	(void)b;
	worldmodel_dump(&m->model, f);
}

static const struct {
	const char *name;
	DumpFn *fn;
} dumps[] = {
	{"table", dump_table},
	{"retina", dump_retina},
	{"touch", dump_touch},
	{"regions", dump_regions},
	{"model", dump_model},
};
enum { DUMP_COUNT = sizeof dumps / sizeof dumps[0] };

static int usage_error(const char *fmt, const char *arg)
{
	fputs("utak: ", stderr);
	fprintf(stderr, fmt, arg);
	fputs(" (utak --help for usage)\n", stderr);
	return 2;
}

/* parse_dumps(list, want): sets want[i] for each name in the comma-separated list. */
static int parse_dumps(const char *list, bool want[DUMP_COUNT])
{
	const char *s = list;
	for (;;) {
		size_t n = strcspn(s, ",");
		int i = 0;
		while (i < DUMP_COUNT && !(strlen(dumps[i].name) == n && strncmp(dumps[i].name, s, n) == 0))
			i++;
		if (i == DUMP_COUNT) {
			char known[256] = "";
			for (int k = 0; k < DUMP_COUNT; k++) {
				strcat(known, k ? ", " : "");
				strcat(known, dumps[k].name);
			}
			fprintf(stderr, "utak: --dump: unknown dump '%.*s' (known: %s)\n", (int)(n > 40 ? 40 : n),
				s, known);
			return 2;
		}
		want[i] = true;
		if (s[n] == 0)
			return 0;
		s += n + 1;
	}
}

int main(int argc, char **argv)
{
	static const struct option longopts[] = {
		{"act", required_argument, NULL, 'a'},
		{"dump", required_argument, NULL, 'd'},
		{"help", no_argument, NULL, 'h'},
		{"dry-run", no_argument, NULL, 'n'},
		{"version", no_argument, NULL, 'V'},
		{NULL, 0, NULL, 0},
	};
	const char *act = NULL, *outfile = NULL;
	bool want[DUMP_COUNT] = {false}, any_dump = false, dry_run = false;
	int c;
	opterr = 0;
	while ((c = getopt_long(argc, argv, ":o:hnV", longopts, NULL)) != -1) {
		switch (c) {
		case 'a':
			act = optarg;
			break;
		case 'd':
			if (parse_dumps(optarg, want))
				return 2;
			any_dump = true;
			break;
		case 'o':
			outfile = optarg;
			break;
		case 'n':
			dry_run = true;
			break;
		case 'h':
			fputs(usage_text, stdout);
			return 0;
		case 'V':
			puts("utak " UTAK_VERSION);
			return 0;
		case ':':
			return usage_error("option '%s' needs an argument", argv[optind - 1]);
		default:
			return usage_error("unknown option '%s'", argv[optind - 1]);
		}
	}
	if (optind >= argc)
		return usage_error("%s", "no WORLD file given");
	if (argc - optind > 2)
		return usage_error("too many arguments, from '%s' (quote the TASK)", argv[optind + 2]);
	const char *path = argv[optind], *task = optind + 1 < argc ? argv[optind + 1] : NULL;
	Diag d;
	Task goal;
	if (task && task_parse(task, &goal, &d)) {
		fprintf(stderr, "utak: %s\n", d.msg);
		return 2;
	}
	if (task && act)
		return usage_error("%s", "give either --act or a TASK, not both");
	if (task && !dry_run) {
		fprintf(stderr, "utak: the controller is not built yet; drive Utak with --act\n");
		return 2;
	}

	MotorCommand *cmds = NULL;
	int ncmds = 0;
	if (act && act_parse(act, strlen(act), &cmds, &ncmds, &d)) {
		fprintf(stderr, "utak: %s\n", d.msg);
		return 2;
	}
	Body body;
	if (world_read(&body.world, path, &d) || table_build(&body.table, &body.world, &d)) {
		world_free(&body.world); /* safe on a world that failed to read */
		fprintf(stderr, "utak: %s\n", d.msg);
		free(cmds);
		return 2;
	}
	if (dry_run) {
		if (task) {
			char form[64];
			const char *number = task_paper_number(&goal);
			task_short_form(&goal, form, sizeof form);
			printf("task: \"%s\" reads as \"%s\"", task, form);
			if (number)
				printf(", the paper's task %s", number);
			putchar('\n');
		}
		free(cmds);
		table_free(&body.table);
		world_free(&body.world);
		return 0;
	}
	if (!any_dump)
		want[0] = true; /* the TABLE */

	Mind mind;
	retina_sense(&body.world, &body.table, &body.sensed);
	mind_start(&mind, &body.sensed);
	for (int i = 0; i < ncmds; i++) {
		MotorOutcome out;
		motion_execute(&body.world, &body.table, &cmds[i], &out);
		printf("act %d: ", i + 1);
		motion_print(&cmds[i], &out, stdout);
		putchar('\n');
		/* Utak halts: a fresh impression, and the mind perceives it (paper 3.1 steps 10-11). */
		retina_sense(&body.world, &body.table, &body.sensed);
		mind_perceive(&mind, &cmds[i], &body.sensed);
	}
	for (int i = 0; i < DUMP_COUNT; i++)
		if (want[i])
			dumps[i].fn(&body, &mind, stdout);

	int status = 0;
	if (outfile) {
		FILE *f = fopen(outfile, "w");
		if (!f) {
			fprintf(stderr, "utak: %s: cannot write\n", outfile);
			status = 2;
		} else {
			world_write(&body.world, f);
			if (fclose(f) != 0) {
				fprintf(stderr, "utak: %s: cannot write\n", outfile);
				status = 2;
			}
		}
	}
	free(cmds);
	worldmodel_free(&mind.model);
	table_free(&body.table);
	world_free(&body.world);
	return status;
}
