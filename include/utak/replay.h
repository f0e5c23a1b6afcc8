/* replay.h - a recording of a whole run, written as one self-contained HTML page that
 * replays it cycle by cycle in a browser (`utak --html FILE`). Not from the paper,
 * but made to show it: each frame is one turn of the action cycle of section 3.1
 * (steps 8-13), with the TABLE of Figure 1, the retinal impression of Figure 2, the
 * world model of 3.3, and the screen with the skeleton and pathgraph of Figure 3.
 * SIMULATOR SIDE (it reads the TABLE) and an observer of the controller, like svg.h:
 * it only reads, and the controller never learns it is watched.
 *
 * USE (main.c):
 *   Replay *r = replay_new(world, table, "go ne-corner", "skeleton");
 *   replay_start(r, world, table, impression, ctl);        after controller_start
 *   while (controller_decide(ctl, &cmd)) {
 *       replay_decided(r, ctl);                             steps 8-9
 *       ... the simulator carries out cmd, the controller perceives ...
 *       replay_cycle(r, world, table, impression, ctl, &cmd, &outcome);
 *   }                                                       steps 10-13
 *   replay_write(r, verdict, file);  replay_free(r);
 *
 * THE PAGE. The viewer (src/replay.html: HTML, CSS and JavaScript, no network, no
 * external scripts or fonts) is compiled into utak; the run's data goes into it as
 * one JSON document in <script id="utak-replay-data" type="application/json">,
 * laid out one field a line so that a change to what is recorded reads as a diff
 * (the golden tests keep the data of a run: tests/golden/NAME.replay). Its fields:
 *
 *   format      "utak-replay 1"
 *   world, task, paper, planner, verdict, cycles
 *   table       {w, h, runs}: the TABLE at the start (see RUNS); objects: [{name,
 *               colour}] in world-file order; heading: Utak's on the TABLE
 *   origin      [x, y]: the TABLE square where Utak stood first: the model frame's
 *               square (0, 0), turned by the heading (worldmodel.h, FRAME)
 *   eye         the 160 retinal cells [ox, oy, size] in impression order (eye.h)
 *   view        [x0, y0, x1, y1]: model squares that hold everything the mind drew
 *   plans       every plan the planner made (see PLAN), in order
 *   frames      frame 0 is the start (steps 1-7), frame k the k-th action cycle:
 *     cycle, line      the cycle's trace line, as utak prints it
 *     phase            the controller's phase after the cycle; decided: {phase,
 *                      plan, next} when the action was chosen (step 9)
 *     utak, held       Utak's true point (TABLE squares) and the held object (-1)
 *     table            TABLE squares that changed: [[x, y, w, h, runs], ...]
 *     retina, touch    160 gray levels as digits, 8 touch colours (impression.h)
 *     belief           world-model squares whose belief changed: [[y, x, codes]]
 *                      ('?' unknown; floor 'p', 'i', 'f' and occupied 'P', 'I',
 *                      'F' by the finest resolution seen: peripheral, intermediate,
 *                      fovea; 'u'/'U' known without being seen)
 *     model            Utak's believed point, the last accommodation, and the
 *                      nodes of the tree with rings and confidences (worldmodel.h);
 *                      left out when the same as in the frame before; a node the
 *                      same as one of the frame before is its index in that list;
 *                      one that changed, when shorter so, is its changes to the
 *                      node of the same object there: "like": its index, and each
 *                      ring that both have "from": [k, p, q]: the first p and the
 *                      last q vertices (and beyond codes) are those of ring k of
 *                      node "like", "v" and "beyond" the ones between
 *     screen           {x0, y0, w, h, cells}: the screen as step 12 saw it (codes
 *                      '.' space, '?' unknown, '#' verge or wall, 'o' object, 'h'
 *                      the held object, 'x' space and 'z' unknown that the planner
 *                      may not enter: the configuration space of a push, or
 *                      squares bumped into); left out when unchanged
 *     plan, next       the plan in force after the cycle (an index of plans, -1
 *                      none) and the waypoint being walked to
 *     carry            for a carried object: {footprint: rings about the pose's
 *                      point, poses: [[x, y, theta degrees], ...]} in the model
 *                      frame: the object now, then after each command still
 *                      ahead. The push planner's (task (v)) go without turning
 *                      (theta 0), one at each waypoint; the carry planner's (tasks
 *                      (vi)-(ix), carrytask.h) follow its pushes and its turns
 *                      about Utak's point (theta summed).
 *   PLAN         {cycle, step ("7", "9" or "13"), planner, x0, y0, w, h (the grid
 *                 planned on, model squares), ok, goal, exploring, vertices [[i, j,
 *                 kind]], edges [[v0, v1, i, j, steps]] (the chain from cell (i, j)
 *                 by steps 'n', 'e', 's', 'w'), skeleton_more [[i, j]] (skeleton
 *                 cells on no edge and no vertex: the skeleton is the three), found
 *                 (along the pathgraph) and taut
 *                 (rope-tightened) paths and their lengths, route (the waypoints
 *                 Utak walks), all points in the model frame}
 *   RUNS         a grid row after row from its south row, each square one
 *                 character, a run of n > 1 the same written as the character and n
 *
 * SIZE. The TABLE is written once, by runs, and after that only where an object
 * moved; the belief map only where it changed; a model node by the vertices that
 * changed (the floor's outline grows with what Utak has seen, a few vertices a
 * cycle); a screen only when it differs from the frame before. So a page grows with
 * the run (about 2 to 6 kB a cycle) and the TABLE's area costs only its runs.
 *
 * MEMORY: the frames as text, a byte per evidence square of the world model
 * (WORLDMODEL_SIDE^2) and each object's polygon at the last frame. */
#ifndef UTAK_REPLAY_H
#define UTAK_REPLAY_H

#include <stdio.h>

#include "utak/body/motion.h"
#include "utak/body/table.h"
#include "utak/body/world.h"
#include "utak/impression.h"
#include "utak/mind/controller.h"

typedef struct Replay Replay;

/* replay_new(w, t, task, planner): a recording of a run in world w (task: its short
 * form, or NULL for an --act run; planner: its name). */
Replay *replay_new(const World *w, const Table *t, const char *task, const char *planner);
void replay_free(Replay *r);
/* replay_start(r, w, t, imp, c): frame 0, after controller_start: the first impression
 * accommodated and, with a task, the first plan (steps 1-7). */
void replay_start(Replay *r, const World *w, const Table *t, const Impression *imp,
                  const Controller *c);
/* replay_decided(r, c): after controller_decide gave a command (steps 8-9). */
void replay_decided(Replay *r, const Controller *c);
/* replay_cycle(r, w, t, imp, c, cmd, out): a frame after the simulator carried out cmd
 * (step 10) and the controller perceived imp (steps 11-13). */
void replay_cycle(Replay *r, const World *w, const Table *t, const Impression *imp,
                  const Controller *c, const MotorCommand *cmd, const MotorOutcome *out);
/* replay_write(r, verdict, f): the page, with the verdict line. Returns 0, or -1 when
 * a write failed (errno says why). */
int replay_write(Replay *r, const char *verdict, FILE *f);

#endif
