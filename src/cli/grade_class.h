/* whitted grade's class: every submission's check, its student, scene,
 * points and (for the report) its pictures, and what the class as a
 * whole did. */
#ifndef RT_CLI_GRADE_CLASS_H
#define RT_CLI_GRADE_CLASS_H

#include "cli/check.h"
#include "cli/grade_inputs.h"
#include "cli/grade_marks.h"

/* A picture kept for the report, as PNG bytes (the images themselves are
 * freed row by row: a class of a hundred 768-pixel images is gigabytes). */
struct grade_png {
	unsigned char *data;
	size_t len;
	int width, height;
};

struct grade_row {
	const struct grade_input *in;
	struct check_result res;	/* its images freed after the check */
	double points;
	char diagnosis[1200];
	char best[160];			/* the best explanation's ids: "camera+no-shadows" */
	char camera[240];		/* the camera found ("" when not moved) */
	char objects[400];		/* the object-by-object line */
	/* The likeliest causes in words, kept for the report. */
	struct grade_row_cause {
		char id[96], words[240], fix[480];
		double psnr;
		bool estimated, explains, first_equal;
	} causes[5];
	int n_causes;
	struct grade_png reference, submission, difference;
};

struct grade_class {
	const struct check_options *o;
	struct check_reference refs[CHECK_MAX_SCENES];
	int n_refs;
	struct grade_inputs inputs;
	struct grade_row *rows;
	size_t n_rows;
	struct grade_marks marks;
};

/* "match", "differs" or "unreadable". */
const char *grade_verdict_name(enum check_verdict v);
/* The outcome a row is counted under in the summary and the points:
 * "match", "camera", a cause id (or a pair's), "close", "differs",
 * "unreadable". */
const char *grade_outcome(const struct grade_row *r, char *buf, size_t size);

/* How many rows of each outcome, in the order first met (the first
 * GRADE_OUTCOMES outcomes; rows of any later one are not counted). */
#define GRADE_OUTCOMES 64
struct grade_outcome_tally {
	char names[GRADE_OUTCOMES][160];
	size_t counts[GRADE_OUTCOMES];
	size_t n;
};
void grade_outcome_tally(const struct grade_class *c, struct grade_outcome_tally *t);

/* The CSV file of the rows. */
int grade_write_csv(const struct grade_class *c, const char *path, struct diag *d);
/* The HTML report (grade_html.c). */
int grade_write_report(const struct grade_class *c, const char *path, struct diag *d);

#endif
