/* bvh.c - a bounding volume hierarchy over the scene's objects, in static arrays.
 * Built once after parsing with the binned surface area heuristic; traversed front to
 * back with a fixed stack, shrinking the search as hits are found.
 * See LICENSE for copyright and licence. */
#include "bvh.h"

#include "box.h"
#include "intersect.h"


#define BINS 16           /* SAH candidate planes per axis, minus one */
#define MAX_LEAF 4        /* a leaf holds at most this many objects when it can be split */
#define MAX_BUILD_DEPTH 60 /* deeper nodes become leaves; bounds the traversal stack */
#define STACK_SIZE (MAX_BUILD_DEPTH + 2)

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
			right_area[i] = half_area(run_lo, run_hi);
			right_count[i] = n;
		}
		box_empty(&run_lo, &run_hi);
		n = 0;
		for (i = 0; i < BINS - 1; i++) {
			real cost;
			n += bin_count[axis][i];
			if (bin_count[axis][i])
				box_grow_box(&run_lo, &run_hi, bin_lo[axis][i], bin_hi[axis][i]);
			if (n == 0 || right_count[i + 1] == 0)
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

/* Fills node `node` for index[first .. first+count) and recurses into its children.
 * Recursion depth is at most MAX_BUILD_DEPTH. */
static void build_node(bvh_tree *t, int node, int first, int count, int depth)
{
	bvh_node *n = &t->nodes[node];
	int i, left = 0, axis = 0;
	vec3 clo, chi; /* the bounds of the objects' centres */
	box_empty(&n->bounds[0], &n->bounds[1]);
	box_empty(&clo, &chi);
	for (i = 0; i < count; i++) {
		const build_item *o = &items[first + i];
		box_grow_box(&n->bounds[0], &n->bounds[1], o->lo, o->hi);
		box_grow(&clo, &chi, o->centre);
	}
	if (count > 1 && depth < MAX_BUILD_DEPTH) {
		left = sah_split(first, count, n->bounds[0], n->bounds[1], clo, chi, &axis);
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

void bvh_build(bvh_tree *t, const scene *s)
{
	static unsigned char bounded[RT_MAX_OBJECTS];
	int i, next;
	t->node_count = 0;
	t->unbounded_count = 0;
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
}

/* A ray prepared for slab tests: 1/d per axis and, per axis, which box corner it meets
 * first. A zero component must mean an infinite slab, decided by the origin alone:
 * floating point gets that from IEEE's 1/0 = +-inf. In Q16.16 a reciprocal saturates
 * (about 32768 for any component below 2^-15), and a box the ray runs along would be cut
 * short and skipped: every eye ray of the image row and column through the eye's own
 * coordinates, and all rays of a narrow view. So a component whose reciprocal passes
 * RECIPROCAL_LIMIT marks its axis `divided`: its slab distances are quotients, which
 * saturate towards the right infinity, and a zero component's are +-infinity by the
 * origin's side. */
typedef struct {
	vec3 origin, inv;
	int near_x, near_y, near_z; /* 0: the lower bound is entered first, 1: the upper */
	int divided; /* 1 when some axis's distances are divided out (slab_distance) */
	dir3 dir;
} slab_ray;

#define RECIPROCAL_LIMIT REAL_C(16384.0) /* 1/d for |d| >= 2^-14, well inside Q16.16 */

/* Where the ray meets the plane `offset` past its origin along an axis of direction
 * component d: the quotient, or for d = 0 +-infinity (REAL_MAX) by the side of the
 * origin, a plane through it counting as behind (near) or ahead (far) so that a ray
 * lying in a box's face still enters the box. */
static real slab_distance(real offset, unit d, int far)
{
	if (d == UNIT_C(0.0))
		return offset > 0 || (offset == 0 && far) ? REAL_MAX : -REAL_MAX;
	return real_div_unit(offset, d);
}

/* box_hit's interval for a ray with a divided axis: every distance a quotient. */
static int box_hit_divided(const bvh_node *n, const slab_ray *r, real tmax, real *tenter)
{
	real tnear = REAL_C(0.0), tfar = tmax;
	int axis;
	for (axis = 0; axis < 3; axis++) {
		int near = axis == 0 ? r->near_x : axis == 1 ? r->near_y : r->near_z;
		unit d = axis == 0 ? r->dir.x : axis == 1 ? r->dir.y : r->dir.z;
		real o = vec_get(r->origin, axis);
		real t0 = slab_distance(real_add(vec_get(n->bounds[near], axis), -o), d, 0);
		real t1 = slab_distance(real_add(vec_get(n->bounds[!near], axis), -o), d, 1);
		tnear = t0 > tnear ? t0 : tnear;
		tfar = t1 < tfar ? t1 : tfar;
	}
	*tenter = tnear;
	return tnear <= tfar;
}

/* Does the ray enter node n's box before tmax? *tenter gets where. The comparisons are
 * written so that NaN from 0 * inf (a ray lying in a slab plane) leaves the interval as
 * it was instead of poisoning it. */
static inline int box_hit(const bvh_node *n, const slab_ray *r, real tmax, real *tenter)
{
	real tnear = REAL_C(0.0), tfar = tmax;
	real x0, x1, y0, y1, z0, z1;
	if (REAL_SATURATES && r->divided)
		return box_hit_divided(n, r, tmax, tenter);
	/* Saturating differences (real_add): a box of an object that reaches the edge of
	 * fixed point's range, less a far origin, would overflow. */
	x0 = real_mul(real_add(n->bounds[r->near_x].x, -r->origin.x), r->inv.x);
	x1 = real_mul(real_add(n->bounds[!r->near_x].x, -r->origin.x), r->inv.x);
	y0 = real_mul(real_add(n->bounds[r->near_y].y, -r->origin.y), r->inv.y);
	y1 = real_mul(real_add(n->bounds[!r->near_y].y, -r->origin.y), r->inv.y);
	z0 = real_mul(real_add(n->bounds[r->near_z].z, -r->origin.z), r->inv.z);
	z1 = real_mul(real_add(n->bounds[!r->near_z].z, -r->origin.z), r->inv.z);
	tnear = x0 > tnear ? x0 : tnear;
	tnear = y0 > tnear ? y0 : tnear;
	tnear = z0 > tnear ? z0 : tnear;
	tfar = x1 < tfar ? x1 : tfar;
	tfar = y1 < tfar ? y1 : tfar;
	tfar = z1 < tfar ? z1 : tfar;
	*tenter = tnear;
	return tnear <= tfar;
}

/* The two queries share one traversal; `shadow` is a constant at each call, so the
 * compiler makes two specialised copies. Nearest: the closest hit, shrinking tmax as hits
 * are found, children visited nearest first. Shadow: the product of the kt of every
 * transmitting object crossed, stopping at the first opaque one (*found gets it, or -1). */
static inline real traverse(const scene *s, const bvh_tree *t, const ray *r, int skip,
			    real tmax, hit *h, int shadow, int *found)
{
	struct {
		int node;
		real enter;
	} stack[STACK_SIZE];
	int top = 0, i;
	real pass = REAL_C(1.0), enter, enter0, enter1;
	slab_ray sr;

	*found = shadow ? -1 : 0;
	/* Visits object `o`: returns 1 when the search is over (an opaque shadow blocker). */
#define VISIT(o)                                                                              \
	do {                                                                                  \
		int visit_ = (o);                                                             \
		if (visit_ == skip) /* the object the ray leaves and cannot meet again */     \
			break;                                                                \
		if (shadow) {                                                                 \
			if (object_intersect(s, visit_, r, REAL_C(0.0), tmax, NULL)) {       \
				real kt_ = s->materials[s->objects[visit_].material].kt;    \
				if (kt_ <= REAL_C(0.0)) {                                     \
					*found = visit_;                                      \
					return REAL_C(0.0);                                   \
				}                                                             \
				pass = real_mul(pass, kt_);                                   \
			}                                                                     \
		} else if (object_intersect(s, visit_, r, REAL_C(0.0), tmax, h)) {           \
			tmax = h->t;                                                          \
			h->object = visit_;                                                   \
			*found = 1;                                                           \
		}                                                                             \
	} while (0)

	for (i = 0; i < t->unbounded_count; i++)
		VISIT(t->index[i]);
	sr.origin = r->origin;
	sr.inv = vec_make(real_div_unit(REAL_C(1.0), r->dir.x), real_div_unit(REAL_C(1.0), r->dir.y),
			  real_div_unit(REAL_C(1.0), r->dir.z));
	sr.near_x = sr.inv.x < REAL_C(0.0);
	sr.near_y = sr.inv.y < REAL_C(0.0);
	sr.near_z = sr.inv.z < REAL_C(0.0);
	sr.dir = r->dir;
	sr.divided = REAL_SATURATES && !(real_fabs(sr.inv.x) < RECIPROCAL_LIMIT &&
					 real_fabs(sr.inv.y) < RECIPROCAL_LIMIT &&
					 real_fabs(sr.inv.z) < RECIPROCAL_LIMIT);
	if (t->node_count && box_hit(&t->nodes[0], &sr, tmax, &enter)) {
		stack[0].node = 0;
		stack[0].enter = enter;
		top = 1;
	}
	while (top > 0) {
		const bvh_node *n;
		top--;
		/* A nearer hit found since this node was pushed may make it pointless. */
		if (!shadow && stack[top].enter > tmax)
			continue;
		n = &t->nodes[stack[top].node];
		if (n->count) {
			for (i = 0; i < n->count; i++)
				VISIT(t->index[n->start + i]);
		} else {
			/* Test both children here and push only those the ray enters, the
			 * nearer one last so that it is searched first. */
			int hit0 = box_hit(&t->nodes[n->start], &sr, tmax, &enter0);
			int hit1 = box_hit(&t->nodes[n->start + 1], &sr, tmax, &enter1);
			if (hit0 && hit1) {
				int near = enter0 <= enter1 ? 0 : 1;
				stack[top].node = n->start + !near;
				stack[top++].enter = near ? enter0 : enter1;
				stack[top].node = n->start + near;
				stack[top++].enter = near ? enter1 : enter0;
			} else if (hit0 || hit1) {
				stack[top].node = n->start + (hit0 ? 0 : 1);
				stack[top++].enter = hit0 ? enter0 : enter1;
			}
		}
	}
#undef VISIT
	return pass;
}

int bvh_nearest(const scene *s, const bvh_tree *t, const ray *r, int skip, real tmax, hit *h)
{
	int found;
	(void)traverse(s, t, r, skip, tmax, h, 0, &found);
	return found;
}

real bvh_transmittance(const scene *s, const bvh_tree *t, const ray *r, int skip, real tmax,
		       int *blocker)
{
	return traverse(s, t, r, skip, tmax, NULL, 1, blocker);
}

