/* render.h - the pixel loop: eye rays for each row, handed to a sink row by row.
 * See LICENSE for copyright and licence. */
#ifndef RT_RENDER_H
#define RT_RENDER_H

#include "camera.h"
#include "sink.h"
#include "trace.h"

/* Sampling of each pixel. */
enum render_sampling {
	SAMPLE_CENTRE, /* one eye ray through the pixel centre */
	SAMPLE_CORNERS /* SPD: (W+1) x (H+1) corner rays, each pixel the mean of its four */
};

/* Told after each finished row: rows done so far out of the total. */
typedef void (*progress_fn)(void *ctx, int done, int total);

/* The sample lines: line y of pixel centres (SAMPLE_CENTRE: image row y) or of pixel
 * corners (SAMPLE_CORNERS: the width + 1 corners on row y's top edge), with the object
 * each ray hit first in ids. A line depends on nothing but y, so lines traced in any
 * order, by any process, are the same. */
void render_line(tracer *t, const camera *c, enum render_sampling sampling, int y,
		 vec3 *colours, int *ids);

/* A row of pixels from its corner lines: the means of each pixel's four corners replace
 * `above` (width + 1 corners each line), and ids become -1 (four rays, no one object). */
void render_corner_means(int width, vec3 *above, const vec3 *below, int *ids);

/* Renders rows [y0, y1) of the camera's image into `out` (y0 = 0, y1 = height for the
 * whole image). Bands rendered separately and joined are identical to the whole image.
 * `progress` may be NULL. Returns 1 on success, 0 when the sink fails. */
int render_image(tracer *t, const camera *c, enum render_sampling sampling, int y0, int y1,
		 sink *out, progress_fn progress, void *progress_ctx);

#endif
