/* test_deflate.c - the zlib stream of deflate.c against an inflater written here for the
 * fixed-code blocks it makes (RFC 1951 read the other way), on input that crosses its
 * window's slides: noise, long runs, matches at the window's far end; and the checksums
 * against their published check values. PNG files as a whole are decoded by Python's
 * zlib in tests/cli.sh. See LICENSE for copyright and licence. */
#include <string.h>

#include "deflate.h"
#include "support.h"
#include "test.h"

/* The compressed stream, gathered. */
static unsigned char packed[600000];
static size_t packed_length;

static int keep(void *ctx, const unsigned char *data, size_t n)
{
	(void)ctx;
	if (packed_length + n > sizeof packed)
		return 0;
	memcpy(packed + packed_length, data, n);
	packed_length += n;
	return 1;
}

/* The inflater's bit reader. */
typedef struct {
	const unsigned char *data;
	size_t length, bit; /* bits read so far */
	int bad;
} reader;

static unsigned bits(reader *r, int count)
{
	unsigned v = 0;
	int i;
	for (i = 0; i < count; i++, r->bit++) {
		if (r->bit / 8 >= r->length) {
			r->bad = 1;
			return 0;
		}
		v |= (unsigned)(r->data[r->bit / 8] >> (r->bit % 8) & 1) << i;
	}
	return v;
}

/* A Huffman code, highest bit first. */
static unsigned code(reader *r, int count)
{
	unsigned v = 0;
	int i;
	for (i = 0; i < count; i++)
		v = v << 1 | bits(r, 1);
	return v;
}

/* A symbol of the fixed literal/length code. */
static int fixed_symbol(reader *r)
{
	unsigned v = code(r, 7);
	if (v <= 23)
		return 256 + (int)v;
	v = v << 1 | bits(r, 1);
	if (v >= 0x30 && v <= 0xBF)
		return (int)v - 0x30;
	if (v >= 0xC0 && v <= 0xC7)
		return 280 + (int)v - 0xC0;
	v = v << 1 | bits(r, 1);
	return 144 + (int)v - 0x190;
}

/* Inflates a zlib stream of fixed-code blocks into out; its length, or -1 when it is
 * not a valid one (or its Adler-32 is wrong). */
static long inflate_fixed(const unsigned char *data, size_t length, unsigned char *out, size_t room)
{
	static const unsigned short lbase[29] = {3,  4,  5,  6,  7,  8,  9,  10,  11,  13,
						 15, 17, 19, 23, 27, 31, 35, 43,  51,  59,
						 67, 83, 99, 115, 131, 163, 195, 227, 258};
	static const unsigned char lextra[29] = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2,
						 2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0};
	static const unsigned short dbase[30] = {1,    2,    3,    4,    5,    7,     9,     13,
						 17,   25,   33,   49,   65,   97,    129,   193,
						 257,  385,  513,  769,  1025, 1537,  2049,  3073,
						 4097, 6145, 8193, 12289, 16385, 24577};
	static const unsigned char dextra[30] = {0, 0, 0, 0, 1, 1, 2, 2,  3,  3,  4,  4,  5,  5,  6,
						 6, 7, 7, 8, 8, 9, 9, 10, 10, 11, 11, 12, 12, 13, 13};
	reader r;
	size_t n = 0, i;
	unsigned long a = 1, b = 0;
	int last;
	if (length < 6 || data[0] != 0x78 || (data[0] * 256 + data[1]) % 31 != 0)
		return -1;
	r.data = data + 2;
	r.length = length - 6;
	r.bit = 0;
	r.bad = 0;
	do {
		last = (int)bits(&r, 1);
		if (bits(&r, 2) != 1)
			return -1;
		for (;;) {
			int s = fixed_symbol(&r), d;
			size_t len, dist;
			if (r.bad || s > 285)
				return -1;
			if (s < 256) {
				if (n == room)
					return -1;
				out[n++] = (unsigned char)s;
				continue;
			}
			if (s == 256)
				break;
			len = lbase[s - 257] + bits(&r, lextra[s - 257]);
			d = (int)code(&r, 5);
			if (d > 29)
				return -1;
			dist = dbase[d] + bits(&r, dextra[d]);
			if (r.bad || dist > n || dist > 32768 || n + len > room)
				return -1;
			for (i = 0; i < len; i++, n++)
				out[n] = out[n - dist];
		}
	} while (!last);
	r.bit = (r.bit + 7) / 8 * 8;
	for (i = 0; i < n; i++) {
		a = (a + out[i]) % 65521;
		b = (b + a) % 65521;
	}
	i = 2 + r.bit / 8;
	if (r.bad || i + 4 != length ||
	    (((unsigned long)data[i] << 8 | data[i + 1]) != b) ||
	    (((unsigned long)data[i + 2] << 8 | data[i + 3]) != a))
		return -1;
	return (long)n;
}

static deflate_stream stream;
static unsigned char input[400000], output[400000];

/* Compresses input[0 .. n) fed in pieces of `piece` bytes, inflates it back and checks
 * the bytes; returns the compressed length. */
static size_t round_trip(size_t n, size_t piece)
{
	size_t at;
	long got;
	packed_length = 0;
	deflate_start(&stream, keep, NULL);
	for (at = 0; at < n; at += piece)
		CHECK(deflate_feed(&stream, input + at, at + piece < n ? piece : n - at));
	CHECK(deflate_finish(&stream));
	got = inflate_fixed(packed, packed_length, output, sizeof output);
	CHECK_INT(got, (long)n);
	CHECK(got == (long)n && memcmp(input, output, n) == 0);
	return packed_length;
}

static void test_round_trips(void)
{
	size_t i, n;
	/* Nothing at all. */
	CHECK_INT((long)round_trip(0, 1), 9); /* header, two empty blocks, Adler-32 */
	/* Noise: no matches, across several slides of the window; pieces of odd sizes. */
	test_seed(7);
	for (i = 0; i < 300000; i++)
		input[i] = (unsigned char)(test_random_bits() >> 24);
	n = round_trip(300000, 9973);
	CHECK(n < 300000 * 9 / 8 + 100); /* 8 or 9 bits a byte */
	/* A run: a match of distance 1, 258 long, over and over. */
	memset(input, 0x5A, 300000);
	CHECK(round_trip(300000, 300000) < 3000);
	/* Repeats at the window's far end: a block of noise, then itself 32,767 bytes later,
	 * the longest distance kept; and a row pattern as an image has them. */
	for (i = 0; i < 20000; i++)
		input[i] = (unsigned char)(test_random_bits() >> 24);
	for (i = 20000; i < 32767; i++)
		input[i] = (unsigned char)i;
	memcpy(input + 32767, input, 20000);
	CHECK(round_trip(52767, 1000) < 20000 + 16000);
	for (i = 0; i < 390000; i++)
		input[i] = (unsigned char)((i % 3001) * 7 + (i / 3001) % 5);
	round_trip(390000, 3001);
}

static void test_checksums(void)
{
	static const unsigned char check[] = "123456789", wiki[] = "Wikipedia";
	/* CRC-32's check value; Adler-32 of "Wikipedia" is 0x11E60398. */
	CHECK(deflate_crc32(0, check, 9) == 0xCBF43926u);
	CHECK(deflate_crc32(deflate_crc32(0, check, 4), check + 4, 5) == 0xCBF43926u);
	packed_length = 0;
	deflate_start(&stream, keep, NULL);
	deflate_feed(&stream, wiki, 9);
	deflate_finish(&stream);
	CHECK(packed_length > 6 && packed[packed_length - 4] == 0x11 && packed[packed_length - 3] == 0xE6 &&
	      packed[packed_length - 2] == 0x03 && packed[packed_length - 1] == 0x98);
}

/* A write that fails is reported, and no more are tried. */
static int refuse(void *ctx, const unsigned char *data, size_t n)
{
	(void)data;
	(void)n;
	++*(int *)ctx;
	return 0;
}

static void test_failed_write(void)
{
	int calls = 0;
	size_t i;
	for (i = 0; i < 200000; i++)
		input[i] = (unsigned char)(test_random_bits() >> 24);
	deflate_start(&stream, refuse, &calls);
	CHECK(!deflate_feed(&stream, input, 200000));
	CHECK(!deflate_finish(&stream));
	CHECK_INT(calls, 1);
}

void suite_deflate(void)
{
	test_checksums();
	test_round_trips();
	test_failed_write();
}
