/* bvh_items.h - the build's items as its two split files share them (bvh_split.c keeps
 * the array; bvh_small_split.c splits small runs of it): an item's box and centre, the
 * boxes grown over runs of items, and what a split costs.
 * See LICENSE for copyright and licence. */
#ifndef RT_BVH_ITEMS_H
#define RT_BVH_ITEMS_H

#include <float.h>

#include "box.h"
#include "bvh_split.h"

#define MAX_LEAF 4 /* a leaf holds at most this many objects when it can be split */

/* Makes [lo, hi] the empty box, inside out. */
static inline void points_empty(bvh_point *lo, bvh_point *hi)
{
#if BVH_WIDE
	lo->x = lo->y = lo->z = FLT_MAX;
	hi->x = hi->y = hi->z = -FLT_MAX;
#else
	box_empty(lo, hi);
#endif
}

/* Grows [lo, hi] to hold the box [a, b] (a <= b), in the corners' own type. */
static inline void points_grow(bvh_point *lo, bvh_point *hi, const bvh_point *a, const bvh_point *b)
{
	lo->x = a->x < lo->x ? a->x : lo->x;
	lo->y = a->y < lo->y ? a->y : lo->y;
	lo->z = a->z < lo->z ? a->z : lo->z;
	hi->x = b->x > hi->x ? b->x : hi->x;
	hi->y = b->y > hi->y ? b->y : hi->y;
	hi->z = b->z > hi->z ? b->z : hi->z;
}

/* Build scratch: each bounded object's bounds, as the nodes keep them (float, rounded
 * outwards, in floating types: a node's box is then the union of its objects' as they
 * are), kept in the order of the tree's index (partitioned with it), so that every pass
 * over a node's objects reads memory in order: reached through the index, the 1 M sphere
 * build spent most of its 1.4 s waiting for memory, and much of the rest reading boxes
 * of doubles. */
typedef struct {
	bvh_point lo, hi;
	int object;
} build_item;

/* An item's centre, by which it is binned and sorted: in floating types the sum of its
 * corners in float, twice the centre (float arithmetic, and no scaling: binning the
 * 1 M sphere scene in double took most of its build); in fixed point the midpoint (the
 * sum could overflow). A centre is a point of the corners' own type. */
#if BVH_WIDE
typedef float centre_coord;
static inline bvh_point item_centre(const build_item *o)
{
	bvh_point c;
	c.x = o->lo.x + o->hi.x;
	c.y = o->lo.y + o->hi.y;
	c.z = o->lo.z + o->hi.z;
	return c;
}
#else
typedef real centre_coord;
static inline bvh_point item_centre(const build_item *o)
{
	return vec_scale(vec_add(o->lo, o->hi), REAL_C(0.5));
}
#endif

/* A coordinate of a centre or a corner. */
static inline centre_coord point_get(bvh_point c, int axis)
{
	return axis == 0 ? c.x : axis == 1 ? c.y : c.z;
}

/* The bounds of the run of `count` items from `run`. */
static inline bvh_item_bounds items_bounds_of(const build_item *run, int count)
{
	bvh_item_bounds b;
	int i;
	points_empty(&b.lo, &b.hi);
	points_empty(&b.clo, &b.chi);
	for (i = 0; i < count; i++) {
		bvh_point centre = item_centre(&run[i]);
		points_grow(&b.lo, &b.hi, &run[i].lo, &run[i].hi);
		points_grow(&b.clo, &b.chi, &centre, &centre);
	}
	return b;
}

/* Nodes of at most this many objects (most of a tree's nodes) are split by sorting their
 * centres on each axis and pricing every plane between them: exact where binning is not,
 * and with few objects far cheaper than sweeping BINS bins on three axes, which made
 * nearly all of a small scene's build. Fixed point keeps its bins (no sorted split), so
 * that its tree, and its images at the edge of its range, stay as they were. */
#define SORTED_MAX 16

/* The cost of a split, relative to a leaf's of one intersection per object: a traversal
 * step plus each side's objects weighted by the chance that a ray entering the node
 * enters that side (its area relative to the node's). */
static inline real split_cost(real2 left_area, int left, real2 right_area, int right, real2 node_area)
{
	return REAL_C(0.5) + real_mul(real2_ratio(left_area, node_area), real_from_int(left)) +
	       real_mul(real2_ratio(right_area, node_area), real_from_int(right));
}

/* Whether a node stays a leaf: no plane parts its objects, or the best costs no less than
 * the leaf and the leaf is small enough. */
static inline int leaf_is_better(int best_axis, real best_cost, int count)
{
	return best_axis < 0 || (best_cost >= real_from_int(count) && count <= MAX_LEAF);
}

#if BVH_WIDE
/* The split of a run of 2 .. SORTED_MAX items, whose bounds are `node`, exact
 * (bvh_small_split.c): as bvh_node_split's, the number that go left (0: a leaf). */
int bvh_small_split(build_item *run, int count, const bvh_item_bounds *node, int *axis_out,
		    bvh_item_bounds child[2]);
#endif

#endif
