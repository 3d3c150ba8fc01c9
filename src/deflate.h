/* deflate.h - a zlib stream (RFC 1950, 1951) written as its input arrives: LZ77 matches
 * over a 32 KiB window, found through hash chains, in deflate's fixed Huffman codes. For
 * PNG's image data, streamed row by row in bounded memory (about 330 KiB, static, in the
 * stream itself). See LICENSE for copyright and licence. */
#ifndef RT_DEFLATE_H
#define RT_DEFLATE_H

#include <stddef.h>
#include <stdint.h>

#define DEFLATE_WINDOW 32768 /* the most a match reaches back (deflate's limit) */
#define DEFLATE_HASH_BITS 15
#define DEFLATE_OUT_BYTES 65536 /* compressed bytes gathered before each write */

/* Takes n compressed bytes; returns 1 on success, 0 on failure. */
typedef int (*deflate_write_fn)(void *ctx, const unsigned char *data, size_t n);

typedef struct {
	/* The input: up to DEFLATE_WINDOW bytes already coded (what matches reach back
	 * into), then those still to code; slid down by a window when full. */
	unsigned char input[2 * DEFLATE_WINDOW];
	size_t filled, next; /* bytes in input; the first not yet coded */
	/* Hash chains: the latest position of each 3-byte hash, and for each position the
	 * one before with its hash (-1: none). */
	int32_t head[1 << DEFLATE_HASH_BITS];
	int32_t previous[DEFLATE_WINDOW];
	uint32_t adler_a, adler_b; /* the Adler-32 of the input so far */
	uint32_t bits;             /* output bits not yet a whole byte, lowest first */
	int bit_count;
	unsigned char out[DEFLATE_OUT_BYTES];
	size_t out_count;
	deflate_write_fn write;
	void *ctx;
	int ok; /* 0 once a write failed */
} deflate_stream;

/* Starts a zlib stream: its header goes out with the first compressed bytes. */
void deflate_start(deflate_stream *z, deflate_write_fn write, void *ctx);

/* Codes n more bytes of input (some wait for more to find longer matches). Returns 0 once
 * a write has failed. */
int deflate_feed(deflate_stream *z, const unsigned char *data, size_t n);

/* Codes what is left, ends the stream (its Adler-32) and writes every byte out. */
int deflate_finish(deflate_stream *z);

/* The CRC-32 (ISO 3309, as PNG and zlib use) of n bytes, continued from crc (0 to
 * start). */
uint32_t deflate_crc32(uint32_t crc, const unsigned char *data, size_t n);

#endif
