/* The reference of compare and grade: the scene, and its render at a
 * camera and a size (a view) with the pixels where either colour is
 * right (ties). */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/alloc.h"
#include "cli/check.h"
#include "cli/cli.h"
#include "cli/tool.h"

/* The angle (radians) the ties of the given camera allow for: far below a
 * pixel, far above another renderer's rounding. */
#define CHECK_TIE_ANGLE 1e-7

/* A camera found is known to a fraction of a pixel: every pixel whose
 * colour changes by more than 8 levels within a pixel of it (an edge, a
 * checkerboard finer than the pixels towards the horizon, whose colours
 * any error of the camera shuffles) is a tie too. */
#define CHECK_EDGE_TIES_MAX 0.3

/* Whether pixel (x, y) of v's reference differs by more than 8 levels
 * from one of its neighbours, and into *ties how many of those
 * neighbours are ties, of *n. */
static bool check_edge_at(const struct check_view *v, int x, int y, int *ties, int *n)
{
	const int w = v->image.width, h = v->image.height;
	const uint8_t *p = v->image.pixels;
	const size_t k = (size_t)y * (size_t)w + (size_t)x;
	bool edge = false;
	int i, j, c;

	*ties = *n = 0;
	for (j = -1; j <= 1; j++)
		for (i = -1; i <= 1; i++) {
			size_t q;
			if ((i == 0 && j == 0) || x + i < 0 || x + i >= w || y + j < 0 || y + j >= h)
				continue;
			q = (size_t)(y + j) * (size_t)w + (size_t)(x + i);
			*ties += v->ties[q] != 0;
			(*n)++;
			for (c = 0; c < 3 && !edge; c++)
				edge = abs((int)p[3 * k + c] - (int)p[3 * q + c]) > 8;
		}
	return edge;
}

/* Where edges are most of the image (a small one), what is left would be
 * too little to judge the shading by: then only the edges at least half
 * of whose neighbours are ties already (the chequer aliased towards the
 * horizon, a reflection's rim), while the ties stay within
 * CHECK_EDGE_TIES_AMONG_MAX of the image.  There the camera's nudges (six
 * of them) leave a pixel unchanged by chance: a correct render at a
 * camera found to 0.004 pixels (rafid013, 256 px, a view from above the
 * objects' side) still had 10 such pixels off by 26 levels of 48464,
 * 0.0206%, where the gate allows 0.02%; at 160 px the ties come to 37%.
 * Not beyond: at 64 px, where the ties came to 63%, a reflection level
 * too few was called a match. */
#define CHECK_EDGE_TIES_AMONG_MAX 0.4
static void check_edge_ties(struct check_view *v)
{
	const int w = v->image.width, h = v->image.height;
	uint8_t *edges = rt_calloc((size_t)w * (size_t)h, 1);
	long n = 0, among_ties = 0;
	bool all;
	size_t k;
	int x, y;

	if (!edges)
		return;
	for (y = 0; y < h; y++)
		for (x = 0; x < w; x++) {
			int ties, around;
			k = (size_t)y * (size_t)w + (size_t)x;
			if (v->ties[k] || !check_edge_at(v, x, y, &ties, &around))
				continue;
			edges[k] = 2 * ties >= around ? 2 : 1;
			n++;
			among_ties += edges[k] == 2;
		}
	all = (double)(v->n_ties + n) <= CHECK_EDGE_TIES_MAX * (double)w * (double)h;
	if (all || (double)(v->n_ties + among_ties) <= CHECK_EDGE_TIES_AMONG_MAX * (double)w * (double)h) {
		for (k = 0; k < (size_t)w * (size_t)h; k++)
			v->ties[k] |= all ? edges[k] != 0 : edges[k] == 2;
		v->n_ties += all ? n : among_ties;
	}
	rt_free(edges);
}

int check_view_make(const struct check_reference *ref, const struct camera_params *p, int width,
		    int height, double angle, struct check_view *v, struct diag *d)
{
	int rc;

	memset(v, 0, sizeof(*v));
	v->params = *p;
	v->tie_angle = angle;
	if ((rc = camera_init_rect(&v->camera, p, width, height, d)) < 0)
		return rc;
	v->job = ref->base;
	v->job.camera = &v->camera;
	if ((rc = grade_render_reference(&v->job, &v->image, d)) < 0)
		return rc;
	if (!(v->ties = rt_calloc((size_t)width * (size_t)height, 1))) {
		check_view_free(v);
		return diag_fail(d, RT_E_NOMEM, "out of memory for the reference's ties");
	}
	if ((rc = grade_tie_mask(&v->job, &v->image, angle, v->ties, &v->n_ties, d)) < 0) {
		check_view_free(v);
		return rc;
	}
	if (angle > CHECK_TIE_ANGLE)
		check_edge_ties(v);
	return 0;
}

void check_view_move(struct check_view *to, struct check_view *from)
{
	*to = *from;
	to->job.camera = &to->camera;
	memset(from, 0, sizeof(*from));
}

void check_view_free(struct check_view *v)
{
	image_free(&v->image);
	image_free(&v->truncated);
	rt_free(v->ties);
	memset(v, 0, sizeof(*v));
}

/* The notes of a scene's reading, held until it is known which reading
 * stands (the strict one's would repeat the other's). */
#define CHECK_HELD_NOTES 16
struct check_notes {
	struct diag note[CHECK_HELD_NOTES];
	int n, dropped;
};

static void check_hold_note(void *ctx, const struct diag *note)
{
	struct check_notes *h = ctx;

	if (h->n < CHECK_HELD_NOTES)
		h->note[h->n++] = *note;
	else
		h->dropped++;
}

static void check_print_notes(const struct check_notes *h, bool quiet)
{
	int i;

	for (i = 0; !quiet && i < h->n; i++)
		tool_print_diag(&h->note[i], "note");
	if (!quiet && h->dropped > 0)
		fprintf(stderr, "(%d more notes)\n", h->dropped);
}

/* The scene as the options say; a file the strict reading refuses (an
 * error in the file itself) is read as the course's count-driven programs
 * read it, which the student's program did to render the image: stop
 * after the last section's count.  Said with the strict reading's error
 * as a note; when that reading fails too, the error is the strict one's. */
static int check_scene_load(struct check_options *o, struct check_reference *ref,
			    struct camera *cam, struct diag *d)
{
	/* Static: 16 diagnostics of a path's length each are 74 KB a reading,
	 * too much for a stack; the programs load one scene at a time. */
	static struct check_notes strict_notes, lenient_notes;
	struct diag lenient_diag;
	int rc;

	memset(&strict_notes, 0, sizeof(strict_notes));
	ref->lenient = o->scene.read.lenient;
	rc = cli_scene_load(&o->scene, o->scene.path, check_hold_note, &strict_notes, &ref->scene,
			    cam, d);
	if (rc != -RT_E_SYNTAX || !o->scene.path || o->scene.read.lenient ||
	    strcmp(d->file, o->scene.path) != 0) {
		check_print_notes(&strict_notes, o->scene.quiet);
		return rc;
	}
	memset(&lenient_notes, 0, sizeof(lenient_notes));
	diag_clear(&lenient_diag);
	o->scene.read.lenient = true;
	rc = cli_scene_load(&o->scene, o->scene.path, check_hold_note, &lenient_notes, &ref->scene,
			    cam, &lenient_diag);
	o->scene.read.lenient = false;
	if (rc < 0) {
		check_print_notes(&strict_notes, o->scene.quiet);
		return -RT_E_SYNTAX;
	}
	ref->lenient = true;
	if (!o->scene.quiet) {
		tool_print_diag(d, "note");
		fprintf(stderr, "%s: note: the strict reading refuses the file; read as the course's "
				"count-driven programs read it (--lenient)\n",
			o->scene.path);
	}
	check_print_notes(&lenient_notes, o->scene.quiet);
	diag_clear(d);
	return 0;
}

int check_reference_make(struct check_options *o, struct check_reference *ref)
{
	struct camera cam;
	struct diag d;
	int rc;

	memset(ref, 0, sizeof(*ref));
	diag_clear(&d);
	rc = check_scene_load(o, ref, &cam, &d);
	if (rc == 0)
		rc = scene_prepare(ref->scene, o->threads, &d);
	if (rc == 0) {
		ref->params = o->scene.camera;
		ref->camera_given = o->scene.camera_given || o->scene.fov_given;
		ref->fit = !o->no_fit;
		ref->base.scene = ref->scene;
		/* The render options that reach render_settings, and how many
		 * rays a pixel (a new one is copied here too). */
		ref->base.settings.recursion = scene_recursion(ref->scene);
		ref->base.settings.clamp = o->scene.clamp;
		ref->base.samples = o->scene.samples;
		ref->base.threads = o->threads;
		ref->base.cancel = &cli_cancelled;
		rc = check_view_make(ref, &ref->params, scene_image_size(ref->scene),
				     scene_image_size(ref->scene), CHECK_TIE_ANGLE, &ref->view, &d);
	}
	if (rc < 0) {
		tool_print_diag(&d, "error");
		check_reference_free(ref);
		if (rc == -RT_E_INTERRUPTED || cli_cancelled)
			return TOOL_EXIT_SIGNAL + (int)cli_cancelled;
		return rc == -RT_E_INVALID ? TOOL_EXIT_USAGE : TOOL_EXIT_FAILURE;
	}
	return 0;
}

void check_reference_free(struct check_reference *ref)
{
	check_view_free(&ref->view);
	scene_destroy(ref->scene);
	ref->scene = NULL;
}

void check_camera_options(const struct camera_params *p, char *buf, size_t size)
{
	struct vec3 f = vec3_normalize(vec3_sub(p->look, p->eye));
	struct vec3 look = vec3_add_scaled(p->eye, f, 100.0);
	struct vec3 r = vec3_normalize(vec3_cross(f, p->up)), u = vec3_cross(r, f);

	/* Digits enough for a tenth of a pixel's turn at 768 pixels. */
	snprintf(buf, size, "--eye %.3f,%.3f,%.3f --look %.3f,%.3f,%.3f --up %.5f,%.5f,%.5f --fov %.3f",
		 p->eye.x, p->eye.y, p->eye.z, look.x, look.y, look.z, u.x, u.y, u.z, p->fov_deg);
}
