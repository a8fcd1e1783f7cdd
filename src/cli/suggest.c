/* "Did you mean" (suggest.h): the optimal string alignment distance
 * between the word and each candidate, computed in two rows of a small
 * table (the words are short: options, subcommands). */
#include <stdbool.h>
#include <stdio.h>
#include <string.h>

#include "cli/suggest.h"

#define SUGGEST_MAX 64	/* longer words are not compared */

static size_t suggest_min3(size_t a, size_t b, size_t c)
{
	size_t m = a < b ? a : b;

	return m < c ? m : c;
}

/* The edit distance of a and b with adjacent swaps (optimal string
 * alignment), or SUGGEST_MAX when either is too long. */
static size_t suggest_distance(const char *a, const char *b)
{
	size_t la = strlen(a), lb = strlen(b), i, j;
	size_t d[3][SUGGEST_MAX + 1];

	if (la > SUGGEST_MAX || lb > SUGGEST_MAX)
		return SUGGEST_MAX;
	for (j = 0; j <= lb; j++)
		d[0][j] = j;
	for (i = 1; i <= la; i++) {
		size_t *row = d[i % 3], *up = d[(i - 1) % 3], *up2 = d[(i + 1) % 3];

		row[0] = i;
		for (j = 1; j <= lb; j++) {
			size_t cost = a[i - 1] != b[j - 1];

			row[j] = suggest_min3(up[j] + 1, row[j - 1] + 1, up[j - 1] + cost);
			if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1] &&
			    up2[j - 2] + 1 < row[j])
				row[j] = up2[j - 2] + 1;
		}
	}
	return d[la % 3][lb];
}

const char *cli_suggest(const char *word, const char *const *candidates, size_t n)
{
	size_t len = strlen(word), limit = len <= 4 ? 1 : len <= 8 ? 2 : 3, best = limit + 1, i;
	const char *found = NULL;
	bool tie = false;

	for (i = 0; i < n; i++) {
		size_t dist = suggest_distance(word, candidates[i]);

		if (dist < best) {
			best = dist;
			found = candidates[i];
			tie = false;
		} else if (dist == best && found && strcmp(found, candidates[i]) != 0) {
			tie = true;
		}
	}
	return tie ? NULL : found;
}
