/* Reading scene text: the byte order mark and the choice of dialect
 * (scene-format.md, "The dialects").  The grammars are parse_classic.c
 * (classic, spot, pyramid) and parse_nearfar.c, over the sections they
 * share (parse_sections.c) and one object (parse_shape.c).  It stops at
 * the first error with a located diagnostic and never prints; notes go to
 * the caller's callback. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "base/alloc.h"
#include "base/hash.h"
#include "scenefile/parse_private.h"
#include "shapes/registry.h"
#include "whitted/scenefile.h"

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
