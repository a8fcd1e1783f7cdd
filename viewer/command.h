/* The whitted command line that renders exactly what a capture rendered. */
#ifndef RT_COMMAND_H
#define RT_COMMAND_H

#include <stddef.h>

#include "whitted/camera.h"
#include "whitted/scene.h"
#include "whitted/settings.h"
#include "cli/scene_opts.h"

/* Writes "whitted SCENE", " --dialect NAME" when dialect is not
 * RT_DIALECT_AUTO (the file was read as one asked for), and the options
 * that reproduce the settings (settings_format_options: "--eye X,Y,Z
 * --look X,Y,Z --up X,Y,Z --fov F --size N --recursion N" and the floor
 * and clamping when they are not the defaults or the file's) into buf.
 * whitted reads the numbers back as the very same doubles; SCENE is
 * quoted for the shell when it needs it, and NULL stands for --test-scene
 * (which has no dialect).  Fails with RT_E_RANGE when buf is too small,
 * and with RT_E_INVALID for a floor that no option can give. */
int command_format(char *buf, size_t size, const char *scene_path, enum scene_dialect dialect,
		   const struct settings *s);

/* s as one shell word: unchanged when it is made of safe characters,
 * otherwise in single quotes.  Fails with RT_E_RANGE when buf is too small. */
int command_quote(char *buf, size_t size, const char *s);

#endif
