/* bvh.h - the bounding volume hierarchy that makes large scenes fast: built once from
 * the loaded scene, beside it (the scene itself stays as loaded), and searched by
 * intersect.c's queries through their accel.
 * Optional at compile time (RT_USE_BVH=0 leaves it out, as the MCU build does: accel is
 * then the scene alone, and nothing calls this).
 * See LICENSE for copyright and licence. */
#ifndef RT_BVH_H
#define RT_BVH_H

#include "shape.h"

#define BVH_MAX_DEPTH 60 /* deeper nodes become leaves; bounds the traversal stacks */

/* Floating-point types search a wide tree with float boxes, the binary tree of the
 * build's splits collapsed as it is made; fixed point, which uses no floating point at
 * all, searches that binary tree itself. */
#define BVH_WIDE (!REAL_FLOAT_FREE)
/* Lanes of a wide node: eight, which cuts the steps a ray takes through a tree of
 * four-wide nodes by about a third, and with them the branches it mispredicts. */
#define WIDE_LANES 8
/* At most n L / (2 (L - 1)) wide nodes for n objects and L lanes: a node with an inner
 * lane has all L lanes (bvh_build.c opens nodes until then), one without has at least
 * two leaf lanes, and there are at most n leaves; so with T nodes of leaves only, the N
 * others hold L N = (T + N - 1) inner lanes + at most n - 2 T leaf lanes, and T + N is
 * largest at T = n / 2. */
#define BVH_WIDE_NODES \
	(BVH_WIDE ? RT_MAX_OBJECTS / 2 + RT_MAX_OBJECTS / (2 * (WIDE_LANES - 1)) + 1 : 1)

#if BVH_WIDE
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

/* x rounded to float towards +infinity (up) or -infinity: a bound on x. Beyond float's
 * range the infinity on x's side or the largest float (converting it is undefined). The
 * step to the next float is made by its bits (IEEE floats are ordered like their
 * magnitudes' bit patterns; no libm call) and without a branch on whether it is needed:
 * half of all corners need it, a coin toss for the processor's prediction (a million
 * spheres' boxes took 0.070 s, 0.031 s now). */
static inline float float_outward(real x, int up)
{
	float f;
	uint32_t bits, step;
	if (x > (real)FLT_MAX)
		return up ? INFINITY : FLT_MAX;
	if (x < (real)-FLT_MAX)
		return up ? -FLT_MAX : -INFINITY;
	f = (float)x;
	step = (uint32_t)(up ? (real)f < x : (real)f > x);
	if (f == 0.0f) /* the least subnormal on x's side */
		return step ? (up ? FLT_MIN * FLT_EPSILON : -FLT_MIN * FLT_EPSILON) : f;
	memcpy(&bits, &f, sizeof bits);
	/* Away from zero for a step outwards from a float on the same side of zero. */
	bits += (f > 0.0f) == (up != 0) ? step : (uint32_t)0 - step;
	memcpy(&f, &bits, sizeof f);
	return f;
}
#endif

/* A corner of a box of the tree: in floating-point types rounded outwards to float
 * (half the memory of double, a third of long double's: a million objects' tree stays
 * small), which the wide tree's lanes take as they are. */
#if BVH_WIDE
typedef struct {
	float x, y, z;
} bvh_point;
#else
typedef vec3 bvh_point;
#endif

/* A coordinate of corner p, as a real. */
static inline real bvh_point_get(const bvh_point *p, int axis)
{
	return axis == 0 ? (real)p->x : axis == 1 ? (real)p->y : (real)p->z;
}

/* A node of the binary tree (bvh_build.c), which fixed point searches. */
typedef struct {
	bvh_point bounds[2]; /* lower and upper corner */
	int start;   /* leaf: first slot in scene.bvh_index; inner: left child (right = start+1) */
	short count; /* leaf: number of objects; 0 marks an inner node */
	short axis;  /* inner: the split axis, for front-to-back traversal */
} bvh_node;

/* Corner `side` (0 lower, 1 upper) of node n's box on an axis. */
static inline real bvh_bound(const bvh_node *n, int side, int axis)
{
	return bvh_point_get(&n->bounds[side], axis);
}

/* A node of the wide tree: the binary tree with every node's children replaced by
 * grandchildren until it has WIDE_LANES (or only leaves left). Its boxes are the binary
 * nodes' rounded outwards to float, so that a box may be too big but never too small;
 * they are stored by row, box[2 axis + side][lane] (side 0 the lower bound, 1 the upper),
 * so that four lanes of a row (SSE) or all eight (AVX) are one load. */
typedef struct {
	float box[6][WIDE_LANES];
	int child[WIDE_LANES]; /* inner lane: a wide node; leaf lane: the first slot in the
				* index, or with count WIDE_ONE_OBJECT the object */
	int count[WIDE_LANES]; /* leaf lane: number of objects; 0: an inner lane, or empty
				* (child -1) */
} bvh_wide_node;

/* The box of lane `lane` of wide node w: its lower corner in box[0], upper in box[1]. */
static inline void bvh_lane_box(const bvh_wide_node *w, int lane, bvh_point box[2])
{
	box[0].x = w->box[0][lane];
	box[1].x = w->box[1][lane];
	box[0].y = w->box[2][lane];
	box[1].y = w->box[3][lane];
	box[0].z = w->box[4][lane];
	box[1].z = w->box[5][lane];
}

/* The count of a leaf lane of one object, whose child is the object's number. */
#define WIDE_ONE_OBJECT (-1)


typedef struct {
	/* node_count 0 means no hierarchy (small scenes test every object); else the nodes
	 * of the binary tree the splits make (in the floating types a count only: that tree
	 * is collapsed into the wide one as it is made, bvh_build.c). index[0 ..
	 * unbounded_count) are objects without finite bounds (planes, open polyhedra),
	 * tested for every ray; the tree's leaves hold the rest. */
	int node_count, unbounded_count;
	int wide_count; /* BVH_WIDE: the wide tree, its root at wide[0], when node_count > 0 */
	/* The index first of the arrays: the tree may begin in the first huge page of the
	 * static data, among small arrays written at start, where no huge page can be made
	 * (pages.h); the index is the smallest, and the nodes then begin 16 MB on (8 MB on
	 * a 32-bit host), where the build plans them. Nothing is written just before them
	 * either: a count written beside the wide nodes before their plan took its first
	 * huge page (SPD rings' wide nodes then all on small pages in some runs). */
	int index[RT_MAX_OBJECTS];
#if BVH_WIDE
	bvh_wide_node wide[BVH_WIDE_NODES];
#else
	bvh_node nodes[2 * RT_MAX_OBJECTS];
#endif
} bvh_tree;

/* Builds the hierarchy of s into t; scenes smaller than RT_BVH_MIN_OBJECTS get none
 * (node_count = 0) and are searched object by object. */
void bvh_build(bvh_tree *t, const scene *s);

/* How many boxes the build gives bounded object `index` of s when capacity allows: a
 * long cone's side is cut into pieces, each in a leaf of its own; others have one. The
 * bounds of its piece `piece` (of `pieces`) go into lo, hi. */
int bvh_object_pieces(const scene *s, int index);
int bvh_piece_bounds(const scene *s, int index, int piece, int pieces, vec3 *lo, vec3 *hi);

/* A corner back as reals (exact: a float is a real in every floating type). */
static inline vec3 bvh_point_vec(bvh_point p)
{
	return vec_make((real)p.x, (real)p.y, (real)p.z);
}

/* A box corner as the nodes keep it: rounded outwards (up for the upper corner) where
 * that is to float, else as it is. */
static inline bvh_point bvh_round_corner(vec3 v, int up)
{
#if BVH_WIDE
	bvh_point p;
	p.x = float_outward(v.x, up);
	p.y = float_outward(v.y, up);
	p.z = float_outward(v.z, up);
	return p;
#else
	(void)up;
	return v;
#endif
}

/* Object `index`'s whole box, padded and rounded as the tree's boxes of it (each of its
 * pieces lies within it); 0 for an object without finite bounds. */
int bvh_object_box(const scene *s, int index, bvh_point *lo, bvh_point *hi);

/* Nearest hit along r over (0, tmax), through the hierarchy (and the unbounded objects),
 * leaving out object `skip` (-1 for none; see object_can_rehit); fills h (normals not yet
 * faced to the ray) and h->object. */
int bvh_nearest(const scene *s, const bvh_tree *t, const ray *r, int skip, real tmax, hit *h);

/* Light passing along r over (0, tmax), leaving out `skip`: 0 at an opaque blocker, else
 * the product of the kt of the transmitting objects crossed, taken in the objects' order
 * as the object-by-object search takes it (a product of three or more rounds by its
 * order); *blocker gets the opaque blocker, or -1. A search notes up to BVH_CROSSED of
 * them in its own frame, more in a buffer of the scene's capacity. */
#define BVH_CROSSED 16
real bvh_transmittance(const scene *s, const bvh_tree *t, const ray *r, int skip, real tmax,
		       int *blocker);

/* The product of the kt of the transmitting objects list[0 .. n), in the objects' order as
 * bvh_transmittance takes it; sorts the list (by insertion: for a few). */
real bvh_pass_in_order(const scene *s, int *list, int n);

#if BVH_WIDE
/* Whether a region meets the box [lo, hi] (a tree's corners, or an object's as the tree
 * pads them). */
typedef int bvh_region_test(const void *region, bvh_point lo, bvh_point hi);

/* Lists in objects[0 .. *count) the objects other than `skip` whose boxes meet a region,
 * each once: through the wide tree, each leaf lane's objects by their own boxes (a long
 * cone cut in pieces, bvh_pieces.c, by the lane's box, which holds its piece's). Returns
 * 0 when they are more than `room`, or when finding them takes more than `lanes` of the
 * tree's lanes. */
int bvh_objects_meeting(const scene *s, const bvh_tree *t, bvh_region_test *meets,
			const void *region, int skip, int *objects, int room, long lanes,
			int *count);
#endif
#endif
