/* fixed_text.c - Q16.16 numbers as decimal text: a scene's numbers read at its length
 * scale, rounded once, and numbers written back for messages, in integer arithmetic only.
 * See LICENSE for copyright and licence. */
#include "fixed.h"

#include <stdio.h>

/* Mantissas keep 18 significant digits (below 2^60). */
#define MANTISSA_LIMIT ((uint64_t)100000000000000000)

int32_t fixed_parse(const char *s, const char **end, int shift, int *overflow)
{
	const char *p = s;
	uint64_t mantissa = 0, room;
	int64_t result, denominator = 1;
	int negative = 0, digits = 0, exponent = 0, binary = 16 + shift, point = 0, up;
	*overflow = 0;
	if (*p == '+' || *p == '-')
		negative = *p++ == '-';
	/* Up to 18 significant digits; later ones only move the decimal point (those before
	 * it), or are dropped (those after it). One loop for both sides of the point. */
	for (;; p++) {
		if (*p == '.' && !point) {
			point = 1;
			continue;
		}
		if (*p < '0' || *p > '9')
			break;
		digits++;
		if (mantissa < MANTISSA_LIMIT) {
			mantissa = mantissa * 10 + (uint64_t)(*p - '0');
			exponent -= point;
		} else {
			exponent += !point;
		}
	}
	if (!digits) {
		*end = s;
		return 0;
	}
	if (*p == 'e' || *p == 'E') {
		const char *q = p + 1;
		int e_negative = 0;
		if (*q == '+' || *q == '-')
			e_negative = *q++ == '-';
		if (*q >= '0' && *q <= '9') {
			int e = 0;
			for (; *q >= '0' && *q <= '9'; q++)
				e = e < 10000 ? e * 10 + (*q - '0') : e;
			exponent += e_negative ? -e : e;
			p = q;
		}
	}
	*end = p;
	if (mantissa == 0)
		return 0;
	/* value = mantissa * 10^exponent * 2^binary, kept within 63 bits throughout: the
	 * mantissa is shifted up by a positive binary (below `room` it fits), the
	 * denominator by a negative one. */
	up = binary > 0 ? binary : 0;
	room = (uint64_t)1 << (62 - up);
	for (; exponent > 0; exponent--) {
		if (mantissa > UINT64_MAX / 20) {
			*overflow = 1;
			return 0;
		}
		mantissa *= 10;
	}
	while (exponent < -18 || (binary > 0 && mantissa >= room)) {
		mantissa = fixed_udiv64(mantissa + 5, 10);
		exponent++;
	}
	for (; exponent < 0; exponent++)
		denominator *= 10;
	if (binary >= 0 && mantissa >= room) {
		*overflow = 1;
		return 0;
	}
	result = fixed_round_div((int64_t)(mantissa << up), denominator << (up - binary));
	if (result > INT32_MAX) {
		*overflow = 1;
		return 0;
	}
	/* A mantissa that was not zero rounded to 0: too small (-1). */
	*overflow = -(result == 0);
	return (int32_t)(negative ? -result : result);
}

int fixed_from_text(const char *text, int shift, int32_t *out)
{
	const char *p = text + (*text == '+' || *text == '-');
	const char *end;
	int overflow;
	/* NaN and infinity, as strtod would read them: not finite (status 2). */
	if ((p[0] == 'n' || p[0] == 'N') || (p[0] == 'i' || p[0] == 'I')) {
		const char *w = (p[0] == 'n' || p[0] == 'N') ? "nan" : "inf";
		int i;
		for (i = 0; i < 3 && (p[i] | 0x20) == w[i]; i++)
			;
		if (i == 3) {
			*out = 0;
			return 2;
		}
	}
	*out = fixed_parse(text, &end, shift, &overflow);
	if (end == text || *end != '\0')
		return 1;
	/* 3 and 4: REAL_TEXT_OUT_OF_RANGE and REAL_TEXT_TINY (real.h). */
	return overflow > 0 ? 3 : overflow < 0 ? 4 : 0;
}

void fixed_format(int32_t x, int shift, char *buf, size_t size)
{
	/* In units of 2^-16, times 2^-shift: as 64 bits (a shift of up to 24 either way). */
	uint64_t magnitude = x < 0 ? (uint64_t)(-(int64_t)x) : (uint64_t)x;
	uint64_t whole, fraction;
	if (shift < 0)
		magnitude <<= (-shift > 24 ? 24 : -shift);
	else
		magnitude >>= (shift > 24 ? 24 : shift);
	whole = magnitude >> 16;
	fraction = ((magnitude & 0xFFFF) * 1000000 + 32768) >> 16;
	if (fraction >= 1000000) {
		whole++;
		fraction -= 1000000;
	}
	snprintf(buf, size, "%s%lu.%06lu", x < 0 ? "-" : "", (unsigned long)whole,
		 (unsigned long)fraction);
}
