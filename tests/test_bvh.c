/* test_bvh.c - the bounding volume hierarchy finds what the object-by-object search
 * finds, for rays whose direction has zero or tiny components (boxes they run along).
 * See LICENSE for copyright and licence. */
#include <math.h>
#include <stdio.h>

#include "box.h"
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
/* Random objects: spheres and axis-aligned tiles (boxes of zero thickness, every tenth
 * with a longer one over it) at
 * coordinates that float cannot hold exactly (tenths), at scales from 1/100 to 100
 * (Q16.16: 1/3 to 3, the ratio of extent to feature it can render). */
static size_t random_objects(char *text, size_t at, size_t size, int count)
{
	int i;
	for (i = 0; i < count && at < size; i++) {
		double scale = i % 3 == 1 ? 1.0 : REAL_FIXED ? (i % 3 ? 3.0 : 0.3) : (i % 3 ? 100.0 : 0.01);
		double x = (double)(long)test_random_range(-300.0, 300.0) / 10.0 * scale;
		double y = (double)(long)test_random_range(-300.0, 300.0) / 10.0 * scale;
		double z = (double)(long)test_random_range(-300.0, 300.0) / 10.0 * scale;
		double e = 0.1 * scale;
		/* Every tenth tile has a second one over it, twice as long: coincident
		 * surfaces in boxes of their own, met at the same distance. */
		int copies = i % 2 ? 1 : i % 10 == 0 ? 2 : 1, copy;
		for (copy = 1; copy <= copies; copy++) {
			double w = e * copy;
			int n = i % 2 ? snprintf(text + at, size - at, "s %.17g %.17g %.17g %.17g\n", x,
						 y, z, e)
				      : snprintf(text + at, size - at,
						 "p 4\n%.17g %.17g %.17g\n%.17g %.17g %.17g\n"
						 "%.17g %.17g %.17g\n%.17g %.17g %.17g\n",
						 x, y, z, x + w, y, z, x + w, y, z + e, x, y, z + e);
			at = n > 0 ? at + (size_t)n : at;
		}
	}
	return at;
}

/* A component made hard for a slab test: kept, 0, -0, or tiny (below 2^-100 too, which
 * the wide tree's float test leaves to its test in reals). */
static double hard_component(double c, int how)
{
	static const double tiny[] = {0.0, -0.0, 1e-7, -1e-20, 1e-35, -1e-300};
	return how < 6 ? tiny[how] : c;
}

/* Rays aimed at the objects' box corners, edges and faces (where a box too small by a
 * rounding would lose the hit), from inside and outside the scene, from far away, with
 * components zeroed or made tiny: through the hierarchy they find what the object-by-
 * object search finds, at the same distance, and in floating point the same object (of
 * two coincident tiles, the first). */
static void test_hard_rays(void)
{
	static char text[1 << 16];
	size_t at;
	int i, rays = 0, hits = 0, mismatches = 0, object_mismatches = 0, ties = 0;
	int beyond_hits = 0; /* hits of rays beyond the float test's reach */
	int shadow_mismatches = 0, beyond_blocked = 0, blocked = 0, clear = 0;
	const accel *tree, *plain;
	test_seed(15);
	at = (size_t)snprintf(text, sizeof text,
			      "v\nfrom 0 -50 0\nat 0 0 0\nup 0 0 1\nangle 30\nhither 1\n"
			      "resolution 8 8\nl 0 -40 10\nf 1 1 1 1 0 0 0 1\n");
	at = random_objects(text, at, sizeof text, 400);
	if (!CHECK(test_parse_buffer(&s, "hard.nff", text, NULL, NULL)))
		return;
	CHECK_INT(s.object_count, 440);
	tree = test_accel(&s, 1);
	plain = test_accel(&s, 0);
	if (!CHECK(tree->tree.node_count > 0))
		return;
	for (i = 0; i < 20000; i++) {
		const object *o = &s.objects[(int)test_random_range(0.0, 439.99)];
		vec3 lo, hi, target, from, d;
		ray r;
		hit through_tree, one_by_one;
		int found_tree, found_each, axis, beyond, shadow;
		if (!shape_bounds(&s, o, &lo, &hi))
			continue;
		/* A corner, an edge's or a face's middle, or a point inside. */
		target = vec_make(i % 3 ? lo.x : vec_get(vec_scale(vec_add(lo, hi), REAL_C(0.5)), 0),
				  i % 5 ? hi.y : vec_get(vec_scale(vec_add(lo, hi), REAL_C(0.5)), 1),
				  i % 7 ? lo.z : hi.z);
		/* From a random point, a point on the same face (a ray in its plane), or far
		 * beyond the scene (floating point: past 2^100). */
		from = vec_make(test_scaled(test_random_range(-3000.0, 3000.0), 0),
				test_scaled(test_random_range(-3000.0, 3000.0), 0),
				test_scaled(test_random_range(-3000.0, 3000.0), 0));
		if (i % 4 == 1)
			from.x = target.x;
		if (!REAL_FIXED && i % 11 == 3)
			from = vec_scale(from, test_real(1e29));
		d = vec_sub(target, from);
		for (axis = 0; axis < 3; axis++) {
			int how = (int)test_random_range(0.0, 30.0);
			double c = hard_component(test_double(vec_get(d, axis)), how);
			if (axis == 0)
				d.x = test_scaled(c, 0);
			else if (axis == 1)
				d.y = test_scaled(c, 0);
			else
				d.z = test_scaled(c, 0);
		}
		if (vec_max_abs(d) == REAL_C(0.0))
			continue;
		r.origin = from;
		r.dir = dir_normalize(d);
		found_tree = scene_intersect(tree, &r, REAL_MAX, &through_tree);
		found_each = scene_intersect(plain, &r, REAL_MAX, &one_by_one);
		rays++;
		hits += found_each;
		beyond = 0;
		for (axis = 0; axis < 3; axis++) {
			double origin_size = fabs(test_double(vec_get(r.origin, axis)));
			double dir_size = fabs(test_double(vec_get(dir_to_vec(r.dir), axis)));
			beyond |= origin_size >= 0x1p100 || (dir_size > 0.0 && dir_size < 0x1p-100);
		}
		beyond_hits += beyond && found_each;
		/* The same ray as a shadow ray (the tiles are opaque: 0 or 1), to the end of the
		 * scene and to the nearest hit (which the open range leaves out). */
		for (shadow = 0; shadow < 1 + found_each; shadow++) {
			real tmax = shadow ? one_by_one.t : REAL_MAX;
			real light_tree = scene_transmittance(tree, &r, tmax, -1, NULL);
			real light_each = scene_transmittance(plain, &r, tmax, -1, NULL);
			shadow_mismatches += light_tree != light_each;
			blocked += light_each == REAL_C(0.0);
			clear += light_each == REAL_C(1.0);
			beyond_blocked += beyond && light_each == REAL_C(0.0);
		}
		mismatches += found_tree != found_each || (found_each && through_tree.t != one_by_one.t);
		/* Floating point: a tie goes to the lower index, as object by object. */
		object_mismatches += !REAL_FIXED && found_each && through_tree.object != one_by_one.object;
		ties += found_each && one_by_one.object + 1 < s.object_count &&
			object_intersect(&s, one_by_one.object + 1, &r, REAL_C(0.0), REAL_MAX, &through_tree) &&
			through_tree.t == one_by_one.t;
	}
	CHECK(rays > 15000);
	CHECK(hits > rays / 20); /* on the tiles, the boxes' corners and edges are met */
	CHECK_INT(mismatches, 0);
	CHECK_INT(object_mismatches, 0);
	CHECK(ties > 100); /* the coincident tiles are met */
	/* Floating types: rays the float test cannot take find their hits too (bvh_traverse.h;
	 * 424 in double, 39 in long double, 20 in float). */
	CHECK(REAL_FIXED || beyond_hits > 10);
	/* Shadow rays through the tree find the blockers the objects' own tests find, those
	 * beyond the float test's reach too (448 in double, 56 in long double, 32 in float;
	 * a search in reals that skipped half the lanes of shadow rays alone failed here). */
	CHECK_INT(shadow_mismatches, 0);
	CHECK(blocked > rays / 20 && clear > rays / 20);
	CHECK(REAL_FIXED || beyond_blocked > 10);
}

/* Parses a scene of `shapes` with the eye at y = -6 (which compare_rays takes the scale
 * from) and eleven spheres far off, so that rt builds a hierarchy for it; *tree and
 * *plain get the two ways of searching it. Returns 0 (a failed check) if it cannot. */
static int scene_of(const char *name, const char *shapes, const accel **tree, const accel **plain)
{
	static char text[4096];
	int i, at = snprintf(text, sizeof text,
			     "v\nfrom 0 -6 0.3\nat 0 0 0\nup 0 0 1\nangle 40\nhither 0.01\n"
			     "resolution 8 8\nl 0 -5 5\nf 1 0 0 1 0 0 0 1\n%s", shapes);
	for (i = 0; i < 11 && at > 0 && at < (int)sizeof text; i++)
		at += snprintf(text + at, sizeof text - (size_t)at, "s %d 30 30 0.5\n", 30 + i);
	if (!CHECK(at > 0 && at < (int)sizeof text) ||
	    !CHECK(test_parse_buffer(&s, name, text, NULL, NULL)))
		return 0;
	*tree = test_accel(&s, 1);
	*plain = test_accel(&s, 0);
	return CHECK((*tree)->tree.node_count > 0);
}

/* A random point in the box [lo, hi] (scene units), at the scene's scale `scale` (fixed
 * point scales the scene when it reads it; floating point: 1). */
static vec3 random_point(const double lo[3], const double hi[3], double scale)
{
	return vec_make(test_real(test_random_range(lo[0], hi[0]) * scale),
			test_real(test_random_range(lo[1], hi[1]) * scale),
			test_real(test_random_range(lo[2], hi[2]) * scale));
}

/* Compares `count` rays from random points of one box to random points of another
 * through the hierarchy and object by object: the same hit, distance and object.
 * Returns the hits; counts disagreements in *mismatches. The scenes below put the eye at
 * y = -6, which gives the scale. */
static int compare_rays(const accel *tree, const accel *plain, int count, const double from_lo[3],
			const double from_hi[3], const double to_lo[3], const double to_hi[3],
			int *mismatches)
{
	double scale = test_double(s.camera.from.y) / -6.0;
	int i, hits = 0;
	for (i = 0; i < count; i++) {
		vec3 from = random_point(from_lo, from_hi, scale);
		vec3 d = vec_sub(random_point(to_lo, to_hi, scale), from);
		hit through_tree, one_by_one;
		int found_tree, found_each;
		ray r;
		if (vec_max_abs(d) == REAL_C(0.0))
			continue;
		r.origin = from;
		r.dir = dir_normalize(d);
		found_tree = scene_intersect(tree, &r, REAL_MAX, &through_tree);
		found_each = scene_intersect(plain, &r, REAL_MAX, &one_by_one);
		hits += found_each;
		*mismatches += found_tree != found_each ||
			       (found_each && (through_tree.t != one_by_one.t ||
					       through_tree.object != one_by_one.object));
	}
	return hits;
}

/* A twisted quadrilateral (one corner raised 0.3): rt puts it in a plane through its
 * centroid, so a ray through its outline meets that plane outside the vertices' box,
 * and a grazing one far outside. Its bounds must hold every hit the test reports
 * (with the vertices' box alone, about 1 in 10,000 such rays was lost through the
 * hierarchy). */
static void test_nonplanar_polygon(void)
{
	/* From all round, level with the quad's low corners: many grazing rays. */
	static const double from_lo[3] = {-4.0, -4.0, -0.2}, from_hi[3] = {4.0, 4.0, 0.1};
	static const double to_lo[3] = {-1.2, -1.2, -0.1}, to_hi[3] = {1.2, 1.2, 0.1};
	int mismatches = 0, hits;
	const accel *tree, *plain;
	test_seed(16);
	if (!scene_of("nonplanar.nff", "p 4\n-1 -1 0\n1 -1 0\n1 1 0.3\n-1 1 0\n", &tree, &plain))
		return;
	hits = compare_rays(tree, plain, 200000, from_lo, from_hi, to_lo, to_hi, &mismatches);
	CHECK(hits > 10000);
	CHECK_INT(mismatches, 0);
}

/* A box with a roof whose two halves meet at a ridge of slope 1e-10, at z = 0 (where a
 * float box rounds by little): its corners come from nearly parallel planes
 * (n_i . (n_j x n_k) = 2e-10), which a fixed threshold of 1e-9 left out of the bounds,
 * losing rays that skim the ridge (long double, whose boxes are padded by less). */
static void test_flat_roof(void)
{
	/* Level rays just below the ridge's height, along it. */
	static const double from_lo[3] = {-0.001, -5.0, -2e-10}, from_hi[3] = {0.001, -5.0, 0.0};
	static const double to_lo[3] = {-0.001, 5.0, -2e-10}, to_hi[3] = {0.001, 5.0, 0.0};
	int mismatches = 0, hits;
	const accel *tree, *plain;
	test_seed(17);
	if (!scene_of("roof.nff",
		      "polyhedron 7\n-1 0 0 1\n1 0 0 1\n0 -1 0 1\n0 1 0 1\n0 0 -1 1\n"
		      "1e-10 0 1 0\n-1e-10 0 1 0\n",
		      &tree, &plain))
		return;
	hits = compare_rays(tree, plain, 20000, from_lo, from_hi, to_lo, to_hi, &mismatches);
	CHECK(hits > 10000);
	CHECK_INT(mismatches, 0);
}

/* Two boxes in the same place: every hit is a tie, which goes to the first, object by
 * object and through the hierarchy alike (a box's test once took a hit at the very
 * distance of the nearest so far, so the second won; and Q16.16's binary tree gave a tie
 * to whichever it met first). */
static void test_coincident_boxes(void)
{
	static const double from_lo[3] = {-4.0, -4.0, -4.0}, from_hi[3] = {4.0, -3.0, 4.0};
	static const double to_lo[3] = {-1.0, -1.0, -1.0}, to_hi[3] = {1.0, 1.0, 1.0};
	int mismatches = 0, hits;
	const accel *tree, *plain;
	hit h;
	ray r;
	test_seed(18);
	if (!scene_of("boxes.nff", "box -1 -1 -1 1 1 1\nbox -1 -1 -1 1 1 1\n", &tree, &plain))
		return;
	r.origin = s.camera.from;
	r.dir = dir_make(UNIT_C(0.0), UNIT_C(1.0), UNIT_C(0.0));
	CHECK(scene_intersect(plain, &r, REAL_MAX, &h) && h.object == 0);
	hits = compare_rays(tree, plain, 20000, from_lo, from_hi, to_lo, to_hi, &mismatches);
	CHECK(hits > 15000);
	CHECK_INT(mismatches, 0);
}

/* Does the box [box_lo, box_hi] hold the bounds of one of object o's pieces (its own,
 * for an object in one piece)? */
static int holds_a_piece(int o, vec3 box_lo, vec3 box_hi)
{
	int pieces = bvh_object_pieces(&s, o), k, axis;
	for (k = 0; k < pieces; k++) {
		vec3 lo, hi;
		int holds = 1;
		if (!bvh_piece_bounds(&s, o, k, pieces, &lo, &hi))
			return 1;
		for (axis = 0; axis < 3; axis++)
			holds &= vec_get(box_lo, axis) <= vec_get(lo, axis) &&
				 vec_get(box_hi, axis) >= vec_get(hi, axis);
		if (holds)
			return 1;
	}
	return 0;
}

#if !BVH_WIDE
/* Corner `side` of binary node n's box. */
static vec3 bvh_corner_of(const bvh_node *n, int side)
{
	return vec_make(bvh_bound(n, side, 0), bvh_bound(n, side, 1), bvh_bound(n, side, 2));
}

/* Checks the binary tree of the scene in `s` (fixed point's) for its shape: every bounded object in as
 * many leaves as it has pieces (one but for long cones), every box holding its
 * children's (and a leaf's a piece of each of its objects), and no leaf of more than
 * four objects unless their centres coincide. Returns the leaves. */
static int check_tree(const bvh_tree *t, const char *what)
{
	static unsigned char seen[RT_MAX_OBJECTS];
	int i, axis, leaves = 0, bad_boxes = 0, big_leaves = 0, missing = 0;
	for (i = 0; i < s.object_count; i++)
		seen[i] = 0;
	for (i = 0; i < t->unbounded_count; i++)
		seen[t->index[i]]++;
	for (i = 0; i < t->node_count; i++) {
		const bvh_node *n = &t->nodes[i];
		int k, first = n->count ? n->start : -1, count = n->count;
		if (!count) {
			/* Both children inside the parent. */
			for (k = 0; k < 2; k++)
				for (axis = 0; axis < 3; axis++)
					bad_boxes += bvh_bound(&t->nodes[n->start + k], 0, axis) <
							     bvh_bound(n, 0, axis) ||
						     bvh_bound(&t->nodes[n->start + k], 1, axis) >
							     bvh_bound(n, 1, axis);
			continue;
		}
		leaves++;
		big_leaves += count > 4;
		for (k = first; k < first + count; k++) {
			int o = t->index[k];
			seen[o]++;
			bad_boxes += !holds_a_piece(o, bvh_corner_of(n, 0), bvh_corner_of(n, 1));
		}
	}
	for (i = 0; i < s.object_count; i++)
		missing += seen[i] != bvh_object_pieces(&s, i);
	if (bad_boxes || big_leaves || missing)
		printf("  %s: %d boxes not holding, %d leaves over 4, %d objects not in their "
		       "pieces' leaves\n", what,
		       bad_boxes, big_leaves, missing);
	CHECK_INT(bad_boxes, 0);
	CHECK_INT(big_leaves, 0);
	CHECK_INT(missing, 0);
	return leaves;
}
#else
/* Does the float box of lane `lane` of wide node w hold [lo, hi]? */
static int lane_holds(const bvh_wide_node *w, int lane, vec3 lo, vec3 hi)
{
	int axis, holds = 1;
	for (axis = 0; axis < 3; axis++)
		holds &= (real)w->box[2 * axis][lane] <= vec_get(lo, axis) &&
			 (real)w->box[2 * axis + 1][lane] >= vec_get(hi, axis);
	return holds;
}

/* Checks the wide tree of the scene in `s` (the floating types') for its shape: from the
 * root, every bounded object in as many leaf lanes as it has pieces, each lane's box
 * holding one piece's bounds (the object's own for one piece), no leaf of more than four
 * objects, every inner lane's box holding all of its node's boxes, a node with an inner
 * lane full (nodes are opened until they have WIDE_LANES lanes or only leaves), empty
 * lanes last and never entered, and no more nodes than the storage's bound. Returns the
 * leaves. */
static int check_tree(const bvh_tree *t, const char *what)
{
	static unsigned char seen[RT_MAX_OBJECTS];
	static int pending[BVH_WIDE_NODES];
	int i, lane, top = 0, bad_boxes = 0, not_full = 0, bad_empty = 0, missing = 0, nodes = 0;
	int leaves = 0, big_leaves = 0;
	for (i = 0; i < s.object_count; i++)
		seen[i] = 0;
	for (i = 0; i < t->unbounded_count; i++)
		seen[t->index[i]]++;
	if (!CHECK(t->wide_count > 0 && t->wide_count <= BVH_WIDE_NODES))
		return 0;
	pending[top++] = 0;
	while (top > 0 && nodes <= t->wide_count) {
		const bvh_wide_node *w = &t->wide[pending[--top]];
		int lanes = 0, inner = 0;
		nodes++;
		for (lane = 0; lane < WIDE_LANES; lane++) {
			int child = w->child[lane], count = w->count[lane];
			vec3 lo, hi;
			if (child < 0) {
				/* Empty: inside out, so that no ray enters it. */
				bad_empty += count != 0 || !(w->box[0][lane] > w->box[1][lane]);
				continue;
			}
			bad_empty += lanes != lane; /* a lane in use after an empty one */
			lanes++;
			if (count == 0) {
				const bvh_wide_node *c = &t->wide[child];
				int k;
				inner++;
				for (k = 0; k < WIDE_LANES; k++) {
					if (c->child[k] < 0)
						continue;
					lo = vec_make((real)c->box[0][k], (real)c->box[2][k], (real)c->box[4][k]);
					hi = vec_make((real)c->box[1][k], (real)c->box[3][k], (real)c->box[5][k]);
					bad_boxes += !lane_holds(w, lane, lo, hi);
				}
				if (top < BVH_WIDE_NODES)
					pending[top++] = child;
				continue;
			}
			lo = vec_make((real)w->box[0][lane], (real)w->box[2][lane],
				      (real)w->box[4][lane]);
			hi = vec_make((real)w->box[1][lane], (real)w->box[3][lane],
				      (real)w->box[5][lane]);
			leaves++;
			big_leaves += count > 4;
			for (i = 0; i < (count == WIDE_ONE_OBJECT ? 1 : count); i++) {
				int o = count == WIDE_ONE_OBJECT ? child : t->index[child + i];
				seen[o]++;
				bad_boxes += !holds_a_piece(o, lo, hi);
			}
		}
		not_full += inner > 0 && lanes < WIDE_LANES;
	}
	for (i = 0; i < s.object_count; i++)
		missing += seen[i] != bvh_object_pieces(&s, i);
	if (bad_boxes || big_leaves || not_full || bad_empty || missing || nodes != t->wide_count)
		printf("  %s, wide: %d boxes not holding, %d leaves over 4, %d nodes not full, "
		       "%d bad empty lanes, %d objects not in their pieces' leaves, %d of %d nodes "
		       "reached\n",
		       what, bad_boxes, big_leaves, not_full, bad_empty, missing, nodes,
		       t->wide_count);
	CHECK_INT(bad_boxes, 0);
	CHECK_INT(big_leaves, 0);
	CHECK_INT(not_full, 0);
	CHECK_INT(bad_empty, 0);
	CHECK_INT(missing, 0);
	CHECK_INT(nodes, t->wide_count);
	return leaves;
}
#endif

/* Rods and cones 100 to 10^9 long (10^4 in float) and 0.02 to 0.3 thick, through the
 * eye's view at many angles, met far from their bases: the build cuts them into pieces
 * with boxes that fit them closely, and every hit their test reports must lie in one of
 * those boxes, or the tree misses what the search object by object finds (before the
 * cone test bounded its near misses, 502 of these rays in float and 7,691 in double).
 * Floating types (fixed point's scenes stay within 4096 and it keeps whole cones). */
static void test_long_cone_pieces(void)
{
	static const double from_lo[3] = {-3.0, -4.0, -3.0}, from_hi[3] = {3.0, -2.5, 3.0};
	static const double to_lo[3] = {-1.0, -0.5, -1.0}, to_hi[3] = {1.0, 0.5, 1.0};
	static char shapes[2048];
	const int longest = sizeof(real) == sizeof(float) ? 4 : 9;
	int at = 0, k, mismatches = 0, hits, pieced = 0;
	const accel *tree, *plain;
	if (REAL_FLOAT_FREE)
		return;
	test_seed(21);
	for (k = 0; k < 12 && at >= 0 && at < (int)sizeof shapes; k++) {
		double length = pow(10.0, 2.0 + (longest - 2) * test_random_range(0.0, 1.0));
		double theta = test_random_range(0.0, 3.14159265358979), phi = test_random_range(0.0, 6.2831853);
		double a[3], c[3], r0 = test_random_range(0.02, 0.3);
		double r1 = k % 3 == 0 ? test_random_range(0.02, 0.3) : r0;
		int i;
		a[0] = sin(theta) * cos(phi);
		a[1] = sin(theta) * sin(phi);
		a[2] = cos(theta);
		for (i = 0; i < 3; i++)
			c[i] = test_random_range(-0.5, 0.5);
		at += snprintf(shapes + at, sizeof shapes - (size_t)at,
			       "c %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g\n",
			       c[0] - a[0] * length / 2, c[1] - a[1] * length / 2,
			       c[2] - a[2] * length / 2, r0, c[0] + a[0] * length / 2,
			       c[1] + a[1] * length / 2, c[2] + a[2] * length / 2, r1);
	}
	if (!CHECK(at > 0 && at < (int)sizeof shapes) ||
	    !scene_of("long-cones.nff", shapes, &tree, &plain))
		return;
	for (k = 0; k < 12; k++)
		pieced += bvh_object_pieces(&s, k) > 1;
	CHECK(pieced >= 6);
	hits = compare_rays(tree, plain, 100000, from_lo, from_hi, to_lo, to_hi, &mismatches);
	CHECK(hits > 5000);
	CHECK_INT(mismatches, 0);
}

/* Long rods across the axes and a long cone, whose sides the build cuts into pieces, a
 * stubby cylinder it leaves whole, and a transmitting rod it must leave whole (a shadow
 * ray would count its kt once for each piece it finds): rays find the same nearest hit
 * through the tree as object by object, and shadow rays the same light. */
static void test_cut_cones(void)
{
	static const double from_lo[3] = {-3.0, -4.0, -3.0}, from_hi[3] = {3.0, -2.5, 3.0};
	static const double to_lo[3] = {-2.0, -1.0, -2.0}, to_hi[3] = {2.0, 1.0, 2.0};
	double scale;
	int mismatches = 0, hits, i, dimmed = 0, shadow_mismatches = 0;
	const accel *tree, *plain;
	test_seed(20);
	if (!scene_of("rods.nff",
		      "c -2 -1 -2 0.05 2 1 2 0.05\nc -2 1 2 0.05 2 -1 -2 0.05\n"
		      "c 2 -1 -2 0.08 -2 1 2 0.02\nc 0 0 -0.2 0.3 0 0 0.2 0.3\n"
		      "f 1 1 1 0 0 0 0.5 1.5\nc -2 0.5 -1 0.1 2 -0.5 1 0.1\n",
		      &tree, &plain))
		return;
	if (BVH_WIDE) {
		CHECK(bvh_object_pieces(&s, 0) > 1 && bvh_object_pieces(&s, 1) > 1 &&
		      bvh_object_pieces(&s, 2) > 1);
		CHECK_INT(bvh_object_pieces(&s, 3), 1);
	}
	CHECK_INT(bvh_object_pieces(&s, 4), 1);
	(void)check_tree(&tree->tree, "rods");
	hits = compare_rays(tree, plain, 100000, from_lo, from_hi, to_lo, to_hi, &mismatches);
	CHECK(hits > 10000);
	CHECK_INT(mismatches, 0);
	/* Shadow rays from one side of the rods to the other. */
	scale = test_double(s.camera.from.y) / -6.0;
	for (i = 0; i < 100000; i++) {
		vec3 from = random_point(from_lo, from_hi, scale);
		vec3 to = random_point(to_lo, to_hi, scale), d;
		real length, through_tree, one_by_one;
		ray r;
		to = vec_add(to, vec_sub(to, from)); /* past the rods */
		d = vec_sub(to, from);
		length = vec_length(d);
		if (!(length > REAL_C(0.0)))
			continue;
		r.origin = from;
		r.dir = dir_normalize(d);
		through_tree = scene_transmittance(tree, &r, length, -1, NULL);
		one_by_one = scene_transmittance(plain, &r, length, -1, NULL);
		shadow_mismatches += through_tree != one_by_one;
		dimmed += one_by_one > REAL_C(0.0) && one_by_one < REAL_C(1.0);
	}
	CHECK(dimmed > 1000);
	CHECK_INT(shadow_mismatches, 0);
}

#if INSIDE_LISTS
/* A point inside the sphere of centre c and radius r (scene units, times `scale`), at a
 * depth below its surface from r / 2 down to 10^-12 of r, or as far outside. */
static vec3 point_in_sphere(const double c[3], double r, double scale, int outside)
{
	double d[3], length = 0.0, depth = r * pow(10.0, -test_random_range(0.3, 12.0));
	int i;
	do {
		length = 0.0;
		for (i = 0; i < 3; i++) {
			d[i] = test_random_range(-1.0, 1.0);
			length += d[i] * d[i];
		}
	} while (length < 1e-6 || length > 1.0);
	length = sqrt(length);
	for (i = 0; i < 3; i++)
		d[i] = c[i] + d[i] / length * (outside ? r + depth : r - depth);
	return vec_make(test_real(d[0] * scale), test_real(d[1] * scale), test_real(d[2] * scale));
}

/* Compares `count` rays from inside (or just outside) solid `solid`, a sphere of centre c
 * and radius r, through its list (lists l) and object by object. Returns the rays the
 * list answered; counts disagreements in *mismatches. */
static int compare_inside(const accel *tree, const accel *plain, const inside_lists *l,
			  int solid, const double c[3], double r, int count, int *mismatches)
{
	double scale = test_double(s.camera.from.y) / -6.0;
	int i, answered = 0;
	for (i = 0; i < count; i++) {
		double d[3];
		hit listed, one_by_one;
		int found_list, found_each, k;
		ray ray_in;
		ray_in.origin = point_in_sphere(c, r, scale, i % 16 == 0);
		for (k = 0; k < 3; k++)
			d[k] = test_random_range(-1.0, 1.0);
		if (i % 8 == 3) {
			/* From a point on the surface (as near as the type has it), along the
			 * tangent plane: the sphere's test can give such a ray a root far off. */
			double p[3], e[3], pr = 0.0;
			for (k = 0; k < 3; k++) {
				e[k] = test_random_range(-1.0, 1.0);
				pr += e[k] * e[k];
			}
			pr = sqrt(pr);
			for (k = 0; k < 3; k++)
				p[k] = c[k] + r * e[k] / pr;
			ray_in.origin = vec_make(test_real(p[0] * scale), test_real(p[1] * scale),
						 test_real(p[2] * scale));
			/* e x d: square to the radius. */
			p[0] = e[1] * d[2] - e[2] * d[1];
			p[1] = e[2] * d[0] - e[0] * d[2];
			p[2] = e[0] * d[1] - e[1] * d[0];
			for (k = 0; k < 3; k++)
				d[k] = p[k];
		}
		if (fabs(d[0]) + fabs(d[1]) + fabs(d[2]) < 1e-3)
			continue;
		ray_in.dir = dir_normalize(vec_make(test_real(d[0]), test_real(d[1]), test_real(d[2])));
		if (inside_nearest(l, accel_scene(tree), &tree->tree, solid, &ray_in, -1, REAL_FAR,
				   &listed, &found_list))
			answered++;
		else
			found_list = scene_intersect_from(tree, &ray_in, NULL, -1, REAL_FAR, &listed);
		found_each = scene_intersect_from(plain, &ray_in, NULL, -1, REAL_FAR, &one_by_one);
		*mismatches += found_list != found_each ||
			       (found_each && (listed.t != one_by_one.t ||
					       listed.object != one_by_one.object));
	}
	return answered;
}

/* Compares `count` rays from inside sphere `solid` (centre c, radius r) aimed at points
 * within 10^-3 to 10^-13 of `target` (scene units), through the solid's list l and
 * object by object, as compare_inside does. */
static void compare_aimed(const accel *tree, const accel *plain, const inside_lists *l,
			  int solid, const double c[3], double r, const double target[3],
			  int count, int *mismatches)
{
	double scale = test_double(s.camera.from.y) / -6.0;
	int i, k;
	for (i = 0; i < count; i++) {
		vec3 origin = point_in_sphere(c, r, scale, 0);
		double spread = pow(10.0, -test_random_range(3.0, 13.0)), d[3];
		hit listed, one_by_one;
		int found_list, found_each;
		ray ray_in;
		for (k = 0; k < 3; k++)
			d[k] = (target[k] + spread * test_random_range(-1.0, 1.0)) * scale -
			       test_double(k == 0 ? origin.x : k == 1 ? origin.y : origin.z);
		ray_in.origin = origin;
		ray_in.dir = dir_normalize(vec_make(test_real(d[0]), test_real(d[1]), test_real(d[2])));
		if (!inside_nearest(l, accel_scene(tree), &tree->tree, solid, &ray_in, -1, REAL_FAR,
				    &listed, &found_list))
			found_list = scene_intersect_from(tree, &ray_in, NULL, -1, REAL_FAR, &listed);
		found_each = scene_intersect_from(plain, &ray_in, NULL, -1, REAL_FAR, &one_by_one);
		*mismatches += found_list != found_each ||
			       (found_each && (listed.t != one_by_one.t ||
					       listed.object != one_by_one.object));
	}
}

/* Rays inside transmitting solids (glass spheres that overlap, touch and hold other
 * objects, a glass cylinder, a glass sphere crowded past INSIDE_MAX), some from the
 * surface along it, find the same nearest hit through the solid's list as object by
 * object; a list with one object left out does not; a scene with a polyhedron gets no
 * lists (its box may leave corners out). */
static void test_inside_lists(void)
{
	static const double a[3] = {0, 0, 0}, b[3] = {1.5, 0, 0}, c[3] = {3.1, 0, 0};
	static const double crowded[3] = {10, 10, 10};
	static inside_lists broken;
	const accel *tree, *plain;
	const inside_lists *l;
	int mismatches = 0, answered, i, k;
	test_seed(22);
	if (!scene_of("inside.nff",
		      "f 1 1 1 0 0 0 0.9 1.5\n"
		      "s 0 0 0 1\ns 1.5 0 0 0.8\ns 3.1 0 0 0.8\nc 0 -3 -1 0.5 0 -3 1 0.5\n"
		      "s 10 10 10 1\n"
		      "f 1 0 0 1 0 0 0 1\n"
		      "s 0.3 0.2 0.1 0.2\np 3\n-2 0.5 -2\n2 0.5 -2\n0 0.5 2\n"
		      "c -2 -2 -1 0.05 4 2 1 0.05\nplane 0 0 -5 0 0 1\n"
		      "s 10 10 10.5 0.1\ns 10 10 9.5 0.1\ns 10 10.5 10 0.1\ns 10 9.5 10 0.1\n"
		      "s 10.5 10 10 0.1\ns 9.5 10 10 0.1\ns 10.3 10.3 10 0.1\ns 9.7 9.7 10 0.1\n"
		      "s 10.3 9.7 10 0.1\n",
		      &tree, &plain))
		return;
	l = &tree->inside;
	/* Lists for the four glass solids that have few neighbours, none for the crowded
	 * one or the opaque objects; the first holds the sphere it overlaps (not the one
	 * beyond, nor the cylinder), the sphere inside it, the triangle and the rod. */
	CHECK_INT(l->list_count, 4);
	CHECK(l->list_of[0] >= 1 && l->list_of[0] <= l->list_count);
	if (!CHECK(l->list_count >= 1) || !CHECK(l->lists[0].solid == 0))
		return;
	CHECK_INT(l->lists[0].count, 4); /* sphere 1, the inner sphere 5, triangle 6, rod 7 */
	answered = compare_inside(tree, plain, l, 0, a, 1.0, 20000, &mismatches);
	CHECK(answered > 15000);
	answered = compare_inside(tree, plain, l, 1, b, 0.8, 20000, &mismatches);
	CHECK(answered > 15000);
	answered = compare_inside(tree, plain, l, 2, c, 0.8, 20000, &mismatches);
	CHECK(answered > 15000);
	CHECK_INT(compare_inside(tree, plain, l, 4, crowded, 1.0, 2000, &mismatches), 0);
	CHECK_INT(mismatches, 0);
	/* Without the sphere inside the first, its rays find the far side through it. */
	broken = *l;
	for (i = k = 0; i < broken.lists[0].count; i++)
		if (broken.lists[0].objects[i] != 5)
			broken.lists[0].objects[k++] = broken.lists[0].objects[i];
	broken.lists[0].count = k;
	mismatches = 0;
	(void)compare_inside(tree, plain, &broken, 0, a, 1.0, 5000, &mismatches);
	CHECK(mismatches > 20);
	/* Spheres 1 and 2 touch at x = 2.3: each lists the other, and its reach (the half-space
	 * sphere 1 lies in, seen from sphere 2) holds the contact point and not sphere 2's
	 * centre, so that only rays whose way ends near the contact test sphere 1. Rays from
	 * inside sphere 2 aimed at the contact point meet sphere 1 there at the distance they
	 * leave sphere 2 (the lower index takes the tie): found through the list as object by
	 * object; with the half-space moved a few pads towards sphere 1, or with sphere 1
	 * never tested, not. */
	if (CHECK(l->list_count >= 3) && CHECK(l->lists[2].solid == 2)) {
		static const double contact[3] = {2.3, 0, 0};
		double scale = test_double(s.camera.from.y) / -6.0;
		const inside_list *two = &l->lists[2];
		const inside_reach *reach = NULL;
		for (i = 0; i < two->count; i++)
			if (two->objects[i] == 1)
				reach = &two->reach[i];
		if (CHECK(reach != NULL)) {
			vec3 at = vec_make(test_real(2.3 * scale), REAL_C(0.0), REAL_C(0.0));
			vec3 centre = vec_make(test_real(3.1 * scale), REAL_C(0.0), REAL_C(0.0));
			CHECK(vec_dot(reach->toward, at) >= reach->beyond);
			CHECK(vec_dot(reach->toward, centre) < reach->beyond);
			mismatches = 0;
			compare_aimed(tree, plain, l, 2, c, 0.8, contact, 20000, &mismatches);
			CHECK_INT(mismatches, 0);
			broken = *l;
			for (i = 0; i < broken.lists[2].count; i++)
				if (broken.lists[2].objects[i] == 1)
					broken.lists[2].reach[i].beyond +=
						REAL_C(4.0) * box_rounding_pad(centre, centre);
			mismatches = 0;
			compare_aimed(tree, plain, &broken, 2, c, 0.8, contact, 20000, &mismatches);
			CHECK(mismatches > 20);
		}
	}
	/* A sphere listed in a glass sphere whose centre lies off the glass's by a length
	 * whose square is subnormal (the least positive number's root, 1.125 times): no
	 * half-space for it (toward would be far from unit length), and the same hits as
	 * object by object. */
	{
		static char text[256];
		static const double origin[3] = {0, 0, 0};
		real least = REAL_C(1.0);
		while (least / REAL_C(2.0) > REAL_C(0.0))
			least /= REAL_C(2.0);
		snprintf(text, sizeof text, "f 1 1 1 0 0 0 0.9 1\ns 0 0 0 1\nf 1 0 0 1 0 0 0 1\n"
			 "s %.20Le 0 0 0.5\n", (long double)(real_sqrt(least) * REAL_C(1.125)));
		if (CHECK(scene_of("inside-near-centre.nff", text, &tree, &plain)) &&
		    CHECK(tree->inside.list_count >= 1)) {
			static const double cap[3] = {-0.47, 0, 0};
			mismatches = 0;
			CHECK(compare_inside(tree, plain, &tree->inside, 0, origin, 1.0, 20000,
					     &mismatches) > 15000);
			/* Through the inner sphere's far cap, where a toward 1.125 long would
			 * have put the half-space's plane inside the sphere. */
			compare_aimed(tree, plain, &tree->inside, 0, origin, 1.0, cap, 20000,
				      &mismatches);
			CHECK_INT(mismatches, 0);
		}
	}
	if (CHECK(scene_of("inside-box.nff", "f 1 1 1 0 0 0 0.9 1.5\ns 0 0 0 1\nbox 2 2 2 3 3 3\n",
			   &tree, &plain)))
		CHECK_INT(tree->inside.list_count, 0);
}
#endif

/* Spheres of `count` at random centres in a cube of side `size` around `centre`, radii
 * from 1/1000 to 1/10 of it; the last `fixed_axes` coordinates (z; y and z; all three) at
 * the centre's own: on a plane, on a line, or all at one point. */
static int sphere_scene(int count, double centre, double size, int fixed_axes)
{
	static char text[1 << 20];
	int i, at = snprintf(text, sizeof text,
			     "v\nfrom 0 0 -10\nat 0 0 0\nup 0 1 0\nangle 40\nhither 0.01\n"
			     "resolution 8 8\nl 0 5 -5\nf 1 0 0 1 0 0 0 1\n");
	for (i = 0; i < count && at > 0 && at < (int)sizeof text; i++) {
		double x = fixed_axes >= 3 ? 0.0 : test_random_range(-0.5, 0.5) * size;
		double y = fixed_axes >= 2 ? 0.0 : test_random_range(-0.5, 0.5) * size;
		double z = fixed_axes >= 1 ? 0.0 : test_random_range(-0.5, 0.5) * size;
		at += snprintf(text + at, sizeof text - (size_t)at, "s %.17g %.17g %.17g %.17g\n",
			       centre + x, centre + y, centre + z,
			       size * test_random_range(0.001, 0.1));
	}
	return CHECK(at > 0 && at < (int)sizeof text) &&
	       CHECK(test_parse_buffer(&s, "spheres.nff", text, NULL, NULL));
}

/* The tree's shape for scenes that take each of the build's ways: nodes split by bins
 * and by sorting (a few objects, a few over the sorted limit, thousands), centres on a
 * plane or a line (axes of no extent, which the binning leaves alone), all centres in
 * one place (split in halves), centres far from the origin where float's steps are
 * coarse (Q16.16: the edge of its range). */
static void test_tree_shape(void)
{
	static const struct {
		int count;
		double centre, size;
		int fixed_axes;
	} cases[] = {{12, 0.0, 10.0, 0},	     {17, 0.0, 10.0, 0},   {33, 0.0, 10.0, 0},
		     {3000, 0.0, 10.0, 0},   {40, 0.0, 10.0, 3},   {300, 0.0, 1e-3, 0},
		     {300, 1e6, 1.0, 0},     {300, -2000.0, 100.0, 0}, {2000, 0.0, 10.0, 1},
		     {2000, 5.0, 10.0, 2}};
	int c, leaves;
	test_seed(19);
	for (c = 0; c < (int)(sizeof cases / sizeof cases[0]); c++) {
		const accel *tree;
		char what[64];
		if (REAL_FIXED && (cases[c].centre > 30000.0 || cases[c].size < 0.01))
			continue;
		if (!sphere_scene(cases[c].count, cases[c].centre, cases[c].size, cases[c].fixed_axes))
			return;
		tree = test_accel(&s, 1);
		snprintf(what, sizeof what, "%d spheres at %g", cases[c].count, cases[c].centre);
		if (!CHECK(tree->tree.node_count > 0))
			continue;
		leaves = check_tree(&tree->tree, what);
		/* A leaf holds one to four objects. */
		CHECK(leaves * 4 >= cases[c].count && leaves <= cases[c].count);
	}
}

/* A cloud of transmitting spheres (four kt that no type holds exactly, a few opaque
 * among them) and shadow rays through it: through the hierarchy the light that passes
 * is the same number as object by object, bit for bit, in every type. The product of
 * three kt or more rounds by the order it is taken in, and the tree meets the spheres
 * in its own order: the search multiplies them in the objects' order, as the object-by-
 * object search does. Also with more crossed than a search holds at once. */
static void test_transmittance_order(void)
{
	static char text[1 << 16];
	static const char *const materials[] = {"f 1 1 1 0.2 0 0 0.3 1\n", "f 1 1 1 0.2 0 0 0.7 1\n",
						"f 1 1 1 0.2 0 0 0.9 1\n", "f 1 1 1 0.2 0 0 0.55 1\n",
						"f 1 1 1 0.2 0 0 0 1\n"};
	const accel *tree, *plain;
	int i, at, rays = 0, many = 0, beyond = 0, mismatches = 0, blocked = 0;
	test_seed(23);
	at = snprintf(text, sizeof text,
		      "v\nfrom 0 -50 0\nat 0 0 0\nup 0 0 1\nangle 30\nhither 1\n"
		      "resolution 8 8\nl 0 -40 10\n");
	for (i = 0; i < 600 && at > 0 && at < (int)sizeof text - 200; i++) {
		/* One sphere in 40 opaque; the rest transmit. */
		const char *f = materials[i % 40 == 39 ? 4 : i % 4];
		at += snprintf(text + at, sizeof text - (size_t)at, "%ss %.17g %.17g %.17g %.17g\n",
			       f, test_random_range(-4.0, 4.0), test_random_range(-4.0, 4.0),
			       test_random_range(-4.0, 4.0), test_random_range(0.3, 0.9));
	}
	if (!CHECK(at > 0 && at < (int)sizeof text) ||
	    !CHECK(test_parse_buffer(&s, "cloud.nff", text, NULL, NULL)))
		return;
	tree = test_accel(&s, 1);
	plain = test_accel(&s, 0);
	if (!CHECK(tree->tree.node_count > 0))
		return;
	for (i = 0; i < 4000; i++) {
		static const double lo[3] = {-6.0, -6.0, -6.0}, hi[3] = {6.0, 6.0, 6.0};
		double scale = test_double(s.camera.from.y) / -50.0;
		vec3 from = random_point(lo, hi, scale);
		vec3 d = vec_sub(random_point(lo, hi, scale), from);
		real through_tree, one_by_one;
		int crossed = 0, blocker_tree = -1, blocker_each = -1, k;
		ray r;
		if (vec_max_abs(d) == REAL_C(0.0))
			continue;
		r.origin = from;
		r.dir = dir_normalize(d);
		through_tree = scene_transmittance(tree, &r, REAL_MAX, -1, &blocker_tree);
		one_by_one = scene_transmittance(plain, &r, REAL_MAX, -1, &blocker_each);
		for (k = 0; k < s.object_count; k++)
			crossed += object_intersect(&s, k, &r, REAL_C(0.0), REAL_MAX, NULL);
		rays++;
		blocked += one_by_one == REAL_C(0.0);
		many += crossed >= 3 && one_by_one > REAL_C(0.0);
		beyond += crossed > BVH_CROSSED && one_by_one > REAL_C(0.0);
		/* The same number (long double's padding bytes are not compared). */
		mismatches += through_tree != one_by_one ||
			      (blocker_tree < 0) != (blocker_each < 0);
	}
	CHECK(rays > 3900);
	CHECK(many > rays / 4); /* most rays cross three transmitting spheres or more */
	CHECK(beyond > 40); /* some cross more than a search holds at once */
	CHECK(blocked > rays / 10);
	CHECK_INT(mismatches, 0);
}
#endif

#if RT_USE_BVH && BVH_WIDE
/* Whether f is x rounded outwards to float, and no further: up, f >= x and the float
 * below f is below x; down, the mirror. */
static int outward_and_tight(real x, int up, float f)
{
	if (up)
		return (real)f >= x && (real)nextafterf(f, -INFINITY) < x;
	return (real)f <= x && (real)nextafterf(f, INFINITY) > x;
}

/* float_outward (the tree's float corners), in both directions, for 0, the subnormals,
 * exact floats, values between floats and beyond float's range (in double and long
 * double: in float every value is a float already), both signs: the box of a corner is
 * too big by at most one float step and never too small. 40,000 magnitudes, each
 * positive and negative, rounded up and down: 160,000 checks. Boxes are finite (the tree
 * leaves other objects out), so infinities and NaN are not asked. */
static void test_float_outward(void)
{
	static const double special[] = {0.0, -0.0, 1.0, -1.0, 1e-45, 1.4e-45, 2.1e-45, 1e-46,
					 1.1754943e-38, 3.4028234663852886e38, 3.4028235e38, 1e39,
					 0.1, -0.1, 1.0 + 1e-12, 16777217.0, -16777217.0};
	long tested = 0, failures = 0;
	int i, up;
	test_seed(7);
	for (i = 0; i < 40000; i++) {
		real x;
		if (i < (int)(sizeof special / sizeof special[0])) {
			x = (real)special[i];
		} else {
			/* A random 53-bit mantissa at a random scale from 2^-160 to 2^140. */
			int scale = (int)(test_random_bits() % 301) - 160;
			x = (real)ldexp(0.5 + 0.5 * test_random(), scale);
		}
		/* In float, values beyond its range are infinite (and a box is finite). */
		if (!(x - x == 0))
			x = (real)FLT_MAX;
		for (up = 0; up < 2; up++) {
			tested++;
			failures += !outward_and_tight(x, up, float_outward(x, up));
			tested++;
			failures += !outward_and_tight(-x, up, float_outward(-x, up));
		}
	}
	CHECK_INT(tested, 160000);
	CHECK_INT(failures, 0);
}
#endif

void suite_bvh(void)
{
#if RT_USE_BVH
	test_axis_rays();
	test_hard_rays();
	test_nonplanar_polygon();
	test_flat_roof();
	test_coincident_boxes();
	test_tree_shape();
	test_transmittance_order();
	test_cut_cones();
	test_long_cone_pieces();
#if BVH_WIDE
	test_float_outward();
#endif
#if INSIDE_LISTS
	test_inside_lists();
#endif
#endif
}
