/* The plugin loader: checks a .so before running any of its code (a
 * readable regular file, an ELF shared object of this processor whole in
 * the file (elf_check.c), the ABI version it was built for), then
 * calls its whitted_plugin_init with the host's services and registers
 * what it registers through the registry's one path.  Loading is
 * serialised by one mutex; the plugin being loaded is `loading`, which
 * host_register_plugin fills in. */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <errno.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "base/alloc.h"
#include "base/file.h"
#include "base/hash.h"
#include "base/platform.h"
#include "base/text.h"
#include "plugin/loader.h"
#include "shapes/registry.h"
#include "shapes/solve.h"
#include "syntax/parser_impl.h"
#include "whitted/mesh.h"
#include "whitted/parser.h"
#include "whitted/plugin.h"
#include "whitted/pov.h"

/* A plugin file larger than this is not read (for its hash). */
#define PLUGIN_FILE_MAX (256u << 20)

struct plugin {
	struct plugin_info info;
	void *handle;
	dev_t dev;
	ino_t ino;
	char *path, *name, *version;
};

static pthread_mutex_t load_lock = PTHREAD_MUTEX_INITIALIZER;
static struct plugin plugins[RT_PLUGINS_MAX];
static size_t n_plugins;
static bool unload_at_exit;

/* The load in progress: its path, what register_plugin recorded, and the
 * message of a refused registration.  `active` only while the plugin's
 * init runs: register_plugin called at any other time or from another
 * thread (from a shape method, a thread of the plugin's, a destructor)
 * is refused. */
static struct {
	const char *path;
	bool active;
	pthread_t thread;	/* the one running init, while active */
	bool registered;
	/* plugins[0..yield_to) win over this one: a clash with them skips
	 * it (`skipped`, the reason in d) rather than failing. */
	size_t yield_to;
	bool skipped;
	int rc;
	char *name, *version;
	struct diag d;
} loading;

static char *plugin_strdup(const char *s)
{
	char *c = malloc(strlen(s) + 1);

	return c ? strcpy(c, s) : NULL;
}

static bool plugin_is_name(const char *s, size_t max)
{
	size_t n = 0;

	for (; s[n]; n++)
		if (!((s[n] >= 'a' && s[n] <= 'z') || (s[n] >= 'A' && s[n] <= 'Z') ||
		      (s[n] >= '0' && s[n] <= '9') || s[n] == '-' || s[n] == '_' || s[n] == '.'))
			return false;
	return n > 0 && n <= max;
}

static int host_register_plugin(const struct whitted_plugin_host *host,
				const struct whitted_plugin *plugin)
{
	size_t i;
	int rc;

	(void)host;
	if (!loading.active || !pthread_equal(loading.thread, pthread_self()))
		return -RT_E_INVALID;
	if (loading.registered)
		rc = diag_fail(&loading.d, RT_E_INVALID, "register_plugin called twice");
	else if (!plugin || !plugin->name || !plugin_is_name(plugin->name, 24))
		rc = diag_fail(&loading.d, RT_E_INVALID,
			       "the plugin's name is not 1 to 24 letters, digits, '-', '_' or '.'");
	else if (!plugin->version || !plugin_is_name(plugin->version, 16))
		rc = diag_fail(&loading.d, RT_E_INVALID,
			       "plugin '%s': its version is not 1 to 16 letters, digits, '-', '_' or '.'",
			       plugin->name);
	else if (!plugin->shapes || !plugin->shapes[0])
		rc = diag_fail(&loading.d, RT_E_INVALID, "plugin '%s' registers no shapes",
			       plugin->name);
	else
		rc = 0;
	for (i = 0; rc == 0 && i < n_plugins; i++)
		if (strcmp(plugins[i].name, plugin->name) == 0) {
			rc = diag_fail(&loading.d, RT_E_INVALID,
				       "a plugin named '%s' is already loaded from %s",
				       plugin->name, plugins[i].path);
			loading.skipped = i < loading.yield_to;
		}
	for (i = 0; rc == 0 && plugin->shapes[i]; i++) {
		const char *kw = plugin->shapes[i]->keyword;
		size_t k;

		for (k = 0; kw && k < loading.yield_to && rc == 0; k++)
			if (shape_registry_has(kw, plugins[k].path)) {
				rc = diag_fail(&loading.d, RT_E_INVALID,
					       "its shape keyword '%s' is already defined by %s",
					       kw, plugins[k].path);
				loading.skipped = true;
			}
	}
	if (rc == 0)
		rc = shape_registry_add(plugin->shapes, loading.path, &loading.d);
	if (rc == 0) {
		loading.name = plugin_strdup(plugin->name);
		loading.version = plugin_strdup(plugin->version);
		if (!loading.name || !loading.version)
			rc = diag_fail(&loading.d, RT_E_NOMEM, "out of memory");
		loading.registered = true;
	}
	if (rc < 0 && loading.rc == 0)
		loading.rc = rc;
	return rc;
}

static int host_parser_integer(struct parser *p, const char *what, long lo, long hi, long *out)
{
	return parser_int(p, what, lo, hi, out);
}

static const struct whitted_plugin_host host = {
	.abi = WHITTED_PLUGIN_ABI,
	.size = sizeof(struct whitted_plugin_host),
	.register_plugin = host_register_plugin,
	.number = parser_number,
	.integer = host_parser_integer,
	.vec3 = parser_vec3,
	.color = parser_color,
	.material = parser_material,
	.fail = parser_fail,
	.alloc = rt_malloc,
	.free = rt_free,
	.pov_number = pov_write_number,
	.pov_vector = pov_write_vector,
	.pov_texture = pov_write_texture,
	.mesh_triangle = mesh_add_triangle,
	.mesh_box = mesh_box,
	.solve_quadratic = solve_quadratic,
	.ray_triangle = solve_ray_triangle,
};

static void plugin_free(struct plugin *pl)
{
	free(pl->path);
	free(pl->name);
	free(pl->version);
}

/* The file's hash, and its identity; RT_E_IO when it cannot be read. */
static int plugin_read(const char *path, struct plugin *pl, struct diag *d)
{
	struct stat st;
	char *bytes;
	size_t len;
	int rc;

	if (stat(path, &st) != 0)
		return diag_fail(d, RT_E_IO, "plugin %s: %s", path, strerror(errno));
	if ((rc = file_read_all(path, "plugin", PLUGIN_FILE_MAX, &bytes, &len, d)) < 0)
		return rc;
	if ((rc = plugin_elf_check(path, (const unsigned char *)bytes, len, d)) < 0) {
		rt_free(bytes);
		return rc;
	}
	pl->info.hash = hash_bytes(RT_HASH_INIT, bytes, len);
	pl->dev = st.st_dev;
	pl->ino = st.st_ino;
	rt_free(bytes);
	return 0;
}

/* Opens it and runs its init: `loading` says what it registered. */
static int plugin_open(const char *path, struct plugin *pl, struct diag *d)
{
	int (*init)(const struct whitted_plugin_host *);
	const unsigned *abi;
	char why[256];
	char *where;
	int rc;

	/* A name without '/' would be looked for on the library path. */
	where = malloc(strlen(path) + 3);
	if (!where)
		return diag_fail(d, RT_E_NOMEM, "out of memory");
	sprintf(where, "%s%s", strchr(path, '/') ? "" : "./", path);
	pl->handle = rt_dl_open(where, why, sizeof(why));
	free(where);
	if (!pl->handle)
		return diag_fail(d, RT_E_SYNTAX, "plugin %s: not a plugin: %s", path, why);
	abi = rt_dl_sym(pl->handle, "whitted_plugin_abi");
	/* POSIX's way of reading a function pointer from dlsym. */
	*(void **)(&init) = rt_dl_sym(pl->handle, "whitted_plugin_init");
	if (!abi || !init)
		rc = diag_fail(d, RT_E_SYNTAX,
			       "plugin %s: not a whitted plugin (it defines no %s; see whitted/plugin.h)",
			       path, !abi ? "whitted_plugin_abi" : "whitted_plugin_init");
	else if (*abi != WHITTED_PLUGIN_ABI)
		rc = diag_fail(d, RT_E_RANGE,
			       "plugin %s: built for plugin ABI version %u, but this whitted supports version %u only (rebuild it against this whitted's headers)",
			       path, *abi, WHITTED_PLUGIN_ABI);
	else
		rc = 0;
	if (rc < 0)
		return rc;
	loading.path = path;
	loading.thread = pthread_self();
	loading.active = true;
	rc = init(&host);
	loading.active = false;
	if (loading.skipped) {
		diag_fail(d, RT_E_INVALID, "plugin %s skipped: %s", path, loading.d.msg);
		return 1;
	}
	if (loading.rc < 0)
		return diag_fail(d, loading.rc == -RT_E_NOMEM ? RT_E_NOMEM : RT_E_INVALID,
				 "plugin %s: %s", path, loading.d.msg);
	if (rc != 0)
		return diag_fail(d, RT_E_INVALID, "plugin %s: init failed (whitted_plugin_init returned %d)",
				 path, rc);
	if (!loading.registered)
		return diag_fail(d, RT_E_INVALID, "plugin %s: init registered no shapes", path);
	return 0;
}

/* 0 loaded (or already loaded), 1 skipped (yielding to plugins[0..yield_to):
 * the reason in d), or a negative enum rt_err. */
static int plugin_load_locked(const char *path, size_t yield_to, struct diag *d)
{
	struct plugin pl;
	size_t i;
	int rc;

	memset(&pl, 0, sizeof(pl));
	if ((rc = plugin_read(path, &pl, d)) < 0)
		return rc;
	for (i = 0; i < n_plugins; i++)
		if (plugins[i].dev == pl.dev && plugins[i].ino == pl.ino)
			return 0;
	if (n_plugins == RT_PLUGINS_MAX)
		return diag_fail(d, RT_E_RANGE, "plugin %s: too many plugins (at most %d)", path,
				 RT_PLUGINS_MAX);
	if (!(pl.path = plugin_strdup(path)))
		return diag_fail(d, RT_E_NOMEM, "out of memory");
	/* Reset before anything can fail: what the last load recorded is
	 * owned by its plugin now. */
	memset(&loading, 0, sizeof(loading));
	diag_clear(&loading.d);
	loading.yield_to = yield_to;
	rc = plugin_open(path, &pl, d);
	pl.name = loading.name;
	pl.version = loading.version;
	loading.name = loading.version = NULL;
	loading.path = NULL;
	if (rc != 0) {
		if (loading.registered)
			shape_registry_remove(path);
		if (pl.handle)
			rt_dl_close(pl.handle);
		plugin_free(&pl);
		return rc;
	}
	pl.info.path = pl.path;
	pl.info.name = pl.name;
	pl.info.version = pl.version;
	plugins[n_plugins++] = pl;
	if (!unload_at_exit)
		unload_at_exit = atexit(plugin_unload_all) == 0;
	return 0;
}

int plugin_load(const char *path, struct diag *d)
{
	int rc;

	pthread_mutex_lock(&load_lock);
	rc = plugin_load_locked(path, 0, d);
	pthread_mutex_unlock(&load_lock);
	return rc;
}

static int plugin_load_yielding(const char *path, size_t yield_to, diag_note_fn *note,
				void *note_ctx, struct diag *d)
{
	int rc;

	pthread_mutex_lock(&load_lock);
	rc = plugin_load_locked(path, yield_to, d);
	pthread_mutex_unlock(&load_lock);
	if (rc > 0) {
		if (note)
			note(note_ctx, d);
		diag_clear(d);
		rc = 0;
	}
	return rc;
}

static bool plugin_is_so(const char *name)
{
	size_t n = strlen(name);

	return n > 3 && name[0] != '.' && strcmp(name + n - 3, ".so") == 0;
}

static int plugin_name_cmp(const void *a, const void *b)
{
	return strcmp(*(char *const *)a, *(char *const *)b);
}

/* The .so files of dir in name order (malloc'ed names, the array too):
 * their count, or -1 with errno. */
static int plugin_list_dir(const char *path, char ***out)
{
	DIR *dir = opendir(path);
	struct dirent *e;
	char **names = NULL, **v;
	int n = 0, cap = 0, err = 0;

	if (!dir)
		return -1;
	while ((e = readdir(dir)) != NULL) {
		if (!plugin_is_so(e->d_name))
			continue;
		if (n == cap) {
			cap = cap ? 2 * cap : 16;
			if (!(v = realloc(names, (size_t)cap * sizeof(*v)))) {
				err = ENOMEM;
				break;
			}
			names = v;
		}
		if (!(names[n] = malloc(strlen(e->d_name) + 1))) {
			err = ENOMEM;
			break;
		}
		strcpy(names[n++], e->d_name);
	}
	closedir(dir);
	if (err) {
		while (n > 0)
			free(names[--n]);
		free(names);
		errno = err;
		return -1;
	}
	if (n > 1)
		qsort(names, (size_t)n, sizeof(*names), plugin_name_cmp);
	*out = names;
	return n;
}

static int plugin_load_dir(const char *dir, size_t len, size_t yield_to, diag_note_fn *note,
			   void *note_ctx, struct diag *d)
{
	char **names = NULL;
	char *path;
	int n, i, rc = 0;

	if (!(path = malloc(len + 1)))
		return diag_fail(d, RT_E_NOMEM, "out of memory");
	memcpy(path, dir, len);
	path[len] = '\0';
	n = plugin_list_dir(path, &names);
	if (n < 0) {
		if (errno != ENOENT)
			rc = diag_fail(d, RT_E_IO, "WHITTED_PLUGIN_PATH: %s: %s", path, strerror(errno));
		free(path);
		return rc;
	}
	for (i = 0; i < n; i++) {
		char *file = malloc(len + strlen(names[i]) + 2);

		if (rc == 0 && !file)
			rc = diag_fail(d, RT_E_NOMEM, "out of memory");
		if (rc == 0) {
			sprintf(file, "%s/%s", path, names[i]);
			rc = plugin_load_yielding(file, yield_to, note, note_ctx, d);
		}
		free(file);
		free(names[i]);
	}
	free(names);
	free(path);
	return rc;
}

int plugin_load_dirs(const char *dirs, diag_note_fn *note, void *note_ctx, struct diag *d)
{
	const char *p = dirs;
	size_t yield_to;
	int rc;

	pthread_mutex_lock(&load_lock);
	yield_to = n_plugins;
	pthread_mutex_unlock(&load_lock);

	while (p && *p) {
		const char *end = strchr(p, ':');
		size_t len = end ? (size_t)(end - p) : strlen(p);

		if (len > 0 && (rc = plugin_load_dir(p, len, yield_to, note, note_ctx, d)) < 0)
			return rc;
		p += len + (end ? 1 : 0);
	}
	return 0;
}

size_t plugin_count(void)
{
	return n_plugins;
}

const struct plugin_info *plugin_at(size_t i)
{
	return i < n_plugins ? &plugins[i].info : NULL;
}

static int plugin_by_name(const void *a, const void *b)
{
	const struct plugin_info *const *x = a, *const *y = b;

	return strcmp((*x)->name, (*y)->name);
}

void plugin_records(const char *const *paths, size_t n_paths, char *buf, size_t size)
{
	const struct plugin_info *sorted[RT_PLUGINS_MAX];
	size_t i, k = 0, n = 0;

	if (size == 0)
		return;
	buf[0] = '\0';
	for (i = 0; i < n_plugins; i++)
		if (!paths || text_among(plugins[i].path, paths, n_paths))
			sorted[k++] = &plugins[i].info;
	qsort(sorted, k, sizeof(sorted[0]), plugin_by_name);
	for (i = 0; i < k && n < size; i++) {
		int k = snprintf(buf + n, size - n, "%s%s@%s#%016llx", i ? "," : "", sorted[i]->name,
				 sorted[i]->version, (unsigned long long)sorted[i]->hash);
		n += k > 0 ? (size_t)k : 0;
	}
}

const struct whitted_plugin_host *plugin_host(void)
{
	return &host;
}

void plugin_unload_all(void)
{
	pthread_mutex_lock(&load_lock);
	while (n_plugins > 0) {
		struct plugin *pl = &plugins[--n_plugins];

		shape_registry_remove(pl->path);
		rt_dl_close(pl->handle);
		plugin_free(pl);
	}
	pthread_mutex_unlock(&load_lock);
}
