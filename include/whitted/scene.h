/* The scene model: settings from the file, the objects and the lights.  The
 * scene owns everything in it; scene_destroy frees it all.  The structure is
 * private to the library: tools read it through the accessors below and
 * change it only through the functions that check what they are given. */
#ifndef RT_SCENE_H
#define RT_SCENE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "diag.h"
#include "material.h"
#include "shape.h"
#include "vec3.h"

/* Limits that keep any input from allocating without bound. */
#define RT_MAX_IMAGE_SIZE 32768
#define RT_MAX_PIXELS (1L << 28)
#define RT_MAX_RECURSION 256
#define RT_MAX_OBJECTS 500000000L	/* within the hierarchy's 2^29 */
#define RT_MAX_LIGHTS 100000L
/* A scene file's size is limited at run time (scenefile.h:
 * scene_read_options' max_bytes, --max-scene-size). */

/* The implicit floor of every scene (the assignment's Floor(1000, 20)). */
#define RT_FLOOR_WIDTH 1000.0
#define RT_FLOOR_TILE 20.0

/* The dialects of scene files (scene-format.md, "The dialects").  A
 * primitive's table says in which dialects its keyword exists as a mask of
 * RT_DIALECT_BIT(d) (0: every dialect). */
enum scene_dialect {
	RT_DIALECT_AUTO = 0,	/* detect from the file (scene_read_options only) */
	RT_DIALECT_CLASSIC,
	RT_DIALECT_SPOT,
	RT_DIALECT_PYRAMID,
	RT_DIALECT_NEARFAR,
	RT_DIALECT_COUNT
};
#define RT_DIALECT_BIT(d) (1u << (d))
/* The dialects of the course's first grammar (parse_classic.c). */
#define RT_DIALECT_CLASSIC_FAMILY \
	(RT_DIALECT_BIT(RT_DIALECT_CLASSIC) | RT_DIALECT_BIT(RT_DIALECT_SPOT) | \
	 RT_DIALECT_BIT(RT_DIALECT_PYRAMID))

/* "auto", "classic", "spot", "pyramid", "nearfar"; NULL for a value
 * outside the enumeration. */
const char *scene_dialect_name(enum scene_dialect d);
/* The dialect of that name, or -1. */
int scene_dialect_from_name(const char *name);
/* Every dialect's name for a message: "auto, classic, spot, pyramid or
 * nearfar"; returns buf. */
const char *scene_dialect_names(char *buf, size_t size);

/* A light: a point light, or a spotlight (spot) that lights a point P only
 * when the angle between P - pos and axis is at most cutoff_deg, a hard
 * edge.  Either kind may fall off with the distance d to P: its light is
 * scaled by exp(-d^2 falloff).  scene_add_light_full checks and completes
 * the struct (axis made unit, cos_cutoff filled; for a point light the
 * spot members are zeroed). */
struct light {
	struct vec3 pos;
	struct color color;	/* each channel >= 0 */
	double falloff;		/* >= 0; 0: none */
	bool spot;
	struct vec3 axis;	/* spot: unit (normalised by scene_add_light_full) */
	double cutoff_deg;	/* spot: the cone's half-angle, in (0, 180] */
	double cos_cutoff;	/* spot: cos(cutoff_deg), filled by scene_add_light_full */
};

/* What a scene file says about the view and the floor besides the objects:
 * the dialect's fixed choices, or nearfar's header.  The camera's eye,
 * look-at point and up vector are never in the file. */
struct scene_view {
	enum scene_dialect dialect;	/* as read (never RT_DIALECT_AUTO) */
	double fov_deg;		/* vertical: 80 (classic, spot), 90 (pyramid), FOVY (nearfar) */
	double near, far;	/* near 0: primary rays start at the eye (all but nearfar) */
	double aspect;		/* 0: FOVX = FOVY; nearfar's ASPECT: FOVX = ASPECT * FOVY */
	double floor_width;	/* RT_FLOOR_WIDTH, or INFINITY: nearfar's infinite checkerboard */
	double floor_cell;	/* 20 classic and spot, 30 pyramid, CELL nearfar */
	struct material floor_mat;	/* colour unused; classic: 0.4 0.2 0.2 0.2, shininess 1;
					 * nearfar: KA KD 0 KR, shininess 1 */
	/* --floor-texture: the images over the white and the black cells
	 * (NULL: the plain colour), read by scene_add_view_floor.  Never in a
	 * scene file. */
	const char *floor_texture[2];
};

struct scene;

struct scene *scene_create(const char *name);
void scene_destroy(struct scene *s);
/* Takes ownership of sh, also on failure. */
int scene_add_shape(struct scene *s, struct shape *sh, struct diag *d);
/* A white or coloured point light without falloff. */
int scene_add_light(struct scene *s, struct vec3 pos, struct color color, struct diag *d);
/* Any light.  Lights are lit in the order added; scene-format.md's order is
 * the point lights first, then the spotlights, and the reader adds them so.
 * RT_E_RANGE for a position that is not finite, a colour channel or a
 * falloff that is negative or not finite, and for a spotlight a zero or
 * not finite axis or a cutoff outside (0, 180]; the diagnostic says what
 * is wrong (without a place in the file: that is the reader's). */
int scene_add_light_full(struct scene *s, const struct light *l, struct diag *d);
/* Makes shape `index` (0-based, in the order added: a scene file's objects
 * in the file's order) glass: transmission kt in (0, 1), index of
 * refraction ior > 0 (both finite).  RT_E_INVALID naming the object (1-based,
 * as --glass counts) when there is no such shape or a value is out of range. */
int scene_set_glass(struct scene *s, size_t index, double ior, double kt, struct diag *d);
/* Adds the checkerboard floor (width and floor cell > 0). */
int scene_add_floor(struct scene *s, double width, double cell, struct diag *d);
/* The recursion level (1..RT_MAX_RECURSION) and the image size (1 ..
 * RT_MAX_IMAGE_SIZE, at most RT_MAX_PIXELS pixels): RT_E_RANGE otherwise. */
int scene_set_recursion(struct scene *s, long recursion, struct diag *d);
int scene_set_image_size(struct scene *s, long size, struct diag *d);
void scene_set_source_hash(struct scene *s, uint64_t hash);

/* The classic dialect's view: fov 80, no near plane, square pixels, the
 * floor RT_FLOOR_WIDTH wide with RT_FLOOR_TILE cells and the classic
 * material.  A new scene has it until scene_set_view. */
void scene_view_default(struct scene_view *v);
/* The view is copied; the reader has checked it. */
void scene_set_view(struct scene *s, const struct scene_view *v);
const struct scene_view *scene_view_of(const struct scene *s);
/* Adds the floor the view describes (floor_create_view): RT_E_RANGE when
 * its width is not > 0 (INFINITY is allowed), its cell not finite and > 0,
 * or its coefficients negative. */
int scene_add_view_floor(struct scene *s, struct diag *d);

const char *scene_name(const struct scene *s);	/* the file name, for messages */
int scene_recursion(const struct scene *s);	/* >= 1; 1 means no reflection rays */
int scene_image_size(const struct scene *s);	/* the image is size x size */
size_t scene_shape_count(const struct scene *s);
bool scene_has_floor(const struct scene *s);	/* scene_add_view_floor's or --floor's */
const struct shape *scene_shape(const struct scene *s, size_t i);
/* The line of the file where object i's keyword is (for whitted explain),
 * recorded by the reader (scene_set_shape_line) where it reads the file
 * in one thread (every file but the biggest); 0 when unknown. */
int scene_shape_line(const struct scene *s, size_t i);
int scene_set_shape_line(struct scene *s, size_t i, int line, struct diag *d);
size_t scene_light_count(const struct scene *s);
const struct light *scene_light(const struct scene *s, size_t i);
/* hash_bytes of the scene text as read, so that region renders can tell
 * whether they come from the same file; 0 unless the reader was asked. */
uint64_t scene_source_hash(const struct scene *s);
/* A hash of the floor's textures (their sizes and pixels), so that tiles
 * rendered with other images under the same names are told apart; 0
 * without textures. */
uint64_t scene_floor_texture_hash(const struct scene *s);
/* The decoded texels (8-bit RGB) of the floor's texture over its white (k
 * 0) or black (k 1) cells, or NULL (no floor, or no texture there). */
struct image;
const struct image *scene_floor_texture(const struct scene *s, int k);

/* Builds the acceleration structure with up to `threads` threads (at least
 * 1; the structure is the same for any number); call after the last shape
 * is added and before rendering. */
int scene_prepare(struct scene *s, int threads, struct diag *d);
/* The hierarchy's size after scene_prepare, for --stats. */
size_t scene_hierarchy_nodes(const struct scene *s);
size_t scene_hierarchy_bytes(const struct scene *s);
/* Which box tests the hierarchy's walks use: "avx512", "avx2", "sse2" or
 * "portable" (see WHITTED_ISA in whitted(1)). */
const char *scene_hierarchy_walk(const struct scene *s);
/* How the renderer's packets of coherent rays go, for --stats: "no
 * packets", or e.g. "avx512 packets, a ray a lane". */
const char *scene_hierarchy_packets(const struct scene *s);
/* WHITTED_ISA's value when it is set to something other than sse2, avx2
 * or avx512 (and so caps nothing), for the programs to warn; else NULL. */
const char *scene_walk_cap_unknown(void);
/* Which set of instructions the vector kernels (packets, shading a lane a
 * ray) use, for --stats: "avx512", "avx2", "sse2" or "portable". */
const char *scene_kernels_isa(void);

#endif
