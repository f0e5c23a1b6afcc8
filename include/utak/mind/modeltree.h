/* modeltree.h - the tree of Utak's world model, derived from its evidence (paper 3.3,
 * 3.4.2, 3.4.3). CONTROLLER SIDE.
 *
 * worldmodel.h describes the tree (ModelNode, ModelRing, ModelVertex) and the
 * evidence it is read from; modeltree.c derives it. The world model calls these
 * after every change to its evidence; nothing else needs to. */
#ifndef UTAK_MODELTREE_H
#define UTAK_MODELTREE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "utak/mind/worldmodel.h"

/* modeltree_derive(m): the tree from m's evidence (its seen_ window kept up to date
 * by the caller): $org, $floor, one node per isolated object and one per uncertain
 * occupied set; objects keep their idents from the last derivation. */
void modeltree_derive(WorldModel *m);

/* modeltree_dump(m, id, depth, f): node id and its sons, indented by depth (the
 * format of worldmodel_dump). */
void modeltree_dump(const WorldModel *m, int32_t id, int depth, FILE *f);

/* modeltree_validate(m, why, size): the tree's invariants (worldmodel_validate). */
bool modeltree_validate(const WorldModel *m, char *why, size_t size);

#endif
