/* shade_lanes in the baseline's instructions (SSE2, or plain C in the
 * portable build), and the choice of the widest set the processor has:
 * shade_lanes_avx2.c and shade_lanes_avx512.c hold the others. */
#include "base/simd.h"
#include "render/shade_lanes.h"

#define SHADE_LANES_FN(name) shade_lanes_base_##name
#include "render/shade_lanes_sum.h"

shade_lanes_fn *const shade_lanes_base = SHADE_LANES_FN(sum);

uint64_t shade_lanes(const struct shade_lanes *in, const struct render_shadows *pre,
		     const struct light *lights, size_t n_lights, double out[3][SHADE_LANES])
{
	switch (rt_simd_level()) {
	case RT_SIMD_AVX512:
		if (shade_lanes_avx512)
			return shade_lanes_avx512(in, pre, lights, n_lights, out);
		/* fall through */
	case RT_SIMD_AVX2:
		if (shade_lanes_avx2)
			return shade_lanes_avx2(in, pre, lights, n_lights, out);
		/* fall through */
	default:
		return SHADE_LANES_FN(sum)(in, pre, lights, n_lights, out);
	}
}
