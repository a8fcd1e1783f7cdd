/* The packet solvers in AVX-512 (eight lanes), compiled with -mavx512f on x86 (the
 * Makefile) and chosen where the processor has it (solve_packet.c);
 * elsewhere an empty set, which is never chosen. */
#include "shapes/solve_packet.h"

#if defined(__AVX512F__) && !defined(ACCEL_PORTABLE)
#define SOLVE_LANES(name) solve_lanes_avx512_##name
#include "shapes/solve_packet_lanes.h"

const struct solve_packet_set solve_packet_avx512 = {
	SOLVE_LANES(sphere), SOLVE_LANES(triangle), SOLVE_LANES(floor), SOLVE_LANES(floor_cells),
	SOLVE_LANES(sphere_normal)
};
#else
const struct solve_packet_set solve_packet_avx512 = { 0, 0, 0, 0, 0 };
#endif
