/* test_cone.c - uncapped cylinders and cones (NFF c): side hits, the open ends, rays
 * parallel to the axis or to a side line, the tip, and NFF's inside-only form.
 * See LICENSE for copyright and licence. */
#include <float.h>
#include <math.h>
#include <stdio.h>

#include "shape.h"
#include "support.h"
#include "test.h"

typedef struct {
	const char *id;
	case_real base[3], apex[3];
	case_real base_radius, apex_radius;
	unsigned flags;
	case_real o[3], d[3]; /* d is normalised here */
	case_real tmin;
	int hit;
	case_real t;
	case_real n[3]; /* expected outward normal, up to length */
} cone_case;

#define TWO OBJ_TWO_SIDED
#define INSIDE (OBJ_TWO_SIDED | OBJ_INSIDE_ONLY)
#define SQRT2 CASE_C(1.4142135623730950488)

/* Cylinder Y: base (0,0,0), top (0,0,2), r 1. Cone K: r 1 at z = 0 to a tip at z = 2.
 * Cone T: r 1 at z = 0 to a tip at z = 1 (a right angle at the tip). */
static const cone_case cases[] = {
	/* Cylinder: the wall from outside and from inside (the normal is outward). */
	{"Y side", {0, 0, 0}, {0, 0, 2}, 1, 1, TWO, {-5, 0, 1}, {1, 0, 0}, 0, 1, 4, {-1, 0, 0}},
	{"Y inside", {0, 0, 0}, {0, 0, 2}, 1, 1, TWO, {0, 0, 1}, {1, 0, 0}, 0, 1, 1, {1, 0, 0}},
	/* Uncapped: the infinite cylinder's wall above and below the ends is not there. */
	{"Y above", {0, 0, 0}, {0, 0, 2}, 1, 1, TWO, {-5, 0, 3}, {1, 0, 0}, 0, 0, 0, {0, 0, 0}},
	{"Y below", {0, 0, 0}, {0, 0, 2}, 1, 1, TWO, {-5, 0, CASE_C(-0.5)}, {1, 0, 0}, 0, 0, 0,
	 {0, 0, 0}},
	/* In through the open top (near root behind the origin), out through the wall. */
	{"Y open top", {0, 0, 0}, {0, 0, 2}, 1, 1, TWO, {0, 0, CASE_C(2.5)}, {1, 0, -1}, 0, 1,
	 SQRT2, {1, 0, 0}},
	/* In through the wall, out through the open top: only the entry. */
	{"Y out top", {0, 0, 0}, {0, 0, 2}, 1, 1, TWO, {-2, 0, CASE_C(0.5)}, {1, 0, 1}, 0, 1,
	 SQRT2, {-1, 0, 0}},
	/* The near root lies above the top, so the far one (the inside of the wall) counts. */
	{"Y far root", {0, 0, 0}, {0, 0, 2}, 1, 1, TWO, {-2, 0, CASE_C(3.5)}, {1, 0, -1}, 0, 1,
	 CASE_C(3.0) * SQRT2, {1, 0, 0}},
	/* Past the near root, the far one. */
	{"Y tmin", {0, 0, 0}, {0, 0, 2}, 1, 1, TWO, {-5, 0, 1}, {1, 0, 0}, CASE_C(4.5), 1, 6,
	 {1, 0, 0}},
	/* Parallel to the axis (a = 0, b = 0): on the axis, inside off it, or outside, the
	 * ray never meets the wall of an uncapped cylinder. */
	{"Y on axis", {0, 0, 0}, {0, 0, 2}, 1, 1, TWO, {0, 0, -5}, {0, 0, 1}, 0, 0, 0, {0, 0, 0}},
	{"Y axis from in", {0, 0, 0}, {0, 0, 2}, 1, 1, TWO, {0, 0, 1}, {0, 0, 1}, 0, 0, 0,
	 {0, 0, 0}},
	{"Y parallel in", {0, 0, 0}, {0, 0, 2}, 1, 1, TWO, {CASE_C(0.5), 0, -5}, {0, 0, 1}, 0, 0, 0,
	 {0, 0, 0}},
	{"Y parallel out", {0, 0, 0}, {0, 0, 2}, 1, 1, TWO, {2, 0, -5}, {0, 0, 1}, 0, 0, 0,
	 {0, 0, 0}},
	/* A slanted cylinder: base (1,2,3), axis (1,1,0)/sqrt 2, length 4, r 0.5. The ray
	 * meets the axis point at height 2, (1+sqrt 2, 2+sqrt 2, 3), straight from below. */
	{"Y slanted", {1, 2, 3},
	 {CASE_C(1.0) + CASE_C(2.0) * SQRT2, CASE_C(2.0) + CASE_C(2.0) * SQRT2, 3}, CASE_C(0.5),
	 CASE_C(0.5), TWO, {CASE_C(1.0) + SQRT2, CASE_C(2.0) + SQRT2, -2}, {0, 0, 1}, 0, 1,
	 CASE_C(4.5), {0, 0, -1}},

	/* Cone K: at z = 1 the radius is 0.5; outward normal (-1, 0, 1/2). */
	{"K side", {0, 0, 0}, {0, 0, 2}, 1, 0, TWO, {-5, 0, 1}, {1, 0, 0}, 0, 1, CASE_C(4.5),
	 {-2, 0, 1}},
	/* The quadric is a double cone: its upper nappe above the tip and its lower part
	 * below the base are not the cone. */
	{"T above tip", {0, 0, 0}, {0, 0, 1}, 1, 0, TWO, {-5, 0, CASE_C(1.5)}, {1, 0, 0}, 0, 0, 0,
	 {0, 0, 0}},
	{"T below base", {0, 0, 0}, {0, 0, 1}, 1, 0, TWO, {-5, 0, CASE_C(-0.5)}, {1, 0, 0}, 0, 0,
	 0, {0, 0, 0}},
	/* Parallel to a side line (a = 0, the linear case): one root, in through the open
	 * base, out through the far wall at (-0.25, 0, 0.75). */
	{"T parallel side", {0, 0, 0}, {0, 0, 1}, 1, 0, TWO, {1, 0, CASE_C(-0.5)}, {-1, 0, 1}, 0, 1,
	 CASE_C(1.25) * SQRT2, {-1, 0, 1}},
	/* Parallel to the axis inside: the upper nappe's root (z = 1.5) is cut off. */
	{"T parallel axis", {0, 0, 0}, {0, 0, 1}, 1, 0, TWO, {CASE_C(0.5), 0, -5}, {0, 0, 1}, 0, 1,
	 CASE_C(5.5), {1, 0, 1}},
	/* Along the axis, or across it, through the tip: the ray touches the cone at one
	 * point, where the side has no normal. A touch is a hit (as a sphere's tangent,
	 * S05), with the axis out of the tip as its unit normal. */
	{"T tip down axis", {0, 0, 0}, {0, 0, 1}, 1, 0, TWO, {0, 0, 5}, {0, 0, -1}, 0, 1, 4,
	 {0, 0, 1}},
	{"T tip up axis", {0, 0, 0}, {0, 0, 1}, 1, 0, TWO, {0, 0, -5}, {0, 0, 1}, 0, 1, 6,
	 {0, 0, 1}},
	{"T tip across", {0, 0, 0}, {0, 0, 1}, 1, 0, TWO, {-5, 0, 1}, {1, 0, 0}, 0, 1, 5,
	 {0, 0, 1}},
	/* A frustum, r 1 at z = 0 to r 0.5 at z = 1: at z = 0.5 the radius is 0.75. */
	{"frustum", {0, 0, 0}, {0, 0, 1}, 1, CASE_C(0.5), TWO, {-5, 0, CASE_C(0.5)}, {1, 0, 0}, 0,
	 1, CASE_C(4.25), {-2, 0, 1}},
	/* Widening upward, tip at the base: the normal points down and out. */
	{"inverted", {0, 0, 0}, {0, 0, 1}, 0, 1, TWO, {-5, 0, CASE_C(0.5)}, {1, 0, 0}, 0, 1,
	 CASE_C(4.5), {-1, 0, -1}},
	{"inverted tip", {0, 0, 0}, {0, 0, 1}, 0, 1, TWO, {0, 0, -5}, {0, 0, 1}, 0, 1, 5,
	 {0, 0, -1}},

	/* From a distant eye (1,000 times the cylinder's radius), straight on and just
	 * inside and outside its silhouette: the quadratic set up from the eye itself lost
	 * the cylinder's size to the distance's square (float's step at 10^6 is 0.06). */
	{"Y far", {0, 0, 0}, {0, 0, 2}, 1, 1, TWO, {-1000, 0, 1}, {1, 0, 0}, 0, 1, 999, {-1, 0, 0}},
	{"Y far graze in", {0, 0, 0}, {0, 0, 2}, 1, 1, TWO, {-1000, CASE_C(0.99), 1}, {1, 0, 0}, 0,
	 1, CASE_C(999.8589326402033), {CASE_C(-0.14106735979665894), CASE_C(0.99), 0}},
	{"Y far graze out", {0, 0, 0}, {0, 0, 2}, 1, 1, TWO, {-1000, CASE_C(1.001), 1}, {1, 0, 0},
	 0, 0, 0, {0, 0, 0}},
	{"K far", {0, 0, 0}, {0, 0, 2}, 1, 0, TWO, {-1000, 0, 1}, {1, 0, 0}, 0, 1, CASE_C(999.5),
	 {-2, 0, 1}},

	/* NFF's negative radii: only the inside shows. From outside, the far wall. */
	{"Y inside-only", {0, 0, 0}, {0, 0, 2}, 1, 1, INSIDE, {-5, 0, 1}, {1, 0, 0}, 0, 1, 6,
	 {1, 0, 0}},
	{"Y inside-only in", {0, 0, 0}, {0, 0, 2}, 1, 1, INSIDE, {0, 0, 1}, {1, 0, 0}, 0, 1, 1,
	 {1, 0, 0}},
	/* In through the wall's outside and out through the open top: nothing visible. */
	{"Y inside-only top", {0, 0, 0}, {0, 0, 2}, 1, 1, INSIDE, {-2, 0, CASE_C(0.5)}, {1, 0, 1},
	 0, 0, 0, {0, 0, 0}},
	{"K inside-only", {0, 0, 0}, {0, 0, 2}, 1, 0, INSIDE, {-5, 0, 1}, {1, 0, 0}, 0, 1,
	 CASE_C(5.5), {2, 0, 1}},
};

/* The largest coordinate of a case's scene (ray origin, base and apex, with a radius
 * beyond them): what the parser would scale it by in fixed point. */
static double case_extent(const cone_case *k)
{
	double e = 0.0, r = (double)k->base_radius > (double)k->apex_radius
				    ? (double)k->base_radius
				    : (double)k->apex_radius;
	int i;
	for (i = 0; i < 3; i++) {
		double v[3];
		v[0] = fabs((double)k->o[i]);
		v[1] = fabs((double)k->base[i]) + r;
		v[2] = fabs((double)k->apex[i]) + r;
		e = v[0] > e ? v[0] : e;
		e = v[1] > e ? v[1] : e;
		e = v[2] > e ? v[2] : e;
	}
	return e;
}

static vec3 scaled(const case_real v[3], int shift)
{
	return vec_make(CASE_REAL(v[0], shift), CASE_REAL(v[1], shift), CASE_REAL(v[2], shift));
}

static object make_cone(const cone_case *k, int shift)
{
	object o;
	vec3 base = scaled(k->base, shift);
	vec3 axis = vec_sub(scaled(k->apex, shift), base);
	real length = vec_length(axis);
	/* As the parser stores it. */
	o.kind = SHAPE_CONE;
	o.flags = (unsigned char)k->flags;
	o.material = 0;
	o.line = 0;
	o.u.cone.base = base;
	o.u.cone.axis = dir_normalize(axis);
	o.u.cone.length = length;
	o.u.cone.base_radius = CASE_REAL(k->base_radius, shift);
	o.u.cone.apex_radius = CASE_REAL(k->apex_radius, shift);
	o.u.cone.slope = real_div(o.u.cone.apex_radius - o.u.cone.base_radius, length);
	return o;
}

/* Tolerances: t and the hit point at the case's scale (Q16.16: 2^9 for most cases, 2^8
 * for the slanted cylinder), the normal as a unit vector. In Q16.16 t is good to 2^-16
 * of t (the rounded direction's length, real.h) and 2 LSB; the point is o + t d to 2
 * LSB, and the normal to an LSB. */
#define T_TOL(t) TOL3(2e-6, 1e-12, ((t) + 2.0) * LSB)
#define P_TOL TOL3(2e-6, 1e-12, 2 * LSB)
#define N_TOL TOL3(1e-6, 1e-12, 1 * LSB)

static void run_case(const cone_case *k)
{
	/* Fixed point: the case as the parser would scale it; floating point: shift 0. */
	int shift = test_shift(case_extent(k));
	double scale = test_scale(shift);
	object o = make_cone(k, shift);
	ray r;
	hit h;
	char what[64];
	double nx = (double)k->n[0], ny = (double)k->n[1], nz = (double)k->n[2];
	double len = sqrt(nx * nx + ny * ny + nz * nz);
	int got;

	r.origin = scaled(k->o, shift);
	r.dir = dir_normalize(scaled(k->d, 0));
	got = cone_intersect(&o, &r, CASE_REAL(k->tmin, shift), REAL_MAX, &h);
	snprintf(what, sizeof what, "%s: %s", k->id, k->hit ? "expected a hit" : "expected a miss");
	if (!test_check(got == k->hit, __FILE__, __LINE__, what))
		return;
	snprintf(what, sizeof what, "%s: same answer without a hit record", k->id);
	test_check(cone_intersect(&o, &r, CASE_REAL(k->tmin, shift), REAL_MAX, NULL) == got,
		   __FILE__, __LINE__, what);
	if (!got)
		return;
	snprintf(what, sizeof what, "%s t", k->id);
	test_check_near(test_double(h.t), (double)k->t * scale, T_TOL((double)k->t * scale),
			__FILE__, __LINE__, what);
	/* The point is on the ray at t. */
	snprintf(what, sizeof what, "%s point.z", k->id);
	test_check_near(test_double(h.point.z),
			test_double(r.origin.z) + test_double(h.t) * test_unit_double(r.dir.z), P_TOL,
			__FILE__, __LINE__, what);
	snprintf(what, sizeof what, "%s normal.x", k->id);
	test_check_near(test_unit_double(h.normal.x), nx / len, N_TOL, __FILE__, __LINE__, what);
	snprintf(what, sizeof what, "%s normal.y", k->id);
	test_check_near(test_unit_double(h.normal.y), ny / len, N_TOL, __FILE__, __LINE__, what);
	snprintf(what, sizeof what, "%s normal.z", k->id);
	test_check_near(test_unit_double(h.normal.z), nz / len, N_TOL, __FILE__, __LINE__, what);
	snprintf(what, sizeof what, "%s: shading normal = normal", k->id);
	test_check(h.shading.x == h.normal.x && h.shading.y == h.normal.y &&
		   h.shading.z == h.normal.z, __FILE__, __LINE__, what);
}

/* The interval: a hit at t = 4 is outside (0, 3.9). Exact values, at scale 1. */
static void test_interval(void)
{
	object o = make_cone(&cases[0], 0);
	ray r;
	hit h;
	r.origin = vec_make(REAL_C(-5.0), REAL_C(0.0), REAL_C(1.0));
	r.dir = DIR_C(1.0, 0.0, 0.0);
	CHECK(!cone_intersect(&o, &r, REAL_C(0.0), REAL_C(3.9), &h));
	CHECK(cone_intersect(&o, &r, REAL_C(0.0), REAL_C(4.1), &h));
	/* Only the far root inside (4.5, 5.9) would do, and it is at 6. */
	CHECK(!cone_intersect(&o, &r, REAL_C(4.5), REAL_C(5.9), &h));
	/* Behind the origin: nothing. */
	r.dir = DIR_C(-1.0, 0.0, 0.0);
	CHECK(!cone_intersect(&o, &r, REAL_C(0.0), REAL_MAX, &h));
}

/* Long rods met far from their base (floating types; fixed point's range budget is 4096):
 * a cylinder of radius 1 and length L along an oblique axis, centred on the origin, and
 * rays that pass its axis at a distance rho of 0.99 (a hit) or 1.01 (a miss), at
 * heights from a tenth to nine tenths of L and at 20 to 90 degrees to the axis, from 30
 * away. The hit is at t = 30 - sqrt(1 - rho^2) / sin(angle). Set up from the ray's point
 * nearest the base, the quadratic's terms were of the size of L^2 and the rod's own
 * size cancelled away: in double a rod 10^8 long answered these rays by chance. */
static void test_long_rods(void)
{
	int exponent, step, angle, side, failures = 0, tests = 0;
	const int longest = REAL_FLOAT_FREE ? 0 : sizeof(real) == sizeof(float) ? 4 : 9;
	/* The cases are made in double: long double is held to double's precision. */
	const double precision = (double)REAL_EPSILON > DBL_EPSILON ? (double)REAL_EPSILON : DBL_EPSILON;
	for (exponent = 2; exponent <= longest; exponent++)
		for (step = 1; step <= 9; step += 2)
			for (angle = 20; angle <= 90; angle += 35)
				for (side = 0; side < 2; side++) {
					double length = pow(10.0, exponent), rho = side ? 1.01 : 0.99;
					double phi = angle * 3.14159265358979323846 / 180.0;
					double a[3] = {0.48, 0.6, 0.64}; /* unit */
					double e1[3] = {0.78086880944303, -0.62469504755443,
							0.0}; /* unit, across a */
					double e2[3] = {a[1] * e1[2] - a[2] * e1[1],
							a[2] * e1[0] - a[0] * e1[2],
							a[0] * e1[1] - a[1] * e1[0]};
					double height = length * step / 10.0, from[3], d[3];
					object o;
					ray r;
					hit h;
					int k, got;
					for (k = 0; k < 3; k++) {
						d[k] = cos(phi) * a[k] + sin(phi) * e2[k];
						from[k] = (height - length / 2) * a[k] + rho * e1[k] -
							  30.0 * d[k];
					}
					o.kind = SHAPE_CONE;
					o.flags = OBJ_TWO_SIDED;
					o.material = 0;
					o.line = 0;
					cone_init(&o.u.cone,
						  vec_make((real)(-length / 2 * a[0]), (real)(-length / 2 * a[1]),
							   (real)(-length / 2 * a[2])),
						  vec_make((real)a[0], (real)a[1], (real)a[2]), (real)length,
						  REAL_C(1.0), REAL_C(1.0));
					r.origin = vec_make((real)from[0], (real)from[1], (real)from[2]);
					r.dir = dir_normalize(vec_make((real)d[0], (real)d[1], (real)d[2]));
					got = cone_intersect(&o, &r, REAL_C(0.0), REAL_MAX, &h);
					tests++;
					if (got != !side ||
					    (got && fabs((double)h.t - (30.0 - sqrt(1.0 - rho * rho) / sin(phi))) >
							    64.0 * precision * length))
						failures++;
				}
	if (REAL_FLOAT_FREE)
		return;
	CHECK(tests == (sizeof(real) == sizeof(float) ? 3 : 8) * 5 * 3 * 2);
	CHECK(failures == 0);
}

void suite_cone(void)
{
	size_t i;
	for (i = 0; i < sizeof cases / sizeof cases[0]; i++)
		run_case(&cases[i]);
	test_interval();
	test_long_rods();
}
