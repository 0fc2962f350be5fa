/* ancf_ale.h -- ALE-ANCF variable-length elements: the planar beam (VLBE of
   Hong & Ren as used by Ding & Ouyang) and the 3D beam-shaft with spin
   (VLBSE of Yang et al.): mass, transport inertia, axial, bending and twist
   viscoelastic forces, loads, analytic Jacobians; chains of them with
   constraints, sliding nodes, segmentation and length control
   -- part of vlbe v0.1.0                          SPDX-License-Identifier: MIT

USAGE
   #include "ancf_ale.h"     (vlbe.h must sit in the same directory)

     vlbe_ale_mat mat = {0};  mat.rhoA = ...; mat.EA = ...; mat.EI = ...;
     mat.f[1] = -9.81 * mat.rhoA;                     (gravity as a load)
     vlbe_ale_elem el;                                (once per material)
     if (vlbe_ale_elem_init(&el, &mat, 0, 0, 0, 0)) fail;   (default Gauss orders)
     vlbe_real q[10] = {x1,y1,x1',y1',p1, x2,y2,x2',y2',p2}, qd[10] = ...;
     vlbe_real M[100], Q[10], K[100], D[100];
     vlbe_ale_mass(&el, 0, q, M);
     vlbe_ale_force(&el, 0, q, qd, Q, K, D);          (K, D may be NULL)
   A chain of elements as a vlbe_dae for integrators.h, end to end in 40
   lines: examples/first_chain.c (make check-first builds and runs it).

CONFIG
   Nothing beyond vlbe.h.

CONVENTIONS
   Element coordinates, 10 per element, node by node:
        q = [x1, y1, x1', y1', p1,  x2, y2, x2', y2', p2]
   r(p) is the position of material point p, ' = d/dp, p the material
   (arc-length in the unstretched state) coordinate; p1 < p2 are the nodal
   material coordinates, L = p2 - p1, xi = (p - p1)/L in [0, 1].  With fixed
   p1, p2 this is the classic planar ANCF cable/beam (Gerstmayr & Shabana).
   Equations of motion of the element (ale-rancf eq. 18, written with the
   sign convention of integrators.h):
        M(q) q'' = Q(q, q'),   Q = Q_f - Q_a - Q_l - Q_t,
   M (eq. 19): rhoA int N^T N dp with N = [S, dS/dp1 e, dS/dp2 e] (eqs. 14-15)
   arranged in the node-by-node order above; Q_a transport inertia
   rhoA int N^T r_v dp; Q_l axial EA int eps_q (eps + c_eps eps') dp with
   the Green strain eps = (r'.r' - 1)/2; Q_t bending EI int kap_q (kap +
   c_kap kap') dp with the signed curvature kap = (r' x r'')_z / |r'|^3;
   Q_f = int N^T f dp for a constant distributed load f per unit material
   length (gravity: f = rhoA g).  Rates eps', kap' are material rates (at
   fixed p), equal to eps_q q', kap_q q'.  Units: any consistent set.
   Matrices 10x10 row-major in the same order.  K = dQ/dq, D = dQ/dq'.
   Arguments, the same order in the planar, 3D and rational elements
   (rancf.h): what fixes the element's basis first (nothing for the planar
   Hermite element, the mode for the 3D one, whose layout it sets, the
   element with its weights for the rational one), then q (and q', a), the
   material point p, the outputs last:  vlbe_ale_point(q, p, r, rp),
   vlbe_ale3_point(mode, q, p, r, rp, th), vlbe_rancf_point(el, q, p, r,
   rp); element calls take the element and mode first: vlbe_ale_force(el,
   mode, q, qd, Q, K, D).

   Mode flags (vlbe_ale_elem_init: defaults of the element type; the eval
   functions OR their `mode` argument into them):
     VLBE_ALE_NO_BEND   string/cable: no Q_t (EI ignored)
     VLBE_ALE_NO_DAMP   no Kelvin-Voigt terms
     VLBE_ALE_FIX_P1/2  material coordinate of node 1/2 fixed (not a
                        coordinate, p' = 0): its row and column stay zero and
                        are not computed.  Both set = Lagrangian ANCF, whose
                        mass matrix is the classic constant one.
     VLBE_ALE_CONSERVATIVE   add to the p-rows the flux of strain energy
                        through the element ends (see NOTES): the elastic
                        p-forces become the gradient of the strain energy.
     VLBE_ALE_INV_AXIAL the axial force (with its Kelvin-Voigt part) from
                        the invariant tables instead of Gauss points
                        (INVARIANTS), fixed-length and ALE elements; with
                        both p fixed the load too.  The same numbers to
                        rounding.  Off by default: per element it is slower
                        for Q alone and for the beam; with K and D the
                        cable gains 5-20 % at most (docs/benchmarks.md).
   Gauss orders per term (init; 0 = default): nm for mass, transport inertia
   and loads (default 4, exact: the integrands are polynomials of degree 6
   in xi), nl for the axial force (default 5, exact: degree 8), nt for the
   bending force (default 5; its integrand is rational).  At most
   VLBE_ALE_NGP_MAX points per term.

   Errors: VLBE_ELENGTH when L = p2 - p1 is out of range: L <= 0, L = Inf
   (p1, p2 of opposite huge signs) or so small that L^-4, the largest
   power of 1/L the basis carries, could overflow (double: L < 1.8e-77,
   float: L < 4.7e-10);
   VLBE_ENONFINITE for NaN/Inf in q or q', and when finite data overflow
   (slopes, rates or lengths so large that an output would be Inf or
   NaN: every output is checked before it is written); VLBE_ESINGULAR
   when the slope vanishes (|r'|^2 <= eps) at a bending point (the
   curvature is undefined there); VLBE_EBOUND when a point load lies
   outside [p1, p2].  On failure no output is written (point loads, which
   add to Q and K, work on copies).
   Stack (float, Cortex-M4F, gcc -O2, tests/m4/stack.awk; double about
   twice): vlbe_ale_force and vlbe_ale_inv_force with K, D up to 3.4 kB
   (local Q, K, D, so that a failure writes nothing, the strain e-columns
   and the point scratch), the other planar eval calls at most 1.6 kB,
   vlbe_ale_elem_init 1.3 kB.
   vlbe_ale_elem is about 16 kB: make one per material, not per element.

DERIVATIONS
   With the code they explain: NOTES (how the Jacobians are formed) at the
   start of the implementation, INVARIANTS (the invariant-matrix
   evaluation of the axial force) at its section, the 3D element's
   equations at the 3D section.

API
   vlbe_status vlbe_ale_elem_init(el, mat, flags, nm, nl, nt)  element type, Gauss tables
   vlbe_status vlbe_ale_mass(el, mode, q, M)                M(q), 10x10
   vlbe_status vlbe_ale_mass_jac(el, mode, q, a, Mq)        d(M a)/dq, 10x10
   vlbe_status vlbe_ale_force(el, mode, q, qd, Q, K, D)     Q and (optional) K, D
   vlbe_status vlbe_ale_energy(el, mode, q, qd, E)          E = {T, U, V}: kinetic,
                                                            strain, load potential
   vlbe_status vlbe_ale_point_force(q, pf, F, Q, K)         Q += N(pf)^T F, K += d/dq
   vlbe_status vlbe_ale_point(q, p, r, rp)                  r(p), r'(p)
   vlbe_status vlbe_ale_strain(q, p, &eps, &kap)            strain, curvature at p
   vlbe_status vlbe_ale_prestretch(EA, F, &eps, &lam)       Green strain, stretch of tension F
   vlbe_status vlbe_ale_split(q, qd, ph, qh, qhd)           exact segmentation at ph
   invariants (fixed-length elements and chains, see INVARIANTS; ALE
   elements: vlbe_ale_force with VLBE_ALE_INV_AXIAL):
   vlbe_status vlbe_ale_inv_init(inv)                       unit tables B, I, int N, dp
   vlbe_status vlbe_ale_inv_force(el, mode, q, qd, Q, K, D) vlbe_ale_force, p fixed, axial
                                                            force and load from invariants
   vlbe_status vlbe_ale_inv_chain_force(el, mode, ne, L, x, v, Q, K, D)  cable chain by an
                                                            element loop (Gauss, or invariants
                                                            with VLBE_ALE_INV_AXIAL), band K, D
   size_t vlbe_ale_inv_sys_work_len(ne)                     buffer for the system invariants
   vlbe_status vlbe_ale_inv_sys_init(sys, el, mode, ne, L, work, len)  assemble B, I, load once
   vlbe_status vlbe_ale_inv_sys_force(sys, x, v, Q, K, D)   cable chain Q, band K, D from them
   3D beam-shaft with spin (VLBSE, see the 3D section; 16 coordinates, 14
   with VLBE_ALE3_NO_SPIN):
   vlbe_status vlbe_ale3_mat_circle(mat, rho, E, G, radius)  solid circular section
   vlbe_status vlbe_ale3_elem_init(el, mat, flags, nm, ns)  element type, Gauss tables
   int vlbe_ale3_nq(mode)                                   coordinates per element
   vlbe_status vlbe_ale3_mass(el, mode, q, M)               M(q), eq. 28
   vlbe_status vlbe_ale3_mass_jac(el, mode, q, a, Mq)       d(M a)/dq
   vlbe_status vlbe_ale3_force(el, mode, q, qd, Q, K, D)    Q and (optional) K, D
   vlbe_status vlbe_ale3_energy(el, mode, q, qd, E)         E = {T, U, V}
   vlbe_status vlbe_ale3_point(mode, q, p, r, rp, th)       r, r', theta at p
   vlbe_status vlbe_ale3_strain(mode, q, p, eps, kap, phi)  strains at p
   vlbe_status vlbe_ale3_point_force(mode, q, pf, F, Q, K)  eq. 45, K += d/dq
   vlbe_status vlbe_ale3_point_torque(mode, q, pf, T, Q, K) eq. 46
   chains (node p modes fixed / prescribed / free, sliding nodes, point masses):
   vlbe_status vlbe_ale_chain_init(ch, el, nodes, nn, cap, cons, ccap)   planar
   vlbe_status vlbe_ale_chain_init3(ch, el3, nodes, nn, cap, cons, ccap) 3D beam-shaft
   vlbe_status vlbe_ale_chain_types(ch, et, els)            per-element types (rancf.h)
   vlbe_status vlbe_ale_chain_add(ch, con)                  add a constraint (VLBE_ALE_CON_*,
                                                            values in con.r / d / axis / law)
   vlbe_status vlbe_ale_chain_layout(ch)                    coordinates n, equations m
   vlbe_status vlbe_ale_chain_band(ch, order, cap)          banded callbacks in the augmented
                                                            order (order NULL: dense)
   size_t vlbe_ale_chain_at(ch, i, j)                       place of entry (i, j) in the
                                                            chain's matrices (dense or band)
   size_t vlbe_ale_chain_mat_len(ch)                        reals of one such matrix
   vlbe_status vlbe_ale_chain_pnode(ch, i, t, q, v, p3)     p, p', p'' of a node
   vlbe_status vlbe_ale_chain_gather(ch, e, t, q, v, qe, ve, idx, mode)  element view
   void vlbe_ale_chain_straight(ch, r0, dir, q)             straight start state
   vlbe_status vlbe_ale_chain_window(ch, s, lam, c)         nodes fixed in space, material
                                                            flowing at c with stretch lam
   vlbe_status vlbe_ale_chain_locate / _point(ch, t, q, p, ...)  element of p, r(p)
   vlbe_status vlbe_ale_chain_energy(ch, t, q, v, E)        T, U, V of the chain
   vlbe_status vlbe_ale_chain_length(ch, t, q, v, len, rate)  arc length, its rate
   vlbe_status vlbe_ale_chain_loads(ch, loads, n)           point loads (vlbe_ale_load: forces,
                                                            moments; fixed or moving, constant
                                                            or callback); ch->load_factor
   int vlbe_ale_chain_mass / _force / _force_jac / _mass_jac / _constr / _constr_jac
       / _constr_acc / _constr_hess(user = ch, ...)         vlbe_dae callbacks
   vlbe_status vlbe_ale_chain_dae(ch, sys)                  fill a vlbe_dae with them
   vlbe_status vlbe_ale_chain_insert(ch, e, ph, t, q, v, qn, vn)  split element e
   vlbe_status vlbe_ale_chain_remove(ch, i, t, q, v, qn, vn)  merge at node i
   vlbe_status vlbe_ale_chain_length_control(ch, Lstd, t, q, v, &s, qn, vn, &chg)

REFERENCES
   [R] Z. Ding, B. Ouyang, A variable-length rational finite element based on
       the absolute nodal coordinate formulation, Machines 10 (2022) 174,
       eqs. 12-19 (unit weights), section 5.
   [V] S. Yang et al., A variable-length beam element incorporating the effect
       of spinning, Lat. Am. J. Solids Struct. 14 (2017), eqs. 2-5, 13-17, 21-22.
   D. Hong, G. Ren, A modeling of sliding joint on one-dimensional flexible
       medium, Multibody Syst. Dyn. 26 (2011) 91-106.
   J. Gerstmayr, A. Shabana, Analysis of thin beams and cables using the
       absolute nodal co-ordinate formulation, Nonlinear Dyn. 45 (2006) 109-130.
*/
#ifndef VLBE_ANCF_ALE_H
#define VLBE_ANCF_ALE_H
#include "vlbe.h"
#include <limits.h>

#if !defined(VLBE_VERSION_MAJOR) || VLBE_VERSION_MAJOR != 0 || VLBE_VERSION_MINOR < 1
#error "ancf_ale.h needs vlbe.h 0.1 or newer in the same directory"
#endif

/* -- constants ---------------------------------------------------------- */
#define VLBE_ALE_NQ 10      /* coordinates per element        */
#define VLBE_ALE_NGP_MAX 8  /* Gauss points per term, at most */

#define VLBE_ALE_NO_BEND 1u
#define VLBE_ALE_NO_DAMP 2u
#define VLBE_ALE_FIX_P1 4u
#define VLBE_ALE_FIX_P2 8u
#define VLBE_ALE_CONSERVATIVE 16u
#define VLBE_ALE_INV_AXIAL 32u /* axial force (both p fixed: and load) from
                                  the invariants (vlbe_ale_inv_*), not Gauss */

#define VLBE_ALE_INV_NP 10 /* symmetric slot pairs of one element         */
#define VLBE_ALE_INV_KD 7  /* half bandwidth of a chain's K, D (band form) */
#define VLBE_ALE_INV_BW 15 /* stored band width, 2 KD + 1                  */

/* -- types -------------------------------------------------------------- */
/* Section and material, per unit material (reference) length. */
typedef struct vlbe_ale_mat {
    vlbe_real rhoA;  /* mass per length                                     */
    vlbe_real EA;    /* axial stiffness                                     */
    vlbe_real EI;    /* bending stiffness                                   */
    vlbe_real c_eps; /* Kelvin-Voigt coefficient of the axial strain [time] */
    vlbe_real c_kap; /* Kelvin-Voigt coefficient of the curvature [time]    */
    vlbe_real f[2];  /* constant distributed load per length (rhoA g, ...)  */
} vlbe_ale_mat;

/* One point of a rule: abscissa xi in [0,1], weight w (they sum to 1), and
   the basis numbers at L = 1: b[k][a][j] = k-th p-derivative of the a-th
   (VLBE_DA_*) p1/p2 partial of N_{j+1}; all six a for k = 0, a < 3 for
   k = 1, 2. */
typedef struct vlbe_ale_gp {
    vlbe_real xi, w;
    vlbe_real b[3][VLBE_DA_N][4];
    vlbe_real l[2][VLBE_DA_N][2]; /* the same for the linear H1, H2 (k < 2;
                                     all a at k = 0, a < 3 at k = 1): the
                                     spin angle of the 3D element */
    vlbe_real b3[4];              /* third p-derivatives of N_{j+1}       */
} vlbe_ale_gp;

typedef struct vlbe_ale_rule {
    int n;
    vlbe_ale_gp g[VLBE_ALE_NGP_MAX];
} vlbe_ale_rule;

/* Invariants of the cubic Hermite basis at unit length (xi in [0, 1], '
   = d/dxi), over the 10 symmetric slot pairs P = (a, b), a <= b, of the
   slots a = 0..3 (r1, r1', r2, r2') in the order
     (0,0) (0,1) (1,1) | (0,2) (0,3) (1,2) (1,3) | (2,2) (2,3) (3,3)
   (node 1, link, node 2): t[P*10 + R] = int h_a' h_b' h_c' h_d' dxi times
   2 for c != d (so that a contraction over R sums each unordered pair
   (c, d) once), R = (c, d); b[P] = int h_a' h_b' dxi; n[a] = int h_a dxi;
   dp[k][a*4 + c]: the partial in p_{k+1} (at fixed p, L = 1) of the slope
   h_a' as a combination of the slopes, sum_c dp[k][a*4 + c] h_c' (ALE
   elements, see INVARIANTS; small integers, slot 0's coefficient 0). */
typedef struct vlbe_ale_inv {
    vlbe_real t[VLBE_ALE_INV_NP * VLBE_ALE_INV_NP];
    vlbe_real b[VLBE_ALE_INV_NP];
    vlbe_real n[4];
    vlbe_real dp[2][16];
} vlbe_ale_inv;

/* An element type: material, default mode flags, a rule per term, the
   two element ends (xi = 0, 1; w unused) for the energy fluxes and the
   invariant tables of fixed-length elements. */
typedef struct vlbe_ale_elem {
    vlbe_ale_mat mat;
    unsigned flags;
    vlbe_ale_rule rm, rl, rt; /* mass/inertia/loads, axial, bending */
    vlbe_ale_gp ends[2];
    vlbe_ale_inv inv;
    vlbe_real bmax; /* largest |basis number| (k = 0, a <= 2) of rm: the
                       overflow bound of vlbe_ale_mass (set by init) */
} vlbe_ale_elem;

/* The system invariants of a chain of ne fixed-length elements (see
   vlbe_ale_inv_sys_init): pointers into the caller's buffer. */
typedef struct vlbe_ale_inv_sys {
    int ne, np;        /* elements, slot pairs 5 ne + 1                     */
    vlbe_real EA, c;   /* axial stiffness, Kelvin-Voigt time (0: undamped)  */
    const vlbe_real *T; /* assembled quartic invariants, band rows of pairs  */
    const vlbe_real *B; /* assembled quadratic invariants, one per pair      */
    vlbe_real *H;      /* scratch: 8 products per pair, then the slots      */
    vlbe_real Lmin, Lmax; /* shortest, longest element (overflow bound)    */
} vlbe_ale_inv_sys;

/* -- planar element and invariants: API prototypes ---------------------- */
VLBE_API vlbe_status vlbe_ale_elem_init(vlbe_ale_elem *el, const vlbe_ale_mat *mat,
                                        unsigned flags, int nm, int nl, int nt);
VLBE_API vlbe_status vlbe_ale_mass(const vlbe_ale_elem *el, unsigned mode, const vlbe_real *q,
                                   vlbe_real *VLBE_RESTRICT M);
VLBE_API vlbe_status vlbe_ale_mass_jac(const vlbe_ale_elem *el, unsigned mode, const vlbe_real *q,
                                       const vlbe_real *a, vlbe_real *VLBE_RESTRICT Mq);
VLBE_API vlbe_status vlbe_ale_force(const vlbe_ale_elem *el, unsigned mode, const vlbe_real *q,
                                    const vlbe_real *qd, vlbe_real *VLBE_RESTRICT Q,
                                    vlbe_real *VLBE_RESTRICT K, vlbe_real *VLBE_RESTRICT D);
VLBE_API vlbe_status vlbe_ale_energy(const vlbe_ale_elem *el, unsigned mode, const vlbe_real *q,
                                     const vlbe_real *qd, vlbe_real *VLBE_RESTRICT E);
VLBE_API vlbe_status vlbe_ale_point_force(const vlbe_real *q, vlbe_real pf, const vlbe_real *F,
                                          vlbe_real *VLBE_RESTRICT Q, vlbe_real *VLBE_RESTRICT K);
VLBE_API vlbe_status vlbe_ale_point(const vlbe_real *q, vlbe_real p, vlbe_real *VLBE_RESTRICT r,
                                    vlbe_real *VLBE_RESTRICT rp);
VLBE_API vlbe_status vlbe_ale_strain(const vlbe_real *q, vlbe_real p, vlbe_real *VLBE_RESTRICT eps,
                                     vlbe_real *VLBE_RESTRICT kap);
VLBE_API vlbe_status vlbe_ale_prestretch(vlbe_real EA, vlbe_real F, vlbe_real *VLBE_RESTRICT eps,
                                         vlbe_real *VLBE_RESTRICT lam);
VLBE_API vlbe_status vlbe_ale_inv_init(vlbe_ale_inv *inv);
VLBE_API vlbe_status vlbe_ale_inv_force(const vlbe_ale_elem *el, unsigned mode, const vlbe_real *q,
                                        const vlbe_real *qd, vlbe_real *VLBE_RESTRICT Q,
                                        vlbe_real *VLBE_RESTRICT K, vlbe_real *VLBE_RESTRICT D);
VLBE_API vlbe_status vlbe_ale_inv_chain_force(const vlbe_ale_elem *el, unsigned mode, int ne,
                                              const vlbe_real *L, const vlbe_real *x,
                                              const vlbe_real *v, vlbe_real *VLBE_RESTRICT Q,
                                              vlbe_real *VLBE_RESTRICT K,
                                              vlbe_real *VLBE_RESTRICT D);
VLBE_API size_t vlbe_ale_inv_sys_work_len(int ne);
VLBE_API vlbe_status vlbe_ale_inv_sys_init(vlbe_ale_inv_sys *sys, const vlbe_ale_elem *el,
                                           unsigned mode, int ne, const vlbe_real *L,
                                           vlbe_real *work, size_t work_len);
VLBE_API vlbe_status vlbe_ale_inv_sys_force(const vlbe_ale_inv_sys *sys, const vlbe_real *x,
                                            const vlbe_real *v, vlbe_real *VLBE_RESTRICT Q,
                                            vlbe_real *VLBE_RESTRICT K,
                                            vlbe_real *VLBE_RESTRICT D);

/* -- 3D beam-shaft element (VLBSE): constants, types, prototypes --------
   (the element is described with its implementation, section "3D
   beam-shaft element with spin" below) */
#define VLBE_ALE3_NO_SPIN 64u
#define VLBE_ALE3_NO_TWIST 128u
#define VLBE_ALE3_NQ 16 /* coordinates per element (with spin; 14 without) */

/* Section and material per unit material length.  vlbe_ale3_mat_circle
   fills it for a solid circular section. */
typedef struct vlbe_ale3_mat {
    vlbe_real rhoA;  /* mass per length                                    */
    vlbe_real rhoI;  /* polar mass moment of inertia per length, rho I_p   */
    vlbe_real EA;    /* axial stiffness                                    */
    vlbe_real EJ;    /* bending stiffness (J: second moment of area)       */
    vlbe_real GI;    /* torsional stiffness G I_p                          */
    vlbe_real c_eps, c_kap, c_phi; /* Kelvin-Voigt times [time]           */
    vlbe_real f[3];  /* constant distributed load per length               */
} vlbe_ale3_mat;

typedef struct vlbe_ale3_elem {
    vlbe_ale3_mat mat;
    unsigned flags;
    vlbe_ale_rule rm, rs; /* mass/inertia/loads; strains (axial, bending, twist) */
    vlbe_real bmax;       /* as vlbe_ale_elem.bmax (Hermite and linear) */
} vlbe_ale3_elem;

VLBE_API vlbe_status vlbe_ale3_mat_circle(vlbe_ale3_mat *mat, vlbe_real rho, vlbe_real E,
                                          vlbe_real G, vlbe_real radius);
VLBE_API vlbe_status vlbe_ale3_elem_init(vlbe_ale3_elem *el, const vlbe_ale3_mat *mat,
                                         unsigned flags, int nm, int ns);
VLBE_API int vlbe_ale3_nq(unsigned mode);
VLBE_API vlbe_status vlbe_ale3_mass(const vlbe_ale3_elem *el, unsigned mode, const vlbe_real *q,
                                    vlbe_real *VLBE_RESTRICT M);
VLBE_API vlbe_status vlbe_ale3_mass_jac(const vlbe_ale3_elem *el, unsigned mode,
                                        const vlbe_real *q, const vlbe_real *a,
                                        vlbe_real *VLBE_RESTRICT Mq);
VLBE_API vlbe_status vlbe_ale3_force(const vlbe_ale3_elem *el, unsigned mode, const vlbe_real *q,
                                     const vlbe_real *qd, vlbe_real *VLBE_RESTRICT Q,
                                     vlbe_real *VLBE_RESTRICT K, vlbe_real *VLBE_RESTRICT D);
VLBE_API vlbe_status vlbe_ale3_energy(const vlbe_ale3_elem *el, unsigned mode, const vlbe_real *q,
                                      const vlbe_real *qd, vlbe_real *VLBE_RESTRICT E);
VLBE_API vlbe_status vlbe_ale3_point(unsigned mode, const vlbe_real *q, vlbe_real p,
                                     vlbe_real *VLBE_RESTRICT r, vlbe_real *VLBE_RESTRICT rp,
                                     vlbe_real *VLBE_RESTRICT th);
VLBE_API vlbe_status vlbe_ale3_strain(unsigned mode, const vlbe_real *q, vlbe_real p,
                                      vlbe_real *VLBE_RESTRICT eps, vlbe_real *VLBE_RESTRICT kap,
                                      vlbe_real *VLBE_RESTRICT phi);
VLBE_API vlbe_status vlbe_ale3_point_force(unsigned mode, const vlbe_real *q, vlbe_real pf,
                                           const vlbe_real *F, vlbe_real *VLBE_RESTRICT Q,
                                           vlbe_real *VLBE_RESTRICT K);
VLBE_API vlbe_status vlbe_ale3_point_torque(unsigned mode, const vlbe_real *q, vlbe_real pf,
                                            vlbe_real T, vlbe_real *VLBE_RESTRICT Q,
                                            vlbe_real *VLBE_RESTRICT K);

/* -- chains of elements: constants, types, prototypes ------------------ */
/* material-coordinate mode of a node */
#define VLBE_ALE_PFIXED 0      /* p constant (node.p), not a coordinate            */
#define VLBE_ALE_PPRESCRIBED 1 /* p(t) given (pfun or node.p + pd t + pdd t^2/2)   */
#define VLBE_ALE_PFREE 2       /* p is a coordinate (initial value node.p)         */

/* constraint types (equations each: planar / 3D).  The values a type reads
   are named fields of vlbe_ale_con (r, d, axis, law; the others unused). */
#define VLBE_ALE_CON_POS 1       /* r_node = r (components: `which` mask)     (2 / 3) */
#define VLBE_ALE_CON_SLOPE_DIR 2 /* r'_node parallel to d, |r'| free (slope `which`):
                                    planar r' x d = 0; 3D r'.b1 = r'.b2 = 0, b1, b2
                                    the orthonormal pair of vlbe__ale_perp (1 / 2) */
#define VLBE_ALE_CON_SLOPE 3     /* r'_node = d (slope `which`)               (2 / 3) */
#define VLBE_ALE_CON_P 4         /* p_node = g(t) of law (free node)          (1 / 1) */
#define VLBE_ALE_CON_EQUAL_LEN 5 /* nodes node..node2 equally spaced in p (eq. 51 of [V]) (node2-node-1) */
#define VLBE_ALE_CON_SLIDE_C 6   /* sliding node: r'(1) = r'(2) (eq. 40 of [R]) (2 / -) */
#define VLBE_ALE_CON_SLIDE_D 7   /* sliding node: |r'(1)| = |r'(2)| (eq. 40)  (1 / -) */
#define VLBE_ALE_CON_SLOPE_ANGLE 8 /* r'_node x (cos a, sin a) = 0, a(t) = g(t) of law
                                      or the chain's afun (slope `which`)     (1 / -) */
#define VLBE_ALE_CON_SPIN 9      /* 3D with spin: theta_node = g(t) of law
                                    (a prescribed spin angle, or rate law[1]) (- / 1) */
#define VLBE_ALE_CON_SLOPE_ROT 10 /* 3D: r'_node parallel to e(t) = R(k, a(t)) e0 (a hub
                                     turning about axis k by a(t) = g(t) of law or the
                                     chain's afun), |r'| free: r'.R b1 = r'.R b2 = 0,
                                     e0 = d, k = axis, b1, b2 of e0 as SLOPE_DIR (- / 2) */
/* g(t) = law[0] + law[1] t + law[2] t^2 / 2.  In a 3D chain
   (vlbe_ale_chain_init3) POS and SLOPE have 3 rows (a spherical joint, eq.
   50 of [V]; POS + SLOPE: a clamp that also holds |r'|, the axial strain
   at the node; POS + SLOPE_DIR or POS + SLOPE_ROT: a clamp leaving the
   axial strain free), and SLOPE_ANGLE, SLIDE_C, SLIDE_D and sliding nodes
   are planar only.  SLOPE_DIR's d, SLOPE_ROT's d and axis need not be unit
   vectors but must not be zero (vlbe_ale_chain_add: VLBE_EARG); an axis
   along e0 is allowed (the slope direction then stays e0).  Spin angle
   under SLOPE_ROT: theta of [V] is the turn of the cross section about the
   beam axis (the third Tait-Bryan angle, section 2), a coordinate of its
   own that enters M and Q only through its own inertia and twist (eqs. 23,
   27-28, 38, 40), so the constraint holds r' only.  A hub turning about k turns
   the root section about the beam axis at the rate a' (k.e) / |k| |e|,
   and k.e(t) = k.e0 is constant, so a chain with spin whose root turns
   with the hub adds VLBE_ALE_CON_SPIN at the node with law = (theta_0, c g1,
   c g2), c = k.e0 / (|k| |e0|) (0 for an axis across the beam, as for a
   radial blade on a hub: theta_0 held), or for an afun a SPIN law of its
   own rates. */

typedef struct vlbe_ale_node {
    int pmode;     /* VLBE_ALE_PFIXED / PPRESCRIBED / PFREE                          */
    int slide;     /* 1: two slope vectors, left r'(1) and right r'(2) of the node   */
    vlbe_real p;   /* fixed value, p(0) when prescribed, initial value when free     */
    vlbe_real pd;  /* prescribed: p'(t) = pd + pdd t (unless the chain has a pfun)   */
    vlbe_real pdd;
    vlbe_real mass; /* point mass carried by the node (a sliding mass: pmode free)   */
    int ofs;       /* set by vlbe_ale_chain_layout: first coordinate in q            */
} vlbe_ale_node;

typedef struct vlbe_ale_con {
    int type;
    int node, node2;   /* node2: last node of VLBE_ALE_CON_EQUAL_LEN                  */
    int which;         /* slope constraints on a sliding node: 0 left, 1 right;
                          VLBE_ALE_CON_POS: mask of the components held (bit k:
                          component k; 0 = all), e.g. 3 = a roller free along z */
    vlbe_real r[3];    /* POS: the position held [m]                                 */
    vlbe_real d[3];    /* SLOPE: the slope r' held; SLOPE_DIR: the direction (not
                          zero, any length); SLOPE_ROT: e0, the direction at a = 0 */
    vlbe_real axis[3]; /* SLOPE_ROT: the rotation axis k (not zero, any length)       */
    vlbe_real law[3];  /* P, SPIN, SLOPE_ANGLE, SLOPE_ROT: g0, g1, g2 of g(t) = g0 + g1 t
                          + g2 t^2/2 [m or rad] (SLOPE_ANGLE, SLOPE_ROT: unused when
                          the chain has an afun) */
} vlbe_ale_con;

/* Per-element types of a planar chain whose elements differ, e.g. rational
   elements each with its own weights (rancf.h, vlbe_rancf_chain_init).
   els is the caller's array of element objects (capacity nn_cap - 1),
   element e of the chain being object e; the chain reaches it only
   through these calls, and keeps the array in step when length control
   inserts or removes nodes:
     elem    the element type of element e (mass, forces, energy);
     basis   its basis at p (the contract of vlbe_herm_ale_eval);
     split   segmentation of element e (coordinates q, rates qd or NULL)
             at ph: the node qh, qhd (the contract of vlbe_ale_split) and,
             in aux (VLBE_ALE_ETYPE_AUX reals), what commit needs; nothing
             changes;
     merge   elements e and e+1 (nodes na, nh, nb, 5 reals each: r, r', p)
             replaced by one between na and nb: what commit needs in aux;
             nothing changes;
     commit  op = +1: element e (of ne) becomes the two elements e, e+1
             (the later ones shift up); op = -1: elements e, e+1 (of ne)
             become one (the later ones shift down); aux from split or
             merge, which validated it: commit cannot fail. */
#define VLBE_ALE_ETYPE_AUX 10
typedef struct vlbe_ale_etype {
    const vlbe_ale_elem *(*elem)(const void *els, int e);
    void (*basis)(const void *els, int e, vlbe_real p, vlbe_real p1, vlbe_real p2, int kmax,
                  int amax, vlbe_herm_ale *b);
    vlbe_status (*split)(const void *els, int e, const vlbe_real *q, const vlbe_real *qd,
                         vlbe_real ph, vlbe_real *qh, vlbe_real *qhd, vlbe_real *aux);
    vlbe_status (*merge)(const void *els, int e, const vlbe_real *na, const vlbe_real *nh,
                         const vlbe_real *nb, vlbe_real *aux);
    void (*commit)(void *els, int ne, int e, int op, const vlbe_real *aux);
} vlbe_ale_etype;

/* A point load on a chain (an array of them is given to the chain with
   vlbe_ale_chain_loads; the chain keeps the pointer, never a copy).  It
   acts at the material point p(t) = p[0] + p[1] t + p[2] t^2/2 (p[1] = p[2]
   = 0: a fixed material point; else a load moving along the chain, e.g. a
   vehicle on a bridge or a carriage), located at each call in the first
   element whose [p1, p2] holds it at the current q, t (at a node shared by
   two elements: the left one; at a sliding node: its left slope).  Kinds:
     VLBE_ALE_LOAD_FORCE   a force in global axes, d components;
                           Q += N(p)^T f (eq. 45 of [V]), the virtual work
                           at the material point (p-rows: f . dr/dp_k at
                           fixed p, as vlbe_ale_point_force);
     VLBE_ALE_LOAD_MOMENT  f[0]: planar chains, a moment about z acting on
                           the slope angle phi = atan2(y', x') (Q +=
                           f0 dphi/dq; a zero slope at p: VLBE_ESINGULAR);
                           3D chains with spin, a torque about the beam
                           axis acting on the spin angle (eq. 46 of [V],
                           as vlbe_ale3_point_torque); 3D without spin:
                           VLBE_EARG;
     VLBE_ALE_LOAD_MOMENT3 3D chains: a moment vector M = f[0..2] in global
                           axes, its virtual work on the rotation of the
                           section, t x dt + dtheta t (t = r'/|r'|, the
                           spin angle theta being the section's rotation
                           about t, as its twist theta' says): Q = (dr'/dq)^T
                           (M x r')/|r'|^2 + (M . t) dtheta/dq -- the
                           bending part through the slope, the axial part
                           as eq. 46; without spin the axial part does no
                           work (no coordinate).  A planar chain: VLBE_EARG;
                           a zero slope at p: VLBE_ESINGULAR.
   Value: f (constant) when fun is NULL, else fun(user, t, r, rd, f, dfr,
   dfv) with the position r and velocity rd = dr/dt of the point (d each;
   rd = N(p) v + r'(p) p'(t), the load's own travel along the chain
   included), which writes f (d components for a force, 1 for a moment, 3
   for MOMENT3)
   and returns 0 (non-zero: the chain's callback fails with
   VLBE_ECALLBACK).  dfr, dfv (nc x d row-major, nc the components of f)
   are NULL in the force call; in the Jacobian call they are zeroed and
   fun may write df/dr, df/drd there (the chain's K and D then carry the
   load's dependence on the state; left zero, the load counts as a dead
   load in K and D).  The chain's load factor scales the value (and its
   derivatives).  outside = 0: a p(t) outside the chain's material range
   makes the callbacks fail with VLBE_EBOUND (fatal, -1); outside = 1: the
   load is absent (no force) while p(t) is outside.
   The chain's force and force_jac check every load before they write
   anything: an unknown kind or outside flag, a MOMENT in a 3D chain
   without spin, a MOMENT3 in a planar one (VLBE_EARG, -1), NaN/Inf in a law, a constant value or
   load_factor (VLBE_ENONFINITE, 1), p(t) outside the range (above); the
   load's index goes to ch->err_load (-1 for every other failure).  A
   failing or non-finite fun, or a zero slope under a planar moment
   (VLBE_ESINGULAR), shows during the assembly (outputs unspecified, as
   for an element's failure). */
#define VLBE_ALE_LOAD_FORCE 1
#define VLBE_ALE_LOAD_MOMENT 2
#define VLBE_ALE_LOAD_MOMENT3 3
typedef struct vlbe_ale_load {
    int kind;        /* VLBE_ALE_LOAD_FORCE / _MOMENT                           */
    int outside;     /* 0: outside the material range is an error; 1: no load   */
    vlbe_real p[3];  /* material point p(t) = p[0] + p[1] t + p[2] t^2/2         */
    vlbe_real f[3];  /* constant value (force d components, moment f[0])        */
    int (*fun)(void *user, vlbe_real t, const vlbe_real *r, const vlbe_real *rd,
               vlbe_real *f, vlbe_real *dfr, vlbe_real *dfv);
    void *user;      /* fun's own pointer                                       */
} vlbe_ale_load;

/* A chain: nodes 0..nn-1, element e between nodes e and e+1 with increasing
   material coordinates.  Global coordinates node by node:
   planar  [x, y, x', y' (, x'(2), y'(2) if sliding) (, p if free)],
   3D      [r(3), r'(3) (, theta with spin) (, p if free)]
   (vlbe_ale_chain_init3: a chain of vlbe_ale3_elem).  The arrays are the
   caller's; the chain never allocates.
   Banded mode (vlbe_ale_chain_band, then vlbe_ale_chain_layout): the
   matrix callbacks write (n + m) x (n + m) band matrices (vlbe.h, Band
   storage, ld = kl + ku + 1) in the augmented order of the system
   [M*, C_q^T; C_q, 0]: entry (i, j) of M, K, D, Mq, Mv, H at
   VLBE_BAND_IDX(ld, kl, order[i], order[j]), entry (k, j) of C_q at
   VLBE_BAND_IDX(ld, kl, order[n + k], order[j]) (C_q only, not its
   transpose); each writes all (n + m) ld slots, zeros where there is no
   entry.  Vectors (Q, C, Ct, gamma, and q, v, a, lambda) keep the natural
   order.  Layout writes order[0 .. n+m-1]: node by node, node i's
   coordinates in q order, then the constraint rows whose highest touched
   coordinate belongs to node i, in row order; the rows that touch node 0
   alone come first, before node 0 (no neighbour on that side: a clamp
   there does not widen the band).  kl = ku = the largest
   |order[a] - order[b]| over the coupled pairs (two coordinates of one
   element; a constraint row and a coordinate it touches), read from the
   structure, not bounded: an element couples the coordinates of its two
   nodes, up to 9 apart for planar ALE nodes (5 coordinates each; 7 with
   fixed p's, 15 for 3D ALE nodes with spin), and the rows of an interior
   node's constraints sit between them, widening the band by their number
   (a clamped Lagrangian cantilever: 7, its clamp rows before node 0).  It does not grow
   with the number of elements, except that an equal-length group ending
   at a free p couples all its rows to that end.  Storage: (n + m)(kl + ku
   + 1) reals a matrix instead of n^2.
   Loads: the distributed loads mat.f of the element types, gravity g on the
   point masses and the point loads (vlbe_ale_load) are all multiplied by
   load_factor (1 after init): load stepping with vlbe_dae_static.  Between
   two calls (steps, load increments) a caller may change load_factor, g,
   the point loads' values, laws and callbacks (in the array given to
   vlbe_ale_chain_loads, or another array through that call), pfun, afun,
   user and Lmin; mat.f lives in the element type, which the chain reads
   at every call (changing it changes every chain using that type).  Only
   followed by vlbe_ale_chain_layout: the nodes' pmode and slide, the
   number of nodes and constraints, mode, the banded switch. */
typedef struct vlbe_ale_chain {
    const vlbe_ale_elem *el;    /* planar element type (NULL in a 3D chain)      */
    const vlbe_ale_etype *et;   /* per-element types (NULL: el for every element) */
    void *els;                  /* their objects (see vlbe_ale_etype)             */
    const vlbe_ale3_elem *el3;  /* 3D element type (NULL in a planar chain)      */
    int d, spin;         /* set by layout: dimension 2 or 3, spin angle per node  */
    unsigned mode;       /* OR'ed into every element's mode                        */
    int nn, nn_cap;      /* nodes, capacity of node[]                              */
    vlbe_ale_node *node;
    int ncon, ncon_cap;
    vlbe_ale_con *con;
    int n, m;            /* coordinates, constraint equations (layout)             */
    vlbe_real g[3];      /* gravity on the point masses (g[2]: 3D only)            */
    vlbe_real Lmin;      /* element length below which callbacks fail (ELENGTH)   */
    /* optional p(t), p'(t), p''(t) of prescribed nodes; returns 0 on success */
    int (*pfun)(void *user, int node, vlbe_real t, vlbe_real *p3);
    /* optional a(t), a'(t), a''(t) of the VLBE_ALE_CON_SLOPE_ANGLE or
       VLBE_ALE_CON_SLOPE_ROT constraint `con` (its index in con[]), e.g. a hub
       angle; returns 0 on success */
    int (*afun)(void *user, int con, vlbe_real t, vlbe_real *a3);
    void *user;
    vlbe_status err;     /* status of the last failed callback (VLBE_OK if none)   */
    int err_elem;        /* element (or node) where it happened                    */
    /* banded mode (vlbe_ale_chain_band; NULL = dense, the default) */
    int *order;          /* caller storage of the augmented order, order_cap ints  */
    int order_cap;
    int kl, ku;          /* set by layout in banded mode: half-bandwidths of the
                            augmented matrix (kl == ku)                            */
    /* loads (see above) */
    vlbe_real load_factor;      /* scales mat.f, g and the point loads (init: 1)   */
    const vlbe_ale_load *loads; /* point loads (vlbe_ale_chain_loads; NULL: none)   */
    int nloads;
    int err_load;        /* the point load of the last failure (-1: not a load)    */
} vlbe_ale_chain;

/* chains: API prototypes */
VLBE_API vlbe_status vlbe_ale_chain_init(vlbe_ale_chain *ch, const vlbe_ale_elem *el,
                                         vlbe_ale_node *nodes, int nn, int nn_cap,
                                         vlbe_ale_con *cons, int ncon_cap);
VLBE_API vlbe_status vlbe_ale_chain_init3(vlbe_ale_chain *ch, const vlbe_ale3_elem *el3,
                                          vlbe_ale_node *nodes, int nn, int nn_cap,
                                          vlbe_ale_con *cons, int ncon_cap);
VLBE_API vlbe_status vlbe_ale_chain_types(vlbe_ale_chain *ch, const vlbe_ale_etype *et, void *els);
VLBE_API vlbe_status vlbe_ale_chain_add(vlbe_ale_chain *ch, const vlbe_ale_con *c);
VLBE_API vlbe_status vlbe_ale_chain_layout(vlbe_ale_chain *ch);
VLBE_API vlbe_status vlbe_ale_chain_band(vlbe_ale_chain *ch, int *order, int order_cap);
VLBE_API size_t vlbe_ale_chain_at(const vlbe_ale_chain *ch, int i, int j);
VLBE_API size_t vlbe_ale_chain_mat_len(const vlbe_ale_chain *ch);
VLBE_API vlbe_status vlbe_ale_chain_pnode(const vlbe_ale_chain *ch, int i, vlbe_real t,
                                          const vlbe_real *q, const vlbe_real *v, vlbe_real *p3);
VLBE_API vlbe_status vlbe_ale_chain_gather(const vlbe_ale_chain *ch, int e, vlbe_real t,
                                           const vlbe_real *q, const vlbe_real *v, vlbe_real *qe,
                                           vlbe_real *ve, int *idx, unsigned *mode);
VLBE_API void vlbe_ale_chain_straight(const vlbe_ale_chain *ch, const vlbe_real *r0,
                                      const vlbe_real *dir, vlbe_real *q);
VLBE_API vlbe_status vlbe_ale_chain_window(vlbe_ale_chain *ch, const vlbe_real *s, vlbe_real lam,
                                           vlbe_real c);
VLBE_API vlbe_status vlbe_ale_chain_locate(const vlbe_ale_chain *ch, vlbe_real t,
                                           const vlbe_real *q, vlbe_real p, int *e);
VLBE_API vlbe_status vlbe_ale_chain_point(const vlbe_ale_chain *ch, vlbe_real t, const vlbe_real *q,
                                          vlbe_real p, vlbe_real *r, vlbe_real *rp);
VLBE_API vlbe_status vlbe_ale_chain_energy(vlbe_ale_chain *ch, vlbe_real t, const vlbe_real *q,
                                           const vlbe_real *v, vlbe_real *E);
VLBE_API vlbe_status vlbe_ale_chain_length(const vlbe_ale_chain *ch, vlbe_real t,
                                           const vlbe_real *q, const vlbe_real *v, vlbe_real *len,
                                           vlbe_real *rate);
VLBE_API vlbe_status vlbe_ale_chain_loads(vlbe_ale_chain *ch, const vlbe_ale_load *loads, int n);
/* vlbe_dae callbacks (user = the chain).  They return 0, or on failure
   the value of vlbe_dae's table (vlbe__dae_rc, vlbe.h: 1, the state is
   outside the model's domain, the integrator may retry; -1: fatal; a point
   load off the chain: -1) with the status and the element (-1:
   none, or a constraint) in ch->err, ch->err_elem -- the only change a call
   makes to the chain (the convention of every model, vlbe.h at vlbe_dae).  Non-finite q, v (force, force_jac), a (mass_jac) or
   lambda (constr_hess) are found before anything is written: VLBE_ENONFINITE
   (for q, v, a with the first element that meets them) and the outputs
   untouched.  Exception to the rule that a failed call writes nothing: a
   failure on finite inputs -- an element shorter than Lmin, out of its
   domain or failing, a failing or NaN pfun / afun, a zero slope of
   SLIDE_D, a sum that overflows (VLBE_ENONFINITE) -- leaves M, Q, K, D, Mq,
   Mv, C, Cq, Ct, gamma, H unspecified: they are assembled in place (n x n,
   or band arrays in banded mode; the chain has no room for a copy) and an
   element's failure shows only after the earlier elements were added.  The
   integrators treat them as scratch after a failure.  force_jac: K or D
   may be NULL; mass_jac: Mv may be NULL (it is zero: M does not depend on
   v); constr_jac: Ct may be NULL. */
VLBE_API int vlbe_ale_chain_mass(void *user, vlbe_real t, const vlbe_real *q, const vlbe_real *v,
                                 vlbe_real *M);
VLBE_API int vlbe_ale_chain_force(void *user, vlbe_real t, const vlbe_real *q, const vlbe_real *v,
                                  vlbe_real *Q);
VLBE_API int vlbe_ale_chain_force_jac(void *user, vlbe_real t, const vlbe_real *q,
                                      const vlbe_real *v, vlbe_real *K, vlbe_real *D);
VLBE_API int vlbe_ale_chain_mass_jac(void *user, vlbe_real t, const vlbe_real *q,
                                     const vlbe_real *v, const vlbe_real *a, vlbe_real *Mq,
                                     vlbe_real *Mv);
VLBE_API int vlbe_ale_chain_constr(void *user, vlbe_real t, const vlbe_real *q, vlbe_real *C);
VLBE_API int vlbe_ale_chain_constr_jac(void *user, vlbe_real t, const vlbe_real *q, vlbe_real *Cq,
                                       vlbe_real *Ct);
VLBE_API int vlbe_ale_chain_constr_acc(void *user, vlbe_real t, const vlbe_real *q,
                                       const vlbe_real *v, vlbe_real *gamma);
VLBE_API int vlbe_ale_chain_constr_hess(void *user, vlbe_real t, const vlbe_real *q,
                                        const vlbe_real *lambda, vlbe_real *H);
/* The vlbe_dae (vlbe.h) of the chain: n, m, every callback above, user =
   ch, the flags (VLBE_DAE_MASS_CONST for a planar chain whose material
   coordinates are all fixed: the classic constant ANCF mass, point masses
   included; none otherwise: M depends on the nodal p's, and a 3D chain's
   on the spin) and the storage (banded with the chain's order and
   half-bandwidths in banded mode, else dense).  Everything else of *sys
   is zeroed.  Call after vlbe_ale_chain_layout and again after every
   change of the layout (length control, insert, remove); VLBE_EARG before
   the first layout (sys untouched).  To add forces of one's own, wrap
   sys->force (and force_jac) in functions that call the chain's and keep
   sys->user = ch, or point sys->user at a struct holding the chain. */
VLBE_API vlbe_status vlbe_ale_chain_dae(vlbe_ale_chain *ch, vlbe_dae *sys);

/* -- segmentation, merging, length control: prototypes ----------------- */
VLBE_API vlbe_status vlbe_ale_split(const vlbe_real *q, const vlbe_real *qd, vlbe_real ph,
                                    vlbe_real *VLBE_RESTRICT qh, vlbe_real *VLBE_RESTRICT qhd);
VLBE_API vlbe_status vlbe_ale_chain_insert(vlbe_ale_chain *ch, int e, vlbe_real ph, vlbe_real t,
                                           const vlbe_real *q, const vlbe_real *v,
                                           vlbe_real *qn, vlbe_real *vn);
VLBE_API vlbe_status vlbe_ale_chain_remove(vlbe_ale_chain *ch, int i, vlbe_real t,
                                           const vlbe_real *q, const vlbe_real *v, vlbe_real *qn,
                                           vlbe_real *vn);
VLBE_API vlbe_status vlbe_ale_chain_length_control(vlbe_ale_chain *ch, vlbe_real Lstd, vlbe_real t,
                                                   const vlbe_real *q, const vlbe_real *v,
                                                   int *slider, vlbe_real *qn, vlbe_real *vn,
                                                   int *changed);

/* ===== implementation =================================================== */

/* NOTES (how the Jacobians are formed)
   At a fixed abscissa xi every basis function is L^(m_j - k - |a|) times a
   number (m_j = 0 for positions, 1 for slopes; k p-derivatives; |a|
   partials in p1, p2), so vlbe_ale_elem_init tabulates those numbers once
   from vlbe_herm_ale_eval and an evaluation only scales them.  For the same
   reason every row of Q is a homogeneous function of (L, e_slope, e'_slope,
   p1', p2') of known degree d: scaling material lengths by s multiplies
   slopes and their rates by 1/s and p' by s.  Euler's theorem then gives
        L dQ/dp2 = d Q + sum_slope (K_e e + D_e e') - p1' D_p1 - p2' D_p2,
   and dQ/dp1 = -dQ/dp2 (the element depends on p1, p2 through L only), so
   the p-columns of K follow from the e-columns and from D at the cost of a
   few dot products.  The axial force is the sum of a part of degree d - 4
   and a part of degree d - 2 (the -1 in eps) and is split accordingly.
   Virtual work at fixed p (eq. 17) misses, in the p-rows, the flux of
   strain energy through an element end that moves in the material: the
   gradient of U = int (EA eps^2 + EI kap^2)/2 dp has Q_p1 += u(p1) and
   Q_p2 -= u(p2) more, u = (EA eps^2 + EI kap^2)/2.  In a chain these cancel
   at every node where eps and kap are continuous; kap is not (cubic
   elements are only C1), so with free material coordinates the paper's
   form exchanges energy at the moving nodes.  VLBE_ALE_CONSERVATIVE adds
   the fluxes (and their Jacobian).
   The same scaling gives the p1/p2 partials of one basis function from its
   p-derivatives: at fixed p, d/dp2 N^(c)_j = ((m_j - c)/L) N^(c)_j -
   xi N^(c+1)_j and d/dp1 = -(d/dp2 + d/dp).  vlbe_ale_force without K and
   D uses it (only the rows N, N', N'' are scaled per point, r''' is
   constant) and takes the curvature factors |r'|^-2, |r'|^-3 of all
   bending points together; with K or D it evaluates the partial rows
   themselves, as the Jacobian needs them.  The two routes agree to rounding
   (test: 64 EPS of max|Q|). */

/* ===== planar ALE-ANCF element ========================================== */


/* index in q of basis j's 2-vector (0, 2, 5, 7), the power m_j of L it
   carries, and the index of p_{k+1} */
#define VLBE__ALE_E(j) ((j) * 2 + ((j) >= 2 ? 1 : 0))
#define VLBE__ALE_M(j) ((j) & 1)
#define VLBE__ALE_P(k) (4 + 5 * (k))

/* One rule point from a basis evaluated at p = xi on [0, 1] (k <= 3, all
   partials): the Hermite one here, the rational one in rancf.h. */
VLBE_INLINE void vlbe__ale_gp_set(vlbe_ale_gp *gp, vlbe_real xi, vlbe_real w,
                                    const vlbe_herm_ale *b)
{
    int k, a, j;
    gp->xi = xi;
    gp->w = w;
    for (j = 0; j < 4; ++j) gp->b3[j] = b->h[3][0][j];
    for (k = 0; k < 3; ++k)
        for (a = 0; a < VLBE_DA_N; ++a) {
            for (j = 0; j < 4; ++j)
                gp->b[k][a][j] = (k == 0 || a < 3) ? b->h[k][a][j] : VLBE_R(0.0);
            for (j = 0; k < 2 && j < 2; ++j)
                gp->l[k][a][j] = (k == 0 || a < 3) ? b->l[k][a][j] : VLBE_R(0.0);
        }
}

VLBE_INLINE void vlbe__ale_gp_fill(vlbe_ale_gp *gp, vlbe_real xi, vlbe_real w)
{
    vlbe_herm_ale b;
    vlbe_herm_ale_eval(xi, VLBE_R(0.0), VLBE_R(1.0), 3, 2, &b);
    vlbe__ale_gp_set(gp, xi, w, &b);
}

VLBE_INLINE vlbe_status vlbe__ale_rule(vlbe_ale_rule *r, int n, int ndef)
{
    const vlbe_real *x, *w;
    int g;
    if (n == 0) n = ndef;
    if (n < 1 || n > VLBE_ALE_NGP_MAX) return VLBE_EARG;
    if (vlbe_gl_rule(n, &x, &w)) return VLBE_EARG;
    r->n = n;
    for (g = 0; g < n; ++g)
        vlbe__ale_gp_fill(&r->g[g], VLBE_R(0.5) * (x[g] + VLBE_R(1.0)), VLBE_R(0.5) * w[g]);
    return VLBE_OK;
}

/* the largest |b[0][a][j]|, |l[0][a][j]| (a <= 2) of a rule: N and its
   first p1/p2 partials at L = 1 (vlbe__ale_mass_ok) */
VLBE_INLINE vlbe_real vlbe__ale_rule_bmax(const vlbe_ale_rule *r)
{
    vlbe_real m = VLBE_R(0.0);
    int g, a, j;
    for (g = 0; g < r->n; ++g)
        for (a = 0; a < 3; ++a) {
            for (j = 0; j < 4; ++j) {
                const vlbe_real t = vlbe_fabs(r->g[g].b[0][a][j]);
                m = t > m ? t : m;
            }
            for (j = 0; j < 2; ++j) {
                const vlbe_real t = vlbe_fabs(r->g[g].l[0][a][j]);
                m = t > m ? t : m;
            }
        }
    return m;
}

/* The arguments of vlbe_ale_elem_init (also checked by the rational
   element before it writes anything): a finite material with rhoA > 0 and
   the other constants >= 0, rule orders 0 (default) .. VLBE_ALE_NGP_MAX. */
VLBE_INLINE vlbe_status vlbe__ale_elem_check(const vlbe_ale_mat *mat, int nm, int nl, int nt)
{
    if (!vlbe_all_finite(&mat->rhoA, 1) || !vlbe_all_finite(&mat->EA, 1) ||
        !vlbe_all_finite(&mat->EI, 1) || !vlbe_all_finite(&mat->c_eps, 1) ||
        !vlbe_all_finite(&mat->c_kap, 1) || !vlbe_all_finite(mat->f, 2))
        return VLBE_ENONFINITE;
    if (!(mat->rhoA > VLBE_R(0.0)) || mat->EA < VLBE_R(0.0) || mat->EI < VLBE_R(0.0) ||
        mat->c_eps < VLBE_R(0.0) || mat->c_kap < VLBE_R(0.0))
        return VLBE_EARG;
    if (nm < 0 || nm > VLBE_ALE_NGP_MAX || nl < 0 || nl > VLBE_ALE_NGP_MAX || nt < 0 ||
        nt > VLBE_ALE_NGP_MAX)
        return VLBE_EARG;
    return VLBE_OK;
}

VLBE_API vlbe_status vlbe_ale_elem_init(vlbe_ale_elem *el, const vlbe_ale_mat *mat,
                                        unsigned flags, int nm, int nl, int nt)
{
    vlbe_status st;
    VLBE_ASSERT(el != NULL && mat != NULL);
    if ((st = vlbe__ale_elem_check(mat, nm, nl, nt)) != VLBE_OK) return st;
    /* nothing can fail below: el is written only now */
    if ((st = vlbe__ale_rule(&el->rm, nm, 4)) != VLBE_OK) return st;
    if ((st = vlbe__ale_rule(&el->rl, nl, 5)) != VLBE_OK) return st;
    if ((st = vlbe__ale_rule(&el->rt, nt, 5)) != VLBE_OK) return st;
    vlbe__ale_gp_fill(&el->ends[0], VLBE_R(0.0), VLBE_R(0.0));
    vlbe__ale_gp_fill(&el->ends[1], VLBE_R(1.0), VLBE_R(0.0));
    if ((st = vlbe_ale_inv_init(&el->inv)) != VLBE_OK) return st;
    el->bmax = vlbe__ale_rule_bmax(&el->rm);
    el->mat = *mat;
    el->flags = flags;
    return VLBE_OK;
}

/* One material point at fixed xi: the basis scaled to the current L and its
   contractions with e and e'. */
typedef struct vlbe__ale_pt {
    vlbe_real N[3][VLBE_DA_N][4]; /* N[k][a][j] = L^(m_j-k-|a|) b[k][a][j]  */
    vlbe_real X[3][VLBE_DA_N][2]; /* X[k][a] = sum_j N[k][a][j] e_j         */
    vlbe_real V[3][3][2];         /* V[k][a] = sum_j N[k][a][j] u_j, a < 3  */
} vlbe__ale_pt;

/* Lp[i] = L^(i - 4), i = 0..5: every power of L a basis number carries;
   computed once per call. */
VLBE_INLINE void vlbe__ale_lpow(vlbe_real L, vlbe_real *Lp)
{
    const vlbe_real r = VLBE_R(1.0) / L;
    Lp[4] = VLBE_R(1.0);
    Lp[5] = L;
    Lp[3] = r;
    Lp[2] = r * r;
    Lp[1] = Lp[2] * r;
    Lp[0] = Lp[2] * Lp[2];
}

/* Rows k0..kmax of p-derivatives; na: p1/p2 partials wanted (1: none, 3:
   first, VLBE_DA_N: also the second ones, at k = 0 only; rows k > 0 have at
   most 3); Lp from vlbe__ale_lpow; u (may be NULL): the rate-like vector to
   contract into V (q' or an acceleration), for the partials a < nu.
   Entries not asked for are left unset. */
VLBE_INLINE void vlbe__ale_pt_eval(const vlbe_ale_gp *gp, const vlbe_real *Lp, int k0, int kmax,
                                     int na, const vlbe_real *q, const vlbe_real *u, int nu,
                                     vlbe__ale_pt *VLBE_RESTRICT pt)
{
    const vlbe_real *e0 = q, *e1 = q + 2, *e2 = q + 5, *e3 = q + 7;
    int k, a;
    for (k = k0; k <= kmax; ++k) {
        const int nak = (k == 0 || na < 3) ? na : 3;
        for (a = 0; a < nak; ++a) {
            const int d = 4 - k - (a == 0 ? 0 : (a < 3 ? 1 : 2));
            const vlbe_real *b = gp->b[k][a];
            const vlbe_real n0 = b[0] * Lp[d], n1 = b[1] * Lp[d + 1], n2 = b[2] * Lp[d],
                            n3 = b[3] * Lp[d + 1];
            vlbe_real *N = pt->N[k][a], *X = pt->X[k][a];
            N[0] = n0;
            N[1] = n1;
            N[2] = n2;
            N[3] = n3;
            X[0] = n0 * e0[0] + n1 * e1[0] + n2 * e2[0] + n3 * e3[0];
            X[1] = n0 * e0[1] + n1 * e1[1] + n2 * e2[1] + n3 * e3[1];
            if (u && a < nu) {
                vlbe_real *V = pt->V[k][a];
                V[0] = n0 * u[0] + n1 * u[2] + n2 * u[5] + n3 * u[7];
                V[1] = n0 * u[1] + n1 * u[3] + n2 * u[6] + n3 * u[8];
            }
        }
    }
}


/* Shortest element length: L^-4, the largest power of 1/L the element's
   basis carries (vlbe__ale_lpow), stays finite, with a little room
   (double: 1.8e-77 > 2^-255, (1/L)^4 < 2^1020; float: 4.7e-10 > 2^-31,
   (1/L)^4 < 2^124). */
#ifdef VLBE_USE_FLOAT
#define VLBE__ALE_LMIN VLBE_R(4.7e-10)
#else
#define VLBE__ALE_LMIN VLBE_R(1.8e-77)
#endif

/* The element length L = p2 - p1 in range: VLBE__ALE_LMIN <= L <=
   REAL_MAX; VLBE_ELENGTH otherwise (L <= 0, L^-4 overflows, p2 - p1
   overflowed).  Two compares, no division: every element call makes it. */
VLBE_INLINE vlbe_status vlbe__ale_len(vlbe_real p1, vlbe_real p2)
{
    const vlbe_real L = p2 - p1;
    if (!(L >= VLBE__ALE_LMIN && L <= VLBE_REAL_MAX)) return VLBE_ELENGTH;
    return VLBE_OK;
}

/* Input checks shared by the eval functions. */
VLBE_INLINE vlbe_status vlbe__ale_check(const vlbe_real *q, const vlbe_real *qd)
{
    if (!vlbe_all_finite(q, VLBE_ALE_NQ)) return VLBE_ENONFINITE;
    if (qd && !vlbe_all_finite(qd, VLBE_ALE_NQ)) return VLBE_ENONFINITE;
    return vlbe__ale_len(q[4], q[9]);
}

/* Which p's are coordinates: bit k set when p_{k+1} is free. */
VLBE_INLINE int vlbe__ale_pmask(unsigned mode)
{
    return ((mode & VLBE_ALE_FIX_P1) ? 0 : 1) | ((mode & VLBE_ALE_FIX_P2) ? 0 : 2);
}

/* Material rate of X[k][0] at a point: V_k,0 + p1' X_k,1 + p2' X_k,2 (the
   partials of a fixed p are not evaluated: its rate is zero). */
VLBE_INLINE void vlbe__ale_rate(const vlbe__ale_pt *pt, int k, int pm, const vlbe_real *pd,
                                  vlbe_real *v)
{
    v[0] = pt->V[k][0][0];
    v[1] = pt->V[k][0][1];
    if (pm & 1) vlbe_v2_axpy(pd[0], pt->X[k][1], v);
    if (pm & 2) vlbe_v2_axpy(pd[1], pt->X[k][2], v);
}

/* Inertia-type term at one point: z the 2-vector field it multiplies and c[j]
   the coefficient with dz/de_j = c_j I (z depends on e through the ALE
   columns only): F += w G^T z and, when J and c are given,
   J[:, e-cols] += w d(G^T z)/de.  G = dr/dq = [N_j I | X_0,1 | X_0,2]. */
VLBE_INLINE void vlbe__ale_gtz(const vlbe__ale_pt *pt, int pm, vlbe_real w, const vlbe_real *z,
                                 const vlbe_real *c, vlbe_real *F, vlbe_real *J)
{
    int i, j, k;
    for (j = 0; j < 4; ++j) {
        const int r = VLBE__ALE_E(j);
        const vlbe_real n = w * pt->N[0][0][j];
        F[r] += n * z[0];
        F[r + 1] += n * z[1];
    }
    for (k = 0; k < 2; ++k)
        if (pm & (1 << k)) F[VLBE__ALE_P(k)] += w * vlbe_v2_dot(pt->X[0][1 + k], z);
    if (!J || !c) return;
    for (j = 0; j < 4; ++j) {
        const int cj = VLBE__ALE_E(j);
        const vlbe_real wc = w * c[j];
        if (wc != VLBE_R(0.0))
            for (i = 0; i < 4; ++i) {
                const int r = VLBE__ALE_E(i);
                const vlbe_real t = wc * pt->N[0][0][i];
                J[r * 10 + cj] += t;
                J[(r + 1) * 10 + cj + 1] += t;
            }
        for (k = 0; k < 2; ++k)
            if (pm & (1 << k)) {
                vlbe_real *row = J + VLBE__ALE_P(k) * 10;
                const vlbe_real bb = w * pt->N[0][1 + k][j];
                row[cj] += bb * z[0] + wc * pt->X[0][1 + k][0];
                row[cj + 1] += bb * z[1] + wc * pt->X[0][1 + k][1];
            }
    }
}

/* psi_q (10) of a strain measure psi(y), y = (r', r'') (ny = 2: r' only),
   with gradient gy, at one point: e-entries N'_j gy[b] + N''_j gy[2+b],
   p-entries gy . Y_k with Y_k = (X_1,k, X_2,k). */
VLBE_INLINE void vlbe__ale_psi_q(const vlbe__ale_pt *pt, int pm, int ny, const vlbe_real *gy,
                                   vlbe_real *psq)
{
    int j, k, b, c;
    for (j = 0; j < 4; ++j) {
        const int r = VLBE__ALE_E(j);
        for (b = 0; b < 2; ++b) {
            vlbe_real v = pt->N[1][0][j] * gy[b];
            if (ny == 4) v += pt->N[2][0][j] * gy[2 + b];
            psq[r + b] = v;
        }
    }
    for (k = 0; k < 2; ++k) {
        vlbe_real v = VLBE_R(0.0);
        if (pm & (1 << k))
            for (c = 0; c < ny; ++c) v += gy[c] * pt->X[1 + c / 2][1 + k][c % 2];
        psq[VLBE__ALE_P(k)] = v;
    }
}

/* A strain measure psi(y) at one point, y = (r', r''): gradient gy, Hessian
   H (4x4; jac only), stiffness S, damping cS, sigma = S psi + cS psi' and
   the degree weight deg (its force contributes w deg psi_q to dQ beyond the
   standard row degrees). */
typedef struct vlbe__ale_sm {
    vlbe_real S, cS, sig, deg;
    vlbe_real gy[4], H[16];
} vlbe__ale_sm;

/* T = H B (ny x 8) with B = dy/de: column 2 j + b (e_jb) is N'_j on y_b
   and N''_j on y_{2+b}. */
VLBE_INLINE void vlbe__ale_hb(const vlbe__ale_pt *pt, int ny, const vlbe_real *H,
                                vlbe_real (*T)[8])
{
    int c, j, b;
    for (c = 0; c < ny; ++c)
        for (j = 0; j < 4; ++j)
            for (b = 0; b < 2; ++b) {
                vlbe_real v = pt->N[1][0][j] * H[c * 4 + b];
                if (ny == 4) v += pt->N[2][0][j] * H[c * 4 + 2 + b];
                T[c][2 * j + b] = v;
            }
}

/* Out (10 x 8: the e-columns, 2 j + b for e_jb) -= w Bt T, T ny x 8, with
   Bt = dy/dq: row e_ib is N'_i on y_b and N''_i on y_{2+b}, row p_k is Y_k
   (free p only). */
VLBE_INLINE void vlbe__ale_bt_acc(const vlbe__ale_pt *pt, int pm, int ny, vlbe_real w,
                                    const vlbe_real (*T)[8], vlbe_real *VLBE_RESTRICT Out)
{
    int i, b, c, j, k;
    for (i = 0; i < 4; ++i)
        for (b = 0; b < 2; ++b) {
            vlbe_real *row = Out + (VLBE__ALE_E(i) + b) * 8;
            const vlbe_real m1 = w * pt->N[1][0][i];
            if (ny == 4) {
                const vlbe_real m2 = w * pt->N[2][0][i];
                for (j = 0; j < 8; ++j) row[j] -= m1 * T[b][j] + m2 * T[2 + b][j];
            } else
                for (j = 0; j < 8; ++j) row[j] -= m1 * T[b][j];
        }
    for (k = 0; k < 2; ++k)
        if (pm & (1 << k)) {
            vlbe_real *row = Out + VLBE__ALE_P(k) * 8;
            for (c = 0; c < ny; ++c) {
                const vlbe_real y = w * pt->X[1 + c / 2][1 + k][c % 2];
                for (j = 0; j < 8; ++j) row[j] -= y * T[c][j];
            }
        }
}

/* The strain measures sm[0..nsm) at one point (ny = 2: r' only):
   Q -= w sum sigma psi_q; with Ke (then De, D and dQ too): the e-columns of
   -w d(sum sigma psi_q)/dq into Ke and of D = -w sum cS psi_q psi_q^T into
   De (both 10 x 8, column 2 j + b for e_jb), its p'-columns into D,
   dQ += w sum deg psi_q.  pd = (p1', p2') (zero for fixed nodes), yd =
   material rate of y (read when some cS != 0).  With psi_q = Bt gy
   (vlbe__ale_bt_acc) everything is Bt times a small matrix:
   d(sigma psi_q)/de_jb = Bt (gy dsigma/de_jb + sigma H B_jb) + mix_jb
   (mix: the p-rows' dY_k/de_jb . sigma gy), dsigma/de_jb = B_jb . (S gy +
   cS H yd) + cS Bd_jb . gy (Bd: the basis of the material rate, sum_k p_k'
   times the p_k-partials), and D = -w Bt (sum cS gy gy^T) Bt^T. */
VLBE_INLINE void vlbe__ale_strain_pt(const vlbe__ale_pt *pt, int pm, int ny, vlbe_real w,
                                       const vlbe__ale_sm *sm, int nsm, const vlbe_real *pd,
                                       const vlbe_real *yd, vlbe_real *VLBE_RESTRICT Q,
                                       vlbe_real *VLBE_RESTRICT Ke, vlbe_real *VLBE_RESTRICT De,
                                       vlbe_real *VLBE_RESTRICT D, vlbe_real *VLBE_RESTRICT dQ)
{
    vlbe_real G[4] = {0, 0, 0, 0}, Gd[4] = {0, 0, 0, 0}, Hc[16], Hd[16], T[4][8], nd[2][4], psq[10];
    int i, j, k, m, b, c, damp = 0;
    for (m = 0; m < nsm; ++m)
        for (c = 0; c < 4; ++c) G[c] += sm[m].sig * sm[m].gy[c];
    vlbe__ale_psi_q(pt, pm, ny, G, psq);
    for (i = 0; i < 10; ++i) Q[i] -= w * psq[i];
    if (!Ke) return;
    for (m = 0; m < nsm; ++m)
        for (c = 0; c < 4; ++c) Gd[c] += sm[m].deg * sm[m].gy[c];
    vlbe__ale_psi_q(pt, pm, ny, Gd, psq);
    for (i = 0; i < 10; ++i) dQ[i] += w * psq[i];
    for (i = 0; i < 16; ++i) Hc[i] = Hd[i] = VLBE_R(0.0);
    for (m = 0; m < nsm; ++m) {
        for (i = 0; i < 16; ++i) Hc[i] += sm[m].sig * sm[m].H[i];
        if (sm[m].cS != VLBE_R(0.0)) {
            damp = 1;
            for (c = 0; c < ny; ++c)
                for (i = 0; i < ny; ++i) Hd[c * 4 + i] += sm[m].cS * sm[m].gy[c] * sm[m].gy[i];
        }
    }
    for (c = 0; c < ny / 2; ++c)
        for (j = 0; j < 4; ++j) {
            nd[c][j] = VLBE_R(0.0);
            for (k = 0; k < 2; ++k)
                if (pm & (1 << k)) nd[c][j] += pd[k] * pt->N[1 + c][1 + k][j];
        }
    vlbe__ale_hb(pt, ny, Hc, T);
    for (m = 0; m < nsm; ++m) {
        const vlbe__ale_sm *s = &sm[m];
        vlbe_real v[4] = {0, 0, 0, 0}, g[4] = {0, 0, 0, 0};
        for (c = 0; c < ny; ++c) {
            v[c] = s->S * s->gy[c];
            g[c] = s->cS * s->gy[c];
            if (s->cS != VLBE_R(0.0))
                for (i = 0; i < ny; ++i) v[c] += s->cS * s->H[c * 4 + i] * yd[i];
        }
        for (j = 0; j < 4; ++j)
            for (b = 0; b < 2; ++b) {
                vlbe_real ds = pt->N[1][0][j] * v[b] + nd[0][j] * g[b];
                if (ny == 4) ds += pt->N[2][0][j] * v[2 + b] + nd[1][j] * g[2 + b];
                for (c = 0; c < ny; ++c) T[c][2 * j + b] += s->gy[c] * ds;
            }
    }
    vlbe__ale_bt_acc(pt, pm, ny, w, (const vlbe_real(*)[8])T, Ke);
    for (k = 0; k < 2; ++k) /* mix */
        if (pm & (1 << k)) {
            vlbe_real *row = Ke + VLBE__ALE_P(k) * 8;
            for (j = 0; j < 4; ++j)
                for (b = 0; b < 2; ++b) {
                    vlbe_real v = pt->N[1][1 + k][j] * G[b];
                    if (ny == 4) v += pt->N[2][1 + k][j] * G[2 + b];
                    row[2 * j + b] -= w * v;
                }
        }
    if (!damp) return;
    vlbe__ale_hb(pt, ny, Hd, T);
    vlbe__ale_bt_acc(pt, pm, ny, w, (const vlbe_real(*)[8])T, De);
    for (k = 0; k < 2; ++k)
        if (pm & (1 << k)) {
            vlbe_real hy[4];
            for (c = 0; c < ny; ++c) {
                hy[c] = VLBE_R(0.0);
                for (i = 0; i < ny; ++i) hy[c] += Hd[c * 4 + i] * pt->X[1 + i / 2][1 + k][i % 2];
            }
            vlbe__ale_psi_q(pt, pm, ny, hy, psq);
            for (i = 0; i < 10; ++i) D[i * 10 + VLBE__ALE_P(k)] -= w * psq[i];
        }
}

/* sum_j b.h[k][a][j] x_j over the four nodal 2-vectors of x (element
   layout): r, r', ALE partials of a point, or their rates with x = q' */
VLBE_INLINE void vlbe__ale_sum(const vlbe_herm_ale *b, int k, int a, const vlbe_real *x,
                                 vlbe_real *out)
{
    int j;
    out[0] = out[1] = VLBE_R(0.0);
    for (j = 0; j < 4; ++j) vlbe_v2_axpy(b->h[k][a][j], x + VLBE__ALE_E(j), out);
}

/* Material rate of the k-th p-derivative of r at the point of b (at fixed
   material p, eq. 14 of [R]): S^(k) e' + (dS^(k)/dp1 e) p1' + (dS^(k)/dp2 e)
   p2'; b needs the p1, p2 derivatives (vlbe_herm_ale_eval with 1). */
VLBE_INLINE void vlbe__ale_mat_rate(const vlbe_herm_ale *b, int k, const vlbe_real *q,
                                      const vlbe_real *qd, vlbe_real *out)
{
    vlbe_real a[2];
    vlbe__ale_sum(b, k, 0, qd, out);
    vlbe__ale_sum(b, k, 1, q, a);
    vlbe_v2_axpy(qd[4], a, out);
    vlbe__ale_sum(b, k, 2, q, a);
    vlbe_v2_axpy(qd[9], a, out);
}

/* Axial strain from the slope r1 = r': eps, gradient and (constant) Hessian
   in y = (r', r''). */
VLBE_INLINE vlbe_real vlbe__ale_eps(const vlbe_real *r1, vlbe_real *gy, vlbe_real *H)
{
    int i;
    gy[0] = r1[0];
    gy[1] = r1[1];
    gy[2] = gy[3] = VLBE_R(0.0);
    if (H) {
        for (i = 0; i < 16; ++i) H[i] = VLBE_R(0.0);
        H[0] = H[5] = VLBE_R(1.0);
    }
    return VLBE_R(0.5) * (vlbe_v2_dot(gy, gy) - VLBE_R(1.0));
}

/* Signed curvature from r1 = r', r2 = r'': kap = (r' x r'') |r'|^-3,
   gradient in y = (r', r''), Hessian when H != NULL.  VLBE_ESINGULAR for
   |r'|^2 <= eps. */
VLBE_INLINE void vlbe__ale_kap_t(const vlbe_real *r1, const vlbe_real *r2, vlbe_real t,
                                   vlbe_real g32, vlbe_real *kap, vlbe_real *gy, vlbe_real *H)
{
    vlbe_real k, sy[4], gv[4];
    int a, c;
    k = vlbe_v2_cross(r1, r2) * g32;
    /* s = r' x r'' and g = r'.r', differentiated in (r'x, r'y, r''x, r''y) */
    sy[0] = r2[1];
    sy[1] = -r2[0];
    sy[2] = -r1[1];
    sy[3] = r1[0];
    gv[0] = VLBE_R(2.0) * r1[0];
    gv[1] = VLBE_R(2.0) * r1[1];
    gv[2] = gv[3] = VLBE_R(0.0);
    for (a = 0; a < 4; ++a) gy[a] = g32 * sy[a] - VLBE_R(1.5) * k * t * gv[a];
    if (H) {
        for (a = 0; a < 4; ++a)
            for (c = 0; c < 4; ++c)
                H[a * 4 + c] = -VLBE_R(1.5) * t * g32 * (sy[a] * gv[c] + gv[a] * sy[c]) +
                               VLBE_R(3.75) * k * t * t * gv[a] * gv[c];
        H[0 * 4 + 3] += g32; /* s_yy */
        H[3 * 4 + 0] += g32;
        H[1 * 4 + 2] -= g32;
        H[2 * 4 + 1] -= g32;
        H[0] -= VLBE_R(3.0) * k * t; /* g_yy = 2 I on the r' block */
        H[5] -= VLBE_R(3.0) * k * t;
    }
    *kap = k;
}

VLBE_INLINE vlbe_status vlbe__ale_kap(const vlbe_real *r1, const vlbe_real *r2, vlbe_real *kap,
                                        vlbe_real *gy, vlbe_real *H)
{
    const vlbe_real gg = vlbe_v2_dot(r1, r1);
    vlbe_real t;
    if (!(gg > VLBE_EPS)) return VLBE_ESINGULAR;
    t = VLBE_R(1.0) / gg;
    vlbe__ale_kap_t(r1, r2, t, t * vlbe_sqrt(t), kap, gy, H);
    return VLBE_OK;
}

/* Where the coordinates of one element sit, for the code both elements
   share (the scaling identity): n per element, d the dimension of the
   vectors, e[j] the first entry of basis j's d-vector (r1, r1', r2, r2'),
   th[i] node i's spin angle (-1: none), p[i] its material coordinate.
   vlbe__ale_lay2: the planar element; vlbe__ale_layout: the 3D one. */
typedef struct vlbe__ale_lay {
    int n, d, spin, e[4], th[2], p[2];
    int bad; /* 3D: a planar-only mode bit (CONSERVATIVE, INV_AXIAL): VLBE_EARG */
} vlbe__ale_lay;

VLBE_INLINE const vlbe__ale_lay *vlbe__ale_lay2(void)
{
    static const vlbe__ale_lay ly = {VLBE_ALE_NQ, 2, 0, {0, 2, 5, 7}, {-1, -1}, {4, 9}, 0};
    return &ly;
}

/* The basis at one point scaled to the current L: N[k][a][j] = L^(m_j - k
   - |a|) b[k][a][j] (Hermite), H[k][a][j] = L^(-k - |a|) l[k][a][j]
   (linear, only with spin); rows k0..kmax, partials a < na at k = 0,
   a < min(na, 3) above. */
typedef struct vlbe__ale_lpt {
    vlbe_real N[3][VLBE_DA_N][4];
    vlbe_real H[2][VLBE_DA_N][2];
} vlbe__ale_lpt;

VLBE_INLINE void vlbe__ale_lpt_eval(const vlbe_ale_gp *gp, const vlbe_real *Lp, int k0, int kmax,
                                    int na, int spin, vlbe__ale_lpt *VLBE_RESTRICT pt)
{
    int k, a, j;
    for (k = k0; k <= kmax; ++k) {
        const int nak = (k == 0 || na < 3) ? na : 3;
        for (a = 0; a < nak; ++a) {
            const int d = 4 - k - (a == 0 ? 0 : (a < 3 ? 1 : 2));
            for (j = 0; j < 4; ++j) pt->N[k][a][j] = gp->b[k][a][j] * Lp[d + (j & 1)];
            if (spin && k < 2)
                for (j = 0; j < 2; ++j) pt->H[k][a][j] = gp->l[k][a][j] * Lp[d];
        }
    }
}

/* out = sum_j n[j] x_j over the four d-vectors of x (r1, r1', r2, r2');
   d = ly->d, an argument of its own so that the 3D kernels' literal 3
   unrolls the loops */
VLBE_INLINE void vlbe__ale_lsum(const vlbe__ale_lay *ly, int d, const vlbe_real *n,
                                const vlbe_real *x, vlbe_real *out)
{
    const vlbe_real *x0 = x + ly->e[0], *x1 = x + ly->e[1], *x2 = x + ly->e[2],
                    *x3 = x + ly->e[3];
    int c;
    for (c = 0; c < d; ++c) out[c] = n[0] * x0[c] + n[1] * x1[c] + n[2] * x2[c] + n[3] * x3[c];
}

/* sum_j h[j] x_th_j over the two spin angles (0 without spin) */
VLBE_INLINE vlbe_real vlbe__ale_lsum_th(const vlbe__ale_lay *ly, const vlbe_real *h,
                                      const vlbe_real *x)
{
    return ly->spin ? h[0] * x[ly->th[0]] + h[1] * x[ly->th[1]] : VLBE_R(0.0);
}

/* dF = d F for a force of the standard row degrees (1 + m_j on the
   position and slope rows, 1 on spin-angle rows, 0 on p-rows): inertia,
   loads, bending. */
VLBE_INLINE void vlbe__ale_degree(const vlbe__ale_lay *ly, const vlbe_real *F, vlbe_real *dF)
{
    int j, c;
    for (j = 0; j < ly->n; ++j) dF[j] = F[j];
    for (j = 1; j < 4; j += 2)
        for (c = 0; c < ly->d; ++c) dF[ly->e[j] + c] *= VLBE_R(2.0);
    dF[ly->p[0]] = dF[ly->p[1]] = VLBE_R(0.0);
}

/* The p-columns of K = dF/dq from the scaling identity (NOTES):
   L dF/dp2 = dF + sum_slope (K_e e + D_e u) - pd1 D_p1 - pd2 D_p2 and
   dF/dp1 = -dF/dp2, with dF the degree-weighted F, D = dF/du, u the
   rate-like argument (q' for forces; the acceleration a for d(M a)/dq, where
   D = M and pd = (a_p1, a_p2)). */
VLBE_INLINE void vlbe__ale_pcols(const vlbe__ale_lay *ly, vlbe_real L, int pm,
                                   const vlbe_real *dF, const vlbe_real *pd, const vlbe_real *q,
                                   const vlbe_real *u, vlbe_real *K, const vlbe_real *D)
{
    const int n = ly->n;
    int i, j, c;
    for (i = 0; i < n; ++i) {
        const vlbe_real *Ki = K + i * n, *Di = D + i * n;
        vlbe_real s = dF[i] - pd[0] * Di[ly->p[0]] - pd[1] * Di[ly->p[1]];
        for (j = 1; j < 4; j += 2)
            for (c = 0; c < ly->d; ++c) {
                const int cj = ly->e[j] + c;
                s += Ki[cj] * q[cj] + Di[cj] * u[cj];
            }
        s /= L;
        K[i * n + ly->p[0]] = (pm & 1) ? -s : VLBE_R(0.0);
        K[i * n + ly->p[1]] = (pm & 2) ? s : VLBE_R(0.0);
    }
}

/* Energy fluxes through the element ends (VLBE_ALE_CONSERVATIVE): p-rows
   Q_p1 += u(0), Q_p2 -= u(1), u = (EA eps^2 + EI kap^2)/2, their e-columns
   in K, and their degree-weighted part in dQ. */
VLBE_INLINE vlbe_status vlbe__ale_flux(const vlbe_ale_elem *el, int pm, int bend,
                                         const vlbe_real *q, vlbe_real L, vlbe_real *Q,
                                         vlbe_real *K, vlbe_real *dQ)
{
    const vlbe_ale_mat *mt = &el->mat;
    vlbe__ale_pt pt;
    vlbe_real Lp[6];
    int e, i;
    vlbe__ale_lpow(L, Lp);
    for (e = 0; e < 2; ++e) {
        const int row = VLBE__ALE_P(e);
        const vlbe_real sgn = e == 0 ? VLBE_R(1.0) : VLBE_R(-1.0);
        vlbe_real gy[4], psq[10], eps, u, du = VLBE_R(0.0);
        if (!(pm & (1 << e))) continue;
        vlbe__ale_pt_eval(&el->ends[e], Lp, 1, 2, 1, q, NULL, 0, &pt);
        eps = vlbe__ale_eps(pt.X[1][0], gy, NULL);
        u = VLBE_R(0.5) * mt->EA * eps * eps;
        /* degrees: eps^2 = (a - 1/2)^2 with a = |r'|^2/2 of degree -2 */
        du = -VLBE_R(2.0) * mt->EA * (eps + VLBE_R(0.5)) * eps;
        if (K) {
            vlbe__ale_psi_q(&pt, 0, 2, gy, psq);
            for (i = 0; i < 10; ++i) K[row * 10 + i] += sgn * mt->EA * eps * psq[i];
        }
        if (bend) {
            vlbe_real kap;
            vlbe_status st = vlbe__ale_kap(pt.X[1][0], pt.X[2][0], &kap, gy, NULL);
            if (st != VLBE_OK) return st;
            u += VLBE_R(0.5) * mt->EI * kap * kap; /* degree 0 */
            if (K) {
                vlbe__ale_psi_q(&pt, 0, 4, gy, psq);
                for (i = 0; i < 10; ++i) K[row * 10 + i] += sgn * mt->EI * kap * psq[i];
            }
        }
        Q[row] += sgn * u;
        if (dQ) dQ[row] += sgn * du;
    }
    return VLBE_OK;
}

/* Axial (psi = eps(r'), eqs. 19, 21) and/or bending (psi = kap(r', r''),
   eqs. 19, 22 in planar signed form) terms at one Gauss point, sharing the
   point evaluation.  Ke, De, D, dQ as in vlbe__ale_strain_pt (Ke NULL: Q
   only). */
VLBE_INLINE vlbe_status vlbe__ale_strain_gp(const vlbe_ale_mat *mt, const vlbe_ale_gp *gp,
                                              const vlbe_real *Lp, int pm, const vlbe_real *pd,
                                              int axial, int bend, int damp, const vlbe_real *q,
                                              const vlbe_real *qd, vlbe_real *Q, vlbe_real *Ke,
                                              vlbe_real *De, vlbe_real *D, vlbe_real *dQ)
{
    const vlbe_real w = gp->w * Lp[5];
    const int ny = bend ? 4 : 2;
    vlbe__ale_sm sm[2];
    vlbe_real yd[4];
    vlbe__ale_pt pt;
    vlbe_status st;
    int nsm = 0, m, c;
    vlbe__ale_pt_eval(gp, Lp, 1, ny / 2, pm ? 3 : 1, q, damp ? qd : NULL, 1, &pt);
    if (damp) {
        vlbe__ale_rate(&pt, 1, pm, pd, yd);
        if (bend) vlbe__ale_rate(&pt, 2, pm, pd, yd + 2);
        else yd[2] = yd[3] = VLBE_R(0.0);
    }
    if (axial) {
        vlbe__ale_sm *s = &sm[nsm++];
        const vlbe_real eps = vlbe__ale_eps(pt.X[1][0], s->gy, Ke ? s->H : NULL);
        s->S = mt->EA;
        s->cS = damp ? mt->c_eps * mt->EA : VLBE_R(0.0);
        s->sig = s->S * eps;
    }
    if (bend) {
        vlbe__ale_sm *s = &sm[nsm++];
        vlbe_real kap;
        if ((st = vlbe__ale_kap(pt.X[1][0], pt.X[2][0], &kap, s->gy, Ke ? s->H : NULL)) != VLBE_OK)
            return st;
        s->S = mt->EI;
        s->cS = damp ? mt->c_kap * mt->EI : VLBE_R(0.0);
        s->sig = s->S * kap;
        s->deg = VLBE_R(0.0);
    }
    for (m = 0; m < nsm; ++m) {
        vlbe__ale_sm *s = &sm[m];
        if (s->cS != VLBE_R(0.0))
            for (c = 0; c < ny; ++c) s->sig += s->cS * s->gy[c] * yd[c];
    }
    /* degrees below the standard ones: the axial force -sigma eps_q is 4
       lower for the |r'|^2/2 part of eps, 2 lower for its -1/2 */
    if (axial) sm[0].deg = VLBE_R(4.0) * sm[0].sig + mt->EA;
    vlbe__ale_strain_pt(&pt, pm, ny, w, sm, nsm, pd, yd, Q, Ke, De, D, dQ);
    return VLBE_OK;
}

/* INVARIANTS (invariant-matrix force evaluation)
   With both p fixed the Green-strain axial force is a cubic polynomial of
   the nodal data: with B_ab = int s_a' s_b' dp and I_abcd = int s_a' s_b'
   s_c' s_d' dp over the four slots r1, r1', r2, r2' and the Gram matrix
   G_cd = r_c . r_d,  Q_a = -EA sum_b (sum_cd I_abcd H_cd - B_ab)/2 r_b with
   H = G + c_eps dG/dt (the Kelvin-Voigt part is polynomial too); K and D
   in closed form (derivation above vlbe__ale_inv_slots).  vlbe_ale_elem_init
   tabulates B, I (35 unique numbers, stored as a 10 x 10 matrix over the
   symmetric slot pairs) and int N at L = 1 (vlbe_ale_inv, el->inv); a
   slope carries one power of L, so one table serves every L: I scales
   with L^-3, B with L^-1 once the slopes are multiplied by L.  Bending
   (exact curvature, rational) stays on Gauss points: vlbe_ale_inv_force
   gives the cable (NO_BEND) force wholly from invariants and the beam's as
   invariant axial force + Gauss bending.
   ALE elements (p1 and/or p2 free; vlbe_ale_force with VLBE_ALE_INV_AXIAL)
   need no further integrals.  At fixed p the partial of a slope function,
   d s_a'/dp_k = L^(m_a - 2) ((m_a - 1) h_a' - xi h_a'') for p2 (p1: -(m_a
   - 1) h_a' + (xi - 1) h_a''), is a quadratic in xi, and the slopes h_b'
   of the cubic basis span the quadratics, so d s_a'/dp_k = L^(m_a - 2)
   sum_b dp_k[a][b] h_b' with small integer maps dp_k (vlbe_ale_inv.dp).
   Hence dr'/dp_k is the r' of virtual slot vectors y_k (with the slots
   scaled, r~_a = L^m_a r_a: y~_k,b = sum_a dp_k[a][b] r~_a / L), and:
   eps_pk = r' . dr'/dp_k = sum_b y_k,b . eps_{r_b}, so the p-rows are
   Q_pk = sum_b y_k,b . Q_b; the material rate of r' is that of the slot
   rates r_b' + p1' y_1,b + p2' y_2,b, which enter the fixed-length
   Kelvin-Voigt formula in place of r_b'; K and D follow by the product
   rule (p-rows y^T K + Q . dy/dr and y^T D, p'-columns D y, and in K the
   rates' own dependence on r through y), and the p-columns of K from the
   scaling identity of NOTES with the degree weights -4 Q + 2 Q0 of the
   axial force (Q0: its B part), as on the Gauss route.  The transport inertia, the load of a free-p element,
   the bending force and CONSERVATIVE's end fluxes stay on Gauss points /
   the end points.  Same numbers as the Gauss route to rounding (tests:
   64 EPS of the largest entry; at small strain eps both routes' rounding
   relative to Q is ~EPS/eps, the Green strain's cancellation).  Per
   element call (bench/bench_inv_ale.c, -O3 -march=native): invariants are
   slower for Q alone (0.65-0.85 x the Gauss route's speed), slightly
   faster for the damped ALE cable's Q+K+D (1.05 x), even for the undamped
   one, and slower for the beam (0.8 x), whose Gauss route evaluates the
   bending at the axial points.
   Chains of fixed-length cable elements: coordinates node by node x = [x,
   y, x', y'] (vlbe_ale_chain's layout with every p fixed and no sliding
   node), n = 4 (ne + 1); K, D in band storage, row i holding columns i-7
   .. i+7: entry (i, j) at K[i*VLBE_ALE_INV_BW + j - i + VLBE_ALE_INV_KD].
   vlbe_ale_inv_chain_force loops over the elements (gather, element call,
   scatter); the system invariants (vlbe_ale_inv_sys_*) hold B and I of the
   whole chain assembled once in the caller's buffer and evaluate Q, K, D
   without an element loop.  Their variables are translation-free: as h1'
   = -h3', element e's r' = h3' d_e + L h2' r_e' + L h4' r_{e+1}' reads
   only the chord d_e = r_{e+1} - r_e and the two nodal slopes, so the
   system's slots are the ne chords and ne + 1 slopes (2 ne + 1), B and I
   are assembled over the 5 ne + 1 slot pairs that share an element (each
   row a contiguous range of 6 or 11 pairs, 35 ne + 1 numbers; the x/y
   Kronecker factor is never stored), the Gram entries are of the size of
   L^2, L, 1 wherever the chain is, and the slot forces and 2x2 blocks go
   back to the nodal layout by the chain rule of d_e (Q = J^T Q~, K = J^T
   K~ J, D = J^T D~ J, J = +-1 entries; vlbe__ale_sys_force).  Rounding
   (tests/test_ale_inv.c): at eps = 1e-4 on 64 elements far from the
   origin the system route's Q is within ~3 EPS/eps of max|Q| of the
   Gauss route per element in its own frame and of a long double
   reference (EPS/eps is the Green strain's own conditioning, the floor of
   every route), K and D within ~5 EPS; it does not grow with the chain.
   The Gauss route on the nodal values forms r' from positions of size
   |r| (~EPS |r|/L / eps); the element invariants work relative to their
   node 1's position but take the nodal velocities as they are (damped:
   ~c |v|/L more). */

/* -- invariant-matrix axial force of fixed-length elements --------------
   With both material coordinates fixed the axial force is a polynomial of
   the nodal data.  With r' = sum_a s_a' r_a (slots a = 0..3: r1, r1', r2,
   r2'; s_a the Hermite functions in p) the Green strain and its rate are
        eps  = (sum_cd s_c' s_d' G_cd - 1)/2,   G_cd = r_c . r_d,
        eps' = sum_cd s_c' s_d' r_c . v_d       (v = r-dot, fixed p),
   so with B_ab = int s_a' s_b' dp and I_abcd = int s_a' s_b' s_c' s_d' dp
   the axial force Q_a = -EA int s_a' r' (eps + c eps') dp (the -Q_l of
   NOTES, c = c_eps) is
        Q_a = -EA sum_b S_ab r_b,   S_ab = (sum_cd I_abcd H_cd - B_ab)/2,
        H_cd = G_cd + c (r_c . v_d + r_d . v_c).
   Its Jacobians (dS_ab/dr_e = sum_d I_abed (r_d + c v_d), dS_ab/dv_e =
   c sum_d I_abed r_d; 2x2 blocks, i, j = x, y):
        K_ae,ij = -EA (S_ae delta_ij + sum_bd I_aebd r_b,i z_d,j),  z = r + c v,
        D_ae,ij = -EA c sum_bd I_aebd r_b,i r_d,j.
   Both blocks are symmetric in (a, e), so one symmetric slot pair P = (a,
   e) gives the blocks (a, e) and (e, a), and every contraction is the
   matrix t of vlbe_ale_inv times a vector of symmetrized pair products
   (vlbe__ale_inv_prod).  Scaling: s_a(p) = L^m_a h_a(xi) (m = 0 positions,
   1 slopes) gives B_ab = L^(m_a+m_b-1) b_ab, I_abcd = L^(m_a+m_b+m_c+m_d-3)
   i_abcd: with the slopes multiplied by L (r~_a = L^m_a r_a) the unit
   tables serve every L with the overall factors L^-3 (quartic part) and
   L^-1 (quadratic part), and Q_a = L^m_a Q~_a, K_ae = L^(m_a+m_e) K~_ae.
   An ALE element at its current L = p2 - p1 (INVARIANTS): with y_k,b =
   (1/L) sum_a dp_k[a][b] r~_a (scaled, like r~) dr'/dp_k = (1/L) sum_b
   h_b' y_k,b, so the scaled material slot rates are w = v~ + p1' y_1 +
   p2' y_2 (H built with w), Q_pk = sum_b y_k,b . Q~_b (the scalings
   cancel: y_b = L^-m_b y~_b), and with W_eb = sum_k p_k' dp_k[e][b] / L
   (w = v~ + W^T r~):  K~_ae += sum_b D~_ab W_eb,  K_pk,e = L^m_e (sum_b
   y_k,b^T K~_be + (1/L) sum_b dp_k[e][b] Q~_b),  D_pk,e = L^m_e sum_b
   y_k,b^T D~_be,  D_a,pk' = L^m_a sum_b D~_ab y_k,b,  D_pl,pk' = y_l^T D~
   y_k.  The p-columns of K: vlbe__ale_pcols with the degree weights. */

/* slots (A, B), A <= B, of pair P in the order of vlbe_ale_inv: node 1's
   three pairs (0, 0), (0, 1), (1, 1), its four links to node 2 (0, 2), (0,
   3), (1, 2), (1, 3), node 2's three pairs.  vlbe__ale_inv_pa: A at [P], B
   at [10 + P]. */
VLBE_INLINE const signed char *vlbe__ale_inv_pa(void)
{
    static const signed char pa[20] = {0, 0, 1, 0, 0, 1, 1, 2, 2, 3,
                                       0, 1, 1, 2, 3, 2, 3, 2, 3, 3};
    return pa;
}

VLBE_INLINE void vlbe__ale_inv_slots(int P, int *A, int *B)
{
    const signed char *pa = vlbe__ale_inv_pa();
    *A = pa[P];
    *B = pa[10 + P];
}

/* Pair products of slots a, b (2-vectors r, v; v may be NULL = 0), times
   s: H[0] = H_ab; with jac the symmetrized r (x) z, z = r + c v: H[1..4] =
   (r_a,i z_b,j + r_b,i z_a,j)/2 for ij = xx, xy, yx, yy, and the
   symmetrized r (x) r: H[5..7] for xx, xy, yy. */
VLBE_INLINE void vlbe__ale_inv_prod(const vlbe_real *ra, const vlbe_real *rb, const vlbe_real *va,
                                      const vlbe_real *vb, vlbe_real c, vlbe_real s, int jac,
                                      vlbe_real *H)
{
    vlbe_real za[2], zb[2], hs;
    int i;
    H[0] = vlbe_v2_dot(ra, rb);
    for (i = 0; i < 2; ++i) {
        za[i] = ra[i];
        zb[i] = rb[i];
    }
    if (va && vb) {
        H[0] += c * (vlbe_v2_dot(ra, vb) + vlbe_v2_dot(rb, va));
        vlbe_v2_axpy(c, va, za);
        vlbe_v2_axpy(c, vb, zb);
    }
    H[0] *= s;
    if (!jac) return;
    hs = VLBE_R(0.5) * s;
    H[1] = hs * (ra[0] * zb[0] + rb[0] * za[0]);
    H[2] = hs * (ra[0] * zb[1] + rb[0] * za[1]);
    H[3] = hs * (ra[1] * zb[0] + rb[1] * za[0]);
    H[4] = hs * (ra[1] * zb[1] + rb[1] * za[1]);
    H[5] = s * ra[0] * rb[0];
    H[6] = hs * (ra[0] * rb[1] + rb[0] * ra[1]);
    H[7] = s * ra[1] * rb[1];
}

/* y[k] = sum_j T[j] H[8 j + k], j < w, k < 8: one row of a contraction
   (eight independent sums: they vectorize) */
VLBE_INLINE void vlbe__ale_inv_row(const vlbe_real *T, int w, const vlbe_real *H, vlbe_real *y)
{
    int j, k;
    for (k = 0; k < 8; ++k) y[k] = VLBE_R(0.0);
    for (j = 0; j < w; ++j)
        for (k = 0; k < 8; ++k) y[k] += T[j] * H[8 * j + k];
}

/* The part of pair (a, b) (same: a = b) with S = S_ab and, with jac, the
   contracted products y (vlbe__ale_inv_row): Qa += -EA S r_b, Qb += -EA S
   r_a and the 2x2 blocks (a, b), (b, a) of K and D (EAc = EA c; D only for
   EAc != 0), leading dimension ld; K, D may be NULL. */
VLBE_INLINE void vlbe__ale_inv_out(vlbe_real S, const vlbe_real *y, int jac, vlbe_real EA,
                                     vlbe_real EAc, const vlbe_real *ra, const vlbe_real *rb,
                                     int same, vlbe_real *Qa, vlbe_real *Qb, vlbe_real *Kab,
                                     vlbe_real *Kba, vlbe_real *Dab, vlbe_real *Dba, int ld)
{
    const vlbe_real f = -EA * S;
    vlbe_real k[4], d[3];
    int i, m;
    vlbe_v2_axpy(f, rb, Qa);
    if (!same) vlbe_v2_axpy(f, ra, Qb);
    if (!jac) return;
    k[0] = f - EA * y[1];
    k[1] = -EA * y[2];
    k[2] = -EA * y[3];
    k[3] = f - EA * y[4];
    for (m = 0; Kab && m < 2 - same; ++m) {
        vlbe_real *Kb = m ? Kba : Kab;
        for (i = 0; i < 2; ++i) {
            Kb[i * ld] += k[2 * i];
            Kb[i * ld + 1] += k[2 * i + 1];
        }
    }
    if (EAc == VLBE_R(0.0) || !Dab) return;
    for (i = 0; i < 3; ++i) d[i] = -EAc * y[5 + i];
    for (m = 0; m < 2 - same; ++m) {
        vlbe_real *Db = m ? Dba : Dab;
        Db[0] += d[0];
        Db[1] += d[1];
        Db[ld] += d[1];
        Db[ld + 1] += d[2];
    }
}

/* Axial force of an element of length L from the unit tables (see above):
   Q += (all rows), K += (the e-columns of all rows), D += (all columns,
   damped only), 10-coordinate layout; with K and pm != 0, dQ += the
   axial force's degree weights beyond the standard row degrees (the
   p-columns of K then follow from the scaling identity, as on the Gauss
   route: vlbe__ale_forces).  pm: the free p's (vlbe__ale_pmask; 0 = fixed
   length), pd = (p1', p2') (0 for a fixed p).  K, D, dQ may be NULL (with
   K given, D must be too).  c: Kelvin-Voigt time (0: undamped, qd not
   read).  Q alone contracts column by column (ten independent sums), with
   K row by row over eight products.  Ks, Ds: the caller's scratch of 64
   each for the 8 x 8 slot blocks (with K only; left as scratch).  The
   axial force of eqs. 19, 21 of [R] (eps = (r'.r' - 1)/2, N = EA (eps +
   c eps')) from the invariants.  About 160 lines: the slot products and
   the contraction are one pass whose partial sums the Q, K and D parts
   share (the Q-only path is the hot one of fixed-length chains); the
   pieces without shared state are helpers (vlbe__ale_inv_slots, _prod,
   _row, _out). */
VLBE_INLINE void vlbe__ale_inv_axial(const vlbe_ale_inv *iv, vlbe_real EA, vlbe_real c,
                                       vlbe_real L, int pm, const vlbe_real *pd,
                                       const vlbe_real *q, const vlbe_real *qd, vlbe_real *Q,
                                       vlbe_real *K, vlbe_real *D, vlbe_real *dQ, vlbe_real *Ks,
                                       vlbe_real *Ds)
{
    const vlbe_real Li = VLBE_R(1.0) / L, L3 = Li * Li * Li;
    const signed char *pa = vlbe__ale_inv_pa();
    const int damp = c != VLBE_R(0.0), jac = K != NULL;
    vlbe_real sc[4], r[8], u[8], y[2][8], H[VLBE_ALE_INV_NP * 8], Qs[8];
    vlbe_real yv[8] = {0, 0, 0, 0, 0, 0, 0, 0};
    int a, b, i, j, k, l, m, P, R;
    /* positions relative to node 1: the force is invariant to translation
       (s_1' + s_3' = 0), and so the Gram entries stay of size L^2 instead of
       |r|^2 (their rounding would grow like (|r|/L)^2) */
    for (a = 0; a < 4; ++a) {
        sc[a] = VLBE__ALE_M(a) ? L : VLBE_R(1.0);
        for (i = 0; i < 2; ++i) {
            r[2 * a + i] = sc[a] * (q[VLBE__ALE_E(a) + i] - (a == 2 ? q[i] : VLBE_R(0.0)));
            u[2 * a + i] = damp ? sc[a] * qd[VLBE__ALE_E(a) + i] : VLBE_R(0.0);
        }
    }
    r[0] = r[1] = VLBE_R(0.0);
    /* ALE: dr'/dp_k = (1/L) sum_b h_b' y_k,b with y_k,b = (1/L) sum_a
       dp[k][a][b] r_a, and the material rate of r' is that of the slots u +
       p1' y_1 + p2' y_2.  dp has no slot-0 coefficients, so y_k,0 = 0 and
       the sums over the entries m of a y below start at m = 2 (slot 1) */
    for (k = 0; k < 2; ++k) {
        if (!(pm & (1 << k))) continue;
        y[k][0] = y[k][1] = VLBE_R(0.0);
        for (b = 1; b < 4; ++b)
            for (i = 0; i < 2; ++i) {
                vlbe_real t = VLBE_R(0.0);
                for (a = 1; a < 4; ++a) t += iv->dp[k][4 * a + b] * r[2 * a + i];
                y[k][2 * b + i] = Li * t;
            }
        if (damp)
            for (m = 2; m < 8; ++m) u[m] += pd[k] * y[k][m];
    }
    for (i = 0; i < 8; ++i) Qs[i] = VLBE_R(0.0);
    for (P = 0; P < VLBE_ALE_INV_NP; ++P) {
        a = pa[P];
        b = pa[10 + P];
        vlbe__ale_inv_prod(r + 2 * a, r + 2 * b, damp ? u + 2 * a : NULL, damp ? u + 2 * b : NULL,
                           c, L3, jac, H + 8 * P);
    }
    if (!jac) {
        vlbe_real S[VLBE_ALE_INV_NP];
        for (P = 0; P < VLBE_ALE_INV_NP; ++P) S[P] = -Li * iv->b[P];
        for (R = 0; R < VLBE_ALE_INV_NP; ++R)
            for (P = 0; P < VLBE_ALE_INV_NP; ++P) S[P] += iv->t[P * VLBE_ALE_INV_NP + R] * H[8 * R];
        for (P = 0; P < VLBE_ALE_INV_NP; ++P) {
            a = pa[P];
            b = pa[10 + P];
            vlbe__ale_inv_out(VLBE_R(0.5) * S[P], yv, 0, EA, EA * c, r + 2 * a, r + 2 * b, a == b,
                              Qs + 2 * a, Qs + 2 * b, NULL, NULL, NULL, NULL, 8);
        }
    } else {
        for (i = 0; i < 64; ++i) Ks[i] = Ds[i] = VLBE_R(0.0);
        for (P = 0; P < VLBE_ALE_INV_NP; ++P) {
            a = pa[P];
            b = pa[10 + P];
            vlbe__ale_inv_row(iv->t + P * VLBE_ALE_INV_NP, VLBE_ALE_INV_NP, H, yv);
            vlbe__ale_inv_out(VLBE_R(0.5) * (yv[0] - Li * iv->b[P]), yv, 1, EA, EA * c, r + 2 * a,
                              r + 2 * b, a == b, Qs + 2 * a, Qs + 2 * b, Ks + 2 * a * 8 + 2 * b,
                              Ks + 2 * b * 8 + 2 * a, Ds + 2 * a * 8 + 2 * b,
                              Ds + 2 * b * 8 + 2 * a, 8);
        }
        /* damped ALE: the slot rates depend on r through the y_k, du_c/dr_e
           = sum_k p_k' dp[k][e][c] / L: K_ae += sum_c D_ac du_c/dr_e (in
           this plain order: faster in place than rows of the symmetric D
           added transposed, bench_inv_ale.c) */
        if (damp && pm) {
            vlbe_real cp[16];
            for (i = 0; i < 16; ++i)
                cp[i] = Li * (((pm & 1) ? pd[0] * iv->dp[0][i] : VLBE_R(0.0)) +
                              ((pm & 2) ? pd[1] * iv->dp[1][i] : VLBE_R(0.0)));
            for (m = 0; m < 8; ++m)
                for (a = 0; a < 4; ++a)
                    for (j = 0; j < 2; ++j) {
                        vlbe_real t = VLBE_R(0.0);
                        for (b = 1; b < 4; ++b) t += cp[4 * a + b] * Ds[m * 8 + 2 * b + j];
                        Ks[m * 8 + 2 * a + j] += t;
                    }
        }
    }
    for (a = 0; a < 4; ++a)
        for (i = 0; i < 2; ++i) {
            const int ra = VLBE__ALE_E(a) + i;
            Q[ra] += sc[a] * Qs[2 * a + i];
            if (!jac) continue;
            for (b = 0; b < 4; ++b)
                for (j = 0; j < 2; ++j) {
                    const int cb = VLBE__ALE_E(b) + j, kk = (2 * a + i) * 8 + 2 * b + j;
                    K[ra * 10 + cb] += sc[a] * sc[b] * Ks[kk];
                    if (damp) D[ra * 10 + cb] += sc[a] * sc[b] * Ds[kk];
                }
        }
    if (!pm) return;
    /* p-rows: eps_pk = r'.dr'/dp_k = sum_b y_k,b . eps_{r_b} (scaled slots),
       so Q_pk = sum_b y_k,b . Q_b; K, D by the product rule: the rows y_k^T
       K + Q . dy_k/dr, y_k^T D; the p'-columns D y_k (= (y_k^T D)^T: D is
       symmetric), the corner y_l^T D y_k */
    for (k = 0; k < 2; ++k) {
        const int rp = VLBE__ALE_P(k);
        const vlbe_real *yk = y[k];
        vlbe_real kr[8], dy[8];
        if (!(pm & (1 << k))) continue;
        for (m = 2; m < 8; ++m) Q[rp] += yk[m] * Qs[m];
        if (!jac) continue;
        for (i = 0; i < 8; ++i) kr[i] = dy[i] = VLBE_R(0.0);
        for (m = 2; m < 8; ++m) {
            const vlbe_real ym = yk[m], *Km = Ks + m * 8, *Dm = Ds + m * 8;
            for (i = 0; i < 8; ++i) {
                kr[i] += ym * Km[i];
                dy[i] += ym * Dm[i];
            }
        }
        for (b = 0; b < 4; ++b)
            for (j = 0; j < 2; ++j) {
                vlbe_real kv = VLBE_R(0.0);
                for (a = 1; a < 4; ++a) kv += iv->dp[k][4 * b + a] * Qs[2 * a + j];
                K[rp * 10 + VLBE__ALE_E(b) + j] += sc[b] * (kr[2 * b + j] + Li * kv);
            }
        if (!damp) continue;
        for (a = 0; a < 4; ++a)
            for (i = 0; i < 2; ++i) {
                const int ra = VLBE__ALE_E(a) + i;
                const vlbe_real d = sc[a] * dy[2 * a + i];
                D[rp * 10 + ra] += d;
                D[ra * 10 + rp] += d;
            }
        for (l = 0; l < 2; ++l)
            if (pm & (1 << l))
                for (m = 2; m < 8; ++m) D[VLBE__ALE_P(l) * 10 + rp] += y[l][m] * dy[m];
    }
    /* degree weights: the quartic part of the force (all but the -1/2 of
       eps) is 4 below the standard row degrees, the quadratic part Q0 (from
       -B/2 in S) 2 below: dQ += -4 Q + 2 Q0 */
    if (jac && dQ) {
        vlbe_real Z[8];
        for (i = 0; i < 8; ++i) Z[i] = VLBE_R(-4.0) * Qs[i];
        for (P = 0; P < VLBE_ALE_INV_NP; ++P) {
            const vlbe_real f = EA * Li * iv->b[P];
            a = pa[P];
            b = pa[10 + P];
            for (i = 0; i < 2; ++i) {
                Z[2 * a + i] += f * r[2 * b + i];
                if (a != b) Z[2 * b + i] += f * r[2 * a + i];
            }
        }
        for (a = 0; a < 4; ++a)
            for (i = 0; i < 2; ++i) dQ[VLBE__ALE_E(a) + i] += sc[a] * Z[2 * a + i];
        for (k = 0; k < 2; ++k)
            if (pm & (1 << k))
                for (m = 2; m < 8; ++m) dQ[VLBE__ALE_P(k)] += y[k][m] * Z[m];
    }
}

/* Distributed load of a fixed-length element: Q_a += L^(m_a+1) n_a f. */
VLBE_INLINE void vlbe__ale_inv_load(const vlbe_ale_inv *iv, vlbe_real L, const vlbe_real *f,
                                      vlbe_real *Q)
{
    int a;
    for (a = 0; a < 4; ++a)
        vlbe_v2_axpy((VLBE__ALE_M(a) ? L * L : L) * iv->n[a], f, Q + VLBE__ALE_E(a));
}

/* Q alone (K = D = NULL): the inertia/load, axial and bending terms in
   straight-line code per point.  Only the p-derivative rows N, N', N'' of
   the basis are scaled; every p1/p2 partial comes from the identity of
   NOTES applied to one function: at fixed p, d/dp2 N^(c)_j = ((m_j - c)/L)
   N^(c)_j - xi N^(c+1)_j, and d/dp1 = -(d/dp2 + d/dp).  Summed over the
   nodes (E^(c), O^(c): the parts of r^(c) from the positions, the slopes):
       Y2_c = dr^(c)/dp2 = (O^(c) - c r^(c))/L - xi r^(c+1),
       Y1_c = dr^(c)/dp1 = -Y2_c - r^(c+1),
   and, with A = p1' d/dp1 + p2' d/dp2 = (p2' - p1') d/dp2 - p1' d/dp and
   s = p1' + xi (p2' - p1'), the transport acceleration (eq. 15)
       r_v = 2 A v + A^2 r = 2 ((p2' - p1') O_v/L - s v') + 2 (p2' - p1') s E'/L + s^2 r''
   (v = S e', O_v its slope part).  The material rate of r^(c) (the
   damping) is v^(c) + (p2' - p1') Y2_c - p1' r^(c+1).  Agrees with the
   Gauss-point route of the Jacobian calls to rounding (test).  About 130
   lines of straight-line code on purpose: the most frequent call (every
   residual), one pass per point over the inertia and load (eqs. 15, 19 of
   [R]), axial (eqs. 19, 21) and bending terms (eq. 22), sharing the
   point's r, r', r'' and their p-partials; split, each part would gather
   them again. */
VLBE_INLINE vlbe_status vlbe__ale_q(const vlbe_ale_elem *el, const vlbe_real *f, int pm,
                                      int damp, int bend, int shared, int inv, const vlbe_real *Lp,
                                      const vlbe_real *pd, const vlbe_real *q, const vlbe_real *qd,
                                      vlbe_real *Q)
{
    const vlbe_ale_mat *mt = &el->mat;
    const vlbe_real *e0 = q, *e1 = q + 2, *e2 = q + 5, *e3 = q + 7;
    const vlbe_real *u0 = qd, *u1 = qd + 2, *u2 = qd + 5, *u3 = qd + 7;
    const vlbe_real L = Lp[5], Li = Lp[3], a = pd[0], dl = pd[1] - pd[0];
    const vlbe_real cE = damp ? mt->c_eps * mt->EA : VLBE_R(0.0);
    const vlbe_real cB = damp ? mt->c_kap * mt->EI : VLBE_R(0.0);
    vlbe_real R1[VLBE_ALE_NGP_MAX][2], gt[VLBE_ALE_NGP_MAX], g3[VLBE_ALE_NGP_MAX];
    int g, b, pass;

    /* transport inertia and distributed load: z = f - rhoA r_v (eqs. 15, 19);
       fixed length with invariants: the load alone, from the tables */
    if (inv && !pm) vlbe__ale_inv_load(&el->inv, L, f, Q);
    for (g = 0; !(inv && !pm) && g < el->rm.n; ++g) {
        const vlbe_ale_gp *gp = &el->rm.g[g];
        const vlbe_real *b0 = gp->b[0][0], *b1 = gp->b[1][0], *b2 = gp->b[2][0];
        const vlbe_real w = gp->w * L, xi = gp->xi, s = a + xi * dl;
        const vlbe_real n0 = b0[0], n1 = b0[1] * L, n2 = b0[2], n3 = b0[3] * L;
        vlbe_real z[2], Y1[2] = {0, 0}, Y2[2] = {0, 0};
        for (b = 0; b < 2; ++b) {
            z[b] = f[b];
            if (pm) {
                const vlbe_real E1 = Li * (b1[0] * e0[b] + b1[2] * e2[b]);
                const vlbe_real r1 = E1 + b1[1] * e1[b] + b1[3] * e3[b];
                const vlbe_real r2 = Lp[2] * (b2[0] * e0[b] + b2[2] * e2[b]) +
                                     Li * (b2[1] * e1[b] + b2[3] * e3[b]);
                const vlbe_real v1 = Li * (b1[0] * u0[b] + b1[2] * u2[b]) + b1[1] * u1[b] +
                                     b1[3] * u3[b];
                const vlbe_real Ov = n1 * u1[b] + n3 * u3[b];
                const vlbe_real rv = VLBE_R(2.0) * (dl * Ov * Li - s * v1 + dl * s * Li * E1) +
                                     s * s * r2;
                Y2[b] = (n1 * e1[b] + n3 * e3[b]) * Li - xi * r1;
                Y1[b] = -Y2[b] - r1;
                z[b] -= mt->rhoA * rv;
            }
        }
        for (b = 0; b < 2; ++b) {
            Q[0 + b] += w * n0 * z[b];
            Q[2 + b] += w * n1 * z[b];
            Q[5 + b] += w * n2 * z[b];
            Q[7 + b] += w * n3 * z[b];
        }
        if (pm & 1) Q[4] += w * vlbe_v2_dot(Y1, z);
        if (pm & 2) Q[9] += w * vlbe_v2_dot(Y2, z);
    }

    /* axial (with bending when the rules share the points), then bending;
       inv: the axial part from the invariants */
    if (inv && mt->EA != VLBE_R(0.0))
        vlbe__ale_inv_axial(&el->inv, mt->EA, damp ? mt->c_eps : VLBE_R(0.0), L, pm, pd, q, qd, Q,
                            NULL, NULL, NULL, NULL, NULL);
    for (pass = 0; pass < 2; ++pass) {
        const int ax = pass == 0 && mt->EA != VLBE_R(0.0) && !inv;
        const int bd = pass == 0 ? shared : (bend && !shared);
        const vlbe_ale_rule *ru = pass == 0 ? &el->rl : &el->rt;
        if (!ax && !bd) continue;
        /* r' first at every point, then the curvature factors |r'|^-2,
           |r'|^-3 of all points together: their divisions and square roots
           overlap instead of each ending a dependency chain */
        for (g = 0; g < ru->n; ++g) {
            const vlbe_real *b1 = ru->g[g].b[1][0];
            for (b = 0; b < 2; ++b)
                R1[g][b] = Li * (b1[0] * e0[b] + b1[2] * e2[b]) + b1[1] * e1[b] + b1[3] * e3[b];
            gt[g] = vlbe_v2_dot(R1[g], R1[g]);
        }
        if (bd) {
            for (g = 0; g < ru->n; ++g)
                if (!(gt[g] > VLBE_EPS)) return VLBE_ESINGULAR;
            for (g = 0; g < ru->n; ++g) {
                gt[g] = VLBE_R(1.0) / gt[g];
                g3[g] = gt[g] * vlbe_sqrt(gt[g]);
            }
        }
        for (g = 0; g < ru->n; ++g) {
            const vlbe_ale_gp *gp = &ru->g[g];
            const vlbe_real *b1 = gp->b[1][0], *b2 = gp->b[2][0], *b3 = gp->b3;
            const vlbe_real w = gp->w * L, xi = gp->xi;
            const vlbe_real n10 = b1[0] * Li, n11 = b1[1], n12 = b1[2] * Li, n13 = b1[3];
            const vlbe_real n20 = b2[0] * Lp[2], n21 = b2[1] * Li, n22 = b2[2] * Lp[2],
                            n23 = b2[3] * Li;
            const vlbe_real *r1 = R1[g];
            vlbe_real r2[2], r3[2], Y1[4], Y2[4], yd[4] = {0, 0, 0, 0}, G[4] = {0, 0, 0, 0};
            vlbe_real gy[4], sig, kap;
            for (b = 0; b < 2; ++b) {
                r3[b] = Lp[1] * (b3[0] * e0[b] + b3[2] * e2[b]) +
                        Lp[2] * (b3[1] * e1[b] + b3[3] * e3[b]);
            }
            for (b = 0; b < 2; ++b) {
                const vlbe_real E1 = Li * (b1[0] * e0[b] + b1[2] * e2[b]);
                const vlbe_real E2 = n20 * e0[b] + n22 * e2[b], O2 = n21 * e1[b] + n23 * e3[b];
                r2[b] = E2 + O2;
                Y2[b] = -E1 * Li - xi * r2[b];
                Y1[b] = -Y2[b] - r2[b];
                Y2[2 + b] = -(VLBE_R(2.0) * E2 + O2) * Li - xi * r3[b];
                Y1[2 + b] = -Y2[2 + b] - r3[b];
                if (damp) {
                    yd[b] = n10 * u0[b] + n11 * u1[b] + n12 * u2[b] + n13 * u3[b] + dl * Y2[b] -
                            a * r2[b];
                    yd[2 + b] = n20 * u0[b] + n21 * u1[b] + n22 * u2[b] + n23 * u3[b] +
                                dl * Y2[2 + b] - a * r3[b];
                }
            }
            if (ax) {
                const vlbe_real eps = vlbe__ale_eps(r1, gy, NULL);
                sig = mt->EA * eps + cE * (gy[0] * yd[0] + gy[1] * yd[1]);
                G[0] = sig * gy[0];
                G[1] = sig * gy[1];
            }
            if (bd) {
                vlbe__ale_kap_t(r1, r2, gt[g], g3[g], &kap, gy, NULL);
                sig = mt->EI * kap +
                      cB * (gy[0] * yd[0] + gy[1] * yd[1] + gy[2] * yd[2] + gy[3] * yd[3]);
                for (b = 0; b < 4; ++b) G[b] += sig * gy[b];
            }
            for (b = 0; b < 2; ++b) {
                Q[0 + b] -= w * (n10 * G[b] + n20 * G[2 + b]);
                Q[2 + b] -= w * (n11 * G[b] + n21 * G[2 + b]);
                Q[5 + b] -= w * (n12 * G[b] + n22 * G[2 + b]);
                Q[7 + b] -= w * (n13 * G[b] + n23 * G[2 + b]);
            }
            if (pm & 1) Q[4] -= w * (G[0] * Y1[0] + G[1] * Y1[1] + G[2] * Y1[2] + G[3] * Y1[3]);
            if (pm & 2) Q[9] -= w * (G[0] * Y2[0] + G[1] * Y2[1] + G[2] * Y2[2] + G[3] * Y2[3]);
        }
    }
    return VLBE_OK;
}

/* The inertia/load, axial and bending terms: Q always, and K and D when K is
   given (e- and p'-columns directly, then the p-columns by the scaling
   identity).  Q, K, D are the caller's zeroed locals; f the distributed
   load (el->mat.f, or the chain's scaled copy).  Terms: the transport
   inertia and load (eqs. 15, 19 of [R]) here, per mass point; the axial
   and bending forces (eqs. 19, 21, 22) by vlbe__ale_strain_gp or the
   invariants (vlbe__ale_inv_axial); the energy flux of a conservative
   element by vlbe__ale_flux.  About 120 lines: the mass-point loop with
   its p'-columns of D is the one part written here. */
VLBE_INLINE vlbe_status vlbe__ale_forces(const vlbe_ale_elem *el, unsigned mode,
                                           const vlbe_real *f, const vlbe_real *q,
                                           const vlbe_real *qd,
                                           vlbe_real *Q, vlbe_real *K, vlbe_real *D)
{
    const vlbe_ale_mat *mt = &el->mat;
    const int pm = vlbe__ale_pmask(mode), jac = K != NULL;
    const int damp = !(mode & VLBE_ALE_NO_DAMP);
    const int bend = !(mode & VLBE_ALE_NO_BEND) && mt->EI != VLBE_R(0.0);
    const vlbe_real L = q[9] - q[4];
    const int inv = (mode & VLBE_ALE_INV_AXIAL) != 0, tload = inv && pm == 0;
    const int shared = bend && mt->EA != VLBE_R(0.0) && el->rl.n == el->rt.n && !inv;
    vlbe_real pd[2], Lp[6], dQ[10], dQx[10], Ke[80], De[80];
    vlbe_status st;
    int g, i, j, k;
    vlbe__ale_lpow(L, Lp);
    pd[0] = (pm & 1) ? qd[4] : VLBE_R(0.0);
    pd[1] = (pm & 2) ? qd[9] : VLBE_R(0.0);
    if (!jac) {
        if ((st = vlbe__ale_q(el, f, pm, damp, bend, shared, inv, Lp, pd, q, qd, Q)) != VLBE_OK)
            return st;
        if (mode & VLBE_ALE_CONSERVATIVE) return vlbe__ale_flux(el, pm, bend, q, L, Q, NULL, NULL);
        return VLBE_OK;
    }
    for (i = 0; i < 10; ++i) dQx[i] = VLBE_R(0.0);

    /* the axial force from the tables (inv; its p-columns of K come with
       the others' below; Ke, De its scratch before they are zeroed for the
       strain terms); transport inertia and distributed load: z = f -
       rhoA r_v (eqs. 15, 19), fixed length with invariants (tload): the load
       alone (constant), from the tables */
    if (inv && mt->EA != VLBE_R(0.0))
        vlbe__ale_inv_axial(&el->inv, mt->EA, damp ? mt->c_eps : VLBE_R(0.0), L, pm, pd, q, qd, Q,
                            K, D, dQx, Ke, De);
    for (i = 0; i < 80; ++i) Ke[i] = De[i] = VLBE_R(0.0);
    if (tload) vlbe__ale_inv_load(&el->inv, L, f, Q);
    for (g = 0; !tload && g < el->rm.n; ++g) {
        const vlbe_ale_gp *gp = &el->rm.g[g];
        const vlbe_real w = gp->w * L;
        vlbe_real z[2], c[4], dd[4];
        vlbe__ale_pt pt; /* per point: its storage is shared with the strain points' */
        vlbe__ale_pt_eval(gp, Lp, 0, 0, pm ? VLBE_DA_N : 1, q, pm ? qd : NULL, 3, &pt);
        z[0] = f[0];
        z[1] = f[1];
        if (pm) {
            for (i = 0; i < 2; ++i)
                z[i] -= mt->rhoA * (VLBE_R(2.0) * (pd[0] * pt.V[0][1][i] + pd[1] * pt.V[0][2][i]) +
                                    pd[0] * pd[0] * pt.X[0][VLBE_DA_11][i] +
                                    VLBE_R(2.0) * pd[0] * pd[1] * pt.X[0][VLBE_DA_12][i] +
                                    pd[1] * pd[1] * pt.X[0][VLBE_DA_22][i]);
            for (j = 0; jac && j < 4; ++j) {
                c[j] = -mt->rhoA * (pd[0] * pd[0] * pt.N[0][VLBE_DA_11][j] +
                                    VLBE_R(2.0) * pd[0] * pd[1] * pt.N[0][VLBE_DA_12][j] +
                                    pd[1] * pd[1] * pt.N[0][VLBE_DA_22][j]);
                dd[j] = -mt->rhoA * VLBE_R(2.0) * (pd[0] * pt.N[0][1][j] + pd[1] * pt.N[0][2][j]);
            }
        }
        vlbe__ale_gtz(&pt, pm, w, z, jac && pm ? c : NULL, Q, K);
        if (!jac || !pm) continue;
        /* D: e'-columns (dz/de'_j = dd_j I) and p'-columns (dz/dp'_k) */
        for (j = 0; j < 4; ++j) {
            const int cj = VLBE__ALE_E(j);
            const vlbe_real wd = w * dd[j];
            for (i = 0; i < 4; ++i) {
                const int r = VLBE__ALE_E(i);
                const vlbe_real t = wd * pt.N[0][0][i];
                D[r * 10 + cj] += t;
                D[(r + 1) * 10 + cj + 1] += t;
            }
            for (k = 0; k < 2; ++k)
                if (pm & (1 << k)) {
                    D[VLBE__ALE_P(k) * 10 + cj] += wd * pt.X[0][1 + k][0];
                    D[VLBE__ALE_P(k) * 10 + cj + 1] += wd * pt.X[0][1 + k][1];
                }
        }
        for (k = 0; k < 2; ++k)
            if (pm & (1 << k)) {
                /* dr_v/dp'_k = 2 V_0,k + 2 p1' X_0,1k + 2 p2' X_0,2k */
                const int a1 = k == 0 ? VLBE_DA_11 : VLBE_DA_12;
                const int a2 = k == 0 ? VLBE_DA_12 : VLBE_DA_22;
                vlbe_real dz[2], col[10];
                for (i = 0; i < 2; ++i)
                    dz[i] = -mt->rhoA * VLBE_R(2.0) *
                            (pt.V[0][1 + k][i] + pd[0] * pt.X[0][a1][i] + pd[1] * pt.X[0][a2][i]);
                for (i = 0; i < 10; ++i) col[i] = VLBE_R(0.0);
                vlbe__ale_gtz(&pt, pm, w, dz, NULL, col, NULL);
                for (i = 0; i < 10; ++i) D[i * 10 + VLBE__ALE_P(k)] += col[i];
            }
    }

    /* axial and bending; at the axial points the bending term too when
       the rules have the same points (the default) */
    if (mt->EA != VLBE_R(0.0) && !inv)
        for (g = 0; g < el->rl.n; ++g)
            if ((st = vlbe__ale_strain_gp(mt, &el->rl.g[g], Lp, pm, pd, 1, shared, damp, q, qd, Q,
                                          jac ? Ke : NULL, De, D, dQx)) != VLBE_OK)
                return st;
    if (bend && !shared)
        for (g = 0; g < el->rt.n; ++g)
            if ((st = vlbe__ale_strain_gp(mt, &el->rt.g[g], Lp, pm, pd, 0, 1, damp, q, qd, Q,
                                          jac ? Ke : NULL, De, D, dQx)) != VLBE_OK)
                return st;
    if (jac) /* the strain terms' e-columns */
        for (i = 0; i < 10; ++i)
            for (j = 0; j < 4; ++j)
                for (k = 0; k < 2; ++k) {
                    K[i * 10 + VLBE__ALE_E(j) + k] += Ke[i * 8 + 2 * j + k];
                    D[i * 10 + VLBE__ALE_E(j) + k] += De[i * 8 + 2 * j + k];
                }

    /* p-columns of K by the scaling identity: standard row degrees for all
       terms, the axial part's lower degrees in dQx */
    if (jac && pm) {
        vlbe__ale_degree(vlbe__ale_lay2(), Q, dQ);
        for (i = 0; i < 10; ++i) dQ[i] += dQx[i];
    }
    if (mode & VLBE_ALE_CONSERVATIVE)
        if ((st = vlbe__ale_flux(el, pm, bend, q, L, Q, K, jac ? dQ : NULL)) != VLBE_OK) return st;
    if (jac && pm) vlbe__ale_pcols(vlbe__ale_lay2(), L, pm, dQ, pd, q, qd, K, D);
    return VLBE_OK;
}

/* vlbe_ale_force with the final mode (element flags already ORed in);
   fin = 0 skips the final finiteness check of the outputs (for a caller
   that bounded them from the data, vlbe_ale_inv_chain_force); f: the
   distributed load (NULL: el->mat.f) */
VLBE_INLINE vlbe_status vlbe__ale_force(const vlbe_ale_elem *el, unsigned mode,
                                          const vlbe_real *q, const vlbe_real *qd, vlbe_real *Q,
                                          vlbe_real *K, vlbe_real *D, int fin, const vlbe_real *f)
{
    vlbe_real Qt[10], Kt[100], Dt[100];
    const int jac = K != NULL || D != NULL;
    vlbe_status st;
    int i;
    if ((st = vlbe__ale_check(q, qd)) != VLBE_OK) return st;
    for (i = 0; i < 10; ++i) Qt[i] = VLBE_R(0.0);
    if (jac)
        for (i = 0; i < 100; ++i) Kt[i] = Dt[i] = VLBE_R(0.0);
    st = vlbe__ale_forces(el, mode, f ? f : el->mat.f, q, qd, Qt, jac ? Kt : NULL,
                          jac ? Dt : NULL);
    if (st != VLBE_OK) return st;
    /* finite inputs can still overflow (huge slopes, rates, L^3 of a huge
       element): nothing is written then */
    if (fin && (!vlbe_all_finite(Qt, 10) || (K && !vlbe_all_finite(Kt, 100)) ||
                (D && !vlbe_all_finite(Dt, 100))))
        return VLBE_ENONFINITE;
    for (i = 0; i < 10; ++i) Q[i] = Qt[i];
    if (K)
        for (i = 0; i < 100; ++i) K[i] = Kt[i];
    if (D)
        for (i = 0; i < 100; ++i) D[i] = Dt[i];
    return VLBE_OK;
}

VLBE_API vlbe_status vlbe_ale_force(const vlbe_ale_elem *el, unsigned mode, const vlbe_real *q,
                                    const vlbe_real *qd, vlbe_real *VLBE_RESTRICT Q,
                                    vlbe_real *VLBE_RESTRICT K, vlbe_real *VLBE_RESTRICT D)
{
    VLBE_ASSERT(el != NULL && q != NULL && qd != NULL && Q != NULL);
    return vlbe__ale_force(el, mode | el->flags, q, qd, Q, K, D, 1, NULL);
}

/* ===== mass, mass Jacobian, kinetic energy: both elements ================
   One implementation for the planar element (eq. 19) and the 3D one (eq.
   28 of [V]), driven by the layout (vlbe__ale_lay).  At a mass point G_r =
   dr/dq = [N_j I_d | X_k] and, with spin, G_th = dtheta/dq = [H_j | Xt_k],
   X_k = dr/dp_k and Xt_k = dtheta/dp_k at fixed e (k = 1, 2, only for a
   free p_k); M = sum_g w_g (rhoA G_r^T G_r + rhoI G_th^T G_th). */

/* X_k = dr/dp_k and Xt_k = dtheta/dp_k of the coordinates x at one point,
   for the p_k in pm (zero for the others). */
VLBE_INLINE void vlbe__ale_xp(const vlbe__ale_lay *ly, int d, const vlbe__ale_lpt *pt, int pm,
                              const vlbe_real *x, vlbe_real (*X)[3], vlbe_real *Xt)
{
    int k, c;
    for (k = 0; k < 2; ++k)
        if (pm & (1 << k)) {
            vlbe__ale_lsum(ly, d, pt->N[0][1 + k], x, X[k]);
            Xt[k] = vlbe__ale_lsum_th(ly, pt->H[0][1 + k], x);
        } else {
            for (c = 0; c < 3; ++c) X[k][c] = VLBE_R(0.0);
            Xt[k] = VLBE_R(0.0);
        }
}

/* One point's part wa G_r^T G_r + wi G_th^T G_th of M: the e-e and th-th
   blocks for i <= j, p1-p2 for k <= l, every coupling with a p on the
   p-row (vlbe__ale_mass_mirror completes M). */
VLBE_INLINE void vlbe__ale_mass_pt(const vlbe__ale_lay *ly, int d, const vlbe__ale_lpt *pt, int pm,
                                   const vlbe_real (*X)[3], const vlbe_real *Xt, vlbe_real wa,
                                   vlbe_real wi, vlbe_real *M)
{
    const int n = ly->n;
    const vlbe_real *N = pt->N[0][0], *H = pt->H[0][0];
    int i, j, k, l, c;
    for (i = 0; i < 4; ++i) {
        const int r = ly->e[i];
        const vlbe_real wn = wa * N[i];
        for (j = i; j < 4; ++j) {
            const vlbe_real t = wn * N[j];
            for (c = 0; c < d; ++c) M[(r + c) * n + ly->e[j] + c] += t;
        }
        for (k = 0; k < 2; ++k)
            if (pm & (1 << k))
                for (c = 0; c < d; ++c) M[ly->p[k] * n + r + c] += wn * X[k][c];
    }
    if (ly->spin)
        for (i = 0; i < 2; ++i) {
            const vlbe_real hi = wi * H[i];
            for (j = i; j < 2; ++j) M[ly->th[i] * n + ly->th[j]] += hi * H[j];
            for (k = 0; k < 2; ++k)
                if (pm & (1 << k)) M[ly->p[k] * n + ly->th[i]] += hi * Xt[k];
        }
    for (k = 0; k < 2; ++k)
        for (l = k; l < 2; ++l)
            if ((pm & (1 << k)) && (pm & (1 << l))) {
                vlbe_real t = wa * vlbe_vec_dot(d, X[k], X[l]);
                if (ly->spin) t += wi * Xt[k] * Xt[l];
                M[ly->p[k] * n + ly->p[l]] += t;
            }
}

/* Complete M from the parts vlbe__ale_mass_pt accumulated (the blocks it
   writes, not a scan of all n^2 entries): M is exactly symmetric. */
VLBE_INLINE void vlbe__ale_mass_mirror(const vlbe__ale_lay *ly, int d, int pm, vlbe_real *M)
{
    const int n = ly->n;
    int i, j, k, c;
    for (i = 0; i < 4; ++i)
        for (j = i + 1; j < 4; ++j)
            for (c = 0; c < d; ++c)
                M[(ly->e[j] + c) * n + ly->e[i] + c] = M[(ly->e[i] + c) * n + ly->e[j] + c];
    if (ly->spin) M[ly->th[1] * n + ly->th[0]] = M[ly->th[0] * n + ly->th[1]];
    for (k = 0; k < 2; ++k)
        if (pm & (1 << k)) {
            const int p = ly->p[k];
            for (i = 0; i < 4; ++i)
                for (c = 0; c < d; ++c) M[(ly->e[i] + c) * n + p] = M[p * n + ly->e[i] + c];
            if (ly->spin)
                for (i = 0; i < 2; ++i) M[ly->th[i] * n + p] = M[p * n + ly->th[i]];
        }
    if ((pm & 3) == 3) M[ly->p[1] * n + ly->p[0]] = M[ly->p[0] * n + ly->p[1]];
}

/* A mass matrix sum_g w_g G^T G (w_g > 0, sum w_g = rho L) is bounded
   before it is formed, so that it can be accumulated in the caller's M:
   its entries are w times products of basis values N (|N| <= A = bmax
   max(1, L)) and components of the p-partials X of r (|X_c| <= Xc =
   bmax (sum of the position/angle components / L + sum of the slope
   components) <= 2 bmax (mp / L + ms) for the two nodes' largest
   components mp, ms; d components: |X.X| <= d Xc^2), so every entry and
   every partial sum is at most rho L (A + 2 Xc)^2 for d <= 4, and the
   factors at most (A + 2 Xc)^2.  1 when both stay below REAL_MAX / 4.
   mp, ms: 0 with both p fixed (X is not formed then).  rho: rhoA + rhoI. */
VLBE_INLINE int vlbe__ale_mass_ok(vlbe_real bmax, vlbe_real rho, vlbe_real L, vlbe_real iL,
                                  vlbe_real mp, vlbe_real ms)
{
    const vlbe_real A = bmax * (L > VLBE_R(1.0) ? L : VLBE_R(1.0));
    const vlbe_real g = A + VLBE_R(4.0) * bmax * (mp * iL + ms);
    return g * g <= VLBE_R(0.25) * VLBE_REAL_MAX &&
           rho * L * (g * g) <= VLBE_R(0.25) * VLBE_REAL_MAX;
}

/* d(M a)/dq bounded before it is formed, with g, A, Xc of
   vlbe__ale_mass_ok (M <= rho L g^2), U = max(1, 1/L) (|p1/p2 partial of
   N| <= bmax U), am the largest |a_i|, ms the largest slope component:
   |G a| <= 4 am g, the e-columns (w c N, w N_p z, w c X with c = sum ap
   N_p) at most 8 rho L am bmax U g, M a at most 16 am rho L g^2, and the
   p-columns of the scaling identity ((dF - ap M_p + sum_slope (J_e q +
   M_e a)) / L, 6 slope components at most) at most rho L am U (40 g^2 +
   48 ms bmax U g); all below 256 rho L (1 + am) U h^2 with h = g + bmax U
   (1 + ms).  1 when that and its factor without rho L stay below
   REAL_MAX / 4 (which implies vlbe__ale_mass_ok). */
VLBE_INLINE int vlbe__ale_mjac_ok(vlbe_real bmax, vlbe_real rho, vlbe_real L, vlbe_real iL,
                                  vlbe_real mp, vlbe_real ms, vlbe_real am)
{
    const vlbe_real A = bmax * (L > VLBE_R(1.0) ? L : VLBE_R(1.0));
    const vlbe_real U = iL > VLBE_R(1.0) ? iL : VLBE_R(1.0);
    const vlbe_real h = A + VLBE_R(4.0) * bmax * (mp * iL + ms) + bmax * U * (VLBE_R(1.0) + ms);
    const vlbe_real f = VLBE_R(256.0) * (VLBE_R(1.0) + am) * U * h * h;
    return f <= VLBE_R(0.25) * VLBE_REAL_MAX && rho * L * f <= VLBE_R(0.25) * VLBE_REAL_MAX;
}

/* largest position or spin-angle component (they scale with 1/L in the
   p-partials) and slope component of the two nodes */
VLBE_INLINE void vlbe__ale_qmax(const vlbe__ale_lay *ly, int d, const vlbe_real *q,
                                vlbe_real *mp, vlbe_real *ms)
{
    int i, c;
    *mp = *ms = VLBE_R(0.0);
    for (i = 0; i < 2; ++i) {
        for (c = 0; c < d; ++c) {
            const vlbe_real a = vlbe_fabs(q[ly->e[2 * i] + c]);
            const vlbe_real b = vlbe_fabs(q[ly->e[2 * i + 1] + c]);
            *mp = a > *mp ? a : *mp;
            *ms = b > *ms ? b : *ms;
        }
        if (ly->spin) {
            const vlbe_real a = vlbe_fabs(q[ly->th[i]]);
            *mp = a > *mp ? a : *mp;
        }
    }
}

/* The density, mass rule and bound of one element, as the kernels below
   take them (rhoI = 0: no spin field). */
typedef struct vlbe__ale_inertia {
    const vlbe_ale_rule *rm;
    vlbe_real rhoA, rhoI, bmax;
} vlbe__ale_inertia;

/* M(q), bounded first (vlbe__ale_mass_ok): VLBE_ENONFINITE, nothing
   written, when it could overflow.  d = ly->d: a literal at every call
   (vlbe__ale_lsum). */
VLBE_INLINE vlbe_status vlbe__ale_mass(const vlbe__ale_lay *ly, int d, const vlbe__ale_inertia *in,
                                       int pm, const vlbe_real *q, vlbe_real *VLBE_RESTRICT M)
{
    const vlbe_real L = q[ly->p[1]] - q[ly->p[0]];
    vlbe_real Lp[6], X[2][3], Xt[2], mp = VLBE_R(0.0), ms = VLBE_R(0.0);
    vlbe__ale_lpt pt;
    int g, i;
    vlbe__ale_lpow(L, Lp);
    if (pm) vlbe__ale_qmax(ly, d, q, &mp, &ms);
    if (!vlbe__ale_mass_ok(in->bmax, in->rhoA + in->rhoI, L, Lp[3], mp, ms))
        return VLBE_ENONFINITE;
    for (i = 0; i < ly->n * ly->n; ++i) M[i] = VLBE_R(0.0);
    for (g = 0; g < in->rm->n; ++g) {
        const vlbe_real gw = in->rm->g[g].w;
        vlbe__ale_lpt_eval(&in->rm->g[g], Lp, 0, 0, pm ? 3 : 1, ly->spin, &pt);
        vlbe__ale_xp(ly, d, &pt, pm, q, X, Xt);
        vlbe__ale_mass_pt(ly, d, &pt, pm, (const vlbe_real(*)[3])X, Xt, in->rhoA * gw * L,
                          in->rhoI * gw * L, M);
    }
    vlbe__ale_mass_mirror(ly, d, pm, M);
    return VLBE_OK;
}

/* Mq = d(M a)/dq (zero with both p fixed: M is constant).  With z = G a
   per field, d(G^T z)/de_j = G^T dz/de_j + (dG/de_j)^T z, dz/de_j = c_j
   = sum_k a_pk dN_j/dp_k (the p-columns of G are linear in e); the
   p-columns by the scaling identity with D = M and the rates a
   (vlbe__ale_pcols).  Mq is written only after the bound check. */
VLBE_INLINE vlbe_status vlbe__ale_mass_jac(const vlbe__ale_lay *ly, int d,
                                           const vlbe__ale_inertia *in, int pm, const vlbe_real *q,
                                           const vlbe_real *a, vlbe_real *VLBE_RESTRICT J)
{
    const int n = ly->n;
    vlbe_real M[VLBE_ALE3_NQ * VLBE_ALE3_NQ], Ma[VLBE_ALE3_NQ], dF[VLBE_ALE3_NQ];
    vlbe_real ap[2], Lp[6], L, mp, ms, am = VLBE_R(0.0);
    vlbe__ale_lpt pt;
    int g, i, j, k, c;
    if (!pm) {
        for (i = 0; i < n * n; ++i) J[i] = VLBE_R(0.0);
        return VLBE_OK;
    }
    L = q[ly->p[1]] - q[ly->p[0]];
    ap[0] = (pm & 1) ? a[ly->p[0]] : VLBE_R(0.0);
    ap[1] = (pm & 2) ? a[ly->p[1]] : VLBE_R(0.0);
    vlbe__ale_lpow(L, Lp);
    vlbe__ale_qmax(ly, d, q, &mp, &ms);
    for (i = 0; i < n; ++i) am = vlbe_fabs(a[i]) > am ? vlbe_fabs(a[i]) : am;
    if (!vlbe__ale_mjac_ok(in->bmax, in->rhoA + in->rhoI, L, Lp[3], mp, ms, am))
        return VLBE_ENONFINITE;
    for (i = 0; i < n; ++i) Ma[i] = VLBE_R(0.0);
    for (i = 0; i < n * n; ++i) M[i] = J[i] = VLBE_R(0.0);
    for (g = 0; g < in->rm->n; ++g) { /* d(M a)/dq and M itself */
        const vlbe_real gw = in->rm->g[g].w, wa = in->rhoA * gw * L, wi = in->rhoI * gw * L;
        vlbe_real X[2][3], Xt[2], z[3], zt = VLBE_R(0.0), cN[4], cH[2] = {0, 0};
        vlbe__ale_lpt_eval(&in->rm->g[g], Lp, 0, 0, 3, ly->spin, &pt);
        vlbe__ale_xp(ly, d, &pt, 3, q, X, Xt);
        vlbe__ale_lsum(ly, d, pt.N[0][0], a, z); /* z = G_r a, zt = G_th a */
        if (ly->spin) zt = vlbe__ale_lsum_th(ly, pt.H[0][0], a);
        for (k = 0; k < 2; ++k)
            if (pm & (1 << k)) {
                for (c = 0; c < d; ++c) z[c] += ap[k] * X[k][c];
                zt += ap[k] * Xt[k];
            }
        for (j = 0; j < 4; ++j) cN[j] = ap[0] * pt.N[0][1][j] + ap[1] * pt.N[0][2][j];
        if (ly->spin)
            for (j = 0; j < 2; ++j) cH[j] = ap[0] * pt.H[0][1][j] + ap[1] * pt.H[0][2][j];
        for (j = 0; j < 4; ++j) { /* M a: e-rows */
            const vlbe_real wn = wa * pt.N[0][0][j];
            for (c = 0; c < d; ++c) Ma[ly->e[j] + c] += wn * z[c];
        }
        if (ly->spin)
            for (j = 0; j < 2; ++j) Ma[ly->th[j]] += wi * pt.H[0][0][j] * zt;
        for (k = 0; k < 2; ++k)
            if (pm & (1 << k)) {
                const vlbe_real s = wa * vlbe_vec_dot(d, X[k], z);
                Ma[ly->p[k]] += ly->spin ? s + wi * Xt[k] * zt : s;
            }
        for (j = 0; j < 4; ++j) { /* J: the e-columns */
            const int cj = ly->e[j];
            const vlbe_real wc = wa * cN[j];
            if (wc != VLBE_R(0.0))
                for (i = 0; i < 4; ++i) {
                    const vlbe_real t = wc * pt.N[0][0][i];
                    for (c = 0; c < d; ++c) J[(ly->e[i] + c) * n + cj + c] += t;
                }
            for (k = 0; k < 2; ++k)
                if (pm & (1 << k)) {
                    vlbe_real *row = J + ly->p[k] * n;
                    const vlbe_real bb = wa * pt.N[0][1 + k][j];
                    for (c = 0; c < d; ++c) row[cj + c] += bb * z[c] + wc * X[k][c];
                }
        }
        if (ly->spin)
            for (j = 0; j < 2; ++j) { /* J: the spin-angle columns */
                const int cj = ly->th[j];
                const vlbe_real wc = wi * cH[j];
                for (i = 0; i < 2; ++i) J[ly->th[i] * n + cj] += wc * pt.H[0][0][i];
                for (k = 0; k < 2; ++k)
                    if (pm & (1 << k))
                        J[ly->p[k] * n + cj] += wi * pt.H[0][1 + k][j] * zt + wc * Xt[k];
            }
        vlbe__ale_mass_pt(ly, d, &pt, pm, (const vlbe_real(*)[3])X, Xt, wa, wi, M);
    }
    vlbe__ale_mass_mirror(ly, d, pm, M);
    vlbe__ale_degree(ly, Ma, dF);
    vlbe__ale_pcols(ly, L, pm, dF, ap, q, a, J, M);
    return VLBE_OK;
}

/* Kinetic energy T = int (rhoA |r_t|^2 + rhoI theta_t^2) / 2 dp with r_t
   = G_r q', theta_t = G_th q', and the potential V = -int f . r dp of the
   distributed load f, over the mass points. */
VLBE_INLINE void vlbe__ale_kin_pot(const vlbe__ale_lay *ly, int d, const vlbe__ale_inertia *in,
                                   const vlbe_real *f, int pm, const vlbe_real *q,
                                   const vlbe_real *qd, vlbe_real *T, vlbe_real *V)
{
    const vlbe_real L = q[ly->p[1]] - q[ly->p[0]];
    vlbe_real Lp[6], X[2][3], Xt[2];
    vlbe__ale_lpt pt;
    int g, k, c;
    vlbe__ale_lpow(L, Lp);
    *T = *V = VLBE_R(0.0);
    for (g = 0; g < in->rm->n; ++g) {
        const vlbe_real w = in->rm->g[g].w * L;
        vlbe_real v[3], r[3], vt = VLBE_R(0.0);
        vlbe__ale_lpt_eval(&in->rm->g[g], Lp, 0, 0, pm ? 3 : 1, ly->spin, &pt);
        vlbe__ale_xp(ly, d, &pt, pm, q, X, Xt);
        vlbe__ale_lsum(ly, d, pt.N[0][0], qd, v);
        if (ly->spin) vt = vlbe__ale_lsum_th(ly, pt.H[0][0], qd);
        for (k = 0; k < 2; ++k)
            if (pm & (1 << k)) {
                for (c = 0; c < d; ++c) v[c] += qd[ly->p[k]] * X[k][c];
                vt += qd[ly->p[k]] * Xt[k];
            }
        *T += w * VLBE_R(0.5) * in->rhoA * vlbe_vec_dot(d, v, v);
        if (ly->spin) *T += w * VLBE_R(0.5) * in->rhoI * vt * vt;
        vlbe__ale_lsum(ly, d, pt.N[0][0], q, r);
        *V -= w * vlbe_vec_dot(d, f, r);
    }
}

/* The planar element's density, mass rule and bound */
VLBE_INLINE void vlbe__ale_inertia2(const vlbe_ale_elem *el, vlbe__ale_inertia *in)
{
    in->rm = &el->rm;
    in->rhoA = el->mat.rhoA;
    in->rhoI = VLBE_R(0.0);
    in->bmax = el->bmax;
}

/* M(q) = rhoA int G^T G dp (eq. 19), through vlbe__ale_mass */
VLBE_API vlbe_status vlbe_ale_mass(const vlbe_ale_elem *el, unsigned mode, const vlbe_real *q,
                                   vlbe_real *VLBE_RESTRICT M)
{
    vlbe__ale_inertia in;
    vlbe_status st;
    VLBE_ASSERT(el != NULL && q != NULL && M != NULL);
    if ((st = vlbe__ale_check(q, NULL)) != VLBE_OK) return st;
    vlbe__ale_inertia2(el, &in);
    return vlbe__ale_mass(vlbe__ale_lay2(), 2, &in, vlbe__ale_pmask(mode | el->flags), q, M);
}

VLBE_API vlbe_status vlbe_ale_mass_jac(const vlbe_ale_elem *el, unsigned mode, const vlbe_real *q,
                                       const vlbe_real *a, vlbe_real *VLBE_RESTRICT Mq)
{
    vlbe__ale_inertia in;
    vlbe_status st;
    VLBE_ASSERT(el != NULL && q != NULL && a != NULL && Mq != NULL);
    if ((st = vlbe__ale_check(q, a)) != VLBE_OK) return st;
    vlbe__ale_inertia2(el, &in);
    return vlbe__ale_mass_jac(vlbe__ale_lay2(), 2, &in, vlbe__ale_pmask(mode | el->flags), q, a,
                              Mq);
}

VLBE_API vlbe_status vlbe_ale_energy(const vlbe_ale_elem *el, unsigned mode, const vlbe_real *q,
                                     const vlbe_real *qd, vlbe_real *VLBE_RESTRICT E)
{
    const vlbe_ale_mat *mt = &el->mat;
    vlbe_real L, Lp[6], gy[4], T, U = VLBE_R(0.0), V;
    vlbe__ale_inertia in;
    vlbe__ale_pt pt;
    vlbe_status st;
    int g;
    VLBE_ASSERT(el != NULL && q != NULL && qd != NULL && E != NULL);
    mode |= el->flags;
    if ((st = vlbe__ale_check(q, qd)) != VLBE_OK) return st;
    vlbe__ale_inertia2(el, &in);
    vlbe__ale_kin_pot(vlbe__ale_lay2(), 2, &in, mt->f, vlbe__ale_pmask(mode), q, qd, &T, &V);
    L = q[9] - q[4];
    vlbe__ale_lpow(L, Lp);
    for (g = 0; g < el->rl.n; ++g) {
        vlbe_real eps;
        vlbe__ale_pt_eval(&el->rl.g[g], Lp, 1, 1, 1, q, NULL, 0, &pt);
        eps = vlbe__ale_eps(pt.X[1][0], gy, NULL);
        U += el->rl.g[g].w * L * VLBE_R(0.5) * mt->EA * eps * eps;
    }
    if (!(mode & VLBE_ALE_NO_BEND) && mt->EI != VLBE_R(0.0))
        for (g = 0; g < el->rt.n; ++g) {
            vlbe_real kap;
            vlbe__ale_pt_eval(&el->rt.g[g], Lp, 1, 2, 1, q, NULL, 0, &pt);
            if ((st = vlbe__ale_kap(pt.X[1][0], pt.X[2][0], &kap, gy, NULL)) != VLBE_OK) return st;
            U += el->rt.g[g].w * L * VLBE_R(0.5) * mt->EI * kap * kap;
        }
    if (!isfinite(T) || !isfinite(U) || !isfinite(V)) return VLBE_ENONFINITE;
    E[0] = T;
    E[1] = U;
    E[2] = V;
    return VLBE_OK;
}

/* r and r' (either may be NULL) from a basis b evaluated with k <= 1,
   written only when both are finite (shared with rancf.h). */
VLBE_INLINE vlbe_status vlbe__ale_point_b(const vlbe_herm_ale *b, const vlbe_real *q,
                                            vlbe_real *r, vlbe_real *rp)
{
    vlbe_real x[4];
    vlbe__ale_sum(b, 0, 0, q, x);
    vlbe__ale_sum(b, 1, 0, q, x + 2);
    if (!vlbe_all_finite(x, 4)) return VLBE_ENONFINITE;
    if (r) {
        r[0] = x[0];
        r[1] = x[1];
    }
    if (rp) {
        rp[0] = x[2];
        rp[1] = x[3];
    }
    return VLBE_OK;
}

/* r(p) and r'(p) of one element (either may be NULL); p may lie outside
   [p1, p2] (the cubic is extrapolated). */
VLBE_API vlbe_status vlbe_ale_point(const vlbe_real *q, vlbe_real p, vlbe_real *VLBE_RESTRICT r,
                                    vlbe_real *VLBE_RESTRICT rp)
{
    vlbe_herm_ale b;
    vlbe_status st;
    VLBE_ASSERT(q != NULL);
    if ((st = vlbe__ale_check(q, NULL)) != VLBE_OK) return st;
    if (!isfinite(p)) return VLBE_ENONFINITE;
    vlbe_herm_ale_eval(p, q[4], q[9], 1, 0, &b);
    return vlbe__ale_point_b(&b, q, r, rp);
}

/* Strain and curvature from a basis b evaluated with k <= 2 (shared with
   rancf.h). */
VLBE_INLINE vlbe_status vlbe__ale_strain_b(const vlbe_herm_ale *b, const vlbe_real *q,
                                             vlbe_real *eps, vlbe_real *kap)
{
    vlbe_real r1[2], r2[2], gy[4], k = VLBE_R(0.0), e;
    vlbe_status st;
    vlbe__ale_sum(b, 1, 0, q, r1);
    vlbe__ale_sum(b, 2, 0, q, r2);
    if (kap && (st = vlbe__ale_kap(r1, r2, &k, gy, NULL)) != VLBE_OK) return st;
    e = vlbe__ale_eps(r1, gy, NULL);
    if ((eps && !isfinite(e)) || !isfinite(k)) return VLBE_ENONFINITE;
    if (eps) *eps = e;
    if (kap) *kap = k;
    return VLBE_OK;
}

/* Prestress of a straight element.  The axial force of the planar and the
   3D element is EA eps along r' with the Green strain eps = (|r'|^2 - 1)/2
   (p is the unstretched arc length), so a straight piece under the tension
   F (force in space, F < 0 compression) has eps with
        T(eps) = EA eps sqrt(1 + 2 eps) = F
   and the stretch lam = |r'| = sqrt(1 + 2 eps): a span of length l in space
   holds l / lam of material (so rho A, per unstretched length, gives rho A
   / lam per metre in space).  T is increasing and convex for eps > -1/3
   (T' = EA (1 + 3 eps) / lam, T'' = EA (2 + 3 eps) / lam^3), from its least
   value -EA / (3 sqrt 3) there; Newton from eps0 = F / EA, where T(eps0) >=
   F (lam >= 1 for F >= 0, lam < 1 and eps0 < 0 else), then decreases
   monotonically to the root and stops when a step no longer decreases it:
   eps to a few ulps.  EA <= 0, F or EA not finite, F <= -EA / (3 sqrt 3)
   (no stretched state left: the piece collapses): VLBE_EARG; outputs
   untouched on failure.  For a given stress-free length L0 of a span of
   length l, lam = l / L0 instead (eps = (lam^2 - 1) / 2). */
VLBE_API vlbe_status vlbe_ale_prestretch(vlbe_real EA, vlbe_real F, vlbe_real *VLBE_RESTRICT eps,
                                         vlbe_real *VLBE_RESTRICT lam)
{
    vlbe_real x[2], e, en;
    int k;
    VLBE_ASSERT(eps != NULL && lam != NULL);
    x[0] = EA;
    x[1] = F;
    if (!vlbe_all_finite(x, 2) || !(EA > VLBE_R(0.0))) return VLBE_EARG;
    if (!(F > -EA / (VLBE_R(3.0) * vlbe_sqrt(VLBE_R(3.0))))) return VLBE_EARG;
    e = F / EA;
    if (!vlbe_all_finite(&e, 1)) return VLBE_EARG; /* F / EA overflows: no such piece */
    for (k = 0; k < 200; ++k) {
        const vlbe_real l = vlbe_sqrt(VLBE_R(1.0) + VLBE_R(2.0) * e);
        const vlbe_real r = EA * e * l - F, dT = EA * (VLBE_R(1.0) + VLBE_R(3.0) * e) / l;
        if (!(r > VLBE_R(0.0)) || !(dT > VLBE_R(0.0))) break; /* at the root (to rounding) */
        en = e - r / dT;
        if (!(en < e)) break; /* no longer decreasing: converged */
        e = en;
    }
    *eps = e;
    *lam = vlbe_sqrt(VLBE_R(1.0) + VLBE_R(2.0) * e);
    return VLBE_OK;
}

/* Green strain and signed curvature at material point p (either output may
   be NULL; the curvature needs |r'|^2 > eps). */
VLBE_API vlbe_status vlbe_ale_strain(const vlbe_real *q, vlbe_real p, vlbe_real *VLBE_RESTRICT eps,
                                     vlbe_real *VLBE_RESTRICT kap)
{
    vlbe_herm_ale b;
    vlbe_status st;
    VLBE_ASSERT(q != NULL);
    if ((st = vlbe__ale_check(q, NULL)) != VLBE_OK) return st;
    if (!isfinite(p)) return VLBE_ENONFINITE;
    vlbe_herm_ale_eval(p, q[4], q[9], 2, 0, &b);
    return vlbe__ale_strain_b(&b, q, eps, kap);
}

/* A constant global force F at the material point pf in [p1, p2]:
   Q += N(pf)^T F (planar eq. 45 of [V]), K += d/dq (K may be NULL).  All ten
   rows and columns are written, whatever the element's mode. */
/* Q += N^T F, K += d/dq from a basis b evaluated with k = 0 and all p1/p2
   partials (shared with rancf.h). */
VLBE_INLINE void vlbe__ale_point_force_b(const vlbe_herm_ale *b, const vlbe_real *q,
                                           const vlbe_real *F, vlbe_real *Q, vlbe_real *K)
{
    static const int dd[2][2] = {{VLBE_DA_11, VLBE_DA_12}, {VLBE_DA_12, VLBE_DA_22}};
    vlbe_real a[2][2], x[2];
    int j, k, l;
    for (j = 0; j < 4; ++j) {
        const int r = VLBE__ALE_E(j);
        Q[r] += b->h[0][0][j] * F[0];
        Q[r + 1] += b->h[0][0][j] * F[1];
    }
    for (k = 0; k < 2; ++k) {
        vlbe__ale_sum(b, 0, 1 + k, q, a[k]);
        Q[VLBE__ALE_P(k)] += vlbe_v2_dot(a[k], F);
    }
    if (!K) return;
    for (j = 0; j < 4; ++j) {
        const int c = VLBE__ALE_E(j);
        for (k = 0; k < 2; ++k) {
            const int pk = VLBE__ALE_P(k);
            const vlbe_real h = b->h[0][1 + k][j];
            K[c * 10 + pk] += h * F[0];
            K[(c + 1) * 10 + pk] += h * F[1];
            K[pk * 10 + c] += h * F[0];
            K[pk * 10 + c + 1] += h * F[1];
        }
    }
    for (k = 0; k < 2; ++k)
        for (l = 0; l < 2; ++l) {
            vlbe__ale_sum(b, 0, dd[k][l], q, x);
            K[VLBE__ALE_P(k) * 10 + VLBE__ALE_P(l)] += vlbe_v2_dot(x, F);
        }
}

/* vlbe__ale_point_force_b on copies of Q and K, committed only when the
   sums are finite (shared with rancf.h). */
VLBE_INLINE vlbe_status vlbe__ale_point_force_c(const vlbe_herm_ale *b, const vlbe_real *q,
                                                  const vlbe_real *F, vlbe_real *Q, vlbe_real *K)
{
    vlbe_real Qt[10], Kt[100];
    int i;
    for (i = 0; i < 10; ++i) Qt[i] = Q[i];
    for (i = 0; K && i < 100; ++i) Kt[i] = K[i];
    vlbe__ale_point_force_b(b, q, F, Qt, K ? Kt : NULL);
    if (!vlbe_all_finite(Qt, 10) || (K && !vlbe_all_finite(Kt, 100))) return VLBE_ENONFINITE;
    for (i = 0; i < 10; ++i) Q[i] = Qt[i];
    for (i = 0; K && i < 100; ++i) K[i] = Kt[i];
    return VLBE_OK;
}

VLBE_API vlbe_status vlbe_ale_point_force(const vlbe_real *q, vlbe_real pf, const vlbe_real *F,
                                          vlbe_real *VLBE_RESTRICT Q, vlbe_real *VLBE_RESTRICT K)
{
    vlbe_herm_ale b;
    vlbe_status st;
    VLBE_ASSERT(q != NULL && F != NULL && Q != NULL);
    if ((st = vlbe__ale_check(q, NULL)) != VLBE_OK) return st;
    if (!isfinite(pf) || !vlbe_all_finite(F, 2)) return VLBE_ENONFINITE;
    if (pf < q[4] || pf > q[9]) return VLBE_EBOUND;
    vlbe_herm_ale_eval(pf, q[4], q[9], 0, 2, &b);
    return vlbe__ale_point_force_c(&b, q, F, Q, K);
}

/* ===== invariant-matrix forces of fixed-length elements and chains ====== */
/* Unit tables (L = 1) by the 5-point Gauss rule on [0, 1], exact for the
   integrands of degree <= 9 here (h_a' quadratic: degree 8; h_a: 3) up to
   the rounding of the rule's nodes and weights.  The slope maps dp by
   interpolation: a partial f = d h_a'/dp_k is a quadratic in xi, and so is
   its expansion c1 h_2' + c2 h_3' + c3 h_4' (h_1' = -h_3', c0 = 0); at xi
   = 0, 1/2, 1 the slopes are (1, 0, 0), (-1/4, 3/2, -1/4), (0, 0, 1), so
   c1 = f(0), c3 = f(1), c2 = (f(1/2) + (c1 + c3)/4) / (3/2).  Exact in
   floating point: f is sampled at dyadic points from integer polynomial
   coefficients, and the c are integers (tests). */
VLBE_API vlbe_status vlbe_ale_inv_init(vlbe_ale_inv *inv)
{
    const vlbe_real *x, *w;
    vlbe_real d[5][4], n[5][4], wg[5];
    vlbe_status st;
    int g, P, R, a, b, c, e, j;
    VLBE_ASSERT(inv != NULL);
    if ((st = vlbe_gl_rule(5, &x, &w)) != VLBE_OK) return st;
    for (g = 0; g < 5; ++g) {
        vlbe_herm_ale hb;
        vlbe_herm_ale_eval(VLBE_R(0.5) * (x[g] + VLBE_R(1.0)), VLBE_R(0.0), VLBE_R(1.0), 1, 0, &hb);
        wg[g] = VLBE_R(0.5) * w[g];
        for (j = 0; j < 4; ++j) {
            n[g][j] = hb.h[0][0][j];
            d[g][j] = hb.h[1][0][j];
        }
    }
    for (j = 0; j < 4; ++j) {
        inv->n[j] = VLBE_R(0.0);
        for (g = 0; g < 5; ++g) inv->n[j] += wg[g] * n[g][j];
    }
    for (P = 0; P < VLBE_ALE_INV_NP; ++P) {
        vlbe__ale_inv_slots(P, &a, &b);
        inv->b[P] = VLBE_R(0.0);
        for (g = 0; g < 5; ++g) inv->b[P] += wg[g] * d[g][a] * d[g][b];
        for (R = 0; R < VLBE_ALE_INV_NP; ++R) {
            vlbe_real t = VLBE_R(0.0);
            vlbe__ale_inv_slots(R, &c, &e);
            for (g = 0; g < 5; ++g) t += wg[g] * d[g][a] * d[g][b] * d[g][c] * d[g][e];
            inv->t[P * VLBE_ALE_INV_NP + R] = c == e ? t : VLBE_R(2.0) * t;
        }
    }
    {
        /* f[g][k][a] = d h_a'/dp_k at xi = g/2, one basis evaluation at a time */
        vlbe_real f[3][2][4];
        int k;
        for (g = 0; g < 3; ++g) {
            vlbe_herm_ale hf;
            vlbe_herm_ale_eval(VLBE_R(0.5) * (vlbe_real)g, VLBE_R(0.0), VLBE_R(1.0), 1, 1, &hf);
            for (k = 0; k < 2; ++k)
                for (a = 0; a < 4; ++a) f[g][k][a] = hf.h[1][1 + k][a];
        }
        for (k = 0; k < 2; ++k)
            for (a = 0; a < 4; ++a) {
                vlbe_real *cf = inv->dp[k] + 4 * a;
                cf[0] = VLBE_R(0.0);
                cf[1] = f[0][k][a];
                cf[3] = f[2][k][a];
                cf[2] = (f[1][k][a] + VLBE_R(0.25) * (cf[1] + cf[3])) / VLBE_R(1.5);
            }
    }
    return VLBE_OK;
}

/* vlbe_ale_force of the fixed-length element (FIX_P1 | FIX_P2 implied:
   p-rows and -columns zero, p' ignored) with the axial force and the load
   from the invariants; bending (unless NO_BEND) on Gauss points.  Errors
   and outputs as vlbe_ale_force.  (ALE elements: vlbe_ale_force with
   VLBE_ALE_INV_AXIAL in mode or flags.) */
VLBE_API vlbe_status vlbe_ale_inv_force(const vlbe_ale_elem *el, unsigned mode, const vlbe_real *q,
                                        const vlbe_real *qd, vlbe_real *VLBE_RESTRICT Q,
                                        vlbe_real *VLBE_RESTRICT K, vlbe_real *VLBE_RESTRICT D)
{
    VLBE_ASSERT(el != NULL && q != NULL && qd != NULL && Q != NULL);
    mode |= el->flags | VLBE_ALE_FIX_P1 | VLBE_ALE_FIX_P2 | VLBE_ALE_INV_AXIAL;
    return vlbe__ale_force(el, mode, q, qd, Q, K, D, 1, NULL);
}

/* n x n band storage (VLBE_ALE_INV_BW per row): entry (i, j) */
#define VLBE__ALE_BAND(i, j) ((size_t)(i) * VLBE_ALE_INV_BW + (size_t)((j) - (i) + VLBE_ALE_INV_KD))

/* |x| over the ne + 1 nodes of a chain, per component: m[j] = max |x_j|;
   0 when some x is NaN or Inf.  On the bits: for |x| the bit patterns
   (sign cleared) order like the values, and Inf and NaN lie above every
   finite one, so one integer max per lane (4 lanes, vectorized) gives the
   maxima and the finiteness. */
VLBE_INLINE int vlbe__ale_chain_max(int ne, const vlbe_real *x, vlbe_real *m)
{
    const vlbe__bits A = VLBE__BITS_ABS, E = VLBE__BITS_EXP;
    vlbe__bits b[4] = {0, 0, 0, 0}, u[4], t;
    int i, j;
    for (i = 0; i <= ne; ++i) {
        memcpy(u, x + 4 * i, sizeof u);
        for (j = 0; j < 4; ++j) {
            t = u[j] & A;
            b[j] = t > b[j] ? t : b[j];
        }
    }
    t = b[0] > b[1] ? b[0] : b[1];
    t = b[2] > t ? b[2] : t;
    t = b[3] > t ? b[3] : t;
    if (t >= E) return 0;
    memcpy(m, b, sizeof b);
    return 1;
}

/* Inputs of a chain of ne elements: lengths (L may be NULL), x, v (may be
   NULL), n = 4 (ne + 1) coordinates each; mx = the largest position and
   slope component of x, then of v (0 for v = NULL), for
   vlbe__ale_cable_ok. */
VLBE_INLINE vlbe_status vlbe__ale_chain_in(int ne, const vlbe_real *L, const vlbe_real *x,
                                             const vlbe_real *v, vlbe_real *mx)
{
    vlbe_real m[4];
    vlbe_status st;
    int e;
    if (!vlbe__ale_chain_max(ne, x, m)) return VLBE_ENONFINITE;
    mx[0] = m[0] > m[1] ? m[0] : m[1];
    mx[1] = m[2] > m[3] ? m[2] : m[3];
    mx[2] = mx[3] = VLBE_R(0.0);
    if (v) {
        if (!vlbe__ale_chain_max(ne, v, m)) return VLBE_ENONFINITE;
        mx[2] = m[0] > m[1] ? m[0] : m[1];
        mx[3] = m[2] > m[3] ? m[2] : m[3];
    }
    if (L) {
        if (!vlbe_all_finite(L, ne)) return VLBE_ENONFINITE;
        for (e = 0; e < ne; ++e)
            if ((st = vlbe__ale_len(VLBE_R(0.0), L[e])) != VLBE_OK) return st;
    }
    return VLBE_OK;
}

/* The forces of a chain of fixed-length cable elements are accumulated in
   the caller's Q, K, D, so they are bounded before anything is written:
   with mx = {xm, sm, vm, wm} the largest position and slope component of
   x and of v (vlbe__ale_chain_in), every element's |r'| <= A = 2 (3 xm /
   Lmin + 2 sm) (|h1'|, |h3'| <=
   1.5 / L, |h2'|, |h4'| <= 1; twice that for the 1-norm of 2-vectors)
   and |r_v'| <= B likewise; the axial force density is at most EA (1 + c)
   (1 + A + B)^2 and Q, K, D at most that times (1 + A + B) max(2.25 /
   Lmin, Lmax^2, 1.5) (the integrals of the basis slopes and their
   products; Lmax^2: the Gauss route forms w N = L^2 of a slope function
   for the load rows even when f = 0), times 8 for the two elements of a
   node and the Gauss route's rounding.  fq bounds the load part (|f|_1 max(L, L^2) of an element,
   or the stored load vector).  Returns 1 when that bound, and the
   factor (1 + c) (1 + A + B)^3 max(...) alone, stay below REAL_MAX / 1024
   (then no intermediate or sum can overflow: the invariant products form
   r' + c r_v' and c (r' . r_v') before EA multiplies them); inputs finite,
   Lmin > 0, c >= 0. */
VLBE_INLINE int vlbe__ale_cable_ok(vlbe_real EA, vlbe_real c, vlbe_real fq, vlbe_real Lmin,
                                     vlbe_real Lmax, const vlbe_real *m)
{
    vlbe_real A, B, g, z;
    A = VLBE_R(2.0) * (VLBE_R(3.0) * m[0] / Lmin + VLBE_R(2.0) * m[1]);
    B = VLBE_R(2.0) * (VLBE_R(3.0) * m[2] / Lmin + VLBE_R(2.0) * m[3]);
    g = VLBE_R(1.0) + A + B;
    z = VLBE_R(2.25) / Lmin;
    if (Lmax * Lmax > z) z = Lmax * Lmax; /* w N of a slope: L^2 (the load rows) */
    if (VLBE_R(1.5) > z) z = VLBE_R(1.5);
    /* the data's own factor too: with a tiny EA the strain (and with a
       huge c its damped part) could still overflow */
    return (VLBE_R(1.0) + c) * g * g * g * z <= VLBE_REAL_MAX / VLBE_R(1024.0) &&
           VLBE_R(8.0) * (EA * (VLBE_R(1.0) + c) * g * g * g * z + fq) <=
               VLBE_REAL_MAX / VLBE_R(1024.0);
}

/* Cable forces (axial + load; NO_BEND, both p fixed implied) of a chain of
   ne >= 1 elements of lengths L[ne] by an element loop: each element by
   vlbe_ale_force's Gauss route, or by the invariants when mode has
   VLBE_ALE_INV_AXIAL.  x, v (v may be NULL = 0): n = 4 (ne + 1)
   coordinates (INVARIANTS); Q (n) is overwritten, K, D (n *
   VLBE_ALE_INV_BW, band storage, either may be NULL) too.  Errors (nothing
   written): VLBE_EARG for ne < 1 or ne so large that n * VLBE_ALE_INV_BW
   overflows an int; VLBE_ENONFINITE for NaN/Inf in L, x, v, or data so
   large that the forces could overflow (vlbe__ale_cable_ok: far beyond
   any physical chain); VLBE_ELENGTH for L[e] out of range (<= 0, or
   L^-4 overflows, as vlbe_ale_force). */
VLBE_API vlbe_status vlbe_ale_inv_chain_force(const vlbe_ale_elem *el, unsigned mode, int ne,
                                              const vlbe_real *L, const vlbe_real *x,
                                              const vlbe_real *v, vlbe_real *VLBE_RESTRICT Q,
                                              vlbe_real *VLBE_RESTRICT K,
                                              vlbe_real *VLBE_RESTRICT D)
{
    vlbe_real qe[10], ve[10], Qe[10], Ke[100], De[100], Lmin, Lmax, fq, mx[4];
    vlbe_status st;
    int n, e, i, j;
    VLBE_ASSERT(el != NULL && L != NULL && x != NULL && Q != NULL);
    if (ne < 1 || ne > (INT_MAX - 4) / 4 / VLBE_ALE_INV_BW - 1) return VLBE_EARG;
    n = 4 * (ne + 1);
    mode |= el->flags | VLBE_ALE_NO_BEND | VLBE_ALE_FIX_P1 | VLBE_ALE_FIX_P2;
    if ((st = vlbe__ale_chain_in(ne, L, x, v, mx)) != VLBE_OK) return st;
    Lmin = Lmax = L[0];
    for (e = 1; e < ne; ++e) {
        if (L[e] < Lmin) Lmin = L[e];
        if (L[e] > Lmax) Lmax = L[e];
    }
    fq = (vlbe_fabs(el->mat.f[0]) + vlbe_fabs(el->mat.f[1])) * Lmax * (VLBE_R(1.0) + Lmax);
    if (!vlbe__ale_cable_ok(el->mat.EA, (mode & VLBE_ALE_NO_DAMP) ? VLBE_R(0.0) : el->mat.c_eps,
                            fq, Lmin, Lmax, mx))
        return VLBE_ENONFINITE;
    /* nothing fails below: a cable element with p fixed, finite data, L in
       range and forces bounded as above has no failing case */
    for (i = 0; i < n; ++i) Q[i] = VLBE_R(0.0);
    for (i = 0; K && i < n * VLBE_ALE_INV_BW; ++i) K[i] = VLBE_R(0.0);
    for (i = 0; D && i < n * VLBE_ALE_INV_BW; ++i) D[i] = VLBE_R(0.0);
    for (e = 0; e < ne; ++e) {
        const int o = 4 * e;
        for (i = 0; i < 4; ++i) {
            qe[i] = x[o + i];
            qe[5 + i] = x[o + 4 + i];
            ve[i] = v ? v[o + i] : VLBE_R(0.0);
            ve[5 + i] = v ? v[o + 4 + i] : VLBE_R(0.0);
        }
        qe[4] = ve[4] = ve[9] = VLBE_R(0.0);
        qe[9] = L[e];
        /* K and D come together; the Q-only route without; the outputs are
           bounded above, so the element's own final check is skipped */
        if (K || D)
            st = vlbe__ale_force(el, mode, qe, ve, Qe, Ke, De, 0, NULL);
        else
            st = vlbe__ale_force(el, mode, qe, ve, Qe, NULL, NULL, 0, NULL);
        if (st != VLBE_OK) return st; /* excluded by the checks above */
        for (i = 0; i < 8; ++i) {
            const int ri = i + (i >= 4), gi = o + i;
            Q[gi] += Qe[ri];
            for (j = 0; j < 8; ++j) {
                const int cj = j + (j >= 4), gj = o + j;
                if (K) K[VLBE__ALE_BAND(gi, gj)] += Ke[ri * 10 + cj];
                if (D) D[VLBE__ALE_BAND(gi, gj)] += De[ri * 10 + cj];
            }
        }
    }
    return VLBE_OK;
}

/* -- system invariants: translation-free slots ---------------------------
   The strain of element e reads its nodes only through the chord and the
   slopes: h1' = -h3' (the cubic Hermite basis), so in the xi-form r' =
   h3' d_e + L h2' r_e' + L h4' r_{e+1}' with d_e = r_{e+1} - r_e.  The
   system route's slots are these vectors: slot 2n the slope r_n' of node
   n, slot 2n + 1 the chord d_n of element n (2 ne + 1 slots); element e
   reads the slots 2e .. 2e + 2, which are the slots 1..3 (r1', r2, r2')
   of vlbe_ale_inv with r1 = 0, so its tables serve unchanged.  The Gram
   entries are then of the size of L^2, L and 1 whatever the chain's extent
   (positions measured from one point made them ~R^2 and their rounding
   relative to the strain grow like (R/L)^2).  Slot pairs sharing an
   element, 5 ne + 1 in all: node n's (2n, 2n) at 5n and element n's (2n,
   2n+1), (2n, 2n+2), (2n+1, 2n+1), (2n+1, 2n+2) at 5n + 1..4, so element
   e's six pairs are 5e .. 5e + 5 (the last is node e+1's).
   vlbe__ale_sys_pa: for local pair t = 0..5 of an element, the slot
   offsets from 2e at [t] and [6 + t] and the pair of vlbe_ale_inv at
   [12 + t].  The forces on the slots, Q~ = -EA S r~ (vlbe__ale_inv_out
   in slot space), map back to the nodal coordinates by the chain rule of
   d_n = r_{n+1} - r_n: Q = J^T Q~, K = J^T K~ J, D = J^T D~ J, J sparse
   with the entries +-1 of vlbe__ale_sys_tgt. */
VLBE_INLINE const signed char *vlbe__ale_sys_pa(void)
{
    static const signed char pa[18] = {0, 0, 0, 1, 1, 2, 0, 1, 2, 1, 2, 2, 2, 5, 6, 7, 8, 9};
    return pa;
}

/* Rows of the assembled quartic invariants T (pairs P in the order above,
   np = 5 ne + 1): row P holds the pairs R in [c0, c0 + w) that share an
   element with P, a contiguous range: node n's pair meets elements n-1, n
   (w = 11, 6 at an end node), a pair of element n meets its six (w = 6).
   start: offset of the row in the stored T, nnz = 35 ne + 1 in all. */
VLBE_INLINE void vlbe__ale_sys_row(int ne, int P, int *start, int *c0, int *w)
{
    const int n = P / 5, t = P % 5, wn = (n == 0 || n == ne) ? 6 : 11;
    const int blk = n == 0 ? 0 : 30 + 35 * (n - 1); /* rows of the nodes before n */
    if (t == 0) {
        *start = blk;
        *c0 = n > 0 ? 5 * (n - 1) : 0;
        *w = wn;
    } else {
        *start = blk + wn + 6 * (t - 1);
        *c0 = 5 * n;
        *w = 6;
    }
}

/* slot A of the nodal vector x (coordinates or their rates): the slope of
   node A/2 (A even) or the chord of element (A-1)/2 (A odd) */
VLBE_INLINE void vlbe__ale_sys_slot(const vlbe_real *x, int A, vlbe_real *r)
{
    const int o = 4 * (A / 2);
    if (A & 1) {
        r[0] = x[o + 4] - x[o];
        r[1] = x[o + 5] - x[o + 1];
    } else {
        r[0] = x[o + 2];
        r[1] = x[o + 3];
    }
}

/* The nodal coordinates (index of the x of the 2-vector) slot A acts on,
   with the sign of its derivative: the slope itself (+1), or for a chord
   node n (-1) and node n+1 (+1).  Returns their number. */
VLBE_INLINE int vlbe__ale_sys_tgt(int A, int *ix, vlbe_real *sg)
{
    const int o = 4 * (A / 2);
    if (!(A & 1)) {
        ix[0] = o + 2;
        sg[0] = VLBE_R(1.0);
        return 1;
    }
    ix[0] = o;
    sg[0] = VLBE_R(-1.0);
    ix[1] = o + 4;
    sg[1] = VLBE_R(1.0);
    return 2;
}

/* M (band) += s b at the 2x2 block of rows i, i+1 and columns j, j+1 (b
   2x2 row-major) */
VLBE_INLINE void vlbe__ale_sys_blk(vlbe_real *M, int i, int j, vlbe_real s, const vlbe_real *b)
{
    vlbe_real *m = M + VLBE__ALE_BAND(i, j);
    m[0] += s * b[0];
    m[1] += s * b[1];
    m[VLBE_ALE_INV_BW - 1] += s * b[2];
    m[VLBE_ALE_INV_BW] += s * b[3];
}

/* Length (in vlbe_real) of the buffer of vlbe_ale_inv_sys_init for ne
   elements, 88 ne + 16; 0 for ne < 1 or too large for int indexing. */
VLBE_API size_t vlbe_ale_inv_sys_work_len(int ne)
{
    /* T (35 ne + 1), B (np = 5 ne + 1), load vector (4 ne + 4), scratch:
       pair products (8 np), slot vectors (4 ne + 2) */
    if (ne < 1 || ne > (INT_MAX - 64) / 88) return 0;
    return (size_t)88 * (size_t)ne + 16;
}

/* System invariants of a chain of ne fixed-length cable elements of
   lengths L[ne] (material, load and the tables from el; damping unless
   (mode | el->flags) has NO_DAMP): the assembled I and B over the slot
   pairs (each element's table scaled to its L and added into the pair
   rows it touches) and the load vector, in work (work_len >=
   vlbe_ale_inv_sys_work_len(ne)), which must live as long as sys and is
   also the scratch of vlbe_ale_inv_sys_force (one evaluation at a time per
   buffer).  Errors (sys and work untouched): VLBE_EARG for ne < 1 or too
   large, VLBE_EWORK for a short buffer, VLBE_ENONFINITE for NaN/Inf in L
   or a load f L^2 that could overflow, VLBE_ELENGTH for L[e] <= 0 or
   L[e]^4 or L[e]^-4 (the scaled tables) out of range. */
VLBE_API vlbe_status vlbe_ale_inv_sys_init(vlbe_ale_inv_sys *sys, const vlbe_ale_elem *el,
                                           unsigned mode, int ne, const vlbe_real *L,
                                           vlbe_real *work, size_t work_len)
{
    const vlbe_ale_inv *iv;
    const signed char *pa = vlbe__ale_sys_pa();
    const size_t need = vlbe_ale_inv_sys_work_len(ne);
    vlbe_real *T, *B, *F, fm, Lmin, Lmax;
    vlbe_status st;
    int np, nnz, e, p, r, i;
    VLBE_ASSERT(sys != NULL && el != NULL && L != NULL && work != NULL);
    if (need == 0) return VLBE_EARG;
    if (work_len < need) return VLBE_EWORK;
    if (!vlbe_all_finite(L, ne)) return VLBE_ENONFINITE;
    fm = vlbe_fabs(el->mat.f[0]) + vlbe_fabs(el->mat.f[1]);
    Lmin = Lmax = L[0];
    for (e = 0; e < ne; ++e) {
        /* the tables carry L^-3 .. L^4 (entries <= 10), the load L^2 f */
        const vlbe_real L2 = L[e] * L[e];
        if ((st = vlbe__ale_len(VLBE_R(0.0), L[e])) != VLBE_OK) return st;
        if (!(L2 * L2 <= VLBE_REAL_MAX / VLBE_R(64.0))) return VLBE_ELENGTH;
        if (!(fm * (L[e] + L2) <= VLBE_REAL_MAX / VLBE_R(64.0))) return VLBE_ENONFINITE;
        if (L[e] < Lmin) Lmin = L[e];
        if (L[e] > Lmax) Lmax = L[e];
    }
    mode |= el->flags;
    iv = &el->inv;
    np = 5 * ne + 1;
    nnz = 35 * ne + 1;
    T = work;
    B = T + nnz;
    F = B + np;
    for (i = 0; i < nnz + np + 4 * ne + 4; ++i) work[i] = VLBE_R(0.0);
    /* sum of the element tables over their slots 1..3, each scaled to its
       L (the slopes are not): with m = 1 for a slope, 0 for the chord,
       I_abcd = L^(m_a+m_b+m_c+m_d-3) i_abcd, B_ab = L^(m_a+m_b-1) b_ab;
       load L^(m_a+1) n_a f on the nodal layout */
    for (e = 0; e < ne; ++e) {
        vlbe_real Lp[8];
        Lp[3] = VLBE_R(1.0);
        for (i = 4; i < 8; ++i) Lp[i] = Lp[i - 1] * L[e];
        for (i = 2; i >= 0; --i) Lp[i] = Lp[i + 1] / L[e]; /* Lp[k] = L^(k-3) */
        for (p = 0; p < 6; ++p) {
            int start, c0, w;
            const int P = 5 * e + p, mp = !(pa[p] & 1) + !(pa[6 + p] & 1);
            vlbe__ale_sys_row(ne, P, &start, &c0, &w);
            B[P] += Lp[2 + mp] * iv->b[pa[12 + p]];
            for (r = 0; r < 6; ++r)
                T[start + 5 * e + r - c0] += Lp[mp + !(pa[r] & 1) + !(pa[6 + r] & 1)] *
                                             iv->t[pa[12 + p] * VLBE_ALE_INV_NP + pa[12 + r]];
        }
        {
            vlbe_real Fe[10];
            for (i = 0; i < 10; ++i) Fe[i] = VLBE_R(0.0);
            vlbe__ale_inv_load(iv, L[e], el->mat.f, Fe);
            for (i = 0; i < 8; ++i) F[4 * e + i] += Fe[i + (i >= 4)];
        }
    }
    sys->ne = ne;
    sys->np = np;
    sys->EA = el->mat.EA;
    sys->c = (mode & VLBE_ALE_NO_DAMP) ? VLBE_R(0.0) : el->mat.c_eps;
    sys->T = T;
    sys->B = B;
    sys->H = F + 4 * ne + 4;
    sys->Lmin = Lmin;
    sys->Lmax = Lmax;
    return VLBE_OK;
}

/* vlbe_ale_inv_sys_force (the public wrapper below asserts the pointers):
   the chain's cable force Q (n = 4 (ne + 1), overwritten) and, when not
   NULL, K = dQ/dx and D = dQ/dv in band storage, from the system
   invariants: one pass over the 2 ne + 1 slots, one over the 5 ne + 1
   slot pairs for their products, one over the stored rows, whose slot
   forces and blocks go to the nodal rows and columns by the chain rule.
   v may be NULL (= 0; D is still c dQ/dv).  Same numbers as
   vlbe_ale_inv_chain_force to rounding.  Errors (nothing written):
   VLBE_ENONFINITE for NaN/Inf in x, v, or data so large that the forces
   could overflow (vlbe__ale_cable_ok). */
VLBE_INLINE vlbe_status vlbe__ale_sys_force(const vlbe_ale_inv_sys *sys, const vlbe_real *x,
                                              const vlbe_real *v, vlbe_real *Q, vlbe_real *K,
                                              vlbe_real *D)
{
    const int n = 4 * (sys->ne + 1), damp = sys->c != VLBE_R(0.0) && v != NULL;
    const int jac = K != NULL || D != NULL, ne = sys->ne, np = sys->np;
    const signed char *pa = vlbe__ale_sys_pa();
    const vlbe_real *F = sys->B + np, *T = sys->T;
    const vlbe_real EA = sys->EA, EAc = sys->EA * sys->c;
    vlbe_real *H = sys->H, *rs = sys->H + 8 * np, y[8] = {0, 0, 0, 0, 0, 0, 0, 0}, mx[4];
    vlbe_status st;
    int P, i, j;
    if ((st = vlbe__ale_chain_in(ne, NULL, x, damp ? v : NULL, mx)) != VLBE_OK) return st;
    /* the stored load is below REAL_MAX / 64 (vlbe_ale_inv_sys_init) */
    if (!vlbe__ale_cable_ok(EA, sys->c, VLBE_R(0.0), sys->Lmin, sys->Lmax, mx))
        return VLBE_ENONFINITE;
    for (i = 0; i < n; ++i) Q[i] = F[i];
    for (i = 0; K && i < n * VLBE_ALE_INV_BW; ++i) K[i] = VLBE_R(0.0);
    for (i = 0; D && i < n * VLBE_ALE_INV_BW; ++i) D[i] = VLBE_R(0.0);
    for (i = 0; i <= 2 * ne; ++i) vlbe__ale_sys_slot(x, i, rs + 2 * i);
    /* pair products (pair 5 nd + t: slots 2 nd + pa[t], 2 nd + pa[6 + t]) */
    for (P = 0; P < np; ++P) {
        const int A = 2 * (P / 5) + pa[P % 5], B = 2 * (P / 5) + pa[6 + P % 5];
        vlbe_real va[2], vb[2];
        if (damp) {
            vlbe__ale_sys_slot(v, A, va);
            vlbe__ale_sys_slot(v, B, vb);
        }
        vlbe__ale_inv_prod(rs + 2 * A, rs + 2 * B, damp ? va : NULL, damp ? vb : NULL, sys->c,
                           VLBE_R(1.0), jac, H + 8 * P);
    }
    /* the rows of T, stored one after another (vlbe__ale_sys_row); the
       pair's slot force and blocks (2x2, (A, B) = (B, A)) in Qt, Kt, Dt,
       then scattered to the nodal layout */
    for (P = 0; P < np; ++P) {
        const int A = 2 * (P / 5) + pa[P % 5], B = 2 * (P / 5) + pa[6 + P % 5];
        vlbe_real S, Qt[4] = {0, 0, 0, 0}, Kt[8] = {0, 0, 0, 0, 0, 0, 0, 0};
        vlbe_real Dt[8] = {0, 0, 0, 0, 0, 0, 0, 0}, sa[2], sb[2];
        int start, c0, w, ia[2], ib[2], na, nb, a, b;
        vlbe__ale_sys_row(ne, P, &start, &c0, &w);
        if (jac) {
            vlbe__ale_inv_row(T + start, w, H + 8 * c0, y);
            S = y[0];
        } else {
            S = VLBE_R(0.0);
            for (j = 0; j < w; ++j) S += T[start + j] * H[8 * (c0 + j)];
        }
        vlbe__ale_inv_out(VLBE_R(0.5) * (S - sys->B[P]), y, jac, EA, EAc, rs + 2 * A, rs + 2 * B,
                          A == B, Qt, Qt + 2, K ? Kt : NULL, K ? Kt + 4 : NULL, D ? Dt : NULL,
                          D ? Dt + 4 : NULL, 2);
        na = vlbe__ale_sys_tgt(A, ia, sa);
        nb = vlbe__ale_sys_tgt(B, ib, sb);
        for (a = 0; a < na; ++a) vlbe_v2_axpy(sa[a], Qt, Q + ia[a]);
        for (b = 0; A != B && b < nb; ++b) vlbe_v2_axpy(sb[b], Qt + 2, Q + ib[b]);
        for (a = 0; jac && a < na; ++a)
            for (b = 0; b < nb; ++b) {
                const vlbe_real s = sa[a] * sb[b];
                if (K) vlbe__ale_sys_blk(K, ia[a], ib[b], s, Kt);
                if (D) vlbe__ale_sys_blk(D, ia[a], ib[b], s, Dt);
                if (A == B) continue;
                if (K) vlbe__ale_sys_blk(K, ib[b], ia[a], s, Kt);
                if (D) vlbe__ale_sys_blk(D, ib[b], ia[a], s, Dt);
            }
    }
    return VLBE_OK;
}

VLBE_API vlbe_status vlbe_ale_inv_sys_force(const vlbe_ale_inv_sys *sys, const vlbe_real *x,
                                            const vlbe_real *v, vlbe_real *VLBE_RESTRICT Q,
                                            vlbe_real *VLBE_RESTRICT K,
                                            vlbe_real *VLBE_RESTRICT D)
{
    VLBE_ASSERT(sys != NULL && x != NULL && Q != NULL);
    return vlbe__ale_sys_force(sys, x, v, Q, K, D);
}

/* ===== 3D beam-shaft element with spin (VLBSE of [V]) ===================
   Node coordinates [r(3), r'(3), theta, p], 16 per element:
        q = [r1, r1', th1, p1,  r2, r2', th2, p2]      (eq. 16 of [V])
   with VLBE_ALE3_NO_SPIN the spin angle is not a coordinate (the 3D ALE
   cable/beam, 14 per element: [r1, r1', p1, r2, r2', p2]).  r(p) is the
   cubic Hermite interpolation of the positions and slopes (eqs. 4-5),
   theta(p) the linear one of the spin angles (eqs. 6-7), both in the ALE
   form of vlbe.h (p1, p2 free or fixed per node, FIX_P1/FIX_P2 as for the
   planar element).  Equations of motion, sign convention of integrators.h:
        M(q) q'' = Q(q, q'),  Q = Q_f + Q_F + Q_T - Q_p - Q_s   (eq. 48)
   M (eq. 28): int S^T diag(rhoA I3, rhoI) S dp, S = [S_e | dS_e/dp_k q_e]
   (eq. 15); Q_p the transport inertia int S^T diag(.) eta_p dp (eqs. 17,
   29); Q_s = Q_se + Q_sk + Q_sphi (eqs. 31-40) with
        eps = (r'.r' - 1)/2                  axial (Green) strain, eq. 21
        k   = r' x r'' / |r'|^3              curvature vector, |k| = kappa of eq. 22
        phi = theta'                         twist, eq. 23
   stresses EA (eps + c_eps eps'), EJ (k + c_kap k'), GI (phi + c_phi
   phi') (rates at fixed material p: the Kelvin-Voigt parts), Q_f = int S_t^T
   f dp for a constant load f per unit material length (eq. 44), point
   force and torque at a material point (eqs. 45-46,
   vlbe_ale3_point_force / _point_torque).
   Curvature.  The paper's kappa = |r' x r''| / |r'|^3 has no derivative at
   kappa = 0 (a straight beam, the common case) and its Kelvin-Voigt rate is
   undefined there.  vlbe uses the curvature VECTOR k: its energy EJ |k|^2/2
   is the paper's EJ kappa^2/2 (so the elastic force is the same), it is a
   polynomial in r', r'' times |r'|^-3 (smooth wherever the slope does not
   vanish), its rate k' is defined everywhere, and for motion in a plane it
   is the planar element's signed curvature times the plane's normal: in
   plane, with theta = 0 and no twist, the element is vlbe_ale_force's.
   Shared with the planar element, through the layout (vlbe__ale_lay):
   mass, mass Jacobian, kinetic energy and load potential (section "mass,
   mass Jacobian, kinetic energy: both elements"), the scaling identity
   (vlbe__ale_degree, _pcols), the basis tables.  Kept apart: the strain
   kernels.  The planar one works on the scalar signed curvature and 2-
   vectors; the 3D one on the curvature vector, the twist and 3-vectors,
   and costs twice as much on the same planar state (bench/bench_ale3.c,
   NO_SPIN Lagrangian against vlbe_ale_force's Lagrangian: 2.0 for Q, 2.0
   for Q+K+D), so the planar element, the hot path of most scenes, keeps
   its own.  A chain calls the 3D element directly (ch->el3: mass, mass
   Jacobian, force, energy, point), not through the element-type table
   (vlbe_ale_etype), whose split and merge serve segmentation, which 3D
   chains do not have: the table would add indirect calls and remove none
   of the chain's dimension and spin branches.
   Switches (VLBE_ALE_* as for the planar element, OR-ed like there):
     VLBE_ALE3_NO_SPIN   no spin angle: 14 coordinates, no rhoI, GI terms
     VLBE_ALE_NO_BEND    no Q_sk (string/cable)
     VLBE_ALE3_NO_TWIST  no Q_sphi (the spin angle keeps its inertia)
     VLBE_ALE_NO_DAMP    no Kelvin-Voigt terms
     VLBE_ALE_FIX_P1/2   material coordinate of a node fixed (Lagrangian);
                         its row and column stay zero
   K = dQ/dq and D = dQ/dq' as for the planar element: e-columns and the
   p'-columns directly, the p-columns by the scaling identity of NOTES
   (every term is homogeneous under p -> s p, slopes -> slopes / s, p' ->
   s p'; row degrees 1 + m_j for positions and slopes, 1 for theta, 0 for
   p; the axial part 4 and 2 lower, the twist part 2 lower).
   Errors: VLBE_ELENGTH (L = p2 - p1 out of range, as the planar
   element), VLBE_ENONFINITE (NaN/Inf in the input, or an output that
   would overflow), VLBE_ESINGULAR (|r'|^2 <= eps at a bending point),
   VLBE_EBOUND (point load outside [p1, p2]),
   VLBE_EARG for the planar element's VLBE_ALE_CONSERVATIVE and
   VLBE_ALE_INV_AXIAL (not available here: with free p the elastic
   p-forces are the paper's, without the end energy fluxes); no output is
   written on failure.  Stack (float, Cortex-M4F, gcc -O2,
   tests/m4/stack.awk; double about twice): vlbe_ale3_force with K and D
   4.5 kB (local Q, K, D of 16 x 16, which the failure contract needs),
   vlbe_ale3_mass_jac 2.0 kB (the 16 x 16 mass matrix), the other calls
   at most 1.5 kB. */

/* -- 3D element: definitions ------------------------------------------- */

VLBE_API vlbe_status vlbe_ale3_mat_circle(vlbe_ale3_mat *mat, vlbe_real rho, vlbe_real E,
                                          vlbe_real G, vlbe_real radius)
{
    const vlbe_real pi = VLBE_PI;
    vlbe_real A, J;
    VLBE_ASSERT(mat != NULL);
    if (!isfinite(rho) || !isfinite(E) || !isfinite(G) || !isfinite(radius))
        return VLBE_ENONFINITE;
    if (!(rho > VLBE_R(0.0)) || !(radius > VLBE_R(0.0)) || E < VLBE_R(0.0) || G < VLBE_R(0.0))
        return VLBE_EARG;
    A = pi * radius * radius;
    J = VLBE_R(0.25) * A * radius * radius;
    {
        /* a radius, density or modulus so large that a section constant
           overflows: VLBE_ENONFINITE, mat untouched */
        const vlbe_real m[5] = {rho * A, rho * VLBE_R(2.0) * J, E * A, E * J,
                                G * VLBE_R(2.0) * J};
        if (!vlbe_all_finite(m, 5)) return VLBE_ENONFINITE;
    }
    mat->rhoA = rho * A;
    mat->rhoI = rho * VLBE_R(2.0) * J; /* polar I_p = 2 J */
    mat->EA = E * A;
    mat->EJ = E * J;
    mat->GI = G * VLBE_R(2.0) * J;
    mat->c_eps = mat->c_kap = mat->c_phi = VLBE_R(0.0);
    mat->f[0] = mat->f[1] = mat->f[2] = VLBE_R(0.0);
    return VLBE_OK;
}

VLBE_API vlbe_status vlbe_ale3_elem_init(vlbe_ale3_elem *el, const vlbe_ale3_mat *mat,
                                         unsigned flags, int nm, int ns)
{
    vlbe_status st;
    VLBE_ASSERT(el != NULL && mat != NULL);
    {
        const vlbe_real m[8] = {mat->rhoA, mat->rhoI, mat->EA,    mat->EJ,
                                mat->GI,   mat->c_eps, mat->c_kap, mat->c_phi};
        if (!vlbe_all_finite(m, 8) || !vlbe_all_finite(mat->f, 3)) return VLBE_ENONFINITE;
    }
    if (!(mat->rhoA > VLBE_R(0.0)) || mat->rhoI < VLBE_R(0.0) || mat->EA < VLBE_R(0.0) ||
        mat->EJ < VLBE_R(0.0) || mat->GI < VLBE_R(0.0) || mat->c_eps < VLBE_R(0.0) ||
        mat->c_kap < VLBE_R(0.0) || mat->c_phi < VLBE_R(0.0))
        return VLBE_EARG;
    if (!(flags & VLBE_ALE3_NO_SPIN) && !(mat->rhoI > VLBE_R(0.0)))
        return VLBE_EARG; /* a spin angle without inertia: M singular */
    if (nm < 0 || nm > VLBE_ALE_NGP_MAX || ns < 0 || ns > VLBE_ALE_NGP_MAX) return VLBE_EARG;
    if ((st = vlbe__ale_rule(&el->rm, nm, 4)) != VLBE_OK) return st;
    if ((st = vlbe__ale_rule(&el->rs, ns, 5)) != VLBE_OK) return st;
    el->bmax = vlbe__ale_rule_bmax(&el->rm);
    el->mat = *mat;
    el->flags = flags;
    return VLBE_OK;
}

VLBE_API int vlbe_ale3_nq(unsigned mode)
{
    return (mode & VLBE_ALE3_NO_SPIN) ? VLBE_ALE3_NQ - 2 : VLBE_ALE3_NQ;
}

VLBE_INLINE void vlbe__ale_layout(unsigned mode, vlbe__ale_lay *ly)
{
    const int spin = !(mode & VLBE_ALE3_NO_SPIN), ns = spin ? 8 : 7;
    ly->d = 3;
    ly->spin = spin;
    ly->bad = (mode & (VLBE_ALE_CONSERVATIVE | VLBE_ALE_INV_AXIAL)) != 0;
    ly->n = 2 * ns;
    ly->e[0] = 0;
    ly->e[1] = 3;
    ly->e[2] = ns;
    ly->e[3] = ns + 3;
    ly->th[0] = spin ? 6 : -1;
    ly->th[1] = spin ? ns + 6 : -1;
    ly->p[0] = ns - 1;
    ly->p[1] = 2 * ns - 1;
}

VLBE_INLINE vlbe_status vlbe__ale3_check(const vlbe__ale_lay *ly, const vlbe_real *q,
                                         const vlbe_real *qd)
{
    if (ly->bad) return VLBE_EARG;
    if (!vlbe_all_finite(q, ly->n)) return VLBE_ENONFINITE;
    if (qd && !vlbe_all_finite(qd, ly->n)) return VLBE_ENONFINITE;
    return vlbe__ale_len(q[ly->p[0]], q[ly->p[1]]);
}

/* [v]x applied: out = v x u, and the matrix rows of [v]x */
VLBE_INLINE void vlbe__ale3_skew(const vlbe_real *v, vlbe_real *S)
{
    S[0] = VLBE_R(0.0), S[1] = -v[2], S[2] = v[1];
    S[3] = v[2], S[4] = VLBE_R(0.0), S[5] = -v[0];
    S[6] = -v[1], S[7] = v[0], S[8] = VLBE_R(0.0);
}

/* Curvature-vector stress at one point.  a = r', b = r'', ad, bd their
   material rates (NULL: undamped), S = EJ, cS = c_kap EJ: sigma = S k +
   cS k'.  Adds to G (7: r', r'', phi) the gradient k_y^T sigma and, with
   A, Ad (7 x 7, row-major), d(k_y^T sigma)/dy at fixed rates and
   d/dy' = cS k_y^T k_y.  *kk = |k|^2.  VLBE_ESINGULAR for |r'|^2 <= eps. */
VLBE_INLINE vlbe_status vlbe__ale3_bend(const vlbe_real *a, const vlbe_real *b,
                                        const vlbe_real *ad, const vlbe_real *bd, vlbe_real S,
                                        vlbe_real cS, vlbe_real *G, vlbe_real *A, vlbe_real *Ad,
                                        vlbe_real *kk)
{
    const vlbe_real g = vlbe_v3_dot(a, a);
    vlbe_real h, h5, s[3], k[3], sig[3], tau, bs[3], sa[3], ky[18];
    int i, j, c;
    if (!(g > VLBE_EPS)) return VLBE_ESINGULAR;
    h5 = VLBE_R(1.0) / g;
    h = h5 * vlbe_sqrt(h5); /* g^-3/2 */
    h5 = h * h5;            /* g^-5/2 */
    vlbe_v3_cross(a, b, s);
    for (c = 0; c < 3; ++c) sig[c] = k[c] = s[c] * h;
    if (kk) *kk = vlbe_v3_dot(k, k);
    for (c = 0; c < 3; ++c) sig[c] *= S;
    {
        vlbe_real sd[3] = {0, 0, 0}, t[3], ga = VLBE_R(0.0), hd = VLBE_R(0.0);
        if (ad && bd && cS != VLBE_R(0.0)) {
            vlbe_v3_cross(ad, b, sd);
            vlbe_v3_cross(a, bd, t);
            for (c = 0; c < 3; ++c) sd[c] += t[c];
            ga = vlbe_v3_dot(a, ad);
            hd = -VLBE_R(3.0) * h5 * ga;
            for (c = 0; c < 3; ++c) sig[c] += cS * (sd[c] * h + s[c] * hd);
        }
        tau = vlbe_v3_dot(sig, s);
        vlbe_v3_cross(b, sig, bs);
        vlbe_v3_cross(sig, a, sa);
        for (c = 0; c < 3; ++c) {
            G[c] += h * bs[c] - VLBE_R(3.0) * h5 * tau * a[c];
            G[3 + c] += h * sa[c];
        }
        if (!A) return VLBE_OK;
        /* k_y = [k_a | k_b], k_a = -h [b]x - 3 h5 s a^T, k_b = h [a]x */
        {
            vlbe_real Sb[9], Sa[9];
            vlbe__ale3_skew(b, Sb);
            vlbe__ale3_skew(a, Sa);
            for (i = 0; i < 3; ++i)
                for (j = 0; j < 3; ++j) {
                    ky[i * 6 + j] = -h * Sb[i * 3 + j] - VLBE_R(3.0) * h5 * s[i] * a[j];
                    ky[i * 6 + 3 + j] = h * Sa[i * 3 + j];
                }
        }
        /* Hessian of sigma . k at fixed sigma:
           f_aa = -3 h5 (bs a^T + a bs^T) + 15 h5/g tau a a^T - 3 h5 tau I,
           f_ab = -h [sigma]x - 3 h5 a sa^T,  f_ba = f_ab^T,  f_bb = 0 */
        {
            vlbe_real Ss[9];
            const vlbe_real h7 = VLBE_R(15.0) * h5 / g * tau;
            vlbe__ale3_skew(sig, Ss);
            for (i = 0; i < 3; ++i)
                for (j = 0; j < 3; ++j) {
                    vlbe_real faa = -VLBE_R(3.0) * h5 * (bs[i] * a[j] + a[i] * bs[j]) +
                                    h7 * a[i] * a[j];
                    const vlbe_real fab = -h * Ss[i * 3 + j] - VLBE_R(3.0) * h5 * a[i] * sa[j];
                    if (i == j) faa -= VLBE_R(3.0) * h5 * tau;
                    A[i * 7 + j] += faa;
                    A[i * 7 + 3 + j] += fab;
                    A[(3 + j) * 7 + i] += fab;
                }
        }
        /* + k_y^T (S k_y + cS dk'/dy): dk'/da = -h [bd]x - 3 h5 sd a^T - hd [b]x
           + s (15 h5/g ga a^T - 3 h5 ad^T), dk'/db = h [ad]x + hd [a]x */
        {
            vlbe_real W[18];
            for (i = 0; i < 18; ++i) W[i] = S * ky[i];
            if (ad && bd && cS != VLBE_R(0.0)) {
                vlbe_real Sbd[9], Sad[9], Sb[9], Sa[9];
                const vlbe_real h7 = VLBE_R(15.0) * h5 / g * ga;
                vlbe__ale3_skew(bd, Sbd);
                vlbe__ale3_skew(ad, Sad);
                vlbe__ale3_skew(b, Sb);
                vlbe__ale3_skew(a, Sa);
                for (i = 0; i < 3; ++i)
                    for (j = 0; j < 3; ++j) {
                        W[i * 6 + j] += cS * (-h * Sbd[i * 3 + j] -
                                              VLBE_R(3.0) * h5 * sd[i] * a[j] -
                                              hd * Sb[i * 3 + j] + s[i] * (h7 * a[j] -
                                              VLBE_R(3.0) * h5 * ad[j]));
                        W[i * 6 + 3 + j] += cS * (h * Sad[i * 3 + j] + hd * Sa[i * 3 + j]);
                    }
            }
            for (i = 0; i < 6; ++i)
                for (j = 0; j < 6; ++j) {
                    vlbe_real t1 = VLBE_R(0.0), t2 = VLBE_R(0.0);
                    for (c = 0; c < 3; ++c) {
                        t1 += ky[c * 6 + i] * W[c * 6 + j];
                        t2 += ky[c * 6 + i] * ky[c * 6 + j];
                    }
                    A[i * 7 + j] += t1;
                    if (Ad) Ad[i * 7 + j] += cS * t2;
                }
        }
    }
    return VLBE_OK;
}

/* Axial, bending and twist terms at one strain point (eqs. 31-40 of [V]):
   Q -= w Z^T G with Z = dz/dq, z = (r', r'', phi) and the generalized
   stresses G of the strains eps, k, phi (eqs. 21-23: the axial part here,
   the bending part in vlbe__ale3_bend, the twist part here); with K: the
   e- and theta-columns of -w d(Z^T G)/dq into K, -w Z^T Ad Z into D (all
   columns) and the degree extras into dQ (the scaling identity, see the
   3D section's notes).  About 200 lines: one pass over the strain point,
   whose rows z, Y and stresses G, A, Ad every part of Q, K and D shares;
   split, they would be recomputed or handed through a dozen arguments.
   The update X -= w Z^T T is written twice on purpose, for K and for D:
   as one routine called for both, the 3D Q + K + D executes 3.5 % more
   instructions (callgrind, gcc 12 -O3, with spin, ALE: 145.4 M against
   140.3 M for 2000 calls), as one loop over the two passes it ran 4 %
   (ALE) to 11 % (Lagrangian) longer in bench/bench_ale3.c. */
VLBE_INLINE vlbe_status vlbe__ale3_strain_gp(const vlbe_ale3_elem *el, const vlbe__ale_lay *ly,
                                             const vlbe_ale_gp *gp, const vlbe_real *Lp, int pm,
                                             const vlbe_real *pd, int bend, int twist, int damp,
                                             const vlbe_real *q, const vlbe_real *qd,
                                             vlbe_real *Q, vlbe_real *K, vlbe_real *D,
                                             vlbe_real *dQ)
{
    const vlbe_ale3_mat *mt = &el->mat;
    const int n = ly->n, jac = K != NULL, nz = bend ? 6 : 3;
    const vlbe_real w = gp->w * Lp[5];
    vlbe__ale_lpt pt;
    vlbe_real y[7], Y[2][7], yd[7], G[7] = {0, 0, 0, 0, 0, 0, 0}, Gx[7] = {0, 0, 0, 0, 0, 0, 0};
    vlbe_real A[49], Ad[49], T[7][VLBE_ALE3_NQ], Nd[3][4], Hd[2];
    int i, j, k, c, rows[7], nr = 0;
    vlbe_status st;
    vlbe__ale_lpt_eval(gp, Lp, 1, bend ? 2 : 1, pm ? 3 : 1, 1, &pt);
    for (c = 0; c < 7; ++c) y[c] = yd[c] = Y[0][c] = Y[1][c] = VLBE_R(0.0);
    vlbe__ale_lsum(ly, 3, pt.N[1][0], q, y);
    if (bend) vlbe__ale_lsum(ly, 3, pt.N[2][0], q, y + 3);
    if (twist) y[6] = vlbe__ale_lsum_th(ly, pt.H[1][0], q);
    for (k = 0; k < 2; ++k)
        if (pm & (1 << k)) {
            vlbe__ale_lsum(ly, 3, pt.N[1][1 + k], q, Y[k]);
            if (bend) vlbe__ale_lsum(ly, 3, pt.N[2][1 + k], q, Y[k] + 3);
            if (twist) Y[k][6] = vlbe__ale_lsum_th(ly, pt.H[1][1 + k], q);
        }
    if (damp) {
        vlbe__ale_lsum(ly, 3, pt.N[1][0], qd, yd);
        if (bend) vlbe__ale_lsum(ly, 3, pt.N[2][0], qd, yd + 3);
        if (twist) yd[6] = vlbe__ale_lsum_th(ly, pt.H[1][0], qd);
        for (k = 0; k < 2; ++k)
            for (c = 0; c < 7; ++c) yd[c] += pd[k] * Y[k][c];
    }
    if (jac)
        for (i = 0; i < 49; ++i) A[i] = Ad[i] = VLBE_R(0.0);
    if (mt->EA != VLBE_R(0.0)) {
        const vlbe_real eps = VLBE_R(0.5) * (vlbe_v3_dot(y, y) - VLBE_R(1.0));
        const vlbe_real cE = damp ? mt->c_eps * mt->EA : VLBE_R(0.0);
        const vlbe_real sig = mt->EA * eps + cE * vlbe_v3_dot(y, yd);
        for (c = 0; c < 3; ++c) G[c] += sig * y[c];
        if (jac) {
            for (i = 0; i < 3; ++i) {
                for (j = 0; j < 3; ++j) {
                    A[i * 7 + j] += y[i] * (mt->EA * y[j] + cE * yd[j]);
                    Ad[i * 7 + j] += cE * y[i] * y[j];
                }
                A[i * 7 + i] += sig;
                Gx[i] += (VLBE_R(4.0) * sig + mt->EA) * y[i];
            }
        }
    }
    if (bend) {
        const vlbe_real cB = damp ? mt->c_kap * mt->EJ : VLBE_R(0.0);
        if ((st = vlbe__ale3_bend(y, y + 3, damp ? yd : NULL, damp ? yd + 3 : NULL, mt->EJ, cB, G,
                                jac ? A : NULL, jac ? Ad : NULL, NULL)) != VLBE_OK)
            return st;
    }
    if (twist) {
        const vlbe_real cT = damp ? mt->c_phi * mt->GI : VLBE_R(0.0);
        const vlbe_real sig = mt->GI * y[6] + cT * yd[6];
        G[6] += sig;
        if (jac) {
            A[48] += mt->GI;
            Ad[48] += cT;
            Gx[6] += VLBE_R(2.0) * sig;
        }
    }
    /* Q -= w Z^T G */
    for (j = 0; j < 4; ++j)
        for (c = 0; c < 3; ++c) {
            vlbe_real v = pt.N[1][0][j] * G[c];
            if (bend) v += pt.N[2][0][j] * G[3 + c];
            Q[ly->e[j] + c] -= w * v;
        }
    if (twist)
        for (j = 0; j < 2; ++j) Q[ly->th[j]] -= w * pt.H[1][0][j] * G[6];
    for (k = 0; k < 2; ++k)
        if (pm & (1 << k)) {
            vlbe_real v = VLBE_R(0.0);
            for (c = 0; c < nz; ++c) v += Y[k][c] * G[c];
            if (twist) v += Y[k][6] * G[6];
            Q[ly->p[k]] -= w * v;
        }
    if (!jac) return VLBE_OK;

    /* degree extras: dQ += w Z^T Gx */
    for (j = 0; j < 4; ++j)
        for (c = 0; c < 3; ++c) dQ[ly->e[j] + c] += w * pt.N[1][0][j] * Gx[c];
    if (twist)
        for (j = 0; j < 2; ++j) dQ[ly->th[j]] += w * pt.H[1][0][j] * Gx[6];
    for (k = 0; k < 2; ++k)
        if (pm & (1 << k)) dQ[ly->p[k]] += w * (vlbe_v3_dot(Y[k], Gx) + Y[k][6] * Gx[6]);

    /* the rows of z in use */
    for (c = 0; c < nz; ++c) rows[nr++] = c;
    if (twist) rows[nr++] = 6;
    /* rate basis: d(material rate of z)/de_j at fixed e' = sum_k p_k' dZ/dp_k */
    for (j = 0; j < 4; ++j) {
        Nd[1][j] = Nd[2][j] = VLBE_R(0.0);
        for (k = 0; k < 2; ++k)
            if (damp && (pm & (1 << k))) {
                Nd[1][j] += pd[k] * pt.N[1][1 + k][j];
                if (bend) Nd[2][j] += pd[k] * pt.N[2][1 + k][j];
            }
    }
    for (j = 0; j < 2; ++j) {
        Hd[j] = VLBE_R(0.0);
        for (k = 0; k < 2; ++k)
            if (damp && twist && (pm & (1 << k))) Hd[j] += pd[k] * pt.H[1][1 + k][j];
    }
    /* K: T = A Z_e + Ad Zd_e on the e- and theta-columns */
    for (i = 0; i < nr; ++i) {
        const vlbe_real *Ai = A + rows[i] * 7, *Adi = Ad + rows[i] * 7;
        vlbe_real *Ti = T[i];
        for (j = 0; j < 4; ++j)
            for (c = 0; c < 3; ++c) {
                vlbe_real v = Ai[c] * pt.N[1][0][j] + Adi[c] * Nd[1][j];
                if (bend) v += Ai[3 + c] * pt.N[2][0][j] + Adi[3 + c] * Nd[2][j];
                Ti[ly->e[j] + c] = v;
            }
        if (ly->spin)
            for (j = 0; j < 2; ++j)
                Ti[ly->th[j]] = twist ? Ai[6] * pt.H[1][0][j] + Adi[6] * Hd[j] : VLBE_R(0.0);
        Ti[ly->p[0]] = Ti[ly->p[1]] = VLBE_R(0.0);
    }
    /* K rows -= w Z^T T (the p-columns of T are zero: filled later) */
    for (j = 0; j < 4; ++j)
        for (c = 0; c < 3; ++c) {
            vlbe_real *Kr = K + (ly->e[j] + c) * n;
            const vlbe_real m1 = w * pt.N[1][0][j], m2 = bend ? w * pt.N[2][0][j] : VLBE_R(0.0);
            const vlbe_real *T1 = T[c], *T2 = T[bend ? 3 + c : c];
            for (i = 0; i < n; ++i) Kr[i] -= m1 * T1[i] + m2 * T2[i];
        }
    if (twist)
        for (j = 0; j < 2; ++j) {
            vlbe_real *Kr = K + ly->th[j] * n;
            const vlbe_real m = w * pt.H[1][0][j], *T6 = T[nr - 1];
            for (i = 0; i < n; ++i) Kr[i] -= m * T6[i];
        }
    for (k = 0; k < 2; ++k)
        if (pm & (1 << k)) {
            vlbe_real *Kr = K + ly->p[k] * n;
            for (c = 0; c < nr; ++c) {
                const vlbe_real m = w * Y[k][rows[c]], *Tc = T[c];
                for (i = 0; i < n; ++i) Kr[i] -= m * Tc[i];
            }
            /* mix: d(Y_k . G)/de at fixed G */
            for (j = 0; j < 4; ++j)
                for (c = 0; c < 3; ++c) {
                    vlbe_real v = pt.N[1][1 + k][j] * G[c];
                    if (bend) v += pt.N[2][1 + k][j] * G[3 + c];
                    Kr[ly->e[j] + c] -= w * v;
                }
            if (twist)
                for (j = 0; j < 2; ++j) Kr[ly->th[j]] -= w * pt.H[1][1 + k][j] * G[6];
        }
    if (!damp) return VLBE_OK;
    /* D -= w Z^T Ad Z: T = Ad Z on every column */
    for (i = 0; i < nr; ++i) {
        const vlbe_real *Adi = Ad + rows[i] * 7;
        vlbe_real *Ti = T[i];
        for (j = 0; j < 4; ++j)
            for (c = 0; c < 3; ++c) {
                vlbe_real v = Adi[c] * pt.N[1][0][j];
                if (bend) v += Adi[3 + c] * pt.N[2][0][j];
                Ti[ly->e[j] + c] = v;
            }
        if (ly->spin)
            for (j = 0; j < 2; ++j) Ti[ly->th[j]] = twist ? Adi[6] * pt.H[1][0][j] : VLBE_R(0.0);
        for (k = 0; k < 2; ++k) {
            vlbe_real v = VLBE_R(0.0);
            if (pm & (1 << k)) {
                for (c = 0; c < nz; ++c) v += Adi[c] * Y[k][c];
                if (twist) v += Adi[6] * Y[k][6];
            }
            Ti[ly->p[k]] = v;
        }
    }
    for (j = 0; j < 4; ++j)
        for (c = 0; c < 3; ++c) {
            vlbe_real *Dr = D + (ly->e[j] + c) * n;
            const vlbe_real m1 = w * pt.N[1][0][j], m2 = bend ? w * pt.N[2][0][j] : VLBE_R(0.0);
            const vlbe_real *T1 = T[c], *T2 = T[bend ? 3 + c : c];
            for (i = 0; i < n; ++i) Dr[i] -= m1 * T1[i] + m2 * T2[i];
        }
    if (twist)
        for (j = 0; j < 2; ++j) {
            vlbe_real *Dr = D + ly->th[j] * n;
            const vlbe_real m = w * pt.H[1][0][j], *T6 = T[nr - 1];
            for (i = 0; i < n; ++i) Dr[i] -= m * T6[i];
        }
    for (k = 0; k < 2; ++k)
        if (pm & (1 << k)) {
            vlbe_real *Dr = D + ly->p[k] * n;
            for (c = 0; c < nr; ++c) {
                const vlbe_real m = w * Y[k][rows[c]], *Tc = T[c];
                for (i = 0; i < n; ++i) Dr[i] -= m * Tc[i];
            }
        }
    return VLBE_OK;
}

/* Inertia-type field term at one mass point: Q += w G^T z for the position
   field (z = f - rhoA eta_p, eqs. 17, 29, 44) and the spin field (z =
   -rhoI eta_p); with K: e/theta-columns of K, and D (e', theta' and p'
   columns).  pt holds k = 0 with all partials when pm != 0. */
VLBE_INLINE void vlbe__ale3_inertia_pt(const vlbe_ale3_mat *mt, const vlbe_real *f,
                                       const vlbe__ale_lay *ly,
                                       const vlbe__ale_lpt *pt, int pm, const vlbe_real *pd,
                                       vlbe_real w, const vlbe_real *q, const vlbe_real *qd,
                                       vlbe_real *Q, vlbe_real *K, vlbe_real *D)
{
    static const int a2[2][2] = {{VLBE_DA_11, VLBE_DA_12}, {VLBE_DA_12, VLBE_DA_22}};
    const int n = ly->n;
    vlbe_real X[2][3], V[2][3], Xkl[3][3], z[3], c4[4], d4[4];
    vlbe_real Xt[2] = {0, 0}, Vt[2] = {0, 0}, Xtl[3] = {0, 0, 0}, zt = VLBE_R(0.0), c2[2], d2[2];
    int i, j, k, l, c;
    const int spin = ly->spin && mt->rhoI != VLBE_R(0.0) && pm;
    for (c = 0; c < 3; ++c) z[c] = f[c];
    if (pm) {
        for (k = 0; k < 2; ++k) {
            vlbe__ale_lsum(ly, 3, pt->N[0][1 + k], q, X[k]);
            vlbe__ale_lsum(ly, 3, pt->N[0][1 + k], qd, V[k]);
            if (spin) {
                Xt[k] = vlbe__ale_lsum_th(ly, pt->H[0][1 + k], q);
                Vt[k] = vlbe__ale_lsum_th(ly, pt->H[0][1 + k], qd);
            }
        }
        for (k = 0; k < 3; ++k) {
            vlbe__ale_lsum(ly, 3, pt->N[0][VLBE_DA_11 + k], q, Xkl[k]);
            if (spin) Xtl[k] = vlbe__ale_lsum_th(ly, pt->H[0][VLBE_DA_11 + k], q);
        }
        for (c = 0; c < 3; ++c)
            z[c] -= mt->rhoA * (VLBE_R(2.0) * (pd[0] * V[0][c] + pd[1] * V[1][c]) +
                                pd[0] * pd[0] * Xkl[0][c] +
                                VLBE_R(2.0) * pd[0] * pd[1] * Xkl[1][c] +
                                pd[1] * pd[1] * Xkl[2][c]);
        if (spin)
            zt = -mt->rhoI * (VLBE_R(2.0) * (pd[0] * Vt[0] + pd[1] * Vt[1]) +
                              pd[0] * pd[0] * Xtl[0] + VLBE_R(2.0) * pd[0] * pd[1] * Xtl[1] +
                              pd[1] * pd[1] * Xtl[2]);
    }
    for (j = 0; j < 4; ++j)
        for (c = 0; c < 3; ++c) Q[ly->e[j] + c] += w * pt->N[0][0][j] * z[c];
    if (spin)
        for (j = 0; j < 2; ++j) Q[ly->th[j]] += w * pt->H[0][0][j] * zt;
    for (k = 0; k < 2; ++k)
        if (pm & (1 << k)) Q[ly->p[k]] += w * (vlbe_v3_dot(X[k], z) + Xt[k] * zt);
    if (!K || !pm) return;
    /* dz/de_j = c_j I, dz/de'_j = d_j I (the same for theta with rhoI) */
    for (j = 0; j < 4; ++j) {
        c4[j] = -mt->rhoA * (pd[0] * pd[0] * pt->N[0][VLBE_DA_11][j] +
                             VLBE_R(2.0) * pd[0] * pd[1] * pt->N[0][VLBE_DA_12][j] +
                             pd[1] * pd[1] * pt->N[0][VLBE_DA_22][j]);
        d4[j] = -mt->rhoA * VLBE_R(2.0) * (pd[0] * pt->N[0][1][j] + pd[1] * pt->N[0][2][j]);
    }
    for (j = 0; j < 2; ++j) {
        c2[j] = d2[j] = VLBE_R(0.0);
        if (spin) {
            c2[j] = -mt->rhoI * (pd[0] * pd[0] * pt->H[0][VLBE_DA_11][j] +
                                 VLBE_R(2.0) * pd[0] * pd[1] * pt->H[0][VLBE_DA_12][j] +
                                 pd[1] * pd[1] * pt->H[0][VLBE_DA_22][j]);
            d2[j] = -mt->rhoI * VLBE_R(2.0) * (pd[0] * pt->H[0][1][j] + pd[1] * pt->H[0][2][j]);
        }
    }
    for (j = 0; j < 4; ++j)
        for (c = 0; c < 3; ++c) {
            const int cj = ly->e[j] + c;
            for (i = 0; i < 4; ++i) {
                const int r = ly->e[i] + c;
                K[r * n + cj] += w * pt->N[0][0][i] * c4[j];
                D[r * n + cj] += w * pt->N[0][0][i] * d4[j];
            }
            for (k = 0; k < 2; ++k)
                if (pm & (1 << k)) {
                    K[ly->p[k] * n + cj] += w * (pt->N[0][1 + k][j] * z[c] + c4[j] * X[k][c]);
                    D[ly->p[k] * n + cj] += w * d4[j] * X[k][c];
                }
        }
    if (spin)
        for (j = 0; j < 2; ++j) {
            const int cj = ly->th[j];
            for (i = 0; i < 2; ++i) {
                K[ly->th[i] * n + cj] += w * pt->H[0][0][i] * c2[j];
                D[ly->th[i] * n + cj] += w * pt->H[0][0][i] * d2[j];
            }
            for (k = 0; k < 2; ++k)
                if (pm & (1 << k)) {
                    K[ly->p[k] * n + cj] += w * (pt->H[0][1 + k][j] * zt + c2[j] * Xt[k]);
                    D[ly->p[k] * n + cj] += w * d2[j] * Xt[k];
                }
        }
    /* p'-columns: dz/dp_k' = -2 rho (V_k + sum_l p_l' X_kl) */
    for (k = 0; k < 2; ++k)
        if (pm & (1 << k)) {
            const int pk = ly->p[k];
            vlbe_real dz[3], dzt = VLBE_R(0.0);
            for (c = 0; c < 3; ++c)
                dz[c] = -VLBE_R(2.0) * mt->rhoA *
                        (V[k][c] + pd[0] * Xkl[a2[k][0] - VLBE_DA_11][c] +
                         pd[1] * Xkl[a2[k][1] - VLBE_DA_11][c]);
            if (spin)
                dzt = -VLBE_R(2.0) * mt->rhoI *
                      (Vt[k] + pd[0] * Xtl[a2[k][0] - VLBE_DA_11] +
                       pd[1] * Xtl[a2[k][1] - VLBE_DA_11]);
            for (j = 0; j < 4; ++j)
                for (c = 0; c < 3; ++c) D[(ly->e[j] + c) * n + pk] += w * pt->N[0][0][j] * dz[c];
            if (spin)
                for (j = 0; j < 2; ++j) D[ly->th[j] * n + pk] += w * pt->H[0][0][j] * dzt;
            for (l = 0; l < 2; ++l)
                if (pm & (1 << l)) D[ly->p[l] * n + pk] += w * (vlbe_v3_dot(X[l], dz) + Xt[l] * dzt);
        }
}

VLBE_INLINE vlbe_status vlbe__ale3_forces(const vlbe_ale3_elem *el, const vlbe__ale_lay *ly,
                                          unsigned mode, const vlbe_real *f,
                                          const vlbe_real *q, const vlbe_real *qd,
                                          vlbe_real *Q, vlbe_real *K, vlbe_real *D)
{
    const vlbe_ale3_mat *mt = &el->mat;
    const int pm = vlbe__ale_pmask(mode), n = ly->n;
    const int damp = !(mode & VLBE_ALE_NO_DAMP);
    const int bend = !(mode & VLBE_ALE_NO_BEND) && mt->EJ != VLBE_R(0.0);
    const int twist = ly->spin && !(mode & VLBE_ALE3_NO_TWIST) && mt->GI != VLBE_R(0.0);
    const vlbe_real L = q[ly->p[1]] - q[ly->p[0]];
    vlbe_real pd[2], Lp[6], dQ[VLBE_ALE3_NQ], dQx[VLBE_ALE3_NQ];
    vlbe_status st;
    int g, i;
    const int f0 = f[0] != VLBE_R(0.0) || f[1] != VLBE_R(0.0) || f[2] != VLBE_R(0.0);
    vlbe__ale_lpow(L, Lp);
    pd[0] = (pm & 1) ? qd[ly->p[0]] : VLBE_R(0.0);
    pd[1] = (pm & 2) ? qd[ly->p[1]] : VLBE_R(0.0);
    for (i = 0; i < n; ++i) dQx[i] = VLBE_R(0.0);
    if (pm || f0)
        for (g = 0; g < el->rm.n; ++g) {
            const vlbe_ale_gp *gp = &el->rm.g[g];
            vlbe__ale_lpt pt; /* per point: its storage is shared with the strain points' */
            vlbe__ale_lpt_eval(gp, Lp, 0, 0, pm ? VLBE_DA_N : 1, 1, &pt);
            vlbe__ale3_inertia_pt(mt, f, ly, &pt, pm, pd, gp->w * L, q, qd, Q, K, D);
        }
    if (mt->EA != VLBE_R(0.0) || bend || twist)
        for (g = 0; g < el->rs.n; ++g)
            if ((st = vlbe__ale3_strain_gp(el, ly, &el->rs.g[g], Lp, pm, pd, bend, twist, damp, q, qd,
                                         Q, K, D, dQx)) != VLBE_OK)
                return st;
    if (K && pm) {
        vlbe__ale_degree(ly, Q, dQ);
        for (i = 0; i < n; ++i) dQ[i] += dQx[i];
        vlbe__ale_pcols(ly, L, pm, dQ, pd, q, qd, K, D);
    }
    return VLBE_OK;
}

/* vlbe_ale3_force with the distributed load f (NULL: el->mat.f; a chain's
   scaled copy) */
VLBE_INLINE vlbe_status vlbe__ale3_force(const vlbe_ale3_elem *el, unsigned mode,
                                         const vlbe_real *q, const vlbe_real *qd, vlbe_real *Q,
                                         vlbe_real *K, vlbe_real *D, const vlbe_real *f)
{
    vlbe_real Qt[VLBE_ALE3_NQ], Kt[VLBE_ALE3_NQ * VLBE_ALE3_NQ], Dt[VLBE_ALE3_NQ * VLBE_ALE3_NQ];
    vlbe_real *Kp = NULL, *Dp = NULL; /* the local K, D when wanted */
    vlbe__ale_lay ly;
    const int jac = K != NULL || D != NULL;
    vlbe_status st;
    int i, nn;
    VLBE_ASSERT(el != NULL && q != NULL && qd != NULL && Q != NULL);
    mode |= el->flags;
    vlbe__ale_layout(mode, &ly);
    if ((st = vlbe__ale3_check(&ly, q, qd)) != VLBE_OK) return st;
    nn = ly.n * ly.n;
    for (i = 0; i < ly.n; ++i) Qt[i] = VLBE_R(0.0);
    if (jac) {
        for (i = 0; i < nn; ++i) Kt[i] = Dt[i] = VLBE_R(0.0);
        Kp = Kt;
        Dp = Dt;
    }
    if ((st = vlbe__ale3_forces(el, &ly, mode, f ? f : el->mat.f, q, qd, Qt, Kp, Dp)) != VLBE_OK)
        return st;
    if (!vlbe_all_finite(Qt, ly.n) || (K && !vlbe_all_finite(Kt, nn)) ||
        (D && !vlbe_all_finite(Dt, nn)))
        return VLBE_ENONFINITE; /* overflow from finite input: nothing written */
    for (i = 0; i < ly.n; ++i) Q[i] = Qt[i];
    if (K)
        for (i = 0; i < nn; ++i) K[i] = Kt[i];
    if (D)
        for (i = 0; i < nn; ++i) D[i] = Dt[i];
    return VLBE_OK;
}

VLBE_API vlbe_status vlbe_ale3_force(const vlbe_ale3_elem *el, unsigned mode, const vlbe_real *q,
                                     const vlbe_real *qd, vlbe_real *VLBE_RESTRICT Q,
                                     vlbe_real *VLBE_RESTRICT K, vlbe_real *VLBE_RESTRICT D)
{
    return vlbe__ale3_force(el, mode, q, qd, Q, K, D, NULL);
}

/* The 3D element's layout, density, mass rule and bound, and the check
   of q and u (a rate or an acceleration; NULL: none) */
VLBE_INLINE vlbe_status vlbe__ale3_setup(const vlbe_ale3_elem *el, unsigned mode,
                                         const vlbe_real *q, const vlbe_real *u, vlbe__ale_lay *ly,
                                         vlbe__ale_inertia *in)
{
    vlbe__ale_layout(mode, ly);
    in->rm = &el->rm;
    in->rhoA = el->mat.rhoA;
    in->rhoI = el->mat.rhoI;
    in->bmax = el->bmax;
    return vlbe__ale3_check(ly, q, u);
}

/* M(q) (eq. 28), through vlbe__ale_mass */
VLBE_API vlbe_status vlbe_ale3_mass(const vlbe_ale3_elem *el, unsigned mode, const vlbe_real *q,
                                    vlbe_real *VLBE_RESTRICT M)
{
    vlbe__ale_lay ly;
    vlbe__ale_inertia in;
    vlbe_status st;
    VLBE_ASSERT(el != NULL && q != NULL && M != NULL);
    mode |= el->flags;
    if ((st = vlbe__ale3_setup(el, mode, q, NULL, &ly, &in)) != VLBE_OK) return st;
    return vlbe__ale_mass(&ly, 3, &in, vlbe__ale_pmask(mode), q, M);
}

VLBE_API vlbe_status vlbe_ale3_mass_jac(const vlbe_ale3_elem *el, unsigned mode,
                                        const vlbe_real *q, const vlbe_real *a,
                                        vlbe_real *VLBE_RESTRICT Mq)
{
    vlbe__ale_lay ly;
    vlbe__ale_inertia in;
    vlbe_status st;
    VLBE_ASSERT(el != NULL && q != NULL && a != NULL && Mq != NULL);
    mode |= el->flags;
    if ((st = vlbe__ale3_setup(el, mode, q, a, &ly, &in)) != VLBE_OK) return st;
    return vlbe__ale_mass_jac(&ly, 3, &in, vlbe__ale_pmask(mode), q, a, Mq);
}

/* E = {T, U, V}: kinetic energy and load potential by vlbe__ale_kin_pot,
   strain energy int (EA eps^2 + EJ |k|^2 + GI phi^2)/2 dp. */
VLBE_API vlbe_status vlbe_ale3_energy(const vlbe_ale3_elem *el, unsigned mode, const vlbe_real *q,
                                      const vlbe_real *qd, vlbe_real *VLBE_RESTRICT E)
{
    const vlbe_ale3_mat *mt = &el->mat;
    vlbe_real Lp[6], L, T, U = VLBE_R(0.0), V;
    vlbe__ale_lay ly;
    vlbe__ale_inertia in;
    vlbe__ale_lpt pt;
    vlbe_status st;
    int g, bend, twist;
    VLBE_ASSERT(el != NULL && q != NULL && qd != NULL && E != NULL);
    mode |= el->flags;
    if ((st = vlbe__ale3_setup(el, mode, q, qd, &ly, &in)) != VLBE_OK) return st;
    vlbe__ale_kin_pot(&ly, 3, &in, mt->f, vlbe__ale_pmask(mode), q, qd, &T, &V);
    bend = !(mode & VLBE_ALE_NO_BEND) && mt->EJ != VLBE_R(0.0);
    twist = ly.spin && !(mode & VLBE_ALE3_NO_TWIST) && mt->GI != VLBE_R(0.0);
    L = q[ly.p[1]] - q[ly.p[0]];
    vlbe__ale_lpow(L, Lp);
    for (g = 0; g < el->rs.n; ++g) {
        const vlbe_real w = el->rs.g[g].w * L;
        vlbe_real a[3], b[3], G[7], kk = VLBE_R(0.0), eps, phi;
        vlbe__ale_lpt_eval(&el->rs.g[g], Lp, 1, bend ? 2 : 1, 1, 1, &pt);
        vlbe__ale_lsum(&ly, 3, pt.N[1][0], q, a);
        eps = VLBE_R(0.5) * (vlbe_v3_dot(a, a) - VLBE_R(1.0));
        U += w * VLBE_R(0.5) * mt->EA * eps * eps;
        if (bend) {
            vlbe__ale_lsum(&ly, 3, pt.N[2][0], q, b);
            if ((st = vlbe__ale3_bend(a, b, NULL, NULL, VLBE_R(0.0), VLBE_R(0.0), G, NULL, NULL,
                                    &kk)) != VLBE_OK)
                return st;
            U += w * VLBE_R(0.5) * mt->EJ * kk;
        }
        if (twist) {
            phi = vlbe__ale_lsum_th(&ly, pt.H[1][0], q);
            U += w * VLBE_R(0.5) * mt->GI * phi * phi;
        }
    }
    if (!isfinite(T) || !isfinite(U) || !isfinite(V)) return VLBE_ENONFINITE;
    E[0] = T;
    E[1] = U;
    E[2] = V;
    return VLBE_OK;
}

/* r(p), r'(p) and theta(p) of one element (each may be NULL; theta is 0
   without spin); p may lie outside [p1, p2] (extrapolated). */
VLBE_API vlbe_status vlbe_ale3_point(unsigned mode, const vlbe_real *q, vlbe_real p,
                                     vlbe_real *VLBE_RESTRICT r, vlbe_real *VLBE_RESTRICT rp,
                                     vlbe_real *VLBE_RESTRICT th)
{
    vlbe__ale_lay ly;
    vlbe_herm_ale b;
    vlbe_real x[7];
    vlbe_status st;
    int i;
    VLBE_ASSERT(q != NULL);
    vlbe__ale_layout(mode, &ly);
    if ((st = vlbe__ale3_check(&ly, q, NULL)) != VLBE_OK) return st;
    if (!isfinite(p)) return VLBE_ENONFINITE;
    vlbe_herm_ale_eval(p, q[ly.p[0]], q[ly.p[1]], 1, 0, &b);
    vlbe__ale_lsum(&ly, 3, b.h[0][0], q, x);
    vlbe__ale_lsum(&ly, 3, b.h[1][0], q, x + 3);
    x[6] = vlbe__ale_lsum_th(&ly, b.l[0][0], q);
    if (!vlbe_all_finite(x, 7)) return VLBE_ENONFINITE;
    for (i = 0; i < 3; ++i) {
        if (r) r[i] = x[i];
        if (rp) rp[i] = x[3 + i];
    }
    if (th) *th = x[6];
    return VLBE_OK;
}

/* Axial strain, curvature kappa = |k| (eq. 22) and twist (eq. 23) at p
   (each output may be NULL; kappa needs |r'|^2 > eps). */
VLBE_API vlbe_status vlbe_ale3_strain(unsigned mode, const vlbe_real *q, vlbe_real p,
                                      vlbe_real *VLBE_RESTRICT eps, vlbe_real *VLBE_RESTRICT kap,
                                      vlbe_real *VLBE_RESTRICT phi)
{
    vlbe__ale_lay ly;
    vlbe_herm_ale b;
    vlbe_real a[3], r2[3], G[7] = {0, 0, 0, 0, 0, 0, 0}, kk = VLBE_R(0.0), x[3];
    vlbe_status st;
    VLBE_ASSERT(q != NULL);
    vlbe__ale_layout(mode, &ly);
    if ((st = vlbe__ale3_check(&ly, q, NULL)) != VLBE_OK) return st;
    if (!isfinite(p)) return VLBE_ENONFINITE;
    vlbe_herm_ale_eval(p, q[ly.p[0]], q[ly.p[1]], 2, 0, &b);
    vlbe__ale_lsum(&ly, 3, b.h[1][0], q, a);
    vlbe__ale_lsum(&ly, 3, b.h[2][0], q, r2);
    if (kap &&
        (st = vlbe__ale3_bend(a, r2, NULL, NULL, VLBE_R(0.0), VLBE_R(0.0), G, NULL, NULL, &kk)) !=
            VLBE_OK)
        return st;
    x[0] = VLBE_R(0.5) * (vlbe_v3_dot(a, a) - VLBE_R(1.0));
    x[1] = vlbe_sqrt(kk);
    x[2] = vlbe__ale_lsum_th(&ly, b.l[1][0], q);
    if ((eps && !isfinite(x[0])) || (kap && !isfinite(x[1])) || (phi && !isfinite(x[2])))
        return VLBE_ENONFINITE;
    if (eps) *eps = x[0];
    if (kap) *kap = x[1];
    if (phi) *phi = x[2];
    return VLBE_OK;
}

/* A point load at material point pf in [p1, p2] on the position field
   (F, 3 components: eq. 45) or on the spin field (torque T about the
   axis: eq. 46): Q += S(pf)^T F, K += d/dq (Kr, Kc may be NULL), on the
   caller's copies (vlbe__ale3_point_load).  K changes in the p-rows and
   p-columns only: Kr[k * VLBE_ALE3_NQ + i] is K(p_k, i), Kc[k *
   VLBE_ALE3_NQ + i] is K(i, p_k) for the rows i that are not p's. */
VLBE_INLINE vlbe_status vlbe__ale3_point_add(unsigned mode, const vlbe_real *q, vlbe_real pf,
                                             const vlbe_real *F, vlbe_real T, int torque,
                                             vlbe_real *Q, vlbe_real *Kr, vlbe_real *Kc)
{
    static const int dd[2][2] = {{VLBE_DA_11, VLBE_DA_12}, {VLBE_DA_12, VLBE_DA_22}};
    vlbe__ale_lay ly;
    vlbe_herm_ale b;
    vlbe_real x[3];
    vlbe_status st;
    int j, k, l, c;
    vlbe__ale_layout(mode, &ly);
    if ((st = vlbe__ale3_check(&ly, q, NULL)) != VLBE_OK) return st;
    if (!isfinite(pf) || (torque ? !isfinite(T) : !vlbe_all_finite(F, 3))) return VLBE_ENONFINITE;
    if (torque && !ly.spin) return VLBE_EARG;
    if (pf < q[ly.p[0]] || pf > q[ly.p[1]]) return VLBE_EBOUND;
    vlbe_herm_ale_eval(pf, q[ly.p[0]], q[ly.p[1]], 0, 2, &b);
    if (torque) {
        for (j = 0; j < 2; ++j) Q[ly.th[j]] += b.l[0][0][j] * T;
        for (k = 0; k < 2; ++k) Q[ly.p[k]] += vlbe__ale_lsum_th(&ly, b.l[0][1 + k], q) * T;
    } else {
        for (j = 0; j < 4; ++j)
            for (c = 0; c < 3; ++c) Q[ly.e[j] + c] += b.h[0][0][j] * F[c];
        for (k = 0; k < 2; ++k) {
            vlbe__ale_lsum(&ly, 3, b.h[0][1 + k], q, x);
            Q[ly.p[k]] += vlbe_v3_dot(x, F);
        }
    }
    if (!Kr) return VLBE_OK;
    for (k = 0; k < 2; ++k) {
        vlbe_real *const row = Kr + k * VLBE_ALE3_NQ, *const col = Kc + k * VLBE_ALE3_NQ;
        if (torque)
            for (j = 0; j < 2; ++j) {
                const vlbe_real h = b.l[0][1 + k][j] * T;
                col[ly.th[j]] += h;
                row[ly.th[j]] += h;
            }
        else
            for (j = 0; j < 4; ++j)
                for (c = 0; c < 3; ++c) {
                    const vlbe_real h = b.h[0][1 + k][j] * F[c];
                    col[ly.e[j] + c] += h;
                    row[ly.e[j] + c] += h;
                }
        for (l = 0; l < 2; ++l) {
            if (torque)
                row[ly.p[l]] += vlbe__ale_lsum_th(&ly, b.l[0][dd[k][l]], q) * T;
            else {
                vlbe__ale_lsum(&ly, 3, b.h[0][dd[k][l]], q, x);
                row[ly.p[l]] += vlbe_v3_dot(x, F);
            }
        }
    }
    return VLBE_OK;
}

/* vlbe__ale3_point_add on copies of Q and of the p-rows and p-columns of K
   (the rest of K does not change), committed when Q and all of K are
   finite.  An entry that is not finite stays so when a number is added,
   so the check of the caller's K and of the copies is that of the whole
   updated K. */
VLBE_INLINE vlbe_status vlbe__ale3_point_load(unsigned mode, const vlbe_real *q, vlbe_real pf,
                                              const vlbe_real *F, vlbe_real T, int torque,
                                              vlbe_real *Q, vlbe_real *K)
{
    vlbe_real Qt[VLBE_ALE3_NQ], Kr[2 * VLBE_ALE3_NQ], Kc[2 * VLBE_ALE3_NQ];
    vlbe__ale_lay ly;
    vlbe_status st;
    const int n = vlbe_ale3_nq(mode);
    int i, k;
    vlbe__ale_layout(mode, &ly);
    for (i = 0; i < n; ++i) Qt[i] = Q[i];
    for (k = 0; K && k < 2; ++k)
        for (i = 0; i < n; ++i) {
            Kr[k * VLBE_ALE3_NQ + i] = K[ly.p[k] * n + i];
            Kc[k * VLBE_ALE3_NQ + i] = K[i * n + ly.p[k]];
        }
    if ((st = vlbe__ale3_point_add(mode, q, pf, F, T, torque, Qt, K ? Kr : NULL,
                                 K ? Kc : NULL)) != VLBE_OK)
        return st;
    if (!vlbe_all_finite(Qt, n) ||
        (K && (!vlbe_all_finite(K, n * n) || !vlbe_all_finite(Kr, n) ||
               !vlbe_all_finite(Kr + VLBE_ALE3_NQ, n) || !vlbe_all_finite(Kc, n) ||
               !vlbe_all_finite(Kc + VLBE_ALE3_NQ, n))))
        return VLBE_ENONFINITE;
    for (i = 0; i < n; ++i) Q[i] = Qt[i];
    for (k = 0; K && k < 2; ++k)
        for (i = 0; i < n; ++i) {
            K[ly.p[k] * n + i] = Kr[k * VLBE_ALE3_NQ + i];
            if (i != ly.p[0] && i != ly.p[1]) K[i * n + ly.p[k]] = Kc[k * VLBE_ALE3_NQ + i];
        }
    return VLBE_OK;
}

/* A constant global force F (3) at material point pf (eq. 45).  Every row
   and column of the layout is written, whatever the FIX_P flags. */
VLBE_API vlbe_status vlbe_ale3_point_force(unsigned mode, const vlbe_real *q, vlbe_real pf,
                                           const vlbe_real *F, vlbe_real *VLBE_RESTRICT Q,
                                           vlbe_real *VLBE_RESTRICT K)
{
    VLBE_ASSERT(q != NULL && F != NULL && Q != NULL);
    return vlbe__ale3_point_load(mode, q, pf, F, VLBE_R(0.0), 0, Q, K);
}

/* A torque T about the beam axis at material point pf, acting on the spin
   angle (eq. 46); VLBE_EARG without spin. */
VLBE_API vlbe_status vlbe_ale3_point_torque(unsigned mode, const vlbe_real *q, vlbe_real pf,
                                            vlbe_real T, vlbe_real *VLBE_RESTRICT Q,
                                            vlbe_real *VLBE_RESTRICT K)
{
    VLBE_ASSERT(q != NULL && Q != NULL);
    return vlbe__ale3_point_load(mode, q, pf, NULL, T, 1, Q, K);
}

/* ===== chains of elements ================================================ */
/* -- implementation ----------------------------------------------------- */
VLBE_INLINE vlbe_status vlbe__ale_chain_init(vlbe_ale_chain *ch, const vlbe_ale_elem *el,
                                               const vlbe_ale3_elem *el3, vlbe_ale_node *nodes,
                                               int nn, int nn_cap, vlbe_ale_con *cons,
                                               int ncon_cap)
{
    VLBE_ASSERT(ch != NULL && (el != NULL) != (el3 != NULL) && nodes != NULL);
    if (nn < 2 || nn_cap < nn || ncon_cap < 0 || (ncon_cap > 0 && cons == NULL)) return VLBE_EARG;
    ch->el = el;
    ch->el3 = el3;
    ch->et = NULL;
    ch->els = NULL;
    ch->d = el3 ? 3 : 2;
    ch->spin = el3 && !(el3->flags & VLBE_ALE3_NO_SPIN);
    ch->mode = 0;
    ch->nn = nn;
    ch->nn_cap = nn_cap;
    ch->node = nodes;
    ch->ncon = 0;
    ch->ncon_cap = ncon_cap;
    ch->con = cons;
    ch->n = ch->m = 0;
    ch->g[0] = ch->g[1] = ch->g[2] = VLBE_R(0.0);
    ch->Lmin = VLBE_R(0.0);
    ch->pfun = NULL;
    ch->afun = NULL;
    ch->user = NULL;
    ch->err = VLBE_OK;
    ch->err_elem = -1;
    ch->order = NULL;
    ch->order_cap = 0;
    ch->kl = ch->ku = 0;
    ch->load_factor = VLBE_R(1.0);
    ch->loads = NULL;
    ch->nloads = 0;
    ch->err_load = -1;
    return VLBE_OK;
}

VLBE_API vlbe_status vlbe_ale_chain_init(vlbe_ale_chain *ch, const vlbe_ale_elem *el,
                                         vlbe_ale_node *nodes, int nn, int nn_cap,
                                         vlbe_ale_con *cons, int ncon_cap)
{
    return vlbe__ale_chain_init(ch, el, NULL, nodes, nn, nn_cap, cons, ncon_cap);
}

/* A chain of 3D beam-shaft elements (the node layout follows the spin
   switch of the element's flags and ch->mode at vlbe_ale_chain_layout). */
VLBE_API vlbe_status vlbe_ale_chain_init3(vlbe_ale_chain *ch, const vlbe_ale3_elem *el3,
                                          vlbe_ale_node *nodes, int nn, int nn_cap,
                                          vlbe_ale_con *cons, int ncon_cap)
{
    return vlbe__ale_chain_init(ch, NULL, el3, nodes, nn, nn_cap, cons, ncon_cap);
}

/* Gives a planar chain per-element types (see vlbe_ale_etype; rancf.h's
   vlbe_rancf_chain_init calls it): els holds one object per element, at
   least nn_cap - 1 of them.  A 3D chain: VLBE_EARG. */
VLBE_API vlbe_status vlbe_ale_chain_types(vlbe_ale_chain *ch, const vlbe_ale_etype *et, void *els)
{
    VLBE_ASSERT(ch != NULL && et != NULL && els != NULL);
    if (ch->el3) return VLBE_EARG;
    ch->et = et;
    ch->els = els;
    return VLBE_OK;
}

/* the element type of element e of a planar chain */
VLBE_INLINE const vlbe_ale_elem *vlbe__ale_el(const vlbe_ale_chain *ch, int e)
{
    return ch->et ? ch->et->elem(ch->els, e) : ch->el;
}

/* the basis of element e of a planar chain at p */
VLBE_INLINE void vlbe__ale_chain_basis(const vlbe_ale_chain *ch, int e, vlbe_real p,
                                         vlbe_real p1, vlbe_real p2, int kmax, int amax,
                                         vlbe_herm_ale *b)
{
    if (ch->et) ch->et->basis(ch->els, e, p, p1, p2, kmax, amax, b);
    else vlbe_herm_ale_eval(p, p1, p2, kmax, amax, b);
}

/* rows of a constraint in a chain of dimension d (-1: not a type; 0: not
   available in this dimension) */
VLBE_INLINE int vlbe__ale_con_rows(const vlbe_ale_chain *ch, const vlbe_ale_con *c)
{
    const int d = ch->el3 ? 3 : 2, planar = ch->el3 == NULL;
    switch (c->type) {
    case VLBE_ALE_CON_POS: {
        int k, r = 0;
        if (c->which == 0) return d;
        if (c->which < 0 || c->which >= (1 << d)) return -1;
        for (k = 0; k < d; ++k) r += (c->which >> k) & 1;
        return r;
    }
    case VLBE_ALE_CON_SLOPE: return d;
    case VLBE_ALE_CON_SLIDE_C: return planar ? 2 : 0;
    case VLBE_ALE_CON_SLOPE_DIR: return d - 1;
    case VLBE_ALE_CON_SLOPE_ROT: return planar ? 0 : 2;
    case VLBE_ALE_CON_SLIDE_D: case VLBE_ALE_CON_SLOPE_ANGLE: return planar ? 1 : 0;
    case VLBE_ALE_CON_P: return 1;
    case VLBE_ALE_CON_SPIN: return planar ? 0 : 1;
    case VLBE_ALE_CON_EQUAL_LEN: /* node checked first: node2 - node cannot overflow */
        return (c->node < 0 || c->node2 <= c->node) ? -1 : c->node2 - c->node - 1;
    default: return -1;
    }
}

/* u = x / |x| for a finite x of d components, scaled by its largest
   component first (no overflow or underflow of |x|^2); 0 when x is zero or
   not finite, 1 on success */
VLBE_INLINE int vlbe__ale_unit(int d, const vlbe_real *x, vlbe_real *u)
{
    vlbe_real m = VLBE_R(0.0), n2 = VLBE_R(0.0), n;
    int i;
    for (i = 0; i < d; ++i)
        if (vlbe_fabs(x[i]) > m) m = vlbe_fabs(x[i]);
    if (!(m > VLBE_R(0.0)) || !isfinite(m)) return 0;
    for (i = 0; i < d; ++i) {
        u[i] = x[i] / m;
        n2 += u[i] * u[i];
    }
    n = vlbe_sqrt(n2); /* in [1, sqrt(d)] */
    for (i = 0; i < d; ++i) u[i] /= n;
    return 1;
}

/* The orthonormal pair b = [b1, b2] across a 3D direction e (not zero):
   with u = e / |e| and c the first component of least |u_c| (|u_c| <=
   1/sqrt 3), b1 = (e_c - u_c u) / |e_c - u_c u| (the unit axis farthest
   from e, its part across e: |e_c - u_c u|^2 = 1 - u_c^2 >= 2/3, so no
   cancellation) and b2 = u x b1; [u, b1, b2] is right-handed.  Returns 0
   for a zero or non-finite e. */
VLBE_INLINE int vlbe__ale_perp(const vlbe_real *e, vlbe_real *b)
{
    vlbe_real u[3], w[3];
    int i, c = 0;
    if (!vlbe__ale_unit(3, e, u)) return 0;
    for (i = 1; i < 3; ++i)
        if (vlbe_fabs(u[i]) < vlbe_fabs(u[c])) c = i;
    for (i = 0; i < 3; ++i) w[i] = (i == c ? VLBE_R(1.0) : VLBE_R(0.0)) - u[c] * u[i];
    if (!vlbe__ale_unit(3, w, b)) return 0; /* cannot happen: |w|^2 >= 2/3 */
    vlbe_v3_cross(u, b, b + 3);
    return 1;
}

/* The checks of vlbe_ale_chain_add and _layout on one constraint: its
   type, rows and nodes (VLBE_EARG), its values finite (VLBE_ENONFINITE),
   the directions SLOPE_DIR and SLOPE_ROT read not zero (VLBE_EARG). */
VLBE_INLINE vlbe_status vlbe__ale_con_check(const vlbe_ale_chain *ch, const vlbe_ale_con *c)
{
    const int d = ch->el3 ? 3 : 2;
    vlbe_real u[3];
    if (vlbe__ale_con_rows(ch, c) < 1 || c->node < 0 || c->node >= ch->nn) return VLBE_EARG;
    if (c->type == VLBE_ALE_CON_EQUAL_LEN && c->node2 >= ch->nn) return VLBE_EARG;
    if (!vlbe_all_finite(c->r, 3) || !vlbe_all_finite(c->d, 3) || !vlbe_all_finite(c->axis, 3) ||
        !vlbe_all_finite(c->law, 3))
        return VLBE_ENONFINITE;
    if ((c->type == VLBE_ALE_CON_SLOPE_DIR || c->type == VLBE_ALE_CON_SLOPE_ROT) &&
        !vlbe__ale_unit(d, c->d, u))
        return VLBE_EARG;
    if (c->type == VLBE_ALE_CON_SLOPE_ROT && !vlbe__ale_unit(3, c->axis, u)) return VLBE_EARG;
    return VLBE_OK;
}

/* Appends constraint c (copied) after the checks of vlbe__ale_con_check;
   VLBE_EWORK when con[] is full.  On failure nothing changes. */
VLBE_API vlbe_status vlbe_ale_chain_add(vlbe_ale_chain *ch, const vlbe_ale_con *c)
{
    vlbe_status st;
    VLBE_ASSERT(ch != NULL && c != NULL);
    if (ch->ncon >= ch->ncon_cap) return VLBE_EWORK;
    if ((st = vlbe__ale_con_check(ch, c)) != VLBE_OK) return st;
    ch->con[ch->ncon++] = *c;
    return VLBE_OK;
}

/* index of the coordinate p of node i in q, -1 when p is not a coordinate */
VLBE_INLINE int vlbe__ale_pidx(const vlbe_ale_chain *ch, int i)
{
    const vlbe_ale_node *nd = &ch->node[i];
    return nd->pmode == VLBE_ALE_PFREE ? nd->ofs + ch->d * (2 + nd->slide) + ch->spin : -1;
}

/* index of the spin angle of node i (3D chains with spin) */
VLBE_INLINE int vlbe__ale_tidx(const vlbe_ale_chain *ch, int i)
{
    return ch->spin ? ch->node[i].ofs + 2 * ch->d : -1;
}

/* index of slope `which` (0 left, 1 right) of node i */
VLBE_INLINE int vlbe__ale_sidx(const vlbe_ale_chain *ch, int i, int which)
{
    return ch->node[i].ofs + ch->d * (1 + (ch->node[i].slide && which ? 1 : 0));
}

/* element e's index map into q: its coordinates node by node (position,
   the slope on the element's side, spin, p), -1 for a p that is not a
   coordinate (the layout of vlbe_ale_chain_gather) */
VLBE_INLINE void vlbe__ale_eidx(const vlbe_ale_chain *ch, int e, int *idx)
{
    const int d = ch->d, nb = 2 * d + ch->spin + 1; /* element block per node */
    int s, k;
    for (s = 0; s < 2; ++s) {
        const int i = e + s, b = nb * s;
        const int o = ch->node[i].ofs, sl = vlbe__ale_sidx(ch, i, s == 0);
        for (k = 0; k < d; ++k) {
            idx[b + k] = o + k;
            idx[b + d + k] = sl + k;
        }
        if (ch->spin) idx[b + 2 * d] = vlbe__ale_tidx(ch, i);
        idx[b + nb - 1] = vlbe__ale_pidx(ch, i);
    }
}

/* Row j of constraint c of a laid-out chain: the lowest coordinate of q
   the row touches in *lo and, returned, the node of the highest (the
   row's place in the augmented order).  The columns are those that
   vlbe__ale_chain_con writes. */
VLBE_INLINE int vlbe__ale_con_row(const vlbe_ale_chain *ch, const vlbe_ale_con *c, int j,
                                    int *lo)
{
    const int o = ch->node[c->node].ofs;
    int b, h = -1;
    switch (c->type) {
    case VLBE_ALE_CON_POS: /* the j-th held component */
        for (b = 0; b + 1 < ch->d; ++b)
            if ((!c->which || ((c->which >> b) & 1)) && ++h == j) break;
        *lo = o + b;
        return c->node;
    case VLBE_ALE_CON_SLOPE: *lo = vlbe__ale_sidx(ch, c->node, c->which) + j; return c->node;
    case VLBE_ALE_CON_SLOPE_DIR: case VLBE_ALE_CON_SLOPE_ANGLE: case VLBE_ALE_CON_SLOPE_ROT:
        *lo = vlbe__ale_sidx(ch, c->node, c->which); /* the whole slope */
        return c->node;
    case VLBE_ALE_CON_P: *lo = vlbe__ale_pidx(ch, c->node); return c->node;
    case VLBE_ALE_CON_SPIN: *lo = vlbe__ale_tidx(ch, c->node); return c->node;
    case VLBE_ALE_CON_EQUAL_LEN: { /* p of node i, and of the ends when free */
        const int i = c->node + 1 + j, ca = vlbe__ale_pidx(ch, c->node);
        *lo = ca >= 0 ? ca : vlbe__ale_pidx(ch, i);
        return vlbe__ale_pidx(ch, c->node2) >= 0 ? c->node2 : i;
    }
    case VLBE_ALE_CON_SLIDE_C: *lo = o + 2 + j; return c->node; /* and o + 4 + j */
    default: *lo = o + 2; return c->node; /* SLIDE_D: both slopes, o + 2 .. o + 5 */
    }
}

/* The highest coordinate row j of constraint c touches, for the rows of
   one node (every type but VLBE_ALE_CON_EQUAL_LEN); lo from
   vlbe__ale_con_row. */
VLBE_INLINE int vlbe__ale_con_hi(const vlbe_ale_chain *ch, const vlbe_ale_con *c, int lo)
{
    switch (c->type) {
    case VLBE_ALE_CON_SLOPE_DIR: case VLBE_ALE_CON_SLOPE_ANGLE: case VLBE_ALE_CON_SLOPE_ROT:
        return lo + ch->d - 1; /* the slope's d components */
    case VLBE_ALE_CON_SLIDE_C: return lo + 2;                                   /* r'(1), r'(2) */
    case VLBE_ALE_CON_SLIDE_D: return lo + 3;
    default: return lo; /* one coordinate */
    }
}

/* Do the callbacks' matrices of a chain of n coordinates, m equations (in
   dimension d, with the constraints of ch) fit?  Dense: n * n and m * n in
   a size_t (else VLBE_EARG).  Banded: n + m <= INT_MAX (VLBE_EARG), <=
   ch->order_cap (VLBE_EWORK), and (n + m) ld in a size_t for the largest
   ld the structure allows (VLBE_EARG): a coupled pair lies within s
   consecutive nodes (an element: 2; an equal-length group: node2 - node
   + 1) of at most 3 d + 2 coordinates each, and the m rows, so kl < s (3 d
   + 2) + m and ld <= 2 kl + 1. */
VLBE_INLINE vlbe_status vlbe__ale_size_ok(const vlbe_ale_chain *ch, int d, int n, int m)
{
    const size_t big = (size_t)-1 / 4, nc = (size_t)(3 * d + 2);
    size_t span = 2, klb;
    int k;
    if (!ch->order) {
        if ((size_t)n > (size_t)-1 / (size_t)n || (size_t)m > (size_t)-1 / (size_t)n)
            return VLBE_EARG;
        return VLBE_OK;
    }
    if (n > INT_MAX - m) return VLBE_EARG;
    if (n + m > ch->order_cap) return VLBE_EWORK;
    for (k = 0; k < ch->ncon; ++k) {
        const vlbe_ale_con *c = &ch->con[k];
        if (c->type == VLBE_ALE_CON_EQUAL_LEN && (size_t)(c->node2 - c->node) + 1 > span)
            span = (size_t)(c->node2 - c->node) + 1;
    }
    if ((size_t)m > big || span > (big - (size_t)m) / nc) return VLBE_EARG;
    klb = span * nc + (size_t)m; /* <= big: 2 klb + 1 does not wrap */
    return (size_t)(n + m) > (size_t)-1 / (2 * klb + 1) ? VLBE_EARG : VLBE_OK;
}

/* The augmented order and half-bandwidth of a laid-out chain in banded mode
   (see vlbe_ale_chain).  order[] serves as its own scratch: the node of
   each constraint row goes to order[n + r] (-1: a row of node 0 alone,
   which goes first), the rows per node to order[0 .. nn-1] (n >= 4 nn),
   turned into the rows before each node, then the rows' places; the
   coordinates come last, node by node from the last, node i's
   overwriting order[ofs_i ..] (ofs_i >= 4 i) after order[i - 1], the rows
   before node i, was read. */
VLBE_INLINE void vlbe__ale_band_order(vlbe_ale_chain *ch)
{
    int *ord = ch->order;
    const int n = ch->n, nn = ch->nn, ne = 2 * (2 * ch->d + ch->spin + 1);
    int i, k, j, r, s, kl = 0, c0 = 0, f0 = 0;
    for (i = 0; i < nn; ++i) ord[i] = 0;
    for (k = 0, r = 0; k < ch->ncon; ++k) {
        const int rows = vlbe__ale_con_rows(ch, &ch->con[k]);
        for (j = 0; j < rows; ++j, ++r) {
            int lo;
            ord[n + r] = vlbe__ale_con_row(ch, &ch->con[k], j, &lo);
            if (ord[n + r] == 0 && ch->con[k].type != VLBE_ALE_CON_EQUAL_LEN) {
                ord[n + r] = -1; /* before node 0: no neighbour on that side */
                ++c0;
            } else {
                ord[ord[n + r]]++;
            }
        }
    }
    for (i = 0, s = c0; i < nn; ++i) { /* rows before node i's coordinates, c0 included */
        const int c = ord[i];
        ord[i] = s;
        s += c;
    }
    for (r = 0; r < ch->m; ++r) { /* after its node's coordinates, in row order */
        const int nd = ord[n + r], end = nd + 1 < nn ? ch->node[nd + 1].ofs : n;
        ord[n + r] = nd < 0 ? f0++ : end + ord[nd]++;
    }
    for (i = nn - 1; i >= 0; --i) { /* ord[i - 1]: now the rows of the nodes before i */
        const int before = i > 0 ? ord[i - 1] : c0, end = i + 1 < nn ? ch->node[i + 1].ofs : n;
        for (k = ch->node[i].ofs; k < end; ++k) ord[k] = k + before;
    }
    /* the bandwidth: the coordinates keep their order, so an element's
       widest pair is its first and last coordinate, and a row (placed after
       every coordinate it touches) is farthest from its lowest one.  The
       Hessian's pairs (SLIDE_D: the slopes of one node) lie inside that
       row's, the point masses on the diagonal. */
    for (k = 0; k + 1 < nn; ++k) {
        int idx[VLBE_ALE3_NQ], a = INT_MAX, b = -1;
        vlbe__ale_eidx(ch, k, idx);
        for (j = 0; j < ne; ++j)
            if (idx[j] >= 0) {
                if (ord[idx[j]] < a) a = ord[idx[j]];
                if (ord[idx[j]] > b) b = ord[idx[j]];
            }
        if (b - a > kl) kl = b - a;
    }
    for (k = 0, r = 0; k < ch->ncon; ++k) {
        const int rows = vlbe__ale_con_rows(ch, &ch->con[k]);
        for (j = 0; j < rows; ++j, ++r) {
            int lo, w;
            (void)vlbe__ale_con_row(ch, &ch->con[k], j, &lo);
            /* a row before node 0 is farthest from its highest coordinate */
            w = ord[n + r] < c0 ? ord[vlbe__ale_con_hi(ch, &ch->con[k], lo)] - ord[n + r]
                                : ord[n + r] - ord[lo];
            if (w > kl) kl = w;
        }
    }
    ch->kl = ch->ku = kl;
}

/* Assign coordinates (node.ofs, n) and count constraint rows (m); checks
   the nodes and constraints.  Call after any change of nodes or constraints
   and after vlbe_ale_chain_band.  In banded mode it writes the augmented
   order to order[0 .. n+m-1] and sets kl, ku.  VLBE_EARG also when n or m
   would exceed INT_MAX or the callbacks' matrices the range of size_t
   (dense: n * n, m * n; banded: n + m > INT_MAX, (n + m) ld, see
   vlbe__ale_size_ok); VLBE_EWORK in banded mode when order_cap < n + m.
   On failure the chain is unchanged (order included). */
VLBE_API vlbe_status vlbe_ale_chain_layout(vlbe_ale_chain *ch)
{
    int i, k, n = 0, m = 0, d, spin;
    vlbe_status st;
    VLBE_ASSERT(ch != NULL);
    d = ch->el3 ? 3 : 2;
    spin = ch->el3 && !((ch->el3->flags | ch->mode) & VLBE_ALE3_NO_SPIN);
    if (ch->nn < 2 || ch->nn > ch->nn_cap || ch->ncon < 0 || ch->ncon > ch->ncon_cap)
        return VLBE_EARG;
    for (i = 0; i < ch->nn; ++i) {
        const vlbe_ale_node *nd = &ch->node[i];
        if (nd->pmode < VLBE_ALE_PFIXED || nd->pmode > VLBE_ALE_PFREE || nd->slide < 0 ||
            nd->slide > 1 || nd->mass < VLBE_R(0.0) || (ch->el3 && nd->slide))
            return VLBE_EARG;
        if (!vlbe_all_finite(&nd->p, 1) || !vlbe_all_finite(&nd->pd, 1) ||
            !vlbe_all_finite(&nd->pdd, 1) || !vlbe_all_finite(&nd->mass, 1))
            return VLBE_ENONFINITE;
    }
    for (k = 0; k < ch->ncon; ++k) {
        const vlbe_ale_con *c = &ch->con[k];
        int r = vlbe__ale_con_rows(ch, c);
        if ((st = vlbe__ale_con_check(ch, c)) != VLBE_OK) return st;
        if (m > INT_MAX - r) return VLBE_EARG;
        if (c->type == VLBE_ALE_CON_SPIN && !spin) return VLBE_EARG;
        if (c->type == VLBE_ALE_CON_EQUAL_LEN) {
            for (i = c->node + 1; i < c->node2; ++i)
                if (ch->node[i].pmode != VLBE_ALE_PFREE) return VLBE_EARG;
        }
        if (c->type == VLBE_ALE_CON_P && ch->node[c->node].pmode != VLBE_ALE_PFREE) return VLBE_EARG;
        if ((c->type == VLBE_ALE_CON_SLIDE_C || c->type == VLBE_ALE_CON_SLIDE_D) &&
            !ch->node[c->node].slide)
            return VLBE_EARG;
        m += r;
    }
    for (i = 0; i < ch->nn; ++i) { /* count first: a refused layout changes nothing */
        const int nc = d * (2 + ch->node[i].slide) + spin + (ch->node[i].pmode == VLBE_ALE_PFREE);
        if (n > INT_MAX - nc) return VLBE_EARG;
        n += nc;
    }
    if ((st = vlbe__ale_size_ok(ch, d, n, m)) != VLBE_OK) return st;
    for (i = 0, n = 0; i < ch->nn; ++i) {
        ch->node[i].ofs = n;
        n += d * (2 + ch->node[i].slide) + spin + (ch->node[i].pmode == VLBE_ALE_PFREE);
    }
    ch->d = d;
    ch->spin = spin;
    ch->n = n;
    ch->m = m;
    if (ch->order) vlbe__ale_band_order(ch);
    return VLBE_OK;
}

/* Switches the matrix callbacks to band storage in the augmented order
   (order != NULL: the caller's array of order_cap ints, kept by the chain)
   or back to dense n x n ones (order == NULL, the default).  Call
   vlbe_ale_chain_layout next, either way: it fills order and kl, ku (until
   then kl = ku = -1 in banded mode, and the matrix callbacks must not be
   called); insertion, removal and length control run it themselves, an
   insertion needing order_cap >= n + m + 4.  order_cap < 0 with an order:
   VLBE_EARG, nothing changed. */
VLBE_API vlbe_status vlbe_ale_chain_band(vlbe_ale_chain *ch, int *order, int order_cap)
{
    VLBE_ASSERT(ch != NULL);
    if (order && order_cap < 0) return VLBE_EARG;
    ch->order = order;
    ch->order_cap = order ? order_cap : 0;
    ch->kl = ch->ku = order ? -1 : 0;
    return VLBE_OK;
}

/* p, p', p'' of node i at time t (q, v: the state, for free nodes; v may
   be NULL: p' = 0).  i outside [0, nn): VLBE_EARG; a failing pfun:
   VLBE_ECALLBACK; a non-finite result (NaN in q, v, an overflow of the
   prescribed p(t)): VLBE_ENONFINITE.  On failure p3 is not written. */
VLBE_API vlbe_status vlbe_ale_chain_pnode(const vlbe_ale_chain *ch, int i, vlbe_real t,
                                          const vlbe_real *q, const vlbe_real *v, vlbe_real *p3)
{
    const vlbe_ale_node *nd;
    vlbe_real r[3];
    VLBE_ASSERT(ch != NULL && p3 != NULL);
    if (i < 0 || i >= ch->nn) return VLBE_EARG;
    nd = &ch->node[i];
    switch (nd->pmode) {
    case VLBE_ALE_PFREE: {
        const int k = vlbe__ale_pidx(ch, i);
        VLBE_ASSERT(q != NULL);
        if (!isfinite(q[k]) || (v && !isfinite(v[k]))) return VLBE_ENONFINITE;
        p3[0] = q[k];
        p3[1] = v ? v[k] : VLBE_R(0.0);
        p3[2] = VLBE_R(0.0);
        return VLBE_OK;
    }
    case VLBE_ALE_PPRESCRIBED: /* through locals: p(t) may overflow, pfun give NaN */
        if (ch->pfun) {
            if (ch->pfun(ch->user, i, t, r)) return VLBE_ECALLBACK;
        } else {
            vlbe__law(nd->p, nd->pd, nd->pdd, t, r);
        }
        if (!vlbe_all_finite(r, 3)) return VLBE_ENONFINITE;
        p3[0] = r[0];
        p3[1] = r[1];
        p3[2] = r[2];
        return VLBE_OK;
    default: /* node.p: finite (layout) */
        p3[0] = nd->p;
        p3[1] = p3[2] = VLBE_R(0.0);
        return VLBE_OK;
    }
}

/* vlbe_ale_chain_gather without the range check, written in place (the
   callers' own locals): rates when v and ve are both given */
VLBE_INLINE vlbe_status vlbe__ale_gather(const vlbe_ale_chain *ch, int e, vlbe_real t,
                                           const vlbe_real *q, const vlbe_real *v, vlbe_real *qe,
                                           vlbe_real *ve, int *idx, unsigned *mode)
{
    const int nb = 2 * ch->d + ch->spin + 1; /* element block per node */
    const int rates = v != NULL && ve != NULL;
    int s, k;
    vlbe_status st;
    *mode = ch->mode;
    vlbe__ale_eidx(ch, e, idx);
    for (s = 0; s < 2; ++s) {
        const int i = e + s, b = nb * s;
        vlbe_real p3[3];
        if ((st = vlbe_ale_chain_pnode(ch, i, t, q, v, p3)) != VLBE_OK) return st;
        for (k = 0; k < nb - 1; ++k) {
            qe[b + k] = q[idx[b + k]];
            if (rates) ve[b + k] = v[idx[b + k]];
        }
        qe[b + nb - 1] = p3[0];
        if (rates) ve[b + nb - 1] = p3[1];
        if (ch->node[i].pmode == VLBE_ALE_PFIXED) *mode |= s ? VLBE_ALE_FIX_P2 : VLBE_ALE_FIX_P1;
    }
    if (!vlbe_all_finite(qe, 2 * nb) || (rates && !vlbe_all_finite(ve, 2 * nb)))
        return VLBE_ENONFINITE;
    if (!(qe[2 * nb - 1] - qe[nb - 1] > ch->Lmin)) return VLBE_ELENGTH;
    return VLBE_OK;
}

/* Element e's coordinates qe (and rates ve when v and ve are given; ve is
   written only then), its index map idx into q (-1 for a p that is not a
   coordinate) and element mode; qe, ve, idx hold the element's coordinates
   (10 planar, vlbe_ale3_nq(mode) 3D: VLBE_ALE3_NQ is always enough).  e
   outside [0, nn - 1): VLBE_EARG; NaN/Inf in the element's coordinates or
   rates: VLBE_ENONFINITE; p2 - p1 <= ch->Lmin: VLBE_ELENGTH; the errors of
   vlbe_ale_chain_pnode.  On failure nothing is written. */
VLBE_API vlbe_status vlbe_ale_chain_gather(const vlbe_ale_chain *ch, int e, vlbe_real t,
                                           const vlbe_real *q, const vlbe_real *v, vlbe_real *qe,
                                           vlbe_real *ve, int *idx, unsigned *mode)
{
    vlbe_real qt[VLBE_ALE3_NQ], vt[VLBE_ALE3_NQ];
    int it[VLBE_ALE3_NQ], k, ne;
    unsigned md;
    vlbe_status st;
    VLBE_ASSERT(ch != NULL && q != NULL && qe != NULL && idx != NULL && mode != NULL);
    if (e < 0 || e >= ch->nn - 1) return VLBE_EARG;
    /* vt is written by the gather when ve is given (cppcheck cannot see it) */
    /* cppcheck-suppress legacyUninitvar */
    if ((st = vlbe__ale_gather(ch, e, t, q, v, qt, ve ? vt : NULL, it, &md)) != VLBE_OK) return st;
    ne = 2 * (2 * ch->d + ch->spin + 1);
    for (k = 0; k < ne; ++k) {
        qe[k] = qt[k];
        idx[k] = it[k];
        if (v && ve) ve[k] = vt[k];
    }
    *mode = md;
    return VLBE_OK;
}

/* Nodes on a straight line: r_i = r0 + dir (p_i - p_0), slopes dir (unit for
   an unstretched chain; scale dir for a uniform stretch), free p's at
   node.p, spin angles 0; all other coordinates of q are written too.  r0,
   dir: d = 2 or 3 components. */
VLBE_API void vlbe_ale_chain_straight(const vlbe_ale_chain *ch, const vlbe_real *r0,
                                      const vlbe_real *dir, vlbe_real *q)
{
    const int d = ch->d;
    int i, k;
    for (i = 0; i < ch->nn; ++i) {
        const vlbe_ale_node *nd = &ch->node[i];
        const int o = nd->ofs;
        for (k = 0; k < d; ++k) {
            q[o + k] = r0[k] + dir[k] * (nd->p - ch->node[0].p);
            q[o + d + k] = dir[k];
            if (nd->slide) q[o + 2 * d + k] = dir[k];
        }
        if (ch->spin) q[vlbe__ale_tidx(ch, i)] = VLBE_R(0.0);
        if (nd->pmode == VLBE_ALE_PFREE) q[vlbe__ale_pidx(ch, i)] = nd->p;
    }
}

/* An axially moving span in an Eulerian window (a moving string or belt,
   a band saw, a strip between rolls): nodes 0..nn-1 stay at the places s[i]
   (strictly increasing arc positions in space along the span) while the
   material passes through them at speed c (its velocity in space along the
   span; c < 0 flows towards node 0) with the stretch lam (vlbe_ale_prestretch
   for a tension, l / L0 for a stress-free length L0 of a span l).  Material
   coordinates are unstretched arc length, so the material point at place s
   at time t is p = (s - c t) / lam: every node gets pmode
   VLBE_ALE_PPRESCRIBED, p = s[i] / lam, pd = -c / lam, pdd = 0 (a chain's
   pfun, if set, still overrides them).  Call before vlbe_ale_chain_layout
   (the modes decide the coordinates); the straight start state is then
   vlbe_ale_chain_straight(ch, r0, lam e, q) with e the unit direction of
   the span (r = r0 + (s - s[0]) e, r' = lam e), at rest (v = 0: the nodes do
   not move, the material does).  lam <= 0, s not increasing, or a value
   not finite: VLBE_EARG, the nodes untouched. */
VLBE_API vlbe_status vlbe_ale_chain_window(vlbe_ale_chain *ch, const vlbe_real *s, vlbe_real lam,
                                           vlbe_real c)
{
    vlbe_real x[2];
    int i;
    VLBE_ASSERT(ch != NULL && s != NULL);
    x[0] = lam;
    x[1] = c;
    if (!vlbe_all_finite(x, 2) || !(lam > VLBE_R(0.0)) || !vlbe_all_finite(s, ch->nn))
        return VLBE_EARG;
    for (i = 0; i + 1 < ch->nn; ++i)
        if (!(s[i + 1] > s[i])) return VLBE_EARG;
    for (i = 0; i < ch->nn; ++i) { /* p and p' finite (no overflow) */
        x[0] = s[i] / lam;
        x[1] = -c / lam;
        if (!vlbe_all_finite(x, 2)) return VLBE_EARG;
    }
    for (i = 0; i < ch->nn; ++i) {
        ch->node[i].pmode = VLBE_ALE_PPRESCRIBED;
        ch->node[i].p = s[i] / lam;
        ch->node[i].pd = -c / lam;
        ch->node[i].pdd = VLBE_R(0.0);
    }
    return VLBE_OK;
}

/* Element holding material point p (the first whose [p1, p2] contains it). */
VLBE_API vlbe_status vlbe_ale_chain_locate(const vlbe_ale_chain *ch, vlbe_real t,
                                           const vlbe_real *q, vlbe_real p, int *e)
{
    int i;
    vlbe_real pa[3], pb[3];
    vlbe_status st;
    if ((st = vlbe_ale_chain_pnode(ch, 0, t, q, NULL, pa)) != VLBE_OK) return st;
    for (i = 0; i + 1 < ch->nn; ++i) {
        if ((st = vlbe_ale_chain_pnode(ch, i + 1, t, q, NULL, pb)) != VLBE_OK) return st;
        if (p >= pa[0] && p <= pb[0]) {
            *e = i;
            return VLBE_OK;
        }
        pa[0] = pb[0];
    }
    return VLBE_EBOUND;
}

/* Position r and slope rp (each d components; either may be NULL) of the
   material point p, in the first element holding it.  Errors of
   vlbe_ale_chain_locate and _gather, of the element's point evaluation; a
   non-finite r or rp: VLBE_ENONFINITE.  On failure r, rp are not written. */
VLBE_API vlbe_status vlbe_ale_chain_point(const vlbe_ale_chain *ch, vlbe_real t, const vlbe_real *q,
                                          vlbe_real p, vlbe_real *r, vlbe_real *rp)
{
    vlbe_real qe[VLBE_ALE3_NQ], r3[3], rp3[3];
    int e, k, idx[VLBE_ALE3_NQ];
    unsigned md;
    vlbe_status st;
    VLBE_ASSERT(ch != NULL);
    if ((st = vlbe_ale_chain_locate(ch, t, q, p, &e)) != VLBE_OK) return st;
    if ((st = vlbe__ale_gather(ch, e, t, q, NULL, qe, NULL, idx, &md)) != VLBE_OK) return st;
    /* through locals: committed when finite */
    if (ch->el3) {
        if ((st = vlbe_ale3_point(md | ch->el3->flags, qe, p, r3, rp3, NULL)) != VLBE_OK) return st;
    } else if (ch->et) {
        vlbe_herm_ale b;
        vlbe__ale_chain_basis(ch, e, p, qe[4], qe[9], 1, 0, &b);
        vlbe__ale_sum(&b, 0, 0, qe, r3);
        vlbe__ale_sum(&b, 1, 0, qe, rp3);
    } else if ((st = vlbe_ale_point(qe, p, r3, rp3)) != VLBE_OK) {
        return st;
    }
    if (!vlbe_all_finite(r3, ch->d) || !vlbe_all_finite(rp3, ch->d)) return VLBE_ENONFINITE;
    for (k = 0; k < ch->d; ++k) {
        if (r) r[k] = r3[k];
        if (rp) rp[k] = rp3[k];
    }
    return VLBE_OK;
}

/* Kinetic, strain and potential energy E = {T, U, V} (loads and gravity on
   point masses); v is required.  V is that of the distributed loads and
   gravity times the load factor, and of the constant point forces at fixed
   material points (-load_factor f . r(p); moments, moving or callback
   loads have none here).  Errors of vlbe_ale_chain_gather and the element
   energies, of vlbe_ale_chain_point for a point force (an `outside` one
   outside the range counts 0); a sum that overflows: VLBE_ENONFINITE.  On
   failure E is not written. */
VLBE_API vlbe_status vlbe_ale_chain_energy(vlbe_ale_chain *ch, vlbe_real t, const vlbe_real *q,
                                           const vlbe_real *v, vlbe_real *E)
{
    vlbe_real qe[VLBE_ALE3_NQ], ve[VLBE_ALE3_NQ], Ee[3] = {0, 0, 0}, Es[3];
    int e, i, k, idx[VLBE_ALE3_NQ];
    unsigned md;
    vlbe_status st;
    VLBE_ASSERT(ch != NULL && q != NULL && v != NULL && E != NULL);
    Es[0] = Es[1] = Es[2] = VLBE_R(0.0);
    for (e = 0; e + 1 < ch->nn; ++e) {
        if ((st = vlbe__ale_gather(ch, e, t, q, v, qe, ve, idx, &md)) != VLBE_OK) return st;
        st = ch->el3 ? vlbe_ale3_energy(ch->el3, md, qe, ve, Ee)
                     : vlbe_ale_energy(vlbe__ale_el(ch, e), md, qe, ve, Ee);
        if (st != VLBE_OK) return st;
        Es[0] += Ee[0];
        Es[1] += Ee[1];
        Es[2] += ch->load_factor * Ee[2];
    }
    for (i = 0; i < ch->nn; ++i) {
        const vlbe_real m = ch->node[i].mass, *r = q + ch->node[i].ofs, *rd = v + ch->node[i].ofs;
        for (k = 0; k < ch->d; ++k) {
            Es[0] += VLBE_R(0.5) * m * rd[k] * rd[k];
            Es[2] -= ch->load_factor * m * ch->g[k] * r[k];
        }
    }
    for (i = 0; i < ch->nloads; ++i) { /* constant forces at fixed material points */
        const vlbe_ale_load *ld = &ch->loads[i];
        vlbe_real r[3];
        if (ld->kind != VLBE_ALE_LOAD_FORCE || ld->fun || ld->p[1] != VLBE_R(0.0) ||
            ld->p[2] != VLBE_R(0.0))
            continue;
        st = vlbe_ale_chain_point(ch, t, q, ld->p[0], r, NULL);
        if (st == VLBE_EBOUND && ld->outside) continue;
        if (st != VLBE_OK) return st;
        for (k = 0; k < ch->d; ++k) Es[2] -= ch->load_factor * ld->f[k] * r[k];
    }
    if (!vlbe_all_finite(Es, 3)) return VLBE_ENONFINITE;
    E[0] = Es[0];
    E[1] = Es[1];
    E[2] = Es[2];
    return VLBE_OK;
}

/* Deformed arc length of the chain, sum of int |r'| dp over the elements
   (8-point Gauss-Legendre per element: |r'| is the root of a quartic, smooth
   while r' != 0), and, when v and rate are given, its time derivative
   d/dt int |r'| dp = int r'.(dr'/dt)/|r'| dp + |r'| p' at the last node
   - |r'| p' at the first (dr'/dt at fixed material p: the material rate of
   the slope, eq. 14 of [R] differentiated in p); the terms of interior
   nodes cancel, |r'| being continuous there.  A zero slope: VLBE_ESINGULAR;
   an overflow: VLBE_ENONFINITE; a 3D chain: VLBE_EARG.  On failure len and
   rate are not written. */
VLBE_API vlbe_status vlbe_ale_chain_length(const vlbe_ale_chain *ch, vlbe_real t,
                                           const vlbe_real *q, const vlbe_real *v, vlbe_real *len,
                                           vlbe_real *rate)
{
    const vlbe_real *xi, *w;
    vlbe_real qe[10], ve[10], L = VLBE_R(0.0), Ld = VLBE_R(0.0);
    int e, g, idx[10];
    unsigned md;
    vlbe_status st;
    const int want_rate = v != NULL && rate != NULL;
    VLBE_ASSERT(ch != NULL && q != NULL && len != NULL);
    if (ch->el3) return VLBE_EARG; /* planar chains only */
    if ((st = vlbe_gl_rule(8, &xi, &w)) != VLBE_OK) return st;
    for (e = 0; e + 1 < ch->nn; ++e) {
        vlbe_real h;
        if ((st = vlbe__ale_gather(ch, e, t, q, want_rate ? v : NULL, qe, want_rate ? ve : NULL,
                                   idx, &md)) != VLBE_OK)
            return st;
        h = VLBE_R(0.5) * (qe[9] - qe[4]);
        for (g = 0; g < 8; ++g) {
            const vlbe_real p = qe[4] + h * (VLBE_R(1.0) + xi[g]);
            vlbe_herm_ale b;
            vlbe_real r1[2], n1;
            vlbe__ale_chain_basis(ch, e, p, qe[4], qe[9], 1, want_rate, &b);
            vlbe__ale_sum(&b, 1, 0, qe, r1);
            n1 = vlbe_sqrt(vlbe_v2_dot(r1, r1));
            if (!(n1 > VLBE_R(0.0))) return VLBE_ESINGULAR;
            L += w[g] * h * n1;
            if (want_rate) { /* dr'/dt at fixed material p */
                vlbe_real r1d[2];
                vlbe__ale_mat_rate(&b, 1, qe, ve, r1d);
                Ld += w[g] * h * vlbe_v2_dot(r1, r1d) / n1;
            }
        }
        if (want_rate && e == 0) /* moving end points */
            Ld -= vlbe_sqrt(vlbe_v2_dot(qe + 2, qe + 2)) * ve[4];
        if (want_rate && e + 2 == ch->nn) Ld += vlbe_sqrt(vlbe_v2_dot(qe + 7, qe + 7)) * ve[9];
    }
    if (!isfinite(L) || (want_rate && !isfinite(Ld))) return VLBE_ENONFINITE;
    *len = L;
    if (want_rate) *rate = Ld;
    return VLBE_OK;
}

/* Records a callback failure and returns the callback's value: positive
   (the integrator may retry a smaller step) when the state itself is out of
   the model's domain -- an element shorter than Lmin or inverted, a zero
   slope, non-finite values, which a Newton iterate can produce -- and
   negative (fatal) for everything else (bad arguments, a failing pfun). */
VLBE_INLINE int vlbe__ale_fail(vlbe_ale_chain *ch, vlbe_status st, int where)
{
    ch->err = st;
    ch->err_elem = where;
    ch->err_load = -1;
    return vlbe__dae_rc(st);
}

/* coordinates of one element of the chain (10 planar, 14 or 16 in 3D) */
VLBE_INLINE int vlbe__ale_ne(const vlbe_ale_chain *ch)
{
    return 2 * (2 * ch->d + ch->spin + 1);
}

/* the element calls of the chain's element type (md: the gathered mode) */
VLBE_INLINE vlbe_status vlbe__ale_el_mass(const vlbe_ale_chain *ch, int e, unsigned md,
                                            const vlbe_real *qe, vlbe_real *Me)
{
    return ch->el3 ? vlbe_ale3_mass(ch->el3, md, qe, Me)
                   : vlbe_ale_mass(vlbe__ale_el(ch, e), md, qe, Me);
}

VLBE_INLINE vlbe_status vlbe__ale_el_mass_jac(const vlbe_ale_chain *ch, int e, unsigned md,
                                                const vlbe_real *qe, const vlbe_real *ae,
                                                vlbe_real *Je)
{
    return ch->el3 ? vlbe_ale3_mass_jac(ch->el3, md, qe, ae, Je)
                   : vlbe_ale_mass_jac(vlbe__ale_el(ch, e), md, qe, ae, Je);
}

/* (the force with the distributed load mat.f times the chain's load factor) */
VLBE_INLINE vlbe_status vlbe__ale_el_force(const vlbe_ale_chain *ch, int e, unsigned md,
                                             const vlbe_real *qe, const vlbe_real *ve,
                                             vlbe_real *Qe, vlbe_real *Ke, vlbe_real *De)
{
    const vlbe_ale_elem *el = ch->el3 ? NULL : vlbe__ale_el(ch, e);
    const vlbe_real *f = el ? el->mat.f : ch->el3->mat.f;
    vlbe_real fl[3] = {0, 0, 0};
    int c;
    for (c = 0; c < ch->d; ++c) fl[c] = ch->load_factor * f[c];
    return el ? vlbe__ale_force(el, md | el->flags, qe, ve, Qe, Ke, De, 1, fl)
              : vlbe__ale3_force(ch->el3, md, qe, ve, Qe, Ke, De, fl);
}

/* The index map of the chain's matrices: entry (i, j) -- i, j < n
   coordinates, or n + k for constraint row k in banded mode -- at
   A[vlbe_ale_chain_at(ch, i, j)]: dense i n + j, banded VLBE_BAND_IDX(ld, kl,
   order[i], order[j]) with ld = kl + ku + 1 (see vlbe_ale_chain).  Every
   assembly below goes through it, and a caller adding terms of its own to
   M, K or D (after the layout) does the same. */
VLBE_API size_t vlbe_ale_chain_at(const vlbe_ale_chain *ch, int i, int j)
{
    if (!ch->order) return (size_t)i * (size_t)ch->n + (size_t)j;
    return VLBE_BAND_IDX(ch->kl + ch->ku + 1, ch->kl, ch->order[i], ch->order[j]);
}

/* entry (k, j) of C_q: row k of the dense m x n matrix, or the row of
   constraint k in the augmented order */
VLBE_INLINE size_t vlbe__ale_cq_at(const vlbe_ale_chain *ch, int k, int j)
{
    return vlbe_ale_chain_at(ch, ch->order ? ch->n + k : k, j);
}

/* reals of one of the chain's matrices (after the layout): n * n dense,
   (n + m) ld banded (the layout checked that it fits in a size_t) */
VLBE_API size_t vlbe_ale_chain_mat_len(const vlbe_ale_chain *ch)
{
    if (!ch->order) return (size_t)ch->n * (size_t)ch->n;
    VLBE_ASSERT(ch->kl >= 0); /* vlbe_ale_chain_band is followed by a layout */
    return (size_t)(ch->n + ch->m) * (size_t)(ch->kl + ch->ku + 1);
}

/* scatter the ne x ne element matrix Ae into the chain's matrix A and,
   when given, Be into B (global coordinates idx, < 0: none; map: the
   caller's 2 ne scratch for vlbe__scatter_map); the finiteness of the sums
   is vlbe__ale_band_finite's, after the assembly */
VLBE_INLINE void vlbe__ale_scatter(const vlbe_ale_chain *ch, int ne, const int *idx, size_t *map,
                                   const vlbe_real *Ae, vlbe_real *A, const vlbe_real *Be,
                                   vlbe_real *B)
{
    if (!A && !B) return;
    vlbe__scatter_map(ne, idx, ch->n, ch->order, ch->kl, ch->ku, map, map + ne);
    if (A) (void)vlbe__scatter(ne, map, map + ne, Ae, A);
    if (B) (void)vlbe__scatter(ne, map, map + ne, Be, B);
}

/* 1 when every entry an element can touch in the assembled matrix A is
   finite, checked after the assembly (an entry that overflowed while being
   summed stays Inf or NaN).  Dense: rows of node i, columns of nodes i-1
   .. i+1 (contiguous in q), one vectorised pass over the band; banded: the
   whole band array, row by row. */
VLBE_INLINE int vlbe__ale_band_finite(const vlbe_ale_chain *ch, const vlbe_real *A)
{
    const size_t n = (size_t)ch->n;
    int i, r, ok = 1;
    if (ch->order) {
        const int ld = ch->kl + ch->ku + 1;
        for (r = 0; r < ch->n + ch->m; ++r) ok &= vlbe_all_finite(A + (size_t)r * (size_t)ld, ld);
        return ok;
    }
    for (i = 0; i < ch->nn; ++i) {
        const int lo = ch->node[i > 0 ? i - 1 : 0].ofs;
        const int hi = i + 2 < ch->nn ? ch->node[i + 2].ofs : ch->n;
        const int r1 = i + 1 < ch->nn ? ch->node[i + 1].ofs : ch->n;
        for (r = ch->node[i].ofs; r < r1; ++r)
            ok &= vlbe_all_finite(A + (size_t)r * n + (size_t)lo, hi - lo);
    }
    return ok;
}

/* 1 when the diagonal of the n x n matrix A is finite: enough for the mass
   matrix, a sum of positive semidefinite element matrices (w G^T G, eqs.
   19, 28) and point masses, whose entries obey |M_ij| <= sqrt(M_ii M_jj) */
VLBE_INLINE int vlbe__ale_diag_finite(int n, const vlbe_real *A)
{
    const size_t n1 = (size_t)n + 1;
    int i, ok = 1;
    for (i = 0; i < n; ++i) ok &= A[(size_t)i * n1] - A[(size_t)i * n1] == VLBE_R(0.0);
    return ok;
}

/* 1 when the diagonal of the chain's matrix A is finite (the mass matrix:
   vlbe__ale_diag_finite) */
VLBE_INLINE int vlbe__ale_mdiag_finite(const vlbe_ale_chain *ch, const vlbe_real *A)
{
    int i, ok = 1;
    if (!ch->order) return vlbe__ale_diag_finite(ch->n, A);
    for (i = 0; i < ch->n; ++i) {
        const vlbe_real a = A[vlbe_ale_chain_at(ch, i, i)];
        ok &= a - a == VLBE_R(0.0);
    }
    return ok;
}

/* zero one of the chain's matrices (vlbe_ale_chain_mat_len reals) */
VLBE_INLINE void vlbe__ale_zero_mat(const vlbe_ale_chain *ch, vlbe_real *A)
{
    const size_t len = vlbe_ale_chain_mat_len(ch);
    size_t i;
    for (i = 0; i < len; ++i) A[i] = VLBE_R(0.0);
}

/* the first element whose coordinates hold entry k of q (or v, a): that
   of node i's position, slopes, spin and p is element i - 1 (element 0 for
   node 0), except the right slope of a sliding node: element i */
VLBE_INLINE int vlbe__ale_elem_of(const vlbe_ale_chain *ch, int k)
{
    int i = 0;
    while (i + 1 < ch->nn && ch->node[i + 1].ofs <= k) ++i; /* node i holds k */
    if (i == 0) return 0;
    if (ch->node[i].slide && i + 1 < ch->nn && k >= ch->node[i].ofs + 2 * ch->d &&
        k < ch->node[i].ofs + 3 * ch->d)
        return i;
    return i - 1;
}

/* index of the first NaN/Inf of x[0..n-1], n when none (x may be NULL) */
VLBE_INLINE int vlbe__ale_first_bad(const vlbe_real *x, int n)
{
    int k = 0;
    if (x)
        while (k < n && isfinite(x[k])) ++k;
    return x ? k : n;
}

/* NaN/Inf in a callback's input q, v, a (each n; v, a may be NULL), found
   before any output is written: records VLBE_ENONFINITE with the first
   element that gathers such a value and returns the callback's value; 0
   when all finite (the common case: one vectorised pass per array) */
VLBE_INLINE int vlbe__ale_in_check(vlbe_ale_chain *ch, const vlbe_real *q, const vlbe_real *v,
                                     const vlbe_real *a)
{
    int e = ch->nn, k, j;
    const vlbe_real *x[3];
    if (vlbe_all_finite(q, ch->n) && (!v || vlbe_all_finite(v, ch->n)) &&
        (!a || vlbe_all_finite(a, ch->n)))
        return 0;
    x[0] = q;
    x[1] = v;
    x[2] = a;
    for (j = 0; j < 3; ++j)
        if ((k = vlbe__ale_first_bad(x[j], ch->n)) < ch->n) {
            const int ek = vlbe__ale_elem_of(ch, k);
            if (ek < e) e = ek;
        }
    return vlbe__ale_fail(ch, VLBE_ENONFINITE, e);
}

/* prescribed p'' of the element's non-coordinate p's, as an acceleration
   vector in element coordinates (zero elsewhere); returns 0 if all zero */
VLBE_INLINE int vlbe__ale_pres_acc(const vlbe_ale_chain *ch, int e, vlbe_real t, vlbe_real *ae)
{
    const int ne = vlbe__ale_ne(ch);
    int s, any = 0, k;
    for (k = 0; k < ne; ++k) ae[k] = VLBE_R(0.0);
    for (s = 0; s < 2; ++s)
        if (ch->node[e + s].pmode == VLBE_ALE_PPRESCRIBED) {
            vlbe_real p3[3];
            if (vlbe_ale_chain_pnode(ch, e + s, t, NULL, NULL, p3) == VLBE_OK && p3[2] != VLBE_R(0.0)) {
                ae[ne / 2 - 1 + (ne / 2) * s] = p3[2];
                any = 1;
            }
        }
    return any;
}

VLBE_API int vlbe_ale_chain_mass(void *user, vlbe_real t, const vlbe_real *q, const vlbe_real *v,
                                 vlbe_real *M)
{
    vlbe_ale_chain *ch = (vlbe_ale_chain *)user;
    vlbe_real qe[VLBE_ALE3_NQ], Me[VLBE_ALE3_NQ * VLBE_ALE3_NQ];
    size_t map[2 * VLBE_ALE3_NQ];
    int e, i, k, rc, ne, idx[VLBE_ALE3_NQ];
    unsigned md;
    vlbe_status st;
    (void)v;
    VLBE_ASSERT(ch != NULL && q != NULL && M != NULL);
    ne = vlbe__ale_ne(ch);
    if ((rc = vlbe__ale_in_check(ch, q, NULL, NULL)) != 0) return rc;
    vlbe__ale_zero_mat(ch, M);
    for (e = 0; e + 1 < ch->nn; ++e) {
        if ((st = vlbe__ale_gather(ch, e, t, q, NULL, qe, NULL, idx, &md)) != VLBE_OK ||
            (st = vlbe__ale_el_mass(ch, e, md, qe, Me)) != VLBE_OK)
            return vlbe__ale_fail(ch, st, e);
        vlbe__ale_scatter(ch, ne, idx, map, Me, M, NULL, NULL);
    }
    for (i = 0; i < ch->nn; ++i)
        for (k = 0; k < ch->d; ++k) {
            const int r = ch->node[i].ofs + k;
            M[vlbe_ale_chain_at(ch, r, r)] += ch->node[i].mass;
        }
    return vlbe__ale_mdiag_finite(ch, M) ? 0 : vlbe__ale_fail(ch, VLBE_ENONFINITE, -1);
}

/* -- point loads and the load factor (vlbe_ale_load) -------------------- */
/* a load's own data: kind, flag, law and constant value */
VLBE_INLINE vlbe_status vlbe__ale_load_ok(const vlbe_ale_chain *ch, const vlbe_ale_load *ld)
{
    if (ld->kind != VLBE_ALE_LOAD_FORCE && ld->kind != VLBE_ALE_LOAD_MOMENT &&
        ld->kind != VLBE_ALE_LOAD_MOMENT3)
        return VLBE_EARG;
    if (ld->kind == VLBE_ALE_LOAD_MOMENT && ch->el3 && !ch->spin) return VLBE_EARG;
    if (ld->kind == VLBE_ALE_LOAD_MOMENT3 && !ch->el3) return VLBE_EARG;
    if (ld->outside != 0 && ld->outside != 1) return VLBE_EARG;
    if (!vlbe_all_finite(ld->p, 3) || (!ld->fun && !vlbe_all_finite(ld->f, 3)))
        return VLBE_ENONFINITE;
    return VLBE_OK;
}

/* Gives the chain its point loads: the caller's array of n (n = 0: none),
   kept by pointer.  Each is checked (kind and outside: VLBE_EARG, a MOMENT
   in a 3D chain without spin too; NaN/Inf in p or, without fun, in f:
   VLBE_ENONFINITE; n < 0 or a NULL array with n > 0: VLBE_EARG); on
   failure the chain is unchanged.  The callbacks check them again at
   every call (the caller may change them between calls). */
VLBE_API vlbe_status vlbe_ale_chain_loads(vlbe_ale_chain *ch, const vlbe_ale_load *loads, int n)
{
    int k;
    vlbe_status st;
    VLBE_ASSERT(ch != NULL);
    if (n < 0 || (n > 0 && loads == NULL)) return VLBE_EARG;
    for (k = 0; k < n; ++k)
        if ((st = vlbe__ale_load_ok(ch, &loads[k])) != VLBE_OK) return st;
    ch->loads = n > 0 ? loads : NULL;
    ch->nloads = n;
    return VLBE_OK;
}

/* p(t), p'(t) of load ld in pp and the element holding p(t) in *e (-1: an
   `outside` load outside the material range) */
VLBE_INLINE vlbe_status vlbe__ale_load_at(const vlbe_ale_chain *ch, const vlbe_ale_load *ld,
                                            vlbe_real t, const vlbe_real *q, vlbe_real *pp, int *e)
{
    vlbe_status st;
    vlbe_real g3[3];
    vlbe__law(ld->p[0], ld->p[1], ld->p[2], t, g3);
    pp[0] = g3[0];
    pp[1] = g3[1];
    if (!vlbe_all_finite(pp, 2)) return VLBE_ENONFINITE;
    st = vlbe_ale_chain_locate(ch, t, q, pp[0], e);
    if (st == VLBE_EBOUND && ld->outside) {
        *e = -1;
        return VLBE_OK;
    }
    return st;
}

/* column of slot j (0: r1, 1: r1', 2: r2, 3: r2') in gathered element
   coordinates (nb per node, d per vector); p_k at nb k + nb - 1, theta_i
   at nb i + 2 d */
VLBE_INLINE int vlbe__ale_lso(int d, int nb, int j)
{
    return nb * (j >> 1) + d * (j & 1);
}

/* u = r^(kk)(p) (kk = 0: position, 1: slope; d components) of a gathered
   element from its basis b (k <= kk, p1/p2 partials to second order), and
   G = du/dq (d x ne, written whole) */
VLBE_INLINE void vlbe__ale_ld_field(int d, int nb, const vlbe_herm_ale *b, int kk,
                                      const vlbe_real *qe, vlbe_real *u, vlbe_real *G)
{
    const int ne = 2 * nb;
    int c, j, k;
    for (c = 0; c < d * ne; ++c) G[c] = VLBE_R(0.0);
    for (c = 0; c < d; ++c) {
        u[c] = VLBE_R(0.0);
        for (j = 0; j < 4; ++j) {
            const int o = vlbe__ale_lso(d, nb, j) + c;
            u[c] += b->h[kk][0][j] * qe[o];
            G[c * ne + o] = b->h[kk][0][j];
            for (k = 0; k < 2; ++k) G[c * ne + nb * k + nb - 1] += b->h[kk][1 + k][j] * qe[o];
        }
    }
}

/* Ke += s sum_c w_c d^2 u_c/dq^2 for u = r^(kk)(p): the e-p and p-p blocks
   (u is linear in the slots e) */
VLBE_INLINE void vlbe__ale_ld_hess(int d, int nb, const vlbe_herm_ale *b, int kk,
                                     const vlbe_real *qe, const vlbe_real *w, vlbe_real s,
                                     vlbe_real *Ke)
{
    static const int dd[2][2] = {{VLBE_DA_11, VLBE_DA_12}, {VLBE_DA_12, VLBE_DA_22}};
    const int ne = 2 * nb;
    int c, j, k, l;
    for (j = 0; j < 4; ++j) {
        const int o = vlbe__ale_lso(d, nb, j);
        vlbe_real ws = VLBE_R(0.0);
        for (c = 0; c < d; ++c) ws += w[c] * qe[o + c];
        for (k = 0; k < 2; ++k) {
            const int pk = nb * k + nb - 1;
            for (c = 0; c < d; ++c) {
                const vlbe_real h = s * b->h[kk][1 + k][j] * w[c];
                Ke[(o + c) * ne + pk] += h;
                Ke[pk * ne + o + c] += h;
            }
            for (l = 0; l < 2; ++l) Ke[pk * ne + nb * l + nb - 1] += s * b->h[kk][dd[k][l]][j] * ws;
        }
    }
}

/* The spin angle's Jacobian G (1 x ne, written whole) at the point of b
   (linear H basis, eq. 46 of [V]) and, with Ke, Ke += s w d^2 theta/dq^2 */
VLBE_INLINE void vlbe__ale_ld_spin(int d, int nb, const vlbe_herm_ale *b, const vlbe_real *qe,
                                     vlbe_real *G, vlbe_real w, vlbe_real s, vlbe_real *Ke)
{
    static const int dd[2][2] = {{VLBE_DA_11, VLBE_DA_12}, {VLBE_DA_12, VLBE_DA_22}};
    const int ne = 2 * nb;
    int i, k, l;
    for (i = 0; i < ne; ++i) G[i] = VLBE_R(0.0);
    for (i = 0; i < 2; ++i) {
        const int o = nb * i + 2 * d;
        G[o] = b->l[0][0][i];
        for (k = 0; k < 2; ++k) {
            const int pk = nb * k + nb - 1;
            G[pk] += b->l[0][1 + k][i] * qe[o];
            if (!Ke) continue;
            Ke[o * ne + pk] += s * w * b->l[0][1 + k][i];
            Ke[pk * ne + o] += s * w * b->l[0][1 + k][i];
            for (l = 0; l < 2; ++l)
                Ke[pk * ne + nb * l + nb - 1] += s * w * b->l[0][dd[k][l]][i] * qe[o];
        }
    }
}

/* A += s G^T B for G (nc x ne), B (nc x ne) */
VLBE_INLINE void vlbe__ale_ld_gtb(int nc, int ne, const vlbe_real *G, const vlbe_real *B,
                                    vlbe_real s, vlbe_real *A)
{
    int a, c, j;
    for (c = 0; c < nc; ++c)
        for (a = 0; a < ne; ++a) {
            const vlbe_real g = s * G[c * ne + a];
            if (g == VLBE_R(0.0)) continue;
            for (j = 0; j < ne; ++j) A[a * ne + j] += g * B[c * ne + j];
        }
}

/* Point load ld on element e of the chain (gathered qe, ve), at p = pp[0]
   moving with p' = pp[1]: the element vectors Qe and, when given, Ke and
   De (written whole), all times the load factor.  Force: Q = N^T f (eq. 45
   of [V]), K = f . d^2 r/dq^2 (the dependence on free p1, p2 at fixed p),
   planar moment M on phi = atan2(y', x'): Q = M dphi/dq, K = M
   d^2 phi/dq^2; 3D torque on the spin angle (eq. 46): the same with theta;
   3D moment vector: Q = G^T M, G = [r' x] G1/|r'|^2 + r' dtheta/dq/|r'|
   (G1 = dr'/dq), K its q-derivative at fixed M; a callback's df/dr,
   df/drd add G^T (df/dr dr/dq + df/drd drd/dq) to K and G^T df/drd dr/dv
   to D (G = d(r, phi, theta or the rotation)/dq, rd = N v + r' p').
   Errors: a zero slope under a planar moment or a moment vector
   (VLBE_ESINGULAR), a moment without spin in 3D or a moment vector in a
   planar chain (VLBE_EARG), fun failing (VLBE_ECALLBACK) or non-finite
   (VLBE_ENONFINITE).  About 150 lines: the four kinds share the point's
   basis, the map G of the load's variable and the callback's Jacobian
   terms; the kinds' own parts are in helpers (vlbe__ale_ld_field,
   _ld_hess, _ld_spin, _ld_gtb). */
VLBE_INLINE vlbe_status vlbe__ale_load_elem(const vlbe_ale_chain *ch, const vlbe_ale_load *ld,
                                              int e, vlbe_real t, const vlbe_real *pp,
                                              const vlbe_real *qe, const vlbe_real *ve,
                                              vlbe_real *Qe, vlbe_real *Ke, vlbe_real *De)
{
    static const int dd[2][2] = {{VLBE_DA_11, VLBE_DA_12}, {VLBE_DA_12, VLBE_DA_22}};
    const int d = ch->d, nb = 2 * d + ch->spin + 1, ne = 2 * nb;
    const int mom = ld->kind == VLBE_ALE_LOAD_MOMENT, m3 = ld->kind == VLBE_ALE_LOAD_MOMENT3;
    const int nc = mom ? 1 : d;
    const int jac = Ke != NULL || De != NULL, move = pp[1] != VLBE_R(0.0);
    const int slope = (mom && !ch->el3) || m3 || (ld->fun && move);
    const vlbe_real s = ch->load_factor;
    vlbe_herm_ale b;
    vlbe_real r[3] = {0, 0, 0}, r1[3] = {0, 0, 0}, f[3] = {0, 0, 0}, g[2] = {0, 0};
    vlbe_real dfr[9], dfv[9], Gr[3 * VLBE_ALE3_NQ], G1[3 * VLBE_ALE3_NQ];
    vlbe_real Gu[3 * VLBE_ALE3_NQ], W[3 * VLBE_ALE3_NQ], rho2 = VLBE_R(0.0), rho = VLBE_R(0.0);
    const vlbe_real *G = Gr;
    int a, c, j, k, l;
    if ((mom && ch->el3 && !ch->spin) || (m3 && !ch->el3)) return VLBE_EARG;
    if (ch->el3) vlbe_herm_ale_eval(pp[0], qe[nb - 1], qe[ne - 1], 1, 2, &b);
    else vlbe__ale_chain_basis(ch, e, pp[0], qe[nb - 1], qe[ne - 1], 1, 2, &b);
    vlbe__ale_ld_field(d, nb, &b, 0, qe, r, Gr);
    if (slope) vlbe__ale_ld_field(d, nb, &b, 1, qe, r1, G1);
    for (c = 0; c < 9; ++c) dfr[c] = dfv[c] = VLBE_R(0.0);
    if (ld->fun) { /* the value at the point's position and velocity */
        vlbe_real rd[3] = {0, 0, 0};
        for (c = 0; c < d; ++c) {
            for (a = 0; a < ne; ++a) rd[c] += Gr[c * ne + a] * ve[a];
            if (move) rd[c] += r1[c] * pp[1];
        }
        if (ld->fun(ld->user, t, r, rd, f, jac ? dfr : NULL, jac ? dfv : NULL))
            return VLBE_ECALLBACK;
        if (!vlbe_all_finite(f, nc) || !vlbe_all_finite(dfr, 9) || !vlbe_all_finite(dfv, 9))
            return VLBE_ENONFINITE;
    } else {
        for (c = 0; c < nc; ++c) f[c] = ld->f[c];
    }
    if (mom && !ch->el3) { /* dphi/dr' = (-y', x')/|r'|^2 */
        rho2 = r1[0] * r1[0] + r1[1] * r1[1];
        if (!(rho2 > VLBE_R(0.0))) return VLBE_ESINGULAR;
        g[0] = -r1[1] / rho2;
        g[1] = r1[0] / rho2;
        for (a = 0; a < ne; ++a) Gu[a] = g[0] * G1[a] + g[1] * G1[ne + a];
        G = Gu;
    } else if (mom) {
        vlbe__ale_ld_spin(d, nb, &b, qe, Gu, f[0], s, NULL);
        G = Gu;
    } else if (m3) { /* G = [r' x] dr'/dq / |r'|^2 + r' dtheta/dq / |r'| */
        rho2 = vlbe_v3_dot(r1, r1);
        rho = vlbe_sqrt(rho2);
        if (!(rho2 > VLBE_R(0.0))) return VLBE_ESINGULAR;
        if (ch->spin) vlbe__ale_ld_spin(d, nb, &b, qe, W, VLBE_R(0.0), s, NULL);
        else
            for (a = 0; a < ne; ++a) W[a] = VLBE_R(0.0);
        for (a = 0; a < ne; ++a) {
            const vlbe_real x0 = G1[a], x1 = G1[ne + a], x2 = G1[2 * ne + a], th = W[a] / rho;
            Gu[a] = (r1[1] * x2 - r1[2] * x1) / rho2 + r1[0] * th;
            Gu[ne + a] = (r1[2] * x0 - r1[0] * x2) / rho2 + r1[1] * th;
            Gu[2 * ne + a] = (r1[0] * x1 - r1[1] * x0) / rho2 + r1[2] * th;
        }
        G = Gu;
    }
    for (a = 0; a < ne; ++a) {
        vlbe_real x = VLBE_R(0.0);
        for (c = 0; c < nc; ++c) x += G[c * ne + a] * f[c];
        Qe[a] = s * x;
    }
    if (!jac) return VLBE_OK;
    if (Ke) {
        for (a = 0; a < ne * ne; ++a) Ke[a] = VLBE_R(0.0);
        if (!mom && !m3) {
            vlbe__ale_ld_hess(d, nb, &b, 0, qe, f, s, Ke);
        } else if (mom && !ch->el3) { /* M (G1^T A G1 + g . d^2 r'/dq^2), A = d^2 phi/dr'^2 */
            const vlbe_real x = r1[0], y = r1[1], i4 = VLBE_R(1.0) / (rho2 * rho2);
            const vlbe_real axx = VLBE_R(2.0) * x * y * i4, axy = (y * y - x * x) * i4;
            vlbe__ale_ld_hess(d, nb, &b, 1, qe, g, s * f[0], Ke);
            for (a = 0; a < ne; ++a) {
                W[a] = axx * G1[a] + axy * G1[ne + a];
                W[ne + a] = axy * G1[a] - axx * G1[ne + a];
            }
            vlbe__ale_ld_gtb(2, ne, G1, W, s * f[0], Ke);
        } else if (m3) {
            /* bending: a = (M x r')/|r'|^2, K += a . d^2 r'/dq^2 + G1^T da/dr' G1,
               da/dr' = [M x]/|r'|^2 - 2 a r'^T/|r'|^2 */
            vlbe_real av[3], A3[9], bm = VLBE_R(0.0), bs[3];
            vlbe_v3_cross(f, r1, av);
            for (c = 0; c < 3; ++c) av[c] /= rho2;
            A3[0] = A3[4] = A3[8] = VLBE_R(0.0);
            A3[1] = -f[2] / rho2;
            A3[2] = f[1] / rho2;
            A3[3] = f[2] / rho2;
            A3[5] = -f[0] / rho2;
            A3[6] = -f[1] / rho2;
            A3[7] = f[0] / rho2;
            for (c = 0; c < 3; ++c)
                for (j = 0; j < 3; ++j) A3[c * 3 + j] -= VLBE_R(2.0) * av[c] * r1[j] / rho2;
            vlbe__ale_ld_hess(d, nb, &b, 1, qe, av, s, Ke);
            for (c = 0; c < 3; ++c)
                for (a = 0; a < ne; ++a)
                    W[c * ne + a] = A3[c * 3] * G1[a] + A3[c * 3 + 1] * G1[ne + a] +
                                    A3[c * 3 + 2] * G1[2 * ne + a];
            vlbe__ale_ld_gtb(3, ne, G1, W, s, Ke);
            if (ch->spin) { /* axial part bm = M . r'/|r'| on theta (eq. 46) */
                bm = vlbe_v3_dot(f, r1) / rho;
                for (c = 0; c < 3; ++c) bs[c] = f[c] / rho - bm * r1[c] / rho2;
                vlbe__ale_ld_spin(d, nb, &b, qe, W, bm, s, Ke); /* W: dtheta/dq */
                for (a = 0; a < ne; ++a)
                    W[ne + a] = bs[0] * G1[a] + bs[1] * G1[ne + a] + bs[2] * G1[2 * ne + a];
                vlbe__ale_ld_gtb(1, ne, W, W + ne, s, Ke);
            }
        } else {
            vlbe__ale_ld_spin(d, nb, &b, qe, Gu, f[0], s, Ke);
        }
    }
    if (De) {
        for (a = 0; a < ne * ne; ++a) De[a] = VLBE_R(0.0);
        if (ld->fun) { /* df/drd dr/dv: rd = N v + r' p' */
            for (c = 0; c < nc; ++c)
                for (a = 0; a < ne; ++a) {
                    vlbe_real x = VLBE_R(0.0);
                    for (j = 0; j < d; ++j) x += dfv[c * d + j] * Gr[j * ne + a];
                    W[c * ne + a] = x;
                }
            vlbe__ale_ld_gtb(nc, ne, G, W, s, De);
        }
    }
    if (Ke && ld->fun) { /* df/dr dr/dq + df/drd drd/dq */
        vlbe_real Grd[3 * VLBE_ALE3_NQ];
        for (c = 0; c < d; ++c) {
            for (a = 0; a < ne; ++a) Grd[c * ne + a] = move ? pp[1] * G1[c * ne + a] : VLBE_R(0.0);
            for (j = 0; j < 4; ++j) { /* d(N v)/dq: N depends on p1, p2, and on e through dr/dp_k */
                const int o = vlbe__ale_lso(d, nb, j) + c;
                for (k = 0; k < 2; ++k) {
                    const int pk = nb * k + nb - 1;
                    Grd[c * ne + o] += b.h[0][1 + k][j] * ve[pk];
                    Grd[c * ne + pk] += b.h[0][1 + k][j] * ve[o];
                    for (l = 0; l < 2; ++l)
                        Grd[c * ne + nb * l + nb - 1] += b.h[0][dd[k][l]][j] * qe[o] * ve[pk];
                }
            }
        }
        for (c = 0; c < nc; ++c)
            for (a = 0; a < ne; ++a) {
                vlbe_real x = VLBE_R(0.0);
                for (j = 0; j < d; ++j)
                    x += dfr[c * d + j] * Gr[j * ne + a] + dfv[c * d + j] * Grd[j * ne + a];
                W[c * ne + a] = x;
            }
        vlbe__ale_ld_gtb(nc, ne, G, W, s, Ke);
    }
    return VLBE_OK;
}

/* records a failure of point load k (element e, -1: none): as
   vlbe__ale_fail, but a load off the chain is fatal (-1, vlbe_dae's table) */
VLBE_INLINE int vlbe__ale_load_fail(vlbe_ale_chain *ch, vlbe_status st, int e, int k)
{
    const int rc = vlbe__ale_fail(ch, st, e);
    ch->err_load = k;
    return st == VLBE_EBOUND ? -1 : rc;
}

/* Checks every point load before anything is written: its data, a finite
   load factor, its place on the chain at (q, t).  0 or the callback's
   failure value. */
VLBE_INLINE int vlbe__ale_loads_check(vlbe_ale_chain *ch, vlbe_real t, const vlbe_real *q)
{
    int k, e;
    vlbe_real pp[2];
    vlbe_status st;
    if (!isfinite(ch->load_factor)) return vlbe__ale_fail(ch, VLBE_ENONFINITE, -1);
    if (ch->nloads < 0 || (ch->nloads > 0 && !ch->loads)) return vlbe__ale_fail(ch, VLBE_EARG, -1);
    for (k = 0; k < ch->nloads; ++k)
        if ((st = vlbe__ale_load_ok(ch, &ch->loads[k])) != VLBE_OK ||
            (st = vlbe__ale_load_at(ch, &ch->loads[k], t, q, pp, &e)) != VLBE_OK)
            return vlbe__ale_load_fail(ch, st, -1, k);
    return 0;
}

/* Q and/or K, D (the chain's matrices: n x n, or band arrays; any of the three
   may be NULL) */
VLBE_INLINE int vlbe__ale_chain_forces(vlbe_ale_chain *ch, vlbe_real t, const vlbe_real *q,
                                         const vlbe_real *v, vlbe_real *Q, vlbe_real *K,
                                         vlbe_real *D)
{
    vlbe_real qe[VLBE_ALE3_NQ], ve[VLBE_ALE3_NQ], Qe[VLBE_ALE3_NQ], ae[VLBE_ALE3_NQ];
    vlbe_real Ke[VLBE_ALE3_NQ * VLBE_ALE3_NQ], De[VLBE_ALE3_NQ * VLBE_ALE3_NQ];
    size_t map[2 * VLBE_ALE3_NQ];
    int e, i, k, rc, ne, idx[VLBE_ALE3_NQ];
    unsigned md;
    vlbe_status st;
    VLBE_ASSERT(ch != NULL && q != NULL && v != NULL);
    ne = vlbe__ale_ne(ch);
    if ((rc = vlbe__ale_in_check(ch, q, v, NULL)) != 0) return rc;
    if (ch->nloads && (rc = vlbe__ale_loads_check(ch, t, q)) != 0) return rc;
    if (Q)
        for (i = 0; i < ch->n; ++i) Q[i] = VLBE_R(0.0);
    if (K) vlbe__ale_zero_mat(ch, K);
    if (D) vlbe__ale_zero_mat(ch, D);
    for (e = 0; e + 1 < ch->nn; ++e) {
        if ((st = vlbe__ale_gather(ch, e, t, q, v, qe, ve, idx, &md)) != VLBE_OK ||
            (st = vlbe__ale_el_force(ch, e, md, qe, ve, Qe, K ? Ke : NULL, D ? De : NULL)) != VLBE_OK)
            return vlbe__ale_fail(ch, st, e);
        if (vlbe__ale_pres_acc(ch, e, t, ae)) {
            /* inertia of the prescribed p'': Q -= M ae, K -= d(M ae)/dq */
            vlbe_real Me[VLBE_ALE3_NQ * VLBE_ALE3_NQ], Mq[VLBE_ALE3_NQ * VLBE_ALE3_NQ];
            if ((st = vlbe__ale_el_mass(ch, e, md, qe, Me)) != VLBE_OK) return vlbe__ale_fail(ch, st, e);
            for (i = 0; i < ne; ++i)
                for (k = 0; k < ne; ++k) Qe[i] -= Me[i * ne + k] * ae[k];
            if (K) {
                if ((st = vlbe__ale_el_mass_jac(ch, e, md, qe, ae, Mq)) != VLBE_OK)
                    return vlbe__ale_fail(ch, st, e);
                for (i = 0; i < ne * ne; ++i) Ke[i] -= Mq[i];
            }
        }
        if (Q)
            for (i = 0; i < ne; ++i)
                if (idx[i] >= 0) Q[idx[i]] += Qe[i];
        vlbe__ale_scatter(ch, ne, idx, map, Ke, K, De, D);
    }
    for (k = 0; k < ch->nloads; ++k) { /* point loads, on their elements */
        vlbe_real pp[2];
        if ((st = vlbe__ale_load_at(ch, &ch->loads[k], t, q, pp, &e)) != VLBE_OK)
            return vlbe__ale_load_fail(ch, st, -1, k);
        if (e < 0) continue; /* outside, and allowed to be */
        if ((st = vlbe__ale_gather(ch, e, t, q, v, qe, ve, idx, &md)) != VLBE_OK ||
            (st = vlbe__ale_load_elem(ch, &ch->loads[k], e, t, pp, qe, ve, Qe, K ? Ke : NULL,
                                      D ? De : NULL)) != VLBE_OK)
            return vlbe__ale_load_fail(ch, st, e, k);
        if (Q)
            for (i = 0; i < ne; ++i)
                if (idx[i] >= 0) Q[idx[i]] += Qe[i];
        vlbe__ale_scatter(ch, ne, idx, map, Ke, K, De, D);
    }
    if ((K && !vlbe__ale_band_finite(ch, K)) || (D && !vlbe__ale_band_finite(ch, D)))
        return vlbe__ale_fail(ch, VLBE_ENONFINITE, -1);
    if (Q) {
        for (i = 0; i < ch->nn; ++i)
            for (k = 0; k < ch->d; ++k)
                Q[ch->node[i].ofs + k] += ch->node[i].mass * ch->g[k] * ch->load_factor;
        if (!vlbe_all_finite(Q, ch->n)) return vlbe__ale_fail(ch, VLBE_ENONFINITE, -1);
    }
    return 0;
}

VLBE_API int vlbe_ale_chain_force(void *user, vlbe_real t, const vlbe_real *q, const vlbe_real *v,
                                  vlbe_real *Q)
{
    VLBE_ASSERT(Q != NULL);
    return vlbe__ale_chain_forces((vlbe_ale_chain *)user, t, q, v, Q, NULL, NULL);
}

VLBE_API int vlbe_ale_chain_force_jac(void *user, vlbe_real t, const vlbe_real *q,
                                      const vlbe_real *v, vlbe_real *K, vlbe_real *D)
{
    return vlbe__ale_chain_forces((vlbe_ale_chain *)user, t, q, v, NULL, K, D);
}

VLBE_API int vlbe_ale_chain_mass_jac(void *user, vlbe_real t, const vlbe_real *q,
                                     const vlbe_real *v, const vlbe_real *a, vlbe_real *Mq,
                                     vlbe_real *Mv)
{
    vlbe_ale_chain *ch = (vlbe_ale_chain *)user;
    vlbe_real qe[VLBE_ALE3_NQ], ae[VLBE_ALE3_NQ], Je[VLBE_ALE3_NQ * VLBE_ALE3_NQ];
    size_t map[2 * VLBE_ALE3_NQ];
    int e, i, rc, ne, idx[VLBE_ALE3_NQ];
    unsigned md;
    vlbe_status st;
    (void)v;
    VLBE_ASSERT(ch != NULL && q != NULL && a != NULL && Mq != NULL);
    ne = vlbe__ale_ne(ch);
    if ((rc = vlbe__ale_in_check(ch, q, NULL, a)) != 0) return rc;
    vlbe__ale_zero_mat(ch, Mq);
    if (Mv) vlbe__ale_zero_mat(ch, Mv);
    for (e = 0; e + 1 < ch->nn; ++e) {
        if ((st = vlbe__ale_gather(ch, e, t, q, NULL, qe, NULL, idx, &md)) != VLBE_OK)
            return vlbe__ale_fail(ch, st, e);
        for (i = 0; i < ne; ++i) ae[i] = idx[i] >= 0 ? a[idx[i]] : VLBE_R(0.0);
        if ((st = vlbe__ale_el_mass_jac(ch, e, md, qe, ae, Je)) != VLBE_OK)
            return vlbe__ale_fail(ch, st, e);
        vlbe__ale_scatter(ch, ne, idx, map, Je, Mq, NULL, NULL);
    }
    return vlbe__ale_band_finite(ch, Mq) ? 0 : vlbe__ale_fail(ch, VLBE_ENONFINITE, -1);
}

/* known p (and its rates) of node i for the equal-length constraint */
VLBE_INLINE vlbe_status vlbe__ale_eql_end(const vlbe_ale_chain *ch, int i, vlbe_real t,
                                            const vlbe_real *q, vlbe_real *p3, int *col)
{
    *col = vlbe__ale_pidx(ch, i);
    return vlbe_ale_chain_pnode(ch, i, t, q, NULL, p3);
}

/* a, a', a'' at t of the angle of the VLBE_ALE_CON_SLOPE_ANGLE or
   VLBE_ALE_CON_SLOPE_ROT constraint k: the chain's afun, or its law */
VLBE_INLINE vlbe_status vlbe__ale_law(const vlbe_ale_chain *ch, int k, vlbe_real t,
                                        vlbe_real *a3)
{
    const vlbe_ale_con *c = &ch->con[k];
    if (ch->afun) {
        if (ch->afun(ch->user, k, t, a3)) return VLBE_ECALLBACK;
        if (!vlbe_all_finite(a3, 3)) return VLBE_ENONFINITE;
    } else {
        vlbe__law(c->law[0], c->law[1], c->law[2], t, a3);
    }
    return VLBE_OK;
}

/* a, a', a'' of the VLBE_ALE_CON_SLOPE_ANGLE constraint k at t, and the
   slope s = r' it acts on: cs = [cos a, sin a], w = [a', a''], the index of
   the slope in q. */
VLBE_INLINE vlbe_status vlbe__ale_angle(const vlbe_ale_chain *ch, int k, vlbe_real t,
                                          vlbe_real *cs, vlbe_real *w, int *s)
{
    const vlbe_ale_con *c = &ch->con[k];
    vlbe_real a3[3];
    vlbe_status st;
    if ((st = vlbe__ale_law(ch, k, t, a3)) != VLBE_OK) return st;
    cs[0] = vlbe_cos(a3[0]);
    cs[1] = vlbe_sin(a3[0]);
    w[0] = a3[1];
    w[1] = a3[2];
    *s = vlbe__ale_sidx(ch, c->node, c->which);
    return VLBE_OK;
}

/* The rows of the 3D slope-direction constraint k (VLBE_ALE_CON_SLOPE_DIR
   or _SLOPE_ROT) at t: B = [b1, b2] (rows of C_q on the slope s, C = B s)
   and, for SLOPE_ROT, kB = dB/da = k x B and kkB = k x (k x B) (zero for
   SLOPE_DIR), w = [a', a''].  SLOPE_ROT: b_j = R(k, a) b_j0 with b_j0 the
   pair across e0 (vlbe__ale_perp) and R x = x cos a + (k x x) sin a + k (k.x)
   (1 - cos a) (Rodrigues, k unit); dR x / da = k x R x, so C_t = a' kB s
   and C_tt = a'' kB s + a'^2 kkB s.  add and layout have checked d and axis. */
VLBE_INLINE vlbe_status vlbe__ale_dir3(const vlbe_ale_chain *ch, int k, vlbe_real t,
                                         vlbe_real *B, vlbe_real *kB, vlbe_real *kkB,
                                         vlbe_real *w)
{
    const vlbe_ale_con *c = &ch->con[k];
    vlbe_real b0[6] = {0, 0, 0, 0, 0, 0}, u[3] = {0, 0, 0}, a3[3], ca, sa, x[3];
    int j, i;
    vlbe_status st;
    (void)vlbe__ale_perp(c->d, b0);
    if (c->type != VLBE_ALE_CON_SLOPE_ROT) {
        for (i = 0; i < 6; ++i) {
            B[i] = b0[i];
            kB[i] = kkB[i] = VLBE_R(0.0);
        }
        w[0] = w[1] = VLBE_R(0.0);
        return VLBE_OK;
    }
    if ((st = vlbe__ale_law(ch, k, t, a3)) != VLBE_OK) return st;
    (void)vlbe__ale_unit(3, c->axis, u);
    ca = vlbe_cos(a3[0]);
    sa = vlbe_sin(a3[0]);
    for (j = 0; j < 2; ++j) {
        const vlbe_real *b = b0 + 3 * j, ub = vlbe_v3_dot(u, b) * (VLBE_R(1.0) - ca);
        vlbe_v3_cross(u, b, x);
        for (i = 0; i < 3; ++i) B[3 * j + i] = b[i] * ca + x[i] * sa + u[i] * ub;
        vlbe_v3_cross(u, B + 3 * j, kB + 3 * j);
        vlbe_v3_cross(u, kB + 3 * j, kkB + 3 * j);
    }
    w[0] = a3[1];
    w[1] = a3[2];
    return VLBE_OK;
}

/* Constraint rows: C (may be NULL), Cq (m x n, or the band array in banded
   mode; may be NULL), Ct. */
VLBE_INLINE vlbe_status vlbe__ale_chain_con(const vlbe_ale_chain *ch, vlbe_real t,
                                              const vlbe_real *q, vlbe_real *C, vlbe_real *Cq,
                                              vlbe_real *Ct)
{
    const size_t nm = ch->order ? vlbe_ale_chain_mat_len(ch) : (size_t)ch->n * (size_t)ch->m;
    size_t iz;
    int k, r = 0, i, b;
    vlbe_status st;
    if (Cq)
        for (iz = 0; iz < nm; ++iz) Cq[iz] = VLBE_R(0.0);
    for (k = 0; k < ch->ncon; ++k) {
        const vlbe_ale_con *c = &ch->con[k];
        const int o = ch->node[c->node].ofs;
        switch (c->type) {
        case VLBE_ALE_CON_POS: {
            int j = 0; /* row of the next held component */
            for (b = 0; b < ch->d; ++b) {
                if (c->which && !((c->which >> b) & 1)) continue;
                if (C) C[r + j] = q[o + b] - c->r[b];
                if (Cq) Cq[vlbe__ale_cq_at(ch, r + j, o + b)] = VLBE_R(1.0);
                if (Ct) Ct[r + j] = VLBE_R(0.0);
                ++j;
            }
        } break;
        case VLBE_ALE_CON_SLOPE: {
            const int s = vlbe__ale_sidx(ch, c->node, c->which);
            for (b = 0; b < ch->d; ++b) {
                if (C) C[r + b] = q[s + b] - c->d[b];
                if (Cq) Cq[vlbe__ale_cq_at(ch, r + b, s + b)] = VLBE_R(1.0);
                if (Ct) Ct[r + b] = VLBE_R(0.0);
            }
        } break;
        case VLBE_ALE_CON_SLOPE_DIR:
        case VLBE_ALE_CON_SLOPE_ROT: {
            const int s = vlbe__ale_sidx(ch, c->node, c->which);
            vlbe_real B[6], kB[6], kkB[6], w[2];
            if (ch->d == 2) { /* planar SLOPE_DIR: r' x d */
                if (C) C[r] = q[s] * c->d[1] - q[s + 1] * c->d[0];
                if (Cq) {
                    Cq[vlbe__ale_cq_at(ch, r, s)] = c->d[1];
                    Cq[vlbe__ale_cq_at(ch, r, s + 1)] = -c->d[0];
                }
                if (Ct) Ct[r] = VLBE_R(0.0);
                break;
            }
            if ((st = vlbe__ale_dir3(ch, k, t, B, kB, kkB, w)) != VLBE_OK) return st;
            for (b = 0; b < 2; ++b) { /* C = b_j . r', C_t = a' (k x b_j) . r' */
                if (C) C[r + b] = vlbe_v3_dot(B + 3 * b, q + s);
                if (Cq)
                    for (i = 0; i < 3; ++i) Cq[vlbe__ale_cq_at(ch, r + b, s + i)] = B[3 * b + i];
                if (Ct) Ct[r + b] = w[0] * vlbe_v3_dot(kB + 3 * b, q + s);
            }
        } break;
        case VLBE_ALE_CON_SLOPE_ANGLE: { /* C = r' x e(a) = x' sin a - y' cos a */
            vlbe_real cs[2], w[2];
            int s;
            if ((st = vlbe__ale_angle(ch, k, t, cs, w, &s)) != VLBE_OK) return st;
            if (C) C[r] = q[s] * cs[1] - q[s + 1] * cs[0];
            if (Cq) {
                Cq[vlbe__ale_cq_at(ch, r, s)] = cs[1];
                Cq[vlbe__ale_cq_at(ch, r, s + 1)] = -cs[0];
            }
            if (Ct) Ct[r] = w[0] * (q[s] * cs[0] + q[s + 1] * cs[1]);
        } break;
        case VLBE_ALE_CON_P:
        case VLBE_ALE_CON_SPIN: {
            const int pi = c->type == VLBE_ALE_CON_P ? vlbe__ale_pidx(ch, c->node)
                                                     : vlbe__ale_tidx(ch, c->node);
            if (C) C[r] = q[pi] - c->law[0] - (c->law[1] + VLBE_R(0.5) * c->law[2] * t) * t;
            if (Cq) Cq[vlbe__ale_cq_at(ch, r, pi)] = VLBE_R(1.0);
            if (Ct) Ct[r] = -(c->law[1] + c->law[2] * t);
        } break;
        case VLBE_ALE_CON_EQUAL_LEN: {
            const int a = c->node, z = c->node2;
            vlbe_real pa[3], pz[3];
            int ca, cz;
            if ((st = vlbe__ale_eql_end(ch, a, t, q, pa, &ca)) != VLBE_OK) return st;
            if ((st = vlbe__ale_eql_end(ch, z, t, q, pz, &cz)) != VLBE_OK) return st;
            for (i = a + 1; i < z; ++i) {
                const vlbe_real al = (vlbe_real)(z - i) / (vlbe_real)(z - a);
                const vlbe_real be = (vlbe_real)(i - a) / (vlbe_real)(z - a);
                const int ri = r + i - a - 1;
                if (C) C[ri] = q[vlbe__ale_pidx(ch, i)] - al * pa[0] - be * pz[0];
                if (Cq) {
                    Cq[vlbe__ale_cq_at(ch, ri, vlbe__ale_pidx(ch, i))] = VLBE_R(1.0);
                    if (ca >= 0) Cq[vlbe__ale_cq_at(ch, ri, ca)] = -al;
                    if (cz >= 0) Cq[vlbe__ale_cq_at(ch, ri, cz)] = -be;
                }
                if (Ct) Ct[ri] = -(ca >= 0 ? VLBE_R(0.0) : al * pa[1]) - (cz >= 0 ? VLBE_R(0.0) : be * pz[1]);
            }
        } break;
        case VLBE_ALE_CON_SLIDE_C:
            for (b = 0; b < 2; ++b) {
                if (C) C[r + b] = q[o + 2 + b] - q[o + 4 + b];
                if (Cq) {
                    Cq[vlbe__ale_cq_at(ch, r + b, o + 2 + b)] = VLBE_R(1.0);
                    Cq[vlbe__ale_cq_at(ch, r + b, o + 4 + b)] = VLBE_R(-1.0);
                }
                if (Ct) Ct[r + b] = VLBE_R(0.0);
            }
            break;
        case VLBE_ALE_CON_SLIDE_D: {
            const vlbe_real na = vlbe_v2_norm(q + o + 2), nb = vlbe_v2_norm(q + o + 4);
            if (!(na > VLBE_R(0.0)) || !(nb > VLBE_R(0.0))) return VLBE_ESINGULAR;
            if (C) C[r] = na - nb;
            if (Cq)
                for (b = 0; b < 2; ++b) {
                    Cq[vlbe__ale_cq_at(ch, r, o + 2 + b)] = q[o + 2 + b] / na;
                    Cq[vlbe__ale_cq_at(ch, r, o + 4 + b)] = -q[o + 4 + b] / nb;
                }
            if (Ct) Ct[r] = VLBE_R(0.0);
        } break;
        default: return VLBE_EARG;
        }
        r += vlbe__ale_con_rows(ch, c);
    }
    return VLBE_OK;
}

VLBE_API int vlbe_ale_chain_constr(void *user, vlbe_real t, const vlbe_real *q, vlbe_real *C)
{
    vlbe_ale_chain *ch = (vlbe_ale_chain *)user;
    vlbe_status st;
    VLBE_ASSERT(ch != NULL && q != NULL && C != NULL);
    if (!vlbe_all_finite(q, ch->n)) return vlbe__ale_fail(ch, VLBE_ENONFINITE, -1);
    st = vlbe__ale_chain_con(ch, t, q, C, NULL, NULL);
    if (st == VLBE_OK && !vlbe_all_finite(C, ch->m)) st = VLBE_ENONFINITE;
    return st ? vlbe__ale_fail(ch, st, -1) : 0;
}

/* (Cq's entries are finite for finite q: +-1, the constraints' values
   (checked by add and layout), cos and sin, unit vectors, slopes over
   their norms, al, be) */
VLBE_API int vlbe_ale_chain_constr_jac(void *user, vlbe_real t, const vlbe_real *q, vlbe_real *Cq,
                                       vlbe_real *Ct)
{
    vlbe_ale_chain *ch = (vlbe_ale_chain *)user;
    vlbe_status st;
    VLBE_ASSERT(ch != NULL && q != NULL && Cq != NULL);
    if (!vlbe_all_finite(q, ch->n)) return vlbe__ale_fail(ch, VLBE_ENONFINITE, -1);
    st = vlbe__ale_chain_con(ch, t, q, NULL, Cq, Ct);
    if (st == VLBE_OK && Ct && !vlbe_all_finite(Ct, ch->m)) st = VLBE_ENONFINITE;
    return st ? vlbe__ale_fail(ch, st, -1) : 0;
}

/* gamma = -((C_q v)_q v + 2 C_qt v + C_tt): nonzero for prescribed p (p''),
   equal lengths with prescribed ends, the |r'(1)| = |r'(2)| constraint and
   a turning slope direction (SLOPE_ANGLE, SLOPE_ROT). */
VLBE_API int vlbe_ale_chain_constr_acc(void *user, vlbe_real t, const vlbe_real *q,
                                       const vlbe_real *v, vlbe_real *gamma)
{
    vlbe_ale_chain *ch = (vlbe_ale_chain *)user;
    int k, r = 0, i;
    vlbe_status st;
    VLBE_ASSERT(ch != NULL && q != NULL && v != NULL && gamma != NULL);
    if (!vlbe_all_finite(q, ch->n) || !vlbe_all_finite(v, ch->n))
        return vlbe__ale_fail(ch, VLBE_ENONFINITE, -1);
    for (k = 0; k < ch->ncon; ++k) {
        const vlbe_ale_con *c = &ch->con[k];
        const int rows = vlbe__ale_con_rows(ch, c), o = ch->node[c->node].ofs;
        for (i = 0; i < rows; ++i) gamma[r + i] = VLBE_R(0.0);
        if (c->type == VLBE_ALE_CON_P || c->type == VLBE_ALE_CON_SPIN) {
            gamma[r] = c->law[2];
        } else if (c->type == VLBE_ALE_CON_EQUAL_LEN) {
            vlbe_real pa[3], pz[3];
            int ca, cz;
            if ((st = vlbe__ale_eql_end(ch, c->node, t, q, pa, &ca)) != VLBE_OK ||
                (st = vlbe__ale_eql_end(ch, c->node2, t, q, pz, &cz)) != VLBE_OK)
                return vlbe__ale_fail(ch, st, -1);
            for (i = c->node + 1; i < c->node2; ++i) {
                const vlbe_real al = (vlbe_real)(c->node2 - i) / (vlbe_real)(c->node2 - c->node);
                gamma[r + i - c->node - 1] = (ca >= 0 ? VLBE_R(0.0) : al * pa[2]) +
                                             (cz >= 0 ? VLBE_R(0.0) : (VLBE_R(1.0) - al) * pz[2]);
            }
        } else if (c->type == VLBE_ALE_CON_SLIDE_D) {
            /* d2|a|/dt2 at fixed a'' = (|a'|^2 - (a.a')^2/|a|^2)/|a| */
            vlbe_real g = VLBE_R(0.0);
            int s;
            for (s = 0; s < 2; ++s) {
                const vlbe_real *a = q + o + 2 + 2 * s, *ad = v + o + 2 + 2 * s;
                const vlbe_real na = vlbe_v2_norm(a), d = vlbe_v2_dot(a, ad);
                if (!(na > VLBE_R(0.0))) return vlbe__ale_fail(ch, VLBE_ESINGULAR, c->node);
                g += (s ? VLBE_R(-1.0) : VLBE_R(1.0)) * (vlbe_v2_dot(ad, ad) - d * d / (na * na)) / na;
            }
            gamma[r] = -g;
        } else if (c->type == VLBE_ALE_CON_SLOPE_ROT) {
            /* C = B(a) s: gamma = -(2 a' kB s' + a'' kB s + a'^2 kkB s) */
            vlbe_real B[6], kB[6], kkB[6], w[2];
            const int s = vlbe__ale_sidx(ch, c->node, c->which);
            if ((st = vlbe__ale_dir3(ch, k, t, B, kB, kkB, w)) != VLBE_OK)
                return vlbe__ale_fail(ch, st, -1);
            for (i = 0; i < 2; ++i)
                gamma[r + i] = -(VLBE_R(2.0) * w[0] * vlbe_v3_dot(kB + 3 * i, v + s) +
                                 w[1] * vlbe_v3_dot(kB + 3 * i, q + s) +
                                 w[0] * w[0] * vlbe_v3_dot(kkB + 3 * i, q + s));
        } else if (c->type == VLBE_ALE_CON_SLOPE_ANGLE) {
            /* C = s x e(a): C_qt v = a' (s'.e), C_tt = a'' (s.e) - a'^2 (s x e) */
            vlbe_real cs[2], w[2];
            int s;
            if ((st = vlbe__ale_angle(ch, k, t, cs, w, &s)) != VLBE_OK) return vlbe__ale_fail(ch, st, -1);
            gamma[r] = -(VLBE_R(2.0) * w[0] * (v[s] * cs[0] + v[s + 1] * cs[1]) +
                         w[1] * (q[s] * cs[0] + q[s + 1] * cs[1]) -
                         w[0] * w[0] * (q[s] * cs[1] - q[s + 1] * cs[0]));
        }
        r += rows;
    }
    return vlbe_all_finite(gamma, ch->m) ? 0 : vlbe__ale_fail(ch, VLBE_ENONFINITE, -1);
}

/* H = d(C_q^T lambda)/dq: only the |r'| constraint is nonlinear (the
   others, SLOPE_ROT included, are linear in q: H = 0 for them). */
VLBE_API int vlbe_ale_chain_constr_hess(void *user, vlbe_real t, const vlbe_real *q,
                                        const vlbe_real *lambda, vlbe_real *H)
{
    vlbe_ale_chain *ch = (vlbe_ale_chain *)user;
    int k, r = 0, i, j, s;
    (void)t;
    VLBE_ASSERT(ch != NULL && q != NULL && lambda != NULL && H != NULL);
    if (!vlbe_all_finite(q, ch->n) || !vlbe_all_finite(lambda, ch->m))
        return vlbe__ale_fail(ch, VLBE_ENONFINITE, -1);
    vlbe__ale_zero_mat(ch, H);
    for (k = 0; k < ch->ncon; ++k) {
        const vlbe_ale_con *c = &ch->con[k];
        if (c->type == VLBE_ALE_CON_SLIDE_D) {
            const int o = ch->node[c->node].ofs;
            for (s = 0; s < 2; ++s) {
                const vlbe_real *a = q + o + 2 + 2 * s, na = vlbe_v2_norm(a);
                const vlbe_real f = (s ? -lambda[r] : lambda[r]) / na;
                const int b = o + 2 + 2 * s;
                if (!(na > VLBE_R(0.0))) return vlbe__ale_fail(ch, VLBE_ESINGULAR, c->node);
                for (i = 0; i < 2; ++i)
                    for (j = 0; j < 2; ++j) {
                        vlbe_real *h = &H[vlbe_ale_chain_at(ch, b + i, b + j)];
                        *h += f * ((i == j ? VLBE_R(1.0) : VLBE_R(0.0)) - a[i] * a[j] / (na * na));
                        if (!isfinite(*h)) return vlbe__ale_fail(ch, VLBE_ENONFINITE, c->node);
                    }
            }
        }
        r += vlbe__ale_con_rows(ch, c);
    }
    return 0;
}

VLBE_API vlbe_status vlbe_ale_chain_dae(vlbe_ale_chain *ch, vlbe_dae *sys)
{
    int i;
    VLBE_ASSERT(ch != NULL && sys != NULL);
    if (ch->n < 1) return VLBE_EARG; /* not laid out */
    memset(sys, 0, sizeof *sys);
    sys->n = ch->n;
    sys->m = ch->m;
    sys->user = ch;
    sys->mass = vlbe_ale_chain_mass;
    sys->force = vlbe_ale_chain_force;
    sys->force_jac = vlbe_ale_chain_force_jac;
    sys->mass_jac = vlbe_ale_chain_mass_jac;
    sys->constr = vlbe_ale_chain_constr;
    sys->constr_jac = vlbe_ale_chain_constr_jac;
    sys->constr_acc = vlbe_ale_chain_constr_acc;
    sys->constr_hess = vlbe_ale_chain_constr_hess;
    for (i = 0; i < ch->nn && ch->node[i].pmode == VLBE_ALE_PFIXED; ++i) continue;
    if (ch->d == 2 && i == ch->nn) sys->flags |= VLBE_DAE_MASS_CONST;
    if (ch->order) {
        sys->storage = VLBE_DAE_BANDED;
        sys->kl = ch->kl;
        sys->ku = ch->ku;
        sys->order = ch->order;
    }
    return VLBE_OK;
}

/* ===== segmentation, merging, length control ============================ */
/* The new node at ph from the basis b evaluated there (k <= 1, the
   element's own basis): qh = [r(ph), r'(ph), ph] and, with qd and qhd, the
   rates of a node moving with the material, [v(ph), v'(ph), 0]; written
   only when all are finite (shared with rancf.h). */
VLBE_INLINE vlbe_status vlbe__ale_split_node(const vlbe_herm_ale *b, const vlbe_real *q,
                                             const vlbe_real *qd, vlbe_real ph, vlbe_real *qh,
                                             vlbe_real *qhd)
{
    vlbe_real h[4], hd[4];
    int k;
    for (k = 0; k < 2; ++k) { /* k = 0: r, k = 1: r' */
        vlbe__ale_sum(b, k, 0, q, h + 2 * k);
        if (qd && qhd) vlbe__ale_mat_rate(b, k, q, qd, hd + 2 * k);
    }
    if (!vlbe_all_finite(h, 4) || (qd && qhd && !vlbe_all_finite(hd, 4)))
        return VLBE_ENONFINITE;
    for (k = 0; k < 4; ++k) qh[k] = h[k];
    qh[4] = ph;
    if (qd && qhd) {
        for (k = 0; k < 4; ++k) qhd[k] = hd[k];
        qhd[4] = VLBE_R(0.0);
    }
    return VLBE_OK;
}

/* Exact segmentation (cubic subdivision) of an element at the material point
   ph in (p1, p2): the new node H gets qh = [r(ph), r'(ph), ph] and, when qd
   is given, the rates of a node that moves with the material (p_H' = 0):
   qhd = [v(ph), v'(ph), 0] with v = N q' the material velocity (eq. 14).  The
   elements [node 1, H] and [H, node 2] describe exactly the same curve and
   material parametrisation as the original (a cubic is determined by its
   values and slopes at two points), so positions, strains and energies are
   unchanged.  ph outside (p1, p2): VLBE_EBOUND. */
VLBE_API vlbe_status vlbe_ale_split(const vlbe_real *q, const vlbe_real *qd, vlbe_real ph,
                                    vlbe_real *VLBE_RESTRICT qh, vlbe_real *VLBE_RESTRICT qhd)
{
    vlbe_herm_ale b;
    vlbe_status st;
    VLBE_ASSERT(q != NULL && qh != NULL);
    if ((st = vlbe__ale_check(q, qd)) != VLBE_OK) return st;
    if (!isfinite(ph)) return VLBE_ENONFINITE;
    if (!(ph > q[4] && ph < q[9])) return VLBE_EBOUND;
    vlbe_herm_ale_eval(ph, q[4], q[9], 1, 1, &b);
    return vlbe__ale_split_node(&b, q, qd, ph, qh, qhd);
}

VLBE_INLINE int vlbe__ale_ncoord(const vlbe_ale_node *nd)
{
    return 4 + 2 * nd->slide + (nd->pmode == VLBE_ALE_PFREE);
}

/* copy nc coordinates from offset o of (q, v) to offset on of (qn, vn);
   forward copy, so in place is fine when on <= o */
VLBE_INLINE void vlbe__ale_copy_node(const vlbe_real *q, const vlbe_real *v, int o, int nc,
                                       vlbe_real *qn, vlbe_real *vn, int on)
{
    int k;
    for (k = 0; k < nc; ++k) {
        qn[on + k] = q[o + k];
        if (v && vn) vn[on + k] = v[o + k];
    }
}

/* does a constraint name node i (or an equal-length group contain it)? */
VLBE_INLINE int vlbe__ale_constrained(const vlbe_ale_chain *ch, int i)
{
    int k;
    for (k = 0; k < ch->ncon; ++k) {
        const vlbe_ale_con *c = &ch->con[k];
        if (c->node == i || (c->type == VLBE_ALE_CON_EQUAL_LEN && i >= c->node && i <= c->node2))
            return 1;
    }
    return 0;
}

/* Insert a node with a fixed material coordinate ph inside element e
   (between nodes e and e+1) by exact segmentation; (q, v) of the old layout
   map to (qn, vn) of the new one (qn, vn must not alias q, v; v and vn may
   be NULL).  Constraints on later nodes are renumbered and the layout is
   run (in banded mode: order, kl, ku too).  Needs nn < nn_cap and, in
   banded mode, order_cap >= n + m + 4 (else VLBE_EWORK); qn, vn hold
   ch->n + 4 reals.  VLBE_EARG when the new layout's matrices would not fit
   in a size_t; an element inside an equal-length group
   (VLBE_ALE_CON_EQUAL_LEN) cannot be split (VLBE_EARG); e outside [0,
   nn - 1) or a 3D chain: VLBE_EARG; the errors of vlbe_ale_chain_gather
   and of the split (ph outside (p1, p2): VLBE_EBOUND; a non-finite new
   node: VLBE_ENONFINITE).  On failure nothing changes. */
VLBE_API vlbe_status vlbe_ale_chain_insert(vlbe_ale_chain *ch, int e, vlbe_real ph, vlbe_real t,
                                           const vlbe_real *q, const vlbe_real *v,
                                           vlbe_real *qn, vlbe_real *vn)
{
    vlbe_real qe[10], ve[10] = {0}, qh[5], qhd[5] = {0}, aux[VLBE_ALE_ETYPE_AUX];
    int idx[10], i, k, on;
    unsigned md;
    vlbe_status st;
    VLBE_ASSERT(ch != NULL && q != NULL && qn != NULL);
    if (ch->el3) return VLBE_EARG; /* planar chains only */
    if (e < 0 || e >= ch->nn - 1 || ch->n > INT_MAX - 4) return VLBE_EARG;
    for (k = 0; k < ch->ncon; ++k) { /* a fixed node inside an equally spaced group: no */
        const vlbe_ale_con *c = &ch->con[k];
        if (c->type == VLBE_ALE_CON_EQUAL_LEN && e >= c->node && e < c->node2) return VLBE_EARG;
    }
    if (ch->nn >= ch->nn_cap) return VLBE_EWORK;
    /* the layout that ends the insertion: 4 coordinates more, the same rows */
    if ((st = vlbe__ale_size_ok(ch, 2, ch->n + 4, ch->m)) != VLBE_OK) return st;
    if ((st = vlbe__ale_gather(ch, e, t, q, v, qe, v ? ve : NULL, idx, &md)) != VLBE_OK)
        return st;
    st = ch->et ? ch->et->split(ch->els, e, qe, v ? ve : NULL, ph, qh, v ? qhd : NULL, aux)
                : vlbe_ale_split(qe, v ? ve : NULL, ph, qh, v ? qhd : NULL);
    if (st != VLBE_OK) return st;
    if (!vlbe_all_finite(qh, 5) || !vlbe_all_finite(qhd, 5)) return VLBE_ENONFINITE;
    if (ch->et) ch->et->commit(ch->els, ch->nn - 1, e, 1, aux);
    /* shift nodes e+1.. up by one; their ofs still name the old layout */
    for (i = ch->nn; i > e + 1; --i) ch->node[i] = ch->node[i - 1];
    ch->node[e + 1].pmode = VLBE_ALE_PFIXED;
    ch->node[e + 1].slide = 0;
    ch->node[e + 1].p = ph;
    ch->node[e + 1].pd = ch->node[e + 1].pdd = VLBE_R(0.0);
    ch->node[e + 1].mass = VLBE_R(0.0);
    ch->nn++;
    for (k = 0; k < ch->ncon; ++k) {
        vlbe_ale_con *c = &ch->con[k];
        if (c->node > e) c->node++;
        if (c->type == VLBE_ALE_CON_EQUAL_LEN && c->node2 > e) c->node2++;
    }
    on = 0;
    for (i = 0; i < ch->nn; ++i) {
        const int nc = vlbe__ale_ncoord(&ch->node[i]);
        if (i == e + 1) {
            for (k = 0; k < 4; ++k) {
                qn[on + k] = qh[k];
                if (v && vn) vn[on + k] = qhd[k];
            }
        } else {
            vlbe__ale_copy_node(q, v, ch->node[i].ofs, nc, qn, vn, on);
        }
        on += nc;
    }
    return vlbe_ale_chain_layout(ch);
}

/* the per-element types' merge at node i (elements i-1 and i), from the
   nodes [r, r', p] of both elements */
VLBE_INLINE vlbe_status vlbe__ale_merge_aux(const vlbe_ale_chain *ch, int i, vlbe_real t,
                                              const vlbe_real *q, vlbe_real *aux)
{
    vlbe_real qa[10], qb[10];
    int idx[10];
    unsigned md;
    vlbe_status st;
    if ((st = vlbe__ale_gather(ch, i - 1, t, q, NULL, qa, NULL, idx, &md)) != VLBE_OK ||
        (st = vlbe__ale_gather(ch, i, t, q, NULL, qb, NULL, idx, &md)) != VLBE_OK)
        return st;
    return ch->et->merge(ch->els, i - 1, qa, qa + 5, qb + 5, aux);
}

/* Remove interior node i, merging elements i-1 and i into one between the
   neighbours, whose coordinates stay as they are (eq. 29 of [R]).  The
   merged cubic is the Hermite interpolant of the outer nodes; it differs
   from the two pieces unless they form one cubic, by the interpolation
   error of the removed node (the caller measures the change of positions
   and energy when it matters; scenes/ex_slide.h reports it).  A chain
   with per-element types (vlbe_ale_etype) asks its merge for the merged
   element (rancf.h: weights through the removed node, eqs. 30-38); t is
   the time of q (prescribed material coordinates).  Node i must carry no
   mass and no constraint, not be sliding and not belong to an equal-length
   group (else VLBE_EARG, nothing changed).  q -> qn may be in place (qn ==
   q, vn == v).  The layout is run (in banded mode: order, kl, ku too);
   its errors are found before anything changes. */
/* The removal itself, node i checked; aux: the merge of the per-element
   types (vlbe__ale_merge_aux), unused without them. */
VLBE_INLINE vlbe_status vlbe__ale_chain_remove(vlbe_ale_chain *ch, int i, const vlbe_real *q,
                                                 const vlbe_real *v, vlbe_real *qn, vlbe_real *vn,
                                                 const vlbe_real *aux)
{
    int k, j, on;
    if (ch->et) ch->et->commit(ch->els, ch->nn - 1, i - 1, -1, aux);
    on = 0;
    for (j = 0; j < ch->nn; ++j) {
        const int nc = vlbe__ale_ncoord(&ch->node[j]);
        if (j == i) continue;
        vlbe__ale_copy_node(q, v, ch->node[j].ofs, nc, qn, vn, on);
        on += nc;
    }
    for (j = i; j + 1 < ch->nn; ++j) ch->node[j] = ch->node[j + 1];
    ch->nn--;
    for (k = 0; k < ch->ncon; ++k) {
        vlbe_ale_con *c = &ch->con[k];
        if (c->node > i) c->node--;
        if (c->type == VLBE_ALE_CON_EQUAL_LEN && c->node2 > i) c->node2--;
    }
    return vlbe_ale_chain_layout(ch);
}

VLBE_API vlbe_status vlbe_ale_chain_remove(vlbe_ale_chain *ch, int i, vlbe_real t,
                                           const vlbe_real *q, const vlbe_real *v, vlbe_real *qn,
                                           vlbe_real *vn)
{
    vlbe_real aux[VLBE_ALE_ETYPE_AUX] = {0};
    VLBE_ASSERT(ch != NULL && q != NULL && qn != NULL);
    if (ch->el3 || i <= 0 || i >= ch->nn - 1 || ch->nn <= 2) return VLBE_EARG;
    if (ch->node[i].slide || ch->node[i].mass != VLBE_R(0.0) || vlbe__ale_constrained(ch, i))
        return VLBE_EARG;
    { /* the layout that ends the removal (order_cap may have changed since the last) */
        const int n1 = ch->n - vlbe__ale_ncoord(&ch->node[i]);
        const vlbe_status st = vlbe__ale_size_ok(ch, 2, n1, ch->m);
        if (st != VLBE_OK) return st;
    }
    if (ch->et) {
        const vlbe_status st = vlbe__ale_merge_aux(ch, i, t, q, aux);
        if (st != VLBE_OK) return st;
    }
    return vlbe__ale_chain_remove(ch, i, q, v, qn, vn, aux);
}

/* may node i be removed by length control? */
VLBE_INLINE int vlbe__ale_removable(const vlbe_ale_chain *ch, int i)
{
    if (i <= 0 || i >= ch->nn - 1 || ch->node[i].slide || ch->node[i].mass != VLBE_R(0.0) ||
        ch->node[i].pmode == VLBE_ALE_PFREE)
        return 0;
    return !vlbe__ale_constrained(ch, i);
}

/* Length control of a sliding node (Figure 7 of [R]), keeping the two
   elements next to node *slider between 0.5 and 1.5 Lstd (arguments: the
   chain; the inputs Lstd, t, q, v; the node *slider, in and out; the
   outputs qn, vn, *changed):
   (a) the paper's rule: when the element on one side is longer than
       1.5 Lstd, insert a node at distance Lstd from that element's far node
       (the new element away from the slider has length Lstd) and remove the
       slider's neighbour on the other side (merging the two elements
       there), so the number of nodes and coordinates stays the same;
   (b) its complement, for a start that is not in the paper's steady state
       (a node ahead of the slider that rule (a) would never remove, e.g. a
       sliding node placed next to a chain end): when the element on one
       side is shorter than 0.5 Lstd and its far node is removable, remove
       that node, and, if the element on the other side is at least Lstd
       long, insert a node in it at distance min(Lstd, length - 0.5 Lstd)
       from its far node (both pieces then at least 0.5 Lstd).  In the
       steady state (the two lengths summing to 2 Lstd) (a) and (b) fire
       together and make the same change.
   Near a chain end, where no removable node is on the other side, only the
   insertion is made (needs capacity); removable means interior, fixed p, no
   mass, no constraint, not in an equal-length group.  The insertion is
   made first: it needs nn < nn_cap and, in banded mode, order_cap >= n +
   m + 4 (else VLBE_EWORK, nothing changed) and qn, vn must hold ch->n + 4
   reals; the layout is run after every change.  (q, v) -> (qn, vn) in the new layout
   (copied unchanged when nothing is done; qn, vn must not alias q, v); *slider
   follows its node; *changed = 0 (nothing), 1 (inserted), 2 (inserted and
   removed), 3 (removed).  Restart the integrator from (qn, vn) when
   *changed != 0.  A slider at a chain end (0 or nn - 1): nothing done.
   Errors: VLBE_EARG for *slider outside [0, nn), a 3D chain, or Lstd not
   finite or with 0.5 Lstd <= max(0, ch->Lmin) (the control would make
   elements the callbacks refuse); the errors of vlbe_ale_chain_pnode,
   _insert and _remove.  On failure nothing changes: the chain, its nodes,
   constraints and element objects, qn, vn, *slider and *changed. */
VLBE_API vlbe_status vlbe_ale_chain_length_control(vlbe_ale_chain *ch, vlbe_real Lstd, vlbe_real t,
                                                   const vlbe_real *q, const vlbe_real *v,
                                                   int *slider, vlbe_real *qn, vlbe_real *vn,
                                                   int *changed)
{
    vlbe_real pl[3], ps[3], pr[3], Ll = VLBE_R(0.0), Lr = VLBE_R(0.0), at,
        aux[VLBE_ALE_ETYPE_AUX] = {0};
    const vlbe_real lo = VLBE_R(0.5) * Lstd, hi = VLBE_R(1.5) * Lstd;
    int s, side = 0, ins, k;
    vlbe_status st;
    VLBE_ASSERT(ch != NULL && slider != NULL && q != NULL && qn != NULL && changed != NULL);
    s = *slider;
    if (ch->el3 || s < 0 || s >= ch->nn || !isfinite(Lstd) || !(lo > VLBE_R(0.0)) ||
        !(lo > ch->Lmin))
        return VLBE_EARG;
    if (s > 0 && s < ch->nn - 1) {
        if ((st = vlbe_ale_chain_pnode(ch, s - 1, t, q, v, pl)) != VLBE_OK ||
            (st = vlbe_ale_chain_pnode(ch, s, t, q, v, ps)) != VLBE_OK ||
            (st = vlbe_ale_chain_pnode(ch, s + 1, t, q, v, pr)) != VLBE_OK)
            return st;
        Ll = ps[0] - pl[0];
        Lr = pr[0] - ps[0];
        /* side -1: work on the left element (insert there, remove on the right) */
        if (Ll > hi || (Lr < lo && vlbe__ale_removable(ch, s + 1))) side = -1;
        else if (Lr > hi || (Ll < lo && vlbe__ale_removable(ch, s - 1))) side = 1;
    }
    if (!side) {
        for (k = 0; k < ch->n; ++k) {
            qn[k] = q[k];
            if (v && vn) vn[k] = v[k];
        }
        *changed = 0;
        return VLBE_OK;
    }
    if (side < 0) {
        ins = Ll >= Lstd;
        at = pl[0] + (Ll - lo < Lstd ? Ll - lo : Lstd);
    } else {
        ins = Lr >= Lstd;
        at = pr[0] - (Lr - lo < Lstd ? Lr - lo : Lstd);
    }
    if (ins && ch->et) { /* the merge that follows the insertion, made before it: a
                            failure changes nothing; the two elements it joins are on
                            the other side of the slider, the insertion leaves them */
        const int i = side < 0 ? s + 1 : s - 1; /* before the insertion */
        if (vlbe__ale_removable(ch, i) && (st = vlbe__ale_merge_aux(ch, i, t, q, aux)) != VLBE_OK)
            return st;
    }
    /* *slider and *changed are written only after the change succeeded (the
       removal after an insertion cannot fail: its merge is made above) */
    if (!ins) { /* rule (b) only: remove the far node of the short element */
        const int i = s - side; /* s + 1 when side = -1, s - 1 when side = 1 */
        if ((st = vlbe_ale_chain_remove(ch, i, t, q, v, qn, vn)) != VLBE_OK) return st;
        if (side > 0) *slider = s - 1;
        *changed = 3;
        return VLBE_OK;
    }
    if (side < 0) { /* new node in element s-1; the slider becomes s+1 */
        if ((st = vlbe_ale_chain_insert(ch, s - 1, at, t, q, v, qn, vn)) != VLBE_OK) return st;
        *slider = s + 1;
        *changed = 1;
        if (vlbe__ale_removable(ch, s + 2)) {
            *changed = 2;
            return vlbe__ale_chain_remove(ch, s + 2, qn, vn, qn, vn, aux);
        }
    } else { /* new node in element s; the slider keeps its index */
        if ((st = vlbe_ale_chain_insert(ch, s, at, t, q, v, qn, vn)) != VLBE_OK) return st;
        *changed = 1;
        if (vlbe__ale_removable(ch, s - 1)) {
            *changed = 2;
            *slider = s - 1;
            return vlbe__ale_chain_remove(ch, s - 1, qn, vn, qn, vn, aux);
        }
    }
    return VLBE_OK;
}

#endif /* VLBE_ANCF_ALE_H */
