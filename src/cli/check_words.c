/* What compare and grade say of a check: the causes in words, the
 * diagnosis sentence and the line on the objects. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cli/check.h"

static const struct grade_job *check_job(const struct check_reference *ref,
					 const struct check_result *res)
{
	return res ? &check_result_view(ref, res)->job : &ref->view.job;
}

/* One cause with its form's detail: "another recursion level (recursion
 * level 2 instead of 4)". */
static void check_one_cause(const struct grade_job *job, enum grade_cause c, int form, char *buf,
			    size_t size)
{
	char detail[128];

	grade_cause_detail(job, c, form, detail, sizeof(detail));
	if (detail[0] && c != RT_CAUSE_GAMMA && c != RT_CAUSE_LIGHT_BEHIND && c != RT_CAUSE_PIXEL_CORNERS)
		snprintf(buf, size, "%s (%s)", grade_cause_text(c, job->settings.clamp)->with, detail);
	else
		snprintf(buf, size, "%s", grade_cause_text(c, job->settings.clamp)->with);
}

void check_cause_words(const struct check_reference *ref, const struct check_result *res,
		       const struct grade_rank *r, char *buf, size_t size)
{
	const struct grade_job *job = check_job(ref, res);
	char a[200], b[200];

	check_one_cause(job, r->cause, r->form, a, sizeof(a));
	if (r->also == RT_CAUSE_NONE) {
		snprintf(buf, size, "%s", a);
		return;
	}
	if (r->cause == RT_CAUSE_MIRRORED && r->also == RT_CAUSE_UPSIDE_DOWN) {
		snprintf(buf, size, "the image turned half round (mirrored and upside down)");
		return;
	}
	check_one_cause(job, r->also, r->also_form, b, sizeof(b));
	snprintf(buf, size, "%s and %s", a, b);
}

/* A rank's cause, or its two causes joined by sep: the id ("gamma+fov")
 * and the fix ("...; and ...") say a pair alike, each by its own field of
 * the causes' texts; also is NULL for a rank of one cause. */
static void check_join_causes(const char *cause, const char *also, const char *sep, char *buf,
			      size_t size)
{
	snprintf(buf, size, "%s%s%s", cause, also ? sep : "", also ? also : "");
}

void check_cause_id(const struct check_reference *ref, const struct grade_rank *r, char *buf,
		    size_t size)
{
	enum clamp_mode clamp = ref->base.settings.clamp;

	check_join_causes(grade_cause_text(r->cause, clamp)->id,
			  r->also == RT_CAUSE_NONE ? NULL : grade_cause_text(r->also, clamp)->id, "+",
			  buf, size);
}

void check_cause_fix(const struct check_reference *ref, const struct grade_rank *r, char *buf,
		     size_t size)
{
	enum clamp_mode clamp = ref->base.settings.clamp;

	check_join_causes(grade_cause_text(r->cause, clamp)->fix,
			  r->also == RT_CAUSE_NONE ? NULL : grade_cause_text(r->also, clamp)->fix,
			  "; and ", buf, size);
}

/* "your camera differs: found --eye ...; at that camera " or "". */
static void check_camera_words(const struct check_result *res, char *buf, size_t size)
{
	char opts[200];

	buf[0] = '\0';
	if (!res->moved)
		return;
	check_camera_options(&res->found.params, opts, sizeof(opts));
	snprintf(buf, size, "your camera differs: found %s; at that camera ", opts);
}

/* The diagnosis when no cause comes close: the image nearly matches
 * (CHECK_NEAR_PSNR), or it differs by what no known mistake makes. */
static void check_unexplained_words(const struct check_result *res,
				    const struct grade_figures *plain, const char *cam,
				    const char *first, char *buf, size_t size)
{
	if (plain->psnr >= CHECK_NEAR_PSNR)
		snprintf(buf, size, "%s%s (%.1f dB; %.2f%% of the pixels differ): no known mistake comes "
			 "nearer (the nearest, %s, reaches %.1f dB), so what remains is small: %sa "
			 "difference no known mistake makes (see where with --diff)", cam,
			 res->moved ? "it nearly matches" : "nearly matches", plain->psnr,
			 100.0 * plain->off2, first, res->ranks[0].fig.psnr,
			 res->moved ? "the camera found a little off, or " : "");
	else
		snprintf(buf, size, "%s%snone of the known mistakes comes close (the nearest, %s, "
			 "reaches %.1f dB against the reference's %.1f dB)", cam,
			 res->moved ? "it differs: " : "", first, res->ranks[0].fig.psnr, plain->psnr);
}

void check_diagnosis(const struct check_reference *ref, const struct check_result *res,
		     char *buf, size_t size)
{
	char cam[320], first[400], fix[600], equal[400] = "", efix[600] = "";
	const char *conv = "";
	const struct grade_figures *plain = res->moved ? &res->fig_found : &res->fig;

	check_camera_words(res, cam, sizeof(cam));
	if (res->floor_textured && res->verdict != CHECK_UNREADABLE) {
		size_t n = strlen(cam);
		snprintf(cam + n, sizeof(cam) - n, "%sthe floor is textured, not the reference's two-colour "
			 "checker: judged without it; ", n ? "" : "");
	}
	if (res->verdict == CHECK_UNREADABLE) {
		snprintf(buf, size, "unreadable: %s", res->error.msg);
		return;
	}
	if (res->verdict == CHECK_MATCH && res->moved) {
		snprintf(buf, size, "%syour image matches the reference (%.1f dB there, against "
			 "%.1f dB at the camera given)", cam, res->fig_found.psnr_gate, res->fig.psnr);
		return;
	}
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
	if (res->n_ranks == 0) {
		snprintf(buf, size, "%s%snone of the known mistakes changes this scene's image", cam,
			 res->moved ? "it differs: " : "");
		return;
	}
	check_cause_words(ref, res, &res->ranks[0], first, sizeof(first));
	check_cause_fix(ref, &res->ranks[0], fix, sizeof(fix));
	if (res->n_ranks > 1 && res->ranks[1].first_equal) {
		check_cause_words(ref, res, &res->ranks[1], equal, sizeof(equal));
		check_cause_fix(ref, &res->ranks[1], efix, sizeof(efix));
	}
	if (res->ranks[0].truncated)
		conv = " (and 255*c truncated, not rounded: that is fine)";
	if (res->explained == CHECK_EXPLAINED)
		snprintf(buf, size, "%s%s with %s%s%s%s: %s%s%s", cam,
			 res->moved ? "your image matches the reference" : "matches the reference",
			 first, equal[0] ? ", or equally with " : "", equal, conv, fix,
			 equal[0] ? "; or " : "", efix);
	else if (res->explained == CHECK_CLOSE)
		snprintf(buf, size, "%s%smost likely %s%s%s (%.1f dB against the reference's %.1f dB), "
			 "though %.2f%% of the pixels still differ: %s; then look for another mistake",
			 cam, res->moved ? "it differs: " : "", first, equal[0] ? ", or equally " : "",
			 equal, res->ranks[0].fig.psnr, plain->psnr, 100.0 * res->ranks[0].fig.off2, fix);
	else
		check_unexplained_words(res, plain, cam, first, buf, size);
}

/* How many objects of each keyword a list names, as "the 3 spheres and 2
 * triangles" (keywords in the order met). */
static void check_count_words(const struct grade_object *const *objs, size_t n, char *buf,
			      size_t size)
{
	const char *seen[16];
	size_t counts[16], n_seen = 0, k, j, len = 0;

	for (k = 0; k < n; k++) {
		for (j = 0; j < n_seen && strcmp(seen[j], objs[k]->keyword) != 0; j++)
			;
		if (j == n_seen && n_seen < 16) {
			seen[n_seen] = objs[k]->keyword;
			counts[n_seen++] = 0;
		}
		if (j < n_seen)
			counts[j]++;
	}
	buf[0] = '\0';
	for (j = 0; j < n_seen && len < size; j++) {
		const char *sep = j == 0 ? "" : j + 1 == n_seen ? " and " : ", ";
		int w = counts[j] == 1 ? snprintf(buf + len, size - len, "%sthe %s", j == 0 ? "" : sep, seen[j])
				       : snprintf(buf + len, size - len, "%s%zu %ss", j == 0 ? "the " : sep,
						  counts[j], seen[j]);
		len += w > 0 ? (size_t)w : 0;
	}
}

void check_objects_line(const struct check_result *res, char *buf, size_t size)
{
	const struct grade_object *same[256], *differ[256];
	size_t n_same = 0, n_differ = 0, k, len;
	char list[400];

	buf[0] = '\0';
	if (res->n_objects == 0 || res->verdict == CHECK_UNREADABLE)
		return;
	for (k = 0; k < res->n_objects; k++) {
		const struct grade_object *o = &res->objects[k];
		if (o->index == 0)
			continue;
		if (o->off2 <= RT_GRADE_MAX_OFF2 * 5.0 && n_same < 256)
			same[n_same++] = o;
		else if (o->off2 > RT_GRADE_MAX_OFF2 * 5.0 && n_differ < 256)
			differ[n_differ++] = o;
	}
	len = 0;
	if (n_same > 0) {
		check_count_words(same, n_same, list, sizeof(list));
		len = (size_t)snprintf(buf, size, "%s match%s", list, n_same == 1 ? "es" : "");
	}
	for (k = 0; k < res->n_objects && len < size; k++) {
		const struct grade_object *o = &res->objects[k];
		if (o->index == 0 && o->off2 > RT_GRADE_MAX_OFF2 * 5.0)
			len += (size_t)snprintf(buf + len, size - len, "%sthe %s differs in %.0f%% of its pixels",
						len ? "; " : "", o->keyword, 100.0 * o->off2);
	}
	for (k = 0; k < n_differ && k < 6 && len < size; k++)
		len += (size_t)snprintf(buf + len, size - len, "%s%s %ld differs in %.0f%% of its pixels",
					len ? "; " : "", differ[k]->keyword, differ[k]->index,
					100.0 * differ[k]->off2);
	if (n_differ > 6 && len < size)
		snprintf(buf + len, size - len, "; %zu more objects differ", n_differ - 6);
}
