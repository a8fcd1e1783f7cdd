/* The sets of vector instructions whitted's kernels are compiled for, in
 * one table (simd.c), and the set the program uses: chosen once, at the
 * first question, as the widest the processor runs and the build has,
 * within WHITTED_ISA's limit (read here and nowhere else).
 *
 * A module's kernels are one source written over base/lanes.h (the
 * render's render_kernels.c, the shapes' solve_kernels.c, the hierarchy's
 * accel_kernels.c) that the Makefile compiles once per set this build has,
 * with its -m flags and -DRT_SIMD_KERNEL=<suffix>, into one table named
 * <prefix>_<suffix> (RT_SIMD_KERNEL_NAME); the module's tables, indexed by
 * set, come from RT_SIMD_TABLES.  A new set is this header (its enum
 * entry and its line in the list), its row in simd.c, its flags in the
 * Makefile and its lanes in base/lanes.h. */
#ifndef RT_SIMD_H
#define RT_SIMD_H

#include <stdbool.h>

enum rt_simd {
	RT_SIMD_BASE,	/* SSE2, or plain C in the portable build */
	RT_SIMD_AVX2,
	RT_SIMD_AVX512,
	RT_SIMD_COUNT
};

/* X(set, suffix, a, b) for each set whose kernels this build compiled:
 * on x86-64 the Makefile says RT_SIMD_X86_KERNELS (not for Windows, whose
 * compiler misaligns the wide spills, nor for the web); elsewhere the
 * baseline alone. */
#ifdef RT_SIMD_X86_KERNELS
#define RT_SIMD_BUILT_SETS(X, a, b) X(RT_SIMD_BASE, base, a, b) X(RT_SIMD_AVX2, avx2, a, b) X(RT_SIMD_AVX512, avx512, a, b)
#else
#define RT_SIMD_BUILT_SETS(X, a, b) X(RT_SIMD_BASE, base, a, b)
#endif

/* In a kernel source: the name of its table in the set being compiled. */
#define RT_SIMD_CAT_(a, b) a##_##b
#define RT_SIMD_CAT(a, b) RT_SIMD_CAT_(a, b)
#define RT_SIMD_KERNEL_NAME(prefix) RT_SIMD_CAT(prefix, RT_SIMD_KERNEL)

/* In a module: its tables (of type, named prefix_<suffix>) declared and
 * listed by set in the array name, NULL for a set not built. */
#define RT_SIMD_DECLARE_(set, suffix, type, prefix) extern const type prefix##_##suffix;
#define RT_SIMD_ENTRY_(set, suffix, type, prefix) [set] = &prefix##_##suffix,
#define RT_SIMD_TABLES(type, prefix, name) \
	RT_SIMD_BUILT_SETS(RT_SIMD_DECLARE_, type, prefix) \
	static const type *const name[RT_SIMD_COUNT] = { \
		RT_SIMD_BUILT_SETS(RT_SIMD_ENTRY_, type, prefix) \
	}

/* The set in use: the widest the processor runs and the build has
 * (the portable build: RT_SIMD_BASE), within WHITTED_ISA's limit. */
enum rt_simd rt_simd_level(void);
/* Whether the processor runs set s (whatever the build or WHITTED_ISA). */
int rt_simd_cpu_has(enum rt_simd s);
/* Whether this build compiled set s's kernels (and may run them). */
bool rt_simd_built(enum rt_simd s);
/* Set s's name: "sse2" ("portable" in the portable build), "avx2",
 * "avx512": WHITTED_ISA's words, and what --stats prints. */
const char *rt_simd_name(enum rt_simd s);
/* WHITTED_ISA's value when it names no set (it is then ignored), else
 * NULL. */
const char *rt_simd_request_unknown(void);

#endif
