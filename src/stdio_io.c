/* stdio_io.c - the host's side of rt's I/O: scene files read through stdio, messages
 * to standard error. The microcontroller build has its own (src/mcu/semihost_io.c).
 * See LICENSE for copyright and licence. */
#define _POSIX_C_SOURCE 200809L

#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#include "diag.h"
#include "parse.h"

void diag_standard_error(void *ctx, const char *message)
{
	(void)ctx;
	fputs(message, stderr);
}

/* A scene file, opened afresh for each pass. */
typedef struct {
	const char *path;
	FILE *file;
} file_reader;

static int file_open(void *ctx)
{
	file_reader *f = ctx;
	struct stat st;
	f->file = fopen(f->path, "rb");
	if (!f->file) {
		diag_error(f->path, 0, "cannot open: %s", strerror(errno));
		return 0;
	}
	/* A folder opens, and then reads as an empty file ("no view"): say what it is. */
	if (fstat(fileno(f->file), &st) == 0 && S_ISDIR(st.st_mode)) {
		diag_error(f->path, 0, "cannot read: %s", strerror(EISDIR));
		fclose(f->file);
		f->file = NULL;
		return 0;
	}
	return 1;
}

static int file_read(void *ctx)
{
	int c = getc(((file_reader *)ctx)->file);
	return c == EOF ? -1 : c;
}

static int file_close(void *ctx, int ok)
{
	file_reader *f = ctx;
	int failed = ferror(f->file);
	fclose(f->file);
	f->file = NULL;
	/* After a parse error the reading stopped early; a read error would only repeat it. */
	if (ok && failed) {
		diag_error(f->path, 0, "read error");
		return 0;
	}
	return 1;
}

int parse_scene_file(scene *s, const char *path)
{
	file_reader f;
	scene_source source;
	f.path = path;
	f.file = NULL;
	source.open = file_open;
	source.read = file_read;
	source.close = file_close;
	source.ctx = &f;
	return parse_scene_source(s, path, &source);
}
