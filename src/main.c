/* main.c - the utak command: reads a world, runs Utak in it, prints what happened.
 *
 * The only file that sees both sides of the wall (impression.h): it owns the body
 * (World, Table: the simulator) and the mind (Controller), and passes between them
 * only impressions and motor commands. It alone prints diagnostics and chooses the
 * exit status: 0 done, 1 a task was not achieved, 2 bad usage, bad input or an
 * output that could not be written (standard output among them; 2 wins over 1),
 * 3 out of memory (util.h).
 *
 * The output files (-o, --svg, --html) are opened before the run, as temporaries
 * beside their targets, so that a path that cannot be written fails at once; they
 * replace their targets after the run, and only when standard output has been
 * written in full (output.h). */
#include <errno.h>
#include <getopt.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "utak/body/act.h"
#include "utak/mind/controller.h"
#include "utak/base/eye.h"
#include "utak/base/output.h"
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
	"Runs Utak, the robot of Rosenberg and Jenkin's TABLETOP, in the world file WORLD\n"
	"(- for standard input), on TASK (e.g. \"go ne-corner\", \"Push the square into\n"
	"the northeast corner\").\n"
	"\n"
	"  --act SCRIPT      carry out motor commands instead of a task,\n"
	"                    e.g. \"move 3 0; grasp; push 0 5; turn 90; release\";\n"
	"                    --act @FILE reads them from FILE\n"
	"  --act-file FILE   the same: motor commands from FILE (- for standard input),\n"
	"                    one or more a line, '#' comments\n"
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
	"  -o FILE           write the final state as a world file (- standard output)\n"
	"  -n, --dry-run     read WORLD and TASK (or the --act script), say how it reads,\n"
	"                    check the output paths, and stop\n"
	"  -h, --help        this text\n"
	"  -V, --version     the version and the licence\n"
	"Output files are replaced whole, only when the run has completed. Exit status:\n"
	"0 done, 1 task not achieved, 2 bad usage or input, or an output not written,\n"
	"3 out of memory. See utak(1) and, for the world file, utak(5).\n";

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

/* ---- options ---------------------------------------------------------------------- */

/* The output files, each opened before the run and committed after it. */
enum { OUT_WORLD, OUT_SVG, OUT_HTML, OUT_COUNT };
static const char *const output_option[OUT_COUNT] = {"-o", "--svg", "--html"};

typedef struct Options {
	const char *world_path; /* WORLD, "-" for standard input */
	const char *task_text;  /* TASK, or NULL */
	const char *act;        /* --act SCRIPT (or @FILE), or NULL */
	const char *act_file;   /* --act-file FILE, or NULL */
	const char *out_path[OUT_COUNT]; /* -o, --svg, --html: NULL when not given */
	bool want[DUMP_COUNT], any_dump, dry_run, quiet, verbose, step;
	PlannerKind planner;
	long max_cycles;
	double noise;            /* --noise SIGMA */
	unsigned long long seed; /* --seed N */
} Options;

/* The names standing for "-" and for standard output in diagnostics. */
static const char stdin_name[] = "standard input";
static const char stdout_name[] = "standard output";

static const struct option longopts[] = {
	{"act", required_argument, NULL, 'a'},	      {"act-file", required_argument, NULL, 'A'},
	{"dump", required_argument, NULL, 'd'},	      {"planner", required_argument, NULL, 'p'},
	{"max-cycles", required_argument, NULL, 'm'}, {"svg", required_argument, NULL, 's'},
	{"quiet", no_argument, NULL, 'q'},	      {"verbose", no_argument, NULL, 'v'},
	{"help", no_argument, NULL, 'h'},	      {"dry-run", no_argument, NULL, 'n'},
	{"version", no_argument, NULL, 'V'},	      {"noise", required_argument, NULL, 'N'},
	{"seed", required_argument, NULL, 'S'},	      {"html", required_argument, NULL, 'H'},
	{"step", no_argument, NULL, 'T'},	      {NULL, 0, NULL, 0},
};

/* A parse_option result that means "go on" (any other is an exit status). */
enum { OPTIONS_GO_ON = -1 };

/* parse_number_option(o, c, arg): --max-cycles, --noise, --seed. */
static int parse_number_option(Options *o, int c, const char *arg)
{
	char *end;
	errno = 0;
	switch (c) {
	case 'm':
		o->max_cycles = strtol(arg, &end, 10);
		if (errno || end == arg || *end || o->max_cycles < 0 || o->max_cycles > UTAK_MAX_CYCLES_LIMIT)
			return usage_error("--max-cycles: '%s' is not a whole number from 0 to 100000", arg);
		break;
	case 'N':
		o->noise = strtod(arg, &end);
		if (errno || end == arg || *end || !(o->noise >= 0 && o->noise <= MOTION_NOISE_MAX))
			return usage_error("--noise: '%s' is not a number from 0 to 1", arg);
		break;
	default:
		o->seed = strtoull(arg, &end, 10);
		if (errno || end == arg || *end || arg[0] == '-' || arg[0] == '+')
			return usage_error("--seed: '%s' is not a whole number from 0 to 18446744073709551615", arg);
		break;
	}
	return OPTIONS_GO_ON;
}

/* parse_option(o, c, arg, argv): one option of getopt_long's. */
static int parse_option(Options *o, int c, char *arg, char **argv)
{
	switch (c) {
	case 'a':
		o->act = arg;
		break;
	case 'A':
		o->act_file = arg;
		break;
	case 'd':
		if (parse_dumps(arg, o->want))
			return 2;
		o->any_dump = true;
		break;
	case 'p':
		if (!planner_parse(arg, &o->planner))
			return usage_error("--planner: unknown planner '%s' (skeleton, grid or visibility)", arg);
		break;
	case 'm':
	case 'N':
	case 'S':
		return parse_number_option(o, c, arg);
	case 'o':
		o->out_path[OUT_WORLD] = arg;
		break;
	case 's':
		o->out_path[OUT_SVG] = arg;
		break;
	case 'H':
		o->out_path[OUT_HTML] = arg;
		break;
	case 'T':
		o->step = true;
		break;
	case 'q':
		o->quiet = true;
		break;
	case 'v':
		o->verbose = true;
		break;
	case 'n':
		o->dry_run = true;
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
	return OPTIONS_GO_ON;
}

/* script_file(o): the file the --act script is read from (--act @FILE or
 * --act-file FILE), or NULL. */
static const char *script_file(const Options *o)
{
	return o->act_file ? o->act_file : o->act && o->act[0] == '@' ? o->act + 1 : NULL;
}

/* check_options(o): what the options ask for together, before anything is read. */
static int check_options(const Options *o)
{
	if (o->act && o->act_file)
		return usage_error("%s", "give either --act or --act-file, not both");
	if (o->dry_run && !o->task_text && !o->act && !o->act_file)
		return usage_error("%s", "-n, --dry-run needs a TASK (or --act) to read");
	if (!o->world_path[0])
		return usage_error("%s", "WORLD: the file name is empty");
	const char *file = script_file(o);
	if (file && !file[0])
		return usage_error("%s: the file name is empty", o->act_file ? "--act-file" : "--act @FILE");
	if (file && strcmp(file, "-") == 0 && strcmp(o->world_path, "-") == 0)
		return usage_error("%s", "standard input can be WORLD or the --act script, not both");
	/* --step waits for Enter on standard input: a world or script read from it
	 * would leave it at its end, and each Enter would be taken from the file. */
	bool from_stdin = strcmp(o->world_path, "-") == 0 || (file && strcmp(file, "-") == 0);
	if (o->step && !o->quiet && from_stdin)
		return usage_error("%s", "--step waits on standard input, so WORLD or the script cannot be '-'");
	for (int i = 0; i < OUT_COUNT; i++)
		if (o->out_path[i] && !o->out_path[i][0])
			return usage_error("%s: the file name is empty", output_option[i]);
	for (int i = 0; i < OUT_COUNT; i++)
		for (int j = i + 1; j < OUT_COUNT; j++)
			if (o->out_path[i] && o->out_path[j] && output_same(o->out_path[i], o->out_path[j])) {
				fprintf(stderr, "utak: %s and %s name the same file '%s' (utak --help for usage)\n",
					output_option[i], output_option[j], o->out_path[j]);
				return 2;
			}
	return OPTIONS_GO_ON;
}

/* parse_options(o, argc, argv): fills o; OPTIONS_GO_ON, or the exit status. */
static int parse_options(Options *o, int argc, char **argv)
{
	*o = (Options){.planner = PLANNER_SKELETON, .max_cycles = UTAK_MAX_CYCLES, .seed = 1};
	int c;
	opterr = 0;
	while ((c = getopt_long(argc, argv, ":o:hnqvV", longopts, NULL)) != -1) {
		int status = parse_option(o, c, optarg, argv);
		if (status != OPTIONS_GO_ON)
			return status;
	}
	if (optind >= argc)
		return usage_error("%s", "no WORLD file given");
	if (argc - optind > 2)
		return usage_error("too many arguments, from '%s' (quote the TASK)", argv[optind + 2]);
	o->world_path = argv[optind];
	o->task_text = optind + 1 < argc ? argv[optind + 1] : NULL;
	if ((o->verbose || o->step) && !o->any_dump)
		for (int i = 0; i < DUMP_COUNT; i++)
			o->want[i] = true;
	return check_options(o);
}

/* ---- reading ------------------------------------------------------------------------ */

/* read_world(body, path, d): the world and its TABLE; "-" is standard input. */
static int read_world(Body *body, const char *path, Diag *d)
{
	int status = strcmp(path, "-") == 0 ? world_read_stream(&body->world, stdin_name, stdin, d)
					    : world_read(&body->world, path, d);
	if (status == 0 && table_build(&body->table, &body->world, d) == 0)
		return 0;
	world_free(&body->world); /* safe on a world that failed to read */
	return -1;
}

/* read_script(o, &cmds, &n, d): the --act script: given inline, or as --act @FILE
 * or --act-file FILE ("-" is standard input). No script: no commands. */
static int read_script(const Options *o, MotorCommand **cmds, int *n, Diag *d)
{
	*cmds = NULL;
	*n = 0;
	const char *file = script_file(o);
	if (!file)
		return o->act ? act_parse(o->act, strlen(o->act), cmds, n, d) : 0;
	if (strcmp(file, "-") == 0)
		return act_read_stream(stdin_name, stdin, cmds, n, d);
	FILE *f = fopen(file, "rb");
	if (!f)
		return diag_set(d, file, 0, 0, "cannot open: %s", strerror(errno));
	int status = act_read_stream(file, f, cmds, n, d);
	fclose(f);
	return status;
}

/* ---- outputs -------------------------------------------------------------------------- */

/* The signals that end the program: each first removes the temporaries, then
 * ends it as the signal would have. */
static const int fatal_signal[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGPIPE};

static void on_fatal_signal(int sig)
{
	output_abandon_all();
	signal(sig, SIG_DFL);
	raise(sig);
}

/* outputs_guard(): no temporary outlives the program, whatever ends it; and a
 * file-size limit (ulimit -f) makes a write fail with EFBIG, reported like a full
 * disk, instead of killing the program mid-write with SIGXFSZ. */
static void outputs_guard(void)
{
	signal(SIGXFSZ, SIG_IGN);
	for (size_t i = 0; i < sizeof fatal_signal / sizeof fatal_signal[0]; i++) {
		struct sigaction sa = {.sa_handler = on_fatal_signal}, old;
		sigemptyset(&sa.sa_mask);
		/* A signal ignored by whoever started utak (nohup, a background job's
		 * SIGINT) stays ignored. */
		if (sigaction(fatal_signal[i], NULL, &old) == 0 && old.sa_handler != SIG_IGN)
			sigaction(fatal_signal[i], &sa, NULL);
	}
	atexit(output_abandon_all); /* exit(3) on running out of memory */
}

/* outputs_open(o, out): opens every output given (unopened ones get a NULL
 * stream); on failure says why, closes what it opened and returns 2. */
static int outputs_open(const Options *o, Output out[OUT_COUNT])
{
	for (int i = 0; i < OUT_COUNT; i++)
		out[i] = (Output){.stream = NULL, .slot = -1, .standard = false};
	for (int i = 0; i < OUT_COUNT; i++) {
		Diag d;
		if (o->out_path[i] && output_open(&out[i], o->out_path[i], &d)) {
			fprintf(stderr, "utak: %s\n", d.msg);
			for (int j = 0; j < i; j++)
				output_abandon(&out[j]);
			return 2;
		}
	}
	return 0;
}

/* WriteFn(f, ctx): writes an output's contents to f; 0, or -1 with errno set. */
typedef int WriteFn(FILE *f, void *ctx);

/* output_write(out, fn, ctx): fn into an open output; a failure abandons it (its
 * target untouched) with "utak: FILE: reason". Returns 0, or 2. Nothing when the
 * output was not asked for. */
static int output_write(Output *out, WriteFn *fn, void *ctx)
{
	if (!output_stream(out))
		return 0;
	errno = 0;
	if (fn(output_stream(out), ctx) == 0)
		return 0;
	fprintf(stderr, "utak: %s: %s\n", out->name, errno ? strerror(errno) : "write error");
	output_abandon(out);
	return 2;
}

/* outputs_finish(out, status): after the run. Standard output is flushed and
 * checked; if it failed, no output replaces its target. Then each output is
 * committed. Returns the exit status: 2 when anything failed, else status. */
static int outputs_finish(Output out[OUT_COUNT], int status)
{
	Diag d;
	bool stdout_ok = output_flush(stdout, stdout_name, &d) == 0;
	if (!stdout_ok) {
		fprintf(stderr, "utak: %s\n", d.msg);
		status = 2;
	}
	for (int i = 0; i < OUT_COUNT; i++) {
		if (!output_stream(&out[i]))
			continue;
		if (!stdout_ok) {
			output_abandon(&out[i]);
		} else if (output_commit(&out[i], &d)) {
			fprintf(stderr, "utak: %s\n", d.msg);
			status = 2;
		}
	}
	return status;
}

/* finish(status): the exit status, once standard output is known to be written:
 * for the ways out before any output file is open. */
static int finish(int status)
{
	Diag d;
	if (output_flush(stdout, stdout_name, &d)) {
		fprintf(stderr, "utak: %s\n", d.msg);
		return 2;
	}
	return status;
}

/* What the replay's page is written from (output_write's ctx). */
typedef struct ReplayOut {
	Replay *rec;
	const char *verdict;
} ReplayOut;

static int write_replay(FILE *f, void *ctx)
{
	const ReplayOut *r = ctx;
	return replay_write(r->rec, r->verdict, f);
}

/* What the picture is drawn from (output_write's ctx). */
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

static int write_world(FILE *f, void *ctx)
{
	world_write(ctx, f);
	return 0;
}

/* ---- the run ------------------------------------------------------------------------ */

/* A trail of Utak's true positions, for the judge and the picture. */
typedef struct Trail {
	Vec2 *p;
	int count, cap;
} Trail;

static void trail_add(Trail *t, Vec2 p)
{
	t->p = util_grow(t->p, &t->cap, t->count + 1, sizeof *t->p);
	t->p[t->count++] = p;
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

/* run_act(o, body, ctl, cmds, n, out): the --act run: each command, its outcome,
 * and the mind perceiving the impression that follows (paper 3.1 steps 10-11);
 * then the picture and the replay, when asked for. Stops early when standard
 * output fails. Returns the exit status. */
static int run_act(const Options *o, Body *body, Controller *ctl, const MotorCommand *cmds, int n,
		   Output out[OUT_COUNT])
{
	Replay *rec = output_stream(&out[OUT_HTML])
			  ? replay_new(&body->world, &body->table, NULL, planner_name(o->planner))
			  : NULL;
	if (rec)
		replay_start(rec, &body->world, &body->table, &body->sensed, ctl);
	Trail trail = {0};
	trail_add(&trail, body->world.utak);
	int done = 0;
	for (; done < n && !ferror(stdout); done++) {
		MotorOutcome mo;
		motion_execute_noisy(&body->world, &body->table, &cmds[done], &body->noise, &mo);
		trail_add(&trail, body->world.utak);
		printf("act %d: ", done + 1);
		motion_print(&cmds[done], &mo, stdout);
		putchar('\n');
		retina_sense(&body->world, &body->table, &body->sensed);
		controller_perceive(ctl, &cmds[done], &body->sensed);
		if (rec)
			replay_cycle(rec, &body->world, &body->table, &body->sensed, ctl, &cmds[done], &mo);
	}
	if (!o->any_dump) {
		bool table_only[DUMP_COUNT] = {[DUMP_TABLE] = true};
		print_dumps(table_only, body, ctl);
	} else {
		print_dumps(o->want, body, ctl);
	}
	char title[400], verdict[64];
	snprintf(title, sizeof title, "%d motor commands in %s", n, body->world.file);
	snprintf(verdict, sizeof verdict, "%d motor commands carried out", done);
	int status = output_write(&out[OUT_SVG], write_svg,
				  &(SvgOut){body, ctl, trail.p, trail.count, title, verdict});
	if (rec) {
		if (output_write(&out[OUT_HTML], write_replay, &(ReplayOut){rec, verdict}))
			status = 2;
		replay_free(rec);
	}
	free(trail.p);
	return status;
}

/* verdict_line(o, ctl, achieved, why, cycle, out_of_cycles, line, size): the
 * verdict of the ground truth, with Utak's belief beside it when they differ. */
static void verdict_line(const Options *o, const Controller *ctl, bool achieved, const char *why, long cycle,
			 bool out_of_cycles, char *line, size_t size)
{
	const char *belief = ctl->phase == PHASE_DONE ? "achieved" : "not achieved";
	if (achieved && ctl->phase == PHASE_DONE)
		snprintf(line, size, "task: achieved (%s, %ld cycles)", why, cycle);
	else if (achieved)
		snprintf(line, size, "task: achieved (%s, %ld cycles; Utak believes it not achieved: %s)", why, cycle,
			 ctl->phase == PHASE_FAILED ? ctl->why : "he was still at work");
	else if (out_of_cycles)
		snprintf(line, size, "task: failed: out of cycles (%ld); %s", o->max_cycles, why);
	else if (ctl->phase == PHASE_FAILED)
		snprintf(line, size, "task: failed: %s; %s", ctl->why, why);
	else
		snprintf(line, size, "task: failed: %s (Utak believes it %s)", why, belief);
}

/* run_task(o, body, ctl, task, start, out): the action cycle on a task, then the
 * verdict of the ground truth, the picture and the replay. Returns the exit
 * status. Stops early when standard output fails. */
static int run_task(const Options *o, Body *body, Controller *ctl, const Task *task, const World *start,
		    Output out[OUT_COUNT])
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
	Replay *rec = output_stream(&out[OUT_HTML])
			  ? replay_new(&body->world, &body->table, form, planner_name(o->planner))
			  : NULL;
	if (rec)
		replay_start(rec, &body->world, &body->table, &body->sensed, ctl);
	Trail trail = {0};
	trail_add(&trail, body->world.utak);
	MotorCommand cmd;
	long cycle = 0;
	bool out_of_cycles = false;
	while (!ferror(stdout) && controller_decide(ctl, &cmd)) {
		if (cycle == o->max_cycles) {
			out_of_cycles = true;
			break;
		}
		cycle++;
		if (rec)
			replay_decided(rec, ctl);
		MotorOutcome mo;
		motion_execute_noisy(&body->world, &body->table, &cmd, &body->noise, &mo);
		trail_add(&trail, body->world.utak);
		retina_sense(&body->world, &body->table, &body->sensed);
		controller_perceive(ctl, &cmd, &body->sensed);
		if (rec)
			replay_cycle(rec, &body->world, &body->table, &body->sensed, ctl, &cmd, &mo);
		if (!o->quiet) {
			printf("cycle %ld: ", cycle);
			motion_print(&cmd, &mo, stdout);
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
	bool achieved = judge_task(start, &body->world, &body->table, task, trail.p, trail.count, why, sizeof why);
	verdict_line(o, ctl, achieved, why, cycle, out_of_cycles, verdict, sizeof verdict);
	int status = achieved ? 0 : 1;
	char title[400];
	const char *number = task_paper_number(task);
	snprintf(title, sizeof title, "%s%s%s in %s", form, number ? ", the paper's task " : "", number ? number : "",
		 body->world.file);
	if (output_write(&out[OUT_SVG], write_svg, &(SvgOut){body, ctl, trail.p, trail.count, title, verdict}))
		status = 2;
	if (rec) {
		if (output_write(&out[OUT_HTML], write_replay, &(ReplayOut){rec, verdict}))
			status = 2;
		replay_free(rec);
	}
	free(trail.p);
	printf("%s\n", verdict);
	return status;
}

/* dry_run(o, task, ncmds): -n: how the task or the script reads. */
static void dry_run(const Options *o, const Task *task, int ncmds)
{
	if (o->task_text) {
		char form[64];
		const char *number = task_paper_number(task);
		task_short_form(task, form, sizeof form);
		printf("task: \"%s\" reads as \"%s\"", o->task_text, form);
		if (number)
			printf(", the paper's task %s", number);
		putchar('\n');
	} else {
		printf("act: %d motor command%s\n", ncmds, ncmds == 1 ? "" : "s");
	}
}

/* run(o, body, task, cmds, ncmds, out): Utak's run, a task or a script, its
 * picture and replay, and the final world, into the outputs that are open.
 * Returns the exit status. */
static int run(const Options *o, Body *body, const Task *task, const MotorCommand *cmds, int ncmds,
	       Output out[OUT_COUNT])
{
	/* The world as it began, for the judge: a copy of the objects (none in a
	 * world without any, whose array is NULL: memcpy must not be given it). */
	World start = body->world;
	start.objects = util_alloc((size_t)body->world.object_count + 1, sizeof *start.objects);
	if (body->world.object_count > 0)
		memcpy(start.objects, body->world.objects, sizeof *start.objects * (size_t)body->world.object_count);
	Controller *ctl = util_alloc(1, sizeof *ctl);
	controller_init(ctl, o->planner);
	if (o->task_text)
		controller_set_task(ctl, task);
	retina_sense(&body->world, &body->table, &body->sensed);
	controller_start(ctl, &body->sensed);
	int status = o->task_text ? run_task(o, body, ctl, task, &start, out)
				  : run_act(o, body, ctl, cmds, ncmds, out);
	controller_free(ctl);
	free(ctl);
	free(start.objects);
	if (output_write(&out[OUT_WORLD], write_world, &body->world))
		status = 2;
	return status;
}

int main(int argc, char **argv)
{
	outputs_guard();
	Options o;
	int status = parse_options(&o, argc, argv);
	if (status != OPTIONS_GO_ON)
		return finish(status);
	Diag d;
	Task task;
	if (o.task_text && task_parse(o.task_text, &task, &d)) {
		fprintf(stderr, "utak: %s\n", d.msg);
		return 2;
	}
	if (o.task_text && (o.act || o.act_file))
		return usage_error("%s", "give either --act or a TASK, not both");
	MotorCommand *cmds;
	int ncmds;
	if (read_script(&o, &cmds, &ncmds, &d)) {
		fprintf(stderr, "utak: %s\n", d.msg);
		return 2;
	}
	Body body;
	if (read_world(&body, o.world_path, &d)) {
		fprintf(stderr, "utak: %s\n", d.msg);
		free(cmds);
		return 2;
	}
	motion_noise_init(&body.noise, o.noise, o.seed);
	Output out[OUT_COUNT];
	status = outputs_open(&o, out);
	if (status == 0 && o.dry_run) {
		dry_run(&o, &task, ncmds);
		for (int i = 0; i < OUT_COUNT; i++)
			output_abandon(&out[i]);
		status = finish(0);
	} else if (status == 0) {
		status = outputs_finish(out, run(&o, &body, &task, cmds, ncmds, out));
	}
	free(cmds);
	table_free(&body.table);
	world_free(&body.world);
	return status;
}
