/* inside.h - the nearest hit of a ray that starts inside a solid (a glass sphere, say),
 * without the hierarchy: such a ray meets the solid on its way out, and nothing can be
 * met before that but the objects whose boxes overlap the solid's box, which are listed
 * once for each transmitting solid that has few enough of them. Floating types
 * with the wide tree (bvh.h's BVH_WIDE); elsewhere every ray searches the tree.
 * See LICENSE for copyright and licence. */
#ifndef RT_INSIDE_H
#define RT_INSIDE_H

#include "bvh.h"

#define INSIDE_LISTS (RT_USE_BVH && BVH_WIDE)

#if INSIDE_LISTS
#define INSIDE_MAX 8          /* other objects a list holds; a solid with more gets none */
/* Solids with lists, at most: the others search the tree. */
#define INSIDE_SOLIDS (RT_MAX_OBJECTS < 65536 ? RT_MAX_OBJECTS : 65536)

/* Where a listed object lies, seen from its solid: wholly in the half-space
 * toward . x >= beyond (its bounding ball's, rounding allowed for); toward 0 and beyond -1
 * where no such plane is known (the object is always tested). A ray's way through the
 * solid is a segment, which meets the half-space only if one of its ends does: touching
 * glass spheres, each listed by the others' boxes, meet within a pad of one point. */
typedef struct {
	vec3 toward;
	real beyond;
} inside_reach;

/* A solid's box, as the tree pads and rounds it, and the objects whose boxes overlap that
 * box grown by its padding once more (so that a hit point rounded a little outside the
 * box still has its object listed), with where each lies. */
typedef struct {
	bvh_point lo, hi;
	int solid;
	int count;
	int objects[INSIDE_MAX];
	inside_reach reach[INSIDE_MAX];
} inside_list;

typedef struct {
	/* Object i's list is lists[list_of[i] - 1] if that is a list of this build's and
	 * its solid is i: written only for the solids given lists, so that a scene of a
	 * million objects does not touch a million entries. */
	int list_of[RT_MAX_OBJECTS];
	int list_count;
	inside_list lists[INSIDE_SOLIDS];
} inside_lists;

/* Lists the objects overlapping each transmitting solid of s, through its tree t. A scene
 * with a polyhedron gets no lists: a polyhedron's box leaves out the corners that meet
 * too obliquely to compute (hedron.c), and its hits there may lie outside the box. */
void inside_build(inside_lists *l, const scene *s, const bvh_tree *t);

/* The nearest hit along r over (0, tmax), leaving out `skip`, for a ray that starts inside
 * object `solid`, as bvh_nearest finds it (h->object set, normals not faced): returns 1
 * with *found set when the list answers, 0 when the tree must (no list, or the ray starts
 * outside the solid's box, or meets the solid nowhere, or outside its box). */
int inside_nearest(const inside_lists *l, const scene *s, const bvh_tree *t, int solid,
		   const ray *r, int skip, real tmax, hit *h, int *found);
#endif

#endif
