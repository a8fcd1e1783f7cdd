/* The packet walks against the single-ray walks: every ray of a packet
 * gets what it gets alone, to the bit (the same shape, not only one at the
 * same distance; the same t; the same occlusion), with every walk the
 * processor runs (SSE2 over four children, AVX2 and AVX-512 over eight), on random scenes of every primitive with packets
 * coherent and not (rays that disagree on which child is nearer), exact
 * ties (copies of one shape, cubes that share faces), rays along box faces
 * and edges (slabs of 0 * inf), and a shape with its own packet method;
 * and shadow rays and nearest hits of rays given as lanes in place
 * (accel_occluded_lanes, accel_intersect_lanes). */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "accel/accel.h"
#include "accel/accel_tree.h"
#include "random_scene.h"
#include "support.h"
#include "walk_set.h"

static const struct material mat = { { 1, 1, 1 }, 0.1, 0.5, 0.2, 0.1, 5, 0.0, 1.0 };

static void add(struct scene *s, struct shape *sh)
{
	struct diag d;

	assert_non_null(sh);
	assert_int_equal(scene_add_shape(s, sh, &d), 0);
}

/* A random primitive near c of size about `size`: sphere, triangle,
 * cube, pyramid or a quadric clipped on some axes or none. */
static void add_random_shape(struct scene *s, struct vec3 c, double size)
{
	double kind = support_rng();

	if (kind < 0.3) {
		add(s, sphere_create(c, support_uniform(0.05, 1.0) * size, &mat));
	} else if (kind < 0.6) {
		add(s, triangle_create(vec3_add(c, support_random_point(size)), vec3_add(c, support_random_point(size)),
				       vec3_add(c, support_random_point(size)), &mat));
	} else if (kind < 0.7) {
		add(s, cube_create(c, support_uniform(0.1, 1.0) * size, &mat));
	} else if (kind < 0.8) {
		add(s, pyramid_create(c, support_uniform(0.1, 1.0) * size, support_uniform(0.1, 1.0) * size, &mat));
	} else {
		double a = support_uniform(0.2, 1.0), b = support_uniform(0.2, 1.0), e = support_uniform(-1.0, 1.0);
		double r = support_uniform(0.2, 1.0) * size;
		double coef[10] = {
			a, b, e, 0, 0, 0, -2 * a * c.x, -2 * b * c.y, -2 * e * c.z,
			a * c.x * c.x + b * c.y * c.y + e * c.z * c.z - r * r,
		};
		struct vec3 ext = vec3_make(support_uniform(0.5, 2) * size, support_rng() < 0.3 ? 0 : size, size);

		add(s, quadric_create(coef, vec3_sub(c, vec3_scale(ext, 0.5)), ext, &mat));
	}
}

/* The same rays as lanes left in place (accel_occluded_lanes): the n rays
 * spread over the packet's lanes in a random order, some lanes left out
 * (filled with a copy of another ray, as the caller's), and each active
 * lane blocked exactly when its ray alone is. */
static void check_lanes_with(const struct accel *a, const struct ray *r, int n,
			     const double *t_min, const double *t_max)
{
	struct ray_packet p;
	double lo[ACCEL_PACKET], hi[ACCEL_PACKET];
	int ray_of[ACCEL_PACKET], i;
	uint32_t active = 0, blocked;

	/* Dense masks, sparse ones, one lane, the upper run alone (as a
	 * packet's reflections have them). */
	double u = support_rng(), dense = u < 0.4 ? 0.8 : u < 0.7 ? 0.25 : 0.0;
	int one = (int)(support_rng() * ACCEL_PACKET);

	memset(&p, 0, sizeof(p));
	for (i = 0; i < ACCEL_PACKET; i++) {
		int k = (int)(support_rng() * n) % n;
		struct ray copy = r[k];

		ray_of[i] = k;
		if (u < 0.7 ? support_rng() < dense
			    : u < 0.85 ? i == one : i >= 8 && support_rng() < 0.6)
			active |= (uint32_t)1 << i;
		ray_packet_set(&p, i, &copy);
		lo[i] = t_min[k];
		hi[i] = t_max[k];
	}
	/* Lanes left out hold garbage, as a caller's may. */
	for (i = 0; i < ACCEL_PACKET; i++)
		if (!(active >> i & 1) && support_rng() < 0.5) {
			p.ox[i] = NAN;
			p.dx[i] = INFINITY;
			lo[i] = NAN;
			hi[i] = -1.0;
		}
	blocked = accel_occluded_lanes(a, &p, active, lo, hi);
	assert_int_equal(blocked & ~active, 0);
	/* The nearest hits likewise (accel_intersect_lanes): the active
	 * lanes' shape and t the ray's alone, the others untouched. */
	{
		const struct shape *hit[ACCEL_PACKET];
		double t[ACCEL_PACKET];
		const struct shape *const mark = (const struct shape *)&p;

		for (i = 0; i < ACCEL_PACKET; i++) {
			hit[i] = mark;
			t[i] = active >> i & 1 ? hi[i] : -2.0;
		}
		accel_intersect_lanes(a, &p, active, lo, t, hit);
		for (i = 0; i < ACCEL_PACKET; i++) {
			double ts = hi[i];
			const struct shape *one;

			if (!(active >> i & 1)) {
				if (hit[i] != mark || t[i] != -2.0) {
					print_error("lane %d, not active, written (%s)\n", i,
						    accel_walk_name(a));
					fail();
				}
				continue;
			}
			one = accel_intersect(a, &r[ray_of[i]], lo[i], &ts);
			if (one != hit[i] || memcmp(&ts, &t[i], sizeof(ts)) != 0) {
				print_error("lane %d (ray %d of %d, %s, packets %d): alone %s at %.17g, "
					    "in lanes %s at %.17g\n",
					    i, ray_of[i], n, accel_walk_name(a), (int)a->rays_set,
					    one ? one->ops->keyword : "nothing", ts,
					    hit[i] ? hit[i]->ops->keyword : "nothing", t[i]);
				fail();
			}
		}
	}
	for (i = 0; i < ACCEL_PACKET; i++) {
		bool occ;

		if (!(active >> i & 1))
			continue;
		occ = accel_occluded(a, &r[ray_of[i]], lo[i], hi[i]);
		if (occ != (bool)(blocked >> i & 1)) {
			print_error("lane %d (ray %d of %d, %s, packets %d): occluded alone %d, in "
				    "lanes %d\n",
				    i, ray_of[i], n, accel_walk_name(a), (int)a->rays_set, occ,
				    (int)(blocked >> i & 1));
			fail();
		}
	}
}

/* Compares one packet with the single-ray walks of the same hierarchy:
 * shapes, t to the bit, occlusion; and with the first walk's (the base
 * one's) single rays. */
static void check_packet_with(const struct accel *a, const struct accel *base,
			      const struct ray *r, int n, const double *t_min, const double *t_max)
{
	const struct shape *hit[ACCEL_PACKET];
	double t[ACCEL_PACKET];
	uint32_t blocked;
	int i;

	memcpy(t, t_max, (size_t)n * sizeof(*t));
	accel_intersect_packet(a, r, n, t_min, t, hit);
	blocked = accel_occluded_packet(a, r, n, t_min, t_max);
	for (i = 0; i < n; i++) {
		double ts = t_max[i], tb = t_max[i];
		const struct shape *one = accel_intersect(a, &r[i], t_min[i], &ts);
		const struct shape *by_base = accel_intersect(base, &r[i], t_min[i], &tb);
		bool occ = accel_occluded(a, &r[i], t_min[i], t_max[i]);

		if (one != hit[i] || memcmp(&ts, &t[i], sizeof(ts)) != 0 ||
		    occ != (bool)(blocked >> i & 1) || one != by_base ||
		    memcmp(&ts, &tb, sizeof(ts)) != 0) {
			print_error("ray %d of %d (%s, packets %d): alone %s at t = %.17g, occluded %d; in the "
				    "packet %s at t = %.17g, occluded %d; base walk %s at %.17g\n",
				    i, n, accel_walk_name(a), (int)a->rays_set,
				    one ? one->ops->keyword : "nothing",
				    ts, occ, hit[i] ? hit[i]->ops->keyword : "nothing", t[i],
				    (int)(blocked >> i & 1), by_base ? by_base->ops->keyword : "nothing",
				    tb);
			fail();
		}
	}
	assert_int_equal(blocked >> n, 0);
	check_lanes_with(a, r, n, t_min, t_max);
}

/* With every walk of w. */
static void check_packet(const struct walk_set *w, const struct ray *r, int n,
			 const double *t_min, const double *t_max)
{
	int k;

	for (k = 0; k < w->n; k++)
		check_packet_with(w->a[k], w->a[0], r, n, t_min, t_max);
}

/* A random packet of the kind `kind`: 0, from one point towards a small
 * patch (a block's primary rays); 1, the same towards a wide cone, whose
 * rays disagree on which child is nearer; 2, from points of a small
 * patch towards one point (shadow rays to a light); 3, half towards one
 * place and half towards another; 4, every ray its own; 5, along the
 * axes, either way, some components -0. */
static int random_packet(int kind, double half, struct ray *r, double *t_min, double *t_max)
{
	int n = support_rng() < 0.7 ? ACCEL_PACKET : 1 + (int)(support_rng() * ACCEL_PACKET), i;
	struct vec3 o = support_random_point(1.5 * half), aim = support_random_point(half);
	struct vec3 other = support_random_point(half);
	double spread = kind == 1 ? half : 0.02 * half;
	bool open = support_rng() < 0.5;

	for (i = 0; i < n; i++) {
		switch (kind) {
		case 0:
		case 1:
			r[i].origin = o;
			r[i].dir = vec3_normalize(vec3_sub(vec3_add(aim, support_random_point(spread)), o));
			break;
		case 2:
			r[i].origin = vec3_add(aim, support_random_point(spread));
			r[i].dir = vec3_sub(o, r[i].origin);
			break;
		case 3:
			r[i].origin = o;
			r[i].dir = vec3_sub(i % 2 ? aim : other, o);
			break;
		case 4:
			r[i].origin = support_random_point(1.5 * half);
			r[i].dir = support_random_direction();
			break;
		default: {
			int axis = (int)(support_rng() * 3);
			double sign = support_rng() < 0.5 ? -1.0 : 1.0;
			r[i].origin = vec3_add(o, support_random_point(0.1 * half));
			r[i].dir = vec3_make(axis == 0 ? sign : -0.0 * (support_rng() < 0.5),
					     axis == 1 ? sign : 0.0, axis == 2 ? sign : -0.0);
		}
		}
		if (vec3_length(r[i].dir) == 0.0)
			r[i].dir = support_random_direction();
		t_min[i] = kind == 2 ? 1e-6 : open ? 1e-6 : support_uniform(0, half);
		t_max[i] = kind == 2 ? 1.0 : open ? INFINITY : support_uniform(t_min[i], 4 * half);
	}
	return n;
}

static void test_packet_random_scenes_match_single_rays(void **state)
{
	struct walk_set w;
	int scene_no;

	(void)state;
	for (scene_no = 0; scene_no < 10; scene_no++) {
		double half = 50;
		struct scene *s = random_scene(add_random_shape, (uint64_t)scene_no + 7,
					       1 + scene_no * scene_no * 20, half, scene_no % 3 == 0);
		int k;

		walk_set_build(&w, s);
		for (k = 0; k < 600; k++) {
			struct ray r[ACCEL_PACKET];
			double t_min[ACCEL_PACKET], t_max[ACCEL_PACKET];
			int m = random_packet(k % 6, half, r, t_min, t_max);
			check_packet(&w, r, m, t_min, t_max);
		}
		walk_set_free(&w);
		scene_destroy(s);
	}
}

/* Exact ties: eight copies of each of a few spheres, triangles and cubes
 * (every copy hit at the same t), whose copies the build spreads over
 * leaves and subtrees; the single walk keeps the first copy it meets, and
 * so must each ray of a packet. */
static void test_packet_ties_keep_the_single_walks_shape(void **state)
{
	struct walk_set w;
	struct scene *s = scene_create("ties");
	struct diag d;
	int i, j, k;

	(void)state;
	support_rng_seed(99);
	for (i = 0; i < 30; i++) {
		struct vec3 c = support_random_point(20), a = support_random_point(3), b = support_random_point(3);
		double size = support_uniform(0.5, 3);
		int kind = i % 3;
		for (j = 0; j < 8; j++) {
			if (kind == 0)
				add(s, sphere_create(c, size, &mat));
			else if (kind == 1)
				add(s, triangle_create(c, vec3_add(c, a), vec3_add(c, b), &mat));
			else
				add(s, cube_create(c, size, &mat));
		}
	}
	assert_int_equal(scene_prepare(s, 1, &d), 0);
	walk_set_build(&w, s);
	for (k = 0; k < 1500; k++) {
		struct ray r[ACCEL_PACKET];
		double t_min[ACCEL_PACKET], t_max[ACCEL_PACKET];
		int m = random_packet(k % 6, 20, r, t_min, t_max);
		check_packet(&w, r, m, t_min, t_max);
	}
	walk_set_free(&w);
	scene_destroy(s);
}

/* Unit cubes on an integer lattice, touching (shared faces: ties between
 * neighbours), and rays on the lattice's planes and lines: from integer
 * and half-integer points along the axes (slab values of 0 * inf, NaN,
 * and +-inf) and the diagonals (through edges and corners of boxes). */
static void test_packet_rays_along_faces_and_edges(void **state)
{
	struct walk_set w;
	struct scene *s = scene_create("lattice");
	struct diag d;
	int x, y, z, k;

	(void)state;
	support_rng_seed(5);
	for (x = 0; x < 6; x++)
		for (y = 0; y < 6; y++)
			for (z = 0; z < 6; z++)
				if (support_rng() < 0.6)
					add(s, cube_create(vec3_make(x, y, z), 1.0, &mat));
	assert_int_equal(scene_prepare(s, 1, &d), 0);
	walk_set_build(&w, s);
	for (k = 0; k < 3000; k++) {
		struct ray r[ACCEL_PACKET];
		double t_min[ACCEL_PACKET], t_max[ACCEL_PACKET];
		int n = 1 + (int)(support_rng() * ACCEL_PACKET), i;
		struct vec3 o = vec3_make(floor(support_uniform(-2, 8)), floor(support_uniform(-2, 8)),
					  floor(support_uniform(-2, 8)));

		for (i = 0; i < n; i++) {
			double c[3];
			int j;
			/* Each component of the direction -1, -0, 0 or 1. */
			for (j = 0; j < 3; j++) {
				double u = support_rng();
				c[j] = u < 0.3 ? -1.0 : u < 0.45 ? -0.0 : u < 0.7 ? 0.0 : 1.0;
			}
			if (c[0] == 0.0 && c[1] == 0.0 && c[2] == 0.0)
				c[(int)(support_rng() * 3)] = 1.0;
			r[i].dir = vec3_make(c[0], c[1], c[2]);
			r[i].origin = o;
			if (support_rng() < 0.5)
				r[i].origin = vec3_add(o, vec3_make(0.5 * (int)(support_rng() * 3),
								    0.5 * (int)(support_rng() * 3),
								    0.5 * (int)(support_rng() * 3)));
			t_min[i] = 1e-9;
			t_max[i] = support_rng() < 0.7 ? INFINITY : floor(support_uniform(1, 8));
		}
		check_packet(&w, r, n, t_min, t_max);
	}
	walk_set_free(&w);
	scene_destroy(s);
}

/* Rays on and beside the limits of the float box tests (float_box_ray):
 * origins' coordinates about 1e30 and 2^99, directions' about 2^-24,
 * 2^64 and rounding to float 0 without being 0, t_min about 0 (signed
 * zeros, a tiny negative) and 1e37; the packets' walks check the limits
 * on values rounded to floats (accel_packet_rays.h), and each ray, in a
 * packet with the float tests or with the double ones, gives its single
 * walk's answer. */
static void test_packet_rays_at_the_float_limits(void **state)
{
	static const double coord[] = { 1e30, -1e30, 0x1p99, -0x1p99, 1e30 * (1 - 0x1p-52),
					0x1p99 * (1 - 0x1p-52), 0x1p99 * (1 + 0x1p-52) };
	static const double dir[] = { 0x1p-24, -0x1p-24, 0x1p-24 * (1 - 0x1p-40),
				      0x1p-24 * (1 + 0x1p-40), 1e-46, -1e-46, 1e-300, -0.0,
				      0x1p64, -0x1p64, 0x1p64 * (1 - 0x1p-52),
				      0x1p64 * (1 + 0x1p-52) };
	static const double start[] = { 0.0, -0.0, -1e-300, 1e-300, 1e37, 0x1p122,
					0x1p122 * (1 - 0x1p-52), 1e37 * (1 + 0x1p-52) };
	struct walk_set w;
	struct scene *s = scene_create("limits");
	struct diag d;
	int i, k;

	(void)state;
	support_rng_seed(11);
	for (i = 0; i < 40; i++)
		add_random_shape(s, support_random_point(20), support_uniform(0.5, 5));
	assert_int_equal(scene_add_floor(s, 80, 8, &d), 0);
	assert_int_equal(scene_prepare(s, 1, &d), 0);
	walk_set_build(&w, s);
	for (k = 0; k < 3000; k++) {
		struct ray r[ACCEL_PACKET];
		double t_min[ACCEL_PACKET], t_max[ACCEL_PACKET];
		int n = random_packet(k % 6, 20, r, t_min, t_max);
		/* One lane, or every lane, at a limit. */
		int lane = (int)(support_rng() * n), all = k % 7 == 0, axis = (int)(support_rng() * 3);

		for (i = 0; i < n; i++) {
			double *o = axis == 0 ? &r[i].origin.x : axis == 1 ? &r[i].origin.y : &r[i].origin.z;
			double *dv = axis == 0 ? &r[i].dir.x : axis == 1 ? &r[i].dir.y : &r[i].dir.z;

			if (i != lane && !all)
				continue;
			switch (k / 6 % 3) {
			case 0:
				*o = coord[(int)(support_rng() * (sizeof(coord) / sizeof(coord[0])))];
				break;
			case 1:
				*dv = dir[(int)(support_rng() * (sizeof(dir) / sizeof(dir[0])))];
				break;
			default:
				t_min[i] = start[(int)(support_rng() * (sizeof(start) / sizeof(start[0])))];
				if (t_max[i] < t_min[i])
					t_max[i] = INFINITY;
			}
		}
		check_packet(&w, r, n, t_min, t_max);
	}
	walk_set_free(&w);
	scene_destroy(s);
}

/* No bounded shapes (only the floor), and no shapes at all. */
static void test_packet_unbounded_and_empty(void **state)
{
	struct walk_set w;
	struct scene *s = scene_create("floor only");
	struct ray r[ACCEL_PACKET];
	double t_min[ACCEL_PACKET], t_max[ACCEL_PACKET];
	struct diag d;
	int k;

	(void)state;
	support_rng_seed(3);
	assert_int_equal(scene_add_floor(s, 80, 8, &d), 0);
	assert_int_equal(scene_prepare(s, 1, &d), 0);
	walk_set_build(&w, s);
	for (k = 0; k < 200; k++) {
		int n = random_packet(k % 6, 50, r, t_min, t_max);
		check_packet(&w, r, n, t_min, t_max);
	}
	walk_set_free(&w);
	scene_destroy(s);
	s = scene_create("empty");
	assert_int_equal(scene_prepare(s, 1, &d), 0);
	walk_set_build(&w, s);
	for (k = 0; k < 20; k++) {
		int n = random_packet(k % 6, 50, r, t_min, t_max);
		check_packet(&w, r, n, t_min, t_max);
	}
	walk_set_free(&w);
	scene_destroy(s);
}

/* A primitive with its own packet method: the walks call it (and not
 * intersect ray by ray), and the answers are still the single walk's. */
static int packet_calls;

static uint32_t counting_intersect_packet(const struct shape *s, const struct ray_packet *p,
					  uint32_t active, const double *t_min, double *t_max)
{
	uint32_t hit = 0;
	int i;

	packet_calls++;
	/* Only the active lanes: the others of a run may hold anything. */
	for (i = 0; i < RT_PACKET_MAX; i++) {
		struct ray r;

		if (!(active >> i & 1))
			continue;
		r = ray_packet_get(p, i);
		if (s->ops->intersect(s, &r, t_min[i], t_max + i))
			hit |= (uint32_t)1 << i;
	}
	return hit;
}

/* r[0..n) as a packet, the other lanes of the last run filled with r[0]
 * (intersect_packet may read them). */
static void to_packet(const struct ray *r, int n, struct ray_packet *p)
{
	int i;

	for (i = 0; i < RT_PACKET_MAX; i++)
		ray_packet_set(p, i, &r[i < n ? i : 0]);
}

static void test_packet_shape_packet_method(void **state)
{
	struct walk_set w;
	struct scene *s = scene_create("packet method");
	struct shape_ops ops;
	struct diag d;
	int i, k, before;

	(void)state;
	support_rng_seed(11);
	for (i = 0; i < 200; i++) {
		struct shape *sh = sphere_create(support_random_point(40), support_uniform(0.5, 4), &mat);
		assert_non_null(sh);
		if (i == 0) {
			ops = *sh->ops;
			assert_non_null(ops.intersect_packet);
			ops.intersect_packet = counting_intersect_packet;
		}
		sh->ops = &ops;
		add(s, sh);
	}
	assert_int_equal(scene_prepare(s, 1, &d), 0);
	walk_set_build(&w, s);
	for (k = 0; k < 600; k++) {
		struct ray r[ACCEL_PACKET];
		double t_min[ACCEL_PACKET], t_max[ACCEL_PACKET];
		int n = random_packet(k % 5, 40, r, t_min, t_max);
		check_packet(&w, r, n, t_min, t_max);
	}
	before = packet_calls;
	assert_true(before > 100);
	/* The default loops intersect: the same answers as the method. */
	for (k = 0; k < 200; k++) {
		struct ray r[ACCEL_PACKET];
		struct ray_packet p;
		double t_min[ACCEL_PACKET], t_max[ACCEL_PACKET], ta[ACCEL_PACKET], tb[ACCEL_PACKET];
		struct shape *sh = s->shapes[k % s->n_shapes];
		int n = random_packet(k % 5, 40, r, t_min, t_max);
		uint32_t mask = (uint32_t)(support_rng() * 65536.0) & (((uint32_t)1 << n) - 1), ma, mb;
		struct shape_ops plain = ops;

		to_packet(r, n, &p);
		plain.intersect_packet = NULL;
		memcpy(ta, t_max, sizeof(ta));
		memcpy(tb, t_max, sizeof(tb));
		ma = shape_intersect_packet(sh, &p, mask, t_min, ta);
		sh->ops = &plain;
		mb = shape_intersect_packet(sh, &p, mask, t_min, tb);
		sh->ops = &ops;
		assert_int_equal(ma, mb);
		assert_memory_equal(ta, tb, (size_t)n * sizeof(double));
		assert_int_equal(ma & ~mask, 0);
	}
	walk_set_free(&w);
	scene_destroy(s);
}

/* The default packet method on a whole mask of RT_PACKET_MAX rays (the
 * top bit too): each ray as intersect answers it alone. */
static void test_packet_default_method_full_mask(void **state)
{
	struct shape *sh = sphere_create(vec3_make(0, 0, 0), 5, &mat);
	struct shape_ops plain;
	struct ray r[RT_PACKET_MAX];
	struct ray_packet p;
	double t_min[RT_PACKET_MAX], t[RT_PACKET_MAX];
	uint32_t hit;
	int i, hits = 0;

	(void)state;
	assert_non_null(sh);
	plain = *sh->ops;
	plain.intersect_packet = NULL;
	sh->ops = &plain;
	support_rng_seed(21);
	for (i = 0; i < RT_PACKET_MAX; i++) {
		r[i].origin = vec3_make(support_uniform(-8, 8), -20, support_uniform(-8, 8));
		r[i].dir = vec3_make(0, 1, 0);
		t_min[i] = 1e-6;
		t[i] = INFINITY;
	}
	to_packet(r, RT_PACKET_MAX, &p);
	hit = shape_intersect_packet(sh, &p, ~(uint32_t)0, t_min, t);
	for (i = 0; i < RT_PACKET_MAX; i++) {
		double ts = INFINITY;
		bool one = shape_intersect(sh, &r[i], t_min[i], &ts);
		assert_int_equal(one, (bool)(hit >> i & 1));
		assert_memory_equal(&ts, &t[i], sizeof(ts));
		hits += one;
	}
	assert_true(hits > 4 && hits < RT_PACKET_MAX);
	shape_destroy(sh);
}

/* A packet method that answers for rays it was not asked about (every
 * bit set) must not reach them: the host keeps only the active bits, so
 * no ray outside the mask is hit and nothing is written past the
 * packet's arrays (the sanitizer build would see it). */
static uint32_t stray_intersect_packet(const struct shape *s, const struct ray_packet *p,
				       uint32_t active, const double *t_min, double *t_max)
{
	(void)s;
	(void)p;
	(void)active;
	(void)t_min;
	(void)t_max;
	return ~(uint32_t)0;
}

static void test_packet_stray_bits_of_a_method_are_dropped(void **state)
{
	struct scene *s = scene_create("stray bits");
	struct shape_ops ops;
	struct ray r[ACCEL_PACKET];
	double t_min[ACCEL_PACKET], t_max[ACCEL_PACKET];
	const struct shape *hit[ACCEL_PACKET];
	struct diag d;
	struct shape *bad = NULL;
	int i, k;

	(void)state;
	support_rng_seed(31);
	for (i = 0; i < 300; i++) {
		struct shape *sh = sphere_create(support_random_point(40), support_uniform(0.5, 4), &mat);
		assert_non_null(sh);
		if (i == 0) {
			ops = *sh->ops;
			ops.intersect_packet = stray_intersect_packet;
			sh->ops = &ops;
			bad = sh;
		}
		add(s, sh);
	}
	assert_int_equal(scene_prepare(s, 1, &d), 0);
	for (i = 0; i < ACCEL_PACKET; i++) {
		r[i].origin = vec3_make(0, -200, 0);
		r[i].dir = vec3_make(0, 1, 0);
		t_min[i] = 1e-6;
		t_max[i] = INFINITY;
	}
	{
		struct ray_packet p;

		to_packet(r, ACCEL_PACKET, &p);
		assert_int_equal(shape_intersect_packet(bad, &p, 0x5, t_min, t_max), 0x5);
	}
	/* One ray at a time through the whole scene: the stray bits would
	 * name rays 1 to 31 of a one-ray packet. */
	for (k = 0; k < 300; k++) {
		struct ray one = { support_random_point(60), vec3_normalize(support_random_point(1)) };
		double lo = 1e-6, hi = INFINITY;

		hit[0] = NULL;
		accel_intersect_packet(s->accel, &one, 1, &lo, &hi, hit);
		assert_true(hit[0] == NULL || hit[0]->ops != NULL);
		(void)accel_occluded_packet(s->accel, &one, 1, &lo, &hi);
	}
	scene_destroy(s);
}

SUPPORT_MAIN(SUPPORT_TESTS(test_packet_random_scenes_match_single_rays,
			   test_packet_ties_keep_the_single_walks_shape,
			   test_packet_rays_along_faces_and_edges,
			   test_packet_rays_at_the_float_limits,
			   test_packet_unbounded_and_empty, test_packet_shape_packet_method,
			   test_packet_stray_bits_of_a_method_are_dropped,
			   test_packet_default_method_full_mask))
