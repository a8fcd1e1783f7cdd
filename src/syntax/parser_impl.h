/* The parser's state, for the scene-file reader (src/scenefile) that drives
 * it; shapes see only the services of whitted/parser.h. */
#ifndef RT_PARSER_IMPL_H
#define RT_PARSER_IMPL_H

#include <stddef.h>

#include "syntax/lexer.h"
#include "whitted/diag.h"
#include "whitted/parser.h"

/* An object keyword the parser looked up lately (its table's own), with
 * the dialects it was looked up in. */
struct parser_ops_memo {
	const struct shape_ops *ops;	/* NULL: an empty entry */
	unsigned dialects;
};

/* How many object keywords a parser remembers: a file names a few
 * kinds, object after object. */
#define PARSER_OPS_MEMO 4

struct parser {
	struct lexer lx;
	struct token last;		/* the token most recently read */
	const char *name;
	const char *text;
	size_t len;
	struct diag *d;
	diag_note_fn *note;		/* NULL: no notes */
	void *note_ctx;
	int notes_sent, notes_dropped;	/* the notes about shapes, capped */
	unsigned dialects;		/* object keywords of these dialects (0: any) */
	const char *dialect_name;	/* the dialect being read, for messages */
	bool lenient;			/* scene_read_options' lenient */
	/* The tables of the keywords met lately (zeroed with the parser):
	 * so that each object of a big file does not take the registry's
	 * lock, which the threads reading its parts contended for (pthread
	 * calls were 6% of gen-1M's run); see parse_find_ops. */
	struct parser_ops_memo ops_memo[PARSER_OPS_MEMO];
	unsigned ops_memo_next;
};

/* Reads the next token into p->last. */
struct token parser_next(struct parser *p);
/* An integer in [lo, hi]; integral reals such as "4.0" are accepted. */
int parser_int(struct parser *p, const char *what, long lo, long hi, long *out);
/* A number >= 0, and one > 0. */
int parser_non_negative(struct parser *p, const char *what, double *out);
int parser_positive(struct parser *p, const char *what, double *out);
/* A size (radius, side, height): > 0, and small enough (<= 1e150) that
 * the points made from it stay finite. */
int parser_size(struct parser *p, const char *what, double *out);
/* A note at line (0: none) of the file, when the caller asked for notes. */
void parser_note(struct parser *p, int line, const char *fmt, ...)
#if defined(__GNUC__)
	__attribute__((format(printf, 3, 4)))
#endif
	;
/* Quotes a token for a message: at most 40 bytes, unprintable bytes escaped. */
void parser_describe_token(const struct token *t, char *buf, size_t size);

#endif
