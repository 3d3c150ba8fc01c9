/* quadratic.c - the roots of a quadratic without cancellation, for the sphere and the
 * cone (numerics.md section 1).
 * See LICENSE for copyright and licence. */
#include "quadratic.h"

int solve_quadratic(real a, real b, real2 c, real2 discriminant, real *t0, real *t1)
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
