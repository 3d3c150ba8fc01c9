/* antialias.h - adaptive antialiasing (-a), in the manner of Whitted's 1980 tracer: rays
 * through the pixels' corners, shared between neighbours, and more rays only in the
 * pixels whose corners differ. See LICENSE for copyright and licence. */
#ifndef RT_ANTIALIAS_H
#define RT_ANTIALIAS_H

#include "render.h"

#define ANTIALIAS_MAX_DEPTH 4 /* a pixel's side halved at most 4 times: 16 x 16 squares */

typedef struct {
	int depth;     /* most halvings of a pixel's side, 1 to ANTIALIAS_MAX_DEPTH */
	int threshold; /* a square whose corners differ by more than this many sRGB codes
			* (0 to 255) in a channel, or hit different objects, is halved */
} antialias;

/* Pixel row y from the corner lines on its top and bottom edges (render_line's with
 * SAMPLE_CORNERS: width + 1 colours and ids each): each pixel the mean of its four
 * corners, or, where they differ, of its four halves, each settled the same way down to
 * aa->depth halvings; the means are taken in linear light. */
void antialias_row(tracer *t, const camera *c, const antialias *aa, int y, const vec3 *above,
		   const int *above_ids, const vec3 *below, const int *below_ids, vec3 *pixels);

/* render_image with adaptive antialiasing: rows [y0, y1) to the sink, ids all -1. */
int render_adaptive(tracer *t, const camera *c, const antialias *aa, int y0, int y1, sink *out,
		    progress_fn progress, void *progress_ctx);

#endif
