/* load.h - loading a scene: from a file, a buffer or any source that can be read again,
 * in the passes the number type needs, refused when the type cannot hold it.
 * See LICENSE for copyright and licence. */
#ifndef RT_LOAD_H
#define RT_LOAD_H

#include <stddef.h>

#include "lexer.h"
#include "scene.h"

/* A scene that can be read from its start more than once (fixed point reads it twice:
 * once to measure it, once at the scale that fits). open starts a pass and close ends
 * it; each reports its own failure through diag (naming the file) and returns 0. close
 * is told whether parsing went well and checks for a read error. */
typedef struct {
	/* again: another pass may read the source from its start after this one (an input
	 * that cannot be reopened must then be kept). */
	int (*open)(void *ctx, int again);
	read_fn read;
#if RT_READ_BUFFER
	read_block_fn read_block; /* if not NULL, used instead of read */
#endif
	int (*close)(void *ctx, int ok);
	void *ctx;
} scene_source;

/* Loads the scene from `source`: in fixed point it is read first to measure it, then
 * at the scale that fits it, and refused when the number type cannot hold it. Returns 1
 * on success; errors go through diag. */
int load_scene_source(scene *s, const char *name, const scene_source *source);

/* The same for a scene file; an unreadable file is an error too. Defined by the
 * platform's I/O layer (stdio on a host, semihosting on a microcontroller). */
int load_scene_file(scene *s, const char *path);

/* The same for a scene held in memory. */
int load_scene_buffer(scene *s, const char *name, const void *data, size_t size);

#endif
