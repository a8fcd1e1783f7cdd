/* The scene and options hash: FNV-1a 64 against published test vectors,
 * hashing in pieces, the threaded hash_start/hash_finish against the plain
 * one for inputs below and above the size that takes a thread, and which
 * scenes get a hash. */
#include <string.h>

#include "base/hash.h"
#include "scene/scene_impl.h"
#include "whitted/scenefile.h"
#include "whitted/scene.h"
#include "support.h"

static void test_hash_fnv1a_vectors(void **state)
{
	(void)state;
	/* From the FNV reference test suite (isthe.com/chongo/tech/comp/fnv). */
	assert_true(hash_bytes(RT_HASH_INIT, "", 0) == UINT64_C(0xcbf29ce484222325));
	assert_true(hash_bytes(RT_HASH_INIT, "a", 1) == UINT64_C(0xaf63dc4c8601ec8c));
	assert_true(hash_bytes(RT_HASH_INIT, "foobar", 6) == UINT64_C(0x85944171f73967e8));
}

static void test_hash_in_pieces(void **state)
{
	const char text[] = "4\n512\n\n1\nsphere 0 0 0 1\n";
	size_t cut;

	(void)state;
	for (cut = 0; cut <= sizeof(text) - 1; cut++)
		assert_true(hash_bytes(hash_bytes(RT_HASH_INIT, text, cut), text + cut,
				       sizeof(text) - 1 - cut) ==
			    hash_bytes(RT_HASH_INIT, text, sizeof(text) - 1));
}

static void test_hash_threaded_equals_plain(void **state)
{
	static const size_t sizes[] = { 0, 1, 1000, (1u << 20) - 1, 1u << 20, 3u << 20 };
	size_t k, i, max = 3u << 20;
	unsigned char *buf = test_malloc(max);

	(void)state;
	for (i = 0; i < max; i++)
		buf[i] = (unsigned char)(i * 2654435761u >> 13);
	for (k = 0; k < sizeof(sizes) / sizeof(sizes[0]); k++) {
		struct hash_job job;
		hash_start(&job, buf, sizes[k]);
		assert_true(hash_finish(&job) == hash_bytes(RT_HASH_INIT, buf, sizes[k]));
	}
	test_free(buf);
}

/* Files are hashed when asked (for tiles), and the built-in test scene
 * always, as its tiles need it too: the FNV-1a of its text, worked out
 * independently (Python) as 0x32d7e95d47447506. */
static void test_hash_of_scenes(void **state)
{
	const char text[] = "4 8\n0\n0\n";
	struct scene_read_options opt = { 1, true, RT_DIALECT_AUTO, false, 0 };
	struct scene *s;
	struct diag d;

	(void)state;
	assert_int_equal(scene_test_scene(&s, &d), 0);
	assert_true(s->source_hash == UINT64_C(0x32d7e95d47447506));
	scene_destroy(s);
	assert_int_equal(scene_parse("t.txt", text, sizeof(text) - 1, &opt, NULL, NULL, &s, &d), 0);
	assert_true(s->source_hash == hash_bytes(RT_HASH_INIT, text, sizeof(text) - 1));
	scene_destroy(s);
	opt.hash = false;
	assert_int_equal(scene_parse("t.txt", text, sizeof(text) - 1, &opt, NULL, NULL, &s, &d), 0);
	assert_true(s->source_hash == 0);
	scene_destroy(s);
}

SUPPORT_MAIN(SUPPORT_TESTS(test_hash_fnv1a_vectors, test_hash_in_pieces,
			   test_hash_threaded_equals_plain, test_hash_of_scenes))
