/* pages.c - memory made ready in bulk (pages.h): MADV_POPULATE_WRITE on Linux.
 * See LICENSE for copyright and licence. */
#define _DEFAULT_SOURCE 1 /* madvise */

#include "pages.h"

#if defined(__linux__) && !defined(RT_NO_PAGES_AHEAD)
#include <stdint.h>
#include <sys/mman.h>
#include <unistd.h>

/* Linux's request since 5.14 (an older kernel refuses it, and the pages fault one by one
 * as they would have). */
#ifndef MADV_POPULATE_WRITE
#define MADV_POPULATE_WRITE 23
#endif

/* Bytes prepared at a time for a growing array: 16 pages, so that a scene's arrays end
 * at most this far past what they use (memory proportional to the scene) while a million
 * objects take a few thousand requests. */
#define PAGES_CHUNK ((size_t)65536)

void pages_prepare(void *start, size_t bytes)
{
	static size_t page;
	size_t lead;
	if (bytes == 0)
		return;
	if (!page) {
		long size = sysconf(_SC_PAGESIZE);
		page = size > 0 ? (size_t)size : 4096u;
	}
	/* Outwards to whole pages: a page that holds any byte of the range is part of the
	 * same writable mapping, and preparing it writes nothing. */
	lead = (size_t)((uintptr_t)start & (page - 1));
	(void)madvise((unsigned char *)start - lead, (lead + bytes + page - 1) & ~(page - 1),
		      MADV_POPULATE_WRITE);
}

void pages_ahead(void *array, size_t size, size_t first, size_t count, size_t capacity)
{
	size_t per = PAGES_CHUNK / size + 1; /* elements a chunk */
	size_t from = first ? (first - 1) / per + 1 : 0, to, end;
	if (count == 0)
		return;
	to = (first + count - 1) / per;
	if (from > to)
		return;
	end = (to + 1) * per < capacity ? (to + 1) * per : capacity;
	pages_prepare((unsigned char *)array + from * per * size, (end - from * per) * size);
}
#endif
