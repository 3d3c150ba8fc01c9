/* png.c - PNG through stb_image_write (src/vendor, v1.16, public domain), no heap.
 * stb's STBIW_MALLOC/REALLOC/FREE go to a bump allocator over a caller's arena. stb
 * does not survive a failed allocation (its growable arrays write on regardless), so
 * running out of arena jumps straight back to png_write, which reports it.
 * See LICENSE for copyright and licence. */
#include "png.h"

#include "colour.h"

/* stb_image_write has floating-point code (HDR, JPEG): a build with no floating point at
 * all (Q16.16) goes without PNG (png_available says so). */
#if !REAL_FLOAT_FREE

#include <setjmp.h>
#include <string.h>

/* The arena in use during one png_write; png_write is not reentrant. */
static struct {
	unsigned char *base;
	size_t size, used, peak;
	unsigned char *last; /* most recent block: it can grow or shrink in place */
	jmp_buf out_of_memory;
} arena;

/* Every block starts with its size, keeping the payload aligned for any type. */
typedef union {
	size_t size;
	long double align_ld;
	void *align_p;
} block_header;

static void *arena_alloc(size_t n)
{
	size_t need = sizeof(block_header) + ((n + sizeof(block_header) - 1) /
					      sizeof(block_header)) * sizeof(block_header);
	block_header *h;
	if (need > arena.size - arena.used)
		longjmp(arena.out_of_memory, 1);
	h = (block_header *)(void *)(arena.base + arena.used);
	h->size = n;
	arena.used += need;
	arena.peak = arena.used > arena.peak ? arena.used : arena.peak;
	arena.last = (unsigned char *)(h + 1);
	return arena.last;
}

static void *arena_realloc(void *p, size_t old_size, size_t n)
{
	unsigned char *fresh;
	if (!p)
		return arena_alloc(n);
	/* The newest block grows in place: stb's output buffer usually is the newest. */
	if (p == arena.last) {
		block_header *h = (block_header *)p - 1;
		size_t start = (size_t)((unsigned char *)h - arena.base);
		size_t need = sizeof(block_header) + ((n + sizeof(block_header) - 1) /
						      sizeof(block_header)) * sizeof(block_header);
		if (need > arena.size - start)
			longjmp(arena.out_of_memory, 1);
		h->size = n;
		arena.used = start + need;
		arena.peak = arena.used > arena.peak ? arena.used : arena.peak;
		return p;
	}
	fresh = arena_alloc(n);
	memcpy(fresh, p, old_size < n ? old_size : n);
	return fresh;
}

static void arena_free(void *p)
{
	/* Only the newest block gives its space back; the rest waits for the next image. */
	if (p && p == arena.last) {
		arena.used = (size_t)((unsigned char *)((block_header *)p - 1) - arena.base);
		arena.last = NULL;
	}
}

#define STBIW_MALLOC(n) arena_alloc(n)
#define STBIW_REALLOC_SIZED(p, old, n) arena_realloc((p), (old), (n))
#define STBIW_FREE(p) arena_free(p)
#define STBIW_ASSERT(x) ((void)0)
#define STBI_WRITE_NO_STDIO
#define STB_IMAGE_WRITE_IMPLEMENTATION
/* The vendored file is not held to rt's warnings. GCC and clang (the compilers rt's flags
 * are written for) know these pragmas; C99 has other compilers ignore them. */
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wcast-qual"
#pragma GCC diagnostic ignored "-Wmissing-prototypes"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wdouble-promotion"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wpedantic"
#include "vendor/stb_image_write.h"
#pragma GCC diagnostic pop

/* stb's write callback returns nothing: remember a failed write for png_write. */
typedef struct {
	write_fn write;
	void *ctx;
	int failed;
} png_output;

static void png_chunk(void *context, void *data, int size)
{
	png_output *out = context;
	if (!out->failed && size > 0 && !out->write(out->ctx, data, (size_t)size))
		out->failed = 1;
}

size_t png_arena_peak(void)
{
	return arena.peak;
}

size_t png_arena_needed(int w, int h)
{
	/* stb at its default compression level 8 keeps up to 16 matches in each of 16384
	 * hash chains; a chain grows 1, 3, 7, 15, 31 entries and, in a bump arena, leaves each
	 * old copy behind: under 512 bytes a chain, 8 MiB in all. The rest scales with the
	 * filtered image (w*3+1)*h: the filtered copy, the deflate output (a little larger
	 * than its input for noise) that doubles as it grows, and the final chunk buffer.
	 * Measured peaks with noise images (png_arena_peak): 7.7 MB at 320x240, 12.2 MB at
	 * 640x480, 59 MB at 2048x2048 - all below this bound. */
	size_t raw = ((size_t)w * 3 + 1) * (size_t)h;
	return raw * 5 + (size_t)16384 * 512 + ((size_t)1 << 20);
}

int png_write(const unsigned char *rgb, int w, int h, write_fn write, void *ctx,
	      unsigned char *base, size_t size)
{
	/* volatile: read after a longjmp back into this function. */
	png_output out;
	volatile int ok = 0;
	out.write = write;
	out.ctx = ctx;
	out.failed = 0;
	arena.base = base;
	arena.size = size;
	arena.used = arena.peak = 0;
	arena.last = NULL;
	if (setjmp(arena.out_of_memory) == 0)
		ok = stbi_write_png_to_func(png_chunk, &out, w, h, 3, rgb, w * 3);
	else
		return 0;
	if (out.failed)
		return -1;
	return ok ? 1 : 0;
}

static unsigned char png_arena[RT_PNG_ARENA_BYTES];

int png_fits(int w, int h)
{
	size_t pixels = (size_t)w * 3 * (size_t)h;
	return pixels <= sizeof png_arena && png_arena_needed(w, h) <= sizeof png_arena - pixels;
}

static int png_begin(sink *self, int width, int height)
{
	png_sink *p = (png_sink *)self;
	if (!png_fits(width, height)) {
		self->error = "image too large for PNG output (its encoder's memory is the fixed "
			      "RT_PNG_ARENA_BYTES arena; raise it in src/config.h, or write .ppm)";
		return 0;
	}
	p->width = width;
	p->height = height;
	p->rows = 0;
	/* The pixels sit at the start of the arena; the encoder works in the rest. */
	p->rgb = png_arena;
	return 1;
}

static int png_row(sink *self, const vec3 *colors, const int *ids)
{
	png_sink *p = (png_sink *)self;
	(void)ids;
	colour_encode_row(colors, p->width, p->rgb + (size_t)p->rows * (size_t)p->width * 3);
	p->rows++;
	return 1;
}

static int png_end(sink *self)
{
	png_sink *p = (png_sink *)self;
	size_t pixels = (size_t)p->width * 3 * (size_t)p->height;
	int status = png_write(p->rgb, p->width, p->height, self->write, self->ctx,
			       png_arena + pixels, sizeof png_arena - pixels);
	if (status == 0)
		self->error = "PNG encoder ran out of its fixed memory (RT_PNG_ARENA_BYTES)";
	return status == 1;
}

void png_sink_init(png_sink *p, write_fn write, void *ctx)
{
	sink_init(&p->base, png_begin, png_row, png_end, write, ctx);
	p->width = p->height = p->rows = 0;
	p->rgb = NULL;
}

int png_available(void)
{
	return 1;
}

#else

int png_available(void)
{
	return 0;
}

int png_fits(int w, int h)
{
	(void)w;
	(void)h;
	return 0;
}

void png_sink_init(png_sink *p, write_fn write, void *ctx)
{
	(void)p;
	(void)write;
	(void)ctx;
}

#endif
