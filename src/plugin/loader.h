/* Loading plugins (whitted/plugin.h): a .so named on the command line or
 * found in the directories of WHITTED_PLUGIN_PATH, checked, initialised
 * with the host's services, its shapes registered beside the built-in ones
 * (src/shapes/registry.h).  What is loaded is remembered for the tiles'
 * record (name, version and a hash of the file) and unloaded at exit. */
#ifndef RT_PLUGIN_LOADER_H
#define RT_PLUGIN_LOADER_H

#include <stddef.h>
#include <stdint.h>

#include "whitted/diag.h"
#include "whitted/plugin.h"

/* At most this many plugins at once. */
#define RT_PLUGINS_MAX 32
/* Room for plugin_records with every plugin loaded. */
#define RT_PLUGIN_RECORDS_MAX (RT_PLUGINS_MAX * 64)

struct plugin_info {
	const char *path;	/* as given (or found in WHITTED_PLUGIN_PATH) */
	const char *name, *version;
	uint64_t hash;		/* hash_bytes of the file's bytes */
};

/* Loads one plugin.  The same file (the same device and inode) loaded a
 * second time is left as it is.  Fails, with a message that names the
 * file, and nothing of the plugin left registered: RT_E_IO when the file is
 * missing or unreadable; RT_E_SYNTAX when it is not a plugin (not a
 * shared object of this processor whose segments lie within the file
 * (plugin_elf_check, before dlopen), or without whitted_plugin_abi or
 * whitted_plugin_init); RT_E_RANGE when it was built for an ABI version
 * this whitted does not support; RT_E_INVALID when its name or a keyword
 * clashes with a built-in or an earlier plugin's, or its init fails. */
int plugin_load(const char *path, struct diag *d);
/* Loads every *.so of each directory of a colon-separated list (empty
 * entries and directories that do not exist are skipped), in name order
 * within each.  NULL or "" loads nothing.  The plugins loaded before this
 * call win: a .so of the directories whose name or a keyword is one of
 * theirs is skipped (closed, nothing of it registered), and `note` (when
 * not NULL) told why; any other failure is plugin_load's. */
int plugin_load_dirs(const char *dirs, diag_note_fn *note, void *note_ctx, struct diag *d);

size_t plugin_count(void);
/* The i-th loaded plugin, in the order loaded; NULL past the last. */
const struct plugin_info *plugin_at(size_t i);
/* The loaded plugins as one word for a tile's record, sorted by name:
 * "name@version#hash16,name@version#hash16"; "" when none is loaded.
 * Only those whose path is among paths[0..n) when paths is not NULL (the
 * plugins whose shapes a scene has: see shape_registry_origin). */
void plugin_records(const char *const *paths, size_t n, char *buf, size_t size);
/* The checks of a plugin file's bytes before dlopen (elf_check.c): an
 * ELF shared object of this processor's class, byte order and machine
 * ("built for aarch64, this is x86-64"), its program headers, loaded
 * segments and section headers within the file (a truncated copy).
 * RT_E_SYNTAX naming the file when it fails. */
int plugin_elf_check(const char *path, const unsigned char *bytes, size_t len, struct diag *d);
/* The services every plugin's init is given (for the tests: its
 * register_plugin refuses, -RT_E_INVALID, outside a plugin's init). */
const struct whitted_plugin_host *plugin_host(void);
/* Unloads every plugin and takes its shapes out of the registry (also run
 * at exit); no shape of a plugin may be alive. */
void plugin_unload_all(void);

#endif
