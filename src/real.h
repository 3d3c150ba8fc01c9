/* real.h - the one place that chooses rt's number type `real`.
 * Everything numeric goes through the names defined here, so one source builds as
 * float, double (default) or long double. See LICENSE for copyright and licence. */
#ifndef RT_REAL_H
#define RT_REAL_H

#include <float.h>
#include <math.h>
#include <stdlib.h>

/* Pick one with -DRT_REAL_FLOAT, -DRT_REAL_DOUBLE or -DRT_REAL_LONG_DOUBLE. */
#if !defined(RT_REAL_FLOAT) && !defined(RT_REAL_DOUBLE) && !defined(RT_REAL_LONG_DOUBLE)
#define RT_REAL_DOUBLE
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
#define real_tan tanf
#define real_isfinite(x) isfinite(x)
#define real_parse(s, end) strtof((s), (end))
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
#define real_tan tan
#define real_isfinite(x) isfinite(x)
#define real_parse(s, end) strtod((s), (end))
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
#define real_tan tanl
#define real_isfinite(x) isfinite(x)
#define real_parse(s, end) strtold((s), (end))
#else
#error "rt: choose one of RT_REAL_FLOAT, RT_REAL_DOUBLE, RT_REAL_LONG_DOUBLE"
#endif

#define real_mul(a, b) ((a) * (b))
#define real_div(a, b) ((a) / (b))
#define real_from_int(i) ((real)(i))
#define real_to_double(x) ((double)(x))
#define real_min(a, b) ((a) < (b) ? (a) : (b))
#define real_max(a, b) ((a) > (b) ? (a) : (b))

/* Range budget (floating point): every number in a scene is at most REAL_INPUT_LIMIT in
 * magnitude, so squares and dot products of coordinates (1e24 at most) and the bounding
 * box arithmetic stay finite in every type. Double keeps hit points accurate to ~1e-10
 * relative; float is good to ~1e3 units from the origin (numerics.md section 1). */
#define REAL_INPUT_LIMIT REAL_C(1e12)

#endif
