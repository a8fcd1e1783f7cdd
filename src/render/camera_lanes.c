/* camera_lanes in the baseline's instructions (SSE2, or plain C in the
 * portable build), and the choice of the widest set the processor has:
 * camera_lanes_avx2.c and camera_lanes_avx512.c hold the others. */
#include "base/simd.h"
#include "render/camera_lanes.h"

#define CAMERA_LANES_FN(name) camera_lanes_base_##name
#include "render/camera_lanes_lanes.h"

camera_lanes_fn *const camera_lanes_base = CAMERA_LANES_FN(rays);

void camera_lanes(const struct camera *c, const struct camera_lanes_in *in,
		  struct ray_packet *out)
{
	switch (rt_simd_level()) {
	case RT_SIMD_AVX512:
		if (camera_lanes_avx512) {
			camera_lanes_avx512(c, in, out);
			return;
		}
		/* fall through */
	case RT_SIMD_AVX2:
		if (camera_lanes_avx2) {
			camera_lanes_avx2(c, in, out);
			return;
		}
		/* fall through */
	default:
		CAMERA_LANES_FN(rays)(c, in, out);
	}
}
