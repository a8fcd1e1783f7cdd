/* The scene's fields, for the library modules that walk them on the hot
 * path (the renderer, the hierarchy's builder); everything else goes
 * through the accessors of whitted/scene.h. */
#ifndef RT_SCENE_IMPL_H
#define RT_SCENE_IMPL_H

#include "whitted/scene.h"

struct accel;

struct scene {
	char *name;
	int recursion;
	int image_size;
	struct shape **shapes;
	size_t n_shapes, cap_shapes;
	int *shape_lines;		/* cap_lines of them, once one is set; else NULL */
	size_t cap_lines;
	struct light *lights;
	size_t n_lights, cap_lights;
	/* Lights with a falloff or a cone: while 0 the renderer takes the
	 * classic path, which neither tests nor multiplies. */
	size_t n_special_lights;
	struct scene_view view;
	struct accel *accel;		/* built by scene_prepare */
	uint64_t source_hash;
	uint64_t floor_texture_hash;	/* of the floor's textures' pixels; 0: none */
	const struct shape *floor;	/* scene_add_view_floor's, or NULL */
	/* Filled by scene_prepare for the ray tree's bound (render/ray_tree.h):
	 * whether an object transmits (kt > 0: its hits spawn two rays), the
	 * most a hit adds by itself, ka + (kd + ks) * the lights' brightest
	 * channels summed, and the most its rays' colours are multiplied by,
	 * kr + kt (at least 1 for glass: total internal reflection). */
	bool glass;
	double tree_emit, tree_gain;
};

#endif
