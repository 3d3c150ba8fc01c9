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
#include <stdio.h>

#define REAL_INPUT_LIMIT REAL_C(1e12) /* the largest magnitude a scene may write */
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
#endif

#endif
