/* bvh_traverse.h - the search of the hierarchy, front to back with a fixed stack,
 * shrinking the search as hits are found; shadow rays stop at the first opaque blocker.
 * Included by bvh.c once for each instruction set it searches the wide tree with:
 * TRAVERSE names the function, WIDE_HIT the wide node test it uses, WIDE_PREPARE what
 * that test needs made once a ray (its wide_ray given) and TRAVERSE_TARGET
 * the instruction set it is compiled for (empty: the program's own).
 * See LICENSE for copyright and licence. */

/* The two queries share one traversal (`shadow` says which). Nearest: the closest hit,
 * shrinking tmax as hits are found, children visited nearest first. Shadow: the product
 * of the kt of every transmitting object crossed, stopping at the first opaque one
 * (*found gets it, or -1), taken again in the objects' order where that matters (three
 * or more: transmittance_in_order). */
static TRAVERSE_TARGET TRAVERSE_INLINE real TRAVERSE(const scene *s, const bvh_tree *t,
						     const ray *r, int skip, real tmax, hit *h,
						     int shadow, int *found)
{
	int top, i;
	real pass = REAL_C(1.0), enter;
	crossing crossed; /* the transmitting objects a shadow ray crosses */
	slab_ray sr;
#if BVH_WIDE
	wide_ray wr;
#endif

	*found = shadow ? -1 : 0;
	crossed.count = 0;
	/* Visits object `o` for a shadow ray: returns at an opaque blocker. */
#define VISIT_SHADOW(o)                                                                       \
	do {                                                                                  \
		int visit_ = (o);                                                             \
		if (visit_ != skip && object_intersect(s, visit_, r, REAL_C(0.0), tmax, NULL)) { \
			real kt_ = s->materials[s->objects[visit_].material].kt;            \
			if (kt_ <= REAL_C(0.0)) {                                             \
				*found = visit_;                                              \
				return REAL_C(0.0);                                           \
			}                                                                     \
			pass = real_mul(pass, kt_);                                           \
			crossing_add(&crossed, visit_);                                       \
		}                                                                             \
	} while (0)
	/* A search's answer: a shadow ray's product, in the objects' order where three or
	 * more were crossed (one or two kt give the same product in any order). */
#define SHADOW_PASS()                                                                         \
	(shadow && crossed.count > 2 ? transmittance_in_order(s, &crossed) : pass)
	/* Visits object `o` for a nearest-hit query: shrinks tmax to a nearer hit. */
#define VISIT_NEAREST(o)                                                                      \
	do {                                                                                  \
		int visit_ = (o);                                                             \
		if (visit_ == skip) /* the object the ray leaves and cannot meet again */     \
			break;                                                                \
		if (*found && visit_ < h->object) {                                           \
			/* A hit at the same distance as the nearest so far goes to the lower  \
			 * index, as in the search object by object: coincident surfaces      \
			 * then look the same whatever order the tree meets them in. */        \
			hit tie_;                                                             \
			if (object_intersect(s, visit_, r, REAL_C(0.0), real_step_up(tmax),   \
					     &tie_) &&                                        \
			    tie_.t <= tmax) {                                                 \
				*h = tie_;                                                    \
				tmax = h->t;                                                  \
				h->object = visit_;                                           \
			}                                                                     \
		} else if (object_intersect(s, visit_, r, REAL_C(0.0), tmax, h)) {           \
			tmax = h->t;                                                          \
			h->object = visit_;                                                   \
			*found = 1;                                                           \
		}                                                                             \
	} while (0)
#define VISIT(o)                                                                              \
	do {                                                                                  \
		if (shadow)                                                                   \
			VISIT_SHADOW(o);                                                      \
		else                                                                          \
			VISIT_NEAREST(o);                                                     \
	} while (0)
	/* Visits a wide leaf lane's objects (`count` of them from slot `child` of the index,
	 * or with count WIDE_ONE_OBJECT the object `child`), then narrows the float limit to
	 * the nearest hit. */
#define VISIT_LEAF(child, count)                                                              \
	do {                                                                                  \
		int leaf_ = (child), count_ = (count);                                        \
		if (count_ == WIDE_ONE_OBJECT)                                                \
			VISIT(leaf_);                                                         \
		else                                                                          \
			for (i = leaf_; i < leaf_ + count_; i++)                              \
				VISIT(t->index[i]);                                           \
		if (!shadow)                                                                  \
			limit = wide_limit(tmax);                                             \
	} while (0)

	for (i = 0; i < t->unbounded_count; i++)
		VISIT(t->index[i]);
#if BVH_WIDE
	if (t->node_count && wide_ray_make(&wr, r)) {
		/* Each node pushes at most all lanes but one (that one is searched at once). */
		struct {
			int child, count; /* a wide node (count 0) or a leaf's objects */
			float enter;
		} wide_stack[(WIDE_LANES - 1) * (BVH_MAX_DEPTH + 1) + 2];
		float limit = wide_limit(tmax);
		int current = -1; /* the wide node to search next; -1: take one from the stack */
		WIDE_PREPARE(&wr);
		wide_stack[0].child = 0; /* the root */
		wide_stack[0].count = 0;
		wide_stack[0].enter = 0.0f;
		top = 1;
		for (;;) {
			const bvh_wide_node *node;
			float lane_enter[WIDE_LANES];
			int order[WIDE_LANES], k, mask, near;
			if (current < 0) {
				if (top == 0)
					break;
				top--;
				/* A nearer hit found since this entry was pushed may make it
				 * pointless; the entry may be computed a few roundings late (the
				 * box of a patch met at the very distance of the nearest hit). */
				if (!shadow && (real)wide_stack[top].enter > tmax * (real)WIDE_SLACK)
					continue;
				if (wide_stack[top].count) {
					VISIT_LEAF(wide_stack[top].child, wide_stack[top].count);
					continue;
				}
				current = wide_stack[top].child;
			}
			node = &t->wide[current];
			mask = WIDE_HIT(node, &wr, limit, lane_enter);
			current = -1;
			if (!mask)
				continue;
			if (shadow) {
				/* Any blocker ends the search, so the lanes are taken as they
				 * come: leaves at once, one inner lane next, the rest later. */
				for (; mask; mask &= mask - 1) {
					int lane = lowest_lane[mask];
					int child = node->child[lane], count = node->count[lane];
					if (!count) {
						if (current >= 0) {
							wide_stack[top].child = current;
							wide_stack[top].count = 0;
							wide_stack[top++].enter = 0.0f;
						}
						current = child;
					} else if (count == WIDE_ONE_OBJECT) {
						VISIT_SHADOW(child);
					} else {
						for (i = child; i < child + count; i++)
							VISIT_SHADOW(t->index[i]);
					}
				}
				continue;
			}
			/* The lanes entered, farthest first: all but the nearest wait on the
			 * stack, the nearest is searched now. */
			for (k = 0; mask; mask &= mask - 1)
				order[k++] = lowest_lane[mask];
			for (i = 1; i < k; i++) {
				int lane = order[i], j;
				for (j = i; j > 0 && lane_enter[order[j - 1]] < lane_enter[lane]; j--)
					order[j] = order[j - 1];
				order[j] = lane;
			}
			for (i = 0; i < k - 1; i++) {
				wide_stack[top + i].child = node->child[order[i]];
				wide_stack[top + i].count = node->count[order[i]];
				wide_stack[top + i].enter = lane_enter[order[i]];
			}
			top += k - 1;
			near = order[k - 1];
			if (!node->count[near])
				current = node->child[near];
			else
				VISIT_LEAF(node->child[near], node->count[near]);
		}
		return SHADOW_PASS();
	}
#endif
	sr.origin = r->origin;
	sr.inv = vec_make(real_div_unit(REAL_C(1.0), r->dir.x), real_div_unit(REAL_C(1.0), r->dir.y),
			  real_div_unit(REAL_C(1.0), r->dir.z));
	sr.near_x = sr.inv.x < REAL_C(0.0);
	sr.near_y = sr.inv.y < REAL_C(0.0);
	sr.near_z = sr.inv.z < REAL_C(0.0);
	sr.dir = r->dir;
	sr.divided = REAL_SATURATES && !(real_fabs(sr.inv.x) < RECIPROCAL_LIMIT &&
					 real_fabs(sr.inv.y) < RECIPROCAL_LIMIT &&
					 real_fabs(sr.inv.z) < RECIPROCAL_LIMIT);
#if BVH_WIDE
	if (t->node_count) {
		/* A ray beyond the float test's reach (wide_ray_make: an origin beyond 2^100,
		 * a direction component below 2^-100 other than 0): the same wide tree, each
		 * lane's box tested in reals as box_hit tests any box, and the lanes entered
		 * searched as they come. */
		int wide_stack[(WIDE_LANES - 1) * (BVH_MAX_DEPTH + 1) + 2], lane;
		float limit = 0.0f; /* VISIT_LEAF narrows it; no float test reads it here */
		wide_stack[0] = 0; /* the root */
		top = 1;
		while (top > 0) {
			const bvh_wide_node *node = &t->wide[wide_stack[--top]];
			for (lane = 0; lane < WIDE_LANES && node->child[lane] >= 0; lane++) {
				bvh_point box[2];
				bvh_lane_box(node, lane, box);
				if (!box_hit(box, &sr, tmax, &enter))
					continue;
				if (node->count[lane])
					VISIT_LEAF(node->child[lane], node->count[lane]);
				else
					wide_stack[top++] = node->child[lane];
			}
		}
		(void)limit;
	}
#else
	{
		struct {
			int node;
			real enter;
		} stack[STACK_SIZE];
		real enter0, enter1;
		top = 0;
		if (t->node_count && box_hit(t->nodes[0].bounds, &sr, tmax, &enter)) {
			stack[0].node = 0;
			stack[0].enter = enter;
			top = 1;
		}
		while (top > 0) {
			const bvh_node *n;
			top--;
			/* A nearer hit found since this node was pushed may make it pointless. */
			if (!shadow && stack[top].enter > (REAL_SATURATES ? tmax : tmax * BOX_SLACK))
				continue;
			n = &t->nodes[stack[top].node];
			if (n->count) {
				for (i = 0; i < n->count; i++)
					VISIT(t->index[n->start + i]);
			} else {
				/* Test both children here and push only those the ray enters, the
				 * nearer one last so that it is searched first. */
				int hit0 = box_hit(t->nodes[n->start].bounds, &sr, tmax, &enter0);
				int hit1 = box_hit(t->nodes[n->start + 1].bounds, &sr, tmax, &enter1);
				if (hit0 && hit1) {
					int near = enter0 <= enter1 ? 0 : 1;
					stack[top].node = n->start + !near;
					stack[top++].enter = near ? enter0 : enter1;
					stack[top].node = n->start + near;
					stack[top++].enter = near ? enter1 : enter0;
				} else if (hit0 || hit1) {
					stack[top].node = n->start + (hit0 ? 0 : 1);
					stack[top++].enter = hit0 ? enter0 : enter1;
				}
			}
		}
	}
#endif
#undef VISIT
#undef VISIT_LEAF
#undef VISIT_NEAREST
#undef VISIT_SHADOW
	return SHADOW_PASS();
#undef SHADOW_PASS
}

#undef TRAVERSE
#undef TRAVERSE_TARGET
#undef WIDE_HIT
#undef WIDE_PREPARE
