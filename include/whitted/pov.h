/* Writing scenes as POV-Ray 3.7 scene language. */
#ifndef RT_POV_H
#define RT_POV_H

#include <stdbool.h>
#include <stdio.h>

#include "material.h"

enum pov_finish {
	RT_POV_FINISH_EXACT,	/* per-object light groups: the tinted highlight */
	RT_POV_FINISH_PLAIN,	/* ordinary white phong highlights */
};

struct pov_options {
	enum pov_finish finish;
	/* True while writing the opaque shadow twin of a glass object (see
	 * pov_write_texture). */
	bool shadow_twin;
	/* The images a textured floor's image_maps name (white cells, black
	 * cells), relative to the .pov's directory: the opaque 24-bit PNGs of
	 * its decoded texels that scene2pov writes beside OUT.pov, so that
	 * POV-Ray reads the texels whitted uses whatever the input's format
	 * (alpha, 32-bit or top-down BMP).  NULL: the input file itself. */
	const char *floor_texture[2];
};

/* Writes "texture { pigment { ... } finish { ... } }" for a material.
 * Glass (kt > 0) adds " interior { ior N } no_shadow" after it, and its
 * pigment transmits kt; with opt->shadow_twin it writes instead an
 * opaque black texture and " no_image no_reflection": the twin that
 * casts the glass object's opaque shadow (whitted's rule) unseen. */
void pov_write_texture(FILE *out, const struct material *m, const struct pov_options *opt);
/* Writes a number so that POV-Ray reads back the same double. */
/* The finish's terms after its ambient, " diffuse KD phong KS phong_size
 * N reflection { KR } } }", closing the finish and the texture: the part
 * every texture of a material shares. */
void pov_write_finish_terms(FILE *out, const struct material *m);
void pov_write_number(FILE *out, double v);
void pov_write_vector(FILE *out, double x, double y, double z);

#endif
