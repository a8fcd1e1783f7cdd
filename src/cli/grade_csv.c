/* grade's CSV file: a row an image, the columns of earlier versions
 * first (scripts read them by place), then the student, the scene, the
 * camera found, the best explanation, the objects and the points. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cli/cli.h"
#include "cli/grade_class.h"

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

static void csv_psnr(FILE *f, double psnr)
{
	if (isinf(psnr))
		fprintf(f, "inf");
	else
		fprintf(f, "%.3f", psnr);
}

static int grade_fill_csv(void *ctx, FILE *f, struct diag *d)
{
	const struct grade_class *c = ctx;
	size_t i;

	fprintf(f, "file,verdict,psnr,mean_error,off2,off8,off32,cause,cause_psnr,explains,diagnosis,"
		   "student,id,scene,camera_moved,camera,best,objects,points\n");
	for (i = 0; i < c->n_rows; i++) {
		const struct grade_row *row = &c->rows[i];
		const struct check_result *r = &row->res;
		const struct check_reference *ref = &c->refs[row->in->scene];
		csv_field(f, row->in->label);
		fprintf(f, ",%s,", grade_verdict_name(r->verdict));
		if (r->verdict != CHECK_UNREADABLE) {
			csv_psnr(f, r->fig.psnr);
			fprintf(f, ",%.4f,%.6f,%.6f,%.6f", r->fig.mean_error, r->fig.off2, r->fig.off8,
				r->fig.off32);
		} else {
			fprintf(f, ",,,,");
		}
		/* A cause only when it explains the image or comes close; causes
		 * ranked first equally joined by " or ": none is preferred. */
		if (r->verdict == CHECK_DIFFERS && row->n_causes > 0 && r->explained != CHECK_NONE) {
			int k;
			fputc(',', f);
			for (k = 0; k < row->n_causes && (k == 0 || row->causes[k].first_equal); k++)
				fprintf(f, "%s%s", k ? " or " : "", row->causes[k].id);
			fputc(',', f);
			csv_psnr(f, row->causes[0].psnr);
			fprintf(f, ",%s,", r->explained == CHECK_EXPLAINED ? "yes" : "no");
		} else {
			fprintf(f, ",,,,");
		}
		csv_field(f, row->diagnosis);
		fputc(',', f);
		csv_field(f, row->in->student);
		fputc(',', f);
		csv_field(f, row->in->id);
		fputc(',', f);
		csv_field(f, ref->scene ? scene_name(ref->scene) : "test-scene");
		fprintf(f, ",%s,", r->moved ? "yes" : "no");
		csv_field(f, row->camera);
		fputc(',', f);
		csv_field(f, row->best);
		fputc(',', f);
		csv_field(f, row->objects);
		fprintf(f, ",%g\n", row->points);
	}
	if (ferror(f))
		return diag_fail(d, RT_E_IO, "cannot write the CSV file");
	return 0;
}

int grade_write_csv(const struct grade_class *c, const char *path, struct diag *d)
{
	return image_write_file(path, grade_fill_csv, (void *)c, &cli_cancelled, d);
}
