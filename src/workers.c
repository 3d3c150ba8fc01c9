/* workers.c - -j's worker processes (workers.h): each forked with a Unix socket to the
 * parent, through which the parent sends units of work by number and the worker sends
 * each back, with its ray counts so far, when it is done; what a unit is and where its
 * result goes is parallel.c's.
 *
 * Ending: a worker that reads end of file where its next unit would be (the parent done,
 * or gone) ends; a signal that ends the parent stops the workers first (output.c's
 * handlers call workers_stop); the parent reaps every worker, and one that ends early
 * fails the render with one message.
 * See LICENSE for copyright and licence. */
#define _POSIX_C_SOURCE 200809L

#include "workers.h"

#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include "diag.h"
#include "output.h"

typedef struct {
	pid_t pid;
	int socket;        /* units out, results in */
	int in_flight;     /* units handed out and not yet back */
	trace_stats stats; /* the worker's counts so far */
} worker;

static worker workers[RT_MAX_JOBS];
static int worker_count;
/* The workers' process IDs, for workers_stop in a signal handler; 0 where none. */
static volatile sig_atomic_t worker_pids[RT_MAX_JOBS];

void workers_stop(void)
{
	int i;
	for (i = 0; i < RT_MAX_JOBS; i++)
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

/* The worker's life: units in, done, back with the counts so far, until the parent
 * closes its end. */
static void work(const worker_task *task, int fd)
{
	work_unit u;
	memset(&u, 0, sizeof u); /* its padding too: all of it is sent */
	task->begin(task->ctx);
	while (read_full(fd, &u, sizeof u)) {
		/* Only what the parent sends; anything else (nothing should be) ends the worker
		 * before it writes where it should not. */
		if (!task->work(task->ctx, &u))
			_exit(1);
		u.stats = *task->counts;
		if (!send_full(fd, &u, sizeof u, 0))
			_exit(1);
	}
	_exit(0);
}

/* fd moved above standard input, output and error (closed, fd itself); -1 when it
 * cannot be. With one of those closed, socketpair hands out its number, and rt's image
 * (or a read of its input) would go to a worker's socket. */
static int above_standard(int fd)
{
	int moved;
	if (fd > STDERR_FILENO)
		return fd;
	moved = fcntl(fd, F_DUPFD, STDERR_FILENO + 1);
	close(fd);
	return moved;
}

/* Forks worker i. 0, with errno, when it cannot. */
static int start_worker(int i, const worker_task *task)
{
	int ends[2];
	pid_t pid;
	if (socketpair(AF_UNIX, SOCK_STREAM, 0, ends) != 0)
		return 0;
	ends[0] = above_standard(ends[0]);
	ends[1] = above_standard(ends[1]);
	if (ends[0] < 0 || ends[1] < 0) {
		int saved = errno;
		if (ends[0] >= 0)
			close(ends[0]);
		if (ends[1] >= 0)
			close(ends[1]);
		errno = saved;
		return 0;
	}
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
		work(task, ends[1]);
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

int workers_start(int count, const worker_task *task)
{
	while (worker_count < count && start_worker(worker_count, task))
		;
	return worker_count;
}

int workers_count(void)
{
	return worker_count;
}

int workers_in_flight(int i)
{
	return workers[i].in_flight;
}

int workers_finish(int stop, int culprit)
{
	int i, status, fine = 1;
	if (stop)
		workers_stop();
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
	return fine;
}

/* Takes every result worker w has sent so far (one at least: it is ready). Taking one a
 * round left the others waiting in the socket while the parent traced its next line,
 * and the worker, its units done, idle: one line for each of the parent's, however much
 * cheaper its own. 0 when the worker has ended or `accept` refuses what it sent. */
static int receive_all(worker *w, int (*accept)(void *ctx, const work_unit *u), void *ctx)
{
	struct pollfd more;
	more.fd = w->socket;
	more.events = POLLIN;
	do {
		work_unit u;
		if (!read_full(w->socket, &u, sizeof u) || !accept(ctx, &u))
			return 0;
		w->in_flight--;
		w->stats = u.stats;
	} while (w->in_flight > 0 && poll(&more, 1, 0) > 0);
	return 1;
}

int workers_receive(int wait, int (*accept)(void *ctx, const work_unit *u), void *ctx,
		    int *culprit)
{
	struct pollfd ready[RT_MAX_JOBS];
	int waiting[RT_MAX_JOBS], count = 0, k;
	*culprit = -1;
	for (k = 0; k < worker_count; k++)
		if (workers[k].in_flight > 0) {
			ready[count].fd = workers[k].socket;
			ready[count].events = POLLIN;
			waiting[count++] = k;
		}
	if (count == 0)
		return 0;
	if (poll(ready, (nfds_t)count, wait ? -1 : 0) < 0)
		return -1;
	for (k = 0; k < count; k++)
		if (ready[k].revents && !receive_all(&workers[waiting[k]], accept, ctx)) {
			*culprit = waiting[k];
			break;
		}
	return 0;
}

int workers_hand_out(int i, int kind, int index)
{
	work_unit u;
	memset(&u, 0, sizeof u);
	u.kind = kind;
	u.index = index;
	if (!send_full(workers[i].socket, &u, sizeof u, MSG_NOSIGNAL))
		return 0;
	workers[i].in_flight++;
	return 1;
}

void workers_sum_stats(trace_stats *sum, const trace_stats *own)
{
	int i;
	*sum = *own;
	for (i = 0; i < worker_count; i++) {
		sum->eye_rays += workers[i].stats.eye_rays;
		sum->eye_hits += workers[i].stats.eye_hits;
		sum->shadow_rays += workers[i].stats.shadow_rays;
		sum->reflect_rays += workers[i].stats.reflect_rays;
		sum->refract_rays += workers[i].stats.refract_rays;
	}
}
