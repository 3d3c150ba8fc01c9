/* output.h - where the image goes: standard output, a stream, or a file replaced only when
 * the whole image is written (output.c gives the rules, as README and rt.1 do).
 * See LICENSE for copyright and licence. */
#ifndef RT_OUTPUT_H
#define RT_OUTPUT_H

#include <signal.h>
#include <stddef.h>
#include <stdio.h>

enum output_mode {
	OUTPUT_STREAM, /* standard output, a FIFO, a terminal, a device: written straight */
	OUTPUT_RENAME, /* a temporary file beside the target, renamed over it at the end */
	OUTPUT_COPY    /* a temporary file elsewhere, copied into the target at the end */
};

typedef struct {
	FILE *file;
	const char *path;  /* as given; NULL for standard output */
	char target[4096]; /* the file replaced: path after its symbolic links */
	enum output_mode mode;
} output;

/* Opens the output; reports and returns 0 on failure (nothing is touched then). */
int output_open(output *out, const char *path);

/* Finishes it: flushes and, when ok, puts the image in place; otherwise removes the
 * temporary file and leaves the target as it was. Reports a failure and returns 0. */
int output_close(output *out, int ok);

/* Reports a write error (errno's) on the output, naming the file or standard output. */
void output_report_error(const output *out);

/* --time-limit: arms a wall-clock timer of `micros` that ends the run, from wherever it
 * is (reading, building, tracing a pixel), with `rt: SCENE: the time limit of AS_GIVEN
 * seconds was reached; no image written` and exit status 1, the temporary file removed.
 * Rows already streamed to standard output or a FIFO stay there, and the message says
 * the image is incomplete. 0, reported, if the timer cannot be set. */
int output_time_limit(const char *scene, unsigned long long micros, const char *as_given);

/* While *line_drawn is set, a signal that ends the run, or the time limit, first erases
 * the line standard error's cursor is on (the progress bar's). */
void output_erase_on_end(const volatile sig_atomic_t *line_drawn);

/* A function that a signal ending the run, or the time limit, calls first (it must be
 * async-signal-safe): workers_stop (workers.c), which stops -j's workers. NULL for none. */
void output_on_end(void (*stop)(void));

/* In a forked worker: the parent's signal handlers (put back as they were before rt),
 * temporary file and status line are not its own. */
void output_forget(void);

/* A write callback for the sinks: ctx is the output. */
int output_write(void *ctx, const void *data, size_t n);

#endif
