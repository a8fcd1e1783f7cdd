/* The difference picture of a check: |reference - image| times 8 beside
 * the mask of the pixels off, the ties and the objects that differ
 * outlined, against the view and the conversion the verdict used. */
#include <string.h>

#include "base/alloc.h"
#include "cli/check.h"

int check_diff_picture(const struct check_reference *ref, const struct check_result *res,
		       struct image *out, struct diag *d)
{
	const struct check_view *v = check_result_view(ref, res);
	const struct image *shown = res->truncated && v->truncated.pixels ? &v->truncated : &v->image;
	size_t slots = scene_shape_count(ref->scene) + 2, k;
	uint8_t *differs = rt_calloc(slots, 1);
	int rc;

	if (!differs)
		return diag_fail(d, RT_E_NOMEM, "out of memory for the difference");
	for (k = 0; k < res->n_objects; k++) {
		const struct grade_object *o = &res->objects[k];
		size_t slot = o->index > 0 ? (size_t)o->index + 1 : strcmp(o->keyword, "floor") == 0;
		if (slot < slots && o->off2 > 5.0 * RT_GRADE_MAX_OFF2)
			differs[slot] = 1;
	}
	rc = grade_diff_picture(shown, &res->image, v->ties, res->ids, differs, out, d);
	rt_free(differs);
	return rc;
}
