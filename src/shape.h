/* shape.h - rays, hit records and the one intersection contract every shape follows.
 * Each shape_intersect returns 1 on a hit with tmin < t < tmax, else 0; when `h` is
 * not NULL it fills t, the hit point and the outward geometric and shading normals.
 * A NULL `h` marks a shadow query: one-sided surfaces then block light from both sides.
 * Facing the normals toward the ray happens once, in intersect.c.
 * See LICENSE for copyright and licence. */
#ifndef RT_SHAPE_H
#define RT_SHAPE_H

#include "scene.h"
#include "tolerance.h"

typedef struct {
	vec3 origin;
	dir3 dir; /* unit length */
} ray;

/* Where an infinite plane meets a ray that reaches it beyond REAL_FAR: the horizon
 * (plane.c). A hit this far is shaded but sends no further rays. */
#define HORIZON_T real_mul(REAL_FAR, REAL_C(0.99))

typedef struct {
	real t;
	vec3 point;
	dir3 normal;  /* geometric normal, unit; outward from the shape, then faced to the ray */
	dir3 shading; /* shading normal (interpolated on patches), on the same side as normal */
	int object;   /* index into scene.objects */
	int front;    /* 1 when the ray arrived from the outside of the surface */
	int flat;     /* 1 when shading is the geometric normal (all but patches): set with front */
	int rough;    /* 1 when the hit point is only as good as Q16.16 (cones): rays leave it
		       * by the larger offset (real.h); set with front */
	unit incidence; /* the ray's direction dotted with the faced normal (<= 0): the cosine
			 * a reflection about it needs; set with front */
	unit per_t;     /* at the horizon (t = HORIZON_T, plane.c): 1 / the true t, whose
			 * point is beyond the type's numbers; unset elsewhere */
} hit;

/* On the M0 the larger shape tests stay functions of their own (RT_APART): inlined
 * into the dispatch that the scene's loops inline (intersect.c), their frames added up to
 * one of 204 bytes that every test paid to set up. */

/* ---- set-up: each shape from the numbers the parser read --------------------------- */

/* Sets a sphere's centre and radius (> 0), and the terms made from the radius. */
void sphere_init(sphere_shape *s, vec3 center, real radius);

/* Newell's normal of vertices[0 .. count), as a unit vector; the zero vector when the
 * polygon fills nothing (its vertices all on one line). */
dir3 polygon_normal(const vec3 *vertices, int count);

/* Sets a polygon (patch = 1: a patch, whose vertex normals are s->normals from `first`)
 * of s->vertices[first .. first + count) with its normal from polygon_normal. */
void polygon_init(scene *s, polygon_shape *poly, dir3 normal, int first, int count, int patch);

/* Sets a cone from its base centre, its axis (apex - base, of length `length` > 0) and
 * its two radii (of one sign, not both 0). */
void cone_init(cone_shape *c, vec3 base, vec3 axis, real length, real base_radius,
	       real apex_radius);

/* Sets the half-space n.x <= d, normalised; length2 = |n|^2 > 0. */
void hedron_plane_init(halfspace *h, vec3 n, real2 length2, real d);

/* Sets the plane through `point` with normal `normal` (not zero). */
void plane_init(plane_shape *pl, const vec3 *point, vec3 normal);

/* ---- what each kind is, and the operations that dispatch on it (shape.c) ------------- */

/* The table of what each kind is, by column: each property is the set of the kinds that
 * have it (bit k for kind k), so that asking costs a shift, not a load. */
#define SHAPE_KIND(k) (1u << (k))
/* Lies in one plane: a line meets it once. */
#define SHAPE_FLAT (SHAPE_KIND(SHAPE_POLYGON) | SHAPE_KIND(SHAPE_PATCH) | SHAPE_KIND(SHAPE_PLANE))
/* Bounds a convex solid (a cone: a frustum, its radii of one sign): a ray leaving it
 * outwards never returns. */
#define SHAPE_CONVEX (SHAPE_KIND(SHAPE_SPHERE) | SHAPE_KIND(SHAPE_CONE) | SHAPE_KIND(SHAPE_HEDRON))
/* Encloses a volume: the eye may be inside it. */
#define SHAPE_CLOSED (SHAPE_KIND(SHAPE_SPHERE) | SHAPE_KIND(SHAPE_HEDRON))
/* Hit points only as good as Q16.16's quadratic: rays leave them by the larger offset
 * (tolerance.h). */
#define SHAPE_ROUGH SHAPE_KIND(SHAPE_CONE)
/* Has kind `kind` the property? */
#define shape_is(property, kind) ((property) >> (kind) & 1u)

/* The object's bounding box; 0 when it has none (an infinite plane, an open polyhedron). */
int shape_bounds(const scene *s, const object *o, vec3 *lo, vec3 *hi);

/* No more than the distance from p to the object's surface (up to rounding). */
real shape_clearance(const scene *s, const object *o, const vec3 *p);

/* Grows the scene's extent by the object, and shrinks its smallest feature (scene.h);
 * polygons and polyhedra are measured through the scene's pools. */
void shape_measure(const object *o, real *extent, real *feature);

/* Each shape's own: bounds, clearance and measure, as above. */
int sphere_bounds(const sphere_shape *s, vec3 *lo, vec3 *hi);
real sphere_clearance(const sphere_shape *s, const vec3 *p);
void sphere_measure(const sphere_shape *s, real *extent, real *feature);
int polygon_bounds(const scene *s, const polygon_shape *poly, vec3 *lo, vec3 *hi);
real polygon_clearance(const scene *s, const polygon_shape *g, const vec3 *p);
int cone_bounds(const cone_shape *c, vec3 *lo, vec3 *hi);
/* The size of a cone's coordinates (its ends', and half its larger radius), at least 1:
 * no more than its box's, by whose surface offset the hierarchy pads its boxes; its test
 * reports no hit farther off its side than half that. */
real cone_scale(const cone_shape *c);
/* The bounds of piece `piece` of `pieces` equal lengths of the cone's side (bvh_pieces.c
 * gives a long cone several boxes); one piece is cone_bounds. */
int cone_piece_bounds(const cone_shape *c, int piece, int pieces, vec3 *lo, vec3 *hi);
real cone_clearance(const cone_shape *g, const vec3 *p);
void cone_measure(const cone_shape *c, real *extent, real *feature);
int hedron_bounds(const scene *s, const hedron_shape *g, vec3 *lo, vec3 *hi);
real hedron_clearance(const scene *s, const hedron_shape *g, const vec3 *p);
void plane_measure(const plane_shape *pl, real *extent);

/* ---- intersection ------------------------------------------------------------------ */

int sphere_intersect(const object *o, const ray *r, real tmin, real tmax, hit *h);

/* The terms of a sphere's or a plane's test that depend on the ray's origin alone, which
 * rays sharing an origin (every eye ray) can compute once. */
typedef struct {
	vec3 f; /* sphere: origin - centre */
	union {
		real2 c;       /* sphere: |f|^2 - r^2 */
		real distance; /* plane: offset - n.origin */
	} u;
} origin_term;

/* object_origin_term (intersect.h) fills them. */

/* 1 only when the sphere test's clear-miss tests would reject the ray with unit
 * direction d (as every ray's is, to 2^-10) from the origin whose offset from the centre
 * is f, given c = |f|^2 - r^2 or NULL: the same tests in 32-bit products of f's and d's
 * top bits (fixed point; floating point has no coarse test, and this is always 0). */
int sphere_coarse_miss(const sphere_shape *s, dir3 d, const vec3 *f, const real2 *c);

/* The sphere and plane tests from the origin's terms k (or NULL: they compute their own):
 * the same results either way. */
RT_APART int sphere_intersect_from(const object *o, const ray *r, const origin_term *k,
				     real tmin, real tmax, hit *h);
int plane_intersect_from(const object *o, const ray *r, const origin_term *k, real tmin,
			 real tmax, hit *h);
RT_APART int polygon_intersect(const scene *s, const object *o, const ray *r, real tmin,
				 real tmax, hit *h);
int cone_intersect(const object *o, const ray *r, real tmin, real tmax, hit *h);
RT_APART int hedron_intersect(const scene *s, const object *o, const ray *r, real tmin,
				real tmax, hit *h);
/* offset - n.origin: how far the plane n.x = offset lies ahead of the origin along n,
 * saturating (an origin far beyond the scene, a hit whose point saturated, has a dot
 * product at the edge of fixed point's range). One copy on the M0 (plane.c). */
RT_APART real plane_gap(dir3 normal, real offset, const vec3 *origin);

/* Does the ray's line pass through the polygon with vertices[0 .. count)? The crossings
 * test in the ray's frame (polygon.c): the same answer for an edge or vertex in every
 * polygon that shares it, so exactly one of a tiling's polygons is met. */
int polygon_contains_ray(const vec3 *vertices, int count, const ray *r);
/* Floating types: does the ray, which meets the plane of convex polygon `poly` at t
 * (cosine: its direction's dot product with the normal), pass through it? 1 or 0 where
 * the hit point lies farther than rounding can reach from every edge's line, else -1
 * (the crossings test decides); always -1 in fixed point and for polygons of other
 * shapes or of more than RT_POLYGON_RUN vertices (polygon.c). */
int polygon_edge_verdict(const scene *s, const polygon_shape *poly, const ray *r, real t,
			 unit cosine);
/* The same, with the runs of s's vertex pool from `first` (the polygon's own) passed over
 * where none of their edges can count (RT_POLYGON_RUNS: a 144-gon's test a third as long). */
int polygon_outline_crossed(const vec3 *vertices, int count, const ray *r, const scene *s,
			    int first);

/* The 2D coordinates of p in the projection that drops `axis` (u = axis+1, v = axis+2,
 * mod 3), where a patch's shading normal is blended. */
vec2 polygon_project(vec3 p, int axis);


#endif
