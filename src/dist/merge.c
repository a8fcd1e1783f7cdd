/* The merge of region renders.  The tiles are read twice: first only their
 * descriptions, so that foreign tiles, overlaps and gaps are found before
 * the full image is allocated; then their pixels.  Coverage is checked on
 * the grid of the distinct tile edges, where each cell is wholly inside or
 * outside each tile: every cell must have exactly one owner. */
#include <stdlib.h>
#include <string.h>

#include "base/alloc.h"
#include "whitted/merge.h"

/* More grid cells than this are refused (the tiles of a W x H split make
 * W x H cells; only an odd set of tiles comes near). */
#define MERGE_MAX_CELLS (1L << 26)

static int merge_cmp_int(const void *a, const void *b)
{
	int x = *(const int *)a, y = *(const int *)b;

	return (x > y) - (x < y);
}

/* Sorts v[0..n) and drops duplicates; returns the new count. */
static size_t merge_unique(int *v, size_t n)
{
	size_t i, m = 0;

	qsort(v, n, sizeof(*v), merge_cmp_int);
	for (i = 0; i < n; i++)
		if (m == 0 || v[m - 1] != v[i])
			v[m++] = v[i];
	return m;
}

/* The index of value in the sorted v[0..n), which holds it. */
static size_t merge_index(const int *v, size_t n, int value)
{
	size_t lo = 0, hi = n;

	while (hi - lo > 1) {
		size_t mid = lo + (hi - lo) / 2;
		if (v[mid] <= value)
			lo = mid;
		else
			hi = mid;
	}
	return lo;
}

static int merge_max(int a, int b)
{
	return a > b ? a : b;
}

static int merge_min(int a, int b)
{
	return a < b ? a : b;
}

/* The plugins a tile's options record ("" for none), in buf. */
static void merge_plugins_of(const struct tile_info *t, char *buf, size_t size)
{
	const char *at = strstr(t->options, " plugins="), *end;
	size_t n;

	buf[0] = '\0';
	if (!at)
		return;
	at += strlen(" plugins=");
	end = strchr(at, ' ');
	n = end ? (size_t)(end - at) : strlen(at);
	if (n >= size)
		n = size - 1;
	memcpy(buf, at, n);
	buf[n] = '\0';
}

/* Tiles of the same render agree on everything but their region. */
static int merge_check_same(const char *const *paths, const struct tile_info *t, size_t i,
			    struct diag *d)
{
	const struct tile_info *a = &t[0], *b = &t[i];
	char pa[RT_TILE_OPTIONS_MAX], pb[RT_TILE_OPTIONS_MAX];

	if (a->full_width != b->full_width || a->full_height != b->full_height)
		return diag_set(d, RT_E_INVALID, paths[i], 0, 0,
				"a tile of a %dx%d image, but %s is of a %dx%d image",
				b->full_width, b->full_height, paths[0], a->full_width, a->full_height);
	if (a->scene_hash != b->scene_hash)
		return diag_set(d, RT_E_INVALID, paths[i], 0, 0,
				"a tile of another scene file than %s (scene hash %016llx, not %016llx)",
				paths[0], (unsigned long long)b->scene_hash,
				(unsigned long long)a->scene_hash);
	merge_plugins_of(a, pa, sizeof(pa));
	merge_plugins_of(b, pb, sizeof(pb));
	if (strcmp(pa, pb) != 0)
		return diag_set(d, RT_E_INVALID, paths[i], 0, 0,
				"made with other plugins than %s (%s, not %s): render every tile with the same --plugin files",
				paths[0], pb[0] ? pb : "none", pa[0] ? pa : "none");
	if (a->options_hash != b->options_hash)
		return diag_set(d, RT_E_INVALID, paths[i], 0, 0,
				"rendered with other options than %s ('%s', not '%s')",
				paths[0], b->options, a->options);
	return 0;
}

/* Checks that the regions cover the image exactly once.  Long: one sweep
 * over the rows keeps the overlap and the gap messages beside the state
 * they name (which files, which pixel). */
static int merge_check_cover(const char *const *paths, const struct tile_info *t, size_t n,
			     struct diag *d)
{
	int w = t[0].full_width, h = t[0].full_height;
	size_t nx = 0, ny = 0, i, cx, cy, x0, x1, y0, y1;
	int *xs, *ys, *owner = NULL;
	int rc = 0;

	xs = rt_reallocarray(NULL, 2 * n + 2, sizeof(*xs));
	ys = rt_reallocarray(NULL, 2 * n + 2, sizeof(*ys));
	if (!xs || !ys) {
		rc = diag_fail(d, RT_E_NOMEM, "out of memory");
		goto out_free;
	}
	xs[nx++] = 0;
	xs[nx++] = w;
	ys[ny++] = 0;
	ys[ny++] = h;
	for (i = 0; i < n; i++) {
		xs[nx++] = t[i].x0;
		xs[nx++] = t[i].x1;
		ys[ny++] = t[i].y0;
		ys[ny++] = t[i].y1;
	}
	nx = merge_unique(xs, nx) - 1;	/* cells across */
	ny = merge_unique(ys, ny) - 1;
	if ((double)nx * (double)ny > (double)MERGE_MAX_CELLS) {
		rc = diag_fail(d, RT_E_RANGE,
			      "the tiles' edges make more than %ld cells to check", MERGE_MAX_CELLS);
		goto out_free;
	}
	owner = rt_reallocarray(NULL, nx * ny, sizeof(*owner));
	if (!owner) {
		rc = diag_fail(d, RT_E_NOMEM, "out of memory");
		goto out_free;
	}
	for (i = 0; i < nx * ny; i++)
		owner[i] = -1;
	for (i = 0; i < n; i++) {
		x0 = merge_index(xs, nx + 1, t[i].x0);
		x1 = merge_index(xs, nx + 1, t[i].x1);
		y0 = merge_index(ys, ny + 1, t[i].y0);
		y1 = merge_index(ys, ny + 1, t[i].y1);
		for (cy = y0; cy < y1; cy++) {
			for (cx = x0; cx < x1; cx++) {
				int *o = &owner[cy * nx + cx];
				const struct tile_info *a, *b = &t[i];
				if (*o < 0) {
					*o = (int)i;
					continue;
				}
				a = &t[*o];
				if (strcmp(paths[*o], paths[i]) == 0)
					rc = diag_set(d, RT_E_INVALID, paths[i], 0, 0, "given twice");
				else
					rc = diag_set(d, RT_E_INVALID, paths[i], 0, 0,
						      "overlaps %s in region %d,%d,%d,%d (tiles must cover the image exactly once)",
						      paths[*o], merge_max(a->x0, b->x0), merge_max(a->y0, b->y0),
						      merge_min(a->x1, b->x1), merge_min(a->y1, b->y1));
				goto out_free;
			}
		}
	}
	for (cy = 0; cy < ny; cy++) {
		for (cx = 0; cx < nx; cx++) {
			if (owner[cy * nx + cx] >= 0)
				continue;
			rc = diag_fail(d, RT_E_INVALID,
				      "missing tile: no tile covers region %d,%d,%d,%d of the %dx%d image",
				      xs[cx], ys[cy], xs[cx + 1], ys[cy + 1], w, h);
			goto out_free;
		}
	}
out_free:
	rt_free(owner);
	rt_free(xs);
	rt_free(ys);
	return rc;
}

static bool merge_same_info(const struct tile_info *a, const struct tile_info *b)
{
	return a->full_width == b->full_width && a->full_height == b->full_height &&
	       a->x0 == b->x0 && a->y0 == b->y0 && a->x1 == b->x1 && a->y1 == b->y1 &&
	       a->scene_hash == b->scene_hash && a->options_hash == b->options_hash;
}

static void merge_copy(struct image *full, const struct image *tile, const struct tile_info *t)
{
	size_t row = (size_t)tile->width * 3;
	int y;

	for (y = 0; y < tile->height; y++)
		memcpy(full->pixels + ((size_t)(t->y0 + y) * (size_t)full->width + (size_t)t->x0) * 3,
		       tile->pixels + (size_t)y * row, row);
}

int merge_tiles(const char *const *paths, size_t n, struct image *img, struct tile_info *first,
		struct diag *d)
{
	struct tile_info *infos, again;
	struct image tile;
	size_t i;
	int rc = 0;

	img->pixels = NULL;
	if (n == 0)
		return diag_fail(d, RT_E_INVALID, "no tiles to merge");
	infos = rt_reallocarray(NULL, n, sizeof(*infos));
	if (!infos)
		return diag_fail(d, RT_E_NOMEM, "out of memory");
	for (i = 0; i < n; i++)
		if ((rc = tile_read(paths[i], &infos[i], NULL, d)) < 0)
			goto out_free;
	for (i = 1; i < n; i++)
		if ((rc = merge_check_same(paths, infos, i, d)) < 0)
			goto out_free;
	if ((rc = merge_check_cover(paths, infos, n, d)) < 0)
		goto out_free;
	if ((rc = image_alloc(img, infos[0].full_width, infos[0].full_height, d)) < 0)
		goto out_free;
	for (i = 0; i < n; i++) {
		if ((rc = tile_read(paths[i], &again, &tile, d)) < 0)
			goto out_image;
		if (!merge_same_info(&again, &infos[i])) {
			image_free(&tile);
			rc = diag_set(d, RT_E_IO, paths[i], 0, 0, "changed while merging");
			goto out_image;
		}
		merge_copy(img, &tile, &infos[i]);
		image_free(&tile);
	}
	if (first)
		*first = infos[0];
	rt_free(infos);
	return 0;
out_image:
	image_free(img);
out_free:
	rt_free(infos);
	return rc;
}
