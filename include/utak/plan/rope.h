/* rope.h - rope-tightening: pull a found path taut, to the shortest path of its
 * homotopy class (paper 5, which names it as an open problem: "When you have found
 * one reasonable path between two points, how do you tighten the path to the
 * shortest possible way?").
 *
 * Given a free polyline (visibility.h's definition) from S to D, rope_tighten
 * returns the shortest free polyline from S to D that can be deformed into it
 * without crossing an obstacle: the position a rope laid along the path takes when
 * pulled at both ends. It is never longer than the input, keeps both end points,
 * bends only at convex corners of the blocked cells (lattice points), and goes round
 * every obstacle on the same side as the input. It is not, in general, the shortest
 * path from S to D: that may go round an obstacle on the other side
 * (visibility_find gives that one).
 *
 * METHOD (rope.c): the free space is cut into ROW RUNS, maximal horizontal runs of
 * free cells, joined by PORTALS, the stretches of grid line two runs in adjacent rows
 * share; every portal ends on an obstacle, so it is a chord of the free space. The
 * input's sequence of runs, with immediate back-and-forth crossings of a portal
 * cancelled, is the sleeve of its homotopy class (Hershberger and Snoeyink 1994,
 * "Computing minimum length paths of a given homotopy class"), and the funnel
 * algorithm (Lee and Preparata 1984, "Euclidean shortest paths in the presence of
 * rectilinear barriers"; in the form of Chazelle 1982 and Mononen's "simple stupid
 * funnel") finds the shortest path through the sleeve's portals.
 *
 * COST: O(n + k w) for an input of n points crossing k grid lines in a grid w wide
 * (each run is found by a scan along its row), plus the funnel's O(k) amortised
 * (O(k^2) in the worst case of restarts). */
#ifndef UTAK_ROPE_H
#define UTAK_ROPE_H

#include "utak/plan/grid.h"
#include "utak/plan/path.h"

typedef enum RopeStatus {
	ROPE_OK = 0,    /* out holds the tightened path */
	ROPE_BAD_INPUT, /* in is empty or not free (visibility_path_free): out is empty */
} RopeStatus;

/* rope_tighten(g, in, out): the shortest path homotopic to in (see above). out must
 * not be in. out->expanded counts the portals of the sleeve. */
RopeStatus rope_tighten(const Grid *g, const Path *in, Path *out);

#endif
