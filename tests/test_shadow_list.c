/* test_shadow_list.c - shadow rays from a transmitting solid towards a light answered by
 * the solid's list (shadow_list.h) pass the same light as object by object: from inside,
 * on and just outside glass spheres that overlap and touch, through stacks of glass whose
 * product rounds by its order, past opaque blockers, to lights near and far, at the
 * scales a scene may have; a crowded shaft gets no list, rays that do not start at the
 * solid or end at the light are left to the tree, and a list with one object left out
 * gives the wrong light.
 * See LICENSE for copyright and licence. */
#include <math.h>
#include <stdio.h>

#include "intersect.h"
#include "shadow_list.h"
#include "support.h"
#include "test.h"

#if SHADOW_LISTS
static scene s; /* large: static */
static char text[1 << 15];

/* The scene: glass spheres 0 (kt 0.9), 1 (0.9, overlapping 0) and 2 (0.7, touching 1),
 * a stack above 0 of glass 3 (0.55) and 4 (0.7) and an opaque sphere 5 that covers part
 * of the way to light 2, a triangle 6 and a rod 7 beside sphere 1, a glass sphere 8 with
 * twelve opaque beads 9-20 round its way to light 0, and eleven spheres far off; lights 0
 * (far), 1 (near the spheres) and 2 (high above). `scale` multiplies every length. */
static int write_scene(double scale)
{
	/* Light 0 seen from sphere 8's centre (10, 10, 10): (50, -50, 70) over its length. */
	const double toward[3] = {50 / 99.4987, -50 / 99.4987, 70 / 99.4987};
	int at, i;
	at = snprintf(text, sizeof text,
		      "v\nfrom 0 %g %g\nat 0 0 0\nup 0 0 1\nangle 40\nhither 0.01\n"
		      "resolution 8 8\nl %g %g %g\nl %g %g %g\nl %g %g %g\n"
		      "f 1 1 1 0 0 0 0.9 1.5\ns 0 0 0 %g\ns %g 0 0 %g\n"
		      "f 1 1 1 0 0 0 0.7 1.3\ns %g 0 0 %g\n"
		      "f 1 1 1 0 0 0 0.55 1.2\ns 0 0 %g %g\n"
		      "f 1 1 1 0 0 0 0.7 1.3\ns 0 0 %g %g\n"
		      "f 1 0 0 1 0 0 0 1\ns %g 0 %g %g\n"
		      "p 3\n%g %g %g\n%g %g %g\n%g %g %g\n"
		      "c %g %g %g %g %g %g %g %g\n"
		      "f 1 1 1 0 0 0 0.9 1.5\ns %g %g %g %g\nf 0 1 0 1 0 0 0 1\n",
		      -8 * scale, 1 * scale, 60 * scale, -40 * scale, 80 * scale, -2 * scale,
		      1 * scale, 3 * scale, 0.5 * scale, 0.5 * scale, 30 * scale, 1 * scale,
		      1.5 * scale, 0.8 * scale, 3.1 * scale, 0.8 * scale, 2.5 * scale, 0.5 * scale,
		      4 * scale, 0.4 * scale, 0.25 * scale, 5.5 * scale, 0.3 * scale, 1 * scale,
		      -2 * scale, -1 * scale, 2.5 * scale, -2 * scale, 1 * scale, 1.5 * scale,
		      -1 * scale, 2 * scale, 2 * scale, -2 * scale, 0.0, 0.05 * scale, 2 * scale,
		      -2 * scale, 3 * scale, 0.05 * scale, 10 * scale, 10 * scale, 10 * scale,
		      1 * scale);
	for (i = 0; i < 12 && at > 0 && at < (int)sizeof text; i++) {
		double along = 2.0 + 0.35 * i;
		at += snprintf(text + at, sizeof text - (size_t)at, "s %g %g %g %g\n",
			       (10 + along * toward[0]) * scale, (10 + along * toward[1]) * scale,
			       (10 + along * toward[2]) * scale, 0.12 * scale);
	}
	for (i = 0; i < 11 && at > 0 && at < (int)sizeof text; i++)
		at += snprintf(text + at, sizeof text - (size_t)at, "s %g %g %g %g\n",
			       (-60 + i) * scale, -60 * scale, -60 * scale, 0.5 * scale);
	return CHECK(at > 0 && at < (int)sizeof text) &&
	       CHECK(test_parse_buffer(&s, "shadow-lists.nff", text, NULL, NULL));
}

/* A shadow ray as the tracer makes it (trace.c): from a point of sphere o's surface, or
 * inside or outside it by 10^-12 to a third of its radius, towards light `lamp`, as far as
 * the light is from the surface point (its direction and length from there too). */
static ray shadow_ray(int o, int lamp, real *tmax)
{
	const sphere_shape *sphere = &s.objects[o].u.sphere;
	double c[3], r = test_double(sphere->radius), d[3], length = 0.0;
	double depth = r * pow(10.0, -test_random_range(0.5, 12.0));
	vec3 surface, to;
	ray shadow;
	int k;
	c[0] = test_double(sphere->center.x);
	c[1] = test_double(sphere->center.y);
	c[2] = test_double(sphere->center.z);
	do {
		length = 0.0;
		for (k = 0; k < 3; k++) {
			d[k] = test_random_range(-1.0, 1.0);
			length += d[k] * d[k];
		}
	} while (length < 1e-6 || length > 1.0);
	length = sqrt(length);
	surface = vec_make(test_real(c[0] + r * d[0] / length), test_real(c[1] + r * d[1] / length),
			   test_real(c[2] + r * d[2] / length));
	to = vec_sub(s.lights[lamp].position, surface);
	*tmax = real_sqrt(vec_dot(to, to));
	shadow.dir = dir_normalize(to);
	shadow.origin = surface;
	if (test_random_bits() % 4 != 0) {
		double off = test_random_bits() % 2 ? r + depth : r - depth;
		shadow.origin = vec_make(test_real(c[0] + off * d[0] / length),
					 test_real(c[1] + off * d[1] / length),
					 test_real(c[2] + off * d[2] / length));
	}
	return shadow;
}

typedef struct {
	int answered, mismatches, dimmed, thrice, blocked;
} tally;

/* `count` shadow rays from sphere o to light `lamp` through list l (where it answers) and
 * object by object. */
static void compare(const accel *tree, const accel *plain, const shadow_list *l, int o,
		    int lamp, int count, tally *t)
{
	int i;
	for (i = 0; i < count; i++) {
		real tmax, listed, one_by_one;
		int blocker;
		ray r = shadow_ray(o, lamp, &tmax);
		if (shadow_list_pass(l, &s, &r, tmax, -1, &listed, &blocker))
			t->answered++;
		else
			listed = scene_transmittance(tree, &r, tmax, -1, NULL);
		one_by_one = scene_transmittance(plain, &r, tmax, -1, NULL);
		t->mismatches += listed != one_by_one;
		t->dimmed += one_by_one > REAL_C(0.0) && one_by_one < REAL_C(1.0);
		t->thrice += one_by_one > REAL_C(0.0) && one_by_one < REAL_C(0.9 * 0.55);
		t->blocked += one_by_one == REAL_C(0.0);
	}
}

/* Object o's list for light `lamp`, made as a tracer makes it. */
static void list_of(const accel *tree, int o, int lamp, shadow_list *l)
{
	bvh_point lo, hi;
	l->count = -1;
	if (CHECK(bvh_object_box(&s, o, &lo, &hi)))
		shadow_list_make(l, &s, &tree->tree, bvh_point_vec(lo), bvh_point_vec(hi),
				 s.lights[lamp].position);
}

static void test_lists(double scale)
{
	static shadow_list lists[9][3], broken;
	const accel *tree, *plain;
	tally t = {0, 0, 0, 0, 0};
	int lamp, o, i, missing, stack, far;
	if (!write_scene(scale))
		return;
	tree = test_accel(&s, 1);
	plain = test_accel(&s, 0);
	if (!CHECK(tree->tree.node_count > 0))
		return;
	for (o = 0; o < 9; o++)
		for (lamp = 0; lamp < 3; lamp++)
			list_of(tree, o, lamp, &lists[o][lamp]);
	/* Glass spheres 0-2 to every light, 3 to light 2 (through 4 and past 5). */
	for (o = 0; o < 3; o++)
		for (lamp = 0; lamp < 3; lamp++)
			compare(tree, plain, &lists[o][lamp], o, lamp, 3000, &t);
	compare(tree, plain, &lists[3][2], 3, 2, 3000, &t);
	CHECK(t.answered > 20000);
	CHECK(t.dimmed > 10000);
	CHECK(t.thrice > 300);
	CHECK(t.blocked > 300);
	CHECK_INT(t.mismatches, 0);
	/* The way from sphere 8 to light 0 passes twelve beads, too many to list; to light 2,
	 * nothing. */
	CHECK_INT(lists[8][0].count, -1);
	CHECK(lists[8][2].count >= 0);
	t.answered = 0;
	compare(tree, plain, &lists[8][0], 8, 0, 500, &t);
	CHECK_INT(t.answered, 0);
	CHECK_INT(t.mismatches, 0);
	/* Sphere 0's list for light 2 holds the stack above it (3, 4 and 5), nothing far. */
	for (i = stack = far = 0; i < lists[0][2].count; i++) {
		stack += lists[0][2].objects[i] >= 3 && lists[0][2].objects[i] <= 5;
		far += lists[0][2].objects[i] >= 8;
	}
	CHECK_INT(stack, 3);
	CHECK_INT(far, 0);
	/* Rays that end short of the light, or start far from the solid: not answered. */
	for (i = 0, t.answered = 0; i < 1000; i++) {
		real tmax, pass;
		int blocker;
		ray r = shadow_ray(0, 2, &tmax);
		if (shadow_list_pass(&lists[0][2], &s, &r, tmax * REAL_C(0.99), -1, &pass,
				     &blocker))
			t.answered++;
		r.origin = vec_add(r.origin, vec_make(test_real(3 * scale), test_real(3 * scale),
						      test_real(3 * scale)));
		if (shadow_list_pass(&lists[0][2], &s, &r, tmax, -1, &pass, &blocker))
			t.answered++;
	}
	CHECK_INT(t.answered, 0);
	/* Sphere 0's list for light 2 without the glass sphere 3 above it: wrong light. */
	broken = lists[0][2];
	for (i = missing = 0; i < broken.count; i++)
		if (broken.objects[i] != 3)
			broken.objects[missing++] = broken.objects[i];
	CHECK_INT(missing, broken.count - 1);
	broken.count = missing;
	t.mismatches = 0;
	compare(tree, plain, &broken, 0, 2, 3000, &t);
	CHECK(t.mismatches > 100);
}

/* The accel's lists: one for each light of each glass solid with an inside list, the
 * crowded shaft's none, none for opaque objects; none in a scene with a polyhedron (its
 * box may leave corners out) or a plane (it would be in every list). */
static void test_built(void)
{
	static const char *const without[] = {"box 2 2 2 3 3 3\n", "plane 0 0 -5 0 0 1\n"};
	const accel *tree;
	const shadow_list *l;
	int o, lamp, found = 0, k;
	if (!write_scene(1.0))
		return;
	tree = test_accel(&s, 1);
	CHECK_INT(tree->shadow.list_count, tree->inside.list_count * 3);
	for (o = 0; o < s.object_count; o++)
		for (lamp = 0; lamp < 3; lamp++) {
			l = shadow_lists_find(&tree->shadow, &s, &tree->inside, o, lamp);
			found += l != NULL;
			CHECK(l == NULL || (o <= 4 || o == 8));
		}
	/* 0-4 and 8 for every light, but 8 for light 0. */
	CHECK_INT(found, 17);
	for (k = 0; k < 2; k++) {
		int at = snprintf(text, sizeof text,
				  "v\nfrom 0 -6 0\nat 0 0 0\nup 0 0 1\nangle 40\nhither 0.01\n"
				  "resolution 8 8\nl 0 -5 5\nf 1 1 1 0 0 0 0.9 1.5\ns 0 0 0 1\n%s",
				  without[k]);
		for (o = 0; o < 11 && at > 0 && at < (int)sizeof text; o++)
			at += snprintf(text + at, sizeof text - (size_t)at, "s %d 9 9 1\n",
				       5 + 3 * o);
		if (CHECK(at > 0 && at < (int)sizeof text) &&
		    CHECK(test_parse_buffer(&s, "shadow-none.nff", text, NULL, NULL))) {
			tree = test_accel(&s, 1);
			CHECK(tree->tree.node_count > 0);
			CHECK_INT(tree->shadow.list_count, 0);
			CHECK(shadow_lists_find(&tree->shadow, &s, &tree->inside, 0, 0) == NULL);
		}
	}
}

/* Random scenes of glass spheres and opaque triangles and spheres, lights among and
 * round them: every list's rays pass the same light as object by object. */
static void test_random_scenes(void)
{
	int scene_number;
	for (scene_number = 0; scene_number < 4; scene_number++) {
		const accel *tree, *plain;
		tally t = {0, 0, 0, 0, 0};
		int at, i, k, lamp, listed = 0;
		test_seed(900 + (unsigned long long)scene_number);
		at = snprintf(text, sizeof text,
			      "v\nfrom 0 -30 2\nat 0 0 0\nup 0 0 1\nangle 40\nhither 0.01\n"
			      "resolution 8 8\n");
		/* Each random number drawn in a statement of its own: the order a call's
		 * arguments are evaluated in is the compiler's. */
		for (lamp = 0; lamp < 3 && at > 0; lamp++) {
			double p[3];
			for (k = 0; k < 3; k++)
				p[k] = test_random_range(k < 2 ? -12 : 0, k < 2 ? 12 : 12 + 40 * lamp);
			at += snprintf(text + at, sizeof text - (size_t)at, "l %g %g %g\n", p[0], p[1],
				       p[2]);
		}
		for (i = 0; i < 60 && at > 0 && at < (int)sizeof text - 200; i++) {
			double p[6];
			for (k = 0; k < 6; k++)
				p[k] = k < 3 ? test_random_range(-6, 6) : test_random_range(-1, 1);
			if (i % 3 == 0)
				at += snprintf(text + at, sizeof text - (size_t)at,
					       "f 1 1 1 0 0 0 %g 1.5\ns %g %g %g %g\n",
					       0.3 + 0.3 * (p[3] + 1), p[0], p[1], p[2],
					       0.7 + 0.5 * p[4]);
			else if (i % 3 == 1)
				at += snprintf(text + at, sizeof text - (size_t)at,
					       "f 1 0 0 1 0 0 0 1\np 3\n%g %g %g\n%g %g %g\n"
					       "%g %g %g\n",
					       p[0], p[1], p[2], p[0] + p[3], p[1] + p[4], p[2], p[0],
					       p[1] + p[5], p[2] + p[3]);
			else
				at += snprintf(text + at, sizeof text - (size_t)at,
					       "f 0 1 0 1 0 0 0 1\ns %g %g %g %g\n", p[0], p[1], p[2],
					       0.325 + 0.275 * p[3]);
		}
		if (!CHECK(at > 0 && at < (int)sizeof text) ||
		    !CHECK(test_parse_buffer(&s, "shadow-random.nff", text, NULL, NULL)))
			return;
		tree = test_accel(&s, 1);
		plain = test_accel(&s, 0);
		for (k = 0; k < s.object_count; k++) {
			if (s.objects[k].kind != SHAPE_SPHERE ||
			    !(s.materials[s.objects[k].material].kt > REAL_C(0.0)))
				continue;
			for (lamp = 0; lamp < 3; lamp++) {
				static shadow_list l;
				list_of(tree, k, lamp, &l);
				listed += l.count >= 0;
				compare(tree, plain, &l, k, lamp, 300, &t);
			}
		}
		CHECK(listed > 40); /* of 60 (20 glass spheres, 3 lights) */
		CHECK(t.answered > 12000);
		CHECK(t.dimmed > 10000);
		CHECK(t.blocked > 100);
		CHECK_INT(t.mismatches, 0);
	}
}
#endif

void suite_shadow_list(void)
{
#if SHADOW_LISTS
	test_lists(1.0);
	test_lists(1e-4);
	test_lists(3e4);
	test_built();
	test_random_scenes();
#endif
}
