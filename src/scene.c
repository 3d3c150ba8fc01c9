/* scene.c - the scene's defaults.
 * See LICENSE for copyright and licence. */
#include "scene.h"

#include <string.h>

void scene_init(scene *s, const char *file)
{
	/* Counts, camera and colours to zero; the arrays are filled up to their counts. */
	memset(&s->camera, 0, sizeof s->camera);
	s->file = file;
	s->length_shift = 0;
	s->longest_length = REAL_C(0.0);
	s->background = vec_make(REAL_C(0.0), REAL_C(0.0), REAL_C(0.0));
	s->ambient = s->background;
	s->depth = RT_DEFAULT_DEPTH;
	s->cutoff = REAL_C(0.00390625); /* 1/256: cannot change an 8-bit pixel */
	s->material_count = s->light_count = s->object_count = 0;
	s->vertex_count = s->plane_count = 0;
}

/* Grows *extent to cover every coordinate of p, and r beyond it. */
static void cover(real *extent, vec3 p, real r)
{
	*extent = real_max(*extent, real_add(vec_max_abs(p), r));
}

void scene_measure(const scene *s, real *extent, real *feature)
{
	int i;
	*extent = REAL_C(0.0);
	*feature = REAL_MAX;
	cover(extent, s->camera.from, REAL_C(0.0));
	cover(extent, s->camera.at, REAL_C(0.0));
	for (i = 0; i < s->light_count; i++)
		cover(extent, s->lights[i].position, REAL_C(0.0));
	for (i = 0; i < s->vertex_count; i++)
		cover(extent, s->vertices[i], REAL_C(0.0));
	for (i = 0; i < s->plane_count; i++)
		*extent = real_max(*extent, real_fabs(s->planes[i].offset));
	for (i = 0; i < s->object_count; i++) {
		const object *o = &s->objects[i];
		if (o->kind == SHAPE_SPHERE) {
			cover(extent, o->u.sphere.center, o->u.sphere.radius);
			*feature = real_min(*feature, o->u.sphere.radius);
		} else if (RT_SHAPE_CONE && o->kind == SHAPE_CONE) {
			real r = real_max(o->u.cone.base_radius, o->u.cone.apex_radius);
			cover(extent, o->u.cone.base, r);
			cover(extent, dir_madd(o->u.cone.base, o->u.cone.length, o->u.cone.axis), r);
			*feature = real_min(*feature, r);
			/* A steep cone (radius changing much faster than its length) is as fine
			 * as its length over its slope. */
			*feature = real_min(*feature,
					    real_div(o->u.cone.length,
						     real_max(REAL_C(1.0), real_fabs(o->u.cone.slope))));
		} else if (o->kind == SHAPE_PLANE) {
			*extent = real_max(*extent, real_fabs(o->u.plane.offset));
		}
	}
}
