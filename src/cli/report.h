/* The progress bar and the --stats lines of a render, on stderr. */
#ifndef RT_CLI_REPORT_H
#define RT_CLI_REPORT_H

#include "whitted/render.h"
#include "whitted/scene.h"
#include "whitted/settings.h"

/* A monotonic clock, in seconds. */
double report_now(void);

struct progress_bar {
	int last_percent;
};
/* A render_job progress callback; ctx is a struct progress_bar. */
void report_progress(void *ctx, long done, long total);

struct report_times {
	double parse, build, render, write;
};
/* The --stats lines, among them "settings: " and the canonical text of
 * the settings (for frames, the last frame's): what a tile of this run
 * records, to compare with a tile that the merge refuses. */
void report_stats(const struct scene *s, const struct settings *set, const struct ray_counts *rc,
		  int threads, const struct report_times *t);

#endif
