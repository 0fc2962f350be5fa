/* test_ale3.c -- cmocka suite of the 3D beam-shaft element with spin of
   ancf_ale.h (VLBSE: vlbe_ale3_*)                  -- part of vlbe
                                                   SPDX-License-Identifier: MIT
   cc -std=c99 -Wall -Wextra -Wpedantic ... -O2 tests/test_ale3.c -lcmocka -lm
   (add -DVLBE_USE_FLOAT for the float build; the same source passes in both)

   Every tolerance says why it has its size.  They are multiples of EPS (the
   machine epsilon of vlbe_real) for rounding-only checks and of
   FD = EPS^(2/3) for central differences with the step h = EPS^(1/3)
   (times max(1, |x|); the step balances the truncation error h^2 f'''/6
   against the rounding error EPS f / h, both then ~EPS^(2/3)): FD =
   3.7e-11 in double, 2.4e-5 in float.  A Jacobian error is taken
   against the scale of its entry's row and column, the largest entry
   there of the analytic or the differenced matrix (a Jacobian that is
   wrongly zero cannot pass), with the differences' rounding 16 EPS
   max|out| / h as a floor (tests/fd_harness.h: never looser than against
   the largest entry of the matrix).  Set VLBE_TEST_REPORT=1 to
   print each measured error next to its tolerance; "measured" below is
   the double -O2 build (tag m:), the float build where it is quoted too
   (m@flt:), and numbers of a few EPS are orders of magnitude (m~:, they
   move with the compiler); tests/measured.sh checks them against the
   report.  Layout per node [r(3), r'(3), theta, p] (16 per element) or
   [r, r', p] (14, VLBE_ALE3_NO_SPIN);
   "all 64 modes" = every OR of NO_SPIN, NO_BEND, NO_TWIST, NO_DAMP, FIX_P1,
   FIX_P2.  Random states (make_state): chord of length 1.0 .. 1.4 in a
   random 3D direction, stretched +-15 %, slopes turned off it in random 3D
   directions (curved out of any one plane, |k| ~ 1), twist rate up to 0.8,
   rates O(1), p' O(0.5); the material mat3_std has every term O(1) (rhoI,
   GI, all three Kelvin-Voigt times and all three load components non-zero).

   Tests
     force_jacobians      K = dQ/dq, D = dQ/dq' vs central differences, all 64
                          modes, 3 random states; fixed-p rows and columns
                          (and Q's row) exactly zero; K or D alone and Q alone
                          give the same bits (one code path).  Tol 64 FD: the
                          entries reach L^-5 |r'|^-5 terms whose third
                          derivatives (the truncation error) are tens times
                          the entries, as for the planar element; measured
                          15 (m:fj_K_fd) FD (K), 3.0 (m:fj_D_fd) FD (D; 3.9
                          (m@flt:fj_D_fd) in float).
     mass_jacobian        d(M a)/dq vs differences of vlbe_ale3_mass (M depends
                          on NO_SPIN, FIX_P1/2 only: the other bits give the
                          same bits); both p fixed: exactly zero.  Tol 64 FD as
                          for K (M polynomial in e, rational in L); measured
                          1.8 (m:mj_fd) FD.
     point_force_jacobian, point_torque_jacobian  K vs differences of Q at
                          interior points (all columns) and at the ends (no
                          p-columns: a p step would leave the element);
                          accumulation (a second call doubles Q, K exactly);
                          FIX bits ignored; resultant N1 + N3 = 1, H1 + H2 = 1
                          to 4 EPS (two rounded basis values); the torque puts
                          nothing on the position field; EBOUND outside [p1,
                          p2] (also 4 EPS outside), EARG for the torque
                          without spin, no output written.  Tol 64 FD (third
                          p-derivatives of the basis, ~L^-3 with large
                          coefficients); measured 7.9 (m:pf_fd) FD
                          (force), 4.2 (m:pt_fd) FD (torque).
     energy_gradient      both p fixed, undamped, qd = 0: Q = -d(U + V)/dq by
                          differences of E[1] + E[2], every mode with both p
                          fixed: the string (NO_BEND: axial integrand of
                          degree 8, exact with ns = 5) and with bending
                          (rational: the force and the energy sum the same
                          Gauss points, so the identity holds per rule;
                          checked with the default ns = 5 and with nm = ns =
                          8).  Also free p for the string with twist (exact
                          quadrature): the p-rows with the end fluxes u(p_k) -
                          f.r(p_k), u = (EA eps^2 + GI phi^2)/2, as for the
                          planar element (the 3D element has no CONSERVATIVE
                          mode).  Scale max(|Q|, |grad|, max|K|) (the FD
                          error follows the derivatives of U, not |Q|), tol 16
                          FD (U quartic in the slopes); measured
                          2.0 (m:eg_fd) FD.
     kinetic_energy       E[0] = qd^T M qd / 2 to 64 EPS of sum |terms|
                          (measured 1 (m:ke_T) in double, 0.7 (m@flt~:ke_T)
                          in float; E[0] sums the points' rhoA |r_t|^2 and
                          rhoI theta_t^2, not qd^T M qd); M exactly
                          symmetric (one triangle formed, the other copied:
                          measured 0 (m:ke_sym)); total mass of the
                          position block rhoA L per direction to 16 EPS
                          (measured 0.5 (m~:ke_mass)); theta block rhoI L
                          [1/3 1/6; 1/6 1/3] to 16 EPS (measured
                          1.4 (m~:ke_theta)), no theta-position coupling at fixed
                          p (exact zeros); both p fixed: the classic ANCF
                          cable matrix (x) I3, 64 EPS per entry (measured
                          2.7 (m~:ke_classic)); positive semidefinite: the
                          e/theta block positive definite (Cholesky), x^T M
                          x > 16 EPS sum|terms| for random x; a free p_k has
                          the null vector (r_k', r''(p_k), theta', 1) of the
                          re-parametrization: M x = 0 to 64 EPS max|M| |x|
                          (measured 1.3 (m~:ke_null)).
     planar_reproduction  theta = 0, z = 0: the 3D element (EJ = EI, the same
                          default Gauss points) against vlbe_ale_force/_mass in
                          plane, free and fixed p, damped and undamped, bending
                          on and off, both layouts: Q, K, D, M to 32 EPS of the
                          largest entry (the same integrals summed in another
                          order; measured 2.0 (m~:pl_QKDM) EPS, i.e.
                          ~4e-16 in double, far inside the required 1e-10),
                          Q of the planar Q-alone route to 64 EPS (that
                          route differs from the planar Jacobian route by up
                          to 64 EPS itself; measured 4.0 (m~:pl_Qalone),
                          7.1 (m@flt~:pl_Qalone) in float);
                          out-of-plane rows of Q (z, z', theta) exactly zero;
                          K, D, M do not couple the plane to z, z', theta
                          (reflection symmetry; asserted to 32 EPS, measured
                          exactly 0 (m:pl_couple)).
     rigid_motion         a straight unstretched element rotated (angles to
                          100 rad about random axes) and translated (|r| to
                          10), uniform spin angle, rigid velocity field (v0 +
                          w x r, w x r', equal spin rates), both p fixed, no
                          load: Q = 0 to 64 EPS S, S = (1 + |r|/L) (EA + EJ/L^2
                          + (c_eps EA + c_kap EJ/L^2) |v|/L) (eps from
                          positions of size |r| cancels to EPS |r|/L, r'' to
                          EPS |r|/L^2, the rates to EPS |v|/L); measured
                          0.3 (m~:rm_Q).
                          Rotation covariance of a curved, twisted, moving
                          state (the load rotated too): Q(Bq) = B Q(q), K, D
                          -> B K B^T (B rotates the 3-blocks, keeps theta and
                          p), all 64 modes, to 64 EPS (1 + |shift|) of the
                          largest entry (rotated data round differently;
                          measured 16 (m~:rm_rot) EPS).
     twist_energy         straight unstretched shaft, theta1 = 0, theta2 = phi
                          L (|phi| 1e-3 .. 5, L 0.4 .. 3): U = GI phi^2 L / 2
                          to 16 EPS plus the strain energy of the rounded eps,
                          k (L/2 (EA + EJ/L^2) (64 EPS (1 + |r|/L))^2); Q =
                          -dU/dtheta = +GI phi at node 1, -GI phi at node 2 to
                          16 EPS; free p: Q_p1 = -GI phi^2, Q_p2 = +GI phi^2
                          (dphi/dp1 = phi/L = -dphi/dp2) to 16 EPS + 64 EPS S;
                          other rows 0 to 64 EPS S; NO_TWIST: all zero.
                          Measured 0.13 (m:tw_ratio) of the tolerance at most.
     straight_shaft_spin  straight unstretched shaft, uniform spin angle and
                          rate, moving axially at speed v with the nodes at
                          arbitrary p' (r_k rates t (p_k' + v)), all 64 modes:
                          the field r(p, t) = r0 + t (p + v t) is reproduced
                          exactly by the cubic for any p1, p2, so the ALE
                          transport acceleration of a straight uniform field
                          vanishes (and so do eps, k, phi and their rates):
                          the element gives Q = 0, consistent with M q'' = Q
                          for this motion's q'' = 0.  Tol 64 EPS S, S as in
                          rigid_motion plus the terms that cancel: rhoA (p'^2
                          + p' |v|) and rhoI (p'^2 |theta|/L + p' |Omega|),
                          times (1 + |r|/L); measured 0.69 (m~:ss_Q).
     curvature            vlbe_ale3_strain on a cubic Hermite arc in a tilted
                          plane: |kappa R - 1| <= 1.05 theta^2/12, at the
                          middle theta^2/24 and at the ends theta^2/12 within
                          5 %, ratio 3.5 .. 4.5 per halving (the interpolation
                          error of r'', as in the planar curvature_arc), plus
                          rounding 32 EPS (1 + |c|/R) / theta^2 (float at
                          theta = 0.1: 1.03 (m@flt:cv_end) of theta^2/12);
                          phi = 0.5 (linear theta) to 8 EPS (1 + 1/L).
                          Straight: kappa exactly
                          0 along a coordinate axis through the origin (the
                          other components are exact zeros), else 32 EPS (1 +
                          |r|/L)/L (measured 2.7 (m~:cv_straight), float
                          5.0 (m@flt~:cv_straight)); eps = (s^2-1)/2 to 32 EPS
                          (1 + |r|/L).  K and D at kappa = 0 (exactly and to
                          rounding), moving and twisting, all 64 modes: finite
                          and equal to the differences, tol 64 FD as in
                          force_jacobians (measured 14 (m:cv_KD_fd) FD).
     errors_eval          ELENGTH (p2 = p1, p2 < p1, every mode), ENONFINITE
                          (NaN, +-Inf in every entry of q and qd, also a fixed
                          p's rate; in p, F, T), ESINGULAR (zero slope: force,
                          energy, strain's kappa; the string and EJ = 0
                          succeed, finite; zero slope at node 1 only: interior
                          Gauss points, every mode succeeds), EBOUND, EARG
                          for the planar-only CONSERVATIVE and INV_AXIAL; both
                          layouts; nothing written on failure (sentinels).
     errors_init          EARG (rhoA <= 0, negative rhoI, stiffness or damping,
                          rhoI = 0 with spin, Gauss orders -1, 9, 100),
                          ENONFINITE (every field); the element not written.
                          vlbe_ale3_mat_circle: ENONFINITE, EARG (rho, radius
                          <= 0, E, G < 0), the material not written; its
                          values (A, J, I_p = 2 J) to 8 EPS (a few products).
     reduced_equals_full  NO_SPIN = the position rows and columns of the spin
                          model at uniform theta and spin rate (Q, K, D, M,
                          Mq, U, V) bit for bit (H1 = 1 - xi and H2 = xi have
                          exactly opposite partials, so the spin terms add
                          exact zeros); T more by rhoI Omega^2 L / 2 to 16 EPS
                          of T (measured 2.8 (m~:rf_T)).  NO_TWIST = GI 0,
                          NO_DAMP = every c 0, NO_BEND = EJ 0, and each bit given as an
                          element flag = as a mode: bit for bit (the same code
                          runs; a zero Kelvin-Voigt coefficient adds exact
                          zeros).
     quadrature           M and Mq with nm = 4, 5 vs 8 (degree 6 in xi), the
                          string force Q, K, D (axial degree 8, twist, inertia,
                          load) with (nm, ns) = (4, 5) vs (8, 8): 64 EPS of the
                          largest entry (Gauss sums of terms a few times the
                          result); measured 6.1 (m~:qd_eps) EPS.
     transport_inertia_lagrange  (beyond the required list) Q_p with spin
                          against Lagrange's equations of T: Mdot qd - dT/dq =
                          Q_p + B, B the end terms rho [p' G^T v] and the
                          kinetic fluxes, for r and for theta (omega_k =
                          theta_k' - theta'(p_k) p_k'); EA = EJ = GI = 0, f =
                          0.  Tol 16 FD of max(|Q|, |Mdot qd|, |dT/dq|) (T
                          quadratic in qd, rational in L); measured
                          0.7 (m:lg_fd) FD.
     dissipation          (beyond the list) Kelvin-Voigt power, both p fixed:
                          qd . (Q(q, qd) - Q(q, 0)) = -sum_g w_g L (c_eps EA
                          eps'^2 + c_kap EJ |k'|^2 + c_phi GI phi'^2), rates
                          by central differences in time of vlbe_ale3_strain;
                          a curved string and a straight beam (|k'| from |k|
                          at k = 0).  The value check of the twist and the 3D
                          bending damping that K/D consistency cannot give.
                          Tol 16 FD of sum |qd_i| (|dQ_i| + |Q0_i|) +
                          |reference|; measured 0.5 (m:ds_fd) FD. */
#include "test_util.h"
#include "../ancf_ale.h"
#include "ale_fixtures.h"
#include "fd_harness.h"

#include <stdlib.h>
#include <string.h>

#define EPS ((double)VLBE_EPS)
#define ARRAY_LEN(a) ((int)(sizeof(a) / sizeof((a)[0])))
#define FD_STEP (cbrt(EPS))    /* h = EPS^(1/3) on O(1) variables           */
#define FD_ERR (EPS / FD_STEP) /* EPS^(2/3): error unit of a central difference */
#define SENTINEL VLBE_R(12345.0)
#define NQ VLBE_ALE3_NQ /* 16: coordinates with spin (14 without) */
#define NN (NQ * NQ)
#define N_FD_STATES 3 /* random states of the Jacobian test */

static const double PI = 3.14159265358979323846;

/* ------------------------------------------------------------------------ */
/* layout, modes, material                                                    */
/* ------------------------------------------------------------------------ */

/* coordinates per node: [r, r', theta, p] or [r, r', p] */
static int node_len(unsigned mode) { return (mode & VLBE_ALE3_NO_SPIN) ? 7 : 8; }
static int nq_of(unsigned mode) { return vlbe_ale3_nq(mode); }
static int idx_p(unsigned mode, int k) { return k * node_len(mode) + node_len(mode) - 1; }
static int idx_th(unsigned mode, int k) { return (mode & VLBE_ALE3_NO_SPIN) ? -1 : 8 * k + 6; }
static int is_p(unsigned mode, int i) { return i == idx_p(mode, 0) || i == idx_p(mode, 1); }
static int is_th(unsigned mode, int i) { return i == idx_th(mode, 0) || i == idx_th(mode, 1); }

/* 1 when coordinate i is a fixed material coordinate in mode */
static int is_fixed(unsigned mode, int i)
{
    return (i == idx_p(mode, 0) && (mode & VLBE_ALE_FIX_P1)) ||
           (i == idx_p(mode, 1) && (mode & VLBE_ALE_FIX_P2));
}

/* All 64 combinations of the six mode bits. */
#define N_MODES 64
static unsigned mode_of(int k)
{
    unsigned m = (unsigned)k & 15u; /* NO_BEND, NO_DAMP, FIX_P1, FIX_P2 */
    if (k & 16) m |= VLBE_ALE3_NO_SPIN;
    if (k & 32) m |= VLBE_ALE3_NO_TWIST;
    return m;
}

/* The 32 combinations of the five bits other than NO_SPIN (k < 32), in the
   layout lay (0 or VLBE_ALE3_NO_SPIN). */
static unsigned mode_lay(int k, unsigned lay) { return mode_of((k & 15) | ((k & 16) << 1)) | lay; }

static void elem_make(vlbe_ale3_elem *el, const vlbe_ale3_mat *m, unsigned flags, int nm, int ns)
{
    assert_int_equal(vlbe_ale3_elem_init(el, m, flags, nm, ns), VLBE_OK);
}

/* ------------------------------------------------------------------------ */
/* states                                                                     */
/* ------------------------------------------------------------------------ */

/* A state (or a rate) in double, node by node, packed into the layout of a
   mode by pack(). */
typedef struct node3 {
    double r[3], rp[3], th, p;
} node3;
typedef struct st3 {
    node3 n[2];
} st3;

static void pack(unsigned mode, const st3 *s, vlbe_real *q)
{
    const int o = node_len(mode);
    int k, c;
    for (k = 0; k < 2; ++k) {
        for (c = 0; c < 3; ++c) {
            q[k * o + c] = (vlbe_real)s->n[k].r[c];
            q[k * o + 3 + c] = (vlbe_real)s->n[k].rp[c];
        }
        if (o == 8) q[k * o + 6] = (vlbe_real)s->n[k].th;
        q[k * o + o - 1] = (vlbe_real)s->n[k].p;
    }
}

static double dot3(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void cross3(const double *a, const double *b, double *c)
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}

static void rand_vec(tu_rng *g, double *v)
{
    int c;
    for (c = 0; c < 3; ++c) v[c] = tu_rng_uniform(g);
}

/* uniformly distributed unit vector (rejection from the cube) */
static void rand_dir(tu_rng *g, double *t)
{
    double n;
    int c;
    do {
        rand_vec(g, t);
        n = sqrt(dot3(t, t));
    } while (n < 0.2 || n > 1.0);
    for (c = 0; c < 3; ++c) t[c] /= n;
}

/* A random deformed 3D state: chord of material length L in [1.0, 1.4]
   from p1 in [0.1, 0.5] along a random direction, stretched by up to
   +-stretch, nodal slopes turned off the chord in random 3D directions by
   up to about curv rad (curv = 0.5: curved out of any one plane, |k| ~ 1)
   with magnitudes varying by +-10 %, spin angles th1 in [-1, 1] and th2 =
   th1 + twist L u (twist rate up to +-twist).  Rates (qd != NULL) O(1),
   p' O(0.5). */
static void make_state(tu_rng *g, double curv, double stretch, double twist, st3 *q, st3 *qd)
{
    const double p1 = 0.3 + 0.2 * tu_rng_uniform(g), L = 1.2 + 0.2 * tu_rng_uniform(g);
    const double s = 1.0 + stretch * tu_rng_uniform(g);
    double t[3], x1[3], th1;
    int k, c;
    rand_dir(g, t);
    rand_vec(g, x1);
    th1 = tu_rng_uniform(g);
    for (k = 0; k < 2; ++k) {
        double d[3], nd;
        const double mag = s * (1.0 + 0.1 * tu_rng_uniform(g));
        rand_vec(g, d);
        for (c = 0; c < 3; ++c) d[c] = t[c] + curv * d[c];
        nd = sqrt(dot3(d, d));
        for (c = 0; c < 3; ++c) {
            q->n[k].r[c] = x1[c] + k * s * L * t[c];
            q->n[k].rp[c] = mag * d[c] / nd;
        }
        q->n[k].p = p1 + k * L;
    }
    q->n[0].th = th1;
    q->n[1].th = th1 + twist * L * tu_rng_uniform(g);
    if (qd)
        for (k = 0; k < 2; ++k) {
            rand_vec(g, qd->n[k].r);
            rand_vec(g, qd->n[k].rp);
            qd->n[k].th = tu_rng_uniform(g);
            qd->n[k].p = 0.5 * tu_rng_uniform(g);
        }
}

/* Rotation matrix (row-major) about the unit axis n by angle a (Rodrigues). */
static void rotation(const double *n, double a, double *R)
{
    const double c = cos(a), s = sin(a);
    int i, j;
    for (i = 0; i < 3; ++i)
        for (j = 0; j < 3; ++j) R[i * 3 + j] = (1.0 - c) * n[i] * n[j] + (i == j ? c : 0.0);
    R[1] -= s * n[2];
    R[2] += s * n[1];
    R[3] += s * n[2];
    R[5] -= s * n[0];
    R[6] -= s * n[1];
    R[7] += s * n[0];
}

static void mat3_vec(const double *R, const double *x, double *y)
{
    int i;
    for (i = 0; i < 3; ++i) y[i] = R[i * 3] * x[0] + R[i * 3 + 1] * x[1] + R[i * 3 + 2] * x[2];
}

/* ------------------------------------------------------------------------ */
/* central differences of the element functions (fd_harness.h)               */
/* ------------------------------------------------------------------------ */
enum { FD_Q_OF_Q, FD_Q_OF_QD, FD_MA_OF_Q, FD_PF_OF_Q, FD_PT_OF_Q, FD_E_OF_Q };

/* fd (first: fd_harness.h's context; el, mode, n, q, qd, a there; the FIX
   bits of mode select the skipped p) and the point load */
typedef struct ale3_fd {
    fd_ctx fd;
    vlbe_real pf, F[3], T;
} ale3_fd;

/* The differenced function (fd_eval): Q, M a, point-force or point-torque
   Q, or E. */
static double fd3_eval(const fd_ctx *fc, const vlbe_real *q, const vlbe_real *qd, double *out)
{
    const ale3_fd *c = (const ale3_fd *)fc;
    const vlbe_ale3_elem *el = (const vlbe_ale3_elem *)fc->el;
    vlbe_real buf[NN];
    const int n = fc->n;
    int i, k;
    switch (fc->which) {
    case FD_Q_OF_Q:
    case FD_Q_OF_QD:
        assert_int_equal(vlbe_ale3_force(el, fc->mode, q, qd, buf, NULL, NULL), VLBE_OK);
        for (i = 0; i < n; ++i) out[i] = (double)buf[i];
        break;
    case FD_MA_OF_Q:
        assert_int_equal(vlbe_ale3_mass(el, fc->mode, q, buf), VLBE_OK);
        for (i = 0; i < n; ++i) {
            out[i] = 0.0;
            for (k = 0; k < n; ++k) out[i] += (double)buf[i * n + k] * (double)fc->a[k];
        }
        break;
    case FD_PF_OF_Q:
    case FD_PT_OF_Q:
        fill(n, VLBE_R(0.0), buf);
        if (fc->which == FD_PF_OF_Q)
            assert_int_equal(vlbe_ale3_point_force(fc->mode, q, c->pf, c->F, buf, NULL), VLBE_OK);
        else
            assert_int_equal(vlbe_ale3_point_torque(fc->mode, q, c->pf, c->T, buf, NULL), VLBE_OK);
        for (i = 0; i < n; ++i) out[i] = (double)buf[i];
        break;
    default:
        assert_int_equal(vlbe_ale3_energy(el, fc->mode, q, qd, buf), VLBE_OK);
        for (i = 0; i < 3; ++i) out[i] = (double)buf[i];
        break;
    }
    return tu_max_abs(fc->nout, out);
}

/* c zeroed, for el in mode: n = nq_of(mode), step EPS^(1/3) max(1, |x|) */
static void ctx_init(ale3_fd *c, const vlbe_ale3_elem *el, unsigned mode)
{
    memset(c, 0, sizeof *c);
    fd_init(&c->fd, nq_of(mode), fd3_eval, el, mode);
}

/* J (n x n, analytic, d out / d var) against central differences over the
   columns j that are coordinates (fixed p of c->fd.mode skipped), rows
   likewise; only the columns with col_mask[j] != 0 when col_mask is given.
   The error of entry (i, j) is measured against the scale of its row and
   column (analytic or differenced, so that a Jacobian that is wrongly zero
   cannot pass; fd_check, with its rounding floor): |J_fd - J| / scale_ij
   <= tol.  Returns the worst measured ratio. */
static double check_jac(ale3_fd *c, int which, const vlbe_real *J, const int *col_mask, double tol,
                        const char *what)
{
    fd_stats st;
    int skip[NQ], i;
    for (i = 0; i < c->fd.n; ++i) skip[i] = is_fixed(c->fd.mode, i);
    c->fd.which = which;
    c->fd.wrt_qd = which == FD_Q_OF_QD;
    (void)fd_check(&c->fd, J, skip, col_mask, tol, 0.0, what, &st);
    return st.err;
}

/* Rows and columns of fixed p are exactly zero (Q: its row). */
static void check_fixed_zero(unsigned mode, const vlbe_real *Q, const vlbe_real *J)
{
    const int n = nq_of(mode);
    int i, k;
    for (k = 0; k < 2; ++k) {
        const int pk = idx_p(mode, k);
        if (!is_fixed(mode, pk)) continue;
        if (Q) ASSERT_CLOSE_CTX(Q[pk], 0.0, 0, 0, "Q[%d], mode %u", pk, mode);
        if (!J) continue;
        for (i = 0; i < n; ++i) {
            ASSERT_CLOSE_CTX(J[pk * n + i], 0.0, 0, 0, "row %d col %d, mode %u", pk, i, mode);
            ASSERT_CLOSE_CTX(J[i * n + pk], 0.0, 0, 0, "row %d col %d, mode %u", i, pk, mode);
        }
    }
}

/* ======================================================================= */
/* 1. force Jacobians                                                        */
/* ======================================================================= */

static void test_force_jacobians(void **state)
{
    const vlbe_ale3_mat m = mat3_std();
    const double tol = 64.0 * FD_ERR;
    vlbe_ale3_elem el;
    tu_rng g = tu_rng_seed(311);
    double wk = 0.0, wd = 0.0;
    int s, k;
    (void)state;
    elem_make(&el, &m, 0, 0, 0);
    for (s = 0; s < N_FD_STATES; ++s) {
        st3 x, xd;
        make_state(&g, 0.5, 0.15, 0.8, &x, &xd);
        for (k = 0; k < N_MODES; ++k) {
            vlbe_real Q[NQ], K[NN], D[NN];
            ale3_fd c;
            ctx_init(&c, &el, mode_of(k));
            pack(c.fd.mode, &x, c.fd.q);
            pack(c.fd.mode, &xd, c.fd.qd);
            assert_int_equal(vlbe_ale3_force(&el, c.fd.mode, c.fd.q, c.fd.qd, Q, K, D), VLBE_OK);
            check_fixed_zero(c.fd.mode, Q, K);
            check_fixed_zero(c.fd.mode, NULL, D);
            if (s == 0) {
                /* K, D optional: Q alone, K alone, D alone give the same bits
                   (one code path; only the outputs asked for are copied) */
                const int n = c.fd.n;
                vlbe_real Q2[NQ], J2[NN];
                assert_int_equal(vlbe_ale3_force(&el, c.fd.mode, c.fd.q, c.fd.qd, Q2, NULL, NULL),
                                 VLBE_OK);
                ASSERT_VEC_CLOSE(Q2, Q, n, 0, 0);
                assert_int_equal(vlbe_ale3_force(&el, c.fd.mode, c.fd.q, c.fd.qd, Q2, J2, NULL),
                                 VLBE_OK);
                ASSERT_VEC_CLOSE(Q2, Q, n, 0, 0);
                ASSERT_VEC_CLOSE(J2, K, n * n, 0, 0);
                assert_int_equal(vlbe_ale3_force(&el, c.fd.mode, c.fd.q, c.fd.qd, Q2, NULL, J2),
                                 VLBE_OK);
                ASSERT_VEC_CLOSE(J2, D, n * n, 0, 0);
            }
            wk = fmax(wk, check_jac(&c, FD_Q_OF_Q, K, NULL, tol, "K"));
            wd = fmax(wd, check_jac(&c, FD_Q_OF_QD, D, NULL, tol, "D"));
        }
    }
    tu_report("K = dQ/dq (64 modes), err / entry scale", wk, tol);
    tu_report("D = dQ/dq' (64 modes), err / entry scale", wd, tol);
    tu_measured("fj_K_fd", wk / FD_ERR);
    tu_measured("fj_D_fd", wd / FD_ERR);
}

/* ======================================================================= */
/* 2. mass Jacobian                                                          */
/* ======================================================================= */

static void test_mass_jacobian(void **state)
{
    const vlbe_ale3_mat m = mat3_std();
    const double tol = 64.0 * FD_ERR;
    vlbe_ale3_elem el;
    tu_rng g = tu_rng_seed(312);
    double w = 0.0;
    int s, k, i;
    (void)state;
    elem_make(&el, &m, 0, 0, 0);
    for (s = 0; s < 3; ++s) {
        st3 x, xa;
        make_state(&g, 0.5, 0.15, 0.8, &x, &xa);
        for (k = 0; k < N_MODES; ++k) {
            vlbe_real Mq[NN], Mq2[NN];
            ale3_fd c;
            /* M depends on NO_SPIN, FIX_P1, FIX_P2 only: the other bits give
               the same bits; difference the 8 combinations */
            const unsigned base =
                mode_of(k) & (VLBE_ALE3_NO_SPIN | VLBE_ALE_FIX_P1 | VLBE_ALE_FIX_P2);
            ctx_init(&c, &el, mode_of(k));
            pack(c.fd.mode, &x, c.fd.q);
            pack(c.fd.mode, &xa, c.fd.a);
            for (i = 0; i < c.fd.n; ++i) c.fd.a[i] = (vlbe_real)(2.0 * (double)c.fd.a[i]);
            assert_int_equal(vlbe_ale3_mass_jac(&el, c.fd.mode, c.fd.q, c.fd.a, Mq), VLBE_OK);
            assert_int_equal(vlbe_ale3_mass_jac(&el, base, c.fd.q, c.fd.a, Mq2), VLBE_OK);
            ASSERT_VEC_CLOSE(Mq, Mq2, c.fd.n * c.fd.n, 0, 0);
            if (c.fd.mode != base) continue;
            check_fixed_zero(c.fd.mode, NULL, Mq);
            if ((c.fd.mode & (VLBE_ALE_FIX_P1 | VLBE_ALE_FIX_P2)) ==
                (VLBE_ALE_FIX_P1 | VLBE_ALE_FIX_P2)) {
                /* Lagrangian: M constant, the Jacobian is exactly zero */
                assert_all_equal(c.fd.n * c.fd.n, Mq, VLBE_R(0.0));
                continue;
            }
            w = fmax(w, check_jac(&c, FD_MA_OF_Q, Mq, NULL, tol, "Mq"));
        }
    }
    tu_report("Mq = d(M a)/dq, err / entry scale", w, tol);
    tu_measured("mj_fd", w / FD_ERR);
}

/* ======================================================================= */
/* 3. point force and point torque                                           */
/* ======================================================================= */

/* One point load (force or torque) at the abscissae xis of one state and
   layout: K vs differences of Q (all columns inside; at the ends the
   e-columns and theta-columns only, since a p step would move the point out
   of the element), accumulation (a second call doubles Q and K exactly),
   the FIX bits ignored (every row and column written), the resultant.
   Returns the worst interior Jacobian error. */
static double point_load_check(ale3_fd *c, int torque, double tol)
{
    static const double xis[] = {0.0, 0.27, 0.5, 0.81, 1.0};
    const unsigned mode = c->fd.mode;
    const vlbe_real *q = c->fd.q;
    const int n = c->fd.n, p1 = idx_p(mode, 0), p2 = idx_p(mode, 1);
    double w = 0.0;
    int ix, i, j;
    for (ix = 0; ix < ARRAY_LEN(xis); ++ix) {
        vlbe_real Q[NQ], K[NN], Q2[NQ], K2[NN];
        const int end = ix == 0 || ix == ARRAY_LEN(xis) - 1;
        c->pf = (vlbe_real)((double)q[p1] + xis[ix] * ((double)q[p2] - (double)q[p1]));
        if (ix == 0) c->pf = q[p1];
        if (ix == ARRAY_LEN(xis) - 1) c->pf = q[p2];
        fill(n, VLBE_R(0.0), Q);
        fill(n * n, VLBE_R(0.0), K);
        if (torque)
            assert_int_equal(vlbe_ale3_point_torque(mode, q, c->pf, c->T, Q, K), VLBE_OK);
        else
            assert_int_equal(vlbe_ale3_point_force(mode, q, c->pf, c->F, Q, K), VLBE_OK);
        /* accumulates; FIX bits change nothing */
        memcpy(Q2, Q, sizeof Q2);
        memcpy(K2, K, sizeof K2);
        if (torque)
            assert_int_equal(vlbe_ale3_point_torque(mode | VLBE_ALE_FIX_P1 | VLBE_ALE_FIX_P2, q,
                                                    c->pf, c->T, Q2, K2),
                             VLBE_OK);
        else
            assert_int_equal(vlbe_ale3_point_force(mode | VLBE_ALE_FIX_P1 | VLBE_ALE_FIX_P2, q,
                                                   c->pf, c->F, Q2, K2),
                             VLBE_OK);
        for (i = 0; i < n; ++i) ASSERT_CLOSE(Q2[i], 2.0 * (double)Q[i], 0, 0);
        for (i = 0; i < n * n; ++i) ASSERT_CLOSE(K2[i], 2.0 * (double)K[i], 0, 0);
        if (end) {
            int mask[NQ];
            for (j = 0; j < n; ++j) mask[j] = !is_p(mode, j);
            (void)check_jac(c, torque ? FD_PT_OF_Q : FD_PF_OF_Q, K, mask, tol, "end point load K");
        } else {
            w = fmax(w,
                     check_jac(c, torque ? FD_PT_OF_Q : FD_PF_OF_Q, K, NULL, tol, "point load K"));
        }
        /* resultant: N1 + N3 = 1 and H1 + H2 = 1, up to their rounding */
        if (torque) {
            const int t1 = idx_th(mode, 0), t2 = idx_th(mode, 1);
            assert_true(t1 >= 0 && t2 >= 0);
            if (t1 >= 0 && t2 >= 0)
                ASSERT_CLOSE((double)Q[t1] + (double)Q[t2], (double)c->T, 0,
                             4 * EPS * fabs((double)c->T));
            for (i = 0; i < n; ++i) /* nothing on the position field */
                if (!is_p(mode, i) && !is_th(mode, i)) ASSERT_CLOSE(Q[i], 0.0, 0, 0);
        } else {
            const int o = node_len(mode);
            for (i = 0; i < 3; ++i)
                ASSERT_CLOSE((double)Q[i] + (double)Q[o + i], (double)c->F[i], 0,
                             4 * EPS * fabs((double)c->F[i]));
            if (o == 8) {
                ASSERT_CLOSE(Q[6], 0.0, 0, 0);
                ASSERT_CLOSE(Q[14], 0.0, 0, 0);
            }
        }
    }
    return w;
}

static void test_point_force_jacobian(void **state)
{
    const double tol = 64.0 * FD_ERR;
    tu_rng g = tu_rng_seed(313);
    double w = 0.0;
    int s, l;
    (void)state;
    for (s = 0; s < 2; ++s) {
        st3 x;
        make_state(&g, 0.5, 0.15, 0.8, &x, NULL);
        for (l = 0; l < 2; ++l) {
            ale3_fd c;
            ctx_init(&c, NULL, l ? VLBE_ALE3_NO_SPIN : 0u);
            pack(c.fd.mode, &x, c.fd.q);
            c.F[0] = (vlbe_real)(3.0 * tu_rng_uniform(&g));
            c.F[1] = (vlbe_real)(3.0 * tu_rng_uniform(&g));
            c.F[2] = (vlbe_real)(3.0 * tu_rng_uniform(&g));
            w = fmax(w, point_load_check(&c, 0, tol));
        }
    }
    tu_report("point force K, err / entry scale", w, tol);
    tu_measured("pf_fd", w / FD_ERR);
}

static void test_point_torque_jacobian(void **state)
{
    const double tol = 64.0 * FD_ERR;
    tu_rng g = tu_rng_seed(314);
    double w = 0.0;
    int s;
    (void)state;
    for (s = 0; s < 3; ++s) {
        st3 x;
        ale3_fd c;
        vlbe_real Q[NQ], K[NN];
        make_state(&g, 0.5, 0.15, 0.8, &x, NULL);
        ctx_init(&c, NULL, 0u);
        pack(0u, &x, c.fd.q);
        c.T = (vlbe_real)(3.0 * tu_rng_uniform(&g));
        w = fmax(w, point_load_check(&c, 1, tol));
        /* without spin there is no angle to act on */
        {
            vlbe_real q14[NQ];
            pack(VLBE_ALE3_NO_SPIN, &x, q14);
            fill(NQ, SENTINEL, Q);
            fill(NN, SENTINEL, K);
            assert_int_equal(vlbe_ale3_point_torque(VLBE_ALE3_NO_SPIN, q14, q14[6], c.T, Q, K),
                             VLBE_EARG);
            assert_int_equal(vlbe_ale3_point_torque(VLBE_ALE3_NO_SPIN, q14, q14[6], c.T, Q, NULL),
                             VLBE_EARG);
            assert_all_equal(NQ, Q, SENTINEL);
            assert_all_equal(NN, K, SENTINEL);
        }
        /* outside [p1, p2], also just outside; the ends are inside */
        {
            const vlbe_real F[3] = {VLBE_R(1.0), VLBE_R(-2.0), VLBE_R(0.5)};
            const vlbe_real outside[4] = {c.fd.q[7] - VLBE_R(0.3), c.fd.q[15] + VLBE_R(0.3),
                                          c.fd.q[7] - VLBE_R(4.0) * VLBE_EPS * c.fd.q[7],
                                          c.fd.q[15] + VLBE_R(4.0) * VLBE_EPS * c.fd.q[15]};
            int i;
            for (i = 0; i < 4; ++i) {
                assert_true(outside[i] < c.fd.q[7] || outside[i] > c.fd.q[15]);
                fill(NQ, SENTINEL, Q);
                fill(NN, SENTINEL, K);
                assert_int_equal(vlbe_ale3_point_torque(0, c.fd.q, outside[i], c.T, Q, K),
                                 VLBE_EBOUND);
                assert_int_equal(vlbe_ale3_point_force(0, c.fd.q, outside[i], F, Q, K),
                                 VLBE_EBOUND);
                assert_int_equal(vlbe_ale3_point_force(0, c.fd.q, outside[i], F, Q, NULL),
                                 VLBE_EBOUND);
                assert_all_equal(NQ, Q, SENTINEL);
                assert_all_equal(NN, K, SENTINEL);
            }
        }
    }
    tu_report("point torque K, err / entry scale", w, tol);
    tu_measured("pt_fd", w / FD_ERR);
}

/* ======================================================================= */
/* 4. forces as gradients of the energies                                    */
/* ======================================================================= */

/* d(E[1] + E[2])/dq (kinetic = 0) or dE[0]/dq (kinetic = 1) by central
   differences, all n columns. */
static void energy_grad(const vlbe_ale3_elem *el, unsigned mode, const vlbe_real *q,
                        const vlbe_real *qd, int kinetic, double *grad)
{
    ale3_fd c;
    double Jfd[3 * NQ];
    int j, n;
    ctx_init(&c, el, mode);
    n = c.fd.n;
    c.fd.which = FD_E_OF_Q;
    c.fd.nout = 3;
    memcpy(c.fd.q, q, (size_t)n * sizeof *q);
    memcpy(c.fd.qd, qd, (size_t)n * sizeof *qd);
    fd_jac(&c.fd, NULL, Jfd);
    for (j = 0; j < n; ++j) grad[j] = kinetic ? Jfd[j] : Jfd[n + j] + Jfd[2 * n + j];
}

static void test_energy_gradient(void **state)
{
    vlbe_ale3_mat m = mat3_std();
    const double tol = 16.0 * FD_ERR;
    const unsigned fix = VLBE_ALE_FIX_P1 | VLBE_ALE_FIX_P2;
    vlbe_ale3_elem el[2];
    tu_rng g = tu_rng_seed(314);
    double ws = 0.0, wb = 0.0, wf = 0.0;
    int s, k, i, r;
    (void)state;
    m.c_eps = m.c_kap = m.c_phi = VLBE_R(0.0);
    elem_make(&el[0], &m, 0, 0, 0);
    elem_make(&el[1], &m, 0, 8, 8);
    for (s = 0; s < 3; ++s) {
        st3 x;
        make_state(&g, 0.5, 0.15, 0.8, &x, NULL);
        for (r = 0; r < 2; ++r)
            for (k = 0; k < N_MODES; ++k) {
                const unsigned mode = mode_of(k);
                vlbe_real q[NQ], qd[NQ], Q[NQ], K[NN];
                double grad[NQ], scale;
                const int n = nq_of(mode);
                if ((mode & fix) != fix) continue;
                pack(mode, &x, q);
                fill(NQ, VLBE_R(0.0), qd);
                assert_int_equal(vlbe_ale3_force(&el[r], mode, q, qd, Q, K, NULL), VLBE_OK);
                energy_grad(&el[r], mode, q, qd, 0, grad);
                scale = fmax(fmax(max_abs(n, Q), tu_max_abs(n, grad)), max_abs(n * n, K));
                for (i = 0; i < n; ++i) {
                    const double res = is_p(mode, i) ? 0.0 : grad[i] + (double)Q[i];
                    if (mode & VLBE_ALE_NO_BEND)
                        ws = fmax(ws, fabs(res) / scale);
                    else
                        wb = fmax(wb, fabs(res) / scale);
                    ASSERT_CLOSE_CTX(res, 0.0, 0, tol * scale, "row %d, mode %u, rule %d", i, mode,
                                     r);
                }
            }
    }
    /* free p, the string with twist (exact quadrature): the p-rows with
       the end fluxes of u = (EA eps^2 + GI phi^2)/2 and of the load f.r */
    for (s = 0; s < 3; ++s) {
        st3 x;
        make_state(&g, 0.5, 0.15, 0.8, &x, NULL);
        for (k = 0; k < N_MODES; ++k) {
            const unsigned mode = mode_of(k) | VLBE_ALE_NO_BEND;
            vlbe_real q[NQ], qd[NQ], Q[NQ], K[NN];
            double grad[NQ], scale, flux[2];
            const int n = nq_of(mode);
            if (mode_of(k) & VLBE_ALE_NO_BEND) continue;
            pack(mode, &x, q);
            fill(NQ, VLBE_R(0.0), qd);
            assert_int_equal(vlbe_ale3_force(&el[0], mode, q, qd, Q, K, NULL), VLBE_OK);
            energy_grad(&el[0], mode, q, qd, 0, grad);
            for (i = 0; i < 2; ++i) {
                const vlbe_real p = q[idx_p(mode, i)];
                vlbe_real eps = VLBE_R(0.0), phi = VLBE_R(0.0), rr[3] = {0, 0, 0};
                const int tw = !(mode & (VLBE_ALE3_NO_SPIN | VLBE_ALE3_NO_TWIST));
                assert_int_equal(vlbe_ale3_strain(mode, q, p, &eps, NULL, &phi), VLBE_OK);
                assert_int_equal(vlbe_ale3_point(mode, q, p, rr, NULL, NULL), VLBE_OK);
                flux[i] = 0.5 * (double)m.EA * (double)eps * (double)eps +
                          (tw ? 0.5 * (double)m.GI * (double)phi * (double)phi : 0.0) -
                          ((double)m.f[0] * (double)rr[0] + (double)m.f[1] * (double)rr[1] +
                           (double)m.f[2] * (double)rr[2]);
            }
            scale = fmax(fmax(max_abs(n, Q), tu_max_abs(n, grad)), max_abs(n * n, K));
            for (i = 0; i < n; ++i) {
                double res = grad[i] + (double)Q[i];
                if (i == idx_p(mode, 0)) res += flux[0];
                if (i == idx_p(mode, 1)) res -= flux[1];
                if (is_fixed(mode, i)) res = 0.0;
                wf = fmax(wf, fabs(res) / scale);
                ASSERT_CLOSE_CTX(res, 0.0, 0, tol * scale, "free p: row %d, mode %u", i, mode);
            }
        }
    }
    tu_report("string: -Q - grad(U + V), p fixed", ws, tol);
    tu_report("bending: -Q - grad(U + V), p fixed, same rule", wb, tol);
    tu_report("string, free p: -Q - grad(U + V) + end fluxes", wf, tol);
    tu_measured("eg_fd", fmax(fmax(ws, wb), wf) / FD_ERR);
}

/* ======================================================================= */
/* 5. kinetic energy and mass matrix                                         */
/* ======================================================================= */


/* The classic constant ANCF cable mass on the Hermite data (r1, r1', r2,
   r2'), rhoA L C_ij times the L powers of the slopes. */
static double classic_mass(double rhoA, double L, int i, int j)
{
    static const double cm[4][4] = {{13.0 / 35.0, 11.0 / 210.0, 9.0 / 70.0, -13.0 / 420.0},
                                    {11.0 / 210.0, 1.0 / 105.0, 13.0 / 420.0, -1.0 / 140.0},
                                    {9.0 / 70.0, 13.0 / 420.0, 13.0 / 35.0, -11.0 / 210.0},
                                    {-13.0 / 420.0, -1.0 / 140.0, -11.0 / 210.0, 1.0 / 105.0}};
    const int pw = (i & 1) + (j & 1);
    return rhoA * L * cm[i][j] * (pw == 0 ? 1.0 : pw == 1 ? L : L * L);
}

static void test_kinetic_energy(void **state)
{
    const vlbe_ale3_mat m = mat3_std();
    vlbe_ale3_elem el;
    tu_rng g = tu_rng_seed(315);
    double wt = 0.0, wsym = 0.0, wm = 0.0, wth = 0.0, wc = 0.0, wn = 0.0;
    int s, k, i, j;
    (void)state;
    elem_make(&el, &m, 0, 0, 0);
    for (s = 0; s < 4; ++s) {
        st3 x, xd;
        make_state(&g, 0.5, 0.15, 0.8, &x, &xd);
        for (k = 0; k < N_MODES; ++k) {
            const unsigned mode = mode_of(k);
            const int n = nq_of(mode), o = node_len(mode);
            const int pfix = (mode & VLBE_ALE_FIX_P1) && (mode & VLBE_ALE_FIX_P2);
            vlbe_real q[NQ], qd[NQ], M[NN], E[3];
            double u[NQ], absum, t, L, mx;
            int e_idx[NQ], ne = 0, c;
            pack(mode, &x, q);
            pack(mode, &xd, qd);
            L = (double)q[idx_p(mode, 1)] - (double)q[idx_p(mode, 0)];
            assert_int_equal(vlbe_ale3_mass(&el, mode, q, M), VLBE_OK);
            assert_int_equal(vlbe_ale3_energy(&el, mode, q, qd, E), VLBE_OK);
            check_fixed_zero(mode, NULL, M);
            mx = max_abs(n * n, M);
            /* T = qd^T M qd / 2 */
            for (i = 0; i < n; ++i) u[i] = (double)qd[i];
            t = 0.5 * quad_form(n, M, u, &absum);
            wt = fmax(wt, fabs((double)E[0] - t) / (EPS * absum));
            ASSERT_CLOSE_CTX(E[0], t, 0, 64 * EPS * absum, "T, mode %u", mode);
            /* exactly symmetric */
            for (i = 0; i < n; ++i)
                for (j = 0; j < i; ++j) {
                    const double d = fabs((double)M[i * n + j] - (double)M[j * n + i]);
                    wsym = fmax(wsym, d / (EPS * mx));
                    ASSERT_CLOSE_CTX(M[i * n + j], M[j * n + i], 0, 0.0,
                                     "symmetry (%d, %d), mode %u", i, j, mode);
                }
            /* total mass of the position block: unit translations */
            for (c = 0; c < 3; ++c) {
                double ux[NQ] = {0.0}, mt;
                ux[c] = ux[o + c] = 1.0;
                mt = quad_form(n, M, ux, NULL);
                wm = fmax(wm, fabs(mt / ((double)m.rhoA * L) - 1.0) / EPS);
                ASSERT_CLOSE(mt, (double)m.rhoA * L, 16 * EPS, 0);
            }
            /* theta block: rhoI L [1/3 1/6; 1/6 1/3] */
            if (!(mode & VLBE_ALE3_NO_SPIN)) {
                const double ref[2][2] = {{1.0 / 3.0, 1.0 / 6.0}, {1.0 / 6.0, 1.0 / 3.0}};
                int a, b;
                for (a = 0; a < 2; ++a)
                    for (b = 0; b < 2; ++b) {
                        const double v = (double)M[idx_th(mode, a) * n + idx_th(mode, b)];
                        const double rv = (double)m.rhoI * L * ref[a][b];
                        wth = fmax(wth, fabs(v - rv) / (EPS * rv));
                        ASSERT_CLOSE(v, rv, 16 * EPS, 0);
                    }
                /* no coupling of theta with the position field at fixed p */
                for (i = 0; i < n; ++i)
                    if (!is_th(mode, i) && !is_p(mode, i)) {
                        ASSERT_CLOSE(M[idx_th(mode, 0) * n + i], 0.0, 0, 0);
                        ASSERT_CLOSE(M[idx_th(mode, 1) * n + i], 0.0, 0, 0);
                    }
            }
            /* positive semidefinite: x^T M x >= 0 for random x (beyond its
               rounding 16 EPS sum|terms| the other way: > -that) and > 0
               when both p are fixed; the e/theta block positive definite */
            for (i = 0; i < n; ++i)
                if (!is_p(mode, i)) e_idx[ne++] = i;
            assert_true(cholesky_ok(M, n, e_idx, ne));
            for (i = 0; i < 4; ++i) {
                double xr[NQ], qf;
                for (j = 0; j < n; ++j) xr[j] = is_fixed(mode, j) ? 0.0 : tu_rng_uniform(&g);
                qf = quad_form(n, M, xr, &absum);
                assert_true(qf > 16 * EPS * absum);
            }
            if (pfix) {
                /* the classic constant matrix C (x) I3, rounding 64 EPS
                   relative per entry */
                int a, b, c2;
                for (a = 0; a < 4; ++a)
                    for (b = 0; b < 4; ++b)
                        for (c = 0; c < 3; ++c)
                            for (c2 = 0; c2 < 3; ++c2) {
                                const int ri = (a / 2) * o + (a & 1) * 3 + c;
                                const int ci = (b / 2) * o + (b & 1) * 3 + c2;
                                const double ref =
                                    c == c2 ? classic_mass((double)m.rhoA, L, a, b) : 0.0;
                                if (c == c2)
                                    wc = fmax(wc, fabs((double)M[ri * n + ci] - ref) /
                                                      (EPS * fabs(ref)));
                                ASSERT_CLOSE_CTX(M[ri * n + ci], ref, 64 * EPS, 0,
                                                 "classic mass (%d, %d)", ri, ci);
                            }
            }
            /* a free p_k: the re-parametrization that moves p_k together
               with the nodal data moves no material point, M x = 0 with
               x = (r_k': at r_k, r''(p_k): at r_k', theta'(p_k): at theta_k,
               1: at p_k) (linear theta: theta' = (th2 - th1)/L) */
            for (i = 0; i < 2; ++i) {
                const int pk = idx_p(mode, i);
                vlbe_herm_ale hb;
                double xn[NQ] = {0.0}, rpp[3] = {0.0, 0.0, 0.0}, xs;
                int r, jj, b;
                if (is_fixed(mode, pk)) continue;
                vlbe_herm_ale_eval(q[pk], q[idx_p(mode, 0)], q[idx_p(mode, 1)], 2, 0, &hb);
                for (b = 0; b < 4; ++b)
                    for (c = 0; c < 3; ++c)
                        rpp[c] += (double)hb.h[2][0][b] * (double)q[(b / 2) * o + (b & 1) * 3 + c];
                xn[pk] = 1.0;
                for (c = 0; c < 3; ++c) {
                    xn[i * o + c] = (double)q[i * o + 3 + c];
                    xn[i * o + 3 + c] = rpp[c];
                }
                if (!(mode & VLBE_ALE3_NO_SPIN))
                    xn[idx_th(mode, i)] = ((double)q[14] - (double)q[6]) / L;
                xs = tu_max_abs(n, xn);
                for (r = 0; r < n; ++r) {
                    double Mx = 0.0;
                    if (is_fixed(mode, r)) continue;
                    for (jj = 0; jj < n; ++jj) Mx += (double)M[r * n + jj] * xn[jj];
                    wn = fmax(wn, fabs(Mx) / (EPS * mx * xs));
                    ASSERT_CLOSE_CTX(Mx, 0.0, 0, 64 * EPS * mx * xs,
                                     "null vector of p%d, row %d, mode %u", i + 1, r, mode);
                }
            }
        }
    }
    tu_report("T - qd^T M qd / 2, in EPS * sum|terms|", wt, 64.0);
    tu_report("M - M^T, in EPS max|M|", wsym, 0.0);
    tu_report("total mass, in EPS", wm, 16.0);
    tu_report("theta block rhoI L/3, L/6, in EPS", wth, 16.0);
    tu_report("classic mass (p fixed), in EPS per entry", wc, 64.0);
    tu_report("M x_null (free p), in EPS max|M| |x|", wn, 64.0);
    tu_measured("ke_T", wt);
    tu_measured("ke_sym", wsym);
    tu_measured("ke_mass", wm);
    tu_measured("ke_theta", wth);
    tu_measured("ke_classic", wc);
    tu_measured("ke_null", wn);
}

/* ======================================================================= */
/* 6. the planar element in the plane                                        */
/* ======================================================================= */

/* planar coordinate i (0..9) -> its 3D index in mode */
static int map2(unsigned mode, int i)
{
    static const int comp[5] = {0, 1, 3, 4, -1};
    const int o = node_len(mode), k = i / 5, c = i % 5;
    return k * o + (c == 4 ? o - 1 : comp[c]);
}

static void test_planar_reproduction(void **state)
{
    const vlbe_ale_mat m2 = mat_std();
    vlbe_ale3_mat m3 = mat3_std();
    const double tol = 32.0 * EPS;
    vlbe_ale_elem e2 = {0}; /* cmocka asserts are not noreturn: gcc -O2 cannot see init ran */
    vlbe_ale3_elem e3;
    tu_rng g = tu_rng_seed(316);
    double wq = 0.0, wk = 0.0, wd = 0.0, wmm = 0.0, wx = 0.0, wq1 = 0.0;
    int s, k, i, j;
    (void)state;
    mat3_planar(&m3, &m2);
    assert_int_equal(vlbe_ale_elem_init(&e2, &m2, 0, 0, 0, 0), VLBE_OK);
    elem_make(&e3, &m3, 0, 0, 0);
    for (s = 0; s < 4; ++s) {
        const double p1 = 0.3 + 0.2 * tu_rng_uniform(&g), L = 1.2 + 0.2 * tu_rng_uniform(&g);
        const double th = PI * tu_rng_uniform(&g), sc = 1.0 + 0.15 * tu_rng_uniform(&g);
        const double x1 = tu_rng_uniform(&g), y1 = tu_rng_uniform(&g);
        const double a1 = th + 0.6 * tu_rng_uniform(&g), a2 = th + 0.6 * tu_rng_uniform(&g);
        const double s1 = sc * (1.0 + 0.1 * tu_rng_uniform(&g));
        const double s2 = sc * (1.0 + 0.1 * tu_rng_uniform(&g));
        vlbe_real q2[10], qd2[10];
        ale_chord_q(p1, L, x1, y1, th, sc, a1, a2, s1, s2, q2);
        for (i = 0; i < 10; ++i)
            qd2[i] = (vlbe_real)(((i % 5) == 4 ? 0.5 : 1.0) * tu_rng_uniform(&g));
        for (k = 0; k < 32; ++k) {
            /* NO_BEND, NO_DAMP, FIX_P1, FIX_P2; with and without spin */
            const unsigned mode2 = (unsigned)k & 15u;
            const unsigned mode3 = mode2 | ((k & 16) ? VLBE_ALE3_NO_SPIN : 0u);
            const int n = nq_of(mode3);
            vlbe_real Q2[10], K2[100], D2[100], M2[100], Q2f[10];
            vlbe_real q3[NQ], qd3[NQ], Q3[NQ], K3[NN], D3[NN], M3[NN];
            int in[NQ];
            double sq, sk, sd, sm;
            fill(NQ, VLBE_R(0.0), q3);
            fill(NQ, VLBE_R(0.0), qd3);
            for (i = 0; i < NQ; ++i) in[i] = 0;
            for (i = 0; i < 10; ++i) {
                q3[map2(mode3, i)] = q2[i];
                qd3[map2(mode3, i)] = qd2[i];
                in[map2(mode3, i)] = 1;
            }
            assert_int_equal(vlbe_ale_force(&e2, mode2, q2, qd2, Q2, K2, D2), VLBE_OK);
            assert_int_equal(vlbe_ale_force(&e2, mode2, q2, qd2, Q2f, NULL, NULL), VLBE_OK);
            assert_int_equal(vlbe_ale_mass(&e2, mode2, q2, M2), VLBE_OK);
            assert_int_equal(vlbe_ale3_force(&e3, mode3, q3, qd3, Q3, K3, D3), VLBE_OK);
            assert_int_equal(vlbe_ale3_mass(&e3, mode3, q3, M3), VLBE_OK);
            sq = max_abs(10, Q2);
            sk = max_abs(100, K2);
            sd = max_abs(100, D2);
            sm = max_abs(100, M2);
            for (i = 0; i < 10; ++i) {
                const int a = map2(mode3, i);
                wq = fmax(wq, fabs((double)Q3[a] - (double)Q2[i]) / (EPS * sq));
                wq1 = fmax(wq1, fabs((double)Q3[a] - (double)Q2f[i]) / (EPS * sq));
                ASSERT_CLOSE_CTX(Q3[a], Q2[i], 0, tol * sq, "Q[%d], mode %u", i, mode3);
                ASSERT_CLOSE_CTX(Q3[a], Q2f[i], 0, 2.0 * tol * sq, "Q[%d] (Q alone), mode %u", i,
                                 mode3);
                for (j = 0; j < 10; ++j) {
                    const int b = map2(mode3, j);
                    wk =
                        fmax(wk, fabs((double)K3[a * n + b] - (double)K2[i * 10 + j]) / (EPS * sk));
                    if (sd > 0.0)
                        wd = fmax(wd, fabs((double)D3[a * n + b] - (double)D2[i * 10 + j]) /
                                          (EPS * sd));
                    wmm = fmax(wmm,
                               fabs((double)M3[a * n + b] - (double)M2[i * 10 + j]) / (EPS * sm));
                    ASSERT_CLOSE_CTX(K3[a * n + b], K2[i * 10 + j], 0, tol * sk,
                                     "K (%d, %d), mode %u", i, j, mode3);
                    ASSERT_CLOSE_CTX(D3[a * n + b], D2[i * 10 + j], 0, tol * sd,
                                     "D (%d, %d), mode %u", i, j, mode3);
                    ASSERT_CLOSE_CTX(M3[a * n + b], M2[i * 10 + j], 0, tol * sm,
                                     "M (%d, %d), mode %u", i, j, mode3);
                }
            }
            /* out of plane: z, z', theta rows of Q exactly zero; K, D, M do
               not couple the plane to them (reflection symmetry z -> -z) */
            for (i = 0; i < n; ++i) {
                if (in[i]) continue;
                ASSERT_CLOSE_CTX(Q3[i], 0.0, 0, 0, "out-of-plane Q[%d], mode %u", i, mode3);
                for (j = 0; j < n; ++j) {
                    if (!in[j]) continue;
                    wx = fmax(wx, fabs((double)K3[i * n + j]) / (EPS * sk));
                    wx = fmax(wx, fabs((double)K3[j * n + i]) / (EPS * sk));
                    ASSERT_CLOSE_CTX(K3[i * n + j], 0.0, 0, tol * sk, "K (%d, %d)", i, j);
                    ASSERT_CLOSE_CTX(K3[j * n + i], 0.0, 0, tol * sk, "K (%d, %d)", j, i);
                    ASSERT_CLOSE_CTX(D3[i * n + j], 0.0, 0, tol * sd, "D (%d, %d)", i, j);
                    ASSERT_CLOSE_CTX(D3[j * n + i], 0.0, 0, tol * sd, "D (%d, %d)", j, i);
                    ASSERT_CLOSE_CTX(M3[i * n + j], 0.0, 0, tol * sm, "M (%d, %d)", i, j);
                }
            }
        }
    }
    tu_report("planar vs 3D: Q, in EPS max|Q|", wq, 32.0);
    tu_report("planar (Q alone route) vs 3D: Q, in EPS max|Q|", wq1, 64.0);
    tu_report("planar vs 3D: K, in EPS max|K|", wk, 32.0);
    tu_report("planar vs 3D: D, in EPS max|D|", wd, 32.0);
    tu_report("planar vs 3D: M, in EPS max|M|", wmm, 32.0);
    tu_report("3D: K coupling plane / out of plane, in EPS max|K|", wx, 32.0);
    tu_measured("pl_QKDM", fmax(fmax(wq, wk), fmax(wd, wmm)));
    tu_measured("pl_Qalone", wq1);
    tu_measured("pl_couple", wx);
}

/* ======================================================================= */
/* 7. rigid motion and rotation covariance                                   */
/* ======================================================================= */

static void test_rigid_motion(void **state)
{
    static const double angles[] = {0.0, 0.3, 2.1, -1.7, 7.5, 100.0};
    static const double shifts[][3] = {{0.0, 0.0, 0.0}, {3.0, -2.0, 1.0}, {-10.0, 7.5, -4.0}};
    vlbe_ale3_mat m = mat3_std();
    vlbe_ale3_elem el;
    tu_rng g = tu_rng_seed(317);
    double w = 0.0, wr = 0.0, wkr = 0.0;
    int ia, is, k, i, j, c;
    (void)state;
    m.f[0] = m.f[1] = m.f[2] = VLBE_R(0.0);
    elem_make(&el, &m, 0, 0, 0);
    for (ia = 0; ia < ARRAY_LEN(angles); ++ia)
        for (is = 0; is < ARRAY_LEN(shifts); ++is) {
            const double p1 = 0.35, L = 1.25, th0 = 2.3 * tu_rng_uniform(&g);
            const double Om = 2.0 * tu_rng_uniform(&g);
            double ax[3], R[9], t[3], ex[3] = {1.0, 0.0, 0.0}, v0[3], om[3], rmax, vmax, S;
            st3 x, xd;
            int kk;
            rand_dir(&g, ax);
            rotation(ax, angles[ia], R);
            mat3_vec(R, ex, t);
            rand_vec(&g, v0);
            rand_vec(&g, om);
            for (kk = 0; kk < 2; ++kk) {
                double wr3[3], wt3[3];
                for (c = 0; c < 3; ++c) {
                    x.n[kk].r[c] = shifts[is][c] + (0.2 + kk * L) * t[c];
                    x.n[kk].rp[c] = t[c];
                }
                x.n[kk].th = th0;
                x.n[kk].p = p1 + kk * L;
                cross3(om, x.n[kk].r, wr3);
                cross3(om, t, wt3);
                for (c = 0; c < 3; ++c) {
                    xd.n[kk].r[c] = v0[c] + wr3[c];
                    xd.n[kk].rp[c] = wt3[c];
                }
                xd.n[kk].th = Om;
                xd.n[kk].p = 0.0;
            }
            rmax = vmax = 0.0;
            for (kk = 0; kk < 2; ++kk)
                for (c = 0; c < 3; ++c) {
                    rmax = fmax(rmax, fabs(x.n[kk].r[c]));
                    vmax = fmax(vmax, fabs(xd.n[kk].r[c]));
                }
            /* the size the cancelling terms would have: EA eps with eps
               rounded from positions of size |r| over L, EJ/L^2 for the
               curvature, the Kelvin-Voigt parts with rates of size vmax */
            S = (1.0 + rmax / L) *
                ((double)m.EA + (double)m.EJ / (L * L) +
                 ((double)m.c_eps * (double)m.EA + (double)m.c_kap * (double)m.EJ / (L * L)) *
                     vmax / L);
            for (k = 0; k < N_MODES; ++k) {
                const unsigned mode = mode_of(k) | VLBE_ALE_FIX_P1 | VLBE_ALE_FIX_P2;
                const int n = nq_of(mode);
                vlbe_real q[NQ], qd[NQ], Q[NQ], E[3];
                if (mode_of(k) & (VLBE_ALE_FIX_P1 | VLBE_ALE_FIX_P2)) continue;
                pack(mode, &x, q);
                pack(mode, &xd, qd);
                assert_int_equal(vlbe_ale3_force(&el, mode, q, qd, Q, NULL, NULL), VLBE_OK);
                for (i = 0; i < n; ++i) {
                    w = fmax(w, fabs((double)Q[i]) / (EPS * S));
                    ASSERT_CLOSE_CTX(Q[i], 0.0, 0, 64.0 * EPS * S,
                                     "angle %g shift %d mode %u row %d", angles[ia], is, mode, i);
                }
                assert_int_equal(vlbe_ale3_energy(&el, mode, q, qd, E), VLBE_OK);
                ASSERT_CLOSE(E[1], 0.0, 0, 64.0 * EPS * S * L); /* U ~ EA eps^2 L: tiny */
            }
        }
    tu_report("rigid motion |Q| in EPS (1 + |r|/L) (EA + EJ/L^2 + damping)", w, 64.0);
    tu_measured("rm_Q", w);

    /* Q(B q) = B Q(q), K(B q) = B K(q) B^T, D likewise, for a curved,
       twisted, moving state: B rotates every 3-block (positions, slopes,
       their rates, and the load), translates the positions, leaves theta
       and p alone.  Rounding: 64 EPS (1 + |c|/L) of the largest entry of
       the compared array. */
    {
        vlbe_ale3_mat mr = mat3_std();
        const vlbe_ale3_mat m0 = mat3_std();
        vlbe_ale3_elem e0, er;
        int s;
        elem_make(&e0, &m0, 0, 0, 0);
        for (s = 0; s < 3; ++s) {
            const double shift[3] = {0.5, -1.0, 2.0}, ang = 0.9 + 2.0 * s;
            double ax[3], R[9], f0[3], fr[3], sh = 0.0;
            st3 x, xd, y, yd;
            int kk;
            make_state(&g, 0.5, 0.15, 0.8, &x, &xd);
            rand_dir(&g, ax);
            rotation(ax, ang, R);
            for (c = 0; c < 3; ++c) {
                f0[c] = (double)m0.f[c];
                sh = fmax(sh, fabs(shift[c]));
            }
            mat3_vec(R, f0, fr);
            for (c = 0; c < 3; ++c) mr.f[c] = (vlbe_real)fr[c];
            elem_make(&er, &mr, 0, 0, 0);
            y = x;
            yd = xd;
            for (kk = 0; kk < 2; ++kk) {
                mat3_vec(R, x.n[kk].r, y.n[kk].r);
                mat3_vec(R, x.n[kk].rp, y.n[kk].rp);
                mat3_vec(R, xd.n[kk].r, yd.n[kk].r);
                mat3_vec(R, xd.n[kk].rp, yd.n[kk].rp);
                for (c = 0; c < 3; ++c) y.n[kk].r[c] += shift[c];
            }
            for (k = 0; k < N_MODES; ++k) {
                const unsigned mode = mode_of(k);
                const int n = nq_of(mode), o = node_len(mode);
                vlbe_real q[NQ], qd[NQ], qr[NQ], qdr[NQ];
                vlbe_real Q[NQ], K[NN], D[NN], Qr[NQ], Kr[NN], Dr[NN];
                double B[NN] = {0.0}, BQ[NQ], BK[NN], BD[NN], T1[NN], T2[NN], tq;
                int a, b;
                pack(mode, &x, q);
                pack(mode, &xd, qd);
                pack(mode, &y, qr);
                pack(mode, &yd, qdr);
                assert_int_equal(vlbe_ale3_force(&e0, mode, q, qd, Q, K, D), VLBE_OK);
                assert_int_equal(vlbe_ale3_force(&er, mode, qr, qdr, Qr, Kr, Dr), VLBE_OK);
                /* B: block diagonal */
                for (i = 0; i < n; ++i)
                    if (is_p(mode, i) || is_th(mode, i)) B[i * n + i] = 1.0;
                for (kk = 0; kk < 2; ++kk)
                    for (a = 0; a < 2; ++a)
                        for (i = 0; i < 3; ++i)
                            for (j = 0; j < 3; ++j)
                                B[(kk * o + 3 * a + i) * n + kk * o + 3 * a + j] = R[i * 3 + j];
                for (i = 0; i < n; ++i) {
                    BQ[i] = 0.0;
                    for (j = 0; j < n; ++j) {
                        BQ[i] += B[i * n + j] * (double)Q[j];
                        T1[i * n + j] = T2[i * n + j] = 0.0;
                        for (a = 0; a < n; ++a) {
                            T1[i * n + j] += B[i * n + a] * (double)K[a * n + j];
                            T2[i * n + j] += B[i * n + a] * (double)D[a * n + j];
                        }
                    }
                }
                for (i = 0; i < n; ++i)
                    for (j = 0; j < n; ++j) {
                        BK[i * n + j] = BD[i * n + j] = 0.0;
                        for (b = 0; b < n; ++b) {
                            BK[i * n + j] += T1[i * n + b] * B[j * n + b];
                            BD[i * n + j] += T2[i * n + b] * B[j * n + b];
                        }
                    }
                tq = 64.0 * EPS * (1.0 + sh);
                {
                    const double sq = tu_max_abs(n, BQ), sk = tu_max_abs(n * n, BK);
                    const double sd = tu_max_abs(n * n, BD);
                    for (i = 0; i < n; ++i) wr = fmax(wr, fabs((double)Qr[i] - BQ[i]) / (EPS * sq));
                    for (i = 0; i < n * n; ++i) {
                        wkr = fmax(wkr, fabs((double)Kr[i] - BK[i]) / (EPS * sk));
                        wkr = fmax(wkr, fabs((double)Dr[i] - BD[i]) / (EPS * sd));
                    }
                    ASSERT_VEC_CLOSE(Qr, BQ, n, 0, tq * sq);
                    ASSERT_VEC_CLOSE(Kr, BK, n * n, 0, tq * sk);
                    ASSERT_VEC_CLOSE(Dr, BD, n * n, 0, tq * sd);
                }
            }
        }
    }
    tu_report("rotated state: Q(Bq) - B Q(q), in EPS max|Q|", wr, 64.0 * 3.0);
    tu_report("rotated state: K, D, in EPS max", wkr, 64.0 * 3.0);
    tu_measured("rm_rot", fmax(wr, wkr));
}

/* ======================================================================= */
/* 8. pure twist                                                             */
/* ======================================================================= */

static void test_twist_energy(void **state)
{
    static const double phis[] = {0.3, -1.7, 5.0, 1e-3};
    static const double lens[] = {0.4, 1.25, 3.0};
    vlbe_ale3_mat m = mat3_std();
    vlbe_ale3_elem el;
    tu_rng g = tu_rng_seed(318);
    double wu = 0.0, wt = 0.0, wp = 0.0, wo = 0.0;
    int ip, il, k, i, c;
    (void)state;
    m.f[0] = m.f[1] = m.f[2] = VLBE_R(0.0);
    elem_make(&el, &m, 0, 0, 0);
    for (ip = 0; ip < ARRAY_LEN(phis); ++ip)
        for (il = 0; il < ARRAY_LEN(lens); ++il) {
            const double phi = phis[ip], L = lens[il], p1 = 0.3, GI = (double)m.GI;
            double t[3], x0[3], rmax = 0.0, S, Ur;
            st3 x;
            int kk;
            rand_dir(&g, t);
            rand_vec(&g, x0);
            for (kk = 0; kk < 2; ++kk) {
                for (c = 0; c < 3; ++c) {
                    x.n[kk].r[c] = 2.0 * x0[c] + kk * L * t[c];
                    x.n[kk].rp[c] = t[c];
                    rmax = fmax(rmax, fabs(x.n[kk].r[c]));
                }
                x.n[kk].th = kk * phi * L;
                x.n[kk].p = p1 + kk * L;
            }
            /* rounding scale of the (vanishing) axial and bending parts:
               forces ~ S EPS; strain energy L/2 (EA eps^2 + EJ k^2) with
               eps ~ 64 EPS (1 + |r|/L), k ~ that / L */
            S = (1.0 + rmax / L) * ((double)m.EA + (double)m.EJ / (L * L));
            Ur = 0.5 * L * pow(64.0 * EPS * (1.0 + rmax / L), 2.0) *
                 ((double)m.EA + (double)m.EJ / (L * L));
            for (k = 0; k < N_MODES; ++k) {
                const unsigned mode = mode_of(k);
                const int n = nq_of(mode);
                const int tw = !(mode & VLBE_ALE3_NO_TWIST);
                vlbe_real q[NQ], qd[NQ], Q[NQ], E[3];
                double Uref, phic;
                if (mode & VLBE_ALE3_NO_SPIN) continue;
                pack(mode, &x, q);
                fill(NQ, VLBE_R(0.0), qd);
                /* the twist of the rounded data */
                phic = (double)q[14] / L;
                Uref = tw ? 0.5 * GI * phic * phic * L : 0.0;
                assert_int_equal(vlbe_ale3_force(&el, mode, q, qd, Q, NULL, NULL), VLBE_OK);
                assert_int_equal(vlbe_ale3_energy(&el, mode, q, qd, E), VLBE_OK);
                wu = fmax(wu, fabs((double)E[1] - Uref) / (16 * EPS * Uref + Ur));
                ASSERT_CLOSE_CTX(E[1], Uref, 16 * EPS, Ur, "U: phi %g L %g mode %u", phi, L, mode);
                for (i = 0; i < n; ++i) {
                    double ref = 0.0, rt = 0.0, at = 64.0 * EPS * S;
                    if (i == 6 || i == 14) {
                        /* Q = -dU/dtheta: +GI phi at node 1, -GI phi at node 2 */
                        ref = tw ? (i == 6 ? GI * phic : -GI * phic) : 0.0;
                        rt = 16 * EPS;
                        at = 0.0;
                        if (tw) wt = fmax(wt, fabs((double)Q[i] - ref) / (rt * fabs(ref)));
                    } else if (is_p(mode, i) && !is_fixed(mode, i)) {
                        /* -int GI phi dphi/dp_k dp, dphi/dp1 = phi/L = -dphi/dp2 */
                        ref = tw ? (i == 7 ? -GI * phic * phic : GI * phic * phic) : 0.0;
                        rt = 16 * EPS;
                        if (tw) wp = fmax(wp, fabs((double)Q[i] - ref) / (rt * fabs(ref) + at));
                    } else {
                        wo = fmax(wo, fabs((double)Q[i]) / (EPS * S));
                    }
                    ASSERT_CLOSE_CTX(Q[i], ref, rt, at, "row %d: phi %g L %g mode %u", i, phi, L,
                                     mode);
                }
            }
        }
    tu_report("U - GI phi^2 L/2, / (16 EPS U + rounding of eps, k)", wu, 1.0);
    tu_report("nodal torques -+GI phi, / 16 EPS", wt, 1.0);
    tu_report("p-rows -+GI phi^2, / (16 EPS |Q| + 64 EPS S)", wp, 1.0);
    tu_report("other rows, in EPS (1 + |r|/L)(EA + EJ/L^2)", wo, 64.0);
    tu_measured("tw_ratio", fmax(fmax(wu, wt), fmax(wp, wo / 64)));
}

/* ======================================================================= */
/* 9. straight spinning shaft, axially moving                                */
/* ======================================================================= */

static void test_straight_shaft_spin(void **state)
{
    vlbe_ale3_mat m = mat3_std();
    vlbe_ale3_elem el;
    tu_rng g = tu_rng_seed(319);
    double w = 0.0;
    int s, k, i, c;
    (void)state;
    m.f[0] = m.f[1] = m.f[2] = VLBE_R(0.0);
    elem_make(&el, &m, 0, 0, 0);
    for (s = 0; s < 6; ++s) {
        const double p1 = 0.3 + 0.2 * tu_rng_uniform(&g), L = 1.2 + 0.2 * tu_rng_uniform(&g);
        const double th0 = 2.0 * tu_rng_uniform(&g), Om = 3.0 * tu_rng_uniform(&g);
        /* s = 0, 1: pure spin (no axial motion, nodes at rest) */
        const double v = s < 2 ? 0.0 : 1.5 * tu_rng_uniform(&g);
        const double pd[2] = {s < 2 ? 0.0 : 0.5 * tu_rng_uniform(&g),
                              s < 2 ? 0.0 : 0.5 * tu_rng_uniform(&g)};
        double t[3], x0[3];
        rand_dir(&g, t);
        rand_vec(&g, x0);
        for (k = 0; k < N_MODES; ++k) {
            const unsigned mode = mode_of(k);
            const int n = nq_of(mode);
            vlbe_real q[NQ], qd[NQ], Q[NQ];
            double rmax = 0.0, vmax = 0.0, pdm = 0.0, S;
            st3 x, xd;
            int kk;
            for (kk = 0; kk < 2; ++kk) {
                /* a fixed node has p' = 0 (the element ignores it) */
                const double pk =
                    (kk == 0 ? (mode & VLBE_ALE_FIX_P1) : (mode & VLBE_ALE_FIX_P2)) ? 0.0 : pd[kk];
                for (c = 0; c < 3; ++c) {
                    x.n[kk].r[c] = x0[c] + kk * L * t[c];
                    x.n[kk].rp[c] = t[c];
                    xd.n[kk].r[c] = (pk + v) * t[c];
                    xd.n[kk].rp[c] = 0.0;
                    rmax = fmax(rmax, fabs(x.n[kk].r[c]));
                    vmax = fmax(vmax, fabs(xd.n[kk].r[c]));
                }
                x.n[kk].th = th0;
                x.n[kk].p = p1 + kk * L;
                xd.n[kk].th = Om;
                xd.n[kk].p = pk;
                pdm = fmax(pdm, fabs(pk));
            }
            pack(mode, &x, q);
            pack(mode, &xd, qd);
            /* sizes of the cancelling terms: elastic as in rigid_motion, the
               Kelvin-Voigt rates from vmax and p' r'' (positions |r| over
               L^2), the transport accelerations rho (p'^2 |r|/L^2 + p' v/L)
               times L, spin alike with |theta|, |Omega| */
            S = (1.0 + rmax / L) *
                ((double)m.EA + (double)m.EJ / (L * L) +
                 ((double)m.c_eps * (double)m.EA + (double)m.c_kap * (double)m.EJ / (L * L)) *
                     (vmax + pdm) / L +
                 (double)m.rhoA * (pdm * pdm + pdm * vmax) +
                 (double)m.rhoI * (pdm * pdm * fabs(th0) / L + pdm * fabs(Om)));
            assert_int_equal(vlbe_ale3_force(&el, mode, q, qd, Q, NULL, NULL), VLBE_OK);
            for (i = 0; i < n; ++i) {
                w = fmax(w, fabs((double)Q[i]) / (EPS * S));
                ASSERT_CLOSE_CTX(Q[i], 0.0, 0, 64.0 * EPS * S, "state %d mode %u row %d", s, mode,
                                 i);
            }
        }
    }
    tu_report("straight spinning shaft |Q|, in EPS S", w, 64.0);
    tu_measured("ss_Q", w);
}

/* ======================================================================= */
/* 10. curvature                                                             */
/* ======================================================================= */

static void test_curvature(void **state)
{
    static const double thetas[] = {0.4, 0.2, 0.1};
    static const double radii[] = {0.5, 3.0};
    static const double xis[] = {-0.3, 0.0, 0.1, 0.37, 0.5, 0.77, 1.0, 1.4};
    const double tol = 64.0 * FD_ERR;
    const double ctr[3] = {0.3, -0.2, 0.1};
    vlbe_ale3_mat m = mat3_std();
    vlbe_ale3_elem el;
    tu_rng g = tu_rng_seed(320);
    double wm = 0.0, we = 0.0, ws = 0.0, wk = 0.0, wd = 0.0;
    double R3[9], ax[3], e1[3], e2[3], ex[3] = {1.0, 0.0, 0.0}, ey[3] = {0.0, 1.0, 0.0};
    int ir, it, ix, c, a, k;
    (void)state;
    elem_make(&el, &m, 0, 0, 0);
    /* the arc's plane: the xy-plane turned about a random axis */
    rand_dir(&g, ax);
    rotation(ax, 1.1, R3);
    mat3_vec(R3, ex, e1);
    mat3_vec(R3, ey, e2);
    for (ir = 0; ir < ARRAY_LEN(radii); ++ir) {
        double prev_mid = 0.0, prev_end = 0.0;
        for (it = 0; it < ARRAY_LEN(thetas); ++it) {
            const double R = radii[ir], th = thetas[it], L = R * th, p1 = 0.25, a0 = 0.7;
            const double rnd = 32.0 * EPS * (1.0 + sqrt(dot3(ctr, ctr)) / R) / (th * th);
            vlbe_real q[NQ];
            double emid = 0.0, eend = 0.0;
            int kk;
            for (kk = 0; kk < 2; ++kk) {
                const double ph = a0 + kk * th;
                for (c = 0; c < 3; ++c) {
                    q[8 * kk + c] = (vlbe_real)(ctr[c] + R * (sin(ph) * e1[c] - cos(ph) * e2[c]));
                    q[8 * kk + 3 + c] = (vlbe_real)(cos(ph) * e1[c] + sin(ph) * e2[c]);
                }
                q[8 * kk + 6] = (vlbe_real)(0.3 + 0.5 * kk * L);
                q[8 * kk + 7] = (vlbe_real)(p1 + kk * L);
            }
            for (ix = 0; ix <= 4; ++ix) {
                const double xi = 0.25 * ix;
                vlbe_real kap, phi;
                double rel;
                assert_int_equal(vlbe_ale3_strain(0, q, (vlbe_real)(p1 + xi * L), NULL, &kap, &phi),
                                 VLBE_OK);
                rel = fabs((double)kap * R - 1.0);
                ASSERT_CLOSE_CTX(rel, 0.0, 0, th * th / 12.0 * 1.05 + rnd, "R %g theta %g xi %g", R,
                                 th, xi);
                /* linear theta: phi = 0.5 (two products and a sum) */
                ASSERT_CLOSE(phi, 0.5, 8 * EPS * (1.0 + 1.0 / L), 0);
                if (ix == 2) emid = rel;
                if (ix == 0) eend = rel;
            }
            ASSERT_CLOSE(emid, th * th / 24.0, 0, th * th / 24.0 * 0.05 + rnd);
            ASSERT_CLOSE(eend, th * th / 12.0, 0, th * th / 12.0 * 0.05 + rnd);
            wm = fmax(wm, emid / (th * th / 24.0));
            we = fmax(we, eend / (th * th / 12.0));
            if (it > 0) {
                assert_true(prev_mid / emid > 3.5 && prev_mid / emid < 4.5);
                assert_true(prev_end / eend > 3.5 && prev_end / eend < 4.5);
            }
            prev_mid = emid;
            prev_end = eend;
        }
    }
    tu_report("tilted arc: kap err at middle / (theta^2/24)", wm, 1.05);
    tu_report("tilted arc: kap err at ends / (theta^2/12)", we, 1.05);
    tu_measured("cv_end", we);

    /* straight: along a coordinate axis through the origin the other two
       components are exactly zero, so r' x r'' and kappa are exactly 0; in
       a general direction kappa is rounding, |r''| ~ EPS |r| / L^2 over
       |r'|^2: 32 EPS (1 + |r|/L) / L */
    for (a = 0; a < 4; ++a) {
        const double L = 1.3, p1 = -0.4, sc = 1.1;
        double t[3] = {0.0, 0.0, 0.0}, x0[3] = {0.0, 0.0, 0.0}, rmax = 0.0;
        vlbe_real q[NQ];
        int kk;
        if (a < 3) {
            t[a] = 1.0;
            x0[a] = -0.7;
        } else {
            rand_dir(&g, t);
            rand_vec(&g, x0);
            for (c = 0; c < 3; ++c) x0[c] *= 3.0;
        }
        for (kk = 0; kk < 2; ++kk) {
            for (c = 0; c < 3; ++c) {
                q[8 * kk + c] = (vlbe_real)(x0[c] + kk * sc * L * t[c]);
                q[8 * kk + 3 + c] = (vlbe_real)(sc * t[c]);
                rmax = fmax(rmax, fabs((double)q[8 * kk + c]));
            }
            q[8 * kk + 6] = VLBE_R(0.0);
            q[8 * kk + 7] = (vlbe_real)(p1 + kk * L);
        }
        for (ix = 0; ix < ARRAY_LEN(xis); ++ix) {
            vlbe_real eps, kap;
            assert_int_equal(
                vlbe_ale3_strain(0, q, (vlbe_real)(p1 + xis[ix] * L), &eps, &kap, NULL), VLBE_OK);
            if (a < 3) ASSERT_CLOSE_CTX(kap, 0.0, 0, 0, "axis %d xi %g", a, xis[ix]);
            ws = fmax(ws, fabs((double)kap) / (EPS * (1.0 + rmax / L) / L));
            ASSERT_CLOSE_CTX(kap, 0.0, 0, 32.0 * EPS * (1.0 + rmax / L) / L, "dir %d xi %g", a,
                             xis[ix]);
            ASSERT_CLOSE(eps, 0.5 * (sc * sc - 1.0), 0, 32.0 * EPS * (1.0 + rmax / L));
        }
    }
    tu_report("straight: kappa, in EPS (1 + |r|/L) / L", ws, 32.0);
    tu_measured("cv_straight", ws);

    /* K and D at kappa = 0 (axis-aligned, kappa exactly 0, unstretched)
       and at a straight stretched state in a general direction: finite and
       equal to the differences, all 64 modes, random rates (a moving,
       spinning, twisting straight shaft) */
    for (a = 0; a < 2; ++a) {
        const double L = 1.25, p1 = 0.3, sc = a == 0 ? 1.0 : 1.1;
        double t[3] = {0.0, 0.0, 1.0}, x0[3] = {0.0, 0.0, 0.5};
        st3 x, xd;
        int kk;
        memset(&xd, 0, sizeof xd); /* filled below; cleared for cppcheck (uninitvar) */
        if (a == 1) {
            rand_dir(&g, t);
            rand_vec(&g, x0);
        }
        for (kk = 0; kk < 2; ++kk) {
            for (c = 0; c < 3; ++c) {
                x.n[kk].r[c] = x0[c] + kk * sc * L * t[c];
                x.n[kk].rp[c] = sc * t[c];
            }
            x.n[kk].th = 0.2 + 0.6 * kk;
            x.n[kk].p = p1 + kk * L;
            rand_vec(&g, xd.n[kk].r);
            rand_vec(&g, xd.n[kk].rp);
            xd.n[kk].th = tu_rng_uniform(&g);
            xd.n[kk].p = 0.5 * tu_rng_uniform(&g);
        }
        for (k = 0; k < N_MODES; ++k) {
            vlbe_real Q[NQ], K[NN], D[NN];
            ale3_fd cx;
            ctx_init(&cx, &el, mode_of(k));
            pack(cx.fd.mode, &x, cx.fd.q);
            pack(cx.fd.mode, &xd, cx.fd.qd);
            if (a == 0 && !(cx.fd.mode & VLBE_ALE_NO_BEND)) {
                vlbe_real kap;
                assert_int_equal(
                    vlbe_ale3_strain(cx.fd.mode, cx.fd.q, VLBE_R(0.77), NULL, &kap, NULL), VLBE_OK);
                ASSERT_CLOSE(kap, 0.0, 0, 0);
            }
            assert_int_equal(vlbe_ale3_force(&el, cx.fd.mode, cx.fd.q, cx.fd.qd, Q, K, D), VLBE_OK);
            assert_int_equal(vlbe_all_finite(K, cx.fd.n * cx.fd.n), 1);
            assert_int_equal(vlbe_all_finite(D, cx.fd.n * cx.fd.n), 1);
            wk = fmax(wk, check_jac(&cx, FD_Q_OF_Q, K, NULL, tol, "K straight"));
            wd = fmax(wd, check_jac(&cx, FD_Q_OF_QD, D, NULL, tol, "D straight"));
        }
    }
    tu_report("straight: K = dQ/dq, err / entry scale", wk, tol);
    tu_report("straight: D = dQ/dq', err / entry scale", wd, tol);
    tu_measured("cv_KD_fd", fmax(wk, wd) / FD_ERR);
}

/* ======================================================================= */
/* 11. bad inputs to the eval functions                                      */
/* ======================================================================= */

typedef struct outs {
    vlbe_real Q[NQ], K[NN], D[NN], M[NN], E[3], r[3], rp[3], th, eps, kap, phi;
} outs;

static void outs_fill(outs *o)
{
    fill(NQ, SENTINEL, o->Q);
    fill(NN, SENTINEL, o->K);
    fill(NN, SENTINEL, o->D);
    fill(NN, SENTINEL, o->M);
    fill(3, SENTINEL, o->E);
    fill(3, SENTINEL, o->r);
    fill(3, SENTINEL, o->rp);
    o->th = o->eps = o->kap = o->phi = SENTINEL;
}

static void outs_check(const outs *o)
{
    assert_all_equal(NQ, o->Q, SENTINEL);
    assert_all_equal(NN, o->K, SENTINEL);
    assert_all_equal(NN, o->D, SENTINEL);
    assert_all_equal(NN, o->M, SENTINEL);
    assert_all_equal(3, o->E, SENTINEL);
    assert_all_equal(3, o->r, SENTINEL);
    assert_all_equal(3, o->rp, SENTINEL);
    assert_true(o->th == SENTINEL && o->eps == SENTINEL && o->kap == SENTINEL &&
                o->phi == SENTINEL);
}

/* Every eval function on (q, qd) must fail with want (force with and
   without K, D, energy, mass_jac with a = qd; unless qd_only: mass, point,
   strain, point force and point torque at the middle -- the torque checks
   the state before the layout, so it fails with want without spin too);
   nothing written. */
static void expect_fail_all(const vlbe_ale3_elem *el, unsigned mode, const vlbe_real *q,
                            const vlbe_real *qd, int qd_only, vlbe_status want)
{
    const vlbe_real F[3] = {VLBE_R(1.0), VLBE_R(-2.0), VLBE_R(0.5)};
    const vlbe_real pm = VLBE_R(0.5) * (q[idx_p(mode, 0)] + q[idx_p(mode, 1)]);
    const vlbe_real pmid = pm == pm ? pm : VLBE_R(0.0);
    outs o;
    outs_fill(&o);
    assert_int_equal(vlbe_ale3_force(el, mode, q, qd, o.Q, o.K, o.D), want);
    assert_int_equal(vlbe_ale3_force(el, mode, q, qd, o.Q, NULL, NULL), want);
    assert_int_equal(vlbe_ale3_energy(el, mode, q, qd, o.E), want);
    assert_int_equal(vlbe_ale3_mass_jac(el, mode, q, qd, o.M), want);
    if (!qd_only) {
        assert_int_equal(vlbe_ale3_mass(el, mode, q, o.M), want);
        assert_int_equal(vlbe_ale3_point(mode, q, pmid, o.r, o.rp, &o.th), want);
        assert_int_equal(vlbe_ale3_strain(mode, q, pmid, &o.eps, &o.kap, &o.phi), want);
        assert_int_equal(vlbe_ale3_point_force(mode, q, pmid, F, o.Q, o.K), want);
        assert_int_equal(vlbe_ale3_point_torque(mode, q, pmid, VLBE_R(0.7), o.Q, o.K), want);
    }
    outs_check(&o);
}

static void test_errors_eval(void **state)
{
    const vlbe_ale3_mat m = mat3_std();
    const vlbe_real bad[3] = {(vlbe_real)NAN, (vlbe_real)INFINITY, -(vlbe_real)INFINITY};
    const vlbe_real F[3] = {VLBE_R(1.0), VLBE_R(-2.0), VLBE_R(0.5)};
    const unsigned layouts[2] = {0u, VLBE_ALE3_NO_SPIN};
    vlbe_ale3_elem el;
    tu_rng g = tu_rng_seed(321);
    st3 x, xd;
    outs o;
    int i, b, k, l;
    (void)state;
    elem_make(&el, &m, 0, 0, 0);
    make_state(&g, 0.5, 0.15, 0.8, &x, &xd);
    /* the planar element's CONSERVATIVE and INV_AXIAL do not exist here:
       VLBE_EARG from every evaluation, nothing written */
    {
        const unsigned planar_only[2] = {VLBE_ALE_CONSERVATIVE, VLBE_ALE_INV_AXIAL};
        vlbe_real qq[NQ], qqd[NQ];
        pack(0, &x, qq);
        pack(0, &xd, qqd);
        for (k = 0; k < 2; ++k) {
            outs_fill(&o);
            assert_int_equal(vlbe_ale3_force(&el, planar_only[k], qq, qqd, o.Q, o.K, o.D),
                             VLBE_EARG);
            assert_int_equal(vlbe_ale3_mass(&el, planar_only[k], qq, o.M), VLBE_EARG);
            assert_int_equal(vlbe_ale3_energy(&el, planar_only[k], qq, qqd, o.E), VLBE_EARG);
            outs_check(&o);
        }
    }
    for (l = 0; l < 2; ++l) {
        const unsigned lay = layouts[l];
        const int n = nq_of(lay), p1 = idx_p(lay, 0), p2 = idx_p(lay, 1);
        vlbe_real q[NQ], qd[NQ], qb[NQ], qdb[NQ];
        pack(lay, &x, q);
        pack(lay, &xd, qd);
        /* length: p2 = p1 and p2 < p1, every mode (fixed p's still define L) */
        for (k = 0; k < 32; ++k) {
            const unsigned mode = mode_lay(k, lay);
            memcpy(qb, q, sizeof qb);
            qb[p2] = qb[p1];
            expect_fail_all(&el, mode, qb, qd, 0, VLBE_ELENGTH);
            qb[p2] = qb[p1] - VLBE_R(0.5);
            expect_fail_all(&el, mode, qb, qd, 0, VLBE_ELENGTH);
        }
        /* non-finite q (every entry, NaN and both infinities) and qd */
        for (i = 0; i < n; ++i)
            for (b = 0; b < 3; ++b) {
                memcpy(qb, q, sizeof qb);
                qb[i] = bad[b];
                expect_fail_all(&el, lay, qb, qd, 0, VLBE_ENONFINITE);
                expect_fail_all(&el, lay | VLBE_ALE_FIX_P1 | VLBE_ALE_FIX_P2, qb, qd, 0,
                                VLBE_ENONFINITE);
                memcpy(qdb, qd, sizeof qdb);
                qdb[i] = bad[b];
                expect_fail_all(&el, lay, q, qdb, 1, VLBE_ENONFINITE);
                /* even where the mode ignores the entry (fixed p's rate) */
                expect_fail_all(&el, lay | VLBE_ALE_FIX_P1 | VLBE_ALE_FIX_P2, q, qdb, 1,
                                VLBE_ENONFINITE);
            }
        /* non-finite point arguments: p, F, T */
        for (b = 0; b < 3; ++b) {
            const vlbe_real Fb[3] = {VLBE_R(0.0), bad[b], VLBE_R(0.0)};
            outs_fill(&o);
            assert_int_equal(vlbe_ale3_point(lay, q, bad[b], o.r, o.rp, &o.th), VLBE_ENONFINITE);
            assert_int_equal(vlbe_ale3_strain(lay, q, bad[b], &o.eps, &o.kap, &o.phi),
                             VLBE_ENONFINITE);
            assert_int_equal(vlbe_ale3_point_force(lay, q, bad[b], F, o.Q, o.K), VLBE_ENONFINITE);
            assert_int_equal(vlbe_ale3_point_force(lay, q, q[p1], Fb, o.Q, o.K), VLBE_ENONFINITE);
            assert_int_equal(vlbe_ale3_point_torque(lay, q, bad[b], VLBE_R(0.7), o.Q, o.K),
                             VLBE_ENONFINITE);
            assert_int_equal(vlbe_ale3_point_torque(lay, q, q[p1], bad[b], o.Q, o.K),
                             VLBE_ENONFINITE);
            outs_check(&o);
        }
        /* outside [p1, p2] (just outside too) */
        {
            const vlbe_real outside[4] = {q[p1] - VLBE_R(0.3), q[p2] + VLBE_R(0.3),
                                          q[p1] - VLBE_R(4.0) * VLBE_EPS * q[p1],
                                          q[p2] + VLBE_R(4.0) * VLBE_EPS * q[p2]};
            for (i = 0; i < 4; ++i) {
                outs_fill(&o);
                assert_true(outside[i] < q[p1] || outside[i] > q[p2]);
                assert_int_equal(vlbe_ale3_point_force(lay, q, outside[i], F, o.Q, o.K),
                                 VLBE_EBOUND);
                assert_int_equal(vlbe_ale3_point_force(lay, q, outside[i], F, o.Q, NULL),
                                 VLBE_EBOUND);
                /* without spin the torque is refused first (EARG) */
                assert_int_equal(vlbe_ale3_point_torque(lay, q, outside[i], VLBE_R(0.7), o.Q, o.K),
                                 l ? VLBE_EARG : VLBE_EBOUND);
                outs_check(&o);
            }
        }
        /* zero slope everywhere (r1 = r2, r1' = r2' = 0): the curvature is
           undefined at every bending point -> ESINGULAR from force (with and
           without Jacobians) and energy where bending is on; the string
           succeeds (finite, eps = -1/2); mass and its Jacobian need no slope */
        memcpy(qb, q, sizeof qb);
        for (i = 0; i < 3; ++i) {
            qb[node_len(lay) + i] = qb[i];
            qb[3 + i] = qb[node_len(lay) + 3 + i] = VLBE_R(0.0);
        }
        for (k = 0; k < 32; ++k) {
            const unsigned mode = mode_lay(k, lay);
            const vlbe_status want = (mode & VLBE_ALE_NO_BEND) ? VLBE_OK : VLBE_ESINGULAR;
            outs_fill(&o);
            assert_int_equal(vlbe_ale3_force(&el, mode, qb, qd, o.Q, o.K, o.D), want);
            if (want == VLBE_OK) {
                assert_int_equal(vlbe_all_finite(o.Q, n), 1);
                assert_int_equal(vlbe_all_finite(o.K, n * n), 1);
                assert_int_equal(vlbe_all_finite(o.D, n * n), 1);
                outs_fill(&o);
            }
            assert_int_equal(vlbe_ale3_force(&el, mode, qb, qd, o.Q, NULL, NULL), want);
            if (want == VLBE_OK) outs_fill(&o);
            assert_int_equal(vlbe_ale3_energy(&el, mode, qb, qd, o.E), want);
            if (want != VLBE_OK) outs_check(&o);
            assert_int_equal(vlbe_ale3_mass(&el, mode, qb, o.M), VLBE_OK);
            assert_int_equal(vlbe_ale3_mass_jac(&el, mode, qb, qd, o.K), VLBE_OK);
        }
        {
            vlbe_ale3_mat m0 = m;
            vlbe_ale3_elem el0;
            m0.EJ = VLBE_R(0.0);
            elem_make(&el0, &m0, 0, 0, 0);
            assert_int_equal(vlbe_ale3_force(&el0, lay, qb, qd, o.Q, o.K, o.D), VLBE_OK);
            assert_int_equal(vlbe_ale3_energy(&el0, lay, qb, qd, o.E), VLBE_OK);
        }
        /* strain: the curvature needs the slope, eps and phi do not */
        outs_fill(&o);
        assert_int_equal(vlbe_ale3_strain(lay, qb, qb[p1], &o.eps, &o.kap, &o.phi), VLBE_ESINGULAR);
        assert_int_equal(vlbe_ale3_strain(lay, qb, qb[p1], NULL, &o.kap, NULL), VLBE_ESINGULAR);
        outs_check(&o);
        assert_int_equal(vlbe_ale3_strain(lay, qb, qb[p1], &o.eps, NULL, &o.phi), VLBE_OK);
        ASSERT_CLOSE(o.eps, -0.5, 0, 0);
        /* zero slope at node 1 only: the Gauss points are interior, every
           mode succeeds; the curvature at p1 itself is singular */
        memcpy(qb, q, sizeof qb);
        qb[3] = qb[4] = qb[5] = VLBE_R(0.0);
        for (k = 0; k < 32; ++k)
            assert_int_equal(vlbe_ale3_force(&el, mode_lay(k, lay), qb, qd, o.Q, o.K, o.D),
                             VLBE_OK);
        outs_fill(&o);
        assert_int_equal(vlbe_ale3_strain(lay, qb, qb[p1], &o.eps, &o.kap, NULL), VLBE_ESINGULAR);
        outs_check(&o);
    }
}

/* ======================================================================= */
/* 12. bad inputs to the init functions                                      */
/* ======================================================================= */

static void test_errors_init(void **state)
{
    static const int bad_orders[] = {-1, VLBE_ALE_NGP_MAX + 1, 100};
    const vlbe_ale3_mat good = mat3_std();
    const vlbe_real nonfinite[3] = {(vlbe_real)NAN, (vlbe_real)INFINITY, -(vlbe_real)INFINITY};
    vlbe_ale3_elem el, ref;
    vlbe_ale3_mat m, mref;
    int i, b, f;
    (void)state;
    memset(&ref, 0x5a, sizeof ref);
#define EXPECT_INIT(mat_, flags_, nm_, ns_, want_)                                            \
    do {                                                                                      \
        memset(&el, 0x5a, sizeof el);                                                         \
        assert_int_equal(vlbe_ale3_elem_init(&el, &(mat_), (flags_), (nm_), (ns_)), (want_)); \
        assert_true(memcmp(&el, &ref, sizeof el) == 0);                                       \
    } while (0)
    /* rhoA > 0 */
    m = good;
    m.rhoA = VLBE_R(0.0);
    EXPECT_INIT(m, 0, 0, 0, VLBE_EARG);
    m.rhoA = -VLBE_R(0.0);
    EXPECT_INIT(m, 0, 0, 0, VLBE_EARG);
    m.rhoA = VLBE_R(-1.0);
    EXPECT_INIT(m, VLBE_ALE3_NO_SPIN, 0, 0, VLBE_EARG);
    /* rhoI, stiffnesses, damping >= 0 (with and without spin) */
    for (f = 0; f < 7; ++f) {
        vlbe_real *field[7];
        m = good;
        field[0] = &m.rhoI;
        field[1] = &m.EA;
        field[2] = &m.EJ;
        field[3] = &m.GI;
        field[4] = &m.c_eps;
        field[5] = &m.c_kap;
        field[6] = &m.c_phi;
        *field[f] = VLBE_R(-0.5);
        EXPECT_INIT(m, 0, 0, 0, VLBE_EARG);
        EXPECT_INIT(m, VLBE_ALE3_NO_SPIN, 0, 0, VLBE_EARG);
    }
    /* a spin angle needs inertia: rhoI = 0 only without spin */
    m = good;
    m.rhoI = VLBE_R(0.0);
    EXPECT_INIT(m, 0, 0, 0, VLBE_EARG);
    EXPECT_INIT(m, VLBE_ALE_NO_BEND | VLBE_ALE3_NO_TWIST, 0, 0, VLBE_EARG);
    assert_int_equal(vlbe_ale3_elem_init(&el, &m, VLBE_ALE3_NO_SPIN, 0, 0), VLBE_OK);
    /* non-finite in every field */
    for (f = 0; f < 11; ++f)
        for (b = 0; b < 3; ++b) {
            vlbe_real *field[11];
            m = good;
            field[0] = &m.rhoA;
            field[1] = &m.rhoI;
            field[2] = &m.EA;
            field[3] = &m.EJ;
            field[4] = &m.GI;
            field[5] = &m.c_eps;
            field[6] = &m.c_kap;
            field[7] = &m.c_phi;
            field[8] = &m.f[0];
            field[9] = &m.f[1];
            field[10] = &m.f[2];
            *field[f] = nonfinite[b];
            EXPECT_INIT(m, 0, 0, 0, VLBE_ENONFINITE);
            EXPECT_INIT(m, VLBE_ALE3_NO_SPIN, 0, 0, VLBE_ENONFINITE);
        }
    /* Gauss orders out of [0, 8], each rule */
    for (i = 0; i < ARRAY_LEN(bad_orders); ++i) {
        EXPECT_INIT(good, 0, bad_orders[i], 0, VLBE_EARG);
        EXPECT_INIT(good, 0, 0, bad_orders[i], VLBE_EARG);
    }
#undef EXPECT_INIT
    /* accepted: the limits, zero stiffnesses and damping; 0 = the defaults */
    m = good;
    m.EA = m.EJ = m.GI = m.c_eps = m.c_kap = m.c_phi = VLBE_R(0.0);
    assert_int_equal(vlbe_ale3_elem_init(&el, &m, 0, 1, VLBE_ALE_NGP_MAX), VLBE_OK);
    assert_int_equal(el.rm.n, 1);
    assert_int_equal(el.rs.n, VLBE_ALE_NGP_MAX);
    assert_int_equal(vlbe_ale3_elem_init(&el, &good, VLBE_ALE_NO_BEND, 0, 0), VLBE_OK);
    assert_int_equal(el.rm.n, 4);
    assert_int_equal(el.rs.n, 5);
    assert_true(el.flags == VLBE_ALE_NO_BEND);
    assert_int_equal(vlbe_ale3_nq(0), 16);
    assert_int_equal(vlbe_ale3_nq(VLBE_ALE3_NO_SPIN | VLBE_ALE_FIX_P1), 14);

    /* vlbe_ale3_mat_circle: bad input refused, the material not written */
    {
        const vlbe_real okv[4] = {VLBE_R(7700.0), VLBE_R(206e9), VLBE_R(79e9), VLBE_R(0.01)};
        const double pi = PI, r = (double)okv[3], A = pi * r * r, J = A * r * r / 4.0;
        vlbe_real v[4];
        memset(&mref, 0x5a, sizeof mref);
#define EXPECT_CIRCLE(want_)                                                         \
    do {                                                                             \
        memset(&m, 0x5a, sizeof m);                                                  \
        assert_int_equal(vlbe_ale3_mat_circle(&m, v[0], v[1], v[2], v[3]), (want_)); \
        assert_true(memcmp(&m, &mref, sizeof m) == 0);                               \
    } while (0)
        for (f = 0; f < 4; ++f) {
            for (b = 0; b < 3; ++b) {
                memcpy(v, okv, sizeof v);
                v[f] = nonfinite[b];
                EXPECT_CIRCLE(VLBE_ENONFINITE);
            }
            /* rho, radius > 0; E, G >= 0 */
            memcpy(v, okv, sizeof v);
            v[f] = VLBE_R(-1.0);
            EXPECT_CIRCLE(VLBE_EARG);
            v[f] = VLBE_R(0.0);
            if (f == 0 || f == 3) EXPECT_CIRCLE(VLBE_EARG);
        }
#undef EXPECT_CIRCLE
        memcpy(v, okv, sizeof v);
        memset(&m, 0x5a, sizeof m);
        assert_int_equal(vlbe_ale3_mat_circle(&m, v[0], v[1], v[2], v[3]), VLBE_OK);
        /* a few roundings of products: 8 EPS */
        ASSERT_CLOSE(m.rhoA, 7700.0 * A, 8 * EPS, 0);
        ASSERT_CLOSE(m.rhoI, 7700.0 * 2.0 * J, 8 * EPS, 0);
        ASSERT_CLOSE(m.EA, 206e9 * A, 8 * EPS, 0);
        ASSERT_CLOSE(m.EJ, 206e9 * J, 8 * EPS, 0);
        ASSERT_CLOSE(m.GI, 79e9 * 2.0 * J, 8 * EPS, 0);
        assert_true(m.c_eps == VLBE_R(0.0) && m.c_kap == VLBE_R(0.0) && m.c_phi == VLBE_R(0.0));
        assert_true(m.f[0] == VLBE_R(0.0) && m.f[1] == VLBE_R(0.0) && m.f[2] == VLBE_R(0.0));
        assert_int_equal(vlbe_ale3_elem_init(&el, &m, 0, 0, 0), VLBE_OK);
        /* E = G = 0 is accepted (a rigid-body-free, stiffness-free section) */
        v[1] = v[2] = VLBE_R(0.0);
        assert_int_equal(vlbe_ale3_mat_circle(&m, v[0], v[1], v[2], v[3]), VLBE_OK);
    }
}

/* ======================================================================= */
/* 13. reduced models                                                        */
/* ======================================================================= */

/* spin index i (not theta) -> its index without spin */
static int nospin_of(int i) { return i < 6 ? i : (i == 7 ? 6 : (i < 14 ? i - 1 : 13)); }

static void test_reduced_equals_full(void **state)
{
    const vlbe_ale3_mat m = mat3_std();
    vlbe_ale3_mat m0;
    vlbe_ale3_elem el, elz;
    tu_rng g = tu_rng_seed(322);
    double wst = 0.0;
    int s, k, i, j, v;
    (void)state;
    elem_make(&el, &m, 0, 0, 0);
    for (s = 0; s < 3; ++s) {
        st3 x, xd, xa;
        const double th0 = 1.7 * tu_rng_uniform(&g), Om = 2.0 * tu_rng_uniform(&g);
        make_state(&g, 0.5, 0.15, 0.8, &x, &xd);
        make_state(&g, 0.5, 0.15, 0.8, &xa, NULL);
        for (i = 0; i < 2; ++i) {
            x.n[i].th = th0;
            xd.n[i].th = Om;
            xa.n[i].th = -0.6; /* uniform acceleration of the spin: a for Mq */
            xa.n[i].p = 0.7 * tu_rng_uniform(&g);
        }
        /* NO_SPIN = the position rows and columns of the spin model at
           uniform theta and spin rate (no twist, no twist rate) */
        for (k = 0; k < 32; ++k) {
            const unsigned mode = mode_lay(k, 0u), mns = mode | VLBE_ALE3_NO_SPIN;
            vlbe_real q[NQ], qd[NQ], a[NQ], Q[NQ], K[NN], D[NN], M[NN], Mq[NN], E[3];
            vlbe_real qn[NQ], qdn[NQ], an[NQ], Qn[NQ], Kn[NN], Dn[NN], Mn[NN], Mqn[NN], En[3];
            double L;
            pack(mode, &x, q);
            pack(mode, &xd, qd);
            pack(mode, &xa, a);
            pack(mns, &x, qn);
            pack(mns, &xd, qdn);
            pack(mns, &xa, an);
            assert_int_equal(vlbe_ale3_force(&el, mode, q, qd, Q, K, D), VLBE_OK);
            assert_int_equal(vlbe_ale3_force(&el, mns, qn, qdn, Qn, Kn, Dn), VLBE_OK);
            assert_int_equal(vlbe_ale3_mass(&el, mode, q, M), VLBE_OK);
            assert_int_equal(vlbe_ale3_mass(&el, mns, qn, Mn), VLBE_OK);
            assert_int_equal(vlbe_ale3_mass_jac(&el, mode, q, a, Mq), VLBE_OK);
            assert_int_equal(vlbe_ale3_mass_jac(&el, mns, qn, an, Mqn), VLBE_OK);
            assert_int_equal(vlbe_ale3_energy(&el, mode, q, qd, E), VLBE_OK);
            assert_int_equal(vlbe_ale3_energy(&el, mns, qn, qdn, En), VLBE_OK);
            for (i = 0; i < 16; ++i) {
                const int a1 = nospin_of(i);
                if (is_th(mode, i)) continue;
                ASSERT_CLOSE_CTX(Q[i], Qn[a1], 0, 0, "Q[%d], mode %u", i, mode);
                for (j = 0; j < 16; ++j) {
                    const int b1 = nospin_of(j);
                    if (is_th(mode, j)) continue;
                    ASSERT_CLOSE_CTX(K[i * 16 + j], Kn[a1 * 14 + b1], 0, 0, "K (%d, %d), mode %u",
                                     i, j, mode);
                    ASSERT_CLOSE_CTX(D[i * 16 + j], Dn[a1 * 14 + b1], 0, 0, "D (%d, %d), mode %u",
                                     i, j, mode);
                    ASSERT_CLOSE_CTX(M[i * 16 + j], Mn[a1 * 14 + b1], 0, 0, "M (%d, %d), mode %u",
                                     i, j, mode);
                    ASSERT_CLOSE_CTX(Mq[i * 16 + j], Mqn[a1 * 14 + b1], 0, 0,
                                     "Mq (%d, %d), mode %u", i, j, mode);
                }
            }
            /* U, V equal; T more by the spin's rhoI Omega^2 L / 2 */
            L = (double)q[15] - (double)q[7];
            ASSERT_CLOSE(E[1], En[1], 0, 0);
            ASSERT_CLOSE(E[2], En[2], 0, 0);
            wst =
                fmax(wst, fabs((double)E[0] - (double)En[0] - 0.5 * (double)m.rhoI * Om * Om * L) /
                              (EPS * (double)E[0]));
            ASSERT_CLOSE((double)E[0] - (double)En[0], 0.5 * (double)m.rhoI * Om * Om * L, 0,
                         16 * EPS * (double)E[0]);
        }
        /* NO_TWIST = GI 0, NO_DAMP = every c 0, NO_BEND = EJ 0: the same
           code runs (the switches test the coefficient too; a zero
           Kelvin-Voigt coefficient adds exact zeros): bit for bit */
        for (v = 0; v < 3; ++v) {
            const unsigned bit = v == 0   ? VLBE_ALE3_NO_TWIST
                                 : v == 1 ? VLBE_ALE_NO_DAMP
                                          : VLBE_ALE_NO_BEND;
            m0 = m;
            if (v == 0) m0.GI = VLBE_R(0.0);
            if (v == 1) m0.c_eps = m0.c_kap = m0.c_phi = VLBE_R(0.0);
            if (v == 2) m0.EJ = VLBE_R(0.0);
            elem_make(&elz, &m0, 0, 0, 0);
            for (k = 0; k < N_MODES; ++k) {
                const unsigned mode = mode_of(k);
                const int n = nq_of(mode);
                vlbe_real q[NQ], qd[NQ], Q[NQ], K[NN], D[NN], E[3];
                vlbe_real Qz[NQ], Kz[NN], Dz[NN], Ez[3];
                if (mode & bit) continue;
                pack(mode, &x, q);
                pack(mode, &xd, qd);
                assert_int_equal(vlbe_ale3_force(&el, mode | bit, q, qd, Q, K, D), VLBE_OK);
                assert_int_equal(vlbe_ale3_force(&elz, mode, q, qd, Qz, Kz, Dz), VLBE_OK);
                ASSERT_VEC_CLOSE(Qz, Q, n, 0, 0);
                ASSERT_VEC_CLOSE(Kz, K, n * n, 0, 0);
                ASSERT_VEC_CLOSE(Dz, D, n * n, 0, 0);
                assert_int_equal(vlbe_ale3_energy(&el, mode | bit, q, qd, E), VLBE_OK);
                assert_int_equal(vlbe_ale3_energy(&elz, mode, q, qd, Ez), VLBE_OK);
                ASSERT_VEC_CLOSE(Ez, E, 3, 0, 0);
                /* and the bit as an element flag = the bit as a mode */
                {
                    vlbe_ale3_elem ef;
                    elem_make(&ef, &m, bit, 0, 0);
                    assert_int_equal(vlbe_ale3_force(&ef, mode, q, qd, Qz, Kz, Dz), VLBE_OK);
                    ASSERT_VEC_CLOSE(Qz, Q, n, 0, 0);
                    ASSERT_VEC_CLOSE(Kz, K, n * n, 0, 0);
                    ASSERT_VEC_CLOSE(Dz, D, n * n, 0, 0);
                }
            }
        }
    }
    tu_report("T spin - T no spin - rhoI Om^2 L/2, in EPS T", wst, 16.0);
    tu_measured("rf_T", wst);
}

/* ======================================================================= */
/* 14. quadrature exactness                                                  */
/* ======================================================================= */

static void test_quadrature(void **state)
{
    static const int nms[] = {4, 5, 8};
    const vlbe_ale3_mat m = mat3_std();
    const double tol = 64.0 * EPS;
    vlbe_ale3_elem el[3], e8;
    tu_rng g = tu_rng_seed(323);
    double wm = 0.0, wf = 0.0;
    int s, k, r, i;
    (void)state;
    for (r = 0; r < 3; ++r) elem_make(&el[r], &m, 0, nms[r], 5);
    elem_make(&e8, &m, 0, 8, 8);
    for (s = 0; s < 3; ++s) {
        st3 x, xd, xa;
        make_state(&g, 0.5, 0.15, 0.8, &x, &xd);
        make_state(&g, 0.5, 0.15, 0.8, &xa, NULL);
        for (k = 0; k < N_MODES; ++k) {
            const unsigned mode = mode_of(k);
            const int n = nq_of(mode);
            vlbe_real q[NQ], qd[NQ], a[NQ], M8[NN], M[NN], Q8[NQ], K8[NN], D8[NN], Q[NQ], K[NN],
                D[NN];
            double sc;
            if (mode & VLBE_ALE_NO_BEND) continue; /* set below */
            pack(mode, &x, q);
            pack(mode, &xd, qd);
            pack(mode, &xa, a);
            for (r = 0; r < 2; ++r) {
                assert_int_equal(vlbe_ale3_mass(&el[2], mode, q, M8), VLBE_OK);
                assert_int_equal(vlbe_ale3_mass(&el[r], mode, q, M), VLBE_OK);
                sc = max_abs(n * n, M8);
                for (i = 0; i < n * n; ++i) wm = fmax(wm, fabs((double)M[i] - (double)M8[i]) / sc);
                ASSERT_VEC_CLOSE(M, M8, n * n, 0, tol * sc);
                assert_int_equal(vlbe_ale3_mass_jac(&el[r], mode, q, a, M), VLBE_OK);
                assert_int_equal(vlbe_ale3_mass_jac(&el[2], mode, q, a, M8), VLBE_OK);
                sc = max_abs(n * n, M8);
                for (i = 0; sc > 0.0 && i < n * n; ++i)
                    wm = fmax(wm, fabs((double)M[i] - (double)M8[i]) / sc);
                ASSERT_VEC_CLOSE(M, M8, n * n, 0, tol * (sc > 0.0 ? sc : 1.0));
            }
            /* the string: axial (degree 8 with its p-rows), twist (degree 0),
               transport inertia and load (degree 6): polynomial */
            assert_int_equal(vlbe_ale3_force(&el[0], mode | VLBE_ALE_NO_BEND, q, qd, Q, K, D),
                             VLBE_OK);
            assert_int_equal(vlbe_ale3_force(&e8, mode | VLBE_ALE_NO_BEND, q, qd, Q8, K8, D8),
                             VLBE_OK);
            sc = max_abs(n, Q8);
            for (i = 0; i < n; ++i) wf = fmax(wf, fabs((double)Q[i] - (double)Q8[i]) / sc);
            ASSERT_VEC_CLOSE(Q, Q8, n, 0, tol * sc);
            sc = max_abs(n * n, K8);
            for (i = 0; i < n * n; ++i) wf = fmax(wf, fabs((double)K[i] - (double)K8[i]) / sc);
            ASSERT_VEC_CLOSE(K, K8, n * n, 0, tol * sc);
            sc = max_abs(n * n, D8);
            for (i = 0; sc > 0.0 && i < n * n; ++i)
                wf = fmax(wf, fabs((double)D[i] - (double)D8[i]) / sc);
            ASSERT_VEC_CLOSE(D, D8, n * n, 0, tol * (sc > 0.0 ? sc : 1.0));
        }
    }
    tu_report("mass, mass_jac nm = 4, 5 vs 8, in EPS of max", wm / EPS, 64.0);
    tu_report("string force (4, 5) vs (8, 8), in EPS of max", wf / EPS, 64.0);
    tu_measured("qd_eps", fmax(wm, wf) / EPS);
}

/* ======================================================================= */
/* 15. transport inertia against Lagrange's equations                       */
/* ======================================================================= */

static void test_transport_inertia_lagrange(void **state)
{
    vlbe_ale3_mat m = mat3_std();
    const double tol = 16.0 * FD_ERR;
    vlbe_ale3_elem el;
    tu_rng g = tu_rng_seed(324);
    double w = 0.0;
    int s, k, i, j, c;
    (void)state;
    m.EA = m.EJ = m.GI = VLBE_R(0.0);
    m.f[0] = m.f[1] = m.f[2] = VLBE_R(0.0);
    elem_make(&el, &m, 0, 0, 0);
    for (s = 0; s < 3; ++s) {
        st3 x, xd;
        make_state(&g, 0.5, 0.15, 0.8, &x, &xd);
        for (k = 0; k < N_MODES; ++k) {
            const unsigned mode = mode_of(k);
            const int n = nq_of(mode), o = node_len(mode);
            const double rho = (double)m.rhoA, rhoI = (double)m.rhoI;
            vlbe_real q[NQ], qd[NQ], Q[NQ], Mq[NN];
            double dT[NQ], mdot[NQ], B[NQ] = {0.0}, pd[2], scale;
            int kk;
            /* only the mass and the transport inertia act: NO_SPIN, FIX_P1/2 */
            if (mode & (VLBE_ALE_NO_BEND | VLBE_ALE_NO_DAMP | VLBE_ALE3_NO_TWIST)) continue;
            pack(mode, &x, q);
            pack(mode, &xd, qd);
            for (kk = 0; kk < 2; ++kk)
                pd[kk] = is_fixed(mode, idx_p(mode, kk)) ? 0.0 : (double)qd[idx_p(mode, kk)];
            assert_int_equal(vlbe_ale3_force(&el, mode, q, qd, Q, NULL, NULL), VLBE_OK);
            assert_int_equal(vlbe_ale3_mass_jac(&el, mode, q, qd, Mq), VLBE_OK);
            energy_grad(&el, mode, q, qd, 1, dT);
            for (i = 0; i < n; ++i) {
                mdot[i] = 0.0;
                for (j = 0; j < n; ++j) mdot[i] += (double)Mq[i * n + j] * (double)qd[j];
            }
            for (kk = 0; kk < 2; ++kk) {
                const double sg = kk == 0 ? -1.0 : 1.0; /* [.]_{p1}^{p2} */
                const int pk = idx_p(mode, kk);
                double v[3], tv = 0.0;
                for (c = 0; c < 3; ++c) {
                    v[c] = (double)qd[kk * o + c] - (double)q[kk * o + 3 + c] * pd[kk];
                    B[kk * o + c] += sg * rho * pd[kk] * v[c];
                    tv += (double)q[kk * o + 3 + c] * v[c];
                }
                B[pk] += sg * rho * pd[kk] * -tv - sg * 0.5 * rho * dot3(v, v);
                if (!(mode & VLBE_ALE3_NO_SPIN)) {
                    const double L = (double)q[idx_p(mode, 1)] - (double)q[idx_p(mode, 0)];
                    const double ph = ((double)q[14] - (double)q[6]) / L;
                    const double om = (double)qd[idx_th(mode, kk)] - ph * pd[kk];
                    B[idx_th(mode, kk)] += sg * rhoI * pd[kk] * om;
                    B[pk] += sg * rhoI * pd[kk] * -ph * om - sg * 0.5 * rhoI * om * om;
                }
            }
            scale = fmax(fmax(max_abs(n, Q), tu_max_abs(n, mdot)), tu_max_abs(n, dT));
            for (i = 0; i < n; ++i) {
                double res;
                if (is_fixed(mode, i)) continue;
                res = mdot[i] - dT[i] + (double)Q[i] - B[i];
                w = fmax(w, fabs(res) / scale);
                ASSERT_CLOSE_CTX(res, 0.0, 0, tol * scale, "row %d, mode %u", i, mode);
            }
        }
    }
    tu_report("Mdot qd - dT/dq - Q_p - B (with spin)", w, tol);
    tu_measured("lg_fd", w / FD_ERR);
}

/* ======================================================================= */
/* 16. Kelvin-Voigt dissipation                                              */
/* ======================================================================= */

/* qd . (Q(q, qd) - Q(q, 0)) = -sum_g w_g L (c_eps EA eps'^2 + c_kap EJ |k'|^2
   + c_phi GI phi'^2) over the strain points (both p fixed: no transport
   inertia; the elastic force and the load cancel in the difference), the
   rates by central differences in time of vlbe_ale3_strain along q +- h qd
   (|k'| only at k = 0, where |k(q +- h qd)| = h |k'| + O(h^2) with
   opposite second-order terms).  Returns the residual; *scale = its FD
   error unit, sum_i |qd_i| (|Q_i - Q0_i| + |Q0_i|) + |reference|. */
static double dissipation_residual(const vlbe_ale3_elem *el, unsigned mode, const vlbe_real *q,
                                   const vlbe_real *qd, double *scale, double *power)
{
    const vlbe_ale3_mat *m = &el->mat;
    const int n = nq_of(mode), bend = !(mode & VLBE_ALE_NO_BEND);
    const int tw = !(mode & (VLBE_ALE3_NO_SPIN | VLBE_ALE3_NO_TWIST));
    const double p1 = (double)q[idx_p(mode, 0)], L = (double)q[idx_p(mode, 1)] - p1;
    vlbe_real z[NQ], Q[NQ], Q0[NQ], qp[NQ], qm[NQ];
    double pw = 0.0, ref = 0.0, sc = 0.0;
    int i, gi;
    fill(NQ, VLBE_R(0.0), z);
    assert_int_equal(vlbe_ale3_force(el, mode, q, qd, Q, NULL, NULL), VLBE_OK);
    assert_int_equal(vlbe_ale3_force(el, mode, q, z, Q0, NULL, NULL), VLBE_OK);
    for (i = 0; i < n; ++i) {
        pw += (double)qd[i] * ((double)Q[i] - (double)Q0[i]);
        sc += fabs((double)qd[i]) * (fabs((double)Q[i] - (double)Q0[i]) + fabs((double)Q0[i]));
    }
    memcpy(qp, q, sizeof qp);
    memcpy(qm, q, sizeof qm);
    for (i = 0; i < n; ++i)
        if (!is_p(mode, i)) {
            qp[i] = (vlbe_real)((double)q[i] + FD_STEP * (double)qd[i]);
            qm[i] = (vlbe_real)((double)q[i] - FD_STEP * (double)qd[i]);
        }
    for (gi = 0; gi < el->rs.n; ++gi) {
        const vlbe_real p = (vlbe_real)(p1 + (double)el->rs.g[gi].xi * L);
        vlbe_real ep, em, kp = VLBE_R(0.0), km = VLBE_R(0.0), fp, fm;
        double ed, kd, fd;
        assert_int_equal(vlbe_ale3_strain(mode, qp, p, &ep, bend ? &kp : NULL, &fp), VLBE_OK);
        assert_int_equal(vlbe_ale3_strain(mode, qm, p, &em, bend ? &km : NULL, &fm), VLBE_OK);
        /* the steps really taken are h qd_i up to the rounding of q_i + h
           qd_i (EPS |q| against h |qd|: an FD-sized error) */
        ed = ((double)ep - (double)em) / (2.0 * FD_STEP);
        kd = ((double)kp + (double)km) / (2.0 * FD_STEP);
        fd = ((double)fp - (double)fm) / (2.0 * FD_STEP);
        ref -= (double)el->rs.g[gi].w * L *
               ((double)m->c_eps * (double)m->EA * ed * ed +
                (bend ? (double)m->c_kap * (double)m->EJ * kd * kd : 0.0) +
                (tw ? (double)m->c_phi * (double)m->GI * fd * fd : 0.0));
    }
    *scale = sc + fabs(ref);
    *power = pw;
    return pw - ref;
}

static void test_dissipation(void **state)
{
    const vlbe_ale3_mat m = mat3_std();
    const double tol = 16.0 * FD_ERR;
    vlbe_ale3_elem el;
    tu_rng g = tu_rng_seed(325);
    double wa = 0.0, wb = 0.0;
    int s, k, c;
    (void)state;
    elem_make(&el, &m, 0, 0, 0);
    for (s = 0; s < 3; ++s) {
        st3 x, xd, y, yd;
        double t[3];
        int kk;
        /* curved (string only: |k| does not give |k'| where k != 0) */
        make_state(&g, 0.5, 0.15, 0.8, &x, &xd);
        /* straight, stretched 1.1, twisted, random rates */
        make_state(&g, 0.0, 0.0, 0.8, &y, &yd);
        rand_dir(&g, t);
        for (kk = 0; kk < 2; ++kk)
            for (c = 0; c < 3; ++c) {
                y.n[kk].r[c] = y.n[0].r[c] + kk * 1.1 * (y.n[1].p - y.n[0].p) * t[c];
                y.n[kk].rp[c] = 1.1 * t[c];
            }
        for (k = 0; k < N_MODES; ++k) {
            const unsigned mode = mode_of(k) | VLBE_ALE_FIX_P1 | VLBE_ALE_FIX_P2;
            vlbe_real q[NQ], qd[NQ];
            double res, sc, pw;
            if (mode_of(k) & (VLBE_ALE_NO_DAMP | VLBE_ALE_FIX_P1 | VLBE_ALE_FIX_P2)) continue;
            if (mode & VLBE_ALE_NO_BEND) {
                pack(mode, &x, q);
                pack(mode, &xd, qd);
                res = dissipation_residual(&el, mode, q, qd, &sc, &pw);
                wa = fmax(wa, fabs(res) / sc);
                ASSERT_CLOSE_CTX(res, 0.0, 0, tol * sc, "curved, mode %u", mode);
                assert_true(pw < 0.0);
            }
            pack(mode, &y, q);
            pack(mode, &yd, qd);
            res = dissipation_residual(&el, mode, q, qd, &sc, &pw);
            wb = fmax(wb, fabs(res) / sc);
            ASSERT_CLOSE_CTX(res, 0.0, 0, tol * sc, "straight, mode %u", mode);
            assert_true(pw < 0.0);
        }
    }
    tu_report("dissipation, curved string (+ twist)", wa, tol);
    tu_report("dissipation, straight beam (+ twist)", wb, tol);
    tu_measured("ds_fd", fmax(wa, wb) / FD_ERR);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_force_jacobians),
        cmocka_unit_test(test_mass_jacobian),
        cmocka_unit_test(test_point_force_jacobian),
        cmocka_unit_test(test_point_torque_jacobian),
        cmocka_unit_test(test_energy_gradient),
        cmocka_unit_test(test_kinetic_energy),
        cmocka_unit_test(test_planar_reproduction),
        cmocka_unit_test(test_rigid_motion),
        cmocka_unit_test(test_twist_energy),
        cmocka_unit_test(test_straight_shaft_spin),
        cmocka_unit_test(test_curvature),
        cmocka_unit_test(test_errors_eval),
        cmocka_unit_test(test_errors_init),
        cmocka_unit_test(test_reduced_equals_full),
        cmocka_unit_test(test_quadrature),
        cmocka_unit_test(test_transport_inertia_lagrange),
        cmocka_unit_test(test_dissipation),
    };
    return cmocka_run_group_tests_name("ale3", tests, NULL, NULL);
}
