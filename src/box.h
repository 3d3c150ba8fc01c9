/* box.h - axis-aligned boxes as two corners: the bounds each shape gives the BVH.
 * See LICENSE for copyright and licence. */
#ifndef RT_BOX_H
#define RT_BOX_H

#include "tolerance.h"
#include "vec.h"

/* A box that holds nothing: every point grows it. */
static inline void box_empty(vec3 *lo, vec3 *hi)
{
	*lo = vec_make(REAL_MAX, REAL_MAX, REAL_MAX);
	*hi = vec_neg(*lo);
}

/* Grows the box to hold p. */
static inline void box_grow(vec3 *lo, vec3 *hi, vec3 p)
{
	lo->x = real_min(lo->x, p.x);
	lo->y = real_min(lo->y, p.y);
	lo->z = real_min(lo->z, p.z);
	hi->x = real_max(hi->x, p.x);
	hi->y = real_max(hi->y, p.y);
	hi->z = real_max(hi->z, p.z);
}

/* Grows the box to hold the box [blo, bhi] (blo <= bhi in every axis): the same as
 * growing by both corners, in half the comparisons. */
static inline void box_grow_box(vec3 *lo, vec3 *hi, vec3 blo, vec3 bhi)
{
	lo->x = real_min(lo->x, blo.x);
	lo->y = real_min(lo->y, blo.y);
	lo->z = real_min(lo->z, blo.z);
	hi->x = real_max(hi->x, bhi.x);
	hi->y = real_max(hi->y, bhi.y);
	hi->z = real_max(hi->z, bhi.z);
}

/* How far an object's box [lo, hi] is grown on every side so that rounding never puts a
 * hit the object's own test reports outside it: the secondary-ray offset of the box's
 * size. The hierarchy pads its boxes so (bvh_pieces.c), a warped polygon's far-off hits
 * are held to the same box (polygon.c), and the cone test bounds its near misses by half
 * of it (cone.c). */
static inline real box_rounding_pad(vec3 lo, vec3 hi)
{
	return real_surface_offset(real_max(REAL_C(1.0), real_max(vec_max_abs(lo), vec_max_abs(hi))),
				   1);
}

/* Whether p lies in the box [lo, hi], faces included. */
static inline int box_holds(vec3 lo, vec3 hi, vec3 p)
{
	return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y && p.z >= lo.z &&
	       p.z <= hi.z;
}

/* Half the surface area of the box [lo, hi], 0 for an empty one: the chance that a ray
 * meets it, up to a common factor (the SAH). */
static inline real2 box_half_area(vec3 lo, vec3 hi)
{
	vec3 d = vec_sub(hi, lo);
	if (d.x < 0 || d.y < 0 || d.z < 0)
		return 0;
	return real_mul2(d.x, d.y) + real_mul2(d.y, d.z) + real_mul2(d.z, d.x);
}

#endif
