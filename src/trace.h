/* trace.h - the recursive Whitted tracer: one ray in, one linear colour out.
 * See LICENSE for copyright and licence. */
#ifndef RT_TRACE_H
#define RT_TRACE_H

#include "eye_cover.h"
#include "intersect.h"

typedef struct {
	unsigned long eye_rays, eye_hits;
	unsigned long shadow_rays, reflect_rays, refract_rays;
} trace_stats;

/* The media a ray travels in: materials of the transmitting objects it is inside,
 * innermost last (RTG ch. 11's stack, simplified for objects that do not overlap). */
typedef struct {
	int count;
	int material[RT_MAX_MEDIA];
} media;

typedef struct {
	const accel *accel; /* the scene and its hierarchy (accel_scene gives the scene) */
	int depth;   /* ray tree levels, eye ray = 1 */
	real cutoff; /* smallest path weight still traced */
	trace_stats stats;
	media eye_media; /* what the eye is inside of */
	/* The opaque object that last blocked each light at each ray level, tried first:
	 * neighbouring shadow rays usually share their blocker. -1 when none. */
	int last_blocker[RT_MAX_DEPTH][RT_MAX_LIGHTS];
	origin_terms eye; /* the objects' terms for rays from the camera */
	vec3 ambient[RT_MAX_MATERIALS]; /* each material's ambient light, made once */
#if !REAL_FIXED
	/* Each material's least cosine whose highlight is not 0 (optics_highlight_floor). */
	real highlight_floor[RT_MAX_MATERIALS];
#endif
#if EYE_COVER
	eye_cover cover; /* the eye rays that meet nothing, known without a search */
#endif
#if INSIDE_LISTS
	int inside; /* the solid the next ray traced starts inside of, or -1 */
#endif
} tracer;

/* Ready to trace the scene `a` searches (intersect.h). */
void trace_init(tracer *t, const accel *a, int depth, real cutoff);

/* The eye rays that follow lie in the plane through the eye with unit normal n (an
 * image line's, camera_line.normal): objects the plane misses are not looked for. */
void trace_eye_line(tracer *t, dir3 n);

/* Colour seen along an eye ray, from the camera (linear, not clamped). *hit_object gets
 * the index of the first object hit, or -1; it may be NULL. */
vec3 trace_eye(tracer *t, const ray *r, int *hit_object);

/* The offset origin of a ray leaving the hit h on the side `side` points to: moved by
 * REAL_OFFSET times the scale of the hit point's rounding error (numerics.md section 2),
 * in fixed point by the larger offset when the hit is rough (tolerance.h). */
vec3 trace_offset(const hit *h, dir3 side);

#endif
