/* camera.h - the pinhole camera: pixel coordinates to eye rays.
 * See LICENSE for copyright and licence. */
#ifndef RT_CAMERA_H
#define RT_CAMERA_H

#include "shape.h"

typedef struct {
	vec3 eye;
	dir3 forward, right, up; /* orthonormal, right-handed as NFF is */
	real half_width;         /* tan(angle / 2): half the image plane at unit distance */
	int width, height;
	real_reciprocal per_width; /* for dividing by the width: once here, not per ray */
} camera;

/* Sets up the camera for a width x height image. Returns 0 when the view is degenerate
 * (from = at, or up parallel to the view direction). */
int camera_init(camera *c, const view *v, int width, int height);

/* What the eye rays of one image line share: its offset along up on the image plane. */
typedef struct {
	vec3 up_offset;
} camera_line;

/* The line at y pixels from the top, for camera_ray. */
camera_line camera_line_at(const camera *c, real y);

/* The eye ray through image position (x, y), in pixels from the top-left corner, for
 * the line at y: (i + 0.5, j + 0.5) is the centre of pixel (i, j), (i, j) its top-left
 * corner. */
ray camera_ray(const camera *c, const camera_line *line, real x);

#endif
