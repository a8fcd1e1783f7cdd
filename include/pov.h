/* Writing scenes as POV-Ray 3.7 scene language. */
#ifndef RT_POV_H
#define RT_POV_H

#include <stdio.h>

#include "material.h"

enum pov_finish {
	RT_POV_FINISH_EXACT,	/* per-object light groups: the tinted highlight */
	RT_POV_FINISH_PLAIN,	/* ordinary white phong highlights */
};

struct pov_options {
	enum pov_finish finish;
};

/* Writes "texture { pigment { ... } finish { ... } }" for a material. */
void pov_write_texture(FILE *out, const struct material *m, const struct pov_options *opt);
/* Writes a number so that POV-Ray reads back the same double. */
void pov_write_number(FILE *out, double v);
void pov_write_vector(FILE *out, double x, double y, double z);

#endif
