/* The scene model: ownership of shapes and lights, the checked setters
 * and the accessors.  It knows no file format: loading is src/scenefile's. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "accel/accel.h"
#include "base/alloc.h"
#include "base/simd.h"
#include "base/text.h"
#include "scene/scene_impl.h"
#include "shapes/shapes.h"
#include "whitted/camera.h"

struct scene *scene_create(const char *name)
{
	struct scene *s = rt_calloc(1, sizeof(*s));

	if (!s)
		return NULL;
	s->name = rt_strdup(name ? name : "");
	if (!s->name) {
		rt_free(s);
		return NULL;
	}
	s->recursion = 1;
	s->image_size = 1;
	scene_view_default(&s->view);
	return s;
}

void scene_destroy(struct scene *s)
{
	size_t i;

	if (!s)
		return;
	accel_destroy(s->accel);
	for (i = 0; i < s->n_shapes; i++)
		shape_destroy(s->shapes[i]);
	rt_free(s->shapes);
	rt_free(s->shape_lines);
	rt_free(s->lights);
	rt_free(s->name);
	rt_free(s);
}

/* Grows an array geometrically, so that a file's counts never make us
 * allocate for objects that are not there. */
static int scene_grow(void **array, size_t *cap, size_t need, size_t elem)
{
	size_t new_cap;
	void *p;

	if (need <= *cap)
		return 0;
	new_cap = *cap ? *cap * 2 : 16;
	while (new_cap < need)
		new_cap *= 2;
	p = rt_reallocarray(*array, new_cap, elem);
	if (!p)
		return -RT_E_NOMEM;
	*array = p;
	*cap = new_cap;
	return 0;
}

int scene_add_shape(struct scene *s, struct shape *sh, struct diag *d)
{
	if (s->n_shapes >= (size_t)RT_MAX_OBJECTS + 1) {
		shape_destroy(sh);
		return diag_set(d, RT_E_RANGE, s->name, 0, 0, "more than %ld objects", RT_MAX_OBJECTS);
	}
	if (scene_grow((void **)&s->shapes, &s->cap_shapes, s->n_shapes + 1, sizeof(*s->shapes)) < 0) {
		shape_destroy(sh);
		return diag_set(d, RT_E_NOMEM, s->name, 0, 0, "out of memory");
	}
	if (s->shape_lines && s->cap_lines < s->cap_shapes) {
		/* Grown with the shapes (as often), their lines unknown until set. */
		int *lines = rt_reallocarray(s->shape_lines, s->cap_shapes, sizeof(*lines));
		if (!lines) {
			shape_destroy(sh);
			return diag_set(d, RT_E_NOMEM, s->name, 0, 0, "out of memory");
		}
		memset(lines + s->cap_lines, 0, (s->cap_shapes - s->cap_lines) * sizeof(*lines));
		s->shape_lines = lines;
		s->cap_lines = s->cap_shapes;
	}
	s->shapes[s->n_shapes++] = sh;
	return 0;
}

int scene_set_shape_line(struct scene *s, size_t i, int line, struct diag *d)
{
	if (i >= s->n_shapes)
		return diag_fail(d, RT_E_INVALID, "no object %zu", i);
	if (!s->shape_lines) {
		if (!(s->shape_lines = rt_calloc(s->cap_shapes, sizeof(int))))
			return diag_set(d, RT_E_NOMEM, s->name, 0, 0, "out of memory");
		s->cap_lines = s->cap_shapes;
	}
	s->shape_lines[i] = line;
	return 0;
}

int scene_shape_line(const struct scene *s, size_t i)
{
	return s->shape_lines && i < s->n_shapes ? s->shape_lines[i] : 0;
}

static int scene_push_light(struct scene *s, const struct light *l, struct diag *d)
{
	if (s->n_lights >= (size_t)RT_MAX_LIGHTS)
		return diag_set(d, RT_E_RANGE, s->name, 0, 0, "more than %ld lights", RT_MAX_LIGHTS);
	if (scene_grow((void **)&s->lights, &s->cap_lights, s->n_lights + 1, sizeof(*s->lights)) < 0)
		return diag_set(d, RT_E_NOMEM, s->name, 0, 0, "out of memory");
	s->lights[s->n_lights++] = *l;
	if (l->spot || l->falloff > 0.0)
		s->n_special_lights++;
	return 0;
}

int scene_add_light(struct scene *s, struct vec3 pos, struct color color, struct diag *d)
{
	struct light l;

	memset(&l, 0, sizeof(l));
	l.pos = pos;
	l.color = color;
	return scene_push_light(s, &l, d);
}

static bool scene_color_ok(struct color c)
{
	return c.r >= 0.0 && c.g >= 0.0 && c.b >= 0.0 &&
	       isfinite(c.r) && isfinite(c.g) && isfinite(c.b);
}

/* cos of an angle in degrees, exact at the right angles, where the sign
 * decides whether the points at 90 degrees from the axis are in the cone
 * (cos(pi / 2) is 6e-17 in doubles) and 180 lights every point. */
static double scene_cos_deg(double deg)
{
	const double pi = 3.14159265358979323846;

	if (deg == 90.0)
		return 0.0;
	if (deg == 180.0)
		return -1.0;
	return cos(deg * pi / 180.0);
}

int scene_add_light_full(struct scene *s, const struct light *l, struct diag *d)
{
	struct light c = *l;
	double len;

	if (!vec3_is_finite(c.pos))
		return diag_set(d, RT_E_RANGE, s->name, 0, 0, "the light's position is not finite");
	if (!scene_color_ok(c.color))
		return diag_set(d, RT_E_RANGE, s->name, 0, 0,
				"light colours must be finite and >= 0, found %g %g %g",
				c.color.r, c.color.g, c.color.b);
	if (!(c.falloff >= 0.0 && isfinite(c.falloff)))
		return diag_set(d, RT_E_RANGE, s->name, 0, 0,
				"a light's falloff must be finite and >= 0, found %g", c.falloff);
	if (!c.spot) {
		c.axis = vec3_make(0.0, 0.0, 0.0);
		c.cutoff_deg = 0.0;
		c.cos_cutoff = 0.0;
		return scene_push_light(s, &c, d);
	}
	len = vec3_length(c.axis);
	if (!vec3_is_finite(c.axis) || !isfinite(len))
		return diag_set(d, RT_E_RANGE, s->name, 0, 0, "the spotlight's axis is not finite");
	if (!(len > 0.0))
		return diag_set(d, RT_E_RANGE, s->name, 0, 0, "the spotlight's axis is zero");
	if (!(c.cutoff_deg > 0.0 && c.cutoff_deg <= 180.0))
		return diag_set(d, RT_E_RANGE, s->name, 0, 0,
				"a spotlight's cutoff must be in (0, 180] degrees, found %g",
				c.cutoff_deg);
	c.axis = vec3_scale(c.axis, 1.0 / len);
	c.cos_cutoff = scene_cos_deg(c.cutoff_deg);
	return scene_push_light(s, &c, d);
}

int scene_add_floor(struct scene *s, double width, double tile, struct diag *d)
{
	struct shape *floor;

	if (!(width > 0.0) || !(tile > 0.0) || !isfinite(width) || !isfinite(tile))
		return diag_fail(d, RT_E_INVALID,
				"floor width and tile size must be finite and > 0");
	floor = floor_create(width, tile);
	if (!floor)
		return diag_set(d, RT_E_NOMEM, s->name, 0, 0, "out of memory");
	return scene_add_shape(s, floor, d);
}

void scene_view_default(struct scene_view *v)
{
	memset(v, 0, sizeof(*v));
	v->dialect = RT_DIALECT_CLASSIC;
	v->fov_deg = RT_CAMERA_FOV;
	v->floor_width = RT_FLOOR_WIDTH;
	v->floor_cell = RT_FLOOR_TILE;
	v->floor_mat = floor_classic_material;
}

void scene_set_view(struct scene *s, const struct scene_view *v)
{
	s->view = *v;
}

const struct scene_view *scene_view_of(const struct scene *s)
{
	return &s->view;
}

int scene_add_view_floor(struct scene *s, struct diag *d)
{
	const struct scene_view *v = &s->view;
	const struct material *m = &v->floor_mat;
	struct shape *floor;
	int rc;

	if (!(v->floor_width > 0.0) || !(v->floor_cell > 0.0) || !isfinite(v->floor_cell) ||
	    (!isfinite(v->floor_width) && v->floor_width != INFINITY))
		return diag_set(d, RT_E_RANGE, s->name, 0, 0,
				"the floor's width must be > 0 and its cells finite and > 0, "
				"found %g and %g", v->floor_width, v->floor_cell);
	if (!(m->ka >= 0.0 && m->kd >= 0.0 && m->ks >= 0.0 && m->kr >= 0.0 &&
	      m->shininess >= 0.0) ||
	    !isfinite(m->ka + m->kd + m->ks + m->kr + m->shininess))
		return diag_set(d, RT_E_RANGE, s->name, 0, 0,
				"the floor's coefficients must be finite and >= 0");
	floor = floor_create_view(v->floor_width, v->floor_cell, m);
	if (!floor)
		return diag_set(d, RT_E_NOMEM, s->name, 0, 0, "out of memory");
	if ((v->floor_texture[0] || v->floor_texture[1]) &&
	    (rc = floor_set_textures(floor, v->floor_texture[0], v->floor_texture[1], d)) < 0) {
		shape_destroy(floor);
		return rc;
	}
	s->floor_texture_hash = floor_texture_hash(floor);
	if ((rc = scene_add_shape(s, floor, d)) < 0)
		return rc;
	s->floor = floor;
	return 0;
}

/* The dialects' names, one table (--dialect, the notes, the settings'
 * text, the messages). */
static const char *const scene_dialects[RT_DIALECT_COUNT] = {
	[RT_DIALECT_AUTO] = "auto",
	[RT_DIALECT_CLASSIC] = "classic",
	[RT_DIALECT_SPOT] = "spot",
	[RT_DIALECT_PYRAMID] = "pyramid",
	[RT_DIALECT_NEARFAR] = "nearfar",
};

const char *scene_dialect_name(enum scene_dialect d)
{
	return (unsigned)d < RT_DIALECT_COUNT ? scene_dialects[d] : NULL;
}

int scene_dialect_from_name(const char *name)
{
	int d;

	for (d = 0; d < RT_DIALECT_COUNT; d++)
		if (strcmp(name, scene_dialects[d]) == 0)
			return d;
	return -1;
}

const char *scene_dialect_names(char *buf, size_t size)
{
	return text_word_list(buf, size, "", scene_dialects, RT_DIALECT_COUNT);
}

/* The figures of the ray tree's bound (scene_impl.h). */
static void scene_tree_bound(struct scene *s)
{
	double lights = 0.0;
	size_t i;

	for (i = 0; i < s->n_lights; i++) {
		const struct color *c = &s->lights[i].color;
		lights += fmax(c->r, fmax(c->g, c->b));
	}
	s->glass = false;
	s->tree_emit = s->tree_gain = 0.0;
	for (i = 0; i < s->n_shapes; i++) {
		const struct material *m = &s->shapes[i]->mat;
		double gain = m->kt > 0.0 ? fmax(m->kr + m->kt, 1.0) : m->kr;

		s->glass |= m->kt > 0.0;
		s->tree_emit = fmax(s->tree_emit, m->ka + (m->kd + m->ks) * lights);
		s->tree_gain = fmax(s->tree_gain, gain);
	}
}

int scene_prepare(struct scene *s, int threads, struct diag *d)
{
	scene_tree_bound(s);
	accel_destroy(s->accel);
	s->accel = NULL;
	return accel_build(s->shapes, s->n_shapes, threads, &s->accel, d);
}

size_t scene_hierarchy_nodes(const struct scene *s)
{
	return s->accel ? accel_node_count(s->accel) : 0;
}

size_t scene_hierarchy_bytes(const struct scene *s)
{
	return s->accel ? accel_bytes(s->accel) : 0;
}

const char *scene_hierarchy_walk(const struct scene *s)
{
	return accel_walk_name(s->accel);
}

const char *scene_hierarchy_packets(const struct scene *s)
{
	return accel_packets_name(s->accel);
}

const char *scene_walk_cap_unknown(void)
{
	return rt_simd_request_unknown();
}

const char *scene_kernels_isa(void)
{
	return rt_simd_name(rt_simd_level());
}

int scene_set_recursion(struct scene *s, long recursion, struct diag *d)
{
	if (recursion < 1 || recursion > RT_MAX_RECURSION)
		return diag_set(d, RT_E_RANGE, s->name, 0, 0,
				"recursion level must be between 1 and %d, found %ld",
				RT_MAX_RECURSION, recursion);
	s->recursion = (int)recursion;
	return 0;
}

int scene_set_image_size(struct scene *s, long size, struct diag *d)
{
	if (size < 1 || size > RT_MAX_IMAGE_SIZE)
		return diag_set(d, RT_E_RANGE, s->name, 0, 0,
				"image size must be between 1 and %d, found %ld", RT_MAX_IMAGE_SIZE, size);
	if (size * size > RT_MAX_PIXELS)
		return diag_set(d, RT_E_RANGE, s->name, 0, 0,
				"image size %ld gives more than %ld pixels", size, RT_MAX_PIXELS);
	s->image_size = (int)size;
	return 0;
}

void scene_set_source_hash(struct scene *s, uint64_t hash)
{
	s->source_hash = hash;
}

const char *scene_name(const struct scene *s)
{
	return s->name;
}

int scene_recursion(const struct scene *s)
{
	return s->recursion;
}

int scene_image_size(const struct scene *s)
{
	return s->image_size;
}

bool scene_has_floor(const struct scene *s)
{
	return s->floor != NULL;
}

size_t scene_shape_count(const struct scene *s)
{
	return s->n_shapes;
}

const struct shape *scene_shape(const struct scene *s, size_t i)
{
	return i < s->n_shapes ? s->shapes[i] : NULL;
}

size_t scene_light_count(const struct scene *s)
{
	return s->n_lights;
}

const struct light *scene_light(const struct scene *s, size_t i)
{
	return i < s->n_lights ? &s->lights[i] : NULL;
}

uint64_t scene_source_hash(const struct scene *s)
{
	return s->source_hash;
}

const struct image *scene_floor_texture(const struct scene *s, int k)
{
	return s->floor && k >= 0 && k < 2 ? floor_texture(s->floor, k) : NULL;
}

uint64_t scene_floor_texture_hash(const struct scene *s)
{
	return s->floor_texture_hash;
}
