/* fuzz_scene.c - the fuzzing entry point: parse any bytes as a scene and, if they parse,
 * render a tiny image of it. Built with libFuzzer by `make fuzz`; replayed over the
 * corpus by `make test` (replay.c), which checks through fuzz_rendered and fuzz_eye_rays
 * that the inputs reach the renderer. See LICENSE for copyright and licence. */
#include <stddef.h>
#include <stdint.h>

#include "bvh.h"
#include "camera.h"
#include "diag.h"
#include "image.h"
#include "load.h"
#include "preview.h"
#include "render.h"
#include "trace.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* Inputs rendered and the eye rays they traced, since the process started. */
unsigned long fuzz_rendered, fuzz_eye_rays;

static void quiet(void *ctx, const char *message)
{
	(void)ctx;
	(void)message;
}

static int discard(void *ctx, const void *bytes, size_t n)
{
	(void)ctx;
	(void)bytes;
	(void)n;
	return 1;
}

static scene fuzz_scene;
static tracer fuzz_tracer;

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	camera cam;
	diag_set_sink(quiet, NULL);
	if (load_scene_buffer(&fuzz_scene, "fuzz.nff", data, size)) {
		/* A tiny image: every code path of the tracer, a few dozen eye rays; then the
		 * same through the ANSI preview. */
		if (!camera_init(&cam, &fuzz_scene.camera, 6, 4)) {
			ppm_sink ppm;
			preview_sink ansi;
			trace_init(&fuzz_tracer, accel_build(&fuzz_scene), fuzz_scene.depth,
				   fuzz_scene.cutoff);
			ppm_sink_init(&ppm, discard, NULL);
			render_image(&fuzz_tracer, &cam, SAMPLE_CORNERS, 0, cam.height, &ppm.base,
				     NULL, NULL);
			preview_sink_init(&ansi, PREVIEW_ANSI_256, discard, NULL);
			render_image(&fuzz_tracer, &cam, SAMPLE_CENTRE, 0, cam.height, &ansi.base,
				     NULL, NULL);
			fuzz_rendered++;
			fuzz_eye_rays += fuzz_tracer.stats.eye_rays;
		}
	}
	diag_set_sink(NULL, NULL);
	return 0;
}
