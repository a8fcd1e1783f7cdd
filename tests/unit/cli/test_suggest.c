/* cli_suggest (src/cli/suggest.c): a slip of one letter, a swap of two, a
 * missing or an extra letter finds the word; a word too far, an empty
 * list, or two candidates as near find none; the limit grows with the
 * word's length. */
#include <string.h>

#include "cli/suggest.h"
#include "support.h"

static const char *const subcommands[] = { "merge", "compare", "grade", "help" };
static const char *const options[] = { "size", "samples", "stats", "recursion", "output",
					 "floor", "floor-texture", "no-floor", "glass" };

#define N(a) (sizeof(a) / sizeof((a)[0]))

static void assert_suggests(const char *word, const char *const *c, size_t n, const char *want)
{
	const char *got = cli_suggest(word, c, n);

	if (!want) {
		if (got)
			fail_msg("'%s': expected no suggestion, got '%s'", word, got);
		return;
	}
	if (!got || strcmp(got, want) != 0)
		fail_msg("'%s': expected '%s', got '%s'", word, want, got ? got : "(none)");
}

static void test_suggest_slips(void **state)
{
	(void)state;
	assert_suggests("comapre", subcommands, N(subcommands), "compare");	/* a swap */
	assert_suggests("compar", subcommands, N(subcommands), "compare");	/* a letter short */
	assert_suggests("comparee", subcommands, N(subcommands), "compare");	/* one more */
	assert_suggests("grdae", subcommands, N(subcommands), "grade");
	assert_suggests("marge", subcommands, N(subcommands), "merge");	/* one wrong */
	assert_suggests("hlep", subcommands, N(subcommands), "help");
	assert_suggests("samles", options, N(options), "samples");
	assert_suggests("recusrion", options, N(options), "recursion");
	assert_suggests("ouptut", options, N(options), "output");
	assert_suggests("floor-textrue", options, N(options), "floor-texture");
	assert_suggests("nofloor", options, N(options), "no-floor");
}

static void test_suggest_refusals(void **state)
{
	(void)state;
	assert_suggests("view", subcommands, N(subcommands), NULL);
	assert_suggests("bogus", options, N(options), NULL);
	assert_suggests("x", options, N(options), NULL);
	assert_suggests("", options, N(options), NULL);
	assert_suggests("compare", subcommands, 0, NULL);
	/* Two letters off a short word is too far: "sz" is not "size". */
	assert_suggests("sz", options, N(options), NULL);
	/* As near to two words: no guess ("stas": stats and... size? no;
	 * "flor" is one from "floor" only). */
	assert_suggests("flor", options, N(options), "floor");
	{
		static const char *const two[] = { "abcd", "abce" };
		assert_suggests("abcf", two, 2, NULL);
	}
	/* A word longer than the table's rows. */
	{
		char long_word[200];
		memset(long_word, 'a', sizeof(long_word) - 1);
		long_word[sizeof(long_word) - 1] = '\0';
		assert_suggests(long_word, options, N(options), NULL);
	}
}

SUPPORT_MAIN(SUPPORT_TESTS(test_suggest_slips, test_suggest_refusals))
