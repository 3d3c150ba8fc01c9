/* main.c - the command line: options, scene in, image or preview out, statistics.
 * See LICENSE for copyright and licence. */
#define _POSIX_C_SOURCE 200809L

#include <ctype.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "camera.h"
#include "diag.h"
#include "load.h"
#include "output.h"
#include "parallel.h"
#include "png.h"
#include "preview.h"
#include "render.h"
#include "term.h"
#include "trace.h"

#define RT_VERSION "0.2.0"

static const char usage_text[] =
	"Usage: rt [OPTION]... SCENE\n"
	"Render SCENE (NFF with rt's extensions; - reads standard input) by recursive\n"
	"ray tracing.\n"
	"The image goes to standard output as binary PPM; on a terminal, rt shows a\n"
	"preview instead.\n"
	"\n"
	"  -o FILE      write to FILE, in the format its name ends with: .ppm, .png,\n"
	"               .txt (ASCII preview), .ans (ANSI colour preview) or .pgm\n"
	"               (object IDs); FILE is replaced only when the render succeeds;\n"
	"               - is standard output\n"
	"  -f, --format FORMAT\n"
	"               ppm, png, txt, ans or pgm, where no file name says it\n"
	"  -s WxH       image size in pixels, overriding the scene's resolution\n"
	"  -d N         ray tree depth, 1 to " RT_STRINGIFY(RT_MAX_DEPTH) " (eye ray = 1)\n"
	"  -a, --antialias  adaptive antialiasing: rays through the pixels' corners, and\n"
	"               more rays only where they differ (--aa-threshold, --aa-depth)\n"
	"  --aa-threshold T  halve a pixel whose corners differ by more than T (0 to 1,\n"
	"               default 0.02) in a channel of the sRGB image, or see different\n"
	"               objects, and its halves by 4 T, 16 T...; lower is smoother and\n"
	"               slower (implies -a)\n"
	"  --aa-depth N halve a pixel's side at most N times, 1 to " RT_STRINGIFY(ANTIALIAS_MAX_DEPTH) " (default 2:\n"
	"               up to 25 rays a pixel; 4: 289) (implies -a)\n"
	"  -j, --jobs N render with N processes, 1 to " RT_STRINGIFY(PARALLEL_MAX_JOBS) " (default: one per\n"
	"               processor online); the image is the same for every N\n"
	"  --ascii      ASCII-art preview (7-bit, no escape sequences)\n"
	"  --ansi       colour preview with half-blocks (24-bit if COLORTERM says so,\n"
	"               else 256 colours), whatever NO_COLOR and TERM say\n"
	"  --cols N     preview width in characters (default: the terminal's, else 80;\n"
	"               no taller than the terminal, less a line for the prompt)\n"
	"  --ids        instead of colours, write a 16-bit PGM of the object each pixel's\n"
	"               eye ray hits first (1 + its index in the scene; 0 for none)\n"
	"  --rows Y0:Y1 render only rows Y0 to Y1-1, as a PPM of that band (for splitting\n"
	"               a render across machines: see docs/speed.md)\n"
	"  --spd        SPD testing procedure: corner rays, depth 5, no weight cutoff\n"
	"  --stats      print ray counts and timings on standard error\n"
	"  -q, --quiet  no warnings (a skipped degenerate object); errors still print\n"
	"  --time-limit S  stop after S seconds of wall-clock time (a decimal, e.g.\n"
	"               2.5): exit status 1, no -o file written or replaced\n"
	"  --size       print the image size the other options give, as 'W H', and exit\n"
	"  --help       show this help and exit\n"
	"  --version    show the version and exit\n"
	"\n"
	"Exit status: 0 on success, 1 on a scene or output error, 2 on a usage error.\n";

enum format { FORMAT_DEFAULT, FORMAT_PPM, FORMAT_PNG, FORMAT_ASCII, FORMAT_ANSI, FORMAT_IDS };

/* --ids writes object numbers as 16-bit samples; 0 is "no object". */
RT_STATIC_ASSERT(ids_fit_16_bits, RT_MAX_OBJECTS < 65536);

typedef struct {
	const char *scene_path;  /* "-": standard input */
	const char *scene_name;  /* for messages: the path, or <stdin> */
	const char *output_path; /* NULL: standard output */
	int to_stdout;           /* -o - */
	enum format format;
	int width, height; /* 0: the scene's */
	int depth;         /* 0: the scene's */
	int jobs;          /* processes rendering; 0: one per processor */
	int antialias;     /* -a */
	antialias aa;      /* its settings */
	int columns;       /* preview width, 0: the terminal's */
	int row_first, row_end; /* --rows: [first, end); end 0 for all rows */
	int spd;
	int stats;
	int quiet;     /* -q: no warnings */
	int chosen;    /* the preview is rt's choice for a terminal, not asked for */
	int size_only; /* --size: print the image size and stop */
	const char *time_limit; /* --time-limit as given; NULL for none */
	unsigned long long time_limit_micros;
} options;

/* A preview of a width x height scene that fits the terminal: as wide as it is, and no
 * taller than its lines less one (the prompt's), the aspect kept (fewer columns where
 * the height is the bound). */
static void fit_preview(int width, int height, int *pixels_wide, int *pixels_high)
{
	int columns = term_columns(), lines = term_lines();
	preview_size(columns, width, height, pixels_wide, pixels_high);
	while (lines > 1 && *pixels_high / 2 > lines - 1 && columns > 1)
		preview_size(--columns, width, height, pixels_wide, pixels_high);
}

/* Scene storage is large and lives for the whole run. */
static scene the_scene;
static tracer the_tracer;

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
	if (o->format != FORMAT_DEFAULT && o->format != f)
		return usage_error("conflicting output formats ('%s')", why);
	o->format = f;
	return -1;
}

/* Returns -1 to go on, else the exit status. */
/* The exit status after a text answer on standard output (--help, --version, --size): 1,
 * with a message, when it could not be written (a full disk, /dev/full). */
static int stdout_status(void)
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

static int parse_options(int argc, char **argv, options *o)
{
	int i, status;
	memset(o, 0, sizeof *o);
	o->aa.depth = 2;
	o->aa.threshold = 5; /* 0.02 of 255, rounded */
	for (i = 1; i < argc; i++) {
		const char *a = argv[i];
		const char *value = NULL, *rest;
		if (strcmp(a, "--help") == 0) {
			fputs(usage_text, stdout);
			return stdout_status();
		} else if (strcmp(a, "--version") == 0) {
			printf("rt %s (real = %s)\n", RT_VERSION, REAL_NAME);
			return stdout_status();
		} else if (strcmp(a, "-a") == 0 || strcmp(a, "--antialias") == 0) {
			o->antialias = 1;
		} else if (strcmp(a, "--stats") == 0) {
			o->stats = 1;
		} else if (strcmp(a, "-q") == 0 || strcmp(a, "--quiet") == 0) {
			o->quiet = 1;
		} else if (strcmp(a, "--size") == 0) {
			o->size_only = 1;
		} else if (strcmp(a, "--spd") == 0) {
			o->spd = 1;
		} else if (strcmp(a, "--ids") == 0) {
			status = choose_format(o, FORMAT_IDS, a);
			if (status >= 0)
				return status;
		} else if (strcmp(a, "--ascii") == 0 || strcmp(a, "--ansi") == 0) {
			status = choose_format(o, strcmp(a, "--ascii") == 0 ? FORMAT_ASCII : FORMAT_ANSI, a);
			if (status >= 0)
				return status;
		} else if (strcmp(a, "-o") == 0 || strcmp(a, "-s") == 0 || strcmp(a, "-d") == 0 ||
			   strcmp(a, "-f") == 0 || strcmp(a, "--format") == 0 ||
			   strcmp(a, "-j") == 0 || strcmp(a, "--jobs") == 0 ||
			   strcmp(a, "--aa-threshold") == 0 || strcmp(a, "--aa-depth") == 0 ||
			   strcmp(a, "--rows") == 0 || strcmp(a, "--cols") == 0 ||
			   strcmp(a, "--time-limit") == 0) {
			value = i + 1 < argc ? argv[++i] : NULL;
			if (!value)
				return usage_error("option '%s' needs a value", a);
			if (strcmp(a, "-o") == 0) {
				enum format f = format_of(value);
				/* One image per run: a second -o is a mistake, not a choice. */
				if (o->output_path || o->to_stdout)
					return usage_error("more than one output file given ('%s')",
							   value);
				if (strcmp(value, "-") == 0) {
					o->to_stdout = 1;
					continue;
				}
				o->output_path = value;
				/* A name that says no format needs -f (checked once all are read). */
				status = f == FORMAT_DEFAULT ? -1 : choose_format(o, f, value);
				if (status >= 0)
					return status;
			} else if (strcmp(a, "-f") == 0 || strcmp(a, "--format") == 0) {
				enum format f = format_of_name(value);
				if (f == FORMAT_DEFAULT)
					return usage_error("bad format '%s' (expected ppm, png, txt, ans or "
							   "pgm)",
							   value);
				status = choose_format(o, f, value);
				if (status >= 0)
					return status;
			} else if (strcmp(a, "-s") == 0) {
				if (!parse_int(value, 'x', 1, RT_MAX_WIDTH, &o->width, &rest) ||
				    !parse_int(rest, '\0', 1, RT_MAX_HEIGHT, &o->height, NULL))
					return usage_error("bad size '%s' (expected WxH, e.g. 320x240, "
							   "at most " RT_STRINGIFY(RT_MAX_WIDTH) "x" RT_STRINGIFY(
								   RT_MAX_HEIGHT) ")",
							   value);
			} else if (strcmp(a, "-d") == 0) {
				if (!parse_int(value, '\0', 1, RT_MAX_DEPTH, &o->depth, NULL))
					return usage_error("bad depth '%s' (expected 1 to " RT_STRINGIFY(
								   RT_MAX_DEPTH) ")",
							   value);
			} else if (strcmp(a, "-j") == 0 || strcmp(a, "--jobs") == 0) {
				if (!parse_int(value, '\0', 1, PARALLEL_MAX_JOBS, &o->jobs, NULL))
					return usage_error("bad job count '%s' (expected 1 to " RT_STRINGIFY(
								   PARALLEL_MAX_JOBS) ")",
							   value);
			} else if (strcmp(a, "--aa-depth") == 0) {
				o->antialias = 1;
				if (!parse_int(value, '\0', 1, ANTIALIAS_MAX_DEPTH, &o->aa.depth, NULL))
					return usage_error("bad antialiasing depth '%s' (expected 1 to " RT_STRINGIFY(
								   ANTIALIAS_MAX_DEPTH) ")",
							   value);
			} else if (strcmp(a, "--aa-threshold") == 0) {
				o->antialias = 1;
				o->aa.threshold = parse_fraction_codes(value);
				if (o->aa.threshold < 0)
					return usage_error("bad antialiasing threshold '%s' (expected 0 to 1, "
							   "e.g. 0.03)",
							   value);
			} else if (strcmp(a, "--time-limit") == 0) {
				o->time_limit = value;
				o->time_limit_micros = parse_seconds(value);
				if (!o->time_limit_micros)
					return usage_error("bad time limit '%s' (expected seconds, e.g. "
							   "2.5, from 0.000001 to 100000000)",
							   value);
			} else if (strcmp(a, "--cols") == 0) {
				if (!parse_int(value, '\0', 1, RT_MAX_WIDTH, &o->columns, NULL))
					return usage_error("bad column count '%s' (expected 1 to " RT_STRINGIFY(
								   RT_MAX_WIDTH) ")",
							   value);
			} else if (!parse_int(value, ':', 0, RT_MAX_HEIGHT - 1, &o->row_first, &rest) ||
				   !parse_int(rest, '\0', o->row_first + 1, RT_MAX_HEIGHT, &o->row_end,
					      NULL)) {
				return usage_error("bad rows '%s' (expected Y0:Y1 with 0 <= Y0 < Y1)",
						   value);
			}
		} else if (a[0] == '-' && a[1] != '\0') {
			return usage_error("unknown option '%s'", a);
		} else if (o->scene_path) {
			return usage_error("more than one scene given ('%s')", a);
		} else {
			o->scene_path = a;
		}
	}
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
static void print_seconds(const char *name, unsigned long long micros)
{
	fprintf(stderr, "%s: %llu.%06llu\n", name, micros / 1000000u, micros % 1000000u);
}

/* extra_eye_rays: -a's rays beyond the pixels' corners, -1 without -a. */
static void print_stats(const trace_stats *st, long extra_eye_rays,
			unsigned long long parse_micros, unsigned long long micros)
{
	unsigned long rays = st->eye_rays + st->shadow_rays + st->reflect_rays + st->refract_rays;
	fprintf(stderr, "objects: %d\n", the_scene.object_count);
	fprintf(stderr, "eye_rays: %lu\n", st->eye_rays);
	fprintf(stderr, "eye_hits: %lu\n", st->eye_hits);
	if (extra_eye_rays >= 0)
		fprintf(stderr, "antialias_rays: %ld\n", extra_eye_rays);
	fprintf(stderr, "shadow_rays: %lu\n", st->shadow_rays);
	fprintf(stderr, "reflect_rays: %lu\n", st->reflect_rays);
	fprintf(stderr, "refract_rays: %lu\n", st->refract_rays);
	print_seconds("parse_seconds", parse_micros);
	print_seconds("seconds", micros);
	fprintf(stderr, "rays_per_second: %llu\n",
		micros ? (unsigned long long)rays * 1000000u / micros : 0u);
}

int main(int argc, char **argv)
{
	static union {
		ppm_sink ppm;
		ids_sink ids;
		png_sink png;
		preview_sink preview;
	} sinks;
	options opt;
	camera cam;
	output out;
	progress_bar bar;
	sink *target;
	const char *why;
	int status = parse_options(argc, argv, &opt), width, height, rows, depth, ok;
	unsigned long long start, parsed;
	const accel *searched; /* the scene and its hierarchy */

	if (status >= 0)
		return status;
	diag_quiet(opt.quiet);
	if (opt.time_limit &&
	    !output_time_limit(opt.scene_name, opt.time_limit_micros, opt.time_limit))
		return 1;
	start = term_micros();
	if (!load_scene_file(&the_scene, opt.scene_path))
		return 1;
	searched = accel_build(&the_scene);
	parsed = term_micros();
	width = opt.width ? opt.width : the_scene.camera.width;
	height = opt.height ? opt.height : the_scene.camera.height;
	if (opt.format == FORMAT_ASCII || opt.format == FORMAT_ANSI) {
		/* A preview traces its own, smaller image: one ray per half cell. */
		if (opt.format == FORMAT_ANSI)
			opt.format = term_color_mode(!opt.chosen) == PREVIEW_ASCII ? FORMAT_ASCII
										   : FORMAT_ANSI;
		if (opt.columns)
			preview_size(opt.columns, width, height, &width, &height);
		else
			fit_preview(width, height, &width, &height);
	}
	if (opt.size_only) {
		printf("%d %d\n", width, height);
		return stdout_status();
	}
	if (opt.row_end > height) {
		diag_error(NULL, 0, "--rows %d:%d is outside the image's %d rows", opt.row_first,
			   opt.row_end, height);
		return 2;
	}
	if (opt.format == FORMAT_PNG && !png_available()) {
		diag_error(opt.output_path, 0, "this build (%s) writes no PNG; write .ppm", REAL_NAME);
		return 1;
	}
	if (opt.format == FORMAT_PNG && !png_fits(width, height)) {
		diag_error(opt.output_path, 0,
			   "%dx%d is too large for PNG output in this build (the encoder's fixed "
			   "memory, RT_PNG_ARENA_BYTES in src/config.h, is %ld MiB); write .ppm",
			   width, height, (long)(RT_PNG_ARENA_BYTES >> 20));
		return 1;
	}
	why = camera_init(&cam, &the_scene.camera, width, height);
	if (why) {
		diag_error(opt.scene_name, 0, "%s", why);
		return 1;
	}
	depth = opt.spd ? 5 : opt.depth ? opt.depth : the_scene.depth;
	trace_init(&the_tracer, searched, depth, opt.spd ? REAL_C(0.0) : the_scene.cutoff);
	if (!output_open(&out, opt.output_path))
		return 1;
	switch (opt.format) {
	case FORMAT_PNG:
		png_sink_init(&sinks.png, output_write, &out);
		target = &sinks.png.base;
		break;
	case FORMAT_IDS:
		ids_sink_init(&sinks.ids, output_write, &out);
		target = &sinks.ids.base;
		break;
	case FORMAT_ASCII:
	case FORMAT_ANSI:
		preview_sink_init(&sinks.preview,
				  opt.format == FORMAT_ASCII ? PREVIEW_ASCII : term_color_mode(!opt.chosen),
				  output_write, &out);
		target = &sinks.preview.base;
		break;
	default:
		ppm_sink_init(&sinks.ppm, output_write, &out);
		target = &sinks.ppm.base;
	}
	/* The bar would garble a preview drawn on the same terminal. */
	progress_start(&bar,
		       term_is_tty(2) && !term_is_dumb() && !(opt.output_path == NULL && term_is_tty(1)),
		       &the_tracer.stats);
	/* Ctrl-C, another ending signal or the time limit erases the bar before rt ends. */
	if (bar.enabled)
		output_erase_on_end(&bar.drawn);
	rows = (opt.row_end ? opt.row_end : height) - opt.row_first;
	ok = render_parallel(&the_tracer, &cam, opt.spd ? SAMPLE_CORNERS : SAMPLE_CENTRE,
			     opt.antialias ? &opt.aa : NULL, opt.row_first, opt.row_first + rows, target,
			     opt.jobs ? opt.jobs : parallel_default_jobs(), progress_update, &bar);
	progress_finish(&bar);
	if (ok < 0)
		ok = 0; /* a worker's failure, reported */
	else if (!ok && target->error)
		diag_error(opt.output_path, 0, "%s", target->error);
	else if (!ok)
		output_report_error(&out);
	if (!output_close(&out, ok))
		return 1;
	if (opt.stats)
		print_stats(&the_tracer.stats,
			    opt.antialias ? (long)the_tracer.stats.eye_rays -
						    (long)(width + 1) * (rows + 1)
					  : -1,
			    parsed - start, term_micros() - parsed);
	return 0;
}
