/* main.c - the command line: options, scene in, image out, statistics.
 * See LICENSE for copyright and licence. */
#define _POSIX_C_SOURCE 200809L

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "bvh.h"
#include "camera.h"
#include "diag.h"
#include "parse.h"
#include "render.h"
#include "trace.h"

#define RT_VERSION "0.1.0"

static const char usage_text[] =
	"Usage: rt [OPTION]... SCENE\n"
	"Render SCENE (NFF with rt's extensions) by recursive ray tracing.\n"
	"The image goes to standard output as binary PPM unless -o is given.\n"
	"\n"
	"  -o FILE      write the image to FILE (replaced only when the render succeeds)\n"
	"  -s WxH       image size in pixels, overriding the scene's resolution\n"
	"  -d N         ray tree depth, 1 to " RT_STRINGIFY(RT_MAX_DEPTH) " (eye ray = 1)\n"
	"  --rows Y0:Y1 render only rows Y0 to Y1-1, as a PPM of that band (for splitting\n"
	"               a render across processes: see tools/render-parallel)\n"
	"  --spd        SPD testing procedure: corner rays, depth 5, no weight cutoff\n"
	"  --stats      print ray counts and timings on standard error\n"
	"  --help       show this help and exit\n"
	"  --version    show the version and exit\n"
	"\n"
	"Exit status: 0 on success, 1 on a scene or output error, 2 on a usage error.\n";

typedef struct {
	const char *scene_path;
	const char *output_path;
	int width, height; /* 0: the scene's */
	int depth;         /* 0: the scene's */
	int row_first, row_end; /* --rows: [first, end); end 0 for all rows */
	int spd;
	int stats;
} options;

/* Scene storage is large and lives for the whole run. */
static scene the_scene;

static int usage_error(const char *fmt, const char *arg)
{
	fprintf(stderr, "rt: ");
	fprintf(stderr, fmt, arg);
	fprintf(stderr, "\nTry 'rt --help' for more information.\n");
	return 2;
}

/* Parses a positive decimal integer that fills the whole string up to `stop`. */
static int parse_size(const char *text, char stop, long max, int *out, const char **rest)
{
	char *end;
	long value;
	if (*text < '0' || *text > '9')
		return 0;
	errno = 0;
	value = strtol(text, &end, 10);
	if (errno || *end != stop || value < 1 || value > max)
		return 0;
	*out = (int)value;
	if (rest)
		*rest = end + 1;
	return 1;
}

/* Parses Y0:Y1 with 0 <= Y0 < Y1 <= RT_MAX_HEIGHT. */
static int parse_rows(const char *text, int *first, int *end)
{
	char *stop;
	long a, b;
	if (*text < '0' || *text > '9')
		return 0;
	errno = 0;
	a = strtol(text, &stop, 10);
	if (errno || *stop != ':' || stop[1] < '0' || stop[1] > '9')
		return 0;
	b = strtol(stop + 1, &stop, 10);
	if (errno || *stop != '\0' || a < 0 || b <= a || b > RT_MAX_HEIGHT)
		return 0;
	*first = (int)a;
	*end = (int)b;
	return 1;
}

/* Returns -1 to go on, else the exit status. */
static int parse_options(int argc, char **argv, options *o)
{
	int i;
	memset(o, 0, sizeof *o);
	for (i = 1; i < argc; i++) {
		const char *a = argv[i];
		if (strcmp(a, "--help") == 0) {
			fputs(usage_text, stdout);
			return 0;
		} else if (strcmp(a, "--version") == 0) {
			printf("rt %s (real = %s)\n", RT_VERSION, REAL_NAME);
			return 0;
		} else if (strcmp(a, "--stats") == 0) {
			o->stats = 1;
		} else if (strcmp(a, "--spd") == 0) {
			o->spd = 1;
		} else if (strcmp(a, "--rows") == 0) {
			const char *value = i + 1 < argc ? argv[++i] : NULL;
			if (!value)
				return usage_error("option '%s' needs a value", a);
			if (!parse_rows(value, &o->row_first, &o->row_end))
				return usage_error("bad rows '%s' (expected Y0:Y1 with 0 <= Y0 < Y1)", value);
		} else if (strcmp(a, "-o") == 0 || strcmp(a, "-s") == 0 || strcmp(a, "-d") == 0) {
			const char *value = i + 1 < argc ? argv[++i] : NULL, *rest;
			if (!value)
				return usage_error("option '%s' needs a value", a);
			if (a[1] == 'o') {
				o->output_path = value;
			} else if (a[1] == 's') {
				if (!parse_size(value, 'x', RT_MAX_WIDTH, &o->width, &rest) ||
				    !parse_size(rest, '\0', RT_MAX_HEIGHT, &o->height, NULL))
					return usage_error("bad size '%s' (expected WxH, e.g. 320x240, "
							   "at most " RT_STRINGIFY(RT_MAX_WIDTH) "x" RT_STRINGIFY(RT_MAX_HEIGHT) ")",
							   value);
			} else if (!parse_size(value, '\0', RT_MAX_DEPTH, &o->depth, NULL)) {
				return usage_error("bad depth '%s' (expected 1 to " RT_STRINGIFY(RT_MAX_DEPTH) ")",
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
	return -1;
}

static double now_seconds(void)
{
	struct timespec ts;
	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

static int write_stdio(void *ctx, const void *data, size_t n)
{
	return fwrite(data, 1, n, (FILE *)ctx) == n;
}

/* The output: stdout, or a temporary file beside the target renamed over it at the end,
 * so a failed run never leaves a half-written image or clobbers an existing one. */
typedef struct {
	FILE *file;
	char temp_path[4096];
	int is_temp;
} output;

/* mkstemp creates the file private (0600); the image should get the mode a plain fopen
 * gives: the replaced file's own, or 0666 less the umask for a new one. */
static mode_t output_mode(const char *path)
{
	struct stat st;
	mode_t mask;
	if (stat(path, &st) == 0 && S_ISREG(st.st_mode))
		return st.st_mode & 07777;
	mask = umask(0);
	umask(mask);
	return 0666 & ~mask;
}

static int output_open(output *out, const char *path)
{
	int fd;
	out->is_temp = 0;
	if (!path) {
		out->file = stdout;
		return 1;
	}
	if (snprintf(out->temp_path, sizeof out->temp_path, "%s.tmpXXXXXX", path) >=
	    (int)sizeof out->temp_path) {
		diag_error(path, 0, "output path too long");
		return 0;
	}
	fd = mkstemp(out->temp_path);
	if (fd >= 0)
		(void)fchmod(fd, output_mode(path));
	if (fd < 0 || !(out->file = fdopen(fd, "wb"))) {
		diag_error(path, 0, "cannot create a temporary file beside it: %s", strerror(errno));
		if (fd >= 0) {
			close(fd);
			remove(out->temp_path);
		}
		return 0;
	}
	out->is_temp = 1;
	return 1;
}

/* Finishes the output: flushes, and renames the temporary file into place when ok. */
static int output_close(output *out, const char *path, int ok)
{
	int flushed = fflush(out->file) == 0 && !ferror(out->file);
	if (ok && !flushed)
		diag_error(NULL, 0, "write error: %s", strerror(errno));
	ok = ok && flushed;
	if (!out->is_temp)
		return ok;
	if (fclose(out->file) != 0 && ok) {
		diag_error(path, 0, "write error: %s", strerror(errno));
		ok = 0;
	}
	if (ok && rename(out->temp_path, path) != 0) {
		diag_error(path, 0, "cannot replace: %s", strerror(errno));
		ok = 0;
	}
	if (!ok)
		remove(out->temp_path);
	return ok;
}

static void print_stats(const trace_stats *st, double parse_seconds, double seconds)
{
	unsigned long rays = st->eye_rays + st->shadow_rays + st->reflect_rays + st->refract_rays;
	fprintf(stderr, "objects: %d\n", the_scene.object_count);
	fprintf(stderr, "eye_rays: %lu\n", st->eye_rays);
	fprintf(stderr, "eye_hits: %lu\n", st->eye_hits);
	fprintf(stderr, "shadow_rays: %lu\n", st->shadow_rays);
	fprintf(stderr, "reflect_rays: %lu\n", st->reflect_rays);
	fprintf(stderr, "refract_rays: %lu\n", st->refract_rays);
	fprintf(stderr, "parse_seconds: %.6f\n", parse_seconds);
	fprintf(stderr, "seconds: %.6f\n", seconds);
	fprintf(stderr, "rays_per_second: %.0f\n", seconds > 0 ? (double)rays / seconds : 0.0);
}

int main(int argc, char **argv)
{
	options opt;
	camera cam;
	output out;
	static tracer tr;
	int status = parse_options(argc, argv, &opt), width, height, depth, ok;
	double start, parsed;
	real cutoff;

	if (status >= 0)
		return status;
	start = now_seconds();
	if (!parse_scene_file(&the_scene, opt.scene_path))
		return 1;
#if RT_USE_BVH
	bvh_build(&the_scene);
#endif
	parsed = now_seconds();
	width = opt.width ? opt.width : the_scene.camera.width;
	height = opt.height ? opt.height : the_scene.camera.height;
	depth = opt.spd ? 5 : opt.depth ? opt.depth : the_scene.depth;
	cutoff = opt.spd ? REAL_C(0.0) : the_scene.cutoff;
	if (!camera_init(&cam, &the_scene.camera, width, height)) {
		diag_error(opt.scene_path, 0, "degenerate view");
		return 1;
	}
	if (opt.row_end > height) {
		diag_error(NULL, 0, "--rows %d:%d is outside the image's %d rows", opt.row_first,
			   opt.row_end, height);
		return 2;
	}
	tracer_init(&tr, &the_scene, depth, cutoff);
	if (!output_open(&out, opt.output_path))
		return 1;
	ok = render_ppm(&tr, &cam, opt.spd ? SAMPLE_CORNERS : SAMPLE_CENTRE, opt.row_first,
			opt.row_end ? opt.row_end : height, write_stdio, out.file);
	if (!ok)
		diag_error(NULL, 0, "write error: %s", strerror(errno));
	if (!output_close(&out, opt.output_path, ok))
		return 1;
	if (opt.stats)
		print_stats(&tr.stats, parsed - start, now_seconds() - parsed);
	return 0;
}
