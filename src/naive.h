/* naive.h - the naive forms the literature warns about, kept to measure what robustness
 * costs (tools/speed-vs-error, docs/number-types.md). One switch chooses at most one of
 * them (RT_NAIVE in config.h, set by mk/variants.mk's algorithm builds); the robust code
 * asks `if (RT_NAIVE == RT_NAIVE_X)` of a constant, so every other build compiles the
 * naive form away. Nothing here is used by rt as shipped.
 * See LICENSE for copyright and licence. */
#ifndef RT_NAIVE_H
#define RT_NAIVE_H

#include "shape.h"

/* The textbook sphere roots t = -b -+ sqrt(b^2 - c) for a unit direction: b^2 - c cancels
 * for small, distant or grazing spheres, and -b +- sqrt cancels for huge ones
 * (numerics.md section 1). Returns 0 for a miss. */
static inline int naive_sphere_roots(real b, real2 c, real *t0, real *t1)
{
	real2 discriminant = real_mul2(b, b) - c;
	real root;
	if (!(discriminant >= 0))
		return 0;
	root = real2_sqrt(discriminant);
	*t0 = -b - root;
	*t1 = -b + root;
	return 1;
}

/* The per-face form, for comparison only: hit each face's plane, then keep the point if
 * it is strictly inside every other plane. Rays through edges and vertices leak, because
 * the point rounds to just outside a neighbouring plane (numerics.md section 3). */
static inline int naive_hedron_intersect(const scene *s, const object *o, const ray *r,
					  real tmin, real tmax, hit *h)
{
	const halfspace *planes = s->planes + o->u.hedron.first;
	int count = o->u.hedron.count, i, j, face = -1;
	real best = tmax;
	for (i = 0; i < count; i++) {
		unit vd = dir_dot(planes[i].normal, r->dir);
		real t;
		vec3 p;
		if (vd == UNIT_C(0.0))
			continue;
		t = real_div_unit(planes[i].offset - dir_dot_vec(planes[i].normal, r->origin), vd);
		if (!(t > tmin && t < best))
			continue;
		p = dir_madd(r->origin, t, r->dir);
		for (j = 0; j < count; j++)
			if (j != i && !(dir_dot_vec(planes[j].normal, p) - planes[j].offset < REAL_C(0.0)))
				break;
		if (j == count) {
			best = t;
			face = i;
		}
	}
	if (face < 0)
		return 0;
	if (h) {
		h->t = best;
		if (!(best < HORIZON_T))
			h->per_t = unit_over_real(UNIT_C(1.0), best);
		h->point = dir_madd(r->origin, best, r->dir);
		h->normal = planes[face].normal;
		h->shading = h->normal;
	}
	return 1;
}

/* The classic fixed epsilon by which secondary rays leave a surface: too small far from
 * the origin, too large for small objects (numerics.md section 2). */
static inline real naive_offset(void)
{
	return REAL_C(1e-4);
}

#endif
