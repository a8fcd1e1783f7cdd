/* The plugin interface: a new primitive as a shared object (.so) that
 * every program of whitted loads at run time (--plugin FILE.so, or every
 * .so in the directories of WHITTED_PLUGIN_PATH).  See docs/plugins.md for
 * a tutorial.
 *
 * A plugin is one C file compiled with
 *     cc -shared -fPIC $(pkg-config --cflags whitted) -o x.so x.c
 * that defines two symbols:
 *     WHITTED_PLUGIN_ABI_SYMBOL;    (const unsigned whitted_plugin_abi = ...)
 *     int whitted_plugin_init(const struct whitted_plugin_host *host);
 * The host checks whitted_plugin_abi before anything else: a plugin built
 * for another ABI version is refused before its init runs (only static
 * constructors run at dlopen, and a plugin has no need of any).
 * whitted_plugin_init then calls host->register_plugin once with the
 * plugin's name, version and shape tables (struct shape_ops of
 * whitted/shape.h, one per keyword), and returns what it returned (0, or a
 * negative enum rt_err: the load then fails with the host's message, or,
 * for a failure of the plugin's own, "init failed").
 *
 * The plugin calls the host only through the function pointers below: the
 * programs are linked with the static libwhitted.a, whose symbols a .so
 * cannot see.  The inline helpers of vec3.h, ray.h, aabb.h and material.h
 * are header-only and free to use; the functions declared in parser.h,
 * pov.h and mesh.h are not (use host->...).  Keep the host pointer (it
 * stays valid as long as the plugin is loaded) for the shape methods.
 *
 * The shape tables follow the rules of whitted/shape.h: parse reads the
 * words after the keyword with host->number, ->vec3, ... and ends with
 * host->material; it returns 0 with a whole shape (first member struct
 * shape, its ops the plugin's table, allocated with host->alloc) or a
 * negative enum rt_err with *out NULL and the message given through
 * host->fail (located at the last word read).  A table's dialects member
 * may be 0 (every dialect of the course format).
 *
 * Threads: intersect (and normal, color_at) run on every render thread at
 * once, for every ray: they must allocate nothing and take no lock.
 * bounds, too, runs on several threads at once (the hierarchy's build
 * bounds a big scene's shapes in parallel), and must write nothing.
 * parse, too, may run on several threads at once, each with its own
 * struct parser (a big scene file is parsed in parts in parallel: see
 * src/scenefile/parse_parts.c), and so may host->alloc and host->free,
 * which are thread-safe: parse must not write any state but the shape it
 * builds (no static buffers, no counters; read-only tables are fine).
 * Only whitted_plugin_init runs alone (loading is serialised, and
 * register_plugin is refused with -RT_E_INVALID at any other time).
 *
 * Stability: the host loads a plugin only when its whitted_plugin_abi is
 * exactly the host's WHITTED_PLUGIN_ABI (older and newer versions alike
 * are refused; there is no compatibility range).  WHITTED_PLUGIN_ABI goes
 * up by one with ANY change of the size, member order, member types or
 * meaning of what a plugin sees:
 *     struct shape_ops, struct shape, struct material, struct color,
 *     struct vec3, struct ray, struct aabb, struct ray_packet,
 *     RT_PACKET_MAX, RT_PACKET_RUN (shape.h, material.h, vec3.h, ray.h,
 *     aabb.h), struct mesh, struct mesh_texture, struct mesh_uv,
 *     struct mesh_options, RT_MESH_TEXELS_MAX, RT_MESH_FLOATS_PER_VERTEX
 *     (mesh.h), struct pov_options (pov.h), struct whitted_plugin_host (a member added at its end too:
 *     host->size is informational only) and struct whitted_plugin (here),
 *     the values of enum rt_err (diag.h), of enum scene_dialect and
 *     RT_DIALECT_BIT (scene.h), and the behaviour a host function
 *     promises below;
 * that includes growing a struct that is embedded by value (struct
 * material inside struct shape shifts every member of a plugin's own
 * shape struct).  tests/unit/plugin/test_abi.c pins the sizes and offsets
 * of these types for the current version, so that such a change cannot
 * land without the bump.
 * History: 1, the first (never released alone); 2, the first released:
 * host->solve_quadratic and host->ray_triangle, struct material's kt and
 * ior, struct shape_ops' specular_color_at and closed, struct
 * pov_options' shadow_twin and floor_texture; 3: struct shape_ops'
 * intersect_packet (at its end) and RT_PACKET_MAX (shape.h); 4:
 * intersect_packet takes its rays as a struct ray_packet (a coordinate an
 * array, so that a method can load a run of rays into a vector register)
 * and may read whole runs of RT_PACKET_RUN rays; 5: struct shape_ops'
 * normal_packet and color_packet (at its end), a packet's hit points'
 * normals and colours. */
#ifndef RT_PLUGIN_H
#define RT_PLUGIN_H

#include <stddef.h>
#include <stdio.h>

#include "aabb.h"
#include "diag.h"
#include "material.h"
#include "shape.h"
#include "vec3.h"

#define WHITTED_PLUGIN_ABI 5

/* Defines the symbol the host checks first; write it once in the plugin's
 * file, at file scope. */
#define WHITTED_PLUGIN_ABI_SYMBOL const unsigned whitted_plugin_abi = WHITTED_PLUGIN_ABI

struct mesh;
struct parser;
struct pov_options;

/* What a plugin registers: its name (letters, digits, '-', '_', '.'; it
 * names the plugin in tiles and in --list-shapes), its version (free text
 * without spaces, e.g. "1.0"), and its tables, NULL-terminated, each with
 * a keyword that no built-in and no other plugin has (a word of letters,
 * digits and '_' that starts with a letter).  Everything it points to
 * stays valid while the plugin is loaded (static storage). */
struct whitted_plugin {
	const char *name;
	const char *version;
	const struct shape_ops *const *shapes;
};

struct whitted_plugin_host {
	unsigned abi;		/* WHITTED_PLUGIN_ABI of the host */
	size_t size;		/* sizeof(struct whitted_plugin_host) in the host
				 * (equal to the plugin's: the versions are) */

	/* Registers the plugin's shapes, all or none: 0, or -RT_E_INVALID
	 * when a keyword clashes with a registered one, a table lacks a
	 * required method, or register_plugin was already called; the host
	 * then reports why. */
	int (*register_plugin)(const struct whitted_plugin_host *host,
			       const struct whitted_plugin *plugin);

	/* The parser's services for parse.  `what` names the item in the
	 * messages ("torus minor radius").  Each returns 0, or a negative
	 * enum rt_err with the located message already filled in: return it
	 * as it is. */
	int (*number)(struct parser *p, const char *what, double *out);
	/* An integer in [lo, hi] (an integral real such as 4.0 is one). */
	int (*integer)(struct parser *p, const char *what, long lo, long hi, long *out);
	int (*vec3)(struct parser *p, const char *what, struct vec3 *out);
	/* Three numbers in [0, 1]. */
	int (*color)(struct parser *p, const char *what, struct color *out);
	/* The colour, coefficients and shininess that end every object. */
	int (*material)(struct parser *p, struct material *out);
	/* Fails at the last word read with a printf-style message; returns
	 * -err (RT_E_SYNTAX for a word that does not fit, RT_E_RANGE for a
	 * value out of its range). */
	int (*fail)(struct parser *p, enum rt_err err, const char *fmt, ...)
#if defined(__GNUC__)
		__attribute__((format(printf, 3, 4)))
#endif
		;

	/* Memory for shapes: alloc returns NULL when out of memory (parse
	 * then fails with host->fail(p, RT_E_NOMEM, "out of memory")); free
	 * releases it (in destroy).  Thread-safe: parse may run on several
	 * threads at once. */
	void *(*alloc)(size_t size);
	void (*free)(void *p);

	/* For export_pov: POV-Ray 3.7 text that reads back as the same
	 * doubles, and the texture of a material as the built-ins write it. */
	void (*pov_number)(FILE *out, double v);
	void (*pov_vector)(FILE *out, double x, double y, double z);
	void (*pov_texture)(FILE *out, const struct material *m, const struct pov_options *opt);

	/* For tessellate (the viewer's drawing): one triangle with its
	 * vertex normals, and the twelve of a box.  0 or -RT_E_NOMEM. */
	int (*mesh_triangle)(struct mesh *m, const struct vec3 p[3], const struct vec3 n[3]);
	int (*mesh_box)(struct mesh *m, struct aabb box);

	/* The built-ins' maths, to share rather than copy (ABI 2).  Real roots
	 * of a t^2 + b t + c = 0, ascending, without cancellation (a = 0: the
	 * linear case); how many (0, 1 or 2).  Pure, for intersect. */
	int (*solve_quadratic)(double a, double b, double c, double roots[2]);
	/* Moller-Trumbore: the t in (t_min, t_max) where the ray meets the
	 * triangle v0 + u e1 + v e2 (u, v >= 0, u + v <= 1), from either
	 * side.  Pure, for intersect. */
	bool (*ray_triangle)(const struct ray *r, struct vec3 v0, struct vec3 e1, struct vec3 e2,
			     double t_min, double t_max, double *t);
};

/* The two symbols every plugin defines (declared here so that the
 * plugin's definitions have a prototype). */
extern const unsigned whitted_plugin_abi;
int whitted_plugin_init(const struct whitted_plugin_host *host);

/* Helpers for the steps every plugin takes the same way, inline so that
 * they are compiled into the plugin against the header it was built with
 * (and so need no symbol of the host's).
 *
 * The body of a usual whitted_plugin_init: refuses a host of another ABI
 * or a smaller table with -RT_E_INVALID, otherwise keeps h in *keep for
 * the shapes' methods and registers plugin, returning what that returns. */
static inline int whitted_plugin_start(const struct whitted_plugin_host *h,
				       const struct whitted_plugin_host **keep,
				       const struct whitted_plugin *plugin)
{
	if (h->abi != WHITTED_PLUGIN_ABI || h->size < sizeof(*h))
		return -RT_E_INVALID;
	*keep = h;
	return h->register_plugin(h, plugin);
}

/* The end of a usual parse: reads the material, then allocates a shape of
 * size bytes (a struct whose first member is its struct shape) with ops
 * and that material, the rest for the caller to fill in.  NULL with *rc
 * the error (the message filled in) when the material does not read or
 * memory runs out; otherwise *rc is 0. */
static inline struct shape *whitted_plugin_new_shape(const struct whitted_plugin_host *h,
						     struct parser *p,
						     const struct shape_ops *ops,
						     size_t size, int *rc)
{
	struct material m;
	struct shape *s;

	if ((*rc = h->material(p, &m)) < 0)
		return NULL;
	if (!(s = (struct shape *)h->alloc(size))) {
		*rc = h->fail(p, RT_E_NOMEM, "out of memory");
		return NULL;
	}
	s->ops = ops;
	s->mat = m;
	*rc = 0;
	return s;
}

/* The closed method of a shape that always bounds a solid. */
static inline bool whitted_plugin_closed_always(const struct shape *s)
{
	(void)s;
	return true;
}

#endif
