/* A plugin whose methods break the rules of whitted/shape.h one way each,
 * chosen at build time (tests/cli/plugins.sh): the keyword "blob" (a
 * sphere of radius 1 at the point read) whose
 *   -DPARSE_ZERO      parse returns 0 without a shape,
 *   -DPARSE_POSITIVE  parse returns 7,
 *   -DPARSE_SILENT    parse fails without calling host->fail,
 *   -DPARSE_ODD_ERROR parse fails with -RT_E_INVALID (not a parse's error),
 *   -DPARSE_ALIEN     parse returns a shape of another table,
 *   -DEXPORT_POSITIVE export_pov returns 3,
 *   -DEXPORT_SILENT   export_pov returns -RT_E_IO without writing,
 *   -DTESS_POSITIVE   tessellate returns 5.
 * The host must refuse each with a message that names the plugin's fault,
 * and never crash. */
#include <math.h>

#include "whitted/plugin.h"

WHITTED_PLUGIN_ABI_SYMBOL;

static const struct whitted_plugin_host *host;

struct blob {
	struct shape base;
	struct vec3 c;
};

static const struct shape_ops blob_ops;
#if defined(PARSE_ALIEN)
static const struct shape_ops alien_ops;
#endif

static int blob_parse(struct parser *p, struct shape **out)
{
	struct blob *b;
	int rc;

	*out = NULL;
#if defined(PARSE_ZERO)
	(void)p, (void)b, (void)rc;
	return 0;
#elif defined(PARSE_POSITIVE)
	(void)p, (void)b, (void)rc;
	return 7;
#elif defined(PARSE_SILENT)
	(void)p, (void)b, (void)rc;
	return -RT_E_SYNTAX;
#elif defined(PARSE_ODD_ERROR)
	(void)b, (void)rc;
	return host->fail(p, RT_E_INVALID, "blob: an error of the wrong kind");
#else
	b = host->alloc(sizeof(*b));
	if (!b)
		return host->fail(p, RT_E_NOMEM, "out of memory");
	if ((rc = host->vec3(p, "blob centre", &b->c)) < 0 ||
	    (rc = host->material(p, &b->base.mat)) < 0) {
		host->free(b);
		return rc;
	}
#if defined(PARSE_ALIEN)
	b->base.ops = &alien_ops;
#else
	b->base.ops = &blob_ops;
#endif
	*out = &b->base;
	return 0;
#endif
}

static bool blob_intersect(const struct shape *s, const struct ray *r, double t_min,
			   double *t_max)
{
	const struct blob *b = (const struct blob *)s;
	struct vec3 oc = vec3_sub(r->origin, b->c);
	double a = vec3_dot(r->dir, r->dir), h = vec3_dot(oc, r->dir);
	double c = vec3_dot(oc, oc) - 1.0, disc = h * h - a * c, t;

	if (disc < 0.0)
		return false;
	t = (-h - sqrt(disc)) / a;
	if (!(t > t_min))
		t = (-h + sqrt(disc)) / a;
	if (!(t > t_min && t < *t_max))
		return false;
	*t_max = t;
	return true;
}

static struct vec3 blob_normal(const struct shape *s, struct vec3 p)
{
	return vec3_normalize(vec3_sub(p, ((const struct blob *)s)->c));
}

static int blob_export(const struct shape *s, FILE *out, const struct pov_options *opt)
{
#if defined(EXPORT_POSITIVE)
	(void)s, (void)out, (void)opt;
	return 3;
#elif defined(EXPORT_SILENT)
	(void)s, (void)out, (void)opt;
	return -RT_E_IO;
#else
	const struct blob *b = (const struct blob *)s;

	fputs("sphere { ", out);
	host->pov_vector(out, b->c.x, b->c.y, b->c.z);
	fputs(", 1\n", out);
	host->pov_texture(out, &s->mat, opt);
	fputs("}\n", out);
	return 0;
#endif
}

static void blob_destroy(struct shape *s)
{
	host->free(s);
}

static bool blob_bounds(const struct shape *s, struct aabb *out)
{
	const struct blob *b = (const struct blob *)s;

	out->min = vec3_sub(b->c, vec3_make(1.0, 1.0, 1.0));
	out->max = vec3_add(b->c, vec3_make(1.0, 1.0, 1.0));
	return true;
}

static int blob_tessellate(const struct shape *s, const struct mesh_options *opt,
			   struct mesh *out)
{
	struct aabb box;

	(void)opt;
	blob_bounds(s, &box);
#if defined(TESS_POSITIVE)
	(void)out, (void)box;
	return 5;
#else
	return host->mesh_box(out, box);
#endif
}

static const struct shape_ops blob_ops = {
	.keyword = "blob",
	.parse = blob_parse,
	.intersect = blob_intersect,
	.normal = blob_normal,
	.export_pov = blob_export,
	.destroy = blob_destroy,
	.bounds = blob_bounds,
	.tessellate = blob_tessellate,
};

#if defined(PARSE_ALIEN)
/* Never registered: a table the host does not know. */
static const struct shape_ops alien_ops = {
	.keyword = "alien",
	.parse = blob_parse,
	.intersect = blob_intersect,
	.normal = blob_normal,
	.export_pov = blob_export,
	.destroy = blob_destroy,
};
#endif

static const struct shape_ops *const blob_shapes[] = { &blob_ops, NULL };

int whitted_plugin_init(const struct whitted_plugin_host *h)
{
	static const struct whitted_plugin plugin = { "hostile", "1", blob_shapes };

	host = h;
	return host->register_plugin(host, &plugin);
}
