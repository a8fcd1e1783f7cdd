/* The programs' shared printing of errors and notes, and their exit codes. */
#include <getopt.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stdio.h>
#include <string.h>

#include "base/platform.h"
#include "cli/suggest.h"
#include "cli/tool.h"
#include "whitted/version.h"

static const char *name = "whitted";

void tool_set_name(const char *n)
{
	name = n;
}

const char *tool_name(void)
{
	return name;
}

int tool_usage_error(const char *fmt, ...)
{
	va_list ap;

	fprintf(stderr, "%s: error: ", name);
	va_start(ap, fmt);
	vfprintf(stderr, fmt, ap);
	va_end(ap);
	fprintf(stderr, "\nTry '%s --help' for more information.\n", name);
	return TOOL_EXIT_USAGE;
}

int tool_file_arg(const char *option, const char *arg, const char **out)
{
	if (arg[0] == '\0')
		return tool_usage_error("%s: expected a file name, found ''", option);
	*out = arg;
	return 0;
}

int tool_unknown_option(const char *arg, const struct option *longopts)
{
	const char *names[128], *hit = NULL;
	char word[64];
	size_t n = 0, len = strcspn(arg, "=");

	if (strncmp(arg, "--", 2) == 0 && longopts && len - 2 < sizeof(word)) {
		memcpy(word, arg + 2, len - 2);
		word[len - 2] = '\0';
		for (; longopts[n].name && n < sizeof(names) / sizeof(names[0]); n++)
			names[n] = longopts[n].name;
		hit = cli_suggest(word, names, n);
	}
	if (hit)
		return tool_usage_error("unknown option '%s'; did you mean '--%s'?", arg, hit);
	return tool_usage_error("unknown option '%s'", arg);
}

int tool_out_of_memory(void)
{
	fprintf(stderr, "%s: error: out of memory\n", name);
	return TOOL_EXIT_FAILURE;
}

void tool_print_diag(const struct diag *d, const char *kind)
{
	char line[RT_DIAG_FILE_MAX + RT_DIAG_MSG_MAX + 64];

	diag_format(d, name, kind, line, sizeof(line));
	fprintf(stderr, "%s\n", line);
}

void tool_print_note(void *quiet, const struct diag *note)
{
	if (!quiet || !*(const bool *)quiet)
		tool_print_diag(note, "note");
}

int tool_status_of(int rc)
{
	return rc == -RT_E_INVALID ? TOOL_EXIT_USAGE : TOOL_EXIT_FAILURE;
}

void tool_print_version(const char *program)
{
	printf("%s %s%s%s\n", program, RT_VERSION, rt_platform_note()[0] ? "\n" : "",
	       rt_platform_note());
}
