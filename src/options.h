/* options.h - rt's command line on a host: what it asks for, read and checked.
 * See LICENSE for copyright and licence. */
#ifndef RT_OPTIONS_H
#define RT_OPTIONS_H

#include "antialias.h"
#include "colour.h"

enum format { FORMAT_DEFAULT, FORMAT_PPM, FORMAT_PNG, FORMAT_ASCII, FORMAT_ANSI, FORMAT_IDS };

typedef struct {
	const char *scene_path;  /* "-": standard input */
	const char *scene_name;  /* for messages: the path, or <stdin> */
	const char *output_path; /* NULL: standard output */
	int to_stdout;           /* -o - */
	enum format format;
	int width, height; /* 0: the scene's */
	int depth;         /* 0: the scene's */
	int jobs;          /* processes rendering; 0: one per processor */
	int antialias;     /* -a */
	antialias aa;      /* its settings */
	int colours;       /* --colours: an enum colour_pipeline, -1 for the scene's */
	int columns;       /* preview width, 0: the terminal's */
	int row_first, row_end; /* --rows: [first, end); end 0 for all rows */
	int spd;
	int stats;
	int quiet;     /* -q: no warnings */
	int chosen;    /* the preview is rt's choice for a terminal, not asked for */
	int size_only; /* --print-size: print the image size and stop */
	const char *time_limit; /* --time-limit as given; NULL for none */
	unsigned long long time_limit_micros;
} options;

/* Reads the command line into o. Returns -1 to go on, else the exit status: 0 after
 * --help or --version, 2 after a usage error (reported). */
int options_parse(int argc, char **argv, options *o);

/* The exit status after a text answer on standard output (--help, --version,
 * --print-size): 1, reported, when it could not be written (a full disk, /dev/full). */
int options_stdout_status(void);

#endif
