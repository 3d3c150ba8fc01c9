/* test_image.c - from linear colour to bytes: the sRGB curve both ways, row encoding and
 * the PPM header, checked against the IEC 61966-2-1 formula.
 * See LICENSE for copyright and licence. */
#include <string.h>

#include "colour.h"
#include "image.h"
#include "test.h"

/* The sRGB encoding, straight from its definition, in double: the reference. */
static double srgb_encode(double linear)
{
	return linear <= 0.0031308 ? 12.92 * linear : 1.055 * pow(linear, 1 / 2.4) - 0.055;
}

static void test_byte_ends(void)
{
	CHECK_INT(colour_byte(REAL_C(0.0)), 0);
	CHECK_INT(colour_byte(REAL_C(1.0)), 255);
	CHECK_INT(colour_byte(-REAL_C(0.0)), 0);
	/* Out of range clamps; NaN must not become a bright pixel (Q16.16 has none). */
#if !REAL_FIXED
	CHECK_INT(colour_byte((real)NAN), 0);
	CHECK_INT(colour_byte(-(real)NAN), 0);
#endif
	CHECK_INT(colour_byte(REAL_C(-0.5)), 0);
	CHECK_INT(colour_byte(-REAL_MAX), 0);
	CHECK_INT(colour_byte(REAL_C(1.5)), 255);
	CHECK_INT(colour_byte(REAL_MAX), 255);
#if !REAL_FIXED
	CHECK_INT(colour_byte((real)INFINITY), 255);
	CHECK_INT(colour_byte(-(real)INFINITY), 0);
#endif
	/* Below half a code: still black. */
	CHECK_INT(colour_byte(REAL_C(1e-30)), 0);
	CHECK_INT(colour_byte(REAL_C(0.0001)), 0);
}

static void test_byte_formula(void)
{
	/* Points at least 0.01 code away from a rounding boundary; the codes are the
	 * formula's, rounded to nearest. */
	static const struct {
		double linear;
		int code;
	} table[] = {
		{0.0002, 1},   {0.001, 3},   {0.0031308, 10}, {0.004, 13}, {0.01, 25},
		{0.05, 63},    {0.1, 89},    {0.18, 118},     {0.214, 127}, {0.25, 137},
		{0.5, 188},    {0.75, 225},  {0.9, 243},      {0.99, 254}, {0.999, 255},
	};
	size_t i;
	int bad = 0, checked = 0, n;
	for (i = 0; i < sizeof table / sizeof table[0]; i++) {
		CHECK_INT(colour_byte(test_real(table[i].linear)), table[i].code);
		/* The table itself agrees with the reference. */
		CHECK_INT((int)floor(255 * srgb_encode(table[i].linear) + 0.5), table[i].code);
	}
	/* 0.214 is about 50% grey: 127.49 codes. */
	CHECK(colour_byte(REAL_C(0.214)) >= 127 && colour_byte(REAL_C(0.214)) <= 128);

	/* A dense sweep (quadratic, so the steep dark end is sampled finely): every point
	 * not within 1e-4 code of a boundary rounds exactly as the formula does. Q16.16:
	 * each code's threshold is decoded in Q16.16 and good to an LSB, which is 0.05 code
	 * (12.92 x 255 LSB) where the curve is steepest: 0.06 code from a boundary. */
	for (n = 0; n <= 20000; n++) {
		double x = (double)n / 20000, v;
		x *= x;
		v = 255 * srgb_encode(test_double(test_real(x)));
		if (fabs(v - floor(v) - 0.5) < TOL3(1e-4, 1e-4, 0.06))
			continue;
		checked++;
		if (colour_byte(test_real(x)) != (int)floor(v + 0.5) && bad++ == 0)
			printf("%s:%d: colour_byte(%.17g): expected %d (the formula), got %d\n",
			       __FILE__, __LINE__, x, (int)floor(v + 0.5),
			       colour_byte(test_real(x)));
	}
	CHECK_INT(bad, 0);
	/* Q16.16 skips 12 % of the points (0.12 of each code). */
	CHECK(checked > TOL3(19000, 19000, 17000));
}

static void test_byte_monotonic(void)
{
	int n, previous = 0, seen[256], distinct = 0, decreases = 0;
	memset(seen, 0, sizeof seen);
	/* Non-decreasing from below 0 to above 1, and every code is reached. */
	for (n = -100; n <= 110000; n++) {
		double x = (double)n / 100000;
		int code = colour_byte(test_real(x * fabs(x)));
		if (code < previous && decreases++ == 0)
			printf("%s:%d: colour_byte(%.17g): expected at least %d (a smaller "
			       "value's), got %d\n",
			       __FILE__, __LINE__, x * fabs(x), previous, code);
		previous = code;
		if (!seen[code]++)
			distinct++;
	}
	CHECK_INT(decreases, 0);
	CHECK_INT(previous, 255);
	CHECK_INT(distinct, 256);
}

static void test_to_linear(void)
{
	vec3 c = colour_srgb_to_linear(vec_make(REAL_C(0.0), REAL_C(0.5), REAL_C(1.0)));
	double eps = TOL3(1e-6, 1e-12, 1 * LSB); /* Q16.16: one rounding */
	CHECK_REAL(c.x, 0, 0);
	CHECK_REAL(c.y, 0.21404114048223255, eps);
	CHECK_REAL(c.z, 1, 0);
	/* The linear segment and the join of the two pieces. */
	c = colour_srgb_to_linear(vec_make(REAL_C(0.02), REAL_C(0.04045), REAL_C(0.8)));
	CHECK_REAL(c.x, 0.02 / 12.92, eps);
	CHECK_REAL(c.y, 0.0031308049535603713, eps);
	CHECK_REAL(c.z, 0.6038273388553378, eps);
	/* Negative clamps to black; brighter than white is kept as given, not clamped. */
	c = colour_srgb_to_linear(vec_make(REAL_C(-0.5), REAL_C(2.0), REAL_C(0.25)));
	CHECK_REAL(c.x, 0, 0);
	CHECK_REAL(c.y, 2, 0);
	CHECK_REAL(c.z, 0.05087608817155679, eps);
}

static void test_round_trip(void)
{
	/* A scene colour k/255 decodes and encodes back to code k, for every code: what a
	 * background or an unlit, fully diffuse surface shows. */
	int k;
	for (k = 0; k < 256; k++) {
		real v = real_div(real_from_int(k), REAL_C(255.0));
		vec3 c = colour_srgb_to_linear(vec_make(v, v, v));
		if (!CHECK_INT(colour_byte(c.x), k))
			break;
	}
	/* b 0.5 0.5 0.5 decodes to 0.214 and shows as code 128 (0.5 * 255 = 127.5 rounds up). */
	CHECK_INT(colour_byte(colour_srgb_to_linear(vec_make(REAL_C(0.5), REAL_C(0.5),
							       REAL_C(0.5))).y),
		  128);
}

static void test_encode_row(void)
{
	vec3 colors[3];
	unsigned char bytes[12];
	static const unsigned char expect[9] = {0, 255, 188, 89, 0, 255, 0, 25, 137};
	colors[0] = vec_make(REAL_C(0.0), REAL_C(1.0), REAL_C(0.5));
#if !REAL_FIXED
	colors[1] = vec_make(REAL_C(0.1), (real)NAN, REAL_C(7.0));
#else
	colors[1] = vec_make(REAL_C(0.1), REAL_C(-7.0), REAL_C(7.0)); /* no NaN: negative */
#endif
	colors[2] = vec_make(REAL_C(-1.0), REAL_C(0.01), REAL_C(0.25));
	memset(bytes, 0xA5, sizeof bytes);
	colour_encode_row(colors, 3, bytes);
	CHECK(memcmp(bytes, expect, 9) == 0);
	CHECK_INT(bytes[2], 188);
	CHECK_INT(bytes[4], 0);
	CHECK_INT(bytes[5], 255);
	/* Nothing past count * 3 bytes is touched. */
	CHECK_INT(bytes[9], 0xA5);
	CHECK_INT(bytes[11], 0xA5);
	memset(bytes, 0xA5, sizeof bytes);
	colour_encode_row(colors, 1, bytes);
	CHECK(memcmp(bytes, expect, 3) == 0);
	CHECK_INT(bytes[3], 0xA5);
	colour_encode_row(colors, 0, bytes);
	CHECK_INT(bytes[0], 0);
	CHECK_INT(bytes[3], 0xA5);
}

/* A write callback into memory, and one that always fails. */
typedef struct {
	unsigned char data[64];
	size_t used;
	int calls;
} byte_buffer;

static int write_sink(void *ctx, const void *data, size_t n)
{
	byte_buffer *s = ctx;
	s->calls++;
	if (n > sizeof s->data - s->used)
		return 0;
	memcpy(s->data + s->used, data, n);
	s->used += n;
	return 1;
}

static int write_fail(void *ctx, const void *data, size_t n)
{
	(void)data;
	(void)n;
	(*(int *)ctx)++;
	return 0;
}

static void test_ppm_header(void)
{
	byte_buffer s;
	int calls = 0;
	memset(&s, 0, sizeof s);
	CHECK_INT(ppm_write_header(write_sink, &s, 4, 3), 1);
	CHECK_INT(s.used, 11);
	CHECK(memcmp(s.data, "P6\n4 3\n255\n", 11) == 0);
	memset(&s, 0, sizeof s);
	CHECK_INT(ppm_write_header(write_sink, &s, 8192, 1), 1);
	CHECK_INT(s.used, 14);
	CHECK(memcmp(s.data, "P6\n8192 1\n255\n", 14) == 0);
	/* A failing writer is reported, not ignored. */
	CHECK_INT(ppm_write_header(write_fail, &calls, 4, 3), 0);
	CHECK(calls >= 1);
}

void suite_image(void)
{
	test_byte_ends();
	test_byte_formula();
	test_byte_monotonic();
	test_to_linear();
	test_round_trip();
	test_encode_row();
	test_ppm_header();
}
