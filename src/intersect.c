/* intersect.c - nearest-hit and shadow queries over all objects of a scene.
 * This is also where normals are turned to face the ray, in one place for every shape.
 * See LICENSE for copyright and licence. */
#include "intersect.h"

#include "bvh.h"

int object_intersect(const scene *s, int index, const ray *r, real tmin, real tmax, hit *h)
{
	const object *o = &s->objects[index];
	switch (o->kind) {
	case SHAPE_SPHERE:
		return sphere_intersect(o, r, tmin, tmax, h);
	case SHAPE_POLYGON:
	case SHAPE_PATCH:
		return polygon_intersect(s, o, r, tmin, tmax, h);
	case SHAPE_CONE:
		return cone_intersect(o, r, tmin, tmax, h);
	case SHAPE_HEDRON:
		return hedron_intersect(s, o, r, tmin, tmax, h);
	case SHAPE_PLANE:
		return plane_intersect(o, r, tmin, tmax, h);
	default:
		return 0;
	}
}

/* Turns the geometric normal against the ray and the shading normal to the same side
 * (SPD's teapot has patches whose vertex normals oppose the face). */
static void face_forward(const ray *r, hit *h)
{
	h->front = vec_dot(h->normal, r->dir) < REAL_C(0.0);
	if (!h->front)
		h->normal = vec_neg(h->normal);
	if (vec_dot(h->shading, h->normal) < REAL_C(0.0))
		h->shading = vec_neg(h->shading);
}

/* Nearest-hit search state shared with the hierarchy's visitor. */
typedef struct {
	const scene *s;
	const ray *r;
	hit *h;
	int found;
} nearest_search;

static int visit_nearest(void *ctx, int index, real *tmax)
{
	nearest_search *q = ctx;
	/* Each hit shrinks tmax, so later objects only report nearer hits. */
	if (object_intersect(q->s, index, q->r, REAL_C(0.0), *tmax, q->h)) {
		*tmax = q->h->t;
		q->h->object = index;
		q->found = 1;
	}
	return 0;
}

/* Shadow search state: the light passed so far. */
typedef struct {
	const scene *s;
	const ray *r;
	real pass;
} shadow_search;

static int visit_shadow(void *ctx, int index, real *tmax)
{
	shadow_search *q = ctx;
	if (object_intersect(q->s, index, q->r, REAL_C(0.0), *tmax, NULL)) {
		real kt = q->s->materials[q->s->objects[index].material].kt;
		/* Stop at the first opaque blocker: nothing else can change the answer. */
		if (kt <= REAL_C(0.0)) {
			q->pass = REAL_C(0.0);
			return 1;
		}
		q->pass = real_mul(q->pass, kt);
	}
	return 0;
}

/* Visits every candidate object: through the hierarchy when the scene has one, else
 * all of them in order. Returns 1 if a visit stopped the search. */
static int visit_objects(const scene *s, const ray *r, real *tmax,
			 int (*visit)(void *, int, real *), void *ctx)
{
	int i;
#if RT_USE_BVH
	if (s->bvh_node_count)
		return bvh_traverse(s, r, tmax, visit, ctx);
#endif
	for (i = 0; i < s->object_count; i++)
		if (visit(ctx, i, tmax))
			return 1;
	return 0;
}

int scene_intersect(const scene *s, const ray *r, real tmax, hit *h)
{
	nearest_search q;
	q.s = s;
	q.r = r;
	q.h = h;
	q.found = 0;
	visit_objects(s, r, &tmax, visit_nearest, &q);
	if (q.found)
		face_forward(r, h);
	return q.found;
}

real scene_transmittance(const scene *s, const ray *r, real tmax)
{
	shadow_search q;
	q.s = s;
	q.r = r;
	q.pass = REAL_C(1.0);
	visit_objects(s, r, &tmax, visit_shadow, &q);
	return q.pass;
}
