/* test_scenes_ale.c -- cmocka suite of the sliding-mass scenes of the planar
   ALE-ANCF element (ale-rancf sections 6.1 and 6.2: examples/falling_beam.c,
   examples/suspended_beam.c, their model and run loop scenes/ex_slide.h)
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
     rancf_unit_equals_ancf  ALE-RANCF with its unit start weights = ALE-ANCF
                       (falling beam, 5 elements) up to the first length-
                       control event: histories compared
     falling_beam_rancf  scene 6.1, 20 ALE-RANCF elements: the mass leaves,
                       merged weights positive, sigma finite
     suspended_beam_rancf  scene 6.2, ALE-RANCF, 1 s: status OK, splits exact,
                       merge arc-length jumps bounded and smaller than
                       ALE-ANCF's at the first merge (from the same state)
   The dynamic scenes run in float too (the default Newton tolerances
   follow the precision).  Bounds that stand for "the Newton tolerance's
   share" are 1000 times HHT's default rtol (1e-6 in double, 7.6e-3 in
   float), bounds of a rounding are multiples of VLBE_EPS (never below the
   double figure).
   Set VLBE_TEST_REPORT=1 to print the measured numbers. */
#include "test_util.h"
#include "../ancf_ale.h"
#include "../integrators.h"

#include "../scenes/falling_beam.h"
#include "../scenes/suspended_beam.h"

#include <float.h>
#include <stdlib.h>
#include <string.h>

#define EPS ((double)VLBE_EPS)

/* the energy a run of HHT with the default Newton tolerances may gain
   between events, per unit of the peak kinetic energy: 1000 rtol */
static double newton_share(void)
{
    vlbe_hht_params p;
    assert_int_equal(vlbe_hht_params_alpha(&p, VLBE_R(-0.05)), VLBE_OK);
    return 1e3 * (double)p.rtol;
}

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
   elements 0.1, 0.3, 0.2, 0.2, 0.2 m; measured 7.46e-5 (m:circle_deficit).
   Asserted within 5 % of that (the th^6 term of the 0.3 m element, th =
   0.6: ~1.5 %).
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
        tu_measured("circle_deficit", dev);
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
     peak kinetic energy (newton_share(); measured 1.3e-8 (m:fb_gain_rel),
     in float 4.3e-6 (m@flt:fb_gain_rel) of 7.6e-3).  The paper form
     is reported (it gains 3.5e-3 J (m:fb_paper_gain) here, more with more
     elements, examples/falling_beam.c: the missing flux of strain energy
     through the moving nodes). */
static void test_falling_beam(void **state)
{
    (void)state;
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
            if (f) {
                tu_measured("fb_gain_rel", r.dE_gain / r.T_max);
            } else {
                tu_measured("fb_paper_gain", r.dE_gain);
                tu_measured("fb_t_leave", r.t_leave);
                if (r.nev > 0) tu_measured("fb_first_event", r.ev[0].t);
            }
            assert_int_equal(r.status, VLBE_OK);
            assert_true(r.t_leave > 0.0);
            assert_true(r.lc_events >= 3);
            if (f) assert_true(r.dE_gain <= newton_share() * r.T_max);
        }
    }
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
     polynomials of degree 6 and 8, not for it): measured at most
     5e-9 (m:split_dE_max) J over the splits of the three runs, 1e-9
     (m:split_dE_rel) of the peak kinetic energy (the split at the first
     step, on the straight beam, changes it by rounding only), asserted
     below 1e-7 of it (float: 1e3 eps, the rounding of an energy of
     strain EA eps); the arc length (8-point Gauss of |r'|) to 1e-12 m
     (float: 64 eps L, the rounding of the sum); measured
     1e-15 (m~:split_dlen) m;
   - conservative form: no energy gain between events (newton_share() of
     the peak kinetic energy, as for the falling beam) and the loss, HHT's
     dissipation, falls with the step: h = 1e-3 -> 2.5e-4 divides it by at
     least 8 (the dissipation of HHT is O(h^2) for resolved motion, a ratio
     of 16; measured 21 (m:loss_ratio) over this 1 s; 8 leaves room for
     the unresolved axial modes);
   - paper form: it gains energy between events, more than 1e-2 of the peak
     kinetic energy (measured 3.4e-2 (m:sb_paper_gain_rel)): the flux the
     paper's virtual work leaves out (ancf_ale.h, VLBE_ALE_CONSERVATIVE); if
     this ever fails the paper form has become conservative and the
     finding of docs/results.md is stale. */
static void test_suspended_beam(void **state)
{
    (void)state;
    {
        ex_slide_cfg cfg;
        ex_slide_out r[3];
        static const double hs[3] = {1e-3, 2.5e-4, 1e-3};
        double dE_max = 0.0, dE_rel = 0.0, dlen = 0.0;
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
                    dE_max = fmax(dE_max, fabs(r[j].ev[k].dE));
                    dE_rel = fmax(dE_rel, fabs(r[j].ev[k].dE) / r[j].T_max);
                    dlen = fmax(dlen, fabs(r[j].ev[k].dlen));
                    assert_true(fabs(r[j].ev[k].dE) <= fmax(1e-7, 1e3 * EPS) * r[j].T_max);
                    assert_true(fabs(r[j].ev[k].dlen) <= fmax(1e-12, 64.0 * EPS * cfg.L));
                }
        }
        tu_measured("split_dE_max", dE_max);
        tu_measured("split_dE_rel", dE_rel);
        tu_measured("split_dlen", dlen);
        tu_measured("loss_ratio", r[0].dE_loss / r[1].dE_loss);
        tu_measured("sb_paper_gain_rel", r[2].dE_gain / r[2].T_max);
        assert_true(splits >= 1);
        assert_true(r[0].dE_gain <= newton_share() * r[0].T_max);
        assert_true(r[1].dE_gain <= newton_share() * r[1].T_max);
        assert_true(r[0].dE_loss < 0.0 && r[0].dE_loss <= 8.0 * r[1].dE_loss);
        assert_true(r[2].dE_gain > 1e-2 * r[2].T_max);
    }
}

/* ======================================================================= */
/* 4. ALE-RANCF (cfg.rational)                                              */
/* ======================================================================= */

/* (a) Unit weights: the rational element's basis is the Hermite one (the
   weighting function sum w_i N_i is 1 identically, eq. 9), so up to the
   first length-control event the ALE-RANCF run is the ALE-ANCF run.  The
   falling beam with 5 elements has its first event at t = 0.261 s
   (m:fb_first_event) (the ALE-ANCF run of test_falling_beam); t_end = 0.2 s
   leaves it out (asserted: no event in either run).
   The histories (tip y, mass x, y, p, energy, arc length) are compared
   row by row.  Tolerance: the two are different code paths (rancf.h
   divides by the weighting function and adds the terms of its derivatives,
   which are 0 here up to rounding), so they may differ by rounding per
   evaluation, propagated over 200 steps by a Newton iteration whose
   tolerance is far above rounding (a rounding difference that changes one
   iteration count leaves a difference of the order of that tolerance, not
   of EPS).  Measured: 0 (m~:rancf_unit_diff), bit for bit, in the dbl
   build and 0 (m@san~:rancf_unit_diff) in the unoptimised sanitizer
   build.  Asserted, so
   that a compiler contracting the two paths differently (FMA) does not
   fail it: 1e-9 relative to each history's largest magnitude (1e-9 stands
   for "the same trajectory": the rounding
   share of a 200-step Newton-converged run is far below it, any model
   difference, e.g. a weight derivative term not vanishing, gives O(1)
   relative changes in the tip motion).  In float: 0 too. */
static inline double hist_reldiff(const double *a, const double *b, int n)
{
    double d = 0.0, s = 0.0;
    int k;
    for (k = 0; k < n; ++k) {
        if (fabs(a[k]) > s) s = fabs(a[k]);
        if (fabs(a[k] - b[k]) > d) d = fabs(a[k] - b[k]);
    }
    return s > 0.0 ? d / s : d;
}

static void test_rancf_unit_equals_ancf(void **state)
{
    (void)state;
    {
        ex_slide_cfg cfg;
        ex_slide_out r[2];
        ex_slide_hist hi[2];
        int f, k;
        double worst = 0.0;
        for (f = 0; f < 2; ++f) {
            fb_cfg(&cfg, 5, 0u, 1e-3);
            cfg.t_end = 0.2;
            cfg.rational = f;
            assert_int_equal(ex_slide_hist_alloc(&hi[f], 256), 0);
            r[f] = ex_slide_run(&cfg, &hi[f]);
            assert_int_equal(r[f].status, VLBE_OK);
            assert_int_equal(r[f].lc_events, 0);
        }
        assert_int_equal(hi[0].n, hi[1].n);
        assert_true(hi[0].n > 150);
        for (k = 0; k < hi[0].n; ++k) assert_true(hi[0].t[k] == hi[1].t[k]);
        {
            const double *a[6] = {hi[0].probe_y, hi[0].mass_x, hi[0].mass_y, hi[0].mass_p,
                                  hi[0].energy, hi[0].length};
            const double *b[6] = {hi[1].probe_y, hi[1].mass_x, hi[1].mass_y, hi[1].mass_p,
                                  hi[1].energy, hi[1].length};
            static const char *nm[6] = {"tip y", "mass x", "mass y", "mass p", "energy",
                                        "arc length"};
            for (k = 0; k < 6; ++k) {
                const double d = hist_reldiff(a[k], b[k], hi[0].n);
                if (tu_report_on())
                    print_message("    rancf (unit weights) vs ancf, %s: largest relative "
                                  "difference %.3g\n", nm[k], d);
                if (d > worst) worst = d;
            }
        }
        tu_report("rancf unit weights vs ancf, largest relative history difference", worst, 1e-9);
        tu_measured("rancf_unit_diff", worst);
        assert_true(worst <= 1e-9);
        ex_slide_hist_free(&hi[0]);
        ex_slide_hist_free(&hi[1]);
    }
}

/* (b) Scene 6.1 with 20 ALE-RANCF elements: the mass leaves the beam
   (measured t_leave 0.731 (m:fbr_t_leave) s; the 5-element ALE-ANCF run
   of test_falling_beam 0.5655 (m:fb_t_leave) s, the paper's figures 0.6 to
   0.7 s; asserted in [0.55, 0.8], the paper's range widened by the spread
   of our meshes), the weights made by merges exist (the paper's Table 2:
   57 for 20 elements; measured 57 (m:fbr_nmerge)), are all positive (a
   weight <= 0 makes the element singular, eq. 9) and their sigma (eq. 42)
   is finite; no merge needed the unit-weight fallback of eq. 38. */
static void test_falling_beam_rancf(void **state)
{
    (void)state;
    {
        ex_slide_cfg cfg;
        ex_slide_out r;
        fb_cfg(&cfg, 20, 0u, 1e-3);
        cfg.rational = 1;
        r = ex_slide_run(&cfg, NULL);
        if (tu_report_on())
            print_message("    falling beam, 20 ALE-RANCF elements: %s, leaves at %.4f s, %ld "
                          "events, merged weights %ld in [%.4g, %.4g], sigma %.4g, fallbacks "
                          "%ld\n", vlbe_status_str(r.status), r.t_leave, r.lc_events, r.wmerge.n,
                          r.wmerge.kmin, r.wmerge.kmax, ex_slide_sigma(&r.wmerge),
                          r.merge_fallbacks);
        tu_measured("fbr_t_leave", r.t_leave);
        tu_measured("fbr_nmerge", (double)r.wmerge.n);
        assert_int_equal(r.status, VLBE_OK);
        assert_true(r.t_leave >= 0.55 && r.t_leave <= 0.8);
        assert_true(r.wmerge.n > 0);
        assert_true(r.wmerge.kmin > 0.0 && r.wall.kmin > 0.0);
        assert_true(isfinite(ex_slide_sigma(&r.wmerge)) && isfinite(ex_slide_sigma(&r.wall)));
        assert_true(r.merge_fallbacks == 0);
    }
}

/* (c) Scene 6.2, ALE-RANCF, 1 s (events: a split at the start, a merge at
   0.216 s (m:sbr_t_ev2), a split + merge at 0.602 s (m:sbr_t_ev3)).
   Asserted:
   - status OK;
   - a split (kind 1) changes the arc length by rounding only: 1e-12 m
     (float: 64 eps L), as for ALE-ANCF above (exact segmentation, eqs.
     21-28);
   - every event's |dlen| <= 1 mm = 3e-3 L_std.  Why this bound: the
     merged element keeps the end nodes' positions and slopes and fits the
     two pieces by least squares, so its length differs from theirs by the
     second-order shape error of that fit; measured at most
     0.133 (m:sbr_dlen_max) mm, 0.13 (m:sbr_dlen_min) mm at the other merge.
     The ALE-ANCF merge from the very same state (both models are identical
     up to the first merge, test (a)) jumps by 1.63 (m:sba_dlen_first) mm:
     the bound, 7.5 (m:sbr_bound_ratio) x the measured rational jump and 0.6
     (m:sba_bound_ratio) x the ALE-ANCF one, fails if the rational merge
     degrades to the Hermite one;
   - the paper's claim, at the first merge (same state before): |dE| and
     |dlen| of ALE-RANCF below those of ALE-ANCF (paper form); measured
     0.019 (m:sbr_dE_first) J vs 0.349 (m:sba_dE_first) J and
     0.13 (m:sbr_dlen_first) mm vs 1.63 (m:sba_dlen_first) mm. */
static void test_suspended_beam_rancf(void **state)
{
    (void)state;
    {
        ex_slide_cfg cfg;
        ex_slide_out r[2];
        const ex_slide_event *fm[2] = {NULL, NULL};
        double dlen_max = 0.0, dlen_min = INFINITY; /* ALE-RANCF events, merges [mm] */
        int f, k;
        for (f = 0; f < 2; ++f) {
            sb_cfg(&cfg, 0u, 1e-3, 1.0);
            cfg.rational = f;
            r[f] = ex_slide_run(&cfg, NULL);
            assert_int_equal(r[f].status, VLBE_OK);
            for (k = 0; k < r[f].nev; ++k) {
                const ex_slide_event *ev = &r[f].ev[k];
                if (tu_report_on())
                    print_message("    suspended beam, %s, event %d at %.4f s (kind %d): dE %.4g "
                                  "J, dlen %.4g mm\n", f ? "ALE-RANCF" : "ALE-ANCF", k + 1, ev->t,
                                  ev->changed, ev->dE, 1e3 * ev->dlen);
                if (ev->changed >= 2 && !fm[f]) fm[f] = ev;
                if (!f) continue;
                if (ev->changed == 1) assert_true(fabs(ev->dlen) <= fmax(1e-12, 64.0 * EPS * cfg.L));
                assert_true(fabs(ev->dlen) <= 1e-3);
                dlen_max = fmax(dlen_max, 1e3 * fabs(ev->dlen));
                if (ev->changed >= 2) dlen_min = fmin(dlen_min, 1e3 * fabs(ev->dlen));
                if (k == 1 || k == 2) tu_measured(k == 1 ? "sbr_t_ev2" : "sbr_t_ev3", ev->t);
            }
        }
        assert_true(r[1].lc_events >= 2);
        assert_non_null(fm[0]);
        assert_non_null(fm[1]);
        {
            /* the first merges' arc-length jumps [mm]; the bound is 1 mm */
            const double da = 1e3 * fabs(fm[0]->dlen), dr = 1e3 * fabs(fm[1]->dlen);
            tu_measured("sbr_dlen_max", dlen_max);
            tu_measured("sbr_dlen_min", dlen_min);
            tu_measured("sbr_bound_ratio", 1 / dlen_max);
            tu_measured("sba_bound_ratio", 1 / da);
            tu_measured("sba_dlen_first", da);
            tu_measured("sbr_dlen_first", dr);
            tu_measured("sba_dE_first", fabs(fm[0]->dE));
            tu_measured("sbr_dE_first", fabs(fm[1]->dE));
        }
        assert_true(fm[0]->t == fm[1]->t); /* the same state before it */
        assert_true(fabs(fm[1]->dE) < fabs(fm[0]->dE));
        assert_true(fabs(fm[1]->dlen) < fabs(fm[0]->dlen));
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_chain_length),
        cmocka_unit_test(test_falling_beam),
        cmocka_unit_test(test_suspended_beam),
        cmocka_unit_test(test_rancf_unit_equals_ancf),
        cmocka_unit_test(test_falling_beam_rancf),
        cmocka_unit_test(test_suspended_beam_rancf),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
