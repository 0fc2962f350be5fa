/* m4_hht.c -- HHT-alpha of integrators.h on the Cortex-M4F (make
   check-m4): the clamped cantilever of 4 Lagrangian ALE-ANCF elements
   (ancf_ale.h chain, nodes at p = 0, 0.25, 0.5, 0.75, 1; rhoA 7.85, EA
   2.1e8, EI 1.75e3, gravity 9.81), clamped at node 0 (position and slope),
   straight and at rest at t = 0; vlbe_hht_params_alpha(-0.05) with its
   defaults, h = 1e-3, 1000 steps.  Prints the tip (x, y, x', y' and their
   rates) every 250 steps and the counters; a failed step prints its status
   and the program exits nonzero.  The vlbe_dae is the chain's
   (vlbe_ale_chain_dae, dense storage).
   -- part of vlbe                                  SPDX-License-Identifier: MIT */
#include "../../ancf_ale.h"
#include "../../integrators.h"
#include "m4_out.h"

#define NE 4
#define WORK_CAP 8192
#define IWORK_CAP 256

static vlbe_ale_elem el; /* about 16 kB: static */
static vlbe_ale_node node[NE + 1];
static vlbe_ale_con con[2];
static vlbe_ale_chain ch;
static vlbe_dae sys;
static vlbe_hht st;
static vlbe_real work[WORK_CAP], q0[64], v0[64];
static int iwork[IWORK_CAP];

static void print_tip(void)
{
    const int o = node[NE].ofs; /* tip node: x, y, x', y' */
    m4_val("t", -1, st.t);
    m4_vec("tip_q", st.q + o, 4);
    m4_vec("tip_v", st.v + o, 4);
}

int main(void)
{
    vlbe_ale_mat mat;
    vlbe_ale_con c;
    vlbe_hht_params par;
    const vlbe_real r0[2] = {VLBE_R(0.0), VLBE_R(0.0)}, dir[2] = {VLBE_R(1.0), VLBE_R(0.0)};
    size_t lw, liw;
    int i, k;
    memset(&mat, 0, sizeof mat);
    mat.rhoA = VLBE_R(7.85);
    mat.EA = VLBE_R(2.1e8);
    mat.EI = VLBE_R(1.75e3);
    mat.f[1] = VLBE_R(-9.81) * mat.rhoA;
    if (m4_status("ale_elem_init", vlbe_ale_elem_init(&el, &mat, 0, 0, 0, 0))) return m4_exit();
    for (i = 0; i <= NE; ++i) {
        memset(&node[i], 0, sizeof node[i]);
        node[i].pmode = VLBE_ALE_PFIXED;
        node[i].p = (vlbe_real)i / (vlbe_real)NE;
    }
    if (m4_status("chain_init", vlbe_ale_chain_init(&ch, &el, node, NE + 1, NE + 1, con, 2)))
        return m4_exit();
    memset(&c, 0, sizeof c);
    c.type = VLBE_ALE_CON_POS;
    c.node = 0;
    if (m4_status("chain_add_pos", vlbe_ale_chain_add(&ch, &c))) return m4_exit();
    c.type = VLBE_ALE_CON_SLOPE;
    c.d[0] = VLBE_R(1.0);
    if (m4_status("chain_add_slope", vlbe_ale_chain_add(&ch, &c))) return m4_exit();
    if (m4_status("chain_layout", vlbe_ale_chain_layout(&ch))) return m4_exit();
    /* planar, every p fixed: VLBE_DAE_MASS_CONST */
    if (m4_status("chain_dae", vlbe_ale_chain_dae(&ch, &sys))) return m4_exit();
    m4_int("n", sys.n);
    m4_int("m", sys.m);
    lw = vlbe_hht_work_len_sys(&sys);
    liw = vlbe_hht_iwork_len_sys(&sys);
    if (lw > WORK_CAP || liw > IWORK_CAP || sys.n > 64) {
        m4_status("workspace", VLBE_EWORK);
        return m4_exit();
    }
    vlbe_ale_chain_straight(&ch, r0, dir, q0);
    if (m4_status("hht_params_hht", vlbe_hht_params_alpha(&par, VLBE_R(-0.05)))) return m4_exit();
    if (m4_status("hht_init", vlbe_hht_init(&st, &sys, &par, VLBE_R(0.0), q0, v0, work, lw, iwork,
                                            liw)))
        return m4_exit();
    for (k = 1; k <= 1000; ++k) {
        vlbe_status s = vlbe_hht_step(&st, VLBE_R(1e-3));
        if (s != VLBE_OK) {
            m4_int("failed_step", k - 1);
            m4_status("hht_step", s);
            break;
        }
        if (k % 250 == 0) print_tip();
    }
    m4_stats(&st.stats);
    return m4_exit();
}
