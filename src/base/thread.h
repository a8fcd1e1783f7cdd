/* Starting a worker thread with a stack of a known size (and the vector
 * level, base/simd.h, already resolved).  The default is
 * the process's stack limit on glibc but 2 MiB when that limit is
 * unlimited, and 128 KiB on musl; a packet's recursive shading and the
 * hierarchy walks need some hundred kilobytes at the deepest recursion,
 * so the renderer's and the grader's workers ask for RT_THREAD_STACK. */
#ifndef RT_THREAD_H
#define RT_THREAD_H

#include <pthread.h>

#define RT_THREAD_STACK ((size_t)8 << 20)

/* pthread_create(t, attributes with RT_THREAD_STACK, fn, arg); falls back
 * to the default attributes if the size cannot be set.  Returns 0 or the
 * error pthread_create returned. */
int rt_thread_start(pthread_t *t, void *(*fn)(void *), void *arg);

/* fn(arg) on n threads at once, the calling thread one of them (at most
 * RT_PARTS_MAX; fewer when a thread cannot be started): workers that
 * share arg and take their work from it.  The others get RT_THREAD_STACK.
 * Returns when all have returned. */
void rt_run_shared(int n, void *(*fn)(void *), void *arg);

/* The parts a job is cut into that rt_run_parts starts threads for; more
 * run on the calling thread. */
#define RT_PARTS_MAX 64

/* fn on each of n parts, part k at (char *)parts + k * size: the first
 * on the calling thread, the others on threads of their own (the
 * default attributes: the parts' work is shallow), and a part whose
 * thread cannot be started on the calling thread once the rest are done.
 * Returns when every part has run. */
void rt_run_parts(void *parts, size_t size, int n, void *(*fn)(void *));

#endif
