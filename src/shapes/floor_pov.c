/* The floor in POV-Ray's scene language: a polygon (the square) or a
 * plane (nearfar's endless floor) with a checker of the cells' textures,
 * their images as image maps where the floor is textured. */
#include <stdio.h>

#include "shapes/floor_impl.h"
#include "whitted/pov.h"

/* A cell's texture: the material's, or with a texture k (0 white, 1 black)
 * an image_map over each unit square of pattern space (so each cell, once
 * the checker is scaled), nearest texel (no interpolate), read linearly
 * (gamma 1, as whitted takes the bytes), its finish the cell's: the
 * texel is the pigment of the ambient and diffuse terms and the phong
 * highlight stays white (the black cell has none). */
static void floor_write_cell(const struct shape *s, int k, const struct material *m,
			     const struct pov_options *plain, FILE *out)
{
	const struct floor *fl = (const struct floor *)s;
	const char *p, *name = plain->floor_texture[k];

	if (!fl->tex_path[k]) {
		pov_write_texture(out, m, plain);
		return;
	}
	if (name)
		fputs("texture { pigment { image_map { png \"", out);
	else
		fprintf(out, "texture { pigment { image_map { %s \"", image_format_name(fl->tex_format[k]));
	for (p = name ? name : fl->tex_path[k]; *p; p++) {
		if (*p == '"' || *p == '\\')
			fputc('\\', out);
		fputc(*p, out);
	}
	fputs("\" gamma 1.0 } } finish { ambient ", out);
	pov_write_number(out, m->ka);
	pov_write_finish_terms(out, m);
}

/* The texture of a checkerboard whose cell (0, 0) starts at (x0, y0).
 * POV-Ray's checker is colour 1 where floor(x) + floor(y) + floor(z) is
 * even, in pattern space.  Scaling by the cell and translating by (x0, y0)
 * gives our cell indices; translating z by -cell/2 puts the plane z = 0 at
 * pattern z = 0.5, mid-cell, where floor(z) = 0 keeps the parity. */
static void floor_write_checker(const struct shape *s, double cell, double x0, double y0,
				const struct pov_options *opt, FILE *out)
{
	/* The cell colour varies, so the floor cannot use the exact mode's
	 * tinted light group: a plain texture is exact here, since the white
	 * cell's highlight is white and the black cell has none. */
	struct pov_options plain = { RT_POV_FINISH_PLAIN, false, { NULL, NULL } };
	struct material black = s->mat;

	plain.floor_texture[0] = opt->floor_texture[0];
	plain.floor_texture[1] = opt->floor_texture[1];
	black.color = color_make(0.0, 0.0, 0.0);
	black.ks = 0.0;
	fputs("\n  texture { checker\n    ", out);
	floor_write_cell(s, 0, &s->mat, &plain, out);
	fputs("\n    ", out);
	floor_write_cell(s, 1, &black, &plain, out);
	fputs("\n    scale ", out);
	pov_write_number(out, cell);
	fputs(" translate ", out);
	pov_write_vector(out, x0, y0, -0.5 * cell);
	fputs("\n  }\n}\n", out);
}

int floor_export_pov(const struct shape *s, FILE *out, const struct pov_options *opt)
{
	const struct floor *fl = (const struct floor *)s;
	double h = fl->half;

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
	floor_write_checker(s, fl->cell, -h, -h, opt, out);
	return ferror(out) ? -RT_E_IO : 0;
}
/* The plane z = 0 with cell (0, 0) at the origin. */
int floor_infinite_export_pov(const struct shape *s, FILE *out, const struct pov_options *opt)
{
	const struct floor *fl = (const struct floor *)s;

	fputs("plane { z, 0", out);
	floor_write_checker(s, fl->cell, 0.0, 0.0, opt, out);
	return ferror(out) ? -RT_E_IO : 0;
}
