/* clearance.h - lower bounds of a point's distance from the scene's surfaces.
 * See LICENSE for copyright and licence. */
#ifndef RT_CLEARANCE_H
#define RT_CLEARANCE_H

#include "scene.h"

/* No more than the distance from p to the object's surface (up to rounding). */
real object_clearance(const scene *s, const object *o, const vec3 *p);

/* The least object_clearance over the scene's objects (REAL_MAX with none), and the
 * index of the object it came from in *nearest (-1 with none). */
real scene_clearance(const scene *s, const vec3 *p, int *nearest);

#endif
