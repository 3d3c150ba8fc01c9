/* hedron.c - ray/convex polyhedron intersection, the watertight t-interval form.
 * Haines, "Fast Ray-Convex Polyhedron Intersection" (Graphics Gems II): clip the ray's
 * [tnear, tfar] interval against every bounding plane. There is no per-face inside test
 * to disagree at edges and vertices, so nothing leaks (numerics.md section 3).
 * See LICENSE for copyright and licence. */
#include "shape.h"

#include "box.h"
#include "naive.h"

void hedron_plane_init(halfspace *h, vec3 n, real2 length2, real d)
{
	/* Divided by the length as dir_normalize does (one reciprocal for all four). */
	real_reciprocal per_length = real2_reciprocal_sqrt(length2);
	h->normal = dir_times_reciprocal(n, per_length);
	h->offset = real_times_reciprocal(d, per_length);
}

/* ---- bounds and clearance --------------------------------------------------------- */

/* Below this |n_i . (n_j x n_k)| three unit normals are coplanar as far as the arithmetic
 * can tell, and their corner is not determined: normals coplanar as written (a prism's
 * sides, turned any way) give at most 1.5 epsilons (20,000 random prisms of 3-12 sides,
 * written to 17 digits). Above it a corner is determined, however obliquely its planes
 * meet, and corner_error bounds how far it may be off: it is kept, so that the box holds
 * it. A fixed threshold (it was 1e-9) lost the ridge of a roof flatter than that in double
 * and long double; 64 epsilons lost every corner but the apex of a pyramid 18 wide and
 * 1e-6 high (tests/good/40). Fixed point's Q16.16 determinant is exact enough to take
 * every nonzero one. */
#define CORNER_DET_MIN (REAL_FIXED ? REAL_C(0.0) : 8 * REAL_EPSILON)

/* How far rounding may have moved a corner p = numerator / det computed from offsets of
 * total size `offsets`: a few roundings of each term, magnified by 1 / |det|, which is
 * large for a corner where the planes meet at a shallow angle. Floating point only: the
 * fixed-point corners are as they were, and its box padding covers them. */
static real corner_error(real offsets, vec3 p, real det)
{
	if (REAL_FIXED)
		return REAL_C(0.0);
	return 8 * REAL_EPSILON * (offsets + 2 * vec_max_abs(p)) / real_fabs(det);
}

/* Corners of a convex polyhedron: every point where three planes meet and that lies
 * inside all the others (within the corner's rounding). The planes are first closed by a
 * huge box; a corner on that box means the polyhedron is unbounded (returns 0). The box
 * holds each corner together with its rounding. */
int hedron_bounds(const scene *s, const hedron_shape *g, vec3 *lo, vec3 *hi)
{
	halfspace planes[RT_MAX_HEDRON_PLANES + 6];
	vec3 normal[RT_MAX_HEDRON_PLANES + 6]; /* as reals: Cramer's rule multiplies three */
	int count = g->count, i, j, k, m, corners = 0;
	/* Beyond every coordinate, and a third of REAL_FAR so that three such terms in
	 * Cramer's rule below still fit fixed point. */
	const real far_away = real_div(REAL_FAR, REAL_C(3.0));
	for (i = 0; i < count; i++)
		planes[i] = s->planes[g->first + i];
	for (i = 0; i < 6; i++) {
		unit sign = i & 1 ? UNIT_C(-1.0) : UNIT_C(1.0);
		planes[count + i].normal = dir_make(i / 2 == 0 ? sign : UNIT_C(0.0),
						    i / 2 == 1 ? sign : UNIT_C(0.0),
						    i / 2 == 2 ? sign : UNIT_C(0.0));
		planes[count + i].offset = far_away;
	}
	for (i = 0; i < count + 6; i++)
		normal[i] = dir_to_vec(planes[i].normal);
	box_empty(lo, hi);
	for (i = 0; i < count + 6; i++)
		for (j = i + 1; j < count + 6; j++)
			for (k = j + 1; k < count + 6; k++) {
				/* Cramer's rule: p = (d_i (n_j x n_k) + d_j (n_k x n_i) +
				 * d_k (n_i x n_j)) / (n_i . (n_j x n_k)). */
				vec3 jk = vec_cross(normal[j], normal[k]);
				real det = vec_dot(normal[i], jk);
				vec3 p, error;
				real rounding;
				if (!(real_fabs(det) > CORNER_DET_MIN))
					continue;
				p = vec_scale(jk, planes[i].offset);
				p = vec_madd(p, planes[j].offset, vec_cross(normal[k], normal[i]));
				p = vec_madd(p, planes[k].offset, vec_cross(normal[i], normal[j]));
				p = vec_scale(p, real_div(REAL_C(1.0), det));
				rounding = corner_error(real_fabs(planes[i].offset) +
								real_fabs(planes[j].offset) +
								real_fabs(planes[k].offset),
							p, det);
				for (m = 0; m < count + 6; m++) {
					real slack = real_surface_offset(real_max(REAL_C(1.0), vec_max_abs(p)), 1) +
						     2 * rounding;
					if (vec_dot(normal[m], p) > planes[m].offset + slack)
						break;
				}
				if (m < count + 6)
					continue;
				if (k >= count)
					return 0; /* a corner on the closing box: unbounded */
				error = vec_make(rounding, rounding, rounding);
				box_grow(lo, hi, vec_sub(p, error));
				box_grow(lo, hi, vec_add(p, error));
				corners++;
			}
	return corners > 0;
}

/* A convex polyhedron's surface is no nearer than its nearest plane from inside, and
 * than its farthest plane from outside: either way |max(n.p - d)|. */
real hedron_clearance(const scene *s, const hedron_shape *g, const vec3 *p)
{
	const halfspace *planes = s->planes + g->first;
	real most = -REAL_MAX;
	int i;
	for (i = 0; i < g->count; i++) {
		real side = -plane_gap(planes[i].normal, planes[i].offset, p);
		most = real_max(most, side);
	}
	return real_fabs(most);
}

/* ---- intersection ------------------------------------------------------------------ */

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
	/* Entering hit if it lies strictly between tmin and tmax, else the exit from inside
	 * (numerics.md P10, P11: a strict tmin keeps a ray that starts on a face from hitting
	 * it at t = 0). A strict tmax, as every other shape has, leaves a hit at the very
	 * distance of the nearest so far to the object found first, as the hierarchy's tie
	 * rule needs; the MCU build, which has no hierarchy, leaves the test out for flash
	 * (docs/mcu.md). */
	if (near_face >= 0 && tnear > tmin && (!RT_HOST_CHECKS || tnear < tmax)) {
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

