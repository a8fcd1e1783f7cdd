/* Strict reading of numbers given as text outside scene files (option
 * values, keyframe files): the whole string, finite, in range, with a
 * message that names the option. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <stdio.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/number.h"

int number_parse_double(const char *opt, const char *arg, double *out, struct diag *d)
{
	char *end;
	double v;

	errno = 0;
	v = strtod(arg, &end);
	if (end == arg || *end != '\0' || !isfinite(v) || arg[strspn(arg, "0123456789+-.eE")] != '\0')
		return diag_fail(d, RT_E_INVALID, "%s: expected a finite number, found '%s'",
				opt, arg);
	*out = v;
	return 0;
}

int number_parse_long(const char *opt, const char *arg, long lo, long hi, long *out, struct diag *d)
{
	char *end;
	long v;

	errno = 0;
	v = strtol(arg, &end, 10);
	if (end == arg || *end != '\0' || errno == ERANGE || v < lo || v > hi ||
	    arg[strspn(arg, "0123456789+-")] != '\0')
		return diag_fail(d, RT_E_INVALID,
				"%s: expected an integer from %ld to %ld, found '%s'", opt, lo, hi, arg);
	*out = v;
	return 0;
}

int number_parse_list(const char *opt, const char *arg, double *out, int n, struct diag *d)
{
	char buf[256];
	char *item = buf;
	int i;

	if (strlen(arg) >= sizeof(buf))
		goto out_bad;
	strcpy(buf, arg);
	for (i = 0; i < n; i++) {
		char *comma = strchr(item, ',');
		if ((comma == NULL) != (i == n - 1))
			goto out_bad;
		if (comma)
			*comma = '\0';
		if (number_parse_double(opt, item, &out[i], d) < 0)
			goto out_bad;
		if (comma)
			item = comma + 1;
	}
	return 0;
out_bad:
	return diag_fail(d, RT_E_INVALID, "%s: expected %d comma-separated numbers%s, found '%s'",
			opt, n, n == 3 ? " X,Y,Z" : "", arg);
}


void number_format_shortest(char *buf, size_t size, double v)
{
	int digits;

	for (digits = 15; digits < 17; digits++) {
		snprintf(buf, size, "%.*g", digits, v);
		if (strtod(buf, NULL) == v)
			return;
	}
	snprintf(buf, size, "%.17g", v);
}
