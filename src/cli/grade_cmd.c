/* whitted grade: a class's images (files, folders, zip files; one or more
 * scenes each) against their references, one row each, with the points
 * of a table, a summary of the class, a CSV file and an HTML report. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "base/alloc.h"
#include "cli/cli.h"
#include "cli/grade_class.h"
#include "cli/tool.h"

/* The points of a row by the table. */
static double grade_points_of(const struct grade_class *c, const struct grade_row *r)
{
	const struct grade_marks *m = &c->marks;
	const struct check_result *res = &r->res;
	const struct check_reference *ref = &c->refs[r->in->scene];
	enum clamp_mode clamp = ref->base.settings.clamp;

	if (res->verdict == CHECK_UNREADABLE)
		return m->unreadable;
	if (res->verdict == CHECK_MATCH)
		return res->moved ? m->camera : m->match;
	if (res->explained == CHECK_EXPLAINED && res->n_ranks > 0) {
		const struct grade_rank *b = &res->ranks[0];
		double p = grade_marks_cause(m, grade_cause_text(b->cause, clamp)->id);
		if (b->also != RT_CAUSE_NONE) {
			double q = grade_marks_cause(m, grade_cause_text(b->also, clamp)->id);
			p = (p < q ? p : q) - (m->cause - m->close);
		}
		return p;
	}
	return res->explained == CHECK_CLOSE ? m->close : m->differs;
}

/* An output's path, checked before the first image is graded: its
 * folder exists and takes a new file, and it is no folder itself. */
static int grade_check_output(const char *path, const char *what)
{
	char dir[4096];
	const char *slash = strrchr(path, '/');
	size_t n = slash ? (size_t)(slash - path) : 0;
	char *probe;
	int fd;

	if (n >= sizeof(dir) - 16)
		return tool_usage_error("%s: the path '%s' is too long", what, path);
	if (slash) {
		memcpy(dir, path, n ? n : 1);
		dir[n ? n : 1] = '\0';
	} else {
		strcpy(dir, ".");
	}
	if (access(path, F_OK) == 0 && access(path, W_OK) != 0) {
		fprintf(stderr, "whitted: error: %s: cannot write %s '%s': %s\n", what, what, path,
			strerror(errno));
		return TOOL_EXIT_FAILURE;
	}
	probe = rt_malloc(strlen(dir) + 32);
	if (!probe)
		return TOOL_EXIT_FAILURE;
	sprintf(probe, "%s/.whitted-grade-XXXXXX", dir);
	fd = mkstemp(probe);
	if (fd < 0) {
		fprintf(stderr, "whitted: error: %s: cannot write %s '%s': %s (checked before grading)\n",
			what, what, path, strerror(errno));
		rt_free(probe);
		return TOOL_EXIT_FAILURE;
	}
	close(fd);
	unlink(probe);
	rt_free(probe);
	return 0;
}

/* The references of the scenes, each loaded from the options as given
 * (loading one resolves its camera and floor into the options). */
static int grade_references(struct check_options *o, struct grade_class *c)
{
	struct cli_scene given = o->scene;
	int s, status;

	for (s = 0; s < (o->n_scenes ? o->n_scenes : 1); s++) {
		o->scene = given;
		o->scene.path = o->n_scenes ? o->scenes[s] : NULL;
		if ((status = check_reference_make(o, &c->refs[s])) != 0)
			return status;
		c->n_refs = s + 1;
	}
	o->scene = given;
	o->scene.path = o->n_scenes ? o->scenes[0] : NULL;
	return 0;
}

static int grade_png_of(const struct image *img, struct grade_png *p, struct diag *d)
{
	p->width = img->width;
	p->height = img->height;
	return image_encode_png(img, &p->data, &p->len, d);
}

/* The row's pictures for the report, then its images freed. */
static int grade_keep_pictures(const struct grade_class *c, struct grade_row *r, struct diag *d)
{
	const struct check_reference *ref = &c->refs[r->in->scene];
	const struct check_view *v;
	struct image diff = { 0, 0, NULL };
	int rc;

	if (r->res.verdict == CHECK_UNREADABLE)
		return 0;
	v = check_result_view(ref, &r->res);
	if ((rc = grade_png_of(&v->image, &r->reference, d)) < 0 ||
	    (rc = grade_png_of(&r->res.image, &r->submission, d)) < 0 ||
	    (rc = check_diff_picture(ref, &r->res, &diff, d)) < 0)
		return rc;
	rc = grade_png_of(&diff, &r->difference, d);
	image_free(&diff);
	return rc;
}

static void grade_row_words(const struct grade_class *c, struct grade_row *r)
{
	const struct check_reference *ref = &c->refs[r->in->scene];
	const struct check_result *res = &r->res;
	size_t len = 0;

	check_diagnosis(ref, res, r->diagnosis, sizeof(r->diagnosis));
	check_objects_line(res, r->objects, sizeof(r->objects));
	r->camera[0] = r->best[0] = '\0';
	if (res->moved) {
		check_camera_options(&res->found.params, r->camera, sizeof(r->camera));
		len = (size_t)snprintf(r->best, sizeof(r->best), "camera");
	}
	if (res->verdict == CHECK_DIFFERS && res->n_ranks > 0 && res->explained != CHECK_NONE) {
		char id[96];
		check_cause_id(ref, &res->ranks[0], id, sizeof(id));
		snprintf(r->best + len, sizeof(r->best) - len, "%s%s", len ? "+" : "", id);
	}
	for (r->n_causes = 0; res->verdict == CHECK_DIFFERS && r->n_causes < 5 && (size_t)r->n_causes < res->n_ranks;
	     r->n_causes++) {
		struct grade_row_cause *rc = &r->causes[r->n_causes];
		const struct grade_rank *k = &res->ranks[r->n_causes];
		check_cause_id(ref, k, rc->id, sizeof(rc->id));
		check_cause_words(ref, res, k, rc->words, sizeof(rc->words));
		check_cause_fix(ref, k, rc->fix, sizeof(rc->fix));
		rc->psnr = k->fig.psnr;
		rc->estimated = k->estimated;
		rc->explains = k->fig.match;
		rc->first_equal = k->first_equal;
	}
}

static void grade_print_row(const struct grade_row *r)
{
	printf("%-32s %-10s ", r->in->label, grade_verdict_name(r->res.verdict));
	if (r->res.verdict == CHECK_UNREADABLE)
		printf("%9s", "-");
	else if (isinf(r->res.fig.psnr))
		printf("%9s", "inf");
	else
		printf("%6.2f dB", r->res.fig.psnr);
	printf(" %6g  %s\n", r->points, r->diagnosis);
	fflush(stdout);
}

/* The class's summary: images and students, each verdict, each outcome. */
static void grade_print_summary(const struct grade_class *c)
{
	struct grade_outcome_tally t;
	size_t k, j, students = 0;
	size_t verdicts[3] = { 0, 0, 0 };

	for (k = 0; k < c->n_rows; k++) {
		verdicts[c->rows[k].res.verdict]++;
		if (k == 0 || strcmp(c->rows[k].in->student, c->rows[k - 1].in->student) != 0)
			students++;
	}
	grade_outcome_tally(c, &t);
	printf("class: %zu image%s of %zu student%s: %zu match, %zu differ, %zu unreadable; by outcome:",
	       c->n_rows, c->n_rows == 1 ? "" : "s", students, students == 1 ? "" : "s",
	       verdicts[CHECK_MATCH], verdicts[CHECK_DIFFERS], verdicts[CHECK_UNREADABLE]);
	for (j = 0; j < t.n; j++)
		printf("%s %s %zu", j ? "," : "", t.names[j], t.counts[j]);
	printf("\n");
}

static void grade_class_free(struct grade_class *c)
{
	size_t k;
	int s;

	for (k = 0; k < c->n_rows; k++) {
		check_result_free(&c->rows[k].res);
		rt_free(c->rows[k].reference.data);
		rt_free(c->rows[k].submission.data);
		rt_free(c->rows[k].difference.data);
	}
	rt_free(c->rows);
	grade_inputs_free(&c->inputs);
	for (s = 0; s < c->n_refs; s++)
		check_reference_free(&c->refs[s]);
}

/* Long: the command in its order (options, references, the class's images,
 * the summary, the files) with the cleanup of each step on every exit. */
int grade_main(int argc, char **argv)
{
	struct check_options o;
	struct grade_class c;
	struct diag d;
	int status = check_args_parse(argc, argv, true, &o), rc = 0;
	bool all_match = true;
	size_t k;

	if (status != 0)
		return status < 0 ? 0 : status;
	memset(&c, 0, sizeof(c));
	c.o = &o;
	diag_clear(&d);
	/* Everything that can fail before the first image is graded. */
	if ((o.report_path && (status = grade_check_output(o.report_path, "--output")) != 0) ||
	    (o.csv_path && (status = grade_check_output(o.csv_path, "--csv")) != 0))
		return status;
	if (o.marks_path) {
		if ((rc = grade_marks_read(o.marks_path, &c.marks, &d)) < 0) {
			tool_print_diag(&d, "error");
			return TOOL_EXIT_FAILURE;
		}
	} else {
		grade_marks_default(&c.marks);
	}
	cli_set_signals();
	if ((rc = grade_inputs_collect(o.images, o.n_images, o.scenes, o.n_scenes > 0 ? o.n_scenes : 1,
				       &c.inputs, &d)) < 0)
		goto out;
	if (c.inputs.n == 0) {
		fprintf(stderr, "whitted: error: no image found in the operands (PNG, BMP or PPM files, "
			"folders or zip files of them)\n");
		status = TOOL_EXIT_FAILURE;
		goto done;
	}
	if ((status = grade_references(&o, &c)) != 0)
		goto done;
	if (!(c.rows = rt_calloc(c.inputs.n, sizeof(*c.rows)))) {
		rc = diag_fail(&d, RT_E_NOMEM, "out of memory for %zu results", c.inputs.n);
		goto out;
	}
	printf("%-32s %-10s %9s %6s  %s\n", "file", "verdict", "PSNR", "points", "likely cause");
	for (k = 0; k < c.inputs.n; k++) {
		struct grade_row *r = &c.rows[k];
		struct check_reference *ref;
		r->in = &c.inputs.v[k];
		ref = &c.refs[r->in->scene];
		c.n_rows = k + 1;
		rc = r->in->path ? check_image(ref, r->in->path, &r->res, &d)
				 : check_image_data(ref, r->in->label, r->in->data, r->in->len, &r->res, &d);
		if (rc < 0)
			goto out;
		grade_row_words(&c, r);
		r->points = grade_points_of(&c, r);
		all_match = all_match && r->res.verdict == CHECK_MATCH;
		grade_print_row(r);
		if (o.report_path && (rc = grade_keep_pictures(&c, r, &d)) < 0)
			goto out;
		image_free(&r->res.image);
		check_view_free(&r->res.own);
		check_view_free(&r->res.found);
		rt_free(r->res.ids);
		r->res.ids = NULL;
	}
	grade_print_summary(&c);
	if (o.csv_path && (rc = grade_write_csv(&c, o.csv_path, &d)) < 0)
		goto out;
	if (o.report_path && (rc = grade_write_report(&c, o.report_path, &d)) < 0)
		goto out;
	status = all_match ? TOOL_EXIT_OK : CHECK_EXIT_DIFFERS;
out:
	if (rc < 0) {
		tool_print_diag(&d, "error");
		status = rc == -RT_E_INTERRUPTED || cli_cancelled ? TOOL_EXIT_SIGNAL + (int)cli_cancelled
								  : TOOL_EXIT_FAILURE;
	}
done:
	grade_class_free(&c);
	return status;
}
