/* Constructors of the built-in primitives, for the scene model (the floor)
 * and the unit tests; scene files reach the primitives through the
 * registry instead. */
#ifndef RT_SHAPES_H
#define RT_SHAPES_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "whitted/diag.h"
#include "whitted/material.h"
#include "whitted/shape.h"
#include "whitted/vec3.h"

struct shape *sphere_create(struct vec3 centre, double radius, const struct material *m);
struct shape *triangle_create(struct vec3 a, struct vec3 b, struct vec3 c,
			      const struct material *m);
/* coef = A..J of A x^2 + B y^2 + C z^2 + D xy + E xz + F yz + G x + H y + I z + J;
 * extent 0 on an axis means no clipping along it. */
struct shape *quadric_create(const double coef[10], struct vec3 clip_ref,
			     struct vec3 clip_extent, const struct material *m);

/* The pyramid dialect's pyramid: the base [corner.x, corner.x + base] x
 * [corner.y, corner.y + base] at height corner.z, the apex above the base's
 * centre at corner.z + height; a closed solid.  Sizes > 0. */
struct shape *pyramid_create(struct vec3 corner, double base, double height,
			     const struct material *m);
/* nearfar's: the base [x - width/2, x + width/2] x [y - width/2, y + width/2]
 * at height z about centre (x, y, z), the apex at (x, y, z + height). */
struct shape *pyramid_create_centred(struct vec3 centre, double width, double height,
				     const struct material *m);
/* nearfar's cube: the box [corner, corner + side] on each axis (side > 0). */
struct shape *cube_create(struct vec3 corner, double side, const struct material *m);

/* The checkerboard floor at z = 0 with cells of side `cell` (> 0), white
 * where the cell indices' sum is even, black where it is odd, with m's
 * coefficients and shininess (its colour is not used).  A finite width
 * (> 0) is the square [-w/2, w/2)^2 with cell (floor((x + w/2) / cell),
 * floor((y + w/2) / cell)); width INFINITY is nearfar's checkerboard over
 * the whole plane, unbounded, with cell (floor(x / cell), floor(y / cell)). */
struct shape *floor_create_view(double width, double cell, const struct material *m);
/* The assignment's floor finish (0.4 0.2 0.2 0.2, shininess 1), which
 * every dialect's floor but nearfar's has, and floor_create_view with it. */
extern const struct material floor_classic_material;
struct shape *floor_create(double width, double cell);
/* Puts the image of path white (NULL: none) over each white cell of a floor
 * of floor_create_view, and that of black over each black cell (see
 * floor.c).  RT_E_IO naming the file when one cannot be read as a PNG or
 * BMP image; the floor keeps what it read and floor's destroy frees it. */
int floor_set_textures(struct shape *s, const char *white, const char *black, struct diag *d);
/* hash_bytes over the textures' sizes and pixels, white then black (0 for
 * a floor without textures). */
uint64_t floor_texture_hash(const struct shape *s);
/* The closed method of the shapes that always bound a solid. */
bool shape_closed_always(const struct shape *s);
/* The decoded texels (8-bit RGB, top row first) of the white (k 0) or
 * black (k 1) cells' texture, or NULL when that cell has none. */
const struct image *floor_texture(const struct shape *s, int k);
/* A new shape of `size` bytes (a struct whose first member is its struct
 * shape) with its ops and material set, the rest uninitialised; NULL when
 * out of memory. */
void *shape_alloc(size_t size, const struct shape_ops *ops, const struct material *m);
/* The normal_packet of a shape whose normal is the same everywhere: v
 * into each active lane of n. */
static inline void shape_normal_fill(uint32_t active, struct vec3 v, double *const n[3])
{
	int i;

	for (i = 0; i < RT_PACKET_MAX && active >> i; i++) {
		if (!(active >> i & 1))
			continue;
		n[0][i] = v.x;
		n[1][i] = v.y;
		n[2][i] = v.z;
	}
}
/* The destroy method of the shapes that own nothing outside their own
 * block of rt_malloc. */
void shape_destroy_block(struct shape *s);

struct parser;
struct pov_options;
/* The start of a POV-Ray object that the built-ins' export_pov write:
 * open, its keyword and brace as written ("box { "), then its n leading
 * vectors (points, or a quadric's coefficients three at a time) separated
 * by ", ".  The caller goes on with its own terms, then shape_pov_finish. */
void shape_pov_begin(FILE *out, const char *open, const struct vec3 *v, int n);
/* The end that every built-in's export_pov writes after its geometry: the
 * material's texture on a line of its own and the closing brace; 0, or
 * -RT_E_IO when out has failed. */
int shape_pov_finish(const struct shape *s, FILE *out, const struct pov_options *opt);
/* The parse method of the objects written as a point, a size (see
 * parser_size) and the material, made by create (sphere_create,
 * cube_create); what_point and what_size name the two in messages. */
typedef struct shape *shape_point_size_create(struct vec3 point, double size,
					      const struct material *m);
int shape_parse_point_size(struct parser *p, const char *what_point, const char *what_size,
			   shape_point_size_create *create, struct shape **out);

#endif
