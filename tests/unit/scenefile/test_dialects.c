/* The choice of dialect (scene-format.md, "The dialects") and what each
 * dialect's grammar reads: the detection rules in their order, the note
 * that names the dialect, forcing one, the spot and nearfar sections (with
 * the colour-line variant), the view each dialect gives, and the errors
 * where a file fits no dialect. */
#include <math.h>
#include <string.h>

#include "support.h"

#define MAT "1 0 0 0.4 0.2 0.2 0.2 10\n"
#define SPHERE "sphere 0 0 10 10 " MAT

struct read {
	int rc;
	struct scene *s;
	struct diag d;
	int notes;
	char dialect_note[RT_DIAG_MSG_MAX];
	char last_note[RT_DIAG_MSG_MAX];
};

static void on_note(void *ctx, const struct diag *note)
{
	struct read *r = ctx;

	if (strncmp(note->msg, "read as the ", 12) == 0)
		snprintf(r->dialect_note, sizeof(r->dialect_note), "%s", note->msg);
	else
		snprintf(r->last_note, sizeof(r->last_note), "%s", note->msg);
	r->notes++;
}

static void read_as(const char *text, enum scene_dialect forced, struct read *r)
{
	struct scene_read_options opt = { 1, false, forced, false, 0 };

	memset(r, 0, sizeof(*r));
	diag_clear(&r->d);
	r->rc = scene_parse("t.txt", text, strlen(text), &opt, on_note, r, &r->s, &r->d);
}

static void expect_dialect(const char *text, const char *note)
{
	struct read r;

	read_as(text, RT_DIALECT_AUTO, &r);
	if (r.rc != 0)
		print_error("parse failed: %d:%d: %s\n", r.d.line, r.d.col, r.d.msg);
	assert_int_equal(r.rc, 0);
	assert_string_equal(r.dialect_note, note);
	scene_destroy(r.s);
}

static void expect_error(const char *text, enum scene_dialect forced, int line, int col,
			 const char *words)
{
	struct read r;

	read_as(text, forced, &r);
	if (r.rc == 0 || r.d.line != line || r.d.col != col || !strstr(r.d.msg, words))
		print_error("got %d at %d:%d '%s', expected %d:%d '%s'\n", r.rc, r.d.line,
			    r.d.col, r.d.msg, line, col, words);
	assert_true(r.rc < 0);
	assert_int_equal(r.d.line, line);
	assert_int_equal(r.d.col, col);
	assert_non_null(strstr(r.d.msg, words));
	assert_null(r.s);
}

static void test_dialects_detection_order(void **state)
{
	(void)state;
	expect_dialect("4 16 1 " SPHERE "1 0 0 100 1 1 1\n",
		       "read as the classic dialect (1 point light)");
	/* Positions only: still classic. */
	expect_dialect("4 16 1 " SPHERE "2 0 0 100 50 0 100\n",
		       "read as the classic dialect (2 point lights)");
	/* A spotlight section: 1 + 10 N numbers after lights with colours. */
	expect_dialect("4 16 1 " SPHERE "1 0 0 100 1 1 1\n1\n0 0 100 1 1 1 0 0 -1 30\n",
		       "read as the spot dialect (1 point light, 1 spotlight)");
	/* A spotlight count of 0 is a spot file too. */
	expect_dialect("4 16 1 " SPHERE "1 0 0 100 1 1 1\n0\n",
		       "read as the spot dialect (1 point light, 0 spotlights)");
	/* A pyramid among the objects. */
	expect_dialect("4 16 2 " SPHERE "pyramid 0 0 0 10 10 " MAT "1 0 0 100\n",
		       "read as the pyramid dialect (1 point light)");
	/* 11 numbers before the first word. */
	expect_dialect("1 1000 80 1 4 16 50 0.1 0.3 0.6 1 " SPHERE "1 0 0 100 0 0\n",
		       "read as the nearfar dialect (1 point light, 0 spotlights)");
	/* No word at all, and the nearfar header with no objects fits. */
	expect_dialect("1 1000 80 1 4 16 50 0.1 0.3 0.6 0 1 0 0 100 0.001 0\n",
		       "read as the nearfar dialect (1 point light, 0 spotlights)");
	/* 11 numbers before the first word, or none, with a third of 0: the
	 * object count of a classic-layout file, never nearfar's FOVY. */
	expect_dialect("4 64 0 1  0 0 50 1 1 1  0  input explanation\n",
		       "read as the spot dialect (1 point light, 0 spotlights)");
	expect_dialect("4 64 0 2  0 0 50 1 1 1  0 1 50 1 1 1  0\n",
		       "read as the spot dialect (2 point lights, 0 spotlights)");
	/* No word, and a classic file with no objects. */
	expect_dialect("4 16 0 1 0 0 100 1 1 1\n", "read as the classic dialect (1 point light)");
}

static void test_dialects_views(void **state)
{
	struct read r;
	const struct scene_view *v;

	(void)state;
	read_as("4 16 2 " SPHERE "pyramid 0 0 0 10 10 " MAT "1 0 0 100\n", RT_DIALECT_AUTO, &r);
	v = scene_view_of(r.s);
	assert_int_equal(v->dialect, RT_DIALECT_PYRAMID);
	assert_true(v->fov_deg == 90.0 && v->floor_cell == 30.0 && v->floor_width == 1000.0);
	assert_true(v->near == 0.0 && v->aspect == 0.0);
	scene_destroy(r.s);
	read_as("1 1000 70 1.5 4 16 50 0.1 0.3 0.6 1 " SPHERE "1 0 0 100 0.5 0\n",
		RT_DIALECT_AUTO, &r);
	v = scene_view_of(r.s);
	assert_int_equal(v->dialect, RT_DIALECT_NEARFAR);
	assert_true(v->near == 1.0 && v->far == 1000.0 && v->fov_deg == 70.0 && v->aspect == 1.5);
	assert_true(isinf(v->floor_width) && v->floor_cell == 50.0);
	assert_true(v->floor_mat.ka == 0.1 && v->floor_mat.kd == 0.3 && v->floor_mat.ks == 0.0 &&
		    v->floor_mat.kr == 0.6);
	assert_true(scene_light(r.s, 0)->falloff == 0.5 && !scene_light(r.s, 0)->spot);
	scene_destroy(r.s);
}

static void test_dialects_nearfar_lights(void **state)
{
	struct read r;
	const struct light *l;

	(void)state;
	/* Plain: x y z falloff; spot: x y z falloff, look-at, cutoff. */
	read_as("1 1000 80 1 4 16 50 0.1 0.3 0.6 0\n1\n1 2 3 0.25\n1\n0 0 100 0.5 0 0 0 30\n",
		RT_DIALECT_AUTO, &r);
	assert_int_equal(r.rc, 0);
	assert_int_equal(scene_light_count(r.s), 2);
	l = scene_light(r.s, 1);
	assert_true(l->spot && l->falloff == 0.5 && l->cutoff_deg == 30.0);
	assert_true(l->axis.x == 0.0 && l->axis.y == 0.0 && l->axis.z == -1.0);
	assert_true(l->color.r == 1.0 && l->color.g == 1.0 && l->color.b == 1.0);
	scene_destroy(r.s);
	/* The colour-line revision: read so only when only it fits, with a note. */
	read_as("1 1000 80 1 4 16 50 0.1 0.3 0.6 0\n1\n1 2 3\n1 0 0\n0.25\n1\n0 0 100\n0 1 0\n0.5 0 0 0 30\n",
		RT_DIALECT_AUTO, &r);
	assert_int_equal(r.rc, 0);
	assert_non_null(strstr(r.last_note, "colour line"));
	assert_true(scene_light(r.s, 0)->color.g == 0.0 && scene_light(r.s, 0)->falloff == 0.25);
	assert_true(scene_light(r.s, 1)->color.r == 0.0 && scene_light(r.s, 1)->color.g == 1.0);
	scene_destroy(r.s);
}

static void test_dialects_forced(void **state)
{
	char msg[600];
	struct read r;

	(void)state;
	read_as("4 16 1 " SPHERE "1 0 0 100 1 1 1\n0\n", RT_DIALECT_SPOT, &r);
	assert_int_equal(r.rc, 0);
	assert_string_equal(r.dialect_note,
			    "read as the spot dialect, as asked (1 point light, 0 spotlights)");
	scene_destroy(r.s);
	/* The same file as classic: the spotlight count is data no count
	 * describes. */
	expect_error("4 16 1 " SPHERE "1 0 0 100 1 1 1\n0\n", RT_DIALECT_CLASSIC, 3, 1,
		     "expected the end of the data after the last light, found the number '0'");
	/* A forced spot file must have the spotlight count. */
	expect_error("4 16 1 " SPHERE "1 0 0 100 1 1 1\n", RT_DIALECT_SPOT, 3, 1,
		     "expected an integer (spotlight count), found end of file");
	/* A pyramid in a file forced classic: the keyword is another
	 * dialect's, and the message lists classic's (from the registry). */
	snprintf(msg, sizeof(msg), "unknown object 'pyramid' in the classic dialect; known objects: %s",
		 shape_keywords_in(RT_DIALECT_BIT(RT_DIALECT_CLASSIC)));
	expect_error("4 16 1 pyramid 0 0 0 10 10 " MAT "0\n", RT_DIALECT_CLASSIC, 1, 8, msg);
	/* A cube is nearfar's only. */
	expect_error("4 16 1 cube 0 0 0 10 " MAT "0\n", RT_DIALECT_AUTO, 1, 8,
		     "unknown object 'cube' in the classic dialect");
}

static void test_dialects_errors(void **state)
{
	char msg[600];

	(void)state;
	/* Numbers after the last section. */
	expect_error("4 16 0 1 0 0 100 1 1 1\n5 5\n", RT_DIALECT_AUTO, 2, 1,
		     "(2 numbers follow: a count does not describe the data");
	/* A recursion level of 0 is read as 1; -1 is not a level. */
	expect_error("-1 16 0 0\n", RT_DIALECT_AUTO, 1, 1, "recursion level must be between 0 and 256");
	/* Spotlights: a zero axis, a cutoff outside (0, 180]. */
	expect_error("4 16 0 1 0 0 100 1 1 1\n1\n0 0 100 1 1 1 0 0 0 30\n", RT_DIALECT_AUTO, 3, 19,
		     "the spotlight's direction is zero");
	expect_error("4 16 0 1 0 0 100 1 1 1\n1\n0 0 100 1 1 1 0 0 -1 190\n", RT_DIALECT_AUTO, 3, 22,
		     "spotlight cutoff angle must be in (0, 180] degrees, found 190");
	/* nearfar's header. */
	expect_error("1 1 80 1 4 16 50 0.1 0.3 0.6 0 0 0\n", RT_DIALECT_AUTO, 1, 3,
		     "the far distance must be beyond the near one");
	expect_error("1 1000 100 2 4 16 50 0.1 0.3 0.6 0 0 0\n", RT_DIALECT_AUTO, 1, 12,
		     "the field of view along x (aspect 2 times 100 degrees) must stay below 180 degrees");
	expect_error("1 1000 80 1 4 16 0 0.1 0.3 0.6 0 0 0\n", RT_DIALECT_AUTO, 1, 18,
		     "checkerboard cell width must be > 0");
	/* A spotlight that looks at its own position. */
	expect_error("1 1000 80 1 4 16 50 0.1 0.3 0.6 0 0 1 5 5 5 0 5 5 5 30\n", RT_DIALECT_AUTO, 1, 51,
		     "the spotlight looks at its own position");
	/* A triangle is not a nearfar keyword. */
	snprintf(msg, sizeof(msg), "unknown object 'triangle' in the nearfar dialect; known objects: %s",
		 shape_keywords_in(RT_DIALECT_BIT(RT_DIALECT_NEARFAR)));
	expect_error("1 1000 80 1 4 16 50 0.1 0.3 0.6 1 triangle\n", RT_DIALECT_AUTO, 1, 35, msg);
}

static void test_dialects_notes(void **state)
{
	struct read r;

	(void)state;
	read_as("\xef\xbb\xbf" "0 16 0 0\n", RT_DIALECT_AUTO, &r);
	assert_int_equal(r.rc, 0);
	assert_int_equal(r.notes, 3);	/* the mark, the level, the dialect */
	assert_int_equal(scene_recursion(r.s), 1);
	assert_non_null(strstr(r.last_note, "recursion level 0 read as 1"));
	scene_destroy(r.s);
	/* The mark does not shift the columns of line 1. */
	expect_error("\xef\xbb\xbf" "x", RT_DIALECT_AUTO, 1, 1, "expected an integer (recursion level)");
}

SUPPORT_MAIN(SUPPORT_TESTS(test_dialects_detection_order, test_dialects_views,
			   test_dialects_nearfar_lights, test_dialects_forced,
			   test_dialects_errors, test_dialects_notes))
