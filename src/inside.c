/* inside.c - the objects a ray inside a transmitting solid can meet before it leaves the
 * solid, listed once (inside.h), and the nearest hit of such a ray through its list.
 * See LICENSE for copyright and licence. */
#include "inside.h"

#include "box.h"
#include "intersect.h"

#include <limits.h>

#if INSIDE_LISTS

/* Whether the boxes [alo, ahi] and [blo, bhi] share a point (faces included). */
static int boxes_meet(const bvh_point *alo, const bvh_point *ahi, const bvh_point *blo,
		      const bvh_point *bhi)
{
	return alo->x <= bhi->x && blo->x <= ahi->x && alo->y <= bhi->y && blo->y <= ahi->y &&
	       alo->z <= bhi->z && blo->z <= ahi->z;
}

/* Whether the box [lo, hi] meets the box `region` (two corners), faces included. */
static int meets_box(const void *region, bvh_point lo, bvh_point hi)
{
	const bvh_point *reach = (const bvh_point *)region;
	return boxes_meet(&lo, &hi, &reach[0], &reach[1]);
}

/* Lists in l the objects other than `solid` whose boxes in the tree meet l's box grown by
 * its padding. Returns 0 when they are more than INSIDE_MAX. */
static int list_overlaps(inside_list *l, const scene *s, const bvh_tree *t, int solid)
{
	bvh_point reach[2];
	vec3 lo = bvh_point_vec(l->lo), hi = bvh_point_vec(l->hi);
	real pad = box_rounding_pad(lo, hi);
	vec3 grow = vec_make(pad, pad, pad);
	reach[0] = bvh_round_corner(vec_sub(lo, grow), 0);
	reach[1] = bvh_round_corner(vec_add(hi, grow), 1);
	return bvh_objects_meeting(s, t, meets_box, reach, solid, l->objects, INSIDE_MAX, LONG_MAX,
				   &l->count);
}

/* Where listed object o lies, seen from the centre of its solid's box [lo, hi]: the
 * half-space of its bounding ball's far side from there (inside.h), less what rounding can
 * move either side of the comparison inside_nearest makes. A sphere's ball is its own,
 * grown by two of the pads the tree grows its box by; any other object's is the ball
 * round its padded box. */
static inside_reach reach_of(const scene *s, int o, vec3 lo, vec3 hi)
{
	const object *ob = &s->objects[o];
	inside_reach reach;
	vec3 ball, away, olo, ohi;
	real radius, distance, size;
	reach.toward = vec_make(REAL_C(0.0), REAL_C(0.0), REAL_C(0.0));
	reach.beyond = REAL_C(-1.0);
	if (ob->kind == SHAPE_SPHERE) {
		if (!shape_bounds(s, ob, &olo, &ohi))
			return reach;
		ball = ob->u.sphere.center;
		radius = real_fabs(ob->u.sphere.radius) + REAL_C(2.0) * box_rounding_pad(olo, ohi);
	} else {
		bvh_point plo, phi;
		vec3 half;
		if (bvh_object_pieces(s, o) != 1 || !bvh_object_box(s, o, &plo, &phi))
			return reach;
		olo = bvh_point_vec(plo);
		ohi = bvh_point_vec(phi);
		ball = vec_scale(vec_add(olo, ohi), REAL_C(0.5));
		half = vec_scale(vec_sub(ohi, olo), REAL_C(0.5));
		radius = real_mul(real_sqrt(vec_dot(half, half)),
				  REAL_C(1.0) + REAL_C(8.0) * REAL_EPSILON);
	}
	/* The sizes of everything compared: the ball, and twice the solid's box, which holds
	 * the ends of a ray's way (so their coordinates' magnitudes sum to at most
	 * |lo|1 + |hi|1, as does the way's length). */
	size = real_fabs(ball.x) + real_fabs(ball.y) + real_fabs(ball.z) + radius +
	       REAL_C(2.0) * (real_fabs(lo.x) + real_fabs(lo.y) + real_fabs(lo.z) +
			      real_fabs(hi.x) + real_fabs(hi.y) + real_fabs(hi.z));
	away = vec_sub(ball, vec_scale(vec_add(lo, hi), REAL_C(0.5)));
	distance = real_sqrt(vec_dot(away, away));
	/* A ball centred within an epsilon of that size of the solid's centre has no side
	 * worth knowing, and the square of so short an offset could be subnormal, which would
	 * leave toward far from unit length: such an object is always tested. Past it the
	 * square is a normal number (the box is at least 4 pads wide), and toward unit to a
	 * few roundings. */
	if (!(distance > REAL_EPSILON * size) || !real_isfinite(distance))
		return reach;
	/* A point of the ball lies at least toward . ball - radius (1 + 4 epsilon) along
	 * toward. What the comparison must allow for is a few epsilon of `size` each: the
	 * rounding of the three dot products; the distance from the exact ray of the solid's
	 * computed exit point and of a listed object's computed hit (points on the ray, from
	 * the origin and a distance both bounded by the solid's box: a sphere's test is
	 * exact to a few epsilon of the offset from its centre, which a hit far along a ray
	 * from far off puts many pads off the sphere); and the ball's centre as computed.
	 * 32 epsilon of `size` covers them. */
	reach.toward = vec_scale(away, REAL_C(1.0) / distance);
	reach.beyond = vec_dot(reach.toward, ball) -
		       real_mul(radius, REAL_C(1.0) + REAL_C(4.0) * REAL_EPSILON) -
		       real_mul(REAL_C(32.0) * REAL_EPSILON, size);
	return reach;
}

void inside_build(inside_lists *l, const scene *s, const bvh_tree *t)
{
	int i;
	l->list_count = 0;
	/* A polyhedron's box may leave out a corner (hedron.c), and a list would then miss
	 * the polyhedron where it pokes into a solid's box: no lists (inside.h). */
	for (i = 0; i < s->object_count; i++)
		if (s->objects[i].kind == SHAPE_HEDRON)
			return;
	for (i = 0; i < s->object_count; i++) {
		const object *o = &s->objects[i];
		inside_list *list = &l->lists[l->list_count];
		/* A transmitting solid, which rays travel inside of (a flat object has no
		 * inside), in a tree, in one box (as bvh_object_box gives it). */
		if (!t->node_count || l->list_count == INSIDE_SOLIDS ||
		    shape_is(SHAPE_FLAT, o->kind) || !(s->materials[o->material].kt > REAL_C(0.0)) ||
		    bvh_object_pieces(s, i) != 1 || !bvh_object_box(s, i, &list->lo, &list->hi))
			continue;
		list->solid = i;
		if (list_overlaps(list, s, t, i)) {
			vec3 lo = bvh_point_vec(list->lo), hi = bvh_point_vec(list->hi);
			int k;
			for (k = 0; k < list->count; k++)
				list->reach[k] = reach_of(s, list->objects[k], lo, hi);
			l->list_of[i] = ++l->list_count;
		}
	}
}

/* Visits object o for the nearest hit as the tree's search does (bvh_traverse.h's
 * VISIT_NEAREST): a hit at the distance of the nearest so far goes to the lower index. */
static void visit_nearest(const scene *s, int o, const ray *r, int skip, real *tmax, hit *h)
{
	hit tie;
	if (o == skip)
		return;
	if (o < h->object) {
		if (object_intersect(s, o, r, REAL_C(0.0), real_step_up(*tmax), &tie) &&
		    tie.t <= *tmax) {
			*h = tie;
			*tmax = h->t;
			h->object = o;
		}
	} else if (object_intersect(s, o, r, REAL_C(0.0), *tmax, h)) {
		*tmax = h->t;
		h->object = o;
	}
}

/* Whether p lies in the solid's box of list l (faces included, exactly). */
static int list_holds(const inside_list *l, const vec3 *p)
{
	return p->x >= (real)l->lo.x && p->x <= (real)l->hi.x && p->y >= (real)l->lo.y &&
	       p->y <= (real)l->hi.y && p->z >= (real)l->lo.z && p->z <= (real)l->hi.z;
}

/* Why the list's answer is the tree's: the ray starts in the solid's box (checked
 * exactly) and meets the solid at h->t at a point found in the box too (checked; the
 * true point is within the point's rounding of it, far less than the box's padding); the
 * box being convex, the ray stays in it, so grown, all the way between. Any object the
 * ray meets before (or at) that distance it meets there, in its own box as the tree pads
 * it (the tree's own guarantee, which polyhedra do not keep: inside_build), so its box
 * meets the solid's grown box, and it is listed; objects without bounds are tested as
 * the tree tests them. Beyond that distance nothing can be nearer than the solid's hit. */
int inside_nearest(const inside_lists *l, const scene *s, const bvh_tree *t, int solid,
		   const ray *r, int skip, real tmax, hit *h, int *found)
{
	const inside_list *list;
	vec3 way_end;
	int i, k = l->list_of[solid];
	if (k < 1 || k > l->list_count || solid == skip)
		return 0;
	list = &l->lists[k - 1];
	if (list->solid != solid || !list_holds(list, &r->origin))
		return 0;
	/* The solid's hit must lie in its box, as the argument above needs (a ray from exactly
	 * on a sphere, tangent to it, can be given a root far off, which the tree would not
	 * take as nearest); the computed point is within the box's padding of the true one. */
	if (!object_intersect(s, solid, r, REAL_C(0.0), tmax, h) || !list_holds(list, &h->point))
		return 0;
	h->object = solid;
	tmax = h->t;
	way_end = h->point;
	for (i = 0; i < t->unbounded_count; i++)
		visit_nearest(s, t->index[i], r, skip, &tmax, h);
	for (i = 0; i < list->count; i++) {
		/* The ray's way to the solid's exit (or less, past a nearer hit) meets the
		 * listed object's half-space only if one of its ends lies in it. */
		const inside_reach *reach = &list->reach[i];
		if (vec_dot(reach->toward, r->origin) < reach->beyond &&
		    vec_dot(reach->toward, way_end) < reach->beyond)
			continue;
		visit_nearest(s, list->objects[i], r, skip, &tmax, h);
	}
	*found = 1;
	return 1;
}
#else
typedef int inside_unused; /* ISO C wants something in a translation unit */
#endif
