/* quadratic.h - the roots of a t^2 + 2 b t + c = 0, shared by the sphere and the cone.
 * Inline on a host (it is in every sphere test that comes near: the call was a tenth of
 * c-ray's scene); on the M0 (flash.h) one ordinary copy in quadratic.c, which link-time
 * optimisation places as before (forced out of line it cost 48 bytes and 16
 * instructions a pixel).
 * See LICENSE for copyright and licence. */
#ifndef RT_QUADRATIC_H
#define RT_QUADRATIC_H

#include "real.h"

/* Solves a t^2 + 2 b t + c = 0 for its roots t0 <= t1 without cancellation
 * (Press et al.: q = -(b + sign(b) sqrt(b^2 - a c)), t0 = c/q, t1 = q/a), given the
 * discriminant b^2 - a c computed by the caller. Returns the number of roots (0 or 2). */
#if RT_FLASH_SHORT
#define QUADRATIC_FUNCTION
int solve_quadratic(real a, real b, real2 c, real2 discriminant, real *t0, real *t1);
#else
#define QUADRATIC_FUNCTION static inline
#endif

#if !RT_FLASH_SHORT || defined(QUADRATIC_BODY)
QUADRATIC_FUNCTION int solve_quadratic(real a, real b, real2 c, real2 discriminant, real *t0, real *t1)
{
	real root, q;
	/* `!(x >= 0)` also rejects NaN (numerics.md N01). */
	if (!(discriminant >= 0))
		return 0;
	root = real2_sqrt(discriminant);
	q = b >= REAL_C(0.0) ? -real_add(b, root) : real_add(root, -b);
	/* q = 0 only when b = 0 and the discriminant is 0: a tangent at the origin (S19). */
	if (q == REAL_C(0.0)) {
		if (a == REAL_C(0.0))
			return 0;
		*t0 = *t1 = REAL_C(0.0);
		return 2;
	}
	*t0 = real2_div(c, q);
	/* a = 0 is the linear case (a ray parallel to a cylinder's axis): one root only;
	 * a = 1 (a unit direction, often exactly) needs no division. */
	*t1 = a == REAL_C(0.0) ? *t0 : a == REAL_C(1.0) ? q : real_div(q, a);
	if (*t1 < *t0) {
		real swap = *t0;
		*t0 = *t1;
		*t1 = swap;
	}
	return 2;
}
#endif

#endif
