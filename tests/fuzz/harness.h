/* The fuzz target shared by the libFuzzer build and the replay driver. */
#ifndef RT_FUZZ_HARNESS_H
#define RT_FUZZ_HARNESS_H

#include <stddef.h>
#include <stdint.h>

/* Parses the bytes as a scene file; when they parse, prepares the scene
 * and renders a few pixels with small caps on size and recursion.
 * Always returns 0; a bug shows as a sanitizer report or a crash. */
int fuzz_scene_one(const uint8_t *data, size_t size);

#endif
