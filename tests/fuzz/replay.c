/* replay.c - runs the fuzzing entry point over files given on the command line, so the
 * corpus is replayed by `make test` under the sanitizers without libFuzzer.
 * Prints `N passed, N failed` (a file passes when it is processed without a crash).
 * See LICENSE for copyright and licence. */
#include <stdint.h>
#include <stdio.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static uint8_t buffer[4 << 20]; /* largest corpus file, bytes */

int main(int argc, char **argv)
{
	int i, passed = 0, failed = 0;
	for (i = 1; i < argc; i++) {
		FILE *f = fopen(argv[i], "rb");
		size_t n;
		if (!f) {
			printf("replay: cannot open %s\n", argv[i]);
			failed++;
			continue;
		}
		n = fread(buffer, 1, sizeof buffer, f);
		fclose(f);
		/* A crash or sanitizer report ends the process: reaching here is a pass. */
		LLVMFuzzerTestOneInput(buffer, n);
		passed++;
	}
	printf("%d passed, %d failed\n", passed, failed);
	return failed != 0;
}
