/* A 64-bit FNV-1a hash, to recognise the same scene text and settings
 * across processes and machines.  It detects accidents (a tile of another
 * scene or another size), not tampering: it is not a cryptographic hash. */
#ifndef RT_HASH_H
#define RT_HASH_H

#include <pthread.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

/* The FNV-1a 64-bit offset basis: the hash of no bytes. */
#define RT_HASH_INIT UINT64_C(0xcbf29ce484222325)

/* Continues hash h over n bytes at p; hash_bytes(RT_HASH_INIT, ...) starts
 * a new one, and hashing a + b in two calls equals one call over both. */
uint64_t hash_bytes(uint64_t h, const void *p, size_t n);

/* hash_bytes(RT_HASH_INIT, p, n) worked out by another thread, for a big
 * input that the caller reads meanwhile (FNV-1a takes a multiplication a
 * byte, a fifth of the time a scene file takes to parse).  Small inputs,
 * or when no thread can be started, are hashed by hash_start itself.
 * Every hash_start is followed by one hash_finish, which returns the hash;
 * the bytes must stay unchanged until then. */
struct hash_job {
	const void *p;
	size_t n;
	uint64_t h;
	bool threaded;
	pthread_t thread;
};

void hash_start(struct hash_job *job, const void *p, size_t n);
uint64_t hash_finish(struct hash_job *job);

#endif
