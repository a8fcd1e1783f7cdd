/* whitted, the command line: reads a scene, renders it (or a region of it,
 * or the frames of an animation) and writes the images; `whitted merge`
 * joins region renders; `whitted compare` and `whitted grade` check
 * students' images against the reference.  The only code that reads argv,
 * prints to stderr or chooses the exit status: 0 success, 1 a scene, input
 * or I/O error, 2 a bad command line, 128 + the signal when interrupted
 * (compare and grade add 3: an image differs). */
#define _POSIX_C_SOURCE 200809L
#include <signal.h>
#include <stdbool.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "base/platform.h"
#include "cli/cli.h"
#include "cli/suggest.h"
#include "cli/tool.h"
#include "whitted/scene.h"

/* The commands that render (all but merge) say when WHITTED_ISA is not
 * one the walks understand (they then ignore it). */
static void warn_walk_cap(void)
{
	const char *isa = scene_walk_cap_unknown();

	if (isa)
		fprintf(stderr, "%s: warning: WHITTED_ISA=%s names no walk (sse2, avx2 or avx512): "
			"ignored\n", tool_name(), isa);
}

/* The subcommands, each with its name in messages and its entry point;
 * the first is the default (a render), named by none. */
static const struct subcommand {
	const char *word, *name;
	int (*run)(int argc, char **argv);
	bool renders;
} subcommands[] = {
	{ NULL, "whitted", render_main, true },
	{ "merge", "whitted merge", merge_main, false },
	{ "compare", "whitted compare", compare_main, true },
	{ "grade", "whitted grade", grade_main, true },
	{ "explain", "whitted explain", explain_main, true },
};
#define N_SUBCOMMANDS (sizeof(subcommands) / sizeof(subcommands[0]))

static int run_subcommand(const struct subcommand *c, int argc, char **argv)
{
	tool_set_name(c->name);
	if (c->renders)
		warn_walk_cap();
	return c->run(argc, argv);
}

/* Whether argv[1] looks like a word meant as a subcommand: lower-case
 * letters and '-', and no file of that name (a scene file may be called
 * anything: only what is not there is taken for a slip). */
static bool looks_like_command(const char *w)
{
	size_t n = strspn(w, "abcdefghijklmnopqrstuvwxyz-");

	return n >= 2 && w[n] == '\0' && w[0] != '-' && access(w, F_OK) != 0;
}

/* A first word that is no subcommand and no file: "whitted comapre" (did
 * you mean compare?), "whitted view" (the viewer's own program), or 0 to
 * go on and read it as the scene. */
static int not_a_command(const char *w)
{
	const char *words[N_SUBCOMMANDS];
	const char *hit;
	size_t i;

	if (!looks_like_command(w))
		return 0;
	tool_set_name("whitted");
	if (strcmp(w, "view") == 0 || strcmp(w, "viewer") == 0)
		return tool_usage_error("'%s' is not a subcommand (and no file): the viewer is its own "
					"program, whitted-view SCENE", w);
	if (strcmp(w, "pov") == 0 || strcmp(w, "export") == 0 || strcmp(w, "scene2pov") == 0)
		return tool_usage_error("'%s' is not a subcommand (and no file): the POV-Ray export is "
					"its own program, scene2pov SCENE", w);
	if (strcmp(w, "render") == 0)
		return tool_usage_error("'render' is not a subcommand (and no file): whitted renders "
					"without one, whitted [OPTIONS] SCENE");
	/* The subcommands' words, then "help" in the place of the render's. */
	for (i = 1; i < N_SUBCOMMANDS; i++)
		words[i - 1] = subcommands[i].word;
	words[N_SUBCOMMANDS - 1] = "help";
	hit = cli_suggest(w, words, N_SUBCOMMANDS);
	if (hit)
		return tool_usage_error("'%s' is not a subcommand (and no file); did you mean "
					"'whitted %s'?", w, hit);
	return 0;
}

int main(int argc, char **argv)
{
	size_t i;
	int rc;

	/* A subcommand comes first; a scene file named "merge", "compare" or
	 * "grade" is ./merge, ./compare, ./grade. */
	for (i = 1; argc >= 2 && i < N_SUBCOMMANDS; i++)
		if (strcmp(argv[1], subcommands[i].word) == 0)
			return run_subcommand(&subcommands[i], argc - 1, argv + 1);
	/* whitted help [SUBCOMMAND]: that one's --help. */
	if (argc >= 2 && strcmp(argv[1], "help") == 0 && access(argv[1], F_OK) != 0) {
		char help[] = "--help";
		char *args[3] = { argv[0], help, NULL };

		for (i = 1; argc >= 3 && i < N_SUBCOMMANDS; i++)
			if (strcmp(argv[2], subcommands[i].word) == 0) {
				args[0] = argv[2];
				return run_subcommand(&subcommands[i], 2, args);
			}
		if (argc >= 3)
			return tool_usage_error("help: no subcommand '%s' (merge, compare, grade or explain)",
						argv[2]);
		return run_subcommand(&subcommands[0], 2, args);
	}
	if (argc >= 2 && (rc = not_a_command(argv[1])) != 0)
		return rc;
	return run_subcommand(&subcommands[0], argc, argv);
}
