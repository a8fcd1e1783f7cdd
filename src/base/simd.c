/* Which vector instructions the packet loops use (simd.h). */
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#include "base/simd.h"

int rt_simd_cpu_has(enum rt_simd s)
{
#if defined(__x86_64__) && defined(__GNUC__) && !defined(ACCEL_PORTABLE)
	switch (s) {
	case RT_SIMD_AVX512:
		return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("fma");
	case RT_SIMD_AVX2:
		return __builtin_cpu_supports("avx2");
	default:
		return 1;
	}
#else
	return s == RT_SIMD_BASE;
#endif
}

static pthread_once_t level_once = PTHREAD_ONCE_INIT;
static enum rt_simd level;

static void level_init(void)
{
	const char *isa = getenv("WHITTED_ISA");
	enum rt_simd cap = RT_SIMD_AVX512;

	if (isa && strcmp(isa, "sse2") == 0)
		cap = RT_SIMD_BASE;
	else if (isa && strcmp(isa, "avx2") == 0)
		cap = RT_SIMD_AVX2;
	for (level = cap; level > RT_SIMD_BASE && !rt_simd_cpu_has(level);)
		level = (enum rt_simd)(level - 1);
}

enum rt_simd rt_simd_level(void)
{
	pthread_once(&level_once, level_init);
	return level;
}
