/* The scene parser's reading primitives, shared by the shape parsers.  Each
 * reads one item, or fills the diagnostic with what was expected and what
 * was found (at that token's line and column) and returns -RT_E_*. */
#ifndef RT_PARSE_H
#define RT_PARSE_H

#include "diag.h"
#include "material.h"
#include "vec3.h"

struct parser;

/* `what` names the item for messages, e.g. "sphere radius". */
int parser_number(struct parser *p, const char *what, double *out);
int parser_vec3(struct parser *p, const char *what, struct vec3 *out);
int parser_color(struct parser *p, const char *what, struct color *out);
/* The colour, coefficients and shininess that end every object. */
int parser_material(struct parser *p, struct material *out);

/* Reports an error located at the last token read; returns -err. */
int parser_fail(struct parser *p, enum rt_err err, const char *fmt, ...)
#if defined(__GNUC__)
	__attribute__((format(printf, 3, 4)))
#endif
	;

#endif
