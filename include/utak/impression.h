/* impression.h - the wall between body and mind: what Utak senses and what he can do
 * (paper 2.2, 3.1).
 *
 * The simulator (the world, the TABLE, the eye's sampling) and the controller
 * (regions, world model, planner, action cycle) meet here and nowhere else: the
 * simulator hands the controller an Impression each time Utak halts, and the
 * controller hands the simulator one MotorCommand at a time. Everything the
 * controller knows of the world it has inferred from these two; it includes no
 * header of the simulator's (world.h, table.h, motion.h, retina.h), a rule that
 * tests/wall.test.sh checks. */
#ifndef UTAK_IMPRESSION_H
#define UTAK_IMPRESSION_H

#include <stdint.h>

/* The retina (paper 2.2, its 160 cells): 64 foveal cells of one square, 48 cells of
 * 2x2 squares, 48 of 4x4 squares; a 32x32-square field. */
enum {
	RETINA_CELLS = 160,
	RETINA_FOVEA = 64,
	RETINA_INTERMEDIATE = 48,
	RETINA_PERIPHERAL = 48,
	RETINA_FIELD = 32,	/* the field is RETINA_FIELD x RETINA_FIELD squares */
	RETINA_LEVELS = 8,	/* gray levels 0..7: 3 bits */
	TOUCH_CELLS = 8,	/* the squares around Utak */
};

/* One retinal and tactile impression. Cell i of the retina is described by
 * eye_cell(i) (eye.h); touch[k] is the colour of the k-th square around Utak in
 * his own frame, in the order ahead, ahead-right, right, behind-right, behind,
 * behind-left, left, ahead-left: '.' floor, 'B' verge, 'A'..'Z' an object. */
typedef struct Impression {
	uint8_t level[RETINA_CELLS];
	char touch[TOUCH_CELLS];
} Impression;

/* The five motor outputs of paper 2.2, one active at a time. Displacements are in
 * Utak's own frame (x to his right, y ahead) in TABLE squares; a turn is in
 * degrees, counter-clockwise for positive, of the held object about Utak's point. */
typedef enum MotorKind {
	MOTOR_MOVE,	/* Utak alone, in a straight line */
	MOTOR_GRASP,	/* take hold of an object he touches */
	MOTOR_PUSH,	/* Utak and the held object, rigidly, in a straight line */
	MOTOR_TURN,	/* the held object about Utak's point */
	MOTOR_RELEASE,	/* let go */
} MotorKind;

typedef struct MotorCommand {
	MotorKind kind;
	double dx, dy;	/* move, push: displacement in Utak's frame, squares */
	double deg;	/* turn: degrees, counter-clockwise positive */
} MotorCommand;

#endif
