/* camera.c - NFF's view: from, at, up (not necessarily perpendicular) and the angle.
 * `angle` spans the image width; pixels are square, so the height follows.
 * See LICENSE for copyright and licence. */
#include "camera.h"

int camera_init(camera *c, const view *v, int width, int height)
{
	vec3 forward = vec_sub(v->at, v->from);
	dir3 right;
	if (!(vec_dot2(forward, forward) > 0))
		return 0;
	c->forward = dir_normalize(forward);
	/* Orthonormalise: right = forward x up, then the true up = right x forward. */
	right = dir_cross(c->forward, dir_normalize(v->up));
	if (!(unit_sqrt(dir_dot(right, right)) > UNIT_C(1e-9)))
		return 0;
	c->right = dir_renormalize(right);
	c->up = dir_cross(c->right, c->forward);
	c->eye = v->from;
	c->half_width = real_tan_degrees(real_mul(v->angle, REAL_C(0.5)));
	c->width = width;
	c->height = height;
	c->per_width = real_reciprocal_of(real_from_int(width));
	return 1;
}

/* Image-plane offsets at unit distance, as fractions of the half width; y grows
 * downwards in the image. (Multiplying x by a rounded pixel size would carry its
 * rounding across the row: in Q16.16 several pixels at the far edge. The reciprocal of
 * the width keeps 31 bits in fixed point, and is the division in floating point.)
 * 2x is x + x: the same number in every type (pixel coordinates are far below
 * overflow), and no multiply. */
camera_line camera_line_at(const camera *c, real y)
{
	camera_line line;
	real v = real_mul(real_times_reciprocal(real_from_int(c->height) - (y + y),
						c->per_width),
			  c->half_width);
	line.up_offset = dir_scale(c->up, v);
	return line;
}

ray camera_ray(const camera *c, const camera_line *line, real x)
{
	real u = real_mul(real_times_reciprocal(x + x - real_from_int(c->width), c->per_width),
			  c->half_width);
	ray r;
	r.origin = c->eye;
	/* forward + u right, then the line's v up: in that order, as sums round. */
	r.dir = dir_normalize(vec_add(dir_madd(dir_to_vec(c->forward), u, c->right),
				      line->up_offset));
	return r;
}
