/* image.c - the PPM and object-ID sinks: binary PPM and PGM headers, then each row as
 * it is done (colours encoded by colour.c).
 * See LICENSE for copyright and licence. */
#include "image.h"

#include "colour.h"
#include "config.h"

#include <stdio.h>

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
	/* 16-bit IDs, unless the scene has more objects (builds whose capacity allows it). */
	int ids = self->row == ids_row && !(RT_MAX_OBJECTS > 65534 && ((ppm_sink *)self)->wide);
	((ppm_sink *)self)->width = width;
	return write_pnm_header(self->write, self->ctx, ids ? 5 : 6, width, height,
				ids ? 65535 : 255);
}

static int ppm_row(sink *self, const vec3 *colors, const int *ids)
{
	static unsigned char bytes[3 * RT_MAX_WIDTH];
	ppm_sink *p = (ppm_sink *)self;
	(void)ids;
	colour_encode_row(colors, p->width, bytes);
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
	static unsigned char bytes[3 * RT_MAX_WIDTH];
	ids_sink *p = (ids_sink *)self;
	int x;
	(void)colors;
	if (RT_MAX_OBJECTS > 65534 && p->wide) {
		for (x = 0; x < p->width; x++) {
			unsigned value = ids[x] < 0 ? 0u : (unsigned)ids[x] + 1u; /* below 2^24 */
			bytes[3 * x] = (unsigned char)(value >> 16);
			bytes[3 * x + 1] = (unsigned char)(value >> 8 & 0xFF);
			bytes[3 * x + 2] = (unsigned char)(value & 0xFF);
		}
		return self->write(self->ctx, bytes, (size_t)p->width * 3);
	}
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
