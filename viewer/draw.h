/* The OpenGL picture of a scene: meshes in a display list built once, the
 * scene's lights as GL lights, and a projection equal to whitted's camera. */
#ifndef RT_DRAW_H
#define RT_DRAW_H

#include <stdbool.h>

#include "aabb.h"
#include "diag.h"
#include "fly_camera.h"
#include "scene.h"

struct draw {
	unsigned list;		/* GL display list of the shapes */
	unsigned floor_texture;	/* the 2 x 2 checker, 0 without a floor */
	struct aabb world;	/* everything drawn, floor and lights included */
	int n_lights;		/* GL lights in use */
};

/* The box around the scene's objects and lights, the floor left out (it
 * would dwarf them): what the steps and unclipped quadrics are sized by.
 * Never empty or flat. */
struct aabb draw_scene_box(const struct scene *s);

/* Needs a current GL context.  Notes (lights beyond GL's limit, shapes it
 * cannot draw) go to note. */
int draw_init(struct draw *dr, const struct scene *s, scene_note_fn *note, void *note_ctx,
	      struct diag *d);
/* Draws the scene as cam sees it into a square viewport of size pixels at
 * (x, y) of the window. */
void draw_frame(const struct draw *dr, const struct scene *s, const struct fly_camera *cam,
		int x, int y, int size);

#endif
