/* task.h - the tasks of paper 2.3, read from a short form or the paper's English. BOTH SIDES
 * (base/): the controller carries a task out, the judge checks it (doc/verdicts.md).
 *
 * The paper assumes a task arrives as a starting and a goal world model (3.1,
 * step 6) "to circumvent the handling of natural language input". Here a task is
 * one of a small closed set, written either as a short form ("go ne-corner",
 * "push square next-room") or as one of the paper's nine sentences and their
 * obvious variants ("Go to the northeast corner", "Push the L-shaped object into
 * the next room"), case-insensitive. Compass words are in Utak's own frame: north
 * is where he faced at the first impression. */
#ifndef UTAK_TASK_H
#define UTAK_TASK_H

#include <stddef.h>

#include "utak/base/diag.h"

typedef enum TaskKind {
	TASK_GO_CORNER,		/* (i)    go to a corner of the current room */
	TASK_GO_NEXT_ROOM,	/* (ii)   go to the next room */
	TASK_GO_SHAPE,		/* (iii)  go to an object */
	TASK_GO_ROUND,		/* (iv)   go round an object and return */
	TASK_PUSH_CORNER,	/* (v)    push an object into a corner */
	TASK_PUSH_NEXT_ROOM,	/* (vi), (ix) push an object into the next room */
	TASK_PUSH_THROUGH_DOOR,	/* (vii)  push an object through the door */
	TASK_PUSH_AROUND_CORNER,/* (viii) push an object around the corner */
} TaskKind;

/* The shapes a task can name: the judge names true polygons (body/judgeshape.h),
 * the controller the squares of its world model (mind/shape.h). */
typedef enum Shape { SHAPE_NONE, SHAPE_SQUARE, SHAPE_BRICK, SHAPE_LSHAPE, SHAPE_TRIANGLE } Shape;

/* Corners, in Utak's frame: north is +y (ahead at the first impression), east +x. */
typedef enum Corner { CORNER_NONE, CORNER_NE, CORNER_NW, CORNER_SE, CORNER_SW } Corner;

typedef struct Task {
	TaskKind kind;
	Shape shape;	/* the object, for every kind but GO_CORNER and GO_NEXT_ROOM */
	Corner corner;	/* GO_CORNER, PUSH_CORNER */
} Task;

/* task_parse(text, t, d): reads a task. On failure fills d with one line that
 * lists the forms, and returns -1. */
int task_parse(const char *text, Task *t, Diag *d);
/* task_short_form(t, buf, size): the canonical short form, e.g. "push square ne-corner". */
void task_short_form(const Task *t, char *buf, size_t size);
/* task_paper_number(t): "(i)".."(ix)" when the task is one of the paper's nine
 * (with the paper's objects and corner), else NULL. */
const char *task_paper_number(const Task *t);
const char *task_shape_name(Shape s);
const char *task_corner_name(Corner c);
/* task_corner_signs(c, &sx, &sy): the corner's compass direction in the frame of
 * its words (north +y, east +x): +1 or -1 each way. */
void task_corner_signs(Corner c, int *sx, int *sy);

#endif
