/* bvh_build.c - builds the bounding volume hierarchy over the scene's objects, in static
 * arrays, once after parsing: a binary tree by the binned surface area heuristic, then
 * (floating-point types) the same tree collapsed into nodes of four children, whose float
 * boxes bvh.c tests four at once.
 * See LICENSE for copyright and licence. */
#include "bvh.h"

#include "box.h"
#include "intersect.h"


#define BINS 16    /* SAH candidate planes per axis, minus one */
#define MAX_LEAF 4 /* a leaf holds at most this many objects when it can be split */

RT_STATIC_ASSERT(node_count_fits, 2 * (long)RT_MAX_OBJECTS < 2147483647L);

/* Build scratch: each bounded object's bounds and their centre, kept in the order of the
 * tree's index (partitioned with it), so that every pass over a node's objects reads
 * memory in order: reached through the index, the 1 M sphere build spent most of its 1.4 s
 * waiting for memory. */
typedef struct {
	vec3 lo, hi, centre;
	int object;
} build_item;
static build_item items[RT_MAX_OBJECTS];

/* The bin (0 .. BINS-1) of a centre at `offset` past the lowest centre, out of `extent`.
 * The comparison keeps a NaN or out-of-range quotient from reaching the int conversion. */
static int bin_of(real offset, real extent)
{
	real b = real_mul(real_div(offset, extent), real_from_int(BINS));
	return b >= REAL_C(0.0) ? (b < real_from_int(BINS) ? real_to_int(b) : BINS - 1) : 0;
}

/* bin_of by a product with scale = BINS / extent, where that cannot decide otherwise:
 * the product and the quotient differ by a few roundings, so only an offset within
 * BIN_SLACK of a bin's edge takes the quotient, and every bin is bin_of's (the same
 * tree, a division per object and axis fewer: the 1 M sphere build took 1.8 s). Fixed
 * point keeps its quotient: its product rounds differently. */
#define BIN_SLACK REAL_C(0.00001)
static int bin_by_scale(real offset, real extent, real scale)
{
	real b = real_mul(offset, scale);
	if (!REAL_SATURATES && b >= REAL_C(0.0) && b < real_from_int(BINS)) {
		int whole = real_to_int(b);
		real part = b - real_from_int(whole);
		if (part > BIN_SLACK && part < REAL_C(1.0) - BIN_SLACK)
			return whole;
	}
	return bin_of(offset, extent);
}

static real2 half_area(vec3 lo, vec3 hi)
{
	vec3 d = vec_sub(hi, lo);
	if (d.x < 0 || d.y < 0 || d.z < 0)
		return 0;
	return real_mul2(d.x, d.y) + real_mul2(d.y, d.z) + real_mul2(d.z, d.x);
}

/* Chooses the split of index[first .. first+count), whose centres lie in [clo, chi], with
 * the lowest SAH cost over BINS bins of centres per axis and partitions the objects by
 * it. Returns the number moved to the left, or 0 when a leaf is cheaper and small enough,
 * or when all centres coincide. */
static int sah_split(int first, int count, vec3 node_lo, vec3 node_hi, vec3 clo,
		     vec3 chi, int *axis_out)
{
	real2 node_area = half_area(node_lo, node_hi);
	real best_cost, lo[3], extent[3], scale[3];
	int bin_count[3][BINS];
	vec3 bin_lo[3][BINS], bin_hi[3][BINS];
	int best_axis = -1, best_plane = 0, axis, i, left;
	for (axis = 0; axis < 3; axis++) {
		lo[axis] = vec_get(clo, axis);
		extent[axis] = vec_get(chi, axis) - lo[axis];
		scale[axis] = extent[axis] > REAL_C(0.0) && !REAL_SATURATES
				      ? real_div(real_from_int(BINS), extent[axis])
				      : REAL_C(0.0);
		for (i = 0; i < BINS; i++) {
			bin_count[axis][i] = 0;
			box_empty(&bin_lo[axis][i], &bin_hi[axis][i]);
		}
	}
	/* One pass over the objects bins them on all three axes. */
	for (i = 0; i < count; i++) {
		const build_item *o = &items[first + i];
		for (axis = 0; axis < 3; axis++) {
			int b;
			if (!(extent[axis] > REAL_C(0.0)))
				continue;
			b = bin_by_scale(vec_get(o->centre, axis) - lo[axis], extent[axis], scale[axis]);
			bin_count[axis][b]++;
			box_grow_box(&bin_lo[axis][b], &bin_hi[axis][b], o->lo, o->hi);
		}
	}
	/* Leaf cost: one intersection per object; a split costs one traversal step plus the
	 * children's objects weighted by the chance of entering each. */
	best_cost = REAL_MAX;
	for (axis = 0; axis < 3; axis++) {
		vec3 run_lo, run_hi;
		real2 right_area[BINS];
		int right_count[BINS], n;
		if (!(extent[axis] > REAL_C(0.0)))
			continue;
		/* Sweep from the right, then from the left, pricing each plane between bins.
		 * An empty bin's box is inside out (+MAX..-MAX) and must not be grown by. */
		box_empty(&run_lo, &run_hi);
		n = 0;
		for (i = BINS - 1; i > 0; i--) {
			n += bin_count[axis][i];
			if (bin_count[axis][i])
				box_grow_box(&run_lo, &run_hi, bin_lo[axis][i], bin_hi[axis][i]);
			/* Only the planes after a bin with objects are priced (below). */
			right_area[i] = bin_count[axis][i - 1] ? half_area(run_lo, run_hi) : 0;
			right_count[i] = n;
		}
		box_empty(&run_lo, &run_hi);
		n = 0;
		for (i = 0; i < BINS - 1; i++) {
			real cost;
			n += bin_count[axis][i];
			if (bin_count[axis][i])
				box_grow_box(&run_lo, &run_hi, bin_lo[axis][i], bin_hi[axis][i]);
			/* The plane after an empty bin parts the objects as the one before it
			 * does, at the same cost, which cannot be lower: most planes of a small
			 * node, where the pricing is most of the work. */
			if (n == 0 || right_count[i + 1] == 0 || !bin_count[axis][i])
				continue;
			/* Areas relative to the node's: the chance that a ray entering the node
			 * enters each child. */
			cost = REAL_C(0.5) +
			       real_mul(real2_ratio(half_area(run_lo, run_hi), node_area),
					real_from_int(n)) +
			       real_mul(real2_ratio(right_area[i + 1], node_area),
					real_from_int(right_count[i + 1]));
			if (cost < best_cost) {
				best_cost = cost;
				best_axis = axis;
				best_plane = i;
			}
		}
	}
	/* Keep a leaf when that is cheaper, unless it would be too big. */
	if (best_axis < 0 || (best_cost >= real_from_int(count) && count <= MAX_LEAF))
		return 0;
	/* Partition: objects whose centre falls in bins 0..best_plane go left. */
	{
		int j = first + count - 1;
		i = first;
		while (i <= j) {
			int b = bin_by_scale(vec_get(items[i].centre, best_axis) - lo[best_axis],
					     extent[best_axis], scale[best_axis]);
			if (b <= best_plane) {
				i++;
			} else {
				build_item swap = items[i];
				items[i] = items[j];
				items[j--] = swap;
			}
		}
		left = i - first;
	}
	*axis_out = best_axis;
	return left > 0 && left < count ? left : 0;
}

/* A box corner as the node keeps it: rounded outwards (up for the upper corner) where
 * that is to float, else as it is. */
static bvh_point corner_outward(vec3 v, int up)
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

/* Fills node `node` for index[first .. first+count) and recurses into its children.
 * Recursion depth is at most BVH_MAX_DEPTH. */
static void build_node(bvh_tree *t, int node, int first, int count, int depth)
{
	bvh_node *n = &t->nodes[node];
	int i, left = 0, axis = 0;
	vec3 lo, hi, clo, chi; /* the bounds of the objects, and of their centres */
	box_empty(&lo, &hi);
	box_empty(&clo, &chi);
	for (i = 0; i < count; i++) {
		const build_item *o = &items[first + i];
		box_grow_box(&lo, &hi, o->lo, o->hi);
		box_grow(&clo, &chi, o->centre);
	}
	n->bounds[0] = corner_outward(lo, 0);
	n->bounds[1] = corner_outward(hi, 1);
	if (count > 1 && depth < BVH_MAX_DEPTH) {
		left = sah_split(first, count, lo, hi, clo, chi, &axis);
		/* Too many objects for one leaf but no plane between their centres (all
		 * centres equal): split the list in half. */
		if (!left && count > MAX_LEAF) {
			left = count / 2;
			axis = 0;
		}
	}
	if (!left) {
		n->start = first;
		n->count = (short)count;
		n->axis = 0;
		return;
	}
	n->start = t->node_count;
	n->count = 0;
	n->axis = (short)axis;
	t->node_count += 2;
	build_node(t, n->start, first, left, depth + 1);
	build_node(t, n->start + 1, first + left, count - left, depth + 1);
}

#if BVH_WIDE
/* Corner `side` of node n's box. */
static vec3 bvh_corner(const bvh_node *n, int side)
{
	return vec_make(bvh_bound(n, side, 0), bvh_bound(n, side, 1), bvh_bound(n, side, 2));
}

/* Fills wide node w's lanes from binary nodes lane[0 .. n) and recurses into the inner
 * ones; the rest of the four lanes are empty (a box inside out, which no ray enters). */
static void wide_fill(bvh_tree *t, int w, const int *lane, int n);

/* Collapses binary node b (with its subtree) into a new wide node; returns its number.
 * The lanes start as b's children, and the inner lane with the largest box is opened
 * into its two children until there are four lanes or only leaves. */
static int wide_collapse(bvh_tree *t, int b)
{
	int lane[4], n = 0, w = t->wide_count++;
	if (t->nodes[b].count) {
		lane[n++] = b;
	} else {
		lane[n++] = t->nodes[b].start;
		lane[n++] = t->nodes[b].start + 1;
	}
	while (n < 4) {
		int i, widest = -1;
		real2 widest_area = 0;
		for (i = 0; i < n; i++) {
			const bvh_node *c = &t->nodes[lane[i]];
			real2 area = half_area(bvh_corner(c, 0), bvh_corner(c, 1));
			if (!c->count && (widest < 0 || area > widest_area)) {
				widest = i;
				widest_area = area;
			}
		}
		if (widest < 0)
			break;
		lane[n++] = t->nodes[lane[widest]].start + 1;
		lane[widest] = t->nodes[lane[widest]].start;
	}
	wide_fill(t, w, lane, n);
	return w;
}

static void wide_fill(bvh_tree *t, int w, const int *lane, int n)
{
	int i, axis;
	for (i = 0; i < 4; i++) {
		const bvh_node *c = i < n ? &t->nodes[lane[i]] : NULL;
		for (axis = 0; axis < 3; axis++) {
			t->wide[w].box[2 * axis][i] = c ? (float)bvh_bound(c, 0, axis) : INFINITY;
			t->wide[w].box[2 * axis + 1][i] = c ? (float)bvh_bound(c, 1, axis) : -INFINITY;
		}
		t->wide[w].count[i] = c ? c->count : 0;
		t->wide[w].child[i] = !c ? -1 : c->count ? c->start : wide_collapse(t, lane[i]);
	}
}
#endif

void bvh_build(bvh_tree *t, const scene *s)
{
	static unsigned char bounded[RT_MAX_OBJECTS];
	int i, next;
	t->node_count = 0;
	t->unbounded_count = 0;
	t->wide_count = 0;
	if (s->object_count < RT_BVH_MIN_OBJECTS)
		return;
	for (i = 0; i < s->object_count; i++) {
		vec3 lo, hi;
		bounded[i] = shape_bounds(s, &s->objects[i], &lo, &hi) && vec_is_finite(lo) &&
			     vec_is_finite(hi);
		if (bounded[i]) {
			/* Pad by the secondary-ray offset scale so rounding never loses a hit that
			 * the object's own test would find. */
			real pad = real_surface_offset(
				real_max(REAL_C(1.0), real_max(vec_max_abs(lo), vec_max_abs(hi))), 1);
			vec3 p = vec_make(pad, pad, pad);
			build_item *item = &items[i];
			item->lo = vec_sub(lo, p);
			item->hi = vec_add(hi, p);
			item->centre = vec_scale(vec_add(item->lo, item->hi), REAL_C(0.5));
			item->object = i;
		} else {
			t->index[t->unbounded_count++] = i;
		}
	}
	/* Unbounded objects first, then the bounded ones the tree is built over: item i
	 * moves up to slot unbounded_count + (bounded objects before i), from the last down,
	 * so that none is overwritten before it moves; the index takes the items' order when
	 * the tree is done. */
	next = s->object_count;
	for (i = s->object_count - 1; i >= 0; i--)
		if (bounded[i])
			items[--next] = items[i];
	if (next == s->object_count)
		return;
	t->node_count = 1;
	build_node(t, 0, t->unbounded_count, s->object_count - t->unbounded_count, 0);
	for (i = t->unbounded_count; i < s->object_count; i++)
		t->index[i] = items[i].object;
#if BVH_WIDE
	t->wide_count = 0;
	(void)wide_collapse(t, 0);
#endif
}

