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
	printf("%s:%d: %s: expected true, got false\n", file, line, what);
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

int test_check_int(long long actual, long long expected, const char *file, int line,
		   const char *what)
{
	if (actual == expected) {
		test_passed++;
		return 1;
	}
	test_failed++;
	printf("%s:%d: %s: expected %lld, got %lld\n", file, line, what, expected, actual);
	return 0;
}

/* A string as a C literal: quoted, with escapes for quotes, backslashes and every byte
 * outside printable ASCII (messages end in newlines; previews hold escape sequences). */
static void print_quoted(const char *s)
{
	if (!s) {
		fputs("NULL", stdout);
		return;
	}
	putchar('"');
	for (; *s; s++) {
		unsigned char c = (unsigned char)*s;
		if (c == '\n')
			fputs("\\n", stdout);
		else if (c == '"' || c == '\\')
			printf("\\%c", c);
		else if (c < 32 || c > 126)
			printf("\\x%02X", c);
		else
			putchar(c);
	}
	putchar('"');
}

int test_check_str(const char *actual, const char *expected, const char *file, int line,
		   const char *what)
{
	if (actual && expected && strcmp(actual, expected) == 0) {
		test_passed++;
		return 1;
	}
	test_failed++;
	printf("%s:%d: %s: expected ", file, line, what);
	print_quoted(expected);
	fputs(", got ", stdout);
	print_quoted(actual);
	putchar('\n');
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
		{"parse", suite_parse},           {"image", suite_image},   {"output", suite_output}, {"deflate", suite_deflate},
		{"fixed", suite_fixed},           {"camera", suite_camera}, {"bvh", suite_bvh},
		{"eye_cover", suite_eye_cover},   {"shadow_list", suite_shadow_list},
		{"clearance", suite_clearance},   {"pages", suite_pages},
	};
	size_t i;
	for (i = 0; i < sizeof suites / sizeof suites[0]; i++)
		if (argc < 2 || strcmp(argv[1], suites[i].name) == 0)
			suites[i].run();
	printf("%d passed, %d failed\n", test_passed, test_failed);
	return test_failed ? 1 : 0;
}
