/* sphere.c - ray/sphere intersection by the Hearn & Baker discriminant.
 * numerics.md section 1: r^2 - |f - (f.d)d|^2 avoids the cancellation of b^2 - 4ac for
 * small, distant or grazing spheres; the stable roots avoid it for huge ones.
 * See LICENSE for copyright and licence. */
#include "shape.h"

int solve_quadratic(real a, real b, real2 c, real2 discriminant, real *t0, real *t1)
{
	real root, q;
	/* `!(x >= 0)` also rejects NaN (numerics.md N01). */
	if (!(discriminant >= 0))
		return 0;
	root = real2_sqrt(discriminant);
	q = b >= REAL_C(0.0) ? -real_add(b, root) : real_add(root, -b);
	/* q = 0 only when b = 0 and the discriminant is 0: a tangent at the origin (S19). */
	if (q == REAL_C(0.0)) {
		if (a == REAL_C(0.0))
			return 0;
		*t0 = *t1 = REAL_C(0.0);
		return 2;
	}
	*t0 = real2_div(c, q);
	/* a = 0 is the linear case (a ray parallel to a cylinder's axis): one root only;
	 * a = 1 (a unit direction, often exactly) needs no division. */
	*t1 = a == REAL_C(0.0) ? *t0 : a == REAL_C(1.0) ? q : real_div(q, a);
	if (*t1 < *t0) {
		real swap = *t0;
		*t0 = *t1;
		*t1 = swap;
	}
	return 2;
}

int sphere_intersect(const object *o, const ray *r, real tmin, real tmax, hit *h)
{
	origin_term k;
	k.f = vec_sub(r->origin, o->u.sphere.center);
	k.u.c = vec_dot2(k.f, k.f) - o->u.sphere.radius2;
	return sphere_intersect_from(o, r, &k, tmin, tmax, h);
}

void origin_term_init(const object *o, vec3 origin, origin_term *k)
{
	if (o->kind == SHAPE_SPHERE) {
		k->f = vec_sub(origin, o->u.sphere.center);
		k->u.c = vec_dot2(k->f, k->f) - o->u.sphere.radius2;
	} else if (o->kind == SHAPE_PLANE) {
		k->u.distance = o->u.plane.offset - dir_dot_vec(o->u.plane.normal, origin);
	}
}

int sphere_intersect_from(const object *o, const ray *r, const origin_term *k, real tmin,
			  real tmax, hit *h)
{
	const sphere_shape *s = &o->u.sphere;
	/* f through the pointer, not copied: a copy of k's 8-byte aligned terms is a
	 * memcpy call on the M0. */
	const vec3 *f = &k->f;
	real2 c = k->u.c;
	real b = dir_dot_vec(r->dir, *f), t0, t1, t;
	/* Outside the sphere and moving away from its centre: both roots lie behind the
	 * origin (their product c/a > 0, their sum -2b/a < 0). Most rays miss most spheres,
	 * and this costs nothing. */
	if (c > 0 && b > REAL_C(0.0))
		return 0;
#if RT_SPHERE_TEXTBOOK
	/* The textbook form, for comparison only: b^2 - c cancels for small, distant or
	 * grazing spheres, and -b +- sqrt cancels for huge ones (numerics.md section 1). */
	real2 discriminant = real_mul2(b, b) - c;
	real root;
	if (!(discriminant >= 0))
		return 0;
	root = real2_sqrt(discriminant);
	t0 = -b - root;
	t1 = -b + root;
#else
	/* a = |d|^2 is 1 only up to rounding (in fixed point it is |d|^2 in Q2.30 rounded to
	 * Q16.16, so mostly exactly 1): over a long ray a unit-length assumption would put
	 * the hit point off the surface, so the quadratic keeps its a. Perpendicular offset
	 * of the centre from the ray line (terms of size r^2, not |f|^2); b^2 - a c =
	 * a (r^2 - |v|^2), written as D + D (a - 1) to keep fixed point's low bits. */
	real a;
	vec3 v;
	/* A clear miss by the textbook discriminant b^2 - a c (cheap: no division, no root)
	 * is a miss: only rays that pass near the sphere take the careful path below. It
	 * is tested with a = 1: directions are unit up to rounding, so a >= 1 - 2^-10, and
	 * for c > 0 (outside; inside, b^2 - a c >= 0 is never a miss) b^2 - a c is then
	 * below b^2 - c + c 2^-10. Rays that miss need neither a nor its product. */
	if (c > 0 && real_mul2(b, b) - c < -(real2_error_bound(b, c) + real2_unit_slack(c)))
		return 0;
	a = unit_to_real(dir_dot(r->dir, r->dir));
	/* a = 1 exactly (often, in every type) divides by nothing and scales by nothing:
	 * the same numbers without the division and the product. */
	v = dir_madd(*f, a == REAL_C(1.0) ? -b : -real_div(b, a), r->dir);
	real2 perpendicular = s->radius2 - vec_dot2(v, v);
	real2 discriminant = perpendicular;
	if (a != REAL_C(1.0))
		discriminant += real2_scale(perpendicular, a - REAL_C(1.0));
	if (!solve_quadratic(a, b, c, discriminant, &t0, &t1))
		return 0;
#endif
	/* The near root enters, the far root leaves; an inside-only sphere shows only exits. */
	if (t0 > tmin && t0 < tmax && !(o->flags & OBJ_INSIDE_ONLY))
		t = t0;
	else if (t1 > tmin && t1 < tmax)
		t = t1;
	else
		return 0;
	if (h) {
		h->t = t;
		h->point = dir_madd(r->origin, t, r->dir);
		/* Normalised rather than divided by r: a hit point a little off the surface
		 * would otherwise give a normal that is not unit length, and the reflected ray
		 * with it (the sphere test assumes unit directions). */
		h->normal = dir_normalize(vec_sub(h->point, s->center));
		h->shading = h->normal;
	}
	return 1;
}
