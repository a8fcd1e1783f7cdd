/* The pinhole camera of the assignment: a vertical field of view on a
 * square image, one ray through each pixel's centre; nearfar's variant
 * (a wider or narrower horizontal view, rays from the image plane) is the
 * same computation with half_width and near set, so that the classic
 * camera's rays keep every bit. */
#include <math.h>

#include "render/camera_span.h"
#include "whitted/camera.h"

void camera_params_default(struct camera_params *p)
{
	p->eye = RT_CAMERA_EYE;
	p->look = RT_CAMERA_LOOK;
	p->up = RT_CAMERA_UP;
	p->fov_deg = RT_CAMERA_FOV;
	p->near = 0.0;
	p->aspect = 0.0;
}

int camera_init(struct camera *c, const struct camera_params *p, int size, struct diag *d)
{
	return camera_init_rect(c, p, size, size, d);
}

/* Long: the camera's checks and its basis, each a named step of scene-
 * format.md's camera. */
int camera_init_rect(struct camera *c, const struct camera_params *p, int width, int height,
		     struct diag *d)
{
	const double pi = 3.14159265358979323846;
	struct vec3 view = vec3_sub(p->look, p->eye);
	struct vec3 right;
	double view_len = vec3_length(view), up_len = vec3_length(p->up);

	if (!vec3_is_finite(p->eye) || !vec3_is_finite(p->look) || !vec3_is_finite(p->up) ||
	    !isfinite(view_len) || !isfinite(up_len))
		return diag_fail(d, RT_E_INVALID, "camera vectors must be finite");
	if (!(view_len > 0.0))
		return diag_fail(d, RT_E_INVALID, "the eye is at the look-at point");
	if (!(up_len > 0.0))
		return diag_fail(d, RT_E_INVALID, "the up vector is zero");
	if (!(p->fov_deg > 0.0 && p->fov_deg < 180.0))
		return diag_fail(d, RT_E_INVALID,
				"the field of view must be between 0 and 180 degrees, found %g",
				p->fov_deg);
	if (!(p->near >= 0.0 && isfinite(p->near)))
		return diag_fail(d, RT_E_INVALID,
				"the near plane's distance must be finite and >= 0, found %g", p->near);
	if (!(p->aspect >= 0.0 && isfinite(p->aspect)))
		return diag_fail(d, RT_E_INVALID,
				"the aspect ratio must be finite and >= 0, found %g", p->aspect);
	if (p->aspect > 0.0 && !(p->aspect * p->fov_deg > 0.0 && p->aspect * p->fov_deg < 180.0))
		return diag_fail(d, RT_E_INVALID,
				"the horizontal field of view (aspect %g times %g degrees) must be "
				"between 0 and 180 degrees, found %g",
				p->aspect, p->fov_deg, p->aspect * p->fov_deg);
	if (width < 1 || height < 1)
		return diag_fail(d, RT_E_INVALID, "the image size must be >= 1");
	c->forward = vec3_scale(view, 1.0 / view_len);
	right = vec3_cross(c->forward, vec3_scale(p->up, 1.0 / up_len));
	/* sin of the angle between view and up: parallel within ~0.06 degrees
	 * leaves no usable image orientation. */
	if (vec3_length(right) < 1e-3)
		return diag_fail(d, RT_E_INVALID,
				"the up vector is parallel to the viewing direction");
	c->right = vec3_normalize(right);
	c->up = vec3_cross(c->right, c->forward);
	c->eye = p->eye;
	c->half_height = tan(p->fov_deg * pi / 360.0);
	c->size = width;
	c->width = width;
	c->height = height;
	/* Once here rather than a division for every pixel. */
	c->pixel_scale = 2.0 * c->half_height / height;
	if (p->aspect > 0.0) {
		c->half_width = tan(p->aspect * p->fov_deg * pi / 360.0);
		c->pixel_scale_x = 2.0 * c->half_width / width;
	} else if (width == height) {
		/* The square image's: the very bits it always had. */
		c->half_width = c->half_height;
		c->pixel_scale_x = c->pixel_scale;
	} else {
		c->half_width = c->half_height * width / height;
		c->pixel_scale_x = 2.0 * c->half_width / width;
	}
	c->near = p->near;
	return 0;
}

/* The ray through w, a point of the image plane at distance 1 from the
 * eye: from the eye (or the near plane's point along it), towards w.  The
 * one place a primary ray is made of its point; camera_lanes_lanes.h is
 * its vector twin, lane for lane. */
static inline struct ray camera_ray_through(const struct camera *c, struct vec3 w)
{
	struct ray r;

	r.origin = c->eye;
	if (c->near > 0.0)
		r.origin = vec3_add_scaled(r.origin, w, c->near);
	r.dir = vec3_normalize(w);
	return r;
}

struct ray camera_ray_at(const struct camera *c, double x, double y)
{
	return camera_ray_through(c, camera_plane_point(c, x, y));
}

/* The pixel's centre: x + 0.5 is exact for any pixel, so these are
 * camera_ray_at's very operations. */
struct ray camera_ray(const struct camera *c, int px, int py)
{
	return camera_ray_at(c, px + 0.5, py + 0.5);
}

void camera_span_init(struct camera_span *sp, const struct camera *c, int x0, int x1)
{
	int i;

	sp->x0 = x0;
	sp->n = x1 - x0;
	for (i = 0; i < sp->n; i++) {
		double u = (x0 + i + 0.5) * c->pixel_scale_x - c->half_width;
		sp->right_u[i] = vec3_scale(c->right, u);
	}
}

/* camera_ray's sums, w = forward + (right u + up v), with the two
 * products taken from the span and the row. */
void camera_span_rays(const struct camera_span *sp, const struct camera *c, int py,
		      struct ray *out)
{
	double v = c->half_height - (py + 0.5) * c->pixel_scale;
	struct vec3 up_v = vec3_scale(c->up, v);
	int i;

	for (i = 0; i < sp->n; i++)
		out[i] = camera_ray_through(c, vec3_add(c->forward, vec3_add(sp->right_u[i], up_v)));
}
