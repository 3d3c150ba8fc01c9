/* scale.c - a scene's length scale and whether the number type can hold the scene
 * (scale.h): nothing to do in floating point; in Q16.16 the power of two that brings the
 * scene into range, and the refusal of a dynamic range too large for it.
 * See LICENSE for copyright and licence. */
#include "scale.h"

#if REAL_FIXED
int scale_length_shift(real extent, int measured_shift)
{
	/* At most 4096 (2^12): squares, ray lengths across the scene and their sums keep
	 * headroom in Q16.16 and Q32.32; at least 2048, to use the bits there are. */
	int s = measured_shift;
	int32_t e = extent > 0 ? extent : 1; /* doubled only while at most 2^27: 32 bits */
	while (e > (int32_t)4096 * 65536) {
		e >>= 1;
		s--;
	}
	while (e <= (int32_t)2048 * 65536 && s < 16) {
		e <<= 1;
		s++;
	}
	return s;
}

int scale_can_represent(real extent, real feature, const char **why)
{
	/* The smallest feature (a radius, a cone's length) must keep its square and stay
	 * well above the hit point's error and the secondary-ray offset: at least 1/32768 of
	 * the extent, 1/8 unit at full scale. Measured at 256x256 against the reference:
	 * SPD shells (ratio 28,600) hits another object in 0.03 % of its pixels, SPD tree at
	 * its default size (49,140) in 3.1 %. */
	*why = NULL;
	/* In 32 bits: from 65536 on, feature * 32768 is past any extent. */
	if (feature > 0 && feature < 65536 && feature * 32768 < extent) {
		*why = "the ratio of its extent to its smallest feature is over 32768";
		return 0;
	}
	return 1;
}
#else
int scale_length_shift(real extent, int measured_shift)
{
	(void)extent;
	(void)measured_shift;
	return 0;
}

int scale_can_represent(real extent, real feature, const char **why)
{
	(void)extent;
	(void)feature;
	*why = 0;
	return 1;
}
#endif
