/* The render's kernels of the set of instructions in use (render_kernels.h),
 * and the entry points that call them: the primary rays, the directions
 * to a light and the plain hits' Whitted sum a vector lane a ray. */
#include <stddef.h>

#include "render/render_kernels.h"

RT_SIMD_TABLES(struct render_kernels, render_kernels, render_sets);

const struct render_kernels *render_kernels_of(enum rt_simd s)
{
	return (unsigned)s < RT_SIMD_COUNT ? render_sets[s] : NULL;
}

const struct render_kernels *render_kernels(void)
{
	return render_sets[rt_simd_level()];
}

void camera_lanes(const struct camera *c, const struct camera_lanes_in *in,
		  struct ray_packet *out)
{
	render_kernels()->camera_lanes(c, in, out);
}

uint32_t light_dirs(const struct light_dirs_points *p, struct vec3 pos, struct light_dirs *out,
		    struct light_rays *rays)
{
	return render_kernels()->light_dirs(p, pos, out, rays);
}

uint64_t shade_lanes(const struct shade_lanes *in, const struct render_shadows *pre,
		     const struct light *lights, size_t n_lights, double out[3][SHADE_LANES])
{
	return render_kernels()->shade_lanes(in, pre, lights, n_lights, out);
}
