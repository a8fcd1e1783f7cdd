/* The parser's state and the steps that parse.c shares with
 * parse_parts.c (which reads the objects of a big file in several
 * threads); private to the two. */
#ifndef RT_PARSE_PRIVATE_H
#define RT_PARSE_PRIVATE_H

#include <stddef.h>

#include "diag.h"
#include "lexer.h"
#include "scene.h"
#include "shape.h"

#define PARSE_MAX_NOTES 20

struct parser {
	struct lexer lx;
	struct token last;		/* the token most recently read */
	const char *name;
	const char *text;
	size_t len;
	struct diag *d;
	scene_note_fn *note;		/* NULL: no notes */
	void *note_ctx;
	int notes_sent, notes_dropped;	/* the notes about shapes, capped */
};

/* Reads one object, keyword first, into *out; *line is the keyword's.
 * index and count (1-based) are for the messages. */
int parse_shape(struct parser *p, struct shape **out, int *line, long index, long count);
/* The note for a shape that can never be seen, for the first
 * PARSE_MAX_NOTES such shapes; the others are counted. */
void parser_note_degenerate(struct parser *p, const struct shape *sh, int line, long index);

/* Objects read ahead by other threads: the file after the object count is
 * cut at object keywords that begin a line, and each part but the first
 * is read by a thread of its own while the caller reads the first.
 * Nothing of a part is used unless the caller, reading on, arrives at the
 * part's first token, and nothing then differs from reading it alone: a
 * part that met an error, or holds more objects than are left to read,
 * is dropped and the caller reads that text itself.  So the scene, its
 * notes and any error are the same for any number of threads. */
struct parse_parts;

/* Starts reading ahead from the parser's position, in up to threads - 1
 * threads; NULL when the text is too short to be worth it, or when no
 * thread can be started or no memory had. */
struct parse_parts *parse_parts_start(const struct parser *p, int threads);
/* Called before each object with the number of objects still to read:
 * when the next token is the first of a part, adds that part's shapes to
 * s (with their notes), moves the parser past them and returns how many
 * there were; otherwise 0.  Returns a negative rt_err, with p's diagnostic
 * filled in, when adding the shapes fails. */
long parse_parts_take(struct parse_parts *pp, struct parser *p, struct scene *s, long index,
		      long remaining);
/* Waits for the threads and frees what was not taken. */
void parse_parts_finish(struct parse_parts *pp);

#endif
