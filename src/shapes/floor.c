/* The implicit checkerboard floor: the square |x|, |y| < width / 2 on the
 * plane z = 0 (half-open: [-w/2, w/2)), tile (i, j) = (floor((x + w/2) /
 * tile), floor((y + w/2) / tile)) white when i + j is even, black otherwise. */
#include <math.h>

#include "alloc.h"
#include "diag.h"
#include "pov.h"
#include "shape.h"

struct floor {
	struct shape base;
	double half, tile;
};

static bool floor_intersect(const struct shape *s, const struct ray *r,
			    double t_min, double *t_max)
{
	const struct floor *fl = (const struct floor *)s;
	double t, x, y;

	if (r->dir.z == 0.0)
		return false;
	t = -r->origin.z / r->dir.z;
	if (!(t > t_min && t < *t_max))
		return false;
	x = r->origin.x + t * r->dir.x;
	y = r->origin.y + t * r->dir.y;
	if (x < -fl->half || x >= fl->half || y < -fl->half || y >= fl->half)
		return false;
	*t_max = t;
	return true;
}

static struct vec3 floor_normal(const struct shape *s, struct vec3 p)
{
	(void)s;
	(void)p;
	return vec3_make(0.0, 0.0, 1.0);
}

static struct color floor_color_at(const struct shape *s, struct vec3 p)
{
	const struct floor *fl = (const struct floor *)s;
	double i = floor((p.x + fl->half) / fl->tile);
	double j = floor((p.y + fl->half) / fl->tile);
	double parity = fmod(fabs(i + j), 2.0);

	return parity == 0.0 ? color_make(1.0, 1.0, 1.0) : color_make(0.0, 0.0, 0.0);
}

static bool floor_bounds(const struct shape *s, struct aabb *out)
{
	const struct floor *fl = (const struct floor *)s;

	out->min = vec3_make(-fl->half, -fl->half, 0.0);
	out->max = vec3_make(fl->half, fl->half, 0.0);
	return true;
}

/* POV-Ray's checker is colour 1 where floor(x) + floor(y) + floor(z) is even,
 * in pattern space.  Scaling by the tile and translating by -w/2 in x and y
 * gives our tile indices; translating z by -tile/2 puts the plane z = 0 at
 * pattern z = 0.5, mid-tile, where floor(z) = 0 keeps the parity. */
static int floor_export_pov(const struct shape *s, FILE *out, const struct pov_options *opt)
{
	const struct floor *fl = (const struct floor *)s;
	/* The tile colour varies, so the floor cannot use the exact mode's
	 * tinted light group: a plain texture is exact here, since the white
	 * tile's highlight is white and the black tile has none. */
	const struct pov_options plain = { RT_POV_FINISH_PLAIN };
	struct material black = s->mat;
	double h = fl->half;

	(void)opt;

	black.color = color_make(0.0, 0.0, 0.0);
	black.ks = 0.0;
	fputs("polygon { 5, ", out);
	pov_write_vector(out, -h, -h, 0.0);
	fputs(", ", out);
	pov_write_vector(out, h, -h, 0.0);
	fputs(", ", out);
	pov_write_vector(out, h, h, 0.0);
	fputs(", ", out);
	pov_write_vector(out, -h, h, 0.0);
	fputs(", ", out);
	pov_write_vector(out, -h, -h, 0.0);
	fputs("\n  texture { checker\n    ", out);
	pov_write_texture(out, &s->mat, &plain);
	fputs("\n    ", out);
	pov_write_texture(out, &black, &plain);
	fputs("\n    scale ", out);
	pov_write_number(out, fl->tile);
	fputs(" translate ", out);
	pov_write_vector(out, -h, -h, -0.5 * fl->tile);
	fputs("\n  }\n}\n", out);
	return ferror(out) ? -RT_E_IO : 0;
}

static void floor_destroy(struct shape *s)
{
	rt_free(s);
}

/* Not in the registry: the floor is implicit, never read from a file. */
static void floor_geometry(const struct shape *s, struct shape_geometry *out)
{
	const struct floor *fl = (const struct floor *)s;

	out->kind = RT_SHAPE_FLOOR;
	out->u.floor.width = 2.0 * fl->half;
	out->u.floor.tile = fl->tile;
}

const struct shape_ops floor_ops = {
	.keyword = "floor",
	.intersect = floor_intersect,
	.normal = floor_normal,
	.export_pov = floor_export_pov,
	.destroy = floor_destroy,
	.color_at = floor_color_at,
	.bounds = floor_bounds,
	.geometry = floor_geometry,
};

struct shape *floor_create(double width, double tile)
{
	struct floor *fl = rt_malloc(sizeof(*fl));

	if (!fl)
		return NULL;
	fl->base.ops = &floor_ops;
	fl->base.mat.color = color_make(1.0, 1.0, 1.0);
	fl->base.mat.ka = 0.4;
	fl->base.mat.kd = 0.2;
	fl->base.mat.ks = 0.2;
	fl->base.mat.kr = 0.2;
	fl->base.mat.shininess = 1.0;
	fl->half = 0.5 * width;
	fl->tile = tile;
	return &fl->base;
}
