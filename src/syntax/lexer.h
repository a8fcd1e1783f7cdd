/* Tokens of a scene file held in memory: whitespace-separated words, with
 * '#', '//' and a lone '-' starting comments that run to the end of line. */
#ifndef RT_LEXER_H
#define RT_LEXER_H

#include <stdbool.h>
#include <stddef.h>

#define RT_TOKEN_MAX 256	/* longest token accepted, in bytes */

struct token {
	const char *text;	/* not NUL-terminated; NULL at end of file */
	size_t len;
	int line, col;		/* 1-based position of the first byte */
};

struct lexer {
	const char *pos, *end;
	int line;
	const char *line_start;	/* the first byte of the current line */
};

void lexer_init(struct lexer *lx, const char *text, size_t len);
/* A lexer over the same text that starts at `start`, the first byte of
 * line `line` (for a reader that takes up the text in the middle). */
void lexer_init_at(struct lexer *lx, const char *text, size_t len, const char *start, int line);
/* How far into text (the text given to lexer_init) the lexer has read. */
size_t lexer_offset(const struct lexer *lx, const char *text);
/* The next token, or one with text NULL (and the end's position) at EOF. */
struct token lexer_next(struct lexer *lx);
/* The common case of reading a number, in one pass: when the next token
 * is [+-]digits[.digits] with at most 15 digits and no comment comes
 * before it, reads it into *t and its value into *out, exactly as
 * lexer_next and lexer_number would, and returns true; otherwise returns
 * false and leaves the lexer as it was. */
bool lexer_next_simple_number(struct lexer *lx, struct token *t, double *out);
/* Parses a whole token as a finite decimal real, as strtod reads it but
 * without nan, inf or hex.  Returns false when it is not one. */
bool lexer_number(const struct token *t, double *out);
/* True when strtod would read the whole token (nan, inf and hex included):
 * the token is meant as a number even if it is not an acceptable one. */
bool lexer_looks_numeric(const struct token *t);

#endif
