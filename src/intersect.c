/* intersect.c - nearest-hit and shadow queries over all objects of a scene.
 * This is also where normals are turned to face the ray, in one place for every shape.
 * See LICENSE for copyright and licence. */
#include "intersect.h"

#include "pages.h"

/* The shape's own test, inlined into the scene's loops below (on the M0 a call more per
 * object and ray was a tenth of all the work). Without origin terms (k NULL) the sphere
 * and plane tests make their own. */
RT_INLINE int shape_intersect(const scene *s, const object *o, const ray *r,
				  const origin_term *k, real tmin, real tmax, hit *h)
{
	switch (o->kind) {
	case SHAPE_SPHERE:
		return sphere_intersect_from(o, r, k, tmin, tmax, h);
	case SHAPE_POLYGON:
	case SHAPE_PATCH:
		return polygon_intersect(s, o, r, tmin, tmax, h);
	case SHAPE_CONE:
		return RT_SHAPE_CONE && cone_intersect(o, r, tmin, tmax, h);
	case SHAPE_HEDRON:
		return hedron_intersect(s, o, r, tmin, tmax, h);
	case SHAPE_PLANE:
		return plane_intersect_from(o, r, k, tmin, tmax, h);
	default:
		return 0;
	}
}

int object_intersect(const scene *s, int index, const ray *r, real tmin, real tmax, hit *h)
{
	return object_intersect_from(s, index, r, NULL, tmin, tmax, h);
}

int object_intersect_from(const scene *s, int index, const ray *r, const origin_term *k,
			  real tmin, real tmax, hit *h)
{
	return shape_intersect(s, &s->objects[index], r, k, tmin, tmax, h);
}

/* Turns the geometric normal against the ray and the shading normal to the same side
 * (SPD's teapot has patches whose vertex normals oppose the face). */
static void face_forward(const ray *r, hit *h)
{
	h->flat = h->shading.x == h->normal.x && h->shading.y == h->normal.y &&
		  h->shading.z == h->normal.z;
	h->incidence = dir_dot(h->normal, r->dir);
	h->front = h->incidence < UNIT_C(0.0);
	if (!h->front) {
		h->normal = dir_neg(h->normal);
		h->incidence = -h->incidence;
	}
	/* A shading normal that is the geometric one turns with it: no product needed. */
	if (h->flat)
		h->shading = h->normal;
	else if (dir_dot(h->shading, h->normal) < UNIT_C(0.0))
		h->shading = dir_neg(h->shading);
}

/* What every query's nearest hit gets once found: normals faced, roughness noted. */
static void hit_finish(const scene *s, const ray *r, hit *h)
{
	face_forward(r, h);
	h->rough = (int)shape_is(SHAPE_ROUGH, s->objects[h->object].kind);
}

void object_origin_term(const object *o, vec3 origin, origin_term *k)
{
	if (o->kind == SHAPE_SPHERE) {
		k->f = vec_sub(origin, o->u.sphere.center);
		k->u.c = vec_dot2(k->f, k->f) - o->u.sphere.radius2;
	} else if (o->kind == SHAPE_PLANE) {
		k->u.distance = o->u.plane.offset - dir_dot_vec(o->u.plane.normal, origin);
	}
}

void origin_terms_init(const scene *s, vec3 origin, int count, origin_terms *k)
{
	int i;
	if (count > s->object_count)
		count = s->object_count;
	k->candidates = ~(uint32_t)0;
	pages_prepare(k->terms, (size_t)count * sizeof k->terms[0]);
	for (i = 0; i < count; i++)
		object_origin_term(&s->objects[i], origin, &k->terms[i]);
}

void origin_terms_plane(const scene *s, dir3 n, origin_terms *k)
{
	int i;
	k->candidates = ~(uint32_t)0;
	for (i = 0; i < s->object_count && i < ORIGIN_PLANE_OBJECTS; i++) {
		const object *o = &s->objects[i];
		const vec3 *f = &k->terms[i].f;
		real reach;
		if (o->kind != SHAPE_SPHERE)
			continue;
		/* The centre's distance from the plane against the radius, with room for the
		 * rays' own rounding (their directions are good to about 2^-16, and so their
		 * plane at the centre's distance) and the sphere test's: 2^-10 of the scale. */
		reach = real_add(o->u.sphere.radius,
				 real_mul(real_add(o->u.sphere.radius, real_add(vec_max_abs(*f), vec_max_abs(*f))),
					  REAL_C(0.0009765625)));
		if (real_fabs(dir_dot_vec(n, *f)) > reach)
			k->candidates &= ~((uint32_t)1 << i);
	}
}

RT_STATIC_ASSERT(every_shape_flat_or_convex,
		 (SHAPE_FLAT | SHAPE_CONVEX) == (1u << SHAPE_KINDS) - 1 && !(SHAPE_FLAT & SHAPE_CONVEX));

int object_can_rehit(const scene *s, int index, int front)
{
	/* A flat one never; a convex solid only from inside. Every kind is one or the other
	 * (checked below): a shape that is neither would be met again from outside too. */
	return !shape_is(SHAPE_FLAT, s->objects[index].kind) && !front;
}

#if RT_USE_BVH
const accel *accel_build(const scene *s)
{
	static accel the_accel; /* large: a tree of 2 RT_MAX_OBJECTS nodes */
	the_accel.scene = s;
	bvh_build(&the_accel.tree, s);
#if INSIDE_LISTS
	inside_build(&the_accel.inside, s, &the_accel.tree);
	shadow_lists_build(&the_accel.shadow, s, &the_accel.tree, &the_accel.inside);
#endif
	return &the_accel;
}
#endif

int scene_intersect(const accel *a, const ray *r, real tmax, hit *h)
{
	return scene_intersect_from(a, r, NULL, -1, tmax, h);
}

int scene_intersect_from(const accel *a, const ray *r, const origin_terms *k, int skip,
			 real tmax, hit *h)
{
	const scene *s = accel_scene(a);
	const bvh_tree *tree = accel_tree(a);
	int found = 0;
	if (tree) {
		found = bvh_nearest(s, tree, r, skip, tmax, h);
	} else {
		uint32_t candidates = k ? k->candidates : ~(uint32_t)0;
		int i;
		for (i = 0; i < s->object_count; i++) {
			/* Each hit shrinks tmax, so later objects only report nearer hits. */
			if (i != skip && (i >= ORIGIN_PLANE_OBJECTS || candidates >> i & 1) &&
			    shape_intersect(s, &s->objects[i], r, k ? &k->terms[i] : NULL, REAL_C(0.0),
					    tmax, h)) {
				tmax = h->t;
				h->object = i;
				found = 1;
			}
		}
	}
	if (found)
		hit_finish(s, r, h);
	return found;
}

#if INSIDE_LISTS
int scene_intersect_inside(const accel *a, const ray *r, int solid, int skip, real tmax, hit *h)
{
	const scene *s = accel_scene(a);
	int found;
	if (solid < 0 || !a->tree.node_count ||
	    !inside_nearest(&a->inside, s, &a->tree, solid, r, skip, tmax, h, &found))
		return scene_intersect_from(a, r, NULL, skip, tmax, h);
	hit_finish(s, r, h);
	return found;
}
#endif

real scene_transmittance(const accel *a, const ray *r, real tmax, int skip, int *blocker)
{
	const scene *s = accel_scene(a);
	const bvh_tree *tree = accel_tree(a);
	real pass = REAL_C(1.0);
	int i, unused;
	if (!blocker)
		blocker = &unused;
	*blocker = -1;
	if (tree)
		return bvh_transmittance(s, tree, r, skip, tmax, blocker);
	for (i = 0; i < s->object_count; i++) {
		if (i != skip && shape_intersect(s, &s->objects[i], r, NULL, REAL_C(0.0), tmax, NULL)) {
			real kt = s->materials[s->objects[i].material].kt;
			/* Stop at the first opaque blocker: nothing else can change the answer. */
			if (kt <= REAL_C(0.0)) {
				*blocker = i;
				return REAL_C(0.0);
			}
			pass = real_mul(pass, kt);
		}
	}
	return pass;
}
