/* Reading a big file's objects in several threads (src/parse_parts.c):
 * for files big enough to be cut into parts, the scene, the notes and any
 * error must be exactly those of reading with one thread, whatever the
 * number of threads and wherever the file goes wrong. */
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "support.h"

/* A growing text. */
struct text {
	char *s;
	size_t len, cap;
};

static void put(struct text *t, const char *fmt, ...)
{
	va_list ap;
	int n;

	for (;;) {
		va_start(ap, fmt);
		/* No buffer yet: vsnprintf(NULL, 0) only measures (NULL + 0 is
		 * undefined in C, which clang's checks catch). */
		n = vsnprintf(t->s ? t->s + t->len : NULL, t->cap - t->len, fmt, ap);
		va_end(ap);
		assert_true(n >= 0);
		if ((size_t)n < t->cap - t->len)
			break;
		t->cap = t->cap * 2 + (size_t)n + 1;
		t->s = realloc(t->s, t->cap);
		assert_non_null(t->s);
	}
	t->len += (size_t)n;
}

/* Where the objects to spoil are. */
struct spots {
	size_t object_line[4];	/* byte offsets of some objects' first number */
};

/* A scene of `objects` objects (about 110 bytes each) with everything the
 * lexer knows: comments of each kind, CRLF lines, indented keywords,
 * annotated numbers and degenerate triangles (more than the notes show),
 * spread over the whole file.  The count written is `count`. */
static void make_scene(struct text *t, long objects, long count, const char *after_lights,
		       struct spots *spots)
{
	long i;

	t->len = 0;
	put(t, "# a generated scene\n3\n200\n\n%ld\n", count);
	for (i = 0; i < objects; i++) {
		double x = (double)(i % 97) - 48, y = (double)(i % 89), z = (double)(i % 13) + 1;
		if (spots && i % (objects / 4) == objects / 8)
			spots->object_line[i / (objects / 4)] = t->len;
		switch (i % 7) {
		case 0:
			put(t, "sphere\n%g %g %g\n%g\n", x, y, z, 0.5 + (double)(i % 5) * 0.1);
			break;
		case 1:
			put(t, "  triangle   // indented\r\n%g %g %g\r\n%g %g %g\r\n%g %g %g\r\n", x, y, z,
			    x + 1, y, z, x, y + 1, z);
			break;
		case 2:
			if (i % 1001 == 2) {
				/* Degenerate: a note each, 20 shown. */
				put(t, "triangle\n%g %g %g\n%g %g %g\n%g %g %g\n", x, y, z, x, y, z, x, y, z);
			} else {
				put(t, "triangle\n%g %g %g\n%g %g %g\n%g %g %g\n", x, y, z, x, y + 2, z, x, y,
				    z + 2);
			}
			break;
		case 3:
			put(t, "general\n1 1 1 0 0 0 %g %g %g %g\n%g %g %g %g %g %g\n", -2 * x, -2 * y,
			    -2 * z, x * x + y * y + z * z - 1, x - 1, y - 1, z - 1, 2.0, 2.0, 2.0);
			break;
		case 4:
			put(t, "sphere  # a comment\n%g %g %g\t- centre\n%g\t- radius\n", x, y, z, 0.7);
			break;
		case 5:
			put(t, "\t sphere\n%g %g %g %g\n", x, y, z, 0.4);
			break;
		default:
			put(t, "# sphere in a comment\nsphere\n%g %g %g\n0.3\n", x, y, z);
			break;
		}
		put(t, "%g %g %g\n0.1 0.5 0.3 %g\n%ld\n\n", (double)(i % 3) / 2, 0.5, 1.0,
		    (double)(i % 4) / 10, 1 + i % 30);
	}
	put(t, "2\n0 0 100\n1 1 1\n50 -50 60\n0.5 0.5 0.5\n%s", after_lights);
}

struct outcome {
	int rc;
	struct diag d;
	int notes;
	char note_text[24][RT_DIAG_MSG_MAX + 32];
	struct scene *s;
};

static void count_note(void *ctx, const struct diag *note)
{
	struct outcome *o = ctx;

	if (o->notes < 24)
		snprintf(o->note_text[o->notes], sizeof(o->note_text[0]), "%d: %s", note->line,
			 note->msg);
	o->notes++;
}

static void parse_with(const struct text *t, int threads, struct outcome *o)
{
	struct scene_read_options opt = { threads, false, RT_DIALECT_AUTO, false, 0 };

	memset(o, 0, sizeof(*o));
	diag_clear(&o->d);
	o->rc = scene_parse("big.txt", t->s, t->len, &opt, count_note, o, &o->s, &o->d);
}

/* The scene's shapes as POV-Ray text, in a temporary file. */
static FILE *export_shapes(const struct scene *s)
{
	const struct pov_options opt = { RT_POV_FINISH_EXACT, false, { NULL, NULL } };
	FILE *f = tmpfile();
	size_t i;

	assert_non_null(f);
	for (i = 0; i < s->n_shapes; i++)
		assert_int_equal(shape_export_pov(s->shapes[i], f, &opt), 0);
	rewind(f);
	return f;
}

/* The shapes must be equal: same primitive and material, and the same
 * POV-Ray text, which has every number of the geometry (written so that
 * it reads back exactly) whatever the primitive. */
static void assert_same_scene(const struct scene *a, const struct scene *b)
{
	static char text_a[1 << 16], text_b[1 << 16];
	FILE *fa, *fb;
	size_t i, na, nb, line = 1;

	assert_int_equal(a->n_shapes, b->n_shapes);
	assert_int_equal(a->n_lights, b->n_lights);
	for (i = 0; i < a->n_shapes; i++) {
		assert_ptr_equal(a->shapes[i]->ops, b->shapes[i]->ops);
		assert_memory_equal(&a->shapes[i]->mat, &b->shapes[i]->mat, sizeof(a->shapes[i]->mat));
	}
	fa = export_shapes(a);
	fb = export_shapes(b);
	do {
		na = fread(text_a, 1, sizeof(text_a), fa);
		nb = fread(text_b, 1, sizeof(text_b), fb);
		assert_int_equal(na, nb);
		for (i = 0; i < na; i++) {
			if (text_a[i] != text_b[i])
				fail_msg("the shapes' POV-Ray text differs on its line %zu", line);
			line += text_a[i] == '\n';
		}
	} while (na == sizeof(text_a));
	fclose(fa);
	fclose(fb);
}

/* Parses with 1 thread and then with each of the n_threads others: the
 * same outcome. */
static void assert_same_for(const struct text *t, const int *threads, size_t n_threads)
{
	struct outcome *one = malloc(sizeof(*one)), *many = malloc(sizeof(*many));
	size_t k;
	int i;

	assert_non_null(one);
	assert_non_null(many);
	parse_with(t, 1, one);
	for (k = 0; k < n_threads; k++) {
		parse_with(t, threads[k], many);
		assert_int_equal(many->rc, one->rc);
		assert_int_equal(many->d.line, one->d.line);
		assert_int_equal(many->d.col, one->d.col);
		assert_string_equal(many->d.msg, one->d.msg);
		assert_int_equal(many->notes, one->notes);
		for (i = 0; i < one->notes && i < 24; i++)
			assert_string_equal(many->note_text[i], one->note_text[i]);
		assert_true((many->s == NULL) == (one->s == NULL));
		if (one->s)
			assert_same_scene(one->s, many->s);
		scene_destroy(many->s);
	}
	scene_destroy(one->s);
	free(one);
	free(many);
}

/* 1 thread against 2, 3, 7 and 64. */
static void assert_same_for_threads(const struct text *t)
{
	static const int threads[] = { 2, 3, 7, 64 };

	assert_same_for(t, threads, sizeof(threads) / sizeof(threads[0]));
}

#define BIG 60000	/* objects: over 3 MiB, enough for six parts */

static void test_parse_parts_big_scene_same_for_any_threads(void **state)
{
	struct text t = { NULL, 0, 0 };
	struct outcome o;

	(void)state;
	make_scene(&t, BIG, BIG, "", NULL);
	assert_true(t.len > (size_t)3 << 20);
	assert_same_for_threads(&t);
	/* And it is a real scene: every object, and the notes (20 shown of
	 * the 60 degenerate triangles, objects 3, 1004, ..., then the count
	 * of the rest). */
	parse_with(&t, 7, &o);
	assert_int_equal(o.rc, 0);
	assert_int_equal(o.s->n_shapes, BIG);
	assert_int_equal(o.notes, 22);	/* and the dialect note last */
	assert_non_null(strstr(o.note_text[21], "read as the classic dialect"));
	assert_non_null(strstr(o.note_text[0], "triangle (object 3)"));
	assert_non_null(strstr(o.note_text[19], "triangle (object 19022)"));
	assert_non_null(strstr(o.note_text[20], "40 more notes not shown"));
	scene_destroy(o.s);
	free(t.s);
}

static void test_parse_parts_errors_same_for_any_threads(void **state)
{
	struct text t = { NULL, 0, 0 };
	struct spots spots;
	int k;

	(void)state;
	/* Fewer objects counted than written; more counted than written. */
	make_scene(&t, BIG, BIG - 100, "", NULL);
	assert_same_for_threads(&t);
	make_scene(&t, BIG, BIG + 5, "", NULL);
	assert_same_for_threads(&t);
	/* Text after the lights, with object keywords that begin lines. */
	make_scene(&t, BIG, BIG, "sphere\n1 2 3\n\nsphere\ntriangle\n", NULL);
	assert_same_for_threads(&t);
	/* A bad number in each quarter of the file, and a missing one (the
	 * next keyword read as a number). */
	for (k = 0; k < 4; k++) {
		make_scene(&t, BIG, BIG, "", &spots);
		memcpy(t.s + spots.object_line[k] + strcspn(t.s + spots.object_line[k], "\n") + 1,
		       k % 2 ? "x" : "#", 1);
		assert_same_for_threads(&t);
	}
	free(t.s);
}

/* Random damage anywhere in a big file: bytes overwritten with what the
 * lexer cares about, lines deleted, object keywords and broken objects
 * inserted at the start of a line.  Whatever the damage, 3 and 7 threads
 * must give what 1 gives. */
static void test_parse_parts_random_damage(void **state)
{
	static const char bytes[] = " \t\n\r#/-.+0123456789eExs";
	static const char *const inserts[] = {
		"sphere\n", "triangle 1 2 3\n", "general\n", "# sphere\n", "- sphere\n", "\n\n",
	};
	static const int threads[] = { 3, 7 };
	struct text t = { NULL, 0, 0 }, base = { NULL, 0, 0 };
	uint64_t rng = 99;
	int round;

	(void)state;
	make_scene(&base, BIG, BIG, "", NULL);
	for (round = 0; round < 16; round++) {
		int k, n_damage;
		t.len = 0;
		put(&t, "%s", base.s);
		rng = rng * 6364136223846793005u + 1442695040888963407u;
		n_damage = 1 + (int)(rng >> 62);
		for (k = 0; k < n_damage; k++) {
			size_t at, kind;
			rng = rng * 6364136223846793005u + 1442695040888963407u;
			at = (size_t)(rng >> 20) % t.len;
			kind = (size_t)(rng >> 8) % 3;
			if (kind == 0) {
				t.s[at] = bytes[(rng >> 40) % (sizeof(bytes) - 1)];
			} else {
				/* At the start of the line that holds `at`. */
				char *line = t.s + at, *next;
				while (line > t.s && line[-1] != '\n')
					line--;
				next = strchr(line, '\n');
				if (kind == 1 && next) {
					memmove(line, next + 1, strlen(next + 1) + 1);
				} else {
					const char *ins = inserts[(rng >> 40) % 6];
					size_t n = strlen(ins), off = (size_t)(line - t.s);
					put(&t, "%*s", (int)n, "");
					memmove(t.s + off + n, t.s + off, t.len - n - off + 1);
					memcpy(t.s + off, ins, n);
				}
				t.len = strlen(t.s);
			}
		}
		assert_same_for(&t, threads, sizeof(threads) / sizeof(threads[0]));
	}
	free(t.s);
	free(base.s);
}

/* A file too small to cut is read by one thread; a NULL options reads
 * with one thread too. */
static void test_parse_parts_small_file(void **state)
{
	struct text t = { NULL, 0, 0 };
	struct outcome o;
	struct diag d;
	struct scene *s;

	(void)state;
	make_scene(&t, 100, 100, "", NULL);
	assert_same_for_threads(&t);
	parse_with(&t, 64, &o);
	assert_int_equal(o.rc, 0);
	assert_int_equal(o.s->n_shapes, 100);
	scene_destroy(o.s);
	assert_int_equal(scene_parse("small.txt", t.s, t.len, NULL, NULL, NULL, &s, &d), 0);
	assert_int_equal(s->n_shapes, 100);
	assert_true(s->source_hash == 0);
	scene_destroy(s);
	free(t.s);
}

SUPPORT_MAIN(SUPPORT_TESTS(test_parse_parts_big_scene_same_for_any_threads,
			   test_parse_parts_errors_same_for_any_threads,
			   test_parse_parts_random_damage, test_parse_parts_small_file))
