/* clearance.c - how far a point is from the nearest surface of the scene, from below.
 * Lights need it for their shadow segments (trace.c): a light nearer a surface than a
 * ray's offset gets segments that end exactly at it. Fixed point needs it to refuse an eye
 * or a light that its numbers cannot place off a surface (load.c).
 * Each bound is a distance the surface cannot be nearer than (to rounding): a plane's, a
 * box's, a slab's; never more than the true distance, often much less far away, where
 * it does not matter.
 * See LICENSE for copyright and licence. */
#include "clearance.h"

#include "shape.h"

/* How far x lies outside [low, high] (0 inside). Plain differences: every coordinate is
 * within the scene's extent, which the type holds twice over (parse.c). */
static real outside(real x, real low, real high)
{
	return real_max(REAL_C(0.0), real_max(low - x, x - high));
}

/* How far x lies outside the vertices' range along one axis. */
static real axis_gap(const vec3 *v, int count, int axis, real x)
{
	real low = vec_get(v[0], axis), high = low;
	int i;
	for (i = 1; i < count; i++) {
		real c = vec_get(v[i], axis);
		low = real_min(low, c);
		high = real_max(high, c);
	}
	return outside(x, low, high);
}

/* A polygon lies in its plane and in the box of its vertices. */
static real polygon_clearance(const scene *s, const polygon_shape *g, const vec3 *p)
{
	const vec3 *v = s->vertices + g->first;
	real most = real_fabs(plane_gap(g->normal, g->offset, p));
	int axis;
	for (axis = 0; axis < 3; axis++) {
		real gap = axis_gap(v, g->count, axis, vec_get(*p, axis));
		most = real_max(most, gap);
	}
	return most;
}

/* A convex polyhedron's surface is no nearer than its nearest plane from inside, and
 * than its farthest plane from outside: either way |max(n.p - d)|. */
static real hedron_clearance(const scene *s, const hedron_shape *g, const vec3 *p)
{
	const halfspace *planes = s->planes + g->first;
	real most = -REAL_MAX;
	int i;
	for (i = 0; i < g->count; i++) {
		real side = -plane_gap(planes[i].normal, planes[i].offset, p);
		most = real_max(most, side);
	}
	return real_fabs(most);
}

#if RT_SHAPE_CONE
/* In the cone's own coordinates (z along the axis, rho from it) its surface is the
 * segment from (0, r0) to (length, r1): no nearer than the slab 0 <= z <= length, the
 * ring between the two radii, and the segment's line. */
static real cone_clearance(const cone_shape *g, const vec3 *p)
{
	vec3 w = vec_sub(*p, g->base);
	real z = dir_dot_vec(g->axis, w);
	real2 rho2 = vec_dot2(w, w) - real_mul2(z, z);
	real rho = rho2 > 0 ? real2_sqrt(rho2) : REAL_C(0.0);
	/* Radii of one sign (parse.c); the slope of their sizes. */
	real r0 = real_fabs(g->base_radius), r1 = real_fabs(g->apex_radius);
	real slope = g->base_radius < REAL_C(0.0) ? -g->slope : g->slope;
	/* The line's distance is |rho - r0 - z slope| / sqrt(1 + slope^2), no less than that
	 * over 1 + |slope|. */
	real line = real_div(real_fabs(real_add(real_add(rho, -r0), -real_mul(z, slope))),
			     real_add(REAL_C(1.0), real_fabs(slope)));
	return real_max(line, real_max(outside(z, REAL_C(0.0), g->length),
				       outside(rho, real_min(r0, r1), real_max(r0, r1))));
}
#endif

real object_clearance(const scene *s, const object *o, const vec3 *p)
{
	switch (o->kind) {
	case SHAPE_SPHERE: {
		vec3 f = vec_sub(*p, o->u.sphere.center);
		return real_fabs(real2_sqrt(vec_dot2(f, f)) - o->u.sphere.radius);
	}
	case SHAPE_POLYGON:
	case SHAPE_PATCH:
		return polygon_clearance(s, &o->u.polygon, p);
#if RT_SHAPE_CONE
	case SHAPE_CONE:
		return cone_clearance(&o->u.cone, p);
#endif
	case SHAPE_HEDRON:
		return hedron_clearance(s, &o->u.hedron, p);
	case SHAPE_PLANE:
		return real_fabs(plane_gap(o->u.plane.normal, o->u.plane.offset, p));
	default:
		return REAL_MAX;
	}
}

real scene_clearance(const scene *s, const vec3 *p, int *nearest)
{
	real least = REAL_MAX;
	int i;
	*nearest = -1;
	for (i = 0; i < s->object_count; i++) {
		real c = object_clearance(s, &s->objects[i], p);
		if (c < least) {
			least = c;
			*nearest = i;
		}
	}
	return least;
}
