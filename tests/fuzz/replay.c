/* Replays fuzz inputs through the fuzz harness without libFuzzer, so that
 * the corpus runs under gcc's ASan and UBSan in `make check`.  Each argument
 * is a file or a directory of files; each file runs in its own child
 * process, so that one crash is counted and named and the rest still run. */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "harness.h"
#include "plugin/loader.h"

/* The harness replayed: the scene parser's, or another (-DRT_FUZZ_TARGET=fuzz_image_one). */
#ifndef RT_FUZZ_TARGET
#define RT_FUZZ_TARGET fuzz_scene_one
#define RT_FUZZ_PLUGINS 1	/* the scene harness loads the plugins first */
#endif

static int passed, failed;
/* Seeds named plugin-*: they need the example plugins loaded. */
static int plugin_seeds;

static int replay_read(const char *path, unsigned char **out, size_t *out_len)
{
	FILE *f = fopen(path, "rb");
	unsigned char *buf = NULL;
	size_t len = 0, cap = 0, n;

	if (!f)
		return -1;
	do {
		if (len == cap) {
			unsigned char *p = realloc(buf, cap = cap ? 2 * cap : 4096);
			if (!p) {
				free(buf);
				fclose(f);
				return -1;
			}
			buf = p;
		}
		n = fread(buf + len, 1, cap - len, f);
		len += n;
	} while (n > 0);
	if (ferror(f)) {
		free(buf);
		fclose(f);
		return -1;
	}
	fclose(f);
	*out = buf;
	*out_len = len;
	return 0;
}

static void replay_file(const char *path)
{
	const char *base = strrchr(path, '/');
	int status;
	pid_t pid;

	if (strncmp(base ? base + 1 : path, "plugin-", 7) == 0)
		plugin_seeds++;

	fflush(NULL);
	pid = fork();
	if (pid < 0) {
		perror("fuzz-replay: fork");
		failed++;
		return;
	}
	if (pid == 0) {
		unsigned char *data;
		size_t len;
		if (replay_read(path, &data, &len) < 0) {
			perror(path);
			_exit(3);
		}
		RT_FUZZ_TARGET(data, len);
		free(data);
		_exit(0);
	}
	if (waitpid(pid, &status, 0) < 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
		fprintf(stderr, "fuzz-replay: FAIL %s\n", path);
		failed++;
	} else {
		passed++;
	}
}

static int replay_name_cmp(const void *a, const void *b)
{
	return strcmp(*(char *const *)a, *(char *const *)b);
}

static void replay_dir(const char *dir)
{
	char **names = NULL;
	size_t n = 0, cap = 0, i;
	struct dirent *e;
	DIR *dp = opendir(dir);

	if (!dp) {
		perror(dir);
		failed++;
		return;
	}
	while ((e = readdir(dp)) != NULL) {
		char *path;
		if (e->d_name[0] == '.')
			continue;
		if (n == cap) {
			char **p = realloc(names, (cap = cap ? 2 * cap : 64) * sizeof(*names));
			if (!p)
				break;
			names = p;
		}
		path = malloc(strlen(dir) + strlen(e->d_name) + 2);
		if (!path)
			break;
		sprintf(path, "%s/%s", dir, e->d_name);
		names[n++] = path;
	}
	closedir(dp);
	qsort(names, n, sizeof(*names), replay_name_cmp);
	for (i = 0; i < n; i++) {
		replay_file(names[i]);
		free(names[i]);
	}
	free(names);
}

int main(int argc, char **argv)
{
	int i;

	if (argc < 2) {
		fprintf(stderr, "usage: fuzz_replay FILE|DIR...\n");
		return 2;
	}
#ifdef RT_FUZZ_PLUGINS
	if (fuzz_init() < 0)
		return 1;
	printf("fuzz-replay: %zu plugins loaded\n", plugin_count());
#endif
	for (i = 1; i < argc; i++) {
		struct stat st;
		if (stat(argv[i], &st) == 0 && S_ISDIR(st.st_mode))
			replay_dir(argv[i]);
		else
			replay_file(argv[i]);
	}
	/* Without the plugins, their seeds only reach "unknown object". */
	if (plugin_seeds > 0 && plugin_count() == 0) {
		printf("fuzz-replay: %d plugin-* seeds but no plugin loaded (set WHITTED_PLUGIN_PATH, e.g. to build/plugins)\n",
		       plugin_seeds);
		failed++;
	}
	printf("fuzz-replay: %d passed, %d failed, 0 skipped\n", passed, failed);
	return failed == 0 && passed > 0 ? 0 : 1;
}
