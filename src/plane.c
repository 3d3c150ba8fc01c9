/* plane.c - ray/infinite plane intersection (an rt extension to NFF).
 * An infinite plane reaches the horizon, beyond the farthest distance a number type
 * holds comfortably (REAL_FAR: 1e15 in floating point, six scene extents in Q16.16): a
 * ray that meets it farther away meets it "at the horizon", at 0.99 REAL_FAR along the
 * ray. The point is then off the plane; the hit keeps the reciprocal of the true t, from
 * which the tracer lights the plane's true far point (its lights' directions scaled
 * down), and sends no rays from it (they would start beyond the range fixed point can
 * compute with). See LICENSE for copyright and licence. */
#include "shape.h"

void plane_init(plane_shape *pl, const vec3 *point, vec3 normal)
{
	pl->normal = dir_normalize(normal);
	pl->offset = dir_dot_vec(pl->normal, *point);
}

void plane_measure(const plane_shape *pl, real *extent)
{
	*extent = real_max(*extent, real_fabs(pl->offset));
}

real plane_gap(dir3 normal, real offset, const vec3 *origin)
{
	return real_add(offset, -dir_dot_vec(normal, *origin));
}

int plane_intersect_from(const object *o, const ray *r, const origin_term *k, real tmin,
			 real tmax, hit *h)
{
	const plane_shape *pl = &o->u.plane;
	unit denom = dir_dot(pl->normal, r->dir);
	real distance, t;
	if (denom == UNIT_C(0.0))
		return 0;
	distance = k ? k->u.distance : plane_gap(pl->normal, pl->offset, &r->origin);
	/* A plane behind the origin or through it (t <= 0) is no hit when tmin >= 0: known
	 * from the signs, without dividing (costly on small cores). */
	if (tmin >= REAL_C(0.0) && (distance > REAL_C(0.0)) != (denom > UNIT_C(0.0)))
		return 0;
	t = real_div_unit(distance, denom);
	if (t > HORIZON_T)
		t = HORIZON_T;
	if (!(t > tmin && t < tmax))
		return 0;
	if (h) {
		/* Where the true t is beyond the horizon its reciprocal still is a number: the
		 * tracer lights the plane's far point from it. */
		if (!(t < HORIZON_T))
			h->per_t = unit_over_real(denom, distance);
		h->t = t;
		h->point = dir_madd(r->origin, t, r->dir);
		h->normal = pl->normal;
		h->shading = pl->normal;
	}
	return 1;
}
