/* CMA-ES with the tutorial's default parameters (Hansen 2016, Table 1):
 * weighted recombination of the better half, cumulative step-size
 * adaptation, rank-one and rank-mu updates of the covariance, whose
 * eigenvectors come from a few Jacobi sweeps (the dimension is tiny). */
#include <math.h>
#include <string.h>

#include "grade/cmaes.h"

enum { N_MAX = CMAES_MAX_DIM, L_MAX = CMAES_MAX_LAMBDA };

/* xorshift64*, and a normal deviate by Box-Muller: the same numbers on
 * every machine for a seed. */
static double cmaes_uniform(uint64_t *s)
{
	*s ^= *s >> 12;
	*s ^= *s << 25;
	*s ^= *s >> 27;
	return ((double)((*s * 2685821657736338717ULL) >> 11) + 0.5) / 9007199254740992.0;
}

static double cmaes_normal(uint64_t *s)
{
	double u = cmaes_uniform(s), v = cmaes_uniform(s);

	return sqrt(-2.0 * log(u)) * cos(6.283185307179586 * v);
}

/* The eigenvectors (columns of b) and the square roots of the
 * eigenvalues of the symmetric c, by cyclic Jacobi rotations. */
static void cmaes_eigen(int n, double c[N_MAX][N_MAX], double b[N_MAX][N_MAX], double *dsqrt)
{
	double a[N_MAX][N_MAX];
	int i, j, k, p, q, sweep;

	for (i = 0; i < n; i++)
		for (j = 0; j < n; j++) {
			a[i][j] = 0.5 * (c[i][j] + c[j][i]);
			b[i][j] = i == j;
		}
	for (sweep = 0; sweep < 50; sweep++) {
		double off = 0.0;
		for (p = 0; p < n; p++)
			for (q = p + 1; q < n; q++)
				off += a[p][q] * a[p][q];
		if (off < 1e-30)
			break;
		for (p = 0; p < n; p++)
			for (q = p + 1; q < n; q++) {
				double th, t, cs, sn;
				if (fabs(a[p][q]) < 1e-300)
					continue;
				th = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
				t = (th >= 0.0 ? 1.0 : -1.0) / (fabs(th) + sqrt(th * th + 1.0));
				cs = 1.0 / sqrt(t * t + 1.0);
				sn = t * cs;
				for (k = 0; k < n; k++) {
					double kp = a[k][p], kq = a[k][q];
					a[k][p] = cs * kp - sn * kq;
					a[k][q] = sn * kp + cs * kq;
				}
				for (k = 0; k < n; k++) {
					double pk = a[p][k], qk = a[q][k];
					a[p][k] = cs * pk - sn * qk;
					a[q][k] = sn * pk + cs * qk;
				}
				for (k = 0; k < n; k++) {
					double kp = b[k][p], kq = b[k][q];
					b[k][p] = cs * kp - sn * kq;
					b[k][q] = sn * kp + cs * kq;
				}
			}
	}
	for (i = 0; i < n; i++)
		dsqrt[i] = sqrt(a[i][i] > 1e-30 ? a[i][i] : 1e-30);
}

double cmaes_minimise(const struct cmaes_options *o, double *x, const double *scale,
		      cmaes_batch_fn *f, void *ctx, long *evals)
{
	const int n = o->dim, lambda = o->lambda, mu = lambda / 2;
	double w[L_MAX], wsum = 0.0, w2 = 0.0, mueff, cc, cs, c1, cmu, damps, chin;
	double m[N_MAX], c[N_MAX][N_MAX], b[N_MAX][N_MAX], dsq[N_MAX];
	double pc[N_MAX] = { 0 }, ps[N_MAX] = { 0 }, sigma = o->sigma, best = INFINITY;
	double z[L_MAX][N_MAX], y[L_MAX][N_MAX], xs[L_MAX * N_MAX], fs[L_MAX];
	int order[L_MAX], i, j, k, g;
	uint64_t seed = o->seed ? o->seed : 0x9e3779b97f4a7c15ULL;

	for (i = 0; i < mu; i++) {
		w[i] = log(mu + 0.5) - log(i + 1.0);
		wsum += w[i];
	}
	for (i = 0; i < mu; i++) {
		w[i] /= wsum;
		w2 += w[i] * w[i];
	}
	mueff = 1.0 / w2;
	cc = (4.0 + mueff / n) / (n + 4.0 + 2.0 * mueff / n);
	cs = (mueff + 2.0) / (n + mueff + 5.0);
	c1 = 2.0 / ((n + 1.3) * (n + 1.3) + mueff);
	cmu = 2.0 * (mueff - 2.0 + 1.0 / mueff) / ((n + 2.0) * (n + 2.0) + mueff);
	cmu = cmu < 1.0 - c1 ? cmu : 1.0 - c1;
	damps = 1.0 + 2.0 * fmax(0.0, sqrt((mueff - 1.0) / (n + 1.0)) - 1.0) + cs;
	chin = sqrt((double)n) * (1.0 - 1.0 / (4.0 * n) + 1.0 / (21.0 * n * n));
	for (i = 0; i < n; i++) {
		m[i] = x[i] / scale[i];
		dsq[i] = 1.0;
		for (j = 0; j < n; j++)
			c[i][j] = b[i][j] = i == j;
	}
	if (o->cov) {
		for (i = 0; i < n; i++)
			for (j = 0; j < n; j++)
				c[i][j] = o->cov[i][j];
		cmaes_eigen(n, c, b, dsq);
	}
	if (evals)
		*evals = 0;
	for (g = 0; g < o->generations; g++) {
		double yw[N_MAX] = { 0 }, t1[N_MAX], t2[N_MAX], psn = 0.0, dmax = 0.0;
		int hsig;

		for (k = 0; k < lambda; k++) {
			for (i = 0; i < n; i++)
				z[k][i] = cmaes_normal(&seed);
			for (i = 0; i < n; i++) {
				y[k][i] = 0.0;
				for (j = 0; j < n; j++)
					y[k][i] += b[i][j] * dsq[j] * z[k][j];
				xs[k * n + i] = (m[i] + sigma * y[k][i]) * scale[i];
			}
		}
		f(ctx, xs, fs, lambda);
		if (evals)
			*evals += lambda;
		/* Best first (a NaN as the worst); equal values in the order
		 * drawn, so that the answer does not depend on a sort's whims. */
		for (k = 0; k < lambda; k++) {
			if (fs[k] != fs[k])
				fs[k] = INFINITY;
			for (j = k; j > 0 && fs[order[j - 1]] > fs[k]; j--)
				order[j] = order[j - 1];
			order[j] = k;
		}
		if (fs[order[0]] < best) {
			best = fs[order[0]];
			memcpy(x, xs + order[0] * n, sizeof(double) * (size_t)n);
		}
		for (k = 0; k < mu; k++)
			for (i = 0; i < n; i++)
				yw[i] += w[k] * y[order[k]][i];
		for (i = 0; i < n; i++)
			m[i] += sigma * yw[i];
		/* C^(-1/2) yw = B D^-1 B' yw */
		for (i = 0; i < n; i++) {
			t1[i] = 0.0;
			for (j = 0; j < n; j++)
				t1[i] += b[j][i] * yw[j];
			t1[i] /= dsq[i];
		}
		for (i = 0; i < n; i++) {
			t2[i] = 0.0;
			for (j = 0; j < n; j++)
				t2[i] += b[i][j] * t1[j];
			ps[i] = (1.0 - cs) * ps[i] + sqrt(cs * (2.0 - cs) * mueff) * t2[i];
			psn += ps[i] * ps[i];
		}
		psn = sqrt(psn);
		hsig = psn / sqrt(1.0 - pow(1.0 - cs, 2.0 * (g + 1))) / chin < 1.4 + 2.0 / (n + 1.0);
		for (i = 0; i < n; i++)
			pc[i] = (1.0 - cc) * pc[i] + hsig * sqrt(cc * (2.0 - cc) * mueff) * yw[i];
		for (i = 0; i < n; i++)
			for (j = 0; j < n; j++) {
				double r = 0.0;
				for (k = 0; k < mu; k++)
					r += w[k] * y[order[k]][i] * y[order[k]][j];
				c[i][j] = (1.0 - c1 - cmu) * c[i][j] +
					  c1 * (pc[i] * pc[j] + (1 - hsig) * cc * (2.0 - cc) * c[i][j]) +
					  cmu * r;
			}
		sigma *= exp((cs / damps) * (psn / chin - 1.0));
		cmaes_eigen(n, c, b, dsq);
		for (i = 0; i < n; i++)
			dmax = dsq[i] > dmax ? dsq[i] : dmax;
		if (sigma * dmax < o->sigma_stop)
			break;
	}
	if (o->cov) {
		/* Normalised to a largest axis of 1, the scale going to sigma. */
		double dmax = 0.0;
		for (i = 0; i < n; i++)
			dmax = dsq[i] > dmax ? dsq[i] : dmax;
		for (i = 0; i < n; i++)
			for (j = 0; j < n; j++)
				o->cov[i][j] = c[i][j] / (dmax * dmax);
		sigma *= dmax;
	}
	if (o->sigma_out)
		*o->sigma_out = sigma;
	return best;
}
