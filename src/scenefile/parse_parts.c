/* Reading a big scene's objects in several threads (see parse_private.h):
 * the text after the object count is cut into parts at lines that begin
 * with an object keyword, and every part but the first is read by a
 * thread of its own into a list of shapes, while the caller reads the
 * first.  The caller takes a part only when its own reading arrives at
 * the part's first token, so the cuts need not be right: a cut that is
 * not where an object begins (a keyword swallowed by a malformed object,
 * or in the text after the lights) is never arrived at, and that part is
 * dropped, its thread told to stop. */
#include <pthread.h>
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

#include "base/alloc.h"
#include "scenefile/parse_private.h"

/* A part has at least this much text: less is not worth a thread. */
#define PARSE_PART_MIN ((size_t)512 << 10)
#define PARSE_PARTS_MAX 64
/* How far from where a cut should be its object keyword is looked for. */
#define PARSE_CUT_WINDOW ((size_t)64 << 10)

struct parse_parts;

struct parse_part {
	struct parse_parts *owner;
	const char *name, *text;
	size_t len;
	unsigned dialects;	/* the keywords the reader accepts */
	size_t line, start, stop;	/* its first line; its objects' keywords in [start, stop) */
	struct lexer end;	/* after its last object */
	struct shape **shapes;
	size_t n, cap;
	/* The first degenerate shapes (index in the part, keyword line) and
	 * how many there are: the notes the caller gives when it takes them. */
	size_t degenerate[PARSE_MAX_NOTES];
	int degenerate_line[PARSE_MAX_NOTES];
	size_t n_degenerate;
	bool started, ok;
	bool cancelled;		/* under owner->lock: no longer wanted */
	pthread_t thread;
};

struct parse_parts {
	struct parse_part part[PARSE_PARTS_MAX];
	int n, next;		/* parts started; the next one to take */
	pthread_mutex_t lock;
};

/* A part's thread looks this often whether it is still wanted: an error
 * early in the file then waits for little of the rest. */
#define PARSE_CANCEL_EVERY 256

static bool part_cancelled(struct parse_part *pt)
{
	bool c;

	pthread_mutex_lock(&pt->owner->lock);
	c = pt->cancelled;
	pthread_mutex_unlock(&pt->owner->lock);
	return c;
}

/* Whether c ends a token, as the lexer sees it: a space or a comment. */
static bool ends_token(const char *c, const char *end)
{
	return *c == ' ' || *c == '\t' || *c == '\n' || *c == '\r' || *c == '\v' || *c == '\f' ||
	       *c == '#' || (*c == '/' && c + 1 < end && c[1] == '/');
}

/* The first token in [from, stop) that is an object keyword and the first
 * token of its line (after blanks), or stop when there is none; *line
 * receives where its line begins.  Line by line, at the speed of memchr:
 * the text after the objects can be long.  No token crosses stop, which
 * is the start of such a token itself or the end of the text. */
static size_t find_part_start(const char *text, size_t from, size_t stop, size_t *line)
{
	const char *end = text + stop, *c = text + from;

	if (from > 0 && c[-1] != '\n') {
		c = memchr(c, '\n', (size_t)(end - c));
		if (!c)
			return stop;
		c++;
	}
	while (c < end) {
		const char *w, *start = c;
		while (c < end && (*c == ' ' || *c == '\t'))
			c++;
		for (w = c; w < end && !ends_token(w, end); w++)
			;
		if (w > c && shape_ops_find(c, (size_t)(w - c))) {
			*line = (size_t)(start - text);
			return (size_t)(c - text);
		}
		c = memchr(c, '\n', (size_t)(end - c));
		if (!c)
			return stop;
		c++;
	}
	return stop;
}

static int part_push(struct parse_part *pt, struct shape *sh, int line)
{
	if (pt->n == pt->cap) {
		size_t cap = pt->cap ? pt->cap * 2 : 1024;
		struct shape **p = rt_reallocarray(pt->shapes, cap, sizeof(*p));
		if (!p)
			return -RT_E_NOMEM;
		pt->shapes = p;
		pt->cap = cap;
	}
	if (shape_degenerate(sh)) {
		if (pt->n_degenerate < PARSE_MAX_NOTES) {
			pt->degenerate[pt->n_degenerate] = pt->n;
			pt->degenerate_line[pt->n_degenerate] = line;
		}
		pt->n_degenerate++;
	}
	pt->shapes[pt->n++] = sh;
	return 0;
}

static void *part_run(void *arg)
{
	struct parse_part *pt = arg;
	struct parser p;
	struct diag d;
	const char *c, *start = pt->text + pt->line;
	int line = 1;

	for (c = pt->text; (c = memchr(c, '\n', (size_t)(start - c))) != NULL; c++)
		line++;
	memset(&p, 0, sizeof(p));
	lexer_init_at(&p.lx, pt->text, pt->len, start, line);
	p.name = pt->name;
	p.dialects = pt->dialects;
	p.text = pt->text;
	p.len = pt->len;
	p.d = &d;
	for (;;) {
		struct lexer ahead = p.lx;
		struct token t = lexer_next(&ahead);
		struct shape *sh;
		int kw_line;

		if (!t.text || (size_t)(t.text - pt->text) >= pt->stop ||
		    !parse_find_ops(&p, t.text, t.len, 0))
			break;
		if (pt->n % PARSE_CANCEL_EVERY == PARSE_CANCEL_EVERY - 1 && part_cancelled(pt))
			return NULL;
		/* An error is left for the caller to find, reading the text
		 * itself, if it ever gets there. */
		if (parse_shape(&p, &sh, &kw_line, 0, 0) < 0)
			return NULL;
		if (part_push(pt, sh, kw_line) < 0) {
			shape_destroy(sh);
			return NULL;
		}
	}
	pt->end = p.lx;
	pt->ok = true;
	return NULL;
}

static void part_free_shapes(struct parse_part *pt, size_t from)
{
	size_t i;

	for (i = from; i < pt->n; i++)
		shape_destroy(pt->shapes[i]);
	rt_free(pt->shapes);
	pt->shapes = NULL;
	pt->n = pt->cap = 0;
}

struct parse_parts *parse_parts_start(const struct parser *p, int threads)
{
	size_t from = lexer_offset(&p->lx, p->text), left = p->len - from, stop = p->len;
	struct parse_parts *pp;
	int n = threads, k;

	if (threads < 2 || left < 2 * PARSE_PART_MIN)
		return NULL;
	if ((size_t)n > left / PARSE_PART_MIN)
		n = (int)(left / PARSE_PART_MIN);
	if (n > PARSE_PARTS_MAX)
		n = PARSE_PARTS_MAX;
	pp = rt_calloc(1, sizeof(*pp));
	if (!pp)
		return NULL;
	if (pthread_mutex_init(&pp->lock, NULL) != 0) {
		rt_free(pp);
		return NULL;
	}
	/* The cuts, from the last: part k runs from its keyword line at or
	 * after from + k/n of the text to the next part's start. */
	for (k = n - 1; k >= 1; k--) {
		size_t line = 0, target = from + left / (size_t)n * (size_t)k;
		/* Objects begin every hundred bytes or so: a cut with no object
		 * in its window is in the text after them, and not made. */
		size_t window = stop - target < PARSE_CUT_WINDOW ? stop : target + PARSE_CUT_WINDOW;
		size_t start = find_part_start(p->text, target, window, &line);
		struct parse_part *pt = &pp->part[pp->n];
		if (start >= window)
			continue;
		pt->owner = pp;
		pt->name = p->name;
		pt->dialects = p->dialects;
		pt->text = p->text;
		pt->len = p->len;
		pt->line = line;
		pt->start = start;
		pt->stop = stop;
		stop = start;
		pp->n++;
	}
	/* In text order, nearest first, before any thread starts. */
	for (k = 0; k < pp->n / 2; k++) {
		struct parse_part tmp = pp->part[k];
		pp->part[k] = pp->part[pp->n - 1 - k];
		pp->part[pp->n - 1 - k] = tmp;
	}
	for (k = 0; k < pp->n; k++)
		pp->part[k].started =
			pthread_create(&pp->part[k].thread, NULL, part_run, &pp->part[k]) == 0;
	return pp;
}

/* Waits for part k's thread. */
static void part_join(struct parse_part *pt)
{
	if (pt->started) {
		pthread_join(pt->thread, NULL);
		pt->started = false;
	}
}

/* Drops parts k and after: the caller reads their text itself.  Their
 * threads are told to stop first. */
static void parts_drop_from(struct parse_parts *pp, int k)
{
	int i;

	pthread_mutex_lock(&pp->lock);
	for (i = k; i < pp->n; i++)
		pp->part[i].cancelled = true;
	pthread_mutex_unlock(&pp->lock);
	for (i = k; i < pp->n; i++) {
		part_join(&pp->part[i]);
		part_free_shapes(&pp->part[i], 0);
	}
	pp->n = k;
}

long parse_parts_take(struct parse_parts *pp, struct parser *p, struct scene *s, long index,
		      long remaining)
{
	struct parse_part *pt;
	struct lexer ahead;
	struct token t;
	size_t i, at = lexer_offset(&p->lx, p->text), next_note = 0;

	if (pp->next >= pp->n)
		return 0;
	pt = &pp->part[pp->next];
	/* Most objects are far from the next cut: no need to look. */
	if (at < pt->start && pt->start - at > 4096)
		return 0;
	ahead = p->lx;
	t = lexer_next(&ahead);
	if (t.text && t.text < p->text + pt->start)
		return 0;
	if (t.text != p->text + pt->start) {
		/* Past the cut without meeting it (or at the end). */
		parts_drop_from(pp, pp->next);
		return 0;
	}
	part_join(pt);
	if (!pt->ok || pt->n == 0 || pt->n > (size_t)remaining) {
		parts_drop_from(pp, pp->next);
		return 0;
	}
	for (i = 0; i < pt->n; i++) {
		int rc;
		if (next_note < pt->n_degenerate && next_note < PARSE_MAX_NOTES &&
		    pt->degenerate[next_note] == i) {
			parser_note_degenerate(p, pt->shapes[i], pt->degenerate_line[next_note],
					       index + (long)i);
			next_note++;
		}
		rc = scene_add_shape(s, pt->shapes[i], p->d);
		if (rc < 0) {
			/* The scene has shapes up to i (the last destroyed by
			 * scene_add_shape); the rest go with the parts. */
			part_free_shapes(pt, i + 1);
			parts_drop_from(pp, pp->next);
			return rc;
		}
	}
	/* The degenerate shapes past the recorded ones only count. */
	p->notes_dropped += (int)(pt->n_degenerate - next_note);
	p->lx = pt->end;
	i = pt->n;
	part_free_shapes(pt, i);
	pp->next++;
	return (long)i;
}

void parse_parts_finish(struct parse_parts *pp)
{
	if (!pp)
		return;
	parts_drop_from(pp, pp->next);
	pthread_mutex_destroy(&pp->lock);
	rt_free(pp);
}
