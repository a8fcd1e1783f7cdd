/* The bound on a pixel's tree of rays.  Without glass a hit spawns at
 * most one ray (its reflection), so a pixel's rays are a chain of at most
 * the recursion level; with glass a hit spawns two (the reflection and the
 * transmission) and the tree can have 2^255 rays at recursion 256.  Two
 * bounds keep its work finite, and neither changes an image:
 *
 * - The cut-off.  A ray's weight w is the product of the coefficients
 *   (kr, kt, or 1 under total internal reflection) along its path from the
 *   pixel; its colour is at most B (1 under --clamp level; under --clamp
 *   final B(d) = E (1 + K + ... + K^d) with d the levels left below it, E
 *   the most one hit adds and K the most its rays are multiplied by:
 *   scene_impl.h), and since the sum is monotone and its clamps
 *   1-Lipschitz, leaving the ray out lowers the pixel by at most w B.  In a
 *   scene with glass a ray with w B below the tree's `cut` is left out and
 *   w B added to `lost`.  The pixel's bytes are then those of every colour
 *   in [c, c + lost] (render_tree_again checks it, with a margin for
 *   rounding far wider than the sums' own); when they are not, the pixel
 *   is traced again with a cut 256 times finer, and with none at all
 *   after a few rounds.  So the bytes are always the whole tree's: the
 *   cut only saves the rays that could not change them.
 * - The budget.  The tree of one primary ray (a pixel's, or a sample's)
 *   may have at most `budget` rays; one that needs more stops the render
 *   with an error that names the pixel (render_image, --max-rays).  The
 *   budget is at least RT_MAX_RECURSION, so that a chain (no glass) never
 *   reaches it, on whichever path its pixel goes.
 *
 * The tree is also where the trace looks at the cancel flag: every
 * RENDER_TREE_CHUNK rays, so that a signal stops even one huge pixel at
 * once.  One tree a thread, reset for each pixel; the per-ray path
 * decrements a counter and compares a weight, and allocates nothing. */
#ifndef RT_RAY_TREE_H
#define RT_RAY_TREE_H

#include <limits.h>
#include <signal.h>
#include <stdbool.h>
#include <stdint.h>

#include "whitted/material.h"
#include "whitted/render.h"

struct scene;

/* Rays between two looks at the cancel flag and the budget. */
#define RENDER_TREE_CHUNK 4096
/* The first round's cut-off: 1/256 of a level of 8-bit output. */
#define RENDER_TREE_CUT (1.0 / (255.0 * 256.0))

enum render_tree_state {
	RENDER_TREE_GOING,
	RENDER_TREE_CANCELLED,	/* the cancel flag, or another thread's failure */
	RENDER_TREE_OVER,	/* the pixel needs more than the budget */
};

struct render_tree {
	struct ray_counts *counts;	/* may be NULL */
	double cut;			/* 0: every ray is traced */
	double first_cut;		/* a pixel's first round's: RENDER_TREE_CUT with glass, else 0 */
	double unit;			/* B's lower bound: 1 (--clamp level) or E */
	double lost;			/* the sum of w B over the rays left out */
	long left;			/* rays before render_tree_more looks again */
	uint64_t used;			/* rays handed out to `left` for this tree */
	uint64_t budget;		/* the most rays one primary ray's tree may have */
	const volatile sig_atomic_t *cancel;	/* may be NULL */
	const int *halt;		/* read atomically: non-zero stops; may be NULL */
	enum render_tree_state state;
	int x, y;			/* RENDER_TREE_OVER: the pixel */
};

/* A tree for renders of s with rs: `budget` rays a primary ray (0: the
 * default), the flags that stop it (either may be NULL). */
void render_tree_init(struct render_tree *t, const struct scene *s,
		      const struct render_settings *rs, uint64_t budget,
		      const volatile sig_atomic_t *cancel, const int *halt,
		      struct ray_counts *counts);

/* A new pixel: its first round's cut. */
static inline void render_tree_pixel(struct render_tree *t)
{
	t->cut = t->first_cut;
	t->lost = 0.0;
}

/* A new primary ray: its whole budget. */
static inline void render_tree_ray(struct render_tree *t)
{
	t->left = 0;
	t->used = 0;
}

/* A tree that never cuts, stops or looks at a flag (a chain of mirrors'
 * rays, which the recursion level bounds). */
static inline void render_tree_unbound(struct render_tree *t, struct ray_counts *counts)
{
	t->counts = counts;
	t->cut = t->first_cut = t->lost = 0.0;
	t->unit = 1.0;
	t->left = LONG_MAX;
	t->used = 0;
	t->budget = UINT64_MAX;
	t->cancel = NULL;
	t->halt = NULL;
	t->state = RENDER_TREE_GOING;
	t->x = t->y = -1;
}

/* Whether the render goes on: false once the tree is stopped, or the
 * cancel flag or another thread's failure stops it now (for the loops
 * whose rays the tree does not count: packets). */
static inline bool render_tree_poll(struct render_tree *t)
{
	if (t->state != RENDER_TREE_GOING)
		return false;
	if ((t->cancel && *t->cancel) || (t->halt && __atomic_load_n(t->halt, __ATOMIC_RELAXED))) {
		t->state = RENDER_TREE_CANCELLED;
		return false;
	}
	return true;
}

/* Called when `left` has run out: whether the trace goes on (then `left`
 * is refilled and one ray taken from it); false once it is cancelled or
 * over its budget, and from then on. */
bool render_tree_more(struct render_tree *t);

/* One ray more for the tree: false when it must not be traced (the trace
 * is stopping). */
static inline bool render_tree_take(struct render_tree *t)
{
	return --t->left >= 0 || render_tree_more(t);
}

/* The slow half of render_tree_cuts, for rays whose weight is below the
 * cut: computes B and decides. */
bool render_tree_cut_slow(struct render_tree *t, const struct scene *s,
			  const struct render_settings *rs, double w, int level);
/* render_tree_cuts' answer without its effect on `lost`: for the packets,
 * which leave out of a packet the reflections the shading will cut. */
bool render_tree_would_cut(const struct render_tree *t, const struct scene *s,
			   const struct render_settings *rs, double w, int level);

/* Whether a ray of weight w at `level` is left out (then its bound is
 * added to `lost`): never when the cut is 0, as it is without glass. */
static inline bool render_tree_cuts(struct render_tree *t, const struct scene *s,
				    const struct render_settings *rs, double w, int level)
{
	return w * t->unit < t->cut && render_tree_cut_slow(t, s, rs, w, level);
}

/* After a round of the pixel whose colour is c (a sample's, or the mean
 * of n samples, whose lost bounds were summed): whether to trace it again
 * (with a finer cut, set here) because what was left out could change its
 * bytes.  Resets `lost` for the next round. */
bool render_tree_again_slow(struct render_tree *t, struct color c, int n);
static inline bool render_tree_again(struct render_tree *t, struct color c, int n)
{
	return t->lost != 0.0 && render_tree_again_slow(t, c, n);
}

/* render_trace for one round of a pixel, with its tree (shade.c): the
 * colour of the rays the tree takes, black where it stops; r is a primary
 * ray, with the whole budget. */
struct color render_trace_tree(const struct scene *s, const struct render_settings *rs,
			       const struct ray *r, int level, struct render_tree *tree);

#endif
