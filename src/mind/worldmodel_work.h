/* worldmodel_work.h - what worldmodel.c (evidence, accommodation, disparity: paper
 * 3.3-3.5), heldobject.c (the held object's squares in the model: paper 2.2's
 * grasp and push, 3.5) and firstlook.c (recognition by the first impression, 3.5)
 * share. Private to the world model: not installed under include/, and nothing
 * outside those three files includes it. */
#ifndef UTAK_WORLDMODEL_WORK_H
#define UTAK_WORLDMODEL_WORK_H

#include <stdbool.h>
#include <stdint.h>

#include "utak/mind/worldmodel.h"

/* The disparity cost of a cell the model cannot predict: about what a square
 * known only from a coarse cell is expected to be wrong by. It, the two costs of
 * worldmodel.c's ties (WM_LINE_COST, WM_DISTANCE_COST) and
 * WORLDMODEL_DISPARITY_MARGIN were chosen by running random walks in every world
 * and counting how often the belief ends off the true square. */
#define WM_UNKNOWN_COST 0.005
/* Ties go, last, to the candidate nearest the prediction: each square of distance
 * costs this much. */
#define WM_DISTANCE_COST 1e-4

/* A square's p is definite, and can be predicted, within this of 0 or 1. */
#define WM_DEFINITE 0.1

/* A candidate position on a square believed occupied this surely is not tried
 * (worldmodel.c's disparity search), nor is a held set put down on one
 * (wm_register_held). */
#define WM_BLOCKED_CONF 0.5

/* Own-frame offsets of the touch squares, in Impression.touch order. */
extern const int8_t wm_touch_offset[TOUCH_CELLS][2];

/* worldmodel.c */

/* wm_at(m, x, y): the evidence of square (x, y) to write, its tile allocated (all
 * unseen) if need be; NULL beyond the reach. */
Evidence *wm_at(WorldModel *m, int32_t x, int32_t y);
/* wm_score_holding(m, x, y, held, under, imp, &compared): the disparity of Utak on
 * (x, y) with the held object (held, lifted) put down beside him there. */
double wm_score_holding(WorldModel *m, int32_t x, int32_t y, const Evidence *held, Evidence *under,
                        const Impression *imp, int32_t *compared);

/* heldobject.c (each function's comment is there) */

void wm_find_held(WorldModel *m, const Impression *imp);
void wm_prune_held(WorldModel *m);
void wm_refind_held(WorldModel *m, const Impression *imp);
void wm_box_held(WorldModel *m);
bool *wm_floor_round_held(const WorldModel *m);
void wm_regrow_held(WorldModel *m, const bool *was_floor);
int32_t wm_held_on_solid(const WorldModel *m, int32_t x, int32_t y);
int32_t wm_held_on_occupied(const WorldModel *m, int32_t x, int32_t y);
void wm_register_held(WorldModel *m, int32_t x, int32_t y, const Evidence *held, Evidence *under,
                      const Impression *imp);
void wm_vacate(WorldModel *m, Vec2 from, Evidence *saved);
void wm_carry(WorldModel *m, Vec2 from, Vec2 to, double deg);

#endif
