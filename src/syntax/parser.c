/* The reading primitives of scene files that the scene-file grammar and
 * every shape's parse share: numbers, integers, vectors, colours, the
 * material block, and located errors and notes.  They know tokens, not
 * scenes or shapes. */
#include <ctype.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "syntax/parser_impl.h"

/* Quotes a token for a message: at most 40 bytes, unprintable bytes escaped. */
void parser_describe_token(const struct token *t, char *buf, size_t size)
{
	size_t i, n = 0;

	if (!t->text) {
		snprintf(buf, size, "end of file");
		return;
	}
	buf[n++] = '\'';
	for (i = 0; i < t->len && i < 40 && n + 6 < size; i++) {
		unsigned char c = (unsigned char)t->text[i];
		if (isprint(c) && c != '\\') {
			buf[n++] = (char)c;
		} else {
			snprintf(buf + n, size - n, "\\x%02x", c);
			n += 4;
		}
	}
	if (i < t->len && n + 4 < size) {
		memcpy(buf + n, "...", 3);
		n += 3;
	}
	buf[n++] = '\'';
	buf[n] = '\0';
}

static int parser_fail_at(struct parser *p, const struct token *t, enum rt_err err,
			  const char *fmt, va_list ap)
{
	char msg[RT_DIAG_MSG_MAX];

	vsnprintf(msg, sizeof(msg), fmt, ap);
	return diag_set(p->d, err, p->name, t->line, t->col, "%s", msg);
}

int parser_fail(struct parser *p, enum rt_err err, const char *fmt, ...)
{
	va_list ap;
	int rc;

	va_start(ap, fmt);
	rc = parser_fail_at(p, &p->last, err, fmt, ap);
	va_end(ap);
	return rc;
}

void parser_note(struct parser *p, int line, const char *fmt, ...)
{
	struct diag note;
	va_list ap;

	if (!p->note)
		return;
	diag_clear(&note);
	snprintf(note.file, sizeof(note.file), "%s", p->name);
	note.line = line;
	va_start(ap, fmt);
	vsnprintf(note.msg, sizeof(note.msg), fmt, ap);
	va_end(ap);
	p->note(p->note_ctx, &note);
}

struct token parser_next(struct parser *p)
{
	p->last = lexer_next(&p->lx);
	return p->last;
}

/* The error for a token that should have been a number. */
static int parser_not_a_number(struct parser *p, const char *expected, const char *what)
{
	char found[64];

	parser_describe_token(&p->last, found, sizeof(found));
	if (p->last.text && p->last.len > RT_TOKEN_MAX)
		return parser_fail(p, RT_E_RANGE, "token too long (over %d bytes) where %s (%s) was expected",
				   RT_TOKEN_MAX, expected, what);
	if (lexer_looks_numeric(&p->last))
		return parser_fail(p, RT_E_RANGE, "expected a finite decimal number (%s), found %s",
				   what, found);
	return parser_fail(p, RT_E_SYNTAX, "expected %s (%s), found %s", expected, what, found);
}

int parser_number(struct parser *p, const char *what, double *out)
{
	if (lexer_next_simple_number(&p->lx, &p->last, out))
		return 0;
	parser_next(p);
	if (!lexer_number(&p->last, out))
		return parser_not_a_number(p, "a number", what);
	return 0;
}

/* An integer in [lo, hi]; integral reals such as "4.0" are accepted. */
int parser_int(struct parser *p, const char *what, long lo, long hi, long *out)
{
	double v;

	parser_next(p);
	if (!lexer_number(&p->last, &v))
		return parser_not_a_number(p, "an integer", what);
	if (v != floor(v)) {
		char found[64];
		parser_describe_token(&p->last, found, sizeof(found));
		return parser_fail(p, RT_E_SYNTAX, "expected an integer (%s), found %s", what, found);
	}
	/* Checked before the conversion: a value outside a long (1e300) is
	 * out of range, and converting it would be undefined. */
	if (v < (double)lo || v > (double)hi)
		return parser_fail(p, RT_E_RANGE, "%s must be between %ld and %ld, found %.17g",
				   what, lo, hi, v);
	*out = (long)v;
	return 0;
}

/* Three numbers, each read by `read` (a point's coordinates, a colour's
 * components), stopping at the first that fails. */
static int parser_three(struct parser *p, const char *what,
			int (*read)(struct parser *p, const char *what, double *out),
			double *a, double *b, double *c)
{
	int rc;

	if ((rc = read(p, what, a)) < 0 || (rc = read(p, what, b)) < 0 ||
	    (rc = read(p, what, c)) < 0)
		return rc;
	return 0;
}

int parser_vec3(struct parser *p, const char *what, struct vec3 *out)
{
	return parser_three(p, what, parser_number, &out->x, &out->y, &out->z);
}

/* A number that must be at least lo (more than lo where lo_excluded) and
 * at most hi: the colour components' and the coefficients' ranges differ
 * only in their bounds, and their errors read "WHAT must be RANGE, found
 * V" with range ("in [0, 1]", ">= 0") as the bounds are said there. */
static int parser_number_within(struct parser *p, const char *what, double lo, bool lo_excluded,
				double hi, const char *range, double *out)
{
	int rc = parser_number(p, what, out);

	if (rc < 0)
		return rc;
	if ((lo_excluded ? !(*out > lo) : *out < lo) || *out > hi)
		return parser_fail(p, RT_E_RANGE, "%s must be %s, found %g", what, range, *out);
	return 0;
}

static int parser_unit_interval(struct parser *p, const char *what, double *out)
{
	return parser_number_within(p, what, 0.0, false, 1.0, "in [0, 1]", out);
}

int parser_color(struct parser *p, const char *what, struct color *out)
{
	return parser_three(p, what, parser_unit_interval, &out->r, &out->g, &out->b);
}

int parser_non_negative(struct parser *p, const char *what, double *out)
{
	return parser_number_within(p, what, 0.0, false, INFINITY, ">= 0", out);
}

int parser_positive(struct parser *p, const char *what, double *out)
{
	return parser_number_within(p, what, 0.0, true, INFINITY, "> 0", out);
}

int parser_size(struct parser *p, const char *what, double *out)
{
	int rc = parser_positive(p, what, out);

	if (rc < 0)
		return rc;
	if (*out > 1e150)
		return parser_fail(p, RT_E_RANGE, "%s is too large (%g)", what, *out);
	return 0;
}

int parser_material(struct parser *p, struct material *m)
{
	int rc;

	m->kt = 0.0;
	m->ior = 1.0;
	if ((rc = parser_color(p, "colour component", &m->color)) < 0 ||
	    (rc = parser_non_negative(p, "ambient coefficient", &m->ka)) < 0 ||
	    (rc = parser_non_negative(p, "diffuse coefficient", &m->kd)) < 0 ||
	    (rc = parser_non_negative(p, "specular coefficient", &m->ks)) < 0 ||
	    (rc = parser_non_negative(p, "reflection coefficient", &m->kr)) < 0 ||
	    (rc = parser_non_negative(p, "shininess", &m->shininess)) < 0)
		return rc;
	return 0;
}

