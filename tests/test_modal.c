/* test_modal.c -- cmocka suite of the modal analyses of the scenes: the
   Campbell diagram of the rotating cantilever (examples/campbell_rotating.c)
   and the eigen route of the axially moving string and beam
   (examples/moving_string.c): linearisation (vlbe_dae_linearize) and the
   gyroscopic eigenproblem (vlbe_eig_quad) against closed forms, a
   continuum series, the exact rotating beam and the time histories.
   -- part of vlbe                                  SPDX-License-Identifier: MIT
   cc -std=c99 -Wall -Wextra -Wpedantic ... -O2 tests/test_modal.c -lcmocka -lm

   Tests
     rot_exact        the shooting reference ex_cant_rot: at Om = 0 the
                      cantilever roots (ex_cant_b^2), flap mode 1 at
                      Om = 1..12 the published table, lag^2 = flap^2 - Om^2
     rot_campbell     3D beam-shaft and planar chains spinning: reduced =
                      full (planar lag = 3D lag), Om = 0: flap = lag, h^4
                      convergence to the exact rotating beam in the
                      inextensible limit, the 1/EA law of the difference
     rot_floating     the linearisation about the unstressed beam (linear
                      floating frame): lag^2 = w0^2 - Om^2 below w0, stable
                      at 0.95 w0, unstable at 1.05 w0 (both sides)
     moving_modes     the flowing window: string modes against the closed
                      form k (c^2 - v^2) / (2 l c), beam modes against the
                      Galerkin series, h^4 convergence, at three speeds
     moving_history   4 elements: the eigen route's f1 against the time
                      history's (Richardson-extrapolated DFT peak)
     moving_diverge   divergence speed: stiff below, lost above (both
                      sides), at the analytic speed
   Float: the chain tests skip.  A straight prestressed or stretched chain
   carries its strain to a few EPS, a spurious tension of EA EPS: relative
   to the bending stiffness of these slender beams (EA L^2 / EI = 2e5 and
   8e5) that is 2-10 % of a frequency in float, so a float run measures
   the rounding of the strain and not the analysis (tests/test_lin.c
   checks the linearisation itself in float).
   Set VLBE_TEST_REPORT=1 to print measured errors beside the tolerances. */
#include "test_util.h"

#include "../scenes/campbell_rotating.h"
#include "../scenes/moving_string.h"

#define DBL_ONLY()                                                                             \
    do {                                                                                       \
        if (sizeof(vlbe_real) != sizeof(double)) {                                             \
            print_message("    float: skipped (the strain's rounding dominates, see top)\n"); \
            skip();                                                                            \
        }                                                                                      \
    } while (0)

static double rel(double a, double b) { return fabs(a - b) / fabs(b); }

/* -- the exact rotating cantilever ------------------------------------- */
static void test_rot_exact(void **state)
{
    /* Wright, Smith, Thresher, Wang (1982), flap mode 1 at Om = 1..12, five
       digits: agreement to half a unit of the last one */
    static const double pub[12] = {3.6816, 4.1373, 4.7973, 5.5850, 6.4495, 7.3604,
                                   8.2996, 9.2568, 10.2257, 11.2023, 12.1843, 13.1702};
    int n, k;
    (void)state;
    /* at Om = 0 the clamped-free roots: the RK4 truncation with 2000 steps
       is (b h)^4 / 120 ~ 1e-13 relative for b <= 8, the bisection ends at
       2e-16: held to 1e-10 */
    for (n = 1; n <= 3; ++n) {
        const double e = rel(ex_cant_rot(n, 0.0, 0), ex_cant_b[n - 1] * ex_cant_b[n - 1]);
        tu_report("rot_exact: Om = 0 root vs ex_cant_b^2", e, 1e-10);
        assert_true(e <= 1e-10);
    }
    for (k = 0; k < 12; ++k) {
        const double w = ex_cant_rot(1, k + 1.0, 0);
        assert_true(fabs(w - pub[k]) <= 0.5e-4 + 1e-12);
    }
    /* the lag equation solved on its own: w_lag^2 = w_flap^2 - Om^2, both
       to the truncation above */
    for (k = 2; k <= 10; k += 4) {
        const double f = ex_cant_rot(1, k, 0), l = ex_cant_rot(1, k, 1);
        const double e = rel(l * l, f * f - (double)k * k);
        tu_report("rot_exact: lag^2 vs flap^2 - Om^2", e, 1e-10);
        assert_true(e <= 1e-10);
    }
}

/* -- the rotating chains ------------------------------------------------ */
static void test_rot_campbell(void **state)
{
    const double u = cr_unit();
    double Om[2] = {0.0, 10.0}, l2[2][CR_NW], f2[2][CR_NW], l3[2][CR_NW], f3[2][CR_NW];
    double l8[1][CR_NW], f8[1][CR_NW], l16[1][CR_NW], f16[1][CR_NW], le[3][1][CR_NW],
        fe[1][CR_NW], cpu;
    const double fx = u * ex_cant_rot(1, 10.0 / u, 0), lx = u * ex_cant_rot(1, 10.0 / u, 1);
    double e8, e16;
    int k;
    (void)state;
    DBL_ONLY();
    assert_int_equal(cr_sweep(8, 2, 1.0, 1, 2, Om, l2, f2, NULL, &cpu), 0);
    assert_int_equal(cr_sweep(8, 3, 1.0, 1, 2, Om, l3, f3, NULL, &cpu), 0);
    /* reduced = full: the 3D element in the plane is the planar one (its
       curvature vector is the planar curvature times the normal), so the
       two chains' in-plane modes agree to the rounding of two eigen-solves
       of matrices with condition ~1e9 (the axial modes): 1e-9 relative */
    for (k = 0; k < 2; ++k) {
        const double e = rel(l3[1][k], l2[1][k]);
        tu_report("rot_campbell: 3D lag vs planar lag, Om = 10", e, 1e-9);
        assert_true(e <= 1e-9);
    }
    /* at rest flap and lag are the same modes (round section) */
    for (k = 0; k < 2; ++k) assert_true(rel(f3[0][k], l3[0][k]) <= 1e-9);
    /* the inextensible limit (EA x 1000): the exact rotating beam, to the
       discretisation error of the Hermite elements, which falls as h^4:
       at least a factor 8 from 8 to 16 elements (16 in the limit) */
    assert_int_equal(cr_sweep(8, 3, 1000.0, 1, 1, Om + 1, l8, f8, NULL, &cpu), 0);
    assert_int_equal(cr_sweep(16, 3, 1000.0, 1, 1, Om + 1, l16, f16, NULL, &cpu), 0);
    e8 = rel(f8[0][0], fx);
    e16 = rel(f16[0][0], fx);
    tu_report("rot_campbell: flap 1, 16 el., EA x 1000", e16, e8 / 8.0);
    assert_true(e16 <= e8 / 8.0);
    e8 = rel(l8[0][0], lx);
    e16 = rel(l16[0][0], lx);
    tu_report("rot_campbell: lag 1, 16 el., EA x 1000", e16, e8 / 8.0);
    assert_true(e16 <= e8 / 8.0);
    /* the extensible beam departs from the inextensible theory by the
       stretch and the Coriolis coupling with the axial modes, both of
       order Om^2 rhoA L^2 / EA: with EA x 1, x 10 against x 1000 the
       departure falls tenfold (to 10 %, the next order) */
    for (k = 0; k < 2; ++k)
        assert_int_equal(cr_sweep(16, 2, k ? 10.0 : 1.0, 1, 1, Om + 1, le[k], fe, NULL, &cpu), 0);
    assert_int_equal(cr_sweep(16, 2, 1000.0, 1, 1, Om + 1, le[2], fe, NULL, &cpu), 0);
    {
        const double d1 = le[0][0][0] - le[2][0][0], d10 = le[1][0][0] - le[2][0][0];
        tu_report("rot_campbell: 1/EA law of the lag departure", fabs(10.0 * d10 / d1 - 1.0), 0.1);
        assert_true(d1 < 0.0);
        assert_true(fabs(10.0 * d10 / d1 - 1.0) <= 0.1);
    }
}

static void test_rot_floating(void **state)
{
    const double w0e = cr_unit() * ex_cant_b[0] * ex_cant_b[0];
    double Om[3], l[3][CR_NW], f[3][CR_NW], re[3], cpu;
    (void)state;
    DBL_ONLY();
    Om[0] = 0.0;
    Om[1] = 0.95 * w0e;
    Om[2] = 1.05 * w0e;
    assert_int_equal(cr_sweep(8, 2, 1.0, 0, 3, Om, l, f, re, &cpu), 0);
    /* about the unstressed beam the frame adds only M G^2 (softening) and
       the Coriolis coupling with the axial modes: lag^2 = w0^2 - Om^2 to
       (Om / w_axial)^2 ~ 3e-5 of w0^2 at 0.95 w0 (w_axial = 762 rad/s) */
    {
        const double e = fabs(l[1][0] * l[1][0] - (l[0][0] * l[0][0] - Om[1] * Om[1])) /
                         (l[0][0] * l[0][0]);
        tu_report("rot_floating: lag^2 vs w0^2 - Om^2 at 0.95 w0", e, 1e-4);
        assert_true(e <= 1e-4);
    }
    /* both sides of the limit w0: below, every Re s is rounding (1e-3 w0
       is far above it); above, the divergent pair grows at
       sqrt(Om^2 - w0^2) = 0.32 w0 */
    assert_true(re[1] <= 1e-3 * w0e);
    assert_true(re[2] >= 0.2 * w0e);
}

/* -- the flowing window -------------------------------------------------- */
static void test_moving_modes(void **state)
{
    double rhoA, EA, EI, eps, lam, c;
    const double sp[3] = {0.0, MS_V0, 60.0};
    int b, s, k;
    (void)state;
    DBL_ONLY();
    ms_section(&rhoA, &EA, &EI, &eps, &lam);
    c = sqrt(MS_F * lam / rhoA);
    for (b = 0; b < 2; ++b)
        for (s = 0; s < 3; ++s) {
            double f8[3], f16[3], g[3], amax = 0, cpu;
            assert_int_equal(ms_eig(8, b, sp[s], 3, f8, NULL, &cpu), VLBE_OK);
            assert_int_equal(ms_eig(16, b, sp[s], 3, f16, &amax, &cpu), VLBE_OK);
            if (b) {
                assert_int_equal(ms_galerkin(1, sp[s], MS_GAL_MAX, 3, g), VLBE_OK);
            } else {
                for (k = 0; k < 3; ++k) g[k] = (k + 1) * (c * c - sp[s] * sp[s]) / (2.0 * MS_L * c);
            }
            for (k = 0; k < 3; ++k) {
                /* h^4: the 16-element error at most a tenth of the
                   8-element one, or at the reference's own floor (the
                   Galerkin series to 48 sine modes: below 3e-7, see
                   ms_galerkin; the string's closed form: exact, the
                   floor the rounding of the eigen-solve, 1e-10) */
                const double e8 = rel(f8[k], g[k]), e16 = rel(f16[k], g[k]);
                const double floor = b ? 3e-7 : 1e-10;
                tu_report(b ? "moving_modes: beam, 16 el. vs Galerkin"
                            : "moving_modes: string, 16 el. vs closed form",
                          e16, fmax(e8 / 10.0, floor));
                assert_true(e16 <= fmax(e8 / 10.0, floor));
            }
        }
}

static void test_moving_history(void **state)
{
    const int slow = tu_slow_run();
    const double h = slow ? 8e-4 : 2e-4, T = slow ? 0.25 : 0.5;
    int b;
    (void)state;
    DBL_ONLY();
    for (b = 0; b < 2; ++b) {
        double fe = 0, cpu = 0;
        const double ft = ms_freq(4, b, h, T, NULL, NULL);
        assert_int_equal(ms_eig(4, b, MS_V0, 1, &fe, NULL, &cpu), VLBE_OK);
        assert_true(ft > 0);
        /* the time history's estimate: Richardson over h, h/2 leaves
           O((w h)^4) ~ 1e-8 at h = 2e-4 (3e-6 at 8e-4), the DFT peak of
           0.5 s of record about 1e-7: held to 1e-6 (1e-5 in slow builds) */
        tu_report("moving_history: eigen f1 vs time history", rel(fe, ft), slow ? 1e-5 : 1e-6);
        assert_true(rel(fe, ft) <= (slow ? 1e-5 : 1e-6));
    }
}

static void test_moving_diverge(void **state)
{
    const double PI = 3.14159265358979323846;
    double rhoA, EA, EI, eps, lam, vd[2];
    int b;
    (void)state;
    DBL_ONLY();
    ms_section(&rhoA, &EA, &EI, &eps, &lam);
    vd[0] = sqrt(MS_F * lam / rhoA);
    vd[1] = sqrt((lam * MS_F + EI * PI * PI / (MS_L * MS_L)) / rhoA);
    for (b = 0; b < 2; ++b) {
        /* both sides, 1 % off: the 16-element discretisation moves the
           divergence speed by its first mode's error (below 1e-6) */
        const double v = ms_divergence(16, b, 0.99 * vd[b], 1.01 * vd[b]);
        assert_int_equal(ms_diverged(16, b, 0.99 * vd[b]), 0);
        assert_int_equal(ms_diverged(16, b, 1.01 * vd[b]), 1);
        tu_report("moving_diverge: divergence speed vs analytic", rel(v, vd[b]), 1e-6);
        assert_true(rel(v, vd[b]) <= 1e-6);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_rot_exact),      cmocka_unit_test(test_rot_campbell),
        cmocka_unit_test(test_rot_floating),   cmocka_unit_test(test_moving_modes),
        cmocka_unit_test(test_moving_history), cmocka_unit_test(test_moving_diverge),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
