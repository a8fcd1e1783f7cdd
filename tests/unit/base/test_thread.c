/* rt_run_parts: every part run exactly once, the first on the calling
 * thread, for one part, a few, the most it starts threads for, and more
 * (the rest on the calling thread); and no call for no parts. */
#include <pthread.h>
#include <string.h>

#include "base/thread.h"
#include "support.h"

struct part {
	int runs;
	pthread_t by;
	char pad[40];	/* parts need not be a word's size apart */
};

static void *run_part(void *arg)
{
	struct part *p = arg;

	p->runs++;
	p->by = pthread_self();
	return NULL;
}

static void test_run_parts_runs_each_part_once(void **state)
{
	static const int counts[] = { 1, 2, 7, RT_PARTS_MAX, RT_PARTS_MAX + 9 };
	static struct part parts[RT_PARTS_MAX + 9];
	size_t c;
	int k;

	(void)state;
	for (c = 0; c < sizeof(counts) / sizeof(counts[0]); c++) {
		int n = counts[c];

		memset(parts, 0, sizeof(parts));
		rt_run_parts(parts, sizeof(parts[0]), n, run_part);
		for (k = 0; k < RT_PARTS_MAX + 9; k++)
			if (parts[k].runs != (k < n ? 1 : 0))
				fail_msg("%d parts: part %d ran %d times", n, k, parts[k].runs);
		assert_true(pthread_equal(parts[0].by, pthread_self()));
		for (k = RT_PARTS_MAX; k < n; k++)
			assert_true(pthread_equal(parts[k].by, pthread_self()));
	}
}

static void test_run_parts_of_nothing(void **state)
{
	struct part p = { 0, pthread_self(), { 0 } };

	(void)state;
	rt_run_parts(&p, sizeof(p), 0, run_part);
	rt_run_parts(&p, sizeof(p), -3, run_part);
	assert_int_equal(p.runs, 0);
}

SUPPORT_MAIN(SUPPORT_TESTS(test_run_parts_runs_each_part_once, test_run_parts_of_nothing))
