/* The hierarchy's walks in one set of instructions: compiled by the
 * Makefile once per set (with its -m flags and -DRT_SIMD_KERNEL=<suffix>)
 * into the table accel_kernels_<suffix> (accel_kernels.h).  The node tests
 * are the set's own; a set without its own, a new one among them, takes
 * the base walks (SSE2, or plain C). */
#include <math.h>
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

#include "accel/accel.h"
#include "accel/accel_kernels.h"
#include "accel/accel_slab.h"
#include "accel/accel_tree.h"

/* The table's entries for a set's rays4 walk (accel_packet_rays.h with
 * RAYS_WALK(name) prefix##_##name). */
#define ACCEL_KERNELS_RAYS4(prefix) { \
	.intersect_packet = prefix##_intersect_packet, \
	.occluded_packet = prefix##_occluded_packet, \
	.intersect_lanes = prefix##_intersect_lanes, \
	.occluded_lanes = prefix##_occluded_lanes, \
}
#ifdef RT_TEST_HOOKS
#define ACCEL_KERNELS_TEST_HOOKS(node, rays) .node_tests = node, .rays_node_tests = rays,
#else
#define ACCEL_KERNELS_TEST_HOOKS(node, rays)
#endif

/* By the set being compiled (the Makefile's -DRT_SIMD_KERNEL_<suffix>),
 * not by what the compiler allows: the base set's walks stay the
 * four-child ones under -march=native too. */
#if defined(RT_SIMD_KERNEL_avx512) && defined(__AVX512F__) && !defined(ACCEL_PORTABLE)
#include "accel/walk_avx512.h"
#elif defined(RT_SIMD_KERNEL_avx2) && defined(__AVX2__) && !defined(ACCEL_PORTABLE)
#include "accel/walk_avx2.h"
#else
#include "accel/walk_base.h"
#endif

extern const struct accel_kernels RT_SIMD_KERNEL_NAME(accel_kernels);
const struct accel_kernels RT_SIMD_KERNEL_NAME(accel_kernels) = ACCEL_KERNELS_TABLE;
