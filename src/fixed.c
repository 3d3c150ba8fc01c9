/* fixed.c - the Q16.16 build's core: fixed.h's kernels (defined here, once, on the M0),
 * square roots and reciprocal square roots, ratios and scaling by powers of two, in
 * integer arithmetic only (the fixed build compiles with -mgeneral-regs-only).
 * fixed_func.c has the exponentials and angles, fixed_text.c the decimal text.
 * See LICENSE for copyright and licence. */
/* On the M0 the kernels of fixed.h are defined here, once. */
#define FIXED_KERNEL_BODIES
#include "fixed.h"

/* Plain integer code, as are fixed_func.c and fixed_text.c: every build compiles it (the
 * unit tests check it in each), and only the fixed build's `real` uses it. */
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
RT_APART int32_t fixed_sqrt(int32_t a)
{
	return a <= 0 ? 0 : fixed_saturate((int64_t)fixed_isqrt64((uint64_t)a << 16));
}

/* Apart: 32 bytes less M0 flash than inlined where it is used. */
RT_APART int32_t fixed_sqrt2(int64_t w)
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
RT_APART int32_t fixed_ratio2(int64_t a, int64_t b)
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
