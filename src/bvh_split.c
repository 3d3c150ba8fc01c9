/* bvh_split.c - how the hierarchy's build parts a node's objects: the build's items (each
 * bounded object's box, kept in the tree's order) and the split of a run of them by the
 * surface area heuristic by bins (small runs: bvh_small_split.c); bvh_build.c makes the
 * trees.
 * See LICENSE for copyright and licence. */
#include "bvh_split.h"

#include "bvh_items.h"
#include "pages.h"

/* x86 (SSE2, every x86-64): the binning and the partition take an item's corners four
 * floats at a time (bin_items, partition below); RT_NO_SIMD=1 and other targets take the
 * plain C loops, which give the same tree. Only where float arithmetic is done in float
 * (FLT_EVAL_METHOD 0): a 32-bit build computing in the x87's wider format would bin the
 * plain way differently, and keeps that way throughout. */
#if BVH_WIDE && defined(__SSE2__) && defined(FLT_EVAL_METHOD) && FLT_EVAL_METHOD == 0 && \
	!RT_NO_SIMD
#include <emmintrin.h>
#include <stddef.h>
#define BIN_SSE 1
#else
#define BIN_SSE 0
#endif


/* SAH candidate planes per axis, minus one: BINS for most nodes, FINE_BINS (floating
 * types) for nodes of more than FINE_BINS_FROM objects. With 32 bins everywhere SPD
 * teapot-s12's searches took 0.959 of the instructions (its triangles, all of a size,
 * are parted better near the top of the tree; balls 0.994, the other SPD scenes within
 * 0.3 %), but sweeping the extra bins of every small node made its build 7 ms -> 10 ms;
 * above 256 objects the searches gain as much (0.959) and the build costs no more than a
 * run can show. Fixed point keeps BINS, so its tree and its images stay as they were. */
#define BINS 16
#define FINE_BINS (BVH_WIDE ? 32 : BINS)
#define FINE_BINS_FROM 256

/* Build scratch (bvh_items.h). */
static build_item items[RT_MAX_OBJECTS];

/* The items as bvh_build.c makes and reads them (bvh_split.h). */
void bvh_items_prepare(int count)
{
	pages_prepare(items, (size_t)count * sizeof items[0]);
}

void bvh_items_ahead(int first, int count)
{
	pages_ahead(items, sizeof items[0], (size_t)first, (size_t)count, RT_MAX_OBJECTS);
}

void bvh_item_make(int at, int index, vec3 lo, vec3 hi, real pad)
{
	vec3 p = vec_make(pad, pad, pad);
	items[at].lo = bvh_round_corner(vec_sub(lo, p), 0);
	items[at].hi = bvh_round_corner(vec_add(hi, p), 1);
	items[at].object = index;
}

void bvh_items_shift(int count, int by)
{
	int i;
	for (i = count - 1; i >= 0; i--)
		items[by + i] = items[i];
}

int bvh_item_object(int at)
{
	return items[at].object;
}


/* The bounds of items[first .. first+count). */
bvh_item_bounds bvh_items_bounds(int first, int count)
{
	return items_bounds_of(&items[first], count);
}

/* How one axis's centres fall into `count` bins: from the lowest centre `lo` over
 * `extent`, by a product with `scale` = count / extent in floating types (the same
 * product in the binning and in the partition, so both put an item in the same bin), by
 * the quotient in fixed point (whose product rounds too coarsely). extent 0: one bin, not
 * split. */
typedef struct {
	centre_coord lo, extent, scale;
	int count;
} axis_bins;

static axis_bins axis_bins_make(bvh_point clo, bvh_point chi, int axis, int count)
{
	axis_bins a;
	a.count = count;
	a.lo = point_get(clo, axis);
	a.extent = point_get(chi, axis) - a.lo;
#if BVH_WIDE
	a.scale = a.extent > 0.0f ? (float)count / a.extent : 0.0f;
#else
	a.scale = 0;
#endif
	return a;
}

#if !BIN_SSE
/* The bin (0 .. a->count - 1) of centre c. The comparisons keep a NaN or out-of-range
 * value (centres beyond float's range) from reaching the int conversion. (bins_of, below,
 * is the same for x86.) */
static inline int bin_at(const axis_bins *a, centre_coord c)
{
#if BVH_WIDE
	float b = (c - a->lo) * a->scale;
	return b >= 0.0f ? (b < (float)a->count ? (int)b : a->count - 1) : 0;
#else
	real b = real_mul(real_div(c - a->lo, a->extent), real_from_int(a->count));
	return b >= REAL_C(0.0) ? (b < real_from_int(a->count) ? real_to_int(b) : a->count - 1)
				: 0;
#endif
}
#endif

#if BIN_SSE
/* An item's corners as four floats each: lo.x, lo.y, lo.z and hi.x; hi.x, hi.y, hi.z and
 * the object's number. The fourth lane is never read. */
RT_STATIC_ASSERT(item_floats, offsetof(build_item, hi) == 3 * sizeof(float) &&
				      offsetof(build_item, object) == 6 * sizeof(float));
static inline __m128 item_lo4(const build_item *o)
{
	return _mm_loadu_ps(&o->lo.x);
}
static inline __m128 item_hi4(const build_item *o)
{
	return _mm_loadu_ps(&o->hi.x);
}

/* The corner of the first three lanes of v. */
static inline bvh_point point_of(__m128 v)
{
	float lane[4];
	bvh_point p;
	_mm_storeu_ps(lane, v);
	p.x = lane[0];
	p.y = lane[1];
	p.z = lane[2];
	return p;
}

/* a in the lanes where mask is all ones, b where it is 0. */
static inline __m128 pick(__m128 mask, __m128 a, __m128 b)
{
	return _mm_or_ps(_mm_and_ps(mask, a), _mm_andnot_ps(mask, b));
}

/* b[axis] = bin_at(&bins[axis], the centre's coordinate on axis) for the three axes at
 * once, by the same float difference and product; the clamp as bin_at's (maxps gives
 * its second operand, 0, for a NaN). */
static inline void bins_of(const axis_bins bins[3], __m128 centre, int b[4])
{
	__m128 origin = _mm_setr_ps(bins[0].lo, bins[1].lo, bins[2].lo, 0.0f);
	__m128 scale = _mm_setr_ps(bins[0].scale, bins[1].scale, bins[2].scale, 0.0f);
	__m128 last = _mm_setr_ps((float)(bins[0].count - 1), (float)(bins[1].count - 1),
				  (float)(bins[2].count - 1), 0.0f);
	__m128 place = _mm_mul_ps(_mm_sub_ps(centre, origin), scale);
	place = _mm_min_ps(_mm_max_ps(place, _mm_setzero_ps()), last);
	_mm_storeu_si128((__m128i *)(void *)b, _mm_cvttps_epi32(place));
}
#endif



/* Bins items[first .. first+count) on the three axes whose bins are `bins` (an axis of
 * extent 0 is left alone): each bin's count and the box of its items. */
static void bin_items(int first, int count, const axis_bins bins[3], int bins_used,
		      int bin_count[3][FINE_BINS], bvh_point bin_lo[3][FINE_BINS],
		      bvh_point bin_hi[3][FINE_BINS])
{
	int i, axis;
	for (axis = 0; axis < 3; axis++)
		for (i = 0; i < bins_used; i++) {
			bin_count[axis][i] = 0;
			points_empty(&bin_lo[axis][i], &bin_hi[axis][i]);
		}
#if BIN_SSE
	{
		/* Each bin's box as two vectors, grown by one minimum and one maximum, and the
		 * three axes' bins found by one product: a million spheres' build took 0.70-0.74
		 * of the time of the loop below. */
		__m128 box_lo[3][FINE_BINS], box_hi[3][FINE_BINS];
		int used[3];
		for (axis = 0; axis < 3; axis++) {
			used[axis] = bins[axis].extent > 0;
			for (i = 0; i < bins_used; i++) {
				box_lo[axis][i] = _mm_set1_ps(FLT_MAX);
				box_hi[axis][i] = _mm_set1_ps(-FLT_MAX);
			}
		}
		for (i = 0; i < count; i++) {
			const build_item *o = &items[first + i];
			__m128 lo = item_lo4(o), hi = item_hi4(o);
			int b[4];
			bins_of(bins, _mm_add_ps(lo, hi), b);
			for (axis = 0; axis < 3; axis++) {
				if (!used[axis])
					continue;
				bin_count[axis][b[axis]]++;
				box_lo[axis][b[axis]] = _mm_min_ps(lo, box_lo[axis][b[axis]]);
				box_hi[axis][b[axis]] = _mm_max_ps(hi, box_hi[axis][b[axis]]);
			}
		}
		for (axis = 0; axis < 3; axis++)
			for (i = 0; i < bins_used; i++) {
				bin_lo[axis][i] = point_of(box_lo[axis][i]);
				bin_hi[axis][i] = point_of(box_hi[axis][i]);
			}
	}
#else
	for (i = 0; i < count; i++) {
		const build_item *o = &items[first + i];
		bvh_point centre = item_centre(o);
		for (axis = 0; axis < 3; axis++) {
			int b;
			if (!(bins[axis].extent > 0))
				continue;
			b = bin_at(&bins[axis], point_get(centre, axis));
			bin_count[axis][b]++;
			points_grow(&bin_lo[axis][b], &bin_hi[axis][b], &o->lo, &o->hi);
		}
	}
#endif
}

/* Partition: objects whose centre falls in bins 0..plane of axis `axis` go left, in one
 * pass without a branch on the side (each item swapped with the first right one, which
 * stays where it is when the item is right too): which side an object falls on is a coin
 * toss the processor cannot predict, and a branch on it made this partition as slow as
 * the binning (a million spheres' build 0.94 s, then 0.83 s). child[0] and child[1] get
 * their centres' bounds; returns the number that went left. */
static int partition(int first, int count, const axis_bins bins[3], int axis, int plane,
		     bvh_item_bounds child[2])
{
	int i, to = first;
#if BIN_SSE
	/* Both sides' centre bounds in registers, each item's centre or a bound that
	 * changes nothing chosen for each side by masks, where growing the side's bounds in
	 * memory waited on the last item's. */
	const __m128 no_lo = _mm_set1_ps(FLT_MAX), no_hi = _mm_set1_ps(-FLT_MAX);
	__m128 left_lo = no_lo, left_hi = no_hi, right_lo = no_lo, right_hi = no_hi;
	for (i = first; i < first + count; i++) {
		/* The corners loaded from the array, not from the copy (whose 16-byte loads
		 * would wait on its smaller stores). */
		__m128 centre = _mm_add_ps(item_lo4(&items[i]), item_hi4(&items[i]));
		build_item item = items[i];
		__m128 side;
		int b[4], right;
		bins_of(bins, centre, b);
		right = b[axis] > plane;
		side = _mm_castsi128_ps(_mm_set1_epi32(-right)); /* all ones: right */
		left_lo = _mm_min_ps(pick(side, no_lo, centre), left_lo);
		left_hi = _mm_max_ps(pick(side, no_hi, centre), left_hi);
		right_lo = _mm_min_ps(pick(side, centre, no_lo), right_lo);
		right_hi = _mm_max_ps(pick(side, centre, no_hi), right_hi);
		items[i] = items[to];
		items[to] = item;
		to += !right;
	}
	child[0].clo = point_of(left_lo);
	child[0].chi = point_of(left_hi);
	child[1].clo = point_of(right_lo);
	child[1].chi = point_of(right_hi);
#else
	for (i = 0; i < 2; i++)
		points_empty(&child[i].clo, &child[i].chi);
	for (i = first; i < first + count; i++) {
		build_item item = items[i];
		bvh_point centre = item_centre(&item);
		int right = bin_at(&bins[axis], point_get(centre, axis)) > plane;
		points_grow(&child[right].clo, &child[right].chi, &centre, &centre);
		items[i] = items[to];
		items[to] = item;
		to += !right;
	}
#endif
	return to - first;
}

/* Chooses the split of items[first .. first+count), whose bounds are `node`, with the
 * lowest SAH cost over the bins of centres on each axis and partitions the objects by it.
 * Returns the number moved to the left, or 0 when a leaf is cheaper and small enough, or
 * when all centres coincide; child[0] and child[1] get the two sides' bounds (the bins'
 * boxes and the centres met in the partition: no pass of their own). */
static int sah_split(int first, int count, const bvh_item_bounds *node, int *axis_out,
		     bvh_item_bounds child[2])
{
	real2 node_area = box_half_area(bvh_point_vec(node->lo), bvh_point_vec(node->hi));
	real best_cost;
	axis_bins bins[3];
	int bin_count[3][FINE_BINS];
	bvh_point bin_lo[3][FINE_BINS], bin_hi[3][FINE_BINS];
	int best_axis = -1, best_plane = 0, axis, i, left;
	int bins_used = count > FINE_BINS_FROM ? FINE_BINS : BINS;
#if BVH_WIDE
	if (count <= SORTED_MAX)
		return bvh_small_split(&items[first], count, node, axis_out, child);
#endif
	for (axis = 0; axis < 3; axis++)
		bins[axis] = axis_bins_make(node->clo, node->chi, axis, bins_used);
	bin_items(first, count, bins, bins_used, bin_count, bin_lo, bin_hi);
	best_cost = REAL_MAX;
	for (axis = 0; axis < 3; axis++) {
		bvh_point run_lo, run_hi;
		real2 right_area[FINE_BINS];
		int right_count[FINE_BINS], n;
		if (!(bins[axis].extent > 0))
			continue;
		/* Sweep from the right, then from the left, pricing each plane between bins.
		 * An empty bin's box is inside out (+MAX..-MAX) and must not be grown by. */
		points_empty(&run_lo, &run_hi);
		n = 0;
		for (i = bins_used - 1; i > 0; i--) {
			n += bin_count[axis][i];
			if (bin_count[axis][i])
				points_grow(&run_lo, &run_hi, &bin_lo[axis][i], &bin_hi[axis][i]);
			/* Only the planes after a bin with objects are priced (below). */
			right_area[i] = bin_count[axis][i - 1]
					      ? box_half_area(bvh_point_vec(run_lo), bvh_point_vec(run_hi))
					      : 0;
			right_count[i] = n;
		}
		points_empty(&run_lo, &run_hi);
		n = 0;
		for (i = 0; i < bins_used - 1; i++) {
			real cost;
			n += bin_count[axis][i];
			if (bin_count[axis][i])
				points_grow(&run_lo, &run_hi, &bin_lo[axis][i], &bin_hi[axis][i]);
			/* The plane after an empty bin parts the objects as the one before it
			 * does, at the same cost, which cannot be lower: most planes of a small
			 * node, where the pricing is most of the work. */
			if (n == 0 || right_count[i + 1] == 0 || !bin_count[axis][i])
				continue;
			cost = split_cost(box_half_area(bvh_point_vec(run_lo), bvh_point_vec(run_hi)), n,
					  right_area[i + 1], right_count[i + 1], node_area);
			if (cost < best_cost) {
				best_cost = cost;
				best_axis = axis;
				best_plane = i;
			}
		}
	}
	if (leaf_is_better(best_axis, best_cost, count))
		return 0;
	/* Each side's box is the union of its bins' boxes (its centres' bounds the
	 * partition's). */
	for (i = 0; i < 2; i++)
		points_empty(&child[i].lo, &child[i].hi);
	for (i = 0; i < bins_used; i++)
		if (bin_count[best_axis][i])
			points_grow(&child[i > best_plane].lo, &child[i > best_plane].hi,
				    &bin_lo[best_axis][i], &bin_hi[best_axis][i]);
	left = partition(first, count, bins, best_axis, best_plane, child);
	*axis_out = best_axis;
	return left > 0 && left < count ? left : 0;
}

/* How items[first .. first+count), whose bounds are `b`, a node at `depth` in the binary
 * tree, are split: the number that go left (0: the node is a leaf), child[0] and child[1]
 * their bounds, *axis the split's. Deeper than BVH_MAX_DEPTH a node is a leaf. */
int bvh_node_split(int first, int count, const bvh_item_bounds *b, int depth, int *axis,
		      bvh_item_bounds child[2])
{
	int left = 0;
	*axis = 0;
	if (count > 1 && depth < BVH_MAX_DEPTH) {
		left = sah_split(first, count, b, axis, child);
		/* Too many objects for one leaf but no plane between their centres (all
		 * centres equal): split the list in half. */
		if (!left && count > MAX_LEAF) {
			left = count / 2;
			*axis = 0;
			child[0] = bvh_items_bounds(first, left);
			child[1] = bvh_items_bounds(first + left, count - left);
		}
	}
	return left;
}
