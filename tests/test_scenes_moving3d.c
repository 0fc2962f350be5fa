/* test_scenes_moving3d.c -- cmocka suite of VLBSE scene 4.1 in 3D: the
   axially moving string and beam of examples/moving_string.c (vlbse 4.1,
   Table 1) with the 3D beam-shaft chain (vlbe_ale_chain_init3, VLBSE) in
   the Eulerian window, theta = 0 and nothing driving the spin.
   -- part of vlbe                                  SPDX-License-Identifier: MIT
   cc -std=c99 -Wall -Wextra -Wpedantic ... -O2 tests/test_scenes_moving3d.c -lcmocka -lm
   (add -DVLBE_USE_FLOAT for the float build; the same source passes in both)

   Tests (4 elements; f1_exact also 8 in fast builds)
     planar_agreement   3D vs planar chain on the same scene (same h, same
                        integrator), every node's position at every step:
                        axial to a few EPS, transverse to 1e-10 of its
                        amplitude (the required bound; it is rounding times
                        the Green strain's conditioning 1/eps), out-of-plane
                        positions, slopes and theta exactly 0, the two
                        histories' frequencies equal; without the spin
                        angle (VLBE_ALE3_NO_SPIN) the same history
     f1_exact           3D first frequency (Richardson over h, h/2) vs the
                        exact value of the prestretched moving string (eq.
                        56 with our reading of F, see moving_string.c), eq.
                        (56) as printed and the paper's VLBSE value
     isotropy           the same string and beam vibrating in the x-z plane:
                        the history of the x-y one with y and z exchanged,
                        the same frequency
   Slow builds (-O0, AddressSanitizer, valgrind, or VLBE_TEST_QUICK=1) run
   shorter histories (0.1 s instead of 0.5 s; the string only in isotropy,
   without the spin-switch check) and f1_exact with 4 elements only, 0.25 s
   of response at h = 8e-4, 4e-4, each test saying what it keeps; the suite
   then takes ~0.1 s at -O2 (~7 s under valgrind), the full one ~1 s.
   Float runs the same chains: the spin angle's mass rhoI L/3 is r^2/2 =
   1.25e-5 of the translational one, below the LU's pivot test n EPS
   max|A| (~5e-6 relative with n = 41 in float) before the integrators
   equilibrated the rows of their iteration matrices (integrators.h,
   vlbe__dae_equil); the chain with and without the spin angle give the
   same history bit for bit in both precisions (checked below).
   Set VLBE_TEST_REPORT=1 to print measured errors beside the tolerances. */
#include "test_util.h"

#include "../scenes/moving_string.h"

#include <float.h>

#define EPS ((double)VLBE_EPS)

#define M3 MS_3D

/* Green strain of the prestretch, eps = 1.8e-4 */
static double prestretch(void)
{
    double rhoA, EA, EI, eps, lam;
    ms_section(&rhoA, &EA, &EI, &eps, &lam);
    return eps;
}

/* The transverse history tolerance, relative to the transverse amplitude.
   Two models of the same motion that round differently differ by their
   rounding amplified by the Green strain's conditioning: the axial force
   comes from (|r'|^2 - 1)/2 = eps with slopes ~1, so it carries EPS/eps
   relative (1.2e-12 in double, 6.6e-4 in float), and the tension error
   becomes a phase error that the history accumulates.  Measured 3D vs
   planar, 0.5 s, 4 elements: 2.7 (m~:ps_hist_epsr) (string) and
   1.2 (m~:pb_hist_epsr) (beam) EPS/eps in double, 3.4 (m@flt~:ps_hist_epsr)
   and 1.3 (m@flt~:pb_hist_epsr) EPS/eps in float.  The required 1e-10 is 82
   EPS/eps in double; the same multiple in float is 5.4e-2. */
static double tol_hist(void) { return 82.0 * EPS / prestretch(); }

/* The frequencies of two histories that agree to tol_hist: a phase drift
   of at most tol_hist over the record's 2 pi f1 t_end radians, plus the
   estimator's floor (ex_peak_freq on the 3D and planar histories, which
   agree to a few 1e-12: measured 0.0e0 (m~:ps_fdiff) and
   1.0e-9 (m~:pb_fdiff) apart, the rounding of the DFT power near its flat
   peak; held to 1e-7). */
static double tol_freq(double f1, double t_end)
{
    const double PI = 3.14159265358979323846;
    return 1e-7 + tol_hist() / (2.0 * PI * f1 * t_end);
}

/* The checks of one comparison of histories (ms_compare of model a
   against model b): axial within 16 EPS L (measured 4 (m~:ps_axial_eps)
   EPS in double, 6 (m@flt~:ps_axial_eps) in float for the string: the
   nodes' axial positions ~L rounded), transverse within tol_hist of its
   amplitude, the out-of-plane positions and slopes and theta of run a
   exactly 0 (structural zeros: every force, mass and Jacobian entry that
   couples them to the plane of motion is a product with a zero, and
   nothing drives the spin), the frequencies equal to tol_freq.  The
   measured numbers are reported under the keys key_axial_eps (in EPS L),
   key_hist_rel (of the amplitude), key_hist_epsr (in EPS/eps), key_fdiff
   (relative) and key_diff (the sum of the three largest differences: 0
   for histories equal bit for bit). */
static void check_cmp(const char *what, const char *key, int kind_a, int kind_b, double t_end)
{
    const double h = 2e-4;
    char name[160];
    ms_cmp c;
    assert_int_equal(ms_compare(4, kind_a, kind_b, h, t_end, &c), 0);
    assert_true(c.n == (size_t)(t_end / h + 1.5));
    assert_true(c.amax[1] > 1e-7); /* the vibration is there */
    snprintf(name, sizeof name, "%s: max |dx| / L", what);
    tu_report(name, c.d[0] / MS_L, 16.0 * EPS);
    snprintf(name, sizeof name, "%s: max |dtr| / max |tr|", what);
    tu_report(name, c.d[1] / c.amax[1], tol_hist());
    snprintf(name, sizeof name, "%s: f1 (this history)", what);
    tu_report(name, fabs(c.fa - c.fb) / c.fb, tol_freq(c.fb, t_end));
    if (tu_report_on())
        print_message("    %s: out-of-plane %g, theta %g, f1 %.10f vs %.10f\n", what, c.oop,
                      c.th, c.fa, c.fb);
    snprintf(name, sizeof name, "%s_axial_eps", key);
    tu_measured(name, c.d[0] / MS_L / EPS);
    snprintf(name, sizeof name, "%s_hist_rel", key);
    tu_measured(name, c.d[1] / c.amax[1]);
    snprintf(name, sizeof name, "%s_hist_epsr", key);
    tu_measured(name, c.d[1] / c.amax[1] / (EPS / prestretch()));
    snprintf(name, sizeof name, "%s_fdiff", key);
    tu_measured(name, fabs(c.fa - c.fb) / c.fb);
    snprintf(name, sizeof name, "%s_diff", key);
    tu_measured(name, c.d[0] + c.d[1] + c.d[2]);
    ASSERT_CLOSE(c.d[0], 0.0, 0, 16.0 * EPS * MS_L);
    ASSERT_CLOSE(c.d[1], 0.0, 0, tol_hist() * c.amax[1]);
    assert_true(c.d[2] == 0.0 && c.oop == 0.0 && c.th == 0.0);
    ASSERT_CLOSE(c.fa, c.fb, tol_freq(c.fb, t_end), 0);
}

/* 3D (theta = 0) vs planar, string and beam, 0.5 s at h = 2e-4 (slow
   builds 0.1 s: measured 3.3e-12 (m@san~:ps_hist_rel) of the amplitude
   for the string).  In fast builds also the 3D chain without the spin
   angle against the one with it: measured bit for bit equal, largest
   differences 0 (m~:ns_diff) in double and 0 (m@flt~:ns_diff) in float
   (the spin angles' rows and columns decouple at theta = 0), held to the
   same tolerances. */
static void test_planar_agreement(void **state)
{
    const int slow = tu_slow_run();
    const double t_end = slow ? 0.1 : 0.5;
    (void)state;
    check_cmp("3D vs planar string", "ps", M3, 0, t_end);
    check_cmp("3D vs planar beam", "pb", M3 | MS_BEND, MS_BEND, t_end);
    if (!slow)
        check_cmp("3D without vs with spin angle, string", "ns", MS_3D | MS_NOSPIN, MS_3D, t_end);
}

/* The 3D string's first frequency against the exact value of the
   prestretched moving string ms_f1_exact() = 22.689908 Hz, with the
   tolerances of the planar test (tests/test_chain_ale.c, scene1): the 3D
   element in plane is the planar one (planar_agreement), so its errors
   are the planar ones:
   - 4 elements, Richardson over h = 2e-4, 1e-4:
     measured 3.95e-5 (m:f4_exact), held to 1e-4 (spatial error; the
     integration error left by Richardson, O(h^4), is far below it); slow
     builds take 0.25 s of response at h = 8e-4, 4e-4 (an eighth of the
     steps): measured 4.02e-5 (m@san:f4_exact) (a larger h^4 term, the
     estimator on 5.7 periods).
   - the same against eq. (56) as printed (22.6857):
     measured 2.25e-4 (m:f4_eq56), held to 3e-4 (the prestretch 1.86e-4 of
     our reading plus the mesh error); against the paper's VLBSE value
     22.6723: measured 8.2e-4 (m:f4_vlbse), held to 9e-4 = our 3e-4 bound
     against eq. (56) plus the paper's own 5.9e-4 between its VLBSE value
     and eq. (56) (2.8e-4 below its VLBE 22.6786, which the planar test
     holds to 6e-4).
   - 8 elements (fast builds): measured 9.2e-7 (m:f8_exact), held to 2e-6
     (the spatial error falls at the order 5.4 (m:f_order) in N:
     3.95e-5 (m:f4_exact) at 4).
   - beam, 4 elements (fast builds), against the paper's VLBSE 32.2097 (no
     exact value): measured 5.9e-4 (m:fb_vlbse), held to 1e-3 (the paper's
     value carries its own mesh error; examples/moving_string.c compares
     both with a converged run).
   Float: the tension carries FLT_EPSILON / eps = 6.6e-4 relative (see
   tests/test_chain_ale.c); measured 9.2e-4 (m@flt~:f4_exact), held to 4
   FLT_EPSILON / eps as the planar float check. */
static void test_f1_exact(void **state)
{
    const double fx = ms_f1_exact();
    const int slow = tu_slow_run();
    const double h = slow ? 8e-4 : 2e-4, T = slow ? 0.25 : 0.5;
    const double f4 = ms_freq(4, M3, h, T, NULL, NULL);
    (void)state;
    assert_true(f4 > 0.0);
#ifndef VLBE_USE_FLOAT
    tu_report("3D string f1, 4 elements vs exact", fabs(f4 - fx) / fx, 1e-4);
    tu_report("3D string f1, 4 elements vs eq. (56) as printed",
              fabs(f4 - MS_F1_PAPER_EXACT) / MS_F1_PAPER_EXACT, 3e-4);
    tu_report("3D string f1, 4 elements vs paper VLBSE",
              fabs(f4 - MS_F1_PAPER_VLBSE) / MS_F1_PAPER_VLBSE, 9e-4);
    tu_measured("f4_exact", fabs(f4 - fx) / fx);
    tu_measured("f4_eq56", fabs(f4 - MS_F1_PAPER_EXACT) / MS_F1_PAPER_EXACT);
    tu_measured("f4_vlbse", fabs(f4 - MS_F1_PAPER_VLBSE) / MS_F1_PAPER_VLBSE);
    ASSERT_CLOSE(f4, fx, 1e-4, 0);
    ASSERT_CLOSE(f4, MS_F1_PAPER_EXACT, 3e-4, 0);
    ASSERT_CLOSE(f4, MS_F1_PAPER_VLBSE, 9e-4, 0);
    if (!slow) {
        const double f8 = ms_freq(8, MS_3D, h, 0.5, NULL, NULL);
        const double fb = ms_freq(4, MS_3D | MS_BEND, h, 0.5, NULL, NULL);
        tu_measured("f8_exact", fabs(f8 - fx) / fx);
        tu_measured("f_order", log2(fabs(f4 - fx) / fabs(f8 - fx)));
        tu_measured("fb_vlbse", fabs(fb - MS_F1_PAPER_BEAM3) / MS_F1_PAPER_BEAM3);
        tu_report("3D string f1, 8 elements vs exact", fabs(f8 - fx) / fx, 2e-6);
        tu_report("3D beam f1, 4 elements vs paper VLBSE",
                  fabs(fb - MS_F1_PAPER_BEAM3) / MS_F1_PAPER_BEAM3, 1e-3);
        ASSERT_CLOSE(f8, fx, 2e-6, 0);
        ASSERT_CLOSE(fb, MS_F1_PAPER_BEAM3, 1e-3, 0);
    }
#else
    tu_report("3D string f1 (float), 4 elements vs exact", fabs(f4 - fx) / fx,
              4.0 * (double)FLT_EPSILON / prestretch());
    tu_measured("f4_exact", fabs(f4 - fx) / fx);
    ASSERT_CLOSE(f4, fx, 4.0 * (double)FLT_EPSILON / prestretch(), 0);
#endif
}

/* Isotropy: the string and the beam vibrating in the x-z plane (initial
   velocities along z) against the x-y plane, histories compared with y
   and z exchanged, 0.5 s at h = 2e-4 (slow builds: 0.1 s, the string
   only): measured bit for bit equal, largest differences 0 (m~:xs_diff)
   and 0 (m~:xb_diff) in double, 0 (m@flt~:xs_diff) and 0 (m@flt~:xb_diff)
   in float, held to the tolerances of check_cmp. */
static void test_isotropy(void **state)
{
    const int slow = tu_slow_run();
    const double t_end = slow ? 0.1 : 0.5;
    (void)state;
    check_cmp("x-z vs x-y plane, string", "xs", M3 | MS_XZ, M3, t_end);
    if (!slow)
        check_cmp("x-z vs x-y plane, beam", "xb", M3 | MS_XZ | MS_BEND, M3 | MS_BEND, t_end);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_planar_agreement),
        cmocka_unit_test(test_f1_exact),
        cmocka_unit_test(test_isotropy),
    };
    return cmocka_run_group_tests_name("scenes_moving3d", tests, NULL, NULL);
}
