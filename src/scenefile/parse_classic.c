/* The grammar of the classic family of scene files (scene-format.md):
 * `classic` (point lights with or without colours), `spot` (a section of
 * spotlights after the point lights) and `pyramid` (the 2019 files, whose
 * objects include the corner-placed pyramid, with 30-wide floor cells and a
 * 90 degree view).  Which of the three a file is comes from its data: a
 * pyramid among the objects, or numbers after the point lights that are
 * exactly a spotlight section. */
#include <math.h>
#include <string.h>

#include "scenefile/parse_private.h"
#include "whitted/scenefile.h"

/* A light's colour: three numbers >= 0 (lights may be brighter than 1). */
int parse_light_colour(struct parser *p, struct color *out)
{
	int rc;

	if ((rc = parser_non_negative(p, "light colour component", &out->r)) < 0 ||
	    (rc = parser_non_negative(p, "light colour component", &out->g)) < 0 ||
	    (rc = parser_non_negative(p, "light colour component", &out->b)) < 0)
		return rc;
	return 0;
}

/* Point lights: position and colour each, or (the Jan 2018 copies) when
 * exactly 3 numbers a light follow, positions only and white.  Sets
 * *coloured to which it was. */
static int parse_point_lights(struct parser *p, struct scene *s, long count, bool *coloured)
{
	long available = parse_count_numbers(p, 6 * count);
	bool positions_only = count > 0 && available == 3 * count;
	long i;
	int rc;

	*coloured = !positions_only;
	for (i = 0; i < count; i++) {
		struct vec3 pos;
		struct color color = { 1.0, 1.0, 1.0 };
		if ((rc = parser_vec3(p, "light position", &pos)) < 0 ||
		    (!positions_only && (rc = parse_light_colour(p, &color)) < 0))
			return parse_light_count_hint(p, rc, count, available);
		if ((rc = scene_add_light(s, pos, color, p->d)) < 0)
			return rc;
	}
	return 0;
}

int parse_cutoff(struct parser *p, double *out)
{
	int rc = parser_number(p, "spotlight cutoff angle", out);

	if (rc < 0)
		return rc;
	if (!(*out > 0.0 && *out <= 180.0))
		return parser_fail(p, RT_E_RANGE,
				   "spotlight cutoff angle must be in (0, 180] degrees, found %g", *out);
	return 0;
}

int parse_add_spot(struct parser *p, struct scene *s, struct light *l)
{
	l->spot = true;
	return scene_add_light_full(s, l, p->d);
}

/* The spot dialect's spotlights: position, colour, axis, cutoff each. */
static int parse_spotlights(struct parser *p, struct scene *s, long count)
{
	long i;
	int rc;

	for (i = 0; i < count; i++) {
		struct light l;

		memset(&l, 0, sizeof(l));
		if ((rc = parser_vec3(p, "spotlight position", &l.pos)) < 0 ||
		    (rc = parse_light_colour(p, &l.color)) < 0 ||
		    (rc = parser_vec3(p, "spotlight direction", &l.axis)) < 0)
			return rc;
		if (!(vec3_dot(l.axis, l.axis) > 0.0))
			return parser_fail(p, RT_E_RANGE, "the spotlight's direction is zero");
		if ((rc = parse_cutoff(p, &l.cutoff_deg)) < 0 ||
		    (rc = parse_add_spot(p, s, &l)) < 0)
			return rc;
	}
	return 0;
}

/* Whether the numbers after the point lights are exactly a spotlight
 * section: a count N and 10 N numbers, up to a word or the end. */
static bool parse_spot_section_follows(const struct parser *p)
{
	long limit = 2 + 10 * RT_MAX_LIGHTS, n = parse_count_numbers(p, limit);
	double k;

	return n > 0 && n < limit && parse_number_ahead(p, 0, &k) && k == floor(k) && k >= 0 &&
	       (double)n == 1.0 + 10.0 * k;
}

/* The end of a classic file's data.  Numbers there that begin with a
 * whole number k may be a spotlight section whose count is wrong: the
 * message then says what such a section would need. */
static int parse_end_spot_hint(struct parser *p)
{
	long n = parse_count_numbers(p, 2 + 10 * RT_MAX_LIGHTS);
	double k = 0.0;
	bool counted = n >= 2 && parse_number_ahead(p, 0, &k);
	int rc = parse_end(p, "last light");
	size_t len;

	if (rc == 0 || !p->d || !counted)
		return rc;
	if (k >= 1 && k == floor(k) && k <= RT_MAX_LIGHTS) {
		len = strlen(p->d->msg);
		if (n - 1 == 10 * (long)k)
			snprintf(p->d->msg + len, sizeof(p->d->msg) - len,
				 "; they are a whole spotlight section (a count of %ld and %ld "
				 "numbers), which only the spot dialect has", (long)k, n - 1);
		else
			snprintf(p->d->msg + len, sizeof(p->d->msg) - len,
				 "; as a spotlight section, a count of %ld would need %ld numbers "
				 "after it, and %ld follow", (long)k, 10 * (long)k, n - 1);
	}
	return rc;
}

/* A pyramid among the objects makes a file of the family the pyramid
 * dialect: the only table of these three dialects that classic lacks. */
static bool parse_has_pyramid_only_objects(const struct scene *s)
{
	unsigned classic = RT_DIALECT_BIT(RT_DIALECT_CLASSIC);
	size_t i;

	for (i = 0; i < scene_shape_count(s); i++) {
		unsigned m = scene_shape(s, i)->ops->dialects;
		if (m != 0 && !(m & classic))
			return true;
	}
	return false;
}

int parse_classic(struct parser *p, struct scene *s, int threads, enum scene_dialect forced)
{
	enum scene_dialect dialect = forced;
	struct scene_view view;
	long objects, lights, spots;
	bool coloured;
	int rc;

	p->dialects = forced == RT_DIALECT_AUTO ? RT_DIALECT_CLASSIC_FAMILY : RT_DIALECT_BIT(forced);
	p->dialect_name = scene_dialect_name(forced == RT_DIALECT_AUTO ? RT_DIALECT_CLASSIC : forced);
	if ((rc = parse_recursion(p, s)) < 0 || (rc = parse_image_size(p, s)) < 0 ||
	    (rc = parse_objects(p, s, threads, &objects)) < 0)
		return rc;
	if (dialect == RT_DIALECT_AUTO && parse_has_pyramid_only_objects(s))
		dialect = RT_DIALECT_PYRAMID;
	if ((rc = parse_count(p, "light count", RT_MAX_LIGHTS, objects, &lights)) < 0 ||
	    (rc = parse_point_lights(p, s, lights, &coloured)) < 0)
		return rc;
	if (dialect == RT_DIALECT_AUTO)
		dialect = coloured && parse_spot_section_follows(p) ? RT_DIALECT_SPOT
								      : RT_DIALECT_CLASSIC;
	p->dialect_name = scene_dialect_name(dialect);
	if (dialect == RT_DIALECT_SPOT &&
	    ((rc = parse_count(p, "spotlight count", RT_MAX_LIGHTS, objects, &spots)) < 0 ||
	     (rc = parse_spotlights(p, s, spots)) < 0))
		return rc;
	scene_view_default(&view);
	view.dialect = dialect;
	if (dialect == RT_DIALECT_PYRAMID) {
		view.fov_deg = 90.0;
		view.floor_cell = 30.0;
	}
	scene_set_view(s, &view);
	if (dialect == RT_DIALECT_CLASSIC && coloured)
		return parse_end_spot_hint(p);
	return parse_end(p, dialect == RT_DIALECT_SPOT ? "last spotlight" : "last light");
}
