/* image.h - the PPM writer and the object-ID (PGM) writer.
 * Writers take a callback (stb's *_to_func style) so tests capture bytes in memory.
 * See LICENSE for copyright and licence. */
#ifndef RT_IMAGE_H
#define RT_IMAGE_H

#include <stddef.h>

#include "sink.h"
#include "vec.h"

/* Binary PPM: P6, maxval 255, then the rows. */
int ppm_write_header(write_fn write, void *ctx, int width, int height);

/* The PPM sink: header at begin, then each row as RGB bytes as soon as it is done. */
typedef struct {
	sink base;
	int width;
	int wide; /* the ID sink only: 24-bit IDs in a PPM (set after ids_sink_init) */
} ppm_sink;

void ppm_sink_init(ppm_sink *p, write_fn write, void *ctx);

/* The object-ID sink (--ids): a 16-bit binary PGM (P5, maxval 65535, big-endian samples)
 * whose pixel is 1 + the index of the object the pixel's eye ray hit first, in scene
 * order, and 0 where it hit nothing. For counting pixels that hit the wrong object. With
 * `wide` set (scenes of 65,535 objects and more, where builds hold them), a binary PPM
 * (P6, maxval 255) whose three samples are that number's bytes, highest first: 24 bits. */
typedef ppm_sink ids_sink;

void ids_sink_init(ids_sink *p, write_fn write, void *ctx);

#endif
