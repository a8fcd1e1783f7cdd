/* The programs' side of plugins: --plugin FILE.so (repeatable, a shared
 * scene option), then WHITTED_PLUGIN_PATH, loaded before the scene is read,
 * whitted --list-shapes, and the record of the plugins a scene used for
 * its tiles.  Nothing here prints but cli_print_shapes. */
#ifndef RT_CLI_PLUGIN_OPTS_H
#define RT_CLI_PLUGIN_OPTS_H

#include <stdio.h>

#include "plugin/loader.h"
#include "whitted/diag.h"
#include "whitted/scene.h"

/* The environment variable of the plugin directories. */
#define CLI_PLUGIN_PATH_ENV "WHITTED_PLUGIN_PATH"

/* Loads files[0..n) in order, then every .so of $WHITTED_PLUGIN_PATH's
 * directories; once (a second call does nothing).  A file of the path
 * whose plugin name or keyword is one of files' is skipped, with a note
 * (the files override the path); any other clash is an error.  On failure
 * the message names the file, and the status is -RT_E_IO or another code
 * of a scene input error (never RT_E_INVALID: a bad plugin is bad input,
 * exit 1). */
int cli_plugins_load(const char *const *files, int n, diag_note_fn *note, void *note_ctx,
		     struct diag *d);
/* The record of the plugins whose shapes s has (see plugin_records), in a
 * static buffer: "" when it has none. */
const char *cli_plugins_used(const struct scene *s);
/* "KEYWORD  ORIGIN  DIALECTS" for every registered shape, one a line. */
void cli_print_shapes(FILE *out);

#endif
