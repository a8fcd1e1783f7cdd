/* Joins the tiles of one render (whitted --region) into the full image,
 * after checking that they come from the same scene text and settings and
 * cover the image exactly once. */
#ifndef RT_MERGE_H
#define RT_MERGE_H

#include <stddef.h>

#include "diag.h"
#include "image.h"
#include "tile.h"

/* Fills img (allocated here; image_free it) from the tiles at paths[0..n)
 * and, when first is not NULL, copies the first tile's description there.
 * Fails with RT_E_IO for an unreadable file, RT_E_SYNTAX for a file that
 * is not a tile, and RT_E_INVALID when the tiles do not belong together:
 * a different scene, settings or full size, an overlap or a gap.  The
 * message names the files and pixels concerned.  Nothing is allocated on
 * failure. */
int merge_tiles(const char *const *paths, size_t n, struct image *img, struct tile_info *first,
		struct diag *d);

#endif
