/* The causes' forms: which exist for a job (the other recursion levels,
 * the floors, the phases that change the checker), how two combine, what
 * each says of itself; and another floor in the rules' trace. */
#include <math.h>
#include <string.h>

#include "course_scene.h"
#include "grade/grade_impl.h"
#include "render/shade_rules.h"
#include "grade_fixture.h"
#include "support.h"

struct job_setup {
	struct scene *s;
	struct camera cam;
	struct grade_job job;
};

static void job_make(struct job_setup *j, int size, bool square)
{
	struct camera_params p;
	struct diag d;

	j->s = grade_fixture_scene(course_scene, &p);
	assert_int_equal(camera_init_rect(&j->cam, &p, size, square ? size : size / 2, &d), 0);
	grade_fixture_job(&j->job, j->s, &j->cam, 4, 1);
}

static void test_causes_forms(void **state)
{
	struct job_setup j;
	struct grade_variant v;
	char buf[128];
	int levels[GRADE_VARIANTS], n = 0, f;

	(void)state;
	job_make(&j, 32, true);
	/* Recursion 4: one fewer (3) and one more (5) are causes of their
	 * own, 1 is no-reflections; the other levels are 6, 7 and 2. */
	for (f = 0; f < GRADE_VARIANTS; f++)
		if (grade_variant_of(&j.job, RT_CAUSE_RECURSION_LEVEL, f, &v))
			levels[n++] = v.settings.recursion;
	assert_int_equal(n, 3);
	assert_int_equal(levels[0], 6);
	assert_int_equal(levels[1], 7);
	assert_int_equal(levels[2], 2);
	assert_true(grade_variant_of(&j.job, RT_CAUSE_NO_REFLECTIONS, 0, &v));
	assert_int_equal(v.settings.recursion, 1);
	grade_cause_detail(&j.job, RT_CAUSE_RECURSION_LEVEL, 2, buf, sizeof(buf));
	assert_string_equal(buf, "recursion level 2 instead of 4");
	/* The classic floor: 1000 wide, cells 20.  Its corner is 25 cells
	 * from the origin, an odd number: cells counted from the origin
	 * swap colours (form 0 exists); half a cell off (1, 2) too. */
	assert_true(grade_variant_of(&j.job, RT_CAUSE_FLOOR_HORIZON, 0, &v));
	assert_true(v.other_floor && isinf(v.floor.half) && v.floor.cell == 20.0);
	assert_true(grade_variant_of(&j.job, RT_CAUSE_FLOOR_SIZE, 2, &v));
	assert_near(v.floor.half, 1000.0, 0.0);
	assert_near(v.floor.ox, -1000.0, 0.0);
	grade_cause_detail(&j.job, RT_CAUSE_FLOOR_SIZE, 2, buf, sizeof(buf));
	assert_string_equal(buf, "2000 wide instead of 1000");
	grade_cause_detail(&j.job, RT_CAUSE_FLOOR_SIZE, 0, buf, sizeof(buf));
	assert_string_equal(buf, "400 wide instead of 1000");
	/* No spotlight in the course scene: no spot-cone. */
	for (f = 0; f < GRADE_VARIANTS; f++)
		assert_false(grade_variant_of(&j.job, RT_CAUSE_SPOT_CONE, f, &v));
	/* No form that is the floor's own cell. */
	for (f = 0; f < GRADE_VARIANTS; f++)
		if (grade_variant_of(&j.job, RT_CAUSE_FLOOR_CELL, f, &v))
			assert_true(v.floor.cell != 20.0);
	assert_true(grade_variant_of(&j.job, RT_CAUSE_CHECKER_PHASE, 0, &v));
	assert_near(v.floor.ox, 0.0, 0.0);
	assert_true(grade_variant_of(&j.job, RT_CAUSE_CHECKER_PHASE, 1, &v));
	assert_near(v.floor.ox, 10.0, 0.0);
	assert_false(grade_variant_of(&j.job, RT_CAUSE_CHECKER_PHASE, 3, &v));
	assert_true(grade_variant_of(&j.job, RT_CAUSE_TRANSPOSED, 0, &v));
	scene_destroy(j.s);
	/* No transposition of an image that is not square. */
	job_make(&j, 32, false);
	assert_false(grade_variant_of(&j.job, RT_CAUSE_TRANSPOSED, 0, &v));
	scene_destroy(j.s);
}

static void test_causes_combine(void **state)
{
	struct job_setup j;
	struct grade_variant a, b, c;

	(void)state;
	job_make(&j, 32, true);
	assert_true(grade_variant_of(&j.job, RT_CAUSE_WHITE_SPECULAR, 0, &a));
	assert_true(grade_variant_of(&j.job, RT_CAUSE_RED_BLUE, 0, &b));
	assert_true(grade_variant_combine(&a, &b, &c));
	assert_true(c.use_rules && (c.rules & RT_RULE_WHITE_SPECULAR) && c.map == GRADE_MAP_RED_BLUE);
	assert_true(grade_variant_of(&j.job, RT_CAUSE_NO_REFLECTIONS, 0, &b));
	assert_true(grade_variant_combine(&a, &b, &c));
	assert_int_equal(c.settings.recursion, 1);
	/* Two levels, two floors, two rules of one bit: no pair. */
	assert_true(grade_variant_of(&j.job, RT_CAUSE_RECURSION_MORE, 0, &a));
	assert_true(grade_variant_combine(&a, &b, &c));	/* b's level wins */
	/* Two floor causes that change different parts make one floor
	 * (endless with cells 10; 400 wide from its own corner with cells
	 * 10); two that change one part (the width, the cells' origin) do
	 * not combine. */
	assert_true(grade_variant_of(&j.job, RT_CAUSE_FLOOR_HORIZON, 0, &a));
	assert_true(grade_variant_of(&j.job, RT_CAUSE_FLOOR_CELL, 0, &b));
	assert_true(grade_variant_combine(&a, &b, &c));
	assert_true(c.other_floor && isinf(c.floor.half) && c.floor.cell == 10.0 &&
		    c.floor.ox == -500.0);
	assert_true(grade_variant_of(&j.job, RT_CAUSE_FLOOR_SIZE, 0, &a));
	assert_true(grade_variant_combine(&b, &a, &c));
	assert_true(c.floor.half == 200.0 && c.floor.cell == 10.0 && c.floor.ox == -200.0 &&
		    c.floor.oy == -200.0 && c.floor.cx == 0.0);
	assert_true(grade_variant_of(&j.job, RT_CAUSE_FLOOR_HORIZON, 0, &b));
	assert_false(grade_variant_combine(&a, &b, &c));
	assert_true(grade_variant_of(&j.job, RT_CAUSE_CHECKER_PHASE, 1, &b));
	assert_false(grade_variant_combine(&a, &b, &c));
	assert_true(grade_variant_of(&j.job, RT_CAUSE_LIGHT_BEHIND, 1, &a));
	assert_false(grade_variant_combine(&a, &a, &c));
	scene_destroy(j.s);
}

/* A spot scene's five cones, each one rule, named in its detail. */
static void test_causes_spot_cone(void **state)
{
	static const unsigned rules[] = { RT_RULE_SPOT_COS_DEGREES, RT_RULE_SPOT_NO_CONE,
					  RT_RULE_SPOT_FULL_ANGLE, RT_RULE_SPOT_PI_MACRO,
					  RT_RULE_SPOT_UNLIT };
	struct job_setup j;
	struct grade_variant v;
	struct diag d;
	char buf[128];
	int f;

	(void)state;
	job_make(&j, 32, true);
	scene_destroy(j.s);
	j.s = support_parse("1\n8\n1\nsphere\n0 0 0\n1\n1 1 1\n0.1 0.3 0.4 0\n2\n1\n0 10 0\n"
			    "1 1 1\n1\n0 -10 0\n1 1 1\n0 1 0\n30\n");
	assert_int_equal(scene_prepare(j.s, 1, &d), 0);
	j.job.scene = j.s;
	for (f = 0; f < 5; f++) {
		assert_true(grade_variant_of(&j.job, RT_CAUSE_SPOT_CONE, f, &v));
		assert_true(v.use_rules);
		assert_int_equal(v.rules, rules[f]);
	}
	assert_false(grade_variant_of(&j.job, RT_CAUSE_SPOT_CONE, 5, &v));
	grade_cause_detail(&j.job, RT_CAUSE_SPOT_CONE, 3, buf, sizeof(buf));
	assert_string_equal(buf, "PI a macro without parentheses: 2.47 times narrower");
	scene_destroy(j.s);
}

/* The rules' trace with another floor: the scene's own floor as "another"
 * gives the very colours; an endless one is met where the scene's ends. */
static void test_causes_other_floor_in_the_trace(void **state)
{
	struct job_setup j;
	struct shade_floor same = { .moved = true, .half = 500.0, .cell = 20.0, .ox = -500.0,
				    .oy = -500.0 };
	struct shade_floor endless = { .moved = true, .half = INFINITY, .cell = 20.0, .ox = -500.0,
				       .oy = -500.0 };
	struct shade_floor own = { .own_finish = true };
	struct render_settings rs = { 4, RT_CLAMP_LEVEL };
	int k;

	(void)state;
	job_make(&j, 32, true);
	own.finish = j.s->floor->mat;
	support_rng_seed(3);
	for (k = 0; k < 2000; k++) {
		struct ray r = support_ray(support_uniform(-300, 300), support_uniform(-300, 300), support_uniform(5, 200), 0, 0, 0);
		struct color a, b;
		r.dir = support_random_direction();
		if (r.dir.z > -0.05)
			r.dir.z = -0.05 - fabs(r.dir.z);
		r.dir = vec3_normalize(r.dir);
		a = shade_rules_trace(j.s, &rs, 0, &r, 1);
		b = shade_rules_trace_floor(j.s, &rs, 0, &same, &r, 1);
		assert_memory_equal(&a, &b, sizeof(a));
		b = shade_rules_trace_floor(j.s, &rs, 0, &own, &r, 1);
		assert_memory_equal(&a, &b, sizeof(a));
	}
	{
		/* Ambient 1 alone: a white cell's colour is 1, a black one's 0,
		 * whatever the lights: (-399.5, -399.5) is in cell (5, 5),
		 * (-379.5, -399.5) in (6, 5), far from every object. */
		struct shade_floor ambient = { .own_finish = true };
		struct ray down = support_ray(-399.5, -399.5, 300.0, 0, 0, -1);
		struct color c;

		ambient.finish.ka = 1.0;
		c = shade_rules_trace_floor(j.s, &rs, 0, &ambient, &down, 1);
		assert_near(c.r, 1.0, 0.0);
		assert_near(c.b, 1.0, 0.0);
		down = support_ray(-379.5, -399.5, 300.0, 0, 0, -1);
		c = shade_rules_trace_floor(j.s, &rs, 0, &ambient, &down, 1);
		assert_near(c.g, 0.0, 0.0);
	}
	{
		/* From high above, straight down on (700.5, 10.5): no floor
		 * there (|x| >= 500), black; the endless one's cell (60, 25) is
		 * odd: black too; (720.5, 10.5): cell (61, 25), even: white. */
		struct ray down = support_ray(720.5, 10.5, 300.0, 0, 0, -1);
		struct color none = shade_rules_trace(j.s, &rs, 0, &down, 1);
		struct color white = shade_rules_trace_floor(j.s, &rs, 0, &endless, &down, 1);
		assert_near(none.r, 0.0, 0.0);
		assert_true(white.r > 0.3 && white.g > 0.3 && white.b > 0.3);
		down = support_ray(700.5, 10.5, 300.0, 0, 0, -1);
		white = shade_rules_trace_floor(j.s, &rs, 0, &endless, &down, 1);
		assert_true(white.r < 0.05 && white.g < 0.05 && white.b < 0.05);
	}
	scene_destroy(j.s);
}

SUPPORT_MAIN(SUPPORT_TESTS(test_causes_forms, test_causes_combine, test_causes_spot_cone,
			   test_causes_other_floor_in_the_trace))
