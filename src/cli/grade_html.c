/* The HTML report of whitted grade: one self-contained file (the images
 * inlined as data: URIs of PNGs, the style in the page, no network), with
 * a summary table and, per submission, the reference, the submission and
 * their difference side by side with the figures and the likely causes.
 * A small script records on <body> how many images loaded, for tests and
 * for a reader who wonders. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "base/alloc.h"
#include "cli/check.h"
#include "cli/cli.h"

static void html_text(FILE *f, const char *s)
{
	for (; *s; s++) {
		switch (*s) {
		case '<': fputs("&lt;", f); break;
		case '>': fputs("&gt;", f); break;
		case '&': fputs("&amp;", f); break;
		case '"': fputs("&quot;", f); break;
		default: fputc(*s, f);
		}
	}
}

/* The image as a data: URI (base64 of its PNG), written to f. */
static int html_image_uri(FILE *f, const struct image *img, struct diag *d)
{
	static const char b64[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
	unsigned char *png;
	size_t len, i;
	int rc = image_encode_png(img, &png, &len, d);

	if (rc < 0)
		return rc;
	fputs("data:image/png;base64,", f);
	for (i = 0; i + 2 < len; i += 3) {
		unsigned v = (unsigned)png[i] << 16 | (unsigned)png[i + 1] << 8 | png[i + 2];
		fputc(b64[v >> 18], f);
		fputc(b64[(v >> 12) & 63], f);
		fputc(b64[(v >> 6) & 63], f);
		fputc(b64[v & 63], f);
	}
	if (i < len) {
		unsigned v = (unsigned)png[i] << 16 | (i + 1 < len ? (unsigned)png[i + 1] << 8 : 0u);
		fputc(b64[v >> 18], f);
		fputc(b64[(v >> 12) & 63], f);
		fputc(i + 1 < len ? b64[(v >> 6) & 63] : '=', f);
		fputc('=', f);
	}
	rt_free(png);
	return 0;
}

static void html_psnr(FILE *f, double psnr)
{
	if (isinf(psnr))
		fputs("&infin;", f);
	else
		fprintf(f, "%.2f dB", psnr);
}

static const char *html_verdict(enum check_verdict v)
{
	return v == CHECK_MATCH ? "match" : v == CHECK_DIFFERS ? "differs" : "unreadable";
}

static const char html_style[] =
	"body{font-family:sans-serif;margin:1.5em;color:#222;background:#fafafa}"
	"table{border-collapse:collapse;margin:0.5em 0}"
	"th,td{border:1px solid #ccc;padding:0.25em 0.6em;text-align:left;vertical-align:top}"
	"th{background:#eee}.match .verdict{color:#176f2c;font-weight:bold}"
	".differs .verdict{color:#b00020;font-weight:bold}.unreadable .verdict{color:#8a5a00;font-weight:bold}"
	".images{display:flex;gap:1em;flex-wrap:wrap}figure{margin:0}"
	"figure img{width:256px;image-rendering:pixelated;border:1px solid #999;background:#000}"
	"figure img.difference{width:512px}figcaption{font-size:0.85em;color:#555}"
	"section{border-top:2px solid #ccc;margin-top:1.5em;padding-top:0.5em}"
	".diagnosis{font-weight:bold}#summary td:nth-child(4),.causes td:nth-child(2){white-space:nowrap}";

static const char html_script[] =
	"<script>window.addEventListener('load',function(){var im=document.images,ok=0,i;"
	"for(i=0;i<im.length;i++){im[i].setAttribute('data-natural-width',im[i].naturalWidth);"
	"if(im[i].complete&&im[i].naturalWidth>0)ok++;}"
	"document.body.setAttribute('data-images',im.length);"
	"document.body.setAttribute('data-images-loaded',ok);});</script>\n";

struct html_ctx {
	const struct check_options *o;
	const struct check_reference *ref;
	const struct check_result *res;
};

static int html_submission(FILE *f, const struct html_ctx *c, int i, struct diag *d)
{
	const struct check_result *r = &c->res[i];
	char diagnosis[1024];
	struct image diff = { 0, 0, NULL };
	size_t k;
	int rc;

	check_diagnosis(c->ref, r, diagnosis, sizeof(diagnosis));
	fprintf(f, "<section class=\"submission %s\" id=\"sub%d\">\n<h2>", html_verdict(r->verdict), i + 1);
	html_text(f, c->o->images[i]);
	fprintf(f, ": <span class=\"verdict\">%s</span></h2>\n", html_verdict(r->verdict));
	fputs("<p class=\"diagnosis\">", f);
	html_text(f, diagnosis);
	fputs("</p>\n", f);
	if (r->verdict == CHECK_UNREADABLE)
		return fputs("</section>\n", f) < 0 ? diag_fail(d, RT_E_IO, "cannot write the report") : 0;
	fputs("<div class=\"images\"><figure><img class=\"reference\" alt=\"reference\" src=\"", f);
	if ((rc = html_image_uri(f, &c->ref->view.image, d)) < 0)
		return rc;
	fputs("\"><figcaption>reference</figcaption></figure>\n"
	      "<figure><img class=\"submitted\" alt=\"submission\" src=\"", f);
	if ((rc = html_image_uri(f, &r->image, d)) < 0)
		return rc;
	fputs("\"><figcaption>submission</figcaption></figure>\n", f);
	if ((rc = grade_diff_image(&c->ref->view.image, &r->image, &diff, d)) < 0)
		return rc;
	fputs("<figure><img class=\"difference\" alt=\"difference\" src=\"", f);
	rc = html_image_uri(f, &diff, d);
	image_free(&diff);
	if (rc < 0)
		return rc;
	fputs("\"><figcaption>difference &times;8 | where it differs (yellow &gt; 2 levels, "
	      "red &gt; 8)</figcaption></figure></div>\n", f);
	fputs("<table class=\"figures\"><tr><th>PSNR</th><th>mean error</th><th>off by &gt; 2</th>"
	      "<th>off by &gt; 8</th><th>off by &gt; 32</th></tr><tr><td>", f);
	html_psnr(f, r->fig.psnr);
	if (r->fig.left_out > 0 && r->fig.psnr_gate != r->fig.psnr) {
		fputs(" (gate: ", f);
		html_psnr(f, r->fig.psnr_gate);
		fprintf(f, " without the worst %ld px)", r->fig.left_out);
	}
	fprintf(f, "</td><td>%.3f levels</td><td>%.3f %%</td><td>%.3f %%</td><td>%.3f %%</td></tr></table>\n",
		r->fig.mean_error, 100.0 * r->fig.off2, 100.0 * r->fig.off8, 100.0 * r->fig.off32);
	if (r->verdict == CHECK_DIFFERS && r->n_ranks > 0) {
		fputs("<table class=\"causes\"><tr><th>likely cause</th><th>PSNR of its image</th>"
		      "<th>fix</th></tr>\n", f);
		for (k = 0; k < r->n_ranks && k < 5; k++) {
			const struct grade_cause_text *t = grade_cause_text(r->ranks[k].cause,
									     c->ref->base.settings.clamp);
			fprintf(f, "<tr data-cause=\"%s\"><td>", t->id);
			html_text(f, t->with);
			fputs("</td><td>", f);
			if (r->ranks[k].estimated)
				fputs("~", f);
			html_psnr(f, r->ranks[k].fig.psnr);
			fputs(r->ranks[k].fig.match ? " (explains it)" : "", f);
			fputs(r->ranks[k].first_equal ? " (first equal)" : "", f);
			fputs("</td><td>", f);
			html_text(f, t->fix);
			fputs("</td></tr>\n", f);
		}
		fputs("</table>\n", f);
	}
	fputs("</section>\n", f);
	return 0;
}

static int html_fill(void *ctx, FILE *f, struct diag *d)
{
	const struct html_ctx *c = ctx;
	const char *scene = c->o->scene.path ? c->o->scene.path : "the test scene";
	char diagnosis[1024];
	int i, rc, matches = 0;

	for (i = 0; i < c->o->n_images; i++)
		matches += c->res[i].verdict == CHECK_MATCH;
	fputs("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n<title>whitted grade: ", f);
	html_text(f, scene);
	fprintf(f, "</title>\n<style>%s</style></head>\n<body>\n<h1>whitted grade: ", html_style);
	html_text(f, scene);
	fprintf(f, "</h1>\n<p>Reference %dx%d, recursion level %d, clamping %s. The gate: PSNR "
		   "&ge; %g dB, at most %g %% of pixels off by more than 2 levels and %g %% by more "
		   "than 8. <span id=\"tally\">%d of %d images match.</span></p>\n",
		c->ref->view.image.width, c->ref->view.image.height, c->ref->base.settings.recursion,
		c->ref->base.settings.clamp == RT_CLAMP_LEVEL ? "at every level" : "at the end",
		RT_GRADE_MIN_PSNR, 100.0 * RT_GRADE_MAX_OFF2, 100.0 * RT_GRADE_MAX_OFF8, matches,
		c->o->n_images);
	fputs("<table id=\"summary\"><thead><tr><th>#</th><th>file</th><th>verdict</th><th>PSNR</th>"
	      "<th>likely cause</th></tr></thead><tbody>\n", f);
	for (i = 0; i < c->o->n_images; i++) {
		const struct check_result *r = &c->res[i];
		check_diagnosis(c->ref, r, diagnosis, sizeof(diagnosis));
		fprintf(f, "<tr class=\"row %s\" data-verdict=\"%s\" data-cause=\"%s\"><td>%d</td>"
			   "<td><a href=\"#sub%d\">", html_verdict(r->verdict), html_verdict(r->verdict),
			r->verdict == CHECK_DIFFERS && r->n_ranks > 0
				? grade_cause_text(r->ranks[0].cause, c->ref->base.settings.clamp)->id : "",
			i + 1, i + 1);
		html_text(f, c->o->images[i]);
		fprintf(f, "</a></td><td class=\"verdict\">%s</td><td>", html_verdict(r->verdict));
		if (r->verdict != CHECK_UNREADABLE)
			html_psnr(f, r->fig.psnr);
		fputs("</td><td>", f);
		html_text(f, diagnosis);
		fputs("</td></tr>\n", f);
	}
	fputs("</tbody></table>\n", f);
	for (i = 0; i < c->o->n_images; i++)
		if ((rc = html_submission(f, c, i, d)) < 0)
			return rc;
	fputs(html_script, f);
	fputs("</body></html>\n", f);
	if (ferror(f))
		return diag_fail(d, RT_E_IO, "cannot write the report");
	return 0;
}

int check_write_report(const struct check_options *o, const struct check_reference *ref,
		       const struct check_result *res, struct diag *d)
{
	struct html_ctx c = { o, ref, res };

	return image_write_file(o->report_path, html_fill, &c, &cli_cancelled, d);
}
