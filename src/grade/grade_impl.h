/* The grade module's parts: the causes' forms, the transforms and the
 * renders of the causes. */
#ifndef RT_GRADE_IMPL_H
#define RT_GRADE_IMPL_H

#include <stdint.h>

#include "render/shade_rules.h"
#include "whitted/grade.h"

/* What a render's pixel (x, y) is taken from: the reference's pixel
 * mirrored, flipped or transposed, and its red and blue swapped. */
enum grade_map {
	GRADE_MAP_MIRROR = 1u << 0,
	GRADE_MAP_FLIP = 1u << 1,
	GRADE_MAP_TRANSPOSE = 1u << 2,
	GRADE_MAP_RED_BLUE = 1u << 3,
};

/* How a cause renders in one of its forms: broken rules, other settings,
 * another floor, rays through a corner of the pixel, and what becomes of
 * the colour (gamma, bytes that wrap) and of the pixel's place (map). */
struct grade_variant {
	unsigned rules;
	struct render_settings settings;
	bool use_rules;
	bool corner;			/* rays through (x + cx, y + cy), not the centre */
	bool wrap;			/* the bytes wrap round instead of saturating */
	double cx, cy;
	bool other_floor;		/* floor in place of the scene's */
	struct shade_floor floor;
	unsigned floor_changes;		/* GRADE_FLOOR_*: what floor changes of the scene's */
	int gamma;			/* 0 none, 1 the sRGB curve, 2 c^(1/2.2) */
	unsigned map;			/* enum grade_map */
};

/* The parts of the scene's floor a floor cause changes: two causes that
 * change different parts make one floor (a student's floor can be both
 * narrower and of smaller cells). */
enum grade_floor_change {
	GRADE_FLOOR_HALF = 1u << 0,	/* its width */
	GRADE_FLOOR_CELL = 1u << 1,	/* its cells' size */
	GRADE_FLOOR_ORIGIN = 1u << 2,	/* where the cells are counted from */
	GRADE_FLOOR_CENTRE = 1u << 3,	/* where it lies */
	GRADE_FLOOR_FINISH = 1u << 4,	/* its coefficients and shininess */
};

/* The most forms a cause has. */
#define GRADE_VARIANTS 8
/* A bound on the renders of one ranking: far above what the causes'
 * table makes (about 53 forms of singles, the pairs with the floors' and
 * the finish's sweeps, 6 in full: about 155 at most). */
#define GRADE_MAX_RENDERS (RT_CAUSE_COUNT * (GRADE_VARIANTS + 1) + GRADE_MAX_PAIRS)

/* The render of form `form` of cause c into v; false when the cause has
 * no such form for this job (or the form would not change the image). */
bool grade_variant_of(const struct grade_job *job, enum grade_cause c, int form,
		      struct grade_variant *v);
/* The render of the reference itself. */
void grade_variant_plain(const struct grade_job *job, struct grade_variant *v);
/* Both causes' forms at once in out; false when they cannot be
 * combined (two recursion levels, two floors, ...). */
bool grade_variant_combine(const struct grade_variant *a, const struct grade_variant *b,
			   struct grade_variant *out);

/* The map of a transform cause. */
unsigned grade_cause_map(enum grade_cause c);

/* The reference transformed as map says (enum grade_map). */
int grade_transform_map(const struct image *ref, unsigned map, struct image *out, struct diag *d);

/* The colour the variant's program traces along r (its rules, settings
 * and floor), before it is stored; and that colour as it encodes it
 * (gamma), before the bytes.  The one place a cause's colour is made. */
struct color grade_variant_trace(const struct grade_job *job, const struct grade_variant *v,
				 const struct ray *r);
struct color grade_variant_encode(const struct grade_variant *v, struct color c);
/* Whether the variant traces as the reference does (NULL, or a mistake
 * made only when the colour is stored, gamma): its rays can then go
 * through the renderer's own paths, packets included, and the colours be
 * encoded after. */
bool grade_variant_traces_plain(const struct grade_job *job, const struct grade_variant *v);

/* Renders, for each of the n variants, the listed pixels (indices y *
 * width + x; NULL: every pixel) into imgs[i], which have the camera's
 * size, and when timgs is not NULL the same colours converted by
 * truncation into timgs[i] (one trace, both conversions); threads share
 * chunks of the list of every render. */
int grade_render_variants(const struct grade_job *job, const struct grade_variant *variants,
			  struct image *imgs, struct image *timgs, size_t n,
			  const uint32_t *pixels, size_t n_pixels, struct diag *d);

#endif
