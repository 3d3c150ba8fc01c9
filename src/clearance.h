/* clearance.h - lower bounds of a point's distance from the scene's surfaces; each
 * shape gives its own (shape_clearance, shape.h).
 * See LICENSE for copyright and licence. */
#ifndef RT_CLEARANCE_H
#define RT_CLEARANCE_H

#include "scene.h"

/* The least shape_clearance over the scene's objects (REAL_MAX with none), and the
 * index of the object it came from in *nearest (-1 with none). */
real scene_clearance(const scene *s, const vec3 *p, int *nearest);

/* How far x lies outside [low, high] (0 inside): the distance bounds of slabs and boxes
 * are made of it. */
real clearance_outside(real x, real low, real high);

#endif
