/* whitted, the command line: reads a scene, renders it (or a region of it,
 * or the frames of an animation) and writes the images; `whitted merge`
 * joins region renders; `whitted compare` and `whitted grade` check
 * students' images against the reference.  The only code that reads argv,
 * prints to stderr or chooses the exit status: 0 success, 1 a scene, input
 * or I/O error, 2 a bad command line, 128 + the signal when interrupted
 * (compare and grade add 3: an image differs). */
#define _POSIX_C_SOURCE 200809L
#include <signal.h>
#include <stdio.h>
#include <string.h>

#include "cli/cli.h"
#include "cli/tool.h"
#include "whitted/scene.h"

volatile sig_atomic_t cli_cancelled;

static void on_signal(int sig)
{
	cli_cancelled = sig;
}

void cli_set_signals(void)
{
	struct sigaction sa, old_sa;

	memset(&sa, 0, sizeof(sa));
	sa.sa_handler = on_signal;
	sigemptyset(&sa.sa_mask);
	sigaction(SIGINT, &sa, NULL);
	sigaction(SIGTERM, &sa, NULL);
	/* A closed terminal stops the render cleanly too, unless the hang-up
	 * is ignored (nohup). */
	if (sigaction(SIGHUP, NULL, &old_sa) == 0 && old_sa.sa_handler != SIG_IGN)
		sigaction(SIGHUP, &sa, NULL);
	/* A file-size limit then fails the write with EFBIG instead of killing
	 * us with a temporary file left behind. */
	signal(SIGXFSZ, SIG_IGN);
}

/* The commands that render (all but merge) say when WHITTED_ISA is not
 * one the walks understand (they then ignore it). */
static void warn_walk_cap(void)
{
	const char *isa = scene_walk_cap_unknown();

	if (isa)
		fprintf(stderr, "%s: warning: WHITTED_ISA=%s names no walk (sse2, avx2 or avx512): "
			"ignored\n", tool_name(), isa);
}

int main(int argc, char **argv)
{
	/* A subcommand comes first; a scene file named "merge", "compare" or
	 * "grade" is ./merge, ./compare, ./grade. */
	if (argc >= 2 && strcmp(argv[1], "merge") == 0) {
		tool_set_name("whitted merge");
		return merge_main(argc - 1, argv + 1);
	}
	if (argc >= 2 && strcmp(argv[1], "compare") == 0) {
		tool_set_name("whitted compare");
		warn_walk_cap();
		return compare_main(argc - 1, argv + 1);
	}
	if (argc >= 2 && strcmp(argv[1], "grade") == 0) {
		tool_set_name("whitted grade");
		warn_walk_cap();
		return grade_main(argc - 1, argv + 1);
	}
	tool_set_name("whitted");
	warn_walk_cap();
	return render_main(argc, argv);
}
