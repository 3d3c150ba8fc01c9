/* intersect.h - queries against the whole scene: nearest hit and shadow transmittance.
 * See LICENSE for copyright and licence. */
#ifndef RT_INTERSECT_H
#define RT_INTERSECT_H

#include <stddef.h>
#include <stdint.h>

#include "bvh.h"
#include "inside.h"
#include "shadow_list.h"
#include "shape.h"

/* What the queries below search: the scene, and where the build has one its BVH, built
 * once beside it (accel_build): the scene itself stays as it was loaded. Without a BVH
 * (the MCU build) there is nothing to add, and the scene is searched as it is. */
#if RT_USE_BVH
typedef struct {
	const scene *scene;
	bvh_tree tree;
#if INSIDE_LISTS
	inside_lists inside; /* the objects rays inside each transmitting solid can meet */
	shadow_lists shadow; /* and its shadow rays can cross on the way to each light */
#endif
} accel;
#define accel_scene(a) ((a)->scene)
#define accel_tree(a) ((a)->tree.node_count ? &(a)->tree : NULL) /* NULL: search each object */

/* The accel the queries search for s, built once into the intersection layer's own
 * storage (its hierarchy, for a scene large enough to need one): one scene at a time. */
const accel *accel_build(const scene *s);
#else
typedef scene accel;
#define accel_scene(a) (a)
#define accel_tree(a) ((void)(a), (const bvh_tree *)NULL)
#define accel_build(s) ((const accel *)(s)) /* a macro: on the M0 an inline function cost flash */
#endif

/* Dispatches to the object's shape; same contract as the shapes (shape.h). */
int object_intersect(const scene *s, int index, const ray *r, real tmin, real tmax, hit *h);
/* The same, given the object's terms for the ray's origin (or NULL). */
int object_intersect_from(const scene *s, int index, const ray *r, const origin_term *k,
			  real tmin, real tmax, hit *h);

/* Fills k for an object and an origin (nothing for shapes without such terms). */
void object_origin_term(const object *o, vec3 origin, origin_term *k);

/* Nearest hit along r in (0, tmax). On a hit, h's normals face the ray (h->front says
 * from which side it came). */
int scene_intersect(const accel *a, const ray *r, real tmax, hit *h);

/* The objects origin_terms_plane looks at: bits of a uint32_t. */
#define ORIGIN_PLANE_OBJECTS 32

/* Every object's terms that depend on the ray's origin alone (shape.h), for all rays
 * from one point: every eye ray starts at the camera. */
typedef struct {
	origin_term terms[RT_MAX_OBJECTS];
	/* Objects 0 to 31 that rays from the origin in the current plane may meet (bit i for
	 * object i; later objects are always tested): origin_terms_plane. */
	uint32_t candidates;
} origin_terms;

/* Fills the terms of the first `count` objects (at most the scene's) for rays from
 * `origin`: every object's for a search object by object, which uses them; the tree's
 * search takes none, and its caller asks only for origin_terms_plane's. */
void origin_terms_init(const scene *s, vec3 origin, int count, origin_terms *k);

/* The rays that follow from k's origin all lie in the plane through it with unit normal
 * n (an image line's eye rays): spheres the plane misses are left out of their searches. */
void origin_terms_plane(const scene *s, dir3 n, origin_terms *k);

/* Can a ray that leaves object `index` on the side a hit came from (front: the outside)
 * meet it again? Not a flat one (plane, polygon, patch): a line crosses its plane once,
 * there, and the surface offset already keeps the search from finding that crossing. Nor
 * a sphere, polyhedron or cone left from outside (each bounds a convex solid: a ray from
 * its surface outwards never comes back). Any hit the search found there would be the hit
 * point's own rounding: float finds such false hits where c = |f|^2 - r^2 cancels on huge
 * spheres (scenes/hard/bigspheres.nff: 18 % of the pixels were off by more than 2 levels,
 * now 0.08 %), fixed point on cones, whose quadratic rounds to Q16.16. Such a ray's
 * searches below leave the object out (`skip`). */
int object_can_rehit(const scene *s, int index, int front);

/* scene_intersect, for a ray from k's origin (k may be NULL) that cannot meet object
 * `skip` (-1 for none): the same hit, with fewer products. */
int scene_intersect_from(const accel *a, const ray *r, const origin_terms *k, int skip,
			 real tmax, hit *h);

/* Fraction of light that passes along r over (0, tmax): 0 at the first opaque blocker,
 * else the product of the kt of the transmitting objects crossed, leaving out object
 * `skip` (as scene_intersect_from). *blocker (if not NULL) gets the opaque blocker's
 * index, or -1. */
real scene_transmittance(const accel *a, const ray *r, real tmax, int skip, int *blocker);

#if INSIDE_LISTS
/* scene_intersect_from without origin terms for a ray that starts inside object `solid`
 * (-1: not known to), through the solid's list where it has one (inside.h). */
int scene_intersect_inside(const accel *a, const ray *r, int solid, int skip, real tmax, hit *h);
#endif

#endif
