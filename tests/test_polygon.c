/* test_polygon.c - polygons and patches: the cases G01-G11 of numerics.md section 6, with a
 * seeded test that points on shared edges of a polygon grid lie in exactly one polygon.
 * See LICENSE for copyright and licence. */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "diag.h"
#include "parse.h"
#include "shape.h"
#include "support.h"
#include "test.h"

/* Several megabytes: static, never on the stack. */
static scene s;

/* Appends a vertex, as the parser stores it. */
static void add_vertex(vec3 v)
{
	s.vertices[s.vertex_count] = v;
	s.vertex_count++;
}

/* Appends count (x, y) pairs as vertices in the plane z = 0; returns the first index. */
static int add_xy(const real *xy, int count)
{
	int first = s.vertex_count, i;
	for (i = 0; i < count; i++)
		add_vertex(vec_make(xy[2 * i], xy[2 * i + 1], REAL_C(0)));
	return first;
}

static object polygon_object(int first, int count, vec3 normal, real offset, int axis,
			     unsigned flags)
{
	object o;
	o.kind = SHAPE_POLYGON;
	o.flags = (unsigned char)flags;
	o.material = 0;
	o.line = 0;
	o.u.polygon.normal = dir_normalize(normal);
	o.u.polygon.offset = offset;
	o.u.polygon.spread = REAL_C(0.0); /* the vertices lie in the plane given */
	o.u.polygon.first = first;
	o.u.polygon.count = count;
	o.u.polygon.axis = axis;
#if POLYGON_EDGES
	o.u.polygon.extent = REAL_C(0.0); /* no edge lines: the crossings test answers */
#endif
	return o;
}

/* A polygon in z = 0 facing +z (dropping z projects it to (x, y)). */
static object xy_polygon(const real *xy, int count, unsigned flags)
{
	return polygon_object(add_xy(xy, count), count, VEC_C(0, 0, 1), 0, 2, flags);
}

/* Is (x, y) inside a polygon in z = 0? Through the ray up the z axis from below, whose
 * frame (polygon.c) is the plane's own (u, v) = (x, y). */
static int contains(const object *o, real x, real y)
{
	ray r = test_ray(vec_make(x, y, REAL_C(-1)), VEC_C(0, 0, 1));
	return polygon_contains_ray(s.vertices + o->u.polygon.first, o->u.polygon.count, &r);
}

static const real unit_square[] = {REAL_C(0), REAL_C(0), REAL_C(1), REAL_C(0),
				   REAL_C(1), REAL_C(1), REAL_C(0), REAL_C(1)};

/* G01, G02, G06: inside, and the half-open rule on the boundary: right and top edges
 * (and their corner) belong to the square, left and bottom ones do not. */
static void test_square(void)
{
	static const real repeated[] = {REAL_C(0), REAL_C(0), REAL_C(1), REAL_C(0), REAL_C(1),
					REAL_C(0), REAL_C(1), REAL_C(1), REAL_C(0), REAL_C(1)};
	static const struct {
		real x, y;
		int inside;
	} points[] = {
		{REAL_C(0.5), REAL_C(0.5), 1},  {REAL_C(1.0), REAL_C(0.5), 1},
		{REAL_C(0.5), REAL_C(1.0), 1},  {REAL_C(1.0), REAL_C(1.0), 1},
		{REAL_C(0.0), REAL_C(0.0), 0},  {REAL_C(1.0), REAL_C(0.0), 0},
		{REAL_C(0.0), REAL_C(1.0), 0},  {REAL_C(0.5), REAL_C(0.0), 0},
		{REAL_C(0.0), REAL_C(0.5), 0},  {REAL_C(1.5), REAL_C(0.5), 0},
		{REAL_C(-0.5), REAL_C(0.5), 0}, {REAL_C(0.5), REAL_C(2.0), 0},
	};
	object square, twice;
	ray r;
	hit h;
	size_t i;
	char what[64];

	s.vertex_count = 0;
	square = xy_polygon(unit_square, 4, 0);
	/* G06: a repeated vertex is a zero-length edge and changes nothing. */
	twice = xy_polygon(repeated, 5, 0);
	for (i = 0; i < sizeof points / sizeof points[0]; i++) {
		snprintf(what, sizeof what, "G02: (%g, %g) %s", test_double(points[i].x),
			 test_double(points[i].y), points[i].inside ? "inside" : "outside");
		test_check(contains(&square, points[i].x, points[i].y) == points[i].inside,
			   __FILE__, __LINE__, what);
		snprintf(what, sizeof what, "G06: (%g, %g) %s", test_double(points[i].x),
			 test_double(points[i].y), points[i].inside ? "inside" : "outside");
		test_check(contains(&twice, points[i].x, points[i].y) == points[i].inside, __FILE__,
			   __LINE__, what);
	}

	/* G01 through the ray: O(0.5, 0.5, 1) D(0, 0, -1) hits at t = 1. */
	r = test_ray(VEC_C(0.5, 0.5, 1), VEC_C(0, 0, -1));
	CHECK(polygon_intersect(&s, &square, &r, 0, REAL_MAX, &h));
	CHECK_REAL(h.t, 1.0, 0.0);
	CHECK_REAL(h.point.x, 0.5, 0.0);
	CHECK_REAL(h.point.y, 0.5, 0.0);
	CHECK_REAL(h.point.z, 0.0, 0.0);
	CHECK(h.normal.x == UNIT_C(0.0) && h.normal.y == UNIT_C(0.0) && h.normal.z == UNIT_C(1.0));
	CHECK(h.shading.x == UNIT_C(0.0) && h.shading.y == UNIT_C(0.0) &&
	      h.shading.z == UNIT_C(1.0));
	CHECK(polygon_intersect(&s, &square, &r, 0, REAL_MAX, NULL));
	CHECK(!polygon_intersect(&s, &square, &r, 0, REAL_C(0.5), &h));
	CHECK(!polygon_intersect(&s, &square, &r, REAL_C(1.5), REAL_MAX, &h));
	/* An opaque polygon is one-sided: from behind it is not there; two-sided it is. */
	r = test_ray(VEC_C(0.5, 0.5, -1), VEC_C(0, 0, 1));
	CHECK(!polygon_intersect(&s, &square, &r, 0, REAL_MAX, &h));
	square.flags = OBJ_TWO_SIDED;
	CHECK(polygon_intersect(&s, &square, &r, 0, REAL_MAX, &h));
	CHECK_REAL(h.t, 1.0, 0.0);
	/* Beside the square, the plane is hit but the point is outside. */
	r = test_ray(VEC_C(1.5, 0.5, 1), VEC_C(0, 0, -1));
	CHECK(!polygon_intersect(&s, &square, &r, 0, REAL_MAX, &h));
}

/* G07, G08: a ray parallel to the plane, or lying in it, misses; the unguarded division
 * gives -inf or 0/0 = NaN. One-sided and two-sided alike. */
static void test_parallel(void)
{
	object square;
	ray r;
	hit h;
	unsigned flags;

	s.vertex_count = 0;
	square = xy_polygon(unit_square, 4, 0);
	for (flags = 0; flags <= OBJ_TWO_SIDED; flags += OBJ_TWO_SIDED) {
		square.flags = (unsigned char)flags;
		r = test_ray(VEC_C(0.5, 0.5, 1), VEC_C(1, 0, 0));
		CHECK(!polygon_intersect(&s, &square, &r, 0, REAL_MAX, &h));
		r = test_ray(VEC_C(-1, 0.5, 0), VEC_C(1, 0, 0));
		CHECK(!polygon_intersect(&s, &square, &r, 0, REAL_MAX, &h));
	}
}

/* G03, G04: a point on a shared edge or vertex belongs to exactly one polygon. */
static void test_shared(void)
{
	static const real right[] = {REAL_C(1), REAL_C(0), REAL_C(2), REAL_C(0),
				     REAL_C(2), REAL_C(1), REAL_C(1), REAL_C(1)};
	static const real top_left[] = {REAL_C(0), REAL_C(1), REAL_C(1), REAL_C(1),
					REAL_C(1), REAL_C(2), REAL_C(0), REAL_C(2)};
	static const real top_right[] = {REAL_C(1), REAL_C(1), REAL_C(2), REAL_C(1),
					 REAL_C(2), REAL_C(2), REAL_C(1), REAL_C(2)};
	object a, b, c, d;

	s.vertex_count = 0;
	a = xy_polygon(unit_square, 4, 0);
	b = xy_polygon(right, 4, 0);
	c = xy_polygon(top_left, 4, 0);
	d = xy_polygon(top_right, 4, 0);
	/* G03: (1, 0.5) is the right edge of a, the left edge of b. */
	CHECK_INT(contains(&a, REAL_C(1.0), REAL_C(0.5)), 1);
	CHECK_INT(contains(&b, REAL_C(1.0), REAL_C(0.5)), 0);
	/* G04: (1, 1), the corner of all four, is the top-right corner of a only. */
	CHECK_INT(contains(&a, REAL_C(1.0), REAL_C(1.0)), 1);
	CHECK_INT(contains(&b, REAL_C(1.0), REAL_C(1.0)), 0);
	CHECK_INT(contains(&c, REAL_C(1.0), REAL_C(1.0)), 0);
	CHECK_INT(contains(&d, REAL_C(1.0), REAL_C(1.0)), 0);

	/* The same through polygon_intersect, for rays from above a rounding error off the
	 * edge and the corner, to either side (float 2^-23 = 1 ulp of 1, double and long
	 * double 2^-51 = 2 ulp, Q16.16 1 LSB): each meets exactly one polygon, the one its
	 * point is in. */
	{
		static const double sides[4][2] = {{1, 1}, {1, -1}, {-1, 1}, {-1, -1}};
		double off = TOL3(ldexp(1.0, -23), ldexp(1.0, -51), 1 * LSB);
		int k, wrong_edge = 0, wrong_corner = 0;
		for (k = 0; k < 4; k++) {
			hit h;
			int east = sides[k][0] > 0, up = sides[k][1] > 0;
			ray r = test_ray(vec_make(test_real(1.0 + sides[k][0] * off),
						  test_real(0.5 + sides[k][1] * off), REAL_C(1.0)),
					 VEC_C(0, 0, -1));
			int in_a = polygon_intersect(&s, &a, &r, 0, REAL_MAX, &h);
			int in_b = polygon_intersect(&s, &b, &r, 0, REAL_MAX, &h);
			wrong_edge += in_a != !east || in_b != east;
			r.origin.y = test_real(1.0 + sides[k][1] * off);
			in_a = polygon_intersect(&s, &a, &r, 0, REAL_MAX, &h);
			in_b = polygon_intersect(&s, &b, &r, 0, REAL_MAX, &h);
			{
				int in_c = polygon_intersect(&s, &c, &r, 0, REAL_MAX, &h);
				int in_d = polygon_intersect(&s, &d, &r, 0, REAL_MAX, &h);
				wrong_corner += in_a != (!east && !up) || in_b != (east && !up) ||
						in_c != (!east && up) || in_d != (east && up);
			}
		}
		CHECK_INT(wrong_edge, 0);
		CHECK_INT(wrong_corner, 0);
	}
	/* Exactly on the edge and the corner from above, whose frame mirrors the plane's:
	 * still exactly one polygon each. */
	{
		hit h;
		ray r = test_ray(VEC_C(1, 0.5, 1), VEC_C(0, 0, -1));
		CHECK_INT(polygon_intersect(&s, &a, &r, 0, REAL_MAX, &h) +
				  polygon_intersect(&s, &b, &r, 0, REAL_MAX, &h),
			  1);
		r = test_ray(VEC_C(1, 1, 1), VEC_C(0, 0, -1));
		CHECK_INT(polygon_intersect(&s, &a, &r, 0, REAL_MAX, &h) +
				  polygon_intersect(&s, &b, &r, 0, REAL_MAX, &h) +
				  polygon_intersect(&s, &c, &r, 0, REAL_MAX, &h) +
				  polygon_intersect(&s, &d, &r, 0, REAL_MAX, &h),
			  1);
	}
}

/* G09: the L (0,0)(2,0)(2,1)(1,1)(1,2)(0,2) is concave. G10: a pentagram's centre is
 * outside by the even-odd rule (its winding number is 2); its points are inside. */
static void test_concave(void)
{
	static const real ell[] = {REAL_C(0), REAL_C(0), REAL_C(2), REAL_C(0),
				   REAL_C(2), REAL_C(1), REAL_C(1), REAL_C(1),
				   REAL_C(1), REAL_C(2), REAL_C(0), REAL_C(2)};
	real star[10];
	object l, p;
	int k;

	s.vertex_count = 0;
	l = xy_polygon(ell, 6, 0);
	CHECK_INT(contains(&l, REAL_C(1.5), REAL_C(1.5)), 0);
	CHECK_INT(contains(&l, REAL_C(0.5), REAL_C(1.5)), 1);
	CHECK_INT(contains(&l, REAL_C(1.5), REAL_C(0.5)), 1);
	/* {5/2}: every second vertex of a unit pentagon, starting at the top. */
	for (k = 0; k < 5; k++) {
		double angle = 1.5707963267948966 + k * 2.0 * 2.0 * 3.1415926535897932 / 5.0;
		star[2 * k] = test_real(cos(angle));
		star[2 * k + 1] = test_real(sin(angle));
	}
	p = xy_polygon(star, 5, 0);
	CHECK_INT(contains(&p, REAL_C(0.0), REAL_C(0.0)), 0);
	CHECK_INT(contains(&p, REAL_C(0.0), REAL_C(0.9)), 1);
	CHECK_INT(contains(&p, REAL_C(0.0), REAL_C(-0.5)), 0);
}

/* ---- G05 through the parser --------------------------------------------------- */

/* Counts the parser's zero-area warnings (other messages are not this test's business). */
static int zero_area_warnings;

static void capture(void *ctx, const char *message)
{
	(void)ctx;
	if (strstr(message, "zero area"))
		zero_area_warnings++;
}

/* G05: collinear vertices have a zero Newell normal; the parser drops the polygon with a
 * warning instead of dividing by its length. */
static void test_collinear(void)
{
	int ok;
	zero_area_warnings = 0;
	ok = test_parse_text(&s, "g05.nff",
			     "v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle 45\nhither 1\n"
			     "resolution 4 4\n"
			     "p 3\n0 0 0\n1 0 0\n2 0 0\n"
			     "p 3\n0 0 0\n1 0 0\n0 1 0\n",
			     capture, NULL);
	CHECK(ok);
	/* Only the second, proper triangle is left, with a unit normal. */
	CHECK_INT(s.object_count, 1);
	CHECK_INT(zero_area_warnings, 1);
	CHECK_UNIT(s.objects[0].u.polygon.normal.z, 1.0, 0.0);
}

/* ---- G11: random points on shared edges of a grid --------------------------------- */

enum { CELLS = 8, MAX_EDGES = 4 * CELLS * CELLS };

/* A jittered lattice cut into quads and triangles: the plane tiled without gaps. */
typedef struct {
	double uv[CELLS + 1][CELLS + 1][2];
	int polygons;        /* objects s.objects[0 .. polygons) */
	double edge[MAX_EDGES][2][2]; /* interior edges (shared by two polygons) */
	int edges;
} grid;

static int convex(const double *a, const double *b, const double *c, const double *d)
{
	const double *q[4];
	int i;
	q[0] = a;
	q[1] = b;
	q[2] = c;
	q[3] = d;
	for (i = 0; i < 4; i++) {
		const double *p0 = q[i], *p1 = q[(i + 1) % 4], *p2 = q[(i + 2) % 4];
		if ((p1[0] - p0[0]) * (p2[1] - p1[1]) - (p1[1] - p0[1]) * (p2[0] - p1[0]) <= 0.0)
			return 0;
	}
	return 1;
}

static void add_edge(grid *g, const double *a, const double *b)
{
	memcpy(g->edge[g->edges][0], a, sizeof g->edge[0][0]);
	memcpy(g->edge[g->edges][1], b, sizeof g->edge[0][1]);
	g->edges++;
}

/* The grid's polygons go into s.objects with vertices from `place`, which maps the
 * plane's (u, v) to a scene point; every polygon copies the same rounded vertices. */
typedef vec3 (*place_fn)(const double *uv);

static void add_grid_polygon(grid *g, place_fn place, const double *const *corner, int count,
			     vec3 normal, real offset, int axis)
{
	int first = s.vertex_count, i;
	for (i = 0; i < count; i++)
		add_vertex(place(corner[i]));
	s.objects[g->polygons++] = polygon_object(first, count, normal, offset, axis, 0);
}

static void build_grid(grid *g, place_fn place, vec3 normal, real offset, int axis)
{
	int i, j;
	s.vertex_count = 0;
	g->polygons = 0;
	g->edges = 0;
	for (i = 0; i <= CELLS; i++)
		for (j = 0; j <= CELLS; j++) {
			/* Jitter of at most 0.2 keeps every cell simple and the cells a tiling. */
			g->uv[i][j][0] = i + 0.4 * (test_random() - 0.5);
			g->uv[i][j][1] = j + 0.4 * (test_random() - 0.5);
		}
	for (i = 0; i < CELLS; i++)
		for (j = 0; j < CELLS; j++) {
			const double *q[4];
			double pick = test_random();
			q[0] = g->uv[i][j];
			q[1] = g->uv[i + 1][j];
			q[2] = g->uv[i + 1][j + 1];
			q[3] = g->uv[i][j + 1];
			/* Interior lattice edges: the cell's left and bottom ones. */
			if (i > 0)
				add_edge(g, q[3], q[0]);
			if (j > 0)
				add_edge(g, q[0], q[1]);
			if (pick < 0.4 || !convex(q[0], q[1], q[2], q[3])) {
				add_grid_polygon(g, place, q, 4, normal, offset, axis);
			} else {
				/* Two triangles along one diagonal, listed in opposite orders. */
				const double *t1[3], *t2[3];
				int k = pick < 0.7 ? 0 : 1;
				t1[0] = q[k];
				t1[1] = q[k + 1];
				t1[2] = q[k + 2];
				t2[0] = q[k + 2];
				t2[1] = q[(k + 3) % 4];
				t2[2] = q[k];
				add_grid_polygon(g, place, t1, 3, normal, offset, axis);
				add_grid_polygon(g, place, t2, 3, normal, offset, axis);
				add_edge(g, q[k], q[k + 2]);
			}
		}
}

/* A random point on a random shared edge (1 in 8: an interior lattice vertex exactly). */
static void pick_on_edge(const grid *g, double uv[2])
{
	if (test_random() < 0.125) {
		int i = 1 + (int)(test_random() * (CELLS - 1));
		int j = 1 + (int)(test_random() * (CELLS - 1));
		uv[0] = g->uv[i][j][0];
		uv[1] = g->uv[i][j][1];
	} else {
		const double(*e)[2] = g->edge[(int)(test_random() * g->edges)];
		double t = test_random();
		/* A point that close to the end of an edge on the grid's border could land
		 * outside the grid once rounded (in Q16.16 a ray's origin and direction are off
		 * by an LSB or so, far from the origin). Points stay 5 % of an edge from its
		 * ends (interior vertices are picked above). */
		t = 0.05 + 0.9 * t;
		uv[0] = e[0][0] + t * (e[1][0] - e[0][0]);
		uv[1] = e[0][1] + t * (e[1][1] - e[0][1]);
	}
}

/* Lengths are scaled by 2^grid_shift before they are rounded to real: in fixed point the
 * scale the parser would give the grid's scene, 0 in floating point. */
static int grid_shift;

static real length(double x)
{
	return test_real(ldexp(x, grid_shift));
}

static vec3 place_flat(const double *uv)
{
	return vec_make(length(uv[0]), length(uv[1]), REAL_C(0.0));
}

/* A tilted plane through (3.7, -2.1, 11.3) spanned by e1, e2; its normal is mostly along
 * x, so the polygons project onto (y, z). */
static const double tilt_origin[3] = {3.7, -2.1, 11.3};
static const double tilt_e1[3] = {-0.36, 0.48, 0.8};
static const double tilt_e2[3] = {0.0, -0.8, 0.6};

static void tilt_point(const double *uv, double p[3])
{
	int k;
	for (k = 0; k < 3; k++)
		p[k] = tilt_origin[k] + uv[0] * tilt_e1[k] + uv[1] * tilt_e2[k];
}

static vec3 place_tilted(const double *uv)
{
	double p[3];
	tilt_point(uv, p);
	return vec_make(length(p[0]), length(p[1]), length(p[2]));
}

/* G11: every point on a shared edge is inside exactly one polygon of the grid, both in
 * the projection and through rays that hit the point from random directions. */
static void test_grid(void)
{
	enum { POINTS = 100000 };
	static grid g;
	double normal[3], len;
	vec3 n;
	real offset;
	int neither = 0, both = 0, n_ray_neither = 0, n_ray_both = 0, wrong_t = 0, k, i;

	test_seed(1618033988u);
	/* The flat grid spans 0 .. 8. */
	grid_shift = test_shift(CELLS + 0.5);
	build_grid(&g, place_flat, VEC_C(0, 0, 1), 0, 2);
	for (k = 0; k < POINTS; k++) {
		double uv[2];
		int count = 0;
		real x, y;
		pick_on_edge(&g, uv);
		x = length(uv[0]);
		y = length(uv[1]);
		for (i = 0; i < g.polygons; i++)
			count += contains(&s.objects[i], x, y);
		neither += count == 0;
		both += count > 1;
	}
	CHECK_INT(neither, 0);
	CHECK_INT(both, 0);

	/* The same in a tilted plane, through polygon_intersect. All polygons share one
	 * plane (unit normal e1 x e2, offset through the plane's origin), as coplanar
	 * polygons of a scene do, so they all compute the same hit point. */
	normal[0] = tilt_e1[1] * tilt_e2[2] - tilt_e1[2] * tilt_e2[1];
	normal[1] = tilt_e1[2] * tilt_e2[0] - tilt_e1[0] * tilt_e2[2];
	normal[2] = tilt_e1[0] * tilt_e2[1] - tilt_e1[1] * tilt_e2[0];
	len = sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
	for (i = 0; i < 3; i++)
		normal[i] /= len;
	n = vec_make(test_real(normal[0]), test_real(normal[1]), test_real(normal[2]));
	/* The tilted grid and the rays' origins (up to 20 from it) reach about 40. */
	grid_shift = test_shift(40.0);
	offset = length(normal[0] * tilt_origin[0] + normal[1] * tilt_origin[1] +
			normal[2] * tilt_origin[2]);
	/* Project along the normal's largest component (x here), as the parser does. */
	CHECK(fabs(normal[0]) > fabs(normal[1]) && fabs(normal[0]) > fabs(normal[2]));
	build_grid(&g, place_tilted, n, offset, 0);
	for (k = 0; k < POINTS; k++) {
		double uv[2], p[3], w[3], cosine, back = 1.0 + 19.0 * test_random();
		int count = 0;
		ray r;
		hit h;
		pick_on_edge(&g, uv);
		tilt_point(uv, p);
		/* A random direction on the front side, not grazing (cos >= 0.2). */
		do {
			for (i = 0; i < 3; i++)
				w[i] = 2.0 * test_random() - 1.0;
			len = sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
			cosine = w[0] * normal[0] + w[1] * normal[1] + w[2] * normal[2];
			cosine = len > 0.0 ? cosine / len : 0.0;
		} while (len > 1.0 || cosine < 0.2);
		for (i = 0; i < 3; i++)
			w[i] /= len;
		r = test_ray(vec_make(length(p[0] + back * w[0]), length(p[1] + back * w[1]),
				      length(p[2] + back * w[2])),
			     vec_make(test_real(-w[0]), test_real(-w[1]), test_real(-w[2])));
		for (i = 0; i < g.polygons; i++)
			if (polygon_intersect(&s, &s.objects[i], &r, 0, REAL_MAX, &h)) {
				count++;
				/* Q16.16 (at the grid's scale): t is good to 2^-16 of t (the
				 * direction's rounding, real.h), and the plane's rounded normal
				 * (half an LSB per component: 1.5 LSB of |p|inf) moves it by up
				 * to 2^-16 1.5 |p|inf over the cosine. */
				if (!(fabs(test_double(h.t) - back * test_scale(grid_shift)) <
				      TOL3(1e-4 * back, 1e-10 * back,
					   (back * test_scale(grid_shift) +
					    1.5 * test_double(vec_max_abs(h.point)) / cosine +
					    4.0) * LSB)))
					wrong_t++;
			}
		n_ray_neither += count == 0;
		n_ray_both += count > 1;
	}
	CHECK_INT(n_ray_neither, 0);
	CHECK_INT(n_ray_both, 0);
	CHECK_INT(wrong_t, 0);
}

/* Polygons facing along x and y drop those coordinates instead. */
static void test_other_axes(void)
{
	object o;
	ray r;
	hit h;
	int first;

	s.vertex_count = 0;
	/* The unit square in the plane x = 2: (y, z) = (0,0) (1,0) (1,1) (0,1), facing +x. */
	first = s.vertex_count;
	add_vertex(VEC_C(2, 0, 0));
	add_vertex(VEC_C(2, 1, 0));
	add_vertex(VEC_C(2, 1, 1));
	add_vertex(VEC_C(2, 0, 1));
	o = polygon_object(first, 4, VEC_C(1, 0, 0), REAL_C(2.0), 0, 0);
	r = test_ray(VEC_C(5, 0.25, 0.75), VEC_C(-1, 0, 0));
	CHECK(polygon_intersect(&s, &o, &r, 0, REAL_MAX, &h));
	CHECK_REAL(h.t, 3.0, 0.0);
	r = test_ray(VEC_C(5, 1.25, 0.75), VEC_C(-1, 0, 0));
	CHECK(!polygon_intersect(&s, &o, &r, 0, REAL_MAX, &h));

	/* The same square in the plane y = -3, facing -y. */
	first = s.vertex_count;
	add_vertex(VEC_C(0, -3, 0));
	add_vertex(VEC_C(0, -3, 1));
	add_vertex(VEC_C(1, -3, 1));
	add_vertex(VEC_C(1, -3, 0));
	o = polygon_object(first, 4, VEC_C(0, -1, 0), REAL_C(3.0), 1, 0);
	r = test_ray(VEC_C(0.5, -7, 0.5), VEC_C(0, 1, 0));
	CHECK(polygon_intersect(&s, &o, &r, 0, REAL_MAX, &h));
	CHECK_REAL(h.t, 4.0, 0.0);
	CHECK(h.normal.x == UNIT_C(0.0) && h.normal.y == UNIT_C(-1.0) && h.normal.z == UNIT_C(0.0));
	/* From behind, one-sided: nothing. */
	r = test_ray(VEC_C(0.5, 1, 0.5), VEC_C(0, -1, 0));
	CHECK(!polygon_intersect(&s, &o, &r, 0, REAL_MAX, &h));
}

/* Q16.16: the vertex normals are rounded to half an LSB each, and the blend and its
 * normalisation add a few more. */
#define NORMAL_TOL TOL3(1e-6, 1e-14, 1 * LSB)

/* Patches: the shading normal is the barycentric blend of the vertex normals of the fan
 * triangle holding the hit; the geometric normal stays the face's. */
static void check_patch_normal(const object *o, real x, real y, const double expect[3])
{
	ray r = test_ray(vec_make(x, y, REAL_C(1)), VEC_C(0, 0, -1));
	double len = sqrt(expect[0] * expect[0] + expect[1] * expect[1] + expect[2] * expect[2]);
	hit h;
	if (!CHECK(polygon_intersect(&s, o, &r, 0, REAL_MAX, &h)))
		return;
	CHECK(h.normal.x == UNIT_C(0.0) && h.normal.y == UNIT_C(0.0) && h.normal.z == UNIT_C(1.0));
	CHECK_UNIT(h.shading.x, expect[0] / len, NORMAL_TOL);
	CHECK_UNIT(h.shading.y, expect[1] / len, NORMAL_TOL);
	CHECK_UNIT(h.shading.z, expect[2] / len, NORMAL_TOL);
}

static void test_patch(void)
{
	const double r2 = 0.70710678118654752, r3 = 0.57735026918962576;
	object tri, quad;
	double e[3];
	int first;

	s.vertex_count = 0;
	/* Triangle (0,0) (1,0) (1,1) with normals (0,0,1), (1,0,1)/sqrt 2, (1,1,1)/sqrt 3.
	 * At (x, y) the barycentric weights are 1 - x, x - y, y. */
	tri = xy_polygon(unit_square, 3, OBJ_TWO_SIDED);
	tri.kind = SHAPE_PATCH;
	first = tri.u.polygon.first;
	s.normals[first] = DIR_C(0, 0, 1);
	s.normals[first + 1] = dir_make(test_unit(r2), UNIT_C(0), test_unit(r2));
	s.normals[first + 2] = dir_make(test_unit(r3), test_unit(r3), test_unit(r3));
	/* (0.75, 0.25): weights 0.25, 0.5, 0.25. */
	e[0] = 0.5 * r2 + 0.25 * r3;
	e[1] = 0.25 * r3;
	e[2] = 0.25 + 0.5 * r2 + 0.25 * r3;
	check_patch_normal(&tri, REAL_C(0.75), REAL_C(0.25), e);
	/* Near a vertex the blend tends to that vertex's normal (in Q16.16, where 1e-5 is
	 * below an LSB, the point is 8 and 16 LSB from the vertex instead). */
	{
#if REAL_FIXED
		real x = REAL_C(1.0) - 8, y = REAL_C(1.0) - 16;
#else
		real x = REAL_C(0.99999), y = REAL_C(0.99998);
#endif
		double a = 1.0 - test_double(x), b = test_double(x) - test_double(y),
		       c = test_double(y);
		e[0] = b * r2 + c * r3;
		e[1] = c * r3;
		e[2] = a + b * r2 + c * r3;
		check_patch_normal(&tri, x, y, e);
	}

	/* The unit square as a patch: two fan triangles (0,1,2) and (0,2,3). Normals
	 * (0,0,1), (1,0,1)/sqrt 2, (1,1,1)/sqrt 3, (0,1,1)/sqrt 2. */
	quad = xy_polygon(unit_square, 4, OBJ_TWO_SIDED);
	quad.kind = SHAPE_PATCH;
	first = quad.u.polygon.first;
	s.normals[first] = DIR_C(0, 0, 1);
	s.normals[first + 1] = dir_make(test_unit(r2), UNIT_C(0), test_unit(r2));
	s.normals[first + 2] = dir_make(test_unit(r3), test_unit(r3), test_unit(r3));
	s.normals[first + 3] = dir_make(UNIT_C(0), test_unit(r2), test_unit(r2));
	/* (0.25, 0.75) is in the second fan triangle, 0.25 v0 + 0.25 v2 + 0.5 v3. */
	e[0] = 0.25 * r3;
	e[1] = 0.25 * r3 + 0.5 * r2;
	e[2] = 0.25 + 0.25 * r3 + 0.5 * r2;
	check_patch_normal(&quad, REAL_C(0.25), REAL_C(0.75), e);
	/* (0.75, 0.25) is in the first, as for the triangle. */
	e[0] = 0.5 * r2 + 0.25 * r3;
	e[1] = 0.25 * r3;
	e[2] = 0.25 + 0.5 * r2 + 0.25 * r3;
	check_patch_normal(&quad, REAL_C(0.75), REAL_C(0.25), e);
	/* A plain polygon over the same vertices ignores the normals. */
	quad.kind = SHAPE_POLYGON;
	e[0] = e[1] = 0.0;
	e[2] = 1.0;
	check_patch_normal(&quad, REAL_C(0.25), REAL_C(0.75), e);
}

/* Rays at big polygons, counted: how many, how many the plain crossings test finds
 * inside, and how many polygon_intersect (with the runs' boxes and, in floating point,
 * the discs) answers otherwise. */
typedef struct {
	int rays, inside, disagree;
} ray_tally;

static void tally_ray(ray_tally *t, const object *o, vec3 from, vec3 target)
{
	ray r = test_ray(from, vec_sub(target, from));
	hit h;
	int plain = polygon_contains_ray(s.vertices + o->u.polygon.first, o->u.polygon.count, &r);
	t->rays++;
	t->inside += plain;
	t->disagree += polygon_intersect(&s, o, &r, REAL_C(0.0), REAL_MAX, &h) != plain;
}

/* Two big star polygons (203 and 37 vertices, after a small polygon in the pool: their
 * runs' slots are not the pool's first, and each ends in a shorter run), tilted: rays
 * from their front at random points of their plane, at their vertices and at their
 * edges' middles meet them through polygon_intersect (which passes over runs of edges by
 * their boxes) exactly when the plain crossings test says they should. */
static void test_runs(void)
{
	static char text[1 << 15];
	static const int points[2] = {203, 37};
	size_t at;
	int i, star_at;
	ray_tally tally = {0, 0, 0};
	test_seed(16);
	at = (size_t)snprintf(text, sizeof text,
			      "v\nfrom 0 0 10\nat 0 0 0\nup 0 1 0\nangle 30\nhither 1\n"
			      "resolution 8 8\nl 0 0 10\nf 1 1 1 1 0 0 0 1\n"
			      "p 5\n5 5 5\n6 5 5\n6 6 5\n5.5 6.5 5\n5 6 5\n");
	for (star_at = 0; star_at < 2; star_at++) {
		int n = snprintf(text + at, sizeof text - at, "p %d\n", points[star_at]);
		at = n > 0 ? at + (size_t)n : at;
		for (i = 0; i < points[star_at] && at < sizeof text; i++) {
			double angle = 6.283185307179586 * i / points[star_at];
			double radius = i % 2 ? 0.3 + 0.5 * test_random() : 1.0;
			double x = radius * cos(angle), y = radius * sin(angle);
			n = snprintf(text + at, sizeof text - at, "%.17g %.17g %.17g\n",
				     x + 0.1 * y, 0.3 * x + y, 0.2 * x - 0.4 * y);
			at = n > 0 ? at + (size_t)n : at;
		}
	}
	if (!CHECK(test_parse_buffer(&s, "star.nff", text, NULL, NULL)))
		return;
	CHECK_INT(s.object_count, 3);
	CHECK_INT(s.objects[1].u.polygon.count, points[0]);
	CHECK_INT(s.objects[2].u.polygon.count, points[1]);
	for (i = 0; i < 40000; i++) {
		const object *star = &s.objects[1 + i % 2];
		int count = star->u.polygon.count;
		const vec3 *v = s.vertices + star->u.polygon.first;
		int k = (int)test_random_range(0.0, count - 0.01);
		vec3 target, from, front = dir_to_vec(star->u.polygon.normal);
		if (i / 2 % 3 == 0)
			target = v[k];
		else if (i / 2 % 3 == 1)
			target = vec_scale(vec_add(v[k], v[(k + 1) % count]), REAL_C(0.5));
		else
			target = vec_make(test_real(test_random_range(-1.1, 1.1)),
					  test_real(test_random_range(-1.1, 1.1)), REAL_C(0.0));
		from = vec_add(vec_scale(front, REAL_C(4.0)),
			       vec_make(test_real(test_random_range(-2.0, 2.0)),
					test_real(test_random_range(-2.0, 2.0)),
					test_real(test_random_range(-2.0, 2.0))));
		tally_ray(&tally, star, from, target);
	}
	CHECK_INT(tally.rays, 40000);
	CHECK(tally.inside > 10000 && tally.inside < 30000);
	CHECK_INT(tally.disagree, 0);
}

/* A random coordinate for test_triangles: on a coarse grid (1/4 steps: products of such
 * numbers tie exactly, and rays pass exactly through vertices and along edges) or
 * anywhere in [-2, 2). */
static real triangle_coordinate(int coarse)
{
	return test_real(coarse ? (int)test_random_range(-8.0, 8.0) / 4.0
				: test_random_range(-2.0, 2.0));
}

/* A triangle's own path through the crossings test (polygon.c) answers as the general
 * loop does: each triangle against itself with its last vertex repeated (an edge from a
 * vertex to itself never straddles, so the loop's answer for it is the triangle's), on
 * random triangles and on triangles of grid points (some with two equal vertices, some
 * with three on a line), by rays from every side (every axis the largest of the
 * direction) aimed at their vertices, their edges' middles and random points. */
static void test_triangles(void)
{
	int i, k, inside = 0, disagree = 0;
	test_seed(33);
	for (i = 0; i < 60000; i++) {
		int coarse = i % 2;
		vec3 v[7], target, from;
		ray r;
		int pick = i / 2 % 3, three, four;
		s.vertex_count = 0;
		for (k = 0; k < 3; k++)
			v[k] = vec_make(triangle_coordinate(coarse), triangle_coordinate(coarse),
					triangle_coordinate(coarse));
		if (coarse && i % 10 == 1)
			v[2] = v[i % 20 == 1 ? 0 : 1]; /* two vertices the same */
		if (pick == 0)
			target = v[(int)test_random_range(0.0, 2.99)];
		else if (pick == 1)
			target = vec_scale(vec_add(v[i % 3], v[(i + 1) % 3]), REAL_C(0.5));
		else
			target = vec_make(triangle_coordinate(coarse), triangle_coordinate(coarse),
					  triangle_coordinate(coarse));
		from = vec_make(triangle_coordinate(coarse), triangle_coordinate(coarse),
				triangle_coordinate(coarse));
		from = vec_add(from, vec_scale(vec_sub(from, target), REAL_C(2.0)));
		if (vec_dot(vec_sub(target, from), vec_sub(target, from)) <= REAL_C(0.0))
			continue;
		r = test_ray(from, vec_sub(target, from));
		for (k = 0; k < 3; k++)
			add_vertex(v[k]);
		add_vertex(v[2]);
		three = polygon_contains_ray(s.vertices, 3, &r);
		four = polygon_contains_ray(s.vertices, 4, &r);
		inside += three;
		disagree += three != four;
	}
	CHECK(inside > 12000 && inside < 20000);
	CHECK_INT(disagree, 0);
}

/* A point of big test polygon `shape` (i of n vertices), before it is tilted: a circle,
 * a star, a crescent (a thin C, whose centroid lies in its hollow, outside it), and a
 * circle whose vertices lie up to 0.02 off its plane. */
static vec3 disc_shape_point(int shape, int i, int n)
{
	double angle = 6.283185307179586 * i / n, radius = 1.0, z = 0.0;
	if (shape == 1)
		radius = i % 2 ? 0.4 + 0.3 * test_random() : 1.0;
	if (shape == 2) {
		/* The outer arc out, the inner back: the C opens towards +x. */
		int half = n / 2, k = i < half ? i : n - 1 - i;
		angle = 3.141592653589793 * (0.3 + 1.4 * k / (half - 1));
		radius = i < half ? 1.0 : 0.9;
	}
	if (shape == 3)
		z = test_random_range(-0.02, 0.02);
	return vec_make(test_real(radius * cos(angle)), test_real(radius * sin(angle)), test_real(z));
}

/* Where a test ray at `target` starts: at cosine c to `front` (a unit normal; c < 0 from
 * behind), the rest along a random side, scale times a random [lo, hi) away. 0 when the
 * side drawn lies too near the normal (the caller draws again). */
static int ray_start(vec3 target, vec3 front, double c, double scale, double lo, double hi,
		     vec3 *from)
{
	double spin = test_random_range(0.0, 6.283185307179586);
	vec3 side = vec_make(test_real(cos(spin)), test_real(sin(spin)), test_real(cos(3 * spin)));
	side = vec_sub(side, vec_scale(front, vec_dot(side, front)));
	if (vec_max_abs(side) < REAL_C(0.01))
		return 0;
	/* real_div: in Q16.16 a plain / of two reals divides their raw integers. */
	side = vec_scale(side, real_div(test_real(sqrt(1.0 - c * c)), vec_length(side)));
	*from = vec_add(target, vec_scale(vec_add(vec_scale(front, test_real(c)), side),
					  test_real(scale * test_random_range(lo, hi))));
	return 1;
}

/* Big polygons (more than RT_POLYGON_RUN vertices), whose hits deep inside floating
 * point takes from a disc about the centroid without the crossings test (polygon.c):
 * the shapes of disc_shape_point, tilted, and in floating point the circle again 2e5
 * from the origin, seen from up to 4e5 away. Rays from in front, at every angle down to
 * the grazing REACH, at random points, at points just inside and outside the circle's
 * edges (where the disc ends), at vertices and well inside: polygon_intersect meets each
 * exactly when the plain crossings test says it should. */
static void test_discs(void)
{
	static char text[1 << 16];
	const int shapes = REAL_FIXED ? 4 : 5, counts[5] = {60, 41, 48, 50, 60};
	const double far[5] = {0.0, 0.0, 0.0, 0.0, 2e5}, scale[5] = {1.0, 1.0, 1.0, 1.0, 10.0};
	size_t at;
	int shape, i, deep = 0;
	ray_tally tally = {0, 0, 0};
	test_seed(17);
	at = (size_t)snprintf(text, sizeof text,
			      "v\nfrom 0 0 10\nat 0 0 0\nup 0 1 0\nangle 30\nhither 1\n"
			      "resolution 8 8\nl 0 0 10\nf 1 1 1 1 0 0 0 1\n");
	for (shape = 0; shape < shapes; shape++) {
		int n = snprintf(text + at, sizeof text - at, "p %d\n", counts[shape]);
		at = n > 0 ? at + (size_t)n : at;
		for (i = 0; i < counts[shape] && at < sizeof text; i++) {
			vec3 p = vec_scale(disc_shape_point(shape % 4, i, counts[shape]),
					   test_real(scale[shape]));
			double x = test_double(p.x), y = test_double(p.y), z = test_double(p.z);
			n = snprintf(text + at, sizeof text - at, "%.17g %.17g %.17g\n",
				     far[shape] + x + 0.1 * y, far[shape] + 0.3 * x + y,
				     -far[shape] + 0.2 * x - 0.4 * y + z);
			at = n > 0 ? at + (size_t)n : at;
		}
	}
	if (!CHECK(test_parse_buffer(&s, "discs.nff", text, NULL, NULL)))
		return;
	CHECK_INT(s.object_count, shapes);
	for (i = 0; i < 60000; i++) {
		const object *o = &s.objects[i % shapes];
		int which = i % shapes, count = o->u.polygon.count, how = i / shapes % 4;
		const vec3 *v = s.vertices + o->u.polygon.first;
		/* Lengths as the scene stores them (fixed point scales them up). */
		double stored = ldexp(1.0, s.length_shift), size = scale[which] * stored;
		vec3 centre = vec_make(test_real(far[which] * stored), test_real(far[which] * stored),
				       test_real(-far[which] * stored));
		vec3 front = dir_to_vec(o->u.polygon.normal), target, from;
		double c = test_random_range(0.26, 1.0);
		/* A point on the tilted polygon's plane at radius `reach` and a random angle
		 * (random points in the square, the circle's edge, well inside), or a vertex. */
		double angle = test_random_range(0.0, 6.283185307179586), reach;
		reach = how == 0 ? test_random_range(0.0, 1.5) : how == 1 ? test_random_range(0.95, 1.0)
								   : test_random_range(0.0, 0.5);
		if (how == 3) {
			target = v[(int)test_random_range(0.0, count - 0.01)];
		} else {
			double x = size * reach * cos(angle), y = size * reach * sin(angle);
			target = vec_add(centre, vec_make(test_real(x + 0.1 * y), test_real(0.3 * x + y),
							  test_real(0.2 * x - 0.4 * y)));
		}
		deep += how == 2 && reach < 0.4 && c > 0.5 && (which == 0 || which == 4);
		/* From in front: cos c to the normal, the rest along a random side. */
		if (!ray_start(target, front, c, size * (which == 4 ? 1000.0 : 1.0), 2.0, 40.0, &from))
			continue;
		tally_ray(&tally, o, from, target);
	}
	CHECK(tally.rays > 55000);
	CHECK(tally.inside > tally.rays / 4 && tally.inside < tally.rays * 3 / 4);
	CHECK(deep > 1000); /* rays the disc answers (floating point), well inside */
	CHECK_INT(tally.disagree, 0);
}

/* A random rotation, from a random unit quaternion: its first two rows (unit vectors at
 * right angles) and the third (their cross product). */
static void random_rotation(double axis[3][3])
{
	double q[4], n2 = 0.0;
	int k;
	for (k = 0; k < 4; k++) {
		q[k] = test_random_range(-1.0, 1.0);
		n2 += q[k] * q[k];
	}
	for (k = 0; k < 4; k++)
		q[k] /= sqrt(n2);
	axis[0][0] = 1 - 2 * (q[2] * q[2] + q[3] * q[3]);
	axis[0][1] = 2 * (q[1] * q[2] + q[0] * q[3]);
	axis[0][2] = 2 * (q[1] * q[3] - q[0] * q[2]);
	axis[1][0] = 2 * (q[1] * q[2] - q[0] * q[3]);
	axis[1][1] = 1 - 2 * (q[1] * q[1] + q[3] * q[3]);
	axis[1][2] = 2 * (q[2] * q[3] + q[0] * q[1]);
	axis[2][0] = axis[0][1] * axis[1][2] - axis[0][2] * axis[1][1];
	axis[2][1] = axis[0][2] * axis[1][0] - axis[0][0] * axis[1][2];
	axis[2][2] = axis[0][0] * axis[1][1] - axis[0][1] * axis[1][0];
}

/* A tiny polygon (1e-4 across, in floating point) with a slit from its rim that ends
 * just past its centroid, so that the centroid lies outside it, a few roundings of the
 * coordinates' size from the slit's walls: the check that gives a polygon its disc only
 * when the centroid is inside must be as fine as the polygon, not as the unit (a check
 * from a unit away gave a quarter of these a disc, and the ray at the centroid a hit).
 * Randomly turned; the ray straight down the normal at the centroid, and rays near it,
 * meet each through polygon_intersect exactly when the crossings test says so. */
static void test_disc_slit(void)
{
	static char text[1 << 13];
	/* A few roundings of the size (no finer than double's, in which the test computes
	 * the vertices). */
	const double size = 1e-4,
		     gap = 3e-8 * fmax((double)REAL_EPSILON, DBL_EPSILON) / 1.1920928955078125e-7;
	int turn, i;
	ray_tally tally = {0, 0, 0}, at_centroid = {0, 0, 0};
	if (REAL_FIXED)
		return; /* no discs, and 1e-4 is below Q16.16's reach */
	test_seed(18);
	for (turn = 0; turn < 40; turn++) {
		double axis[3][3], sum = 0.0, end, pts[42][2];
		size_t at;
		const object *o;
		vec3 centre = vec_make(REAL_C(0.0), REAL_C(0.0), REAL_C(0.0));
		random_rotation(axis);
		/* The rim from angle 0.05 round to -0.05, then the slit's end at x = end, its
		 * walls gap / size from the axis: end puts the vertices' mean gap / size
		 * before it. */
		for (i = 0; i < 40; i++) {
			double angle = 0.05 + (6.283185307179586 - 0.1) * i / 39;
			pts[i][0] = cos(angle);
			pts[i][1] = sin(angle);
			sum += pts[i][0];
		}
		end = (sum - 42.0 * gap / size) / 40.0;
		pts[40][0] = pts[41][0] = end;
		pts[40][1] = -gap / size;
		pts[41][1] = gap / size;
		at = (size_t)snprintf(text, sizeof text,
				      "v\nfrom 0 0 10\nat 0 0 0\nup 0 1 0\nangle 30\nhither 1\n"
				      "resolution 8 8\nl 0 0 10\nf 1 1 1 1 0 0 0 1\np 42\n");
		for (i = 0; i < 42 && at < sizeof text; i++) {
			double x = size * pts[i][0], y = size * pts[i][1];
			int n = snprintf(text + at, sizeof text - at, "%.17g %.17g %.17g\n",
					 x * axis[0][0] + y * axis[1][0], x * axis[0][1] + y * axis[1][1],
					 x * axis[0][2] + y * axis[1][2]);
			at = n > 0 ? at + (size_t)n : at;
		}
		if (!CHECK(test_parse_buffer(&s, "slit.nff", text, NULL, NULL)))
			return;
		o = &s.objects[0];
		for (i = 0; i < 42; i++)
			centre = vec_add(centre, s.vertices[o->u.polygon.first + i]);
		centre = vec_scale(centre, REAL_C(1.0) / 42);
		for (i = 0; i < 20; i++) {
			vec3 front = dir_to_vec(o->u.polygon.normal), target = centre, from;
			if (i > 0)
				target = vec_add(centre, vec_make(test_real(test_random_range(-1e-3, 1e-3) * size),
								  test_real(test_random_range(-1e-3, 1e-3) * size),
								  test_real(test_random_range(-1e-3, 1e-3) * size)));
			from = vec_add(target, vec_scale(front, test_real(2.0 * size)));
			tally_ray(i > 0 ? &tally : &at_centroid, o, from, target);
		}
	}
	CHECK_INT(tally.rays, 760);
	CHECK(tally.inside > 400); /* around the centroid: the polygon, but for the slit */
	CHECK_INT(tally.disagree, 0);
	CHECK_INT(at_centroid.rays, 40);
	CHECK_INT(at_centroid.inside, 0); /* in the slit */
	CHECK_INT(at_centroid.disagree, 0);
}

/* Whether the build gave the polygon edge lines (polygon_init). */
static int has_edge_lines(const polygon_shape *poly)
{
#if POLYGON_EDGES
	return poly->extent > REAL_C(0.0);
#else
	(void)poly;
	return 0;
#endif
}

/* The outlines of test_edge_lines in their own plane (u, v), w off it; returns the vertex
 * count. Kinds 0-3 are convex and go once round (a triangle, a needle, a convex polygon
 * of 4-16 vertices on an ellipse, either way round, a quad with a corner off the plane);
 * 4-7 are not (a dart, a bow-tie, a pentagon twice round, a square with a vertex
 * repeated) and must get no edge lines. */
static int edge_test_outline(int kind, double uvw[16][3])
{
	int n, i;
	memset(uvw, 0, 16 * sizeof uvw[0]);
	if (kind <= 1) {
		for (i = 0; i < 3; i++) {
			uvw[i][0] = test_random_range(-1.0, 1.0);
			uvw[i][1] = test_random_range(-1.0, 1.0);
		}
		if (kind == 1) { /* the third vertex just off the first two's line */
			double f = test_random_range(0.1, 0.9), off = pow(10.0, -test_random_range(3.0, 6.0));
			uvw[2][0] = uvw[0][0] + f * (uvw[1][0] - uvw[0][0]) - off * (uvw[1][1] - uvw[0][1]);
			uvw[2][1] = uvw[0][1] + f * (uvw[1][1] - uvw[0][1]) + off * (uvw[1][0] - uvw[0][0]);
		}
		return 3;
	}
	if (kind == 2 || kind == 3) {
		double a = test_random_range(0.3, 1.0), b = test_random_range(0.3, 1.0), sense;
		double angle[16];
		n = kind == 3 ? 4 : 4 + (int)test_random_range(0.0, 12.99);
		sense = test_random() < 0.5 ? 1.0 : -1.0;
		for (i = 0; i < n; i++) /* sorted angles: a convex outline */
			angle[i] = 6.283185307179586 * (i + test_random_range(0.05, 0.95)) / n;
		for (i = 0; i < n; i++) {
			uvw[i][0] = a * cos(sense * angle[i]);
			uvw[i][1] = b * sin(sense * angle[i]);
		}
		if (kind == 3)
			uvw[2][2] = test_random_range(-0.01, 0.01);
		return n;
	}
	if (kind == 4 || kind == 5) {
		static const double dart[4][2] = {{0, 0}, {1, 0.4}, {0.3, 0}, {1, -0.4}};
		static const double bow[4][2] = {{0, 0}, {1, 1}, {1, 0}, {0, 1}};
		for (i = 0; i < 4; i++) {
			uvw[i][0] = kind == 4 ? dart[i][0] : bow[i][0];
			uvw[i][1] = kind == 4 ? dart[i][1] : bow[i][1];
		}
		return 4;
	}
	n = kind == 6 ? 10 : 5;
	for (i = 0; i < n; i++) {
		int k = kind == 6 ? i % 5 : i == 4 ? 3 : i;
		double angle = kind == 6 ? 1.2566370614359172 * k : 1.5707963267948966 * k;
		uvw[i][0] = cos(angle);
		uvw[i][1] = sin(angle);
	}
	return n;
}

/* Convex polygons, floating point: a ray the hit point's distances from the edges' lines
 * decide (polygon_edge_verdict) is decided as the crossings test decides it. 480
 * polygons of the kinds of edge_test_outline, turned at random, 10^-3 to 10^3 across and
 * up to 10^4 of their size from the origin (fixed point: 1 to 100, near it), each met by
 * 250 rays from either side at every angle down to 1/1000 of a right angle's cosine, at
 * random points, at vertices and at points of an edge moved off it by 10^-15 to 10^-2 of
 * the size (where the lines cannot decide, and the crossings test must). Fixed point has
 * no edge lines: every verdict is -1. */
static void test_edge_lines(void)
{
	static char text[1 << 19];
	const int polygons = 480, rays = 250;
	size_t at;
	int i, k, decided = 0, undecided = 0, wrong = 0, inside = 0, disagree = 0, total = 0;
	int lined[8] = {0}, open_rays = 0, open_decided = 0;
	double sizes[480];
	test_seed(19);
	at = (size_t)snprintf(text, sizeof text,
			      "v\nfrom 0 0 10\nat 0 0 0\nup 0 1 0\nangle 30\nhither 1\n"
			      "resolution 8 8\nl 0 0 10\nf 1 1 1 1 0 0 0 1\n");
	for (i = 0; i < polygons; i++) {
		double uvw[16][3], axis[3][3], size, far[3];
		int n = edge_test_outline(i % 8, uvw), m;
		random_rotation(axis);
		size = REAL_FIXED ? test_random_range(1.0, 100.0) : pow(10.0, test_random_range(-3.0, 3.0));
		for (k = 0; k < 3; k++)
			far[k] = REAL_FIXED ? test_random_range(-50.0, 50.0)
					    : size * test_random_range(-1e4, 1e4) * (i % 3 == 0);
		sizes[i] = size;
		m = snprintf(text + at, sizeof text - at, "p %d\n", n);
		at = m > 0 && (size_t)m < sizeof text - at ? at + (size_t)m : sizeof text;
		for (k = 0; k < n && at < sizeof text; k++) {
			double p[3];
			int c;
			for (c = 0; c < 3; c++)
				p[c] = far[c] + size * (uvw[k][0] * axis[0][c] + uvw[k][1] * axis[1][c] +
							uvw[k][2] * axis[2][c]);
			m = snprintf(text + at, sizeof text - at, "%.17g %.17g %.17g\n", p[0], p[1], p[2]);
			/* Past the end (truncated): at stays there, and nothing more is written. */
			at = m > 0 && (size_t)m < sizeof text - at ? at + (size_t)m : sizeof text;
		}
	}
	if (!CHECK(at < sizeof text) || !CHECK(test_parse_buffer(&s, "edges.nff", text, NULL, NULL)))
		return;
	CHECK_INT(s.object_count, polygons);
	for (i = 0; i < polygons && i < s.object_count; i++) {
		const object *o = &s.objects[i];
		const polygon_shape *poly = &o->u.polygon;
		const vec3 *v = s.vertices + poly->first;
		double size = sizes[i] * ldexp(1.0, s.length_shift);
		vec3 front = dir_to_vec(poly->normal);
		lined[i % 8] += has_edge_lines(poly);
		for (k = 0; k < rays; k++) {
			int how = k % 3, a = (int)test_random_range(0.0, poly->count - 0.01), verdict, plain;
			int b = a + 1 == poly->count ? 0 : a + 1;
			double c = pow(10.0, -test_random_range(0.0, 3.0)), off;
			vec3 target, across, from;
			unit denom;
			real t;
			ray r;
			if (how == 0) {
				double f = test_random_range(0.0, 1.0);
				int d = (a + 2) % poly->count;
				target = vec_add(vec_scale(v[a], test_real(1.0 - f)), vec_scale(v[d], test_real(f)));
				target = vec_add(target, vec_scale(vec_sub(v[b], v[a]),
								   test_real(test_random_range(-0.5, 0.5))));
			} else if (how == 1) {
				target = v[a];
			} else {
				/* A point of edge (a, b) moved across it in the plane. */
				double f = test_random_range(0.0, 1.0);
				target = vec_add(vec_scale(v[a], test_real(1.0 - f)), vec_scale(v[b], test_real(f)));
				across = vec_cross(front, vec_sub(v[b], v[a]));
				if (!(vec_length(across) > REAL_C(0.0)))
					continue;
				off = size * pow(10.0, -test_random_range(2.0, 15.0)) *
				      (test_random() < 0.5 ? -1.0 : 1.0);
				target = vec_add(target,
						 vec_scale(across, real_div(test_real(off), vec_length(across))));
			}
			/* Q16.16: near enough that the distance stays in its range. */
			if (!ray_start(target, front, k % 2 ? c : -c, size, 0.5, REAL_FIXED ? 4.0 : 100.0,
				       &from))
				continue;
			r = test_ray(from, vec_sub(target, from));
			denom = dir_dot(poly->normal, r.dir);
			if (denom == UNIT_C(0.0))
				continue;
			t = real_div_unit(plane_gap(poly->normal, poly->offset, &r.origin), denom);
			if (!(t > REAL_C(0.0)))
				continue;
			plain = polygon_contains_ray(v, poly->count, &r);
			verdict = polygon_edge_verdict(&s, poly, &r, t, denom);
			total++;
			inside += plain;
			decided += verdict >= 0;
			undecided += verdict < 0 && has_edge_lines(poly);
			wrong += verdict >= 0 && verdict != plain;
			/* Rays at random points of a lined polygon's plane, mostly far from its
			 * edges: the lines decide most (not near a needle's, nor within the
			 * bent quad's spread of its edges). */
			open_rays += how == 0 && has_edge_lines(poly);
			open_decided += how == 0 && verdict >= 0;
			/* The whole test, where no grazing box check can step in (polygon.c). */
			if (unit_fabs(denom) >= UNIT_C(0.25))
				disagree += polygon_intersect(&s, o, &r, REAL_C(0.0), REAL_MAX, NULL) != plain;
		}
	}
	CHECK(total > polygons * rays * 9 / 10);
	CHECK(inside > total / 5 && inside < total * 4 / 5);
	CHECK_INT(wrong, 0);
	CHECK_INT(disagree, 0);
	if (REAL_FIXED) {
		CHECK_INT(decided, 0);
		return;
	}
	/* Float's margin, 1024 of its roundings of the coordinates' size, is as wide as a
	 * polygon 10^4 of its size from the origin, and its needles are too thin for it to
	 * tell their third vertex from the line of the others: it decides far fewer. */
	for (k = 0; k < 8; k++) /* 60 of each kind: the convex ones lined, the others not */
		CHECK_INT(lined[k], k >= 4 ? 0 : k == 1 && REAL_EPSILON > REAL_C(1e-10) ? lined[k] : 60);
	CHECK(lined[1] >= 30);
	CHECK(open_rays > 15000);
	if (REAL_EPSILON > REAL_C(1e-10))
		CHECK(open_decided > open_rays / 10);
	else
		CHECK(open_decided > open_rays * 8 / 10);
	CHECK(undecided > 100); /* rays the crossings test had to decide, at the edges */
}

void suite_polygon(void)
{
	scene_init(&s, "polygon");
	test_square();
	test_parallel();
	test_shared();
	test_concave();
	test_other_axes();
	test_grid();
	test_patch();
	test_collinear();
	test_runs();
	test_triangles();
	test_discs();
	test_disc_slit();
	test_edge_lines();
}
