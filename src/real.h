/* real.h - the one place that chooses rt's number type `real`.
 * Everything numeric goes through the names defined here, so one source builds as
 * float, double (default), long double or Q16.16 fixed point (fixed.h). What the type
 * means for rt's policies is beside it: tolerance.h (offsets, the horizon, rounding
 * bounds, the range budget), realtext.h (numbers as text), scale.h (a scene's scale).
 * See LICENSE for copyright and licence. */
#ifndef RT_REAL_H
#define RT_REAL_H

/* Pick one with -DRT_REAL_FLOAT, -DRT_REAL_DOUBLE, -DRT_REAL_LONG_DOUBLE or
 * -DRT_REAL_FIXED. */
#if !defined(RT_REAL_FLOAT) && !defined(RT_REAL_DOUBLE) && !defined(RT_REAL_LONG_DOUBLE) && \
	!defined(RT_REAL_FIXED)
#define RT_REAL_DOUBLE
#endif

/* Smaller and larger of two numbers of any of the types below (a macro, for real, unit
 * and real2 alike). */
#define real_min(a, b) ((a) < (b) ? (a) : (b))
#define real_max(a, b) ((a) > (b) ? (a) : (b))

#include "flash.h" /* RT_APART, RT_INLINE, RT_SHARED */

#if defined(RT_REAL_FIXED)
#include "fixed.h"
#else
#include <float.h>
#include <math.h>
#include <stdlib.h>
#endif

/* Operations whose meaning changes with the type are named; + - < stay plain.
 * REAL_C wraps every literal so tables compile in every build. */
#if defined(RT_REAL_FLOAT)
typedef float real;
#define REAL_NAME "float"
#define REAL_C(x) ((float)(x))
#define REAL_MAX FLT_MAX
#define REAL_MIN FLT_MIN /* the least normal number */
#define REAL_EPSILON FLT_EPSILON /* 2^-23: the gap between 1 and the next value */
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
#define REAL_MIN DBL_MIN /* the least normal number */
#define REAL_EPSILON DBL_EPSILON
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
#define REAL_MIN LDBL_MIN /* the least normal number */
#define REAL_EPSILON LDBL_EPSILON
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
/* Numbers have a narrow range and saturate at its ends (reals near 32768, units at 2):
 * code that must stay within range asks this, not which type it is. */
#define REAL_SATURATES 1
#define REAL_FLOAT_FREE 1 /* no floating point at all: code that needs it is left out */
#define REAL_C(x) ((real)((x) * 65536.0 + ((x) < 0 ? -0.5 : 0.5)))
#define REAL_MAX ((real)0x7FFFFFFF)
#define REAL_EPSILON ((real)1) /* one step, 2^-16 */
#define real_step_up(x) fixed_add((x), 1) /* the next number above x */
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
#define real_ldexp(x, e) fixed_ldexp((x), (e))
/* n / d in 64 bits without the runtime library's division (the M0 has none to spare). */
#define wide_udiv(n, d) fixed_udiv64((n), (d))
#else
#error "rt: choose one of RT_REAL_FLOAT, RT_REAL_DOUBLE, RT_REAL_LONG_DOUBLE, RT_REAL_FIXED"
#endif

#if !defined(RT_REAL_FIXED)
typedef real real2; /* floating point needs no wider type for squares */
#define real_ldexp(x, e) real_ldexp_((x), (e))
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
#define REAL_SQUARES_UNDERFLOW 1 /* a number's square can round to 0 */
#define REAL_SATURATES 0 /* see the Q16.16 block */
#define REAL_FLOAT_FREE 0
/* At or a step or two above the next number above x >= 0 (x itself at 0). */
#define real_step_up(x) ((x) + (x) * REAL_EPSILON)
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
#define wide_udiv(n, d) ((n) / (d)) /* n / d of two uint64_t, d > 0 */
#endif

/* real2 is the type of squared lengths and products of two lengths (dot products of
 * positions, areas, quadratic coefficients): real_mul2(a, b) is a * b as a real2,
 * real2_dot3 is a dot product as a real2, real2_from widens, real2_sqrt gives back a real length, real2_div(w, b) is w / b as a
 * real, real2_ratio(a, b) is a / b as a real, real2_scale(w, a) is w * a for a unitless a. */

#endif
