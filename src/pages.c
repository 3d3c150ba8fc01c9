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

/* A huge page (x86-64 and arm64 Linux): a range asked for that holds whole, aligned huge
 * pages gets them where the system gives them (MADV_HUGEPAGE, with transparent huge pages
 * set to "madvise" or "always"), and so does an array growing past its first HUGE_PAGE
 * bytes, a huge page at a time (pages_ahead). On a virtual machine whose memory the host
 * backs lazily, writing 256 MB of fresh bss took 0.7 s in small pages as they fault, 0.4 s
 * asked for at once, 0.03 s in huge pages: a million objects' arrays (items, nodes, wide
 * nodes, object records) were a third of their build. Small arrays stay on small pages
 * unless planned (pages_plan): an array holds at most one huge page it does not use. */
#define HUGE_PAGE ((size_t)2 << 20)

/* A range planned (pages_plan) takes huge pages when it fills at least this share of
 * the huge pages it touches (256 KiB of one). Here a huge page first
 * written cost 0.22-0.29 ms, its 2 MiB in small pages asked for a chunk at a time
 * 3.4-3.5 ms, 7 us a page: an eighth of a huge page in small pages costs more than the
 * huge page. */
#define PAGES_HUGE_SHARE 8

/* How many bytes from address a up to the next multiple of unit (0 when a is one). */
static size_t to_boundary(uintptr_t a, size_t unit)
{
	return (size_t)(unit - a % unit) % unit;
}

/* madvise over the bytes from address `from` (a number: the pages around an array begin
 * and end outside it, where C forms no pointer) for `bytes`. The address made from it
 * only goes to the system, which is why the lint's warning on that cast (it hides where
 * a pointer came from from the optimiser) does not apply. */
static void advise(uintptr_t from, size_t bytes, int advice)
{
	(void)madvise((void *)from, bytes, advice); /* NOLINT(performance-no-int-to-ptr) */
}

void pages_plan(void *start, size_t bytes)
{
#ifdef MADV_HUGEPAGE
	/* The huge pages the range touches, whole: the range's first and last bytes may
	 * share theirs with other arrays, which is as good, before any of their pages
	 * exist (a huge page is only made where a fault finds none of its pages). So a
	 * range is planned only well inside the static data: one in its first huge page
	 * would round down into the program's other mappings and advise them too. */
	size_t lead = (size_t)((uintptr_t)start % HUGE_PAGE), span = lead + bytes;
	span += to_boundary(span, HUGE_PAGE); /* from a huge page's start, as the span is */
	if (bytes > 0 && bytes >= span / PAGES_HUGE_SHARE)
		advise((uintptr_t)start - lead, span, MADV_HUGEPAGE);
#else
	(void)start;
	(void)bytes;
#endif
}

void pages_prepare(void *start, size_t bytes)
{
	static size_t page;
	size_t lead, huge_lead = to_boundary((uintptr_t)start, HUGE_PAGE);
	if (bytes == 0)
		return;
	if (!page) {
		long size = sysconf(_SC_PAGESIZE);
		page = size > 0 ? (size_t)size : 4096u;
	}
#ifdef MADV_HUGEPAGE
	/* The whole huge pages in the range, before their pages exist: a huge page is only
	 * made for a range with none yet. */
	if (bytes > huge_lead && bytes - huge_lead >= HUGE_PAGE)
		advise((uintptr_t)start + huge_lead, (bytes - huge_lead) / HUGE_PAGE * HUGE_PAGE,
		       MADV_HUGEPAGE);
#endif
	/* Outwards to whole pages: a page that holds any byte of the range is part of the
	 * same writable mapping, and preparing it writes nothing. */
	lead = (size_t)((uintptr_t)start & (page - 1));
	advise((uintptr_t)start - lead, (lead + bytes + page - 1) & ~(page - 1), MADV_POPULATE_WRITE);
}

void pages_ahead(void *array, size_t size, size_t first, size_t count, size_t capacity)
{
	size_t per = PAGES_CHUNK / size + 1; /* elements a chunk */
	size_t from = first ? (first - 1) / per + 1 : 0, to, end;
	unsigned char *start, *stop, *limit = (unsigned char *)array + capacity * size;
	if (count == 0)
		return;
	to = (first + count - 1) / per;
	if (from > to)
		return;
	end = (to + 1) * per < capacity ? (to + 1) * per : capacity;
	start = (unsigned char *)array + from * per * size;
	stop = (unsigned char *)array + end * size;
	/* Past the array's first huge page, up to the next huge page's boundary: the whole
	 * huge page after it is then fresh when a chunk first enters it (the chunks that
	 * follow within it ask again for pages that are there, which costs little). */
	if (from * per * size >= HUGE_PAGE) {
		size_t past = to_boundary((uintptr_t)stop, HUGE_PAGE);
		stop = past < (size_t)(limit - stop) ? stop + past : limit;
	}
	pages_prepare(start, (size_t)(stop - start));
}
#endif
