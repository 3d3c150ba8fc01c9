/* bvh.c - searches the bounding volume hierarchy (built by bvh_build.c) for each
 * instruction set: the search itself is bvh_traverse.h, built once for each, and the box
 * tests it uses bvh_box.h; here too the product of what a shadow ray crosses, in order.
 * See LICENSE for copyright and licence. */
#include "bvh.h"

#include "bvh_box.h"
#include "intersect.h"

#include <string.h>

#define STACK_SIZE (BVH_MAX_DEPTH + 2)

/* The transmitting objects a shadow search crosses, as it meets them: the first
 * BVH_CROSSED here; a ray that crosses more (through a stack of glass panes, say) has them
 * all in crossed_beyond, which one search at a time uses (a process traces one ray at a
 * time). Each object is met once in a search: the index lists it once. */
typedef struct {
	int count;
	int index[BVH_CROSSED];
} crossing;

static int crossed_beyond[RT_MAX_OBJECTS], crossed_spare[RT_MAX_OBJECTS];

static void crossing_add(crossing *c, int o)
{
	if (c->count == BVH_CROSSED)
		memcpy(crossed_beyond, c->index, sizeof c->index);
	if (c->count < BVH_CROSSED)
		c->index[c->count] = o;
	else
		crossed_beyond[c->count] = o;
	c->count++;
}

/* Sorts a[0 .. n) (object indices, below 2^31) by least significant digit first, 8 bits
 * a pass, through `spare` (as long): linear in n, for a ray through thousands of panes.
 * Returns where the sorted list is (a or spare). */
static int *radix_sort(int *a, int *spare, int n)
{
	int most = 0, shift, i;
	for (i = 0; i < n; i++)
		most = a[i] > most ? a[i] : most;
	for (shift = 0; shift < 31 && most >> shift; shift += 8) {
		int start[257] = {0}, *swap;
		for (i = 0; i < n; i++)
			start[(a[i] >> shift & 255) + 1]++;
		for (i = 0; i < 256; i++)
			start[i + 1] += start[i];
		for (i = 0; i < n; i++)
			spare[start[a[i] >> shift & 255]++] = a[i];
		swap = a;
		a = spare;
		spare = swap;
	}
	return a;
}

/* The product of the kt of the objects list[0 .. n), in the list's order. */
static real product_of(const scene *s, const int *list, int n)
{
	real pass = REAL_C(1.0);
	int i;
	for (i = 0; i < n; i++)
		pass = real_mul(pass, s->materials[s->objects[list[i]].material].kt);
	return pass;
}

real bvh_pass_in_order(const scene *s, int *list, int n)
{
	int i;
	for (i = 1; i < n; i++) {
		int o = list[i], j;
		for (j = i; j > 0 && list[j - 1] > o; j--)
			list[j] = list[j - 1];
		list[j] = o;
	}
	return product_of(s, list, n);
}

/* The product of the kt of the transmitting objects a shadow search crossed, in the
 * objects' order, as the object-by-object search takes it: a product of three or more
 * rounds by its order, which the tree's would not keep. A few are sorted in place, more
 * by radix sort. */
static real transmittance_in_order(const scene *s, crossing *c)
{
	if (c->count > BVH_CROSSED)
		return product_of(s, radix_sort(crossed_beyond, crossed_spare, c->count), c->count);
	return bvh_pass_in_order(s, c->index, c->count);
}

/* The search is built into one function for each query, the query a constant in each:
 * a search of either kind then carries no test of which it is, and no arguments the
 * other needs (on SPD balls, 2 % of the instructions). */
#if defined(__GNUC__)
#define TRAVERSE_INLINE __attribute__((always_inline)) inline
#else
#define TRAVERSE_INLINE inline
#endif

#define TRAVERSE traverse
#define TRAVERSE_TARGET
#define WIDE_HIT wide_hit
#if WIDE_SSE
#define WIDE_PREPARE wide_ray_broadcast
#else
#define WIDE_PREPARE(w) ((void)(w))
#endif
#include "bvh_traverse.h"

static int nearest(const scene *s, const bvh_tree *t, const ray *r, int skip, real tmax, hit *h)
{
	int found;
	(void)traverse(s, t, r, skip, tmax, h, 0, &found);
	return found;
}

static real transmittance(const scene *s, const bvh_tree *t, const ray *r, int skip, real tmax,
			  int *blocker)
{
	return traverse(s, t, r, skip, tmax, NULL, 1, blocker);
}

#if WIDE_AVX
#define TRAVERSE traverse_avx
#define TRAVERSE_TARGET WIDE_AVX_TARGET
#define WIDE_HIT wide_hit_avx
#define WIDE_PREPARE(w) ((void)(w))
#include "bvh_traverse.h"

static WIDE_AVX_TARGET int nearest_avx(const scene *s, const bvh_tree *t, const ray *r, int skip,
				       real tmax, hit *h)
{
	int found;
	(void)traverse_avx(s, t, r, skip, tmax, h, 0, &found);
	return found;
}

static WIDE_AVX_TARGET real transmittance_avx(const scene *s, const bvh_tree *t, const ray *r,
					      int skip, real tmax, int *blocker)
{
	return traverse_avx(s, t, r, skip, tmax, NULL, 1, blocker);
}
#endif

int bvh_nearest(const scene *s, const bvh_tree *t, const ray *r, int skip, real tmax, hit *h)
{
#if WIDE_AVX
	if (avx_present())
		return nearest_avx(s, t, r, skip, tmax, h);
#endif
	return nearest(s, t, r, skip, tmax, h);
}

real bvh_transmittance(const scene *s, const bvh_tree *t, const ray *r, int skip, real tmax,
		       int *blocker)
{
#if WIDE_AVX
	if (avx_present())
		return transmittance_avx(s, t, r, skip, tmax, blocker);
#endif
	return transmittance(s, t, r, skip, tmax, blocker);
}

#if BVH_WIDE
/* Adds object o to objects[0 .. *count) unless it is `skip`, listed already (a long
 * cone's pieces are in several leaves), or of one piece with a box the region misses (a
 * cone's piece is known by its leaf's box alone, which holds it). Returns 0 when the list
 * would pass `room`. */
static int list_object(const scene *s, bvh_region_test *meets, const void *region, int skip,
		       int o, int *objects, int room, int *count)
{
	bvh_point lo, hi;
	int k;
	for (k = 0; k < *count && objects[k] != o; k++)
		;
	if (o == skip || k < *count)
		return 1;
	if (bvh_object_pieces(s, o) == 1 && bvh_object_box(s, o, &lo, &hi) &&
	    !meets(region, lo, hi))
		return 1;
	if (*count == room)
		return 0;
	objects[(*count)++] = o;
	return 1;
}

int bvh_objects_meeting(const scene *s, const bvh_tree *t, bvh_region_test *meets,
			const void *region, int skip, int *objects, int room, long lanes,
			int *count)
{
	int stack[(WIDE_LANES - 1) * (BVH_MAX_DEPTH + 1) + 2], top = 1;
	*count = 0;
	stack[0] = 0; /* the root */
	while (top > 0) {
		const bvh_wide_node *w = &t->wide[stack[--top]];
		int lane, i;
		for (lane = 0; lane < WIDE_LANES && w->child[lane] >= 0; lane++) {
			int child = w->child[lane], n = w->count[lane];
			bvh_point box[2];
			if (--lanes < 0)
				return 0;
			bvh_lane_box(w, lane, box);
			if (!meets(region, box[0], box[1]))
				continue;
			if (!n) {
				stack[top++] = child;
				continue;
			}
			if (n == WIDE_ONE_OBJECT) {
				if (!list_object(s, meets, region, skip, child, objects, room,
						 count))
					return 0;
				continue;
			}
			for (i = child; i < child + n; i++)
				if (!list_object(s, meets, region, skip, t->index[i], objects, room,
						 count))
					return 0;
		}
	}
	return 1;
}
#endif
