/* cone.c - ray/uncapped cone or cylinder intersection (NFF c).
 * In the cone's frame a point p lies on the surface when its distance from the axis
 * equals r(h) = base_radius + slope * h, with h its height along the axis in [0, length].
 * See LICENSE for copyright and licence. */
#include "shape.h"

#include "box.h"
#include "clearance.h"
#include "quadratic.h"


void cone_init(cone_shape *c, vec3 base, vec3 axis, real length, real base_radius,
	       real apex_radius)
{
	c->base = base;
	c->axis = dir_normalize(axis);
	c->length = length;
	c->base_radius = base_radius;
	c->apex_radius = apex_radius;
	c->slope = real_div(apex_radius - base_radius, length);
}

int cone_bounds(const cone_shape *c, vec3 *lo, vec3 *hi)
{
	/* Each end circle spans r * sqrt(1 - a_i^2) along axis i. */
	vec3 a = dir_to_vec(c->axis), apex = dir_madd(c->base, c->length, c->axis);
	vec3 disc = vec_make(real_sqrt(real_max(REAL_C(0.0), REAL_C(1.0) - real_mul(a.x, a.x))),
			     real_sqrt(real_max(REAL_C(0.0), REAL_C(1.0) - real_mul(a.y, a.y))),
			     real_sqrt(real_max(REAL_C(0.0), REAL_C(1.0) - real_mul(a.z, a.z))));
	box_empty(lo, hi);
	box_grow(lo, hi, vec_madd(c->base, c->base_radius, disc));
	box_grow(lo, hi, vec_madd(c->base, -c->base_radius, disc));
	box_grow(lo, hi, vec_madd(apex, c->apex_radius, disc));
	box_grow(lo, hi, vec_madd(apex, -c->apex_radius, disc));
	return 1;
}

/* In the cone's own coordinates (z along the axis, rho from it) its surface is the
 * segment from (0, r0) to (length, r1): no nearer than the slab 0 <= z <= length, the
 * ring between the two radii, and the segment's line. */
real cone_clearance(const cone_shape *g, const vec3 *p)
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
	return real_max(line, real_max(clearance_outside(z, REAL_C(0.0), g->length),
				       clearance_outside(rho, real_min(r0, r1), real_max(r0, r1))));
}

void cone_measure(const cone_shape *c, real *extent, real *feature)
{
	real r = real_max(c->base_radius, c->apex_radius);
	scene_cover(extent, c->base, r);
	scene_cover(extent, dir_madd(c->base, c->length, c->axis), r);
	*feature = real_min(*feature, r);
	/* A steep cone (radius changing much faster than its length) is as fine as its
	 * length over its slope. */
	*feature = real_min(*feature, real_div(c->length, real_max(REAL_C(1.0), real_fabs(c->slope))));
}

int cone_intersect(const object *o, const ray *r, real tmin, real tmax, hit *h)
{
	const cone_shape *c = &o->u.cone;
	/* The quadratic is set up from the point of the ray nearest the cone's base, not
	 * from its origin: from a distant eye the terms below are of the size of the
	 * distance squared, and the few that remain of the cone cancel away (as in the
	 * textbook sphere test; numerics.md section 1). From that point they are of the
	 * cone's own size; the roots are then distances from it. */
	real shift = dir_dot_vec(r->dir, vec_sub(c->base, r->origin));
	vec3 origin = dir_madd(r->origin, shift, r->dir);
	vec3 f = vec_sub(origin, c->base);
	real oh = dir_dot_vec(c->axis, f);
	unit dh = dir_dot(r->dir, c->axis);
	/* Components of origin and direction perpendicular to the axis. */
	vec3 fp = dir_madd(f, -oh, c->axis);
	dir3 dp = dir_madd_unit(r->dir, -dh, c->axis);
	/* Saturating sums (real_add): a steep cone seen from far away takes these past fixed
	 * point's range, where the test is meaningless anyway but must stay defined. */
	real radius_at_origin = real_add(c->base_radius, real_mul(c->slope, oh));
	real slope_dh = real_mul_unit(c->slope, dh);
	/* |fp + t dp|^2 = (radius_at_origin + slope dh t)^2, as a t^2 + 2 b t + cc = 0. */
	real a = real_add(unit_to_real(dir_dot(dp, dp)), -real_mul(slope_dh, slope_dh)); /* unitless */
	real b = real_add(dir_dot_vec(dp, fp), -real_mul(radius_at_origin, slope_dh));
	real2 cc = real2_sub(vec_dot2(fp, fp), real_mul2(radius_at_origin, radius_at_origin));
	real roots[2];
	int i;

	if (!solve_quadratic(a, b, cc, real2_sub(real_mul2(b, b), real2_scale(cc, a)), &roots[0],
			     &roots[1]))
		return 0;
	for (i = 0; i < 2; i++) {
		real t = real_add(shift, roots[i]), height;
		vec3 p, radial, gradient;
		dir3 normal;
		if (!(t > tmin && t < tmax))
			continue;
		height = real_add(oh, real_mul_unit(roots[i], dh));
		/* The quadric is a double cone: keep the part between the two end circles. */
		if (height < REAL_C(0.0) || height > c->length)
			continue;
		/* A shadow query needs no normal unless the cone shows only its inside. */
		if (!h && !(o->flags & OBJ_INSIDE_ONLY))
			return 1;
		/* From the nearer point too: o + t d from a distant eye keeps only the
		 * eye's precision. */
		p = dir_madd(origin, roots[i], r->dir);
		radial = dir_madd(vec_sub(p, c->base), -height, c->axis);
		/* Gradient of |radial|^2 - r(h)^2, halved: outward on the side wall. */
		gradient = dir_madd(radial,
				    -real_mul(real_add(c->base_radius, real_mul(c->slope, height)),
					      c->slope),
				    c->axis);
		normal = dir_normalize(gradient);
		/* At a pointed tip the radial part and the radius are both 0, so is the
		 * gradient: a ray along the axis, or across it through the tip, touches the
		 * cone only there. A touch is a hit (like a sphere's tangent); give it the axis
		 * out of the tip as its normal rather than the zero vector. */
		if (!(dir_dot(normal, normal) > 0))
			normal = c->slope < REAL_C(0.0) ? c->axis : dir_neg(c->axis);
		if ((o->flags & OBJ_INSIDE_ONLY) && dir_dot(normal, r->dir) < UNIT_C(0.0))
			continue;
		if (h) {
			h->t = t;
			h->point = p;
			h->normal = normal;
			h->shading = normal;
		}
		return 1;
	}
	return 0;
}
