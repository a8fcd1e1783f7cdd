/* The sets of vector instructions (simd.h): one table, and the choice. */
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#include "base/simd.h"

/* The table of sets: WHITTED_ISA's word for each, and whether the
 * processor runs it (the AVX-512 kernels also use fused multiply-adds
 * where they widen float tests, so they need FMA too). */
#if defined(__x86_64__) && defined(__GNUC__) && !defined(ACCEL_PORTABLE)
#define SIMD_X86 1
#define SIMD_CPU(feature) __builtin_cpu_supports(feature)
#else
#define SIMD_X86 0
#define SIMD_CPU(feature) 0
#endif

static int simd_cpu_avx2(void)
{
	return SIMD_CPU("avx2");
}

static int simd_cpu_avx512(void)
{
	return SIMD_CPU("avx512f") && SIMD_CPU("fma");
}

static const struct simd_set {
	const char *name;
	int (*cpu_has)(void);	/* NULL: every processor the build runs on */
} simd_sets[RT_SIMD_COUNT] = {
#if defined(__SSE2__) && !defined(ACCEL_PORTABLE)
	[RT_SIMD_BASE] = { "sse2", NULL },
#else
	[RT_SIMD_BASE] = { "portable", NULL },
#endif
	[RT_SIMD_AVX2] = { "avx2", simd_cpu_avx2 },
	[RT_SIMD_AVX512] = { "avx512", simd_cpu_avx512 },
};

int rt_simd_cpu_has(enum rt_simd s)
{
	if (s == RT_SIMD_BASE)
		return 1;
	return SIMD_X86 && (unsigned)s < RT_SIMD_COUNT &&
	       (!simd_sets[s].cpu_has || simd_sets[s].cpu_has());
}

bool rt_simd_built(enum rt_simd s)
{
#define SIMD_IS(set, suffix, a, b) || s == set
	return false RT_SIMD_BUILT_SETS(SIMD_IS, -, -);
#undef SIMD_IS
}

const char *rt_simd_name(enum rt_simd s)
{
	return (unsigned)s < RT_SIMD_COUNT ? simd_sets[s].name : "?";
}

/* WHITTED_ISA's set: the set it names (the baseline's "sse2" also in the
 * portable build), or RT_SIMD_COUNT for none (unset, or a word that names
 * no set). */
static enum rt_simd simd_requested(void)
{
	const char *isa = getenv("WHITTED_ISA");
	int s;

	if (!isa || !*isa)
		return RT_SIMD_COUNT;
	if (strcmp(isa, "sse2") == 0)
		return RT_SIMD_BASE;
	for (s = 0; s < RT_SIMD_COUNT; s++)
		if (strcmp(isa, simd_sets[s].name) == 0)
			return (enum rt_simd)s;
	return RT_SIMD_COUNT;
}

const char *rt_simd_request_unknown(void)
{
	const char *isa = getenv("WHITTED_ISA");

	return isa && *isa && simd_requested() == RT_SIMD_COUNT ? isa : NULL;
}

static pthread_once_t level_once = PTHREAD_ONCE_INIT;
static enum rt_simd level;

static void level_init(void)
{
	enum rt_simd cap = simd_requested();

	level = cap == RT_SIMD_COUNT ? (enum rt_simd)(RT_SIMD_COUNT - 1) : cap;
	while (level > RT_SIMD_BASE && !(rt_simd_built(level) && rt_simd_cpu_has(level)))
		level = (enum rt_simd)(level - 1);
}

enum rt_simd rt_simd_level(void)
{
	pthread_once(&level_once, level_init);
	return level;
}
