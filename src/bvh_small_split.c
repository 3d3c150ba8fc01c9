/* bvh_small_split.c - the exact split of a small run of the build's items (2 to
 * SORTED_MAX, most of a tree's nodes, floating types only): sorted by centre on each axis
 * and every plane between them priced, or for two items compared directly.
 * See LICENSE for copyright and licence. */
#include "bvh_items.h"

#if BVH_WIDE
/* sorted_split for two objects, without its sorts and sweeps: the same numbers compared
 * in the same order, so the same split (the trees of the SPD scenes and of 60,000 random
 * spheres hash the same). On each axis where their centres differ the one plane between
 * them is priced, the object with the lower centre on the left; the two orders add the
 * same two areas' terms in turn, which can round apart, so each is priced as its own.
 * Nodes of two are a third of a million spheres' splits, which took 440 processor cycles
 * each as sorted_split made them, mostly its loops' mispredicted exits. */
static int pair_split(build_item *run, const bvh_item_bounds *node, int *axis_out, bvh_item_bounds child[2])
{
	real2 node_area = box_half_area(bvh_point_vec(node->lo), bvh_point_vec(node->hi));
	const build_item *a = &run[0], *b = &run[1];
	real2 area_a = box_half_area(bvh_point_vec(a->lo), bvh_point_vec(a->hi));
	real2 area_b = box_half_area(bvh_point_vec(b->lo), bvh_point_vec(b->hi));
	bvh_point centre_a = item_centre(a), centre_b = item_centre(b);
	real cost[2], best_cost = REAL_MAX;
	int best_axis = -1, b_first = 0, axis;
	cost[0] = split_cost(area_a, 1, area_b, 1, node_area);
	cost[1] = split_cost(area_b, 1, area_a, 1, node_area);
	for (axis = 0; axis < 3; axis++) {
		centre_coord ka = point_get(centre_a, axis), kb = point_get(centre_b, axis);
		int swapped = kb < ka;
		if (!(ka < kb) && !swapped)
			continue; /* equal centres (or NaN): no plane */
		if (cost[swapped] < best_cost) {
			best_cost = cost[swapped];
			best_axis = axis;
			b_first = swapped;
		}
	}
	if (leaf_is_better(best_axis, best_cost, 2))
		return 0;
	if (b_first) {
		build_item swap = run[0];
		run[0] = run[1];
		run[1] = swap;
	}
	child[0] = items_bounds_of(run, 1);
	child[1] = items_bounds_of(run + 1, 1);
	*axis_out = best_axis;
	return 1;
}

/* sah_split for a node of at most SORTED_MAX objects: the objects are sorted by centre
 * on each axis, every plane between two different centres is priced, and the objects
 * are put in the best axis's order with the first `left` going left. */
static int sorted_split(build_item *run, int count, const bvh_item_bounds *node, int *axis_out,
			bvh_item_bounds child[2])
{
	real2 node_area = box_half_area(bvh_point_vec(node->lo), bvh_point_vec(node->hi));
	int order[3][SORTED_MAX];
	real best_cost = REAL_MAX;
	int best_axis = -1, best_left = 0, axis, i, j;
	build_item sorted[SORTED_MAX];
	if (count < 2 || count > SORTED_MAX)
		return 0; /* (never: sah_split sends only 2 .. SORTED_MAX) */
	for (axis = 0; axis < 3; axis++) {
		centre_coord key[SORTED_MAX] = {0}; /* (set before read; the lint cannot tell) */
		real2 right_area[SORTED_MAX];
		bvh_point run_lo, run_hi;
		/* Insertion sort: stable, and at this size the quickest. */
		for (i = 0; i < count; i++) {
			centre_coord k = point_get(item_centre(&run[i]), axis);
			for (j = i; j > 0 && key[j - 1] > k; j--) {
				key[j] = key[j - 1];
				order[axis][j] = order[axis][j - 1];
			}
			key[j] = k;
			order[axis][j] = i;
		}
		points_empty(&run_lo, &run_hi);
		for (i = count - 1; i > 0; i--) {
			const build_item *o = &run[order[axis][i]];
			points_grow(&run_lo, &run_hi, &o->lo, &o->hi);
			right_area[i] = box_half_area(bvh_point_vec(run_lo), bvh_point_vec(run_hi));
		}
		points_empty(&run_lo, &run_hi);
		for (i = 0; i < count - 1; i++) {
			const build_item *o = &run[order[axis][i]];
			real cost;
			real2 left_area;
			points_grow(&run_lo, &run_hi, &o->lo, &o->hi);
			/* Equal centres stay together, as in a bin. */
			if (!(key[i] < key[i + 1]))
				continue;
			left_area = box_half_area(bvh_point_vec(run_lo), bvh_point_vec(run_hi));
			cost = split_cost(left_area, i + 1, right_area[i + 1], count - i - 1,
					  node_area);
			if (cost < best_cost) {
				best_cost = cost;
				best_axis = axis;
				best_left = i + 1;
			}
		}
	}
	if (leaf_is_better(best_axis, best_cost, count))
		return 0;
	for (i = 0; i < count; i++)
		sorted[i] = run[order[best_axis][i]];
	for (i = 0; i < count; i++)
		run[i] = sorted[i];
	child[0] = items_bounds_of(run, best_left);
	child[1] = items_bounds_of(run + best_left, count - best_left);
	*axis_out = best_axis;
	return best_left;
}

int bvh_small_split(build_item *run, int count, const bvh_item_bounds *node, int *axis_out,
		    bvh_item_bounds child[2])
{
	return count == 2 ? pair_split(run, node, axis_out, child)
			  : sorted_split(run, count, node, axis_out, child);
}
#endif
