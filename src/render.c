/* render.c - walks the image row by row and hands each finished row to the sink:
 * single pass, no frame buffer, so memory does not grow with the image height.
 * See LICENSE for copyright and licence. */
#include "render.h"

/* Colours of one row of pixel centres, or two rows of pixel corners. */
static vec3 row_colors[RT_MAX_WIDTH + 1];
static int row_ids[RT_MAX_WIDTH + 1];
static vec3 corner_rows[2][RT_MAX_WIDTH + 1];

/* Eye rays through the corners on image line y (in pixels from the top). */
static void trace_corner_row(tracer *t, const camera *c, int y, vec3 *out)
{
	int x;
	for (x = 0; x <= c->width; x++) {
		ray r = camera_ray(c, real_from_int(x), real_from_int(y));
		out[x] = tracer_eye(t, &r, NULL);
	}
}

int render_image(tracer *t, const camera *c, enum render_sampling sampling, int y0, int y1,
		 sink *out, progress_fn progress, void *progress_ctx)
{
	int x, y, top = 0;
	if (!out->begin(out, c->width, y1 - y0))
		return 0;
	if (sampling == SAMPLE_CORNERS)
		trace_corner_row(t, c, y0, corner_rows[top]);
	for (y = y0; y < y1; y++) {
		if (sampling == SAMPLE_CORNERS) {
			/* The bottom corners of this row are the top corners of the next. */
			const vec3 *above = corner_rows[top], *below = corner_rows[!top];
			trace_corner_row(t, c, y + 1, corner_rows[!top]);
			for (x = 0; x < c->width; x++) {
				vec3 sum = vec_add(vec_add(above[x], above[x + 1]),
						   vec_add(below[x], below[x + 1]));
				row_colors[x] = vec_scale(sum, REAL_C(0.25));
				row_ids[x] = -1;
			}
			top = !top;
		} else {
			for (x = 0; x < c->width; x++) {
				ray r = camera_ray(c, real_from_int(x) + REAL_C(0.5),
						   real_from_int(y) + REAL_C(0.5));
				row_colors[x] = tracer_eye(t, &r, &row_ids[x]);
			}
		}
		if (!out->row(out, row_colors, row_ids))
			return 0;
		if (progress)
			progress(progress_ctx, y + 1 - y0, y1 - y0);
	}
	return out->end(out);
}
