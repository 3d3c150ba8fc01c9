/* config.h - rt's static capacities and compile-time limits.
 * Every array in rt is sized here; nothing is allocated at run time.
 * See LICENSE for copyright and licence. */
#ifndef RT_CONFIG_H
#define RT_CONFIG_H

#include <stdint.h>

/* Each capacity may be overridden with -DNAME=value (the MCU build shrinks them).
 * Exceeding one at run time is a clear error that names the macro to raise. */

/* Scene capacities in millions on 64-bit hosts: 4 M primitives, their vertices and
 * planes (bss costs nothing until a scene touches it), 2.2 GiB of address space in
 * double, past the 2 GiB of x86-64's default code model (the Makefile builds with the
 * medium model there). A 32-bit host keeps half as many objects, a third of the
 * vertices and a quarter of the planes, which its address space holds. */
#define RT_HOST_64 (SIZE_MAX > 0xFFFFFFFFu)
#ifndef RT_MAX_OBJECTS
#define RT_MAX_OBJECTS (RT_HOST_64 ? 4194304 : 2097152) /* primitives in a scene */
#endif
#ifndef RT_MAX_LIGHTS
#define RT_MAX_LIGHTS 64 /* point lights */
#endif
#ifndef RT_MAX_MATERIALS
#define RT_MAX_MATERIALS 1024 /* distinct `f` materials (repeats share one slot) */
#endif
#ifndef RT_MAX_VERTICES
#define RT_MAX_VERTICES (RT_HOST_64 ? 12582912 : 4194304) /* polygon and patch vertices, all polygons together: 4 M triangles */
#endif
#ifndef RT_MAX_POLY_VERTS
#define RT_MAX_POLY_VERTS 1024 /* vertices of one polygon (SPD gears needs 144) */
#endif
#ifndef RT_MAX_PLANES
#define RT_MAX_PLANES (RT_HOST_64 ? 4194304 : 1048576) /* bounding planes, all polyhedra together */
#endif
#ifndef RT_MAX_HEDRON_PLANES
#define RT_MAX_HEDRON_PLANES 64 /* planes of one polyhedron */
#endif
#ifndef RT_MAX_WIDTH
#define RT_MAX_WIDTH 8192 /* image width in pixels (row buffers are this wide) */
#endif
#ifndef RT_MAX_HEIGHT
#define RT_MAX_HEIGHT 8192 /* image height in pixels */
#endif
/* The largest `resolution` a scene may ask for. The same as the image's capacity on a
 * host; the MCU build reads 320x240 scenes and renders them at the size -s gives. */
#ifndef RT_MAX_SCENE_WIDTH
#define RT_MAX_SCENE_WIDTH RT_MAX_WIDTH
#endif
#ifndef RT_MAX_SCENE_HEIGHT
#define RT_MAX_SCENE_HEIGHT RT_MAX_HEIGHT
#endif
#ifndef RT_MAX_DEPTH
#define RT_MAX_DEPTH 8 /* ray tree levels, eye ray = level 1; bounds the recursion */
#endif
#ifndef RT_MAX_MEDIA
#define RT_MAX_MEDIA 8 /* nested transmitting objects a ray can be inside at once */
#endif
#ifndef RT_MAX_JOBS
#define RT_MAX_JOBS 64 /* processes a render runs at once (-j): the parent and its workers */
#endif
#ifndef RT_PARALLEL_POOL
/* -j's pool, in colours (and as many ids), which holds the window: four lines a process
 * and two more, of the image's width (twice that with -a); mapped shared with the workers,
 * and touched only as far as the window needs. 2^20 holds 64 processes to 4,000 pixels
 * wide, 31 at 8,192. */
#define RT_PARALLEL_POOL (1L << 20)
#endif
#ifndef RT_READ_BUFFER
/* Bytes the lexer takes from a scene file at a time; 0 reads byte by byte through the
 * source's read function (the MCU, whose RAM is short). */
#define RT_READ_BUFFER 4096
#endif
#ifndef RT_TOKEN_MAX
#define RT_TOKEN_MAX 64 /* longest token in a scene file, in bytes */
#endif

/* Cones and cylinders (NFF `c`); 0 leaves them out, for a small target whose flash is
 * short (a scene with one is then refused, naming this switch). */
#ifndef RT_SHAPE_CONE
#define RT_SHAPE_CONE 1
#endif

/* Patches (NFF `pp`: polygons shaded by their vertex normals); 0 leaves them out, for a
 * small target whose flash and RAM are short (the vertex normals' pool goes too; a scene
 * with a patch is then refused, naming this switch). */
#ifndef RT_SHAPE_PATCH
#define RT_SHAPE_PATCH 1
#endif
#define RT_PATCH_VERTICES (RT_SHAPE_PATCH ? RT_MAX_VERTICES : 1) /* the patch pools' size */

/* The classic colour pipeline (`colours classic`, --colours); 0 leaves it out where flash
 * is short (the command is then refused). */
#ifndef RT_COLOUR_PIPELINES
#define RT_COLOUR_PIPELINES 1
#endif

/* Runs of a big polygon's edges skipped at once by the inside test (their box on one
 * side of the ray's plane, scene.h); 0 leaves the boxes and their pool out (the MCU's
 * polygons are small). */
#ifndef RT_POLYGON_RUNS
#define RT_POLYGON_RUNS 1
#endif
#define RT_POLYGON_RUN 16 /* edges in a run */

/* Buckets of the sRGB encoder's table (colour.c), a power of two: the host's 4,096 make
 * encoding a step or two; the MCU's 256 save its RAM. The bytes are the same. */
#ifndef RT_COLOUR_STEPS
#define RT_COLOUR_STEPS 4096
#endif
/* Whether a pixel of its left neighbour's colour takes that one's codes without encoding
 * (colour.c): a few percent of a scene with much background; 0 saves the MCU its flash. */
#ifndef RT_COLOUR_REPEATS
#define RT_COLOUR_REPEATS 1
#endif

/* The ANSI colour previews; 0 leaves them out (ASCII only) where flash is short. */
#ifndef RT_PREVIEW_COLOR
#define RT_PREVIEW_COLOR 1
#endif

#ifndef RT_CORNER_SAMPLING
#define RT_CORNER_SAMPLING 1 /* --spd's corner rays (a second row buffer); 0 leaves them out */
#endif

#ifndef RT_USE_BVH
#define RT_USE_BVH 1 /* bounding volume hierarchy for large scenes; 0 leaves it out */
#endif
/* Three checks the build with the hierarchy makes and the MCU's, which has none, leaves
 * out for flash (docs/mcu.md): a grazing ray's hit beyond a polygon's box is none
 * (polygon.c), a polyhedron's entry at the very distance of the nearest hit so far is
 * no nearer hit (hedron.c), and each image line forgets the shadow rays' remembered
 * blockers (trace.c). A host build without the hierarchy keeps them with
 * -DRT_HOST_CHECKS=1, and then searches object by object exactly as the tree does
 * (build/rt-no-tree, tests/tree.sh). */
#ifndef RT_HOST_CHECKS
#define RT_HOST_CHECKS RT_USE_BVH
#endif
#ifndef RT_BVH_MIN_OBJECTS
#define RT_BVH_MIN_OBJECTS 12 /* scenes with fewer objects test them all: cheaper */
#endif

/* Algorithm choices, for measuring what robustness costs (tools/speed-vs-error, naive.h):
 * RT_NAIVE names at most one naive form the literature warns about; 0 (the default) is
 * the robust code throughout. */
#define RT_NAIVE_SPHERE 1 /* b^2 - 4ac and -b +- sqrt, not Hearn & Baker + stable roots */
#define RT_NAIVE_HEDRON 2 /* hit a face plane, then test the point against the others */
#define RT_NAIVE_OFFSET 3 /* secondary rays start 1e-4 off the surface, whatever its scale */
#ifndef RT_NAIVE
#define RT_NAIVE 0
#endif

#define RT_DEFAULT_DEPTH 5 /* SPD's testing procedure uses 5 levels */

/* Compile-time check (C99 has no static_assert): a negative array size fails to compile. */
/* Turns a macro's value into a string literal. */
#define RT_STRINGIFY_(x) #x
#define RT_STRINGIFY(x) RT_STRINGIFY_(x)

#define RT_STATIC_ASSERT(name, cond) typedef char rt_assert_##name[(cond) ? 1 : -1]

#endif
