/* test_clearance.c - each shape's clearance is a lower bound of the true distance from a
 * point to its surface, and near the surface (where it decides anything) within a factor
 * of two of it; the parser keeps each light's, and fixed point refuses an eye it cannot
 * hold off a floor.
 * See LICENSE for copyright and licence. */
#include <math.h>
#include <stdio.h>

#include "clearance.h"
#include "shape.h"
#include "support.h"
#include "test.h"

/* Several megabytes: static, never on the stack. */
static scene s;

static double outside_of(double x, double low, double high)
{
	return x < low ? low - x : x > high ? x - high : 0.0;
}

/* The true distances, in double, to the shapes of `shapes` below. */
static double sphere_distance(double x, double y, double z)
{
	return fabs(sqrt(x * x + y * y + z * z) - 1.0);
}

static double plane_distance(double x, double y, double z)
{
	(void)x;
	(void)y;
	return fabs(z);
}

static double square_distance(double x, double y, double z)
{
	double gx = outside_of(x, -1.0, 1.0), gy = outside_of(y, -1.0, 1.0);
	return sqrt(gx * gx + gy * gy + z * z);
}

static double box_distance(double x, double y, double z)
{
	double gx = outside_of(x, -1.0, 1.0), gy = outside_of(y, -1.0, 1.0),
	       gz = outside_of(z, -1.0, 1.0);
	double in = fmin(1.0 - fabs(x), fmin(1.0 - fabs(y), 1.0 - fabs(z)));
	return gx > 0 || gy > 0 || gz > 0 ? sqrt(gx * gx + gy * gy + gz * gz) : in;
}

/* The cone from radius 1 at z = 0 to 0.5 at z = 2: in (z, rho) the segment from (0, 1) to
 * (2, 0.5). */
static double cone_distance(double x, double y, double z)
{
	double rho = sqrt(x * x + y * y), ez = 2.0, er = -0.5;
	double t = (z * ez + (rho - 1.0) * er) / (ez * ez + er * er);
	double dz, dr;
	t = t < 0.0 ? 0.0 : t > 1.0 ? 1.0 : t;
	dz = z - t * ez;
	dr = rho - (1.0 + t * er);
	return sqrt(dz * dz + dr * dr);
}

static const struct {
	const char *name, *nff;
	double (*distance)(double, double, double);
} shapes[] = {
	{"sphere", "s 0 0 0 1\n", sphere_distance},
	{"plane", "plane 0 0 0 0 0 1\n", plane_distance},
	{"square", "p 4\n-1 -1 0\n1 -1 0\n1 1 0\n-1 1 0\n", square_distance},
	{"box", "box -1 -1 -1 1 1 1\n", box_distance},
#if RT_SHAPE_CONE
	{"cone", "c\n0 0 0 1\n0 0 2 0.5\n", cone_distance},
#endif
};

/* Points on a grid over [-2.5, 2.5]^3 whose step (0.37) puts none exactly on a face. */
static void test_lower_bounds(void)
{
	size_t k;
	for (k = 0; k < sizeof shapes / sizeof shapes[0]; k++) {
		static char text[512];
		int i, j, l, above = 0, loose = 0, points = 0;
		double scale_of;
		snprintf(text, sizeof text,
			 "v\nfrom 0 -10 3\nat 0 0 0\nup 0 0 1\nangle 40\nhither 1\nresolution 8 8\n"
			 "l 5 -5 5\nf 1 1 1 1 0 0 0 1\n%s",
			 shapes[k].nff);
		if (!CHECK(test_parse_buffer(&s, shapes[k].name, text, NULL, NULL)) ||
		    !CHECK_INT(s.object_count, 1))
			continue;
		scale_of = test_scale(s.length_shift);
		for (i = 0; i < 14; i++)
			for (j = 0; j < 14; j++)
				for (l = 0; l < 14; l++) {
					double x = -2.5 + 0.37 * i, y = -2.5 + 0.37 * j,
					       z = -2.5 + 0.37 * l;
					double d = shapes[k].distance(x, y, z);
					vec3 p = vec_make(test_scaled(x, s.length_shift),
							  test_scaled(y, s.length_shift),
							  test_scaled(z, s.length_shift));
					double c = test_double(shape_clearance(&s, &s.objects[0], &p)) / scale_of;
					points++;
					/* Rounding: the type's, or 8 Q16.16 steps at the scene's scale. */
					above += c > d * (1.0 + 1e-5) + TOL3(1e-5, 1e-12, 8 * LSB / scale_of);
					loose += d < 1.0 && c < 0.5 * d - TOL3(1e-5, 1e-12, 8 * LSB / scale_of);
				}
		if (!CHECK_INT(above, 0) || !CHECK_INT(loose, 0))
			printf("  %s: %d of %d points above the distance, %d below half of it\n",
			       shapes[k].name, above, points, loose);
	}
}

/* The parser keeps each light's clearance: the nearest surface's, here a floor's. */
static void test_light_clearance(void)
{
	static const char text[] = "v\nfrom 0 -10 3\nat 0 0 0\nup 0 0 1\nangle 40\nhither 1\n"
				   "resolution 8 8\nl 1 2 0.25\nl 0 0 3\nf 1 1 1 1 0 0 0 1\n"
				   "p 4\n-5 -5 0\n5 -5 0\n5 5 0\n-5 5 0\ns 0 0 4 0.5\n";
	double scale_of;
	if (!CHECK(test_parse_buffer(&s, "lights", text, NULL, NULL)))
		return;
	scale_of = test_scale(s.length_shift);
	CHECK_NEAR(test_double(s.lights[0].clearance) / scale_of, 0.25, TOL3(1e-6, 1e-12, 4 * LSB / scale_of));
	CHECK_NEAR(test_double(s.lights[1].clearance) / scale_of, 0.5, TOL3(1e-6, 1e-12, 4 * LSB / scale_of));
}

/* Fixed point refuses an eye that Q16.16 would round onto a floor (1e-9 above it, in a
 * scene 10 across) and takes one 1e-3 above it; floating point takes both. */
static void test_eye_placement(void)
{
	static char text[512];
	static const char *const heights[] = {"0.000000001", "0.001"};
	int i;
	for (i = 0; i < 2; i++) {
		snprintf(text, sizeof text,
			 "v\nfrom 0 -4.5 %s\nat 0 0 %s\nup 0 0 1\nangle 60\nhither 1e-10\n"
			 "resolution 8 8\nl 2 -4 6\nf 1 1 1 1 0 0 0 1\np 4\n-5 -5 0\n5 -5 0\n5 5 0\n"
			 "-5 5 0\n",
			 heights[i], heights[i]);
		CHECK_INT(test_parse_buffer(&s, "eye", text, NULL, NULL), REAL_FIXED && i == 0 ? 0 : 1);
	}
}

void suite_clearance(void)
{
	test_lower_bounds();
	test_light_clearance();
	test_eye_placement();
}
