/* test_eig.c -- cmocka suite of the eigen-solvers of vlbe.h (vlbe_eig_sym,
   vlbe_eig_gsym, vlbe_eig_real, vlbe_eig_quad)
   -- part of vlbe                                 SPDX-License-Identifier: MIT

   Build and run from the repository root (add -DVLBE_USE_FLOAT for the
   float build; the same source passes in both precisions):
       cc -std=c99 -Wall -Wextra -Wpedantic -O2 tests/test_eig.c -o test_eig -lcmocka -lm
       ./test_eig

   Every check compares with an independent fact: a spectrum fixed before
   the matrix is built (Q diag(lam) Q^T, similarity, companion matrices of
   polynomials with known roots), closed forms (spring-mass chains, a
   gyroscopic rotor, a damped oscillator), a reference computed in long
   double by another method (power iteration on a flexibility matrix
   formed from sums of positive terms), or residuals of the defining
   equations evaluated in long double.  Tolerances are multiples of
   VLBE_EPS, each with its reason; VLBE_TEST_REPORT=1 prints the worst
   error of each check next to its tolerance.

   Groups: symmetric (Jacobi) | symmetric-definite (shift-invert) | general
   real (QR) | quadratic | failure paths. */
#include "test_util.h"
#include "../vlbe.h"

#include <float.h>
#include <string.h>

#define EPS ((double)VLBE_EPS)
#define PI 3.14159265358979323846
#define NMAX 40

/* ======================================================================= */
/* helpers                                                                  */
/* ======================================================================= */

/* Q (n x n, long double) = H1 H2 H3, Householder reflections I - 2 u u^T /
   u^T u of random vectors u: orthogonal to the rounding of long double. */
static void random_q(int n, tu_rng *g, long double *Q)
{
    long double u[NMAX], t[NMAX];
    int r, i, j;
    for (i = 0; i < n; ++i)
        for (j = 0; j < n; ++j) Q[i * n + j] = i == j ? 1.0L : 0.0L;
    for (r = 0; r < 3; ++r) {
        long double uu = 0.0L;
        for (i = 0; i < n; ++i) {
            u[i] = (long double)tu_rng_uniform(g);
            uu += u[i] * u[i];
        }
        for (i = 0; i < n; ++i) { /* Q <- Q (I - 2 u u^T / uu): t = Q u */
            t[i] = 0.0L;
            for (j = 0; j < n; ++j) t[i] += Q[i * n + j] * u[j];
        }
        for (i = 0; i < n; ++i)
            for (j = 0; j < n; ++j) Q[i * n + j] -= 2.0L * t[i] * u[j] / uu;
    }
}

/* A = Q diag(d) Q^T rounded to vlbe_real */
static void build_sym(int n, const long double *Q, const double *d, vlbe_real *A)
{
    int i, j, k;
    for (i = 0; i < n; ++i)
        for (j = 0; j < n; ++j) {
            long double s = 0.0L;
            for (k = 0; k < n; ++k) s += Q[i * n + k] * (long double)d[k] * Q[j * n + k];
            A[i * n + j] = (vlbe_real)s;
        }
}

/* max |(A x_k - lam_k B x_k)_i| over i, k (B = NULL: identity), long double */
static double eig_residual(int n, const vlbe_real *A, const vlbe_real *B, const vlbe_real *lam,
                           const vlbe_real *X)
{
    long double res = 0.0L;
    int i, j, k;
    for (k = 0; k < n; ++k)
        for (i = 0; i < n; ++i) {
            long double r = 0.0L;
            for (j = 0; j < n; ++j)
                r += ((long double)A[i * n + j] -
                      (long double)lam[k] * (B ? (long double)B[i * n + j] : (i == j ? 1.0L : 0.0L))) *
                     (long double)X[j * n + k];
            if (fabsl(r) > res) res = fabsl(r);
        }
    return (double)res;
}

/* max |X^T B X - I| (B = NULL: identity), long double */
static double orth_err(int n, const vlbe_real *B, const vlbe_real *X)
{
    long double e = 0.0L;
    int i, j, a, b;
    for (i = 0; i < n; ++i)
        for (j = 0; j < n; ++j) {
            long double s = i == j ? -1.0L : 0.0L;
            for (a = 0; a < n; ++a)
                for (b = 0; b < n; ++b)
                    s += (long double)X[a * n + i] *
                         (B ? (long double)B[a * n + b] : (a == b ? 1.0L : 0.0L)) *
                         (long double)X[b * n + j];
            if (fabsl(s) > e) e = fabsl(s);
        }
    return (double)e;
}

/* Fixed-fixed spring chain: n masses m_i, n + 1 springs k_0 .. k_n (k_0
   from the wall to mass 0, k_n from mass n-1 to the wall): K tridiagonal,
   M diagonal.  wall = 0: no wall springs (free-free, k_0 and k_n unused). */
static void chain(int n, const double *k, const double *m, int wall, vlbe_real *K, vlbe_real *M)
{
    int i;
    memset(K, 0, (size_t)n * (size_t)n * sizeof *K);
    memset(M, 0, (size_t)n * (size_t)n * sizeof *M);
    for (i = 0; i < n; ++i) {
        double d = 0.0;
        if (i > 0 || wall) d += k[i];
        if (i < n - 1 || wall) d += k[i + 1];
        K[i * n + i] = (vlbe_real)d;
        if (i > 0) K[i * n + i - 1] = K[(i - 1) * n + i] = (vlbe_real)-k[i];
        M[i * n + i] = (vlbe_real)m[i];
    }
}

/* The lowest eigenvalue of the fixed-fixed chain (K x = lam M x) in long
   double, independently of the code under test: the flexibility matrix
   F = K^-1 has the closed form F_ij = A_min(i,j) B_max(i,j) / C, A_i =
   sum_{l <= i} 1/k_l, B_i = sum_{l > i} 1/k_l, C = A_i + B_i (a unit force
   on mass j: the springs left and right of it act in parallel), sums of
   positive terms, each entry to a few long-double eps relative.  1/lam_1
   is the Perron root of the positive symmetric S = M^1/2 F M^1/2, whose
   relative perturbation by entrywise relative errors d is at most d; it
   comes from power iteration with the Rayleigh quotient, iterated until
   it stops changing. */
static long double chain_lam1(int n, const double *k, const double *m)
{
    long double A[NMAX], B[NMAX], S[NMAX * NMAX], x[NMAX], y[NMAX], C, rq = 0.0L, prev = -1.0L;
    int i, j, it;
    for (i = 0; i < n; ++i) {
        A[i] = 0.0L;
        for (j = 0; j <= i; ++j) A[i] += 1.0L / (long double)k[j];
        B[i] = 0.0L;
        for (j = i + 1; j <= n; ++j) B[i] += 1.0L / (long double)k[j];
    }
    C = A[0] + B[0];
    for (i = 0; i < n; ++i)
        for (j = 0; j < n; ++j)
            S[i * n + j] = sqrtl((long double)m[i] * (long double)m[j]) *
                           (i <= j ? A[i] * B[j] : A[j] * B[i]) / C;
    for (i = 0; i < n; ++i) x[i] = 1.0L;
    for (it = 0; it < 200000; ++it) {
        long double nx = 0.0L, xy = 0.0L;
        for (i = 0; i < n; ++i) {
            y[i] = 0.0L;
            for (j = 0; j < n; ++j) y[i] += S[i * n + j] * x[j];
        }
        for (i = 0; i < n; ++i) {
            xy += x[i] * y[i];
            nx += x[i] * x[i];
        }
        rq = xy / nx;
        nx = 0.0L;
        for (i = 0; i < n; ++i) nx += y[i] * y[i];
        nx = sqrtl(nx);
        for (i = 0; i < n; ++i) x[i] = y[i] / nx;
        if (rq == prev) break;
        prev = rq;
    }
    return 1.0L / rq;
}

/* ======================================================================= */
/* symmetric: vlbe_eig_sym                                                  */
/* ======================================================================= */

static void test_work_len(void **state)
{
    (void)state;
    assert_true(vlbe_eig_work_len(5) == 80);
    assert_true(vlbe_eig_real_work_len(5) == 20);
    assert_true(vlbe_eig_quad_work_len(5) == 9 * 25 + 100);
    assert_true(vlbe_eig_quad_iwork_len(5) == 20);
    assert_true(vlbe_eig_work_len(0) == 0 && vlbe_eig_real_work_len(-1) == 0);
    assert_true(vlbe_eig_quad_work_len(0) == 0 && vlbe_eig_quad_iwork_len(0) == 0);
    /* 2n must fit int for the quadratic problem */
    assert_true(vlbe_eig_quad_work_len(INT_MAX / 2 + 1) == 0);
    if (sizeof(size_t) <= 4) assert_true(vlbe_eig_work_len(65536) == 0); /* 3 * 2^32 */
}

/* A = Q diag(lam) Q^T, lam chosen (uniform in [-1, 1], then scaled by 10
   and with a pair of close ones), n = 1 .. 30.  The rounding of A to
   vlbe_real moves each eigenvalue by at most ||dA||_2 <= n EPS/2 max|a|
   (Weyl); Jacobi is backward stable with an error of a few EPS ||A|| per
   sweep, summed over ~10 sweeps as random-signed terms: 4 n EPS ||A||
   (||A|| = max |lam|) bounds eigenvalue errors, the residual ||A x - lam
   x|| and ||X^T X - I|| (relative to 1) with a margin. */
static void test_sym_random(void **state)
{
    static const int sizes[] = {1, 2, 3, 5, 12, 30};
    static long double Q[NMAX * NMAX];
    static vlbe_real A[NMAX * NMAX], X[NMAX * NMAX], w[3 * NMAX * NMAX + NMAX];
    vlbe_real lam[NMAX], lam2[NMAX];
    double d[NMAX], e_lam = 0.0, e_res = 0.0, e_orth = 0.0;
    tu_rng g = tu_rng_seed(77);
    int s, i, j;
    (void)state;
    for (s = 0; s < (int)(sizeof sizes / sizeof sizes[0]); ++s) {
        const int n = sizes[s];
        double amax = 0.0, tol;
        random_q(n, &g, Q);
        for (i = 0; i < n; ++i) d[i] = 10.0 * tu_rng_uniform(&g);
        if (n > 2) d[1] = d[0] + 1e-9; /* a near-double eigenvalue */
        for (i = 0; i < n; ++i) amax = fmax(amax, fabs(d[i]));
        build_sym(n, Q, d, A);
        assert_int_equal(vlbe_eig_sym(n, A, lam, X, w, vlbe_eig_work_len(n)), VLBE_OK);
        for (i = 1; i < n; ++i) /* d sorted ascending */
            for (j = i; j > 0 && d[j] < d[j - 1]; --j) {
                const double t = d[j];
                d[j] = d[j - 1];
                d[j - 1] = t;
            }
        tol = 4.0 * n * EPS * amax;
        for (i = 0; i < n; ++i) {
            ASSERT_CLOSE_CTX((double)lam[i], d[i], 0.0, tol, "n = %d, lam %d", n, i);
            e_lam = fmax(e_lam, fabs((double)lam[i] - d[i]) / (n * EPS * amax));
        }
        e_res = fmax(e_res, eig_residual(n, A, NULL, lam, X) / (n * EPS * amax));
        e_orth = fmax(e_orth, orth_err(n, NULL, X) / (n * EPS));
        assert_true(eig_residual(n, A, NULL, lam, X) <= tol);
        assert_true(orth_err(n, NULL, X) <= 4.0 * n * EPS);
        /* without vectors: the same rotations, the same eigenvalues */
        assert_int_equal(vlbe_eig_sym(n, A, lam2, NULL, w, vlbe_eig_work_len(n)), VLBE_OK);
        for (i = 0; i < n; ++i) assert_true(lam2[i] == lam[i]);
    }
    tu_report("eig_sym: |lam - lam_exact| / (n EPS ||A||)", e_lam, 4.0);
    tu_report("eig_sym: |A x - lam x| / (n EPS ||A||)", e_res, 4.0);
    tu_report("eig_sym: |X^T X - I| / (n EPS)", e_orth, 4.0);
}

/* n = 12: A = tridiag(-1, 2, -1), B = tridiag(1, 4, 1) / 6 (the stiffness
   and consistent mass of linear elements on a fixed-fixed string, unit
   element length).  Both have the eigenvectors sin(j k pi / (n + 1)), so
       A:        2 - 2 cos t_k = 4 sin^2(t_k / 2),
       (A, B):   6 (1 - cos t_k) / (2 + cos t_k),   t_k = k pi / (n + 1).
   Tolerances: Jacobi is backward stable, each eigenvalue is within a few
   n EPS ||C|| of the exact one (C the reduced matrix): absolute 4 n EPS
   ||A|| (sym, ||A|| < 4); for the pencil (shift-invert, sigma = 0) the
   reduced C = L^-1 B L^-T has ||C|| = 1/lam_1, so mu_k = 1/lam_k carries
   4 n EPS / lam_1 and lam_k a relative 4 n EPS lam_k / lam_1 (12 EPS
   lam_k (lam_k / lam_1) is the bound asserted per mode, with B's
   condition 3 on top: 4 n EPS 3 lam_k^2 / lam_1).  Largest errors in
   double: 8.9e-16 (m~:eig_sym); 7.3e-14 (m~:eig_gsym), the top mode's
   (lam_12 / lam_1 = 160: shift-invert puts the rounding there). */
static void test_eig_known(void **state)
{
    enum { N = 12 };
    vlbe_real A[N * N], B[N * N], lam[N], X[N * N], w[3 * N * N + N];
    int i, k, info = -1;
    double err = 0.0, res, orth, lam1;
    (void)state;
    memset(A, 0, sizeof A);
    memset(B, 0, sizeof B);
    for (i = 0; i < N; ++i) {
        A[i * N + i] = VLBE_R(2.0);
        B[i * N + i] = VLBE_R(4.0) / VLBE_R(6.0);
        if (i > 0) {
            A[i * N + i - 1] = A[(i - 1) * N + i] = VLBE_R(-1.0);
            B[i * N + i - 1] = B[(i - 1) * N + i] = VLBE_R(1.0) / VLBE_R(6.0);
        }
    }
    assert_int_equal(vlbe_eig_sym(N, A, lam, X, w, sizeof w / sizeof w[0]), VLBE_OK);
    for (k = 0; k < N; ++k) {
        const double t = (k + 1) * PI / (N + 1), ex = 4.0 * sin(t / 2) * sin(t / 2);
        err = fmax(err, fabs((double)lam[k] - ex));
        ASSERT_CLOSE((double)lam[k], ex, 0.0, 4.0 * N * EPS * 4.0);
    }
    res = eig_residual(N, A, NULL, lam, X);
    tu_report("eig_sym: |lam - 4 sin^2(t_k/2)|", err, 4.0 * N * EPS * 4.0);
    tu_report("eig_sym: |A x - lam x|", res, 4.0 * N * EPS * 4.0);
    tu_measured("eig_sym", err);
    assert_true(res <= 4.0 * N * EPS * 4.0);

    err = 0.0;
    assert_int_equal(vlbe_eig_gsym(N, A, B, VLBE_R(0.0), lam, X, &info, w, sizeof w / sizeof w[0]),
                     VLBE_OK);
    assert_int_equal(info, 0);
    lam1 = 6.0 * (1.0 - cos(PI / (N + 1))) / (2.0 + cos(PI / (N + 1)));
    for (k = 0; k < N; ++k) {
        const double t = (k + 1) * PI / (N + 1);
        const double ex = 12.0 * sin(t / 2) * sin(t / 2) / (2.0 + cos(t));
        const double tol = 4.0 * N * EPS * 3.0 * ex * ex / lam1;
        err = fmax(err, fabs((double)lam[k] - ex));
        ASSERT_CLOSE_CTX((double)lam[k], ex, 0.0, tol, "mode %d", k);
    }
    res = eig_residual(N, A, B, lam, X);
    orth = orth_err(N, B, X);
    tu_report("eig_gsym: |A x - lam B x|", res, 4.0 * N * EPS * 36.0);
    tu_measured("eig_gsym", err);
    tu_report("eig_gsym: |X^T B X - I|", orth, 4.0 * N * EPS * 3.0);
    assert_true(res <= 4.0 * N * EPS * 36.0);
    assert_true(orth <= 4.0 * N * EPS * 3.0);
    /* X may be NULL: the same eigenvalues */
    {
        vlbe_real lam2[N];
        assert_int_equal(vlbe_eig_gsym(N, A, B, VLBE_R(0.0), lam2, NULL, NULL, w,
                                       sizeof w / sizeof w[0]),
                         VLBE_OK);
        ASSERT_VEC_CLOSE(lam2, lam, N, 0.0, 0.0);
    }
}

/* ======================================================================= */
/* symmetric-definite: vlbe_eig_gsym                                        */
/* ======================================================================= */

/* Fixed-fixed chain of n equal masses m and n + 1 equal springs k:
   lam_j = (2k/m)(1 - cos(j pi/(n+1))) = (4k/m) sin^2(j pi / (2(n+1))).
   Shift-invert (sigma = 0): mu_j = 1/lam_j has the error of Jacobi, a few
   n EPS mu_1 (||C|| = mu_1), so lam_j comes with relative error a few n
   EPS lam_j / lam_1: the fundamental to a few n EPS, the top mode (lam_n
   / lam_1 ~ 4 (n+1)^2 / pi^2) less.  Asserted: 4 n EPS lam_j / lam_1 per
   mode; X^T M X = I and K X = M X diag(lam) to 4 n EPS (relative to 1 and
   to ||K||).  Also sigma < 0 (rigid modes): the free-free chain has lam_j
   = (4k/m) sin^2(j pi / (2n)), j = 0..n-1, lam_0 = 0; with sigma = -lam_1
   / 4 the rigid mode is mu = 1/|sigma|, the largest, and comes out as
   sigma + 1/mu, to a few EPS |sigma| absolute (4 n EPS |sigma| asserted).
   The same chain with sigma = 0: K singular, the last Cholesky pivot is
   0 (info = n). */
static void test_gsym_chain(void **state)
{
    enum { N = 20 };
    static vlbe_real K[N * N], M[N * N], X[N * N], w[3 * N * N + N];
    vlbe_real lam[N];
    double k[N + 1], m[N], worst = 0.0;
    const double kk = 3.0e5, mm = 0.25;
    int i, info = -1;
    (void)state;
    for (i = 0; i <= N; ++i) k[i] = kk;
    for (i = 0; i < N; ++i) m[i] = mm;
    chain(N, k, m, 1, K, M);
    assert_int_equal(vlbe_eig_gsym(N, K, M, VLBE_R(0.0), lam, X, &info, w, 3 * N * N + N),
                     VLBE_OK);
    assert_int_equal(info, 0);
    {
        const double l1 = 4.0 * kk / mm * sin(PI / (2.0 * (N + 1))) * sin(PI / (2.0 * (N + 1)));
        for (i = 0; i < N; ++i) {
            const double s = sin((i + 1) * PI / (2.0 * (N + 1)));
            const double ex = 4.0 * kk / mm * s * s;
            const double rel = fabs((double)lam[i] - ex) / ex;
            ASSERT_CLOSE_CTX((double)lam[i], ex, 4.0 * N * EPS * ex / l1, 0.0, "mode %d", i);
            worst = fmax(worst, rel / (N * EPS * ex / l1));
            if (i == 0) tu_report("gsym chain: lam_1 relative error / EPS", rel / EPS, 4.0 * N);
        }
        tu_report("gsym chain: rel. error / (n EPS lam_j / lam_1)", worst, 4.0);
        tu_report("gsym chain: |X^T M X - I| / (n EPS)", orth_err(N, M, X) / (N * EPS), 4.0);
        assert_true(orth_err(N, M, X) <= 4.0 * N * EPS);
        assert_true(eig_residual(N, K, M, lam, X) <= 4.0 * N * EPS * 4.0 * kk);
    }
    /* free-free: rigid mode */
    chain(N, k, m, 0, K, M);
    {
        const double s1 = sin(PI / (2.0 * N)), l1 = 4.0 * kk / mm * s1 * s1;
        const vlbe_real sigma = (vlbe_real)(-0.25 * l1);
        assert_int_equal(vlbe_eig_gsym(N, K, M, sigma, lam, X, &info, w, 3 * N * N + N),
                         VLBE_OK);
        tu_report("gsym free-free: |lam_0| / |sigma|", fabs((double)lam[0]) / (0.25 * l1),
                  4.0 * N * EPS);
        assert_true(fabs((double)lam[0]) <= 4.0 * N * EPS * 0.25 * l1);
        for (i = 1; i < N; ++i) {
            const double s = sin(i * PI / (2.0 * N)), ex = 4.0 * kk / mm * s * s;
            ASSERT_CLOSE_CTX((double)lam[i], ex, 4.0 * N * EPS * 5.0 * ex / l1, 0.0, "mode %d", i);
        }
        /* rigid mode: all masses move together, x = c (1, ..., 1), c^2 n m = 1 */
        for (i = 0; i < N; ++i)
            ASSERT_CLOSE_CTX(fabs((double)X[i * N]), 1.0 / sqrt(N * mm), 4.0 * N * EPS * 5.0, 0.0,
                             "rigid mode, entry %d", i);
        assert_int_equal(vlbe_eig_gsym(N, K, M, VLBE_R(0.0), lam, X, &info, w, 3 * N * N + N),
                         VLBE_ESINGULAR);
        assert_int_equal(info, N);
    }
}

/* A graded chain: n = 8 masses, springs k_l = R^(l/n) from 1 to R (R =
   1e8 in double, 1e4 in float: the spread of the spectrum must stay
   inside 1/EPS for mu_min > 0), masses 1.  lam_max / lam_1 is then about
   R.  The reference lam_1 is chain_lam1 (long double, independent).
   Shift-invert, sigma = 0: lam_1 is mu_max's reciprocal, to a few EPS
   RELATIVE (asserted: 16 EPS: Jacobi's n EPS mu_max on the largest mu plus
   the Cholesky of K, backward stable with a componentwise error for this
   diagonally dominant M-matrix).  The direct form, sigma far below (-S, S
   = max K_ii / min M_ii, what a user who wants K - sigma M safely
   positive definite without knowing the spectrum picks): all mu near
   1/S, lam_1 = sigma + 1/mu_1 carries the rounding of S: a relative
   error of order EPS S / lam_1 ~ EPS R.  Asserted: above 100 EPS (the
   trap shows), far above the shift-invert error. */
static void test_gsym_graded(void **state)
{
    enum { N = 8 };
    vlbe_real K[N * N], M[N * N], lam[N], w[3 * N * N + N];
#ifdef VLBE_USE_FLOAT
    const double R = 1e4;
#else
    const double R = 1e8;
#endif
    double k[N + 1], m[N], ref, e_si, e_dir, S = 0.0;
    int i, info = -1;
    (void)state;
    for (i = 0; i <= N; ++i) k[i] = pow(R, (double)i / N);
    for (i = 0; i < N; ++i) m[i] = 1.0;
    chain(N, k, m, 1, K, M);
    ref = (double)chain_lam1(N, k, m);
    for (i = 0; i < N; ++i) S = fmax(S, (double)K[i * N + i] / (double)M[i * N + i]);
    assert_int_equal(vlbe_eig_gsym(N, K, M, VLBE_R(0.0), lam, NULL, &info, w, 3 * N * N + N),
                     VLBE_OK);
    e_si = fabs((double)lam[0] - ref) / ref;
    assert_int_equal(vlbe_eig_gsym(N, K, M, (vlbe_real)-S, lam, NULL, &info, w, 3 * N * N + N),
                     VLBE_OK);
    e_dir = fabs((double)lam[0] - ref) / ref;
    if (tu_report_on())
        print_message("    graded chain: lam_max / lam_1 ~ %.1e, lam_1 = %.17g\n", S / ref, ref);
    tu_report("gsym graded: shift-invert lam_1 rel. error / EPS", e_si / EPS, 16.0);
    tu_report("gsym graded: direct (sigma = -S) lam_1 rel. error / EPS", e_dir / EPS, 100.0);
    assert_true(e_si <= 16.0 * EPS);
    assert_true(e_dir > 100.0 * EPS);
}

/* ======================================================================= */
/* general real: vlbe_eig_real                                               */
/* ======================================================================= */

/* The companion matrix of the monic x^n + c[n-1] x^(n-1) + ... + c[0]
   (ones on the subdiagonal, -c in the last column), rounded */
static void companion(int n, const double *c, vlbe_real *A)
{
    int i;
    memset(A, 0, (size_t)n * (size_t)n * sizeof *A);
    for (i = 1; i < n; ++i) A[i * n + i - 1] = VLBE_R(1.0);
    for (i = 0; i < n; ++i) A[i * n + n - 1] = (vlbe_real)-c[i];
}

/* Coefficients of prod (x - r_k) for real roots and pairs (re +- i im):
   roots given as (re, im), im > 0 meaning the pair; c[0..deg-1] */
static int poly_from_roots(int nr, const double *re, const double *im, double *c)
{
    double p[NMAX + 1];
    int deg = 0, r, i;
    p[0] = 1.0;
    for (r = 0; r < nr; ++r) {
        if (im[r] == 0.0) { /* times (x - re) */
            p[deg + 1] = 0.0;
            for (i = deg + 1; i > 0; --i) p[i] = p[i - 1] - re[r] * p[i];
            p[0] *= -re[r];
            ++deg;
        } else { /* times (x^2 - 2 re x + re^2 + im^2) */
            const double b = -2.0 * re[r], q = re[r] * re[r] + im[r] * im[r];
            p[deg + 1] = p[deg + 2] = 0.0;
            for (i = deg + 2; i >= 0; --i)
                p[i] = (i >= 2 ? p[i - 2] : 0.0) + (i >= 1 ? b * p[i - 1] : 0.0) + q * p[i];
            deg += 2;
        }
    }
    /* p[i] is the coefficient of x^i in p[0..deg] after the updates above,
       stored with the highest in p[deg] = 1 */
    for (i = 0; i < deg; ++i) c[i] = p[i];
    return deg;
}

/* cond(r) = sum |c_i| |r|^i / |r p'(r)| (c_n = 1) of a simple root r = re
   + i im of the monic p of degree n with c[0..n-1]: the change of r per
   unit relative change of the coefficients (complex Horner, long double) */
static double root_cond(int n, const double *c, double re, double im)
{
    long double pr = 1.0L, pi = 0.0L, dr = 0.0L, di = 0.0L, num = 0.0L, rp = 1.0L;
    const long double r = sqrtl((long double)re * re + (long double)im * im);
    int i;
    for (i = n - 1; i >= 0; --i) { /* p' then p, Horner from the top */
        const long double t = dr * re - di * im + pr, u = dr * im + di * re + pi;
        const long double a = pr * re - pi * im + c[i], b = pr * im + pi * re;
        dr = t;
        di = u;
        pr = a;
        pi = b;
    }
    for (i = 0; i < n; ++i) {
        num += fabsl((long double)c[i]) * rp;
        rp *= r;
    }
    num += rp;
    return (double)(num / (r * sqrtl(dr * dr + di * di)));
}

/* each expected root (re, im; pairs as +im and -im) matched by the closest
   unused computed eigenvalue; the largest distance */
static double match_roots(int n, const vlbe_real *wr, const vlbe_real *wi, const double *er,
                          const double *ei)
{
    int used[NMAX], i, j, best;
    double worst = 0.0;
    for (j = 0; j < n; ++j) used[j] = 0;
    for (i = 0; i < n; ++i) {
        double dbest = HUGE_VAL;
        best = -1;
        for (j = 0; j < n; ++j) {
            const double d = hypot((double)wr[j] - er[i], (double)wi[j] - ei[i]);
            if (!used[j] && d < dbest) {
                dbest = d;
                best = j;
            }
        }
        assert_true(best >= 0);
        used[best] = 1;
        worst = fmax(worst, dbest);
    }
    return worst;
}

/* pairs: adjacent, equal real parts, opposite imaginary parts, + first */
static void assert_pairs(int n, const vlbe_real *wr, const vlbe_real *wi)
{
    int i = 0;
    while (i < n) {
        if (wi[i] == VLBE_R(0.0)) {
            ++i;
            continue;
        }
        assert_true(i + 1 < n);
        assert_true(wi[i] > VLBE_R(0.0));
        assert_true(wi[i + 1] == -wi[i] && wr[i + 1] == wr[i]);
        i += 2;
    }
}

/* Companion matrices of polynomials with known roots.  A simple root r of
   p moves under a backward error of relative size e in the coefficients
   by about e cond(r), cond(r) = sum |c_i| |r|^i / |r p'(r)|; QR with
   balancing on a companion matrix has a backward error of a few n EPS in
   that sense for these moderate coefficients, so the asserted tolerance is
   8 n EPS max(1, |r|) cond(r), the largest over the set (root_cond):
   (1) real 1 .. 5, (2) pairs +-i and 1 +- 2i and the real -3, (3) a
   triple root 1 and a double -2: a root of
   multiplicity m moves by (e)^(1/m), asserted at 8 (n EPS
   max|c|)^(1/3) (the triple) in size. */
static void test_real_companion(void **state)
{
    vlbe_real A[NMAX * NMAX], wr[NMAX], wi[NMAX], w[4 * NMAX];
    double c[NMAX], er[NMAX], ei[NMAX], err, tol;
    int n, i;
    (void)state;
    { /* (1) */
        const double re[] = {1, 2, 3, 4, 5}, im[] = {0, 0, 0, 0, 0};
        double cond = 0.0;
        n = poly_from_roots(5, re, im, c);
        companion(n, c, A);
        assert_int_equal(vlbe_eig_real(n, A, wr, wi, w, 4 * NMAX), VLBE_OK);
        for (i = 0; i < n; ++i) {
            er[i] = re[i];
            ei[i] = 0.0;
            cond = fmax(cond, fmax(1.0, fabs(re[i])) * root_cond(n, c, re[i], 0.0));
        }
        err = match_roots(n, wr, wi, er, ei);
        tol = 8.0 * n * EPS * cond;
        tu_report("eig_real: companion, roots 1..5", err, tol);
        assert_true(err <= tol);
        for (i = 0; i < n; ++i) assert_true(wi[i] == VLBE_R(0.0));
    }
    { /* (2) */
        const double re[] = {0, 1, -3}, im[] = {1, 2, 0};
        double cond = 0.0;
        n = poly_from_roots(3, re, im, c);
        assert_int_equal(n, 5);
        companion(n, c, A);
        assert_int_equal(vlbe_eig_real(n, A, wr, wi, w, 4 * NMAX), VLBE_OK);
        er[0] = 0;
        ei[0] = 1;
        er[1] = 0;
        ei[1] = -1;
        er[2] = 1;
        ei[2] = 2;
        er[3] = 1;
        ei[3] = -2;
        er[4] = -3;
        ei[4] = 0;
        for (i = 0; i < n; ++i)
            cond = fmax(cond, fmax(1.0, hypot(er[i], ei[i])) * root_cond(n, c, er[i], ei[i]));
        err = match_roots(n, wr, wi, er, ei);
        tol = 8.0 * n * EPS * cond;
        tu_report("eig_real: companion, +-i, 1+-2i, -3", err, tol);
        assert_true(err <= tol);
        assert_pairs(n, wr, wi);
    }
    { /* (3) (x - 1)^3 (x + 2)^2 */
        const double re[] = {1, 1, 1, -2, -2}, im[] = {0, 0, 0, 0, 0};
        double cmax = 0.0;
        n = poly_from_roots(5, re, im, c);
        for (i = 0; i < n; ++i) cmax = fmax(cmax, fabs(c[i]));
        companion(n, c, A);
        assert_int_equal(vlbe_eig_real(n, A, wr, wi, w, 4 * NMAX), VLBE_OK);
        for (i = 0; i < n; ++i) {
            er[i] = re[i];
            ei[i] = 0.0;
        }
        err = match_roots(n, wr, wi, er, ei);
        tol = 8.0 * cbrt(n * EPS * cmax);
        tu_report("eig_real: companion, (x-1)^3 (x+2)^2", err, tol);
        assert_true(err <= tol);
        assert_pairs(n, wr, wi);
        /* the sum of the eigenvalues is the trace, -c[n-1] = 3 - 4 = -1,
           to rounding of the similarity (n EPS ||A|| per eigenvalue) */
        {
            double s = 0.0;
            for (i = 0; i < n; ++i) s += (double)wr[i];
            ASSERT_CLOSE(s, -1.0, 0.0, 8.0 * n * n * EPS * cmax);
        }
    }
}

/* A = S B S^-1, B block diagonal with known eigenvalues (2 x 2 blocks
   [a b; -b a]: a +- i b, and reals), S = Q D, Q orthogonal (random_q), D
   = diag(2^e), e in -2..2, so S^-1 = D^-1 Q^T exactly up to Q's long-
   double rounding.  The eigenvalue condition numbers are at most cond(S)
   <= 16; QR's backward error a few n EPS ||A||: 8 n EPS ||A|| 16
   asserted.  n = 9 and 24. */
static void test_real_similarity(void **state)
{
    static long double Q[NMAX * NMAX], SB[NMAX * NMAX];
    static vlbe_real A[NMAX * NMAX];
    vlbe_real wr[NMAX], wi[NMAX], w[4 * NMAX];
    double er[NMAX], ei[NMAX], dsc[NMAX];
    tu_rng g = tu_rng_seed(4242);
    static const int sizes[] = {9, 24};
    int s;
    (void)state;
    for (s = 0; s < 2; ++s) {
        const int n = sizes[s];
        long double B[NMAX * NMAX];
        double anorm = 0.0, err, tol;
        int i, j, k;
        memset(B, 0, sizeof B);
        for (i = 0; i < n; ++i) {
            if (i + 1 < n && i % 3 != 2) { /* a pair */
                const double a = 3.0 * tu_rng_uniform(&g), b = 0.5 + fabs(tu_rng_uniform(&g));
                B[i * n + i] = B[(i + 1) * n + i + 1] = a;
                B[i * n + i + 1] = b;
                B[(i + 1) * n + i] = -b;
                er[i] = er[i + 1] = a;
                ei[i] = b;
                ei[i + 1] = -b;
                ++i;
            } else {
                er[i] = 3.0 * tu_rng_uniform(&g);
                ei[i] = 0.0;
                B[i * n + i] = er[i];
            }
        }
        for (i = 0; i < n; ++i) dsc[i] = ldexp(1.0, (int)(i % 5) - 2);
        random_q(n, &g, Q);
        for (i = 0; i < n; ++i) /* SB = Q D B */
            for (j = 0; j < n; ++j) {
                long double t = 0.0L;
                for (k = 0; k < n; ++k) t += Q[i * n + k] * (long double)dsc[k] * B[k * n + j];
                SB[i * n + j] = t;
            }
        for (i = 0; i < n; ++i) /* A = SB D^-1 Q^T */
            for (j = 0; j < n; ++j) {
                long double t = 0.0L;
                for (k = 0; k < n; ++k) t += SB[i * n + k] / (long double)dsc[k] * Q[j * n + k];
                A[i * n + j] = (vlbe_real)t;
                anorm = fmax(anorm, fabs((double)t));
            }
        anorm *= n;
        assert_int_equal(vlbe_eig_real(n, A, wr, wi, w, 4 * NMAX), VLBE_OK);
        assert_pairs(n, wr, wi);
        err = match_roots(n, wr, wi, er, ei);
        tol = 8.0 * n * EPS * anorm * 16.0;
        tu_report("eig_real: S B S^-1", err, tol);
        assert_true(err <= tol);
    }
}

/* 2 x 2 matrices (the standardisation of the final blocks): real
   distinct, a complex pair, a rotation, triangular, zero, and the same
   scaled by 2^k near the overflow and underflow limits (exact scaling:
   the eigenvalues scale exactly).  Exact values: [1 2; 3 4]: (5 +-
   sqrt 33)/2; [0 -1; 1 0]: +-i; [2 -5; 1 -2]: +-i; [3 7; 0 -1]: 3, -1.
   Tolerance 4 EPS |lam| (the formulas of vlbe__eig_2x2 round a few
   times). */
static void test_real_2x2(void **state)
{
    static const double mats[5][4] = {{1, 2, 3, 4}, {0, -1, 1, 0}, {2, -5, 1, -2}, {3, 7, 0, -1},
                                      {0, 0, 0, 0}};
    const double s33 = sqrt(33.0);
    const double exr[5][2] = {{(5 - s33) / 2, (5 + s33) / 2}, {0, 0}, {0, 0}, {-1, 3}, {0, 0}};
    const double exi[5][2] = {{0, 0}, {1, -1}, {1, -1}, {0, 0}, {0, 0}};
    const int scales[] = {0, 100, -100};
    int t, sc, i;
    (void)state;
    for (sc = 0; sc < 3; ++sc)
        for (t = 0; t < 5; ++t) {
            vlbe_real A[4], wr[2], wi[2], w[8];
            const int e = scales[sc];
            const double f = ldexp(1.0, e);
            double er[2], ei[2];
            for (i = 0; i < 4; ++i) A[i] = (vlbe_real)(mats[t][i] * f);
            assert_int_equal(vlbe_eig_real(2, A, wr, wi, w, 8), VLBE_OK);
            for (i = 0; i < 2; ++i) {
                er[i] = exr[t][i] * f;
                ei[i] = exi[t][i] * f;
            }
            {
                const double err = match_roots(2, wr, wi, er, ei);
                ASSERT_CLOSE_CTX(err, 0.0, 0.0, 4.0 * EPS * 6.0 * f, "matrix %d, scale 2^%d", t, e);
            }
            assert_pairs(2, wr, wi);
        }
}

/* ======================================================================= */
/* quadratic: vlbe_eig_quad                                                  */
/* ======================================================================= */

typedef struct quad_out {
    vlbe_real sr[2 * NMAX], si[2 * NMAX], Xr[2 * NMAX * NMAX], Xi[2 * NMAX * NMAX];
} quad_out;

static vlbe_real qwork[9 * NMAX * NMAX + 20 * NMAX];
static int qiwork[4 * NMAX];

static vlbe_status quad(int n, const vlbe_real *M, const vlbe_real *D, const vlbe_real *K,
                        vlbe_real sigma, quad_out *o)
{
    return vlbe_eig_quad(n, M, D, K, sigma, o->sr, o->si, 2 * n, o->Xr, o->Xi, qwork,
                         vlbe_eig_quad_work_len(n), qiwork, vlbe_eig_quad_iwork_len(n));
}

/* The eigenvector residuals: max over k of ||P(s_k) x_k||_inf / (|s|^2
   ||M|| + |s| ||D|| + ||K||) (inf-norms; long double complex arithmetic
   written out), and max | ||x_k||_2 - 1 |; checks the normalisation:
   the largest component real positive. */
static double quad_residual(int n, const vlbe_real *M, const vlbe_real *D, const vlbe_real *K,
                            const quad_out *o, double *nerr)
{
    const int n2 = 2 * n;
    double worst = 0.0;
    int k, i, j;
    long double nm = 0.0L, nd = 0.0L, nk = 0.0L;
    for (i = 0; i < n; ++i) {
        long double a = 0.0L, b = 0.0L, c = 0.0L;
        for (j = 0; j < n; ++j) {
            a += fabsl((long double)M[i * n + j]);
            b += D ? fabsl((long double)D[i * n + j]) : 0.0L;
            c += fabsl((long double)K[i * n + j]);
        }
        nm = fmaxl(nm, a);
        nd = fmaxl(nd, b);
        nk = fmaxl(nk, c);
    }
    *nerr = 0.0;
    for (k = 0; k < n2; ++k) {
        const long double a = o->sr[k], b = o->si[k];
        const long double s2r = a * a - b * b, s2i = 2.0L * a * b, as = sqrtl(a * a + b * b);
        long double rmax = 0.0L, xn = 0.0L, xmax = 0.0L;
        int ok = 0;
        for (i = 0; i < n; ++i) {
            long double rr = 0.0L, ri = 0.0L;
            for (j = 0; j < n; ++j) {
                const long double d = D ? (long double)D[i * n + j] : 0.0L;
                const long double pr = s2r * M[i * n + j] + a * d + K[i * n + j];
                const long double pi = s2i * M[i * n + j] + b * d;
                const long double xr = o->Xr[j * n2 + k], xi = o->Xi[j * n2 + k];
                rr += pr * xr - pi * xi;
                ri += pr * xi + pi * xr;
            }
            rmax = fmaxl(rmax, sqrtl(rr * rr + ri * ri));
        }
        for (j = 0; j < n; ++j) {
            const long double xr = o->Xr[j * n2 + k], xi = o->Xi[j * n2 + k];
            const long double m2 = xr * xr + xi * xi;
            xn += m2;
            if (m2 > xmax) xmax = m2;
        }
        /* a component of largest modulus (to the rounding of the moduli,
           4 EPS: symmetric modes have equal ones) is real and positive */
        for (j = 0; j < n; ++j)
            if (o->Xi[j * n2 + k] == VLBE_R(0.0) && o->Xr[j * n2 + k] > VLBE_R(0.0) &&
                (long double)o->Xr[j * n2 + k] >= sqrtl(xmax) * (1.0L - 4.0L * (long double)EPS))
                ok = 1;
        assert_true(ok);
        *nerr = fmax(*nerr, fabs((double)sqrtl(xn) - 1.0));
        worst = fmax(worst, (double)(rmax / (as * as * nm + as * nd + nk)));
    }
    return worst;
}

/* output order: |s - sigma| ascending, conjugate pairs adjacent (+ first) */
static void assert_quad_order(int n, vlbe_real sigma, const quad_out *o)
{
    int k;
    for (k = 0; k + 1 < 2 * n; ++k) {
        const double d0 = hypot((double)(o->sr[k] - sigma), (double)o->si[k]);
        const double d1 = hypot((double)(o->sr[k + 1] - sigma), (double)o->si[k + 1]);
        assert_true(d0 <= d1 * (1.0 + 4.0 * EPS));
    }
    for (k = 0; k < 2 * n;) {
        if (o->si[k] == VLBE_R(0.0)) {
            ++k;
            continue;
        }
        assert_true(o->si[k] > VLBE_R(0.0) && k + 1 < 2 * n);
        assert_true(o->si[k + 1] == -o->si[k] && o->sr[k + 1] == o->sr[k]);
        k += 2;
    }
}

/* Undamped, M and K symmetric (the uniform chain and a random pair M =
   Q1 diag Q1^T, K = Q2 diag Q2^T): s = +-i w, w^2 the eigenvalues of
   vlbe_eig_gsym(K, M, 0).  Tolerances: both solvers give the lowest modes
   to a few n EPS relative and the others to n EPS (w_max / w_1)^2 relative
   (gsym, see above) and n EPS w_max / w_1 (quad: ||T|| = 1/w_1):
   asserted per mode 8 n EPS (w_k/w_1)^2 on w_k, Re s to 8 n EPS w_max.
   Eigenvector residual 8 n EPS (relative, see quad_residual), unit norm
   to 8 n EPS. */
static void test_quad_undamped(void **state)
{
    enum { N = 10 };
    static quad_out o;
    static long double Q[NMAX * NMAX];
    vlbe_real K[N * N], M[N * N], lam[N], w[3 * N * N + N];
    double k[N + 1], m[N], d[N], nerr, res;
    tu_rng g = tu_rng_seed(99);
    int c, j, i;
    (void)state;
    for (c = 0; c < 2; ++c) {
        if (c == 0) {
            for (i = 0; i <= N; ++i) k[i] = 40.0;
            for (i = 0; i < N; ++i) m[i] = 0.5;
            chain(N, k, m, 1, K, M);
        } else {
            random_q(N, &g, Q);
            for (i = 0; i < N; ++i) d[i] = 1.0 + 0.5 * tu_rng_uniform(&g);
            build_sym(N, Q, d, M);
            random_q(N, &g, Q);
            for (i = 0; i < N; ++i) d[i] = 2.0 + 1.5 * tu_rng_uniform(&g);
            build_sym(N, Q, d, K);
        }
        assert_int_equal(vlbe_eig_gsym(N, K, M, VLBE_R(0.0), lam, NULL, NULL, w, 3 * N * N + N),
                         VLBE_OK);
        assert_int_equal(quad(N, M, NULL, K, VLBE_R(0.0), &o), VLBE_OK);
        assert_quad_order(N, VLBE_R(0.0), &o);
        for (j = 0; j < N; ++j) {
            const double wk = sqrt((double)lam[j]), w1 = sqrt((double)lam[0]);
            const double wmax = sqrt((double)lam[N - 1]);
            const double tol = 8.0 * N * EPS * (wk / w1) * (wk / w1) * wk;
            ASSERT_CLOSE_CTX((double)o.si[2 * j], wk, 0.0, tol, "case %d, mode %d", c, j);
            ASSERT_CLOSE_CTX((double)o.si[2 * j + 1], -wk, 0.0, tol, "case %d, mode %d", c, j);
            ASSERT_CLOSE_CTX((double)o.sr[2 * j], 0.0, 0.0, 8.0 * N * EPS * wmax, "case %d", c);
        }
        res = quad_residual(N, M, NULL, K, &o, &nerr);
        tu_report("eig_quad undamped: ||P(s) x|| / ||P||", res, 8.0 * N * EPS);
        assert_true(res <= 8.0 * N * EPS);
        assert_true(nerr <= 8.0 * N * EPS);
    }
}

/* The two-DOF rotor in a rotating frame: M = I, D = 2 Om [0 -1; 1 0]
   (gyroscopic, skew), K = (k - Om^2) I.  det P(s) = (s^2 + k - Om^2)^2 +
   4 Om^2 s^2 = 0 gives s^2 + k - Om^2 = +-2 i Om s, whose roots are
       s = i (+-sqrt(k) +- Om)
   for EVERY Om: no divergence band; for |Om| > sqrt(k) K is negative
   definite and the gyroscopic coupling still keeps s imaginary (whirl
   frequencies |sqrt(k) +- Om|); at |Om| = sqrt(k), K = 0 and s = 0 is a
   double root (P(0) = 0: sigma = 0 is singular, a shift below works).
   Tolerance: 8 EPS (sqrt(k) + |Om|) on every s (n = 2, T well
   conditioned: its eigenvalues are normal here, T = (A - sigma)^-1 with A
   similar to a skew matrix).  Eigenvector residuals as above. */
static void test_quad_rotor(void **state)
{
    static const double oms[] = {0.0, 0.3, 1.7, 2.0, 3.0, -3.0};
    static quad_out o;
    const double k = 4.0;
    int c, i;
    (void)state;
    for (c = 0; c < (int)(sizeof oms / sizeof oms[0]); ++c) {
        const double om = oms[c], sk = sqrt(k);
        const vlbe_real sigma = fabs(fabs(om) - sk) < 1e-12 ? VLBE_R(-0.5) : VLBE_R(0.0);
        vlbe_real M[4] = {1, 0, 0, 1}, D[4], K[4];
        double ex[4], got[4], res, nerr;
        D[0] = D[3] = VLBE_R(0.0);
        D[1] = (vlbe_real)(-2.0 * om);
        D[2] = (vlbe_real)(2.0 * om);
        K[0] = K[3] = (vlbe_real)(k - om * om);
        K[1] = K[2] = VLBE_R(0.0);
        if (sigma == VLBE_R(-0.5)) /* K = 0: P(0) singular */
            assert_int_equal(quad(2, M, D, K, VLBE_R(0.0), &o), VLBE_ESINGULAR);
        assert_int_equal(quad(2, M, D, K, sigma, &o), VLBE_OK);
        assert_quad_order(2, sigma, &o);
        ex[0] = sk + om;
        ex[1] = sk - om;
        ex[2] = -sk + om;
        ex[3] = -sk - om;
        for (i = 0; i < 4; ++i) {
            ASSERT_CLOSE_CTX((double)o.sr[i], 0.0, 0.0, 8.0 * EPS * (sk + fabs(om)), "Om = %g", om);
            got[i] = (double)o.si[i];
        }
        /* the multiset of imaginary parts: sort both */
        {
            int a, b;
            for (a = 0; a < 4; ++a)
                for (b = a + 1; b < 4; ++b) {
                    double t;
                    if (ex[b] < ex[a]) {
                        t = ex[a];
                        ex[a] = ex[b];
                        ex[b] = t;
                    }
                    if (got[b] < got[a]) {
                        t = got[a];
                        got[a] = got[b];
                        got[b] = t;
                    }
                }
        }
        for (i = 0; i < 4; ++i)
            ASSERT_CLOSE_CTX(got[i], ex[i], 0.0, 8.0 * EPS * (sk + fabs(om)), "Om = %g, %d", om, i);
        if (om != 0.0 && sigma == VLBE_R(0.0)) { /* simple eigenvalues: vectors */
            res = quad_residual(2, M, D, K, &o, &nerr);
            tu_report("eig_quad rotor: ||P(s) x|| / ||P||", res, 16.0 * EPS);
            assert_true(res <= 16.0 * EPS);
            assert_true(nerr <= 8.0 * EPS);
        }
    }
}

/* A damped single DOF m s^2 + c s + k = 0, w = sqrt(k/m), zeta = c / (2
   m w): s = -zeta w +- i w sqrt(1 - zeta^2) (zeta < 1), s = -w (zeta +-
   sqrt(zeta^2 - 1)) (zeta > 1; the small root as w^2 / the large one,
   without cancellation).  Tolerance 8 EPS w (1 + 2 zeta + 1 / sqrt|1 -
   zeta^2|): n = 1, T is 2 x 2 and its eigenvalues come to a few EPS ||T||
   (||T|| ~ max(1, 2 zeta) / w, relative to |mu| ~ 1/w), times their
   condition, which grows near critical damping as the roots approach a
   double one: 1 / |s_1 - s_2| = 1 / (2 w sqrt|1 - zeta^2|). */
static void test_quad_damped(void **state)
{
    static const double zetas[] = {0.0, 0.02, 0.5, 0.999, 1.5, 20.0};
    static quad_out o;
    const double mm = 2.0, kk = 50.0, wn = 5.0;
    int c;
    (void)state;
    for (c = 0; c < (int)(sizeof zetas / sizeof zetas[0]); ++c) {
        const double z = zetas[c];
        vlbe_real M = (vlbe_real)mm, D = (vlbe_real)(2.0 * mm * wn * z), K = (vlbe_real)kk;
        double er[2], ei[2], res, nerr;
        assert_int_equal(quad(1, &M, &D, &K, VLBE_R(0.0), &o), VLBE_OK);
        if (z < 1.0) {
            er[0] = er[1] = -z * wn;
            ei[0] = wn * sqrt(1.0 - z * z);
            ei[1] = -ei[0];
        } else {
            er[1] = -wn * (z + sqrt(z * z - 1.0));
            er[0] = wn * wn / er[1];
            ei[0] = ei[1] = 0.0;
        }
        {
            const double e = match_roots(2, o.sr, o.si, er, ei);
            const double tol = 8.0 * EPS * (1.0 + 2.0 * z + 1.0 / sqrt(fabs(1.0 - z * z)));
            ASSERT_CLOSE_CTX(e, 0.0, 0.0, tol * wn, "zeta = %g", z);
            tu_report("eig_quad damped SDOF: |s - s_exact| / w", e / wn, tol);
        }
        assert_quad_order(1, VLBE_R(0.0), &o);
        res = quad_residual(1, &M, &D, &K, &o, &nerr);
        assert_true(res <= 8.0 * EPS);
        assert_true(nerr <= 8.0 * EPS);
    }
}

/* Random nonsymmetric M (diagonally dominant: nonsingular), D, K, n = 12,
   two shifts: every eigenvector's residual ||P(s) x|| <= 64 n EPS ||P||
   (relative), the order of the output, and the same eigenvalues for
   both shifts to 1e3 n EPS |s| (they are computed from different T's;
   the eigenvalues of a random pencil have condition numbers of tens).
   The shift-invert image: the sum over the eigenvalues of 1/(s - sigma)
   is the trace of T, -trace(P(sigma)^-1 (D + 2 sigma M))... not used;
   the residual is the independent fact. */
static void test_quad_random(void **state)
{
    enum { N = 12 };
    static quad_out o, o2;
    vlbe_real M[N * N], D[N * N], K[N * N];
    tu_rng g = tu_rng_seed(5150);
    double res, nerr;
    int i, j;
    (void)state;
    for (i = 0; i < N * N; ++i) {
        M[i] = (vlbe_real)(0.2 * tu_rng_uniform(&g));
        D[i] = (vlbe_real)(0.5 * tu_rng_uniform(&g));
        K[i] = (vlbe_real)(3.0 * tu_rng_uniform(&g));
    }
    for (i = 0; i < N; ++i) M[i * N + i] += VLBE_R(3.0);
    assert_int_equal(quad(N, M, D, K, VLBE_R(0.0), &o), VLBE_OK);
    assert_quad_order(N, VLBE_R(0.0), &o);
    res = quad_residual(N, M, D, K, &o, &nerr);
    tu_report("eig_quad random: ||P(s) x|| / ||P||", res, 64.0 * N * EPS);
    assert_true(res <= 64.0 * N * EPS);
    assert_true(nerr <= 8.0 * N * EPS);
    assert_int_equal(quad(N, M, D, K, VLBE_R(-0.7), &o2), VLBE_OK);
    assert_quad_order(N, VLBE_R(-0.7), &o2);
    res = quad_residual(N, M, D, K, &o2, &nerr);
    assert_true(res <= 64.0 * N * EPS);
    {
        double worst = 0.0;
        for (i = 0; i < 2 * N; ++i) {
            double best = HUGE_VAL, as = hypot((double)o.sr[i], (double)o.si[i]);
            for (j = 0; j < 2 * N; ++j)
                best = fmin(best, hypot((double)(o.sr[i] - o2.sr[j]), (double)(o.si[i] - o2.si[j])));
            worst = fmax(worst, best / as);
            assert_true(best <= 1e3 * N * EPS * as);
        }
        tu_report("eig_quad random: sigma 0 vs -0.7, |ds| / |s|", worst, 1e3 * N * EPS);
    }
}

/* The graded chain of test_gsym_graded, undamped: s_1 = i sqrt(lam_1),
   lam_1 from chain_lam1 (independent).  With sigma = 0 the fundamental is
   the largest |mu| = 1/w_1: relative 16 EPS on w_1 (QR's n EPS ||T||
   on the largest |mu|, plus P(0) = K's LU).  The spread w_max/w_1 ~
   sqrt(R) = 1e4 would cost QR on the first-order A itself that factor. */
static void test_quad_graded(void **state)
{
    enum { N = 8 };
    static quad_out o;
    vlbe_real K[N * N], M[N * N];
#ifdef VLBE_USE_FLOAT
    const double R = 1e4;
#else
    const double R = 1e8;
#endif
    double k[N + 1], m[N], w1, e;
    int i;
    (void)state;
    for (i = 0; i <= N; ++i) k[i] = pow(R, (double)i / N);
    for (i = 0; i < N; ++i) m[i] = 1.0;
    chain(N, k, m, 1, K, M);
    w1 = (double)sqrtl(chain_lam1(N, k, m));
    assert_int_equal(quad(N, M, NULL, K, VLBE_R(0.0), &o), VLBE_OK);
    e = fabs((double)o.si[0] - w1) / w1;
    tu_report("eig_quad graded: w_1 rel. error / EPS", e / EPS, 16.0);
    assert_true(e <= 16.0 * EPS);
    assert_true(fabs((double)o.sr[0]) <= 16.0 * EPS * w1);
}

/* ======================================================================= */
/* failure paths                                                            */
/* ======================================================================= */

#define SENT VLBE_R(-7.25)

static void fill(int n, vlbe_real *a)
{
    int i;
    for (i = 0; i < n; ++i) a[i] = SENT;
}
static void untouched(int n, const vlbe_real *a)
{
    int i;
    for (i = 0; i < n; ++i) assert_true(a[i] == SENT);
}

static void test_fail_sym_gsym(void **state)
{
    vlbe_real K[9] = {3, 0, 0, 0, 1, 0, 0, 0, 5}, M[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    vlbe_real lam[3], X[9], w[30];
    int info = 0;
    (void)state;
    fill(3, lam);
    fill(9, X);
    /* K - sigma M indefinite: diag(1, -1, 3), the second pivot */
    assert_int_equal(vlbe_eig_gsym(3, K, M, VLBE_R(2.0), lam, X, &info, w, 30), VLBE_ESINGULAR);
    assert_int_equal(info, 2);
    /* exactly singular: sigma = the eigenvalue 1 */
    assert_int_equal(vlbe_eig_gsym(3, K, M, VLBE_R(1.0), lam, X, &info, w, 30), VLBE_ESINGULAR);
    assert_int_equal(info, 2);
    /* M indefinite: mu = -1 appears, M's Cholesky fails at column 2: n + 2 */
    M[4] = VLBE_R(-1.0);
    assert_int_equal(vlbe_eig_gsym(3, K, M, VLBE_R(0.0), lam, X, &info, w, 30), VLBE_ESINGULAR);
    assert_int_equal(info, 5);
    /* M semidefinite (a massless coordinate): mu = 0 */
    M[4] = VLBE_R(0.0);
    assert_int_equal(vlbe_eig_gsym(3, K, M, VLBE_R(0.0), lam, X, &info, w, 30), VLBE_ESINGULAR);
    assert_int_equal(info, 5);
    M[4] = VLBE_R(1.0);
    /* non-finite */
    K[4] = (vlbe_real)NAN;
    assert_int_equal(vlbe_eig_gsym(3, K, M, VLBE_R(0.0), lam, X, &info, w, 30), VLBE_ENONFINITE);
    assert_int_equal(vlbe_eig_sym(3, K, lam, X, w, 30), VLBE_ENONFINITE);
    K[4] = VLBE_R(1.0);
    M[8] = (vlbe_real)INFINITY;
    assert_int_equal(vlbe_eig_gsym(3, K, M, VLBE_R(0.0), lam, X, &info, w, 30), VLBE_ENONFINITE);
    M[8] = VLBE_R(1.0);
    assert_int_equal(vlbe_eig_gsym(3, K, M, (vlbe_real)NAN, lam, X, &info, w, 30),
                     VLBE_ENONFINITE);
    /* workspace and size */
    assert_int_equal(vlbe_eig_gsym(3, K, M, VLBE_R(0.0), lam, X, &info, w, 29), VLBE_EWORK);
    assert_int_equal(vlbe_eig_sym(3, K, lam, X, w, 29), VLBE_EWORK);
    assert_int_equal(vlbe_eig_gsym(0, K, M, VLBE_R(0.0), lam, X, &info, w, 30), VLBE_EARG);
    assert_int_equal(vlbe_eig_sym(-1, K, lam, X, w, 30), VLBE_EARG);
    untouched(3, lam);
    untouched(9, X);
    /* a spread beyond the working precision, M = I: K = [2 -1; -1 2]
       (eigenvalues 1 on (1, 1), 3 on (1, -1)) coupled by 0.5 to a third
       coordinate of stiffness 1/EPS^2, which moves them by O(EPS^2):
       the call succeeds, lam_1 = 1 and lam_2 = 3 to 16 EPS relative, lam_3
       finite and above them (the rounding case, a computed mu <= 0 raised
       to the resolution bound, is met by the float build of
       test_scenes_shaft: the frozen frequencies of the spinning shaft) */
    {
        const double big = 1.0 / (EPS * EPS);
        vlbe_real Kw[9], lw[3];
        double Kd[9] = {2, -1, 0, -1, 2, 0, 0, 0, 0};
        int i;
        Kd[8] = big;
        Kd[2] = Kd[6] = 0.5;
        Kd[5] = Kd[7] = 0.5;
        for (i = 0; i < 9; ++i) Kw[i] = (vlbe_real)Kd[i];
        assert_int_equal(vlbe_eig_gsym(3, Kw, M, VLBE_R(0.0), lw, NULL, &info, w, 30), VLBE_OK);
        assert_int_equal(info, 0);
        ASSERT_CLOSE((double)lw[0], 1.0, 16.0 * EPS, 0.0);
        ASSERT_CLOSE((double)lw[1], 3.0, 16.0 * EPS, 0.0);
        assert_true((double)lw[2] > 1.0 / (3.0 * EPS) * 0.5);
    }
    /* the good case after all that: diagonal, exact */
    assert_int_equal(vlbe_eig_gsym(3, K, M, VLBE_R(0.0), lam, X, &info, w, 30), VLBE_OK);
    assert_int_equal(info, 0);
    /* lam = 1/mu, mu = 1/K_ii rounded by the reduction: 4 EPS relative */
    ASSERT_CLOSE((double)lam[0], 1.0, 4.0 * EPS, 0.0);
    ASSERT_CLOSE((double)lam[1], 3.0, 4.0 * EPS, 0.0);
    ASSERT_CLOSE((double)lam[2], 5.0, 4.0 * EPS, 0.0);
}

static void test_fail_real(void **state)
{
    vlbe_real A[9] = {1, 2, 3, 4, 5, 6, 7, 8, 10}, wr[3], wi[3], w[12];
    (void)state;
    fill(3, wr);
    fill(3, wi);
    A[5] = (vlbe_real)NAN;
    assert_int_equal(vlbe_eig_real(3, A, wr, wi, w, 12), VLBE_ENONFINITE);
    assert_true(A[0] == VLBE_R(1.0) && A[8] == VLBE_R(10.0)); /* found before any write */
    A[5] = VLBE_R(6.0);
    assert_int_equal(vlbe_eig_real(3, A, wr, wi, w, 11), VLBE_EWORK);
    assert_int_equal(vlbe_eig_real(0, A, wr, wi, w, 12), VLBE_EARG);
    untouched(3, wr);
    untouched(3, wi);
    /* n = 1 */
    assert_int_equal(vlbe_eig_real(1, A, wr, wi, w, 4), VLBE_OK);
    assert_true(wr[0] == VLBE_R(1.0) && wi[0] == VLBE_R(0.0));
}

static void test_fail_quad(void **state)
{
    static quad_out o;
    vlbe_real M[4] = {1, 0, 0, 1}, D[4] = {0.1f, 0, 0, 0.1f}, K[4] = {2, -1, -1, 2};
    vlbe_real w[200];
    int iw[8];
    (void)state;
    fill(4, o.sr);
    fill(4, o.si);
    fill(8, o.Xr);
    fill(8, o.Xi);
    /* P(sigma) singular: D = 0, K = [[1, -1], [-1, 1]], sigma = 0 */
    {
        vlbe_real Ks[4] = {1, -1, -1, 1};
        assert_int_equal(vlbe_eig_quad(2, M, NULL, Ks, VLBE_R(0.0), o.sr, o.si, 4, o.Xr, o.Xi, w,
                                       200,
                                       iw, 8),
                         VLBE_ESINGULAR);
    }
    D[3] = (vlbe_real)NAN;
    assert_int_equal(vlbe_eig_quad(2, M, D, K, VLBE_R(0.0), o.sr, o.si, 4, o.Xr, o.Xi, w, 200, iw,
                                   8),
                     VLBE_ENONFINITE);
    D[3] = VLBE_R(0.1);
    assert_int_equal(vlbe_eig_quad(2, M, D, K, (vlbe_real)INFINITY, o.sr, o.si, 4, o.Xr, o.Xi, w,
                                   200, iw, 8),
                     VLBE_ENONFINITE);
    assert_int_equal(vlbe_eig_quad(2, M, D, K, VLBE_R(0.0), o.sr, o.si, 4, o.Xr, o.Xi, w,
                                   vlbe_eig_quad_work_len(2) - 1, iw, 8),
                     VLBE_EWORK);
    assert_int_equal(vlbe_eig_quad(2, M, D, K, VLBE_R(0.0), o.sr, o.si, 4, o.Xr, o.Xi, w, 200, iw,
                                   vlbe_eig_quad_iwork_len(2) - 1),
                     VLBE_EWORK);
    assert_int_equal(vlbe_eig_quad(0, M, D, K, VLBE_R(0.0), o.sr, o.si, 4, o.Xr, o.Xi, w, 200, iw,
                                   8),
                     VLBE_EARG);
    /* nvec outside 0..2n */
    assert_int_equal(vlbe_eig_quad(2, M, D, K, VLBE_R(0.0), o.sr, o.si, 5, o.Xr, o.Xi, w, 200,
                                   iw, 8),
                     VLBE_EARG);
    assert_int_equal(vlbe_eig_quad(2, M, D, K, VLBE_R(0.0), o.sr, o.si, -1, o.Xr, o.Xi, w, 200,
                                   iw, 8),
                     VLBE_EARG);
    /* 2n must fit int: refused before any buffer is touched */
    assert_int_equal(vlbe_eig_quad(INT_MAX / 2 + 1, M, D, K, VLBE_R(0.0), o.sr, o.si, 4, o.Xr, o.Xi,
                                   w, 200, iw, 8),
                     VLBE_EARG);
    untouched(4, o.sr);
    untouched(4, o.si);
    untouched(8, o.Xr);
    untouched(8, o.Xi);
    /* M singular: an infinite eigenvalue, mu = 0 */
    {
        vlbe_real Ms[4] = {1, 0, 0, 0};
        const vlbe_status st = vlbe_eig_quad(2, Ms, NULL, K, VLBE_R(0.0), o.sr, o.si, 4, o.Xr, o.Xi,
                                             w, 200, iw, 8);
        assert_int_equal(st, VLBE_ENONFINITE);
        untouched(4, o.sr);
    }
    /* Xre, Xim NULL: the same eigenvalues */
    {
        vlbe_real sr[4], si[4];
        int i;
        assert_int_equal(vlbe_eig_quad(2, M, D, K, VLBE_R(0.0), o.sr, o.si, 4, o.Xr, o.Xi, w, 200,
                                       iw,
                                       8),
                         VLBE_OK);
        assert_int_equal(vlbe_eig_quad(2, M, D, K, VLBE_R(0.0), sr, si, 0, NULL, NULL, w, 200, iw,
                                       8),
                         VLBE_OK);
        for (i = 0; i < 4; ++i) assert_true(sr[i] == o.sr[i] && si[i] == o.si[i]);
        /* the vectors of the first nvec = 2 only (n x 2, ld 2): the
           leading columns of all four, bit for bit (the same iteration) */
        {
            vlbe_real xr[4], xi[4];
            int r, c;
            assert_int_equal(vlbe_eig_quad(2, M, D, K, VLBE_R(0.0), sr, si, 2, xr, xi, w, 200, iw,
                                           8),
                             VLBE_OK);
            for (r = 0; r < 2; ++r)
                for (c = 0; c < 2; ++c)
                    assert_true(xr[2 * r + c] == o.Xr[4 * r + c] &&
                                xi[2 * r + c] == o.Xi[4 * r + c]);
        }
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_work_len),
        cmocka_unit_test(test_sym_random),
        cmocka_unit_test(test_eig_known),
        cmocka_unit_test(test_gsym_chain),
        cmocka_unit_test(test_gsym_graded),
        cmocka_unit_test(test_real_companion),
        cmocka_unit_test(test_real_similarity),
        cmocka_unit_test(test_real_2x2),
        cmocka_unit_test(test_quad_undamped),
        cmocka_unit_test(test_quad_rotor),
        cmocka_unit_test(test_quad_damped),
        cmocka_unit_test(test_quad_random),
        cmocka_unit_test(test_quad_graded),
        cmocka_unit_test(test_fail_sym_gsym),
        cmocka_unit_test(test_fail_real),
        cmocka_unit_test(test_fail_quad),
    };
    return cmocka_run_group_tests_name("eig", tests, NULL, NULL);
}
