/* render.h - the pixel loop: eye rays for each row, streamed out row by row.
 * See LICENSE for copyright and licence. */
#ifndef RT_RENDER_H
#define RT_RENDER_H

#include "camera.h"
#include "image.h"
#include "trace.h"

/* Sampling of each pixel. */
enum render_sampling {
	SAMPLE_CENTRE, /* one eye ray through the pixel centre */
	SAMPLE_CORNERS /* SPD: (W+1) x (H+1) corner rays, each pixel the mean of its four */
};

/* Renders rows [y0, y1) of the camera's image as a PPM of that band through `write`
 * (y0 = 0, y1 = height for the whole image). Bands rendered separately and joined (one
 * header, then each band's pixels in order) are byte-identical to the whole image.
 * Returns 1 on success, 0 when a write fails (the caller reports it). */
int render_ppm(tracer *t, const camera *c, enum render_sampling sampling, int y0, int y1,
	       write_fn write, void *ctx);

#endif
