/* test_bvh.c - the bounding volume hierarchy finds what the object-by-object search
 * finds, for rays whose direction has zero or tiny components (boxes they run along).
 * See LICENSE for copyright and licence. */
#include <stdio.h>

#include "bvh.h"
#include "intersect.h"
#include "support.h"
#include "test.h"

/* Several megabytes: static, never on the stack. */
static scene s;

#if RT_USE_BVH
/* Appends the NFF text of a 1 x 1 tile at x0, z0 in the plane y = 0, facing -y. */
static size_t tile(char *text, size_t at, size_t size, int x0, int z0)
{
	int n = snprintf(text + at, size - at, "p 4\n%d 0 %d\n%d 0 %d\n%d 0 %d\n%d 0 %d\n", x0, z0,
			 x0 + 1, z0, x0 + 1, z0 + 1, x0, z0 + 1);
	return n > 0 ? at + (size_t)n : at;
}

/* The eye at (0, -50, 0) in front of a 4 x 4 grid of tiles whose edges lie on x = 0 and
 * z = 0: the eye's own coordinates. Rays towards the grid with components of 0 and below
 * 2^-15 (where Q16.16's reciprocal saturated and boxes were cut short) must meet the same
 * tile through the hierarchy as object by object. */
static void test_axis_rays(void)
{
	static char text[4096];
	static const double tiny[] = {0.0, 1e-7, -1e-7, 1e-6, -1e-6, 1e-5, -1e-5, 3e-5, -3e-5,
				      6e-5, -6e-5, 1e-3, -1e-3, 0.01, -0.01, 0.03, -0.03};
	enum { TINY = sizeof tiny / sizeof tiny[0] };
	size_t at;
	int i, j, x, z, misses = 0, mismatches = 0, rays = 0;
	const accel *tree, *plain;

	at = (size_t)snprintf(text, sizeof text,
			      "v\nfrom 0 -50 0\nat 0 0 0\nup 0 0 1\nangle 30\nhither 1\n"
			      "resolution 8 8\nl 0 -40 10\nf 1 1 1 1 0 0 0 1\n");
	for (x = -2; x < 2; x++)
		for (z = -2; z < 2; z++)
			at = tile(text, at, sizeof text, x, z);
	if (!CHECK(test_parse_buffer(&s, "axis.nff", text, NULL, NULL)))
		return;
	CHECK_INT(s.object_count, 16);
	tree = test_accel(&s, 1);
	plain = test_accel(&s, 0);
	if (!CHECK(tree->tree.node_count > 0))
		return;
	for (i = 0; i < TINY; i++)
		for (j = 0; j < TINY; j++) {
			ray r;
			hit through_tree, one_by_one;
			int found_tree, found_each;
			r.origin = s.camera.from;
			r.dir = dir_make(test_unit(tiny[i]), UNIT_C(1.0), test_unit(tiny[j]));
			found_tree = scene_intersect(tree, &r, REAL_MAX, &through_tree);
			found_each = scene_intersect(plain, &r, REAL_MAX, &one_by_one);
			rays++;
			misses += !found_each;
			mismatches += found_tree != found_each ||
				      (found_each && through_tree.object != one_by_one.object);
		}
	CHECK_INT(rays, TINY * TINY);
	CHECK_INT(misses, 0);
	CHECK_INT(mismatches, 0);
}
#endif

void suite_bvh(void)
{
#if RT_USE_BVH
	test_axis_rays();
#endif
}
