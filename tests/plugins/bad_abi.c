/* A plugin built for another ABI version than the host's: refused before its
 * init runs (tests/cli/plugins.sh). */
#include "whitted/plugin.h"

/* 99 by default; -DBAD_ABI=N for another (an older one). */
#ifndef BAD_ABI
#define BAD_ABI 99
#endif
const unsigned whitted_plugin_abi = BAD_ABI;

int whitted_plugin_init(const struct whitted_plugin_host *host)
{
	(void)host;
	return 0;
}
