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

/* The bytes of an array of `capacity` bytes that text_bytes of scene text fill, about:
 * one and a half for a byte of text. SPD's scenes fill 0.4-2.1 (teapot-s12's 1.5 MB its
 * objects' 0.8 MB, vertices' 0.7 MB, normals' 0.7 MB and edge lines' 0.9 MB; balls' 0.3
 * MB its objects' 0.65 MB). An array so planned takes huge pages where that fills enough
 * of them (pages_plan): in huge pages SPD teapot-s12's run at 2x2 pixels (reading,
 * building, start and exit) took 15.2 ms of CPU time against 19.9 ms, mount's 11.6 ms
 * against 14.6 ms; in small pages, asked for a chunk at a time, each 4 KiB cost 7 us. A
 * short file's arrays stay on small pages, and so do those that hold a few numbers for
 * each polygon (its runs, its disc). */
static size_t planned(long text_bytes, size_t capacity)
{
	size_t guess = (size_t)text_bytes + (size_t)text_bytes / 2;
	return guess < capacity ? guess : capacity;
}

void scene_plan_pages(scene *s, long text_bytes)
{
	if (text_bytes <= 0)
		return;
	/* The objects' first huge page may hold the materials and lights too. */
	pages_plan(s->objects, planned(text_bytes, sizeof s->objects));
	pages_plan(s->vertices, planned(text_bytes, sizeof s->vertices));
	pages_plan(s->normals, planned(text_bytes, sizeof s->normals));
	pages_plan(s->planes, planned(text_bytes, sizeof s->planes));
#if POLYGON_EDGES
	pages_plan(s->edges, planned(text_bytes, sizeof s->edges));
#endif
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
