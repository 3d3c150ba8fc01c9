/* bvh_split.h - the build's items and the splits of runs of them (bvh_split.c), from
 * which bvh_build.c makes the hierarchy's trees.
 * See LICENSE for copyright and licence. */
#ifndef RT_BVH_SPLIT_H
#define RT_BVH_SPLIT_H

#include "bvh.h"

/* The box of some items and the box of their centres. */
typedef struct {
	bvh_point lo, hi;
	bvh_point clo, chi;
} bvh_item_bounds;

/* The items are a static array of RT_MAX_OBJECTS, in the order of the tree's index:
 * bvh_items_prepare makes the first `count` resident at once, bvh_items_ahead the run
 * [first, first+count) (an object in pieces takes several). */
void bvh_items_prepare(int count);
void bvh_items_ahead(int first, int count);
/* Item `at` gets the box [lo, hi] of object `index`, grown by `pad` on every side and
 * rounded outwards as the tree keeps it. */
void bvh_item_make(int at, int index, vec3 lo, vec3 hi, real pad);
/* Moves items [0, count) up by `by` places (the unbounded objects go first in the index). */
void bvh_items_shift(int count, int by);
/* The object of item `at`. */
int bvh_item_object(int at);
/* The bounds of items [first, first+count). */
bvh_item_bounds bvh_items_bounds(int first, int count);
/* How items [first, first+count), whose bounds are `b`, a node at `depth` in the binary
 * tree, are split: reorders them and returns the number that go left (0: the node is a
 * leaf), with child[0] and child[1] their bounds and *axis the split's axis. Deeper than
 * BVH_MAX_DEPTH a node is a leaf. */
int bvh_node_split(int first, int count, const bvh_item_bounds *b, int depth, int *axis,
		   bvh_item_bounds child[2]);

#endif
