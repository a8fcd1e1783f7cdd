/* Helpers for writing POV-Ray 3.7 scene language: numbers that read back
 * exactly, vectors, and the texture that reproduces a material. */
#include <stdio.h>
#include <stdlib.h>

#include "pov.h"

void pov_write_number(FILE *out, double v)
{
	/* The shortest of 15 to 17 significant digits that reads back as the
	 * same double (17 always do): 0.4, not 0.40000000000000002. */
	char buf[32];
	int prec;

	if (v == 0.0)
		v = 0.0;	/* no "-0" */
	for (prec = 15; prec < 17; prec++) {
		snprintf(buf, sizeof(buf), "%.*g", prec, v);
		if (strtod(buf, NULL) == v)
			break;
	}
	if (prec == 17)
		snprintf(buf, sizeof(buf), "%.17g", v);
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
void pov_write_texture(FILE *out, const struct material *m, const struct pov_options *opt)
{
	const struct color *c = &m->color;

	if (opt->finish == RT_POV_FINISH_EXACT) {
		fputs("texture { pigment { rgb 1 } finish { ambient rgb ", out);
		pov_write_vector(out, m->ka * c->r, m->ka * c->g, m->ka * c->b);
	} else {
		fputs("texture { pigment { rgb ", out);
		pov_write_vector(out, c->r, c->g, c->b);
		fputs(" } finish { ambient ", out);
		pov_write_number(out, m->ka);
	}
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
