/* The scene parser: every rule of scene-format.md, every error with its
 * line, column and message, the limits, and the real scene files that
 * circulate with the course (tests/data/real-scenes). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

#include "base/alloc.h"
#include "scene/scene_impl.h"
#include "whitted/scenefile.h"
#include "whitted/camera.h"
#include "course_scene.h"

/* The keywords of classic, spot and pyramid files, which a file of no
 * forced dialect may use. */
#define CLASSIC_FAMILY \
	(RT_DIALECT_BIT(RT_DIALECT_CLASSIC) | RT_DIALECT_BIT(RT_DIALECT_SPOT) | \
	 RT_DIALECT_BIT(RT_DIALECT_PYRAMID))
#include "whitted/render.h"
#include "support.h"

#ifndef RT_TEST_DATA_DIR
#define RT_TEST_DATA_DIR "tests/data"
#endif

/* The notes of a read, apart from the one that says which dialect it was
 * read as (kept in dialect; every read gives exactly one). */
struct notes {
	int n;
	struct diag first, last;
	int n_dialect;
	struct diag dialect;
};

static void collect_note(void *ctx, const struct diag *note)
{
	struct notes *ns = ctx;

	if (strncmp(note->msg, "read as the ", 12) == 0) {
		ns->dialect = *note;
		ns->n_dialect++;
		return;
	}
	if (ns->n == 0)
		ns->first = *note;
	ns->last = *note;
	ns->n++;
}

/* Parses text that must parse, collecting its notes. */
static struct scene *parse_noted(const char *text, struct notes *ns)
{
	struct scene *s = NULL;
	struct diag d;

	memset(ns, 0, sizeof(*ns));
	diag_clear(&d);
	if (scene_parse("test.txt", text, strlen(text), NULL, collect_note, ns, &s, &d) < 0) {
		print_error("parse failed: %s:%d:%d: %s\n", d.file, d.line, d.col, d.msg);
		fail();
	}
	return s;
}

/* The text must fail with err at line:col, and the message must contain
 * each of the NULL-terminated words. */
#define assert_parse_error(text, err, line, col, ...) \
	check_parse_error((text), (err), (line), (col), \
			  (const char *const[]){ __VA_ARGS__, NULL }, __FILE__, __LINE__)

static void check_parse_error(const char *text, enum rt_err err, int line, int col,
			      const char *const *words, const char *file, int at)
{
	struct diag d;
	int rc = support_parse_error(text, &d);

	if (rc != -(int)err || d.line != line || d.col != col || strcmp(d.file, "test.txt") != 0) {
		print_error("got %d at %s:%d:%d (%s), expected %d at test.txt:%d:%d\n",
			    rc, d.file, d.line, d.col, d.msg, -(int)err, line, col);
		_fail(file, at);
	}
	for (; *words; words++) {
		if (!strstr(d.msg, *words)) {
			print_error("message '%s' does not contain '%s'\n", d.msg, *words);
			_fail(file, at);
		}
	}
}

#define SPHERE "sphere 0 0 0 1  1 1 1  0 0 0 0  0\n"

static void test_parse_course_example(void **state)
{
	struct notes ns;
	struct scene *s = parse_noted(course_scene, &ns);
	const struct shape_ops *sphere = shape_ops_find("sphere", 6);
	const struct shape_ops *triangle = shape_ops_find("triangle", 8);
	size_t i;

	(void)state;
	assert_int_equal(s->recursion, 4);
	assert_int_equal(s->image_size, 768);
	assert_int_equal(s->n_shapes, 6);
	for (i = 0; i < 3; i++)
		assert_ptr_equal(s->shapes[i]->ops, sphere);
	for (i = 3; i < 6; i++)
		assert_ptr_equal(s->shapes[i]->ops, triangle);
	/* The second sphere: colour 0 0 1, coefficients 0.2 0.2 0.4 0.2, 15. */
	assert_near(s->shapes[1]->mat.color.b, 1.0, 0.0);
	assert_near(s->shapes[1]->mat.ks, 0.4, 0.0);
	assert_near(s->shapes[1]->mat.shininess, 15.0, 0.0);
	assert_int_equal(s->n_lights, 4);
	assert_vec3_near(s->lights[0].pos, vec3_make(70, 70, 70), 0.0);
	assert_near(s->lights[0].color.r, 1.0, 0.0);
	assert_near(s->lights[0].color.g, 0.0, 0.0);
	assert_vec3_near(s->lights[3].pos, vec3_make(-70, -70, 70), 0.0);
	assert_near(s->lights[3].color.g, 1.0, 0.0);
	assert_near(s->lights[3].color.r, 0.0, 0.0);
	assert_string_equal(s->name, "test.txt");
	/* No trailing text, no degenerate shapes: no notes. */
	assert_int_equal(ns.n, 0);
	assert_null(s->accel);
	scene_destroy(s);
}

static void test_parse_annotated_comments(void **state)
{
	struct notes ns;
	struct scene *s = parse_noted(
		"4\t\t- recursion\n"
		"64 // pixels\n"
		"# objects follow\n"
		"2\n"
		"general\n"
		"1 1 1 0 0 0 -20 -20 -20 200\t- A B C D E F G H I J\n"
		"0 0 0 0 0 5\t- cube reference point, length, width, height (0 indicates no clipping)\n"
		"0.0 0.0 1.0\t- color\n"
		"0.4 0.2 0.1 0.3\t- ambient, diffuse, specular, recursive reflection coefficient\n"
		"3\t\t- shininess\n"
		"sphere\n"
		"-20.0 0 10.0 - center\n"
		"10.0 # radius\n"
		"0 1 0 0.4 0.2 0.2 0.2 10\n"
		"1\n"
		"-50 50 50 - position\n"
		"1 1 1 - colour\n", &ns);

	(void)state;
	assert_int_equal(s->recursion, 4);
	assert_int_equal(s->image_size, 64);
	assert_int_equal(s->n_shapes, 2);
	assert_ptr_equal(s->shapes[0]->ops, shape_ops_find("general", 7));
	assert_near(s->shapes[0]->mat.shininess, 3.0, 0.0);
	/* '-20.0' is a number, not a comment. */
	{
		struct aabb box;
		assert_true(shape_bounds(s->shapes[1], &box));
		assert_vec3_near(box.min, vec3_make(-30, -10, 0), 0.0);
	}
	assert_int_equal(s->n_lights, 1);
	assert_vec3_near(s->lights[0].pos, vec3_make(-50, 50, 50), 0.0);
	assert_int_equal(ns.n, 0);
	scene_destroy(s);
}

static void test_parse_lights_with_colours(void **state)
{
	struct notes ns;
	struct scene *s = parse_noted("1 1 0 2\n0 0 10 0.5 0.25 1\n5 5 10 1 0 0\n", &ns);

	(void)state;
	assert_int_equal(s->n_lights, 2);
	assert_vec3_near(s->lights[0].pos, vec3_make(0, 0, 10), 0.0);
	assert_near(s->lights[0].color.r, 0.5, 0.0);
	assert_near(s->lights[0].color.g, 0.25, 0.0);
	assert_near(s->lights[0].color.b, 1.0, 0.0);
	assert_vec3_near(s->lights[1].pos, vec3_make(5, 5, 10), 0.0);
	assert_near(s->lights[1].color.g, 0.0, 0.0);
	assert_int_equal(ns.n, 0);
	scene_destroy(s);
}

static void test_parse_lights_positions_only(void **state)
{
	struct notes ns;
	struct scene *s;

	(void)state;
	/* Exactly 3 x 2 numbers before the end of the file: white lights. */
	s = parse_noted("1 1 0 2\n0 0 10\n-5 5 100\n", &ns);
	assert_int_equal(s->n_lights, 2);
	assert_vec3_near(s->lights[1].pos, vec3_make(-5, 5, 100), 0.0);
	assert_near(s->lights[0].color.r, 1.0, 0.0);
	assert_near(s->lights[0].color.g, 1.0, 0.0);
	assert_near(s->lights[1].color.b, 1.0, 0.0);
	assert_int_equal(ns.n, 0);
	scene_destroy(s);

	/* Exactly 3 numbers before the first non-number token: one white
	 * light, and the rest is trailing text with its note. */
	s = parse_noted("1 1 0 1\n0 0 10\nInput explanation:\n1 level\n", &ns);
	assert_int_equal(s->n_lights, 1);
	assert_near(s->lights[0].color.g, 1.0, 0.0);
	assert_int_equal(ns.n, 1);
	assert_int_equal(ns.first.line, 3);
	scene_destroy(s);

	/* Comments do not count as tokens. */
	s = parse_noted("1 1 0 1\n0 0 10 # position\n// nothing else\n", &ns);
	assert_int_equal(s->n_lights, 1);
	assert_near(s->lights[0].color.b, 1.0, 0.0);
	assert_int_equal(ns.n, 0);
	scene_destroy(s);

	/* Six numbers for two lights are read as two positions, as the
	 * contract says (3 x N numbers), not as one coloured light. */
	s = parse_noted("1 1 0 2\n0 0 10 1 0 0\n", &ns);
	assert_int_equal(s->n_lights, 2);
	assert_vec3_near(s->lights[1].pos, vec3_make(1, 0, 0), 0.0);
	assert_near(s->lights[1].color.g, 1.0, 0.0);
	scene_destroy(s);

	/* Six numbers for one light: position and colour. */
	s = parse_noted("1 1 0 1\n0 0 10 1 0 0\n", &ns);
	assert_int_equal(s->n_lights, 1);
	assert_near(s->lights[0].color.g, 0.0, 0.0);
	scene_destroy(s);
}

static void test_parse_trailing_text_one_note(void **state)
{
	struct notes ns;
	char text[1024];
	struct scene *s;

	(void)state;
	snprintf(text, sizeof(text), "%s\n\nInput explanation:\n\n4 level of recursion\n"
		 "768 pixels along both dimensions\n", course_scene);
	s = parse_noted(text, &ns);
	assert_int_equal(s->n_lights, 4);
	assert_int_equal(ns.n, 1);
	/* The course scene is 58 lines; lines 59 and 60 are blank, the text
	 * starts on line 61 and runs to line 64: 4 lines. */
	assert_int_equal(ns.first.line, 61);
	assert_int_equal(ns.first.col, 0);
	assert_string_equal(ns.first.file, "test.txt");
	assert_string_equal(ns.first.msg, "ignoring 4 lines after the last light");
	scene_destroy(s);

	/* One line, without a final newline: singular. */
	s = parse_noted("1 1 0 0 the end", &ns);
	assert_int_equal(ns.n, 1);
	assert_int_equal(ns.first.line, 1);
	assert_string_equal(ns.first.msg, "ignoring 1 line after the last light");
	scene_destroy(s);

	/* Trailing comments alone are not text. */
	s = parse_noted("1 1 0 0\n# the end\n// really\n", &ns);
	assert_int_equal(ns.n, 0);
	scene_destroy(s);

	/* Extra lights beyond the count are numbers that no count describes:
	 * an error at the first of them (scene-format.md: a number after the
	 * last section is not a trailer). */
	assert_parse_error("1 1 0 1\n0 0 10 1 1 1\n5 5 10 1 1 1\n", RT_E_SYNTAX, 3, 1,
			   "expected the end of the data after the last light, found the number '5'",
			   "6 numbers follow: a count does not describe the data");
}

static void test_parse_zero_objects_zero_lights_size_one(void **state)
{
	struct notes ns;
	struct scene *s = parse_noted("1\n1\n0\n0\n", &ns);

	(void)state;
	assert_int_equal(s->recursion, 1);
	assert_int_equal(s->image_size, 1);
	assert_int_equal(s->n_shapes, 0);
	assert_int_equal(s->n_lights, 0);
	assert_int_equal(ns.n, 0);
	scene_destroy(s);
	/* Zero lights right after objects. */
	s = parse_noted("2 3 1 " SPHERE "0", &ns);
	assert_int_equal(s->n_shapes, 1);
	assert_int_equal(s->n_lights, 0);
	scene_destroy(s);
}

static void test_parse_crlf(void **state)
{
	size_t n = strlen(course_scene), i, k = 0;
	char *text = malloc(2 * n + 1);
	struct notes ns;
	struct scene *s;

	(void)state;
	assert_non_null(text);
	for (i = 0; i < n; i++) {
		if (course_scene[i] == '\n')
			text[k++] = '\r';
		text[k++] = course_scene[i];
	}
	text[k] = '\0';
	s = parse_noted(text, &ns);
	assert_int_equal(s->n_shapes, 6);
	assert_int_equal(s->n_lights, 4);
	assert_near(s->lights[3].color.g, 1.0, 0.0);
	assert_int_equal(ns.n, 0);
	scene_destroy(s);
	free(text);
	/* Error positions in a CRLF file: the bad token on line 4, column 1. */
	assert_parse_error("1\r\n1\r\n1\r\nnosuchshape\r\n", RT_E_SYNTAX, 4, 1, "unknown object 'nosuchshape'");
	/* A comment ending in CR. */
	s = parse_noted("1 1 0 1 - lights\r\n0 0 10\r\n", &ns);
	assert_int_equal(s->n_lights, 1);
	scene_destroy(s);
}

static void test_parse_integral_reals_and_extremes(void **state)
{
	struct notes ns;
	struct scene *s;

	(void)state;
	/* Integer fields accept integral reals. */
	s = parse_noted("4.0 1e1 1.0 sphere 0 0 0 0.5  0 1 0.5  0 0 0 0  0  1e0 0 0 0 0 0 0\n", &ns);
	assert_int_equal(s->recursion, 4);
	assert_int_equal(s->image_size, 10);
	assert_int_equal(s->n_shapes, 1);
	assert_int_equal(s->n_lights, 1);
	/* Colours at 0 and 1, coefficients and shininess 0. */
	assert_near(s->shapes[0]->mat.color.r, 0.0, 0.0);
	assert_near(s->shapes[0]->mat.color.g, 1.0, 0.0);
	assert_near(s->shapes[0]->mat.shininess, 0.0, 0.0);
	scene_destroy(s);
	/* Real shininess, large coefficients. */
	s = parse_noted("1 1 1 sphere 0 0 0 1  1 1 1  2 3 4 5  2.5 0", &ns);
	assert_near(s->shapes[0]->mat.shininess, 2.5, 0.0);
	assert_near(s->shapes[0]->mat.kr, 5.0, 0.0);
	scene_destroy(s);
	/* The largest values the limits allow: 256 levels, 16384^2 = 2^28
	 * pixels. */
	s = parse_noted("256 16384 0 0", &ns);
	assert_int_equal(s->recursion, 256);
	assert_int_equal(s->image_size, 16384);
	scene_destroy(s);
}

static void test_parse_degenerate_triangle_one_note(void **state)
{
	struct notes ns;
	struct scene *s = parse_noted("1 1\n2\n" SPHERE
				      "triangle\n0 0 0\n1 1 1\n2 2 2\n1 0 0\n0.4 0.2 0.1 0.3\n5\n0\n", &ns);

	(void)state;
	/* Accepted (and kept), with one note at its keyword's line. */
	assert_int_equal(s->n_shapes, 2);
	assert_int_equal(ns.n, 1);
	assert_int_equal(ns.first.line, 4);
	assert_string_equal(ns.first.file, "test.txt");
	assert_non_null(strstr(ns.first.msg, "triangle (object 2)"));
	assert_non_null(strstr(ns.first.msg, "degenerate"));
	scene_destroy(s);
}

static void test_parse_many_notes_are_capped(void **state)
{
	char text[4096];
	struct notes ns;
	struct scene *s;
	size_t n;
	int i;

	(void)state;
	n = (size_t)snprintf(text, sizeof(text), "1 1 25\n");
	for (i = 0; i < 25; i++)
		n += (size_t)snprintf(text + n, sizeof(text) - n,
				      "triangle 0 0 0 0 0 0 0 0 0 1 1 1 0 0 0 0 0\n");
	snprintf(text + n, sizeof(text) - n, "0\n");
	s = parse_noted(text, &ns);
	assert_int_equal(s->n_shapes, 25);
	/* 20 notes, then one that says how many were left out. */
	assert_int_equal(ns.n, 21);
	assert_int_equal(ns.first.line, 2);
	assert_string_equal(ns.last.msg, "5 more notes not shown");
	scene_destroy(s);
	/* The note about trailing text is not one of those left out. */
	snprintf(text + n, sizeof(text) - n, "0\nInput explanation:\n");
	s = parse_noted(text, &ns);
	assert_int_equal(ns.n, 22);
	assert_int_equal(ns.last.line, 28);
	assert_string_equal(ns.last.msg, "ignoring 1 line after the last light");
	scene_destroy(s);
}

static void test_parse_error_settings(void **state)
{
	(void)state;
	assert_parse_error("", RT_E_SYNTAX, 1, 1, "expected an integer (recursion level), found end of file");
	assert_parse_error("  # nothing\n", RT_E_SYNTAX, 2, 1, "recursion level", "end of file");
	assert_parse_error("4.5 10 0 0", RT_E_SYNTAX, 1, 1, "expected an integer (recursion level), found '4.5'");
	assert_parse_error("4\nabc 0 0", RT_E_SYNTAX, 2, 1, "expected an integer (image size), found 'abc'");
	assert_parse_error("-1 10 0 0", RT_E_RANGE, 1, 1, "recursion level must be between 0 and 256, found -1");
	assert_parse_error("257 10 0 0", RT_E_RANGE, 1, 1, "recursion level must be between 0 and 256, found 257");
	assert_parse_error("1 0 0 0", RT_E_RANGE, 1, 3, "image size must be between 1 and 32768, found 0");
	assert_parse_error("1 -5 0 0", RT_E_RANGE, 1, 3, "image size", "found -5");
	assert_parse_error("1 32769 0 0", RT_E_RANGE, 1, 3, "image size must be between 1 and 32768");
	/* 16385^2 is over the 2^28-pixel limit. */
	assert_parse_error("1 16385 0 0", RT_E_RANGE, 1, 3, "16385", "268435456 pixels");
	assert_parse_error("1 1 -1 0", RT_E_RANGE, 1, 5, "object count must be between 0 and 500000000, found -1");
	assert_parse_error("1 1 1.5 0", RT_E_SYNTAX, 1, 5, "expected an integer (object count), found '1.5'");
	assert_parse_error("1 1 500000001 0", RT_E_RANGE, 1, 5, "object count must be between 0 and 500000000");
	assert_parse_error("1 1 0 100001", RT_E_RANGE, 1, 7, "light count must be between 0 and 100000");
	assert_parse_error("1 1 0 2.5", RT_E_SYNTAX, 1, 7, "expected an integer (light count), found '2.5'");
	assert_parse_error("1 1 0 x", RT_E_SYNTAX, 1, 7, "expected an integer (light count), found 'x'");
}

static void test_parse_error_huge_integers(void **state)
{
	(void)state;
	/* Integral but far outside every range (and outside a long): a range
	 * error, not "not an integer". */
	assert_parse_error("1e300 1 0 0", RT_E_RANGE, 1, 1, "recursion level must be between 0 and 256");
	assert_parse_error("1 1e19 0 0", RT_E_RANGE, 1, 3, "image size must be between 1 and 32768");
	assert_parse_error("1 1 -1e300 0", RT_E_RANGE, 1, 5, "object count must be between 0 and 500000000");
	assert_parse_error("1 1 0 9223372036854775808", RT_E_RANGE, 1, 7, "light count");
}

static void test_parse_error_not_finite(void **state)
{
	static const char *const bad[] = { "nan", "inf", "-inf", "0x10", "1e999", "infinity" };
	char text[128], quoted[32];
	size_t i;

	(void)state;
	for (i = 0; i < sizeof(bad) / sizeof(bad[0]); i++) {
		snprintf(text, sizeof(text), "1 1 1\nsphere 0 0 0 %s 1 1 1 0 0 0 0 0\n0\n", bad[i]);
		snprintf(quoted, sizeof(quoted), "found '%s'", bad[i]);
		assert_parse_error(text, RT_E_RANGE, 2, 14,
				   "expected a finite decimal number (sphere radius)", quoted);
	}
	assert_parse_error("nan 1 0 0", RT_E_RANGE, 1, 1, "recursion level", "'nan'");
	assert_parse_error("1 1 0 1\n0 inf 0\n", RT_E_RANGE, 2, 3, "light position", "'inf'");
	/* Trailing garbage is not a number at all. */
	assert_parse_error("1 1 1\nsphere 0 0 0 10abc", RT_E_SYNTAX, 2, 14,
			   "expected a number (sphere radius), found '10abc'");
}

static void test_parse_error_token_too_long(void **state)
{
	char text[512];
	size_t n;

	(void)state;
	n = (size_t)snprintf(text, sizeof(text), "1 1 1\nsphere 0 0 0 ");
	memset(text + n, '1', 300);
	text[n + 300] = '\0';
	assert_parse_error(text, RT_E_RANGE, 2, 14, "token too long", "sphere radius");
}

static void test_parse_error_unknown_keyword(void **state)
{
	char known[600];

	(void)state;
	snprintf(known, sizeof(known), "unknown object 'nosuchshape'; known objects: %s",
		 shape_keywords_in(CLASSIC_FAMILY));
	assert_parse_error("1 1 1\nnosuchshape 0 0 0 1", RT_E_SYNTAX, 2, 1, known);
	/* Keywords are lower case. */
	assert_parse_error("1 1 1\n  Sphere 0 0 0 1", RT_E_SYNTAX, 2, 3, "unknown object 'Sphere'",
			   shape_keywords_in(CLASSIC_FAMILY));
	/* The floor is implicit, not a keyword. */
	assert_parse_error("1 1 1\nfloor 1000 20", RT_E_SYNTAX, 2, 1, "unknown object 'floor'");
	/* A long unprintable keyword is quoted safely and cut short. */
	assert_parse_error("1 1 1\nab\x01zzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzz", RT_E_SYNTAX, 2, 1,
			   "unknown object 'ab\\x01zzz", "...'");
}

static void test_parse_error_expected_found(void **state)
{
	(void)state;
	assert_parse_error("1 1 1\nsphere 0 0 abc 1", RT_E_SYNTAX, 2, 12,
			   "expected a number (sphere centre), found 'abc'");
	assert_parse_error("1 1 1\ntriangle 0 0 0 1 1 1 2 2\n", RT_E_SYNTAX, 3, 1,
			   "expected a number (triangle vertex), found end of file");
	assert_parse_error("1 1 1\ngeneral 1 1 1 0 0 0 0 0 0 -1 0 0 0 x", RT_E_SYNTAX, 2, 36,
			   "expected a number (clip box length), found 'x'");
	/* A missing shininess swallows the light count; the light count is
	 * then missing at the end of the file. */
	assert_parse_error("1 1 1\nsphere 0 0 0 1 1 1 1 0 0 0 0\n0\n", RT_E_SYNTAX, 4, 1,
			   "expected an integer (light count), found end of file");
	/* A keyword where a number belongs. */
	assert_parse_error("1 1 2\nsphere 0 0 0 1 1 1 1 0 0 0 0\nsphere", RT_E_SYNTAX, 3, 1,
			   "expected a number (shininess), found 'sphere'");
}

static void test_parse_error_ranges(void **state)
{
	(void)state;
	/* "sphere 0 0 0 " is 13 columns: the radius is at 14. */
	assert_parse_error("1 1 1\nsphere 0 0 0 -1 1 1 1 0 0 0 0 0\n0", RT_E_RANGE, 2, 14,
			   "sphere radius must be > 0, found -1");
	assert_parse_error("1 1 1\nsphere 0 0 0 0 1 1 1 0 0 0 0 0\n0", RT_E_RANGE, 2, 14,
			   "sphere radius must be > 0, found 0");
	/* Colours: "sphere 0 0 0 1 0.5 " puts the second component at 20. */
	assert_parse_error("1 1 1\nsphere 0 0 0 1 0.5 1.5 0 0 0 0 0 0\n0", RT_E_RANGE, 2, 20,
			   "colour component must be in [0, 1], found 1.5");
	assert_parse_error("1 1 1\nsphere 0 0 0 1 -0.1 0 0 0 0 0 0 0\n0", RT_E_RANGE, 2, 16,
			   "colour component must be in [0, 1], found -0.1");
	/* Coefficients: "sphere 0 0 0 1 1 1 1 " is 21 columns. */
	assert_parse_error("1 1 1\nsphere 0 0 0 1 1 1 1 -1 0 0 0 0\n0", RT_E_RANGE, 2, 22,
			   "ambient coefficient must be >= 0, found -1");
	assert_parse_error("1 1 1\nsphere 0 0 0 1 1 1 1 0 -1 0 0 0\n0", RT_E_RANGE, 2, 24,
			   "diffuse coefficient must be >= 0, found -1");
	assert_parse_error("1 1 1\nsphere 0 0 0 1 1 1 1 0 0 -1 0 0\n0", RT_E_RANGE, 2, 26,
			   "specular coefficient must be >= 0, found -1");
	assert_parse_error("1 1 1\nsphere 0 0 0 1 1 1 1 0 0 0 -1 0\n0", RT_E_RANGE, 2, 28,
			   "reflection coefficient must be >= 0, found -1");
	assert_parse_error("1 1 1\nsphere 0 0 0 1 1 1 1 0 0 0 0 -1\n0", RT_E_RANGE, 2, 30,
			   "shininess must be >= 0, found -1");
	/* The same material rules for triangles and quadrics. */
	assert_parse_error("1 1 1\ntriangle 0 0 0 1 0 0 0 1 0 2 0 0 0 0 0 0 0\n0", RT_E_RANGE, 2, 28,
			   "colour component must be in [0, 1], found 2");
	/* Light colours: >= 0 (a light may be brighter than 1). */
	assert_parse_error("1 1 0 1\n0 0 10 1 -2 1\n", RT_E_RANGE, 2, 10,
			   "light colour component must be >= 0, found -2");
}

static void test_parse_error_quadric(void **state)
{
	(void)state;
	/* All ten coefficients zero: located at the tenth ("general " is 8
	 * columns, the tenth single-digit coefficient at 9 + 2 * 9 = 27). */
	assert_parse_error("1 1 1\ngeneral 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 1 1 1 0 0 0 0 0\n0",
			   RT_E_RANGE, 2, 27, "all ten quadric coefficients are zero");
	/* -0 is zero too. */
	assert_parse_error("1 1 1\ngeneral -0 0 0 0 0 0 0 0 0 0.0 0 0 0 0 0 0 1 1 1 0 0 0 0 0\n0",
			   RT_E_RANGE, 2, 28, "all ten quadric coefficients are zero");
	/* A negative clip extent: the width at column 38. */
	assert_parse_error("1 1 1\ngeneral 1 1 1 0 0 0 0 0 0 -1 0 0 0 0 -5 0 1 1 1 0 0 0 0 0\n0",
			   RT_E_RANGE, 2, 38, "clip box width must be >= 0", "found -5");
}

static void test_parse_error_object_count_mismatch(void **state)
{
	char expected[600];

	(void)state;
	/* Fewer objects than the count: the light count stands where the
	 * second object's keyword should be. */
	snprintf(expected, sizeof(expected),
		 "expected an object keyword (%s) for object 2 of 2, found '0'", shape_keywords_in(CLASSIC_FAMILY));
	assert_parse_error("1 1\n2\n" SPHERE "0\n", RT_E_SYNTAX, 4, 1, expected,
			   "does the object count match");
	assert_parse_error("1 1\n2\n" SPHERE, RT_E_SYNTAX, 4, 1,
			   "object 2 of 2, found end of file");
	/* More objects than the count. */
	assert_parse_error("1 1\n1\n" SPHERE SPHERE "0\n", RT_E_SYNTAX, 4, 1,
			   "expected the light count, found the object keyword 'sphere'",
			   "more objects than the object count of 1");
	assert_parse_error("1 1\n0\n" SPHERE "0\n", RT_E_SYNTAX, 3, 1,
			   "expected the light count", "object count of 0");
}

static void test_parse_error_light_count_mismatch(void **state)
{
	(void)state;
	/* 11 numbers for 2 lights: neither 6 nor 12, read with colours, the
	 * last colour component is missing. */
	assert_parse_error("1 1 0 2\n0 0 10 1 1 1\n5 5 10 1 1\n", RT_E_SYNTAX, 4, 1,
			   "expected a number (light colour component), found end of file");
	/* 3 numbers for 2 lights. */
	assert_parse_error("1 1 0 2\n0 0 10\n", RT_E_SYNTAX, 3, 1,
			   "expected a number (light colour component), found end of file");
	/* 6 numbers for 3 lights: read with colours, so the first light's
	 * colour is "5 5 10" on line 3, and 5 is not a colour. */
	assert_parse_error("1 1 0 3\n0 0 10\n5 5 -10\n", RT_E_RANGE, 3, 5,
			   "light colour component must be >= 0, found -10");
	/* A word in a position. */
	assert_parse_error("1 1 0 1\n0 abc 10 1 1 1", RT_E_SYNTAX, 2, 3,
			   "expected a number (light position), found 'abc'");
	/* No light count at all (a file cut short). */
	assert_parse_error("1 1\n1\n" SPHERE, RT_E_SYNTAX, 4, 1,
			   "expected an integer (light count), found end of file");
}

/* A count far beyond the objects present fails at the first missing one,
 * quickly and without allocating for the count. */
static void test_parse_huge_counts_fail_fast(void **state)
{
	unsigned long allocations;
	clock_t start = clock();

	(void)state;
	rt_alloc_fail_from(0);
	assert_parse_error("1 1\n9999999\n" SPHERE "0\n", RT_E_SYNTAX, 4, 1, "object 2 of 9999999");
	assert_parse_error("1 1 0 99999\n0 0 10 1 1 1\n", RT_E_SYNTAX, 3, 1, "light position",
			   "end of file");
	/* The scene, its name, one shape, the shape array, the light array:
	 * a handful of allocations, none of them sized by a count. */
	allocations = rt_alloc_fail_from(0);
	assert_true(allocations <= 10);
	assert_true(clock() - start < CLOCKS_PER_SEC);
}

static void test_parse_load_missing_file(void **state)
{
	struct scene *s = (struct scene *)1;
	struct diag d;

	(void)state;
	diag_clear(&d);
	assert_int_equal(scene_load("/nonexistent/scene.txt", NULL, NULL, NULL, &s, &d), -RT_E_IO);
	assert_null(s);
	assert_string_equal(d.file, "/nonexistent/scene.txt");
	assert_non_null(strstr(d.msg, "cannot open"));
}

static void test_parse_test_scene(void **state)
{
	struct scene *s = NULL;
	struct diag d;

	(void)state;
	/* The assignment's test scene: a red sphere of radius 10 at (0,0,10),
	 * 0.4 0.2 0.2 0.2, shininess 1, a white light at (-50, 50, 50). */
	assert_int_equal(scene_test_scene(&s, &d), 0);
	assert_int_equal(s->n_shapes, 1);
	assert_near(s->shapes[0]->mat.color.r, 1.0, 0.0);
	assert_near(s->shapes[0]->mat.color.g, 0.0, 0.0);
	assert_near(s->shapes[0]->mat.shininess, 1.0, 0.0);
	assert_int_equal(s->n_lights, 1);
	assert_vec3_near(s->lights[0].pos, vec3_make(-50, 50, 50), 0.0);
	scene_destroy(s);
}

/* The real scene files, copied into tests/data/real-scenes.  When they
 * are missing the tests fail: they are part of the suite. */
static void real_path(char *buf, size_t size, const char *name)
{
	struct stat st;

	snprintf(buf, size, "%s/real-scenes/%s", RT_TEST_DATA_DIR, name);
	if (stat(buf, &st) != 0) {
		print_error("%s is missing: the real scene files are in tests/data\n", buf);
		fail();
	}
}

static struct scene *load_real(const char *name, struct notes *ns)
{
	char path[1024];
	struct scene *s = NULL;
	struct diag d;

	real_path(path, sizeof(path), name);
	memset(ns, 0, sizeof(*ns));
	diag_clear(&d);
	if (scene_load(path, NULL, collect_note, ns, &s, &d) < 0) {
		print_error("%s:%d:%d: %s\n", d.file, d.line, d.col, d.msg);
		fail();
	}
	return s;
}

/* Renders the scene with its floor at 8 x 8: it must work, and something
 * must be visible. */
static void render_small(struct scene *s)
{
	struct render_job job;
	struct camera cam;
	struct image img;
	struct diag d;
	size_t i, lit = 0;

	assert_int_equal(scene_add_floor(s, RT_FLOOR_WIDTH, RT_FLOOR_TILE, &d), 0);
	assert_int_equal(scene_prepare(s, 1, &d), 0);
	support_default_camera(&cam, 8);
	assert_int_equal(image_alloc(&img, 8, 8, &d), 0);
	render_job_init(&job, s, &cam, 2);
	assert_int_equal(render_image(&job, &img, NULL, &d), 0);
	for (i = 0; i < 8 * 8 * 3; i++)
		lit += img.pixels[i] != 0;
	assert_true(lit > 0);
	image_free(&img);
}

static size_t count_ops(const struct scene *s, const char *keyword)
{
	const struct shape_ops *ops = shape_ops_find(keyword, strlen(keyword));
	size_t i, n = 0;

	for (i = 0; i < s->n_shapes; i++)
		n += s->shapes[i]->ops == ops;
	return n;
}

static void test_parse_real_anachor(void **state)
{
	struct notes ns;
	struct scene *s = load_real("anachor.txt", &ns);

	(void)state;
	/* One sphere of radius 130, four coloured lights, then "Input
	 * explanation:" on line 24 to the end, line 66 (no final newline). */
	assert_int_equal(s->n_shapes, 1);
	assert_int_equal(count_ops(s, "sphere"), 1);
	assert_int_equal(s->n_lights, 4);
	assert_near(s->lights[1].color.b, 1.0, 0.0);
	assert_int_equal(ns.n, 1);
	assert_int_equal(ns.first.line, 24);
	assert_string_equal(ns.first.msg, "ignoring 43 lines after the last light");
	assert_non_null(strstr(ns.first.file, "anachor.txt"));
	render_small(s);
	scene_destroy(s);
}

static void test_parse_real_pistachio102(void **state)
{
	struct notes ns;
	struct scene *s = load_real("pistachio102.txt", &ns);
	struct ray r;
	double t = INFINITY;

	(void)state;
	assert_int_equal(s->n_shapes, 8);
	assert_int_equal(count_ops(s, "sphere"), 3);
	assert_int_equal(count_ops(s, "triangle"), 3);
	assert_int_equal(count_ops(s, "general"), 2);
	assert_int_equal(s->n_lights, 2);
	assert_int_equal(ns.n, 0);
	/* The first quadric is x^2 + y^2 + z^2 = 100 clipped to z in [0, 20]:
	 * from below along the axis the near root (z = -10) is clipped and
	 * the dome is seen from inside at z = 10, t = 110. */
	r.origin = vec3_make(0, 0, -100);
	r.dir = vec3_make(0, 0, 1);
	assert_true(shape_intersect(s->shapes[6], &r, 0.0, &t));
	assert_near(t, 110.0, 1e-9);
	render_small(s);
	scene_destroy(s);
}

static void test_parse_real_adibashaira(void **state)
{
	struct notes ns;
	struct scene *s = load_real("adibashaira.txt", &ns);
	struct aabb box;

	(void)state;
	assert_int_equal(s->n_shapes, 11);
	assert_int_equal(s->n_lights, 4);
	assert_int_equal(ns.n, 0);
	/* The last object: a sphere of radius 125 around the origin. */
	assert_ptr_equal(s->shapes[10]->ops, shape_ops_find("sphere", 6));
	assert_true(shape_bounds(s->shapes[10], &box));
	assert_vec3_near(box.min, vec3_make(-125, -125, -125), 0.0);
	assert_vec3_near(box.max, vec3_make(125, 125, 125), 0.0);
	render_small(s);
	scene_destroy(s);
}

static void test_parse_real_ajakil(void **state)
{
	struct notes ns;
	struct scene *s = load_real("ajakil.txt", &ns);

	(void)state;
	assert_int_equal(s->n_shapes, 8);
	assert_int_equal(s->n_lights, 3);
	assert_int_equal(ns.n, 0);
	render_small(s);
	scene_destroy(s);
}

static void test_parse_real_mdraihansobhan(void **state)
{
	struct notes ns;
	struct scene *s = load_real("mdraihansobhan.txt", &ns);

	(void)state;
	assert_int_equal(s->n_shapes, 8);
	assert_int_equal(s->n_lights, 5);
	assert_true(s->lights[4].spot);
	/* Read as the spot dialect (tests/data/course-files/README.md): its
	 * spotlight section (lines 74 to 78) is data, a fifth light. */
	assert_int_equal(ns.n, 0);
	assert_string_equal(ns.dialect.msg, "read as the spot dialect (4 point lights, 1 spotlight)");
	render_small(s);
	scene_destroy(s);
}

static void check_real_error(const char *name, int line, int col, const char *words)
{
	char path[1024];
	struct scene *s = NULL;
	struct diag d;

	real_path(path, sizeof(path), name);
	diag_clear(&d);
	assert_int_equal(scene_load(path, NULL, NULL, NULL, &s, &d), -RT_E_SYNTAX);
	assert_null(s);
	assert_string_equal(d.file, path);
	if (d.line != line || d.col != col || !strstr(d.msg, words)) {
		print_error("%s:%d:%d: %s\n", d.file, d.line, d.col, d.msg);
		fail();
	}
}

static void test_parse_real_apurbostarry(void **state)
{
	(void)state;
	/* The file ends with the last object's shininess "5" on line 48 (no
	 * final newline): the light count is missing at 48:2. */
	check_real_error("apurbostarry.txt", 48, 2,
			 "expected an integer (light count), found end of file");
}

static void test_parse_real_nazmultakbir(void **state)
{
	(void)state;
	/* Its spheres carry an extra colour line: the first sphere reads
	 * "1 1 0" as its colour, "1 1 0 0.2" as coefficients and "0.3" as
	 * shininess, so the next keyword is expected at the "0.2" at 10:9. */
	check_real_error("nazmultakbir.txt", 10, 9, "expected an object keyword");
}

SUPPORT_MAIN(SUPPORT_TESTS(test_parse_course_example, test_parse_annotated_comments,
			   test_parse_lights_with_colours, test_parse_lights_positions_only,
			   test_parse_trailing_text_one_note,
			   test_parse_zero_objects_zero_lights_size_one, test_parse_crlf,
			   test_parse_integral_reals_and_extremes,
			   test_parse_degenerate_triangle_one_note,
			   test_parse_many_notes_are_capped, test_parse_error_settings,
			   test_parse_error_huge_integers, test_parse_error_not_finite,
			   test_parse_error_token_too_long, test_parse_error_unknown_keyword,
			   test_parse_error_expected_found, test_parse_error_ranges,
			   test_parse_error_quadric, test_parse_error_object_count_mismatch,
			   test_parse_error_light_count_mismatch,
			   test_parse_huge_counts_fail_fast, test_parse_load_missing_file,
			   test_parse_test_scene, test_parse_real_anachor,
			   test_parse_real_pistachio102, test_parse_real_adibashaira,
			   test_parse_real_ajakil, test_parse_real_mdraihansobhan,
			   test_parse_real_apurbostarry, test_parse_real_nazmultakbir))
