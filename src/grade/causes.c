/* The causes: their texts, and how each renders (the rules broken, the
 * settings changed, the pixel's corner), in each of its common forms. */
#include "grade/grade_impl.h"
#include "render/shade_rules.h"

static const struct grade_cause_text grade_texts[RT_CAUSE_COUNT] = {
	[RT_CAUSE_MIRRORED] = { "mirrored", "the image mirrored left-right",
		"the camera's right vector has the wrong sign: right = forward x up, and pixel i "
		"(from the left) goes to column i" },
	[RT_CAUSE_UPSIDE_DOWN] = { "upside-down", "the image upside down",
		"BMP rows go bottom-up: write image row j to file row height-1-j (or the up "
		"vector's sign is wrong)" },
	[RT_CAUSE_TRANSPOSED] = { "transposed", "i and j swapped (the image transposed)",
		"pixel (i, j) is column i, row j: swap i and j where the ray is built or the "
		"pixel is stored" },
	[RT_CAUSE_RED_BLUE] = { "red-blue", "red and blue swapped",
		"BMP stores each pixel as blue, green, red: write the bytes in that order" },
	[RT_CAUSE_GAMMA] = { "gamma", "gamma encoding applied",
		"write round(255 c) with no gamma encoding: the assignment's colours are linear" },
	[RT_CAUSE_WHITE_SPECULAR] = { "white-highlight", "the highlight left white",
		"multiply the specular term by the object colour: Lc ks (R.L)^n C" },
	[RT_CAUSE_NO_SHADOWS] = { "no-shadows", "no shadows",
		"cast a shadow ray from the hit point to each light and skip the light when an "
		"object is nearer than the light" },
	[RT_CAUSE_LIGHT_BEHIND] = { "light-behind", "lights behind the surface still lighting it",
		"skip a light when N.L <= 0, its specular highlight included" },
	[RT_CAUSE_RECURSION_FEWER] = { "recursion-fewer", "one reflection level too few",
		"trace the reflected ray while level < recursion level, with the primary ray at "
		"level 1" },
	[RT_CAUSE_RECURSION_MORE] = { "recursion-more", "one reflection level too many",
		"stop reflecting at the recursion level: a primary ray is level 1, and recursion "
		"level 1 means no reflection" },
	[RT_CAUSE_CLAMP_OTHER] = { "clamp-final", "colours clamped only at the end",
		"clamp each channel to [0, 1] at every recursion level, before it is scaled by kr" },
	[RT_CAUSE_NEVER_CLAMP] = { "no-clamp", "colours never clamped (bytes wrapping round)",
		"clamp each channel to [0, 1] at every level and before the conversion to 0..255" },
	[RT_CAUSE_PIXEL_CORNERS] = { "pixel-corners", "rays through the pixels' corners",
		"aim each primary ray at the centre of its pixel: (i + 0.5, j + 0.5)" },
	[RT_CAUSE_UNIT_STARTS] = { "unit-offset", "shadow and reflected rays started 1 unit out",
		"start shadow and reflected rays at intersection + direction * epsilon with a tiny "
		"epsilon (1e-6), not the handout's * 1" },
	[RT_CAUSE_FLOOR_SWAPPED] = { "floor-swapped", "the floor's tiles swapped",
		"tile (i, j) is white when i + j is even: i = floor((x + 500) / tile width)" },
};

static const struct grade_cause_text grade_clamp_level_text = {
	"clamp-level", "colours clamped at every level",
	"with --clamp final, clamp only the finished pixel (as POV-Ray does)"
};

const struct grade_cause_text *grade_cause_text(enum grade_cause c, enum clamp_mode clamp)
{
	if (c == RT_CAUSE_CLAMP_OTHER && clamp == RT_CLAMP_FINAL)
		return &grade_clamp_level_text;
	return &grade_texts[c];
}

bool grade_cause_is_transform(enum grade_cause c)
{
	return c <= RT_CAUSE_GAMMA;
}

int grade_variant_count(enum grade_cause c)
{
	/* Rays through each of the four corners; the light behind adding its
	 * highlight only, or its diffuse term too (two-sided, |N.L|), or its
	 * diffuse term signed (no test at all: kd N.L darkens), the commonest. */
	return c == RT_CAUSE_PIXEL_CORNERS ? 4 : c == RT_CAUSE_LIGHT_BEHIND ? 3 : 1;
}

void grade_variant_of(const struct grade_job *job, int id, struct grade_variant *v)
{
	enum grade_cause c = (enum grade_cause)(id / GRADE_VARIANTS);
	int variant = id % GRADE_VARIANTS;
	static const unsigned rule_of[RT_CAUSE_COUNT] = {
		[RT_CAUSE_WHITE_SPECULAR] = RT_RULE_WHITE_SPECULAR,
		[RT_CAUSE_NO_SHADOWS] = RT_RULE_NO_SHADOWS,
		[RT_CAUSE_LIGHT_BEHIND] = RT_RULE_LIGHT_BEHIND,
		[RT_CAUSE_UNIT_STARTS] = RT_RULE_UNIT_STARTS,
		[RT_CAUSE_FLOOR_SWAPPED] = RT_RULE_FLOOR_SWAPPED,
	};
	v->settings = job->settings;
	v->corner = false;
	v->wrap = false;
	if (id == GRADE_PLAIN_RENDER) {
		v->rules = 0;
		v->use_rules = false;
		return;
	}
	v->rules = rule_of[c];
	v->use_rules = v->rules != 0;
	if (c == RT_CAUSE_RECURSION_FEWER)
		v->settings.recursion--;
	else if (c == RT_CAUSE_RECURSION_MORE)
		v->settings.recursion++;
	else if (c == RT_CAUSE_CLAMP_OTHER)
		v->settings.clamp = job->settings.clamp == RT_CLAMP_LEVEL ? RT_CLAMP_FINAL : RT_CLAMP_LEVEL;
	else if (c == RT_CAUSE_NEVER_CLAMP) {
		/* No clamping at any level (render_trace with --clamp final
		 * leaves the colour as it is) and bytes that wrap, made in the
		 * conversion so that one trace gives both the rounded and the
		 * truncated byte; RT_RULE_NEVER_CLAMP is the rounded one alone. */
		v->settings.clamp = RT_CLAMP_FINAL;
		v->wrap = true;
	}
	else if (c == RT_CAUSE_PIXEL_CORNERS) {
		/* (i, j), the top-left corner, and the three others. */
		v->corner = true;
		v->cx = variant & 1 ? 1.0 : 0.0;
		v->cy = variant & 2 ? 1.0 : 0.0;
	} else if (c == RT_CAUSE_LIGHT_BEHIND && variant == 1) {
		v->rules |= RT_RULE_TWO_SIDED;
	} else if (c == RT_CAUSE_LIGHT_BEHIND && variant == 2) {
		v->rules |= RT_RULE_SIGNED_DIFFUSE;
	}
}

bool grade_cause_applies(const struct grade_job *job, enum grade_cause c)
{
	if (c == RT_CAUSE_RECURSION_FEWER)
		return job->settings.recursion >= 2;
	if (c == RT_CAUSE_TRANSPOSED)
		return job->camera->size > 1;
	return true;
}
