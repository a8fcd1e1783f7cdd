/* The list of what grade grades, and which names are images: shared by
 * the walk of the operands (grade_inputs.c) and of a zip file's entries
 * (grade_zip.c). */
#include <ctype.h>
#include <stdbool.h>
#include <string.h>

#include "base/alloc.h"
#include "cli/grade_inputs.h"
#include "whitted/image.h"

int grade_inputs_add(struct grade_inputs *in, const char *label, const char *path,
		     unsigned char *data, size_t len, struct diag *d)
{
	struct grade_input *g;

	if (in->n == in->cap) {
		size_t cap = in->cap ? 2 * in->cap : 16;
		struct grade_input *v = rt_reallocarray(in->v, cap, sizeof(*v));
		if (!v) {
			rt_free(data);
			return diag_fail(d, RT_E_NOMEM, "out of memory for the submissions");
		}
		in->v = v;
		in->cap = cap;
	}
	g = &in->v[in->n];
	memset(g, 0, sizeof(*g));
	g->label = rt_strdup(label);
	g->path = path ? rt_strdup(path) : NULL;
	g->data = data;
	g->len = len;
	g->scene = -1;
	if (!g->label || (path && !g->path)) {
		rt_free(g->label);
		rt_free(g->path);
		rt_free(data);
		return diag_fail(d, RT_E_NOMEM, "out of memory for the submissions");
	}
	in->n++;
	return 0;
}

void grade_inputs_free(struct grade_inputs *in)
{
	size_t k;

	for (k = 0; k < in->n; k++) {
		rt_free(in->v[k].label);
		rt_free(in->v[k].student);
		rt_free(in->v[k].id);
		rt_free(in->v[k].path);
		rt_free(in->v[k].data);
	}
	rt_free(in->v);
	memset(in, 0, sizeof(*in));
}

bool grade_ends_with(const char *s, const char *tail)
{
	size_t a = strlen(s), b = strlen(tail), i;

	if (a < b)
		return false;
	for (i = 0; i < b; i++)
		if (tolower((unsigned char)s[a - b + i]) != tail[i])
			return false;
	return true;
}

/* Images (also the lossy kinds, which grade reports as such), by their
 * names. */
bool grade_is_image_name(const char *name)
{
	return image_format_from_path(name) != RT_FORMAT_UNKNOWN || grade_ends_with(name, ".jpg") ||
	       grade_ends_with(name, ".jpeg") || grade_ends_with(name, ".pnm");
}
