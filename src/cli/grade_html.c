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

#include "base/text.h"
#include "cli/cli.h"
#include "cli/grade_class.h"

/* Text in HTML: the markup's characters escaped, and a byte that is no
 * part of a UTF-8 sequence (a file name need not be UTF-8) written as
 * U+FFFD, so that the page is valid UTF-8 whatever the names. */
static void html_text(FILE *f, const char *s)
{
	const unsigned char *p = (const unsigned char *)s;

	while (*p) {
		int n = text_utf8_length(p);
		switch (*p) {
		case '<': fputs("&lt;", f); break;
		case '>': fputs("&gt;", f); break;
		case '&': fputs("&amp;", f); break;
		case '"': fputs("&quot;", f); break;
		default:
			if (n == 0)
				fputs("&#xfffd;", f);
			else if (*p < 0x20 && *p != '\t')
				fprintf(f, "&#x%x;", *p);
			else
				fwrite(p, 1, (size_t)n, f);
		}
		p += n ? n : 1;
	}
}

/* PNG bytes as a data: URI (base64), written to f. */
static void html_png_uri(FILE *f, const unsigned char *png, size_t len)
{
	static const char b64[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
	size_t i;

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
}

static void html_psnr(FILE *f, double psnr)
{
	if (isinf(psnr))
		fputs("&infin;", f);
	else
		fprintf(f, "%.2f dB", psnr);
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

/* The load check the tests read (how many images decoded), and the
 * tables' sorting (click a heading; again to reverse) and filter (the
 * rows that contain every word typed). */
static const char html_script[] =
	"<script>window.addEventListener('load',function(){var im=document.images,ok=0,i;"
	"for(i=0;i<im.length;i++){im[i].setAttribute('data-natural-width',im[i].naturalWidth);"
	"if(im[i].complete&&im[i].naturalWidth>0)ok++;}"
	"document.body.setAttribute('data-images',im.length);"
	"document.body.setAttribute('data-images-loaded',ok);});\n"
	"function sortBy(th){var t=th.closest('table'),b=t.tBodies[0],c=th.cellIndex,"
	"d=th.getAttribute('data-dir')==='1'?-1:1,r=Array.prototype.slice.call(b.rows);"
	"r.sort(function(x,y){var a=x.cells[c].getAttribute('data-v')||x.cells[c].textContent,"
	"e=y.cells[c].getAttribute('data-v')||y.cells[c].textContent,n=parseFloat(a),m=parseFloat(e);"
	"if(!isNaN(n)&&!isNaN(m))return d*(n-m);return d*a.localeCompare(e);});"
	"th.setAttribute('data-dir',d===1?'1':'-1');r.forEach(function(x){b.appendChild(x);});}\n"
	"function filterRows(inp){var w=inp.value.toLowerCase().split(/\\s+/).filter(Boolean),"
	"t=document.getElementById(inp.getAttribute('data-table'));"
	"Array.prototype.forEach.call(t.tBodies[0].rows,function(x){var s=x.textContent.toLowerCase();"
	"x.style.display=w.every(function(v){return s.indexOf(v)>=0;})?'':'none';});}</script>\n";

static const char *html_verdict(enum check_verdict v)
{
	return v == CHECK_MATCH ? "match" : v == CHECK_DIFFERS ? "differs" : "unreadable";
}

static void html_th(FILE *f, const char *name)
{
	fprintf(f, "<th onclick=\"sortBy(this)\" title=\"sort\">%s</th>", name);
}

/* Long: one submission's section of the report, element after element, as it
 * reads on the page. */
static int html_submission(FILE *f, const struct grade_class *c, size_t i)
{
	const struct grade_row *row = &c->rows[i];
	const struct check_result *r = &row->res;
	int k;

	fprintf(f, "<section class=\"submission %s\" id=\"sub%zu\">\n<h2>", html_verdict(r->verdict), i + 1);
	html_text(f, row->in->label);
	fprintf(f, ": <span class=\"verdict\">%s</span></h2>\n", html_verdict(r->verdict));
	if (row->in->student[0]) {
		fputs("<p class=\"student\">", f);
		html_text(f, row->in->student);
		if (row->in->id[0]) {
			fputs(" (", f);
			html_text(f, row->in->id);
			fputs(")", f);
		}
		fprintf(f, ", %g points</p>\n", row->points);
	}
	fputs("<p class=\"diagnosis\">", f);
	html_text(f, row->diagnosis);
	fputs("</p>\n", f);
	if (r->verdict == CHECK_UNREADABLE) {
		fputs("</section>\n", f);
		return 0;
	}
	if (row->objects[0]) {
		fputs("<p class=\"objects\">", f);
		html_text(f, row->objects);
		fputs("</p>\n", f);
	}
	fputs("<div class=\"images\"><figure><img class=\"reference\" alt=\"reference\" src=\"", f);
	html_png_uri(f, row->reference.data, row->reference.len);
	fprintf(f, "\"><figcaption>reference%s</figcaption></figure>\n"
		   "<figure><img class=\"submitted\" alt=\"submission\" src=\"",
		r->moved ? " at the camera found" : "");
	html_png_uri(f, row->submission.data, row->submission.len);
	fputs("\"><figcaption>submission</figcaption></figure>\n"
	      "<figure><img class=\"difference\" alt=\"difference\" src=\"", f);
	html_png_uri(f, row->difference.data, row->difference.len);
	fputs("\"><figcaption>difference &times;8 | where it differs (yellow &gt; 2 levels, "
	      "red &gt; 8, blue ties, cyan the objects that differ)</figcaption></figure></div>\n", f);
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
	if (row->camera[0]) {
		fputs("<p class=\"camera\">camera found: <code>", f);
		html_text(f, row->camera);
		fputs("</code> (PSNR there ", f);
		html_psnr(f, r->fig_found.psnr);
		fputs(")</p>\n", f);
	}
	if (row->n_causes > 0) {
		fputs("<table class=\"causes\"><tr><th>likely cause</th><th>PSNR of its image</th>"
		      "<th>fix</th></tr>\n", f);
		for (k = 0; k < row->n_causes; k++) {
			const struct grade_row_cause *rc = &row->causes[k];
			fputs("<tr data-cause=\"", f);
			html_text(f, rc->id);
			fputs("\"><td>", f);
			html_text(f, rc->words);
			fputs("</td><td>", f);
			if (rc->estimated)
				fputs("<span title=\"estimated from a sample of the pixels\">~</span>", f);
			html_psnr(f, rc->psnr);
			fputs(rc->explains ? " (explains it)" : "", f);
			fputs(rc->first_equal ? " (first equal)" : "", f);
			fputs("</td><td>", f);
			html_text(f, rc->fix);
			fputs("</td></tr>\n", f);
		}
		fputs("</table>\n", f);
	}
	fputs("</section>\n", f);
	return 0;
}

/* The class: how many images of each outcome. */
static void html_outcomes(FILE *f, const struct grade_class *c)
{
	struct grade_outcome_tally t;
	size_t j;

	grade_outcome_tally(c, &t);
	fputs("<table id=\"outcomes\"><thead><tr><th>outcome</th><th>images</th></tr></thead><tbody>\n", f);
	for (j = 0; j < t.n; j++) {
		fputs("<tr><td>", f);
		html_text(f, t.names[j]);
		fprintf(f, "</td><td>%zu</td></tr>\n", t.counts[j]);
	}
	fputs("</tbody></table>\n", f);
}

/* A row a student, a column a scene (its verdict and points), the total. */
static void html_students(FILE *f, const struct grade_class *c)
{
	size_t a = 0, b, k;
	int s;

	fputs("<h2>Students</h2><p><input type=\"search\" placeholder=\"filter\" data-table=\"students\" "
	      "oninput=\"filterRows(this)\"></p>\n<table id=\"students\"><thead><tr>", f);
	html_th(f, "student");
	html_th(f, "id");
	for (s = 0; s < c->n_refs; s++) {
		fputs("<th onclick=\"sortBy(this)\">", f);
		html_text(f, scene_name(c->refs[s].scene));
		fputs("</th>", f);
	}
	html_th(f, "points");
	fputs("</tr></thead><tbody>\n", f);
	while (a < c->n_rows) {
		double total = 0.0;
		for (b = a; b < c->n_rows && strcmp(c->rows[b].in->student, c->rows[a].in->student) == 0; b++)
			total += c->rows[b].points;
		fputs("<tr><td>", f);
		html_text(f, c->rows[a].in->student);
		fputs("</td><td>", f);
		html_text(f, c->rows[a].in->id);
		fputs("</td>", f);
		for (s = 0; s < c->n_refs; s++) {
			fputs("<td>", f);
			for (k = a; k < b; k++)
				if (c->rows[k].in->scene == s)
					fprintf(f, "<a href=\"#sub%zu\">%s</a> %g ", k + 1,
						html_verdict(c->rows[k].res.verdict), c->rows[k].points);
			fputs("</td>", f);
		}
		fprintf(f, "<td>%g</td></tr>\n", total);
		a = b;
	}
	fputs("</tbody></table>\n", f);
}

/* Long: the report's page, head, table and sections, as it reads. */
static int html_fill(void *ctx, FILE *f, struct diag *d)
{
	const struct grade_class *c = ctx;
	size_t i, matches = 0;
	int s;

	for (i = 0; i < c->n_rows; i++)
		matches += c->rows[i].res.verdict == CHECK_MATCH;
	fputs("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n<title>whitted grade: ", f);
	for (s = 0; s < c->n_refs; s++) {
		fputs(s ? ", " : "", f);
		html_text(f, scene_name(c->refs[s].scene));
	}
	fprintf(f, "</title>\n<style>%s</style></head>\n<body>\n<h1>whitted grade: ", html_style);
	for (s = 0; s < c->n_refs; s++) {
		fputs(s ? ", " : "", f);
		html_text(f, scene_name(c->refs[s].scene));
	}
	fprintf(f, "</h1>\n<p>Reference %dx%d, recursion level %d, clamping %s. The gate: PSNR "
		   "&ge; %g dB, at most %g %% of pixels off by more than 2 levels and %g %% by more "
		   "than 8, ties (either colour right) left out. An image of another camera is found "
		   "and judged at that camera. <span id=\"tally\">%zu of %zu images match.</span></p>\n",
		c->refs[0].view.image.width, c->refs[0].view.image.height,
		c->refs[0].base.settings.recursion,
		c->refs[0].base.settings.clamp == RT_CLAMP_LEVEL ? "at every level" : "at the end",
		RT_GRADE_MIN_PSNR, 100.0 * RT_GRADE_MAX_OFF2, 100.0 * RT_GRADE_MAX_OFF8, matches,
		c->n_rows);
	html_outcomes(f, c);
	if (c->n_refs > 1)
		html_students(f, c);
	fputs("<h2>Images</h2><p><input type=\"search\" placeholder=\"filter: a name, a verdict, a cause\" "
	      "data-table=\"summary\" oninput=\"filterRows(this)\"></p>\n"
	      "<table id=\"summary\"><thead><tr>", f);
	html_th(f, "#");
	html_th(f, "student");
	html_th(f, "file");
	html_th(f, "verdict");
	html_th(f, "PSNR");
	html_th(f, "points");
	html_th(f, "best explanation");
	html_th(f, "likely cause");
	fputs("</tr></thead><tbody>\n", f);
	for (i = 0; i < c->n_rows; i++) {
		const struct grade_row *row = &c->rows[i];
		const struct check_result *r = &row->res;
		fprintf(f, "<tr class=\"row %s\" data-verdict=\"%s\" data-cause=\"", html_verdict(r->verdict),
			html_verdict(r->verdict));
		if (r->verdict == CHECK_DIFFERS && row->n_causes > 0)
			html_text(f, row->causes[0].id);
		fprintf(f, "\"><td>%zu</td><td>", i + 1);
		html_text(f, row->in->student);
		fprintf(f, "</td><td><a href=\"#sub%zu\">", i + 1);
		html_text(f, row->in->label);
		fprintf(f, "</a></td><td class=\"verdict\">%s</td><td data-v=\"%g\">", html_verdict(r->verdict),
			r->verdict == CHECK_UNREADABLE ? -1.0 : isinf(r->fig.psnr) ? 999.0 : r->fig.psnr);
		if (r->verdict != CHECK_UNREADABLE)
			html_psnr(f, r->fig.psnr);
		fprintf(f, "</td><td>%g</td><td>", row->points);
		html_text(f, row->best);
		fputs("</td><td>", f);
		html_text(f, row->diagnosis);
		fputs("</td></tr>\n", f);
	}
	fputs("</tbody></table>\n", f);
	for (i = 0; i < c->n_rows; i++)
		html_submission(f, c, i);
	fputs(html_script, f);
	fputs("</body></html>\n", f);
	if (ferror(f))
		return diag_fail(d, RT_E_IO, "cannot write the report");
	return 0;
}

int grade_write_report(const struct grade_class *c, const char *path, struct diag *d)
{
	return image_write_file(path, html_fill, (void *)c, &cli_cancelled, d);
}
