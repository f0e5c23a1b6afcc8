/* movingai.h - the Moving AI grid benchmark files: .map and .scen (benchmark input
 * for the paper's path-finding comparison, paper 4.1).
 *
 * Format (https://movingai.com/benchmarks/, tests/data/README.md; N. Sturtevant,
 * "Benchmarks for Grid-Based Pathfinding", IEEE TCIAIG 4(2), 2012):
 *   .map  - "type octile", "height H", "width W", "map", then H rows of W characters;
 *           '.' 'G' 'S' are free, '@' 'O' 'T' 'W' blocked. Row r is y = r (y grows
 *           down the file; the planner does not care). CRLF line ends are accepted.
 *   .scen - "version 1" (or "version 1.0"), then one problem per line: bucket, map
 *           name, map width, map height, start x, start y, goal x, goal y, optimal
 *           length, TAB-separated. Blank lines are skipped.
 * Errors are input errors: the reader returns false and writes one line
 * "FILE:LINE: message" (no program name, no newline) into the caller's buffer. */
#ifndef UTAK_MOVINGAI_H
#define UTAK_MOVINGAI_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "utak/plan/grid.h"

/* Room for one error message, file name included. */
#define MOVINGAI_ERROR_SIZE 512

typedef struct MovingAiProblem {
	int32_t bucket;         /* the file's difficulty bucket */
	int32_t sx, sy, gx, gy; /* start and goal cells, map coordinates */
	double optimum;         /* the published optimal 8-connected length */
	int32_t line;           /* line of the .scen file, for messages */
} MovingAiProblem;

typedef struct MovingAiScen {
	int32_t map_w, map_h; /* the map size every problem names */
	int count, cap;
	MovingAiProblem *problems;
} MovingAiScen;

/* movingai_read_map(path, grid, err): reads a .map into grid (which the caller frees
 * with grid_free). */
bool movingai_read_map(const char *path, Grid *grid, char err[MOVINGAI_ERROR_SIZE]);

/* movingai_read_scen(path, grid, scen, err): reads a .scen whose problems must fit
 * grid: the width and height fields equal the grid's, the cells are inside it and
 * free. The caller frees scen with movingai_scen_free. */
bool movingai_read_scen(const char *path, const Grid *grid, MovingAiScen *scen,
                        char err[MOVINGAI_ERROR_SIZE]);
void movingai_scen_free(MovingAiScen *scen);

/* movingai_tolerance(optimum): how far a computed length may be from the published
 * one: the files print about 6 significant digits (README: 1e-3 + 1e-5 x length). */
double movingai_tolerance(double optimum);

#endif
