/* test_scenes_torsion.c -- cmocka suite of the free torsional vibration of
   a fixed-free shaft (VLBSE scene 4.2; vlbse section 4.2, Table 3;
   examples/shaft_torsion.c): N 3D beam-shaft elements in a Lagrangian chain.
   -- part of vlbe                                  SPDX-License-Identifier: MIT
   cc -std=c99 -Wall -Wextra -Wpedantic ... -O2 tests/test_scenes_torsion.c -lcmocka -lm

   Tests
     closed_form     the torsional eigenfrequencies of the linearised chain
                     (theta block of K0 = -dQ/dq and M) against the closed
                     form of N linear elements with consistent mass, every
                     mode of N = 1..40, to rounding
     convergence     towards eq. 58 from above, error ~ (k_i h)^2 / 24:
                     leading coefficient and observed order 2 between N =
                     10, 20 (and 40 in double)
     decoupled       at the straight state the K0 and M blocks between the
                     theta coordinates and the others are zero (N = 1..10),
                     the state is an equilibrium, and the full reduced
                     problem's modes have theta shares 0 or 1, its torsional
                     ones being the theta block's (N = 4)
     time_history    4 elements, trapezoidal rule at h = 10 us and 5 us over
                     20 ms: the frequencies of the free-end twist are the
                     trapezoidal rule's image atan(pi f h)/(pi h) of the
                     eigenvalues f, and the Richardson values are the
                     eigenvalues up to the rule's O(h^4) residual
     table3_bins     our reading of Table 3: every entry is one of the two
                     9.999 Hz DFT bins around the closed-form value, 37 of
                     40 the nearest; the rectangular DFT (st_dft_peak)
                     picks the nearest bin of each line of a 0.1 s record
   Tolerances, derived in each test's comment, carry the working precision
   EPS = VLBE_EPS.  The history runs in both precisions: the spin
   inertia rhoI h/3 ~ 2e-7 kg m of a theta row (4 elements) sits below n
   FLT_EPSILON = 5e-6 times the constraint rows' unit entries (SI units:
   rhoI/rhoA = r^2/2 = 1.25e-5 m^2), which vlbe_lu_factor's relative
   pivot test read as singular in float until the integrators
   equilibrated the rows of their iteration matrices (vlbe__dae_equil).
   Set VLBE_TEST_REPORT=1 to print the measured errors beside their
   tolerances. */
#include "test_util.h"
#include "../scenes/shaft_torsion.h"

#include <float.h>

#define EPS ((double)VLBE_EPS)

static st_eig_out g_eo;

/* Rounding tolerance of the computed f_i of N elements (relative):
   EPS (16 + (f_N / f_i)^2 + (f_i / f_1)^2).
   - The element matrices carry roundings of EPS of their entries; a
     symmetric perturbation E of K0 (or M) moves w_i^2 by x_i^T E x_i /
     x_i^T M x_i (first order), and for |E| ~ EPS |K0| that is up to EPS
     w_N^2, relative to w_i^2: (f_N/f_i)^2 (the linear element's rigid
     mode gets a stiffness of EPS GI/h from rounding; summed over N
     elements against the energy of mode i: ~ EPS (f_N/f_i)^2).
   - The eigensolver (vlbe_eig_gsym, shift-invert with sigma = 0: Jacobi
     on L^-1 M L^-T, K0 = L L^T) gives each mu = 1/w^2 to a few EPS of
     the largest, 1/w_1^2: relative to 1/w_i^2, (f_i/f_1)^2.
   - The closed form and the rest: a few EPS, the 16.
   Measured up to 0.10 (m:cf_worst) of it in double (one element: 1.8 EPS
   against 18), 0.06 (m@flt:cf_worst) in float; mode 1 of 40 elements:
   131 (m~:cf_n40m1_eps) EPS in double, 189 (m@flt~:cf_n40m1_eps) EPS in
   float against 7800 EPS; mode 12 of 12: 32 (m~:cf_n12m12_eps) EPS
   against 700. */
static double eig_tol(int ne, int i)
{
    const double a = st_f_lin(ne, ne) / st_f_lin(ne, i), b = st_f_lin(ne, i) / st_f_lin(ne, 1);
    return EPS * (16.0 + a * a + b * b);
}

/* ======================================================================= */
/* 1. eigenvalues against the closed form of the linear element            */
/* ======================================================================= */

/* Every mode i = 1..N of N = 1..40 (theta block, vlbe_eig_gsym with
   sigma = 0) against f_i^lin (examples/shaft_torsion.c, top), to
   eig_tol.  One element: f_1 = sqrt(3) c / (2 pi l), 2 sqrt(3)/pi - 1 =
   +10.27 % above eq. 58 (the paper's 10.20 % is its 869.9 Hz bin). */
static void test_closed_form(void **state)
{
    double worst = 0.0;
    int ne, i, worst_ne = 0, worst_i = 0;
    (void)state;
    for (ne = 1; ne <= ST_NE_MAX; ++ne) {
        assert_int_equal(st_eigen(ne, 0, &g_eo), 0);
        for (i = 1; i <= ne; ++i) {
            const double ref = st_f_lin(ne, i), tol = eig_tol(ne, i);
            const double r = tu_err_ratio(g_eo.ft[i - 1], ref, tol, 0.0);
            ASSERT_CLOSE_CTX(g_eo.ft[i - 1], ref, tol, 0.0, "N = %d, mode %d", ne, i);
            if (r > worst) worst = r, worst_ne = ne, worst_i = i;
            if ((ne == 40 && i == 1) || (ne == 12 && i == 12))
                tu_measured(ne == 40 ? "cf_n40m1_eps" : "cf_n12m12_eps",
                            fabs(g_eo.ft[i - 1] / ref - 1.0) / EPS);
        }
        if (ne == 1) {
            ASSERT_CLOSE(st_f_lin(1, 1), sqrt(3.0) * st_c() / (2.0 * ST_PI * ST_L),
                         8.0 * DBL_EPSILON, 0.0);
            ASSERT_CLOSE(g_eo.ft[0] / st_f_exact(1), 2.0 * sqrt(3.0) / ST_PI,
                         eig_tol(1, 1) + 8.0 * DBL_EPSILON, 0.0);
        }
    }
    tu_report("f_i vs closed form, N = 1..40 (worst ratio to eig_tol)", worst, 1.0);
    tu_measured("cf_worst", worst);
    if (tu_report_on())
        print_message("    worst at N = %d, mode %d\n", worst_ne, worst_i);
}

/* ======================================================================= */
/* 2. convergence towards eq. 58                                           */
/* ======================================================================= */

/* e_i(N) = f_i / f_i,exact - 1 from the eigenvalues, modes 1..5.  The
   closed form expands to e = (k_i h)^2 / 24 + O(h^4) = C_i / N^2 (1 +
   O(N^-2)), C_i = ((2i - 1) pi / 2)^2 / 24 (positive: from above).  At N
   >= 10 its e N^2 / C_i lies in [1, 1.0085] and its order log2(e(N) /
   e(2N)) in [1.9997, 2.0073] (computed from the closed form); asserted:
     |e N^2 / C_i - 1| <= 0.01 + t N^2 / C_i,
     |p - 2| <= 0.01 + (t(N) / e(N) + t(2N) / e(2N)) / ln 2,
   t = eig_tol(N, i) (the rounding of e).  N = 10, 20, 40 in double (the
   rounding terms below 1e-7); 10, 20 in float, where the order of modes
   2..5 is held within 0.03 of 2 and that of mode 1 only loosely (its
   rounding bound at N = 20, 2.3e-4, is near its error 2.6e-4: tolerance
   1.4; at N = 40 the bound, 9e-4, exceeds the error, 6e-5). */
static void test_convergence(void **state)
{
#ifdef VLBE_USE_FLOAT
    static const int nes[2] = {10, 20};
    const int nn = 2;
#else
    static const int nes[3] = {10, 20, 40};
    const int nn = 3;
#endif
    double e[3][ST_NMODE], worst_c = 0.0, worst_p = 0.0;
    int k, i;
    (void)state;
    for (k = 0; k < nn; ++k) {
        assert_int_equal(st_eigen(nes[k], 0, &g_eo), 0);
        for (i = 1; i <= ST_NMODE; ++i) {
            const double N = nes[k], C = pow((2.0 * i - 1.0) * ST_PI / 2.0, 2.0) / 24.0;
            const double tol = 0.01 + eig_tol(nes[k], i) * N * N / C;
            e[k][i - 1] = g_eo.ft[i - 1] / st_f_exact(i) - 1.0;
            assert_true(e[k][i - 1] > 0.0);
            ASSERT_CLOSE_CTX(e[k][i - 1] * N * N / C, 1.0, 0.0, tol, "N = %d, mode %d", nes[k], i);
            worst_c = fmax(worst_c, fabs(e[k][i - 1] * N * N / C - 1.0) / tol);
        }
    }
    for (k = 0; k + 1 < nn; ++k)
        for (i = 1; i <= ST_NMODE; ++i) {
            const double a = e[k][i - 1], b = e[k + 1][i - 1], p = log(a / b) / log(2.0);
            const double tol =
                0.01 + (eig_tol(nes[k], i) / a + eig_tol(nes[k + 1], i) / b) / log(2.0);
            ASSERT_CLOSE_CTX(p, 2.0, 0.0, tol, "N = %d -> %d, mode %d", nes[k], nes[k + 1], i);
            worst_p = fmax(worst_p, fabs(p - 2.0) / tol);
        }
    tu_report("e N^2 / C_i - 1 (worst ratio to tolerance)", worst_c, 1.0);
    tu_report("observed order - 2 (worst ratio to tolerance)", worst_p, 1.0);
}

/* ======================================================================= */
/* 3. twist decoupled from bending and stretching                          */
/* ======================================================================= */

/* At the straight state every entry of K0 and M between a theta
   coordinate and a position or slope coordinate is exactly zero, N =
   1..10: the twist energy GI theta'^2/2 and the spin inertia rhoI
   theta-dot^2/2 contain no r, and the strain and inertia routines never
   add a position term to a theta row (an exact structural zero; any
   nonzero, even of rounding size, is a coupling the element should not
   have).  The straight state is an equilibrium: max |Q| <= 64 EPS EA (the
   axial force of the rounded slopes; measured 3 (m~:qmax_eps) EPS EA).
   Full reduced problem, N = 4 (28 coordinates): the share of x^T M x on
   theta of every mode is within 64 EPS of 0 or 1 (measured 0 (m~:dshare)),
   exactly 4 modes are
   torsional and their frequencies are the theta block's to eig_tol: with
   the blocks exactly decoupled, the Cholesky factor and the Jacobi
   rotations never mix them (a zero pair is skipped), so the theta part is
   computed by the theta block's own arithmetic, up to Jacobi's skip
   threshold EPS^2 max|a_ij| of the whole reduced matrix (its largest entry
   is 1/w^2 of the first bending mode, 7 Hz: EPS^2 (f_i / 7 Hz)^2 << EPS
   relative; measured identical: largest difference 0 (m~:fa_ft_diff)). */
static void test_decoupled(void **state)
{
    const double EA = ST_E * ST_PI * ST_R * ST_R;
    double ft[ST_NE_MAX], qmax = 0.0, fdiff = 0.0;
    int ne, i;
    (void)state;
    for (ne = 1; ne <= 10; ++ne) {
        assert_int_equal(st_eigen(ne, ne == 4, &g_eo), 0);
        assert_int_equal(g_eo.nfree, 7 * ne);
        assert_true(g_eo.kc == 0.0);
        assert_true(g_eo.mc == 0.0);
        ASSERT_CLOSE_CTX(g_eo.qmax, 0.0, 0.0, 64.0 * EPS * EA, "N = %d", ne);
        qmax = fmax(qmax, g_eo.qmax);
        if (ne == 4) {
            for (i = 0; i < ne; ++i) ft[i] = g_eo.ft[i];
            tu_report("theta share: max distance from 0 or 1", g_eo.dshare, 64.0 * EPS);
            tu_measured("dshare", g_eo.dshare);
            assert_true(g_eo.dshare <= 64.0 * EPS);
            assert_int_equal(g_eo.na, ne);
            for (i = 0; i < ne; ++i) {
                ASSERT_CLOSE_CTX(g_eo.fa[i], ft[i], eig_tol(ne, i + 1), 0.0, "mode %d", i + 1);
                fdiff = fmax(fdiff, fabs(g_eo.fa[i] - ft[i]));
            }
        }
    }
    tu_measured("qmax_eps", qmax / (EPS * EA));
    tu_measured("fa_ft_diff", fdiff);
}

/* ======================================================================= */
/* 4. frequencies from time histories                                      */
/* ======================================================================= */

/* 4 elements, the five-mode start (modes 1..4 exist), trapezoidal rule
   (Newmark 1/4, 1/2) at h = 10 us and 5 us over T = 20 ms, theta at the
   free end every step, ex_peak_freq in f (1 +- 5 %) around each
   eigenvalue f.
   (a) On a linear system the rule turns w into (2/h) atan(w h/2) exactly:
   the measured frequency is f_h = atan(pi f h)/(pi h) up to the peak
   estimator's error.  That error: the Blackman-Harris sidelobes are below
   -92 dB (2.5e-5 in amplitude), so the three other lines and the mean
   (all of about the same amplitude, >= 15 bins of 1/T away) leave eps <=
   1e-4 of the peak's amplitude near it, which moves the peak by <= ~2 eps
   / T (its curvature is ~T^2 in bins): relative tolerance 2e-4 / (f T),
   5e-6 for f1 and 7e-7 for f4 (the larger of the two steps' errors:
   measured 3.2e-7 (m:th_f1) and 2.1e-8 (m:th_f4)).
   (b) Richardson R = (4 f_{h/2} - f_h) / 3 against the eigenvalue f.
   The rule's own Richardson value R* = (4 f*_{h/2} - f*_h) / 3 (f* the
   atan images) differs from f by -(w h)^4 / 320 + 7e-4 (w h)^6 - ...
   (the series of atan(y)/y), an alternating series: |R* - f| / f <= (w
   h)^4 / 320 (asserted: 2e-8 for f1, 9.2e-5 for f4 at h = 10 us), and
   |R - R*| / f <= (4 + 1)/3 times the estimator tolerance; together |R -
   f| / f <= (w h)^4 / 320 + 5/3 tol.  R is asserted closer to f than the
   raw f_{h/2} (whose error is ~ (w h/2)^2 / 12: 3.6e-3 for f4).
   The same in float (measured: (a) 8 (m@flt:th_a_pct) % of the
   tolerance, (b) 5 (m@flt:th_b_pct) %). */
static void test_time_history(void **state)
{
    (void)state;
    {
        const int ne = 4;
        const double dt = 1e-5, T = 0.02;
        st_hist o[2];
        double fh[2][4], worst_a = 0.0, worst_b = 0.0;
        int k, i;
        assert_int_equal(st_eigen(ne, 0, &g_eo), 0);
        for (k = 0; k < 2; ++k) {
            /* h = dt / (k + 1), sampled every step of the coarse run */
            assert_int_equal(st_history(ne, dt, k + 1, T, &o[k]), VLBE_OK);
            assert_true(o[k].n == (size_t)(T / dt + 1.5));
            assert_int_equal(st_hist_freqs(&o[k], g_eo.ft, ne, fh[k]), 0);
            free(o[k].y);
        }
        for (i = 0; i < ne; ++i) {
            const double f = g_eo.ft[i], tol = 2e-4 / (f * T);
            const double rs = (4.0 * st_f_trap(f, 0.5 * dt) - st_f_trap(f, dt)) / 3.0;
            const double r = (4.0 * fh[1][i] - fh[0][i]) / 3.0;
            const double x = 2.0 * ST_PI * f * dt, x4 = x * x * x * x / 320.0;
            for (k = 0; k < 2; ++k) {
                const double fp = st_f_trap(f, dt / (k + 1));
                ASSERT_CLOSE_CTX(fh[k][i], fp, tol, 0.0, "mode %d, h = %g", i + 1, dt / (k + 1));
                worst_a = fmax(worst_a, tu_err_ratio(fh[k][i], fp, tol, 0.0));
            }
            if (i == 0 || i == ne - 1) /* the larger error of the two steps */
                tu_measured(i ? "th_f4" : "th_f1",
                            fmax(fabs(fh[0][i] / st_f_trap(f, dt) - 1.0),
                                 fabs(fh[1][i] / st_f_trap(f, 0.5 * dt) - 1.0)));
            ASSERT_CLOSE_CTX(rs, f, x4, 0.0, "mode %d", i + 1);
            ASSERT_CLOSE_CTX(r, rs, 0.0, 5.0 / 3.0 * tol * f, "mode %d", i + 1);
            ASSERT_CLOSE_CTX(r, f, x4 + 5.0 / 3.0 * tol, 0.0, "mode %d", i + 1);
            worst_b = fmax(worst_b, tu_err_ratio(r, rs, 0.0, 5.0 / 3.0 * tol * f));
            assert_true(fabs(r - f) < fabs(fh[1][i] - f));
            if (tu_report_on())
                print_message("    mode %d: f %.6f, h: %+.2e, h/2: %+.2e vs the atan image; "
                              "Richardson %+.2e (rule's %+.2e, bound %.2e)\n",
                              i + 1, f, fh[0][i] / st_f_trap(f, dt) - 1.0,
                              fh[1][i] / st_f_trap(f, 0.5 * dt) - 1.0, r / f - 1.0,
                              rs / f - 1.0, x4);
        }
        tu_report("history vs atan image (worst ratio to tolerance)", worst_a, 1.0);
        tu_report("Richardson vs the rule's Richardson (worst ratio to tol.)", worst_b, 1.0);
        tu_measured("th_a_pct", 100 * worst_a);
        tu_measured("th_b_pct", 100 * worst_b);
    }
}

/* ======================================================================= */
/* 5. Table 3 as DFT bins                                                  */
/* ======================================================================= */

/* Our reading of the paper's Table 3 (examples/shaft_torsion.c, top), in
   double whatever vlbe_real is (closed form only): with the bin df =
   1/(10001 x 10 us), every entry is within 0.05 Hz (its printed digit) of
   floor(x) df or ceil(x) df, x = f^lin / df; it is the nearest of the two
   in 37 of the 40 entries, and in the other 3 x lies within 0.08 of a
   midpoint (|x - floor x - 1/2| <= 0.08).  Then st_dft_peak on a 0.1 s
   record (10001 samples at 10 us) of the five lines of 10 elements (unit
   amplitudes): each peak is the nearest bin (the lines sit 0.03..0.26 bin
   from theirs, >= 0.24 from a midpoint, so the rectangular window's
   leakage from the others, <= 1/(pi 150) of a line, cannot move it). */
static void test_table3_bins(void **state)
{
    const double df = st_bin();
    int ne, i, nearest = 0, total = 0;
    (void)state;
    ASSERT_CLOSE(df, 1e5 / 10001.0, 4.0 * DBL_EPSILON, 0.0);
    for (ne = 1; ne <= 10; ++ne)
        for (i = 1; i <= ne && i <= ST_NMODE; ++i) {
            const double x = st_f_lin(ne, i) / df, p = st_paper[ne - 1][i - 1];
            const double lo = floor(x) * df, hi = (floor(x) + 1.0) * df;
            const double near = x - floor(x) < 0.5 ? lo : hi;
            ++total;
            assert_true(p > 0.0);
            assert_true(fabs(p - lo) <= 0.05 || fabs(p - hi) <= 0.05);
            if (fabs(p - near) <= 0.05)
                ++nearest;
            else
                ASSERT_CLOSE_CTX(x - floor(x), 0.5, 0.0, 0.08, "N = %d, f%d", ne, i);
        }
    assert_int_equal(total, 40);
    assert_int_equal(nearest, 37);
    {
        st_hist o;
        size_t j;
        memset(&o, 0, sizeof o);
        o.dt = ST_DT;
        o.n = (size_t)(ST_T / ST_DT + 1.5);
        o.y = (double *)malloc(o.n * sizeof *o.y);
        assert_non_null(o.y);
        assert_int_equal((int)o.n, 10001);
        for (j = 0; j < o.n; ++j) {
            double s = 0.0;
            for (i = 1; i <= ST_NMODE; ++i)
                s += sin(2.0 * ST_PI * st_f_lin(10, i) * ST_DT * (double)j);
            o.y[j] = s;
        }
        for (i = 1; i <= ST_NMODE; ++i) {
            const double f = st_f_lin(10, i), near = floor(f / df + 0.5) * df;
            ASSERT_CLOSE_CTX(st_dft_peak(&o, f - 2.0 * df, f + 2.0 * df), near, 0.0, 1e-9 * f,
                             "f%d", i);
            ASSERT_CLOSE_CTX(near, st_paper[9][i - 1], 0.0, 0.05, "f%d", i);
        }
        free(o.y);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_closed_form),  cmocka_unit_test(test_convergence),
        cmocka_unit_test(test_decoupled),    cmocka_unit_test(test_time_history),
        cmocka_unit_test(test_table3_bins),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
