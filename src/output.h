/* output.h - where the image goes: standard output, or a file replaced only on success.
 * See LICENSE for copyright and licence. */
#ifndef RT_OUTPUT_H
#define RT_OUTPUT_H

#include <stddef.h>
#include <stdio.h>

/* With a path, the image is written to a temporary file beside it and renamed over it
 * only when everything succeeded, so a failed run (or one stopped by a signal) never
 * leaves a half-written image or touches an existing file. */
typedef struct {
	FILE *file;
	const char *path; /* NULL for standard output */
	int is_temp;
} output;

/* Opens the output; reports and returns 0 on failure. */
int output_open(output *out, const char *path);

/* Finishes it: flushes and, when ok, renames the temporary file into place; otherwise
 * removes it. Reports a failure and returns 0. */
int output_close(output *out, int ok);

/* A write callback for the sinks: ctx is the output. */
int output_write(void *ctx, const void *data, size_t n);

#endif
