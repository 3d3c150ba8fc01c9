/* bvh_box.h - a ray's tests against the hierarchy's boxes: the binary tree's in reals
 * (slab tests), the wide tree's in float, four or eight boxes at once where the processor
 * can. Included by bvh.c alone, whose searches (bvh_traverse.h) use them.
 * See LICENSE for copyright and licence. */
#ifndef RT_BVH_BOX_H
#define RT_BVH_BOX_H
#include "bvh.h"

#include <stddef.h>

/* SSE (every x86-64, and x86 built for it) tests a wide node's boxes four at a time;
 * other targets take the plain C loop, with the same results. RT_NO_SIMD=1 forces it.
 * Where the compiler can build a function for AVX alone (a target attribute) and the
 * processor has it, the search is a second copy of the traversal built for it, which
 * tests all eight boxes at once: asked at run time, so that the program itself still
 * runs on any x86-64. RT_NO_AVX=1 leaves it out. */
#if BVH_WIDE && defined(__SSE__) && !RT_NO_SIMD
#include <xmmintrin.h>
#define WIDE_SSE 1
#else
#define WIDE_SSE 0
#endif
/* With SSE2 (every x86-64) a double build prepares a ray's three axes at once. */
#if WIDE_SSE && defined(__SSE2__) && defined(RT_REAL_DOUBLE)
#include <emmintrin.h>
#define WIDE_SSE2_RAY 1
#else
#define WIDE_SSE2_RAY 0
#endif
#if WIDE_SSE && WIDE_LANES == 8 && defined(__GNUC__) && \
	(defined(__x86_64__) || defined(__i386__)) && !RT_NO_AVX
#include <cpuid.h>
#include <immintrin.h>
#define WIDE_AVX 1
#define WIDE_AVX_TARGET __attribute__((target("avx")))
#else
#define WIDE_AVX 0
#endif

/* A ray prepared for slab tests: 1/d per axis and, per axis, which box corner it meets
 * first. A zero component must mean an infinite slab, decided by the origin alone:
 * floating point gets that from IEEE's 1/0 = +-inf. In Q16.16 a reciprocal saturates
 * (about 32768 for any component below 2^-15), and a box the ray runs along would be cut
 * short and skipped: every eye ray of the image row and column through the eye's own
 * coordinates, and all rays of a narrow view. So a component whose reciprocal passes
 * RECIPROCAL_LIMIT marks its axis `divided`: its slab distances are quotients, which
 * saturate towards the right infinity, and a zero component's are +-infinity by the
 * origin's side. */
typedef struct {
	vec3 origin, inv;
	int near_x, near_y, near_z; /* 0: the lower bound is entered first, 1: the upper */
	int divided; /* 1 when some axis's distances are divided out (slab_distance) */
	dir3 dir;
} slab_ray;

#define BOX_SLACK (REAL_C(1.0) + REAL_C(16.0) * REAL_EPSILON)

/* Is the slab interval [tnear, tfar] open, allowing for the rounding of its ends? Each
 * end is off by a few roundings of itself: in floating point a few parts in 2^53
 * (double) of the distance, and BOX_SLACK widens the exit by more; in Q16.16 the
 * reciprocal 1/d (|d| <= 1) is off by half a step, 2^-17 of itself at most, and the
 * product by half a step more, so the exit is widened by 2^-15 of itself and two steps.
 * Without it a thin box far from the origin (a tile 0.1 wide at 10^30 in double, a tile
 * at 3,000 in Q16.16) seems to be left before it is entered, and its hit is lost. */
static inline int slab_interval_open(real tnear, real tfar)
{
	if (REAL_SATURATES)
		return tnear <= real_add(tfar, real_add(real_fabs(tfar) / 32768, REAL_EPSILON * 2));
	return tnear <= tfar * BOX_SLACK;
}
#define RECIPROCAL_LIMIT REAL_C(16384.0) /* 1/d for |d| >= 2^-14, well inside Q16.16 */

/* Where the ray meets the plane `offset` past its origin along an axis of direction
 * component d: the quotient, or for d = 0 +-infinity (REAL_MAX) by the side of the
 * origin, a plane through it counting as behind (near) or ahead (far) so that a ray
 * lying in a box's face still enters the box. */
static real slab_distance(real offset, unit d, int far)
{
	if (d == UNIT_C(0.0))
		return offset > 0 || (offset == 0 && far) ? REAL_MAX : -REAL_MAX;
	return real_div_unit(offset, d);
}

/* box_hit's interval for a ray with a divided axis: every distance a quotient. */
static int box_hit_divided(const bvh_point box[2], const slab_ray *r, real tmax, real *tenter)
{
	real tnear = REAL_C(0.0), tfar = tmax;
	int axis;
	for (axis = 0; axis < 3; axis++) {
		int near = axis == 0 ? r->near_x : axis == 1 ? r->near_y : r->near_z;
		unit d = axis == 0 ? r->dir.x : axis == 1 ? r->dir.y : r->dir.z;
		real o = vec_get(r->origin, axis);
		real t0 = slab_distance(real_add(bvh_point_get(&box[near], axis), -o), d, 0);
		real t1 = slab_distance(real_add(bvh_point_get(&box[!near], axis), -o), d, 1);
		tnear = t0 > tnear ? t0 : tnear;
		tfar = t1 < tfar ? t1 : tfar;
	}
	*tenter = tnear;
	return slab_interval_open(tnear, tfar);
}

/* Does the ray enter the box of corners box[0] and box[1] before tmax? *tenter gets
 * where. The comparisons are written so that NaN from 0 * inf (a ray lying in a slab
 * plane) leaves the interval as it was instead of poisoning it. */
static inline int box_hit(const bvh_point box[2], const slab_ray *r, real tmax, real *tenter)
{
	real tnear = REAL_C(0.0), tfar = tmax;
	real x0, x1, y0, y1, z0, z1;
	if (REAL_SATURATES && r->divided)
		return box_hit_divided(box, r, tmax, tenter);
	/* Saturating differences (real_add): a box of an object that reaches the edge of
	 * fixed point's range, less a far origin, would overflow. */
	x0 = real_mul(real_add((real)box[r->near_x].x, -r->origin.x), r->inv.x);
	x1 = real_mul(real_add((real)box[!r->near_x].x, -r->origin.x), r->inv.x);
	y0 = real_mul(real_add((real)box[r->near_y].y, -r->origin.y), r->inv.y);
	y1 = real_mul(real_add((real)box[!r->near_y].y, -r->origin.y), r->inv.y);
	z0 = real_mul(real_add((real)box[r->near_z].z, -r->origin.z), r->inv.z);
	z1 = real_mul(real_add((real)box[!r->near_z].z, -r->origin.z), r->inv.z);
	tnear = x0 > tnear ? x0 : tnear;
	tnear = y0 > tnear ? y0 : tnear;
	tnear = z0 > tnear ? z0 : tnear;
	tfar = x1 < tfar ? x1 : tfar;
	tfar = y1 < tfar ? y1 : tfar;
	tfar = z1 < tfar ? z1 : tfar;
	*tenter = tnear;
	return slab_interval_open(tnear, tfar);
}

#if BVH_WIDE
/* The byte offsets in a node of the rows a ray enters a box by (at[axis]) and leaves it
 * by (at[3 + axis]), for each choice of the signs of 1 / d (bit axis set: negative). */
typedef struct {
	size_t at[6];
} wide_rows;

#define WIDE_ROW_AT(row) \
	(offsetof(bvh_wide_node, box) + (size_t)(row) * sizeof(float) * WIDE_LANES)
#define WIDE_SIGN(signs, axis) ((signs) >> (axis) & 1)
#define WIDE_ROWS(signs)                                                                  \
	{                                                                                  \
		{WIDE_ROW_AT(0 + WIDE_SIGN(signs, 0)), WIDE_ROW_AT(2 + WIDE_SIGN(signs, 1)),     \
		 WIDE_ROW_AT(4 + WIDE_SIGN(signs, 2)), WIDE_ROW_AT(1 - WIDE_SIGN(signs, 0)),     \
		 WIDE_ROW_AT(3 - WIDE_SIGN(signs, 1)), WIDE_ROW_AT(5 - WIDE_SIGN(signs, 2))}     \
	}
static const wide_rows wide_row_table[8] = {WIDE_ROWS(0), WIDE_ROWS(1), WIDE_ROWS(2),
					    WIDE_ROWS(3), WIDE_ROWS(4), WIDE_ROWS(5),
					    WIDE_ROWS(6), WIDE_ROWS(7)};

/* A ray prepared for the wide tree's float slab tests, made so that a computed entry is
 * never after the true one and a computed exit never before it (Ize, "Robust BVH ray
 * traversal", gives the same argument): per axis two float copies of the origin, one at
 * or below it and one at or above (WIDE_WIDEN), and the near plane's distance taken from
 * the copy that makes it smallest, the far plane's from the one that makes it largest;
 * what the float subtraction, product and reciprocal round is relative to the distance,
 * at most 4 2^-24, and the test allows WIDE_SLACK for it. Rays with an origin beyond
 * WIDE_LIMIT or a direction component below 1 / WIDE_LIMIT (other than 0) are left to
 * the binary tree: there the reciprocal would not be a float, or a product could lose
 * its relative accuracy. */
typedef struct {
	/* The origin, rounded for each plane; 1 / d (+-infinity for a zero component, by
	 * its sign). A fourth element each, unused, lets SSE store all three at once. */
	float near_from[4], far_from[4], inv[4];
	/* Where in a node the box rows are of the planes the ray enters by (row 2 axis +
	 * (1 / d < 0): -0 counts as negative) and of those it leaves by: byte offsets, so
	 * that a node's test finds each row with one addition (wide_row). */
	wide_rows rows;
#if WIDE_SSE
	/* The SSE test's copies of near_from, far_from and inv in four lanes, made once a
	 * search by its own traversal (WIDE_PREPARE): the object tests between two nodes
	 * leave no vector in a register, and broadcasting nine for each node cost balls
	 * 1.7 % of its instructions there. AVX's test broadcasts from memory instead. */
	__m128 near_from4[3], far_from4[3], inv4[3];
#endif
} wide_ray;

#define WIDE_LIMIT REAL_C(1.2676506002282294e30) /* 2^100 */

/* The row of node n's box `offset` bytes into the node (a wide_ray's rows). */
static inline const float *wide_row(const bvh_wide_node *n, size_t offset)
{
	return (const float *)(const void *)((const char *)n + offset);
}
#define WIDE_SLACK (1.0f + 1.0f / 1048576.0f)     /* 1 + 2^-20: covers 8 2^-24 */

/* The origin's float copies below and above it: o -+ (|o| 2^-22 + 2^-140) rounded to
 * float. 2^-22 of |o| is two of float's steps at o or more, so rounding to the nearest
 * float cannot cross o; 2^-140 is many subnormal steps, for an o too small for that.
 * One subtraction, one addition and their conversions, without comparisons: the
 * bounds are a step or two wider than o's neighbouring floats, which no box test notices. */
#define WIDE_WIDEN REAL_C(2.384185791015625e-07) /* 2^-22 */
#define WIDE_TINY REAL_C(7.174648137343064e-43)  /* 2^-140 */

#if WIDE_SSE2_RAY
/* The operations of wide_axis (the scalar form, below) on the three axes at once, with
 * SSE2 (doubles in pairs, their floats in one register): the same bits in fewer
 * instructions. A ray's preparation was a tenth of SPD mount's instructions once, and
 * with the exact neighbouring floats of the origin still about 100 instructions a search
 * (SPD balls, 2026-12-06). */
static inline int wide_ray_make(wide_ray *w, const ray *r)
{
	const __m128d limit = _mm_set1_pd(WIDE_LIMIT), least = _mm_set1_pd(1.0 / WIDE_LIMIT);
	const __m128d magnitude = _mm_castsi128_pd(_mm_set1_epi64x(0x7fffffffffffffffLL));
	const __m128d widen = _mm_set1_pd(WIDE_WIDEN), tiny = _mm_set1_pd(WIDE_TINY);
	/* z in both lanes of its pair: the upper passes or fails the checks as the lower. */
	__m128d oxy = _mm_set_pd(r->origin.y, r->origin.x), oz = _mm_set1_pd(r->origin.z);
	__m128d dxy = _mm_set_pd(r->dir.y, r->dir.x), dz = _mm_set1_pd(r->dir.z);
	__m128d zero = _mm_setzero_pd(), axy = _mm_and_pd(oxy, magnitude);
	__m128d az = _mm_and_pd(oz, magnitude), gxy, gz, okxy, okz;
	__m128 lower, upper, inv, negative;
	/* |o| < WIDE_LIMIT, and d = 0 or |d| > 1 / WIDE_LIMIT, on every axis (NaN fails). */
	okxy = _mm_and_pd(_mm_cmplt_pd(axy, limit),
			  _mm_or_pd(_mm_cmpeq_pd(dxy, zero),
				    _mm_cmpgt_pd(_mm_and_pd(dxy, magnitude), least)));
	okz = _mm_and_pd(_mm_cmplt_pd(az, limit),
			 _mm_or_pd(_mm_cmpeq_pd(dz, zero), _mm_cmpgt_pd(_mm_and_pd(dz, magnitude), least)));
	if (_mm_movemask_pd(_mm_and_pd(okxy, okz)) != 3)
		return 0;
	gxy = _mm_add_pd(_mm_mul_pd(axy, widen), tiny);
	gz = _mm_add_pd(_mm_mul_pd(az, widen), tiny);
	lower = _mm_movelh_ps(_mm_cvtpd_ps(_mm_sub_pd(oxy, gxy)), _mm_cvtpd_ps(_mm_sub_pd(oz, gz)));
	upper = _mm_movelh_ps(_mm_cvtpd_ps(_mm_add_pd(oxy, gxy)), _mm_cvtpd_ps(_mm_add_pd(oz, gz)));
	inv = _mm_div_ps(_mm_set1_ps(1.0f), _mm_movelh_ps(_mm_cvtpd_ps(dxy), _mm_cvtpd_ps(dz)));
	negative = _mm_cmplt_ps(inv, _mm_setzero_ps());
	_mm_storeu_ps(w->inv, inv);
	_mm_storeu_ps(w->near_from, _mm_or_ps(_mm_and_ps(negative, lower),
					      _mm_andnot_ps(negative, upper)));
	_mm_storeu_ps(w->far_from, _mm_or_ps(_mm_and_ps(negative, upper),
					     _mm_andnot_ps(negative, lower)));
	w->rows = wide_row_table[_mm_movemask_ps(negative) & 7];
	return 1;
}
#else
/* One axis of wide_ray_make: origin component o, direction component d; the axis's bit
 * of *signs set for 1 / d < 0. Without branches on the data: the direction's sign is a
 * coin toss for rays from hit points, and mispredicted branches on such tests were a
 * tenth of SPD mount's time. */
static inline int wide_axis(wide_ray *w, int axis, real o, unit d, int *signs)
{
	real widen = real_fabs(o) * WIDE_WIDEN + WIDE_TINY;
	float copies[2];
	int negative;
	if (!(real_fabs(o) < WIDE_LIMIT) ||
	    (d != UNIT_C(0.0) && !(unit_fabs(d) > UNIT_C(1.0) / WIDE_LIMIT)))
		return 0;
	copies[0] = (float)(o - widen);
	copies[1] = (float)(o + widen);
	w->inv[axis] = 1.0f / (float)d; /* a zero keeps its sign: 1 / -0 is -infinity */
	negative = w->inv[axis] < 0.0f;
	*signs |= negative << axis;
	/* Entering through the lower plane the origin's upper copy gives the smaller
	 * distance, and the other way round. */
	w->near_from[axis] = copies[!negative];
	w->far_from[axis] = copies[negative];
	return 1;
}

static inline int wide_ray_make(wide_ray *w, const ray *r)
{
	int signs = 0;
	if (!(wide_axis(w, 0, r->origin.x, r->dir.x, &signs) &&
	      wide_axis(w, 1, r->origin.y, r->dir.y, &signs) &&
	      wide_axis(w, 2, r->origin.z, r->dir.z, &signs)))
		return 0;
	w->rows = wide_row_table[signs];
	return 1;
}
#endif

/* tmax as a float, infinity beyond float's range: rounded to the nearest, which
 * WIDE_SLACK covers. */
static float wide_limit(real tmax)
{
	return tmax < (real)FLT_MAX ? (float)tmax : INFINITY;
}

/* Which of node n's boxes the ray enters before tmax: bit i for lane i, and enter[i]
 * where, never after the true entry. A NaN distance (0 times infinity: a ray lying in a
 * slab plane) fails its comparison and leaves the interval as it was. */
static inline int wide_hit(const bvh_wide_node *n, const wide_ray *r, float tmax,
			   float enter[WIDE_LANES])
{
#if WIDE_SSE
	/* The same operations, four lanes at once: max_ps(a, b) is a > b ? a : b, lane by
	 * lane, NaN included, so both paths give the same bits. */
	int group, mask = 0;
	for (group = 0; group < WIDE_LANES; group += 4) {
		__m128 tnear = _mm_setzero_ps(), tfar = _mm_set1_ps(tmax);
		int axis;
		for (axis = 0; axis < 3; axis++) {
			const float *lo = wide_row(n, r->rows.at[axis]) + group;
			const float *hi = wide_row(n, r->rows.at[3 + axis]) + group;
			__m128 t0 = _mm_mul_ps(_mm_sub_ps(_mm_loadu_ps(lo), r->near_from4[axis]),
					       r->inv4[axis]);
			__m128 t1 = _mm_mul_ps(_mm_sub_ps(_mm_loadu_ps(hi), r->far_from4[axis]),
					       r->inv4[axis]);
			tnear = _mm_max_ps(t0, tnear);
			tfar = _mm_min_ps(t1, tfar);
		}
		_mm_storeu_ps(&enter[group], tnear);
		mask |= _mm_movemask_ps(_mm_cmple_ps(
				tnear, _mm_add_ps(_mm_mul_ps(tfar, _mm_set1_ps(WIDE_SLACK)),
						  _mm_set1_ps(FLT_MIN))))
			<< group;
	}
	return mask;
#else
	int i, axis, mask = 0;
	for (i = 0; i < WIDE_LANES; i++) {
		float tnear = 0.0f, tfar = tmax;
		for (axis = 0; axis < 3; axis++) {
			float lo = wide_row(n, r->rows.at[axis])[i];
			float hi = wide_row(n, r->rows.at[3 + axis])[i];
			float t0 = (lo - r->near_from[axis]) * r->inv[axis];
			float t1 = (hi - r->far_from[axis]) * r->inv[axis];
			tnear = t0 > tnear ? t0 : tnear;
			tfar = t1 < tfar ? t1 : tfar;
		}
		enter[i] = tnear;
		/* FLT_MIN: below it a product is subnormal and its error absolute. */
		mask |= (tnear <= tfar * WIDE_SLACK + FLT_MIN) << i;
	}
	return mask;
#endif
}

#if WIDE_AVX
/* wide_hit's operations on all eight lanes at once (the same bits: _mm256_max_ps is
 * a > b ? a : b lane by lane, and the comparison is false for NaN). */
static inline WIDE_AVX_TARGET int wide_hit_avx(const bvh_wide_node *n, const wide_ray *r,
						float tmax, float enter[WIDE_LANES])
{
	__m256 tnear = _mm256_setzero_ps(), tfar = _mm256_set1_ps(tmax);
	int axis;
	/* The ray's numbers broadcast from memory, one instruction each (a broadcast of a
	 * value the compiler holds in a register took three). */
	for (axis = 0; axis < 3; axis++) {
		__m256 inv = _mm256_broadcast_ss(&r->inv[axis]);
		__m256 lo = _mm256_loadu_ps(wide_row(n, r->rows.at[axis]));
		__m256 hi = _mm256_loadu_ps(wide_row(n, r->rows.at[3 + axis]));
		__m256 from_near = _mm256_broadcast_ss(&r->near_from[axis]);
		__m256 from_far = _mm256_broadcast_ss(&r->far_from[axis]);
		__m256 t0 = _mm256_mul_ps(_mm256_sub_ps(lo, from_near), inv);
		__m256 t1 = _mm256_mul_ps(_mm256_sub_ps(hi, from_far), inv);
		tnear = _mm256_max_ps(t0, tnear);
		tfar = _mm256_min_ps(t1, tfar);
	}
	_mm256_storeu_ps(enter, tnear);
	return _mm256_movemask_ps(_mm256_cmp_ps(
		tnear,
		_mm256_add_ps(_mm256_mul_ps(tfar, _mm256_set1_ps(WIDE_SLACK)), _mm256_set1_ps(FLT_MIN)),
		_CMP_LE_OQ));
}

/* Whether the processor has AVX and the system saves its registers (XCR0's SSE and AVX
 * state bits): asked once, on the first search. By cpuid itself rather than the
 * compiler's feature query, whose library data a program of more than 2 GiB of static
 * arrays cannot reach from clang's build. */
static int avx_present(void)
{
	static int present = -1;
	unsigned int a, b, c, d, xcr0_low, xcr0_high;
	if (present >= 0)
		return present;
	present = 0;
	if (__get_cpuid(1, &a, &b, &c, &d) && (c & bit_AVX) && (c & bit_OSXSAVE)) {
		/* Volatile: not moved out of the branch that the cached answer skips. */
		__asm__ __volatile__("xgetbv" : "=a"(xcr0_low), "=d"(xcr0_high) : "c"(0));
		present = (xcr0_low & 6) == 6;
	}
	return present;
}
#endif

/* The lowest lane set in a mask of eight (0 for none): one load, where a loop or two
 * lookups by halves cost balls 1-6 %. */
static const unsigned char lowest_lane[256] = {
	0, 0, 1, 0, 2, 0, 1, 0, 3, 0, 1, 0, 2, 0, 1, 0, 4, 0, 1, 0, 2, 0, 1, 0, 3, 0, 1, 0, 2, 0, 1, 0,
	5, 0, 1, 0, 2, 0, 1, 0, 3, 0, 1, 0, 2, 0, 1, 0, 4, 0, 1, 0, 2, 0, 1, 0, 3, 0, 1, 0, 2, 0, 1, 0,
	6, 0, 1, 0, 2, 0, 1, 0, 3, 0, 1, 0, 2, 0, 1, 0, 4, 0, 1, 0, 2, 0, 1, 0, 3, 0, 1, 0, 2, 0, 1, 0,
	5, 0, 1, 0, 2, 0, 1, 0, 3, 0, 1, 0, 2, 0, 1, 0, 4, 0, 1, 0, 2, 0, 1, 0, 3, 0, 1, 0, 2, 0, 1, 0,
	7, 0, 1, 0, 2, 0, 1, 0, 3, 0, 1, 0, 2, 0, 1, 0, 4, 0, 1, 0, 2, 0, 1, 0, 3, 0, 1, 0, 2, 0, 1, 0,
	5, 0, 1, 0, 2, 0, 1, 0, 3, 0, 1, 0, 2, 0, 1, 0, 4, 0, 1, 0, 2, 0, 1, 0, 3, 0, 1, 0, 2, 0, 1, 0,
	6, 0, 1, 0, 2, 0, 1, 0, 3, 0, 1, 0, 2, 0, 1, 0, 4, 0, 1, 0, 2, 0, 1, 0, 3, 0, 1, 0, 2, 0, 1, 0,
	5, 0, 1, 0, 2, 0, 1, 0, 3, 0, 1, 0, 2, 0, 1, 0, 4, 0, 1, 0, 2, 0, 1, 0, 3, 0, 1, 0, 2, 0, 1, 0,
};
RT_STATIC_ASSERT(lanes_fit_the_table, WIDE_LANES <= 8);
#endif

#if WIDE_SSE
/* The SSE test's four-lane copies of the ray's numbers (wide_ray). */
static inline void wide_ray_broadcast(wide_ray *w)
{
	int axis;
	for (axis = 0; axis < 3; axis++) {
		w->near_from4[axis] = _mm_set1_ps(w->near_from[axis]);
		w->far_from4[axis] = _mm_set1_ps(w->far_from[axis]);
		w->inv4[axis] = _mm_set1_ps(w->inv[axis]);
	}
}
#endif

#endif
