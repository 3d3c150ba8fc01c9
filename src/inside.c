/* inside.c - the objects a ray inside a transmitting solid can meet before it leaves the
 * solid, listed once (inside.h), and the nearest hit of such a ray through its list.
 * See LICENSE for copyright and licence. */
#include "inside.h"

#include "box.h"
#include "intersect.h"

#if INSIDE_LISTS

/* Whether the boxes [alo, ahi] and [blo, bhi] share a point (faces included). */
static int boxes_meet(const bvh_point *alo, const bvh_point *ahi, const bvh_point *blo,
		      const bvh_point *bhi)
{
	return alo->x <= bhi->x && blo->x <= ahi->x && alo->y <= bhi->y && blo->y <= ahi->y &&
	       alo->z <= bhi->z && blo->z <= ahi->z;
}

/* Lists in l the objects other than `solid` whose boxes in the tree meet l's box grown by
 * its padding: through
 * the binary tree, each leaf's objects by their own boxes (a long cone cut in pieces,
 * bvh_pieces.c, by the leaf's box, which holds its piece's). Returns 0 when they are more
 * than INSIDE_MAX. */
static int list_overlaps(inside_list *l, const scene *s, const bvh_tree *t, int solid)
{
	int stack[BVH_MAX_DEPTH + 2], top = 1;
	bvh_point reach_lo, reach_hi;
	{
		vec3 lo = vec_make((real)l->lo.x, (real)l->lo.y, (real)l->lo.z);
		vec3 hi = vec_make((real)l->hi.x, (real)l->hi.y, (real)l->hi.z);
		real pad = box_rounding_pad(lo, hi);
		vec3 grow = vec_make(pad, pad, pad);
		reach_lo = bvh_round_corner(vec_sub(lo, grow), 0);
		reach_hi = bvh_round_corner(vec_add(hi, grow), 1);
	}
	l->count = 0;
	stack[0] = 0;
	while (top > 0) {
		const bvh_node *n = &t->nodes[stack[--top]];
		int i, k;
		if (!boxes_meet(&n->bounds[0], &n->bounds[1], &reach_lo, &reach_hi))
			continue;
		if (!n->count) {
			stack[top++] = n->start;
			stack[top++] = n->start + 1;
			continue;
		}
		for (i = n->start; i < n->start + n->count; i++) {
			int o = t->index[i];
			bvh_point lo, hi;
			/* A long cone's pieces are in several leaves: listed once. */
			for (k = 0; k < l->count && l->objects[k] != o; k++)
				;
			if (o == solid || k < l->count)
				continue;
			if (bvh_object_pieces(s, o) == 1 && bvh_object_box(s, o, &lo, &hi) &&
			    !boxes_meet(&lo, &hi, &reach_lo, &reach_hi))
				continue;
			if (l->count == INSIDE_MAX)
				return 0;
			l->objects[l->count++] = o;
		}
	}
	return 1;
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
		if (list_overlaps(list, s, t, i))
			l->list_of[i] = ++l->list_count;
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
	for (i = 0; i < t->unbounded_count; i++)
		visit_nearest(s, t->index[i], r, skip, &tmax, h);
	for (i = 0; i < list->count; i++)
		visit_nearest(s, list->objects[i], r, skip, &tmax, h);
	*found = 1;
	return 1;
}
#else
typedef int inside_unused; /* ISO C wants something in a translation unit */
#endif
