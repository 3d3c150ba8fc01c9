/* scene.h - the parsed scene: fixed arrays of materials, lights and objects.
 * The loader fills it once; nothing changes it after (the BVH is intersect.h's accel).
 * See LICENSE for copyright and licence. */
#ifndef RT_SCENE_H
#define RT_SCENE_H

#include "config.h"
#include "vec.h"

/* NFF `f` plus the absorption extension. */
typedef struct {
	vec3 color;   /* surface colour, 0..1 */
	real kd;      /* diffuse weight */
	real ks;      /* highlight weight and mirror weight (clamped below 1 for rays) */
	real shine;   /* Phong exponent */
	real kt;      /* weight of the refracted ray; > 0 makes the object two-sided */
	real ior;     /* index of refraction relative to the outside; used only when kt > 0 */
	vec3 absorb;  /* Beer-Lambert coefficient per channel inside the object, per scene unit */
} material;

typedef struct {
	vec3 position;
	vec3 color;
	real clearance; /* no surface is nearer (clearance.c) */
} light;

enum shape_kind {
	SHAPE_SPHERE,
	SHAPE_POLYGON, /* NFF p: planar, may be concave */
	SHAPE_PATCH,   /* NFF pp: planar polygon with per-vertex normals */
	SHAPE_CONE,    /* NFF c: uncapped cone or cylinder */
	SHAPE_HEDRON,  /* extension: convex polyhedron as an intersection of half-spaces */
	SHAPE_PLANE,   /* extension: infinite plane */
	SHAPE_KINDS
};

/* Object flags. */
#define OBJ_TWO_SIDED 1u  /* back faces are hit too (everything but opaque polygons) */
#define OBJ_INSIDE_ONLY 2u /* NFF negative radius: only the inside is visible */

typedef struct {
	vec3 center;
	real radius;
	real2 radius2; /* squared: real2, which fixed point keeps in 64 bits */
	/* What the normal is divided by the radius through (sphere.c): fixed point's
	 * reciprocal, or 1 / radius rounded in the floating types. */
#if REAL_FIXED
	real_reciprocal per_radius;
#else
	real inverse_radius;
#endif
} sphere_shape;

/* Floating-point types decide most rays at a convex polygon by the hit point's distances
 * from its edges' lines in its plane, without the crossings test (polygon.c); fixed point,
 * whose images stay as they were, does not. */
#define POLYGON_EDGES (!REAL_FIXED)

/* A polygon's vertices are scene.vertices[first .. first+count); a patch's normals
 * are scene.normals at the same indices. `normal` and `offset` give its plane n.x = offset;
 * `spread` is how far the farthest vertex lies off that plane (0 when planar, up to
 * rounding); `axis` is the coordinate a patch drops to project it to 2D (the normal's
 * largest). */
typedef struct {
	dir3 normal;
	real offset;
	real spread;
	int first, count;
	int axis;
#if POLYGON_EDGES
	real extent; /* largest coordinate in magnitude; 0: no edge lines (only convex get them) */
#endif
} polygon_shape;

/* Base centre and radius, unit axis towards the apex end, its length and apex radius. */
typedef struct {
	vec3 base;
	dir3 axis;
	real length;
	real base_radius, apex_radius;
	real slope; /* (apex_radius - base_radius) / length */
} cone_shape;

/* Half-spaces scene.planes[first .. first+count): inside where n.x <= d. */
typedef struct {
	int first, count;
} hedron_shape;

typedef struct {
	dir3 normal; /* unit */
	real offset; /* n.x = offset */
} plane_shape;

typedef struct {
	unsigned char kind;  /* enum shape_kind */
	unsigned char flags; /* OBJ_* */
	unsigned short material;
	int line; /* scene file line, for messages */
	union {
		sphere_shape sphere;
		polygon_shape polygon;
		cone_shape cone;
		hedron_shape hedron;
		plane_shape plane;
	} u;
} object;

typedef struct {
	dir3 normal;
	real offset;
} halfspace;

/* A point projected to a polygon's 2D coordinates (see polygon_shape.axis). */
typedef struct {
	real u, v;
} vec2;

typedef struct {
	vec3 from, at, up;
	real angle; /* full horizontal field of view, degrees */
	real hither;
	int width, height;
} view;

/* Floating-point types take a big polygon's hits deep inside its outline without the
 * crossings test (polygon.c); fixed point, whose images stay as they were, does not. */
#define POLYGON_DISCS (RT_POLYGON_RUNS && !REAL_FIXED)

typedef struct {
	const char *file; /* scene file name, for messages */
	int length_shift; /* lengths are stored times 2^length_shift (fixed point's scale) */
	real longest_length; /* the largest length in the file, in magnitude, as stored */
	view camera;
	vec3 background;
	vec3 ambient;
	int depth;   /* ray tree levels, 1..RT_MAX_DEPTH */
	real cutoff; /* smallest path weight still traced */

	int material_count, light_count, object_count, vertex_count, plane_count;
	material materials[RT_MAX_MATERIALS];
	light lights[RT_MAX_LIGHTS];
	object objects[RT_MAX_OBJECTS];
	vec3 vertices[RT_MAX_VERTICES];
	/* Patches only (one unused slot where RT_SHAPE_PATCH leaves them out): */
	dir3 normals[RT_PATCH_VERTICES]; /* each vertex's shading normal */
	halfspace planes[RT_MAX_PLANES];
#if RT_POLYGON_RUNS
	/* The boxes of the polygons' runs of RT_POLYGON_RUN edges (polygon_init): the run
	 * whose first vertex is pool vertex g is in slot g / RT_POLYGON_RUN. A shorter run
	 * that ends a polygon is in tail_lo and tail_hi, in the slot of its last vertex. */
	vec3 run_lo[RT_MAX_VERTICES / RT_POLYGON_RUN + 1], run_hi[RT_MAX_VERTICES / RT_POLYGON_RUN + 1];
	vec3 tail_lo[RT_MAX_VERTICES / RT_POLYGON_RUN + 1], tail_hi[RT_MAX_VERTICES / RT_POLYGON_RUN + 1];
#if POLYGON_DISCS
	/* A polygon of more than RT_POLYGON_RUN vertices has a disc about its centroid that
	 * lies inside its outline (polygon_init): its centre and radius (0: none), and how
	 * far its farthest vertex lies from the centre, in the slot of its first run. */
	vec3 disc_centre[RT_MAX_VERTICES / RT_POLYGON_RUN + 1];
	real disc_radius[RT_MAX_VERTICES / RT_POLYGON_RUN + 1];
	real disc_reach[RT_MAX_VERTICES / RT_POLYGON_RUN + 1];
#endif
#endif
#if POLYGON_EDGES
	/* A convex polygon's edges as lines in its plane (polygon_init): for the edge from
	 * pool vertex g to the next, the unit normal in the plane towards the inside and its
	 * offset, in slot g. */
	halfspace edges[RT_MAX_VERTICES];
#endif
} scene;

/* Clears a scene to NFF's defaults (black background, no ambient, default depth). */
void scene_init(scene *s, const char *file);

/* Plans the memory of the arrays a scene file of `text_bytes` bytes fills (pages.h),
 * before anything is written to them: a long file's in huge pages. */
void scene_plan_pages(scene *s, long text_bytes);

/* Grows *extent to cover every coordinate of p, and r beyond it. */
void scene_cover(real *extent, vec3 p, real r);

/* The scene's extent (largest coordinate of any object, light or the camera, in
 * magnitude) and its smallest feature (the smallest sphere or cone radius, cone length,
 * or a steep cone's length over its slope; REAL_MAX when there is none): what decides
 * whether a number type can hold it. */
void scene_measure(const scene *s, real *extent, real *feature);

#endif
