/* shade_lanes in AVX-512 (eight lanes), compiled with -mavx512f on x86 (the
 * Makefile) and chosen where the processor has it (shade_lanes.c);
 * elsewhere NULL. */
#include <stddef.h>

#include "render/shade_lanes.h"

#if defined(__AVX512F__) && !defined(ACCEL_PORTABLE)
#define SHADE_LANES_FN(name) shade_lanes_avx512_##name
#include "render/shade_lanes_sum.h"

shade_lanes_fn *const shade_lanes_avx512 = SHADE_LANES_FN(sum);
#else
shade_lanes_fn *const shade_lanes_avx512 = NULL;
#endif
