/* The steps the parse files share, private to src/scenefile.  From the
 * bottom: one object (parse_shape.c), a big file's objects in several
 * threads (parse_parts.c), the sections every grammar has
 * (parse_sections.c), the grammars (parse_classic.c, parse_nearfar.c) and
 * the choice between them (parse.c). */
#ifndef RT_PARSE_PRIVATE_H
#define RT_PARSE_PRIVATE_H

#include <stdbool.h>
#include <stddef.h>

#include "syntax/parser_impl.h"
#include "whitted/scene.h"
#include "whitted/shape.h"

#define PARSE_MAX_NOTES 20

/* Reads one object, keyword first, into *out; *line is the keyword's.
 * index and count (1-based) are for the messages. */
int parse_shape(struct parser *p, struct shape **out, int *line, long index, long count);
/* shape_ops_find_in(text, len, dialects), from the parser's memo of the
 * keywords it met lately where it holds this one (the registry does not
 * change while a file is read), so that a big file's objects do not each
 * take the registry's lock. */
const struct shape_ops *parse_find_ops(struct parser *p, const char *text, size_t len,
				       unsigned dialects);
/* The note for a shape that can never be seen, for the first
 * PARSE_MAX_NOTES such shapes; the others are counted. */
void parser_note_degenerate(struct parser *p, const struct shape *sh, int line, long index);

/* How many number tokens follow, up to limit, without consuming them. */
long parse_count_numbers(const struct parser *p, long limit);
/* The value of the k-th token ahead (0: the next), when it and all before
 * it are numbers. */
bool parse_number_ahead(const struct parser *p, long k, double *out);
/* Adds to a light's error how many numbers follow the light count when
 * they fit neither 6 nor 3 per light: the count is the likely culprit. */
int parse_light_count_hint(struct parser *p, int rc, long count, long available);
/* The recursion level (0 is read as 1, with a note) and the image size. */
int parse_recursion(struct parser *p, struct scene *s);
int parse_image_size(struct parser *p, struct scene *s);
/* The object count and that many objects (read ahead by threads). */
int parse_objects(struct parser *p, struct scene *s, int threads, long *count);
/* A count after the objects; an object keyword in its place means more
 * objects than the object count. */
int parse_count(struct parser *p, const char *what, long max, long objects, long *out);
/* The end of the data after the last section: nothing, words (ignored
 * with a note) or numbers (an error: a count does not describe the data). */
int parse_end(struct parser *p, const char *section);

/* A light's colour (three numbers >= 0), a spotlight's cutoff angle in
 * (0, 180], and adding a spotlight whose axis was checked non-zero. */
int parse_light_colour(struct parser *p, struct color *out);
int parse_cutoff(struct parser *p, double *out);
int parse_add_spot(struct parser *p, struct scene *s, struct light *l);

/* The grammars: classic, spot and pyramid (forced: RT_DIALECT_AUTO to
 * detect among them), and nearfar. */
int parse_classic(struct parser *p, struct scene *s, int threads, enum scene_dialect forced);
int parse_nearfar(struct parser *p, struct scene *s, int threads);
/* Whether a text of n numbers and no word is a nearfar header with no
 * objects and lights that fit. */
bool parse_nearfar_fits_without_objects(const struct parser *p, long n);

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
