/* fixed.c - the Q16.16 build's square roots, exponentials, tangent and number parsing,
 * in integer arithmetic only (the fixed build compiles with -mgeneral-regs-only).
 * Series run in Q4.28 or Q2.30 inside int64, so their rounding stays below 1 LSB of the
 * Q16.16 result. See LICENSE for copyright and licence. */
/* On the M0 the kernels of fixed.h are defined here, once. */
#define FIXED_KERNEL_BODIES
#include "fixed.h"

/* Plain integer code: every build compiles it (the unit tests check it in each), and
 * only the fixed build's `real` uses it. */
#include <stdio.h>

/* floor(sqrt(x)) and the remainder x - root^2, digit by digit in 32-bit arithmetic. */
static uint32_t isqrt_remainder32(uint32_t x, uint32_t *remainder)
{
	uint32_t r = 0, bit;
	if (x == 0) {
		*remainder = 0;
		return 0;
	}
	/* The highest power of 4 not above x, from its bit length (no search loop). */
	bit = (uint32_t)1 << ((fixed_bit_length(x) - 1) & ~1);
	while (bit) {
		if (x >= r + bit) {
			x -= r + bit;
			r = (r >> 1) + bit;
		} else {
			r >>= 1;
		}
		bit >>= 2;
	}
	*remainder = x;
	return r;
}

uint64_t fixed_isqrt64(uint64_t x)
{
	uint32_t low = (uint32_t)x, root, rem32;
	uint64_t rem;
	int i;
	if (!(x >> 32)) {
		root = isqrt_remainder32(low, &rem32);
		/* Round: sqrt(n) >= r + 1/2 exactly when n - r^2 > r (numerics.md Q03). */
		return rem32 > root ? (uint64_t)root + 1 : root;
	}
	/* The root of the high word first (32-bit arithmetic, cheap on small cores), then
	 * one more root bit per two bits of the low word: trying root bit 1 adds
	 * (2 root + 1)^2 - (2 root)^2 = 4 root + 1 to the square. */
	root = isqrt_remainder32((uint32_t)(x >> 32), &rem32);
	if (!(x >> 60)) {
		/* The root stays below 2^30 and the remainder at most twice the root: every
		 * step fits 32 bits (squared lengths of a scaled scene are all this small). */
		for (i = 0; i < 16; i++) {
			uint32_t trial = (root << 2) | 1u;
			rem32 = (rem32 << 2) | (low >> 30);
			low <<= 2;
			root <<= 1;
			if (rem32 >= trial) {
				rem32 -= trial;
				root |= 1u;
			}
		}
		return rem32 > root ? (uint64_t)root + 1 : root;
	}
	rem = rem32;
	for (i = 0; i < 16; i++) {
		uint64_t trial = ((uint64_t)root << 2) | 1u;
		rem = (rem << 2) | (low >> 30);
		low <<= 2;
		root <<= 1;
		if (rem >= trial) {
			rem -= trial;
			root |= 1u;
		}
	}
	return rem > root ? (uint64_t)root + 1 : root;
}

/* Apart: 12 bytes less M0 flash than inlined where it is used. */
FIXED_APART int32_t fixed_sqrt(int32_t a)
{
	return a <= 0 ? 0 : fixed_saturate((int64_t)fixed_isqrt64((uint64_t)a << 16));
}

/* Apart: 32 bytes less M0 flash than inlined where it is used. */
FIXED_APART int32_t fixed_sqrt2(int64_t w)
{
	return w <= 0 ? 0 : fixed_saturate((int64_t)fixed_isqrt64((uint64_t)w));
}

int32_t fixed_sqrt30(int32_t u)
{
	return u <= 0 ? 0 : (int32_t)fixed_isqrt64((uint64_t)u << 30);
}

/* 1/sqrt(w) as a fixed_reciprocal, without a square root or a division: w = t 4^k with t
 * in [1/4, 1), so 2^(30 + k) / sqrt(w) = 2^30 y for y = 1/sqrt(t) in (1, 2], which Newton's
 * y (3 - t y^2) / 2 refines from a table of 24 starting values (good to 2^-5) in three
 * steps (2^-9, 2^-17, then the 2^-30 that 32-bit products keep). Each step is three
 * products; the first two take y's top bits, so that each product is two 16 x 16 ones
 * (on the M0 a full 32 x 32 -> 64 product is four, and a sum of carries). Dividing by a
 * rounded root was a root and a division. */
static uint32_t sqrt_mantissa(uint64_t w, int k)
{
	/* t = w / 4^k in Q0.32 (w's top 30 to 32 bits), from w's 32-bit halves: a 64-bit
	 * shift is a library call on small cores. k is 1 to 32, so s is -30 to 32. */
	uint32_t high = (uint32_t)(w >> 32), low = (uint32_t)w;
	int s = 2 * k - 32;
	if (s <= 0)
		return low << -s;
	return s == 32 ? high : high << (32 - s) | low >> s;
}

fixed_reciprocal fixed_reciprocal_sqrt2(int64_t w)
{
	static const uint8_t start[32] = {
		0,   0,   0,   0,   0,   0,   0,   0,
		241, 214, 191, 171, 154, 138, 124, 112, 101, 90, 81, 72,
		64,  56,  49,  43,  37,  31,  25,  20,  15,  11, 6,  2,
	}; /* 1/sqrt(t) - 1 in Q0.8 at the middle of t's 24 intervals of 1/32 from 1/4, at
	    * index 32 t (the first 8 are never read: t >= 1/4) */
	fixed_reciprocal r;
	uint32_t t, y, low, high, ty;
	int k;
	r.negative = 0;
	if (w <= 0) { /* as fixed_reciprocal_of(0): quotients saturate */
		r.scale = 0;
		r.shift = 15;
		return r;
	}
	k = (fixed_bit_length((uint64_t)w) + 1) / 2; /* sqrt(w) in [2^(k-1), 2^k) */
	t = sqrt_mantissa((uint64_t)w, k);
	/* The first step starts from the table's 9 bits y0 (y = y0 2^22 in Q2.30), so each
	 * of its products is a 32-bit number's two 16-bit halves times y0: with the bits
	 * the 64-bit products below keep, t y / 2^32 is t y0 / 2^10, (t y) y / 2^30 is
	 * (t y) y0 / 2^8 and y m / 2^31 is m y0 / 2^9 (floors, the last two modulo 2^32).
	 * Two 16 x 16 products each, not four. */
	y = 256u + start[t >> 27];
	ty = ((t >> 16) * y << 6) + ((t & 0xFFFFu) * y >> 10);    /* t y in Q2.30 */
	ty = ((ty >> 16) * y << 8) + ((ty & 0xFFFFu) * y >> 8);   /* t y^2 in Q2.30 */
	ty = 0xC0000000u - ty;                                    /* 3 - t y^2 */
	y = ((ty >> 16) * y << 7) + ((ty & 0xFFFFu) * y >> 9);    /* y (3 - t y^2) / 2 */
	/* The second step from y's top 16 bits (y15 = y in Q1.15, at most 2^16): again two
	 * 16 x 16 products each, and good to 2^-17 (Newton squares the 2^-9 error; the 2^-15
	 * y15 drops is corrected with it). t y and the correction are below 2^31 (t y = 1/y
	 * is below 1), so no product passes 32 bits. */
	y >>= 15;
	ty = (t >> 16) * y + ((t & 0xFFFFu) * y >> 16);            /* t y in Q1.31 */
	ty = (ty >> 16) * y + ((ty & 0xFFFFu) * y >> 16);          /* t y^2 in Q2.30 */
	ty = 0xC0000000u - ty;                                     /* 3 - t y^2 */
	y = (ty >> 16) * y + ((ty & 0xFFFFu) * y >> 16);           /* y (3 - t y^2) / 2 */
	/* The last step in full 32 x 32 -> 64 products: 2^-34, below what Q2.30 keeps. */
	fixed_umul64_parts(t, y, &low, &ty);    /* t y in Q2.30 */
	fixed_umul64_parts(ty, y, &low, &high); /* t y^2 in Q4.60 */
	/* 3 - t y^2 in Q2.30 (t y^2 is within 2^-16 of 1 here). */
	fixed_umul64_parts(y, 0xC0000000u - ((high << 2) | (low >> 30)), &low, &high);
	y = (high << 1) | (low >> 31); /* y (3 - t y^2) / 2 in Q2.30 */
	r.scale = y;
	r.shift = 14 + k;
	return r;
}

int32_t fixed_sqrt_by_reciprocal(int64_t w, fixed_reciprocal r)
{
	/* sqrt(w) = t y 2^k: the product t y (Q2.62, below 2^62) over 2^s, s = 62 - k, in
	 * 32-bit halves (s is 31 to 61 for w below 2^62). q is the quotient by 2^(s - 1),
	 * whose last bit rounds. */
	int s = 76 - r.shift;
	uint32_t low, high, q;
	if (w <= 0)
		return 0;
	if (s <= 30)
		return FIXED_MAX; /* w >= 2^62: a root of 2^31 or more */
	fixed_umul64_parts(sqrt_mantissa((uint64_t)w, r.shift - 14), r.scale, &low, &high);
	q = s > 32 ? high >> (s - 33) : high << (33 - s) | low >> (s - 1);
	q = (q >> 1) + (q & 1);
	return q > (uint32_t)INT32_MAX ? FIXED_MAX : (int32_t)q;
}

/* Apart: its 64-bit arithmetic inlined into the polygon parser cost 60 bytes more
 * M0 flash. */
FIXED_APART int32_t fixed_ratio2(int64_t a, int64_t b)
{
	int negative = (a < 0) != (b < 0);
	int64_t q;
	a = a < 0 ? -a : a;
	b = b < 0 ? -b : b;
	/* Keep a * 65536 within 63 bits; the ratio loses nothing that Q16.16 could show. */
	while (a > ((int64_t)1 << 46)) {
		a >>= 1;
		b >>= 1;
	}
	if (b == 0)
		return negative ? -FIXED_MAX : FIXED_MAX;
	q = (int64_t)fixed_udiv64((uint64_t)(a * 65536 + b / 2), (uint64_t)b);
	return fixed_saturate(negative ? -q : q);
}


/* The product of two Q2.30 numbers (each below 2^32), truncated to Q2.30: 32-bit halves,
 * not a 64 x 64 multiply (a library call on small cores). */
static uint32_t mul_q30(uint32_t a, uint32_t b)
{
	uint32_t low, high;
	fixed_umul64_parts(a, b, &low, &high);
	return (high << 2) | (low >> 30);
}

/* 2^y for y in Q16.16, as Q16.16: 2^k by shifting, 2^f for the fraction f by the
 * Taylor series of e^(f ln 2) in Q2.30 (error below 1e-7 for f < 1). Every term and sum
 * is below 2^31, so the series runs in 32-bit numbers. */
static int32_t exp2_fixed(int64_t y)
{
	static const uint32_t inverse_factorial[] = {
		1073741824, 1073741824, 536870912, 178956971, 44739243, 8947849, 1491308, 213044, 26631,
	}; /* 1/k! in Q2.30, k = 0..8 */
	const uint32_t ln2 = 744261118; /* ln 2 in Q2.30 */
	int32_t v, k;
	uint32_t u, sum;
	int i;
	if (y >= (int64_t)15 * 65536)
		return FIXED_MAX;
	if (y < (int64_t)-17 * 65536)
		return 0;
	v = (int32_t)y;
	k = v >= 0 ? v / 65536 : -((-v + 65535) / 65536); /* floor, in [-17, 14] */
	u = mul_q30((uint32_t)(v - k * 65536) << 14, ln2); /* f ln 2 in Q2.30 */
	sum = inverse_factorial[8];
	for (i = 7; i >= 0; i--)
		sum = mul_q30(sum, u) + inverse_factorial[i];
	/* sum = 2^f in Q2.30; to Q16.16 and times 2^k, rounding. */
	if (k >= 0) {
		uint32_t whole = ((sum >> 13) + 1) >> 1;
		return whole > ((uint32_t)INT32_MAX >> k) ? FIXED_MAX : (int32_t)(whole << k);
	}
	k = 14 - k; /* total right shift, 15 to 31 */
	return (int32_t)((sum + ((uint32_t)1 << (k - 1))) >> k);
}

int32_t fixed_exp(int32_t x)
{
	const int64_t log2e = 1549082005; /* log2(e) in Q2.30 */
	return exp2_fixed((int64_t)x * log2e >> 30);
}

/* log2 x for x > 0 (Q16.16), in Q8.24: the integer part from the top bit, then one
 * fraction bit per squaring of the mantissa (in Q2.30). 24 bits keep x^y good to a few
 * LSB even for Phong exponents in the hundreds. The result is within +-2^28: 32 bits. */
static int32_t log2_fixed(int32_t x)
{
	int top = fixed_bit_length((uint32_t)x) - 1, i; /* x in [2^top, 2^(top+1)) */
	uint32_t m = (uint32_t)x << (30 - top);
	int32_t result = (top - 16) * ((int32_t)1 << 24);
	for (i = 23; i >= 0; i--) {
		m = mul_q30(m, m); /* below 2^32: m < 2^31 before */
		if (m >= (uint32_t)1 << 31) {
			m >>= 1;
			result += (int32_t)1 << i;
		}
	}
	return result;
}

int32_t fixed_pow(int32_t x, int32_t y)
{
	if (y == 0)
		return FIXED_ONE;
	if (x <= 0)
		return 0;
	/* ln x <= x - 1, so x^y <= 2^(-y (1 - x) / ln 2), below 2^-18 when y (1 - x) > 12.5:
	 * the result below would be 0 (log2's error, under 2^-23, times y is far smaller
	 * than the margin). Most Phong highlights end here, with one product. */
	if (fixed_mul(y, FIXED_ONE - x) > 12 * FIXED_ONE + FIXED_ONE / 2)
		return 0;
	/* y log2 x in Q16.16; log2 x (Q8.24, at most 15 in size) times y fits 64 bits. */
	return exp2_fixed(fixed_wide_mul(log2_fixed(x), y) >> 24);
}

/* pi / 180 in Q20.44: degrees in Q16.16 times this, shifted by 32, are radians in Q4.28.
 * (pi / 180 in Q16.16 keeps only 11 bits: a field of view 1.8e-4 too wide.) */
#define RADIANS_PER_DEGREE_Q44 INT64_C(307041569098)

void fixed_sin_cos_half_angle(int32_t degrees, int32_t *sine, int32_t *cosine)
{
	/* sin and cos by their nested Taylor series in Q4.28 (x^2 reaches 2.47 at pi/2);
	 * degrees < 180 keep the product below 2^62. */
	int64_t t = fixed_round_div((int64_t)degrees * RADIANS_PER_DEGREE_Q44, INT64_C(1) << 33);
	int64_t t2 = t * t >> 28, series[2];
	int k;
	/* Both series in one loop (one copy of its 64-bit arithmetic): series[k & 1], the
	 * cosine's for the even k (16 to 2), the sine's for the odd k (15 to 3). */
	series[0] = series[1] = (int64_t)1 << 28;
	for (k = 16; k >= 2; k--)
		series[k & 1] = ((int64_t)1 << 28) -
				fixed_div64(t2 * series[k & 1] >> 28, k * (k - 1));
	*sine = (int32_t)(t * series[1] >> 28);
	*cosine = (int32_t)series[0];
}

int32_t fixed_tan_degrees(int32_t degrees)
{
	int32_t s, c;
	fixed_sin_cos_half_angle(degrees * 2, &s, &c);
	if (c <= 0)
		return FIXED_MAX;
	return fixed_saturate(fixed_round_div((int64_t)s * 65536, c));
}

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

int32_t fixed_ldexp(int32_t x, int e)
{
	/* In 32 bits (64-bit shifts are library calls on small cores). Up: the magnitude,
	 * saturated when it has more bits than the shift leaves room for (any shift past 31
	 * acts as 31 does: 0 stays 0, the rest saturates). */
	if (e >= 0) {
		uint32_t m = x < 0 ? 0u - (uint32_t)x : (uint32_t)x;
		e = e > 31 ? 31 : e;
		m = m > ((uint32_t)INT32_MAX >> e) ? (uint32_t)INT32_MAX : m << e;
		return x < 0 ? -(int32_t)m : (int32_t)m;
	}
	/* Down by k = -e, rounding half up: floor(x / 2^k + 1/2) is the floor of x / 2^k plus
	 * the bit below it (x + 2^(k - 1) itself could overflow), both from x / 2^(k - 1). */
	if (e < -31)
		return 0;
	x >>= -e - 1;
	return (x >> 1) + (x & 1);
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
