/* test_integrators.c -- cmocka suite of integrators.h, generalized-alpha
   family (Newmark, HHT-alpha, generalized-alpha) -- part of vlbe
                                                   SPDX-License-Identifier: MIT
   cc -std=c99 -Wall -Wextra -Wpedantic ... -O2 tests/test_integrators.c -lcmocka -lm

   The problems come from the examples (pendulum, Andrews' mechanism), which
   are included without their main(); the linear oscillator is defined here.
   Every tolerance says why it has its size.  Checks that need more than
   float precision sit under #ifndef VLBE_USE_FLOAT with the reason.

   Tests
     params_presets            preset formulas; HHT alpha, rho_inf out of range -> EARG
     pendulum_period_order     period error ratio ~4 per halving (HHT, gen-alpha)
     pendulum_multiplier       lambda vs -3 m g y / L^2 along the run, O(h^2)
     pendulum_constraint       |C| at Newton-tolerance level (index 3)
     oscillator_spectral_radius  measured decay per step vs eigenvalues of the
                               3x3 amplification matrix, omega h = 0.1 .. 1e4
     newmark_gamma_stability   gamma < 1/2 grows; gamma >= 1/2, beta >= gamma/2 does not
     trapezoidal_index3_unstable  Newmark's multiplier error grows, HHT damps it
     fail_nonfinite            NaN force -> ENONFINITE, state bitwise unchanged
     fail_callback             callback error -> ECALLBACK, state unchanged;
                               callback +1 once -> halved and through; without
                               halvings, or -1: ECALLBACK, state unchanged
     fail_singular             the same constraint twice -> ESINGULAR at init
     row_scaling               a copy of an oscillator scaled by 2^-60 (tiny
                               inertia) runs, bit for bit equal to the original
     fail_noconv_and_recovery  huge step -> ENOCONV, unchanged; with halvings: ok
     fail_args                 workspace too small -> EWORK; h <= 0, NaN -> EARG
     counters                  identities of the counters; modified vs full Newton
     hht_residual_test         ftol (eq. 53): >= the iterations of ftol = 0 step by
                               step, ||Psi||/sqrt(N) <= ftol after each step, one
                               more residual evaluation per step; presets ftol = 0;
                               ftol < 0, NaN -> EARG; unreachable ftol -> ENOCONV
     consistent_acc_fd_gamma   vlbe_dae_consistent_acc with gamma by differences
                               (constr_acc NULL) vs exact q'', lambda: moving
                               pendulum, rheonomic bead
     andrews_consistent_start  vlbe_dae_consistent_acc vs the Test Set values
     andrews_jacobians         analytic Jacobians of the example vs differences
     andrews_reference         HHT and gen-alpha reach the Test Set at 1e-6
     hht_advance               vlbe_hht_advance lands on 0.1 k and k / 3 exactly,
                               ceil((t_out - t) / h_max) steps a call; equals
                               plain stepping where h_max divides the interval
     hht_advance_fail          a failing step: the state of the last accepted
                               step, that of plain stepping there
   (the projected start of vlbe_hht_init: test_dae_project.c) */
#include "test_util.h"
#include "../integrators.h"

#include "../scenes/pendulum.h"
#include "../scenes/andrews.h"
#include "pend_faults.h"

#include <string.h>

#define EPS ((double)VLBE_EPS)

/* ------------------------------------------------------------------------ */
/* Integrator set-up with a fixed-size workspace (the largest problem here is
   Andrews', n = 7, m = 6). */
enum { WLEN = 2048, IWLEN = 64 };
typedef struct run {
    vlbe_hht st;
    vlbe_real w[WLEN];
    int iw[IWLEN];
} run;

static vlbe_status run_init(run *r, const vlbe_dae *sys, const vlbe_hht_params *par,
                            const vlbe_real *q0, const vlbe_real *v0)
{
    assert_true(vlbe_hht_work_len(sys->n, sys->m) <= WLEN);
    assert_true(vlbe_hht_iwork_len(sys->n, sys->m) <= IWLEN);
    return vlbe_hht_init(&r->st, sys, par, VLBE_R(0.0), q0, v0, r->w,
                         vlbe_hht_work_len(sys->n, sys->m), r->iw,
                         vlbe_hht_iwork_len(sys->n, sys->m));
}

/* The state of one step: t and q v qdd a lambda (contiguous in the workspace). */
typedef struct snap {
    vlbe_real t;
    vlbe_real x[64];
    int len;
} snap;

static void snap_take(const vlbe_hht *st, snap *s)
{
    s->t = st->t;
    s->len = 4 * st->n + st->m;
    assert_true(s->len <= 64);
    memcpy(s->x, st->q, (size_t)s->len * sizeof(vlbe_real));
}

/* bitwise comparison: a failed call must leave the state exactly as it was */
static void snap_assert_same(const vlbe_hht *st, const snap *s)
{
    assert_true(memcmp(&s->t, &st->t, sizeof s->t) == 0);
    assert_true(memcmp(s->x, st->q, (size_t)s->len * sizeof(vlbe_real)) == 0);
    assert_true(memcmp(s->x + 4 * st->n, st->lambda, (size_t)st->m * sizeof(vlbe_real)) == 0);
}

/* ------------------------------------------------------------------------ */
static void test_params_presets(void **state)
{
    vlbe_hht_params p;
    static const double alphas[] = {-1.0 / 3.0, -0.2, -0.05, 0.0};
    static const double rhos[] = {0.0, 0.5, 0.8, 1.0};
    int i;
    (void)state;
    vlbe_hht_params_newmark(&p, VLBE_R(0.25), VLBE_R(0.5)); /* p defined whatever follows */
    /* out of range and NaN */
    assert_int_equal(vlbe_hht_params_alpha(&p, VLBE_R(0.01)), VLBE_EARG);
    assert_int_equal(vlbe_hht_params_alpha(&p, VLBE_R(-0.34)), VLBE_EARG);
    assert_int_equal(vlbe_hht_params_alpha(&p, (vlbe_real)NAN), VLBE_EARG);
    assert_int_equal(vlbe_hht_params_genalpha(&p, VLBE_R(-0.01)), VLBE_EARG);
    assert_int_equal(vlbe_hht_params_genalpha(&p, VLBE_R(1.01)), VLBE_EARG);
    assert_int_equal(vlbe_hht_params_genalpha(&p, (vlbe_real)NAN), VLBE_EARG);
    /* The formulas are a few flops each: agreement to 4 eps (relative, plus
       4 eps absolute for the zero alpha_m/alpha_f) is all rounding allows. */
    for (i = 0; i < 4; ++i) {
        double a = (double)(vlbe_real)alphas[i];
        assert_int_equal(vlbe_hht_params_alpha(&p, (vlbe_real)a), VLBE_OK);
        ASSERT_CLOSE(p.alpha_m, 0.0, 0.0, 0.0);
        ASSERT_CLOSE(p.alpha_f, -a, 4 * EPS, 0.0);
        ASSERT_CLOSE(p.gamma, 0.5 - a, 4 * EPS, 0.0);
        ASSERT_CLOSE(p.beta, 0.25 * (1.0 - a) * (1.0 - a), 4 * EPS, 0.0);
        /* gamma = 1/2 + alpha_f - alpha_m holds for HHT as well */
        ASSERT_CLOSE(p.gamma, 0.5 + (double)p.alpha_f - (double)p.alpha_m, 4 * EPS, 0.0);
    }
    for (i = 0; i < 4; ++i) {
        double r = rhos[i], am = (2.0 * r - 1.0) / (r + 1.0), af = r / (r + 1.0);
        double g = 0.5 + af - am;
        assert_int_equal(vlbe_hht_params_genalpha(&p, (vlbe_real)r), VLBE_OK);
        ASSERT_CLOSE(p.alpha_m, am, 4 * EPS, 4 * EPS);
        ASSERT_CLOSE(p.alpha_f, af, 4 * EPS, 4 * EPS);
        ASSERT_CLOSE(p.gamma, g, 4 * EPS, 0.0);
        ASSERT_CLOSE(p.beta, 0.25 * (g + 0.5) * (g + 0.5), 8 * EPS, 0.0);
        ASSERT_CLOSE(p.gamma, 0.5 + (double)p.alpha_f - (double)p.alpha_m, 4 * EPS, 0.0);
    }
    /* rho_inf = 1 is the trapezoidal rule: alpha_m = alpha_f = 1/2 cancel */
    vlbe_hht_params_genalpha(&p, VLBE_R(1.0));
    ASSERT_CLOSE(p.gamma, 0.5, 0.0, 0.0);
    ASSERT_CLOSE(p.beta, 0.25, 0.0, 0.0);
    vlbe_hht_params_newmark(&p, VLBE_R(0.3), VLBE_R(0.6));
    ASSERT_CLOSE(p.alpha_m, 0.0, 0.0, 0.0);
    ASSERT_CLOSE(p.alpha_f, 0.0, 0.0, 0.0);
    ASSERT_CLOSE(p.beta, (double)VLBE_R(0.3), 0.0, 0.0);
    ASSERT_CLOSE(p.gamma, (double)VLBE_R(0.6), 0.0, 0.0);
}

/* ------------------------------------------------------------------------ */
/* Pendulum runs with tight Newton tolerances, so that the integration error,
   not the Newton error, is measured. */
static void pend_params(int method, vlbe_hht_params *par)
{
    if (method == 0) vlbe_hht_params_alpha(par, VLBE_R(-0.05));
    else if (method == 1) vlbe_hht_params_genalpha(par, VLBE_R(0.8));
    else if (method == 2) vlbe_hht_params_newmark(par, VLBE_R(0.25), VLBE_R(0.5));
    else vlbe_hht_params_alpha(par, VLBE_R(-0.1));
#ifndef VLBE_USE_FLOAT
    par->rtol = par->atol = VLBE_R(1e-12);
#endif
}

/* In float the period cannot be resolved: the float rounding of q over the
   1e3..1e4 steps gives period errors near 1e-4, above the O(h^2) error. */
static void test_pendulum_period_order(void **state)
{
#ifndef VLBE_USE_FLOAT
    const double T = pend_period_exact(PEND_L, PEND_G);
    static const double hs[3] = {2e-3, 1e-3, 5e-4};
    double rmin = HUGE_VAL, rmax = 0.0;
    int method, k;
    (void)state;
    /* the AGM value against the published one: 13 digits are published */
    ASSERT_CLOSE(T, PEND_T_PUBLISHED, 0.0, 1e-12);
    for (method = 0; method < 2; ++method) {
        double err[3];
        for (k = 0; k < 3; ++k) {
            vlbe_hht_params par;
            pend_result r;
            pend_params(method, &par);
            /* 2 periods: crossings at T/4, 5T/4, 9T/4 */
            assert_int_equal(pend_run(&par, hs[k], 6.0, &r), VLBE_OK);
            err[k] = fabs(r.period - T);
            tu_report(method ? "gen-alpha 0.8: period error / (T h^2) [s^-2] (vs 10)"
                             : "HHT -0.05: period error / (T h^2) [s^-2] (vs 10)",
                      err[k] / (T * hs[k] * hs[k]), 10.0);
            /* the error constant is 3.2 (m:period_const_hht) (HHT) and
               3.0 (m:period_const_ga) (gen-alpha) s^-2 times T at h = 5e-4;
               10 T h^2 bounds it with room to spare */
            assert_true(err[k] <= 10.0 * T * hs[k] * hs[k]);
        }
        tu_measured(method ? "period_const_ga" : "period_const_hht", err[2] / (T * hs[2] * hs[2]));
        /* second order: halving h divides the error by 4 (1 + O(h^2)); the
           Hermite crossing error O(h^4) and the Newton error 1e-12 are far
           below 1e-8; the ratios are 3.99 (m:period_ratio_min) ..
           4.00 (m:period_ratio_max), so +-10% */
        for (k = 0; k < 2; ++k) {
            rmin = fmin(rmin, err[k] / err[k + 1]);
            rmax = fmax(rmax, err[k] / err[k + 1]);
        }
        ASSERT_CLOSE(err[0] / err[1], 4.0, 0.1, 0.0);
        ASSERT_CLOSE(err[1] / err[2], 4.0, 0.1, 0.0);
    }
    tu_measured("period_ratio_min", rmin);
    tu_measured("period_ratio_max", rmax);
#else
    (void)state;
    TU_SKIP("float rounding of q gives period errors near 1e-4, above the O(h^2) error");
#endif
}

/* lambda along the run.  The index-3 multiplier error is O(h^2) (Arnold &
   Bruls 2007, with a_0 = q''_0); its Newton part is tol / (beta h^2), hence
   the tight tolerance and the double-only check (in float eps / (beta h^2)
   is about 0.5 N/m at h = 1e-3). */
static void test_pendulum_multiplier(void **state)
{
#ifndef VLBE_USE_FLOAT
    const double hk[2] = {2e-3, 1e-3};
    double c2 = 0.0, dev = 0.0;
    int method, k;
    (void)state;
    for (method = 0; method < 2; ++method) {
        vlbe_hht_params par;
        pend_result r[2];
        double d, ratio;
        pend_params(method, &par);
        par.rtol = par.atol = VLBE_R(1e-14); /* the Newton part below */
        for (k = 0; k < 2; ++k) assert_int_equal(pend_run(&par, hk[k], 3.0, &r[k]), VLBE_OK);
        /* the largest error is the start transient: 98 (m:lam_err_h2) h^2
           N/m/s^2 at h = 1e-3 (the larger of HHT's and gen-alpha's); 200 h^2
           is twice that, while lambda itself reaches 3 m g / L = 29.4 N/m */
        c2 = fmax(c2, r[1].max_lam_err / (hk[1] * hk[1]));
        tu_report("pendulum lambda error at h = 1e-3 [N/m] (vs 200 h^2)", r[1].max_lam_err,
                  200.0 * hk[1] * hk[1]);
        assert_true(r[1].max_lam_err <= 200.0 * hk[1] * hk[1]);
        /* and it is second order: r[0] / r[1] = 4 (1 + d), d from three parts:
           - the next terms of the transient's expansion, relative powers of
             omega h with omega = sqrt(g / L) = 3.1 rad/s (the pendulum's one
             rate) and O(1) coefficients: at most omega h1 = 6.3e-3;
           - the Newton stop: the last position increment is below
             sqrt(2) (atol + rtol L) (RMS norm <= 1, n = 2), and q'' and
             lambda move with it as dq / bp, bp = beta h^2 (1 - alpha_f) /
             (1 - alpha_m): lambda off by m dq / (bp L), relative to the
             error itself 1.1e-3 at h = 1e-3 with the 1e-14 set above (with
             the 1e-12 of the other tests: 0.11, hence 1e-14);
           - rounding: C rounds to ~16 EPS L^2, which moves lambda the same
             way by m 16 EPS L / (bp L): 1.4e-4 at h = 1e-3.
           Their sum at h1 and h2 is the tolerance (7.6e-3); the deviation
           is 8.3e-7 (m~:lam_ratio_dev), of the size of the rounding part's
           actual value (eps / h^4, far below its bound). */
        d = sqrt(PEND_G / PEND_L) * hk[0];
        for (k = 0; k < 2; ++k) {
            const double bp = (double)par.beta * (1.0 - (double)par.alpha_f) /
                              (1.0 - (double)par.alpha_m) * hk[k] * hk[k];
            const double dq = sqrt(2.0) * ((double)par.atol + (double)par.rtol * PEND_L) +
                              16.0 * EPS * PEND_L;
            d += PEND_M * dq / (bp * PEND_L) / r[k].max_lam_err;
        }
        ratio = r[0].max_lam_err / r[1].max_lam_err;
        dev = fmax(dev, fabs(ratio / 4.0 - 1.0));
        tu_report("pendulum lambda error ratio h = 2e-3 / 1e-3: |ratio / 4 - 1|",
                  fabs(ratio / 4.0 - 1.0), d);
        ASSERT_CLOSE(ratio, 4.0, d, 0.0);
    }
    tu_measured("lam_err_h2", c2);
    tu_measured("lam_ratio_dev", dev);
#else
    (void)state;
    TU_SKIP("eps / (beta h^2), the Newton floor of lambda, is about 0.5 N/m at h = 1e-3");
#endif
}

/* Index 3: the positions satisfy C = 0 up to the Newton tolerance, whatever h.
   The last Newton increment dq satisfies |dq_i| <= sqrt(n) (atol + rtol |q|)
   (RMS norm <= 1, n = 2) and the remaining C is at most C_q dq ~ L |dq|;
   add 16 eps L^2 for the rounding of C itself. */
static void test_pendulum_constraint(void **state)
{
    static const char *const key[3] = {"cv_hht", "cv_ga08", "cv_ga0"};
    double cvmin = HUGE_VAL, cvmax = 0.0;
    int k;
    (void)state;
    for (k = 0; k < 3; ++k) {
        vlbe_hht_params par;
        pend_result r;
        double bound;
        if (k == 0) vlbe_hht_params_alpha(&par, VLBE_R(-0.05));
        else if (k == 1) vlbe_hht_params_genalpha(&par, VLBE_R(0.8));
        else vlbe_hht_params_genalpha(&par, VLBE_R(0.0));
        bound = sqrt(2.0) * ((double)par.atol + (double)par.rtol * PEND_L) * PEND_L +
                16.0 * EPS * PEND_L * PEND_L;
        assert_int_equal(pend_run(&par, 4e-3, 3.0, &r), VLBE_OK);
        tu_report("pendulum |C| [m^2] (vs Newton-level bound)", r.max_c, bound);
        assert_true(r.max_c <= bound);
        /* the velocity constraint is not enforced in index 3: C_q v = O(h^2),
           at h = 4e-3: 1.1e-4 (m:cv_hht) for HHT, 1.1e-4 (m:cv_ga08) for
           rho_inf = 0.8 (both 7 h^2), 4.3e-4 (m:cv_ga0) (27 h^2) for
           rho_inf = 0; 40 h^2 bounds them.  On top, the Newton stop: the
           velocity moves with the position by dv = gamma / (beta h) dq, so
           the position-level bound above reaches C_q v times gamma / (beta h)
           (~500 at h = 4e-3: 7e-7 in double, 7e-3 in float with its
           default tolerances 7.6e-6, 9.5e-7; float gives
           5.5e-4 (m@flt:cv_min) .. 1.3e-3 (m@flt:cv_max)) */
        tu_measured(key[k], r.max_cv);
        cvmin = fmin(cvmin, r.max_cv);
        cvmax = fmax(cvmax, r.max_cv);
        tu_report("pendulum |C_q v| [m^2/s] (vs its bound)", r.max_cv,
                  40.0 * 4e-3 * 4e-3 + (double)par.gamma / ((double)par.beta * 4e-3) * bound);
        assert_true(r.max_cv <= 40.0 * 4e-3 * 4e-3 +
                                    (double)par.gamma / ((double)par.beta * 4e-3) * bound);
        assert_true(r.max_cv > bound); /* and it is not at Newton level */
    }
    tu_measured("cv_min", cvmin);
    tu_measured("cv_max", cvmax);
}

/* ------------------------------------------------------------------------ */
/* Linear undamped oscillator q'' = -omega^2 q (n = 1, m = 0, M = 1). */
typedef struct osc {
    vlbe_real w2;
} osc;

static int osc_mass(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v, vlbe_real *M)
{
    (void)u;
    (void)t;
    (void)q;
    (void)v;
    M[0] = VLBE_R(1.0);
    return 0;
}
static int osc_force(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v, vlbe_real *Q)
{
    (void)t;
    (void)v;
    Q[0] = -((const osc *)u)->w2 * q[0];
    return 0;
}
/* exact Jacobian, so that one Newton iteration solves the linear step */
static int osc_force_jac(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v,
                         vlbe_real *K, vlbe_real *D)
{
    (void)t;
    (void)q;
    (void)v;
    K[0] = -((const osc *)u)->w2;
    D[0] = VLBE_R(0.0);
    return 0;
}
static void osc_setup(vlbe_dae *sys, osc *o)
{
    vlbe_dae z = {0};
    *sys = z;
    sys->n = 1;
    sys->m = 0;
    sys->flags = VLBE_DAE_MASS_CONST;
    sys->user = o;
    sys->mass = osc_mass;
    sys->force = osc_force;
    sys->force_jac = osc_force_jac;
}

/* Amplification matrix of one step for x = (q, h v, h^2 a), Omega = omega h:
   the scheme (integrators.h, Arnold-Bruls form)
     q1 = q0 + h v0 + h^2 ((1/2 - beta) a0 + beta a1)
     v1 = v0 + h ((1 - gamma) a0 + gamma a1)
     (1 - am) a1 + am a0 = (1 - af) q''1 + af q''0,   q'' = -omega^2 q
   is L x1 = R x0; A = L^-1 R (L inverted by its adjugate). */
static void amp_matrix(const vlbe_hht_params *p, double W, double A[9])
{
    double am = (double)p->alpha_m, af = (double)p->alpha_f, b = (double)p->beta,
           g = (double)p->gamma, W2 = W * W;
    double L[9], R[9], Li[9], det;
    int i, j, k;
    L[0] = 1.0, L[1] = 0.0, L[2] = -b;
    L[3] = 0.0, L[4] = 1.0, L[5] = -g;
    L[6] = (1.0 - af) * W2, L[7] = 0.0, L[8] = 1.0 - am;
    R[0] = 1.0, R[1] = 1.0, R[2] = 0.5 - b;
    R[3] = 0.0, R[4] = 1.0, R[5] = 1.0 - g;
    R[6] = -af * W2, R[7] = 0.0, R[8] = -am;
    Li[0] = L[4] * L[8] - L[5] * L[7];
    Li[1] = L[2] * L[7] - L[1] * L[8];
    Li[2] = L[1] * L[5] - L[2] * L[4];
    Li[3] = L[5] * L[6] - L[3] * L[8];
    Li[4] = L[0] * L[8] - L[2] * L[6];
    Li[5] = L[2] * L[3] - L[0] * L[5];
    Li[6] = L[3] * L[7] - L[4] * L[6];
    Li[7] = L[1] * L[6] - L[0] * L[7];
    Li[8] = L[0] * L[4] - L[1] * L[3];
    det = L[0] * Li[0] + L[1] * Li[3] + L[2] * Li[6];
    for (i = 0; i < 3; ++i)
        for (j = 0; j < 3; ++j) {
            double s = 0.0;
            for (k = 0; k < 3; ++k) s += Li[i * 3 + k] * R[k * 3 + j];
            A[i * 3 + j] = s / det;
        }
}

/* Moduli of the eigenvalues of a 3x3 matrix from its characteristic cubic
   mu^3 - c2 mu^2 + c1 mu - c0 (c2 trace, c1 sum of principal 2x2 minors,
   c0 determinant): a real root by bisection on [-B, B] (Cauchy bound), the
   other two from the deflated quadratic.  mod[0] >= mod[1] >= mod[2]. */
static void eig3_moduli(const double A[9], double mod[3], double *sin_arg)
{
    double c2 = A[0] + A[4] + A[8];
    double c1 = A[0] * A[4] - A[1] * A[3] + A[0] * A[8] - A[2] * A[6] + A[4] * A[8] - A[5] * A[7];
    double c0 = A[0] * (A[4] * A[8] - A[5] * A[7]) - A[1] * (A[3] * A[8] - A[5] * A[6]) +
                A[2] * (A[3] * A[7] - A[4] * A[6]);
    double B = 1.0 + fmax(fabs(c2), fmax(fabs(c1), fabs(c0))), lo = -B, hi = B, r, b, c, d, t;
    int k;
    for (k = 0; k < 2000; ++k) {
        double mid = 0.5 * (lo + hi), pm;
        if (mid <= lo || mid >= hi) break;
        pm = ((mid - c2) * mid + c1) * mid - c0;
        if (pm < 0.0) lo = mid;
        else hi = mid;
    }
    r = 0.5 * (lo + hi);
    b = r - c2;     /* p = (mu - r)(mu^2 + b mu + c) */
    c = c1 + r * b;
    d = b * b - 4.0 * c;
    mod[0] = fabs(r);
    *sin_arg = 1.0; /* |sin arg mu| of the complex pair, 1 if all are real */
    if (d < 0.0) {
        mod[1] = mod[2] = sqrt(c);
        *sin_arg = 0.5 * sqrt(-d) / sqrt(c);
    } else {
        double s = sqrt(d), q = -0.5 * (b + (b >= 0.0 ? s : -s));
        mod[1] = fabs(q);
        mod[2] = q != 0.0 ? fabs(c / q) : 0.0;
    }
    /* sort descending */
    if (mod[1] > mod[0]) t = mod[0], mod[0] = mod[1], mod[1] = t;
    if (mod[2] > mod[1]) t = mod[1], mod[1] = mod[2], mod[2] = t;
    if (mod[1] > mod[0]) t = mod[0], mod[0] = mod[1], mod[1] = t;
}

/* Spectral radius of the amplification matrix; *second: modulus of the
   spurious (third) eigenvalue, *sin_arg: |sin| of the argument of the pair. */
static double rho_theory(const vlbe_hht_params *p, double W, double *second, double *sin_arg)
{
    double A[9], mod[3], sa;
    amp_matrix(p, W, A);
    eig3_moduli(A, mod, &sa);
    if (second) *second = mod[1] == mod[0] ? mod[2] : mod[1];
    if (sin_arg) *sin_arg = sa;
    return mod[0];
}

/* Measured amplitude ratio per step of the integrator on the oscillator.
   After the third (spurious) mode has decayed, q_n = Re(c mu^n) of the
   dominant pair mu, |mu| = rho, and the Casoratian D_n = q_n^2 - q_{n+1} q_{n-1}
   is D_0 rho^(2n) exactly (no beating), so rho = (D_N / D_M)^(1/(2(N-M))).
   (For a real dominant pair the same identity holds.)  The state is
   rescaled by powers of two, exactly and linearly, to stay in range.
   skip: steps before M; span: N - M. */
static double rho_measured(const vlbe_hht_params *par, double W, long skip, long span)
{
    osc o;
    vlbe_dae sys;
    run *r = (run *)malloc(sizeof *r);
    vlbe_real q0 = VLBE_R(1.0), v0 = VLBE_R(0.0), h = VLBE_R(1.0);
    double qm1 = 0.0, q = 0.0, D = 0.0, lD = 0.0, lDM = 0.0, lF = 0.0;
    long n;
    assert_non_null(r);
    o.w2 = (vlbe_real)(W * W); /* h = 1: omega = Omega */
    osc_setup(&sys, &o);
    assert_int_equal(run_init(r, &sys, par, &q0, &v0), VLBE_OK);
    for (n = 0; n <= skip + span + 1; ++n) {
        double qp1, mag, f = 0.0;
        if (n > 0) assert_int_equal(vlbe_hht_step(&r->st, h), VLBE_OK);
        qp1 = (double)r->st.q[0];
        if (n >= 2) {
            /* D_(n-1) from q_(n-2), q_(n-1), q_n, all stored with the factor
               exp(lF): log |D_true| = log |D| - 2 lF */
            D = q * q - qp1 * qm1;
            lD = log(fabs(D)) - 2.0 * lF;
            if (n == skip + 1) lDM = lD;
        }
        qm1 = q;
        q = qp1;
        /* keep |x| near 1: multiply q v q'' a (contiguous) by 2^30 or 2^-30,
           exactly; the step is linear in the state */
        mag = fabs((double)r->st.q[0]) + fabs((double)r->st.v[0]) + fabs((double)r->st.a[0]);
        if (mag < 0x1p-30) f = 0x1p30;
        else if (mag > 0x1p30) f = 0x1p-30;
        if (f != 0.0) {
            int i;
            for (i = 0; i < 4; ++i) r->st.q[i] *= (vlbe_real)f;
            qm1 *= f;
            q *= f;
            lF += log(f);
        }
    }
    free(r);
    assert_true(D != 0.0);
    return exp((lD - lDM) / (2.0 * (double)span));
}

static void osc_params(int k, vlbe_hht_params *p)
{
    if (k == 0) vlbe_hht_params_alpha(p, VLBE_R(-0.05));
    else if (k == 1) vlbe_hht_params_alpha(p, VLBE_R(-0.3));
    else if (k == 2) vlbe_hht_params_genalpha(p, VLBE_R(0.8));
    else if (k == 3) vlbe_hht_params_genalpha(p, VLBE_R(0.5));
    else vlbe_hht_params_newmark(p, VLBE_R(0.25), VLBE_R(0.5));
}

static void test_oscillator_spectral_radius(void **state)
{
    static const double Ws[] = {0.1, 1.0, 10.0, 1e4};
#ifdef VLBE_USE_FLOAT
    /* at omega h = 1e4 the pair is -rho exp(+-i phi), phi ~ 4e-4: the
       Casoratian loses eps / phi^2 ~ 1 in float */
    const int nW = 3;
#else
    const int nW = 4;
#endif
    int k, j;
    (void)state;
    for (k = 0; k < 5; ++k) {
        vlbe_hht_params p;
        double rinf;
        osc_params(k, &p);
        /* rho_inf of each scheme (limit omega h -> inf) */
        if (k < 2) rinf = (1.0 - (double)p.alpha_f) / (1.0 + (double)p.alpha_f); /* (1+a)/(1-a) */
        else if (k == 2) rinf = 0.8;
        else if (k == 3) rinf = 0.5;
        else rinf = 1.0;
        for (j = 0; j < nW; ++j) {
            double second, sa, rt = rho_theory(&p, Ws[j], &second, &sa), rm, tol;
            long skip = 2, span = 2000;
            /* skip the spurious mode down to eps^2 of the pair (it is
               exactly 0 for Newmark) */
            if (second > 0.0 && second < rt)
                skip += (long)ceil(2.0 * log(EPS) / log(second / rt));
            assert_true(skip < 40000);
            rm = rho_measured(&p, Ws[j], skip, span);
            /* D = q_n^2 - q_(n+1) q_(n-1) is a difference of terms |sin arg|^-2
               larger than itself: rounding eps / sin^2 relative in D, an
               error 1/(2 span) of that in rho; plus eps-level rounding of the
               steps themselves; a factor 64 on both.  The theoretical root
               (double) of a cubic whose roots lie d = rho - |mu_3| apart is
               itself good to about DBL_EPSILON / d^2 (5e-12 for
               generalized-alpha at omega h = 1e4, d = 5e-3): 64 times that. */
            tol = 64.0 * EPS * (1.0 + 1.0 / (sa * sa)) / (2.0 * (double)span) + 64.0 * EPS +
                  64.0 * DBL_EPSILON / ((rt - second) * (rt - second));
            tu_report("oscillator: |rho of the run / rho theory - 1|", fabs(rm / rt - 1.0), tol);
            ASSERT_CLOSE(rm, rt, tol, 0.0);
            if (k == 4) {
                /* trapezoidal: no numerical damping at any omega h; c0 = det,
                   the cubic's rounding is eps-level: 64 eps */
                ASSERT_CLOSE(rt, 1.0, 64.0 * EPS, 0.0);
            } else {
                assert_true(rt < 1.0); /* dissipative for every omega h > 0 */
            }
        }
        /* the theoretical radius at omega h = 1e4 is rho_inf: for HHT (and
           Newmark) the correction is O((omega h)^-2), 150 (omega h)^-2 =
           1.5e-6 for alpha = -0.3: 1e-5; for generalized-alpha the three
           roots meet at -rho_inf (a triple root) and split like
           (omega h)^(-2/3): 1.7e-3 at 1e4: 5e-3 */
#ifndef VLBE_USE_FLOAT
        /* (not in float: there the rounded beta, gamma miss the relation
           beta = (1 - alpha)^2 / 4, gamma = 1/2 - alpha by ~eps, an error
           that the limit magnifies by (omega h)^2) */
        ASSERT_CLOSE(rho_theory(&p, 1e4, NULL, NULL), rinf, (k == 2 || k == 3) ? 5e-3 : 1e-5,
                     0.0);
#endif
        if (k == 2 || k == 3)
            assert_true(fabs(rho_theory(&p, 1e8, NULL, NULL) - rinf) <
                        fabs(rho_theory(&p, 1e4, NULL, NULL) - rinf));
    }
}

/* Newmark's stability: gamma < 1/2 amplifies (rho > 1), gamma >= 1/2 with
   beta >= gamma/2 ... (gamma + 1/2)^2 / 4 does not. */
static void test_newmark_gamma_stability(void **state)
{
    static const double Ws[] = {0.5, 1.0, 3.0, 100.0};
    const double one = 1.0 + 64.0 * EPS;
    int j;
    (void)state;
    for (j = 0; j < 4; ++j) {
        vlbe_hht_params p;
        double rt, rm, second, sa, tol;
        /* unstable: gamma = 0.4 */
        vlbe_hht_params_newmark(&p, VLBE_R(0.25), VLBE_R(0.4));
        rt = rho_theory(&p, Ws[j], &second, &sa);
        assert_true(rt > 1.0 + 1e-3); /* grows by more than 1e-3 per step */
        rm = rho_measured(&p, Ws[j], 4, 500);
        /* same tolerance argument as in the spectral radius test */
        tol = 64.0 * EPS * (1.0 + 1.0 / (sa * sa)) / 1000.0 + 64.0 * EPS;
        ASSERT_CLOSE(rm, rt, tol, 0.0);
        assert_true(rm > 1.0 + 1e-3);
        /* stable: gamma = 1/2, beta = 1/4 (rho = 1) and gamma = 0.6 with
           beta = gamma/2 = 0.3 and beta = (gamma + 1/2)^2/4 = 0.3025;
           one: 1 plus the rounding allowance of the tests above */
        vlbe_hht_params_newmark(&p, VLBE_R(0.25), VLBE_R(0.5));
        assert_true(rho_measured(&p, Ws[j], 4, 500) <= one);
        vlbe_hht_params_newmark(&p, VLBE_R(0.3), VLBE_R(0.6));
        assert_true(rho_theory(&p, Ws[j], NULL, NULL) <= one);
        assert_true(rho_measured(&p, Ws[j], 40, 500) <= one);
        vlbe_hht_params_newmark(&p, VLBE_R(0.3025), VLBE_R(0.6));
        assert_true(rho_theory(&p, Ws[j], NULL, NULL) < 1);
        assert_true(rho_measured(&p, Ws[j], 40, 500) < 1);
    }
}

/* ------------------------------------------------------------------------ */
/* Trapezoidal Newmark on the index-3 pendulum: the multiplier mode has the
   eigenvalue -1 (no damping), the nonlinear coupling makes its error grow
   (Cardona & Geradin 1989) until Newton fails; HHT alpha = -0.1 damps it. */
static void test_trapezoidal_index3_unstable(void **state)
{
    vlbe_hht_params par;
    pend_result rn, rh, rf;
    (void)state;
    pend_params(2, &par);
    pend_run(&par, 1e-3, 5.0, &rn);
    pend_params(3, &par);
    assert_int_equal(pend_run(&par, 1e-3, 5.0, &rh), VLBE_OK);
    /* HHT: the start transient is damped: the late error is below the early one */
    assert_true(rh.lam_err_late < rh.lam_err_early);
#ifndef VLBE_USE_FLOAT
    /* Newmark: the error in the last second is far above that of the first
       (1.8e-4 (m:nm_lam_early) N/m in the first second, then growing to
       10 (m:nm_lam_late) N/m in the fifth) */
    tu_measured("nm_lam_early", rn.lam_err_early);
    tu_measured("nm_lam_late", rn.lam_err_late);
    tu_report("Newmark lambda error, 5th s / 1st s (vs > 100)",
              rn.lam_err_late / rn.lam_err_early, 100.0);
    assert_int_equal(rn.status, VLBE_OK);
    assert_true(rn.lam_err_late > 100.0 * rn.lam_err_early);
    /* and the positions of both are fine (period within 1e-5 relative: the
       O(h^2) error at h = 1e-3 is about 3 h^2 = 3e-6 by the error constant
       of the period test; not in float, see the period test) */
    ASSERT_CLOSE(rn.period, PEND_T_PUBLISHED, 1e-5, 0.0);
    ASSERT_CLOSE(rh.period, PEND_T_PUBLISHED, 1e-5, 0.0);
#else
    /* float: the mode starts from rounding errors 1e4 times larger and
       Newmark's Newton may fail before 5 s; either way it is the growth */
    assert_true(rn.status == VLBE_ENOCONV || rn.lam_err_late > 100.0 * rn.lam_err_early);
#endif
    /* left to itself, Newmark's run ends in a Newton failure, reported */
    pend_params(2, &par);
    assert_int_equal(pend_run(&par, 1e-3, 15.0, &rf), VLBE_ENOCONV);
    assert_true(rf.t_reached < 15.0);
    assert_true(rf.t_reached >= rn.t_reached);
}

/* ------------------------------------------------------------------------ */
/* Faulty variants of the pendulum: pend_faults.h. */

/* Runs 10 good steps, then arms the fault and checks the status of the
   next step and that the state is bitwise unchanged. */
/* The fault `mode` armed inside the Newton iteration of one step (for
   `count` calls, 0: for ever), without and with step halving: the step
   returns expect[0] and expect[1]; a failed step leaves the state as it
   was, and the repaired integrator goes on from there. */
static void check_fault_n(int mode, long count, vlbe_status expect0, vlbe_status expect1)
{
    faulty f;
    vlbe_dae sys;
    vlbe_hht_params par;
    vlbe_real q0[2], v0[2];
    run *r = (run *)malloc(sizeof *r);
    snap s;
    int k, halv;
    assert_non_null(r);
    for (halv = 0; halv < 2; ++halv) {
        const vlbe_status expect = halv ? expect1 : expect0;
        faulty_setup(&sys, &f, mode);
        vlbe_hht_params_alpha(&par, VLBE_R(-0.05));
        par.max_halvings = 3 * halv; /* halving must not hide the fault */
        pend_initial(&f.p, q0, v0);
        assert_int_equal(run_init(r, &sys, &par, q0, v0), VLBE_OK);
        for (k = 0; k < 10; ++k) assert_int_equal(vlbe_hht_step(&r->st, VLBE_R(1e-2)), VLBE_OK);
        snap_take(&r->st, &s);
        f.mode = mode;
        f.after = 1; /* the fault hits inside the Newton iteration */
        f.count = count;
        f.calls = 0;
        r->st.stats.rejected = 0;
        assert_int_equal(vlbe_hht_step(&r->st, VLBE_R(1e-2)), expect);
        if (expect == VLBE_OK) {
            /* retried at h/2 after one rejected attempt */
            assert_true(r->st.stats.rejected == 1);
            assert_true(vlbe_fabs(r->st.t - s.t - VLBE_R(1e-2)) <= 4 * VLBE_EPS);
        } else {
            snap_assert_same(&r->st, &s);
        }
        if (mode >= 5) assert_int_equal(r->st.stats.callback_rc, mode == 5 ? 1 : -1);
        /* repaired, the integrator goes on from there */
        f.mode = 0;
        assert_int_equal(vlbe_hht_step(&r->st, VLBE_R(1e-2)), VLBE_OK);
    }
    free(r);
}

static void check_fault(int mode, vlbe_status expect) { check_fault_n(mode, 0, expect, expect); }

static void test_fail_nonfinite(void **state)
{
    (void)state;
    check_fault(1, VLBE_ENONFINITE);
}

/* A callback error stops the step; one that calls a single Newton iterate
   outside its domain (returns +1 once, as an element chain does for an
   inverted element) is retried at h/2 when halving is on and goes through;
   the same fault returned as -1 is fatal even with halvings. */
static void test_fail_callback(void **state)
{
    (void)state;
    check_fault(2, VLBE_ECALLBACK);
    check_fault(3, VLBE_ECALLBACK);
    check_fault_n(5, 1, VLBE_ECALLBACK, VLBE_OK);
    check_fault_n(6, 1, VLBE_ECALLBACK, VLBE_ECALLBACK);
}

/* The same constraint twice: C_q has rank 1 < m = 2. */
static int twice_constr(void *u, vlbe_real t, const vlbe_real *q, vlbe_real *C)
{
    pend_constr(u, t, q, C);
    C[1] = C[0];
    return 0;
}
static int twice_constr_jac(void *u, vlbe_real t, const vlbe_real *q, vlbe_real *Cq, vlbe_real *Ct)
{
    pend_constr_jac(u, t, q, Cq, NULL);
    Cq[2] = Cq[0];
    Cq[3] = Cq[1];
    if (Ct) Ct[0] = Ct[1] = VLBE_R(0.0);
    return 0;
}

/* Two copies of the oscillator, the second with mass and stiffness scaled by
   S = 2^-60 (a tiny inertia next to a unit one, as a spin angle's rho I
   next to rho A in SI units): the equations of the second are those of
   the first times S.  Without row equilibration vlbe_lu_factor's pivot
   test (|pivot| <= n EPS max|A|) calls the iteration matrix singular in
   both precisions; the integrators scale each row by a power of 2, which
   is exact, so the second row becomes the first bit for bit and the two
   histories must be identical (an exact check, no tolerance): with both
   the consistent start (vlbe_dae_consistent_acc inside vlbe_hht_init) and
   the steps, and with modified Newton (the stored LU and its scales
   reused over iterations). */
static int osc2_mass(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v, vlbe_real *M)
{
    (void)u, (void)t, (void)q, (void)v;
    M[0] = VLBE_R(1.0), M[1] = M[2] = VLBE_R(0.0);
    M[3] = (vlbe_real)ldexp(1.0, -60);
    return 0;
}
static int osc2_force(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v, vlbe_real *Q)
{
    const vlbe_real w2 = ((const osc *)u)->w2;
    (void)t, (void)v;
    Q[0] = -w2 * q[0];
    Q[1] = -((vlbe_real)ldexp(1.0, -60) * w2) * q[1];
    return 0;
}
static int osc2_force_jac(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v,
                          vlbe_real *K, vlbe_real *D)
{
    const vlbe_real w2 = ((const osc *)u)->w2;
    (void)t, (void)q, (void)v;
    K[0] = -w2, K[1] = K[2] = VLBE_R(0.0);
    K[3] = -((vlbe_real)ldexp(1.0, -60) * w2);
    D[0] = D[1] = D[2] = D[3] = VLBE_R(0.0);
    return 0;
}

static void test_row_scaling(void **state)
{
    osc o;
    vlbe_dae sys = {0};
    vlbe_hht_params par;
    const vlbe_real q0[2] = {VLBE_R(0.3), VLBE_R(0.3)}, v0[2] = {VLBE_R(-1.0), VLBE_R(-1.0)};
    run *r = (run *)malloc(sizeof *r);
    int k, mod;
    (void)state;
    assert_non_null(r);
    o.w2 = VLBE_R(40.0);
    sys.n = 2;
    sys.flags = VLBE_DAE_MASS_CONST;
    sys.user = &o;
    sys.mass = osc2_mass;
    sys.force = osc2_force;
    sys.force_jac = osc2_force_jac;
    for (mod = 0; mod < 2; ++mod) {
        vlbe_hht_params_alpha(&par, VLBE_R(-0.1));
        par.modified = mod;
        assert_int_equal(run_init(r, &sys, &par, q0, v0), VLBE_OK);
        assert_true(r->st.qdd[0] == r->st.qdd[1] && r->st.qdd[0] != VLBE_R(0.0));
        for (k = 0; k < 200; ++k) {
            assert_int_equal(vlbe_hht_step(&r->st, VLBE_R(0.01)), VLBE_OK);
            assert_true(r->st.q[0] == r->st.q[1] && r->st.v[0] == r->st.v[1]);
        }
        assert_true(r->st.stats.lu_factors > 0);
    }
    free(r);
}

static void test_fail_singular(void **state)
{
    pend_par p = pend_default();
    vlbe_dae sys;
    vlbe_hht_params par;
    vlbe_real q0[2], v0[2];
    run *r = (run *)malloc(sizeof *r);
    (void)state;
    assert_non_null(r);
    pend_setup(&sys, &p);
    sys.m = 2;
    sys.constr = twice_constr;
    sys.constr_jac = twice_constr_jac;
    sys.constr_acc = NULL;   /* the FD path of gamma, m = 2 */
    sys.constr_hess = NULL;
    vlbe_hht_params_genalpha(&par, VLBE_R(0.8));
    pend_initial(&p, q0, v0);
    assert_int_equal(run_init(r, &sys, &par, q0, v0), VLBE_ESINGULAR);
    free(r);
}

/* A step of 0.5 s (a fifth of the period) from the horizontal: the predictor
   is far off and Newton diverges; with halvings the same call succeeds. */
static void test_fail_noconv_and_recovery(void **state)
{
    pend_par p = pend_default();
    vlbe_dae sys;
    vlbe_hht_params par;
    vlbe_real q0[2], v0[2], h = VLBE_R(0.5);
    run *r = (run *)malloc(sizeof *r);
    snap s;
    long f0;
    (void)state;
    assert_non_null(r);
    pend_setup(&sys, &p);
    vlbe_hht_params_alpha(&par, VLBE_R(-0.05));
    pend_initial(&p, q0, v0);
    assert_int_equal(run_init(r, &sys, &par, q0, v0), VLBE_OK);
    assert_int_equal(vlbe_hht_step(&r->st, VLBE_R(0.05)), VLBE_OK);
    snap_take(&r->st, &s);
    f0 = r->st.stats.newton_fails;
    assert_int_equal(vlbe_hht_step(&r->st, h), VLBE_ENOCONV);
    snap_assert_same(&r->st, &s);
    assert_true(r->st.stats.newton_fails == f0 + 1);
    assert_true(r->st.stats.rejected >= 1);
    assert_true(r->st.stats.steps == 1);
    /* with halvings: the step goes through as 2^k smaller ones */
    r->st.par.max_halvings = 6;
    assert_int_equal(vlbe_hht_step(&r->st, h), VLBE_OK);
    ASSERT_CLOSE(r->st.t, 0.55, 8 * EPS, 0.0);
    assert_true(r->st.stats.steps > 2);
    /* and it lands on the circle: |C| at Newton level (see constraint test) */
    ASSERT_CLOSE(sqrt((double)(r->st.q[0] * r->st.q[0] + r->st.q[1] * r->st.q[1])), 1.0,
                 2e-9 + 16 * EPS, 0.0);
    free(r);
}

static void test_fail_args(void **state)
{
    pend_par p = pend_default();
    vlbe_dae sys, bad;
    vlbe_hht_params par;
    vlbe_real q0[2], v0[2];
    run *r = (run *)malloc(sizeof *r);
    size_t lw = vlbe_hht_work_len(2, 1), liw = vlbe_hht_iwork_len(2, 1);
    snap s;
    (void)state;
    assert_non_null(r);
    pend_setup(&sys, &p);
    vlbe_hht_params_alpha(&par, VLBE_R(-0.05));
    pend_initial(&p, q0, v0);
    assert_int_equal(vlbe_hht_init(&r->st, &sys, &par, 0, q0, v0, r->w, lw - 1, r->iw, liw),
                     VLBE_EWORK);
    assert_int_equal(vlbe_hht_init(&r->st, &sys, &par, 0, q0, v0, r->w, lw, r->iw, liw - 1),
                     VLBE_EWORK);
    assert_int_equal(vlbe_hht_init(&r->st, &sys, &par, 0, q0, v0, NULL, lw, r->iw, liw),
                     VLBE_EWORK);
    /* bad problem and parameters */
    bad = sys;
    bad.n = 0;
    assert_int_equal(vlbe_hht_init(&r->st, &bad, &par, 0, q0, v0, r->w, lw, r->iw, liw), VLBE_EARG);
    bad = sys;
    bad.constr = NULL;
    assert_int_equal(vlbe_hht_init(&r->st, &bad, &par, 0, q0, v0, r->w, lw, r->iw, liw), VLBE_EARG);
    par.beta = VLBE_R(0.0);
    assert_int_equal(vlbe_hht_init(&r->st, &sys, &par, 0, q0, v0, r->w, lw, r->iw, liw), VLBE_EARG);
    vlbe_hht_params_alpha(&par, VLBE_R(-0.05));
    q0[0] = (vlbe_real)NAN;
    assert_int_equal(vlbe_hht_init(&r->st, &sys, &par, 0, q0, v0, r->w, lw, r->iw, liw),
                     VLBE_ENONFINITE);
    pend_initial(&p, q0, v0);
    assert_int_equal(vlbe_hht_init(&r->st, &sys, &par, 0, q0, v0, r->w, lw, r->iw, liw), VLBE_OK);
    /* h <= 0, NaN, inf: EARG, state untouched */
    snap_take(&r->st, &s);
    assert_int_equal(vlbe_hht_step(&r->st, VLBE_R(0.0)), VLBE_EARG);
    assert_int_equal(vlbe_hht_step(&r->st, VLBE_R(-1e-3)), VLBE_EARG);
    assert_int_equal(vlbe_hht_step(&r->st, (vlbe_real)NAN), VLBE_EARG);
    assert_int_equal(vlbe_hht_step(&r->st, (vlbe_real)INFINITY), VLBE_EARG);
    snap_assert_same(&r->st, &s);
    assert_true(r->st.stats.steps == 0);
    free(r);
}

/* ------------------------------------------------------------------------ */
/* Counters: exact identities for the pendulum with analytic Jacobians, and
   modified Newton against full Newton on the same run. */
static void test_counters(void **state)
{
    pend_par p = pend_default();
    vlbe_dae sys;
    vlbe_hht_params par;
    vlbe_real q0[2], v0[2];
    run *rm = (run *)malloc(sizeof *rm), *rf = (run *)malloc(sizeof *rf);
    const long nsteps = 300;
    long k;
    double tol;
    (void)state;
    assert_non_null(rm);
    assert_non_null(rf);
    pend_setup(&sys, &p);
    pend_initial(&p, q0, v0);
    vlbe_hht_params_genalpha(&par, VLBE_R(0.8));
    par.modified = 1;
    assert_int_equal(run_init(rm, &sys, &par, q0, v0), VLBE_OK);
    par.modified = 0;
    assert_int_equal(run_init(rf, &sys, &par, q0, v0), VLBE_OK);
    for (k = 0; k < nsteps; ++k) {
        assert_int_equal(vlbe_hht_step(&rm->st, VLBE_R(1e-2)), VLBE_OK);
        assert_int_equal(vlbe_hht_step(&rf->st, VLBE_R(1e-2)), VLBE_OK);
    }
    /* both: every step accepted; one LU for the consistent start */
    assert_true(rm->st.stats.steps == nsteps && rf->st.stats.steps == nsteps);
    assert_true(rm->st.stats.rejected == 0 && rf->st.stats.rejected == 0);
    /* full Newton: one Jacobian and one LU per iteration (+ the start's LU);
       one solve per iteration (+ the start's) */
    assert_true(rf->st.stats.jac_evals == rf->st.stats.newton_iters);
    assert_true(rf->st.stats.lu_factors == rf->st.stats.newton_iters + 1);
    assert_true(rf->st.stats.lu_solves == rf->st.stats.newton_iters + 1);
    assert_true(rf->st.stats.newton_iters >= nsteps);
    /* modified Newton: the LU is kept across steps of the same h */
    assert_true(rm->st.stats.lu_factors == rm->st.stats.jac_evals + 1);
    assert_true(rm->st.stats.lu_solves == rm->st.stats.newton_iters + 1);
    assert_true(5 * rm->st.stats.lu_factors < rf->st.stats.lu_factors);
    assert_true(rm->st.stats.newton_iters >= rf->st.stats.newton_iters);
    /* analytic Jacobians: a force call per iteration, one per Jacobian
       (force_jac), one at the start; the mass (VLBE_DAE_MASS_CONST): one
       call at the start, one at the first iteration, then kept */
    assert_true(rm->st.stats.force_calls ==
                rm->st.stats.newton_iters + rm->st.stats.jac_evals + 1);
    assert_true(rm->st.stats.mass_calls == 2);
    /* the same answer: each step's Newton error is below atol + rtol |q|
       (RMS, sqrt(2) for the max over n = 2; |q| = L = 1), or below the
       rounding floor 8 eps |q| at which integrators.h accepts, and the
       pendulum's error propagation is neutral: at most nsteps times that */
    tol = (double)nsteps * sqrt(2.0) * ((double)par.atol + (double)par.rtol + 8.0 * EPS);
    ASSERT_VEC_CLOSE(rm->st.q, rf->st.q, 2, 0.0, tol);
    free(rm);
    free(rf);
}

/* ------------------------------------------------------------------------ */
/* The residual test of the Newton iteration (par.ftol, Hsiao et al. eq. 53):
   ||Psi||_2 / sqrt(n + m) with Psi = (M q'' + C_q^T lambda - Q, C) at the
   accepted state of the pendulum, evaluated here from the formulas. */
static double pend_psi(const pend_par *p, const vlbe_hht *st)
{
    const double m = (double)p->m, g = (double)p->g, L = (double)p->L;
    const double x = (double)st->q[0], y = (double)st->q[1], lam = (double)st->lambda[0];
    const double r0 = m * (double)st->qdd[0] + x * lam;
    const double r1 = m * (double)st->qdd[1] + y * lam + m * g;
    const double c = 0.5 * (x * x + y * y - L * L);
    return sqrt((r0 * r0 + r1 * r1 + c * c) / 3.0);
}
/* the rounding of Psi as integrators.h computes it (in vlbe_real) against
   pend_psi (double, from the same stored state): each component is a sum of
   at most 3 rounded products (gamma_3 < 3.1 eps of the sum of their
   moduli), the norm adds ~2 eps of itself: 4 eps (m |q''| + |q| |lambda| +
   m g + L^2) */
static double pend_psi_round(const pend_par *p, const vlbe_hht *st)
{
    return 4.0 * EPS *
           ((double)p->m * (fabs((double)st->qdd[0]) + fabs((double)st->qdd[1])) +
            (fabs((double)st->q[0]) + fabs((double)st->q[1])) * fabs((double)st->lambda[0]) +
            (double)p->m * (double)p->g + (double)p->L * (double)p->L);
}

/* Two pendulum runs in lockstep: before every step run B gets run A's
   whole state (workspace, stored LU and its step size included), then both
   take the step, A with ftol = 0, B with ftol > 0.  Up to A's convergence
   both iterate identically, so B needs at least as many iterations; its
   accepted state has ||Psi||/sqrt(N) <= ftol; and ftol binds (A's residual
   exceeds it at some steps: the default modified Newton stops on the
   increment test with residuals up to 3e-7 (m:psi_a) N in double,
   9e-3 (m@flt:psi_a) N in float).  ftol: 1e-9 N in double, 1e-4 N in float,
   well above the rounding of Psi (a few eps times m g ~ 10 N): run C, full
   Newton with ftol = 0 on the same steps, ends at 3e-15 (m~:psi_full) N in
   double, 2e-6 (m@flt~:psi_full) N in float, held to ftol / 10.  Psi is
   evaluated here in double from the state: it may exceed the solver's
   (vlbe_real) value by pend_psi_round, ~4e-5 N in float. */
static void test_hht_residual_test(void **state)
{
    pend_par p = pend_default();
    vlbe_dae sys;
    vlbe_hht_params par, pf;
    vlbe_real q0[2], v0[2];
    run *ra = (run *)malloc(sizeof *ra), *rb = (run *)malloc(sizeof *rb);
    const long nsteps = 300;
    long k, more = 0, ia, ib;
    double psi_a = 0.0, psi_b = 0.0, psi_full = 0.0;
#ifndef VLBE_USE_FLOAT
    const double ftol = 1e-9;
#else
    const double ftol = 1e-4;
#endif
    (void)state;
    assert_non_null(ra);
    assert_non_null(rb);
    /* every preset leaves the test off; init rejects ftol < 0, NaN, Inf */
    vlbe_hht_params_newmark(&par, VLBE_R(0.25), VLBE_R(0.5));
    ASSERT_CLOSE(par.ftol, 0.0, 0.0, 0.0);
    vlbe_hht_params_alpha(&par, VLBE_R(-0.1));
    ASSERT_CLOSE(par.ftol, 0.0, 0.0, 0.0);
    vlbe_hht_params_genalpha(&par, VLBE_R(0.8));
    ASSERT_CLOSE(par.ftol, 0.0, 0.0, 0.0);
    pend_setup(&sys, &p);
    pend_initial(&p, q0, v0);
    pf = par;
    pf.ftol = VLBE_R(-1e-6);
    assert_int_equal(run_init(rb, &sys, &pf, q0, v0), VLBE_EARG);
    pf.ftol = (vlbe_real)NAN;
    assert_int_equal(run_init(rb, &sys, &pf, q0, v0), VLBE_EARG);
    pf.ftol = (vlbe_real)INFINITY;
    assert_int_equal(run_init(rb, &sys, &pf, q0, v0), VLBE_EARG);

    pf = par;
    pf.ftol = (vlbe_real)ftol;
    assert_int_equal(run_init(ra, &sys, &par, q0, v0), VLBE_OK);
    assert_int_equal(run_init(rb, &sys, &pf, q0, v0), VLBE_OK);
    for (k = 0; k < nsteps; ++k) {
        /* the same workspace layout (same n, m, lengths): the copy is B's
           state with A's numbers, the stored LU included */
        rb->st.t = ra->st.t;
        memcpy(rb->w, ra->w, sizeof rb->w);
        memcpy(rb->iw, ra->iw, sizeof rb->iw);
        rb->st.have_lu_ = ra->st.have_lu_;
        rb->st.h_lu_ = ra->st.h_lu_;
        ia = ra->st.stats.newton_iters;
        ib = rb->st.stats.newton_iters;
        assert_int_equal(vlbe_hht_step(&ra->st, VLBE_R(1e-2)), VLBE_OK);
        assert_int_equal(vlbe_hht_step(&rb->st, VLBE_R(1e-2)), VLBE_OK);
        ia = ra->st.stats.newton_iters - ia;
        ib = rb->st.stats.newton_iters - ib;
        assert_true(ib >= ia);
        if (ib > ia) ++more;
        psi_a = fmax(psi_a, pend_psi(&p, &ra->st));
        psi_b = fmax(psi_b, pend_psi(&p, &rb->st));
        assert_true(pend_psi(&p, &rb->st) <= ftol + pend_psi_round(&p, &rb->st));
    }
    tu_report("HHT ftol: max ||Psi||/sqrt(N) with ftol [N]", psi_b, ftol);
    tu_report("HHT ftol = 0: max ||Psi||/sqrt(N) [N] (vs ftol)", psi_a, ftol);
    tu_measured("psi_a", psi_a);
    assert_true(psi_a > ftol); /* the test binds ...                       */
    assert_true(more > 0);     /* ... and costs iterations at some steps */
    /* ... and can be met: full Newton (run C) ends far below it */
    {
        run *rc_ = (run *)malloc(sizeof *rc_);
        vlbe_hht_params pc = par;
        assert_non_null(rc_);
        pc.modified = 0;
        assert_int_equal(run_init(rc_, &sys, &pc, q0, v0), VLBE_OK);
        for (k = 0; k < nsteps; ++k) {
            assert_int_equal(vlbe_hht_step(&rc_->st, VLBE_R(1e-2)), VLBE_OK);
            psi_full = fmax(psi_full, pend_psi(&p, &rc_->st));
        }
        free(rc_);
        tu_report("HHT full Newton, ftol = 0: max ||Psi||/sqrt(N) [N] (vs ftol / 10)", psi_full,
                  0.1 * ftol);
        tu_measured("psi_full", psi_full);
        assert_true(psi_full <= 0.1 * ftol);
    }
    /* counters: ftol = 0 keeps the identities of test_counters (a force
       call per iteration + the start's, one more per Jacobian; the
       constant mass twice: start and first iteration); ftol > 0 adds one
       residual evaluation per step, at the accepted iterate, and nothing
       else (its mass is the kept one) */
    assert_true(ra->st.stats.mass_calls == 2);
    assert_true(ra->st.stats.force_calls ==
                ra->st.stats.newton_iters + ra->st.stats.jac_evals + 1);
    assert_true(rb->st.stats.mass_calls == 2);
    assert_true(rb->st.stats.force_calls ==
                rb->st.stats.newton_iters + rb->st.stats.jac_evals + 1 + rb->st.stats.steps);
    assert_true(rb->st.stats.lu_solves == rb->st.stats.newton_iters + 1);
    /* an ftol below the rounding of Psi can only be met by luck (Psi
       exactly 0 in vlbe_real, which happens in float): otherwise ENOCONV,
       the state as it was (measured: ENOCONV in double) */
    {
        snap sn;
        vlbe_status rc;
        rb->st.par.ftol = (vlbe_real)(1e-6 * EPS * EPS);
        snap_take(&rb->st, &sn);
        rc = vlbe_hht_step(&rb->st, VLBE_R(1e-2));
        if (rc != VLBE_OK) {
            assert_int_equal(rc, VLBE_ENOCONV);
            snap_assert_same(&rb->st, &sn);
        } else {
            assert_true(pend_psi(&p, &rb->st) <= pend_psi_round(&p, &rb->st));
        }
    }
    free(ra);
    free(rb);
}

/* ------------------------------------------------------------------------ */
/* The consistent start with gamma from the integrator's central difference
   (constr_acc = NULL) against exact values, at states where gamma is not
   zero: the pendulum moving (gamma = -|v|^2 from the velocity term (C_q
   v)_q v), and a rheonomic bead x = A sin(w t) (gamma = -C_tt = A w^2
   sin(w t), from the time terms).  Exact: pendulum lambda = m (|v|^2 - g
   y) / L^2 and q'' = (0, -g) - lambda q / m (pendulum.c); bead x'' = -A
   w^2 sin(w t), lambda = -m x'' (its row m x'' + lambda = 0), y'' = -g.
   The difference quotient of step e = eps^(1/3) s / (1 + |v|) (s =
   max(|t|, |q|, 1) = 1 here) is exact for the pendulum's g(e) = (q + e
   v).v but for rounding, at most ~4 eps |q| |v| / (2 e) = 20 eps^(2/3) at
   |v| = 3 m/s, 1.1 eps^(2/3) of the scale sc = |v|^2 + g of q''; for the
   bead its truncation e^2 A w^4 / 6 < 0.7 eps^(2/3), 0.06 eps^(2/3) of sc =
   A w^2 + g.  Tolerance 16 eps^(2/3) of sc (lambda: of m sc), ten times
   the larger bound; measured 0.12 (m:gamma_fd) eps^(2/3) in double,
   0.03 (m@flt:gamma_fd) in float (there the solve's rounding, ~5 eps,
   dominates).  A wrong sign of
   gamma is an error of 2 |v|^2 / sc (pendulum), 2 A w^2 / sc (bead). */
typedef struct bead_par {
    vlbe_real m, g, A, w;
} bead_par;

static int bead_constr(void *user, vlbe_real t, const vlbe_real *q, vlbe_real *C)
{
    const bead_par *b = (const bead_par *)user;
    C[0] = q[0] - b->A * vlbe_sin(b->w * t);
    return 0;
}

static int bead_constr_jac(void *user, vlbe_real t, const vlbe_real *q, vlbe_real *Cq,
                           vlbe_real *Ct)
{
    const bead_par *b = (const bead_par *)user;
    (void)q;
    Cq[0] = VLBE_R(1.0);
    Cq[1] = VLBE_R(0.0);
    if (Ct) Ct[0] = -b->A * b->w * vlbe_cos(b->w * t);
    return 0;
}

static int bead_mass(void *user, vlbe_real t, const vlbe_real *q, const vlbe_real *v, vlbe_real *M)
{
    const bead_par *b = (const bead_par *)user;
    (void)t;
    (void)q;
    (void)v;
    M[0] = M[3] = b->m;
    M[1] = M[2] = VLBE_R(0.0);
    return 0;
}

static int bead_force(void *user, vlbe_real t, const vlbe_real *q, const vlbe_real *v, vlbe_real *Q)
{
    const bead_par *b = (const bead_par *)user;
    (void)t;
    (void)q;
    (void)v;
    Q[0] = VLBE_R(0.0);
    Q[1] = -b->m * b->g;
    return 0;
}

static void test_consistent_acc_fd_gamma(void **state)
{
    const double tol = 16.0 * pow(EPS, 2.0 / 3.0);
    pend_par p = pend_default();
    bead_par b;
    vlbe_dae sys;
    vlbe_real q[2], v[2], qdd[2] = {0, 0}, lam[1] = {0}, w[64];
    int iw[8];
    double th, om, ex[2], el, sc, e = 0.0;
    (void)state;
    assert_true(vlbe_dae_work_len(2, 1) <= 64 && vlbe_dae_iwork_len(2, 1) <= 8);
    /* pendulum 50 degrees below the horizontal, swinging at 3 rad/s */
    pend_setup(&sys, &p);
    sys.constr_acc = NULL;
    th = -50.0 * 3.14159265358979323846 / 180.0;
    om = 3.0;
    q[0] = (vlbe_real)((double)p.L * cos(th));
    q[1] = (vlbe_real)((double)p.L * sin(th));
    v[0] = (vlbe_real)(-om * (double)q[1]);
    v[1] = (vlbe_real)(om * (double)q[0]);
    assert_int_equal(vlbe_dae_consistent_acc(&sys, VLBE_R(0.0), q, v, qdd, lam, NULL, w, 64, iw, 8),
                     VLBE_OK);
    {
        const double x = (double)q[0], y = (double)q[1], vx = (double)v[0], vy = (double)v[1];
        const double L2 = (double)p.L * (double)p.L, m = (double)p.m;
        el = m * (vx * vx + vy * vy - (double)p.g * y) / L2;
        ex[0] = -el * x / m;
        ex[1] = -(double)p.g - el * y / m;
        sc = vx * vx + vy * vy + (double)p.g;
    }
    e = fmax(fmax(fabs((double)qdd[0] - ex[0]), fabs((double)qdd[1] - ex[1])) / sc,
             fabs((double)lam[0] - el) / ((double)p.m * sc));
    ASSERT_VEC_CLOSE(qdd, ex, 2, 0.0, tol * sc);
    ASSERT_CLOSE(lam[0], el, 0.0, tol * (double)p.m * sc);
    /* rheonomic bead at t = 0.7 s, A = 0.5 m, w = 2 rad/s */
    {
        vlbe_dae z = {0};
        const double t = 0.7;
        b.m = VLBE_R(2.0);
        b.g = VLBE_R(9.81);
        b.A = VLBE_R(0.5);
        b.w = VLBE_R(2.0);
        sys = z;
        sys.n = 2;
        sys.m = 1;
        sys.flags = VLBE_DAE_MASS_CONST;
        sys.user = &b;
        sys.mass = bead_mass;
        sys.force = bead_force;
        sys.constr = bead_constr;
        sys.constr_jac = bead_constr_jac;
        q[0] = (vlbe_real)(0.5 * sin(2.0 * t));
        q[1] = VLBE_R(0.3);
        v[0] = (vlbe_real)(0.5 * 2.0 * cos(2.0 * t));
        v[1] = VLBE_R(-0.4);
        assert_int_equal(vlbe_dae_consistent_acc(&sys, (vlbe_real)t, q, v, qdd, lam, NULL, w, 64,
                                                 iw, 8),
                         VLBE_OK);
        ex[0] = -0.5 * 4.0 * sin(2.0 * (double)(vlbe_real)t);
        ex[1] = -(double)b.g;
        el = -(double)b.m * ex[0];
        sc = 0.5 * 4.0 + (double)b.g;
        e = fmax(e, fmax(fmax(fabs((double)qdd[0] - ex[0]), fabs((double)qdd[1] - ex[1])) / sc,
                         fabs((double)lam[0] - el) / ((double)b.m * sc)));
        ASSERT_VEC_CLOSE(qdd, ex, 2, 0.0, tol * sc);
        ASSERT_CLOSE(lam[0], el, 0.0, tol * (double)b.m * sc);
    }
    tu_report("consistent start, gamma by differences", e, tol);
    tu_measured("gamma_fd", e / pow(EPS, 2.0 / 3.0));
}

/* ------------------------------------------------------------------------ */
/* Andrews' mechanism. */
static void test_andrews_consistent_start(void **state)
{
    andr_par p = andr_default();
    vlbe_dae sys;
    vlbe_real q0[ANDR_N], v0[ANDR_N], qdd[ANDR_N], lam[ANDR_M];
    vlbe_real w[512];
    int iw[16], i;
    (void)state;
    andr_setup(&sys, &p);
    andr_initial(q0, v0);
    assert_true(vlbe_dae_work_len(ANDR_N, ANDR_M) <= 512);
    assert_int_equal(vlbe_dae_consistent_acc(&sys, VLBE_R(0.0), q0, v0, qdd, lam, NULL, w, 512, iw,
                                             16),
                     VLBE_OK);
    /* the initial positions are consistent: |g| at rounding level of the
       0.01..0.1 m lengths (16 eps * 0.1 m) */
    andr_constr(&p, VLBE_R(0.0), q0, lam);
    for (i = 0; i < ANDR_M; ++i) ASSERT_CLOSE(lam[i], 0.0, 0.0, 16 * EPS * 0.1);
    assert_int_equal(vlbe_dae_consistent_acc(&sys, VLBE_R(0.0), q0, v0, qdd, lam, NULL, w, 512, iw,
                                             16),
                     VLBE_OK);
    /* a 13 x 13 saddle-point solve with inertias 1e-7..1e-5 and lengths
       1e-2: the largest relative error of the nonzero q'' is
       6e-16 (m~:qdd0_rel) in double, 3e-7 (m@flt~:qdd0_rel) in float (a few eps);
       1024 eps for the conditioning; the zero ones to 1024 eps of the scale
       (1.4e4 for q'', 1e2 for lambda) */
    {
        double e = 0.0;
        for (i = 0; i < ANDR_N; ++i)
            if (andr_qdd0()[i] != 0.0)
                e = fmax(e, fabs((double)qdd[i] - andr_qdd0()[i]) / fabs(andr_qdd0()[i]));
        tu_report("Andrews consistent q'': max relative error of the nonzero ones", e, 1024 * EPS);
        tu_measured("qdd0_rel", e);
    }
    ASSERT_VEC_CLOSE(qdd, andr_qdd0(), ANDR_N, 1024 * EPS, 1024 * EPS * 1.4e4);
    ASSERT_VEC_CLOSE(lam, andr_lambda0(), ANDR_M, 1024 * EPS, 1024 * EPS * 1e2);
}

/* Analytic Jacobians of the example against central differences at a
   generic state (the Test Set values at 0.03 s, where nothing vanishes).
   Central differences with step eps^(1/3) x scale err by about eps^(2/3)
   relative: the tolerance is 100 eps^(2/3) of the column scale. */
typedef struct andr_fd_ctx {
    andr_par *p;
    int which;     /* 0 force in q, 1 force in v, 2 M a in q, 3 C in q, 4 C_q^T lam in q, 5 C_q v in q */
    int j;
    const vlbe_real *q, *v, *a, *lam;
} andr_fd_ctx;

static double andr_fd_fn(void *ctx, double x, double *out)
{
    andr_fd_ctx *c = (andr_fd_ctx *)ctx;
    vlbe_real q[ANDR_N], v[ANDR_N], tmp[ANDR_N * ANDR_N], o[ANDR_N];
    double used;
    int i, k;
    memcpy(q, c->q, sizeof q);
    memcpy(v, c->v, sizeof v);
    if (c->which == 1) {
        v[c->j] = (vlbe_real)x;
        used = (double)v[c->j];
    } else {
        q[c->j] = (vlbe_real)x;
        used = (double)q[c->j];
    }
    switch (c->which) {
    case 0:
    case 1: andr_force(c->p, 0, q, v, o); break;
    case 2:
        andr_mass(c->p, 0, q, v, tmp);
        for (i = 0; i < ANDR_N; ++i) {
            o[i] = VLBE_R(0.0);
            for (k = 0; k < ANDR_N; ++k) o[i] += tmp[i * ANDR_N + k] * c->a[k];
        }
        break;
    case 3: andr_constr(c->p, 0, q, o); break;
    case 4:
        andr_constr_jac(c->p, 0, q, tmp, NULL);
        for (i = 0; i < ANDR_N; ++i) {
            o[i] = VLBE_R(0.0);
            for (k = 0; k < ANDR_M; ++k) o[i] += tmp[k * ANDR_N + i] * c->lam[k];
        }
        break;
    default: /* C_q v, whose derivative along v gives -gamma */
        andr_constr_jac(c->p, 0, q, tmp, NULL);
        for (k = 0; k < ANDR_M; ++k) {
            o[k] = VLBE_R(0.0);
            for (i = 0; i < ANDR_N; ++i) o[k] += tmp[k * ANDR_N + i] * c->v[i];
        }
        break;
    }
    for (i = 0; i < (c->which >= 3 && c->which != 4 ? ANDR_M : ANDR_N); ++i) out[i] = (double)o[i];
    return used;
}

static void test_andrews_jacobians(void **state)
{
    andr_par p = andr_default();
    vlbe_real q[ANDR_N], v[ANDR_N], a[ANDR_N], lam[ANDR_M];
    vlbe_real K[49], D[49], Mq[49], G[42], H[49], gam[ANDR_M];
    double d[ANDR_N], work[ANDR_N], gfd[ANDR_M];
    double tol_rel = 100.0 * pow(EPS, 2.0 / 3.0);
    andr_fd_ctx c;
    int i, j, which;
    (void)state;
    for (i = 0; i < ANDR_N; ++i) {
        q[i] = (vlbe_real)andr_qref()[i];
        v[i] = (vlbe_real)(andr_vref()[i] * 1e-3); /* O(1) rad/s keeps the terms comparable */
        a[i] = (vlbe_real)(1.0 + 0.1 * i);
    }
    for (i = 0; i < ANDR_M; ++i) lam[i] = (vlbe_real)andr_lambda_ref()[i];
    andr_force_jac(&p, 0, q, v, K, D);
    andr_mass_jac(&p, 0, q, v, a, Mq, NULL);
    andr_constr_jac(&p, 0, q, G, NULL);
    andr_constr_hess(&p, 0, q, lam, H);
    andr_constr_acc(&p, 0, q, v, gam);
    c.p = &p;
    c.q = q;
    c.v = v;
    c.a = a;
    c.lam = lam;
    for (i = 0; i < ANDR_M; ++i) gfd[i] = 0.0;
    for (which = 0; which < 6; ++which) {
        int rows = (which == 3 || which == 5) ? ANDR_M : ANDR_N;
        c.which = which;
        for (j = 0; j < ANDR_N; ++j) {
            double x = which == 1 ? (double)v[j] : (double)q[j];
            double scale = 0.0, hstep = tu_fd_step(EPS, fmax(1.0, fabs(x)));
            const vlbe_real *an = which == 0 ? K : which == 1 ? D : which == 2 ? Mq : which == 4 ? H : G;
            int ld = which == 3 ? ANDR_N : ANDR_N;
            c.j = j;
            tu_central_diff(andr_fd_fn, &c, x, hstep, rows, work, d);
            if (which == 5) {
                /* (C_q v)_q v summed over j gives -gamma */
                for (i = 0; i < ANDR_M; ++i) gfd[i] -= d[i] * (double)v[j];
                continue;
            }
            for (i = 0; i < rows; ++i) scale = fmax(scale, fabs(d[i]));
            for (i = 0; i < rows; ++i) {
                double an_ij = (double)an[i * ld + j];
                ASSERT_CLOSE(an_ij, d[i], tol_rel, tol_rel * fmax(scale, 1e-3));
            }
        }
    }
    {
        double gs = 0.0;
        for (i = 0; i < ANDR_M; ++i) gs = fmax(gs, fabs(gfd[i]));
        ASSERT_VEC_CLOSE(gam, gfd, ANDR_M, tol_rel, tol_rel * gs);
    }
}

/* HHT-alpha and generalized-alpha reach the Test Set positions at 0.03 s to
   1e-6 relative.  The error is O(h^2): max relative over the 7 angles
   1.8e-5 (m:andr_hht_coarse) (HHT) and 1.6e-5 (m:andr_ga_coarse) (gen-alpha)
   at h = 1e-5, 1.7e-7 (m:andr_hht) and 1.4e-7 (m:andr_ga) at h = 1e-6
   (Newton rtol 1e-12); h = 1e-6 leaves a factor 6.  A 24-bit mantissa
   cannot hold the 15.8 rad angle to 1e-6 over 3e4 steps: double only.
   Slow builds (tu_slow_run: -O0, sanitizers, valgrind) check h = 5e-6 at
   1e-5 instead (4.5e-6 (m@san:andr_quick), the worse method) and skip
   the runs at h = 1e-5. */
static void test_andrews_reference(void **state)
{
#ifndef VLBE_USE_FLOAT
    const int slow = tu_slow_run();
    const long nsteps = slow ? 6000 : 30000;
    const double tol = slow ? 1e-5 : 1e-6;
    double qworst = 0.0, lworst = 0.0;
    int method;
    (void)state;
    for (method = 0; method < 2; ++method) {
        vlbe_hht_params par;
        andr_result r;
        andr_params_for(method, &par);
        assert_int_equal(andr_run(&par, nsteps, &r), VLBE_OK);
        tu_report(method ? "Andrews gen-alpha: max relative error of q" :
                           "Andrews HHT: max relative error of q", r.max_rel_err, tol);
        if (!slow) tu_measured(method ? "andr_ga" : "andr_hht", r.max_rel_err);
        qworst = fmax(qworst, r.max_rel_err);
        ASSERT_VEC_CLOSE(r.q, andr_qref(), ANDR_N, tol, 0.0);
        /* multipliers are O(h^2) as well: 5.9e-7 (m:andr_lam) (lambda_1,
           the worse method) at h = 1e-6, 1.3e-5 (m@san:andr_lam_quick)
           at 5e-6; 100 tol */
        lworst = fmax(lworst, fabs(r.lambda[0] - andr_lambda_ref()[0]) /
                                  fabs(andr_lambda_ref()[0]));
        ASSERT_CLOSE(r.lambda[0], andr_lambda_ref()[0], 100.0 * tol, 0.0);
        /* constraints at Newton level (lengths 1e-2 m, rtol 1e-12) */
        assert_true(r.max_c <= 1e-13);
        assert_true(r.stats.steps == nsteps);
        if (!slow) {
            /* h = 1e-5, for the order (reported) */
            assert_int_equal(andr_run(&par, nsteps / 10, &r), VLBE_OK);
            tu_measured(method ? "andr_ga_coarse" : "andr_hht_coarse", r.max_rel_err);
        }
    }
    tu_measured(slow ? "andr_quick" : "andr_qworst", qworst);
    tu_measured(slow ? "andr_lam_quick" : "andr_lam", lworst);
#else
    (void)state;
    TU_SKIP("a 24-bit mantissa cannot hold the 15.8 rad angle to 1e-6 over 3e4 steps");
#endif
}


/* ------------------------------------------------------------------------ */
/* vlbe_hht_advance: equal steps of at most h_max that end on t_out.
   Output times that are no binary fractions (0.1 k, k / 3), many calls:
   st.t == t_out bit for bit after each, the steps of each call as many as
   ceil((t_out - t) / h_max) (computed here in double, away from an integer),
   none halved or rejected.  Where h_max divides the interval exactly
   (binary fractions: h_max = 1/16 from t = 0 to 1, then to 2) the run is
   the one of plain vlbe_hht_step(h_max) calls, bit for bit, the second
   call included (the run of steps goes on).  Arguments. */
static void test_hht_advance(void **state)
{
    pend_par p = pend_default();
    vlbe_dae sys;
    vlbe_hht_params par;
    vlbe_real q0[2], v0[2];
    run *a = (run *)malloc(sizeof *a), *b = (run *)malloc(sizeof *b);
    int i, k;
    (void)state;
    assert_non_null(a);
    assert_non_null(b);
    pend_setup(&sys, &p);
    pend_initial(&p, q0, v0);
    vlbe_hht_params_genalpha(&par, VLBE_R(0.8));
    /* 0.1 k with h_max 0.013, then k / 3 with h_max 0.01 */
    assert_int_equal(run_init(a, &sys, &par, q0, v0), VLBE_OK);
    for (k = 0; k < 2; ++k) {
        const vlbe_real hmax = k == 0 ? VLBE_R(0.013) : VLBE_R(0.01);
        for (i = 1; i <= 30; ++i) {
            const vlbe_real tout = k == 0 ? (vlbe_real)i / VLBE_R(10.0)
                                          : VLBE_R(3.0) + (vlbe_real)i / VLBE_R(3.0);
            const double r = ((double)tout - (double)a->st.t) / (double)hmax;
            const long steps0 = a->st.stats.steps, kexp = (long)ceil(r);
            /* ceil is well defined here: r is no integer to 1e-6 */
            assert_true(fabs(r - floor(r + 0.5)) > 1e-6);
            assert_int_equal(vlbe_hht_advance(&a->st, tout, hmax), VLBE_OK);
            assert_true(a->st.t == tout);
            assert_true(a->st.stats.steps - steps0 == kexp);
        }
        assert_true(a->st.stats.rejected == 0);
    }
    /* t_out == t: nothing; behind, NaN, bad h_max: EARG */
    {
        const long steps0 = a->st.stats.steps;
        const vlbe_real t = a->st.t;
        assert_int_equal(vlbe_hht_advance(&a->st, t, VLBE_R(0.01)), VLBE_OK);
        assert_int_equal(vlbe_hht_advance(&a->st, t - VLBE_R(0.5), VLBE_R(0.01)), VLBE_EARG);
        assert_int_equal(vlbe_hht_advance(&a->st, (vlbe_real)NAN, VLBE_R(0.01)), VLBE_EARG);
        assert_int_equal(vlbe_hht_advance(&a->st, t + VLBE_R(1.0), VLBE_R(0.0)), VLBE_EARG);
        assert_int_equal(vlbe_hht_advance(&a->st, t + VLBE_R(1.0), (vlbe_real)INFINITY),
                         VLBE_EARG);
        assert_int_equal(vlbe_hht_advance(&a->st, t + VLBE_R(1.0), VLBE_EPS), VLBE_EARG);
        assert_true(a->st.t == t && a->st.stats.steps == steps0);
    }
    /* h_max divides the interval: plain stepping, bit for bit */
    assert_int_equal(run_init(a, &sys, &par, q0, v0), VLBE_OK);
    assert_int_equal(run_init(b, &sys, &par, q0, v0), VLBE_OK);
    for (k = 1; k <= 2; ++k) {
        snap s;
        assert_int_equal(vlbe_hht_advance(&a->st, (vlbe_real)k, VLBE_R(0.0625)), VLBE_OK);
        for (i = 0; i < 16; ++i) assert_int_equal(vlbe_hht_step(&b->st, VLBE_R(0.0625)), VLBE_OK);
        assert_true(b->st.t == (vlbe_real)k);
        snap_take(&b->st, &s);
        snap_assert_same(&a->st, &s);
        assert_true(a->st.stats.lu_factors == b->st.stats.lu_factors &&
                    a->st.stats.newton_iters == b->st.stats.newton_iters);
    }
    free(a);
    free(b);
}

/* A step of vlbe_hht_advance fails (the force reports an error from its
   41st call on, no halvings): the status comes back, the state is the
   last accepted step, a point t0 + j h of the call's grid, and it is the
   state plain stepping with that h reaches there, bit for bit. */
static void test_hht_advance_fail(void **state)
{
    faulty f;
    vlbe_dae sys;
    vlbe_hht_params par;
    vlbe_real q0[2], v0[2];
    run *a = (run *)malloc(sizeof *a), *b = (run *)malloc(sizeof *b);
    snap s;
    long j = 0;
    (void)state;
    assert_non_null(a);
    assert_non_null(b);
    faulty_setup(&sys, &f, 0);
    pend_initial(&f.p, q0, v0);
    vlbe_hht_params_genalpha(&par, VLBE_R(0.8));
    assert_int_equal(run_init(a, &sys, &par, q0, v0), VLBE_OK);
    f.mode = 2;
    f.after = 40;
    f.calls = 0;
    assert_int_equal(vlbe_hht_advance(&a->st, VLBE_R(1.0), VLBE_R(0.01)), VLBE_ECALLBACK);
    assert_true(a->st.t > VLBE_R(0.0) && a->st.t < VLBE_R(1.0));
    f.mode = 0;
    assert_int_equal(run_init(b, &sys, &par, q0, v0), VLBE_OK);
    while (b->st.t < a->st.t) {
        assert_true(++j < 100);
        assert_int_equal(vlbe_hht_step(&b->st, VLBE_R(1.0) / VLBE_R(100.0)), VLBE_OK);
    }
    snap_take(&b->st, &s);
    snap_assert_same(&a->st, &s);
    /* repaired: the rest of the way, ending on t_out */
    assert_int_equal(vlbe_hht_advance(&a->st, VLBE_R(1.0), VLBE_R(0.01)), VLBE_OK);
    assert_true(a->st.t == VLBE_R(1.0));
    free(a);
    free(b);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_params_presets),
        cmocka_unit_test(test_pendulum_period_order),
        cmocka_unit_test(test_pendulum_multiplier),
        cmocka_unit_test(test_pendulum_constraint),
        cmocka_unit_test(test_oscillator_spectral_radius),
        cmocka_unit_test(test_newmark_gamma_stability),
        cmocka_unit_test(test_trapezoidal_index3_unstable),
        cmocka_unit_test(test_fail_nonfinite),
        cmocka_unit_test(test_fail_callback),
        cmocka_unit_test(test_fail_singular),
        cmocka_unit_test(test_row_scaling),
        cmocka_unit_test(test_fail_noconv_and_recovery),
        cmocka_unit_test(test_fail_args),
        cmocka_unit_test(test_counters),
        cmocka_unit_test(test_hht_residual_test),
        cmocka_unit_test(test_consistent_acc_fd_gamma),
        cmocka_unit_test(test_andrews_consistent_start),
        cmocka_unit_test(test_andrews_jacobians),
        cmocka_unit_test(test_andrews_reference),
        cmocka_unit_test(test_hht_advance),
        cmocka_unit_test(test_hht_advance_fail),
    };
    return cmocka_run_group_tests_name("integrators", tests, NULL, NULL);
}
