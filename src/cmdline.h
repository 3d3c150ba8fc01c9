/* cmdline.h - command-line options in GNU getopt_long's forms, written for rt so that
 * every build has it (the MCU's C library has no getopt_long): short options alone (-q),
 * in clusters (-qa), with a value attached (-oFILE, -s320x240) or following (-o FILE);
 * long options (--output) with a value after = or following, and abbreviated to any
 * unambiguous prefix (--out); -- ends the options; operands may come anywhere before it,
 * and - is an operand (standard input). It compiles for the MCU too (its C library has
 * memcpy, memset and strlen, all this uses), but the MCU's main keeps its own loop over
 * its six options: this parser would cost 808 bytes of the M0's flash, which has 4 to
 * spare. See LICENSE for copyright and licence. */
#ifndef RT_CMDLINE_H
#define RT_CMDLINE_H

typedef struct {
	const char *name; /* the long name without its --; NULL for none */
	char letter;      /* the short name; 0 for none */
	char needs_value; /* 1 when the option takes a value */
} cmdline_option;

typedef struct {
	int argc;
	char **argv;
	int next;            /* the next element of argv to read */
	const char *cluster; /* the rest of a cluster of short options, or NULL */
	int operands_only;   /* after -- */
	const char *value;   /* the value of the option just read; an operand's text */
	char written[160];   /* the option as written, for messages: -o, --output */
	const char *error;   /* CMDLINE_ERROR: what is wrong, a format for `written` */
} cmdline;

#define CMDLINE_END (-1)     /* no more arguments */
#define CMDLINE_OPERAND (-2) /* an operand, in value */
#define CMDLINE_ERROR (-3)   /* error is a message with one %s, for written */

void cmdline_start(cmdline *c, int argc, char **argv);

/* The next option: its index in options[0 .. count - 1], with its value in c->value when
 * it takes one; or CMDLINE_OPERAND, CMDLINE_END or CMDLINE_ERROR. */
int cmdline_next(cmdline *c, const cmdline_option *options, int count);

#endif
