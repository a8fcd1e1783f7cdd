/* Strict value parsers for option values and keyframe files: the whole
 * string, finite, in range; the message names the option (`opt`). */
#ifndef RT_NUMBER_H
#define RT_NUMBER_H

#include <stddef.h>

#include "whitted/diag.h"

int number_parse_long(const char *opt, const char *arg, long lo, long hi, long *out,
		      struct diag *d);
int number_parse_double(const char *opt, const char *arg, double *out, struct diag *d);
/* n comma-separated finite numbers. */
int number_parse_list(const char *opt, const char *arg, double *out, int n, struct diag *d);

/* v with the fewest of 15, 16 or 17 significant digits that strtod reads
 * back as v (17 always do): 0.4, not 0.40000000000000002. */
void number_format_shortest(char *buf, size_t size, double v);

#endif
