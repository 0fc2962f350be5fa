/* fixtures_common.h -- helpers the element suites share (after
   test_util.h and the header under test, which brings vlbe_real).
   -- part of vlbe                                  SPDX-License-Identifier: MIT */
#ifndef VLBE_TEST_FIXTURES_COMMON_H
#define VLBE_TEST_FIXTURES_COMMON_H

/* u^T M u in double (M n x n, row-major); *absum = sum of |terms| (the
   rounding scale) when absum != NULL */
static inline double quad_form(int n, const vlbe_real *M, const double *u, double *absum)
{
    double s = 0.0, a = 0.0;
    int i, j;
    for (i = 0; i < n; ++i)
        for (j = 0; j < n; ++j) {
            const double t = u[i] * (double)M[i * n + j] * u[j];
            s += t;
            a += fabs(t);
        }
    if (absum) *absum = a;
    return s;
}

/* a[i] = v, i < n */
static inline void fill(int n, vlbe_real v, vlbe_real *a)
{
    int i;
    for (i = 0; i < n; ++i) a[i] = v;
}

/* every a[i] == v exactly (e.g. an output left untouched) */
static inline void assert_all_equal(int n, const vlbe_real *a, vlbe_real v)
{
    int i;
    for (i = 0; i < n; ++i) ASSERT_CLOSE_CTX(a[i], v, 0, 0, "entry %d", i);
}

/* Cholesky in double of the n x n (n <= 16) matrix M of leading dimension ld
   restricted to the index list idx (NULL: 0..n-1); 1 when every pivot is
   > 0 (positive definite to the precision of the factorisation) */
static inline int cholesky_ok(const vlbe_real *M, int ld, const int *idx, int n)
{
    double A[256];
    int i, j, k;
    if (n > 16) return 0;
    for (i = 0; i < n; ++i)
        for (j = 0; j < n; ++j)
            A[i * n + j] = (double)M[(idx ? idx[i] : i) * ld + (idx ? idx[j] : j)];
    for (k = 0; k < n; ++k) {
        double d = A[k * n + k];
        for (j = 0; j < k; ++j) d -= A[k * n + j] * A[k * n + j];
        if (!(d > 0.0)) return 0;
        A[k * n + k] = sqrt(d);
        for (i = k + 1; i < n; ++i) {
            double sm = A[i * n + k];
            for (j = 0; j < k; ++j) sm -= A[i * n + j] * A[k * n + j];
            A[i * n + k] = sm / A[k * n + k];
        }
    }
    return 1;
}

/* Residual of column r of X (n x nrhs) against B for the n x n row-major
   A: returns ||A x - b||_inf and sets *scale = ||A||_inf ||x||_inf, summed
   in long double so that its own rounding stays well below the backward-
   error bounds the LU suites assert (a multiple of n eps *scale). */
static inline double lu_residual(int n, int nrhs, int r, const vlbe_real *A, const vlbe_real *X,
                                 const vlbe_real *B, double *scale)
{
    long double res = 0.0L, anorm = 0.0L, xnorm = 0.0L;
    int i, j;
    for (i = 0; i < n; ++i) {
        long double s = -(long double)B[i * nrhs + r], row = 0.0L;
        for (j = 0; j < n; ++j) {
            s += (long double)A[i * n + j] * (long double)X[j * nrhs + r];
            row += fabsl((long double)A[i * n + j]);
        }
        if (fabsl(s) > res) res = fabsl(s);
        if (row > anorm) anorm = row;
        if (fabsl((long double)X[i * nrhs + r]) > xnorm)
            xnorm = fabsl((long double)X[i * nrhs + r]);
    }
    *scale = (double)(anorm * xnorm);
    return (double)res;
}

#endif /* VLBE_TEST_FIXTURES_COMMON_H */
