/* Diagnostics: diag_set's return value and fields, diag_format's forms. */
#include <string.h>

#include "support.h"

static void test_diag_set_fills_and_returns_negative(void **state)
{
	struct diag d;
	int rc;

	(void)state;
	diag_clear(&d);
	rc = diag_set(&d, RT_E_RANGE, "scene.txt", 12, 5, "radius %d", 3);
	assert_int_equal(rc, -RT_E_RANGE);
	assert_string_equal(d.file, "scene.txt");
	assert_int_equal(d.line, 12);
	assert_int_equal(d.col, 5);
	assert_string_equal(d.msg, "radius 3");
	/* A NULL diag is allowed: only the code comes back. */
	assert_int_equal(diag_set(NULL, RT_E_IO, "x", 1, 1, "y"), -RT_E_IO);
	/* A NULL file becomes the empty string. */
	diag_set(&d, RT_E_NOMEM, NULL, 0, 0, "out of memory");
	assert_string_equal(d.file, "");
}

static void test_diag_clear_zeroes(void **state)
{
	struct diag d;

	(void)state;
	memset(&d, 'x', sizeof(d));
	diag_clear(&d);
	assert_string_equal(d.file, "");
	assert_string_equal(d.msg, "");
	assert_int_equal(d.line, 0);
	assert_int_equal(d.col, 0);
}

static void test_diag_format_forms(void **state)
{
	static const struct {
		enum rt_err code;
		const char *file;
		int line, col;
		const char *msg, *severity, *want;
	} forms[] = {
		{ RT_E_SYNTAX, "scene.txt", 12, 5, "expected a number, found 'abc'", "error",
		  "scene.txt:12:5: error: expected a number, found 'abc'" },
		{ RT_E_SYNTAX, "scene.txt", 40, 0, "ignoring 55 lines after the last light", "note",
		  "scene.txt:40: note: ignoring 55 lines after the last light" },
		/* A note about a whole file starts with the file, as notes do. */
		{ RT_OK, "scene.txt", 0, 0, "read as the spot dialect (4 point lights, 1 spotlight)",
		  "note", "scene.txt: note: read as the spot dialect (4 point lights, 1 spotlight)" },
		{ RT_E_IO, "out.png", 0, 0, "cannot write: No such file or directory", "error",
		  "whitted: error: out.png: cannot write: No such file or directory" },
		{ RT_E_INVALID, "", 3, 4, "the up vector is zero", "error",
		  "whitted: error: the up vector is zero" },
	};
	char buf[1024];
	struct diag d;
	size_t i;

	(void)state;
	for (i = 0; i < sizeof(forms) / sizeof(forms[0]); i++) {
		diag_set(&d, forms[i].code, forms[i].file, forms[i].line, forms[i].col, "%s",
			 forms[i].msg);
		diag_format(&d, "whitted", forms[i].severity, buf, sizeof(buf));
		assert_string_equal(buf, forms[i].want);
	}
}

static void test_diag_format_truncates(void **state)
{
	char buf[16];
	struct diag d;

	(void)state;
	diag_set(&d, RT_E_SYNTAX, "scene.txt", 1, 2, "a long message that does not fit");
	diag_format(&d, "whitted", "error", buf, sizeof(buf));
	assert_int_equal(strlen(buf), sizeof(buf) - 1);
	assert_memory_equal(buf, "scene.txt:1:2: ", 15);
}

SUPPORT_MAIN(SUPPORT_TESTS(test_diag_set_fills_and_returns_negative, test_diag_clear_zeroes,
			   test_diag_format_forms, test_diag_format_truncates))
