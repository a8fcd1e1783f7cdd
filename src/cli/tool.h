/* What every program of whitted does alike: its name in messages, the
 * exit statuses, and the printing of errors, notes and usage errors.  The
 * only code of the project, with the programs' main files, that prints to
 * stderr. */
#ifndef RT_CLI_TOOL_H
#define RT_CLI_TOOL_H

#include "whitted/diag.h"

enum tool_exit {
	TOOL_EXIT_OK = 0,
	TOOL_EXIT_FAILURE = 1,	/* a scene, input or I/O error */
	TOOL_EXIT_USAGE = 2,	/* a bad command line */
	TOOL_EXIT_SIGNAL = 128,	/* + the signal's number */
};

/* The name that starts every message ("whitted", "whitted merge"). */
void tool_set_name(const char *name);
const char *tool_name(void);

/* "NAME: error: MESSAGE" and the --help hint; returns TOOL_EXIT_USAGE. */
int tool_usage_error(const char *fmt, ...)
#if defined(__GNUC__)
	__attribute__((format(printf, 1, 2)))
#endif
	;
/* The usage error for an option getopt_long did not know, as it appears
 * in argv ("--samles", "--samles=3", "-x"): "unknown option '--samles';
 * did you mean '--samples'?" when one of longopts (getopt's array, ended
 * by a NULL name) is near (cli/suggest.h).  Returns TOOL_EXIT_USAGE. */
struct option;
int tool_unknown_option(const char *arg, const struct option *longopts);

/* A file name option's value into *out: 0, or a usage error (2) for an
 * empty one ("--output: expected a file name, found ''"). */
int tool_file_arg(const char *option, const char *arg, const char **out);
/* "NAME: error: out of memory", for an allocation of the program's own
 * (no library call's diag to print); returns TOOL_EXIT_FAILURE. */
int tool_out_of_memory(void);
/* One diagnostic as "FILE:LINE:COL: KIND: MSG" (see diag_format). */
void tool_print_diag(const struct diag *d, const char *kind);
/* A diag_note_fn: prints the note unless *(const bool *)quiet is true. */
void tool_print_note(void *quiet, const struct diag *note);
/* --version's text on stdout: "PROGRAM VERSION" and, where the platform
 * leaves something out, its note on the next line. */
void tool_print_version(const char *program);
/* The exit status for a failed library call: TOOL_EXIT_USAGE when the
 * command line was at fault (RT_E_INVALID), TOOL_EXIT_FAILURE otherwise. */
int tool_status_of(int rc);

#endif
