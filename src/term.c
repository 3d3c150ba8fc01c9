/* term.c - terminal queries (isatty, TIOCGWINSZ, colour variables) and the progress bar.
 * See LICENSE for copyright and licence. */
#define _POSIX_C_SOURCE 200809L
#define _DEFAULT_SOURCE /* TIOCGWINSZ */

#include "term.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <time.h>
#include <unistd.h>

int term_is_tty(int fd)
{
	return isatty(fd);
}

/* An environment variable that holds a whole number in 1..max, else 0. It comes from
 * outside: atoi would overflow on a long one, and a value past the capacity made the
 * preview fail with a misleading write error. */
static int env_count(const char *name, long max)
{
	const char *text = getenv(name);
	char *end;
	long n;
	if (!text)
		return 0;
	n = strtol(text, &end, 10);
	return end != text && *end == '\0' && n > 0 && n <= max ? (int)n : 0;
}

/* At most RT_MAX_WIDTH, the widest preview. */
int term_columns(void)
{
	struct winsize ws;
	int columns;
	if (isatty(1) && ioctl(1, TIOCGWINSZ, &ws) == 0 && ws.ws_col > 0)
		return ws.ws_col < RT_MAX_WIDTH ? ws.ws_col : RT_MAX_WIDTH;
	columns = env_count("COLUMNS", RT_MAX_WIDTH);
	return columns ? columns : 80;
}

int term_lines(void)
{
	struct winsize ws;
	if (isatty(1) && ioctl(1, TIOCGWINSZ, &ws) == 0 && ws.ws_row > 0)
		return ws.ws_row;
	return env_count("LINES", RT_MAX_HEIGHT);
}

int term_is_dumb(void)
{
	const char *term = getenv("TERM");
	return term && strcmp(term, "dumb") == 0;
}

enum preview_mode term_color_mode(int asked)
{
	const char *no_color = getenv("NO_COLOR"), *colorterm = getenv("COLORTERM");
	/* A colour asked for on the command line wins over NO_COLOR (no-color.org) and over
	 * TERM; the preview rt chooses itself for a terminal honours both. */
	if (!asked && ((no_color && *no_color) || term_is_dumb()))
		return PREVIEW_ASCII;
	if (colorterm && (strcmp(colorterm, "truecolor") == 0 || strcmp(colorterm, "24bit") == 0))
		return PREVIEW_ANSI_24;
	return PREVIEW_ANSI_256;
}

unsigned long long term_micros(void)
{
	struct timespec ts;
	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (unsigned long long)ts.tv_sec * 1000000u + (unsigned long long)ts.tv_nsec / 1000u;
}

void progress_start(progress_bar *p, int enabled, const trace_stats *stats)
{
	p->enabled = enabled;
	p->start = term_micros();
	p->last_draw = 0;
	p->stats = stats;
	p->drawn = 0;
	p->samples = p->next = 0;
}

/* Keeps a sample, the oldest going once the window is full. */
static void keep_sample(progress_bar *p, unsigned long long now, int done,
			unsigned long long rays)
{
	p->when[p->next] = now;
	p->rows[p->next] = done;
	p->rays[p->next] = rays;
	p->next = (p->next + 1) % PROGRESS_WINDOW;
	if (p->samples < PROGRESS_WINDOW)
		p->samples++;
}

void progress_update(void *ctx, int done, int total)
{
	progress_bar *p = ctx;
	const trace_stats *st = p->stats;
	unsigned long long now, elapsed, left, rays;
	int filled, i;
	char bar[32];
	if (!p->enabled)
		return;
	now = term_micros();
	elapsed = now - p->start;
	left = elapsed / (unsigned)done * (unsigned)(total - done);
	/* Quiet for quick renders; a few redraws a second for the rest. */
	if (elapsed < 500000u || elapsed + left < 1000000u || now - p->last_draw < 100000u)
		return;
	p->last_draw = now;
	rays = st->eye_rays + st->shadow_rays + st->reflect_rays + st->refract_rays;
	{
		/* Rates over the recent window (the whole render until a sample is kept): the
		 * rows still to come cost what the last ones did, not the average so far. */
		int oldest = p->samples < PROGRESS_WINDOW ? 0 : p->next;
		unsigned long long since = p->samples ? now - p->when[oldest] : elapsed;
		unsigned long long traced = p->samples ? rays - p->rays[oldest] : rays;
		int rows = p->samples ? done - p->rows[oldest] : done;
		if (since > 0 && rows > 0) {
			left = since / (unsigned)rows * (unsigned)(total - done);
			elapsed = since;
			rays = traced;
		}
		keep_sample(p, now, done, st->eye_rays + st->shadow_rays + st->reflect_rays +
						  st->refract_rays);
	}
	filled = (int)((long)done * 30 / total);
	for (i = 0; i < 30; i++)
		bar[i] = i < filled ? '#' : '.';
	bar[30] = '\0';
	fprintf(stderr, "\r[%s] %d/%d rows  %llu.%02llu Mrays/s  %llu s left \033[K", bar, done,
		total, rays / elapsed, rays * 100u / elapsed % 100u, (left + 500000u) / 1000000u);
	fflush(stderr);
	p->drawn = 1;
}

void progress_finish(progress_bar *p)
{
	if (p->drawn)
		fprintf(stderr, "\r\033[K");
	p->drawn = 0;
}
