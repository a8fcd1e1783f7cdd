/* camera_lanes (camera_lanes.h) written once over base/lanes.h's vectors:
 * the including file, compiled for one set of instructions, defines
 * CAMERA_LANES_FN(name), the name it gets.  The scalar lines each step
 * stands for are camera.c's camera_span_rays and vec3.h's
 * vec3_normalize. */
#include "base/lanes.h"
#include "render/camera_lanes.h"

static void CAMERA_LANES_FN(rays)(const struct camera *c, const struct camera_lanes_in *in,
				  struct ray_packet *out)
{
	const lv zero = lv_set1(0.0), one = lv_set1(1.0);
	const lv fx = lv_set1(c->forward.x), fy = lv_set1(c->forward.y), fz = lv_set1(c->forward.z);
	const lv ex = lv_set1(c->eye.x), ey = lv_set1(c->eye.y), ez = lv_set1(c->eye.z);
	int j;

	for (j = 0; j < CAMERA_LANES; j += LANES_W) {
		/* w = vec3_add(forward, vec3_add(right_u, up_v)) */
		lv wx = lv_add(fx, lv_add(lv_load(in->ru[0] + j), lv_load(in->uv[0] + j)));
		lv wy = lv_add(fy, lv_add(lv_load(in->ru[1] + j), lv_load(in->uv[1] + j)));
		lv wz = lv_add(fz, lv_add(lv_load(in->ru[2] + j), lv_load(in->uv[2] + j)));
		/* len = sqrt(vec3_dot(w, w)); len > 0 ? w * (1 / len) : w */
		lv len = lv_sqrt(lv_add(lv_add(lv_mul(wx, wx), lv_mul(wy, wy)), lv_mul(wz, wz)));
		lv inv = lv_div(one, len);
		lm pos = lv_gt(len, zero);

		if (c->near > 0.0) {
			const lv nr = lv_set1(c->near);
			lv_store(out->ox + j, lv_add(ex, lv_mul(wx, nr)));
			lv_store(out->oy + j, lv_add(ey, lv_mul(wy, nr)));
			lv_store(out->oz + j, lv_add(ez, lv_mul(wz, nr)));
		} else {
			lv_store(out->ox + j, ex);
			lv_store(out->oy + j, ey);
			lv_store(out->oz + j, ez);
		}
		lv_store(out->dx + j, lv_sel(pos, lv_mul(wx, inv), wx));
		lv_store(out->dy + j, lv_sel(pos, lv_mul(wy, inv), wy));
		lv_store(out->dz + j, lv_sel(pos, lv_mul(wz, inv), wz));
	}
}
