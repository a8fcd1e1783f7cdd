/* The scene as a POV-Ray 3.7 scene file and the .ini that renders it the way
 * `whitted --clamp final` does.  The shapes write themselves (shape_ops
 * export_pov); this module writes the settings, the camera and the lights
 * around them. */
#ifndef RT_POV_EXPORT_H
#define RT_POV_EXPORT_H

#include <stdio.h>

#include "whitted/camera.h"
#include "whitted/diag.h"
#include "whitted/pov.h"
#include "whitted/scene.h"

/* Writes the whole .pov file.  Returns 0, -RT_E_NOMEM or -RT_E_IO. */
int pov_export_scene(FILE *out, const struct scene *s, const struct camera *cam,
		     const struct pov_options *opt, struct diag *d);

/* True when the camera has a near plane (whitted sees nothing nearer) and
 * a shape's bounds reach into the box that holds the space between the eye
 * and the plane: POV-Ray, which has no near plane, may then show what
 * whitted does not. */
bool pov_export_near_hides(const struct scene *s, const struct camera *cam);

/* Writes the .ini that renders pov_name into png_name at size x size pixels
 * with linear output.  With dir (the absolute directory of both, and of
 * the textures' images), the .ini works from any directory: POV-Ray finds
 * the scene and the images there (Library_Path) and writes the PNG there;
 * with dir NULL both names are relative to the directory povray runs in. */
int pov_export_ini(FILE *out, const char *pov_name, const char *png_name, const char *dir,
		   int size, struct diag *d);

/* True when POV-Ray's .ini syntax can carry the name (no quote, no control
 * character, not empty). */
bool pov_export_name_ok(const char *name);

#endif
