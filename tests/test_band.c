/* test_band.c -- cmocka suite of the band matrices of vlbe.h: banded LU
   (factor, solve), band matrix-vector products
   -- part of vlbe                                 SPDX-License-Identifier: MIT

   Build and run from the repository root (add -DVLBE_USE_FLOAT for the
   float build; the same source passes in both precisions):
       cc -std=c99 -Wall -Wextra -Wpedantic -O2 tests/test_band.c -o test_band -lcmocka -lm
       ./test_band

   The reference is the dense LU of vlbe.h (tests/test_vlbe.c) on the full
   matrix: with partial pivoting the band elimination performs the same
   operations on the entries inside the band and skips only zeros, so
   pivots, U, the multipliers (up to the row order of L) and solutions must
   agree bit for bit (tolerance 0; both run in the same build, with the
   compiler's default of no FMA contraction under -std=c99).  Independent of
   that, residuals are checked against the backward-error bound of partial
   pivoting (check_residual).  Every band array holds NaN in the slots
   outside the matrix (a read of one shows up as a NaN or a failed call).
   Tolerances are multiples of VLBE_EPS; references in double (long double
   for residuals).  VLBE_TEST_REPORT=1 prints the worst measured ratios.

   Groups: factor and solve against the dense LU | residuals | singular and
   non-finite input | in place | products | arguments, flops. */
#include "test_util.h"
#include "../vlbe.h"
#include "fixtures_common.h"

#include <string.h>

#define EPS ((double)VLBE_EPS)
#define ARRAY_LEN(a) ((int)(sizeof(a) / sizeof((a)[0])))
#define SENTINEL 0xA5

static vlbe_real *alloc_real(size_t n) { return (vlbe_real *)test_malloc(n * sizeof(vlbe_real)); }
static int *alloc_int(size_t n) { return (int *)test_malloc(n * sizeof(int)); }

static int imin(int a, int b) { return a < b ? a : b; }
static int imax(int a, int b) { return a > b ? a : b; }

/* 1 if (i, j) is inside the n x n matrix and the band kl, ku */
static int in_band(int n, int kl, int ku, int i, int j)
{
    return j >= 0 && j < n && j >= i - kl && j <= i + ku;
}

/* A band matrix (n, kl, ku, lda): entries uniform[-1, 1) off the
   diagonal; on it, with dscale < 1, a random sign times [dscale/2, dscale)
   (the diagonal is then rarely the largest entry of its column, so partial
   pivoting swaps rows at most steps), with dscale > 1, dscale + uniform
   (above kl + ku + 1: diagonally dominant by columns, which elimination
   preserves, so no row is ever swapped).  Every slot outside the matrix
   and beyond kl + ku + 1 in a row is NaN. */
static void band_random(tu_rng *g, int n, int kl, int ku, int lda, double dscale, vlbe_real *A)
{
    int i, s;
    for (i = 0; i < n; ++i)
        for (s = 0; s < lda; ++s) {
            const int j = i - kl + s;
            double v = (double)NAN;
            if (s <= kl + ku && in_band(n, kl, ku, i, j))
                v = i != j ? tu_rng_uniform(g)
                    : dscale < 1.0 ? dscale * (0.5 + 0.25 * (1.0 + tu_rng_uniform(g))) *
                                         (tu_rng_uniform(g) < 0.0 ? -1.0 : 1.0)
                                   : dscale + tu_rng_uniform(g);
            A[(size_t)i * (size_t)lda + (size_t)s] = (vlbe_real)v;
        }
}

/* D = the full n x n matrix of band A */
static void band_to_dense(int n, int kl, int ku, const vlbe_real *A, int lda, vlbe_real *D)
{
    int i, j;
    for (i = 0; i < n; ++i)
        for (j = 0; j < n; ++j)
            D[i * n + j] = in_band(n, kl, ku, i, j) ? A[VLBE_BAND_IDX(lda, kl, i, j)] : 0;
}

/* B = D X rounded to working precision; D n x n, X and B n x nrhs */
static void mat_mul_ref(int n, int nrhs, const vlbe_real *D, const vlbe_real *X, vlbe_real *B)
{
    int i, j, r;
    for (i = 0; i < n; ++i)
        for (r = 0; r < nrhs; ++r) {
            long double s = 0.0L;
            for (j = 0; j < n; ++j)
                s += (long double)D[i * n + j] * (long double)X[j * nrhs + r];
            B[i * nrhs + r] = (vlbe_real)s;
        }
}

/* Normwise backward error of column r of X: ||D x - b||_inf <= 10 w eps
   ||D||_inf ||x||_inf, w = min(n, kl + ku + 1).  Partial pivoting gives
   (D + dD) x = b with |dD| <= gamma_{3m} |L||U| (Higham, Accuracy and
   Stability, thm. 9.4), m the length of the longest inner product, at most
   kl + ku + 1 in a band factor; || |L||U| || is a small multiple of ||D||
   for these random matrices (the largest growth max|U| / max|A| is
   5.3 (m:band_growth)).  The residual is summed in long double so that its
   own rounding stays below the bound. */
static double res_worst; /* worst residual / (w eps ||D|| ||x||) */

static void check_residual(int n, int kl, int ku, int nrhs, int r, const vlbe_real *D,
                           const vlbe_real *X, const vlbe_real *B)
{
    const int w = imin(n, kl + ku + 1);
    double scale, res = lu_residual(n, nrhs, r, D, X, B, &scale);
    ASSERT_CLOSE_CTX(res, 0.0, 0, 10.0 * w * EPS * scale, "n %d kl %d ku %d, right-hand side %d",
                     n, kl, ku, r);
    if (scale > 0.0) res_worst = fmax(res_worst, res / (w * EPS * scale));
}

/* ======================================================================= */
/* factor and solve against the dense LU                                   */
/* ======================================================================= */

typedef struct band_case {
    int n, kl, ku;
} band_case;

/* kl != ku both ways, kl = 0 (no pivoting possible), ku = 0, n = 1, a band
   of width n - 1 (the full matrix), kl and ku beyond n - 1, chains of the
   half-bandwidths of the planar (7) and 3D (13) cables */
static const band_case cases[] = {
    {1, 0, 0},  {1, 2, 3},   {2, 1, 0},   {2, 0, 1},   {3, 5, 4},   {5, 0, 2},
    {6, 2, 0},  {8, 1, 1},   {12, 3, 1},  {12, 1, 3},  {9, 8, 8},   {16, 15, 15},
    {16, 15, 2}, {16, 2, 15}, {20, 2, 5}, {40, 7, 7},  {60, 13, 13}, {200, 7, 7},
};

static double growth_worst; /* max|U| / max|A| over the random cases */

/* The band factor of A (n, kl, ku; lda = kl + ku + 1, out of place) and
   the dense factor of the full matrix D: status OK, A untouched, the same
   pivots (with swaps when kl > 0), U bitwise equal and zero beyond
   kl + ku super-diagonals in the dense factor, the band multipliers equal
   to the dense L after the later row swaps; then the solutions of nrhs
   right-hand sides bitwise equal, one column alone equal to the block, and
   the residual bound.  Pivoting (dscale < 1): swaps at a quarter of the
   steps at least when kl > 0; dominant (dscale > kl + ku + 1): none.  The
   growth stays below the documented bound 2^(s+1), s = min(n-1, kl+ku). */
static void check_vs_dense(tu_rng *g, int n, int kl, int ku, double dscale, int nrhs)
{
    const int lda = kl + ku + 1;
    const size_t ld = vlbe_band_lu_ld(kl, ku), N = (size_t)n, nb = N * (size_t)nrhs;
    vlbe_real *A = alloc_real(N * (size_t)lda), *A0 = alloc_real(N * (size_t)lda);
    vlbe_real *LU = alloc_real(N * ld), *D = alloc_real(N * N), *DLU = alloc_real(N * N);
    vlbe_real *X = alloc_real(nb), *B = alloc_real(nb), *Y = alloc_real(nb);
    vlbe_real *x1 = alloc_real(N), *m = alloc_real(N);
    int *piv = alloc_int(N), *dpiv = alloc_int(N);
    int info = -7, dinfo = -7, i, j, k, r, swaps = 0;
    double amax = 0.0, umax = 0.0;
    assert_int_equal(ld, (size_t)(2 * kl + ku + 1));
    band_random(g, n, kl, ku, lda, dscale, A);
    memcpy(A0, A, N * (size_t)lda * sizeof(vlbe_real));
    band_to_dense(n, kl, ku, A, lda, D);
    for (i = 0; i < n * n; ++i) amax = fmax(amax, fabs((double)D[i]));
    memset(LU, SENTINEL, N * ld * sizeof(vlbe_real));
    assert_int_equal(vlbe_band_lu_factor(n, kl, ku, A, lda, LU, piv, &info), VLBE_OK);
    assert_int_equal(info, 0);
    assert_memory_equal(A, A0, N * (size_t)lda * sizeof(vlbe_real)); /* NaN slots too */
    assert_int_equal(vlbe_lu_factor(n, D, DLU, dpiv, &dinfo), VLBE_OK);
    for (k = 0; k < n; ++k) {
        assert_int_equal(piv[k], dpiv[k]);
        assert_true(piv[k] >= k && piv[k] <= imin(n - 1, k + kl));
        swaps += piv[k] != k;
    }
    if (dscale > 1.0) assert_int_equal(swaps, 0);
    else if (kl > 0 && n >= 4) assert_true(swaps >= n / 4);
    for (i = 0; i < n; ++i) /* U: bitwise, and no entry beyond i + kl + ku */
        for (j = i; j < n; ++j) {
            if (j <= i + kl + ku) {
                ASSERT_CLOSE_CTX(LU[VLBE_BAND_IDX(ld, kl, i, j)], DLU[i * n + j], 0, 0,
                                 "U(%d, %d), n %d kl %d ku %d", i, j, n, kl, ku);
                umax = fmax(umax, fabs((double)DLU[i * n + j]));
            } else {
                ASSERT_CLOSE_CTX(DLU[i * n + j], 0.0, 0, 0, "dense U(%d, %d) off the band", i, j);
            }
        }
    /* multipliers of step k: rows k+1 .. k+kl at that step; the dense L is
       that of P A, so the later swaps move them: apply those, compare the
       whole column (zeros included) */
    for (k = 0; k < n; ++k) {
        for (i = 0; i < n; ++i)
            m[i] = i > k && i <= k + kl ? LU[VLBE_BAND_IDX(ld, kl, i, k)] : VLBE_R(0.0);
        for (j = k + 1; j < n; ++j) {
            const vlbe_real t = m[j];
            m[j] = m[piv[j]];
            m[piv[j]] = t;
        }
        for (i = k + 1; i < n; ++i)
            ASSERT_CLOSE_CTX(m[i], DLU[i * n + k], 0, 0, "L(%d, %d), n %d kl %d ku %d", i, k, n,
                             kl, ku);
    }
    assert_true(umax <= ldexp(amax, imin(n - 1, kl + ku) + 1));
    growth_worst = fmax(growth_worst, umax / amax);
    /* solutions */
    for (i = 0; i < (int)nb; ++i) X[i] = (vlbe_real)tu_rng_uniform(g);
    mat_mul_ref(n, nrhs, D, X, B);
    memcpy(X, B, nb * sizeof(vlbe_real));
    memcpy(Y, B, nb * sizeof(vlbe_real));
    vlbe_band_lu_solve(n, kl, ku, LU, piv, nrhs, X);
    vlbe_lu_solve(n, DLU, dpiv, nrhs, Y);
    ASSERT_VEC_CLOSE(X, Y, (int)nb, 0, 0); /* the same operations */
    for (r = 0; r < nrhs; ++r) {
        check_residual(n, kl, ku, nrhs, r, D, X, B);
        for (i = 0; i < n; ++i) x1[i] = B[i * nrhs + r];
        vlbe_band_lu_solve(n, kl, ku, LU, piv, 1, x1);
        for (i = 0; i < n; ++i) ASSERT_CLOSE(x1[i], X[i * nrhs + r], 0, 0); /* column by column */
    }
    test_free(dpiv);
    test_free(piv);
    test_free(m);
    test_free(x1);
    test_free(Y);
    test_free(B);
    test_free(X);
    test_free(DLU);
    test_free(D);
    test_free(LU);
    test_free(A0);
    test_free(A);
}

/* small diagonal: interchanges at most steps.  kl = 0: no choice of
   pivot, the diagonal kept away from 0; ku = 0: the determinant is the
   product of the diagonal, so a diagonal of 1e-2 would make the matrix
   nearly singular: 0.5 keeps it regular and still below most
   sub-diagonal entries. */
static void test_band_vs_dense_pivoting(void **state)
{
    tu_rng g = tu_rng_seed(4242);
    int c, t;
    (void)state;
    res_worst = growth_worst = 0.0;
    for (c = 0; c < ARRAY_LEN(cases); ++c)
        for (t = 0; t < 3; ++t) {
            const band_case *bc = &cases[c];
            const double d = bc->kl == 0 ? 2.0 : bc->ku == 0 ? 0.5 : 1e-2;
            check_vs_dense(&g, bc->n, bc->kl, bc->ku, d, 1 + 2 * t);
        }
    tu_report("band LU, pivoting: residual in w eps ||A|| ||x||", res_worst, 10.0);
    tu_measured("band_growth", growth_worst);
}

/* diagonally dominant: no interchange, U keeps ku super-diagonals */
static void test_band_vs_dense_dominant(void **state)
{
    tu_rng g = tu_rng_seed(99);
    int c;
    (void)state;
    res_worst = 0.0;
    for (c = 0; c < ARRAY_LEN(cases); ++c) {
        const band_case *bc = &cases[c];
        check_vs_dense(&g, bc->n, bc->kl, bc->ku, bc->kl + bc->ku + 2.0, 2);
    }
    tu_report("band LU, dominant: residual in w eps ||A|| ||x||", res_worst, 10.0);
}

/* ======================================================================= */
/* singular and non-finite input                                           */
/* ======================================================================= */

/* VLBE_ESINGULAR with *info = want (the dense LU's too), A untouched, info
   may be NULL */
static void check_singular(int n, int kl, int ku, const vlbe_real *A, int want)
{
    const int lda = kl + ku + 1;
    const size_t ld = vlbe_band_lu_ld(kl, ku), na = (size_t)n * (size_t)lda;
    vlbe_real *A0 = alloc_real(na), *LU = alloc_real((size_t)n * ld);
    vlbe_real *D = alloc_real((size_t)(n * n)), *DLU = alloc_real((size_t)(n * n));
    int *piv = alloc_int((size_t)n), info = -7, dinfo = -7;
    memcpy(A0, A, na * sizeof(vlbe_real));
    assert_int_equal(vlbe_band_lu_factor(n, kl, ku, A, lda, LU, piv, &info), VLBE_ESINGULAR);
    assert_int_equal(info, want);
    assert_memory_equal(A, A0, na * sizeof(vlbe_real));
    band_to_dense(n, kl, ku, A, lda, D);
    assert_int_equal(vlbe_lu_factor(n, D, DLU, piv, &dinfo), VLBE_ESINGULAR);
    assert_int_equal(dinfo, want);
    assert_int_equal(vlbe_band_lu_factor(n, kl, ku, A, lda, LU, piv, NULL), VLBE_ESINGULAR);
    test_free(piv);
    test_free(DLU);
    test_free(D);
    test_free(LU);
    test_free(A0);
}

static void test_band_singular(void **state)
{
    static const band_case sc[] = {{6, 2, 1}, {10, 1, 3}, {10, 3, 0}, {12, 0, 2}, {9, 8, 8}};
    tu_rng g = tu_rng_seed(2024);
    vlbe_real A[12 * 4], R[4];
    int s, c, i;
    (void)state;
    for (s = 0; s < ARRAY_LEN(sc); ++s) {
        const int n = sc[s].n, kl = sc[s].kl, ku = sc[s].ku, lda = kl + ku + 1;
        vlbe_real *B = alloc_real((size_t)(n * lda));
        for (c = 0; c < n; ++c) {
            /* zero column c inside the band: it stays zero through the
               elimination (every update of it subtracts l * 0), the first
               zero pivot is at step c */
            band_random(&g, n, kl, ku, lda, 1e-2, B);
            for (i = imax(0, c - ku); i <= imin(n - 1, c + kl); ++i)
                B[VLBE_BAND_IDX(lda, kl, i, c)] = VLBE_R(0.0);
            check_singular(n, kl, ku, B, c + 1);
        }
        test_free(B);
    }
    /* the zero matrix; the 1 x 1 zero */
    for (i = 0; i < 12 * 4; ++i) A[i] = VLBE_R(0.0);
    check_singular(12, 1, 2, A, 1);
    check_singular(1, 0, 0, A, 1);
    /* [[1, 1], [1, 1 + d]] (kl = ku = 1): the second pivot d is relatively
       zero for d = eps <= 2 eps (1 + eps) = n eps max|A|, not for 4 eps;
       slot 0 (column -1) and slot 5 (column 2) lie outside: NaN */
    R[0] = 1, R[1] = 1;
    A[0] = (vlbe_real)NAN, A[1] = 1, A[2] = 1, A[3] = 1, A[4] = 1 + VLBE_EPS, A[5] = (vlbe_real)NAN;
    check_singular(2, 1, 1, A, 2);
    A[4] = 1 + 4 * VLBE_EPS;
    {
        vlbe_real LU[8];
        int piv[2], info = -7;
        assert_int_equal(vlbe_band_lu_factor(2, 1, 1, A, 3, LU, piv, &info), VLBE_OK);
        assert_int_equal(info, 0);
        vlbe_band_lu_solve(2, 1, 1, LU, piv, 1, R); /* x = (1, 0) exactly */
        ASSERT_CLOSE(R[0], 1.0, 0, 0);
        ASSERT_CLOSE(R[1], 0.0, 0, 0);
        /* the test is relative to max|A|: scaled by 2^-40 (exact), 4 eps is
           still accepted and eps still rejected */
        for (i = 1; i <= 4; ++i) A[i] = (vlbe_real)ldexp((double)A[i], -40);
        assert_int_equal(vlbe_band_lu_factor(2, 1, 1, A, 3, LU, piv, &info), VLBE_OK);
        A[4] = (vlbe_real)ldexp(1.0 + EPS, -40);
        check_singular(2, 1, 1, A, 2);
    }
}

/* NaN or +-Inf anywhere inside the band: VLBE_ENONFINITE before anything is
   written (LU, piv, *info keep their sentinels, A untouched), in place too. */
static void test_band_nonfinite(void **state)
{
    enum { N = 7, KL = 2, KU = 3, LDA = KL + KU + 1, LD = 2 * KL + KU + 1 };
    const vlbe_real bad[3] = {(vlbe_real)NAN, (vlbe_real)INFINITY, -(vlbe_real)INFINITY};
    vlbe_real A[N * LD], A0[N * LD], LU[N * LD], LU0[N * LD];
    int piv[N], piv0[N], info, b, i, j, hits = 0;
    tu_rng g = tu_rng_seed(5);
    (void)state;
    memset(LU0, SENTINEL, sizeof LU0);
    memset(piv0, SENTINEL, sizeof piv0);
    for (b = 0; b < 3; ++b)
        for (i = 0; i < N; ++i)
            for (j = imax(0, i - KL); j <= imin(N - 1, i + KU); ++j) {
                band_random(&g, N, KL, KU, LDA, 1.0, A);
                A[VLBE_BAND_IDX(LDA, KL, i, j)] = bad[b];
                memcpy(A0, A, sizeof(vlbe_real) * N * LDA);
                memcpy(LU, LU0, sizeof LU);
                memcpy(piv, piv0, sizeof piv);
                info = -7;
                assert_int_equal(vlbe_band_lu_factor(N, KL, KU, A, LDA, LU, piv, &info),
                                 VLBE_ENONFINITE);
                assert_int_equal(info, -7);
                assert_memory_equal(LU, LU0, sizeof LU);
                assert_memory_equal(piv, piv0, sizeof piv);
                assert_memory_equal(A, A0, sizeof(vlbe_real) * N * LDA);
                /* in place, lda = ld: nothing written either */
                band_random(&g, N, KL, KU, LD, 1.0, A);
                A[VLBE_BAND_IDX(LD, KL, i, j)] = bad[b];
                memcpy(A0, A, sizeof A);
                assert_int_equal(vlbe_band_lu_factor(N, KL, KU, A, LD, A, piv, &info),
                                 VLBE_ENONFINITE);
                assert_int_equal(info, -7);
                assert_memory_equal(A, A0, sizeof A);
                assert_memory_equal(piv, piv0, sizeof piv);
                ++hits;
            }
    assert_int_equal(hits, 3 * (N * (KL + KU + 1) - KL * (KL + 1) / 2 - KU * (KU + 1) / 2));
}

/* Overflow: [[M, M], [-M, M]] gives U22 = 2M = Inf, caught at the pivot;
   an overflow off the pivots (U(1, 2) = M + M with U(1, 1) finite and
   l21 = 0, the 3 x 3 of test_contract_core) by the final scan.  Near the
   limit without overflow the scan runs and must pass: a random band
   scaled to max|A| ~ VLBE_REAL_MAX / 8 (< 2^(s+1) = 2^5 below the limit)
   gives the dense factor bitwise, the NaN slots outside the matrix
   ignored by the scan. */
static void test_band_overflow(void **state)
{
    const vlbe_real M = VLBE_REAL_MAX / VLBE_R(1.5);
    vlbe_real A[5 * 5], LU[5 * 7], D[25], DLU[25];
    int piv[5], dpiv[5], info = -7, i, j;
    tu_rng g = tu_rng_seed(77);
    (void)state;
    /* n = 2, kl = ku = 1: slots 0 and 5 are outside */
    A[0] = (vlbe_real)NAN, A[1] = M, A[2] = M, A[3] = -M, A[4] = M, A[5] = (vlbe_real)NAN;
    assert_int_equal(vlbe_band_lu_factor(2, 1, 1, A, 3, LU, piv, &info), VLBE_ENONFINITE);
    assert_int_equal(info, -7);
    /* n = 3, kl = ku = 2 (full): rows M M/4 M | -M M/4 M | 0 0 M */
    for (i = 0; i < 15; ++i) A[i] = (vlbe_real)NAN;
    A[2] = M, A[3] = M / VLBE_R(4.0), A[4] = M;
    A[6] = -M, A[7] = M / VLBE_R(4.0), A[8] = M;
    A[10] = VLBE_R(0.0), A[11] = VLBE_R(0.0), A[12] = M;
    assert_int_equal(vlbe_band_lu_factor(3, 2, 2, A, 5, LU, piv, &info), VLBE_ENONFINITE);
    assert_int_equal(info, -7);
    /* large but no overflow: n = 5, kl = ku = 2 */
    band_random(&g, 5, 2, 2, 5, 1e-2, A);
    for (i = 0; i < 25; ++i)
        if (A[i] == A[i]) A[i] *= VLBE_REAL_MAX / VLBE_R(8.0);
    band_to_dense(5, 2, 2, A, 5, D);
    assert_int_equal(vlbe_band_lu_factor(5, 2, 2, A, 5, LU, piv, &info), VLBE_OK);
    assert_int_equal(vlbe_lu_factor(5, D, DLU, dpiv, &info), VLBE_OK);
    for (i = 0; i < 5; ++i) {
        assert_int_equal(piv[i], dpiv[i]);
        for (j = i; j < 5; ++j) ASSERT_CLOSE(LU[VLBE_BAND_IDX(7, 2, i, j)], DLU[i * 5 + j], 0, 0);
    }
}

/* ======================================================================= */
/* in place                                                                */
/* ======================================================================= */

/* LU == A (lda = ld): the factor equals the out-of-place one bit for bit,
   the fill slots of the input (NaN here, "ignored on input") are zeroed
   where they lie inside the matrix, the pivots agree; singular in place is
   still reported. */
static void test_band_in_place(void **state)
{
    static const band_case ic[] = {{1, 0, 0}, {7, 0, 3}, {10, 3, 2}, {30, 7, 7}, {9, 8, 8}};
    tu_rng g = tu_rng_seed(31);
    int c;
    (void)state;
    for (c = 0; c < ARRAY_LEN(ic); ++c) {
        const int n = ic[c].n, kl = ic[c].kl, ku = ic[c].ku;
        const size_t ld = vlbe_band_lu_ld(kl, ku), N = (size_t)n;
        vlbe_real *A = alloc_real(N * ld), *X = alloc_real(N * ld), *LU = alloc_real(N * ld);
        int *piv = alloc_int(N), *piv2 = alloc_int(N), info = -7, i, s;
        band_random(&g, n, kl, ku, (int)ld, 1e-2, A); /* the fill slots are NaN */
        memcpy(X, A, N * ld * sizeof(vlbe_real));
        memcpy(LU, A, N * ld * sizeof(vlbe_real)); /* the same outside the matrix */
        assert_int_equal(vlbe_band_lu_factor(n, kl, ku, A, (int)ld, LU, piv, &info), VLBE_OK);
        assert_int_equal(vlbe_band_lu_factor(n, kl, ku, X, (int)ld, X, piv2, &info), VLBE_OK);
        assert_int_equal(info, 0);
        assert_memory_equal(piv, piv2, N * sizeof(int));
        for (i = 0; i < n; ++i)
            for (s = 0; s < (int)ld; ++s) {
                const int j = i - kl + s, inside = j >= 0 && j < n;
                const vlbe_real v = X[(size_t)i * ld + (size_t)s];
                if (inside) { /* every slot inside is written: no NaN left */
                    ASSERT_CLOSE_CTX(v, LU[(size_t)i * ld + (size_t)s], 0, 0, "slot (%d, %d)", i,
                                     s);
                } else { /* outside: never written */
                    assert_true(v != v);
                }
            }
        /* singular in place: zero column 0 */
        band_random(&g, n, kl, ku, (int)ld, 1e-2, X);
        for (i = 0; i <= imin(n - 1, kl); ++i) X[VLBE_BAND_IDX(ld, kl, i, 0)] = VLBE_R(0.0);
        info = -7;
        assert_int_equal(vlbe_band_lu_factor(n, kl, ku, X, (int)ld, X, piv2, &info),
                         VLBE_ESINGULAR);
        assert_int_equal(info, 1);
        test_free(piv2);
        test_free(piv);
        test_free(LU);
        test_free(X);
        test_free(A);
    }
}

/* ======================================================================= */
/* products                                                                */
/* ======================================================================= */

/* y = A x and y = A^T x: bitwise those of vlbe_mat_vec / vlbe_mat_tvec on
   the full matrix for finite x (the same sums in the same order, the zero
   terms skipped: adding a zero product leaves a sum unchanged), and within
   the rounding bound of a w-term sum of the exact value: |y - y_exact| <=
   w eps sum |a_ij x_j| (gamma_w <= w u / (1 - w u), u = eps / 2), w =
   min(n, kl + ku + 1) terms, reference in long double.  lda above
   kl + ku + 1 with NaN padding, the slots outside NaN: never read. */
static void test_band_mat_vec(void **state)
{
    static const band_case pc[] = {{1, 0, 0}, {1, 3, 2}, {5, 0, 0}, {6, 2, 0}, {6, 0, 2},
                                   {11, 3, 1}, {11, 1, 3}, {9, 8, 8}, {4, 6, 5}, {50, 7, 13}};
    tu_rng g = tu_rng_seed(8);
    double worst = 0.0;
    int c, pad;
    (void)state;
    for (c = 0; c < ARRAY_LEN(pc); ++c)
        for (pad = 0; pad <= 2; pad += 2) {
            const int n = pc[c].n, kl = pc[c].kl, ku = pc[c].ku, lda = kl + ku + 1 + pad;
            const int w = imin(n, kl + ku + 1);
            const size_t N = (size_t)n;
            vlbe_real *A = alloc_real(N * (size_t)lda), *D = alloc_real(N * N);
            vlbe_real *x = alloc_real(N), *y = alloc_real(N), *yd = alloc_real(N);
            int i, j, t;
            band_random(&g, n, kl, ku, lda, 1.0, A);
            band_to_dense(n, kl, ku, A, lda, D);
            for (i = 0; i < n; ++i) x[i] = (vlbe_real)tu_rng_uniform(&g);
            for (t = 0; t < 2; ++t) {
                for (i = 0; i < n; ++i) y[i] = (vlbe_real)NAN; /* overwritten, not added to */
                if (t == 0) {
                    vlbe_band_mat_vec(n, kl, ku, A, lda, x, y);
                    vlbe_mat_vec(n, n, D, x, yd);
                } else {
                    vlbe_band_mat_tvec(n, kl, ku, A, lda, x, y);
                    vlbe_mat_tvec(n, n, D, x, yd);
                }
                ASSERT_VEC_CLOSE(y, yd, n, 0, 0);
                for (i = 0; i < n; ++i) {
                    long double s = 0.0L, sa = 0.0L;
                    for (j = 0; j < n; ++j) {
                        const long double a = (long double)(t == 0 ? D[i * n + j] : D[j * n + i]);
                        s += a * (long double)x[j];
                        sa += fabsl(a * (long double)x[j]);
                    }
                    ASSERT_CLOSE_CTX(y[i], (double)s, 0, w * EPS * (double)sa,
                                     "n %d kl %d ku %d row %d, %s", n, kl, ku, i,
                                     t ? "A^T x" : "A x");
                    if (sa > 0.0L)
                        worst = fmax(worst, fabs((double)y[i] - (double)s) /
                                                (w * EPS * (double)sa));
                }
            }
            test_free(yd);
            test_free(y);
            test_free(x);
            test_free(D);
            test_free(A);
        }
    tu_report("band products: error in w eps sum |a x|", worst, 1.0);
}

/* ======================================================================= */
/* arguments, flops                                                        */
/* ======================================================================= */

/* VLBE_EARG, nothing written: n < 1, kl < 0, ku < 0, lda < kl + ku + 1,
   in place with lda != ld */
static void test_band_args(void **state)
{
    vlbe_real A[4 * 8], LU[4 * 8], LU0[4 * 8], A0[4 * 8];
    int piv[4], piv0[4], info = -7;
    tu_rng g = tu_rng_seed(3);
    (void)state;
    band_random(&g, 4, 1, 1, 8, 1.0, A);
    memcpy(A0, A, sizeof A);
    memset(LU, SENTINEL, sizeof LU);
    memset(piv, SENTINEL, sizeof piv);
    memcpy(LU0, LU, sizeof LU);
    memcpy(piv0, piv, sizeof piv);
    assert_int_equal(vlbe_band_lu_factor(0, 1, 1, A, 3, LU, piv, &info), VLBE_EARG);
    assert_int_equal(vlbe_band_lu_factor(-3, 1, 1, A, 3, LU, piv, &info), VLBE_EARG);
    assert_int_equal(vlbe_band_lu_factor(4, -1, 1, A, 3, LU, piv, &info), VLBE_EARG);
    assert_int_equal(vlbe_band_lu_factor(4, 1, -1, A, 3, LU, piv, &info), VLBE_EARG);
    assert_int_equal(vlbe_band_lu_factor(4, 1, 1, A, 2, LU, piv, &info), VLBE_EARG);
    assert_int_equal(vlbe_band_lu_factor(4, 1, 1, A, 0, LU, piv, &info), VLBE_EARG);
    assert_int_equal(vlbe_band_lu_factor(4, 1, 1, A, -5, LU, piv, &info), VLBE_EARG);
    assert_int_equal(vlbe_band_lu_factor(4, 2, 3, A, 5, LU, piv, &info), VLBE_EARG);
    assert_int_equal(vlbe_band_lu_factor(4, 0, 0, A, 0, LU, piv, &info), VLBE_EARG);
    /* in place needs lda = ld = 2 kl + ku + 1 = 4 */
    assert_int_equal(vlbe_band_lu_factor(4, 1, 1, A, 3, A, piv, &info), VLBE_EARG);
    assert_int_equal(vlbe_band_lu_factor(4, 1, 1, A, 8, A, piv, &info), VLBE_EARG);
    assert_int_equal(info, -7);
    assert_memory_equal(A, A0, sizeof A);
    assert_memory_equal(LU, LU0, sizeof LU);
    assert_memory_equal(piv, piv0, sizeof piv);
    /* lda above the minimum is fine out of place */
    assert_int_equal(vlbe_band_lu_factor(4, 1, 1, A, 8, LU, piv, &info), VLBE_OK);
}

static void test_band_ld_flops(void **state)
{
    int n;
    (void)state;
    assert_int_equal(vlbe_band_lu_ld(0, 0), 1);
    assert_int_equal(vlbe_band_lu_ld(2, 3), 8);
    assert_int_equal(vlbe_band_lu_ld(7, 7), 22);
    /* sum over t = n-1-k of min(kl, t) (2 min(ku, t) + 1), integers: exact */
    ASSERT_CLOSE(vlbe_band_lu_flops(1, 0, 0), 0.0, 0, 0);
    ASSERT_CLOSE(vlbe_band_lu_flops(1, 3, 3), 0.0, 0, 0);
    ASSERT_CLOSE(vlbe_band_lu_flops(100, 0, 5), 0.0, 0, 0);
    ASSERT_CLOSE(vlbe_band_lu_flops(2, 1, 0), 1.0, 0, 0);
    /* 0 + 3 + 10 + 7 * 14 */
    ASSERT_CLOSE(vlbe_band_lu_flops(10, 2, 3), 111.0, 0, 0);
    /* ku = 0: 0 + 1 + 2 (n - 2) */
    ASSERT_CLOSE(vlbe_band_lu_flops(10, 2, 0), 17.0, 0, 0);
    /* full band: sum_t t (2t + 1) = (n-1) n (2n-1) / 3 + n (n-1) / 2, for
       kl, ku = n - 1 and beyond */
    for (n = 1; n <= 40; n += 13) {
        const double f = (double)(n - 1) * n * (2 * n - 1) / 3.0 + (double)n * (n - 1) / 2.0;
        ASSERT_CLOSE(vlbe_band_lu_flops(n, n - 1, n - 1), f, 0, 0);
        ASSERT_CLOSE(vlbe_band_lu_flops(n, n + 5, n + 2), f, 0, 0);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_band_vs_dense_pivoting),
        cmocka_unit_test(test_band_vs_dense_dominant),
        cmocka_unit_test(test_band_singular),
        cmocka_unit_test(test_band_nonfinite),
        cmocka_unit_test(test_band_overflow),
        cmocka_unit_test(test_band_in_place),
        cmocka_unit_test(test_band_mat_vec),
        cmocka_unit_test(test_band_args),
        cmocka_unit_test(test_band_ld_flops),
    };
    return cmocka_run_group_tests_name("band", tests, NULL, NULL);
}
