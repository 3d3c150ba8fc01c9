/* run-timed.c - runs a command with its output in a file and prints the wall-clock and
 * CPU seconds it took, for tools/bench.
 *
 * Usage: run-timed LOG COMMAND [ARGUMENT...]
 * Prints "WALL CPU" (seconds, to the microsecond) and exits with the command's status
 * (128 + the signal that ended it). The wall time runs from just before the fork to just
 * after the command is reaped: the command's own start-up counts, a shell's does not
 * (timing with `date` before and after the command added about 2.5 ms to each run here,
 * 1 % of a quarter-second render and more of a shorter one). The CPU time is the user and
 * system time of the command and of every process it waited for (wait4's usage), exact
 * where `times` counts in steps of 0.01 s.
 * See LICENSE for copyright and licence. */
#define _DEFAULT_SOURCE 1 /* wait4 */

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/time.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

static double seconds_of(struct timeval tv)
{
	return (double)tv.tv_sec + (double)tv.tv_usec / 1e6;
}

int main(int argc, char **argv)
{
	struct timespec start, end;
	struct rusage usage;
	int log, status;
	pid_t pid;
	if (argc < 3) {
		fprintf(stderr, "usage: run-timed LOG COMMAND [ARGUMENT...]\n");
		return 2;
	}
	log = open(argv[1], O_WRONLY | O_CREAT | O_TRUNC, 0644);
	if (log < 0) {
		fprintf(stderr, "run-timed: %s: %s\n", argv[1], strerror(errno));
		return 2;
	}
	clock_gettime(CLOCK_MONOTONIC, &start);
	pid = fork();
	if (pid < 0) {
		fprintf(stderr, "run-timed: fork: %s\n", strerror(errno));
		return 2;
	}
	if (pid == 0) {
		dup2(log, STDOUT_FILENO);
		dup2(log, STDERR_FILENO);
		close(log);
		execvp(argv[2], argv + 2);
		fprintf(stderr, "run-timed: %s: %s\n", argv[2], strerror(errno));
		_exit(127);
	}
	close(log);
	while (wait4(pid, &status, 0, &usage) < 0) {
		if (errno != EINTR) {
			fprintf(stderr, "run-timed: wait: %s\n", strerror(errno));
			return 2;
		}
	}
	clock_gettime(CLOCK_MONOTONIC, &end);
	printf("%.6f %.6f\n",
	       (double)(end.tv_sec - start.tv_sec) + (double)(end.tv_nsec - start.tv_nsec) / 1e9,
	       seconds_of(usage.ru_utime) + seconds_of(usage.ru_stime));
	return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}
