/* Glass (scene_set_glass, render_trace's transmitted term): single rays
 * against values that follow from Snell's law and the stated rules: a ray
 * through a sphere's centre passes straight and is scaled by kt at each
 * surface; an off-axis ray comes out along the direction computed here
 * from Snell's law at both surfaces (entering with 1/n, leaving with n),
 * found by a small target placed on it and missed beside it; glass in
 * glass bends by the ratio of the two indices, and a quadric's negated
 * coefficients (its normal pointing in) make the same glass (the ray's
 * glass stack, not the normal's sign, says entering or leaving); total
 * internal reflection (glass into a bubble) sends the ray on as a whole
 * mirror (weight 1); the
 * recursion level counts each passage; glass casts an opaque shadow; and
 * scene_set_glass's checks. */
#include <math.h>
#include <string.h>

#include "scene/scene_impl.h"
#include "whitted/render.h"
#include "support.h"

/* An opaque target: colour (0.2, 0.4, 0.8), KA 1, nothing else. */
#define TARGET "0.2 0.4 0.8  1 0 0 0  1  "
/* A material that adds nothing of its own: the glass's light is all kt's. */
#define CLEAR "1 1 1  0 0 0 0  1  "

/* The colour r sees in s, prepared here on one thread, clamped at the end
 * (RT_CLAMP_FINAL); s is destroyed. */
static struct color trace_prepared(struct scene *s, int recursion, struct ray r)
{
	struct render_settings rs;
	struct diag d;
	struct color c;

	assert_int_equal(scene_prepare(s, 1, &d), 0);
	rs.recursion = recursion;
	rs.clamp = RT_CLAMP_FINAL;
	c = render_trace(s, &rs, &r, 1, NULL);
	scene_destroy(s);
	return c;
}

static struct color trace_glass(const char *text, double ior, double kt, int recursion,
				struct ray r)
{
	struct scene *s = support_parse(text);
	struct diag d;

	assert_int_equal(scene_set_glass(s, 0, ior, kt, &d), 0);
	return trace_prepared(s, recursion, r);
}

static void test_glass_through_the_centre(void **state)
{
	/* Along the axis: no bending; kt 0.5 at the front and at the back,
	 * so 0.25 of the target's 1 * C, once the recursion lets the ray
	 * reach it (level 1 the front, 2 the back, 3 the target). */
	const char *text = "9 1 2 sphere 0 0 0 1 " CLEAR "sphere 0 0 10 1 " TARGET "0";
	struct ray r = support_ray(0, 0, -5, 0, 0, 1);
	struct color c;

	(void)state;
	c = trace_glass(text, 1.5, 0.5, 3, r);
	assert_near(c.r, 0.05, 1e-15);
	assert_near(c.g, 0.1, 1e-15);
	assert_near(c.b, 0.2, 1e-15);
	c = trace_glass(text, 1.5, 0.5, 2, r);
	assert_near(c.r + c.g + c.b, 0.0, 0.0);
}

/* Snell's law in vector form, written here apart from the renderer:
 * t = eta d + (eta cos i - cos t) n, n facing d. */
static struct vec3 snell(struct vec3 d, struct vec3 n, double eta)
{
	double ci = -vec3_dot(d, n), ct = sqrt(1.0 - eta * eta * (1.0 - ci * ci));

	return vec3_normalize(vec3_add(vec3_scale(d, eta), vec3_scale(n, eta * ci - ct)));
}

/* The ray x = b along +z through a glass unit sphere of index n, out the
 * other side: where it is 20 units after leaving. */
static struct vec3 emergent_point(double b, double n)
{
	struct vec3 d = vec3_make(0, 0, 1), p1 = vec3_make(b, 0, -sqrt(1.0 - b * b)), t, p2, out;
	double along;

	t = snell(d, p1, 1.0 / n);		/* the outward normal at p1 is p1 */
	along = -2.0 * vec3_dot(p1, t);		/* the chord: |p1 + s t| = 1 */
	p2 = vec3_add_scaled(p1, t, along);
	out = snell(t, vec3_neg(p2), n);	/* inside, the normal facing t is -p2 */
	return vec3_add_scaled(p2, out, 20.0);
}

static void test_glass_bends_by_snell(void **state)
{
	struct vec3 q = emergent_point(0.5, 1.5);
	char text[512];
	struct ray r = support_ray(0.5, 0, -5, 0, 0, 1);
	struct color c;

	(void)state;
	/* The ray bends towards the axis: it crosses x = 0 before q. */
	assert_true(q.x < -1.0);
	snprintf(text, sizeof(text), "9 1 2 sphere 0 0 0 1 " CLEAR "sphere %.17g %.17g %.17g 0.05 "
		 TARGET "0", q.x, q.y, q.z);
	c = trace_glass(text, 1.5, 0.5, 3, r);
	assert_near(c.b, 0.2, 1e-12);
	/* The same target 0.2 aside (beyond its radius), or the other index:
	 * missed. */
	snprintf(text, sizeof(text), "9 1 2 sphere 0 0 0 1 " CLEAR "sphere %.17g %.17g %.17g 0.05 "
		 TARGET "0", q.x + 0.2, q.y, q.z);
	c = trace_glass(text, 1.5, 0.5, 3, r);
	assert_near(c.b, 0.0, 0.0);
	q = emergent_point(0.5, 1.3);
	snprintf(text, sizeof(text), "9 1 2 sphere 0 0 0 1 " CLEAR "sphere %.17g %.17g %.17g 0.05 "
		 TARGET "0", q.x, q.y, q.z);
	c = trace_glass(text, 1.5, 0.5, 3, r);
	assert_near(c.b, 0.0, 0.0);
	c = trace_glass(text, 1.3, 0.5, 3, r);
	assert_near(c.b, 0.2, 1e-12);
}

/* The nearest t > 1e-9 where o + t d (d unit) meets the sphere of radius
 * rad about the origin, or -1. */
static double sphere_exit(struct vec3 o, struct vec3 d, double rad)
{
	double b = vec3_dot(o, d), c = vec3_dot(o, o) - rad * rad, disc = b * b - c, t;

	if (disc < 0.0)
		return -1.0;
	t = -b - sqrt(disc);
	if (t > 1e-9)
		return t;
	t = -b + sqrt(disc);
	return t > 1e-9 ? t : -1.0;
}

/* The ray x = b along +z through a glass unit sphere of index n1 holding
 * a concentric one of radius 0.5 and index n2: where it is 20 units after
 * leaving, by Snell's law at the four surfaces with the indices on either
 * side (1 | n1 | n2 | n1 | 1). */
static struct vec3 nested_emergent_point(double b, double n1, double n2)
{
	const double rad[4] = { 1.0, 0.5, 0.5, 1.0 };
	const double eta[4] = { 1.0 / n1, n1 / n2, n2 / n1, n1 / 1.0 };
	struct vec3 o = vec3_make(b, 0, -5), d = vec3_make(0, 0, 1), p, n;
	int i;

	for (i = 0; i < 4; i++) {
		p = vec3_add_scaled(o, d, sphere_exit(o, d, rad[i]));
		n = vec3_normalize(p);
		if (vec3_dot(n, d) > 0.0)
			n = vec3_neg(n);
		d = snell(d, n, eta[i]);
		o = p;
	}
	return vec3_add_scaled(o, d, 20.0);
}

static struct color trace_nested(struct vec3 q, double n1, double n2, struct ray r)
{
	struct scene *s;
	struct render_settings rs = { 6, RT_CLAMP_FINAL };
	struct diag d;
	struct color c;
	char text[512];

	snprintf(text, sizeof(text), "9 1 3 sphere 0 0 0 1 " CLEAR "sphere 0 0 0 0.5 " CLEAR
		 "sphere %.17g %.17g %.17g 0.05 " TARGET "0", q.x, q.y, q.z);
	s = support_parse(text);
	assert_int_equal(scene_set_glass(s, 0, n1, 0.5, &d), 0);
	assert_int_equal(scene_set_glass(s, 1, n2, 0.5, &d), 0);
	assert_int_equal(scene_prepare(s, 1, &d), 0);
	c = render_trace(s, &rs, &r, 1, NULL);
	scene_destroy(s);
	return c;
}

static void test_glass_nested_bends_between_the_glasses(void **state)
{
	/* Into the inner sphere the ray passes from glass of 1.5 into glass
	 * of 1.2 (eta 1.5 / 1.2), not from air: the target on that path is
	 * seen through the four surfaces (kt^4 = 1/16 of 0.8), and the one
	 * on the path of eta 1 / 1.2 there (what the normal's sign alone
	 * gave) is missed. */
	struct ray r = support_ray(0.4, 0, -5, 0, 0, 1);
	struct vec3 q = nested_emergent_point(0.4, 1.5, 1.2), wrong;
	struct color c;

	(void)state;
	c = trace_nested(q, 1.5, 1.2, r);
	assert_near(c.b, 0.8 / 16.0, 1e-12);
	/* The path with air's index around the inner sphere. */
	wrong = nested_emergent_point(0.4, 1.5, 1.2 * 1.5);
	assert_true(vec3_length(vec3_sub(wrong, q)) > 0.2);
	c = trace_nested(wrong, 1.5, 1.2, r);
	assert_near(c.b, 0.0, 0.0);
}

/* The unit sphere as a quadric x^2 + y^2 + z^2 - 1 = 0, with every
 * coefficient times `sign`, unclipped. */
static struct color trace_quadric_glass(double sign, struct vec3 q, struct ray r)
{
	char text[512];

	snprintf(text, sizeof(text), "9 1 2 general %g %g %g 0 0 0 0 0 0 %g  0 0 0 0 0 0 " CLEAR
		 "sphere %.17g %.17g %.17g 0.05 " TARGET "0", sign, sign, sign, -sign, q.x, q.y,
		 q.z);
	return trace_glass(text, 1.5, 0.5, 3, r);
}

static void test_glass_negated_quadric_is_the_same_glass(void **state)
{
	/* The negated quadric's gradient points inwards; entering is still
	 * the first hit and leaving the second: both bend the ray onto the
	 * sphere's emergent point, the same bits. */
	struct vec3 q = emergent_point(0.5, 1.5);
	struct ray r = support_ray(0.5, 0, -5, 0, 0, 1);
	struct color pos, neg;

	(void)state;
	pos = trace_quadric_glass(1.0, q, r);
	neg = trace_quadric_glass(-1.0, q, r);
	assert_near(pos.b, 0.2, 1e-12);
	assert_memory_equal(&pos, &neg, sizeof(pos));
}

/* The ray x = 1.35 along +z into a glass sphere of radius 10 and index
 * 1.5 holding a bubble (radius 1, index n_in, kr 0.3) at its centre; its
 * path by Snell's law (entering: eta 1 / 1.5, the impact distance 1.35
 * becomes 0.9), then at the bubble reflected (`mirror`) and out of the
 * big sphere again: the point 5 units past.  The bubble's sin i is 0.9. */
static struct vec3 bubble_reflected_point(void)
{
	struct vec3 o = vec3_make(1.35, 0, -20), d = vec3_make(0, 0, 1), p, n;

	p = vec3_add_scaled(o, d, sphere_exit(o, d, 10.0));
	d = snell(d, vec3_scale(p, 0.1), 1.0 / 1.5);
	p = vec3_add_scaled(p, d, sphere_exit(p, d, 1.0));
	n = vec3_normalize(p);
	d = vec3_add_scaled(d, n, -2.0 * vec3_dot(d, n));
	o = p;
	p = vec3_add_scaled(o, d, sphere_exit(o, d, 10.0));
	d = snell(d, vec3_scale(p, -0.1), 1.5);
	return vec3_add_scaled(p, d, 5.0);
}

static struct color trace_bubble(double n_in, int recursion)
{
	struct vec3 q = bubble_reflected_point();
	struct ray r = support_ray(1.35, 0, -20, 0, 0, 1);
	struct scene *s;
	struct diag d;
	char text[512];

	snprintf(text, sizeof(text), "9 1 3 sphere 0 0 0 10 " CLEAR "sphere 0 0 0 1 1 1 1  0 0 0 0.3 1 "
		 "sphere %.17g %.17g %.17g 0.05 " TARGET "0", q.x, q.y, q.z);
	s = support_parse(text);
	assert_int_equal(scene_set_glass(s, 0, 1.5, 0.5, &d), 0);
	assert_int_equal(scene_set_glass(s, 1, n_in, 0.5, &d), 0);
	return trace_prepared(s, recursion, r);
}

static void test_glass_total_internal_reflection(void **state)
{
	/* From glass of 1.5 into a bubble of 1.0 at sin i = 0.9 > 1 / 1.5:
	 * total reflection, whose ray is seen whole (weight 1, not kt or kr
	 * + kt of it): the target on it at kt 0.5 in and kt 0.5 out, 0.25. */
	struct color c;

	(void)state;
	c = trace_bubble(1.0, 4);
	assert_near(c.r, 0.05, 1e-12);
	assert_near(c.b, 0.2, 1e-12);
	/* Into a bubble of 1.4 (critical angle asin(1.4 / 1.5) = 69 degrees
	 * > asin 0.9 = 64) it passes, and only the finish's reflection kr =
	 * 0.3 sees the target. */
	c = trace_bubble(1.4, 4);
	assert_near(c.b, 0.25 * 0.3 * 0.8, 1e-12);
	/* The target is the fourth level: not reached at recursion 3. */
	c = trace_bubble(1.0, 3);
	assert_near(c.b, 0.0, 0.0);
}

static void test_glass_casts_an_opaque_shadow(void **state)
{
	/* A plane's point under a glass sphere, the light above it: only
	 * the plane's ambient 0.1 C is left, as under an opaque sphere. */
	const char *text = "9 1 2 sphere 0 0 25 2 " CLEAR
			   "triangle -100 -100 0  100 -100 0  0 100 0  1 0.5 0.25  0.1 0.5 0 0 1  "
			   "1 0 0 50 1 1 1";
	struct scene *s = support_parse(text);
	struct render_settings rs = { 1, RT_CLAMP_FINAL };
	struct ray r = support_ray(5, -30, 30, -5, 30, -30);
	struct diag d;
	struct color c;

	(void)state;
	assert_int_equal(scene_set_glass(s, 0, 1.5, 0.9, &d), 0);
	assert_int_equal(scene_prepare(s, 1, &d), 0);
	r.dir = vec3_normalize(r.dir);
	c = render_trace(s, &rs, &r, 1, NULL);
	assert_near(c.r, 0.1, 1e-12);
	assert_near(c.g, 0.05, 1e-12);
	scene_destroy(s);
}

static void test_glass_set_checks(void **state)
{
	struct scene *s = support_parse("9 1 1 sphere 0 0 0 1 " CLEAR "0");
	struct diag d;

	(void)state;
	assert_int_equal(scene_set_glass(s, 1, 1.5, 0.5, &d), -RT_E_INVALID);
	assert_non_null(strstr(d.msg, "--glass 2: the scene has 1 object"));
	assert_int_equal(scene_set_glass(s, 0, 0.0, 0.5, &d), -RT_E_INVALID);
	assert_int_equal(scene_set_glass(s, 0, INFINITY, 0.5, &d), -RT_E_INVALID);
	assert_int_equal(scene_set_glass(s, 0, 1.5, 1.0, &d), -RT_E_INVALID);
	assert_int_equal(scene_set_glass(s, 0, 1.5, 0.0, &d), -RT_E_INVALID);
	assert_int_equal(scene_set_glass(s, 0, 1.5, NAN, &d), -RT_E_INVALID);
	assert_int_equal(scene_set_glass(s, 0, 1.5, 0.5, &d), 0);
	assert_near(s->shapes[0]->mat.kt, 0.5, 0.0);
	assert_near(s->shapes[0]->mat.ior, 1.5, 0.0);
	scene_destroy(s);
}

static void test_glass_file_objects_are_opaque(void **state)
{
	struct scene *s = support_parse("9 1 1 sphere 0 0 0 1 " CLEAR "0");

	(void)state;
	assert_near(s->shapes[0]->mat.kt, 0.0, 0.0);
	assert_near(s->shapes[0]->mat.ior, 1.0, 0.0);
	scene_destroy(s);
}

SUPPORT_MAIN(SUPPORT_TESTS(test_glass_through_the_centre, test_glass_bends_by_snell,
			   test_glass_nested_bends_between_the_glasses,
			   test_glass_negated_quadric_is_the_same_glass,
			   test_glass_total_internal_reflection,
			   test_glass_casts_an_opaque_shadow, test_glass_set_checks,
			   test_glass_file_objects_are_opaque))
