/* cmdline.c - GNU getopt_long's option forms (cmdline.h), with no state beyond the
 * cmdline the caller holds, and of the C library only what the MCU's has (memcpy,
 * memset, strlen).
 * See LICENSE for copyright and licence. */
#include "cmdline.h"

#include <string.h>

void cmdline_start(cmdline *c, int argc, char **argv)
{
	memset(c, 0, sizeof *c);
	c->argc = argc;
	c->argv = argv;
	c->next = 1;
}

/* Keeps the option as written (cut to fit) for messages. */
static void note_written(cmdline *c, const char *text, size_t length)
{
	if (length > sizeof c->written - 1)
		length = sizeof c->written - 1;
	memcpy(c->written, text, length);
	c->written[length] = '\0';
}

static int fail(cmdline *c, const char *error)
{
	c->error = error;
	return CMDLINE_ERROR;
}

/* The value of option i: what follows it in its own argument (`attached`, NULL when
 * nothing does), else the next argument. */
static int take_value(cmdline *c, const cmdline_option *options, int i, const char *attached)
{
	if (!options[i].needs_value) {
		if (attached)
			return fail(c, "option '%s' takes no value");
		return i;
	}
	if (attached) {
		c->value = attached;
		return i;
	}
	if (c->next >= c->argc)
		return fail(c, "option '%s' needs a value");
	c->value = c->argv[c->next++];
	return i;
}

/* Appends text to c->written, cut to fit. */
static void append_written(cmdline *c, const char *text)
{
	size_t used = strlen(c->written);
	while (*text != '\0' && used < sizeof c->written - 1)
		c->written[used++] = *text++;
	c->written[used] = '\0';
}

/* How a long option as written (`text`, up to its = or its end) matches a name: 2 when
 * it is the name, 1 when it begins it, 0 when neither. */
static int name_match(const char *name, const char *text)
{
	while (*text != '\0' && *text != '=' && *text == *name) {
		text++;
		name++;
	}
	if (*text != '\0' && *text != '=')
		return 0;
	return *name == '\0' ? 2 : 1;
}

/* A long option, `text` after its --: an exact name, else the one name it begins. */
static int long_option(cmdline *c, const cmdline_option *options, int count, const char *text)
{
	const char *equals = text;
	int i, found = -1, matches = 0;
	while (*equals != '\0' && *equals != '=')
		equals++;
	note_written(c, text - 2, (size_t)(equals - text) + 2);
	for (i = 0; i < count; i++) {
		int match = options[i].name ? name_match(options[i].name, text) : 0;
		if (match == 2) {
			found = i;
			matches = 1;
			break;
		}
		if (match == 1) {
			found = i;
			matches++;
		}
	}
	if (matches == 0)
		return fail(c, "unknown option '%s'");
	if (matches > 1) {
		/* '--a' is ambiguous: --antialias --aa-threshold --aa-depth */
		note_written(c, "'", 1);
		append_written(c, text - 2);
		c->written[equals - text + 3] = '\0';
		append_written(c, "' is ambiguous:");
		for (i = 0; i < count; i++)
			if (options[i].name && name_match(options[i].name, text) == 1) {
				append_written(c, " --");
				append_written(c, options[i].name);
			}
		return fail(c, "option %s");
	}
	/* Messages about its value name it in full. */
	note_written(c, "--", 2);
	append_written(c, options[found].name);
	return take_value(c, options, found, *equals == '=' ? equals + 1 : NULL);
}

/* The next short option of the cluster in c->cluster. */
static int short_option(cmdline *c, const cmdline_option *options, int count)
{
	char letter = *c->cluster++;
	int i;
	c->written[0] = '-';
	c->written[1] = letter;
	c->written[2] = '\0';
	for (i = 0; i < count && options[i].letter != letter; i++)
		;
	if (i == count) {
		c->cluster = NULL;
		return fail(c, "unknown option '%s'");
	}
	if (options[i].needs_value) {
		/* The rest of the cluster is the value, if there is a rest. */
		const char *attached = *c->cluster ? c->cluster : NULL;
		c->cluster = NULL;
		return take_value(c, options, i, attached);
	}
	if (*c->cluster == '\0')
		c->cluster = NULL;
	return i;
}

int cmdline_next(cmdline *c, const cmdline_option *options, int count)
{
	const char *a;
	c->value = NULL;
	c->error = NULL;
	if (c->cluster)
		return short_option(c, options, count);
	if (c->next >= c->argc)
		return CMDLINE_END;
	a = c->argv[c->next++];
	if (c->operands_only || a[0] != '-' || a[1] == '\0') {
		c->value = a;
		return CMDLINE_OPERAND;
	}
	if (a[1] == '-') {
		if (a[2] == '\0') {
			c->operands_only = 1;
			return cmdline_next(c, options, count);
		}
		return long_option(c, options, count, a + 2);
	}
	c->cluster = a + 1;
	return short_option(c, options, count);
}
