/* The whitted-tile chunk's text: a tile_info as "key value" lines, shared
 * by the tile record (tile.c) and the tile PNGs (tile_png.c). */
#ifndef RT_DIST_TILE_TEXT_H
#define RT_DIST_TILE_TEXT_H

#include <stddef.h>

#include "whitted/diag.h"
#include "whitted/tile.h"

/* Room for the text of any tile_info, with its NUL. */
#define RT_TILE_TEXT_MAX (RT_TILE_OPTIONS_MAX + 256)

/* Writes the chunk's text (six lines, no trailing newline). */
void tile_text_format(const struct tile_info *t, char *buf, size_t size);

/* Parses the len bytes at text, which must be exactly what
 * tile_text_format writes for a region inside its full image and with the
 * options hash of its options text; anything else is RT_E_SYNTAX, with
 * path in the diag. */
int tile_text_parse(const char *path, const char *text, size_t len, struct tile_info *t,
		    struct diag *d);

#endif
