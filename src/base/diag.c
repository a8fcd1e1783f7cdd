/* Filling and formatting diagnostics. */
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "whitted/diag.h"

void diag_clear(struct diag *d)
{
	memset(d, 0, sizeof(*d));
}

static int diag_vset(struct diag *d, enum rt_err err, const char *file, int line, int col,
		     const char *fmt, va_list ap)
{
	if (d) {
		snprintf(d->file, sizeof(d->file), "%s", file ? file : "");
		d->line = line;
		d->col = col;
		vsnprintf(d->msg, sizeof(d->msg), fmt, ap);
	}
	return -(int)err;
}

int diag_set(struct diag *d, enum rt_err err, const char *file, int line, int col,
	     const char *fmt, ...)
{
	va_list ap;
	int rc;

	va_start(ap, fmt);
	rc = diag_vset(d, err, file, line, col, fmt, ap);
	va_end(ap);
	return rc;
}

int diag_fail(struct diag *d, enum rt_err err, const char *fmt, ...)
{
	va_list ap;
	int rc;

	va_start(ap, fmt);
	rc = diag_vset(d, err, "", 0, 0, fmt, ap);
	va_end(ap);
	return rc;
}

void diag_format(const struct diag *d, const char *prog, const char *kind, char *buf,
		 unsigned long size)
{
	if (d->file[0] == '\0')
		snprintf(buf, size, "%s: %s: %s", prog, kind, d->msg);
	else if (d->line <= 0 && strcmp(kind, "note") == 0)
		snprintf(buf, size, "%s: %s: %s", d->file, kind, d->msg);
	else if (d->line <= 0)
		snprintf(buf, size, "%s: %s: %s: %s", prog, kind, d->file, d->msg);
	else if (d->col <= 0)
		snprintf(buf, size, "%s:%d: %s: %s", d->file, d->line, kind, d->msg);
	else
		snprintf(buf, size, "%s:%d:%d: %s: %s", d->file, d->line, d->col, kind, d->msg);
}
