/* test_output.c - the output sinks: ASCII and ANSI previews.
 * See LICENSE for copyright and licence. */
#include <string.h>

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


void suite_output(void)
{
	test_ascii();
	test_ansi();
	test_preview_size();
}
