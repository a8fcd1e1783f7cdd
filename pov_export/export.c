/* The POV-Ray 3.7 file for a scene: settings that make POV-Ray compute what
 * whitted computes (linear output, ambient light 1, whitted's recursion
 * depth, no adaptive depth cut), whitted's camera as explicit vectors, the
 * lights, and each shape's own export.  In the exact finish the model's
 * highlight is tinted by the object colour, which POV-Ray's phong is not:
 * each object therefore sits in a light group whose lights carry the light
 * colour times the object colour, over a white pigment.  Objects of one
 * colour share a group.  Light groups only choose whose light falls on an
 * object; every object still casts shadows for every light (measured on
 * POV-Ray 3.7.0.10, see docs/validation.md). */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "export.h"

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

static void pov_write_light(FILE *out, const char *indent, struct vec3 pos, struct color c)
{
	fprintf(out, "%slight_source { ", indent);
	pov_write_vector(out, pos.x, pos.y, pos.z);
	fputs(" color rgb ", out);
	pov_write_vector(out, c.r, c.g, c.b);
	fputs(" }\n", out);
}

/* POV-Ray's perspective ray for the image point (x, y) in [-0.5, 0.5]^2
 * (x to the right, y up) is direction + x right + y up.  With |right| =
 * |up| = 1 and |direction| = 0.5 / tan(fov / 2) this is whitted's pinhole;
 * giving right = forward x up explicitly fixes the handedness, where
 * POV-Ray's default right (<1.33,0,0>, for a left-handed world) would
 * mirror the image. */
static void pov_write_camera(FILE *out, const struct camera *cam)
{
	struct vec3 dir = vec3_scale(cam->forward, 0.5 / cam->half_height);

	fputs("camera {\n  perspective\n  location ", out);
	pov_write_vector(out, cam->eye.x, cam->eye.y, cam->eye.z);
	fputs("\n  direction ", out);
	pov_write_vector(out, dir.x, dir.y, dir.z);
	fputs("\n  right ", out);
	pov_write_vector(out, cam->right.x, cam->right.y, cam->right.z);
	fputs("\n  up ", out);
	pov_write_vector(out, cam->up.x, cam->up.y, cam->up.z);
	fputs("\n}\n", out);
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
		s->recursion);
}

/* One light group per run of equal colours in members (sorted by colour). */
static int pov_write_groups(FILE *out, const struct scene *s, const struct pov_member *m,
			    size_t n, const struct pov_options *opt)
{
	size_t i = 0, j, k;
	int rc;

	while (i < n) {
		const struct color *c = &m[i].shape->mat.color;

		fputs("light_group {\n", out);
		for (k = 0; k < s->n_lights; k++) {
			struct color lc = color_mul(s->lights[k].color, *c);
			/* A black light adds nothing; leaving it out saves POV-Ray
			 * its shadow rays. */
			if (lc.r != 0.0 || lc.g != 0.0 || lc.b != 0.0)
				pov_write_light(out, "  ", s->lights[k].pos, lc);
		}
		for (j = i; j < n && pov_same_color(&m[j].shape->mat.color, c); j++)
			if ((rc = shape_export_pov(m[j].shape, out, opt)) < 0)
				return rc;
		fputs("  global_lights off\n}\n", out);
		i = j;
	}
	return 0;
}

int pov_export_scene(FILE *out, const struct scene *s, const struct camera *cam,
		     const struct pov_options *opt, struct diag *d)
{
	struct pov_member *members = NULL;
	size_t i, n = 0;
	int rc = 0;

	fputs("// Written by scene2pov " RT_VERSION " from ", out);
	pov_write_comment_name(out, s->name ? s->name : "(unnamed)");
	fprintf(out, "\n// Render with the .ini written beside it: linear output, %dx%d,"
		" no antialiasing.\n#version 3.7;\n", s->image_size, s->image_size);
	pov_write_settings(out, s);
	pov_write_camera(out, cam);
	/* The global lights: in the exact finish they light only the textured
	 * shapes (the floor), in the plain finish everything. */
	for (i = 0; i < s->n_lights; i++)
		pov_write_light(out, "", s->lights[i].pos, s->lights[i].color);

	if (opt->finish == RT_POV_FINISH_EXACT && s->n_shapes > 0) {
		members = malloc(s->n_shapes * sizeof(*members));
		if (!members)
			return diag_set(d, RT_E_NOMEM, "", 0, 0, "out of memory");
	}
	for (i = 0; i < s->n_shapes; i++) {
		const struct shape *sh = s->shapes[i];
		if (members && !shape_is_textured(sh)) {
			members[n].shape = sh;
			members[n].index = i;
			n++;
		} else if ((rc = shape_export_pov(sh, out, opt)) < 0) {
			goto out_free;
		}
	}
	if (members) {
		qsort(members, n, sizeof(*members), pov_member_cmp);
		if ((rc = pov_write_groups(out, s, members, n, opt)) < 0)
			goto out_free;
	}
out_free:
	free(members);
	/* The shapes' exports fail only on a write error. */
	if (rc < 0 || ferror(out))
		return diag_set(d, RT_E_IO, "", 0, 0, "write error");
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
int pov_export_ini(FILE *out, const char *pov_name, const char *png_name, int size,
		   struct diag *d)
{
	if (!pov_export_name_ok(pov_name) || !pov_export_name_ok(png_name))
		return diag_set(d, RT_E_INVALID, "", 0, 0,
				"POV-Ray's .ini cannot name a file with a quote or control character");
	fprintf(out,
		"; Written by scene2pov " RT_VERSION ": run povray on this file in its directory.\n"
		"Input_File_Name=\"%s\"\n"
		"Output_File_Name=\"%s\"\n"
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
		pov_name, png_name, size, size);
	if (ferror(out))
		return diag_set(d, RT_E_IO, "", 0, 0, "write error");
	return 0;
}
