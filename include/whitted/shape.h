/* The primitive interface.  Each primitive is one file under src/shapes/
 * that fills in a static const struct shape_ops; the registry maps scene
 * keywords to tables.  Outside src/shapes/ only the wrappers below call
 * through the table, so the NULL checks for optional members live there. */
#ifndef RT_SHAPE_H
#define RT_SHAPE_H

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>

#include "aabb.h"
#include "material.h"
#include "ray.h"

/* The most rays intersect_packet is given at once: the bits of its mask. */
#define RT_PACKET_MAX 32
/* intersect_packet may read whole runs of this many rays (0-7, 8-15,
 * ...): see there. */
#define RT_PACKET_RUN 8

/* intersect_packet's rays, a coordinate an array: so that a method can
 * take a run of rays into one vector register a coordinate. */
struct ray_packet {
	double ox[RT_PACKET_MAX], oy[RT_PACKET_MAX], oz[RT_PACKET_MAX];
	double dx[RT_PACKET_MAX], dy[RT_PACKET_MAX], dz[RT_PACKET_MAX];
};

/* Ray i of a packet. */
static inline struct ray ray_packet_get(const struct ray_packet *p, int i)
{
	struct ray r;

	r.origin = vec3_make(p->ox[i], p->oy[i], p->oz[i]);
	r.dir = vec3_make(p->dx[i], p->dy[i], p->dz[i]);
	return r;
}

static inline void ray_packet_set(struct ray_packet *p, int i, const struct ray *r)
{
	p->ox[i] = r->origin.x;
	p->oy[i] = r->origin.y;
	p->oz[i] = r->origin.z;
	p->dx[i] = r->dir.x;
	p->dy[i] = r->dir.y;
	p->dz[i] = r->dir.z;
}

struct mesh;
struct mesh_options;
struct parser;
struct shape;
struct pov_options;

struct shape_ops {
	const char *keyword;	/* scene-file keyword, unique within each dialect */
	/* The dialects whose files name this keyword: a mask of
	 * RT_DIALECT_BIT(d) for d of enum scene_dialect (whitted/scene.h).
	 * 0: every dialect (plugins, and any table that does not say).  Two
	 * tables may share a keyword when their masks are disjoint (the
	 * pyramid's two placements). */
	unsigned dialects;

	/* Reads the geometry and material after the keyword.  Returns 0 with a
	 * whole shape in *out (whose ops is this table), or a negative enum
	 * rt_err with *out NULL and the parser's diagnostic filled in.  The
	 * host checks the answer: 0 without a shape or with another table's,
	 * a positive number, or an error without a message is the table's
	 * fault, reported at the object's keyword (a shape of another table is
	 * freed by this table's destroy). */
	int (*parse)(struct parser *p, struct shape **out);
	/* Nearest hit with t in (t_min, *t_max); on a hit shrinks *t_max to it.
	 * The direction need not be unit length. */
	bool (*intersect)(const struct shape *s, const struct ray *r,
			  double t_min, double *t_max);
	/* Unit normal at a point on the surface, in world space (either side). */
	struct vec3 (*normal)(const struct shape *s, struct vec3 p);
	/* Writes the shape, with its texture, as one POV-Ray object. */
	int (*export_pov)(const struct shape *s, FILE *out,
			  const struct pov_options *opt);
	void (*destroy)(struct shape *s);

	/* Optional.  NULL: the material colour everywhere. */
	struct color (*color_at)(const struct shape *s, struct vec3 p);
	/* Optional.  NULL or false: the shape is unbounded.  The wrapper
	 * starts *out at -inf .. inf on every axis, so that an unbounded shape
	 * can still give the axes it is bounded along (a quadric clipped on
	 * some axes only) and leave the others. */
	bool (*bounds)(const struct shape *s, struct aabb *out);
	/* Optional.  A line for the scene's notes when the shape can never be
	 * seen (a degenerate triangle); NULL when it is fine. */
	const char *(*degenerate)(const struct shape *s);
	/* Optional.  Appends the shape's triangles to out (see mesh.h), an
	 * unbounded one's inside opt->around.  0 or -RT_E_NOMEM.  NULL: the
	 * shape is meshed as its bounding box, and not at all if unbounded. */
	int (*tessellate)(const struct shape *s, const struct mesh_options *opt,
			  struct mesh *out);
	/* Optional.  When the specular highlight's colour at p is not
	 * color_at's (a textured floor: the texel colours the ambient and
	 * diffuse terms, the highlight keeps the cell's colour), stores it in
	 * *out and returns true.  NULL or false: color_at's. */
	bool (*specular_color_at)(const struct shape *s, struct vec3 p, struct color *out);
	/* Optional.  True when the surface bounds a solid (every ray that
	 * enters it leaves it), so that refraction through it as glass is
	 * exact: the sphere, the cube, the pyramid, a quadric that is a whole
	 * ellipsoid inside its clip box.  NULL or false: not known to be
	 * closed (a triangle, an open or clipped quadric), which --glass
	 * accepts with a note. */
	bool (*closed)(const struct shape *s);
	/* Optional (ABI 4).  intersect for each ray i of p whose bit i is
	 * set in `active` (i < RT_PACKET_MAX), in (t_min[i], t_max[i]),
	 * shrinking t_max[i] on a hit; the mask of the rays hit.  Each ray's
	 * answer must be intersect's to the bit (the same hit, the same t):
	 * images do not depend on which of the two ran.  The method may read
	 * every ray (and t_min, t_max) of a run of RT_PACKET_RUN that holds
	 * an active one (the host fills the others with some ray), so that it
	 * can test a run at once; t_max[i] of a ray not hit keeps its value
	 * (a method may store it back).  Bits outside `active` in the result
	 * are ignored.  NULL: intersect, ray by ray. */
	uint32_t (*intersect_packet)(const struct shape *s, const struct ray_packet *p,
				     uint32_t active, const double *t_min, double *t_max);
	/* Optional (ABI 5).  normal at each point i whose bit i is set in
	 * `active` (i < RT_PACKET_MAX), the point (p[0][i], p[1][i], p[2][i])
	 * and its normal into (n[0][i], n[1][i], n[2][i]): each normal's to
	 * the bit, as intersect_packet's answers are intersect's.  The method
	 * may read and write every lane of a run of RT_PACKET_RUN that holds
	 * an active one (the host's arrays hold whole runs; the others hold
	 * finite points, maybe of other surfaces, and what is written there is
	 * dropped).  NULL:
	 * normal, point by point. */
	void (*normal_packet)(const struct shape *s, const double *const p[3], uint32_t active,
			      double *const n[3]);
	/* Optional (ABI 5), and only beside color_at: color_at likewise, the
	 * red, green and blue of point i into (c[0][i], c[1][i], c[2][i]).
	 * NULL: color_at, point by point. */
	void (*color_packet)(const struct shape *s, const double *const p[3], uint32_t active,
			     double *const c[3]);
};

struct shape {
	const struct shape_ops *ops;
	struct material mat;
};

static inline bool shape_intersect(const struct shape *s, const struct ray *r,
				   double t_min, double *t_max)
{
	return s->ops->intersect(s, r, t_min, t_max);
}

/* See intersect_packet. */
static inline uint32_t shape_intersect_packet(const struct shape *s, const struct ray_packet *p,
					      uint32_t active, const double *t_min, double *t_max)
{
	uint32_t hit = 0;
	int i;

	/* A method's stray bits would give other rays hits they do not have
	 * (and index past the caller's arrays). */
	if (s->ops->intersect_packet)
		return s->ops->intersect_packet(s, p, active, t_min, t_max) & active;
	for (i = 0; i < RT_PACKET_MAX && active >> i; i++) {
		struct ray r;
		if (!(active >> i & 1))
			continue;
		r = ray_packet_get(p, i);
		if (s->ops->intersect(s, &r, t_min[i], t_max + i))
			hit |= (uint32_t)1 << i;
	}
	return hit;
}

static inline struct vec3 shape_normal(const struct shape *s, struct vec3 p)
{
	return s->ops->normal(s, p);
}

/* See normal_packet. */
static inline void shape_normal_packet(const struct shape *s, const double *const p[3],
				       uint32_t active, double *const n[3])
{
	int i;

	if (s->ops->normal_packet) {
		s->ops->normal_packet(s, p, active, n);
		return;
	}
	for (i = 0; i < RT_PACKET_MAX && active >> i; i++) {
		struct vec3 v;
		if (!(active >> i & 1))
			continue;
		v = s->ops->normal(s, vec3_make(p[0][i], p[1][i], p[2][i]));
		n[0][i] = v.x;
		n[1][i] = v.y;
		n[2][i] = v.z;
	}
}

/* Inline, as it runs at every hit; the default for a NULL color_at is
 * still written only here. */
static inline struct color shape_color_at(const struct shape *s, struct vec3 p)
{
	return s->ops->color_at ? s->ops->color_at(s, p) : s->mat.color;
}

/* shape_color_at point by point over the active lanes: the fallback of
 * shape_color_packet, and of a color_packet for the points it has no
 * faster way for. */
static inline void shape_color_lanes(const struct shape *s, const double *const p[3],
				     uint32_t active, double *const c[3])
{
	int i;

	for (i = 0; i < RT_PACKET_MAX && active >> i; i++) {
		struct color v;
		if (!(active >> i & 1))
			continue;
		v = shape_color_at(s, vec3_make(p[0][i], p[1][i], p[2][i]));
		c[0][i] = v.r;
		c[1][i] = v.g;
		c[2][i] = v.b;
	}
}

/* See color_packet: the material colour where the shape has no color_at. */
static inline void shape_color_packet(const struct shape *s, const double *const p[3],
				      uint32_t active, double *const c[3])
{
	if (s->ops->color_at && s->ops->color_packet) {
		s->ops->color_packet(s, p, active, c);
		return;
	}
	shape_color_lanes(s, p, active, c);
}

/* See specular_color_at: false (and *out untouched) for the usual shape. */
static inline bool shape_specular_color_at(const struct shape *s, struct vec3 p,
					   struct color *out)
{
	return s->ops->specular_color_at && s->ops->specular_color_at(s, p, out);
}

/* True when the colour varies over the surface (color_at is set): such a
 * shape's POV-Ray export carries its own texture for the global lights. */
bool shape_is_textured(const struct shape *s);
/* True when bounded; false leaves -inf .. inf on the axes it is not
 * bounded along (every axis, for most unbounded shapes). */
bool shape_bounds(const struct shape *s, struct aabb *out);
const char *shape_degenerate(const struct shape *s);
/* See closed: false when the table has none. */
bool shape_closed(const struct shape *s);
/* True when the primitive makes its own mesh; false when shape_tessellate
 * gives its bounding box (or nothing, if it is unbounded) instead. */
bool shape_tessellates(const struct shape *s);
/* The table's status as it is: any value but 0 is a failure (a plugin's
 * positive number too), which the caller reports as the table's own. */
int shape_tessellate(const struct shape *s, const struct mesh_options *opt, struct mesh *out);
int shape_export_pov(const struct shape *s, FILE *out, const struct pov_options *opt);
void shape_destroy(struct shape *s);

/* The registry: the table for a scene keyword (len bytes, not
 * NUL-terminated), or NULL; the first registered table of that keyword,
 * whatever its dialects. */
const struct shape_ops *shape_ops_find(const char *keyword, size_t len);
/* The table for a keyword among those whose mask meets `dialects` (a mask
 * of RT_DIALECT_BIT(d); a table of mask 0 meets every one, and dialects 0
 * means any table: shape_ops_find), or NULL. */
const struct shape_ops *shape_ops_find_in(const char *keyword, size_t len, unsigned dialects);
/* The registered tables in order, NULL-terminated: the built-in ones,
 * then those of the plugins loaded (whitted/plugin.h).  Plugins are loaded
 * before any scene is read; the array and the lists below are not to be
 * read while one is being loaded. */
const struct shape_ops *const *shape_ops_all(void);
/* The keywords of every table, each once, in the registry's order:
 * "sphere, triangle, general, pyramid, cube", for error messages. */
const char *shape_keywords(void);
/* The same, of the tables shape_ops_find_in finds for `dialects` (0:
 * shape_keywords()): "sphere, triangle, general, pyramid" for the pyramid
 * dialect.  The lists are static, built for every mask of the dialects of
 * enum scene_dialect when tables are registered (thread-safe); bits above
 * the last dialect's are ignored here and in shape_ops_find_in. */
const char *shape_keywords_in(unsigned dialects);

#endif
