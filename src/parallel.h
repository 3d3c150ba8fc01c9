/* parallel.h - rendering on several cores: worker processes trace lines, the parent
 * streams the rows in order. See LICENSE for copyright and licence. */
#ifndef RT_PARALLEL_H
#define RT_PARALLEL_H

#include "antialias.h"

/* The processors online, at least 1 and at most RT_MAX_JOBS (config.h): -j's default. */
int parallel_default_jobs(void);

/* render_image (render_adaptive when aa is not NULL) with `jobs` worker processes: the
 * same bytes to the sink, row by row as they are done, and t->stats the workers' counts
 * summed (the progress callback sees them). jobs 1 (or a single line) is render_image
 * (render_adaptive) itself; jobs is cut to what the window holds at this width. Returns 1 on success, 0 when
 * the sink fails, -1 when a worker could not start or ended early (reported here; every
 * worker is stopped and reaped before it returns). */
int render_parallel(tracer *t, const camera *c, enum render_sampling sampling,
		    const antialias *aa, int y0, int y1, sink *out, int jobs, progress_fn progress,
		    void *progress_ctx);

#endif
