/* hit_lanes' shared part in AVX-512 (eight lanes), compiled with -mavx512f on x86 (the
 * Makefile) and chosen where the processor has it (hit_lanes.c);
 * elsewhere NULL. */
#include <stddef.h>

#include "render/hit_lanes.h"

#if defined(__AVX512F__) && !defined(ACCEL_PORTABLE)
#define HIT_LANES_FN(name) hit_lanes_avx512_##name
#include "render/hit_lanes_lanes.h"

const struct hit_lanes_set hit_lanes_avx512 = { HIT_LANES_FN(points), HIT_LANES_FN(turn),
						HIT_LANES_FN(offsets), HIT_LANES_FN(bounce) };
#else
const struct hit_lanes_set hit_lanes_avx512 = { NULL, NULL, NULL, NULL };
#endif
