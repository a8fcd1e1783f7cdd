/* "Did you mean": the nearest of a closed list of words (subcommands, long
 * options) to a word that is none of them, for the usage errors of every
 * program. */
#ifndef RT_CLI_SUGGEST_H
#define RT_CLI_SUGGEST_H

#include <stddef.h>

/* The candidate nearest to word (edit distance: insertions, deletions,
 * substitutions and swaps of two neighbouring letters), when it is near
 * enough to be a slip (at most 1 for words of up to 4 letters, 2 up to 8,
 * 3 beyond) and no other candidate is as near; else NULL. */
const char *cli_suggest(const char *word, const char *const *candidates, size_t n);

#endif
