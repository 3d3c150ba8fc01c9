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

/* Opens `path` and parses it; an unreadable file is an error too. Fixed point reads it
 * twice (to find the scene's scale) and refuses a scene it cannot hold. */
int parse_scene_file(scene *s, const char *path);

/* The same for a scene held in memory. */
int parse_scene_buffer(scene *s, const char *name, const void *data, size_t size);

#endif
