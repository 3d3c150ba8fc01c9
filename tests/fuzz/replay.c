/* replay.c - runs the fuzzing entry point over files given on the command line, so the
 * corpus is replayed by `make test` under the sanitizers without libFuzzer.
 * Prints `N passed, N failed`: a file passes when it is processed without a crash; two
 * more checks prove that the entry point renders (a scene known to be good traces the
 * 35 corner and 24 centre eye rays of its 6x4 images, and some of the files render too).
 * See LICENSE for copyright and licence. */
#include <stdint.h>
#include <stdio.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
extern unsigned long fuzz_rendered, fuzz_eye_rays;

static uint8_t buffer[4 << 20]; /* largest corpus file, bytes */

/* A sphere in front of the eye, lit: it parses in every build and must render. */
static const char good_scene[] = "v\nfrom 0 0 -5\nat 0 0 0\nup 0 1 0\nangle 40\nhither 1\n"
				 "resolution 6 4\nl 5 5 -5\nf 1 0 0 1 0 0 0 1\ns 0 0 0 1\n";

int main(int argc, char **argv)
{
	int i, passed = 0, failed = 0;
	unsigned long rendered;
	LLVMFuzzerTestOneInput((const uint8_t *)good_scene, sizeof good_scene - 1);
	if (fuzz_rendered == 1 && fuzz_eye_rays == 35 + 24) {
		passed++;
	} else {
		printf("replay: the good scene rendered %lu times with %lu eye rays, expected once "
		       "with 59\n",
		       fuzz_rendered, fuzz_eye_rays);
		failed++;
	}
	rendered = fuzz_rendered;
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
	/* Corpus inputs that parse must reach the renderer (the corpus holds good scenes). */
	if (argc > 1 && fuzz_rendered == rendered) {
		printf("replay: none of the %d files rendered\n", argc - 1);
		failed++;
	} else if (argc > 1) {
		passed++;
	}
	printf("replay: %lu of %d files rendered, %lu eye rays\n", fuzz_rendered - rendered,
	       argc - 1, fuzz_eye_rays);
	printf("%d passed, %d failed\n", passed, failed);
	return failed != 0;
}
