/* main.c - rt on a microcontroller: the same renderer and scene files as on a host,
 * with a smaller command line. The image (PPM, ASCII preview or object IDs) goes to
 * standard output through semihosting, byte for byte what the host's fixed-point build
 * writes. Start reading here for the MCU build; the rest is src/.
 * See LICENSE for copyright and licence. */
#include <stdio.h>
#include <string.h>

#include "builtin.h"
#include "camera.h"
#include "diag.h"
#include "image.h"
#include "load.h"
#include "mcu.h"
#include "parse.h"
#include "preview.h"
#include "render.h"
#include "trace.h"

#define PREVIEW_COLUMNS 80 /* --ascii width when --cols is not given: no terminal to ask */

static const char usage_text[] =
	"Usage: rt [-s WxH] [-d N] [--ascii] [--cols N] [--ids] [--stack] SCENE\n";

enum format { FORMAT_PPM, FORMAT_ASCII, FORMAT_IDS };

typedef struct {
	const char *scene_path;
	enum format format;
	int width, height, depth, columns;
	int report_stack; /* --stack: print the stack's high-water mark on standard error */
} options;

/* Large: static, as the stack is small. */
static scene the_scene;
static tracer the_tracer;
static union {
	ppm_sink ppm;
	ids_sink ids;
	preview_sink preview;
} sinks;

static int usage_error(const char *what, const char *arg)
{
	diag_error(NULL, 0, "%s '%s'", what, arg);
	mcu_stderr(usage_text);
	return 2;
}

/* A decimal number in [1, max] ending at `stop`; *rest is after it. */
static int read_int(const char *text, char stop, int max, int *out, const char **rest)
{
	long v;
	const char *end = lexer_digits(text, max, &v);
	if (end == text || *end != stop || v < 1 || v > max)
		return 0;
	*out = (int)v;
	if (rest)
		*rest = end + 1;
	return 1;
}

/* The options, in the order of enum option (for lexer_keyword). */
static const char option_names[] = "--ascii\0--ids\0--stack\0-s\0-d\0--cols\0";
enum option { OPT_ASCII, OPT_IDS, OPT_STACK, OPT_SIZE, OPT_DEPTH, OPT_COLUMNS, OPT_NONE };

/* Returns -1 to go on, else the exit status. */
static int parse_options(int argc, char **argv, options *o)
{
	int i;
	memset(o, 0, sizeof *o);
	o->columns = PREVIEW_COLUMNS;
	for (i = 1; i < argc; i++) {
		const char *a = argv[i], *value, *rest;
		enum option which = (enum option)lexer_keyword(option_names, a);
		if (which == OPT_ASCII) {
			o->format = FORMAT_ASCII;
		} else if (which == OPT_IDS) {
			o->format = FORMAT_IDS;
		} else if (which == OPT_STACK) {
			o->report_stack = 1;
		} else if (which != OPT_NONE) {
			if (i + 1 >= argc)
				return usage_error("option needs a value:", a);
			value = argv[++i];
			if (which == OPT_SIZE ? !read_int(value, 'x', RT_MAX_WIDTH, &o->width, &rest) ||
							!read_int(rest, '\0', RT_MAX_HEIGHT, &o->height, NULL)
			    : which == OPT_DEPTH ? !read_int(value, '\0', RT_MAX_DEPTH, &o->depth, NULL)
						 : !read_int(value, '\0', RT_MAX_WIDTH, &o->columns, NULL))
				return usage_error("bad value for option", a);
		} else if (a[0] == '-' || o->scene_path) {
			return usage_error("unexpected argument", a);
		} else {
			o->scene_path = a;
		}
	}
	/* With a scene compiled in, a file named on the command line still wins. */
	if (!o->scene_path && !RT_BUILTIN_SCENE)
		return usage_error("no scene file given", "");
	return -1;
}

/* The scene compiled in, if the build has one (parse_options allows no file then);
 * *name becomes the file it came from, for messages. */
static int load_builtin(const char **name)
{
#if RT_BUILTIN_SCENE
	*name = rt_builtin_scene_name;
	return load_scene_buffer(&the_scene, *name, rt_builtin_scene, rt_builtin_scene_size);
#else
	(void)name;
	return 0;
#endif
}

/* Prints the stack's high-water mark: what the measured run really used. */
static void print_stack_used(void)
{
	char line[48];
	snprintf(line, sizeof line, "stack_bytes: %lu\n", (unsigned long)mcu_stack_used());
	mcu_stderr(line);
}

int main(int argc, char **argv)
{
	options opt;
	camera cam;
	sink *target;
	const char *why;
	int status = parse_options(argc, argv, &opt), width, height, ok;
	if (status >= 0)
		return status;
	if (!(opt.scene_path ? load_scene_file(&the_scene, opt.scene_path)
			     : load_builtin(&opt.scene_path)))
		return 1;
	width = opt.width ? opt.width : the_scene.camera.width;
	height = opt.height ? opt.height : the_scene.camera.height;
	if (opt.format == FORMAT_ASCII)
		preview_size(opt.columns, width, height, &width, &height);
	if (width > RT_MAX_WIDTH || height > RT_MAX_HEIGHT) {
		diag_error(opt.scene_path, 0,
			   "%dx%d is over this build's image size limit %dx%d (give -s WxH)", width,
			   height, RT_MAX_WIDTH, RT_MAX_HEIGHT);
		return 1;
	}
	why = camera_init(&cam, &the_scene.camera, width, height);
	if (why) {
		diag_error(opt.scene_path, 0, "%s", why);
		return 1;
	}
	trace_init(&the_tracer, accel_build(&the_scene), opt.depth ? opt.depth : the_scene.depth,
		    the_scene.cutoff);
	if (opt.format == FORMAT_ASCII) {
		preview_sink_init(&sinks.preview, PREVIEW_ASCII, mcu_stdout_write, NULL);
		target = &sinks.preview.base;
	} else if (opt.format == FORMAT_IDS) {
		ids_sink_init(&sinks.ids, mcu_stdout_write, NULL);
		target = &sinks.ids.base;
	} else {
		ppm_sink_init(&sinks.ppm, mcu_stdout_write, NULL);
		target = &sinks.ppm.base;
	}
	ok = render_image(&the_tracer, &cam, SAMPLE_CENTRE, 0, height, target, NULL, NULL);
	ok = mcu_stdout_flush() && ok;
	if (!ok) {
		diag_error(NULL, 0, "%s", target->error ? target->error : "write error");
		return 1;
	}
	if (opt.report_stack)
		print_stack_used();
	return 0;
}
