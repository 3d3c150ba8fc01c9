/* support.c - helpers shared by the unit-test suites.
 * See LICENSE for copyright and licence. */
#include "support.h"

#include <math.h>
#include <string.h>

#include "load.h"
#include "parse.h"
#include "scale.h"
#include "test.h"

ray test_ray(vec3 origin, vec3 dir)
{
	ray r;
	r.origin = origin;
	r.dir = dir_normalize(dir);
	return r;
}

typedef struct {
	const char *text;
	size_t at;
} text_reader;

static int read_text(void *ctx)
{
	text_reader *t = ctx;
	return t->text[t->at] ? (unsigned char)t->text[t->at++] : -1;
}

static void drop(void *ctx, const char *message)
{
	(void)ctx;
	(void)message;
}

int test_parse_text(scene *s, const char *name, const char *text, diag_sink_fn sink,
		    void *ctx)
{
	text_reader t;
	int ok;
	t.text = text;
	t.at = 0;
	diag_set_sink(sink ? sink : drop, ctx);
	ok = parse_scene(s, name, read_text, &t);
	diag_set_sink(NULL, NULL);
	return ok;
}

int test_parse_buffer(scene *s, const char *name, const char *text, diag_sink_fn sink,
		      void *ctx)
{
	int ok;
	diag_set_sink(sink ? sink : drop, ctx);
	ok = load_scene_buffer(s, name, text, strlen(text));
	diag_set_sink(NULL, NULL);
	return ok;
}

int test_shift(double extent)
{
	/* As load_scene_source measures: at scale 1 when the extent fits there, else at
	 * SCALE_FIRST_PASS_SHIFT. */
	if (extent < 32767.0)
		return scale_length_shift(test_real(extent), 0);
	return scale_length_shift(test_real(ldexp(extent, SCALE_FIRST_PASS_SHIFT)),
				 SCALE_FIRST_PASS_SHIFT);
}

real test_scaled(double x, int shift)
{
	return test_real(ldexp(x, shift));
}

double test_scale(int shift)
{
	return ldexp(1.0, shift);
}

const accel *test_accel(const scene *s, int bvh)
{
#if RT_USE_BVH
	static accel plain; /* large: static */
	if (bvh)
		return accel_build(s);
	plain.scene = s;
	plain.tree.node_count = 0;
	plain.tree.unbounded_count = 0;
	return &plain;
#else
	(void)bvh;
	return s;
#endif
}
