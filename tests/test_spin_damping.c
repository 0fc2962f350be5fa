/* test_spin_damping.c -- damping on relative coordinates in the spin-up
   scene (rotating-beam scene 3; examples/spin_damping.c, scenes/ex_spin.h
   SP_ANCF): Kelvin-Voigt damping from the strain rates against damping on
   the absolute nodal velocities, Q_d = -(abs_a M + abs_b K0) v.
   -- part of vlbe                                  SPDX-License-Identifier: MIT

   Tests
     kv_rigid_spin      a straight unstretched beam at angle theta moving
                        rigidly at W (v = W z x r at every node, slopes
                        too): the force with c_kv > 0 minus the force with
                        c_kv = 0, and its power v.Q_d, vanish to round-off;
                        a radial stretch v = W r at the same state costs
                        c_kv EA L W^2 (the check is not blind)
     abs_rigid_spin     the same motion: abs. M dissipates v.Q_d = -abs_a
                        v^T M v = -abs_a rhoA W^2 L^3/3; abs. K0 dissipates
                        nothing at theta = 0 and -abs_b EA L W^2
                        sin^2(theta) at theta != 0
     kv_equals_abs_at_rest  straight beam at rest: the Kelvin-Voigt damping
                        Jacobian D (force_jac, c_kv = c) equals the
                        absolute damping matrix with abs_b = c (m.Dabs)
     reference_closed_forms  the example's elastica reference (shooting)
                        against closed forms: linear cantilever under the
                        triangular drag 11 q0 L^4/(120 EI), spinning rod
                        tan(kL)/k - L
     scene_w6           the spin-up to W = 6 rad/s: abs. M settles to the
                        elastica's steady lag; Kelvin-Voigt to no lag (its
                        tip vibrates about 0 and less than undamped);
                        abs. K0 leaves the 2 m bound in the first 0.5 rad
   Round-off tolerances are multiples of VLBE_EPS times the size of the
   terms summed (stated in each test), so the float build checks them
   too, and the scene at W = 6 with the same bounds (the default Newton
   tolerances follow the precision).  Measured errors against tolerances:
   VLBE_TEST_REPORT=1. */
#include "test_util.h"
#include "../scenes/spin_damping.h"

#define TEPS ((double)VLBE_EPS) /* the working precision, as a double */

static sp_model g_m0, g_m1, g_mk; /* ~1 MB each: static */

/* the model of the scene with damping model kind (SD_*; W does not enter
   the forces); its settings in *c */
static void init_model(sp_model *m, int kind, sp_cfg *c)
{
    sd_cfg(c, 6.0, kind);
    assert_int_equal(sp_init(m, c), VLBE_OK);
    assert_int_equal(m->n, 4 * (c->ne + 1)); /* [x, y, x', y'] per node */
}

/* straight unstretched beam from the axis at angle theta, moving rigidly
   at W: v = W z x r for positions and slopes alike */
static void rigid_state(const sp_model *m, double theta, double W, vlbe_real *q, vlbe_real *v)
{
    const vlbe_real r0[2] = {VLBE_R(0.0), VLBE_R(0.0)};
    vlbe_real dir[2];
    int i;
    dir[0] = (vlbe_real)cos(theta);
    dir[1] = (vlbe_real)sin(theta);
    vlbe_ale_chain_straight(&m->ch, r0, dir, q);
    for (i = 0; i < m->n; i += 2) {
        v[i] = (vlbe_real)(-W * (double)q[i + 1]);
        v[i + 1] = (vlbe_real)(W * (double)q[i]);
    }
}

static void force(sp_model *m, const vlbe_real *q, const vlbe_real *v, vlbe_real *Q)
{
    assert_int_equal(m->sys.force(m->sys.user, VLBE_R(0.0), q, v, Q), 0);
}

/* d = Q(m1) - Q(m0) at (q, v), in double */
static void force_diff(sp_model *m1, sp_model *m0, const vlbe_real *q, const vlbe_real *v,
                       double *d)
{
    static vlbe_real Q1[SP_NMAX], Q0[SP_NMAX];
    int i;
    force(m1, q, v, Q1);
    force(m0, q, v, Q0);
    for (i = 0; i < m1->n; ++i) d[i] = (double)Q1[i] - (double)Q0[i];
}

/* S_i = sum_j |D_ij| |v_j|: the size of the terms of (D v)_i */
static void term_size(int n, const vlbe_real *D, const vlbe_real *v, double *S)
{
    int i, j;
    for (i = 0; i < n; ++i) {
        S[i] = 0.0;
        for (j = 0; j < n; ++j) S[i] += fabs((double)D[i * n + j]) * fabs((double)v[j]);
    }
}

static double dot(int n, const vlbe_real *v, const double *d)
{
    double s = 0.0;
    int i;
    for (i = 0; i < n; ++i) s += (double)v[i] * d[i];
    return s;
}

static double dot_abs(int n, const vlbe_real *v, const double *d)
{
    double s = 0.0;
    int i;
    for (i = 0; i < n; ++i) s += fabs((double)v[i] * d[i]);
    return s;
}

static const double g_thetas[5] = {0.0, 0.4, 1.3, 2.9, -2.2};
static const double g_Ws[2] = {2.0, 10.0};

/* Kelvin-Voigt under rigid spin.  The damping force is linear in v, Q_kv
   = D v with D the damping Jacobian (force_jac of the c_kv model; with
   both p fixed the chain's D is the Kelvin-Voigt part alone), and the
   strain rates eps' = r'.v', kap' = kap_q v of a rigid rotation cancel
   exactly: what remains is the rounding of the terms of D v, relative
   size EPS times S_i = sum_j |D_ij| |v_j| per row and times sum_i |v_i| S_i
   for the power.  Tolerances 64 EPS S_i and 64 EPS sum |v_i| S_i (a
   dozen roundings per Gauss point, the slopes formed from nodal values
   of size L/Le = 8 times the slope; measured: rows 0.010 (m:kv_rows) of
   it in double, 0.007 (m@flt:kv_rows) in float, the power far below).
   The radial stretch (same
   tolerance on its power) has the uniform strain rate W and no curvature
   rate: v.Q_kv = -c_kv EA L W^2. */
static void test_kv_rigid_spin(void **state)
{
    static vlbe_real q[SP_NMAX], v[SP_NMAX], K[SP_NMAX * SP_NMAX], D[SP_NMAX * SP_NMAX];
    double d[SP_NMAX], S[SP_NMAX];
    sp_cfg c;
    int it, iw, i;
    double worst = 0.0, worst_p = 0.0, worst_s = 0.0;
    (void)state;
    init_model(&g_m0, SD_UNDAMPED, &c);
    init_model(&g_m1, SD_KV, &c);
    assert_true(c.c_kv > 0.0);
    for (it = 0; it < 5; ++it)
        for (iw = 0; iw < 2; ++iw) {
            const int n = g_m1.n;
            double P, Ps;
            rigid_state(&g_m1, g_thetas[it], g_Ws[iw], q, v);
            force_diff(&g_m1, &g_m0, q, v, d);
            assert_int_equal(g_m1.sys.force_jac(g_m1.sys.user, VLBE_R(0.0), q, v, K, D), 0);
            term_size(n, D, v, S);
            assert_true(tu_max_abs(n, S) > 0.0); /* the damping is on */
            for (i = 0; i < n; ++i) {
                ASSERT_CLOSE_CTX(d[i], 0.0, 0.0, 64.0 * TEPS * S[i],
                                 "theta %g, W %g, row %d", g_thetas[it], g_Ws[iw], i);
                if (S[i] > 0.0) worst = fmax(worst, fabs(d[i]) / (64.0 * TEPS * S[i]));
            }
            P = dot(n, v, d);
            Ps = dot_abs(n, v, S);
            ASSERT_CLOSE_CTX(P, 0.0, 0.0, 64.0 * TEPS * Ps, "theta %g, W %g",
                             g_thetas[it], g_Ws[iw]);
            worst_p = fmax(worst_p, fabs(P) / (64.0 * TEPS * Ps));
            /* not a blind check: the radial stretch v = W r at the same
               state, uniform strain rate W, no curvature rate, costs
               c EA L W^2 to the same rounding */
            for (i = 0; i < n; ++i) v[i] = (vlbe_real)(g_Ws[iw] * (double)q[i]);
            force_diff(&g_m1, &g_m0, q, v, d);
            term_size(n, D, v, S);
            P = dot(n, v, d);
            Ps = dot_abs(n, v, S);
            ASSERT_CLOSE_CTX(P, -c.c_kv * c.EA * c.L * g_Ws[iw] * g_Ws[iw], 0.0,
                             64.0 * TEPS * Ps, "stretch: theta %g, W %g", g_thetas[it], g_Ws[iw]);
            worst_s = fmax(worst_s, fabs(P + c.c_kv * c.EA * c.L * g_Ws[iw] * g_Ws[iw]) /
                                        (64.0 * TEPS * Ps));
        }
    tu_report("KV rigid spin: max |Q_kv_i| / (64 EPS S_i)", worst, 1.0);
    tu_measured("kv_rows", worst);
    tu_report("KV rigid spin: |v.Q_kv| / (64 EPS sum |v| S)", worst_p, 1.0);
    tu_report("KV radial stretch: v.Q_kv vs -c EA L W^2 (ratio)", worst_s, 1.0);
}

/* Absolute damping under the same rigid spin.
   abs. M: Q_d = -abs_a M v, so v.Q_d = -abs_a v^T M v (M from the mass
   callback), and v^T M v = int rhoA |W z x r|^2 ds = rhoA W^2 L^3/3 (the
   cubic Hermite interpolation holds the linear field exactly).  Both to
   64 EPS relative (all terms of v^T M v are of the size of the sum within
   a factor of a few: the rows of M weigh positions and slopes with
   positive and negative entries; measured 0.033 (m:absm_ratio) of it in
   double, 0.011 (m@flt:absm_ratio) in float).
   abs. K0: Q_d = -abs_b K0 v with K0 of the beam along x: its axial part
   sees the x-velocity -W sin(theta) s, a uniform strain rate, and its
   bending part the y-velocity W cos(theta) s, linear, no curvature rate:
   v.Q_d = -abs_b EA L W^2 sin^2(theta), zero at theta = 0.  Tolerance 64
   EPS sum_i |v_i| S_i, S_i = sum_j |Dabs_ij| |v_j| (the terms of v^T
   K0 v are ~ 8 (L/Le) / sin^2(theta) times their sum). */
static void test_abs_rigid_spin(void **state)
{
    static vlbe_real q[SP_NMAX], v[SP_NMAX], M[SP_NMAX * SP_NMAX];
    double d[SP_NMAX], Mv[SP_NMAX], S[SP_NMAX], a, b, L, EA, rhoA;
    sp_cfg c;
    int it, iw, i, j;
    double wm = 0.0, wk = 0.0;
    (void)state;
    init_model(&g_m0, SD_UNDAMPED, &c);
    init_model(&g_mk, SD_ABS_K, &c);
    b = c.abs_b;
    init_model(&g_m1, SD_ABS_M, &c);
    a = c.abs_a;
    L = c.L;
    EA = c.EA;
    rhoA = c.rhoA;
    assert_true(a > 0.0 && b > 0.0);
    for (it = 0; it < 5; ++it)
        for (iw = 0; iw < 2; ++iw) {
            const int n = g_m1.n;
            const double W = g_Ws[iw], th = g_thetas[it];
            double P, vMv = 0.0, Pk, Pk_ref, Ps;
            rigid_state(&g_m1, th, W, q, v);
            /* abs. M */
            force_diff(&g_m1, &g_m0, q, v, d);
            assert_int_equal(g_m1.sys.mass(g_m1.sys.user, VLBE_R(0.0), q, v, M), 0);
            for (i = 0; i < n; ++i) {
                Mv[i] = 0.0;
                for (j = 0; j < n; ++j) Mv[i] += (double)M[i * n + j] * (double)v[j];
            }
            vMv = dot(n, v, Mv);
            P = dot(n, v, d);
            ASSERT_CLOSE_CTX(vMv, rhoA * W * W * L * L * L / 3.0, 64.0 * TEPS, 0.0,
                             "theta %g, W %g", th, W);
            ASSERT_CLOSE_CTX(P, -a * vMv, 64.0 * TEPS, 0.0, "theta %g, W %g", th, W);
            assert_true(P < 0.0);
            wm = fmax(wm, tu_err_ratio(P, -a * vMv, 64.0 * TEPS, 0.0));
            /* abs. K0 */
            force_diff(&g_mk, &g_m0, q, v, d);
            term_size(n, g_mk.Dabs, v, S);
            Pk = dot(n, v, d);
            Ps = dot_abs(n, v, S);
            Pk_ref = -b * EA * L * W * W * sin(th) * sin(th);
            ASSERT_CLOSE_CTX(Pk, Pk_ref, 0.0, 64.0 * TEPS * Ps, "theta %g, W %g", th, W);
            if (th != 0.0) assert_true(Pk < 0.0 && fabs(Pk) > 1e3 * 64.0 * TEPS * Ps);
            wk = fmax(wk, tu_err_ratio(Pk, Pk_ref, 0.0, 64.0 * TEPS * Ps));
        }
    tu_report("abs. M rigid spin: v.Q_d vs -abs_a v^T M v (ratio)", wm, 1.0);
    tu_measured("absm_ratio", wm);
    tu_report("abs. K0 rigid spin: v.Q_d vs -abs_b EA L W^2 sin^2 (ratio)", wk, 1.0);
}

/* Straight beam at rest (theta = 0, v = 0): D of the Kelvin-Voigt model
   = -c (EA int eps_q eps_q^T + EI int kap_q kap_q^T) and Dabs = c dQ/dq =
   the same minus c (EA int eps eps_qq + EI int kap kap_qq), with eps and
   kap zero to round-off: the difference is c EA eps int S_a' S_b' (a
   geometric stiffness of the rounded strain, eps ~ EPS L/Le) in the x and
   the y blocks alike, so its size is EPS times the axial entries.
   Tolerance 64 EPS max_i |Dabs_ii| for every entry (the nonzero bending
   entries are 1/300 to 1/2400 of the axial diagonal: held to 3.4e-11 of
   themselves in double, 2e-2 in float). */
static void test_kv_equals_abs_at_rest(void **state)
{
    static vlbe_real q[SP_NMAX], v[SP_NMAX], K[SP_NMAX * SP_NMAX], D[SP_NMAX * SP_NMAX];
    sp_cfg c;
    int n, i, j;
    double worst = 0.0, c_kv, dmax = 0.0, tol;
    (void)state;
    init_model(&g_m1, SD_KV, &c);
    c_kv = c.c_kv;
    init_model(&g_mk, SD_ABS_K, &c);
    assert_true(c.abs_b == c_kv && c_kv > 0.0);
    n = g_m1.n;
    sp_rest(&g_m1, q, v);
    assert_int_equal(g_m1.sys.force_jac(g_m1.sys.user, VLBE_R(0.0), q, v, K, D), 0);
    for (i = 0; i < n; ++i) dmax = fmax(dmax, fabs((double)g_mk.Dabs[i * n + i]));
    tol = 64.0 * TEPS * dmax;
    for (i = 0; i < n; ++i)
        for (j = 0; j < n; ++j) {
            const double a = (double)D[i * n + j], b = (double)g_mk.Dabs[i * n + j];
            ASSERT_CLOSE_CTX(a, b, 0.0, tol, "entry (%d, %d)", i, j);
            worst = fmax(worst, fabs(a - b) / tol);
        }
    /* not trivially zero: the bending diagonal is -c EI times a positive */
    assert_true(g_mk.Dabs[(n - 1) * n + n - 1] < VLBE_R(0.0));
    tu_report("KV D vs abs_b Dabs at rest (entry ratio)", worst, 1.0);
}

/* The shooting reference of the example against closed forms.
   Drag only (cf = 0), small (tip 1e-3 m): the linear cantilever under the
   triangular load q0 x/L, 11 q0 L^4/(120 EI); deviations of the elastica
   from the linear theory O((tip/L)^2) = 1e-8, of RK4 at 1000 steps
   below 1e-12: rtol 1e-7 (measured 3.5e-9 (m:ref_lin)).  Centrifugal only (dr = 0):
   the straight rod, EA u'' = -rhoA W^2 (s + u), u(0) = 0, u'(L) = 0,
   u(L) = tan(kL)/k - L, k^2 = rhoA W^2/EA (the elastica's axial law is
   the same linear one), transverse exactly 0: rtol 1e-10 (RK4 1e-12;
   Newton stops at an end force of 1e-11 of the force scale fs = 1.2e4 N,
   3e-11 of u(L) through L/EA; measured 5e-12 (m~:ref_rod)). */
static void test_reference_closed_forms(void **state)
{
    sp_cfg c;
    sd_ref b;
    double tip[2], lin, k, u;
    (void)state;
    sp_cfg_default(&c, 10.0, SP_ANCF);
    sd_ref_set(&b, &c, 0.0, 0.0);
    b.dr = 1e-3 * 120.0 * c.EI / (11.0 * pow(c.L, 5.0)); /* tip 1e-3 m */
    assert_int_equal(sd_ref_tip(&b, 1000, tip), 0);
    lin = -11.0 * b.dr * c.L * pow(c.L, 4.0) / (120.0 * c.EI);
    tu_report("elastica vs 11 q0 L^4/(120 EI) (rel.)", fabs(tip[1] / lin - 1.0), 1e-7);
    tu_measured("ref_lin", fabs(tip[1] / lin - 1));
    ASSERT_CLOSE(tip[1], lin, 1e-7, 0.0);
    sd_ref_set(&b, &c, 10.0, 0.0);
    assert_int_equal(sd_ref_tip(&b, 1000, tip), 0);
    k = sqrt(c.rhoA * 100.0 / c.EA);
    u = tan(k * c.L) / k - c.L;
    tu_report("elastica vs rod tan(kL)/k - L (rel.)", fabs(tip[0] / u - 1.0), 1e-10);
    tu_measured("ref_rod", fabs(tip[0] / u - 1));
    ASSERT_CLOSE(tip[0], u, 1e-10, 0.0);
    assert_true(tip[1] == 0.0);
    /* and sd_lin_tip is the same closed form */
    ASSERT_CLOSE(sd_lin_tip(&c, 6.0, 0.1), -11.0 * 0.1 * c.rhoA * 6.0 * c.L * pow(c.L, 4.0) /
                                               (120.0 * c.EI), 1e-15, 0.0);
}

/* The scene at W = 6 rad/s (the scene's 5 ms step; abs. M on the scene's
   8 elements, the others on 4).
   abs. M: the mean transverse tip over [Ts, t_end] against the elastica
   (shooting, 1000 RK4 steps): error budget, relative to the lag (each
   item run here, mesh and step in the fast builds only): mesh
   1.2e-4 (m:absm_mesh) (8 vs 16 elements), step 3e-5 (m:absm_step) (5 vs
   2.5 ms), the residual vibration's share of the window mean
   3.4e-4 (m:absm_vib) (the amplitude 1.9e-3 (m:absm_amp) m times T/(pi
   Tw) = 0.09, T = 1.4 s the period of the first in-plane mode at W = 6,
   omega^2 = omega_1^2 + 0.17 W^2, Tw = 5 s), the element's Green strain /
   curvature per deformed length against the elastica's laws O(N/EA) =
   8e-5: 5.7e-4 together;
   tolerance rtol 1e-3 (measured 2.2e-4 (m:absm_err), in float
   2.6e-4 (m@flt:absm_err)).  The linear bound
   without stiffening is 45 (m:absm_lin_pct) % larger in magnitude: the
   check sees the centrifugal stiffening.
   Kelvin-Voigt: no steady lag: the tip vibrates about 0 (0 within the
   window's [min, max]); the window mean within 0.1 of the vibration's
   amplitude (the T/(pi Tw) = 0.09 above; measured 0.053 (m:kv_mean_amp):
   9.8e-5 (m:kv_mean) m), so below 1e-3 of the abs. M lag (0.1 amplitude
   = 3.7e-4 (m:kv_amp_lag) of it); the vibration smaller than undamped
   (statuses).
   abs. K0: VLBE_EBOUND before a hub angle of 0.5 rad (status;
   measured 0.29 (m:absk_angle) rad at t = 3.2 (m:absk_t) s). */
static void test_scene_w6(void **state)
{
    static sd_rec rec;
    const double W = 6.0;
    sp_cfg c;
    sp_out o;
    sd_ref b;
    double ref[2], mean, amp_kv, mean_kv, g[3];
    (void)state;
    /* abs. M */
    sd_cfg(&c, W, SD_ABS_M);
    sd_rec_init(&rec, 1000000, c.Ts);
    sp_run(&g_m0, &c, sd_rec_obs, &rec, &o);
    assert_int_equal(o.status, VLBE_OK);
    sd_ref_set(&b, &c, W, c.abs_a);
    assert_int_equal(sd_ref_tip(&b, 1000, ref), 0);
    mean = sd_rec_mean(&rec);
    tu_report("W=6 abs. M steady tip vs elastica (rel.)", fabs(mean / ref[1] - 1.0), 1e-3);
    tu_measured("absm_err", fabs(mean / ref[1] - 1));
    tu_measured("absm_amp", sd_rec_amp(&rec));
    {
        /* the first in-plane mode at W: omega^2 = omega_1^2 + 0.17 W^2 */
        const double w = sqrt(sp_omega1(&c) * sp_omega1(&c) + 0.17 * W * W);
        const double PI = 3.14159265358979323846, Tp = 2.0 * PI / w, Tw = c.t_end - c.Ts;
        const double share = sd_rec_amp(&rec) * Tp / (PI * Tw) / fabs(ref[1]);
        tu_measured("absm_vib", share);
    }
    tu_measured("absm_lin_pct", 100 * (fabs(sd_lin_tip(&c, W, c.abs_a) / ref[1]) - 1));
    ASSERT_CLOSE(mean, ref[1], 1e-3, 0.0);
    assert_true(fabs(ref[1]) < 0.8 * fabs(sd_lin_tip(&c, W, c.abs_a)));
    if (!tu_slow_run()) { /* the budget's mesh and step items */
        sp_cfg cm = c, ch = c;
        cm.ne = 16;
        ch.h = 0.5 * c.h;
        sd_rec_init(&rec, 1000000, c.Ts);
        sp_run(&g_m0, &cm, sd_rec_obs, &rec, &o);
        assert_int_equal(o.status, VLBE_OK);
        tu_measured("absm_mesh", fabs(sd_rec_mean(&rec) / mean - 1));
        sd_rec_init(&rec, 1000000, c.Ts);
        sp_run(&g_m0, &ch, sd_rec_obs, &rec, &o);
        assert_int_equal(o.status, VLBE_OK);
        tu_measured("absm_step", fabs(sd_rec_mean(&rec) / mean - 1));
    }
    /* Kelvin-Voigt */
    sd_cfg(&c, W, SD_KV);
    c.ne = 4;
    sd_rec_init(&rec, 1000000, c.Ts);
    sp_run(&g_m0, &c, sd_rec_obs, &rec, &o);
    assert_int_equal(o.status, VLBE_OK);
    mean_kv = sd_rec_mean(&rec);
    amp_kv = sd_rec_amp(&rec);
    assert_true(rec.lo < 0.0 && rec.hi > 0.0);
    tu_report("W=6 KV |steady tip| / amplitude", fabs(mean_kv) / amp_kv, 0.1);
    tu_measured("kv_mean_amp", fabs(mean_kv) / amp_kv);
    tu_measured("kv_mean", fabs(mean_kv));
    tu_measured("kv_amp_lag", amp_kv / fabs(ref[1]) / 10);
    ASSERT_CLOSE(mean_kv, 0.0, 0.0, 0.1 * amp_kv);
    assert_true(fabs(mean_kv) < 1e-3 * fabs(ref[1]));
    /* undamped: larger residual vibration */
    sd_cfg(&c, W, SD_UNDAMPED);
    c.ne = 4;
    sd_rec_init(&rec, 1000000, c.Ts);
    sp_run(&g_m0, &c, sd_rec_obs, &rec, &o);
    assert_int_equal(o.status, VLBE_OK);
    tu_report("W=6 KV amplitude / undamped amplitude", amp_kv / sd_rec_amp(&rec), 1.0);
    assert_true(amp_kv < sd_rec_amp(&rec));
    /* abs. K0 */
    sd_cfg(&c, W, SD_ABS_K);
    sd_rec_init(&rec, 1000000, c.Ts);
    sp_run(&g_m0, &c, sd_rec_obs, &rec, &o);
    assert_int_equal(o.status, VLBE_EBOUND);
    sp_theta(&c, o.t_stop, g);
    tu_report("W=6 abs. K0: hub angle at the bound / 0.5 rad", g[0] / 0.5, 1.0);
    tu_measured("absk_angle", g[0]);
    tu_measured("absk_t", o.t_stop);
    assert_true(g[0] < 0.5 && isfinite(o.tip_end[1]));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_kv_rigid_spin),
        cmocka_unit_test(test_abs_rigid_spin),
        cmocka_unit_test(test_kv_equals_abs_at_rest),
        cmocka_unit_test(test_reference_closed_forms),
        cmocka_unit_test(test_scene_w6),
    };
    return cmocka_run_group_tests_name("spin_damping", tests, NULL, NULL);
}
