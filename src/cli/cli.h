/* The commands of the whitted program and what they share with main.c:
 * the signal that stops a render or a merge cleanly. */
#ifndef RT_CLI_CLI_H
#define RT_CLI_CLI_H

#include <signal.h>

/* The signal that arrived (SIGINT, SIGTERM, SIGHUP), or 0. */
extern volatile sig_atomic_t cli_cancelled;
/* Catches those signals into cli_cancelled, and ignores SIGXFSZ so that a
 * file-size limit fails the write instead of killing the process. */
void cli_set_signals(void);

/* `whitted [OPTIONS] SCENE` and `whitted merge ...` (argv[0] "merge"):
 * each returns the exit status. */
int render_main(int argc, char **argv);
int merge_main(int argc, char **argv);
/* `whitted compare ...` and `whitted grade ...` (argv[0] the subcommand). */
int compare_main(int argc, char **argv);
int grade_main(int argc, char **argv);
/* `whitted explain ...` (argv[0] "explain"). */
int explain_main(int argc, char **argv);

#endif
