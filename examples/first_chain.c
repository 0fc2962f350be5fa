/* first_chain.c -- a steel flat bar (1 m, 100 x 10 mm) clamped at x = 0 and
   released under gravity: four ALE-ANCF elements in a chain, HHT-alpha.
   cc -std=c99 -O2 examples/first_chain.c -lm && ./a.out
   -- part of vlbe                                  SPDX-License-Identifier: MIT */
#include "../ancf_ale.h"
#include "../integrators.h"
#include <stdio.h>

#define NE 4 /* elements */
#define TRY(call) do { vlbe_status s_ = (call); if (s_ != VLBE_OK) { \
    printf("%s: %s\n", #call, vlbe_status_str(s_)); return 1; } } while (0)

static vlbe_ale_elem el;             /* Gauss tables, about 16 kB */
static vlbe_real work[4096];
static int iwork[64];

int main(void)
{
    vlbe_ale_mat mat = {0};                      /* SI units */
    vlbe_ale_node node[NE + 1] = {{0}};          /* pmode 0: material points fixed */
    vlbe_ale_con con[2] = {{0}}, c = {0};
    vlbe_ale_chain ch;
    vlbe_dae sys;
    vlbe_hht_params par;
    vlbe_hht hht;
    vlbe_real q0[5 * (NE + 1)], v0[5 * (NE + 1)] = {0};
    const vlbe_real r0[2] = {0, 0}, dir[2] = {1, 0};
    int i;
    mat.rhoA = VLBE_R(7.85);                     /* 7850 kg/m^3 x 1e-3 m^2 */
    mat.EA = VLBE_R(2.1e8);
    mat.EI = VLBE_R(1.75e3);
    mat.f[1] = VLBE_R(-9.81) * mat.rhoA;         /* gravity: a load per length */
    TRY(vlbe_ale_elem_init(&el, &mat, 0u, 0, 0, 0));
    for (i = 0; i <= NE; ++i) node[i].p = (vlbe_real)i / NE;
    TRY(vlbe_ale_chain_init(&ch, &el, node, NE + 1, NE + 1, con, 2));
    c.type = VLBE_ALE_CON_POS;   c.node = 0;     /* clamp: r(0) = (0, 0) ... */
    TRY(vlbe_ale_chain_add(&ch, &c));
    c.type = VLBE_ALE_CON_SLOPE; c.d[0] = 1;     /* ... and r'(0) = (1, 0) */
    TRY(vlbe_ale_chain_add(&ch, &c));
    TRY(vlbe_ale_chain_layout(&ch));             /* coordinates: ch.n, equations: ch.m */
    TRY(vlbe_ale_chain_dae(&ch, &sys));
    vlbe_ale_chain_straight(&ch, r0, dir, q0);   /* straight, at rest */
    TRY(vlbe_hht_params_alpha(&par, VLBE_R(-0.05)));
    TRY(vlbe_hht_init(&hht, &sys, &par, 0, q0, v0, work, 4096, iwork, 64));
    for (i = 1; i <= 1000; ++i) {                /* 1 s in steps of 1 ms */
        TRY(vlbe_hht_step(&hht, VLBE_R(1e-3)));
        if (i % 100 == 0)
            printf("t = %.1f s   tip y = %8.3f mm\n", (double)hht.t,
                   1e3 * (double)hht.q[node[NE].ofs + 1]);
    }
    printf("static tip deflection q L^4 / (8 EI) = %.3f mm\n", -1e3 * 9.81 * 7.85 / (8 * 1.75e3));
    return 0;
}
