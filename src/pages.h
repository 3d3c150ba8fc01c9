/* pages.h - memory made ready in bulk: the pages of rt's large static arrays asked of
 * the system a chunk at a time, ahead of their first use, instead of one fault a page.
 * See LICENSE for copyright and licence. */
#ifndef RT_PAGES_H
#define RT_PAGES_H

#include <stddef.h>

/* A page first written costs the kernel a fault; on virtual machines where a guest's
 * memory is backed lazily that was 9-13 us a page (a 4 KiB page of bss written once),
 * against under 5 us for pages asked for together: SPD tetra's 385 faults were about a
 * tenth of its 45 ms render, balls' 632 were 6-8 ms before its first ray. A host that has no such request (or a kernel older than
 * Linux 5.14) faults the pages as before. The MCU has neither faults nor the request. */
#if defined(__linux__) && !defined(RT_NO_PAGES_AHEAD)
/* Makes the pages that hold [start, start + bytes) present and writable, at once. */
void pages_prepare(void *start, size_t bytes);

/* Says that [start, start + bytes) is about to be written: a range that fills enough of
 * the huge pages it touches (pages.c) is then given them, whole, where its pages first
 * fault (the range's first and last huge pages with whatever else they hold: plan
 * arrays well inside the static data). Writes nothing and makes nothing present: a huge
 * page of the range that is never written costs nothing. */
void pages_plan(void *start, size_t bytes);

/* For an array of `capacity` elements of `size` bytes filled from its start, about to
 * be written at [first, first + count): prepares the chunks of PAGES_CHUNK bytes the
 * range enters, each once (the chunk that holds element first - 1 was prepared when
 * that was written). */
void pages_ahead(void *array, size_t size, size_t first, size_t count, size_t capacity);
#else
#define pages_prepare(start, bytes) ((void)(start), (void)(bytes))
#define pages_plan(start, bytes) ((void)(start), (void)(bytes))
#define pages_ahead(array, size, first, count, capacity)                                   \
	((void)(array), (void)(size), (void)(first), (void)(count), (void)(capacity))
#endif

#endif
