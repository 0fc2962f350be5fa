/* m4_lu.c -- vlbe.h dense and banded LU on the Cortex-M4F (make check-m4):
   a 12 x 12 well-conditioned nonsymmetric matrix (diagonally dominant,
   pivoting still exchanges rows: its first column grows downwards) factored
   and solved for two right-hand sides, and a 20 x 20 band matrix (kl 2,
   ku 3) through vlbe_band_lu_factor / _solve; factors, solutions and
   float residuals printed (tests/m4/m4_out.h).
   -- part of vlbe                                  SPDX-License-Identifier: MIT */
#include "../../vlbe.h"
#include "m4_out.h"

#define N 12
#define NB 20
#define KL 2
#define KU 3
#define LDA (KL + KU + 1)
#define LDF (2 * KL + KU + 1)

static vlbe_real A[N * N], LU[N * N], B[N * 2], R[N * 2];
static vlbe_real Ab[NB * LDA], LUb[NB * LDF], Bb[NB], Rb[NB];
static int piv[N], pivb[NB];

int main(void)
{
    int i, j, info = -1;
    for (i = 0; i < N; ++i)
        for (j = 0; j < N; ++j) {
            vlbe_real d = (vlbe_real)(i > j ? i - j : j - i);
            A[i * N + j] = VLBE_R(1.0) / (VLBE_R(1.0) + d) + VLBE_R(0.05) * (vlbe_real)(i - 2 * j);
            if (i == j) A[i * N + j] += VLBE_R(4.0);
        }
    for (i = 0; i < N; ++i) A[i * N] += VLBE_R(0.6) * (vlbe_real)i; /* pivoting: rows swap */
    for (i = 0; i < N; ++i) {
        B[i * 2] = VLBE_R(1.0);
        B[i * 2 + 1] = (vlbe_real)(i % 3) - VLBE_R(0.5);
    }
    memcpy(R, B, sizeof R);
    if (m4_status("lu_factor", vlbe_lu_factor(N, A, LU, piv, &info))) return m4_exit();
    m4_int("lu_info", info);
    for (i = 0; i < N; ++i) m4_int("lu_piv", piv[i]);
    m4_vec("LU", LU, N * N);
    vlbe_lu_solve(N, LU, piv, 2, B);
    m4_vec("x", B, N * 2);
    for (i = 0; i < N; ++i) /* r = b - A x, both columns */
        for (j = 0; j < N; ++j) {
            R[i * 2] -= A[i * N + j] * B[j * 2];
            R[i * 2 + 1] -= A[i * N + j] * B[j * 2 + 1];
        }
    m4_vec("r", R, N * 2);

    /* band matrix, entry (i, j) at VLBE_BAND_IDX(LDA, KL, i, j) */
    memset(Ab, 0, sizeof Ab);
    for (i = 0; i < NB; ++i)
        for (j = i - KL; j <= i + KU; ++j) {
            if (j < 0 || j >= NB) continue;
            Ab[VLBE_BAND_IDX(LDA, KL, i, j)] =
                i == j ? VLBE_R(3.0) + VLBE_R(0.1) * (vlbe_real)(i % 4)
                       : VLBE_R(1.0) / (vlbe_real)(2 + j - i + KL) - VLBE_R(0.02) * (vlbe_real)i;
        }
    Ab[VLBE_BAND_IDX(LDA, KL, 2, 0)] = VLBE_R(5.0); /* a pivot below the diagonal */
    for (i = 0; i < NB; ++i) Bb[i] = VLBE_R(1.0) + VLBE_R(0.25) * (vlbe_real)(i % 5);
    memcpy(Rb, Bb, sizeof Rb);
    info = -1;
    if (m4_status("band_lu_factor", vlbe_band_lu_factor(NB, KL, KU, Ab, LDA, LUb, pivb, &info)))
        return m4_exit();
    m4_int("band_info", info);
    for (i = 0; i < NB; ++i) m4_int("band_piv", pivb[i]);
    m4_vec("LUb", LUb, NB * LDF);
    vlbe_band_lu_solve(NB, KL, KU, LUb, pivb, 1, Bb);
    m4_vec("xb", Bb, NB);
    vlbe_band_mat_vec(NB, KL, KU, Ab, LDA, Bb, Rb + 0 * NB); /* Rb = A x ... */
    for (i = 0; i < NB; ++i) Rb[i] -= VLBE_R(1.0) + VLBE_R(0.25) * (vlbe_real)(i % 5); /* - b */
    m4_vec("rb", Rb, NB);
    return m4_exit();
}
