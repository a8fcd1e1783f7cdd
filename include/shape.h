/* The primitive interface.  Each primitive is one file under src/shapes/
 * that fills in a static const struct shape_ops; the registry maps scene
 * keywords to tables.  Outside src/shapes/ only the wrappers below call
 * through the table, so the NULL checks for optional members live there. */
#ifndef RT_SHAPE_H
#define RT_SHAPE_H

#include <stdbool.h>
#include <stdio.h>

#include "aabb.h"
#include "material.h"
#include "ray.h"

struct parser;
struct shape;
struct pov_options;

/* What a shape is, in the numbers of its scene-file entry, for tools that
 * draw shapes themselves (the OpenGL viewer) rather than trace them. */
enum shape_kind {
	RT_SHAPE_OTHER = 0,	/* no description: a primitive without the method */
	RT_SHAPE_SPHERE,
	RT_SHAPE_TRIANGLE,
	RT_SHAPE_QUADRIC,
	RT_SHAPE_FLOOR,
};

struct shape_geometry {
	enum shape_kind kind;
	union {
		struct {
			struct vec3 centre;
			double radius;
		} sphere;
		struct {
			struct vec3 v[3];
		} triangle;
		struct {
			double coef[10];	/* A..J of scene-format.md */
			struct vec3 lo, hi;	/* the clip box */
			bool clipped[3];	/* false: that axis is not clipped */
		} quadric;
		struct {
			double width, tile;	/* centred on the origin, z = 0 */
		} floor;
	} u;
};

struct shape_ops {
	const char *keyword;	/* scene-file keyword, unique */

	/* Reads the geometry and material after the keyword.  Returns 0 with a
	 * whole shape in *out, or a negative enum rt_err with *out NULL and the
	 * parser's diagnostic filled in. */
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
	/* Optional.  NULL or false: the shape is unbounded. */
	bool (*bounds)(const struct shape *s, struct aabb *out);
	/* Optional.  A line for the scene's notes when the shape can never be
	 * seen (a degenerate triangle); NULL when it is fine. */
	const char *(*degenerate)(const struct shape *s);
	/* Optional.  NULL: described as RT_SHAPE_OTHER. */
	void (*geometry)(const struct shape *s, struct shape_geometry *out);
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

static inline struct vec3 shape_normal(const struct shape *s, struct vec3 p)
{
	return s->ops->normal(s, p);
}

struct color shape_color_at(const struct shape *s, struct vec3 p);
/* True when the colour varies over the surface (color_at is set): such a
 * shape's POV-Ray export carries its own texture for the global lights. */
bool shape_is_textured(const struct shape *s);
bool shape_bounds(const struct shape *s, struct aabb *out);
const char *shape_degenerate(const struct shape *s);
void shape_geometry(const struct shape *s, struct shape_geometry *out);
int shape_export_pov(const struct shape *s, FILE *out, const struct pov_options *opt);
void shape_destroy(struct shape *s);

/* The registry: the table for a scene keyword, or NULL. */
const struct shape_ops *shape_ops_find(const char *keyword, size_t len);
/* The registered tables in order, NULL-terminated. */
const struct shape_ops *const *shape_ops_all(void);
/* "sphere, triangle, general": for error messages. */
const char *shape_keywords(void);

/* Primitives that the registry does not parse from files. */
struct shape *floor_create(double width, double tile);

#endif
