/* sphere.c - ray/sphere intersection by the Hearn & Baker discriminant.
 * numerics.md section 1: r^2 - |f - (f.d)d|^2 avoids the cancellation of b^2 - 4ac for
 * small, distant or grazing spheres; the stable roots avoid it for huge ones.
 * See LICENSE for copyright and licence. */
#include "shape.h"

#include "naive.h"
#include "quadratic.h"

void sphere_init(sphere_shape *s, vec3 center, real radius)
{
	s->center = center;
	s->radius = radius;
	s->radius2 = real_mul2(radius, radius);
#if REAL_FIXED
	/* From r^2 (Newton, good to 2^-29), so that no division kernel is linked for it
	 * alone. */
	s->per_radius = real2_reciprocal_sqrt(s->radius2);
#else
	s->inverse_radius = REAL_C(1.0) / radius;
#endif
}

int sphere_bounds(const sphere_shape *s, vec3 *lo, vec3 *hi)
{
	real r = s->radius;
	vec3 extent = vec_make(r, r, r);
	*lo = vec_sub(s->center, extent);
	*hi = vec_add(s->center, extent);
	return 1;
}

real sphere_clearance(const sphere_shape *s, const vec3 *p)
{
	vec3 f = vec_sub(*p, s->center);
	return real_fabs(real2_sqrt(vec_dot2(f, f)) - s->radius);
}

void sphere_measure(const sphere_shape *s, real *extent, real *feature)
{
	scene_cover(extent, s->center, s->radius);
	*feature = real_min(*feature, s->radius);
}

int sphere_intersect(const object *o, const ray *r, real tmin, real tmax, hit *h)
{
	return sphere_intersect_from(o, r, NULL, tmin, tmax, h);
}

#if REAL_FIXED
/* The two clear-miss tests below (b > 0 outside, and the textbook discriminant), from
 * the integer parts of f and the top 16 bits of d (Q2.14), in 32-bit products: one
 * instruction each on a small core, where the exact b is twelve. Most rays miss most
 * spheres, and this settles most of them before b, and c for rays from a hit point, are
 * computed: on the M0 it took scenes/mcu-demo.nff from 8,176 to 7,013 instructions per
 * pixel when it came.
 *
 * fx, fy, fz are floor(f) in units; c_floor is at most c, in units. With d = dh 2^-14 +
 * dl, dl in [0, 2^-14), and f = fh + fl, fl in [0, 1):
 *   |d.f - dh.fh 2^-14| = |dh.fl 2^-14 + dl.fh + dl.fl| < sqrt(3) + (|fh|1 + 3) 2^-14
 * for a unit d (|dh|1 <= sqrt(3) 2^14), which is below e = 3 + floor(|fh|1 2^-14) <= 9
 * (a bound from f's own size would settle more rays that pass far spheres closely, but
 * cost more on the M0 than it saved on scenes/mcu-demo.nff: 7,145 against 7,013). So b
 * (rounded by 2^-17 more) lies in (bq - e, bq + 1 + e), bq = floor(B 2^-14), B = dh.fh:
 * b > 0 when bq >= e, and |b| + 1 < bm = |bq| + e + 2. bm^2 < c (1 - 2^-10 - 2^-15)
 * then implies the clear miss's b^2 + |b| 2^-16 + 2^-15 < c (1 - 2^-10 - 2^-16). */
RT_INLINE int coarse_miss(int32_t fx, int32_t fy, int32_t fz, dir3 d, int32_t c_floor)
{
	/* Each product is below 2^30 in size; their sum below 2^31 for a unit d (sqrt(3)
	 * 2^29), and summed in unsigned arithmetic, so that a direction that is not unit
	 * (which the bound does not hold for either) cannot overflow it. */
	int32_t bq = (int32_t)((uint32_t)((d.x >> 16) * fx) + (uint32_t)((d.y >> 16) * fy) +
			       (uint32_t)((d.z >> 16) * fz)) >>
		     14;
	const int32_t e = 9; /* 3 + floor(|fh|1 2^-14) for any |fh| <= 2^15 */
	uint32_t bm, c = (uint32_t)c_floor;
	if (c_floor < 1)
		return 0; /* c > 0 is not certain */
	if (bq >= e)
		return 1;
	bm = (uint32_t)(bq < 0 ? -bq : bq) + (uint32_t)e + 2;
	/* bm < 2^16 keeps its square in 32 bits (it is below 1.8 2^15 for |f| < 2^15). */
	return bm < 65536 && bm * bm + 2 < c - (c >> 10) - (c >> 15);
}

/* Inlined at both of its uses in the sphere test (on the M0 a call and its frame would
 * cost half of what it saves); sphere_coarse_miss is the same, for the tests. */
RT_INLINE int coarse_miss_of(const sphere_shape *s, dir3 d, const vec3 *f, const real2 *c)
{
	int32_t fx = f->x >> 16, fy = f->y >> 16, fz = f->z >> 16, c_floor;
	if (c) {
		/* With c (eye rays, from their terms): its integer part. */
		if (*c < 0)
			return 0;
		c_floor = (int32_t)(*c >> 32);
	} else {
		/* Without: a lower bound of |f|^2 from the near end of each component's unit
		 * interval (fh for fh >= 0, -fh - 1 below), less an upper bound of r^2. */
		uint32_t gx = (uint32_t)(fx < 0 ? -(fx + 1) : fx),
			 gy = (uint32_t)(fy < 0 ? -(fy + 1) : fy),
			 gz = (uint32_t)(fz < 0 ? -(fz + 1) : fz);
		uint32_t f2 = gx * gx + gy * gy + gz * gz; /* each below 2^30: 32 bits hold it */
		uint32_t r2 = (uint32_t)(s->radius2 >> 32) + 1;
		if (f2 <= r2 || f2 - r2 >= 0x80000000u)
			return 0;
		c_floor = (int32_t)(f2 - r2);
	}
	return coarse_miss(fx, fy, fz, d, c_floor);
}

#else
/* Floating point has no coarse test: the careful one below decides every ray. */
RT_INLINE int coarse_miss_of(const sphere_shape *s, dir3 d, const vec3 *f, const real2 *c)
{
	(void)s;
	(void)d;
	(void)f;
	(void)c;
	return 0;
}
#endif

int sphere_coarse_miss(const sphere_shape *s, dir3 d, const vec3 *f, const real2 *c)
{
	return coarse_miss_of(s, d, f, c);
}

/* Floating point: does a ray that wants no hit record (a shadow ray), with a real
 * discriminant D, certainly meet the sphere between tmin <= 0 and tmax? Then the careful
 * path below would answer 1, and its square root and quotients are not needed (SPD
 * mount's shadow rays cross its glass spheres 280 k times, most from inside). The roots
 * are q / a and c / q, q = -(b + sqrt(D)) for b >= 0 and sqrt(D) - b below, rounded: |q|
 * is at least |b|, and at most 1.001 (|b| + |r|) (D is at most r^2 and a little, a near
 * 1). Below 2^20 that keeps every quotient of a normal number by q from rounding to 0,
 * in every floating type.
 * - From outside (c > 0) towards the centre (b < 0): both roots are positive, and the
 *   near one as computed is at most c / |b| rounded, below tmax when c is below tmax |b|
 *   less five roundings of it (`limit` takes off eight; it and its product are normal).
 * - From inside (c < 0) away from the centre (b > 0): the root ahead is c / q, at most
 *   |c| / b rounded, below tmax by the same rule.
 * - From inside towards the centre (b < 0): the root ahead is q / a, at most 1.003 (|r| +
 *   |b|), below tmax when twice that sum is.
 * Fixed point has no such path. */
RT_INLINE int crossing_certain(const sphere_shape *s, real b, real2 c, real tmin, real tmax)
{
#if REAL_FIXED
	(void)s;
	(void)b;
	(void)c;
	(void)tmin;
	(void)tmax;
	return 0;
#else
	real size = real_fabs(s->radius) + real_fabs(b), limit;
	if (!(tmin <= REAL_C(0.0) && size <= REAL_C(1048576.0)))
		return 0;
	if (c < 0 && b < REAL_C(0.0))
		return size * REAL_C(2.0) < tmax;
	if (!(c > 0 ? b < REAL_C(0.0) : c < 0 && b > REAL_C(0.0)) || !(real_fabs(c) >= REAL_MIN))
		return 0;
	limit = tmax * real_fabs(b) * (REAL_C(1.0) - REAL_C(8.0) * REAL_EPSILON);
	return limit >= REAL_MIN && limit < REAL_MAX && real_fabs(c) < limit;
#endif
}

int sphere_intersect_from(const object *o, const ray *r, const origin_term *k, real tmin,
			  real tmax, hit *h)
{
	const sphere_shape *s = &o->u.sphere;
	origin_term own;
	const vec3 *f;
	real2 c;
	real b, t0, t1, t;
	/* Without terms (rays from a hit point), f first: in fixed point most misses are
	 * known from it, before c is computed. */
	if (!k) {
		/* vec_sub, inline: most of these rays end at the coarse test two lines on. */
		own.f = vec_make(real_add(r->origin.x, -s->center.x), real_add(r->origin.y, -s->center.y),
				 real_add(r->origin.z, -s->center.z));
		if (coarse_miss_of(s, r->dir, &own.f, NULL))
			return 0;
		own.u.c = vec_dot2(own.f, own.f) - s->radius2;
		k = &own;
	}
	else if (coarse_miss_of(s, r->dir, &k->f, &k->u.c))
		return 0;
	/* f through the pointer, not copied: a copy of k's 8-byte aligned terms is a
	 * memcpy call on the M0. */
	f = &k->f;
	c = k->u.c;
	b = dir_dot_vec(r->dir, *f);
	/* Outside the sphere and moving away from its centre: both roots lie behind the
	 * origin (their product c/a > 0, their sum -2b/a < 0). Most rays miss most spheres,
	 * and this costs nothing. */
	if (c > 0 && b > REAL_C(0.0))
		return 0;
	if (RT_NAIVE == RT_NAIVE_SPHERE) {
		if (!naive_sphere_roots(b, c, &t0, &t1))
			return 0;
	} else {
		/* a = |d|^2 is 1 only up to rounding (in fixed point it is |d|^2 in Q2.30
		 * rounded to Q16.16, so mostly exactly 1): over a long ray a unit-length
		 * assumption would put the hit point off the surface, so the quadratic
		 * keeps its a. Perpendicular offset of the centre from the ray line (terms
		 * of size r^2, not |f|^2); b^2 - a c = a (r^2 - |v|^2), written as D + D
		 * (a - 1) to keep fixed point's low bits. */
		real a;
		vec3 v;
		/* A clear miss by the textbook discriminant b^2 - a c (cheap: no division,
		 * no root) is a miss: only rays that pass near the sphere take the careful
		 * path below. It is tested with a = 1: directions are unit up to rounding,
		 * so a >= 1 - 2^-10, and for c > 0 (outside; inside, b^2 - a c >= 0 is
		 * never a miss) b^2 - a c is then below b^2 - c + c 2^-10. Rays that miss
		 * need neither a nor its product. Fixed point made this test in 32-bit
		 * products already (sphere_coarse_miss), and leaves the few clear misses
		 * that escape it to the careful path: the same images, in less code and
		 * time than the exact test's 64-bit products. */
		if (!REAL_FIXED && c > 0 &&
		    real_mul2(b, b) - c < -(real2_error_bound(b, c) + real2_unit_slack(c)))
			return 0;
		a = unit_to_real(dir_dot(r->dir, r->dir));
		/* a = 1 exactly (often, in every type) divides by nothing and scales by nothing:
		 * the same numbers without the division and the product. */
		v = dir_madd(*f, a == REAL_C(1.0) ? -b : -real_div(b, a), r->dir);
		real2 perpendicular = s->radius2 - vec_dot2(v, v);
		real2 discriminant = perpendicular;
		if (a != REAL_C(1.0))
			discriminant += real2_scale(perpendicular, a - REAL_C(1.0));
		if (!REAL_FIXED && !h && discriminant >= 0 && !(o->flags & OBJ_INSIDE_ONLY) &&
		    crossing_certain(s, b, c, tmin, tmax))
			return 1;
		if (!REAL_FIXED && c < 0 && b < REAL_C(0.0) && a == REAL_C(1.0) &&
		    tmin >= REAL_C(0.0)) {
			/* From inside towards the centre (a ray traced inside glass from its
			 * surface, whenever its |d|^2 rounds to 1): the roots' product c < 0
			 * puts the near one, c / q, at or behind the origin, where the choice
			 * below never takes it, and with a = 1 the far one is q itself.
			 * solve_quadratic's numbers without its division. */
			if (!(discriminant >= 0))
				return 0;
			t0 = REAL_C(0.0);
			t1 = real_add(real2_sqrt(discriminant), -b);
		} else if (!solve_quadratic(a, b, c, discriminant, &t0, &t1)) {
			return 0;
		}
	}
	/* The near root enters, the far root leaves; an inside-only sphere shows only exits. */
	if (t0 > tmin && t0 < tmax && !(o->flags & OBJ_INSIDE_ONLY))
		t = t0;
	else if (t1 > tmin && t1 < tmax)
		t = t1;
	else
		return 0;
	if (h) {
		vec3 out;
		unit length2;
		h->t = t;
		h->point = dir_madd(r->origin, t, r->dir);
		out = vec_sub(h->point, s->center);
		/* (p - c) / r, kept where it is unit length to the type's rounding, else
		 * normalised: a hit point a little off the surface would give a normal that is
		 * not unit length, and the reflected ray with it (the sphere test assumes unit
		 * directions). Fixed point divides by r through its reciprocal (a product per
		 * component, where normalising takes a reciprocal square root too: on the M0
		 * half the work), and keeps that when it is unit to 2^-20: a ray reflected
		 * about it is then unit to Q16.16's step, which the sphere test's a = |d|^2 sees
		 * as 1. Floating types multiply by 1 / r and keep it unit to 16 epsilon (a hit
		 * point a few roundings of its own size off a sphere a tenth as large): the
		 * square root and the quotients of normalising lay between a glass sphere's hit
		 * and the next ray, SPD mount's 0.77 M of them. */
#if REAL_FIXED
		h->normal = dir_times_reciprocal(out, s->per_radius);
		length2 = dir_dot(h->normal, h->normal);
		if (length2 < UNIT_C(1.0) - 1024 || length2 > UNIT_C(1.0) + 1024)
			h->normal = dir_normalize(out);
#else
		h->normal = dir_make(out.x * s->inverse_radius, out.y * s->inverse_radius,
				     out.z * s->inverse_radius);
		length2 = dir_dot(h->normal, h->normal);
		if (!(real_fabs(length2 - REAL_C(1.0)) <= REAL_C(16.0) * REAL_EPSILON))
			h->normal = dir_normalize(out);
#endif
		h->shading = h->normal;
	}
	return 1;
}
