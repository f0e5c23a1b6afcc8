/* carryompl.cpp - carrying in (x, y, theta): utak's lattice planner (carry.h) against
 * OMPL's sampling planners on the same problems, with the same validity check, in
 * one run (issue 12; like the Box2D cross-check, C++ because OMPL's API is).
 *
 *   carryompl [--limit S] FILE.carry...      (files written by carrybench --write)
 *
 * For each problem: utak's planner (the best of 3 runs, thread CPU ms, its set-up
 * included), then OMPL 1.5 (Debian's libompl-dev) in SE2 = (x, y, yaw), the object's
 * pose about Utak's point: RRTConnect (Kuffner and LaValle 2000) and RRT* (Karaman
 * and Frazzoli 2011, asymptotically optimal), each given S seconds (default 10) of
 * wall time, seeded. Validity: carry_pose_free, utak's own per-configuration check
 * (the TABLE's rule at any pose); motions checked by OMPL's discrete validator every
 * quarter square of the metric below. The goal: carry_pose_inside (the object wholly
 * in the goal region), sampled by rejection for the planners' goal trees.
 *
 * THE METRIC. A path's length is the squares Utak's point travels plus the object's
 * reach (its farthest point from his) times the radians it turns: the distance its
 * far end travels when pushes and turns alternate, as carry.h's costs count it (SE2
 * weights 1 and the reach). OMPL's segments turn and translate at once, which Utak
 * cannot do; such a segment would be carried out as a turn and then a push of the
 * same length in this metric, through poses nobody checked. So OMPL's paths are
 * measured, not executed.
 *
 * OUTPUT, per problem: utak's ms and length (or "no" and the reason); for each OMPL
 * planner whether it found a path within 1 s and within S s, the time of its first
 * path (thread CPU ms), its path's length at the end, and the ratios OMPL / utak of
 * time and length. Then the success rates over the problems utak solved, and the
 * median ratios. On the problems utak proves impossible OMPL can only run out of
 * time: it is given them too, and its time is the limit. */
#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <memory>
#include <string>
#include <vector>

#include <ompl/base/SpaceInformation.h>
#include <ompl/config.h>
#include <ompl/base/goals/GoalSampleableRegion.h>
#include <ompl/base/spaces/SE2StateSpace.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/geometric/planners/rrt/RRTstar.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

extern "C" {
#include "utak/plan/carry.h"
}

namespace ob = ompl::base;
namespace og = ompl::geometric;

static const double PI = 3.14159265358979323846;

static double thread_ms()
{
	struct timespec ts;
	clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
	return ts.tv_sec * 1e3 + ts.tv_nsec / 1e6;
}

struct Problem {
	std::string name;
	Grid grid{}, goal{};
	CarryObject obj{};
	int angles = CARRY_ANGLES_DEFAULT;
	std::vector<int> goal_cells; /* free cells of the goal region */
};

/* read_rows(f, g): h rows of w characters, '.' free. */
static bool read_rows(FILE *f, Grid *g)
{
	std::vector<char> line((size_t)g->w + 8);
	for (int y = 0; y < g->h; y++) {
		if (fscanf(f, "%s", line.data()) != 1 || (int)strlen(line.data()) != g->w)
			return false;
		for (int x = 0; x < g->w; x++)
			g->cells[(size_t)y * g->w + x] = line[(size_t)x] == '.' ? GRID_FREE : GRID_BLOCKED;
	}
	return true;
}

static bool read_problem(const char *path, Problem *p)
{
	FILE *f = fopen(path, "r");
	if (!f)
		return false;
	int version, w, h, n;
	char word[64], name[256];
	bool ok = fscanf(f, "carry %d grid %d %d", &version, &w, &h) == 3 && version == 1 && w > 0 && h > 0;
	if (ok) {
		grid_init(&p->grid, w, h, GRID_BLOCKED);
		grid_init(&p->goal, w, h, GRID_BLOCKED);
		ok = read_rows(f, &p->grid) && fscanf(f, "%63s", word) == 1 && strcmp(word, "goal") == 0 &&
		     read_rows(f, &p->goal) && fscanf(f, " object %d", &n) == 1 && n >= 3 && n <= GEOM_MAX_VERTICES;
	}
	if (ok) {
		p->obj.shape.count = n;
		for (int i = 0; i < n && ok; i++)
			ok = fscanf(f, "%lf %lf", &p->obj.shape.v[i].x, &p->obj.shape.v[i].y) == 2;
		ok = ok && fscanf(f, " utak %lf %lf angles %d name %255s", &p->obj.at.x, &p->obj.at.y, &p->angles, name) == 4;
	}
	fclose(f);
	if (!ok)
		return false;
	p->name = name;
	for (int i = 0; i < w * h; i++)
		if (p->goal.cells[i] == GRID_FREE && p->grid.cells[i] == GRID_FREE)
			p->goal_cells.push_back(i);
	return true;
}

/* The goal of carry.h for OMPL: the object wholly in the goal region, and sampled. */
class CarryGoalRegion : public ob::GoalSampleableRegion {
public:
	CarryGoalRegion(const ob::SpaceInformationPtr &si, const Problem *p) : ob::GoalSampleableRegion(si), p_(p)
	{
		setThreshold(0.5);
	}
	double distanceGoal(const ob::State *st) const override
	{
		const auto *s = st->as<ob::SE2StateSpace::StateType>();
		return carry_pose_inside(&p_->obj, &p_->goal, vec2(s->getX(), s->getY()), s->getYaw() * 180 / PI) ? 0
															  : 1;
	}
	void sampleGoal(ob::State *st) const override
	{
		auto *s = st->as<ob::SE2StateSpace::StateType>();
		/* Rejection: a random goal cell, a random point in it, a random angle. */
		for (int tries = 0; tries < 1000; tries++) {
			int c = p_->goal_cells[(size_t)rng_.uniformInt(0, (int)p_->goal_cells.size() - 1)];
			s->setXY(c % p_->grid.w + rng_.uniform01(), c / p_->grid.w + rng_.uniform01());
			s->setYaw(rng_.uniformReal(-PI, PI));
			if (distanceGoal(st) == 0 && si_->isValid(st))
				return;
		}
	}
	unsigned int maxSampleCount() const override { return UINT_MAX; }

private:
	const Problem *p_;
	mutable ompl::RNG rng_;
};

struct Outcome {
	bool found = false;
	double first_ms = 0; /* thread CPU ms to the first path (the limit when none) */
	double wall_first = 0;
	double length = 0;
};

/* run_ompl(p, cp, reach, rrtstar, limit): one planner on one problem. */
static Outcome run_ompl(const Problem &p, CarryPlanner *cp, double reach, bool rrtstar, double limit)
{
	auto space = std::make_shared<ob::SE2StateSpace>();
	ob::RealVectorBounds bounds(2);
	bounds.setLow(0, 0);
	bounds.setHigh(0, p.grid.w);
	bounds.setLow(1, 0);
	bounds.setHigh(1, p.grid.h);
	space->setBounds(bounds);
	space->setSubspaceWeight(1, reach > 0 ? reach : 1);
	og::SimpleSetup ss(space);
	const CarryObject *obj = &p.obj;
	ss.setStateValidityChecker([cp, obj](const ob::State *st) {
		const auto *s = st->as<ob::SE2StateSpace::StateType>();
		return carry_pose_free(cp, obj, vec2(s->getX(), s->getY()), s->getYaw() * 180 / PI);
	});
	space->setup();
	space->setLongestValidSegmentFraction(0.25 / space->getMaximumExtent());
	ob::ScopedState<ob::SE2StateSpace> start(space);
	start->setXY(p.obj.at.x, p.obj.at.y);
	start->setYaw(0);
	ss.setStartState(start);
	ss.setGoal(std::make_shared<CarryGoalRegion>(ss.getSpaceInformation(), &p));
	if (rrtstar)
		ss.setPlanner(std::make_shared<og::RRTstar>(ss.getSpaceInformation()));
	else
		ss.setPlanner(std::make_shared<og::RRTConnect>(ss.getSpaceInformation()));
	ss.setup();
	Outcome out;
	double t0 = thread_ms();
	struct timespec w0;
	clock_gettime(CLOCK_MONOTONIC, &w0);
	bool first = true;
	ss.getProblemDefinition()->setIntermediateSolutionCallback(
		[&](const ob::Planner *, const std::vector<const ob::State *> &, const ob::Cost) {
			if (!first)
				return;
			first = false;
			out.first_ms = thread_ms() - t0;
			struct timespec w1;
			clock_gettime(CLOCK_MONOTONIC, &w1);
			out.wall_first = (double)(w1.tv_sec - w0.tv_sec) + (w1.tv_nsec - w0.tv_nsec) / 1e9;
		});
	ob::PlannerStatus st = ss.solve(limit);
	double spent = thread_ms() - t0;
	struct timespec w1;
	clock_gettime(CLOCK_MONOTONIC, &w1);
	double wall = (double)(w1.tv_sec - w0.tv_sec) + (w1.tv_nsec - w0.tv_nsec) / 1e9;
	out.found = st == ob::PlannerStatus::EXACT_SOLUTION;
	if (out.found) {
		out.length = ss.getSolutionPath().length();
		if (first) { /* RRTConnect stops at its first path and reports none on the way */
			out.first_ms = spent;
			out.wall_first = wall;
		}
	} else {
		out.first_ms = spent;
		out.wall_first = wall;
	}
	return out;
}

static double median(std::vector<double> v)
{
	if (v.empty())
		return NAN;
	std::sort(v.begin(), v.end());
	size_t n = v.size();
	return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

int main(int argc, char **argv)
{
	double limit = 10;
	int first_file = 1;
	if (argc > 2 && strcmp(argv[1], "--limit") == 0) {
		limit = atof(argv[2]);
		first_file = 3;
	}
	ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
	printf("carryompl: utak's lattice planner and OMPL %d.%d.%d in SE2 on the same problems; OMPL given %.0f s each\n",
	       OMPL_MAJOR_VERSION, OMPL_MINOR_VERSION, OMPL_PATCH_VERSION, limit);
	printf("lengths: squares Utak travels + reach x radians turned; times: thread CPU ms; x: OMPL / utak\n");
	printf("%-14s %8s %7s | %-34s | %-34s\n", "problem", "utak ms", "length", "RRTConnect: 1s 10s ms length x-time x-len",
	       "RRT*: 1s 10s first-ms length x-time x-len");
	const char *names[2] = {"RRTConnect", "RRT*"};
	int solved = 0, ok1[2] = {0, 0}, ok10[2] = {0, 0};
	std::vector<double> xtime[2], xlen[2];
	for (int i = first_file; i < argc; i++) {
		Problem p;
		if (!read_problem(argv[i], &p)) {
			fprintf(stderr, "carryompl: %s: not a problem file of carrybench --write\n", argv[i]);
			return 2;
		}
		CarryParams params = carry_params_default();
		params.angles = p.angles;
		CarryResult r;
		carry_result_init(&r);
		double ms = INFINITY;
		for (int rep = 0; rep < 3; rep++) {
			double t0 = thread_ms();
			CarryPlanner cp;
			carry_init(&cp, &p.grid, &params);
			CarryGoal goal = {&p.goal, false, nullptr, nullptr};
			carry_plan(&cp, &p.obj, &goal, &r);
			carry_free(&cp);
			ms = std::min(ms, thread_ms() - t0);
		}
		bool found = r.status == CARRY_FOUND;
		double length = found ? r.plan.pushed + r.plan.turned * PI / 180 * r.reach : 0;
		solved += found;
		printf("%-14s %8.1f %7s |", p.name.c_str(), ms, found ? std::to_string((int)lround(length)).c_str() : "no");
		CarryPlanner cp;
		carry_init(&cp, &p.grid, &params);
		for (int k = 0; k < 2; k++) {
			ompl::RNG::setSeed(2026);
			Outcome o = run_ompl(p, &cp, r.reach, k == 1, limit);
			bool in1 = o.found && o.wall_first <= 1.0;
			if (found) {
				ok1[k] += in1;
				ok10[k] += o.found;
			}
			if (o.found) {
				double xt = o.first_ms / ms, xl = found ? o.length / length : NAN;
				if (found) {
					xtime[k].push_back(xt);
					xlen[k].push_back(xl);
				}
				printf(" %3s %3s %8.1f %6.0f %7.1f %5.2f |", in1 ? "yes" : "no", "yes", o.first_ms, o.length, xt, xl);
			} else {
				printf(" %3s %3s %8.1f %6s %7s %5s |", "no", "no", o.first_ms, "-", "-", "-");
			}
			fflush(stdout);
		}
		printf("\n");
		if (!found)
			printf("  %s: utak: %s\n", p.name.c_str(), r.why);
		carry_free(&cp);
		carry_result_free(&r);
		grid_free(&p.grid);
		grid_free(&p.goal);
	}
	for (int k = 0; k < 2; k++)
		printf("%s: solved %d of %d within 1 s, %d within %.0f s (of the %d utak solved); median time %.1f x, "
		       "length %.2f x utak's\n",
		       names[k], ok1[k], solved, ok10[k], limit, solved, median(xtime[k]), median(xlen[k]));
	return 0;
}
