/* Splits scene text into tokens.  Tokens are maximal runs of non-space
 * bytes; '#' and '//' start a comment anywhere, and a token that is exactly
 * '-' starts one too (the annotated style: "10.0	- radius"). */
#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "syntax/lexer.h"

void lexer_init(struct lexer *lx, const char *text, size_t len)
{
	lx->pos = text;
	lx->end = text + len;
	lx->line = 1;
	lx->line_start = text;
}

void lexer_init_at(struct lexer *lx, const char *text, size_t len, const char *start, int line)
{
	lexer_init(lx, text, len);
	lx->pos = start;
	lx->line = line;
	lx->line_start = start;
}

size_t lexer_offset(const struct lexer *lx, const char *text)
{
	return (size_t)(lx->pos - text);
}

/* What each byte can be, for the loop that reads every byte of a
 * million-object file: a table look-up instead of up to eight compares. */
enum {
	LX_SPACE = 1,		/* ' ' \t \n \r \v \f */
	LX_NEWLINE = 2,
	LX_COMMENT = 4,		/* '#', or '/' which starts one when doubled */
};

static const unsigned char lexer_class[256] = {
	['\t'] = LX_SPACE, ['\n'] = LX_SPACE | LX_NEWLINE, ['\v'] = LX_SPACE,
	['\f'] = LX_SPACE, ['\r'] = LX_SPACE, [' '] = LX_SPACE,
	['#'] = LX_COMMENT, ['/'] = LX_COMMENT,
};

static inline unsigned lexer_class_of(char c)
{
	return lexer_class[(unsigned char)c];
}

static inline bool lexer_at_comment(const char *p, const char *end)
{
	return *p == '#' || (*p == '/' && p + 1 < end && p[1] == '/');
}

/* Columns are counted from the line's start when a token is found rather
 * than byte by byte. */
struct token lexer_next(struct lexer *lx)
{
	const char *p = lx->pos, *end = lx->end;
	struct token t;

	for (;;) {
		unsigned cls;
		while (p < end && ((cls = lexer_class_of(*p)) & LX_SPACE)) {
			if (cls & LX_NEWLINE) {
				lx->line++;
				lx->line_start = p + 1;
			}
			p++;
		}
		if (p < end && lexer_at_comment(p, end)) {
			while (p < end && *p != '\n')
				p++;
			continue;
		}
		t.text = p < end ? p : NULL;
		t.line = lx->line;
		t.col = (int)(p - lx->line_start) + 1;
		while (p < end && (!((cls = lexer_class_of(*p)) & (LX_SPACE | LX_COMMENT)) ||
				   (cls == LX_COMMENT && !lexer_at_comment(p, end))))
			p++;
		t.len = t.text ? (size_t)(p - t.text) : 0;
		if (t.len == 1 && t.text[0] == '-') {
			while (p < end && *p != '\n')
				p++;
			continue;
		}
		lx->pos = p;
		return t;
	}
}

/* The common case, [+-]digits[.digits] with at most 15 digits, without
 * strtod (which was half of the parse time): the digits make an integer
 * m < 10^15 < 2^53 and the k fraction digits a power 10^k <= 10^15, both
 * exact in a double, so the one rounding of m / 10^k gives the correctly
 * rounded value, which is what strtod returns.  Reads from c as far as
 * that form goes and returns where it stopped, or NULL when what it read
 * is not that case (no digit, or too many). */
static const char *lexer_scan_decimal(const char *c, const char *end, double *out)
{
	static const double pow10[16] = {
		1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7,
		1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
	};
	bool negative = false, point = false;
	int64_t m = 0;
	int digits = 0, fraction = 0;
	double v;

	if (c < end && (*c == '-' || *c == '+'))
		negative = *c++ == '-';
	for (; c < end; c++) {
		if (*c >= '0' && *c <= '9') {
			if (++digits > 15)
				return NULL;
			m = m * 10 + (*c - '0');
			fraction += point;
		} else if (*c == '.' && !point) {
			point = true;
		} else {
			break;
		}
	}
	if (digits == 0)
		return NULL;
	v = (double)m / pow10[fraction];
	*out = negative ? -v : v;
	return c;
}

bool lexer_next_simple_number(struct lexer *lx, struct token *t, double *out)
{
	const char *p = lx->pos, *end = lx->end, *start, *line_start = lx->line_start;
	int line = lx->line;
	unsigned cls = 0;
	double v;

	while (p < end && ((cls = lexer_class_of(*p)) & LX_SPACE)) {
		if (cls & LX_NEWLINE) {
			line++;
			line_start = p + 1;
		}
		p++;
	}
	start = p;
	p = lexer_scan_decimal(start, end, &v);
	/* The token must end where the number does, as lexer_next would end
	 * it: at a space, a comment or the end.  Anything else (an exponent,
	 * a letter, a second point, a NUL) is for the general path. */
	if (!p || (p < end && !(lexer_class_of(*p) & LX_SPACE) && !lexer_at_comment(p, end)))
		return false;
	*out = v;
	t->text = start;
	t->len = (size_t)(p - start);
	t->line = line;
	t->col = (int)(start - line_start) + 1;
	lx->pos = p;
	lx->line = line;
	lx->line_start = line_start;
	return true;
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

/* The whole token in the common form (see lexer_scan_decimal). */
static bool lexer_simple_number(const struct token *t, double *out)
{
	double v;

	if (lexer_scan_decimal(t->text, t->text + t->len, &v) != t->text + t->len)
		return false;
	*out = v;
	return true;
}

bool lexer_number(const struct token *t, double *out)
{
	char buf[RT_TOKEN_MAX + 1];
	char *end;
	double v;

	if (!t->text)
		return false;
	if (lexer_simple_number(t, out))
		return true;
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
