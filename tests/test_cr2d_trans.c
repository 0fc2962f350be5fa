/* test_cr2d_trans.c -- cmocka suite of the transition element of corot2d.h
   (Hsiao et al. section 2.5: an element across the exit of a prismatic
   joint) -- part of vlbe                           SPDX-License-Identifier: MIT

   Tests
     trans_jacobians     K = dQ/dq, D = dQ/dq', d(M a)/dq against central
                         differences at random states (node 1 inside by up
                         to L/3 or just outside, node 2 outside, arbitrary
                         joint axis), every mode but LINEAR
     trans_energy        q' = 0: Q = -grad U (differences of U); U has the
                         closed form of the header with L1 from eq. 24
     trans_lengths       eq. 24 holds exactly: l1/L1 = l2/L2 + eps_v with
                         L1 + L2 = L, eps_v = (1/2L2) int v'^2 by Gauss
                         quadrature of the Hermite v written here
     trans_conventional  node 1 at the exit (L1 = 0), outside chord along the
                         axis: energy, mass, node-2 forces and stiffness of
                         the conventional element with theta1 = theta3
     trans_rigid         rigid translation along the axis: no elastic force
     trans_errors        EBOUND, EARG, ENONFINITE; outputs untouched
   Tolerances in each test's comment; FD = EPS^(2/3), the error unit of a
   central difference with step EPS^(1/3). */
#include "test_util.h"
#include "../corot2d.h"
#include "cr2d_fixtures.h"

#include <string.h>

#define EPS ((double)VLBE_EPS)
#define FD_STEP (cbrt(EPS))
#define FD_ERR (EPS / FD_STEP)


/* A joint with axis at angle ax through C, and an element of length L
   along it with node 1 at distance d1 inside (negative: outside); the
   state deforms it: node 1 moved along the axis by s1 (and across it by
   w1: the joint's constraints would hold w1 = phi1 = 0, the element must
   ignore them), node 2 at chord angle b2 from C and distance l2, phi2. */
typedef struct tcase {
    vlbe_cr2d_joint jt;
    vlbe_cr2d_elem el;
    vlbe_real q[6], qd[6];
} tcase;

static void tcase_make(tcase *c, const vlbe_cr2d_mat *m, double ax, double L, double d1,
                       tu_rng *g, double defo)
{
    const double ca = cos(ax), sa = sin(ax), Cx = 0.3, Cy = -0.2;
    vlbe_real X1[2], X2[2];
    double s1, b2, l2, x2, y2;
    int i;
    c->jt.C[0] = (vlbe_real)Cx;
    c->jt.C[1] = (vlbe_real)Cy;
    c->jt.a[0] = (vlbe_real)ca;
    c->jt.a[1] = (vlbe_real)sa;
    X1[0] = (vlbe_real)(Cx - d1 * ca);
    X1[1] = (vlbe_real)(Cy - d1 * sa);
    X2[0] = (vlbe_real)(Cx + (L - d1) * ca);
    X2[1] = (vlbe_real)(Cy + (L - d1) * sa);
    assert_int_equal(vlbe_cr2d_elem_init(&c->el, m, X1, X2, 0), VLBE_OK);
    s1 = 0.02 * defo * tu_rng_uniform(g) * L;
    b2 = ax + 0.3 * defo * tu_rng_uniform(g);
    l2 = (L - d1) * (1.0 + 0.05 * defo * tu_rng_uniform(g));
    x2 = Cx + l2 * cos(b2);
    y2 = Cy + l2 * sin(b2);
    c->q[0] = (vlbe_real)(s1 * ca + 0.01 * defo * tu_rng_uniform(g) * (-sa));
    c->q[1] = (vlbe_real)(s1 * sa + 0.01 * defo * tu_rng_uniform(g) * ca);
    c->q[2] = (vlbe_real)(0.1 * defo * tu_rng_uniform(g));
    c->q[3] = (vlbe_real)(x2 - (double)X2[0]);
    c->q[4] = (vlbe_real)(y2 - (double)X2[1]);
    c->q[5] = (vlbe_real)(0.4 * defo * tu_rng_uniform(g) + 2.0 * CR_PI * 3.0);
    for (i = 0; i < 6; ++i) c->qd[i] = (vlbe_real)tu_rng_uniform(g);
}

static double maxabs(int n, const vlbe_real *a)
{
    double m = 0.0;
    int i;
    for (i = 0; i < n; ++i) m = fmax(m, fabs((double)a[i]));
    return m;
}

/* Central differences of Q (in q or in q') and of M a (in q), column j. */
enum { D_QQ, D_QQD, D_MA };
static void tdiff(const tcase *c, unsigned mode, int which, int j, const vlbe_real *a, double h,
                  double *col)
{
    vlbe_real q[6], qd[6], Qp[6] = {0, 0, 0, 0, 0, 0}, Qm[6] = {0, 0, 0, 0, 0, 0}, M[36];
    int s, i, k;
    for (s = 0; s < 2; ++s) {
        vlbe_real *out = s ? Qm : Qp;
        memcpy(q, c->q, sizeof q);
        memcpy(qd, c->qd, sizeof qd);
        if (which == D_QQD)
            qd[j] += (vlbe_real)(s ? -h : h);
        else
            q[j] += (vlbe_real)(s ? -h : h);
        if (which == D_MA) {
            assert_int_equal(vlbe_cr2d_trans_mass(&c->el, &c->jt, mode, q, M), VLBE_OK);
            for (i = 0; i < 6; ++i) {
                out[i] = VLBE_R(0.0);
                for (k = 0; k < 6; ++k) out[i] += M[i * 6 + k] * a[k];
            }
        } else
            assert_int_equal(vlbe_cr2d_trans_force(&c->el, &c->jt, mode, q, qd, out, NULL, NULL),
                             VLBE_OK);
    }
    for (i = 0; i < 6; ++i) col[i] = ((double)Qp[i] - (double)Qm[i]) / (2.0 * h);
}

/* Tolerance 64 FD of the largest entry (the entries are smooth functions
   of q with O(1) derivatives at these O(1) states; the central difference
   has error h^2 f''' + EPS f / h, both ~ FD), plus 16 EPS max|Q| / h for
   the rounding of Q itself where Q is much larger than the entry. */
static void test_trans_jacobians(void **state)
{
    const vlbe_cr2d_mat m = cr_mat_unit();
    static const unsigned modes[4] = {0u, VLBE_CR2D_NO_NLI, VLBE_CR2D_NO_DAMP,
                                      VLBE_CR2D_NO_NLI | VLBE_CR2D_NO_DAMP};
    tu_rng g = tu_rng_seed(71);
    double wk = 0.0, wd = 0.0, wm = 0.0;
    int s, k, j, i;
    (void)state;
    for (s = 0; s < 8; ++s) {
        tcase c;
        const double d1 = s < 6 ? 0.33 * 1.2 * (0.5 + 0.5 * tu_rng_uniform(&g))
                                : -0.05 * 1.2; /* node 1 just outside (L1 < 0) */
        vlbe_real a[6];
        tcase_make(&c, &m, 2.0 * CR_PI * tu_rng_uniform(&g), 1.2, d1, &g, 1.0);
        for (i = 0; i < 6; ++i) a[i] = (vlbe_real)tu_rng_uniform(&g);
        for (k = 0; k < 4; ++k) {
            vlbe_real Q[6], K[36], D[36], Mq[36];
            double col[6], tk, td, tm;
            assert_int_equal(vlbe_cr2d_trans_force(&c.el, &c.jt, modes[k], c.q, c.qd, Q, K, D),
                             VLBE_OK);
            assert_int_equal(vlbe_cr2d_trans_mass_jac(&c.el, &c.jt, modes[k], c.q, a, Mq),
                             VLBE_OK);
            tk = 64.0 * FD_ERR * maxabs(36, K) + 16.0 * EPS * maxabs(6, Q) / FD_STEP;
            td = 64.0 * FD_ERR * maxabs(36, D) + 16.0 * EPS * maxabs(6, Q) / FD_STEP;
            tm = 64.0 * FD_ERR * (maxabs(36, Mq) + 1.0);
            for (j = 0; j < 6; ++j) {
                tdiff(&c, modes[k], D_QQ, j, NULL, FD_STEP, col);
                for (i = 0; i < 6; ++i) {
                    wk = fmax(wk, fabs(col[i] - (double)K[i * 6 + j]) / tk);
                    ASSERT_CLOSE_CTX(K[i * 6 + j], col[i], 0, tk, "K[%d][%d] mode %u state %d", i,
                                     j, modes[k], s);
                }
                tdiff(&c, modes[k], D_QQD, j, NULL, FD_STEP, col);
                for (i = 0; i < 6; ++i) {
                    wd = fmax(wd, fabs(col[i] - (double)D[i * 6 + j]) / td);
                    ASSERT_CLOSE_CTX(D[i * 6 + j], col[i], 0, td, "D[%d][%d] mode %u", i, j,
                                     modes[k]);
                }
                tdiff(&c, modes[k], D_MA, j, a, FD_STEP, col);
                for (i = 0; i < 6; ++i) {
                    wm = fmax(wm, fabs(col[i] - (double)Mq[i * 6 + j]) / tm);
                    ASSERT_CLOSE_CTX(Mq[i * 6 + j], col[i], 0, tm, "Mq[%d][%d]", i, j);
                }
            }
        }
    }
    tu_report("transition K vs FD (fraction of tolerance)", wk, 1.0);
    tu_report("transition D vs FD (fraction of tolerance)", wd, 1.0);
    tu_report("transition d(Ma)/dq vs FD (fraction of tolerance)", wm, 1.0);
}

/* The energy from the definitions, written here: node positions, l1 along
   the axis, l2 and the angles against the outside chord, L1 from eq. 24 by
   bisection (independent of the header's closed root), U = EA L eps0^2/2 +
   EI/2 int_0^L2 v''^2 with v'' of the Hermite v by 3-point Gauss (exact:
   v''^2 is quadratic). */
static double u_ref(const tcase *c, const vlbe_real *q, double *L1o, double *cond)
{
    const vlbe_cr2d_elem *el = &c->el;
    const double L = (double)el->L, ax = (double)c->jt.a[0], ay = (double)c->jt.a[1];
    const double Cx = (double)c->jt.C[0], Cy = (double)c->jt.C[1];
    const double x1 = (double)el->X[0] + (double)q[0], y1 = (double)el->X[1] + (double)q[1];
    const double x2 = (double)el->X[2] + (double)q[3], y2 = (double)el->X[3] + (double)q[4];
    const double l1 = (Cx - x1) * ax + (Cy - y1) * ay;
    const double dx = x2 - Cx, dy = y2 - Cy, l2 = sqrt(dx * dx + dy * dy), b = atan2(dy, dx);
    const double a0 = atan2((double)el->s0, (double)el->c0);
    double t3 = atan2(ay, ax) - b, t2 = a0 + (double)q[5] - b, lo, hi, L1 = 0.0, L2, ev, eps;
    double ib = 0.0;
    int it, gq;
    static const double gx[3] = {-0.7745966692414834, 0.0, 0.7745966692414834};
    static const double gw[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
    t3 -= 2.0 * CR_PI * floor(t3 / (2.0 * CR_PI) + 0.5);
    t2 -= 2.0 * CR_PI * floor(t2 / (2.0 * CR_PI) + 0.5);
    ev = (4.0 * t3 * t3 - 2.0 * t3 * t2 + 4.0 * t2 * t2) / 60.0;
    /* f(L1) = l1/L1 - l2/(L - L1) - ev is decreasing in L1 on (0, L) for l1 > 0 */
    lo = 1e-300;
    hi = L * (1.0 - 1e-15);
    for (it = 0; it < 200; ++it) {
        const double mid = 0.5 * (lo + hi);
        if (l1 / mid - l2 / (L - mid) - ev > 0.0)
            lo = mid;
        else
            hi = mid;
    }
    L1 = 0.5 * (lo + hi);
    L2 = L - L1;
    eps = l2 / L2 + ev - 1.0;
    for (gq = 0; gq < 3; ++gq) { /* v = L2 (xi - 2 xi^2 + xi^3) t3 + L2 (-xi^2 + xi^3) t2 */
        const double xi = 0.5 * (gx[gq] + 1.0);
        const double v2 = ((-4.0 + 6.0 * xi) * t3 + (-2.0 + 6.0 * xi) * t2) / L2;
        ib += 0.5 * gw[gq] * v2 * v2 * L2;
    }
    if (L1o) *L1o = L1;
    /* relative condition of eps0 = l2/L2 + ev - 1 (cancellation) */
    if (cond) *cond = (l2 / L2 + ev + 1.0) / fabs(eps);
    return 0.5 * (double)el->mat.EA * L * eps * eps + 0.5 * (double)el->mat.EI * ib;
}

/* U against u_ref: 4 EPS (1 + cond), cond = (l2/L2 + eps_v + 1)/|eps0|
   the condition of eps0 = l2/L2 + eps_v - 1 (the sum cancels to |eps0| ~
   0.05 here: the one or two roundings of each O(1) term become cond ~ 40
   roundings of eps0, doubled in U ~ eps0^2), the bisection converged to
   the last bit.  Q = -grad U at q' = 0: central
   differences of the element's own U, 16 FD of max|Q|.  In float the
   references are double, the element's U float: 64 EPS still holds. */
static void test_trans_energy(void **state)
{
    const vlbe_cr2d_mat m = cr_mat_unit();
    tu_rng g = tu_rng_seed(72);
    double wu = 0.0, wg = 0.0;
    int s, j;
    (void)state;
    for (s = 0; s < 6; ++s) {
        tcase c;
        vlbe_real E[2], Q[6], zero[6] = {0, 0, 0, 0, 0, 0};
        double Ur, cond;
        tcase_make(&c, &m, 2.0 * CR_PI * tu_rng_uniform(&g), 1.2, 0.4 * (0.2 + 0.8 * (s + 1) / 6.0),
                   &g, 1.0);
        assert_int_equal(vlbe_cr2d_trans_energy(&c.el, &c.jt, 0, c.q, zero, E), VLBE_OK);
        Ur = u_ref(&c, c.q, NULL, &cond);
        wu = fmax(wu, fabs((double)E[1] - Ur) / (4.0 * EPS * (1.0 + cond) * fabs(Ur)));
        ASSERT_CLOSE(E[1], Ur, 4.0 * EPS * (1.0 + cond), 0);
        assert_int_equal(vlbe_cr2d_trans_force(&c.el, &c.jt, 0, c.q, zero, Q, NULL, NULL),
                         VLBE_OK);
        for (j = 0; j < 6; ++j) {
            vlbe_real q[6], Ep[2], Em[2];
            double d;
            memcpy(q, c.q, sizeof q);
            q[j] += (vlbe_real)FD_STEP;
            assert_int_equal(vlbe_cr2d_trans_energy(&c.el, &c.jt, 0, q, zero, Ep), VLBE_OK);
            q[j] -= (vlbe_real)(2.0 * FD_STEP);
            assert_int_equal(vlbe_cr2d_trans_energy(&c.el, &c.jt, 0, q, zero, Em), VLBE_OK);
            d = ((double)Ep[1] - (double)Em[1]) / (2.0 * FD_STEP);
            wg = fmax(wg, fabs(-d - (double)Q[j]) / (FD_ERR * maxabs(6, Q)));
            ASSERT_CLOSE(-d, Q[j], 0, 16.0 * FD_ERR * maxabs(6, Q));
        }
    }
    tu_report("transition U vs reference (fraction of tolerance)", wu, 1.0);
    tu_report("transition -grad U vs Q (FD units)", wg, 16.0);
}

/* L1 of the element (trans_local) against the bisection of eq. 24: 64 EPS
   of L (the element's closed root has no cancellation). */
static void test_trans_lengths(void **state)
{
    const vlbe_cr2d_mat m = cr_mat_unit();
    tu_rng g = tu_rng_seed(73);
    int s;
    (void)state;
    for (s = 0; s < 8; ++s) {
        tcase c;
        vlbe_real loc[6] = {0, 0, 0, 0, 0, 0};
        double L1;
        tcase_make(&c, &m, 2.0 * CR_PI * tu_rng_uniform(&g), 1.2, 0.05 + 0.1 * s, &g, 1.0);
        assert_int_equal(vlbe_cr2d_trans_local(&c.el, &c.jt, 0, c.q, loc), VLBE_OK);
        u_ref(&c, c.q, &L1, NULL);
        ASSERT_CLOSE(loc[5], L1, 0, 64.0 * EPS * 1.2);
    }
}

/* Node 1 at the exit (L1 = 0) and the outside chord along the axis
   (theta3 = theta1 = 0 at node 1 with phi1 = 0): the transition element is
   the conventional element there -- same U, same T (also for a node-1
   velocity along the axis), and with node 1 at rest the same node-2 rows
   and columns of Q, K, D and M.
   (The force on node 1's axial coordinate differs by the change of L2 with
   it, which the conventional element does not model: not compared.)
   Tolerance 16 EPS of the largest entry: the same quantities through
   different but exact formulas. */
static void test_trans_conventional(void **state)
{
    const vlbe_cr2d_mat m = cr_mat_unit();
    tu_rng g = tu_rng_seed(74);
    int s, i, j;
    (void)state;
    for (s = 0; s < 4; ++s) {
        const double ax = 2.0 * CR_PI * tu_rng_uniform(&g), ca = cos(ax), sa = sin(ax);
        vlbe_cr2d_joint jt;
        vlbe_cr2d_elem el;
        vlbe_real X1[2], X2[2], q[6], qd[6], Qc[6], Qt[6], Kc[36], Kt[36], Dc[36], Dt[36];
        vlbe_real Mc[36], Mt[36], Ec[2], Et[2];
        double st = 1.0 + 0.01 * tu_rng_uniform(&g), v1 = tu_rng_uniform(&g);
        jt.C[0] = VLBE_R(0.1);
        jt.C[1] = VLBE_R(0.7);
        jt.a[0] = (vlbe_real)ca;
        jt.a[1] = (vlbe_real)sa;
        X1[0] = jt.C[0];
        X1[1] = jt.C[1];
        X2[0] = (vlbe_real)(0.1 + 1.2 * ca);
        X2[1] = (vlbe_real)(0.7 + 1.2 * sa);
        assert_int_equal(vlbe_cr2d_elem_init(&el, &m, X1, X2, 0), VLBE_OK);
        q[0] = q[1] = q[2] = VLBE_R(0.0);
        q[3] = (vlbe_real)((st - 1.0) * 1.2 * ca);
        q[4] = (vlbe_real)((st - 1.0) * 1.2 * sa);
        q[5] = (vlbe_real)(0.2 * tu_rng_uniform(&g));
        /* node 1 at rest: the conventional element's frame turns at node 1
           too, so a node-1 velocity would enter its K through the turning
           of the node-1 frame, which the transition element (node 1 in the
           fixed axis frame) does not have */
        qd[0] = qd[1] = qd[2] = VLBE_R(0.0);
        for (i = 3; i < 6; ++i) qd[i] = (vlbe_real)tu_rng_uniform(&g);
        assert_int_equal(vlbe_cr2d_force(&el, 0, q, qd, Qc, Kc, Dc), VLBE_OK);
        assert_int_equal(vlbe_cr2d_trans_force(&el, &jt, 0, q, qd, Qt, Kt, Dt), VLBE_OK);
        assert_int_equal(vlbe_cr2d_mass(&el, 0, q, Mc), VLBE_OK);
        assert_int_equal(vlbe_cr2d_trans_mass(&el, &jt, 0, q, Mt), VLBE_OK);
        assert_int_equal(vlbe_cr2d_energy(&el, 0, q, qd, Ec), VLBE_OK);
        assert_int_equal(vlbe_cr2d_trans_energy(&el, &jt, 0, q, qd, Et), VLBE_OK);
        ASSERT_CLOSE(Et[0], Ec[0], 16.0 * EPS, 0);
        ASSERT_CLOSE(Et[1], Ec[1], 16.0 * EPS, 0);
        { /* T of a node-1 velocity along the axis */
            vlbe_real u1[6] = {0, 0, 0, 0, 0, 0};
            u1[0] = (vlbe_real)(v1 * ca);
            u1[1] = (vlbe_real)(v1 * sa);
            assert_int_equal(vlbe_cr2d_energy(&el, 0, q, u1, Ec), VLBE_OK);
            assert_int_equal(vlbe_cr2d_trans_energy(&el, &jt, 0, q, u1, Et), VLBE_OK);
            ASSERT_CLOSE(Et[0], Ec[0], 16.0 * EPS, 0);
        }
        for (i = 3; i < 6; ++i) {
            ASSERT_CLOSE(Qt[i], Qc[i], 0, 16.0 * EPS * maxabs(6, Qc));
            for (j = 3; j < 6; ++j) {
                ASSERT_CLOSE(Kt[i * 6 + j], Kc[i * 6 + j], 0, 16.0 * EPS * maxabs(36, Kc));
                ASSERT_CLOSE(Dt[i * 6 + j], Dc[i * 6 + j], 0, 16.0 * EPS * maxabs(36, Dc));
                ASSERT_CLOSE(Mt[i * 6 + j], Mc[i * 6 + j], 0, 16.0 * EPS * maxabs(36, Mc));
            }
        }
    }
}

/* Rigid translation of the unstrained element along the axis (the beam
   sliding through the joint): no elastic force, 16 EPS of EA. */
static void test_trans_rigid(void **state)
{
    vlbe_cr2d_mat m = cr_mat_unit();
    tu_rng g = tu_rng_seed(75);
    int s, i;
    (void)state;
    m.ray_a = m.ray_b = VLBE_R(0.0);
    for (s = 0; s < 6; ++s) {
        tcase c;
        vlbe_real Q[6], zero[6] = {0, 0, 0, 0, 0, 0};
        const double sl = 0.3 * tu_rng_uniform(&g);
        tcase_make(&c, &m, 2.0 * CR_PI * tu_rng_uniform(&g), 1.2, 0.5, &g, 0.0);
        c.q[0] = (vlbe_real)(sl * (double)c.jt.a[0]);
        c.q[1] = (vlbe_real)(sl * (double)c.jt.a[1]);
        c.q[2] = VLBE_R(0.0);
        c.q[3] = c.q[0];
        c.q[4] = c.q[1];
        c.q[5] = VLBE_R(0.0);
        assert_int_equal(vlbe_cr2d_trans_force(&c.el, &c.jt, 0, c.q, zero, Q, NULL, NULL),
                         VLBE_OK);
        for (i = 0; i < 6; ++i) ASSERT_CLOSE(Q[i], 0.0, 0, 16.0 * EPS * (double)m.EA);
    }
}

static void test_trans_errors(void **state)
{
    const vlbe_cr2d_mat m = cr_mat_unit();
    tu_rng g = tu_rng_seed(76);
    tcase c;
    vlbe_real q[6], Q[6], K[36], D[36], M[36], E[2], loc[6];
    vlbe_cr2d_joint bad;
    int i;
    (void)state;
    tcase_make(&c, &m, 0.7, 1.2, 0.4, &g, 1.0);
    for (i = 0; i < 6; ++i) Q[i] = E[i % 2] = loc[i] = VLBE_R(7.0);
    for (i = 0; i < 36; ++i) K[i] = D[i] = M[i] = VLBE_R(7.0);
#define UNTOUCHED()                                                                            \
    do {                                                                                       \
        for (i = 0; i < 6; ++i) assert_true(Q[i] == VLBE_R(7.0) && loc[i] == VLBE_R(7.0));     \
        for (i = 0; i < 36; ++i)                                                               \
            assert_true(K[i] == VLBE_R(7.0) && D[i] == VLBE_R(7.0) && M[i] == VLBE_R(7.0));     \
        assert_true(E[0] == VLBE_R(7.0) && E[1] == VLBE_R(7.0));                               \
    } while (0)
    /* node 2 pulled back into the joint */
    memcpy(q, c.q, sizeof q);
    q[3] = (vlbe_real)((double)c.jt.C[0] - 0.1 * (double)c.jt.a[0] - (double)c.el.X[2]);
    q[4] = (vlbe_real)((double)c.jt.C[1] - 0.1 * (double)c.jt.a[1] - (double)c.el.X[3]);
    assert_int_equal(vlbe_cr2d_trans_force(&c.el, &c.jt, 0, q, c.qd, Q, K, D), VLBE_EBOUND);
    assert_int_equal(vlbe_cr2d_trans_mass(&c.el, &c.jt, 0, q, M), VLBE_EBOUND);
    assert_int_equal(vlbe_cr2d_trans_energy(&c.el, &c.jt, 0, q, c.qd, E), VLBE_EBOUND);
    UNTOUCHED();
    /* node 1 outside by more than L/2 */
    memcpy(q, c.q, sizeof q);
    q[0] = (vlbe_real)((0.4 + 0.61 * 1.2) * (double)c.jt.a[0]);
    q[1] = (vlbe_real)((0.4 + 0.61 * 1.2) * (double)c.jt.a[1]);
    assert_int_equal(vlbe_cr2d_trans_local(&c.el, &c.jt, 0, q, loc), VLBE_EBOUND);
    UNTOUCHED();
    /* joint axis not unit, LINEAR mode */
    bad = c.jt;
    bad.a[0] *= VLBE_R(1.01);
    assert_int_equal(vlbe_cr2d_trans_force(&c.el, &bad, 0, c.q, c.qd, Q, K, D), VLBE_EARG);
    assert_int_equal(vlbe_cr2d_trans_force(&c.el, &c.jt, VLBE_CR2D_LINEAR, c.q, c.qd, Q, K, D),
                     VLBE_EARG);
    UNTOUCHED();
    /* non-finite state or joint */
    memcpy(q, c.q, sizeof q);
    q[4] = (vlbe_real)NAN;
    assert_int_equal(vlbe_cr2d_trans_force(&c.el, &c.jt, 0, q, c.qd, Q, K, D), VLBE_ENONFINITE);
    bad = c.jt;
    bad.C[1] = (vlbe_real)INFINITY;
    assert_int_equal(vlbe_cr2d_trans_mass(&c.el, &bad, 0, c.q, M), VLBE_EARG);
    UNTOUCHED();
#undef UNTOUCHED
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_trans_jacobians), cmocka_unit_test(test_trans_energy),
        cmocka_unit_test(test_trans_lengths),   cmocka_unit_test(test_trans_conventional),
        cmocka_unit_test(test_trans_rigid),     cmocka_unit_test(test_trans_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
