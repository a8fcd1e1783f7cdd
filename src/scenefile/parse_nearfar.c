/* The grammar of the nearfar dialect (Jul 2018 and Jan 2023,
 * description.txt; scene-format.md "Dialect nearfar"): a header with the
 * camera's near plane, field of view and aspect, the infinite
 * checkerboard's cell and coefficients, then spheres, pyramids and cubes,
 * point lights and spotlights with an exponential falloff.  The first
 * revision of the Jan 2023 handout puts a colour line in every light; a
 * file is read that way when only that layout fits its counts. */
#include <math.h>
#include <string.h>

#include "scenefile/parse_private.h"
#include "whitted/scenefile.h"

/* The numbers a light takes: x y z [R G B] falloff for a point light, and
 * a look-at point and a cutoff more for a spotlight. */
#define NEARFAR_POINT(colour) ((colour) ? 7L : 4L)
#define NEARFAR_SPOT(colour) ((colour) ? 11L : 8L)

/* Whether the n numbers from the k-th ahead are exactly P point lights, a
 * spotlight count S and S spotlights in the layout with or without
 * colours, P being the number at k - 1 (or given). */
static bool nearfar_layout_fits(const struct parser *p, long k, long n, long points, bool colour)
{
	long at = k + points * NEARFAR_POINT(colour);
	double spots;

	if (n < points * NEARFAR_POINT(colour) + 1 || !parse_number_ahead(p, at, &spots) ||
	    spots != floor(spots) || spots < 0 || spots > RT_MAX_LIGHTS)
		return false;
	return n == points * NEARFAR_POINT(colour) + 1 + (long)spots * NEARFAR_SPOT(colour);
}

bool parse_nearfar_fits_without_objects(const struct parser *p, long n)
{
	double objects, points;

	if (!parse_number_ahead(p, 10, &objects) || objects != 0.0 ||
	    !parse_number_ahead(p, 11, &points) || points != floor(points) || points < 0 ||
	    points > RT_MAX_LIGHTS)
		return false;
	return nearfar_layout_fits(p, 12, n - 12, (long)points, false) ||
	       nearfar_layout_fits(p, 12, n - 12, (long)points, true);
}

/* NEAR FAR FOVY ASPECT: the view, checked as the handout's rules need. */
static int nearfar_view(struct parser *p, struct scene_view *v)
{
	int rc;

	if ((rc = parser_positive(p, "near distance", &v->near)) < 0 ||
	    (rc = parser_number(p, "far distance", &v->far)) < 0)
		return rc;
	if (!(v->far > v->near))
		return parser_fail(p, RT_E_RANGE, "the far distance must be beyond the near one (%g), found %g",
				   v->near, v->far);
	if ((rc = parser_number(p, "field of view along y", &v->fov_deg)) < 0)
		return rc;
	if (!(v->fov_deg > 0.0 && v->fov_deg < 180.0))
		return parser_fail(p, RT_E_RANGE,
				   "the field of view along y must be in (0, 180) degrees, found %g",
				   v->fov_deg);
	if ((rc = parser_positive(p, "aspect ratio", &v->aspect)) < 0)
		return rc;
	if (!(v->aspect * v->fov_deg < 180.0))
		return parser_fail(p, RT_E_RANGE,
				   "the field of view along x (aspect %g times %g degrees) must stay below 180 degrees",
				   v->aspect, v->fov_deg);
	return 0;
}

/* CELL KA KD KR: the infinite checkerboard, without specular. */
static int nearfar_floor(struct parser *p, struct scene_view *v)
{
	int rc;

	v->floor_width = INFINITY;
	if ((rc = parser_positive(p, "checkerboard cell width", &v->floor_cell)) < 0 ||
	    (rc = parser_non_negative(p, "checkerboard ambient coefficient", &v->floor_mat.ka)) < 0 ||
	    (rc = parser_non_negative(p, "checkerboard diffuse coefficient", &v->floor_mat.kd)) < 0 ||
	    (rc = parser_non_negative(p, "checkerboard reflection coefficient", &v->floor_mat.kr)) < 0)
		return rc;
	v->floor_mat.ks = 0.0;
	return 0;
}

/* One light: position, the colour line when the file has them, falloff;
 * for a spotlight the look-at point and the cutoff. */
static int nearfar_light(struct parser *p, struct scene *s, bool spot, bool colour)
{
	struct light l;
	struct vec3 look;
	int rc;

	memset(&l, 0, sizeof(l));
	l.color = color_make(1.0, 1.0, 1.0);
	if ((rc = parser_vec3(p, spot ? "spotlight position" : "light position", &l.pos)) < 0 ||
	    (colour && (rc = parse_light_colour(p, &l.color)) < 0) ||
	    (rc = parser_non_negative(p, "light falloff", &l.falloff)) < 0)
		return rc;
	if (!spot)
		return scene_add_light_full(s, &l, p->d);
	if ((rc = parser_vec3(p, "spotlight look-at point", &look)) < 0)
		return rc;
	l.axis = vec3_sub(look, l.pos);
	if (!(vec3_dot(l.axis, l.axis) > 0.0))
		return parser_fail(p, RT_E_RANGE, "the spotlight looks at its own position");
	if ((rc = parse_cutoff(p, &l.cutoff_deg)) < 0)
		return rc;
	return parse_add_spot(p, s, &l);
}

static int nearfar_lights(struct parser *p, struct scene *s, long objects)
{
	long points, spots, i, n;
	bool colour;
	int rc;

	if ((rc = parse_count(p, "point light count", RT_MAX_LIGHTS, objects, &points)) < 0)
		return rc;
	n = parse_count_numbers(p, 2 + (points + RT_MAX_LIGHTS) * NEARFAR_SPOT(true));
	colour = !nearfar_layout_fits(p, 0, n, points, false) &&
		 nearfar_layout_fits(p, 0, n, points, true);
	if (colour)
		parser_note(p, p->last.line,
			    "each light has a colour line before its falloff (the first revision of "
			    "the Jan 2023 handout): the colours are used");
	for (i = 0; i < points; i++)
		if ((rc = nearfar_light(p, s, false, colour)) < 0)
			return rc;
	if ((rc = parse_count(p, "spotlight count", RT_MAX_LIGHTS, objects, &spots)) < 0)
		return rc;
	for (i = 0; i < spots; i++)
		if ((rc = nearfar_light(p, s, true, colour)) < 0)
			return rc;
	return 0;
}

int parse_nearfar(struct parser *p, struct scene *s, int threads)
{
	struct scene_view view;
	long objects;
	int rc;

	p->dialects = RT_DIALECT_BIT(RT_DIALECT_NEARFAR);
	p->dialect_name = scene_dialect_name(RT_DIALECT_NEARFAR);
	scene_view_default(&view);
	view.dialect = RT_DIALECT_NEARFAR;
	if ((rc = nearfar_view(p, &view)) < 0 || (rc = parse_recursion(p, s)) < 0 ||
	    (rc = parse_image_size(p, s)) < 0 || (rc = nearfar_floor(p, &view)) < 0 ||
	    (rc = parse_objects(p, s, threads, &objects)) < 0 ||
	    (rc = nearfar_lights(p, s, objects)) < 0)
		return rc;
	scene_set_view(s, &view);
	return parse_end(p, "last spotlight");
}
