/* render.c - walks the image row by row and hands each finished row to the sink:
 * single pass, no frame buffer, so memory does not grow with the image height.
 * See LICENSE for copyright and licence. */
#include "render.h"

/* Colours of one row of pixel centres in rows[0]; or two rows of pixel corners, whose
 * means replace the upper row in place. Builds without --spd keep one row
 * (RT_CORNER_SAMPLING). */
static vec3 rows[1 + RT_CORNER_SAMPLING][RT_MAX_WIDTH + 1];
static int row_ids[RT_MAX_WIDTH + 1];

void render_line(tracer *t, const camera *c, enum render_sampling sampling, int y,
		 vec3 *colours, int *ids)
{
	int corners = RT_CORNER_SAMPLING && sampling == SAMPLE_CORNERS;
	/* Corners lie on the pixels' edges (2 y half pixels down, x from 0), centres half a
	 * pixel in (2 y + 1, x from 1). */
	camera_line line = camera_line_at(c, 2 * y + !corners, !corners);
	int x;
	trace_eye_line(t, line.normal);
	for (x = 0; x < c->width + corners; x++) {
		ray r;
		camera_next_ray(&line, &r);
		colours[x] = trace_eye(t, &r, &ids[x]);
	}
}

void render_corner_means(int width, vec3 *above, const vec3 *below, int *ids)
{
	int x;
	/* Pixel x needs corners x and x + 1, and x is done before x + 1 is overwritten. */
	for (x = 0; x < width; x++) {
		vec3 sum = vec_add(vec_add(above[x], above[x + 1]), vec_add(below[x], below[x + 1]));
		above[x] = vec_scale(sum, REAL_C(0.25));
		ids[x] = -1;
	}
}

int render_image(tracer *t, const camera *c, enum render_sampling sampling, int y0, int y1,
		 sink *out, progress_fn progress, void *progress_ctx)
{
	int corners = RT_CORNER_SAMPLING && sampling == SAMPLE_CORNERS, y, top = 0;
	if (!out->begin(out, c->width, y1 - y0))
		return 0;
	if (corners)
		render_line(t, c, sampling, y0, rows[top], row_ids);
	for (y = y0; y < y1; y++) {
		/* With corners, the bottom corners of this row are the top corners of the next:
		 * traced into the other row, which the next row then uses as its top. */
		vec3 *traced = rows[corners ? RT_CORNER_SAMPLING - top : 0], *done = traced;
		render_line(t, c, sampling, y + corners, traced, row_ids);
		if (corners) {
			done = rows[top];
			render_corner_means(c->width, done, traced, row_ids);
			top = RT_CORNER_SAMPLING - top;
		}
		if (!out->row(out, done, row_ids))
			return 0;
		if (progress)
			progress(progress_ctx, y + 1 - y0, y1 - y0);
	}
	return out->end(out);
}
