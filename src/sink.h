/* sink.h - where rendered rows go: the one interface every output format implements.
 * The render loop calls begin once, row for each row top to bottom, then end; a sink
 * never reaches back into the tracer. See LICENSE for copyright and licence. */
#ifndef RT_SINK_H
#define RT_SINK_H

#include <stddef.h>

#include "config.h"
#include "vec.h"

/* Writes n bytes; returns 1 on success, 0 on failure. */
typedef int (*write_fn)(void *ctx, const void *data, size_t n);

typedef struct sink sink;
struct sink {
	/* The image that will arrive: width x height linear colours. Returns 1 if ok. */
	int (*begin)(sink *self, int width, int height);
	/* One row of `width` linear colours, top row first, with the index of the object
	 * each pixel's eye ray hit first (-1 for none; -1 throughout with corner sampling,
	 * where a pixel has four eye rays). Returns 1 if ok. */
	int (*row)(sink *self, const vec3 *colors, const int *ids);
	/* After the last row. Returns 1 if ok. */
	int (*end)(sink *self);
	write_fn write; /* where the bytes go */
	void *ctx;
	/* Set by a sink that fails for a reason of its own (not a failed write). */
	const char *error;
};

/* Fills in a sink's common part: its three steps and where its bytes go. */
static inline void sink_init(sink *s, int (*begin)(sink *, int, int),
			     int (*row)(sink *, const vec3 *, const int *), int (*end)(sink *),
			     write_fn write, void *ctx)
{
	s->begin = begin;
	s->row = row;
	s->end = end;
	s->write = write;
	s->ctx = ctx;
	s->error = NULL;
}

#endif
