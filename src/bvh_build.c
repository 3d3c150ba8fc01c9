/* bvh_build.c - builds the bounding volume hierarchy over the scene's objects, in static
 * arrays, once after parsing: a binary tree of the splits bvh_split.c makes, which fixed
 * point keeps and the floating-point types collapse, as its nodes are made, into nodes of
 * WIDE_LANES children whose float boxes bvh.c tests several at once.
 * See LICENSE for copyright and licence. */
#include "bvh.h"

#include "box.h"
#include "bvh_split.h"
#include "intersect.h"
#include "pages.h"

RT_STATIC_ASSERT(node_count_fits, 2 * (long)RT_MAX_OBJECTS < 2147483647L);

#if BVH_WIDE
/* A lane of a wide node being built: a subtree of the binary tree the splits make, which
 * is never stored (fixed point searches it; the floating types search only the wide
 * tree, and writing it took a quarter of a million spheres' memory): items[first ..
 * first+count), their bounds and their box's area, the node's depth in the binary tree,
 * and its split, made as the lane is made (left 0: a leaf). */
typedef struct {
	bvh_item_bounds bounds, child[2];
	real2 area;
	int first, count, depth, left;
} wide_lane;

/* Makes lane l of items[first .. first+count), whose bounds are b, at binary depth
 * `depth`, and splits it; t counts the binary nodes the splits make. */
static void lane_make(bvh_tree *t, wide_lane *l, int first, int count, const bvh_item_bounds *b,
		      int depth)
{
	int axis;
	l->bounds = *b;
	l->area = box_half_area(bvh_point_vec(b->lo), bvh_point_vec(b->hi));
	l->first = first;
	l->count = count;
	l->depth = depth;
	l->left = bvh_node_split(first, count, b, depth, &axis, l->child);
	if (l->left)
		t->node_count += 2;
}

/* Lane `side` (0 left, 1 right) of split lane l: its child. */
static void lane_child(bvh_tree *t, wide_lane *child, const wide_lane *l, int side)
{
	if (side)
		lane_make(t, child, l->first + l->left, l->count - l->left, &l->child[1],
			  l->depth + 1);
	else
		lane_make(t, child, l->first, l->left, &l->child[0], l->depth + 1);
}

/* Makes a new wide node of lane `root` (with its subtree); returns its number. The lanes
 * start as root's children (or root itself, a leaf), and the split lane with the largest
 * box is replaced by its two children until there are WIDE_LANES lanes or only leaves:
 * the binary tree's nodes collapsed into nodes of WIDE_LANES children, each split made
 * as its lane is opened. Every split partitions only its own items, so it finds them as
 * a binary build, splitting node by node, would: the same tree. */
static int wide_build(bvh_tree *t, const wide_lane *root)
{
	wide_lane lane[WIDE_LANES];
	int n, i, axis, w = t->wide_count++;
	bvh_wide_node *node = &t->wide[w];
	pages_ahead(t->wide, sizeof t->wide[0], (size_t)w, 1, BVH_WIDE_NODES);
	if (!root->left) {
		lane[0] = *root;
		n = 1;
	} else {
		lane_child(t, &lane[0], root, 0);
		lane_child(t, &lane[1], root, 1);
		n = 2;
	}
	while (n < WIDE_LANES) {
		wide_lane opened;
		int widest = -1;
		for (i = 0; i < n; i++)
			if (lane[i].left && (widest < 0 || lane[i].area > lane[widest].area))
				widest = i;
		if (widest < 0)
			break;
		opened = lane[widest];
		lane_child(t, &lane[widest], &opened, 0);
		lane_child(t, &lane[n++], &opened, 1);
	}
	for (i = 0; i < WIDE_LANES; i++) {
		const wide_lane *l = i < n ? &lane[i] : NULL;
		for (axis = 0; axis < 3; axis++) {
			node->box[2 * axis][i] = l ? (float)bvh_point_get(&l->bounds.lo, axis) : INFINITY;
			node->box[2 * axis + 1][i] = l ? (float)bvh_point_get(&l->bounds.hi, axis) : -INFINITY;
		}
		/* A leaf of one object (most leaves) names the object itself: the search
		 * then skips a load from the index. */
		node->count[i] = !l || l->left ? 0 : l->count == 1 ? WIDE_ONE_OBJECT : l->count;
		node->child[i] = !l	       ? -1
				 : l->left      ? wide_build(t, l)
				 : l->count == 1 ? bvh_item_object(l->first)
						 : l->first;
	}
	return w;
}
#else
/* Fills node `node` for items[first .. first+count), whose bounds are `b`, and recurses
 * into its children. Recursion depth is at most BVH_MAX_DEPTH. */
static void build_node(bvh_tree *t, int node, int first, int count, const bvh_item_bounds *b,
		       int depth)
{
	bvh_node *n = &t->nodes[node];
	bvh_item_bounds child[2];
	int axis, left = bvh_node_split(first, count, b, depth, &axis, child);
	n->bounds[0] = b->lo;
	n->bounds[1] = b->hi;
	if (!left) {
		n->start = first;
		n->count = (short)count;
		n->axis = 0;
		return;
	}
	n->start = t->node_count;
	n->count = 0;
	n->axis = (short)axis;
	pages_ahead(t->nodes, sizeof t->nodes[0], (size_t)t->node_count, 2, 2 * RT_MAX_OBJECTS);
	t->node_count += 2;
	build_node(t, n->start, first, left, &child[0], depth + 1);
	build_node(t, n->start + 1, first + left, count - left, &child[1], depth + 1);
}
#endif

void bvh_build(bvh_tree *t, const scene *s)
{
	int i, boxes = 0; /* items made: the bounded objects' boxes, from items[0] */
	t->node_count = 0;
	t->unbounded_count = 0;
	t->wide_count = 0;
	if (s->object_count < RT_BVH_MIN_OBJECTS)
		return;
	bvh_items_prepare(s->object_count);
	pages_prepare(t->index, (size_t)s->object_count * sizeof t->index[0]);
	for (i = 0; i < s->object_count; i++) {
		const object *o = &s->objects[i];
		vec3 lo, hi;
		real pad;
		int pieces, k;
		if (!(shape_bounds(s, o, &lo, &hi) && vec_is_finite(lo) && vec_is_finite(hi))) {
			t->index[t->unbounded_count++] = i;
			continue;
		}
		/* Pieces only while the boxes so far, these, and one for each object still to
		 * come fit the capacity (which bounds the tree's nodes). */
		pieces = bvh_object_pieces(s, i);
		if (t->unbounded_count + boxes + pieces + (s->object_count - i - 1) >
		    RT_MAX_OBJECTS)
			pieces = 1;
		pad = box_rounding_pad(lo, hi); /* a piece is padded as its whole cone (cone.c) */
		if (pieces == 1) {
			bvh_item_make(boxes++, i, lo, hi, pad);
			continue;
		}
		bvh_items_ahead(boxes, pieces);
		for (k = 0; k < pieces; k++) {
			(void)bvh_piece_bounds(s, i, k, pieces, &lo, &hi);
			bvh_item_make(boxes++, i, lo, hi, pad);
		}
	}
	if (boxes == 0)
		return;
	/* Unbounded objects first in the index, then the boxes the tree is built over: they
	 * move up past the unbounded, from the last down, so that none is overwritten before
	 * it moves; the index takes the items' order when the tree is done. */
	if (t->unbounded_count)
		bvh_items_shift(boxes, t->unbounded_count);
	pages_prepare(t->index, (size_t)(t->unbounded_count + boxes) * sizeof t->index[0]);
	t->node_count = 1;
	{
		bvh_item_bounds all = bvh_items_bounds(t->unbounded_count, boxes);
#if BVH_WIDE
		wide_lane root;
		/* At most n L / (2 (L - 1)) wide nodes for n boxes (bvh.h). */
		pages_plan(t->wide, ((size_t)boxes / 2 + (size_t)boxes / (2 * (WIDE_LANES - 1)) + 1) *
					    sizeof t->wide[0]);
		lane_make(t, &root, t->unbounded_count, boxes, &all, 0);
		(void)wide_build(t, &root);
#else
		/* A tree of n boxes has at most 2n - 1 nodes. */
		pages_plan(t->nodes, 2 * (size_t)boxes * sizeof t->nodes[0]);
		pages_ahead(t->nodes, sizeof t->nodes[0], 0, 1, 2 * RT_MAX_OBJECTS); /* the root */
		build_node(t, 0, t->unbounded_count, boxes, &all, 0);
#endif
	}
	for (i = t->unbounded_count; i < t->unbounded_count + boxes; i++)
		t->index[i] = bvh_item_object(i);
}
