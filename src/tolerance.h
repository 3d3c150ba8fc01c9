/* tolerance.h - how far rt trusts its numbers, in each number type: how far secondary
 * rays leave a surface, how near a surface an eye or a light may stand, where the horizon
 * lies, and how much rounding the sphere test allows for. The range budget below is why;
 * docs/numerics.md has the measurements behind each choice.
 * See LICENSE for copyright and licence. */
#ifndef RT_TOLERANCE_H
#define RT_TOLERANCE_H

#include "real.h"

/* Range budget (floating point): every number in a scene is at most 1e12 in magnitude,
 * so squares and dot products of coordinates (1e24 at most) and the bounding box
 * arithmetic stay finite in every type. Double keeps hit points accurate to ~1e-10
 * relative; float is good to ~1e3 units from the origin (numerics.md section 1).
 * Range budget (Q16.16): the parser scales the scene so that every coordinate is within
 * +-4096 (2^12); squares then reach 2^24 as real2 (Q32.32, up to 2^31), ray lengths
 * across the scene stay below 2^14, and features must stay at least 2^-4 after scaling
 * (their squares keep 8 bits), else the scene is refused. */

#if REAL_FIXED
/* Beyond any scaled scene's coordinates (4096): an infinite plane is seen out to six
 * times the scene's extent. Hit points out there are within range (4096 + 24000), and
 * the vector arithmetic from them saturates (real_add) rather than overflows. */
#define REAL_FAR REAL_C(24000.0)
/* Absolute precision: a hit point is good to a couple of LSB wherever it is, and the
 * offset grows with the ray's scale. Directions, normals and their dot products are
 * Q2.30 (unit, real.h), so a hit point is good to a few LSB plus about 2^-18 of the ray's
 * scale, and secondary rays leave it by 8 LSB + 2^-16 of the scale. The cone's quadratic
 * still rounds to Q16.16: a cone's hit (hit.rough) needs 16 LSB + 2^-13, which is also
 * the bound the BVH pads boxes by (docs/numerics.md, "Secondary-ray offsets", has the
 * measurements that chose these). */
#define real_surface_offset(scale, rough) \
	((rough) ? (real)16 + ((scale) >> 13) : (real)8 + ((scale) >> 16))
/* An eye or a light nearer a surface than 2^REAL_CLEARANCE_BITS steps may round onto it or
 * through it. */
#define REAL_CLEARANCE_BITS 2
#define REAL_CLEARANCE_MIN ((real)1 << REAL_CLEARANCE_BITS)
/* How far b^2 - w can be off through rounding, for b a rounded dot product (half an LSB:
 * b^2 off by |b| in Q32.32) and w a real2 scaled by a near-one factor (real2_scale
 * truncates: off by |w| / 2^16), with room to spare: errors here are absolute. */
#define real2_error_bound(b, w) \
	((real2)fixed_abs(b) + (real2)(((w) < 0 ? 0u - (uint64_t)(w) : (uint64_t)(w)) >> 16) + \
	 (real2)131072)
/* How far w > 0 moves when scaled by the squared length of a unit direction (within
 * 2^-10 of 1, far more than rounding leaves it off): 2^-10 of w, a shift (w / 1024 for
 * w > 0, without a signed division's correction). */
#define real2_unit_slack(w) ((w) >> 10)
#else
/* REAL_OFFSET is the relative size of the offset that moves a secondary ray's origin off
 * the surface (times max(1, |p|inf, t)): a few thousand ulps of the hit point, well above
 * the hit point's rounding error and well below any feature size. */
#if defined(RT_REAL_FLOAT)
#define REAL_OFFSET REAL_C(6.103515625e-05) /* 2^-14 = 512 ulp */
#elif defined(RT_REAL_DOUBLE)
#define REAL_OFFSET REAL_C(9.313225746154785e-10) /* 2^-30 = 2^22 ulp */
#else
#define REAL_OFFSET REAL_C(9.094947017729282e-13) /* 2^-40 = 2^23 ulp */
#endif
#define REAL_FAR REAL_C(1e15) /* a length beyond any scene's coordinates */
#define real_surface_offset(scale, rough) ((void)(rough), real_mul(REAL_OFFSET, (scale)))
/* Floating point places any point off a surface. */
#define REAL_CLEARANCE_BITS 0
#define REAL_CLEARANCE_MIN REAL_C(0.0)
/* How far b^2 - w can be off through rounding: relative errors, bounded generously. */
#define real2_error_bound(b, w) ((real_mul2((b), (b)) + real_fabs(w)) * REAL_OFFSET)
#define real2_unit_slack(w) ((w) * REAL_C(0.0009765625)) /* 2^-10 of w (see the Q16.16 form) */
#endif

#endif
