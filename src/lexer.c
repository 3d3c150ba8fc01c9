/* lexer.c - a scene file as tokens and numbers (lexer.h): line ends of every kind, a
 * byte-order mark, comments, tokens, and numbers read in the build's own type.
 * See LICENSE for copyright and licence. */
#include "lexer.h"

#include <limits.h>
#include <stdarg.h>
#include <string.h>

void lexer_init(lexer *lx, const char *file, read_fn read, void *ctx, int length_shift)
{
	/* The rest is zero already (the parser clears itself whole): one memset less of
	 * M0 flash. */
	lx->read = read;
	lx->ctx = ctx;
	lx->file = file;
	lx->line = 1;
	lx->last_line = 1;
	lx->pending = NO_BYTE;
	lx->at_start = 1;
	lx->length_shift = length_shift;
}

#if RT_READ_BUFFER
void lexer_read_blocks(lexer *lx, read_block_fn read_block)
{
	lx->read_block = read_block;
	lx->buffered = lx->taken = 0;
	lx->buffer[0] = '\0';
}

/* The next byte of the input through the block reader, or -1 at its end. */
static int next_buffered(lexer *lx)
{
	if (lx->taken == lx->buffered) {
		lx->buffered = lx->read_block(lx->ctx, lx->buffer, RT_READ_BUFFER);
		lx->taken = 0;
		if (lx->buffered <= 0)
			lx->buffered = 0;
		lx->buffer[lx->buffered] = '\0';
		if (lx->buffered == 0)
			return -1;
	}
	return lx->buffer[lx->taken++];
}
#endif

/* The line state after byte c (-1: the end) is read: its line, and whether it ends one.
 * A line ends at LF, at CR LF and at a lone CR (old Mac files): a CR counts the line, an
 * LF right after it does not. Saturates: a hostile file of 2^31 newlines must not
 * overflow the counter. */
RT_INLINE void count_byte(lexer *lx, int c)
{
	if (c >= 0)
		lx->last_line = lx->line;
	lx->counted = (c == '\r' || (c == '\n' && !lx->after_cr)) && lx->line < INT_MAX;
	lx->line += lx->counted;
	lx->cr_before = lx->after_cr;
	lx->after_cr = c == '\r';
}

static int next_byte(lexer *lx)
{
	int c;
	if (lx->pending != NO_BYTE) {
		c = lx->pending;
		lx->pending = NO_BYTE;
	} else {
#if RT_READ_BUFFER
		c = lx->read_block ? next_buffered(lx) : lx->read(lx->ctx);
#else
		c = lx->read(lx->ctx);
#endif
	}
	count_byte(lx, c);
	return c;
}

/* Gives back the byte just read, to be read again: it counts its line again then. */
static void give_back(lexer *lx, int c)
{
	lx->line -= lx->counted;
	lx->after_cr = lx->cr_before;
	lx->pending = c;
}

int lexer_fail(lexer *lx, int line, const char *fmt, ...)
{
	if (!lx->failed) {
		va_list ap;
		va_start(ap, fmt);
		diag_verror(lx->file, line, fmt, ap);
		va_end(ap);
	}
	lx->failed = 1;
	return 0;
}

static int is_space(int c)
{
	return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
}

#if RT_READ_BUFFER
/* A byte that continues a token: printable, not a space, not a comment's start. */
static int is_token_byte(int c)
{
	return c >= 0x21 && c <= 0x7E && c != '#';
}
#endif

/* A byte-order mark at the start: UTF-8's is skipped, UTF-16's is refused. */
static int check_start(lexer *lx)
{
	int c = next_byte(lx);
	lx->at_start = 0;
	if (c == 0xFF || c == 0xFE) {
		int d = next_byte(lx);
		if ((c == 0xFF && d == 0xFE) || (c == 0xFE && d == 0xFF))
			return lexer_fail(lx, 1, "the file is UTF-16 text; save it as ASCII or UTF-8");
		/* Only one byte can be given back, and c is no text byte anyway: report it
		 * here (a newline in d would otherwise move the error to line 2). */
		return lexer_fail(lx, 1, "unexpected byte 0x%02X (this is not a text scene file)",
			    (unsigned)c);
	}
	if (c == 0xEF) {
		/* Read one at a time: the second byte is read only if the first matched. */
		int b = next_byte(lx);
		if (b == 0xBB && next_byte(lx) == 0xBF)
			return 1;
		return lexer_fail(lx, 1, "unexpected bytes at the start of the file");
	}
	/* Give the byte back (its line end counts again when reread, else a file starting
	 * with a blank line reports every line one too far). */
	give_back(lx, c);
	return 1;
}

#if RT_READ_BUFFER
/* Takes the spaces, tabs and line feeds before the next token from the block buffer,
 * each as next_byte takes it (the line count and the state give_back and a CR LF pair
 * need). Returns 0 where the byte-by-byte path must take the byte it gave back. */
static int take_buffered_spaces(lexer *lx)
{
	long at;
	if (lx->pending != NO_BYTE) {
		/* The delimiter the byte-by-byte path gave back: taken as it takes it. */
		if (lx->pending != ' ' && lx->pending != '\t' && lx->pending != '\n')
			return 0;
		(void)next_byte(lx);
	}
	for (at = lx->taken; at < lx->buffered; at++) {
		int c = lx->buffer[at];
		if (c != ' ' && c != '\t' && c != '\n')
			break;
		count_byte(lx, c);
	}
	lx->taken = at;
	return 1;
}

/* Whether the n bytes at lx->taken are a whole token as the byte-by-byte path reads it:
 * at most RT_TOKEN_MAX (a longer one is its error), and ended by a delimiter still in the
 * buffer (a space, line end or comment), which is left there for the next call: the
 * byte-by-byte path reads every delimiter twice, once to end the token and once again
 * after giving it back. */
static int ends_buffered_token(const lexer *lx, long n)
{
	long at = lx->taken + n;
	int c;
	if (n == 0 || n > RT_TOKEN_MAX || at >= lx->buffered)
		return 0;
	c = lx->buffer[at];
	return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '#';
}

/* Takes the n bytes at lx->taken as the current token: its first byte as next_byte takes
 * it (no token byte ends a line), the token copied. */
static void take_buffered_token(lexer *lx, int n)
{
	count_byte(lx, lx->buffer[lx->taken]);
	memcpy(lx->tok, lx->buffer + lx->taken, (size_t)n);
	lx->tok[n] = '\0';
	lx->tok_line = lx->line;
	lx->taken += n;
}

/* The next token straight from the block buffer, where it and the spaces before it lie
 * wholly there. Returns 1 with the token in lx->tok; 0 where the byte-by-byte path must
 * go on (any other byte, a token at the buffer's end or too long), from a state it would
 * have reached itself: only whole spaces are taken, a token only when complete. SPD
 * teapot-s12's 184 k tokens took 230 instructions each in lexer_next. */
static int next_buffered_token(lexer *lx)
{
	long at;
	if (!take_buffered_spaces(lx))
		return 0;
	for (at = lx->taken; at < lx->buffered; at++) {
		unsigned c = lx->buffer[at];
		if (c - 0x21u > 0x7Eu - 0x21u || c == '#')
			break;
	}
	if (!ends_buffered_token(lx, at - lx->taken))
		return 0;
	take_buffered_token(lx, (int)(at - lx->taken));
	return 1;
}

#if !REAL_FIXED
/* The next token read as a number straight from the block buffer, where it is a short
 * decimal (realtext.h) within the limits of a scene's numbers: the scan of its digits
 * finds its end too (the NUL after the block stops it), where lexer_next found the token
 * and real_from_text then scanned its copy. Returns 1 with the token taken as lexer_next
 * takes it and its value in *out; 0, with only whole spaces taken, where lexer_next and
 * real_from_text must read it (and say what is wrong with it). */
static int next_buffered_number(lexer *lx, real *out)
{
	const char *token, *end;
	real_decimal d;
	/* Where lexer_next would take a token from the block (nothing given back, no
	 * byte-order mark to look for). */
	if (lx->pushed || lx->at_start || !lx->read_block || !take_buffered_spaces(lx))
		return 0;
	token = (const char *)lx->buffer + lx->taken;
	end = real_decimal_scan(token, &d);
	if (!end || !ends_buffered_token(lx, end - token) || !real_from_decimal(&d, out) ||
	    !(real_fabs(*out) <= REAL_INPUT_LIMIT))
		return 0;
	take_buffered_token(lx, (int)(end - token));
	lx->have_tok = 1;
	return 1;
}
#endif
#endif

int lexer_next(lexer *lx)
{
	int c, n = 0;
	if (lx->pushed) {
		lx->pushed = 0;
		return lx->have_tok;
	}
	if (lx->at_start && !check_start(lx))
		return lx->have_tok = 0;
#if RT_READ_BUFFER
	if (lx->read_block && next_buffered_token(lx))
		return lx->have_tok = 1;
#endif
	for (;;) {
		c = next_byte(lx);
		if (c == '#') {
			/* A comment runs to the end of the line, whatever bytes it holds. */
			while (c != '\n' && c != '\r' && c >= 0)
				c = next_byte(lx);
		}
		if (c < 0) {
			/* The end of the file is on its last line (an editor's last line), not
			 * on the empty line after a final newline. */
			lx->tok[0] = '\0';
			lx->tok_line = lx->last_line;
			return lx->have_tok = 0;
		}
		if (!is_space(c))
			break;
	}
	lx->tok_line = lx->line;
	while (c >= 0 && !is_space(c) && c != '#') {
		if (c < 0x21 || c > 0x7E) {
			lexer_fail(lx, lx->line, "unexpected byte 0x%02X (this is not a text scene file)",
			     (unsigned)c);
			return lx->have_tok = 0;
		}
		if (n == RT_TOKEN_MAX) {
			lx->tok[n] = '\0';
			lexer_fail(lx, lx->tok_line, "token too long (over %d bytes): '%.16s...'",
			     RT_TOKEN_MAX, lx->tok);
			return lx->have_tok = 0;
		}
		lx->tok[n++] = (char)c;
#if RT_READ_BUFFER
		/* The rest of the token, as far as the buffer holds it, without next_byte's
		 * bookkeeping for each byte (teapot's 1.5 MB took 60 instructions a byte). c
		 * came through next_byte (nothing is pending) and ended no line, and no token
		 * byte ends one: the line state next_byte left stands (cr_before, which may
		 * differ, is read only by give_back, after the next next_byte sets it). */
		if (lx->read_block)
			while (lx->taken < lx->buffered && n < RT_TOKEN_MAX &&
			       is_token_byte(lx->buffer[lx->taken]))
				lx->tok[n++] = (char)lx->buffer[lx->taken++];
#endif
		c = next_byte(lx);
	}
	lx->tok[n] = '\0';
	/* Give the delimiter back; its line end is counted again when reread. */
	if (c >= 0)
		give_back(lx, c);
	return lx->have_tok = 1;
}

void lexer_push_back(lexer *lx) { lx->pushed = 1; }


int lexer_is_number(const char *tok)
{
	real unused;
	return real_from_text(tok, 0, &unused) != REAL_TEXT_NOT_A_NUMBER;
}

int lexer_next_value(lexer *lx, const char *what, int whole)
{
	if (lexer_next(lx))
		return 1;
	if (lx->failed)
		return 0;
	return lexer_fail(lx, lx->tok_line, "unexpected end of file (expected %s%s%s)",
		    whole ? "" : "a number (", what, whole ? "" : ")");
}

/* Reads one finite number; a length (or a position) is read times the scene's length
 * scale, 2^length_shift, and counts towards the longest one. */
int lexer_read_value(lexer *lx, const char *what, int length, real *out)
{
	/* One format for the three ways a token can fail: the end of the message for each
	 * status from REAL_TEXT_NOT_A_NUMBER on, and the range named only for a number out of
	 * it. */
	static const char *const why[] = {"", " (not a finite number)", " (out of range)"};
	int shift = length ? lx->length_shift : 0, status, out_of_range;
	*out = REAL_C(0.0); /* defined even on failure (static analysis cannot see through fail) */
#if RT_READ_BUFFER && !REAL_FIXED
	if (next_buffered_number(lx, out))
		status = REAL_TEXT_OK;
	else
#endif
	{
		if (!lexer_next_value(lx, what, 0))
			return 0;
		status = real_from_text(lx->tok, shift, out);
	}
	/* Underflow to zero is no error, but a zero it makes is named for what it is
	 * (zero_word). */
	if (status == REAL_TEXT_TINY) {
		lx->tiny_line = lx->tok_line;
		status = REAL_TEXT_OK;
	}
	if (status == REAL_TEXT_OK) {
		if (length)
			lx->longest = real_max(lx->longest, real_fabs(*out));
		return 1;
	}
	/* Overflow, NaN and infinity are errors. */
	out_of_range = status == REAL_TEXT_OUT_OF_RANGE;
	return lexer_fail(lx, lx->tok_line, "expected a number (%s)%s%s, got '%s'%s", what,
		    out_of_range ? " within " : "", out_of_range ? REAL_RANGE_TEXT : "", lx->tok,
		    why[status - REAL_TEXT_NOT_A_NUMBER]);
}

int lexer_read_triple(lexer *lx, const char *what, int length, vec3 *out)
{
	return lexer_read_value(lx, what, length, &out->x) && lexer_read_value(lx, what, length, &out->y) &&
	       lexer_read_value(lx, what, length, &out->z);
}

/* Reads a number that must not be negative. Checked while lx->tok still holds it, so
 * the message shows the token at its own line (a look-ahead or the next number would
 * move the current token on). */
int lexer_read_nonnegative(lexer *lx, const char *what, real *out)
{
	if (!lexer_read_value(lx, what, 0, out))
		return 0;
	if (*out < REAL_C(0.0))
		return lexer_fail(lx, lx->tok_line, "%s must not be negative, got %s", what, lx->tok);
	return 1;
}

const char *lexer_digits(const char *text, long max, long *out)
{
	long v = 0;
	for (; *text >= '0' && *text <= '9'; text++)
		if (v <= max)
			v = v * 10 + (*text - '0');
	*out = v;
	return text;
}

/* Reads a whole number in [lo, hi]; `limit` names the capacity macro behind hi, if any.
 * Read as strtol reads a token (which holds no spaces): a sign, then decimal digits. A
 * magnitude past hi is held above it (the messages show the token, not the value), so
 * a long run of digits is simply too large. */
int lexer_read_count(lexer *lx, const char *what, long lo, long hi, const char *limit,
		      long *out)
{
	const char *digits, *end;
	*out = 0; /* defined even on failure, as in read_value */
	if (!lexer_next_value(lx, what, 1))
		return 0;
	digits = lx->tok + (lx->tok[0] == '-' || lx->tok[0] == '+');
	end = lexer_digits(digits, hi, out);
	if (end == digits || *end != '\0')
		return lexer_fail(lx, lx->tok_line, "expected %s (a whole number), got '%s'", what,
			    lx->tok);
	if (lx->tok[0] == '-')
		*out = -*out;
	if (limit && *out > hi)
		return lexer_fail(lx, lx->tok_line,
			    "%s %s is over the limit %s = %ld (raise it in src/config.h)", what,
			    lx->tok, limit, hi);
	if (*out < lo || *out > hi)
		return lexer_fail(lx, lx->tok_line, "%s must be %ld to %ld, got %s", what, lo, hi,
			    lx->tok);
	return 1;
}

int lexer_keyword(const char *names, const char *word)
{
	int i = 0;
	while (*names && strcmp(names, word) != 0) {
		names += strlen(names) + 1;
		i++;
	}
	return i;
}
