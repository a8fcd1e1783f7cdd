/* The stop signals of every command: caught into cli_cancelled, which the
 * library's loops read, so that a run stops within a pixel and leaves no
 * output file. */
#include <signal.h>

#include "base/platform.h"
#include "cli/cli.h"

volatile sig_atomic_t cli_cancelled;

static void on_signal(int sig)
{
	cli_cancelled = sig;
}

void cli_set_signals(void)
{
	rt_on_stop_signals(on_signal);
}
