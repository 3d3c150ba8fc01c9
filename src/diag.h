/* diag.h - the one path for messages to the user: errors and warnings.
 * Messages read `rt: FILE:LINE: what is wrong`; nothing here exits the process.
 * See LICENSE for copyright and licence. */
#ifndef RT_DIAG_H
#define RT_DIAG_H

#include <stdarg.h>

/* Where messages go; standard error unless a test captures them. */
typedef void (*diag_sink_fn)(void *ctx, const char *message);
void diag_set_sink(diag_sink_fn sink, void *ctx); /* NULL: back to standard error */

/* The default sink: writes the message to standard error. Defined by the platform's I/O
 * layer (stdio on a host, semihosting on a microcontroller). */
void diag_standard_error(void *ctx, const char *message);

/* Silences all messages while on (for a trial pass); returns the previous setting. */
int diag_mute(int on);

/* Silences warnings while on (-q); errors are always reported. */
void diag_quiet(int on);

#if defined(__GNUC__)
#define RT_PRINTF(f, a) __attribute__((format(printf, f, a)))
#else
#define RT_PRINTF(f, a)
#endif

/* `rt: FILE:LINE: message` (FILE:LINE: left out when file is NULL, LINE when line <= 0). */
void diag_error(const char *file, int line, const char *fmt, ...) RT_PRINTF(3, 4);
/* diag_error with its arguments as a va_list, for a caller's own printf-like reporter. */
void diag_verror(const char *file, int line, const char *fmt, va_list ap) RT_PRINTF(3, 0);
/* `rt: FILE:LINE: warning: message` */
void diag_warning(const char *file, int line, const char *fmt, ...) RT_PRINTF(3, 4);

#endif
