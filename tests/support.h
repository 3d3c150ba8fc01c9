/* support.h - small helpers the unit-test suites share: rays and parsing from text.
 * See LICENSE for copyright and licence. */
#ifndef RT_TEST_SUPPORT_H
#define RT_TEST_SUPPORT_H

#include "diag.h"
#include "intersect.h"

/* A ray from origin along dir, normalised in the tested precision. */
ray test_ray(vec3 origin, vec3 dir);

/* Parses a scene held in a string; messages go to `sink` (NULL: dropped). Returns what
 * parse_scene returns. */
int test_parse_text(scene *s, const char *name, const char *text, diag_sink_fn sink,
		    void *ctx);

/* Parses a scene held in a string as a scene file is loaded (load_scene_buffer: in fixed
 * point measured, scaled, and refused when out of range). */
/* What the queries search for s (intersect.h): without a hierarchy (bvh = 0: every object
 * tested) or with the one rt builds (bvh = 1). Each kind has its own storage, so a test
 * can hold one of each. */
const accel *test_accel(const scene *s, int bvh);

int test_parse_buffer(scene *s, const char *name, const char *text, diag_sink_fn sink,
		      void *ctx);

/* The power of two by which the parser scales a scene whose largest coordinate is
 * `extent` (scale_length_shift; always 0 in floating point), and a length at that scale
 * as `real`, rounded once. */
int test_shift(double extent);
real test_scaled(double x, int shift);

/* 2^shift as a double, to bring a scaled result back to the case's own units. */
double test_scale(int shift);

#endif
