/* Reading scene text: the byte order mark, the choice of dialect
 * (scene-format.md, "The dialects"), and the pieces every dialect's grammar
 * shares (objects through the registry, counts of the numbers ahead, the
 * end of the data).  The grammars themselves are parse_classic.c (classic,
 * spot, pyramid) and parse_nearfar.c.  It stops at the first error with a
 * located diagnostic and never prints; notes go to the caller's callback. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "base/alloc.h"
#include "base/hash.h"
#include "scenefile/parse_private.h"
#include "shapes/registry.h"
#include "whitted/scenefile.h"

const struct shape_ops *parse_find_ops(struct parser *p, const char *text, size_t len,
				       unsigned dialects)
{
	struct parser_ops_memo *m;
	const struct shape_ops *ops;
	size_t i;

	for (i = 0; i < PARSER_OPS_MEMO; i++) {
		m = &p->ops_memo[i];
		/* The registry's own test (registry_is): the keyword, exactly. */
		if (m->ops && m->dialects == dialects && strlen(m->ops->keyword) == len &&
		    memcmp(m->ops->keyword, text, len) == 0)
			return m->ops;
	}
	ops = shape_ops_find_in(text, len, dialects);
	if (ops) {
		m = &p->ops_memo[p->ops_memo_next++ % PARSER_OPS_MEMO];
		m->ops = ops;
		m->dialects = dialects;
	}
	return ops;
}

/* Who made a table, for the messages about its parse: "the plugin
 * FILE" or "whitted (built in)". */
static void parse_table_origin(const struct shape_ops *ops, char *buf, size_t size)
{
	const char *origin = shape_registry_origin(ops);

	if (origin)
		snprintf(buf, size, "the plugin %s", origin);
	else
		snprintf(buf, size, "whitted (built in)");
}

/* ops->parse, its answer checked: a plugin's parse that returns a
 * positive number, 0 without a shape or a shape of another table, or
 * fails without a message, is the plugin's error, located at the
 * object's keyword kw.  Never a crash, and the status is one of a
 * parse's (RT_E_SYNTAX, RT_E_RANGE, RT_E_NOMEM). */
static int parse_shape_checked(struct parser *p, const struct shape_ops *ops,
			       const struct token *kw, struct shape **out)
{
	char who[RT_DIAG_FILE_MAX + 32];
	int rc;

	/* Only the message, which tells whether the parse gave one: the whole
	 * record is 4.6 KB, and a big file has millions of objects. */
	if (p->d)
		p->d->msg[0] = '\0';
	rc = ops->parse(p, out);
	if (rc < 0) {
		*out = NULL;
		if (rc != -RT_E_SYNTAX && rc != -RT_E_RANGE && rc != -RT_E_NOMEM)
			rc = -RT_E_SYNTAX;
		if (!p->d || p->d->msg[0])
			return rc;
		parse_table_origin(ops, who, sizeof(who));
		return diag_set(p->d, (enum rt_err)-rc, p->name, kw->line, kw->col,
				"object '%s' of %s: its parse failed without a message "
				"(it returned an error without calling host->fail)",
				ops->keyword, who);
	}
	if (rc == 0 && *out && (*out)->ops == ops)
		return 0;
	parse_table_origin(ops, who, sizeof(who));
	if (rc > 0) {
		*out = NULL;
		return diag_set(p->d, RT_E_SYNTAX, p->name, kw->line, kw->col,
				"object '%s' of %s: its parse returned %d, which is neither 0 "
				"(a shape) nor a negative error", ops->keyword, who, rc);
	}
	if (!*out)
		return diag_set(p->d, RT_E_SYNTAX, p->name, kw->line, kw->col,
				"object '%s' of %s: its parse returned 0 (success) without a shape",
				ops->keyword, who);
	/* Made by this parse, so its table's destroy is the one to free it. */
	ops->destroy(*out);
	*out = NULL;
	return diag_set(p->d, RT_E_SYNTAX, p->name, kw->line, kw->col,
			"object '%s' of %s: its parse returned a shape whose table is not "
			"'%s''s own", ops->keyword, who, ops->keyword);
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
				   shape_keywords_in(p->dialects), index, count);
	ops = parse_find_ops(p, kw.text, kw.len, p->dialects);
	if (!ops) {
		parser_describe_token(&kw, found, sizeof(found));
		if (lexer_looks_numeric(&kw))
			return parser_fail(p, RT_E_SYNTAX,
					   "expected an object keyword (%s) for object %ld of %ld, found %s "
					   "(does the object count match the objects, and each object its format? "
					   "A fifth coefficient or an extra line in an object shows this way)",
					   shape_keywords_in(p->dialects), index, count, found);
		if (shape_ops_find(kw.text, kw.len))
			return parser_fail(p, RT_E_SYNTAX,
					   "unknown object %s in the %s dialect; known objects: %s",
					   found, p->dialect_name,
					   shape_keywords_in(p->dialects));
		return parser_fail(p, RT_E_SYNTAX,
				   "unknown object %s; known objects: %s (not part of the course "
				   "format: a student extension needs a plugin that provides it)",
				   found, shape_keywords_in(p->dialects));
	}
	return parse_shape_checked(p, ops, &kw, out);
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
	if ((rc = scene_add_shape(s, sh, p->d)) < 0)
		return rc;
	return scene_set_shape_line(s, scene_shape_count(s) - 1, line, p->d);
}

long parse_count_numbers(const struct parser *p, long limit)
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

int parse_light_count_hint(struct parser *p, int rc, long count, long available)
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

bool parse_number_ahead(const struct parser *p, long k, double *out)
{
	struct lexer ahead = p->lx;
	long n;

	for (n = 0; n <= k; n++) {
		struct token t = lexer_next(&ahead);
		if (!t.text || !lexer_number(&t, out))
			return false;
	}
	return true;
}

int parse_recursion(struct parser *p, struct scene *s)
{
	long recursion;
	int rc = parser_int(p, "recursion level", 0, RT_MAX_RECURSION, &recursion);

	if (rc < 0)
		return rc;
	if (recursion == 0) {
		parser_note(p, p->last.line, "recursion level 0 read as 1 (no reflection rays)");
		recursion = 1;
	}
	return scene_set_recursion(s, recursion, p->d);
}

int parse_image_size(struct parser *p, struct scene *s)
{
	long size;
	int rc = parser_int(p, "image size", 1, RT_MAX_IMAGE_SIZE, &size);

	if (rc < 0)
		return rc;
	if (size * size > RT_MAX_PIXELS)
		return parser_fail(p, RT_E_RANGE, "image size %ld gives more than %ld pixels",
				   size, RT_MAX_PIXELS);
	return scene_set_image_size(s, size, p->d);
}

int parse_objects(struct parser *p, struct scene *s, int threads, long *count)
{
	struct parse_parts *parts;
	long objects, i;
	int rc;

	if ((rc = parser_int(p, "object count", 0, RT_MAX_OBJECTS, &objects)) < 0)
		return rc;
	*count = objects;
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
	return 0;
}

int parse_count(struct parser *p, const char *what, long max, long objects, long *out)
{
	int rc = parser_int(p, what, 0, max, out);
	const struct shape_ops *ops;

	if (rc < 0 && p->last.text && (ops = shape_ops_find(p->last.text, p->last.len)) != NULL)
		return parser_fail(p, RT_E_SYNTAX,
				   "expected the %s, found the object keyword '%s' "
				   "(there are more objects than the object count of %ld)",
				   what, ops->keyword, objects);
	return rc;
}

int parse_end(struct parser *p, const char *section)
{
	struct lexer ahead = p->lx;
	struct token t = lexer_next(&ahead);
	const char *c;
	int last_line;

	if (!t.text)
		return 0;
	if (lexer_looks_numeric(&t) && p->lenient) {
		long more = parse_count_numbers(p, RT_MAX_LIGHTS * 16L);
		parser_note(p, t.line, "ignoring %ld number%s from line %d on: no count describes "
			    "them (--lenient: read as a program that stops after the %s does)",
			    more, more == 1 ? "" : "s", t.line, section);
		return 0;
	}
	if (lexer_looks_numeric(&t)) {
		long more = parse_count_numbers(p, RT_MAX_LIGHTS * 16L);
		char found[64];

		parser_next(p);
		parser_describe_token(&t, found, sizeof(found));
		return parser_fail(p, RT_E_SYNTAX,
				   "expected the end of the data after the %s, found the number %s "
				   "(%ld number%s: a count does not describe the data, e.g. a "
				   "section deleted without its count)",
				   section, found, more, more == 1 ? " follows" : "s follow");
	}
	last_line = t.line;
	for (c = t.text; c < p->text + p->len; c++)
		if (*c == '\n' && c + 1 < p->text + p->len)
			last_line++;
	parser_note(p, t.line, "ignoring %d line%s after the %s", last_line - t.line + 1,
		    last_line > t.line ? "s" : "", section);
	return 0;
}

/* Whether the header of the nearfar dialect starts the text: 11 numbers
 * before the first word (scene-format.md, "The dialects", rule 1), nan and
 * inf counted as numbers.  Their third must not be 0: in classic's layout that is an object count of 0
 * (the only way a classic file has no word that soon: "4 64 0 1 ... 0
 * explanation" is a spot file), and nearfar's FOVY cannot be 0. */
static bool parse_looks_nearfar(const struct parser *p)
{
	struct lexer ahead = p->lx;
	long n = 0;
	struct token t;
	double third;

	/* Only a finite 0 rules it out: a header with nan or inf in it is
	 * still nearfar's, whose parser then names the field. */
	if (parse_number_ahead(p, 2, &third) && third == 0.0)
		return false;
	for (;;) {
		t = lexer_next(&ahead);
		if (!t.text || !lexer_looks_numeric(&t))
			break;
		n++;
	}
	if (t.text)
		return n == 11;
	/* No word at all: the nearfar header with no objects, if the lights
	 * after it fit. */
	return n >= 13 && parse_nearfar_fits_without_objects(p, n);
}

static void parse_note_dialect(struct parser *p, const struct scene *s, bool forced)
{
	size_t i, points = 0, spots = 0;

	for (i = 0; i < scene_light_count(s); i++) {
		if (scene_light(s, i)->spot)
			spots++;
		else
			points++;
	}
	if (spots > 0 || strcmp(p->dialect_name, "spot") == 0 ||
	    strcmp(p->dialect_name, "nearfar") == 0)
		parser_note(p, 0, "read as the %s dialect%s (%zu point light%s, %zu spotlight%s)",
			    p->dialect_name, forced ? ", as asked" : "",
			    points, points == 1 ? "" : "s", spots, spots == 1 ? "" : "s");
	else
		parser_note(p, 0, "read as the %s dialect%s (%zu point light%s)",
			    p->dialect_name, forced ? ", as asked" : "",
			    points, points == 1 ? "" : "s");
}

static int parse_scene(struct parser *p, struct scene *s, int threads, enum scene_dialect forced)
{
	struct lexer ahead = p->lx;
	struct token first = lexer_next(&ahead);
	int rc;

	if (!first.text)
		return diag_set(p->d, RT_E_SYNTAX, p->name, first.line, first.col,
				"expected an integer (recursion level), found end of file (%s)",
				p->len > 0 ? "the file has no data, only space and comments"
					   : "the file is empty");
	if (forced == RT_DIALECT_NEARFAR || (forced == RT_DIALECT_AUTO && parse_looks_nearfar(p)))
		rc = parse_nearfar(p, s, threads);
	else
		rc = parse_classic(p, s, threads, forced);
	if (rc == 0)
		parse_note_dialect(p, s, forced != RT_DIALECT_AUTO);
	return rc;
}

/* After a forced dialect's error: what auto-detection reads the text as,
 * added to the message when it reads it whole as another dialect (a spot
 * file read with --dialect classic fails on its spotlights, which the
 * auto-detected spot dialect reads). */
static void parse_say_auto(const char *name, const char *text, size_t len,
			   const struct scene_read_options *opt, struct diag *d)
{
	struct scene_read_options o = *opt;
	struct scene *s = NULL;
	struct diag scratch;
	enum scene_dialect found;
	size_t n;

	if (!d)
		return;
	o.dialect = RT_DIALECT_AUTO;
	o.hash = false;
	if (scene_parse(name, text, len, &o, NULL, NULL, &s, &scratch) < 0)
		return;
	found = scene_view_of(s)->dialect;
	scene_destroy(s);
	if (found == opt->dialect)
		return;
	n = strlen(d->msg);
	snprintf(d->msg + n, sizeof(d->msg) - n,
		 "; auto-detection (no --dialect %s) reads it without error as the %s dialect",
		 scene_dialect_name(opt->dialect), scene_dialect_name(found));
}

int scene_parse(const char *name, const char *text, size_t len,
		const struct scene_read_options *opt, diag_note_fn *note, void *note_ctx,
		struct scene **out, struct diag *d)
{
	struct parser p;
	struct scene *s;
	struct hash_job hash;
	bool bom = len >= 3 && memcmp(text, "\xef\xbb\xbf", 3) == 0;
	int rc;

	*out = NULL;
	memset(&p, 0, sizeof(p));
	/* Columns are counted after the mark, as an editor shows them. */
	lexer_init_at(&p.lx, text, len, bom ? text + 3 : text, 1);
	p.name = name;
	p.text = text;
	p.len = len;
	p.d = d;
	p.note = note;
	p.note_ctx = note_ctx;
	p.lenient = opt && opt->lenient;
	if (bom)
		parser_note(&p, 1, "skipped the UTF-8 byte order mark at the start of the file");
	s = scene_create(name);
	if (!s)
		return diag_set(d, RT_E_NOMEM, name, 0, 0, "out of memory");
	if (opt && opt->hash)
		hash_start(&hash, text, len);
	rc = parse_scene(&p, s, opt && opt->threads > 1 ? opt->threads : 1,
			 opt ? opt->dialect : RT_DIALECT_AUTO);
	if (opt && opt->hash)
		scene_set_source_hash(s, hash_finish(&hash));
	if (rc < 0) {
		scene_destroy(s);
		if (opt && opt->dialect != RT_DIALECT_AUTO)
			parse_say_auto(name, text, len, opt, d);
		return rc;
	}
	*out = s;
	return 0;
}
