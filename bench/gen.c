/* gen_scene: writes a scene.txt of N small random spheres and triangles
 * (half each) over the floor in front of the course camera, for the
 * benchmark.  Two layouts:
 *
 *   surface (the default): the objects cover the surfaces of six large
 *     balls (which are not in the scene themselves), like a model
 *     tessellated ever finer: their size shrinks as N^(-1/2), so that they
 *     cover the same share of the balls at every N and the pictures look
 *     alike.  Most scenes with many primitives are like this: the detail
 *     lies on surfaces.
 *   cloud: the objects float anywhere in a box, shrinking as N^(-1/2) too,
 *     so that a ray passing through meets about as many of them at every
 *     N.  The hardest case for any hierarchy: a ray crossing the cloud
 *     passes near N^(1/3) objects that it misses, and each must be ruled
 *     out.
 *
 * The seed is fixed, so the same N always gives the same file.
 * Usage: gen_scene [--layout surface|cloud] N [SEED] > scene.txt */
#include <math.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* splitmix64: small, fast and the same on every platform. */
static uint64_t rng_state;

static uint64_t rng_next(void)
{
	uint64_t z = (rng_state += 0x9e3779b97f4a7c15ULL);

	z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
	z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
	return z ^ (z >> 31);
}

/* Uniform in [lo, hi), from the top 53 bits. */
static double rng_range(double lo, double hi)
{
	return lo + (hi - lo) * (double)(rng_next() >> 11) * (1.0 / 9007199254740992.0);
}

static void write_material(void)
{
	printf("%.3f %.3f %.3f\n", rng_range(0, 1), rng_range(0, 1), rng_range(0, 1));
	printf("%.2f %.2f %.2f %.2f\n", rng_range(0.1, 0.4), rng_range(0.2, 0.5),
	       rng_range(0.1, 0.4), rng_range(0.0, 0.3));
	printf("%d\n", (int)rng_range(1, 30));
}

/* A point of the unit sphere, uniform by area. */
static void random_unit(double v[3])
{
	for (;;) {
		double x = rng_range(-1, 1), y = rng_range(-1, 1), z = rng_range(-1, 1);
		double r2 = x * x + y * y + z * z;
		if (r2 > 1e-6 && r2 <= 1.0) {
			double r = sqrt(r2);
			v[0] = x / r;
			v[1] = y / r;
			v[2] = z / r;
			return;
		}
	}
}

static void write_sphere(const double c[3], double size)
{
	printf("sphere\n%.4f %.4f %.4f\n%.4f\n", c[0], c[1], c[2], size * rng_range(0.3, 0.6));
}

/* A triangle about `size` across around c, its corners offset along a and
 * b (and a little along n). */
static void write_triangle(const double c[3], double size, const double a[3], const double b[3],
			   const double n[3], double depth)
{
	int k, j;

	printf("triangle\n");
	for (k = 0; k < 3; k++) {
		/* In this order, which is the order gcc evaluated the arguments
		 * of the first version's printf in: the same files as then. */
		double h = size * rng_range(-depth, depth);
		double w = size * rng_range(-0.7, 0.7);
		double u = size * rng_range(-0.7, 0.7), p[3];
		for (j = 0; j < 3; j++)
			p[j] = c[j] + u * a[j] + w * b[j] + h * n[j];
		printf("%.4f %.4f %.4f\n", p[0], p[1], p[2]);
	}
}

/* The balls that the surface layout covers, in view of the course camera
 * (eye 0,-200,10, 80 degrees): x, y, z, radius. */
static const double balls[6][4] = {
	{ -80, 60, 45, 45 }, { 20, 40, 35, 35 }, { 95, 95, 50, 50 },
	{ -30, -25, 20, 20 }, { 60, -35, 18, 18 }, { 0, 140, 60, 60 },
};

static void write_surface(long n)
{
	double area = 0.0, size;
	long i;
	int k;

	for (k = 0; k < 6; k++)
		area += balls[k][3] * balls[k][3];
	/* Objects about 1.2 times their spacing across: the balls look
	 * closed, with gaps. */
	size = 1.2 * sqrt(4.0 * 3.14159265358979 * area / (double)n);
	for (i = 0; i < n; i++) {
		double pick = rng_range(0, area), v[3], c[3];
		const double *ball = balls[5];
		for (k = 0; k < 6; k++) {
			if (pick < balls[k][3] * balls[k][3]) {
				ball = balls[k];
				break;
			}
			pick -= balls[k][3] * balls[k][3];
		}
		/* Points too near the floor are drawn again: every ball's upper
		 * half is above this. */
		do {
			random_unit(v);
			for (k = 0; k < 3; k++)
				c[k] = ball[k] + ball[3] * v[k];
		} while (c[2] < (size < 0.5 * ball[3] ? size : 0.5 * ball[3]));
		if (i % 2 == 0) {
			write_sphere(c, size);
		} else {
			/* Tangent to the ball: a and b span its tangent plane. */
			double a[3], b[3], len;
			if (fabs(v[2]) < 0.9) {
				a[0] = v[1], a[1] = -v[0], a[2] = 0;
			} else {
				a[0] = 0, a[1] = v[2], a[2] = -v[1];
			}
			len = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
			for (k = 0; k < 3; k++)
				a[k] /= len;
			b[0] = v[1] * a[2] - v[2] * a[1];
			b[1] = v[2] * a[0] - v[0] * a[2];
			b[2] = v[0] * a[1] - v[1] * a[0];
			write_triangle(c, size, a, b, v, 0.1);
		}
		write_material();
		printf("\n");
	}
}

static void write_cloud(long n)
{
	/* The region the course camera sees well. */
	const double x0 = -150, x1 = 150, y0 = -80, y1 = 170, z0 = 0, z1 = 110;
	static const double ex[3] = { 1, 0, 0 }, ey[3] = { 0, 1, 0 }, ez[3] = { 0, 0, 1 };
	/* 1,000 objects of size 8 cover a good part of the view. */
	double size = 8.0 * sqrt(1000.0 / (double)n);
	long i;

	for (i = 0; i < n; i++) {
		double c[3];
		c[0] = rng_range(x0, x1);
		c[1] = rng_range(y0, y1);
		c[2] = rng_range(z0 + size, z1);
		if (i % 2 == 0)
			write_sphere(c, size);
		else
			write_triangle(c, size, ex, ey, ez, 0.7);
		write_material();
		printf("\n");
	}
}

static int usage(void)
{
	fprintf(stderr, "usage: gen_scene [--layout surface|cloud] N [SEED] > scene.txt\n");
	return 2;
}

int main(int argc, char **argv)
{
	bool cloud = false;
	long n;
	char *end;
	int a = 1;

	if (argc > 2 && strcmp(argv[1], "--layout") == 0) {
		if (strcmp(argv[2], "cloud") == 0)
			cloud = true;
		else if (strcmp(argv[2], "surface") != 0)
			return usage();
		a = 3;
	}
	if (argc - a < 1 || argc - a > 2)
		return usage();
	n = strtol(argv[a], &end, 10);
	if (*end != '\0' || n < 1 || n > 10000000) {
		fprintf(stderr, "gen_scene: N must be 1..10000000\n");
		return 2;
	}
	rng_state = argc - a == 2 ? strtoull(argv[a + 1], NULL, 10) : 20240601;
	printf("4\n512\n\n%ld\n", n);
	if (cloud)
		write_cloud(n);
	else
		write_surface(n);
	printf("3\n70 -70 150\n1 1 1\n-100 -50 80\n0.6 0.6 0.8\n0 100 200\n0.5 0.4 0.3\n");
	return ferror(stdout) ? 1 : 0;
}
