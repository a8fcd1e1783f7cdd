/* A pinhole camera: eye, look-at point, up vector and vertical field of
 * view, one ray through the centre of each pixel of a square image. */
#ifndef RT_CAMERA_H
#define RT_CAMERA_H

#include "diag.h"
#include "ray.h"
#include "vec3.h"

/* The assignment's test set-up. */
#define RT_CAMERA_EYE vec3_make(0.0, -200.0, 10.0)
#define RT_CAMERA_LOOK vec3_make(0.0, 0.0, 0.0)
#define RT_CAMERA_UP vec3_make(0.0, 0.0, 1.0)
#define RT_CAMERA_FOV 80.0

struct camera_params {
	struct vec3 eye, look, up;
	double fov_deg;			/* vertical, in (0, 180) */
};

struct camera {
	struct vec3 eye;
	struct vec3 forward, right, up;	/* orthonormal, right = forward x up */
	double half_height;		/* tan(fov / 2) */
	double pixel_scale;		/* 2 half_height / size: a pixel's width at distance 1 */
	int size;			/* pixels per side */
};

void camera_params_default(struct camera_params *p);
/* Fails with RT_E_INVALID when the eye is at the look-at point, the up
 * vector is zero or parallel to the view, or the field of view is outside
 * (0, 180) degrees. */
int camera_init(struct camera *c, const struct camera_params *p, int size, struct diag *d);
/* The unit-direction ray through the centre of pixel (px, py); py = 0 is the
 * top row. */
struct ray camera_ray(const struct camera *c, int px, int py);

#endif
