/* Why a pixel has its colour: the tree of rays that the Whitted sum of
 * render/shade.c traces for it (scene-format.md, "Shading"), each ray with
 * the object it hits, the point, the normal, every light's ambient, diffuse
 * and specular terms and its shadow ray, and the reflected and refracted
 * rays level by level, down to the clamped sum and the 8-bit value, which
 * is the rendered image's pixel (the same operations in the same order;
 * test_explain checks it on every dialect).  For `whitted explain` and the
 * web page's click on a pixel, and for a student comparing their own
 * tracer's numbers with these. */
#ifndef RT_EXPLAIN_H
#define RT_EXPLAIN_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "camera.h"
#include "diag.h"
#include "material.h"
#include "ray.h"
#include "render.h"
#include "scene.h"
#include "vec3.h"

/* What a light does at a hit. */
enum explain_light_state {
	EXPLAIN_LIT,		/* its terms are added */
	EXPLAIN_AT_POINT,	/* the light is at the point (distance <= the offset) */
	EXPLAIN_BEHIND,		/* N.L <= 0: the surface faces away from it */
	EXPLAIN_OUTSIDE_CONE,	/* a spotlight whose cone does not reach the point */
	EXPLAIN_SHADOWED,	/* its shadow ray is blocked */
};

/* An object of the scene: its index in the file (1-based; 0 for the
 * floor, which no file lists), its keyword, the line its keyword is on
 * (0 when the scene does not record it). */
struct explain_object {
	long index;
	const char *keyword;
	int line;
	bool floor;
};

struct explain_light {
	enum explain_light_state state;
	struct vec3 l;		/* the unit direction to the light */
	double distance, n_dot_l, r_dot_l;
	double attenuation;	/* exp(-d^2 falloff), 1 without a falloff */
	struct explain_object blocker;	/* EXPLAIN_SHADOWED: the nearest blocker */
	bool blocker_known;
	/* Lc C kd (N.L) a and Lc S ks max(R.L, 0)^shininess a (S the
	 * highlight's colour), and the term the sum adds (0 unless lit). */
	struct color diffuse, specular, term;
};

enum explain_ray_kind { EXPLAIN_PRIMARY, EXPLAIN_REFLECTED, EXPLAIN_REFRACTED };

/* One ray of the tree. */
struct explain_ray {
	enum explain_ray_kind kind;
	int sample;		/* which of the pixel's samples (0 without --samples) */
	long parent;		/* the ray that spawned it, -1 for a primary ray */
	int level;		/* 1 for a primary ray */
	double weight;		/* its coefficient in the pixel: the product of kr, kt */
	struct ray ray;
	bool hit;
	/* The rest only when hit. */
	struct explain_object object;
	double t;
	struct vec3 point, normal;	/* the normal turned to face the ray */
	bool turned;			/* the surface's normal faced away and was turned */
	struct color surface;		/* C, the colour at the point */
	bool highlight_own;		/* a textured floor: the highlight is the cell's colour */
	struct color highlight;		/* S, the highlight's colour when highlight_own */
	struct material mat;
	struct color ambient;		/* ka C */
	size_t first_light;		/* its lights in explanation.lights[first_light ...] */
	size_t n_lights;
	struct color direct;		/* the lights' terms summed */
	long reflected, refracted;	/* the child rays, or -1 */
	double k_reflected;		/* kr, or 1 under total internal reflection */
	bool total_internal_reflection;
	double eta;			/* n1 / n2 of the refraction (glass only) */
	struct color reflected_color, refracted_color;	/* what those rays see */
	struct color sum;		/* before this level's clamp */
	struct color color;		/* what this ray returns */
};

struct explanation {
	int x, y;			/* the pixel */
	int width, height;		/* the image */
	struct render_settings settings;
	int samples;			/* 1, or N of --samples (N x N rays) */
	struct explain_ray *rays;	/* in the order traced, each sample's tree in turn */
	size_t n_rays;
	struct explain_light *lights;
	size_t n_lights;
	struct color *sample_colors;	/* each sample's colour (samples x samples) */
	struct color color;		/* the pixel's colour before the final clamp: the mean */
	struct color clamped;
	uint8_t value[3];		/* round(255 clamp(color)): the image's pixel */
};

/* The most rays an explanation records: a pixel whose tree is larger
 * (glass at a high recursion) is refused with a message. */
#define RT_EXPLAIN_MAX_RAYS 65536

/* Explains pixel (x, y) of the image cam sees of the prepared scene s,
 * rendered with rs and `samples` (0 or 1: one ray a pixel).  Returns 0
 * with *out filled (free with explanation_free), or a negative status with
 * d filled (RT_E_INVALID: the pixel is outside the image; RT_E_RANGE: the
 * tree is larger than RT_EXPLAIN_MAX_RAYS; RT_E_NOMEM). */
int explain_pixel(const struct scene *s, const struct camera *cam,
		  const struct render_settings *rs, int samples, int x, int y,
		  struct explanation *out, struct diag *d);
void explanation_free(struct explanation *e);

/* The names of the light states and the ray kinds ("lit", "shadowed",
 * "primary", ...), for the programs' text and JSON. */
const char *explain_light_state_name(enum explain_light_state s);
const char *explain_ray_kind_name(enum explain_ray_kind k);

#endif
