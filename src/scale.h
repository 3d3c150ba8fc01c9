/* scale.h - a scene's length scale and whether the number type can hold the scene.
 * Floating point reads every scene as written (scale 1) and holds any scene within its
 * input limit. Q16.16 reads a scene first to measure it, then scales its lengths by the
 * power of two that brings it into range, and refuses a scene whose smallest feature is
 * too fine for its extent. load.c applies these rules.
 * See LICENSE for copyright and licence. */
#ifndef RT_SCALE_H
#define RT_SCALE_H

#include "real.h"

/* The length scale of the first, measuring pass: 2^-12 in Q16.16 (lengths up to 1.3e8
 * units fit, to find the scene's extent); 0 in floating point, which needs no measuring
 * pass. */
#if REAL_FIXED
#define SCALE_FIRST_PASS_SHIFT (-12)
#else
#define SCALE_FIRST_PASS_SHIFT 0
#endif

/* The length scale 2^shift that brings a scene whose extent (largest coordinate) was
 * measured at 2^measured_shift into the type's comfortable range (Q16.16: 2048 to 4096;
 * floating point: 0, always). */
int scale_length_shift(real extent, int measured_shift);

/* Can a scene of this extent and smallest feature (both after scaling) be rendered?
 * 0 and *why when its dynamic range is too large for the type. */
int scale_can_represent(real extent, real feature, const char **why);

#endif
