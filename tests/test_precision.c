/* test_precision.c -- cmocka suite of the precision-aware defaults of
   integrators.h: the default tolerances follow VLBE_EPS, and a stiff steel
   cantilever runs with them in double and in float -- part of vlbe
                                                   SPDX-License-Identifier: MIT
   cc -std=c99 -Wall -Wextra -Wpedantic ... -O2 tests/test_precision.c -lcmocka -lm
   (add -DVLBE_USE_FLOAT for the float build; the same source passes in both)

   The cantilever: 4 Lagrangian planar ALE-ANCF elements, 1 m, steel-like
   section rhoA = 7.85 kg/m, EA = 2.1e8 N, EI = 1.75e3 N m^2, gravity as
   the distributed load q = rhoA g, clamped at node 0 (position and slope
   constraints), straight and at rest at t = 0.  In float its axial force
   is known to EA eps = 25 N only (the strain (|r'|^2 - 1)/2 of a unit
   slope carries a rounding of eps), as large as the weight of an element
   (19 N): the consistent start's multipliers and q'' carry that noise, and
   the Newton iteration of the first step starts far from its solution.

   Tests
     tolerance_defaults   HHT (three families), BDF, static: the double
                          values in double; in float the floors 64 eps
                          (relative) and 8 eps (absolute); in every build
                          rtol >= 64 eps and atol >= 8 eps
     cantilever_static    vlbe_dae_static with defaults: tip deflection vs
                          the Euler-Bernoulli q L^4 / (8 EI)
     cantilever_dynamic   HHT-alpha -0.05 with defaults, h = 1 ms, to
                          t = 1 s without a failed step: the tip stays in
                          the band of a suddenly applied load (0 to twice
                          the static deflection), its mean over the run is
                          the static deflection, and the energy balance */
#include "test_util.h"
#include "../ancf_ale.h"
#include "../integrators.h"

#include <string.h>

#define EPS ((double)VLBE_EPS)

/* -- the cantilever ------------------------------------------------------- */
enum { CT_NE = 4, CT_NN = CT_NE + 1, CT_WLEN = 8192, CT_IWLEN = 256 };
#define CT_RHOA 7.85
#define CT_EA 2.1e8
#define CT_EI 1.75e3
#define CT_G 9.81

typedef struct ct_model {
    vlbe_ale_mat mat;
    vlbe_ale_elem el;
    vlbe_ale_node node[CT_NN];
    vlbe_ale_con con[2];
    vlbe_ale_chain ch;
    vlbe_dae sys;
    vlbe_real q[CT_NN * 4], v[CT_NN * 4], lam[8];
    vlbe_real w[CT_WLEN];
    int iw[CT_IWLEN];
} ct_model;

static void ct_setup(ct_model *c)
{
    vlbe_ale_con k;
    vlbe_real r0[2] = {0, 0}, dir[2] = {1, 0};
    int i;
    memset(c, 0, sizeof *c);
    c->mat.rhoA = VLBE_R(7.85);
    c->mat.EA = VLBE_R(2.1e8);
    c->mat.EI = VLBE_R(1.75e3);
    c->mat.f[1] = -VLBE_R(9.81) * c->mat.rhoA;
    assert_int_equal(vlbe_ale_elem_init(&c->el, &c->mat, 0, 0, 0, 0), VLBE_OK);
    for (i = 0; i < CT_NN; ++i) {
        c->node[i].pmode = VLBE_ALE_PFIXED;
        c->node[i].p = (vlbe_real)i / (vlbe_real)CT_NE;
    }
    assert_int_equal(vlbe_ale_chain_init(&c->ch, &c->el, c->node, CT_NN, CT_NN, c->con, 2),
                     VLBE_OK);
    memset(&k, 0, sizeof k);
    k.type = VLBE_ALE_CON_POS;
    k.node = 0;
    assert_int_equal(vlbe_ale_chain_add(&c->ch, &k), VLBE_OK);
    k.type = VLBE_ALE_CON_SLOPE;
    k.d[0] = VLBE_R(1.0);
    assert_int_equal(vlbe_ale_chain_add(&c->ch, &k), VLBE_OK);
    assert_int_equal(vlbe_ale_chain_layout(&c->ch), VLBE_OK);
    /* planar, every p fixed: VLBE_DAE_MASS_CONST */
    assert_int_equal(vlbe_ale_chain_dae(&c->ch, &c->sys), VLBE_OK);
    vlbe_ale_chain_straight(&c->ch, r0, dir, c->q);
    assert_true(vlbe_hht_work_len(c->ch.n, c->ch.m) <= CT_WLEN);
    assert_true(vlbe_static_work_len(c->ch.n, c->ch.m) <= CT_WLEN);
    assert_true(vlbe_hht_iwork_len(c->ch.n, c->ch.m) <= CT_IWLEN);
}

/* static tip deflection of the Euler-Bernoulli cantilever, q L^4 / (8 EI) */
static double ct_w_static(void) { return CT_RHOA * CT_G / (8.0 * CT_EI); }

/* The tolerance of a tip deflection in float: the axial force is known to
   EA eps, and an axial force N changes the bending stiffness of the
   cantilever by N / N_cr (N_cr = pi^2 EI / (4 L^2), Euler's load of the
   clamped-free column): |dw / w| <= EA eps / N_cr = 5.8e-3 in float,
   5e-11 in double. */
static double ct_noise_rel(void)
{
    const double pi = 3.14159265358979323846;
    return CT_EA * EPS / (pi * pi * CT_EI / 4.0);
}

/* ------------------------------------------------------------------------ */
static void test_tolerance_defaults(void **state)
{
    vlbe_hht_params h[3];
    vlbe_bdf_params b;
    vlbe_static_params s;
    const double rfl = 64.0 * EPS, afl = 8.0 * EPS; /* the floors */
    int k;
    (void)state;
    vlbe_hht_params_newmark(&h[0], VLBE_R(0.25), VLBE_R(0.5));
    assert_int_equal(vlbe_hht_params_alpha(&h[1], VLBE_R(-0.05)), VLBE_OK);
    assert_int_equal(vlbe_hht_params_genalpha(&h[2], VLBE_R(0.8)), VLBE_OK);
    vlbe_bdf_params_default(&b);
    vlbe_static_params_default(&s);
    for (k = 0; k < 3; ++k) {
        ASSERT_CLOSE(h[k].rtol, 1e-9 > rfl ? (double)VLBE_R(1e-9) : rfl, 0.0, 0.0);
        ASSERT_CLOSE(h[k].atol, 1e-11 > afl ? (double)VLBE_R(1e-11) : afl, 0.0, 0.0);
    }
    ASSERT_CLOSE(b.rtol, 1e-6 > rfl ? (double)VLBE_R(1e-6) : rfl, 0.0, 0.0);
    ASSERT_CLOSE(b.atol, 1e-8 > afl ? (double)VLBE_R(1e-8) : afl, 0.0, 0.0);
    ASSERT_CLOSE(s.rtol, 1e-10 > rfl ? (double)VLBE_R(1e-10) : rfl, 0.0, 0.0);
    ASSERT_CLOSE(s.atol, 1e-12 > afl ? (double)VLBE_R(1e-12) : afl, 0.0, 0.0);
    /* in every build above what the arithmetic resolves */
    assert_true((double)h[1].rtol >= rfl && (double)h[1].atol >= afl);
    assert_true((double)b.rtol >= rfl && (double)b.atol >= afl);
    assert_true((double)s.rtol >= rfl && (double)s.atol >= afl);
#ifdef VLBE_USE_FLOAT
    /* the double values would sit below float's resolution */
    assert_true((double)h[1].rtol > 1e-9 && (double)b.rtol > 1e-6 && (double)s.rtol > 1e-10);
#endif
}

/* Static equilibrium with the default parameters.  The Hermite cubic gives
   the exact nodal deflections of the linear beam under a uniform load; the
   ANCF element is geometrically nonlinear, which changes the tip by
   (w / L)^2 = 3e-5 relative; float adds the axial-force noise
   (ct_noise_rel).  Tolerance 1e-4 + that noise. */
static void test_cantilever_static(void **state)
{
    static ct_model c;
    vlbe_static_params par;
    vlbe_dae_stats st;
    double ws = ct_w_static(), tip, tol = 1e-4 + ct_noise_rel();
    (void)state;
    ct_setup(&c);
    vlbe_static_params_default(&par);
    memset(&st, 0, sizeof st);
    assert_int_equal(vlbe_dae_static(&c.sys, &par, 0, c.q, c.lam, &st, c.w, CT_WLEN, c.iw,
                                     CT_IWLEN),
                     VLBE_OK);
    tip = -(double)c.q[4 * CT_NE + 1];
    tu_report("cantilever static tip vs qL^4/8EI", fabs(tip - ws) / ws, tol);
    ASSERT_CLOSE(tip, ws, tol, 0.0);
}

/* HHT-alpha -0.05 with every default (no step halving), h = 1 ms, 1000
   steps.  A load switched on at t = 0 on a structure at rest: each mode
   oscillates about its static share between 0 and twice it, so the tip
   stays within [0, 2 w_s] (5 % margin for the higher modes' phases) and
   its mean over the run is w_s: the first mode (52.5 rad/s, 8.4 periods
   in 1 s) leaves at most w_s / (omega_1 T) = 1.9 % of w_s from the
   unfinished period, the higher modes less: tolerance 3 %.  Energy: the
   work of gravity (q times the area under the deflection, m g times the
   mean drop) equals kinetic plus strain energy plus what HHT dissipates,
   which is >= 0: V + T + U <= 0 within the rounding of V (float: EA eps
   noise in U, bounded by 1e-3 of |V| here). */
static void test_cantilever_dynamic(void **state)
{
    static ct_model c;
    vlbe_hht_params par;
    vlbe_hht st;
    double ws = ct_w_static(), sum = 0.0, ymin = 0.0, ymax = 0.0;
    vlbe_real E[3] = {0, 0, 0};
    int k, nk = 1000;
    (void)state;
    ct_setup(&c);
    assert_int_equal(vlbe_hht_params_alpha(&par, VLBE_R(-0.05)), VLBE_OK);
    assert_int_equal(vlbe_hht_init(&st, &c.sys, &par, 0, c.q, c.v, c.w, CT_WLEN, c.iw, CT_IWLEN),
                     VLBE_OK);
    for (k = 0; k < nk; ++k) {
        double y;
        vlbe_status rc = vlbe_hht_step(&st, VLBE_R(1e-3));
        if (rc != VLBE_OK) print_message("step %d: %s\n", k, vlbe_status_str(rc));
        assert_int_equal(rc, VLBE_OK);
        y = -(double)st.q[4 * CT_NE + 1];
        sum += y;
        if (y < ymin) ymin = y;
        if (y > ymax) ymax = y;
    }
    ASSERT_CLOSE(st.t, 1.0, 4.0 * EPS, 0.0);
    assert_int_equal(st.stats.rejected, 0);
    tu_report("cantilever HHT mean tip vs w_s", fabs(sum / nk - ws) / ws, 0.03);
    ASSERT_CLOSE(sum / nk, ws, 0.03, 0.0);
    assert_true(ymin >= -0.05 * ws && ymax <= 2.05 * ws);
    assert_int_equal(vlbe_ale_chain_energy(&c.ch, st.t, st.q, st.v, E), VLBE_OK);
    {
        double tot = (double)E[0] + (double)E[1] + (double)E[2], v = fabs((double)E[2]);
        tu_report("cantilever HHT (T + U + V) / |V|", tot / v, 1e-3);
        assert_true(tot <= 1e-3 * v);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_tolerance_defaults),
        cmocka_unit_test(test_cantilever_static),
        cmocka_unit_test(test_cantilever_dynamic),
    };
    return cmocka_run_group_tests_name("precision", tests, NULL, NULL);
}
