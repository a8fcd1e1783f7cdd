/* The scene.txt parser: the structure of scene-format.md (settings, objects,
 * lights, trailing text) and the reading primitives the shape parsers share.
 * It stops at the first error with a located diagnostic and never prints;
 * notes go to the caller's callback. */
#include <ctype.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "alloc.h"
#include "hash.h"
#include "lexer.h"
#include "parse.h"
#include "parse_private.h"
#include "scene.h"
#include "shape.h"

/* Quotes a token for a message: at most 40 bytes, unprintable bytes escaped. */
static void token_describe(const struct token *t, char *buf, size_t size)
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

static void parser_note(struct parser *p, int line, const char *fmt, ...)
#if defined(__GNUC__)
	__attribute__((format(printf, 3, 4)))
#endif
	;

static void parser_note(struct parser *p, int line, const char *fmt, ...)
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

static struct token parser_next(struct parser *p)
{
	p->last = lexer_next(&p->lx);
	return p->last;
}

/* The error for a token that should have been a number. */
static int parser_not_a_number(struct parser *p, const char *expected, const char *what)
{
	char found[64];

	token_describe(&p->last, found, sizeof(found));
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
static int parser_int(struct parser *p, const char *what, long lo, long hi, long *out)
{
	double v;

	parser_next(p);
	if (!lexer_number(&p->last, &v))
		return parser_not_a_number(p, "an integer", what);
	if (v != floor(v)) {
		char found[64];
		token_describe(&p->last, found, sizeof(found));
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

int parser_vec3(struct parser *p, const char *what, struct vec3 *out)
{
	int rc;

	if ((rc = parser_number(p, what, &out->x)) < 0 ||
	    (rc = parser_number(p, what, &out->y)) < 0 ||
	    (rc = parser_number(p, what, &out->z)) < 0)
		return rc;
	return 0;
}

static int parser_unit_interval(struct parser *p, const char *what, double *out)
{
	int rc = parser_number(p, what, out);

	if (rc < 0)
		return rc;
	if (*out < 0.0 || *out > 1.0)
		return parser_fail(p, RT_E_RANGE, "%s must be in [0, 1], found %g", what, *out);
	return 0;
}

int parser_color(struct parser *p, const char *what, struct color *out)
{
	int rc;

	if ((rc = parser_unit_interval(p, what, &out->r)) < 0 ||
	    (rc = parser_unit_interval(p, what, &out->g)) < 0 ||
	    (rc = parser_unit_interval(p, what, &out->b)) < 0)
		return rc;
	return 0;
}

static int parser_non_negative(struct parser *p, const char *what, double *out)
{
	int rc = parser_number(p, what, out);

	if (rc < 0)
		return rc;
	if (*out < 0.0)
		return parser_fail(p, RT_E_RANGE, "%s must be >= 0, found %g", what, *out);
	return 0;
}

int parser_material(struct parser *p, struct material *m)
{
	int rc;

	if ((rc = parser_color(p, "colour component", &m->color)) < 0 ||
	    (rc = parser_non_negative(p, "ambient coefficient", &m->ka)) < 0 ||
	    (rc = parser_non_negative(p, "diffuse coefficient", &m->kd)) < 0 ||
	    (rc = parser_non_negative(p, "specular coefficient", &m->ks)) < 0 ||
	    (rc = parser_non_negative(p, "reflection coefficient", &m->kr)) < 0 ||
	    (rc = parser_non_negative(p, "shininess", &m->shininess)) < 0)
		return rc;
	return 0;
}

int parse_shape(struct parser *p, struct shape **out, int *line, long index, long count)
{
	const struct shape_ops *ops;
	struct token kw = parser_next(p);
	char found[64];

	*out = NULL;
	*line = kw.line;
	if (!kw.text)
		return parser_fail(p, RT_E_SYNTAX,
				   "expected an object keyword (%s) for object %ld of %ld, found end of file",
				   shape_keywords(), index, count);
	ops = shape_ops_find(kw.text, kw.len);
	if (!ops) {
		token_describe(&kw, found, sizeof(found));
		if (lexer_looks_numeric(&kw))
			return parser_fail(p, RT_E_SYNTAX,
					   "expected an object keyword (%s) for object %ld of %ld, found %s "
					   "(does the object count match the objects, and each object its format?)",
					   shape_keywords(), index, count, found);
		return parser_fail(p, RT_E_SYNTAX, "unknown object %s; known objects: %s",
				   found, shape_keywords());
	}
	return ops->parse(p, out);
}

void parser_note_degenerate(struct parser *p, const struct shape *sh, int line, long index)
{
	const char *why = shape_degenerate(sh);

	if (why && p->notes_sent < PARSE_MAX_NOTES) {
		p->notes_sent++;
		parser_note(p, line, "%s (object %ld) %s", sh->ops->keyword, index, why);
	} else if (why) {
		p->notes_dropped++;
	}
}

static int parse_object(struct parser *p, struct scene *s, long index, long count)
{
	struct shape *sh;
	int line, rc = parse_shape(p, &sh, &line, index, count);

	if (rc < 0)
		return rc;
	parser_note_degenerate(p, sh, line, index);
	return scene_add_shape(s, sh, p->d);
}

/* Counts the number tokens that follow, up to `limit`, without consuming
 * them: this decides between lights with and without colours. */
static long parser_count_numbers(const struct parser *p, long limit)
{
	struct lexer ahead = p->lx;
	long n = 0;

	while (n < limit) {
		struct token t = lexer_next(&ahead);
		if (!t.text || !lexer_looks_numeric(&t))
			break;
		n++;
	}
	return n;
}

/* Adds to a light's error, when the numbers after the light count fit
 * neither 6 nor 3 per light, how many there are: the count is the likely
 * culprit. */
static int parser_light_count_hint(struct parser *p, int rc, long count, long available)
{
	size_t n;

	if (!p->d)
		return rc;
	n = strlen(p->d->msg);
	if (available < 6 * count && available != 3 * count)
		snprintf(p->d->msg + n, sizeof(p->d->msg) - n,
			 " (%ld light%s %ld numbers, or %ld without colours, and %ld follow the light count)",
			 count, count == 1 ? " needs" : "s need", 6 * count, 3 * count, available);
	return rc;
}

static int parse_lights(struct parser *p, struct scene *s, long count)
{
	long available = parser_count_numbers(p, 6 * count);
	bool positions_only = count > 0 && available == 3 * count;
	long i;
	int rc;

	for (i = 0; i < count; i++) {
		struct vec3 pos;
		struct color color = { 1.0, 1.0, 1.0 };
		if ((rc = parser_vec3(p, "light position", &pos)) < 0 ||
		    (!positions_only && (rc = parser_color(p, "light colour component", &color)) < 0))
			return parser_light_count_hint(p, rc, count, available);
		if ((rc = scene_add_light(s, pos, color, p->d)) < 0)
			return rc;
	}
	return 0;
}

/* Notes the text after the last light, if there is any. */
static void parse_trailing(struct parser *p)
{
	struct token t = lexer_next(&p->lx);
	const char *c;
	int last_line;

	if (!t.text)
		return;
	last_line = t.line;
	for (c = t.text; c < p->text + p->len; c++)
		if (*c == '\n' && c + 1 < p->text + p->len)
			last_line++;
	parser_note(p, t.line, "ignoring %d line%s after the last light",
		    last_line - t.line + 1, last_line > t.line ? "s" : "");
}

static int parse_scene(struct parser *p, struct scene *s, int threads)
{
	struct lexer ahead = p->lx;
	struct token first = lexer_next(&ahead);
	struct parse_parts *parts;
	long recursion, size, objects, lights, i;
	int rc;

	if (!first.text)
		return diag_set(p->d, RT_E_SYNTAX, p->name, first.line, first.col,
				"expected an integer (recursion level), found end of file (%s)",
				p->len > 0 ? "the file has no data, only space and comments"
					   : "the file is empty");
	if ((rc = parser_int(p, "recursion level", 1, RT_MAX_RECURSION, &recursion)) < 0 ||
	    (rc = parser_int(p, "image size", 1, RT_MAX_IMAGE_SIZE, &size)) < 0)
		return rc;
	if (size * size > RT_MAX_PIXELS)
		return parser_fail(p, RT_E_RANGE, "image size %ld gives more than %ld pixels",
				   size, RT_MAX_PIXELS);
	s->recursion = (int)recursion;
	s->image_size = (int)size;
	if ((rc = parser_int(p, "object count", 0, RT_MAX_OBJECTS, &objects)) < 0)
		return rc;
	parts = objects > 0 ? parse_parts_start(p, threads) : NULL;
	for (i = 1; i <= objects; i++) {
		long taken = parts ? parse_parts_take(parts, p, s, i, objects - i + 1) : 0;
		if (taken < 0) {
			parse_parts_finish(parts);
			return (int)taken;
		}
		if (taken > 0) {
			i += taken - 1;
			continue;
		}
		if ((rc = parse_object(p, s, i, objects)) < 0) {
			parse_parts_finish(parts);
			return rc;
		}
	}
	parse_parts_finish(parts);
	if (p->notes_dropped > 0)
		parser_note(p, 0, "%d more notes not shown", p->notes_dropped);
	rc = parser_int(p, "light count", 0, RT_MAX_LIGHTS, &lights);
	if (rc < 0) {
		if (p->last.text && shape_ops_find(p->last.text, p->last.len))
			return parser_fail(p, RT_E_SYNTAX,
					   "expected the light count, found the object keyword '%s' "
					   "(there are more objects than the object count of %ld)",
					   shape_ops_find(p->last.text, p->last.len)->keyword, objects);
		return rc;
	}
	if ((rc = parse_lights(p, s, lights)) < 0)
		return rc;
	parse_trailing(p);
	return 0;
}

int scene_parse(const char *name, const char *text, size_t len,
		const struct scene_read_options *opt, scene_note_fn *note, void *note_ctx,
		struct scene **out, struct diag *d)
{
	struct parser p;
	struct scene *s;
	struct hash_job hash;
	int rc;

	*out = NULL;
	if (len >= 3 && memcmp(text, "\xef\xbb\xbf", 3) == 0)
		return diag_set(d, RT_E_SYNTAX, name, 1, 1,
				"the file starts with a UTF-8 byte order mark; save it as plain text without one");
	memset(&p, 0, sizeof(p));
	lexer_init(&p.lx, text, len);
	p.name = name;
	p.text = text;
	p.len = len;
	p.d = d;
	p.note = note;
	p.note_ctx = note_ctx;
	s = scene_create(name);
	if (!s)
		return diag_set(d, RT_E_NOMEM, name, 0, 0, "out of memory");
	if (opt && opt->hash)
		hash_start(&hash, text, len);
	rc = parse_scene(&p, s, opt && opt->threads > 1 ? opt->threads : 1);
	if (opt && opt->hash)
		s->source_hash = hash_finish(&hash);
	if (rc < 0) {
		scene_destroy(s);
		return rc;
	}
	*out = s;
	return 0;
}
