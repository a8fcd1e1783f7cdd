/* Capturing the current view: the library traces it in a thread of its own
 * (on all cores) and writes a PNG, while the window stays responsive.  No
 * GL here: the main loop polls. */
#ifndef RT_CAPTURE_H
#define RT_CAPTURE_H

#include <pthread.h>
#include <signal.h>
#include <stdbool.h>
#include <stddef.h>

#include "whitted/camera.h"
#include "whitted/diag.h"
#include "whitted/image.h"
#include "whitted/render.h"
#include "whitted/scene.h"

struct capture {
	pthread_t thread;
	bool running;			/* started and not yet joined */
	volatile sig_atomic_t cancel;
	long rows_done, rows_total;	/* written by the thread, atomically */
	int finished;			/* set by the thread, atomically, at its end */
	int rc;
	struct diag diag;
	struct camera camera;
	struct render_job job;
	struct image img;
	char path[64];
};

/* Creates the first capture-N.png with N >= *next that does not exist yet
 * (O_EXCL, so an existing file is never overwritten, not even by another
 * process) and sets *next past it. */
int capture_reserve(int *next, char *path, size_t size, struct diag *d);

/* Starts tracing scene through camera into the reserved path (a copy of the
 * camera is kept; the scene must live until capture_join). */
int capture_start(struct capture *c, const struct scene *s, const struct camera *cam,
		  const struct render_settings *rs, int samples, int threads, const char *path,
		  struct diag *d);
/* True once the thread has finished (capture_join will not block). */
bool capture_finished(const struct capture *c);
/* Progress in percent, 0 to 100. */
int capture_percent(const struct capture *c);
/* Asks the thread to stop soon; capture_join then fails with
 * RT_E_INTERRUPTED. */
void capture_cancel(struct capture *c);
/* Waits for the thread and frees the image; on failure the reserved file
 * is removed.  Returns the capture's status with its diagnostic in *d. */
int capture_join(struct capture *c, struct diag *d);

#endif
