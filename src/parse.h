/* parse.h - the scene language: NFF read unchanged, plus rt's documented extensions.
 * See LICENSE for copyright and licence. */
#ifndef RT_PARSE_H
#define RT_PARSE_H

#include <stddef.h>

#include "scene.h"

/* Returns the next byte of the input, or -1 at its end. */
typedef int (*read_fn)(void *ctx);

/* Parses a whole scene into s (scene_init is called first). Errors and warnings go
 * through diag as `rt: FILE:LINE: ...`, with s->file as FILE. Returns 1 on success. */
int parse_scene(scene *s, const char *file, read_fn read, void *ctx);

/* A scene that can be read from its start more than once (fixed point reads it twice:
 * once to measure it, once at the scale that fits). open starts a pass and close ends
 * it; each reports its own failure through diag (naming the file) and returns 0. close
 * is told whether parsing went well and checks for a read error. */
typedef struct {
	/* again: another pass may read the source from its start after this one (an input
	 * that cannot be reopened must then be kept). */
	int (*open)(void *ctx, int again);
	read_fn read;
	int (*close)(void *ctx, int ok);
	void *ctx;
} scene_source;

/* Parses the scene from `source`: in fixed point it is read first to measure it, then
 * at the scale that fits it, and refused when the number type cannot hold it. */
int parse_scene_source(scene *s, const char *name, const scene_source *source);

/* The same for a scene file; an unreadable file is an error too. Defined by the
 * platform's I/O layer (stdio on a host, semihosting on a microcontroller). */
int parse_scene_file(scene *s, const char *path);

/* The same for a scene held in memory. */
int parse_scene_buffer(scene *s, const char *name, const void *data, size_t size);

/* The position of `word` in `names`, a string of names each ended by its NUL and the
 * list by an empty name; the number of names if it is not there. Scene commands and the
 * microcontroller's options are found this way (one loop: less flash than a chain of
 * comparisons). */
int parse_keyword(const char *names, const char *word);

/* Reads the decimal digits at the start of `text` into *out and returns the first byte
 * after them (`text` itself when there are none). A value past `max` is held above it,
 * not read on: `max` up to LONG_MAX / 10 - 1 (the capacities are far below). The scene's
 * counts and the microcontroller's option values are read this way. */
const char *parse_digits(const char *text, long max, long *out);

#endif
