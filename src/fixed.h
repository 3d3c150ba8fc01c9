/* fixed.h - Q16.16 fixed-point arithmetic for the RT_REAL_FIXED build of `real`.
 * Every product and quotient goes through 64 bits and rounds to nearest; results that
 * do not fit saturate instead of wrapping (signed overflow would be undefined). Right
 * shifts of negative numbers are arithmetic on every compiler rt supports.
 * See LICENSE for copyright and licence. */
#ifndef RT_FIXED_H
#define RT_FIXED_H

#include <stddef.h>
#include <stdint.h>

#include "flash.h"

#define FIXED_ONE 65536      /* 1.0 */
#define FIXED_MAX INT32_MAX  /* largest value, about 32768.0 */

/* Clamps a 64-bit intermediate into the 32-bit range. */
static inline int32_t fixed_saturate(int64_t v)
{
	return v > INT32_MAX ? INT32_MAX : v < -INT32_MAX ? -INT32_MAX : (int32_t)v;
}

/* A Cortex-M0 (ARMv6-M) multiplies only 32 x 32 -> 32 bits and cannot divide: there a
 * 64-bit product is a call to a general 64 x 64 routine (~40 instructions) and a 64-bit
 * quotient one to a general 64 / 64 routine (~500). The narrow forms below build the
 * same bits from 16 x 16 products and shift-and-subtract; tests/test_fixed.c checks both
 * forms agree on every build. Elsewhere the compiler's 64-bit arithmetic is used. */
#if defined(__ARM_ARCH_6M__)
#define FIXED_NARROW 1
#else
#define FIXED_NARROW 0
#endif

/* Where GCC builds for the M0, the narrow forms' primitives are Thumb-1 assembly
 * (fixed_m0.h, through fixed_narrow.h). */
#if FIXED_NARROW && defined(__GNUC__)
#define FIXED_ASM 1
#else
#define FIXED_ASM 0
#endif

/* a + b, saturating (fixed_narrow.h defines it, in Thumb-1 assembly on the M0). */
RT_INLINE int32_t fixed_add(int32_t a, int32_t b);

/* |a|, saturating (a few instructions: inline everywhere). */
static inline int32_t fixed_abs(int32_t a)
{
	return a < 0 ? (a == INT32_MIN ? INT32_MAX : -a) : a;
}

/* The kernels. On the M0 each is one out-of-line function, defined once in fixed.c
 * (which sets FIXED_KERNEL_BODIES): inlined copies in every file overflow its flash.
 * Elsewhere they are inline (RT_SHARED), and the 64-bit ones are the compiler's own
 * arithmetic. */
RT_SHARED int64_t fixed_wide_mul(int32_t a, int32_t b);     /* a b, exactly */
RT_SHARED uint32_t fixed_udiv(uint64_t n, uint32_t d);      /* n / d, or UINT32_MAX */
RT_SHARED uint64_t fixed_udiv64(uint64_t n, uint64_t d);    /* n / d; UINT64_MAX if d = 0 */
RT_SHARED int64_t fixed_div64(int64_t n, int64_t d);        /* n / d, truncated */
RT_SHARED int64_t fixed_round_div(int64_t n, int64_t d);    /* n / d, rounded */
RT_SHARED int32_t fixed_round_div_sat(int64_t n, int32_t d); /* rounded, saturated */
RT_SHARED int32_t fixed_mul(int32_t a, int32_t b);
RT_SHARED int32_t fixed_dot3(int32_t ax, int32_t ay, int32_t az, int32_t bx, int32_t by,
				int32_t bz);
RT_SHARED int64_t fixed_dot3_wide(int32_t ax, int32_t ay, int32_t az, int32_t bx,
				     int32_t by, int32_t bz); /* as 64 bits, exactly */
RT_SHARED int32_t fixed_div(int32_t a, int32_t b);
RT_SHARED int32_t fixed_from_int(long i);
RT_SHARED int32_t fixed_div2(int64_t w, int32_t b);
RT_SHARED int64_t fixed_scale2(int64_t w, int32_t a);
/* a - b, saturating to +-INT64_MAX instead of overflowing. */
static inline int64_t fixed_sub2_sat(int64_t a, int64_t b)
{
	if (b < 0 && a > INT64_MAX + b)
		return INT64_MAX;
	if (b > 0 && a < -INT64_MAX + b)
		return -INT64_MAX;
	return a - b;
}

/* For dividing several numbers by one d (a vector by its length): one division, then a
 * product per number, within an LSB of dividing each (scale keeps 31 bits, not the 16 of
 * a Q16.16 reciprocal). */
typedef struct {
	uint32_t scale; /* 2^(30 + bits of |d|) / |d|, in (2^30, 2^31]; 0 when d = 0 */
	int shift;      /* 14 + bits of |d| */
	int negative;   /* d < 0 */
} fixed_reciprocal;
RT_SHARED fixed_reciprocal fixed_reciprocal_of(int32_t d);
/* x / d: x times the reciprocal's scale over 2^shift, given as numbers (a struct is
 * kept in memory on the M0). */
RT_SHARED int32_t fixed_times_scale(int32_t x, uint32_t scale, int shift, int negative);
static inline int32_t fixed_times_reciprocal(int32_t x, fixed_reciprocal r)
{
	return fixed_times_scale(x, r.scale, r.shift, r.negative);
}

/* Q2.30 (unit-length quantities): a b / 2^30 and a dot product / 2^30, rounded and
 * saturated, keep the format of the factor that is not Q2.30 (Q2.30 when both are);
 * a / b for a Q16.16 over a Q2.30. */
RT_SHARED int32_t fixed_mul30(int32_t a, int32_t b);
RT_SHARED int32_t fixed_dot3_30(int32_t ax, int32_t ay, int32_t az, int32_t bx, int32_t by,
				   int32_t bz);
RT_SHARED int32_t fixed_div30(int32_t a, int32_t b);

/* The reciprocal whose quotients are Q2.30 units (for |x| <= |d|): its scale over
 * 2^(shift - 14), not 2^shift, 14 more fraction bits. Its shift is at least 15 (d is at
 * least one LSB), so at least 1 here. */
static inline fixed_reciprocal fixed_unit_reciprocal(fixed_reciprocal r)
{
	r.shift -= 14;
	return r;
}

/* The narrow forms: 64-bit products and quotients from 32-bit steps (the M0's kernels,
 * defined there, are made of them; every build has them, and the unit tests check them against the
 * wide forms). */
#include "fixed_narrow.h"

#if !FIXED_NARROW
/* Hosts and wide cores: the compiler's own 64-bit arithmetic, inline (RT_SHARED). The M0's
 * forms of these are in fixed_narrow.h. */
RT_SHARED int64_t fixed_wide_mul(int32_t a, int32_t b)
{
	return (int64_t)a * b;
}

RT_SHARED uint32_t fixed_udiv(uint64_t n, uint32_t d)
{
	uint64_t q = n / d;
	return q > UINT32_MAX ? UINT32_MAX : (uint32_t)q;
}

RT_SHARED uint64_t fixed_udiv64(uint64_t n, uint64_t d)
{
	return d ? n / d : UINT64_MAX;
}

RT_SHARED int32_t fixed_mul(int32_t a, int32_t b)
{
	return fixed_saturate(((int64_t)a * b + 0x8000) >> 16);
}

/* A dot product summed in 64 bits and rounded once. */
RT_SHARED int32_t fixed_dot3(int32_t ax, int32_t ay, int32_t az, int32_t bx, int32_t by,
				 int32_t bz)
{
	return fixed_saturate(((int64_t)ax * bx + (int64_t)ay * by + (int64_t)az * bz + 0x8000) >>
			      16);
}

RT_SHARED int64_t fixed_dot3_wide(int32_t ax, int32_t ay, int32_t az, int32_t bx,
				     int32_t by, int32_t bz)
{
	/* Summed modulo 2^64, as the M0's parts are: each product is below 2^62, and only a
	 * vector of three near-saturated components (far beyond any scene: a ray's sum that
	 * saturated) takes the sum past 2^63. That wraps, a defined conversion on every
	 * compiler rt builds with, where signed overflow would be undefined. */
	return (int64_t)((uint64_t)((int64_t)ax * bx) + (uint64_t)((int64_t)ay * by) +
			 (uint64_t)((int64_t)az * bz));
}

/* Rounded at bit 29 and saturated (as fixed_mul, at bit 30). */
RT_SHARED int32_t fixed_mul30(int32_t a, int32_t b)
{
	return fixed_saturate(((int64_t)a * b + ((int64_t)1 << 29)) >> 30);
}

RT_SHARED int32_t fixed_dot3_30(int32_t ax, int32_t ay, int32_t az, int32_t bx, int32_t by,
				   int32_t bz)
{
	return fixed_saturate(((int64_t)ax * bx + (int64_t)ay * by + (int64_t)az * bz +
			       ((int64_t)1 << 29)) >>
			      30);
}
#endif

#if !FIXED_NARROW || defined(FIXED_KERNEL_BODIES)
/* The same on every core, from the kernels above. */

/* n / d truncated towards zero, as C's `/` (d != 0), through the kernels above. */
RT_SHARED int64_t fixed_div64(int64_t n, int64_t d)
{
	uint64_t q = fixed_udiv64(n < 0 ? 0u - (uint64_t)n : (uint64_t)n,
				  d < 0 ? 0u - (uint64_t)d : (uint64_t)d);
	return (n < 0) != (d < 0) ? -(int64_t)q : (int64_t)q;
}

/* n / d rounded to nearest, halves away from zero (|n| + |d| / 2 must fit 63 bits). */
RT_SHARED int64_t fixed_round_div(int64_t n, int64_t d)
{
	int64_t half = (d < 0 ? -d : d) / 2;
	/* Away from zero: the half goes the way n points (the division truncates). */
	return fixed_div64(n < 0 ? n - half : n + half, d);
}

/* n / d rounded to nearest, halves away from zero, saturated to Q16.16's range. */
RT_SHARED int32_t fixed_round_div_sat(int64_t n, int32_t d)
{
	uint64_t magnitude = n < 0 ? 0u - (uint64_t)n : (uint64_t)n;
	uint32_t divisor = d < 0 ? 0u - (uint32_t)d : (uint32_t)d;
	uint32_t q;
	if (magnitude > UINT64_MAX - divisor / 2)
		q = UINT32_MAX;
	else
		q = fixed_udiv(magnitude + divisor / 2, divisor);
	if (q > (uint32_t)INT32_MAX)
		q = (uint32_t)INT32_MAX;
	return (n < 0) != (d < 0) ? -(int32_t)q : (int32_t)q;
}

RT_SHARED int32_t fixed_div(int32_t a, int32_t b)
{
	if (b == 0)
		return a >= 0 ? FIXED_MAX : -FIXED_MAX;
	return fixed_round_div_sat((int64_t)a * 65536, b);
}

RT_SHARED int32_t fixed_from_int(long i)
{
	return i > 32767 ? FIXED_MAX : i < -32767 ? -FIXED_MAX : (int32_t)(i * 65536);
}

/* Q32.32 (a squared length) divided by Q16.16 gives Q16.16. */
RT_SHARED int32_t fixed_div2(int64_t w, int32_t b)
{
	if (b == 0)
		return w >= 0 ? FIXED_MAX : -FIXED_MAX;
	return fixed_round_div_sat(w, b);
}

/* w (Q32.32) times a (Q16.16) as Q32.32, saturating when the product could pass 2^63
 * (a bit-length test: no 64-bit division). */
RT_SHARED int64_t fixed_scale2(int64_t w, int32_t a)
{
	/* |w / 65536| (truncated, as C divides) is |w| >> 16. */
	uint64_t mh = (w < 0 ? 0u - (uint64_t)w : (uint64_t)w) >> 16;
	uint32_t ma = a < 0 ? 0u - (uint32_t)a : (uint32_t)a;
	uint64_t product;
	if (ma == 0 || mh == 0)
		return 0;
	/* The usual factor is near one (a squared unit length): its 17 bits and the 46 of
	 * |high| cannot pass 2^63, and then no bit lengths are needed. */
	if ((ma >> 17 || mh >> 46) && fixed_bit_length(mh) + fixed_bit_length(ma) > 63)
		return (w < 0) != (a < 0) ? -INT64_MAX : INT64_MAX;
	/* |high| |a| < 2^63 here: split |high| into 32-bit halves, each times |a| exactly;
	 * the high half's product is below 2^31, so 32 bits hold it. */
	product = ((uint64_t)((uint32_t)(mh >> 32) * ma) << 32) + fixed_umul64((uint32_t)mh, ma);
	return (w < 0) != (a < 0) ? -(int64_t)product : (int64_t)product;
}

RT_SHARED fixed_reciprocal fixed_reciprocal_of(int32_t d)
{
	fixed_reciprocal r;
	uint32_t magnitude = d < 0 ? 0u - (uint32_t)d : (uint32_t)d;
	int bits = fixed_bit_length(magnitude);
	r.negative = d < 0;
	r.shift = 14 + bits;
	r.scale = magnitude ? fixed_udiv((uint64_t)1 << (30 + bits), magnitude) : 0;
	return r;
}

RT_SHARED int32_t fixed_times_scale(int32_t x, uint32_t scale, int shift, int negative)
{
	/* x 2^16 / d = x scale / 2^shift, rounded half away from zero: the product (below
	 * 2^62) in 32-bit halves, and the shift (1 to 46) on them, not on 64 bits. */
	uint32_t magnitude = x < 0 ? 0u - (uint32_t)x : (uint32_t)x, low, high, q;
	if (scale == 0) /* d = 0: as fixed_div */
		return x >= 0 ? FIXED_MAX : -FIXED_MAX;
	fixed_umul64_parts(magnitude, scale, &low, &high);
	if (shift > 32) {
		high += (uint32_t)1 << (shift - 33);
		q = high >> (shift - 32);
	} else {
		uint32_t half = (uint32_t)1 << (shift - 1);
		low += half;
		high += low < half;
		if (shift == 32)
			q = high;
		else
			q = (high >> shift) != 0 ? UINT32_MAX : (high << (32 - shift)) | (low >> shift);
	}
	if (q > (uint32_t)INT32_MAX)
		q = (uint32_t)INT32_MAX;
	return (x < 0) != negative ? -(int32_t)q : (int32_t)q;
}

RT_SHARED int32_t fixed_div30(int32_t a, int32_t b)
{
	if (b == 0)
		return a >= 0 ? FIXED_MAX : -FIXED_MAX;
	return fixed_round_div_sat((int64_t)a * ((int64_t)1 << 30), b);
}
#endif

/* Rounded integer square root of a 64-bit number. */
uint64_t fixed_isqrt64(uint64_t x);

int32_t fixed_sqrt(int32_t a);      /* of Q16.16 */
int32_t fixed_sqrt2(int64_t w);     /* of Q32.32, as Q16.16 */
int32_t fixed_sqrt30(int32_t u);    /* of Q2.30, as Q2.30 */
int32_t fixed_ratio2(int64_t a, int64_t b); /* a / b of two Q32.32, as Q16.16 */
/* For dividing by sqrt(w) (w Q32.32 > 0, a squared length): a reciprocal as from
 * fixed_reciprocal_of, good to 2^-29 of the root's exact value (not of a rounded one);
 * quotients saturate for w <= 0. fixed_sqrt_by_reciprocal gives sqrt(w) from it, within
 * an LSB plus 2^-29 of it (tests/test_fixed.c). */
fixed_reciprocal fixed_reciprocal_sqrt2(int64_t w);
int32_t fixed_sqrt_by_reciprocal(int64_t w, fixed_reciprocal r);
int32_t fixed_exp(int32_t x);       /* e^x */
int32_t fixed_pow(int32_t x, int32_t y); /* x^y for 0 <= x <= 1, y >= 0 */
int32_t fixed_tan_degrees(int32_t degrees); /* tan for 0 <= degrees < 90 */
/* sin and cos of degrees / 2 for 0 <= degrees < 180, in Q4.28: their quotient keeps a
 * narrow view's tangent to full precision, where Q16.16 keeps 4 bits at 0.0035 degrees. */
void fixed_sin_cos_half_angle(int32_t degrees, int32_t *sine, int32_t *cosine);

/* Reads a decimal number (sign, digits, point, exponent) as Q16.16 times 2^shift,
 * rounded; *end is set after the last character used (to s when there is no number).
 * *overflow is 1 when the value does not fit, -1 when a number that is not zero rounds
 * to 0, else 0. */
int32_t fixed_parse(const char *s, const char **end, int shift, int *overflow);

/* A whole token as Q16.16 times 2^shift: REAL_TEXT_OK, _NOT_A_NUMBER, _NOT_FINITE,
 * _OUT_OF_RANGE or _TINY (0 to 4, realtext.h). */
int fixed_from_text(const char *text, int shift, int32_t *out);

/* x times 2^e, saturating. */
int32_t fixed_ldexp(int32_t x, int e);

/* Writes x / 2^shift as a decimal with 6 fraction digits into buf (at least 24 bytes):
 * a scaled length in the scene's own units, which may be beyond Q16.16's range. */
void fixed_format(int32_t x, int shift, char *buf, size_t size);

#endif
