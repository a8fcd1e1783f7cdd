/* Drawing with OpenGL 1.x fixed function.  The projection is glFrustum on
 * the tracer's image plane: at distance 1 in front of the eye it spans
 * [-tan(fov/2), tan(fov/2)] both ways, and GL samples pixel centres as
 * camera_ray does, so a window of N x N pixels shows what an N x N render
 * shows.  Lighting is GL's Phong per vertex with the material's ka, kd, ks
 * and shininess and the scene's lights (no shadows, no reflections): close
 * enough to see the shapes as solid and to aim the camera. */
#include <GL/gl.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "draw.h"
#include "mesh.h"

/* Grid resolution for the longest axis of a quadric's box. */
#define DRAW_QUADRIC_CELLS 64
/* Floor quads per side: GL lights per vertex, so the floor needs vertices
 * under the highlights; the checker itself comes from the texture. */
#define DRAW_FLOOR_GRID 96

/* Widens box along one axis to take in [lo, hi]. */
static void box_include_axis(struct aabb *box, int axis, double lo, double hi)
{
	double *min = axis == 0 ? &box->min.x : axis == 1 ? &box->min.y : &box->min.z;
	double *max = axis == 0 ? &box->max.x : axis == 1 ? &box->max.y : &box->max.z;

	*min = fmin(*min, lo);
	*max = fmax(*max, hi);
}

struct aabb draw_scene_box(const struct scene *s)
{
	struct aabb box = { { INFINITY, INFINITY, INFINITY }, { -INFINITY, -INFINITY, -INFINITY } };
	struct shape_geometry g;
	double size;
	size_t i;
	int axis;

	for (i = 0; i < s->n_shapes; i++) {
		struct aabb b;
		shape_geometry(s->shapes[i], &g);
		if (g.kind == RT_SHAPE_FLOOR)
			continue;
		if (shape_bounds(s->shapes[i], &b)) {
			box = aabb_union(box, b);
		} else if (g.kind == RT_SHAPE_QUADRIC) {
			/* A quadric clipped on some axes still has a place
			 * along them. */
			for (axis = 0; axis < 3; axis++)
				if (g.u.quadric.clipped[axis])
					box_include_axis(&box, axis, vec3_component(g.u.quadric.lo, axis),
							 vec3_component(g.u.quadric.hi, axis));
		}
	}
	for (i = 0; i < s->n_lights; i++) {
		struct aabb b = { s->lights[i].pos, s->lights[i].pos };
		box = aabb_union(box, b);
	}
	if (!(box.min.x <= box.max.x)) {
		box.min = vec3_make(-100, -100, -100);
		box.max = vec3_make(100, 100, 100);
	}
	/* A flat box (one light, coplanar triangles) still needs a size. */
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

static void set_material(const struct material *m, struct color c)
{
	GLfloat amb[4] = { (GLfloat)(m->ka * c.r), (GLfloat)(m->ka * c.g), (GLfloat)(m->ka * c.b), 1 };
	GLfloat dif[4] = { (GLfloat)(m->kd * c.r), (GLfloat)(m->kd * c.g), (GLfloat)(m->kd * c.b), 1 };
	/* The format tints the highlight with the object's colour. */
	GLfloat spe[4] = { (GLfloat)(m->ks * c.r), (GLfloat)(m->ks * c.g), (GLfloat)(m->ks * c.b), 1 };
	GLfloat shine = (GLfloat)fmin(128.0, m->shininess);

	glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, amb);
	glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, dif);
	glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, spe);
	glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, shine);
}

static void emit_mesh(const struct mesh *m)
{
	size_t i;

	glBegin(GL_TRIANGLES);
	for (i = 0; i < m->n_vertices; i++) {
		const float *v = m->data + i * RT_MESH_FLOATS_PER_VERTEX;
		glNormal3fv(v + 3);
		glVertex3fv(v);
	}
	glEnd();
}

static void emit_triangle(const struct shape_geometry *g)
{
	const struct vec3 *v = g->u.triangle.v;
	struct vec3 n = vec3_normalize(vec3_cross(vec3_sub(v[1], v[0]), vec3_sub(v[2], v[0])));
	int k;

	glBegin(GL_TRIANGLES);
	glNormal3d(n.x, n.y, n.z);
	for (k = 0; k < 3; k++)
		glVertex3d(v[k].x, v[k].y, v[k].z);
	glEnd();
}

/* The floor's tile (i, j) is white when i + j is even: a 2 x 2 texture
 * repeated every two tiles, sampled without filtering. */
static unsigned make_floor_texture(void)
{
	static const GLubyte texels[2][2][3] = {
		{ { 255, 255, 255 }, { 0, 0, 0 } },
		{ { 0, 0, 0 }, { 255, 255, 255 } },
	};
	GLuint tex;

	glGenTextures(1, &tex);
	glBindTexture(GL_TEXTURE_2D, tex);
	glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
	glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
	glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
	glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
	glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
	glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 2, 2, 0, GL_RGB, GL_UNSIGNED_BYTE, texels);
	return tex;
}

static void emit_floor(const struct shape_geometry *g, unsigned tex)
{
	double half = 0.5 * g->u.floor.width, period = 2.0 * g->u.floor.tile;
	double cell = g->u.floor.width / DRAW_FLOOR_GRID;
	int i, j;

	glEnable(GL_TEXTURE_2D);
	glBindTexture(GL_TEXTURE_2D, tex);
	glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
	glNormal3d(0, 0, 1);
	glBegin(GL_QUADS);
	for (j = 0; j < DRAW_FLOOR_GRID; j++) {
		for (i = 0; i < DRAW_FLOOR_GRID; i++) {
			static const int corner[4][2] = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } };
			int k;
			for (k = 0; k < 4; k++) {
				double x = -half + (i + corner[k][0]) * cell;
				double y = -half + (j + corner[k][1]) * cell;
				/* Texture coordinates count tile pairs from the
				 * floor's corner, as the tile index does. */
				glTexCoord2d((x + half) / period, (y + half) / period);
				glVertex3d(x, y, 0.0);
			}
		}
	}
	glEnd();
	glDisable(GL_TEXTURE_2D);
}

/* Cells per axis in proportion to the box, at least 4 on each. */
static void quadric_cells(struct aabb box, int cells[3])
{
	struct vec3 e = vec3_sub(box.max, box.min);
	double longest = fmax(e.x, fmax(e.y, e.z));
	int axis;

	for (axis = 0; axis < 3; axis++) {
		double n = ceil(DRAW_QUADRIC_CELLS * vec3_component(e, axis) / longest);
		cells[axis] = n < 4 ? 4 : (int)n;
	}
}

/* Spheres get fewer facets when there are many of them. */
static void sphere_facets(size_t n_shapes, int *slices, int *stacks)
{
	*slices = n_shapes > 20000 ? 8 : n_shapes > 2000 ? 12 : 32;
	*stacks = *slices / 2;
}

static int emit_shape(const struct shape *sh, const struct shape_geometry *g,
		      struct aabb around, size_t n_shapes, struct draw *dr, struct diag *d)
{
	struct mesh m;
	int cells[3], slices, stacks, rc = 0;

	mesh_init(&m);
	switch (g->kind) {
	case RT_SHAPE_SPHERE:
		set_material(&sh->mat, sh->mat.color);
		sphere_facets(n_shapes, &slices, &stacks);
		rc = mesh_sphere(&m, g->u.sphere.centre, g->u.sphere.radius, slices, stacks);
		break;
	case RT_SHAPE_TRIANGLE:
		set_material(&sh->mat, sh->mat.color);
		emit_triangle(g);
		break;
	case RT_SHAPE_QUADRIC: {
		struct aabb box = mesh_quadric_region(g, around);
		set_material(&sh->mat, sh->mat.color);
		quadric_cells(box, cells);
		rc = mesh_quadric(&m, g->u.quadric.coef, box, cells);
		break;
	}
	case RT_SHAPE_FLOOR:
		/* White material; the texture turns half the tiles black. */
		set_material(&sh->mat, color_make(1, 1, 1));
		if (!dr->floor_texture)
			dr->floor_texture = make_floor_texture();
		emit_floor(g, dr->floor_texture);
		break;
	case RT_SHAPE_OTHER:
		break;
	}
	if (rc == 0 && m.n_vertices)
		emit_mesh(&m);
	mesh_free(&m);
	/* The meshes can fail only for memory. */
	if (rc < 0)
		return diag_set(d, RT_E_NOMEM, "", 0, 0, "out of memory for the shapes' meshes");
	return 0;
}

int draw_init(struct draw *dr, const struct scene *s, scene_note_fn *note, void *note_ctx,
	      struct diag *d)
{
	struct aabb box = draw_scene_box(s), around;
	struct vec3 e = vec3_sub(box.max, box.min), half;
	GLint max_lights = 8;
	size_t i;
	int rc = 0;

	memset(dr, 0, sizeof(*dr));
	/* Unclipped quadrics are drawn in a cube around the objects and
	 * lights, half again as wide as the box's longest side: a surface
	 * runs on past the scene, and a cone or hyperboloid spreads. */
	half = vec3_scale(vec3_make(1, 1, 1), 0.75 * fmax(e.x, fmax(e.y, e.z)));
	around.min = vec3_sub(aabb_centre(box), half);
	around.max = vec3_add(aabb_centre(box), half);
	dr->world = around;
	for (i = 0; i < s->n_shapes; i++) {
		struct aabb b;
		if (shape_bounds(s->shapes[i], &b))
			dr->world = aabb_union(dr->world, b);
	}
	glGetIntegerv(GL_MAX_LIGHTS, &max_lights);
	dr->n_lights = s->n_lights < (size_t)max_lights ? (int)s->n_lights : max_lights;
	if (note && s->n_lights > (size_t)max_lights) {
		struct diag n;
		diag_set(&n, RT_OK, "", 0, 0, "OpenGL lights the view with the first %d of the %zu lights"
			 " (the captures use them all)", max_lights, s->n_lights);
		note(note_ctx, &n);
	}
	dr->list = glGenLists(1);
	glNewList(dr->list, GL_COMPILE);
	for (i = 0; i < s->n_shapes && rc == 0; i++) {
		struct shape_geometry g;
		shape_geometry(s->shapes[i], &g);
		rc = emit_shape(s->shapes[i], &g, around, s->n_shapes, dr, d);
	}
	glEndList();
	return rc;
}

static void set_view(const struct fly_camera *cam, const struct draw *dr)
{
	const double pi = 3.14159265358979323846;
	struct vec3 f = cam->forward, u = cam->up, r = fly_camera_right(cam), e = cam->eye;
	struct vec3 centre = aabb_centre(dr->world);
	double radius = 0.5 * vec3_length(vec3_sub(dr->world.max, dr->world.min));
	double far = vec3_length(vec3_sub(e, centre)) + radius, near, h;
	/* Rows of the view matrix are right, up and -forward: GL looks down
	 * its -z axis.  Column-major for glLoadMatrixd. */
	const GLdouble view[16] = {
		r.x, u.x, -f.x, 0,
		r.y, u.y, -f.y, 0,
		r.z, u.z, -f.z, 0,
		-vec3_dot(r, e), -vec3_dot(u, e), vec3_dot(f, e), 1,
	};

	far *= 1.01;
	/* 24-bit depth keeps about four decades between the planes. */
	near = far * 1e-4;
	h = tan(cam->fov_deg * pi / 360.0) * near;
	glMatrixMode(GL_PROJECTION);
	glLoadIdentity();
	glFrustum(-h, h, -h, h, near, far);
	glMatrixMode(GL_MODELVIEW);
	glLoadMatrixd(view);
}

/* Positions are set under the view matrix, so GL keeps them in world
 * space. */
static void set_lights(const struct draw *dr, const struct scene *s)
{
	static const GLfloat black[4] = { 0, 0, 0, 1 };
	static const GLfloat white[4] = { 1, 1, 1, 1 };
	int i;

	glLightModelfv(GL_LIGHT_MODEL_AMBIENT, white);
	glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
	glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
	for (i = 0; i < dr->n_lights; i++) {
		const struct light *l = &s->lights[i];
		GLfloat pos[4] = { (GLfloat)l->pos.x, (GLfloat)l->pos.y, (GLfloat)l->pos.z, 1 };
		GLfloat col[4] = { (GLfloat)l->color.r, (GLfloat)l->color.g, (GLfloat)l->color.b, 1 };
		glEnable(GL_LIGHT0 + i);
		glLightfv(GL_LIGHT0 + i, GL_POSITION, pos);
		glLightfv(GL_LIGHT0 + i, GL_AMBIENT, black);
		glLightfv(GL_LIGHT0 + i, GL_DIFFUSE, col);
		glLightfv(GL_LIGHT0 + i, GL_SPECULAR, col);
	}
}

static void draw_lights(const struct scene *s)
{
	size_t i;

	glDisable(GL_LIGHTING);
	glPointSize(9.0f);
	glBegin(GL_POINTS);
	for (i = 0; i < s->n_lights; i++) {
		const struct light *l = &s->lights[i];
		glColor3d(l->color.r, l->color.g, l->color.b);
		glVertex3d(l->pos.x, l->pos.y, l->pos.z);
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
	draw_lights(s);
}
