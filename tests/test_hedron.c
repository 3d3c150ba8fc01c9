/* test_hedron.c - convex polyhedra: the cube cases P01-P13 of numerics.md section 6 and a
 * seeded watertightness test through edges and vertices.
 * See LICENSE for copyright and licence. */
#include <math.h>
#include <stdio.h>

#include "shape.h"
#include "support.h"
#include "test.h"

/* Several megabytes: static, never on the stack. */
static scene s;

/* Where the cube sits: world = rot local + move; rot's columns are the cube's axes. */
typedef struct {
	double rot[3][3];
	double move[3];
} frame;

/* Lengths are scaled by 2^world_shift before they are rounded to real: in fixed point
 * the scale the parser would give the scene, 0 in floating point. */
static int world_shift;

/* The cube |x|, |y|, |z| <= 1 placed by f, as the six half-spaces n.x <= offset in
 * s.planes[0..6). Built in double, then rounded to real once, as a parser would. */
static void set_cube(const frame *f)
{
	int axis, side;
	s.plane_count = 0;
	for (axis = 0; axis < 3; axis++)
		for (side = 0; side < 2; side++) {
			double sign = side ? -1.0 : 1.0;
			double n[3], offset = 1.0;
			int k;
			for (k = 0; k < 3; k++) {
				n[k] = sign * f->rot[k][axis];
				offset += n[k] * f->move[k];
			}
			s.planes[s.plane_count].normal =
				dir_make(test_unit(n[0]), test_unit(n[1]), test_unit(n[2]));
			s.planes[s.plane_count].offset = test_real(ldexp(offset, world_shift));
			s.plane_count++;
		}
}

static const frame unit_cube = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {0, 0, 0}};

static object cube_object(void)
{
	object o;
	o.kind = SHAPE_HEDRON;
	o.flags = OBJ_TWO_SIDED;
	o.material = 0;
	o.line = 0;
	o.u.hedron.first = 0;
	o.u.hedron.count = 6;
	return o;
}

/* What a row expects of the face normal. */
enum { NORMAL_ANY, NORMAL_EXACT, NORMAL_PLUS_X_OR_Y };
enum { MISS, HIT, EITHER };

typedef struct {
	const char *id;
	case_real o[3], d[3];
	case_real tmin;
	int expect;  /* MISS, HIT, or EITHER (degenerate: no NaN, and a hit must be right) */
	case_real t;
	double tol;  /* on t (fixed point: at the case's scale) */
	int normal;  /* NORMAL_* */
	case_real n[3];
} hedron_case;

static const hedron_case cases[] = {
	{"P01", {0, 0, -5}, {0, 0, 1}, 0, HIT, 4, 0, NORMAL_EXACT, {0, 0, -1}},
	/* Parallel to the y slab and outside it: vd = 0, vn > 0. */
	{"P02", {0, 2, -5}, {0, 0, 1}, 0, MISS, 0, 0, NORMAL_ANY, {0, 0, 0}},
	{"P03", {0, CASE_C(0.5), -5}, {0, 0, 1}, 0, HIT, 4, 0, NORMAL_EXACT, {0, 0, -1}},
	/* The ray lies in the plane y = 1: either answer, but no NaN. */
	{"P04", {0, 1, -5}, {0, 0, 1}, 0, EITHER, 4, 0, NORMAL_EXACT, {0, 0, -1}},
	/* Through the edge x = y = 1: the per-face test leaks here. The ray enters the
	 * +x and +y faces at once; either is the entry face. Q16.16 (scale 2^10): t is
	 * good to 2^-16 of t (2896 LSB), the rounded direction's length (real.h). */
	{"P05", {3, 3, CASE_C(0.25)}, {-1, -1, 0}, 0, HIT, CASE_C(2.8284271247461903),
	 TOL3(1e-6, 1e-12, 2900 * LSB), NORMAL_PLUS_X_OR_Y, {0, 0, 0}},
	/* Through the vertex (1, 1, 1); the catalog's tolerance is 1e-12, float's 4 ulp,
	 * Q16.16's 2^-16 of t (3547 LSB at scale 2^10). */
	{"P06", {3, 3, 3}, {-1, -1, -1}, 0, HIT, CASE_C(3.46410161513775459),
	 TOL3(1e-6, 1e-12, 3550 * LSB),
	 NORMAL_ANY, {0, 0, 0}},
	/* Along the edge line x = y = 1: degenerate, Haines keeps it (both slabs touch). */
	{"P07", {1, 1, -5}, {0, 0, 1}, 0, HIT, 4, 0, NORMAL_EXACT, {0, 0, -1}},
	/* 1.4e-4 outside the edge x = -1, y = 1. */
	{"P08", {CASE_C(-2.0) + CASE_C(1e-4), CASE_C(4.0) + CASE_C(1e-4), CASE_C(0.25)},
	 {1, -1, 0}, 0, MISS, 0, 0, NORMAL_ANY, {0, 0, 0}},
	/* From inside: the exit. */
	{"P09", {0, 0, 0}, {0, 0, 1}, 0, HIT, 1, 0, NORMAL_EXACT, {0, 0, 1}},
	/* On a face, leaving: the published code returns a t = 0 self-hit. */
	{"P10", {0, 0, 1}, {0, 0, 1}, CASE_C(1e-9), MISS, 0, 0, NORMAL_ANY, {0, 0, 0}},
	/* On a face, entering: not the face it starts on, but the far one at t = 2. */
	{"P11", {0, 0, 1}, {0, 0, -1}, CASE_C(1e-9), HIT, 2, 0, NORMAL_EXACT, {0, 0, -1}},
	/* P05 moved by less than an ulp (or, in long double, by 1e-17 outward in y, which
	 * still enters at t = 2 sqrt 2 + 1e-17): the same answer. In Q16.16 1e-17 is no
	 * move at all: P05 exactly. */
	{"P12", {3, CASE_C(3.0) + CASE_C(1e-17), CASE_C(0.25)}, {-1, -1, 0}, 0, HIT,
	 CASE_C(2.8284271247461903), TOL3(1e-6, 1e-12, 2900 * LSB), NORMAL_PLUS_X_OR_Y, {0, 0, 0}},
};

/* The largest coordinate of a case's scene (the ray's origin and the cube). */
static double case_extent(const hedron_case *k)
{
	double e = 1.0;
	int i;
	for (i = 0; i < 3; i++)
		e = fabs((double)k->o[i]) > e ? fabs((double)k->o[i]) : e;
	return e;
}

static void run_case(const object *o, const hedron_case *k)
{
	/* Fixed point: the case as the parser would scale it (2^9 here), with the cube
	 * scaled alike; floating point: shift 0. */
	int shift = test_shift(case_extent(k));
	ray r = test_ray(vec_make(CASE_REAL(k->o[0], shift), CASE_REAL(k->o[1], shift),
				  CASE_REAL(k->o[2], shift)),
			 vec_make(CASE_REAL(k->d[0], 0), CASE_REAL(k->d[1], 0),
				  CASE_REAL(k->d[2], 0)));
	real tmin = CASE_REAL(k->tmin, shift);
	char what[64];
	hit h;
	int got;

	/* P10, P11's tmin of 1e-9 is below an LSB at any scale: there it is 1 LSB. */
	if (REAL_FIXED && k->tmin > 0 && tmin == REAL_C(0.0))
		tmin = test_real(LSB);
	world_shift = shift;
	set_cube(&unit_cube);
	got = hedron_intersect(&s, o, &r, tmin, REAL_MAX, &h);
	if (k->expect != EITHER) {
		snprintf(what, sizeof what, "%s: %s", k->id,
			 k->expect == HIT ? "expected a hit" : "expected a miss");
		if (!test_check(got == k->expect, __FILE__, __LINE__, what))
			return;
	}
	snprintf(what, sizeof what, "%s: same answer without a hit record", k->id);
	test_check(hedron_intersect(&s, o, &r, tmin, REAL_MAX, NULL) == got, __FILE__, __LINE__,
		   what);
	if (!got)
		return;
	snprintf(what, sizeof what, "%s t", k->id);
	test_check_near(test_double(h.t), (double)k->t * test_scale(shift), k->tol, __FILE__,
			__LINE__, what);
	if (k->normal == NORMAL_EXACT) {
		snprintf(what, sizeof what, "%s: normal (%g, %g, %g)", k->id, (double)k->n[0],
			 (double)k->n[1], (double)k->n[2]);
		test_check(h.normal.x == CASE_UNIT(k->n[0]) &&
				   h.normal.y == CASE_UNIT(k->n[1]) &&
				   h.normal.z == CASE_UNIT(k->n[2]),
			   __FILE__, __LINE__, what);
	} else if (k->normal == NORMAL_PLUS_X_OR_Y) {
		snprintf(what, sizeof what, "%s: normal +x or +y", k->id);
		test_check(h.normal.z == UNIT_C(0.0) &&
				   ((h.normal.x == UNIT_C(1.0) && h.normal.y == UNIT_C(0.0)) ||
				    (h.normal.x == UNIT_C(0.0) && h.normal.y == UNIT_C(1.0))),
			   __FILE__, __LINE__, what);
	}
}

/* P13: a zero direction must be rejected where rays are made; normalising it gives NaN
 * (rt's vec_normalize keeps it zero). Either way the polyhedron must answer "miss".
 * Q16.16 has no NaN: there only the zero direction is checked. */
static void test_bad_direction(const object *o)
{
	ray r;
	world_shift = 0;
	set_cube(&unit_cube);
#if !REAL_FIXED
	r.dir = dir_make(REAL_C(NAN), REAL_C(NAN), REAL_C(NAN));
	r.origin = vec_make(0, 0, -5);
	CHECK(!hedron_intersect(&s, o, &r, 0, REAL_MAX, NULL));
	r.origin = vec_make(0, 0, 0);
	CHECK(!hedron_intersect(&s, o, &r, 0, REAL_MAX, NULL));
	/* One NaN component is enough to poison every plane it meets. */
	r.dir = dir_make(REAL_C(NAN), 0, 1);
	CHECK(!hedron_intersect(&s, o, &r, 0, REAL_MAX, NULL));
#endif
	r.origin = vec_make(REAL_C(0.0), REAL_C(0.0), REAL_C(0.0));
	r.dir = dir_normalize(vec_make(REAL_C(0.0), REAL_C(0.0), REAL_C(0.0)));
	CHECK(!hedron_intersect(&s, o, &r, REAL_C(0.0), REAL_MAX, NULL));
	r.origin = vec_make(REAL_C(0.0), REAL_C(0.0), REAL_C(-5.0));
	CHECK(!hedron_intersect(&s, o, &r, REAL_C(0.0), REAL_MAX, NULL));
}

/* ---- watertightness ------------------------------------------------------------ */

/* -1 or 1, as likely (test.h's seeded generator). */
static double rnd_sign(void) { return test_random() < 0.5 ? -1.0 : 1.0; }

/* A point (moved) or a direction (only rotated) from cube to world coordinates. */
static void to_world(const frame *f, const double local[3], double w[3], int is_point)
{
	int i;
	for (i = 0; i < 3; i++)
		w[i] = f->rot[i][0] * local[0] + f->rot[i][1] * local[1] + f->rot[i][2] * local[2] +
		       (is_point ? f->move[i] : 0.0);
}

static void normalize3(double v[3])
{
	double len = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
	v[0] /= len;
	v[1] /= len;
	v[2] /= len;
}

/* A point, times 2^world_shift, or a direction, as real. */
static vec3 to_point(const double v[3])
{
	return vec_make(test_real(ldexp(v[0], world_shift)), test_real(ldexp(v[1], world_shift)),
			test_real(ldexp(v[2], world_shift)));
}
static vec3 to_vec(const double v[3])
{
	return vec_make(test_real(v[0]), test_real(v[1]), test_real(v[2]));
}

/* A ray whose origin lies `back` before the world point p along the unit direction dir. */
static ray ray_through(const double p[3], const double dir[3], double back)
{
	double o[3];
	int i;
	for (i = 0; i < 3; i++)
		o[i] = p[i] - back * dir[i];
	return test_ray(to_point(o), to_vec(dir));
}

/* A point on a cube edge (vertex = 0) or a vertex (vertex = 1), in cube coordinates,
 * with the signs of its fixed coordinates; `free_axis` is the edge's direction. */
static void pick_boundary_point(int vertex, double local[3], double signs[3], int *free_axis)
{
	int i;
	*free_axis = vertex ? -1 : (int)(test_random() * 3.0);
	for (i = 0; i < 3; i++) {
		signs[i] = i == *free_axis ? 0.0 : rnd_sign();
		local[i] = i == *free_axis ? test_random_range(-0.95, 0.95) : signs[i];
	}
}

/* Where an entry point may be off, at the test's scale. Q16.16: its directions are good
 * to 2^-17 (float's to 2^-24), and a grazing entry multiplies that by t over the sine
 * of its angle to the face; over these seeded rays (t up to 10) measured up to 2.1e-3. */
#define POINT_TOL TOL3(1e-3, 1e-9, 5e-3 * scale)
#define FACE_TOL TOL3(1e-6, 1e-6, LSB)

/* Rays through edges and vertices into the interior must all hit (0 leaks), enter on a
 * face that meets there, at that point; rays passing 1e-3 outside must all miss. */
static void watertight(const char *name, const frame *f)
{
	enum { RAYS = 20000 };
	object o = cube_object();
	int leaks = 0, wrong_face = 0, wrong_point = 0, false_hits = 0, vertex, n;
	double scale;
	char what[96];

	/* Fixed point: the scale the parser would give the cube and the ray origins (up to
	 * 10 away); 0 in floating point. Hit points are compared at that scale. */
	world_shift = test_shift(fabs(f->move[0]) + fabs(f->move[1]) + fabs(f->move[2]) + 12.0);
	scale = test_scale(world_shift);
	set_cube(f);
	for (vertex = 0; vertex < 2; vertex++) {
		for (n = 0; n < RAYS; n++) {
			double local[3], signs[3], target[3], dl[3], p[3], dir[3], face[3];
			int free_axis, i, face_ok = 0;
			ray r;
			hit h;
			pick_boundary_point(vertex, local, signs, &free_axis);
			/* Aim at a random interior point: the exact answer is "hit". */
			for (i = 0; i < 3; i++) {
				target[i] = test_random_range(-0.9, 0.9);
				dl[i] = target[i] - local[i];
			}
			to_world(f, local, p, 1);
			to_world(f, dl, dir, 0);
			normalize3(dir);
			r = ray_through(p, dir, test_random_range(0.5, 10.0));
			if (!hedron_intersect(&s, &o, &r, 0, REAL_MAX, &h)) {
				leaks++;
				continue;
			}
			/* The entry face is one of those meeting at the edge or vertex. */
			for (i = 0; i < 3; i++) {
				double ln[3] = {0, 0, 0};
				if (signs[i] == 0.0)
					continue;
				ln[i] = signs[i];
				to_world(f, ln, face, 0);
				/* Q16.16: the plane normals are rounded to half an LSB. */
				if (fabs(test_unit_double(h.normal.x) - face[0]) < FACE_TOL &&
				    fabs(test_unit_double(h.normal.y) - face[1]) < FACE_TOL &&
				    fabs(test_unit_double(h.normal.z) - face[2]) < FACE_TOL)
					face_ok = 1;
			}
			wrong_face += !face_ok;
			/* Where: at p, up to the ray's rounding (grazing entries amplify it). */
			if (!(fabs(test_double(h.point.x) - p[0] * scale) < POINT_TOL &&
			      fabs(test_double(h.point.y) - p[1] * scale) < POINT_TOL &&
			      fabs(test_double(h.point.z) - p[2] * scale) < POINT_TOL))
				wrong_point++;
		}
		/* 1e-3 outside the edge or vertex, in the plane through it that separates it
		 * from the cube: every such ray misses the cube by 1e-3. */
		for (n = 0; n < RAYS; n++) {
			double local[3], signs[3], away[3], along[3], p[3], dir[3];
			double len = vertex ? sqrt(3.0) : sqrt(2.0), dot = 0.0;
			int free_axis, i;
			ray r;
			pick_boundary_point(vertex, local, signs, &free_axis);
			for (i = 0; i < 3; i++) {
				away[i] = signs[i] / len;
				local[i] += 1e-3 * away[i];
				along[i] = test_random_range(-1.0, 1.0);
				dot += along[i] * away[i];
			}
			/* Remove the component along `away`: a random direction in the plane. */
			for (i = 0; i < 3; i++)
				along[i] -= dot * away[i];
			to_world(f, local, p, 1);
			to_world(f, along, dir, 0);
			normalize3(dir);
			r = ray_through(p, dir, test_random_range(0.5, 10.0));
			false_hits += hedron_intersect(&s, &o, &r, 0, REAL_MAX, NULL);
		}
	}
	snprintf(what, sizeof what, "%s: leaks through edges and vertices", name);
	test_check_int(leaks, 0, __FILE__, __LINE__, what);
	snprintf(what, sizeof what, "%s: entry face not at the edge or vertex", name);
	test_check_int(wrong_face, 0, __FILE__, __LINE__, what);
	snprintf(what, sizeof what, "%s: entry point away from the edge or vertex", name);
	test_check_int(wrong_point, 0, __FILE__, __LINE__, what);
	snprintf(what, sizeof what, "%s: hits by rays 1e-3 outside", name);
	test_check_int(false_hits, 0, __FILE__, __LINE__, what);
}

/* The rotation R = Rz(c) Ry(b) Rx(a), built in double. */
static void rotation(double a, double b, double c, double rot[3][3])
{
	double ca = cos(a), sa = sin(a), cb = cos(b), sb = sin(b), cc = cos(c), sc = sin(c);
	rot[0][0] = cc * cb;
	rot[0][1] = cc * sb * sa - sc * ca;
	rot[0][2] = cc * sb * ca + sc * sa;
	rot[1][0] = sc * cb;
	rot[1][1] = sc * sb * sa + cc * ca;
	rot[1][2] = sc * sb * ca - cc * sa;
	rot[2][0] = -sb;
	rot[2][1] = cb * sa;
	rot[2][2] = cb * ca;
}

void suite_hedron(void)
{
	frame turned;
	object o = cube_object();
	size_t i;

	set_cube(&unit_cube);
	for (i = 0; i < sizeof cases / sizeof cases[0]; i++)
		run_case(&o, &cases[i]);
	test_bad_direction(&o);

	test_seed(20240601u);
	watertight("axis-aligned cube", &unit_cube);
	rotation(0.3, 0.7, 1.1, turned.rot);
	turned.move[0] = turned.move[1] = turned.move[2] = 0.0;
	watertight("rotated cube", &turned);
	/* The catalog's rotated cube away from the origin. */
	turned.move[0] = 3.7;
	turned.move[1] = -2.1;
	turned.move[2] = 11.3;
	watertight("rotated cube at (3.7, -2.1, 11.3)", &turned);
}
