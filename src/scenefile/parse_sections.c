/* The sections every dialect's grammar shares: the recursion level and
 * image size, the objects (in several threads for a big file, parse_parts.c),
 * the counts and the numbers ahead of them, and the end of the data. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "base/alloc.h"
#include "base/hash.h"
#include "scenefile/parse_private.h"
#include "shapes/registry.h"
#include "whitted/scenefile.h"

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
