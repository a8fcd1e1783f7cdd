#include "base/thread.h"

#include <stdbool.h>

int rt_thread_start(pthread_t *t, void *(*fn)(void *), void *arg)
{
	pthread_attr_t attr;
	bool sized = pthread_attr_init(&attr) == 0;
	int rc;

	if (sized && pthread_attr_setstacksize(&attr, RT_THREAD_STACK) != 0) {
		pthread_attr_destroy(&attr);
		sized = false;
	}
	rc = pthread_create(t, sized ? &attr : NULL, fn, arg);
	if (sized)
		pthread_attr_destroy(&attr);
	return rc;
}
