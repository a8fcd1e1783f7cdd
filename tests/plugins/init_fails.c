/* A plugin whose init fails without registering anything
 * (tests/cli/plugins.sh). */
#include "whitted/plugin.h"

WHITTED_PLUGIN_ABI_SYMBOL;

int whitted_plugin_init(const struct whitted_plugin_host *host)
{
	(void)host;
	return -1;
}
