/* The bound on a pixel's tree of rays (ray_tree.h): the budget and the
 * cancel flag looked at every RENDER_TREE_CHUNK rays, the cut-off's bound
 * B, and the check that what a round left out cannot change the pixel's
 * bytes. */
#include <math.h>

#include "render/ray_tree.h"
#include "render/shade_math.h"
#include "scene/scene_impl.h"

/* Below this the next round has no cut at all: 2^-40 of a level is far
 * below any difference the rounding margin lets through. */
#define RENDER_TREE_CUT_LAST 1e-12
/* The margin for rounding, relative to max(1, |channel|): the sums are of
 * non-negative terms, each round's rays are the same rays with the same
 * arithmetic, and a sum of n non-negative terms is within n 2^-53 of its
 * exact value; a tree of 2^22 rays, each a few hundred operations deep,
 * stays below 1e-9. */
#define RENDER_TREE_MARGIN 1e-9

void render_tree_init(struct render_tree *t, const struct scene *s,
		      const struct render_settings *rs, uint64_t budget,
		      const volatile sig_atomic_t *cancel, const int *halt,
		      struct ray_counts *counts)
{
	t->counts = counts;
	t->budget = budget ? budget : RT_DEFAULT_MAX_RAYS;
	t->cancel = cancel;
	t->halt = halt;
	t->first_cut = s->glass ? RENDER_TREE_CUT : 0.0;
	t->unit = rs->clamp == RT_CLAMP_LEVEL ? 1.0 : s->tree_emit;
	t->state = RENDER_TREE_GOING;
	t->x = t->y = -1;
	render_tree_pixel(t);
}

bool render_tree_more(struct render_tree *t)
{
	uint64_t n;

	t->left = 0;
	if (!render_tree_poll(t))
		return false;
	if (t->used >= t->budget) {
		t->state = RENDER_TREE_OVER;
		return false;
	}
	n = t->budget - t->used < RENDER_TREE_CHUNK ? t->budget - t->used : RENDER_TREE_CHUNK;
	t->used += n;
	t->left = (long)n - 1;
	return true;
}

/* B(d): the most a ray's colour can be with d levels below it, clamped at
 * every level (1) or only at the end: E (1 + K + ... + K^d), infinite
 * when that overflows (the ray is then never left out). */
static double render_tree_bound(const struct scene *s, const struct render_settings *rs, int d)
{
	double k = s->tree_gain, e = s->tree_emit;

	if (rs->clamp == RT_CLAMP_LEVEL)
		return 1.0;
	if (d < 0)
		d = 0;
	if (k == 1.0)
		return e * (d + 1);
	return e * ((pow(k, d + 1) - 1.0) / (k - 1.0));
}

bool render_tree_cut_slow(struct render_tree *t, const struct scene *s,
			  const struct render_settings *rs, double w, int level)
{
	double b = w * render_tree_bound(s, rs, rs->recursion - level);

	if (!(b < t->cut))
		return false;
	t->lost += b;
	return true;
}

bool render_tree_would_cut(const struct render_tree *t, const struct scene *s,
			   const struct render_settings *rs, double w, int level)
{
	return w * t->unit < t->cut && w * render_tree_bound(s, rs, rs->recursion - level) < t->cut;
}

/* Whether v and every value up to lost above it give one byte. */
static bool render_tree_channel_decided(double v, double lost)
{
	double margin = RENDER_TREE_MARGIN * (fabs(v) > 1.0 ? fabs(v) : 1.0);

	return render_channel(render_clamp01(v - margin)) ==
	       render_channel(render_clamp01(v + lost + margin));
}

bool render_tree_again_slow(struct render_tree *t, struct color c, int n)
{
	double lost = t->lost / (n > 1 ? n : 1);

	t->lost = 0.0;
	if (lost == 0.0 || t->state != RENDER_TREE_GOING)
		return false;
	if (render_tree_channel_decided(c.r, lost) && render_tree_channel_decided(c.g, lost) &&
	    render_tree_channel_decided(c.b, lost))
		return false;
	t->cut = t->cut > RENDER_TREE_CUT_LAST ? t->cut / 256.0 : 0.0;
	return true;
}
