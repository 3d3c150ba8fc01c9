/* polygon.c - ray/polygon (NFF p) and ray/patch (NFF pp) intersection.
 * Plane first, then the crossings test in the plane (Haines, Graphics Gems IV) with the
 * half-open rule and each edge's endpoints in a canonical order, so a point on an edge
 * shared by two polygons belongs to exactly one of them (numerics.md section 3).
 * See LICENSE for copyright and licence. */
#include "shape.h"

vec2 polygon_project(vec3 p, int axis)
{
	vec2 q;
	q.u = axis == 0 ? p.y : axis == 1 ? p.z : p.x;
	q.v = axis == 0 ? p.z : axis == 1 ? p.x : p.y;
	return q;
}

int polygon_contains_2d(const vec2 *uv, int count, real pu, real pv)
{
	int inside = 0, i;
	vec2 a = uv[count - 1];

	for (i = 0; i < count; a = uv[i++]) {
		vec2 lo = a, hi = uv[i];
		/* Half-open in v: the edge counts when its ends lie on different sides of
		 * v = pv, an end exactly on it counting as above. Most edges stop here. */
		if ((lo.v >= pv) == (hi.v >= pv))
			continue;
		/* Canonical order (by v, then u): both neighbours of an edge see the same
		 * endpoints in the same order and so round the same way. */
		if (hi.v < lo.v || (hi.v == lo.v && hi.u < lo.u)) {
			vec2 swap = lo;
			lo = hi;
			hi = swap;
		}
		/* Does the edge cross the +u ray from the point, i.e. is its u-intercept >= pu?
		 * Without a division (hi.v - lo.v > 0 here), that is cross(lo - p, hi - p) >= 0.
		 * Relative to p, each vertex is rounded once, the same way for every edge and
		 * polygon that meets there. The intercept form rounded `pu - lo.u` per edge, and
		 * a hit point within rounding of a vertex shared by several polygons was then
		 * claimed by three of them (G11 through rays: 147 in 400k in float, 21 in
		 * double). */
		{
			real au = lo.u - pu, av = lo.v - pv, bu = hi.u - pu, bv = hi.v - pv;
			if (real_mul2(au, bv) >= real_mul2(av, bu))
				inside = !inside;
		}
	}
	return inside;
}

int polygon_contains(const vec3 *vertices, int count, int axis, real pu, real pv)
{
	vec2 uv[RT_MAX_POLY_VERTS];
	int i;
	if (count < 1 || count > RT_MAX_POLY_VERTS)
		return 0;
	for (i = 0; i < count; i++)
		uv[i] = polygon_project(vertices[i], axis);
	return polygon_contains_2d(uv, count, pu, pv);
}

#if RT_SHAPE_PATCH
/* Twice the signed area of triangle (a, b, c) in the polygon's projection: a product of
 * two lengths, so a real2, exact in fixed point. */
static real2 area_2d(vec2 a, vec2 b, vec2 c)
{
	return real_mul2(b.u - a.u, c.v - a.v) - real_mul2(b.v - a.v, c.u - a.u);
}

/* Shading normal of a patch at p: barycentric interpolation of the vertex normals in
 * the fan triangle (0, i, i+1) that holds p (SPD patches are all triangles). The weights
 * are ratios of areas, which the projection that drops the normal's largest axis scales
 * all alike (by that component, at least 1/sqrt(3)): they are taken there, from the
 * projected vertices the inside test uses, in two products each rather than the six
 * and three scalings of areas along the normal in 3D. */
static dir3 patch_normal(const scene *s, const polygon_shape *poly, vec3 p)
{
	const vec2 *uv = s->projected + poly->first;
	const dir3 *vn = s->normals + poly->first;
	vec2 q = polygon_project(p, poly->axis);
	int i;
	for (i = 1; i + 1 < poly->count; i++) {
		real2 whole = area_2d(uv[0], uv[i], uv[i + 1]);
		real2 a0 = area_2d(q, uv[i], uv[i + 1]);
		real2 a1 = area_2d(uv[0], q, uv[i + 1]);
		real2 a2 = whole - a0 - a1;
		/* The projection may mirror the polygon: the signs that count are those
		 * relative to the whole triangle's. */
		int sense = whole < 0 ? -1 : 1;
		if (whole != 0 && ((a0 * sense >= 0 && a1 * sense >= 0 && a2 * sense >= 0) ||
				   i + 2 == poly->count)) {
			/* Barycentric weights: each area over the whole. */
			vec3 n = vec_scale(dir_to_vec(vn[0]), real2_ratio(a0, whole));
			dir3 unit_n;
			n = dir_madd(n, real2_ratio(a1, whole), vn[i]);
			n = dir_madd(n, real2_ratio(a2, whole), vn[i + 1]);
			unit_n = dir_normalize(n);
			return dir_dot(unit_n, unit_n) > 0 ? unit_n : poly->normal;
		}
	}
	return poly->normal;
}
#endif

int polygon_intersect(const scene *s, const object *o, const ray *r, real tmin, real tmax,
		      hit *h)
{
	const polygon_shape *poly = &o->u.polygon;
	unit denom = dir_dot(poly->normal, r->dir);
	real t;
	vec3 p;

	/* A ray parallel to the plane (or lying in it) misses (numerics.md G07, G08). */
	if (denom == UNIT_C(0.0))
		return 0;
	/* An opaque polygon is one-sided: seen from behind it is not there. A shadow query
	 * (h == NULL) is blocked from either side: light does not pass through its back. */
	if (denom > UNIT_C(0.0) && !(o->flags & OBJ_TWO_SIDED) && h)
		return 0;
	t = real_div_unit(poly->offset - dir_dot_vec(poly->normal, r->origin), denom);
	if (!(t > tmin && t < tmax))
		return 0;
	p = dir_madd(r->origin, t, r->dir);
	{
		/* The point is tested snapped to a grid a little coarser than its rounding
		 * error: a ray meant exactly through a shared edge or vertex then lands exactly
		 * on it, whatever the number type, and the half-open rule settles it the same
		 * way in all of them (without the snap, by which way p happened to round). The
		 * grid's powers of two keep every exactly placed point on it. */
		real grid = real_snap_grid(real_max(real_max(vec_max_abs(p), real_fabs(t)),
						    REAL_C(0.0009765625)),
					   s->snap_limit);
		vec2 q = polygon_project(p, poly->axis);
		if (!polygon_contains_2d(s->projected + poly->first, poly->count,
					 real_snap(q.u, grid), real_snap(q.v, grid)))
			return 0;
	}
	if (h) {
		h->t = t;
		h->point = p;
		h->normal = poly->normal;
#if RT_SHAPE_PATCH
		h->shading = o->kind == SHAPE_PATCH ? patch_normal(s, poly, p) : poly->normal;
#else
		h->shading = poly->normal;
#endif
	}
	return 1;
}
