/* output.c - where `-o FILE` writes, as the shell's `>` would, and never half an image:
 * - a FIFO, a terminal, a device or /dev/stdout is written straight into, as a stream;
 * - a regular file (new, or replaced) is written whole to a temporary file first, which
 *   is moved into place only when everything succeeded;
 * - a symbolic link is followed: its target is replaced, the link stays;
 * - a file the user may not write is refused before rendering, as `>` refuses it;
 * - a file a rename would change (more than one hard link, another owner or group, or in a
 *   folder the user may not create files in) keeps its inode: the image is made in a
 *   temporary file elsewhere ($TMPDIR, else /tmp) and copied into it at the end.
 * A signal that ends the process removes the temporary file first, then ends it as that
 * signal would.
 * See LICENSE for copyright and licence. */
#define _POSIX_C_SOURCE 200809L

#include "output.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/time.h>
#include <unistd.h>

#include "diag.h"

#ifndef PATH_MAX
#define PATH_MAX 4096
#endif

/* The temporary file's name, for the signal handler: it may only call async-signal-safe
 * functions (unlink, sigaction, raise). */
static char temp_path[PATH_MAX];
static volatile sig_atomic_t temp_live;

/* Every signal whose default action ends the process, and what was there before rt's
 * handler: restored for the re-raise (the default, or a sanitizer's own handler). */
static const int ending_signals[] = {SIGHUP,  SIGINT,  SIGQUIT, SIGILL,    SIGTRAP, SIGABRT,
				     SIGBUS,  SIGFPE,  SIGUSR1, SIGSEGV,   SIGUSR2, SIGPIPE,
				     SIGALRM, SIGTERM, SIGXCPU, SIGXFSZ,   SIGVTALRM, SIGPROF,
				     SIGSYS};
#define ENDING_SIGNALS (sizeof ending_signals / sizeof ending_signals[0])
static struct sigaction previous[ENDING_SIGNALS];
static unsigned char replaced[ENDING_SIGNALS]; /* rt's handler is in place */

/* Called first by the handlers below (output_on_end). */
static void (*volatile on_end)(void);

/* A line of standard error that an ending run should erase (the progress bar): the
 * handlers below erase it when *status_line is set. */
static const volatile sig_atomic_t *status_line;

static void erase_status_line(void)
{
	static const char erase[] = "\r\033[K";
	if (status_line && *status_line && write(STDERR_FILENO, erase, sizeof erase - 1) < 0)
		return;
}

static void remove_temp_and_end(int sig)
{
	size_t i;
	if (on_end)
		on_end();
	erase_status_line();
	if (temp_live)
		unlink(temp_path);
	temp_live = 0;
	for (i = 0; i < ENDING_SIGNALS; i++)
		if (ending_signals[i] == sig)
			sigaction(sig, &previous[i], NULL);
	/* Delivered when the handler returns (the signal is blocked inside it): the process
	 * ends as the signal ends it, with its exit status (a fault repeats its instruction
	 * and meets the restored handler). */
	raise(sig);
}

/* --time-limit: a wall-clock timer whose SIGALRM ends the run with a message and exit
 * status 1, removing the temporary file first; the message is made when the timer is
 * armed, since the handler may only write it (and the ending that says what became of
 * the output). */
static char limit_message[512]; /* diag's longest message */
static size_t limit_message_length;
static volatile sig_atomic_t limit_armed;
static volatile sig_atomic_t stream_open; /* an output written straight, as it renders */

static void write_message(const char *text, size_t length)
{
	if (write(STDERR_FILENO, text, length) < 0)
		return;
}

static void end_at_time_limit(int sig)
{
	static const char nothing[] = "; no image written\n";
	static const char partly[] = "; the image written so far is incomplete\n";
	(void)sig;
	if (on_end)
		on_end();
	erase_status_line();
	if (temp_live)
		unlink(temp_path);
	temp_live = 0;
	write_message(limit_message, limit_message_length);
	if (stream_open)
		write_message(partly, sizeof partly - 1);
	else
		write_message(nothing, sizeof nothing - 1);
	_exit(1);
}

/* A diag sink that keeps the message, formatted as every other, for the handler. */
static void keep_limit_message(void *ctx, const char *message)
{
	size_t n = strlen(message);
	(void)ctx;
	if (n > 0 && message[n - 1] == '\n')
		n--; /* the handler ends the line */
	limit_message_length = n < sizeof limit_message ? n : sizeof limit_message;
	memcpy(limit_message, message, limit_message_length);
}

int output_time_limit(const char *scene, unsigned long long micros, const char *as_given)
{
	struct sigaction action;
	struct itimerval timer;
	diag_set_sink(keep_limit_message, NULL);
	diag_error(scene, 0, "the time limit of %s seconds was reached", as_given);
	diag_set_sink(NULL, NULL);
	memset(&action, 0, sizeof action);
	action.sa_handler = end_at_time_limit;
	sigemptyset(&action.sa_mask);
	memset(&timer, 0, sizeof timer);
	timer.it_value.tv_sec = (time_t)(micros / 1000000u);
	timer.it_value.tv_usec = (suseconds_t)(micros % 1000000u);
	if (sigaction(SIGALRM, &action, NULL) != 0 || setitimer(ITIMER_REAL, &timer, NULL) != 0) {
		diag_error(NULL, 0, "cannot set the time limit: %s", strerror(errno));
		return 0;
	}
	limit_armed = 1;
	return 1;
}

static void catch_ending_signals(void)
{
	static int caught;
	size_t i;
	if (caught)
		return;
	caught = 1;
	for (i = 0; i < ENDING_SIGNALS; i++) {
		struct sigaction action;
		/* The time limit's own SIGALRM handler stays. */
		if (limit_armed && ending_signals[i] == SIGALRM)
			continue;
		if (sigaction(ending_signals[i], NULL, &previous[i]) != 0)
			continue;
		/* A signal the caller ignores (nohup's SIGHUP, SIGINT for a background job)
		 * stays ignored: it would otherwise end a run that was meant to survive it. */
		if (previous[i].sa_handler == SIG_IGN)
			continue;
		memset(&action, 0, sizeof action);
		action.sa_handler = remove_temp_and_end;
		sigemptyset(&action.sa_mask);
		replaced[i] = sigaction(ending_signals[i], &action, NULL) == 0;
	}
}

void output_on_end(void (*stop)(void))
{
	on_end = stop;
}

void output_forget(void)
{
	size_t i;
	on_end = NULL;
	status_line = NULL;
	temp_live = 0;
	stream_open = 0;
	for (i = 0; i < ENDING_SIGNALS; i++)
		if (replaced[i])
			sigaction(ending_signals[i], &previous[i], NULL);
	/* The time limit's timer is the parent's alone (fork does not copy it). */
	if (limit_armed)
		signal(SIGALRM, SIG_DFL);
	limit_armed = 0;
}

void output_erase_on_end(const volatile sig_atomic_t *line_drawn)
{
	status_line = line_drawn;
	catch_ending_signals();
}

/* The file a path names after its symbolic links, into `out` (the path itself when it
 * is none; a dangling link gives the file it would create). 0 with errno on failure. */
static int follow_links(const char *path, char *out, size_t size)
{
	char link[PATH_MAX];
	int hops;
	size_t length = strlen(path);
	if (length >= size) {
		errno = ENAMETOOLONG;
		return 0;
	}
	memcpy(out, path, length + 1);
	for (hops = 0; hops < 40; hops++) {
		struct stat st;
		ssize_t n;
		const char *slash;
		size_t dir_len;
		if (lstat(out, &st) != 0 || !S_ISLNK(st.st_mode))
			return 1;
		n = readlink(out, link, sizeof link - 1);
		if (n < 0)
			return 0;
		link[n] = '\0';
		/* A relative target is relative to the link's folder. */
		slash = strrchr(out, '/');
		dir_len = link[0] == '/' || !slash ? 0 : (size_t)(slash - out) + 1;
		if (dir_len + (size_t)n >= size) {
			errno = ENAMETOOLONG;
			return 0;
		}
		memmove(out + dir_len, link, (size_t)n + 1);
	}
	errno = ELOOP;
	return 0;
}

/* Makes the temporary file in `dir` (a folder path with its trailing slash, or "" for the
 * current one), named after `base` where the name fits the folder's NAME_MAX. */
static int make_temp(const char *dir, const char *base)
{
	static const char suffix[] = ".tmpXXXXXX";
	long name_max = pathconf(*dir ? dir : ".", _PC_NAME_MAX);
	size_t keep = strlen(base);
	if (name_max <= 0)
		name_max = 255;
	/* A long name is cut (its temporary file only), keeping the suffix mkstemp needs. */
	if (keep + sizeof suffix - 1 > (size_t)name_max)
		keep = (size_t)name_max > sizeof suffix - 1 ? (size_t)name_max - (sizeof suffix - 1) : 0;
	if (snprintf(temp_path, sizeof temp_path, "%s%.*s%s", dir, (int)keep, base, suffix) >=
	    (int)sizeof temp_path) {
		errno = ENAMETOOLONG;
		return -1;
	}
	return mkstemp(temp_path);
}

/* Could the image replace `st` by a rename without changing what a user sees of the file
 * (its links, its owner and group)? The mode is copied either way. */
static int rename_keeps_file(const struct stat *st)
{
	return st->st_nlink == 1 && st->st_uid == geteuid() && st->st_gid == getegid();
}

int output_open(output *out, const char *path)
{
	struct stat st;
	const char *slash, *base;
	int exists, fd = -1;
	mode_t mode;
	out->path = path;
	out->mode = OUTPUT_STREAM;
	out->file = stdout;
	stream_open = path == NULL;
	if (!path)
		return 1;
	exists = stat(path, &st) == 0;
	if (exists && S_ISDIR(st.st_mode)) {
		diag_error(path, 0, "cannot write: %s", strerror(EISDIR));
		return 0;
	}
	/* Not a regular file: a stream (a FIFO and its reader, a terminal, /dev/stdout, a
	 * device), opened as the shell opens it. */
	if (exists && !S_ISREG(st.st_mode)) {
		fd = open(path, O_WRONLY);
		if (fd < 0 || !(out->file = fdopen(fd, "wb"))) {
			diag_error(path, 0, "cannot write: %s", strerror(errno));
			if (fd >= 0)
				close(fd);
			return 0;
		}
		stream_open = 1;
		return 1;
	}
	if (!follow_links(path, out->target, sizeof out->target)) {
		diag_error(path, 0, "cannot write: %s", strerror(errno));
		return 0;
	}
	if (exists && access(out->target, W_OK) != 0) {
		diag_error(path, 0, "cannot write: %s", strerror(errno));
		return 0;
	}
	slash = strrchr(out->target, '/');
	base = slash ? slash + 1 : out->target;
	catch_ending_signals();
	if (!exists || rename_keeps_file(&st)) {
		/* Beside the target, so that the rename stays within one file system. */
		char dir[PATH_MAX];
		size_t dir_len = slash ? (size_t)(slash - out->target) + 1 : 0;
		memcpy(dir, out->target, dir_len);
		dir[dir_len] = '\0';
		fd = make_temp(dir, base);
		if (fd < 0 && !exists) {
			diag_error(path, 0, "cannot create: %s", strerror(errno));
			return 0;
		}
		out->mode = OUTPUT_RENAME;
	}
	if (fd < 0) {
		/* Copied in at the end: the file keeps its inode, links, owner and group. */
		const char *tmpdir = getenv("TMPDIR");
		char dir[PATH_MAX];
		if (!tmpdir || !*tmpdir)
			tmpdir = "/tmp";
		if (snprintf(dir, sizeof dir, "%s/", tmpdir) >= (int)sizeof dir)
			errno = ENAMETOOLONG;
		else
			fd = make_temp(dir, "rt");
		if (fd < 0) {
			diag_error(path, 0, "cannot create a temporary file in %s: %s", tmpdir,
				   strerror(errno));
			return 0;
		}
		out->mode = OUTPUT_COPY;
	}
	temp_live = 1;
	/* mkstemp makes the file private (0600): the image gets the replaced file's mode, or
	 * for a new one what the shell's `>` would give it, 0666 less the umask. */
	if (exists) {
		mode = st.st_mode & 07777;
	} else {
		mode = umask(0);
		umask(mode);
		mode = 0666 & ~mode;
	}
	if (out->mode == OUTPUT_RENAME)
		(void)fchmod(fd, mode);
	if (!(out->file = fdopen(fd, "wb"))) {
		diag_error(path, 0, "cannot write: %s", strerror(errno));
		close(fd);
		unlink(temp_path);
		temp_live = 0;
		return 0;
	}
	return 1;
}

/* Copies the finished temporary file into the target, which keeps its inode. */
static int copy_into_target(output *out)
{
	char buffer[65536];
	int from = open(temp_path, O_RDONLY), to = -1, ok = from >= 0;
	if (ok)
		ok = (to = open(out->target, O_WRONLY | O_TRUNC)) >= 0;
	while (ok) {
		ssize_t n = read(from, buffer, sizeof buffer), done = 0;
		if (n <= 0) {
			ok = n == 0;
			break;
		}
		while (ok && done < n) {
			ssize_t w = write(to, buffer + done, (size_t)(n - done));
			ok = w > 0;
			done += w > 0 ? w : 0;
		}
	}
	if (to >= 0 && close(to) != 0)
		ok = 0;
	if (!ok)
		diag_error(out->path, 0, "cannot write: %s", strerror(errno));
	if (from >= 0)
		close(from);
	return ok;
}

void output_report_error(const output *out)
{
	if (out->path)
		diag_error(out->path, 0, "write error: %s", strerror(errno));
	else
		diag_error(NULL, 0, "write error: standard output: %s", strerror(errno));
}

int output_close(output *out, int ok)
{
	int flushed = fflush(out->file) == 0 && !ferror(out->file);
	if (ok && !flushed)
		output_report_error(out);
	ok = ok && flushed;
	if (out->mode == OUTPUT_STREAM) {
		if (out->path && fclose(out->file) != 0 && ok) {
			output_report_error(out);
			ok = 0;
		}
		return ok;
	}
	if (fclose(out->file) != 0 && ok) {
		output_report_error(out);
		ok = 0;
	}
	if (ok && out->mode == OUTPUT_RENAME && rename(temp_path, out->target) != 0) {
		diag_error(out->path, 0, "cannot replace: %s", strerror(errno));
		ok = 0;
	}
	if (ok && out->mode == OUTPUT_COPY)
		ok = copy_into_target(out);
	if (!ok || out->mode == OUTPUT_COPY)
		unlink(temp_path);
	temp_live = 0;
	return ok;
}

int output_write(void *ctx, const void *data, size_t n)
{
	output *out = ctx;
	return fwrite(data, 1, n, out->file) == n;
}
