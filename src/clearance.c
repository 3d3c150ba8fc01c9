/* clearance.c - how far a point is from the nearest surface of the scene, from below.
 * Lights need it for their shadow segments (trace.c): a light nearer a surface than a
 * ray's offset gets segments that end exactly at it. Fixed point needs it to refuse an eye
 * or a light that its numbers cannot place off a surface (load.c).
 * Each bound is a distance the surface cannot be nearer than (to rounding): a plane's, a
 * box's, a slab's; never more than the true distance, often much less far away, where
 * it does not matter.
 * See LICENSE for copyright and licence. */
#include "clearance.h"

#include "shape.h"

/* How far x lies outside [low, high] (0 inside). Plain differences: every coordinate is
 * within the scene's extent, which the type holds twice over (load.c). */
real clearance_outside(real x, real low, real high)
{
	return real_max(REAL_C(0.0), real_max(low - x, x - high));
}

real scene_clearance(const scene *s, const vec3 *p, int *nearest)
{
	real least = REAL_MAX;
	int i;
	*nearest = -1;
	for (i = 0; i < s->object_count; i++) {
		real c = shape_clearance(s, &s->objects[i], p);
		if (c < least) {
			least = c;
			*nearest = i;
		}
	}
	return least;
}
