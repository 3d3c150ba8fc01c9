/* test_fixed.c - the Q16.16 arithmetic of fixed.c against numerics.md's fixed-point cases
 * (Q01-Q04, B06). Integer code, so it runs in every build.
 * See LICENSE for copyright and licence. */
#include <math.h>

#include "fixed.h"
#include "scale.h"
#include "test.h"

#define Q(x) ((int32_t)((x) * 65536.0 + ((x) < 0 ? -0.5 : 0.5)))

static double to_double(int32_t x) { return x / 65536.0; }

static void test_products(void)
{
	/* Q01: 181^2 fits Q16.16, 182^2 does not; the 64-bit square (real2) holds both. */
	CHECK_INT(fixed_mul(Q(181.0), Q(181.0)), Q(32761.0));
	CHECK_INT(fixed_mul(Q(182.0), Q(182.0)), FIXED_MAX); /* saturates, never wraps */
	CHECK_INT((int64_t)Q(182.0) * Q(182.0), (int64_t)33124 << 32);
	/* Rounding to nearest: 0.5 LSB products round away, -0.5 LSB too. */
	CHECK_INT(fixed_mul(1, 32768), 1);
	CHECK_INT(fixed_mul(Q(-1.5), Q(2.0)), Q(-3.0));
	CHECK_INT(fixed_div(Q(1.0), Q(3.0)), 21845);
	CHECK_INT(fixed_div(Q(-1.0), Q(3.0)), -21845);
	CHECK_INT(fixed_div(Q(5.0), 0), FIXED_MAX);
	/* Dot products are summed in 64 bits, rounded once, and saturate. */
	CHECK_INT(fixed_dot3(Q(100.0), Q(100.0), Q(100.0), Q(100.0), Q(100.0), Q(100.0)),
		  Q(30000.0));
	CHECK_INT(fixed_dot3(Q(200.0), Q(200.0), Q(200.0), Q(200.0), Q(200.0), Q(200.0)),
		  FIXED_MAX);
	/* Q02: r = 1e-3 is 66 LSB; its square vanishes in Q16.16 but is 4356 in Q32.32. */
	CHECK_INT(Q(0.001), 66);
	CHECK_INT(fixed_mul(Q(0.001), Q(0.001)), 0);
	CHECK_INT((int64_t)Q(0.001) * Q(0.001), 4356);
}

/* fixed_reciprocal_sqrt2 by its definition: the table's start and three Newton steps,
 * the second from y's top 16 bits (Q1.15), every product in plain 64-bit arithmetic. */
static fixed_reciprocal reference_reciprocal_sqrt2(int64_t w)
{
	static const uint8_t start[24] = {
		241, 214, 191, 171, 154, 138, 124, 112, 101, 90, 81, 72,
		64,  56,  49,  43,  37,  31,  25,  20,  15,  11, 6,  2,
	};
	fixed_reciprocal r;
	uint64_t x = (uint64_t)w;
	uint32_t t, y, ty, m;
	int k = 0, i;
	r.negative = 0;
	r.scale = 0;
	r.shift = 15;
	if (w <= 0)
		return r;
	while (k < 32 && x >> (2 * k)) /* sqrt(w) in [2^(k-1), 2^k) */
		k++;
	t = 2 * k >= 32 ? (uint32_t)(x >> (2 * k - 32)) : (uint32_t)x << (32 - 2 * k);
	y = (256u + start[(t >> 27) - 8]) << 22;
	for (i = 0; i < 3; i++) {
		if (i == 1) {
			uint32_t y15 = y >> 15;
			ty = (uint32_t)(((uint64_t)t * y15) >> 16);
			m = 0xC0000000u - (uint32_t)(((uint64_t)ty * y15) >> 16);
			y = (uint32_t)(((uint64_t)m * y15) >> 16);
			continue;
		}
		ty = (uint32_t)(((uint64_t)t * y) >> 32);
		m = 0xC0000000u - (uint32_t)(((uint64_t)ty * y) >> 30);
		y = (uint32_t)(((uint64_t)y * m) >> 31);
	}
	r.scale = y;
	r.shift = 14 + k;
	return r;
}

static void test_roots(void)
{
	int32_t third;
	/* Q03: sqrt 2 rounds to 92682 (a truncating root gives 92681). */
	CHECK_INT(fixed_sqrt(Q(2.0)), 92682);
	CHECK_INT(fixed_sqrt(Q(4.0)), Q(2.0));
	CHECK_INT(fixed_sqrt(0), 0);
	CHECK_INT(fixed_sqrt(-5), 0);
	CHECK_INT(fixed_isqrt64((uint64_t)1 << 62), (uint64_t)1 << 31);
	CHECK_INT(fixed_isqrt64(24), 5); /* 4.899 rounds up */
	CHECK_INT(fixed_isqrt64(UINT64_MAX), (uint64_t)1 << 32);
	CHECK_INT(fixed_isqrt64(((uint64_t)1 << 32) + 1), (uint64_t)1 << 16);
	CHECK_INT(fixed_isqrt64((uint64_t)4294967295u * 4294967295u), 4294967295u);
	/* Either side of 2^60, where the digit loop leaves 32-bit arithmetic. */
	CHECK_INT(fixed_isqrt64(((uint64_t)1 << 60) - 1), (uint64_t)1 << 30);
	CHECK_INT(fixed_isqrt64((uint64_t)1073741823u * 1073741823u + 1073741823u), 1073741823u);
	CHECK_INT(fixed_isqrt64((uint64_t)1 << 60), (uint64_t)1 << 30);
	CHECK_INT(fixed_isqrt64(((uint64_t)1 << 60) + ((uint64_t)1 << 31)), ((uint64_t)1 << 30) + 1);
	{
		/* Against the exact rule, on seeded random numbers of every size: r is the
		 * rounded root when (r - 1/2)^2 <= x < (r + 1/2)^2, i.e. r^2 - r < x <= r^2 + r. */
		int i, wrong = 0;
		test_seed(99);
		for (i = 0; i < 20000; i++) {
			uint64_t x = ((uint64_t)test_random_bits() << 32 | test_random_bits()) >>
				     (test_random_bits() % 64u);
			uint64_t r = fixed_isqrt64(x);
			/* r^2 - r < x <= r^2 + r, in 64 bits: r <= 2^32 so r^2 - r fits. */
			if (r > 0 && !(r * r - r < x && (x - (r * r - r)) <= 2 * r))
				wrong++;
		}
		CHECK_INT(wrong, 0);
	}
	CHECK_INT(fixed_sqrt2((int64_t)9 << 32), Q(3.0));
	/* Q04: (1,1,1)/sqrt 3 has 37837 LSB per component. */
	third = fixed_div(Q(1.0), fixed_sqrt(Q(3.0)));
	CHECK_INT(third, 37837);
	/* The reciprocal square root (Newton, no root or division): unit vectors' components
	 * are the exact quotients rounded, and the length from it the rounded root. */
	CHECK_INT(fixed_times_reciprocal(Q(1.0), fixed_reciprocal_sqrt2((int64_t)3 << 32)), 37837);
	CHECK_INT(fixed_times_reciprocal(Q(3.0), fixed_reciprocal_sqrt2((int64_t)25 << 32)),
		  Q(0.6));
	CHECK_INT(fixed_sqrt_by_reciprocal((int64_t)9 << 32,
					   fixed_reciprocal_sqrt2((int64_t)9 << 32)),
		  Q(3.0));
	CHECK_INT(fixed_times_reciprocal(Q(2.0), fixed_reciprocal_sqrt2(0)), FIXED_MAX);
	CHECK_INT(fixed_sqrt_by_reciprocal(0, fixed_reciprocal_sqrt2(0)), 0);
	{
		/* The same bits as the definition (whose first step's products fold to 16-bit
		 * halves times the table's 9 bits): every power of two and its neighbours, then
		 * seeded random numbers of every size. */
		int i, wrong = 0;
		test_seed(31);
		for (i = 0; i < 200000; i++) {
			int64_t w;
			fixed_reciprocal r, expect;
			if (i < 63 * 3)
				w = ((int64_t)1 << (i / 3)) + (i % 3) - 1;
			else
				w = (int64_t)(((uint64_t)test_random_bits() << 32 | test_random_bits()) >>
					      (1 + test_random_bits() % 63u));
			r = fixed_reciprocal_sqrt2(w);
			expect = reference_reciprocal_sqrt2(w);
			if (r.scale != expect.scale || r.shift != expect.shift ||
			    r.negative != expect.negative)
				wrong++;
		}
		CHECK_INT(wrong, 0);
		CHECK_INT(fixed_reciprocal_sqrt2(INT64_MAX).scale,
			  reference_reciprocal_sqrt2(INT64_MAX).scale);
		CHECK_INT(fixed_reciprocal_sqrt2(-1).scale, 0);
	}
	{
		/* Seeded random vectors of every size: each component over the length within
		 * 0.5 LSB (rounding) plus 2^-10 LSB (the reciprocal's 2^-29); the length within
		 * an LSB plus 2^-29 of it (4 LSB at 2^31). */
		int i, wrong = 0;
		test_seed(7);
		for (i = 0; i < 20000; i++) {
			int shift = (int)(test_random_bits() % 31u);
			int32_t x = (int32_t)(test_random_bits() >> 2) >> shift;
			int32_t y = (int32_t)(test_random_bits() >> 2) >> shift;
			int32_t z = -((int32_t)(test_random_bits() >> 2) >> shift);
			int64_t w = (int64_t)x * x + (int64_t)y * y + (int64_t)z * z;
			fixed_reciprocal r;
			long double length;
			if (w <= 0 || w >= (int64_t)1 << 62)
				continue;
			r = fixed_reciprocal_sqrt2(w);
			length = sqrtl((long double)w);
			if (fabsl(fixed_times_reciprocal(z, r) - z * 65536.0L / length) >
				    0.5L + 1.0L / 1024 ||
			    fabsl(fixed_sqrt_by_reciprocal(w, r) - length) > 1.0L + length / (1L << 29))
				wrong++;
		}
		CHECK_INT(wrong, 0);
	}
}

static void test_exp_pow_tan(void)
{
	int i;
	double worst = 0.0;
	/* B06: e^-x in Q16.16 is within 1 LSB of the rounded exact value (x = 1, 5, 10), and
	 * e^-11.78 is about 1 LSB. */
	CHECK_NEAR(fixed_exp(Q(-1.0)), exp(-1.0) * 65536.0, 1.0);
	CHECK_NEAR(fixed_exp(Q(-5.0)), exp(-5.0) * 65536.0, 1.0);
	CHECK_NEAR(fixed_exp(Q(-10.0)), exp(-10.0) * 65536.0, 1.0);
	CHECK_INT(fixed_exp(Q(-10.0)), 3);
	CHECK(fixed_exp(Q(-11.78)) <= 1);
	CHECK_INT(fixed_exp(0), Q(1.0));
	CHECK_INT(fixed_exp(Q(-30.0)), 0);
	for (i = 0; i <= 200; i++) {
		double x = -i * 0.05;
		double err = fabs(to_double(fixed_exp(Q(x))) - exp(x));
		worst = err > worst ? err : worst;
	}
	CHECK(worst < 2.0 / 65536.0);
	/* x^y for the Phong exponents rt meets, on [0, 1]. */
	CHECK_NEAR(to_double(fixed_pow(Q(0.5), Q(2.0))), 0.25, 2.0 / 65536.0);
	CHECK_NEAR(to_double(fixed_pow(Q(0.9), Q(45.28))), pow(to_double(Q(0.9)), 45.28),
		   4.0 / 65536.0);
	CHECK_INT(fixed_pow(0, Q(3.0)), 0);
	CHECK_INT(fixed_pow(Q(0.3), 0), Q(1.0));
	/* tan of half the field of view, to a few LSB. */
	CHECK_NEAR(to_double(fixed_tan_degrees(Q(26.0))), tan(26.0 * 3.14159265358979323846 / 180.0), 1.0 / 65536.0);
	CHECK_NEAR(to_double(fixed_tan_degrees(Q(57.29578))), tan(1.0), 8.0 / 65536.0);
	/* The angle is converted at 2^-28: tan 26.565051177 degrees (scenes/hard/grid-edges.nff,
	 * half its field of view) is 1/2 to the last bit, where pi / 180 as Q16.16 gave 4 LSB
	 * too many. */
	CHECK_INT(fixed_tan_degrees(Q(26.56505117707799)), Q(0.5));
}

static void test_parsing(void)
{
	int32_t v;
	CHECK_INT(fixed_from_text("1", 0, &v), 0);
	CHECK_INT(v, Q(1.0));
	CHECK_INT(fixed_from_text("-2.25", 0, &v), 0);
	CHECK_INT(v, Q(-2.25));
	CHECK_INT(fixed_from_text("1e-3", 0, &v), 0);
	CHECK_INT(v, 66);
	/* Too small: read as 0, and said so (REAL_TEXT_TINY); zero itself is no underflow. */
	CHECK_INT(fixed_from_text("1.11022e-16", 0, &v), 4);
	CHECK_INT(v, 0);
	CHECK_INT(fixed_from_text("0.000e-9", 0, &v), 0);
	CHECK_INT(v, 0);
	/* A length scale: 0.006 read at 2^8. */
	CHECK_INT(fixed_from_text("0.006", 8, &v), 0);
	CHECK_INT(v, 100663);
	CHECK_INT(fixed_from_text("32768", 0, &v), 3); /* out of range */
	CHECK_INT(fixed_from_text("1e99999", 0, &v), 3);
	CHECK_INT(fixed_from_text("nan", 0, &v), 2);
	CHECK_INT(fixed_from_text("-Inf", 0, &v), 2);
	CHECK_INT(fixed_from_text("1.0x", 0, &v), 1);
	CHECK_INT(fixed_from_text("", 0, &v), 1);
	/* Scaling a scene: the extent ends up in 2048 .. 4096 (Q16.16's rule; floating
	 * point reads every scene at scale 1). */
	CHECK_INT(scale_length_shift(Q(12.0), 0), REAL_FIXED ? 8 : 0);
	CHECK_INT(scale_length_shift(Q(100.0), -12), REAL_FIXED ? -7 : 0);
}

/* Operands worth checking: the edges of the range, and random numbers of every size. */
static int32_t operand(int i)
{
	static const int32_t edges[] = {0,      1,     -1,     65535,     65536,     -65536,
					32767,  32768, -32768, INT32_MAX, -INT32_MAX, INT32_MIN,
					0x7FFF0000, -0x7FFF0000, 0x00010001, -0x00010001};
	int n = (int)(sizeof edges / sizeof edges[0]);
	if (i < n)
		return edges[i];
	/* Random bits shifted to a random size, with a random sign. */
	return (int32_t)(test_random_bits() >> (test_random_bits() % 32u));
}

/* a * 65536 / b rounded to nearest, halves away from zero, in plain 64-bit arithmetic. */
static int64_t reference_round_div(int32_t a, int32_t b)
{
	int64_t n = (int64_t)a * 65536, d = b, half = (d < 0 ? -d : d) / 2;
	return (n < 0 ? n - half : n + half) / d;
}

/* The M0's narrow kernels (16 x 16 products, shift-and-subtract division) give exactly
 * the bits of 64-bit arithmetic, which the host build uses: both builds must write the
 * same image. Checked on every build, whichever form its fixed_mul uses. */
static void test_narrow_kernels(void)
{
	int i, j, mismatches = 0, checked = 0;
	test_seed(12345);
	for (i = 0; i < 400; i++) {
		for (j = 0; j < 16; j++) {
			int32_t a = operand(i), b = operand(j + (i < 16 ? 0 : 16));
			uint32_t d = (uint32_t)b == 0 ? 1u : (b < 0 ? 0u - (uint32_t)b : (uint32_t)b);
			uint64_t n = ((uint64_t)(uint32_t)a << 16) | (uint32_t)b;
			uint64_t q = n / d;
			checked++;
			if (fixed_wide_mul_narrow(a, b) != (int64_t)a * b)
				mismatches++;
			if (fixed_umul64_narrow((uint32_t)a, (uint32_t)b) != (uint64_t)(uint32_t)a * (uint32_t)b)
				mismatches++;
			if (fixed_udiv_narrow(n, d) != (q > UINT32_MAX ? UINT32_MAX : (uint32_t)q))
				mismatches++;
			if (fixed_udiv64_narrow(n * 977, d) != n * 977 / d ||
			    fixed_udiv64_narrow(n, n / 3 + 1) != n / (n / 3 + 1))
				mismatches++;
			if (fixed_add(a, b) != fixed_saturate((int64_t)a + b))
				mismatches++;
			/* And the kernels built on them, against their 64-bit definitions. */
			if (fixed_mul(a, b) != fixed_saturate(((int64_t)a * b + 0x8000) >> 16) ||
			    fixed_mul_narrow(a, b) != fixed_mul(a, b))
				mismatches++;
			/* Halved, so that three products sum within 63 bits. */
			if (fixed_dot3_narrow(a >> 1, b, (a ^ b) >> 1, b >> 1, a, b >> 3) !=
				    fixed_dot3(a >> 1, b, (a ^ b) >> 1, b >> 1, a, b >> 3) ||
			    fixed_dot3_wide_narrow(a >> 1, -(b >> 1), b, b, a >> 1, a >> 5) !=
				    (int64_t)(a >> 1) * b - (int64_t)(b >> 1) * (a >> 1) +
					    (int64_t)b * (a >> 5))
				mismatches++;
			/* The Q2.30 forms, rounded at bit 30 (the dot product halved as above). */
			if (fixed_mul30_narrow(a, b) !=
				    fixed_saturate(((int64_t)a * b + ((int64_t)1 << 29)) >> 30) ||
			    fixed_mul30(a, b) != fixed_mul30_narrow(a, b) ||
			    fixed_dot3_30_narrow(a >> 1, b, (a ^ b) >> 1, b >> 1, a, b >> 3) !=
				    fixed_saturate(((int64_t)(a >> 1) * (b >> 1) + (int64_t)b * a +
						    (int64_t)((a ^ b) >> 1) * (b >> 3) +
						    ((int64_t)1 << 29)) >>
						   30) ||
			    fixed_dot3_30(a >> 1, b, (a ^ b) >> 1, b >> 1, a, b >> 3) !=
				    fixed_dot3_30_narrow(a >> 1, b, (a ^ b) >> 1, b >> 1, a, b >> 3))
				mismatches++;
			/* One reciprocal for many divisions: within an LSB of dividing (two past 2^30). */
			if (b != 0 && fixed_div(a, b) != FIXED_MAX && fixed_div(a, b) != -FIXED_MAX &&
			    fixed_abs(fixed_times_reciprocal(a, fixed_reciprocal_of(b)) - fixed_div(a, b)) >
				    1 + (fixed_abs(fixed_div(a, b)) >> 30))
				mismatches++;
			/* The reciprocal's product and shift, against 64-bit arithmetic. */
			if (b != 0) {
				fixed_reciprocal r = fixed_reciprocal_of(b);
				uint32_t m = a < 0 ? 0u - (uint32_t)a : (uint32_t)a;
				uint64_t p = ((uint64_t)m * r.scale + ((uint64_t)1 << (r.shift - 1))) >>
					     r.shift;
				int32_t expect = p > INT32_MAX ? INT32_MAX : (int32_t)p;
				if (fixed_times_reciprocal(a, r) != ((a < 0) != (b < 0) ? -expect : expect))
					mismatches++;
			}
			/* Division rounds to nearest, halves away from zero. */
			if (b != 0 && fixed_div(a, b) != fixed_saturate(reference_round_div(a, b)))
				mismatches++;
		}
	}
	CHECK_INT(mismatches, 0);
	CHECK_INT(checked, 6400);
	{
		/* Quotients of every size (the 16- and 32-step paths) and remainders from 0 to
		 * d - 1: n = q d + r, which the division must give back. */
		int wrong = 0;
		for (i = 0; i < 100000; i++) {
			uint32_t d = test_random_bits() >> (test_random_bits() % 32u);
			uint32_t q = test_random_bits() >> (test_random_bits() % 32u), r;
			d = d ? d : 1u;
			r = i % 3 == 0 ? 0u : i % 3 == 1 ? d - 1 : test_random_bits() % d;
			if (fixed_udiv_narrow((uint64_t)q * d + r, d) != q ||
			    fixed_udiv((uint64_t)q * d + r, d) != q)
				wrong++;
		}
		CHECK_INT(wrong, 0);
	}
	/* Division's saturation and rounding edges. */
	CHECK_INT(fixed_udiv_narrow((uint64_t)1 << 32, 1), UINT32_MAX);
	CHECK_INT(fixed_udiv_narrow(((uint64_t)1 << 32) - 1, 1), UINT32_MAX);
	CHECK_INT(fixed_udiv_narrow(UINT64_MAX, UINT32_MAX), UINT32_MAX);
	CHECK_INT(fixed_udiv_narrow(UINT64_MAX - 1, UINT32_MAX), UINT32_MAX);
	CHECK_INT(fixed_udiv_narrow(7, 2), 3);
	/* Rounding a Q32.32 sum to Q16.16 saturates at +-INT32_MAX, never INT32_MIN. */
	CHECK_INT(fixed_dot3_narrow(INT32_MIN, 0, 0, 65536, 0, 0), -INT32_MAX);
	CHECK_INT(fixed_dot3_narrow(INT32_MIN + 1, 0, 0, 65536, 0, 0), -INT32_MAX);
	CHECK_INT(fixed_dot3_narrow(INT32_MAX, 0, 0, 65536, 0, 0), INT32_MAX);
	CHECK_INT(fixed_mul30_narrow(INT32_MIN, INT32_MIN), INT32_MAX);
	CHECK_INT(fixed_mul30_narrow(INT32_MIN, 1 << 30), -INT32_MAX);
	CHECK_INT(fixed_mul30_narrow(-1, 1 << 29), 0); /* -0.5 LSB rounds towards +infinity */
	CHECK_INT(fixed_mul30_narrow(-1, (1 << 29) + 1), -1);
	CHECK_INT(fixed_dot3_30_narrow(INT32_MAX, INT32_MAX, 0, 1 << 30, 1 << 30, 0), INT32_MAX);
	CHECK_INT(fixed_mul_narrow(-65536, 65535), -65535);
	CHECK_INT(fixed_mul_narrow(-1, 32768), 0);  /* -0.5 LSB rounds towards +infinity */
	CHECK_INT(fixed_mul_narrow(-1, 32769), -1);
	CHECK_INT(fixed_mul_narrow(INT32_MAX, INT32_MAX), INT32_MAX);
	CHECK_INT(fixed_mul_narrow(INT32_MAX, -INT32_MAX), -INT32_MAX);
	CHECK_INT(fixed_div(Q(1.0), -Q(3.0)), -21845);
	CHECK_INT(fixed_div(3, 2 * 65536), 2); /* 1.5 LSB rounds away from zero */
	CHECK_INT(fixed_div(-3, 2 * 65536), -2);
	CHECK_INT(fixed_div(1, -65536), -1); /* a negative divisor rounds the same way */
	CHECK_INT(fixed_div(3, -2 * 65536), -2);
	/* scale2: w times a small factor, exactly, and saturation past 2^63. */
	CHECK_INT(fixed_scale2((int64_t)3 << 40, Q(0.5)), (int64_t)3 << 39);
	CHECK_INT(fixed_scale2(-((int64_t)3 << 40), Q(0.5)), -((int64_t)3 << 39));
	CHECK_INT(fixed_scale2((int64_t)1 << 62, Q(4.0)), INT64_MAX);
	CHECK_INT(fixed_scale2(((int64_t)5 << 50) + 12345, 7), (((int64_t)5 << 50) + 12345) / 65536 * 7);
}

/* The integer kernels alone, which tests/mcu/kernels.c also runs on the microcontroller
 * (where fixed.h's assembly forms are the ones compiled). */
void suite_fixed_kernels(void)
{
	test_narrow_kernels();
	test_products();
}

void suite_fixed(void)
{
	suite_fixed_kernels();
	test_roots();
	test_exp_pow_tan();
	test_parsing();
}
