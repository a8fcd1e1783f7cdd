/* grade's points table (grade_marks.c has its format). */
#ifndef RT_CLI_GRADE_MARKS_H
#define RT_CLI_GRADE_MARKS_H

#include "whitted/diag.h"

#define GRADE_MARKS_MAX_CAUSES 64

struct grade_marks_cause {
	char id[48];
	double points;
};

struct grade_marks {
	double match, camera, cause, close, differs, unreadable;
	struct grade_marks_cause causes[GRADE_MARKS_MAX_CAUSES];
	int n_causes;
};

/* The table whitted grade uses without --marks. */
void grade_marks_default(struct grade_marks *m);
/* The defaults with path's lines over them; a bad line fails with
 * FILE:LINE:COL. */
int grade_marks_read(const char *path, struct grade_marks *m, struct diag *d);
/* The points of a mistake by its id ("no-shadows"): its own line, else
 * cause's. */
double grade_marks_cause(const struct grade_marks *m, const char *id);

#endif
