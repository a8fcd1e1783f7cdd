/* Shading from a nearest hit found elsewhere (render_image.c traces a
 * block's primary rays as packets): the colour render_trace gives the ray
 * at level 1 when its nearest hit is `hit` at t (NULL: nothing, black). */
#ifndef RT_SHADE_HIT_H
#define RT_SHADE_HIT_H

#include "whitted/render.h"

struct color render_shade_hit(const struct scene *s, const struct render_settings *rs,
			      const struct ray *r, double t, const struct shape *hit,
			      struct ray_counts *counts);

#endif
