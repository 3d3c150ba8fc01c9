/* fixed_narrow.h - Q16.16's narrow forms: 64-bit products and quotients made of 32-bit
 * steps (16 x 16 products with their carries, shift-and-subtract division), and 64-bit
 * values handled as two 32-bit halves. A Cortex-M0 builds its kernels from them (in
 * Thumb-1 assembly where fixed_m0.h has it); every other build has them too, as the C
 * forms the unit tests check against the compiler's own 64-bit arithmetic. Included by
 * fixed.h only.
 * See LICENSE for copyright and licence. */
#ifndef RT_FIXED_NARROW_H
#define RT_FIXED_NARROW_H

/* The exact 64-bit product a b from four 16 x 16 products: a = ah 2^16 + al with ah
 * signed and al in [0, 2^16), so every partial product fits 32 bits. Each cross product
 * is added to the low word with its carry, all in 32-bit arithmetic (unsigned, where it
 * wraps by design), which an M0 does in a few instructions each. */
static inline int64_t fixed_wide_mul_narrow(int32_t a, int32_t b)
{
	int32_t ah = a >> 16, bh = b >> 16;
	uint32_t al = (uint32_t)a & 0xFFFFu, bl = (uint32_t)b & 0xFFFFu;
	uint32_t low = al * bl, high = (uint32_t)(ah * bh), shifted;
	int32_t cross = (int32_t)al * bh;
	shifted = (uint32_t)cross << 16;
	low += shifted;
	high += (uint32_t)(cross >> 16) + (low < shifted);
	cross = ah * (int32_t)bl;
	shifted = (uint32_t)cross << 16;
	low += shifted;
	high += (uint32_t)(cross >> 16) + (low < shifted);
	return (int64_t)(((uint64_t)high << 32) | low);
}

/* The exact 64-bit product of two unsigned 32-bit numbers, as fixed_wide_mul_narrow:
 * four 16 x 16 products, the cross terms added with their carries. */
static inline uint64_t fixed_umul64_narrow(uint32_t a, uint32_t b)
{
	uint32_t ah = a >> 16, al = a & 0xFFFFu, bh = b >> 16, bl = b & 0xFFFFu;
	uint32_t low = al * bl, high = ah * bh, cross = al * bh, shifted = cross << 16;
	low += shifted;
	high += (cross >> 16) + (low < shifted);
	cross = ah * bl;
	shifted = cross << 16;
	low += shifted;
	high += (cross >> 16) + (low < shifted);
	return ((uint64_t)high << 32) | low;
}

/* The primitives the narrow forms are made of: a saturating add, the two 32 x 32 -> 64
 * products, a 64-bit add and the quotient steps of a division, each on 64-bit values as
 * two 32-bit halves (on the M0 a 64-bit value in C costs register shuffles and carry
 * tests the instruction set does in one step). Where GCC builds for the M0 they are
 * Thumb-1 assembly (fixed_m0.h); everywhere else C with the same results, which the unit
 * tests check on every build. */
#if FIXED_ASM
#include "fixed_m0.h"
#else
/* fixed_saturate((int64_t)a + b) in 32-bit arithmetic: the overflow test first. On the
 * M0 the add's own overflow flag tells it, and a sum of exactly -2^31 (no overflow, but
 * outside the range) is the one other case: two instructions more, where the C test is
 * six (vector sums are most of its uses). */
RT_INLINE int32_t fixed_add(int32_t a, int32_t b)
{
	if (b > 0 ? a > INT32_MAX - b : a < -INT32_MAX - b)
		return b > 0 ? INT32_MAX : -INT32_MAX;
	return a + b;
}

/* a b as (*high << 32) + *low for unsigned a and b, as fixed_umul64_narrow. */
RT_INLINE void fixed_umul64_parts(uint32_t a, uint32_t b, uint32_t *low, uint32_t *high)
{
	/* Elsewhere the compiler's own product where it is cheap (a Cortex-M3 has one
	 * instruction for it), the 16 x 16 form on a narrow core without GCC. */
	uint64_t product = FIXED_NARROW ? fixed_umul64_narrow(a, b) : (uint64_t)a * b;
	*low = (uint32_t)product;
	*high = (uint32_t)(product >> 32);
}

/* a b as (*high << 32) + *low, exactly. */
RT_INLINE void fixed_wide_mul_parts(int32_t a, int32_t b, uint32_t *low, int32_t *high)
{
	int64_t product = FIXED_NARROW ? fixed_wide_mul_narrow(a, b) : (int64_t)a * b;
	*low = (uint32_t)product;
	*high = (int32_t)(product >> 32);
}

/* (*high, *low) += (high, low), wrapping as 64-bit two's complement. */
RT_INLINE void fixed_add_parts(uint32_t *low, int32_t *high, uint32_t add_low,
				   int32_t add_high)
{
	uint32_t sum = *low + add_low;
	*high = (int32_t)((uint32_t)*high + (uint32_t)add_high + (sum < add_low));
	*low = sum;
}

/* The quotient steps of fixed_udiv_narrow: `steps` bits of the quotient shifted into *low
 * as the remainder *rem (below d) takes the bits shifted out of it. */
RT_INLINE void fixed_udiv_steps(uint32_t *low_bits, uint32_t *remainder, uint32_t d, int steps)
{
	uint32_t low = *low_bits, rem = *remainder;
	for (; steps > 0; steps--) {
		/* rem < d, so 2 rem + 1 < 2^33: the bit shifted out is the 33rd. */
		uint32_t carry = rem >> 31;
		rem = (rem << 1) | (low >> 31);
		low <<= 1;
		if (carry || rem >= d) {
			rem -= d;
			low |= 1;
		}
	}
	*low_bits = low;
	*remainder = rem;
}
#endif


RT_INLINE uint64_t fixed_umul64(uint32_t a, uint32_t b)
{
#if FIXED_NARROW
	uint32_t low, high;
	fixed_umul64_parts(a, b, &low, &high);
	return ((uint64_t)high << 32) | low;
#else
	return (uint64_t)a * b;
#endif
}



RT_INLINE int64_t fixed_join_parts(uint32_t low, int32_t high)
{
	return (int64_t)(((uint64_t)(uint32_t)high << 32) | low);
}

/* fixed_saturate(((high << 32) + low + 2^(bits - 1)) >> bits), in 32-bit steps (no 64-bit
 * shift and no call): bits = 16 rounds a Q32.32 value to Q16.16; bits = 30 rounds a product
 * with a Q2.30 factor (Q4.60, or Q18.46 for a Q16.16 one) back to its other factor's
 * format. bits is a constant at most calls (16 or 30); eye rays drop 2 to 16 (camera.c). */
RT_INLINE int32_t fixed_round_parts(uint32_t low, int32_t high, int bits)
{
	uint32_t half = (uint32_t)1 << (bits - 1);
	int32_t v;
	fixed_add_parts(&low, &high, half, 0);
	/* In range when high is in [-2^(bits - 1), 2^(bits - 1)), but for -2^31 itself: one
	 * unsigned test (the conversion to int32_t wraps, as on every compiler rt supports). */
	v = (int32_t)(((uint32_t)high << (32 - bits)) | (low >> bits));
	if (((uint32_t)high + half) >> bits || v == INT32_MIN)
		return high < 0 ? -INT32_MAX : INT32_MAX;
	return v;
}

/* fixed_mul, fixed_dot3 and the dot product as 64 bits, from the parts. */
RT_INLINE int32_t fixed_mul_narrow(int32_t a, int32_t b)
{
	uint32_t low;
	int32_t high;
	fixed_wide_mul_parts(a, b, &low, &high);
	return fixed_round_parts(low, high, 16);
}

RT_INLINE void fixed_dot3_parts(int32_t ax, int32_t ay, int32_t az, int32_t bx,
				    int32_t by, int32_t bz, uint32_t *low, int32_t *high)
{
	uint32_t l;
	int32_t h;
	fixed_wide_mul_parts(ax, bx, low, high);
	fixed_wide_mul_parts(ay, by, &l, &h);
	fixed_add_parts(low, high, l, h);
	fixed_wide_mul_parts(az, bz, &l, &h);
	fixed_add_parts(low, high, l, h);
}

RT_INLINE int32_t fixed_dot3_narrow(int32_t ax, int32_t ay, int32_t az, int32_t bx,
					int32_t by, int32_t bz)
{
	uint32_t low;
	int32_t high;
	fixed_dot3_parts(ax, ay, az, bx, by, bz, &low, &high);
	return fixed_round_parts(low, high, 16);
}

RT_INLINE int64_t fixed_dot3_wide_narrow(int32_t ax, int32_t ay, int32_t az, int32_t bx,
					     int32_t by, int32_t bz)
{
	uint32_t low;
	int32_t high;
	fixed_dot3_parts(ax, ay, az, bx, by, bz, &low, &high);
	return fixed_join_parts(low, high);
}

/* The same rounded at bit 30: products and dot products with Q2.30 numbers. */
RT_INLINE int32_t fixed_mul30_narrow(int32_t a, int32_t b)
{
	uint32_t low;
	int32_t high;
	fixed_wide_mul_parts(a, b, &low, &high);
	return fixed_round_parts(low, high, 30);
}

RT_INLINE int32_t fixed_dot3_30_narrow(int32_t ax, int32_t ay, int32_t az, int32_t bx,
					   int32_t by, int32_t bz)
{
	uint32_t low;
	int32_t high;
	fixed_dot3_parts(ax, ay, az, bx, by, bz, &low, &high);
	return fixed_round_parts(low, high, 30);
}

/* Number of significant bits of x (0 for 0), by halving: a few steps, no loop. */
static inline int fixed_bit_length(uint64_t x)
{
	int n = 0;
	uint32_t v = (uint32_t)x;
	if (x >> 32) {
		n = 32;
		v = (uint32_t)(x >> 32);
	}
	if (v >> 16) {
		n += 16;
		v >>= 16;
	}
	if (v >> 8) {
		n += 8;
		v >>= 8;
	}
	if (v >> 4) {
		n += 4;
		v >>= 4;
	}
	if (v >> 2) {
		n += 2;
		v >>= 2;
	}
	if (v >> 1) {
		n += 1;
		v >>= 1;
	}
	return n + (int)v;
}

/* floor(n / d) for d > 0, or UINT32_MAX when the quotient does not fit 32 bits: one
 * quotient bit per step, from a remainder that always stays below d. The low word of n
 * is shifted out at the top as the quotient bits are shifted in at the bottom. */
static inline uint32_t fixed_udiv_narrow(uint64_t n, uint32_t d)
{
	uint32_t rem = (uint32_t)(n >> 32), low = (uint32_t)n;
	int steps = 32;
	if (rem >= d)
		return UINT32_MAX; /* the quotient needs more than 32 bits */
	if (!(rem >> 16) && ((rem << 16) | (low >> 16)) < d) {
		/* At most 16 quotient bits (a result below 1.0): start 16 bits further on. */
		rem = (rem << 16) | (low >> 16);
		low <<= 16;
		steps = 16;
	}
	fixed_udiv_steps(&low, &rem, d, steps);
	return low;
}

/* floor(n / d), 64 bits by 64 (UINT64_MAX for d = 0): one quotient bit per step, from
 * the top one. */
static inline uint64_t fixed_udiv64_narrow(uint64_t n, uint64_t d)
{
	int shift = fixed_bit_length(n) - fixed_bit_length(d), i;
	uint64_t q = 0;
	if (d == 0)
		return UINT64_MAX; /* as if infinite: callers never divide by 0 */
	if (shift < 0)
		return 0;
	d <<= shift; /* fits: it has as many bits as n now */
	for (i = 0; i <= shift; i++) {
		q <<= 1;
		if (n >= d) {
			n -= d;
			q |= 1;
		}
		d >>= 1;
	}
	return q;
}


#if FIXED_NARROW && defined(FIXED_KERNEL_BODIES)
/* The M0's kernels (declared in fixed.h), each defined once, out of line, in fixed.c:
 * made of the narrow forms above. */
RT_SHARED int64_t fixed_wide_mul(int32_t a, int32_t b)
{
	uint32_t low;
	int32_t high;
	fixed_wide_mul_parts(a, b, &low, &high);
	return fixed_join_parts(low, high);
}

RT_SHARED uint32_t fixed_udiv(uint64_t n, uint32_t d)
{
	return fixed_udiv_narrow(n, d);
}

RT_SHARED uint64_t fixed_udiv64(uint64_t n, uint64_t d)
{
	return fixed_udiv64_narrow(n, d);
}

RT_SHARED int32_t fixed_mul(int32_t a, int32_t b)
{
	return fixed_mul_narrow(a, b);
}

RT_SHARED int32_t fixed_dot3(int32_t ax, int32_t ay, int32_t az, int32_t bx, int32_t by,
				 int32_t bz)
{
	return fixed_dot3_narrow(ax, ay, az, bx, by, bz);
}

RT_SHARED int64_t fixed_dot3_wide(int32_t ax, int32_t ay, int32_t az, int32_t bx,
				     int32_t by, int32_t bz)
{
	return fixed_dot3_wide_narrow(ax, ay, az, bx, by, bz);
}

/* Rounded at bit 29 and saturated: in 32-bit halves, inlined (as fixed_mul). */
RT_SHARED int32_t fixed_mul30(int32_t a, int32_t b)
{
	return fixed_mul30_narrow(a, b);
}

RT_SHARED int32_t fixed_dot3_30(int32_t ax, int32_t ay, int32_t az, int32_t bx, int32_t by,
				   int32_t bz)
{
	return fixed_dot3_30_narrow(ax, ay, az, bx, by, bz);
}
#endif

#endif
