/* The operands after a command's options: the SCENE (none with
 * --test-scene) and what follows it. */
#include "cli/scene_opts.h"
#include "cli/tool.h"

int cli_scene_operand(const struct cli_scene *o, int argc, char **argv, int first,
		      const char **path, struct diag *d)
{
	*path = NULL;
	if (o->list_shapes && first == argc)
		return 0;
	if (o->test_scene) {
		if (first != argc)
			return diag_fail(d, RT_E_INVALID,
					"--test-scene takes no SCENE, found '%s'", argv[first]);
		return 0;
	}
	if (first == argc)
		return diag_fail(d, RT_E_INVALID, "no SCENE given");
	if (first + 1 != argc)
		return diag_fail(d, RT_E_INVALID, "one SCENE expected, found also '%s'",
				argv[first + 1]);
	*path = argv[first];
	return 0;
}

int cli_scene_and_operand(struct cli_scene *o, int argc, char **argv, int *first, const char *what,
			  const char *hint)
{
	if (!o->test_scene) {
		if (*first == argc)
			return tool_usage_error("no SCENE given");
		o->path = argv[(*first)++];
	}
	if (*first == argc)
		return tool_usage_error("no %s given", what);
	if (*first + 1 != argc)
		return tool_usage_error("one %s expected, found also '%s'%s", what, argv[*first + 1], hint);
	return 0;
}
