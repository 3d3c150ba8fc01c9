/* shadow_list.h - shadow rays without the hierarchy: a ray from a hit on an object towards a
 * light stays within the hull of the object's box and the light, and only the objects
 * whose boxes meet that hull can be crossed on the way. A transmitting solid, whose
 * surface the rays inside it meet again and again, each hit sending shadow rays, gets a
 * list of them for each light, where they are few, and its rays test only those.
 * Floating types with the wide tree (inside.h's INSIDE_LISTS); elsewhere every shadow ray
 * searches it.
 * See LICENSE for copyright and licence. */
#ifndef RT_SHADOW_LIST_H
#define RT_SHADOW_LIST_H

#include "inside.h"

#define SHADOW_LISTS INSIDE_LISTS

#if SHADOW_LISTS
#define SHADOW_LIST_MAX 8 /* objects a list holds; a shaft with more gets none */
/* Lists at most, and the tree's lanes one list's making looks at: on this scale the
 * making costs a few milliseconds (1,024 lists of 3,000 glass spheres, 3 ms). */
#define SHADOW_LIST_PAIRS 1024
#define SHADOW_LIST_LANES 256

/* An object's list for one light: where a shadow ray must start (the object's box, grown)
 * and end (the light, grown) for the list to hold everything it can cross, and what it
 * can cross. */
typedef struct {
	vec3 from_lo, from_hi, to_lo, to_hi;
	int count; /* -1: too many objects (or none could be made); the tree answers */
	int objects[SHADOW_LIST_MAX];
} shadow_list;

/* Makes l, the list of the objects of s (in tree t) that a shadow ray from the box
 * [lo, hi] towards a light at `lamp_at` can cross. */
void shadow_list_make(shadow_list *l, const scene *s, const bvh_tree *t, vec3 lo, vec3 hi,
		      vec3 lamp_at);

/* The light passing along shadow ray r over (0, tmax), leaving out `skip`, as
 * bvh_transmittance gives it (*blocker the opaque blocker, or -1), through list l: returns
 * 1 with *pass set when the list answers, 0 when the tree must (r does not start in the
 * list's box or does not end at its light, or the list has none). */
int shadow_list_pass(const shadow_list *l, const scene *s, const ray *r, real tmax, int skip,
		     real *pass, int *blocker);

/* The lists of the solids with inside lists (inside.h), for every light: solid k's (its
 * list_of - 1) for light i is lists[k light_count + i], made for as many solids as
 * SHADOW_LIST_PAIRS holds, in the inside lists' order. */
typedef struct {
	int list_count; /* lists made: a whole number of solids' */
	shadow_list lists[SHADOW_LIST_PAIRS];
} shadow_lists;

/* Makes the lists of s's solids with inside lists through tree t: none where the tree's
 * boxes may not hold their objects' hits (polyhedra: inside.h's boxes_hold) or some
 * objects have no bounds (they would be in every list). */
void shadow_lists_build(shadow_lists *sl, const scene *s, const bvh_tree *t,
			const inside_lists *inside);

/* The list for a shadow ray from a hit on object `from` towards light `lamp`, or NULL
 * where the tree is to answer. */
const shadow_list *shadow_lists_find(const shadow_lists *sl, const scene *s,
				     const inside_lists *inside, int from, int lamp);
#endif

#endif
