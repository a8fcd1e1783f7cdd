/* One object of any dialect through the shape registry: its keyword found
 * (with a hint for a keyword from another table), its numbers read by the
 * shape's own parser, and the note for a degenerate one. */
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
