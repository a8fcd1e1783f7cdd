/* Splits scene text into tokens.  Tokens are maximal runs of non-space
 * bytes; '#' and '//' start a comment anywhere, and a token that is exactly
 * '-' starts one too (the annotated style: "10.0	- radius"). */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "lexer.h"

void lexer_init(struct lexer *lx, const char *text, size_t len)
{
	lx->pos = text;
	lx->end = text + len;
	lx->line = 1;
	lx->col = 1;
}

static bool lexer_is_space(char c)
{
	return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}

static void lexer_advance(struct lexer *lx)
{
	if (*lx->pos == '\n') {
		lx->line++;
		lx->col = 1;
	} else {
		lx->col++;
	}
	lx->pos++;
}

static void lexer_skip_line(struct lexer *lx)
{
	while (lx->pos < lx->end && *lx->pos != '\n')
		lexer_advance(lx);
}

static bool lexer_at_comment(const struct lexer *lx)
{
	return *lx->pos == '#' ||
	       (*lx->pos == '/' && lx->pos + 1 < lx->end && lx->pos[1] == '/');
}

struct token lexer_next(struct lexer *lx)
{
	struct token t;

	for (;;) {
		while (lx->pos < lx->end && lexer_is_space(*lx->pos))
			lexer_advance(lx);
		if (lx->pos < lx->end && lexer_at_comment(lx)) {
			lexer_skip_line(lx);
			continue;
		}
		t.text = lx->pos < lx->end ? lx->pos : NULL;
		t.line = lx->line;
		t.col = lx->col;
		t.len = 0;
		while (lx->pos < lx->end && !lexer_is_space(*lx->pos) && !lexer_at_comment(lx)) {
			lexer_advance(lx);
			t.len++;
		}
		if (t.len == 1 && t.text[0] == '-') {
			lexer_skip_line(lx);
			continue;
		}
		return t;
	}
}

/* Copies the token into buf as a C string; false when it does not fit or
 * holds a NUL byte (strtod would stop there: "1\0" "6" must not read as 1). */
static bool token_copy(const struct token *t, char *buf, size_t size)
{
	if (!t->text || t->len == 0 || t->len >= size || memchr(t->text, '\0', t->len))
		return false;
	memcpy(buf, t->text, t->len);
	buf[t->len] = '\0';
	return true;
}

bool lexer_number(const struct token *t, double *out)
{
	char buf[RT_TOKEN_MAX + 1];
	char *end;
	double v;

	if (!token_copy(t, buf, sizeof(buf)))
		return false;
	/* Decimal reals only: this rules out nan, inf and hex floats. */
	if (buf[strspn(buf, "0123456789+-.eE")] != '\0')
		return false;
	errno = 0;
	v = strtod(buf, &end);
	if (end == buf || *end != '\0' || !isfinite(v))
		return false;
	*out = v;
	return true;
}

bool lexer_looks_numeric(const struct token *t)
{
	char buf[RT_TOKEN_MAX + 1];
	char *end;

	if (!token_copy(t, buf, sizeof(buf)))
		return false;
	(void)strtod(buf, &end);
	return end != buf && *end == '\0';
}
