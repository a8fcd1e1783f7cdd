/* What the render tests share: rendering one region of a job, the check
 * that two renders cast the same rays, and the kernels of the set an ISA
 * test runs for.  Header only. */
#ifndef RT_TESTS_RENDER_FIXTURE_H
#define RT_TESTS_RENDER_FIXTURE_H

#include "render/render_kernels.h"
#include "whitted/image.h"
#include "whitted/render.h"
#include "support.h"

/* Renders [x0, x1) x [y0, y1) of job into img (allocated here; the caller
 * frees it), the rays cast in *counts. */
static inline void render_fixture_region(struct render_job *job, int x0, int y0, int x1, int y1,
					 struct image *img, struct ray_counts *counts)
{
	struct diag d;

	job->x0 = x0;
	job->y0 = y0;
	job->x1 = x1;
	job->y1 = y1;
	assert_int_equal(image_alloc(img, x1 - x0, y1 - y0, &d), 0);
	assert_int_equal(render_image(job, img, counts, &d), 0);
}

/* The primary, shadow and reflection rays of two renders' ray_counts
 * equal (a macro, so that a failure names the caller's line). */
#define assert_same_ray_counts(n, n1) \
	do { \
		assert_int_equal((n).primary, (n1).primary); \
		assert_int_equal((n).shadow, (n1).shadow); \
		assert_int_equal((n).reflection, (n1).reflection); \
	} while (0)

/* The render kernels of the set of instructions this test runs for
 * (SUPPORT_ISA_TESTS); the test is skipped where the processor lacks the
 * set and fails where the build does (support_need_isa). */
static inline const struct render_kernels *render_fixture_kernels(void **state)
{
	enum rt_simd isa = SUPPORT_ISA_OF(state);
	const struct render_kernels *k = render_kernels_of(isa);

	support_need_isa(isa, k != NULL);
	return k;
}

#endif
