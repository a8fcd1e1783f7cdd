/* light_dirs in AVX2 (four lanes), compiled with -mavx2 on x86 (the Makefile)
 * and chosen where the processor has it (light_dirs.c); elsewhere NULL. */
#include <stddef.h>

#include "render/light_dirs.h"

#if defined(__AVX2__) && !defined(ACCEL_PORTABLE)
#define LIGHT_DIRS(name) light_dirs_avx2_##name
#include "render/light_dirs_lanes.h"

light_dirs_fn *const light_dirs_avx2 = LIGHT_DIRS(dirs);
#else
light_dirs_fn *const light_dirs_avx2 = NULL;
#endif
