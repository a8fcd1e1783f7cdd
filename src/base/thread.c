#include "base/thread.h"

#include <stdbool.h>

#include "base/simd.h"

int rt_thread_start(pthread_t *t, void *(*fn)(void *), void *arg)
{
	pthread_attr_t attr;
	bool sized = pthread_attr_init(&attr) == 0;
	int rc;

	/* The vector level is resolved here, before the thread exists, so
	 * that the workers only ever read it: pthread_once's fast path is an
	 * atomic load that helgrind does not count as ordering, and a worker
	 * that lost the race to initialise it was reported as a data race. */
	(void)rt_simd_level();
	if (sized && pthread_attr_setstacksize(&attr, RT_THREAD_STACK) != 0) {
		pthread_attr_destroy(&attr);
		sized = false;
	}
	rc = pthread_create(t, sized ? &attr : NULL, fn, arg);
	if (sized)
		pthread_attr_destroy(&attr);
	return rc;
}

void rt_run_shared(int n, void *(*fn)(void *), void *arg)
{
	pthread_t tid[RT_PARTS_MAX];
	int k, started = 0;

	n = n > RT_PARTS_MAX ? RT_PARTS_MAX : n;
	for (k = 1; k < n; k++) {
		if (rt_thread_start(&tid[k], fn, arg) != 0)
			break;
		started++;
	}
	fn(arg);
	for (k = 1; k <= started; k++)
		pthread_join(tid[k], NULL);
}

void rt_run_parts(void *parts, size_t size, int n, void *(*fn)(void *))
{
	pthread_t tid[RT_PARTS_MAX];
	bool started[RT_PARTS_MAX];
	char *p = parts;
	int k;

	if (n < 1)
		return;
	for (k = 1; k < n && k < RT_PARTS_MAX; k++)
		started[k] = pthread_create(&tid[k], NULL, fn, p + (size_t)k * size) == 0;
	fn(p);
	for (k = 1; k < n; k++) {
		if (k < RT_PARTS_MAX && started[k])
			pthread_join(tid[k], NULL);
		else
			fn(p + (size_t)k * size);
	}
}
