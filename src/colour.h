/* colour.h - the colour pipeline: how scene colours become the tracer's linear light, and
 * linear colours the 8-bit code values of every image format.
 * See LICENSE for copyright and licence. */
#ifndef RT_COLOUR_H
#define RT_COLOUR_H

#include "vec.h"

/* sRGB (the default): scene colours (surface and background) are sRGB values, as colour
 * pickers give them, decoded to linear light for the tracer, and images are encoded back
 * to sRGB. Classic: what NFF's own renderers did: scene colours taken as they are and
 * written as they are (clamped to [0, 1], times 255), no curve either way. Lights are
 * linear in both. */
enum colour_pipeline { COLOUR_SRGB, COLOUR_CLASSIC };

/* Chooses the pipeline, before the scene is read. From the scene (its `colours`
 * command), a choice the command line made stands. */
void colour_choose(enum colour_pipeline pipeline, int from_scene);

/* Linear [0, 1] (clamped) to the image's 8-bit code value, rounded to nearest. */
unsigned char colour_byte(real linear);

/* A scene colour (surface or background) as the tracer uses it, by the pipeline. */
vec3 colour_scene_to_linear(vec3 colour);

/* sRGB's curve whatever the pipeline: what a display makes of code values (previews). */
vec3 colour_srgb_to_linear(vec3 srgb);

/* Encodes `count` colours as RGB bytes. */
void colour_encode_row(const vec3 *colors, int count, unsigned char *bytes);

#endif
