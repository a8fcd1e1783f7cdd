/* light_dirs in AVX-512 (eight lanes), compiled with -mavx512f on x86 (the Makefile)
 * and chosen where the processor has it (light_dirs.c); elsewhere NULL. */
#include <stddef.h>

#include "render/light_dirs.h"

#if defined(__AVX512F__) && !defined(ACCEL_PORTABLE)
#define LIGHT_DIRS(name) light_dirs_avx512_##name
#include "render/light_dirs_lanes.h"

light_dirs_fn *const light_dirs_avx512 = LIGHT_DIRS(dirs);
#else
light_dirs_fn *const light_dirs_avx512 = NULL;
#endif
