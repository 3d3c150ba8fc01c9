/* workers.h - -j's worker processes: forked with a socket each, handed units of work by
 * number, their results taken back, reaped. See LICENSE for copyright and licence. */
#ifndef RT_WORKERS_H
#define RT_WORKERS_H

#include "trace.h"

/* A unit of work as the parent sends it (what kind, which number); and, with the worker's
 * counts so far, as the worker sends it back when it is done. */
typedef struct {
	int kind;
	int index;
	trace_stats stats;
} work_unit;

/* What the workers do, in each worker process: `begin` once as it starts, then `work`
 * for each unit, which returns 0 for one it was not meant to get (the worker then ends,
 * status 1). `counts` are the worker's ray counts, sent back with each unit. */
typedef struct {
	void (*begin)(void *ctx);
	int (*work)(void *ctx, const work_unit *u);
	void *ctx;
	const trace_stats *counts;
} worker_task;

/* Forks workers until there are `count` (or one cannot start: errno says why); returns
 * how many run. Each runs `task` until the parent closes its socket. */
int workers_start(int count, const worker_task *task);

int workers_count(void);

/* Units handed to worker i and not yet back. */
int workers_in_flight(int i);

/* Sends worker i unit (kind, index); 0 if the worker has ended. */
int workers_hand_out(int i, int kind, int index);

/* Takes the results the workers have sent: waits for one (wait) or only looks. `accept`
 * checks each unit and records it, 0 for one the worker was not asked for. Returns -1
 * when polling fails (errno), else 0, with *culprit a worker that has ended or sent what
 * `accept` refused (-1: none). */
int workers_receive(int wait, int (*accept)(void *ctx, const work_unit *u), void *ctx,
		    int *culprit);

/* *sum = own counts plus every worker's so far. */
void workers_sum_stats(trace_stats *sum, const trace_stats *own);

/* Closes every socket and waits for every worker; with `stop`, ends them first. Reports
 * the first worker that did not end normally, or, when `culprit` is one, that one.
 * Returns 1 when every worker ended normally. */
int workers_finish(int stop, int culprit);

/* Ends every worker (SIGTERM); async-signal-safe, for a signal handler. */
void workers_stop(void);

#endif
