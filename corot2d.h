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
   mat.ray_b [s] (time-dependent damping, eq. 56: the caller updates them
   in el->mat directly).  Geometry changes go through vlbe_cr2d_elem_init;
   a direct change of el->mat is honoured (the local m and k0 tabulated at
   init are used only while the material they were made from is unchanged).
   Equations of motion (sign convention of integrators.h):
        M(q) q'' = Q(q, q'),   Q = -(f^d + f^i_nl + f^v)  (global),
   K = dQ/dq, D = dQ/dq'.  Matrices 6x6 row-major in the order of q.

   Transition element (section 2.5, vlbe_cr2d_trans_*): an element that
   straddles the exit C of a prismatic joint (axis a, vlbe_cr2d_joint).
   Node 1 is inside: the joint holds its lateral position and rotation
   (constraints of the caller's model, no force from this element on
   them), its axial coordinate a.x1 is the element's; node 2 is outside.
   The inside segment (undeformed length L1) is straight along a; the
   outside one (L2 = L - L1) runs from C to node 2 with the slope a at C
   (theta3 = angle of a against the chord C -> x2, eq. 35) and theta2 at
   node 2; L1, L2 follow from the uniform extension (eq. 24) exactly (no
   first-order expansion, eq. 26), U = EA L eps0^2/2 + EI (2 theta3^2 + 2
   theta3 theta2 + 2 theta2^2)/L2, inertia m_a over L (axial: a.x1 and
   e1.x2), m_b over L2 on (v2, phi2) and the velocity terms of eqs. 45-46;
   damping alpha m + beta k0 with k0 over L (axial) and L2 (bending).
   Forces and Jacobians are exact derivatives, including those of L2(q).
   With node 1 at the exit (L1 = 0) it has the energy, the mass and the
   node-2 forces of the conventional element with theta1 = theta3; the
   force on node 1's axial coordinate differs by the change of L2 (the
   bending and the extension of the material drawn into the joint), which
   the conventional element does not model.

   Mode flags (vlbe_cr2d_elem_init: defaults of the element; the eval
   functions OR their mode argument into them):
     VLBE_CR2D_LINEAR   linear element: small displacements about the
                        reference configuration, frame fixed at a0, K = k0
                        (geometric stiffness off), M constant, no nonlinear
                        inertia.  The model that fails under large rotation.
     VLBE_CR2D_NO_NLI   drop the nonlinear (velocity) inertia terms only
     VLBE_CR2D_NO_DAMP  drop the Rayleigh damping

   Floating frame of a LINEAR element (vlbe_cr2d_*_ff, vlbe_cr2d_beam.frame):
   the caller gives the angle theta and rate theta' of a frame turning
   about the global origin (a hub), fth = {theta, theta'}.  The element
   measures its linear deformation in that frame:
        d = R^T(theta) (X + u) - X per node (positions), phi - theta (rotations),
   elastic force -T^T K0 d with T = blockdiag(R^T(theta), 1) per node and K0
   = the fixed-frame LINEAR stiffness (k0 turned to a0), tangent K = -T^T
   K0 T; damping (alpha m + beta k0) on the rate relative to the frame, dd =
   R^T(theta) (u' + theta' J (X + u)), J (x, y) = (y, -x), phi' - theta'
   (so rigid rotation with the frame is not damped), which adds D theta' J
   to K.  Mass matrix and inertia stay those of the fixed-frame LINEAR
   element: constant M, exact in the global coordinates, so centrifugal
   softening and Coriolis forces are present but no geometric (centrifugal)
   stiffening -- the linear floating-frame (FFRF-equivalent) model that
   diverges in a spin-up above the first bending frequency.  theta = 0
   reproduces the fixed-frame LINEAR element bit for bit (cos - 1 is
   computed as -2 sin^2(theta/2)).  Energies: strain of d, kinetic of q'.
   theta'' is not used (the frame's acceleration acts through the global
   inertia).  A beam with frame != NULL passes the frame at the callback's
   t to every element whose mode has LINEAR; others ignore it.

   Errors: VLBE_ENONFINITE for NaN/Inf in q, q' or an acceleration;
   VLBE_ELENGTH when the chord length l <= L * 1e-6 (the frame is
   undefined); VLBE_ENONFINITE also when finite input overflows (each
   output is checked before it is written); vlbe_cr2d_elem_init:
   VLBE_ELENGTH for X1 = X2 or a length so small that the tabulated
   stiffness (L^-3) overflows, VLBE_ENONFINITE for one so large that the
   mass (L^3) does, VLBE_EARG / VLBE_ENONFINITE for a bad material.
   Transition element: VLBE_EBOUND when node 1 is outside the joint by
   more than L/2 (a.(x1 - C) > L/2: the formulas continue smoothly to a
   node just outside, as Newton
   iterates and the step in which it leaves need), node 2 not outside
   (a.(x2 - C) <= 0, or |x2 - C| <= 1e-6 L) or L2 <= 1e-6 L; VLBE_EARG for
   |a| != 1, a non-finite C or the LINEAR mode (no linear transition
   element); VLBE_ESINGULAR when eq. 24 has no solution.  Floating frame
   (*_ff): VLBE_EARG when the element's mode has no LINEAR, VLBE_ENONFINITE
   for NaN/Inf in fth; vlbe_cr2d_beam_energy: VLBE_EARG for a beam with a
   frame (it needs t: vlbe_cr2d_beam_energy_t).  On failure no output is
   written.
   Stack (float, Cortex-M4F, gcc -O2, tests/m4/stack.awk; double about
   twice): vlbe_cr2d_force, _force_ff and _trans_force with K and D at
   most 1944 B, the other element calls at most 1.1 kB; the beam
   callbacks up to 3.3 kB (force with the element views and the loads'
   frames).

API
   vlbe_status vlbe_cr2d_elem_init(el, mat, X1, X2, flags)   element (geometry, material)
   vlbe_status vlbe_cr2d_force(el, mode, q, qd, Q, K, D)     Q and (optional) K, D
   vlbe_status vlbe_cr2d_mass(el, mode, q, M)                M(q), 6x6
   vlbe_status vlbe_cr2d_mass_jac(el, mode, q, a, Mq)        d(M a)/dq, 6x6
   vlbe_status vlbe_cr2d_energy(el, mode, q, qd, E)          E = {T, U}: kinetic (q'^T M q'/2), strain
   vlbe_status vlbe_cr2d_local(el, mode, q, loc)             loc = {l, theta1, theta2, eps0}
   floating frame fth = {theta, theta'} of a LINEAR element:
   vlbe_status vlbe_cr2d_force_ff(el, mode, fth, q, qd, Q, K, D)  as force, deformation in the frame
   vlbe_status vlbe_cr2d_energy_ff(el, mode, fth, q, qd, E)  {T of q', U of d}
   vlbe_status vlbe_cr2d_local_ff(el, mode, fth, q, loc)     local of d
   transition element at the joint jt (node 1 inside, node 2 outside):
   vlbe_status vlbe_cr2d_trans_force / _mass / _mass_jac / _energy(el, jt, mode, ...)  as above
   vlbe_status vlbe_cr2d_trans_local(el, jt, mode, q, loc)   loc = {l1, l2, theta3, theta2, eps0, L1}
   beams (element e joins nodes e, e + 1; loads P; prescribed coordinates):
   vlbe_status vlbe_cr2d_beam_init(b, el, ne, fix, nfix)     n = 3 (ne + 1), m = nfix
   vlbe_status vlbe_cr2d_beam_band(b, order, order_cap)      banded callbacks (order: n + m
                                                             of the caller) or dense (NULL)
   vlbe_status vlbe_cr2d_beam_loads(b, loads, n)             point loads between the nodes
                                                             (vlbe_cr2d_load); b->dist, dist_e:
                                                             distributed dead load
   void vlbe_cr2d_fix_eval(f, t, g3)                         g, g', g'' of a prescribed coordinate
   int vlbe_cr2d_beam_mass / _force / _force_jac / _mass_jac / _constr / _constr_jac
       / _constr_acc (user = beam, ...)                      vlbe_dae callbacks
   vlbe_status vlbe_cr2d_beam_dae(b, sys)                    fill a vlbe_dae with them
   vlbe_status vlbe_cr2d_beam_energy(b, q, v, E)             T, U of the beam (no frame)
   vlbe_status vlbe_cr2d_beam_energy_t(b, t, q, v, E)        T, U at t (frame at t)

REFERENCES
   [H] K. M. Hsiao, T. F. Liu, M. H. Tsai, Geometrically nonlinear dynamic
       analysis of sliding beam, NSC 93-2211-E-009-026 (2005), eqs. 1-53.
   K. M. Hsiao, R. T. Yang, A. C. Lee, A consistent finite element
       formulation for non-linear dynamic analysis of planar beam, Int. J.
       Numer. Meth. Engng. 37 (1994) 75-89.
   M. A. Crisfield, Non-linear Finite Element Analysis of Solids and
       Structures, vol. 1, Wiley 1991, ch. 7 (co-rotational beam).
*/
#ifndef VLBE_COROT2D_H
#define VLBE_COROT2D_H
#include "vlbe.h"
#include <limits.h>

#if !defined(VLBE_VERSION_MAJOR) || VLBE_VERSION_MAJOR != 0 || VLBE_VERSION_MINOR < 1
#error "corot2d.h needs vlbe.h 0.1 or newer in the same directory"
#endif

/* -- constants ---------------------------------------------------------- */
#define VLBE_CR2D_NQ 6 /* coordinates per element */

#define VLBE_CR2D_LINEAR 1u
#define VLBE_CR2D_NO_NLI 2u
#define VLBE_CR2D_NO_DAMP 4u
/* internal: the caller needs the frame only (mass routines of the
   conventional element: no deformation rotations, no atan2) */
#define VLBE__CR2D_FRAME_ONLY 0x100u

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
    /* private: local mass and linear stiffness tabulated by init, valid
       while mat.rhoA, rhoI, EA, EI equal key_ (checked at each use, so a
       direct change of el->mat is still honoured) */
    vlbe_real m_[VLBE_CR2D_NQ * VLBE_CR2D_NQ], k0_[VLBE_CR2D_NQ * VLBE_CR2D_NQ], key_[4];
} vlbe_cr2d_elem;

/* The prismatic joint of the transition element: exit point C, unit axis
   a pointing out of the joint (toward the free part of the beam). */
typedef struct vlbe_cr2d_joint {
    vlbe_real C[2];
    vlbe_real a[2];
} vlbe_cr2d_joint;

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
VLBE_API vlbe_status vlbe_cr2d_force_ff(const vlbe_cr2d_elem *el, unsigned mode,
                                        const vlbe_real *fth, const vlbe_real *q,
                                        const vlbe_real *qd, vlbe_real *VLBE_RESTRICT Q,
                                        vlbe_real *VLBE_RESTRICT K, vlbe_real *VLBE_RESTRICT D);
VLBE_API vlbe_status vlbe_cr2d_energy_ff(const vlbe_cr2d_elem *el, unsigned mode,
                                         const vlbe_real *fth, const vlbe_real *q,
                                         const vlbe_real *qd, vlbe_real *VLBE_RESTRICT E);
VLBE_API vlbe_status vlbe_cr2d_local_ff(const vlbe_cr2d_elem *el, unsigned mode,
                                        const vlbe_real *fth, const vlbe_real *q,
                                        vlbe_real *VLBE_RESTRICT loc);
VLBE_API vlbe_status vlbe_cr2d_trans_force(const vlbe_cr2d_elem *el, const vlbe_cr2d_joint *jt,
                                           unsigned mode, const vlbe_real *q, const vlbe_real *qd,
                                           vlbe_real *VLBE_RESTRICT Q, vlbe_real *VLBE_RESTRICT K,
                                           vlbe_real *VLBE_RESTRICT D);
VLBE_API vlbe_status vlbe_cr2d_trans_mass(const vlbe_cr2d_elem *el, const vlbe_cr2d_joint *jt,
                                          unsigned mode, const vlbe_real *q,
                                          vlbe_real *VLBE_RESTRICT M);
VLBE_API vlbe_status vlbe_cr2d_trans_mass_jac(const vlbe_cr2d_elem *el,
                                              const vlbe_cr2d_joint *jt, unsigned mode,
                                              const vlbe_real *q, const vlbe_real *a,
                                              vlbe_real *VLBE_RESTRICT Mq);
VLBE_API vlbe_status vlbe_cr2d_trans_energy(const vlbe_cr2d_elem *el, const vlbe_cr2d_joint *jt,
                                            unsigned mode, const vlbe_real *q,
                                            const vlbe_real *qd, vlbe_real *VLBE_RESTRICT E);
VLBE_API vlbe_status vlbe_cr2d_trans_local(const vlbe_cr2d_elem *el, const vlbe_cr2d_joint *jt,
                                           unsigned mode, const vlbe_real *q,
                                           vlbe_real *VLBE_RESTRICT loc);

/* ===== implementation =================================================== */

VLBE_INLINE void vlbe__cr2d_lmat(const vlbe_cr2d_elem *el, int tr, vlbe_real L2, vlbe_real *m,
                                   vlbe_real *k0, vlbe_real *dm, vlbe_real *dk0);


VLBE_API vlbe_status vlbe_cr2d_elem_init(vlbe_cr2d_elem *el, const vlbe_cr2d_mat *mat,
                                         const vlbe_real *X1, const vlbe_real *X2,
                                         unsigned flags)
{
    vlbe_cr2d_elem t;
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
    if (!isfinite(L)) return VLBE_ENONFINITE; /* |X2 - X1|^2 overflowed */
    t.mat = *mat;
    t.X[0] = X1[0];
    t.X[1] = X1[1];
    t.X[2] = X2[0];
    t.X[3] = X2[1];
    t.L = L;
    t.c0 = d[0] / L;
    t.s0 = d[1] / L;
    t.a0 = vlbe_atan2(d[1], d[0]);
    t.flags = flags;
    /* not yet tabulated: lmat computes them (all four set, as gcc -O3
       cannot see that the first comparison already fails) */
    t.key_[0] = t.key_[1] = t.key_[2] = t.key_[3] = -VLBE_R(1.0);
    vlbe__cr2d_lmat(&t, 0, L, t.m_, t.k0_, NULL, NULL);
    /* powers of L up to L^-3 (k0) and L^3 (m): a length so small or so
       large that they overflow is out of range, el stays as it was */
    if (!vlbe_all_finite(t.m_, VLBE_CR2D_NQ * VLBE_CR2D_NQ) ||
        !vlbe_all_finite(t.k0_, VLBE_CR2D_NQ * VLBE_CR2D_NQ) || !isfinite(t.c0) || !isfinite(t.s0))
        return L < VLBE_R(1.0) ? VLBE_ELENGTH : VLBE_ENONFINITE;
    t.key_[0] = mat->rhoA;
    t.key_[1] = mat->rhoI;
    t.key_[2] = mat->EA;
    t.key_[3] = mat->EI;
    *el = t;
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

/* x^e for a small integer e */
VLBE_INLINE vlbe_real vlbe__cr2d_ipow(vlbe_real x, int e)
{
    vlbe_real r = VLBE_R(1.0);
    const vlbe_real b = e < 0 ? VLBE_R(1.0) / x : x;
    int i;
    for (i = 0; i < (e < 0 ? -e : e); ++i) r *= b;
    return r;
}

/* out (stride ld, at the rows/columns ib; ib < 0: skipped) += c * table t
   * L^(p + e), p = (i & 1) + (j & 1) the L powers of the table; dout (may
   be NULL) += its L-derivative. */
VLBE_INLINE void vlbe__cr2d_herm(int t, vlbe_real c, int e, vlbe_real L, const int *ib, int ld,
                                   vlbe_real *out, vlbe_real *dout)
{
    int i, j;
    for (i = 0; i < 4; ++i)
        for (j = 0; j < 4; ++j) {
            const int p = (i & 1) + (j & 1) + e;
            const vlbe_real v = c * (vlbe_real)vlbe__cr2d_tab[t][i][j];
            if (ib[i] < 0 || ib[j] < 0) continue;
            if (out) out[ib[i] * ld + ib[j]] += v * vlbe__cr2d_ipow(L, p);
            if (dout) dout[ib[i] * ld + ib[j]] += v * (vlbe_real)p * vlbe__cr2d_ipow(L, p - 1);
        }
}

static const int vlbe__cr2d_ib[4] = {1, 2, 4, 5}; /* v1, phi1, v2, phi2 in the 6-order */
static const int vlbe__cr2d_i4[4] = {0, 1, 2, 3};

static const int vlbe__cr2d_ib2[4] = {-1, -1, 4, 5}; /* the transition's v2, phi2 */

/* Local mass m and linear stiffness k0 (either may be NULL) of a
   conventional element (tr = 0: m_a, k_a over L and m_b, k_b over L) or of
   the transition element (tr = 1: m_a, k_a over L; m_b, k_b of the outside
   segment over L2 on v2, phi2 only, eqs. 48-49); dm, dk0 (transition, may
   be NULL, also without m, k0): their L2-derivatives.  m_b with rhoI (eq. 22 prints rhoA on the
   rotary term; eq. 19 shows rhoI). */
VLBE_INLINE void vlbe__cr2d_lmat(const vlbe_cr2d_elem *el, int tr, vlbe_real L2, vlbe_real *m,
                                   vlbe_real *k0, vlbe_real *dm, vlbe_real *dk0)
{
    const vlbe_real L = el->L, ma = el->mat.rhoA * L / VLBE_R(6.0), ka = el->mat.EA / L;
    const int *ib = tr ? vlbe__cr2d_ib2 : vlbe__cr2d_ib;
    int i;
    if (!tr && L2 == L && el->key_[0] == el->mat.rhoA && el->key_[1] == el->mat.rhoI &&
        el->key_[2] == el->mat.EA && el->key_[3] == el->mat.EI) { /* tabulated by init */
        if (m)
            for (i = 0; i < VLBE_CR2D_NQ * VLBE_CR2D_NQ; ++i) m[i] = el->m_[i];
        if (k0)
            for (i = 0; i < VLBE_CR2D_NQ * VLBE_CR2D_NQ; ++i) k0[i] = el->k0_[i];
        return;
    }
    if (m || dm) {
        if (m) {
            for (i = 0; i < VLBE_CR2D_NQ * VLBE_CR2D_NQ; ++i) m[i] = VLBE_R(0.0);
            m[0 * VLBE_CR2D_NQ + 0] = m[3 * VLBE_CR2D_NQ + 3] = VLBE_R(2.0) * ma;
            m[0 * VLBE_CR2D_NQ + 3] = m[3 * VLBE_CR2D_NQ + 0] = ma;
        }
        if (dm)
            for (i = 0; i < VLBE_CR2D_NQ * VLBE_CR2D_NQ; ++i) dm[i] = VLBE_R(0.0);
        vlbe__cr2d_herm(VLBE__CR2D_NN, el->mat.rhoA / VLBE_R(420.0), 1, L2, ib, VLBE_CR2D_NQ, m,
                        dm);
        vlbe__cr2d_herm(VLBE__CR2D_N1N1, el->mat.rhoI / VLBE_R(30.0), -1, L2, ib, VLBE_CR2D_NQ, m,
                        dm);
    }
    if (k0 || dk0) {
        if (k0) {
            for (i = 0; i < VLBE_CR2D_NQ * VLBE_CR2D_NQ; ++i) k0[i] = VLBE_R(0.0);
            k0[0 * VLBE_CR2D_NQ + 0] = k0[3 * VLBE_CR2D_NQ + 3] = ka;
            k0[0 * VLBE_CR2D_NQ + 3] = k0[3 * VLBE_CR2D_NQ + 0] = -ka;
        }
        if (dk0)
            for (i = 0; i < VLBE_CR2D_NQ * VLBE_CR2D_NQ; ++i) dk0[i] = VLBE_R(0.0);
        vlbe__cr2d_herm(VLBE__CR2D_N2N2, el->mat.EI, -3, L2, ib, VLBE_CR2D_NQ, k0, dk0);
    }
}

/* G_b = int N_b' N_b'^T dx over a length L2 (4x4 on v1, phi1, v2, phi2),
   dG (may be NULL) its L2-derivative */
VLBE_INLINE void vlbe__cr2d_gb(vlbe_real L2, vlbe_real *G, vlbe_real *dG)
{
    int i;
    for (i = 0; i < 16; ++i) G[i] = VLBE_R(0.0);
    if (dG)
        for (i = 0; i < 16; ++i) dG[i] = VLBE_R(0.0);
    vlbe__cr2d_herm(VLBE__CR2D_N1N1, VLBE_R(1.0) / VLBE_R(30.0), -1, L2, vlbe__cr2d_i4, 4, G, dG);
}

/* -- the rotation T into the element frame ------------------------------ */
/* Per node a frame (c, s = cos, sin of its angle): the chord for a
   conventional element; for the transition element the joint axis at node
   1 and the outside segment's chord at node 2.  rot[k]: node k's frame
   turns with the chord angle b (the q-dependence of T). */
typedef struct vlbe__cr2d_fr {
    vlbe_real c[2], s[2];
    int rot[2];
} vlbe__cr2d_fr;

VLBE_INLINE void vlbe__cr2d_fr_set(vlbe__cr2d_fr *f, vlbe_real c1, vlbe_real s1, int r1,
                                     vlbe_real c2, vlbe_real s2, int r2)
{
    f->c[0] = c1;
    f->s[0] = s1;
    f->rot[0] = r1;
    f->c[1] = c2;
    f->s[1] = s2;
    f->rot[1] = r2;
}

/* y = T x: per node (u, v) = (c x + s y, -s x + c y), phi unchanged */
VLBE_INLINE void vlbe__cr2d_to_loc(const vlbe__cr2d_fr *f, const vlbe_real *x, vlbe_real *y)
{
    int k;
    for (k = 0; k < 2; ++k) {
        const vlbe_real a = x[3 * k], b = x[3 * k + 1], c = f->c[k], s = f->s[k];
        y[3 * k] = c * a + s * b;
        y[3 * k + 1] = -s * a + c * b;
        y[3 * k + 2] = x[3 * k + 2];
    }
}

/* x = T^T y */
VLBE_INLINE void vlbe__cr2d_to_glob(const vlbe__cr2d_fr *f, const vlbe_real *y, vlbe_real *x)
{
    int k;
    for (k = 0; k < 2; ++k) {
        const vlbe_real a = y[3 * k], b = y[3 * k + 1], c = f->c[k], s = f->s[k];
        x[3 * k] = c * a - s * b;
        x[3 * k + 1] = s * a + c * b;
        x[3 * k + 2] = y[3 * k + 2];
    }
}

/* G += T^T A T (A local 6x6) */
VLBE_INLINE void vlbe__cr2d_congr(const vlbe__cr2d_fr *f, const vlbe_real *A, vlbe_real *G)
{
    vlbe_real B[VLBE_CR2D_NQ * VLBE_CR2D_NQ], col[VLBE_CR2D_NQ], out[VLBE_CR2D_NQ];
    int i, j;
    /* B = A T: row i of A T is r T = (T^T r^T)^T, r the row i of A */
    for (i = 0; i < VLBE_CR2D_NQ; ++i)
        vlbe__cr2d_to_glob(f, A + i * VLBE_CR2D_NQ, B + i * VLBE_CR2D_NQ);
    for (j = 0; j < VLBE_CR2D_NQ; ++j) {
        for (i = 0; i < VLBE_CR2D_NQ; ++i) col[i] = B[i * VLBE_CR2D_NQ + j];
        vlbe__cr2d_to_glob(f, col, out);
        for (i = 0; i < VLBE_CR2D_NQ; ++i) G[i * VLBE_CR2D_NQ + j] += out[i];
    }
}

/* K_ij += x_i gb_j with x = d(T^T f(T u_g))/db = T^T (Jf f + A Jt u): the
   part of a Jacobian that comes from the turning of the frame (A = df/du
   local, f the local force, u = T u_g the local rate or acceleration);
   per turning node d(T x)/db = Jt (T x), Jt: (u, v) -> (v, -u), and
   d(T^T y)/db = T^T Jf y, Jf: (u, v) -> (-v, u). */
VLBE_INLINE void vlbe__cr2d_frame_col(const vlbe__cr2d_fr *fr, const vlbe_real *f,
                                        const vlbe_real *A, const vlbe_real *u,
                                        const vlbe_real *gb, vlbe_real *K)
{
    vlbe_real ju[VLBE_CR2D_NQ], y[VLBE_CR2D_NQ], x[VLBE_CR2D_NQ];
    int i, j, k;
    for (k = 0; k < 2; ++k) {
        ju[3 * k] = fr->rot[k] ? u[3 * k + 1] : VLBE_R(0.0);
        ju[3 * k + 1] = fr->rot[k] ? -u[3 * k] : VLBE_R(0.0);
        ju[3 * k + 2] = VLBE_R(0.0);
    }
    for (i = 0; i < VLBE_CR2D_NQ; ++i) {
        vlbe_real t = VLBE_R(0.0);
        for (j = 0; j < VLBE_CR2D_NQ; ++j) t += A[i * VLBE_CR2D_NQ + j] * ju[j];
        y[i] = t;
    }
    for (k = 0; k < 2; ++k)
        if (fr->rot[k]) { /* Jf f */
            y[3 * k] -= f[3 * k + 1];
            y[3 * k + 1] += f[3 * k];
        }
    vlbe__cr2d_to_glob(fr, y, x);
    for (i = 0; i < VLBE_CR2D_NQ; ++i)
        for (j = 0; j < VLBE_CR2D_NQ; ++j) K[i * VLBE_CR2D_NQ + j] += x[i] * gb[j];
}

/* -- kinematics ---------------------------------------------------------- */
/* The element's current frame and deformation measures.  Conventional:
   chord x1 -> x2 of length l, theta_j = a0 + phi_j - b, the bending length
   L2 = L.  Transition (jt != NULL, section 2.5): node 1 inside the joint at
   the distance l1 from its exit C, the outside segment's chord C -> x2 of
   length l (= l2), theta = (theta3, theta2) with theta3 the angle of the
   joint axis against that chord (the slope at C, eq. 35), L1 + L2 = L the
   undeformed lengths inside and outside, eps = eps0 of eq. 24. */
typedef struct vlbe__cr2d_kin {
    vlbe__cr2d_fr fr;   /* the element frame at both nodes                  */
    vlbe_real c, s, l;  /* (outside) chord direction and length             */
    vlbe_real th[2];    /* deformation rotations                            */
    vlbe_real eps;      /* eps0 (eqs. 7, 24)                                */
    vlbe_real L2;       /* bending length                                   */
    vlbe_real gl[VLBE_CR2D_NQ], gb[VLBE_CR2D_NQ]; /* gradients of l and of the chord angle b      */
    vlbe_real gL2[VLBE_CR2D_NQ];   /* gradient of L2 (transition; else 0)              */
    /* transition only: y = (l1, l2, theta3, theta2), B = dy/dq (4 x 6), L1
       and its y-derivatives, eps_v (eq. 25) */
    int tr;
    vlbe_real l1, L1, ev;
    vlbe_real B[4][VLBE_CR2D_NQ], L1y[4], L1yy[16];
} vlbe__cr2d_kin;

VLBE_INLINE vlbe_status vlbe__cr2d_check(const vlbe_real *q, const vlbe_real *qd)
{
    if (!vlbe_all_finite(q, VLBE_CR2D_NQ)) return VLBE_ENONFINITE;
    if (qd && !vlbe_all_finite(qd, VLBE_CR2D_NQ)) return VLBE_ENONFINITE;
    return VLBE_OK;
}

/* Angle of the direction (ca, sa) against the chord (c, s), in (-pi, pi]. */
VLBE_INLINE vlbe_real vlbe__cr2d_rel_angle(vlbe_real ca, vlbe_real sa, vlbe_real c, vlbe_real s)
{
    return vlbe_atan2(sa * c - ca * s, ca * c + sa * s);
}

/* theta of node j: the cross-section tangent a0 + phi_j against the chord;
   sine and cosine only, so any number of accumulated turns is harmless */
VLBE_INLINE vlbe_real vlbe__cr2d_theta(const vlbe_cr2d_elem *el, vlbe_real ph, vlbe_real c,
                                         vlbe_real s)
{
    const vlbe_real cp = vlbe_cos(ph), sp = vlbe_sin(ph);
    return vlbe__cr2d_rel_angle(el->c0 * cp - el->s0 * sp, el->s0 * cp + el->c0 * sp, c, s);
}

/* gradients of the chord length and angle; both = 0: the chord starts at
   a fixed point */
VLBE_INLINE void vlbe__cr2d_chord_grad(vlbe__cr2d_kin *k, int both)
{
    int i;
    for (i = 0; i < VLBE_CR2D_NQ; ++i) k->gl[i] = k->gb[i] = k->gL2[i] = VLBE_R(0.0);
    k->gl[3] = k->c;
    k->gl[4] = k->s;
    k->gb[3] = -k->s / k->l;
    k->gb[4] = k->c / k->l;
    if (both) {
        k->gl[0] = -k->c;
        k->gl[1] = -k->s;
        k->gb[0] = k->s / k->l;
        k->gb[1] = -k->c / k->l;
    }
}

/* Conventional element; LINEAR: the frame stays at a0, theta_j = phi_j -
   (v2 - v1)/L and eps0 = (u2 - u1)/L in it. */
VLBE_INLINE vlbe_status vlbe__cr2d_kin_eval(const vlbe_cr2d_elem *el, int lin, int frame_only,
                                              const vlbe_real *q, vlbe__cr2d_kin *k)
{
    const vlbe_real L = el->L;
    int j;
    k->tr = 0;
    k->L2 = L;
    if (lin) {
        vlbe_real u[VLBE_CR2D_NQ];
        vlbe__cr2d_fr_set(&k->fr, el->c0, el->s0, 0, el->c0, el->s0, 0);
        vlbe__cr2d_to_loc(&k->fr, q, u);
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
        vlbe__cr2d_fr_set(&k->fr, k->c, k->s, 1, k->c, k->s, 1);
        for (j = 0; j < 2; ++j)
            k->th[j] = frame_only ? VLBE_R(0.0) : vlbe__cr2d_theta(el, q[2 + 3 * j], k->c, k->s);
        k->eps = (l - L) / L + (VLBE_R(4.0) * k->th[0] * k->th[0] -
                                VLBE_R(2.0) * k->th[0] * k->th[1] +
                                VLBE_R(4.0) * k->th[1] * k->th[1]) /
                                   VLBE_R(60.0);
    }
    vlbe__cr2d_chord_grad(k, 1);
    return VLBE_OK;
}

/* Transition element (section 2.5).  Node 1 must be inside the joint or
   at its exit (l1 = a.(C - x1) >= 0) and node 2 outside (a.(x2 - C) > 0).
   The formulas continue smoothly to l1 < 0 (L1 < 0: node 1 just outside),
   which Newton iterates and the step in which node 1 leaves need; beyond
   l1 < -L/2 it is VLBE_EBOUND.  The undeformed lengths follow from the uniform
   extension (eq. 24) without the first-order expansion of eq. 26:
   l1/L1 = l2/L2 + eps_v with L1 + L2 = L and eps_v = (4 theta3^2 - 2 theta3
   theta2 + 4 theta2^2)/60 (eq. 25 with the Hermite v), i.e. the smaller
   root of F(L1) = eps_v L1^2 - (l1 + l2 + eps_v L) L1 + l1 L = 0, taken as
   2 l1 L / (P + sqrt(P^2 - 4 eps_v l1 L)), P = l1 + l2 + eps_v L (no
   cancellation; L1 = 0 exactly when l1 = 0: then the element is the
   conventional one with theta1 = theta3).  Its y-derivatives by implicit
   differentiation of F (linear in w = (l1, l2, eps_v) at fixed L1). */
VLBE_INLINE vlbe_status vlbe__cr2d_kin_tr(const vlbe_cr2d_elem *el, const vlbe_cr2d_joint *jt,
                                            const vlbe_real *q, vlbe__cr2d_kin *k)
{
    const vlbe_real L = el->L, ax = jt->a[0], ay = jt->a[1];
    const vlbe_real x1 = el->X[0] + q[0] - jt->C[0], y1 = el->X[1] + q[1] - jt->C[1];
    const vlbe_real dx = el->X[2] + q[3] - jt->C[0], dy = el->X[3] + q[4] - jt->C[1];
    const vlbe_real l1 = -(ax * x1 + ay * y1);
    vlbe_real l, P, disc, FL, Fw[3], Lw[3], FLw[3], Lww[3][3], et[2], wy[3][4];
    int i, j, a, b;
    if (!(vlbe_fabs(ax * ax + ay * ay - VLBE_R(1.0)) <= VLBE_R(64.0) * VLBE_EPS) ||
        !vlbe_all_finite(jt->C, 2))
        return VLBE_EARG;
    l = vlbe_sqrt(dx * dx + dy * dy);
    if (!(l1 >= -VLBE_R(0.5) * L) || !(ax * dx + ay * dy > VLBE_R(0.0)) ||
        !(l > VLBE_R(1e-6) * L))
        return VLBE_EBOUND;
    k->tr = 1;
    k->l1 = l1;
    k->l = l;
    k->c = dx / l;
    k->s = dy / l;
    vlbe__cr2d_fr_set(&k->fr, ax, ay, 0, k->c, k->s, 1);
    k->th[0] = vlbe__cr2d_rel_angle(ax, ay, k->c, k->s);
    k->th[1] = vlbe__cr2d_theta(el, q[5], k->c, k->s);
    k->ev = (VLBE_R(4.0) * k->th[0] * k->th[0] - VLBE_R(2.0) * k->th[0] * k->th[1] +
             VLBE_R(4.0) * k->th[1] * k->th[1]) /
            VLBE_R(60.0);
    P = l1 + l + k->ev * L;
    disc = P * P - VLBE_R(4.0) * k->ev * l1 * L;
    if (!(disc >= VLBE_R(0.0))) return VLBE_ESINGULAR;
    k->L1 = VLBE_R(2.0) * l1 * L / (P + vlbe_sqrt(disc));
    k->L2 = L - k->L1;
    if (!(k->L2 > VLBE_R(1e-6) * L)) return VLBE_EBOUND;
    k->eps = l / k->L2 + k->ev - VLBE_R(1.0);
    /* dL1/dw = -F_w / F_L1, d2L1/dw2 = -(2 eps_v L1_w L1_w^T + F_L1w L1_w^T
       + L1_w F_L1w^T) / F_L1 */
    FL = VLBE_R(2.0) * k->ev * k->L1 - P;
    Fw[0] = k->L2;
    Fw[1] = -k->L1;
    Fw[2] = -k->L1 * k->L2;
    FLw[0] = FLw[1] = -VLBE_R(1.0);
    FLw[2] = VLBE_R(2.0) * k->L1 - L;
    for (a = 0; a < 3; ++a) Lw[a] = -Fw[a] / FL;
    for (a = 0; a < 3; ++a)
        for (b = 0; b < 3; ++b)
            Lww[a][b] = -(VLBE_R(2.0) * k->ev * Lw[a] * Lw[b] + FLw[a] * Lw[b] + Lw[a] * FLw[b]) / FL;
    et[0] = (VLBE_R(8.0) * k->th[0] - VLBE_R(2.0) * k->th[1]) / VLBE_R(60.0);
    et[1] = (VLBE_R(8.0) * k->th[1] - VLBE_R(2.0) * k->th[0]) / VLBE_R(60.0);
    for (a = 0; a < 3; ++a)
        for (i = 0; i < 4; ++i) wy[a][i] = VLBE_R(0.0);
    wy[0][0] = wy[1][1] = VLBE_R(1.0);
    wy[2][2] = et[0];
    wy[2][3] = et[1];
    for (i = 0; i < 4; ++i) {
        k->L1y[i] = Lw[0] * wy[0][i] + Lw[1] * wy[1][i] + Lw[2] * wy[2][i];
        for (j = 0; j < 4; ++j) {
            vlbe_real v = VLBE_R(0.0);
            for (a = 0; a < 3; ++a)
                for (b = 0; b < 3; ++b) v += wy[a][i] * Lww[a][b] * wy[b][j];
            k->L1yy[i * 4 + j] = v;
        }
    }
    /* + L1_eps_v d2 eps_v/dtheta2, d2 eps_v/dtheta2 = [[8, -2], [-2, 8]]/60 */
    k->L1yy[2 * 4 + 2] += Lw[2] * VLBE_R(8.0) / VLBE_R(60.0);
    k->L1yy[3 * 4 + 3] += Lw[2] * VLBE_R(8.0) / VLBE_R(60.0);
    k->L1yy[2 * 4 + 3] -= Lw[2] * VLBE_R(2.0) / VLBE_R(60.0);
    k->L1yy[3 * 4 + 2] -= Lw[2] * VLBE_R(2.0) / VLBE_R(60.0);
    vlbe__cr2d_chord_grad(k, 0);
    for (i = 0; i < VLBE_CR2D_NQ; ++i) {
        k->B[0][i] = VLBE_R(0.0);
        k->B[1][i] = k->gl[i];
        k->B[2][i] = -k->gb[i];
        k->B[3][i] = -k->gb[i];
    }
    k->B[0][0] = -ax;
    k->B[0][1] = -ay;
    k->B[3][5] = VLBE_R(1.0);
    for (i = 0; i < VLBE_CR2D_NQ; ++i) {
        vlbe_real v = VLBE_R(0.0);
        for (a = 0; a < 4; ++a) v -= k->L1y[a] * k->B[a][i];
        k->gL2[i] = v;
    }
    return VLBE_OK;
}

/* K += B^T H B for nl local variables with gradient rows B (nl x 6) and
   local Hessian H (nl x nl). */
VLBE_INLINE void vlbe__cr2d_bthb(int nl, const vlbe_real *B, const vlbe_real *H, vlbe_real *K)
{
    int i, j, a, b;
    for (a = 0; a < nl; ++a)
        for (b = 0; b < nl; ++b) {
            const vlbe_real h = H[a * nl + b];
            if (h == VLBE_R(0.0)) continue;
            for (i = 0; i < VLBE_CR2D_NQ; ++i) {
                const vlbe_real hb = h * B[a * VLBE_CR2D_NQ + i];
                for (j = 0; j < VLBE_CR2D_NQ; ++j)
                    K[i * VLBE_CR2D_NQ + j] += hb * B[b * VLBE_CR2D_NQ + j];
            }
        }
}

/* K += gl d2l/dq2 + gt d2(-b)/dq2 for a chord d = x2 - x1 of length l,
   direction (c, s), angle b: d2l/dd2 = e2 e2^T / l, d2b/dd2 = -(e1 e2^T +
   e2 e1^T) / l^2 (e1 e2^T + e2 e1^T = [[-2cs, c^2 - s^2], [c^2 - s^2,
   2cs]]); gt is the sum of the forces on the angles theta = ... - b.
   both = 0: the chord starts at a fixed point (only the x2 block). */
VLBE_INLINE void vlbe__cr2d_chord_hess(vlbe_real c, vlbe_real s, vlbe_real l, vlbe_real gl,
                                         vlbe_real gt, int both, vlbe_real *K)
{
    vlbe_real P[2][2];
    const vlbe_real l2 = l * l;
    int a, b;
    P[0][0] = gl * s * s / l - gt * VLBE_R(2.0) * c * s / l2;
    P[0][1] = P[1][0] = -gl * c * s / l + gt * (c * c - s * s) / l2;
    P[1][1] = gl * c * c / l + gt * VLBE_R(2.0) * c * s / l2;
    for (a = 0; a < 2; ++a)
        for (b = 0; b < 2; ++b) {
            K[(3 + a) * VLBE_CR2D_NQ + 3 + b] += P[a][b];
            if (both) {
                K[a * VLBE_CR2D_NQ + b] += P[a][b];
                K[a * VLBE_CR2D_NQ + 3 + b] -= P[a][b];
                K[(3 + a) * VLBE_CR2D_NQ + b] -= P[a][b];
            }
        }
}

/* -- deformation force (nonlinear): F = grad U, K = Hess U --------------- */
VLBE_INLINE void vlbe__cr2d_elastic(const vlbe_cr2d_elem *el, const vlbe__cr2d_kin *k,
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
    vlbe_real B[3][VLBE_CR2D_NQ];
    int i;
    for (i = 0; i < VLBE_CR2D_NQ; ++i) {
        B[0][i] = k->gl[i];
        B[1][i] = -k->gb[i];
        B[2][i] = -k->gb[i];
    }
    B[1][2] += VLBE_R(1.0);
    B[2][5] += VLBE_R(1.0);
    for (i = 0; i < VLBE_CR2D_NQ; ++i) F[i] += gl * B[0][i] + g1 * B[1][i] + g2 * B[2][i];
    if (!K) return;
    {
        /* Hessian in (l, theta1, theta2) (eq. 21 plus the terms it drops) */
        const vlbe_real kg = EA * L * eps / VLBE_R(30.0), kb = EI / L;
        vlbe_real H[9];
        H[0] = EA / L;
        H[1] = H[3] = EA * a1;
        H[2] = H[6] = EA * a2;
        H[4] = EA * L * a1 * a1 + VLBE_R(4.0) * kg + VLBE_R(4.0) * kb;
        H[8] = EA * L * a2 * a2 + VLBE_R(4.0) * kg + VLBE_R(4.0) * kb;
        H[5] = H[7] = EA * L * a1 * a2 - kg + VLBE_R(2.0) * kb;
        vlbe__cr2d_bthb(3, &B[0][0], H, K);
        vlbe__cr2d_chord_hess(k->c, k->s, k->l, gl, g1 + g2, 1, K);
    }
}

/* Transition element: U = EA L eps0^2/2 + EI (2 theta3^2 + 2 theta3 theta2 +
   2 theta2^2)/L2 with eps0 = l2/L2 + eps_v - 1 (eqs. 24-27, 38-39: the
   inside segment is straight), derivatives in y = (l1, l2, theta3,
   theta2) through L2 = L - L1(y), then F = B^T U_y and K = B^T U_yy B +
   the turning of the outside chord (eqs. 43-44, 48: the paper's k_a, k_b
   plus the terms of the consistent linearization it drops). */
VLBE_INLINE void vlbe__cr2d_elastic_tr(const vlbe_cr2d_elem *el, const vlbe__cr2d_kin *k,
                                         vlbe_real *F, vlbe_real *K)
{
    const vlbe_real L = el->L, EA = el->mat.EA, EI = el->mat.EI, L2 = k->L2, l2 = k->l;
    const vlbe_real t3 = k->th[0], t2 = k->th[1], eps = k->eps, iL = VLBE_R(1.0) / L2;
    const vlbe_real Bt = VLBE_R(2.0) * (t3 * t3 + t3 * t2 + t2 * t2);
    vlbe_real iLy[4], ey[4], By[4], Uy[4];
    int i, j;
    By[0] = By[1] = VLBE_R(0.0);
    By[2] = VLBE_R(4.0) * t3 + VLBE_R(2.0) * t2;
    By[3] = VLBE_R(2.0) * t3 + VLBE_R(4.0) * t2;
    for (i = 0; i < 4; ++i) {
        iLy[i] = k->L1y[i] * iL * iL; /* d(1/L2)/dy, dL2 = -dL1 */
        ey[i] = l2 * iLy[i];
    }
    ey[1] += iL;
    ey[2] += (VLBE_R(8.0) * t3 - VLBE_R(2.0) * t2) / VLBE_R(60.0);
    ey[3] += (VLBE_R(8.0) * t2 - VLBE_R(2.0) * t3) / VLBE_R(60.0);
    for (i = 0; i < 4; ++i) Uy[i] = EA * L * eps * ey[i] + EI * (By[i] * iL + Bt * iLy[i]);
    for (i = 0; i < VLBE_CR2D_NQ; ++i)
        F[i] += Uy[0] * k->B[0][i] + Uy[1] * k->B[1][i] + Uy[2] * k->B[2][i] +
                Uy[3] * k->B[3][i];
    if (!K) return;
    {
        static const signed char evyy[2][2] = {{8, -2}, {-2, 8}}, byy[2][2] = {{4, 2}, {2, 4}};
        vlbe_real H[16];
        for (i = 0; i < 4; ++i)
            for (j = 0; j < 4; ++j) {
                /* d2(1/L2) = 2 L1_y L1_y^T / L2^3 + L1_yy / L2^2 */
                const vlbe_real iLyy =
                    VLBE_R(2.0) * k->L1y[i] * k->L1y[j] * iL * iL * iL + k->L1yy[i * 4 + j] * iL * iL;
                vlbe_real eyy = l2 * iLyy + (i == 1 ? iLy[j] : VLBE_R(0.0)) +
                                (j == 1 ? iLy[i] : VLBE_R(0.0));
                vlbe_real b2 = VLBE_R(0.0);
                if (i >= 2 && j >= 2) {
                    eyy += (vlbe_real)evyy[i - 2][j - 2] / VLBE_R(60.0);
                    b2 = (vlbe_real)byy[i - 2][j - 2];
                }
                H[i * 4 + j] = EA * L * (ey[i] * ey[j] + eps * eyy) +
                               EI * (b2 * iL + By[i] * iLy[j] + iLy[i] * By[j] + Bt * iLyy);
            }
        vlbe__cr2d_bthb(4, &k->B[0][0], H, K);
        vlbe__cr2d_chord_hess(k->c, k->s, l2, Uy[1], Uy[2] + Uy[3], 0, K);
    }
}

/* -- nonlinear inertia (eqs. 18-19, 45-46) ------------------------------ */
/* The velocity terms of the inertia force in the element frame, for a
   bending segment of length L2 at the outer end of an element of length
   L (L1 = L - L2 inside a joint; a conventional element has L2 = L).
   u: local rates (u1, v1, phi1, u2, v2, phi2), the segment's slope rate
   v'_t = N'_b (v1, phi1, v2, phi2) over L2 (the transition element passes
   v1 = phi1 = 0: the joint holds them).  With xi = x/L2,
   v'_t = c0 + c1 xi + c2 xi^2 and p = v'_t^2 = sum p_k xi^k,
        f_a1 = rhoA (W L/6 - (1 - L1/L) I0 + I1/L),
        f_a2 = rhoA (W L/3 - (L1/L) I0 - I1/L),
   W = int_0^L2 v'_t^2 = L2 sum p_k/(k+1), I0 = int_0^L2 int_0^x v'_t^2 =
   L2^2 sum p_k/((k+1)(k+2)), I1 = int_0^L2 x int_0^x v'_t^2 = L2^3 sum
   p_k/((k+1)(k+3)) (eq. 45; eq. 18 for L1 = 0), and f_b = -2 rhoI
   ((u2' - u1')/L) G_b(L2) u_b (eqs. 19, 46).  f = f_a + f_b (6), A =
   df/du (6x6); fL (may be NULL) = df/dL2 at fixed u. */
VLBE_INLINE void vlbe__cr2d_nli(const vlbe_cr2d_elem *el, vlbe_real L2, const vlbe_real *u,
                                  vlbe_real *f, vlbe_real *A, vlbe_real *fL)
{
    const vlbe_real L = el->L, L1 = L - L2, rA = el->mat.rhoA, rI = el->mat.rhoI;
    const vlbe_real w = (u[4] - u[1]) / L2, ed = (u[3] - u[0]) / L;
    const int *ib = vlbe__cr2d_ib;
    vlbe_real cc[3], dcL[3], dc[3][VLBE_CR2D_NQ], Q[2][3][3], QL[2][3][3], Qc[2][3];
    vlbe_real Gb[16], GL[16], gu[4], gL[4], ub[4];
    int r, i, j, k;
    cc[0] = u[2];
    cc[1] = -VLBE_R(4.0) * u[2] - VLBE_R(2.0) * u[5] + VLBE_R(6.0) * w;
    cc[2] = VLBE_R(3.0) * u[2] + VLBE_R(3.0) * u[5] - VLBE_R(6.0) * w;
    dcL[0] = VLBE_R(0.0);
    dcL[1] = -VLBE_R(6.0) * w / L2;
    dcL[2] = VLBE_R(6.0) * w / L2;
    for (r = 0; r < 2; ++r) {
        vlbe_real g[5], gd[5];
        for (k = 0; k < 5; ++k) {
            const vlbe_real k1 = (vlbe_real)(k + 1), k2 = k1 + VLBE_R(1.0), k3 = k1 + VLBE_R(2.0);
            const vlbe_real a0 = r == 0 ? VLBE_R(1.0) - L1 / L : L1 / L;
            const vlbe_real sg = r == 0 ? VLBE_R(1.0) : -VLBE_R(1.0);
            const vlbe_real wl = r == 0 ? L / VLBE_R(6.0) : L / VLBE_R(3.0);
            /* gamma_k: the coefficient of p_k, and its L2-derivative
               (d(1 - L1/L)/dL2 = 1/L, d(L1/L)/dL2 = -1/L) */
            g[k] = (wl * L2 - a0 * L2 * L2 / k2 + sg * L2 * L2 * L2 / (L * k3)) / k1;
            gd[k] = (wl - (sg * L2 * L2 / L + a0 * VLBE_R(2.0) * L2) / k2 +
                     sg * VLBE_R(3.0) * L2 * L2 / (L * k3)) /
                    k1;
        }
        /* p0 = c0^2, p1 = 2 c0 c1, p2 = c1^2 + 2 c0 c2, p3 = 2 c1 c2, p4 = c2^2 */
        Q[r][0][0] = g[0];
        Q[r][0][1] = Q[r][1][0] = g[1];
        Q[r][1][1] = Q[r][0][2] = Q[r][2][0] = g[2];
        Q[r][1][2] = Q[r][2][1] = g[3];
        Q[r][2][2] = g[4];
        QL[r][0][0] = gd[0];
        QL[r][0][1] = QL[r][1][0] = gd[1];
        QL[r][1][1] = QL[r][0][2] = QL[r][2][0] = gd[2];
        QL[r][1][2] = QL[r][2][1] = gd[3];
        QL[r][2][2] = gd[4];
        for (i = 0; i < 3; ++i)
            Qc[r][i] = rA * (Q[r][i][0] * cc[0] + Q[r][i][1] * cc[1] + Q[r][i][2] * cc[2]);
    }
    for (i = 0; i < VLBE_CR2D_NQ; ++i) f[i] = VLBE_R(0.0);
    f[0] = cc[0] * Qc[0][0] + cc[1] * Qc[0][1] + cc[2] * Qc[0][2];
    f[3] = cc[0] * Qc[1][0] + cc[1] * Qc[1][1] + cc[2] * Qc[1][2];
    ub[0] = u[1];
    ub[1] = u[2];
    ub[2] = u[4];
    ub[3] = u[5];
    vlbe__cr2d_gb(L2, Gb, fL ? GL : NULL);
    for (i = 0; i < 4; ++i) {
        gu[i] = VLBE_R(0.0);
        for (j = 0; j < 4; ++j) gu[i] += Gb[i * 4 + j] * ub[j];
        f[ib[i]] = -VLBE_R(2.0) * rI * ed * gu[i];
    }
    if (fL) {
        for (i = 0; i < VLBE_CR2D_NQ; ++i) fL[i] = VLBE_R(0.0);
        for (r = 0; r < 2; ++r) {
            vlbe_real t = VLBE_R(0.0);
            for (i = 0; i < 3; ++i) {
                t += VLBE_R(2.0) * Qc[r][i] * dcL[i];
                for (j = 0; j < 3; ++j) t += rA * cc[i] * QL[r][i][j] * cc[j];
            }
            fL[3 * r] = t;
        }
        for (i = 0; i < 4; ++i) {
            gL[i] = VLBE_R(0.0);
            for (j = 0; j < 4; ++j) gL[i] += GL[i * 4 + j] * ub[j];
            fL[ib[i]] = -VLBE_R(2.0) * rI * ed * gL[i];
        }
    }
    if (!A) return;
    for (i = 0; i < VLBE_CR2D_NQ * VLBE_CR2D_NQ; ++i) A[i] = VLBE_R(0.0);
    for (i = 0; i < 3; ++i)
        for (j = 0; j < VLBE_CR2D_NQ; ++j) dc[i][j] = VLBE_R(0.0);
    dc[0][2] = VLBE_R(1.0);
    dc[1][1] = -VLBE_R(6.0) / L2;
    dc[1][2] = -VLBE_R(4.0);
    dc[1][4] = VLBE_R(6.0) / L2;
    dc[1][5] = -VLBE_R(2.0);
    dc[2][1] = VLBE_R(6.0) / L2;
    dc[2][2] = VLBE_R(3.0);
    dc[2][4] = -VLBE_R(6.0) / L2;
    dc[2][5] = VLBE_R(3.0);
    for (r = 0; r < 2; ++r)
        for (j = 0; j < VLBE_CR2D_NQ; ++j)
            A[3 * r * VLBE_CR2D_NQ + j] = VLBE_R(2.0) * (Qc[r][0] * dc[0][j] + Qc[r][1] * dc[1][j] +
                                              Qc[r][2] * dc[2][j]);
    for (i = 0; i < 4; ++i) {
        A[ib[i] * VLBE_CR2D_NQ + 0] += VLBE_R(2.0) * rI * gu[i] / L;
        A[ib[i] * VLBE_CR2D_NQ + 3] -= VLBE_R(2.0) * rI * gu[i] / L;
        for (j = 0; j < 4; ++j)
            A[ib[i] * VLBE_CR2D_NQ + ib[j]] -= VLBE_R(2.0) * rI * ed * Gb[i * 4 + j];
    }
}

/* The element's kinematics: conventional (jt NULL) or transition. */
VLBE_INLINE vlbe_status vlbe__cr2d_kin_any(const vlbe_cr2d_elem *el, const vlbe_cr2d_joint *jt,
                                             unsigned mode, const vlbe_real *q, const vlbe_real *qd,
                                             vlbe__cr2d_kin *k)
{
    vlbe_status st;
    VLBE_ASSERT(el != NULL && q != NULL);
    if ((st = vlbe__cr2d_check(q, qd)) != VLBE_OK) return st;
    if (!jt)
        return vlbe__cr2d_kin_eval(el, (mode & VLBE_CR2D_LINEAR) != 0,
                                   (mode & VLBE__CR2D_FRAME_ONLY) != 0, q, k);
    if (mode & VLBE_CR2D_LINEAR) return VLBE_EARG; /* no linear transition element */
    return vlbe__cr2d_kin_tr(el, jt, q, k);
}

/* Local rates u = T q'; the transition element has no node-1 lateral or
   rotation coordinate (the joint holds them). */
VLBE_INLINE void vlbe__cr2d_rates(const vlbe__cr2d_kin *k, const vlbe_real *qd, vlbe_real *u)
{
    vlbe__cr2d_to_loc(&k->fr, qd, u);
    if (k->tr) u[1] = u[2] = VLBE_R(0.0);
}

/* Q, K, D into the caller's zeroed locals (F = -Q accumulated, negated at
   the end) */
VLBE_INLINE void vlbe__cr2d_forces(const vlbe_cr2d_elem *el, unsigned mode,
                                     const vlbe__cr2d_kin *k, const vlbe_real *q,
                                     const vlbe_real *qd, vlbe_real *F, vlbe_real *K, vlbe_real *D)
{
    const int lin = (mode & VLBE_CR2D_LINEAR) != 0;
    const int nli = !lin && !(mode & VLBE_CR2D_NO_NLI);
    const int damp = !(mode & VLBE_CR2D_NO_DAMP) &&
                     (el->mat.ray_a != VLBE_R(0.0) || el->mat.ray_b != VLBE_R(0.0));
    int i, j;
    if (lin) {
        vlbe_real k0[VLBE_CR2D_NQ * VLBE_CR2D_NQ], u[VLBE_CR2D_NQ], f[VLBE_CR2D_NQ],
            g[VLBE_CR2D_NQ];
        vlbe__cr2d_lmat(el, 0, el->L, NULL, k0, NULL, NULL);
        vlbe__cr2d_to_loc(&k->fr, q, u);
        vlbe_mat_vec(VLBE_CR2D_NQ, VLBE_CR2D_NQ, k0, u, f);
        vlbe__cr2d_to_glob(&k->fr, f, g);
        for (i = 0; i < VLBE_CR2D_NQ; ++i) F[i] += g[i];
        if (K) vlbe__cr2d_congr(&k->fr, k0, K);
    } else if (k->tr)
        vlbe__cr2d_elastic_tr(el, k, F, K);
    else
        vlbe__cr2d_elastic(el, k, F, K);
    if (nli || damp) {
        /* local rate u = T q', local force f = f_nl(u) + C u, A = df/du,
           fL = df/dL2 (transition: L2 depends on q) */
        vlbe_real u[VLBE_CR2D_NQ], f[VLBE_CR2D_NQ], A[VLBE_CR2D_NQ * VLBE_CR2D_NQ],
            fL[VLBE_CR2D_NQ], g[VLBE_CR2D_NQ];
        vlbe__cr2d_rates(k, qd, u);
        for (i = 0; i < VLBE_CR2D_NQ; ++i) f[i] = fL[i] = VLBE_R(0.0);
        for (i = 0; i < VLBE_CR2D_NQ * VLBE_CR2D_NQ; ++i) A[i] = VLBE_R(0.0);
        if (nli) vlbe__cr2d_nli(el, k->L2, u, f, A, k->tr ? fL : NULL);
        if (damp) { /* m, k0, then (transition) their L2-derivatives in the same pair */
            vlbe_real m[VLBE_CR2D_NQ * VLBE_CR2D_NQ], k0[VLBE_CR2D_NQ * VLBE_CR2D_NQ];
            vlbe__cr2d_lmat(el, k->tr, k->L2, m, k0, NULL, NULL);
            for (i = 0; i < VLBE_CR2D_NQ; ++i)
                for (j = 0; j < VLBE_CR2D_NQ; ++j) {
                    const int e = i * VLBE_CR2D_NQ + j;
                    const vlbe_real c = el->mat.ray_a * m[e] + el->mat.ray_b * k0[e];
                    f[i] += c * u[j];
                    A[e] += c;
                }
            if (k->tr) {
                vlbe__cr2d_lmat(el, 1, k->L2, NULL, NULL, m, k0);
                for (i = 0; i < VLBE_CR2D_NQ; ++i)
                    for (j = 0; j < VLBE_CR2D_NQ; ++j)
                        fL[i] += (el->mat.ray_a * m[i * VLBE_CR2D_NQ + j] + el->mat.ray_b * k0[i * VLBE_CR2D_NQ + j]) * u[j];
            }
        }
        if (k->tr) { /* eq. 46: f_b on v2, phi2 only; no node-1 lateral rates */
            f[1] = f[2] = fL[1] = fL[2] = VLBE_R(0.0);
            for (i = 0; i < VLBE_CR2D_NQ; ++i)
                A[1 * VLBE_CR2D_NQ + i] = A[2 * VLBE_CR2D_NQ + i] = A[i * VLBE_CR2D_NQ + 1] =
                    A[i * VLBE_CR2D_NQ + 2] = VLBE_R(0.0);
        }
        vlbe__cr2d_to_glob(&k->fr, f, g);
        for (i = 0; i < VLBE_CR2D_NQ; ++i) F[i] += g[i];
        if (D) vlbe__cr2d_congr(&k->fr, A, D);
        if (K && !lin) {
            vlbe__cr2d_frame_col(&k->fr, f, A, u, k->gb, K);
            if (k->tr) {
                vlbe__cr2d_to_glob(&k->fr, fL, g);
                for (i = 0; i < VLBE_CR2D_NQ; ++i)
                    for (j = 0; j < VLBE_CR2D_NQ; ++j) K[i * VLBE_CR2D_NQ + j] += g[i] * k->gL2[j];
            }
        }
    }
}

/* -- the floating frame of a LINEAR element ------------------------------ */
/* fth = (theta, theta') of the floating frame; d = the element's
   coordinates measured in it: per node R^T(theta) (X + u) - X, written
   R^T(theta) u + (R^T(theta) - I) X with cos theta - 1 = -2 sin^2(theta/2)
   (no cancellation; theta = 0 gives d = q exactly), and phi - theta;
   dd (optional, with qd) its rate R^T(theta) (u' + theta' J (X + u)), J:
   (x, y) -> (y, -x), and phi' - theta'.  fr receives the rotation
   T = blockdiag(R^T(theta), 1) of both nodes (to_loc applies T). */
VLBE_INLINE vlbe_status vlbe__cr2d_float(const vlbe_cr2d_elem *el, const vlbe_real *fth,
                                           const vlbe_real *q, const vlbe_real *qd,
                                           vlbe__cr2d_fr *fr, vlbe_real *d, vlbe_real *dd)
{
    const vlbe_real c = vlbe_cos(fth[0]), s = vlbe_sin(fth[0]);
    const vlbe_real sh = vlbe_sin(VLBE_R(0.5) * fth[0]), cm = -VLBE_R(2.0) * sh * sh;
    vlbe_real off[VLBE_CR2D_NQ], w[VLBE_CR2D_NQ];
    int k;
    if (!vlbe_all_finite(fth, 2)) return VLBE_ENONFINITE;
    if ((vlbe__cr2d_check(q, qd)) != VLBE_OK) return VLBE_ENONFINITE;
    vlbe__cr2d_fr_set(fr, c, s, 0, c, s, 0);
    vlbe__cr2d_to_loc(fr, q, d);
    for (k = 0; k < 2; ++k) {
        const vlbe_real X = el->X[2 * k], Y = el->X[2 * k + 1];
        off[3 * k] = cm * X + s * Y;
        off[3 * k + 1] = -s * X + cm * Y;
        d[3 * k] += off[3 * k];
        d[3 * k + 1] += off[3 * k + 1];
        d[3 * k + 2] -= fth[0];
        if (qd) {
            w[3 * k] = qd[3 * k] + fth[1] * (Y + q[3 * k + 1]);
            w[3 * k + 1] = qd[3 * k + 1] - fth[1] * (X + q[3 * k]);
            w[3 * k + 2] = qd[3 * k + 2] - fth[1];
        }
    }
    if (qd && dd) vlbe__cr2d_to_loc(fr, w, dd);
    return VLBE_OK;
}

VLBE_INLINE vlbe_status vlbe__cr2d_force_any(const vlbe_cr2d_elem *el,
                                               const vlbe_cr2d_joint *jt, unsigned mode,
                                               const vlbe_real *fth, const vlbe_real *q,
                                               const vlbe_real *qd, vlbe_real *VLBE_RESTRICT Q,
                                               vlbe_real *VLBE_RESTRICT K,
                                               vlbe_real *VLBE_RESTRICT D)
{
    vlbe_real FKD[VLBE_CR2D_NQ + 2 * VLBE_CR2D_NQ * VLBE_CR2D_NQ], d[VLBE_CR2D_NQ],
        dd[VLBE_CR2D_NQ];
    vlbe_real *const F = FKD, *const Kt = FKD + VLBE_CR2D_NQ,
                     *const Dt = FKD + VLBE_CR2D_NQ + VLBE_CR2D_NQ * VLBE_CR2D_NQ;
    vlbe__cr2d_fr fr;
    vlbe__cr2d_kin k;
    vlbe_status st;
    int i, j;
    VLBE_ASSERT(el != NULL && qd != NULL && Q != NULL);
    mode = (mode | el->flags) & ~VLBE__CR2D_FRAME_ONLY;
    /* the identity frame (read only with fth; set so that gcc -O3 sees
       fr defined on every path) */
    vlbe__cr2d_fr_set(&fr, VLBE_R(1.0), VLBE_R(0.0), 0, VLBE_R(1.0), VLBE_R(0.0), 0);
    if (fth) { /* floating frame: the element sees d, dd (LINEAR only) */
        if (jt || !(mode & VLBE_CR2D_LINEAR)) return VLBE_EARG;
        if ((st = vlbe__cr2d_float(el, fth, q, qd, &fr, d, dd)) != VLBE_OK) return st;
        q = d;
        qd = dd;
    }
    if ((st = vlbe__cr2d_kin_any(el, jt, mode, q, qd, &k)) != VLBE_OK) return st;
    for (i = 0; i < VLBE_CR2D_NQ; ++i) F[i] = VLBE_R(0.0);
    for (i = 0; i < VLBE_CR2D_NQ * VLBE_CR2D_NQ; ++i) Kt[i] = Dt[i] = VLBE_R(0.0);
    vlbe__cr2d_forces(el, mode, &k, q, qd, F, K ? Kt : NULL, D ? Dt : NULL);
    if (fth) {
        /* Q = -T^T F(d, dd), K = T^T K_d T + D J theta' (dd depends on q
           through theta' J u), D = T^T D_d T */
        vlbe_real G[VLBE_CR2D_NQ * VLBE_CR2D_NQ];
        vlbe__cr2d_to_glob(&fr, F, d);
        for (i = 0; i < VLBE_CR2D_NQ; ++i) F[i] = d[i];
        if (K || D) {
            for (i = 0; i < VLBE_CR2D_NQ * VLBE_CR2D_NQ; ++i) G[i] = VLBE_R(0.0);
            vlbe__cr2d_congr(&fr, Dt, G);
            for (i = 0; i < VLBE_CR2D_NQ * VLBE_CR2D_NQ; ++i) Dt[i] = G[i];
        }
        if (K) {
            for (i = 0; i < VLBE_CR2D_NQ * VLBE_CR2D_NQ; ++i) G[i] = VLBE_R(0.0);
            vlbe__cr2d_congr(&fr, Kt, G);
            for (i = 0; i < VLBE_CR2D_NQ; ++i)
                for (j = 0; j < 2; ++j) {
                    G[i * VLBE_CR2D_NQ + 3 * j] -= fth[1] * Dt[i * VLBE_CR2D_NQ + 3 * j + 1];
                    G[i * VLBE_CR2D_NQ + 3 * j + 1] += fth[1] * Dt[i * VLBE_CR2D_NQ + 3 * j];
                }
            for (i = 0; i < VLBE_CR2D_NQ * VLBE_CR2D_NQ; ++i) Kt[i] = G[i];
        }
    }
    /* finite input can overflow (huge rates, stiffness): nothing written.
       F, Kt, Dt are one buffer, scanned in one pass (Q only: F alone) */
    if (vlbe__fin_bits(FKD,
                       K || D ? VLBE_CR2D_NQ + 2 * VLBE_CR2D_NQ * VLBE_CR2D_NQ : VLBE_CR2D_NQ) &
        VLBE__BITS_SIGN)
        return VLBE_ENONFINITE;
    for (i = 0; i < VLBE_CR2D_NQ; ++i) Q[i] = -F[i];
    if (K)
        for (i = 0; i < VLBE_CR2D_NQ * VLBE_CR2D_NQ; ++i) K[i] = -Kt[i];
    if (D)
        for (i = 0; i < VLBE_CR2D_NQ * VLBE_CR2D_NQ; ++i) D[i] = -Dt[i];
    return VLBE_OK;
}

VLBE_INLINE vlbe_status vlbe__cr2d_mass_any(const vlbe_cr2d_elem *el, const vlbe_cr2d_joint *jt,
                                              unsigned mode, const vlbe_real *q,
                                              vlbe_real *VLBE_RESTRICT M)
{
    vlbe__cr2d_kin k;
    vlbe_real m[VLBE_CR2D_NQ * VLBE_CR2D_NQ];
    vlbe_status st;
    int i;
    VLBE_ASSERT(el != NULL && M != NULL);
    mode |= el->flags | VLBE__CR2D_FRAME_ONLY;
    if ((st = vlbe__cr2d_kin_any(el, jt, mode, q, NULL, &k)) != VLBE_OK) return st;
    /* finite q whose current positions X + q overflow give a NaN frame (the
       other outputs are scanned; the bound below holds for a rotation
       only): x - x is NaN exactly for NaN and Inf */
    if (!(k.fr.c[0] - k.fr.c[0] + k.fr.c[1] - k.fr.c[1] + k.fr.s[0] - k.fr.s[0] + k.fr.s[1] -
              k.fr.s[1] ==
          VLBE_R(0.0)))
        return VLBE_ENONFINITE;
    vlbe__cr2d_lmat(el, k.tr, k.L2, m, NULL, NULL, NULL);
    /* M = T^T m T, T a rotation per node: every entry and partial sum is at
       most 4 max |m|, so m bounded means M finite (checked before writing) */
    {   /* on the bits: |x| orders like its pattern with the sign cleared */
        const vlbe_real lim = VLBE_R(0.125) * VLBE_REAL_MAX;
        vlbe__bits bl, u, b = 0;
        memcpy(&bl, &lim, sizeof bl);
        for (i = 0; i < VLBE_CR2D_NQ * VLBE_CR2D_NQ; ++i) {
            memcpy(&u, &m[i], sizeof u);
            u &= VLBE__BITS_ABS;
            b = u > b ? u : b;
        }
        if (b > bl) return VLBE_ENONFINITE;
    }
    for (i = 0; i < VLBE_CR2D_NQ * VLBE_CR2D_NQ; ++i) M[i] = VLBE_R(0.0);
    vlbe__cr2d_congr(&k.fr, m, M);
    return VLBE_OK;
}

/* d(M a)/dq = d(T^T m T a)/dq: the turning frame, and (transition) the
   L2-dependence of m */
VLBE_INLINE vlbe_status vlbe__cr2d_mass_jac_any(const vlbe_cr2d_elem *el,
                                                  const vlbe_cr2d_joint *jt, unsigned mode,
                                                  const vlbe_real *q, const vlbe_real *a,
                                                  vlbe_real *VLBE_RESTRICT Mq)
{
    vlbe__cr2d_kin k;
    vlbe_real m[VLBE_CR2D_NQ * VLBE_CR2D_NQ], dm[VLBE_CR2D_NQ * VLBE_CR2D_NQ], u[VLBE_CR2D_NQ],
        f[VLBE_CR2D_NQ], g[VLBE_CR2D_NQ], J[VLBE_CR2D_NQ * VLBE_CR2D_NQ];
    vlbe_status st;
    int i, j;
    VLBE_ASSERT(el != NULL && a != NULL && Mq != NULL);
    mode |= el->flags | VLBE__CR2D_FRAME_ONLY;
    if ((st = vlbe__cr2d_kin_any(el, jt, mode, q, a, &k)) != VLBE_OK) return st;
    for (i = 0; i < VLBE_CR2D_NQ * VLBE_CR2D_NQ; ++i) J[i] = VLBE_R(0.0);
    if (!(mode & VLBE_CR2D_LINEAR)) { /* LINEAR: M constant, J = 0 */
        vlbe__cr2d_lmat(el, k.tr, k.L2, m, NULL, k.tr ? dm : NULL, NULL);
        vlbe__cr2d_to_loc(&k.fr, a, u);
        vlbe_mat_vec(VLBE_CR2D_NQ, VLBE_CR2D_NQ, m, u, f);
        vlbe__cr2d_frame_col(&k.fr, f, m, u, k.gb, J);
        if (k.tr) {
            vlbe_mat_vec(VLBE_CR2D_NQ, VLBE_CR2D_NQ, dm, u, f);
            vlbe__cr2d_to_glob(&k.fr, f, g);
            for (i = 0; i < VLBE_CR2D_NQ; ++i)
                for (j = 0; j < VLBE_CR2D_NQ; ++j) J[i * VLBE_CR2D_NQ + j] += g[i] * k.gL2[j];
        }
        if (!vlbe_all_finite(J, VLBE_CR2D_NQ * VLBE_CR2D_NQ)) return VLBE_ENONFINITE;
    }
    for (i = 0; i < VLBE_CR2D_NQ * VLBE_CR2D_NQ; ++i) Mq[i] = J[i];
    return VLBE_OK;
}

/* fth: floating frame (LINEAR): the strain energy of d, the kinetic energy
   of the global rates q' */
VLBE_INLINE vlbe_status vlbe__cr2d_energy_any(const vlbe_cr2d_elem *el,
                                                const vlbe_cr2d_joint *jt, unsigned mode,
                                                const vlbe_real *fth, const vlbe_real *q,
                                                const vlbe_real *qd, vlbe_real *VLBE_RESTRICT E)
{
    vlbe__cr2d_kin k;
    vlbe__cr2d_fr fr;
    vlbe_real m[VLBE_CR2D_NQ * VLBE_CR2D_NQ], u[VLBE_CR2D_NQ], mu[VLBE_CR2D_NQ], d[VLBE_CR2D_NQ], T,
        U;
    vlbe_status st;
    VLBE_ASSERT(el != NULL && qd != NULL && E != NULL);
    mode = (mode | el->flags) & ~VLBE__CR2D_FRAME_ONLY;
    if (fth) {
        if (jt || !(mode & VLBE_CR2D_LINEAR)) return VLBE_EARG;
        if ((st = vlbe__cr2d_float(el, fth, q, qd, &fr, d, NULL)) != VLBE_OK) return st;
        q = d;
    }
    if ((st = vlbe__cr2d_kin_any(el, jt, mode, q, qd, &k)) != VLBE_OK) return st;
    vlbe__cr2d_lmat(el, k.tr, k.L2, m, NULL, NULL, NULL);
    vlbe__cr2d_rates(&k, qd, u);
    vlbe_mat_vec(VLBE_CR2D_NQ, VLBE_CR2D_NQ, m, u, mu);
    T = VLBE_R(0.5) * vlbe_vec_dot(VLBE_CR2D_NQ, u, mu);
    /* LINEAR: k.eps, k.th are the linear measures, and U = q^T K0 q / 2 has
       the same form without the quadratic part of eps0 */
    U = VLBE_R(0.5) * el->mat.EA * el->L * k.eps * k.eps +
        el->mat.EI / k.L2 * VLBE_R(2.0) *
            (k.th[0] * k.th[0] + k.th[0] * k.th[1] + k.th[1] * k.th[1]);
    if (!isfinite(T) || !isfinite(U)) return VLBE_ENONFINITE;
    E[0] = T;
    E[1] = U;
    return VLBE_OK;
}

VLBE_API vlbe_status vlbe_cr2d_force(const vlbe_cr2d_elem *el, unsigned mode, const vlbe_real *q,
                                     const vlbe_real *qd, vlbe_real *VLBE_RESTRICT Q,
                                     vlbe_real *VLBE_RESTRICT K, vlbe_real *VLBE_RESTRICT D)
{
    return vlbe__cr2d_force_any(el, NULL, mode, NULL, q, qd, Q, K, D);
}

VLBE_API vlbe_status vlbe_cr2d_mass(const vlbe_cr2d_elem *el, unsigned mode, const vlbe_real *q,
                                    vlbe_real *VLBE_RESTRICT M)
{
    return vlbe__cr2d_mass_any(el, NULL, mode, q, M);
}

VLBE_API vlbe_status vlbe_cr2d_mass_jac(const vlbe_cr2d_elem *el, unsigned mode,
                                        const vlbe_real *q, const vlbe_real *a,
                                        vlbe_real *VLBE_RESTRICT Mq)
{
    return vlbe__cr2d_mass_jac_any(el, NULL, mode, q, a, Mq);
}

VLBE_API vlbe_status vlbe_cr2d_energy(const vlbe_cr2d_elem *el, unsigned mode, const vlbe_real *q,
                                      const vlbe_real *qd, vlbe_real *VLBE_RESTRICT E)
{
    return vlbe__cr2d_energy_any(el, NULL, mode, NULL, q, qd, E);
}

VLBE_API vlbe_status vlbe_cr2d_local(const vlbe_cr2d_elem *el, unsigned mode, const vlbe_real *q,
                                     vlbe_real *VLBE_RESTRICT loc)
{
    return vlbe_cr2d_local_ff(el, mode, NULL, q, loc);
}

VLBE_API vlbe_status vlbe_cr2d_force_ff(const vlbe_cr2d_elem *el, unsigned mode,
                                        const vlbe_real *fth, const vlbe_real *q,
                                        const vlbe_real *qd, vlbe_real *VLBE_RESTRICT Q,
                                        vlbe_real *VLBE_RESTRICT K, vlbe_real *VLBE_RESTRICT D)
{
    VLBE_ASSERT(fth != NULL);
    return vlbe__cr2d_force_any(el, NULL, mode, fth, q, qd, Q, K, D);
}

VLBE_API vlbe_status vlbe_cr2d_energy_ff(const vlbe_cr2d_elem *el, unsigned mode,
                                         const vlbe_real *fth, const vlbe_real *q,
                                         const vlbe_real *qd, vlbe_real *VLBE_RESTRICT E)
{
    VLBE_ASSERT(fth != NULL);
    return vlbe__cr2d_energy_any(el, NULL, mode, fth, q, qd, E);
}

VLBE_API vlbe_status vlbe_cr2d_local_ff(const vlbe_cr2d_elem *el, unsigned mode,
                                        const vlbe_real *fth, const vlbe_real *q,
                                        vlbe_real *VLBE_RESTRICT loc)
{
    vlbe__cr2d_kin k;
    vlbe__cr2d_fr fr;
    vlbe_real d[VLBE_CR2D_NQ];
    vlbe_status st;
    VLBE_ASSERT(el != NULL && loc != NULL);
    mode = (mode | el->flags) & ~VLBE__CR2D_FRAME_ONLY;
    if (fth) {
        if (!(mode & VLBE_CR2D_LINEAR)) return VLBE_EARG;
        if ((st = vlbe__cr2d_float(el, fth, q, NULL, &fr, d, NULL)) != VLBE_OK) return st;
        q = d;
    }
    if ((st = vlbe__cr2d_kin_any(el, NULL, mode, q, NULL, &k)) != VLBE_OK) return st;
    if (!isfinite(k.l) || !isfinite(k.th[0]) || !isfinite(k.th[1]) || !isfinite(k.eps))
        return VLBE_ENONFINITE;
    loc[0] = k.l;
    loc[1] = k.th[0];
    loc[2] = k.th[1];
    loc[3] = k.eps;
    return VLBE_OK;
}

VLBE_API vlbe_status vlbe_cr2d_trans_force(const vlbe_cr2d_elem *el, const vlbe_cr2d_joint *jt,
                                           unsigned mode, const vlbe_real *q, const vlbe_real *qd,
                                           vlbe_real *VLBE_RESTRICT Q, vlbe_real *VLBE_RESTRICT K,
                                           vlbe_real *VLBE_RESTRICT D)
{
    VLBE_ASSERT(jt != NULL);
    return vlbe__cr2d_force_any(el, jt, mode, NULL, q, qd, Q, K, D);
}

VLBE_API vlbe_status vlbe_cr2d_trans_mass(const vlbe_cr2d_elem *el, const vlbe_cr2d_joint *jt,
                                          unsigned mode, const vlbe_real *q,
                                          vlbe_real *VLBE_RESTRICT M)
{
    VLBE_ASSERT(jt != NULL);
    return vlbe__cr2d_mass_any(el, jt, mode, q, M);
}

VLBE_API vlbe_status vlbe_cr2d_trans_mass_jac(const vlbe_cr2d_elem *el,
                                              const vlbe_cr2d_joint *jt, unsigned mode,
                                              const vlbe_real *q, const vlbe_real *a,
                                              vlbe_real *VLBE_RESTRICT Mq)
{
    VLBE_ASSERT(jt != NULL);
    return vlbe__cr2d_mass_jac_any(el, jt, mode, q, a, Mq);
}

VLBE_API vlbe_status vlbe_cr2d_trans_energy(const vlbe_cr2d_elem *el, const vlbe_cr2d_joint *jt,
                                            unsigned mode, const vlbe_real *q,
                                            const vlbe_real *qd, vlbe_real *VLBE_RESTRICT E)
{
    VLBE_ASSERT(jt != NULL);
    return vlbe__cr2d_energy_any(el, jt, mode, NULL, q, qd, E);
}

VLBE_API vlbe_status vlbe_cr2d_trans_local(const vlbe_cr2d_elem *el, const vlbe_cr2d_joint *jt,
                                           unsigned mode, const vlbe_real *q,
                                           vlbe_real *VLBE_RESTRICT loc)
{
    vlbe__cr2d_kin k;
    vlbe_status st;
    VLBE_ASSERT(el != NULL && jt != NULL && loc != NULL);
    mode = (mode | el->flags) & ~VLBE__CR2D_FRAME_ONLY;
    if ((st = vlbe__cr2d_kin_any(el, jt, mode, q, NULL, &k)) != VLBE_OK) return st;
    if (!isfinite(k.l1) || !isfinite(k.l) || !isfinite(k.th[0]) || !isfinite(k.th[1]) ||
        !isfinite(k.eps) || !isfinite(k.L1))
        return VLBE_ENONFINITE;
    loc[0] = k.l1;
    loc[1] = k.l;
    loc[2] = k.th[0];
    loc[3] = k.th[1];
    loc[4] = k.eps;
    loc[5] = k.L1;
    return VLBE_OK;
}

/* ===== beams: chains of elements ======================================== */
/* A beam of ne elements, element e joining nodes e and e + 1; coordinates
   q[3 i .. 3 i + 2] = (u, v, phi) of node i, n = 3 (ne + 1).  Constant nodal
   loads P (n, scaled by `load`) and prescribed coordinates (holonomic,
   rheonomic constraints q[dof] = g(t), m = nfix) complete the vlbe_dae
   problem; the callbacks below take the beam as `user` (b->user is the
   caller's own pointer, which the beam never reads).  Loads between the
   nodes: point loads (vlbe_cr2d_load, vlbe_cr2d_beam_loads) and a dead
   load per unit reference length (dist, plus dist_e per element) with
   consistent nodal forces and moments Q = int (dr/dq)^T w dx over the
   element's interpolation (for small rotations q L/2 and q L^2/12 at the
   nodes) and their stiffness; `load` scales P, dist, dist_e and the point
   loads (load stepping with vlbe_dae_static).  Between calls a caller may
   change load, P, dist, dist_e and the point loads (their array, or
   another through vlbe_cr2d_beam_loads): the callbacks read them at every
   call.  The force
   callbacks check the loads before they write anything (a bad kind or
   outside flag, a load on the transition element or a LINEAR element in a
   floating frame: VLBE_EARG, -1; NaN/Inf in load, dist, dist_e, a law or a
   constant value: VLBE_ENONFINITE, 1; s(t) outside the beam: VLBE_EBOUND,
   -1), with the load's index in err_load (-1: the distributed load, or no
   load).  The beam's energies have no load potential.  A callback that
   fails returns the value of vlbe_dae's table (vlbe__dae_rc, vlbe.h): 1
   for VLBE_ELENGTH, VLBE_ENONFINITE, VLBE_EBOUND and
   VLBE_ESINGULAR (the point lies outside the model's domain, e.g. a
   Newton iterate moved a node of the transition element across the
   joint's exit: the integrators retry smaller) and -1 otherwise, with the
   status and the element in err, err_elem (the convention of every model,
   vlbe.h at vlbe_dae).  With joint set, element trans
   is evaluated as the transition element (vlbe_cr2d_trans_*); the caller
   moves trans (and the constraints of the nodes inside the joint) when a
   node crosses the exit.  NaN/Inf in a callback's q, v (force, force_jac)
   or a (mass_jac) is found before anything is written (VLBE_ENONFINITE at
   the first element reading it, outputs untouched); a fix's dof outside
   [0, n) in a constraint callback: VLBE_EARG (-1).  Exception to the rule
   that a failed call writes nothing: a failure on finite inputs -- an
   element out of its domain, a fix or frame function giving NaN, a sum
   that overflows (VLBE_ENONFINITE, err_elem -1 outside the elements) --
   leaves M, Q, K, D, Mq, Mv, C, Cq, Ct, gamma unspecified: they are
   assembled in place (n x n; the beam has no room for a copy) and an
   element's failure shows only after the earlier elements were added.  The
   integrators treat them as scratch after a failure.  K or D of force_jac,
   Mv of mass_jac, Ct of constr_jac may be NULL.
   Storage of the matrices: dense (order NULL, what vlbe_cr2d_beam_init
   sets): M, K, D, Mq, Mv n x n, Cq m x n, row-major.  Banded
   (vlbe_cr2d_beam_band): the matrix callbacks write (n + m) x (n + m)
   band arrays, ld = kl + ku + 1, in the augmented order of vlbe.h's Band
   storage and integrators.h: M(i, j) at VLBE_BAND_IDX(ld, kl, order[i],
   order[j]) (K, D, Mq, Mv alike), Cq(k, j) at VLBE_BAND_IDX(ld, kl,
   order[n + k], order[j]) (not its transpose), every (n + m) ld slot
   written (zeros where there is no entry); the vectors (Q, C, Ct, gamma)
   keep the natural order.  The order is node by node: the node's u, v,
   phi, then the rows of the fixes on that node in the order of fix[];
   kl = ku = the largest |order[a] - order[b]| over the pairs an element
   or a fix couples: 5 + (fixes on node e) for element e, 3 + (earlier
   fixes on the node) - dof % 3 for a fix -- 5 for a beam without fixes,
   8 for one clamped at node 0, whatever ne.  The order is made from the
   fixes: after a new layout (vlbe_cr2d_beam_init, which restarts in
   dense mode, or fixes moved or added) call vlbe_cr2d_beam_band again; a
   banded matrix callback whose nfix is not the one the order was made
   for, or (constr_jac) whose fix lies outside the band, fails with
   VLBE_EARG (-1) before writing. */
typedef struct vlbe_cr2d_fix {
    int dof;          /* index in q                                        */
    vlbe_real g[3];   /* g(t) = g0 + g1 t + g2 t^2/2 when fun is NULL      */
    void (*fun)(void *ctx, vlbe_real t, vlbe_real *g3); /* g, g', g'' at t */
    void *ctx;
} vlbe_cr2d_fix;

/* A point load on a beam (vlbe_cr2d_beam_loads: the caller's array, kept
   by pointer) at the material point s(t) = s[0] + s[1] t + s[2] t^2/2, s
   the reference arc length from node 0 along the elements (element e
   spans the sum of the earlier lengths L plus [0, L_e]; at a node shared
   by two elements the left one): fixed (s[1] = s[2] = 0) or moving (a
   vehicle crossing a bridge).  Inside element e, at xi = (s - s_e)/L_e,
   it follows the element's interpolation (eqs. 7-9 of [H]): position
   r(xi) = x1 + xi (x2 - x1) + L (N2 theta1 + N4 theta2) e2 (N2 = xi (1 -
   xi)^2, N4 = xi^2 (xi - 1), the local deflection in the current frame e1,
   e2 of the chord), section rotation psi(xi) = beta + N2' theta1 + N4'
   theta2 (beta the chord angle; psi = a0 + phi_j at the nodes).
     VLBE_CR2D_LOAD_FORCE   force f[0..1], global axes: Q = (dr/dq)^T f,
                            K = f . d^2 r/dq^2 (the frame turns with the
                            nodes: a load stiffness);
     VLBE_CR2D_LOAD_MOMENT  moment f[0] about z: Q = f0 dpsi/dq, K = f0
                            d^2 psi/dq^2.
   At a node both are the nodal load of P (same Q, K = 0 there: r and psi
   of a node are linear in q).  LINEAR elements (without a floating frame)
   use the linearised interpolation (reference frame; Q constant, K = 0);
   the transition element and LINEAR elements in a floating frame take no
   loads between their nodes (VLBE_EARG).  Value: f, or fun(user, t, r,
   rd, f, dfr, dfv) of the point's position r and velocity rd = (dr/dq) v
   + (dr/dxi) xi' (2 each), writing f (2 for a force, 1 for a moment),
   returning 0 (else VLBE_ECALLBACK); dfr, dfv (nc x 2) are NULL in the
   force call and zeroed in the Jacobian call, where fun may write df/dr,
   df/drd (K and D then carry them).  Scaled by the beam's `load` factor.
   outside = 0: s(t) outside [0, sum L] fails with VLBE_EBOUND (-1: the
   range does not depend on the state); 1: the load is absent there. */
#define VLBE_CR2D_LOAD_FORCE 1
#define VLBE_CR2D_LOAD_MOMENT 2
typedef struct vlbe_cr2d_load {
    int kind;        /* VLBE_CR2D_LOAD_FORCE / _MOMENT                         */
    int outside;     /* 0: outside the beam is an error; 1: no load there       */
    vlbe_real s[3];  /* material coordinate s(t) = s[0] + s[1] t + s[2] t^2/2    */
    vlbe_real f[3];  /* constant value (force f[0..1], moment f[0])             */
    int (*fun)(void *user, vlbe_real t, const vlbe_real *r, const vlbe_real *rd,
               vlbe_real *f, vlbe_real *dfr, vlbe_real *dfv);
    void *user;      /* fun's own pointer                                      */
} vlbe_cr2d_load;

typedef struct vlbe_cr2d_beam {
    const vlbe_cr2d_elem *el; /* ne elements                              */
    int ne, n;                /* elements, coordinates 3 (ne + 1)         */
    unsigned mode;            /* ORed into every element call             */
    const vlbe_real *P;       /* nodal loads (n) or NULL                  */
    vlbe_real load;           /* factor on P                              */
    const vlbe_cr2d_fix *fix; /* prescribed coordinates                   */
    int nfix;
    const vlbe_cr2d_joint *joint; /* prismatic joint (NULL: none)         */
    int trans;                /* the element that is the transition
                                 element at the joint (-1: none)          */
    const vlbe_cr2d_fix *frame; /* floating frame of the LINEAR elements:
                                 theta(t), theta', theta'' as a prescribed
                                 coordinate (dof not used); NULL: none    */
    vlbe_status err;          /* last failure of a callback               */
    int err_elem;
    /* storage of the matrices, set by vlbe_cr2d_beam_band: */
    int *order;               /* augmented order (n + m, caller storage);
                                 NULL: dense mode                         */
    int order_cap;            /* length of order                          */
    int kl, ku;               /* half-bandwidths of the banded mode       */
    int band_m_;              /* private: the nfix order was made for     */
    /* loads between the nodes (all scaled by `load`, as P): */
    vlbe_real dist[2];        /* distributed dead load per unit reference
                                 length, global axes (gravity: rhoA g)     */
    const vlbe_real *dist_e;  /* per element, added to dist (2 ne; NULL)  */
    const vlbe_cr2d_load *loads; /* point loads (vlbe_cr2d_beam_loads)    */
    int nloads;
    int err_load;             /* point load of the last failure (-1: none
                                 or the distributed load's element)        */
    void *user;               /* the caller's own data (init: NULL); the
                                 callbacks' user stays the beam             */
} vlbe_cr2d_beam;

VLBE_API vlbe_status vlbe_cr2d_beam_init(vlbe_cr2d_beam *b, const vlbe_cr2d_elem *el, int ne,
                                         const vlbe_cr2d_fix *fix, int nfix);
VLBE_API vlbe_status vlbe_cr2d_beam_band(vlbe_cr2d_beam *b, int *order, int order_cap);
VLBE_API vlbe_status vlbe_cr2d_beam_loads(vlbe_cr2d_beam *b, const vlbe_cr2d_load *loads, int n);
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
/* The vlbe_dae (vlbe.h) of the beam: n = 3 (ne + 1), m = nfix, every
   callback above (constr_hess NULL: the prescribed coordinates are linear
   in q, so d(C_q^T lambda)/dq = 0 and the solvers' differences of it
   vanish), user = b, flags 0 (the consistent mass depends on q), the
   storage of the beam (banded with its order and half-bandwidths after
   vlbe_cr2d_beam_band, else dense); everything else of *sys zeroed.  Call
   again after changing nfix or the storage; VLBE_EARG (sys untouched) when
   the banded order was made for another nfix. */
VLBE_API vlbe_status vlbe_cr2d_beam_dae(vlbe_cr2d_beam *b, vlbe_dae *sys);
VLBE_API vlbe_status vlbe_cr2d_beam_energy(const vlbe_cr2d_beam *b, const vlbe_real *q,
                                           const vlbe_real *v, vlbe_real *E);
VLBE_API vlbe_status vlbe_cr2d_beam_energy_t(const vlbe_cr2d_beam *b, vlbe_real t,
                                             const vlbe_real *q, const vlbe_real *v,
                                             vlbe_real *E);

/* ne >= 1 elements el[0..ne-1], nfix >= 0 prescribed coordinates fix
   (NULL when nfix = 0), each dof in [0, n): else VLBE_EARG, also when n =
   3 (ne + 1) would exceed INT_MAX or n * n, nfix * n the range of size_t
   (the callbacks' matrices); a non-finite g of a fix without fun:
   VLBE_ENONFINITE.  On failure b is not written.  The beam starts in
   dense mode. */
VLBE_API vlbe_status vlbe_cr2d_beam_init(vlbe_cr2d_beam *b, const vlbe_cr2d_elem *el, int ne,
                                         const vlbe_cr2d_fix *fix, int nfix)
{
    int i, n;
    VLBE_ASSERT(b != NULL && el != NULL);
    if (ne < 1 || ne > INT_MAX / 3 - 1 || nfix < 0 || (nfix > 0 && fix == NULL)) return VLBE_EARG;
    n = 3 * (ne + 1);
    if ((size_t)n > (size_t)-1 / (size_t)n || (size_t)nfix > (size_t)-1 / (size_t)n)
        return VLBE_EARG;
    for (i = 0; i < nfix; ++i)
        if (fix[i].dof < 0 || fix[i].dof >= n) return VLBE_EARG;
    for (i = 0; i < nfix; ++i)
        if (!fix[i].fun && !vlbe_all_finite(fix[i].g, 3)) return VLBE_ENONFINITE;
    b->el = el;
    b->ne = ne;
    b->n = n;
    b->mode = 0;
    b->P = NULL;
    b->load = VLBE_R(1.0);
    b->fix = fix;
    b->nfix = nfix;
    b->joint = NULL;
    b->trans = -1;
    b->frame = NULL;
    b->err = VLBE_OK;
    b->err_elem = -1;
    b->order = NULL;
    b->order_cap = 0;
    b->kl = b->ku = 0;
    b->band_m_ = 0;
    b->dist[0] = b->dist[1] = VLBE_R(0.0);
    b->dist_e = NULL;
    b->loads = NULL;
    b->nloads = 0;
    b->err_load = -1;
    b->user = NULL;
    return VLBE_OK;
}

/* order != NULL: banded mode with the augmented order of the beam's
   current fixes (type comment) in order[0 .. n + nfix - 1] and kl = ku;
   order_cap < n + nfix: VLBE_EWORK; a fix's dof outside [0, n) or nfix < 0
   (the caller may change them after init), n + nfix above INT_MAX:
   VLBE_EARG; on these failures neither b nor order is written.  A band of
   (n + m) ld entries beyond the range of size_t (possible only with a
   32-bit size_t): VLBE_EARG with b unchanged, order scratch.  order NULL:
   dense mode (order_cap ignored).  O(n + nfix), no other storage. */
VLBE_API vlbe_status vlbe_cr2d_beam_band(vlbe_cr2d_beam *b, int *order, int order_cap)
{
    int n, m, nn, p, k, e, i, s, w;
    VLBE_ASSERT(b != NULL);
    if (!order) {
        b->order = NULL;
        b->order_cap = 0;
        b->kl = b->ku = 0;
        b->band_m_ = 0;
        return VLBE_OK;
    }
    n = b->n;
    m = b->nfix;
    nn = n / 3;
    if (m < 0 || (m > 0 && b->fix == NULL) || m > INT_MAX - n) return VLBE_EARG;
    for (k = 0; k < m; ++k)
        if (b->fix[k].dof < 0 || b->fix[k].dof >= n) return VLBE_EARG;
    if (order_cap < n + m) return VLBE_EWORK;
    /* a counting sort of the fixes by node, in order itself: order[p]
       (p < nn <= n, apart from the rows n + k) counts node p's fixes, then
       is the next free row slot of node p (its coordinates come first),
       then, once every row is placed, the end of node p's block */
    for (p = 0; p < nn; ++p) order[p] = 0;
    for (k = 0; k < m; ++k) ++order[b->fix[k].dof / 3];
    for (p = 0, s = 0; p < nn; ++p) {
        const int c = order[p];
        order[p] = s + 3;
        s += 3 + c;
    }
    for (k = 0; k < m; ++k) order[n + k] = order[b->fix[k].dof / 3]++;
    /* node p starts where node p - 1 ends (order[p - 1]); from the last
       node down, so that order[p - 1] is read before 3 (p - 1) .. 3 p - 1
       are written (3 q >= 3 p + 3 > p - 1 for the nodes q > p done) */
    for (p = nn - 1; p >= 0; --p) {
        const int s0 = p > 0 ? order[p - 1] : 0;
        order[3 * p] = s0;
        order[3 * p + 1] = s0 + 1;
        order[3 * p + 2] = s0 + 2;
    }
    /* the half-bandwidth: the largest distance an element's 6 coordinates
       or a fix's row and coordinate are apart */
    w = 0;
    for (e = 0; e < b->ne; ++e) {
        int lo = order[3 * e], hi = lo;
        for (i = 1; i < VLBE_CR2D_NQ; ++i) {
            const int o = order[3 * e + i];
            lo = o < lo ? o : lo;
            hi = o > hi ? o : hi;
        }
        w = hi - lo > w ? hi - lo : w;
    }
    for (k = 0; k < m; ++k) {
        const int d = order[n + k] - order[b->fix[k].dof];
        w = d > w ? d : (-d > w ? -d : w);
    }
    if ((size_t)w > ((size_t)-1 / (size_t)(n + m) - 1u) / 2u) return VLBE_EARG; /* (n + m) ld */
    b->order = order;
    b->order_cap = order_cap;
    b->kl = b->ku = w;
    b->band_m_ = m;
    return VLBE_OK;
}

VLBE_API void vlbe_cr2d_fix_eval(const vlbe_cr2d_fix *f, vlbe_real t, vlbe_real *g3)
{
    if (f->fun) {
        f->fun(f->ctx, t, g3);
        return;
    }
    vlbe__law(f->g[0], f->g[1], f->g[2], t, g3);
}

/* the joint when element e is the transition element, else NULL */
VLBE_INLINE const vlbe_cr2d_joint *vlbe__cr2d_jt(const vlbe_cr2d_beam *b, int e)
{
    return (b->joint && e == b->trans) ? b->joint : NULL;
}

/* the floating frame (theta, theta') of element e at t into fth: NULL when
   the beam has none or the element is not LINEAR */
VLBE_INLINE const vlbe_real *vlbe__cr2d_bframe(const vlbe_cr2d_beam *b, int e, vlbe_real t,
                                                 vlbe_real *fth)
{
    vlbe_real g[3];
    if (!b->frame || !((b->mode | b->el[e].flags) & VLBE_CR2D_LINEAR)) return NULL;
    vlbe_cr2d_fix_eval(b->frame, t, g);
    fth[0] = g[0];
    fth[1] = g[1];
    return fth;
}

VLBE_INLINE int vlbe__cr2d_fail(vlbe_cr2d_beam *b, vlbe_status st, int e)
{
    b->err = st;
    b->err_elem = e;
    b->err_load = -1;
    return vlbe__dae_rc(st);
}

/* The index map of element e (vlbe__scatter_map): its entry (i, j), i, j
   < 6, is the beam matrix's A[map[i] + map[6 + j]]; coordinates 3e .. 3e + 5. */
VLBE_INLINE void vlbe__cr2d_map(const vlbe_cr2d_beam *b, int e, size_t *map)
{
    int g[VLBE_CR2D_NQ], i;
    for (i = 0; i < VLBE_CR2D_NQ; ++i) g[i] = 3 * e + i;
    vlbe__scatter_map(VLBE_CR2D_NQ, g, b->n, b->order, b->kl, b->ku, map, map + VLBE_CR2D_NQ);
}

/* entries of an n x n matrix of the beam (rows m = nfix for Cq): dense n
   rows (m) of n, banded (n + m) ld (init and _band checked that they fit
   in a size_t) */
VLBE_INLINE size_t vlbe__cr2d_len(const vlbe_cr2d_beam *b, int rows)
{
    if (b->order)
        return ((size_t)b->n + (size_t)b->nfix) * (size_t)(b->kl + b->ku + 1);
    return (size_t)rows * (size_t)b->n;
}

/* a banded matrix callback: the beam's nfix still the one its order was
   made for (else VLBE_EARG: vlbe_cr2d_beam_band was not called again after
   a new layout); 0 or the callback's value */
VLBE_INLINE int vlbe__cr2d_band_check(vlbe_cr2d_beam *b)
{
    if (b->order && b->nfix != b->band_m_) return vlbe__cr2d_fail(b, VLBE_EARG, -1);
    return 0;
}


/* zero cnt entries (init checked that n * n and nfix * n fit in a size_t) */
VLBE_INLINE void vlbe__cr2d_zero(size_t cnt, vlbe_real *A)
{
    size_t i;
    for (i = 0; i < cnt; ++i) A[i] = VLBE_R(0.0);
}

/* NaN/Inf in a callback's q, v, a (each n; v, a may be NULL), found before
   any output is written: records VLBE_ENONFINITE at the first element that
   reads it and returns the callback's value (1); 0 when all finite */
VLBE_INLINE int vlbe__cr2d_in_check(vlbe_cr2d_beam *b, const vlbe_real *q, const vlbe_real *v,
                                      const vlbe_real *a)
{
    int e;
    if (vlbe_all_finite(q, b->n) && (!v || vlbe_all_finite(v, b->n)) &&
        (!a || vlbe_all_finite(a, b->n)))
        return 0;
    for (e = 0; e < b->ne; ++e)
        if (!vlbe_all_finite(q + 3 * e, VLBE_CR2D_NQ) ||
            (v && !vlbe_all_finite(v + 3 * e, VLBE_CR2D_NQ)) ||
            (a && !vlbe_all_finite(a + 3 * e, VLBE_CR2D_NQ)))
            break;
    return vlbe__cr2d_fail(b, VLBE_ENONFINITE, e < b->ne ? e : -1);
}

/* the constraint callbacks: every fix's dof in [0, n) (the caller may move
   the fixes after init) and q finite; 0 or the callback's value */
VLBE_INLINE int vlbe__cr2d_fix_check(vlbe_cr2d_beam *b, const vlbe_real *q, const vlbe_real *v)
{
    int k;
    for (k = 0; k < b->nfix; ++k)
        if (b->fix[k].dof < 0 || b->fix[k].dof >= b->n) return vlbe__cr2d_fail(b, VLBE_EARG, -1);
    if ((q && !vlbe_all_finite(q, b->n)) || (v && !vlbe_all_finite(v, b->n)))
        return vlbe__cr2d_fail(b, VLBE_ENONFINITE, -1);
    return 0;
}

VLBE_API int vlbe_cr2d_beam_mass(void *user, vlbe_real t, const vlbe_real *q, const vlbe_real *v,
                                 vlbe_real *M)
{
    vlbe_cr2d_beam *b = (vlbe_cr2d_beam *)user;
    vlbe_real Me[VLBE_CR2D_NQ * VLBE_CR2D_NQ];
    size_t map[2 * VLBE_CR2D_NQ];
    vlbe_status st;
    int e, rc;
    (void)t;
    (void)v;
    VLBE_ASSERT(b != NULL && q != NULL && M != NULL);
    if ((rc = vlbe__cr2d_band_check(b)) != 0) return rc;
    if ((rc = vlbe__cr2d_in_check(b, q, NULL, NULL)) != 0) return rc;
    vlbe__cr2d_zero(vlbe__cr2d_len(b, b->n), M);
    for (e = 0; e < b->ne; ++e) {
        if ((st = vlbe__cr2d_mass_any(&b->el[e], vlbe__cr2d_jt(b, e), b->mode, q + 3 * e, Me)) !=
            VLBE_OK)
            return vlbe__cr2d_fail(b, st, e);
        vlbe__cr2d_map(b, e, map);
        if (!vlbe__scatter(VLBE_CR2D_NQ, map, map + VLBE_CR2D_NQ, Me, M))
            return vlbe__cr2d_fail(b, VLBE_ENONFINITE, e);
    }
    return 0;
}

/* -- loads between the nodes: point loads (vlbe_cr2d_load), distributed
   dead load ------------------------------------------------------------ */
/* The frame of element e at q for its loads (see vlbe_cr2d_load):
   d = x2 - x1, e1, e2, the rotations theta1, theta2, db = dbeta/dd and the
   Hessian A = d^2 beta/dd^2 (xx, xy, yy); LINEAR elements: the reference
   frame, beta = a0 + e2.(u2 - u1)/L to first order, A = 0. */
typedef struct vlbe__cr2d_lf {
    vlbe_real L, e1[2], e2[2], d[2], th[2], db[2], A[3];
    int lin;
} vlbe__cr2d_lf;

VLBE_INLINE vlbe_status vlbe__cr2d_lframe(const vlbe_cr2d_elem *el, unsigned mode,
                                            const vlbe_real *q, vlbe__cr2d_lf *f)
{
    int j;
    f->L = el->L;
    f->lin = (mode & VLBE_CR2D_LINEAR) != 0;
    f->d[0] = el->X[2] - el->X[0] + q[3] - q[0];
    f->d[1] = el->X[3] - el->X[1] + q[4] - q[1];
    if (f->lin) {
        const vlbe_real db = (-el->s0 * (q[3] - q[0]) + el->c0 * (q[4] - q[1])) / el->L;
        f->e1[0] = el->c0;
        f->e1[1] = el->s0;
        f->th[0] = q[2] - db;
        f->th[1] = q[5] - db;
        f->A[0] = f->A[1] = f->A[2] = VLBE_R(0.0);
    } else {
        const vlbe_real x = f->d[0], y = f->d[1], l2 = x * x + y * y, l = vlbe_sqrt(l2);
        vlbe_real i4;
        if (!(l > VLBE_R(1e-6) * el->L) || !isfinite(l)) return VLBE_ELENGTH;
        i4 = VLBE_R(1.0) / (l2 * l2);
        f->e1[0] = x / l;
        f->e1[1] = y / l;
        for (j = 0; j < 2; ++j) { /* wrapped: the angle of a0 + phi_j against e1 */
            const vlbe_real c = vlbe_cos(el->a0 + q[3 * j + 2]);
            const vlbe_real s = vlbe_sin(el->a0 + q[3 * j + 2]);
            f->th[j] = vlbe_atan2(f->e1[0] * s - f->e1[1] * c, f->e1[0] * c + f->e1[1] * s);
        }
        f->A[0] = VLBE_R(2.0) * x * y * i4;
        f->A[1] = (y * y - x * x) * i4;
        f->A[2] = -f->A[0];
    }
    f->e2[0] = -f->e1[1];
    f->e2[1] = f->e1[0];
    { /* dbeta/dd = e2 / l (LINEAR: e2 / L) */
        const vlbe_real l = f->lin ? el->L : vlbe_sqrt(f->d[0] * f->d[0] + f->d[1] * f->d[1]);
        f->db[0] = f->e2[0] / l;
        f->db[1] = f->e2[1] / l;
    }
    return VLBE_OK;
}

/* adds H_dd (2x2, symmetric) and H_dphi_j (2 x 2: column j) of a function of
   (x1, d, phi1, phi2) to the 6x6 K in q (d = u2 - u1 + const) */
VLBE_INLINE void vlbe__cr2d_lhess(const vlbe_real *Hdd, const vlbe_real *Hdp, vlbe_real *K)
{
    int a, c, j;
    for (a = 0; a < 2; ++a) {
        for (c = 0; c < 2; ++c) {
            const vlbe_real h = Hdd[a * 2 + c];
            K[a * VLBE_CR2D_NQ + c] += h;
            K[a * VLBE_CR2D_NQ + 3 + c] -= h;
            K[(3 + a) * VLBE_CR2D_NQ + c] -= h;
            K[(3 + a) * VLBE_CR2D_NQ + 3 + c] += h;
        }
        for (j = 0; j < 2; ++j) {
            const vlbe_real h = Hdp[a * 2 + j];
            K[a * VLBE_CR2D_NQ + 3 * j + 2] -= h;
            K[(3 * j + 2) * VLBE_CR2D_NQ + a] -= h;
            K[(3 + a) * VLBE_CR2D_NQ + 3 * j + 2] += h;
            K[(3 * j + 2) * VLBE_CR2D_NQ + 3 + a] += h;
        }
    }
}

/* The field R = a x1 + c d + L (n2 theta1 + n4 theta2) e2 of the element's
   interpolation (position at xi: a = 1, c = xi, n2 = xi (1 - xi)^2, n4 =
   xi^2 (xi - 1), eqs. 8-9 of [H]; its xi-derivative: 0, 1, dn2, dn4):
   G += s d(w.R)/dq (6) and, with K, K += s d^2(w.R)/dq^2.  w.R =
   a w.x1 + c w.d + Phi(beta, phi), Phi = L W (w.e2), W = n2 theta1 + n4
   theta2, theta_j = a0 + phi_j - beta, de2/dbeta = -e1, de1/dbeta = e2. */
VLBE_INLINE void vlbe__cr2d_lfield(const vlbe__cr2d_lf *f, vlbe_real a, vlbe_real c,
                                     vlbe_real n2, vlbe_real n4, const vlbe_real *w, vlbe_real s,
                                     vlbe_real *G, vlbe_real *K)
{
    const vlbe_real L = f->L, W = n2 * f->th[0] + n4 * f->th[1];
    const vlbe_real we1 = f->lin ? VLBE_R(0.0) : w[0] * f->e1[0] + w[1] * f->e1[1];
    const vlbe_real we2 = w[0] * f->e2[0] + w[1] * f->e2[1];
    const vlbe_real Pb = -L * (n2 + n4) * we2 - L * W * we1; /* dPhi/dbeta */
    int k;
    for (k = 0; k < 2; ++k) {
        const vlbe_real gd = c * w[k] + Pb * f->db[k];
        G[k] += s * (a * w[k] - gd);
        G[3 + k] += s * gd;
    }
    G[2] += s * L * n2 * we2;
    G[5] += s * L * n4 * we2;
    if (K && !f->lin) {
        const vlbe_real Pbb = VLBE_R(2.0) * L * (n2 + n4) * we1 - L * W * we2;
        const vlbe_real Pbp[2] = {-L * n2 * we1, -L * n4 * we1};
        vlbe_real Hdd[4], Hdp[4];
        Hdd[0] = s * (Pbb * f->db[0] * f->db[0] + Pb * f->A[0]);
        Hdd[1] = Hdd[2] = s * (Pbb * f->db[0] * f->db[1] + Pb * f->A[1]);
        Hdd[3] = s * (Pbb * f->db[1] * f->db[1] + Pb * f->A[2]);
        for (k = 0; k < 2; ++k) {
            Hdp[k * 2 + 0] = s * Pbp[0] * f->db[k];
            Hdp[k * 2 + 1] = s * Pbp[1] * f->db[k];
        }
        vlbe__cr2d_lhess(Hdd, Hdp, K);
    }
}

/* The rotation of the section at xi, psi = beta + dn2 theta1 + dn4 theta2
   (slope of eqs. 8-9; psi = a0 + phi_j at the nodes), times a moment m:
   G += s m dpsi/dq, K += s m d^2 psi/dq^2 (through beta(d) only) */
VLBE_INLINE void vlbe__cr2d_lrot(const vlbe__cr2d_lf *f, vlbe_real dn2, vlbe_real dn4,
                                   vlbe_real m, vlbe_real s, vlbe_real *G, vlbe_real *K)
{
    const vlbe_real pb = VLBE_R(1.0) - dn2 - dn4;
    int k;
    for (k = 0; k < 2; ++k) {
        G[k] -= s * m * pb * f->db[k];
        G[3 + k] += s * m * pb * f->db[k];
    }
    G[2] += s * m * dn2;
    G[5] += s * m * dn4;
    if (K && !f->lin) {
        const vlbe_real Hdd[4] = {s * m * pb * f->A[0], s * m * pb * f->A[1], s * m * pb * f->A[1],
                                  s * m * pb * f->A[2]};
        const vlbe_real Hdp[4] = {0, 0, 0, 0};
        vlbe__cr2d_lhess(Hdd, Hdp, K);
    }
}

/* Hermite numbers at xi: n2, n4 and their xi-derivatives */
VLBE_INLINE void vlbe__cr2d_lherm(vlbe_real xi, vlbe_real *h)
{
    const vlbe_real x1 = VLBE_R(1.0) - xi;
    h[0] = xi * x1 * x1;
    h[1] = -xi * xi * x1;
    h[2] = x1 * (VLBE_R(1.0) - VLBE_R(3.0) * xi);
    h[3] = xi * (VLBE_R(3.0) * xi - VLBE_R(2.0));
}

/* a load's own data: kind, flag, law, constant value */
VLBE_INLINE vlbe_status vlbe__cr2d_load_ok(const vlbe_cr2d_load *ld)
{
    if (ld->kind != VLBE_CR2D_LOAD_FORCE && ld->kind != VLBE_CR2D_LOAD_MOMENT) return VLBE_EARG;
    if (ld->outside != 0 && ld->outside != 1) return VLBE_EARG;
    if (!vlbe_all_finite(ld->s, 3) || (!ld->fun && !vlbe_all_finite(ld->f, 3)))
        return VLBE_ENONFINITE;
    return VLBE_OK;
}

/* Gives the beam its point loads (the caller's array of n, kept by
   pointer; n = 0: none).  Each is checked: kind, outside (VLBE_EARG), NaN/
   Inf in s or, without fun, in f (VLBE_ENONFINITE); n < 0 or a NULL array
   with n > 0: VLBE_EARG.  On failure b is unchanged. */
VLBE_API vlbe_status vlbe_cr2d_beam_loads(vlbe_cr2d_beam *b, const vlbe_cr2d_load *loads, int n)
{
    int k;
    vlbe_status st;
    VLBE_ASSERT(b != NULL);
    if (n < 0 || (n > 0 && loads == NULL)) return VLBE_EARG;
    for (k = 0; k < n; ++k)
        if ((st = vlbe__cr2d_load_ok(&loads[k])) != VLBE_OK) return st;
    b->loads = n > 0 ? loads : NULL;
    b->nloads = n;
    return VLBE_OK;
}

/* s(t), s'(t) of load ld, its element *e and xi there (*e = -1: an
   `outside` load outside [0, total reference length]) */
VLBE_INLINE vlbe_status vlbe__cr2d_load_at(const vlbe_cr2d_beam *b, const vlbe_cr2d_load *ld,
                                             vlbe_real t, vlbe_real *ss, int *e, vlbe_real *xi)
{
    vlbe_real a = VLBE_R(0.0), g3[3];
    int k;
    vlbe__law(ld->s[0], ld->s[1], ld->s[2], t, g3);
    ss[0] = g3[0];
    ss[1] = g3[1];
    if (!vlbe_all_finite(ss, 2)) return VLBE_ENONFINITE;
    for (k = 0; k < b->ne; ++k) {
        const vlbe_real c = a + b->el[k].L;
        if (ss[0] >= a && ss[0] <= c) {
            *e = k;
            *xi = (ss[0] - a) / b->el[k].L;
            if (*xi > VLBE_R(1.0)) *xi = VLBE_R(1.0);
            return VLBE_OK;
        }
        a = c;
    }
    *e = -1;
    return ld->outside ? VLBE_OK : VLBE_EBOUND;
}

/* element e's mode, and whether loads between its nodes are available
   (not the transition element, not a LINEAR element in a floating frame) */
VLBE_INLINE vlbe_status vlbe__cr2d_lmode(const vlbe_cr2d_beam *b, int e, unsigned *mode)
{
    *mode = b->mode | b->el[e].flags;
    if (vlbe__cr2d_jt(b, e) || (b->frame && (*mode & VLBE_CR2D_LINEAR))) return VLBE_EARG;
    return VLBE_OK;
}

/* Point load ld on element e at xi moving with xi' (xd): Qe (6) and, when
   given, Ke, De (6x6), all written whole, times the load factor.  Force:
   Q = (dr/dq)^T f, K = f . d^2 r/dq^2; moment: Q = m dpsi/dq, K = m
   d^2 psi/dq^2; a callback's derivatives add G^T (df/dr dr/dq + df/drd
   drd/dq) to K and G^T df/drd dr/dq to D, rd = (dr/dq) v + (dr/dxi) xi'. */
VLBE_INLINE vlbe_status vlbe__cr2d_load_elem(const vlbe_cr2d_beam *b, const vlbe_cr2d_load *ld,
                                               int e, vlbe_real t, vlbe_real xi, vlbe_real xd,
                                               const vlbe_real *q, const vlbe_real *v,
                                               vlbe_real *Qe, vlbe_real *Ke, vlbe_real *De)
{
    static const vlbe_real ex[2][2] = {{1, 0}, {0, 1}};
    const int mom = ld->kind == VLBE_CR2D_LOAD_MOMENT, nc = mom ? 1 : 2;
    const int jac = Ke != NULL || De != NULL;
    const vlbe_real s = b->load;
    vlbe__cr2d_lf fr;
    vlbe_real h[4], f[2] = {0, 0}, dfr[4] = {0, 0, 0, 0}, dfv[4] = {0, 0, 0, 0};
    vlbe_real Gr[2 * VLBE_CR2D_NQ], G[2 * VLBE_CR2D_NQ], W[2 * VLBE_CR2D_NQ];
    unsigned mode;
    vlbe_status st;
    int a, c, j;
    if ((st = vlbe__cr2d_lmode(b, e, &mode)) != VLBE_OK) return st;
    if ((st = vlbe__cr2d_lframe(&b->el[e], mode, q, &fr)) != VLBE_OK) return st;
    vlbe__cr2d_lherm(xi, h);
    for (a = 0; a < 2 * VLBE_CR2D_NQ; ++a) Gr[a] = G[a] = VLBE_R(0.0);
    for (c = 0; c < 2; ++c)
        vlbe__cr2d_lfield(&fr, 1, xi, h[0], h[1], ex[c], 1, Gr + VLBE_CR2D_NQ * c, NULL);
    if (ld->fun) { /* position and velocity of the point */
        vlbe_real r[2], rd[2];
        const vlbe_real Wv = h[0] * fr.th[0] + h[1] * fr.th[1];
        const vlbe_real Wx = h[2] * fr.th[0] + h[3] * fr.th[1];
        for (c = 0; c < 2; ++c) {
            r[c] = b->el[e].X[c] + q[c] + xi * fr.d[c] + fr.L * Wv * fr.e2[c];
            rd[c] = (fr.d[c] + fr.L * Wx * fr.e2[c]) * xd;
            for (a = 0; a < VLBE_CR2D_NQ; ++a) rd[c] += Gr[VLBE_CR2D_NQ * c + a] * v[a];
        }
        if (ld->fun(ld->user, t, r, rd, f, jac ? dfr : NULL, jac ? dfv : NULL))
            return VLBE_ECALLBACK;
        if (!vlbe_all_finite(f, nc) || !vlbe_all_finite(dfr, 4) || !vlbe_all_finite(dfv, 4))
            return VLBE_ENONFINITE;
    } else {
        for (c = 0; c < nc; ++c) f[c] = ld->f[c];
    }
    if (Ke)
        for (a = 0; a < VLBE_CR2D_NQ * VLBE_CR2D_NQ; ++a) Ke[a] = VLBE_R(0.0);
    if (De)
        for (a = 0; a < VLBE_CR2D_NQ * VLBE_CR2D_NQ; ++a) De[a] = VLBE_R(0.0);
    for (a = 0; a < VLBE_CR2D_NQ; ++a) Qe[a] = VLBE_R(0.0);
    if (mom) {
        vlbe__cr2d_lrot(&fr, h[2], h[3], f[0], s, Qe, Ke);
        vlbe__cr2d_lrot(&fr, h[2], h[3], 1, 1, G, NULL);
    } else {
        vlbe__cr2d_lfield(&fr, 1, xi, h[0], h[1], f, s, Qe, Ke);
        for (a = 0; a < 2 * VLBE_CR2D_NQ; ++a) G[a] = Gr[a];
    }
    if (!jac || !ld->fun) return VLBE_OK;
    if (De) { /* df/drd dr/dv */
        for (c = 0; c < nc; ++c)
            for (a = 0; a < VLBE_CR2D_NQ; ++a) {
                vlbe_real x = VLBE_R(0.0);
                for (j = 0; j < 2; ++j) x += dfv[c * 2 + j] * Gr[VLBE_CR2D_NQ * j + a];
                W[VLBE_CR2D_NQ * c + a] = x;
            }
        for (c = 0; c < nc; ++c)
            for (a = 0; a < VLBE_CR2D_NQ; ++a)
                for (j = 0; j < VLBE_CR2D_NQ; ++j)
                    De[a * VLBE_CR2D_NQ + j] +=
                        s * G[VLBE_CR2D_NQ * c + a] * W[VLBE_CR2D_NQ * c + j];
    }
    if (Ke) { /* df/dr dr/dq + df/drd drd/dq, drd/dq = d^2 r/dq^2 v + xi' d(dr/dxi)/dq */
        vlbe_real Grd[2 * VLBE_CR2D_NQ], Hc[VLBE_CR2D_NQ * VLBE_CR2D_NQ];
        for (a = 0; a < 2 * VLBE_CR2D_NQ; ++a) W[a] = VLBE_R(0.0);
        for (c = 0; c < 2; ++c) {
            for (a = 0; a < VLBE_CR2D_NQ * VLBE_CR2D_NQ; ++a) Hc[a] = VLBE_R(0.0);
            for (a = 0; a < VLBE_CR2D_NQ; ++a) Grd[VLBE_CR2D_NQ * c + a] = VLBE_R(0.0);
            vlbe__cr2d_lfield(&fr, 1, xi, h[0], h[1], ex[c], 1, W, Hc); /* W: scratch */
            for (a = 0; a < VLBE_CR2D_NQ; ++a)
                for (j = 0; j < VLBE_CR2D_NQ; ++j)
                    Grd[VLBE_CR2D_NQ * c + a] += Hc[a * VLBE_CR2D_NQ + j] * v[j];
            vlbe__cr2d_lfield(&fr, 0, 1, h[2], h[3], ex[c], xd, Grd + VLBE_CR2D_NQ * c, NULL);
        }
        for (c = 0; c < nc; ++c)
            for (a = 0; a < VLBE_CR2D_NQ; ++a) {
                vlbe_real x = VLBE_R(0.0);
                for (j = 0; j < 2; ++j)
                    x += dfr[c * 2 + j] * Gr[VLBE_CR2D_NQ * j + a] +
                         dfv[c * 2 + j] * Grd[VLBE_CR2D_NQ * j + a];
                W[VLBE_CR2D_NQ * c + a] = x;
            }
        for (c = 0; c < nc; ++c)
            for (a = 0; a < VLBE_CR2D_NQ; ++a)
                for (j = 0; j < VLBE_CR2D_NQ; ++j)
                    Ke[a * VLBE_CR2D_NQ + j] +=
                        s * G[VLBE_CR2D_NQ * c + a] * W[VLBE_CR2D_NQ * c + j];
    }
    return VLBE_OK;
}

/* The distributed dead load w (global, per unit reference length) on
   element e: Qe = load int_0^L (dr/dq)^T w dx, Ke its q-derivative (3-point
   Gauss rule: the integrands are cubic in xi, exact); Qe, Ke written whole
   (Ke may be NULL) */
VLBE_INLINE vlbe_status vlbe__cr2d_dist_elem(const vlbe_cr2d_beam *b, int e, const vlbe_real *w,
                                               const vlbe_real *q, vlbe_real *Qe, vlbe_real *Ke)
{
    const vlbe_real *x, *wg;
    vlbe__cr2d_lf fr;
    unsigned mode;
    vlbe_status st;
    int g, a;
    if ((st = vlbe__cr2d_lmode(b, e, &mode)) != VLBE_OK) return st;
    if ((st = vlbe__cr2d_lframe(&b->el[e], mode, q, &fr)) != VLBE_OK) return st;
    if ((st = vlbe_gl_rule(3, &x, &wg)) != VLBE_OK) return st;
    for (a = 0; a < VLBE_CR2D_NQ; ++a) Qe[a] = VLBE_R(0.0);
    if (Ke)
        for (a = 0; a < VLBE_CR2D_NQ * VLBE_CR2D_NQ; ++a) Ke[a] = VLBE_R(0.0);
    for (g = 0; g < 3; ++g) {
        const vlbe_real xi = VLBE_R(0.5) * (x[g] + VLBE_R(1.0));
        vlbe_real h[4];
        vlbe__cr2d_lherm(xi, h);
        vlbe__cr2d_lfield(&fr, 1, xi, h[0], h[1], w, b->load * VLBE_R(0.5) * wg[g] * fr.L, Qe, Ke);
    }
    return VLBE_OK;
}

/* the distributed load of element e into w (beam-wide dist plus dist_e);
   0 when it is zero */
VLBE_INLINE int vlbe__cr2d_dist_of(const vlbe_cr2d_beam *b, int e, vlbe_real *w)
{
    w[0] = b->dist[0] + (b->dist_e ? b->dist_e[2 * e] : VLBE_R(0.0));
    w[1] = b->dist[1] + (b->dist_e ? b->dist_e[2 * e + 1] : VLBE_R(0.0));
    return w[0] != VLBE_R(0.0) || w[1] != VLBE_R(0.0);
}

/* records a failure of point load k (-1: the distributed load): as
   vlbe__cr2d_fail, but a load outside the beam is fatal (-1) -- the range
   does not depend on the state */
VLBE_INLINE int vlbe__cr2d_load_fail(vlbe_cr2d_beam *b, vlbe_status st, int e, int k)
{
    const int rc = vlbe__cr2d_fail(b, st, e);
    b->err_load = k;
    return st == VLBE_EBOUND ? -1 : rc;
}

/* Checks the loads before anything is written: factor, distributed
   values, each point load's data and place.  0 or the callback's value. */
VLBE_INLINE int vlbe__cr2d_loads_check(vlbe_cr2d_beam *b, vlbe_real t)
{
    vlbe_real ss[2], xi, w[2];
    int k, e;
    vlbe_status st;
    if (!isfinite(b->load)) return vlbe__cr2d_fail(b, VLBE_ENONFINITE, -1);
    if (b->nloads < 0 || (b->nloads > 0 && !b->loads)) return vlbe__cr2d_fail(b, VLBE_EARG, -1);
    if (!vlbe_all_finite(b->dist, 2) || (b->dist_e && !vlbe_all_finite(b->dist_e, 2 * b->ne)))
        return vlbe__cr2d_load_fail(b, VLBE_ENONFINITE, -1, -1);
    for (e = 0; e < b->ne; ++e) {
        unsigned md;
        if (vlbe__cr2d_dist_of(b, e, w) && vlbe__cr2d_lmode(b, e, &md) != VLBE_OK)
            return vlbe__cr2d_load_fail(b, VLBE_EARG, e, -1);
    }
    for (k = 0; k < b->nloads; ++k) {
        unsigned md;
        if ((st = vlbe__cr2d_load_ok(&b->loads[k])) != VLBE_OK ||
            (st = vlbe__cr2d_load_at(b, &b->loads[k], t, ss, &e, &xi)) != VLBE_OK ||
            (e >= 0 && (st = vlbe__cr2d_lmode(b, e, &md)) != VLBE_OK))
            return vlbe__cr2d_load_fail(b, st, e, k);
    }
    return 0;
}

/* adds the loads between the nodes to Q and/or K, D (Qe, Ke, De: the
   caller's element scratch) */
VLBE_INLINE int vlbe__cr2d_beam_loads(vlbe_cr2d_beam *b, vlbe_real t, const vlbe_real *q,
                                        const vlbe_real *v, vlbe_real *Q, vlbe_real *K,
                                        vlbe_real *D, vlbe_real *Qe, vlbe_real *Ke, vlbe_real *De)
{
    vlbe_real w[2], ss[2], xi;
    size_t map[2 * VLBE_CR2D_NQ];
    vlbe_status st;
    int e, i, k;
    for (e = 0; e < b->ne; ++e) {
        if (!vlbe__cr2d_dist_of(b, e, w)) continue;
        if ((st = vlbe__cr2d_dist_elem(b, e, w, q + 3 * e, Qe, K ? Ke : NULL)) != VLBE_OK)
            return vlbe__cr2d_load_fail(b, st, e, -1);
        if (Q)
            for (i = 0; i < VLBE_CR2D_NQ; ++i) Q[3 * e + i] += Qe[i];
        if (K) {
            vlbe__cr2d_map(b, e, map);
            if (!vlbe__scatter(VLBE_CR2D_NQ, map, map + VLBE_CR2D_NQ, Ke, K))
                return vlbe__cr2d_fail(b, VLBE_ENONFINITE, e);
        }
    }
    for (k = 0; k < b->nloads; ++k) {
        if ((st = vlbe__cr2d_load_at(b, &b->loads[k], t, ss, &e, &xi)) != VLBE_OK)
            return vlbe__cr2d_load_fail(b, st, -1, k);
        if (e < 0) continue; /* outside, and allowed to be */
        if ((st = vlbe__cr2d_load_elem(b, &b->loads[k], e, t, xi, ss[1] / b->el[e].L, q + 3 * e,
                                       v + 3 * e, Qe, K ? Ke : NULL, D ? De : NULL)) != VLBE_OK)
            return vlbe__cr2d_load_fail(b, st, e, k);
        if (Q)
            for (i = 0; i < VLBE_CR2D_NQ; ++i) Q[3 * e + i] += Qe[i];
        if (K || D) vlbe__cr2d_map(b, e, map);
        if ((K && !vlbe__scatter(VLBE_CR2D_NQ, map, map + VLBE_CR2D_NQ, Ke, K)) ||
            (D && !vlbe__scatter(VLBE_CR2D_NQ, map, map + VLBE_CR2D_NQ, De, D)))
            return vlbe__cr2d_fail(b, VLBE_ENONFINITE, e);
    }
    return 0;
}

VLBE_INLINE int vlbe__cr2d_beam_forces(vlbe_cr2d_beam *b, vlbe_real t, const vlbe_real *q,
                                         const vlbe_real *v, vlbe_real *Q, vlbe_real *K,
                                         vlbe_real *D)
{
    vlbe_real Qe[VLBE_CR2D_NQ], Ke[VLBE_CR2D_NQ * VLBE_CR2D_NQ], De[VLBE_CR2D_NQ * VLBE_CR2D_NQ],
        fth[2];
    size_t map[2 * VLBE_CR2D_NQ];
    vlbe_status st;
    int e, i, rc;
    VLBE_ASSERT(b != NULL && q != NULL && v != NULL);
    if ((K || D) && (rc = vlbe__cr2d_band_check(b)) != 0) return rc;
    if ((rc = vlbe__cr2d_in_check(b, q, v, NULL)) != 0) return rc;
    if ((rc = vlbe__cr2d_loads_check(b, t)) != 0) return rc;
    if (Q) {
        vlbe_vec_zero(b->n, Q);
        if (b->P)
            for (i = 0; i < b->n; ++i) Q[i] = b->load * b->P[i];
    }
    if (K) vlbe__cr2d_zero(vlbe__cr2d_len(b, b->n), K);
    if (D) vlbe__cr2d_zero(vlbe__cr2d_len(b, b->n), D);
    for (e = 0; e < b->ne; ++e) {
        if ((st = vlbe__cr2d_force_any(&b->el[e], vlbe__cr2d_jt(b, e), b->mode,
                                       vlbe__cr2d_bframe(b, e, t, fth), q + 3 * e, v + 3 * e,
                                       Qe, K ? Ke : NULL, D ? De : NULL)) != VLBE_OK)
            return vlbe__cr2d_fail(b, st, e);
        if (Q)
            for (i = 0; i < VLBE_CR2D_NQ; ++i) Q[3 * e + i] += Qe[i];
        if (K || D) vlbe__cr2d_map(b, e, map);
        if ((K && !vlbe__scatter(VLBE_CR2D_NQ, map, map + VLBE_CR2D_NQ, Ke, K)) ||
            (D && !vlbe__scatter(VLBE_CR2D_NQ, map, map + VLBE_CR2D_NQ, De, D)))
            return vlbe__cr2d_fail(b, VLBE_ENONFINITE, e);
    }
    if ((rc = vlbe__cr2d_beam_loads(b, t, q, v, Q, K, D, Qe, Ke, De)) != 0) return rc;
    if (Q && !vlbe_all_finite(Q, b->n)) return vlbe__cr2d_fail(b, VLBE_ENONFINITE, -1);
    return 0;
}

VLBE_API int vlbe_cr2d_beam_force(void *user, vlbe_real t, const vlbe_real *q, const vlbe_real *v,
                                  vlbe_real *Q)
{
    VLBE_ASSERT(Q != NULL);
    return vlbe__cr2d_beam_forces((vlbe_cr2d_beam *)user, t, q, v, Q, NULL, NULL);
}

VLBE_API int vlbe_cr2d_beam_force_jac(void *user, vlbe_real t, const vlbe_real *q,
                                      const vlbe_real *v, vlbe_real *K, vlbe_real *D)
{
    return vlbe__cr2d_beam_forces((vlbe_cr2d_beam *)user, t, q, v, NULL, K, D);
}

VLBE_API int vlbe_cr2d_beam_mass_jac(void *user, vlbe_real t, const vlbe_real *q,
                                     const vlbe_real *v, const vlbe_real *a, vlbe_real *Mq,
                                     vlbe_real *Mv)
{
    vlbe_cr2d_beam *b = (vlbe_cr2d_beam *)user;
    vlbe_real Me[VLBE_CR2D_NQ * VLBE_CR2D_NQ];
    size_t map[2 * VLBE_CR2D_NQ];
    vlbe_status st;
    int e, rc;
    (void)t;
    (void)v;
    VLBE_ASSERT(b != NULL && q != NULL && a != NULL && Mq != NULL);
    if ((rc = vlbe__cr2d_band_check(b)) != 0) return rc;
    if ((rc = vlbe__cr2d_in_check(b, q, NULL, a)) != 0) return rc;
    vlbe__cr2d_zero(vlbe__cr2d_len(b, b->n), Mq);
    if (Mv) vlbe__cr2d_zero(vlbe__cr2d_len(b, b->n), Mv);
    for (e = 0; e < b->ne; ++e) {
        if ((st = vlbe__cr2d_mass_jac_any(&b->el[e], vlbe__cr2d_jt(b, e), b->mode, q + 3 * e,
                                          a + 3 * e, Me)) != VLBE_OK)
            return vlbe__cr2d_fail(b, st, e);
        vlbe__cr2d_map(b, e, map);
        if (!vlbe__scatter(VLBE_CR2D_NQ, map, map + VLBE_CR2D_NQ, Me, Mq))
            return vlbe__cr2d_fail(b, VLBE_ENONFINITE, e);
    }
    return 0;
}

VLBE_API int vlbe_cr2d_beam_constr(void *user, vlbe_real t, const vlbe_real *q, vlbe_real *C)
{
    vlbe_cr2d_beam *b = (vlbe_cr2d_beam *)user;
    vlbe_real g[3];
    int k, rc;
    VLBE_ASSERT(b != NULL && q != NULL && (b->nfix == 0 || C != NULL));
    if ((rc = vlbe__cr2d_fix_check(b, q, NULL)) != 0) return rc;
    for (k = 0; k < b->nfix; ++k) {
        vlbe_cr2d_fix_eval(&b->fix[k], t, g);
        C[k] = q[b->fix[k].dof] - g[0];
    }
    return vlbe_all_finite(C, b->nfix) ? 0 : vlbe__cr2d_fail(b, VLBE_ENONFINITE, -1);
}

VLBE_API int vlbe_cr2d_beam_constr_jac(void *user, vlbe_real t, const vlbe_real *q, vlbe_real *Cq,
                                       vlbe_real *Ct)
{
    vlbe_cr2d_beam *b = (vlbe_cr2d_beam *)user;
    vlbe_real g[3];
    int k, rc;
    (void)q;
    VLBE_ASSERT(b != NULL && (b->nfix == 0 || Cq != NULL));
    if ((rc = vlbe__cr2d_fix_check(b, NULL, NULL)) != 0) return rc;
    if ((rc = vlbe__cr2d_band_check(b)) != 0) return rc;
    if (b->order)
        for (k = 0; k < b->nfix; ++k) {
            const int d = b->order[b->n + k] - b->order[b->fix[k].dof];
            if (d > b->kl || -d > b->kl) /* moved out of the band (kl = ku) */
                return vlbe__cr2d_fail(b, VLBE_EARG, -1);
        }
    if (Cq) vlbe__cr2d_zero(vlbe__cr2d_len(b, b->nfix), Cq); /* NULL: nfix = 0 */
    for (k = 0; k < b->nfix; ++k) {
        if (b->order)
            Cq[VLBE_BAND_IDX(b->kl + b->ku + 1, b->kl, b->order[b->n + k],
                             b->order[b->fix[k].dof])] = VLBE_R(1.0);
        else
            Cq[(size_t)k * (size_t)b->n + (size_t)b->fix[k].dof] = VLBE_R(1.0);
        if (Ct) {
            vlbe_cr2d_fix_eval(&b->fix[k], t, g);
            Ct[k] = -g[1];
        }
    }
    return (!Ct || vlbe_all_finite(Ct, b->nfix)) ? 0 : vlbe__cr2d_fail(b, VLBE_ENONFINITE, -1);
}

VLBE_API int vlbe_cr2d_beam_constr_acc(void *user, vlbe_real t, const vlbe_real *q,
                                       const vlbe_real *v, vlbe_real *gamma)
{
    vlbe_cr2d_beam *b = (vlbe_cr2d_beam *)user;
    vlbe_real g[3];
    int k, rc;
    (void)q;
    (void)v;
    VLBE_ASSERT(b != NULL && (b->nfix == 0 || gamma != NULL));
    if ((rc = vlbe__cr2d_fix_check(b, NULL, NULL)) != 0) return rc;
    for (k = 0; k < b->nfix; ++k) {
        vlbe_cr2d_fix_eval(&b->fix[k], t, g);
        gamma[k] = g[2];
    }
    return vlbe_all_finite(gamma, b->nfix) ? 0 : vlbe__cr2d_fail(b, VLBE_ENONFINITE, -1);
}

VLBE_API vlbe_status vlbe_cr2d_beam_dae(vlbe_cr2d_beam *b, vlbe_dae *sys)
{
    VLBE_ASSERT(b != NULL && sys != NULL);
    if (b->order && b->nfix != b->band_m_) return VLBE_EARG;
    memset(sys, 0, sizeof *sys);
    sys->n = b->n;
    sys->m = b->nfix;
    sys->user = b;
    sys->mass = vlbe_cr2d_beam_mass;
    sys->force = vlbe_cr2d_beam_force;
    sys->force_jac = vlbe_cr2d_beam_force_jac;
    sys->mass_jac = vlbe_cr2d_beam_mass_jac;
    sys->constr = vlbe_cr2d_beam_constr;
    sys->constr_jac = vlbe_cr2d_beam_constr_jac;
    sys->constr_acc = vlbe_cr2d_beam_constr_acc;
    if (b->order) {
        sys->storage = VLBE_DAE_BANDED;
        sys->kl = b->kl;
        sys->ku = b->ku;
        sys->order = b->order;
    }
    return VLBE_OK;
}

VLBE_API vlbe_status vlbe_cr2d_beam_energy(const vlbe_cr2d_beam *b, const vlbe_real *q,
                                           const vlbe_real *v, vlbe_real *E)
{
    VLBE_ASSERT(b != NULL);
    if (b->frame) return VLBE_EARG; /* the frame needs the time: _energy_t */
    return vlbe_cr2d_beam_energy_t(b, VLBE_R(0.0), q, v, E);
}

VLBE_API vlbe_status vlbe_cr2d_beam_energy_t(const vlbe_cr2d_beam *b, vlbe_real t,
                                             const vlbe_real *q, const vlbe_real *v,
                                             vlbe_real *E)
{
    vlbe_real Ee[2], fth[2], T = VLBE_R(0.0), U = VLBE_R(0.0);
    vlbe_status st;
    int e;
    VLBE_ASSERT(b != NULL && q != NULL && v != NULL && E != NULL);
    for (e = 0; e < b->ne; ++e) {
        if ((st = vlbe__cr2d_energy_any(&b->el[e], vlbe__cr2d_jt(b, e), b->mode,
                                        vlbe__cr2d_bframe(b, e, t, fth), q + 3 * e, v + 3 * e,
                                        Ee)) != VLBE_OK)
            return st; /* E untouched */
        T += Ee[0];
        U += Ee[1];
    }
    if (!isfinite(T) || !isfinite(U)) return VLBE_ENONFINITE; /* a sum that overflows */
    E[0] = T;
    E[1] = U;
    return VLBE_OK;
}

#endif /* VLBE_COROT2D_H */
