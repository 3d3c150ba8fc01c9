/* parse.h - the scene language: NFF read unchanged, plus rt's documented extensions.
 * One pass over a scene's text; loading it (the passes fixed point needs, the sources,
 * the checks that the number type can hold it) is load.h's.
 * See LICENSE for copyright and licence. */
#ifndef RT_PARSE_H
#define RT_PARSE_H

#include "lexer.h"
#include "scene.h"

/* Parses a whole scene into s (scene_init is called first), reading its lengths times
 * 2^length_shift. Errors and warnings go through diag as `rt: FILE:LINE: ...`, with
 * `file` as FILE. Returns 1 on success. */
int parse_scene_at(scene *s, const char *file, read_fn read, void *ctx, int length_shift);

#if RT_READ_BUFFER
/* parse_scene_at reading the scene a block at a time (lexer_read_blocks). */
int parse_scene_blocks(scene *s, const char *file, read_block_fn read_block, void *ctx,
		       int length_shift);
#endif

/* The same at scale 1 (every length as written). */
int parse_scene(scene *s, const char *file, read_fn read, void *ctx);

#endif
