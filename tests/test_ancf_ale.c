/* test_ancf_ale.c -- cmocka suite of the element part of ancf_ale.h (planar
   ALE-ANCF variable-length beam element)     -- part of vlbe
                                                   SPDX-License-Identifier: MIT
   cc -std=c99 -Wall -Wextra -Wpedantic ... -O2 tests/test_ancf_ale.c -lcmocka -lm
   (add -DVLBE_USE_FLOAT for the float build; the same source passes in both)

   Every tolerance says why it has its size.  They are multiples of EPS (the
   machine epsilon of vlbe_real) for rounding-only checks and of
   FD = EPS^(2/3) for central differences with the step h = EPS^(1/3) (the
   step that balances the truncation error h^2 f'''/6 against the rounding
   error EPS f / h, both then ~EPS^(2/3)): FD = 3.7e-11 in double, 2.4e-5 in
   float.  Set VLBE_TEST_REPORT=1 in the environment to print the measured
   error of each check next to its tolerance.  "measured" below is the
   double -O2 build (tag m:), the float build where it is quoted too
   (m@flt:), and numbers of a few EPS are orders of magnitude (m~:, they
   move with the compiler); tests/measured.sh checks them against the
   report.

   Tests
     force_jacobians        K = dQ/dq, D = dQ/dq' vs central differences, all
                            32 mode combinations, 4 random curved, stretched,
                            moving states with damping and a load; rows and
                            columns of fixed p exactly zero
     jacobian_outputs       K or D alone: the same Q, K, D bit for bit; Q alone
                            (fast route) equal to rounding, every mode and rule
     mass_jacobian          d(M a)/dq vs differences of vlbe_ale_mass
     point_force_jacobian   K of vlbe_ale_point_force vs differences of its Q
     energy_gradient_string -Q = dU/dq for the string (exact quadrature), with the
                            end-point fluxes of the p-rows, every mode
     energy_gradient_bend   the same with bending: e-rows for any Gauss order,
                            p-rows with nt = 8 (quadrature error measured)
     load_potential         Q of the load = -dV/dq, e-rows and p-rows (flux f.r)
     transport_inertia_lagrange  Q_a against Lagrange's equations of T (Mdot qd -
                            dT/dq) up to the kinetic end fluxes
     kinetic_energy         T = qd^T M qd / 2
     rigid_motion           straight unstretched element, translated and rotated
                            (angles beyond 2 pi): no elastic force
     mass_properties        symmetric, Cholesky of the e-block, x^T M x > 0,
                            total mass rhoA L, classic ANCF cable matrix,
                            constant for fixed p; with a free p_k the null
                            vector (p_k, nodal data) of the re-parametrization:
                            one ALE element's M is only semi-definite
     fixed_equals_lagrangian  FIX_P1|FIX_P2 = e-rows of mode 0 at p1' = p2' = 0
     flags_vs_mode          flags given to init = the same bits as a mode argument
     errors_eval            ELENGTH, ENONFINITE, ESINGULAR, EBOUND; no output
                            written on failure
     errors_init            EARG, ENONFINITE; the element not written
     quadrature_exactness   nm = 4, 5, 8 and nl = 5, 8 agree (polynomial integrands)
     point_at_nodes         vlbe_ale_point / _strain at the nodes = nodal data
     strain_stretched       uniform stretch s: eps = (s^2 - 1)/2, kap = 0
     curvature_arc          cubic Hermite arc: kap -> 1/R as theta^2, r as theta^4 */
#include "test_util.h"
#include "../ancf_ale.h"
#include "ale_fixtures.h"
#include "ale_harness.h"

#include <stdlib.h>
#include <string.h>

#define EPS ((double)VLBE_EPS)
#define ARRAY_LEN(a) ((int)(sizeof(a) / sizeof((a)[0])))
#define FD_STEP (cbrt(EPS))     /* h = EPS^(1/3) on O(1) variables           */
#define FD_ERR (EPS / FD_STEP)  /* EPS^(2/3): error unit of a central difference */
#define SENTINEL VLBE_R(12345.0)


/* ------------------------------------------------------------------------ */
/* helpers                                                                    */
/* ------------------------------------------------------------------------ */

static void elem_make(vlbe_ale_elem *el, const vlbe_ale_mat *m, unsigned flags, int nm, int nl,
                      int nt)
{
    assert_int_equal(vlbe_ale_elem_init(el, m, flags, nm, nl, nt), VLBE_OK);
}

/* the element's calls for the difference harness (ale_harness.h) */
static vlbe_status op_force(const void *el, unsigned mode, const vlbe_real *q,
                            const vlbe_real *qd, vlbe_real *Q)
{
    return vlbe_ale_force((const vlbe_ale_elem *)el, mode, q, qd, Q, NULL, NULL);
}
static vlbe_status op_mass(const void *el, unsigned mode, const vlbe_real *q, vlbe_real *M)
{
    return vlbe_ale_mass((const vlbe_ale_elem *)el, mode, q, M);
}
static vlbe_status op_point_force(const void *el, const vlbe_real *q, vlbe_real pf,
                                  const vlbe_real *F, vlbe_real *Q)
{
    (void)el;
    return vlbe_ale_point_force(q, pf, F, Q, NULL);
}
static vlbe_status op_point(const void *el, const vlbe_real *q, vlbe_real p, vlbe_real *r)
{
    (void)el;
    return vlbe_ale_point(q, p, r, NULL);
}
static vlbe_status op_energy(const void *el, unsigned mode, const vlbe_real *q,
                             const vlbe_real *qd, vlbe_real *E)
{
    return vlbe_ale_energy((const vlbe_ale_elem *)el, mode, q, qd, E);
}
static const ale_ops OPS = {op_force, op_mass, op_point_force, op_point, op_energy};

/* ======================================================================= */
/* 1. Jacobians                                                              */
/* ======================================================================= */

/* Tolerance: 64 FD relative to the largest entry (2.4e-9 in double, 1.5e-3
   in float).  The entries involve up to L^-5 and the bending terms
   |r'|^-5 at |kap| ~ 1, so the third derivatives that set the truncation
   error are tens times the entries: measured worst 17 (m:fj_K_fd) FD for
   K and 2.0 (m:fj_D_fd) FD for D over all modes and states, in float
   17 (m@flt:fj_K_fd) and 2.6 (m@flt:fj_D_fd) FD alike (the truncation
   error dominates and scales like the tolerance). */
static void test_force_jacobians(void **state)
{
    const vlbe_ale_mat m = mat_std();
    const double tol = 64.0 * FD_ERR;
    vlbe_ale_elem el;
    tu_rng g = tu_rng_seed(11);
    double wk = 0.0, wd = 0.0;
    int s, k;
    (void)state;
    elem_make(&el, &m, 0, 0, 0, 0);
    for (s = 0; s < 4; ++s) {
        ale_fd c;
        ale_fd_init(&c, &OPS, &el, 0);
        make_state(&g, 0.6, 0.15, c.fd.q, c.fd.qd);
        for (k = 0; k < N_MODES; ++k) {
            vlbe_real Q[10], K[100], D[100];
            c.fd.mode = mode_of(k);
            assert_int_equal(vlbe_ale_force(&el, c.fd.mode, c.fd.q, c.fd.qd, Q, K, D), VLBE_OK);
            check_fixed_zero(c.fd.mode, Q, K);
            check_fixed_zero(c.fd.mode, NULL, D);
            wk = fmax(wk, check_jac(&c, FD_Q_OF_Q, K, c.fd.mode, tol, "K"));
            wd = fmax(wd, check_jac(&c, FD_Q_OF_QD, D, c.fd.mode, tol, "D"));
        }
    }
    tu_report("K = dQ/dq (all modes), err / entry scale", wk, tol);
    tu_report("D = dQ/dq' (all modes), err / entry scale", wd, tol);
    tu_measured("fj_K_fd", wk / FD_ERR);
    tu_measured("fj_D_fd", wd / FD_ERR);
}

/* K and D are optional: with K or D asked for, any combination gives the
   same Q, K, D bit for bit (the same operations run; only the outputs asked
   for are copied).  Q alone runs the fast route (vlbe__ale_q: p1/p2
   partials from the ALE scaling identity, curvature factors batched), which
   sums the same integrals in another order: it agrees with the Q of the
   Jacobian route to rounding.  Tolerance 64 EPS of max|Q|: each entry is a
   sum of about 100 products over 14 points whose magnitudes reach a few
   times max|Q| (stiff axial and bending terms against inertia), so a few
   EPS times that sum is the rounding difference of two summation orders;
   measured 7 (m~:jo_eps) EPS on these states. */
static void test_jacobian_outputs(void **state)
{
    const vlbe_ale_mat m = mat_std();
    vlbe_ale_mat m0 = mat_std();
    const double tol = 64.0 * EPS;
    vlbe_ale_elem el, els[4];
    vlbe_real q[10], qd[10], Q[10], K[100], D[100], Q2[10], K2[100], D2[100];
    tu_rng g = tu_rng_seed(12);
    double worst = 0.0;
    int k, e, s, i;
    (void)state;
    elem_make(&el, &m, 0, 0, 0, 0);
    /* the rules shared (default), not shared, no axial term, low orders */
    elem_make(&els[0], &m, 0, 0, 0, 0);
    elem_make(&els[1], &m, 0, 3, 4, 6);
    m0.EA = VLBE_R(0.0);
    elem_make(&els[2], &m0, 0, 0, 0, 0);
    elem_make(&els[3], &m, 0, 2, 3, 3);
    for (s = 0; s < 8; ++s) {
        make_state(&g, 0.6, 0.15, q, qd);
        for (e = 0; e < 4; ++e)
            for (k = 0; k < N_MODES; ++k) {
                double mx = 0.0, d = 0.0;
                assert_int_equal(vlbe_ale_force(&els[e], mode_of(k), q, qd, Q, K, D), VLBE_OK);
                assert_int_equal(vlbe_ale_force(&els[e], mode_of(k), q, qd, Q2, NULL, NULL),
                                 VLBE_OK);
                for (i = 0; i < 10; ++i) {
                    mx = fmax(mx, fabs((double)Q[i]));
                    d = fmax(d, fabs((double)Q2[i] - (double)Q[i]));
                    if (is_fixed(mode_of(k), i)) assert_true(Q2[i] == VLBE_R(0.0));
                }
                worst = fmax(worst, d / mx);
            }
    }
    tu_report("Q alone vs Q of the Jacobian route, max err / max|Q|", worst, tol);
    tu_measured("jo_eps", worst / EPS);
    assert_true(worst <= tol);
    make_state(&g, 0.6, 0.15, q, qd);
    for (k = 0; k < N_MODES; ++k) {
        const unsigned mode = mode_of(k);
        assert_int_equal(vlbe_ale_force(&el, mode, q, qd, Q, K, D), VLBE_OK);
        fill(100, SENTINEL, D2);
        assert_int_equal(vlbe_ale_force(&el, mode, q, qd, Q2, K2, NULL), VLBE_OK);
        ASSERT_VEC_CLOSE(Q2, Q, 10, 0, 0);
        ASSERT_VEC_CLOSE(K2, K, 100, 0, 0);
        assert_all_equal(100, D2, SENTINEL);
        fill(100, SENTINEL, K2);
        assert_int_equal(vlbe_ale_force(&el, mode, q, qd, Q2, NULL, D2), VLBE_OK);
        ASSERT_VEC_CLOSE(Q2, Q, 10, 0, 0);
        ASSERT_VEC_CLOSE(D2, D, 100, 0, 0);
        assert_all_equal(100, K2, SENTINEL);
    }
}

/* d(M a)/dq against differences of M(q) a (a random, with p-components).
   Tolerance 64 FD relative to the largest entry as for K: M is polynomial
   in e and rational in L (L^-2 at most in M, so smooth); measured
   1.5 (m:mj_fd) FD. */
static void test_mass_jacobian(void **state)
{
    const vlbe_ale_mat m = mat_std();
    const double tol = 64.0 * FD_ERR;
    vlbe_ale_elem el;
    tu_rng g = tu_rng_seed(13);
    double w = 0.0;
    int s, k, i;
    (void)state;
    elem_make(&el, &m, 0, 0, 0, 0);
    for (s = 0; s < 4; ++s) {
        ale_fd c;
        ale_fd_init(&c, &OPS, &el, 0);
        make_state(&g, 0.6, 0.15, c.fd.q, c.fd.qd);
        for (i = 0; i < 10; ++i) c.fd.a[i] = (vlbe_real)(2.0 * tu_rng_uniform(&g));
        for (k = 0; k < N_MODES; ++k) {
            vlbe_real Mq[100];
            c.fd.mode = mode_of(k);
            assert_int_equal(vlbe_ale_mass_jac(&el, c.fd.mode, c.fd.q, c.fd.a, Mq), VLBE_OK);
            check_fixed_zero(c.fd.mode, NULL, Mq);
            if ((c.fd.mode & (VLBE_ALE_FIX_P1 | VLBE_ALE_FIX_P2)) ==
                (VLBE_ALE_FIX_P1 | VLBE_ALE_FIX_P2)) {
                /* Lagrangian: M constant, the Jacobian is exactly zero */
                assert_all_equal(100, Mq, VLBE_R(0.0));
                continue;
            }
            w = fmax(w, check_jac(&c, FD_MA_OF_Q, Mq, c.fd.mode, tol, "Mq"));
        }
    }
    tu_report("Mq = d(M a)/dq, err / entry scale", w, tol);
    tu_measured("mj_fd", w / FD_ERR);
}

/* Point force at interior points and at both ends: K vs differences of Q
   (all ten rows and columns, whatever the mode).  Tolerance 64 FD relative
   to the largest entry, as for K: the truncation error of the p-columns
   involves the third p1, p2 derivatives of the basis (~L^-3 with large
   coefficients, tens times the entries); measured 22 (m:pf_fd) FD. */
static void test_point_force_jacobian(void **state)
{
    static const double xis[] = {0.0, 0.27, 0.5, 0.81, 1.0};
    const double tol = 64.0 * FD_ERR;
    tu_rng g = tu_rng_seed(14);
    double w = 0.0;
    int s, ix;
    (void)state;
    for (s = 0; s < 3; ++s) {
        ale_fd c;
        ale_fd_init(&c, &OPS, NULL, 0);
        make_state(&g, 0.6, 0.15, c.fd.q, c.fd.qd);
        c.F[0] = (vlbe_real)(3.0 * tu_rng_uniform(&g));
        c.F[1] = (vlbe_real)(3.0 * tu_rng_uniform(&g));
        for (ix = 0; ix < ARRAY_LEN(xis); ++ix) {
            vlbe_real Q[10], K[100], Q0[10];
            const vlbe_real *q = c.fd.q;
            /* keep pf inside [p1, p2] while p1, p2 are differenced: the
               interior points only (the ends are checked without p steps) */
            c.pf = (vlbe_real)((double)q[4] + xis[ix] * ((double)q[9] - (double)q[4]));
            if (ix == 0) c.pf = q[4];
            if (ix == ARRAY_LEN(xis) - 1) c.pf = q[9];
            fill(10, VLBE_R(0.0), Q);
            fill(100, VLBE_R(0.0), K);
            assert_int_equal(vlbe_ale_point_force(q, c.pf, c.F, Q, K), VLBE_OK);
            /* accumulates: a second call on the result doubles it exactly */
            memcpy(Q0, Q, sizeof Q);
            {
                vlbe_real Q2[10], K2[100];
                int i;
                memcpy(Q2, Q, sizeof Q2);
                memcpy(K2, K, sizeof K2);
                assert_int_equal(vlbe_ale_point_force(q, c.pf, c.F, Q2, K2), VLBE_OK);
                for (i = 0; i < 10; ++i) ASSERT_CLOSE(Q2[i], 2.0 * (double)Q0[i], 0, 0);
                for (i = 0; i < 100; ++i) ASSERT_CLOSE(K2[i], 2.0 * (double)K[i], 0, 0);
            }
            if (ix == 0 || ix == ARRAY_LEN(xis) - 1) {
                /* at an end a p step would leave the element: difference the
                   e-columns only, and check the resultant: sum of the
                   position rows = F (N1 + N3 = 1) */
                double Jfd[100];
                int cols[10], i, j;
                for (j = 0; j < 10; ++j) cols[j] = !is_p(j);
                ale_fd_use(&c, FD_PF_OF_Q);
                fd_jac(&c.fd, cols, Jfd);
                for (j = 0; j < 10; ++j) {
                    if (is_p(j)) continue;
                    for (i = 0; i < 10; ++i)
                        ASSERT_CLOSE_CTX(Jfd[i * 10 + j], K[i * 10 + j], 0, tol * max_abs(100, K),
                                         "end point force K (%d, %d)", i, j);
                }
            } else {
                w = fmax(w, check_jac(&c, FD_PF_OF_Q, K, 0, tol, "point force K"));
            }
            /* resultant: Q[x1] + Q[x2] = F exactly up to the rounding of N1 + N3 */
            ASSERT_CLOSE((double)Q[0] + (double)Q[5], c.F[0], 0, 4 * EPS * fabs((double)c.F[0]));
            ASSERT_CLOSE((double)Q[1] + (double)Q[6], c.F[1], 0, 4 * EPS * fabs((double)c.F[1]));
        }
    }
    tu_report("point force K, err / entry scale", w, tol);
    tu_measured("pf_fd", w / FD_ERR);
}

/* ======================================================================= */
/* 2. forces as gradients of the energies                                    */
/* ======================================================================= */

/* Strain energy density u = (EA eps^2 + EI kap^2)/2 at material point p. */
static double energy_density(const vlbe_ale_mat *m, int bend, const vlbe_real *q, vlbe_real p)
{
    vlbe_real eps, kap = VLBE_R(0.0);
    assert_int_equal(vlbe_ale_strain(q, p, &eps, bend ? &kap : NULL), VLBE_OK);
    return 0.5 * (double)m->EA * (double)eps * (double)eps +
           (bend ? 0.5 * (double)m->EI * (double)kap * (double)kap : 0.0);
}

/* Residual of -Q = grad U at one state and mode (elastic forces only: qd = 0,
   f = 0, no damping).  e-rows: dU/de + Q_e.  p-rows: dU/dp1 + Q_p1 + u(p1)
   and dU/dp2 + Q_p2 - u(p2) without CONSERVATIVE (Q_p1 += u(p1) and
   Q_p2 -= u(p2) are the fluxes the header adds to make the p-forces the
   gradient), dU/dp + Q_p with it.  Writes the residuals (10) and returns
   the scale of the FD error, max(|Q|, |grad U|, max|K|). */
static double energy_residual(const vlbe_ale_elem *el, unsigned mode, const vlbe_real *q,
                              double *res)
{
    vlbe_real Q[10], K[100], qd[10];
    double grad[10], scale;
    const int bend = !((mode | el->flags) & VLBE_ALE_NO_BEND) && el->mat.EI != VLBE_R(0.0);
    int i;
    fill(10, VLBE_R(0.0), qd);
    assert_int_equal(vlbe_ale_force(el, mode, q, qd, Q, K, NULL), VLBE_OK);
    energy_grad(&OPS, el, mode, q, qd, 1, grad);
    for (i = 0; i < 10; ++i) res[i] = grad[i] + (double)Q[i];
    if (!(mode & VLBE_ALE_CONSERVATIVE)) {
        res[4] += energy_density(&el->mat, bend, q, q[4]);
        res[9] -= energy_density(&el->mat, bend, q, q[9]);
    }
    for (i = 4; i < 10; i += 5)
        if (is_fixed(mode, i)) res[i] = 0.0; /* not a coordinate: Q_p = 0 */
    scale = fmax(fmax(max_abs(10, Q), tu_max_abs(10, grad)), max_abs(100, K));
    return scale;
}

/* String (NO_BEND): the axial integrands (u and d(xi u)/dxi, degree 8 in xi)
   are integrated exactly by nl = 5, so the identity holds to the accuracy of
   the differences.  The error of a central difference is set by the
   derivatives of U, not by |Q| (small near the unstrained state), so the
   scale is max(|Q|, |grad U|, max|K|), K the analytic stiffness.
   Tolerance 16 FD of that scale: U is a polynomial of degree 4 in the
   slopes, its third derivatives a few times K; measured 2.8 (m:eg_str_fd)
   FD. */
static void test_energy_gradient_string(void **state)
{
    vlbe_ale_mat m = mat_std();
    const double tol = 16.0 * FD_ERR;
    vlbe_ale_elem el;
    tu_rng g = tu_rng_seed(21);
    double w = 0.0;
    int s, k, i;
    (void)state;
    m.c_eps = m.c_kap = VLBE_R(0.0);
    m.f[0] = m.f[1] = VLBE_R(0.0);
    elem_make(&el, &m, 0, 0, 0, 0);
    for (s = 0; s < 3; ++s) {
        vlbe_real q[10];
        make_state(&g, 0.6, 0.15, q, NULL);
        for (k = 0; k < N_MODES; ++k) {
            const unsigned mode = mode_of(k) | VLBE_ALE_NO_BEND;
            double res[10];
            const double scale = energy_residual(&el, mode, q, res);
            for (i = 0; i < 10; ++i) {
                w = fmax(w, fabs(res[i]) / scale);
                ASSERT_CLOSE_CTX(res[i], 0.0, 0, tol * scale, "row %d, mode %u", i, mode);
            }
        }
    }
    tu_report("string: -Q - grad U (with fluxes)", w, tol);
    tu_measured("eg_str_fd", w / FD_ERR);
}

/* With bending.  e-rows: -Q_e is the e-gradient of the same Gauss sum
   (U_h = sum_g w_g L u(xi_g), differentiated at fixed xi_g and L), so it
   holds to FD accuracy whatever nt: checked with the default nt = 5.
   p-rows: the Leibniz flux identity needs int_0^1 d(xi u)/dxi dxi = u(1),
   exact only for the exact integral; the bending density is rational, so
   the Gauss error of that integral enters.  Mildly curved states (slopes
   within +-0.25 rad of the chord) with nt = 8.  The p-row residuals, max
   over these states and modes, relative to the scale, measured (double):
       nt = 4: 1.3e-4 (m:bend_nt4)  5: 9.6e-6 (m:bend_nt5)
       6: 1.3e-6 (m:bend_nt6)  7: 1.1e-7 (m:bend_nt7)  8: 6.5e-9 (m:bend_nt8)
   (geometric, ~10x per point; nt = 8 is at 10x the FD noise).  Tolerance
   of the p-rows: the FD part 16 FD plus the quadrature part |res7 - res8|,
   the difference between nt = 7 and nt = 8 at the same state, which is the
   Gauss error of nt = 7 to 10 %, so ~10x that of nt = 8: a self-calibrated
   bound that stays small where the flux is right (a wrong or missing flux
   u(p) ~ 1e-1 of the scale shows up equally at nt = 7 and 8 and fails).
   In float the FD part (16 FD = 3.9e-4) dominates.  e-rows: 16 FD.
   Scale as in the string test. */
static void test_energy_gradient_bend(void **state)
{
    vlbe_ale_mat m = mat_std();
    const double tol = 16.0 * FD_ERR;
    vlbe_ale_elem el, el8, el7, eln[3];
    tu_rng g = tu_rng_seed(22);
    double we = 0.0, wp = 0.0, wp7 = 0.0, wq = 0.0, wpn[3] = {0.0, 0.0, 0.0};
    int s, k, i, r;
    (void)state;
    m.c_eps = m.c_kap = VLBE_R(0.0);
    m.f[0] = m.f[1] = VLBE_R(0.0);
    elem_make(&el, &m, 0, 0, 0, 0);
    elem_make(&el8, &m, 0, 8, 8, 8);
    elem_make(&el7, &m, 0, 8, 8, 7);
    for (r = 0; r < 3; ++r) elem_make(&eln[r], &m, 0, 8, 8, 4 + r); /* report only */
    for (s = 0; s < 3; ++s) {
        vlbe_real q[10];
        make_state(&g, 0.25, 0.15, q, NULL);
        for (k = 0; k < N_MODES; ++k) {
            const unsigned mode = mode_of(k);
            double res[10], res8[10], res7[10], resn[3][10], scale, scale8;
            if (mode & VLBE_ALE_NO_BEND) continue; /* the string test covers these */
            scale = energy_residual(&el, mode, q, res);
            for (i = 0; i < 10; ++i) {
                if (is_p(i)) continue;
                we = fmax(we, fabs(res[i]) / scale);
                ASSERT_CLOSE_CTX(res[i], 0.0, 0, tol * scale, "e-row %d, mode %u", i, mode);
            }
            scale8 = energy_residual(&el8, mode, q, res8);
            (void)energy_residual(&el7, mode, q, res7);
            for (r = 0; r < 3; ++r) (void)energy_residual(&eln[r], mode, q, resn[r]);
            for (i = 4; i < 10; i += 5) {
                const double quad = fabs(res7[i] - res8[i]);
                wp = fmax(wp, fabs(res8[i]) / scale8);
                wp7 = fmax(wp7, fabs(res7[i]) / scale8);
                for (r = 0; r < 3; ++r) wpn[r] = fmax(wpn[r], fabs(resn[r][i]) / scale8);
                wq = fmax(wq, fabs(res8[i]) / (tol * scale8 + quad));
                ASSERT_CLOSE_CTX(res8[i], 0.0, 0, tol * scale8 + quad,
                                 "p-row %d, mode %u (nt = 7: %.3g)", i, mode, res7[i]);
            }
        }
    }
    tu_report("bending: e-rows -Q - grad U (nt = 5)", we, tol);
    tu_report("bending: p-rows with fluxes, nt = 8", wp, tol);
    tu_report("bending: p-rows with fluxes, nt = 7 (info)", wp7, tol);
    tu_report("bending: p-rows nt = 8 / (16 FD + |res7 - res8|)", wq, 1.0);
    tu_measured("bend_nt4", wpn[0]);
    tu_measured("bend_nt5", wpn[1]);
    tu_measured("bend_nt6", wpn[2]);
    tu_measured("bend_nt7", wp7);
    tu_measured("bend_nt8", wp);
#ifndef VLBE_USE_FLOAT
    /* the p-row residual is the Gauss error: it shrinks from nt = 7 to 8
       (float: hidden below the FD error 16 FD = 3.9e-4) */
    assert_true(wp < wp7);
#endif
}

/* Load potential V = -int f.r dp: the load part of Q (EA = EI = 0, qd = 0,
   so Q is the load alone) is -dV/de on the e-rows; on the p-rows the end
   points carry the flux f.r: dV/dp1 = f.r(p1) - Q_p1, dV/dp2 = -f.r(p2) -
   Q_p2.  V is a cubic in each coordinate, integrated exactly (nm = 4);
   tolerance 16 FD relative to max(|Q|, |grad V|) (truncation is exact
   h^2 V'''/6 with V''' of the size of V: a few FD); measured
   1.1 (m:load_fd) FD. */
static void test_load_potential(void **state)
{
    vlbe_ale_mat m = mat_std();
    const double tol = 16.0 * FD_ERR;
    vlbe_ale_elem el;
    tu_rng g = tu_rng_seed(23);
    double w = 0.0;
    int s, k, i;
    (void)state;
    m.EA = m.EI = VLBE_R(0.0);
    elem_make(&el, &m, 0, 0, 0, 0);
    for (s = 0; s < 3; ++s) {
        vlbe_real q[10], qd[10], Q[10], r[2] = {0, 0};
        double grad[10], res[10], scale, fr1, fr2;
        make_state(&g, 0.6, 0.15, q, NULL);
        fill(10, VLBE_R(0.0), qd);
        assert_int_equal(vlbe_ale_point(q, q[4], r, NULL), VLBE_OK);
        fr1 = (double)m.f[0] * (double)r[0] + (double)m.f[1] * (double)r[1];
        assert_int_equal(vlbe_ale_point(q, q[9], r, NULL), VLBE_OK);
        fr2 = (double)m.f[0] * (double)r[0] + (double)m.f[1] * (double)r[1];
        for (k = 0; k < N_MODES; ++k) {
            const unsigned mode = mode_of(k);
            assert_int_equal(vlbe_ale_force(&el, mode, q, qd, Q, NULL, NULL), VLBE_OK);
            energy_grad(&OPS, &el, mode, q, qd, 2, grad);
            for (i = 0; i < 10; ++i) res[i] = grad[i] + (double)Q[i];
            res[4] = is_fixed(mode, 4) ? 0.0 : res[4] - fr1;
            res[9] = is_fixed(mode, 9) ? 0.0 : res[9] + fr2;
            scale = fmax(max_abs(10, Q), tu_max_abs(10, grad));
            for (i = 0; i < 10; ++i) {
                w = fmax(w, fabs(res[i]) / scale);
                ASSERT_CLOSE_CTX(res[i], 0.0, 0, tol * scale, "row %d, mode %u", i, mode);
            }
        }
    }
    tu_report("load: -Q_f - grad V (with end fluxes)", w, tol);
    tu_measured("load_fd", w / FD_ERR);
}

/* Transport inertia against the kinetic energy.  Lagrange's equations of
   T = int rhoA |v|^2 / 2 dp over the moving domain [p1, p2] differ from the
   virtual-work form used by the element (Q_a = rhoA int G^T r_v dp, G =
   dr/dq at fixed p) by terms at the element ends only (they cancel between
   neighbours in a chain, where v and G are continuous):
       Mdot qd - dT/dq = Q_a + B,
       B = rhoA [p' G^T v]_{p1}^{p2} + rhoA |v(p1)|^2/2 e_p1 - rhoA |v(p2)|^2/2 e_p2,
   with v(p1) = r1. - r1' p1', v(p2) = r2. - r2' p2' (material velocity at
   the ends), G(p1)^T v = (v at the r1-rows, -r1'.v at the p1-row) and
   G(p2)^T v = (v at the r2-rows, -r2'.v at the p2-row).  (The symmetric
   second derivatives of r make int rhoA (Gdot^T v - dG/dq^T qd . v) vanish.)
   With EA = EI = 0 and f = 0 the force is Q = -Q_a; Mdot qd = Mq qd from
   vlbe_ale_mass_jac (checked against differences above) and dT/dq by
   central differences of E[0].  Tolerance 16 FD relative to the largest of
   |Q|, |Mdot qd|, |dT/dq| (T is quadratic in qd and rational in L, third
   derivatives a few times T); measured 1.9 (m:lg_fd) FD. */
static void test_transport_inertia_lagrange(void **state)
{
    vlbe_ale_mat m = mat_std();
    const double tol = 16.0 * FD_ERR;
    vlbe_ale_elem el;
    tu_rng g = tu_rng_seed(25);
    double w = 0.0;
    int s, k, i, j;
    (void)state;
    m.EA = m.EI = VLBE_R(0.0);
    m.f[0] = m.f[1] = VLBE_R(0.0);
    elem_make(&el, &m, 0, 0, 0, 0);
    for (s = 0; s < 4; ++s) {
        vlbe_real q[10], qd[10];
        make_state(&g, 0.6, 0.15, q, qd);
        for (k = 0; k < N_MODES; ++k) {
            const unsigned mode = mode_of(k);
            const double rho = (double)m.rhoA;
            const double pd1 = is_fixed(mode, 4) ? 0.0 : (double)qd[4];
            const double pd2 = is_fixed(mode, 9) ? 0.0 : (double)qd[9];
            vlbe_real Q[10], Mq[100];
            double dT[10], mdot[10], B[10] = {0}, v1[2], v2[2], scale;
            assert_int_equal(vlbe_ale_force(&el, mode, q, qd, Q, NULL, NULL), VLBE_OK);
            assert_int_equal(vlbe_ale_mass_jac(&el, mode, q, qd, Mq), VLBE_OK);
            energy_grad(&OPS, &el, mode, q, qd, 0, dT);
            for (i = 0; i < 10; ++i) {
                mdot[i] = 0.0;
                for (j = 0; j < 10; ++j) mdot[i] += (double)Mq[i * 10 + j] * (double)qd[j];
            }
            for (i = 0; i < 2; ++i) {
                v1[i] = (double)qd[i] - (double)q[2 + i] * pd1;
                v2[i] = (double)qd[5 + i] - (double)q[7 + i] * pd2;
                B[i] -= rho * pd1 * v1[i];
                B[5 + i] += rho * pd2 * v2[i];
            }
            B[4] = -rho * pd1 * -((double)q[2] * v1[0] + (double)q[3] * v1[1]) +
                   0.5 * rho * (v1[0] * v1[0] + v1[1] * v1[1]);
            B[9] = rho * pd2 * -((double)q[7] * v2[0] + (double)q[8] * v2[1]) -
                   0.5 * rho * (v2[0] * v2[0] + v2[1] * v2[1]);
            scale = fmax(fmax(max_abs(10, Q), tu_max_abs(10, mdot)), tu_max_abs(10, dT));
            for (i = 0; i < 10; ++i) {
                double res;
                if (is_fixed(mode, i)) continue;
                res = mdot[i] - dT[i] + (double)Q[i] - B[i];
                w = fmax(w, fabs(res) / scale);
                ASSERT_CLOSE_CTX(res, 0.0, 0, tol * scale, "row %d, mode %u", i, mode);
            }
        }
    }
    tu_report("Mdot qd - dT/dq - Q_a - B", w, tol);
    tu_measured("lg_fd", w / FD_ERR);
}

/* T = qd^T M qd / 2 (same mode: fixed p's velocities are ignored by both).
   Rounding only: 64 EPS relative to sum |qd_i M_ij qd_j| (the quadrature
   sums of T and M and the double product here); measured
   0.6 (m~:ke_T) EPS. */
static void test_kinetic_energy(void **state)
{
    const vlbe_ale_mat m = mat_std();
    vlbe_ale_elem el;
    tu_rng g = tu_rng_seed(24);
    double w = 0.0;
    int s, k, i;
    (void)state;
    elem_make(&el, &m, 0, 0, 0, 0);
    for (s = 0; s < 4; ++s) {
        vlbe_real q[10], qd[10], M[100], E[3];
        double x[10], absum, t;
        make_state(&g, 0.6, 0.15, q, qd);
        for (i = 0; i < 10; ++i) x[i] = (double)qd[i];
        for (k = 0; k < N_MODES; ++k) {
            const unsigned mode = mode_of(k);
            assert_int_equal(vlbe_ale_mass(&el, mode, q, M), VLBE_OK);
            assert_int_equal(vlbe_ale_energy(&el, mode, q, qd, E), VLBE_OK);
            t = 0.5 * quad_form(10, M, x, &absum);
            w = fmax(w, fabs((double)E[0] - t) / (EPS * absum));
            ASSERT_CLOSE_CTX(E[0], t, 0, 64 * EPS * absum, "mode %u", mode);
            assert_true(E[0] > VLBE_R(0.0));
        }
    }
    tu_report("T - qd^T M qd / 2, in EPS * sum|terms|", w, 64.0);
    tu_measured("ke_T", w);
}

/* ======================================================================= */
/* 3. rigid motion                                                            */
/* ======================================================================= */

/* Straight, unstretched: r' = t (unit) everywhere, so eps = 0 and kap = 0 at
   every point and the elastic forces vanish; qd = 0 and f = 0 switch the
   rest off.  Rounding: eps = (r'.r' - 1)/2 with r' from nodal values of size
   |r| (cancellation ~EPS |r| / L), curvature from r'' ~ EPS |r| / L^2;
   Q ~ EA eps.  Tolerance 64 EPS (1 + |r|/L) EA per row (2.4e-13 at r ~ 10
   in double, below the target 1e-12 of EA), measured 0.7 (m~:rm_Q) EPS
   (1 + |r|/L) EA. */
static void test_rigid_motion(void **state)
{
    static const double angles[] = {0.0, 0.3, 2.1, -1.7, 7.5, -11.2, 100.0};
    static const double shifts[][2] = {{0.0, 0.0}, {3.0, -2.0}, {-10.0, 7.5}};
    static const unsigned modes[] = {0, VLBE_ALE_CONSERVATIVE, VLBE_ALE_FIX_P1 | VLBE_ALE_FIX_P2,
                                     VLBE_ALE_NO_BEND, VLBE_ALE_FIX_P2 | VLBE_ALE_CONSERVATIVE};
    vlbe_ale_mat m = mat_std();
    vlbe_ale_elem el;
    double w = 0.0;
    int ia, is, im, i;
    (void)state;
    m.f[0] = m.f[1] = VLBE_R(0.0);
    elem_make(&el, &m, 0, 0, 0, 0);
    for (ia = 0; ia < ARRAY_LEN(angles); ++ia)
        for (is = 0; is < ARRAY_LEN(shifts); ++is) {
            const double p1 = 0.35, L = 1.25, c = cos(angles[ia]), sn = sin(angles[ia]);
            /* a point at material coordinate 0.2 sits at the shift */
            const double x1 = shifts[is][0] + 0.2 * c, y1 = shifts[is][1] + 0.2 * sn;
            vlbe_real q[10], qd[10], Q[10], E[3];
            double rmax, tol;
            q[0] = (vlbe_real)x1;
            q[1] = (vlbe_real)y1;
            q[2] = (vlbe_real)c;
            q[3] = (vlbe_real)sn;
            q[4] = (vlbe_real)p1;
            q[5] = (vlbe_real)(x1 + L * c);
            q[6] = (vlbe_real)(y1 + L * sn);
            q[7] = (vlbe_real)c;
            q[8] = (vlbe_real)sn;
            q[9] = (vlbe_real)(p1 + L);
            fill(10, VLBE_R(0.0), qd);
            rmax = fmax(fmax(fabs(x1), fabs(y1)), fmax(fabs((double)q[5]), fabs((double)q[6])));
            tol = 64.0 * EPS * (1.0 + rmax / L) * (double)m.EA;
            for (im = 0; im < ARRAY_LEN(modes); ++im) {
                assert_int_equal(vlbe_ale_force(&el, modes[im], q, qd, Q, NULL, NULL), VLBE_OK);
                for (i = 0; i < 10; ++i) {
                    w = fmax(w, fabs((double)Q[i]) / (EPS * (1.0 + rmax / L) * (double)m.EA));
                    ASSERT_CLOSE_CTX(Q[i], 0.0, 0, tol, "angle %g shift %d mode %u row %d",
                                     angles[ia], is, modes[im], i);
                }
                /* no strain energy either (tolerance: U ~ EA eps^2 L) */
                assert_int_equal(vlbe_ale_energy(&el, modes[im], q, qd, E), VLBE_OK);
                ASSERT_CLOSE(E[1], 0.0, 0, tol * tol / (double)m.EA);
                ASSERT_CLOSE(E[0], 0.0, 0, 0); /* at rest: exactly zero */
            }
        }
    tu_report("rigid motion |Q| in EPS (1 + |r|/L) EA", w, 64.0);
    tu_measured("rm_Q", w);
}

/* ======================================================================= */
/* 4. mass matrix                                                             */
/* ======================================================================= */

/* The classic constant mass matrix of the planar ANCF cable (Gerstmayr &
   Shabana), rhoA L * C (x) I2, C on the Hermite data (r1, r1', r2, r2'). */
static double classic_mass(double rhoA, double L, int i, int j)
{
    static const double c[4][4] = {{13.0 / 35.0, 11.0 / 210.0, 9.0 / 70.0, -13.0 / 420.0},
                                   {11.0 / 210.0, 1.0 / 105.0, 13.0 / 420.0, -1.0 / 140.0},
                                   {9.0 / 70.0, 13.0 / 420.0, 13.0 / 35.0, -11.0 / 210.0},
                                   {-13.0 / 420.0, -1.0 / 140.0, -11.0 / 210.0, 1.0 / 105.0}};
    /* slopes carry one power of L each */
    const int pw = (i & 1) + (j & 1);
    return rhoA * L * c[i][j] * (pw == 0 ? 1.0 : pw == 1 ? L : L * L);
}

/* M(q): symmetric bit for bit; total mass rhoA L for unit translations (all
   p-modes); the e-block positive definite (Cholesky) and x^T M x > 0 for
   random x; M[p, p] > 0.  With both p fixed: the classic constant cable
   matrix, independent of the nodal positions and slopes.  With a free p
   the element matrix is only positive SEMI-definite: dr/dp_k at fixed p is
   a cubic in p, hence a combination of the Hermite columns, and the
   re-parametrization that moves p_k together with the matching nodal data
   moves no material point (see the null vector below): one element is
   singular in every ALE mode.  (In a chain the p-column of a shared node
   has the slopes -r''(p_k) from either side: it is in the Hermite span,
   and the chain's mass singular, only where r'' is continuous at the node,
   e.g. a straight or uniformly curved configuration.) */
static void test_mass_properties(void **state)
{
    static const int e_idx[8] = {0, 1, 2, 3, 5, 6, 7, 8};
    static const unsigned pmodes[] = {0, VLBE_ALE_FIX_P1, VLBE_ALE_FIX_P2,
                                      VLBE_ALE_FIX_P1 | VLBE_ALE_FIX_P2};
    const vlbe_ale_mat m = mat_std();
    vlbe_ale_elem el;
    tu_rng g = tu_rng_seed(41);
    double wc = 0.0, wn = 0.0, wt = 0.0;
    int s, im, i, j, a, b;
    (void)state;
    elem_make(&el, &m, 0, 0, 0, 0);
    for (s = 0; s < 4; ++s) {
        vlbe_real q[10], q2[10], M[100], M2[100];
        double L;
        make_state(&g, 0.6, 0.15, q, NULL);
        L = (double)q[9] - (double)q[4];
        for (im = 0; im < ARRAY_LEN(pmodes); ++im) {
            const unsigned mode = pmodes[im];
            double ux[10] = {0}, uy[10] = {0}, x[10], absum, mt;
            assert_int_equal(vlbe_ale_mass(&el, mode, q, M), VLBE_OK);
            check_fixed_zero(mode, NULL, M);
            /* symmetric bit for bit (the code mirrors one triangle) */
            for (i = 0; i < 10; ++i)
                for (j = 0; j < i; ++j) ASSERT_CLOSE(M[i * 10 + j], M[j * 10 + i], 0, 0);
            /* total mass: unit translations; N1 + N3 = 1, rounding of the 4
               Gauss sums and the double products: 16 EPS of rhoA L
               (measured 1 (m~:mp_mass) EPS) */
            ux[0] = ux[5] = 1.0;
            uy[1] = uy[6] = 1.0;
            mt = quad_form(10, M, ux, NULL);
            wt = fmax(wt, fabs(mt / ((double)m.rhoA * L) - 1.0) / EPS);
            ASSERT_CLOSE(mt, (double)m.rhoA * L, 16 * EPS, 0);
            ASSERT_CLOSE(quad_form(10, M, uy, NULL), (double)m.rhoA * L, 16 * EPS, 0);
            /* the e-block (same in every mode) is positive definite */
            assert_true(cholesky_ok(M, 10, e_idx, 8));
            /* x^T M x > 0 for random x, by more than its rounding (16 EPS
               of sum |terms|) */
            for (i = 0; i < 5; ++i) {
                double qf;
                for (j = 0; j < 10; ++j) x[j] = tu_rng_uniform(&g);
                qf = quad_form(10, M, x, &absum);
                assert_true(qf > 16 * EPS * absum);
            }
            /* ALE rows: M[p, p] = rhoA int |dr/dp_k|^2 > 0 on a curved state */
            for (i = 4; i < 10; i += 5)
                if (!is_fixed(mode, i)) assert_true(M[i * 10 + i] > VLBE_R(0.0));
            if (mode == (VLBE_ALE_FIX_P1 | VLBE_ALE_FIX_P2)) {
                /* the classic matrix; rounding of 4 Gauss sums of products
                   of tabulated basis numbers times L powers: 64 EPS
                   relative per entry (2.8e-14 in double; the target 1e-14
                   is ~45 EPS), measured 2.7 (m~:mp_classic) EPS */
                for (i = 0; i < 4; ++i)
                    for (j = 0; j < 4; ++j)
                        for (a = 0; a < 2; ++a)
                            for (b = 0; b < 2; ++b) {
                                const int r = VLBE__ALE_E(i) + a, c = VLBE__ALE_E(j) + b;
                                const double ref =
                                    a == b ? classic_mass((double)m.rhoA, L, i, j) : 0.0;
                                if (a == b)
                                    wc = fmax(wc, fabs((double)M[r * 10 + c] - ref) /
                                                      (EPS * fabs(ref)));
                                ASSERT_CLOSE_CTX(M[r * 10 + c], ref, 64 * EPS, 0,
                                                 "classic mass (%d, %d)", r, c);
                            }
                /* constant: another state with the same p1, p2 gives the same
                   matrix bit for bit */
                make_state(&g, 0.9, 0.3, q2, NULL);
                q2[4] = q[4];
                q2[9] = q[9];
                assert_int_equal(vlbe_ale_mass(&el, mode, q2, M2), VLBE_OK);
                ASSERT_VEC_CLOSE(M2, M, 100, 0, 0);
                assert_true(cholesky_ok(M, 10, e_idx, 8));
            } else {
                /* With a free p the element mass is singular: dr/dp_k at
                   fixed p is itself a cubic in p, so it lies in the span of
                   the Hermite columns.  Its Hermite data: at p1 the value
                   -r'(p1) and slope -r''(p1) for k = 1 (0, 0 at p2), and at
                   p2 the value -r'(p2), slope -r''(p2) for k = 2.  The null
                   vector x = (e-part: minus those data, x_pk = 1)
                   re-parametrizes the element without moving any material
                   point: M x = 0.  Rounding: 64 EPS of max|M| |x|;
                   measured 1.8 (m~:mp_null) EPS. */
                for (i = 4; i < 10; i += 5) {
                    const int k = i == 4 ? 0 : 1;
                    vlbe_herm_ale hb;
                    vlbe_real rpp[2] = {0, 0};
                    const vlbe_real pe = q[i];
                    double xn[10] = {0}, Mx, xs;
                    int r, c2;
                    if (is_fixed(mode, i)) continue;
                    vlbe_herm_ale_eval(pe, q[4], q[9], 2, 0, &hb);
                    for (j = 0; j < 4; ++j) vlbe_v2_axpy(hb.h[2][0][j], q + VLBE__ALE_E(j), rpp);
                    xn[i] = 1.0;
                    xn[k == 0 ? 0 : 5] = (double)q[k == 0 ? 2 : 7];
                    xn[k == 0 ? 1 : 6] = (double)q[k == 0 ? 3 : 8];
                    xn[k == 0 ? 2 : 7] = (double)rpp[0];
                    xn[k == 0 ? 3 : 8] = (double)rpp[1];
                    xs = tu_max_abs(10, xn);
                    for (r = 0; r < 10; ++r) {
                        Mx = 0.0;
                        for (c2 = 0; c2 < 10; ++c2) Mx += (double)M[r * 10 + c2] * xn[c2];
                        wn = fmax(wn, fabs(Mx) / (EPS * max_abs(100, M) * xs));
                        ASSERT_CLOSE_CTX(Mx, 0.0, 0, 64 * EPS * max_abs(100, M) * xs,
                                         "null vector of p%d, row %d, mode %u", k + 1, r, mode);
                    }
                }
            }
        }
    }
    tu_report("classic mass, in EPS relative per entry", wc, 64.0);
    tu_report("M x_null, in EPS max|M| |x|", wn, 64.0);
    tu_report("total mass, in EPS", wt, 16.0);
    tu_measured("mp_mass", wt);
    tu_measured("mp_classic", wc);
    tu_measured("mp_null", wn);
}

/* ======================================================================= */
/* 5. Lagrangian limit                                                        */
/* ======================================================================= */

/* With p1' = p2' = 0 the ALE terms vanish and the e-rows of the full element
   are the Lagrangian (both p fixed) element: Q, the e-block of K and D, and
   M, bit for bit (the same operations; the ALE additions are exact zeros).
   The fixed element ignores the p-velocities: random values there. */
static void test_fixed_equals_lagrangian(void **state)
{
    static const int e_idx[8] = {0, 1, 2, 3, 5, 6, 7, 8};
    const unsigned fix = VLBE_ALE_FIX_P1 | VLBE_ALE_FIX_P2;
    const vlbe_ale_mat m = mat_std();
    vlbe_ale_elem el;
    tu_rng g = tu_rng_seed(51);
    int s, k, i, j;
    (void)state;
    elem_make(&el, &m, 0, 0, 0, 0);
    for (s = 0; s < 3; ++s) {
        vlbe_real q[10], qd[10], qd0[10];
        make_state(&g, 0.6, 0.15, q, qd);
        memcpy(qd0, qd, sizeof qd);
        qd0[4] = qd0[9] = VLBE_R(0.0);
        for (k = 0; k < N_MODES; ++k) {
            const unsigned extra = mode_of(k) & ~fix; /* bend, damp, conservative */
            vlbe_real Qf[10], Kf[100], Df[100], Qa[10], Ka[100], Da[100], Mf[100], Ma[100];
            if (mode_of(k) & fix) continue;
            assert_int_equal(vlbe_ale_force(&el, extra | fix, q, qd, Qf, Kf, Df), VLBE_OK);
            assert_int_equal(vlbe_ale_force(&el, extra, q, qd0, Qa, Ka, Da), VLBE_OK);
            assert_int_equal(vlbe_ale_mass(&el, fix, q, Mf), VLBE_OK);
            assert_int_equal(vlbe_ale_mass(&el, 0, q, Ma), VLBE_OK);
            for (i = 0; i < 8; ++i) {
                const int r = e_idx[i];
                ASSERT_CLOSE_CTX(Qf[r], Qa[r], 0, 0, "Q[%d], mode %u", r, extra);
                for (j = 0; j < 8; ++j) {
                    const int c = e_idx[j];
                    ASSERT_CLOSE_CTX(Kf[r * 10 + c], Ka[r * 10 + c], 0, 0, "K (%d, %d), mode %u", r,
                                     c, extra);
                    ASSERT_CLOSE_CTX(Df[r * 10 + c], Da[r * 10 + c], 0, 0, "D (%d, %d), mode %u", r,
                                     c, extra);
                    ASSERT_CLOSE_CTX(Mf[r * 10 + c], Ma[r * 10 + c], 0, 0, "M (%d, %d)", r, c);
                }
            }
        }
    }
}

/* Flags given to vlbe_ale_elem_init act as bits ORed into every mode: an
   element made with flags F evaluated in mode 0 = an element made with 0
   evaluated in mode F, bit for bit. */
static void test_flags_vs_mode(void **state)
{
    const vlbe_ale_mat m = mat_std();
    vlbe_ale_elem el0, elf;
    vlbe_real q[10], qd[10], a[10];
    tu_rng g = tu_rng_seed(52);
    int k, i;
    (void)state;
    make_state(&g, 0.6, 0.15, q, qd);
    for (i = 0; i < 10; ++i) a[i] = (vlbe_real)tu_rng_uniform(&g);
    elem_make(&el0, &m, 0, 0, 0, 0);
    for (k = 1; k < N_MODES; ++k) {
        vlbe_real Q0[10], K0[100], D0[100], Q1[10], K1[100], D1[100], E0[3], E1[3];
        elem_make(&elf, &m, mode_of(k), 0, 0, 0);
        assert_int_equal(vlbe_ale_force(&el0, mode_of(k), q, qd, Q0, K0, D0), VLBE_OK);
        assert_int_equal(vlbe_ale_force(&elf, 0, q, qd, Q1, K1, D1), VLBE_OK);
        ASSERT_VEC_CLOSE(Q1, Q0, 10, 0, 0);
        ASSERT_VEC_CLOSE(K1, K0, 100, 0, 0);
        ASSERT_VEC_CLOSE(D1, D0, 100, 0, 0);
        assert_int_equal(vlbe_ale_mass(&el0, mode_of(k), q, K0), VLBE_OK);
        assert_int_equal(vlbe_ale_mass(&elf, 0, q, K1), VLBE_OK);
        ASSERT_VEC_CLOSE(K1, K0, 100, 0, 0);
        assert_int_equal(vlbe_ale_mass_jac(&el0, mode_of(k), q, a, K0), VLBE_OK);
        assert_int_equal(vlbe_ale_mass_jac(&elf, 0, q, a, K1), VLBE_OK);
        ASSERT_VEC_CLOSE(K1, K0, 100, 0, 0);
        assert_int_equal(vlbe_ale_energy(&el0, mode_of(k), q, qd, E0), VLBE_OK);
        assert_int_equal(vlbe_ale_energy(&elf, 0, q, qd, E1), VLBE_OK);
        ASSERT_VEC_CLOSE(E1, E0, 3, 0, 0);
        /* and the mode argument cannot clear a flag of the element (Q
           alone: the fast route on both sides) */
        assert_int_equal(vlbe_ale_force(&el0, mode_of(k), q, qd, Q0, NULL, NULL), VLBE_OK);
        assert_int_equal(vlbe_ale_force(&elf, mode_of(k), q, qd, Q1, NULL, NULL), VLBE_OK);
        ASSERT_VEC_CLOSE(Q1, Q0, 10, 0, 0);
        assert_int_equal(vlbe_ale_force(&elf, 0, q, qd, Q1, NULL, NULL), VLBE_OK);
        ASSERT_VEC_CLOSE(Q1, Q0, 10, 0, 0);
    }
}

/* ======================================================================= */
/* 7. bad inputs                                                              */
/* ======================================================================= */

/* Outputs of every eval function, filled with the sentinel before a call
   that must fail and checked unchanged after it. */
typedef struct outs {
    vlbe_real Q[10], K[100], D[100], M[100], E[3], r[2], rp[2], eps, kap;
} outs;

static void outs_fill(outs *o)
{
    fill(10, SENTINEL, o->Q);
    fill(100, SENTINEL, o->K);
    fill(100, SENTINEL, o->D);
    fill(100, SENTINEL, o->M);
    fill(3, SENTINEL, o->E);
    fill(2, SENTINEL, o->r);
    fill(2, SENTINEL, o->rp);
    o->eps = o->kap = SENTINEL;
}

static void outs_check(const outs *o)
{
    assert_all_equal(10, o->Q, SENTINEL);
    assert_all_equal(100, o->K, SENTINEL);
    assert_all_equal(100, o->D, SENTINEL);
    assert_all_equal(100, o->M, SENTINEL);
    assert_all_equal(3, o->E, SENTINEL);
    assert_all_equal(2, o->r, SENTINEL);
    assert_all_equal(2, o->rp, SENTINEL);
    assert_true(o->eps == SENTINEL && o->kap == SENTINEL);
}

/* Every eval function on (q, qd) must fail with want (force, energy, mass,
   mass_jac with a = qd, point, strain, point force at the middle); nothing
   written.  Functions that do not read qd get a state check only when
   qd_only is 0. */
static void expect_fail_all(const vlbe_ale_elem *el, unsigned mode, const vlbe_real *q,
                            const vlbe_real *qd, int qd_only, vlbe_status want)
{
    const vlbe_real F[2] = {VLBE_R(1.0), VLBE_R(-2.0)};
    const vlbe_real pm = VLBE_R(0.5) * (q[4] + q[9]);
    const vlbe_real pmid = pm == pm ? pm : VLBE_R(0.0);
    outs o;
    outs_fill(&o);
    assert_int_equal(vlbe_ale_force(el, mode, q, qd, o.Q, o.K, o.D), want);
    assert_int_equal(vlbe_ale_force(el, mode, q, qd, o.Q, NULL, NULL), want);
    assert_int_equal(vlbe_ale_energy(el, mode, q, qd, o.E), want);
    assert_int_equal(vlbe_ale_mass_jac(el, mode, q, qd, o.M), want);
    if (!qd_only) {
        assert_int_equal(vlbe_ale_mass(el, mode, q, o.M), want);
        assert_int_equal(vlbe_ale_point(q, pmid, o.r, o.rp), want);
        assert_int_equal(vlbe_ale_strain(q, pmid, &o.eps, &o.kap), want);
        assert_int_equal(vlbe_ale_point_force(q, pmid, F, o.Q, o.K), want);
    }
    outs_check(&o);
}

static void test_errors_eval(void **state)
{
    const vlbe_ale_mat m = mat_std();
    const vlbe_real bad[3] = {(vlbe_real)NAN, (vlbe_real)INFINITY, -(vlbe_real)INFINITY};
    const vlbe_real F[2] = {VLBE_R(1.0), VLBE_R(-2.0)};
    vlbe_ale_elem el;
    vlbe_real q[10], qd[10], qb[10], qdb[10];
    tu_rng g = tu_rng_seed(71);
    outs o;
    int i, b, k;
    (void)state;
    elem_make(&el, &m, 0, 0, 0, 0);
    make_state(&g, 0.6, 0.15, q, qd);

    /* length: p2 = p1 and p2 < p1, in every mode (fixed p's still define L) */
    for (k = 0; k < N_MODES; ++k) {
        memcpy(qb, q, sizeof qb);
        qb[9] = qb[4];
        expect_fail_all(&el, mode_of(k), qb, qd, 0, VLBE_ELENGTH);
        qb[9] = qb[4] - VLBE_R(0.5);
        expect_fail_all(&el, mode_of(k), qb, qd, 0, VLBE_ELENGTH);
    }

    /* non-finite q (every entry, NaN and both infinities) and qd */
    for (i = 0; i < 10; ++i)
        for (b = 0; b < 3; ++b) {
            memcpy(qb, q, sizeof qb);
            qb[i] = bad[b];
            expect_fail_all(&el, 0, qb, qd, 0, VLBE_ENONFINITE);
            expect_fail_all(&el, VLBE_ALE_FIX_P1 | VLBE_ALE_FIX_P2, qb, qd, 0, VLBE_ENONFINITE);
            memcpy(qdb, qd, sizeof qdb);
            qdb[i] = bad[b];
            expect_fail_all(&el, 0, q, qdb, 1, VLBE_ENONFINITE);
            /* even where the mode ignores the entry (fixed p's velocity) */
            expect_fail_all(&el, VLBE_ALE_FIX_P1 | VLBE_ALE_FIX_P2, q, qdb, 1, VLBE_ENONFINITE);
        }
    /* non-finite point argument */
    for (b = 0; b < 3; ++b) {
        const vlbe_real Fb[2] = {bad[b], VLBE_R(0.0)};
        outs_fill(&o);
        assert_int_equal(vlbe_ale_point(q, bad[b], o.r, o.rp), VLBE_ENONFINITE);
        assert_int_equal(vlbe_ale_strain(q, bad[b], &o.eps, &o.kap), VLBE_ENONFINITE);
        assert_int_equal(vlbe_ale_point_force(q, bad[b], F, o.Q, o.K), VLBE_ENONFINITE);
        assert_int_equal(vlbe_ale_point_force(q, q[4], Fb, o.Q, o.K), VLBE_ENONFINITE);
        outs_check(&o);
    }

    /* zero slope everywhere (r1 = r2, r1' = r2' = 0): the curvature is
       undefined at every bending point -> ESINGULAR from force (with and
       without Jacobians, and from the end fluxes) and energy; the string
       and EI = 0 have no curvature and succeed */
    memcpy(qb, q, sizeof qb);
    qb[5] = qb[0];
    qb[6] = qb[1];
    qb[2] = qb[3] = qb[7] = qb[8] = VLBE_R(0.0);
    for (k = 0; k < N_MODES; ++k) {
        const unsigned mode = mode_of(k);
        const vlbe_status want = (mode & VLBE_ALE_NO_BEND) ? VLBE_OK : VLBE_ESINGULAR;
        outs_fill(&o);
        assert_int_equal(vlbe_ale_force(&el, mode, qb, qd, o.Q, o.K, o.D), want);
        if (want == VLBE_OK) {
            /* all finite: the string at eps = -1/2 */
            assert_int_equal(vlbe_all_finite(o.Q, 10), 1);
            assert_int_equal(vlbe_all_finite(o.K, 100), 1);
            assert_int_equal(vlbe_all_finite(o.D, 100), 1);
            outs_fill(&o);
        }
        assert_int_equal(vlbe_ale_force(&el, mode, qb, qd, o.Q, NULL, NULL), want);
        if (want == VLBE_OK) outs_fill(&o);
        assert_int_equal(vlbe_ale_energy(&el, mode, qb, qd, o.E), want);
        if (want != VLBE_OK) outs_check(&o);
        /* mass and its Jacobian need no slope */
        assert_int_equal(vlbe_ale_mass(&el, mode, qb, o.M), VLBE_OK);
        assert_int_equal(vlbe_ale_mass_jac(&el, mode, qb, qd, o.K), VLBE_OK);
    }
    {
        vlbe_ale_mat m0 = m;
        vlbe_ale_elem el0;
        m0.EI = VLBE_R(0.0);
        elem_make(&el0, &m0, 0, 0, 0, 0);
        assert_int_equal(vlbe_ale_force(&el0, VLBE_ALE_CONSERVATIVE, qb, qd, o.Q, o.K, o.D),
                         VLBE_OK);
        assert_int_equal(vlbe_ale_energy(&el0, 0, qb, qd, o.E), VLBE_OK);
    }
    /* zero slope at node 1 only: the Gauss points are interior and fine,
       but the energy flux of CONSERVATIVE needs the curvature at the free
       end p1 -> ESINGULAR there, and only there */
    {
        static const unsigned ok_modes[] = {0, VLBE_ALE_CONSERVATIVE | VLBE_ALE_FIX_P1,
                                            VLBE_ALE_CONSERVATIVE | VLBE_ALE_NO_BEND,
                                            VLBE_ALE_FIX_P2 | VLBE_ALE_NO_DAMP};
        vlbe_real q1[10];
        memcpy(q1, q, sizeof q1);
        q1[2] = q1[3] = VLBE_R(0.0);
        for (i = 0; i < ARRAY_LEN(ok_modes); ++i)
            assert_int_equal(vlbe_ale_force(&el, ok_modes[i], q1, qd, o.Q, o.K, o.D), VLBE_OK);
        assert_int_equal(vlbe_ale_energy(&el, VLBE_ALE_CONSERVATIVE, q1, qd, o.E), VLBE_OK);
        outs_fill(&o);
        assert_int_equal(vlbe_ale_force(&el, VLBE_ALE_CONSERVATIVE, q1, qd, o.Q, o.K, o.D),
                         VLBE_ESINGULAR);
        assert_int_equal(vlbe_ale_force(&el, VLBE_ALE_CONSERVATIVE | VLBE_ALE_FIX_P2, q1, qd, o.Q,
                                        NULL, NULL),
                         VLBE_ESINGULAR);
        assert_int_equal(vlbe_ale_strain(q1, q1[4], &o.eps, &o.kap), VLBE_ESINGULAR);
        outs_check(&o);
    }

    /* vlbe_ale_strain: the curvature needs the slope, the strain does not */
    outs_fill(&o);
    assert_int_equal(vlbe_ale_strain(qb, qb[4], &o.eps, &o.kap), VLBE_ESINGULAR);
    assert_int_equal(vlbe_ale_strain(qb, qb[4], NULL, &o.kap), VLBE_ESINGULAR);
    outs_check(&o);
    assert_int_equal(vlbe_ale_strain(qb, qb[4], &o.eps, NULL), VLBE_OK);
    ASSERT_CLOSE(o.eps, -0.5, 0, 0);

    /* point force outside [p1, p2] (just outside too); the ends are inside */
    {
        const vlbe_real outside[4] = {q[4] - VLBE_R(0.3), q[9] + VLBE_R(0.3),
                                      q[4] - VLBE_R(4.0) * VLBE_EPS * q[4],
                                      q[9] + VLBE_R(4.0) * VLBE_EPS * q[9]};
        for (i = 0; i < 4; ++i) {
            outs_fill(&o);
            assert_true(outside[i] < q[4] || outside[i] > q[9]);
            assert_int_equal(vlbe_ale_point_force(q, outside[i], F, o.Q, o.K), VLBE_EBOUND);
            assert_int_equal(vlbe_ale_point_force(q, outside[i], F, o.Q, NULL), VLBE_EBOUND);
            outs_check(&o);
        }
        fill(10, VLBE_R(0.0), o.Q);
        assert_int_equal(vlbe_ale_point_force(q, q[4], F, o.Q, NULL), VLBE_OK);
        assert_int_equal(vlbe_ale_point_force(q, q[9], F, o.Q, NULL), VLBE_OK);
    }
}

static void test_errors_init(void **state)
{
    static const int bad_orders[] = {-1, VLBE_ALE_NGP_MAX + 1, 100};
    const vlbe_ale_mat good = mat_std();
    const vlbe_real nonfinite[3] = {(vlbe_real)NAN, (vlbe_real)INFINITY, -(vlbe_real)INFINITY};
    vlbe_ale_elem el, ref;
    vlbe_ale_mat m;
    int i, b, f;
    (void)state;
    memset(&ref, 0x5a, sizeof ref);
#define EXPECT_INIT(mat_, nm_, nl_, nt_, want_)                                              \
    do {                                                                                     \
        memset(&el, 0x5a, sizeof el);                                                        \
        assert_int_equal(vlbe_ale_elem_init(&el, &(mat_), 0, (nm_), (nl_), (nt_)), (want_)); \
        assert_true(memcmp(&el, &ref, sizeof el) == 0);                                      \
    } while (0)
    /* rhoA must be > 0; the stiffnesses and damping coefficients >= 0 */
    m = good;
    m.rhoA = VLBE_R(0.0);
    EXPECT_INIT(m, 0, 0, 0, VLBE_EARG);
    m.rhoA = -VLBE_R(0.0);
    EXPECT_INIT(m, 0, 0, 0, VLBE_EARG);
    m.rhoA = VLBE_R(-1.0);
    EXPECT_INIT(m, 0, 0, 0, VLBE_EARG);
    for (f = 0; f < 4; ++f) {
        m = good;
        *(f == 0 ? &m.EA : f == 1 ? &m.EI : f == 2 ? &m.c_eps : &m.c_kap) = VLBE_R(-0.5);
        EXPECT_INIT(m, 0, 0, 0, VLBE_EARG);
    }
    /* non-finite in every field */
    for (f = 0; f < 7; ++f)
        for (b = 0; b < 3; ++b) {
            vlbe_real *field[7];
            m = good;
            field[0] = &m.rhoA;
            field[1] = &m.EA;
            field[2] = &m.EI;
            field[3] = &m.c_eps;
            field[4] = &m.c_kap;
            field[5] = &m.f[0];
            field[6] = &m.f[1];
            *field[f] = nonfinite[b];
            EXPECT_INIT(m, 0, 0, 0, VLBE_ENONFINITE);
        }
    /* Gauss orders out of [0, 8], each term */
    for (i = 0; i < ARRAY_LEN(bad_orders); ++i) {
        EXPECT_INIT(good, bad_orders[i], 0, 0, VLBE_EARG);
        EXPECT_INIT(good, 0, bad_orders[i], 0, VLBE_EARG);
        EXPECT_INIT(good, 0, 0, bad_orders[i], VLBE_EARG);
    }
#undef EXPECT_INIT
    /* accepted: the limits, zero stiffnesses and damping; 0 = the defaults */
    m = good;
    m.EA = m.EI = m.c_eps = m.c_kap = VLBE_R(0.0);
    assert_int_equal(vlbe_ale_elem_init(&el, &m, 0, 1, 1, VLBE_ALE_NGP_MAX), VLBE_OK);
    assert_int_equal(el.rm.n, 1);
    assert_int_equal(el.rl.n, 1);
    assert_int_equal(el.rt.n, VLBE_ALE_NGP_MAX);
    assert_int_equal(vlbe_ale_elem_init(&el, &good, VLBE_ALE_NO_BEND, 0, 0, 0), VLBE_OK);
    assert_int_equal(el.rm.n, 4);
    assert_int_equal(el.rl.n, 5);
    assert_int_equal(el.rt.n, 5);
    assert_true(el.flags == VLBE_ALE_NO_BEND);
}

/* ======================================================================= */
/* 8. quadrature exactness                                                    */
/* ======================================================================= */

/* Mass, transport inertia and load (degree 6 in xi) with nm = 4, 5, 8, and
   the axial force with its Jacobians (degree 8) with nl = 5, 8, give the
   same numbers to rounding.  The string (NO_BEND) makes the whole force
   polynomial, so Q, K, D all agree.  Tolerance: 64 EPS relative to the
   largest entry of the compared array (2.8e-14 in double; the targets
   1e-14 for M and 1e-13 for the force are ~45 and ~450 EPS);
   measured 2.4 (m~:qd_M) EPS for M and 3.9 (m~:qd_QKD) EPS for Q, K, D
   (Gauss sums of terms a few times larger than the result). */
static void test_quadrature_exactness(void **state)
{
    static const int nms[] = {4, 5, 8};
    const vlbe_ale_mat m = mat_std();
    const double tol = 64.0 * EPS;
    vlbe_ale_elem el[3], e8;
    tu_rng g = tu_rng_seed(81);
    double wm = 0.0, wf = 0.0;
    int s, k, r;
    (void)state;
    for (r = 0; r < 3; ++r) elem_make(&el[r], &m, 0, nms[r], 5, 0);
    elem_make(&e8, &m, 0, 8, 8, 0);
    for (s = 0; s < 3; ++s) {
        vlbe_real q[10], qd[10], a[10];
        int i;
        make_state(&g, 0.6, 0.15, q, qd);
        for (i = 0; i < 10; ++i) a[i] = (vlbe_real)tu_rng_uniform(&g);
        for (k = 0; k < N_MODES; ++k) {
            const unsigned mode = mode_of(k) | VLBE_ALE_NO_BEND;
            vlbe_real M8[100], M[100], Q8[10], K8[100], D8[100], Q[10], K[100], D[100];
            double sc;
            assert_int_equal(vlbe_ale_mass(&el[2], mode, q, M8), VLBE_OK);
            for (r = 0; r < 2; ++r) {
                assert_int_equal(vlbe_ale_mass(&el[r], mode, q, M), VLBE_OK);
                sc = max_abs(100, M8);
                for (i = 0; i < 100; ++i) wm = fmax(wm, fabs((double)M[i] - (double)M8[i]) / sc);
                ASSERT_VEC_CLOSE(M, M8, 100, 0, tol * sc);
                assert_int_equal(vlbe_ale_mass_jac(&el[r], mode, q, a, M), VLBE_OK);
                assert_int_equal(vlbe_ale_mass_jac(&el[2], mode, q, a, M8), VLBE_OK);
                sc = max_abs(100, M8);
                ASSERT_VEC_CLOSE(M, M8, 100, 0, tol * (sc > 0.0 ? sc : 1.0));
                assert_int_equal(vlbe_ale_mass(&el[2], mode, q, M8), VLBE_OK);
            }
            assert_int_equal(vlbe_ale_force(&el[0], mode, q, qd, Q, K, D), VLBE_OK);
            assert_int_equal(vlbe_ale_force(&e8, mode, q, qd, Q8, K8, D8), VLBE_OK);
            sc = max_abs(10, Q8);
            for (i = 0; i < 10; ++i) wf = fmax(wf, fabs((double)Q[i] - (double)Q8[i]) / sc);
            ASSERT_VEC_CLOSE(Q, Q8, 10, 0, tol * sc);
            sc = max_abs(100, K8);
            for (i = 0; i < 100; ++i) wf = fmax(wf, fabs((double)K[i] - (double)K8[i]) / sc);
            ASSERT_VEC_CLOSE(K, K8, 100, 0, tol * sc);
            sc = max_abs(100, D8);
            for (i = 0; i < 100; ++i) wf = fmax(wf, fabs((double)D[i] - (double)D8[i]) / sc);
            ASSERT_VEC_CLOSE(D, D8, 100, 0, tol * sc);
        }
    }
    tu_report("mass nm = 4, 5 vs 8, in EPS of max|M|", wm / EPS, 64.0);
    tu_report("string force nl = 5 vs 8, in EPS of max", wf / EPS, 64.0);
    tu_measured("qd_M", wm / EPS);
    tu_measured("qd_QKD", wf / EPS);
}

/* ======================================================================= */
/* 9. vlbe_ale_point, vlbe_ale_strain                                         */
/* ======================================================================= */

/* At the nodes (xi = 0, 1) the Hermite basis is exactly 0/1 and its slopes
   exactly 0/1: r and r' are the nodal data bit for bit; the strain and
   curvature there equal those of the nodal slope (eps exactly, kap to a
   few EPS: r'' is a sum of four products). */
static void test_point_at_nodes(void **state)
{
    tu_rng g = tu_rng_seed(91);
    int s, n;
    (void)state;
    for (s = 0; s < 6; ++s) {
        vlbe_real q[10];
        make_state(&g, 0.6, 0.15, q, NULL);
        for (n = 0; n < 2; ++n) {
            const int o = n * 5;
            vlbe_real r[2], rp[2], eps, kap;
            double gg;
            assert_int_equal(vlbe_ale_point(q, q[4 + o], r, rp), VLBE_OK);
            ASSERT_CLOSE(r[0], q[o + 0], 0, 0);
            ASSERT_CLOSE(r[1], q[o + 1], 0, 0);
            ASSERT_CLOSE(rp[0], q[o + 2], 0, 0);
            ASSERT_CLOSE(rp[1], q[o + 3], 0, 0);
            /* either output alone */
            fill(2, SENTINEL, rp);
            assert_int_equal(vlbe_ale_point(q, q[4 + o], r, NULL), VLBE_OK);
            assert_int_equal(vlbe_ale_point(q, q[4 + o], NULL, rp), VLBE_OK);
            ASSERT_CLOSE(rp[0], q[o + 2], 0, 0);
            assert_int_equal(vlbe_ale_strain(q, q[4 + o], &eps, &kap), VLBE_OK);
            gg = (double)q[o + 2] * (double)q[o + 2] + (double)q[o + 3] * (double)q[o + 3];
            ASSERT_CLOSE(eps, 0.5 * (gg - 1.0), 4 * EPS, 4 * EPS); /* two products, a sum */
            assert_true(kap == kap && fabs((double)kap) < 10.0);
        }
    }
}

/* Uniformly stretched straight element, r(p) = r0 + s t (p - p1): the cubic
   reproduces it, eps = (s^2 - 1)/2 at every p and kap = 0.  Rounding: r' is
   a sum of four products of size |r|/L: 32 EPS (1 + |r|/L) s^2 for eps
   (measured 1.4 (m~:st_eps)), and kap ~ |r''| / s^2 with r'' = 0 up to
   EPS |r| / L^2. */
static void test_strain_stretched(void **state)
{
    static const double stretches[] = {0.8, 1.0, 1.05, 1.5};
    /* outside [0, 1]: vlbe_ale_point and _strain extrapolate the cubic */
    static const double xis[] = {-0.3, 0.0, 0.1, 0.37, 0.5, 0.77, 1.0, 1.4};
    double we = 0.0, wk = 0.0;
    int is, ix, ia;
    (void)state;
    for (is = 0; is < ARRAY_LEN(stretches); ++is)
        for (ia = 0; ia < 3; ++ia) {
            const double s = stretches[is], th = 1.3 * ia - 0.4, p1 = -0.7 + 0.5 * ia, L = 0.9;
            const double c = cos(th), sn = sin(th), x1 = 2.0, y1 = -1.0;
            vlbe_real q[10];
            double rmax, tol;
            q[0] = (vlbe_real)x1;
            q[1] = (vlbe_real)y1;
            q[2] = (vlbe_real)(s * c);
            q[3] = (vlbe_real)(s * sn);
            q[4] = (vlbe_real)p1;
            q[5] = (vlbe_real)(x1 + s * L * c);
            q[6] = (vlbe_real)(y1 + s * L * sn);
            q[7] = q[2];
            q[8] = q[3];
            q[9] = (vlbe_real)(p1 + L);
            rmax = fmax(fmax(fabs(x1), fabs(y1)), fmax(fabs((double)q[5]), fabs((double)q[6])));
            tol = 32.0 * EPS * (1.0 + rmax / L) * s * s;
            for (ix = 0; ix < ARRAY_LEN(xis); ++ix) {
                const vlbe_real p = (vlbe_real)((double)q[4] + xis[ix] * L);
                vlbe_real eps, kap, r[2] = {0, 0}; /* set by the asserted call */
                assert_int_equal(vlbe_ale_strain(q, p, &eps, &kap), VLBE_OK);
                we = fmax(we, fabs((double)eps - 0.5 * (s * s - 1.0)) /
                                  (EPS * (1.0 + rmax / L) * s * s));
                wk = fmax(wk, fabs((double)kap) / (EPS * (1.0 + rmax / L) / L));
                ASSERT_CLOSE_CTX(eps, 0.5 * (s * s - 1.0), 0, tol, "s %g xi %g", s, xis[ix]);
                ASSERT_CLOSE_CTX(kap, 0.0, 0, 32.0 * EPS * (1.0 + rmax / L) / L, "s %g xi %g", s,
                                 xis[ix]);
                /* and the point is on the line */
                assert_int_equal(vlbe_ale_point(q, p, r, NULL), VLBE_OK);
                ASSERT_CLOSE(r[0], x1 + s * ((double)p - p1) * c, 0, 8.0 * EPS * (rmax + L));
                ASSERT_CLOSE(r[1], y1 + s * ((double)p - p1) * sn, 0, 8.0 * EPS * (rmax + L));
            }
        }
    tu_report("stretched: eps, in EPS (1 + |r|/L) s^2", we, 32.0);
    tu_report("stretched: kap, in EPS (1 + |r|/L) / L", wk, 32.0);
    tu_measured("st_eps", we);
}

/* A circular arc of radius R and angle theta, r(p) = c + R (sin(p/R),
   -cos(p/R)) with unit slopes at the nodes (unstretched).  The cubic
   Hermite interpolation error is e(p) = f''''(p-p1)^2 (p-p2)^2 / 24 with
   |f''''| = 1/R^3 along the normal: R theta^4 / 384 in position at the
   middle, and in the second derivative |f''''| L^2 / 24 at the middle and
   L^2 / 12 at the ends.  So the curvature is 1/R only to O(theta^2)
   relative, theta^2/24 at the middle and theta^2/12 at the ends (the
   theta^4 is the position's order, not the curvature's).  Checked:
   positive curvature (counter-clockwise), |kap R - 1| <= 1.05 theta^2/12
   everywhere; at the middle and the ends the error is 0.95 .. 1.05 times
   its asymptotic value (higher-order terms O(theta^2) of it: measured
   0.984 (m:arc_min) .. 1.000 (m:arc_max) in double), plus rounding 32 EPS
   / theta^2 (r'' of size 1/R from positions of size R over L^2: float up
   to 1.4 % at theta = 0.1, measured 1.013 (m@flt:arc_end)); the position
   error likewise against
   R theta^4/384 (+ 16 EPS R); and ratio 3.5 .. 4.5 per halving of theta
   (second order).  theta = 0.4, 0.2, 0.1. */
static void test_curvature_arc(void **state)
{
    static const double thetas[] = {0.4, 0.2, 0.1};
    static const double radii[] = {0.5, 3.0};
    double wm = 0.0, we = 0.0, wp = 0.0, rmin = HUGE_VAL;
    int ir, it, ix;
    (void)state;
    for (ir = 0; ir < ARRAY_LEN(radii); ++ir) {
        double prev_mid = 0.0, prev_end = 0.0;
        for (it = 0; it < ARRAY_LEN(thetas); ++it) {
            const double R = radii[ir], th = thetas[it], L = R * th, p1 = 0.25;
            const double a0 = 0.7;                  /* rotation of the whole arc */
            const double rnd = 32.0 * EPS / (th * th); /* rounding of kap R */
            vlbe_real q[10];
            double emid = 0.0, eend = 0.0, epos;
            int n;
            for (n = 0; n < 2; ++n) {
                const double phi = a0 + n * th; /* tangent angle */
                q[5 * n + 0] = (vlbe_real)(R * sin(phi));
                q[5 * n + 1] = (vlbe_real)(-R * cos(phi));
                q[5 * n + 2] = (vlbe_real)cos(phi);
                q[5 * n + 3] = (vlbe_real)sin(phi);
            }
            q[4] = (vlbe_real)p1;
            q[9] = (vlbe_real)(p1 + L);
            for (ix = 0; ix <= 4; ++ix) {
                const double xi = 0.25 * ix;
                vlbe_real kap;
                double rel;
                assert_int_equal(vlbe_ale_strain(q, (vlbe_real)(p1 + xi * L), NULL, &kap),
                                 VLBE_OK);
                rel = fabs((double)kap * R - 1.0);
                assert_true((double)kap > 0.0); /* counter-clockwise: positive */
                ASSERT_CLOSE_CTX(rel, 0.0, 0, th * th / 12.0 * 1.05 + rnd, "R %g theta %g xi %g", R,
                                 th, xi);
                if (ix == 2) emid = rel;
                if (ix == 0) eend = rel;
            }
            ASSERT_CLOSE(emid, th * th / 24.0, 0, th * th / 24.0 * 0.05 + rnd);
            ASSERT_CLOSE(eend, th * th / 12.0, 0, th * th / 12.0 * 0.05 + rnd);
            wm = fmax(wm, emid / (th * th / 24.0));
            we = fmax(we, eend / (th * th / 12.0));
            rmin = fmin(rmin, fmin(emid / (th * th / 24.0), eend / (th * th / 12.0)));
            /* position at the middle: R theta^4 / 384, and bounded by it */
            {
                vlbe_real r[2];
                const double phi = a0 + 0.5 * th;
                assert_int_equal(vlbe_ale_point(q, (vlbe_real)(p1 + 0.5 * L), r, NULL), VLBE_OK);
                epos = hypot((double)r[0] - R * sin(phi), (double)r[1] + R * cos(phi));
                ASSERT_CLOSE(epos, R * pow(th, 4) / 384.0, 0,
                             R * pow(th, 4) / 384.0 * 0.05 + 16 * EPS * R);
                wp = fmax(wp, epos / (R * pow(th, 4) / 384.0));
            }
            if (it > 0) {
                /* second order: ratio 4 per halving, within 3.5 .. 4.5 */
                assert_true(prev_mid / emid > 3.5 && prev_mid / emid < 4.5);
                assert_true(prev_end / eend > 3.5 && prev_end / eend < 4.5);
            }
            prev_mid = emid;
            prev_end = eend;
        }
    }
    tu_report("arc: kap err at middle / (theta^2/24)", wm, 1.05);
    tu_report("arc: kap err at ends / (theta^2/12)", we, 1.05);
    tu_report("arc: position err at middle / (R theta^4/384)", wp, 1.05);
    tu_measured("arc_min", rmin);
    tu_measured("arc_max", fmax(wm, we));
    tu_measured("arc_end", we);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_force_jacobians),
        cmocka_unit_test(test_jacobian_outputs),
        cmocka_unit_test(test_mass_jacobian),
        cmocka_unit_test(test_point_force_jacobian),
        cmocka_unit_test(test_energy_gradient_string),
        cmocka_unit_test(test_energy_gradient_bend),
        cmocka_unit_test(test_load_potential),
        cmocka_unit_test(test_transport_inertia_lagrange),
        cmocka_unit_test(test_kinetic_energy),
        cmocka_unit_test(test_rigid_motion),
        cmocka_unit_test(test_mass_properties),
        cmocka_unit_test(test_fixed_equals_lagrangian),
        cmocka_unit_test(test_flags_vs_mode),
        cmocka_unit_test(test_errors_eval),
        cmocka_unit_test(test_errors_init),
        cmocka_unit_test(test_quadrature_exactness),
        cmocka_unit_test(test_point_at_nodes),
        cmocka_unit_test(test_strain_stretched),
        cmocka_unit_test(test_curvature_arc),
    };
    return cmocka_run_group_tests_name("ancf_ale", tests, NULL, NULL);
}
