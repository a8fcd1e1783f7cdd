/* whitted grade: a class's images against one reference, one row each,
 * with a CSV file and an HTML report for the teacher. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/alloc.h"
#include "cli/check.h"
#include "cli/cli.h"
#include "cli/tool.h"

static const char *grade_verdict_name(enum check_verdict v)
{
	return v == CHECK_MATCH ? "match" : v == CHECK_DIFFERS ? "differs" : "unreadable";
}

/* A quoted CSV field; one that starts with = + - @ (or a tab or carriage
 * return) gets a leading ' so that a spreadsheet shows it as text instead
 * of running it as a formula (a file named "=HYPERLINK(...)"). */
static void csv_field(FILE *f, const char *s)
{
	fputc('"', f);
	if (*s && strchr("=+-@\t\r", *s))
		fputc('\'', f);
	for (; *s; s++) {
		if (*s == '"')
			fputc('"', f);
		fputc(*s, f);
	}
	fputc('"', f);
}

struct grade_csv {
	const struct check_options *o;
	const struct check_reference *ref;
	const struct check_result *res;
};

static int grade_fill_csv(void *ctx, FILE *f, struct diag *d)
{
	const struct grade_csv *c = ctx;
	char diagnosis[1024];
	int i;

	fprintf(f, "file,verdict,psnr,mean_error,off2,off8,off32,cause,cause_psnr,explains,diagnosis\n");
	for (i = 0; i < c->o->n_images; i++) {
		const struct check_result *r = &c->res[i];
		csv_field(f, c->o->images[i]);
		fprintf(f, ",%s,", grade_verdict_name(r->verdict));
		if (r->verdict != CHECK_UNREADABLE) {
			if (isinf(r->fig.psnr))
				fprintf(f, "inf");
			else
				fprintf(f, "%.3f", r->fig.psnr);
			fprintf(f, ",%.4f,%.6f,%.6f,%.6f", r->fig.mean_error, r->fig.off2, r->fig.off8,
				r->fig.off32);
		} else {
			fprintf(f, ",,,,");
		}
		/* A cause only when it explains the image or comes close; causes
		 * ranked first equally joined by " or ": none is preferred. */
		if (r->verdict == CHECK_DIFFERS && r->n_ranks > 0 && r->explained != CHECK_NONE) {
			size_t k;
			fputc(',', f);
			for (k = 0; k < r->n_ranks && (k == 0 || r->ranks[k].first_equal); k++)
				fprintf(f, "%s%s", k ? " or " : "",
					grade_cause_text(r->ranks[k].cause, c->ref->base.settings.clamp)->id);
			if (isinf(r->ranks[0].fig.psnr))
				fprintf(f, ",inf");
			else
				fprintf(f, ",%.3f", r->ranks[0].fig.psnr);
			fprintf(f, ",%s,", r->explained == CHECK_EXPLAINED ? "yes" : "no");
		} else {
			fprintf(f, ",,,,");
		}
		check_diagnosis(c->ref, r, diagnosis, sizeof(diagnosis));
		csv_field(f, diagnosis);
		fputc('\n', f);
	}
	if (ferror(f))
		return diag_fail(d, RT_E_IO, "cannot write the CSV file");
	return 0;
}

int grade_main(int argc, char **argv)
{
	struct check_options o;
	struct check_reference ref;
	struct check_result *res = NULL;
	struct diag d;
	int status = check_args_parse(argc, argv, true, &o), i, done = 0, rc = 0;
	bool all_match = true;

	if (status != 0)
		return status < 0 ? 0 : status;
	cli_set_signals();
	if ((status = check_reference_make(&o, &ref)) != 0)
		return status;
	diag_clear(&d);
	if (!(res = rt_calloc((size_t)o.n_images, sizeof(*res)))) {
		diag_fail(&d, RT_E_NOMEM, "out of memory for %d results", o.n_images);
		rc = -RT_E_NOMEM;
		goto out;
	}
	printf("%-32s %-10s %9s  %s\n", "file", "verdict", "PSNR", "likely cause");
	for (i = 0; i < o.n_images; i++) {
		char diagnosis[1024];
		done = i + 1;
		if ((rc = check_image(&ref, o.images[i], &res[i], &d)) < 0)
			goto out;
		all_match = all_match && res[i].verdict == CHECK_MATCH;
		printf("%-32s %-10s ", o.images[i], grade_verdict_name(res[i].verdict));
		if (res[i].verdict == CHECK_UNREADABLE)
			printf("%9s", "-");
		else if (isinf(res[i].fig.psnr))
			printf("%9s", "inf");
		else
			printf("%6.2f dB", res[i].fig.psnr);
		check_diagnosis(&ref, &res[i], diagnosis, sizeof(diagnosis));
		printf("  %s\n", diagnosis);
		fflush(stdout);
	}
	if (o.csv_path) {
		struct grade_csv c = { &o, &ref, res };
		if ((rc = image_write_file(o.csv_path, grade_fill_csv, &c, &cli_cancelled, &d)) < 0)
			goto out;
	}
	if (o.report_path && (rc = check_write_report(&o, &ref, res, &d)) < 0)
		goto out;
	status = all_match ? TOOL_EXIT_OK : CHECK_EXIT_DIFFERS;
out:
	if (rc < 0) {
		tool_print_diag(&d, "error");
		status = rc == -RT_E_INTERRUPTED || cli_cancelled ? TOOL_EXIT_SIGNAL + (int)cli_cancelled
								  : TOOL_EXIT_FAILURE;
	}
	for (i = 0; i < done; i++)
		check_result_free(&res[i]);
	rt_free(res);
	check_reference_free(&ref);
	return status;
}
