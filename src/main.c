/* main.c - rt on a host: the options (options.c) wired to the scene, the camera, the
 * renderer and the output; statistics at the end.
 * See LICENSE for copyright and licence. */
#define _POSIX_C_SOURCE 200809L

#include <stdio.h>

#include "camera.h"
#include "diag.h"
#include "image.h"
#include "load.h"
#include "options.h"
#include "output.h"
#include "parallel.h"
#include "png.h"
#include "preview.h"
#include "term.h"

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

static void print_seconds(const char *name, unsigned long long micros)
{
	fprintf(stderr, "%s: %llu.%06llu\n", name, micros / 1000000u, micros % 1000000u);
}

/* extra_eye_rays: -a's rays beyond the pixels' corners, -1 without -a. */
static void print_stats(const trace_stats *st, long extra_eye_rays,
			unsigned long long parse_micros, unsigned long long build_micros,
			unsigned long long micros)
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
	print_seconds("build_seconds", build_micros);
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
	int status = options_parse(argc, argv, &opt), width, height, rows, depth, ok;
	unsigned long long start, loaded, parsed;
	const accel *searched; /* the scene and its hierarchy */

	if (status >= 0)
		return status;
	diag_quiet(opt.quiet);
	if (opt.time_limit &&
	    !output_time_limit(opt.scene_name, opt.time_limit_micros, opt.time_limit))
		return 1;
	if (opt.colours >= 0)
		colour_choose((enum colour_pipeline)opt.colours, 0);
	start = term_micros();
	if (!load_scene_file(&the_scene, opt.scene_path))
		return 1;
	loaded = term_micros();
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
		return options_stdout_status();
	}
	if (opt.row_end > height) {
		diag_error(NULL, 0, "--rows %d:%d is outside the image's %d rows", opt.row_first,
			   opt.row_end, height);
		return 2;
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
		sinks.ids.wide = the_scene.object_count > 65534;
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
			    loaded - start, parsed - loaded, term_micros() - parsed);
	return 0;
}
