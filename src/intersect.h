/* intersect.h - queries against the whole scene: nearest hit and shadow transmittance.
 * See LICENSE for copyright and licence. */
#ifndef RT_INTERSECT_H
#define RT_INTERSECT_H

#include "shape.h"

/* Dispatches to the object's shape; same contract as the shapes (shape.h). */
int object_intersect(const scene *s, int index, const ray *r, real tmin, real tmax, hit *h);

/* Nearest hit along r in (0, tmax). On a hit, h's normals face the ray (h->front says
 * from which side it came). */
int scene_intersect(const scene *s, const ray *r, real tmax, hit *h);

/* Fraction of light that passes along r over (0, tmax): 0 at the first opaque blocker,
 * else the product of the kt of the transmitting objects crossed. *blocker (if not NULL)
 * gets the opaque blocker's index, or -1. */
real scene_transmittance(const scene *s, const ray *r, real tmax, int *blocker);

#endif
