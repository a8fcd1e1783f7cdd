/* The causes: their texts, and how each renders (the rules broken, the
 * settings changed, another floor, the pixel's corner, the colour's
 * curve, the pixel's place), in each of its common forms. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "grade/grade_impl.h"
#include "scene/scene_impl.h"

/* The causes, one row each: their texts, the reference's pixels moved
 * (a transform's map) and the shading rule broken; the rest of a cause
 * (its forms) is grade_variant_of's.  rank.c, the programs' words, the
 * JSON and the HTML read them from here. */
static const struct grade_cause_row {
	struct grade_cause_text text;
	unsigned map;		/* GRADE_MAP_*: a transform of the reference; 0 for a render */
	unsigned rule;		/* RT_RULE_*: the rule it breaks, rendered; 0 for none */
	unsigned floor;		/* GRADE_FLOOR_*: the parts of the floor it changes */
} grade_causes[RT_CAUSE_COUNT] = {
	[RT_CAUSE_MIRRORED] = { .text = { "mirrored", "the image mirrored left-right",
		"the camera's right vector has the wrong sign: right = forward x up, and pixel i "
		"(from the left) goes to column i" },
		.map = GRADE_MAP_MIRROR },
	[RT_CAUSE_UPSIDE_DOWN] = { .text = { "upside-down", "the image upside down",
		"BMP rows go bottom-up: write image row j to file row height-1-j (or the up "
		"vector's sign is wrong)" },
		.map = GRADE_MAP_FLIP },
	[RT_CAUSE_TRANSPOSED] = { .text = { "transposed", "i and j swapped (the image transposed)",
		"pixel (i, j) is column i, row j: swap i and j where the ray is built or the "
		"pixel is stored" },
		.map = GRADE_MAP_TRANSPOSE },
	[RT_CAUSE_RED_BLUE] = { .text = { "red-blue", "red and blue swapped",
		"BMP stores each pixel as blue, green, red: write the bytes in that order" },
		.map = GRADE_MAP_RED_BLUE },
	[RT_CAUSE_GAMMA] = { .text = { "gamma", "gamma encoding applied",
		"write round(255 c) with no gamma encoding: the assignment's colours are linear" } },
	[RT_CAUSE_WHITE_SPECULAR] = { .text = { "white-highlight", "the highlight left white",
		"multiply the specular term by the object colour: Lc ks (R.L)^n C" },
		.rule = RT_RULE_WHITE_SPECULAR },
	[RT_CAUSE_NO_SHADOWS] = { .text = { "no-shadows", "no shadows",
		"cast a shadow ray from the hit point to each light and skip the light when an "
		"object is nearer than the light" },
		.rule = RT_RULE_NO_SHADOWS },
	[RT_CAUSE_LIGHT_BEHIND] = { .text = { "light-behind", "lights behind the surface still lighting it",
		"skip a light when N.L <= 0, its specular highlight included" },
		.rule = RT_RULE_LIGHT_BEHIND },
	[RT_CAUSE_RECURSION_FEWER] = { .text = { "recursion-fewer", "one reflection level too few",
		"trace the reflected ray while level < recursion level, with the primary ray at "
		"level 1" } },
	[RT_CAUSE_RECURSION_MORE] = { .text = { "recursion-more", "one reflection level too many",
		"stop reflecting at the recursion level: a primary ray is level 1, and recursion "
		"level 1 means no reflection" } },
	[RT_CAUSE_CLAMP_OTHER] = { .text = { "clamp-final", "colours clamped only at the end",
		"clamp each channel to [0, 1] at every recursion level, before it is scaled by kr" } },
	[RT_CAUSE_NEVER_CLAMP] = { .text = { "no-clamp", "colours never clamped (bytes wrapping round)",
		"clamp each channel to [0, 1] at every level and before the conversion to 0..255" } },
	[RT_CAUSE_PIXEL_CORNERS] = { .text = { "pixel-corners", "rays through the pixels' corners",
		"aim each primary ray at the centre of its pixel: (i + 0.5, j + 0.5)" } },
	[RT_CAUSE_UNIT_STARTS] = { .text = { "unit-offset", "shadow and reflected rays started 1 unit out",
		"start shadow and reflected rays at intersection + direction * epsilon with a tiny "
		"epsilon (1e-6), not the handout's * 1" },
		.rule = RT_RULE_UNIT_STARTS },
	[RT_CAUSE_FLOOR_SWAPPED] = { .text = { "floor-swapped", "the floor's tiles swapped",
		"tile (i, j) is white when i + j is even: i = floor((x + width / 2) / cell), j "
		"likewise (the classic floor: floor((x + 500) / 20))" },
		.rule = RT_RULE_FLOOR_SWAPPED },
	[RT_CAUSE_NO_REFLECTIONS] = { .text = { "no-reflections", "no reflections (recursion level 1)",
		"add kr I(P + eps R, R) for each hit while level < the file's recursion level (its "
		"first number; a primary ray is level 1)" } },
	[RT_CAUSE_RECURSION_LEVEL] = { .text = { "recursion-level", "another recursion level",
		"read the recursion level from the file (its first number) and trace reflections "
		"while level < it, the primary ray at level 1" } },
	[RT_CAUSE_FLOOR_HORIZON] = { .text = { "floor-horizon", "the floor reaching the horizon",
		"the floor is a square of the file's width centred on the origin (|x|, |y| < "
		"width / 2): a ray that meets z = 0 outside it hits no floor" },
		.floor = GRADE_FLOOR_HALF },
	[RT_CAUSE_FLOOR_SIZE] = { .text = { "floor-size", "the floor of another width",
		"make the floor the dialect's width (1000; --floor WIDTH,TILE when the assignment "
		"says otherwise)" },
		.floor = GRADE_FLOOR_HALF | GRADE_FLOOR_ORIGIN },
	[RT_CAUSE_FLOOR_CELL] = { .text = { "floor-cell", "the checker's cells of another size",
		"make the cells the dialect's width (20 classic and spot, 30 pyramid, the header's "
		"CELL in nearfar)" },
		.floor = GRADE_FLOOR_CELL },
	[RT_CAUSE_FLOOR_PLACE] = { .text = { "floor-place", "the floor with a corner at the origin",
		"centre the floor on the origin: it covers -width / 2 <= x, y < width / 2" },
		.floor = GRADE_FLOOR_CENTRE | GRADE_FLOOR_ORIGIN },
	[RT_CAUSE_CHECKER_PHASE] = { .text = { "checker-phase", "the checker's cells counted from another origin",
		"count the cells from the floor's corner: i = floor((x + width / 2) / cell), j "
		"likewise (nearfar's endless floor: from the origin, i = floor(x / cell))" },
		.floor = GRADE_FLOOR_ORIGIN },
	[RT_CAUSE_SPOT_CONE] = { .text = { "spot-cone", "the spotlights' cone of another width",
		"light P only when the angle between P - position and the axis is at most the "
		"cutoff, in degrees: cos(angle) >= cos(cutoff * pi / 180), with pi in parentheses "
		"if it is a macro" } },
	[RT_CAUSE_FLOOR_FINISH] = { .text = { "floor-finish", "the floor's own coefficients",
		"give the floor the assignment's finish (the classic floor: ambient 0.4, diffuse "
		"0.2, specular 0.2, reflection 0.2, shininess 1; nearfar: the file's header)" },
		.floor = GRADE_FLOOR_FINISH },
};

static const struct grade_cause_text grade_clamp_level_text = {
	"clamp-level", "colours clamped at every level",
	"with --clamp final, clamp only the finished pixel (as POV-Ray does)"
};

const struct grade_cause_text *grade_cause_text(enum grade_cause c, enum clamp_mode clamp)
{
	if (c == RT_CAUSE_CLAMP_OTHER && clamp == RT_CLAMP_FINAL)
		return &grade_clamp_level_text;
	return &grade_causes[c].text;
}

bool grade_cause_is_transform(enum grade_cause c)
{
	return (unsigned)c < RT_CAUSE_COUNT && grade_causes[c].map != 0;
}

bool grade_cause_moves_pixels(enum grade_cause c)
{
	return (unsigned)c < RT_CAUSE_COUNT &&
	       (grade_causes[c].map & (GRADE_MAP_MIRROR | GRADE_MAP_FLIP | GRADE_MAP_TRANSPOSE)) != 0;
}

unsigned grade_cause_map(enum grade_cause c)
{
	return (unsigned)c < RT_CAUSE_COUNT ? grade_causes[c].map : 0u;
}

/* The other recursion levels tried (RT_CAUSE_RECURSION_LEVEL's forms):
 * two and three more, then two fewer, three fewer, ... down to 2 (one
 * more, one fewer and 1 are causes of their own). */
static int grade_other_level(int recursion, int form)
{
	int level;

	if (form < 2)
		return recursion + 2 + form <= RT_MAX_RECURSION ? recursion + 2 + form : 0;
	level = recursion - 2 - (form - 2);
	return level >= 2 ? level : 0;
}

/* The floor the scene has: its half width (INFINITY for nearfar's) and
 * cell; false when there is none. */
static bool grade_scene_floor(const struct grade_job *job, double *half, double *cell)
{
	const struct scene_view *v = scene_view_of(job->scene);

	if (!job->scene->floor)
		return false;
	*half = v->floor_width == INFINITY ? INFINITY : 0.5 * v->floor_width;
	*cell = v->floor_cell;
	return true;
}

static const double grade_width_factors[] = { 0.4, 0.5, 2.0, 3.0, 5.0 };
static const double grade_cells[] = { 10.0, 15.0, 20.0, 25.0, 30.0, 40.0, 50.0 };

/* The spotlights' cones as students get them wrong (RT_CAUSE_SPOT_CONE's
 * forms): cos() of the degrees, no cone at all, the cutoff as the full
 * angle, the angle through `#define PI 2*acos(0.0)` (a cone pi^2 / 4
 * times narrower), no spotlights. */
static const unsigned grade_spot_rules[] = {
	RT_RULE_SPOT_COS_DEGREES, RT_RULE_SPOT_NO_CONE, RT_RULE_SPOT_FULL_ANGLE,
	RT_RULE_SPOT_PI_MACRO, RT_RULE_SPOT_UNLIT,
};
static const char *const grade_spot_details[] = {
	"cos(cutoff) of the degrees", "no cone: lit every way", "the cutoff as the full angle",
	"PI a macro without parentheses: 2.47 times narrower", "the spotlights left out",
};

static bool grade_has_spotlight(const struct grade_job *job)
{
	size_t i;

	for (i = 0; i < job->scene->n_lights; i++)
		if (job->scene->lights[i].spot)
			return true;
	return false;
}

/* The scene's own floor as another floor's starting point (not moved:
 * the scene floor's shape and cells render); false when there is none. */
static bool grade_floor_as_scene(const struct grade_job *job, struct shade_floor *fl)
{
	double half, cell;

	memset(fl, 0, sizeof(*fl));
	if (!grade_scene_floor(job, &half, &cell))
		return false;
	fl->half = half;
	fl->cell = cell;
	/* The contract's cells: from the corner of a finite floor, from the
	 * origin of an endless one. */
	fl->ox = fl->oy = half == INFINITY ? 0.0 : -half;
	return true;
}

/* The other floor of a floor cause's form; false for no such form. */
static bool grade_floor_form(const struct grade_job *job, enum grade_cause c, int form,
			     struct shade_floor *fl)
{
	double half, cell;

	if (!grade_floor_as_scene(job, fl))
		return false;
	fl->moved = true;
	half = fl->half;
	cell = fl->cell;
	switch (c) {
	case RT_CAUSE_FLOOR_HORIZON:
		if (form > 0 || half == INFINITY)
			return false;
		fl->half = INFINITY;
		return true;
	case RT_CAUSE_FLOOR_SIZE:
		if (half == INFINITY || form >= (int)(sizeof(grade_width_factors) / sizeof(double)))
			return false;
		fl->half = half * grade_width_factors[form];
		fl->ox = fl->oy = -fl->half;
		return true;
	case RT_CAUSE_FLOOR_CELL:
		if (form >= (int)(sizeof(grade_cells) / sizeof(double)) || grade_cells[form] == cell)
			return false;
		fl->cell = grade_cells[form];
		return true;
	case RT_CAUSE_FLOOR_PLACE:
		/* The square [0, width)^2 and its three mirror images: the
		 * centre a half width off along each axis, the cells counted
		 * from its own corner. */
		if (half == INFINITY || form >= 4)
			return false;
		fl->cx = form & 1 ? -half : half;
		fl->cy = form & 2 ? -half : half;
		fl->ox = fl->cx - half;
		fl->oy = fl->cy - half;
		return true;
	case RT_CAUSE_CHECKER_PHASE:
		if (form == 0 && half != INFINITY)
			fl->ox = fl->oy = 0.0;
		else if (form == 1)
			fl->ox = fl->oy = 0.5 * cell;
		else if (form == 2 && half != INFINITY)
			fl->ox = fl->oy = -half + 0.5 * cell;
		else
			return false;
		/* The same cells, when the corner is a whole number of pairs of
		 * cells from the origin, change nothing. */
		return fmod(fabs(fl->ox - (half == INFINITY ? 0.0 : -half)), 2.0 * cell) != 0.0;
	default:
		return false;
	}
}

void grade_variant_plain(const struct grade_job *job, struct grade_variant *v)
{
	memset(v, 0, sizeof(*v));
	v->settings = job->settings;
}

/* Long: the causes' forms, a case each in one switch. */
bool grade_variant_of(const struct grade_job *job, enum grade_cause c, int form,
		      struct grade_variant *v)
{
	const int recursion = job->settings.recursion;

	grade_variant_plain(job, v);
	if (form < 0 || form >= GRADE_VARIANTS)
		return false;
	v->rules = grade_causes[c].rule;
	v->use_rules = v->rules != 0;
	switch (c) {
	case RT_CAUSE_MIRRORED:
	case RT_CAUSE_UPSIDE_DOWN:
	case RT_CAUSE_RED_BLUE:
		v->map = grade_cause_map(c);
		return form == 0;
	case RT_CAUSE_TRANSPOSED:
		v->map = GRADE_MAP_TRANSPOSE;
		return form == 0 && job->camera->width == job->camera->height && job->camera->width > 1;
	case RT_CAUSE_GAMMA:
		/* The curve on the linear colour, before either conversion:
		 * (unsigned char)(255 pow(c, 1 / 2.2)) truncates the encoded
		 * value, not the reference's byte. */
		v->gamma = form + 1;
		return form < 2;
	case RT_CAUSE_LIGHT_BEHIND:
		/* Its highlight only; its diffuse term too (two-sided, |N.L|);
		 * its diffuse term signed (no test at all: kd N.L darkens). */
		v->rules |= form == 1 ? RT_RULE_TWO_SIDED : form == 2 ? RT_RULE_SIGNED_DIFFUSE : 0u;
		return form < 3;
	case RT_CAUSE_RECURSION_FEWER:
		v->settings.recursion = recursion - 1;
		return form == 0 && recursion >= 2;
	case RT_CAUSE_RECURSION_MORE:
		v->settings.recursion = recursion + 1;
		return form == 0 && recursion < RT_MAX_RECURSION;
	case RT_CAUSE_NO_REFLECTIONS:
		v->settings.recursion = 1;
		return form == 0 && recursion >= 3;
	case RT_CAUSE_RECURSION_LEVEL:
		v->settings.recursion = grade_other_level(recursion, form);
		return v->settings.recursion > 0;
	case RT_CAUSE_CLAMP_OTHER:
		v->settings.clamp = job->settings.clamp == RT_CLAMP_LEVEL ? RT_CLAMP_FINAL : RT_CLAMP_LEVEL;
		return form == 0;
	case RT_CAUSE_NEVER_CLAMP:
		/* No clamping at any level (render_trace with --clamp final
		 * leaves the colour as it is) and bytes that wrap, made in the
		 * conversion so that one trace gives both the rounded and the
		 * truncated byte; RT_RULE_NEVER_CLAMP is the rounded one alone. */
		v->settings.clamp = RT_CLAMP_FINAL;
		v->wrap = true;
		return form == 0;
	case RT_CAUSE_PIXEL_CORNERS:
		/* (i, j), the top-left corner, and the three others. */
		v->corner = true;
		v->cx = form & 1 ? 1.0 : 0.0;
		v->cy = form & 2 ? 1.0 : 0.0;
		return form < 4;
	case RT_CAUSE_FLOOR_HORIZON:
	case RT_CAUSE_FLOOR_SIZE:
	case RT_CAUSE_FLOOR_CELL:
	case RT_CAUSE_FLOOR_PLACE:
	case RT_CAUSE_CHECKER_PHASE:
		v->use_rules = true;
		v->other_floor = true;
		v->floor_changes = grade_causes[c].floor;
		return grade_floor_form(job, c, form, &v->floor);
	case RT_CAUSE_FLOOR_FINISH:
		/* The scene floor's shape with the finish fitted (its shape's
		 * parts the scene's, for a floor cause to combine with). */
		if (form >= job->n_floor_finishes || form >= 2 || !grade_floor_as_scene(job, &v->floor))
			return false;
		v->use_rules = true;
		v->other_floor = true;
		v->floor_changes = GRADE_FLOOR_FINISH;
		v->floor.own_finish = true;
		v->floor.finish = job->floor_finishes[form];
		return true;
	case RT_CAUSE_SPOT_CONE:
		if (form >= (int)(sizeof(grade_spot_rules) / sizeof(grade_spot_rules[0])) ||
		    !grade_has_spotlight(job))
			return false;
		v->rules = grade_spot_rules[form];
		v->use_rules = true;
		return true;
	default:
		return form == 0;
	}
}

bool grade_variant_combine(const struct grade_variant *a, const struct grade_variant *b,
			   struct grade_variant *out)
{
	const struct render_settings *base = &a->settings;

	*out = *a;
	if ((a->floor_changes & b->floor_changes) || (a->corner && b->corner) || (a->gamma && b->gamma) ||
	    (a->wrap && b->wrap) || (a->map & b->map) || ((a->rules & b->rules) != 0))
		return false;
	out->rules |= b->rules;
	out->use_rules = a->use_rules || b->use_rules;
	out->map |= b->map;
	out->gamma = a->gamma ? a->gamma : b->gamma;
	out->wrap = a->wrap || b->wrap;
	if (b->corner) {
		out->corner = true;
		out->cx = b->cx;
		out->cy = b->cy;
	}
	if (b->other_floor && !a->other_floor) {
		out->other_floor = true;
		out->floor = b->floor;
		out->floor_changes = b->floor_changes;
	} else if (b->other_floor) {
		/* b's parts of the floor over a's (both made from the scene's). */
		out->floor_changes |= b->floor_changes;
		out->floor.moved = a->floor.moved || b->floor.moved;
		if (b->floor_changes & GRADE_FLOOR_FINISH) {
			out->floor.own_finish = true;
			out->floor.finish = b->floor.finish;
		}
		if (b->floor_changes & GRADE_FLOOR_HALF)
			out->floor.half = b->floor.half;
		if (b->floor_changes & GRADE_FLOOR_CELL)
			out->floor.cell = b->floor.cell;
		if (b->floor_changes & GRADE_FLOOR_ORIGIN) {
			out->floor.ox = b->floor.ox;
			out->floor.oy = b->floor.oy;
		}
		if (b->floor_changes & GRADE_FLOOR_CENTRE) {
			out->floor.cx = b->floor.cx;
			out->floor.cy = b->floor.cy;
		}
	}
	/* b's settings where they are not the plain ones (the caller
	 * combines only forms of one job). */
	if (b->settings.recursion != base->recursion) {
		out->settings.recursion = b->settings.recursion;
	}
	if (b->settings.clamp != base->clamp)
		out->settings.clamp = b->settings.clamp;
	return true;
}

/* "ka kd ks kr 0.25 0.25 0.25 0.25, shininess 15, not 0.4 0.2 0.2 0.2, 1"
 * (%g: the fit rounds its values where a round value fits as well). */
static void grade_finish_words(const struct material *m, const struct material *was, char *buf,
			       size_t size)
{
	snprintf(buf, size, "ka kd ks kr %.3g %.3g %.3g %.3g, shininess %.3g, not %.3g %.3g %.3g %.3g, "
		 "%.3g", m->ka, m->kd, m->ks, m->kr, m->shininess, was->ka, was->kd, was->ks, was->kr,
		 was->shininess);
}

void grade_cause_detail(const struct grade_job *job, enum grade_cause c, int form, char *buf,
			size_t size)
{
	struct grade_variant v;
	double half = 0.0, cell = 0.0;

	buf[0] = '\0';
	if (!grade_variant_of(job, c, form, &v))
		return;
	grade_scene_floor(job, &half, &cell);
	switch (c) {
	case RT_CAUSE_GAMMA:
		snprintf(buf, size, form == 0 ? "the sRGB curve" : "c^(1/2.2)");
		break;
	case RT_CAUSE_LIGHT_BEHIND:
		snprintf(buf, size, form == 0 ? "its highlight" : form == 1 ? "lit from both sides"
			 : "its diffuse term negative");
		break;
	case RT_CAUSE_RECURSION_LEVEL:
		snprintf(buf, size, "recursion level %d instead of %d", v.settings.recursion,
			 job->settings.recursion);
		break;
	case RT_CAUSE_PIXEL_CORNERS:
		snprintf(buf, size, "the %s %s corners", form & 2 ? "bottom" : "top",
			 form & 1 ? "right" : "left");
		break;
	case RT_CAUSE_FLOOR_SIZE:
		snprintf(buf, size, "%g wide instead of %g", 2.0 * v.floor.half, 2.0 * half);
		break;
	case RT_CAUSE_FLOOR_CELL:
		snprintf(buf, size, "cells %g wide instead of %g", v.floor.cell, cell);
		break;
	case RT_CAUSE_FLOOR_PLACE:
		snprintf(buf, size, "x from %g to %g, y from %g to %g", v.floor.cx - v.floor.half,
			 v.floor.cx + v.floor.half, v.floor.cy - v.floor.half, v.floor.cy + v.floor.half);
		break;
	case RT_CAUSE_SPOT_CONE:
		snprintf(buf, size, "%s", grade_spot_details[form]);
		break;
	case RT_CAUSE_FLOOR_FINISH:
		grade_finish_words(&v.floor.finish, &job->scene->floor->mat, buf, size);
		break;
	case RT_CAUSE_CHECKER_PHASE:
		snprintf(buf, size, form == 0 ? "from the origin" : form == 1
			 ? "from the origin, half a cell off" : "from the corner, half a cell off");
		break;
	default:
		break;
	}
}
