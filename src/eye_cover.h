/* eye_cover.h - which eye rays can meet anything at all: seen from the eye, each of the
 * hierarchy's top boxes covers a span across the image, and an eye ray outside the spans
 * of the boxes its image line passes meets nothing, so it is background without a search
 * (four fifths of SPD tetra's image, three quarters of which is found so).
 * Floating-point builds with a hierarchy; elsewhere every ray is searched.
 * See LICENSE for copyright and licence. */
#ifndef RT_EYE_COVER_H
#define RT_EYE_COVER_H

#include "intersect.h"

#define EYE_COVER (RT_USE_BVH && !REAL_FIXED)

#if EYE_COVER
#define EYE_COVER_BOXES 64 /* the top boxes: as many as the tree's first levels give */

typedef struct {
	int enabled;
	vec3 eye;
	/* A point x (from the eye) ahead of it is seen across at (x . across) / (x . forward). */
	vec3 forward, across;
	int box_count;
	/* Each box about the eye (its centre and half its extent), and the span across it
	 * is seen in, widened for every rounding (eye_cover.c). */
	vec3 centre[EYE_COVER_BOXES], half[EYE_COVER_BOXES];
	real span_lo[EYE_COVER_BOXES], span_hi[EYE_COVER_BOXES];
	real plane_reach; /* how far off a line's plane a box may lie and still count */
	/* The spans of the boxes the current image line's plane passes through or near,
	 * joined where they overlap, in order. */
	int line_count, line_whole; /* line_whole: search every ray of the line */
	real line_lo[EYE_COVER_BOXES], line_hi[EYE_COVER_BOXES];
	real image_half; /* the image's half width on the plane at unit distance */
} eye_cover;

/* Ready for the eye rays of scene s searched through accel a: disabled (every ray
 * searched) without a hierarchy, with unbounded objects, with the eye inside a medium. */
void eye_cover_init(eye_cover *c, const accel *a, int eye_in_medium);

/* The eye rays that follow lie in the plane through the eye with unit normal n (the
 * zero vector: anywhere). */
void eye_cover_line(eye_cover *c, dir3 n);

/* Does eye ray r (from the scene camera's eye, as every eye ray) certainly meet
 * nothing? (0: search it.) Inline: it is asked for every eye ray. */
static inline int eye_cover_misses(const eye_cover *c, const ray *r)
{
	vec3 d;
	real along, u;
	int low = 0, high;
	if (!c->enabled || c->line_whole)
		return 0;
	d = dir_to_vec(r->dir);
	along = vec_dot(d, c->forward);
	if (!(along > REAL_C(0.0)))
		return 0; /* NaN too */
	u = vec_dot(d, c->across) / along;
	/* The last span that starts at or before u: does it reach u? */
	high = c->line_count;
	while (low < high) {
		int middle = (low + high) / 2;
		if (c->line_lo[middle] <= u)
			low = middle + 1;
		else
			high = middle;
	}
	return (low == 0 || c->line_hi[low - 1] < u) && u == u; /* NaN is searched */
}
#endif

#endif
