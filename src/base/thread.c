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
