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
#if REAL_FIXED
	/* sin and cos of angle / 2 in Q4.28, whose quotient is tan(angle / 2) to full
	 * precision for narrow views */
	int32_t half_sin, half_cos;
	/* The bits an eye ray's Q32.32 direction drops before it is normalised: as few as
	 * keep its components below 2^29 (camera.c) */
	int ray_bits;
	/* right (step[0 .. 2]) and up (step[3 .. 5]) times half_width / width: their steps
	 * per half pixel on the image plane, in Q32.32 (camera.c). */
	real2 step[6];
#else
	real_reciprocal per_width; /* for dividing by the width: once here, not per ray */
	int serial; /* which camera_init made it: the key of its column table (camera.c) */
#endif
} camera;

/* Sets up the camera for a width x height image. Returns NULL, or what is wrong: a
 * degenerate view (from = at, or up parallel to the view direction), or in fixed point
 * one too wide or too narrow for the image's size. */
const char *camera_init(camera *c, const view *v, int width, int height);

/* The eye rays of one image line, left to right: camera_line_at makes it for the line y2
 * half pixels from the top (2 j + 1 is the centre of pixel row j, 2 j its top edge),
 * starting x2 half pixels from the left; each camera_next_ray gives the next ray and
 * moves one pixel to the right, as far as the image's right edge (x2 = 2 width). */
typedef struct {
	const camera *c;
	int x2;      /* the next ray's x, in half pixels */
	dir3 normal; /* of the plane through the eye that holds all of the line's rays (to about
		      * 2^-20 of their length: camera_init squares right to forward) */
#if REAL_FIXED
	/* forward + v up + u right for the next ray, and u right's step per pixel, in Q32.32:
	 * a row of directions by additions, exact in integers (no per-pixel products). */
	real2 sum[3], step[3];
#else
	vec3 up_offset; /* v up, the line's offset on the image plane */
#endif
} camera_line;

camera_line camera_line_at(const camera *c, int y2, int x2);
void camera_next_ray(camera_line *line, ray *r);

/* The eye ray through the point (x, y) / 2^shift half pixels from the top left (shift 0
 * to 4): between the lines' points, for antialiasing. At a point camera_next_ray reaches
 * (x and y multiples of 2^shift) it is the same ray, bit for bit. */
void camera_ray_at(const camera *c, long x, long y, int shift, ray *r);

#endif
