/* Filling and formatting diagnostics. */
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "diag.h"

void diag_clear(struct diag *d)
{
	memset(d, 0, sizeof(*d));
}

int diag_set(struct diag *d, enum rt_err err, const char *file, int line, int col,
	     const char *fmt, ...)
{
	va_list ap;

	if (d) {
		snprintf(d->file, sizeof(d->file), "%s", file ? file : "");
		d->line = line;
		d->col = col;
		va_start(ap, fmt);
		vsnprintf(d->msg, sizeof(d->msg), fmt, ap);
		va_end(ap);
	}
	return -(int)err;
}

void diag_format(const struct diag *d, const char *prog, const char *kind, char *buf,
		 unsigned long size)
{
	if (d->file[0] == '\0')
		snprintf(buf, size, "%s: %s: %s", prog, kind, d->msg);
	else if (d->line <= 0)
		snprintf(buf, size, "%s: %s: %s: %s", prog, kind, d->file, d->msg);
	else if (d->col <= 0)
		snprintf(buf, size, "%s:%d: %s: %s", d->file, d->line, kind, d->msg);
	else
		snprintf(buf, size, "%s:%d:%d: %s: %s", d->file, d->line, d->col, kind, d->msg);
}
