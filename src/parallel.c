/* parallel.c - rendering on several cores (-j).
 *
 * Worker processes are forked once the scene and its hierarchy are built: they share
 * them copy-on-write, and nothing is built twice. The parent hands out sample lines
 * (render_line's) by number, at most UNITS_PER_WORKER to a worker at once, so a worker
 * that finishes early takes the next line and none idles while lines are left (a mirror
 * in one corner makes some lines ten times the cost of others). Each worker sends its
 * lines back over its own socket. The parent keeps them in a window of a few lines per
 * worker, puts the rows together in order as render_image does (the corner means
 * included), and hands each row to the sink as soon as it and every row above it are
 * done: the output streams, and memory is the window's, whatever the image's height.
 *
 * Processes, not threads: the tracer's caches, render.c's rows and the ray counters are
 * each worker's own, so nothing is shared and nothing needs a lock (C99 has no threads).
 * A line depends on its number alone (render.h), so the bytes are those of -j 1 whichever
 * worker traced it.
 *
 * Ending: a worker that reads end of file where its next line number would be (the parent
 * done, or gone) ends; a signal that ends the parent stops the workers first (output.c's
 * handlers call parallel_stop); the parent reaps every worker before it returns, and one
 * that ends early fails the render with one message.
 * See LICENSE for copyright and licence. */
#define _POSIX_C_SOURCE 200809L

#include "parallel.h"

#include <errno.h>
#include <poll.h>
#include <signal.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include "antialias.h"
#include "diag.h"
#include "output.h"

/* Units a worker holds at once: the one it works on and the next, so that it never waits
 * for the parent between them. */
#define UNITS_PER_WORKER 2

/* The parent's window of lines (and, with -a, of rows), a pool of colours: each slot
 * holds a line of width + 1 colours and ids, and with -a the row refined from it too;
 * the window has 2 slots per worker and 2 more, so the pool's size (RT_PARALLEL_POOL,
 * 12 MiB in double) caps -j at the widest images. */
static vec3 pool[RT_PARALLEL_POOL];
static int pool_ids[RT_PARALLEL_POOL];
static int no_ids[RT_MAX_WIDTH]; /* -a's rows: four or more rays a pixel, no one object */

/* The window's most slots: lines may run ahead of the row that leaves next by up to
 * WINDOW_PER_JOB a process (a worker's two units and the parent's one). */
#define WINDOW_PER_JOB 3
#define WINDOW_MAX (PARALLEL_MAX_JOBS * WINDOW_PER_JOB + 2)

enum unit_kind {
	UNIT_LINE, /* trace sample line `index` (render_line) */
	UNIT_ROW   /* -a: refine pixel row `index` from its two corner lines, sent after */
};

/* A unit of work, as the parent sends it; and, with the worker's counts so far, as the
 * worker sends back what it made: a line's colours and ids, or a row's colours. */
typedef struct {
	int kind;
	int index;
	trace_stats stats;
} work_unit;

typedef struct {
	pid_t pid;
	int socket;        /* units out, results in */
	int in_flight;     /* units handed out and not yet back */
	trace_stats stats; /* the worker's counts so far */
} worker;

static worker workers[PARALLEL_MAX_JOBS];
static int worker_count;
/* The workers' process IDs, for parallel_stop in a signal handler; 0 where none. */
static volatile sig_atomic_t worker_pids[PARALLEL_MAX_JOBS];

/* What a render asks for, shared by the parent and (copied by fork) the workers. */
typedef struct {
	tracer *t;
	const camera *c;
	enum render_sampling sampling;
	const antialias *aa;   /* NULL: none */
	int corners;           /* lines of corners (--spd, -a) */
	int ids;               /* lines carry their ids (not --spd's corners, whose means have none) */
	size_t line_length;    /* colours in a line: the width, + 1 for corners */
	size_t slot_length;    /* colours in a slot */
} job;

int parallel_default_jobs(void)
{
	long online = sysconf(_SC_NPROCESSORS_ONLN);
	return online < 1 ? 1 : online > PARALLEL_MAX_JOBS ? PARALLEL_MAX_JOBS : (int)online;
}

/* Stops every worker; async-signal-safe (kill only). */
static void parallel_stop(void)
{
	int i;
	for (i = 0; i < PARALLEL_MAX_JOBS; i++)
		if (worker_pids[i] > 0)
			kill((pid_t)worker_pids[i], SIGTERM);
}

/* Reads exactly n bytes; 0 at end of file or on an error. */
static int read_full(int fd, void *data, size_t n)
{
	unsigned char *p = data;
	while (n > 0) {
		ssize_t got = read(fd, p, n);
		if (got < 0 && errno == EINTR)
			continue;
		if (got <= 0)
			return 0;
		p += got;
		n -= (size_t)got;
	}
	return 1;
}

/* Writes n bytes, with send's flags (the parent's MSG_NOSIGNAL: a worker that has ended
 * is an error to report, not a SIGPIPE that ends rt). 0 on an error. */
static int send_full(int fd, const void *data, size_t n, int flags)
{
	const unsigned char *p = data;
	while (n > 0) {
		ssize_t sent = send(fd, p, n, flags);
		if (sent < 0 && errno == EINTR)
			continue;
		if (sent <= 0)
			return 0;
		p += sent;
		n -= (size_t)sent;
	}
	return 1;
}

/* The worker's life: units in, results out, until the parent closes its end. */
static void work(const job *jb, int fd)
{
	static vec3 colours[2][RT_MAX_WIDTH + 1];
	static int ids[2][RT_MAX_WIDTH + 1];
	static vec3 pixels[RT_MAX_WIDTH];
	size_t n = jb->line_length;
	work_unit u;
	memset(&u, 0, sizeof u); /* its padding too: all of it is sent */
	memset(&jb->t->stats, 0, sizeof jb->t->stats);
	while (read_full(fd, &u, sizeof u)) {
		int ok;
		if (u.kind == UNIT_LINE) {
			render_line(jb->t, jb->c, jb->sampling, u.index, colours[0], ids[0]);
		} else {
			if (!read_full(fd, colours[0], n * sizeof(vec3)) ||
			    !read_full(fd, ids[0], n * sizeof(int)) ||
			    !read_full(fd, colours[1], n * sizeof(vec3)) ||
			    !read_full(fd, ids[1], n * sizeof(int)))
				_exit(1);
			antialias_row(jb->t, jb->c, jb->aa, u.index, colours[0], ids[0], colours[1], ids[1],
				      pixels);
		}
		u.stats = jb->t->stats;
		ok = send_full(fd, &u, sizeof u, 0);
		if (u.kind == UNIT_LINE)
			ok = ok && send_full(fd, colours[0], n * sizeof(vec3), 0) &&
			     (!jb->ids || send_full(fd, ids[0], n * sizeof(int), 0));
		else
			ok = ok && send_full(fd, pixels, (n - 1) * sizeof(vec3), 0);
		if (!ok)
			_exit(1);
	}
	_exit(0);
}

/* Forks worker i. 0, with errno, when it cannot. */
static int start_worker(int i, const job *jb)
{
	int ends[2];
	pid_t pid;
	if (socketpair(AF_UNIX, SOCK_STREAM, 0, ends) != 0)
		return 0;
	pid = fork();
	if (pid < 0) {
		int saved = errno;
		close(ends[0]);
		close(ends[1]);
		errno = saved;
		return 0;
	}
	if (pid == 0) {
		int j;
		/* The parent's signal handlers, temporary file and other workers' sockets are
		 * not this process's: a worker ends as signals end any process, and sees end
		 * of file when the parent closes its own socket. */
		output_forget();
		for (j = 0; j < i; j++)
			close(workers[j].socket);
		close(ends[0]);
		work(jb, ends[1]);
	}
	close(ends[1]);
	workers[i].pid = pid;
	workers[i].socket = ends[0];
	workers[i].in_flight = 0;
	memset(&workers[i].stats, 0, sizeof workers[i].stats);
	worker_pids[i] = (sig_atomic_t)pid;
	worker_count = i + 1;
	return 1;
}

/* Closes every socket and waits for every worker; with `stop`, ends them first. Reports
 * the first worker that did not end normally, or, when `culprit` is one, that one.
 * Returns 1 when every worker ended normally. */
static int finish_workers(int stop, int culprit)
{
	int i, status, fine = 1;
	if (stop)
		parallel_stop();
	for (i = 0; i < worker_count; i++)
		close(workers[i].socket);
	for (i = 0; i < worker_count; i++) {
		int report;
		while (waitpid(workers[i].pid, &status, 0) < 0 && errno == EINTR)
			;
		worker_pids[i] = 0;
		/* Stopped: the one that failed; otherwise any that did not end normally. */
		report = stop ? i == culprit : !WIFEXITED(status) || WEXITSTATUS(status) != 0;
		if (!report)
			continue;
		if (fine && WIFSIGNALED(status))
			diag_error(NULL, 0, "worker process %d of %d (pid %ld) was ended by signal %d "
					    "(%s)",
				   i + 1, worker_count, (long)workers[i].pid, WTERMSIG(status),
				   strsignal(WTERMSIG(status)));
		else if (fine)
			diag_error(NULL, 0, "worker process %d of %d (pid %ld) ended early, status %d",
				   i + 1, worker_count, (long)workers[i].pid,
				   WIFEXITED(status) ? WEXITSTATUS(status) : -1);
		fine = 0;
	}
	worker_count = 0;
	output_on_end(NULL);
	return fine;
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

/* Takes one result from worker w into the window. 0 when the worker has ended or sent
 * what it was not asked for. */
static int receive(const job *jb, worker *w, int end)
{
	work_unit u;
	int slot;
	if (!read_full(w->socket, &u, sizeof u) || u.index < window.first || u.index >= end)
		return 0;
	slot = slot_of(u.index);
	if (u.kind == UNIT_LINE) {
		if (window.line_done[slot] ||
		    !read_full(w->socket, line_colours(jb, u.index), jb->line_length * sizeof(vec3)) ||
		    (jb->ids &&
		     !read_full(w->socket, line_ids(jb, u.index), jb->line_length * sizeof(int))))
			return 0;
		window.line_done[slot] = 1;
	} else {
		if (u.kind != UNIT_ROW || !window.row_sent[slot] || window.row_done[slot] ||
		    !read_full(w->socket, row_colours(jb, u.index),
			       (jb->line_length - 1) * sizeof(vec3)))
			return 0;
		window.row_done[slot] = 1;
	}
	w->in_flight--;
	w->stats = u.stats;
	return 1;
}

/* Takes every result worker w has sent so far (one at least: it is ready). Taking one a
 * round left the others waiting in the socket while the parent traced its next line,
 * and the worker, its units done, idle: one line for each of the parent's, however much
 * cheaper its own. 0 as receive. */
static int receive_all(const job *jb, worker *w, int end)
{
	struct pollfd more;
	more.fd = w->socket;
	more.events = POLLIN;
	do {
		if (!receive(jb, w, end))
			return 0;
	} while (w->in_flight > 0 && poll(&more, 1, 0) > 0);
	return 1;
}

/* Sends worker w a unit; a row's two corner lines after it. 0 if the worker has ended. */
static int hand_out(const job *jb, worker *w, int kind, int index)
{
	work_unit u;
	size_t n = jb->line_length;
	memset(&u, 0, sizeof u);
	u.kind = kind;
	u.index = index;
	if (!send_full(w->socket, &u, sizeof u, MSG_NOSIGNAL))
		return 0;
	if (kind == UNIT_ROW && (!send_full(w->socket, line_colours(jb, index), n * sizeof(vec3),
					    MSG_NOSIGNAL) ||
				 !send_full(w->socket, line_ids(jb, index), n * sizeof(int),
					    MSG_NOSIGNAL) ||
				 !send_full(w->socket, line_colours(jb, index + 1),
					    n * sizeof(vec3), MSG_NOSIGNAL) ||
				 !send_full(w->socket, line_ids(jb, index + 1), n * sizeof(int),
					    MSG_NOSIGNAL)))
		return 0;
	w->in_flight++;
	return 1;
}

/* t->stats as the sum of the workers' counts. */
static void sum_stats(trace_stats *sum)
{
	int i;
	memset(sum, 0, sizeof *sum);
	for (i = 0; i < worker_count; i++) {
		sum->eye_rays += workers[i].stats.eye_rays;
		sum->eye_hits += workers[i].stats.eye_hits;
		sum->shadow_rays += workers[i].stats.shadow_rays;
		sum->reflect_rays += workers[i].stats.reflect_rays;
		sum->refract_rays += workers[i].stats.refract_rays;
	}
}

/* Is row y's result complete in the window? */
static int row_ready(const job *jb, int y)
{
	if (jb->aa)
		return window.row_done[slot_of(y)];
	return window.line_done[slot_of(y)] && (!jb->corners || window.line_done[slot_of(y + 1)]);
}

/* The parent's own share of the work, between looking after the workers: a row to
 * refine (-a) whose lines are in, else the next line inside the window, traced straight
 * into its slot with the parent's tracer. Returns 0 when there is none to take. */
static int work_here(const job *jb, tracer *here, int *next_line, int *next_row, int row,
		     int end, int y1)
{
	if (jb->aa && *next_row < y1 && *next_row + 1 < *next_line &&
	    window.line_done[slot_of(*next_row)] && window.line_done[slot_of(*next_row + 1)]) {
		int y = (*next_row)++;
		antialias_row(here, jb->c, jb->aa, y, line_colours(jb, y), line_ids(jb, y),
			      line_colours(jb, y + 1), line_ids(jb, y + 1), row_colours(jb, y));
		window.row_sent[slot_of(y)] = window.row_done[slot_of(y)] = 1;
		return 1;
	}
	if (*next_line < end && *next_line < row + window.size) {
		int y = (*next_line)++;
		render_line(here, jb->c, jb->sampling, y, line_colours(jb, y), line_ids(jb, y));
		window.line_done[slot_of(y)] = 1;
		return 1;
	}
	return 0;
}

int render_parallel(tracer *t, const camera *c, enum render_sampling sampling,
		    const antialias *aa, int y0, int y1, sink *out, int jobs, progress_fn progress,
		    void *progress_ctx)
{
	/* The parent traces too (jobs - 1 workers and itself: no more processes than
	 * jobs, so none waits for a core), with a tracer of its own whose counts it adds to
	 * the workers'. */
	static tracer here;
	job jb;
	int end, next_line = y0, next_row = y0, row = y0, i, k, fitting;
	jb.t = t;
	jb.c = c;
	jb.sampling = aa ? SAMPLE_CORNERS : sampling;
	jb.aa = aa;
	jb.corners = RT_CORNER_SAMPLING && jb.sampling == SAMPLE_CORNERS;
	jb.ids = !jb.corners || aa;
	jb.line_length = (size_t)c->width + (size_t)jb.corners;
	jb.slot_length = jb.line_length * (aa ? 2 : 1);
	end = y1 + jb.corners; /* lines [y0, end) make rows [y0, y1) */
	/* As many processes as there are lines, and as the pool holds windows for. */
	fitting = (int)((RT_PARALLEL_POOL / (long)jb.slot_length - 2) / WINDOW_PER_JOB);
	jobs = jobs < end - y0 ? jobs : end - y0;
	jobs = jobs < fitting ? jobs : fitting;
	if (jobs <= 1)
		return aa ? render_adaptive(t, c, aa, y0, y1, out, progress, progress_ctx)
			  : render_image(t, c, sampling, y0, y1, out, progress, progress_ctx);
	if (!out->begin(out, c->width, y1 - y0))
		return 0;
	for (i = 0; i < c->width; i++)
		no_ids[i] = -1;
	trace_copy(&here, t);
	output_on_end(parallel_stop);
	while (worker_count < jobs - 1 && start_worker(worker_count, &jb))
		;
	if (worker_count == 0) {
		diag_error(NULL, 0, "cannot start a worker process: %s", strerror(errno));
		output_on_end(NULL);
		return -1;
	}
	window.first = y0;
	window.size = (worker_count + 1) * WINDOW_PER_JOB + 2;
	memset(window.line_done, 0, sizeof window.line_done);
	memset(window.row_sent, 0, sizeof window.row_sent);
	memset(window.row_done, 0, sizeof window.row_done);
	while (row < y1) {
		struct pollfd ready[PARALLEL_MAX_JOBS];
		int waiting[PARALLEL_MAX_JOBS], count = 0, culprit = -1, busy;
		/* With -a, rows whose corner lines are both in go first, each to a worker with
		 * nothing to do (which is reading, so the lines sent after it cannot fill the
		 * socket while that worker sends): they let the output move on. */
		for (i = 0; aa && i < worker_count && next_row < y1; i++)
			if (workers[i].in_flight == 0 && next_row + 1 < next_line &&
			    window.line_done[slot_of(next_row)] &&
			    window.line_done[slot_of(next_row + 1)]) {
				if (!hand_out(&jb, &workers[i], UNIT_ROW, next_row)) {
					culprit = i;
					break;
				}
				window.row_sent[slot_of(next_row++)] = 1;
			}
		/* Lines to every worker with room, one each in turn, inside the window. */
		for (k = 1; culprit < 0 && k <= UNITS_PER_WORKER; k++)
			for (i = 0; i < worker_count && next_line < end && next_line < row + window.size;
			     i++) {
				if (workers[i].in_flight >= k)
					continue;
				if (!hand_out(&jb, &workers[i], UNIT_LINE, next_line)) {
					culprit = i;
					break;
				}
				next_line++;
			}
		/* A unit here; then a look at the workers without waiting, or, with nothing
		 * left here, a wait for them. */
		busy = culprit < 0 && work_here(&jb, &here, &next_line, &next_row, row, end, y1);
		for (i = 0; culprit < 0 && i < worker_count; i++)
			if (workers[i].in_flight > 0) {
				ready[count].fd = workers[i].socket;
				ready[count].events = POLLIN;
				waiting[count++] = i;
			}
		if (culprit < 0 && count > 0 && poll(ready, (nfds_t)count, busy ? 0 : -1) < 0) {
			if (errno == EINTR)
				continue;
			diag_error(NULL, 0, "waiting for the workers: %s", strerror(errno));
			finish_workers(1, -1);
			return -1;
		}
		for (k = 0; culprit < 0 && k < count; k++)
			if (ready[k].revents && !receive_all(&jb, &workers[waiting[k]], end))
				culprit = waiting[k];
		if (culprit >= 0) {
			finish_workers(1, culprit);
			return -1;
		}
		sum_stats(&t->stats);
		t->stats.eye_rays += here.stats.eye_rays;
		t->stats.eye_hits += here.stats.eye_hits;
		t->stats.shadow_rays += here.stats.shadow_rays;
		t->stats.reflect_rays += here.stats.reflect_rays;
		t->stats.refract_rays += here.stats.refract_rays;
		/* The rows now complete leave in order. */
		while (row < y1 && row_ready(&jb, row)) {
			vec3 *colours = aa ? row_colours(&jb, row) : line_colours(&jb, row);
			int *ids = aa ? no_ids : line_ids(&jb, row);
			if (jb.corners && !aa)
				render_corner_means(c->width, colours, line_colours(&jb, row + 1), ids);
			if (!out->row(out, colours, ids)) {
				finish_workers(1, -1);
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
	if (!finish_workers(0, -1))
		return -1;
	return out->end(out);
}
