/* test_camera.c - the pinhole camera's eye rays against their definition in double, and
 * the plane of an image line: every ray of the line lies in it, and a sphere that the
 * plane misses is met by none of them (the tracer leaves such spheres out).
 * See LICENSE for copyright and licence. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "camera.h"
#include "intersect.h"
#include "support.h"
#include "test.h"

/* The camera's own basis in double: forward, right, up. */
static void basis(const camera *c, double f[3], double r[3], double u[3])
{
	f[0] = test_unit_double(c->forward.x);
	f[1] = test_unit_double(c->forward.y);
	f[2] = test_unit_double(c->forward.z);
	r[0] = test_unit_double(c->right.x);
	r[1] = test_unit_double(c->right.y);
	r[2] = test_unit_double(c->right.z);
	u[0] = test_unit_double(c->up.x);
	u[1] = test_unit_double(c->up.y);
	u[2] = test_unit_double(c->up.z);
}

/* The test view (from, at and up askew) at `angle` on a width x height image: its camera,
 * basis in double and the half width the rays are checked against (floating point's own
 * tangent, since near 90 degrees a rounding of the angle moves it far; fixed point's from
 * the angle in double). 0 if the camera refuses it. */
static int test_view(real angle, int width, int height, camera *c, double f[3], double r[3],
		     double u[3], double *hw)
{
	view v;
	v.from = VEC_C(1.0, -7.0, 2.5);
	v.at = VEC_C(0.5, 0.0, 0.75);
	v.up = VEC_C(0.0, 0.2, 1.0);
	v.angle = angle;
	v.hither = REAL_C(0.0);
	v.width = width;
	v.height = height;
	if (!CHECK(camera_init(c, &v, width, height) == NULL))
		return 0;
	basis(c, f, r, u);
	*hw = REAL_FIXED ? tan(test_double(angle) * 3.14159265358979323846 / 360.0)
			 : test_double(c->half_width);
	return 1;
}

/* Every ray of an image (pixel centres) and of its corner lines, against
 * normalize(forward + u right + v up) from the same basis in double, with u and v from
 * the true tan(angle / 2): within `tolerance`. And each ray lies in its line's plane. */
static void eye_rays(real angle, int width, int height, double tolerance, double plane_tolerance)
{
	const double tol[] = {tolerance, plane_tolerance};
	camera c;
	double f[3], r[3], u[3], hw, worst = 0.0, worst_plane = 0.0;
	int x, y, corners, from_eye = 1;
	const vec3 from = VEC_C(1.0, -7.0, 2.5);
	if (!test_view(angle, width, height, &c, f, r, u, &hw))
		return;
	for (corners = 0; corners < 2; corners++) {
		for (y = 0; y < height + corners; y++) {
			int y2 = 2 * y + !corners;
			camera_line line = camera_line_at(&c, y2, !corners);
			double n[3] = {test_unit_double(line.normal.x), test_unit_double(line.normal.y),
				       test_unit_double(line.normal.z)};
			for (x = 0; x < width + corners; x++) {
				double uu = (2.0 * x + !corners - width) / width * hw;
				double vv = (height - (double)y2) / width * hw, d[3], len = 0.0, dn = 0.0;
				int i;
				ray ray_;
				camera_next_ray(&line, &ray_);
				for (i = 0; i < 3; i++) {
					d[i] = f[i] + uu * r[i] + vv * u[i];
					len += d[i] * d[i];
				}
				len = sqrt(len);
				for (i = 0; i < 3; i++) {
					double got = test_unit_double(i == 0 ? ray_.dir.x
								      : i == 1 ? ray_.dir.y : ray_.dir.z);
					double e = fabs(got - d[i] / len);
					worst = e > worst ? e : worst;
					dn += got * n[i];
				}
				worst_plane = fabs(dn) > worst_plane ? fabs(dn) : worst_plane;
				from_eye &= ray_.origin.x == from.x && ray_.origin.y == from.y &&
					    ray_.origin.z == from.z;
			}
		}
	}
	CHECK(from_eye);
	CHECK_NEAR(worst, 0.0, tol[0]);
	CHECK_NEAR(worst_plane, 0.0, tol[1]);
}

/* An ordinary view, one of 179.5 degrees (half width 229) on a wide image, where a
 * line's plane taken from a v rounded before it was scaled by the half width tilted by
 * 2^-9, and a telephoto of 0.007 degrees, whose rays must be good to a small part of its
 * pixels (9.5e-7 across): fixed point once rounded its tangent to 4 bits and its rays'
 * directions to Q16.16 (2^-16, 16 pixels). Floating point is good to a few ulps (float
 * to an eighth of a pixel at 0.007 degrees), fixed point to 2^-16 when the view is wide
 * (it rounds the sums that wide rays need to Q16.16), to a 32nd of a pixel at 0.007
 * degrees. The planes of the lines, which only leave out spheres that they miss by 2^-10
 * of their distance (intersect.c), are good to 2^-15 in fixed point: their v is Q16.16. */
static void test_eye_rays(void)
{
	const double wide = TOL3(4e-7, 1e-15, 1.0 / 65536.0);
	eye_rays(REAL_C(64.0), 37, 23, wide, 2.0 * wide);
	eye_rays(REAL_C(179.5), 999, 5, wide, 2.0 * wide);
	eye_rays(REAL_C(0.007), 129, 129, TOL3(9.5e-7 / 8.0, 1e-15, 9.5e-7 / 32.0),
		 TOL3(8e-7, 2e-15, 2.0 / 65536.0));
}

/* A view from the origin along +y, z up, of the given angle on a size x size image. */
static view view_along_y(real angle, int size)
{
	view v;
	v.from = VEC_C(0.0, 0.0, 0.0);
	v.at = VEC_C(0.0, 1.0, 0.0);
	v.up = VEC_C(0.0, 0.0, 1.0);
	v.angle = angle;
	v.hither = REAL_C(0.0);
	v.width = v.height = size;
	return v;
}

/* A view so narrow that the angle's own rounding moves the image by more than a quarter
 * of a pixel is refused in fixed point (the angle is Q16.16 degrees: 0.001 degrees is 66
 * LSB, and the image 129 wide), taken in floating point. */
static void test_too_narrow(void)
{
	view v = view_along_y(REAL_C(0.001), 129);
	camera c;
	const char *why;
	why = camera_init(&c, &v, 129, 129);
	CHECK((why != NULL) == REAL_FIXED);
	CHECK(why == NULL || strstr(why, "does not fit") != NULL);
	CHECK(camera_init(&c, &v, 16, 16) == NULL); /* 66 LSB: fine at 16 */
}

/* Spheres near the planes of an image's lines: origin_terms_plane may leave a sphere out
 * of a line only when no ray of that line meets it (checked ray by ray with the sphere
 * test itself), and must leave out most of those the plane clearly misses. */
static void test_line_culling(void)
{
	static scene sc;
	static origin_terms terms;
	view v;
	camera c;
	int width = 48, height = 40, x, y, i, wrong = 0, culled = 0, far = 0;
	const char *text = "v from 0 -8 1 at 0 0 1 up 0 0 1 angle 45 hither 0\n"
			   "resolution 48 40\nf 1 1 1 1 0 0 0 1\n"
			   "s -1.5 0 1.6 0.5\ns 0 0.5 1 0.7\ns 1.2 -1 0.2 0.3\ns 0.4 2 2.1 0.9\n"
			   "s 2.5 1 -0.5 0.6\ns -0.5 -3 0.95 0.05\n";
	if (!CHECK(test_parse_buffer(&sc, "lines.nff", text, NULL, NULL)))
		return;
	v = sc.camera;
	if (!CHECK(camera_init(&c, &v, width, height) == NULL))
		return;
	origin_terms_init(&sc, c.eye, sc.object_count, &terms);
	for (y = 0; y < height; y++) {
		camera_line line = camera_line_at(&c, 2 * y + 1, 1);
		origin_terms_plane(&sc, line.normal, &terms);
		for (i = 0; i < sc.object_count; i++) {
			int hit_any = 0;
			camera_line walk = line;
			for (x = 0; x < width; x++) {
				ray r;
				camera_next_ray(&walk, &r);
				hit_any |= object_intersect_from(&sc, i, &r, &terms.terms[i], REAL_C(0.0),
								 REAL_FAR, NULL);
			}
			if (!(terms.candidates >> i & 1)) {
				culled++;
				wrong += hit_any;
			}
			far += !hit_any;
		}
	}
	CHECK_INT(wrong, 0);
	/* Most (line, sphere) pairs that meet nothing are plane misses here (measured: all
	 * 198 of the 240 pairs). */
	CHECK(far > 150);
	CHECK(culled > far * 3 / 4);
}

/* An up within a rounding or two of the view direction (which the parser takes down to
 * 1e-9) leaves the cross product of the two mostly rounding: the camera squares right to
 * forward, so that each line's rays still lie in its plane (the tracer's culling by
 * lines relies on it), at every angle. Floating point; Q16.16's parser refuses such ups
 * and its camera has its own arithmetic. */
static void test_square_lines(void)
{
#if !REAL_FIXED
	static const double tilts[] = {0.5, 1.0, 3.0, 0.0};
	static const double angles[] = {20.0, 60.0, 120.0, 179.0};
	double worst = 0.0;
	size_t i, j;
	for (i = 0; i < sizeof tilts / sizeof tilts[0]; i++)
		for (j = 0; j < sizeof angles / sizeof angles[0]; j++) {
			view v;
			camera c;
			int y2, x;
			double dir[3] = {7.0, -3.0, 5.0};
			double tilt = tilts[i] * (double)REAL_EPSILON;
			v.from = vec_make(REAL_C(1.0), REAL_C(2.0), REAL_C(3.0));
			v.at = vec_add(v.from, vec_make((real)dir[0], (real)dir[1], (real)dir[2]));
			/* Up: the view direction, its last component moved by the tilt (at least
			 * what the parser takes). */
			v.up = vec_make((real)dir[0], (real)dir[1],
					(real)(dir[2] * (1.0 + (tilt > 2e-8 ? tilt : 2e-8))));
			if (tilts[i] == 0.0)
				v.up = vec_make(REAL_C(0.0), REAL_C(0.0), REAL_C(1.0));
			v.angle = (real)angles[j];
			if (!CHECK(camera_init(&c, &v, 40, 30) == NULL))
				continue;
			CHECK(fabs(test_double(unit_to_real(dir_dot(c.right, c.forward)))) <= 1.0 / 1048576);
			for (y2 = 0; y2 <= 60; y2 += 5) {
				camera_line line = camera_line_at(&c, y2, 0);
				for (x = 0; x <= 40; x++) {
					ray r;
					double lean;
					camera_next_ray(&line, &r);
					lean = fabs(test_double(unit_to_real(dir_dot(r.dir, line.normal))));
					worst = lean > worst ? lean : worst;
				}
			}
		}
	CHECK(worst <= 1.0 / 524288); /* 2^-19 */
#endif
}

/* A view so wide that the image plane reaches past 4096 at its corners: refused in fixed
 * point, which could not square such directions in 64 bits, and taken in floating point;
 * at 179.9 degrees an image 1 wide is taken up to 3 high, not 4. */
static void test_too_wide(void)
{
	view v = view_along_y(REAL_C(179.99), 16);
	camera c;
	CHECK((camera_init(&c, &v, 16, 16) != NULL) == REAL_FIXED); /* half width 11459 */
	v.angle = REAL_C(179.9); /* half width 1146 */
	CHECK(camera_init(&c, &v, 16, 16) == NULL);
	CHECK(camera_init(&c, &v, 1, 3) == NULL);
	CHECK((camera_init(&c, &v, 1, 4) != NULL) == REAL_FIXED);
	v.at = v.from;
	CHECK(camera_init(&c, &v, 16, 16) != NULL); /* degenerate */
}

/* camera_ray_at, antialiasing's rays between the lines' points: at a point a line reaches
 * (x, y multiples of 2^shift) the same ray bit for bit, for every shift, on pixel centres
 * and corners alike; and between them, as the definition in double says, to the lines'
 * own tolerance. */
static void rays_at(real angle, int width, int height, double tolerance)
{
	camera c;
	double f[3], r[3], u[3], hw, worst = 0.0;
	int x, y, shift, corners, same = 1;
	if (!test_view(angle, width, height, &c, f, r, u, &hw))
		return;
	for (corners = 0; corners < 2; corners++)
		for (y = 0; y < height + corners; y++) {
			camera_line line = camera_line_at(&c, 2 * y + !corners, !corners);
			for (x = 0; x < width + corners; x++) {
				ray by_line, at;
				camera_next_ray(&line, &by_line);
				for (shift = 0; shift <= 4; shift++) {
					camera_ray_at(&c, (2L * x + !corners) << shift,
						      (2L * y + !corners) << shift, shift, &at);
					/* By value: a long double's padding is not compared. */
					same &= at.dir.x == by_line.dir.x && at.dir.y == by_line.dir.y &&
						at.dir.z == by_line.dir.z && at.origin.x == by_line.origin.x &&
						at.origin.y == by_line.origin.y &&
						at.origin.z == by_line.origin.z;
				}
			}
		}
	CHECK(same);
	/* Between: every sixteenth of a half pixel over a few pixels of each corner. */
	for (y = 0; y < 48; y++)
		for (x = 0; x < 48; x++) {
			long px = x + (x < 24 ? 0 : 32L * width - 48);
			long py = y + (y < 24 ? 0 : 32L * height - 48);
			double uu = ((double)px / 16.0 - width) / width * hw;
			double vv = (height - (double)py / 16.0) / width * hw, d[3], len = 0.0;
			int i;
			ray at;
			camera_ray_at(&c, px, py, 4, &at);
			for (i = 0; i < 3; i++) {
				d[i] = f[i] + uu * r[i] + vv * u[i];
				len += d[i] * d[i];
			}
			len = sqrt(len);
			for (i = 0; i < 3; i++) {
				double got = test_unit_double(i == 0 ? at.dir.x : i == 1 ? at.dir.y : at.dir.z);
				double e = fabs(got - d[i] / len);
				worst = e > worst ? e : worst;
			}
		}
	CHECK_NEAR(worst, 0.0, tolerance);
}

static void test_rays_at(void)
{
	const double wide = TOL3(4e-7, 1e-15, 1.0 / 65536.0);
	rays_at(REAL_C(64.0), 37, 23, wide);
	rays_at(REAL_C(179.5), 999, 5, wide);
	rays_at(REAL_C(0.007), 129, 129, TOL3(9.5e-7 / 8.0, 1e-15, 9.5e-7 / 32.0));
}

void suite_camera(void)
{
	test_eye_rays();
	test_rays_at();
	test_line_culling();
	test_square_lines();
	test_too_wide();
	test_too_narrow();
}
