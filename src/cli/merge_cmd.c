/* whitted merge: joins the region renders of one image into it. */
#define _POSIX_C_SOURCE 200809L
#include <getopt.h>
#include <stdio.h>
#include <string.h>

#include "base/text.h"
#include "cli/cli.h"
#include "cli/plugin_opts.h"
#include "cli/scene_opts.h"
#include "whitted/tile.h"
#include "cli/tool.h"
#include "whitted/image.h"
#include "whitted/merge.h"

enum { OPT_FORMAT = 1000, OPT_PLUGIN };

static void merge_usage(FILE *f)
{
	fprintf(f,
		"Usage: whitted merge -o FULL.png TILE.png...\n"
		"Joins the tiles of one render (whitted --region) into the full image.  The\n"
		"tiles must come from the same scene file and pixel-affecting options (size,\n"
		"recursion, camera, floor, clamping) and cover the image exactly once; any\n"
		"order.  The result is the image a single whitted run writes, byte for byte.\n"
		"\n"
		"  -o, --output FILE      the full image; .png, .bmp or .ppm (required)\n"
		"      --format png|bmp|ppm  the format, when FILE's extension does not say it\n"
		"      --plugin FILE.so   check that the tiles that used a plugin of this\n"
		"                         name were made with this very file (its version and\n"
		"                         hash; repeatable; $WHITTED_PLUGIN_PATH's plugins\n"
		"                         are loaded but not checked)\n"
		"  -h, --help             show this help\n"
		"\n"
		"Exit status: 0 success, 1 a missing, overlapping, foreign or unreadable tile\n"
		"or an I/O error (nothing is written), 2 bad command line.\n");
}

/* Each plugin the first tile records (the others must agree with it) that
 * has the name of a plugin named with --plugin (files[0..n); not those of
 * WHITTED_PLUGIN_PATH, which would change what merge accepts) must be that
 * very plugin: its version and the hash of its file. */
static int merge_check_plugins(const char *first, const char *const *files, int n,
			       struct diag *d)
{
	struct tile_info info;
	char loaded[RT_PLUGIN_RECORDS_MAX], recorded[RT_TILE_OPTIONS_MAX];
	const char *at;
	char *rec;
	size_t i;
	int rc;

	if (n == 0)
		return 0;
	if ((rc = tile_read(first, &info, NULL, d)) < 0)
		return rc;
	at = strstr(info.options, " plugins=");
	snprintf(recorded, sizeof(recorded), "%s", at ? at + strlen(" plugins=") : "");
	recorded[strcspn(recorded, " ")] = '\0';
	for (rec = strtok(recorded, ","); rec; rec = strtok(NULL, ",")) {
		for (i = 0; i < plugin_count(); i++) {
			const struct plugin_info *pl = plugin_at(i);
			size_t len = strlen(pl->name);

			if (strncmp(rec, pl->name, len) != 0 || rec[len] != '@' ||
			    !text_among(pl->path, files, (size_t)n))
				continue;
			plugin_records(&pl->path, 1, loaded, sizeof(loaded));
			if (strcmp(rec, loaded) != 0)
				return diag_set(d, RT_E_INVALID, first, 0, 0,
						"made with another plugin '%s' than %s (%s, not %s)",
						pl->name, pl->path, rec, loaded);
		}
	}
	return 0;
}

/* argv[0] is "merge".
 * Long: the merge command's steps in order with one cleanup. */
int merge_main(int argc, char **argv)
{
	static const struct option longopts[] = {
		{ "output", required_argument, NULL, 'o' },
		{ "format", required_argument, NULL, OPT_FORMAT },
		{ "plugin", required_argument, NULL, OPT_PLUGIN },
		{ "help", no_argument, NULL, 'h' },
		{ NULL, 0, NULL, 0 },
	};
	enum image_format format = RT_FORMAT_UNKNOWN;
	const char *output = NULL;
	const char *plugins[CLI_PLUGINS_MAX];
	int n_plugins = 0;
	struct image img = { 0, 0, NULL };
	struct diag d;
	int c, rc;

	cli_set_signals();
	opterr = 0;
	while ((c = getopt_long(argc, argv, ":o:h", longopts, NULL)) != -1) {
		switch (c) {
		case 'o':
			if (tool_file_arg("--output", optarg, &output) != 0)
				return TOOL_EXIT_USAGE;
			break;
		case OPT_FORMAT:
			format = image_format_from_name(optarg);
			if (format == RT_FORMAT_UNKNOWN) {
				char names[64];
				return tool_usage_error("--format: expected %s, found '%s'",
							image_format_names(names, sizeof(names), ""), optarg);
			}
			break;
		case OPT_PLUGIN:
			if (optarg[0] == '\0')
				return tool_usage_error("--plugin: %s", "expected a file name, found ''");
			if (n_plugins == CLI_PLUGINS_MAX)
				return tool_usage_error("--plugin: at most %d plugins", CLI_PLUGINS_MAX);
			plugins[n_plugins++] = optarg;
			break;
		case 'h':
			merge_usage(stdout);
			return 0;
		case ':':
			return tool_usage_error("option '%s' needs a value", argv[optind - 1]);
		default:
			return tool_unknown_option(argv[optind - 1], longopts);
		}
	}
	if (!output)
		return tool_usage_error("%s", "no output given (-o FULL.png)");
	if (optind == argc)
		return tool_usage_error("%s", "no tiles given");
	if (format == RT_FORMAT_UNKNOWN) {
		format = image_format_from_path(output);
		if (format == RT_FORMAT_UNKNOWN) {
			char ext[64];
			return tool_usage_error("--output: cannot tell the format of '%s' (use %s, or --format)",
						output, image_format_names(ext, sizeof(ext), "."));
		}
	}
	diag_clear(&d);
	if ((rc = cli_plugins_load(plugins, n_plugins, tool_print_note, NULL, &d)) < 0 ||
	    (rc = merge_check_plugins(argv[optind], plugins, n_plugins, &d)) < 0) {
		tool_print_diag(&d, "error");
		return TOOL_EXIT_FAILURE;
	}
	rc = merge_tiles((const char *const *)(argv + optind), (size_t)(argc - optind), &img, NULL, &d);
	if (rc == 0)
		rc = image_write(&img, output, format, &cli_cancelled, &d);
	image_free(&img);
	if (rc < 0) {
		tool_print_diag(&d, "error");
		return rc == -RT_E_INTERRUPTED || cli_cancelled ? 128 + (int)cli_cancelled : TOOL_EXIT_FAILURE;
	}
	return 0;
}

