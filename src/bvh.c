/* bvh.c - searches the bounding volume hierarchy (built by bvh_build.c): front to back
 * with a fixed stack, shrinking the search as hits are found; shadow rays stop at the
 * first opaque blocker.
 * See LICENSE for copyright and licence. */
#include "bvh.h"

#include "intersect.h"

/* SSE (every x86-64, and x86 built for it) tests the wide tree's four boxes at once;
 * other targets take the plain C loop, with the same results. RT_NO_SIMD=1 forces it. */
#if BVH_WIDE && defined(__SSE__) && !RT_NO_SIMD
#include <xmmintrin.h>
#define WIDE_SSE 1
#else
#define WIDE_SSE 0
#endif

#define STACK_SIZE (BVH_MAX_DEPTH + 2)

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

#define BOX_SLACK (REAL_C(1.0) + REAL_C(16.0) * REAL_EPSILON)

/* Is the slab interval [tnear, tfar] open, allowing for the rounding of its ends? Each
 * end is off by a few roundings of itself: in floating point a few parts in 2^53
 * (double) of the distance, and BOX_SLACK widens the exit by more; in Q16.16 the
 * reciprocal 1/d (|d| <= 1) is off by half a step, 2^-17 of itself at most, and the
 * product by half a step more, so the exit is widened by 2^-15 of itself and two steps.
 * Without it a thin box far from the origin (a tile 0.1 wide at 10^30 in double, a tile
 * at 3,000 in Q16.16) seems to be left before it is entered, and its hit is lost. */
static inline int slab_interval_open(real tnear, real tfar)
{
	if (REAL_SATURATES)
		return tnear <= real_add(tfar, real_add(real_fabs(tfar) / 32768, REAL_EPSILON * 2));
	return tnear <= tfar * BOX_SLACK;
}
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
		real t0 = slab_distance(real_add(bvh_bound(n, near, axis), -o), d, 0);
		real t1 = slab_distance(real_add(bvh_bound(n, !near, axis), -o), d, 1);
		tnear = t0 > tnear ? t0 : tnear;
		tfar = t1 < tfar ? t1 : tfar;
	}
	*tenter = tnear;
	return slab_interval_open(tnear, tfar);
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
	x0 = real_mul(real_add((real)n->bounds[r->near_x].x, -r->origin.x), r->inv.x);
	x1 = real_mul(real_add((real)n->bounds[!r->near_x].x, -r->origin.x), r->inv.x);
	y0 = real_mul(real_add((real)n->bounds[r->near_y].y, -r->origin.y), r->inv.y);
	y1 = real_mul(real_add((real)n->bounds[!r->near_y].y, -r->origin.y), r->inv.y);
	z0 = real_mul(real_add((real)n->bounds[r->near_z].z, -r->origin.z), r->inv.z);
	z1 = real_mul(real_add((real)n->bounds[!r->near_z].z, -r->origin.z), r->inv.z);
	tnear = x0 > tnear ? x0 : tnear;
	tnear = y0 > tnear ? y0 : tnear;
	tnear = z0 > tnear ? z0 : tnear;
	tfar = x1 < tfar ? x1 : tfar;
	tfar = y1 < tfar ? y1 : tfar;
	tfar = z1 < tfar ? z1 : tfar;
	*tenter = tnear;
	return slab_interval_open(tnear, tfar);
}

#if BVH_WIDE
/* A ray prepared for the wide tree's float slab tests, made so that a computed entry is
 * never after the true one and a computed exit never before it (Ize, "Robust BVH ray
 * traversal", gives the same argument): per axis the origin rounded to float twice, each
 * way, and the near plane's distance taken from the copy that makes it smallest, the far
 * plane's from the one that makes it largest; what the float subtraction, product and
 * reciprocal round is relative to the distance, at most 4 2^-24, and the test allows
 * WIDE_SLACK for it. Rays with an origin beyond WIDE_LIMIT or a direction component
 * below 1 / WIDE_LIMIT (other than 0) are left to the binary tree: there the reciprocal
 * would not be a float, or a product could lose its relative accuracy. */
typedef struct {
	float near_from[3], far_from[3]; /* the origin, rounded for each plane */
	float inv[3];  /* 1 / d: +-infinity for a zero component, by its sign */
	int near[3];   /* the box row of the plane entered first: 2 axis + (d < 0) */
#if WIDE_SSE
	__m128 near_from4[3], far_from4[3], inv4[3]; /* the same, in each of four lanes */
#endif
} wide_ray;

#define WIDE_LIMIT REAL_C(1.2676506002282294e30) /* 2^100 */
#define WIDE_SLACK (1.0f + 1.0f / 1048576.0f)     /* 1 + 2^-20: covers 8 2^-24 */

static int wide_ray_make(wide_ray *w, const ray *r)
{
	int axis;
	for (axis = 0; axis < 3; axis++) {
		real o = vec_get(r->origin, axis);
		unit d = axis == 0 ? r->dir.x : axis == 1 ? r->dir.y : r->dir.z;
		float fd = (float)d, down, up;
		if (!(real_fabs(o) < WIDE_LIMIT) ||
		    (d != UNIT_C(0.0) && !(unit_fabs(d) > UNIT_C(1.0) / WIDE_LIMIT)))
			return 0;
		down = float_outward(o, 0);
		up = float_outward(o, 1);
		w->inv[axis] = 1.0f / fd; /* a zero keeps its sign: 1 / -0 is -infinity */
		w->near[axis] = 2 * axis + (w->inv[axis] < 0.0f);
		/* Entering through the lower plane the origin's upper copy gives the smaller
		 * distance, and the other way round. */
		w->near_from[axis] = w->inv[axis] < 0.0f ? down : up;
		w->far_from[axis] = w->inv[axis] < 0.0f ? up : down;
#if WIDE_SSE
		w->near_from4[axis] = _mm_set1_ps(w->near_from[axis]);
		w->far_from4[axis] = _mm_set1_ps(w->far_from[axis]);
		w->inv4[axis] = _mm_set1_ps(w->inv[axis]);
#endif
	}
	return 1;
}

/* tmax as a float, infinity beyond float's range: rounded to the nearest, which
 * WIDE_SLACK covers. */
static float wide_limit(real tmax)
{
	return tmax < (real)FLT_MAX ? (float)tmax : INFINITY;
}

/* Which of node n's boxes the ray enters before tmax: bit i for lane i, and enter[i]
 * where, never after the true entry. A NaN distance (0 times infinity: a ray lying in a
 * slab plane) fails its comparison and leaves the interval as it was. */
static inline int wide_hit(const bvh_wide_node *n, const wide_ray *r, float tmax,
			   float enter[WIDE_LANES])
{
#if WIDE_SSE
	/* The same operations, four lanes at once: max_ps(a, b) is a > b ? a : b, lane by
	 * lane, NaN included, so both paths give the same bits. */
	int group, mask = 0;
	for (group = 0; group < WIDE_LANES; group += 4) {
		__m128 tnear = _mm_setzero_ps(), tfar = _mm_set1_ps(tmax);
		int axis;
		for (axis = 0; axis < 3; axis++) {
			__m128 t0 = _mm_mul_ps(_mm_sub_ps(_mm_loadu_ps(&n->box[r->near[axis]][group]),
							  r->near_from4[axis]),
					       r->inv4[axis]);
			__m128 t1 = _mm_mul_ps(_mm_sub_ps(_mm_loadu_ps(&n->box[r->near[axis] ^ 1][group]),
							  r->far_from4[axis]),
					       r->inv4[axis]);
			tnear = _mm_max_ps(t0, tnear);
			tfar = _mm_min_ps(t1, tfar);
		}
		_mm_storeu_ps(&enter[group], tnear);
		mask |= _mm_movemask_ps(_mm_cmple_ps(
				tnear, _mm_add_ps(_mm_mul_ps(tfar, _mm_set1_ps(WIDE_SLACK)),
						  _mm_set1_ps(FLT_MIN))))
			<< group;
	}
	return mask;
#else
	int i, axis, mask = 0;
	for (i = 0; i < WIDE_LANES; i++) {
		float tnear = 0.0f, tfar = tmax;
		for (axis = 0; axis < 3; axis++) {
			float t0 = (n->box[r->near[axis]][i] - r->near_from[axis]) * r->inv[axis];
			float t1 = (n->box[r->near[axis] ^ 1][i] - r->far_from[axis]) * r->inv[axis];
			tnear = t0 > tnear ? t0 : tnear;
			tfar = t1 < tfar ? t1 : tfar;
		}
		enter[i] = tnear;
		/* FLT_MIN: below it a product is subnormal and its error absolute. */
		mask |= (tnear <= tfar * WIDE_SLACK + FLT_MIN) << i;
	}
	return mask;
#endif
}

/* The lowest lane set in a mask of eight (0 for none): one load, where a loop or two
 * lookups by halves cost balls 1-6 %. */
static const unsigned char lowest_lane[256] = {
	0, 0, 1, 0, 2, 0, 1, 0, 3, 0, 1, 0, 2, 0, 1, 0, 4, 0, 1, 0, 2, 0, 1, 0, 3, 0, 1, 0, 2, 0, 1, 0,
	5, 0, 1, 0, 2, 0, 1, 0, 3, 0, 1, 0, 2, 0, 1, 0, 4, 0, 1, 0, 2, 0, 1, 0, 3, 0, 1, 0, 2, 0, 1, 0,
	6, 0, 1, 0, 2, 0, 1, 0, 3, 0, 1, 0, 2, 0, 1, 0, 4, 0, 1, 0, 2, 0, 1, 0, 3, 0, 1, 0, 2, 0, 1, 0,
	5, 0, 1, 0, 2, 0, 1, 0, 3, 0, 1, 0, 2, 0, 1, 0, 4, 0, 1, 0, 2, 0, 1, 0, 3, 0, 1, 0, 2, 0, 1, 0,
	7, 0, 1, 0, 2, 0, 1, 0, 3, 0, 1, 0, 2, 0, 1, 0, 4, 0, 1, 0, 2, 0, 1, 0, 3, 0, 1, 0, 2, 0, 1, 0,
	5, 0, 1, 0, 2, 0, 1, 0, 3, 0, 1, 0, 2, 0, 1, 0, 4, 0, 1, 0, 2, 0, 1, 0, 3, 0, 1, 0, 2, 0, 1, 0,
	6, 0, 1, 0, 2, 0, 1, 0, 3, 0, 1, 0, 2, 0, 1, 0, 4, 0, 1, 0, 2, 0, 1, 0, 3, 0, 1, 0, 2, 0, 1, 0,
	5, 0, 1, 0, 2, 0, 1, 0, 3, 0, 1, 0, 2, 0, 1, 0, 4, 0, 1, 0, 2, 0, 1, 0, 3, 0, 1, 0, 2, 0, 1, 0,
};
RT_STATIC_ASSERT(lanes_fit_the_table, WIDE_LANES <= 8);
#endif

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
#if BVH_WIDE
	wide_ray wr;
#endif

	*found = shadow ? -1 : 0;
	/* Visits object `o` for a shadow ray: returns at an opaque blocker. */
#define VISIT_SHADOW(o)                                                                       \
	do {                                                                                  \
		int visit_ = (o);                                                             \
		if (visit_ != skip && object_intersect(s, visit_, r, REAL_C(0.0), tmax, NULL)) { \
			real kt_ = s->materials[s->objects[visit_].material].kt;            \
			if (kt_ <= REAL_C(0.0)) {                                             \
				*found = visit_;                                              \
				return REAL_C(0.0);                                           \
			}                                                                     \
			pass = real_mul(pass, kt_);                                           \
		}                                                                             \
	} while (0)
	/* Visits object `o` for a nearest-hit query: shrinks tmax to a nearer hit. */
#define VISIT_NEAREST(o)                                                                      \
	do {                                                                                  \
		int visit_ = (o);                                                             \
		if (visit_ == skip) /* the object the ray leaves and cannot meet again */     \
			break;                                                                \
		if (*found && visit_ < h->object) {                                           \
			/* A hit at the same distance as the nearest so far goes to the lower  \
			 * index, as in the search object by object: coincident surfaces      \
			 * then look the same whatever order the tree meets them in. */        \
			hit tie_;                                                             \
			if (object_intersect(s, visit_, r, REAL_C(0.0), real_step_up(tmax),   \
					     &tie_) &&                                        \
			    tie_.t <= tmax) {                                                 \
				*h = tie_;                                                    \
				tmax = h->t;                                                  \
				h->object = visit_;                                           \
			}                                                                     \
		} else if (object_intersect(s, visit_, r, REAL_C(0.0), tmax, h)) {           \
			tmax = h->t;                                                          \
			h->object = visit_;                                                   \
			*found = 1;                                                           \
		}                                                                             \
	} while (0)
#define VISIT(o)                                                                              \
	do {                                                                                  \
		if (shadow)                                                                   \
			VISIT_SHADOW(o);                                                      \
		else                                                                          \
			VISIT_NEAREST(o);                                                     \
	} while (0)

	for (i = 0; i < t->unbounded_count; i++)
		VISIT(t->index[i]);
#if BVH_WIDE
	if (t->node_count && wide_ray_make(&wr, r)) {
		/* Each node pushes at most all lanes but one (that one is searched at once). */
		struct {
			int child, count; /* a wide node (count 0) or a leaf's objects */
			float enter;
		} wide_stack[(WIDE_LANES - 1) * (BVH_MAX_DEPTH + 1) + 2];
		float limit = wide_limit(tmax);
		int current = -1; /* the wide node to search next; -1: take one from the stack */
		wide_stack[0].child = 0; /* the root */
		wide_stack[0].count = 0;
		wide_stack[0].enter = 0.0f;
		top = 1;
		for (;;) {
			const bvh_wide_node *node;
			float lane_enter[WIDE_LANES];
			int order[WIDE_LANES], k, mask, near;
			if (current < 0) {
				if (top == 0)
					break;
				top--;
				/* A nearer hit found since this entry was pushed may make it
				 * pointless; the entry may be computed a few roundings late (the
				 * box of a patch met at the very distance of the nearest hit). */
				if (!shadow && (real)wide_stack[top].enter > tmax * (real)WIDE_SLACK)
					continue;
				if (wide_stack[top].count == WIDE_ONE_OBJECT) {
					VISIT(wide_stack[top].child);
					if (!shadow)
						limit = wide_limit(tmax);
					continue;
				}
				if (wide_stack[top].count) {
					int first = wide_stack[top].child;
					int last = first + wide_stack[top].count;
					for (i = first; i < last; i++)
						VISIT(t->index[i]);
					if (!shadow)
						limit = wide_limit(tmax);
					continue;
				}
				current = wide_stack[top].child;
			}
			node = &t->wide[current];
			mask = wide_hit(node, &wr, limit, lane_enter);
			current = -1;
			if (!mask)
				continue;
			if (shadow) {
				/* Any blocker ends the search, so the lanes are taken as they
				 * come: leaves at once, one inner lane next, the rest later. */
				for (; mask; mask &= mask - 1) {
					int lane = lowest_lane[mask];
					int child = node->child[lane], count = node->count[lane];
					if (!count) {
						if (current >= 0) {
							wide_stack[top].child = current;
							wide_stack[top].count = 0;
							wide_stack[top++].enter = 0.0f;
						}
						current = child;
					} else if (count == WIDE_ONE_OBJECT) {
						VISIT_SHADOW(child);
					} else {
						for (i = child; i < child + count; i++)
							VISIT_SHADOW(t->index[i]);
					}
				}
				continue;
			}
			/* The lanes entered, farthest first: all but the nearest wait on the
			 * stack, the nearest is searched now. */
			for (k = 0; mask; mask &= mask - 1)
				order[k++] = lowest_lane[mask];
			for (i = 1; i < k; i++) {
				int lane = order[i], j;
				for (j = i; j > 0 && lane_enter[order[j - 1]] < lane_enter[lane]; j--)
					order[j] = order[j - 1];
				order[j] = lane;
			}
			for (i = 0; i < k - 1; i++) {
				wide_stack[top + i].child = node->child[order[i]];
				wide_stack[top + i].count = node->count[order[i]];
				wide_stack[top + i].enter = lane_enter[order[i]];
			}
			top += k - 1;
			near = order[k - 1];
			if (!node->count[near]) {
				current = node->child[near];
			} else if (node->count[near] == WIDE_ONE_OBJECT) {
				VISIT(node->child[near]);
				if (!shadow)
					limit = wide_limit(tmax);
			} else {
				int first = node->child[near], last = first + node->count[near];
				for (i = first; i < last; i++)
					VISIT(t->index[i]);
				if (!shadow)
					limit = wide_limit(tmax);
			}
		}
		return pass;
	}
#endif
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
		if (!shadow && stack[top].enter > (REAL_SATURATES ? tmax : tmax * BOX_SLACK))
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
#undef VISIT_NEAREST
#undef VISIT_SHADOW
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

