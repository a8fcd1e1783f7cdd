/* FNV-1a, 64 bits: h = (h XOR byte) * 0x100000001b3 for each byte. */
#include "base/hash.h"

uint64_t hash_bytes(uint64_t h, const void *p, size_t n)
{
	const unsigned char *b = p;
	size_t i;

	for (i = 0; i < n; i++) {
		h ^= b[i];
		h *= UINT64_C(0x100000001b3);
	}
	return h;
}

/* Below this a thread costs more than it saves. */
#define HASH_THREAD_MIN (1u << 20)

static void *hash_run(void *arg)
{
	struct hash_job *job = arg;

	job->h = hash_bytes(RT_HASH_INIT, job->p, job->n);
	return NULL;
}

void hash_start(struct hash_job *job, const void *p, size_t n)
{
	job->p = p;
	job->n = n;
	job->threaded = n >= HASH_THREAD_MIN && pthread_create(&job->thread, NULL, hash_run, job) == 0;
	if (!job->threaded)
		hash_run(job);
}

uint64_t hash_finish(struct hash_job *job)
{
	if (job->threaded) {
		pthread_join(job->thread, NULL);
		job->threaded = false;
	}
	return job->h;
}
