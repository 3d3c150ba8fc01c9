/* parallel.c - rendering on several cores (-j).
 *
 * Worker processes are forked once the scene and its hierarchy are built: they share
 * them copy-on-write, and nothing is built twice. The parent hands out sample lines
 * (render_line's) by number, at most UNITS_PER_WORKER to a worker at once, so a worker
 * that finishes early takes the next line and none idles while lines are left (a mirror
 * in one corner makes some lines ten times the cost of others). The lines go into a
 * window of a few lines a process, mapped before the fork and so shared with the workers:
 * a worker traces straight into its line's slot and sends back over its own socket only
 * the line's number and its counts. The parent puts the rows together in order as
 * render_image does (the corner means included), and hands each row to the sink as soon
 * as it and every row above it are done: the output streams, and memory is the window's,
 * whatever the image's height.
 *
 * Processes, not threads: the tracer's caches, render.c's rows and the ray counters are
 * each worker's own, and a slot of the window is written only by the process its line
 * (or row) was handed to, before that process says so over its socket: nothing needs a
 * lock (C99 has no threads). The kernel's send and receive order the slot's writes
 * before the parent's reads, as its locks on the socket order memory.
 * A line depends on its number alone (render.h), so the bytes are those of -j 1 whichever
 * worker traced it.
 *
 * The worker processes themselves, their sockets and their ending are workers.c's.
 * See LICENSE for copyright and licence. */
#define _POSIX_C_SOURCE 200809L
#define _DEFAULT_SOURCE 1 /* MAP_ANONYMOUS, which POSIX names only from its 2024 issue */

#include "parallel.h"

#include <errno.h>
#include <string.h>
#include <sys/mman.h>
#include <unistd.h>

#include "antialias.h"
#include "diag.h"
#include "output.h"
#include "pages.h"
#include "workers.h"

#if !defined(MAP_ANONYMOUS) && defined(MAP_ANON)
#define MAP_ANONYMOUS MAP_ANON
#endif

/* Units a worker holds at once: the one it works on and two more, so that it does not
 * wait while the parent traces a line of its own that costs more than the worker's next
 * (with two, balls' worker waited for the parent 70-90 times a render, 2-3 ms in all). */
#define UNITS_PER_WORKER 3

/* The window of lines (and, with -a, of rows): a pool of RT_PARALLEL_POOL colours and as
 * many ids (28 MiB in double), a fixed array as a static one would be, but mapped shared
 * before the fork so that the workers write into it; a render touches only its window's
 * part. Each slot holds a line of width + 1 colours and ids, and with -a the row refined
 * from it too; there are WINDOW_PER_JOB slots a process and 2 more, which caps -j at the
 * widest images. */
static vec3 *pool;
static int *pool_ids;
#define POOL_BYTES ((size_t)RT_PARALLEL_POOL * (sizeof(vec3) + sizeof(int)))
static int no_ids[RT_MAX_WIDTH]; /* -a's rows: four or more rays a pixel, no one object */

/* The window's most slots: lines may run ahead of the row that leaves next by up to
 * WINDOW_PER_JOB a process (a worker's units and the parent's one). */
#define WINDOW_PER_JOB (UNITS_PER_WORKER + 1)
#define WINDOW_MAX (RT_MAX_JOBS * WINDOW_PER_JOB + 2)

enum unit_kind {
	UNIT_LINE, /* trace sample line `index` (render_line) */
	UNIT_ROW   /* -a: refine pixel row `index` from its two corner lines, sent after */
};

/* What a render asks for, shared by the parent and (copied by fork) the workers. */
typedef struct {
	tracer *t;
	const camera *c;
	enum render_sampling sampling;
	const antialias *aa;   /* NULL: none */
	int corners;           /* lines of corners (--spd, -a) */
	int end;               /* the render's lines are [window.first, end) */
	size_t line_length;    /* colours in a line: the width, + 1 for corners */
	size_t slot_length;    /* colours in a slot */
} job;

int parallel_default_jobs(void)
{
	long online = sysconf(_SC_NPROCESSORS_ONLN);
	return online < 1 ? 1 : online > RT_MAX_JOBS ? RT_MAX_JOBS : (int)online;
}

/* The window: slot k holds line y0 + k + m window for some m, and with -a the row of the
 * same number; a flag for each (done, and for rows also handed out). */
static struct {
	int first, size; /* the first line's number; slots */
	unsigned char line_done[WINDOW_MAX];
	unsigned char row_sent[WINDOW_MAX];
	unsigned char row_done[WINDOW_MAX];
} window;

static int slot_of(int index)
{
	return (index - window.first) % window.size;
}

static vec3 *line_colours(const job *jb, int index)
{
	return pool + (size_t)slot_of(index) * jb->slot_length;
}

static int *line_ids(const job *jb, int index)
{
	return pool_ids + (size_t)slot_of(index) * jb->slot_length;
}

/* With -a a slot's row follows its line. */
static vec3 *row_colours(const job *jb, int index)
{
	return line_colours(jb, index) + jb->line_length;
}

/* Maps the pool, shared with the processes forked after. 0 when the system refuses. */
static int share_pool(void)
{
	void *mapped = mmap(NULL, POOL_BYTES, PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS,
			    -1, 0);
	if (mapped == MAP_FAILED)
		return 0;
	pool = mapped;
	/* The ids after the colours: at a multiple of sizeof(vec3), aligned for an int. */
	pool_ids = (int *)(void *)((unsigned char *)mapped + RT_PARALLEL_POOL * sizeof(vec3));
	return 1;
}

static void unshare_pool(void)
{
	if (pool)
		munmap(pool, POOL_BYTES);
	pool = NULL;
	pool_ids = NULL;
}

/* Makes the window's part of the pool ready in this process's view of it: the parent's
 * before the fork, a worker's as it starts (a fork maps shared memory afresh, and its
 * pages would fault one by one). */
static void window_prepare(const job *jb)
{
	/* The slots the render's lines reach: fewer than the window's for a short image. */
	int used = jb->end - window.first < window.size ? jb->end - window.first : window.size;
	size_t slots = (size_t)used * jb->slot_length;
	pages_prepare(pool, slots * sizeof *pool);
	pages_prepare(pool_ids, slots * sizeof *pool_ids);
}

/* Traces a unit into its slot of the window: line y, or (-a) row y refined from its two
 * corner lines, which are in the window already. */
static void do_unit(const job *jb, tracer *t, int kind, int y)
{
	if (kind == UNIT_LINE)
		render_line(t, jb->c, jb->sampling, y, line_colours(jb, y), line_ids(jb, y));
	else
		antialias_row(t, jb->c, jb->aa, y, line_colours(jb, y), line_ids(jb, y),
			      line_colours(jb, y + 1), line_ids(jb, y + 1), row_colours(jb, y));
}

/* The workers' side of a unit (worker_task): the window ready as a worker starts, its
 * counts from zero; then each unit the parent sends, if it is one the parent could send
 * (else the worker ends before it writes outside the window). */
static void worker_begin(void *ctx)
{
	const job *jb = ctx;
	window_prepare(jb);
	memset(&jb->t->stats, 0, sizeof jb->t->stats);
}

static int worker_unit(void *ctx, const work_unit *u)
{
	const job *jb = ctx;
	if ((u->kind != UNIT_LINE && u->kind != UNIT_ROW) || u->index < window.first ||
	    u->index + (u->kind == UNIT_ROW) >= jb->end)
		return 0;
	do_unit(jb, jb->t, u->kind, u->index);
	return 1;
}

/* The parent's side of a result: its line or row is in the window. 0 for one no worker
 * was asked for. */
static int accept_result(void *ctx, const work_unit *u)
{
	const job *jb = ctx;
	int slot;
	if (u->index < window.first || u->index >= jb->end)
		return 0;
	slot = slot_of(u->index);
	if (u->kind == UNIT_LINE) {
		if (window.line_done[slot])
			return 0;
		window.line_done[slot] = 1;
	} else {
		if (u->kind != UNIT_ROW || !window.row_sent[slot] || window.row_done[slot])
			return 0;
		window.row_done[slot] = 1;
	}
	return 1;
}

/* Reaps the workers (ending them first with `stop`; workers_finish) and gives back what
 * the render took: 1 when every worker ended normally. */
static int finish(int stop, int culprit)
{
	int fine = workers_finish(stop, culprit);
	output_on_end(NULL);
	unshare_pool();
	return fine;
}

/* Is row y's result complete in the window? */
static int row_ready(const job *jb, int y)
{
	if (jb->aa)
		return window.row_done[slot_of(y)];
	return window.line_done[slot_of(y)] && (!jb->corners || window.line_done[slot_of(y + 1)]);
}

/* The next unit to hand out, into *kind and *index: with -a a row whose corner lines are
 * both in (rows let the output move on), else the next line inside the window. 0 when
 * there is none. */
static int next_unit(const job *jb, int next_line, int next_row, int row, int end, int y1,
		     int *kind, int *index)
{
	if (jb->aa && next_row < y1 && next_row + 1 < next_line &&
	    window.line_done[slot_of(next_row)] && window.line_done[slot_of(next_row + 1)]) {
		*kind = UNIT_ROW;
		*index = next_row;
		return 1;
	}
	if (next_line < end && next_line < row + window.size) {
		*kind = UNIT_LINE;
		*index = next_line;
		return 1;
	}
	return 0;
}

/* Marks unit (kind, index) handed out: the next row or line. */
static void take_unit(int kind, int *next_line, int *next_row)
{
	if (kind == UNIT_ROW)
		window.row_sent[slot_of((*next_row)++)] = 1;
	else
		(*next_line)++;
}

int render_parallel(tracer *t, const camera *c, enum render_sampling sampling,
		    const antialias *aa, int y0, int y1, sink *out, int jobs, progress_fn progress,
		    void *progress_ctx)
{
	/* The parent traces too (jobs - 1 workers and itself: no more processes than
	 * jobs, so none waits for a core), with t, whose counts are its own while it traces
	 * and between units the sum of everyone's (for the progress bar and --stats). */
	trace_stats own;
	job jb;
	worker_task task;
	int end, next_line = y0, next_row = y0, row = y0, i, k, fitting;
	jb.t = t;
	jb.c = c;
	jb.sampling = aa ? SAMPLE_CORNERS : sampling;
	jb.aa = aa;
	jb.corners = RT_CORNER_SAMPLING && jb.sampling == SAMPLE_CORNERS;
	jb.line_length = (size_t)c->width + (size_t)jb.corners;
	jb.slot_length = jb.line_length * (aa ? 2 : 1);
	end = y1 + jb.corners; /* lines [y0, end) make rows [y0, y1) */
	jb.end = end;
	/* As many processes as there are lines, and as the pool holds windows for. */
	fitting = (int)((RT_PARALLEL_POOL / (long)jb.slot_length - 2) / WINDOW_PER_JOB);
	jobs = jobs < end - y0 ? jobs : end - y0;
	jobs = jobs < fitting ? jobs : fitting;
	window.first = y0;
	window.size = jobs * WINDOW_PER_JOB + 2;
	/* Without the shared pool (a system that refuses the mapping: an address-space limit)
	 * one process renders: the same bytes. */
	if (jobs <= 1 || !share_pool())
		return aa ? render_adaptive(t, c, aa, y0, y1, out, progress, progress_ctx)
			  : render_image(t, c, sampling, y0, y1, out, progress, progress_ctx);
	window_prepare(&jb);
	if (!out->begin(out, c->width, y1 - y0)) {
		unshare_pool();
		return 0;
	}
	for (i = 0; i < c->width; i++)
		no_ids[i] = -1;
	own = t->stats;
	output_on_end(workers_stop);
	task.begin = worker_begin;
	task.work = worker_unit;
	task.ctx = &jb;
	task.counts = &t->stats;
	if (workers_start(jobs - 1, &task) == 0) {
		diag_error(NULL, 0, "cannot start a worker process: %s", strerror(errno));
		output_on_end(NULL);
		unshare_pool();
		return -1;
	}
	memset(window.line_done, 0, sizeof window.line_done);
	memset(window.row_sent, 0, sizeof window.row_sent);
	memset(window.row_done, 0, sizeof window.row_done);
	while (row < y1) {
		int culprit = -1, busy = 0, kind, index;
		/* Units to every worker with room, one each in turn. */
		for (k = 1; culprit < 0 && k <= UNITS_PER_WORKER; k++)
			for (i = 0; culprit < 0 && i < workers_count(); i++) {
				if (workers_in_flight(i) >= k)
					continue;
				if (!next_unit(&jb, next_line, next_row, row, end, y1, &kind, &index))
					break;
				if (!workers_hand_out(i, kind, index))
					culprit = i;
				else
					take_unit(kind, &next_line, &next_row);
			}
		/* A unit here; then a look at the workers without waiting, or, with nothing
		 * left here, a wait for them. */
		if (culprit < 0 && next_unit(&jb, next_line, next_row, row, end, y1, &kind, &index)) {
			take_unit(kind, &next_line, &next_row);
			t->stats = own;
			do_unit(&jb, t, kind, index);
			own = t->stats;
			if (kind == UNIT_ROW)
				window.row_done[slot_of(index)] = 1;
			else
				window.line_done[slot_of(index)] = 1;
			busy = 1;
		}
		if (culprit < 0 && workers_receive(!busy, accept_result, &jb, &culprit) < 0) {
			if (errno == EINTR)
				continue;
			diag_error(NULL, 0, "waiting for the workers: %s", strerror(errno));
			finish(1, -1);
			return -1;
		}
		if (culprit >= 0) {
			finish(1, culprit);
			return -1;
		}
		workers_sum_stats(&t->stats, &own);
		/* The rows now complete leave in order. */
		while (row < y1 && row_ready(&jb, row)) {
			vec3 *colours = aa ? row_colours(&jb, row) : line_colours(&jb, row);
			int *ids = aa ? no_ids : line_ids(&jb, row);
			if (jb.corners && !aa)
				render_corner_means(c->width, colours, line_colours(&jb, row + 1), ids);
			if (!out->row(out, colours, ids)) {
				finish(1, -1);
				return 0;
			}
			window.line_done[slot_of(row)] = 0;
			window.row_sent[slot_of(row)] = 0;
			window.row_done[slot_of(row)] = 0;
			row++;
			if (progress)
				progress(progress_ctx, row - y0, y1 - y0);
		}
	}
	if (!finish(0, -1))
		return -1;
	return out->end(out);
}
