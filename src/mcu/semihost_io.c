/* semihost_io.c - the microcontroller's side of rt's I/O: scene files read from the host
 * through semihosting, standard output buffered, messages to standard error. The host
 * build has its own (src/stdio_io.c).
 * See LICENSE for copyright and licence. */
#include <string.h>

#include "diag.h"
#include "load.h"
#include "mcu.h"
#include "semihost.h"

#define SCENE_CHUNK 128  /* bytes read from the host per call */
#define OUTPUT_CHUNK 256 /* bytes sent to the host per call */

static int stdout_handle = -1, stderr_handle = -1;
static unsigned char output[OUTPUT_CHUNK];
static size_t output_used;

static int standard_stream(int *handle, int mode)
{
	if (*handle < 0)
		*handle = semihost_open(":tt", mode);
	return *handle;
}

int mcu_stdout_flush(void)
{
	int ok = output_used == 0 ||
		 semihost_write(standard_stream(&stdout_handle, SEMIHOST_WRITE), output, output_used);
	output_used = 0;
	return ok;
}

int mcu_stdout_write(void *ctx, const void *data, size_t n)
{
	const unsigned char *bytes = data;
	(void)ctx;
	while (n > 0) {
		size_t room = OUTPUT_CHUNK - output_used, k = n < room ? n : room;
		memcpy(output + output_used, bytes, k);
		output_used += k;
		bytes += k;
		n -= k;
		if (output_used == OUTPUT_CHUNK && !mcu_stdout_flush())
			return 0;
	}
	return 1;
}

void mcu_stderr(const char *text)
{
	semihost_write(standard_stream(&stderr_handle, SEMIHOST_APPEND), text, strlen(text));
}

void diag_standard_error(void *ctx, const char *message)
{
	(void)ctx;
	mcu_stderr(message);
}

/* A host file, opened afresh for each pass, read in chunks. */
typedef struct {
	const char *path;
	int handle;
	int failed; /* a read error */
	int used, filled;
	unsigned char chunk[SCENE_CHUNK];
} host_file;

/* The host's files can be opened again for each pass. */
static int file_open(void *ctx, int again)
{
	host_file *f = ctx;
	(void)again;
	f->handle = semihost_open(f->path, SEMIHOST_READ_BINARY);
	f->failed = 0;
	f->used = f->filled = 0;
	if (f->handle < 0) {
		diag_error(f->path, 0, "cannot open");
		return 0;
	}
	return 1;
}

static int file_read(void *ctx)
{
	host_file *f = ctx;
	if (f->used == f->filled) {
		int n = f->failed ? -1 : semihost_read(f->handle, f->chunk, SCENE_CHUNK);
		if (n <= 0) {
			f->failed |= n < 0;
			return -1;
		}
		f->used = 0;
		f->filled = n;
	}
	return f->chunk[f->used++];
}

static int file_close(void *ctx, int ok)
{
	host_file *f = ctx;
	semihost_close(f->handle);
	f->handle = -1;
	if (ok && f->failed) {
		diag_error(f->path, 0, "read error");
		return 0;
	}
	return 1;
}

int load_scene_file(scene *s, const char *path)
{
	/* Static: the stack is the scarcest memory here. */
	static host_file f;
	scene_source source;
	f.path = path;
	f.handle = -1;
	source.open = file_open;
	source.read = file_read;
	source.close = file_close;
	source.ctx = &f;
	return load_scene_source(s, path, &source);
}
