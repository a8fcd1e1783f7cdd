/* What a render reports on stderr besides errors: the progress bar and
 * the --stats lines. */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <time.h>

#include "base/platform.h"
#include "cli/report.h"

double report_now(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (double)ts.tv_sec + ts.tv_nsec * 1e-9;
}

void report_progress(void *ctx, long done, long total)
{
	struct progress_bar *bar = ctx;
	int percent = (int)(100 * done / total), filled = percent * 30 / 100;

	if (percent == bar->last_percent)
		return;
	bar->last_percent = percent;
	fprintf(stderr, "\rrendering %3d%% [%.*s%*s]", percent, filled,
		"==============================", 30 - filled, "");
	if (done == total)
		fprintf(stderr, "\r%*s\r", 48, "");
	fflush(stderr);
}

void report_stats(const struct scene *s, const struct settings *set, const struct ray_counts *rc,
		  int threads, const struct report_times *t)
{
	double total = (double)(rc->primary + rc->shadow + rc->reflection + rc->refraction);
	char text[RT_SETTINGS_TEXT_MAX];

	settings_format(set, text, sizeof(text));
	fprintf(stderr,
		"scene:    %zu objects, %zu lights, %dx%d, recursion %d, %zu hierarchy nodes (%.1f MiB, %s walk, %s; %s kernels)\n"
		"settings: %s\n"
		"time:     parse %.3f s, build %.3f s, render %.3f s (%d threads), write %.3f s\n"
		"rays:     %llu primary, %llu shadow, %llu reflection, %llu refracted, %.2f M rays/s\n"
		"memory:   %.1f MiB peak resident\n",
		scene_shape_count(s), scene_light_count(s), scene_image_size(s), scene_image_size(s),
		scene_recursion(s),
		scene_hierarchy_nodes(s), scene_hierarchy_bytes(s) / 1048576.0, scene_hierarchy_walk(s),
		scene_hierarchy_packets(s), scene_kernels_isa(),
		text,
		t->parse, t->build, t->render, threads, t->write,
		(unsigned long long)rc->primary, (unsigned long long)rc->shadow,
		(unsigned long long)rc->reflection, (unsigned long long)rc->refraction, t->render > 0 ? total / t->render * 1e-6 : 0.0,
		rt_peak_resident_bytes() / 1048576.0);
}

