/* test_eye_cover.c - the eye rays the cover leaves unsearched meet nothing: for scenes of
 * spheres and triangles seen from far, near, inside and at the edge of the view, with up
 * almost the view direction, at every scale a scene may have, every ray of many image
 * lines (and antialiasing's points between them) that eye_cover_misses passes over finds
 * no hit through the full search.
 * See LICENSE for copyright and licence. */
#include <math.h>
#include <stdio.h>

#include "camera.h"
#include "eye_cover.h"
#include "support.h"
#include "test.h"
#include "trace.h"

#if EYE_COVER
/* Several megabytes each: static, never on the stack. */
static scene s;
static tracer t;
static char text[1 << 16];

/* Writes a scene of 60 spheres and 40 triangles in a cube of side `size` about
 * (offset, offset, offset), seen from `from` towards `at` (both in the cube's units:
 * scaled and offset alike) with the view angle `angle`, up +z; or with `tilt` > 0, up
 * the view direction tilted towards +z by `tilt` roundings of the type, or as little as
 * the parser takes (the camera's right is then only roughly square to its view). */
static void write_scene(double size, double offset, const double from[3], const double at[3],
			double angle, double tilt)
{
	double up[3] = {0.0, 0.0, 1.0};
	size_t n = 0;
	int i, k;
	test_seed(77);
	if (tilt > 0.0) {
		double length = 0.0;
		for (k = 0; k < 3; k++) {
			up[k] = at[k] - from[k];
			length += up[k] * up[k];
		}
		/* Not below 4e-9: the parser refuses an up within 1e-9 of the view direction. */
		up[2] += (tilt * (double)REAL_EPSILON > 4e-9 ? tilt * (double)REAL_EPSILON : 4e-9) *
			 sqrt(length);
	}
	n += (size_t)snprintf(text + n, sizeof text - n,
			      "v\nfrom %.17g %.17g %.17g\nat %.17g %.17g %.17g\nup %.17g %.17g %.17g\n"
			      "angle %g\nhither 0.001\nresolution 8 8\nl 0 0 100\nf 1 1 1 1 0 0 0 1\n",
			      offset + size * from[0], offset + size * from[1], offset + size * from[2],
			      offset + size * at[0], offset + size * at[1], offset + size * at[2], up[0],
			      up[1], up[2], angle);
	for (i = 0; i < 60; i++)
		n += (size_t)snprintf(text + n, sizeof text - n, "s %.17g %.17g %.17g %.17g\n",
				      offset + size * test_random_range(-1.0, 1.0),
				      offset + size * test_random_range(-1.0, 1.0),
				      offset + size * test_random_range(-1.0, 1.0),
				      size * test_random_range(0.01, 0.15));
	for (i = 0; i < 40; i++) {
		double c[3];
		for (k = 0; k < 3; k++)
			c[k] = test_random_range(-1.0, 1.0);
		n += (size_t)snprintf(text + n, sizeof text - n, "p 3\n");
		for (k = 0; k < 3; k++)
			n += (size_t)snprintf(text + n, sizeof text - n, "%.17g %.17g %.17g\n",
					      offset + size * (c[0] + test_random_range(-0.2, 0.2)),
					      offset + size * (c[1] + test_random_range(-0.2, 0.2)),
					      offset + size * (c[2] + test_random_range(-0.2, 0.2)));
	}
}

typedef struct {
	long rays, passed_over, edges, wrong;
} tally;

/* Is a ray the cover passes over one that meets nothing? */
static void check_ray(tally *y, const accel *a, const ray *r, int *was_passed)
{
	int passed = eye_cover_misses(&t.cover, r);
	y->rays++;
	if (passed) {
		hit h;
		y->passed_over++;
		y->wrong += scene_intersect(a, r, REAL_FAR, &h);
	}
	y->edges += *was_passed >= 0 && passed != *was_passed;
	*was_passed = passed;
}

/* Every ray of 64 image lines of a 160 x 120 image, and antialiasing's points between
 * pixels (no line plane), checked. */
static void check_view(tally *y, const char *name)
{
	const accel *a;
	camera c;
	int line, x;
	if (!CHECK(test_parse_buffer(&s, name, text, NULL, NULL)))
		return;
	a = test_accel(&s, 1);
	if (!CHECK(a->tree.node_count > 0) || !CHECK(camera_init(&c, &s.camera, 160, 120) == NULL))
		return;
	trace_init(&t, a, 5, REAL_C(0.0));
	for (line = 0; line < 64; line++) {
		int y2 = (int)test_random_range(0.0, 241.0), was_passed = -1;
		camera_line l = camera_line_at(&c, y2, 1);
		trace_eye_line(&t, l.normal);
		for (x = 0; x < 160; x++) {
			ray r;
			camera_next_ray(&l, &r);
			check_ray(y, a, &r, &was_passed);
		}
	}
	trace_eye_line(&t, dir_make(UNIT_C(0.0), UNIT_C(0.0), UNIT_C(0.0)));
	for (x = 0; x < 4000; x++) {
		ray r;
		int was_passed = -1;
		camera_ray_at(&c, (long)test_random_range(0.0, 160.0 * 16), (long)test_random_range(0.0, 120.0 * 16),
			      3, &r);
		check_ray(y, a, &r, &was_passed);
	}
}

static void test_views(void)
{
	static const double scales[][2] = {{1.0, 0.0}, {1e-4, 0.0}, {1e3, 0.0}, {1.0, 1e5}, {0.01, 30.0}};
	static const double views[][8] = {
		/* from, at, angle, up's tilt */
		{6, -9, 4, 0, 0, 0, 20, 0},     /* far: most of the image misses */
		{3, -4, 2, 0, 0, 0, 60, 0},     /* near */
		{0.1, 0.2, 0.05, 1, 0, 0, 90, 0}, /* inside the cluster */
		{4, 0, 0, 0, 3, 0, 40, 0},      /* the cluster at the edge of the view */
		{1.3, -1.3, 0.2, 0, 0, 0, 170, 0}, /* just outside, very wide */
		{200, -300, 100, 0, 0, 0, 0.5, 0}, /* very far, very narrow */
		{6, -9, 4, 0, 0, 0, 40, 0.5},     /* far, up almost the view direction */
		{3, -4, 2, 0, 0, 0, 90, 1},   /* near, the same */
	};
	tally far = {0, 0, 0, 0}, all = {0, 0, 0, 0};
	size_t i, j;
	for (i = 0; i < sizeof scales / sizeof scales[0]; i++)
		for (j = 0; j < sizeof views / sizeof views[0]; j++) {
			tally y = {0, 0, 0, 0};
			write_scene(scales[i][0], scales[i][1], views[j], views[j] + 3, views[j][6],
				    views[j][7]);
			check_view(&y, "cover.nff");
			if (j == 0 && i == 0)
				far = y;
			all.rays += y.rays;
			all.passed_over += y.passed_over;
			all.edges += y.edges;
			all.wrong += y.wrong;
		}
	/* The far view: most rays passed over, along many edges of the covered spans. */
	CHECK(far.rays == 64 * 160 + 4000);
	CHECK(far.passed_over > far.rays / 3);
	CHECK(far.edges > 100);
	CHECK(all.passed_over > all.rays / 5);
	CHECK(all.edges > 600);
	CHECK_INT((int)all.wrong, 0);
}

/* A floor of 12 x 12 square tiles filling [-1, 1]^2 (at scale and offset), seen from
 * several points: every box of the hierarchy is a rectangle of whole tiles, so the ray
 * through a box's extreme corner (a tiles' corner, which the half-open rule gives to a
 * tile when it is the floor's top right one) or just inside it meets a tile and is seen
 * at the very edge of the box's span. Rays through every tiles' corner, and moved in and
 * out from it along the diagonals by 10^-12, 10^-5 and 10^-2 of the floor, are checked. */
static void test_floor_corners(void)
{
	static const double scales[][2] = {{1.0, 0.0}, {1e-4, 0.0}, {1e3, 0.0}, {1.0, 1e5}};
	static const double views[][3] = {{5, -7, 4}, {-8, -3, 2}, {1, 0.5, 7}, {7, 7, 1}};
	tally y = {0, 0, 0, 0};
	long hits = 0;
	size_t i, j;
	for (i = 0; i < sizeof scales / sizeof scales[0]; i++)
		for (j = 0; j < sizeof views / sizeof views[0]; j++) {
			double size = scales[i][0], offset = scales[i][1];
			size_t n = 0;
			int row, column, corner, was_passed = -1;
			const accel *a;
			n += (size_t)snprintf(text + n, sizeof text - n,
					      "v\nfrom %.17g %.17g %.17g\nat %.17g %.17g %.17g\nup 0 0 1\n"
					      "angle 60\nhither 0.001\nresolution 8 8\nl 0 0 100\n"
					      "f 1 1 1 1 0 0 0 1\n",
					      offset + size * views[j][0], offset + size * views[j][1],
					      offset + size * views[j][2], offset, offset, offset);
			for (row = 0; row < 12; row++)
				for (column = 0; column < 12; column++) {
					double x0 = offset + size * (column / 6.0 - 1.0),
					       x1 = offset + size * ((column + 1) / 6.0 - 1.0),
					       y0 = offset + size * (row / 6.0 - 1.0),
					       y1 = offset + size * ((row + 1) / 6.0 - 1.0);
					n += (size_t)snprintf(text + n, sizeof text - n,
							      "p 4\n%.17g %.17g %.17g\n%.17g %.17g %.17g\n"
							      "%.17g %.17g %.17g\n%.17g %.17g %.17g\n",
							      x0, y0, offset, x1, y0, offset, x1, y1, offset,
							      x0, y1, offset);
				}
			if (!CHECK(test_parse_buffer(&s, "floor.nff", text, NULL, NULL)))
				continue;
			a = test_accel(&s, 1);
			if (!CHECK(a->tree.node_count > 0))
				continue;
			trace_init(&t, a, 5, REAL_C(0.0));
			if (!CHECK(t.cover.enabled))
				continue;
			trace_eye_line(&t, dir_make(UNIT_C(0.0), UNIT_C(0.0), UNIT_C(0.0)));
			for (row = 0; row <= 12; row++)
				for (column = 0; column <= 12; column++)
					for (corner = 0; corner < 4 * 7; corner++) {
						static const double moves[7] = {0.0,    1e-12,  1e-5, 1e-2,
										-1e-12, -1e-5, -1e-2};
						double in = moves[corner / 4], x = column / 6.0 - 1.0,
						       z = row / 6.0 - 1.0;
						hit found;
						ray r;
						/* The tiles' corner, moved in or out along a diagonal. */
						x += corner & 1 ? -in : in;
						z += corner & 2 ? -in : in;
						r = test_ray(s.camera.from,
							     vec_sub(vec_make((real)(offset + size * x),
									      (real)(offset + size * z),
									      (real)offset),
								     s.camera.from));
						hits += scene_intersect(a, &r, REAL_FAR, &found);
						check_ray(&y, a, &r, &was_passed);
					}
		}
	CHECK(y.rays > 1000);
	CHECK(hits > y.rays / 4);
	CHECK(y.passed_over >= 16); /* the floor's outer corners, moved out */
	CHECK_INT((int)y.wrong, 0);
}
#endif

void suite_eye_cover(void)
{
#if EYE_COVER
	test_views();
	test_floor_corners();
#endif
}
