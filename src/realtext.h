/* realtext.h - numbers as text in the build's type: a scene's numbers read (at its
 * length scale) and numbers written back into messages.
 * See LICENSE for copyright and licence. */
#ifndef RT_REALTEXT_H
#define RT_REALTEXT_H

#include "real.h"

/* What real_from_text made of a token. */
#define REAL_TEXT_OK 0
#define REAL_TEXT_NOT_A_NUMBER 1
#define REAL_TEXT_NOT_FINITE 2   /* NaN, infinity, or too large for any type */
#define REAL_TEXT_OUT_OF_RANGE 3 /* finite, but beyond what this build reads */
#define REAL_TEXT_TINY 4 /* not zero, but read as 0: too small for this build */

#if REAL_FIXED
/* Q16.16 reads its own digits (fixed.c), times 2^shift, rounded once. */
#define real_from_text(text, shift, out) fixed_from_text((text), (shift), (out))
#define REAL_RANGE_TEXT "the range of Q16.16 fixed point"
#define real_format(x, shift, buf, size) fixed_format((x), (shift), (buf), (size))
#else
#include <stdint.h>
#include <stdio.h>

#include <float.h>

#define REAL_INPUT_LIMIT REAL_C(1e12) /* the largest magnitude a scene may write */

/* The short decimals scenes are made of, read without strtod (Clinger's fast path): a
 * whole number of at most REAL_EXACT_DIGITS digits and a power of ten up to
 * REAL_EXACT_POW10 are both exact in the type, so one product or quotient of them is
 * rounded once, correctly, to what strtod returns, bit for bit. Only where each operation
 * rounds to the type itself (FLT_EVAL_METHOD 0). 1 M spheres: strtod was a third of the
 * reading. */
#if defined(RT_REAL_FLOAT)
#define REAL_EXACT_DIGITS 7  /* below 2^24 */
#define REAL_EXACT_POW10 10  /* 5^10 < 2^24 */
#elif defined(RT_REAL_LONG_DOUBLE)
#define REAL_EXACT_DIGITS (LDBL_MANT_DIG >= 64 ? 19 : 15)
#define REAL_EXACT_POW10 (LDBL_MANT_DIG >= 64 ? 27 : 22)
#else
#define REAL_EXACT_DIGITS 15 /* below 2^53 */
#define REAL_EXACT_POW10 22  /* 5^22 < 2^53 */
#endif

/* A decimal as written: the value is whole / 10^scale, negated if negative; digits
 * counts the digits of whole as written (leading zeros too). */
typedef struct {
	uint64_t whole; /* below 10^19 < 2^64 when it is used (REAL_EXACT_DIGITS) */
	int digits, scale, negative;
} real_decimal;

/* Reads [+-]digits[.digits][e[+-]digits] (an exponent of at most three digits) from c
 * into *d, gathering the digits as a whole number in integer arithmetic. Returns the
 * first byte after it, or NULL where c does not start so. The caller checks that the
 * number ends there. */
static inline const char *real_decimal_scan(const char *c, real_decimal *d)
{
	uint64_t whole = 0;
	int digits, scale = 0, exponent = 0, exponent_negative = 0;
	const char *first;
	d->negative = *c == '-';
	c += *c == '-' || *c == '+';
	/* The digits counted from where they start and stop, not in the loop. */
	for (first = c; *c >= '0' && *c <= '9'; c++)
		whole = whole * 10u + (uint64_t)(*c - '0');
	digits = (int)(c - first);
	if (*c == '.') {
		for (first = ++c; *c >= '0' && *c <= '9'; c++)
			whole = whole * 10u + (uint64_t)(*c - '0');
		scale = (int)(c - first);
		digits += scale;
	}
	if (digits == 0)
		return NULL;
	if (*c == 'e' || *c == 'E') {
		int exponent_digits = 0;
		c++;
		exponent_negative = *c == '-';
		c += *c == '-' || *c == '+';
		for (; *c >= '0' && *c <= '9' && exponent_digits < 3; c++, exponent_digits++)
			exponent = exponent * 10 + (*c - '0');
		if (exponent_digits == 0)
			return NULL;
	}
	d->whole = whole;
	d->digits = digits;
	d->scale = scale - (exponent_negative ? -exponent : exponent);
	return c;
}

/* The short decimals scenes are made of, d read exactly into *out, or 0 when it is not
 * exact so (strtod then reads it): a whole number of at most REAL_EXACT_DIGITS digits and
 * a power of ten up to REAL_EXACT_POW10 are both exact in the type, and the power comes
 * from a table: the same exact operands as a product built digit by digit, in 0.76 of the
 * instructions (SPD teapot-s12's 167 k numbers). */
static inline int real_from_decimal(const real_decimal *d, real *out)
{
	/* 10^k, exact in double (and so in long double) up to 10^22; float reads only up
	 * to 10^10 (REAL_EXACT_POW10). */
	static const real exact_pow10[23] = {
		REAL_C(1e0),  REAL_C(1e1),  REAL_C(1e2),  REAL_C(1e3),  REAL_C(1e4),  REAL_C(1e5),
		REAL_C(1e6),  REAL_C(1e7),  REAL_C(1e8),  REAL_C(1e9),  REAL_C(1e10), REAL_C(1e11),
		REAL_C(1e12), REAL_C(1e13), REAL_C(1e14), REAL_C(1e15), REAL_C(1e16), REAL_C(1e17),
		REAL_C(1e18), REAL_C(1e19), REAL_C(1e20), REAL_C(1e21), REAL_C(1e22)};
	real mantissa, power;
	int size;
	if (FLT_EVAL_METHOD != 0 || d->digits > REAL_EXACT_DIGITS ||
	    d->scale > REAL_EXACT_POW10 || -d->scale > REAL_EXACT_POW10)
		return 0;
	size = d->scale < 0 ? -d->scale : d->scale;
	/* Long double's powers past 10^22: products of exact powers, each exact. */
	for (power = exact_pow10[size < 22 ? size : 22]; size > 22; size--)
		power *= REAL_C(10.0);
	mantissa = (real)d->whole;
	mantissa = d->scale < 0 ? mantissa * power : mantissa / power;
	*out = d->negative ? -mantissa : mantissa;
	return 1;
}

/* A whole token that is a short decimal (real_from_decimal), read exactly into *out; 0
 * otherwise. */
static inline int real_from_short_decimal(const char *c, real *out)
{
	real_decimal d;
	c = real_decimal_scan(c, &d);
	return c && *c == '\0' && real_from_decimal(&d, out);
}
/* Reading numbers: real_from_text converts a whole token, times 2^shift (the scene's
 * length scale, always 0 in floating point), and returns a REAL_TEXT_ status. */
static inline int real_from_text(const char *text, int shift, real *out)
{
	char *end;
	const char *c;
	(void)shift;
	if (!real_from_short_decimal(text, out)) {
		/* NFF numbers are decimal: C's hexadecimal floats (0x1p3) are no number here,
		 * as in fixed point, so every build reads a scene alike (a short decimal has
		 * no x). */
		for (c = text; *c; c++)
			if (*c == 'x' || *c == 'X')
				return REAL_TEXT_NOT_A_NUMBER;
		*out = real_parse(text, &end);
		if (end == text || *end != '\0')
			return REAL_TEXT_NOT_A_NUMBER;
	}
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
#endif

#endif
