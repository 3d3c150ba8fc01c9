/* bvh.h - the bounding volume hierarchy that makes large scenes fast.
 * Optional at compile time (RT_USE_BVH=0 leaves it out, as the MCU build does).
 * See LICENSE for copyright and licence. */
#ifndef RT_BVH_H
#define RT_BVH_H

#include "shape.h"

#if RT_USE_BVH
/* Builds the hierarchy into s's static arrays; scenes smaller than RT_BVH_MIN_OBJECTS
 * get none (bvh_node_count = 0) and are searched object by object. */
void bvh_build(scene *s);

/* Called for each object whose bounds the ray enters before *tmax, nearest boxes first.
 * It may lower *tmax (a nearer hit) and returns 1 to stop the traversal. */
typedef int (*bvh_visit_fn)(void *ctx, int index, real *tmax);

/* Visits the candidate objects for r over (0, *tmax); returns 1 if a visit stopped it. */
int bvh_traverse(const scene *s, const ray *r, real *tmax, bvh_visit_fn visit, void *ctx);
#endif

#endif
