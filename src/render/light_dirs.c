/* light_dirs in the baseline's instructions (SSE2, or plain C in the
 * portable build), and the choice of the widest set the processor has:
 * light_dirs_avx2.c and light_dirs_avx512.c hold the others. */
#include "base/simd.h"
#include "render/light_dirs.h"

#define LIGHT_DIRS(name) light_dirs_base_##name
#include "render/light_dirs_lanes.h"

void (*const light_dirs_base)(const struct light_dirs_points *p, struct vec3 pos,
			      struct light_dirs *out) = LIGHT_DIRS(dirs);

void light_dirs(const struct light_dirs_points *p, struct vec3 pos, struct light_dirs *out)
{
	switch (rt_simd_level()) {
	case RT_SIMD_AVX512:
		if (light_dirs_avx512) {
			light_dirs_avx512(p, pos, out);
			return;
		}
		/* fall through */
	case RT_SIMD_AVX2:
		if (light_dirs_avx2) {
			light_dirs_avx2(p, pos, out);
			return;
		}
		/* fall through */
	default:
		LIGHT_DIRS(dirs)(p, pos, out);
	}
}
