/* Region renders ("tiles") as PNG files that say where they belong: an oFFs
 * chunk with the region's top-left corner in pixels, a vpAg chunk with the
 * full image size (ImageMagick's virtual page), and a tEXt chunk with
 * keyword "whitted-tile" that holds the place, the full size, a hash of the
 * scene text and a hash of the options that affect pixels.  The text is
 * authoritative; the other chunks let ordinary tools place a tile.  See
 * docs/distributed.md for the exact format.  The settings' text is
 * settings.h's; a tile only records it. */
#ifndef RT_TILE_H
#define RT_TILE_H

#include <signal.h>
#include <stdint.h>

#include "diag.h"
#include "image.h"
#include "settings.h"

#define RT_TILE_KEYWORD "whitted-tile"
#define RT_TILE_VERSION 1
#define RT_TILE_OPTIONS_MAX RT_SETTINGS_TEXT_MAX

struct tile_info {
	int full_width, full_height;
	int x0, y0, x1, y1;		/* end-exclusive, inside the full image */
	uint64_t scene_hash;		/* hash_bytes of the scene text */
	uint64_t options_hash;		/* hash_bytes of options[] */
	char options[RT_TILE_OPTIONS_MAX];	/* settings_format of the settings */
};

/* Fills info for the region x0,y0,x1,y1 of a render with these settings of
 * a scene whose text hashed to scene_hash. */
void tile_info_init(struct tile_info *info, const struct settings *s, uint64_t scene_hash,
		    int x0, int y0, int x1, int y1);

/* Checks a region against a full image size: RT_E_INVALID with a message
 * when it is empty, inverted or outside. */
int tile_check_region(int x0, int y0, int x1, int y1, int full_width, int full_height,
		      struct diag *d);

/* Writes img (the region's size) as a tile PNG, atomically as image_write,
 * compressed as image_write compresses a PNG. */
int tile_write(const char *path, const struct image *img, const struct tile_info *info,
	       const volatile sig_atomic_t *cancel, struct diag *d);

/* Reads a tile's description and, when img is not NULL, its pixels (img is
 * then allocated, the region's size; free it with image_free).  A file
 * that is not a PNG, a damaged or truncated one (a bad CRC in any chunk),
 * one with bytes after its IEND chunk, one whose image data inflates to
 * more or less than its header describes or whose size is over
 * RT_MAX_PIXELS, one that is not 8-bit RGB, a PNG without a valid
 * whitted-tile chunk, or one whose chunks disagree fails with
 * RT_E_SYNTAX (the size: RT_E_RANGE), all before anything the size of
 * the image is allocated; unreadable files (and what is not a regular
 * file) with RT_E_IO. */
int tile_read(const char *path, struct tile_info *info, struct image *img, struct diag *d);
/* tile_read of a file's bytes b[0..n), named `name` in messages. */
int tile_read_memory(const unsigned char *b, size_t n, const char *name, struct tile_info *info,
		     struct image *img, struct diag *d);

#endif
