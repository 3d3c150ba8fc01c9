/* output.c - safe image output: a temporary file beside the target, renamed on success,
 * removed on failure or when a signal stops the run.
 * See LICENSE for copyright and licence. */
#define _POSIX_C_SOURCE 200809L

#include "output.h"

#include <errno.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "diag.h"

/* The temporary file's name, for the signal handler: it may only call unlink and raise. */
static char temp_path[4096];
static volatile sig_atomic_t temp_live;

static void remove_temp_and_die(int sig)
{
	if (temp_live)
		unlink(temp_path);
	signal(sig, SIG_DFL);
	raise(sig);
}

/* mkstemp creates the file private (0600); the image should get the mode a plain fopen
 * gives: the replaced file's own, or 0666 less the umask for a new one. */
static mode_t output_mode(const char *path)
{
	struct stat st;
	mode_t mask;
	if (stat(path, &st) == 0 && S_ISREG(st.st_mode))
		return st.st_mode & 07777;
	mask = umask(0);
	umask(mask);
	return 0666 & ~mask;
}

int output_open(output *out, const char *path)
{
	static const int signals[] = {SIGINT, SIGTERM, SIGHUP, SIGPIPE};
	size_t i;
	int fd;
	out->path = path;
	out->is_temp = 0;
	if (!path) {
		out->file = stdout;
		return 1;
	}
	if (snprintf(temp_path, sizeof temp_path, "%s.tmpXXXXXX", path) >= (int)sizeof temp_path) {
		diag_error(path, 0, "output path too long");
		return 0;
	}
	/* A signal the caller ignores (nohup's SIGHUP, SIGINT for a background job) must
	 * stay ignored: it would otherwise kill a run that was meant to survive it. */
	for (i = 0; i < sizeof signals / sizeof signals[0]; i++)
		if (signal(signals[i], remove_temp_and_die) == SIG_IGN)
			signal(signals[i], SIG_IGN);
	fd = mkstemp(temp_path);
	if (fd >= 0)
		(void)fchmod(fd, output_mode(path));
	if (fd < 0 || !(out->file = fdopen(fd, "wb"))) {
		diag_error(path, 0, "cannot create a temporary file beside it: %s", strerror(errno));
		if (fd >= 0) {
			close(fd);
			unlink(temp_path);
		}
		return 0;
	}
	temp_live = 1;
	out->is_temp = 1;
	return 1;
}

int output_close(output *out, int ok)
{
	int flushed = fflush(out->file) == 0 && !ferror(out->file);
	if (ok && !flushed)
		diag_error(NULL, 0, "write error: %s", strerror(errno));
	ok = ok && flushed;
	if (!out->is_temp)
		return ok;
	if (fclose(out->file) != 0 && ok) {
		diag_error(out->path, 0, "write error: %s", strerror(errno));
		ok = 0;
	}
	if (ok && rename(temp_path, out->path) != 0) {
		diag_error(out->path, 0, "cannot replace: %s", strerror(errno));
		ok = 0;
	}
	if (!ok)
		unlink(temp_path);
	temp_live = 0;
	return ok;
}

int output_write(void *ctx, const void *data, size_t n)
{
	output *out = ctx;
	return fwrite(data, 1, n, out->file) == n;
}
