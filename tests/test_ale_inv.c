/* test_ale_inv.c -- cmocka suite of the invariant-matrix axial force of
   ancf_ale.h (fixed-length planar ANCF cable/beam: element invariants,
   chains, system invariants)                 -- part of vlbe
                                                   SPDX-License-Identifier: MIT
   cc -std=c99 -Wall -Wextra -Wpedantic ... -O2 tests/test_ale_inv.c -lcmocka -lm
   (add -DVLBE_USE_FLOAT for the float build; the same source passes in both)

   Tolerances are multiples of EPS (machine epsilon of vlbe_real) for
   rounding-only checks and of FD = EPS^(2/3) for central differences, as in
   test_ancf_ale.c.  VLBE_TEST_REPORT=1 prints each measured error.

   Tests
     tables_exact           unit tables against closed forms: b = classic cable
                            stiffness integrals, n = Hermite integrals,
                            int h1'^4 = 72/35, int h1'^2 h2'^2 = 3/35; the
                            slope maps dp = their integer closed forms and
                            sum_c dp[k][a][c] h_c' = d h_a'/dp_k at random xi
     inv_equals_gauss       vlbe_ale_inv_force = vlbe_ale_force (Gauss points,
                            both p fixed): cable undamped / damped and beam,
                            Q, K, D, random stretched curved moving states,
                            L from 0.05 to 40
     inv_jacobians          K = dQ/dq, D = dQ/dq' of the invariant route vs
                            central differences (cable, damped)
     ale_inv_equals_gauss   ALE elements (p1 free, p2 free, both; p' != 0):
                            vlbe_ale_force with VLBE_ALE_INV_AXIAL = without
                            (Gauss points), all 10 rows of Q (Q alone and
                            with K, D), K and D including the p- and
                            p'-columns; cable / beam, damped / undamped,
                            CONSERVATIVE or not, L from 0.05 to 40; the flag
                            given to init = the same bit as a mode argument
     ale_small_strain       the same at eps = 0.002 (a stretched arc): the
                            Green strain's cancellation, EPS/eps relative
     ale_inv_jacobians      the same invariant route's K, D vs central
                            differences of its Q over all 10 coordinates
     ale_inv_errors         ALE elements with the flag: ELENGTH, ENONFINITE,
                            ESINGULAR (bending points, CONSERVATIVE end flux)
                            as the Gauss route, outputs untouched
     chain_routes           element invariants assembled = Gauss elements
                            assembled by hand (dense); system invariants =
                            element invariants (64 EPS), ne = 1, 2, 5, 16,
                            mixed lengths, damped and not, K or D alone,
                            v = NULL
     sys_long_chain         system route = Gauss route per element (own
                            frame) and = long double for Q, K, D at eps ~
                            1e-4 on 8..64 elements far from the origin and
                            rotated (EA = 2.8e7): Q to 8 EPS/eps, K, D to
                            64 EPS; element invariants to their velocity-
                            cancellation bound
     rigid_motion           straight unstretched chain moved and rotated
                            rigidly (with the rigid velocity): zero force
     errors                 bad L, NaN, ne, short work: the status, and the
                            outputs, system and work untouched */
#include "test_util.h"
#include "../ancf_ale.h"
#include "ale_fixtures.h"
#include "fd_harness.h"

#include <stdlib.h>
#include <string.h>

#define EPS ((double)VLBE_EPS)
#define ARRAY_LEN(a) ((int)(sizeof(a) / sizeof((a)[0])))
#define FD_STEP (cbrt(EPS))
#define FD_ERR (EPS / FD_STEP)
#define SENTINEL VLBE_R(12345.0)
#define FIX (VLBE_ALE_FIX_P1 | VLBE_ALE_FIX_P2)
#define NE_MAX 16
#define N_MAX (4 * (NE_MAX + 1))
#define BW VLBE_ALE_INV_BW

static const double PI = 3.14159265358979323846;

/* max |a - b| / max |b| over n entries (0 when both are zero) */
static double rel_diff(int n, const vlbe_real *a, const vlbe_real *b)
{
    double d = 0.0, m = 0.0;
    int i;
    for (i = 0; i < n; ++i) {
        d = fmax(d, fabs((double)a[i] - (double)b[i]));
        m = fmax(m, fabs((double)b[i]));
    }
    return m > 0.0 ? d / m : d;
}

/* A random fixed-length element state of length L: chord at a random angle
   stretched by up to +-stretch, slopes turned by up to +-0.6 rad with
   magnitudes +-10 %, velocities O(1) (nodal velocities ~ 1, slope rates ~
   1/L); p1 random, p' = 0. */
static void make_state(tu_rng *g, double L, double stretch, vlbe_real *q, vlbe_real *qd)
{
    const double p1 = 0.3 * tu_rng_uniform(g), th = PI * tu_rng_uniform(g);
    const double s = 1.0 + stretch * tu_rng_uniform(g);
    const double x1 = L * tu_rng_uniform(g), y1 = L * tu_rng_uniform(g);
    const double a1 = th + 0.6 * tu_rng_uniform(g), a2 = th + 0.6 * tu_rng_uniform(g);
    const double s1 = s * (1.0 + 0.1 * tu_rng_uniform(g)), s2 = s * (1.0 + 0.1 * tu_rng_uniform(g));
    int i;
    ale_chord_q(p1, L, x1, y1, th, s, a1, a2, s1, s2, q);
    for (i = 0; i < 10; ++i)
        qd[i] = (i == 4 || i == 9) ? VLBE_R(0.0)
                                   : (vlbe_real)(((i % 5) >= 2 ? 1.0 / L : 1.0) * tu_rng_uniform(g));
}

/* A random chain of ne elements of lengths L (nodes on a wavy stretched
   line, slopes along it, velocities O(1)). */
static void make_chain(tu_rng *g, int ne, const vlbe_real *L, vlbe_real *x, vlbe_real *v)
{
    double px = 0.0, py = 0.0, th = PI * tu_rng_uniform(g);
    int k, i;
    for (k = 0; k <= ne; ++k) {
        const double s = 1.0 + 0.15 * tu_rng_uniform(g), a = th + 0.5 * tu_rng_uniform(g);
        x[4 * k + 0] = (vlbe_real)px;
        x[4 * k + 1] = (vlbe_real)py;
        x[4 * k + 2] = (vlbe_real)(s * cos(a));
        x[4 * k + 3] = (vlbe_real)(s * sin(a));
        if (k < ne) {
            const double l = (double)L[k] * (1.0 + 0.1 * tu_rng_uniform(g));
            th += 0.4 * tu_rng_uniform(g);
            px += l * cos(th);
            py += l * sin(th);
        }
    }
    for (i = 0; i < 4 * (ne + 1); ++i) v[i] = (vlbe_real)tu_rng_uniform(g);
}

static void elem_make(vlbe_ale_elem *el, const vlbe_ale_mat *m)
{
    assert_int_equal(vlbe_ale_elem_init(el, m, 0, 0, 0, 0), VLBE_OK);
}

/* The invariant route's Q (with K, D), Q1 (Q alone), K, D against the
   Gauss route's Qg, Kg, Dg: max |difference| / max |Gauss entry| of each
   matrix into the running maxima w[0..2] (Q, K, D); fails above tol,
   naming L, state s and mode. */
static void check_vs_gauss(const vlbe_real *Q, const vlbe_real *Q1, const vlbe_real *K,
                           const vlbe_real *D, const vlbe_real *Qg, const vlbe_real *Kg,
                           const vlbe_real *Dg, double tol, double L, int s, unsigned mode,
                           double *w)
{
    const double e[3] = {fmax(rel_diff(10, Q, Qg), rel_diff(10, Q1, Qg)), rel_diff(100, K, Kg),
                         rel_diff(100, D, Dg)};
    static const char name[3] = {'Q', 'K', 'D'};
    int i;
    for (i = 0; i < 3; ++i) {
        w[i] = fmax(w[i], e[i]);
        if (!(e[i] <= tol))
            fail_msg("%c: L %g state %d mode %u: %.3g EPS", name[i], L, s, mode, e[i] / EPS);
    }
}

/* the maxima of check_vs_gauss in EPS beside the 64 EPS tolerance */
static void report_vs_gauss(const char *what, const double *w)
{
    static const char *const name[3] = {"Q, in EPS of max|Q|", "K, in EPS of max|K|",
                                        "D, in EPS of max|D|"};
    char buf[80];
    int i;
    for (i = 0; i < 3; ++i) {
        snprintf(buf, sizeof buf, "%s vs Gauss %s", what, name[i]);
        tu_report(buf, w[i] / EPS, 64.0);
    }
}

/* Q, K, D of one call bit for bit those of another */
static void assert_qkd_same(const vlbe_real *Q, const vlbe_real *K, const vlbe_real *D,
                            const vlbe_real *Q2, const vlbe_real *K2, const vlbe_real *D2)
{
    assert_memory_equal(Q2, Q, 10 * sizeof Q[0]);
    assert_memory_equal(K2, K, 100 * sizeof K[0]);
    assert_memory_equal(D2, D, 100 * sizeof D[0]);
}

/* ======================================================================= */

/* The unit tables are exact integrals computed by a 5-point Gauss rule:
   equal to the closed forms to a few EPS (the rule's nodes and weights are
   rounded; sums of 5 terms of size <= 2.4).  Tolerance 16 EPS of the
   largest entry of each table. */
static void test_tables_exact(void **state)
{
    static const double bex[4][4] = {{6.0 / 5.0, 1.0 / 10.0, -6.0 / 5.0, 1.0 / 10.0},
                                     {1.0 / 10.0, 2.0 / 15.0, -1.0 / 10.0, -1.0 / 30.0},
                                     {-6.0 / 5.0, -1.0 / 10.0, 6.0 / 5.0, -1.0 / 10.0},
                                     {1.0 / 10.0, -1.0 / 30.0, -1.0 / 10.0, 2.0 / 15.0}};
    static const double nex[4] = {0.5, 1.0 / 12.0, 0.5, -1.0 / 12.0};
    static const int A[10] = {0, 0, 1, 0, 0, 1, 1, 2, 2, 3}, B[10] = {0, 1, 1, 2, 3, 2, 3, 2, 3, 3};
    vlbe_ale_inv iv;
    int P, a;
    (void)state;
    assert_int_equal(vlbe_ale_inv_init(&iv), VLBE_OK);
    for (P = 0; P < 10; ++P) ASSERT_CLOSE_CTX(iv.b[P], bex[A[P]][B[P]], 0, 16.0 * EPS * 1.2, "b[%d]", P);
    for (a = 0; a < 4; ++a) ASSERT_CLOSE_CTX(iv.n[a], nex[a], 0, 16.0 * EPS, "n[%d]", a);
    /* h1' = -6 xi (1 - xi): int h1'^4 = 1296 B(5,5) = 72/35; h2' = (1 - xi)(1 - 3 xi):
       int h1'^2 h2'^2 = 36 (B(3,5) - 6 B(4,5) + 9 B(5,5)) = 3/35 (pair (0,0) x
       (1,1): no multiplicity) */
    ASSERT_CLOSE(iv.t[0], 72.0 / 35.0, 0, 16.0 * EPS * 2.1);
    ASSERT_CLOSE(iv.t[0 * 10 + 2], 3.0 / 35.0, 0, 16.0 * EPS * 2.1);
    /* symmetry of I: t[P][R] / m(R) = t[R][P] / m(P) */
    for (P = 0; P < 10; ++P)
        for (a = 0; a < 10; ++a) {
            const double mp = A[P] == B[P] ? 1.0 : 2.0, mr = A[a] == B[a] ? 1.0 : 2.0;
            ASSERT_CLOSE_CTX((double)iv.t[P * 10 + a] / mr, (double)iv.t[a * 10 + P] / mp, 0,
                             16.0 * EPS * 2.1, "t[%d][%d]", P, a);
        }
    /* slope maps: at L = 1, d h_a'/dp2 = (m_a - 1) h_a' - xi h_a'' and
       d h_a'/dp1 = -(m_a - 1) h_a' + (xi - 1) h_a'' (xi = (p - p1)/L moves
       with p1, p2); expanded in h_2', h_3', h_4' (h_1' = -h_3'), e.g. -h_1'
       - xi h_1'' = 12 xi - 18 xi^2 = -6 h_4'.  Integers: exact.  And the
       expansion reproduces the basis' own partials at random xi: tolerance
       64 EPS absolute (both sides are sums of terms up to ~20 in size: the
       coefficients times slopes here, the polynomial terms of
       vlbe_herm_ale_eval there). */
    {
        static const double dpex[2][16] = {{0, 6, 0, 0, 0, 4, 1, 0, 0, -6, 0, 0, 0, 2, 0, 0},
                                           {0, 0, 0, -6, 0, 0, 0, -2, 0, 0, 0, 6, 0, 0, -1, -4}};
        tu_rng g = tu_rng_seed(700);
        int k, s, c;
        for (k = 0; k < 2; ++k)
            for (a = 0; a < 16; ++a)
                ASSERT_CLOSE_CTX(iv.dp[k][a], dpex[k][a], 0, 0, "dp[%d][%d]", k, a);
        for (s = 0; s < 20; ++s) {
            const vlbe_real xi = (vlbe_real)(0.5 + 0.5 * tu_rng_uniform(&g));
            vlbe_herm_ale hb;
            vlbe_herm_ale_eval(xi, VLBE_R(0.0), VLBE_R(1.0), 1, 1, &hb);
            for (k = 0; k < 2; ++k)
                for (a = 0; a < 4; ++a) {
                    double sum = 0.0;
                    for (c = 0; c < 4; ++c)
                        sum += (double)iv.dp[k][4 * a + c] * (double)hb.h[1][0][c];
                    ASSERT_CLOSE_CTX(sum, hb.h[1][1 + k][a], 0, 64.0 * EPS, "xi %g, k %d, a %d",
                                     (double)xi, k, a);
                }
        }
    }
    /* the element carries the same tables */
    {
        const vlbe_ale_mat m = mat_std();
        vlbe_ale_elem el;
        elem_make(&el, &m);
        assert_memory_equal(&el.inv, &iv, sizeof iv);
    }
}

/* vlbe_ale_inv_force against vlbe_ale_force (Gauss points, nl = 5 exact for
   the degree-8 axial integrand) with both p fixed.  Both evaluate the same
   exact integrals in another order: the difference is rounding.  Each entry
   is a sum of ~100 products whose size reaches a few times the largest
   entry (the quartic and quadratic parts of S cancel to eps ~ 0.1 at +-15 %
   stretch), so a few tens of EPS of the largest entry; tolerance 64 EPS
   relative to max |entry| of each of Q, K, D (1.4e-14 in double, well
   inside the 1e-12 asked for), for L = 0.05 .. 40 (the L powers of the
   tables are exact scalings).  Measured: see VLBE_TEST_REPORT. */
static void test_inv_equals_gauss(void **state)
{
    static const double Ls[] = {0.05, 0.4, 1.3, 6.0, 40.0};
    static const unsigned modes[] = {VLBE_ALE_NO_BEND | VLBE_ALE_NO_DAMP, VLBE_ALE_NO_BEND,
                                     VLBE_ALE_NO_DAMP, 0u};
    const vlbe_ale_mat m = mat_std();
    const double tol = 64.0 * EPS;
    vlbe_ale_elem el;
    tu_rng g = tu_rng_seed(701);
    double w[3] = {0.0, 0.0, 0.0};
    int il, s, k;
    (void)state;
    elem_make(&el, &m);
    for (il = 0; il < ARRAY_LEN(Ls); ++il)
        for (s = 0; s < 4; ++s) {
            vlbe_real q[10], qd[10];
            make_state(&g, Ls[il], 0.15, q, qd);
            for (k = 0; k < ARRAY_LEN(modes); ++k) {
                const unsigned mode = modes[k] | FIX;
                vlbe_real Q[10], K[100], D[100], Qg[10], Kg[100], Dg[100], Q1[10];
                assert_int_equal(vlbe_ale_force(&el, mode, q, qd, Qg, Kg, Dg), VLBE_OK);
                assert_int_equal(vlbe_ale_inv_force(&el, modes[k], q, qd, Q, K, D), VLBE_OK);
                assert_int_equal(vlbe_ale_inv_force(&el, modes[k], q, qd, Q1, NULL, NULL), VLBE_OK);
                /* the flag on vlbe_ale_force is the same route, bit for bit */
                {
                    vlbe_real Q2[10], K2[100], D2[100];
                    assert_int_equal(vlbe_ale_force(&el, mode | VLBE_ALE_INV_AXIAL, q, qd, Q2, K2, D2),
                                     VLBE_OK);
                    assert_qkd_same(Q, K, D, Q2, K2, D2);
                }
                check_vs_gauss(Q, Q1, K, D, Qg, Kg, Dg, tol, Ls[il], s, mode, w);
            }
        }
    report_vs_gauss("inv", w);
}

/* the invariant route's Q (vlbe_ale_force with VLBE_ALE_INV_AXIAL and
   mode; FIX_P1 | FIX_P2 in mode: vlbe_ale_inv_force's route), differenced
   by fd_harness.h */
static double inv_eval(const fd_ctx *c, const vlbe_real *q, const vlbe_real *qd, double *out)
{
    vlbe_real Q[10];
    int i;
    assert_int_equal(vlbe_ale_force((const vlbe_ale_elem *)c->el, c->mode | VLBE_ALE_INV_AXIAL,
                                    q, qd, Q, NULL, NULL),
                     VLBE_OK);
    for (i = 0; i < 10; ++i) out[i] = (double)Q[i];
    return tu_max_abs(10, out);
}

/* K and D of the invariant route at c's state against central differences
   of its Q (inv_eval) in every coordinate and rate, the step EPS^(1/3)
   max(1, |x|); rows and columns of a fixed p (c->mode) exactly zero and not
   differenced (a fixed p still sets L but is no coordinate).  The error of
   an entry is measured against the scale of its row and column (analytic
   or differenced, so that a wrongly zero matrix cannot pass; fd_check,
   with its rounding floor), at most tol;
   worst[0] (K), worst[1] (D): running maxima. */
static void check_fd(fd_ctx *c, const vlbe_real *K, const vlbe_real *D, double tol,
                     double *worst)
{
    int r, i, fixed[10];
    for (i = 0; i < 10; ++i)
        fixed[i] = (i == 4 && (c->mode & VLBE_ALE_FIX_P1)) || (i == 9 && (c->mode & VLBE_ALE_FIX_P2));
    for (r = 0; r < 2; ++r) {
        const vlbe_real *J = r ? D : K;
        fd_stats st;
        for (i = 0; i < 100; ++i)
            if (fixed[i / 10] || fixed[i % 10])
                ASSERT_CLOSE_CTX(J[i], 0.0, 0, 0, "fixed p entry %d, mode %u", i, c->mode);
        c->wrt_qd = r;
        (void)fd_check(c, J, fixed, NULL, tol, 0.0, r ? "D" : "K", &st);
        worst[r] = fmax(worst[r], st.err);
    }
}

/* K and D of the invariant route against central differences of its Q over
   the e-coordinates (the p rows and columns are exactly zero).  Tolerance
   64 FD relative to the largest entry, as in test_ancf_ale.c (truncation
   h^2 f'''/6 with f''' tens times the entries for L ~ 1). */
static void test_inv_jacobians(void **state)
{
    static const unsigned modes[] = {VLBE_ALE_NO_BEND, VLBE_ALE_NO_BEND | VLBE_ALE_NO_DAMP, 0u};
    const vlbe_ale_mat m = mat_std();
    const double tol = 64.0 * FD_ERR;
    vlbe_ale_elem el;
    tu_rng g = tu_rng_seed(702);
    double worst[2] = {0.0, 0.0};
    int s, k;
    (void)state;
    elem_make(&el, &m);
    for (s = 0; s < 3; ++s)
        for (k = 0; k < ARRAY_LEN(modes); ++k) {
            fd_ctx c;
            vlbe_real Q[10], K[100], D[100];
            fd_init(&c, 10, inv_eval, &el, modes[k] | FIX);
            make_state(&g, 0.8 + 0.3 * s, 0.15, c.q, c.qd);
            assert_int_equal(vlbe_ale_inv_force(&el, c.mode, c.q, c.qd, Q, K, D), VLBE_OK);
            check_fd(&c, K, D, tol, worst);
        }
    tu_report("inv K, D vs differences, / entry scale", fmax(worst[0], worst[1]), tol);
}

/* A random ALE element state: make_state's (length L, stretch, curved,
   moving) with material rates p1', p2' in +-0.5 L. */
static void make_ale_state(tu_rng *g, double L, double stretch, vlbe_real *q, vlbe_real *qd)
{
    make_state(g, L, stretch, q, qd);
    qd[4] = (vlbe_real)(0.5 * L * tu_rng_uniform(g));
    qd[9] = (vlbe_real)(0.5 * L * tu_rng_uniform(g));
}

/* which p's are free: p1 alone, p2 alone, both */
static const unsigned ale_pmodes[] = {VLBE_ALE_FIX_P2, VLBE_ALE_FIX_P1, 0u};
/* cable / beam, undamped / damped, with and without the end fluxes */
static const unsigned ale_modes[] = {VLBE_ALE_NO_BEND | VLBE_ALE_NO_DAMP,
                                     VLBE_ALE_NO_BEND,
                                     VLBE_ALE_NO_DAMP,
                                     0u,
                                     VLBE_ALE_NO_BEND | VLBE_ALE_CONSERVATIVE,
                                     VLBE_ALE_NO_BEND | VLBE_ALE_NO_DAMP | VLBE_ALE_CONSERVATIVE,
                                     VLBE_ALE_CONSERVATIVE,
                                     VLBE_ALE_NO_DAMP | VLBE_ALE_CONSERVATIVE};

/* The states above strain by ~10 %.  At engineering strains the axial force
   EA eps r' is a small difference (eps = (|r'|^2 - 1)/2) on both routes,
   whose rounding ~EPS relative to 1 becomes EPS/eps relative to max|Q|:
   the routes then differ by that much, in Q and in whatever follows from
   it (the p-columns of K by the scaling identity).  A uniformly stretched
   circular arc, eps = 0.002 (bench_inv_ale.c's wire: EA = 4.1e6, arc of
   radius 2 L), material flow p' = 1.2 L, 1.0 L, damped, cable and beam,
   every free-p combination and mode; the invariant route on an nl = 2
   element as above.  Tolerance 64 EPS (0.1 / eps) = 3200 EPS (7.1e-13 in
   double: still inside the 1e-12 asked for). */
static void test_ale_small_strain(void **state)
{
    const double lam = 1.002, eps = 0.5 * (lam * lam - 1.0), tol = 64.0 * EPS * 0.1 / eps;
    vlbe_ale_mat m = mat_std();
    vlbe_ale_elem eg, ei;
    double w = 0.0;
    int ip, k, n, i;
    m.EA = VLBE_R(4.1e6);
    m.EI = VLBE_R(6.4);
    m.c_eps = m.c_kap = VLBE_R(1e-3);
    (void)state;
    assert_int_equal(vlbe_ale_elem_init(&eg, &m, 0, 0, 0, 0), VLBE_OK);
    assert_int_equal(vlbe_ale_elem_init(&ei, &m, 0, 0, 2, 0), VLBE_OK);
    for (ip = 0; ip < ARRAY_LEN(ale_pmodes); ++ip)
        for (k = 0; k < ARRAY_LEN(ale_modes); ++k) {
            const unsigned mode = ale_modes[k] | ale_pmodes[ip];
            const double L = 0.25, R = 2.0 * L, om = 0.8;
            vlbe_real q[10], qd[10], Q[10], K[100], D[100], Qg[10], Kg[100], Dg[100];
            double e;
            for (n = 0; n < 2; ++n) {
                const double th = 0.3 + n * L / R;
                const double x = lam * R * sin(th), y = lam * R * (1.0 - cos(th));
                q[5 * n + 0] = (vlbe_real)x;
                q[5 * n + 1] = (vlbe_real)y;
                q[5 * n + 2] = (vlbe_real)(lam * cos(th));
                q[5 * n + 3] = (vlbe_real)(lam * sin(th));
                q[5 * n + 4] = (vlbe_real)(1.0 + n * L);
                qd[5 * n + 0] = (vlbe_real)(0.4 - om * y);
                qd[5 * n + 1] = (vlbe_real)(-0.2 + om * x);
                qd[5 * n + 2] = (vlbe_real)(-om * lam * sin(th));
                qd[5 * n + 3] = (vlbe_real)(om * lam * cos(th));
                qd[5 * n + 4] = (vlbe_real)((n ? 1.0 : 1.2) * L);
            }
            assert_int_equal(vlbe_ale_force(&eg, mode, q, qd, Qg, Kg, Dg), VLBE_OK);
            assert_int_equal(vlbe_ale_force(&ei, mode | VLBE_ALE_INV_AXIAL, q, qd, Q, K, D),
                             VLBE_OK);
            e = fmax(rel_diff(10, Q, Qg), fmax(rel_diff(100, K, Kg), rel_diff(100, D, Dg)));
            assert_int_equal(vlbe_ale_force(&ei, mode | VLBE_ALE_INV_AXIAL, q, qd, Q, NULL, NULL),
                             VLBE_OK);
            e = fmax(e, rel_diff(10, Q, Qg));
            w = fmax(w, e);
            if (!(e <= tol)) fail_msg("small strain, mode %u: %.3g EPS", mode, e / EPS);
            for (i = 0; i < 10; ++i) assert_true(isfinite((double)Q[i]));
        }
    tu_report("ALE inv vs Gauss at eps = 0.002, in EPS of max", w / EPS, tol / EPS);
}

/* ALE elements: vlbe_ale_force with VLBE_ALE_INV_AXIAL against the same
   call without it (Gauss points, nl = 5 exact).  The invariant route gives
   the p-rows as y_k . Q_e and the p-columns of K by the same scaling
   identity as the Gauss route; both evaluate the same exact integrals in
   another order, so the difference is rounding, of the same kind as for
   fixed length (test_inv_equals_gauss): each entry a sum of ~100 products
   reaching a few times the largest entry, the p-columns one division by L
   of a sum of ~10 such entries.  Tolerance 64 EPS of max |entry| of each of
   Q, K, D (1.4e-14 in double: within the 1e-12 asked for), L = 0.05 .. 40,
   4 random states each with p1', p2' != 0, every free-p combination and
   mode of ale_modes.  Q twice: alone (its own contraction order) and with
   K, D.  The invariant route runs on an element with the axial rule nl = 2,
   too few points for the degree-8 integrand: it must not use that rule
   (the Gauss route with it is off by far more than the tolerance: checked,
   so that a route falling back to Gauss points cannot pass).  The element
   with VLBE_ALE_INV_AXIAL among its flags gives the mode's numbers bit for
   bit. */
static void test_ale_inv_equals_gauss(void **state)
{
    static const double Ls[] = {0.05, 0.4, 1.3, 6.0, 40.0};
    const vlbe_ale_mat m = mat_std();
    const double tol = 64.0 * EPS;
    vlbe_ale_elem el, eli, elf;
    tu_rng g = tu_rng_seed(705);
    double w[3] = {0.0, 0.0, 0.0}, wrule = 0.0;
    int il, s, ip, k;
    (void)state;
    elem_make(&el, &m);
    assert_int_equal(vlbe_ale_elem_init(&eli, &m, 0, 0, 2, 0), VLBE_OK);
    assert_int_equal(vlbe_ale_elem_init(&elf, &m, VLBE_ALE_INV_AXIAL, 0, 2, 0), VLBE_OK);
    for (il = 0; il < ARRAY_LEN(Ls); ++il)
        for (s = 0; s < 4; ++s) {
            vlbe_real q[10], qd[10];
            make_ale_state(&g, Ls[il], 0.15, q, qd);
            for (ip = 0; ip < ARRAY_LEN(ale_pmodes); ++ip)
                for (k = 0; k < ARRAY_LEN(ale_modes); ++k) {
                    const unsigned mode = ale_modes[k] | ale_pmodes[ip];
                    vlbe_real Q[10], K[100], D[100], Qg[10], Kg[100], Dg[100], Q1[10];
                    vlbe_real Q2[10], K2[100], D2[100];
                    assert_int_equal(vlbe_ale_force(&el, mode, q, qd, Qg, Kg, Dg), VLBE_OK);
                    assert_int_equal(vlbe_ale_force(&eli, mode, q, qd, Q, K, D), VLBE_OK);
                    wrule = fmax(wrule, rel_diff(10, Q, Qg));
                    assert_int_equal(
                        vlbe_ale_force(&eli, mode | VLBE_ALE_INV_AXIAL, q, qd, Q, K, D), VLBE_OK);
                    assert_int_equal(
                        vlbe_ale_force(&eli, mode | VLBE_ALE_INV_AXIAL, q, qd, Q1, NULL, NULL),
                        VLBE_OK);
                    assert_int_equal(vlbe_ale_force(&elf, mode, q, qd, Q2, K2, D2), VLBE_OK);
                    assert_qkd_same(Q, K, D, Q2, K2, D2);
                    check_vs_gauss(Q, Q1, K, D, Qg, Kg, Dg, tol, Ls[il], s, mode, w);
                }
        }
    report_vs_gauss("ALE inv", w);
    if (!(wrule > 1e3 * tol)) fail_msg("Gauss nl = 2 vs nl = 5: only %.3g EPS", wrule / EPS);
    tu_report("ALE: 1e3 tol / (Gauss nl = 2 vs nl = 5)", 1e3 * tol / wrule, 1.0);
}

/* K and D of the invariant route on ALE elements against central
   differences of its own Q (Q alone) over all 10 coordinates and rates,
   every free-p combination and mode of ale_modes, 3 random states with L
   in [0.8, 1.4]; the element's axial rule nl = 2 (inexact: a Q or K that
   fell back to Gauss points would not match).  Tolerance 64 FD of the
   largest entry, as in
   test_ancf_ale.c's force_jacobians (the same element: entries up to L^-5
   and, with bending, |r'|^-5, whose third derivatives set the truncation
   error h^2 f'''/6 at tens of times the entries).  Rows and columns of a
   fixed p: exactly zero. */
static void test_ale_inv_jacobians(void **state)
{
    const vlbe_ale_mat m = mat_std();
    const double tol = 64.0 * FD_ERR;
    vlbe_ale_elem el;
    tu_rng g = tu_rng_seed(706);
    double worst[2] = {0.0, 0.0};
    int s, ip, k;
    (void)state;
    assert_int_equal(vlbe_ale_elem_init(&el, &m, 0, 0, 2, 0), VLBE_OK);
    for (s = 0; s < 3; ++s)
        for (ip = 0; ip < ARRAY_LEN(ale_pmodes); ++ip)
            for (k = 0; k < ARRAY_LEN(ale_modes); ++k) {
                fd_ctx c;
                vlbe_real Q[10], K[100], D[100];
                fd_init(&c, 10, inv_eval, &el, ale_modes[k] | ale_pmodes[ip]);
                make_ale_state(&g, 0.8 + 0.3 * s, 0.15, c.q, c.qd);
                assert_int_equal(
                    vlbe_ale_force(&el, c.mode | VLBE_ALE_INV_AXIAL, c.q, c.qd, Q, K, D), VLBE_OK);
                check_fd(&c, K, D, tol, worst);
            }
    tu_report("ALE inv K vs differences, / entry scale", worst[0], tol);
    tu_report("ALE inv D vs differences, / entry scale", worst[1], tol);
}

/* Bad input on ALE elements with the flag: the status of the Gauss route
   (vlbe_ale_force without the flag), and the outputs untouched (Q alone and
   with K, D).  L <= 0 (ELENGTH), NaN/Inf in any entry of q or q' including
   p and p' (ENONFINITE), zero slope everywhere (ESINGULAR at the bending
   points; the cable succeeds), zero slope at node 1 with CONSERVATIVE and
   p1 free (ESINGULAR from the end flux only). */
static void test_ale_inv_errors(void **state)
{
    const vlbe_ale_mat m = mat_std();
    const vlbe_real bad[3] = {(vlbe_real)NAN, (vlbe_real)INFINITY, (vlbe_real)-INFINITY};
    vlbe_ale_elem el;
    tu_rng g = tu_rng_seed(707);
    vlbe_real q[10], qd[10];
    int ip, k, i, b, t;
    (void)state;
    elem_make(&el, &m);
    make_ale_state(&g, 1.1, 0.1, q, qd);
    for (ip = 0; ip < ARRAY_LEN(ale_pmodes); ++ip)
        for (k = 0; k < ARRAY_LEN(ale_modes); ++k) {
            const unsigned mode = ale_modes[k] | ale_pmodes[ip];
            /* cases: 0, 1 length; 2 .. 61 non-finite q, q'; 62, 63 slopes */
            for (t = 0; t < 64; ++t) {
                vlbe_real qb[10], qdb[10], Q[10], K[100], D[100];
                vlbe_status want, got;
                int jac;
                memcpy(qb, q, sizeof q);
                memcpy(qdb, qd, sizeof qd);
                if (t < 2)
                    qb[9] = qb[4] - (t ? VLBE_R(0.5) : VLBE_R(0.0));
                else if (t < 62) {
                    i = (t - 2) % 10;
                    b = (t - 2) / 10 % 3;
                    if (t - 2 < 30)
                        qb[i] = bad[b];
                    else
                        qdb[i] = bad[b];
                } else if (t == 62) {
                    qb[5] = qb[0];
                    qb[6] = qb[1];
                    qb[2] = qb[3] = qb[7] = qb[8] = VLBE_R(0.0);
                } else
                    qb[2] = qb[3] = VLBE_R(0.0);
                for (jac = 0; jac < 2; ++jac) {
                    want = vlbe_ale_force(&el, mode, qb, qdb, Q, jac ? K : NULL, jac ? D : NULL);
                    fill(10, SENTINEL, Q);
                    fill(100, SENTINEL, K);
                    fill(100, SENTINEL, D);
                    got = vlbe_ale_force(&el, mode | VLBE_ALE_INV_AXIAL, qb, qdb, Q,
                                         jac ? K : NULL, jac ? D : NULL);
                    if (got != want)
                        fail_msg("mode %u case %d jac %d: status %d, Gauss route %d", mode, t, jac,
                                 (int)got, (int)want);
                    if (t < 62) assert_int_not_equal(got, VLBE_OK);
                    if (t == 62)
                        assert_int_equal(got, (mode & VLBE_ALE_NO_BEND) ? VLBE_OK : VLBE_ESINGULAR);
                    if (t == 63)
                        assert_int_equal(got, (ale_modes[k] & VLBE_ALE_CONSERVATIVE) &&
                                                      !(mode & VLBE_ALE_NO_BEND) &&
                                                      !(mode & VLBE_ALE_FIX_P1)
                                                  ? VLBE_ESINGULAR
                                                  : VLBE_OK);
                    if (got != VLBE_OK) {
                        assert_all_equal(10, Q, SENTINEL);
                        assert_all_equal(100, K, SENTINEL);
                        assert_all_equal(100, D, SENTINEL);
                    }
                }
            }
        }
}

/* dense n x n of a band matrix (VLBE_ALE_INV_BW per row) */
static void band_to_dense(int n, const vlbe_real *Kb, vlbe_real *K)
{
    int i, j;
    for (i = 0; i < n; ++i)
        for (j = 0; j < n; ++j) {
            const int o = j - i + VLBE_ALE_INV_KD;
            K[i * n + j] = (o >= 0 && o < BW) ? Kb[i * BW + o] : VLBE_R(0.0);
        }
}

/* Gauss elements (vlbe_ale_force, p fixed, cable, p1 = 0 so that L is
   exact) assembled by hand into dense n x n; with own, each element in its
   own frame: node 1's position and velocity subtracted from both nodes'
   (exact: the strain and its rate are invariant to a translation and a
   uniform velocity, and the Gauss route's r', v' then come from the chord
   and its rate, not from nodal values of size |r|, |v|) */
static void assemble_gauss(const vlbe_ale_elem *el, unsigned mode, int ne, const vlbe_real *L,
                           const vlbe_real *x, const vlbe_real *v, int own, vlbe_real *Q,
                           vlbe_real *K, vlbe_real *D)
{
    static const int loc[8] = {0, 1, 2, 3, 5, 6, 7, 8};
    const int n = 4 * (ne + 1);
    int e, i, j;
    fill(n, VLBE_R(0.0), Q);
    fill(n * n, VLBE_R(0.0), K);
    fill(n * n, VLBE_R(0.0), D);
    for (e = 0; e < ne; ++e) {
        vlbe_real q[10], qd[10], Qe[10], Ke[100], De[100];
        for (i = 0; i < 8; ++i) {
            q[loc[i]] = x[4 * e + i];
            qd[loc[i]] = v ? v[4 * e + i] : VLBE_R(0.0);
        }
        for (i = 0; own && i < 2; ++i) {
            q[5 + i] -= q[i];
            q[i] = VLBE_R(0.0);
            qd[5 + i] -= qd[i];
            qd[i] = VLBE_R(0.0);
        }
        q[4] = VLBE_R(0.0);
        q[9] = L[e];
        qd[4] = qd[9] = VLBE_R(0.0);
        assert_int_equal(vlbe_ale_force(el, mode | FIX | VLBE_ALE_NO_BEND, q, qd, Qe, Ke, De),
                         VLBE_OK);
        for (i = 0; i < 8; ++i) {
            Q[4 * e + i] += Qe[loc[i]];
            for (j = 0; j < 8; ++j) {
                K[(4 * e + i) * n + 4 * e + j] += Ke[loc[i] * 10 + loc[j]];
                D[(4 * e + i) * n + 4 * e + j] += De[loc[i] * 10 + loc[j]];
            }
        }
    }
}

/* The three chain routes: element invariants assembled
   (vlbe_ale_inv_chain_force with VLBE_ALE_INV_AXIAL) = Gauss elements
   assembled by hand (dense) to the element tolerance 64 EPS of the largest
   entry (an assembled entry adds at most two element entries), and the
   system invariants (vlbe_ale_inv_sys_force) = element invariants to the
   same 64 EPS (both read each element through its chord and slopes, so
   neither's rounding grows with the chain); K or D alone, Q alone and v =
   NULL too.  ne = 1, 2, 5, 16, random lengths in [0.3, 1.3]; the load of
   mat_std is included. */
static void test_chain_routes(void **state)
{
    static const int nes[] = {1, 2, 5, NE_MAX};
    static const unsigned dmodes[] = {0u, VLBE_ALE_NO_DAMP};
    const vlbe_ale_mat m = mat_std();
    const double tol = 64.0 * EPS;
    static vlbe_real work[158 * NE_MAX + 40];
    static vlbe_real Kd[N_MAX * N_MAX], Dd[N_MAX * N_MAX], Kg[N_MAX * N_MAX], Dg[N_MAX * N_MAX];
    vlbe_ale_elem el;
    tu_rng g = tu_rng_seed(703);
    double we = 0.0, ws = 0.0;
    int ie, id, e;
    (void)state;
    elem_make(&el, &m);
    for (ie = 0; ie < ARRAY_LEN(nes); ++ie)
        for (id = 0; id < ARRAY_LEN(dmodes); ++id) {
            const int ne = nes[ie], n = 4 * (ne + 1);
            vlbe_real L[NE_MAX], x[N_MAX], v[N_MAX], Q[N_MAX], Qe[N_MAX], Qg[N_MAX];
            vlbe_real K[N_MAX * BW], D[N_MAX * BW], Ke[N_MAX * BW], De[N_MAX * BW];
            vlbe_real Q2[N_MAX], K2[N_MAX * BW], D2[N_MAX * BW];
            vlbe_ale_inv_sys sys;
            const unsigned md = dmodes[id];
            for (e = 0; e < ne; ++e) L[e] = (vlbe_real)(0.3 + 0.5 * (1.0 + tu_rng_uniform(&g)));
            make_chain(&g, ne, L, x, v);
            /* element invariants assembled = Gauss elements assembled */
            assert_int_equal(
                vlbe_ale_inv_chain_force(&el, md | VLBE_ALE_INV_AXIAL, ne, L, x, v, Qe, Ke, De),
                VLBE_OK);
            assemble_gauss(&el, md, ne, L, x, v, 0, Qg, Kg, Dg);
            band_to_dense(n, Ke, Kd);
            band_to_dense(n, De, Dd);
            we = fmax(we, fmax(rel_diff(n, Qe, Qg), fmax(rel_diff(n * n, Kd, Kg), rel_diff(n * n, Dd, Dg))));
            ASSERT_VEC_CLOSE(Qe, Qg, n, 0, tol * max_abs(n, Qg));
            ASSERT_VEC_CLOSE(Kd, Kg, n * n, 0, tol * max_abs(n * n, Kg));
            ASSERT_VEC_CLOSE(Dd, Dg, n * n, 0, tol * max_abs(n * n, Dg));
            /* system = element invariants */
            assert_true(vlbe_ale_inv_sys_work_len(ne) <= (size_t)ARRAY_LEN(work));
            assert_int_equal(vlbe_ale_inv_sys_init(&sys, &el, md, ne, L, work,
                                                   vlbe_ale_inv_sys_work_len(ne)),
                             VLBE_OK);
            assert_int_equal(vlbe_ale_inv_sys_force(&sys, x, v, Q, K, D), VLBE_OK);
            ws = fmax(ws, fmax(rel_diff(n, Q, Qe),
                               fmax(rel_diff(n * BW, K, Ke), rel_diff(n * BW, D, De))));
            ASSERT_VEC_CLOSE(Q, Qe, n, 0, tol * max_abs(n, Qe));
            ASSERT_VEC_CLOSE(K, Ke, n * BW, 0, tol * max_abs(n * BW, Ke));
            ASSERT_VEC_CLOSE(D, De, n * BW, 0, tol * max_abs(n * BW, De));
            if (md & VLBE_ALE_NO_DAMP) assert_all_equal(n * BW, D, VLBE_R(0.0));
            /* K alone, D alone: the same numbers, bit for bit */
            assert_int_equal(vlbe_ale_inv_sys_force(&sys, x, v, Q2, K2, NULL), VLBE_OK);
            assert_memory_equal(Q2, Q, (size_t)n * sizeof Q[0]);
            assert_memory_equal(K2, K, (size_t)n * BW * sizeof K[0]);
            assert_int_equal(vlbe_ale_inv_sys_force(&sys, x, v, Q2, NULL, D2), VLBE_OK);
            assert_memory_equal(D2, D, (size_t)n * BW * sizeof D[0]);
            /* Q alone (its own contraction order): rounding */
            assert_int_equal(vlbe_ale_inv_sys_force(&sys, x, v, Q2, NULL, NULL), VLBE_OK);
            ASSERT_VEC_CLOSE(Q2, Q, n, 0, tol * max_abs(n, Q));
            /* v = NULL: the undamped force, D still c dQ/dv */
            assert_int_equal(vlbe_ale_inv_sys_force(&sys, x, NULL, Q2, K2, D2), VLBE_OK);
            assert_int_equal(vlbe_ale_inv_chain_force(&el, md | VLBE_ALE_INV_AXIAL, ne, L, x, NULL,
                                                      Qe, Ke, De),
                             VLBE_OK);
            ASSERT_VEC_CLOSE(Q2, Qe, n, 0, tol * max_abs(n, Qe));
            ASSERT_VEC_CLOSE(K2, Ke, n * BW, 0, tol * max_abs(n * BW, Ke));
            ASSERT_VEC_CLOSE(D2, De, n * BW, 0, tol * max_abs(n * BW, De));
        }
    tu_report("chain: elem inv vs Gauss, in EPS of max entry", we / EPS, 64.0);
    tu_report("chain: sys vs elem inv, in EPS of max entry", ws / EPS, 64.0);
}

/* Exact-math reference of a cable chain's Q with the load f: per element
   the 5-point Gauss rule (exact: the integrand has degree 8) in long
   double, in the element's own frame (node 1's position and velocity
   subtracted, exact in long double where it is wider than double):
   Q_a = int N_a f dx - EA int N_a' r' (eps + c eps') dx. */
static void ref_chain_q(int ne, const vlbe_real *L, const vlbe_real *x, const vlbe_real *v,
                        const vlbe_ale_mat *m, long double c, long double *Q)
{
    static const long double gx[3] = {0.906179845938663992797626878299392965L,
                                      0.538469310105683091036314420700208805L, 0.0L};
    static const long double gw[3] = {0.236926885056189087514264040719917363L,
                                      0.478628670499366468041291514835638192L,
                                      0.568888888888888888888888888888888889L};
    const long double EA = (long double)m->EA;
    int e, g, a, i;
    for (i = 0; i < 4 * (ne + 1); ++i) Q[i] = 0.0L;
    for (e = 0; e < ne; ++e) {
        const long double l = (long double)L[e];
        long double q[8], u[8];
        for (i = 0; i < 8; ++i) {
            q[i] = (long double)x[4 * e + i] - (i % 4 < 2 ? (long double)x[4 * e + i % 4] : 0.0L);
            u[i] = (long double)v[4 * e + i] - (i % 4 < 2 ? (long double)v[4 * e + i % 4] : 0.0L);
        }
        for (i = 0; i < 2; ++i) {
            const long double f = (long double)m->f[i];
            Q[4 * e + i] += f * l / 2.0L;
            Q[4 * e + 2 + i] += f * l * l / 12.0L;
            Q[4 * e + 4 + i] += f * l / 2.0L;
            Q[4 * e + 6 + i] -= f * l * l / 12.0L;
        }
        for (g = 0; g < 5; ++g) {
            const long double xi = 0.5L * (1.0L + (g < 3 ? -gx[g] : gx[4 - g]));
            const long double w = 0.5L * gw[g < 3 ? g : 4 - g] * l;
            const long double d[4] = {(6.0L * xi * xi - 6.0L * xi) / l,
                                      1.0L - 4.0L * xi + 3.0L * xi * xi,
                                      (6.0L * xi - 6.0L * xi * xi) / l, 3.0L * xi * xi - 2.0L * xi};
            long double rp[2], vp[2], f;
            for (i = 0; i < 2; ++i) {
                rp[i] = vp[i] = 0.0L;
                for (a = 0; a < 4; ++a) {
                    rp[i] += d[a] * q[2 * a + i];
                    vp[i] += d[a] * u[2 * a + i];
                }
            }
            f = -EA * w * (0.5L * (rp[0] * rp[0] + rp[1] * rp[1] - 1.0L) +
                           c * (rp[0] * vp[0] + rp[1] * vp[1]));
            for (a = 0; a < 4; ++a)
                for (i = 0; i < 2; ++i) Q[4 * e + 2 * a + i] += f * d[a] * rp[i];
        }
    }
}

/* A long chain at small strain: ne elements of mixed lengths (mean 10/ne,
   the spin-up scene's 10 m beam), on an arc turning 0.6 rad, stretched
   so that eps ~ epsn (Green strain; node positions and slope angles
   perturbed by ~epsn/3 L and epsn/3 rad, so eps varies along the chain),
   rotated by th0 and moved by (ox, oy); velocities: a rigid rotation at
   6 rad/s about the chain's first node (|v| up to 60) plus strain rates
   ~3 epsn (c eps' ~ eps for c = 0.3 s).  x, v: 4 (ne + 1). */
static void make_long_chain(tu_rng *g, int ne, double epsn, double th0, double ox, double oy,
                            vlbe_real *L, vlbe_real *x, vlbe_real *v)
{
    const double lam = sqrt(1.0 + 2.0 * epsn), om = 6.0, turn = 0.6;
    const double c = cos(th0), sn = sin(th0);
    double s = 0.0, Ltot = 0.0;
    int k;
    for (k = 0; k < ne; ++k) {
        L[k] = (vlbe_real)(10.0 / ne * (1.0 + 0.3 * tu_rng_uniform(g)));
        Ltot += (double)L[k];
    }
    for (k = 0; k <= ne; ++k) {
        const double R = Ltot / turn, th = s / R + epsn / 3.0 * tu_rng_uniform(g);
        const double dl = (k > 0 ? (double)L[k - 1] : 0.0) * epsn / 3.0;
        const double px = lam * R * sin(s / R) + dl * tu_rng_uniform(g);
        const double py = lam * R * (1.0 - cos(s / R)) + dl * tu_rng_uniform(g);
        const double tx = lam * cos(th), ty = lam * sin(th);
        const double X = c * px - sn * py, Y = sn * px + c * py;
        const double TX = c * tx - sn * ty, TY = sn * tx + c * ty;
        x[4 * k + 0] = (vlbe_real)(ox + X);
        x[4 * k + 1] = (vlbe_real)(oy + Y);
        x[4 * k + 2] = (vlbe_real)TX;
        x[4 * k + 3] = (vlbe_real)TY;
        v[4 * k + 0] = (vlbe_real)(-om * Y + 3.0 * epsn * (double)L[0] * tu_rng_uniform(g));
        v[4 * k + 1] = (vlbe_real)(om * X + 3.0 * epsn * (double)L[0] * tu_rng_uniform(g));
        v[4 * k + 2] = (vlbe_real)(-om * TY + 3.0 * epsn * tu_rng_uniform(g));
        v[4 * k + 3] = (vlbe_real)(om * TX + 3.0 * epsn * tu_rng_uniform(g));
        if (k < ne) s += (double)L[k];
    }
}

/* The system route at small strain on long chains far from the origin (the
   spin-up scene's case, where the old route, Gram entries of positions
   from the middle node, was off by ~(R/L)^2 EPS/eps): 8, 16, 32 and 64
   elements, EA = 2.8e7, eps ~ 1e-4, gravity, rotated by 0, 2.3 and -4
   rad, at 0, 10 and 1000 element lengths from the origin, damped (c = 0.3
   s) and undamped.  References: the Gauss route per element in its own
   frame (assemble_gauss with own: the force of the coordinates as given,
   without the rounding of nodal values of size |r|, |v|) for Q, K, D, and
   ref_chain_q (long double) for Q.  Tolerances: the Green strain is a
   difference (|r'|^2 - 1)/2 ~ eps, so its rounding ~EPS relative to 1 is
   EPS/eps relative to the force on every route (a change of the inputs by
   one ulp moves Q that much: at eps = 1e-4 in double 2.2e-12 of max|Q|,
   the floor of any route); Q to 8 EPS/eps of max|Q| (measured worst, in
   EPS/eps: system route against long double 2.6 (m:lc_sys_ld), Gauss
   route 2.0 (m:lc_gauss_ld), the two routes apart 2.7 (m:lc_sys_g)); K
   and D are dominated by
   their O(EA) geometric part EA r r^T (and EA c r r^T), rounded to a few
   EPS: 64 EPS of max|K|, max|D|.  The same bounds in float (EPS/eps =
   1.2e-3).  The element invariants (vlbe_ale_inv_chain_force with the
   flag) take the nodal velocities as they are, so their damped rounding
   grows like c |v| / L (node velocities of size |v| cancel in the chord
   rate): Q held to 8 EPS/eps (1 + c max|v| / min L), K to 64 EPS (1 + c
   max|v| / min L), D to 64 EPS.  The Gauss route on the
   nodal values (vlbe_ale_inv_chain_force without the flag: r' from
   positions of size |r|, ~EPS |r|/L / eps) is only reported. */
#define NE_LONG 64
#define N_LONG (4 * (NE_LONG + 1))
static void test_sys_long_chain(void **state)
{
    static const int nes[] = {8, 16, 32, NE_LONG};
    static const double angles[] = {0.0, 2.3, -4.0}, offs[] = {0.0, 10.0, 1000.0};
    static const unsigned dmodes[] = {0u, VLBE_ALE_NO_DAMP};
    static vlbe_real work[88 * NE_LONG + 16], Kd[N_LONG * N_LONG], Dd[N_LONG * N_LONG];
    static vlbe_real Kg[N_LONG * N_LONG], Dg[N_LONG * N_LONG], K[N_LONG * BW], D[N_LONG * BW];
    static vlbe_real Ke[N_LONG * BW], De[N_LONG * BW];
    static long double Qr[N_LONG];
    const double epsn = 1e-4, tq = 8.0 * EPS / epsn, tk = 64.0 * EPS;
    vlbe_ale_mat m = mat_std();
    vlbe_ale_elem el;
    tu_rng g = tu_rng_seed(705);
    double ws[4] = {0.0, 0.0, 0.0, 0.0}, we[4] = {0.0, 0.0, 0.0, 0.0}, wp = 0.0, wgl = 0.0;
    int in, ia, io, id, i;
    (void)state;
    m.EA = VLBE_R(2.8e7);
    m.c_eps = VLBE_R(0.3);
    m.f[0] = VLBE_R(0.0);
    m.f[1] = VLBE_R(-11.8);
    elem_make(&el, &m);
    for (in = 0; in < ARRAY_LEN(nes); ++in)
        for (ia = 0; ia < ARRAY_LEN(angles); ++ia)
            for (io = 0; io < ARRAY_LEN(offs); ++io)
                for (id = 0; id < ARRAY_LEN(dmodes); ++id) {
                    const int ne = nes[in], n = 4 * (ne + 1);
                    const unsigned md = dmodes[id];
                    const double off = offs[io] * 10.0 / ne;
                    vlbe_real L[NE_LONG], x[N_LONG], v[N_LONG], Q[N_LONG], Qg[N_LONG];
                    vlbe_real Qe[N_LONG], Ql[N_LONG];
                    vlbe_ale_inv_sys sys;
                    double qm, km, dm, te, vmax = 0.0, Lmin = HUGE_VAL;
                    make_long_chain(&g, ne, epsn, angles[ia], off * cos(1.0 + ia),
                                    off * sin(1.0 + ia), L, x, v);
                    for (i = 0; i < n; ++i)
                        if (i % 4 < 2) vmax = fmax(vmax, fabs((double)v[i]));
                    for (i = 0; i < ne; ++i) Lmin = fmin(Lmin, (double)L[i]);
                    te = tq * (1.0 + (md ? 0.0 : (double)m.c_eps * vmax / Lmin));
                    assemble_gauss(&el, md, ne, L, x, v, 1, Qg, Kg, Dg);
                    ref_chain_q(ne, L, x, v, &m, md ? 0.0L : (long double)m.c_eps, Qr);
                    for (i = 0; i < n; ++i) Ql[i] = (vlbe_real)Qr[i];
                    qm = max_abs(n, Qg);
                    km = max_abs(n * n, Kg);
                    dm = max_abs(n * n, Dg);
                    /* the system route */
                    assert_int_equal(vlbe_ale_inv_sys_init(&sys, &el, md, ne, L, work,
                                                           vlbe_ale_inv_sys_work_len(ne)),
                                     VLBE_OK);
                    assert_int_equal(vlbe_ale_inv_sys_force(&sys, x, v, Q, K, D), VLBE_OK);
                    band_to_dense(n, K, Kd);
                    band_to_dense(n, D, Dd);
                    ASSERT_VEC_CLOSE(Q, Qg, n, 0, tq * qm);
                    ASSERT_VEC_CLOSE(Q, Ql, n, 0, tq * qm);
                    ASSERT_VEC_CLOSE(Kd, Kg, n * n, 0, tk * km);
                    ASSERT_VEC_CLOSE(Dd, Dg, n * n, 0, tk * dm);
                    ws[0] = fmax(ws[0], rel_diff(n, Q, Qg) / tq);
                    ws[1] = fmax(ws[1], rel_diff(n, Q, Ql) / tq);
                    ws[2] = fmax(ws[2], rel_diff(n * n, Kd, Kg) / tk);
                    ws[3] = fmax(ws[3], rel_diff(n * n, Dd, Dg) / tk);
                    wgl = fmax(wgl, rel_diff(n, Qg, Ql) / tq); /* reported */
                    /* Q alone (its own contraction order) */
                    assert_int_equal(vlbe_ale_inv_sys_force(&sys, x, v, Q, NULL, NULL), VLBE_OK);
                    ASSERT_VEC_CLOSE(Q, Qg, n, 0, tq * qm);
                    ASSERT_VEC_CLOSE(Q, Ql, n, 0, tq * qm);
                    ws[0] = fmax(ws[0], rel_diff(n, Q, Qg) / tq);
                    ws[1] = fmax(ws[1], rel_diff(n, Q, Ql) / tq);
                    /* the element invariants */
                    assert_int_equal(vlbe_ale_inv_chain_force(&el, md | VLBE_ALE_INV_AXIAL, ne, L,
                                                              x, v, Qe, Ke, De),
                                     VLBE_OK);
                    band_to_dense(n, Ke, Kd);
                    band_to_dense(n, De, Dd);
                    ASSERT_VEC_CLOSE(Qe, Ql, n, 0, te * qm);
                    ASSERT_VEC_CLOSE(Kd, Kg, n * n, 0, te / tq * tk * km);
                    ASSERT_VEC_CLOSE(Dd, Dg, n * n, 0, tk * dm);
                    we[0] = fmax(we[0], rel_diff(n, Qe, Ql) / te);
                    we[1] = fmax(we[1], rel_diff(n, Qe, Ql) / tq);
                    we[2] = fmax(we[2], rel_diff(n * n, Kd, Kg) / (te / tq * tk));
                    we[3] = fmax(we[3], rel_diff(n * n, Dd, Dg) / tk);
                    /* the Gauss route on the nodal values: reported */
                    assert_int_equal(vlbe_ale_inv_chain_force(&el, md, ne, L, x, v, Qe, NULL, NULL),
                                     VLBE_OK);
                    wp = fmax(wp, rel_diff(n, Qe, Ql) / tq);
                }
    tu_report("long chain: sys Q vs Gauss own frame, / (8 EPS/eps)", ws[0], 1.0);
    tu_report("long chain: sys Q vs long double, / (8 EPS/eps)", ws[1], 1.0);
    tu_report("long chain: sys K vs Gauss own frame, / (64 EPS)", ws[2], 1.0);
    tu_report("long chain: sys D vs Gauss own frame, / (64 EPS)", ws[3], 1.0);
    tu_report("long chain: elem Q vs long double, / its bound", we[0], 1.0);
    tu_report("long chain: elem Q vs long double, / (8 EPS/eps)", we[1], 1e30);
    tu_report("long chain: elem K vs Gauss own frame, / its bound", we[2], 1.0);
    tu_report("long chain: elem D vs Gauss own frame, / (64 EPS)", we[3], 1.0);
    tu_report("long chain: Gauss on nodal values, / (8 EPS/eps)", wp, 1e30);
    tu_measured("lc_sys_ld", 8 * ws[1]);
    tu_measured("lc_gauss_ld", 8 * wgl);
    tu_measured("lc_sys_g", 8 * ws[0]);
}

/* Straight unstretched chain (r' = t unit everywhere: eps = 0), rotated and
   translated, moving rigidly (v = omega x r, slopes omega x t: eps' = 0):
   no force from any route.  As in test_ancf_ale.c: tolerance 64 EPS (1 +
   |r|/L) EA per entry (eps from nodal values of size |r| over L). */
static void test_rigid_motion(void **state)
{
    static const double angles[] = {0.0, 0.7, -2.3, 9.1};
    vlbe_ale_mat m = mat_std();
    static vlbe_real work[158 * 8 + 40];
    vlbe_ale_elem el;
    double w = 0.0;
    int ia, e, i;
    (void)state;
    m.f[0] = m.f[1] = VLBE_R(0.0);
    elem_make(&el, &m);
    for (ia = 0; ia < ARRAY_LEN(angles); ++ia) {
        const int ne = 8, n = 4 * (ne + 1);
        const double c = cos(angles[ia]), sn = sin(angles[ia]), om = 0.7;
        vlbe_real L[8], x[36], v[36], Q[36], Qe[36], Qi[10];
        vlbe_ale_inv_sys sys;
        double s = 0.0, rmax = 0.0, tol;
        for (e = 0; e < ne; ++e) L[e] = (vlbe_real)(0.2 + 0.1 * e);
        for (e = 0; e <= ne; ++e) {
            const double px = 3.0 + s * c, py = -2.0 + s * sn;
            x[4 * e + 0] = (vlbe_real)px;
            x[4 * e + 1] = (vlbe_real)py;
            x[4 * e + 2] = (vlbe_real)c;
            x[4 * e + 3] = (vlbe_real)sn;
            v[4 * e + 0] = (vlbe_real)(0.4 - om * py);
            v[4 * e + 1] = (vlbe_real)(-0.1 + om * px);
            v[4 * e + 2] = (vlbe_real)(-om * sn);
            v[4 * e + 3] = (vlbe_real)(om * c);
            rmax = fmax(rmax, fmax(fabs(px), fabs(py)));
            if (e < ne) s += (double)L[e];
        }
        tol = 64.0 * EPS * (1.0 + rmax / 0.2) * (double)m.EA;
        assert_int_equal(vlbe_ale_inv_sys_init(&sys, &el, 0u, ne, L, work, ARRAY_LEN(work)), VLBE_OK);
        assert_int_equal(vlbe_ale_inv_sys_force(&sys, x, v, Q, NULL, NULL), VLBE_OK);
        assert_int_equal(vlbe_ale_inv_chain_force(&el, VLBE_ALE_INV_AXIAL, ne, L, x, v, Qe, NULL, NULL),
                         VLBE_OK);
        for (i = 0; i < n; ++i) {
            w = fmax(w, fmax(fabs((double)Q[i]), fabs((double)Qe[i])) /
                            (EPS * (1.0 + rmax / 0.2) * (double)m.EA));
            ASSERT_CLOSE_CTX(Q[i], 0.0, 0, tol, "sys, angle %g, entry %d", angles[ia], i);
            ASSERT_CLOSE_CTX(Qe[i], 0.0, 0, tol, "elem, angle %g, entry %d", angles[ia], i);
        }
        { /* one element, with bending (straight: kap = 0 too) */
            vlbe_real q[10], qd[10];
            for (i = 0; i < 4; ++i) {
                q[i] = x[i];
                q[5 + i] = x[4 + i];
                qd[i] = v[i];
                qd[5 + i] = v[4 + i];
            }
            q[4] = VLBE_R(0.0);
            q[9] = L[0];
            qd[4] = qd[9] = VLBE_R(0.0);
            assert_int_equal(vlbe_ale_inv_force(&el, 0u, q, qd, Qi, NULL, NULL), VLBE_OK);
            for (i = 0; i < 10; ++i) ASSERT_CLOSE_CTX(Qi[i], 0.0, 0, tol, "element entry %d", i);
        }
    }
    tu_report("rigid motion |Q| in EPS (1 + |r|/L) EA", w, 64.0);
}

/* Bad input: the status, and nothing written (outputs, system, work). */
static void test_errors(void **state)
{
    const vlbe_ale_mat m = mat_std();
    static vlbe_real work[158 * 3 + 40], wcopy[158 * 3 + 40];
    vlbe_ale_elem el;
    vlbe_ale_inv_sys sys, sys0;
    tu_rng g = tu_rng_seed(704);
    vlbe_real q[10], qd[10], Q[10], K[100], D[100];
    vlbe_real L[3] = {VLBE_R(0.5), VLBE_R(0.7), VLBE_R(0.6)}, x[16], v[16], Qc[16], Kc[16 * BW], Dc[16 * BW];
    const vlbe_real bad[3] = {(vlbe_real)NAN, (vlbe_real)INFINITY, (vlbe_real)-INFINITY};
    int i, b;
    (void)state;
    elem_make(&el, &m);
    make_state(&g, 1.0, 0.1, q, qd);
    make_chain(&g, 3, L, x, v);
    /* element: L <= 0, non-finite q, qd */
    fill(10, SENTINEL, Q);
    fill(100, SENTINEL, K);
    fill(100, SENTINEL, D);
    {
        vlbe_real qb[10];
        memcpy(qb, q, sizeof q);
        qb[9] = qb[4];
        assert_int_equal(vlbe_ale_inv_force(&el, 0u, qb, qd, Q, K, D), VLBE_ELENGTH);
        qb[9] = qb[4] - VLBE_R(0.5);
        assert_int_equal(vlbe_ale_inv_force(&el, 0u, qb, qd, Q, NULL, NULL), VLBE_ELENGTH);
        for (b = 0; b < 3; ++b)
            for (i = 0; i < 10; ++i) {
                vlbe_real qdb[10];
                memcpy(qb, q, sizeof q);
                memcpy(qdb, qd, sizeof qd);
                qb[i] = bad[b];
                assert_int_equal(vlbe_ale_inv_force(&el, 0u, qb, qd, Q, K, D), VLBE_ENONFINITE);
                qdb[i] = bad[b];
                assert_int_equal(vlbe_ale_inv_force(&el, 0u, q, qdb, Q, K, D), VLBE_ENONFINITE);
            }
    }
    assert_all_equal(10, Q, SENTINEL);
    assert_all_equal(100, K, SENTINEL);
    assert_all_equal(100, D, SENTINEL);
    /* chain, element route */
    fill(16, SENTINEL, Qc);
    fill(16 * BW, SENTINEL, Kc);
    fill(16 * BW, SENTINEL, Dc);
    for (b = 0; b < 3; ++b) {
        vlbe_real Lb[3], xb[16];
        memcpy(Lb, L, sizeof L);
        Lb[1] = bad[b];
        assert_int_equal(vlbe_ale_inv_chain_force(&el, 0u, 3, Lb, x, v, Qc, Kc, Dc), VLBE_ENONFINITE);
        memcpy(xb, x, sizeof x);
        xb[7] = bad[b];
        assert_int_equal(vlbe_ale_inv_chain_force(&el, 0u, 3, L, xb, v, Qc, Kc, Dc), VLBE_ENONFINITE);
        assert_int_equal(vlbe_ale_inv_chain_force(&el, 0u, 3, L, x, xb, Qc, Kc, Dc), VLBE_ENONFINITE);
    }
    {
        vlbe_real Lb[3] = {VLBE_R(0.5), VLBE_R(0.0), VLBE_R(0.6)};
        assert_int_equal(vlbe_ale_inv_chain_force(&el, 0u, 3, Lb, x, v, Qc, Kc, Dc), VLBE_ELENGTH);
        Lb[1] = VLBE_R(-0.3);
        assert_int_equal(vlbe_ale_inv_chain_force(&el, 0u, 3, Lb, x, v, Qc, Kc, Dc), VLBE_ELENGTH);
    }
    /* system: work_len, init and force */
    assert_true(vlbe_ale_inv_sys_work_len(0) == 0);
    assert_true(vlbe_ale_inv_sys_work_len(-2) == 0);
    assert_true(vlbe_ale_inv_sys_work_len(3) == 88 * 3 + 16);
    fill(ARRAY_LEN(work), SENTINEL, work);
    memcpy(wcopy, work, sizeof work);
    memset(&sys, 0x5a, sizeof sys);
    sys0 = sys;
    assert_int_equal(vlbe_ale_inv_sys_init(&sys, &el, 0u, 0, L, work, ARRAY_LEN(work)), VLBE_EARG);
    assert_int_equal(vlbe_ale_inv_sys_init(&sys, &el, 0u, 3, L, work, vlbe_ale_inv_sys_work_len(3) - 1),
                     VLBE_EWORK);
    for (b = 0; b < 3; ++b) {
        vlbe_real Lb[3];
        memcpy(Lb, L, sizeof L);
        Lb[2] = bad[b];
        assert_int_equal(vlbe_ale_inv_sys_init(&sys, &el, 0u, 3, Lb, work, ARRAY_LEN(work)),
                         VLBE_ENONFINITE);
    }
    {
        vlbe_real Lb[3] = {VLBE_R(0.5), VLBE_R(0.7), VLBE_R(0.0)};
        assert_int_equal(vlbe_ale_inv_sys_init(&sys, &el, 0u, 3, Lb, work, ARRAY_LEN(work)), VLBE_ELENGTH);
    }
    assert_memory_equal(&sys, &sys0, sizeof sys);
    assert_memory_equal(work, wcopy, sizeof work);
    assert_int_equal(vlbe_ale_inv_sys_init(&sys, &el, 0u, 3, L, work, ARRAY_LEN(work)), VLBE_OK);
    for (b = 0; b < 3; ++b) {
        vlbe_real xb[16];
        memcpy(xb, x, sizeof x);
        xb[12] = bad[b];
        assert_int_equal(vlbe_ale_inv_sys_force(&sys, xb, v, Qc, Kc, Dc), VLBE_ENONFINITE);
        assert_int_equal(vlbe_ale_inv_sys_force(&sys, x, xb, Qc, Kc, Dc), VLBE_ENONFINITE);
    }
    assert_all_equal(16, Qc, SENTINEL);
    assert_all_equal(16 * BW, Kc, SENTINEL);
    assert_all_equal(16 * BW, Dc, SENTINEL);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_tables_exact),  cmocka_unit_test(test_inv_equals_gauss),
        cmocka_unit_test(test_inv_jacobians), cmocka_unit_test(test_ale_inv_equals_gauss),
        cmocka_unit_test(test_ale_small_strain), cmocka_unit_test(test_ale_inv_jacobians),
        cmocka_unit_test(test_ale_inv_errors),
        cmocka_unit_test(test_chain_routes),  cmocka_unit_test(test_sys_long_chain),
        cmocka_unit_test(test_rigid_motion),  cmocka_unit_test(test_errors),
    };
    return cmocka_run_group_tests_name("ale_inv", tests, NULL, NULL);
}
