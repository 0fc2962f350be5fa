/* test_katz.c -- the analytic reference of the spinning-shaft scene
   (VLBSE scene 4.3; scenes/ex_katz.h: Katz 2001, paper section 4.3,
   eqs. 59-63) checked against independent facts.
   -- part of vlbe                                  SPDX-License-Identifier: MIT

   ORACLE CHECKS, NOT LIBRARY TESTS.  Nothing here calls vlbe: every test
   checks scenes/ex_katz.h, the exact modal-series solution that the
   spinning-shaft scene (examples/spinning_shaft.c, tests/test_scenes_shaft.c,
   bench/wp_shaft.c) compares vlbe's ANCF shaft with.  They make that
   comparison rest on a verified reference: a wrong oracle would pass or
   fail the scene for the wrong reason.  The cmocka group is named
   "katz_oracle" so that its count is not read as library coverage.

   Tests
     setup_definitions  the derived values against the definitions written
                        out here: r = 2 beta1 l / pi, J = pi r^4 / 4,
                        omega_1 = (pi/l)^2 sqrt(EJ/rhoA), v = a omega_1 l/pi,
                        omega = 2 pi v k_omega / l, U_s = P l^3/(48 EJ),
                        T = l / v, and with r, A, J eliminated omega_1 =
                        pi beta1 sqrt(E / rho) / l, v_cr = beta1 sqrt(E /
                        rho); bad arguments are refused
     mode_ode_residual  w_n(t) of ex_katz_mode satisfies the modal ODE
                        a w'' - i b w' + c w = F0 sin(theta t) e^{i omega t}
                        (coefficients formed here from eq. 59) by 5-point
                        central differences, for the two paper cases, a
                        thick fast-spinning shaft (both spin senses, load
                        turning backwards) and an exactly resonant load
                        (omega + theta_1 = s1); w(0) = 0 exactly and
                        w(h) = F0 theta h^3 / (6 a) (1 + O(s h)), i.e.
                        w'(0) = w''(0) = 0 and the ODE holds at t = 0
     closed_forms       the paper's expanded eqs. 62-63 (two cases, both
                        rot, modes 1..30) and Fryba's moving-load solution
                        (omega = Omega = 0, rot = 0: a = 0.5, 1.5 and the
                        resonant a = 1, sin - w0 t cos)
     quasi_static       a slow load (a = 1e-4 and 1e-7, k_omega = 0,
                        Omega = 0, rot = 0) deflects the shaft as the static
                        simply supported beam under P at z0 = v t:
                        P b x (l^2 - b^2 - x^2) / (6 EJ l), x <= z0,
                        b = l - z0 (mirrored for x > z0); U_s at midspan
     rot_vs_nonrot      rot = 1 against rot = 0 (N = 30 modes): the
                        difference is O(beta1^2): its size on the paper
                        cases, and halving beta1 divides it by ~4 (the
                        rot = 0 response in U/U_s does not depend on beta1)
     conv_modes         ex_katz_modes_for picks N = 30 for 1e-5 U_s in both
                        cases and both rot; on a 4001-interval grid
                        |U_30 - U_60| and |U_30 - U_240| stay below 1e-5 U_s
   The reference is double-only (like test_util.h), so the float build
   runs the same checks with the same tolerances.  Tolerances are stated
   and justified at each test; VLBE_TEST_REPORT=1 prints the measured
   errors beside them. */
#include "test_util.h"
#include "../scenes/ex_katz.h"

#define KPI 3.14159265358979323846
#define KEPS 2.220446049250313e-16 /* double: the reference computes in double */

/* Table 4 of the paper */
#define K_L 1.0
#define K_BETA1 0.02
#define K_E 206e9
#define K_RHO 7700.0
#define K_OMEGA 1.0
#define K_P 1.0

static const double g_case[2][2] = {{0.5, 1.0}, {1.5, 0.5}}; /* (a, k_omega) */

static void setup_case(ex_katz *k, int c, int rot)
{
    assert_int_equal(ex_katz_setup(k, K_L, K_BETA1, K_E, K_RHO, K_OMEGA, g_case[c][0],
                                   g_case[c][1], K_P, rot),
                     0);
}

/* the modal ODE of mode n, formed here from eq. 59: a w'' - i b w' + c w
   = F0 sin(th t) e^{i om t}, and its roots s1 > 0 > s2 */
typedef struct mode_ode {
    double a, b, c, F0, th, om, s1, s2;
} mode_ode;

static mode_ode mode_coefs(const ex_katz *k, int n)
{
    mode_ode m;
    const double kn = (double)n * KPI / k->l, J = KPI * pow(k->r, 4.0) / 4.0;
    const double A = KPI * k->r * k->r, rhoJ = k->rho * J, rhoA = k->rho * A;
    const double d2 = k->rot ? rhoJ * kn * kn : 0.0; /* -rhoJ d2/dz2 -> +rhoJ k^2 */
    double disc;
    m.a = (rhoA + d2) / rhoA;
    m.b = 2.0 * k->Omega * d2 / rhoA;
    m.c = k->E * J * pow(kn, 4.0) / rhoA;
    m.F0 = 2.0 * k->P / (rhoA * k->l);
    m.th = kn * k->v;
    m.om = k->omega;
    /* -a s^2 + b s + c = 0 */
    disc = sqrt(m.b * m.b + 4.0 * m.a * m.c);
    m.s1 = (m.b + disc) / (2.0 * m.a);
    m.s2 = (m.b - disc) / (2.0 * m.a);
    return m;
}

static void mode(const ex_katz *k, int n, double t, double *wr, double *wi)
{
    assert_int_equal(ex_katz_mode(k, n, t, wr, wi), 0);
}

static double fmax3(double x, double y, double z) { return fmax(x, fmax(y, z)); }

/* ---------------------------------------------------------------------- */
/* Definitions (ex_katz.h, "Non-dimensional parameters"), recomputed here
   from the Table 4 inputs by other routes: J from r^4, omega_1 from the
   first Euler-Bernoulli eigenvalue written out, the traverse time from a.
   All to 16 EPS relative (a handful of roundings, pow against products).
   With J = A r_g^2 and r_g = beta1 l / pi the section drops out:
   omega_1 = pi beta1 sqrt(E / rho) / l and v_cr = beta1 sqrt(E / rho),
   evaluated from the Table 4 inputs, also to 16 EPS.  The paper
   prints neither number (it leaves the definitions to Katz 2001; these
   are our reading): on Table 4 they are omega_1 = 324.99 rad/s, v_cr =
   103.45 m/s, checked to half a unit of the last digit shown (0.005).
   Then every bad argument is refused and leaves *k as it was. */
static void test_setup_definitions(void **state)
{
    ex_katz k, k0;
    double r, J, A, w1, v, u1 = 7.0, u2 = 7.0, wr = 7.0, wi = 7.0;
    int c, rot, j, st, nm = -1;
    (void)state;
    for (c = 0; c < 2; ++c)
        for (rot = 0; rot < 2; ++rot) {
            const double a = g_case[c][0], kw = g_case[c][1];
            setup_case(&k, c, rot);
            r = 2.0 * K_BETA1 * K_L / KPI;
            J = KPI * pow(r, 4.0) / 4.0;
            A = KPI * r * r;
            w1 = pow(KPI / K_L, 2.0) * sqrt(K_E * J / (K_RHO * A));
            v = a * w1 * K_L / KPI;
            ASSERT_CLOSE(k.r, r, 16.0 * KEPS, 0.0);
            ASSERT_CLOSE(k.J, J, 16.0 * KEPS, 0.0);
            ASSERT_CLOSE(k.A, A, 16.0 * KEPS, 0.0);
            ASSERT_CLOSE(k.w1, w1, 16.0 * KEPS, 0.0);
            ASSERT_CLOSE(k.v, v, 16.0 * KEPS, 0.0);
            ASSERT_CLOSE(k.omega, 2.0 * KPI * v * kw / K_L, 16.0 * KEPS, 0.0);
            ASSERT_CLOSE(ex_katz_traverse_time(&k), K_L / v, 16.0 * KEPS, 0.0);
            ASSERT_CLOSE(ex_katz_us(&k), K_P * pow(K_L, 3.0) / (48.0 * K_E * J), 16.0 * KEPS,
                         0.0);
            /* the closed forms without r, A, J */
            ASSERT_CLOSE(k.w1, KPI * K_BETA1 * sqrt(K_E / K_RHO) / K_L, 16.0 * KEPS, 0.0);
            ASSERT_CLOSE(k.vcr, K_BETA1 * sqrt(K_E / K_RHO), 16.0 * KEPS, 0.0);
            /* the rounded values quoted above: half a unit of their last digit */
            ASSERT_CLOSE(k.w1, 324.99, 0.0, 0.005);
            ASSERT_CLOSE(k.vcr, 103.45, 0.0, 0.005);
            /* theta_1 / omega_1 = a: the first critical speed is a = 1 */
            ASSERT_CLOSE(mode_coefs(&k, 1).th / sqrt(mode_coefs(&k, 1).c), a, 16.0 * KEPS, 0.0);
            assert_int_equal(k.rot, rot);
        }
    /* refused arguments: *k untouched */
    setup_case(&k, 0, 1);
    memcpy(&k0, &k, sizeof k);
    for (j = 0; j < 8; ++j) {
        /* inputs l, beta1, E, rho, Omega, a, k_omega, P; row j spoils input j */
        double in[8] = {1.0, 0.02, 2e11, 7700.0, 1.0, 0.5, 1.0, 1.0};
        static const double spoil[8] = {0.0, -0.02, 0.0, -1.0, 0.0, 0.0, 0.0, 0.0};
        if (j == 4 || j == 7) in[j] = (double)NAN;
        else if (j == 6) in[j] = (double)INFINITY;
        else in[j] = spoil[j];
        st = ex_katz_setup(&k, in[0], in[1], in[2], in[3], in[4], in[5], in[6], in[7], 1);
        assert_int_equal(st, EX_KATZ_EARG);
    }
    st = ex_katz_setup(NULL, 1.0, 0.02, 2e11, 7700.0, 1.0, 0.5, 1.0, 1.0, 1);
    assert_int_equal(st, EX_KATZ_EARG);
    assert_memory_equal(&k, &k0, sizeof k);
    assert_int_equal(ex_katz_eval(&k, 0, 0.5, 0.0, &u1, &u2), EX_KATZ_EARG);
    assert_int_equal(ex_katz_eval(&k, 5, -1e-9, 0.0, &u1, &u2), EX_KATZ_EARG);
    assert_int_equal(ex_katz_eval(&k, 5, 1.0 + 1e-9, 0.0, &u1, &u2), EX_KATZ_EARG);
    assert_int_equal(ex_katz_eval(&k, 5, 0.5, -1e-9, &u1, &u2), EX_KATZ_EARG);
    assert_int_equal(ex_katz_eval(&k, 5, 0.5, k.T * (1.0 + 1e-9), &u1, &u2), EX_KATZ_EARG);
    assert_int_equal(ex_katz_eval(&k, 5, (double)NAN, 0.0, &u1, &u2), EX_KATZ_EARG);
    assert_int_equal(ex_katz_mode(&k, 0, 0.001, &wr, &wi), EX_KATZ_EARG);
    assert_true(u1 == 7.0 && u2 == 7.0 && wr == 7.0 && wi == 7.0);
    assert_int_equal(ex_katz_modes_for(&k, 0.0, 10, &nm, NULL), EX_KATZ_EARG);
    assert_int_equal(ex_katz_modes_for(&k, 1e-5, 3, &nm, NULL), EX_KATZ_ENOCONV);
    assert_int_equal(nm, -1);
    /* the end points are accepted */
    assert_int_equal(ex_katz_eval(&k, 5, 0.0, 0.0, &u1, &u2), 0);
    assert_int_equal(ex_katz_eval(&k, 5, k.l, k.T, &u1, &u2), 0);
}

/* ---------------------------------------------------------------------- */
/* The modal ODE.  Parameter sets (l = 1, P = 1):
     0, 1  the paper's cases, rot = 1 (Omega = 1: b tiny)
     2     beta1 = 0.2, Omega = 300 rad/s, a = 0.8, k_omega = -0.7 (thick
           shaft, b/a up to ~600 rad/s: the gyroscopic term matters; the
           load turns against the spin)
     3     as 2 with Omega = -300 (the other root branch)
     4     case 0 with omega set so that omega + theta_1 = s1 (forward whirl
           resonance of mode 1, s1 from the quadratic formula here)
   Modes n = 1, 2, 7, 30; times 0.013 T, 0.3 T, 0.61 T, T.
   Derivatives by the 5-point central stencils with h = 0.02 / smax, smax
   the largest of |s1|, |s2|, |omega +- theta|:
     w'  = (w(-2h) - 8 w(-h) + 8 w(h) - w(2h)) / (12 h), error h^4 w^(5)/30
     w'' = (-w(-2h) + 16 w(-h) - 30 w + 16 w(h) - w(2h)) / (12 h^2),
           error h^4 w^(6)/90.
   Scale: S = |a w''| + |b w'| + |c w| + |F0| (the sizes of the terms of
   the residual, with the forcing amplitude: w may sit at a node of
   sin(theta t) where all terms are small).  w is a sum of exponentials in
   s1, s2, omega +- theta (at resonance t e^{i s1 t} too) whose amplitudes
   times smax^2 are of the size of S, so relative to S
     truncation  ~ (smax h)^4 / 90 = 1.8e-9,
     rounding    ~ EPS (1 + smax t) / (smax h)^2: the phases of w carry
                   ~ EPS smax t of the amplitudes (ex_katz.h, Accuracy),
                   and w'' divides by h^2 (with the stencil's 64/12).
   Tolerance S (4 (smax h)^4 / 90 + 8 EPS (1 + smax t) / (smax h)^2).
   Measured: 0.24 (m:ode_res) of it (the truncation at n = 1, 2 early on,
   the rounding at n = 30, t = T where smax t ~ 5e3).
   Start: w(0) = 0 exactly (all divided differences vanish at t = 0); with
   w(0) = w'(0) = 0 the ODE gives w''(0) = 0 and a w'''(0) = F0 theta, so
   w(h) = F0 theta h^3 / (6 a) (1 + O(smax h)): h = 1e-4 / smax, tolerance
   4 smax h relative (the next Taylor term is w''''(0) h / (4 w'''(0)) with
   |w''''(0) / w'''(0)| = |2 omega + b / a| <= 3 smax; rounding of the
   divided differences ~ EPS / (smax h)^2 = 2e-8 relative).
   Measured: 0.083 (m:ode_start) of it.  Together: w solves the initial
   value problem, which has one solution. */
static void param_set(ex_katz *k, int p)
{
    switch (p) {
    case 0: setup_case(k, 0, 1); break;
    case 1: setup_case(k, 1, 1); break;
    case 2:
        assert_int_equal(ex_katz_setup(k, 1.0, 0.2, K_E, K_RHO, 300.0, 0.8, -0.7, 1.0, 1), 0);
        break;
    case 3:
        assert_int_equal(ex_katz_setup(k, 1.0, 0.2, K_E, K_RHO, -300.0, 0.8, -0.7, 1.0, 1), 0);
        break;
    default: {
        mode_ode m;
        setup_case(k, 0, 1);
        m = mode_coefs(k, 1);
        k->omega = m.s1 - m.th;
        break;
    }
    }
}

static void test_mode_ode_residual(void **state)
{
    static const int ns[4] = {1, 2, 7, 30};
    static const double ts[4] = {0.013, 0.3, 0.61, 1.0};
    double worst = 0.0, worst0 = 0.0;
    int p, in, it, j;
    (void)state;
    for (p = 0; p < 5; ++p) {
        ex_katz k;
        param_set(&k, p);
        for (in = 0; in < 4; ++in) {
            const mode_ode m = mode_coefs(&k, ns[in]);
            const double smax =
                fmax(fmax(fabs(m.s1), fabs(m.s2)), fmax(fabs(m.om + m.th), fabs(m.om - m.th)));
            const double sh = 0.02;
            double h = sh / smax, wr0, wi0, w3;
            for (it = 0; it < 4; ++it) {
                const double t = ts[it] * k.T;
                double wr[5], wi[5], d1r, d1i, d2r, d2i, fr, fi, rr, ri, S, tol;
                for (j = 0; j < 5; ++j) mode(&k, ns[in], t + (double)(j - 2) * h, &wr[j], &wi[j]);
                d1r = (wr[0] - 8.0 * wr[1] + 8.0 * wr[3] - wr[4]) / (12.0 * h);
                d1i = (wi[0] - 8.0 * wi[1] + 8.0 * wi[3] - wi[4]) / (12.0 * h);
                d2r = (-wr[0] + 16.0 * (wr[1] + wr[3]) - 30.0 * wr[2] - wr[4]) / (12.0 * h * h);
                d2i = (-wi[0] + 16.0 * (wi[1] + wi[3]) - 30.0 * wi[2] - wi[4]) / (12.0 * h * h);
                fr = m.F0 * sin(m.th * t) * cos(m.om * t);
                fi = m.F0 * sin(m.th * t) * sin(m.om * t);
                /* a w'' - i b w' + c w - F;  -i b (x + i y) = b y - i b x */
                rr = m.a * d2r + m.b * d1i + m.c * wr[2] - fr;
                ri = m.a * d2i - m.b * d1r + m.c * wi[2] - fi;
                S = m.a * hypot(d2r, d2i) + fabs(m.b) * hypot(d1r, d1i) +
                    m.c * hypot(wr[2], wi[2]) + fabs(m.F0);
                tol = S * (4.0 * pow(sh, 4.0) / 90.0 + 8.0 * KEPS * (1.0 + smax * t) / (sh * sh));
                ASSERT_CLOSE_CTX(hypot(rr, ri), 0.0, 0.0, tol, "set %d, n %d, t %g T", p, ns[in],
                                 ts[it]);
                worst = fmax(worst, hypot(rr, ri) / tol);
            }
            /* start */
            mode(&k, ns[in], 0.0, &wr0, &wi0);
            assert_true(wr0 == 0.0 && wi0 == 0.0);
            h = 1e-4 / smax;
            mode(&k, ns[in], h, &wr0, &wi0);
            w3 = m.F0 * m.th * h * h * h / (6.0 * m.a);
            ASSERT_CLOSE_CTX(hypot(wr0 - w3, wi0), 0.0, 0.0, 4.0 * smax * h * fabs(w3),
                             "start: set %d, n %d", p, ns[in]);
            worst0 = fmax(worst0, hypot(wr0 - w3, wi0) / (4.0 * smax * h * fabs(w3)));
        }
    }
    tu_report("modal ODE residual (ratio)", worst, 1.0);
    tu_report("start w(h) vs F0 theta h^3/(6a) / (4 smax h)", worst0, 1.0);
    tu_measured("ode_res", worst);
    tu_measured("ode_start", worst0);
}

/* ---------------------------------------------------------------------- */
/* Closed forms.
   (a) Eqs. 62-63 as printed (the '.' between the terms of eq. 63 read as
   minus signs), r1 = omega + theta_n, r2 = theta_n - omega, omega_n1 = s1,
   omega_n2 = s2, per mode: U1_n = pref {-(s2-r1)(s2+r2)(r1+r2) sin s1 t +
   (s1-r1)(s1+r2)(r1+r2) sin s2 t - (s1-s2)(s1+r2)(s2+r2) sin r1 t -
   (s1-s2)(s1-r1)(s2-r1) sin r2 t}, U2_n the same with cos and the signs
   +, -, +, -, pref = F0 theta / (a (s1-s2)(r1+r2)(s1-r1)(s1+r2)(s2-r1)
   (s2+r2)).  Paper cases, both rot, modes 1..30, 50 times of the
   traverse.  The four terms are computed independently and summed, so the
   rounding is EPS times the sum of their sizes Sigma, times (1 + smax t)
   for the phases: tolerance 64 EPS (1 + smax t) Sigma (measured below).
   (b) Fryba (omega = Omega = 0, rot = 0, U2 = 0):
   w_n = F0 (sin theta t - (theta / w0) sin w0 t) / (w0^2 - theta^2):
   a = 0.5, 1.5, modes 1..30, 50 times, to 64 EPS (1 + w0 t) Sigma as in
   (a).  At the critical speed a = 1, mode 1 is resonant (theta_1 = w0_1
   up to rounding, delta = |theta_1 - w0_1| <= 4 EPS w0):
   w_1 = F0 (sin w0 t - w0 t cos w0 t) / (2 w0^2).  ex_katz takes its
   confluent divided differences straight through; the solution's
   derivative in theta is ~ F0 t^2 / w0 (the secular term), so the
   rounded theta_1 moves it by ~ 4 EPS (w0 t)^2 F0 / w0^2: tolerance
   (64 EPS (1 + w0 t) + 8 EPS (w0 t)^2) F0 / w0^2.
   Measured: 0.017 (m:cf_paper) of the tolerance for (a), 0.017
   (m:cf_fryba) for (b), 0.0035 (m:cf_crit) at a = 1. */
static void paper_mode(const mode_ode *m, double t, double *u1, double *u2, double *sig)
{
    const double s1 = m->s1, s2 = m->s2, r1 = m->om + m->th, r2 = m->th - m->om;
    const double pref = m->F0 * m->th / (m->a * (s1 - s2) * (r1 + r2) * (s1 - r1) * (s1 + r2) *
                                         (s2 - r1) * (s2 + r2));
    const double c1 = pref * (s2 - r1) * (s2 + r2) * (r1 + r2);
    const double c2 = pref * (s1 - r1) * (s1 + r2) * (r1 + r2);
    const double c3 = pref * (s1 - s2) * (s1 + r2) * (s2 + r2);
    const double c4 = pref * (s1 - s2) * (s1 - r1) * (s2 - r1);
    *u1 = -c1 * sin(s1 * t) + c2 * sin(s2 * t) - c3 * sin(r1 * t) - c4 * sin(r2 * t);
    *u2 = c1 * cos(s1 * t) - c2 * cos(s2 * t) + c3 * cos(r1 * t) - c4 * cos(r2 * t);
    *sig = fabs(c1) + fabs(c2) + fabs(c3) + fabs(c4);
}

static void test_closed_forms(void **state)
{
    double worst_p = 0.0, worst_f = 0.0, worst_r = 0.0;
    int c, rot, n, j;
    ex_katz k;
    (void)state;
    for (c = 0; c < 2; ++c)
        for (rot = 0; rot < 2; ++rot) {
            setup_case(&k, c, rot);
            for (n = 1; n <= 30; ++n) {
                const mode_ode m = mode_coefs(&k, n);
                const double smax = fmax(fabs(m.s1), fabs(m.om) + fabs(m.th));
                for (j = 1; j <= 50; ++j) {
                    const double t = k.T * (double)j / 50.0;
                    double wr, wi, p1, p2, sig, tol, e;
                    mode(&k, n, t, &wr, &wi);
                    paper_mode(&m, t, &p1, &p2, &sig);
                    tol = 64.0 * KEPS * (1.0 + smax * t) * sig;
                    e = hypot(wr - p1, wi - p2);
                    ASSERT_CLOSE_CTX(e, 0.0, 0.0, tol, "eq. 62-63: case %d rot %d n %d t %d/50", c,
                                     rot, n, j);
                    worst_p = fmax(worst_p, e / tol);
                }
            }
        }
    for (c = 0; c < 2; ++c) {
        const double a = c ? 1.5 : 0.5;
        assert_int_equal(ex_katz_setup(&k, K_L, K_BETA1, K_E, K_RHO, 0.0, a, 0.0, K_P, 0), 0);
        for (n = 1; n <= 30; ++n) {
            const mode_ode m = mode_coefs(&k, n);
            const double w0 = sqrt(m.c), th = m.th;
            for (j = 1; j <= 50; ++j) {
                const double t = k.T * (double)j / 50.0;
                const double c1 = m.F0 / (w0 * w0 - th * th), c2 = c1 * th / w0;
                double wr, wi, tol, e;
                mode(&k, n, t, &wr, &wi);
                tol = 64.0 * KEPS * (1.0 + w0 * t) * (fabs(c1) + fabs(c2));
                e = hypot(wr - (c1 * sin(th * t) - c2 * sin(w0 * t)), wi);
                ASSERT_CLOSE_CTX(e, 0.0, 0.0, tol, "Fryba: a %g n %d t %d/50", a, n, j);
                worst_f = fmax(worst_f, e / tol);
            }
        }
    }
    assert_int_equal(ex_katz_setup(&k, K_L, K_BETA1, K_E, K_RHO, 0.0, 1.0, 0.0, K_P, 0), 0);
    {
        const mode_ode m = mode_coefs(&k, 1);
        const double w0 = sqrt(m.c);
        for (j = 1; j <= 50; ++j) {
            const double t = k.T * (double)j / 50.0, x = w0 * t;
            const double ref = m.F0 * (sin(x) - x * cos(x)) / (2.0 * w0 * w0);
            const double tol = (64.0 * KEPS * (1.0 + x) + 8.0 * KEPS * x * x) * m.F0 / (w0 * w0);
            double wr, wi, e;
            mode(&k, 1, t, &wr, &wi);
            e = hypot(wr - ref, wi);
            ASSERT_CLOSE_CTX(e, 0.0, 0.0, tol, "Fryba resonant: t %d/50", j);
            worst_r = fmax(worst_r, e / tol);
        }
    }
    tu_report("eqs. 62-63 / (64 EPS (1 + s t) sum|terms|)", worst_p, 1.0);
    tu_report("Fryba moving load / (64 EPS (1 + w0 t) sum|terms|)", worst_f, 1.0);
    tu_report("Fryba critical speed a = 1 (ratio)", worst_r, 1.0);
    tu_measured("cf_paper", worst_p);
    tu_measured("cf_fryba", worst_f);
    tu_measured("cf_crit", worst_r);
}

/* ---------------------------------------------------------------------- */
/* Quasi-static limit.  omega = Omega = 0, rot = 0: the modes are Fryba's
   (closed_forms b), and with theta_n / w0_n = a / n
     w_n - F0 sin(theta t) / w0^2
       = F0 [(theta/w0)^2 sin(theta t) - (theta/w0) sin(w0 t)] / (w0^2 - theta^2),
   at most F0 / w0_n^2 (a/n + a^2/n^2) / (1 - a^2/n^2).  The static modes
   F0 sin(theta_n t) / w0_n^2 sin(k_n x) sum to the static deflection (the
   modal series of the Green's function), and F0 / w0_n^2 =
   (96 / pi^4) U_s / n^4, so
     |U - U_static| <= (96/pi^4) (a zeta(5) + a^2 zeta(6)) / (1 - a^2) U_s
                       + (96/pi^4) U_s / (3 N^3)   (static modes beyond N)
                    <= 1.022 a U_s + 0.33 U_s / N^3.
   The free vibration carries no factor sin(k_n z0), so mode 1 alone nearly
   reaches the bound (0.9855 a U_s at x = l/2 when |sin(w0_1 t)| = 1).
   Rounding: the phases w0 t carry ~ EPS w0 t of the amplitudes; mode 1,
   of size U_s, has w0_1 T = pi / a (3e7 for a = 1e-7; the high modes reach
   w0_N t ~ 1e14 but are 1e-14 U_s there).  Tolerance (1.03 a + 0.33 / N^3
   + 8 EPS (1 + w0_1 T)) U_s, N = 2000 modes.  Points: the load at
   z0 = l/2 (midspan: U_s exactly) and near 0.3 l, 0.85 l (offset so that
   w0_1 t = pi z0 / a is not a multiple of pi for either a: the free
   vibration is not sampled at its nodes), at x = 0.1, 0.3, 0.5, 0.7,
   0.95 l.  Measured: 0.95 (m:qs_a4) of it for a = 1e-4 (the bound is
   attained, see above), 0.42 (m:qs_a7) for a = 1e-7 (the free vibration
   at |sin(w0_1 t)| = 0.5, and rounding). */
static double static_defl(double P, double EJ, double l, double z0, double x)
{
    double b;
    if (x > z0) return static_defl(P, EJ, l, l - z0, l - x); /* mirror */
    b = l - z0;
    return P * b * x * (l * l - b * b - x * x) / (6.0 * EJ * l);
}

static void test_quasi_static(void **state)
{
    static const double as[2] = {1e-4, 1e-7};
    static const double z0s[3] = {0.5, 0.30005 + 1.7e-8, 0.85002 + 2.3e-8};
    static const double xs[5] = {0.1, 0.3, 0.5, 0.7, 0.95};
    const int N = 2000;
    double worst = 0.0;
    int ia, iz, ix;
    (void)state;
    for (ia = 0; ia < 2; ++ia) {
        ex_katz k;
        const double a = as[ia];
        double Us, tol;
        assert_int_equal(ex_katz_setup(&k, K_L, K_BETA1, K_E, K_RHO, 0.0, a, 0.0, K_P, 0), 0);
        Us = ex_katz_us(&k);
        tol = (1.03 * a + 0.33 / ((double)N * N * N) + 8.0 * KEPS * (1.0 + k.w1 * k.T)) * Us;
        worst = 0.0;
        for (iz = 0; iz < 3; ++iz) {
            const double t = z0s[iz] * k.T, z0 = k.v * t;
            for (ix = 0; ix < 5; ++ix) {
                const double x = xs[ix] * k.l;
                double u1 = 0.0, u2 = 0.0, ref = static_defl(k.P, k.EJ, k.l, z0, x);
                assert_int_equal(ex_katz_eval(&k, N, x, t, &u1, &u2), 0);
                ASSERT_CLOSE_CTX(u1, ref, 0.0, tol, "a %g, z0 %g, x %g", a, z0s[iz], xs[ix]);
                ASSERT_CLOSE_CTX(u2, 0.0, 0.0, tol, "a %g, z0 %g, x %g", a, z0s[iz], xs[ix]);
                worst = fmax(worst, fmax(fabs(u1 - ref), fabs(u2)) / tol);
                if (iz == 0 && ix == 2) ASSERT_CLOSE(ref, Us, 4.0 * KEPS, 0.0);
            }
        }
        tu_report(ia ? "quasi-static a = 1e-7: |U - U_static| / U_s" :
                       "quasi-static a = 1e-4: |U - U_static| / U_s",
                  worst * tol / Us, tol / Us);
        tu_measured(ia ? "qs_a7" : "qs_a4", worst);
    }
}

/* ---------------------------------------------------------------------- */
/* rot = 1 against rot = 0.  D(beta1) = max |U_rot1 - U_rot0| / U_s over 1001
   times of the traverse, at the load and at midspan, both components,
   N = 30 modes (the truncation of both series is 1e-5 U_s and differs
   between them by O(beta1^2) of that).  The rhoJ terms shift mode n's
   frequencies by ~ n^2 beta1^2 / 2 relative (and the spin splits them by
   Omega beta_n^2 / w0_n, negligible at Omega = 1 rad/s), so D is
   O(beta1^2):
     D(0.02) in [0.1, 10] beta1^2 = [4e-5, 4e-3]   (measured 3.46 (m:rot_d0)
                                 beta1^2 = 1.39e-3 (m:rot_d0_abs) for case 0,
                                 1.09 (m:rot_d1) beta1^2 =
                                 4.4e-4 (m:rot_d1_abs) for case 1)
     D(0.02) / D(0.01) in [3.5, 4.5]                (3.97 (m:rot_q0) and
                                 3.66 (m:rot_q1) measured:
                                 beta_n = n beta1 reaches 0.6 at n = 30,
                                 the O(beta^4) rest shows in case 1)
   The rot = 0 response in U/U_s does not depend on beta1 (the
   Euler-Bernoulli shaft in these non-dimensional variables): rot = 0 at
   beta1 = 0.0137 (not a power of 2 from 0.02, which would reproduce the
   same digits) against beta1 = 0.02, to 1e-12 (a few EPS (1 + s t) of
   the amplitudes, s t <= 5e3 for 30 modes; measured 3e-15 (m~:rot_beta)). */
static double rot_diff(int c, double beta1, double *dev0)
{
    ex_katz k1, k0, kr;
    double worst = 0.0, Us;
    int j, p;
    const int N = 30;
    assert_int_equal(ex_katz_setup(&k1, K_L, beta1, K_E, K_RHO, K_OMEGA, g_case[c][0],
                                   g_case[c][1], K_P, 1),
                     0);
    assert_int_equal(ex_katz_setup(&k0, K_L, beta1, K_E, K_RHO, K_OMEGA, g_case[c][0],
                                   g_case[c][1], K_P, 0),
                     0);
    setup_case(&kr, c, 0); /* rot = 0 at the paper's beta1 */
    Us = ex_katz_us(&k1);
    *dev0 = 0.0;
    for (j = 0; j <= 1000; ++j) {
        const double s = (double)j / 1000.0;
        for (p = 0; p < 2; ++p) {
            const double zs = p ? 0.5 : s; /* z / l */
            double a1 = 0.0, a2 = 0.0, b1 = 0.0, b2 = 0.0, c1 = 0.0, c2 = 0.0;
            assert_int_equal(ex_katz_eval(&k1, N, zs * k1.l, s * k1.T, &a1, &a2), 0);
            assert_int_equal(ex_katz_eval(&k0, N, zs * k0.l, s * k0.T, &b1, &b2), 0);
            assert_int_equal(ex_katz_eval(&kr, N, zs * kr.l, s * kr.T, &c1, &c2), 0);
            worst = fmax3(worst, fabs(a1 - b1) / Us, fabs(a2 - b2) / Us);
            *dev0 = fmax3(*dev0, fabs(b1 / Us - c1 / ex_katz_us(&kr)),
                          fabs(b2 / Us - c2 / ex_katz_us(&kr)));
        }
    }
    return worst;
}

static void test_rot_vs_nonrot(void **state)
{
    double worst_beta = 0.0;
    int c;
    (void)state;
    for (c = 0; c < 2; ++c) {
        double dev_a, dev_b, dev_c;
        const double d2 = rot_diff(c, 0.02, &dev_a), d1 = rot_diff(c, 0.01, &dev_b);
        char name[80];
        (void)rot_diff(c, 0.0137, &dev_c);
        assert_true(dev_a == 0.0); /* same beta1: the same computation */
        assert_true(dev_b <= 1e-12 && dev_c <= 1e-12);
        assert_true(d2 >= 0.1 * 0.02 * 0.02 && d2 <= 10.0 * 0.02 * 0.02);
        assert_true(d2 / d1 >= 3.5 && d2 / d1 <= 4.5);
        snprintf(name, sizeof name, "case %d: D(0.02) / beta1^2 (range [0.1, 10])", c);
        tu_report(name, d2 / (0.02 * 0.02), 10.0);
        snprintf(name, sizeof name, "case %d: D(0.02) / D(0.01) (target 4)", c);
        tu_report(name, d2 / d1, 4.0);
        snprintf(name, sizeof name, "case %d: rot 0, beta1 0.0137 vs 0.02", c);
        tu_report(name, dev_c, 1e-12);
        tu_measured(c ? "rot_d1" : "rot_d0", d2 / (K_BETA1 * K_BETA1));
        tu_measured(c ? "rot_d1_abs" : "rot_d0_abs", d2);
        tu_measured(c ? "rot_q1" : "rot_q0", d2 / d1);
        worst_beta = fmax(worst_beta, dev_c);
    }
    tu_measured("rot_beta", worst_beta);
}

/* ---------------------------------------------------------------------- */
/* Convergence in the number of modes.  ex_katz_modes_for(1e-5) picks the
   smallest N with |U_N - U_2N| <= 1e-5 U_s on its 998-time grid: N = 30
   (ex_katz.h documents the measurement) in both cases, both rot.  Here on
   a grid of 4001 intervals (4x denser, not a multiple): |U_30 - U_60| and
   |U_30 - U_240| (nearly the whole tail) below 1e-5 U_s.
   Measured: 9.4e-6 (m:conv_60) and 9.8e-6 (m:conv_240) U_s: the choice is tight by
   construction (N = 29 gives 1.02e-5 (m:conv_29) at least). */
static void test_conv_modes(void **state)
{
    int c, rot, j, p, N = 0;
    double err, worst2 = 0.0, worst8 = 0.0, e29 = HUGE_VAL;
    (void)state;
    for (c = 0; c < 2; ++c)
        for (rot = 0; rot < 2; ++rot) {
            ex_katz k;
            double Us;
            setup_case(&k, c, rot);
            Us = ex_katz_us(&k);
            assert_int_equal(ex_katz_modes_for(&k, 1e-5, 200, &N, &err), 0);
            assert_int_equal(N, 30);
            assert_true(err <= 1e-5);
            e29 = fmin(e29, ex_katz_conv_err(&k, 29));
            assert_true(e29 > 1e-5);
            for (j = 0; j <= 4001; ++j) {
                const double t = k.T * (double)j / 4001.0;
                for (p = 0; p < 2; ++p) {
                    const double z = p ? 0.5 * k.l : k.v * t; /* v T = l to rounding */
                    double a1 = 0.0, a2 = 0.0, b1 = 0.0, b2 = 0.0, d1 = 0.0, d2 = 0.0;
                    assert_int_equal(ex_katz_eval(&k, N, z, t, &a1, &a2), 0);
                    assert_int_equal(ex_katz_eval(&k, 2 * N, z, t, &b1, &b2), 0);
                    assert_int_equal(ex_katz_eval(&k, 8 * N, z, t, &d1, &d2), 0);
                    worst2 = fmax3(worst2, fabs(a1 - b1) / Us, fabs(a2 - b2) / Us);
                    worst8 = fmax3(worst8, fabs(a1 - d1) / Us, fabs(a2 - d2) / Us);
                }
            }
        }
    assert_true(worst2 <= 1e-5);
    assert_true(worst8 <= 1e-5);
    tu_report("|U_30 - U_60| / U_s, dense grid", worst2, 1e-5);
    tu_report("|U_30 - U_240| / U_s, dense grid", worst8, 1e-5);
    tu_measured("conv_60", worst2);
    tu_measured("conv_240", worst8);
    tu_measured("conv_29", e29);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_setup_definitions), cmocka_unit_test(test_mode_ode_residual),
        cmocka_unit_test(test_closed_forms),      cmocka_unit_test(test_quasi_static),
        cmocka_unit_test(test_rot_vs_nonrot),     cmocka_unit_test(test_conv_modes),
    };
    return cmocka_run_group_tests_name("katz_oracle", tests, NULL, NULL);
}
