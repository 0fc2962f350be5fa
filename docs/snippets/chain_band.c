/* chain_band.c -- the program around the banded-chain fragment of
   docs/results.md (section "Long chains"): tests/doc_blocks.sh writes that
   fragment to a file and compiles this one with -DDOC_BLOCK='"<that file>"'.
   A clamped planar ALE-ANCF chain of NE Lagrangian elements (10 m, steel,
   gravity), switched to band storage and made a vlbe_dae by the fragment,
   then started and stepped with HHT-alpha -0.05 at h = 1 ms.
   -- part of vlbe                                  SPDX-License-Identifier: MIT */
#include "ancf_ale.h"
#include "integrators.h"
#include <stdio.h>
#include <stdlib.h>

#ifndef DOC_BLOCK
#error "compile with -DDOC_BLOCK='\"file with the fragment\"' (tests/doc_blocks.sh)"
#endif

enum { NE = 64, NMAX = 5 * (NE + 1) + 4 };

int main(void)
{
    static vlbe_ale_node node[NE + 1];
    static vlbe_ale_elem el;
    static vlbe_ale_chain ch;
    vlbe_ale_mat mat = {0};
    vlbe_ale_con con[2], c = {0};
    vlbe_dae sys = {0};
    static vlbe_hht st;
    vlbe_hht_params par;
    const vlbe_real r0[2] = {0, 0}, dir[2] = {1, 0};
    vlbe_real *w, *q0, *v0;
    int *iw, i, k, rc = 1;
    mat.rhoA = VLBE_R(7.85);
    mat.EA = VLBE_R(2.1e8);
    mat.EI = VLBE_R(1.75e3);
    mat.f[1] = VLBE_R(-9.81) * mat.rhoA; /* gravity */
    if (vlbe_ale_elem_init(&el, &mat, 0, 0, 0, 0) != VLBE_OK) return 1;
    for (i = 0; i <= NE; ++i) {
        node[i].pmode = VLBE_ALE_PFIXED;
        node[i].p = VLBE_R(10.0) * (vlbe_real)i / (vlbe_real)NE;
    }
    if (vlbe_ale_chain_init(&ch, &el, node, NE + 1, NE + 1, con, 2) != VLBE_OK) return 1;
    c.type = VLBE_ALE_CON_POS; /* clamp at node 0: position and slope */
    if (vlbe_ale_chain_add(&ch, &c) != VLBE_OK) return 1;
    c.type = VLBE_ALE_CON_SLOPE;
    c.d[0] = 1;
    if (vlbe_ale_chain_add(&ch, &c) != VLBE_OK) return 1;
    {
#include DOC_BLOCK
        w = (vlbe_real *)malloc(lw * sizeof *w);
        iw = (int *)malloc(liw * sizeof *iw);
        q0 = (vlbe_real *)calloc((size_t)ch.n, sizeof *q0);
        v0 = (vlbe_real *)calloc((size_t)ch.n, sizeof *v0);
        if (w && iw && q0 && v0) {
            vlbe_ale_chain_straight(&ch, r0, dir, q0);
            if (vlbe_hht_params_alpha(&par, VLBE_R(-0.05)) == VLBE_OK &&
                vlbe_hht_init(&st, &sys, &par, 0, q0, v0, w, lw, iw, liw) == VLBE_OK) {
                for (k = 0; k < 10 && vlbe_hht_step(&st, VLBE_R(1e-3)) == VLBE_OK; ++k) continue;
                if (k == 10) {
                    printf("%d elements, n = %d, kl = ku = %d, %zu reals: tip y(10 ms) = %g m\n",
                           NE, ch.n, ch.kl, lw, (double)st.q[ch.n - 3]);
                    rc = 0;
                }
            }
        }
        free(w);
        free(iw);
        free(q0);
        free(v0);
    }
    return rc;
}
