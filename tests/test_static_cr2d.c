/* test_static_cr2d.c -- cmocka suite of vlbe_dae_static (integrators.h) on
   the co-rotational cantilever of corot2d.h under a tip load stepped into
   the large-deflection range: the defaults against plain Newton and
   against the elastica                            -- part of vlbe
                                                   SPDX-License-Identifier: MIT
   cc -std=c99 -Wall -Wextra -Wpedantic ... -O2 tests/test_static_cr2d.c -lcmocka -lm

   The beam: the section of examples/corot_static.c (the sliding-beam
   paper's: EA = 2.995e6 N, EI = 0.7303 N m^2, EA L^2 / EI = 4.1e6), L = 1 m,
   clamped at x = 0 (vlbe_cr2d_fix on u, v, phi of node 0), N equal
   elements, banded matrices (vlbe_cr2d_beam_band), a dead tip load
   -P e_y with k = P L^2 / EI stepped 0.25, 0.5, ..., 10, each step solved
   from the last solution with its multipliers.

   The reference: the elastica of the inextensible Euler beam,
        theta'' = -k cos(theta) (s in [0, 1], theta the slope angle),
        theta(0) = 0, theta'(1) = 0 (no moment at the tip),
   x(1) = int cos(theta), y(1) = int sin(theta) (tip at (x, -y) L),
   by shooting on theta'(0) (bisection, theta'(1) changes sign between
   theta'(0) = 0 and k) with the classical Runge-Kutta method, 4000 steps
   (error ~h^4 ~ 1e-14, far below what is compared).  The closed form in
   elliptic integrals (Bisshopp and Drucker, Quart. Appl. Math. 3 (1945)
   272-275) gives the same numbers: tip deflection 0.30172 L at k = 1,
   0.81061 L at k = 10, which the shooting reproduces to 5 digits (checked
   below).

   Tests
     elastica_reference the shooting against Bisshopp and Drucker's table
     elastica_defaults  N = 16, 32, 64: every load step converges with the
                        default parameters; its Newton iterations at most
                        plain Newton's + 1 (the watchdog lets the full steps
                        through); the tip (u, v) against the elastica at
                        every step, to the discretisation and extension
                        error (stated at the test)
   The float build skips elastica_defaults: in float the iteration matrix of this section
   mixes EA / L_e = 5e7 N/m with rotational pivots of EI / L_e ~ 12 N m,
   below the LU's relative-zero test, and the solve fails with
   VLBE_ESINGULAR at q = 0 from 32 elements (tests/test_scenes_cr2d.c
   states the same for the roll-up). */
#include "test_util.h"
#include "../corot2d.h"
#include "../integrators.h"
#include "../scenes/corot_static.h"

#include <stdlib.h>
#include <string.h>

#define EPS ((double)VLBE_EPS)
#define NE_MAX CS_NE_MAX
#define NSTEP 40 /* k = 0.25 .. 10 */
#define KMAX 10.0

/* ------------------------------------------------------------------------ */
/* the elastica: theta'(1) for theta'(0) = c0, and the tip (x, y) / L */
static double ela_shoot(double k, double c0, double *x, double *y)
{
    const int n = 4000;
    const double h = 1.0 / n;
    double th = 0.0, w = c0, X = 0.0, Y = 0.0;
    int i;
    for (i = 0; i < n; ++i) {
        const double k1t = w, k1w = -k * cos(th), k1x = cos(th), k1y = sin(th);
        const double t2 = th + 0.5 * h * k1t, w2 = w + 0.5 * h * k1w;
        const double k2t = w2, k2w = -k * cos(t2), k2x = cos(t2), k2y = sin(t2);
        const double t3 = th + 0.5 * h * k2t, w3 = w + 0.5 * h * k2w;
        const double k3t = w3, k3w = -k * cos(t3), k3x = cos(t3), k3y = sin(t3);
        const double t4 = th + h * k3t, w4 = w + h * k3w;
        const double k4t = w4, k4w = -k * cos(t4), k4x = cos(t4), k4y = sin(t4);
        th += h / 6.0 * (k1t + 2.0 * k2t + 2.0 * k3t + k4t);
        w += h / 6.0 * (k1w + 2.0 * k2w + 2.0 * k3w + k4w);
        X += h / 6.0 * (k1x + 2.0 * k2x + 2.0 * k3x + k4x);
        Y += h / 6.0 * (k1y + 2.0 * k2y + 2.0 * k3y + k4y);
    }
    *x = X;
    *y = Y;
    return w;
}

/* tip (x, y) / L of the elastica at k = P L^2 / EI > 0 (y: deflection) */
static void elastica_tip(double k, double *x, double *y)
{
    double a = 0.0, b = k;
    int it;
    for (it = 0; it < 100; ++it) {
        const double c = 0.5 * (a + b);
        if (ela_shoot(k, c, x, y) < 0.0) a = c;
        else b = c;
    }
    (void)ela_shoot(k, 0.5 * (a + b), x, y);
}

/* ------------------------------------------------------------------------ */
#ifndef VLBE_USE_FLOAT
typedef cs_model cant;

/* the paper's cantilever (scenes/corot_static.h) under the elastica's tip
   force, banded */
static void cant_build(cant *c, int ne)
{
    assert_int_equal(cs_build(c, ne, 0), 0);
    assert_int_equal(cs_band(c), 0);
    cs_tip_force(c);
}

/* Steps k = KMAX j / NSTEP, j = 1..NSTEP, from the straight beam: the tips
   (u, v) of each step into tip[2 j - 2], tip[2 j - 1], the iterations into
   its[j - 1]; the status of the first failing step or VLBE_OK. */
static vlbe_status cant_run(cant *c, const vlbe_static_params *par, double *tip, long *its)
{
    static vlbe_real w[60000];
    static int iw[400];
    vlbe_real q[3 * (NE_MAX + 1)], lam[3] = {0, 0, 0};
    const size_t lw = vlbe_static_work_len_sys(&c->sys), liw = vlbe_static_iwork_len_sys(&c->sys);
    int j;
    assert_true(lw <= sizeof w / sizeof w[0] && liw <= sizeof iw / sizeof iw[0]);
    memset(q, 0, sizeof q);
    for (j = 1; j <= NSTEP; ++j) {
        vlbe_dae_stats st;
        vlbe_status rc;
        memset(&st, 0, sizeof st);
        c->beam.load = (vlbe_real)(KMAX * j / NSTEP);
        rc = vlbe_dae_static(&c->sys, par, VLBE_R(0.0), q, lam, &st, w, lw, iw, liw);
        its[j - 1] = st.newton_iters;
        if (rc != VLBE_OK) return rc;
        tip[2 * j - 2] = (double)q[3 * c->ne];
        tip[2 * j - 1] = (double)q[3 * c->ne + 1];
    }
    return VLBE_OK;
}

#endif

/* ------------------------------------------------------------------------ */
/* The reference: the shooting against the five digits of Bisshopp and
   Drucker's table (half a unit of the fifth digit), in every build (the
   shooting runs in double). */
static void test_elastica_reference(void **state)
{
    double x, y;
    (void)state;
    elastica_tip(1.0, &x, &y);
    ASSERT_CLOSE(y, 0.30172, 0.0, 5e-6);
    elastica_tip(10.0, &x, &y);
    ASSERT_CLOSE(y, 0.81061, 0.0, 5e-6);
}

/* Per N: defaults and plain Newton over the same 40 load steps; the
   defaults' iterations per step at most plain Newton's + 1 (measured: 0
   (m:ela_extra) more at any step).
   Tolerance of the tip against the elastica, per coordinate and load step:
   - discretisation: the tips of 16, 32 and 64 elements differ by 1.8e-6
     and 1.1e-7 L at k = 10 (order 4 in the element length, as the
     roll-up of examples/corot_static.c), and by about (k / 10)^2 of that
     at smaller loads: 0.3 (k / 10)^2 L / N^4, 2.5 times the 16-element
     difference;
   - extension: the elastica is inextensible; the beam stretches by at most
     P / EA = k EI / (EA L^2) = 2.4e-6 at k = 10, which moves the tip by
     at most about that times L: 1.5 k EI / (EA L) (the converged 64
     elements sit 1.9e-6 L from the elastica at k = 10);
   - the solve: converged to the increment test (rtol 1e-10), far below.
   Measured: up to 1.2e-6 (m:ela_err16) L at 16 elements (discretisation
   and extension of opposite sign), 1.9e-6 (m:ela_err64) L at 64. */
#ifndef VLBE_USE_FLOAT
static void test_elastica_defaults(void **state)
{
    static const int Ns[3] = {16, 32, 64};
    static cant c;
    double ref[2 * NSTEP], tip[2 * NSTEP], tip0[2 * NSTEP], err16 = 0.0, err64 = 0.0;
    long its[NSTEP], its0[NSTEP], extra = -1000;
    int i, j;
    (void)state;
    for (j = 1; j <= NSTEP; ++j) {
        double x, y;
        elastica_tip(KMAX * j / NSTEP, &x, &y);
        ref[2 * j - 2] = x - 1.0; /* u */
        ref[2 * j - 1] = -y;      /* v */
    }
    for (i = 0; i < 3; ++i) {
        const int N = Ns[i];
        vlbe_static_params par, plain;
        vlbe_static_params_default(&par);
        plain = par;
        plain.max_halvings = 0;
        cant_build(&c, N);
        assert_int_equal(cant_run(&c, &plain, tip0, its0), VLBE_OK);
        cant_build(&c, N);
        assert_int_equal(cant_run(&c, &par, tip, its), VLBE_OK);
        for (j = 1; j <= NSTEP; ++j) {
            const double k = KMAX * j / NSTEP;
            const double tol = 0.3 * (k / 10.0) * (k / 10.0) / ((double)N * N * N * N) +
                               1.5 * k * cs_EI() / cs_EA();
            const double e = fmax(fabs(tip[2 * j - 2] - ref[2 * j - 2]),
                                  fabs(tip[2 * j - 1] - ref[2 * j - 1]));
            assert_true(its[j - 1] <= its0[j - 1] + 1);
            extra = its[j - 1] - its0[j - 1] > extra ? its[j - 1] - its0[j - 1] : extra;
            ASSERT_CLOSE_CTX(tip[2 * j - 2], ref[2 * j - 2], 0.0, tol, "N = %d, k = %g, u", N, k);
            ASSERT_CLOSE_CTX(tip[2 * j - 1], ref[2 * j - 1], 0.0, tol, "N = %d, k = %g, v", N, k);
            if (N == 16) err16 = fmax(err16, e);
            if (N == 64) err64 = fmax(err64, e);
            if (tu_report_on() && (j % 8 == 0))
                print_message("    N = %2d, k = %5.2f: tip v %.9f (elastica %.9f), u %.9f (%.9f), "
                              "%ld iterations (plain Newton %ld)\n",
                              N, k, tip[2 * j - 1], ref[2 * j - 1], tip[2 * j - 2], ref[2 * j - 2],
                              its[j - 1], its0[j - 1]);
        }
    }
    tu_measured("ela_err16", err16);
    tu_measured("ela_err64", err64);
    tu_measured("ela_extra", (double)extra);
}
#else
static void test_elastica_defaults(void **state)
{
    (void)state;
    skip(); /* see the top: VLBE_ESINGULAR in float on this section */
}
#endif

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_elastica_reference),
        cmocka_unit_test(test_elastica_defaults),
    };
    return cmocka_run_group_tests_name("static_cr2d", tests, NULL, NULL);
}
