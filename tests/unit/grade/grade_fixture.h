/* What the grade tests set up alike: a scene with the view's floor and a
 * grade job over it.  Included by each test file that uses it (static
 * inline functions, none needed by all). */
#ifndef RT_TESTS_GRADE_FIXTURE_H
#define RT_TESTS_GRADE_FIXTURE_H

#include <string.h>

#include "whitted/camera.h"
#include "whitted/grade.h"
#include "support.h"

/* Scene text parsed, with the floor its view asks for, prepared on one
 * thread; *p the default camera parameters.  The caller destroys it. */
static inline struct scene *grade_fixture_scene(const char *text, struct camera_params *p)
{
	struct scene *s = support_parse(text);
	struct diag d;

	assert_int_equal(scene_add_view_floor(s, &d), 0);
	assert_int_equal(scene_prepare(s, 1, &d), 0);
	camera_params_default(p);
	return s;
}

/* The job that grades s through cam: every other field zero, the clamp
 * the assignment's (by level). */
static inline void grade_fixture_job(struct grade_job *job, const struct scene *s,
				     const struct camera *cam, int recursion, int threads)
{
	memset(job, 0, sizeof(*job));
	job->scene = s;
	job->camera = cam;
	job->settings.recursion = recursion;
	job->settings.clamp = RT_CLAMP_LEVEL;
	job->threads = threads;
}

#endif
