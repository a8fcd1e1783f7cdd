/* Text appended to a fixed buffer: each piece that fits is added, and the
 * buffer is marked full (and keeps what fitted) once one does not. */
#ifndef RT_BASE_TEXT_H
#define RT_BASE_TEXT_H

#include <stdbool.h>
#include <stddef.h>

struct text_buf {
	char *buf;
	size_t size, len;
	bool full;
};

/* Starts an empty text in buf (size 0: full from the start). */
void text_init(struct text_buf *t, char *buf, size_t size);
void text_printf(struct text_buf *t, const char *fmt, ...)
#if defined(__GNUC__)
	__attribute__((format(printf, 2, 3)))
#endif
	;
/* Appends s as one POSIX shell word: unchanged when it is made of safe
 * characters, otherwise in single quotes (a quote in it as '\''); a word
 * starting with '-' gets "./" before it, so that it is not an option. */
void text_shell_word(struct text_buf *t, const char *s);

/* words[0..n) for a message, each after prefix: "a, b or c" (".a, .b or
 * .c"); as much as fits in buf (size > 0: always ended).  Returns buf. */
const char *text_word_list(char *buf, size_t size, const char *prefix, const char *const *words,
			   size_t n);

/* Whether s is one of words[0..n) (strcmp equal). */
bool text_among(const char *s, const char *const *words, size_t n);

/* The length (1 to 4) of the UTF-8 sequence s starts with, or 0 when its
 * first byte starts none (a NUL inside ends a sequence as any byte that
 * is no continuation does). */
int text_utf8_length(const unsigned char *s);

#endif
