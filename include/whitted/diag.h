/* Status codes and diagnostics.  Library functions return 0 or a negative
 * enum rt_err and describe the failure in a struct diag; only the CLI prints
 * one and picks an exit code. */
#ifndef RT_DIAG_H
#define RT_DIAG_H

enum rt_err {
	RT_OK = 0,
	RT_E_SYNTAX,		/* the scene text does not fit the format */
	RT_E_RANGE,		/* a value is outside its allowed range or a limit */
	RT_E_NOMEM,
	RT_E_IO,
	RT_E_INVALID,		/* a bad argument from the caller (camera, options) */
	RT_E_INTERRUPTED,
};

#define RT_DIAG_FILE_MAX 4096	/* PATH_MAX: a long path is never cut short */
#define RT_DIAG_MSG_MAX 512

struct diag {
	char file[RT_DIAG_FILE_MAX];	/* empty when the error has no file */
	int line, col;			/* 1-based; 0 when unknown */
	char msg[RT_DIAG_MSG_MAX];
};

void diag_clear(struct diag *d);

/* Fills d and returns -err, so that `return diag_set(...)` reads naturally. */
int diag_set(struct diag *d, enum rt_err err, const char *file, int line, int col,
	     const char *fmt, ...)
#if defined(__GNUC__)
	__attribute__((format(printf, 6, 7)))
#endif
	;

/* diag_set for a message that has no place in a file (a bad option, out
 * of memory). */
int diag_fail(struct diag *d, enum rt_err err, const char *fmt, ...)
#if defined(__GNUC__)
	__attribute__((format(printf, 3, 4)))
#endif
	;
/* Formats "FILE:LINE:COL: KIND: MSG" (or "FILE:LINE: KIND: MSG" without a
 * column); a diagnostic without a line is "PROG: KIND: FILE: MSG" (a note
 * about a whole file "FILE: note: MSG"), and one without a file
 * "PROG: KIND: MSG". */
void diag_format(const struct diag *d, const char *prog, const char *kind, char *buf,
		 unsigned long size);

/* Receives notes (trailing text, degenerate shapes) while a library call
 * goes on; the caller decides whether and how to show them. */
typedef void diag_note_fn(void *ctx, const struct diag *note);

#endif
