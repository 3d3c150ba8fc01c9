/* load.c - a scene from its source to a scene the number type can hold: the passes
 * (fixed point reads a scene first to measure it, then at the scale that fits), the
 * checks that the type can represent it, and where the eye and the lights stand.
 * See LICENSE for copyright and licence. */
#include "load.h"

#include "clearance.h"
#include "diag.h"
#include "parse.h"
#include "realtext.h"
#include "scale.h"
#include "tolerance.h"

/* One whole pass over the source, from its start, at length scale 2^shift. */
static int source_pass(scene *s, const char *name, const scene_source *source, int shift,
		       int again)
{
	int ok;
	if (!source->open(source->ctx, again))
		return 0;
#if RT_READ_BUFFER
	if (source->read_block)
		ok = parse_scene_blocks(s, name, source->read_block, source->ctx, shift);
	else
#endif
		ok = parse_scene_at(s, name, source->read, source->ctx, shift);
	/* The source reports its own read error; it counts only if parsing went well. */
	if (!source->close(source->ctx, ok))
		ok = 0;
	return ok;
}

/* Each light's clearance, for its shadow segments (trace.c); and the check that the eye
 * and the lights stand off every surface by more than the type can lose (REAL_CLEARANCE_MIN:
 * an eye that Q16.16 rounds onto a floor loses the floor). */
static int place_eye_and_lights(scene *s, const char *name)
{
	int i;
	for (i = -1; i < s->light_count; i++) {
		int nearest;
		real clearance = scene_clearance(s, i < 0 ? &s->camera.from : &s->lights[i].position,
						 &nearest);
		if (i >= 0)
			s->lights[i].clearance = clearance;
		if (clearance < REAL_CLEARANCE_MIN) {
			diag_error(name, 0,
				   "cannot be rendered in %s: the %s is within 2^%d units of the surface "
				   "on line %d",
				   REAL_NAME, i < 0 ? "eye" : "light",
				   REAL_CLEARANCE_BITS - 16 - s->length_shift, s->objects[nearest].line);
			return 0;
		}
	}
	return 1;
}

/* Loads a scene from a re-readable source: once in floating point; in fixed point first
 * to measure it, then at the scale that fits it, then checks it can be held. */
int load_scene_source(scene *s, const char *name, const scene_source *source)
{
	/* Floating point reads the file once. Fixed point reads it first to measure it (at
	 * scale 1, which keeps small scenes' detail, or if a length does not fit there at
	 * the coarse SCALE_FIRST_PASS_SHIFT that holds any coordinate), then again at the
	 * scale that fits its extent into Q16.16's range (scale_length_shift). */
	int final_shift;
	real extent, feature;
	const char *why;
	/* Test the macro, not a variable holding it: the condition is fixed per build, which
	 * static analysis reports about a variable ("always false"). */
	if (SCALE_FIRST_PASS_SHIFT != 0) {
		int shift = 0, ok, was_muted = diag_mute(1);
		ok = source_pass(s, name, source, shift, 1);
		if (!ok) {
			shift = SCALE_FIRST_PASS_SHIFT;
			ok = source_pass(s, name, source, shift, 1);
		}
		diag_mute(was_muted);
		if (!ok) /* again, to report the error */
			return source_pass(s, name, source, shift, 0);
		/* Every length read counts, also those of objects skipped at this scale. */
		final_shift = scale_length_shift(s->longest_length, shift);
	} else {
		final_shift = 0;
	}
	if (!source_pass(s, name, source, final_shift, 0))
		return 0;
	s->length_shift = final_shift;
	scene_measure(s, &extent, &feature);
	if (!scale_can_represent(extent, feature, &why)) {
		char e[32], f[32];
		real_format(extent, final_shift, e, sizeof e);
		real_format(feature, final_shift, f, sizeof f);
		diag_error(name, 0, "cannot be rendered in %s: extent %s, smallest feature %s: %s",
			   REAL_NAME, e, f, why);
		return 0;
	}
	return place_eye_and_lights(s, name);
}

/* A byte buffer read from its start on every pass. */
typedef struct {
	const unsigned char *data;
	size_t size, at;
} buffer_reader;

static int read_buffer(void *ctx)
{
	buffer_reader *b = ctx;
	return b->at < b->size ? b->data[b->at++] : -1;
}

static int buffer_open(void *ctx, int again)
{
	(void)again;
	((buffer_reader *)ctx)->at = 0;
	return 1;
}

static int buffer_close(void *ctx, int ok)
{
	(void)ctx;
	(void)ok;
	return 1;
}

int load_scene_buffer(scene *s, const char *name, const void *data, size_t size)
{
	buffer_reader b;
	scene_source source;
	b.data = data;
	b.size = size;
	b.at = 0;
	source.open = buffer_open;
	source.read = read_buffer;
#if RT_READ_BUFFER
	source.read_block = NULL;
#endif
	source.close = buffer_close;
	source.ctx = &b;
	return load_scene_source(s, name, &source);
}
