/* render.c - walks the image row by row and hands each finished row to the sink:
 * single pass, no frame buffer, so memory does not grow with the image height.
 * See LICENSE for copyright and licence. */
#include "render.h"

/* Colours of one row of pixel centres in rows[0]; or two rows of pixel corners, whose
 * means replace the upper row in place (pixel x needs corners x and x + 1, and x is done
 * before x + 1 is overwritten). Builds without --spd keep one row (RT_CORNER_SAMPLING). */
static vec3 rows[1 + RT_CORNER_SAMPLING][RT_MAX_WIDTH + 1];
static int row_ids[RT_MAX_WIDTH + 1];

/* Eye rays through the corners on image line y (in pixels from the top). */
static void trace_corner_row(tracer *t, const camera *c, int y, vec3 *out)
{
	int x;
	camera_line line = camera_line_at(c, 2 * y, 0);
	trace_eye_line(t, line.normal);
	for (x = 0; x <= c->width; x++) {
		ray r;
		camera_next_ray(&line, &r);
		out[x] = trace_eye(t, &r, NULL);
	}
}

int render_image(tracer *t, const camera *c, enum render_sampling sampling, int y0, int y1,
		 sink *out, progress_fn progress, void *progress_ctx)
{
	int x, y, top = 0;
	const vec3 *done;
	if (!out->begin(out, c->width, y1 - y0))
		return 0;
	if (RT_CORNER_SAMPLING && sampling == SAMPLE_CORNERS)
		trace_corner_row(t, c, y0, rows[top]);
	for (y = y0; y < y1; y++) {
		if (RT_CORNER_SAMPLING && sampling == SAMPLE_CORNERS) {
			/* The bottom corners of this row are the top corners of the next: traced
			 * into the other row, which the next row then uses as its top. */
			vec3 *above = rows[top], *below = rows[RT_CORNER_SAMPLING - top];
			trace_corner_row(t, c, y + 1, below);
			for (x = 0; x < c->width; x++) {
				vec3 sum = vec_add(vec_add(above[x], above[x + 1]),
						   vec_add(below[x], below[x + 1]));
				above[x] = vec_scale(sum, REAL_C(0.25));
				row_ids[x] = -1;
			}
			done = above;
			top = RT_CORNER_SAMPLING - top;
		} else {
			camera_line line = camera_line_at(c, 2 * y + 1, 1);
			trace_eye_line(t, line.normal);
			for (x = 0; x < c->width; x++) {
				ray r;
				camera_next_ray(&line, &r);
				rows[0][x] = trace_eye(t, &r, &row_ids[x]);
			}
			done = rows[0];
		}
		if (!out->row(out, done, row_ids))
			return 0;
		if (progress)
			progress(progress_ctx, y + 1 - y0, y1 - y0);
	}
	return out->end(out);
}
