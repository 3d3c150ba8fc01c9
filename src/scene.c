/* scene.c - the scene's defaults, and the plan of its memory.
 * See LICENSE for copyright and licence. */
#include "scene.h"

#include "pages.h"
#include "shape.h"

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

/* A scene file this long fills arrays of hundreds of kilobytes: its objects take 30-150
 * bytes of text each (an NFF sphere or a polygon's vertex line) and 88 bytes of the object
 * array, a polygon's vertex 24 bytes of vertices and 32 of edge lines (and a patch's 24 of
 * normals). In huge pages those arrays took the CPU time of a run of SPD teapot-s12 at
 * 2x2 pixels (reading, building, start and exit) from 21.6 ms to 15.9 ms, mount's from
 * 16.2 ms to 12.8 ms; in small pages, asked for a chunk at a time, every 4 KiB cost 7 us.
 * A shorter file keeps small pages: its arrays fill too little of a huge page for one to
 * pay. */
#define SCENE_TEXT_HUGE 131072L

void scene_plan_pages(scene *s, long text_bytes)
{
	/* The whole scene: only the huge pages that are written are made, and an array
	 * the scene does not use is not written. */
	if (text_bytes >= SCENE_TEXT_HUGE)
		pages_plan(s, sizeof *s);
}

void scene_cover(real *extent, vec3 p, real r)
{
	*extent = real_max(*extent, real_add(vec_max_abs(p), r));
}

void scene_measure(const scene *s, real *extent, real *feature)
{
	int i;
	*extent = REAL_C(0.0);
	*feature = REAL_MAX;
	scene_cover(extent, s->camera.from, REAL_C(0.0));
	scene_cover(extent, s->camera.at, REAL_C(0.0));
	for (i = 0; i < s->light_count; i++)
		scene_cover(extent, s->lights[i].position, REAL_C(0.0));
	/* Polygons and polyhedra through their pools of vertices and planes; the other
	 * shapes measure themselves. */
	for (i = 0; i < s->vertex_count; i++)
		scene_cover(extent, s->vertices[i], REAL_C(0.0));
	for (i = 0; i < s->plane_count; i++)
		*extent = real_max(*extent, real_fabs(s->planes[i].offset));
	for (i = 0; i < s->object_count; i++)
		shape_measure(&s->objects[i], extent, feature);
}
