/* A scene's hierarchy built once for each walk this processor runs (the
 * base walks over four children; AVX2 and AVX-512 over eight), and the
 * four-child one once more for each set of instructions its packets can
 * go a ray a lane in (accel_packet_rays.h: SSE2 or plain C, AVX2,
 * AVX-512), for the tests that hold the walks to one another's answers.
 * The first is the base walk with the base packets.  A set this processor
 * lacks is left out, and said so once a program (support_isa_part: the
 * unit runner counts it). */
#ifndef RT_TEST_WALK_SET_H
#define RT_TEST_WALK_SET_H

#include "accel/accel.h"
#include "accel/accel_tree.h"
#include "support.h"

struct walk_set {
	struct accel *a[5];
	int n;
};

static inline void walk_set_build(struct walk_set *w, const struct scene *s)
{
	static const enum rt_simd walks[] = { RT_SIMD_BASE, RT_SIMD_AVX2,
						 RT_SIMD_AVX512 };
	static bool reported;
	struct diag d;
	size_t k;

	if (!reported) {
		reported = true;
		(void)support_isa_part(RT_SIMD_AVX2, accel_walk_usable(RT_SIMD_AVX2));
		(void)support_isa_part(RT_SIMD_AVX512, accel_walk_usable(RT_SIMD_AVX512));
	}
	w->n = 0;
	for (k = 0; k < sizeof(walks) / sizeof(walks[0]); k++) {
		size_t j;

		if (!accel_walk_usable(walks[k]))
			continue;
		for (j = 0; j < (walks[k] == RT_SIMD_BASE ? 3u : 1u); j++) {
			if (!accel_walk_usable(walks[j]))
				continue;
			assert_int_equal(accel_build_walk(s->shapes, s->n_shapes, 1, walks[k],
							  &w->a[w->n], &d), 0);
			assert_int_equal(w->a[w->n]->walk_set, walks[k]);
			if (walks[k] == RT_SIMD_BASE)
				accel_set_rays(w->a[w->n], walks[j]);
			w->n++;
		}
	}
}

static inline void walk_set_free(struct walk_set *w)
{
	int k;

	for (k = 0; k < w->n; k++)
		accel_destroy(w->a[k]);
	w->n = 0;
}

#endif
