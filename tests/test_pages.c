/* test_pages.c - pages.c's requests, seen by the kernel: which pages of a static array
 * are resident (mincore) before and after pages_ahead and pages_prepare. Linux only; on
 * other hosts the requests are no-ops and there is nothing to see.
 * See LICENSE for copyright and licence. */
#define _DEFAULT_SOURCE 1 /* mincore */

#include "pages.h"
#include "test.h"

#if defined(__linux__) && !defined(RT_NO_PAGES_AHEAD)
#include <stdint.h>
#include <string.h>
#include <sys/mman.h>
#include <unistd.h>

#define ARRAY_BYTES ((size_t)1 << 20)

/* Written only through the requests below: bss that nothing else touches, of which the
 * array is the 1 MiB from the first page boundary on (pages of up to 64 KiB). */
static unsigned char untouched[(1 << 20) + 65536];
static unsigned char *array;

/* How many pages holding bytes [from, to) of the array are resident. */
static long resident(size_t from, size_t to)
{
	static unsigned char vec[ARRAY_BYTES / 4096];
	size_t page = (size_t)sysconf(_SC_PAGESIZE), first = from / page * page, i;
	size_t length = (to - first + page - 1) / page * page;
	long count = 0;
	memset(vec, 0, sizeof vec); /* MemorySanitizer does not see the kernel's writes */
	if (length / page > sizeof vec || mincore(array + first, length, vec) != 0)
		return -1;
	for (i = 0; i < length / page; i++)
		count += vec[i] & 1;
	return count;
}

void suite_pages(void)
{
	const size_t size = 16, capacity = ARRAY_BYTES / 16, chunk = 65536 / 16 + 1;
	size_t page = (size_t)sysconf(_SC_PAGESIZE);
	long all = (long)(ARRAY_BYTES / page);
	array = untouched + (page - (size_t)((uintptr_t)untouched & (page - 1))) % page;
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
}
#else
void suite_pages(void)
{
	/* No requests here: pages.h's calls compile to nothing. */
	pages_prepare(NULL, 0);
}
#endif
