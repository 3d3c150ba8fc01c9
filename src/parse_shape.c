/* parse_shape.c - the commands that make shapes: s, p, pp, c (NFF) and polyhedron, box,
 * plane (rt's extensions). Each reads its numbers, applies NFF's rules (a negative radius
 * shows the inside; a degenerate shape is skipped with a warning) and leaves the geometry
 * to the shape's own set-up (shape.h).
 * See LICENSE for copyright and licence. */
#include "pages.h"
#include "parser.h"

#include "shape.h"

int parse_sphere(parser *p)
{
	int line = p->lx.tok_line;
	vec3 center;
	real radius;
	object *o;
	if (!lexer_read_triple(&p->lx, "sphere centre", 1, &center) ||
	    !lexer_read_value(&p->lx, "sphere radius", 1, &radius))
		return 0;
	if (radius == REAL_C(0.0)) {
		parser_warn(p, line, "sphere with radius 0");
		return 1;
	}
	o = parser_new_object(p, SHAPE_SPHERE, line);
	if (!o)
		return 0;
	/* NFF: a negative radius shows only the inside. */
	if (radius < REAL_C(0.0)) {
		o->flags |= OBJ_INSIDE_ONLY;
		radius = -radius;
	}
	sphere_init(&o->u.sphere, center, radius);
	return 1;
}

/* `p n` or `pp n` followed by n vertices (pp: each with its normal). */
int parse_polygon(parser *p, int patch)
{
	scene *s = p->s;
	int line = p->lx.tok_line, i, first = s->vertex_count;
	long count;
	dir3 normal;
	object *o;

	if (!lexer_read_count(&p->lx, patch ? "patch vertex count" : "polygon vertex count", 3,
			RT_MAX_POLY_VERTS, "RT_MAX_POLY_VERTS", &count))
		return 0;
	if (count > RT_MAX_VERTICES - s->vertex_count)
		return parser_capacity_error(p, line, "polygon vertices in the scene", "RT_MAX_VERTICES",
				      RT_MAX_VERTICES);
	pages_ahead(s->vertices, sizeof s->vertices[0], (size_t)first, (size_t)count, RT_MAX_VERTICES);
	if (RT_SHAPE_PATCH && patch)
		pages_ahead(s->normals, sizeof s->normals[0], (size_t)first, (size_t)count,
			    RT_PATCH_VERTICES);
	for (i = 0; i < count; i++) {
		if (!lexer_read_triple(&p->lx, patch ? "patch vertex" : "polygon vertex", 1,
			      &s->vertices[first + i]))
			return 0;
		if (RT_SHAPE_PATCH && patch) {
			/* Normalised as read; a zero one stays zero until the face's is known. */
			vec3 n;
			if (!lexer_read_triple(&p->lx, "patch vertex normal", 0, &n))
				return 0;
			s->normals[first + i] = dir_normalize(n);
		}
	}
	normal = polygon_normal(s->vertices + first, (int)count);
	if (!(dir_dot(normal, normal) > 0)) {
		parser_warn(p, line, patch ? "patch with zero area" : "polygon with zero area");
		return 1;
	}
	o = parser_new_object(p, patch ? SHAPE_PATCH : SHAPE_POLYGON, line);
	if (!o)
		return 0;
	polygon_init(s, &o->u.polygon, normal, first, (int)count, patch);
	s->vertex_count += (int)count;
	return 1;
}

int parse_cone(parser *p)
{
	int line = p->lx.tok_line;
	vec3 base, apex, axis;
	real base_radius, apex_radius, length;
	unsigned char inside_only = 0;
	object *o;
	if (!lexer_read_triple(&p->lx, "cone base centre", 1, &base) ||
	    !lexer_read_value(&p->lx, "cone base radius", 1, &base_radius) ||
	    !lexer_read_triple(&p->lx, "cone apex centre", 1, &apex) ||
	    !lexer_read_value(&p->lx, "cone apex radius", 1, &apex_radius))
		return 0;
	/* NFF: both radii negative shows only the inside. */
	if (base_radius < REAL_C(0.0) && apex_radius <= REAL_C(0.0)) {
		inside_only = OBJ_INSIDE_ONLY;
		base_radius = -base_radius;
		apex_radius = -apex_radius;
	} else if (base_radius < REAL_C(0.0) || apex_radius < REAL_C(0.0)) {
		/* The apex radius, read last, is still the current token: show it as written
		 * (whatever the number type). */
		return lexer_fail(&p->lx, line,
			    "cone: both radii must have the same sign, got base radius %s 0 and "
			    "apex radius %s",
			    base_radius < REAL_C(0.0) ? "<" : ">=", p->lx.tok);
	}
	axis = vec_sub(apex, base);
	length = vec_length(axis);
	if (!(length > REAL_C(0.0))) {
		parser_warn(p, line, "cone with zero length");
		return 1;
	}
	if (base_radius == REAL_C(0.0) && apex_radius == REAL_C(0.0)) {
		parser_warn(p, line, "cone with both radii 0");
		return 1;
	}
	o = parser_new_object(p, SHAPE_CONE, line);
	if (!o)
		return 0;
	o->flags |= inside_only;
	cone_init(&o->u.cone, base, axis, length, base_radius, apex_radius);
	return 1;
}

/* Adds the half-space n.x <= d to the plane pool, normalised; `line` is the entity's
 * (a capacity error names it; a zero normal is reported at its own row). */
static int add_halfspace(parser *p, vec3 n, real d, int line)
{
	scene *s = p->s;
	real2 length2 = vec_dot2(n, n);
	if (!(length2 > 0))
		return lexer_fail(&p->lx, p->lx.tok_line, "polyhedron: a plane normal is %s",
			    parser_zero_word(p, p->lx.tok_line, parser_not_all_zero(n)));
	if (s->plane_count == RT_MAX_PLANES)
		return parser_capacity_error(p, line, "polyhedron planes in the scene", "RT_MAX_PLANES",
				      RT_MAX_PLANES);
	pages_ahead(s->planes, sizeof s->planes[0], (size_t)s->plane_count, 1, RT_MAX_PLANES);
	hedron_plane_init(&s->planes[s->plane_count++], n, length2, d);
	return 1;
}

/* Extension `polyhedron n` then n planes `nx ny nz d`: the solid where every n.x <= d. */
int parse_hedron(parser *p)
{
	int line = p->lx.tok_line, first = p->s->plane_count, i;
	long count;
	object *o;
	if (!lexer_read_count(&p->lx, "polyhedron plane count", 1, RT_MAX_HEDRON_PLANES,
			"RT_MAX_HEDRON_PLANES", &count))
		return 0;
	for (i = 0; i < count; i++) {
		vec3 n;
		real d;
		if (!lexer_read_triple(&p->lx, "polyhedron plane normal", 0, &n) ||
		    !lexer_read_value(&p->lx, "polyhedron plane offset", 1, &d) ||
		    !add_halfspace(p, n, d, line))
			return 0;
	}
	o = parser_new_object(p, SHAPE_HEDRON, line);
	if (!o)
		return 0;
	o->u.hedron.first = first;
	o->u.hedron.count = (int)count;
	return 1;
}

/* Extension `box x0 y0 z0 x1 y1 z1`: an axis-aligned box from two opposite corners. */
int parse_box(parser *p)
{
	int line = p->lx.tok_line, first = p->s->plane_count, face;
	vec3 a, b;
	object *o;
	if (!lexer_read_triple(&p->lx, "box corner", 1, &a) ||
	    !lexer_read_triple(&p->lx, "box corner", 1, &b))
		return 0;
	if (a.x == b.x || a.y == b.y || a.z == b.z) {
		parser_warn(p, line, "box with zero thickness");
		return 1;
	}
	/* Face 2 axis + 0 is the upper side n.x <= hi, 2 axis + 1 the lower -n.x <= -lo. */
	for (face = 0; face < 6; face++) {
		int axis = face >> 1;
		real lo = real_min(vec_get(a, axis), vec_get(b, axis));
		real hi = real_max(vec_get(a, axis), vec_get(b, axis));
		vec3 n = vec_make(axis == 0 ? REAL_C(1.0) : REAL_C(0.0),
				  axis == 1 ? REAL_C(1.0) : REAL_C(0.0),
				  axis == 2 ? REAL_C(1.0) : REAL_C(0.0));
		if (!add_halfspace(p, face & 1 ? vec_neg(n) : n, face & 1 ? -lo : hi, line))
			return 0;
	}
	o = parser_new_object(p, SHAPE_HEDRON, line);
	if (!o)
		return 0;
	o->u.hedron.first = first;
	o->u.hedron.count = 6;
	return 1;
}

/* Extension `plane px py pz nx ny nz`: the infinite plane through p with normal n. */
int parse_plane(parser *p)
{
	int line = p->lx.tok_line;
	vec3 point, normal;
	object *o;
	if (!lexer_read_triple(&p->lx, "plane point", 1, &point) ||
	    !lexer_read_triple(&p->lx, "plane normal", 0, &normal))
		return 0;
	if (!(vec_dot2(normal, normal) > 0))
		return lexer_fail(&p->lx, line, "plane: the normal is %s",
			    parser_zero_word(p, line, parser_not_all_zero(normal)));
	o = parser_new_object(p, SHAPE_PLANE, line);
	if (!o)
		return 0;
	plane_init(&o->u.plane, &point, normal);
	return 1;
}
