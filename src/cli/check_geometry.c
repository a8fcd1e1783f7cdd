/* What the check reads off the pictures themselves: how far one camera's
 * view moves from another's and how near the submission comes to each
 * (whether a found camera is another one, and whether it shows any
 * object), and whether a submission's floor is textured where the
 * reference's is a plain checker (then judged without it). */
#include <math.h>
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

#include "base/alloc.h"

#include "cli/check.h"

/* How far camera b shows what camera a shows at its pixels, in pixels:
 * the hit points of a grid of a's primary rays (directions for the
 * background) seen through b; the share CHECK_MOVED_QUANTILE of them
 * move at most that far.  A half-pixel shift (rays through the pixels'
 * corners) is no other camera. */
#define CHECK_MOVED_GRID 24
#define CHECK_MOVED_QUANTILE 0.5

double check_displacement(const struct check_view *a, const struct check_view *b)
{
	double moves[CHECK_MOVED_GRID * CHECK_MOVED_GRID];
	int n = 0, i, j, k;

	for (j = 0; j < CHECK_MOVED_GRID; j++)
		for (i = 0; i < CHECK_MOVED_GRID; i++) {
			int px = (int)((i + 0.5) * a->camera.width / CHECK_MOVED_GRID);
			int py = (int)((j + 0.5) * a->camera.height / CHECK_MOVED_GRID);
			struct ray r = camera_ray(&a->camera, px, py);
			struct vec3 d;
			double t = INFINITY, zf, u, v;
			if (grade_primary_hit(&a->job, &r, &t))
				d = vec3_sub(vec3_add_scaled(r.origin, r.dir, t), b->camera.eye);
			else
				d = r.dir;
			zf = camera_project(&b->camera, d, &u, &v);
			moves[n++] = zf > 0.0 ? hypot(u - 0.5 - px, v - 0.5 - py) : INFINITY;
		}
	for (i = 1; i < n; i++)
		for (k = i; k > 0 && moves[k - 1] > moves[k]; k--) {
			double t = moves[k];
			moves[k] = moves[k - 1];
			moves[k - 1] = t;
		}
	return moves[(int)(CHECK_MOVED_QUANTILE * (n - 1))];
}

/* Whether the submission's floor is textured (the Jan 2023 bonus task:
 * an image over each cell) where the reference's is a plain checker: over
 * the floor's pixels inside a cell (the reference smooth around them), the
 * submission's neighbours differ on average by far more than the
 * reference's do. */
#define CHECK_TEXTURE_MIN_PIXELS 2000
#define CHECK_TEXTURE_DENSE 0.2

static bool check_noisy(const struct image *img, size_t i, int w)
{
	const int step[4] = { 1, -1, w, -w };
	int k, c;

	for (k = 0; k < 4; k++)
		for (c = 0; c < 3; c++)
			if (abs((int)img->pixels[3 * i + c] - (int)img->pixels[3 * (size_t)((long)i + step[k]) + c]) > 8)
				return true;
	return false;
}

bool check_floor_textured(const struct image *ref, const struct image *sub, const int32_t *ids)
{
	const int w = ref->width, h = ref->height;
	long n = 0, dense = 0;
	int x, y, i, j;

	/* Pixels of the floor inside a cell of the reference (it is smooth
	 * around them): in a textured floor most lie in patches where nearly
	 * every pixel differs from a neighbour; a plain checker's cells,
	 * even seen from another camera, are flat but for the thin lines
	 * of their edges. */
	for (y = 2; y + 2 < h; y++)
		for (x = 2; x + 2 < w; x++) {
			size_t p = (size_t)y * (size_t)w + (size_t)x;
			int noisy = 0;
			if (ids[p] != GRADE_ID_FLOOR || check_noisy(ref, p, w))
				continue;
			n++;
			for (j = -1; j <= 1; j++)
				for (i = -1; i <= 1; i++)
					noisy += check_noisy(sub, (size_t)((long)p + j * w + i), w);
			dense += noisy >= 7;
		}
	return n >= CHECK_TEXTURE_MIN_PIXELS && (double)dense / (double)n > CHECK_TEXTURE_DENSE;
}

/* The figures of sub against the reference at view v with the fit's
 * cause (and its second) in its place (RT_CAUSE_NONE: the reference
 * itself), on the pixels skip does not mark. */
static int check_figures_with(const struct check_view *v, const struct grade_fit *fit,
			      const struct image *sub, const uint8_t *skip,
			      struct grade_figures *fig, struct diag *d)
{
	struct grade_rank r;
	struct image img;
	int rc;

	if (fit->cause == RT_CAUSE_NONE) {
		grade_figures_skipping(&v->image, sub, skip, fig);
		return 0;
	}
	memset(&r, 0, sizeof(r));
	r.cause = fit->cause;
	r.form = fit->form;
	r.also = fit->also;
	r.also_form = fit->also_form;
	if ((rc = grade_cause_image(&v->job, &v->image, &r, &img, d)) < 0)
		return rc;
	grade_figures_skipping(&img, sub, skip, fig);
	image_free(&img);
	return 0;
}

int check_compare_cameras(const struct check_view *a, const struct check_view *b,
			  const struct image *sub, const struct grade_fit *fit,
			  struct grade_figures *fa, struct grade_figures *fb, struct diag *d)
{
	size_t total = (size_t)sub->width * (size_t)sub->height, i;
	uint8_t *skip = rt_calloc(total, 1);
	int rc;

	if (!skip)
		return diag_fail(d, RT_E_NOMEM, "out of memory for the ties");
	for (i = 0; i < total; i++)
		skip[i] = (a->ties && a->ties[i]) || (b->ties && b->ties[i]);
	rc = check_figures_with(a, fit, sub, skip, fa, d);
	if (rc == 0)
		rc = check_figures_with(b, fit, sub, skip, fb, d);
	rt_free(skip);
	return rc;
}

/* Whether sub's colour at pixel (x, y) is more than CHECK_TIE_OUTSIDE
 * levels outside the range of the reference's 3 x 3 neighbourhood in a
 * channel: no camera within a pixel gives it. */
#define CHECK_TIE_OUTSIDE 8

static bool check_outside(const struct image *ref, const struct image *sub, int x, int y)
{
	const int w = ref->width, h = ref->height;
	const size_t k = (size_t)y * (size_t)w + (size_t)x;
	int i, j, c;

	for (c = 0; c < 3; c++) {
		int lo = 255, hi = 0, s = sub->pixels[3 * k + c];
		for (j = -1; j <= 1; j++)
			for (i = -1; i <= 1; i++) {
				int q;
				if (x + i < 0 || x + i >= w || y + j < 0 || y + j >= h)
					continue;
				q = ref->pixels[3 * ((size_t)(y + j) * (size_t)w + (size_t)(x + i)) + c];
				lo = q < lo ? q : lo;
				hi = q > hi ? q : hi;
			}
		if (s < lo - CHECK_TIE_OUTSIDE || s > hi + CHECK_TIE_OUTSIDE)
			return true;
	}
	return false;
}

/* A camera known within a pixel moves the colours of a tie within its
 * neighbourhood's range: tie pixels whose submitted colour is outside it
 * are differences, not the camera's (a white highlight where the
 * reference's is coloured, on a small sphere whose highlight is edges all
 * over).  When more of them than the gate allows off by more than 8
 * levels (on the moved set: 50 to 171 of 65536 pixels for a white
 * highlight, 1 to 5 for correct renders a found camera matches), they
 * leave v's ties; returns how many left. */
long check_ties_outside(struct check_view *v, const struct image *sub)
{
	const int w = v->image.width, h = v->image.height;
	long n = 0;
	int x, y, pass;

	if (sub->width != w || sub->height != h)
		return 0;
	for (pass = 0; pass < 2; pass++) {
		for (y = 0; y < h; y++)
			for (x = 0; x < w; x++) {
				size_t k = (size_t)y * (size_t)w + (size_t)x;
				if (!v->ties[k] || !check_outside(&v->image, sub, x, y))
					continue;
				if (pass == 0)
					n++;
				else
					v->ties[k] = 0;
			}
		if (pass == 0 && (double)n <= RT_GRADE_MAX_OFF8 * (double)w * (double)h)
			return 0;
	}
	v->n_ties -= n;
	return n;
}

/* The fit's precision, in pixels: its ties allow for that much. */
#define CHECK_FIT_PIXELS 0.35

int check_found_view(const struct check_reference *ref, const struct check_view *v,
		     const struct camera_params *p, struct check_view *out, struct diag *d)
{
	double angle = CHECK_FIT_PIXELS * 2.0 * tan(p->fov_deg * 3.14159265358979323846 / 360.0) /
		       v->camera.height;

	return check_view_make(ref, p, v->camera.width, v->camera.height, angle, out, d);
}

/* A quarter turn about the vertical axis through the origin maps the
 * floor's checkerboard (centred there, or counted from there) onto itself
 * with its tiles swapped: cell (i, j) goes to (-j - 1, i) or (j, -i - 1)
 * less a whole number, and i + j's parity flips.  A scene whose objects
 * look the same turned (sadathossain01's: all inside a sphere about the
 * origin) then shows, from the camera found turned back, the tiles
 * swapped to the bit: a correct image was called a mistake there.  Both
 * are exact; the turned camera is taken only when it is nearer the given
 * one (students move the camera a few key presses from where it starts):
 * an image with the tiles swapped stays that from near the start. */
static struct vec3 check_turn(struct vec3 a, double s)
{
	return vec3_make(-s * a.y, s * a.x, a.z);
}

int check_quarter_turn(const struct check_reference *ref, struct check_view *found,
		       const struct image *sub, struct grade_figures *fig, struct diag *d)
{
	double s;
	int rc;

	for (s = -1.0; s <= 1.0; s += 2.0) {
		struct camera_params p = found->params;
		struct check_view v;
		struct grade_figures f;
		p.eye = check_turn(p.eye, s);
		p.look = check_turn(p.look, s);
		p.up = check_turn(p.up, s);
		if (vec3_length(vec3_sub(p.eye, ref->params.eye)) >=
		    vec3_length(vec3_sub(found->params.eye, ref->params.eye)))
			continue;
		if ((rc = check_found_view(ref, found, &p, &v, d)) < 0)
			return rc;
		grade_figures_skipping(&v.image, sub, v.ties, &f);
		if (f.match) {
			check_view_free(found);
			check_view_move(found, &v);
			*fig = f;
			return 0;
		}
		check_view_free(&v);
	}
	return 0;
}

/* A camera found counts only where it shows at least this share of its
 * pixels on the scene's objects: a view of the floor and the sky alone
 * looks the same from anywhere at its height and tilt (the checker
 * repeats), and a dark image of anything fits such a view (two real
 * renders were explained by a view of the bare floor from a thousand
 * units away). */
#define CHECK_MOVED_OBJECT_SHARE 0.005

int check_shows_objects(const struct scene *scene, const struct check_view *v, bool *shows,
			struct diag *d)
{
	size_t total = (size_t)v->camera.width * (size_t)v->camera.height, i, seen = 0;
	int32_t *ids;
	int rc;

	*shows = true;
	if (scene_shape_count(scene) <= (scene_has_floor(scene) ? 1u : 0u))
		return 0;
	if (!(ids = rt_reallocarray(NULL, total, sizeof(*ids))))
		return diag_fail(d, RT_E_NOMEM, "out of memory for the object ids");
	if ((rc = grade_object_ids(&v->job, ids, d)) == 0) {
		for (i = 0; i < total; i++)
			seen += ids[i] >= 0;
		*shows = (double)seen >= CHECK_MOVED_OBJECT_SHARE * (double)total;
	}
	rt_free(ids);
	return rc;
}

int check_judged(const struct check_view *v, struct check_result *res, struct image *judged,
		 struct diag *d)
{
	size_t total = (size_t)v->camera.width * (size_t)v->camera.height, i;
	int32_t *ids = rt_reallocarray(NULL, total, sizeof(*ids));
	int rc;

	memset(judged, 0, sizeof(*judged));
	if (!ids)
		return diag_fail(d, RT_E_NOMEM, "out of memory for the object ids");
	if ((rc = grade_object_ids(&v->job, ids, d)) < 0)
		goto out;
	/* A floor the fit found another shape of is a checker, however fine
	 * its cells look at the image's size. */
	res->floor_textured = !(res->fitted && (res->fit.cause == RT_CAUSE_FLOOR_SIZE ||
						res->fit.cause == RT_CAUSE_FLOOR_HORIZON)) &&
			      check_floor_textured(&v->image, &res->image, ids);
	if (!res->floor_textured)
		goto out;
	if ((rc = image_alloc(judged, res->image.width, res->image.height, d)) < 0)
		goto out;
	memcpy(judged->pixels, res->image.pixels, total * 3);
	for (i = 0; i < total; i++)
		if (ids[i] == GRADE_ID_FLOOR)
			memcpy(judged->pixels + 3 * i, v->image.pixels + 3 * i, 3);
out:
	rt_free(ids);
	return rc;
}
