/* bvh.h - the bounding volume hierarchy that makes large scenes fast: built once from
 * the loaded scene, beside it (the scene itself stays as loaded), and searched by
 * intersect.c's queries through their accel.
 * Optional at compile time (RT_USE_BVH=0 leaves it out, as the MCU build does: accel is
 * then the scene alone, and nothing calls this).
 * See LICENSE for copyright and licence. */
#ifndef RT_BVH_H
#define RT_BVH_H

#include "shape.h"

/* A node of the bounding volume hierarchy (bvh.c). */
typedef struct {
	vec3 bounds[2]; /* lower and upper corner */
	int start;   /* leaf: first slot in scene.bvh_index; inner: left child (right = start+1) */
	short count; /* leaf: number of objects; 0 marks an inner node */
	short axis;  /* inner: the split axis, for front-to-back traversal */
} bvh_node;

typedef struct {
	/* node_count 0 means no hierarchy (small scenes test every object). index[0 ..
	 * unbounded_count) are objects without finite bounds (planes, open polyhedra),
	 * tested for every ray; the tree's leaves hold the rest. */
	int node_count, unbounded_count;
	bvh_node nodes[2 * RT_MAX_OBJECTS];
	int index[RT_MAX_OBJECTS];
} bvh_tree;

/* Builds the hierarchy of s into t; scenes smaller than RT_BVH_MIN_OBJECTS get none
 * (node_count = 0) and are searched object by object. */
void bvh_build(bvh_tree *t, const scene *s);

/* Nearest hit along r over (0, tmax), through the hierarchy (and the unbounded objects),
 * leaving out object `skip` (-1 for none; see object_can_rehit); fills h (normals not yet
 * faced to the ray) and h->object. */
int bvh_nearest(const scene *s, const bvh_tree *t, const ray *r, int skip, real tmax, hit *h);

/* Light passing along r over (0, tmax), leaving out `skip`: 0 at an opaque blocker, else
 * the product of the kt of the transmitting objects crossed; *blocker gets the opaque
 * blocker, or -1. */
real bvh_transmittance(const scene *s, const bvh_tree *t, const ray *r, int skip, real tmax,
		       int *blocker);
#endif
