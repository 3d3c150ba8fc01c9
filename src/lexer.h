/* lexer.h - a scene file as tokens and numbers: bytes in, line counting, tokens, and the
 * readers of numbers, counts and keywords that every scene command uses.
 * See LICENSE for copyright and licence. */
#ifndef RT_LEXER_H
#define RT_LEXER_H

#include "config.h"
#include "diag.h"
#include "realtext.h"
#include "vec.h"

/* Returns the next byte of the input, or -1 at its end. */
typedef int (*read_fn)(void *ctx);

#if RT_READ_BUFFER
/* Reads up to max bytes of the input into `to`: their count, 0 at its end (or after an
 * error, which the source reports when the pass ends). */
typedef long (*read_block_fn)(void *ctx, unsigned char *to, long max);
#endif

#define NO_BYTE (-2) /* nothing pushed back */

typedef struct {
	read_fn read;
	void *ctx;
	const char *file;
	int line;     /* line of the next byte */
	int last_line; /* line of the last byte read: where the end of the file is reported */
	int pending;  /* a byte read ahead, or NO_BYTE */
	int after_cr; /* the last byte read was a CR: an LF now ends no further line */
	int counted;  /* the last byte read ended a line (give_back takes that back) */
	int cr_before; /* after_cr before the last byte (give_back restores it) */
	int at_start; /* nothing read yet: a byte-order mark may follow */
	char tok[RT_TOKEN_MAX + 1];
	int tok_line;  /* line of the current token */
	int pushed;    /* the current token was given back and comes again */
	int have_tok;  /* tok holds a token (not end of input) */
	int failed;    /* an error was reported */
	int length_shift; /* lengths are read times 2^length_shift (fixed point's scale) */
	real longest;     /* the largest length read, in magnitude (skipped objects too) */
	int tiny_line;    /* line of the last number too small for the type (read as 0) */
#if RT_READ_BUFFER
	/* Set: the input comes RT_READ_BUFFER bytes at a time, through buffer (a call for
	 * each byte was a tenth of reading a million spheres); read is then not used. */
	read_block_fn read_block;
	long buffered, taken; /* bytes in buffer; bytes of them already read */
	/* The block, and a NUL after it (buffer[buffered]): a scan for a number's digits
	 * stops there at the latest. */
	unsigned char buffer[RT_READ_BUFFER + 1];
#endif
} lexer;

/* Starts reading `file` through read(ctx), lengths times 2^length_shift, with a lexer
 * whose other fields are zero. */
void lexer_init(lexer *lx, const char *file, read_fn read, void *ctx, int length_shift);

#if RT_READ_BUFFER
/* After lexer_init: the input is read a block at a time through read_block. */
void lexer_read_blocks(lexer *lx, read_block_fn read_block);
#endif

/* Reports the first error only (later ones would be consequences) and returns 0. */
int lexer_fail(lexer *lx, int line, const char *fmt, ...) RT_PRINTF(3, 4);

/* Reads the next token into lx->tok. Returns 1 for a token, 0 at the end of input or
 * after an error (lx->failed tells which). */
int lexer_next(lexer *lx);

/* The current token comes again at the next lexer_next. */
void lexer_push_back(lexer *lx);

/* Is the whole token a number (finite or not)? */
int lexer_is_number(const char *tok);

/* Moves to the next token, which must be the value `what`; at the end of the file says
 * what was expected. A number is named "a number (what)" in messages, a whole count
 * by `what` alone. */
int lexer_next_value(lexer *lx, const char *what, int whole);

/* Reads one finite number; a length (length = 1: a position or a size) is read times the
 * scene's length scale, 2^length_shift, and counts towards the longest one. */
int lexer_read_value(lexer *lx, const char *what, int length, real *out);

/* Three numbers: a point (length = 1: lengths) or a direction or colour (length = 0). */
int lexer_read_triple(lexer *lx, const char *what, int length, vec3 *out);

/* A number that must not be negative, refused at its own token. */
int lexer_read_nonnegative(lexer *lx, const char *what, real *out);

/* A whole number in [lo, hi]; `limit` names the capacity macro behind hi, if any. */
int lexer_read_count(lexer *lx, const char *what, long lo, long hi, const char *limit,
		     long *out);

/* Reads the decimal digits at the start of `text` into *out and returns the first byte
 * after them (`text` itself when there are none). A value past `max` is held above it,
 * not read on: `max` up to LONG_MAX / 10 - 1 (the capacities are far below). The scene's
 * counts and the microcontroller's option values are read this way. */
const char *lexer_digits(const char *text, long max, long *out);

/* The position of `word` in `names`, a string of names each ended by its NUL and the
 * list by an empty name; the number of names if it is not there. Scene commands and the
 * microcontroller's options are found this way (one loop: less flash than a chain of
 * comparisons). */
int lexer_keyword(const char *names, const char *word);

#endif
