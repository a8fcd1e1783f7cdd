/* The loader: the status of each failure, the same file loaded once, the
 * record of what is loaded (sorted by name, filtered by path, the hash of
 * the file's bytes), unloading taking the shapes out of the registry, and
 * the ELF checks before dlopen. */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "base/hash.h"
#include "plugin/loader.h"
#include "support.h"

#define QUAD RT_TEST_PLUGIN_DIR "/quad.so"
#define TORUS RT_TEST_PLUGIN_DIR "/torus.so"

static uint64_t file_hash(const char *path)
{
	FILE *f = fopen(path, "rb");
	uint64_t h = RT_HASH_INIT;
	char buf[4096];
	size_t n;

	assert_non_null(f);
	while ((n = fread(buf, 1, sizeof(buf), f)) > 0)
		h = hash_bytes(h, buf, n);
	fclose(f);
	return h;
}

static void test_loader_failures(void **state)
{
	char path[] = "/tmp/whitted-test-loader-XXXXXX";
	struct diag d;
	FILE *f;
	int fd, i;

	(void)state;
	assert_int_equal(plugin_load("/nonexistent/x.so", &d), -RT_E_IO);
	assert_string_equal(d.msg, "plugin /nonexistent/x.so: No such file or directory");
	fd = mkstemp(path);
	assert_true(fd >= 0);
	f = fdopen(fd, "w");
	for (i = 0; i < 100; i++)
		fputs("not a shared object\n", f);
	fclose(f);
	assert_int_equal(plugin_load(path, &d), -RT_E_SYNTAX);
	assert_non_null(strstr(d.msg, ": not a plugin: "));
	remove(path);
	assert_int_equal(plugin_count(), 0);
}

static void write_text_file(char *path)
{
	int fd = mkstemp(path), i;
	FILE *f;

	assert_true(fd >= 0);
	f = fdopen(fd, "w");
	assert_non_null(f);
	for (i = 0; i < 100; i++)
		fputs("not a shared object\n", f);
	fclose(f);
}

/* A refused file after a good plugin: the good one stays whole (its name
 * and version are its own, freed once: ASan sees a double free). */
static void test_loader_failure_after_good(void **state)
{
	char path[] = "/tmp/whitted-test-loader-XXXXXX";
	struct diag d;

	(void)state;
	write_text_file(path);
	assert_int_equal(plugin_load(QUAD, &d), 0);
	assert_int_equal(plugin_load(path, &d), -RT_E_SYNTAX);
	assert_non_null(strstr(d.msg, ": not a plugin: "));
	assert_int_equal(plugin_load("/nonexistent/y.so", &d), -RT_E_IO);
	assert_int_equal(plugin_count(), 1);
	assert_string_equal(plugin_at(0)->name, "quad");
	assert_string_equal(plugin_at(0)->version, "1.0");
	assert_int_equal(plugin_load(TORUS, &d), 0);
	assert_int_equal(plugin_load(path, &d), -RT_E_SYNTAX);
	assert_int_equal(plugin_count(), 2);
	assert_string_equal(plugin_at(1)->name, "torus");
	remove(path);
	plugin_unload_all();
	assert_int_equal(plugin_count(), 0);
}

/* register_plugin outside a plugin's init (a plugin that kept the host
 * pointer and calls it later) is refused and registers nothing. */
static const struct shape_ops *const late_shapes[] = { NULL, NULL };

static void test_loader_register_outside_init(void **state)
{
	const struct whitted_plugin late = { "late", "1.0", late_shapes };
	const struct whitted_plugin_host *host = plugin_host();
	struct diag d;

	(void)state;
	assert_int_equal(host->register_plugin(host, &late), -RT_E_INVALID);
	assert_int_equal(plugin_load(QUAD, &d), 0);
	assert_int_equal(host->register_plugin(host, &late), -RT_E_INVALID);
	assert_int_equal(plugin_count(), 1);
	plugin_unload_all();
	assert_int_equal(host->register_plugin(host, &late), -RT_E_INVALID);
	assert_int_equal(plugin_count(), 0);
}

static void copy_file(const char *from, const char *to)
{
	FILE *in = fopen(from, "rb"), *out = fopen(to, "wb");
	char buf[4096];
	size_t n;

	assert_non_null(in);
	assert_non_null(out);
	while ((n = fread(buf, 1, sizeof(buf), in)) > 0)
		assert_int_equal(fwrite(buf, 1, n, out), n);
	fclose(in);
	assert_int_equal(fclose(out), 0);
}

static int notes;
static char last_note[RT_DIAG_MSG_MAX];

static void count_note(void *ctx, const struct diag *note)
{
	(void)ctx;
	notes++;
	snprintf(last_note, sizeof(last_note), "%s", note->msg);
}

/* A plugin loaded before the directories wins over a .so of theirs with
 * its name (a copy of the file): that one is skipped with a note. */
static void test_loader_dirs_yield(void **state)
{
	static const char skipped[] = "plugin %s skipped: a plugin named 'quad' is already loaded from %s";
	char dir[] = "/tmp/whitted-test-dirs-XXXXXX", copy[64], *want;
	struct diag d;
	size_t len;

	(void)state;
	assert_non_null(mkdtemp(dir));
	snprintf(copy, sizeof(copy), "%s/quad-copy.so", dir);
	copy_file(QUAD, copy);
	notes = 0;
	assert_int_equal(plugin_load(QUAD, &d), 0);
	assert_int_equal(plugin_load_dirs(dir, count_note, NULL, &d), 0);
	assert_int_equal(notes, 1);
	/* Sized for the paths, which depend on where the clone is (a fixed
	 * buffer drew -Wformat-truncation in a deep checkout). */
	len = sizeof(skipped) + strlen(copy) + strlen(QUAD);
	want = malloc(len);
	assert_non_null(want);
	snprintf(want, len, skipped, copy, QUAD);
	assert_string_equal(last_note, want);
	free(want);
	assert_int_equal(plugin_count(), 1);
	assert_string_equal(plugin_at(0)->path, QUAD);
	/* Without an earlier one to yield to, the clash inside the
	 * directories is an error. */
	plugin_unload_all();
	assert_int_equal(plugin_load_dirs(dir, count_note, NULL, &d), 0);
	assert_int_equal(plugin_load(QUAD, &d), -RT_E_INVALID);
	assert_int_equal(notes, 1);
	plugin_unload_all();
	remove(copy);
	rmdir(dir);
}

static void test_loader_records(void **state)
{
	const char *only_torus[] = { TORUS };
	char rec[RT_PLUGIN_RECORDS_MAX], want[256];
	struct diag d;

	(void)state;
	assert_int_equal(plugin_load(TORUS, &d), 0);
	assert_int_equal(plugin_load(QUAD, &d), 0);
	assert_int_equal(plugin_load(TORUS, &d), 0);
	assert_int_equal(plugin_count(), 2);
	assert_string_equal(plugin_at(0)->name, "torus");
	assert_string_equal(plugin_at(1)->version, "1.0");
	assert_null(plugin_at(2));
	plugin_records(NULL, 0, rec, sizeof(rec));
	snprintf(want, sizeof(want), "quad@1.0#%016llx,torus@1.0#%016llx",
		 (unsigned long long)file_hash(QUAD), (unsigned long long)file_hash(TORUS));
	assert_string_equal(rec, want);
	plugin_records(only_torus, 1, rec, sizeof(rec));
	snprintf(want, sizeof(want), "torus@1.0#%016llx", (unsigned long long)file_hash(TORUS));
	assert_string_equal(rec, want);
	assert_non_null(shape_ops_find("quad", 4));
	plugin_unload_all();
	assert_int_equal(plugin_count(), 0);
	assert_null(shape_ops_find("quad", 4));
	assert_null(shape_ops_find("torus", 5));
	plugin_records(NULL, 0, rec, sizeof(rec));
	assert_string_equal(rec, "");
}

static void test_loader_dirs(void **state)
{
	struct diag d;

	(void)state;
	assert_int_equal(plugin_load_dirs(NULL, NULL, NULL, &d), 0);
	assert_int_equal(plugin_load_dirs("::/nonexistent-dir:", NULL, NULL, &d), 0);
	assert_int_equal(plugin_count(), 0);
	assert_int_equal(plugin_load_dirs("/nonexistent-dir:" RT_TEST_PLUGIN_DIR, NULL, NULL, &d), 0);
	assert_true(plugin_count() >= 3);
	assert_non_null(shape_ops_find("cylinder", 8));
	plugin_unload_all();
}

/* The whole of a file into a new buffer of its size. */
/* plugin_elf_check on a good plugin and on its damaged copies: cut short
 * at every length up to its end (an interrupted copy, which dlopen maps
 * and dies of), another processor's, another class's, not a shared
 * object. */
static void test_loader_elf_checks(void **state)
{
	size_t len, cut;
	unsigned char *good = support_read_file(TORUS, &len), *bad;
	struct diag d;
	int refused = 0;

	(void)state;
	assert_true(len > 64);
	assert_int_equal(plugin_elf_check("t.so", good, len, &d), 0);
	for (cut = 0; cut < len; cut += cut < 4096 ? 1 : 997) {
		if (plugin_elf_check("t.so", good, cut, &d) < 0)
			refused++;
		else
			fail_msg("a copy cut at %zu of %zu bytes passed", cut, len);
	}
	assert_true(refused > 4000);
	assert_int_equal(plugin_elf_check("t.so", good, 600, &d), -RT_E_SYNTAX);
	assert_non_null(strstr(d.msg, "plugin t.so: not a plugin: the file is cut short"));
	bad = malloc(len);
	assert_non_null(bad);
#if defined(__x86_64__)
	memcpy(bad, good, len);
	bad[18] = 183;	/* e_machine EM_AARCH64, little-endian */
	bad[19] = 0;
	assert_int_equal(plugin_elf_check("t.so", bad, len, &d), -RT_E_SYNTAX);
	assert_string_equal(d.msg, "plugin t.so: built for aarch64, this is x86-64 (rebuild it on this machine)");
#endif
	memcpy(bad, good, len);
	bad[4] = bad[4] == 2 ? 1 : 2;	/* EI_CLASS */
	assert_int_equal(plugin_elf_check("t.so", bad, len, &d), -RT_E_SYNTAX);
	assert_non_null(strstr(d.msg, "-bit shared object, this whitted is "));
	memcpy(bad, good, len);
	bad[16] = 2;	/* e_type ET_EXEC */
	bad[17] = 0;
	assert_int_equal(plugin_elf_check("t.so", bad, len, &d), -RT_E_SYNTAX);
	assert_non_null(strstr(d.msg, "not a shared object"));
	memcpy(bad, good, len);
	bad[0] = 'X';
	assert_int_equal(plugin_elf_check("t.so", bad, len, &d), -RT_E_SYNTAX);
	assert_non_null(strstr(d.msg, "invalid ELF header"));
	free(bad);
	free(good);
}

SUPPORT_MAIN(SUPPORT_TESTS(test_loader_failures, test_loader_failure_after_good,
			   test_loader_register_outside_init, test_loader_records,
			   test_loader_dirs, test_loader_dirs_yield, test_loader_elf_checks))
