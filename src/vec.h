/* vec.h - three-component vectors: vec3 for points and colours, dir3 for directions and
 * normals.
 * Small inline functions so each vector expression reads like its maths.
 * See LICENSE for copyright and licence. */
#ifndef RT_VEC_H
#define RT_VEC_H

#include "real.h"

typedef struct {
	real x, y, z;
} vec3;

static inline vec3 vec_make(real x, real y, real z)
{
	vec3 v;
	v.x = x;
	v.y = y;
	v.z = z;
	return v;
}

/* A unit vector (a direction, a normal), or a sum of two scaled ones: components of
 * type `unit`, Q2.30 in fixed point (real.h). */
typedef struct {
	unit x, y, z;
} dir3;

static inline dir3 dir_make(unit x, unit y, unit z)
{
	dir3 d;
	d.x = x;
	d.y = y;
	d.z = z;
	return d;
}

/* On the M0 (small flash) the larger operations are one out-of-line copy each, defined
 * in vec.c (which sets VEC_BODIES); elsewhere they are inline (RT_SHARED). */
RT_SHARED vec3 vec_add(vec3 a, vec3 b);
RT_SHARED vec3 vec_sub(vec3 a, vec3 b);
RT_SHARED vec3 vec_scale(vec3 a, real s);
RT_SHARED vec3 vec_mul(vec3 a, vec3 b);
RT_SHARED vec3 vec_madd(vec3 a, real s, vec3 b);
RT_SHARED vec3 vec_cross(vec3 a, vec3 b);
RT_SHARED real2 vec_dot2(vec3 a, vec3 b);
RT_SHARED real vec_length(vec3 a);
RT_SHARED vec3 vec_times_reciprocal(vec3 a, real_reciprocal r);
RT_SHARED real vec_max_abs(vec3 a);
RT_SHARED dir3 dir_times_reciprocal(vec3 a, real_reciprocal r);
RT_SHARED dir3 dir_normalize(vec3 a);
RT_SHARED vec3 dir_madd(vec3 a, real s, dir3 b);
RT_SHARED vec3 dir_scale(dir3 a, real s);
RT_SHARED dir3 dir_madd_unit(dir3 a, unit s, dir3 b);
RT_SHARED dir3 dir_cross(dir3 a, dir3 b);
RT_SHARED vec3 dir_to_vec(dir3 a);

static inline vec3 vec_neg(vec3 a) { return vec_make(-a.x, -a.y, -a.z); }
static inline real vec_dot(vec3 a, vec3 b)
{
	return real_dot3(a.x, a.y, a.z, b.x, b.y, b.z);
}
static inline dir3 dir_neg(dir3 a) { return dir_make(-a.x, -a.y, -a.z); }
/* The cosine between two unit vectors. */
static inline unit dir_dot(dir3 a, dir3 b)
{
	return unit_dot3(a.x, a.y, a.z, b.x, b.y, b.z);
}
/* A position's (or a length's) component along a unit vector. */
static inline real dir_dot_vec(dir3 d, vec3 v)
{
	return real_dot3_unit(d.x, d.y, d.z, v.x, v.y, v.z);
}
/* A dir3 scaled to unit length again (the camera's cross products): normalising does not
 * depend on the scale of the components, so fixed point's Q2.30 takes vec3's path. */
static inline dir3 dir_renormalize(dir3 a) { return dir_normalize(vec_make(a.x, a.y, a.z)); }
static inline real vec_get(vec3 a, int axis) { return axis == 0 ? a.x : axis == 1 ? a.y : a.z; }
static inline int vec_is_finite(vec3 a)
{
	return real_isfinite(a.x) && real_isfinite(a.y) && real_isfinite(a.z);
}

#if !RT_FLASH_SHORT || defined(VEC_BODIES)
/* Vector sums saturate in fixed point (real_add): a ray from far out on an infinite
 * plane may meet coordinates whose exact sum no longer fits, and wrapping would be
 * undefined behaviour. In floating point real_add is plain +. */
RT_SHARED vec3 vec_add(vec3 a, vec3 b)
{
	return vec_make(real_add(a.x, b.x), real_add(a.y, b.y), real_add(a.z, b.z));
}

/* a + (-b), the same sums as a - b component by component: one function body less on
 * the M0 (48 bytes of flash, for 0.6 % more instructions per pixel). */
RT_SHARED vec3 vec_sub(vec3 a, vec3 b)
{
	return vec_add(a, vec_neg(b));
}

RT_SHARED vec3 vec_scale(vec3 a, real s)
{
	return vec_make(real_mul(a.x, s), real_mul(a.y, s), real_mul(a.z, s));
}

/* Component-wise product: colour times colour. */
RT_SHARED vec3 vec_mul(vec3 a, vec3 b)
{
	return vec_make(real_mul(a.x, b.x), real_mul(a.y, b.y), real_mul(a.z, b.z));
}

/* a + s*b: a point moved along a direction, or a weighted colour sum. */
RT_SHARED vec3 vec_madd(vec3 a, real s, vec3 b)
{
	return vec_make(real_add(a.x, real_mul(s, b.x)), real_add(a.y, real_mul(s, b.y)),
			real_add(a.z, real_mul(s, b.z)));
}


RT_SHARED vec3 vec_cross(vec3 a, vec3 b)
{
	return vec_make(real_mul(a.y, b.z) - real_mul(a.z, b.y),
			real_mul(a.z, b.x) - real_mul(a.x, b.z),
			real_mul(a.x, b.y) - real_mul(a.y, b.x));
}

/* a . b as a real2: for positions, whose products need the wider type in fixed point. */
RT_SHARED real2 vec_dot2(vec3 a, vec3 b)
{
	return real2_dot3(a.x, a.y, a.z, b.x, b.y, b.z);
}

RT_SHARED real vec_length(vec3 a) { return real2_sqrt(vec_dot2(a, a)); }

/* a divided by the number whose reciprocal r is. */
RT_SHARED vec3 vec_times_reciprocal(vec3 a, real_reciprocal r)
{
	return vec_make(real_times_reciprocal(a.x, r), real_times_reciprocal(a.y, r),
			real_times_reciprocal(a.z, r));
}

/* a divided by the length whose reciprocal r is, as a unit vector. */
RT_SHARED dir3 dir_times_reciprocal(vec3 a, real_reciprocal r)
{
	real_reciprocal per = unit_reciprocal(r);
	return dir_make(real_times_reciprocal(a.x, per), real_times_reciprocal(a.y, per),
			real_times_reciprocal(a.z, per));
}

/* Unit vector along a; the zero vector stays zero (callers reject it first). Divided by
 * its exact length, not a rounded one: fixed point takes the reciprocal straight from
 * the squared length (real2_reciprocal_sqrt), floating point divides by the root. A
 * vector with no square (zero in fixed point, where unit and real are both int32_t; too
 * small to square in floating point, where they are one type) is kept as it is. */
RT_SHARED dir3 dir_normalize(vec3 a)
{
	real2 w = vec_dot2(a, a);
	return w > 0 ? dir_times_reciprocal(a, real2_reciprocal_sqrt(w)) : dir_make(a.x, a.y, a.z);
}

/* a + s*b: a point moved along a direction. */
RT_SHARED vec3 dir_madd(vec3 a, real s, dir3 b)
{
	return vec_make(real_add(a.x, real_mul_unit(s, b.x)), real_add(a.y, real_mul_unit(s, b.y)),
			real_add(a.z, real_mul_unit(s, b.z)));
}

/* s*a: a length along a direction, as a vector. */
RT_SHARED vec3 dir_scale(dir3 a, real s)
{
	return vec_make(real_mul_unit(s, a.x), real_mul_unit(s, a.y), real_mul_unit(s, a.z));
}

/* a + s*b for directions and a cosine: a reflection, a tangent. */
RT_SHARED dir3 dir_madd_unit(dir3 a, unit s, dir3 b)
{
	return dir_make(unit_add(a.x, unit_mul(s, b.x)), unit_add(a.y, unit_mul(s, b.y)),
			unit_add(a.z, unit_mul(s, b.z)));
}

RT_SHARED dir3 dir_cross(dir3 a, dir3 b)
{
	return dir_make(unit_mul(a.y, b.z) - unit_mul(a.z, b.y),
			unit_mul(a.z, b.x) - unit_mul(a.x, b.z),
			unit_mul(a.x, b.y) - unit_mul(a.y, b.x));
}

/* A unit vector as a vec3 of reals, where its precision matters little (bounds, the
 * blend of a patch's vertex normals). */
RT_SHARED vec3 dir_to_vec(dir3 a)
{
	return vec_make(unit_to_real(a.x), unit_to_real(a.y), unit_to_real(a.z));
}

/* Largest absolute component: the scale of a point's rounding error. */
RT_SHARED real vec_max_abs(vec3 a)
{
	return real_max(real_fabs(a.x), real_max(real_fabs(a.y), real_fabs(a.z)));
}
#endif

#endif
