/* Appending formatted text to a fixed buffer, for the canonical settings
 * text and the viewer's reproducing command (and its shell quoting). */
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "base/text.h"

void text_init(struct text_buf *t, char *buf, size_t size)
{
	t->buf = buf;
	t->size = size;
	t->len = 0;
	t->full = size == 0;
	if (size > 0)
		buf[0] = '\0';
}

void text_printf(struct text_buf *t, const char *fmt, ...)
{
	va_list ap;
	int n;

	if (t->full)
		return;
	va_start(ap, fmt);
	n = vsnprintf(t->buf + t->len, t->size - t->len, fmt, ap);
	va_end(ap);
	if (n < 0 || (size_t)n >= t->size - t->len)
		t->full = true;		/* vsnprintf kept what fitted */
	else
		t->len += (size_t)n;
}

void text_shell_word(struct text_buf *t, const char *s)
{
	static const char safe[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
				   "0123456789_./+,=:@%-";
	const char *p;

	/* A word starting with '-' would be read as an option. */
	if (s[0] == '-')
		text_printf(t, "./");
	if (s[0] != '\0' && s[strspn(s, safe)] == '\0') {
		text_printf(t, "%s", s);
		return;
	}
	text_printf(t, "'");
	for (p = s; *p; p++) {
		if (*p == '\'')
			text_printf(t, "'\\''");
		else
			text_printf(t, "%c", *p);
	}
	text_printf(t, "'");
}

int text_utf8_length(const unsigned char *s)
{
	int n, k;
	unsigned cp;

	if (s[0] < 0x80)
		return 1;
	if (s[0] >= 0xc2 && s[0] <= 0xdf)
		n = 2, cp = s[0] & 0x1fu;
	else if (s[0] >= 0xe0 && s[0] <= 0xef)
		n = 3, cp = s[0] & 0x0fu;
	else if (s[0] >= 0xf0 && s[0] <= 0xf4)
		n = 4, cp = s[0] & 0x07u;
	else
		return 0;
	for (k = 1; k < n; k++) {
		if ((s[k] & 0xc0) != 0x80)
			return 0;
		cp = cp << 6 | (s[k] & 0x3fu);
	}
	/* Overlong forms, surrogates and beyond U+10FFFF are not UTF-8. */
	if ((n == 3 && cp < 0x800) || (n == 4 && (cp < 0x10000 || cp > 0x10ffff)) ||
	    (cp >= 0xd800 && cp <= 0xdfff))
		return 0;
	return n;
}

const char *text_word_list(char *buf, size_t size, const char *prefix, const char *const *words,
			   size_t n)
{
	size_t used = 0, i;

	if (size > 0)
		buf[0] = '\0';
	for (i = 0; i < n && used < size; i++) {
		int k = snprintf(buf + used, size - used, "%s%s%s",
				 i == 0 ? "" : i + 1 == n ? " or " : ", ", prefix, words[i]);
		used += k > 0 ? (size_t)k : 0;
	}
	return buf;
}

bool text_among(const char *s, const char *const *words, size_t n)
{
	size_t i;

	for (i = 0; i < n; i++)
		if (strcmp(words[i], s) == 0)
			return true;
	return false;
}
