/* test_scenes_cr2d.c -- cmocka suite of the static scene of the planar
   co-rotational beam (examples/corot_static.c: roll-up, cantilever
   frequencies, rigid rotation; the eigen-solvers it uses are
   tests/test_eig.c's)                             -- part of vlbe
                                                   SPDX-License-Identifier: MIT
   cc -std=c99 -Wall -Wextra -Wpedantic ... -O2 tests/test_scenes_cr2d.c -lcmocka -lm

   Every reference is a closed form derived independently of the code under
   test (textbook formulas, or by hand from the element's equations, see
   the top of examples/corot_static.c); every tolerance says why it has
   its size.  Checks that need more than float precision sit under
   #ifndef VLBE_USE_FLOAT with the reason.

   Tests
     freq_one_element  one clamped element: the quadratic det(K - w^2 M) = 0
                       of the textbook Hermite matrices, and the axial rod
     freq_convergence  4, 8, 16 elements: bending w1..w3 above the
                       Euler-Bernoulli values (Rayleigh-Ritz) and converging
                       at order 4; first axial mode at order 2
     rollup            4, 8, 16 elements, 8 load steps: every node on the
                       discrete closed form (exact angles, radius R_d);
                       order 4 of the tip error against the exact arc; at
                       lambda = 1 the tip back at the root with phi = 2 pi;
                       the LINEAR element's tip deflection M L^2 / (2 EI)
     rigid_rotation    Q at rounding level for rigid rotations up to 6
                       turns; the LINEAR element's tip force 2 EA at psi = pi
   Set VLBE_TEST_REPORT=1 to print the measured numbers. */
#include "test_util.h"
#include "../corot2d.h"
#include "../integrators.h"

#include "../scenes/corot_static.h"

#include <float.h>
#include <stdlib.h>
#include <string.h>

#define EPS ((double)VLBE_EPS)
#define PI 3.14159265358979323846

/* ======================================================================= */
/* 1. cantilever frequencies                                                */
/* ======================================================================= */

/* One element, clamped at node 1: coordinates (u2, v2, phi2).  Bending
   with the textbook Hermite matrices (Przemieniecki, Theory of Matrix
   Structural Analysis, 1968; any FE text): on (v2, phi2), L = 1,
       K = EI [[12, -6], [-6, 4]],   M = rhoA / 420 [[156, -22], [-22, 4]],
   det(K - w^2 M) = 0 with mu = w^2 rhoA / (420 EI):
       140 mu^2 - 408 mu + 12 = 0,
   mu1 = 24 / (408 + sqrt(159744)) (w1 = 3.5327 sqrt(EI / rhoA)),
   mu2 = (408 + sqrt(159744)) / 280 (w2 = 34.807 sqrt(EI / rhoA)).
   Axial: EA u2 = w^2 (rhoA / 3) u2, w^2 = 3 EA / rhoA.
   Tolerance: rounding only.  The reduction is shift-invert with sigma =
   0 (see cs_freqs): Jacobi's absolute error is a few EPS times the largest
   eigenvalue 1/w1^2, so w1 is kept to a few EPS relative and w2 to a few
   EPS (w2/w1)^2 = 97 EPS: asserted 32 EPS and 8 EPS (w2/w1)^2 (measured
   1 (m~:one_w1_eps) and 14 (m~:one_w2_eps) EPS in double).  The axial
   coordinate is decoupled at rest (its row and column are exactly zero
   off the diagonal): a 1x1 block that no rotation touches, 32 EPS
   (measured 0 (m~:one_axial_eps) EPS). */
static void test_freq_one_element(void **state)
{
    const double EI = cs_EI(), EA = cs_EA(), rA = cs_rhoA();
    const double sq = sqrt(159744.0);
    const double w1 = sqrt(420.0 * EI / rA * 24.0 / (408.0 + sq));
    const double w2 = sqrt(420.0 * EI / rA * (408.0 + sq) / 280.0);
    const double wa = sqrt(3.0 * EA / rA), tol2 = 8.0 * EPS * (w2 / w1) * (w2 / w1);
    double wb[2] = {0, 0}, wx = 0;
    (void)state;
    assert_int_equal(cs_freqs(1, 1, 2, wb, &wx), VLBE_OK);
    tu_report("1 element: w1 vs det(K - w^2 M) = 0", fabs(wb[0] - w1) / w1, 32.0 * EPS);
    tu_report("1 element: w2 vs det(K - w^2 M) = 0", fabs(wb[1] - w2) / w2, tol2);
    tu_report("1 element: axial w vs sqrt(3 EA / rhoA)", fabs(wx - wa) / wa, 32.0 * EPS);
    tu_measured("one_w1_eps", fabs(wb[0] - w1) / w1 / EPS);
    tu_measured("one_w2_eps", fabs(wb[1] - w2) / w2 / EPS);
    tu_measured("one_axial_eps", fabs(wx - wa) / wa / EPS);
    ASSERT_CLOSE(wb[0], w1, 32.0 * EPS, 0.0);
    ASSERT_CLOSE(wb[1], w2, tol2, 0.0);
    ASSERT_CLOSE(wx, wa, 32.0 * EPS, 0.0);
    /* the shift far below, sigma = -S, S = max K0_ii / M_ii (the axial
       3 EA / rhoA = wa^2 here): every mu = 1/(w^2 + S) is near 1/S and
       w^2 = sigma + 1/mu carries the rounding of S: w_k relative to a
       few EPS (1 + S / w_k^2) (8 asserted); w1 pays the factor
       (wa/w1)^2 */
    assert_int_equal(cs_freqs(1, 0, 2, wb, &wx), VLBE_OK);
    tu_report("1 element, sigma = -S: w1", fabs(wb[0] - w1) / w1,
              8.0 * EPS * (1.0 + wa * wa / (w1 * w1)));
    ASSERT_CLOSE(wb[0], w1, 8.0 * EPS * (1.0 + wa * wa / (w1 * w1)), 0.0);
    ASSERT_CLOSE(wb[1], w2, 8.0 * EPS * (1.0 + wa * wa / (w2 * w2)), 0.0);
    ASSERT_CLOSE(wx, wa, 32.0 * EPS, 0.0);
    /* the Euler-Bernoulli roots of the example against the five-digit
       table (Blevins, Formulas for Natural Frequency and Mode Shape):
       within half a unit of the fifth digit */
    ASSERT_CLOSE(ex_cant_root(1), 1.8751, 0.0, 0.5e-4);
    ASSERT_CLOSE(ex_cant_root(2), 4.6941, 0.0, 0.5e-4);
    ASSERT_CLOSE(ex_cant_root(3), 7.8548, 0.0, 0.5e-4);
    ASSERT_CLOSE(1.0 + cos(ex_cant_root(3)) * cosh(ex_cant_root(3)), 0.0, 0.0, 1e-12);
    { /* the table of ex_cant.h is what ex_cant_root computes */
        int k;
        for (k = 0; k < 4; ++k) assert_true(ex_cant_b[k] == ex_cant_root(k + 1));
    }
}

/* 4, 8, 16 elements.  Facts:
   - conforming elements with the consistent mass are a Rayleigh-Ritz
     method: every frequency lies above the exact one (bending: Euler-
     Bernoulli beta L roots; axial: the rod, (pi/2) sqrt(EA / rhoA) / L);
   - the errors fall as h^4 (cubic Hermite, 2 (p + 1 - m) = 4 for p = 3,
     m = 2; Strang & Fix, An Analysis of the Finite Element Method, ch. 6)
     and h^2 for the linear axial element.  Observed order log2(e(N) /
     e(2N)) from 8 to 16 elements within 0.1 of 4 for w1..w3
     (measured: 3.99 (m:ord2_w1), 3.97 (m:ord2_w2), 3.94 (m:ord2_w3): w3
     is still approaching its asymptote, its deviation from 4 shrinks by
     about 4 per halving: 0.33 (m:dev1_w3), 0.065 (m:dev2_w3)), from 4 to 8
     within 0.4 (3.97 (m:ord1_w1), 3.87 (m:ord1_w2), 3.67 (m:ord1_w3));
     axial within 0.01 of 2 (2.002 (m:ord1_ax), 2.001 (m:ord2_ax)).
   Double only: in float the reduction's rounding (EPS times the
   condition of K0, EA / EI ~ 4e6) swamps the discretisation error: the
   float build reports its w1 errors, measured +3.4e-5 (m@flt~:flt_e4),
   -1.3e-4 (m@flt~:flt_e8), -5.7e-4 (m@flt~:flt_e16) at 4, 8, 16 elements,
   and skips. */
static void test_freq_convergence(void **state)
{
    (void)state;
#ifdef VLBE_USE_FLOAT
    {
        static const char *key[3] = {"flt_e4", "flt_e8", "flt_e16"};
        const double EI = cs_EI(), rA = cs_rhoA(), b = ex_cant_root(1);
        const double w1 = b * b * sqrt(EI / rA) / (CS_L * CS_L);
        double wb[3], wa;
        int i;
        for (i = 0; i < 3; ++i) {
            assert_int_equal(cs_freqs(4 << i, 1, 3, wb, &wa), VLBE_OK);
            tu_measured(key[i], (wb[0] - w1) / w1);
        }
        TU_SKIP("the float reduction's rounding swamps the discretisation error");
    }
#else
    {
        static const int Ns[3] = {4, 8, 16};
        const double EI = cs_EI(), EA = cs_EA(), rA = cs_rhoA();
        double wb[3][3], wa[3], e[3][4], wex[4];
        int i, k;
        for (k = 0; k < 3; ++k) {
            const double b = ex_cant_root(k + 1);
            wex[k] = b * b * sqrt(EI / rA) / (CS_L * CS_L);
        }
        wex[3] = 0.5 * PI * sqrt(EA / rA) / CS_L;
        for (i = 0; i < 3; ++i) {
            assert_int_equal(cs_freqs(Ns[i], 1, 3, wb[i], &wa[i]), VLBE_OK);
            for (k = 0; k < 3; ++k) e[i][k] = (wb[i][k] - wex[k]) / wex[k];
            e[i][3] = (wa[i] - wex[3]) / wex[3];
            for (k = 0; k < 4; ++k) assert_true(e[i][k] > 0.0);
        }
        for (k = 0; k < 4; ++k) {
            const double o1 = log2(e[0][k] / e[1][k]), o2 = log2(e[1][k] / e[2][k]);
            const double p = k < 3 ? 4.0 : 2.0;
            static const char *key[4][2] = {{"ord1_w1", "ord2_w1"}, {"ord1_w2", "ord2_w2"},
                                            {"ord1_w3", "ord2_w3"}, {"ord1_ax", "ord2_ax"}};
            tu_measured(key[k][0], o1);
            tu_measured(key[k][1], o2);
            if (k == 2) { /* the distance from the order p = 4 */
                tu_measured("dev1_w3", p - o1);
                tu_measured("dev2_w3", p - o2);
            }
            if (tu_report_on())
                print_message("    %s: rel. errors %.3e %.3e %.3e, orders %.3f %.3f\n",
                              k < 3 ? "bending" : "axial w1", e[0][k], e[1][k], e[2][k], o1, o2);
            ASSERT_CLOSE(o1, p, 0.0, k < 3 ? 0.4 : 0.01);
            ASSERT_CLOSE(o2, p, 0.0, k < 3 ? 0.1 : 0.01);
        }
    }
#endif
}

/* ======================================================================= */
/* 3. roll-up                                                               */
/* ======================================================================= */

/* The discrete closed form (examples/corot_static.c, top): under the tip
   moment lambda 2 pi EI / L, node i of N elements sits at the angle i a on
   the circle through the root of radius R_d = L_e (1 - a^2 / 24) /
   (2 sin(a / 2)), with phi_i = i a, a = 2 pi lambda L_e / L.  Derived by
   hand from eq. 7 and eqs. 16-17 of the paper; nothing of corot2d.h is
   used.  Largest distance of the nodes from it / L, and of the rotations
   in rad. */
static void rollup_vs_closed_form(int N, const vlbe_real *q, double lambda, double *dpos,
                                  double *drot)
{
    const double Le = CS_L / N, a = 2.0 * PI * lambda * Le / CS_L;
    const double Rd = Le * (1.0 - a * a / 24.0) / (2.0 * sin(0.5 * a));
    int i;
    *dpos = *drot = 0.0;
    for (i = 0; i <= N; ++i) {
        const double x = CS_L * i / N + (double)q[3 * i], y = (double)q[3 * i + 1];
        *dpos = fmax(*dpos, hypot(x - Rd * sin(i * a), y - Rd * (1.0 - cos(i * a))) / CS_L);
        *drot = fmax(*drot, fabs((double)q[3 * i + 2] - i * a));
    }
}

/* Tip distance from the exact arc (radius L / (2 pi lambda)) / L. */
static double rollup_tip_error(int N, const vlbe_real *q, double lambda)
{
    const double k = 2.0 * PI * lambda / CS_L;
    return hypot(CS_L + (double)q[3 * N] - sin(k * CS_L) / k,
                 (double)q[3 * N + 1] - (1.0 - cos(k * CS_L)) / k) / CS_L;
}

/* The section of the roll-up test.  The closed forms do not depend on it
   (no axial force, the radius is geometry).  Double: the paper's (EA L^2 /
   EI = 4.1e6).  Float: a stocky one, EA L^2 / EI = 1200 (a rectangle of
   depth L / 10): with the paper's, the iteration matrix of vlbe_dae_static
   mixes EA / L_e = 1.2e7 N/m with rotational pivots of EI / L_e ~ 12 N m,
   below the LU's relative-zero test n FLT_EPSILON max|A| = 26, and every
   solve stops with VLBE_ESINGULAR at q = 0 (a statement about float and
   the unscaled LU, not about the element). */
static int rollup_build(cs_model *m, int N, unsigned flags)
{
#ifdef VLBE_USE_FLOAT
    return cs_build_sec(m, N, flags, 1200.0 * cs_EI() / (CS_L * CS_L), cs_EI(), cs_rhoA());
#else
    return cs_build(m, N, flags);
#endif
}

/* The solver's parameters: plain Newton, whose iterates the scene's
   defaults take too (see cs_rollup).  Float:
   the default increment test (rtol 1e-10, below FLT_EPSILON, and the
   rounding floor max|dq| <= 8 EPS max|q|) cannot be met when the
   rounding of the Newton increments, about EPS kappa(J) max|q|, is larger
   (on the 8-element LINEAR problem the default test ends in VLBE_ENOCONV
   after 50 iterations); rtol = atol = 1e-4 stops at an increment of 1e-4
   |q|, and by the quadratic convergence the point returned is then exact
   to about (1e-4)^2 = 1e-8, below FLT_EPSILON. */
static vlbe_static_params rollup_params(void)
{
    vlbe_static_params p;
    vlbe_static_params_default(&p);
    p.max_halvings = 0;
#ifdef VLBE_USE_FLOAT
    p.rtol = p.atol = VLBE_R(1e-4);
#endif
    return p;
}

/* 4, 8, 16 elements, 8 load steps (plain Newton, see above).  Facts:
   - every node at every load factor on the discrete closed form.  The
     static solution is found to the solver's tolerance (increment test
     rtol 1e-10, quadratic convergence: the returned iterate is exact to
     rounding); what is left is the rounding of the equilibrium, forces of
     size EA EPS (axial) against the bending compliance: measured up to
     4e-16 L (m~:pos16) and 1.8e-15 rad (m~:rot16) at 16 elements in double;
     asserted 64 EPS on positions and 64 EPS N on rotations (they add up
     along the beam).  Float (stocky section, see rollup_build): measured
     3.2 EPS (m@flt~:pos16_eps) and 7 EPS (m@flt~:rot16_eps) at 16
     elements;
   - the tip's distance from the exact arc falls at order 4 (the a^4/1920
     of R_d): log2 ratios 4 -> 8 -> 16 within 0.1 of 4 at lambda = 1/4,
     1/2, 3/4 (measured 4.001 (m:rollup_ord_min) .. 4.055
     (m:rollup_ord_max), the pre-asymptotic a^6 term); double only: the
     16-element errors, up to 1.2e-6 (m:rollup_tip16), are at most ten
     float EPS;
   - lambda = 1: the polygon closes: tip within 64 EPS L of the root and
     phi_tip = 2 pi to 64 EPS N (as above);
   - LINEAR element, one step (the problem is linear): the exact linear
     solution is quadratic in x and the Hermite cubic holds it, so the tip
     deflects by M L^2 / (2 EI) = pi L, phi_tip = 2 pi, u = 0 to rounding.
     One element: the relative error of a linear solve is about EPS times
     the condition number of the (diagonally scaled) stiffness, here that
     of [[12, -6], [-6, 4]] scaled, 13.9: 64 EPS.  (With more elements the
     bending stiffness's condition grows like N^4 and so does the rounding;
     the example prints the 8-element run.) */
static void test_rollup(void **state)
{
    static const int Ns[3] = {4, 8, 16};
    enum { NSTEP = 8 };
    const vlbe_static_params par = rollup_params();
    cs_model *m = (cs_model *)malloc(sizeof *m);
    vlbe_real *qh = (vlbe_real *)malloc((NSTEP + 1) * 3 * 17 * sizeof *qh);
    double tip[3][4], wpos = 0.0, wrot = 0.0, pos16 = 0.0, rot16 = 0.0;
    int i, k;
    (void)state;
    assert_non_null(m);
    assert_non_null(qh);
    for (i = 0; i < 3; ++i) {
        const int N = Ns[i];
        assert_int_equal(rollup_build(m, N, 0u), 0);
        assert_int_equal(cs_rollup(m, NSTEP, &par, qh, NULL), VLBE_OK);
        for (k = 1; k <= NSTEP; ++k) {
            const vlbe_real *q = qh + (size_t)k * (size_t)m->n;
            const double lambda = (double)k / NSTEP;
            double dpos, drot;
            rollup_vs_closed_form(N, q, lambda, &dpos, &drot);
            wpos = fmax(wpos, dpos);
            wrot = fmax(wrot, drot / N);
            if (N == 16) {
                pos16 = fmax(pos16, dpos);
                rot16 = fmax(rot16, drot);
            }
            ASSERT_CLOSE_CTX(dpos, 0.0, 0.0, 64.0 * EPS, "N = %d, lambda = %g, positions", N,
                             lambda);
            ASSERT_CLOSE_CTX(drot, 0.0, 0.0, 64.0 * EPS * N, "N = %d, lambda = %g, rotations",
                             N, lambda);
            if (k % 2 == 0) tip[i][k / 2 - 1] = rollup_tip_error(N, q, lambda);
        }
        /* lambda = 1: back at the root, one full turn */
        {
            const vlbe_real *q = qh + (size_t)NSTEP * (size_t)m->n;
            ASSERT_CLOSE(hypot(CS_L + (double)q[3 * N], (double)q[3 * N + 1]), 0.0, 0.0,
                         64.0 * EPS * CS_L);
            ASSERT_CLOSE((double)q[3 * N + 2], 2.0 * PI, 0.0, 64.0 * EPS * N);
        }
    }
    tu_report("roll-up: nodes vs discrete closed form / L", wpos, 64.0 * EPS);
    tu_report("roll-up: rotations vs discrete closed form / N", wrot, 64.0 * EPS);
    tu_measured("pos16", pos16);
    tu_measured("rot16", rot16);
    tu_measured("pos16_eps", pos16 / EPS);
    tu_measured("rot16_eps", rot16 / EPS);
#ifndef VLBE_USE_FLOAT
    {
        double omin = INFINITY, omax = -INFINITY, t16 = 0.0;
        for (k = 0; k < 3; ++k) {
            const double o1 = log2(tip[0][k] / tip[1][k]), o2 = log2(tip[1][k] / tip[2][k]);
            if (tu_report_on())
                print_message("    roll-up lambda = %g: tip errors %.3e %.3e %.3e, orders %.3f "
                              "%.3f\n", 0.25 * (k + 1), tip[0][k], tip[1][k], tip[2][k], o1, o2);
            omin = fmin(omin, fmin(o1, o2));
            omax = fmax(omax, fmax(o1, o2));
            t16 = fmax(t16, tip[2][k]);
            ASSERT_CLOSE(o1, 4.0, 0.0, 0.1);
            ASSERT_CLOSE(o2, 4.0, 0.0, 0.1);
        }
        tu_measured("rollup_ord_min", omin);
        tu_measured("rollup_ord_max", omax);
        tu_measured("rollup_tip16", t16);
    }
#else
    (void)tip;
#endif
    /* the linear element, one element (see above) */
    assert_int_equal(rollup_build(m, 1, VLBE_CR2D_LINEAR), 0);
    assert_int_equal(cs_rollup(m, 1, &par, qh, NULL), VLBE_OK);
    {
        const vlbe_real *q = qh + m->n;
        const double vt = PI * CS_L; /* M L^2 / (2 EI), M = 2 pi EI / L */
        tu_report("LINEAR: tip deflection vs M L^2/(2 EI)", fabs((double)q[4] - vt) / vt,
                  64.0 * EPS);
        ASSERT_CLOSE((double)q[4], vt, 64.0 * EPS, 0.0);
        ASSERT_CLOSE((double)q[5], 2.0 * PI, 64.0 * EPS, 0.0);
        ASSERT_CLOSE((double)q[3], 0.0, 0.0, 64.0 * EPS * CS_L);
    }
    free(qh);
    free(m);
}

/* ======================================================================= */
/* 4. rigid rotation                                                        */
/* ======================================================================= */

/* 16 elements turned about c = (0.3, -0.2) m by psi in [-4 pi, 12 pi]
   (1006 angles, phi = psi: up to six turns accumulated).  Exact: Q = 0.
   Rounding: node positions carry about EPS (L + |c|) absolute, a chord
   direction then EPS (L + |c|) / L_e, and phi = psi itself EPS |psi|; the
   deformation rotations and eps0 are in error by about those, so
       |Q_force| / EA  and  |Q_moment| L_e / (6 EI)
   stay below 8 EPS (|psi|max + 2 (L + |c|) / L_e) = 8 EPS (38 + 44)
   (measured: 7.2e-15 (m~:rigid_force) and 3.7e-15 (m~:rigid_moment) in
   double, 20 (m~:rigid_force_margin) and 40 (m~:rigid_moment_margin)
   times below).
   LINEAR element (frame fixed at the reference): a rotation by pi reverses
   the element, u2 - u1 = -2 L_e along x, so the tip's x force is
   -EA (u2 - u1)/L_e = 2 EA exactly (nothing of the bending enters x). */
static void test_rigid_rotation(void **state)
{
    static const double c[2] = {0.3, -0.2};
    const int N = 16;
    const double Le = CS_L / N, bound = 8.0 * EPS * (12.0 * PI + 2.0 * (CS_L + 0.37) / Le);
    double fm = -1, mm = -1;
    (void)state;
    assert_int_equal(cs_rigid(N, 0u, -4.0 * PI, 0.05, 1006, c, &fm, &mm), 0);
    tu_report("rigid rotation: max |Q_force| / EA", fm, bound);
    tu_report("rigid rotation: max |Q_moment| L_e / (6 EI)", mm / 6.0, bound);
    tu_measured("rigid_force", fm);
    tu_measured("rigid_force_margin", bound / fm);
    mm /= 6; /* |Q_moment| L_e / (6 EI) */
    tu_measured("rigid_moment", mm);
    tu_measured("rigid_moment_margin", bound / mm);
    assert_true(fm <= bound);
    assert_true(mm <= bound);
    {
        cs_model *m = (cs_model *)malloc(sizeof *m);
        vlbe_real q[3 * 17], v[3 * 17], Q[3 * 17];
        int i;
        assert_non_null(m);
        assert_int_equal(cs_build(m, N, VLBE_CR2D_LINEAR), 0);
        for (i = 0; i <= N; ++i) { /* turned by pi about the root */
            q[3 * i] = (vlbe_real)(-2.0 * CS_L * i / N);
            q[3 * i + 1] = VLBE_R(0.0);
            q[3 * i + 2] = VLBE_PI;
        }
        for (i = 0; i < 3 * (N + 1); ++i) v[i] = VLBE_R(0.0);
        assert_int_equal(vlbe_cr2d_beam_force(&m->beam, VLBE_R(0.0), q, v, Q), 0);
        ASSERT_CLOSE((double)Q[3 * N], 2.0 * cs_EA(), 64.0 * EPS, 0.0);
        free(m);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_freq_one_element), cmocka_unit_test(test_freq_convergence),
        cmocka_unit_test(test_rollup),           cmocka_unit_test(test_rigid_rotation),
    };
    return cmocka_run_group_tests_name("scenes_cr2d", tests, NULL, NULL);
}
