/* gen_scene: writes a scene.txt with N small random spheres and triangles
 * (half each) floating over the floor in front of the course camera, for
 * the benchmark.  The object size shrinks as N^(-1/2), so that a ray meets
 * about as many objects at every N: the images look alike and the time
 * measures how the tracer scales, not how much more there is to see.  The
 * seed is fixed, so the same N always gives the same file.
 * Usage: gen_scene N [SEED] > scene.txt */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

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

int main(int argc, char **argv)
{
	/* The region the course camera (eye 0,-200,10, 80 degrees) sees well. */
	const double x0 = -150, x1 = 150, y0 = -80, y1 = 170, z0 = 0, z1 = 110;
	long n, i;
	double size;
	char *end;

	if (argc < 2 || argc > 3) {
		fprintf(stderr, "usage: gen_scene N [SEED] > scene.txt\n");
		return 2;
	}
	n = strtol(argv[1], &end, 10);
	if (*end != '\0' || n < 1 || n > 10000000) {
		fprintf(stderr, "gen_scene: N must be 1..10000000\n");
		return 2;
	}
	rng_state = argc == 3 ? strtoull(argv[2], NULL, 10) : 20240601;
	/* 1,000 objects of size 8 cover a good part of the view. */
	size = 8.0 * sqrt(1000.0 / (double)n);
	printf("4\n512\n\n%ld\n", n);
	for (i = 0; i < n; i++) {
		double cx = rng_range(x0, x1), cy = rng_range(y0, y1);
		double cz = rng_range(z0 + size, z1);
		if (i % 2 == 0) {
			printf("sphere\n%.4f %.4f %.4f\n%.4f\n", cx, cy, cz,
			       size * rng_range(0.3, 0.6));
		} else {
			int k;
			printf("triangle\n");
			for (k = 0; k < 3; k++)
				printf("%.4f %.4f %.4f\n", cx + size * rng_range(-0.7, 0.7),
				       cy + size * rng_range(-0.7, 0.7),
				       cz + size * rng_range(-0.7, 0.7));
		}
		write_material();
		printf("\n");
	}
	printf("3\n70 -70 150\n1 1 1\n-100 -50 80\n0.6 0.6 0.8\n0 100 200\n0.5 0.4 0.3\n");
	return ferror(stdout) ? 1 : 0;
}
