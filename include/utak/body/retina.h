/* retina.h - Utak's senses: the retinal and tactile impression (paper 2.2). SIMULATOR SIDE.
 *
 * The simulator superimposes the eye (eye.h) on the TABLE, centred on Utak's
 * square and turned with his heading, and computes the 160 gray levels directly
 * from the TABLE; touch is the colours of the 8 squares around him. Only the
 * simulator and main.c include this header: the controller receives the
 * Impression and never sees how it was made. */
#ifndef UTAK_RETINA_H
#define UTAK_RETINA_H

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>

#include "utak/impression.h"
#include "utak/body/table.h"
#include "utak/body/world.h"

/* retina_sense(w, t, imp): the impression Utak receives where he stands now. */
void retina_sense(const World *w, const Table *t, Impression *imp);

/* retina_square(w, ox, oy, &x, &y): the TABLE square at offset (ox, oy) of Utak's
 * frame: his square + ox * right + oy * ahead. */
void retina_square(const World *w, int32_t ox, int32_t oy, int32_t *x, int32_t *y);

/* retina_occupied(w, t, x, y): what the eye counts as occupied: an object, the
 * verge (squares off the TABLE included) or Utak's own square. */
bool retina_occupied(const World *w, const Table *t, int32_t x, int32_t y);

/* retina_print_touch(imp, f): the 8 colours as a 3 x 3 picture around '@' (ahead
 * at the top, Utak's left on the left), then one line in Impression.touch order. */
void retina_print_touch(const Impression *imp, FILE *f);

#endif
