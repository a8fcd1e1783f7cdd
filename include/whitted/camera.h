/* A pinhole camera: eye, look-at point, up vector and vertical field of
 * view, one ray through the centre of each pixel of a square image.  The
 * nearfar dialect adds an image plane at a distance NEAR in front of the
 * eye, where primary rays start, and a horizontal field of view ASPECT
 * times the vertical one (scene-format.md, "Dialect nearfar"). */
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
	double near;			/* >= 0; 0: rays start at the eye */
	double aspect;			/* >= 0; 0: the horizontal field of view is fov_deg,
					 * else aspect * fov_deg (< 180) */
};

struct camera {
	struct vec3 eye;
	struct vec3 forward, right, up;	/* orthonormal, right = forward x up */
	double half_height;		/* tan(fov / 2) */
	double pixel_scale;		/* 2 half_height / height: a pixel's height at distance 1 */
	int size;			/* the width (pixels per side of a square image) */
	int width, height;		/* the image's, in pixels */
	double half_width;		/* tan(fovx / 2); when aspect is 0, half_height
					 * width / height (square pixels) */
	double pixel_scale_x;		/* 2 half_width / width: a pixel's width at distance 1 */
	double near;			/* the image plane's distance; 0: rays start at the eye */
};

void camera_params_default(struct camera_params *p);
/* Fails with RT_E_INVALID when the eye is at the look-at point, the up
 * vector is zero or parallel to the view, the field of view (or aspect
 * times it) is outside (0, 180) degrees, or near or aspect is negative or
 * not finite. */
int camera_init(struct camera *c, const struct camera_params *p, int size, struct diag *d);
/* The same for an image of width x height pixels: the vertical field of
 * view spans the height; the horizontal one is aspect times it (nearfar's
 * ASPECT) or, when aspect is 0, what square pixels give.  camera_init is
 * this with width = height = size, bit for bit. */
int camera_init_rect(struct camera *c, const struct camera_params *p, int width, int height,
		     struct diag *d);
/* The unit-direction ray through the centre of pixel (px, py); py = 0 is the
 * top row.  It starts at the eye, or with near > 0 at the pixel's centre on
 * the image plane: eye + near (forward + u right + v up), where the plane
 * spans 2 near half_width by 2 near half_height. */
struct ray camera_ray(const struct camera *c, int px, int py);
/* The ray through the point (x, y) of the image, in pixels from its top
 * left corner: camera_ray(c, px, py) is the ray through (px + 0.5, py + 0.5)
 * (to within rounding; camera_ray keeps its own arithmetic so that one
 * sample per pixel keeps every bit).  For --samples. */
struct ray camera_ray_at(const struct camera *c, double x, double y);
/* The point of the image plane at distance 1 from the eye that (x, y) of
 * the image shows: forward + u right + v up, the direction of
 * camera_ray_at's ray before it is made a unit vector.  The one place the
 * image's coordinates become a direction (inline: the camera fit's coarse
 * search makes one for every cell of every camera it scores). */
static inline struct vec3 camera_plane_point(const struct camera *c, double x, double y)
{
	double u = x * c->pixel_scale_x - c->half_width;
	double v = c->half_height - y * c->pixel_scale;

	return vec3_add(c->forward, vec3_add(vec3_scale(c->right, u), vec3_scale(c->up, v)));
}

/* Where the camera sees direction d (from the eye; a point less the eye):
 * the (x, y) of the image, in camera_ray_at's pixels from the top left
 * corner (a pixel's centre at its index + 0.5), camera_plane_point undone.
 * Returns d's depth along the view, d . forward: (x, y) mean nothing
 * unless it is > 0 (behind the eye or in its plane). */
static inline double camera_project(const struct camera *c, struct vec3 d, double *x, double *y)
{
	double depth = vec3_dot(d, c->forward);

	*x = (vec3_dot(d, c->right) / depth + c->half_width) / c->pixel_scale_x;
	*y = (c->half_height - vec3_dot(d, c->up) / depth) / c->pixel_scale;
	return depth;
}

#endif
