/* fuzz_lu.c -- libFuzzer harness of the dense LU of vlbe.h (vlbe_lu_factor,
   vlbe_lu_solve)                                   -- part of vlbe
                                                   SPDX-License-Identifier: MIT
   Input: flags byte (bit 0: non-finite reals allowed, bit 1: in place LU ==
   A, bit 2: info = NULL), n = 1 + byte % 12, a structure byte, the n^2
   entries, the structure's row r0 = byte % n (n > 1), its extra reals, nrhs = 1 + byte % 3 and the right-hand sides (fuzz_util.h: real format).
   Structures: 0 any reals, 1 moderate, 2 a zero row, 3 a zero column, 4 a
   repeated row, 5 rank one u v^T, 6 diagonal, 7 upper triangular with a zero
   on the diagonal, 8 moderate rows scaled by any real, 9 s I + any real in
   one entry.
   Asserts
     factor OK      LU finite, piv[k] in [k, n), info = 0, P A = L U to
                    (4n + 4) eps |L||U| (+ an underflow floor); not OK for a
                    matrix with an exactly zero row or column
                    (n >= 2);
                    then solve: X finite when the solution with the same
                    factor in long double, and every product and partial
                    sum on the way, fit in vlbe_real with 2^(n+4) to
                    spare; a finite X has |P b - P A x| <= (6n + 6) eps
                    |L||U||x| (+ underflow floors, see lu_check_solve)
                    (Higham, Accuracy and Stability,
                    thm. 9.4: gamma_3n).
     factor not OK  status VLBE_ESINGULAR (info in 1..n) or VLBE_ENONFINITE
                    (only when A holds NaN/Inf); A, piv unchanged; LU and
                    (ESINGULAR) info as documented (see below).
   A banded LU: add a backend to lu_backends[] whose factor/solve take the
   dense matrix decoded here (restricted to the band by lu_band_mask) and
   whose reconstruct() gives the dense L, U; the checks are the same. */
#include "fuzz_util.h"

#define LU_NMAX 12
#define LU_RMAX 3

typedef long double lu_ld;

/* expand the factor into dense L (unit lower) and U, long double */
static void lu_expand(int n, const vlbe_real *LU, lu_ld *L, lu_ld *U)
{
    int i, j;
    for (i = 0; i < n; ++i)
        for (j = 0; j < n; ++j) {
            const lu_ld v = (lu_ld)LU[i * n + j];
            L[i * n + j] = i > j ? v : (i == j ? 1.0L : 0.0L);
            U[i * n + j] = i <= j ? v : 0.0L;
        }
}

/* rows of A permuted as the factorization did: swap k <-> piv[k] in order */
static void lu_permute(int n, int ncol, const int *piv, const vlbe_real *A, lu_ld *PA)
{
    int i, j, k;
    for (i = 0; i < n * ncol; ++i) PA[i] = (lu_ld)A[i];
    for (k = 0; k < n; ++k)
        if (piv[k] != k)
            for (j = 0; j < ncol; ++j) {
                const lu_ld t = PA[k * ncol + j];
                PA[k * ncol + j] = PA[piv[k] * ncol + j];
                PA[piv[k] * ncol + j] = t;
            }
}

static lu_ld lu_fabsl(lu_ld x) { return x < 0 ? -x : x; }

static void lu_check_factor(int n, const vlbe_real *A, const vlbe_real *LU, const int *piv)
{
    lu_ld L[LU_NMAX * LU_NMAX], U[LU_NMAX * LU_NMAX], PA[LU_NMAX * LU_NMAX];
    const lu_ld dmin = (lu_ld)ldexp(1.0, FZ_MIN_EXP - FZ_MANT_DIG);
    int i, j, k;
    lu_expand(n, LU, L, U);
    lu_permute(n, n, piv, A, PA);
    for (i = 0; i < n; ++i)
        for (j = 0; j < n; ++j) {
            lu_ld s = 0.0L, a = 0.0L, cu = 0.0L;
            for (k = 0; k < n; ++k) {
                s += L[i * n + k] * U[k * n + j];
                a += lu_fabsl(L[i * n + k] * U[k * n + j]);
                cu += lu_fabsl(U[k * n + j]);
            }
            FUZZ_CHECK(lu_fabsl(PA[i * n + j] - s) <=
                           (lu_ld)(4 * n + 4) * (lu_ld)VLBE_EPS * a + 4.0L * n * dmin * (1.0L + cu),
                       "factor OK but P A != L U beyond the backward-error bound");
        }
}

static lu_ld lu_big(lu_ld big, lu_ld v) { return lu_fabsl(v) > big ? lu_fabsl(v) : big; }

/* solution with the same factor in long double: x (n x nrhs); returns the
   largest magnitude of any intermediate or final value: every product
   l_ik y_k, u_ik x_k and partial sum of the substitutions, not only y and
   x (A = [3.0e305 -1.5e306; -9.3e298 3.1e290], b = (1.4e306, 1.4e306):
   x = (-1.5e7, -3.0e6), but u_12 x_2 = 4.5e312 overflows on the way) */
static lu_ld lu_solve_ld(int n, int nrhs, const vlbe_real *LU, const int *piv,
                        const vlbe_real *B, lu_ld *x)
{
    lu_ld L[LU_NMAX * LU_NMAX], U[LU_NMAX * LU_NMAX], big = 0.0L;
    int i, k, r;
    lu_expand(n, LU, L, U);
    lu_permute(n, nrhs, piv, B, x);
    for (i = 0; i < n * nrhs; ++i) big = lu_big(big, x[i]);
    for (r = 0; r < nrhs; ++r) {
        for (i = 0; i < n; ++i)
            for (k = 0; k < i; ++k) {
                const lu_ld t = L[i * n + k] * x[k * nrhs + r];
                x[i * nrhs + r] -= t;
                big = lu_big(lu_big(big, t), x[i * nrhs + r]);
            }
        for (i = n - 1; i >= 0; --i) {
            for (k = i + 1; k < n; ++k) {
                const lu_ld t = U[i * n + k] * x[k * nrhs + r];
                x[i * nrhs + r] -= t;
                big = lu_big(lu_big(big, t), x[i * nrhs + r]);
            }
            x[i * nrhs + r] /= U[i * n + i];
            big = lu_big(big, x[i * nrhs + r]);
        }
    }
    return big;
}

/* Residual bound of the solve.  r = P b - P A x = (P b - L U x) + (L U - P A) x
   with the computed L, U, x:
   - (L U - P A) x: the factor's backward error, asserted by lu_check_factor
     entrywise: |P A - L U|_ij <= (4n + 4) eps (|L||U|)_ij + 4n dmin (1 + cu_j),
     cu_j = sum_k |u_kj|.  The dmin part is absolute, not relative to |L||U|:
     a subnormal multiplier l_ik ~ a_ik / u_kk is rounded on the grid of
     dmin, so l_ik u_kk misses a_ik by up to |u_kk| dmin / 2 however small
     l_ik u_kk (and so row i of |L||U|) is.  Times x it gives
     4n dmin sum_j (1 + cu_j) |x_j|, which |U| bounds, not row i of |L||U|
     (A = [108 1; 3.2e-310 1], x_1 = 6.8e226: l_21 = a_21 fl(1 / u_11) is
     the correctly rounded quotient a_21 / u_11, 0.39 dmin off, and r_2 =
     (a_21 - l_21 u_11) x_1 = 42 dmin x_1, above the solve floor
     8n dmin (1 + lu1)(1 + max|x|) = 32 dmin x_1; no factor stored in
     vlbe_real does better).  The reciprocal of vlbe_lu_factor adds a
     relative eps / 2 to l_ik before that rounding, << dmin for a subnormal
     l_ik.
   - P b - L U x: the two triangular solves (Higham thm. 8.5) with the
     eps part in (2n + 2) eps |L||U||x|; each underflowing product and the
     last rounding x_i = t / u_ii add an absolute dmin / 2, i.e. row i gets
     at most dmin / 2 (n + sum_k |l_ik| (n + |u_kk|)) <= n dmin (n + 1 + lu1) / 2
     (|l_ik| <= 1), below 8n dmin (1 + lu1) for n + 1 <= 15 (LU_NMAX = 12). */
static void lu_check_solve(int n, int nrhs, const vlbe_real *A, const vlbe_real *LU,
                           const int *piv, const vlbe_real *B)
{
    vlbe_real X[LU_NMAX * LU_RMAX];
    lu_ld xl[LU_NMAX * LU_RMAX], L[LU_NMAX * LU_NMAX], U[LU_NMAX * LU_NMAX],
        PA[LU_NMAX * LU_NMAX], PB[LU_NMAX * LU_RMAX], cu[LU_NMAX];
    const lu_ld dmin = (lu_ld)ldexp(1.0, FZ_MIN_EXP - FZ_MANT_DIG);
    const lu_ld big = lu_solve_ld(n, nrhs, LU, piv, B, xl);
    int i, j, k, r, fin;
    memcpy(X, B, sizeof(vlbe_real) * (size_t)(n * nrhs));
    fz_note("vlbe_lu_solve(n=%d, nrhs=%d)", n, nrhs);
    vlbe_lu_solve(n, LU, piv, nrhs, X);
    fin = fz_finite(X, (size_t)(n * nrhs));
    /* a finite X is owed only for a finite B (the decoder may give NaN/Inf) */
    if (fz_finite(B, (size_t)(n * nrhs)) && big * ldexpl(1.0L, n + 4) <= (lu_ld)VLBE_REAL_MAX &&
        !fz_skip("lu-solve-finite"))
        FUZZ_CHECK(fin, "solve after a successful factor gave NaN/Inf for a representable solution");
    if (!fin) return;
    lu_expand(n, LU, L, U);
    lu_permute(n, n, piv, A, PA);
    lu_permute(n, nrhs, piv, B, PB);
    for (j = 0; j < n; ++j) {
        cu[j] = 0.0L;
        for (k = 0; k < n; ++k) cu[j] += lu_fabsl(U[k * n + j]);
    }
    for (r = 0; r < nrhs; ++r)
        for (i = 0; i < n; ++i) {
            lu_ld res = PB[i * nrhs + r], bnd = 0.0L, lu1 = 0.0L, xm = 0.0L, fx = 0.0L;
            for (j = 0; j < n; ++j) {
                lu_ld lu_ij = 0.0L;
                res -= PA[i * n + j] * (lu_ld)X[j * nrhs + r];
                for (k = 0; k < n; ++k) lu_ij += lu_fabsl(L[i * n + k] * U[k * n + j]);
                bnd += lu_ij * lu_fabsl((lu_ld)X[j * nrhs + r]);
                lu1 += lu_ij;
                if (lu_fabsl((lu_ld)X[j * nrhs + r]) > xm) xm = lu_fabsl((lu_ld)X[j * nrhs + r]);
                fx += (1.0L + cu[j]) * lu_fabsl((lu_ld)X[j * nrhs + r]);
            }
            FUZZ_CHECK(lu_fabsl(res) <= (lu_ld)(6 * n + 6) * (lu_ld)VLBE_EPS * bnd +
                                            8.0L * n * dmin * (1.0L + lu1) * (1.0L + xm) +
                                            4.0L * n * dmin * fx,
                       "solve residual above the backward-error bound");
        }
}

/* the matrix of structure s (see the top) */
static int lu_decode(fz_rd *rd, int n, int s, vlbe_real *A)
{
    int i, j, r0, r1;
    for (i = 0; i < n * n; ++i) A[i] = (s == 0 || s == 9) ? fz_real(rd) : fz_mod(rd, 4.0);
    r0 = n > 1 ? fz_int(rd, 0, n - 1) : 0; /* the row / column of a structure */
    r1 = n > 1 ? (r0 + 1) % n : 0;
    switch (s) {
    case 2: for (j = 0; j < n; ++j) A[r0 * n + j] = VLBE_R(0.0); break;
    case 3: for (i = 0; i < n; ++i) A[i * n + r0] = VLBE_R(0.0); break;
    case 4: for (j = 0; j < n; ++j) A[r1 * n + j] = A[r0 * n + j]; break;
    case 5: {
        vlbe_real u[LU_NMAX], v[LU_NMAX];
        fz_reals(rd, u, n);
        fz_reals(rd, v, n);
        for (i = 0; i < n; ++i)
            for (j = 0; j < n; ++j) A[i * n + j] = u[i] * v[j];
        break;
    }
    case 6:
        for (i = 0; i < n; ++i)
            for (j = 0; j < n; ++j)
                if (i != j) A[i * n + j] = VLBE_R(0.0);
        A[r0 * n + r0] = fz_real(rd);
        break;
    case 7:
        for (i = 0; i < n; ++i)
            for (j = 0; j < i; ++j) A[i * n + j] = VLBE_R(0.0);
        A[r0 * n + r0] = VLBE_R(0.0);
        break;
    case 8:
        for (i = 0; i < n; ++i) {
            const vlbe_real sc = fz_real(rd);
            for (j = 0; j < n; ++j) A[i * n + j] *= sc;
        }
        break;
    case 9: {
        const vlbe_real sc = fz_real(rd), e = A[0];
        for (i = 0; i < n * n; ++i) A[i] = VLBE_R(0.0);
        for (i = 0; i < n; ++i) A[i * n + i] = sc;
        A[r0 * n + r1] = e;
        break;
    }
    default: break;
    }
    return r0;
}

/* Structures whose elimination keeps an exactly zero row or column, so
   that a pivot is exactly 0 whatever the rounding (a repeated row or a
   rank-one matrix leave rounding residues that the growth of later steps
   can lift above n eps max|A|: not asserted) */
static int lu_exact_singular(int n, int s) { return n >= 2 && (s == 2 || s == 3); }

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    vlbe_real A[LU_NMAX * LU_NMAX], A0[LU_NMAX * LU_NMAX], LUb[LU_NMAX * LU_NMAX],
        B[LU_NMAX * LU_RMAX], *LU;
    int piv[LU_NMAX], piv0[LU_NMAX], info = 0, info0 = 0, *pinfo, n, s, nrhs, inplace, i, anyinf = 0;
    vlbe_status st;
    fz_rd rd;
    unsigned flags;
    flags = fz_begin("lu", &rd, data, size);
    inplace = (int)((flags >> 1) & 1u);
    pinfo = (flags & 4u) ? NULL : &info;
    n = fz_int(&rd, 1, LU_NMAX);
    s = fz_int(&rd, 0, 9);
    lu_decode(&rd, n, s, A);
    nrhs = fz_int(&rd, 1, LU_RMAX);
    for (i = 0; i < n * nrhs; ++i) B[i] = fz_mod(&rd, 8.0);
    for (i = 0; i < n * n; ++i)
        if (!isfinite(A[i])) anyinf = 1;
    memcpy(A0, A, sizeof A);
    fz_dump("A", A, n * n);
    fz_dump("B", B, n * nrhs);

    LU = inplace ? A : LUb;
    if (!inplace) fz_fill(LUb, sizeof LUb);
    fz_fill(piv, sizeof piv);
    fz_fill(&info, sizeof info);
    fz_fill(&info0, sizeof info0);
    fz_snap_reset();
    if (!inplace) fz_snap(A, sizeof(vlbe_real) * (size_t)(n * n), "A");
    memcpy(piv0, piv, sizeof piv); /* compared by hand below: see the failure paths */
    fz_note("vlbe_lu_factor(n=%d, structure=%d, in_place=%d, info=%s)", n, s, inplace,
            pinfo ? "&info" : "NULL");
    st = vlbe_lu_factor(n, A, LU, piv, pinfo);
    /* info: written on ESINGULAR only (vlbe.h: "writes the 1-based failing
       column to *info (if info != NULL; 0 on success)") */
    if (pinfo && st != VLBE_OK && st != VLBE_ESINGULAR && !fz_skip("lu-info"))
        FUZZ_CHECK(memcmp(&info, &info0, sizeof info) == 0,
                   "failure other than ESINGULAR but *info written");
    FUZZ_CHECK(fz_status_known(st), "unknown status");
    if (st == VLBE_OK) {
        FUZZ_CHECK(!anyinf, "factor OK on a matrix with NaN/Inf");
        if (fz_skip("lu-finite") && !fz_finite(LU, (size_t)(n * n))) return 0;
        FUZZ_CHECK(fz_finite(LU, (size_t)(n * n)), "factor OK but LU holds NaN/Inf");
        for (i = 0; i < n; ++i) FUZZ_CHECK(piv[i] >= i && piv[i] < n, "factor OK but piv out of range");
        if (pinfo) FUZZ_CHECK(info == 0, "factor OK but info != 0");
        FUZZ_CHECK(!lu_exact_singular(n, s), "factor OK on an exactly singular matrix");
        if (!inplace) FUZZ_CHECK(memcmp(A, A0, sizeof(vlbe_real) * (size_t)(n * n)) == 0, "A changed");
        lu_check_factor(n, A0, LU, piv);
        lu_check_solve(n, nrhs, A0, LU, piv, B);
        return 0;
    }
    FUZZ_CHECK(st == VLBE_ESINGULAR || st == VLBE_ENONFINITE, "factor failed with an unexpected status");
    /* ENONFINITE on a finite matrix: only when the elimination may have
       overflowed (vlbe.h: growth of partial pivoting below 2^n, so max|A|
       2^n must be able to pass the largest real) */
    if (st == VLBE_ENONFINITE && !anyinf) {
        long double amax = 0.0L;
        for (i = 0; i < n * n; ++i)
            if (fabsl((long double)A0[i]) > amax) amax = fabsl((long double)A0[i]);
        FUZZ_CHECK(ldexpl(amax, n) > (long double)VLBE_REAL_MAX,
                   "ENONFINITE on a finite matrix that cannot overflow");
    }
    /* piv: untouched when A holds NaN/Inf (vlbe.h: "found before anything
       is written"); after the elimination started, LU and piv are
       documented as unspecified (the factor's outputs, as in LAPACK) */
    if (st == VLBE_ENONFINITE && anyinf)
        FUZZ_CHECK(memcmp(piv, piv0, sizeof piv) == 0, "ENONFINITE on NaN/Inf input but piv written");
    if (st == VLBE_ESINGULAR && pinfo) FUZZ_CHECK(info >= 1 && info <= n, "ESINGULAR but info not in 1..n");
    /* LU: documented unspecified after a failed elimination (vlbe.h,
       vlbe_lu_factor: "LU and piv hold partial results, unspecified (so A
       is lost when LU == A)"), so LU and, in place, A are not compared.
       info: documented written on ESINGULAR only ("the only failure that
       writes *info"). */
    FZ_CHECK_UNCHANGED();
    return 0;
}
