/* The lexer: tokens and their positions, the three comment forms, CRLF,
 * and which tokens are numbers. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "syntax/lexer.h"
#include "support.h"

/* Checks that the next token is `text` at line:col. */
#define assert_token(lx, text, line, col) check_token((lx), (text), (line), (col), __FILE__, __LINE__)

static void check_token(struct lexer *lx, const char *text, int line, int col,
			const char *file, int at)
{
	struct token t = lexer_next(lx);

	if (!text) {
		if (t.text) {
			print_error("expected end of file, found '%.*s'\n", (int)t.len, t.text);
			_fail(file, at);
		}
	} else if (!t.text || t.len != strlen(text) || memcmp(t.text, text, t.len) != 0) {
		print_error("expected '%s', found '%.*s'\n", text, t.text ? (int)t.len : 3,
			    t.text ? t.text : "EOF");
		_fail(file, at);
	}
	if (t.line != line || t.col != col) {
		print_error("'%s' at %d:%d, expected %d:%d\n", text ? text : "EOF", t.line, t.col,
			    line, col);
		_fail(file, at);
	}
}

static void lex(struct lexer *lx, const char *text)
{
	lexer_init(lx, text, strlen(text));
}

static bool number_of(const char *text, double *out)
{
	struct token t;

	t.text = text;
	t.len = strlen(text);
	t.line = t.col = 1;
	return lexer_number(&t, out);
}

static bool looks_numeric(const char *text)
{
	struct token t;

	t.text = text;
	t.len = strlen(text);
	t.line = t.col = 1;
	return lexer_looks_numeric(&t);
}

static void test_lexer_tokens_and_positions(void **state)
{
	struct lexer lx;

	(void)state;
	lex(&lx, "4\n768\n\n  sphere\t40.0 0.0\n");
	assert_token(&lx, "4", 1, 1);
	assert_token(&lx, "768", 2, 1);
	assert_token(&lx, "sphere", 4, 3);
	/* A tab counts as one column. */
	assert_token(&lx, "40.0", 4, 10);
	assert_token(&lx, "0.0", 4, 15);
	/* The end of file sits after the last newline: line 5, column 1. */
	assert_token(&lx, NULL, 5, 1);
	/* And stays there. */
	assert_token(&lx, NULL, 5, 1);
}

static void test_lexer_empty_input(void **state)
{
	struct lexer lx;

	(void)state;
	lex(&lx, "");
	assert_token(&lx, NULL, 1, 1);
	lex(&lx, "  \t ");
	assert_token(&lx, NULL, 1, 5);
}

static void test_lexer_hash_comments(void **state)
{
	struct lexer lx;

	(void)state;
	lex(&lx, "# a comment 1 2 3\n1 # more\n2#glued\n3");
	assert_token(&lx, "1", 2, 1);
	assert_token(&lx, "2", 3, 1);
	assert_token(&lx, "3", 4, 1);
	assert_token(&lx, NULL, 4, 2);
}

static void test_lexer_slash_comments(void **state)
{
	struct lexer lx;

	(void)state;
	lex(&lx, "// comment\n10 // colour\n20//x\na/b 30");
	assert_token(&lx, "10", 2, 1);
	assert_token(&lx, "20", 3, 1);
	/* A single slash is part of a token. */
	assert_token(&lx, "a/b", 4, 1);
	assert_token(&lx, "30", 4, 5);
	assert_token(&lx, NULL, 4, 7);
}

static void test_lexer_lone_dash_comment(void **state)
{
	struct lexer lx;

	(void)state;
	/* The annotated style: a token that is exactly '-' ends the line. */
	lex(&lx, "40.0 0.0 10.0\t- center 1 2\n10.0 - radius\n-20 -x\n- 5\n-");
	assert_token(&lx, "40.0", 1, 1);
	assert_token(&lx, "0.0", 1, 6);
	assert_token(&lx, "10.0", 1, 10);
	assert_token(&lx, "10.0", 2, 1);
	/* A negative number, and '-x', are tokens, not comments. */
	assert_token(&lx, "-20", 3, 1);
	assert_token(&lx, "-x", 3, 5);
	/* "- 5" is a comment, and so is a '-' at the very end. */
	assert_token(&lx, NULL, 5, 2);
}

static void test_lexer_crlf(void **state)
{
	struct lexer lx;

	(void)state;
	lex(&lx, "4\r\n768\r\n\r\nsphere - c\r\n 1\r\n");
	assert_token(&lx, "4", 1, 1);
	assert_token(&lx, "768", 2, 1);
	assert_token(&lx, "sphere", 4, 1);
	assert_token(&lx, "1", 5, 2);
	assert_token(&lx, NULL, 6, 1);
}

static void test_lexer_numbers_accepted(void **state)
{
	double v;

	(void)state;
	assert_true(number_of("10", &v));
	assert_near(v, 10.0, 0.0);
	assert_true(number_of("-20.0", &v));
	assert_near(v, -20.0, 0.0);
	assert_true(number_of(".4", &v));
	assert_near(v, 0.4, 0.0);
	assert_true(number_of("1e2", &v));
	assert_near(v, 100.0, 0.0);
	assert_true(number_of("+3", &v));
	assert_near(v, 3.0, 0.0);
	assert_true(number_of("2.5E-1", &v));
	assert_near(v, 0.25, 0.0);
	assert_true(number_of("5.", &v));
	assert_near(v, 5.0, 0.0);
	assert_true(number_of("04", &v));
	assert_near(v, 4.0, 0.0);
	/* Underflow to a tiny (or zero) finite value is fine. */
	assert_true(number_of("1e-400", &v));
	assert_true(v >= 0.0 && v < 1e-300);
}

static void test_lexer_numbers_rejected(void **state)
{
	static const char *const bad[] = {
		"nan", "NAN", "-nan", "inf", "-inf", "Infinity", "0x10", "0x1p3", "1e999",
		"-1e999", "10abc", "1.0.0", "1e", "--5", "+", ".", "e5", "1-2", "sphere", "",
	};
	double v = 42.0;
	size_t i;

	(void)state;
	for (i = 0; i < sizeof(bad) / sizeof(bad[0]); i++) {
		if (number_of(bad[i], &v)) {
			print_error("'%s' was read as %g\n", bad[i], v);
			fail();
		}
	}
	/* A rejected number leaves the output alone. */
	assert_near(v, 42.0, 0.0);
}

static void test_lexer_number_token_too_long(void **state)
{
	char buf[RT_TOKEN_MAX + 2];
	double v;

	(void)state;
	/* RT_TOKEN_MAX digits is still a number; one more is not. */
	memset(buf, '0', RT_TOKEN_MAX);
	buf[RT_TOKEN_MAX - 1] = '7';
	buf[RT_TOKEN_MAX] = '\0';
	assert_true(number_of(buf, &v));
	assert_near(v, 7.0, 0.0);
	buf[RT_TOKEN_MAX] = '0';
	buf[RT_TOKEN_MAX + 1] = '\0';
	assert_false(number_of(buf, &v));
}

static void test_lexer_number_uses_token_length(void **state)
{
	struct lexer lx;
	struct token t;
	double v;

	(void)state;
	/* Tokens are not NUL-terminated: "12" in "12 34" is 12. */
	lex(&lx, "12 34");
	t = lexer_next(&lx);
	assert_true(lexer_number(&t, &v));
	assert_near(v, 12.0, 0.0);
	t = lexer_next(&lx);
	assert_true(lexer_number(&t, &v));
	assert_near(v, 34.0, 0.0);
	/* The end-of-file token is not a number. */
	t = lexer_next(&lx);
	assert_null(t.text);
	assert_false(lexer_number(&t, &v));
	assert_false(lexer_looks_numeric(&t));
}

static void test_lexer_looks_numeric(void **state)
{
	(void)state;
	/* Meant as numbers, even where not acceptable ones. */
	assert_true(looks_numeric("1"));
	assert_true(looks_numeric("nan"));
	assert_true(looks_numeric("inf"));
	assert_true(looks_numeric("0x10"));
	assert_true(looks_numeric("1e999"));
	assert_false(looks_numeric("sphere"));
	assert_false(looks_numeric("10abc"));
	assert_false(looks_numeric(""));
}

/* The value strtod gives for the token: the independent reference for
 * every number the lexer reads. */
static double strtod_of(const char *text, size_t len)
{
	char buf[64];

	assert_true(len < sizeof(buf));
	memcpy(buf, text, len);
	buf[len] = '\0';
	return strtod(buf, NULL);
}

/* The two readers of a number against strtod, bit for bit: lexer_number
 * always, the one-pass reader when it takes the text (it must, when
 * `simple`: at most 15 digits, no exponent). */
static void check_against_strtod(const char *text, bool simple)
{
	struct lexer lx;
	struct token t;
	double want = strtod_of(text, strlen(text)), v = 0.0;

	if (!number_of(text, &v) || memcmp(&v, &want, sizeof(v)) != 0) {
		print_error("lexer_number('%s') = %.17g, strtod gives %.17g\n", text, v, want);
		fail();
	}
	lexer_init(&lx, text, strlen(text));
	v = 0.0;
	if (!lexer_next_simple_number(&lx, &t, &v)) {
		if (!simple)
			return;
		print_error("lexer_next_simple_number declines '%s'\n", text);
		fail();
	}
	if (memcmp(&v, &want, sizeof(v)) != 0) {
		print_error("lexer_next_simple_number('%s') = %.17g, strtod gives %.17g\n", text, v,
			    want);
		fail();
	}
}

static void test_lexer_simple_numbers_match_strtod(void **state)
{
	/* Values that a sum of digit terms, a multiplication by a power of
	 * 0.1 or a float on the way would round differently from strtod. */
	static const char *const cases[] = {
		"0.1", "0.2", "0.3", "0.7", "1.1", "2.675", "0.00000000000001", "123456789012345",
		"99999999999999.9", ".123456789012345", "9.99999999999999", "-0.3", "+0.3", "-0",
		"-0.0", "5.", ".5", "0.07", "4.35", "8.1", "1.015", "0.000123", "1234567.891",
		"70.0", "-70", "0.0000002", "0.000002", "14.999999999999", "3.1415926535897",
	};
	uint64_t rng = 987654321;
	size_t i;
	int round;

	(void)state;
	for (i = 0; i < sizeof(cases) / sizeof(cases[0]); i++)
		check_against_strtod(cases[i], true);
	/* 16 digits and more, exponents: the general path (strtod itself). */
	check_against_strtod("0.000000000000001", false);
	check_against_strtod("1234567890123456789", false);
	check_against_strtod("2.5e-3", false);
	/* Random numbers of the simple form: a sign or none, 1 to 15
	 * digits, a point or none anywhere among them. */
	for (round = 0; round < 100000; round++) {
		char text[24];
		size_t len = 0;
		int digits, point, k;

		rng = rng * 6364136223846793005u + 1442695040888963407u;
		digits = (int)(rng >> 60) % 15 + 1;
		point = (int)((rng >> 40) % (uint64_t)(digits + 2)) - 1;	/* -1: none */
		if ((rng >> 20) % 4 == 0)
			text[len++] = (rng >> 22) % 2 ? '-' : '+';
		for (k = 0; k < digits; k++) {
			if (k == point)
				text[len++] = '.';
			rng = rng * 6364136223846793005u + 1442695040888963407u;
			text[len++] = (char)('0' + (rng >> 33) % 10);
		}
		if (point == digits)
			text[len++] = '.';
		text[len] = '\0';
		check_against_strtod(text, true);
	}
}

/* The one-pass number reader against lexer_next + lexer_number, on random
 * texts made of the characters that matter (digits, signs, points,
 * exponents, spaces, newlines, CR, comments, a letter, a NUL): whenever it
 * reads a number, the general path must read the same token, at the same
 * place, and leave the lexer in the same state, and both must give the
 * value strtod gives (the general path shares the fast one's digit loop,
 * so agreeing with it alone would prove nothing); when it declines, the
 * lexer must be untouched. */
static void test_lexer_simple_number_matches_general_path(void **state)
{
	static const char alphabet[] = "0123456789012345678901234567890123456789"
				       "+-..eE  \t\n\r#//x";
	uint64_t rng = 12345;
	int round, taken = 0;

	(void)state;
	for (round = 0; round < 200000; round++) {
		char text[40];
		size_t len, i;
		struct lexer fast, slow;
		struct token tf, ts;
		double vf = 0.0, vs = 0.0;

		rng = rng * 6364136223846793005u + 1442695040888963407u;
		len = (size_t)(rng >> 59) + 1;
		for (i = 0; i < len; i++) {
			rng = rng * 6364136223846793005u + 1442695040888963407u;
			/* One character in 64 is a NUL. */
			text[i] = (rng >> 27) % 64 == 0 ? '\0'
							 : alphabet[(rng >> 33) % (sizeof(alphabet) - 1)];
		}
		lexer_init(&fast, text, len);
		lexer_init(&slow, text, len);
		if (!lexer_next_simple_number(&fast, &tf, &vf)) {
			assert_ptr_equal(fast.pos, text);
			assert_int_equal(fast.line, 1);
			assert_ptr_equal(fast.line_start, text);
			continue;
		}
		taken++;
		ts = lexer_next(&slow);
		assert_non_null(ts.text);
		assert_ptr_equal(tf.text, ts.text);
		assert_int_equal(tf.len, ts.len);
		assert_int_equal(tf.line, ts.line);
		assert_int_equal(tf.col, ts.col);
		assert_true(lexer_number(&ts, &vs));
		assert_memory_equal(&vf, &vs, sizeof(vf));
		{
			double want = strtod_of(tf.text, tf.len);
			if (memcmp(&vf, &want, sizeof(vf)) != 0) {
				print_error("'%.*s' read as %.17g, strtod gives %.17g\n", (int)tf.len,
					    tf.text, vf, want);
				fail();
			}
		}
		assert_ptr_equal(fast.pos, slow.pos);
		assert_int_equal(fast.line, slow.line);
		assert_ptr_equal(fast.line_start, slow.line_start);
	}
	/* Enough of both outcomes to mean something. */
	print_message("simple numbers read in %d of 200000 texts\n", taken);
	assert_true(taken > 20000 && taken < 180000);
}

SUPPORT_MAIN(SUPPORT_TESTS(test_lexer_tokens_and_positions, test_lexer_empty_input,
			   test_lexer_hash_comments, test_lexer_slash_comments,
			   test_lexer_lone_dash_comment, test_lexer_crlf,
			   test_lexer_numbers_accepted, test_lexer_numbers_rejected,
			   test_lexer_number_token_too_long,
			   test_lexer_number_uses_token_length, test_lexer_looks_numeric,
			   test_lexer_simple_numbers_match_strtod,
			   test_lexer_simple_number_matches_general_path))
