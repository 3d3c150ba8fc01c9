/* fixed.h - Q16.16 fixed-point arithmetic for the RT_REAL_FIXED build of `real`.
 * Every product and quotient goes through 64 bits and rounds to nearest; results that
 * do not fit saturate instead of wrapping (signed overflow would be undefined). Right
 * shifts of negative numbers are arithmetic on every compiler rt supports.
 * See LICENSE for copyright and licence. */
#ifndef RT_FIXED_H
#define RT_FIXED_H

#include <stddef.h>
#include <stdint.h>

#define FIXED_ONE 65536      /* 1.0 */
#define FIXED_MAX INT32_MAX  /* largest value, about 32768.0 */

/* Clamps a 64-bit intermediate into the 32-bit range. */
static inline int32_t fixed_saturate(int64_t v)
{
	return v > INT32_MAX ? INT32_MAX : v < -INT32_MAX ? -INT32_MAX : (int32_t)v;
}

/* Divides with rounding to nearest (halves away from zero). */
static inline int64_t fixed_round_div(int64_t n, int64_t d)
{
	int64_t half = (d < 0 ? -d : d) / 2;
	return ((n < 0) == (d < 0) ? n + half : n - half) / d;
}

static inline int32_t fixed_mul(int32_t a, int32_t b)
{
	return fixed_saturate(((int64_t)a * b + 0x8000) >> 16);
}

/* A dot product summed in 64 bits and rounded once. */
static inline int32_t fixed_dot3(int32_t ax, int32_t ay, int32_t az, int32_t bx, int32_t by,
				 int32_t bz)
{
	return fixed_saturate(((int64_t)ax * bx + (int64_t)ay * by + (int64_t)az * bz + 0x8000) >>
			      16);
}

static inline int32_t fixed_div(int32_t a, int32_t b)
{
	if (b == 0)
		return a >= 0 ? FIXED_MAX : -FIXED_MAX;
	return fixed_saturate(fixed_round_div((int64_t)a * 65536, b));
}

static inline int32_t fixed_abs(int32_t a)
{
	return a < 0 ? (a == INT32_MIN ? INT32_MAX : -a) : a;
}

static inline int32_t fixed_from_int(long i)
{
	return i > 32767 ? FIXED_MAX : i < -32767 ? -FIXED_MAX : (int32_t)(i * 65536);
}

/* Q32.32 (a squared length) divided by Q16.16 gives Q16.16. */
static inline int32_t fixed_div2(int64_t w, int32_t b)
{
	if (b == 0)
		return w >= 0 ? FIXED_MAX : -FIXED_MAX;
	return fixed_saturate(fixed_round_div(w, b));
}

/* w (Q32.32) times a (Q16.16) as Q32.32, saturating. */
static inline int64_t fixed_scale2(int64_t w, int32_t a)
{
	int64_t high = w / 65536;
	if (a != 0 && (high > INT64_MAX / (a < 0 ? -(int64_t)a : a) ||
		       high < -INT64_MAX / (a < 0 ? -(int64_t)a : a)))
		return (high < 0) != (a < 0) ? -INT64_MAX : INT64_MAX;
	return high * a;
}

/* Rounded integer square root of a 64-bit number. */
uint64_t fixed_isqrt64(uint64_t x);

int32_t fixed_sqrt(int32_t a);      /* of Q16.16 */
int32_t fixed_sqrt2(int64_t w);     /* of Q32.32, as Q16.16 */
int32_t fixed_ratio2(int64_t a, int64_t b); /* a / b of two Q32.32, as Q16.16 */
int32_t fixed_exp(int32_t x);       /* e^x */
int32_t fixed_pow(int32_t x, int32_t y); /* x^y for 0 <= x <= 1, y >= 0 */
int32_t fixed_tan(int32_t x);       /* tan x for 0 <= x < pi/2 (radians) */

/* Reads a decimal number (sign, digits, point, exponent) as Q16.16 times 2^shift,
 * rounded; *end is set after the last character used (to s when there is no number).
 * *overflow is set when the value does not fit. */
int32_t fixed_parse(const char *s, const char **end, int shift, int *overflow);

/* A whole token as Q16.16 times 2^shift: 0 ok, 1 not a number, 2 out of range. */
int fixed_from_text(const char *text, int shift, int32_t *out);

/* x times 2^e, saturating. */
int32_t fixed_ldexp(int32_t x, int e);

/* The length scale 2^shift that brings a scene whose extent (largest coordinate) was
 * measured at 2^measured_shift into Q16.16's comfortable range (2048 to 4096). */
int fixed_length_shift(int32_t extent, int measured_shift);

/* Can a scene of this extent and smallest feature (both after scaling) be rendered?
 * 0 and *why when its dynamic range is too large for Q16.16. */
int fixed_can_represent(int32_t extent, int32_t feature, const char **why);

/* Writes x / 2^shift as a decimal with 6 fraction digits into buf (at least 24 bytes):
 * a scaled length in the scene's own units, which may be beyond Q16.16's range. */
void fixed_format(int32_t x, int shift, char *buf, size_t size);

#endif
