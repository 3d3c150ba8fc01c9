/* main.c - runs every unit-test suite and prints `N passed, N failed`.
 * See LICENSE for copyright and licence. */
#include <math.h>
#include <string.h>

#include "test.h"

int test_passed, test_failed;
unsigned long long test_random_state;

int test_check(int cond, const char *file, int line, const char *what)
{
	if (cond) {
		test_passed++;
		return 1;
	}
	test_failed++;
	printf("%s:%d: check failed: %s\n", file, line, what);
	return 0;
}

int test_check_near(double actual, double expected, double tolerance, const char *file,
		    int line, const char *what)
{
	/* NaN never passes. */
	if (fabs(actual - expected) <= tolerance) {
		test_passed++;
		return 1;
	}
	test_failed++;
	printf("%s:%d: %s: expected %.17g (within %g), got %.17g\n", file, line, what, expected,
	       tolerance, actual);
	return 0;
}

int test_check_int(long actual, long expected, const char *file, int line, const char *what)
{
	if (actual == expected) {
		test_passed++;
		return 1;
	}
	test_failed++;
	printf("%s:%d: %s: expected %ld, got %ld\n", file, line, what, expected, actual);
	return 0;
}

int main(int argc, char **argv)
{
	/* Optional: run only the suite named on the command line. */
	static const struct {
		const char *name;
		void (*run)(void);
	} suites[] = {
		{"sphere", suite_sphere},         {"hedron", suite_hedron}, {"polygon", suite_polygon},
		{"cone", suite_cone},             {"optics", suite_optics}, {"properties", suite_properties},
		{"parse", suite_parse},           {"image", suite_image},   {"output", suite_output},
		{"fixed", suite_fixed},           {"camera", suite_camera}, {"bvh", suite_bvh},
		{"clearance", suite_clearance},
	};
	size_t i;
	for (i = 0; i < sizeof suites / sizeof suites[0]; i++)
		if (argc < 2 || strcmp(argv[1], suites[i].name) == 0)
			suites[i].run();
	printf("%d passed, %d failed\n", test_passed, test_failed);
	return test_failed ? 1 : 0;
}
