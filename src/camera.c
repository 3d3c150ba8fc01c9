/* camera.c - NFF's view: from, at, up (not necessarily perpendicular) and the angle.
 * `angle` spans the image width; pixels are square, so the height follows.
 * See LICENSE for copyright and licence. */
#include "camera.h"

#if !REAL_FIXED
/* How far from square (the cosine) a camera's right may be to its forward: the tracer's
 * image-line planes hold the line's rays to about this (camera_line_at). */
#define CAMERA_LEAN UNIT_C(9.5367431640625e-07) /* 2^-20 */
#endif

#if REAL_FIXED
/* axis half_width / width, the step of half a pixel along a camera axis, rounded to
 * 2^-32, in Q32.32, from half_width = sin / cos of half the angle (Q4.28): Q2.30 times
 * Q4.28 times 4 is Q2.60 (below 2^61), over cos (Q4.28) times the width. A narrow view's
 * steps keep their precision this way: from a Q16.16 half_width they kept 4 bits at 0.007
 * degrees. Times a coordinate of at most twice the image size (2^14) the sums stay far
 * inside 64 bits, for any angle. Apart (RT_APART): inlined into camera_init's loop it
 * cost 16 bytes more M0 flash. */
RT_APART static real2 image_plane_step(const camera *c, unit axis)
{
	return fixed_round_div((int64_t)axis * c->half_sin * 4, (int64_t)c->half_cos * c->width);
}

#endif

#if !REAL_FIXED
/* Floating point's eye rays are forward + u right + v up, with u the column's and v the
 * line's: forward + u right depends on the column alone, so it is made once per camera,
 * for every half-pixel column x2, here (the same operations as per ray, so the same
 * bits: a division and three products a ray fewer, 2 % of c-ray's scene). The table
 * belongs to the camera that camera_init numbered columns_serial; another camera's line
 * remakes it. */
static vec3 columns[2 * RT_MAX_WIDTH + 1];
static int columns_serial, camera_serial;

static void make_columns(const camera *c)
{
	int x2;
	for (x2 = 0; x2 <= 2 * c->width; x2++) {
		real x = real_mul(real_from_int(x2), REAL_C(0.5));
		real u = real_mul(real_times_reciprocal(x + x - real_from_int(c->width), c->per_width),
				  c->half_width);
		columns[x2] = dir_madd(dir_to_vec(c->forward), u, c->right);
	}
	columns_serial = c->serial;
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
#if !REAL_FIXED
	{
		/* An up within a few roundings of the view direction leaves right only roughly
		 * square to forward (their cross product is then mostly rounding), and each
		 * image line's rays off the plane camera_line_at gives for it, by which the
		 * tracer leaves objects out: squared here. A right square to a few roundings
		 * already (every other view) is kept bit for bit. */
		unit lean = dir_dot(c->right, c->forward);
		if (unit_fabs(lean) > CAMERA_LEAN)
			c->right = dir_normalize(
				vec_sub(dir_to_vec(c->right), dir_scale(c->forward, unit_to_real(lean))));
	}
#endif
	c->up = dir_cross(c->right, c->forward);
	c->eye = v->from;
	c->width = width;
	c->height = height;
#if REAL_FIXED
	fixed_sin_cos_half_angle(v->angle, &c->half_sin, &c->half_cos);
	c->half_width = c->half_cos > 0 ? fixed_round_div_sat((int64_t)c->half_sin * 65536, c->half_cos)
					: FIXED_MAX;
	{
		const unit axes[6] = {c->right.x, c->right.y, c->right.z, c->up.x, c->up.y, c->up.z};
		int i, larger = width > height ? width : height;
		/* The image plane's corners are at most half_width max(width, height) / width
		 * from its centre. Refused: past 4096 (a view of over 179.97 degrees on a square
		 * image), where the eye rays' unnormalised directions would reach 2^13 and their
		 * squared lengths crowd 64 bits (numbers beyond what this type holds, as
		 * scale_can_represent refuses scenes); and an angle below max(width, height) LSB
		 * (0.002 degrees at 129 pixels), whose own rounding (it is Q16.16 degrees, good to
		 * half an LSB) moves the image's edge by more than a quarter of a pixel. */
		int64_t reach = (int64_t)c->half_width * larger;
		if (reach > (int64_t)4096 * 65536 * width || v->angle < larger)
			return "the view angle does not fit " REAL_NAME " at this image size";
		/* An eye ray's direction before normalising, forward + u right + v up, has
		 * components below 1 + 2 reach / width. It is rounded to keep them below 2^29
		 * with the fewest bits dropped (the bound times the width against 2^29 times the
		 * width): Q16.16 (16 bits dropped) held a narrow view's u and v to a few bits,
		 * and its rays missed by whole tiles. */
		reach = (int64_t)(FIXED_ONE + 1) * width + 2 * reach;
		c->ray_bits = 16;
		while (c->ray_bits > 2 && reach << (17 - c->ray_bits) < (int64_t)width << 29)
			c->ray_bits--;
		for (i = 0; i < 6; i++)
			c->step[i] = image_plane_step(c, axes[i]);
	}
#else
	c->half_width = real_tan_degrees(real_mul(v->angle, REAL_C(0.5)));
	c->per_width = real_reciprocal_of(real_from_int(width));
	c->serial = ++camera_serial;
#endif
	return NULL;
}

/* Image-plane offsets at unit distance, as fractions of the half width; y grows
 * downwards in the image: at half-pixel coordinates (x2, y2) they are u = (x2 - width) /
 * width and v = (height - y2) / width (width, height and x2, y2 are whole numbers, so
 * these are exact in every type until the division).
 *
 * Floating point divides for each column, once per camera (make_columns). (Multiplying x
 * by a rounded pixel size would carry its rounding across the row.) Fixed point keeps forward + v up + u right in Q32.32 and
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
				      c->step[3 + i] * (c->height - y2) + c->step[i] * (x2 - c->width);
			line.step[i] = c->step[i] * 2;
		}
	}
#else
	{
		real y = real_mul(real_from_int(y2), REAL_C(0.5));
		real v = real_mul(real_times_reciprocal(real_from_int(c->height) - (y + y),
							c->per_width),
				  c->half_width);
		line.up_offset = dir_scale(c->up, v);
		if (columns_serial != c->serial)
			make_columns(c);
	}
#endif
	return line;
}

void camera_ray_at(const camera *c, long x, long y, int shift, ray *r)
{
	vec3 d;
	r->origin = c->eye;
#if REAL_FIXED
	{
		/* camera_line_at's sums with the steps scaled by 2^-shift: at multiples of
		 * 2^shift the products are exact multiples, and the shift gives the same sum. */
		const unit forward[3] = {c->forward.x, c->forward.y, c->forward.z};
		int64_t down = ((int64_t)c->height << shift) - y, across = x - ((int64_t)c->width << shift);
		int i;
		real p[3];
		for (i = 0; i < 3; i++) {
			real2 sum = (real2)forward[i] * 4 + ((c->step[3 + i] * down) >> shift) +
				    ((c->step[i] * across) >> shift);
			p[i] = fixed_round_parts((uint32_t)sum, (int32_t)(sum >> 32), c->ray_bits);
		}
		d = vec_make(p[0], p[1], p[2]);
	}
#else
	{
		/* camera_line_at's and camera_next_ray's arithmetic on x and y / 2^shift, which
		 * are exact (whole numbers below 2^19 over a power of two). */
		real per_shift = real_ldexp(REAL_C(1.0), -shift);
		real half_x = real_mul(real_mul(real_from_int(x), per_shift), REAL_C(0.5));
		real half_y = real_mul(real_mul(real_from_int(y), per_shift), REAL_C(0.5));
		real v = real_mul(real_times_reciprocal(real_from_int(c->height) - (half_y + half_y),
							c->per_width),
				  c->half_width);
		real u = real_mul(real_times_reciprocal(half_x + half_x - real_from_int(c->width),
							c->per_width),
				  c->half_width);
		d = vec_add(dir_madd(dir_to_vec(c->forward), u, c->right), dir_scale(c->up, v));
	}
#endif
	r->dir = dir_normalize(d);
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
			/* Rounded for normalising, ray_bits dropped (in 32-bit halves: no 64-bit
			 * shift). */
			p[i] = fixed_round_parts((uint32_t)line->sum[i], (int32_t)(line->sum[i] >> 32),
						 c->ray_bits);
			line->sum[i] += line->step[i];
		}
		d = vec_make(p[0], p[1], p[2]);
	}
#else
	{
		/* forward + u right, then the line's v up: in that order, as sums round. */
		d = vec_add(columns[line->x2], line->up_offset);
		line->x2 += 2;
	}
#endif
	r->dir = dir_normalize(d);
}
