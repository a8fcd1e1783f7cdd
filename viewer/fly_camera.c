/* The free-flying camera of the course's first assignment: moves along and
 * turns about its own axes.  Each turn rotates two axes of the frame in
 * their plane, v' = v cos a + w sin a, then re-orthonormalises, so the
 * frame stays orthonormal to rounding after any number of turns. */
#include <math.h>

#include "fly_camera.h"

int fly_camera_init(struct fly_camera *c, const struct camera_params *p, struct diag *d)
{
	struct camera cam;
	int rc;

	/* camera_init does the checks and builds the frame whitted uses; the
	 * size does not matter to the frame. */
	if ((rc = camera_init(&cam, p, 1, d)) < 0)
		return rc;
	c->eye = p->eye;
	c->forward = cam.forward;
	c->up = cam.up;
	c->fov_deg = p->fov_deg;
	c->near = p->near;
	c->aspect = p->aspect;
	fly_camera_orthonormalize(c);
	return 0;
}

struct vec3 fly_camera_right(const struct fly_camera *c)
{
	return vec3_cross(c->forward, c->up);
}

void fly_camera_move(struct fly_camera *c, double right, double up, double forward)
{
	c->eye = vec3_add_scaled(c->eye, fly_camera_right(c), right);
	c->eye = vec3_add_scaled(c->eye, c->up, up);
	c->eye = vec3_add_scaled(c->eye, c->forward, forward);
}

/* Rotates a towards b by angle in their plane; a and b are orthonormal. */
static void rotate_pair(struct vec3 *a, struct vec3 *b, double angle)
{
	double co = cos(angle), si = sin(angle);
	struct vec3 a2 = vec3_add(vec3_scale(*a, co), vec3_scale(*b, si));
	struct vec3 b2 = vec3_sub(vec3_scale(*b, co), vec3_scale(*a, si));

	*a = a2;
	*b = b2;
}

void fly_camera_yaw(struct fly_camera *c, double angle)
{
	struct vec3 left = vec3_neg(fly_camera_right(c));

	rotate_pair(&c->forward, &left, angle);
	fly_camera_orthonormalize(c);
}

void fly_camera_pitch(struct fly_camera *c, double angle)
{
	rotate_pair(&c->forward, &c->up, angle);
	fly_camera_orthonormalize(c);
}

void fly_camera_roll(struct fly_camera *c, double angle)
{
	struct vec3 right = fly_camera_right(c);

	/* Clockwise on screen: the top of the image swings to the right. */
	rotate_pair(&c->up, &right, angle);
	fly_camera_orthonormalize(c);
}

void fly_camera_orthonormalize(struct fly_camera *c)
{
	c->forward = vec3_normalize(c->forward);
	c->up = vec3_normalize(vec3_add_scaled(c->up, c->forward, -vec3_dot(c->up, c->forward)));
}

void fly_camera_params(const struct fly_camera *c, struct camera_params *out)
{
	/* A look-at point as far away as the eye is from the origin keeps the
	 * direction look - eye accurate far from the origin, where eye +
	 * forward would round away most of forward's digits. */
	double dist = fmax(1.0, vec3_length(c->eye));

	out->eye = c->eye;
	out->look = vec3_add_scaled(c->eye, c->forward, dist);
	out->up = c->up;
	out->fov_deg = c->fov_deg;
	out->near = c->near;
	out->aspect = c->aspect;
}
