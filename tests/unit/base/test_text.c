/* Text helpers: the length of a UTF-8 sequence (every width, and each
 * way a byte string fails to be one), and a shell word's quoting. */
#include <string.h>

#include "base/text.h"
#include "support.h"

static int len_of(const char *bytes)
{
	return text_utf8_length((const unsigned char *)bytes);
}

static void test_text_utf8_length(void **state)
{
	(void)state;
	assert_int_equal(len_of("a"), 1);
	assert_int_equal(len_of("\xc3\xa9x"), 2);		/* U+00E9 */
	assert_int_equal(len_of("\xe2\x82\xac"), 3);		/* U+20AC */
	assert_int_equal(len_of("\xf0\x9f\x98\x80"), 4);	/* U+1F600 */
	assert_int_equal(len_of("\xf4\x8f\xbf\xbf"), 4);	/* U+10FFFF, the last */
	assert_int_equal(len_of("\x80"), 0);			/* a continuation alone */
	assert_int_equal(len_of("\xc0\x80"), 0);		/* overlong NUL */
	assert_int_equal(len_of("\xc1\xbf"), 0);		/* overlong */
	assert_int_equal(len_of("\xe0\x9f\xbf"), 0);		/* overlong U+07FF */
	assert_int_equal(len_of("\xf0\x8f\xbf\xbf"), 0);	/* overlong U+FFFF */
	assert_int_equal(len_of("\xed\xa0\x80"), 0);		/* surrogate U+D800 */
	assert_int_equal(len_of("\xf4\x90\x80\x80"), 0);	/* U+110000 */
	assert_int_equal(len_of("\xf5\x80\x80\x80"), 0);
	assert_int_equal(len_of("\xe2\x82"), 0);		/* cut by the NUL */
	assert_int_equal(len_of("\xe2\x82x"), 0);		/* cut by a byte */
}

static void test_text_shell_word(void **state)
{
	char buf[64];
	struct text_buf t;

	(void)state;
	text_init(&t, buf, sizeof(buf));
	text_shell_word(&t, "scene.txt");
	text_printf(&t, " ");
	text_shell_word(&t, "it's here");
	text_printf(&t, " ");
	text_shell_word(&t, "-o");
	assert_string_equal(buf, "scene.txt 'it'\\''s here' ./-o");
	assert_false(t.full);
}

/* A message's list of words: one, two, three, with a prefix, and cut
 * short by the buffer (always ended). */
static void test_text_word_list(void **state)
{
	static const char *const w[] = { "png", "bmp", "ppm" };
	char buf[64], small[6];

	(void)state;
	assert_string_equal(text_word_list(buf, sizeof(buf), "", w, 1), "png");
	assert_string_equal(text_word_list(buf, sizeof(buf), "", w, 2), "png or bmp");
	assert_string_equal(text_word_list(buf, sizeof(buf), "", w, 3), "png, bmp or ppm");
	assert_string_equal(text_word_list(buf, sizeof(buf), ".", w, 3), ".png, .bmp or .ppm");
	assert_string_equal(text_word_list(buf, sizeof(buf), "", w, 0), "");
	assert_string_equal(text_word_list(small, sizeof(small), ".", w, 3), ".png,");
}

/* Membership by whole string: a prefix or a longer string is not one of
 * the words, and no words hold nothing. */
static void test_text_among(void **state)
{
	static const char *const w[] = { "a/p.so", "b/q.so" };

	(void)state;
	assert_true(text_among("a/p.so", w, 2));
	assert_true(text_among("b/q.so", w, 2));
	assert_false(text_among("b/q.so", w, 1));
	assert_false(text_among("a/p", w, 2));
	assert_false(text_among("a/p.so.1", w, 2));
	assert_false(text_among("a/p.so", w, 0));
}

SUPPORT_MAIN(SUPPORT_TESTS(test_text_utf8_length, test_text_shell_word, test_text_word_list,
			   test_text_among))
