/* The capture thread: render_image (which starts its own workers) and the
 * PNG writer, exactly as whitted runs them, so the file equals whitted's
 * output for the same camera.  The main thread sees progress and the end
 * through atomics and never blocks until it joins a finished thread. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "capture.h"

int capture_reserve(int *next, char *path, size_t size, struct diag *d)
{
	int n, fd;

	for (n = *next > 0 ? *next : 1; n < 1000000; n++) {
		snprintf(path, size, "capture-%d.png", n);
		fd = open(path, O_WRONLY | O_CREAT | O_EXCL, 0644);
		if (fd >= 0) {
			close(fd);
			*next = n + 1;
			return 0;
		}
		if (errno != EEXIST)
			return diag_set(d, RT_E_IO, path, 0, 0, "cannot create: %s", strerror(errno));
	}
	return diag_fail(d, RT_E_IO, "no free name capture-N.png left");
}

static void capture_progress(void *ctx, long done, long total)
{
	struct capture *c = ctx;

	__atomic_store_n(&c->rows_total, total, __ATOMIC_RELAXED);
	__atomic_store_n(&c->rows_done, done, __ATOMIC_RELAXED);
}

static void *capture_main(void *arg)
{
	struct capture *c = arg;
	int rc;

	rc = render_image(&c->job, &c->img, NULL, &c->diag);
	if (rc == 0)
		rc = image_write(&c->img, c->path, RT_FORMAT_PNG, &c->cancel, &c->diag);
	c->rc = rc;
	__atomic_store_n(&c->finished, 1, __ATOMIC_RELEASE);
	return NULL;
}

int capture_start(struct capture *c, const struct scene *s, const struct camera *cam,
		  const struct render_settings *rs, int samples, int threads, const char *path,
		  struct diag *d)
{
	int rc;

	memset(c, 0, sizeof(*c));
	diag_clear(&c->diag);
	c->camera = *cam;
	snprintf(c->path, sizeof(c->path), "%s", path);
	if ((rc = image_alloc(&c->img, scene_image_size(s), scene_image_size(s), d)) < 0)
		return rc;
	c->rows_total = scene_image_size(s);
	render_job_init(&c->job, s, &c->camera, threads);
	c->job.settings = *rs;
	c->job.samples = samples;
	c->job.cancel = &c->cancel;
	c->job.progress = capture_progress;
	c->job.progress_ctx = c;
	rc = pthread_create(&c->thread, NULL, capture_main, c);
	if (rc != 0) {
		image_free(&c->img);
		return diag_fail(d, RT_E_NOMEM, "cannot start a thread: %s", strerror(rc));
	}
	c->running = true;
	return 0;
}

bool capture_finished(const struct capture *c)
{
	return __atomic_load_n(&c->finished, __ATOMIC_ACQUIRE) != 0;
}

int capture_percent(const struct capture *c)
{
	long done = __atomic_load_n(&c->rows_done, __ATOMIC_RELAXED);
	long total = __atomic_load_n(&c->rows_total, __ATOMIC_RELAXED);

	return total > 0 ? (int)(100 * done / total) : 0;
}

void capture_cancel(struct capture *c)
{
	c->cancel = 1;
}

int capture_join(struct capture *c, struct diag *d)
{
	if (!c->running)
		return 0;
	pthread_join(c->thread, NULL);
	c->running = false;
	image_free(&c->img);
	if (c->rc < 0) {
		unlink(c->path);
		*d = c->diag;
	}
	return c->rc;
}
