/* preview.c - ASCII and ANSI previews, streamed a text line at a time.
 * ASCII picks one of ten characters by the cell's lightness (taken from the sRGB-encoded
 * value, which is close to how light a grey looks). ANSI draws U+2580 UPPER HALF BLOCK
 * with the upper pixel as foreground and the lower one as background, and sends a colour
 * only when it changes. See LICENSE for copyright and licence. */
#include "preview.h"

#include <stdint.h>
#include <stdio.h>

#include "colour.h"

const char preview_ramp[] = " .:-=+*#%@";
#define RAMP_LENGTH (int)(sizeof preview_ramp - 1)

/* Text goes out in chunks, not whole lines, so memory does not grow with the width (a
 * 24-bit colour line is ~40 bytes a cell). A chunk is sent when the next cell might not
 * fit: a cell writes at most two 24-bit escapes (19 bytes each) and a 3-byte glyph. */
#define CHUNK_BYTES 256 /* text buffered before a write */
#define CELL_BYTES 48   /* most bytes one cell can add, with the line's end */

typedef struct {
	preview_sink *p;
	char text[CHUNK_BYTES];
	int n;  /* bytes buffered */
	int ok; /* every write so far succeeded */
} chunk;

/* Sends the buffered text when it might not hold another cell (or always, at the end). */
static void send(chunk *c, int always)
{
	if (c->n > 0 && (always || c->n > CHUNK_BYTES - CELL_BYTES)) {
		c->ok = c->ok && c->p->base.write(c->p->base.ctx, c->text, (size_t)c->n);
		c->n = 0;
	}
}

void preview_size(int columns, int scene_width, int scene_height, int *width, int *height)
{
	/* Square pixels, two to a cell: the pixel rows the aspect asks for, rounded to the
	 * nearest, then up to whole cells. */
	long pixels = (long)wide_udiv((uint64_t)columns * (uint64_t)scene_height +
					       (uint64_t)(scene_width / 2),
				       (uint64_t)scene_width);
	long cells = (pixels + 1) / 2;
	*width = columns;
	*height = (int)(cells < 1 ? 2 : 2 * (cells > RT_MAX_HEIGHT / 2 ? RT_MAX_HEIGHT / 2 : cells));
}

/* BT.709 luma of sRGB bytes, 0..255. */
static int luma(const unsigned char *rgb)
{
	return (54 * rgb[0] + 183 * rgb[1] + 19 * rgb[2]) / 256;
}

/* OKLab (Ottosson 2020: a perceptual space in which distance follows seen difference) of
 * a linear RGB colour, through its definition's two matrices and a cube root. */
typedef struct {
	real l, a, b;
} oklab;

static oklab oklab_of(real r, real g, real b)
{
	real third = REAL_C(0.333333333333333333);
	real l = real_pow(real_dot3(REAL_C(0.4122214708), REAL_C(0.5363325363), REAL_C(0.0514459929), r,
				    g, b),
			  third);
	real m = real_pow(real_dot3(REAL_C(0.2119034982), REAL_C(0.6806995451), REAL_C(0.1073969566), r,
				    g, b),
			  third);
	real s = real_pow(real_dot3(REAL_C(0.0883024619), REAL_C(0.2817188376), REAL_C(0.6299787005), r,
				    g, b),
			  third);
	oklab out;
	out.l = real_dot3(REAL_C(0.2104542553), REAL_C(0.7936177850), REAL_C(-0.0040720468), l, m, s);
	out.a = real_dot3(REAL_C(1.9779984951), REAL_C(-2.4285922050), REAL_C(0.4505937099), l, m, s);
	out.b = real_dot3(REAL_C(0.0259040371), REAL_C(0.7827717662), REAL_C(-0.8086757660), l, m, s);
	return out;
}

/* xterm's 256 colours from 16 on: the 6x6x6 cube, then 24 greys (8, 18, ..., 238). */
#define PALETTE_COLOURS 240

/* The palette in OKLab, and each sRGB code's linear value, made once. */
static oklab palette_lab[PALETTE_COLOURS];
static real code_linear[256];
static int palette_ready;

static void make_palette(void)
{
	static const unsigned char level[6] = {0, 95, 135, 175, 215, 255};
	int i;
	for (i = 0; i < 256; i++) {
		real v = real_div(real_from_int(i), REAL_C(255.0));
		code_linear[i] = colour_srgb_to_linear(vec_make(v, v, v)).x;
	}
	for (i = 0; i < PALETTE_COLOURS; i++) {
		int r = i < 216 ? level[i / 36] : 8 + 10 * (i - 216);
		int g = i < 216 ? level[i / 6 % 6] : r, b = i < 216 ? level[i % 6] : r;
		palette_lab[i] = oklab_of(code_linear[r], code_linear[g], code_linear[b]);
	}
	palette_ready = 1;
}

/* The palette colour nearest to an sRGB colour in OKLab: the one a viewer takes for it.
 * (Nearest in RGB made the violet sky grey and orange glass olive: RGB distance weighs
 * a step in blue as much as one in green, and hue not at all.) */
static int palette_index(const unsigned char *rgb)
{
	oklab want;
	int i, best = 0;
	real best_distance = REAL_MAX;
	if (!palette_ready)
		make_palette();
	want = oklab_of(code_linear[rgb[0]], code_linear[rgb[1]], code_linear[rgb[2]]);
	for (i = 0; i < PALETTE_COLOURS; i++) {
		real dl = palette_lab[i].l - want.l, da = palette_lab[i].a - want.a,
		     db = palette_lab[i].b - want.b;
		real distance = real_dot3(dl, da, db, dl, da, db);
		if (distance < best_distance) {
			best_distance = distance;
			best = i;
		}
	}
	return 16 + best;
}

/* Appends the escape that sets the foreground (layer 38) or background (48) colour. */
static int set_color(char *out, int layer, enum preview_mode mode, const unsigned char *rgb)
{
	if (mode == PREVIEW_ANSI_24)
		return sprintf(out, "\033[%d;2;%d;%d;%dm", layer, rgb[0], rgb[1], rgb[2]);
	return sprintf(out, "\033[%d;5;%dm", layer, palette_index(rgb));
}

/* Would the terminal show a different colour? (In 256 colours, many pixels share one.) */
static int changed(enum preview_mode mode, const unsigned char *a, const unsigned char *b)
{
	if (mode == PREVIEW_ANSI_256)
		return palette_index(a) != palette_index(b);
	return a[0] != b[0] || a[1] != b[1] || a[2] != b[2];
}

/* Writes the text line for an upper and a lower pixel row. */
static int emit_line(preview_sink *p, const unsigned char *upper, const unsigned char *lower)
{
	static chunk c;
	int x;
	const unsigned char *fg = NULL, *bg = NULL; /* colours in effect on this line */
	c.p = p;
	c.n = 0;
	c.ok = 1;
	for (x = 0; x < p->width; x++) {
		const unsigned char *u = upper + 3 * x, *l = lower + 3 * x;
		send(&c, 0);
		if (!RT_PREVIEW_COLOR || p->mode == PREVIEW_ASCII) {
			int lightness = (luma(u) + luma(l)) / 2;
			c.text[c.n++] = preview_ramp[lightness * RAMP_LENGTH / 256];
			continue;
		}
		if (!fg || changed(p->mode, fg, u))
			c.n += set_color(c.text + c.n, 38, p->mode, u);
		if (!bg || changed(p->mode, bg, l))
			c.n += set_color(c.text + c.n, 48, p->mode, l);
		fg = u;
		bg = l;
		c.text[c.n++] = (char)0xE2; /* U+2580 in UTF-8 */
		c.text[c.n++] = (char)0x96;
		c.text[c.n++] = (char)0x80;
	}
	send(&c, 0);
	if (RT_PREVIEW_COLOR && p->mode != PREVIEW_ASCII)
		c.n += sprintf(c.text + c.n, "\033[0m");
	c.text[c.n++] = '\n';
	send(&c, 1);
	return c.ok;
}

static int preview_begin(sink *self, int width, int height)
{
	preview_sink *p = (preview_sink *)self;
	(void)height;
	p->width = width;
	p->have_upper = 0;
	return width >= 1 && width <= RT_MAX_WIDTH;
}

static int preview_row(sink *self, const vec3 *colors, const int *ids)
{
	static unsigned char lower[3 * RT_MAX_WIDTH];
	preview_sink *p = (preview_sink *)self;
	(void)ids;
	if (!p->have_upper) {
		colour_encode_row(colors, p->width, p->upper);
		p->have_upper = 1;
		return 1;
	}
	colour_encode_row(colors, p->width, lower);
	p->have_upper = 0;
	return emit_line(p, p->upper, lower);
}

static int preview_end(sink *self)
{
	preview_sink *p = (preview_sink *)self;
	/* An odd last row fills its cell alone. */
	if (p->have_upper) {
		p->have_upper = 0;
		return emit_line(p, p->upper, p->upper);
	}
	return 1;
}

void preview_sink_init(preview_sink *p, enum preview_mode mode, write_fn write, void *ctx)
{
	sink_init(&p->base, preview_begin, preview_row, preview_end, write, ctx);
	p->mode = RT_PREVIEW_COLOR ? mode : PREVIEW_ASCII;
	p->width = 0;
	p->have_upper = 0;
}
