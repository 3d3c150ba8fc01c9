/* trace.c - start reading here: the recursive ray tracer (Hearn & Baker ch. 10).
 *
 * A ray finds its nearest hit; each light in front of the surface sends a shadow ray and
 * adds diffuse and a Phong highlight; an ambient term is added; a mirror ray weighted by
 * Ks and a refracted ray weighted by T recurse; light travelling inside an absorbing
 * medium is attenuated by e^(-a d). Recursion stops at the depth limit and when a path's
 * weight can no longer change an 8-bit pixel. Nothing is traced that cannot contribute.
 *
 * Stack: trace_ray recurses at most `depth` <= RT_MAX_DEPTH levels. With double and gcc -O3
 * (-fstack-usage) one level is trace_ray's 848 bytes (shading and refraction inlined) plus
 * trace_mirror's 144, and the deepest leaf below it (scene_intersect + cone_intersect) 336:
 * 8 levels * 992 + 336 = about 8.1 KiB worst case (the MCU's: docs/mcu.md).
 * See LICENSE for copyright and licence. */
#include "trace.h"

#include "naive.h"
#include "optics.h"

/* Colours are bounded so that sums of them (64 lights, a mirror and a refracted ray,
 * four pixel corners) stay within fixed point's range; 256 is far above what an 8-bit
 * pixel can show, whatever weight a path gives it. */
#define COLOR_MAX REAL_C(256.0)

/* One copy for its callers (RT_APART): 96 bytes less M0 flash. */
RT_APART static vec3 bounded(vec3 c)
{
	return vec_make(real_min(c.x, COLOR_MAX), real_min(c.y, COLOR_MAX), real_min(c.z, COLOR_MAX));
}

/* Mirror weights stay below 1 so two facing mirrors still fade out. */
#define MIRROR_MAX REAL_C(0.99609375) /* 255/256 */

void trace_init(tracer *t, const accel *a, int depth, real cutoff)
{
	const scene *s = accel_scene(a);
	const bvh_tree *tree = accel_tree(a);
	int i;
	t->accel = a;
	t->depth = depth;
	t->cutoff = cutoff;
	t->stats.eye_rays = t->stats.eye_hits = 0;
	t->stats.shadow_rays = t->stats.reflect_rays = t->stats.refract_rays = 0;
	for (i = 0; i < RT_MAX_DEPTH * RT_MAX_LIGHTS; i++)
		t->last_blocker[i / RT_MAX_LIGHTS][i % RT_MAX_LIGHTS] = -1;
	/* The eye rays' terms: every object's for a search object by object; through the
	 * tree, which takes none, only origin_terms_plane's (a million spheres' terms were
	 * 32 MB written and 20 ms for nothing, in each process of -j). */
	origin_terms_init(s, s->camera.from, tree ? ORIGIN_PLANE_OBJECTS : s->object_count, &t->eye);
#if INSIDE_LISTS
	t->inside = -1;
#endif
	for (i = 0; i < s->material_count; i++) {
		t->ambient[i] = bounded(vec_mul(s->ambient, s->materials[i].color));
#if !REAL_FIXED
		t->highlight_floor[i] = s->materials[i].ks > REAL_C(0.0)
						? optics_highlight_floor(s->materials[i].shine)
						: REAL_C(0.0);
#endif
	}
	/* The eye may sit inside glass: find the closed transmitting objects around it by
	 * asking whether a ray from the eye leaves each of them (an exit hit). */
	t->eye_media.count = 0;
	for (i = 0; i < s->object_count; i++) {
		const object *o = &s->objects[i];
		ray probe;
		hit h;
		if (s->materials[o->material].kt <= REAL_C(0.0))
			continue;
		if (!shape_is(SHAPE_CLOSED, o->kind))
			continue;
		probe.origin = s->camera.from;
		probe.dir = dir_make(UNIT_C(0.0), UNIT_C(0.0), UNIT_C(1.0));
		if (object_intersect(s, i, &probe, REAL_C(0.0), REAL_FAR, &h) &&
		    dir_dot(h.normal, probe.dir) > UNIT_C(0.0) &&
		    t->eye_media.count < RT_MAX_MEDIA)
			t->eye_media.material[t->eye_media.count++] = o->material;
	}
#if EYE_COVER
	eye_cover_init(&t->cover, a, t->eye_media.count > 0);
#endif
}

/* How far rays leave a hit point. */
static real offset_size(const hit *h)
{
	if (RT_NAIVE == RT_NAIVE_OFFSET)
		return naive_offset();
	/* The hit point's rounding error scales with its own size and the ray's length, not
	 * with the unit of length: a scene modelled in metres with 50 um parts needs offsets
	 * far below 1e-4. The small floor keeps a point at the origin off its surface. */
	real scale = real_max(REAL_C(0.0009765625),
			      real_max(vec_max_abs(h->point), real_fabs(h->t)));
	return real_surface_offset(scale, h->rough);
}

vec3 trace_offset(const hit *h, dir3 side)
{
	return dir_madd(h->point, offset_size(h), side);
}

/* Index of refraction of the medium on top of the stack (1 for the outside). Apart
 * (RT_APART): inlined into trace_ray it cost 16 bytes more M0 flash. */
RT_APART static real medium_ior(const scene *s, const media *m)
{
	return m->count ? s->materials[m->material[m->count - 1]].ior : REAL_C(1.0);
}

/* The stack after the ray crosses a surface of material `mat`: entering pushes it,
 * leaving removes its innermost entry (or nothing, if the ray was not known inside).
 * Apart (RT_APART): inlined into trace_ray it cost 20 bytes more M0 flash. */
RT_APART static void media_cross(const media *m, int mat, int entering, media *next)
{
	int i, skip = -1;
	*next = *m;
	if (entering) {
		if (next->count < RT_MAX_MEDIA)
			next->material[next->count++] = mat;
		return;
	}
	for (i = m->count - 1; i >= 0 && skip < 0; i--)
		if (m->material[i] == mat)
			skip = i;
	if (skip < 0)
		return;
	for (i = skip; i + 1 < m->count; i++)
		next->material[i] = m->material[i + 1];
	next->count--;
}

static vec3 trace_ray(tracer *t, const ray *r, int skip, int level, real weight,
		      const media *m, int *hit_object);

/* The origin of the rays that leave a hit on the ray's side (shadow and mirror rays),
 * offset once for all of them, when the first one needs it; and the object they cannot
 * meet again (object_can_rehit), or -1. */
typedef struct {
	const hit *h;
	vec3 point;
	real offset; /* how far point is from the hit's */
	int made;
	int skip;
} departure;

static vec3 departure_point(departure *d)
{
	if (!d->made) {
		d->offset = offset_size(d->h);
		d->point = dir_madd(d->h->point, d->offset, d->h->normal);
		d->made = 1;
	}
	return d->point;
}

/* At the horizon the hit's point stands in for origin + dir / per_t, which is past every
 * number of the type, and so is the light's offset from it; that offset times per_t,
 * (light - origin) per_t - dir, is not, and points the same way. A function of its own on
 * the M0: inlined, its numbers took room in every level of the recursion's stack. */
RT_APART static vec3 horizon_to_light(const light *l, const ray *r, unit per_t)
{
	vec3 from_origin = vec_sub(l->position, r->origin);
	return vec_sub(vec_make(real_mul_unit(from_origin.x, per_t),
				real_mul_unit(from_origin.y, per_t),
				real_mul_unit(from_origin.z, per_t)),
		       dir_to_vec(r->dir));
}

/* The distance along `to` and its direction, from one reciprocal square root (fixed point:
 * no root and no division); 0 when `to` has no length. */
static real toward(vec3 to, dir3 *dir)
{
	real2 distance2 = vec_dot2(to, to);
	real_reciprocal per_distance;
	if (!(distance2 > 0))
		return REAL_C(0.0);
	per_distance = real2_reciprocal_sqrt(distance2);
	*dir = dir_times_reciprocal(to, per_distance);
	return real2_sqrt_by(distance2, per_distance);
}

/* The highlight a light gives at cosine c between its direction and the mirror ray's:
 * ks c^shine (white, in the light's colour). Inlined at both of its uses in shade_lights,
 * before the shadow ray or after it. */
RT_INLINE real highlight_of(const material *mat, unit c)
{
	return real_mul(mat->ks, optics_highlight(unit_to_real(c), mat->shine));
}

/* The light a shadow ray from a hit on object `from` (of material `mat`) towards light
 * `lamp` passes (*blocker the opaque blocker, or -1): through the object's list where it
 * has one (shadow_list.h: transmitting solids only, and only they look), else through the
 * scene. */
RT_INLINE real shadow_pass(tracer *t, int from, const material *mat, int lamp, const ray *r,
			   real tmax, int skip, int *blocker)
{
#if SHADOW_LISTS
	if (mat->kt > REAL_C(0.0)) {
		const accel *a = t->accel;
		const shadow_list *list =
			shadow_lists_find(&a->shadow, accel_scene(a), &a->inside, from, lamp);
		real pass;
		if (list && shadow_list_pass(list, accel_scene(a), r, tmax, skip, &pass, blocker))
			return pass;
	}
#else
	(void)from;
	(void)mat;
	(void)lamp;
#endif
	return scene_transmittance(t->accel, r, tmax, skip, blocker);
}

/* Diffuse and highlight from every light the surface faces, through shadow rays. The
 * highlight's power is taken only for a light the shadow ray finds (a third of SPD
 * balls' lights are blocked), unless there is no diffuse light to send the ray for. The
 * M0 makes it first, as before: its scenes' lights are seldom blocked, and made after
 * the shadow ray it cost mcu-demo 5 instructions a pixel more (made first, 14 fewer than
 * before this order of the rest). */
#define HIGHLIGHT_AFTER_SHADOW (!RT_FLASH_SHORT)

static vec3 shade_lights(tracer *t, const ray *r, departure *from, const material *mat,
			 dir3 mirror_dir, int level)
{
	const scene *s = accel_scene(t->accel);
	const hit *h = from->h;
	vec3 sum = t->ambient[s->objects[h->object].material];
	int i;
	for (i = 0; i < s->light_count; i++) {
		const light *l = &s->lights[i];
		vec3 to_light = h->t < HORIZON_T ? vec_sub(l->position, h->point)
						 : horizon_to_light(l, r, h->per_t);
		real distance, diffuse, highlight = REAL_C(0.0), pass = REAL_C(1.0);
		unit cosine, c = UNIT_C(0.0);
		dir3 dir;
		vec3 lit;
		ray shadow;
		int shiny;
		distance = toward(to_light, &dir);
		if (!(distance > REAL_C(0.0)))
			continue;
		/* A light behind the surface sends no shadow ray (SPD rule). */
		cosine = dir_dot(h->normal, dir);
		if (cosine <= UNIT_C(0.0))
			continue;
		if (!h->flat)
			cosine = real_max(dir_dot(h->shading, dir), UNIT_C(0.0));
		diffuse = real_mul_unit(mat->kd, cosine);
		shiny = mat->ks > REAL_C(0.0) && (c = dir_dot(mirror_dir, dir)) > UNIT_C(0.0);
#if !REAL_FIXED
		/* Below the floor the highlight is 0, as optics_highlight would make it. */
		if (shiny && c < t->highlight_floor[s->objects[h->object].material])
			shiny = 0;
#endif
		/* Without diffuse light only the highlight can show, and decides the shadow ray. */
		if (!HIGHLIGHT_AFTER_SHADOW || !(diffuse > REAL_C(0.0))) {
			if (shiny)
				highlight = highlight_of(mat, c);
			shiny = 0;
			if (!(diffuse > REAL_C(0.0)) && !(highlight > REAL_C(0.0)))
				continue;
		}
		/* At the horizon nothing in the scene is between the point and the light. */
		if (h->t < HORIZON_T) {
			/* The shadow ray leaves from the offset point along the direction from
			 * the hit point: its segment ends at the light plus the offset. Where no
			 * surface is that near the light (its clearance, load.c), nothing
			 * between the two ends can tell them apart, and that costs nothing.
			 * Nearer, it could end behind the surface and be falsely shadowed by
			 * it: the segment then runs from the offset point towards the light
			 * itself, and stops the offset short of it, as it starts the offset off
			 * the surface: a surface that near the light (1e-9 from it, in float at
			 * 5 units) is within the blocker test's rounding of it. */
			int *cached = &t->last_blocker[level - 1][i];
			shadow.origin = departure_point(from);
			shadow.dir = dir;
			if (l->clearance <= from->offset + from->offset) {
				distance = toward(vec_sub(l->position, shadow.origin), &shadow.dir) -
					   from->offset;
				if (!(distance > REAL_C(0.0)))
					continue;
			}
			t->stats.shadow_rays++;
			if (*cached >= 0 && *cached != from->skip &&
			    object_intersect(s, *cached, &shadow, REAL_C(0.0), distance, NULL))
				continue;
			pass = shadow_pass(t, h->object, mat, i, &shadow, distance, from->skip,
					   cached);
			if (pass <= REAL_C(0.0))
				continue;
		}
		if (shiny)
			highlight = highlight_of(mat, c);
		/* The light's full contribution: diffuse in the surface colour, white highlight,
		 * in the light's colour (a white light's products would change nothing). */
		lit = vec_madd(vec_make(highlight, highlight, highlight), diffuse, mat->color);
		if (l->color.x != REAL_C(1.0) || l->color.y != REAL_C(1.0) ||
		    l->color.z != REAL_C(1.0))
			lit = vec_mul(l->color, lit);
		lit = bounded(lit);
		/* Nothing in the way (the usual case) passes all of it: no products. */
		if (pass != REAL_C(1.0))
			lit = vec_scale(lit, pass);
		sum = vec_add(sum, lit);
	}
	return sum;
}

/* Mirror ray of weight `ks` leaving the surface on the ray's side. */
static vec3 trace_mirror(tracer *t, departure *from, dir3 dir, int level, real weight, real ks,
			 const media *m)
{
	ray next;
	next.origin = departure_point(from);
	next.dir = dir;
	t->stats.reflect_rays++;
#if INSIDE_LISTS
	/* A solid's own rays leave it from inside (object_can_rehit): it is around them. */
	t->inside = from->skip < 0 ? from->h->object : -1;
#endif
	return vec_scale(trace_ray(t, &next, from->skip, level + 1, real_mul(weight, ks), m, NULL),
			 ks);
}

/* Refracted ray of weight kt (tinted by the surface colour, as NFF's T filters through
 * the object), or a mirror ray of the same weight on total internal reflection. */
static vec3 trace_refraction(tracer *t, const ray *r, departure *from, const material *mat,
			     int level, real weight, const media *m)
{
	const scene *s = accel_scene(t->accel);
	const hit *h = from->h;
	int mat_index = s->objects[h->object].material;
	media next_media;
	real eta;
	dir3 dir;
	ray next;

	media_cross(m, mat_index, h->front, &next_media);
	eta = real_div(medium_ior(s, m), h->front ? mat->ior : medium_ior(s, &next_media));
	if (!optics_refract(r->dir, h->normal, eta, &dir))
		return vec_mul(mat->color,
			       trace_mirror(t, from, optics_reflect_at(r->dir, h->normal, h->incidence),
					    level, weight, mat->kt, m));
	next.origin = trace_offset(h, dir_neg(h->normal));
	next.dir = dir;
	t->stats.refract_rays++;
#if INSIDE_LISTS
	/* Entering through the front, the ray is inside the object. */
	t->inside = h->front ? h->object : -1;
#endif
	return vec_scale(vec_mul(mat->color,
				 trace_ray(t, &next, -1, level + 1, real_mul(weight, mat->kt),
					   &next_media, NULL)),
			 mat->kt);
}

static vec3 trace_ray(tracer *t, const ray *r, int skip, int level, real weight,
		      const media *m, int *hit_object)
{
	const scene *s = accel_scene(t->accel);
	const vec3 *absorb = m->count ? &s->materials[m->material[m->count - 1]].absorb : NULL;
	int absorbing = absorb && (absorb->x > REAL_C(0.0) || absorb->y > REAL_C(0.0) ||
				   absorb->z > REAL_C(0.0));
	const material *mat;
	vec3 color;
	dir3 mirror_dir;
	real ks;
	hit h;
	departure from;

	/* REAL_FAR: beyond anything in the scene, and far enough from overflow that the hit
	 * point can be computed in every type. */
	/* Eye rays (level 1) take the terms that depend on their origin from the table made
	 * once for the frame, and the objects their image line can meet from it. */
#if INSIDE_LISTS
	int inside = t->inside;
	t->inside = -1;
	if (!(inside >= 0 ? scene_intersect_inside(t->accel, r, inside, skip, REAL_FAR, &h)
			  : scene_intersect_from(t->accel, r, level == 1 ? &t->eye : NULL, skip,
						 REAL_FAR, &h))) {
#else
	if (!scene_intersect_from(t->accel, r, level == 1 ? &t->eye : NULL, skip, REAL_FAR, &h)) {
#endif
		if (hit_object)
			*hit_object = -1;
		/* A ray that never leaves an absorbing medium is absorbed completely. */
		return absorbing ? vec_make(REAL_C(0.0), REAL_C(0.0), REAL_C(0.0)) : s->background;
	}
	if (hit_object)
		*hit_object = h.object;
	mat = &s->materials[s->objects[h.object].material];

	/* Phong shading reflects about the shading normal; if that would send the ray into
	 * the surface (possible on patches), reflect about the geometric normal instead
	 * (the same ray when the two normals are one). */
	if (h.flat) {
		mirror_dir = optics_reflect_at(r->dir, h.normal, h.incidence);
	} else {
		mirror_dir = optics_reflect(r->dir, h.shading);
		if (dir_dot(mirror_dir, h.normal) <= UNIT_C(0.0))
			mirror_dir = optics_reflect_at(r->dir, h.normal, h.incidence);
	}

	from.h = &h;
	from.point = h.point; /* until made */
	from.offset = REAL_C(0.0);
	from.made = 0;
	from.skip = object_can_rehit(s, h.object, h.front) ? -1 : h.object;
	color = shade_lights(t, r, &from, mat, mirror_dir, level);
	ks = real_min(mat->ks, MIRROR_MAX);
	if (!(h.t < HORIZON_T)) {
		/* No rays from the horizon (they would start beyond fixed point's range). Its
		 * mirror ray would leave beyond everything in the scene, as its shadow rays do:
		 * it sees the background (only another infinite plane could be in its way, and
		 * is not looked for). */
		if (ks > REAL_C(0.0) && level < t->depth && real_mul(weight, ks) >= t->cutoff &&
		    !absorbing)
			color = vec_madd(color, ks, s->background);
		return bounded(color);
	}
	if (ks > REAL_C(0.0) && level < t->depth && real_mul(weight, ks) >= t->cutoff)
		color = vec_add(color, trace_mirror(t, &from, mirror_dir, level, weight, ks, m));
	if (mat->kt > REAL_C(0.0) && level < t->depth && real_mul(weight, mat->kt) >= t->cutoff)
		color = vec_add(color, trace_refraction(t, r, &from, mat, level, weight, m));
	if (absorbing)
		color = vec_mul(color, vec_make(optics_beer(absorb->x, h.t), optics_beer(absorb->y, h.t),
						optics_beer(absorb->z, h.t)));
	return bounded(color);
}

void trace_eye_line(tracer *t, dir3 n)
{
	origin_terms_plane(accel_scene(t->accel), n, &t->eye);
#if EYE_COVER
	eye_cover_line(&t->cover, n);
#endif
	/* Each line starts without remembered blockers, so that it renders alike whatever
	 * lines a process traced before it (-j, --rows, -a's rows): a remembered blocker is
	 * tested alone, and a test that reports a hit outside the object's box (Q16.16 on
	 * a scene at the edge of its range) would shadow what the hierarchy, which skips
	 * that box, lights. Without the host's checks (the MCU, which has no hierarchy)
	 * every object is tested anyway. */
	if (RT_HOST_CHECKS) {
		int i;
		for (i = 0; i < RT_MAX_DEPTH * RT_MAX_LIGHTS; i++)
			t->last_blocker[i / RT_MAX_LIGHTS][i % RT_MAX_LIGHTS] = -1;
	}
}

vec3 trace_eye(tracer *t, const ray *r, int *hit_object)
{
	int first;
	vec3 color;
#if EYE_COVER
	/* What trace_ray gives a ray that meets nothing (the eye is in no medium here). */
	if (eye_cover_misses(&t->cover, r)) {
		t->stats.eye_rays++;
		if (hit_object)
			*hit_object = -1;
		return accel_scene(t->accel)->background;
	}
#endif
	color = trace_ray(t, r, -1, 1, REAL_C(1.0), &t->eye_media, &first);
	t->stats.eye_rays++;
	if (first >= 0)
		t->stats.eye_hits++;
	if (hit_object)
		*hit_object = first;
	return color;
}
