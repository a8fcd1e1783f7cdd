/* The fuzz target shared by the libFuzzer build and the replay driver. */
#ifndef RT_FUZZ_HARNESS_H
#define RT_FUZZ_HARNESS_H

#include <stddef.h>
#include <stdint.h>

/* Parses the bytes as a scene file; when they parse, prepares the scene
 * and renders a few pixels with small caps on size and recursion.
 * Always returns 0; a bug shows as a sanitizer report or a crash. */
int fuzz_scene_one(const uint8_t *data, size_t size);
/* Loads the plugins of $WHITTED_PLUGIN_PATH (make fuzz-replay and make
 * fuzz point it at build/plugins), so that their parsers and intersections
 * are fuzzed too; once, before the first input.  0, or -1 with the
 * message printed. */
int fuzz_init(void);

/* Reads the bytes as a tile (tile_read_memory: libpng), and as a
 * submitted image (image_read_memory: PNG, BMP, PPM); when they read as
 * one, compares the image with itself and its mirror image and makes the
 * difference picture.  Always returns 0. */
int fuzz_image_one(const uint8_t *data, size_t size);

/* Checks the bytes as a plugin file (plugin_elf_check: what the loader
 * checks before dlopen; the bytes are never mapped or run).  Always
 * returns 0. */
int fuzz_plugin_one(const uint8_t *data, size_t size);

#endif
