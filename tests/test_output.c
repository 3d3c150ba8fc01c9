/* test_output.c - the output sinks: ASCII and ANSI previews and the PNG encoder's arena.
 * See LICENSE for copyright and licence. */
#include <string.h>

#include "png.h"
#include "preview.h"
#include "test.h"

/* A memory write callback. */
static char captured[1 << 16];
static size_t captured_length;

static int capture(void *ctx, const void *data, size_t n)
{
	(void)ctx;
	if (captured_length + n > sizeof captured)
		return 0;
	memcpy(captured + captured_length, data, n);
	captured_length += n;
	return 1;
}


static vec3 grey(real v) { return vec_make(v, v, v); }

/* Feeds rows of one colour each into a preview sink. */
static void preview_rows(enum preview_mode mode, int width, const vec3 *row_colors, int rows)
{
	static vec3 row[64];
	preview_sink p;
	int x, y;
	captured_length = 0;
	preview_sink_init(&p, mode, capture, NULL);
	CHECK(p.base.begin(&p.base, width, rows));
	for (y = 0; y < rows; y++) {
		for (x = 0; x < width; x++)
			row[x] = row_colors[y];
		CHECK(p.base.row(&p.base, row, NULL));
	}
	CHECK(p.base.end(&p.base));
	captured[captured_length] = '\0';
}

static void test_ascii(void)
{
	vec3 rows[4];
	size_t i;
	/* Black and white cells: the ends of the ramp. */
	rows[0] = rows[1] = grey(REAL_C(0.0));
	rows[2] = rows[3] = grey(REAL_C(1.0));
	preview_rows(PREVIEW_ASCII, 5, rows, 4);
	CHECK_STR(captured, "     \n@@@@@\n");
	/* A cell averages its two halves: black over white is mid-grey, not an end. */
	rows[0] = grey(REAL_C(0.0));
	rows[1] = grey(REAL_C(1.0));
	preview_rows(PREVIEW_ASCII, 3, rows, 2);
	CHECK_INT(captured_length, 4);
	CHECK_INT(captured[0], preview_ramp[127 * 10 / 256]);
	/* 50% grey in sRGB (linear 0.214) sits mid-ramp. */
	rows[0] = rows[1] = grey(REAL_C(0.214));
	preview_rows(PREVIEW_ASCII, 2, rows, 2);
	CHECK(captured[0] == '=' || captured[0] == '-');
	/* An odd last row fills its cell alone. */
	rows[0] = grey(REAL_C(1.0));
	preview_rows(PREVIEW_ASCII, 2, rows, 1);
	CHECK_STR(captured, "@@\n");
	/* Never an escape or anything outside printable 7-bit ASCII. */
	rows[0] = vec_make(REAL_C(1.0), REAL_C(0.0), REAL_C(0.5));
	rows[1] = vec_make(REAL_C(0.0), REAL_C(0.3), REAL_C(0.9));
	preview_rows(PREVIEW_ASCII, 7, rows, 2);
	for (i = 0; i < captured_length; i++)
		CHECK(captured[i] == '\n' || (captured[i] >= 32 && captured[i] < 127));
}

static void test_ansi(void)
{
	vec3 rows[2];
	rows[0] = vec_make(REAL_C(1.0), REAL_C(0.0), REAL_C(0.0));
	rows[1] = vec_make(REAL_C(0.0), REAL_C(0.0), REAL_C(1.0));
	/* 24-bit: colours once (they do not change along the line), three half blocks, reset. */
	preview_rows(PREVIEW_ANSI_24, 3, rows, 2);
	CHECK_STR(captured, "\033[38;2;255;0;0m\033[48;2;0;0;255m"
			    "\xE2\x96\x80\xE2\x96\x80\xE2\x96\x80\033[0m\n");
	/* 256 colours: the palette's pure red (196) over pure blue (21). */
	preview_rows(PREVIEW_ANSI_256, 2, rows, 2);
	CHECK_STR(captured, "\033[38;5;196m\033[48;5;21m\xE2\x96\x80\xE2\x96\x80\033[0m\n");
	/* Greys map to the grey ramp: linear 0.214 is sRGB 127, nearest grey 128 = 244. */
	rows[0] = rows[1] = grey(REAL_C(0.214));
	preview_rows(PREVIEW_ANSI_256, 1, rows, 2);
	CHECK(strstr(captured, "\033[38;5;244m") != NULL);
}

static void test_preview_size(void)
{
	int w, h;
	/* 80 columns of a square scene: 40 rows of cells, 80 pixel rows. */
	preview_size(80, 512, 512, &w, &h);
	CHECK_INT(w, 80);
	CHECK_INT(h, 80);
	/* 4:3 at 60 columns: 45 pixel rows, rounded up to whole cells: 46. */
	preview_size(60, 320, 240, &w, &h);
	CHECK_INT(h, 46);
	/* A very wide scene still gets one row of cells. */
	preview_size(10, 1000, 10, &w, &h);
	CHECK_INT(h, 2);
}

#if !REAL_FIXED
static int discard(void *ctx, const void *data, size_t n)
{
	(void)ctx;
	(void)data;
	(void)n;
	return 1;
}

static void test_png_arena(void)
{
	static unsigned char rgb[32 * 24 * 3], arena[10 << 20];
	size_t i;
	for (i = 0; i < sizeof rgb; i++)
		rgb[i] = (unsigned char)(i * 7919 % 251);
	/* Enough memory: a PNG signature comes out. */
	captured_length = 0;
	CHECK_INT(png_write(rgb, 32, 24, capture, NULL, arena, sizeof arena), 1);
	CHECK(captured_length > 8 && memcmp(captured, "\x89PNG\r\n\x1a\n", 8) == 0);
	CHECK(png_arena_needed(32, 24) <= sizeof arena);
	/* Too little memory: a clean failure (0), whatever the encoder was doing, and the
	 * same arena still works afterwards. */
	CHECK_INT(png_write(rgb, 32, 24, capture, NULL, arena, 4096), 0);
	CHECK_INT(png_write(rgb, 32, 24, capture, NULL, arena, 100), 0);
	captured_length = 0;
	CHECK_INT(png_write(rgb, 32, 24, capture, NULL, arena, sizeof arena), 1);
	CHECK(png_arena_peak() <= png_arena_needed(32, 24));
	/* The bound holds for incompressible pixels, the encoder's worst case. */
	{
		static unsigned char noise[160 * 120 * 3];
		test_seed(1);
		for (i = 0; i < sizeof noise; i++)
			noise[i] = (unsigned char)(test_random_bits() >> 24);
		captured_length = 0;
		CHECK_INT(png_write(noise, 160, 120, discard, NULL, arena, sizeof arena), 1);
		CHECK(png_arena_peak() <= png_arena_needed(160, 120));
	}
	/* The static arena takes 2048 x 2048, not 8192 x 8192. */
	CHECK(png_fits(2048, 2048));
	CHECK(!png_fits(8192, 8192));
}
#else
/* stb_image_write has floating-point code: the Q16.16 build, which has none at all, goes
 * without PNG, and says so. */
static void test_png_arena(void)
{
	CHECK(!png_available());
}
#endif

void suite_output(void)
{
	test_ascii();
	test_ansi();
	test_preview_size();
	test_png_arena();
}
