/* hit_lanes' shared part in AVX2 (four lanes), compiled with -mavx2 on x86 (the
 * Makefile) and chosen where the processor has it (hit_lanes.c);
 * elsewhere NULL. */
#include <stddef.h>

#include "render/hit_lanes.h"

#if defined(__AVX2__) && !defined(ACCEL_PORTABLE)
#define HIT_LANES_FN(name) hit_lanes_avx2_##name
#include "render/hit_lanes_lanes.h"

const struct hit_lanes_set hit_lanes_avx2 = { HIT_LANES_FN(points), HIT_LANES_FN(turn),
						HIT_LANES_FN(offsets), HIT_LANES_FN(bounce) };
#else
const struct hit_lanes_set hit_lanes_avx2 = { NULL, NULL, NULL, NULL };
#endif
