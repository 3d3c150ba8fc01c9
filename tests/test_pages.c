/* test_pages.c - pages.c's requests, seen by the kernel: which pages of a static array
 * are resident (mincore) before and after pages_ahead and pages_prepare, and which
 * ranges are advised to be huge pages (/proc/self/smaps). Linux only; on other hosts the
 * requests are no-ops and there is nothing to see.
 * See LICENSE for copyright and licence. */
#define _DEFAULT_SOURCE 1 /* mincore */

#include "intersect.h"
#include "load.h"
#include "pages.h"
#include "scene.h"
#include "test.h"

#if defined(__linux__) && !defined(RT_NO_PAGES_AHEAD)
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <unistd.h>

#define ARRAY_BYTES ((size_t)1 << 20)
#define HUGE ((size_t)2 << 20)	      /* pages.c's huge page */
#define BIG_BYTES ((size_t)6 << 20) /* an array that grows past its first huge page */

/* Written only through the requests below: bss that nothing else touches, of which the
 * array is the 1 MiB from the first page boundary on (pages of up to 64 KiB), and the big
 * array 6 MiB from 12 KiB past a huge page's boundary (so that its own offsets and the
 * huge pages' boundaries differ). */
static unsigned char untouched[(1 << 20) + 65536];
static unsigned char untouched_big[(6 << 20) + (2 << 20) + 65536];
static unsigned char *array, *big;

/* How many pages holding bytes [from, to) of the array at base are resident. */
static long resident_in(unsigned char *base, size_t from, size_t to)
{
	static unsigned char vec[BIG_BYTES / 4096 + 16];
	size_t page = (size_t)sysconf(_SC_PAGESIZE), first = from / page * page, i;
	size_t length = (to - first + page - 1) / page * page;
	long count = 0;
	memset(vec, 0, sizeof vec); /* MemorySanitizer does not see the kernel's writes */
	if (length / page > sizeof vec || mincore(base + first, length, vec) != 0)
		return -1;
	for (i = 0; i < length / page; i++)
		count += vec[i] & 1;
	return count;
}

static long resident(size_t from, size_t to)
{
	return resident_in(array, from, to);
}

/* Whether the mapping that holds address a is advised to be huge pages (the flag "hg" of
 * its VmFlags in /proc/self/smaps), with its range in *from, *to; -1 where that cannot be
 * read. madvise splits a mapping at the advised range's ends, so the range is the
 * advised one (merged with any advised range next to it). */
static int huge_advised(const unsigned char *a, uintptr_t *from, uintptr_t *to)
{
	FILE *maps = fopen("/proc/self/smaps", "r");
	char line[512];
	int holds = 0, advised = -1;
	if (!maps)
		return -1;
	while (advised < 0 && fgets(line, sizeof line, maps)) {
		unsigned long long lo, hi;
		if (sscanf(line, "%llx-%llx ", &lo, &hi) == 2) {
			holds = (uintptr_t)a >= lo && (uintptr_t)a < hi;
			if (holds) {
				*from = (uintptr_t)lo;
				*to = (uintptr_t)hi;
			}
		} else if (holds && strncmp(line, "VmFlags:", 8) == 0) {
			advised = strstr(line, " hg") != NULL;
		}
	}
	fclose(maps);
	return advised;
}

/* Whether huge-page advice can be seen here (/proc/self/smaps, of which `probe` is any
 * mapped address, and transparent huge pages); if not, says that `what` is not checked. */
static int advice_seen(const unsigned char *probe, const char *what)
{
	uintptr_t from, to;
	if (huge_advised(probe, &from, &to) >= 0 &&
	    access("/sys/kernel/mm/transparent_hugepage", F_OK) == 0)
		return 1;
	printf("pages: %s not checked (no /proc/self/smaps or no transparent huge pages)\n",
	       what);
	return 0;
}

/* The big array's advice: the one whole huge page its requests entered fresh (the third
 * from the aligned start, at `boundary`), and nothing before or after it. */
static void check_big_advice(size_t boundary)
{
	uintptr_t from = 0, to = 0;
	if (!advice_seen(big, "huge-page advice"))
		return;
	CHECK_INT(huge_advised(big + boundary, &from, &to), 1);
	CHECK(from == (uintptr_t)(big + boundary));
	CHECK(to == (uintptr_t)(big + boundary + HUGE));
	CHECK_INT(huge_advised(big, &from, &to), 0);
	CHECK_INT(huge_advised(big + boundary + HUGE, &from, &to), 0);
	CHECK_INT(huge_advised(array, &from, &to), 0);
}

/* An array of BIG_BYTES growing past its first huge page: up to it, a chunk at a time as
 * the small array; past it, to the next huge page's boundary at once, and no further. */
static void check_big_array(size_t page)
{
	const size_t size = 16, capacity = BIG_BYTES / 16, chunk = 65536 / 16 + 1;
	size_t skew = 3 * page, boundary, at;
	big = untouched_big + (HUGE - (size_t)((uintptr_t)untouched_big % HUGE)) % HUGE + skew;
	boundary = 2 * HUGE - skew; /* the big array's offset of its third huge page's start */
	/* Small pages unless pages.c asks otherwise, as where transparent huge pages are set
	 * to "madvise" (under "always" a first write would fault in a whole huge page, and
	 * the counts below would be another system's). */
	(void)madvise(big, BIG_BYTES, MADV_NOHUGEPAGE);
	pages_ahead(big, size, 0, 1, capacity);
	CHECK_INT(resident_in(big, 0, 65536), (long)(65536 / page));
	CHECK_INT(resident_in(big, 131072, HUGE), 0);
	/* A write whose chunk starts past the first HUGE bytes: that chunk and the rest of
	 * the huge page it is in, up to the boundary, and nothing of the huge page after. */
	at = (HUGE / (chunk * size) + 1) * chunk; /* the first chunk starting past HUGE */
	pages_ahead(big, size, at, 1, capacity);
	CHECK_INT(resident_in(big, at * size, boundary), (long)(boundary / page - at * size / page));
	CHECK_INT(resident_in(big, boundary, boundary + 65536), 0);
	/* The next chunks inside it ask again for what is there: nothing new. */
	pages_ahead(big, size, at + chunk, 2 * chunk, capacity);
	CHECK_INT(resident_in(big, boundary, boundary + HUGE), 0);
	/* The first chunk to cross the boundary takes the whole next huge page. */
	at = (boundary / size / chunk) * chunk;
	pages_ahead(big, size, at, 1, capacity);
	CHECK_INT(resident_in(big, boundary, boundary + HUGE), (long)(HUGE / page));
	CHECK_INT(resident_in(big, boundary + HUGE, boundary + HUGE + 65536), 0);
	/* The array's end bounds the last chunk's request, huge page or not. */
	at = (capacity - 1) / chunk * chunk;
	pages_ahead(big, size, at, capacity - at, capacity);
	CHECK_INT(resident_in(big, BIG_BYTES, BIG_BYTES + page), 0);
	CHECK_INT(resident_in(big, BIG_BYTES - page, BIG_BYTES), 1);
	check_big_advice(boundary);
}

/* pages_plan's advice: the huge pages a range touches, whole, when it fills an eighth
 * of them, else none; and the scene's from its file's length (scene_plan_pages). Advice
 * only: what the system then gives (a huge page, or small pages where it has none to
 * spare) is its own. Written by nothing: 10 MiB from a huge page's boundary. */
static unsigned char untouched_plan[(10 << 20) + (2 << 20)];
static scene plan_scene, read_scene, short_scene;
static void check_plan(void)
{
	unsigned char *plan = untouched_plan;
	unsigned char *objects = (unsigned char *)plan_scene.objects;
	unsigned char *vertices = (unsigned char *)plan_scene.vertices;
	uintptr_t from = 0, to = 0;
	int i;
	plan += (HUGE - (size_t)((uintptr_t)plan % HUGE)) % HUGE;
	if (!advice_seen(plan, "plans"))
		return;
	(void)madvise(plan, 5 * HUGE, MADV_NOHUGEPAGE); /* no advice of its own */
	/* 300 KiB inside the second huge page: that huge page, whole. */
	pages_plan(plan + HUGE + 100, 300 * 1024);
	CHECK_INT(huge_advised(plan + HUGE + 100, &from, &to), 1);
	CHECK(from == (uintptr_t)(plan + HUGE));
	CHECK(to == (uintptr_t)(plan + 2 * HUGE));
	CHECK_INT(huge_advised(plan, &from, &to), 0);
	CHECK_INT(huge_advised(plan + 2 * HUGE, &from, &to), 0);
	/* 300 KiB across the boundary of the fourth and fifth fills less than an eighth of
	 * the two: no advice; 600 KiB across it, both. */
	pages_plan(plan + 4 * HUGE - 100 * 1024, 300 * 1024);
	CHECK_INT(huge_advised(plan + 4 * HUGE - 4096, &from, &to), 0);
	CHECK_INT(huge_advised(plan + 4 * HUGE, &from, &to), 0);
	pages_plan(plan + 4 * HUGE - 100 * 1024, 600 * 1024);
	CHECK_INT(huge_advised(plan + 4 * HUGE - 4096, &from, &to), 1);
	CHECK(from == (uintptr_t)(plan + 3 * HUGE));
	CHECK(to == (uintptr_t)(plan + 5 * HUGE));
	/* Nothing planned was written. */
	for (i = 0; i < 5; i++)
		CHECK_INT(resident_in(plan, (size_t)i * HUGE, (size_t)(i + 1) * HUGE), 0);
	/* A scene file of 100 KiB leaves the scene's arrays on small pages (150 KiB of each
	 * planned); one of 1 MiB plans 1.5 MiB of each from its start, and no further. */
	scene_plan_pages(&plan_scene, 100 * 1024);
	CHECK_INT(huge_advised(objects + 65536, &from, &to), 0);
	scene_plan_pages(&plan_scene, 1024 * 1024);
	CHECK_INT(huge_advised(objects + 1024 * 1024, &from, &to), 1);
	CHECK(from <= (uintptr_t)objects);
	CHECK(to >= (uintptr_t)(objects + 1536 * 1024));
	if (objects + 1536 * 1024 + 3 * HUGE < vertices)
		CHECK(to <= (uintptr_t)(objects + 1536 * 1024 + 2 * HUGE));
	CHECK_INT(huge_advised(vertices + 1024 * 1024, &from, &to), 1);
	/* Past the vertices' plan: nothing, unless it is the next array's first huge page. */
	if (vertices + 1600 * 1024 + 3 * HUGE < (unsigned char *)plan_scene.normals)
		CHECK_INT(huge_advised(vertices + 1600 * 1024 + HUGE, &from, &to), 0);
}

/* Writes a scene of `bytes` bytes or a little more (small spheres in a row) to a new
 * temporary file, whose name goes in path; 0 if it cannot. */
static int write_long_scene(char *path, long bytes)
{
	int fd = mkstemp(path);
	FILE *f = fd >= 0 ? fdopen(fd, "w") : NULL;
	long i;
	if (!f) {
		if (fd >= 0)
			close(fd);
		return 0;
	}
	fprintf(f, "v\nfrom 0 0 -10\nat 0 0 0\nup 0 1 0\nangle 40\nhither 1\nresolution 8 8\n"
		   "l 0 10 -10\nf 1 0 0 1 0 1 0 1\n");
	for (i = 0; ftell(f) < bytes; i++)
		fprintf(f, "s %ld.5 %ld.25 %ld 0.125\n", i % 100, i / 100 % 100, i / 10000);
	return fclose(f) == 0;
}

/* The plans as rt makes them: load_scene_file plans the scene from the file's length,
 * the build the wide nodes (fixed point: the binary nodes) from the number of boxes.
 * Their advice is cleared first, so that only this reading and this build can have made
 * it. */
static void check_plans_made(void)
{
	char long_path[] = "/tmp/rt-test-pages-XXXXXX", short_path[] = "/tmp/rt-test-pages-XXXXXX";
	uintptr_t from = 0, to = 0;
	const accel *a;
	int written;
	if (!advice_seen((const unsigned char *)&read_scene, "plans as made"))
		return;
	written = write_long_scene(long_path, 600 * 1024);
	if (!written || !write_long_scene(short_path, 60 * 1024)) {
		if (written)
			remove(long_path);
		printf("pages: plans as made not checked (no temporary file)\n");
		return;
	}
	(void)madvise(&read_scene, sizeof read_scene, MADV_NOHUGEPAGE);
	(void)madvise(&short_scene, sizeof short_scene, MADV_NOHUGEPAGE);
	CHECK_INT(load_scene_file(&read_scene, long_path), 1);
	CHECK_INT(load_scene_file(&short_scene, short_path), 1);
	CHECK(read_scene.object_count > 10000);
	CHECK_INT(huge_advised((unsigned char *)read_scene.objects + 512 * 1024, &from, &to), 1);
	/* (Past the first 2 MiB of the short scene: a huge page of the array before it may
	 * reach that far.) */
	CHECK_INT(huge_advised((unsigned char *)short_scene.objects + HUGE + HUGE / 2, &from, &to),
		  0);
#if BVH_WIDE
	a = accel_build(&short_scene);
	(void)madvise((void *)(uintptr_t)a->tree.wide, sizeof a->tree.wide, MADV_NOHUGEPAGE);
	a = accel_build(&read_scene);
	CHECK(a->tree.wide_count > 1000);
	CHECK_INT(huge_advised((const unsigned char *)&a->tree.wide[a->tree.wide_count / 2],
			       &from, &to),
		  1);
#else
	(void)a;
#endif
	remove(long_path);
	remove(short_path);
}

void suite_pages(void)
{
	const size_t size = 16, capacity = ARRAY_BYTES / 16, chunk = 65536 / 16 + 1;
	size_t page = (size_t)sysconf(_SC_PAGESIZE);
	long all = (long)(ARRAY_BYTES / page);
	array = untouched + (page - (size_t)((uintptr_t)untouched & (page - 1))) % page;
	(void)madvise(array, ARRAY_BYTES, MADV_NOHUGEPAGE); /* as in check_big_array */
	/* A kernel before Linux 5.14 refuses the request (and rt's pages fault one by one,
	 * as they always did): nothing to see. The probe is the array's last page. */
	if (madvise(array + ARRAY_BYTES - page, page, MADV_POPULATE_WRITE) != 0) {
		printf("pages: skipped (this kernel has no MADV_POPULATE_WRITE)\n");
		return;
	}
	/* Nothing else yet: the array is bss that no one has written. */
	CHECK_INT(resident(0, ARRAY_BYTES - page), 0);
	/* pages_prepare: the pages that hold any byte of the range, and no others. */
	pages_prepare(array + 300 * 1024 + 100, 100 * 1024 - 200);
	CHECK_INT(resident(300 * 1024, 400 * 1024), (long)(100 * 1024 / page));
	CHECK_INT(resident(280 * 1024, 300 * 1024), 0);
	CHECK_INT(resident(400 * 1024, 420 * 1024), 0);
	/* pages_ahead: the first element's write prepares the first chunk (64 KiB and the
	 * page it ends in), and nothing far past it. */
	pages_ahead(array, size, 0, 1, capacity);
	CHECK_INT(resident(0, 65536), (long)(65536 / page));
	CHECK_INT(resident(131072, 262144), 0);
	/* Writes inside that chunk ask for nothing more. */
	pages_ahead(array, size, 1, 100, capacity);
	CHECK_INT(resident(131072, 262144), 0);
	/* The first write past it prepares the next chunk: a range that crosses into it. */
	pages_ahead(array, size, chunk - 2, 4, capacity);
	CHECK_INT(resident(65536 + page, 131072), (long)((131072 - 65536 - page) / page));
	CHECK_INT(resident(196608, 262144), 0);
	/* A range far ahead, several chunks at once, up to the array's end and no further
	 * (the capacity): the whole array is resident now. */
	pages_ahead(array, size, 2 * chunk, capacity - 2 * chunk, capacity);
	CHECK_INT(resident(0, ARRAY_BYTES), all);
	CHECK_INT(resident(ARRAY_BYTES, ARRAY_BYTES + page), 0);
	check_big_array(page);
	check_plan();
	check_plans_made();
}
#else
void suite_pages(void)
{
	/* No requests here: pages.h's calls compile to nothing. */
	pages_prepare(NULL, 0);
	pages_plan(NULL, 0);
}
#endif
