/* Loading the plugins the command line and the environment name, and
 * listing the shapes they add beside the built-in ones. */
#include <stdlib.h>
#include <string.h>

#include "cli/plugin_opts.h"
#include "shapes/registry.h"
#include "whitted/shape.h"

int cli_plugins_load(const char *const *files, int n, diag_note_fn *note, void *note_ctx,
		     struct diag *d)
{
	static bool loaded;
	int i, rc = 0;

	if (loaded)
		return 0;
	loaded = true;
	/* The files named first, so that they override the path's. */
	for (i = 0; rc == 0 && i < n; i++)
		rc = plugin_load(files[i], d);
	if (rc == 0)
		rc = plugin_load_dirs(getenv(CLI_PLUGIN_PATH_ENV), note, note_ctx, d);
	return rc == -RT_E_INVALID ? -RT_E_SYNTAX : rc;
}

const char *cli_plugins_used(const struct scene *s)
{
	static char record[RT_PLUGIN_RECORDS_MAX];
	const char *paths[RT_PLUGINS_MAX];
	size_t i, j, n = 0;

	record[0] = '\0';
	if (plugin_count() == 0)
		return record;
	for (i = 0; i < scene_shape_count(s); i++) {
		const struct shape_ops *ops = scene_shape(s, i)->ops;
		const char *origin;
		bool seen = false;

		/* Big scenes are runs of one kind: look each run up once. */
		if (i > 0 && ops == scene_shape(s, i - 1)->ops)
			continue;
		origin = shape_registry_origin(ops);

		for (j = 0; j < n && !seen; j++)
			seen = strcmp(paths[j], origin ? origin : "") == 0;
		if (origin && !seen && n < RT_PLUGINS_MAX)
			paths[n++] = origin;
	}
	if (n > 0)
		plugin_records(paths, n, record, sizeof(record));
	return record;
}

static void cli_print_dialects(FILE *out, unsigned mask)
{
	static const enum scene_dialect all[] = {
		RT_DIALECT_CLASSIC, RT_DIALECT_SPOT, RT_DIALECT_PYRAMID, RT_DIALECT_NEARFAR,
	};
	size_t i;
	bool first = true;

	for (i = 0; i < sizeof(all) / sizeof(all[0]); i++) {
		if (mask != 0 && !(mask & RT_DIALECT_BIT(all[i])))
			continue;
		fprintf(out, "%s%s", first ? "" : ",", scene_dialect_name(all[i]));
		first = false;
	}
}

void cli_print_shapes(FILE *out)
{
	const struct shape_ops *const *all = shape_ops_all();
	size_t i, k;

	for (i = 0; all[i]; i++) {
		const char *origin = shape_registry_origin(all[i]);
		const struct plugin_info *pl = NULL;

		for (k = 0; origin && (pl = plugin_at(k)) != NULL; k++)
			if (strcmp(pl->path, origin) == 0)
				break;
		fprintf(out, "%-12s ", all[i]->keyword);
		if (pl)
			fprintf(out, "plugin %s %s (%s)", pl->name, pl->version, pl->path);
		else
			fputs("built-in", out);
		fputs("  dialects: ", out);
		cli_print_dialects(out, all[i]->dialects);
		fputc('\n', out);
	}
}
