/* camera.c - NFF's view: from, at, up (not necessarily perpendicular) and the angle.
 * `angle` spans the image width; pixels are square, so the height follows.
 * See LICENSE for copyright and licence. */
#include "camera.h"

#if REAL_FIXED
/* axis half_width / width, the step of half a pixel along a camera axis, rounded to
 * 2^-32, in Q32.32: Q2.30 times Q16.16 is Q18.46, 14 bits more. It is below 2^47 (half_width
 * is below 2^15), and times a coordinate of at most twice the image size (2^14) the sums
 * stay far inside 64 bits, for any angle. */
static real2 image_plane_step(unit axis, real half_width, int width)
{
	return fixed_round_div(fixed_wide_mul(axis, half_width), (int64_t)width << 14);
}

#endif

const char *camera_init(camera *c, const view *v, int width, int height)
{
	static const char degenerate[] = "degenerate view";
	vec3 forward = vec_sub(v->at, v->from);
	dir3 right;
	if (!(vec_dot2(forward, forward) > 0))
		return degenerate;
	c->forward = dir_normalize(forward);
	/* Orthonormalise: right = forward x up, then the true up = right x forward. */
	right = dir_cross(c->forward, dir_normalize(v->up));
	if (!(unit_sqrt(dir_dot(right, right)) > UNIT_C(1e-9)))
		return degenerate;
	c->right = dir_renormalize(right);
	c->up = dir_cross(c->right, c->forward);
	c->eye = v->from;
	c->half_width = real_tan_degrees(real_mul(v->angle, REAL_C(0.5)));
	c->width = width;
	c->height = height;
#if REAL_FIXED
	{
		const unit right_axis[3] = {c->right.x, c->right.y, c->right.z};
		const unit up_axis[3] = {c->up.x, c->up.y, c->up.z};
		int i;
		/* The image plane's corners are at most half_width max(width, height) / width
		 * from its centre: past 4096 (a view of over 179.97 degrees on a square image) the
		 * eye rays' unnormalised directions would reach 2^13 and their squared lengths
		 * crowd 64 bits (numbers beyond what this type holds, as fixed_can_represent
		 * refuses scenes). */
		if ((int64_t)c->half_width * (width > height ? width : height) >
		    (int64_t)4096 * 65536 * width)
			return "the view angle is too wide for " REAL_NAME " at this image size";
		for (i = 0; i < 3; i++) {
			c->right_step[i] = image_plane_step(right_axis[i], c->half_width, width);
			c->up_step[i] = image_plane_step(up_axis[i], c->half_width, width);
		}
	}
#else
	c->per_width = real_reciprocal_of(real_from_int(width));
#endif
	return NULL;
}

/* Image-plane offsets at unit distance, as fractions of the half width; y grows
 * downwards in the image: at half-pixel coordinates (x2, y2) they are u = (x2 - width) /
 * width and v = (height - y2) / width (width, height and x2, y2 are whole numbers, so
 * these are exact in every type until the division).
 *
 * Floating point divides for each ray. (Multiplying x by a rounded pixel size would carry
 * its rounding across the row.) Fixed point keeps forward + v up + u right in Q32.32 and
 * adds the step of one pixel, twice axis half_width / width rounded to 2^-32, per ray: one
 * rounding per line and none per ray (Q16.16 products rounded three times, 2^-17 each),
 * and three additions where the M0 did nine products. */

camera_line camera_line_at(const camera *c, int y2, int x2)
{
	camera_line line;
	line.c = c;
	line.x2 = x2;
	{
		/* forward + u right + v up is perpendicular to v forward - up for every u; v
		 * rounded once (the rays' own v is exact to 2^-32 in fixed point). A view so wide
		 * that v passes 2^13 gets no plane (no object is left out for it). */
		real v = real2_div(real_mul2(real_from_int(c->height - y2), c->half_width),
				   real_from_int(c->width));
		line.normal = real_fabs(v) < REAL_C(8192.0)
				      ? dir_normalize(vec_sub(dir_scale(c->forward, v), dir_to_vec(c->up)))
				      : dir_make(UNIT_C(0.0), UNIT_C(0.0), UNIT_C(0.0));
	}
#if REAL_FIXED
	{
		const unit forward[3] = {c->forward.x, c->forward.y, c->forward.z};
		int i;
		for (i = 0; i < 3; i++) {
			line.sum[i] = (real2)forward[i] * 4 + /* Q2.30 to Q32.32 */
				      c->up_step[i] * (c->height - y2) + c->right_step[i] * (x2 - c->width);
			line.step[i] = c->right_step[i] * 2;
		}
	}
#else
	{
		real y = real_mul(real_from_int(y2), REAL_C(0.5));
		real v = real_mul(real_times_reciprocal(real_from_int(c->height) - (y + y),
							c->per_width),
				  c->half_width);
		line.up_offset = dir_scale(c->up, v);
	}
#endif
	return line;
}

void camera_next_ray(camera_line *line, ray *r)
{
	const camera *c = line->c;
	vec3 d;
	r->origin = c->eye;
#if REAL_FIXED
	{
		int i;
		real p[3];
		for (i = 0; i < 3; i++) {
			/* Rounded to Q16.16 for normalising (in 32-bit halves: no 64-bit shift). */
			p[i] = fixed_round_parts((uint32_t)line->sum[i], (int32_t)(line->sum[i] >> 32), 16);
			line->sum[i] += line->step[i];
		}
		d = vec_make(p[0], p[1], p[2]);
	}
#else
	{
		real x = real_mul(real_from_int(line->x2), REAL_C(0.5));
		real u = real_mul(real_times_reciprocal(x + x - real_from_int(c->width), c->per_width),
				  c->half_width);
		/* forward + u right, then the line's v up: in that order, as sums round. */
		d = vec_add(dir_madd(dir_to_vec(c->forward), u, c->right), line->up_offset);
		line->x2 += 2;
	}
#endif
	r->dir = dir_normalize(d);
}
