/* test_scenes_ale.c -- cmocka suite of the sliding-mass scenes of the planar
   ALE-ANCF element (ale-rancf sections 6.1 and 6.2: examples/falling_beam.c,
   examples/suspended_beam.c, their model and run loop examples/ex_slide.h)
   and of vlbe_ale_chain_length           -- part of vlbe
                                                   SPDX-License-Identifier: MIT
   cc -std=c99 -Wall -Wextra -Wpedantic ... -O2 tests/test_scenes_ale.c -lcmocka -lm

   Tests
     chain_length      arc length of a straight stretched chain = (1 + s) x
                       material length; its rate vs a central difference
                       along (t + e, q + e v) on a curved chain with a moving
                       sliding node and moving ends
     falling_beam      scene 2, 5 elements, both forms: the run goes through
                       the length control to the mass leaving the beam; the
                       conservative element never gains energy between
                       length-control events
     suspended_beam    scene 3, 3 elements: splits change nothing, the
                       conservative element never gains energy and loses
                       less with a smaller step (HHT dissipation); the paper
                       form gains energy (its missing flux)
   The dynamic scenes run in double only: in float the Newton tolerances of
   HHT sit near FLT_EPSILON and the ill-conditioned short elements of the
   length control do not converge (a statement about float, not a test).
   Set VLBE_TEST_REPORT=1 to print the measured numbers. */
#include "test_util.h"
#include "../ancf_ale.h"
#include "../integrators.h"

#define VLBE_EXAMPLE_NO_MAIN
#include "../examples/falling_beam.c"
#include "../examples/suspended_beam.c"

#include <float.h>
#include <stdlib.h>
#include <string.h>

#define EPS ((double)VLBE_EPS)

/* ======================================================================= */
/* 1. vlbe_ale_chain_length                                                 */
/* ======================================================================= */

/* The falling-beam chain (5 elements, sliding node at p = 0.1, fixed p
   elsewhere) with its nodes on a circle of radius R through the origin,
   stretched by s: node at p gets r = (1 + s) R (sin(p/R), 1 - cos(p/R)),
   r' = (1 + s) (cos(p/R), sin(p/R)). */
static void arc_state(ex_slide *m, double R, double s, vlbe_real *q)
{
    int i;
    for (i = 0; i < m->ch.nn; ++i) {
        const vlbe_ale_node *nd = &m->node[i];
        const double p = (double)nd->p, a = p / R;
        vlbe_real *x = q + nd->ofs;
        if (R <= 0.0) { /* straight */
            x[0] = (vlbe_real)((1.0 + s) * p);
            x[1] = VLBE_R(0.0);
            x[2] = (vlbe_real)(1.0 + s);
            x[3] = VLBE_R(0.0);
        } else {
            x[0] = (vlbe_real)((1.0 + s) * R * sin(a));
            x[1] = (vlbe_real)((1.0 + s) * R * (1.0 - cos(a)));
            x[2] = (vlbe_real)((1.0 + s) * cos(a));
            x[3] = (vlbe_real)((1.0 + s) * sin(a));
        }
        if (nd->pmode == VLBE_ALE_PFREE) x[4] = nd->p;
    }
}

/* (a) Straight, stretched by s = 0.03: |r'| = 1.03 everywhere (the cubic
   Hermite interpolant of a straight uniformly stretched line is that line),
   so the 8-point Gauss sum is exact up to rounding: a few EPS relative (the
   sum of 40 terms of size ~L/40).  A circle of radius R = 0.5 through the
   1 m chain: the cubic Hermite interpolant of an arc of angle th (end
   tangents of the arc-length parametrisation) is shorter than the arc by
   th^4 / 720 relative, to O(th^6) (series expansion, checked numerically:
   1/720.2 at th = 0.2, 1/731 at 0.6), so the chain is shorter than
   (1 + s) L by sum_e L_e th_e^4 / 720 / L, th_e = L_e / R: 7.56e-5 for the
   elements 0.1, 0.3, 0.2, 0.2, 0.2 m; measured 7.46e-5.  Asserted within
   5 % of that (the th^6 term of the 0.3 m element, th = 0.6: ~1.5 %).
   (b) The rate: on the circle, velocities of every coordinate set to a
   fixed pseudo-random pattern (the sliding node's p' = 0.3 m/s, so the
   transport terms dS/dp e p' enter), the ends' p fixed; then a chain with
   its last node prescribed (p = 1 + 0.2 t: the end term |r'| p' enters).
   Central difference of the length along (t +- e, q +- e v), e = 1e-5 (the
   truncation error e^2 L''' / 6 ~ 1e-10 and rounding EPS L / e ~ 2e-11 of a
   rate ~1): agreement to 1e-8 absolute. */
static void test_chain_length(void **state)
{
    ex_slide_cfg cfg;
    ex_slide *m = (ex_slide *)malloc(sizeof *m);
    vlbe_real q[EX_SLIDE_NMAX * 5], v[EX_SLIDE_NMAX * 5], qe[EX_SLIDE_NMAX * 5];
    vlbe_real len, rate, lp, lm;
    int i, pass;
    (void)state;
    assert_non_null(m);
    fb_cfg(&cfg, 5, 0u, 1e-3);
    assert_int_equal(ex_slide_build(m, &cfg, q, v), 0);

    arc_state(m, 0.0, 0.03, q);
    assert_int_equal(vlbe_ale_chain_length(&m->ch, VLBE_R(0.0), q, NULL, &len, NULL), VLBE_OK);
    tu_report("straight stretched chain, length", fabs((double)len - 1.03) / 1.03, 16.0 * EPS);
    ASSERT_CLOSE((double)len, 1.03, 16.0 * EPS, 0.0);

    arc_state(m, 0.5, 0.03, q);
    assert_int_equal(vlbe_ale_chain_length(&m->ch, VLBE_R(0.0), q, NULL, &len, NULL), VLBE_OK);
    {
        const double dev = (1.03 - (double)len) / 1.03;
        double pred = 0.0;
        for (i = 0; i + 1 < m->ch.nn; ++i) {
            const double Le = (double)(m->node[i + 1].p - m->node[i].p), th = Le / 0.5;
            pred += Le * th * th * th * th / 720.0;
        }
        tu_report("circle: length deficit vs sum L th^4/720", fabs(dev - pred) / pred, 0.05);
        ASSERT_CLOSE(dev, pred, 0.05, 0.0);
    }
#ifndef VLBE_USE_FLOAT
    for (pass = 0; pass < 2; ++pass) {
        const double e = 1e-5;
        if (pass == 1) { /* the last node prescribed: p = 1 + 0.2 t */
            m->node[m->ch.nn - 1].pmode = VLBE_ALE_PPRESCRIBED;
            m->node[m->ch.nn - 1].pd = VLBE_R(0.2);
            assert_int_equal(vlbe_ale_chain_layout(&m->ch), VLBE_OK);
            arc_state(m, 0.5, 0.03, q);
        }
        for (i = 0; i < m->ch.n; ++i) v[i] = (vlbe_real)(0.3 * sin(1.7 * i + 0.4));
        v[m->node[m->slider].ofs + 4] = VLBE_R(0.3);
        assert_int_equal(vlbe_ale_chain_length(&m->ch, VLBE_R(0.0), q, v, &len, &rate), VLBE_OK);
        for (i = 0; i < m->ch.n; ++i) qe[i] = q[i] + (vlbe_real)e * v[i];
        assert_int_equal(vlbe_ale_chain_length(&m->ch, (vlbe_real)e, qe, NULL, &lp, NULL), VLBE_OK);
        for (i = 0; i < m->ch.n; ++i) qe[i] = q[i] - (vlbe_real)e * v[i];
        assert_int_equal(vlbe_ale_chain_length(&m->ch, (vlbe_real)-e, qe, NULL, &lm, NULL),
                         VLBE_OK);
        tu_report(pass ? "length rate vs central difference, moving end"
                       : "length rate vs central difference",
                  fabs((double)rate - (double)(lp - lm) / (2.0 * e)), 1e-8);
        ASSERT_CLOSE((double)rate, (double)(lp - lm) / (2.0 * e), 0.0, 1e-8);
    }
#else
    (void)pass;
    (void)rate;
    (void)lp;
    (void)lm;
    (void)qe;
#endif
    /* a zero slope: a status, not a NaN */
    arc_state(m, 0.0, 0.0, q);
    for (i = 0; i < m->ch.nn; ++i) q[m->node[i].ofs + 2] = q[m->node[i].ofs + 3] = VLBE_R(0.0);
    for (i = 0; i < m->ch.nn; ++i) q[m->node[i].ofs] = VLBE_R(0.0);
    assert_int_equal(vlbe_ale_chain_length(&m->ch, VLBE_R(0.0), q, NULL, &len, NULL),
                     VLBE_ESINGULAR);
    free(m);
}

/* ======================================================================= */
/* 2. the falling beam (scene 2)                                            */
/* ======================================================================= */

/* 5 elements, h = 1e-3, both forms.  Facts asserted:
   - the run reaches the mass leaving the beam with status OK after at least
     3 length-control events (the paper counts 3 for 5 elements; without
     length control the element behind the mass would shrink to nothing,
     test_chain_ale.c's shrinking_element shows what happens then);
   - the conservative element does not gain energy between the events: HHT
     with alpha < 0 dissipates, an energy-consistent force model can only
     lose; the gain allowed is the Newton tolerance's share, 1e-6 of the
     peak kinetic energy (measured 1.3e-8).  The paper form is reported
     (it gains 3.5e-3 J here, 0.19 J with 40 elements: the missing flux of
     strain energy through the moving nodes). */
static void test_falling_beam(void **state)
{
    (void)state;
#ifndef VLBE_USE_FLOAT
    {
        int f;
        for (f = 0; f < 2; ++f) {
            ex_slide_cfg cfg;
            ex_slide_out r;
            fb_cfg(&cfg, 5, f ? VLBE_ALE_CONSERVATIVE : 0u, 1e-3);
            r = ex_slide_run(&cfg, NULL);
            if (tu_report_on())
                print_message("    falling beam, 5 elements, %s: %s, leaves at %.4f s, %ld events, "
                              "energy within steps [%.3g, %.3g] J, peak kinetic %.3g J\n",
                              f ? "conservative" : "paper form", vlbe_status_str(r.status),
                              r.t_leave, r.lc_events, r.dE_loss, r.dE_gain, r.T_max);
            assert_int_equal(r.status, VLBE_OK);
            assert_true(r.t_leave > 0.0);
            assert_true(r.lc_events >= 3);
            if (f) assert_true(r.dE_gain <= 1e-6 * r.T_max);
        }
    }
#endif
}

/* ======================================================================= */
/* 3. the suspended beam (scene 3)                                          */
/* ======================================================================= */

/* 3 elements, 1 s (three length-control events: a split at the start, a
   merge, a split + merge).  Facts asserted:
   - a split alone (event kind 1) changes neither the geometry nor the
     velocities (exact segmentation), so the energy changes only by the
     quadrature error of the bending energy (kappa^2 is rational in p; the
     5-point Gauss rule is exact for the kinetic and axial integrands,
     polynomials of degree 6 and 8, not for it): measured 5e-20 J and
     4e-9 J (1e-9 of the peak kinetic energy), asserted below 1e-7 of it;
     the arc length (8-point Gauss of |r'|) to 1e-12 m (measured 1e-15 m);
   - conservative form: no energy gain between events (1e-6 of the peak
     kinetic energy, as for the falling beam) and the loss, HHT's
     dissipation, falls with the step: h = 1e-3 -> 2.5e-4 divides it by at
     least 8 (the dissipation of HHT is O(h^2) for resolved motion, a ratio
     of 16; measured 21 over this 1 s; 8 leaves room for the unresolved
     axial modes);
   - paper form: it gains energy between events, more than 1e-2 of the peak
     kinetic energy (measured 3.3e-2): the flux the paper's virtual work
     leaves out (ancf_ale.h, VLBE_ALE_CONSERVATIVE); if this ever fails the
     paper form has become conservative and the README's finding is stale. */
static void test_suspended_beam(void **state)
{
    (void)state;
#ifndef VLBE_USE_FLOAT
    {
        ex_slide_cfg cfg;
        ex_slide_out r[3];
        static const double hs[3] = {1e-3, 2.5e-4, 1e-3};
        int j, k, splits = 0;
        for (j = 0; j < 3; ++j) {
            sb_cfg(&cfg, j < 2 ? VLBE_ALE_CONSERVATIVE : 0u, hs[j], 1.0);
            r[j] = ex_slide_run(&cfg, NULL);
            if (tu_report_on())
                print_message("    suspended beam, %s, h = %g: %s, %ld events, energy within steps "
                              "[%.3g, %.3g] J, peak kinetic %.3g J\n",
                              j < 2 ? "conservative" : "paper form", hs[j],
                              vlbe_status_str(r[j].status), r[j].lc_events, r[j].dE_loss,
                              r[j].dE_gain, r[j].T_max);
            assert_int_equal(r[j].status, VLBE_OK);
            assert_true(r[j].lc_events >= 2);
            for (k = 0; k < r[j].nev; ++k)
                if (r[j].ev[k].changed == 1) {
                    ++splits;
                    assert_true(fabs(r[j].ev[k].dE) <= 1e-7 * r[j].T_max);
                    assert_true(fabs(r[j].ev[k].dlen) <= 1e-12);
                }
        }
        assert_true(splits >= 1);
        assert_true(r[0].dE_gain <= 1e-6 * r[0].T_max);
        assert_true(r[1].dE_gain <= 1e-6 * r[1].T_max);
        assert_true(r[0].dE_loss < 0.0 && r[0].dE_loss <= 8.0 * r[1].dE_loss);
        assert_true(r[2].dE_gain > 1e-2 * r[2].T_max);
    }
#endif
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_chain_length),
        cmocka_unit_test(test_falling_beam),
        cmocka_unit_test(test_suspended_beam),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
