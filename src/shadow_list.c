/* shadow_list.c - the objects a shadow ray from a transmitting solid towards a light can
 * cross, listed once (shadow_list.h), and the light such a ray passes through its list.
 * See LICENSE for copyright and licence. */
#include "shadow_list.h"

#include "intersect.h"

#if SHADOW_LISTS

/* How far a list's two boxes and every box tested against their hull are grown, in units
 * of the sizes involved (|lo|1 + |hi|1 + |light|1): many times the roundings of the hull
 * test below and of a ray's computed end. */
#define SHADOW_SLACK (REAL_C(4096.0) * REAL_EPSILON)

/* Narrows [*low, *high] to the s with start + s slope <= bound; 0 when no s has it. A NaN
 * quotient narrows nothing (the corners compared are finite, so none arises). */
static int bound_s(real start, real slope, real bound, real *low, real *high)
{
	if (slope > REAL_C(0.0))
		*high = real_min(*high, (bound - start) / slope);
	else if (slope < REAL_C(0.0))
		*low = real_max(*low, (bound - start) / slope);
	else
		return !(start > bound);
	return 1;
}

/* Whether the hull of the boxes a = [a[0], a[1]] and c meets the box x. The hull is the
 * union of the boxes (1 - s) a + s c over s in [0, 1] (a convex set's hull with another
 * is); on each axis such a box meets x where (1 - s) a0 + s c0 <= x1 and (1 - s) a1 + s c1
 * >= x0, each a bound on s, so x is met for an interval of s, which must hold one. */
static int hull_meets(const vec3 a[2], const vec3 c[2], const vec3 x[2])
{
	real low = REAL_C(0.0), high = REAL_C(1.0);
	int axis;
	for (axis = 0; axis < 3; axis++) {
		real a0 = vec_get(a[0], axis), a1 = vec_get(a[1], axis);
		if (!bound_s(a0, vec_get(c[0], axis) - a0, vec_get(x[1], axis), &low, &high) ||
		    !bound_s(-a1, a1 - vec_get(c[1], axis), -vec_get(x[0], axis), &low, &high))
			return 0;
	}
	return !(low > high);
}

/* A list's hull, and how far the boxes tested against it are grown. */
typedef struct {
	vec3 from[2], to[2];
	real grow;
} shaft;

/* Whether the box [lo, hi], grown by the shaft's slack, meets its hull: first whether it
 * meets the box round both ends (six comparisons). */
static int meets_shaft(const void *region, bvh_point lo, bvh_point hi)
{
	const shaft *h = (const shaft *)region;
	vec3 g = vec_make(h->grow, h->grow, h->grow), x[2];
	x[0] = vec_sub(bvh_point_vec(lo), g);
	x[1] = vec_add(bvh_point_vec(hi), g);
	if (x[1].x < real_min(h->from[0].x, h->to[0].x) ||
	    x[0].x > real_max(h->from[1].x, h->to[1].x) ||
	    x[1].y < real_min(h->from[0].y, h->to[0].y) ||
	    x[0].y > real_max(h->from[1].y, h->to[1].y) ||
	    x[1].z < real_min(h->from[0].z, h->to[0].z) ||
	    x[0].z > real_max(h->from[1].z, h->to[1].z))
		return 0;
	return hull_meets(h->from, h->to, x);
}

static real sum_abs(vec3 a)
{
	return real_fabs(a.x) + real_fabs(a.y) + real_fabs(a.z);
}

void shadow_list_make(shadow_list *l, const scene *s, const bvh_tree *t, vec3 lo, vec3 hi,
		      vec3 lamp_at)
{
	vec3 extent = vec_sub(hi, lo), g;
	real size = sum_abs(lo) + sum_abs(hi) + sum_abs(lamp_at), reach;
	shaft h;
	h.grow = SHADOW_SLACK * size;
	/* Both ends grown by 1/1024 of the object's size, or four offsets at the sizes
	 * involved if more: a shadow ray leaves its hit point, and ends as far from the light,
	 * by one offset (trace.c's, REAL_OFFSET of the point's size or its ray's length). */
	reach = h.grow + real_max(real_max(extent.x, real_max(extent.y, extent.z)) / 1024,
				  REAL_C(4.0) * REAL_OFFSET * size);
	l->count = -1;
	if (!(reach < REAL_MAX / 8))
		return;
	g = vec_make(reach, reach, reach);
	l->from_lo = h.from[0] = vec_sub(lo, g);
	l->from_hi = h.from[1] = vec_add(hi, g);
	l->to_lo = h.to[0] = vec_sub(lamp_at, g);
	l->to_hi = h.to[1] = vec_add(lamp_at, g);
	if (!bvh_objects_meeting(s, t, meets_shaft, &h, -1, l->objects, SHADOW_LIST_MAX,
				 SHADOW_LIST_LANES, &l->count))
		l->count = -1;
}

static int holds(vec3 lo, vec3 hi, vec3 p)
{
	return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y && p.z >= lo.z &&
	       p.z <= hi.z;
}

/* Why the list's answer is the tree's: the ray starts in the list's first box (checked
 * exactly), and its exact end, origin + tmax dir, lies in the second (its computed end
 * is checked to lie inside it by more than that sum's rounding), so the segment between
 * lies in the two boxes' hull. An object the ray crosses on it is crossed in its own box
 * as the tree pads it (the tree's own guarantee, which polyhedra do not keep, and scenes
 * with them have no lists), which then meets the hull, and the object is listed. Each
 * listed object is asked as the tree's search asks it (bvh_traverse.h's VISIT_SHADOW) and
 * the product taken in the objects' order: the same light. */
int shadow_list_pass(const shadow_list *l, const scene *s, const ray *r, real tmax, int skip,
		     real *pass, int *blocker)
{
	int i, crossed[SHADOW_LIST_MAX], n = 0;
	vec3 end, margin;
	real round;
	if (l->count < 0 || !holds(l->from_lo, l->from_hi, r->origin))
		return 0;
	end = dir_madd(r->origin, tmax, r->dir);
	round = REAL_C(16.0) * REAL_EPSILON * (sum_abs(r->origin) + real_fabs(tmax) + sum_abs(end));
	margin = vec_make(round, round, round);
	if (!holds(vec_add(l->to_lo, margin), vec_sub(l->to_hi, margin), end))
		return 0;
	*blocker = -1;
	for (i = 0; i < l->count; i++) {
		int o = l->objects[i];
		real kt;
		if (o == skip || !object_intersect(s, o, r, REAL_C(0.0), tmax, NULL))
			continue;
		kt = s->materials[s->objects[o].material].kt;
		if (kt <= REAL_C(0.0)) {
			*blocker = o;
			*pass = REAL_C(0.0);
			return 1;
		}
		crossed[n++] = o;
	}
	*pass = bvh_pass_in_order(s, crossed, n);
	return 1;
}

void shadow_lists_build(shadow_lists *sl, const scene *s, const bvh_tree *t,
			const inside_lists *inside)
{
	int k, i;
	sl->list_count = 0;
	if (!t->node_count || t->unbounded_count > 0)
		return;
	for (k = 0; k < inside->list_count && (k + 1) * s->light_count <= SHADOW_LIST_PAIRS; k++) {
		const inside_list *solid = &inside->lists[k];
		for (i = 0; i < s->light_count; i++)
			shadow_list_make(&sl->lists[k * s->light_count + i], s, t,
					 bvh_point_vec(solid->lo), bvh_point_vec(solid->hi),
					 s->lights[i].position);
		sl->list_count = (k + 1) * s->light_count;
	}
}

const shadow_list *shadow_lists_find(const shadow_lists *sl, const scene *s,
				     const inside_lists *inside, int from, int lamp)
{
	const shadow_list *l;
	int k = inside->list_of[from];
	/* As inside_nearest finds a solid's inside list: list_of is written only for solids
	 * with lists. */
	if (k < 1 || k > inside->list_count || inside->lists[k - 1].solid != from ||
	    k * s->light_count > sl->list_count)
		return NULL;
	l = &sl->lists[(k - 1) * s->light_count + lamp];
	return l->count >= 0 ? l : NULL;
}
#else
typedef int shadow_list_unused; /* ISO C wants something in a translation unit */
#endif
