/* The build of the hierarchy against Embree's, on the same primitives:
 * reads a scene with whitted's reader, then builds whitted's hierarchy
 * (scene_prepare) and Embree 3's (one user geometry of the scene's bounded
 * shapes, their boxes from whitted's own shape_bounds, the scene committed
 * at Embree's default quality), each with the same number of threads, and
 * prints the median of RUNS builds of each and their ratio.  A benchmark
 * tool for bench/bench.sh, built only where libembree-dev is installed.
 * Usage: embree_build [-j THREADS] [-n RUNS] SCENE */
#define _POSIX_C_SOURCE 200809L
#include <embree3/rtcore.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "whitted/scene.h"
#include "whitted/scenefile.h"
#include "whitted/shape.h"

#define EMBREE_BUILD_MAX_RUNS 15

struct bounded {
	const struct shape **shapes;
	unsigned n;
};

static double now(void)
{
	struct timespec t;

	clock_gettime(CLOCK_MONOTONIC, &t);
	return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

static void shape_box(const struct RTCBoundsFunctionArguments *args)
{
	const struct bounded *b = args->geometryUserPtr;
	struct aabb box;

	shape_bounds(b->shapes[args->primID], &box);
	args->bounds_o->lower_x = (float)box.min.x;
	args->bounds_o->lower_y = (float)box.min.y;
	args->bounds_o->lower_z = (float)box.min.z;
	args->bounds_o->upper_x = (float)box.max.x;
	args->bounds_o->upper_y = (float)box.max.y;
	args->bounds_o->upper_z = (float)box.max.z;
}

static int cmp_double(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;

	return (x > y) - (x < y);
}

static double median(double *v, int n)
{
	qsort(v, (size_t)n, sizeof(*v), cmp_double);
	return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

static double embree_build_once(RTCDevice dev, struct bounded *b)
{
	RTCScene scene = rtcNewScene(dev);
	RTCGeometry geom = rtcNewGeometry(dev, RTC_GEOMETRY_TYPE_USER);
	double t0, t1;

	rtcSetGeometryUserPrimitiveCount(geom, b->n);
	rtcSetGeometryUserData(geom, b);
	rtcSetGeometryBoundsFunction(geom, shape_box, NULL);
	rtcCommitGeometry(geom);
	rtcAttachGeometry(scene, geom);
	rtcReleaseGeometry(geom);
	t0 = now();
	rtcCommitScene(scene);
	t1 = now();
	rtcReleaseScene(scene);
	return t1 - t0;
}

static double whitted_build_once(const char *path, int threads, struct diag *d, int *rc)
{
	struct scene_read_options opt;
	struct scene *s;
	double t0, t1;

	memset(&opt, 0, sizeof(opt));
	opt.threads = threads;
	*rc = scene_load(path, &opt, NULL, NULL, &s, d);
	if (*rc != 0)
		return 0;
	t0 = now();
	*rc = scene_prepare(s, threads, d);
	t1 = now();
	scene_destroy(s);
	return t1 - t0;
}

int main(int argc, char **argv)
{
	double tw[EMBREE_BUILD_MAX_RUNS], te[EMBREE_BUILD_MAX_RUNS];
	struct scene_read_options opt;
	struct bounded b;
	struct scene *s;
	struct diag d;
	RTCDevice dev;
	char config[32];
	int threads = 2, runs = 5, i, rc;
	size_t k;

	while (argc > 2 && argv[1][0] == '-') {
		if (strcmp(argv[1], "-j") == 0)
			threads = atoi(argv[2]);
		else if (strcmp(argv[1], "-n") == 0)
			runs = atoi(argv[2]);
		else
			break;
		argv += 2;
		argc -= 2;
	}
	if (argc != 2 || threads < 1 || runs < 1 || runs > EMBREE_BUILD_MAX_RUNS) {
		fprintf(stderr, "usage: embree_build [-j THREADS] [-n RUNS (1-%d)] SCENE\n",
			EMBREE_BUILD_MAX_RUNS);
		return 2;
	}
	memset(&d, 0, sizeof(d));
	memset(&opt, 0, sizeof(opt));
	opt.threads = threads;
	if (scene_load(argv[1], &opt, NULL, NULL, &s, &d) != 0) {
		fprintf(stderr, "embree_build: %s: %s\n", argv[1], d.msg);
		return 1;
	}
	b.shapes = malloc(scene_shape_count(s) * sizeof(*b.shapes) + 1);
	if (!b.shapes) {
		fprintf(stderr, "embree_build: out of memory\n");
		scene_destroy(s);
		return 1;
	}
	b.n = 0;
	for (k = 0; k < scene_shape_count(s); k++) {
		struct aabb box;
		if (shape_bounds(scene_shape(s, k), &box))
			b.shapes[b.n++] = scene_shape(s, k);
	}
	snprintf(config, sizeof(config), "threads=%d", threads);
	dev = rtcNewDevice(config);
	if (!dev) {
		fprintf(stderr, "embree_build: Embree refused its device\n");
		return 1;
	}
	/* Alternating, as the benchmark does with whole programs. */
	for (i = 0; i < runs; i++) {
		te[i] = embree_build_once(dev, &b);
		tw[i] = whitted_build_once(argv[1], threads, &d, &rc);
		if (rc != 0) {
			fprintf(stderr, "embree_build: %s: %s\n", argv[1], d.msg);
			return 1;
		}
	}
	printf("build of %u primitives, %d threads, median of %d: whitted %.3f s, Embree %.3f s, "
	       "whitted/Embree %.2f\n", b.n, threads, runs, median(tw, runs), median(te, runs),
	       median(tw, runs) / median(te, runs));
	rtcReleaseDevice(dev);
	free(b.shapes);
	scene_destroy(s);
	return 0;
}
