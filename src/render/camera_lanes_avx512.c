/* camera_lanes in AVX-512 (eight lanes), compiled with -mavx512f on x86 (the
 * Makefile) and chosen where the processor has it (camera_lanes.c);
 * elsewhere NULL. */
#include <stddef.h>

#include "render/camera_lanes.h"

#if defined(__AVX512F__) && !defined(ACCEL_PORTABLE)
#define CAMERA_LANES_FN(name) camera_lanes_avx512_##name
#include "render/camera_lanes_lanes.h"

camera_lanes_fn *const camera_lanes_avx512 = CAMERA_LANES_FN(rays);
#else
camera_lanes_fn *const camera_lanes_avx512 = NULL;
#endif
