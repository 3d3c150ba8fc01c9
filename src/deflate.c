/* deflate.c - the zlib stream of deflate.h: greedy LZ77 over hash chains, coded in fixed
 * Huffman blocks (deflate's BTYPE 01: no code tables to send, the codes of RFC 1951
 * section 3.2.6), which is what PNG's image data needs from a small encoder.
 * See LICENSE for copyright and licence. */
#include "deflate.h"

#include <string.h>

#define MIN_MATCH 3
#define MAX_MATCH 258
/* Positions tried along a hash chain before taking the best so far, and a length that
 * ends the search at once: enough for rendered images, whose runs and repeated rows
 * are found at once (more would cost time for a few percent of size). */
#define MAX_CHAIN 48
#define GOOD_MATCH 64

/* RFC 1951's length codes 257-285 and distance codes 0-29: the first length or distance
 * of each, and how many extra bits follow it. */
static const unsigned short length_base[29] = {3,  4,  5,  6,  7,  8,  9,  10, 11,  13,
					       15, 17, 19, 23, 27, 31, 35, 43, 51,  59,
					       67, 83, 99, 115, 131, 163, 195, 227, 258};
static const unsigned char length_extra[29] = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2,
					       2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0};
static const unsigned short distance_base[30] = {
	1,   2,   3,   4,   5,    7,    9,    13,   17,   25,   33,   49,   65,    97,    129,
	193, 257, 385, 513, 769, 1025, 1537, 2049, 3073, 4097, 6145, 8193, 12289, 16385, 24577};
static const unsigned char distance_extra[30] = {0, 0, 0, 0, 1, 1, 2, 2,  3,  3,  4,  4,  5,  5,  6,
						 6, 7, 7, 8, 8, 9, 9, 10, 10, 11, 11, 12, 12, 13, 13};

/* Hands the gathered bytes to the writer. */
static void flush_out(deflate_stream *z)
{
	if (z->out_count > 0 && z->ok && !z->write(z->ctx, z->out, z->out_count))
		z->ok = 0;
	z->out_count = 0;
}

static void put_byte(deflate_stream *z, unsigned char byte)
{
	if (z->out_count == DEFLATE_OUT_BYTES)
		flush_out(z);
	z->out[z->out_count++] = byte;
}

/* count (at most 16) bits of value, lowest first, as deflate packs its data. */
static void put_bits(deflate_stream *z, uint32_t value, int count)
{
	z->bits |= value << z->bit_count;
	z->bit_count += count;
	while (z->bit_count >= 8) {
		put_byte(z, (unsigned char)z->bits);
		z->bits >>= 8;
		z->bit_count -= 8;
	}
}

/* A Huffman code of `length` bits, which deflate sends highest bit first. */
static void put_code(deflate_stream *z, uint32_t code, int length)
{
	uint32_t reversed = 0;
	int i;
	for (i = 0; i < length; i++)
		reversed |= ((code >> i) & 1u) << (length - 1 - i);
	put_bits(z, reversed, length);
}

/* A literal byte or length symbol (0-287) in the fixed code. */
static void put_symbol(deflate_stream *z, int symbol)
{
	if (symbol < 144)
		put_code(z, 0x30u + (uint32_t)symbol, 8);
	else if (symbol < 256)
		put_code(z, 0x190u + (uint32_t)(symbol - 144), 9);
	else if (symbol < 280)
		put_code(z, (uint32_t)(symbol - 256), 7);
	else
		put_code(z, 0xC0u + (uint32_t)(symbol - 280), 8);
}

static void put_match(deflate_stream *z, int length, int distance)
{
	int code = 28;
	while (length < length_base[code])
		code--;
	put_symbol(z, 257 + code);
	put_bits(z, (uint32_t)(length - length_base[code]), length_extra[code]);
	code = 29;
	while (distance < distance_base[code])
		code--;
	put_code(z, (uint32_t)code, 5);
	put_bits(z, (uint32_t)(distance - distance_base[code]), distance_extra[code]);
}

static uint32_t hash_at(const unsigned char *p)
{
	uint32_t v = (uint32_t)p[0] << 16 | (uint32_t)p[1] << 8 | p[2];
	return (v * 2654435761u) >> (32 - DEFLATE_HASH_BITS);
}

/* Enters position pos (at least MIN_MATCH bytes from the end of the input) in its chain. */
static void insert(deflate_stream *z, size_t pos)
{
	uint32_t h = hash_at(z->input + pos);
	z->previous[pos & (DEFLATE_WINDOW - 1)] = z->head[h];
	z->head[h] = (int32_t)pos;
}

/* The longest match for the bytes at z->next among the earlier positions of its chain,
 * at most `limit` long; its distance in *distance. */
static int longest_match(const deflate_stream *z, size_t limit, int *distance)
{
	const unsigned char *here = z->input + z->next;
	int32_t candidate = z->head[hash_at(here)];
	int best = 0, chain = MAX_CHAIN;
	while (candidate >= 0 && chain-- > 0) {
		size_t from = (size_t)candidate, length = 0;
		int32_t older;
		if (z->next - from >= DEFLATE_WINDOW)
			break;
		while (length < limit && z->input[from + length] == here[length])
			length++;
		if ((int)length > best) {
			best = (int)length;
			*distance = (int)(z->next - from);
			if (best >= GOOD_MATCH || length == limit)
				break;
		}
		older = z->previous[from & (DEFLATE_WINDOW - 1)];
		/* A slot reused by a later position leads forwards: the chain ends. */
		if (older >= candidate)
			break;
		candidate = older;
	}
	return best;
}

/* Codes the input up to where `keep` bytes are left (MAX_MATCH while more may come, so
 * that matches there can reach their full length; 0 at the end). */
static void code_input(deflate_stream *z, size_t keep)
{
	while (z->next + keep < z->filled) {
		size_t limit = z->filled - z->next;
		int length = 0, distance = 0;
		if (limit > MAX_MATCH)
			limit = MAX_MATCH;
		if (limit >= MIN_MATCH) {
			length = longest_match(z, limit, &distance);
			insert(z, z->next);
		}
		if (length >= MIN_MATCH) {
			size_t end = z->next + (size_t)length;
			put_match(z, length, distance);
			/* The positions inside the match go into the chains too. */
			for (z->next++; z->next < end; z->next++)
				if (z->next + MIN_MATCH <= z->filled)
					insert(z, z->next);
		} else {
			put_symbol(z, z->input[z->next++]);
		}
	}
}

/* Moves the newest window of input to the front, and the chains with it. */
static void slide(deflate_stream *z)
{
	size_t i;
	memmove(z->input, z->input + DEFLATE_WINDOW, DEFLATE_WINDOW);
	z->filled -= DEFLATE_WINDOW;
	z->next -= DEFLATE_WINDOW;
	for (i = 0; i < (size_t)1 << DEFLATE_HASH_BITS; i++)
		z->head[i] = z->head[i] >= DEFLATE_WINDOW ? z->head[i] - DEFLATE_WINDOW : -1;
	for (i = 0; i < DEFLATE_WINDOW; i++)
		z->previous[i] = z->previous[i] >= DEFLATE_WINDOW ? z->previous[i] - DEFLATE_WINDOW : -1;
}

void deflate_start(deflate_stream *z, deflate_write_fn write, void *ctx)
{
	size_t i;
	z->filled = z->next = 0;
	for (i = 0; i < (size_t)1 << DEFLATE_HASH_BITS; i++)
		z->head[i] = -1;
	for (i = 0; i < DEFLATE_WINDOW; i++)
		z->previous[i] = -1;
	z->adler_a = 1;
	z->adler_b = 0;
	z->bits = 0;
	z->bit_count = 0;
	z->out_count = 0;
	z->write = write;
	z->ctx = ctx;
	z->ok = 1;
	/* zlib's header: deflate with a 32 KiB window, no dictionary, the check bits that
	 * make it a multiple of 31 (0x7801); then a block, not the last, of fixed codes. */
	put_byte(z, 0x78);
	put_byte(z, 0x01);
	put_bits(z, 0, 1);
	put_bits(z, 1, 2);
}

int deflate_feed(deflate_stream *z, const unsigned char *data, size_t n)
{
	while (n > 0) {
		size_t room = 2 * DEFLATE_WINDOW - z->filled, take = n < room ? n : room, i;
		/* Adler-32, its sums reduced often enough that they cannot overflow. */
		for (i = 0; i < take; i++) {
			z->adler_a += data[i];
			z->adler_b += z->adler_a;
			if ((i & 4095) == 4095) {
				z->adler_a %= 65521u;
				z->adler_b %= 65521u;
			}
		}
		z->adler_a %= 65521u;
		z->adler_b %= 65521u;
		memcpy(z->input + z->filled, data, take);
		z->filled += take;
		data += take;
		n -= take;
		code_input(z, MAX_MATCH);
		if (z->filled == 2 * DEFLATE_WINDOW)
			slide(z);
	}
	return z->ok;
}

int deflate_finish(deflate_stream *z)
{
	code_input(z, 0);
	put_symbol(z, 256); /* the block's end */
	/* The last block, empty, so the stream ends however it was fed. */
	put_bits(z, 1, 1);
	put_bits(z, 1, 2);
	put_symbol(z, 256);
	if (z->bit_count > 0)
		put_bits(z, 0, 8 - z->bit_count);
	put_byte(z, (unsigned char)(z->adler_b >> 8));
	put_byte(z, (unsigned char)z->adler_b);
	put_byte(z, (unsigned char)(z->adler_a >> 8));
	put_byte(z, (unsigned char)z->adler_a);
	flush_out(z);
	return z->ok;
}

uint32_t deflate_crc32(uint32_t crc, const unsigned char *data, size_t n)
{
	static uint32_t table[256];
	static int ready;
	size_t i;
	if (!ready) {
		uint32_t k, c;
		int bit;
		for (k = 0; k < 256; k++) {
			for (c = k, bit = 0; bit < 8; bit++)
				c = c & 1u ? 0xEDB88320u ^ (c >> 1) : c >> 1;
			table[k] = c;
		}
		ready = 1;
	}
	crc = ~crc;
	for (i = 0; i < n; i++)
		crc = table[(crc ^ data[i]) & 0xFFu] ^ (crc >> 8);
	return ~crc;
}
