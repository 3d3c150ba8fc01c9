/* outline.c - does a ray pass through a polygon's outline? A crossings test in the ray's
 * own frame with the half-open rule, each edge's endpoints in a canonical order and its
 * side decided exactly, so a ray through an edge or vertex shared by several polygons
 * passes through exactly one of them, whatever their planes (numerics.md section 3).
 * See LICENSE for copyright and licence. */
#include "shape.h"

/* The inside test looks down the ray, as the watertight ray/triangle test of Woop, Benthin
 * and Wald (JCGT 2013) does: with z the axis of the direction's largest component (x and
 * y the next two, cyclically), a point p is seen at
 *   u = a_x d_z - a_z d_x,  v = a_y d_z - a_z d_y,  a = p - origin,
 * its projection along the ray onto z = 0, scaled by d_z (no division). The ray meets the
 * polygon where (0, 0) is inside the projected outline. A vertex's (u, v) depends on the
 * vertex and the ray alone, so the polygons that share an edge see it at the same two
 * points, whatever planes and normals they rounded to (tilted, non-planar, any type). */
typedef struct {
	int z;      /* the axis of the direction's largest component */
	unit dx, dy, dz; /* the direction, its axes in the order z + 1, z + 2, z */
	vec3 origin; /* the same order */
	real v_origin; /* the origin's v in the frame of the axes' zero: v = v(p) - v_origin */
} ray_frame;

/* p's axes in the frame's order: a rotation, which keeps the outline's orientation. */
static vec3 frame_axes(vec3 p, int z)
{
	return z == 2 ? p : z == 0 ? vec_make(p.y, p.z, p.x) : vec_make(p.z, p.x, p.y);
}

static ray_frame frame_of(const ray *r)
{
	ray_frame f;
	unit ax = unit_fabs(r->dir.x), ay = unit_fabs(r->dir.y), az = unit_fabs(r->dir.z);
	f.z = ax > ay ? (ax > az ? 0 : 2) : (ay > az ? 1 : 2);
	{
		/* The direction's axes in the same order (a unit vector's components go
		 * through frame_axes as the numbers they are, in every type). */
		vec3 d = frame_axes(vec_make(r->dir.x, r->dir.y, r->dir.z), f.z);
		f.dx = d.x;
		f.dy = d.y;
		f.dz = d.z;
	}
	f.origin = frame_axes(r->origin, f.z);
	f.v_origin = real_cross_unit(f.dz, f.origin.y, f.dy, f.origin.z);
	return f;
}

/* A point's v and u in the frame (its axes in the frame's order). v is linear in the
 * point: its own less the origin's, two products; u, which only the few edges that
 * straddle v = 0 need, comes from the point relative to the origin. */
static inline real frame_v(const ray_frame *f, vec3 p)
{
	return real_cross_unit(f->dz, p.y, f->dy, p.z) - f->v_origin;
}

static inline real frame_u(const ray_frame *f, vec3 p)
{
	return real_cross_unit(f->dz, p.x - f->origin.x, f->dx, p.z - f->origin.z);
}

/* Does the edge (a, b), whose ends lie on different sides of v = 0, meet the +u ray from
 * (0, 0)? Canonical order (by v): both neighbours of an edge test the same endpoints in
 * the same order. The edge meets v = 0 at u >= 0 when cross(lo, hi) >= 0 (hi.v > lo.v),
 * decided exactly: each edge's answer is then that of the exact geometry of the
 * projected vertices, so neighbours tile the frame with no gap and no overlap, and a ray
 * through a shared edge or vertex is inside exactly one of them. */
static inline int edge_meets_u_ray(real au, real av, real bu, real bv)
{
	return av < bv ? real_products_ge(au, bv, av, bu) : real_products_ge(bu, av, bv, au);
}

#if RT_POLYGON_RUNS
/* Can no edge with both ends in the box [lo, hi] count? When every vertex in it has v on
 * the same side of 0 (no edge straddles v = 0), or u below 0 (an edge that straddles
 * meets v = 0 at u < 0, which the +u ray does not reach). The box's corners with the
 * least and most v, and the one with the most u, chosen by the signs of the terms: every
 * step of u's and v's arithmetic (a difference, a product by a fixed factor, in each
 * type's rounding) is monotonic, so no vertex in the box computes a value beyond theirs,
 * and a run passed over here is one whose every edge crossings() would have passed over. */
static int run_passes(vec3 lo, vec3 hi, const ray_frame *f, int z)
{
	vec3 l = frame_axes(lo, z), h = frame_axes(hi, z);
	real least = real_cross_unit(f->dz, f->dz >= 0 ? l.y : h.y, f->dy, f->dy >= 0 ? h.z : l.z) -
		     f->v_origin;
	real most = real_cross_unit(f->dz, f->dz >= 0 ? h.y : l.y, f->dy, f->dy >= 0 ? l.z : h.z) -
		    f->v_origin;
	return least >= 0 || most < 0 ||
	       real_cross_unit(f->dz, (f->dz >= 0 ? h.x : l.x) - f->origin.x, f->dx,
			       (f->dx >= 0 ? l.z : h.z) - f->origin.z) < 0;
}
#endif

/* The crossings test for one choice of z, so that the compiler makes a copy for each
 * with the axes fixed. With s (the vertices being s's pool from `first`), runs of
 * RT_POLYGON_RUN edges whose box lies on one side of v = 0 are passed over at once: a
 * 144-gon's (SPD gears) test costs a third as much. */
static inline int crossings(const vec3 *vertices, int count, const ray_frame *f, int z,
			    const scene *s, int first)
{
	int inside = 0, i = 0, stop;
	vec3 a = frame_axes(vertices[count - 1], z);
	real av = frame_v(f, a);
	do {
#if RT_POLYGON_RUNS
		/* At a run's start (runs start at vertex 1, 1 + RUN, ...: the edge into
		 * vertex 0 starts at the last), pass over each run whose box holds the ends
		 * of the edges into vertices i .. i + RUN - 1 and lets none of them count;
		 * then over the shorter run that ends the polygon, if it has one. */
		if (s && count > RT_POLYGON_RUN && i > 0 && (i - 1) % RT_POLYGON_RUN == 0) {
			int passed = 0;
			while (i < count) {
				int whole = i + RT_POLYGON_RUN <= count;
				int slot = (first + (whole ? i : count - 1)) / RT_POLYGON_RUN;
				if (!run_passes(whole ? s->run_lo[slot] : s->tail_lo[slot],
						whole ? s->run_hi[slot] : s->tail_hi[slot], f, z))
					break;
				i = whole ? i + RT_POLYGON_RUN : count;
				passed = 1;
			}
			if (passed) {
				a = frame_axes(vertices[i - 1], z);
				av = frame_v(f, a);
			}
		}
		/* Then vertex by vertex up to the next run's start. */
		stop = !s ? count : i == 0 ? 1 : i + RT_POLYGON_RUN - (i - 1) % RT_POLYGON_RUN;
		stop = stop < count ? stop : count;
#else
		(void)s;
		(void)first;
		stop = count;
#endif
		for (; i < stop; i++) {
			vec3 b = frame_axes(vertices[i], z);
			real bv = frame_v(f, b);
			/* Crossings (Haines, Graphics Gems IV) of the +u ray from (0, 0),
			 * half-open in v: an edge counts when its ends lie on different sides
			 * of v = 0, an end on it counting as above. Most edges stop here,
			 * before their u is needed. */
			if ((av >= 0) != (bv >= 0) && edge_meets_u_ray(frame_u(f, a), av, frame_u(f, b), bv))
				inside = !inside;
			a = b;
			av = bv;
		}
	} while (RT_POLYGON_RUNS && i < count); /* count >= 1: one pass without runs */
	return inside;
}

#if !RT_FLASH_SHORT
/* crossings() for a triangle, straight through: its three v first, and a triangle all
 * on one side of v = 0 (most that the ray misses) is left before any u. Otherwise two
 * edges straddle, the two of the vertex alone on its side, and each is decided as
 * crossings() decides it (every vertex's u and v the same numbers): the same answer in
 * a third fewer instructions, the loop's bookkeeping gone (SPD tetra and teapot are
 * all triangles). Left out where flash is short. */
static inline int triangle_crossings(const vec3 *vertices, const ray_frame *f, int z)
{
	vec3 a = frame_axes(vertices[0], z), b = frame_axes(vertices[1], z),
	     c = frame_axes(vertices[2], z);
	real av = frame_v(f, a), bv = frame_v(f, b), cv = frame_v(f, c), au, bu, cu;
	int a_up = av >= 0, b_up = bv >= 0, c_up = cv >= 0;
	if (a_up == b_up && b_up == c_up)
		return 0;
	au = frame_u(f, a);
	bu = frame_u(f, b);
	cu = frame_u(f, c);
	/* The edges (c, a), (a, b), (b, c), as crossings() meets them: the parity of those
	 * that count. */
	return ((a_up != c_up && edge_meets_u_ray(cu, cv, au, av)) ^
		(a_up != b_up && edge_meets_u_ray(au, av, bu, bv)) ^
		(b_up != c_up && edge_meets_u_ray(bu, bv, cu, cv)));
}
#endif

int polygon_outline_crossed(const vec3 *vertices, int count, const ray *r, const scene *s,
			    int first)
{
	ray_frame f = frame_of(r);
	if (count < 1)
		return 0;
#if !RT_FLASH_SHORT
	if (count == 3)
		return f.z == 0	  ? triangle_crossings(vertices, &f, 0)
		       : f.z == 1 ? triangle_crossings(vertices, &f, 1)
				  : triangle_crossings(vertices, &f, 2);
#endif
	/* A polygon of one run or less (a triangle, say) has none to pass over: one pass. */
	if (count <= RT_POLYGON_RUN)
		s = NULL;
	return f.z == 0 ? crossings(vertices, count, &f, 0, s, first)
	       : f.z == 1 ? crossings(vertices, count, &f, 1, s, first)
			  : crossings(vertices, count, &f, 2, s, first);
}

int polygon_contains_ray(const vec3 *vertices, int count, const ray *r)
{
	return polygon_outline_crossed(vertices, count, r, NULL, 0);
}

