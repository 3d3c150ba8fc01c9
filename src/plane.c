/* plane.c - ray/infinite plane intersection (an rt extension to NFF).
 * See LICENSE for copyright and licence. */
#include "shape.h"

int plane_intersect(const object *o, const ray *r, real tmin, real tmax, hit *h)
{
	const plane_shape *pl = &o->u.plane;
	real denom = vec_dot(pl->normal, r->dir);
	real t;
	if (denom == REAL_C(0.0))
		return 0;
	t = real_div(pl->offset - vec_dot(pl->normal, r->origin), denom);
	if (!(t > tmin && t < tmax))
		return 0;
	if (h) {
		h->t = t;
		h->point = vec_madd(r->origin, t, r->dir);
		h->normal = pl->normal;
		h->shading = pl->normal;
	}
	return 1;
}
