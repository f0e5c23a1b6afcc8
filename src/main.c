/* main.c - the utak command: reads a world, runs Utak in it, prints what happened.
 *
 * The only file that sees both sides of the wall (impression.h): it owns the body
 * (World, Table: the simulator) and the mind (Controller), and passes between them
 * only impressions and motor commands. It alone prints diagnostics and chooses the
 * exit status: 0 done, 1 a task was not achieved, 2 bad usage or bad input. */
#include <errno.h>
#include <getopt.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "utak/body/act.h"
#include "utak/mind/controller.h"
#include "utak/base/eye.h"
#include "utak/body/judge.h"
#include "utak/body/motion.h"
#include "utak/body/retina.h"
#include "utak/replay.h"
#include "utak/svg.h"
#include "utak/body/table.h"
#include "utak/base/task.h"
#include "utak/base/util.h"
#include "utak/body/world.h"

/* The Makefile reads the version from this line (utak-plan.pc). */
#define UTAK_VERSION "0.2.0"
/* The default limit on action cycles: several times what any task in worlds/
 * needs, small enough that a hopeless task ends within a second or two. */
#define UTAK_MAX_CYCLES 300
/* The largest --max-cycles accepted. */
#define UTAK_MAX_CYCLES_LIMIT 100000

static const char usage_text[] =
	"usage: utak [OPTIONS] WORLD [TASK]\n"
	"Runs Utak, the robot of Rosenberg and Jenkin's TABLETOP, in the world file WORLD,\n"
	"on TASK (e.g. \"go ne-corner\", \"Push the square into the northeast corner\").\n"
	"\n"
	"  --act SCRIPT      carry out motor commands instead of a task,\n"
	"                    e.g. \"move 3 0; grasp; push 0 5; turn 90; release\"\n"
	"  --dump LIST       print dumps, comma-separated: table, retina, touch, regions,\n"
	"                    model, screen, skeleton, pathgraph, rooms, path\n"
	"  --planner NAME    skeleton (the paper's, default), grid or visibility\n"
	"  --max-cycles N    give up a task after N action cycles (default 300)\n"
	"  --noise SIGMA     noisy motion: each move and push goes astray by a Gaussian\n"
	"                    of SIGMA squares per square moved, each turn likewise\n"
	"  --seed N          the seed of the noise (default 1)\n"
	"  --svg FILE        draw the run as an SVG picture\n"
	"  --html FILE       write a replay of the run, cycle by cycle, as one HTML page\n"
	"  --step            print every dump after each cycle and wait for Enter\n"
	"  -q, --quiet       print only the verdict of a task\n"
	"  -v, --verbose     print every dump after every cycle\n"
	"  -o FILE           write the final state as a world file\n"
	"  -n, --dry-run     read WORLD and TASK, say how the task reads, and stop\n"
	"  -h, --help        this text\n"
	"  -V, --version     the version and the licence\n"
	"See utak(1) and, for the world file, utak(5).\n";

typedef struct Body {
	World world;
	Table table;
	MotionNoise noise; /* the simulator's motor noise (sigma 0: exact) */
	Impression sensed; /* what the senses gave after the last halt */
} Body;

/* ---- dumps -------------------------------------------------------------------------- */

typedef void DumpFn(const Body *b, Controller *c, FILE *f);

static void dump_table(const Body *b, Controller *c, FILE *f)
{
	(void)c;
	fprintf(f, "TABLE %d x %d, north at the top:\n", (int)b->table.w, (int)b->table.h);
	table_dump(&b->table, &b->world, f);
}

static void dump_retina(const Body *b, Controller *c, FILE *f)
{
	(void)c;
	fputs("retina, ahead at the top:\n", f);
	eye_print_picture(b->sensed.level, f);
}

static void dump_touch(const Body *b, Controller *c, FILE *f)
{
	(void)c;
	fputs("touch, ahead at the top:\n", f);
	retina_print_touch(&b->sensed, f);
}

static void dump_regions(const Body *b, Controller *c, FILE *f)
{
	(void)b;
	regions_dump(&c->regions, f);
}

static void dump_model(const Body *b, Controller *c, FILE *f)
{
	(void)b;
	worldmodel_dump(&c->model, f);
}

static void dump_screen(const Body *b, Controller *c, FILE *f)
{
	(void)b;
	controller_dump_screen(c, f);
}

static void dump_skeleton(const Body *b, Controller *c, FILE *f)
{
	(void)b;
	controller_dump_skeleton(c, f);
}

static void dump_pathgraph(const Body *b, Controller *c, FILE *f)
{
	(void)b;
	controller_dump_pathgraph(c, f);
}

static void dump_rooms(const Body *b, Controller *c, FILE *f)
{
	(void)b;
	controller_dump_rooms(c, f);
}

static void dump_path(const Body *b, Controller *c, FILE *f)
{
	(void)b;
	controller_dump_path(c, f);
}

/* The dumps, in the order they are printed whatever order --dump names them. */
static const struct {
	const char *name;
	DumpFn *fn;
} dumps[] = {
	{"table", dump_table},	     {"retina", dump_retina},	  {"touch", dump_touch},
	{"regions", dump_regions},   {"model", dump_model},	  {"screen", dump_screen},
	{"skeleton", dump_skeleton}, {"pathgraph", dump_pathgraph}, {"rooms", dump_rooms},
	{"path", dump_path},
};
enum { DUMP_COUNT = sizeof dumps / sizeof dumps[0], DUMP_TABLE = 0, DUMP_RETINA = 1 };

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
			fprintf(stderr, "utak: --dump: unknown dump '%.*s' (known: %s)\n", (int)(n > 40 ? 40 : n), s,
				known);
			return 2;
		}
		want[i] = true;
		if (s[n] == 0)
			return 0;
		s += n + 1;
	}
}

static void print_dumps(const bool want[DUMP_COUNT], const Body *b, Controller *c)
{
	for (int i = 0; i < DUMP_COUNT; i++)
		if (want[i])
			dumps[i].fn(b, c, stdout);
}

/* ---- the run ------------------------------------------------------------------------ */

typedef struct Options {
	const char *act, *outfile, *svgfile, *htmlfile, *task_text;
	bool want[DUMP_COUNT], any_dump, dry_run, quiet, verbose, step;
	PlannerKind planner;
	long max_cycles;
	double noise;          /* --noise SIGMA */
	unsigned long long seed; /* --seed N */
} Options;

/* write_file(path, fn, ctx): writes an output file with fn, every write checked.
 * Returns 0, or 2 after "utak: PATH: reason" on stderr. */
typedef int WriteFn(FILE *f, void *ctx);
static int write_file(const char *path, WriteFn *fn, void *ctx)
{
	FILE *f = fopen(path, "w");
	if (!f) {
		fprintf(stderr, "utak: %s: %s\n", path, strerror(errno));
		return 2;
	}
	errno = 0;
	bool failed = fn(f, ctx) != 0 || ferror(f);
	int why = errno;
	if (fclose(f) != 0 && !failed) {
		failed = true;
		why = errno;
	}
	if (failed) {
		fprintf(stderr, "utak: %s: %s\n", path, why ? strerror(why) : "write error");
		return 2;
	}
	return 0;
}

/* What the replay's page is written from (write_file's ctx). */
typedef struct ReplayOut {
	Replay *rec;
	const char *verdict;
} ReplayOut;

static int write_replay(FILE *f, void *ctx)
{
	const ReplayOut *r = ctx;
	return replay_write(r->rec, r->verdict, f);
}

/* What the picture is drawn from (write_file's ctx). */
typedef struct SvgOut {
	const Body *body;
	const Controller *ctl;
	const Vec2 *trail;
	int count;
	const char *title, *verdict;
} SvgOut;

static int write_svg(FILE *f, void *ctx)
{
	const SvgOut *s = ctx;
	svg_draw(f, &s->body->world, &s->body->table, s->ctl, s->trail, s->count, s->title, s->verdict);
	return 0;
}

/* step_wait(stepping): --step: waits for a line on standard input; "q" or the end
 * of the input stops the waiting (the run goes on to its end). */
static void step_wait(bool *stepping)
{
	if (!*stepping)
		return;
	fputs("-- Enter: the next cycle; q: run to the end --\n", stderr);
	fflush(stdout);
	char line[64];
	if (!fgets(line, sizeof line, stdin) || line[0] == 'q')
		*stepping = false;
}

/* act(o, body, ctl, cmds, n): the --act run: each command, its outcome, and the
 * mind perceiving the impression that follows (paper 3.1 steps 10-11). */
static int run_act(const Options *o, Body *body, Controller *ctl, const MotorCommand *cmds, int n)
{
	Replay *rec = o->htmlfile ? replay_new(&body->world, &body->table, NULL, planner_name(o->planner)) : NULL;
	if (rec)
		replay_start(rec, &body->world, &body->table, &body->sensed, ctl);
	for (int i = 0; i < n; i++) {
		MotorOutcome out;
		motion_execute_noisy(&body->world, &body->table, &cmds[i], &body->noise, &out);
		printf("act %d: ", i + 1);
		motion_print(&cmds[i], &out, stdout);
		putchar('\n');
		retina_sense(&body->world, &body->table, &body->sensed);
		controller_perceive(ctl, &cmds[i], &body->sensed);
		if (rec)
			replay_cycle(rec, &body->world, &body->table, &body->sensed, ctl, &cmds[i], &out);
	}
	if (!o->any_dump) {
		bool table_only[DUMP_COUNT] = {[DUMP_TABLE] = true};
		print_dumps(table_only, body, ctl);
	} else {
		print_dumps(o->want, body, ctl);
	}
	int status = 0;
	if (rec) {
		char verdict[64];
		snprintf(verdict, sizeof verdict, "%d motor commands carried out", n);
		status = write_file(o->htmlfile, write_replay, &(ReplayOut){rec, verdict});
		replay_free(rec);
	}
	return status;
}

/* run_task(o, body, ctl, task): the action cycle on a task, then the verdict of the
 * ground truth. Returns the exit status. */
static int run_task(const Options *o, Body *body, Controller *ctl, const Task *task, World *start)
{
	char form[64];
	task_short_form(task, form, sizeof form);
	if (!o->quiet) {
		const char *number = task_paper_number(task);
		printf("task: %s%s%s, planner %s", form, number ? ", the paper's task " : "", number ? number : "",
		       planner_name(o->planner));
		if (o->noise > 0)
			printf(", noise %g seed %llu", o->noise, o->seed);
		putchar('\n');
		bool first[DUMP_COUNT] = {[DUMP_TABLE] = true, [DUMP_RETINA] = true};
		print_dumps(o->any_dump || o->verbose || o->step ? o->want : first, body, ctl);
	}
	bool stepping = o->step && !o->quiet;
	step_wait(&stepping);
	Replay *rec = o->htmlfile ? replay_new(&body->world, &body->table, form, planner_name(o->planner)) : NULL;
	if (rec)
		replay_start(rec, &body->world, &body->table, &body->sensed, ctl);
	int cap = 64, count = 0;
	Vec2 *trail = util_alloc((size_t)cap, sizeof *trail);
	trail[count++] = body->world.utak;
	MotorCommand cmd;
	long cycle = 0;
	bool out_of_cycles = false;
	while (controller_decide(ctl, &cmd)) {
		if (cycle == o->max_cycles) {
			out_of_cycles = true;
			break;
		}
		cycle++;
		if (rec)
			replay_decided(rec, ctl);
		MotorOutcome out;
		motion_execute_noisy(&body->world, &body->table, &cmd, &body->noise, &out);
		trail = util_grow(trail, &cap, count + 1, sizeof *trail);
		trail[count++] = body->world.utak;
		retina_sense(&body->world, &body->table, &body->sensed);
		controller_perceive(ctl, &cmd, &body->sensed);
		if (rec)
			replay_cycle(rec, &body->world, &body->table, &body->sensed, ctl, &cmd, &out);
		if (!o->quiet) {
			printf("cycle %ld: ", cycle);
			motion_print(&cmd, &out, stdout);
			printf(" | %s\n", ctl->note);
			if (o->verbose || o->step)
				print_dumps(o->want, body, ctl);
			step_wait(&stepping);
		}
	}
	if (!o->quiet) {
		bool last[DUMP_COUNT] = {[DUMP_TABLE] = true};
		print_dumps(last, body, ctl);
	}
	char why[256], verdict[640];
	bool achieved = judge_task(start, &body->world, &body->table, task, trail, count, why, sizeof why);
	const char *belief = ctl->phase == PHASE_DONE ? "achieved" : "not achieved";
	if (achieved && ctl->phase == PHASE_DONE)
		snprintf(verdict, sizeof verdict, "task: achieved (%s, %ld cycles)", why, cycle);
	else if (achieved)
		snprintf(verdict, sizeof verdict, "task: achieved (%s, %ld cycles; Utak believes it not achieved: %s)", why,
			 cycle, ctl->phase == PHASE_FAILED ? ctl->why : "he was still at work");
	else if (out_of_cycles)
		snprintf(verdict, sizeof verdict, "task: failed: out of cycles (%ld); %s", o->max_cycles, why);
	else if (ctl->phase == PHASE_FAILED)
		snprintf(verdict, sizeof verdict, "task: failed: %s; %s", ctl->why, why);
	else
		snprintf(verdict, sizeof verdict, "task: failed: %s (Utak believes it %s)", why, belief);
	int status = achieved ? 0 : 1;
	if (o->svgfile) {
		char title[400];
		const char *number = task_paper_number(task);
		snprintf(title, sizeof title, "%s%s%s in %s", form, number ? ", the paper's task " : "",
			 number ? number : "", body->world.file);
		if (write_file(o->svgfile, write_svg, &(SvgOut){body, ctl, trail, count, title, verdict}))
			status = 2;
	}
	if (rec) {
		if (write_file(o->htmlfile, write_replay, &(ReplayOut){rec, verdict}))
			status = 2;
		replay_free(rec);
	}
	free(trail);
	printf("%s\n", verdict);
	return status;
}

int main(int argc, char **argv)
{
	static const struct option longopts[] = {
		{"act", required_argument, NULL, 'a'},	      {"dump", required_argument, NULL, 'd'},
		{"planner", required_argument, NULL, 'p'},    {"max-cycles", required_argument, NULL, 'm'},
		{"svg", required_argument, NULL, 's'},	      {"quiet", no_argument, NULL, 'q'},
		{"verbose", no_argument, NULL, 'v'},	      {"help", no_argument, NULL, 'h'},
		{"dry-run", no_argument, NULL, 'n'},	      {"version", no_argument, NULL, 'V'},
		{"noise", required_argument, NULL, 'N'},      {"seed", required_argument, NULL, 'S'},
		{"html", required_argument, NULL, 'H'},       {"step", no_argument, NULL, 'T'},
		{NULL, 0, NULL, 0},
	};
	Options o = {.planner = PLANNER_SKELETON, .max_cycles = UTAK_MAX_CYCLES, .seed = 1};
	int c;
	opterr = 0;
	while ((c = getopt_long(argc, argv, ":o:hnqvV", longopts, NULL)) != -1) {
		char *end;
		switch (c) {
		case 'a':
			o.act = optarg;
			break;
		case 'd':
			if (parse_dumps(optarg, o.want))
				return 2;
			o.any_dump = true;
			break;
		case 'p':
			if (!planner_parse(optarg, &o.planner))
				return usage_error("--planner: unknown planner '%s' (skeleton, grid or visibility)", optarg);
			break;
		case 'm':
			errno = 0;
			o.max_cycles = strtol(optarg, &end, 10);
			if (errno || end == optarg || *end || o.max_cycles < 0 || o.max_cycles > UTAK_MAX_CYCLES_LIMIT)
				return usage_error("--max-cycles: '%s' is not a whole number from 0 to 100000", optarg);
			break;
		case 'N':
			errno = 0;
			o.noise = strtod(optarg, &end);
			if (errno || end == optarg || *end || !(o.noise >= 0 && o.noise <= MOTION_NOISE_MAX))
				return usage_error("--noise: '%s' is not a number from 0 to 1", optarg);
			break;
		case 'S':
			errno = 0;
			o.seed = strtoull(optarg, &end, 10);
			if (errno || end == optarg || *end || optarg[0] == '-' || optarg[0] == '+')
				return usage_error("--seed: '%s' is not a whole number from 0 to 18446744073709551615",
						   optarg);
			break;
		case 's':
			o.svgfile = optarg;
			break;
		case 'H':
			o.htmlfile = optarg;
			break;
		case 'T':
			o.step = true;
			break;
		case 'o':
			o.outfile = optarg;
			break;
		case 'q':
			o.quiet = true;
			break;
		case 'v':
			o.verbose = true;
			break;
		case 'n':
			o.dry_run = true;
			break;
		case 'h':
			fputs(usage_text, stdout);
			return 0;
		case 'V':
			fputs("utak " UTAK_VERSION "\n"
			      "Copyright (c) 2026 the utak authors. MIT licence: see LICENSE.\n"
			      "After R. S. Rosenberg and P. F. Jenkin, \"Spatial problems in a simulated robot\".\n",
			      stdout);
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
	const char *path = argv[optind];
	o.task_text = optind + 1 < argc ? argv[optind + 1] : NULL;
	if ((o.verbose || o.step) && !o.any_dump)
		for (int i = 0; i < DUMP_COUNT; i++)
			o.want[i] = true;
	Diag d;
	Task task;
	if (o.task_text && task_parse(o.task_text, &task, &d)) {
		fprintf(stderr, "utak: %s\n", d.msg);
		return 2;
	}
	if (o.task_text && o.act)
		return usage_error("%s", "give either --act or a TASK, not both");

	MotorCommand *cmds = NULL;
	int ncmds = 0;
	if (o.act && act_parse(o.act, strlen(o.act), &cmds, &ncmds, &d)) {
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
	motion_noise_init(&body.noise, o.noise, o.seed);
	int status = 0;
	if (o.dry_run) {
		if (o.task_text) {
			char form[64];
			const char *number = task_paper_number(&task);
			task_short_form(&task, form, sizeof form);
			printf("task: \"%s\" reads as \"%s\"", o.task_text, form);
			if (number)
				printf(", the paper's task %s", number);
			putchar('\n');
		}
	} else {
		/* The world as it began, for the judge: a copy of the objects. */
		World start = body.world;
		start.objects = util_alloc((size_t)body.world.object_count + 1, sizeof *start.objects);
		memcpy(start.objects, body.world.objects, sizeof *start.objects * (size_t)body.world.object_count);
		Controller *ctl = util_alloc(1, sizeof *ctl);
		controller_init(ctl, o.planner);
		if (o.task_text)
			controller_set_task(ctl, &task);
		retina_sense(&body.world, &body.table, &body.sensed);
		controller_start(ctl, &body.sensed);
		if (o.task_text)
			status = run_task(&o, &body, ctl, &task, &start);
		else
			status = run_act(&o, &body, ctl, cmds, ncmds);
		controller_free(ctl);
		free(ctl);
		free(start.objects);
	}
	if (o.outfile && !o.dry_run) {
		FILE *f = fopen(o.outfile, "w");
		if (!f) {
			fprintf(stderr, "utak: %s: cannot write: %s\n", o.outfile, strerror(errno));
			status = 2;
		} else {
			world_write(&body.world, f);
			if (fclose(f) != 0) {
				fprintf(stderr, "utak: %s: cannot write\n", o.outfile);
				status = 2;
			}
		}
	}
	free(cmds);
	table_free(&body.table);
	world_free(&body.world);
	return status;
}
