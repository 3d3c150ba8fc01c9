/* polygon.c - ray/polygon (NFF p) and ray/patch (NFF pp) intersection: the polygon's
 * plane, bounds and set-up, the distance along the ray and the patch's shading normal;
 * whether the ray passes through the outline is outline.c's (numerics.md section 3).
 * See LICENSE for copyright and licence. */
#include "shape.h"

#include "box.h"
#include "clearance.h"
#include "pages.h"

vec2 polygon_project(vec3 p, int axis)
{
	vec2 q;
	q.u = axis == 0 ? p.y : axis == 1 ? p.z : p.x;
	q.v = axis == 0 ? p.z : axis == 1 ? p.x : p.y;
	return q;
}

/* Twice the signed area of triangle (a, b, c) in the polygon's projection: a product of
 * two lengths, so a real2, exact in fixed point. */
static real2 area_2d(vec2 a, vec2 b, vec2 c)
{
	return real_mul2(b.u - a.u, c.v - a.v) - real_mul2(b.v - a.v, c.u - a.u);
}

/* Shading normal of a patch at p: barycentric interpolation of the vertex normals in
 * the fan triangle (0, i, i+1) that holds p (SPD patches are all triangles). The weights
 * are ratios of areas, which the projection that drops the normal's largest axis scales
 * all alike (by that component, at least 1/sqrt(3)): they are taken there, in two
 * products each rather than the six and three scalings of areas along the normal in 3D.
 * Projecting is choosing two coordinates: done here, for the hit's triangle, it needs
 * no stored copy of the vertices. */
static dir3 patch_normal(const scene *s, const polygon_shape *poly, vec3 p)
{
	const vec3 *v = s->vertices + poly->first;
	const dir3 *vn = s->normals + poly->first;
	vec2 q = polygon_project(p, poly->axis), first = polygon_project(v[0], poly->axis);
	vec2 next = polygon_project(v[1], poly->axis);
	int i;
	for (i = 1; i + 1 < poly->count; i++) {
		/* The fan triangle (0, i, i + 1), projected as the point is. */
		vec2 here = next;
		real2 whole, a0, a1, a2;
		int sense;
		next = polygon_project(v[i + 1], poly->axis);
		whole = area_2d(first, here, next);
		a0 = area_2d(q, here, next);
		a1 = area_2d(first, q, next);
		a2 = whole - a0 - a1;
		/* The projection may mirror the polygon: the signs that count are those
		 * relative to the whole triangle's. */
		sense = whole < 0 ? -1 : 1;
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

/* ---- set-up from the parsed vertices ----------------------------------------- */

/* Newell's normal of vertices[0..count), as a unit vector; the zero vector when the
 * polygon fills nothing (its vertices on one line). Its components are areas (products of lengths), summed as real2
 * and brought back to size by the largest before normalising. Axis by axis in a loop,
 * component k from the two axes after it: one copy of the arithmetic, not three. */
static void newell_sums(const vec3 *v, int count, real2 n[3])
{
	int i, k;
	n[0] = n[1] = n[2] = 0;
	for (i = 0; i < count; i++) {
		/* The vertices by pointer: copies of them cost 20 bytes of M0 flash. */
		const vec3 *a = &v[i], *b = &v[i + 1 == count ? 0 : i + 1];
		for (k = 0; k < 3; k++) {
			int j = k == 2 ? 0 : k + 1, m = k == 0 ? 2 : k - 1;
			/* Saturating: the measuring pass reads coordinates up to fixed point's
			 * limit. */
			n[k] += real_mul2(real_add(vec_get(*a, j), -vec_get(*b, j)),
					  real_add(vec_get(*a, m), vec_get(*b, m)));
		}
	}
}

dir3 polygon_normal(const vec3 *v, int count)
{
	real2 n[3], largest = 0;
	real part[3];
	int i, k;
	newell_sums(v, count, n);
	/* A signed area of zero need not mean nothing is filled: the even-odd rule fills
	 * both lobes of a symmetric bow-tie, whose signed areas cancel. Its plane is then
	 * that of the first three consecutive vertices not on one line; only a polygon
	 * whose vertices all are fills nothing. */
	for (i = 0; n[0] == 0 && n[1] == 0 && n[2] == 0 && i + 3 <= count && count > 3; i++)
		newell_sums(v + i, 3, n);
	for (k = 0; k < 3; k++)
		largest = real_max(largest, n[k] < 0 ? -n[k] : n[k]);
	if (!(largest > 0))
		return dir_make(UNIT_C(0.0), UNIT_C(0.0), UNIT_C(0.0));
	for (k = 0; k < 3; k++)
		part[k] = real2_ratio(n[k], largest);
	return dir_normalize(vec_make(part[0], part[1], part[2]));
}

/* The mean of vertices[0..count), summed as real2 so that many large coordinates cannot
 * overflow fixed point. Axis by axis, one sum at a time (each still in vertex order, so
 * the same sums in every type): 32 bytes less M0 flash than three sums side by side. */
static vec3 centroid_of(const vec3 *v, int count)
{
	real n = real_from_int(count), mean[3];
	int i, k;
	for (k = 0; k < 3; k++) {
		real2 sum = 0;
		for (i = 0; i < count; i++)
			sum += real2_from(vec_get(v[i], k));
		mean[k] = real2_div(sum, n);
	}
	return vec_make(mean[0], mean[1], mean[2]);
}

#if POLYGON_DISCS || POLYGON_EDGES
/* Certain answers away from the outline. The crossings test's answer is the exact one for
 * the vertices as the ray's frame sees them (each edge's side decided exactly), and those
 * differ from the exact projections by a few roundings of the coordinates' size S; so
 * wherever the ray passes farther than some multiple of that from every projected edge,
 * the test's answer is the exact geometry's: inside, or outside of a convex outline. A
 * vector w in the polygon's plane is seen in the frame at least |w| |cos| / (2 sqrt 3)
 * long (cos: of the angle between the ray and the normal; the frame scales by the
 * direction's largest component, at least 1 / sqrt 3), so a point D from every edge in
 * the plane is D |cos| / 4 from every projected edge. OUTLINE_ROUNDING S / |cos| in the
 * plane covers the frame's roundings many times over, and the rounding of the hit point,
 * of the plane's distance and of the distance's own computation, all a few roundings of
 * S; a polygon whose vertices lie off its plane by `spread` has its outline seen up to
 * 2 spread / |cos| away from where the plane's outline is. */
#define OUTLINE_ROUNDING (REAL_C(1024.0) * REAL_EPSILON)

/* How far from every edge a ray down the normal must meet the plane for the crossings
 * test's answer to be certain, for coordinates of size `size` (over |cos| for other rays). */
static real outline_margin(const polygon_shape *poly, real size)
{
	return poly->spread + poly->spread + OUTLINE_ROUNDING * size;
}
#endif

#if POLYGON_DISCS
/* A big polygon's disc: the hits of a ray that meets its plane well inside the disc about
 * the centroid that lies inside the outline are taken without the crossings test (a
 * 144-gon's test passes over nine runs and tests about 23 edges; at SPD gears' gear faces
 * more than half the tests the crossings test makes on big polygons are of such hits).
 * Rays more grazing than REACH_COS take the crossings test. */

/* Distance from p to the segment [a, b]. */
static real segment_distance(vec3 p, vec3 a, vec3 b)
{
	vec3 ab = vec_sub(b, a), ap = vec_sub(p, a);
	real2 length2 = vec_dot2(ab, ab), along = vec_dot2(ap, ab);
	real f = length2 > 0 ? real_max(REAL_C(0.0), real_min(REAL_C(1.0), along / length2)) : 0;
	return vec_length(vec_sub(ap, vec_scale(ab, f)));
}

/* The disc of a polygon of more than RT_POLYGON_RUN vertices: about its centroid, of the
 * centroid's distance from the nearest edge, less the spread (an edge's points lie within
 * it of the plane), when the centroid is inside the outline; else none. Inside: by a
 * crossings test down the normal from the polygon's own distance (from a unit away, a
 * polygon 1e-4 across was rounded as a unit is, and a centroid just outside it seen
 * inside), which a centroid farther than deep_inside's margin for that ray from every
 * edge answers exactly; a disc no wider than that margin is none. */
static void disc_init(scene *s, const polygon_shape *poly, vec3 centroid)
{
	const vec3 *v = s->vertices + poly->first;
	int slot = (poly->first + 1) / RT_POLYGON_RUN, i;
	real radius = REAL_MAX, reach = REAL_C(0.0), size;
	ray along;
	for (i = 0; i < poly->count; i++) {
		radius = real_min(radius, segment_distance(centroid, v[i], v[(i + 1) % poly->count]));
		reach = real_max(reach, vec_length(vec_sub(v[i], centroid)));
	}
	along.origin = dir_madd(centroid, reach, poly->normal);
	along.dir = dir_neg(poly->normal);
	size = real_max(vec_max_abs(along.origin), vec_max_abs(centroid) + reach);
	radius = (radius - poly->spread) * (REAL_C(1.0) - REAL_C(1.0) / 1024);
	s->disc_centre[slot] = centroid;
	s->disc_reach[slot] = reach;
	s->disc_radius[slot] = radius > outline_margin(poly, size) &&
					       polygon_contains_ray(v, poly->count, &along)
				       ? radius
				       : REAL_C(0.0);
}

#endif

#if POLYGON_EDGES
/* A convex polygon's edge lines (polygon_edge_verdict): each edge's unit normal in the
 * plane (the plane's normal times the edge, towards the inside for vertices that turn
 * about the normal as Newell's normal does), through the edge's first vertex. The line of
 * an edge whose ends lie off the plane is that of their projections onto it: the normal
 * is square to both the plane's normal and the edge. Only when every other vertex lies
 * strictly inside every edge's line: then the polygon goes once round a convex outline
 * (a vertex repeated, or a second time round, would lie on a line; a turn the other way,
 * a crossing or a dent, outside one), every point it holds is inside every line (up to
 * the rounding of these checks), and a point inside all of them is inside it. Others
 * get none (extent 0): the crossings test answers for them, as for polygons of more
 * than RT_POLYGON_RUN vertices (whose runs and disc do more for them). */
static void edges_init(scene *s, polygon_shape *poly)
{
	const vec3 *v = s->vertices + poly->first;
	halfspace *e = s->edges + poly->first;
	int count = poly->count, i, j;
	real extent = REAL_C(0.0);
	poly->extent = REAL_C(0.0);
	if (count < 3 || count > RT_POLYGON_RUN)
		return;
	/* In bulk, as the vertices are (parse_shape.c): not a fault for each page. */
	pages_ahead(s->edges, sizeof s->edges[0], (size_t)poly->first, (size_t)count,
		    RT_MAX_VERTICES);
	for (i = 0; i < count; i++) {
		vec3 edge = vec_sub(v[i + 1 == count ? 0 : i + 1], v[i]);
		e[i].normal = dir_normalize(vec_cross(dir_to_vec(poly->normal), edge));
		e[i].offset = dir_dot_vec(e[i].normal, v[i]);
		extent = real_max(extent, vec_max_abs(v[i]));
	}
	for (i = 0; i < count; i++)
		for (j = 0; j < count; j++)
			if (j != i && j != (i + 1 == count ? 0 : i + 1) &&
			    !(dir_dot_vec(e[i].normal, v[j]) - e[i].offset > REAL_C(0.0)))
				return;
	poly->extent = extent;
}
#endif

void polygon_init(scene *s, polygon_shape *poly, dir3 normal, int first, int count, int patch)
{
	vec3 centroid;
	int i;
	poly->normal = normal;
	/* The plane passes through the centroid: the best fit for slightly non-planar input. */
	centroid = centroid_of(s->vertices + first, count);
	poly->offset = dir_dot_vec(poly->normal, centroid);
	poly->first = first;
	poly->count = count;
	poly->spread = REAL_C(0.0);
	for (i = 0; i < count && (RT_USE_BVH || RT_HOST_CHECKS || POLYGON_EDGES); i++) {
		real gap = real_fabs(plane_gap(normal, poly->offset, &s->vertices[first + i]));
		poly->spread = real_max(poly->spread, gap);
	}
#if RT_POLYGON_RUNS
	{
		/* The boxes of the polygon's runs, from vertex 1 in steps of RUN, each with
		 * the vertex before it (the start of its first edge). A run's slot is its
		 * first vertex's pool index over RUN: runs RUN apart, and those of the next
		 * polygon start past this one's end, so no two share a slot. */
		int k;
		for (k = 1; k + RT_POLYGON_RUN <= count; k += RT_POLYGON_RUN) {
			int slot = (first + k) / RT_POLYGON_RUN;
			box_empty(&s->run_lo[slot], &s->run_hi[slot]);
			for (i = first + k - 1; i < first + k + RT_POLYGON_RUN; i++)
				box_grow(&s->run_lo[slot], &s->run_hi[slot], s->vertices[i]);
		}
		/* The shorter run after them (k < count), in a polygon of more than RUN
		 * vertices: a 144-gon's last 15 edges. Its slot is its last vertex's pool
		 * index over RUN: such polygons' last vertices lie more than RUN apart. */
		if (count > RT_POLYGON_RUN && k < count) {
			int slot = (first + count - 1) / RT_POLYGON_RUN;
			box_empty(&s->tail_lo[slot], &s->tail_hi[slot]);
			for (i = first + k - 1; i < first + count; i++)
				box_grow(&s->tail_lo[slot], &s->tail_hi[slot], s->vertices[i]);
		}
	}
#endif
#if POLYGON_DISCS
	if (count > RT_POLYGON_RUN)
		disc_init(s, poly, centroid);
#endif
#if POLYGON_EDGES
	edges_init(s, poly);
#endif
	if (!RT_SHAPE_PATCH)
		return;
	poly->axis = unit_fabs(poly->normal.x) > unit_fabs(poly->normal.y)
			     ? (unit_fabs(poly->normal.x) > unit_fabs(poly->normal.z) ? 0 : 2)
			     : (unit_fabs(poly->normal.y) > unit_fabs(poly->normal.z) ? 1 : 2);
	if (patch) {
		/* A zero vertex normal falls back to the face normal. */
		for (i = 0; i < count; i++) {
			dir3 *n = &s->normals[first + i];
			*n = dir_dot(*n, *n) > 0 ? *n : poly->normal;
		}
	}
}

/* ---- bounds and clearance --------------------------------------------------------- */

/* Where a polygon's hits lie. A ray that passes through a polygon's outline crosses the
 * fan from its centroid to its edges, inside its vertices' box and no farther than
 * `spread` from its plane, and meets the plane within spread / |cos| of there along the
 * ray (cos: of the angle between the ray and the normal). So for |cos| >= 1 / REACH the
 * hit lies within REACH * spread of the vertices' box (the polygon's bounds), plus
 * rounding, which the hierarchy pads every box by; a more grazing ray's hit is checked
 * against that box with the same padding (polygon_intersect), so that no hit ever lies
 * outside the box the hierarchy is given. */
#define REACH 4
#define REACH_COS UNIT_C(0.25) /* 1 / REACH */

int polygon_bounds(const scene *s, const polygon_shape *poly, vec3 *lo, vec3 *hi)
{
	real reach;
	int i;
	box_empty(lo, hi);
	for (i = 0; i < poly->count; i++)
		box_grow(lo, hi, s->vertices[poly->first + i]);
	/* Held within REAL_FAR (fixed point's range): a polygon that spreads that far
	 * reaches across the whole scene anyway. */
	reach = real_min(poly->spread, real_div(REAL_FAR, REAL_C(4.0))) * REACH;
	*lo = vec_sub(*lo, vec_make(reach, reach, reach));
	*hi = vec_add(*hi, vec_make(reach, reach, reach));
	return 1;
}

/* Whether p lies in the polygon's bounds, padded for rounding as the hierarchy pads them. */
static int reaches(const scene *s, const polygon_shape *poly, vec3 p)
{
	vec3 lo, hi, pad;
	real grow;
	polygon_bounds(s, poly, &lo, &hi);
	grow = box_rounding_pad(lo, hi);
	pad = vec_make(grow, grow, grow);
	return box_holds(vec_sub(lo, pad), vec_add(hi, pad), p);
}

/* How far x lies outside the vertices' range along one axis. */
static real axis_gap(const vec3 *v, int count, int axis, real x)
{
	real low = vec_get(v[0], axis), high = low;
	int i;
	for (i = 1; i < count; i++) {
		real c = vec_get(v[i], axis);
		low = real_min(low, c);
		high = real_max(high, c);
	}
	return clearance_outside(x, low, high);
}

/* A polygon lies in its plane and in the box of its vertices. */
real polygon_clearance(const scene *s, const polygon_shape *g, const vec3 *p)
{
	const vec3 *v = s->vertices + g->first;
	real most = real_fabs(plane_gap(g->normal, g->offset, p));
	int axis;
	for (axis = 0; axis < 3; axis++) {
		real gap = axis_gap(v, g->count, axis, vec_get(*p, axis));
		most = real_max(most, gap);
	}
	return most;
}

#if POLYGON_DISCS
/* Does the ray, which meets the plane of polygon `poly` at t, with `cosine` the cosine
 * of its angle to the normal, meet it well inside its disc (a big polygon's)? */
static int deep_inside(const scene *s, const polygon_shape *poly, const ray *r, real t,
		       unit cosine)
{
	int slot = (poly->first + 1) / RT_POLYGON_RUN;
	real radius, size;
	vec3 off;
	if (poly->count <= RT_POLYGON_RUN)
		return 0;
	radius = s->disc_radius[slot];
	if (!(radius > 0) || !(unit_fabs(cosine) >= REACH_COS))
		return 0;
	size = real_max(vec_max_abs(r->origin),
			vec_max_abs(s->disc_centre[slot]) + s->disc_reach[slot]);
	radius -= outline_margin(poly, size) / unit_to_real(unit_fabs(cosine));
	off = vec_sub(dir_madd(r->origin, t, r->dir), s->disc_centre[slot]);
	return radius > 0 && vec_dot2(off, off) < real_mul2(radius, radius);
}
#else
/* Fixed point (and the MCU) keeps the crossings test for every hit. */
#define deep_inside(s, poly, r, t, cosine) 0
#endif

#if POLYGON_EDGES
/* polygon_edge_verdict, inlined into the polygon test. The distances in the plane times
 * |cos| against the margin (over |cos|) times it: no division. A triangle's three lines
 * straight through, its most common case (SPD teapot, tetra, mount). */
RT_INLINE int edge_verdict(const scene *s, const polygon_shape *poly, const ray *r, real t,
			   unit cosine)
{
	const halfspace *e = s->edges + poly->first;
	real slant, margin;
	vec3 p;
	int i, inside = 1;
	if (!(poly->extent > REAL_C(0.0)))
		return -1;
	slant = unit_to_real(unit_fabs(cosine));
	margin = outline_margin(poly, real_max(vec_max_abs(r->origin), poly->extent));
	p = dir_madd(r->origin, t, r->dir);
	if (poly->count == 3) {
		real d0 = real_mul(dir_dot_vec(e[0].normal, p) - e[0].offset, slant);
		real d1 = real_mul(dir_dot_vec(e[1].normal, p) - e[1].offset, slant);
		real d2 = real_mul(dir_dot_vec(e[2].normal, p) - e[2].offset, slant);
		if (d0 < -margin || d1 < -margin || d2 < -margin)
			return 0;
		return d0 > margin && d1 > margin && d2 > margin ? 1 : -1;
	}
	for (i = 0; i < poly->count; i++) {
		real d = real_mul(dir_dot_vec(e[i].normal, p) - e[i].offset, slant);
		if (d < -margin)
			return 0;
		inside &= d > margin;
	}
	return inside ? 1 : -1;
}
#else
RT_INLINE int edge_verdict(const scene *s, const polygon_shape *poly, const ray *r, real t,
			   unit cosine)
{
	(void)s;
	(void)poly;
	(void)r;
	(void)t;
	(void)cosine;
	return -1;
}
#endif

int polygon_edge_verdict(const scene *s, const polygon_shape *poly, const ray *r, real t,
			 unit cosine)
{
	return edge_verdict(s, poly, r, t, cosine);
}

/* ---- intersection --------------------------------------------------------------- */

int polygon_intersect(const scene *s, const object *o, const ray *r, real tmin, real tmax,
		      hit *h)
{
	const polygon_shape *poly = &o->u.polygon;
	unit denom = dir_dot(poly->normal, r->dir);
	real t;
	int verdict;

	/* A ray parallel to the plane (or lying in it) misses (numerics.md G07, G08). */
	if (denom == UNIT_C(0.0))
		return 0;
	/* An opaque polygon is one-sided: seen from behind it is not there. A shadow query
	 * (h == NULL) is blocked from either side: light does not pass through its back. */
	if (denom > UNIT_C(0.0) && !(o->flags & OBJ_TWO_SIDED) && h)
		return 0;
	t = real_div_unit(plane_gap(poly->normal, poly->offset, &r->origin), denom);
	if (!(t > tmin && t < tmax))
		return 0;
	verdict = edge_verdict(s, poly, r, t, denom);
	if (verdict == 0 ||
	    (verdict < 0 && !deep_inside(s, poly, r, t, denom) &&
	     !polygon_outline_crossed(s->vertices + poly->first, poly->count, r, s, poly->first)))
		return 0;
	/* A grazing ray may meet the plane far off a non-planar polygon (see polygon_bounds):
	 * a hit beyond the box is none. The MCU build, which has no hierarchy, leaves this
	 * out for flash (docs/mcu.md). */
	if (RT_HOST_CHECKS && unit_fabs(denom) < REACH_COS &&
	    !reaches(s, poly, dir_madd(r->origin, t, r->dir)))
		return 0;
	if (h) {
		vec3 p = dir_madd(r->origin, t, r->dir);
		h->t = t;
		h->point = p;
		h->normal = poly->normal;
		h->shading = RT_SHAPE_PATCH && o->kind == SHAPE_PATCH ? patch_normal(s, poly, p)
								      : poly->normal;
	}
	return 1;
}
