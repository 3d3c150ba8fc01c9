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

static void report(const char *file, int line, const char *what, long expected, long actual)
{
	char message[160];
	snprintf(message, sizeof message, "%s:%d: %s: expected %ld, got %ld\n", file, line, what,
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
	report(file, line, what, 1, 0);
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

int test_check_int(long actual, long expected, const char *file, int line, const char *what)
{
	if (actual == expected) {
		test_passed++;
		return 1;
	}
	test_failed++;
	report(file, line, what, expected, actual);
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
