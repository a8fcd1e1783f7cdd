/* Where a submission differs, object by object: the object each pixel's
 * primary ray hits in the reference (an object-id buffer), and for the
 * background, the floor and each object of the file its pixels, the share
 * of them off by more than 2 levels and their PSNR. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "accel/accel.h"
#include "base/alloc.h"
#include "base/thread.h"
#include "grade/grade_impl.h"
#include "scene/scene_impl.h"

/* A shape's position in the scene, found by its address. */
struct grade_shape_at {
	const struct shape *shape;
	int32_t index;
};

static int grade_shape_at_cmp(const void *a, const void *b)
{
	const struct shape *x = ((const struct grade_shape_at *)a)->shape;
	const struct shape *y = ((const struct grade_shape_at *)b)->shape;

	return x < y ? -1 : x > y;
}

struct grade_ids_part {
	const struct grade_job *job;
	const struct grade_shape_at *at;
	size_t n_at;
	int32_t *ids;
	int y0, y1;
};

static void *grade_ids_rows(void *arg)
{
	struct grade_ids_part *p = arg;
	const struct camera *cam = p->job->camera;
	int x, y;

	for (y = p->y0; y < p->y1; y++)
		for (x = 0; x < cam->width; x++) {
			struct ray r = camera_ray(cam, x, y);
			double t = INFINITY;
			const struct shape *s = accel_intersect(p->job->scene->accel, &r, 0.0, &t);
			int32_t id = GRADE_ID_BACKGROUND;
			if (s) {
				struct grade_shape_at key = { s, 0 }, *hit;
				hit = bsearch(&key, p->at, p->n_at, sizeof(key), grade_shape_at_cmp);
				id = hit ? hit->index : GRADE_ID_BACKGROUND;
			}
			p->ids[(size_t)y * (size_t)cam->width + (size_t)x] = id;
		}
	return NULL;
}

bool grade_primary_hit(const struct grade_job *job, const struct ray *r, double *t)
{
	return accel_intersect(job->scene->accel, r, 0.0, t) != NULL;
}

int grade_object_ids(const struct grade_job *job, int32_t *ids, struct diag *d)
{
	const struct scene *s = job->scene;
	struct grade_ids_part parts[RT_PARTS_MAX];
	struct grade_shape_at *at;
	size_t i, n = s->n_shapes;
	int k, nparts = job->threads < 1 ? 1 : job->threads > RT_PARTS_MAX ? RT_PARTS_MAX : job->threads;
	int h = job->camera->height;

	if (!(at = rt_reallocarray(NULL, n ? n : 1, sizeof(*at))))
		return diag_fail(d, RT_E_NOMEM, "out of memory for the object ids");
	for (i = 0; i < n; i++) {
		at[i].shape = s->shapes[i];
		at[i].index = s->shapes[i] == s->floor ? GRADE_ID_FLOOR : (int32_t)i;
	}
	qsort(at, n, sizeof(*at), grade_shape_at_cmp);
	nparts = nparts > h ? h : nparts;
	for (k = 0; k < nparts; k++) {
		parts[k].job = job;
		parts[k].at = at;
		parts[k].n_at = n;
		parts[k].ids = ids;
		parts[k].y0 = (int)((long)h * k / nparts);
		parts[k].y1 = (int)((long)h * (k + 1) / nparts);
	}
	rt_run_parts(parts, sizeof(parts[0]), nparts, grade_ids_rows);
	rt_free(at);
	return 0;
}

/* The objects' entries in the order of grade_objects: the background,
 * the floor, then the file's objects by index. */
static size_t grade_slot(int32_t id)
{
	return id == GRADE_ID_BACKGROUND ? 0 : id == GRADE_ID_FLOOR ? 1 : (size_t)id + 2;
}

int grade_objects(const struct grade_job *job, const int32_t *ids, const struct image *ref,
		  const struct image *sub, const uint8_t *skip, struct grade_object **out,
		  size_t *n_out, struct diag *d)
{
	const struct scene *s = job->scene;
	size_t slots = s->n_shapes + 2, i, total = (size_t)ref->width * (size_t)ref->height, n = 0;
	double *sq = rt_calloc(slots, sizeof(double));
	struct grade_object *o = rt_calloc(slots, sizeof(*o));

	*out = NULL;
	*n_out = 0;
	if (!sq || !o) {
		rt_free(sq);
		rt_free(o);
		return diag_fail(d, RT_E_NOMEM, "out of memory for the objects' figures");
	}
	for (i = 0; i < total; i++) {
		size_t k = grade_slot(ids[i]);
		int c, worst = 0;
		if (skip && skip[i])
			continue;
		o[k].pixels++;
		for (c = 0; c < 3; c++) {
			int dv = abs((int)ref->pixels[3 * i + c] - (int)sub->pixels[3 * i + c]);
			sq[k] += (double)dv * dv;
			worst = dv > worst ? dv : worst;
		}
		o[k].differ += worst > 2;
	}
	for (i = 0; i < slots; i++) {
		const struct shape *sh;
		if (o[i].pixels == 0)
			continue;
		o[n] = o[i];
		o[n].index = i < 2 ? 0 : (long)(i - 2) + 1;
		sh = i >= 2 ? s->shapes[i - 2] : NULL;
		o[n].keyword = i == 0 ? "background" : i == 1 ? "floor" : sh->ops->keyword;
		o[n].off2 = (double)o[n].differ / (double)o[n].pixels;
		sq[i] /= 3.0 * (double)o[n].pixels;
		o[n].psnr = sq[i] == 0.0 ? INFINITY : 10.0 * log10(255.0 * 255.0 / sq[i]);
		n++;
	}
	rt_free(sq);
	*out = o;
	*n_out = n;
	return 0;
}
