/* corot2d.h -- planar co-rotational Euler beam (the consistent co-rotational
   total-Lagrangian element of Hsiao et al.): deformation, inertia (with the
   nonlinear inertia terms) and Rayleigh damping forces, their exact
   Jacobians, mass matrix, energies; beams as chains of elements with
   prescribed coordinates -- part of vlbe v0.1.0   SPDX-License-Identifier: MIT

USAGE
   #include "corot2d.h"      (vlbe.h must sit in the same directory)

     vlbe_cr2d_mat mat = {0};  mat.EA = ...; mat.EI = ...; mat.rhoA = ...; mat.rhoI = ...;
     vlbe_cr2d_elem el;                      (one per element: it holds the geometry)
     vlbe_real X1[2] = {0, 0}, X2[2] = {0.1, 0};
     if (vlbe_cr2d_elem_init(&el, &mat, X1, X2, 0)) fail;
     vlbe_real q[6] = {u1, v1, phi1, u2, v2, phi2}, qd[6] = ...;
     vlbe_real Q[6], K[36], D[36], M[36];
     vlbe_cr2d_force(&el, 0, q, qd, Q, K, D);          (K, D may be NULL)
     vlbe_cr2d_mass(&el, 0, q, M);

CONFIG
   Nothing beyond vlbe.h.

CONVENTIONS
   Element coordinates, 6 per element, node by node, in the fixed global
   frame:  q = [u1, v1, phi1, u2, v2, phi2]: displacements of the nodes from
   their reference positions X1, X2 and rotations of the cross-sections
   from the reference (unbounded: any number of turns).  The reference
   configuration is straight and stress free: length L = |X2 - X1|, angle
   a0 of X2 - X1.
   Element frame (section 2.4 of [H]): e1 along the current chord from node
   1 to node 2 (length l, angle b), e2 = e1 turned by +90 deg.  Deformation
   rotations theta_j = a0 + phi_j - b, wrapped into (-pi, pi] through
   atan2 of the sine and cosine of a0 + phi_j against e1, so no turn count
   is ever accumulated; they must stay below pi (small deformation,
   assumption 3 of [H]).  Lateral deflection v(x) = N2 theta1 + N4 theta2
   (Hermite, eqs. 8-9, v1 = v2 = 0 in the element frame) on 0 <= x <= L,
   uniform extension (eq. 7)
        eps0 = (l - L)/L + (1/2L) int v'^2 dx
             = (l - L)/L + (4 theta1^2 - 2 theta1 theta2 + 4 theta2^2)/60,
   strain energy  U = EA L eps0^2 / 2 + (EI/2) int v''^2 dx
                    = EA L eps0^2 / 2 + (EI/L)(2 theta1^2 + 2 theta1 theta2 + 2 theta2^2).
   Its gradient in (l, theta1, theta2) is the paper's f_a^d, f_b^d (eqs.
   16-17: EA eps0 along the chord, EA eps0 int N' v' + EI int N'' v'' on
   the rotations); the global force is the exact gradient of U in q, and
   the tangent K its exact Hessian: the paper's k_a, k_b (eq. 21: k0 +
   kg) plus the terms of the consistent second-order linearization that
   eq. 21 leaves out (EA L deps0 deps0^T, the chord coupling EA deps0 and
   the rotation of the frame), so that Newton converges quadratically and
   K equals the finite differences of Q.
   Inertia (eqs. 18-19, 22): in the element frame of the current instant,
   axial u_a = (e1.x1, e1.x2), lateral u_b = (e2.x1, phi1, e2.x2, phi2):
        f_a^i = m_a u_a'' + rhoA int N_a (x/L int_0^L v'_t^2 - int_0^x v'_t^2) dx,
        f_b^i = m_b u_b'' - 2 rhoI (G_a^T u_a') int N_b' v'_t dx,
   v'_t = N_b'^T u_b' the slope rate, m_a = rhoA int N_a N_a^T, m_b = rhoA
   int N_b N_b^T + rhoI int N_b' N_b'^T (eq. 22 prints rhoA on the second
   term; eq. 19 shows it is the rotary inertia rhoI).  All integrals are
   polynomial and are evaluated in closed form.  In the global frame M(q) =
   T^T m T with T the rotation into the element frame: M depends on q
   through the chord angle b only.
   Damping (eqs. 50-51): f^v = (alpha m + beta k0) u', with k0 the linear
   stiffness (no kg) in the element frame; alpha = mat.ray_a [1/s], beta =
   mat.ray_b [s] (time-dependent damping, eq. 56: the caller updates them).
   Equations of motion (sign convention of integrators.h):
        M(q) q'' = Q(q, q'),   Q = -(f^d + f^i_nl + f^v)  (global),
   K = dQ/dq, D = dQ/dq'.  Matrices 6x6 row-major in the order of q.

   Mode flags (vlbe_cr2d_elem_init: defaults of the element; the eval
   functions OR their mode argument into them):
     VLBE_CR2D_LINEAR   linear element: small displacements about the
                        reference configuration, frame fixed at a0, K = k0
                        (geometric stiffness off), M constant, no nonlinear
                        inertia.  The model that fails under large rotation.
     VLBE_CR2D_NO_NLI   drop the nonlinear (velocity) inertia terms only
     VLBE_CR2D_NO_DAMP  drop the Rayleigh damping

   Errors: VLBE_ENONFINITE for NaN/Inf in q, q' or an acceleration;
   VLBE_ELENGTH when the chord length l <= L * 1e-6 (the frame is
   undefined); vlbe_cr2d_elem_init: VLBE_ELENGTH for X1 = X2, VLBE_EARG /
   VLBE_ENONFINITE for a bad material.  On failure no output is written.
   Stack: under 2 kB per call.

API
   vlbe_status vlbe_cr2d_elem_init(el, mat, X1, X2, flags)   element (geometry, material)
   vlbe_status vlbe_cr2d_force(el, mode, q, qd, Q, K, D)     Q and (optional) K, D
   vlbe_status vlbe_cr2d_mass(el, mode, q, M)                M(q), 6x6
   vlbe_status vlbe_cr2d_mass_jac(el, mode, q, a, Mq)        d(M a)/dq, 6x6
   vlbe_status vlbe_cr2d_energy(el, mode, q, qd, E)          E = {T, U}: kinetic (q'^T M q'/2), strain
   vlbe_status vlbe_cr2d_local(el, mode, q, loc)             loc = {l, theta1, theta2, eps0}
   beams (element e joins nodes e, e + 1; loads P; prescribed coordinates):
   vlbe_status vlbe_cr2d_beam_init(b, el, ne, fix, nfix)     n = 3 (ne + 1), m = nfix
   void vlbe_cr2d_fix_eval(f, t, g3)                         g, g', g'' of a prescribed coordinate
   int vlbe_cr2d_beam_mass / _force / _force_jac / _mass_jac / _constr / _constr_jac
       / _constr_acc (user = beam, ...)                      vlbe_dae callbacks
   vlbe_status vlbe_cr2d_beam_energy(b, q, v, E)             T, U of the beam

REFERENCES
   [H] K. M. Hsiao, T. F. Liu, M. H. Tsai, Geometrically nonlinear dynamic
       analysis of sliding beam, NSC 93-2211-E-009-026 (2005), eqs. 1-22,
       50-53.
   K. M. Hsiao, R. T. Yang, A. C. Lee, A consistent finite element
       formulation for non-linear dynamic analysis of planar beam, Int. J.
       Numer. Meth. Engng. 37 (1994) 75-89.
   M. A. Crisfield, Non-linear Finite Element Analysis of Solids and
       Structures, vol. 1, Wiley 1991, ch. 7 (co-rotational beam).
*/
#ifndef VLBE_COROT2D_H
#define VLBE_COROT2D_H
#include "vlbe.h"

#if !defined(VLBE_VERSION_MAJOR) || VLBE_VERSION_MAJOR != 0 || VLBE_VERSION_MINOR < 1
#error "corot2d.h needs vlbe.h 0.1 or newer in the same directory"
#endif

/* -- constants ---------------------------------------------------------- */
#define VLBE_CR2D_NQ 6 /* coordinates per element */

#define VLBE_CR2D_LINEAR 1u
#define VLBE_CR2D_NO_NLI 2u
#define VLBE_CR2D_NO_DAMP 4u

/* -- types -------------------------------------------------------------- */
/* Section and material, per unit reference length. */
typedef struct vlbe_cr2d_mat {
    vlbe_real EA;    /* axial stiffness                                  */
    vlbe_real EI;    /* bending stiffness                                */
    vlbe_real rhoA;  /* mass per length                                  */
    vlbe_real rhoI;  /* rotary inertia per length (0: none)              */
    vlbe_real ray_a; /* Rayleigh damping: mass-proportional alpha [1/s]  */
    vlbe_real ray_b; /* Rayleigh damping: stiffness-proportional beta [s] */
} vlbe_cr2d_mat;

/* One element: material, reference geometry, default mode flags. */
typedef struct vlbe_cr2d_elem {
    vlbe_cr2d_mat mat;
    vlbe_real X[4];  /* reference positions of node 1 and node 2      */
    vlbe_real L;     /* reference (undeformed) length                 */
    vlbe_real a0;    /* reference angle of X2 - X1                    */
    vlbe_real c0, s0; /* cos a0, sin a0                               */
    unsigned flags;
} vlbe_cr2d_elem;

/* -- API prototypes ----------------------------------------------------- */
VLBE_API vlbe_status vlbe_cr2d_elem_init(vlbe_cr2d_elem *el, const vlbe_cr2d_mat *mat,
                                         const vlbe_real *X1, const vlbe_real *X2,
                                         unsigned flags);
VLBE_API vlbe_status vlbe_cr2d_force(const vlbe_cr2d_elem *el, unsigned mode, const vlbe_real *q,
                                     const vlbe_real *qd, vlbe_real *VLBE_RESTRICT Q,
                                     vlbe_real *VLBE_RESTRICT K, vlbe_real *VLBE_RESTRICT D);
VLBE_API vlbe_status vlbe_cr2d_mass(const vlbe_cr2d_elem *el, unsigned mode, const vlbe_real *q,
                                    vlbe_real *VLBE_RESTRICT M);
VLBE_API vlbe_status vlbe_cr2d_mass_jac(const vlbe_cr2d_elem *el, unsigned mode,
                                        const vlbe_real *q, const vlbe_real *a,
                                        vlbe_real *VLBE_RESTRICT Mq);
VLBE_API vlbe_status vlbe_cr2d_energy(const vlbe_cr2d_elem *el, unsigned mode, const vlbe_real *q,
                                      const vlbe_real *qd, vlbe_real *VLBE_RESTRICT E);
VLBE_API vlbe_status vlbe_cr2d_local(const vlbe_cr2d_elem *el, unsigned mode, const vlbe_real *q,
                                     vlbe_real *VLBE_RESTRICT loc);

/* ===== implementation =================================================== */

VLBE_API vlbe_status vlbe_cr2d_elem_init(vlbe_cr2d_elem *el, const vlbe_cr2d_mat *mat,
                                         const vlbe_real *X1, const vlbe_real *X2,
                                         unsigned flags)
{
    vlbe_real d[2], L;
    VLBE_ASSERT(el != NULL && mat != NULL && X1 != NULL && X2 != NULL);
    if (!vlbe_all_finite(&mat->EA, 1) || !vlbe_all_finite(&mat->EI, 1) ||
        !vlbe_all_finite(&mat->rhoA, 1) || !vlbe_all_finite(&mat->rhoI, 1) ||
        !vlbe_all_finite(&mat->ray_a, 1) || !vlbe_all_finite(&mat->ray_b, 1) ||
        !vlbe_all_finite(X1, 2) || !vlbe_all_finite(X2, 2))
        return VLBE_ENONFINITE;
    if (!(mat->rhoA > VLBE_R(0.0)) || mat->EA < VLBE_R(0.0) || mat->EI < VLBE_R(0.0) ||
        mat->rhoI < VLBE_R(0.0) || mat->ray_a < VLBE_R(0.0) || mat->ray_b < VLBE_R(0.0))
        return VLBE_EARG;
    d[0] = X2[0] - X1[0];
    d[1] = X2[1] - X1[1];
    L = vlbe_v2_norm(d);
    if (!(L > VLBE_R(0.0))) return VLBE_ELENGTH;
    el->mat = *mat;
    el->X[0] = X1[0];
    el->X[1] = X1[1];
    el->X[2] = X2[0];
    el->X[3] = X2[1];
    el->L = L;
    el->c0 = d[0] / L;
    el->s0 = d[1] / L;
    el->a0 = vlbe_atan2(d[1], d[0]);
    el->flags = flags;
    return VLBE_OK;
}

/* -- local (element-frame) matrices, order (u1, v1, phi1, u2, v2, phi2) -- */
/* The cubic Hermite integrals on (v1, phi1, v2, phi2) as integer tables:
   entry (i, j) carries L^((i & 1) + (j & 1)) (one L per rotation index). */
static const short vlbe__cr2d_tab[3][4][4] = {
    /* 420/L int N_b N_b^T dx */
    {{156, 22, 54, -13}, {22, 4, 13, -3}, {54, 13, 156, -22}, {-13, -3, -22, 4}},
    /* 30 L int N_b' N_b'^T dx */
    {{36, 3, -36, 3}, {3, 4, -3, -1}, {-36, -3, 36, -3}, {3, -1, -3, 4}},
    /* L^3 int N_b'' N_b''^T dx */
    {{12, 6, -12, 6}, {6, 4, -6, 2}, {-12, -6, 12, -6}, {6, 2, -6, 4}}};
enum { VLBE__CR2D_NN = 0, VLBE__CR2D_N1N1 = 1, VLBE__CR2D_N2N2 = 2 };

/* out (stride ld, at the rows/columns ib) += c * table t with its L powers */
static inline void vlbe__cr2d_herm(int t, vlbe_real c, vlbe_real L, const int *ib, int ld,
                                   vlbe_real *out)
{
    int i, j;
    for (i = 0; i < 4; ++i)
        for (j = 0; j < 4; ++j) {
            const int p = (i & 1) + (j & 1);
            out[ib[i] * ld + ib[j]] +=
                c * (vlbe_real)vlbe__cr2d_tab[t][i][j] * (p == 0 ? VLBE_R(1.0) : (p == 1 ? L : L * L));
        }
}

static const int vlbe__cr2d_ib[4] = {1, 2, 4, 5}; /* v1, phi1, v2, phi2 in the 6-order */
static const int vlbe__cr2d_i4[4] = {0, 1, 2, 3};

/* m = m_a (+) m_b (eq. 22, the rotary term with rhoI) */
static inline void vlbe__cr2d_mloc(const vlbe_cr2d_elem *el, vlbe_real *m)
{
    const vlbe_real L = el->L, ma = el->mat.rhoA * L / VLBE_R(6.0);
    int i;
    for (i = 0; i < 36; ++i) m[i] = VLBE_R(0.0);
    m[0 * 6 + 0] = m[3 * 6 + 3] = VLBE_R(2.0) * ma;
    m[0 * 6 + 3] = m[3 * 6 + 0] = ma;
    vlbe__cr2d_herm(VLBE__CR2D_NN, el->mat.rhoA * L / VLBE_R(420.0), L, vlbe__cr2d_ib, 6, m);
    vlbe__cr2d_herm(VLBE__CR2D_N1N1, el->mat.rhoI / (VLBE_R(30.0) * L), L, vlbe__cr2d_ib, 6, m);
}

/* G_b = int N_b' N_b'^T dx (4x4 on v1, phi1, v2, phi2) */
static inline void vlbe__cr2d_gb(vlbe_real L, vlbe_real *G)
{
    int i;
    for (i = 0; i < 16; ++i) G[i] = VLBE_R(0.0);
    vlbe__cr2d_herm(VLBE__CR2D_N1N1, VLBE_R(1.0) / (VLBE_R(30.0) * L), L, vlbe__cr2d_i4, 4, G);
}

/* k0: linear stiffness (EA/L axial, EI int N_b'' N_b''^T) */
static inline void vlbe__cr2d_k0loc(const vlbe_cr2d_elem *el, vlbe_real *k)
{
    const vlbe_real L = el->L, ka = el->mat.EA / L;
    int i;
    for (i = 0; i < 36; ++i) k[i] = VLBE_R(0.0);
    k[0 * 6 + 0] = k[3 * 6 + 3] = ka;
    k[0 * 6 + 3] = k[3 * 6 + 0] = -ka;
    vlbe__cr2d_herm(VLBE__CR2D_N2N2, el->mat.EI / (L * L * L), L, vlbe__cr2d_ib, 6, k);
}

/* -- the rotation T into the element frame (c, s = cos, sin of its angle) - */
/* y = T x: per node (u, v) = (c x + s y, -s x + c y), phi unchanged */
static inline void vlbe__cr2d_to_loc(vlbe_real c, vlbe_real s, const vlbe_real *x, vlbe_real *y)
{
    int k;
    for (k = 0; k < 6; k += 3) {
        const vlbe_real a = x[k], b = x[k + 1];
        y[k] = c * a + s * b;
        y[k + 1] = -s * a + c * b;
        y[k + 2] = x[k + 2];
    }
}

/* x = T^T y */
static inline void vlbe__cr2d_to_glob(vlbe_real c, vlbe_real s, const vlbe_real *y, vlbe_real *x)
{
    int k;
    for (k = 0; k < 6; k += 3) {
        const vlbe_real a = y[k], b = y[k + 1];
        x[k] = c * a - s * b;
        x[k + 1] = s * a + c * b;
        x[k + 2] = y[k + 2];
    }
}

/* G += T^T A T (A local 6x6) */
static inline void vlbe__cr2d_congr(vlbe_real c, vlbe_real s, const vlbe_real *A, vlbe_real *G)
{
    vlbe_real B[36], col[6], out[6];
    int i, j;
    /* B = A T: row i of A T is r T = (T^T r^T)^T, r the row i of A */
    for (i = 0; i < 6; ++i) vlbe__cr2d_to_glob(c, s, A + i * 6, B + i * 6);
    for (j = 0; j < 6; ++j) {
        for (i = 0; i < 6; ++i) col[i] = B[i * 6 + j];
        vlbe__cr2d_to_glob(c, s, col, out);
        for (i = 0; i < 6; ++i) G[i * 6 + j] += out[i];
    }
}

/* d(T x)/db = Jt (T x): per node (u, v) -> (v, -u);  d(T^T y)/db = T^T Jf y,
   Jf: (u, v) -> (-v, u). */
static inline void vlbe__cr2d_jt(const vlbe_real *u, vlbe_real *y)
{
    int k;
    for (k = 0; k < 6; k += 3) {
        y[k] = u[k + 1];
        y[k + 1] = -u[k];
        y[k + 2] = VLBE_R(0.0);
    }
}

/* K[:, :] += g_b^T outer: K_ij += x_i gb_j, x = T^T (Jf f + A Jt u) the
   derivative of T^T (f(T q') ...) in the frame angle (A = df/du local,
   f local force, u = T q' local rate) */
static inline void vlbe__cr2d_frame_col(vlbe_real c, vlbe_real s, const vlbe_real *f,
                                        const vlbe_real *A, const vlbe_real *u,
                                        const vlbe_real *gb, vlbe_real *K)
{
    vlbe_real ju[6], y[6], x[6];
    int i, j;
    vlbe__cr2d_jt(u, ju);
    for (i = 0; i < 6; ++i) {
        vlbe_real t = VLBE_R(0.0);
        for (j = 0; j < 6; ++j) t += A[i * 6 + j] * ju[j];
        y[i] = t;
    }
    for (i = 0; i < 6; i += 3) { /* Jf f */
        y[i] -= f[i + 1];
        y[i + 1] += f[i];
    }
    vlbe__cr2d_to_glob(c, s, y, x);
    for (i = 0; i < 6; ++i)
        for (j = 0; j < 6; ++j) K[i * 6 + j] += x[i] * gb[j];
}

/* -- kinematics ---------------------------------------------------------- */
typedef struct vlbe__cr2d_kin {
    vlbe_real c, s, l;  /* chord direction and length (LINEAR: c0, s0, L)   */
    vlbe_real th[2];    /* deformation rotations                            */
    vlbe_real eps;      /* eps0 (eq. 7)                                     */
    vlbe_real gl[6], gb[6]; /* gradients of l and of the chord angle b      */
} vlbe__cr2d_kin;

static inline vlbe_status vlbe__cr2d_check(const vlbe_real *q, const vlbe_real *qd)
{
    if (!vlbe_all_finite(q, 6)) return VLBE_ENONFINITE;
    if (qd && !vlbe_all_finite(qd, 6)) return VLBE_ENONFINITE;
    return VLBE_OK;
}

/* Current chord, deformation rotations and eps0; LINEAR: the frame stays
   at a0, theta_j = phi_j - (v2 - v1)/L and eps0 = (u2 - u1)/L in it. */
static inline vlbe_status vlbe__cr2d_kin_eval(const vlbe_cr2d_elem *el, int lin, const vlbe_real *q,
                                              vlbe__cr2d_kin *k)
{
    const vlbe_real L = el->L;
    int j;
    if (lin) {
        vlbe_real u[6];
        vlbe__cr2d_to_loc(el->c0, el->s0, q, u);
        k->c = el->c0;
        k->s = el->s0;
        k->l = L;
        k->th[0] = u[2] - (u[4] - u[1]) / L;
        k->th[1] = u[5] - (u[4] - u[1]) / L;
        k->eps = (u[3] - u[0]) / L;
    } else {
        const vlbe_real dx = el->X[2] + q[3] - el->X[0] - q[0];
        const vlbe_real dy = el->X[3] + q[4] - el->X[1] - q[1];
        const vlbe_real l = vlbe_sqrt(dx * dx + dy * dy);
        if (!(l > VLBE_R(1e-6) * L)) return VLBE_ELENGTH;
        k->l = l;
        k->c = dx / l;
        k->s = dy / l;
        for (j = 0; j < 2; ++j) {
            /* direction of the cross-section normal's tangent: a0 + phi_j,
               taken against e1 (sine and cosine of the difference) */
            const vlbe_real ph = q[2 + 3 * j];
            const vlbe_real cp = vlbe_cos(ph), sp = vlbe_sin(ph);
            const vlbe_real ca = el->c0 * cp - el->s0 * sp, sa = el->s0 * cp + el->c0 * sp;
            k->th[j] = vlbe_atan2(sa * k->c - ca * k->s, ca * k->c + sa * k->s);
        }
        k->eps = (l - L) / L + (VLBE_R(4.0) * k->th[0] * k->th[0] -
                                VLBE_R(2.0) * k->th[0] * k->th[1] +
                                VLBE_R(4.0) * k->th[1] * k->th[1]) /
                                   VLBE_R(60.0);
    }
    k->gl[0] = -k->c;
    k->gl[1] = -k->s;
    k->gl[3] = k->c;
    k->gl[4] = k->s;
    k->gl[2] = k->gl[5] = VLBE_R(0.0);
    k->gb[0] = k->s / k->l;
    k->gb[1] = -k->c / k->l;
    k->gb[3] = -k->s / k->l;
    k->gb[4] = k->c / k->l;
    k->gb[2] = k->gb[5] = VLBE_R(0.0);
    return VLBE_OK;
}

/* -- deformation force (nonlinear): F = grad U, K = Hess U --------------- */
static inline void vlbe__cr2d_elastic(const vlbe_cr2d_elem *el, const vlbe__cr2d_kin *k,
                                      vlbe_real *F, vlbe_real *K)
{
    const vlbe_real L = el->L, EA = el->mat.EA, EI = el->mat.EI;
    const vlbe_real t1 = k->th[0], t2 = k->th[1], eps = k->eps;
    /* d eps0 / d theta (eq. 7) */
    const vlbe_real a1 = (VLBE_R(4.0) * t1 - t2) / VLBE_R(30.0);
    const vlbe_real a2 = (VLBE_R(4.0) * t2 - t1) / VLBE_R(30.0);
    const vlbe_real gl = EA * eps; /* f_a^d (eq. 16) */
    const vlbe_real g1 = EA * L * eps * a1 + EI / L * (VLBE_R(4.0) * t1 + VLBE_R(2.0) * t2);
    const vlbe_real g2 = EA * L * eps * a2 + EI / L * (VLBE_R(2.0) * t1 + VLBE_R(4.0) * t2);
    vlbe_real B[3][6];
    int i, j, a, b;
    for (i = 0; i < 6; ++i) {
        B[0][i] = k->gl[i];
        B[1][i] = -k->gb[i];
        B[2][i] = -k->gb[i];
    }
    B[1][2] += VLBE_R(1.0);
    B[2][5] += VLBE_R(1.0);
    for (i = 0; i < 6; ++i) F[i] += gl * B[0][i] + g1 * B[1][i] + g2 * B[2][i];
    if (!K) return;
    {
        /* Hessian in (l, theta1, theta2) (eq. 21 plus the terms it drops) */
        const vlbe_real kg = EA * L * eps / VLBE_R(30.0), kb = EI / L;
        vlbe_real H[3][3];
        vlbe_real P[2][2], Hb[2][2];
        const vlbe_real c = k->c, s = k->s, l = k->l;
        const vlbe_real gsum = g1 + g2;
        H[0][0] = EA / L;
        H[0][1] = H[1][0] = EA * a1;
        H[0][2] = H[2][0] = EA * a2;
        H[1][1] = EA * L * a1 * a1 + VLBE_R(4.0) * kg + VLBE_R(4.0) * kb;
        H[2][2] = EA * L * a2 * a2 + VLBE_R(4.0) * kg + VLBE_R(4.0) * kb;
        H[1][2] = H[2][1] = EA * L * a1 * a2 - kg + VLBE_R(2.0) * kb;
        for (a = 0; a < 3; ++a)
            for (b = 0; b < 3; ++b) {
                const vlbe_real h = H[a][b];
                if (h == VLBE_R(0.0)) continue;
                for (i = 0; i < 6; ++i) {
                    const vlbe_real hb = h * B[a][i];
                    for (j = 0; j < 6; ++j) K[i * 6 + j] += hb * B[b][j];
                }
            }
        /* gl d2l/dd2 - (g1 + g2) d2b/dd2, d = x2 - x1: e2 e2^T / l and
           -(e1 e2^T + e2 e1^T) / l^2 */
        P[0][0] = gl * s * s / l;
        P[0][1] = P[1][0] = -gl * c * s / l;
        P[1][1] = gl * c * c / l;
        Hb[0][0] = gsum * VLBE_R(2.0) * (-c * s) / (l * l);
        Hb[0][1] = Hb[1][0] = gsum * (c * c - s * s) / (l * l);
        Hb[1][1] = gsum * VLBE_R(2.0) * (c * s) / (l * l);
        for (a = 0; a < 2; ++a)
            for (b = 0; b < 2; ++b) {
                /* -(g1+g2) * (-(e1 e2^T + e2 e1^T)/l^2): e1 e2^T + e2 e1^T =
                   [[-2cs, c^2 - s^2], [c^2 - s^2, 2cs]] */
                const vlbe_real v = P[a][b] + Hb[a][b];
                K[a * 6 + b] += v;
                K[(3 + a) * 6 + 3 + b] += v;
                K[a * 6 + 3 + b] -= v;
                K[(3 + a) * 6 + b] -= v;
            }
    }
}

/* -- nonlinear inertia (eqs. 18-19): local force and its rate Jacobian --- */
static inline void vlbe__cr2d_nli(const vlbe_cr2d_elem *el, const vlbe_real *u, vlbe_real *f,
                                  vlbe_real *A)
{
    /* v'_t = c0 + c1 xi + c2 xi^2; p = v'_t^2 coefficients; fa_r = rhoA L^2
       c^T Q_r c with Q_r from the moments alpha_k (fa0), beta_k (fa1) */
    const vlbe_real L = el->L, rA = el->mat.rhoA * L * L, rI = el->mat.rhoI;
    const vlbe_real w = (u[4] - u[1]) / L;
    vlbe_real cc[3], dc[3][6], Qr[2][3][3], Qc[2][3], Gb[16], gu[4], ub[4], ed;
    int r, i, j, k;
    cc[0] = u[2];
    cc[1] = -VLBE_R(4.0) * u[2] - VLBE_R(2.0) * u[5] + VLBE_R(6.0) * w;
    cc[2] = VLBE_R(3.0) * u[2] + VLBE_R(3.0) * u[5] - VLBE_R(6.0) * w;
    for (r = 0; r < 2; ++r) {
        vlbe_real al[5];
        for (k = 0; k < 5; ++k) {
            const vlbe_real k1 = (vlbe_real)(k + 1);
            al[k] = r == 0 ? (VLBE_R(1.0) / VLBE_R(6.0) - VLBE_R(1.0) / (k1 + VLBE_R(1.0)) +
                              VLBE_R(1.0) / (k1 + VLBE_R(2.0))) / k1
                           : (VLBE_R(1.0) / VLBE_R(3.0) - VLBE_R(1.0) / (k1 + VLBE_R(2.0))) / k1;
        }
        Qr[r][0][0] = al[0];
        Qr[r][0][1] = Qr[r][1][0] = al[1];
        Qr[r][1][1] = al[2];
        Qr[r][0][2] = Qr[r][2][0] = al[2];
        Qr[r][1][2] = Qr[r][2][1] = al[3];
        Qr[r][2][2] = al[4];
        for (i = 0; i < 3; ++i) Qc[r][i] = rA * (Qr[r][i][0] * cc[0] + Qr[r][i][1] * cc[1] +
                                                  Qr[r][i][2] * cc[2]);
    }
    for (i = 0; i < 6; ++i) f[i] = VLBE_R(0.0);
    f[0] = cc[0] * Qc[0][0] + cc[1] * Qc[0][1] + cc[2] * Qc[0][2];
    f[3] = cc[0] * Qc[1][0] + cc[1] * Qc[1][1] + cc[2] * Qc[1][2];
    /* f_b = -2 rhoI eps' G_b u_b, eps' = (u2' - u1')/L */
    ub[0] = u[1];
    ub[1] = u[2];
    ub[2] = u[4];
    ub[3] = u[5];
    ed = (u[3] - u[0]) / L;
    vlbe__cr2d_gb(L, Gb);
    for (i = 0; i < 4; ++i) {
        gu[i] = VLBE_R(0.0);
        for (j = 0; j < 4; ++j) gu[i] += Gb[i * 4 + j] * ub[j];
    }
    {
        const int *ib = vlbe__cr2d_ib;
        for (i = 0; i < 4; ++i) f[ib[i]] = -VLBE_R(2.0) * rI * ed * gu[i];
        if (!A) return;
        for (i = 0; i < 36; ++i) A[i] = VLBE_R(0.0);
        /* dc/du */
        for (i = 0; i < 3; ++i)
            for (j = 0; j < 6; ++j) dc[i][j] = VLBE_R(0.0);
        dc[0][2] = VLBE_R(1.0);
        dc[1][1] = -VLBE_R(6.0) / L;
        dc[1][2] = -VLBE_R(4.0);
        dc[1][4] = VLBE_R(6.0) / L;
        dc[1][5] = -VLBE_R(2.0);
        dc[2][1] = VLBE_R(6.0) / L;
        dc[2][2] = VLBE_R(3.0);
        dc[2][4] = -VLBE_R(6.0) / L;
        dc[2][5] = VLBE_R(3.0);
        for (j = 0; j < 6; ++j) {
            A[0 * 6 + j] = VLBE_R(2.0) * (Qc[0][0] * dc[0][j] + Qc[0][1] * dc[1][j] +
                                          Qc[0][2] * dc[2][j]);
            A[3 * 6 + j] = VLBE_R(2.0) * (Qc[1][0] * dc[0][j] + Qc[1][1] * dc[1][j] +
                                          Qc[1][2] * dc[2][j]);
        }
        for (i = 0; i < 4; ++i) {
            A[ib[i] * 6 + 0] += VLBE_R(2.0) * rI * gu[i] / L;
            A[ib[i] * 6 + 3] -= VLBE_R(2.0) * rI * gu[i] / L;
            for (j = 0; j < 4; ++j) A[ib[i] * 6 + ib[j]] -= VLBE_R(2.0) * rI * ed * Gb[i * 4 + j];
        }
    }
}

/* Q, K, D into the caller's zeroed locals (F = -Q accumulated, negated at
   the end) */
static inline vlbe_status vlbe__cr2d_forces(const vlbe_cr2d_elem *el, unsigned mode,
                                            const vlbe_real *q, const vlbe_real *qd, vlbe_real *F,
                                            vlbe_real *K, vlbe_real *D)
{
    const int lin = (mode & VLBE_CR2D_LINEAR) != 0;
    const int nli = !lin && !(mode & VLBE_CR2D_NO_NLI) &&
                    (el->mat.rhoA != VLBE_R(0.0) || el->mat.rhoI != VLBE_R(0.0));
    const int damp = !(mode & VLBE_CR2D_NO_DAMP) &&
                     (el->mat.ray_a != VLBE_R(0.0) || el->mat.ray_b != VLBE_R(0.0));
    vlbe__cr2d_kin k;
    vlbe_status st;
    int i;
    if ((st = vlbe__cr2d_kin_eval(el, lin, q, &k)) != VLBE_OK) return st;
    if (lin) {
        vlbe_real k0[36], u[6], f[6], g[6];
        vlbe__cr2d_k0loc(el, k0);
        vlbe__cr2d_to_loc(k.c, k.s, q, u);
        vlbe_mat_vec(6, 6, k0, u, f);
        vlbe__cr2d_to_glob(k.c, k.s, f, g);
        for (i = 0; i < 6; ++i) F[i] += g[i];
        if (K) vlbe__cr2d_congr(k.c, k.s, k0, K);
    } else
        vlbe__cr2d_elastic(el, &k, F, K);
    if (nli || damp) {
        /* local rate u = T q', local force f = f_nl(u) + C u, A = df/du */
        vlbe_real u[6], f[6], A[36], g[6];
        vlbe__cr2d_to_loc(k.c, k.s, qd, u);
        if (nli)
            vlbe__cr2d_nli(el, u, f, A);
        else {
            for (i = 0; i < 6; ++i) f[i] = VLBE_R(0.0);
            for (i = 0; i < 36; ++i) A[i] = VLBE_R(0.0);
        }
        if (damp) {
            vlbe_real m[36], k0[36], cu[6];
            vlbe__cr2d_mloc(el, m);
            vlbe__cr2d_k0loc(el, k0);
            for (i = 0; i < 36; ++i) m[i] = el->mat.ray_a * m[i] + el->mat.ray_b * k0[i];
            vlbe_mat_vec(6, 6, m, u, cu);
            for (i = 0; i < 6; ++i) f[i] += cu[i];
            for (i = 0; i < 36; ++i) A[i] += m[i];
        }
        vlbe__cr2d_to_glob(k.c, k.s, f, g);
        for (i = 0; i < 6; ++i) F[i] += g[i];
        if (D) vlbe__cr2d_congr(k.c, k.s, A, D);
        if (K && !lin) vlbe__cr2d_frame_col(k.c, k.s, f, A, u, k.gb, K);
    }
    return VLBE_OK;
}

VLBE_API vlbe_status vlbe_cr2d_force(const vlbe_cr2d_elem *el, unsigned mode, const vlbe_real *q,
                                     const vlbe_real *qd, vlbe_real *VLBE_RESTRICT Q,
                                     vlbe_real *VLBE_RESTRICT K, vlbe_real *VLBE_RESTRICT D)
{
    vlbe_real F[6], Kt[36], Dt[36];
    vlbe_status st;
    int i;
    VLBE_ASSERT(el != NULL && q != NULL && qd != NULL && Q != NULL);
    mode |= el->flags;
    if ((st = vlbe__cr2d_check(q, qd)) != VLBE_OK) return st;
    for (i = 0; i < 6; ++i) F[i] = VLBE_R(0.0);
    for (i = 0; i < 36; ++i) Kt[i] = Dt[i] = VLBE_R(0.0);
    st = vlbe__cr2d_forces(el, mode, q, qd, F, K ? Kt : NULL, D ? Dt : NULL);
    if (st != VLBE_OK) return st;
    for (i = 0; i < 6; ++i) Q[i] = -F[i];
    if (K)
        for (i = 0; i < 36; ++i) K[i] = -Kt[i];
    if (D)
        for (i = 0; i < 36; ++i) D[i] = -Dt[i];
    return VLBE_OK;
}

VLBE_API vlbe_status vlbe_cr2d_mass(const vlbe_cr2d_elem *el, unsigned mode, const vlbe_real *q,
                                    vlbe_real *VLBE_RESTRICT M)
{
    vlbe__cr2d_kin k;
    vlbe_real m[36];
    vlbe_status st;
    int i;
    VLBE_ASSERT(el != NULL && q != NULL && M != NULL);
    mode |= el->flags;
    if ((st = vlbe__cr2d_check(q, NULL)) != VLBE_OK) return st;
    if ((st = vlbe__cr2d_kin_eval(el, (mode & VLBE_CR2D_LINEAR) != 0, q, &k)) != VLBE_OK)
        return st;
    vlbe__cr2d_mloc(el, m);
    for (i = 0; i < 36; ++i) M[i] = VLBE_R(0.0);
    vlbe__cr2d_congr(k.c, k.s, m, M);
    return VLBE_OK;
}

VLBE_API vlbe_status vlbe_cr2d_mass_jac(const vlbe_cr2d_elem *el, unsigned mode,
                                        const vlbe_real *q, const vlbe_real *a,
                                        vlbe_real *VLBE_RESTRICT Mq)
{
    vlbe__cr2d_kin k;
    vlbe_real m[36], u[6], f[6];
    vlbe_status st;
    int i;
    VLBE_ASSERT(el != NULL && q != NULL && a != NULL && Mq != NULL);
    mode |= el->flags;
    if ((st = vlbe__cr2d_check(q, a)) != VLBE_OK) return st;
    if ((st = vlbe__cr2d_kin_eval(el, (mode & VLBE_CR2D_LINEAR) != 0, q, &k)) != VLBE_OK)
        return st;
    for (i = 0; i < 36; ++i) Mq[i] = VLBE_R(0.0);
    if (mode & VLBE_CR2D_LINEAR) return VLBE_OK; /* M constant */
    vlbe__cr2d_mloc(el, m);
    vlbe__cr2d_to_loc(k.c, k.s, a, u);
    vlbe_mat_vec(6, 6, m, u, f);
    vlbe__cr2d_frame_col(k.c, k.s, f, m, u, k.gb, Mq);
    return VLBE_OK;
}

VLBE_API vlbe_status vlbe_cr2d_energy(const vlbe_cr2d_elem *el, unsigned mode, const vlbe_real *q,
                                      const vlbe_real *qd, vlbe_real *VLBE_RESTRICT E)
{
    vlbe__cr2d_kin k;
    vlbe_real m[36], u[6], mu[6];
    vlbe_status st;
    vlbe_real L;
    VLBE_ASSERT(el != NULL && q != NULL && qd != NULL && E != NULL);
    L = el->L;
    mode |= el->flags;
    if ((st = vlbe__cr2d_check(q, qd)) != VLBE_OK) return st;
    if ((st = vlbe__cr2d_kin_eval(el, (mode & VLBE_CR2D_LINEAR) != 0, q, &k)) != VLBE_OK)
        return st;
    vlbe__cr2d_mloc(el, m);
    vlbe__cr2d_to_loc(k.c, k.s, qd, u);
    vlbe_mat_vec(6, 6, m, u, mu);
    E[0] = VLBE_R(0.5) * vlbe_vec_dot(6, u, mu);
    /* LINEAR: k.eps, k.th are the linear measures, and U = q^T K0 q / 2 has
       the same form without the quadratic part of eps0 */
    E[1] = VLBE_R(0.5) * el->mat.EA * L * k.eps * k.eps +
           el->mat.EI / L * VLBE_R(2.0) *
               (k.th[0] * k.th[0] + k.th[0] * k.th[1] + k.th[1] * k.th[1]);
    return VLBE_OK;
}

VLBE_API vlbe_status vlbe_cr2d_local(const vlbe_cr2d_elem *el, unsigned mode, const vlbe_real *q,
                                     vlbe_real *VLBE_RESTRICT loc)
{
    vlbe__cr2d_kin k;
    vlbe_status st;
    VLBE_ASSERT(el != NULL && q != NULL && loc != NULL);
    mode |= el->flags;
    if ((st = vlbe__cr2d_check(q, NULL)) != VLBE_OK) return st;
    if ((st = vlbe__cr2d_kin_eval(el, (mode & VLBE_CR2D_LINEAR) != 0, q, &k)) != VLBE_OK)
        return st;
    loc[0] = k.l;
    loc[1] = k.th[0];
    loc[2] = k.th[1];
    loc[3] = k.eps;
    return VLBE_OK;
}

/* ===== beams: chains of elements ======================================== */
/* A beam of ne elements, element e joining nodes e and e + 1; coordinates
   q[3 i .. 3 i + 2] = (u, v, phi) of node i, n = 3 (ne + 1).  Constant nodal
   loads P (n, scaled by `load`) and prescribed coordinates (holonomic,
   rheonomic constraints q[dof] = g(t), m = nfix) complete the vlbe_dae
   problem; the callbacks below take the beam as `user`.  A callback that
   fails returns 1 for VLBE_ELENGTH and VLBE_ENONFINITE (the point lies
   outside the model's domain: the integrators retry smaller) and -1
   otherwise, with the status and the element in err, err_elem. */
typedef struct vlbe_cr2d_fix {
    int dof;          /* index in q                                        */
    vlbe_real g[3];   /* g(t) = g0 + g1 t + g2 t^2/2 when fun is NULL      */
    void (*fun)(void *ctx, vlbe_real t, vlbe_real *g3); /* g, g', g'' at t */
    void *ctx;
} vlbe_cr2d_fix;

typedef struct vlbe_cr2d_beam {
    const vlbe_cr2d_elem *el; /* ne elements                              */
    int ne, n;                /* elements, coordinates 3 (ne + 1)         */
    unsigned mode;            /* ORed into every element call             */
    const vlbe_real *P;       /* nodal loads (n) or NULL                  */
    vlbe_real load;           /* factor on P                              */
    const vlbe_cr2d_fix *fix; /* prescribed coordinates                   */
    int nfix;
    vlbe_status err;          /* last failure of a callback               */
    int err_elem;
} vlbe_cr2d_beam;

VLBE_API vlbe_status vlbe_cr2d_beam_init(vlbe_cr2d_beam *b, const vlbe_cr2d_elem *el, int ne,
                                         const vlbe_cr2d_fix *fix, int nfix);
VLBE_API void vlbe_cr2d_fix_eval(const vlbe_cr2d_fix *f, vlbe_real t, vlbe_real *g3);
VLBE_API int vlbe_cr2d_beam_mass(void *user, vlbe_real t, const vlbe_real *q, const vlbe_real *v,
                                 vlbe_real *M);
VLBE_API int vlbe_cr2d_beam_force(void *user, vlbe_real t, const vlbe_real *q, const vlbe_real *v,
                                  vlbe_real *Q);
VLBE_API int vlbe_cr2d_beam_force_jac(void *user, vlbe_real t, const vlbe_real *q,
                                      const vlbe_real *v, vlbe_real *K, vlbe_real *D);
VLBE_API int vlbe_cr2d_beam_mass_jac(void *user, vlbe_real t, const vlbe_real *q,
                                     const vlbe_real *v, const vlbe_real *a, vlbe_real *Mq,
                                     vlbe_real *Mv);
VLBE_API int vlbe_cr2d_beam_constr(void *user, vlbe_real t, const vlbe_real *q, vlbe_real *C);
VLBE_API int vlbe_cr2d_beam_constr_jac(void *user, vlbe_real t, const vlbe_real *q, vlbe_real *Cq,
                                       vlbe_real *Ct);
VLBE_API int vlbe_cr2d_beam_constr_acc(void *user, vlbe_real t, const vlbe_real *q,
                                       const vlbe_real *v, vlbe_real *gamma);
VLBE_API vlbe_status vlbe_cr2d_beam_energy(const vlbe_cr2d_beam *b, const vlbe_real *q,
                                           const vlbe_real *v, vlbe_real *E);

VLBE_API vlbe_status vlbe_cr2d_beam_init(vlbe_cr2d_beam *b, const vlbe_cr2d_elem *el, int ne,
                                         const vlbe_cr2d_fix *fix, int nfix)
{
    int i;
    VLBE_ASSERT(b != NULL && el != NULL);
    if (ne < 1 || nfix < 0 || (nfix > 0 && fix == NULL)) return VLBE_EARG;
    for (i = 0; i < nfix; ++i)
        if (fix[i].dof < 0 || fix[i].dof >= 3 * (ne + 1)) return VLBE_EARG;
    b->el = el;
    b->ne = ne;
    b->n = 3 * (ne + 1);
    b->mode = 0;
    b->P = NULL;
    b->load = VLBE_R(1.0);
    b->fix = fix;
    b->nfix = nfix;
    b->err = VLBE_OK;
    b->err_elem = -1;
    return VLBE_OK;
}

VLBE_API void vlbe_cr2d_fix_eval(const vlbe_cr2d_fix *f, vlbe_real t, vlbe_real *g3)
{
    if (f->fun) {
        f->fun(f->ctx, t, g3);
        return;
    }
    g3[0] = f->g[0] + t * (f->g[1] + VLBE_R(0.5) * t * f->g[2]);
    g3[1] = f->g[1] + t * f->g[2];
    g3[2] = f->g[2];
}

static inline int vlbe__cr2d_fail(vlbe_cr2d_beam *b, vlbe_status st, int e)
{
    b->err = st;
    b->err_elem = e;
    return (st == VLBE_ELENGTH || st == VLBE_ENONFINITE) ? 1 : -1;
}

/* A[3e.., 3e..] += Ae (6x6) in the n x n matrix */
static inline void vlbe__cr2d_scatter(int n, int e, const vlbe_real *Ae, vlbe_real *A)
{
    const size_t o = (size_t)(3 * e), N = (size_t)n;
    size_t i, j;
    for (i = 0; i < 6; ++i)
        for (j = 0; j < 6; ++j) A[(o + i) * N + o + j] += Ae[i * 6 + j];
}

VLBE_API int vlbe_cr2d_beam_mass(void *user, vlbe_real t, const vlbe_real *q, const vlbe_real *v,
                                 vlbe_real *M)
{
    vlbe_cr2d_beam *b = (vlbe_cr2d_beam *)user;
    vlbe_real Me[36];
    vlbe_status st;
    int e;
    (void)t;
    (void)v;
    vlbe_vec_zero(b->n * b->n, M);
    for (e = 0; e < b->ne; ++e) {
        if ((st = vlbe_cr2d_mass(&b->el[e], b->mode, q + 3 * e, Me)) != VLBE_OK)
            return vlbe__cr2d_fail(b, st, e);
        vlbe__cr2d_scatter(b->n, e, Me, M);
    }
    return 0;
}

static inline int vlbe__cr2d_beam_forces(vlbe_cr2d_beam *b, const vlbe_real *q,
                                         const vlbe_real *v, vlbe_real *Q, vlbe_real *K,
                                         vlbe_real *D)
{
    vlbe_real Qe[6], Ke[36], De[36];
    vlbe_status st;
    int e, i;
    if (Q) {
        vlbe_vec_zero(b->n, Q);
        if (b->P)
            for (i = 0; i < b->n; ++i) Q[i] = b->load * b->P[i];
    }
    if (K) vlbe_vec_zero(b->n * b->n, K);
    if (D) vlbe_vec_zero(b->n * b->n, D);
    for (e = 0; e < b->ne; ++e) {
        if ((st = vlbe_cr2d_force(&b->el[e], b->mode, q + 3 * e, v + 3 * e, Qe, K ? Ke : NULL,
                                  D ? De : NULL)) != VLBE_OK)
            return vlbe__cr2d_fail(b, st, e);
        if (Q)
            for (i = 0; i < 6; ++i) Q[3 * e + i] += Qe[i];
        if (K) vlbe__cr2d_scatter(b->n, e, Ke, K);
        if (D) vlbe__cr2d_scatter(b->n, e, De, D);
    }
    return 0;
}

VLBE_API int vlbe_cr2d_beam_force(void *user, vlbe_real t, const vlbe_real *q, const vlbe_real *v,
                                  vlbe_real *Q)
{
    (void)t;
    return vlbe__cr2d_beam_forces((vlbe_cr2d_beam *)user, q, v, Q, NULL, NULL);
}

VLBE_API int vlbe_cr2d_beam_force_jac(void *user, vlbe_real t, const vlbe_real *q,
                                      const vlbe_real *v, vlbe_real *K, vlbe_real *D)
{
    (void)t;
    return vlbe__cr2d_beam_forces((vlbe_cr2d_beam *)user, q, v, NULL, K, D);
}

VLBE_API int vlbe_cr2d_beam_mass_jac(void *user, vlbe_real t, const vlbe_real *q,
                                     const vlbe_real *v, const vlbe_real *a, vlbe_real *Mq,
                                     vlbe_real *Mv)
{
    vlbe_cr2d_beam *b = (vlbe_cr2d_beam *)user;
    vlbe_real Me[36];
    vlbe_status st;
    int e;
    (void)t;
    (void)v;
    vlbe_vec_zero(b->n * b->n, Mq);
    if (Mv) vlbe_vec_zero(b->n * b->n, Mv);
    for (e = 0; e < b->ne; ++e) {
        if ((st = vlbe_cr2d_mass_jac(&b->el[e], b->mode, q + 3 * e, a + 3 * e, Me)) != VLBE_OK)
            return vlbe__cr2d_fail(b, st, e);
        vlbe__cr2d_scatter(b->n, e, Me, Mq);
    }
    return 0;
}

VLBE_API int vlbe_cr2d_beam_constr(void *user, vlbe_real t, const vlbe_real *q, vlbe_real *C)
{
    const vlbe_cr2d_beam *b = (const vlbe_cr2d_beam *)user;
    vlbe_real g[3];
    int k;
    for (k = 0; k < b->nfix; ++k) {
        vlbe_cr2d_fix_eval(&b->fix[k], t, g);
        C[k] = q[b->fix[k].dof] - g[0];
    }
    return 0;
}

VLBE_API int vlbe_cr2d_beam_constr_jac(void *user, vlbe_real t, const vlbe_real *q, vlbe_real *Cq,
                                       vlbe_real *Ct)
{
    const vlbe_cr2d_beam *b = (const vlbe_cr2d_beam *)user;
    vlbe_real g[3];
    int k;
    (void)q;
    vlbe_vec_zero(b->nfix * b->n, Cq);
    for (k = 0; k < b->nfix; ++k) {
        Cq[(size_t)k * (size_t)b->n + (size_t)b->fix[k].dof] = VLBE_R(1.0);
        if (Ct) {
            vlbe_cr2d_fix_eval(&b->fix[k], t, g);
            Ct[k] = -g[1];
        }
    }
    return 0;
}

VLBE_API int vlbe_cr2d_beam_constr_acc(void *user, vlbe_real t, const vlbe_real *q,
                                       const vlbe_real *v, vlbe_real *gamma)
{
    const vlbe_cr2d_beam *b = (const vlbe_cr2d_beam *)user;
    vlbe_real g[3];
    int k;
    (void)q;
    (void)v;
    for (k = 0; k < b->nfix; ++k) {
        vlbe_cr2d_fix_eval(&b->fix[k], t, g);
        gamma[k] = g[2];
    }
    return 0;
}

VLBE_API vlbe_status vlbe_cr2d_beam_energy(const vlbe_cr2d_beam *b, const vlbe_real *q,
                                           const vlbe_real *v, vlbe_real *E)
{
    vlbe_real Ee[2];
    vlbe_status st;
    int e;
    E[0] = E[1] = VLBE_R(0.0);
    for (e = 0; e < b->ne; ++e) {
        if ((st = vlbe_cr2d_energy(&b->el[e], b->mode, q + 3 * e, v + 3 * e, Ee)) != VLBE_OK)
            return st;
        E[0] += Ee[0];
        E[1] += Ee[1];
    }
    return VLBE_OK;
}

#endif /* VLBE_COROT2D_H */
