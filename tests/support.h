/* support.h - small helpers the unit-test suites share: rays and parsing from text.
 * See LICENSE for copyright and licence. */
#ifndef RT_TEST_SUPPORT_H
#define RT_TEST_SUPPORT_H

#include "diag.h"
#include "shape.h"

/* A ray from origin along dir, normalised in the tested precision. */
ray test_ray(vec3 origin, vec3 dir);

/* Parses a scene held in a string; messages go to `sink` (NULL: dropped). Returns what
 * parse_scene returns. */
int test_parse_text(scene *s, const char *name, const char *text, diag_sink_fn sink,
		    void *ctx);

#endif
