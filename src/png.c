/* png.c - the PNG sink: signature, header and sRGB chunk at begin; each row encoded,
 * filtered and fed to a zlib stream whose bytes leave in IDAT chunks of 64 KiB as they
 * come; the stream's end and IEND at the end. No frame buffer: the memory is two rows
 * and the stream's, whatever the image's size.
 * See LICENSE for copyright and licence. */
#include "png.h"

#include <string.h>

#include "colour.h"

/* Large: static, once (one PNG is written at a time). */
static deflate_stream the_stream;

/* The row above (PNG's filters predict from it; zeros above the first), the row being
 * written, and the filtered row with its filter type first. */
static unsigned char above[3 * RT_MAX_WIDTH], current[3 * RT_MAX_WIDTH];
static unsigned char filtered[5][1 + 3 * RT_MAX_WIDTH];

static void put_u32(unsigned char *p, uint32_t v)
{
	p[0] = (unsigned char)(v >> 24);
	p[1] = (unsigned char)(v >> 16);
	p[2] = (unsigned char)(v >> 8);
	p[3] = (unsigned char)v;
}

/* Writes one chunk: length, type, data, CRC of type and data. */
static int write_chunk(sink *out, const char *type, const unsigned char *data, size_t n)
{
	unsigned char head[8], tail[4];
	uint32_t crc = deflate_crc32(0, (const unsigned char *)type, 4);
	crc = deflate_crc32(crc, data, n);
	put_u32(head, (uint32_t)n);
	memcpy(head + 4, type, 4);
	put_u32(tail, crc);
	return out->write(out->ctx, head, 8) && (n == 0 || out->write(out->ctx, data, n)) &&
	       out->write(out->ctx, tail, 4);
}

/* The zlib stream's bytes, each batch an IDAT chunk. */
static int write_idat(void *ctx, const unsigned char *data, size_t n)
{
	return write_chunk(ctx, "IDAT", data, n);
}

static int png_begin(sink *self, int width, int height)
{
	static const unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
	static const unsigned char srgb[1] = {0}; /* rendering intent: perceptual */
	unsigned char header[13];
	png_sink *p = (png_sink *)self;
	if (width < 1 || width > RT_MAX_WIDTH || height < 1)
		return 0;
	p->width = width;
	p->rows = 0;
	p->stream = &the_stream;
	memset(above, 0, 3 * (size_t)width);
	put_u32(header, (uint32_t)width);
	put_u32(header + 4, (uint32_t)height);
	header[8] = 8;  /* bits a sample */
	header[9] = 2;  /* RGB */
	header[10] = 0; /* deflate */
	header[11] = 0; /* adaptive filters */
	header[12] = 0; /* not interlaced */
	deflate_start(p->stream, write_idat, self);
	return self->write(self->ctx, signature, sizeof signature) &&
	       write_chunk(self, "IHDR", header, sizeof header) && write_chunk(self, "sRGB", srgb, 1);
}

/* PNG's Paeth predictor: of left, up and upper left, the nearest to left + up - upper left. */
static int paeth(int a, int b, int c)
{
	int p = a + b - c, pa = p > a ? p - a : a - p, pb = p > b ? p - b : b - p,
	    pc = p > c ? p - c : c - p;
	return pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
}

/* The row filtered by each of PNG's filters; returns the one whose bytes, read as signed,
 * sum smallest in magnitude. */
static int filter_row(int bytes)
{
	long cost[5] = {0, 0, 0, 0, 0};
	int i, f, best = 0;
	for (f = 0; f < 5; f++)
		filtered[f][0] = (unsigned char)f;
	for (i = 0; i < bytes; i++) {
		int x = current[i], a = i >= 3 ? current[i - 3] : 0, b = above[i],
		    c = i >= 3 ? above[i - 3] : 0;
		unsigned char v[5];
		v[0] = (unsigned char)x;
		v[1] = (unsigned char)(x - a);
		v[2] = (unsigned char)(x - b);
		v[3] = (unsigned char)(x - (a + b) / 2);
		v[4] = (unsigned char)(x - paeth(a, b, c));
		for (f = 0; f < 5; f++) {
			filtered[f][1 + i] = v[f];
			cost[f] += v[f] < 128 ? v[f] : 256 - v[f];
		}
	}
	for (f = 1; f < 5; f++)
		if (cost[f] < cost[best])
			best = f;
	return best;
}

static int png_row(sink *self, const vec3 *colors, const int *ids)
{
	png_sink *p = (png_sink *)self;
	int bytes = 3 * p->width, f;
	(void)ids;
	colour_encode_row(colors, p->width, current);
	f = filter_row(bytes);
	memcpy(above, current, (size_t)bytes);
	p->rows++;
	return deflate_feed(p->stream, filtered[f], (size_t)bytes + 1);
}

static int png_end(sink *self)
{
	png_sink *p = (png_sink *)self;
	return deflate_finish(p->stream) && write_chunk(self, "IEND", NULL, 0);
}

void png_sink_init(png_sink *p, write_fn write, void *ctx)
{
	sink_init(&p->base, png_begin, png_row, png_end, write, ctx);
	p->width = p->rows = 0;
	p->stream = NULL;
}
