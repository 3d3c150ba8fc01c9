/* fixed_func.c - the Q16.16 build's exponential, power, logarithm, sine, cosine and
 * tangent, in integer arithmetic only. Series run in Q4.28 or Q2.30 inside int64, so
 * their rounding stays below 1 LSB of the Q16.16 result.
 * See LICENSE for copyright and licence. */
#include "fixed.h"

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
