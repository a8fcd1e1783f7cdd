/* Glass: the transmission and index of refraction that --glass gives a
 * scene file's object, which no course file can say. */
#include <math.h>

#include "scene/scene_impl.h"
#include "whitted/diag.h"
#include "whitted/scene.h"

int scene_set_glass(struct scene *s, size_t index, double ior, double kt, struct diag *d)
{
	struct material *m;

	if (index >= s->n_shapes)
		return diag_fail(d, RT_E_INVALID, "--glass %zu: the scene has %zu object%s", index + 1,
				 s->n_shapes, s->n_shapes == 1 ? "" : "s");
	if (!(ior > 0.0 && isfinite(ior)))
		return diag_fail(d, RT_E_INVALID,
				 "--glass %zu: the index of refraction must be finite and > 0, found %g",
				 index + 1, ior);
	if (!(kt > 0.0 && kt < 1.0))
		return diag_fail(d, RT_E_INVALID,
				 "--glass %zu: the transmission must be in (0, 1), found %g", index + 1, kt);
	m = &s->shapes[index]->mat;
	m->ior = ior;
	m->kt = kt;
	return 0;
}
