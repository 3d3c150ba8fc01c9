/* options.c - rt's command line on a host: the options in GNU's forms (cmdline.c), each
 * value checked, and the combinations that make no sense refused with status 2.
 * See LICENSE for copyright and licence. */
#define _POSIX_C_SOURCE 200809L

#include "options.h"

#include <ctype.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cmdline.h"
#include "diag.h"
#include "parallel.h"
#include "term.h"

#define RT_VERSION "0.2.0"

/* --ids writes 1 + each object's index in 16 bits, or beyond 65,534 objects in 24; 0 is
 * "no object". */
RT_STATIC_ASSERT(ids_fit_24_bits, RT_MAX_OBJECTS < 16777216L);

static const char usage_text[] =
	"Usage: rt [OPTION]... SCENE\n"
	"Render SCENE (NFF with rt's extensions; - reads standard input) by recursive\n"
	"ray tracing.\n"
	"The image goes to standard output as binary PPM; on a terminal, rt shows a\n"
	"preview instead.\n"
	"\n"
	"  -o, --output FILE  write to FILE, in the format its name ends with: .ppm,\n"
	"               .png, .txt (ASCII preview), .ans (ANSI colour preview) or .pgm\n"
	"               (object IDs); FILE is replaced only when the render succeeds;\n"
	"               - is standard output\n"
	"  -f, --format FORMAT\n"
	"               ppm, png, txt, ans or pgm, where no file name says it\n"
	"  -s, --size WxH  image size in pixels, overriding the scene's resolution\n"
	"  -d, --depth N  ray tree depth, 1 to " RT_STRINGIFY(RT_MAX_DEPTH) " (eye ray = 1)\n"
	"  -a, --antialias  adaptive antialiasing: rays through the pixels' corners, and\n"
	"               more rays only where they differ (--aa-threshold, --aa-depth)\n"
	"  --aa-threshold T  halve a pixel whose corners differ by more than T (0 to 1,\n"
	"               default 0.02) in a channel of the sRGB image, or see different\n"
	"               objects, and its halves by 4 T, 16 T...; lower is smoother and\n"
	"               slower (implies -a)\n"
	"  --aa-depth N halve a pixel's side at most N times, 1 to " RT_STRINGIFY(
		ANTIALIAS_MAX_DEPTH) " (default 2:\n"
	"               up to 25 rays a pixel; 4: 289) (implies -a)\n"
	"  -j, --jobs N render with N processes, 1 to " RT_STRINGIFY(
		RT_MAX_JOBS) " (default: one per\n"
	"               processor online); the image is the same for every N\n"
	"  --ascii      ASCII-art preview (7-bit, no escape sequences)\n"
	"  --ansi       colour preview with half-blocks (24-bit if COLORTERM says so,\n"
	"               else 256 colours), whatever NO_COLOR and TERM say\n"
	"  --cols N     preview width in characters (default: the terminal's, else 80;\n"
	"               no taller than the terminal, less a line for the prompt)\n"
	"  --colours PIPELINE  srgb (the default: scene colours are sRGB, lit in linear\n"
	"               light, written as sRGB) or classic (NFF's values as they are, no\n"
	"               curve either way); overrides the scene's own `colours` command\n"
	"  --ids        instead of colours, write a 16-bit PGM of the object each pixel's\n"
	"               eye ray hits first (1 + its index in the scene; 0 for none); past\n"
	"               65,534 objects a PPM whose RGB bytes are a 24-bit ID (-o x.ppm)\n"
	"  --rows Y0:Y1 render only rows Y0 to Y1-1, as a PPM of that band (for splitting\n"
	"               a render across machines: see docs/speed.md)\n"
	"  --spd        SPD testing procedure: corner rays, depth 5, no weight cutoff\n"
	"  --stats      print ray counts and timings on standard error\n"
	"  -q, --quiet  no warnings (a skipped degenerate object); errors still print\n"
	"  --time-limit S  stop after S seconds of wall-clock time (a decimal, e.g.\n"
	"               2.5): exit status 1, no -o file written or replaced\n"
	"  --print-size print the image size the other options give, as 'W H', and exit\n"
	"  -h, --help   show this help and exit\n"
	"  --version    show the version and exit\n"
	"\n"
	"Options take their values as -s320x240 or -s 320x240, --size=320x240 or\n"
	"--size 320x240; short options without values combine (-qa); a long option may\n"
	"be shortened to any beginning no other shares (--out); -- ends the options.\n"
	"\n"
	"Exit status: 0 on success, 1 on a scene or output error, 2 on a usage error.\n";

static int usage_error(const char *fmt, const char *arg)
{
	fprintf(stderr, "rt: ");
	fprintf(stderr, fmt, arg);
	fprintf(stderr, "\nTry 'rt --help' for more information.\n");
	return 2;
}

/* Parses a decimal integer in [min, max] that ends at `stop`; *rest is after it. */
static int parse_int(const char *text, char stop, long min, long max, int *out,
		     const char **rest)
{
	char *end;
	long value;
	if (*text < '0' || *text > '9')
		return 0;
	errno = 0;
	value = strtol(text, &end, 10);
	/* An x between numbers may be written X (640X480). */
	if (errno || (*end != stop && !(stop == 'x' && *end == 'X')) || value < min || value > max)
		return 0;
	*out = (int)value;
	if (rest)
		*rest = end + 1;
	return 1;
}

/* The longest --time-limit, in seconds: about three years. */
#define TIME_LIMIT_MAX_SECONDS 100000000uL

/* Parses --time-limit's seconds, digits with an optional fraction (no floating point: the
 * fixed-point build has none), into microseconds; 0 when it is not such a number, or not
 * from a microsecond to TIME_LIMIT_MAX_SECONDS. Digits past the sixth decimal drop. */
static unsigned long long parse_seconds(const char *text)
{
	unsigned long long seconds = 0, micros = 0;
	const char *p = text;
	if (*p < '0' || *p > '9')
		return 0;
	for (; *p >= '0' && *p <= '9'; p++) {
		seconds = seconds * 10u + (unsigned)(*p - '0');
		if (seconds > TIME_LIMIT_MAX_SECONDS)
			return 0;
	}
	if (*p == '.') {
		unsigned long long scale = 100000u; /* of the first decimal, in microseconds */
		for (p++; *p >= '0' && *p <= '9'; p++, scale /= 10u)
			micros += scale * (unsigned)(*p - '0');
	}
	if (*p != '\0')
		return 0;
	micros += seconds * 1000000u;
	return micros > TIME_LIMIT_MAX_SECONDS * 1000000u ? 0 : micros;
}

/* The format a name gives (-f's, or a file's ending without the dot), in either case
 * (PNG, IMAGE.PNG). */
static enum format format_of_name(const char *name)
{
	static const char names[][4] = {"ppm", "png", "txt", "ans", "pgm"};
	static const enum format formats[] = {FORMAT_PPM, FORMAT_PNG, FORMAT_ASCII, FORMAT_ANSI,
					      FORMAT_IDS};
	size_t i, k;
	for (i = 0; i < sizeof names / sizeof names[0]; i++) {
		for (k = 0; k < 3 && tolower((unsigned char)name[k]) == names[i][k]; k++)
			;
		if (k == 3 && name[3] == '\0')
			return formats[i];
	}
	return FORMAT_DEFAULT;
}

/* The output format a file name asks for, by its ending (there must be a name before it). */
static enum format format_of(const char *path)
{
	size_t n = strlen(path);
	return n > 4 && path[n - 4] == '.' ? format_of_name(path + n - 3) : FORMAT_DEFAULT;
}

/* Sets the format, refusing two different ones. */
static int choose_format(options *o, enum format f, const char *why)
{
	/* --ids may be named .ppm: scenes of 65,535 objects and more get their IDs in one. */
	if ((o->format == FORMAT_IDS && f == FORMAT_PPM && why == o->output_path) ||
	    (o->format == FORMAT_PPM && f == FORMAT_IDS && o->output_path &&
	     format_of(o->output_path) == FORMAT_PPM))
		f = FORMAT_IDS;
	else if (o->format != FORMAT_DEFAULT && o->format != f)
		return usage_error("conflicting output formats ('%s')", why);
	o->format = f;
	return -1;
}

int options_stdout_status(void)
{
	if (fflush(stdout) == 0 && !ferror(stdout))
		return 0;
	diag_error(NULL, 0, "write error: standard output: %s", strerror(errno));
	return 1;
}

/* A decimal fraction from 0 to 1 (at most 6 decimals) as sRGB codes, 0 to 255, rounded;
 * -1 if it is not one. */
static int parse_fraction_codes(const char *text)
{
	long whole = 0, millionths = 0, scale = 100000;
	const char *p = text;
	if (*p < '0' || *p > '9') {
		if (*p != '.')
			return -1;
	}
	while (*p >= '0' && *p <= '9' && whole <= 1)
		whole = whole * 10 + (*p++ - '0');
	if (*p == '.')
		for (p++; *p >= '0' && *p <= '9' && scale > 0; p++, scale /= 10)
			millionths += (*p - '0') * scale;
	if (*p != '\0' || p == text || whole > 1 || (whole == 1 && millionths > 0))
		return -1;
	return (int)((whole * 1000000 + millionths) * 255 + 500000) / 1000000;
}

/* What the options mean together: the defaults they leave, and the combinations that
 * make no sense. Returns -1 to go on, else the exit status. */
static int check_combinations(options *o)
{
	if (!o->scene_path)
		return usage_error("no scene file given%s", "");
	o->scene_name = strcmp(o->scene_path, "-") == 0 ? "<stdin>" : o->scene_path;
	if (o->output_path && o->format == FORMAT_DEFAULT)
		return usage_error("cannot tell the format of '%s' (name it .ppm, .png, .txt, .ans "
				   "or .pgm, or give -f)",
				   o->output_path);
	/* On a terminal, binary PPM would only garble it: show a preview instead. */
	if (o->format == FORMAT_DEFAULT) {
		o->chosen = !o->output_path && !o->to_stdout && term_is_tty(1);
		o->format = o->chosen ? FORMAT_ANSI : FORMAT_PPM;
	}
	if (o->row_end && o->format != FORMAT_PPM && o->format != FORMAT_IDS)
		return usage_error("--rows writes PPM bands only%s", "");
	if (o->spd && !RT_CORNER_SAMPLING)
		return usage_error("--spd needs corner sampling, which this build leaves out "
				   "(RT_CORNER_SAMPLING)%s",
				   "");
	if (o->antialias && o->spd)
		return usage_error("-a and --spd are two ways of sampling; choose one%s", "");
	if (o->antialias && o->format == FORMAT_IDS)
		return usage_error("--ids needs one eye ray per pixel, not -a's%s", "");
	if (o->antialias && !RT_CORNER_SAMPLING)
		return usage_error("-a needs corner sampling, which this build leaves out "
				   "(RT_CORNER_SAMPLING)%s",
				   "");
	if (o->format == FORMAT_IDS && o->spd)
		return usage_error("--ids needs one eye ray per pixel, not --spd's corners%s", "");
	return -1;
}

/* Writes a duration in microseconds as seconds with six decimals. */

/* The options: long name, short name, whether a value follows; in enum option_id's order. */
enum option_id {
	OPT_OUTPUT, OPT_FORMAT, OPT_SIZE, OPT_DEPTH, OPT_ANTIALIAS, OPT_AA_THRESHOLD, OPT_AA_DEPTH,
	OPT_JOBS, OPT_ASCII, OPT_ANSI, OPT_COLS, OPT_IDS, OPT_ROWS, OPT_SPD, OPT_STATS, OPT_QUIET,
	OPT_TIME_LIMIT, OPT_PRINT_SIZE, OPT_HELP, OPT_VERSION, OPT_COLOURS, OPTION_COUNT
};
static const cmdline_option option_table[OPTION_COUNT] = {
	{"output", 'o', 1},      {"format", 'f', 1},   {"size", 's', 1},      {"depth", 'd', 1},
	{"antialias", 'a', 0},   {"aa-threshold", 0, 1}, {"aa-depth", 0, 1},  {"jobs", 'j', 1},
	{"ascii", 0, 0},         {"ansi", 0, 0},       {"cols", 0, 1},        {"ids", 0, 0},
	{"rows", 0, 1},          {"spd", 0, 0},        {"stats", 0, 0},       {"quiet", 'q', 0},
	{"time-limit", 0, 1},    {"print-size", 0, 0}, {"help", 'h', 0},      {"version", 0, 0},
	{"colours", 0, 1}};

/* One option and its value into o. Returns -1 to go on, else the exit status. */
static int take_option(options *o, enum option_id id, const char *value, const char *written)
{
	const char *rest;
	enum format f;
	switch (id) {
	case OPT_HELP:
		fputs(usage_text, stdout);
		return options_stdout_status();
	case OPT_VERSION:
		printf("rt %s (real = %s)\n", RT_VERSION, REAL_NAME);
		return options_stdout_status();
	case OPT_STATS:
		o->stats = 1;
		return -1;
	case OPT_QUIET:
		o->quiet = 1;
		return -1;
	case OPT_PRINT_SIZE:
		o->size_only = 1;
		return -1;
	case OPT_SPD:
		o->spd = 1;
		return -1;
	case OPT_ANTIALIAS:
		o->antialias = 1;
		return -1;
	case OPT_IDS:
		return choose_format(o, FORMAT_IDS, written);
	case OPT_ASCII:
	case OPT_ANSI:
		return choose_format(o, id == OPT_ASCII ? FORMAT_ASCII : FORMAT_ANSI, written);
	case OPT_OUTPUT:
		/* One image per run: a second -o is a mistake, not a choice. */
		if (o->output_path || o->to_stdout)
			return usage_error("more than one output file given ('%s')", value);
		if (strcmp(value, "-") == 0) {
			o->to_stdout = 1;
			return -1;
		}
		o->output_path = value;
		/* A name that says no format needs -f (checked once all are read). */
		f = format_of(value);
		return f == FORMAT_DEFAULT ? -1 : choose_format(o, f, value);
	case OPT_FORMAT:
		f = format_of_name(value);
		if (f == FORMAT_DEFAULT)
			return usage_error("bad format '%s' (expected ppm, png, txt, ans or pgm)", value);
		return choose_format(o, f, value);
	case OPT_SIZE:
		if (!parse_int(value, 'x', 1, RT_MAX_WIDTH, &o->width, &rest) ||
		    !parse_int(rest, '\0', 1, RT_MAX_HEIGHT, &o->height, NULL))
			return usage_error("bad size '%s' (expected WxH, e.g. 320x240, at most " RT_STRINGIFY(
						   RT_MAX_WIDTH) "x" RT_STRINGIFY(RT_MAX_HEIGHT) ")",
					   value);
		return -1;
	case OPT_DEPTH:
		if (!parse_int(value, '\0', 1, RT_MAX_DEPTH, &o->depth, NULL))
			return usage_error("bad depth '%s' (expected 1 to " RT_STRINGIFY(RT_MAX_DEPTH) ")",
					   value);
		return -1;
	case OPT_JOBS:
		if (!parse_int(value, '\0', 1, RT_MAX_JOBS, &o->jobs, NULL))
			return usage_error("bad job count '%s' (expected 1 to " RT_STRINGIFY(
						   RT_MAX_JOBS) ")",
					   value);
		return -1;
	case OPT_AA_DEPTH:
		o->antialias = 1;
		if (!parse_int(value, '\0', 1, ANTIALIAS_MAX_DEPTH, &o->aa.depth, NULL))
			return usage_error("bad antialiasing depth '%s' (expected 1 to " RT_STRINGIFY(
						   ANTIALIAS_MAX_DEPTH) ")",
					   value);
		return -1;
	case OPT_AA_THRESHOLD:
		o->antialias = 1;
		o->aa.threshold = parse_fraction_codes(value);
		if (o->aa.threshold < 0)
			return usage_error("bad antialiasing threshold '%s' (expected 0 to 1, e.g. 0.02)",
					   value);
		return -1;
	case OPT_COLOURS:
		if (strcmp(value, "srgb") != 0 && strcmp(value, "classic") != 0)
			return usage_error("bad colour pipeline '%s' (expected srgb or classic)", value);
		o->colours = strcmp(value, "classic") == 0 ? COLOUR_CLASSIC : COLOUR_SRGB;
		return -1;
	case OPT_TIME_LIMIT:
		o->time_limit = value;
		o->time_limit_micros = parse_seconds(value);
		if (!o->time_limit_micros)
			return usage_error("bad time limit '%s' (expected seconds, e.g. 2.5, from "
					   "0.000001 to 100000000)",
					   value);
		return -1;
	case OPT_COLS:
		if (!parse_int(value, '\0', 1, RT_MAX_WIDTH, &o->columns, NULL))
			return usage_error("bad column count '%s' (expected 1 to " RT_STRINGIFY(
						   RT_MAX_WIDTH) ")",
					   value);
		return -1;
	case OPT_ROWS:
		if (!parse_int(value, ':', 0, RT_MAX_HEIGHT - 1, &o->row_first, &rest) ||
		    !parse_int(rest, '\0', o->row_first + 1, RT_MAX_HEIGHT, &o->row_end, NULL))
			return usage_error("bad rows '%s' (expected Y0:Y1 with 0 <= Y0 < Y1)", value);
		return -1;
	default:
		return -1;
	}
}

int options_parse(int argc, char **argv, options *o)
{
	cmdline c;
	int id, status;
	memset(o, 0, sizeof *o);
	o->colours = -1;
	o->aa.depth = 2;
	o->aa.threshold = 5; /* 0.02 of 255, rounded */
	cmdline_start(&c, argc, argv);
	while ((id = cmdline_next(&c, option_table, OPTION_COUNT)) != CMDLINE_END) {
		if (id == CMDLINE_ERROR)
			return usage_error(c.error, c.written);
		if (id == CMDLINE_OPERAND) {
			if (o->scene_path)
				return usage_error("more than one scene given ('%s')", c.value);
			o->scene_path = c.value;
			continue;
		}
		status = take_option(o, (enum option_id)id, c.value, c.written);
		if (status >= 0)
			return status;
	}
	return check_combinations(o);
}
