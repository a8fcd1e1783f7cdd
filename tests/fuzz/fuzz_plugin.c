/* libFuzzer's entry point for the plugin loader's checks (make fuzz-plugins). */
#include "harness.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	return fuzz_plugin_one(data, size);
}
