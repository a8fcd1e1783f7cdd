/* A plugin registering the keyword CLASH_KEYWORD (-D at build time: a
 * built-in's, "sphere", or another plugin's, "quad"), which the host must
 * refuse (tests/cli/plugins.sh).  The methods are never called. */
#include "whitted/plugin.h"

WHITTED_PLUGIN_ABI_SYMBOL;

static int clash_parse(struct parser *p, struct shape **out)
{
	(void)p;
	*out = NULL;
	return -RT_E_SYNTAX;
}

static bool clash_intersect(const struct shape *s, const struct ray *r, double t_min,
			    double *t_max)
{
	(void)s, (void)r, (void)t_min, (void)t_max;
	return false;
}

static struct vec3 clash_normal(const struct shape *s, struct vec3 p)
{
	(void)s;
	return p;
}

static int clash_export(const struct shape *s, FILE *out, const struct pov_options *opt)
{
	(void)s, (void)out, (void)opt;
	return 0;
}

static void clash_destroy(struct shape *s)
{
	(void)s;
}

static const struct shape_ops clash_ops = {
	.keyword = CLASH_KEYWORD,
	.parse = clash_parse,
	.intersect = clash_intersect,
	.normal = clash_normal,
	.export_pov = clash_export,
	.destroy = clash_destroy,
};

static const struct shape_ops *const clash_shapes[] = { &clash_ops, NULL };

int whitted_plugin_init(const struct whitted_plugin_host *host)
{
	static const struct whitted_plugin plugin = { "clash-" CLASH_KEYWORD, "1", clash_shapes };

	return host->register_plugin(host, &plugin);
}
