/* parallel.c - rendering on several cores (-j).
 *
 * Worker processes are forked once the scene and its hierarchy are built: they share
 * them copy-on-write, and nothing is built twice. The parent hands out sample lines
 * (render_line's) by number, at most LINES_PER_WORKER to a worker at once, so a worker
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

#include "diag.h"
#include "output.h"

/* Lines a worker holds at once: the one it traces and the next, so that it never waits
 * for the parent between lines. */
#define LINES_PER_WORKER 2
/* The parent's lines: every worker's, and the two a row of corners is made from. */
#define WINDOW (PARALLEL_MAX_JOBS * LINES_PER_WORKER + 2)

static vec3 window_colours[WINDOW][RT_MAX_WIDTH + 1];
static int window_ids[WINDOW][RT_MAX_WIDTH + 1];
static unsigned char window_done[WINDOW];

typedef struct {
	pid_t pid;
	int socket;        /* line numbers out, traced lines in */
	int in_flight;     /* lines handed out and not yet back */
	trace_stats stats; /* the worker's counts so far */
} worker;

static worker workers[PARALLEL_MAX_JOBS];
static int worker_count;
/* The workers' process IDs, for parallel_stop in a signal handler; 0 where none. */
static volatile sig_atomic_t worker_pids[PARALLEL_MAX_JOBS];

/* What a worker sends before each line's colours (and, for centres, its ids). */
typedef struct {
	int line;
	trace_stats stats;
} line_header;

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

/* The worker's life: lines in, colours out, until the parent closes its end. */
static void work(tracer *t, const camera *c, enum render_sampling sampling, int fd)
{
	static vec3 colours[RT_MAX_WIDTH + 1];
	static int ids[RT_MAX_WIDTH + 1];
	int corners = RT_CORNER_SAMPLING && sampling == SAMPLE_CORNERS;
	size_t n = (size_t)(c->width + corners);
	line_header h;
	memset(&h, 0, sizeof h); /* its padding too: all of it is sent */
	memset(&t->stats, 0, sizeof t->stats);
	while (read_full(fd, &h.line, sizeof h.line)) {
		render_line(t, c, sampling, h.line, colours, ids);
		h.stats = t->stats;
		if (!send_full(fd, &h, sizeof h, 0) || !send_full(fd, colours, n * sizeof *colours, 0) ||
		    (!corners && !send_full(fd, ids, n * sizeof *ids, 0)))
			_exit(1);
	}
	_exit(0);
}

/* Forks worker i. 0, with errno, when it cannot. */
static int start_worker(int i, tracer *t, const camera *c, enum render_sampling sampling)
{
	int ends[2], j;
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
		/* The parent's signal handlers, temporary file and other workers' sockets are
		 * not this process's: a worker ends as signals end any process, and sees end
		 * of file when the parent closes its own socket. */
		output_forget();
		for (j = 0; j < i; j++)
			close(workers[j].socket);
		close(ends[0]);
		work(t, c, sampling, ends[1]);
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
		while (waitpid(workers[i].pid, &status, 0) < 0 && errno == EINTR)
			;
		worker_pids[i] = 0;
		if (stop ? i != culprit : WIFEXITED(status) && WEXITSTATUS(status) == 0)
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

/* Takes one traced line from worker w into the window. 0 when the worker has ended or
 * sent what it was not asked for. */
static int receive_line(worker *w, int first, int end, int window, int width, int corners)
{
	line_header h;
	size_t n = (size_t)(width + corners);
	int slot;
	if (!read_full(w->socket, &h, sizeof h) || h.line < first || h.line >= end)
		return 0;
	slot = (h.line - first) % window;
	if (window_done[slot] || !read_full(w->socket, window_colours[slot], n * sizeof(vec3)) ||
	    (!corners && !read_full(w->socket, window_ids[slot], n * sizeof(int))))
		return 0;
	window_done[slot] = 1;
	w->in_flight--;
	w->stats = h.stats;
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

int render_parallel(tracer *t, const camera *c, enum render_sampling sampling, int y0, int y1,
		    sink *out, int jobs, progress_fn progress, void *progress_ctx)
{
	int corners = RT_CORNER_SAMPLING && sampling == SAMPLE_CORNERS;
	int end = y1 + corners; /* lines [y0, end) make rows [y0, y1) */
	int next_line = y0, row = y0, window, i, k;
	if (jobs > end - y0)
		jobs = end - y0;
	if (jobs <= 1)
		return render_image(t, c, sampling, y0, y1, out, progress, progress_ctx);
	if (!out->begin(out, c->width, y1 - y0))
		return 0;
	output_on_end(parallel_stop);
	while (worker_count < jobs && start_worker(worker_count, t, c, sampling))
		;
	if (worker_count == 0) {
		diag_error(NULL, 0, "cannot start a worker process: %s", strerror(errno));
		output_on_end(NULL);
		return -1;
	}
	window = worker_count * LINES_PER_WORKER + 2;
	memset(window_done, 0, sizeof window_done);
	while (row < y1) {
		struct pollfd ready[PARALLEL_MAX_JOBS];
		int waiting[PARALLEL_MAX_JOBS], count = 0;
		/* Lines to every worker with room, one each in turn, inside the window. */
		for (k = 1; k <= LINES_PER_WORKER; k++)
			for (i = 0; i < worker_count && next_line < end && next_line < row + window;
			     i++) {
				if (workers[i].in_flight >= k)
					continue;
				if (!send_full(workers[i].socket, &next_line, sizeof next_line,
					       MSG_NOSIGNAL)) {
					finish_workers(1, i);
					return -1;
				}
				workers[i].in_flight++;
				next_line++;
			}
		for (i = 0; i < worker_count; i++)
			if (workers[i].in_flight > 0) {
				ready[count].fd = workers[i].socket;
				ready[count].events = POLLIN;
				waiting[count++] = i;
			}
		if (poll(ready, (nfds_t)count, -1) < 0) {
			if (errno == EINTR)
				continue;
			diag_error(NULL, 0, "waiting for the workers: %s", strerror(errno));
			finish_workers(1, -1);
			return -1;
		}
		for (k = 0; k < count; k++)
			if (ready[k].revents &&
			    !receive_line(&workers[waiting[k]], y0, end, window, c->width, corners)) {
				finish_workers(1, waiting[k]);
				return -1;
			}
		sum_stats(&t->stats);
		/* The rows now complete leave in order. */
		while (row < y1 && window_done[(row - y0) % window] &&
		       (!corners || window_done[(row + 1 - y0) % window])) {
			int slot = (row - y0) % window;
			if (corners)
				render_corner_means(c->width, window_colours[slot],
						    window_colours[(row + 1 - y0) % window],
						    window_ids[slot]);
			if (!out->row(out, window_colours[slot], window_ids[slot])) {
				finish_workers(1, -1);
				return 0;
			}
			window_done[slot] = 0;
			row++;
			if (progress)
				progress(progress_ctx, row - y0, y1 - y0);
		}
	}
	if (!finish_workers(0, -1))
		return -1;
	return out->end(out);
}
