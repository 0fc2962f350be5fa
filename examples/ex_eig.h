/* ex_eig.h -- real symmetric eigenproblems for the examples, tests and
   benchmarks: the standard problem A x = lam x by the cyclic Jacobi method,
   and the generalized symmetric-definite problem A x = lam B x (B positive
   definite: a mass matrix, or a stiffness matrix with the rigid modes
   removed) by a Cholesky factor B = L L^T and Jacobi on L^-1 A L^-T.
   -- part of vlbe                                  SPDX-License-Identifier: MIT

   Examples include it with #include "ex_eig.h" (it sits beside them), so
   `cc -O2 examples/x.c -lm` still works from anywhere.  Like the headers it
   allocates nothing: the caller passes a workspace of ex_eig_work_len(n)
   vlbe_real.  It computes in vlbe_real (float with -DVLBE_USE_FLOAT).

   int n; const vlbe_real *A, *B;        n x n, row-major, symmetric (both
                                          triangles are read; A is used as
                                          (A + A^T)/2)
   vlbe_real lam[n], X[n*n], *w = malloc(ex_eig_work_len(n) * sizeof *w);
   int info;
   if (ex_eig_gsym(n, A, B, lam, X, &info, w, ex_eig_work_len(n)) != VLBE_OK) ...

   Results: lam ascending; X (may be NULL) holds the eigenvectors as
   columns, X[i*n + k] = component i of the vector of lam[k], normalised
   to X^T B X = I (X^T X = I for ex_eig_sym).
   Accuracy: each eigenvalue to a few EPS times the largest |lam| (of the
   reduced matrix).  For the LOWEST modes of a stiff structure solve
   M x = (1/w^2) K x (A = M, B = K, rigid modes removed), so that they are
   the largest eigenvalues (examples/corot_static.c: 1e4 times more
   accurate for the fundamental than K x = w^2 M x).

   Status (a failed call writes nothing to lam, X):
     VLBE_EARG       n < 1, or n > 46340 (n*n must fit an int)
     VLBE_EWORK      lw < ex_eig_work_len(n)
     VLBE_ENONFINITE NaN or Inf in A or B
     VLBE_ESINGULAR  B is not positive definite: a Cholesky pivot
                     B_jj - sum_k L_jk^2 is not above n EPS B_jj (zero,
                     negative, or zero within the rounding of the sum; the
                     LU convention of vlbe.h); *info = j + 1 (1-based
                     column, as vlbe_lu_factor), else *info = 0
     VLBE_ENOCONV    no convergence in EX_EIG_MAX_SWEEPS sweeps (not seen:
                     cyclic Jacobi converges quadratically, 6-10 sweeps)

   Method (Golub & Van Loan, Matrix Computations, 4th ed., alg. 8.5.2
   "symmetric Schur decomposition" and 8.5.3 cyclic Jacobi; 4.2.5
   Cholesky; 8.7.2 the reduction of the symmetric-definite problem).  A
   rotation in the plane (p, q) zeroes a_pq; a sweep visits every p < q in
   row order.  The pair is skipped when |a_pq| <= EPS sqrt(|a_pp a_qq|)
   (the threshold of Demmel and Veselic, Jacobi's method is more accurate
   than QR, SIAM J. Matrix Anal. Appl. 13 (1992) 1204-1245: it keeps the
   small eigenvalues of a graded positive definite matrix to high relative
   accuracy), or when |a_pq| is below EPS^2 times the largest |a_ij| of
   the input (nothing left at the working precision).  Converged when a
   sweep rotates nothing.  The reduction C = L^-1 A L^-T is formed by two
   triangular solves and symmetrised; eigenvectors x = L^-T y.

   API
     size_t ex_eig_work_len(int n)                               3 n^2
     vlbe_status ex_eig_chol(n, B, L, info)                      B = L L^T, L lower (n*n)
     vlbe_status ex_eig_sym(n, A, lam, X, sweeps, w, lw)         A x = lam x
     vlbe_status ex_eig_gsym(n, A, B, lam, X, info, w, lw)       A x = lam B x
   sweeps (may be NULL) gets the number of Jacobi sweeps. */
#ifndef VLBE_EX_EIG_H
#define VLBE_EX_EIG_H

#include "../vlbe.h"

#include <stdint.h>

#define EX_EIG_MAX_SWEEPS 60

static inline size_t ex_eig_work_len(int n)
{
    const size_t N = n > 0 ? (size_t)n : 0;
    if (N > 0 && N > (SIZE_MAX / 4) / N) return SIZE_MAX; /* no buffer is that large */
    return 3 * N * N;
}

/* B = L L^T; L lower triangular, its upper triangle set to zero.  L must
   not alias B.  On failure L holds a partial factor. */
static inline vlbe_status ex_eig_chol(int n, const vlbe_real *B, vlbe_real *L, int *info)
{
    const size_t N = (size_t)n;
    size_t i, j, k;
    if (info) *info = 0;
    if (n < 1 || n > 46340) return VLBE_EARG; /* n * n must fit an int */
    if (!vlbe_all_finite(B, n * n)) return VLBE_ENONFINITE;
    for (j = 0; j < N; ++j) {
        vlbe_real d = B[j * N + j];
        for (k = 0; k < j; ++k) d -= L[j * N + k] * L[j * N + k];
        /* GVL alg. 4.2.2 (gaxpy Cholesky); the pivot test: B_jj - sum L_jk^2
           carries a rounding error up to about j EPS B_jj (the sum is at
           most B_jj for a positive definite B), so a pivot below n EPS B_jj
           cannot be told from zero */
        if (!(d > (vlbe_real)n * VLBE_EPS * vlbe_fabs(B[j * N + j]))) {
            if (info) *info = (int)j + 1;
            return VLBE_ESINGULAR;
        }
        d = vlbe_sqrt(d);
        L[j * N + j] = d;
        for (i = j + 1; i < N; ++i) {
            vlbe_real s = B[i * N + j];
            for (k = 0; k < j; ++k) s -= L[i * N + k] * L[j * N + k];
            L[i * N + j] = s / d;
        }
        for (i = 0; i < j; ++i) L[i * N + j] = VLBE_R(0.0);
    }
    return VLBE_OK;
}

/* one Jacobi rotation of the symmetric C (n x n, full storage) in the
   plane (p, q), p < q; V (or NULL) accumulates the rotations as columns */
static inline void ex__eig_rot(size_t N, size_t p, size_t q, vlbe_real *C, vlbe_real *V)
{
    const vlbe_real apq = C[p * N + q];
    const vlbe_real th = (C[q * N + q] - C[p * N + p]) / (VLBE_R(2.0) * apq);
    vlbe_real t, c, s;
    size_t k;
    /* t = tan of the rotation angle, the smaller root of t^2 + 2 th t - 1 = 0,
       written without forming th^2 for large |th| (no overflow) */
    if (vlbe_fabs(th) > VLBE_R(1.0)) {
        const vlbe_real r = VLBE_R(1.0) / th;
        t = VLBE_R(1.0) / (vlbe_fabs(th) * (VLBE_R(1.0) + vlbe_sqrt(VLBE_R(1.0) + r * r)));
    } else
        t = VLBE_R(1.0) / (vlbe_fabs(th) + vlbe_sqrt(VLBE_R(1.0) + th * th));
    if (th < VLBE_R(0.0)) t = -t;
    c = VLBE_R(1.0) / vlbe_sqrt(VLBE_R(1.0) + t * t);
    s = t * c;
    C[p * N + p] -= t * apq;
    C[q * N + q] += t * apq;
    C[p * N + q] = C[q * N + p] = VLBE_R(0.0);
    for (k = 0; k < N; ++k) {
        vlbe_real g, h;
        if (k == p || k == q) continue;
        g = C[k * N + p];
        h = C[k * N + q];
        C[k * N + p] = C[p * N + k] = c * g - s * h;
        C[k * N + q] = C[q * N + k] = s * g + c * h;
    }
    if (V)
        for (k = 0; k < N; ++k) {
            const vlbe_real g = V[k * N + p], h = V[k * N + q];
            V[k * N + p] = c * g - s * h;
            V[k * N + q] = s * g + c * h;
        }
}

/* Jacobi on C in place (n x n symmetric); V (or NULL) starts as the
   identity and ends with the eigenvectors as columns.  The diagonal of C
   then holds the eigenvalues, unsorted. */
static inline vlbe_status ex__eig_jacobi(size_t N, vlbe_real *C, vlbe_real *V, int *sweeps)
{
    vlbe_real amax = VLBE_R(0.0), floor_abs;
    size_t i, j;
    int sw;
    for (i = 0; i < N * N; ++i)
        if (vlbe_fabs(C[i]) > amax) amax = vlbe_fabs(C[i]);
    floor_abs = VLBE_EPS * VLBE_EPS * amax;
    if (V)
        for (i = 0; i < N; ++i)
            for (j = 0; j < N; ++j) V[i * N + j] = i == j ? VLBE_R(1.0) : VLBE_R(0.0);
    for (sw = 0; sw < EX_EIG_MAX_SWEEPS; ++sw) {
        long rotations = 0;
        for (i = 0; i + 1 < N; ++i)
            for (j = i + 1; j < N; ++j) {
                const vlbe_real a = vlbe_fabs(C[i * N + j]);
                if (a <= floor_abs ||
                    a <= VLBE_EPS * vlbe_sqrt(vlbe_fabs(C[i * N + i]) * vlbe_fabs(C[j * N + j])))
                    continue;
                ex__eig_rot(N, i, j, C, V);
                ++rotations;
            }
        if (rotations == 0) {
            if (sweeps) *sweeps = sw + 1;
            return VLBE_OK;
        }
    }
    if (sweeps) *sweeps = sw;
    return VLBE_ENOCONV;
}

/* lam = diag(C) ascending; X (or NULL) = the columns of V in that order
   (selection sort: n small, n^2 compares and at most n column swaps) */
static inline void ex__eig_sorted(size_t N, const vlbe_real *C, const vlbe_real *V,
                                  vlbe_real *lam, vlbe_real *X)
{
    size_t i, j, k;
    for (i = 0; i < N; ++i) lam[i] = C[i * N + i];
    if (X)
        for (i = 0; i < N * N; ++i) X[i] = V[i];
    for (i = 0; i + 1 < N; ++i) {
        size_t m = i;
        for (j = i + 1; j < N; ++j)
            if (lam[j] < lam[m]) m = j;
        if (m == i) continue;
        {
            const vlbe_real t = lam[i];
            lam[i] = lam[m];
            lam[m] = t;
        }
        if (X)
            for (k = 0; k < N; ++k) {
                const vlbe_real t = X[k * N + i];
                X[k * N + i] = X[k * N + m];
                X[k * N + m] = t;
            }
    }
}

static inline vlbe_status ex__eig_check(int n, size_t lw)
{
    if (n < 1 || n > 46340) return VLBE_EARG; /* n * n must fit an int */
    if (ex_eig_work_len(n) == SIZE_MAX) return VLBE_EARG;
    if (lw < ex_eig_work_len(n)) return VLBE_EWORK;
    return VLBE_OK;
}

/* A x = lam x.  w: ex_eig_work_len(n) vlbe_real. */
static inline vlbe_status ex_eig_sym(int n, const vlbe_real *A, vlbe_real *lam, vlbe_real *X,
                                     int *sweeps, vlbe_real *w, size_t lw)
{
    vlbe_status st = ex__eig_check(n, lw);
    size_t N, i, j;
    vlbe_real *C, *V;
    if (st != VLBE_OK) return st;
    N = (size_t)n;
    C = w;
    V = w + N * N;
    if (!vlbe_all_finite(A, n * n)) return VLBE_ENONFINITE;
    for (i = 0; i < N; ++i)
        for (j = 0; j < N; ++j) C[i * N + j] = VLBE_R(0.5) * (A[i * N + j] + A[j * N + i]);
    if ((st = ex__eig_jacobi(N, C, X ? V : NULL, sweeps)) != VLBE_OK) return st;
    ex__eig_sorted(N, C, V, lam, X);
    return VLBE_OK;
}

/* A x = lam B x, B symmetric positive definite.  w: ex_eig_work_len(n). */
static inline vlbe_status ex_eig_gsym(int n, const vlbe_real *A, const vlbe_real *B,
                                      vlbe_real *lam, vlbe_real *X, int *info, vlbe_real *w,
                                      size_t lw)
{
    vlbe_status st = ex__eig_check(n, lw);
    size_t N, i, j, k;
    vlbe_real *C, *V, *L;
    if (info) *info = 0;
    if (st != VLBE_OK) return st;
    N = (size_t)n;
    C = w;
    V = w + N * N;
    L = w + 2 * N * N;
    if (!vlbe_all_finite(A, n * n)) return VLBE_ENONFINITE;
    if ((st = ex_eig_chol(n, B, L, info)) != VLBE_OK) return st;
    /* V = L^-1 A (forward substitution, column by column of A) */
    for (j = 0; j < N; ++j)
        for (i = 0; i < N; ++i) {
            vlbe_real s = VLBE_R(0.5) * (A[i * N + j] + A[j * N + i]);
            for (k = 0; k < i; ++k) s -= L[i * N + k] * V[k * N + j];
            V[i * N + j] = s / L[i * N + i];
        }
    /* C = L^-1 V^T = L^-1 A L^-T (A symmetric) */
    for (j = 0; j < N; ++j)
        for (i = 0; i < N; ++i) {
            vlbe_real s = V[j * N + i];
            for (k = 0; k < i; ++k) s -= L[i * N + k] * C[k * N + j];
            C[i * N + j] = s / L[i * N + i];
        }
    for (i = 0; i < N; ++i)
        for (j = i + 1; j < N; ++j)
            C[i * N + j] = C[j * N + i] = VLBE_R(0.5) * (C[i * N + j] + C[j * N + i]);
    if ((st = ex__eig_jacobi(N, C, X ? V : NULL, NULL)) != VLBE_OK) return st;
    ex__eig_sorted(N, C, V, lam, X);
    if (X) /* x = L^-T y: back substitution, column by column */
        for (j = 0; j < N; ++j)
            for (i = N; i-- > 0;) {
                vlbe_real s = X[i * N + j];
                for (k = i + 1; k < N; ++k) s -= L[k * N + i] * X[k * N + j];
                X[i * N + j] = s / L[i * N + i];
            }
    return VLBE_OK;
}

#endif /* VLBE_EX_EIG_H */
