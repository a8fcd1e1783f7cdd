/* A row's verdict and outcome in one word, as the summary, the CSV file
 * and the HTML report all print them. */
#include <stdio.h>
#include <string.h>

#include "cli/grade_class.h"

const char *grade_verdict_name(enum check_verdict v)
{
	return v == CHECK_MATCH ? "match" : v == CHECK_DIFFERS ? "differs" : "unreadable";
}

const char *grade_outcome(const struct grade_row *r, char *buf, size_t size)
{
	const struct check_result *res = &r->res;

	if (res->verdict == CHECK_UNREADABLE)
		return "unreadable";
	if (res->verdict == CHECK_MATCH)
		return res->moved ? "camera" : "match";
	if (res->explained == CHECK_EXPLAINED && res->n_ranks > 0) {
		snprintf(buf, size, "%s", r->best);
		return buf;
	}
	return res->explained == CHECK_CLOSE ? "close" : "differs";
}

void grade_outcome_tally(const struct grade_class *c, struct grade_outcome_tally *t)
{
	char buf[160];
	size_t k, j;

	t->n = 0;
	for (k = 0; k < c->n_rows; k++) {
		const char *o = grade_outcome(&c->rows[k], buf, sizeof(buf));
		for (j = 0; j < t->n && strcmp(t->names[j], o) != 0; j++)
			;
		if (j == t->n && t->n < GRADE_OUTCOMES) {
			snprintf(t->names[t->n], sizeof(t->names[t->n]), "%s", o);
			t->counts[t->n++] = 0;
		}
		if (j < t->n)
			t->counts[j]++;
	}
}
