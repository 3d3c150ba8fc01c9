/* png.h - PNG output through the vendored stb_image_write, with no heap: its allocator
 * hooks draw from a fixed arena. See LICENSE for copyright and licence. */
#ifndef RT_PNG_H
#define RT_PNG_H

#include <stddef.h>

#include "image.h"

/* Encodes w x h RGB bytes as PNG through `write`, using the arena of `size` bytes at
 * `base` for all of the encoder's memory. Returns 1 on success, 0 when the arena runs
 * out, -1 when a write fails. */
int png_write(const unsigned char *rgb, int w, int h, write_fn write, void *ctx,
	      unsigned char *base, size_t size);

/* Arena bytes the last png_write used at most (for measuring png_arena_needed). */
size_t png_arena_peak(void);

/* Arena bytes needed for a w x h image in the worst case (incompressible pixels). */
size_t png_arena_needed(int w, int h);

#include "sink.h"

/* The PNG sink keeps the whole image (PNG compresses it at the end) in its arena, a
 * static RT_PNG_ARENA_BYTES; an image that cannot fit is refused at begin. */
typedef struct {
	sink base;
	int width, height, rows;
	unsigned char *rgb;
} png_sink;

void png_sink_init(png_sink *p, write_fn write, void *ctx);

/* Can a w x h image be written as PNG with the static arena? */
int png_fits(int w, int h);

/* Does this build write PNG at all? (The fixed-point build does not.) */
int png_available(void);

#endif
