/* The whitted command line that renders exactly what a capture rendered. */
#ifndef RT_COMMAND_H
#define RT_COMMAND_H

#include <stddef.h>

#include "camera.h"
#include "cli.h"

/* Writes "whitted SCENE --eye X,Y,Z --look X,Y,Z --up X,Y,Z --fov F --size N"
 * and the options in `given` that change the image (recursion, floor,
 * clamping) into buf.  Numbers are printed with %.17g, so that whitted
 * reads back the very same doubles; SCENE is quoted for the shell when it
 * needs it, and NULL stands for --test-scene.  Fails with RT_E_RANGE when
 * buf is too small. */
int command_format(char *buf, size_t size, const char *scene_path,
		   const struct cli_scene *given, const struct camera_params *cam,
		   int image_size);

/* s as one shell word: unchanged when it is made of safe characters,
 * otherwise in single quotes.  Fails with RT_E_RANGE when buf is too small. */
int command_quote(char *buf, size_t size, const char *s);

#endif
