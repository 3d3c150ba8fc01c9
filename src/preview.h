/* preview.h - the terminal preview: ASCII art or ANSI colour half-blocks, row by row.
 * Plain C, no terminal queries: the caller decides the mode and width.
 * See LICENSE for copyright and licence. */
#ifndef RT_PREVIEW_H
#define RT_PREVIEW_H

#include "sink.h"

enum preview_mode {
	PREVIEW_ASCII,    /* 7-bit characters by luminance, no escape sequences */
	PREVIEW_ANSI_256, /* half-blocks in the 256-colour palette */
	PREVIEW_ANSI_24   /* half-blocks in 24-bit colour */
};

/* A preview sink; each text line takes two image rows (upper and lower half of a cell). */
typedef struct {
	sink base;
	enum preview_mode mode;
	int width;
	int have_upper;           /* an upper row is waiting for its lower half */
	unsigned char upper[3 * RT_MAX_WIDTH];
} preview_sink;

void preview_sink_init(preview_sink *p, enum preview_mode mode, write_fn write, void *ctx);

/* Image size in pixels for a preview `columns` wide of a scene with the given aspect:
 * cells are about twice as tall as wide, and each cell holds two pixels, one above the
 * other, so pixels stay square. The height is even (whole cells). */
void preview_size(int columns, int scene_width, int scene_height, int *width, int *height);

/* The ASCII ramp, darkest first (exposed for the tests). */
extern const char preview_ramp[];

#endif
