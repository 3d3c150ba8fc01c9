/* colour.h - sRGB: scene colours decoded to linear light at load, linear colours encoded
 * to 8-bit code values for every image format.
 * See LICENSE for copyright and licence. */
#ifndef RT_COLOUR_H
#define RT_COLOUR_H

#include "vec.h"

/* Linear [0, 1] (clamped) to an 8-bit sRGB code value, rounded to nearest. */
unsigned char colour_srgb_byte(real linear);

/* Scene colours (surface and background) are written as sRGB values, as colour pickers
 * give them; lighting is done in linear light. This decodes one colour for the tracer. */
vec3 colour_srgb_to_linear(vec3 srgb);

/* Encodes `count` colours as RGB bytes. */
void colour_encode_row(const vec3 *colors, int count, unsigned char *bytes);

#endif
