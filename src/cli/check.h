/* What `whitted compare` and `whitted grade` share: their options, the
 * reference render, and the check of one submitted image (its figures
 * against the gate and the likely causes when it differs). */
#ifndef RT_CLI_CHECK_H
#define RT_CLI_CHECK_H

#include <stdbool.h>

#include "cli/scene_opts.h"
#include "whitted/grade.h"

/* Exit statuses besides tool.h's: the image differs from the reference. */
#define CHECK_EXIT_DIFFERS 3

struct check_options {
	struct cli_scene scene;
	int threads;
	bool grade;			/* whitted grade (else compare) */
	const char *diff_path;		/* compare --diff */
	bool json;			/* compare --json */
	const char *report_path;	/* grade -o */
	const char *csv_path;		/* grade --csv */
	char **images;			/* the IMAGE operands */
	int n_images;
};

/* Fills o from argv (argv[0] is the subcommand).  Returns 0, or the exit
 * status to stop with (usage error printed: 2; --help: -1 for exit 0). */
int check_args_parse(int argc, char **argv, bool grade, struct check_options *o);

struct check_reference {
	struct scene *scene;
	struct camera camera;
	struct grade_job job;
	struct image image;
	struct image truncated;		/* converted by truncation: made when first needed */
};

/* Loads the scene and renders the reference; on failure prints the error
 * and returns the exit status (1, or 2 for a bad camera). */
int check_reference_make(struct check_options *o, struct check_reference *ref);
void check_reference_free(struct check_reference *ref);

enum check_verdict {
	CHECK_MATCH,		/* within the gate */
	CHECK_DIFFERS,
	CHECK_UNREADABLE,	/* not an image, truncated, or of another size */
};

/* How well the best cause explains a differing image. */
enum check_explained {
	CHECK_EXPLAINED,	/* the cause's image matches the submission within the gate */
	CHECK_CLOSE,		/* much closer than the reference, not within the gate */
	CHECK_NONE,		/* no cause comes close */
};

struct check_result {
	enum check_verdict verdict;
	struct grade_figures fig;	/* against the reference (for a truncated match,
					 * against its truncated conversion) */
	struct grade_figures fig_rounded;	/* against the rounded reference */
	bool truncated;			/* nearer the reference converted by truncation */
	struct grade_rank ranks[RT_CAUSE_COUNT];
	size_t n_ranks;
	enum check_explained explained;
	struct image image;		/* the submission (empty when unreadable) */
	struct diag error;		/* why it is unreadable */
};

/* Reads and checks one image.  Returns 0 with res filled (an unreadable
 * image is a verdict, not a failure), or a negative status when the check
 * itself failed (out of memory, interrupted) with d filled. */
int check_image(struct check_reference *ref, const char *path, struct check_result *res,
		struct diag *d);
void check_result_free(struct check_result *res);

/* One sentence on the likely cause ("matches the reference with ...: fix
 * ...", "closest: ...", "none of the known mistakes comes close"). */
void check_diagnosis(const struct check_reference *ref, const struct check_result *res,
		     char *buf, size_t size);

/* The HTML report of grade: the reference, and per image its row, the
 * figures, the submission and the difference.  Fails with the diag filled. */
int check_write_report(const struct check_options *o, const struct check_reference *ref,
		       const struct check_result *res, struct diag *d);

#endif
