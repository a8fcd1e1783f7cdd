/* A row's verdict and outcome in one word, as the summary, the CSV file
 * and the HTML report all print them. */
#include <stdio.h>

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
