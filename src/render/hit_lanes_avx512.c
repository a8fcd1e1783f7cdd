/* hit_lanes' shared part in AVX-512 (eight lanes), compiled with -mavx512f on x86 (the
 * Makefile) and chosen where the processor has it (hit_lanes.c);
 * elsewhere NULL. */
#include <stddef.h>

#include "render/hit_lanes.h"

#if defined(__AVX512F__) && !defined(ACCEL_PORTABLE)
#define HIT_LANES_FN(name) hit_lanes_avx512_##name
#include "render/hit_lanes_lanes.h"

hit_lanes_turn_fn *const hit_lanes_turn_avx512 = HIT_LANES_FN(turn);
#else
hit_lanes_turn_fn *const hit_lanes_turn_avx512 = NULL;
#endif
