/* whitted compare: one image against the reference render of its scene,
 * with the figures of the gate and, when it differs, the likely mistakes. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "base/text.h"
#include "cli/check.h"
#include "cli/cli.h"
#include "cli/tool.h"

/* Causes listed after the first. */
#define COMPARE_LISTED 5

/* A JSON string of s, valid whatever the bytes (a file name need not be
 * UTF-8): a byte that is not part of a UTF-8 sequence is written as
 * U+FFFD, the replacement character. */
static void json_string(const char *s)
{
	const unsigned char *p = (const unsigned char *)s;

	putchar('"');
	while (*p) {
		int n = text_utf8_length(p);
		if (*p == '"' || *p == '\\')
			printf("\\%c", *p);
		else if (*p < 0x20 || *p == 0x7f)
			printf("\\u%04x", *p);
		else if (n == 0)
			printf("\\ufffd");
		else
			fwrite(p, 1, (size_t)n, stdout);
		p += n ? n : 1;
	}
	putchar('"');
}

/* JSON has no infinity: identical images have a PSNR of null. */
static void json_psnr(double psnr)
{
	if (isinf(psnr))
		printf("null");
	else
		printf("%.3f", psnr);
}

/* The best explanation's causes as a JSON array: "camera" first when the
 * camera moved, then the first cause's id or ids. */
static void compare_json_best(const struct check_reference *ref, const struct check_result *res)
{
	const struct grade_rank *r = res->n_ranks > 0 ? &res->ranks[0] : NULL;
	bool any = false;
	char id[96];
	double psnr = res->moved ? res->fig_found.psnr : res->fig.psnr;

	printf(", \"best\": {\"causes\": [");
	if (res->moved) {
		printf("\"camera\"");
		any = true;
	}
	if (res->verdict == CHECK_DIFFERS && r && res->explained != CHECK_NONE) {
		check_cause_id(ref, r, id, sizeof(id));
		printf("%s\"%s\"", any ? ", " : "", grade_cause_text(r->cause, ref->base.settings.clamp)->id);
		if (r->also != RT_CAUSE_NONE)
			printf(", \"%s\"", grade_cause_text(r->also, ref->base.settings.clamp)->id);
		psnr = r->fig.psnr;
	}
	printf("], \"psnr\": ");
	json_psnr(res->verdict == CHECK_MATCH ? (res->moved ? res->fig_found.psnr : res->fig.psnr) : psnr);
	printf(", \"explains\": %s}",
	       res->verdict == CHECK_MATCH || res->explained == CHECK_EXPLAINED ? "true" : "false");
}

/* Long: the JSON document's fields in their order, a writer call each. */
static void compare_json(const struct check_options *o, const struct check_reference *ref,
			 const struct check_result *res, const char *diagnosis)
{
	const struct check_view *v = check_result_view(ref, res);
	char buf[600];
	size_t k;

	printf("{\"scene\": ");
	json_string(o->scene.path ? o->scene.path : "test-scene");
	printf(", \"image\": ");
	json_string(o->images[0]);
	printf(", \"width\": %d, \"height\": %d", res->image.width, res->image.height);
	printf(", \"size_note\": ");
	json_string(res->size_note);
	printf(", \"psnr\": ");
	json_psnr(res->fig.psnr);
	printf(", \"psnr_gate\": ");
	json_psnr(res->fig.psnr_gate);
	printf(", \"left_out\": %ld", res->fig.left_out);
	printf(", \"ties\": %ld", v->n_ties);
	printf(", \"lenient\": %s", ref->lenient ? "true" : "false");
	printf(", \"floor_textured\": %s", res->floor_textured ? "true" : "false");
	printf(", \"conversion\": \"%s\"", res->truncated ? "truncate" : "round");
	printf(", \"psnr_rounded\": ");
	json_psnr(res->fig_rounded.psnr);
	printf(", \"identical\": %s", isinf(res->fig.psnr) ? "true" : "false");
	printf(", \"mean_error\": %.4f, \"off2\": %.6f, \"off8\": %.6f, \"off32\": %.6f",
	       res->fig.mean_error, res->fig.off2, res->fig.off8, res->fig.off32);
	printf(", \"gate\": {\"min_psnr\": %g, \"max_off2\": %g, \"max_off8\": %g}",
	       RT_GRADE_MIN_PSNR, RT_GRADE_MAX_OFF2, RT_GRADE_MAX_OFF8);
	printf(", \"verdict\": \"%s\"", res->verdict == CHECK_MATCH ? "match" : "differs");
	printf(", \"explained\": \"%s\"",
	       res->verdict == CHECK_MATCH ? "match" :
	       res->explained == CHECK_EXPLAINED ? "explained" :
	       res->explained == CHECK_CLOSE ? "close" : "none");
	printf(", \"diagnosis\": ");
	json_string(diagnosis);
	check_camera_options(&v->params, buf, sizeof(buf));
	printf(", \"camera\": {\"moved\": %s, \"fitted\": %s, \"options\": ", res->moved ? "true" : "false",
	       res->fitted ? "true" : "false");
	json_string(buf);
	printf(", \"psnr\": ");
	json_psnr(res->moved ? res->fig_found.psnr : res->fig.psnr);
	printf(", \"psnr_given\": ");
	json_psnr(res->fig.psnr);
	printf(", \"candidates\": %ld, \"floor_alone\": %s}", res->fit_evals,
	       res->floor_alone ? "true" : "false");
	compare_json_best(ref, res);
	printf(", \"objects\": [");
	for (k = 0; k < res->n_objects; k++) {
		const struct grade_object *ob = &res->objects[k];
		printf("%s{\"index\": ", k ? ", " : "");
		if (ob->index > 0)
			printf("%ld", ob->index);
		else
			printf("null");
		printf(", \"keyword\": \"%s\", \"pixels\": %ld, \"off2\": %.6f, \"psnr\": ", ob->keyword,
		       ob->pixels, ob->off2);
		json_psnr(ob->psnr);
		printf("}");
	}
	printf("]");
	check_objects_line(res, buf, sizeof(buf));
	printf(", \"objects_line\": ");
	json_string(buf);
	/* The first cause, or all those ranked first equally: none preferred. */
	printf(", \"first\": [");
	for (k = 0; k < res->n_ranks && (k == 0 || res->ranks[k].first_equal); k++) {
		check_cause_id(ref, &res->ranks[k], buf, sizeof(buf));
		printf("%s\"%s\"", k ? ", " : "", buf);
	}
	printf("]");
	printf(", \"causes\": [");
	for (k = 0; k < res->n_ranks; k++) {
		const struct grade_rank *r = &res->ranks[k];
		check_cause_id(ref, r, buf, sizeof(buf));
		printf("%s{\"id\": \"%s\", \"with\": ", k ? ", " : "", buf);
		check_cause_words(ref, res, r, buf, sizeof(buf));
		json_string(buf);
		printf(", \"fix\": ");
		check_cause_fix(ref, r, buf, sizeof(buf));
		json_string(buf);
		printf(", \"psnr\": ");
		json_psnr(r->fig.psnr);
		printf(", \"off2\": %.6f, \"estimated\": %s, \"explains\": %s", r->fig.off2,
		       r->estimated ? "true" : "false", r->fig.match ? "true" : "false");
		printf(", \"first_equal\": %s, \"truncated\": %s, \"pair\": %s}",
		       r->first_equal ? "true" : "false", r->truncated ? "true" : "false",
		       r->also != RT_CAUSE_NONE ? "true" : "false");
	}
	printf("]}\n");
}

static void print_psnr(double psnr)
{
	if (isinf(psnr))
		printf("     inf dB");
	else
		printf("%8.2f dB", psnr);
}

/* Long: the text report's lines in their order. */
static void compare_text(const struct check_options *o, const struct check_reference *ref,
			 const struct check_result *res, const char *diagnosis)
{
	const struct check_view *v = check_result_view(ref, res);
	char buf[600];
	size_t k;
	bool estimated = false;

	printf("%s against the reference of %s (%dx%d)\n", o->images[0],
	       o->scene.path ? o->scene.path : "the test scene", res->image.width, res->image.height);
	if (res->size_note[0])
		printf("  note: %s\n", res->size_note);
	printf("  PSNR          ");
	print_psnr(res->fig.psnr);
	printf("    (every pixel but the ties)\n");
	printf("  PSNR of gate  ");
	print_psnr(res->fig.psnr_gate);
	printf("    gate >= %g dB, the worst %ld pixel%s (<= 0.02 %%) left out\n", RT_GRADE_MIN_PSNR,
	       res->fig.left_out, res->fig.left_out == 1 ? "" : "s");
	printf("  mean error    %8.3f levels\n", res->fig.mean_error);
	printf("  off by > 2    %8.3f %%       gate <= %g %%\n", 100.0 * res->fig.off2, 100.0 * RT_GRADE_MAX_OFF2);
	printf("  off by > 8    %8.3f %%       gate <= %g %%\n", 100.0 * res->fig.off8, 100.0 * RT_GRADE_MAX_OFF8);
	printf("  off by > 32   %8.3f %%\n", 100.0 * res->fig.off32);
	printf("  ties          %8ld px      left out: either colour is right there (a ray on a "
	       "cell's edge, a grazing shadow)\n", ref->view.n_ties);
	if (res->moved) {
		check_camera_options(&res->found.params, buf, sizeof(buf));
		printf("camera: yours differs; found %s\n", buf);
		printf("  PSNR there    ");
		print_psnr(res->fig_found.psnr);
		printf("    (%.2f dB at the camera given; %ld ties there)\n", res->fig.psnr,
		       res->found.n_ties);
		if (res->fig_found.psnr < res->fig.psnr)
			printf("  note: lower than at the camera given: the camera was fitted on the "
			       "image's greys, with a mistake that changes most of it rendered (swapped "
			       "tiles, gamma), and comes nearer so; the plain reference's colours differ "
			       "more there\n");
	} else if (res->floor_alone)
		printf("camera: none found: the nearest view the fit found shows no object, only the "
		       "floor and the sky, which look alike from many places\n");
	printf("verdict: %s\n", res->verdict == CHECK_MATCH
		       ? (res->moved ? "MATCH at the camera found" : "MATCH") : "DIFFERS");
	check_objects_line(res, buf, sizeof(buf));
	if (buf[0] && res->verdict == CHECK_DIFFERS)
		printf("objects: %s\n", buf);
	if (res->verdict == CHECK_MATCH) {
		if ((res->truncated && !res->fig_rounded.match) || res->moved)
			printf("%s\n", diagnosis);
		return;
	}
	if (res->n_ranks > 0) {
		printf("likely causes, best first (PSNR of that mistake's image against %s%s):\n",
		       o->images[0], res->moved ? ", at the camera found" : "");
		for (k = 0; k < res->n_ranks && k < COMPARE_LISTED; k++) {
			const struct grade_rank *r = &res->ranks[k];
			size_t rank = k + 1;
			while (rank > 1 && res->ranks[rank - 1].first_equal && res->ranks[0].first_equal)
				rank--;
			check_cause_words(ref, res, r, buf, sizeof(buf));
			printf("  %zu%s %-48s %s", rank, r->first_equal ? "=" : ".", buf,
			       r->estimated ? "~" : " ");
			estimated = estimated || r->estimated;
			print_psnr(r->fig.psnr);
			printf("%s\n", r->fig.match ? "  explains the image" : "");
			check_cause_fix(ref, r, buf, sizeof(buf));
			printf("     fix: %s\n", buf);
		}
		if (estimated)
			printf("  (~: estimated from a sample of the pixels; the likeliest are rendered in full)\n");
	}
	(void)v;
	printf("%s\n", diagnosis);
}

int compare_main(int argc, char **argv)
{
	struct check_options o;
	struct check_reference ref;
	struct check_result res;
	char diagnosis[1024];
	struct diag d;
	int status = check_args_parse(argc, argv, false, &o), rc;

	if (status != 0)
		return status < 0 ? 0 : status;
	cli_set_signals();
	if ((status = check_reference_make(&o, &ref)) != 0)
		return status;
	diag_clear(&d);
	rc = check_image(&ref, o.images[0], &res, &d);
	if (rc < 0) {
		tool_print_diag(&d, "error");
		status = rc == -RT_E_INTERRUPTED ? TOOL_EXIT_SIGNAL + (int)cli_cancelled : TOOL_EXIT_FAILURE;
		goto out;
	}
	if (res.verdict == CHECK_UNREADABLE) {
		tool_print_diag(&res.error, "error");
		status = TOOL_EXIT_FAILURE;
		goto out;
	}
	if (o.diff_path) {
		struct image diff = { 0, 0, NULL };
		rc = check_diff_picture(&ref, &res, &diff, &d);
		if (rc == 0)
			rc = image_write(&diff, o.diff_path, image_format_from_path(o.diff_path),
					 &cli_cancelled, &d);
		image_free(&diff);
		if (rc < 0) {
			tool_print_diag(&d, "error");
			status = TOOL_EXIT_FAILURE;
			goto out;
		}
	}
	check_diagnosis(&ref, &res, diagnosis, sizeof(diagnosis));
	if (o.json)
		compare_json(&o, &ref, &res, diagnosis);
	else
		compare_text(&o, &ref, &res, diagnosis);
	status = res.verdict == CHECK_MATCH ? TOOL_EXIT_OK : CHECK_EXIT_DIFFERS;
out:
	check_result_free(&res);
	check_reference_free(&ref);
	return status;
}
