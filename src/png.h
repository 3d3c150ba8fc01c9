/* png.h - PNG output, streamed: each row is filtered and compressed as it arrives
 * (deflate.c), so an image of any size rendered is written in the same small, static
 * memory. See LICENSE for copyright and licence. */
#ifndef RT_PNG_H
#define RT_PNG_H

#include "deflate.h"
#include "sink.h"

/* 8-bit RGB, sRGB-encoded (an sRGB chunk says so), every row filtered by whichever of
 * PNG's five filters leaves the smallest sum of magnitudes (the usual heuristic). */
typedef struct {
	sink base;
	int width;
	int rows; /* rows written so far */
	/* Written in IDAT chunks as they fill. */
	deflate_stream *stream;
} png_sink;

void png_sink_init(png_sink *p, write_fn write, void *ctx);

#endif
