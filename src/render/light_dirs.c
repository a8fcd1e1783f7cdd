/* light_dirs in the baseline's instructions (SSE2, or plain C in the
 * portable build), and the choice of the widest set the processor has:
 * light_dirs_avx2.c and light_dirs_avx512.c hold the others. */
#include "base/simd.h"
#include "render/light_dirs.h"

#define LIGHT_DIRS(name) light_dirs_base_##name
#include "render/light_dirs_lanes.h"

light_dirs_fn *const light_dirs_base = LIGHT_DIRS(dirs);

uint32_t light_dirs(const struct light_dirs_points *p, struct vec3 pos, struct light_dirs *out,
		    struct light_rays *rays)
{
	switch (rt_simd_level()) {
	case RT_SIMD_AVX512:
		if (light_dirs_avx512)
			return light_dirs_avx512(p, pos, out, rays);
		/* fall through */
	case RT_SIMD_AVX2:
		if (light_dirs_avx2)
			return light_dirs_avx2(p, pos, out, rays);
		/* fall through */
	default:
		return LIGHT_DIRS(dirs)(p, pos, out, rays);
	}
}
