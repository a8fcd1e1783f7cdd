/* The BVH against brute force: for random scenes of every primitive, the
 * nearest hit (the very shape, ties included, and t) and occlusion agree
 * with a plain loop over the shapes (the unbounded ones, then the others,
 * each in the scene's order) with a strict comparison; rays that graze a shape exactly where its box ends (the
 * boxes are floats, rounded outwards and widened); exact ties between
 * copies, and between a floor and the solids standing on it; the
 * four-child tree's own invariants; and the degenerate scenes (one
 * centre, one shape, none, very many, boxes too big for the tree). */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "accel/accel.h"
#include "accel/accel_build.h"
#include "accel/accel_kernels.h"
#include "accel/accel_tree.h"
#include "shapes/solve.h"
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

/* The four-child tree holds every bounded shape exactly once, in a leaf
 * whose box (and every box above it) holds the shape's own box; each node
 * but the root is reached once; empty children come last, with empty
 * boxes. */
static void assert_accel_sound(const struct accel *a)
{
	const int w = a->width;
	unsigned char *seen = test_calloc(a->n_bounded + 1, 1);
	unsigned char *reached = test_calloc(a->n_nodes + 1, 1);
	struct { size_t node; float lo[3], hi[3]; } stack[(ACCEL_WIDTH_MAX - 1) * ACCEL_STACK + 1];
	size_t i, shapes = 0;
	int top = 0, k;

	if (a->n_nodes == 0) {
		assert_int_equal(a->n_bounded, 0);
		goto out;
	}
	stack[top].node = 0;
	for (k = 0; k < 3; k++) {
		stack[top].lo[k] = -INFINITY;
		stack[top].hi[k] = INFINITY;
	}
	top++;
	while (top > 0) {
		const float *lo, *hi;
		const uint32_t *slots;
		float plo[3], phi[3];
		int c, empty = 0;

		top--;
		lo = (const float *)(const void *)((const char *)a->nodes +
						   stack[top].node * accel_node_bytes(w));
		hi = lo + 3 * w;
		slots = (const uint32_t *)(const void *)(hi + 3 * w);
		memcpy(plo, stack[top].lo, sizeof(plo));
		memcpy(phi, stack[top].hi, sizeof(phi));
		for (c = 0; c < w; c++) {
			uintptr_t slot = slots[c];
			if (slot == 0) {
				/* An empty child: none before it. */
				empty = 1;
				for (k = 0; k < 3; k++)
					assert_true(lo[k * w + c] > hi[k * w + c]);
				continue;
			}
			assert_false(empty);
			for (k = 0; k < 3; k++) {
				assert_true(lo[k * w + c] >= plo[k]);
				assert_true(hi[k * w + c] <= phi[k]);
			}
			if (accel_slot_is_node(slot)) {
				size_t j = accel_slot_index(slot);
				assert_true(j > 0 && j < a->n_nodes);
				assert_false(reached[j]);
				reached[j] = 1;
				stack[top].node = j;
				for (k = 0; k < 3; k++) {
					stack[top].lo[k] = lo[k * w + c];
					stack[top].hi[k] = hi[k * w + c];
				}
				top++;
				continue;
			}
			for (i = 0; i < accel_slot_tag(slot); i++) {
				size_t pos = accel_slot_index(slot) + i;
				struct aabb box;
				assert_true(pos < a->n_bounded);
				assert_false(seen[pos]);
				seen[pos] = 1;
				shapes++;
				assert_true(shape_bounds(a->bounded[pos], &box));
				assert_true(lo[0 * w + c] <= box.min.x && box.max.x <= hi[0 * w + c]);
				assert_true(lo[1 * w + c] <= box.min.y && box.max.y <= hi[1 * w + c]);
				assert_true(lo[2 * w + c] <= box.min.z && box.max.z <= hi[2 * w + c]);
			}
		}
	}
	assert_int_equal(shapes, a->n_bounded);
	for (i = 1; i < a->n_nodes; i++)
		assert_true(reached[i]);
out:
	test_free(seen);
	test_free(reached);
}

static void assert_tree_sound(const struct scene *s)
{
	assert_accel_sound(s->accel);
}

/* A random primitive near centre c with size about `size`. */
static void add_random_shape(struct scene *s, struct vec3 c, double size)
{
	double kind = support_rng();

	if (kind < 0.35) {
		add(s, sphere_create(c, support_uniform(0.05, 1.0) * size, &mat));
	} else if (kind < 0.7) {
		add(s, triangle_create(vec3_add(c, support_random_point(size)), vec3_add(c, support_random_point(size)),
				       vec3_add(c, support_random_point(size)), &mat));
	} else {
		/* An ellipsoid, hyperboloid or cylinder around c:
		 * a (x-cx)^2 + b (y-cy)^2 + e (z-cz)^2 = r^2 expanded. */
		double a = support_uniform(0.2, 1.0), b = support_uniform(0.2, 1.0);
		double e = support_rng() < 0.3 ? 0.0 : support_rng() < 0.5 ? -support_uniform(0.2, 1.0) : support_uniform(0.2, 1.0);
		double r = support_uniform(0.2, 1.0) * size;
		double coef[10] = {
			a, b, e, 0, 0, 0, -2 * a * c.x, -2 * b * c.y, -2 * e * c.z,
			a * c.x * c.x + b * c.y * c.y + e * c.z * c.z - r * r,
		};
		struct vec3 ext = vec3_make(support_uniform(0.5, 2) * size, support_uniform(0.5, 2) * size,
					    support_uniform(0.5, 2) * size);
		double clip = support_rng();

		/* Clipped on all three axes (bounded), on some, or not at all. */
		if (clip < 0.5) {
			/* all three */
		} else if (clip < 0.65) {
			ext.x = 0;
		} else if (clip < 0.8) {
			ext.y = ext.z = 0;
		} else {
			ext = vec3_make(0, 0, 0);
		}
		add(s, quadric_create(coef, vec3_sub(c, vec3_scale(ext, 0.5)), ext, &mat));
	}
}

/* Brute force: the nearest hit over every shape. */
/* The plain loop whose answer the walk must give, ties included: the
 * shapes the tree leaves out (unbounded ones, and boxes past
 * ACCEL_COORD_MAX) first, then the others, each in the scene's order. */
static const struct shape *brute_nearest(const struct scene *s, const struct ray *r,
					 double t_min, double *t_max)
{
	const struct shape *hit = NULL;
	int pass;
	size_t i;

	for (pass = 0; pass < 2; pass++)
		for (i = 0; i < s->n_shapes; i++) {
			struct aabb box;
			if (accel_tree_box(s->shapes[i], &box) != (pass == 1))
				continue;
			if (shape_intersect(s->shapes[i], r, t_min, t_max))
				hit = s->shapes[i];
		}
	return hit;
}

static size_t shape_index(const struct scene *s, const struct shape *sh)
{
	size_t i;

	for (i = 0; i < s->n_shapes; i++)
		if (s->shapes[i] == sh)
			return i;
	return (size_t)-1;
}

static bool brute_occluded(const struct scene *s, const struct ray *r, double t_min, double t_max)
{
	size_t i;

	for (i = 0; i < s->n_shapes; i++) {
		double t = t_max;
		if (shape_intersect(s->shapes[i], r, t_min, &t))
			return true;
	}
	return false;
}

/* Compares the BVH with brute force on n rays, with the scene's own
 * hierarchy and one built for each walk the processor runs (so the
 * eight-child trees face every test, whatever the scene's size); returns
 * how many hit. */
static int compare_rays(const struct scene *s, int n, double half)
{
	struct walk_set w;
	int i, k, hits = 0;

	walk_set_build(&w, s);

	for (i = 0; i < n; i++) {
		struct ray r;
		double t_min = support_rng() < 0.5 ? 1e-6 : support_uniform(0, half);
		double t_max = support_rng() < 0.5 ? INFINITY : support_uniform(t_min, 4 * half);
		double ta = t_max, tb = t_max;
		const struct shape *a, *b;

		r.origin = support_random_point(1.5 * half);
		if (support_rng() < 0.5 && s->n_shapes > 0) {
			/* Aim at a random shape's box (or the origin). */
			struct aabb box;
			const struct shape *target = s->shapes[(size_t)(support_rng() * (double)s->n_shapes)];
			struct vec3 aim = shape_bounds(target, &box) ? aabb_centre(box) : vec3_make(0, 0, 0);
			r.dir = vec3_normalize(vec3_sub(vec3_add(aim, support_random_point(0.1)), r.origin));
			if (vec3_length(r.dir) == 0.0)
				r.dir = support_random_direction();
		} else {
			r.dir = support_random_direction();
		}
		if (support_rng() < 0.1)
			r.dir = vec3_scale(r.dir, support_uniform(0.1, 10));	/* not unit */
		if (support_rng() < 0.05) {
			/* Along an axis: zero components in the slab test. */
			int axis = (int)(support_rng() * 3);
			r.dir = vec3_make(axis == 0, axis == 1, axis == 2);
			if (support_rng() < 0.5)
				r.dir = vec3_neg(r.dir);
		}
		b = brute_nearest(s, &r, t_min, &tb);
		hits += b != NULL;
		for (k = -1; k < w.n; k++) {
			const struct accel *acc = k < 0 ? s->accel : w.a[k];
			ta = t_max;
			a = accel_intersect(acc, &r, t_min, &ta);
			if (ta != tb || (a == NULL) != (b == NULL)) {
				print_error("ray %d (%s walk): BVH t = %.17g (%s), brute force t = "
					    "%.17g (%s)\n", i, accel_walk_name(acc), ta,
					    a ? a->ops->keyword : "none", tb,
					    b ? b->ops->keyword : "none");
				fail();
			}
			if (a != b) {
				/* A tie the walk gave to another shape than the
				 * loop's first. */
				print_error("ray %d (%s walk): BVH shape %zu, brute force shape %zu, "
					    "both at t = %.17g\n", i, accel_walk_name(acc),
					    shape_index(s, a), shape_index(s, b), ta);
				fail();
			}
			if (accel_occluded(acc, &r, t_min, t_max) !=
			    brute_occluded(s, &r, t_min, t_max)) {
				print_error("ray %d (%s walk): occlusion differs\n", i,
					    accel_walk_name(acc));
				fail();
			}
		}
	}
	walk_set_free(&w);
	return hits;
}

static void test_accel_random_scenes_match_brute_force(void **state)
{
	int scene_no;

	(void)state;
	for (scene_no = 0; scene_no < 12; scene_no++) {
		double half = 50;
		struct scene *s = random_scene(add_random_shape, (uint64_t)scene_no + 1,
					       1 + scene_no * scene_no * 4, half, scene_no % 2 == 0);
		int hits;

		assert_tree_sound(s);
		hits = compare_rays(s, 3000, half);
		/* The rays aimed at shapes mostly hit. */
		assert_true(hits > 300);
		scene_destroy(s);
	}
}

/* Every walk the processor runs (AVX2 and AVX-512 over eight-child trees)
 * gives the base walks' answers (SSE2 over four children) to the bit: the
 * same nearest shape (not only one at the same distance: the tie rule
 * makes the answer the tree's and the walk's order's no matter), the
 * same t, the same occlusion, on random scenes and rays (axis-aligned
 * ones too, whose slabs hold infinities and NaNs); and each tree is
 * sound. */
static void test_accel_wide_walks_match_the_base_walks(void **state)
{
	int scene_no;

	(void)state;
	/* Every processor with AVX-512 has AVX2; the set says whether the
	 * AVX-512 walks are among those compared. */
	support_need_isa(RT_SIMD_AVX2, accel_walk_usable(RT_SIMD_AVX2));
	for (scene_no = 0; scene_no < 6; scene_no++) {
		double half = 50;
		struct scene *s = random_scene(add_random_shape, (uint64_t)scene_no + 101,
					       40 + scene_no * scene_no * 60, half, scene_no % 2 == 1);
		struct walk_set w;
		int i, k;

		walk_set_build(&w, s);
		assert_true(w.n >= 2);
		for (k = 0; k < w.n; k++)
			assert_accel_sound(w.a[k]);
		for (i = 0; i < 4000; i++) {
			struct ray r;
			double t_min = support_rng() < 0.5 ? 1e-6 : support_uniform(0, half);
			double t_max = support_rng() < 0.5 ? INFINITY : support_uniform(t_min, 4 * half);
			double ta = t_max;
			const struct shape *sa;
			bool occluded;

			r.origin = support_random_point(1.5 * half);
			r.dir = support_random_direction();
			if (support_rng() < 0.5) {
				struct aabb box;
				const struct shape *target = s->shapes[(size_t)(support_rng() * (double)s->n_shapes)];
				if (shape_bounds(target, &box))
					r.dir = vec3_sub(aabb_centre(box), r.origin);
				if (vec3_length(r.dir) == 0.0)
					r.dir = support_random_direction();
			}
			if (support_rng() < 0.1) {
				int axis = (int)(support_rng() * 3);
				r.dir = vec3_make(axis == 0, axis == 1, -(double)(axis == 2));
			}
			sa = accel_intersect(w.a[0], &r, t_min, &ta);
			occluded = accel_occluded(w.a[0], &r, t_min, t_max);
			for (k = 1; k < w.n; k++) {
				double tb = t_max;
				const struct shape *sb = accel_intersect(w.a[k], &r, t_min, &tb);
				assert_ptr_equal(sa, sb);
				assert_memory_equal(&ta, &tb, sizeof(ta));
				assert_int_equal(occluded, accel_occluded(w.a[k], &r, t_min, t_max));
			}
		}
		walk_set_free(&w);
		scene_destroy(s);
	}
}

static void test_accel_all_shapes_at_one_centre(void **state)
{
	struct scene *s = scene_create("one centre");
	struct diag d;
	int i;

	(void)state;
	support_rng_seed(99);
	/* Spheres of different radii, and triangles and clipped quadrics
	 * whose boxes share the centre: no split by centres is possible. */
	for (i = 0; i < 200; i++) {
		double r = 0.5 + i * 0.05;
		add(s, sphere_create(vec3_make(3, 3, 3), r, &mat));
	}
	for (i = 0; i < 100; i++) {
		struct vec3 a = support_random_point(5);
		add(s, triangle_create(vec3_add(vec3_make(3, 3, 3), a), vec3_sub(vec3_make(3, 3, 3), a),
				       vec3_add(vec3_make(3, 3, 3), vec3_cross(a, vec3_make(0, 0, 1))), &mat));
	}
	assert_int_equal(scene_prepare(s, 1, &d), 0);
	assert_true(accel_node_count(s->accel) > 1);
	assert_true(compare_rays(s, 3000, 10) > 300);
	scene_destroy(s);
}

static void test_accel_one_shape(void **state)
{
	struct scene *s = scene_create("one");
	struct ray r;
	struct diag d;
	double t = INFINITY;

	(void)state;
	add(s, sphere_create(vec3_make(0, 0, 0), 2, &mat));
	assert_int_equal(scene_prepare(s, 1, &d), 0);
	assert_int_equal(accel_node_count(s->accel), 1);
	r.origin = vec3_make(0, 0, -10);
	r.dir = vec3_make(0, 0, 1);
	assert_ptr_equal(accel_intersect(s->accel, &r, 0, &t), s->shapes[0]);
	assert_near(t, 8.0, 1e-12);
	assert_true(accel_occluded(s->accel, &r, 0, 8.5));
	assert_false(accel_occluded(s->accel, &r, 0, 8.0));
	r.dir = vec3_make(0, 0, -1);
	t = INFINITY;
	assert_null(accel_intersect(s->accel, &r, 0, &t));
	assert_true(isinf(t));
	support_rng_seed(7);
	compare_rays(s, 2000, 5);
	scene_destroy(s);
}

static void test_accel_no_shapes(void **state)
{
	struct scene *s = scene_create("empty");
	struct ray r;
	struct diag d;
	double t = 5.0;

	(void)state;
	assert_int_equal(scene_prepare(s, 1, &d), 0);
	assert_non_null(s->accel);
	assert_int_equal(accel_node_count(s->accel), 0);
	r.origin = vec3_make(0, 0, 0);
	r.dir = vec3_make(1, 0, 0);
	assert_null(accel_intersect(s->accel, &r, 0, &t));
	assert_near(t, 5.0, 0.0);
	assert_false(accel_occluded(s->accel, &r, 0, INFINITY));
	/* Only unbounded shapes: no nodes, but hits. */
	{
		static const double plane[10] = { 0, 0, 0, 0, 0, 0, 1, 0, 0, -3 };
		add(s, quadric_create(plane, vec3_make(0, 0, 0), vec3_make(0, 0, 0), &mat));
	}
	assert_int_equal(scene_prepare(s, 1, &d), 0);
	assert_int_equal(accel_node_count(s->accel), 0);
	t = INFINITY;
	assert_ptr_equal(accel_intersect(s->accel, &r, 0, &t), s->shapes[0]);
	assert_near(t, 3.0, 0.0);
	assert_true(accel_occluded(s->accel, &r, 0, INFINITY));
	assert_false(accel_occluded(s->accel, &r, 0, 3.0));
	scene_destroy(s);
}

static void test_accel_many_shapes(void **state)
{
	struct scene *s = scene_create("many");
	struct diag d;
	int i;

	(void)state;
	support_rng_seed(10000);
	for (i = 0; i < 10000; i++)
		add_random_shape(s, support_random_point(200), support_uniform(0.2, 3));
	assert_int_equal(scene_add_floor(s, 300, 10, &d), 0);
	assert_int_equal(scene_prepare(s, 1, &d), 0);
	assert_true(accel_node_count(s->accel) > 1000);
	assert_true(accel_bytes(s->accel) > accel_node_count(s->accel));
	assert_true(compare_rays(s, 3000, 200) > 300);
	/* Preparing again rebuilds without leaking the old hierarchy. */
	assert_int_equal(scene_prepare(s, 1, &d), 0);
	scene_destroy(s);
}

static void test_accel_many_at_one_point(void **state)
{
	struct scene *s = scene_create("stack");
	struct diag d;
	int i;

	(void)state;
	/* 10000 identical tiny spheres: the median split must still end. */
	for (i = 0; i < 10000; i++)
		add(s, sphere_create(vec3_make(1, 2, 3), 0.5, &mat));
	assert_int_equal(scene_prepare(s, 1, &d), 0);
	support_rng_seed(3);
	compare_rays(s, 500, 4);
	scene_destroy(s);
}

/* Node i's slots in a's tree, of either width. */
static const uint32_t *node_slots(const struct accel *a, size_t i)
{
	int w = a->width;

	return (const uint32_t *)(const void *)((const char *)a->nodes + i * accel_node_bytes(w) +
						 6 * (size_t)w * sizeof(float));
}

/* The halves of big nodes are built by different threads, each into the
 * node indices its refs reserve, and the wide levels of the collapse by
 * two: the tree must come out the same, node for node and in the same
 * order, whatever the number of threads, at both widths (the build does
 * not need the processor to run a walk: these trees are not walked). */
static void assert_same_tree_for_threads(struct scene *s)
{
	static const enum rt_simd walks[] = { RT_SIMD_BASE, RT_SIMD_AVX2 };
	static const int threads[] = { 2, 3, 7, 64 };
	struct diag d;
	size_t j, k, i;

	assert_int_equal(scene_prepare(s, 1, &d), 0);
	for (j = 0; j < sizeof(walks) / sizeof(walks[0]); j++) {
		struct accel *one, *many;
		size_t bytes;

		assert_int_equal(accel_build_walk(s->shapes, s->n_shapes, 1, walks[j], &one, &d), 0);
		bytes = one->n_nodes * accel_node_bytes(accel_kernels_of(walks[j])->width);
		assert_accel_sound(one);
		for (k = 0; k < sizeof(threads) / sizeof(threads[0]); k++) {
			assert_int_equal(accel_build_walk(s->shapes, s->n_shapes, threads[k], walks[j],
							  &many, &d), 0);
			assert_int_equal(many->n_nodes, one->n_nodes);
			assert_int_equal(many->n_bounded, one->n_bounded);
			assert_memory_equal(many->nodes, one->nodes, bytes);
			assert_memory_equal(many->bounded, one->bounded,
					    one->n_bounded * sizeof(*one->bounded));
			for (i = 0; i < one->n_bounded; i++)
				assert_ptr_equal(s->shapes[many->bounded_key[i] - many->n_unbounded],
						 one->bounded[i]);
			accel_destroy(many);
		}
		accel_destroy(one);
	}
}

static void test_accel_threads_build_the_same_tree(void **state)
{
	struct scene *s = scene_create("threads");
	struct diag d;
	int i;

	(void)state;
	support_rng_seed(77);
	/* Big enough that the top nodes' halves (4096 refs and more) go to
	 * other threads; the floor is split off first, as in a real scene. */
	for (i = 0; i < 40000; i++)
		add_random_shape(s, support_random_point(300), support_uniform(0.2, 3));
	assert_int_equal(scene_add_floor(s, 1000, 20, &d), 0);
	assert_same_tree_for_threads(s);
	/* The wide tree: at most half as many nodes as shapes at four
	 * children, 40% at eight (here 36%: nodes over only two or three
	 * leaves), within the room the build allows, the root a node. */
	assert_true(s->accel->n_nodes <= s->accel->n_bounded *
			     (s->accel->width == 4 ? 5 : 4) / 10);
	assert_true(s->accel->n_nodes <=
		    accel_collapse_room(s->accel->n_bounded, s->accel->width));
	assert_int_equal(node_slots(s->accel, 0)[0] & 7, ACCEL_SLOT_NODE);
	/* The nodes packed at 112 and 224 bytes from a cache line's start. */
	assert_int_equal((uintptr_t)s->accel->nodes % ACCEL_NODE_ALIGN, 0);
	assert_int_equal(sizeof(struct bvh4_node), 112);
	assert_int_equal(sizeof(struct bvh8_node), 224);
	assert_int_equal(accel_node_bytes(4), 112);
	assert_int_equal(accel_node_bytes(8), 224);
	assert_tree_sound(s);
	assert_true(compare_rays(s, 3000, 300) > 300);
	scene_destroy(s);
}

/* The room the collapse is given (accel_collapse_room) holds any tree:
 * it is at least the bound counted from the nodes' children (a node with
 * fewer children than the width has only leaves below it, at least two:
 * at most floor((wL/2 - 1) / (w - 1)) nodes for L leaves), and trees reach
 * that bound: 8192 spheres evenly spaced on a line make a balanced binary
 * tree whose collapse leaves every bottom node two leaves. */
static void test_accel_collapse_room_holds_the_fullest_tree(void **state)
{
	static const enum rt_simd walks[] = { RT_SIMD_BASE, RT_SIMD_AVX2 };
	struct scene *s = scene_create("line");
	size_t leaves, j, w;
	struct diag d;
	int i;

	(void)state;
	for (leaves = 1; leaves < 20000; leaves++)
		for (w = 4; w <= 8; w += 4)
			assert_true(accel_collapse_room(leaves, (int)w) >=
				    (w * leaves / 2 > 1 ? (w * leaves / 2 - 1) / (w - 1) : 1));
	for (i = 0; i < 8192; i++)
		add(s, sphere_create(vec3_make(3.0 * i, 0, 0), 1, &mat));
	assert_int_equal(scene_prepare(s, 1, &d), 0);
	for (j = 0; j < 2; j++) {
		struct accel *a;
		assert_int_equal(accel_build_walk(s->shapes, s->n_shapes, 2, walks[j], &a, &d), 0);
		w = (size_t)accel_kernels_of(walks[j])->width;
		assert_int_equal(a->n_bounded, 8192);
		assert_int_equal(a->n_nodes, (w * 8192 / 2 - 1) / (w - 1));	/* 5461, 4681 */
		assert_true(a->n_nodes <= accel_collapse_room(8192, (int)w));
		assert_accel_sound(a);
		accel_destroy(a);
	}
	assert_true(compare_rays(s, 2000, 12000) > 0);
	scene_destroy(s);
}

/* A tree big enough that its wide levels (8192 nodes and more) are made
 * by two threads in the collapse: the same nodes for any thread count,
 * and a sound tree. */
static void test_accel_threads_collapse_the_same_tree(void **state)
{
	struct scene *s = scene_create("wide levels");
	int i;

	(void)state;
	support_rng_seed(78);
	for (i = 0; i < 120000; i++)
		add(s, sphere_create(support_random_point(400), support_uniform(0.2, 2), &mat));
	assert_same_tree_for_threads(s);
	assert_true(s->accel->n_nodes >= 3 * 8192);
	assert_tree_sound(s);
	scene_destroy(s);
}

static void test_accel_threads_median_splits(void **state)
{
	struct scene *s = scene_create("stack");
	int i;

	(void)state;
	/* 20000 shapes at one point: the heuristic finds no split and the
	 * median halves (10000, then 5000) go to other threads. */
	for (i = 0; i < 20000; i++)
		add(s, sphere_create(vec3_make(-1, 2, 5), 0.5, &mat));
	assert_same_tree_for_threads(s);
	support_rng_seed(4);
	compare_rays(s, 300, 6);
	scene_destroy(s);
}

static void test_accel_negative_zero_direction(void **state)
{
	/* A triangle standing on z = 0, its bottom edge on the face z = 0 of
	 * its box, and rays running along that face: they touch the edge
	 * (edges are inclusive) at x = 0, t = 5, whether the zero z
	 * component of the direction is +0 or -0. */
	struct scene *s = scene_create("negative zero");
	static const double zeros[2] = { 0.0, -0.0 };
	struct diag d;
	int i, k;

	(void)state;
	add(s, triangle_create(vec3_make(0, -10, 0), vec3_make(0, 10, 0), vec3_make(0, 0, 20), &mat));
	for (i = 0; i < 10; i++)
		add(s, sphere_create(vec3_make(50 + i * 10, 0, 5), 1, &mat));
	assert_int_equal(scene_prepare(s, 1, &d), 0);
	for (k = 0; k < 2; k++) {
		struct ray r;
		double ta = INFINITY, tb = INFINITY;

		r.origin = vec3_make(-5, 0, 0);
		r.dir = vec3_make(1, zeros[k], zeros[k]);
		assert_ptr_equal(brute_nearest(s, &r, 1e-6, &tb), s->shapes[0]);
		assert_near(tb, 5.0, 0.0);
		assert_ptr_equal(accel_intersect(s->accel, &r, 1e-6, &ta), s->shapes[0]);
		assert_near(ta, 5.0, 0.0);
		assert_true(accel_occluded(s->accel, &r, 1e-6, INFINITY));
		/* The same along the top of a box: the sphere at x = 50 spans
		 * z in [4, 6]; a ray along z = 6 grazes it at (50, 0, 6). */
		r.origin = vec3_make(-5, 0, 6);
		r.dir = vec3_make(1, zeros[k], zeros[k]);
		ta = tb = INFINITY;
		assert_ptr_equal(accel_intersect(s->accel, &r, 1e-6, &ta), brute_nearest(s, &r, 1e-6, &tb));
		assert_true(ta == tb);
	}
	scene_destroy(s);
}

/* Rays that graze a shape where its node's box ends.  Nodes keep their
 * boxes as floats; a bound that is not a float must be rounded outwards,
 * because rounded to the nearest float it moves inwards about half the
 * time (float(0.31) > 0.31, float(0.21) < 0.21), and a ray that meets the
 * shape in the sliver so cut off misses through the hierarchy although it
 * hits by brute force.  The expected answers here come from brute force
 * and from the geometry (a ray on an edge hits: edges are inclusive), the
 * slivers from the test's own float conversion. */

/* The point with coordinate va on axis a, vb on axis (a + 1) % 3 and vc
 * on axis (a + 2) % 3. */
static struct vec3 on_axes(int a, double va, double vb, double vc)
{
	double v[3];

	v[a] = va;
	v[(a + 1) % 3] = vb;
	v[(a + 2) % 3] = vc;
	return vec3_make(v[0], v[1], v[2]);
}

/* The distance from v to the float nearest it, signed: > 0 when that
 * float lies above v. */
static double nearest_float_gap(double v)
{
	return (double)(float)v - v;
}

/* One grazed triangle: its edge A-B lies on the plane a = v (v not a
 * float), along axis (a + 2) % 3 from c0 to c0 + 1, in the plane
 * (a + 1) % 3 = w; its third vertex lies 1 away from the edge on the side
 * `inward`, chosen so that the edge is the box's bound that the nearest
 * float would cut: its minimum when float(v) > v, its maximum otherwise. */
struct graze {
	int a;
	double v, inward, w, c0;
	struct shape *shape;
};

#define GRAZE_PER_AXIS 30

static int make_grazes(struct graze *g)
{
	int a, k, n = 0;

	for (a = 0; a < 3; a++) {
		for (k = 1; k <= GRAZE_PER_AXIS; k++) {
			double v = 0.1 * k + 0.01 + 0.003 * a, gap = nearest_float_gap(v);
			struct graze *e = &g[n];

			if (gap == 0.0)
				continue;
			e->a = a;
			e->v = v;
			e->inward = gap > 0 ? 1.0 : -1.0;
			/* The three families apart: each in its own region. */
			e->w = 50.0 * a + 0.37 * k;
			e->c0 = 50.0 * a + 1.5 * k;
			/* v0 = A, e1 = B - A: the edge's a coordinate is v exactly
			 * in the box (v0 + e1 adds 0). */
			e->shape = triangle_create(on_axes(a, v, e->w, e->c0),
						   on_axes(a, v, e->w, e->c0 + 1.0),
						   on_axes(a, v + e->inward, e->w, e->c0 + 0.5), &mat);
			assert_non_null(e->shape);
			n++;
		}
	}
	return n;
}

/* The ray must hit `want` (brute force says so, for a ray that meets it
 * on its edge or inside it) and the hierarchy must agree, for the nearest
 * hit and for occlusion. */
static void check_graze(const struct scene *s, const struct walk_set *w,
			const struct shape *want, struct ray r, const char *what, int index)
{
	double ta, tb = INFINITY;
	const struct shape *a, *b;
	int k;

	b = brute_nearest(s, &r, 1e-6, &tb);
	if (b != want) {
		print_error("%s %d: brute force misses the grazed shape\n", what, index);
		fail();
	}
	for (k = -1; k < w->n; k++) {
		const struct accel *acc = k < 0 ? s->accel : w->a[k];
		ta = INFINITY;
		a = accel_intersect(acc, &r, 1e-6, &ta);
		if (a != b || ta != tb) {
			print_error("%s %d (%s walk): ray from (%.17g, %.17g, %.17g) along (%g, %g, "
				    "%g): BVH %s at t = %.17g, brute force %s at t = %.17g\n", what,
				    index, accel_walk_name(acc), r.origin.x, r.origin.y, r.origin.z,
				    r.dir.x, r.dir.y, r.dir.z, a ? "hits" : "misses", ta,
				    b ? "hits" : "misses", tb);
			fail();
		}
		if (!accel_occluded(acc, &r, 1e-6, 2 * tb)) {
			print_error("%s %d (%s walk): the BVH finds no blocker; brute force hits at "
				    "t = %.17g\n", what, index, accel_walk_name(acc), tb);
			fail();
		}
	}
}

/* Perpendicular rays exactly on the edge (its middle and both ends) and
 * a sliver inside it, where the nearest float would cut the box, and an
 * oblique ray through that sliver. */
static void check_grazes(const struct scene *s, const struct graze *g, int n)
{
	struct walk_set w;
	int i;

	walk_set_build(&w, s);
	for (i = 0; i < n; i++) {
		const struct graze *e = &g[i];
		struct vec3 down = on_axes(e->a, 0, -1, 0);
		double sliver = e->v + 0.5 * nearest_float_gap(e->v);
		struct vec3 dir = vec3_normalize(on_axes(e->a, 0.3 * e->inward, -1, 0.2));
		struct vec3 target = on_axes(e->a, sliver, e->w, e->c0 + 0.5);
		struct ray r;

		/* gap/2 towards the triangle: strictly between v and float(v). */
		assert_true((sliver - e->v) * e->inward > 0);
		r.dir = down;
		r.origin = on_axes(e->a, e->v, e->w + 5, e->c0 + 0.5);
		check_graze(s, &w, e->shape, r, "edge", i);
		r.origin = on_axes(e->a, e->v, e->w + 5, e->c0);
		check_graze(s, &w, e->shape, r, "vertex A", i);
		r.origin = on_axes(e->a, e->v, e->w + 5, e->c0 + 1.0);
		check_graze(s, &w, e->shape, r, "vertex B", i);
		r.origin = on_axes(e->a, sliver, e->w + 5, e->c0 + 0.5);
		check_graze(s, &w, e->shape, r, "sliver", i);
		r.dir = dir;
		r.origin = vec3_add_scaled(target, dir, -5.0);
		check_graze(s, &w, e->shape, r, "oblique", i);
	}
	walk_set_free(&w);
}

static void test_accel_rays_grazing_box_bounds(void **state)
{
	struct graze g[3 * GRAZE_PER_AXIS];
	struct scene *s = scene_create("grazes");
	struct diag d;
	int n, i, cut_min = 0, cut_max = 0;

	(void)state;
	n = make_grazes(g);
	for (i = 0; i < n; i++) {
		add(s, g[i].shape);
		cut_min += g[i].inward > 0;
		cut_max += g[i].inward < 0;
	}
	/* Both kinds of bound, on every axis, in a tree of several levels. */
	assert_true(cut_min >= 20 && cut_max >= 20);
	assert_int_equal(scene_prepare(s, 1, &d), 0);
	assert_true(accel_node_count(s->accel) > 8);
	check_grazes(s, g, n);
	scene_destroy(s);
	/* And each triangle alone, where its box is the root's child. */
	n = make_grazes(g);
	for (i = 0; i < n; i++) {
		s = scene_create("one graze");
		add(s, g[i].shape);
		assert_int_equal(scene_prepare(s, 1, &d), 0);
		check_grazes(s, &g[i], 1);
		scene_destroy(s);
	}
}

static void test_accel_rays_grazing_clip_faces(void **state)
{
	/* Radius-2 spheres as quadrics, at (0, 0, 0) clipped to z in
	 * [-0.69, 0.7] and at (0, 8, 0) ((x)^2 + (y - 8)^2 + z^2 = 4) clipped
	 * to z in [-1.5, -1.5 + 2.2], that is [-1.5, 0.7000000000000002]: each
	 * box is its clip box, and rays across a sphere at the height of a
	 * clip face meet the surface on the face (the clip is inclusive).
	 * -0.69 and 0.7000000000000002 are not floats, and the floats nearest
	 * them lie inside the box. */
	static const double coef[2][10] = {
		{ 1, 1, 1, 0, 0, 0, 0, 0, 0, -4 },
		{ 1, 1, 1, 0, 0, 0, 0, -16, 0, 60 },
	};
	struct scene *s = scene_create("clip faces");
	struct walk_set w;
	struct shape *q;
	struct aabb box;
	struct diag d;
	int i, k;

	(void)state;
	add(s, quadric_create(coef[0], vec3_make(-3, -3, -0.69), vec3_make(6, 6, 1.39), &mat));
	add(s, quadric_create(coef[1], vec3_make(-3, 5, -1.5), vec3_make(6, 6, 2.2), &mat));
	/* Spheres around them, so that the quadrics sit in a tree. */
	for (i = 0; i < 12; i++)
		add(s, sphere_create(vec3_make(20.0 * (i % 4) - 30, 20.0 * (i / 4) + 20, 0), 1, &mat));
	assert_int_equal(scene_prepare(s, 1, &d), 0);
	walk_set_build(&w, s);
	for (k = 0; k < 2; k++) {
		/* The face the nearest float would cut: the bottom of the first
		 * box, the top of the second. */
		double face, heights[2];
		double cy = 8.0 * k;

		q = s->shapes[k];
		assert_true(shape_bounds(q, &box));
		face = k == 0 ? box.min.z : box.max.z;
		assert_true(k == 0 ? nearest_float_gap(face) > 0 : nearest_float_gap(face) < 0);
		heights[0] = face;
		heights[1] = face + 0.5 * nearest_float_gap(face);
		for (i = 0; i < 2; i++) {
			struct ray r;

			r.origin = vec3_make(-10, cy, heights[i]);
			r.dir = vec3_make(1, 0, 0);
			check_graze(s, &w, q, r, "clip face", 2 * k + i);
			r.origin = vec3_make(0, k == 0 ? -10 : 20, heights[i]);
			r.dir = vec3_make(0, k == 0 ? 1 : -1, 0);
			check_graze(s, &w, q, r, "clip face", 2 * k + i);
		}
	}
	walk_set_free(&w);
	scene_destroy(s);
}

/* Exact ties: eight copies of each of a few spheres, triangles and cubes,
 * added interleaved so that the build spreads each one's copies over
 * leaves and subtrees; every ray gets the copy first in the scene, as the
 * plain loop does (compare_rays fails on any other). */
static void test_accel_ties_go_to_the_first_in_the_scene(void **state)
{
	struct scene *s = scene_create("ties");
	struct vec3 c[30], e1[30], e2[30];
	double size[30];
	struct diag d;
	int i, j;

	(void)state;
	support_rng_seed(31);
	for (i = 0; i < 30; i++) {
		c[i] = support_random_point(20);
		e1[i] = support_random_point(3);
		e2[i] = support_random_point(3);
		size[i] = support_uniform(0.5, 3);
	}
	for (j = 0; j < 8; j++)
		for (i = 0; i < 30; i++) {
			if (i % 3 == 0)
				add(s, sphere_create(c[i], size[i], &mat));
			else if (i % 3 == 1)
				add(s, triangle_create(c[i], vec3_add(c[i], e1[i]), vec3_add(c[i], e2[i]), &mat));
			else
				add(s, cube_create(c[i], size[i], &mat));
		}
	assert_int_equal(scene_prepare(s, 1, &d), 0);
	assert_tree_sound(s);
	assert_true(compare_rays(s, 4000, 20) > 400);
	scene_destroy(s);
}


/* Cubes and pyramids standing on a floor added after them (as every
 * dialect does): a ray through a bottom edge hits the floor and the solid
 * at the same t, the solid's box ending exactly there.  An infinite floor
 * (nearfar's, unbounded) wins the tie; a finite one (the other dialects',
 * bounded) loses it to the solid, first in the scene; either way the walk
 * must give the loop's shape, however it met the two. */
static void solids_on_a_floor(double width, bool floor_wins)
{
	struct scene *s = scene_create("standing");
	const struct shape *floor;
	struct walk_set w;
	struct diag d;
	int i, k, ties = 0;

	support_rng_seed(12);
	for (i = 0; i < 300; i++) {
		struct vec3 at = vec3_make(support_uniform(-100, 100), support_uniform(-100, 100), 0);
		double side = support_uniform(2, 12);
		if (i % 2)
			add(s, cube_create(at, side, &mat));
		else
			add(s, pyramid_create_centred(at, side, support_uniform(2, 20), &mat));
	}
	add(s, floor_create_view(width, 25, &mat));
	floor = s->shapes[300];
	assert_int_equal(scene_prepare(s, 1, &d), 0);
	/* Every walk: 300 solids make a tree of four children; the
	 * eight-child walks get theirs here. */
	walk_set_build(&w, s);
	for (i = 0; i < 60000; i++) {
		const struct shape *target = s->shapes[(size_t)(support_rng() * 300)];
		struct aabb box;
		struct vec3 p;
		struct ray r;
		double ta = INFINITY, tb = INFINITY, tf = INFINITY;
		const struct shape *a, *b;
		double u = support_rng();

		assert_true(shape_bounds(target, &box));
		/* A point on the bottom edge of the box (the solid's base edge). */
		if (i % 2)
			p = vec3_make(box.min.x + u * (box.max.x - box.min.x), i % 4 == 1 ? box.min.y : box.max.y, 0);
		else
			p = vec3_make(i % 4 == 0 ? box.min.x : box.max.x, box.min.y + u * (box.max.y - box.min.y), 0);
		if (i % 3 == 0) {
			r.origin = vec3_make(support_uniform(-200, 200), support_uniform(-200, 200),
					     support_uniform(1, 80));
		} else {
			/* From far and low, as a camera looks along a floor. */
			double angle = support_uniform(0, 6.283185307179586), far = support_uniform(150, 400);
			r.origin = vec3_make(p.x + far * cos(angle), p.y + far * sin(angle),
					     support_uniform(0.5, 15));
		}
		r.dir = vec3_sub(p, r.origin);
		b = brute_nearest(s, &r, 1e-9, &tb);
		for (k = 0; k < w.n; k++) {
			ta = INFINITY;
			a = accel_intersect(w.a[k], &r, 1e-9, &ta);
			assert_ptr_equal(a, b);
			assert_memory_equal(&ta, &tb, sizeof(ta));
		}
		if (b == (floor_wins ? floor : target) &&
		    shape_intersect(floor_wins ? target : floor, &r, 1e-9, &tf) && tf == tb)
			ties++;
	}
	/* The rays do meet such ties. */
	print_message("%d of the rays tie a solid with the %s floor\n", ties,
		      floor_wins ? "infinite" : "finite");
	assert_true(ties > 100);
	walk_set_free(&w);
	scene_destroy(s);
}

static void test_accel_solids_on_the_floor_tie_at_their_edges(void **state)
{
	(void)state;
	solids_on_a_floor(INFINITY, true);
	solids_on_a_floor(1000, false);
}

/* The ray of the nearfar example (scenes/nearfar.txt at 317 pixels) that
 * found the need of the boxes' margin: it meets the pyramid's bottom edge
 * and the floor at the same t, and the pyramid's box, unwidened, computes
 * an exit just before its entry.  With a finite floor (bounded, after the
 * pyramid) the pyramid wins the tie, and the walk must meet it. */
static void test_accel_pyramid_edge_on_the_floor(void **state)
{
	struct scene *s = scene_create("edge");
	const struct shape *pyramid, *a, *b;
	struct walk_set w;
	struct diag d;
	struct ray r;
	double ta, tb = INFINITY;
	int k;

	(void)state;
	pyramid = pyramid_create_centred(vec3_make(40, 30, 0), 60, 70, &mat);
	add(s, (struct shape *)pyramid);
	assert_int_equal(scene_add_floor(s, 1000, 25, &d), 0);
	assert_int_equal(scene_prepare(s, 1, &d), 0);
	r.origin = vec3_make(2.2071085321150985, -188.01497193346586, 9.400748596673294);
	r.dir = vec3_make(0.18089149926016515, 0.98227597967414304, -0.049113798983707158);
	b = brute_nearest(s, &r, 1e-9, &tb);
	assert_ptr_equal(b, pyramid);
	walk_set_build(&w, s);
	for (k = 0; k < w.n; k++) {
		ta = INFINITY;
		a = accel_intersect(w.a[k], &r, 1e-9, &ta);
		assert_ptr_equal(a, b);
		assert_memory_equal(&ta, &tb, sizeof(ta));
	}
	walk_set_free(&w);
	scene_destroy(s);
}

/* Shapes whose boxes reach past +-1e30 are tested by every ray (the
 * tree's boxes stay finite); they still hit, and the rest still goes
 * through the tree. */
static void test_accel_huge_boxes_are_tested_by_every_ray(void **state)
{
	struct scene *s = scene_create("huge");
	struct diag d;
	int i;

	(void)state;
	support_rng_seed(8);
	for (i = 0; i < 200; i++)
		add_random_shape(s, support_random_point(40), support_uniform(0.5, 5));
	add(s, sphere_create(vec3_make(0, 0, 3e30), 2.99999e30, &mat));
	add(s, sphere_create(vec3_make(1e35, 0, 0), 1.0, &mat));
	add(s, triangle_create(vec3_make(-1e31, -1e31, -30), vec3_make(1e31, -1e31, -30),
			       vec3_make(0, 1e31, -30), &mat));
	assert_int_equal(scene_prepare(s, 1, &d), 0);
	assert_true(s->accel->n_unbounded >= 3);
	assert_tree_sound(s);
	assert_true(compare_rays(s, 3000, 40) > 300);
	scene_destroy(s);
}

SUPPORT_MAIN(SUPPORT_TESTS(test_accel_random_scenes_match_brute_force,
			   test_accel_wide_walks_match_the_base_walks,
			   test_accel_all_shapes_at_one_centre, test_accel_one_shape,
			   test_accel_no_shapes, test_accel_many_shapes,
			   test_accel_many_at_one_point, test_accel_negative_zero_direction,
			   test_accel_rays_grazing_box_bounds,
			   test_accel_rays_grazing_clip_faces,
			   test_accel_threads_build_the_same_tree,
			   test_accel_threads_median_splits,
			   test_accel_threads_collapse_the_same_tree,
			   test_accel_collapse_room_holds_the_fullest_tree,
			   test_accel_ties_go_to_the_first_in_the_scene,
			   test_accel_solids_on_the_floor_tie_at_their_edges,
			   test_accel_huge_boxes_are_tested_by_every_ray,
			   test_accel_pyramid_edge_on_the_floor))
