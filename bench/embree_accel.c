/* Embree 3 as whitted's hierarchy, for the benchmark's reference: this
 * file defines the functions of src/accel/accel.h, and build/whitted-embree
 * is whitted linked with it in place of src/accel/ (Makefile), so that the
 * scene reader, camera, shading, threads and image writing are whitted's
 * own and only the hierarchy differs.  The bounded shapes are one Embree
 * user geometry (the "user geometry" layout: Embree's own BVH over boxes
 * from whitted's shape_bounds, padded outwards so that the float origin
 * and traversal cannot lose a hit); for each candidate Embree calls back
 * into whitted's double-precision shape_intersect, which keeps the nearest
 * hit in (t_min, t) exactly as whitted's traversal does, and Embree's
 * float tfar follows it (rounded up) to cull what lies beyond.  Unbounded
 * shapes (and boxes past whitted's ACCEL_COORD_MAX) are tested first, as
 * in whitted, and win an exact tie; of two bounded shapes hit at exactly
 * the same distance, the one earlier in the scene wins (its primID), as
 * in whitted (src/accel/accel_tree.h), whatever order Embree calls them
 * in.  bench.sh still compares the images and says so. */
#define _POSIX_C_SOURCE 200809L
#include <embree3/rtcore.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "accel/accel.h"
#include "base/alloc.h"
#include "whitted/aabb.h"

struct accel {
	RTCDevice device;
	RTCScene scene;
	const struct shape **bounded;
	unsigned n_bounded;
	const struct shape **unbounded;
	size_t n_unbounded;
};

/* What the callbacks need of a query: Embree hands back the context. */
struct query {
	struct RTCIntersectContext base;	/* first: args->context points here */
	const struct ray *r;
	double t_min, t;
	const struct shape *hit;
	unsigned key;		/* the hit's primID */
	bool blocked;
};

/* src/accel's accel_tree_box: what goes into the hierarchy. */
static bool tree_box(const struct shape *s, struct aabb *box)
{
	const double m = 1e30;

	return shape_bounds(s, box) && box->min.x >= -m && box->min.y >= -m && box->min.z >= -m &&
	       box->max.x <= m && box->max.y <= m && box->max.z <= m && box->min.x <= m &&
	       box->min.y <= m && box->min.z <= m && box->max.x >= -m && box->max.y >= -m &&
	       box->max.z >= -m;
}

/* The least double above a hit's t (positive and finite here): the bound
 * that lets a shape tie it. */
static double next_up(double x)
{
	return x < INFINITY ? nextafter(x, INFINITY) : x;
}

static float pad_down(double v)
{
	double p = v - 1e-5 * (1.0 + fabs(v));
	float f = (float)p;
	return (double)f > p ? nextafterf(f, -INFINITY) : f;
}

static float pad_up(double v)
{
	double p = v + 1e-5 * (1.0 + fabs(v));
	float f = (float)p;
	return (double)f < p ? nextafterf(f, INFINITY) : f;
}

static void embree_bounds(const struct RTCBoundsFunctionArguments *args)
{
	const struct accel *a = args->geometryUserPtr;
	struct aabb box;

	shape_bounds(a->bounded[args->primID], &box);
	args->bounds_o->lower_x = pad_down(box.min.x);
	args->bounds_o->lower_y = pad_down(box.min.y);
	args->bounds_o->lower_z = pad_down(box.min.z);
	args->bounds_o->upper_x = pad_up(box.max.x);
	args->bounds_o->upper_y = pad_up(box.max.y);
	args->bounds_o->upper_z = pad_up(box.max.z);
}

/* Embree's single-ray layout: tfar is the ninth float. */
static float *ray_tfar(void *rayn)
{
	return (float *)rayn + 8;
}

static void embree_intersect(const struct RTCIntersectFunctionNArguments *args)
{
	const struct accel *a = args->geometryUserPtr;
	struct query *q = (struct query *)(void *)args->context;
	const struct shape *sh = a->bounded[args->primID];

	double t;

	if (!args->valid[0])
		return;
	t = q->hit ? next_up(q->t) : q->t;
	if (shape_intersect(sh, q->r, q->t_min, &t) && (t < q->t || args->primID < q->key)) {
		q->t = t;
		q->hit = sh;
		q->key = args->primID;
		*ray_tfar(args->rayhit) = pad_up(q->t);
	}
}

static void embree_occluded(const struct RTCOccludedFunctionNArguments *args)
{
	const struct accel *a = args->geometryUserPtr;
	struct query *q = (struct query *)(void *)args->context;
	double t = q->t;

	if (!args->valid[0])
		return;
	if (shape_intersect(a->bounded[args->primID], q->r, q->t_min, &t)) {
		q->blocked = true;
		*ray_tfar(args->ray) = -INFINITY;
	}
}

int accel_build(struct shape *const *shapes, size_t n_shapes, int threads, struct accel **out,
		struct diag *d)
{
	struct accel *a = rt_calloc(1, sizeof(*a));
	char config[32];
	size_t i;

	*out = NULL;
	if (!a)
		return diag_fail(d, RT_E_NOMEM, "out of memory building the scene's hierarchy");
	a->bounded = rt_reallocarray(NULL, n_shapes + 1, sizeof(*a->bounded));
	a->unbounded = rt_reallocarray(NULL, n_shapes + 1, sizeof(*a->unbounded));
	if (!a->bounded || !a->unbounded) {
		accel_destroy(a);
		return diag_fail(d, RT_E_NOMEM, "out of memory building the scene's hierarchy");
	}
	for (i = 0; i < n_shapes; i++) {
		struct aabb box;
		if (tree_box(shapes[i], &box))
			a->bounded[a->n_bounded++] = shapes[i];
		else
			a->unbounded[a->n_unbounded++] = shapes[i];
	}
	snprintf(config, sizeof(config), "threads=%d", threads);
	a->device = rtcNewDevice(config);
	if (!a->device) {
		accel_destroy(a);
		return diag_fail(d, RT_E_NOMEM, "Embree: no device");
	}
	a->scene = rtcNewScene(a->device);
	if (a->n_bounded > 0) {
		RTCGeometry g = rtcNewGeometry(a->device, RTC_GEOMETRY_TYPE_USER);
		rtcSetGeometryUserPrimitiveCount(g, a->n_bounded);
		rtcSetGeometryUserData(g, a);
		rtcSetGeometryBoundsFunction(g, embree_bounds, NULL);
		rtcSetGeometryIntersectFunction(g, embree_intersect);
		rtcSetGeometryOccludedFunction(g, embree_occluded);
		rtcCommitGeometry(g);
		rtcAttachGeometry(a->scene, g);
		rtcReleaseGeometry(g);
	}
	rtcCommitScene(a->scene);
	if (rtcGetDeviceError(a->device) != RTC_ERROR_NONE) {
		accel_destroy(a);
		return diag_fail(d, RT_E_NOMEM, "Embree failed to build the scene");
	}
	*out = a;
	return 0;
}

void accel_destroy(struct accel *a)
{
	if (!a)
		return;
	if (a->scene)
		rtcReleaseScene(a->scene);
	if (a->device)
		rtcReleaseDevice(a->device);
	rt_free(a->bounded);
	rt_free(a->unbounded);
	rt_free(a);
}

static void query_ray(struct RTCRay *er, const struct ray *r, double t_max)
{
	er->org_x = (float)r->origin.x;
	er->org_y = (float)r->origin.y;
	er->org_z = (float)r->origin.z;
	er->dir_x = (float)r->dir.x;
	er->dir_y = (float)r->dir.y;
	er->dir_z = (float)r->dir.z;
	/* The exact interval is the callbacks' business: Embree's only culls. */
	er->tnear = 0.0f;
	er->tfar = t_max == INFINITY ? INFINITY : pad_up(t_max);
	er->time = 0.0f;
	er->mask = UINT32_MAX;
	er->id = 0;
	er->flags = 0;
}

const struct shape *accel_intersect(const struct accel *a, const struct ray *r,
				    double t_min, double *t_max)
{
	const struct shape *hit = NULL;
	struct RTCRayHit rh;
	struct query q;
	size_t i;

	for (i = 0; i < a->n_unbounded; i++)
		if (shape_intersect(a->unbounded[i], r, t_min, t_max))
			hit = a->unbounded[i];
	if (a->n_bounded == 0)
		return hit;
	rtcInitIntersectContext(&q.base);
	q.r = r;
	q.t_min = t_min;
	q.t = *t_max;
	q.hit = NULL;
	q.key = 0;
	memset(&rh, 0, sizeof(rh));
	query_ray(&rh.ray, r, *t_max);
	rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
	rtcIntersect1(a->scene, &q.base, &rh);
	if (q.hit) {
		*t_max = q.t;
		hit = q.hit;
	}
	return hit;
}

bool accel_occluded(const struct accel *a, const struct ray *r, double t_min, double t_max)
{
	struct RTCRay er;
	struct query q;
	size_t i;

	for (i = 0; i < a->n_unbounded; i++) {
		double t = t_max;
		if (shape_intersect(a->unbounded[i], r, t_min, &t))
			return true;
	}
	if (a->n_bounded == 0)
		return false;
	rtcInitIntersectContext(&q.base);
	q.r = r;
	q.t_min = t_min;
	q.t = t_max;
	q.blocked = false;
	query_ray(&er, r, t_max);
	rtcOccluded1(a->scene, &q.base, &er);
	return q.blocked;
}

/* whitted's packets (accel.h) as single Embree queries, one ray after
 * another: the reference's rays are the ones it has always traced. */
void accel_intersect_packet(const struct accel *a, const struct ray *r, int n,
			    const double *t_min, double *t_max, const struct shape **hit)
{
	int i;

	for (i = 0; i < n; i++)
		hit[i] = accel_intersect(a, r + i, t_min[i], t_max + i);
}

uint32_t accel_occluded_packet(const struct accel *a, const struct ray *r, int n,
			       const double *t_min, const double *t_max)
{
	uint32_t blocked = 0;
	int i;

	for (i = 0; i < n; i++)
		if (accel_occluded(a, r + i, t_min[i], t_max[i]))
			blocked |= (uint32_t)1 << i;
	return blocked;
}

uint32_t accel_occluded_lanes(const struct accel *a, const struct ray_packet *p, uint32_t active,
			      const double *t_min, const double *t_max)
{
	uint32_t blocked = 0, m;

	for (m = active; m; m &= m - 1) {
		int i = __builtin_ctz(m);
		struct ray r = ray_packet_get(p, i);
		if (accel_occluded(a, &r, t_min[i], t_max[i]))
			blocked |= (uint32_t)1 << i;
	}
	return blocked;
}

void accel_intersect_lanes(const struct accel *a, const struct ray_packet *p, uint32_t active,
			   const double *t_min, double *t_max, const struct shape **hit)
{
	uint32_t m;

	for (m = active; m; m &= m - 1) {
		int i = __builtin_ctz(m);
		struct ray r = ray_packet_get(p, i);
		hit[i] = accel_intersect(a, &r, t_min[i], t_max + i);
	}
}

bool accel_packets_pay(const struct accel *a)
{
	(void)a;
	return false;
}

/* One ray at a time, unless WHITTED_PACKETS=1 asks for the packets (each
 * ray of them still one Embree query). */
bool accel_packets_wanted(const struct accel *a)
{
	const char *p = getenv("WHITTED_PACKETS");

	(void)a;
	return p && strcmp(p, "1") == 0;
}

bool accel_packets_scatter_pay(const struct accel *a)
{
	(void)a;
	return false;
}

const char *accel_packets_name(const struct accel *a)
{
	return accel_packets_wanted(a) ? "packets, a ray at a time" : "no packets";
}

size_t accel_node_count(const struct accel *a)
{
	(void)a;
	return 0;
}

const char *accel_walk_name(const struct accel *a)
{
	(void)a;
	return "embree";
}

size_t accel_bytes(const struct accel *a)
{
	(void)a;
	return 0;
}
