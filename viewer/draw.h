/* The OpenGL picture of a scene: the shapes' meshes in a display list built
 * once, the scene's lights as GL lights (and as dots, spotlights as cones
 * of lines), and a projection equal to whitted's camera, nearfar's near
 * plane and aspect included. */
#ifndef RT_DRAW_H
#define RT_DRAW_H

#include <stdbool.h>

#include "whitted/aabb.h"
#include "whitted/diag.h"
#include "fly_camera.h"
#include "whitted/scene.h"

struct draw {
	unsigned list;		/* GL display list of the shapes */
	unsigned texture;	/* for the meshes' textures, 0 until one has one */
	struct aabb world;	/* everything drawn, floor and lights included */
	double marker_length;	/* of the lines of a spotlight's cone */
	int n_lights;		/* GL lights in use */
};

/* The box around the scene file's objects and the lights, the implicit
 * floor left out (it would dwarf them): what the steps and the region for
 * unbounded shapes are sized by.  Never empty or flat. */
struct aabb draw_scene_box(const struct scene *s);

/* Needs a current GL context.  Notes go to note: lights beyond GL's limit,
 * and once per primitive without a tessellate method, that its shapes are
 * drawn as their bounding boxes (or, unbounded, not at all). */
int draw_init(struct draw *dr, const struct scene *s, diag_note_fn *note, void *note_ctx,
	      struct diag *d);
/* Draws the scene as cam sees it into a square viewport of size pixels at
 * (x, y) of the window. */
void draw_frame(const struct draw *dr, const struct scene *s, const struct fly_camera *cam,
		int x, int y, int size);

#endif
