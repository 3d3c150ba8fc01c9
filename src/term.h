/* term.h - what rt asks of the terminal: is it one, how wide, which colours, and the
 * progress bar it draws on standard error. See LICENSE for copyright and licence. */
#ifndef RT_TERM_H
#define RT_TERM_H

#include <signal.h>

#include "preview.h"
#include "trace.h"

/* Is file descriptor fd a terminal? */
int term_is_tty(int fd);

/* Columns for a preview on standard output: its terminal's width, else $COLUMNS, else 80. */
int term_columns(void);

/* Lines of the terminal standard output shows: its height, else $LINES, else 0 (no
 * bound known). */
int term_lines(void);

/* Is TERM dumb (a terminal that takes no escape sequences: no colour, no progress bar)? */
int term_is_dumb(void);

/* The colour preview here: 24-bit when COLORTERM says truecolor or 24bit, else 256
 * colours. Unless the colours were asked for (asked = 1: --ansi, -o FILE.ans), plain
 * ASCII when NO_COLOR is set and non-empty or TERM is dumb. */
enum preview_mode term_color_mode(int asked);

/* Progress on standard error: shown only when it is a terminal and the render looks like
 * taking more than about a second; redrawn at most ten times a second, erased at the end. */
#define PROGRESS_WINDOW 16 /* recent samples (a few seconds) the rates are taken over */

typedef struct {
	int enabled;
	unsigned long long start, last_draw; /* microseconds */
	const trace_stats *stats; /* live ray counts, for rays/s */
	/* The bar is on the screen: a signal or the time limit erases it (output.c). */
	volatile sig_atomic_t drawn;
	/* Recent samples, oldest first once full: when, rows done, rays traced. The time
	 * left and the rays per second come from the oldest kept and now, so that they
	 * follow the rows being traced, not the render's average. */
	unsigned long long when[PROGRESS_WINDOW], rays[PROGRESS_WINDOW];
	int rows[PROGRESS_WINDOW];
	int samples, next;
} progress_bar;

void progress_start(progress_bar *p, int enabled, const trace_stats *stats);
void progress_update(void *ctx, int done, int total); /* a progress_fn; ctx is the bar */
void progress_finish(progress_bar *p);

/* Microseconds on a monotonic clock (integers: the fixed-point build has no floats). */
unsigned long long term_micros(void);

#endif
