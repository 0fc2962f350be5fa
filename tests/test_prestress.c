/* test_prestress.c -- prestress of ALE-ANCF elements and chains
   (ancf_ale.h: vlbe_ale_prestretch, vlbe_ale_chain_window)
   -- part of vlbe                                 SPDX-License-Identifier: MIT

   prestretch_root     eps solves EA eps sqrt(1 + 2 eps) = F from tiny
                       tension to compression near the limit -EA / (3 sqrt 3):
                       the tension of the returned eps, evaluated in double,
                       equals F to 8 eps |F| (the root is a vlbe_real: its
                       rounding alone moves T by about eps |F|, and Newton
                       stops on the rounding of its residual, 2-3 eps |F|),
                       and lam^2 = 1 + 2 eps to 4 eps; F = 0 gives eps = 0,
                       lam = 1 exactly
   prestretch_bad      EA <= 0, a NaN, F at or below the least tension of a
                       stretched state: VLBE_EARG, outputs untouched
   window_steady       a string and a beam in an Eulerian window (nodes fixed
                       in space, material flowing at c = 3 m/s under tension
                       F = 100 N, EA = 1e4 N, pinned at both ends): the nodes'
                       places are the given s_i, the material point at node
                       2 at t = 0 is found c t downstream at t (to 16 eps of
                       the coordinates, rounding of the basis), and the
                       straight state is a
                       steady flow: the kinetic energy is that of the
                       material moving at c, rho A (l / lam) c^2 / 2 (to 16
                       eps: the quadrature of a constant is exact), the
                       consistent accelerations vanish and
                       the support reactions are the tension, +-F along the
                       span, 0 across.  Tolerance 64 eps / eps_F relative
                       (eps_F = 0.01 the Green strain: it is computed from
                       |r'|^2 - 1, which loses the digits of 1 / eps_F; 64
                       covers the sums over Gauss points and the solve):
                       1.4e-12 in double, 7.6e-4 in float; accelerations
                       against F / (rho A h) for positions and F / (rho A
                       h^2) for slopes (h the element length)
   window_bad          lam <= 0, s not increasing, a NaN: VLBE_EARG, the
                       nodes untouched */
#include "test_util.h"
#include "../ancf_ale.h"
#include "../integrators.h"

#include <string.h>

#define NE 4
#define NN (NE + 1)

static double tension(double EA, double e) { return EA * e * sqrt(1.0 + 2.0 * e); }

static void test_prestretch_root(void **state)
{
    const double ratio[] = {1e-7, 1.8e-4, 1e-2, 0.3, 2.0, 50.0, -1e-5, -0.05, -0.15, -0.19};
    const double EA = 5.5e6;
    const double eps = (double)VLBE_EPS;
    vlbe_real e = 0, lam = 0;
    size_t k;
    (void)state;
    for (k = 0; k < sizeof ratio / sizeof ratio[0]; ++k) {
        const double F = ratio[k] * EA;
        assert_int_equal(vlbe_ale_prestretch((vlbe_real)EA, (vlbe_real)F, &e, &lam), VLBE_OK);
        ASSERT_CLOSE_CTX(tension(EA, (double)e), F, 8.0 * eps, 0.0, "F / EA = %g", ratio[k]);
        ASSERT_CLOSE_CTX((double)lam * (double)lam, 1.0 + 2.0 * (double)e, 4.0 * eps, 0.0,
                         "F / EA = %g", ratio[k]);
        assert_true(F > 0.0 ? (double)lam > 1.0 : (double)lam < 1.0);
    }
    assert_int_equal(vlbe_ale_prestretch((vlbe_real)EA, 0, &e, &lam), VLBE_OK);
    assert_true((double)e == 0.0 && (double)lam == 1.0);
}

static void test_prestretch_bad(void **state)
{
    const vlbe_real EA = 1000;
    vlbe_real e = 7, lam = 9;
    (void)state;
    assert_int_equal(vlbe_ale_prestretch(0, 1, &e, &lam), VLBE_EARG);
    assert_int_equal(vlbe_ale_prestretch(-EA, 1, &e, &lam), VLBE_EARG);
    assert_int_equal(vlbe_ale_prestretch(EA, (vlbe_real)NAN, &e, &lam), VLBE_EARG);
    assert_int_equal(vlbe_ale_prestretch((vlbe_real)INFINITY, 1, &e, &lam), VLBE_EARG);
    /* the least tension of a stretched state is -EA / (3 sqrt 3) = -0.19245 EA */
    assert_int_equal(vlbe_ale_prestretch(EA, (vlbe_real)(-0.2 * 1000.0), &e, &lam), VLBE_EARG);
    assert_int_equal(vlbe_ale_prestretch(EA, -EA, &e, &lam), VLBE_EARG);
    assert_true((double)e == 7.0 && (double)lam == 9.0);
}

typedef struct win {
    vlbe_ale_mat mat;
    vlbe_ale_elem el;
    vlbe_ale_node node[NN];
    vlbe_ale_con con[2];
    vlbe_ale_chain ch;
    vlbe_dae sys;
    vlbe_real s[NN];
    vlbe_real q[5 * NN], v[5 * NN], a[5 * NN], lam[4];
    double eps, stretch;
} win;

static win W; /* the element's Gauss tables: static */

/* window of NE elements over [0.2, 1.2] along e = (0.6, 0.8), F = 100 N,
   EA = 1e4 N, rho A = 2 kg/m, c = 3 m/s; bend: EI = 1 N m^2 (else a string) */
static void win_build(win *w, int bend)
{
    const vlbe_real r0[2] = {VLBE_R(0.3), VLBE_R(-0.1)};
    vlbe_real dir[2], e = 0, lam = 0;
    int i;
    memset(w, 0, sizeof *w);
    w->mat.rhoA = 2;
    w->mat.EA = 10000;
    w->mat.EI = bend ? 1 : 0;
    assert_int_equal(vlbe_ale_elem_init(&w->el, &w->mat, bend ? 0u : VLBE_ALE_NO_BEND, 0, 0, 0),
                     VLBE_OK);
    assert_int_equal(vlbe_ale_prestretch(w->mat.EA, 100, &e, &lam), VLBE_OK);
    w->eps = (double)e;
    w->stretch = (double)lam;
    assert_int_equal(vlbe_ale_chain_init(&w->ch, &w->el, w->node, NN, NN, w->con, 2), VLBE_OK);
    for (i = 0; i < NN; ++i) w->s[i] = (vlbe_real)(0.2 + 1.0 * i / NE);
    assert_int_equal(vlbe_ale_chain_window(&w->ch, w->s, lam, 3), VLBE_OK);
    for (i = 0; i < NN; ++i) {
        assert_int_equal(w->node[i].pmode, VLBE_ALE_PPRESCRIBED);
        assert_true(w->node[i].p == w->s[i] / lam && w->node[i].pd == -3 / lam);
    }
    w->con[0].type = VLBE_ALE_CON_POS;
    w->con[0].node = 0;
    w->con[0].r[0] = r0[0];
    w->con[0].r[1] = r0[1];
    assert_int_equal(vlbe_ale_chain_add(&w->ch, &w->con[0]), VLBE_OK);
    w->con[1] = w->con[0];
    w->con[1].node = NE;
    w->con[1].r[0] = r0[0] + VLBE_R(0.6);
    w->con[1].r[1] = r0[1] + VLBE_R(0.8);
    assert_int_equal(vlbe_ale_chain_add(&w->ch, &w->con[1]), VLBE_OK);
    assert_int_equal(vlbe_ale_chain_layout(&w->ch), VLBE_OK);
    assert_int_equal(vlbe_ale_chain_dae(&w->ch, &w->sys), VLBE_OK);
    dir[0] = VLBE_R(0.6) * lam;
    dir[1] = VLBE_R(0.8) * lam;
    vlbe_ale_chain_straight(&w->ch, r0, dir, w->q);
}

static void test_window_steady(void **state)
{
    static vlbe_real work[4096];
    static int iwork[64];
    int bend, i, k;
    (void)state;
    for (bend = 0; bend <= 1; ++bend) {
        win *w = &W;
        double tol, h, aref, amax_r = 0.0, amax_s = 0.0;
        win_build(w, bend);
        assert_int_equal(w->ch.n, 4 * NN);
        assert_int_equal(w->ch.m, 4);
        tol = 64.0 * (double)VLBE_EPS / w->eps;
        h = 1.0 / NE;
        /* the nodes sit at the given places along the span */
        for (i = 0; i < NN; ++i) {
            const int o = w->node[i].ofs;
            const double sx = 0.3 + 0.6 * ((double)w->s[i] - 0.2);
            const double sy = -0.1 + 0.8 * ((double)w->s[i] - 0.2);
            ASSERT_CLOSE_CTX(w->q[o], sx, 0.0, 8.0 * (double)VLBE_EPS, "node %d", i);
            ASSERT_CLOSE_CTX(w->q[o + 1], sy, 0.0, 8.0 * (double)VLBE_EPS, "node %d", i);
        }
        memset(w->v, 0, sizeof w->v);
        assert_true(vlbe_dae_work_len(w->ch.n, w->ch.m) <= sizeof work / sizeof work[0]);
        assert_int_equal(vlbe_dae_consistent_acc(&w->sys, 0, w->q, w->v, w->a, w->lam, NULL, work,
                                                 sizeof work / sizeof work[0], iwork, 64),
                         VLBE_OK);
        aref = 100.0 / (2.0 * h);
        for (i = 0; i < NN; ++i)
            for (k = 0; k < 4; ++k) {
                const double a = fabs((double)w->a[w->node[i].ofs + k]);
                if (k < 2) amax_r = a > amax_r ? a : amax_r;
                else amax_s = a > amax_s ? a : amax_s;
            }
        tu_report(bend ? "window beam: max |a| of positions / (F / rho A h)"
                       : "window string: max |a| of positions / (F / rho A h)",
                  amax_r / aref, tol);
        assert_true(amax_r <= tol * aref);
        assert_true(amax_s <= tol * aref / h);
        /* the material point at node 2 at t = 0 is c t further down the
           span at t = 0.05 s (the chain's nodes have not moved) */
        {
            const double t = 0.05, sd = (double)w->s[2] - 0.2 + 3.0 * t;
            vlbe_real r[2], rp[2];
            assert_int_equal(vlbe_ale_chain_point(&w->ch, (vlbe_real)t, w->q, w->node[2].p, r, rp),
                             VLBE_OK);
            ASSERT_CLOSE(r[0], 0.3 + 0.6 * sd, 0.0, 16.0 * (double)VLBE_EPS);
            ASSERT_CLOSE(r[1], -0.1 + 0.8 * sd, 0.0, 16.0 * (double)VLBE_EPS);
        }
        /* the material moves at c in space: T = rho A (l / lam) c^2 / 2 */
        {
            vlbe_real E[3] = {0, 0, 0};
            assert_int_equal(vlbe_ale_chain_energy(&w->ch, 0, w->q, w->v, E), VLBE_OK);
            ASSERT_CLOSE(E[0], 0.5 * 2.0 * (1.0 / w->stretch) * 9.0, 16.0 * (double)VLBE_EPS, 0.0);
        }
        /* reactions: C_q^T lambda = Q at rest: +F e at node 0, -F e at the end */
        ASSERT_CLOSE(w->lam[0], 60.0, tol, 0.0);
        ASSERT_CLOSE(w->lam[1], 80.0, tol, 0.0);
        ASSERT_CLOSE(w->lam[2], -60.0, tol, 0.0);
        ASSERT_CLOSE(w->lam[3], -80.0, tol, 0.0);
    }
}

static void test_window_bad(void **state)
{
    win *w = &W;
    vlbe_ale_node before[NN];
    vlbe_real s[NN];
    int i;
    (void)state;
    memset(w, 0, sizeof *w);
    w->mat.rhoA = 2;
    w->mat.EA = 10000;
    assert_int_equal(vlbe_ale_elem_init(&w->el, &w->mat, VLBE_ALE_NO_BEND, 0, 0, 0), VLBE_OK);
    for (i = 0; i < NN; ++i) {
        w->node[i].pmode = VLBE_ALE_PFIXED;
        w->node[i].p = (vlbe_real)(0.25 * i);
        s[i] = (vlbe_real)(0.25 * i);
    }
    assert_int_equal(vlbe_ale_chain_init(&w->ch, &w->el, w->node, NN, NN, w->con, 2), VLBE_OK);
    memcpy(before, w->node, sizeof before);
    assert_int_equal(vlbe_ale_chain_window(&w->ch, s, 0, 1), VLBE_EARG);
    assert_int_equal(vlbe_ale_chain_window(&w->ch, s, -1, 1), VLBE_EARG);
    assert_int_equal(vlbe_ale_chain_window(&w->ch, s, (vlbe_real)NAN, 1), VLBE_EARG);
    assert_int_equal(vlbe_ale_chain_window(&w->ch, s, 1, (vlbe_real)INFINITY), VLBE_EARG);
    s[2] = s[1];
    assert_int_equal(vlbe_ale_chain_window(&w->ch, s, 1, 1), VLBE_EARG);
    s[2] = (vlbe_real)NAN;
    assert_int_equal(vlbe_ale_chain_window(&w->ch, s, 1, 1), VLBE_EARG);
    assert_memory_equal(before, w->node, sizeof before);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_prestretch_root),
        cmocka_unit_test(test_prestretch_bad),
        cmocka_unit_test(test_window_steady),
        cmocka_unit_test(test_window_bad),
    };
    return cmocka_run_group_tests_name("prestress", tests, NULL, NULL);
}
