/* Shared helpers for the cmocka tests. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "support.h"
#include "syntax/parser_impl.h"

void support_assert_near(double a, double b, double eps, const char *expr,
			 const char *file, int line)
{
	if (!(fabs(a - b) <= eps)) {
		print_error("%s = %.17g, expected %.17g (within %g)\n", expr, a, b, eps);
		_fail(file, line);
	}
}

void support_assert_vec3_near(struct vec3 a, struct vec3 b, double eps, const char *expr,
			      const char *file, int line)
{
	if (!(fabs(a.x - b.x) <= eps && fabs(a.y - b.y) <= eps && fabs(a.z - b.z) <= eps)) {
		print_error("%s = (%.17g, %.17g, %.17g), expected (%.17g, %.17g, %.17g) within %g\n",
			    expr, a.x, a.y, a.z, b.x, b.y, b.z, eps);
		_fail(file, line);
	}
}

struct ray support_ray(double ox, double oy, double oz, double dx, double dy, double dz)
{
	struct ray r;

	r.origin = vec3_make(ox, oy, oz);
	r.dir = vec3_make(dx, dy, dz);
	return r;
}

char *support_export_pov(const struct shape *s, enum pov_finish finish)
{
	struct pov_options opt = { finish, false, { NULL, NULL } };
	FILE *f = tmpfile();
	char *text;
	long n;

	assert_non_null(f);
	assert_int_equal(shape_export_pov(s, f, &opt), 0);
	n = ftell(f);
	assert_true(n > 0);
	rewind(f);
	text = malloc((size_t)n + 1);
	assert_non_null(text);
	assert_int_equal(fread(text, 1, (size_t)n, f), (size_t)n);
	text[n] = '\0';
	fclose(f);
	return text;
}

struct scene *support_parse(const char *text)
{
	struct scene *s = NULL;
	struct diag d;
	int rc;

	diag_clear(&d);
	rc = scene_parse("test.txt", text, strlen(text), NULL, NULL, NULL, &s, &d);
	if (rc < 0) {
		print_error("parse failed: %s:%d:%d: %s\n", d.file, d.line, d.col, d.msg);
		fail();
	}
	return s;
}

void support_default_camera(struct camera *cam, int size)
{
	struct camera_params p;
	struct diag d;

	camera_params_default(&p);
	assert_int_equal(camera_init(cam, &p, size, &d), 0);
}

void support_lens_params(struct camera_params *p, double fov_deg, double near, double aspect)
{
	camera_params_default(p);
	p->fov_deg = fov_deg;
	p->near = near;
	p->aspect = aspect;
}

int support_parse_error(const char *text, struct diag *d)
{
	struct scene *s = NULL;
	int rc;

	diag_clear(d);
	rc = scene_parse("test.txt", text, strlen(text), NULL, NULL, NULL, &s, d);
	if (rc == 0) {
		scene_destroy(s);
		print_error("expected a parse error, the text parsed\n");
		fail();
	}
	assert_null(s);
	return rc;
}

void support_assert_scene_error(const char *text, int rc, int line, int col, const char *msg,
				bool whole, const char *file, int at)
{
	struct diag d;
	int got = support_parse_error(text, &d);
	bool said = !msg || (whole ? strcmp(d.msg, msg) == 0 : strstr(d.msg, msg) != NULL);

	if (got != rc || d.line != line || (col > 0 && d.col != col) || !said) {
		print_error("error %d at %d:%d: %s\nexpected error %d at %d:%d: %s%s%s\n", got, d.line,
			    d.col, d.msg, rc, line, col, whole ? "" : "...", msg ? msg : "(any)",
			    whole ? "" : "...");
		_fail(file, at);
	}
}

const enum rt_simd support_isa_sets[3] = { RT_SIMD_BASE, RT_SIMD_AVX2, RT_SIMD_AVX512 };

const char *support_isa_tag(enum rt_simd s)
{
	return s == RT_SIMD_AVX512 ? "avx512" : s == RT_SIMD_AVX2 ? "avx2" : "base";
}

static bool support_isa_ready(enum rt_simd s, bool compiled, const char *skip_tag)
{
	static const char *const names[] = { "SSE2", "AVX2", "AVX-512" };

	if (rt_simd_cpu_has(s) && compiled) {
		print_message("isa: %s\n", support_isa_tag(s));
		return true;
	}
	if (rt_simd_cpu_has(s)) {
		print_error("%s is on this CPU, but its code cannot run here (not compiled for it, "
			    "or WHITTED_ISA caps it)\n", names[s]);
		fail();
	}
	print_message("%s: %s not on this CPU\n", skip_tag, names[s]);
	return false;
}

void support_need_isa(enum rt_simd s, bool compiled)
{
	if (!support_isa_ready(s, compiled, "skip"))
		skip();
}

bool support_isa_part(enum rt_simd s, bool compiled)
{
	return support_isa_ready(s, compiled, "part-skip");
}

int support_run(const char *group, const struct CMUnitTest *tests, size_t n,
		int argc, char **argv)
{
	struct CMUnitTest *chosen = malloc(n * sizeof(*chosen));
	size_t i, k = 0;
	int rc;

	if (!chosen)
		return 1;
	for (i = 0; i < n; i++)
		if (argc < 2 || strstr(tests[i].name, argv[1]))
			chosen[k++] = tests[i];
	rc = _cmocka_run_group_tests(group, chosen, k, NULL, NULL);
	free(chosen);
	return rc;
}

static uint64_t support_rng_state;

void support_rng_seed(uint64_t seed)
{
	support_rng_state = seed * 0x9e3779b97f4a7c15u + 1;
}

double support_rng(void)
{
	support_rng_state ^= support_rng_state >> 12;
	support_rng_state ^= support_rng_state << 25;
	support_rng_state ^= support_rng_state >> 27;
	return (double)((support_rng_state * 0x2545f4914f6cdd1du) >> 11) / 9007199254740992.0;
}

double support_uniform(double lo, double hi)
{
	return lo + (hi - lo) * support_rng();
}

struct vec3 support_random_point(double half)
{
	return vec3_make(support_uniform(-half, half), support_uniform(-half, half),
			 support_uniform(-half, half));
}

struct vec3 support_random_direction(void)
{
	for (;;) {
		struct vec3 v = support_random_point(1.0);
		double len = vec3_length(v);
		if (len > 0.1 && len <= 1.0)
			return vec3_scale(v, 1.0 / len);
	}
}

int support_parse_object(const struct shape_ops *ops, const char *text, struct shape **out,
			 struct diag *d)
{
	struct parser p;

	memset(&p, 0, sizeof(p));
	diag_clear(d);
	lexer_init(&p.lx, text, strlen(text));
	p.name = "test.txt";
	p.text = text;
	p.len = strlen(text);
	p.d = d;
	return ops->parse(&p, out);
}

struct scene *support_prepared(const char *text, bool with_floor)
{
	struct scene *s = support_parse(text);
	struct diag d;

	if (with_floor)
		assert_int_equal(scene_add_floor(s, RT_FLOOR_WIDTH, RT_FLOOR_TILE, &d), 0);
	assert_int_equal(scene_prepare(s, 1, &d), 0);
	return s;
}

int support_hold_shape(void **state, struct shape *s)
{
	*state = s;
	return s ? 0 : -1;
}

int support_drop_shape(void **state)
{
	shape_destroy(*state);
	return 0;
}

void support_assert_hit(const struct shape *s, const struct ray *r, double t_min, double *t_max,
			double t, double eps, const char *file, int line)
{
	*t_max = INFINITY;
	if (!shape_intersect(s, r, t_min, t_max)) {
		print_error("the ray missed, expected a hit at t = %.17g\n", t);
		_fail(file, line);
	}
	support_assert_near(*t_max, t, eps, "t_max", file, line);
}

void support_assert_misses(const struct shape *s, const double (*rays)[6], size_t n)
{
	size_t i;

	for (i = 0; i < n; i++) {
		struct ray r = support_ray(rays[i][0], rays[i][1], rays[i][2], rays[i][3],
					   rays[i][4], rays[i][5]);
		double t_max = 42.0;
		if (shape_intersect(s, &r, 0.0, &t_max)) {
			print_error("ray %zu hit at t = %g\n", i, t_max);
			fail();
		}
		assert_near(t_max, 42.0, 0.0);
	}
}

void support_assert_object_error(const struct shape_ops *ops, const struct support_object_error *e)
{
	/* Not NULL before: the parse must clear it. */
	struct shape *s = (struct shape *)&s;
	struct diag d;

	assert_int_equal(support_parse_object(ops, e->text, &s, &d), -e->rc);
	assert_null(s);
	assert_string_equal(d.file, "test.txt");
	if (d.line != e->line || d.col != e->col || !strstr(d.msg, e->msg)) {
		print_error("%s:%d:%d: %s\nexpected %d:%d: ...%s...\n", d.file, d.line, d.col, d.msg,
			    e->line, e->col, e->msg);
		fail();
	}
}

void support_assert_material(const struct material *m, double r, double g, double b, double ka,
			     double kd, double ks, double kr, double shininess, const char *file,
			     int line)
{
	support_assert_near(m->color.r, r, 0.0, "color.r", file, line);
	support_assert_near(m->color.g, g, 0.0, "color.g", file, line);
	support_assert_near(m->color.b, b, 0.0, "color.b", file, line);
	support_assert_coefficients(m, ka, kd, ks, kr, shininess, file, line);
}

struct shape *support_only_shape(const struct scene *sc, const char *keyword)
{
	assert_int_equal(sc->n_shapes, 1);
	assert_ptr_equal(sc->shapes[0]->ops, shape_ops_find(keyword, strlen(keyword)));
	return sc->shapes[0];
}

void support_assert_coefficients(const struct material *m, double ka, double kd, double ks,
				 double kr, double shininess, const char *file, int line)
{
	support_assert_near(m->ka, ka, 0.0, "ka", file, line);
	support_assert_near(m->kd, kd, 0.0, "kd", file, line);
	support_assert_near(m->ks, ks, 0.0, "ks", file, line);
	support_assert_near(m->kr, kr, 0.0, "kr", file, line);
	support_assert_near(m->shininess, shininess, 0.0, "shininess", file, line);
}

void support_settings(struct settings *s, int size, int recursion)
{
	settings_init(s);
	s->size = size;
	s->recursion = recursion;
}

unsigned char *support_read_file(const char *path, size_t *len)
{
	FILE *f = fopen(path, "rb");
	unsigned char *buf;
	long n;

	assert_non_null(f);
	assert_int_equal(fseek(f, 0, SEEK_END), 0);
	n = ftell(f);
	assert_true(n >= 0);
	rewind(f);
	/* One byte more, so that an empty file has a buffer too. */
	buf = malloc((size_t)n + 1);
	assert_non_null(buf);
	assert_int_equal(fread(buf, 1, (size_t)n, f), (size_t)n);
	fclose(f);
	*len = (size_t)n;
	return buf;
}

size_t support_keyword_list(char *out, size_t size)
{
	const struct shape_ops *const *all = shape_ops_all();
	size_t i, j, used = 0;

	out[0] = '\0';
	for (i = 0; all[i]; i++) {
		bool seen = false;

		for (j = 0; j < i; j++)
			seen = seen || strcmp(all[j]->keyword, all[i]->keyword) == 0;
		if (seen)
			continue;
		used += strlen(all[i]->keyword) + (out[0] ? 2 : 0);
		assert_true(used < size);
		if (out[0])
			strcat(out, ", ");
		strcat(out, all[i]->keyword);
	}
	return i;
}
