/* The reference render and the check of one image, shared by compare and
 * grade. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cli/check.h"
#include "cli/cli.h"
#include "cli/tool.h"

/* A cause "comes close" when its image is CHECK_CLOSE_GAIN dB nearer the
 * submission than the reference is and at least CHECK_CLOSE_PSNR, or
 * CHECK_FAR_GAIN dB nearer whatever its PSNR: a second mistake (or a tie
 * broken otherwise along a tile edge) can keep the right cause from
 * explaining every pixel. */
#define CHECK_CLOSE_GAIN 3.0
#define CHECK_CLOSE_PSNR 30.0
#define CHECK_FAR_GAIN 6.0

int check_reference_make(struct check_options *o, struct check_reference *ref)
{
	struct diag d;
	int rc;

	memset(ref, 0, sizeof(*ref));
	diag_clear(&d);
	rc = cli_scene_load(&o->scene, o->scene.path, tool_print_note, &o->scene.quiet, &ref->scene,
			    &ref->camera, &d);
	if (rc == 0)
		rc = scene_prepare(ref->scene, o->threads, &d);
	if (rc == 0) {
		ref->job.scene = ref->scene;
		ref->job.camera = &ref->camera;
		/* The render options that reach render_settings, and how many
		 * rays a pixel (a new one is copied here too). */
		ref->job.settings.recursion = scene_recursion(ref->scene);
		ref->job.settings.clamp = o->scene.clamp;
		ref->job.samples = o->scene.samples;
		ref->job.threads = o->threads;
		ref->job.cancel = &cli_cancelled;
		rc = grade_render_reference(&ref->job, &ref->image, &d);
	}
	if (rc < 0) {
		tool_print_diag(&d, "error");
		check_reference_free(ref);
		if (rc == -RT_E_INTERRUPTED || cli_cancelled)
			return TOOL_EXIT_SIGNAL + (int)cli_cancelled;
		return rc == -RT_E_INVALID ? TOOL_EXIT_USAGE : TOOL_EXIT_FAILURE;
	}
	return 0;
}

void check_reference_free(struct check_reference *ref)
{
	image_free(&ref->image);
	image_free(&ref->truncated);
	scene_destroy(ref->scene);
	ref->scene = NULL;
}

int check_image(struct check_reference *ref, const char *path, struct check_result *res,
		struct diag *d)
{
	const struct image *r = &ref->image;
	struct grade_figures tfig;
	int rc;

	memset(res, 0, sizeof(*res));
	diag_clear(&res->error);
	rc = image_read(path, &res->image, NULL, &res->error);
	if (rc == -RT_E_NOMEM)
		return diag_fail(d, RT_E_NOMEM, "%s", res->error.msg);
	if (rc == 0 && (res->image.width != r->width || res->image.height != r->height)) {
		diag_set(&res->error, RT_E_RANGE, path, 0, 0,
			 "the image is %dx%d, the reference %dx%d (the scene's size, or --size)",
			 res->image.width, res->image.height, r->width, r->height);
		image_free(&res->image);
		rc = -RT_E_RANGE;
	}
	if (rc < 0) {
		res->verdict = CHECK_UNREADABLE;
		return 0;
	}
	grade_figures_of(r, &res->image, 1, 0, 0, &res->fig);
	res->fig_rounded = res->fig;
	if (res->fig.match) {
		res->verdict = CHECK_MATCH;
		return 0;
	}
	/* The course's code writes (unsigned char)(255 c), a truncation: an
	 * image that matches the reference converted that way is right. */
	if (!ref->truncated.pixels &&
	    (rc = grade_render_truncated(&ref->job, &ref->truncated, d)) < 0)
		return rc;
	grade_figures_of(&ref->truncated, &res->image, 1, 0, 0, &tfig);
	res->truncated = tfig.psnr > res->fig.psnr;
	if (tfig.match) {
		res->fig = tfig;
		res->verdict = CHECK_MATCH;
		return 0;
	}
	res->verdict = CHECK_DIFFERS;
	if ((rc = grade_rank_causes(&ref->job, r, &ref->truncated, &res->image, res->ranks,
				    &res->n_ranks, d)) < 0)
		return rc;
	res->explained = CHECK_NONE;
	if (res->n_ranks > 0) {
		const struct grade_figures *best = &res->ranks[0].fig;
		if (best->match)
			res->explained = CHECK_EXPLAINED;
		else if ((best->psnr >= CHECK_CLOSE_PSNR &&
			  best->psnr >= res->fig.psnr + CHECK_CLOSE_GAIN) ||
			 best->psnr >= res->fig.psnr + CHECK_FAR_GAIN)
			res->explained = CHECK_CLOSE;
	}
	return 0;
}

void check_result_free(struct check_result *res)
{
	image_free(&res->image);
}

void check_diagnosis(const struct check_reference *ref, const struct check_result *res,
		     char *buf, size_t size)
{
	const struct grade_cause_text *t, *equal = NULL;
	const char *conv = "";

	if (res->verdict == CHECK_MATCH && res->truncated && !res->fig_rounded.match) {
		snprintf(buf, size, "matches the reference (written by truncating 255*c, not "
			 "rounding: fine; %.1f dB against the rounded reference)",
			 res->fig_rounded.psnr);
		return;
	}
	if (res->verdict == CHECK_MATCH) {
		snprintf(buf, size, "matches the reference");
		return;
	}
	if (res->verdict == CHECK_UNREADABLE) {
		snprintf(buf, size, "unreadable: %s", res->error.msg);
		return;
	}
	if (res->n_ranks == 0) {
		snprintf(buf, size, "none of the known mistakes changes this scene's image");
		return;
	}
	t = grade_cause_text(res->ranks[0].cause, ref->job.settings.clamp);
	if (res->n_ranks > 1 && res->ranks[1].first_equal)
		equal = grade_cause_text(res->ranks[1].cause, ref->job.settings.clamp);
	if (res->ranks[0].truncated)
		conv = " (and 255*c truncated, not rounded: that is fine)";
	if (res->explained == CHECK_EXPLAINED)
		snprintf(buf, size, "matches the reference with %s%s%s%s: %s%s%s", t->with,
			 equal ? ", or equally with " : "", equal ? equal->with : "",
			 conv, t->fix, equal ? "; or " : "", equal ? equal->fix : "");
	else if (res->explained == CHECK_CLOSE)
		snprintf(buf, size, "most likely %s%s%s (%.1f dB against the reference's %.1f dB), "
			 "though %.2f%% of the pixels still differ: %s; then look for a second mistake",
			 t->with, equal ? ", or equally " : "", equal ? equal->with : "",
			 res->ranks[0].fig.psnr, res->fig.psnr, 100.0 * res->ranks[0].fig.off2, t->fix);
	else
		snprintf(buf, size, "none of the known mistakes comes close (the nearest, %s, "
			 "reaches %.1f dB against the reference's %.1f dB)",
			 t->with, res->ranks[0].fig.psnr, res->fig.psnr);
}
