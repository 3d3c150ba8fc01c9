/* real.h - the one place that chooses rt's number type `real`.
 * Everything numeric goes through the names defined here, so one source builds as
 * float, double (default), long double or Q16.16 fixed point (fixed.c).
 * See LICENSE for copyright and licence. */
#ifndef RT_REAL_H
#define RT_REAL_H

/* Pick one with -DRT_REAL_FLOAT, -DRT_REAL_DOUBLE, -DRT_REAL_LONG_DOUBLE or
 * -DRT_REAL_FIXED. */
#if !defined(RT_REAL_FLOAT) && !defined(RT_REAL_DOUBLE) && !defined(RT_REAL_LONG_DOUBLE) && \
	!defined(RT_REAL_FIXED)
#define RT_REAL_DOUBLE
#endif

#define REAL_TEXT_OK 0
#define REAL_TEXT_NOT_A_NUMBER 1
#define REAL_TEXT_NOT_FINITE 2   /* NaN, infinity, or too large for any type */
#define REAL_TEXT_OUT_OF_RANGE 3 /* finite, but beyond what this build reads */
#define REAL_TEXT_TINY 4 /* not zero, but read as 0: too small for this build */

/* Smaller and larger of two numbers of any of the types below (a macro, for real, unit
 * and real2 alike). */
#define real_min(a, b) ((a) < (b) ? (a) : (b))
#define real_max(a, b) ((a) > (b) ? (a) : (b))

#if defined(RT_REAL_FIXED)
#include "fixed.h"
#else
#include <float.h>
#include <math.h>
#include <stdlib.h>
#endif

/* Operations whose meaning changes with the type are named; + - < stay plain.
 * REAL_C wraps every literal so tables compile in every build.
 * REAL_OFFSET is the relative size of the offset that moves a secondary ray's origin
 * off the surface (times max(1, |p|inf, t)): a few thousand ulps of the hit point,
 * well above the hit point's rounding error and well below any feature size. */
#if defined(RT_REAL_FLOAT)
typedef float real;
#define REAL_NAME "float"
#define REAL_C(x) ((float)(x))
#define REAL_MAX FLT_MAX
#define REAL_OFFSET REAL_C(6.103515625e-05) /* 2^-14 = 512 ulp */
#define real_sqrt sqrtf
#define real_fabs fabsf
#define real_pow powf
#define real_exp expf
#define real_tan_degrees(x) tanf((x) * REAL_C(0.017453292519943295))
#define real_isfinite(x) isfinite(x)
#define real_parse(s, end) strtof((s), (end))
/* a b >= c d, decided exactly: products of floats are exact in double. */
#define real_products_ge(a, b, c, d) ((double)(a) * (double)(b) >= (double)(c) * (double)(d))
#elif defined(RT_REAL_DOUBLE)
typedef double real;
#define REAL_NAME "double"
#define REAL_C(x) ((double)(x))
#define REAL_MAX DBL_MAX
#define REAL_OFFSET REAL_C(9.313225746154785e-10) /* 2^-30 = 2^22 ulp */
#define real_sqrt sqrt
#define real_fabs fabs
#define real_pow pow
#define real_exp exp
#define real_tan_degrees(x) tan((x) * REAL_C(0.017453292519943295))
#define real_isfinite(x) isfinite(x)
#define real_parse(s, end) strtod((s), (end))
#define real_fma fma
#elif defined(RT_REAL_LONG_DOUBLE)
typedef long double real;
#define REAL_NAME "long double"
#define REAL_C(x) ((long double)(x))
#define REAL_MAX LDBL_MAX
#define REAL_OFFSET REAL_C(9.094947017729282e-13) /* 2^-40 = 2^23 ulp */
#define real_sqrt sqrtl
#define real_fabs fabsl
#define real_pow powl
#define real_exp expl
#define real_tan_degrees(x) tanl((x) * 0.0174532925199432957692369L) /* pi / 180 */
#define real_isfinite(x) isfinite(x)
#define real_parse(s, end) strtold((s), (end))
#define real_fma fmal
#elif defined(RT_REAL_FIXED)
/* Q16.16 in an int32_t; every product and quotient goes through 64 bits (fixed.c). The
 * scene is scaled at load so that it fits (scene_scale in the parser). */
typedef int32_t real;
typedef int64_t real2; /* Q32.32: squares and products of lengths */
#define REAL_NAME "Q16.16 fixed point"
#define REAL_FIXED 1
#define REAL_SQUARES_UNDERFLOW 0 /* products are exact in 64 bits (real2) */
/* Small flash (the M0): vec.h's operations become single out-of-line copies (vec.c). */
#define REAL_OUTLINE FIXED_NARROW
#define REAL_C(x) ((real)((x) * 65536.0 + ((x) < 0 ? -0.5 : 0.5)))
#define REAL_MAX ((real)0x7FFFFFFF)
#define real_mul(a, b) fixed_mul((a), (b))
#define real_add(a, b) fixed_add((a), (b))
#define real_dot3(ax, ay, az, bx, by, bz) fixed_dot3((ax), (ay), (az), (bx), (by), (bz))
#define real_div(a, b) fixed_div((a), (b))
#define real_sqrt(a) fixed_sqrt(a)
#define real_fabs(a) fixed_abs(a)
#define real_pow(a, b) fixed_pow((a), (b))
#define real_exp(a) fixed_exp(a)
#define real_tan_degrees(a) fixed_tan_degrees(a)
#define real_isfinite(x) ((void)(x), 1)
#define real_from_int(i) fixed_from_int(i)
#define real_to_int(x) ((x) >> 16)
#define real_mul2(a, b) fixed_wide_mul((a), (b))
/* a b >= c d, decided exactly: 64-bit products. */
#define real_products_ge(a, b, c, d) (fixed_wide_mul((a), (b)) >= fixed_wide_mul((c), (d)))
/* u a - w b for units u, w and reals a, b, rounded once. */
#define real_cross_unit(u, a, w, b) fixed_dot3_30((u), -(w), 0, (a), (b), 0)
#define real2_dot3(ax, ay, az, bx, by, bz) fixed_dot3_wide((ax), (ay), (az), (bx), (by), (bz))
#define real2_from(a) ((real2)(a) * 65536)
#define real2_sqrt(w) fixed_sqrt2(w)
#define real2_div(w, b) fixed_div2((w), (b))
#define real2_ratio(a, b) fixed_ratio2((a), (b))
#define real2_scale(w, a) fixed_scale2((w), (a))
/* a - b of two real2, saturating (a cone seen from far out takes its terms there). */
#define real2_sub(a, b) fixed_sub2_sat((a), (b))
/* Dividing several numbers by one: a reciprocal, then a product each. */
typedef fixed_reciprocal real_reciprocal;
#define real_reciprocal_of(d) fixed_reciprocal_of(d)
#define real_times_reciprocal(x, r) fixed_times_reciprocal((x), (r))
/* Dividing by a length sqrt(w): the reciprocal straight from w (Newton, no root and no
 * division), and the length from it. */
#define real2_reciprocal_sqrt(w) fixed_reciprocal_sqrt2(w)
#define real2_sqrt_by(w, r) fixed_sqrt_by_reciprocal((w), (r))
/* How far b^2 - w can be off through rounding, for b a rounded dot product (half an LSB:
 * b^2 off by |b| in Q32.32) and w a real2 scaled by a near-one factor (real2_scale
 * truncates: off by |w| / 2^16), with room to spare: errors here are absolute. */
#define real2_error_bound(b, w) \
	((real2)fixed_abs(b) + (real2)(((w) < 0 ? 0u - (uint64_t)(w) : (uint64_t)(w)) >> 16) + \
	 (real2)131072)
/* How far w > 0 moves when scaled by the squared length of a unit direction (within
 * 2^-10 of 1, far more than rounding leaves it off): 2^-10 of w, a shift (w / 1024 for
 * w > 0, without a signed division's correction). */
#define real2_unit_slack(w) ((w) >> 10)
/* Unit-length quantities (direction and normal components, cosines) are Q2.30, 1.0 =
 * 2^30: a normalised direction is good to a few 2^-30, where Q16.16 kept 2^-17, and
 * a dot product with it no longer rounds to Q16.16's step. A product with a unit keeps
 * the other factor's format (one 64-bit product, rounded, shifted by 30); a product of a
 * unit and a real that is itself unit-sized (eta times a tangent) is Q16.16's own
 * product (shifted by 16). Range: [-2, 2), which unit vectors and their sums of two
 * keep; sums that could pass it saturate (unit_add). */
typedef int32_t unit;
#define UNIT_C(x) ((unit)((x) * 1073741824.0 + ((x) < 0 ? -0.5 : 0.5)))
#define unit_mul(a, b) fixed_mul30((a), (b))
#define unit_add(a, b) fixed_add((a), (b))
#define unit_scale(u, r) fixed_mul((u), (r))
#define real_mul_unit(r, u) fixed_mul30((r), (u))
#define real_div_unit(r, u) fixed_div30((r), (u))
#define unit_over_real(u, r) fixed_div((u), (r)) /* u / r as a unit: 2^16 u / r */
#define unit_dot3(ax, ay, az, bx, by, bz) fixed_dot3_30((ax), (ay), (az), (bx), (by), (bz))
#define real_dot3_unit(ux, uy, uz, rx, ry, rz) fixed_dot3_30((ux), (uy), (uz), (rx), (ry), (rz))
/* Rounded to Q16.16, halves upwards, in 32 bits. */
#define unit_to_real(u) ((((u) >> 13) + 1) >> 1)
#define unit_sqrt(u) fixed_sqrt30(u)
#define unit_fabs(u) fixed_abs(u)
/* d's reciprocal for quotients x / d that are units, |x| <= |d| (the components of a
 * vector over its length), through real_times_reciprocal. */
#define unit_reciprocal(r) fixed_unit_reciprocal(r)
/* Beyond any scaled scene's coordinates (4096): an infinite plane is seen out to six
 * times the scene's extent. Hit points out there are within range (4096 + 24000), and
 * the vector arithmetic from them saturates (real_add) rather than overflows. */
#define REAL_FAR REAL_C(24000.0)
/* Absolute precision: a hit point is good to a couple of LSB wherever it is. */
/* The offset grows with the ray's scale. Directions, normals and their dot products are
 * Q2.30 (unit, above), so a hit point is good to a few LSB plus about 2^-18 of the ray's
 * scale, and secondary rays leave it by 8 LSB + 2^-16 of the scale. The cone's quadratic
 * still rounds to Q16.16: a cone's hit (hit.rough) needs 16 LSB + 2^-13, which is also
 * the bound the BVH pads boxes by. Measured against the reference at 160x120 (pixels off
 * by more than 2 levels), the finer offset for all but cones: polyhedron.nff 0.031 % -> 0,
 * hard/cube-diagonal 0.062 % -> 0, glass.nff 0.130 -> 0.062 %, polygons.nff 0.026 ->
 * 0.005 %; 4 LSB + 2^-18 breaks glass.nff (19.7 %); the finer offset on cones too triples
 * the dark speckles on cones.nff (1,350 -> 4,093 of 65,536 at 256x256). */
#define real_surface_offset(scale, rough) \
	((rough) ? (real)16 + ((scale) >> 13) : (real)8 + ((scale) >> 16))
/* An eye or a light nearer a surface than 2^REAL_CLEARANCE_BITS steps may round onto it or
 * through it. */
#define REAL_CLEARANCE_BITS 2
#define REAL_CLEARANCE_MIN ((real)1 << REAL_CLEARANCE_BITS)
#define real_from_text(text, shift, out) fixed_from_text((text), (shift), (out))
#define REAL_RANGE_TEXT "the range of Q16.16 fixed point"
#define real_format(x, shift, buf, size) fixed_format((x), (shift), (buf), (size))
#define real_ldexp(x, e) fixed_ldexp((x), (e))
/* Pass 1 reads lengths at 2^-12 (up to 1.3e8 units) to find the scene's extent. */
#define REAL_FIRST_PASS_SHIFT (-12)
#define real_length_shift(extent, shift) fixed_length_shift((extent), (shift))
#define real_can_represent(extent, feature, why) fixed_can_represent((extent), (feature), (why))
#else
#error "rt: choose one of RT_REAL_FLOAT, RT_REAL_DOUBLE, RT_REAL_LONG_DOUBLE, RT_REAL_FIXED"
#endif

#if !defined(RT_REAL_FIXED)
typedef real real2; /* floating point needs no wider type for squares */
#define REAL_INPUT_LIMIT REAL_C(1e12)
#define REAL_FAR REAL_C(1e15) /* a length beyond any scene's coordinates */
#define real_ldexp(x, e) real_ldexp_((x), (e))
#define real_surface_offset(scale, rough) ((void)(rough), real_mul(REAL_OFFSET, (scale)))
/* Floating point places any point off a surface. */
#define REAL_CLEARANCE_BITS 0
#define REAL_CLEARANCE_MIN REAL_C(0.0)
/* Reading numbers: real_from_text converts a whole token, times 2^shift (the scene's
 * length scale, always 0 in floating point), and returns a REAL_TEXT_ status. */
static inline int real_from_text(const char *text, int shift, real *out)
{
	char *end;
	const char *c;
	(void)shift;
	/* NFF numbers are decimal: C's hexadecimal floats (0x1p3) are no number here, as
	 * in fixed point, so every build reads a scene alike. */
	for (c = text; *c; c++)
		if (*c == 'x' || *c == 'X')
			return REAL_TEXT_NOT_A_NUMBER;
	*out = real_parse(text, &end);
	if (end == text || *end != '\0')
		return REAL_TEXT_NOT_A_NUMBER;
	if (!real_isfinite(*out))
		return REAL_TEXT_NOT_FINITE;
	if (*out == REAL_C(0.0)) {
		/* Underflow: a digit 1 to 9 before any exponent. */
		for (c = text; *c && *c != 'e' && *c != 'E'; c++)
			if (*c >= '1' && *c <= '9')
				return REAL_TEXT_TINY;
	}
	return real_fabs(*out) <= REAL_INPUT_LIMIT ? REAL_TEXT_OK : REAL_TEXT_OUT_OF_RANGE;
}
#define REAL_RANGE_TEXT "+-1e12"
/* Writes x / 2^shift in decimal (shift is always 0 here). */
#define real_format(x, shift, buf, size) \
	((void)(shift), (void)snprintf((buf), (size), "%g", (double)(x)))
/* Floating point represents any scene within the input limit: no scaling (shift 0),
 * and nothing is refused for its dynamic range. */
#define REAL_FIRST_PASS_SHIFT 0
#define real_length_shift(extent, shift) ((void)(extent), (void)(shift), 0)
static inline int real_can_represent(real extent, real feature, const char **why)
{
	(void)extent;
	(void)feature;
	*why = 0;
	return 1;
}
#if defined(real_fma)
/* a b >= c d, decided exactly. Rounding is monotonic, so rounded products that differ
 * order the exact ones; when they are equal, the exact difference is that of the
 * products' rounding errors, which a fused multiply-add gives exactly (C99's fma). */
static inline int real_products_ge(real a, real b, real c, real d)
{
	real ab = a * b, cd = c * d;
	return ab != cd ? ab > cd : real_fma(a, b, -ab) >= real_fma(c, d, -cd);
}
#endif
static inline real real_ldexp_(real x, int e)
{
	return e ? x * real_pow(REAL_C(2.0), (real)e) : x;
}
/* Unit-length quantities are plain reals in floating point, and their operations the
 * plain ones: the images are those of a build without the distinction. */
typedef real unit;
#define UNIT_C(x) REAL_C(x)
#define unit_mul(a, b) ((a) * (b))
#define unit_add(a, b) ((a) + (b))
#define unit_scale(u, r) ((u) * (r))
#define real_mul_unit(r, u) ((r) * (u))
#define real_div_unit(r, u) ((r) / (u))
#define unit_over_real(u, r) ((u) / (r))
#define unit_dot3(ax, ay, az, bx, by, bz) real_dot3((ax), (ay), (az), (bx), (by), (bz))
#define real_dot3_unit(ux, uy, uz, rx, ry, rz) real_dot3((ux), (uy), (uz), (rx), (ry), (rz))
#define unit_to_real(u) (u)
#define unit_sqrt(u) real_sqrt(u)
#define unit_fabs(u) real_fabs(u)
#define unit_reciprocal(r) (r)
#define REAL_FIXED 0
#define REAL_OUTLINE 0
#define REAL_SQUARES_UNDERFLOW 1 /* a number's square can round to 0 */
#define real_mul(a, b) ((a) * (b))
#define real_add(a, b) ((a) + (b))
#define real_div(a, b) ((a) / (b))
#define real_dot3(ax, ay, az, bx, by, bz) ((ax) * (bx) + (ay) * (by) + (az) * (bz))
#define real_cross_unit(u, a, w, b) ((u) * (a) - (w) * (b))
#define real_from_int(i) ((real)(i))
#define real_to_int(x) ((int)(x))
#define real_mul2(a, b) ((a) * (b))
#define real2_dot3(ax, ay, az, bx, by, bz) ((ax) * (bx) + (ay) * (by) + (az) * (bz))
#define real2_from(a) (a)
#define real2_sqrt(w) real_sqrt(w)
#define real2_div(w, b) ((w) / (b))
#define real2_ratio(a, b) ((a) / (b))
#define real2_scale(w, a) ((w) * (a))
#define real2_sub(a, b) ((a) - (b))
/* Dividing several numbers by one: floating point keeps the divisor and divides each
 * (exactly rounded; a reciprocal would round twice). */
typedef real real_reciprocal;
#define real_reciprocal_of(d) (d)
#define real_times_reciprocal(x, r) real_div((x), (r))
/* Dividing by a length sqrt(w): the root is the divisor, and the length. */
#define real2_reciprocal_sqrt(w) real2_sqrt(w)
#define real2_sqrt_by(w, r) ((void)(w), (r))
/* How far b^2 - w can be off through rounding: relative errors, bounded generously. */
#define real2_error_bound(b, w) ((real_mul2((b), (b)) + real_fabs(w)) * REAL_OFFSET)
#define real2_unit_slack(w) ((w) * REAL_C(0.0009765625)) /* 2^-10 of w (see above) */
#endif
/* REAL_APART marks a function that stays a function of its own where flash is short
 * (REAL_OUTLINE: the M0), whatever the compiler would inline; each use says why. */
#if REAL_OUTLINE && defined(__GNUC__)
#define REAL_APART __attribute__((noinline))
#else
#define REAL_APART
#endif

/* real2 is the type of squared lengths and products of two lengths (dot products of
 * positions, areas, quadratic coefficients): real_mul2(a, b) is a * b as a real2,
 * real2_dot3 is a dot product as a real2, real2_from widens, real2_sqrt gives back a real length, real2_div(w, b) is w / b as a
 * real, real2_ratio(a, b) is a / b as a real, real2_scale(w, a) is w * a for a unitless a. */


/* Range budget (floating point): every number in a scene is at most 1e12 in magnitude,
 * so squares and dot products of coordinates (1e24 at most) and the bounding box
 * arithmetic stay finite in every type. Double keeps hit points accurate to ~1e-10
 * relative; float is good to ~1e3 units from the origin (numerics.md section 1).
 * Range budget (Q16.16): the parser scales the scene so that every coordinate is within
 * +-4096 (2^12); squares then reach 2^24 as real2 (Q32.32, up to 2^31), ray lengths
 * across the scene stay below 2^14, and features must stay at least 2^-4 after scaling
 * (their squares keep 8 bits), else the scene is refused. */

#endif
