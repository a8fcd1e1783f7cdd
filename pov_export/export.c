/* The POV-Ray 3.7 file for a scene: settings that make POV-Ray compute what
 * whitted computes (linear output, ambient light 1, whitted's recursion
 * depth, no adaptive depth cut), whitted's camera as explicit vectors, the
 * lights (spotlights and falloff as the comments below say), and each
 * shape's own export.  In the exact finish the model's
 * highlight is tinted by the object colour, which POV-Ray's phong is not:
 * each object therefore sits in a light group whose lights carry the light
 * colour times the object colour, over a white pigment.  Objects of one
 * colour share a group.  Light groups only choose whose light falls on an
 * object; every object still casts shadows for every light (measured on
 * POV-Ray 3.7.0.10, see docs/validation.md). */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "cli/scene_opts.h"
#include "export.h"
#include "shapes/registry.h"

struct pov_member {
	const struct shape *shape;
	size_t index;			/* file order: keeps the output stable */
};

static int pov_cmp_double(double a, double b)
{
	return (a > b) - (a < b);
}

static int pov_member_cmp(const void *pa, const void *pb)
{
	const struct pov_member *a = pa, *b = pb;
	const struct color *ca = &a->shape->mat.color, *cb = &b->shape->mat.color;
	int c;

	if ((c = pov_cmp_double(ca->r, cb->r)) != 0 || (c = pov_cmp_double(ca->g, cb->g)) != 0 ||
	    (c = pov_cmp_double(ca->b, cb->b)) != 0)
		return c;
	return (a->index > b->index) - (a->index < b->index);
}

static bool pov_same_color(const struct color *a, const struct color *b)
{
	return a->r == b->r && a->g == b->g && a->b == b->b;
}

/* A comment line that POV-Ray reads as one comment whatever the name holds. */
static void pov_write_comment_name(FILE *out, const char *name)
{
	const unsigned char *p;

	for (p = (const unsigned char *)name; *p; p++)
		fputc(*p >= 0x20 && *p < 0x7f ? *p : '?', out);
}

/* A point POV-Ray's spotlight aims at: along the axis from the light, far
 * enough that the difference keeps the axis's digits. */
static struct vec3 pov_point_at(struct vec3 pos, struct vec3 axis)
{
	double scale = fmax(1.0, fmax(fabs(pos.x), fmax(fabs(pos.y), fabs(pos.z))));

	return vec3_add_scaled(pos, axis, scale);
}

/* A hard cone of half-angle cutoff (at most 90 degrees) around axis:
 * POV-Ray lights fully inside radius, fades to falloff and then nothing,
 * so radius = falloff = cutoff is the hard edge, and tightness 0 leaves
 * the inside at full strength (measured on POV-Ray 3.7.0.10: the lit disc
 * ends at tan(cutoff) within a pixel, its inside is the point light's). */
static void pov_write_cone(FILE *out, struct vec3 pos, struct vec3 axis, double cutoff)
{
	struct vec3 at = pov_point_at(pos, axis);

	fputs(" spotlight point_at ", out);
	pov_write_vector(out, at.x, at.y, at.z);
	fputs(" radius ", out);
	pov_write_number(out, cutoff);
	fputs(" falloff ", out);
	pov_write_number(out, cutoff);
	fputs(" tightness 0", out);
}

/* The falloff exp(-k d^2) has no POV-Ray form.  POV-Ray's fade scales a
 * light by 2 / (1 + (d / fade_distance)^fade_power) (measured on POV-Ray
 * 3.7.0.10), so with the colour times s, fade_distance sqrt(x0 / k) and
 * fade_power 2 q it is g(x) = 2 s / (1 + (x / x0)^q) of x = k d^2.  Each
 * row below is the (s, x0, q) that makes the largest |g(x) - exp(-x)| over
 * 0 <= x <= x_max least (Nelder-Mead on 1500 samples; the error left is in
 * the comment, as a fraction of the light's full strength); a light takes
 * the first row whose x_max covers k d^2 to the farthest corner of the
 * bounded shapes' box, the last when there is none.  Unbounded shapes
 * (the infinite floor) reach farther, where both curves are near 0 but
 * POV-Ray's falls as x^-q, not exponentially.  On scenes/falloff.txt this
 * leaves PSNR 50.8 dB, at most 5 levels off (make povcheck measures it);
 * the simplest mapping, s = 1/2, x0 = 1, q = 1 (1 / (1 + k d^2), exact to
 * first order at d = 0), leaves 34.2 dB, and no fade at all 20.8 dB. */
static const struct pov_fade_row {
	double x_max, s, x0, q;
} pov_fade_rows[] = {
	{ 0.01, 0.499999, 0.980584, 1.003260 },		/* 1.7e-6 */
	{ 0.02, 0.499997, 0.966007, 1.006515 },		/* 6.8e-6 */
	{ 0.05, 0.499979, 0.931577, 1.016253 },		/* 4.2e-5 */
	{ 0.1, 0.499918, 0.889088, 1.032385 },		/* 1.6e-4 */
	{ 0.2, 0.499690, 0.830645, 1.064260 },		/* 6.2e-4 */
	{ 0.5, 0.498351, 0.741105, 1.156380 },		/* 3.3e-3 */
	{ 1, 0.494948, 0.689499, 1.295726 },		/* 1.0e-2 */
	{ 2, 0.488152, 0.674220, 1.505387 },		/* 2.4e-2 */
	{ 3, 0.484448, 0.677372, 1.609973 },		/* 3.1e-2 */
	{ INFINITY, 0.483716, 0.678421, 1.630866 },	/* 3.3e-2 */
};

/* A light's POV-Ray form: its colour's scale and the fade, if any. */
struct pov_fade {
	double scale;		/* 1 without a falloff */
	double distance, power;	/* distance 0: no fade */
};

/* The box of every bounded shape; false when there is none. */
static bool pov_scene_box(const struct scene *s, struct aabb *out)
{
	bool any = false;
	size_t i;

	for (i = 0; i < scene_shape_count(s); i++) {
		struct aabb b;

		if (!shape_bounds(scene_shape(s, i), &b))
			continue;
		if (!any) {
			*out = b;
			any = true;
			continue;
		}
		out->min = vec3_make(fmin(out->min.x, b.min.x), fmin(out->min.y, b.min.y),
				     fmin(out->min.z, b.min.z));
		out->max = vec3_make(fmax(out->max.x, b.max.x), fmax(out->max.y, b.max.y),
				     fmax(out->max.z, b.max.z));
	}
	return any;
}

static struct pov_fade pov_fade_of(const struct light *l, const struct aabb *box)
{
	struct pov_fade f = { 1.0, 0.0, 0.0 };
	const struct pov_fade_row *row;
	double x = INFINITY;
	size_t i;

	if (!(l->falloff > 0.0))
		return f;
	if (box) {
		/* The farthest corner, axis by axis. */
		double dx = fmax(fabs(box->min.x - l->pos.x), fabs(box->max.x - l->pos.x));
		double dy = fmax(fabs(box->min.y - l->pos.y), fabs(box->max.y - l->pos.y));
		double dz = fmax(fabs(box->min.z - l->pos.z), fabs(box->max.z - l->pos.z));

		x = l->falloff * (dx * dx + dy * dy + dz * dz);
	}
	for (i = 0; pov_fade_rows[i].x_max < x; i++)
		;
	row = &pov_fade_rows[i];
	f.scale = row->s;
	f.distance = sqrt(row->x0 / l->falloff);
	f.power = 2.0 * row->q;
	return f;
}

static void pov_write_one_light(FILE *out, const char *indent, const struct light *l,
				const struct pov_fade *f, struct color c, bool cone,
				struct vec3 axis, double cutoff)
{
	fprintf(out, "%slight_source { ", indent);
	pov_write_vector(out, l->pos.x, l->pos.y, l->pos.z);
	fputs(" color rgb ", out);
	if (f->distance > 0.0)
		c = color_scale(c, f->scale);
	pov_write_vector(out, c.r, c.g, c.b);
	if (cone)
		pov_write_cone(out, l->pos, axis, cutoff);
	if (f->distance > 0.0) {
		fputs(" fade_distance ", out);
		pov_write_number(out, f->distance);
		fputs(" fade_power ", out);
		pov_write_number(out, f->power);
	}
	fputs(" }\n", out);
}

/* The light l in colour c.  A POV-Ray spotlight lights nothing more than
 * 90 degrees from its axis, so a wider cone is a point light less a
 * negative spotlight over the dark cone around -axis (of half-angle 180 -
 * cutoff; both lights are shadowed alike, so the difference is exact); a
 * cone of 180 degrees lights everything, as a point light does. */
static void pov_write_light(FILE *out, const char *indent, const struct light *l,
			    const struct pov_fade *f, struct color c)
{
	if (!l->spot || l->cutoff_deg >= 180.0) {
		pov_write_one_light(out, indent, l, f, c, false, l->axis, 0.0);
	} else if (l->cutoff_deg <= 90.0) {
		pov_write_one_light(out, indent, l, f, c, true, l->axis, l->cutoff_deg);
	} else {
		pov_write_one_light(out, indent, l, f, c, false, l->axis, 0.0);
		pov_write_one_light(out, indent, l, f, color_scale(c, -1.0), true, vec3_neg(l->axis),
				    180.0 - l->cutoff_deg);
	}
}

/* POV-Ray's perspective ray for the image point (x, y) in [-0.5, 0.5]^2
 * (x to the right, y up) is direction + x right + y up.  With |right| =
 * |up| = 1 and |direction| = 0.5 / tan(fov / 2) this is whitted's pinhole;
 * giving right = forward x up explicitly fixes the handedness, where
 * POV-Ray's default right (<1.33,0,0>, for a left-handed world) would
 * mirror the image.  The nearfar camera's wider or narrower view is a
 * right of length tan(fovx / 2) / tan(fovy / 2).  Its near plane has no
 * POV-Ray form: POV-Ray's rays start at the eye, along the very lines
 * whitted's start on the plane, so the images agree wherever nothing lies
 * between the eye and the plane; the file says so, and scene2pov notes a
 * shape that reaches in there (pov_export_near_hides). */
static void pov_write_camera(FILE *out, const struct camera *cam)
{
	struct vec3 dir = vec3_scale(cam->forward, 0.5 / cam->half_height);
	struct vec3 right = cam->right;

	if (cam->half_width != cam->half_height)
		right = vec3_scale(right, cam->half_width / cam->half_height);
	if (cam->near > 0.0) {
		fputs("// whitted's primary rays start on the image plane ", out);
		pov_write_number(out, cam->near);
		fputs(" in front of the eye: POV-Ray's camera\n"
		      "// has no near plane and shows what lies nearer, which whitted does not.\n", out);
	}
	fputs("camera {\n  perspective\n  location ", out);
	pov_write_vector(out, cam->eye.x, cam->eye.y, cam->eye.z);
	fputs("\n  direction ", out);
	pov_write_vector(out, dir.x, dir.y, dir.z);
	fputs("\n  right ", out);
	pov_write_vector(out, right.x, right.y, right.z);
	fputs("\n  up ", out);
	pov_write_vector(out, cam->up.x, cam->up.y, cam->up.z);
	fputs("\n}\n", out);
}

/* The box around the eye that holds every point between it and the image
 * plane: corners eye + near (forward +- half_width right +- half_height
 * up) and the eye itself. */
static struct aabb pov_near_box(const struct camera *cam)
{
	struct aabb b;
	int i;

	b.min = b.max = cam->eye;
	for (i = 0; i < 4; i++) {
		double u = i & 1 ? cam->half_width : -cam->half_width;
		double v = i & 2 ? cam->half_height : -cam->half_height;
		struct vec3 w = vec3_add(cam->forward, vec3_add(vec3_scale(cam->right, u),
								 vec3_scale(cam->up, v)));
		struct vec3 c = vec3_add_scaled(cam->eye, w, cam->near);

		b.min = vec3_make(fmin(b.min.x, c.x), fmin(b.min.y, c.y), fmin(b.min.z, c.z));
		b.max = vec3_make(fmax(b.max.x, c.x), fmax(b.max.y, c.y), fmax(b.max.z, c.z));
	}
	return b;
}

bool pov_export_near_hides(const struct scene *s, const struct camera *cam)
{
	struct aabb near, b;
	size_t i;

	if (!(cam->near > 0.0))
		return false;
	near = pov_near_box(cam);
	for (i = 0; i < scene_shape_count(s); i++) {
		const struct shape *sh = scene_shape(s, i);

		/* Bounds of an unbounded shape still say the axes it is bounded
		 * along (the floor's z = 0). */
		shape_bounds(sh, &b);
		if (b.min.x <= near.max.x && b.max.x >= near.min.x && b.min.y <= near.max.y &&
		    b.max.y >= near.min.y && b.min.z <= near.max.z && b.max.z >= near.min.z)
			return true;
	}
	return false;
}

/* max_trace_level R: POV-Ray's primary ray is trace level 1 and a ray at a
 * level above R returns black, so R levels of surfaces are shaded, as in
 * whitted.  adc_bailout 0: no weak reflection is dropped early. */
static void pov_write_settings(FILE *out, const struct scene *s)
{
	fprintf(out,
		"global_settings {\n"
		"  assumed_gamma 1.0\n"
		"  ambient_light rgb 1\n"
		"  max_trace_level %d\n"
		"  adc_bailout 0\n"
		"}\n"
		"background { rgb 0 }\n",
		scene_recursion(s));
}

/* Object `index` (0-based) through its table's export_pov: any status but
 * 0 is a failure, a write error when the file says so and otherwise the
 * table's own (a plugin that fails without a reason, or returns a
 * positive number), named with the object and the plugin. */
static int pov_write_shape(FILE *out, const struct shape *sh, size_t index,
			   const struct pov_options *opt, struct diag *d)
{
	const char *origin;
	int rc = shape_export_pov(sh, out, opt);

	if (rc == 0)
		return 0;
	if (ferror(out))
		return diag_fail(d, RT_E_IO, "write error");
	origin = shape_registry_origin(sh->ops);
	return diag_fail(d, RT_E_RANGE,
			 "object %zu ('%s' of %s%s): its export_pov %s (returned %d)", index + 1,
			 sh->ops->keyword, origin ? "the plugin " : "whitted (built in)",
			 origin ? origin : "", rc > 0 ? "returned neither 0 nor an error" : "failed",
			 rc);
}

/* One light group per run of equal colours in members (sorted by colour). */
static int pov_write_groups(FILE *out, const struct scene *s, const struct pov_fade *fades,
			    const struct pov_member *m, size_t n, const struct pov_options *opt,
			    struct diag *d)
{
	size_t i = 0, j, k;
	int rc;

	while (i < n) {
		const struct color *c = &m[i].shape->mat.color;

		fputs("light_group {\n", out);
		for (k = 0; k < scene_light_count(s); k++) {
			struct color lc = color_mul(scene_light(s, k)->color, *c);
			/* A black light adds nothing; leaving it out saves POV-Ray
			 * its shadow rays. */
			if (lc.r != 0.0 || lc.g != 0.0 || lc.b != 0.0)
				pov_write_light(out, "  ", scene_light(s, k), &fades[k], lc);
		}
		for (j = i; j < n && pov_same_color(&m[j].shape->mat.color, c); j++)
			if ((rc = pov_write_shape(out, m[j].shape, m[j].index, opt, d)) < 0)
				return rc;
		fputs("  global_lights off\n}\n", out);
		i = j;
	}
	return 0;
}

/* Glass casts whitted's opaque shadow: POV-Ray's glass object has
 * no_shadow, and an unseen opaque copy of it (no_image no_reflection,
 * outside every light group so that every light's shadow rays meet it)
 * casts the shadow. */
static int pov_write_shadow_twins(FILE *out, const struct scene *s, const struct pov_options *opt,
				  struct diag *d)
{
	struct pov_options twin = *opt;
	size_t i;
	int rc;

	twin.shadow_twin = true;
	for (i = 0; i < scene_shape_count(s); i++) {
		const struct shape *sh = scene_shape(s, i);

		if (sh->mat.kt > 0.0 && (rc = pov_write_shape(out, sh, i, &twin, d)) < 0)
			return rc;
	}
	return 0;
}

/* Long: the POV-Ray file's sections in their order. */
int pov_export_scene(FILE *out, const struct scene *s, const struct camera *cam,
		     const struct pov_options *opt, struct diag *d)
{
	struct pov_member *members = NULL;
	struct pov_fade *fades;
	struct aabb box;
	bool bounded = pov_scene_box(s, &box);
	size_t i, n = 0;
	int rc = 0;

	fades = malloc((scene_light_count(s) + 1) * sizeof(*fades));
	if (!fades)
		return diag_fail(d, RT_E_NOMEM, "out of memory");
	for (i = 0; i < scene_light_count(s); i++)
		fades[i] = pov_fade_of(scene_light(s, i), bounded ? &box : NULL);

	fputs("// Written by scene2pov " RT_VERSION " from ", out);
	pov_write_comment_name(out, scene_name(s) ? scene_name(s) : "(unnamed)");
	fprintf(out, "\n// Render with the .ini written beside it: linear output, %dx%d,"
		" no antialiasing.\n#version 3.7;\n", scene_image_size(s), scene_image_size(s));
	pov_write_settings(out, s);
	pov_write_camera(out, cam);
	/* The global lights: in the exact finish they light only the textured
	 * shapes (the floor), in the plain finish everything. */
	for (i = 0; i < scene_light_count(s); i++)
		pov_write_light(out, "", scene_light(s, i), &fades[i], scene_light(s, i)->color);

	if (opt->finish == RT_POV_FINISH_EXACT && scene_shape_count(s) > 0) {
		members = malloc(scene_shape_count(s) * sizeof(*members));
		if (!members) {
			free(fades);
			return diag_fail(d, RT_E_NOMEM, "out of memory");
		}
	}
	for (i = 0; i < scene_shape_count(s); i++) {
		const struct shape *sh = scene_shape(s, i);
		if (members && !shape_is_textured(sh)) {
			members[n].shape = sh;
			members[n].index = i;
			n++;
		} else if ((rc = pov_write_shape(out, sh, i, opt, d)) < 0) {
			goto out_free;
		}
	}
	if (members) {
		qsort(members, n, sizeof(*members), pov_member_cmp);
		if ((rc = pov_write_groups(out, s, fades, members, n, opt, d)) < 0)
			goto out_free;
	}
	if ((rc = pov_write_shadow_twins(out, s, opt, d)) < 0)
		goto out_free;
out_free:
	free(members);
	free(fades);
	/* A shape's failure has its message already (pov_write_shape). */
	if (rc < 0)
		return rc;
	if (ferror(out))
		return diag_fail(d, RT_E_IO, "write error");
	return 0;
}

bool pov_export_name_ok(const char *name)
{
	const unsigned char *p;

	if (!name || !*name)
		return false;
	for (p = (const unsigned char *)name; *p; p++)
		if (*p < 0x20 || *p == 0x7f || *p == '"')
			return false;
	return true;
}

/* Each setting here is one fact of the mapping:
 * File_Gamma=1.0 writes the linear values whitted writes (the default,
 * sRGB, encodes them); antialiasing and jitter off leave one ray through
 * each pixel centre; Display=Off because Debian's povray.ini opens a
 * preview window otherwise. */
int pov_export_ini(FILE *out, const char *pov_name, const char *png_name, const char *dir,
		   int size, struct diag *d)
{
	if (!pov_export_name_ok(pov_name) || !pov_export_name_ok(png_name) ||
	    (dir && !pov_export_name_ok(dir)))
		return diag_fail(d, RT_E_INVALID,
				"POV-Ray's .ini cannot name a file with a quote or control character");
	if (dir)
		fprintf(out,
			"; Written by scene2pov " RT_VERSION ": povray on this file, from any "
			"directory, renders the scene\n; beside it.\n"
			"Library_Path=\"%s\"\n"
			"Input_File_Name=\"%s\"\n"
			"Output_File_Name=\"%s%s%s\"\n",
			dir, pov_name, dir, dir[strlen(dir) - 1] == '/' ? "" : "/", png_name);
	else
		fprintf(out,
			"; Written by scene2pov " RT_VERSION ": run povray on this file in its "
			"directory.\n"
			"Input_File_Name=\"%s\"\n"
			"Output_File_Name=\"%s\"\n",
			pov_name, png_name);
	fprintf(out,
		"Output_File_Type=N\n"
		"Bits_Per_Color=8\n"
		"Output_Alpha=Off\n"
		"Width=%d\n"
		"Height=%d\n"
		"File_Gamma=1.0\n"
		"Antialias=Off\n"
		"Jitter=Off\n"
		"Display=Off\n"
		"Pause_When_Done=Off\n",
		size, size);
	if (ferror(out))
		return diag_fail(d, RT_E_IO, "write error");
	return 0;
}
