/* The libFuzzer entry point for the scene parser (built by `make fuzz`),
 * with the plugins of $WHITTED_PLUGIN_PATH loaded first. */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#include "harness.h"

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
	(void)argc, (void)argv;
	if (fuzz_init() < 0)
		exit(1);
	return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	return fuzz_scene_one(data, size);
}
