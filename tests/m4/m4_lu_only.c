/* m4_lu_only.c -- footprint image of make check-m4: vlbe.h's dense and
   banded LU alone, float, default VLBE_ASSERT (on bare metal a trap: no
   __assert_func, no printf, no malloc may be linked; the target checks
   with nm).  No output: the exit status says whether both solves return
   the known solution x = 1 to a few ulps.
   -- part of vlbe                                  SPDX-License-Identifier: MIT */
#include "../../vlbe.h"

#define N 8
#define KL 1
#define KU 2
#define LDA (KL + KU + 1)
#define LDF (2 * KL + KU + 1)

static vlbe_real A[N * N], LU[N * N], b[N], Ab[N * LDA], LUb[N * LDF], bb[N];
static int piv[N], pivb[N];

int main(void)
{
    int i, j, info, bad = 0;
    for (i = 0; i < N; ++i) {
        b[i] = bb[i] = VLBE_R(0.0);
        for (j = 0; j < N; ++j) {
            A[i * N + j] = i == j ? VLBE_R(4.0) : VLBE_R(1.0) / (vlbe_real)(1 + i + j);
            b[i] += A[i * N + j]; /* x = 1 */
        }
        for (j = i - KL; j <= i + KU; ++j) {
            if (j < 0 || j >= N) continue;
            Ab[VLBE_BAND_IDX(LDA, KL, i, j)] = A[i * N + j];
            bb[i] += A[i * N + j];
        }
    }
    if (vlbe_lu_factor(N, A, LU, piv, &info) != VLBE_OK) return 2;
    vlbe_lu_solve(N, LU, piv, 1, b);
    if (vlbe_band_lu_factor(N, KL, KU, Ab, LDA, LUb, pivb, &info) != VLBE_OK) return 3;
    vlbe_band_lu_solve(N, KL, KU, LUb, pivb, 1, bb);
    for (i = 0; i < N; ++i)
        if (vlbe_fabs(b[i] - VLBE_R(1.0)) > VLBE_R(8.0) * VLBE_EPS ||
            vlbe_fabs(bb[i] - VLBE_R(1.0)) > VLBE_R(8.0) * VLBE_EPS)
            bad = 1;
    return bad;
}
