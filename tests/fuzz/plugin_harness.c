/* The fuzz target of the plugin loader's checks before dlopen
 * (plugin_elf_check): any bytes, and no read outside them.  A file that
 * passes is not loaded: dlopen would run its code. */
#include "harness.h"
#include "plugin/loader.h"

int fuzz_plugin_one(const uint8_t *data, size_t size)
{
	struct diag d;

	(void)plugin_elf_check("fuzz.so", data, size, &d);
	return 0;
}
