/* quadratic.h - the roots of a t^2 + 2 b t + c = 0, shared by the sphere and the cone.
 * See LICENSE for copyright and licence. */
#ifndef RT_QUADRATIC_H
#define RT_QUADRATIC_H

#include "real.h"

/* Solves a t^2 + 2 b t + c = 0 for its roots t0 <= t1 without cancellation
 * (Press et al.: q = -(b + sign(b) sqrt(b^2 - a c)), t0 = c/q, t1 = q/a), given the
 * discriminant b^2 - a c computed by the caller. Returns the number of roots (0 or 2). */
int solve_quadratic(real a, real b, real2 c, real2 discriminant, real *t0, real *t1);

#endif
