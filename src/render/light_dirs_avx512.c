/* light_dirs in AVX-512 (eight lanes), compiled with -mavx512f on x86 (the Makefile)
 * and chosen where the processor has it (light_dirs.c); elsewhere NULL. */
#include <stddef.h>

#include "render/light_dirs.h"

#if defined(__AVX512F__) && !defined(ACCEL_PORTABLE)
#define LIGHT_DIRS(name) light_dirs_avx512_##name
#include "render/light_dirs_lanes.h"

void (*const light_dirs_avx512)(const struct light_dirs_points *p, struct vec3 pos,
			      struct light_dirs *out) = LIGHT_DIRS(dirs);
#else
void (*const light_dirs_avx512)(const struct light_dirs_points *p, struct vec3 pos,
			      struct light_dirs *out) = NULL;
#endif
