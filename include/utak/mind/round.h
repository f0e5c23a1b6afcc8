/* round.h - going round an object and returning (paper 2.3 task (iv)). CONTROLLER SIDE. */
#ifndef UTAK_ROUND_H
#define UTAK_ROUND_H

#include <stdbool.h>
#include <stdint.h>

#include "utak/mind/controller.h"

/* round_lay_out(c, k): the points of a loop round object node k. */
void round_lay_out(Controller *c, int32_t k);
/* round_believed_turns(c, k): how often Utak's believed path winds round node k. */
double round_believed_turns(const Controller *c, int32_t k);
/* round_stale(c): the loop was laid out round what is no longer the task's object. */
bool round_stale(Controller *c);

#endif
