/* Shared helpers for the cmocka tests: include this instead of cmocka.h. */
#ifndef RT_TESTS_SUPPORT_H
#define RT_TESTS_SUPPORT_H

#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include "scene/scene_impl.h"
#include "shapes/shapes.h"
#include "whitted/scenefile.h"
#include "whitted/diag.h"
#include "whitted/material.h"
#include "whitted/pov.h"
#include "whitted/ray.h"
#include "whitted/scene.h"
#include "whitted/vec3.h"

/* assert_float_equal converts to float; these keep doubles. */
#define assert_near(a, b, eps) support_assert_near((a), (b), (eps), #a, __FILE__, __LINE__)
#define assert_vec3_near(a, b, eps) \
	support_assert_vec3_near((a), (b), (eps), #a, __FILE__, __LINE__)

void support_assert_near(double a, double b, double eps, const char *expr,
			 const char *file, int line);
void support_assert_vec3_near(struct vec3 a, struct vec3 b, double eps, const char *expr,
			      const char *file, int line);

/* A ray with exactly this origin and (not normalised) direction. */
struct ray support_ray(double ox, double oy, double oz, double dx, double dy, double dz);
/* The text a shape exports to POV-Ray, NUL-terminated; the caller frees it. */
char *support_export_pov(const struct shape *s, enum pov_finish finish);

/* Parses scene text; fails the test with the diagnostic when it does not
 * parse.  The caller destroys the scene. */
struct scene *support_parse(const char *text);
/* Parses text that must fail; returns the error code and fills *d. */
int support_parse_error(const char *text, struct diag *d);

/* A seeded random stream for the randomised tests (xorshift64*): the
 * same numbers for the same seed in every test program. */
void support_rng_seed(uint64_t seed);
double support_rng(void);			/* uniform in [0, 1) */
double support_uniform(double lo, double hi);
struct vec3 support_random_point(double half);	/* in the cube [-half, half]^3 */
struct vec3 support_random_direction(void);	/* a unit vector */

/* Runs the tests whose names contain argv[1] (all without it). */
int support_run(const char *group, const struct CMUnitTest *tests, size_t n,
		int argc, char **argv);
#define SUPPORT_RUN(tests, argc, argv) \
	support_run(__FILE__, tests, sizeof(tests) / sizeof(tests[0]), argc, argv)

#endif
