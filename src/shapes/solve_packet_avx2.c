/* The packet solvers in AVX2 (four lanes), compiled with -mavx2 on x86 (the
 * Makefile) and chosen where the processor has it (solve_packet.c);
 * elsewhere an empty set, which is never chosen. */
#include "shapes/solve_packet.h"

#if defined(__AVX2__) && !defined(ACCEL_PORTABLE)
#define SOLVE_LANES(name) solve_lanes_avx2_##name
#include "shapes/solve_packet_lanes.h"

const struct solve_packet_set solve_packet_avx2 = {
	SOLVE_LANES(sphere), SOLVE_LANES(triangle), SOLVE_LANES(floor), SOLVE_LANES(floor_cells),
	SOLVE_LANES(sphere_normal)
};
#else
const struct solve_packet_set solve_packet_avx2 = { 0, 0, 0, 0, 0 };
#endif
