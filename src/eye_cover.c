/* eye_cover.c - which eye rays can meet anything at all (eye_cover.h).
 *
 * A point x ahead of the eye (x . forward > 0, x taken from the eye) is seen across the
 * image plane at u = (x . across) / (x . forward); the points of a box wholly ahead are
 * seen within the span of its eight corners' u (a ratio of linear functions with a
 * positive denominator is extreme at a vertex), and an eye ray with direction d at u of
 * d. An eye ray that meets an object passes the hierarchy's test of one of its top boxes
 * (the wide tree's lanes a few levels down): so that box lies near the plane of the ray's
 * image line (through the eye, holding the line's rays), and the ray is seen within (or,
 * after every rounding, next to) the box's span. A ray seen outside the spans of all the
 * boxes near its line's plane meets nothing.
 *
 * The spans are widened for the roundings: the wide tree's test lets a ray pass a box it
 * misses by up to about 2^-20 of the distance (WIDE_SLACK; the binary tree's test, for
 * the few rays the wide one leaves to it, by far less), which moves the point seen by that
 * over the box's nearest depth, and the ray's own u is a few roundings off. A box not
 * wholly ahead of the eye by a margin may be seen anywhere. The rays of a line lie in
 * its plane to about 2^-20 (the camera squares its right to its view: an up within a
 * rounding of the view direction would tilt them off it), far within the reach allowed.
 * See LICENSE for copyright and licence. */
#include "eye_cover.h"

#if EYE_COVER
#include <float.h>
#include <string.h>

#define COVER_SLACK (REAL_C(1.0) / 131072) /* 2^-17: eight times the wide test's 2^-20 */
#define COVER_ROUNDING (REAL_C(1.0) / 65536) /* the ray's own (u, v), many times over */
/* A box counts for a line when it lies within COVER_PLANE of the distance from its
 * plane: the camera's lines hold their rays to about 2^-20 (camera.c, CAMERA_LEAN). */
#define COVER_PLANE (REAL_C(1.0) / 1024)

/* A lane of a wide node. */
typedef struct {
	int node, lane;
} top_lane;

/* Appends node's non-empty lanes to list[*count ..] (counting past `room` without
 * storing). */
static void add_lanes(const bvh_tree *t, int node, top_lane *list, int *count, int room)
{
	int k;
	for (k = 0; k < WIDE_LANES; k++) {
		if (t->wide[node].child[k] < 0 && !t->wide[node].count[k])
			continue; /* empty */
		if (*count < room) {
			list[*count].node = node;
			list[*count].lane = k;
		}
		(*count)++;
	}
}

/* The top boxes: the root's lanes, each level's inner lanes replaced by their nodes' lanes
 * while all of the next level fits. Their corners (float, rounded outwards) go to lo, hi. */
static int top_boxes(const bvh_tree *t, vec3 lo[EYE_COVER_BOXES], vec3 hi[EYE_COVER_BOXES])
{
	top_lane list[EYE_COVER_BOXES], next[EYE_COVER_BOXES];
	int count = 0, level, i;
	add_lanes(t, 0, list, &count, EYE_COVER_BOXES);
	for (level = 0; level < 4 && count <= EYE_COVER_BOXES; level++) {
		int opened = 0, next_count = 0;
		for (i = 0; i < count; i++) {
			const bvh_wide_node *n = &t->wide[list[i].node];
			if (n->count[list[i].lane]) { /* a leaf lane stays */
				if (next_count < EYE_COVER_BOXES)
					next[next_count] = list[i];
				next_count++;
			} else {
				add_lanes(t, n->child[list[i].lane], next, &next_count, EYE_COVER_BOXES);
				opened = 1;
			}
		}
		if (!opened || next_count > EYE_COVER_BOXES)
			break;
		count = next_count;
		memcpy(list, next, sizeof list[0] * (size_t)count);
	}
	for (i = 0; i < count; i++) {
		const bvh_wide_node *n = &t->wide[list[i].node];
		int k = list[i].lane;
		lo[i] = vec_make((real)n->box[0][k], (real)n->box[2][k], (real)n->box[4][k]);
		hi[i] = vec_make((real)n->box[1][k], (real)n->box[3][k], (real)n->box[5][k]);
	}
	return count;
}

static real sum_abs(vec3 a)
{
	return real_fabs(a.x) + real_fabs(a.y) + real_fabs(a.z);
}

/* How far a . x ranges either side of a . centre over the box centre +- half. */
static real box_extent(vec3 a, vec3 half)
{
	return real_fabs(a.x) * half.x + real_fabs(a.y) * half.y + real_fabs(a.z) * half.z;
}

/* The least of a . x over the box centre +- half. */
static real box_least(vec3 a, vec3 centre, vec3 half)
{
	return vec_dot(a, centre) - box_extent(a, half);
}

void eye_cover_init(eye_cover *c, const accel *a, int eye_in_medium)
{
	const scene *s = accel_scene(a);
	const bvh_tree *t = accel_tree(a);
	const view *v = &s->camera;
	vec3 lo[EYE_COVER_BOXES], hi[EYE_COVER_BOXES];
	real far = REAL_C(0.0), slack;
	int i, corner;
	c->enabled = 0;
	c->line_count = 0;
	c->line_whole = 1;
	if (!t || !BVH_WIDE || t->unbounded_count > 0 || eye_in_medium)
		return;
	c->eye = v->from;
	c->forward = vec_sub(v->at, v->from);
	c->across = vec_cross(c->forward, v->up);
	if (!(vec_dot(c->forward, c->forward) > 0) || !(vec_dot(c->across, c->across) > 0))
		return;
	c->forward = dir_to_vec(dir_normalize(c->forward));
	c->across = dir_to_vec(dir_normalize(c->across));
	/* The camera's eye rays are seen across within tan(angle / 2). */
	c->image_half = real_tan_degrees(real_mul(v->angle, REAL_C(0.5)));
	if (!(c->image_half < REAL_MAX))
		return;
	c->box_count = top_boxes(t, lo, hi);
	for (i = 0; i < c->box_count; i++) {
		c->centre[i] = vec_sub(vec_scale(vec_add(lo[i], hi[i]), REAL_C(0.5)), c->eye);
		c->half[i] = vec_scale(vec_sub(hi[i], lo[i]), REAL_C(0.5));
		far = real_max(far, sum_abs(c->centre[i]) + sum_abs(c->half[i]));
	}
	/* Boxes at float's limit, or a scene so far out that its roundings are not small. */
	if (!(far < REAL_C(1e30)) || !(sum_abs(c->eye) < REAL_C(1e30)))
		return;
	/* How far a ray that passes a box's test may miss it, and a point's rounding. */
	slack = COVER_SLACK * far + REAL_C(64.0) * REAL_EPSILON * (sum_abs(c->eye) + far) +
		REAL_C(16.0) * (real)FLT_MIN;
	c->plane_reach = slack + COVER_PLANE * far;
	for (i = 0; i < c->box_count; i++) {
		real depth = box_least(c->forward, c->centre[i], c->half[i]);
		real lowest = REAL_MAX, highest = -REAL_MAX, size, widen;
		if (!(depth > REAL_C(16.0) * slack && depth > far / 1024)) {
			/* Not wholly ahead by a margin: seen anywhere. */
			c->span_lo[i] = -REAL_MAX;
			c->span_hi[i] = REAL_MAX;
			continue;
		}
		for (corner = 0; corner < 8; corner++) {
			vec3 x = vec_add(c->centre[i],
					 vec_make(corner & 1 ? c->half[i].x : -c->half[i].x,
						  corner & 2 ? c->half[i].y : -c->half[i].y,
						  corner & 4 ? c->half[i].z : -c->half[i].z));
			real u = vec_dot(x, c->across) / vec_dot(x, c->forward);
			lowest = real_min(lowest, u);
			highest = real_max(highest, u);
		}
		size = REAL_C(1.0) + real_max(real_fabs(lowest), real_fabs(highest));
		widen = REAL_C(4.0) * slack * size / depth + COVER_ROUNDING * size;
		c->span_lo[i] = lowest - widen;
		c->span_hi[i] = highest + widen;
	}
	c->enabled = 1;
	eye_cover_line(c, dir_make(UNIT_C(0.0), UNIT_C(0.0), UNIT_C(0.0)));
}

void eye_cover_line(eye_cover *c, dir3 n)
{
	vec3 normal = dir_to_vec(n);
	real covered;
	int i, j, count = 0;
	c->line_count = 0;
	c->line_whole = 1;
	if (!c->enabled)
		return;
	for (i = 0; i < c->box_count; i++) {
		real lo = c->span_lo[i], hi = c->span_hi[i];
		/* A box wholly on one side of the plane (by more than the reach) holds none
		 * of the line's hits: its centre farther from the plane than its extent
		 * across it and the reach (the same numbers on either side: a negation
		 * rounds as the value it negates). */
		if (real_fabs(vec_dot(normal, c->centre[i])) - box_extent(normal, c->half[i]) >
		    c->plane_reach)
			continue;
		/* Into the ordered spans, joining those it overlaps. */
		for (j = count; j > 0 && c->line_lo[j - 1] > lo; j--) {
			c->line_lo[j] = c->line_lo[j - 1];
			c->line_hi[j] = c->line_hi[j - 1];
		}
		c->line_lo[j] = lo;
		c->line_hi[j] = hi;
		count++;
	}
	/* Join overlapping spans. */
	for (i = 0, j = 0; i < count; i++) {
		if (j > 0 && c->line_lo[i] <= c->line_hi[j - 1]) {
			c->line_hi[j - 1] = real_max(c->line_hi[j - 1], c->line_hi[i]);
			continue;
		}
		c->line_lo[j] = c->line_lo[i];
		c->line_hi[j] = c->line_hi[i];
		j++;
	}
	c->line_count = j;
	/* A line whose spans leave little of the image uncovered is searched ray by ray:
	 * the test costs a sixth of what a ray it spares costs, so it pays from a quarter. */
	for (i = 0, covered = REAL_C(0.0); i < j; i++)
		covered += real_max(REAL_C(0.0), real_min(c->line_hi[i], c->image_half) -
							 real_max(c->line_lo[i], -c->image_half));
	c->line_whole = covered > REAL_C(1.5) * c->image_half;
}
#endif
