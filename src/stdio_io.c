/* stdio_io.c - the host's side of rt's I/O: scene files read through stdio, messages
 * to standard error. The microcontroller build has its own (src/mcu/semihost_io.c).
 * See LICENSE for copyright and licence. */
#define _POSIX_C_SOURCE 200809L

#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#include "diag.h"
#include "load.h"

void diag_standard_error(void *ctx, const char *message)
{
	(void)ctx;
	fputs(message, stderr);
}

/* A scene file. A regular file is opened afresh for each pass. An input that cannot be
 * read twice (a pipe, a FIFO, a terminal) is read once, where the parser will read it
 * again (fixed point measures the scene first): what a pass reads of it is kept in a
 * temporary file, and the next pass reads that copy and then, where the copy ends, the
 * input itself. So no pass reads further into the input than the parser asks for, and
 * an endless input stops at its first error as it does in one pass. */
typedef struct {
	const char *path; /* "-": standard input */
	const char *name; /* for messages: the path, or <stdin> */
	FILE *file; /* the input; held across passes when it is not reopened */
	FILE *copy; /* what the passes so far read of an input that is not reopened */
	long copied; /* bytes in copy */
	long at;     /* the bytes of copy this pass has read */
	scene *planned; /* the scene whose memory the file's length plans, until it is */
	int reopen;  /* a regular file, or one read only once: no copy */
	int writing; /* copy's last operation was a write (a seek must come between) */
	int from_stdin;
} file_reader;

/* Closes the input (standard input stays open: it is not rt's). */
static void close_input(file_reader *f)
{
	if (f->file && f->file != stdin)
		fclose(f->file);
	f->file = NULL;
}

static int file_open(void *ctx, int again)
{
	file_reader *f = ctx;
	struct stat st;
	int known;
	if (f->copy) {
		f->at = 0;
		f->writing = 0;
		return fseek(f->copy, 0, SEEK_SET) == 0;
	}
	/* Standard input is never reopened: it is read through a copy when another pass
	 * follows, as a pipe is, whatever it is (its position is where the shell left it). */
	f->file = f->from_stdin ? stdin : fopen(f->path, "rb");
	if (!f->file) {
		diag_error(f->name, 0, "cannot open: %s", strerror(errno));
		return 0;
	}
	/* A file whose kind cannot be told is taken as a regular one. */
	known = fstat(fileno(f->file), &st) == 0;
	/* A folder opens, and then reads as an empty file ("no view"): say what it is. */
	if (known && S_ISDIR(st.st_mode)) {
		diag_error(f->name, 0, "cannot read: %s", strerror(EISDIR));
		close_input(f);
		return 0;
	}
	if (f->planned && known && S_ISREG(st.st_mode) && st.st_size > 0)
		scene_plan_pages(f->planned, st.st_size > LONG_MAX ? LONG_MAX : (long)st.st_size);
	f->planned = NULL;
	f->reopen = (!f->from_stdin && (!known || S_ISREG(st.st_mode))) || !again;
	if (!f->reopen) {
		f->copy = tmpfile();
		if (!f->copy) {
			diag_error(f->name, 0, "cannot keep a copy of the input for its second "
					       "reading: %s",
				   strerror(errno));
			close_input(f);
			return 0;
		}
	}
	return 1;
}

static int file_read(void *ctx)
{
	file_reader *f = ctx;
	int c;
	/* A regular file, the usual input, without stdio's lock for each byte (rt reads
	 * it from one thread): a fifth of the reading. A copied input keeps getc and putc. */
	if (f->reopen) {
		c = getc_unlocked(f->file);
		return c == EOF ? -1 : c;
	}
	if (f->at < f->copied) {
		if (f->writing && fseek(f->copy, f->at, SEEK_SET) != 0)
			return -1;
		f->writing = 0;
		c = getc(f->copy);
		if (c == EOF)
			return -1;
		f->at++;
		return c;
	}
	c = getc(f->file);
	if (c == EOF)
		return -1;
	if (!f->writing && fseek(f->copy, 0, SEEK_END) != 0)
		return -1;
	f->writing = 1;
	if (putc(c, f->copy) == EOF)
		return -1;
	f->copied++;
	f->at++;
	return c;
}

#if RT_READ_BUFFER
/* A block of the input: straight from the file when it is read afresh each pass (the
 * usual input); an input kept through a copy one byte at a time, as file_read keeps it,
 * so that no pass reads further into it than the parser asks. */
static long file_read_block(void *ctx, unsigned char *to, long max)
{
	file_reader *f = ctx;
	int c;
	if (f->reopen)
		return (long)fread(to, 1, (size_t)max, f->file);
	c = file_read(f);
	if (c < 0)
		return 0;
	to[0] = (unsigned char)c;
	return 1;
}
#endif

/* Reports a read error of the input, or a failure of its copy, once parsing went well
 * (after a parse error the reading stopped early; a read error would only repeat it). */
static int file_check(file_reader *f, int ok)
{
	if (ok && ferror(f->file)) {
		diag_error(f->name, 0, "read error");
		return 0;
	}
	if (ok && f->copy && ferror(f->copy)) {
		diag_error(f->name, 0, "cannot keep a copy of the input for its second reading");
		return 0;
	}
	return 1;
}

static int file_close(void *ctx, int ok)
{
	file_reader *f = ctx;
	int checked = file_check(f, ok);
	if (f->reopen)
		close_input(f);
	return checked;
}

int load_scene_file(scene *s, const char *path)
{
	file_reader f;
	scene_source source;
	int ok;
	memset(&f, 0, sizeof f);
	f.path = path;
	f.planned = s;
	f.from_stdin = strcmp(path, "-") == 0;
	f.name = f.from_stdin ? "<stdin>" : path;
	source.open = file_open;
	source.read = file_read;
#if RT_READ_BUFFER
	source.read_block = file_read_block;
#endif
	source.close = file_close;
	source.ctx = &f;
	ok = load_scene_source(s, f.name, &source);
	/* An input read through a copy stays open until the last pass is done. */
	if (f.copy)
		fclose(f.copy);
	close_input(&f);
	return ok;
}
