/* cone.c - ray/uncapped cone or cylinder intersection (NFF c).
 * In the cone's frame a point p lies on the surface when its distance from the axis
 * equals r(h) = base_radius + slope * h, with h its height along the axis in [0, length].
 * See LICENSE for copyright and licence. */
#include "shape.h"

#include "quadratic.h"

#if RT_SHAPE_CONE

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

int cone_intersect(const object *o, const ray *r, real tmin, real tmax, hit *h)
{
	const cone_shape *c = &o->u.cone;
	vec3 f = vec_sub(r->origin, c->base);
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
		real t = roots[i], height;
		vec3 p, radial, gradient;
		dir3 normal;
		if (!(t > tmin && t < tmax))
			continue;
		height = real_add(oh, real_mul_unit(t, dh));
		/* The quadric is a double cone: keep the part between the two end circles. */
		if (height < REAL_C(0.0) || height > c->length)
			continue;
		p = dir_madd(r->origin, t, r->dir);
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
#else
/* ISO C wants something in every file. */
typedef int rt_cones_left_out;
#endif
