/* The floor finish's least squares: the model C = clamp(ka A + kd D +
 * ks S(n) + kr R) over the sample's rows, its error, the non-negative
 * least squares by the normal equations and the trimming of rows far off
 * (floor_finish.c has the method). */
#include <math.h>
#include <stdbool.h>
#include <string.h>

#include "grade/finish_lsq.h"

static double finish_clamp(double v)
{
	return v < 0.0 ? 0.0 : v > 1.0 ? 1.0 : v;
}

/* The model's colour of row j (pixel j / 3, channel j % 3) for k with
 * specular basis sb. */
double finish_model(const struct finish_sample *fs, int sb, const double k[FINISH_K],
			   size_t j)
{
	return finish_clamp(k[FINISH_KA] * finish_basis(fs, FINISH_A)[j] +
			    k[FINISH_KD] * finish_basis(fs, FINISH_D)[j] +
			    k[FINISH_KS] * finish_basis(fs, sb)[j] +
			    k[FINISH_KR] * finish_basis(fs, FINISH_R)[j]);
}

/* The squared error of k over every row in use (the model clamped). */
double finish_error(const struct finish_sample *fs, int sb, const double k[FINISH_K])
{
	double e = 0.0, r;
	size_t j;

	for (j = 0; j < 3 * fs->n; j++)
		if (fs->use[j]) {
			r = finish_model(fs, sb, k, j) - fs->target[j];
			e += r * r;
		}
	return e;
}

/* Solves the m x m system a x = y (row stride FINISH_K) by elimination
 * with partial pivoting; false when it is singular. */
static bool finish_solve(double a[FINISH_K][FINISH_K], double y[FINISH_K], int m, double x[FINISH_K])
{
	int i, j, c, p;

	for (c = 0; c < m; c++) {
		p = c;
		for (i = c + 1; i < m; i++)
			if (fabs(a[i][c]) > fabs(a[p][c]))
				p = i;
		if (!(fabs(a[p][c]) > 1e-12))
			return false;
		for (j = 0; j < m; j++) {
			double t = a[c][j];
			a[c][j] = a[p][j];
			a[p][j] = t;
		}
		{
			double t = y[c];
			y[c] = y[p];
			y[p] = t;
		}
		for (i = c + 1; i < m; i++) {
			double f = a[i][c] / a[c][c];
			for (j = c; j < m; j++)
				a[i][j] -= f * a[c][j];
			y[i] -= f * y[c];
		}
	}
	for (i = m - 1; i >= 0; i--) {
		double v = y[i];
		for (j = i + 1; j < m; j++)
			v -= a[i][j] * x[j];
		x[i] = v / a[i][i];
	}
	return true;
}

/* The normal equations a x = y of the columns col[idx[0..m)] over the
 * rows in use whose target is not saturated (there the model is
 * unclamped and linear). */
static void finish_normal(const struct finish_sample *fs, const float *const col[FINISH_K],
			  const int idx[FINISH_K], int m, double a[FINISH_K][FINISH_K],
			  double y[FINISH_K])
{
	size_t r;
	int i, j;

	memset(a, 0, sizeof(double) * FINISH_K * FINISH_K);
	memset(y, 0, sizeof(double) * FINISH_K);
	for (r = 0; r < 3 * fs->n; r++) {
		if (!fs->use[r] || fs->target[r] >= 1.0f)
			continue;
		for (i = 0; i < m; i++) {
			y[i] += (double)col[idx[i]][r] * fs->target[r];
			for (j = 0; j < m; j++)
				a[i][j] += (double)col[idx[i]][r] * col[idx[j]][r];
		}
	}
}

/* The least-squares coefficients (>= 0) over the rows in use whose
 * target is not saturated (there the model is unclamped and linear):
 * the normal equations over the coefficients not held at 0; a column
 * with no signal on the sample (no highlight there, a black reflection)
 * is held, and so is the most negative coefficient of a solution, and
 * the rest solved again (at most FINISH_K rounds: one more held each). */
void finish_least_squares(const struct finish_sample *fs, int sb, double k[FINISH_K])
{
	const float *col[FINISH_K];
	bool held[FINISH_K] = { false, false, false, false };
	int round, i, j, m, idx[FINISH_K];

	col[FINISH_KA] = finish_basis(fs, FINISH_A);
	col[FINISH_KD] = finish_basis(fs, FINISH_D);
	col[FINISH_KS] = finish_basis(fs, sb);
	col[FINISH_KR] = finish_basis(fs, FINISH_R);
	for (i = 0; i < FINISH_K; i++)
		k[i] = 0.0;
	for (round = 0; round <= FINISH_K; round++) {
		double a[FINISH_K][FINISH_K], y[FINISH_K], x[FINISH_K], diag[FINISH_K], top = 0.0;
		int worst = -1;

		for (m = 0, i = 0; i < FINISH_K; i++)
			if (!held[i])
				idx[m++] = i;
		if (m == 0)
			return;
		finish_normal(fs, col, idx, m, a, y);
		for (i = 0; i < m; i++) {
			diag[i] = a[i][i];
			top = diag[i] > top ? diag[i] : top;
		}
		for (i = 0; i < m; i++)
			if (!(diag[i] > 1e-9 * top))
				worst = idx[i];
		if (worst < 0 && finish_solve(a, y, m, x)) {
			for (i = 0; i < FINISH_K; i++)
				k[i] = 0.0;
			for (i = 0; i < m; i++) {
				k[idx[i]] = x[i];
				if (x[i] < 0.0 && (worst < 0 || x[i] < k[worst]))
					worst = idx[i];
			}
			if (worst < 0)
				return;
		} else if (worst < 0) {
			/* Singular with every column alive: the weakest goes. */
			for (j = 0, i = 1; i < m; i++)
				j = diag[i] < diag[j] ? i : j;
			worst = idx[j];
		}
		held[worst] = true;
	}
	for (i = 0; i < FINISH_K; i++)
		k[i] = k[i] > 0.0 ? k[i] : 0.0;
}

/* Leaves out of the fit the rows whose error under k is far beyond the
 * rest (a pixel on a cell's edge another colour, an object's edge): more
 * than 4 times the median error, and 8 levels. */
void finish_trim(struct finish_sample *fs, int sb, const double k[FINISH_K], float *tmp)
{
	size_t j, m = 0, lo, hi;
	double median, cut;

	for (j = 0; j < 3 * fs->n; j++)
		if (fs->use[j])
			tmp[m++] = (float)fabs(finish_model(fs, sb, k, j) - fs->target[j]);
	if (m == 0)
		return;
	/* The median by a partial quickselect over tmp[0..m). */
	lo = 0;
	hi = m - 1;
	while (lo < hi) {
		float pivot = tmp[(lo + hi) / 2], t;
		size_t a = lo, b = hi;

		while (a <= b) {
			while (tmp[a] < pivot)
				a++;
			while (tmp[b] > pivot)
				b--;
			if (a <= b) {
				t = tmp[a];
				tmp[a] = tmp[b];
				tmp[b] = t;
				a++;
				if (b == 0)
					break;
				b--;
			}
		}
		if (m / 2 <= b)
			hi = b;
		else if (m / 2 >= a)
			lo = a;
		else
			break;
	}
	median = tmp[m / 2];
	cut = fmax(4.0 * median, 8.0 / 255.0);
	for (j = 0; j < 3 * fs->n; j++)
		if (fs->use[j] && fabs(finish_model(fs, sb, k, j) - fs->target[j]) > cut)
			fs->use[j] = 0;
}
