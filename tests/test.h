/* test.h - rt's tiny test harness: checks that say what failed, counted per run.
 * A failed check prints `file:line: what: expected X, got Y` and the run goes on.
 * See LICENSE for copyright and licence. */
#ifndef RT_TEST_H
#define RT_TEST_H

#include <math.h>
#include <stdint.h>
#include <stdio.h>

#include "real.h"

extern int test_passed, test_failed;

/* Records one check; returns whether it passed, so a test can stop early on a failed
 * precondition. A failure prints `file:line: what: expected X, got Y`: for a condition
 * `expected true, got false`, otherwise both values. */
int test_check(int cond, const char *file, int line, const char *what);
int test_check_near(double actual, double expected, double tolerance, const char *file,
		    int line, const char *what);
int test_check_int(long long actual, long long expected, const char *file, int line,
		   const char *what);
int test_check_str(const char *actual, const char *expected, const char *file, int line,
		   const char *what);

#define CHECK(cond) test_check((cond) != 0, __FILE__, __LINE__, #cond)
#define CHECK_NEAR(actual, expected, tol)                                                     \
	test_check_near((double)(actual), (double)(expected), (double)(tol), __FILE__, __LINE__, \
			#actual)
/* Integers compare as long long: 64-bit values whole, also where long has 32 bits. */
#define CHECK_INT(actual, expected)                                                           \
	test_check_int((long long)(actual), (long long)(expected), __FILE__, __LINE__, #actual)
/* Strings compare byte for byte (NULL is no string, and fails). Not on the MCU. */
#define CHECK_STR(actual, expected)                                                           \
	test_check_str((actual), (expected), __FILE__, __LINE__, #actual)

/* Seeded random numbers, one generator for every suite: Knuth's MMIX linear congruential
 * generator (64-bit state), the same numbers on every machine and in every build. A test
 * seeds it before it draws, so its numbers do not depend on what ran before it; the state
 * is defined beside test_passed. */
extern unsigned long long test_random_state;

static inline void test_seed(unsigned long long seed)
{
	test_random_state = seed;
}

/* The next state: x * 6364136223846793005 + 1442695040888963407 (mod 2^64). */
static inline unsigned long long test_random_next(void)
{
	test_random_state = test_random_state * 6364136223846793005ULL + 1442695040888963407ULL;
	return test_random_state;
}

/* 32 random bits: the state's top half (an LCG's low bits repeat with short periods). */
static inline uint32_t test_random_bits(void)
{
	return (uint32_t)(test_random_next() >> 32);
}

/* A uniform double in [0, 1): the state's top 53 bits. */
static inline double test_random(void)
{
	return (double)(test_random_next() >> 11) * (1.0 / 9007199254740992.0);
}

/* A uniform double in [lo, hi). */
static inline double test_random_range(double lo, double hi)
{
	return lo + (hi - lo) * test_random();
}

/* One Q16.16 step, 2^-16: the unit in which fixed-point tolerances are counted. */
#define LSB (1.0 / 65536.0)

/* Tolerance for a result the reference gives to `digits` significant digits in double,
 * relaxed for float; the hard-case tables give both. TOL3 adds Q16.16's, in units (as a
 * count of LSB at the scale the case runs at, with its reason beside it). In fixed point
 * every case states its own: TOL does not compile there. */
#if defined(RT_REAL_FLOAT)
#define TOL(float_tol, double_tol) (float_tol)
#define TOL3(float_tol, double_tol, fixed_tol) (float_tol)
#elif REAL_FIXED
#define TOL(float_tol, double_tol) TOL_has_no_fixed_point_tolerance_use_TOL3
#define TOL3(float_tol, double_tol, fixed_tol) (fixed_tol)
#else
#define TOL(float_tol, double_tol) (double_tol)
#define TOL3(float_tol, double_tol, fixed_tol) (double_tol)
#endif

/* Between `real` and double. A Q16.16 real holds its value times 2^16, so a cast would
 * read LSBs as units: test_double scales, and test_real rounds to the nearest LSB and
 * saturates. In floating point both are plain conversions, as casts were. */
#if REAL_FIXED
static inline double test_double(real x)
{
	return x / 65536.0;
}
static inline double test_double2(real2 x) /* a Q32.32 square */
{
	return (double)x / 4294967296.0;
}
static inline real test_real(double x)
{
	double v = x * 65536.0;
	if (!(v < 2147483647.0))
		return REAL_MAX;
	if (!(v > -2147483647.0))
		return -REAL_MAX;
	return (real)(v < 0 ? v - 0.5 : v + 0.5);
}
/* The same for a unit (Q2.30: 2^30 is 1.0). */
static inline double test_unit_double(unit x)
{
	return x / 1073741824.0;
}
static inline unit test_unit(double x)
{
	double v = x * 1073741824.0;
	if (!(v < 2147483647.0))
		return INT32_MAX;
	if (!(v > -2147483647.0))
		return -INT32_MAX;
	return (unit)(v < 0 ? v - 0.5 : v + 0.5);
}
#else
#define test_double(x) ((double)(x))
#define test_double2(x) ((double)(x))
#define test_real(x) ((real)(x))
#define test_unit_double(x) ((double)(x))
#define test_unit(x) ((unit)(x))
#endif

/* Numbers in case tables: `real` in floating point, rounded where written (REAL_C); in
 * fixed point doubles, rounded once at the scale the case runs at: CASE_REAL(x, shift)
 * is x times 2^shift as `real` there, and x itself in floating point (shift 0). */
#if REAL_FIXED
typedef double case_real;
#define CASE_C(x) (x)
#define CASE_REAL(x, shift) test_real(ldexp((x), (shift)))
#define CASE_UNIT(x) test_unit(x)
#else
typedef real case_real;
#define CASE_C(x) REAL_C(x)
#define CASE_REAL(x, shift) ((void)(shift), (x))
#define CASE_UNIT(x) (x)
#endif

/* The same for a real2 (a squared length). */
#define CHECK_REAL2(actual, expected, tol)                                                   \
	test_check_near(test_double2(actual), (double)(expected), (double)(tol), __FILE__,       \
			__LINE__, #actual)

/* A vector of literals, each as `real`. */
#define VEC_C(x, y, z) vec_make(REAL_C(x), REAL_C(y), REAL_C(z))

/* A unit vector of literals, and a check on a unit (a cosine, a direction's component). */
#define DIR_C(x, y, z) dir_make(UNIT_C(x), UNIT_C(y), UNIT_C(z))
#define CHECK_UNIT(actual, expected, tol)                                                    \
	test_check_near(test_unit_double(actual), (double)(expected), (double)(tol), __FILE__,   \
			__LINE__, #actual)

/* A check on a `real` against a double, in units. */
#define CHECK_REAL(actual, expected, tol)                                                    \
	test_check_near(test_double(actual), (double)(expected), (double)(tol), __FILE__,        \
			__LINE__, #actual)

/* The suites, one per file. */
void suite_sphere(void);
void suite_hedron(void);
void suite_polygon(void);
void suite_cone(void);
void suite_optics(void);
void suite_properties(void);
void suite_parse(void);
void suite_image(void);
void suite_output(void);
void suite_deflate(void);
void suite_camera(void);
void suite_bvh(void);
void suite_eye_cover(void);
void suite_shadow_list(void);
void suite_clearance(void);
void suite_pages(void);
void suite_fixed(void);
void suite_fixed_kernels(void); /* its integer kernels: also run on the MCU */

#endif
