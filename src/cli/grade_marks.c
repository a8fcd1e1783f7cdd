/* grade's marks: the points an image earns by its outcome, from a small
 * table the teacher can change (--marks FILE):
 *
 *   # OUTCOME [CAUSE] POINTS, one a line; '#' starts a comment
 *   match 10            the image matches the reference
 *   camera 10           it matches at another camera (moved before the capture)
 *   cause 6             a known mistake explains it
 *   cause no-shadows 7  ... this mistake in particular (any cause id)
 *   close 4             one mistake is the likely one, not explaining all of it
 *   differs 2           it differs and nothing explains it
 *   unreadable 0        it cannot be read
 *
 * A pair of mistakes earns the lesser of the two's points, less the
 * difference between a cause's and close's (a second mistake costs as
 * much as the first). */
#define _POSIX_C_SOURCE 200809L
#include <ctype.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/alloc.h"
#include "base/file.h"
#include "cli/grade_marks.h"

void grade_marks_default(struct grade_marks *m)
{
	memset(m, 0, sizeof(*m));
	m->match = 10.0;
	m->camera = 10.0;
	m->cause = 6.0;
	m->close = 4.0;
	m->differs = 2.0;
	m->unreadable = 0.0;
}

static const struct { const char *key; size_t offset; } grade_marks_keys[] = {
	{ "match", offsetof(struct grade_marks, match) },
	{ "camera", offsetof(struct grade_marks, camera) },
	{ "cause", offsetof(struct grade_marks, cause) },
	{ "close", offsetof(struct grade_marks, close) },
	{ "differs", offsetof(struct grade_marks, differs) },
	{ "unreadable", offsetof(struct grade_marks, unreadable) },
};

/* The next word of a line at *p (NUL-terminated in place), or NULL. */
static char *grade_word(char **p, int *col, char *line)
{
	char *s = *p, *w;

	while (*s == ' ' || *s == '\t' || *s == '\r')
		s++;
	if (*s == '\0' || *s == '#')
		return NULL;
	w = s;
	while (*s && *s != ' ' && *s != '\t' && *s != '\r' && *s != '#')
		s++;
	if (*s == '#')
		*s = '\0', s--;
	if (*s)
		*s++ = '\0';
	*p = s;
	*col = (int)(w - line) + 1;
	return w;
}

static int grade_points(const char *path, int line, int col, const char *w, double *out,
			struct diag *d)
{
	char *end;
	double v = w ? strtod(w, &end) : 0.0;

	if (!w || *end != '\0' || !(v >= -1e6 && v <= 1e6))
		return diag_set(d, RT_E_SYNTAX, path, line, col, "expected the points (a number), found %s%s%s",
				w ? "'" : "the end of the line", w ? w : "", w ? "'" : "");
	*out = v;
	return 0;
}

int grade_marks_read(const char *path, struct grade_marks *m, struct diag *d)
{
	char *text = NULL, *line, *next;
	size_t len = 0, k;
	int lineno = 0, rc;

	grade_marks_default(m);
	if ((rc = file_read_all(path, "points table", (size_t)1 << 20, &text, &len, d)) < 0)
		return rc;
	for (line = text; line && *line; line = next) {
		char *p = line, *key, *w;
		int col = 1, kcol;
		next = strchr(line, '\n');
		if (next)
			*next++ = '\0';
		lineno++;
		if (!(key = grade_word(&p, &kcol, line)))
			continue;
		for (k = 0; k < sizeof(grade_marks_keys) / sizeof(grade_marks_keys[0]); k++)
			if (strcmp(key, grade_marks_keys[k].key) == 0)
				break;
		if (k == sizeof(grade_marks_keys) / sizeof(grade_marks_keys[0])) {
			rc = diag_set(d, RT_E_SYNTAX, path, lineno, kcol,
				      "expected match, camera, cause, close, differs or unreadable, "
				      "found '%s'", key);
			goto out;
		}
		w = grade_word(&p, &col, line);
		if (strcmp(key, "cause") == 0 && w && !(isdigit((unsigned char)w[0]) || w[0] == '-' || w[0] == '.')) {
			struct grade_marks_cause *c;
			if (m->n_causes == GRADE_MARKS_MAX_CAUSES) {
				rc = diag_set(d, RT_E_RANGE, path, lineno, col, "more than %d causes",
					      GRADE_MARKS_MAX_CAUSES);
				goto out;
			}
			c = &m->causes[m->n_causes];
			snprintf(c->id, sizeof(c->id), "%s", w);
			w = grade_word(&p, &col, line);
			if ((rc = grade_points(path, lineno, col, w, &c->points, d)) < 0)
				goto out;
			m->n_causes++;
		} else if ((rc = grade_points(path, lineno, col, w, (double *)((char *)m + grade_marks_keys[k].offset),
					      d)) < 0) {
			goto out;
		}
		if ((w = grade_word(&p, &col, line)) != NULL) {
			rc = diag_set(d, RT_E_SYNTAX, path, lineno, col, "expected the end of the line, found '%s'", w);
			goto out;
		}
	}
	rc = 0;
out:
	rt_free(text);
	return rc;
}

double grade_marks_cause(const struct grade_marks *m, const char *id)
{
	int k;

	for (k = 0; k < m->n_causes; k++)
		if (strcmp(m->causes[k].id, id) == 0)
			return m->causes[k].points;
	return m->cause;
}
