/* camera_lanes in AVX2 (four lanes), compiled with -mavx2 on x86 (the
 * Makefile) and chosen where the processor has it (camera_lanes.c);
 * elsewhere NULL. */
#include <stddef.h>

#include "render/camera_lanes.h"

#if defined(__AVX2__) && !defined(ACCEL_PORTABLE)
#define CAMERA_LANES_FN(name) camera_lanes_avx2_##name
#include "render/camera_lanes_lanes.h"

camera_lanes_fn *const camera_lanes_avx2 = CAMERA_LANES_FN(rays);
#else
camera_lanes_fn *const camera_lanes_avx2 = NULL;
#endif
