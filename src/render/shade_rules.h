/* The Whitted sum of shade.c with the assignment's rules breakable one by
 * one: the renders of the typical students' mistakes that `whitted compare`
 * matches a submission against.  One sum: shade.c's, whose rules are the
 * constant 0 on an ordinary render's path and a mask here, with the hooks
 * below (shade_rules.c) where a rule bends it;
 * tests/unit/render/test_shade_rules.c checks that with no rule broken it
 * gives render_trace's colour bit for bit. */
#ifndef RT_SHADE_RULES_H
#define RT_SHADE_RULES_H

#include "render/shade_hit.h"
#include "whitted/render.h"
#include "whitted/scene.h"

/* Each a rule of scene-format.md ("Shading") left out or done as the
 * handout's literal text says; a set of them is an unsigned bit mask. */
enum shade_rule {
	RT_RULE_WHITE_SPECULAR = 1u << 0,	/* specular a Lc ks (R.L)^n, not times C */
	RT_RULE_NO_SHADOWS = 1u << 1,		/* no shadow rays: every light reaches P */
	RT_RULE_LIGHT_BEHIND = 1u << 2,		/* no N.L > 0 test: diffuse max(N.L, 0), the
						 * highlight still added where R.L > 0 */
	RT_RULE_NEVER_CLAMP = 1u << 3,		/* no clamping; the byte wraps (low 8 bits
						 * of round(255 c)) */
	RT_RULE_UNIT_STARTS = 1u << 4,		/* shadow and reflected rays start at
						 * P + 1 * direction (the handout's text) */
	RT_RULE_FLOOR_SWAPPED = 1u << 5,	/* the floor's tile colours inverted: white
						 * where i + j is odd */
	RT_RULE_TWO_SIDED = 1u << 6,		/* with LIGHT_BEHIND: diffuse kd |N.L| */
	RT_RULE_SIGNED_DIFFUSE = 1u << 7,	/* with LIGHT_BEHIND: diffuse kd N.L, signed (a
						 * light behind darkens) */
	/* A spotlight's cone, each a way students get it wrong (at most one): */
	RT_RULE_SPOT_COS_DEGREES = 1u << 8,	/* cos(cutoff) of the degrees as radians */
	RT_RULE_SPOT_NO_CONE = 1u << 9,		/* lit every way, as a point light */
	RT_RULE_SPOT_FULL_ANGLE = 1u << 10,	/* the cutoff taken as the cone's full angle */
	RT_RULE_SPOT_PI_MACRO = 1u << 11,	/* the angle in degrees through an unbracketed
						 * PI macro: rad * 180 / 2 * acos(0) */
	RT_RULE_SPOT_UNLIT = 1u << 12,		/* spotlights left out */
};
#define RT_RULE_SPOT_MASK (RT_RULE_SPOT_COS_DEGREES | RT_RULE_SPOT_NO_CONE | \
			   RT_RULE_SPOT_FULL_ANGLE | RT_RULE_SPOT_PI_MACRO | RT_RULE_SPOT_UNLIT)

/* render_trace with the rules in `rules` broken (0: the contract, the same
 * colour as render_trace).  For RT_RULE_NEVER_CLAMP a primary ray's colour
 * comes back as the wrapped byte over 255, so that render_color_to_rgb8
 * gives the wrapped byte.  Allocates nothing. */
struct color shade_rules_trace(const struct scene *s, const struct render_settings *rs,
			       unsigned rules, const struct ray *r, int level);

/* Another floor in place of the scene's (the students' other floors).
 * When moved: the plane z = 0 within |x - cx|, |y - cy| < half
 * (INFINITY: to the horizon), cell (i, j) = (floor((x - ox) / cell),
 * floor((y - oy) / cell)), white when i + j is even, black otherwise;
 * else the scene floor's shape and cells.  When own_finish: finish in
 * place of the scene floor's coefficients and shininess (its colour
 * stays the cells'), and where own_deeper, deeper in place of it on the
 * floor seen in reflections (a fit's basis is the floor's first hit). */
struct shade_floor {
	bool moved;
	double half, cell, ox, oy, cx, cy;
	bool own_finish, own_deeper;
	struct material finish, deeper;
};

/* shade_rules_trace with the floor fl (NULL: the scene's own). */
struct color shade_rules_trace_floor(const struct scene *s, const struct render_settings *rs,
				     unsigned rules, const struct shade_floor *fl,
				     const struct ray *r, int level);

/* The hooks, for shade.c's sum.  Whether the light at distance dist
 * along l (unit) from p is hidden from it, as the rules cast the shadow
 * ray (none, or from one unit along l). */
bool shade_rules_shadowed(const struct scene *s, unsigned rules, struct vec3 p, struct vec3 l,
			  double dist, double eps);
/* Whether spotlight lt lights along l (unit, from P to the light) as the
 * rules' cone says: the contract's test, cos(angle) >= cos(cutoff), when
 * no spot rule is broken. */
bool shade_rules_spot_lights(const struct light *lt, unsigned rules, struct vec3 l);
/* kd (N.L) as the rules take it: 0 for a light behind (N.L <= 0, which
 * only RT_RULE_LIGHT_BEHIND lets through), kd |N.L| or kd N.L for the
 * two-sided and signed forms. */
double shade_rules_diffuse(const struct material *m, unsigned rules, double nl);
/* Each channel as a byte cast of the unclamped round(255 c) stores it
 * (its low 8 bits), over 255. */
struct color shade_rules_wrap(struct color c);
/* The nearest hit of r beyond eps with the other floor fl (NULL, or not
 * moved: the scene's) in place of the scene's: the scene's floor where fl
 * covers its point, else what lies beyond it; and fl's plane where it
 * covers a point nearer than any other hit. */
const struct shape *shade_rules_intersect(const struct scene *s, const struct shade_floor *fl,
					  const struct ray *r, double eps, double *t);
/* The point h at `level` as the rules and fl colour it (fl's cells, the
 * tiles swapped), and the finish it is shaded with (fl's on its floor). */
const struct material *shade_rules_point(const struct scene *s, unsigned rules,
					 const struct shade_floor *fl, int level,
					 struct render_point *h);

#endif
