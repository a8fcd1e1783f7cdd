/* The implicit checkerboard floor: the square |x|, |y| < width / 2 on the
 * plane z = 0 (half-open: [-w/2, w/2)), cell (i, j) = (floor((x + w/2) /
 * cell), floor((y + w/2) / cell)) white when i + j is even, black otherwise;
 * or nearfar's infinite one, the whole plane z = 0 with cell (floor(x /
 * cell), floor(y / cell)), white when the sum is even: its own table, so
 * that the finite floor's code and images stay as they were.  With
 * textures (--floor-texture), a white cell's colour is the texel of the
 * white image, and a black cell's that of the black image, under the
 * point: one image over each cell, nearest texel (floor_texel). */
#define _XOPEN_SOURCE 700
#include <assert.h>
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/alloc.h"
#include "base/hash.h"
#include "base/platform.h"
#include "whitted/diag.h"
#include "whitted/image.h"
#include "shapes/floor_impl.h"
#include "shapes/shapes.h"
#include "shapes/solve_packet.h"
#include "whitted/shape.h"

extern const struct shape_ops floor_ops;
static const struct shape_ops floor_infinite_ops;

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

static uint32_t floor_intersect_packet(const struct shape *s, const struct ray_packet *p,
				       uint32_t active, const double *t_min, double *t_max)
{
	return solve_packet_floor(p, active, 1, ((const struct floor *)s)->half, t_min, t_max);
}

static uint32_t floor_infinite_intersect_packet(const struct shape *s,
						const struct ray_packet *p, uint32_t active,
						const double *t_min, double *t_max)
{
	(void)s;
	return solve_packet_floor(p, active, 0, 0.0, t_min, t_max);
}

static struct vec3 floor_normal(const struct shape *s, struct vec3 p)
{
	(void)s;
	(void)p;
	return vec3_make(0.0, 0.0, 1.0);
}

/* White when the cell indices' sum i + j is even, black otherwise (i and
 * j are whole numbers, floor's). */
static struct color floor_cell_color(double i, double j)
{
	double sum = i + j, white;

	/* The colour from the test's value, not from a branch on it: the
	 * test waits on two divisions, and a branch that cells make
	 * unpredictable (near the horizon they change every few pixels)
	 * would throw away the shading done meanwhile.  A sum of whole
	 * numbers is whole, so below 2^31 its low bit is the parity.  Beyond,
	 * i + j is even when half of it is a whole number: the same test as
	 * fmod(|i + j|, 2) == 0 for every finite value (and false for inf and
	 * NaN, as there), without the library call. */
	if (fabs(sum) < 2147483648.0) {
		white = (double)(~(int)sum & 1);
	} else {
		double half = 0.5 * fabs(sum);
		white = (double)((half == floor(half)) & (half != INFINITY));
	}
	return color_make(white, white, white);
}

/* The texel over the point (u, v) of a cell, both in [0, 1) from the
 * cell's corner of least x and y: the image covers the cell upright as the
 * default camera sees it, its top row along the cell's far (+y) edge and
 * its left column along the -x edge, so texel (floor(u W), H - 1 -
 * floor(v H)), clamped into the image against rounding.  8-bit values are
 * taken linearly (v / 255), like the scene file's colours. */
static struct color floor_texel(const struct image *t, double u, double v)
{
	int col = (int)(u * t->width), row = t->height - 1 - (int)(v * t->height);
	const uint8_t *px;

	col = col < 0 ? 0 : col >= t->width ? t->width - 1 : col;
	row = row < 0 ? 0 : row >= t->height ? t->height - 1 : row;
	px = t->pixels + ((size_t)row * (size_t)t->width + (size_t)col) * 3;
	return color_make(px[0] / 255.0, px[1] / 255.0, px[2] / 255.0);
}

/* The colour of cell (i, j) at the point whose cell coordinates are (cx,
 * cy) = (i + u, j + v). */
static struct color floor_cell_color_at(const struct floor *fl, double cx, double cy)
{
	double i = floor(cx), j = floor(cy);
	struct color c = floor_cell_color(i, j);
	const struct image *t = &fl->tex[c.r > 0.5 ? 0 : 1];

	return t->pixels ? floor_texel(t, cx - i, cy - j) : c;
}

/* With textures, the highlight keeps the cell's own colour (white or
 * black): the handout's texel scales the ambient and diffuse terms only. */
static bool floor_specular_color_at(const struct shape *s, struct vec3 p, struct color *out)
{
	const struct floor *fl = (const struct floor *)s;

	if (!fl->tex_path[0] && !fl->tex_path[1])
		return false;
	if (s->ops == &floor_ops)
		*out = floor_cell_color(floor((p.x + fl->half) / fl->cell),
					floor((p.y + fl->half) / fl->cell));
	else
		*out = floor_cell_color(floor(p.x / fl->cell), floor(p.y / fl->cell));
	return true;
}

static struct color floor_color_at(const struct shape *s, struct vec3 p)
{
	const struct floor *fl = (const struct floor *)s;
	double i, j;

	if (fl->tex_path[0] || fl->tex_path[1])
		return floor_cell_color_at(fl, (p.x + fl->half) / fl->cell, (p.y + fl->half) / fl->cell);
	i = floor((p.x + fl->half) / fl->cell);
	j = floor((p.y + fl->half) / fl->cell);
	return floor_cell_color(i, j);
}

static void floor_normal_packet(const struct shape *s, const double *const p[3],
				uint32_t active, double *const n[3])
{
	(void)s;
	(void)p;
	shape_normal_fill(active, vec3_make(0.0, 0.0, 1.0), n);
}

/* The plain checkerboard a vector at a time (solve_packet_floor_cells);
 * a textured one point by point. */
static void floor_cells_packet(const struct shape *s, const double *const p[3],
			       uint32_t active, int shifted, double *const c[3])
{
	const struct floor *fl = (const struct floor *)s;

	if (!fl->tex_path[0] && !fl->tex_path[1]) {
		solve_packet_floor_cells(p, active, shifted, fl->half, fl->cell, c);
		return;
	}
	shape_color_lanes(s, p, active, c);
}

static void floor_color_packet(const struct shape *s, const double *const p[3],
			       uint32_t active, double *const c[3])
{
	floor_cells_packet(s, p, active, 1, c);
}

static bool floor_bounds(const struct shape *s, struct aabb *out)
{
	const struct floor *fl = (const struct floor *)s;

	out->min = vec3_make(-fl->half, -fl->half, 0.0);
	out->max = vec3_make(fl->half, fl->half, 0.0);
	return true;
}

static void floor_destroy(struct shape *s)
{
	struct floor *fl = (struct floor *)s;
	int k;

	for (k = 0; k < 2; k++) {
		image_free(&fl->tex[k]);
		rt_free(fl->tex_path[k]);
	}
	rt_free(s);
}

/* Not in the registry: the floor is implicit, never read from a file. */
const struct shape_ops floor_ops = {
	.keyword = "floor",
	.intersect = floor_intersect,
	.intersect_packet = floor_intersect_packet,
	.normal = floor_normal,
	.normal_packet = floor_normal_packet,
	.export_pov = floor_export_pov,
	.destroy = floor_destroy,
	.color_at = floor_color_at,
	.color_packet = floor_color_packet,
	.specular_color_at = floor_specular_color_at,
	.bounds = floor_bounds,
	.tessellate = floor_tessellate,
};

/* The infinite floor: every point of z = 0. */
static bool floor_infinite_intersect(const struct shape *s, const struct ray *r,
				     double t_min, double *t_max)
{
	double t;

	(void)s;
	if (r->dir.z == 0.0)
		return false;
	t = -r->origin.z / r->dir.z;
	if (!(t > t_min && t < *t_max))
		return false;
	*t_max = t;
	return true;
}

static struct color floor_infinite_color_at(const struct shape *s, struct vec3 p)
{
	const struct floor *fl = (const struct floor *)s;

	if (fl->tex_path[0] || fl->tex_path[1])
		return floor_cell_color_at(fl, p.x / fl->cell, p.y / fl->cell);
	return floor_cell_color(floor(p.x / fl->cell), floor(p.y / fl->cell));
}

static void floor_infinite_color_packet(const struct shape *s, const double *const p[3],
					uint32_t active, double *const c[3])
{
	floor_cells_packet(s, p, active, 0, c);
}

/* Unbounded in x and y, and flat: z = 0 is the one axis it is bounded
 * along. */
static bool floor_infinite_bounds(const struct shape *s, struct aabb *out)
{
	(void)s;
	out->min.z = 0.0;
	out->max.z = 0.0;
	return false;
}

static const struct shape_ops floor_infinite_ops = {
	.keyword = "floor",
	.intersect = floor_infinite_intersect,
	.intersect_packet = floor_infinite_intersect_packet,
	.normal = floor_normal,
	.normal_packet = floor_normal_packet,
	.export_pov = floor_infinite_export_pov,
	.destroy = floor_destroy,
	.color_at = floor_infinite_color_at,
	.color_packet = floor_infinite_color_packet,
	.specular_color_at = floor_specular_color_at,
	.bounds = floor_infinite_bounds,
	.tessellate = floor_infinite_tessellate,
};

struct shape *floor_create_view(double width, double cell, const struct material *m)
{
	struct floor *fl;

	assert(width > 0.0 && cell > 0.0);
	fl = shape_alloc(sizeof(*fl), width == INFINITY ? &floor_infinite_ops : &floor_ops, m);
	if (!fl)
		return NULL;
	fl->base.mat.color = color_make(1.0, 1.0, 1.0);
	fl->half = 0.5 * width;
	fl->cell = cell;
	memset(fl->tex, 0, sizeof(fl->tex));
	fl->tex_path[0] = fl->tex_path[1] = NULL;
	return &fl->base;
}

uint64_t floor_texture_hash(const struct shape *s)
{
	const struct floor *fl = (const struct floor *)s;
	uint64_t h = RT_HASH_INIT;
	int k;

	if (!fl->tex_path[0] && !fl->tex_path[1])
		return 0;
	for (k = 0; k < 2; k++) {
		const struct image *t = &fl->tex[k];
		int size[2] = { t->width, t->height };

		h = hash_bytes(h, size, sizeof(size));
		if (t->pixels)
			h = hash_bytes(h, t->pixels, (size_t)t->width * (size_t)t->height * 3);
	}
	return h;
}

const struct image *floor_texture(const struct shape *s, int k)
{
	const struct floor *fl = (const struct floor *)s;

	assert(s->ops == &floor_ops || s->ops == &floor_infinite_ops);
	return fl->tex_path[k] ? &fl->tex[k] : NULL;
}

int floor_set_textures(struct shape *s, const char *white, const char *black, struct diag *d)
{
	struct floor *fl = (struct floor *)s;
	const char *paths[2] = { white, black };
	char *abs;
	int k, rc;

	assert(s->ops == &floor_ops || s->ops == &floor_infinite_ops);
	for (k = 0; k < 2; k++) {
		size_t len;

		if (!paths[k])
			continue;
		if ((rc = image_read(paths[k], &fl->tex[k], &fl->tex_format[k], d)) < 0)
			return rc;
		/* POV-Ray reads the file again, maybe from another directory. */
		abs = rt_real_path(paths[k]);
		if (!abs)
			return diag_set(d, RT_E_IO, paths[k], 0, 0, "cannot resolve: %s",
					strerror(errno));
		len = strlen(abs) + 1;
		fl->tex_path[k] = rt_malloc(len);
		if (fl->tex_path[k])
			memcpy(fl->tex_path[k], abs, len);
		free(abs);
		if (!fl->tex_path[k])
			return diag_fail(d, RT_E_NOMEM, "out of memory");
	}
	return 0;
}

const struct material floor_classic_material = { { 1.0, 1.0, 1.0 }, 0.4, 0.2, 0.2, 0.2, 1.0, 0.0, 1.0 };

struct shape *floor_create(double width, double cell)
{
	return floor_create_view(width, cell, &floor_classic_material);
}
