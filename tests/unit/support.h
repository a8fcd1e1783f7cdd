/* Shared helpers for the cmocka tests: include this instead of cmocka.h. */
#ifndef RT_TESTS_SUPPORT_H
#define RT_TESTS_SUPPORT_H

#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include <stdbool.h>

#include "base/simd.h"
#include "scene/scene_impl.h"
#include "shapes/shapes.h"
#include "whitted/scenefile.h"
#include "whitted/camera.h"
#include "whitted/diag.h"
#include "whitted/material.h"
#include "whitted/pov.h"
#include "whitted/ray.h"
#include "whitted/scene.h"
#include "whitted/settings.h"
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

/* A cmocka fixture whose state is one shape: setup_X returns
 * support_hold_shape(state, X_create(...)) (0, or -1 where creating it
 * failed), and support_drop_shape destroys it after the test. */
int support_hold_shape(void **state, struct shape *s);
int support_drop_shape(void **state);

/* The material's coefficients and shininess, each exactly as given. */
#define assert_coefficients(m, ka, kd, ks, kr, shininess) \
	support_assert_coefficients((m), (ka), (kd), (ks), (kr), (shininess), __FILE__, __LINE__)
void support_assert_coefficients(const struct material *m, double ka, double kd, double ks,
				 double kr, double shininess, const char *file, int line);
/* The material's colour and coefficients, each exactly as given. */
#define assert_material(m, r, g, b, ka, kd, ks, kr, shininess) \
	support_assert_material((m), (r), (g), (b), (ka), (kd), (ks), (kr), (shininess), __FILE__, \
				__LINE__)
void support_assert_material(const struct material *m, double r, double g, double b, double ka,
			     double kd, double ks, double kr, double shininess, const char *file,
			     int line);
/* The scene's only shape, which must be of the table with this keyword. */
struct shape *support_only_shape(const struct scene *sc, const char *keyword);
/* A ray that must hit shape s past t_min: *t_max is set to infinity, and
 * after the call holds the nearest hit, which must be t within eps. */
#define assert_hit(s, r, t_min, t_max, t, eps) \
	support_assert_hit((s), (r), (t_min), (t_max), (t), (eps), __FILE__, __LINE__)
void support_assert_hit(const struct shape *s, const struct ray *r, double t_min, double *t_max,
			double t, double eps, const char *file, int line);
/* Each of the n rays (origin, then direction) misses s past 0 and leaves
 * its t_max (42) as it was. */
void support_assert_misses(const struct shape *s, const double (*rays)[6], size_t n);
/* Object tokens that must not parse (support_parse_object): the error
 * code, the line and column of the offending token, and a part of the
 * message; no shape made. */
struct support_object_error {
	const char *text;
	int rc, line, col;
	const char *msg;
};
void support_assert_object_error(const struct shape_ops *ops, const struct support_object_error *e);

/* The default settings (settings_init) at this size and recursion. */
void support_settings(struct settings *s, int size, int recursion);

/* The whole of the file at path (the test fails where it cannot be read),
 * *len its size; the caller frees it. */
unsigned char *support_read_file(const char *path, size_t *len);

/* The registry's keywords in its order, each once (a keyword of two
 * tables, as the pyramid's, once), joined by ", " into out (size bytes,
 * which must hold them); returns the number of tables. */
size_t support_keyword_list(char *out, size_t size);

/* Parses scene text; fails the test with the diagnostic when it does not
 * parse.  The caller destroys the scene. */
struct scene *support_parse(const char *text);
/* Parses text (failing the test when it does not parse), adds the
 * assignment's floor when with_floor, and prepares the scene for
 * rendering on one thread.  The caller destroys the scene. */
struct scene *support_prepared(const char *text, bool with_floor);
/* *cam, the default camera (camera_params_default) at size x size. */
void support_default_camera(struct camera *cam, int size);
/* *p, the default camera parameters with this lens (nearfar's field of
 * view, near plane and aspect). */
void support_lens_params(struct camera_params *p, double fov_deg, double near, double aspect);
/* Parses text that must fail; returns the error code and fills *d. */
int support_parse_error(const char *text, struct diag *d);
/* Scene text that must not parse (support_parse_error): the error code
 * rc (negative, as scene_parse returns it), the line, the column where
 * col > 0, and the message: all of it (assert_scene_error) or a part of
 * it (assert_scene_error_part); a NULL message is not looked at. */
#define assert_scene_error(text, rc, line, col, msg) \
	support_assert_scene_error((text), (rc), (line), (col), (msg), true, __FILE__, __LINE__)
#define assert_scene_error_part(text, rc, line, col, part) \
	support_assert_scene_error((text), (rc), (line), (col), (part), false, __FILE__, __LINE__)
void support_assert_scene_error(const char *text, int rc, int line, int col, const char *msg,
				bool whole, const char *file, int at);
/* Reads one object's tokens (those after its keyword) with the table's
 * parse, as the scene reader does; the diagnostic names test.txt. */
int support_parse_object(const struct shape_ops *ops, const char *text, struct shape **out,
			 struct diag *d);

/* A seeded random stream for the randomised tests (xorshift64*): the
 * same numbers for the same seed in every test program. */
void support_rng_seed(uint64_t seed);
double support_rng(void);			/* uniform in [0, 1) */
double support_uniform(double lo, double hi);
struct vec3 support_random_point(double half);	/* in the cube [-half, half]^3 */
struct vec3 support_random_direction(void);	/* a unit vector */

/* The sets of instructions a kernel is compiled for (base/simd.h), and
 * whether a test of set s's kernel can run here: the build has it
 * (`compiled`) and this processor runs it.  When it can, prints
 * "isa: NAME" (base, avx2, avx512); tests/unit/run.sh reports the sets
 * that ran and fails where the processor has a set none of whose tests
 * ran.  When the processor lacks it, support_need_isa prints "skip: AVX2
 * not on this CPU" (or AVX-512) and skips the test, which the runner
 * counts as skipped, never as passed; support_isa_part prints "part-skip:"
 * instead and returns false, for a test that compares every set it can
 * and goes on without that one.  A set the processor has but the build
 * lacks (or WHITTED_ISA caps) fails the test. */
void support_need_isa(enum rt_simd s, bool compiled);
bool support_isa_part(enum rt_simd s, bool compiled);
const char *support_isa_tag(enum rt_simd s);
/* Three entries of a CMUnitTest table: f run for each set, its state
 * pointing at the set (read with SUPPORT_ISA_OF), named f_base, f_avx2 and
 * f_avx512. */
extern const enum rt_simd support_isa_sets[3];
#define SUPPORT_ISA_TESTS(f) \
	{ #f "_base", f, NULL, NULL, (void *)&support_isa_sets[0] }, \
	{ #f "_avx2", f, NULL, NULL, (void *)&support_isa_sets[1] }, \
	{ #f "_avx512", f, NULL, NULL, (void *)&support_isa_sets[2] }
#define SUPPORT_ISA_OF(state) (*(const enum rt_simd *)*(state))

/* Runs the tests whose names contain argv[1] (all without it). */
int support_run(const char *group, const struct CMUnitTest *tests, size_t n,
		int argc, char **argv);
#define SUPPORT_RUN(tests, argc, argv) \
	support_run(__FILE__, tests, sizeof(tests) / sizeof(tests[0]), argc, argv)

#include "support_main.h"

#endif
