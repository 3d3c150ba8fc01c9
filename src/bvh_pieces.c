/* bvh_pieces.c - the boxes the hierarchy gives an object: how many (a long cone's side
 * in pieces, each with a box of its own), each one's bounds, and the padding that keeps
 * every hit the object's own test finds inside them.
 * See LICENSE for copyright and licence. */
#include "bvh.h"

#include "box.h"
#include "intersect.h"


/* A long cone across the axes (SPD rings' rods) fills a small part of its box, and a ray
 * through the box mostly misses it: its side is given in 2, 4 or 8 pieces of equal
 * length, each with its own box, as many as make the boxes' total area (the chance that
 * a ray meets one) least, if that is under PIECES_GAIN of the whole box's. A ray may then
 * find the cone in two leaves: a nearest hit is found again at the distance it already
 * has, which changes nothing, but a shadow ray would count a transmitting object's kt
 * twice, so only opaque cones are cut. Floating types only (fixed point keeps its tree). */
#define PIECES_MAX 8
#define PIECES_GAIN REAL_C(0.75)

int bvh_object_pieces(const scene *s, int index)
{
#if BVH_WIDE && RT_SHAPE_CONE
	const object *o = &s->objects[index];
	real2 whole = 0, least = 0;
	int pieces, best = 1;
	if (o->kind != SHAPE_CONE || s->materials[o->material].kt > REAL_C(0.0))
		return 1;
	for (pieces = 1; pieces <= PIECES_MAX; pieces *= 2) {
		real2 total = 0;
		int k;
		for (k = 0; k < pieces; k++) {
			vec3 lo, hi;
			cone_piece_bounds(&o->u.cone, k, pieces, &lo, &hi);
			total += box_half_area(lo, hi);
		}
		if (pieces == 1) {
			whole = least = total;
			continue;
		}
		/* Past the least the boxes' overlap grows faster than they shrink. */
		if (!(total < least))
			break;
		least = total;
		if (total < real2_scale(whole, PIECES_GAIN))
			best = pieces;
	}
	return best;
#else
	(void)s;
	(void)index;
	return 1;
#endif
}

int bvh_piece_bounds(const scene *s, int index, int piece, int pieces, vec3 *lo, vec3 *hi)
{
	const object *o = &s->objects[index];
#if RT_SHAPE_CONE
	if (pieces > 1)
		return cone_piece_bounds(&o->u.cone, piece, pieces, lo, hi);
#else
	(void)piece;
	(void)pieces;
#endif
	return shape_bounds(s, o, lo, hi);
}

int bvh_object_box(const scene *s, int index, bvh_point *lo, bvh_point *hi)
{
	vec3 l, h, p;
	real pad;
	if (!(shape_bounds(s, &s->objects[index], &l, &h) && vec_is_finite(l) && vec_is_finite(h)))
		return 0;
	pad = box_rounding_pad(l, h);
	p = vec_make(pad, pad, pad);
	*lo = bvh_round_corner(vec_sub(l, p), 0);
	*hi = bvh_round_corner(vec_add(h, p), 1);
	return 1;
}
