/* whitted explain's output: the tree of rays as indented text, or as one
 * JSON object.  Numbers to 9 significant digits (a double's colour to far
 * below one 8-bit level), colours as [r, g, b] in [0, 1] before the 8-bit
 * conversion; NaN or an infinity as JSON's null. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>

#include "cli/explain.h"

static void json_text(FILE *out, const char *s)
{
	const unsigned char *p = (const unsigned char *)s;

	fputc('"', out);
	for (; *p; p++) {
		if (*p == '"' || *p == '\\')
			fprintf(out, "\\%c", *p);
		else if (*p < 0x20 || *p >= 0x7f)
			fprintf(out, "\\u%04x", *p < 0x80 ? *p : 0xfffd);
		else
			fputc(*p, out);
	}
	fputc('"', out);
}

static void json_num(FILE *out, double v)
{
	if (isfinite(v))
		fprintf(out, "%.9g", v);
	else
		fputs("null", out);
}

static void json_vec(FILE *out, struct vec3 v)
{
	fputc('[', out);
	json_num(out, v.x);
	fputs(", ", out);
	json_num(out, v.y);
	fputs(", ", out);
	json_num(out, v.z);
	fputc(']', out);
}

static void json_color(FILE *out, struct color c)
{
	json_vec(out, vec3_make(c.r, c.g, c.b));
}

/* ", \"key\": " and the value: a field after the first of an object. */
static void json_key(FILE *out, const char *key)
{
	fprintf(out, ", \"%s\": ", key);
}

static void json_key_num(FILE *out, const char *key, double v)
{
	json_key(out, key);
	json_num(out, v);
}

static void json_key_vec(FILE *out, const char *key, struct vec3 v)
{
	json_key(out, key);
	json_vec(out, v);
}

static void json_key_color(FILE *out, const char *key, struct color c)
{
	json_key(out, key);
	json_color(out, c);
}

static void json_object(FILE *out, const struct explain_object *o)
{
	fputs("{\"index\": ", out);
	if (o->floor)
		fputs("null", out);
	else
		fprintf(out, "%ld", o->index);
	json_key(out, "keyword");
	json_text(out, o->keyword);
	json_key(out, "line");
	if (o->line > 0)
		fprintf(out, "%d", o->line);
	else
		fputs("null", out);
	fprintf(out, ", \"floor\": %s}", o->floor ? "true" : "false");
}

static void json_light(FILE *out, const struct scene *s, size_t index, const struct explain_light *l)
{
	const struct light *lt = scene_light(s, index);

	fprintf(out, "{\"index\": %zu, \"position\": ", index + 1);
	json_vec(out, lt->pos);
	json_key_color(out, "color", lt->color);
	fprintf(out, ", \"spot\": %s, \"state\": \"%s\", \"distance\": ", lt->spot ? "true" : "false",
		explain_light_state_name(l->state));
	json_num(out, l->distance);
	json_key_vec(out, "l", l->l);
	json_key_num(out, "n_dot_l", l->n_dot_l);
	json_key_num(out, "r_dot_l", l->r_dot_l);
	json_key_num(out, "attenuation", l->attenuation);
	json_key(out, "blocker");
	if (l->state == EXPLAIN_SHADOWED && l->blocker_known)
		json_object(out, &l->blocker);
	else
		fputs("null", out);
	json_key_color(out, "diffuse", l->diffuse);
	json_key_color(out, "specular", l->specular);
	json_key_color(out, "term", l->term);
	fputc('}', out);
}

static void json_child(FILE *out, const char *name, long id, double k, struct color seen)
{
	fprintf(out, ", \"%s\": ", name);
	if (id < 0) {
		fputs("null", out);
		return;
	}
	fprintf(out, "{\"ray\": %ld, \"k\": ", id);
	json_num(out, k);
	json_key_color(out, "color", seen);
	fputc('}', out);
}

/* Long: one ray's JSON object, its fields in their order. */
static void json_ray(FILE *out, const struct scene *s, const struct explanation *e, size_t id)
{
	const struct explain_ray *r = &e->rays[id];
	size_t i;

	fprintf(out, "{\"id\": %zu, \"kind\": \"%s\", \"sample\": %d, \"parent\": ", id,
		explain_ray_kind_name(r->kind), r->sample);
	if (r->parent >= 0)
		fprintf(out, "%ld", r->parent);
	else
		fputs("null", out);
	fprintf(out, ", \"level\": %d, \"weight\": ", r->level);
	json_num(out, r->weight);
	json_key_vec(out, "origin", r->ray.origin);
	json_key_vec(out, "direction", r->ray.dir);
	json_key(out, "hit");
	if (!r->hit) {
		fputs("null, \"color\": [0, 0, 0]}", out);
		return;
	}
	fputs("{\"object\": ", out);
	json_object(out, &r->object);
	json_key_num(out, "t", r->t);
	json_key_vec(out, "point", r->point);
	json_key_vec(out, "normal", r->normal);
	fprintf(out, ", \"normal_turned\": %s, \"surface\": ", r->turned ? "true" : "false");
	json_color(out, r->surface);
	json_key_color(out, "highlight", r->highlight);
	fputs(", \"material\": {\"ka\": ", out);
	json_num(out, r->mat.ka);
	json_key_num(out, "kd", r->mat.kd);
	json_key_num(out, "ks", r->mat.ks);
	json_key_num(out, "kr", r->mat.kr);
	json_key_num(out, "shininess", r->mat.shininess);
	json_key_num(out, "kt", r->mat.kt);
	json_key_num(out, "ior", r->mat.ior);
	fputs("}, \"ambient\": ", out);
	json_color(out, r->ambient);
	fputs(", \"lights\": [", out);
	for (i = 0; i < r->n_lights; i++) {
		fputs(i ? ", " : "", out);
		json_light(out, s, i, &e->lights[r->first_light + i]);
	}
	fputs("], \"direct\": ", out);
	json_color(out, r->direct);
	json_child(out, "reflection", r->reflected, r->k_reflected, r->reflected_color);
	json_child(out, "refraction", r->refracted, r->mat.kt, r->refracted_color);
	fprintf(out, ", \"total_internal_reflection\": %s, \"sum\": ",
		r->total_internal_reflection ? "true" : "false");
	json_color(out, r->sum);
	fputs("}, \"color\": ", out);
	json_color(out, r->color);
	fputc('}', out);
}

void explain_print_json(FILE *out, const char *scene_name, const struct scene *s,
			const struct explanation *e)
{
	size_t i;
	int k;

	fputs("{\"scene\": ", out);
	json_text(out, scene_name);
	fprintf(out, ", \"x\": %d, \"y\": %d, \"width\": %d, \"height\": %d, \"recursion\": %d, "
		"\"clamp\": \"%s\", \"samples\": %d, \"sample_colors\": [",
		e->x, e->y, e->width, e->height, e->settings.recursion,
		e->settings.clamp == RT_CLAMP_LEVEL ? "level" : "final", e->samples);
	for (k = 0; k < e->samples * e->samples; k++) {
		fputs(k ? ", " : "", out);
		json_color(out, e->sample_colors[k]);
	}
	fputs("], \"rays\": [", out);
	for (i = 0; i < e->n_rays; i++) {
		fputs(i ? ", " : "", out);
		json_ray(out, s, e, i);
	}
	fputs("], \"color\": ", out);
	json_color(out, e->color);
	json_key_color(out, "clamped", e->clamped);
	fprintf(out, ", \"value\": [%d, %d, %d]}\n", e->value[0], e->value[1], e->value[2]);
}

static void text_vec(FILE *out, struct vec3 v)
{
	fprintf(out, "(%.6g, %.6g, %.6g)", v.x, v.y, v.z);
}

static void text_color(FILE *out, struct color c)
{
	fprintf(out, "(%.6f, %.6f, %.6f)", c.r, c.g, c.b);
}

static void text_object(FILE *out, const struct explain_object *o)
{
	if (o->floor)
		fprintf(out, "the floor");
	else if (o->line > 0)
		fprintf(out, "object %ld (%s, line %d)", o->index, o->keyword, o->line);
	else
		fprintf(out, "object %ld (%s)", o->index, o->keyword);
}

static void text_light(FILE *out, const struct explain_light *l, size_t index)
{
	fprintf(out, "    light %zu: ", index + 1);
	switch (l->state) {
	case EXPLAIN_AT_POINT:
		fprintf(out, "at the point itself: no light\n");
		return;
	case EXPLAIN_BEHIND:
		fprintf(out, "behind the surface (N.L = %.6g <= 0): no light\n", l->n_dot_l);
		return;
	case EXPLAIN_OUTSIDE_CONE:
		fprintf(out, "a spotlight whose cone does not reach the point: no light\n");
		return;
	case EXPLAIN_SHADOWED:
		fprintf(out, "shadow ray blocked by ");
		if (l->blocker_known)
			text_object(out, &l->blocker);
		else
			fprintf(out, "an object");
		fprintf(out, " (N.L = %.6g, the light %.6g away): no light\n", l->n_dot_l, l->distance);
		return;
	case EXPLAIN_LIT:
		break;
	}
	fprintf(out, "N.L = %.6g, R.L = %.6g, distance %.6g", l->n_dot_l, l->r_dot_l, l->distance);
	if (l->attenuation != 1.0)
		fprintf(out, ", falloff factor %.6g", l->attenuation);
	fprintf(out, "\n      diffuse  Lc C kd (N.L)        ");
	text_color(out, l->diffuse);
	fprintf(out, "\n      specular Lc S ks (R.L)^n      ");
	text_color(out, l->specular);
	fprintf(out, "\n      term                          ");
	text_color(out, l->term);
	fputc('\n', out);
}

static void text_ray(FILE *out, const struct explanation *e, size_t id)
{
	const struct explain_ray *r = &e->rays[id];
	size_t i;

	fprintf(out, "ray %zu: %s", id, explain_ray_kind_name(r->kind));
	if (r->parent >= 0)
		fprintf(out, " from ray %ld", r->parent);
	if (e->samples > 1)
		fprintf(out, ", sample %d", r->sample);
	fprintf(out, ", level %d, weight %.6g\n  from ", r->level, r->weight);
	text_vec(out, r->ray.origin);
	fprintf(out, " along ");
	text_vec(out, r->ray.dir);
	fputc('\n', out);
	if (!r->hit) {
		fprintf(out, "  hits nothing: black\n");
		return;
	}
	fprintf(out, "  hits ");
	text_object(out, &r->object);
	fprintf(out, " at t = %.9g\n  point ", r->t);
	text_vec(out, r->point);
	fprintf(out, ", normal ");
	text_vec(out, r->normal);
	fprintf(out, "%s\n", r->turned ? " (turned to face the ray)" : "");
	fprintf(out, "  colour C ");
	text_color(out, r->surface);
	fprintf(out, ", ka %g kd %g ks %g kr %g shininess %g", r->mat.ka, r->mat.kd, r->mat.ks,
		r->mat.kr, r->mat.shininess);
	if (r->mat.kt > 0.0)
		fprintf(out, ", glass kt %g ior %g", r->mat.kt, r->mat.ior);
	fprintf(out, "\n    ambient ka C                    ");
	text_color(out, r->ambient);
	fputc('\n', out);
	for (i = 0; i < r->n_lights; i++)
		text_light(out, &e->lights[r->first_light + i], i);
	if (r->reflected >= 0) {
		fprintf(out, "    reflection %s %.6g x ray %ld's colour ",
			r->total_internal_reflection ? "(total internal reflection)" : "kr",
			r->k_reflected, r->reflected);
		text_color(out, r->reflected_color);
		fputc('\n', out);
	}
	if (r->refracted >= 0) {
		fprintf(out, "    refraction kt %.6g x ray %ld's colour ", r->mat.kt, r->refracted);
		text_color(out, r->refracted_color);
		fputc('\n', out);
	}
	fprintf(out, "  sum ");
	text_color(out, r->sum);
	fprintf(out, "%s ", e->settings.clamp == RT_CLAMP_LEVEL ? ", clamped:" : ", returned:");
	text_color(out, r->color);
	fputc('\n', out);
}

void explain_print_text(FILE *out, const char *scene_name, const struct scene *s,
			const struct explanation *e)
{
	size_t i;
	int k;

	(void)s;
	fprintf(out, "pixel %d,%d of %s (%dx%d, recursion %d, clamp %s", e->x, e->y, scene_name,
		e->width, e->height, e->settings.recursion,
		e->settings.clamp == RT_CLAMP_LEVEL ? "level" : "final");
	if (e->samples > 1)
		fprintf(out, ", %dx%d samples", e->samples, e->samples);
	fprintf(out, ")\n");
	for (i = 0; i < e->n_rays; i++)
		text_ray(out, e, i);
	if (e->samples > 1) {
		fprintf(out, "samples (each clamped, then averaged):\n");
		for (k = 0; k < e->samples * e->samples; k++) {
			fprintf(out, "  %d ", k);
			text_color(out, e->sample_colors[k]);
			fputc('\n', out);
		}
	}
	fprintf(out, "pixel colour ");
	text_color(out, e->color);
	fprintf(out, ", clamped ");
	text_color(out, e->clamped);
	fprintf(out, "\n8-bit value (%d, %d, %d)\n", e->value[0], e->value[1], e->value[2]);
}
