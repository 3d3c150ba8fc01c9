/* colour.c - the colour pipeline (colour.h), both ways.
 * Colours are linear while tracing; each channel is clamped to [0, 1] and encoded with
 * the sRGB transfer curve, the usual meaning of PPM samples in practice. Scene colours
 * come in as sRGB and are decoded once at load, so `b 0.5 0.5 0.5` shows as 50% grey.
 * The classic pipeline has no curve either way: one table (the codes' thresholds) serves
 * both, made from whichever curve is chosen.
 * See LICENSE for copyright and licence. */
#include "colour.h"

#include "config.h"

/* sRGB's transfer curve, linear light from an encoded value in [0, 1]. */
static real decode_channel(real v)
{
	if (v <= REAL_C(0.0))
		return REAL_C(0.0);
	if (v >= REAL_C(1.0))
		return v;
	if (v <= REAL_C(0.04045))
		return real_div(v, REAL_C(12.92));
	return real_pow(real_div(v + REAL_C(0.055), REAL_C(1.055)), REAL_C(2.4));
}

vec3 colour_srgb_to_linear(vec3 srgb)
{
	return vec_make(decode_channel(srgb.x), decode_channel(srgb.y), decode_channel(srgb.z));
}

static enum colour_pipeline pipeline;
static int chosen_on_command_line;

void colour_choose(enum colour_pipeline p, int from_scene)
{
	if (from_scene && chosen_on_command_line)
		return;
	pipeline = p;
	chosen_on_command_line = !from_scene;
}

/* The chosen curve: sRGB's, or none. */
static real scene_channel(real v)
{
	if (RT_COLOUR_PIPELINES && pipeline == COLOUR_CLASSIC)
		return v;
	return decode_channel(v);
}

vec3 colour_scene_to_linear(vec3 colour)
{
	return vec_make(scene_channel(colour.x), scene_channel(colour.y), scene_channel(colour.z));
}

/* Linear value at which each 8-bit code starts: decode((code - 0.5) / 255), computed once
 * in the build's own type, so that code -> linear -> code returns the same code; and for
 * each j < SRGB_STEPS the largest code whose threshold is at most j / SRGB_STEPS (the
 * thresholds times a power of two are exact in every type). Encoding then starts from
 * the code of linear's bucket and steps up, without a power per pixel: a step or two with
 * the host's 4,096 buckets; the MCU's 256 save RAM and take more steps near black, where
 * the curve is steep (up to 13 codes in the first 1/256). */
#define SRGB_STEPS RT_COLOUR_STEPS /* buckets of linear values in [0, 1) */
static real srgb_thresholds[256];
static unsigned char srgb_start[SRGB_STEPS];
static int thresholds_ready;

static void init_thresholds(void)
{
	int code, j;
	srgb_thresholds[0] = REAL_C(0.0);
	for (code = 1; code < 256; code++)
		srgb_thresholds[code] =
			scene_channel(real_div(real_from_int(code) - REAL_C(0.5), REAL_C(255.0)));
	for (j = 0, code = 0; j < SRGB_STEPS; j++) {
		while (code < 255 && srgb_thresholds[code + 1] * SRGB_STEPS <= real_from_int(j))
			code++;
		srgb_start[j] = (unsigned char)code;
	}
	thresholds_ready = 1;
}

unsigned char colour_byte(real linear)
{
	int code;
	if (!thresholds_ready)
		init_thresholds();
	/* NaN fails every comparison and lands on 0, as do negatives. */
	if (!(linear > REAL_C(0.0)))
		return 0;
	/* At 1 and above, past the last threshold (decode(254.5 / 255) < 1). */
	if (!(linear < REAL_C(1.0)))
		return 255;
	/* Largest code whose threshold is <= linear (the thresholds increase), from the
	 * largest one at or below linear's bucket. */
	code = srgb_start[real_to_int(linear * SRGB_STEPS)];
	while (code < 255 && srgb_thresholds[code + 1] <= linear)
		code++;
	return (unsigned char)code;
}

void colour_encode_row(const vec3 *colors, int count, unsigned char *bytes)
{
	int i;
	for (i = 0; i < count; i++) {
		/* A pixel of its left neighbour's colour (the background, flat areas) takes
		 * its codes: equal values encode alike (0 and -0 too; NaN equals nothing). */
		if (RT_COLOUR_REPEATS && i > 0 && colors[i].x == colors[i - 1].x &&
		    colors[i].y == colors[i - 1].y && colors[i].z == colors[i - 1].z) {
			bytes[3 * i + 0] = bytes[3 * i - 3];
			bytes[3 * i + 1] = bytes[3 * i - 2];
			bytes[3 * i + 2] = bytes[3 * i - 1];
			continue;
		}
		bytes[3 * i + 0] = colour_byte(colors[i].x);
		bytes[3 * i + 1] = colour_byte(colors[i].y);
		bytes[3 * i + 2] = colour_byte(colors[i].z);
	}
}
