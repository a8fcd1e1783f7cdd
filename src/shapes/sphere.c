/* The sphere: |P - centre| = radius. */
#include <math.h>

#include "whitted/diag.h"
#include "whitted/mesh.h"
#include "whitted/parser.h"
#include "whitted/pov.h"
#include "shapes/shapes.h"
#include "whitted/shape.h"
#include "shapes/solve.h"
#include "shapes/solve_packet.h"

struct sphere {
	struct shape base;
	struct vec3 centre;
	double radius, radius_sq, inv_radius;
};

static bool sphere_intersect(const struct shape *s, const struct ray *r,
			     double t_min, double *t_max)
{
	const struct sphere *sp = (const struct sphere *)s;
	double t;

	if (!solve_ray_sphere(r, sp->centre, sp->radius_sq, t_min, *t_max, &t))
		return false;
	*t_max = t;
	return true;
}

static uint32_t sphere_intersect_packet(const struct shape *s, const struct ray_packet *p,
				       uint32_t active, const double *t_min, double *t_max)
{
	const struct sphere *sp = (const struct sphere *)s;

	return solve_packet_sphere(p, active, sp->centre, sp->radius_sq, t_min, t_max);
}

static struct vec3 sphere_normal(const struct shape *s, struct vec3 p)
{
	const struct sphere *sp = (const struct sphere *)s;

	return vec3_scale(vec3_sub(p, sp->centre), sp->inv_radius);
}

static void sphere_normal_packet(const struct shape *s, const double *const p[3],
				 uint32_t active, double *const n[3])
{
	const struct sphere *sp = (const struct sphere *)s;

	solve_packet_sphere_normal(p, active, sp->centre, sp->inv_radius, n);
}

static bool sphere_bounds(const struct shape *s, struct aabb *out)
{
	const struct sphere *sp = (const struct sphere *)s;
	struct vec3 r = vec3_make(sp->radius, sp->radius, sp->radius);

	out->min = vec3_sub(sp->centre, r);
	out->max = vec3_add(sp->centre, r);
	return true;
}

static int sphere_export_pov(const struct shape *s, FILE *out, const struct pov_options *opt)
{
	const struct sphere *sp = (const struct sphere *)s;

	shape_pov_begin(out, "sphere { ", &sp->centre, 1);
	fputs(", ", out);
	pov_write_number(out, sp->radius);
	return shape_pov_finish(s, out, opt);
}

static int sphere_parse(struct parser *p, struct shape **out);

/* The unit direction at longitude i / slices, latitude j / stacks from the
 * +z pole. */
static struct vec3 sphere_direction(int i, int j, int slices, int stacks)
{
	const double pi = 3.14159265358979323846;
	double lon = 2.0 * pi * i / slices, lat = pi * j / stacks;

	return vec3_make(sin(lat) * cos(lon), sin(lat) * sin(lon), cos(lat));
}

/* A UV grid: opt->segments slices around the pole axis (z) and half as
 * many stacks from pole to pole; the normals are the exact ones. */
static int sphere_tessellate(const struct shape *s, const struct mesh_options *opt,
			     struct mesh *out)
{
	const struct sphere *sp = (const struct sphere *)s;
	int slices = opt->segments, stacks = opt->segments / 2, i, j, k, rc;

	for (j = 0; j < stacks; j++) {
		for (i = 0; i < slices; i++) {
			struct vec3 n[4] = {
				sphere_direction(i, j, slices, stacks),
				sphere_direction(i, j + 1, slices, stacks),
				sphere_direction(i + 1, j + 1, slices, stacks),
				sphere_direction(i + 1, j, slices, stacks),
			};
			struct vec3 p[4], tri_p[3], tri_n[3];

			for (k = 0; k < 4; k++)
				p[k] = vec3_add_scaled(sp->centre, n[k], sp->radius);
			/* The quads at the poles have two equal corners: one
			 * triangle each. */
			if (j < stacks - 1) {
				tri_p[0] = p[0], tri_p[1] = p[1], tri_p[2] = p[2];
				tri_n[0] = n[0], tri_n[1] = n[1], tri_n[2] = n[2];
				if ((rc = mesh_add_triangle(out, tri_p, tri_n)) < 0)
					return rc;
			}
			if (j > 0) {
				tri_p[0] = p[0], tri_p[1] = p[2], tri_p[2] = p[3];
				tri_n[0] = n[0], tri_n[1] = n[2], tri_n[2] = n[3];
				if ((rc = mesh_add_triangle(out, tri_p, tri_n)) < 0)
					return rc;
			}
		}
	}
	return 0;
}

const struct shape_ops sphere_ops = {
	.keyword = "sphere",
	.parse = sphere_parse,
	.intersect = sphere_intersect,
	.intersect_packet = sphere_intersect_packet,
	.normal = sphere_normal,
	.normal_packet = sphere_normal_packet,
	.export_pov = sphere_export_pov,
	.destroy = shape_destroy_block,
	.bounds = sphere_bounds,
	.tessellate = sphere_tessellate,
	.closed = shape_closed_always,
};

struct shape *sphere_create(struct vec3 centre, double radius, const struct material *m)
{
	struct sphere *sp = shape_alloc(sizeof(*sp), &sphere_ops, m);

	if (!sp)
		return NULL;
	sp->centre = centre;
	sp->radius = radius;
	sp->radius_sq = radius * radius;
	sp->inv_radius = 1.0 / radius;
	return &sp->base;
}

static int sphere_parse(struct parser *p, struct shape **out)
{
	return shape_parse_point_size(p, "sphere centre", "sphere radius", sphere_create, out);
}
