/* Drawing with OpenGL 1.x fixed function.  The projection is glFrustum on
 * the tracer's image plane: at distance 1 in front of the eye it spans
 * [-tan(fovx/2), tan(fovx/2)] across and [-tan(fov/2), tan(fov/2)] up
 * (fovx = aspect * fov with nearfar's aspect, else fov), and GL samples
 * pixel centres as camera_ray does, so a window of N x N pixels shows what
 * an N x N render shows; with nearfar's near plane GL's near plane is that
 * plane, which clips what the tracer's rays start beyond.  Lighting is GL's
 * Phong per vertex with the material's ka, kd, ks and shininess and the
 * scene's lights, spotlights as GL spotlights (no shadows, no
 * reflections): close enough to see the shapes as solid and to aim the
 * camera.  Every shape is drawn from the mesh its primitive makes
 * (shape_tessellate), whatever the primitive; one without a tessellate
 * method is drawn as its bounding box, with a note. */
#include <GL/gl.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "draw.h"
#include "light_marker.h"
#include "shapes/registry.h"
#include "whitted/mesh.h"

/* Primitives noted as drawn without a mesh of their own, per kind of note;
 * beyond this many, the first ones' notes are enough. */
#define DRAW_MAX_NOTED 32

/* The implicit floor, when it is unbounded (nearfar's infinite
 * checkerboard), is meshed in layers: over 8, 64 and 512 times the region
 * that unbounded file objects get, finely near the scene and coarsely far
 * away, each nearer layer drawn over the ones further out.  The last
 * reaches to within a pixel or two of the horizon from a camera as high
 * above the floor as the scene is wide. */
static const struct draw_ground_layer {
	double reach;
	int segments;
} draw_ground[] = { { 8.0, 64 }, { 64.0, 24 }, { 512.0, 24 } };
#define DRAW_GROUND_LAYERS (sizeof(draw_ground) / sizeof(draw_ground[0]))

/* Widens box along one axis to take in [lo, hi]. */
static void box_include_axis(struct aabb *box, int axis, double lo, double hi)
{
	double *min = axis == 0 ? &box->min.x : axis == 1 ? &box->min.y : &box->min.z;
	double *max = axis == 0 ? &box->max.x : axis == 1 ? &box->max.y : &box->max.z;

	*min = fmin(*min, lo);
	*max = fmax(*max, hi);
}

/* A shape that a scene file can name: one of a registered table (a
 * keyword may have several, one per dialect), so not the implicit floor. */
static bool is_file_object(const struct shape *sh)
{
	const struct shape_ops *const *ops;

	for (ops = shape_ops_all(); *ops; ops++)
		if (*ops == sh->ops)
			return true;
	return false;
}

/* A shape's part in the scene's box: its bounds, or for an unbounded
 * shape the axes it is bounded along (a quadric clipped on some axes only
 * still has a place along them). */
static void box_include_shape(struct aabb *box, const struct shape *sh)
{
	struct aabb b;
	int axis;

	if (shape_bounds(sh, &b)) {
		*box = aabb_union(*box, b);
		return;
	}
	for (axis = 0; axis < 3; axis++) {
		double lo = vec3_component(b.min, axis), hi = vec3_component(b.max, axis);
		if (isfinite(lo) && isfinite(hi))
			box_include_axis(box, axis, lo, hi);
	}
}

struct aabb draw_scene_box(const struct scene *s)
{
	struct aabb box = { { INFINITY, INFINITY, INFINITY }, { -INFINITY, -INFINITY, -INFINITY } };
	double size;
	size_t i;
	int axis;

	for (i = 0; i < scene_shape_count(s); i++)
		if (is_file_object(scene_shape(s, i)))
			box_include_shape(&box, scene_shape(s, i));
	for (i = 0; i < scene_light_count(s); i++) {
		struct aabb b = { scene_light(s, i)->pos, scene_light(s, i)->pos };
		box = aabb_union(box, b);
	}
	if (!(box.min.x <= box.max.x)) {
		box.min = vec3_make(-100, -100, -100);
		box.max = vec3_make(100, 100, 100);
	}
	/* A box flat or empty along an axis (one light, coplanar triangles, a
	 * quadric clipped on one axis only) still needs a size there. */
	for (axis = 0; axis < 3; axis++) {
		double lo = vec3_component(box.min, axis), hi = vec3_component(box.max, axis);
		if (!(lo <= hi))
			box_include_axis(&box, axis, 0.0, 0.0);
	}
	size = fmax(1.0, vec3_length(vec3_sub(box.max, box.min)));
	for (axis = 0; axis < 3; axis++) {
		double lo = vec3_component(box.min, axis), hi = vec3_component(box.max, axis);
		if (hi - lo < 0.05 * size)
			box_include_axis(&box, axis, lo - 0.025 * size, hi + 0.025 * size);
	}
	return box;
}

/* Glass is drawn approximately: see-through by 1 - kt (alpha blending
 * over what was drawn before it, no bending). */
static void set_material(const struct material *m, struct color c)
{
	GLfloat alpha = (GLfloat)(1.0 - m->kt);
	GLfloat amb[4] = { (GLfloat)(m->ka * c.r), (GLfloat)(m->ka * c.g), (GLfloat)(m->ka * c.b),
			   alpha };
	GLfloat dif[4] = { (GLfloat)(m->kd * c.r), (GLfloat)(m->kd * c.g), (GLfloat)(m->kd * c.b),
			   alpha };
	/* The format tints the highlight with the object's colour. */
	GLfloat spe[4] = { (GLfloat)(m->ks * c.r), (GLfloat)(m->ks * c.g), (GLfloat)(m->ks * c.b), 1 };
	GLfloat shine = (GLfloat)fmin(128.0, m->shininess);

	glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, amb);
	glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, dif);
	glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, spe);
	glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, shine);
}

/* The mesh's texture, for the triangles that follow: nearest texels,
 * repeated, modulating the lit colour of a white material (which is the
 * material in the texel's colour: the format's highlight is tinted too). */
static void set_texture(const struct material *m, const struct mesh_texture *t, unsigned tex)
{
	GLfloat texels[RT_MESH_TEXELS_MAX][3];
	int k;

	for (k = 0; k < t->width * t->height; k++) {
		texels[k][0] = (GLfloat)t->texels[k].r;
		texels[k][1] = (GLfloat)t->texels[k].g;
		texels[k][2] = (GLfloat)t->texels[k].b;
	}
	set_material(m, color_make(1, 1, 1));
	glEnable(GL_TEXTURE_2D);
	glBindTexture(GL_TEXTURE_2D, tex);
	glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
	glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
	glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
	glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
	glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
	glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, t->width, t->height, 0, GL_RGB, GL_FLOAT, texels);
	glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
}

/* The texture is specified inside the display list, so each textured mesh
 * brings its own texels to the one texture object. */
static void emit_mesh(const struct shape *sh, const struct mesh *m, struct draw *dr)
{
	bool textured = m->texture.width > 0;
	size_t i;

	if (textured) {
		if (!dr->texture)
			glGenTextures(1, &dr->texture);
		set_texture(&sh->mat, &m->texture, dr->texture);
	} else {
		set_material(&sh->mat, sh->mat.color);
	}
	glBegin(GL_TRIANGLES);
	for (i = 0; i < m->n_vertices; i++) {
		const float *v = m->data + i * RT_MESH_FLOATS_PER_VERTEX;
		if (textured)
			glTexCoord2fv(v + 6);
		glNormal3fv(v + 3);
		glVertex3fv(v);
	}
	glEnd();
	if (textured)
		glDisable(GL_TEXTURE_2D);
}

/* The notes on shapes drawn without a mesh of their own: one per
 * primitive, for its bounded shapes and for its unbounded ones. */
struct draw_notes {
	diag_note_fn *note;
	void *ctx;
	const struct shape_ops *seen[2][DRAW_MAX_NOTED];
	int n_seen[2];
};

static void note_no_mesh(struct draw_notes *dn, const struct shape *sh, bool bounded)
{
	struct diag n;
	int k;

	if (!dn->note || dn->n_seen[bounded] == DRAW_MAX_NOTED)
		return;
	for (k = 0; k < dn->n_seen[bounded]; k++)
		if (dn->seen[bounded][k] == sh->ops)
			return;
	dn->seen[bounded][dn->n_seen[bounded]++] = sh->ops;
	if (bounded)
		diag_fail(&n, RT_OK, "each '%s' is drawn as its bounding box"
			  " (its primitive has no tessellate method)", sh->ops->keyword);
	else
		diag_fail(&n, RT_OK, "the unbounded '%s' objects are not drawn"
			  " (their primitive has no tessellate method)", sh->ops->keyword);
	dn->note(dn->ctx, &n);
}

/* Curved shapes get fewer facets when there are many shapes. */
static int draw_segments(size_t n_shapes)
{
	return n_shapes > 20000 ? 8 : n_shapes > 2000 ? 12 : 32;
}

/* Widens box to take in the mesh's vertices. */
static void box_include_mesh(struct aabb *box, const struct mesh *m)
{
	size_t i;

	for (i = 0; i < m->n_vertices; i++) {
		const float *v = m->data + i * RT_MESH_FLOATS_PER_VERTEX;
		struct aabb p = { { v[0], v[1], v[2] }, { v[0], v[1], v[2] } };
		*box = aabb_union(*box, p);
	}
}

/* m is scratch space, kept from shape to shape.  What is drawn widens
 * dr->world, which the far plane is sized by. */
static int emit_shape(const struct shape *sh, const struct mesh_options *opt, struct mesh *m,
		      struct draw *dr, struct draw_notes *dn, struct diag *d)
{
	struct aabb b;
	int rc;

	if (!shape_tessellates(sh))
		note_no_mesh(dn, sh, shape_bounds(sh, &b));
	mesh_clear(m);
	/* The built-ins' meshes fail only for memory; a plugin's tessellate
	 * may fail otherwise, or return what is no status. */
	if ((rc = shape_tessellate(sh, opt, m)) == -RT_E_NOMEM)
		return diag_fail(d, RT_E_NOMEM, "out of memory for the shapes' meshes");
	if (rc != 0) {
		const char *origin = shape_registry_origin(sh->ops);

		return diag_fail(d, RT_E_RANGE, "shape '%s' of %s%s: its tessellate %s (returned %d)",
				 sh->ops->keyword, origin ? "the plugin " : "whitted (built in)",
				 origin ? origin : "",
				 rc > 0 ? "returned neither 0 nor an error" : "failed", rc);
	}
	if (m->n_vertices) {
		emit_mesh(sh, m, dr);
		box_include_mesh(&dr->world, m);
	}
	return 0;
}

/* The region of the unbounded file objects: a cube around the objects and
 * lights, half again as wide as the box's longest side (a surface runs on
 * past the scene, and a cone or hyperboloid spreads), or reach times
 * that. */
static struct aabb draw_region(struct aabb box, double reach)
{
	struct vec3 e = vec3_sub(box.max, box.min);
	struct vec3 half = vec3_scale(vec3_make(1, 1, 1), reach * 0.75 * fmax(e.x, fmax(e.y, e.z)));
	struct aabb r;

	r.min = vec3_sub(aabb_centre(box), half);
	r.max = vec3_add(aabb_centre(box), half);
	return r;
}

/* The implicit floor when it is unbounded: the layers of draw_ground,
 * each further one pushed back in depth (glPolygonOffset) so that where
 * they overlap the finer nearer one is seen, without z-fighting. */
static int emit_ground(const struct shape *sh, struct aabb box, struct mesh *m, struct draw *dr,
		       struct draw_notes *dn, struct diag *d)
{
	struct mesh_options opt;
	size_t k;
	int rc = 0;

	for (k = 0; k < DRAW_GROUND_LAYERS && rc == 0; k++) {
		opt.around = draw_region(box, draw_ground[k].reach);
		opt.segments = draw_ground[k].segments;
		if (k > 0) {
			glEnable(GL_POLYGON_OFFSET_FILL);
			glPolygonOffset((GLfloat)k, (GLfloat)(4 * k));
		}
		rc = emit_shape(sh, &opt, m, dr, dn, d);
	}
	glPolygonOffset(0.0f, 0.0f);
	glDisable(GL_POLYGON_OFFSET_FILL);
	return rc;
}

int draw_init(struct draw *dr, const struct scene *s, diag_note_fn *note, void *note_ctx,
	      struct diag *d)
{
	struct aabb box = draw_scene_box(s);
	struct draw_notes dn;
	struct mesh_options opt;
	struct mesh m;
	GLint max_lights = 8;
	size_t i;
	int rc = 0;

	memset(dr, 0, sizeof(*dr));
	memset(&dn, 0, sizeof(dn));
	dn.note = note;
	dn.ctx = note_ctx;
	opt.around = draw_region(box, 1.0);
	opt.segments = draw_segments(scene_shape_count(s));
	dr->world = box;
	/* A spotlight's cone is a tenth of the scene across. */
	dr->marker_length = 0.1 * vec3_length(vec3_sub(box.max, box.min));
	glGetIntegerv(GL_MAX_LIGHTS, &max_lights);
	dr->n_lights = scene_light_count(s) < (size_t)max_lights ? (int)scene_light_count(s) : max_lights;
	if (note && scene_light_count(s) > (size_t)max_lights) {
		struct diag n;
		diag_fail(&n, RT_OK, "OpenGL lights the view with the first %d of the %zu lights"
			 " (the captures use them all)", max_lights, scene_light_count(s));
		note(note_ctx, &n);
	}
	mesh_init(&m);
	dr->list = glGenLists(1);
	glNewList(dr->list, GL_COMPILE);
	for (i = 0; i < scene_shape_count(s) && rc == 0; i++) {
		const struct shape *sh = scene_shape(s, i);
		struct aabb b;

		if (sh->mat.kt > 0.0)
			continue;
		/* The implicit floor is the ground the camera flies over: when
		 * it is unbounded it reaches to the horizon (a finite one is
		 * meshed over its own square). */
		if (!is_file_object(sh) && !shape_bounds(sh, &b))
			rc = emit_ground(sh, box, &m, dr, &dn, d);
		else
			rc = emit_shape(sh, &opt, &m, dr, &dn, d);
	}
	/* Glass last, blended over the opaque shapes, and not hiding what
	 * lies behind it (no depth writes). */
	glEnable(GL_BLEND);
	glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
	glDepthMask(GL_FALSE);
	for (i = 0; i < scene_shape_count(s) && rc == 0; i++)
		if (scene_shape(s, i)->mat.kt > 0.0)
			rc = emit_shape(scene_shape(s, i), &opt, &m, dr, &dn, d);
	glDepthMask(GL_TRUE);
	glDisable(GL_BLEND);
	glEndList();
	mesh_free(&m);
	return rc;
}

static void set_view(const struct fly_camera *cam, const struct draw *dr)
{
	const double pi = 3.14159265358979323846;
	struct vec3 f = cam->forward, u = cam->up, r = fly_camera_right(cam), e = cam->eye;
	struct vec3 centre = aabb_centre(dr->world);
	double radius = 0.5 * vec3_length(vec3_sub(dr->world.max, dr->world.min));
	double far = vec3_length(vec3_sub(e, centre)) + radius, near, h, w;
	/* Rows of the view matrix are right, up and -forward: GL looks down
	 * its -z axis.  Column-major for glLoadMatrixd. */
	const GLdouble view[16] = {
		r.x, u.x, -f.x, 0,
		r.y, u.y, -f.y, 0,
		r.z, u.z, -f.z, 0,
		-vec3_dot(r, e), -vec3_dot(u, e), vec3_dot(f, e), 1,
	};

	far *= 1.01;
	/* nearfar's image plane, which clips as GL's near plane does (but
	 * for a plane so near that 24-bit depth would blur the scene: six
	 * decades before the far plane at most); otherwise about four
	 * decades before the far plane. */
	near = cam->near > 0.0 ? fmax(cam->near, far * 1e-6) : far * 1e-4;
	far = fmax(far, 2.0 * near);
	h = tan(cam->fov_deg * pi / 360.0) * near;
	w = cam->aspect > 0.0 ? tan(cam->aspect * cam->fov_deg * pi / 360.0) * near : h;
	glMatrixMode(GL_PROJECTION);
	glLoadIdentity();
	glFrustum(-w, w, -h, h, near, far);
	glMatrixMode(GL_MODELVIEW);
	glLoadMatrixd(view);
}

/* Positions and spot directions are set under the view matrix, so GL
 * keeps them in world space.  A spotlight's hard edge is lit per vertex,
 * and its falloff (as any light's) is GL's quadratic attenuation: close,
 * not exact. */
static void set_lights(const struct draw *dr, const struct scene *s)
{
	static const GLfloat black[4] = { 0, 0, 0, 1 };
	static const GLfloat white[4] = { 1, 1, 1, 1 };
	int i;

	glLightModelfv(GL_LIGHT_MODEL_AMBIENT, white);
	glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
	glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
	for (i = 0; i < dr->n_lights; i++) {
		const struct light *l = scene_light(s, i);
		GLfloat pos[4] = { (GLfloat)l->pos.x, (GLfloat)l->pos.y, (GLfloat)l->pos.z, 1 };
		GLfloat col[4] = { (GLfloat)l->color.r, (GLfloat)l->color.g, (GLfloat)l->color.b, 1 };
		glEnable(GL_LIGHT0 + i);
		glLightfv(GL_LIGHT0 + i, GL_POSITION, pos);
		glLightfv(GL_LIGHT0 + i, GL_AMBIENT, black);
		glLightfv(GL_LIGHT0 + i, GL_DIFFUSE, col);
		glLightfv(GL_LIGHT0 + i, GL_SPECULAR, col);
		glLightf(GL_LIGHT0 + i, GL_CONSTANT_ATTENUATION, 1.0f);
		glLightf(GL_LIGHT0 + i, GL_LINEAR_ATTENUATION, 0.0f);
		glLightf(GL_LIGHT0 + i, GL_QUADRATIC_ATTENUATION,
			 (GLfloat)light_marker_gl_quadratic(l));
		glLightf(GL_LIGHT0 + i, GL_SPOT_CUTOFF, (GLfloat)light_marker_gl_cutoff(l));
		glLightf(GL_LIGHT0 + i, GL_SPOT_EXPONENT, 0.0f);
		if (l->spot) {
			GLfloat dir[3] = { (GLfloat)l->axis.x, (GLfloat)l->axis.y,
					   (GLfloat)l->axis.z };
			glLightfv(GL_LIGHT0 + i, GL_SPOT_DIRECTION, dir);
		}
	}
}

static void draw_vertex(struct vec3 p)
{
	glVertex3d(p.x, p.y, p.z);
}

/* Each light as a dot in its colour; a spotlight also as a cone of lines
 * along its axis, opening at its cutoff. */
static void draw_lights(const struct draw *dr, const struct scene *s)
{
	size_t i;
	int k;

	glDisable(GL_LIGHTING);
	glPointSize(9.0f);
	glBegin(GL_POINTS);
	for (i = 0; i < scene_light_count(s); i++) {
		const struct light *l = scene_light(s, i);
		glColor3d(l->color.r, l->color.g, l->color.b);
		draw_vertex(l->pos);
	}
	glEnd();
	glLineWidth(1.5f);
	glBegin(GL_LINES);
	for (i = 0; i < scene_light_count(s); i++) {
		const struct light *l = scene_light(s, i);
		struct light_marker mk;

		light_marker_make(l, dr->marker_length, &mk);
		if (!mk.n_rim)
			continue;
		glColor3d(l->color.r, l->color.g, l->color.b);
		draw_vertex(mk.apex);
		draw_vertex(mk.tip);
		for (k = 0; k < mk.n_rim; k++) {
			draw_vertex(mk.apex);
			draw_vertex(mk.rim[k]);
			draw_vertex(mk.rim[k]);
			draw_vertex(mk.rim[(k + 1) % mk.n_rim]);
		}
	}
	glEnd();
}

void draw_frame(const struct draw *dr, const struct scene *s, const struct fly_camera *cam,
		int x, int y, int size)
{
	glClearColor(0, 0, 0, 1);
	glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
	glViewport(x, y, size, size);
	glEnable(GL_DEPTH_TEST);
	glShadeModel(GL_SMOOTH);
	set_view(cam, dr);
	set_lights(dr, s);
	glEnable(GL_LIGHTING);
	glCallList(dr->list);
	draw_lights(dr, s);
}
