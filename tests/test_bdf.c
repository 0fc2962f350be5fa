/* test_bdf.c -- BDF 1..5 (variable step and order) on the GGL index-2 form
   -- part of vlbe                                  SPDX-License-Identifier: MIT
   build: cc -std=c99 -O2 tests/test_bdf.c -lcmocka -lm   (also -DVLBE_USE_FLOAT)

   1. index-3 pendulum (point mass, rod 1 m, g = 9.81, released at rest from
      the horizontal): period, constraint drift, lambda = -3 g y, error
      decreasing with the tolerance;
   2. the order cap (max_order 2 and 1);
   3. linear undamped oscillator, fixed step and order: the amplification
      per step of BDF1..5 measured from the integrator against the roots of
      the characteristic polynomial (growth inside the unstable band of
      BDF3..5 on the imaginary axis, decay outside, BDF1..2 always decay);
   4. failures: non-finite force (ENONFINITE), callback error (ECALLBACK), a callback
      that calls one iterate outside its domain (retried smaller, goes on),
      h_min too large (ESTEP), small workspace (EWORK), bad arguments
      (EARG), each leaving the state at the last accepted step;
   5. a stiff undamped spring on a spinning arm (the hub scene of
      scenes/ex_spin.h in miniature, rheonomic constraints): the Newton
      rate is measured afresh at every step (a stale one let fixed-step
      BDF2 drift off by 3 rad), and the filtered error estimate keeps the
      variable-step run free of the rejection cascade of the plain one. */
#include "test_util.h"
#include "../integrators.h"

#include "../scenes/pendulum.h"
#include "pend_faults.h"

#include <complex.h>
#include <stdlib.h>
#include <string.h>

#define EPS ((double)VLBE_EPS)

/* -- the pendulum ----------------------------------------------------------
   The problem of scenes/pendulum.h (m = 1 kg, L = 1 m, g = 9.81 m/s^2,
   q = (x, y), C = (x^2 + y^2 - L^2)/2; there also lambda = -3 m g y / L^2
   and the period PEND_T_PUBLISHED for the 90 degree amplitude), its
   callbacks wrapped by pend_faults.h so that the failure tests can inject
   faults.  The runs here use finite differences for the force Jacobian, the
   constraint Hessian and gamma (the example's analytic ones switched off);
   test_pendulum_analytic_jacobians switches force_jac and constr_hess back
   on to compare. */
static vlbe_dae pend_sys(faulty *f)
{
    vlbe_dae s;
    faulty_setup(&s, f, 0);
    s.constr_acc = NULL;
    s.force_jac = NULL;
    s.constr_hess = NULL;
    return s;
}

/* workspace for the small systems of this file */
#define WLEN 4096
static vlbe_real g_work[WLEN];
static int g_iwork[64];

static vlbe_status pend_init(vlbe_bdf *st, const vlbe_dae *s, const vlbe_bdf_params *p)
{
    vlbe_real q0[2], v0[2];
    pend_initial(&((const faulty *)s->user)->p, q0, v0);
    assert_true(vlbe_bdf_work_len(2, 1) <= WLEN);
    return vlbe_bdf_init(st, s, p, VLBE_R(0.0), q0, v0, g_work, WLEN, g_iwork, 64);
}

/* Tolerance of the accuracy runs: 1e-8 in double; float cannot ask for less
   than ~100 eps relative per step (the Newton corrections and the weighted
   differences would be rounding noise). */
static double run_rtol(void) { return EPS < 1e-10 ? 1e-8 : 100.0 * EPS; }

/* -- step caps -------------------------------------------------------------
   Every integration loop here counts its steps against a cap, so that a bug
   that shrinks the steps (or stops t from advancing) fails the test within
   seconds instead of hanging it.  Fixed steps: the number of steps.
   Adaptive steps: step_cap(span, h_floor) = 4 span / h_floor + 100, h_floor
   a step that the loop's problem does not need to go below on average (each
   use says why), or ten times the step count of the run (reported).
   For the pendulum at rtol = atol = tol, h_floor = pend_floor(tol) =
   0.1 sqrt(tol) s: BDF1, the order with the shortest steps, keeps its local
   error h^2 |y''| / 2 below tol (1 + |y|) at h = sqrt(2 tol (1 + |y|) / |y''|),
   at least 0.12 sqrt(tol) s with |y''| up to ~130 m/s^3 (the jerk of the
   swing, sqrt(2 g L) / L times 3 g, in the velocity rows); the higher
   orders take longer steps, and the start (1e-3 of the span) and the
   rejections add a few short ones. */
static long step_cap(double span, double h_floor) { return 4 * (long)(span / h_floor) + 100; }
static double pend_floor(double tol) { return 0.1 * sqrt(tol); }

/* fails the test when the n-th step of a loop passes its cap */
static void cap_check(long n, long cap, const vlbe_bdf *st)
{
    if (n > cap)
        fail_msg("step cap %ld reached at t = %.9g (last step %.3g): the steps shrank", cap,
                 (double)st->t, (double)st->h_last);
}

/* vlbe_bdf_advance under a step cap (its loop of vlbe_bdf_step calls, the
   same statuses); t_out behind t goes to vlbe_bdf_advance itself (EARG). */
static vlbe_status advance_capped(vlbe_bdf *st, vlbe_real t_out, long cap)
{
    long n = 0;
    vlbe_status rc;
    if (!(t_out >= st->t)) return vlbe_bdf_advance(st, t_out);
    while (st->t < t_out) {
        cap_check(++n, cap, st);
        if ((rc = vlbe_bdf_step(st, t_out)) != VLBE_OK) return rc;
    }
    return VLBE_OK;
}

typedef struct pend_out {
    double period_err; /* relative                              */
    double max_c;      /* max |C| over accepted steps           */
    double max_cv;     /* max |C_q v|                           */
    double max_lam;    /* max |lambda - lambda_exact| / (3 m g / L) */
    vlbe_dae_stats stats;
} pend_out;

/* One period; the period error comes from v_y at t = T: near the return
   point (1, 0) the motion is y = -g/2 (t - T_num)^2 (lambda = 0 there),
   so v_y(T) = g (T_num - T), an O(dT^2)-exact measurement. */
static void bdf_pend_run(const vlbe_bdf_params *p, const vlbe_dae *s, pend_out *o,
                         int max_order_seen)
{
    const pend_par *par = &((const faulty *)s->user)->p;
    vlbe_bdf st;
    double T = PEND_T_PUBLISHED, lam_scale = 3.0 * PEND_M * PEND_G / PEND_L;
    const long cap = step_cap(T, pend_floor((double)p->rtol));
    long n = 0;
    assert_int_equal(pend_init(&st, s, p), VLBE_OK);
    /* lambda(0) = 0 from the consistent start (y = 0, v = 0) */
    ASSERT_CLOSE(st.lambda[0], 0.0, 0.0, 1e3 * EPS);
    o->max_c = o->max_cv = o->max_lam = 0.0;
    while (st.t < (vlbe_real)T) {
        double c, cv, le, x, y;
        cap_check(++n, cap, &st);
        assert_int_equal(vlbe_bdf_step(&st, (vlbe_real)T), VLBE_OK);
        assert_true(st.order >= 1 && st.order <= max_order_seen);
        assert_true(st.order_last >= 1 && st.order_last <= max_order_seen);
        x = (double)st.q[0];
        y = (double)st.q[1];
        c = fabs(0.5 * (x * x + y * y - PEND_L * PEND_L)); /* in double */
        cv = fabs(x * (double)st.v[0] + y * (double)st.v[1]);
        le = fabs((double)st.lambda[0] - pend_lambda_exact(par, y)) / lam_scale;
        if (c > o->max_c) o->max_c = c;
        if (cv > o->max_cv) o->max_cv = cv;
        if (le > o->max_lam) o->max_lam = le;
    }
    assert_true(st.t == (vlbe_real)T); /* landed exactly */
    o->period_err = fabs((double)st.v[1] / PEND_G) / T;
    o->stats = st.stats;
}

static void test_pendulum_period(void **state)
{
    faulty c;
    vlbe_dae s = pend_sys(&c);
    vlbe_bdf_params p;
    pend_out o;
    double tol = run_rtol();
    (void)state;
    vlbe_bdf_params_default(&p);
    p.rtol = p.atol = (vlbe_real)tol;
    bdf_pend_run(&p, &s, &o, 5);
    print_message("pendulum rtol %.1e: period err %.2e, |C| %.1e, |C_q v| %.1e, lambda %.1e, "
                  "%ld steps, %ld rejected, %ld Newton, %ld Jacobians, %ld LU\n",
                  tol, o.period_err, o.max_c, o.max_cv, o.max_lam, o.stats.steps,
                  o.stats.rejected, o.stats.newton_iters, o.stats.jac_evals, o.stats.lu_factors);
    tu_report("pendulum period error (relative)", o.period_err, 100.0 * tol);
    tu_report("pendulum max |C|", o.max_c, 10.0 * tol);
    tu_report("pendulum max |C_q v|", o.max_cv, 100.0 * tol);
    tu_report("pendulum max lambda error / (3 m g / L)", o.max_lam, 1e3 * tol);
    tu_measured("pend_c", o.max_c);
    tu_measured("pend_cv", o.max_cv);
    tu_measured("pend_lam", o.max_lam);
    /* period to better than 1e-6 at rtol 1e-8 (float: 100 rtol) */
    assert_true(o.period_err <= 100.0 * tol);
    /* constraints hold to the Newton tolerance at every step, no drift:
       |C| and |C_q v| are of the size of the tolerance (5e-10 (m:pend_c),
       3e-9 (m:pend_cv) at rtol 1e-8) */
    assert_true(o.max_c <= 10.0 * tol);
    assert_true(o.max_cv <= 100.0 * tol);
    /* the index-2 multiplier is less accurate than q, v (5e-7 (m:pend_lam)
       relative at rtol 1e-8): 1e3 rtol */
    assert_true(o.max_lam <= 1e3 * tol);
    /* the Jacobian is kept across steps: far fewer LU than steps */
    assert_true(o.stats.lu_factors * 5 < o.stats.steps);
    assert_true(o.stats.newton_fails == 0);
}

/* Analytic force Jacobian and constraint Hessian give the same answer as the
   finite differences (to the tolerance). */
static void test_pendulum_analytic_jacobians(void **state)
{
    faulty c;
    vlbe_dae s = pend_sys(&c);
    vlbe_bdf_params p;
    pend_out a, b;
    double tol = run_rtol();
    (void)state;
    vlbe_bdf_params_default(&p);
    p.rtol = p.atol = (vlbe_real)tol;
    bdf_pend_run(&p, &s, &a, 5);
    s.force_jac = pend_force_jac;
    s.constr_hess = pend_constr_hess;
    bdf_pend_run(&p, &s, &b, 5);
    assert_true(b.period_err <= 100.0 * tol);
    ASSERT_CLOSE(b.period_err, a.period_err, 0.0, 10.0 * tol);
    /* no differences of Q: 2n force calls fewer per Jacobian */
    assert_true(b.stats.force_calls < a.stats.force_calls);
}

/* The error falls with the tolerance (three decades of rtol). */
static void test_pendulum_convergence(void **state)
{
    faulty c;
    vlbe_dae s = pend_sys(&c);
    vlbe_bdf_params p;
    pend_out o;
    double tol[3], err[3];
    int i;
    (void)state;
    tol[2] = run_rtol();
    tol[1] = 100.0 * tol[2];
    tol[0] = 100.0 * tol[1];
    for (i = 0; i < 3; ++i) {
        vlbe_bdf_params_default(&p);
        p.rtol = p.atol = (vlbe_real)tol[i];
        bdf_pend_run(&p, &s, &o, 5);
        err[i] = o.period_err;
        print_message("pendulum rtol %.1e: period err %.2e, %ld steps\n", tol[i], err[i],
                      o.stats.steps);
        /* tolerance proportionality within a factor 100 */
        tu_report("pendulum period error (relative) vs 100 rtol", err[i], 100.0 * tol[i]);
        assert_true(err[i] <= 100.0 * tol[i]);
    }
    assert_true(err[1] < err[0] && err[2] < err[1]);
}

/* -- order cap ------------------------------------------------------------ */
static void test_order_cap(void **state)
{
    faulty c;
    vlbe_dae s = pend_sys(&c);
    vlbe_bdf_params p;
    pend_out o;
    int k;
    (void)state;
    for (k = 1; k <= 2; ++k) {
        vlbe_bdf st;
        int seen = 0;
        vlbe_bdf_params_default(&p);
        p.rtol = p.atol = (vlbe_real)(100.0 * run_rtol());
        p.max_order = k;
        /* every accepted step, and the order planned for the next, <= k */
        bdf_pend_run(&p, &s, &o, k);
        assert_true(o.period_err <= 1e3 * (double)p.rtol);
        /* and order k itself is used */
        assert_int_equal(pend_init(&st, &s, &p), VLBE_OK);
        {
            const long cap = step_cap(0.5, pend_floor((double)p.rtol));
            long n = 0;
            while (st.t < VLBE_R(0.5)) {
                cap_check(++n, cap, &st);
                assert_int_equal(vlbe_bdf_step(&st, VLBE_R(0.5)), VLBE_OK);
                if (st.order_last > seen) seen = st.order_last;
            }
        }
        assert_int_equal(seen, k);
    }
    /* max_order outside 1..5 */
    vlbe_bdf_params_default(&p);
    p.max_order = 0;
    {
        vlbe_bdf st;
        assert_int_equal(pend_init(&st, &s, &p), VLBE_EARG);
        p.max_order = 6;
        assert_int_equal(pend_init(&st, &s, &p), VLBE_EARG);
    }
}

/* -- linear stability on the imaginary axis -------------------------------
   BDFk at constant step h:  sum_{j=1}^k (1/j) nabla^j y_{n+1} = h f_{n+1}.
   For y' = lambda y, z = h lambda, y_n = zeta^n: nabla^j y_{n+1} =
   zeta^{n+1} (1 - 1/zeta)^j, so zeta solves the characteristic equation
       rho(zeta) - z sigma(zeta) = sum_{j=1}^k (1/j) (zeta - 1)^j zeta^{k-j} - z zeta^k = 0,
   a polynomial of degree k.  The undamped oscillator q'' = -w^2 q, as the
   first-order system q' = v, v' = -w^2 q (GGL with m = 0), has lambda =
   +-i w: z = +-i y with y = w h.  The amplification per step is the largest
   |zeta|; the boundary locus z(theta) = rho(e^{i theta}) / sigma(e^{i theta})
   of BDF3 and BDF4 crosses into the left half-plane near the origin, so the
   imaginary axis has an unstable band 0 < y < y* (y* ~ 1.94 for BDF3, ~4.9
   for BDF4: the principal root is 1 - C (i y)^{k+1} + ... with C = -1/(k+1),
   growing for small y when k = 3, 4); BDF5's band starts at y ~ 0.71 (for
   small y its principal root decays, -(iy)^6/6 < 0) and reaches far out;
   BDF1 and BDF2 are A-stable, |zeta| < 1 for all y != 0.
   The roots are computed here by Durand-Kerner iteration, in double and
   complex arithmetic, independently of the integrator; *second (if not
   NULL): the second largest modulus (for the fit below). */
static double bdf_amplification(int k, double y, double *second)
{
    double complex c[6], r[5];
    double b[6];
    int i, j, l, it;
    for (i = 0; i <= k; ++i) c[i] = 0.0;
    for (j = 1; j <= k; ++j) {
        /* b = (x - 1)^j, b[i] the coefficient of x^i */
        for (i = 0; i <= 5; ++i) b[i] = 0.0;
        b[0] = 1.0;
        for (l = 0; l < j; ++l)
            for (i = l + 1; i >= 0; --i) b[i] = (i > 0 ? b[i - 1] : 0.0) - b[i];
        for (i = 0; i <= j; ++i) c[i + k - j] += b[i] / (double)j;
    }
    c[k] -= (double complex)I * y;
    for (i = 0; i < k; ++i) c[i] /= c[k];
    c[k] = 1.0;
    for (i = 0; i < k; ++i) r[i] = cpow(0.4 + 0.9 * (double complex)I, (double)i);
    for (it = 0; it < 500; ++it)
        for (i = 0; i < k; ++i) {
            double complex p = 0.0, d = 1.0;
            for (j = k; j >= 0; --j) p = p * r[i] + c[j];
            for (j = 0; j < k; ++j)
                if (j != i) d *= r[i] - r[j];
            r[i] -= p / d;
        }
    {
        double a = 0.0, a2 = 0.0;
        for (i = 0; i < k; ++i) {
            /* a root indeed */
            double complex p = 0.0;
            for (j = k; j >= 0; --j) p = p * r[i] + c[j];
            assert_true(cabs(p) < 1e-12);
            if (cabs(r[i]) > a) {
                a2 = a;
                a = cabs(r[i]);
            } else if (cabs(r[i]) > a2) {
                a2 = cabs(r[i]);
            }
        }
        if (second) *second = a2;
        return a;
    }
}

#define OSC_W 1.0 /* rad/s */
static int osc_mass(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v, vlbe_real *M)
{
    (void)u, (void)t, (void)q, (void)v;
    M[0] = VLBE_R(1.0);
    return 0;
}
static int osc_force(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v, vlbe_real *Q)
{
    (void)u, (void)t, (void)v;
    Q[0] = -(vlbe_real)(OSC_W * OSC_W) * q[0];
    return 0;
}
static int osc_fjac(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v, vlbe_real *K,
                    vlbe_real *D)
{
    (void)u, (void)t, (void)q, (void)v;
    K[0] = -(vlbe_real)(OSC_W * OSC_W);
    D[0] = VLBE_R(0.0);
    return 0;
}

/* The integrator's amplification per step: once the parasitic roots
   (|zeta| < 0.8) have died out, q_n = Re(c zeta^n) obeys q_{n+1} = a q_n -
   b q_{n-1} with a = 2 Re zeta, b = |zeta|^2; a and b by least squares over
   the second half of the steps (each equation scaled by the local
   amplitude). */
static double measured_amplification(int k, double y, int nsteps)
{
    vlbe_dae s;
    vlbe_bdf_params p;
    vlbe_bdf st;
    vlbe_real q0 = VLBE_R(1.0), v0 = VLBE_R(0.0);
    double qs[3] = {0.0, 0.0, 0.0}, A11 = 0, A12 = 0, A22 = 0, r1 = 0, r2 = 0, det, b;
    int n;
    memset(&s, 0, sizeof s);
    s.n = 1;
    s.m = 0;
    s.flags = VLBE_DAE_MASS_CONST;
    s.mass = osc_mass;
    s.force = osc_force;
    s.force_jac = osc_fjac;
    vlbe_bdf_params_default(&p);
    p.fixed_step = 1;
    p.h0 = (vlbe_real)(y / OSC_W);
    p.max_order = k;
    p.rtol = p.atol = (vlbe_real)(10.0 * EPS); /* the corrector to rounding */
    assert_int_equal(vlbe_bdf_init(&st, &s, &p, VLBE_R(0.0), &q0, &v0, g_work, WLEN, g_iwork, 64),
                     VLBE_OK);
    for (n = 1; n <= nsteps; ++n) {
        assert_int_equal(vlbe_bdf_step(&st, (vlbe_real)1e30), VLBE_OK);
        assert_true(st.h_last == p.h0);
        assert_int_equal(st.order_last, n < k ? n : k);
        qs[0] = qs[1];
        qs[1] = qs[2];
        qs[2] = (double)st.q[0];
        if (n > nsteps / 2) { /* transients gone: (|zeta_2| / |zeta_1|)^(n/2) tiny */
            double sc = 1.0 / (fabs(qs[0]) + fabs(qs[1]) + fabs(qs[2]));
            double x1 = qs[1] * sc, x2 = -qs[0] * sc, rhs = qs[2] * sc;
            A11 += x1 * x1;
            A12 += x1 * x2;
            A22 += x2 * x2;
            r1 += x1 * rhs;
            r2 += x2 * rhs;
        }
    }
    det = A11 * A22 - A12 * A12;
    b = (A11 * r2 - A12 * r1) / det;
    return sqrt(b);
}

static void test_oscillator_stability(void **state)
{
    /* (order, w h, expected: 1 grows, -1 decays) */
    static const struct {
        int k;
        double y;
        int grows;
    } cs[] = {{1, 0.5, -1}, {1, 2.0, -1}, {2, 0.5, -1}, {2, 2.0, -1}, {3, 1.0, 1},
              {3, 3.0, -1}, {4, 1.0, 1},  {4, 8.0, -1}, {5, 0.4, -1}, {5, 2.0, 1},
              {5, 15.0, -1}};
    size_t i;
    (void)state;
    for (i = 0; i < sizeof cs / sizeof cs[0]; ++i) {
        double th = bdf_amplification(cs[i].k, cs[i].y, NULL);
        /* at most 400 steps, and at most 30 decades of growth or decay
           (float range) */
        int ns = (int)(30.0 / fabs(log10(th)));
        double me = measured_amplification(cs[i].k, cs[i].y, ns < 400 ? ns : 400);
        print_message("BDF%d  w h = %5.2f: |zeta| theory %.10f, integrator %.10f (%d steps)\n",
                      cs[i].k, cs[i].y, th, me, ns < 400 ? ns : 400);
        /* the theory says what the case claims (the band, derived above) */
        assert_true(cs[i].grows > 0 ? th > 1.0 : th < 1.0);
        /* the integrator does the same, to rounding: the fit sees q_n to a
           few ulps over 300 steps (float: 1e-7 relative noise) */
        tu_report("BDF amplification: integrator vs roots", fabs(me - th), 1e3 * EPS);
        ASSERT_CLOSE(me, th, 0.0, 1e3 * EPS);
        assert_true(cs[i].grows > 0 ? me > 1.0 : me < 1.0);
    }
}

/* BDF1 and BDF2 damp the oscillator at every w h: scan over w h = 0.05 ..
   51.2 (factors of 2).  Oracle check: the roots of bdf_amplification have
   |zeta| < 1 (BDF1 and BDF2 are A-stable: a known fact the root finder must
   reproduce).  Library check: the integrator's amplification (the fit of
   measured_amplification, steps as in test_oscillator_stability) is below
   1 and equals the roots' to 1e3 EPS (rounding, as there) plus the
   parasitic root's share at the start of the fit, (|zeta_2| / |zeta_1|)^(n/2)
   relative: BDF2's two roots come close in modulus at large w h (ratio
   0.76 at 51.2), where the fit sees both.  The largest deviation is
   0.10 (m:damp_share_max) of its allowance. */
static void test_bdf12_always_damp(void **state)
{
    double worst = 0.0;
    int k;
    double y;
    (void)state;
    for (k = 1; k <= 2; ++k)
        for (y = 0.05; y < 100.0; y *= 2.0) {
            double second, th = bdf_amplification(k, y, &second), me, tol;
            int ns = (int)(30.0 / fabs(log10(th)));
            if (ns > 400) ns = 400;
            assert_true(th < 1.0); /* the oracle */
            me = measured_amplification(k, y, ns);
            tol = 1e3 * EPS + th * pow(second / th, 0.5 * ns);
            worst = fmax(worst, fabs(me - th) / tol);
            ASSERT_CLOSE_CTX(me, th, 0.0, tol, "BDF%d, w h = %g, %d steps", k, y, ns);
            assert_true(me < 1.0);
        }
    tu_report("BDF1, BDF2 amplification scan: |integrator - roots| / tolerance", worst, 1.0);
    tu_measured("damp_share_max", worst);
}

/* -- failures --------------------------------------------------------------- */
typedef struct snap {
    vlbe_real t, h, y[6];
    int order;
} snap;
static void take(const vlbe_bdf *st, snap *s)
{
    s->t = st->t;
    s->h = st->h;
    s->order = st->order;
    memcpy(s->y, st->q, 6 * sizeof(vlbe_real)); /* q v lambda mu contiguous */
}
static void same(const vlbe_bdf *st, const snap *s)
{
    assert_true(st->t == s->t && st->h == s->h && st->order == s->order);
    assert_memory_equal(st->q, s->y, 6 * sizeof(vlbe_real));
    assert_true(st->q + 2 == st->v && st->v + 2 == st->lambda && st->lambda + 1 == st->mu);
}

/* A NaN force mid-run: ENONFINITE after the retries with smaller steps, the
   state (and the history: the run resumes and ends where a clean run ends)
   untouched. */
static void test_fail_nonfinite(void **state)
{
    faulty c;
    vlbe_dae s = pend_sys(&c);
    vlbe_bdf_params p;
    vlbe_bdf st;
    snap sn;
    vlbe_real ref[4];
    long rej, cap;
    int i;
    (void)state;
    vlbe_bdf_params_default(&p);
    p.rtol = p.atol = (vlbe_real)(100.0 * run_rtol());
    cap = step_cap(1.0, pend_floor((double)p.rtol));
    assert_int_equal(pend_init(&st, &s, &p), VLBE_OK);
    assert_int_equal(advance_capped(&st, VLBE_R(1.0), cap), VLBE_OK);
    for (i = 0; i < 4; ++i) ref[i] = st.q[i];
    assert_int_equal(pend_init(&st, &s, &p), VLBE_OK);
    assert_int_equal(advance_capped(&st, VLBE_R(0.4), cap), VLBE_OK);
    take(&st, &sn);
    rej = st.stats.rejected;
    c.mode = 1; /* NaN force from now on */
    assert_int_equal(vlbe_bdf_step(&st, VLBE_R(1.0)), VLBE_ENONFINITE);
    same(&st, &sn);
    assert_true(st.stats.rejected > rej && st.stats.newton_fails > 0);
    c.mode = 0;
    assert_int_equal(advance_capped(&st, VLBE_R(1.0), cap), VLBE_OK);
    assert_true(st.t == VLBE_R(1.0));
    /* not bitwise (the retried step rebuilt the Jacobian), but to the
       tolerance */
    for (i = 0; i < 4; ++i) ASSERT_CLOSE(st.q[i], ref[i], 0.0, 100.0 * (double)p.rtol);
    /* non-finite initial values */
    {
        vlbe_real q0[2], v0[2];
        pend_initial(&c.p, q0, v0);
        q0[1] = (vlbe_real)NAN;
        assert_int_equal(vlbe_bdf_init(&st, &s, &p, VLBE_R(0.0), q0, v0, g_work, WLEN, g_iwork, 64),
                         VLBE_ENONFINITE);
    }
}

static void test_fail_callback(void **state)
{
    faulty c;
    vlbe_dae s = pend_sys(&c);
    vlbe_bdf_params p;
    vlbe_bdf st;
    snap sn;
    long cap;
    (void)state;
    vlbe_bdf_params_default(&p);
    cap = step_cap(1.3, pend_floor((double)p.rtol));
    assert_int_equal(pend_init(&st, &s, &p), VLBE_OK);
    assert_int_equal(advance_capped(&st, VLBE_R(0.3), cap), VLBE_OK);
    take(&st, &sn);
    c.mode = 2; /* force reports failure */
    assert_int_equal(vlbe_bdf_step(&st, VLBE_R(1.0)), VLBE_ECALLBACK);
    same(&st, &sn);
    c.mode = 4; /* constraint reports failure */
    assert_int_equal(advance_capped(&st, VLBE_R(1.0), cap), VLBE_ECALLBACK);
    same(&st, &sn);
    c.mode = 0;
    assert_int_equal(advance_capped(&st, VLBE_R(1.0), cap), VLBE_OK);
    /* one Newton iterate outside the callback's domain (+1 once): the
       attempt fails like a Newton divergence, the step is retried smaller
       and the run goes on; the same fault as -1 is fatal */
    c.mode = 5;
    c.after = 1;
    c.count = 1;
    c.calls = 0;
    st.stats.rejected = 0;
    assert_int_equal(advance_capped(&st, VLBE_R(1.3), cap), VLBE_OK);
    assert_true(st.stats.rejected >= 1);
    assert_int_equal(st.stats.callback_rc, 1);
    take(&st, &sn);
    c.mode = 6;
    c.after = 0; /* the first call: in float one iteration may already converge */
    c.calls = 0;
    assert_int_equal(vlbe_bdf_step(&st, VLBE_R(2.0)), VLBE_ECALLBACK);
    assert_int_equal(st.stats.callback_rc, -1);
    same(&st, &sn);
    /* at init (consistent start) */
    c.mode = 2;
    c.count = 0;
    assert_int_equal(pend_init(&st, &s, &p), VLBE_ECALLBACK);
}

/* h_min far above what the tolerance allows: VLBE_ESTEP on the first error
   test failure that would go below it; state at the last accepted step. */
static void test_fail_hmin(void **state)
{
    faulty c;
    vlbe_dae s = pend_sys(&c);
    vlbe_bdf_params p;
    vlbe_bdf st;
    snap sn;
    vlbe_status rc = VLBE_OK;
    long n = 0;
    (void)state;
    vlbe_bdf_params_default(&p);
    p.rtol = p.atol = (vlbe_real)(100.0 * run_rtol());
    p.h_min = VLBE_R(0.05);
    assert_int_equal(pend_init(&st, &s, &p), VLBE_OK);
    take(&st, &sn);
    /* cap: steps of at least h_min (asserted) */
    while (st.t < VLBE_R(2.0)) {
        cap_check(++n, step_cap(2.0, (double)p.h_min), &st);
        take(&st, &sn);
        if ((rc = vlbe_bdf_step(&st, VLBE_R(2.0))) != VLBE_OK) break;
        assert_true(st.h_last >= p.h_min);
    }
    assert_int_equal(rc, VLBE_ESTEP);
    same(&st, &sn);
    assert_true(st.stats.rejected > 0);
}

static void test_fail_work_and_args(void **state)
{
    faulty c;
    vlbe_dae s = pend_sys(&c);
    vlbe_bdf_params p;
    vlbe_bdf st;
    vlbe_real q0[2], v0[2];
    size_t lw = vlbe_bdf_work_len(2, 1), liw = vlbe_bdf_iwork_len(2, 1);
    (void)state;
    pend_initial(&c.p, q0, v0);
    vlbe_bdf_params_default(&p);
    assert_int_equal(vlbe_bdf_init(&st, &s, &p, VLBE_R(0.0), q0, v0, g_work, lw - 1, g_iwork, liw),
                     VLBE_EWORK);
    assert_int_equal(vlbe_bdf_init(&st, &s, &p, VLBE_R(0.0), q0, v0, g_work, lw, g_iwork, liw - 1),
                     VLBE_EWORK);
    assert_int_equal(vlbe_bdf_init(&st, &s, &p, VLBE_R(0.0), q0, v0, NULL, lw, g_iwork, liw),
                     VLBE_EWORK);
    /* the exact lengths are enough; the workspace is all that is used
       (canaries around it stay intact) */
    {
        const long cap = step_cap(0.5, pend_floor((double)p.rtol));
        size_t i;
        for (i = 0; i < WLEN; ++i) g_work[i] = (vlbe_real)-777.0;
        for (i = 0; i < 64; ++i) g_iwork[i] = -777;
        assert_int_equal(vlbe_bdf_init(&st, &s, &p, VLBE_R(0.0), q0, v0, g_work + 1, lw, g_iwork + 1,
                                       liw),
                         VLBE_OK);
        assert_int_equal(advance_capped(&st, VLBE_R(0.5), cap), VLBE_OK);
        assert_true(g_work[0] == (vlbe_real)-777.0 && g_work[lw + 1] == (vlbe_real)-777.0);
        assert_true(g_iwork[0] == -777 && g_iwork[liw + 1] == -777);
        /* t_stop / t_out behind t (no step taken) */
        assert_int_equal(vlbe_bdf_step(&st, VLBE_R(0.5)), VLBE_EARG);
        assert_int_equal(vlbe_bdf_advance(&st, VLBE_R(0.25)), VLBE_EARG);
        assert_int_equal(vlbe_bdf_advance(&st, VLBE_R(0.5)), VLBE_OK); /* t_out == t */
    }
    p.rtol = p.atol = VLBE_R(0.0);
    assert_int_equal(pend_init(&st, &s, &p), VLBE_EARG);
    vlbe_bdf_params_default(&p);
    p.fixed_step = 1; /* needs h0 */
    assert_int_equal(pend_init(&st, &s, &p), VLBE_EARG);
    vlbe_bdf_params_default(&p);
    p.newton_max = 0;
    assert_int_equal(pend_init(&st, &s, &p), VLBE_EARG);
}

/* advance lands on each output time exactly, step never passes t_stop.
   vlbe_bdf_advance itself is under test here: h_min = 1e-6 s, 100 times
   below pend_floor of the default rtol and below the first step (1e-3 of
   the span), turns steps that shrink into VLBE_ESTEP instead of a hang. */
static void test_advance_exact(void **state)
{
    faulty c;
    vlbe_dae s = pend_sys(&c);
    vlbe_bdf_params p;
    vlbe_bdf st;
    long n = 0, cap;
    int i;
    (void)state;
    vlbe_bdf_params_default(&p);
    p.h_min = VLBE_R(1e-6);
    cap = step_cap(0.5, pend_floor((double)p.rtol));
    assert_int_equal(pend_init(&st, &s, &p), VLBE_OK);
    for (i = 1; i <= 20; ++i) {
        vlbe_real tout = (vlbe_real)(0.0123 * i);
        assert_int_equal(vlbe_bdf_advance(&st, tout), VLBE_OK);
        assert_true(st.t == tout);
    }
    while (st.t < VLBE_R(0.5)) {
        cap_check(++n, cap, &st);
        assert_int_equal(vlbe_bdf_step(&st, VLBE_R(0.5)), VLBE_OK);
        assert_true(st.t <= VLBE_R(0.5));
    }
    assert_true(st.t == VLBE_R(0.5));
}

/* -- a stiff spring on a spinning arm --------------------------------------
   Point 1 (1 kg) is the tip of an arm of length 1 m turned by the prescribed
   angle theta(t): x1 = cos theta, y1 = sin theta (two rheonomic
   constraints); point 2 (1 kg) hangs from point 1 on an undamped spring of
   stiffness 1e6 N/m and rest length 1 m (1000 rad/s, 1e3 times the slow
   swing).  theta' rises smoothly from 0 to 2 pi rad/s in 2 s as in
   scenes/ex_spin.h, then stays; the run ends at 4 s.  q = (x1, y1, x2,
   y2), start at rest along +x (consistent: theta = theta' = 0).  What is
   compared: the angle of the spring against the arm at 4 s with the
   reference rs_reference() below (-1.7564598 (m:rs_ref) rad). */
#define RS_K 1e6
#define RS_W (2.0 * 3.14159265358979323846)
#define RS_TS 2.0
#define RS_T 4.0

static void rs_theta(double t, double *g)
{
    if (t <= RS_TS) {
        const double w = 2.0 * 3.14159265358979323846 / RS_TS, c = RS_W / RS_TS;
        g[0] = c * (0.5 * t * t + (cos(w * t) - 1.0) / (w * w));
        g[1] = c * (t - sin(w * t) / w);
    } else {
        g[0] = RS_W * (t - 0.5 * RS_TS);
        g[1] = RS_W;
    }
}
static int rs_mass(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v, vlbe_real *M)
{
    int i;
    (void)u, (void)t, (void)q, (void)v;
    for (i = 0; i < 16; ++i) M[i] = VLBE_R(0.0);
    M[0] = M[5] = M[10] = M[15] = VLBE_R(1.0);
    return 0;
}
/* spring force on point 2, f = -k (l - 1) e, and df/dq2 = -(k e e^T + k (l-1)/l (I - e e^T)) */
static void rs_spring(const vlbe_real *q, double *f, double *K)
{
    const double dx = (double)q[2] - (double)q[0], dy = (double)q[3] - (double)q[1];
    const double l = sqrt(dx * dx + dy * dy), ex = dx / l, ey = dy / l, s = RS_K * (l - 1.0) / l;
    f[0] = -s * dx;
    f[1] = -s * dy;
    K[0] = -(RS_K * ex * ex + s * (1.0 - ex * ex));
    K[1] = K[2] = -(RS_K - s) * ex * ey;
    K[3] = -(RS_K * ey * ey + s * (1.0 - ey * ey));
}
static int rs_force(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v, vlbe_real *Q)
{
    double f[2], K[4];
    (void)u, (void)t, (void)v;
    rs_spring(q, f, K);
    Q[0] = (vlbe_real)-f[0];
    Q[1] = (vlbe_real)-f[1];
    Q[2] = (vlbe_real)f[0];
    Q[3] = (vlbe_real)f[1];
    return 0;
}
static int rs_fjac(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v, vlbe_real *K,
                   vlbe_real *D)
{
    double f[2], k[4];
    int i, j;
    (void)u, (void)t, (void)v;
    rs_spring(q, f, k);
    for (i = 0; i < 2; ++i)
        for (j = 0; j < 2; ++j) {
            const vlbe_real x = (vlbe_real)k[2 * i + j];
            K[i * 4 + j] = x;
            K[i * 4 + 2 + j] = -x;
            K[(2 + i) * 4 + j] = -x;
            K[(2 + i) * 4 + 2 + j] = x;
        }
    for (i = 0; i < 16; ++i) D[i] = VLBE_R(0.0);
    return 0;
}
static int rs_constr(void *u, vlbe_real t, const vlbe_real *q, vlbe_real *C)
{
    double g[2];
    (void)u;
    rs_theta((double)t, g);
    C[0] = (vlbe_real)((double)q[0] - cos(g[0]));
    C[1] = (vlbe_real)((double)q[1] - sin(g[0]));
    return 0;
}
static int rs_cjac(void *u, vlbe_real t, const vlbe_real *q, vlbe_real *Cq, vlbe_real *Ct)
{
    double g[2];
    int i;
    (void)u, (void)q;
    rs_theta((double)t, g);
    for (i = 0; i < 8; ++i) Cq[i] = VLBE_R(0.0);
    Cq[0] = Cq[5] = VLBE_R(1.0);
    if (Ct) {
        Ct[0] = (vlbe_real)(sin(g[0]) * g[1]);
        Ct[1] = (vlbe_real)(-cos(g[0]) * g[1]);
    }
    return 0;
}

/* The reference, independent of integrators.h: point 1 moves as prescribed,
   so point 2 (unit mass) alone obeys the ODE r2'' = -k (l - 1) (r2 - r1(t)) / l,
   l = |r2 - r1(t)|, r1 = (cos theta, sin theta), from (2, 0) at rest.  The
   classical Runge-Kutta method integrates it here in double, n steps of
   RS_T / n (stable for 1000 rad/s up to h = 2.8e-3); the angle of the
   spring against the arm at RS_T, in (-pi, pi]. */
static double rs_rk4(long n)
{
    const double h = RS_T / (double)n;
    double y[4] = {2.0, 0.0, 0.0, 0.0}, k[4][4], yt[4], g[2];
    long i;
    int j, sg;
    for (i = 0; i < n; ++i) {
        const double t = (double)i * h;
        for (sg = 0; sg < 4; ++sg) {
            /* stage sg at t + c h from y + c h k[sg - 1], c = 0, 1/2, 1/2, 1 */
            const double c = sg == 0 ? 0.0 : sg == 3 ? 1.0 : 0.5;
            double dx, dy, l, f;
            for (j = 0; j < 4; ++j) yt[j] = sg == 0 ? y[j] : y[j] + c * h * k[sg - 1][j];
            rs_theta(t + c * h, g);
            dx = yt[0] - cos(g[0]);
            dy = yt[1] - sin(g[0]);
            l = sqrt(dx * dx + dy * dy);
            f = -RS_K * (l - 1.0) / l;
            k[sg][0] = yt[2];
            k[sg][1] = yt[3];
            k[sg][2] = f * dx;
            k[sg][3] = f * dy;
        }
        for (j = 0; j < 4; ++j)
            y[j] += h / 6.0 * (k[0][j] + 2.0 * k[1][j] + 2.0 * k[2][j] + k[3][j]);
    }
    rs_theta(RS_T, g);
    return remainder(atan2(y[1] - sin(g[0]), y[0] - cos(g[0])) - g[0],
                     2.0 * 3.14159265358979323846);
}

/* RK4 at h = 2e-4 and 1e-4 s (omega h = 0.2, 0.1 for the spring), once:
   their difference, 3.6e-8 (m:rs_rk4_diff) rad, is 15 times the error of the
   finer run (fourth order), which the Richardson value removes; held to
   1e-6 rad, far below the 5e-3 .. 0.1 rad of the BDF checks. */
static double rs_reference(void)
{
    static double ref = 0.0;
    static int done = 0;
    if (!done) {
        const double a1 = rs_rk4(20000), a2 = rs_rk4(40000);
        tu_measured("rs_rk4_diff", fabs(a2 - a1));
        assert_true(fabs(a2 - a1) <= 1e-6);
        ref = a2 + (a2 - a1) / 15.0;
        tu_measured("rs_ref", ref);
        done = 1;
    }
    return ref;
}

typedef struct rs_out {
    vlbe_status rc;
    double angle_err; /* |angle of the spring against the arm at RS_T - reference| */
    vlbe_dae_stats stats;
} rs_out;

/* One run to RS_T with p (gamma by central differences, C_q^T lambda
   Hessian zero by differences).  Step cap of the variable-step runs: 4e4,
   ten times the 3841 (m:rs_steps2) steps of the longest (rtol 1e-5). */
static void rs_run(const vlbe_bdf_params *p, rs_out *o)
{
    vlbe_dae s;
    vlbe_bdf st;
    const vlbe_real q0[4] = {VLBE_R(1.0), VLBE_R(0.0), VLBE_R(2.0), VLBE_R(0.0)};
    const vlbe_real v0[4] = {VLBE_R(0.0), VLBE_R(0.0), VLBE_R(0.0), VLBE_R(0.0)};
    memset(&s, 0, sizeof s);
    s.n = 4;
    s.m = 2;
    s.flags = VLBE_DAE_MASS_CONST;
    s.mass = rs_mass;
    s.force = rs_force;
    s.force_jac = rs_fjac;
    s.constr = rs_constr;
    s.constr_jac = rs_cjac;
    assert_true(vlbe_bdf_work_len(4, 2) <= WLEN);
    o->rc = vlbe_bdf_init(&st, &s, p, VLBE_R(0.0), q0, v0, g_work, WLEN, g_iwork, 64);
    assert_int_equal(o->rc, VLBE_OK);
    if (p->fixed_step) {
        long k, nsteps = (long)floor(RS_T / (double)p->h0 + 0.5);
        for (k = 0; k < nsteps; ++k)
            if ((o->rc = vlbe_bdf_step(&st, (vlbe_real)1e30)) != VLBE_OK) break;
    } else {
        long n = 0;
        while (st.t < (vlbe_real)RS_T) {
            cap_check(++n, 40000, &st);
            if ((o->rc = vlbe_bdf_step(&st, (vlbe_real)RS_T)) != VLBE_OK) break;
        }
    }
    {
        double g[2];
        const double a =
            atan2((double)st.q[3] - (double)st.q[1], (double)st.q[2] - (double)st.q[0]);
        rs_theta((double)st.t, g);
        o->angle_err =
            fabs(remainder(a - g[0] - rs_reference(), 2.0 * 3.14159265358979323846));
    }
    o->stats = st.stats;
}

/* Fixed step h = 1e-3 (w h = 1 for the spring), BDF2: the iteration matrix
   is kept while the iteration converges; the arm turns the spring (12 rad
   in 4 s) and with it the stiff direction, so that the true rate of the
   iteration with a stored matrix passes 1 within a fraction of a radian.
   With the rate of the step that formed the matrix carried on (DASSL),
   every step "converges" in one iteration on it (a handful of LU in 4000
   steps) and the spring angle ends about 3 rad off; with the rate taken
   afresh at every step the run is within 5.1e-3 (m:stale_err) rad of the
   reference (BDF2's own error at this h; 500 (m:stale_lu) LU).  Asserted:
   0.02 rad.  Double only: in float the spring length 1 + 1e-4 m carries
   2e-7 m of rounding, 0.3 % of its force, and the Newton iteration stalls
   at that level (ENOCONV, and a fixed step has no smaller step to retry
   with); the variable-step runs below retry. */
static void test_stale_rate(void **state)
{
    vlbe_bdf_params p;
    rs_out o;
    (void)state;
#ifdef VLBE_USE_FLOAT
    TU_SKIP("the fixed-step Newton iteration stalls on the float rounding of the spring length");
#endif
    vlbe_bdf_params_default(&p);
    p.rtol = p.atol = VLBE_R(1e-3);
    p.max_order = 2;
    p.fixed_step = 1;
    p.h0 = VLBE_R(1e-3);
    rs_run(&p, &o);
    print_message("spinning spring, fixed h 1e-3, BDF2: angle err %.2e rad, %ld steps, "
                  "%ld Newton, %ld LU\n",
                  o.angle_err, o.stats.steps, o.stats.newton_iters, o.stats.lu_factors);
    tu_report("spinning spring, fixed h 1e-3, BDF2: angle error [rad]", o.angle_err, 0.02);
    tu_measured("stale_err", o.angle_err);
    tu_measured("stale_lu", (double)o.stats.lu_factors);
    assert_int_equal(o.rc, VLBE_OK);
    assert_true(o.angle_err <= 0.02);
}

/* Variable step, BDF2 (max_order 2: the spring is undamped), rtol = atol
   1e-3, 1e-4 (and 1e-5 in double).  With the filtered estimate:
   729 (m:rs_steps0), 1788 (m:rs_steps1), 3841 (m:rs_steps2) steps with
   6 (m:rs_rej0), 2 (m:rs_rej1), 8 (m:rs_rej2) rejected, angle errors
   4.2e-2 (m:rs_err0), 6.6e-3 (m:rs_err1), 1.2e-3 (m:rs_err2).  The plain
   estimate (stiff_filter 0) at 1e-3: 1485 (m:rs_plain_steps) steps,
   1123 (m:rs_plain_rej) rejected (76 (m:rs_plain_pct) %), error
   0.10 (m:rs_plain_err); with the stale Newton rate of test_stale_rate as
   well, the errors are tenths of a radian and do not fall with the
   tolerance.  Asserted: at most 5 % rejected, errors below 0.1, 0.02, 0.005
   rad (float: 0.1, 0.05; 3.9e-2 (m@flt:rs_err0), 1.6e-2 (m@flt:rs_err1):
   the spring length 1 + 1e-4 m carries 2e-7 m of rounding), fewer than
   1200 steps at 1e-3; and the plain estimate's cascade (> 30 % rejected;
   float: 54 (m@flt:rs_plain_pct) %) at 1e-3, the behaviour the filter
   exists for. */
static void test_spinning_spring(void **state)
{
    static const double tol[3] = {1e-3, 1e-4, 1e-5}, bound[3] = {0.1, 0.02, 0.005};
    static const char *const key[3][3] = {{"rs_steps0", "rs_rej0", "rs_err0"},
                                          {"rs_steps1", "rs_rej1", "rs_err1"},
                                          {"rs_steps2", "rs_rej2", "rs_err2"}};
    const int ntol = EPS < 1e-10 ? 3 : 2; /* float: rtol >= 100 eps */
    const double bound1 = EPS < 1e-10 ? bound[1] : 0.05;
    vlbe_bdf_params p;
    rs_out o;
    int i;
    (void)state;
    for (i = 0; i < ntol; ++i) {
        vlbe_bdf_params_default(&p);
        p.rtol = p.atol = (vlbe_real)tol[i];
        p.max_order = 2;
        rs_run(&p, &o);
        print_message("spinning spring, rtol %.0e, BDF2: angle err %.2e rad, %ld steps, "
                      "%ld rejected, %ld Newton, %ld LU\n",
                      tol[i], o.angle_err, o.stats.steps, o.stats.rejected,
                      o.stats.newton_iters, o.stats.lu_factors);
        tu_report("spinning spring, BDF2: angle error [rad]", o.angle_err,
                  i == 1 ? bound1 : bound[i]);
        tu_report("spinning spring, BDF2: rejected / steps", (double)o.stats.rejected /
                  (double)o.stats.steps, 0.05);
        tu_measured(key[i][0], (double)o.stats.steps);
        tu_measured(key[i][1], (double)o.stats.rejected);
        tu_measured(key[i][2], o.angle_err);
        assert_int_equal(o.rc, VLBE_OK);
        assert_true(o.angle_err <= (i == 1 ? bound1 : bound[i]));
        assert_true(20 * o.stats.rejected <= o.stats.steps);
        if (i == 0) assert_true(o.stats.steps < 1200);
    }
    vlbe_bdf_params_default(&p);
    p.rtol = p.atol = VLBE_R(1e-3);
    p.max_order = 2;
    p.stiff_filter = 0;
    rs_run(&p, &o);
    print_message("spinning spring, rtol 1e-3, BDF2, plain estimate: angle err %.2e rad, "
                  "%ld steps, %ld rejected\n",
                  o.angle_err, o.stats.steps, o.stats.rejected);
    tu_measured("rs_plain_steps", (double)o.stats.steps);
    tu_measured("rs_plain_rej", (double)o.stats.rejected);
    tu_measured("rs_plain_pct", (double)(100 * o.stats.rejected) / (double)o.stats.steps);
    tu_measured("rs_plain_err", o.angle_err);
    assert_int_equal(o.rc, VLBE_OK);
    assert_true(10 * o.stats.rejected > 3 * o.stats.steps);
    /* stiff_filter is 0 or 1 */
    p.stiff_filter = 2;
    {
        vlbe_bdf st;
        vlbe_dae s;
        faulty c;
        s = pend_sys(&c);
        assert_int_equal(pend_init(&st, &s, &p), VLBE_EARG);
    }
}

/* -- Andrews' squeezing mechanism (7 bodies, 6 constraints) -----------------
   Against the Test Set reference at t = 0.03 s (PSIDE, rtol 1e-14), with the
   analytic Jacobians and with finite differences.  Double only: in float the
   time itself carries 2e-9 absolute rounding at t ~ 0.02 while the steps are
   ~1e-6 (a 1e-3 relative error in every step size), and rtol cannot go below
   ~1e-5; float runs stop with ENOCONV / ESTEP, never with a wrong answer.
   Step cap: 2.2e4, ten times the 2.1e3 (m:andr_steps) steps of the run
   (analytic Jacobians; the differences take a few more). */
#ifndef VLBE_USE_FLOAT
#include "../scenes/andrews.h"
#endif

static void test_andrews(void **state)
{
#ifndef VLBE_USE_FLOAT
    static vlbe_real w[8192];
    static int iw[64];
    double y1 = 0.0, y7 = 0.0, qw = 0.0;
    int fd, i;
    (void)state;
    assert_true(vlbe_bdf_work_len(ANDR_N, ANDR_M) <= 8192);
    for (fd = 0; fd < 2; ++fd) {
        andr_par P = andr_default();
        vlbe_dae s;
        vlbe_bdf_params p;
        vlbe_bdf st;
        vlbe_real q0[ANDR_N], v0[ANDR_N];
        if (fd) andr_setup_fd(&s, &P);
        else andr_setup(&s, &P);
        andr_initial(q0, v0);
        vlbe_bdf_params_default(&p);
        p.rtol = p.atol = VLBE_R(1e-10);
        assert_int_equal(vlbe_bdf_init(&st, &s, &p, VLBE_R(0.0), q0, v0, w, 8192, iw, 64), VLBE_OK);
        /* consistent start: the Test Set's multipliers */
        for (i = 0; i < ANDR_M; ++i) ASSERT_CLOSE(st.lambda[i], andr_lambda0()[i], 1e-9, 1e-9);
        assert_int_equal(advance_capped(&st, (vlbe_real)ANDR_T_END, 22000), VLBE_OK);
        if (!fd) tu_measured("andr_steps", (double)st.stats.steps);
        print_message("andrews (%s): y1 rel.err %.2e, y7 rel.err %.2e, %ld steps, %ld rejected, "
                      "%ld Newton, %ld Jacobians, %ld LU, %ld force calls\n",
                      fd ? "differences" : "analytic",
                      fabs((double)st.q[0] - andr_qref()[0]) / fabs(andr_qref()[0]),
                      fabs((double)st.q[6] - andr_qref()[6]) / fabs(andr_qref()[6]),
                      st.stats.steps, st.stats.rejected, st.stats.newton_iters,
                      st.stats.jac_evals, st.stats.lu_factors, st.stats.force_calls);
        /* the worse of the two runs: y1 1.6e-10 (m:andr_y1) relative, y7
           6.9e-13 (m:andr_y7), all angles within 6e-10 (m:andr_qmax)
           relative */
        y1 = fmax(y1, fabs((double)st.q[0] - andr_qref()[0]) / fabs(andr_qref()[0]));
        y7 = fmax(y7, fabs((double)st.q[6] - andr_qref()[6]) / fabs(andr_qref()[6]));
        for (i = 0; i < ANDR_N; ++i)
            qw = fmax(qw, fabs((double)st.q[i] - andr_qref()[i]) / fabs(andr_qref()[i]));
        tu_report("Andrews, BDF rtol 1e-10: max relative error of q", qw, 1e-7);
        ASSERT_VEC_CLOSE(st.q, andr_qref(), ANDR_N, 1e-7, 0.0);
        ASSERT_CLOSE(st.q[0], andr_qref()[0], 1e-8, 0.0);
        ASSERT_CLOSE(st.q[6], andr_qref()[6], 1e-8, 0.0);
        /* velocities (|v| up to 1.4e3 rad/s) and the index-2 multipliers */
        ASSERT_VEC_CLOSE(st.v, andr_vref(), ANDR_N, 1e-5, 0.0);
        ASSERT_VEC_CLOSE(st.lambda, andr_lambda_ref(), ANDR_M, 1e-4, 0.0);
    }
    tu_measured("andr_y1", y1);
    tu_measured("andr_y7", y7);
    tu_measured("andr_qmax", qw);
#else
    (void)state;
    TU_SKIP("the float time carries 1e-3 of the steps (~1e-6 s) at t ~ 0.02 s");
#endif
}


/* -- a start off the constraint -----------------------------------------------
   The pendulum released at rest from (L + d, 0), d = 100 tol off the circle
   (1e-8 at rtol = atol = tol = 1e-10 in double; float: tol = 100 eps).
   project = 0: the corrector closes the gap d within the first step, so the
   error estimate holds the jump d whatever h (weighted RMS over q and v
   about d / (2 (atol + rtol L)) / 2 = 12 against 1): every attempt fails,
   h falls by 4 per failure, and the step ends below the minimum:
   VLBE_ESTEP, t and the state as at init.  project = 1 (default): init
   starts from the projection (L, 0) and the run keeps |C| within 10 tol
   (test_pendulum_period's bound).  A gap of tol / 1000 is below the
   threshold of vlbe_bdf_init (a correction of weighted norm 0.1): the run
   is the one without projection, bit for bit. */
static double start_tol(void) { return EPS < 1e-10 ? 1e-10 : 100.0 * EPS; }

static void test_start_projection(void **state)
{
    faulty c;
    vlbe_dae s = pend_sys(&c);
    vlbe_bdf_params p;
    vlbe_bdf st;
    vlbe_real q0[2], v0[2] = {VLBE_R(0.0), VLBE_R(0.0)};
    const double tol = start_tol(), span = 2.0;
    double maxc = 0.0;
    long n = 0;
    vlbe_status rc;
    (void)state;
    vlbe_bdf_params_default(&p);
    assert_int_equal(p.project, 1);
    p.rtol = p.atol = (vlbe_real)tol;
    q0[0] = (vlbe_real)(PEND_L + 100.0 * tol);
    q0[1] = VLBE_R(0.0);
    /* the defect without projection */
    p.project = 0;
    assert_int_equal(vlbe_bdf_init(&st, &s, &p, VLBE_R(0.0), q0, v0, g_work, WLEN, g_iwork, 64),
                     VLBE_OK);
    rc = vlbe_bdf_step(&st, (vlbe_real)span);
    print_message("start 100 tol off, project 0: %s after %ld rejected attempts\n",
                  vlbe_status_str(rc), st.stats.rejected);
    assert_int_equal(rc, VLBE_ESTEP);
    assert_true(st.stats.rejected >= 5 && st.t == VLBE_R(0.0) && st.stats.steps == 0);
    assert_true(st.q[0] == q0[0] && st.q[1] == q0[1]);
    /* with it */
    p.project = 1;
    assert_int_equal(vlbe_bdf_init(&st, &s, &p, VLBE_R(0.0), q0, v0, g_work, WLEN, g_iwork, 64),
                     VLBE_OK);
    assert_true(q0[0] == (vlbe_real)(PEND_L + 100.0 * tol)); /* the caller's start: not written */
    /* the start is the projection: |C| at rounding */
    assert_true(fabs(0.5 * ((double)st.q[0] * (double)st.q[0] - PEND_L * PEND_L)) <= 100.0 * EPS);
    while (st.t < (vlbe_real)span) {
        double x, y;
        cap_check(++n, step_cap(span, pend_floor(tol)), &st);
        assert_int_equal(vlbe_bdf_step(&st, (vlbe_real)span), VLBE_OK);
        x = (double)st.q[0];
        y = (double)st.q[1];
        maxc = fmax(maxc, fabs(0.5 * (x * x + y * y - PEND_L * PEND_L)));
    }
    print_message("start 100 tol off, project 1: %ld steps, %ld rejected, max |C| %.2e\n",
                  st.stats.steps, st.stats.rejected, maxc);
    tu_report("start off the constraint, projected: max |C|", maxc, 10.0 * tol);
    assert_true(maxc <= 10.0 * tol);
    /* a gap the first step absorbs: project 0 and 1 run alike, bit for bit */
    {
        static vlbe_real w2[WLEN];
        static int iw2[64];
        vlbe_bdf st2;
        int k;
        q0[0] = (vlbe_real)(PEND_L + 1e-3 * tol);
        if (q0[0] == (vlbe_real)PEND_L) q0[0] = (vlbe_real)PEND_L + (vlbe_real)PEND_L * VLBE_EPS;
        assert_int_equal(vlbe_bdf_init(&st, &s, &p, VLBE_R(0.0), q0, v0, g_work, WLEN, g_iwork, 64),
                         VLBE_OK);
        p.project = 0;
        assert_int_equal(vlbe_bdf_init(&st2, &s, &p, VLBE_R(0.0), q0, v0, w2, WLEN, iw2, 64),
                         VLBE_OK);
        for (k = 0; k < 50; ++k) {
            assert_int_equal(vlbe_bdf_step(&st, (vlbe_real)span), VLBE_OK);
            assert_int_equal(vlbe_bdf_step(&st2, (vlbe_real)span), VLBE_OK);
            assert_true(st.t == st2.t);
            assert_memory_equal(st.q, st2.q, 6 * sizeof(vlbe_real)); /* q v lambda mu */
        }
        /* the projection's calls are counted */
        assert_true(st.stats.constr_calls > st2.stats.constr_calls);
    }
    p.project = 2;
    assert_int_equal(pend_init(&st, &s, &p), VLBE_EARG);
}

/* -- per-coordinate absolute tolerances --------------------------------------
   Two decoupled undamped oscillators, q1'' = -q1 and q2'' = -(1.5)^2 q2,
   released at rest from q1 = 1 (a position in m) and q2 = 1e-5 (a modal
   amplitude): q1 = cos t, q2 = 1e-5 cos(1.5 t), run to t = 20 s.  rtol =
   1e-6 (float 1e-4), scalar atol = rtol / 100: the weight of q2, atol +
   rtol |q2| ~ atol, is 1e3 times its size times rtol, so the error test
   controls q2 only absolutely, at ~atol, which is 1e-3 of its amplitude.
   With atolv = (atol, 1e-5 atol, atol, 1.5e-5 atol) (q2 and its velocity
   scaled by their amplitudes) q2 is controlled at rtol relative as q1 is.
   Yardstick: e1, q1's largest error over the run with scalar atol (what
   rtol-relative control gives on this problem).  atolv: q2's largest
   error relative to 1e-5 within 2 e1 (0.88 (m:atolv_ratio) e1 in double);
   scalar: more than 5 e1 (11.5 (m:scalar_ratio) e1); the steps: at most
   twice the scalar
   run's (q2 turns 1.5 times faster: equal relative accuracy per radian
   takes 1.5 times the steps). */
static double g_w2;
static int osc2_mass(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v, vlbe_real *M)
{
    (void)u, (void)t, (void)q, (void)v;
    M[0] = M[3] = VLBE_R(1.0);
    M[1] = M[2] = VLBE_R(0.0);
    return 0;
}
static int osc2_force(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v, vlbe_real *Q)
{
    (void)u, (void)t, (void)v;
    Q[0] = -q[0];
    Q[1] = -(vlbe_real)(g_w2 * g_w2) * q[1];
    return 0;
}
typedef struct osc2_out {
    double e1, e2; /* max |q1 - cos t|, max |q2 - 1e-5 cos(w2 t)| / 1e-5 */
    long steps;
} osc2_out;
static void osc2_run(const vlbe_bdf_params *p, osc2_out *o)
{
    vlbe_dae s;
    vlbe_bdf st;
    const vlbe_real q0[2] = {VLBE_R(1.0), VLBE_R(1e-5)}, v0[2] = {VLBE_R(0.0), VLBE_R(0.0)};
    const double T = 20.0;
    long n = 0;
    memset(&s, 0, sizeof s);
    s.n = 2;
    s.flags = VLBE_DAE_MASS_CONST;
    s.mass = osc2_mass;
    s.force = osc2_force;
    assert_int_equal(vlbe_bdf_init(&st, &s, p, VLBE_R(0.0), q0, v0, g_work, WLEN, g_iwork, 64),
                     VLBE_OK);
    o->e1 = o->e2 = 0.0;
    while (st.t < (vlbe_real)T) {
        double t;
        /* cap: BDF1 at rtol 1e-6 would keep h ~ sqrt(2 rtol) = 1.4e-3 s */
        cap_check(++n, step_cap(T, 1e-3), &st);
        assert_int_equal(vlbe_bdf_step(&st, (vlbe_real)T), VLBE_OK);
        t = (double)st.t;
        o->e1 = fmax(o->e1, fabs((double)st.q[0] - cos(t)));
        o->e2 = fmax(o->e2, fabs((double)st.q[1] - 1e-5 * cos(g_w2 * t)) / 1e-5);
    }
    o->steps = st.stats.steps;
}
static void test_atolv(void **state)
{
    vlbe_bdf_params p;
    osc2_out sc, pv;
    vlbe_real av[4];
    const double rtol = EPS < 1e-10 ? 1e-6 : 1e-4;
    (void)state;
    g_w2 = 1.5;
    vlbe_bdf_params_default(&p);
    assert_true(p.atolv == NULL);
    p.rtol = (vlbe_real)rtol;
    p.atol = (vlbe_real)(rtol / 100.0);
    osc2_run(&p, &sc);
    av[0] = av[2] = p.atol;
    av[1] = (vlbe_real)(1e-5 * (double)p.atol);
    av[3] = (vlbe_real)(1.5e-5 * (double)p.atol);
    p.atolv = av;
    osc2_run(&p, &pv);
    print_message("atol scalar: q1 err %.2e, q2 rel.err %.2e, %ld steps; atolv: q1 %.2e, q2 "
                  "%.2e, %ld steps\n",
                  sc.e1, sc.e2, sc.steps, pv.e1, pv.e2, pv.steps);
    tu_report("atolv: q2 relative error / scalar run's q1 error", pv.e2 / sc.e1, 2.0);
    tu_measured("atolv_ratio", pv.e2 / sc.e1);
    tu_measured("scalar_ratio", sc.e2 / sc.e1);
    assert_true(pv.e2 <= 2.0 * sc.e1);
    assert_true(sc.e2 > 5.0 * sc.e1);
    assert_true(pv.steps <= 2 * sc.steps);
    /* invalid entries */
    {
        vlbe_bdf st;
        vlbe_dae s;
        const vlbe_real q0[2] = {VLBE_R(1.0), VLBE_R(0.0)}, v0[2] = {VLBE_R(0.0), VLBE_R(0.0)};
        memset(&s, 0, sizeof s);
        s.n = 2;
        s.mass = osc2_mass;
        s.force = osc2_force;
        av[1] = VLBE_R(-1e-9);
        assert_int_equal(vlbe_bdf_init(&st, &s, &p, VLBE_R(0.0), q0, v0, g_work, WLEN, g_iwork, 64),
                         VLBE_EARG);
        av[1] = (vlbe_real)NAN;
        assert_int_equal(vlbe_bdf_init(&st, &s, &p, VLBE_R(0.0), q0, v0, g_work, WLEN, g_iwork, 64),
                         VLBE_EARG);
        av[1] = VLBE_R(0.0); /* with rtol 0 a zero weight */
        p.rtol = VLBE_R(0.0);
        assert_int_equal(vlbe_bdf_init(&st, &s, &p, VLBE_R(0.0), q0, v0, g_work, WLEN, g_iwork, 64),
                         VLBE_EARG);
    }
}

/* -- dense output -------------------------------------------------------------
   The oscillator q'' = -q (OSC_W = 1) from q = 1 at rest, variable step and
   order, rtol = atol = tol (1e-8; float 100 eps), to t = 10 s.  After each
   step, vlbe_bdf_interp at 7 points inside it (t_n - j h/8) against q =
   cos t, v = -sin t.  The interpolant's error is that of the solution
   points plus the interpolation error of the last k + 1 points, which is
   of the size of the local error the error test bounds (the predictor's
   extrapolation error of the same polynomial family, e = y - y_pred, is
   held to ck |e| <= 1 in the weighted norm, and the interpolation error
   inside the step is smaller than the extrapolation error beyond it):
   asserted
       |y(t) - exact| <= max(err at t_{n-1}, err at t_n) + (atol + rtol |y|),
   the excess over the solution points' error within one weight (the
   largest ratio is reported: 0.006 (m~:interp_excess) in double, 0.06
   (m@flt~:interp_excess) in float, the first
   steps of order 1 and 2 the largest).  At t_n the state itself, bit for
   bit. */
static void test_interp(void **state)
{
    vlbe_dae s;
    vlbe_bdf_params p;
    vlbe_bdf st;
    vlbe_real q0 = VLBE_R(1.0), v0 = VLBE_R(0.0), qi, vi, qo, vo;
    const double tol = EPS < 1e-10 ? 1e-8 : 100.0 * EPS, T = 10.0;
    double eprev = 0.0, worst = 0.0;
    long n = 0;
    int j;
    (void)state;
    memset(&s, 0, sizeof s);
    s.n = 1;
    s.flags = VLBE_DAE_MASS_CONST;
    s.mass = osc_mass;
    s.force = osc_force;
    s.force_jac = osc_fjac;
    vlbe_bdf_params_default(&p);
    p.rtol = p.atol = (vlbe_real)tol;
    assert_int_equal(vlbe_bdf_init(&st, &s, &p, VLBE_R(0.0), &q0, &v0, g_work, WLEN, g_iwork, 64),
                     VLBE_OK);
    /* before the first step: only t0 itself */
    assert_int_equal(vlbe_bdf_interp(&st, VLBE_R(0.0), &qi, &vi), VLBE_OK);
    assert_true(qi == q0 && vi == v0);
    assert_int_equal(vlbe_bdf_interp(&st, VLBE_R(-1e-3), &qi, &vi), VLBE_EARG);
    while (st.t < (vlbe_real)T) {
        double en, bound;
        cap_check(++n, step_cap(T, pend_floor(tol)), &st);
        assert_int_equal(vlbe_bdf_step(&st, (vlbe_real)T), VLBE_OK);
        en = fmax(fabs((double)st.q[0] - cos((double)st.t)),
                  fabs((double)st.v[0] + sin((double)st.t)));
        bound = fmax(eprev, en);
        for (j = 1; j < 8; ++j) {
            const vlbe_real t = st.t - st.h_last * (vlbe_real)j / VLBE_R(8.0);
            double eq, ev, w;
            assert_int_equal(vlbe_bdf_interp(&st, t, &qi, &vi), VLBE_OK);
            eq = fabs((double)qi - cos((double)t));
            ev = fabs((double)vi + sin((double)t));
            w = tol * (1.0 + fmax(fabs((double)qi), fabs((double)vi)));
            worst = fmax(worst, (fmax(eq, ev) - bound) / w);
            if (!(fmax(eq, ev) <= bound + w))
                fail_msg("step %ld (order %d, h %.3g) at t = %.9g: interpolant error %.3g, "
                         "bound %.3g",
                         n, st.order_last, (double)st.h_last, (double)t, fmax(eq, ev),
                         bound + w);
            /* either output alone: the same value */
            assert_int_equal(vlbe_bdf_interp(&st, t, NULL, &vo), VLBE_OK);
            assert_int_equal(vlbe_bdf_interp(&st, t, &qo, NULL), VLBE_OK);
            assert_true(qo == qi && vo == vi);
        }
        eprev = en;
        /* the step's end: the state; the range's ends and outside */
        assert_int_equal(vlbe_bdf_interp(&st, st.t, &qi, &vi), VLBE_OK);
        assert_true(qi == st.q[0] && vi == st.v[0]);
        assert_int_equal(vlbe_bdf_interp(&st, st.t - st.h_last, &qi, &vi), VLBE_OK);
        assert_int_equal(vlbe_bdf_interp(&st, st.t + st.h_last / 64, &qi, &vi), VLBE_EARG);
        assert_int_equal(vlbe_bdf_interp(&st, st.t - st.h_last * VLBE_R(1.5), &qi, &vi),
                         VLBE_EARG);
    }
    assert_int_equal(vlbe_bdf_interp(&st, (vlbe_real)NAN, &qi, &vi), VLBE_EARG);
    print_message("dense output: %ld steps, interpolant error beyond the solution points' at "
                  "most %.2f (atol + rtol |y|)\n",
                  n, worst);
    tu_measured("interp_excess", worst);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_pendulum_period),
        cmocka_unit_test(test_pendulum_analytic_jacobians),
        cmocka_unit_test(test_pendulum_convergence),
        cmocka_unit_test(test_order_cap),
        cmocka_unit_test(test_oscillator_stability),
        cmocka_unit_test(test_bdf12_always_damp),
        cmocka_unit_test(test_fail_nonfinite),
        cmocka_unit_test(test_fail_callback),
        cmocka_unit_test(test_fail_hmin),
        cmocka_unit_test(test_fail_work_and_args),
        cmocka_unit_test(test_advance_exact),
        cmocka_unit_test(test_stale_rate),
        cmocka_unit_test(test_spinning_spring),
        cmocka_unit_test(test_andrews),
        cmocka_unit_test(test_start_projection),
        cmocka_unit_test(test_atolv),
        cmocka_unit_test(test_interp),
    };
    return cmocka_run_group_tests_name("bdf", tests, NULL, NULL);
}
