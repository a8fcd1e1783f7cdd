/* Which vector instructions the packets' loops use (base/lanes.h): the
 * widest the processor has, within WHITTED_ISA's limit. */
#ifndef RT_SIMD_H
#define RT_SIMD_H

enum rt_simd {
	RT_SIMD_BASE,	/* SSE2, or plain C in the portable build */
	RT_SIMD_AVX2,
	RT_SIMD_AVX512
};

/* The widest set the processor runs and the build has (the portable
 * build: RT_SIMD_BASE), within WHITTED_ISA's limit (sse2, avx2, avx512);
 * asked once. */
enum rt_simd rt_simd_level(void);
/* Whether the processor runs set s (whatever WHITTED_ISA says). */
int rt_simd_cpu_has(enum rt_simd s);

#endif
