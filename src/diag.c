/* diag.c - formats errors and warnings and hands them to the sink.
 * See LICENSE for copyright and licence. */
#include "diag.h"

#include <stdio.h>
#include <string.h>

#include "flash.h"

static diag_sink_fn current_sink = diag_standard_error;
static void *current_ctx;
static int muted, quiet;

int diag_mute(int on)
{
	int was = muted;
	muted = on;
	return was;
}

void diag_quiet(int on)
{
	quiet = on;
}

void diag_set_sink(diag_sink_fn sink, void *ctx)
{
	current_sink = sink ? sink : diag_standard_error;
	current_ctx = ctx;
}

/* Appends to a message buffer, never past its end (one byte is kept for the newline). A
 * cut message is the same whether its parts are appended one by one or all at once.
 * One copy for its callers (RT_APART): 16 bytes less M0 flash. */
RT_APART static size_t vappend(char *buf, size_t size, size_t used, const char *fmt, va_list ap)
{
	int n;
	if (used + 2 >= size)
		return used;
	n = vsnprintf(buf + used, size - used - 1, fmt, ap);
	if (n < 0)
		return used;
	used += (size_t)n;
	return used + 2 >= size ? size - 2 : used;
}

static size_t append(char *buf, size_t size, size_t used, const char *fmt, ...)
{
	va_list ap;
	va_start(ap, fmt);
	used = vappend(buf, size, used, fmt, ap);
	va_end(ap);
	return used;
}

/* The most of a file's name a message shows: a longer one keeps its end (the file's own
 * name), so that the line number and the reason still fit the message. */
#define DIAG_NAME_MAX 200

static void emit(const char *file, int line, const char *kind, const char *fmt, va_list ap)
{
	char message[512];
	size_t used, length = file ? strlen(file) : 0;
	const char *cut = length > DIAG_NAME_MAX ? "..." : "";
	if (*cut)
		file += length - (DIAG_NAME_MAX - 3);
	if (file && line > 0)
		used = append(message, sizeof message, 0, "rt: %s%s:%d: %s", cut, file, line, kind);
	else if (file)
		used = append(message, sizeof message, 0, "rt: %s%s: %s", cut, file, kind);
	else
		used = append(message, sizeof message, 0, "rt: %s", kind);
	used = vappend(message, sizeof message, used, fmt, ap);
	message[used] = '\n';
	message[used + 1] = '\0';
	if (!muted)
		current_sink(current_ctx, message);
}

void diag_verror(const char *file, int line, const char *fmt, va_list ap)
{
	emit(file, line, "", fmt, ap);
}

void diag_error(const char *file, int line, const char *fmt, ...)
{
	va_list ap;
	va_start(ap, fmt);
	emit(file, line, "", fmt, ap);
	va_end(ap);
}

void diag_warning(const char *file, int line, const char *fmt, ...)
{
	va_list ap;
	if (quiet)
		return;
	va_start(ap, fmt);
	emit(file, line, "warning: ", fmt, ap);
	va_end(ap);
}
