/* The viewer's free-flying camera: an eye and an orthonormal frame that the
 * keys move and turn, the lens that the keys leave alone (the field of
 * view, and nearfar's near plane and aspect), and the whitted camera
 * parameters that rebuild it. */
#ifndef RT_FLY_CAMERA_H
#define RT_FLY_CAMERA_H

#include "whitted/camera.h"
#include "whitted/diag.h"
#include "whitted/vec3.h"

struct fly_camera {
	struct vec3 eye;
	struct vec3 forward, up;	/* unit and perpendicular */
	double fov_deg;			/* vertical */
	double near;			/* the image plane's distance; 0: none (camera_params) */
	double aspect;			/* 0: the horizontal view is fov_deg, else
					 * aspect * fov_deg */
};

/* The frame of whitted's camera for p (the same checks as camera_init). */
int fly_camera_init(struct fly_camera *c, const struct camera_params *p, struct diag *d);
/* forward x up, the direction of the image's +x, as in struct camera. */
struct vec3 fly_camera_right(const struct fly_camera *c);

/* Moves the eye by the given distances along right, up and forward. */
void fly_camera_move(struct fly_camera *c, double right, double up, double forward);
/* Turns by an angle in radians: yaw > 0 turns left (about up), pitch > 0
 * looks up (about right), roll > 0 tilts clockwise as seen by the viewer
 * (about forward).  Each re-orthonormalises the frame. */
void fly_camera_yaw(struct fly_camera *c, double angle);
void fly_camera_pitch(struct fly_camera *c, double angle);
void fly_camera_roll(struct fly_camera *c, double angle);
/* Gram-Schmidt on forward then up, so rounding never accumulates. */
void fly_camera_orthonormalize(struct fly_camera *c);

/* Parameters for whitted: look = eye + forward * max(1, |eye|), up = the
 * frame's up, and fov_deg, near and aspect as fly_camera_init was given
 * them.  camera_init on them gives the camera the viewer shows. */
void fly_camera_params(const struct fly_camera *c, struct camera_params *out);

#endif
