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

real cone_scale(const cone_shape *c)
{
	/* Half the larger radius: the box spans at least 0.8 of it on some axis. */
	real ends = real_max(vec_max_abs(c->base), vec_max_abs(dir_madd(c->base, c->length, c->axis)));
	real radius = real_max(real_fabs(c->base_radius), real_fabs(c->apex_radius));
	return real_max(REAL_C(1.0), real_max(ends, radius / REAL_C(2.0)));
}

int cone_bounds(const cone_shape *c, vec3 *lo, vec3 *hi)
{
	return cone_piece_bounds(c, 0, 1, lo, hi);
}

/* The part of the side between two heights lies in the hull of its two end circles, and
 * its box is theirs. The heights are length * piece / pieces, the one between two pieces
 * the same number for both, so that no part of the side falls between them; the last
 * piece ends at the apex and its radius exactly, and one piece is the whole cone. */
int cone_piece_bounds(const cone_shape *c, int piece, int pieces, vec3 *lo, vec3 *hi)
{
	/* Each end circle spans r * sqrt(1 - a_i^2) along axis i. */
	vec3 a = dir_to_vec(c->axis);
	vec3 disc = vec_make(real_sqrt(real_max(REAL_C(0.0), REAL_C(1.0) - real_mul(a.x, a.x))),
			     real_sqrt(real_max(REAL_C(0.0), REAL_C(1.0) - real_mul(a.y, a.y))),
			     real_sqrt(real_max(REAL_C(0.0), REAL_C(1.0) - real_mul(a.z, a.z))));
	int end;
	box_empty(lo, hi);
	for (end = 0; end < 2; end++) {
		int k = piece + end;
		real height =
			real_div(real_mul(c->length, real_from_int(k)), real_from_int(pieces));
		vec3 centre = k == 0 ? c->base
			    : dir_madd(c->base, k == pieces ? c->length : height, c->axis);
		real radius = k == 0	  ? c->base_radius
			      : k == pieces ? c->apex_radius
					    : real_add(c->base_radius, real_mul(c->slope, height));
		box_grow(lo, hi, vec_madd(centre, radius, disc));
		box_grow(lo, hi, vec_madd(centre, -radius, disc));
	}
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

/* Floating types: does the ray's line pass the axis's line farther off than the side
 * ever lies (the larger radius)? Then it misses, and the quadratic need not be set up:
 * most rays that come near a long thin cone's box pass it so. The distance is
 * |to_base . n| / |n| with n = d x axis; the test is made in squares, without the root,
 * and allows for the rounding of to_base . n (a few ulps of |to_base| |n|) and of n (a
 * few ulps of 1), which the bound below covers while the ray is 7 degrees or more off
 * the axis (|n|^2 >= 1/64); rays nearer the axis's direction go the whole way. */
static int clear_of_axis(const cone_shape *c, const ray *r, vec3 to_base)
{
	vec3 n = vec_cross(dir_to_vec(r->dir), dir_to_vec(c->axis));
	real n2 = vec_dot(n, n), offset = vec_dot(to_base, n);
	real slack = real_fabs(to_base.x) + real_fabs(to_base.y) + real_fabs(to_base.z);
	real reach = real_max(real_fabs(c->base_radius), real_fabs(c->apex_radius));
	reach = real_add(reach, REAL_C(1024.0) * REAL_EPSILON * real_add(slack, reach));
	return n2 >= REAL_C(0.015625) && real_mul(offset, offset) > real_mul(real_mul(reach, reach), n2);
}

/* How far along the ray the quadratic is set up from (see cone_intersect). The ray's
 * point nearest the base keeps its terms of the size of the cone's extent (the ray, to
 * meet the cone, passes within it). That is a long cone's length, far more than its
 * radii: there, in the floating types, the point of the ray nearest the axis's point
 * nearest the ray's line (that point held to the cone's length) keeps them of the size
 * of the ray's distance from the axis and the radii, so that a long cone met far from
 * its base is found as accurately as a short one (numerics.md, "Cones and cylinders").
 * Only for a cone whose radius changes less than its length (|slope| <= 1): along a
 * steep one the radius at that point may be far larger than where the ray meets it. Any
 * point of the ray would do for the algebra. A ray along the axis (1 - dh^2 = 0) keeps
 * the base. */
static real start_of(const cone_shape *c, const ray *r, vec3 to_base, unit dh)
{
	real along = dir_dot_vec(r->dir, to_base), across, parallel, height;
	if (REAL_FLOAT_FREE || !(real_fabs(c->slope) <= REAL_C(1.0)))
		return along;
	across = real_add(-dir_dot_vec(c->axis, to_base), real_mul_unit(along, dh));
	parallel = REAL_C(1.0) - unit_to_real(real_mul_unit(dh, dh));
	if (!(across > REAL_C(0.0) && parallel > REAL_C(0.0)))
		return along;
	height = across >= real_mul(c->length, parallel) ? c->length : real_div(across, parallel);
	return real_add(along, real_mul_unit(height, dh));
}

/* Floating types: does the hit at `height` along the axis, `radial` its offset from it,
 * lie within half the padding the hierarchy gives the cone's boxes (the offset scale of
 * the cone's coordinates, box.h's box_rounding_pad) of the cone's side? The quadratic's
 * rounding can report a near miss as a hit; this bounds how near, so that a box of the
 * cone, or of a piece of its length, holds every hit the test reports, and the search
 * through the hierarchy finds what the search object by object finds. In the plane
 * through the axis the side is the segment from (0, r0) to (length, r1), and (height,
 * r(height)) is on it: a hit no farther out than that is near enough. A true hit may be
 * farther out where the cone is steep (the radius at a rounded height is far off), so the
 * other hits are measured from (height, |radial|) to the segment, which for a true hit
 * is a few ulps of the coordinates whatever the slope. */
static int near_side(const cone_shape *c, vec3 radial, real height)
{
	real reach = real_surface_offset(cone_scale(c), 1) / REAL_C(2.0);
	real r0 = real_fabs(c->base_radius), span = real_fabs(c->apex_radius) - r0;
	real radius = real_fabs(real_add(c->base_radius, real_mul(c->slope, height)));
	real radial2 = vec_dot(radial, radial), out, along, side2;
	if (radial2 <= real_mul(radius + reach, radius + reach))
		return 1;
	out = real_sqrt(radial2) - r0; /* from the base's rim */
	along = height * c->length + out * span;
	side2 = c->length * c->length + span * span;
	if (along <= REAL_C(0.0))
		return height * height + out * out <= reach * reach;
	if (along >= side2) {
		real up = height - c->length, beyond = out - span;
		return up * up + beyond * beyond <= reach * reach;
	}
	return real_fabs(height * span - out * c->length) <= reach * real_sqrt(side2);
}

int cone_intersect(const object *o, const ray *r, real tmin, real tmax, hit *h)
{
	const cone_shape *c = &o->u.cone;
	/* The quadratic is set up from a point of the ray near the cone, not from its origin:
	 * from a distant eye the terms below are of the size of the distance squared, and
	 * the few that remain of the cone cancel away (as in the textbook sphere test;
	 * numerics.md section 1). Fixed point, and the floating types on a steep cone
	 * (|slope| > 1), take the ray's point nearest the base; the floating types otherwise
	 * the one nearest the axis (start_of). The roots are then distances from that point. */
	vec3 to_base = vec_sub(c->base, r->origin), origin, f, fp;
	unit dh = dir_dot(r->dir, c->axis);
	real shift, oh, radius_at_origin, slope_dh, a, b;
	real2 cc;
	dir3 dp;
	real roots[2];
	int i;
	if (!REAL_FLOAT_FREE && clear_of_axis(c, r, to_base))
		return 0;
	shift = start_of(c, r, to_base, dh);
	origin = dir_madd(r->origin, shift, r->dir);
	f = vec_sub(origin, c->base);
	oh = dir_dot_vec(c->axis, f);
	/* Components of origin and direction perpendicular to the axis. */
	fp = dir_madd(f, -oh, c->axis);
	dp = dir_madd_unit(r->dir, -dh, c->axis);
	/* Saturating sums (real_add): a steep cone seen from far away takes these past fixed
	 * point's range, where the test is meaningless anyway but must stay defined. */
	radius_at_origin = real_add(c->base_radius, real_mul(c->slope, oh));
	slope_dh = real_mul_unit(c->slope, dh);
	/* |fp + t dp|^2 = (radius_at_origin + slope dh t)^2, as a t^2 + 2 b t + cc = 0. */
	a = real_add(unit_to_real(dir_dot(dp, dp)), -real_mul(slope_dh, slope_dh)); /* unitless */
	b = real_add(dir_dot_vec(dp, fp), -real_mul(radius_at_origin, slope_dh));
	cc = real2_sub(vec_dot2(fp, fp), real_mul2(radius_at_origin, radius_at_origin));
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
		/* A shadow query needs no normal unless the cone shows only its inside (nor,
		 * in fixed point, the hit point). */
		if (REAL_FLOAT_FREE && !h && !(o->flags & OBJ_INSIDE_ONLY))
			return 1;
		/* From the nearer point too: o + t d from a distant eye keeps only the
		 * eye's precision. */
		p = dir_madd(origin, roots[i], r->dir);
		radial = dir_madd(vec_sub(p, c->base), -height, c->axis);
		if (!REAL_FLOAT_FREE) {
			if (!near_side(c, radial, height))
				continue;
			if (!h && !(o->flags & OBJ_INSIDE_ONLY))
				return 1;
		}
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
