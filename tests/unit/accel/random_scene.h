/* The accel tests' random scenes: n shapes placed by the test's own
 * add_random_shape (each test file draws its own mix), from the seeded
 * stream of support.h.  Header only. */
#ifndef RT_TEST_RANDOM_SCENE_H
#define RT_TEST_RANDOM_SCENE_H

#include <stdbool.h>
#include <stdint.h>

#include "support.h"

typedef void random_shape_fn(struct scene *s, struct vec3 c, double size);

/* n shapes of size 0.5 to 10 about centres in [-half, half]^3, the stream
 * seeded with seed first; the floor 80 wide in tiles of 8 added when
 * with_floor; prepared on one thread.  The caller destroys it. */
static inline struct scene *random_scene(random_shape_fn *add_random_shape, uint64_t seed, int n,
					 double half, bool with_floor)
{
	struct scene *s = scene_create("random");
	struct diag d;
	int i;

	support_rng_seed(seed);
	assert_non_null(s);
	for (i = 0; i < n; i++)
		add_random_shape(s, support_random_point(half), support_uniform(0.5, 10));
	if (with_floor)
		assert_int_equal(scene_add_floor(s, 80, 8, &d), 0);
	assert_int_equal(scene_prepare(s, 1, &d), 0);
	return s;
}

#endif
