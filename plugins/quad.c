/* The quad plugin: the `quad` object of the course's student extensions,
 * four corners and then the material,
 *     quad
 *     X1 Y1 Z1
 *     X2 Y2 Z2
 *     X3 Y3 Z3
 *     X4 Y4 Z4
 *     R G B
 *     KA KD KS KR
 *     SHININESS
 * seen from both sides.  It is the two triangles 1-2-3 and 1-3-4 (what a
 * planar convex quad is, and what the students' own code drew; a corner
 * order that crosses over gives a bow tie, as theirs did).  A quad whose
 * fourth corner is off the plane of the first three is still those two
 * triangles, with a note; one whose corners are all collinear is
 * invisible, with a note too.  Exported to POV-Ray as a mesh of the same
 * two triangles. */
#include <math.h>

#include "whitted/mesh.h"
#include "whitted/plugin.h"
#include "whitted/pov.h"

WHITTED_PLUGIN_ABI_SYMBOL;

static const struct whitted_plugin_host *host;

struct quad {
	struct shape base;
	struct vec3 v[4];
	struct vec3 n[2];	/* unit normals of 1-2-3 and 1-3-4; zero when degenerate */
	bool planar;
};

/* The triangle a b c, from both sides (the host's Moller-Trumbore). */
static bool quad_triangle(const struct ray *r, struct vec3 a, struct vec3 b, struct vec3 c,
			  double t_min, double t_max, double *t)
{
	return host->ray_triangle(r, a, vec3_sub(b, a), vec3_sub(c, a), t_min, t_max, t);
}

static bool quad_intersect(const struct shape *s, const struct ray *r, double t_min,
			   double *t_max)
{
	const struct quad *q = (const struct quad *)s;
	double t;
	bool hit = false;

	if (quad_triangle(r, q->v[0], q->v[1], q->v[2], t_min, *t_max, &t)) {
		*t_max = t;
		hit = true;
	}
	if (quad_triangle(r, q->v[0], q->v[2], q->v[3], t_min, *t_max, &t)) {
		*t_max = t;
		hit = true;
	}
	return hit;
}

/* The normal of the triangle p lies in: the one whose plane it is nearer
 * (the same normal for a planar quad). */
static struct vec3 quad_normal(const struct shape *s, struct vec3 p)
{
	const struct quad *q = (const struct quad *)s;
	double d0, d1;

	if (q->planar)
		return vec3_dot(q->n[0], q->n[0]) > 0.0 ? q->n[0] : q->n[1];
	d0 = fabs(vec3_dot(vec3_sub(p, q->v[0]), q->n[0]));
	d1 = fabs(vec3_dot(vec3_sub(p, q->v[0]), q->n[1]));
	if (vec3_dot(q->n[0], q->n[0]) == 0.0)
		return q->n[1];
	if (vec3_dot(q->n[1], q->n[1]) == 0.0)
		return q->n[0];
	return d0 <= d1 ? q->n[0] : q->n[1];
}

static bool quad_bounds(const struct shape *s, struct aabb *out)
{
	const struct quad *q = (const struct quad *)s;

	out->min = vec3_min(vec3_min(q->v[0], q->v[1]), vec3_min(q->v[2], q->v[3]));
	out->max = vec3_max(vec3_max(q->v[0], q->v[1]), vec3_max(q->v[2], q->v[3]));
	return true;
}

static bool quad_is_degenerate(const struct quad *q)
{
	return vec3_dot(q->n[0], q->n[0]) == 0.0 && vec3_dot(q->n[1], q->n[1]) == 0.0;
}

static const char *quad_degenerate(const struct shape *s)
{
	const struct quad *q = (const struct quad *)s;

	if (quad_is_degenerate(q))
		return "is degenerate (its corners are collinear) and will not be visible";
	if (!q->planar)
		return "is not planar (corner 4 is off the plane of corners 1, 2 and 3): it is drawn as the triangles 1-2-3 and 1-3-4";
	return NULL;
}

static void quad_write_triangle(FILE *out, struct vec3 a, struct vec3 b, struct vec3 c)
{
	fputs("  triangle { ", out);
	host->pov_vector(out, a.x, a.y, a.z);
	fputs(", ", out);
	host->pov_vector(out, b.x, b.y, b.z);
	fputs(", ", out);
	host->pov_vector(out, c.x, c.y, c.z);
	fputs(" }\n", out);
}

/* A mesh of the two triangles (a degenerate one left out, as POV-Ray
 * would warn about it). */
static int quad_export_pov(const struct shape *s, FILE *out, const struct pov_options *opt)
{
	const struct quad *q = (const struct quad *)s;

	if (quad_is_degenerate(q)) {
		fputs("// a degenerate quad, invisible in whitted and POV-Ray alike\n", out);
		return ferror(out) ? -RT_E_IO : 0;
	}
	fputs("mesh {\n", out);
	if (vec3_dot(q->n[0], q->n[0]) > 0.0)
		quad_write_triangle(out, q->v[0], q->v[1], q->v[2]);
	if (vec3_dot(q->n[1], q->n[1]) > 0.0)
		quad_write_triangle(out, q->v[0], q->v[2], q->v[3]);
	fputs("  ", out);
	host->pov_texture(out, &s->mat, opt);
	fputs("\n}\n", out);
	return ferror(out) ? -RT_E_IO : 0;
}

static int quad_tessellate(const struct shape *s, const struct mesh_options *opt,
			   struct mesh *out)
{
	const struct quad *q = (const struct quad *)s;
	int k, rc;

	(void)opt;
	for (k = 0; k < 2; k++) {
		const struct vec3 p[3] = { q->v[0], q->v[k + 1], q->v[k + 2] };
		const struct vec3 n[3] = { q->n[k], q->n[k], q->n[k] };

		if (vec3_dot(q->n[k], q->n[k]) > 0.0 && (rc = host->mesh_triangle(out, p, n)) < 0)
			return rc;
	}
	return 0;
}

static void quad_destroy(struct shape *s)
{
	host->free(s);
}

static struct vec3 quad_unit_normal(struct vec3 a, struct vec3 b, struct vec3 c)
{
	struct vec3 n = vec3_normalize(vec3_cross(vec3_sub(b, a), vec3_sub(c, a)));

	return vec3_is_finite(n) ? n : vec3_make(0.0, 0.0, 0.0);
}

/* Planar when corner 4 is within a millionth of the quad's size of the
 * plane of 1-2-3 (the course's files are typed in by hand). */
static bool quad_planar(const struct quad *q)
{
	struct vec3 lo, hi;
	double size;
	int k;

	if (vec3_dot(q->n[0], q->n[0]) == 0.0 || vec3_dot(q->n[1], q->n[1]) == 0.0)
		return true;
	lo = hi = q->v[0];
	for (k = 1; k < 4; k++) {
		lo = vec3_min(lo, q->v[k]);
		hi = vec3_max(hi, q->v[k]);
	}
	size = vec3_length(vec3_sub(hi, lo));
	return fabs(vec3_dot(vec3_sub(q->v[3], q->v[0]), q->n[0])) <= 1e-6 * size;
}

static const struct shape_ops quad_ops;

static int quad_parse(struct parser *p, struct shape **out)
{
	struct quad *q;
	struct vec3 v[4];
	int rc, i, j;

	*out = NULL;
	for (i = 0; i < 4; i++)
		if ((rc = host->vec3(p, "quad corner", &v[i])) < 0)
			return rc;
	for (i = 0; i < 4; i++)
		for (j = i + 1; j < 4; j++)
			if (!vec3_is_finite(vec3_sub(v[i], v[j])))
				return host->fail(p, RT_E_RANGE, "quad corners are too far apart");
	q = (struct quad *)whitted_plugin_new_shape(host, p, &quad_ops, sizeof(*q), &rc);
	if (!q)
		return rc;
	for (i = 0; i < 4; i++)
		q->v[i] = v[i];
	q->n[0] = quad_unit_normal(v[0], v[1], v[2]);
	q->n[1] = quad_unit_normal(v[0], v[2], v[3]);
	q->planar = quad_planar(q);
	*out = &q->base;
	return 0;
}

static const struct shape_ops quad_ops = {
	.keyword = "quad",
	.parse = quad_parse,
	.intersect = quad_intersect,
	.normal = quad_normal,
	.export_pov = quad_export_pov,
	.destroy = quad_destroy,
	.bounds = quad_bounds,
	.degenerate = quad_degenerate,
	.tessellate = quad_tessellate,
};

static const struct shape_ops *const quad_shapes[] = { &quad_ops, NULL };

int whitted_plugin_init(const struct whitted_plugin_host *h)
{
	static const struct whitted_plugin plugin = { "quad", "1.0", quad_shapes };

	return whitted_plugin_start(h, &host, &plugin);
}
