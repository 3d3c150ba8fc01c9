/* image.c - sRGB encoding and PPM headers.
 * Colours are linear while tracing; each channel is clamped to [0, 1] and encoded with
 * the sRGB transfer curve, the usual meaning of PPM samples in practice. Scene colours
 * come in as sRGB and are decoded once at load, so `b 0.5 0.5 0.5` shows as 50% grey.
 * See LICENSE for copyright and licence. */
#include "image.h"

#include "config.h"

#include <stdio.h>

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

vec3 image_srgb_to_linear(vec3 srgb)
{
	return vec_make(decode_channel(srgb.x), decode_channel(srgb.y), decode_channel(srgb.z));
}

/* Linear value at which each 8-bit code starts: decode((code - 0.5) / 255), computed once
 * in the build's own type, so that code -> linear -> code returns the same code; and for
 * each j < 256 the largest code whose threshold is at most j / 256 (the thresholds times
 * 256 are exact in every type). Encoding then starts from the code of linear's 1/256
 * and steps up, without a power per pixel: a few steps, but near black, where the curve
 * is steep (up to 13 codes in the first 1/256). */
#define SRGB_STEPS 256 /* buckets of linear values in [0, 1) */
static real srgb_thresholds[256];
static unsigned char srgb_start[SRGB_STEPS];
static int thresholds_ready;

static void init_thresholds(void)
{
	int code, j;
	srgb_thresholds[0] = REAL_C(0.0);
	for (code = 1; code < 256; code++)
		srgb_thresholds[code] =
			decode_channel(real_div(real_from_int(code) - REAL_C(0.5), REAL_C(255.0)));
	for (j = 0, code = 0; j < SRGB_STEPS; j++) {
		while (code < 255 && srgb_thresholds[code + 1] * SRGB_STEPS <= real_from_int(j))
			code++;
		srgb_start[j] = (unsigned char)code;
	}
	thresholds_ready = 1;
}

unsigned char image_srgb_byte(real linear)
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

void image_encode_row(const vec3 *colors, int count, unsigned char *bytes)
{
	int i;
	for (i = 0; i < count; i++) {
		bytes[3 * i + 0] = image_srgb_byte(colors[i].x);
		bytes[3 * i + 1] = image_srgb_byte(colors[i].y);
		bytes[3 * i + 2] = image_srgb_byte(colors[i].z);
	}
}

/* The header of a binary PPM (P6) or PGM (P5) with samples up to maxval: one format for
 * both sinks. */
static int write_pnm_header(write_fn write, void *ctx, int magic, int width, int height,
			    long maxval)
{
	char header[64];
	int n = snprintf(header, sizeof header, "P%d\n%d %d\n%ld\n", magic, width, height,
			 maxval);
	return n > 0 && write(ctx, header, (size_t)n);
}

int ppm_write_header(write_fn write, void *ctx, int width, int height)
{
	return write_pnm_header(write, ctx, 6, width, height, 255);
}

static int ids_row(sink *self, const vec3 *colors, const int *ids);

/* Both sinks begin alike: the width for the rows, then the header, a PGM of 16-bit IDs
 * for the ID sink (the one whose rows are ids_row), else a PPM. */
static int pnm_begin(sink *self, int width, int height)
{
	int ids = self->row == ids_row;
	((ppm_sink *)self)->width = width;
	return write_pnm_header(self->write, self->ctx, ids ? 5 : 6, width, height,
				ids ? 65535 : 255);
}

static int ppm_row(sink *self, const vec3 *colors, const int *ids)
{
	static unsigned char bytes[3 * RT_MAX_WIDTH];
	ppm_sink *p = (ppm_sink *)self;
	(void)ids;
	image_encode_row(colors, p->width, bytes);
	return self->write(self->ctx, bytes, (size_t)p->width * 3);
}

static int ppm_end(sink *self)
{
	(void)self;
	return 1;
}

void ppm_sink_init(ppm_sink *p, write_fn write, void *ctx)
{
	sink_init(&p->base, pnm_begin, ppm_row, ppm_end, write, ctx);
	p->width = 0;
}

static int ids_row(sink *self, const vec3 *colors, const int *ids)
{
	static unsigned char bytes[2 * RT_MAX_WIDTH];
	ids_sink *p = (ids_sink *)self;
	int x;
	(void)colors;
	for (x = 0; x < p->width; x++) {
		unsigned value = ids[x] < 0 ? 0u : (unsigned)ids[x] + 1u;
		bytes[2 * x] = (unsigned char)(value >> 8);
		bytes[2 * x + 1] = (unsigned char)(value & 0xFF);
	}
	return self->write(self->ctx, bytes, (size_t)p->width * 2);
}

void ids_sink_init(ids_sink *p, write_fn write, void *ctx)
{
	ppm_sink_init(p, write, ctx);
	p->base.row = ids_row;
}
