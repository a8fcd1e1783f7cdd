/* The triangle, hit from both sides (Moller-Trumbore). */
#include "whitted/diag.h"
#include "whitted/mesh.h"
#include "whitted/parser.h"
#include "whitted/pov.h"
#include "whitted/scene.h"
#include "shapes/shapes.h"
#include "whitted/shape.h"
#include "shapes/solve.h"
#include "shapes/solve_packet.h"

/* The normal is not stored: computing it at a hit costs little next to
 * finding the hit, and leaving it out keeps a triangle at 144 bytes (a
 * million of them are 24 MB less). */
struct triangle {
	struct shape base;
	struct vec3 v0, e1, e2;		/* e1 = v1 - v0, e2 = v2 - v0 */
};

/* The unit e1 x e2; zero when degenerate. */
static struct vec3 triangle_unit_normal(const struct triangle *tr)
{
	struct vec3 n = vec3_normalize(vec3_cross(tr->e1, tr->e2));

	return vec3_is_finite(n) ? n : vec3_make(0.0, 0.0, 0.0);
}

/* The corners v0, v1, v2 as given. */
static void triangle_vertices(const struct triangle *tr, struct vec3 v[3])
{
	v[0] = tr->v0;
	v[1] = vec3_add(tr->v0, tr->e1);
	v[2] = vec3_add(tr->v0, tr->e2);
}

static bool triangle_intersect(const struct shape *s, const struct ray *r,
			       double t_min, double *t_max)
{
	const struct triangle *tr = (const struct triangle *)s;
	double t;

	if (!solve_ray_triangle(r, tr->v0, tr->e1, tr->e2, t_min, *t_max, &t))
		return false;
	*t_max = t;
	return true;
}

static uint32_t triangle_intersect_packet(const struct shape *s, const struct ray_packet *p,
				       uint32_t active, const double *t_min, double *t_max)
{
	const struct triangle *tr = (const struct triangle *)s;

	return solve_packet_triangle(p, active, tr->v0, tr->e1, tr->e2, t_min, t_max);
}

static struct vec3 triangle_normal(const struct shape *s, struct vec3 p)
{
	(void)p;
	return triangle_unit_normal((const struct triangle *)s);
}

/* One normal for every point: worked out once, the same value each time. */
static void triangle_normal_packet(const struct shape *s, const double *const p[3],
				   uint32_t active, double *const n[3])
{
	(void)p;
	shape_normal_fill(active, triangle_unit_normal((const struct triangle *)s), n);
}

static bool triangle_bounds(const struct shape *s, struct aabb *out)
{
	struct vec3 v[3];

	triangle_vertices((const struct triangle *)s, v);
	out->min = vec3_min(v[0], vec3_min(v[1], v[2]));
	out->max = vec3_max(v[0], vec3_max(v[1], v[2]));
	return true;
}

static const char *triangle_degenerate(const struct shape *s)
{
	struct vec3 n = triangle_unit_normal((const struct triangle *)s);

	if (n.x == 0.0 && n.y == 0.0 && n.z == 0.0)
		return "is degenerate (its vertices are collinear) and will not be visible";
	return NULL;
}

static int triangle_export_pov(const struct shape *s, FILE *out, const struct pov_options *opt)
{
	struct vec3 v[3];

	if (triangle_degenerate(s)) {
		fputs("// a degenerate triangle, invisible in whitted and POV-Ray alike\n", out);
		return ferror(out) ? -RT_E_IO : 0;
	}
	triangle_vertices((const struct triangle *)s, v);
	shape_pov_begin(out, "triangle { ", v, 3);
	return shape_pov_finish(s, out, opt);
}

static int triangle_parse(struct parser *p, struct shape **out);

/* One triangle with its face normal; a degenerate one has no area to
 * draw. */
static int triangle_tessellate(const struct shape *s, const struct mesh_options *opt,
			       struct mesh *out)
{
	const struct triangle *tr = (const struct triangle *)s;
	struct vec3 n = triangle_unit_normal(tr);
	const struct vec3 normals[3] = { n, n, n };
	struct vec3 p[3];

	(void)opt;
	if (triangle_degenerate(s))
		return 0;
	triangle_vertices(tr, p);
	return mesh_add_triangle(out, p, normals);
}

const struct shape_ops triangle_ops = {
	.keyword = "triangle",
	.dialects = RT_DIALECT_CLASSIC_FAMILY,
	.parse = triangle_parse,
	.intersect = triangle_intersect,
	.intersect_packet = triangle_intersect_packet,
	.normal = triangle_normal,
	.normal_packet = triangle_normal_packet,
	.export_pov = triangle_export_pov,
	.destroy = shape_destroy_block,
	.bounds = triangle_bounds,
	.degenerate = triangle_degenerate,
	.tessellate = triangle_tessellate,
};

struct shape *triangle_create(struct vec3 a, struct vec3 b, struct vec3 c,
			      const struct material *m)
{
	struct triangle *tr = shape_alloc(sizeof(*tr), &triangle_ops, m);

	if (!tr)
		return NULL;
	tr->v0 = a;
	tr->e1 = vec3_sub(b, a);
	tr->e2 = vec3_sub(c, a);
	return &tr->base;
}

static int triangle_parse(struct parser *p, struct shape **out)
{
	struct vec3 v[3];
	struct material m;
	int rc, i;

	*out = NULL;
	for (i = 0; i < 3; i++)
		if ((rc = parser_vec3(p, "triangle vertex", &v[i])) < 0)
			return rc;
	for (i = 0; i < 3; i++)
		if (!vec3_is_finite(vec3_sub(v[i], v[(i + 1) % 3])))
			return parser_fail(p, RT_E_RANGE, "triangle vertices are too far apart");
	if ((rc = parser_material(p, &m)) < 0)
		return rc;
	*out = triangle_create(v[0], v[1], v[2], &m);
	return *out ? 0 : parser_fail(p, RT_E_NOMEM, "out of memory");
}
