/* scene.c - the scene's defaults.
 * See LICENSE for copyright and licence. */
#include "scene.h"

#include <string.h>

void scene_init(scene *s, const char *file)
{
	/* Counts, camera and colours to zero; the arrays are filled up to their counts. */
	memset(&s->camera, 0, sizeof s->camera);
	s->file = file;
	s->background = vec_make(REAL_C(0.0), REAL_C(0.0), REAL_C(0.0));
	s->ambient = s->background;
	s->depth = RT_DEFAULT_DEPTH;
	s->cutoff = REAL_C(0.00390625); /* 1/256: cannot change an 8-bit pixel */
	s->material_count = s->light_count = s->object_count = 0;
	s->vertex_count = s->plane_count = 0;
}
