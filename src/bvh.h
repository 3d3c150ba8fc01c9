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

/* Nearest hit along r over (0, tmax), through the hierarchy (and the unbounded objects),
 * leaving out object `skip` (-1 for none; see object_can_rehit); fills h (normals not yet
 * faced to the ray) and h->object. */
int bvh_nearest(const scene *s, const ray *r, int skip, real tmax, hit *h);

/* Light passing along r over (0, tmax), leaving out `skip`: 0 at an opaque blocker, else
 * the product of the kt of the transmitting objects crossed; *blocker gets the opaque
 * blocker, or -1. */
real bvh_transmittance(const scene *s, const ray *r, int skip, real tmax, int *blocker);
#endif

#endif
