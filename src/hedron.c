/* hedron.c - ray/convex polyhedron intersection, the watertight t-interval form.
 * Haines, "Fast Ray-Convex Polyhedron Intersection" (Graphics Gems II): clip the ray's
 * [tnear, tfar] interval against every bounding plane. There is no per-face inside test
 * to disagree at edges and vertices, so nothing leaks (numerics.md section 3).
 * See LICENSE for copyright and licence. */
#include "shape.h"

#include "naive.h"

void hedron_plane_init(halfspace *h, vec3 n, real2 length2, real d)
{
	/* Divided by the length as dir_normalize does (one reciprocal for all four). */
	real_reciprocal per_length = real2_reciprocal_sqrt(length2);
	h->normal = dir_times_reciprocal(n, per_length);
	h->offset = real_times_reciprocal(d, per_length);
}

int hedron_intersect(const scene *s, const object *o, const ray *r, real tmin, real tmax,
		     hit *h)
{
	const halfspace *planes = s->planes + o->u.hedron.first;
	int count = o->u.hedron.count, i;
	real tnear = -REAL_MAX, tfar = tmax;
	int near_face = -1, far_face = -1, face;
	real t;

	if (RT_NAIVE == RT_NAIVE_HEDRON)
		return naive_hedron_intersect(s, o, r, tmin, tmax, h);
	for (i = 0; i < count; i++) {
		unit vd = dir_dot(planes[i].normal, r->dir);
		real vn = -plane_gap(planes[i].normal, planes[i].offset, &r->origin);
		if (vd == UNIT_C(0.0)) {
			/* Parallel: outside this slab misses, inside it the plane does not clip. */
			if (vn > REAL_C(0.0))
				return 0;
			continue;
		}
		t = real_div_unit(-vn, vd);
		/* A face met beyond the horizon is met there, as a plane is (plane.c): an open
		 * polyhedron (a half-space) reaches the horizon too. */
		if (t > HORIZON_T)
			t = HORIZON_T;
		if (vd < UNIT_C(0.0)) {
			/* Front face: the ray enters the half-space here. */
			if (t > tfar)
				return 0;
			if (t > tnear) {
				tnear = t;
				near_face = i;
			}
		} else {
			/* Back face: the ray leaves the half-space here. */
			if (t < tnear)
				return 0;
			if (t < tfar) {
				tfar = t;
				far_face = i;
			}
		}
	}
	/* Entering hit if it lies past tmin, else the exit from inside (numerics.md P10, P11:
	 * a strict tmin keeps a ray that starts on a face from hitting it at t = 0). */
	if (near_face >= 0 && tnear > tmin) {
		t = tnear;
		face = near_face;
	} else if (far_face >= 0 && tfar > tmin && !(tnear > tfar)) {
		t = tfar;
		face = far_face;
	} else {
		return 0;
	}
	if (h) {
		h->t = t;
		/* At the horizon the tracer lights the face's true far point from the
		 * reciprocal of its true t, as a plane's (plane.c). */
		if (!(t < HORIZON_T))
			h->per_t = unit_over_real(dir_dot(planes[face].normal, r->dir),
						  planes[face].offset -
							  dir_dot_vec(planes[face].normal, r->origin));
		h->point = dir_madd(r->origin, t, r->dir);
		h->normal = planes[face].normal;
		h->shading = h->normal;
	}
	return 1;
}

