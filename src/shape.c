/* shape.c - the operations that dispatch on an object's kind outside the hot path:
 * bounds for the BVH, clearance, the scene's extent. What each kind is (flat, convex,
 * closed, rough) is the table in shape.h; the intersection tests dispatch in
 * intersect.c, where the scene's loops inline them. A new shape adds a case to each.
 * See LICENSE for copyright and licence. */
#include "shape.h"

int shape_bounds(const scene *s, const object *o, vec3 *lo, vec3 *hi)
{
	switch (o->kind) {
	case SHAPE_SPHERE:
		return sphere_bounds(&o->u.sphere, lo, hi);
	case SHAPE_POLYGON:
	case SHAPE_PATCH:
		return polygon_bounds(s, &o->u.polygon, lo, hi);
	case SHAPE_CONE:
		return RT_SHAPE_CONE && cone_bounds(&o->u.cone, lo, hi);
	case SHAPE_HEDRON:
		return hedron_bounds(s, &o->u.hedron, lo, hi);
	default:
		return 0;
	}
}

real shape_clearance(const scene *s, const object *o, const vec3 *p)
{
	switch (o->kind) {
	case SHAPE_SPHERE:
		return sphere_clearance(&o->u.sphere, p);
	case SHAPE_POLYGON:
	case SHAPE_PATCH:
		return polygon_clearance(s, &o->u.polygon, p);
	case SHAPE_CONE:
		return RT_SHAPE_CONE ? cone_clearance(&o->u.cone, p) : REAL_MAX;
	case SHAPE_HEDRON:
		return hedron_clearance(s, &o->u.hedron, p);
	case SHAPE_PLANE:
		return real_fabs(plane_gap(o->u.plane.normal, o->u.plane.offset, p));
	default:
		return REAL_MAX;
	}
}

void shape_measure(const object *o, real *extent, real *feature)
{
	switch (o->kind) {
	case SHAPE_SPHERE:
		sphere_measure(&o->u.sphere, extent, feature);
		break;
	case SHAPE_CONE:
		if (RT_SHAPE_CONE)
			cone_measure(&o->u.cone, extent, feature);
		break;
	case SHAPE_PLANE:
		plane_measure(&o->u.plane, extent);
		break;
	default:
		break; /* polygons and polyhedra: their pools (scene_measure) */
	}
}
