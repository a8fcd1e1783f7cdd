/* Helpers for writing POV-Ray 3.7 scene language: numbers that read back
 * exactly, vectors, and the texture that reproduces a material. */
#include <stdio.h>
#include <stdlib.h>

#include "base/number.h"
#include "whitted/pov.h"

void pov_write_number(FILE *out, double v)
{
	char buf[32];

	if (v == 0.0)
		v = 0.0;	/* no "-0" */
	number_format_shortest(buf, sizeof(buf), v);
	fputs(buf, out);
}

void pov_write_vector(FILE *out, double x, double y, double z)
{
	fputc('<', out);
	pov_write_number(out, x);
	fputc(',', out);
	pov_write_number(out, y);
	fputc(',', out);
	pov_write_number(out, z);
	fputc('>', out);
}

/* Exact mode: the object sits in a light group whose lights carry the light
 * colour times the object colour (pov_export writes that), so the pigment
 * is white and the ambient carries KA times the colour; POV's phong is then
 * tinted like the model's specular term.  Plain mode is an ordinary
 * coloured pigment with a white highlight. */
/* Glass: POV-Ray scales a surface's ambient and diffuse light by its
 * opacity 1 - transmit and adds transmit times the light through it,
 * while whitted adds kt I(T) to the whole opaque sum; so the pigment is
 * the colour over 1 - kt, transmitting kt, and the highlight is left as it
 * is (POV-Ray does not scale it).  Fresnel stays off, as POV-Ray's default. */
static void pov_write_glass_pigment(FILE *out, double r, double g, double b, double kt)
{
	double k = 1.0 / (1.0 - kt);

	fputs("texture { pigment { rgbt <", out);
	pov_write_number(out, r * k);
	fputc(',', out);
	pov_write_number(out, g * k);
	fputc(',', out);
	pov_write_number(out, b * k);
	fputc(',', out);
	pov_write_number(out, kt);
	fputc('>', out);
}

void pov_write_finish_terms(FILE *out, const struct material *m)
{
	fputs(" diffuse ", out);
	pov_write_number(out, m->kd);
	fputs(" phong ", out);
	pov_write_number(out, m->ks);
	fputs(" phong_size ", out);
	pov_write_number(out, m->shininess);
	fputs(" reflection { ", out);
	pov_write_number(out, m->kr);
	fputs(" } } }", out);
}

void pov_write_texture(FILE *out, const struct material *m, const struct pov_options *opt)
{
	const struct color *c = &m->color;

	if (opt->shadow_twin) {
		fputs("texture { pigment { rgb 0 } } no_image no_reflection", out);
		return;
	}
	if (opt->finish == RT_POV_FINISH_EXACT) {
		if (m->kt > 0.0)
			pov_write_glass_pigment(out, 1.0, 1.0, 1.0, m->kt);
		else
			fputs("texture { pigment { rgb 1", out);
		fputs(" } finish { ambient rgb ", out);
		pov_write_vector(out, m->ka * c->r, m->ka * c->g, m->ka * c->b);
	} else {
		if (m->kt > 0.0) {
			pov_write_glass_pigment(out, c->r, c->g, c->b, m->kt);
		} else {
			fputs("texture { pigment { rgb ", out);
			pov_write_vector(out, c->r, c->g, c->b);
		}
		fputs(" } finish { ambient ", out);
		pov_write_number(out, m->ka);
	}
	pov_write_finish_terms(out, m);
	if (m->kt > 0.0) {
		fputs(" interior { ior ", out);
		pov_write_number(out, m->ior);
		fputs(" } no_shadow", out);
	}
}
