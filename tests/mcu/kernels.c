/* kernels.c - the fixed-point kernels' unit tests on the microcontroller itself: the
 * Thumb-1 assembly forms of fixed.h (FIXED_ASM) exist only there, so the host's unit
 * tests never run them. The same checks as tests/test_fixed.c's integer suites, reported
 * through semihosting; tests/mcu.sh runs this on both boards.
 * See LICENSE for copyright and licence. */
#include <stdio.h>
#include <string.h>

#include "semihost.h"
#include "test.h"

int test_passed, test_failed;
unsigned long long test_random_state;

/* Standard error, opened once (as src/mcu/semihost_io.c does for rt). */
static void say(const char *text)
{
	static int handle = -1;
	if (handle < 0)
		handle = semihost_open(":tt", SEMIHOST_APPEND);
	semihost_write(handle, text, strlen(text));
}

/* v in decimal, written back from the end of digits[21]; returns where it begins (this
 * libc's snprintf has no %lld). */
static const char *decimal(long long v, char digits[21])
{
	unsigned long long u = v < 0 ? 0ULL - (unsigned long long)v : (unsigned long long)v;
	char *d = digits + 20;
	*d = '\0';
	do {
		*--d = (char)('0' + u % 10);
		u /= 10;
	} while (u);
	if (v < 0)
		*--d = '-';
	return d;
}

static void report(const char *file, int line, const char *what, const char *expected,
		   const char *actual)
{
	char message[160];
	snprintf(message, sizeof message, "%s:%d: %s: expected %s, got %s\n", file, line, what,
		 expected, actual);
	say(message);
}

int test_check(int cond, const char *file, int line, const char *what)
{
	if (cond) {
		test_passed++;
		return 1;
	}
	test_failed++;
	report(file, line, what, "true", "false");
	return 0;
}

/* The kernel suites compare integers only; a tolerance check would be a mistake here. */
int test_check_near(double actual, double expected, double tolerance, const char *file,
		    int line, const char *what)
{
	(void)actual;
	(void)expected;
	(void)tolerance;
	return test_check(0, file, line, what);
}

int test_check_int(long long actual, long long expected, const char *file, int line,
		   const char *what)
{
	char e[21], a[21];
	if (actual == expected) {
		test_passed++;
		return 1;
	}
	test_failed++;
	report(file, line, what, decimal(expected, e), decimal(actual, a));
	return 0;
}

int main(int argc, char **argv)
{
	char summary[48];
	(void)argc;
	(void)argv;
	suite_fixed_kernels();
	snprintf(summary, sizeof summary, "%d passed, %d failed\n", test_passed, test_failed);
	say(summary);
	return test_failed ? 1 : 0;
}
