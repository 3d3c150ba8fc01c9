/* test.h - rt's tiny test harness: checks that say what failed, counted per run.
 * A failed check prints `file:line: expected X, got Y` and the run goes on.
 * See LICENSE for copyright and licence. */
#ifndef RT_TEST_H
#define RT_TEST_H

#include <stdio.h>

#include "real.h"

extern int test_passed, test_failed;

/* Records one check; returns cond so a test can stop early on a failed precondition. */
int test_check(int cond, const char *file, int line, const char *what);
int test_check_near(double actual, double expected, double tolerance, const char *file,
		    int line, const char *what);
int test_check_int(long actual, long expected, const char *file, int line, const char *what);

#define CHECK(cond) test_check((cond) != 0, __FILE__, __LINE__, #cond)
#define CHECK_NEAR(actual, expected, tol)                                                     \
	test_check_near((double)(actual), (double)(expected), (double)(tol), __FILE__, __LINE__, \
			#actual)
#define CHECK_INT(actual, expected)                                                           \
	test_check_int((long)(actual), (long)(expected), __FILE__, __LINE__, #actual)

/* Tolerance for a result the reference gives to `digits` significant digits in double,
 * relaxed for float; the hard-case tables give both. */
#if defined(RT_REAL_FLOAT)
#define TOL(float_tol, double_tol) (float_tol)
#else
#define TOL(float_tol, double_tol) (double_tol)
#endif

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
void suite_fixed(void);

#endif
