/* ancf_ale.h -- planar ALE-ANCF variable-length beam element (VLBE of Hong &
   Ren as used by Ding & Ouyang): shape and ALE matrices, mass, transport
   inertia, axial and bending viscoelastic forces, loads, analytic Jacobians
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
   Gauss orders per term (init; 0 = default): nm for mass, transport inertia
   and loads (default 4, exact: the integrands are polynomials of degree 6
   in xi), nl for the axial force (default 5, exact: degree 8), nt for the
   bending force (default 5; its integrand is rational).  At most
   VLBE_ALE_NGP_MAX points per term.

   Errors: VLBE_ELENGTH when L = p2 - p1 <= 0; VLBE_ENONFINITE for NaN/Inf in
   q or q'; VLBE_ESINGULAR when the slope vanishes (|r'|^2 <= eps) at a
   bending point (the curvature is undefined there); VLBE_EBOUND when a
   point load lies outside [p1, p2].  On failure no output is written.
   Stack: an eval call uses about 3 kB (local Q, K, D, so that a failure
   writes nothing).  vlbe_ale_elem is about 15 kB: make one per material,
   not per element.

NOTES (how the Jacobians are formed)
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
} vlbe_ale_gp;

typedef struct vlbe_ale_rule {
    int n;
    vlbe_ale_gp g[VLBE_ALE_NGP_MAX];
} vlbe_ale_rule;

/* An element type: material, default mode flags, a rule per term and the
   two element ends (xi = 0, 1; w unused) for the energy fluxes. */
typedef struct vlbe_ale_elem {
    vlbe_ale_mat mat;
    unsigned flags;
    vlbe_ale_rule rm, rl, rt; /* mass/inertia/loads, axial, bending */
    vlbe_ale_gp ends[2];
} vlbe_ale_elem;

/* -- API prototypes ----------------------------------------------------- */
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

/* ===== implementation =================================================== */

/* index in q of basis j's 2-vector (0, 2, 5, 7), the power m_j of L it
   carries, and the index of p_{k+1} */
#define VLBE__ALE_E(j) ((j) * 2 + ((j) >= 2 ? 1 : 0))
#define VLBE__ALE_M(j) ((j) & 1)
#define VLBE__ALE_P(k) (4 + 5 * (k))

static inline void vlbe__ale_gp_fill(vlbe_ale_gp *gp, vlbe_real xi, vlbe_real w)
{
    vlbe_herm_ale b;
    int k, a, j;
    gp->xi = xi;
    gp->w = w;
    vlbe_herm_ale_eval(xi, VLBE_R(0.0), VLBE_R(1.0), 2, 2, &b);
    for (k = 0; k < 3; ++k)
        for (a = 0; a < VLBE_DA_N; ++a)
            for (j = 0; j < 4; ++j) gp->b[k][a][j] = (k == 0 || a < 3) ? b.h[k][a][j] : VLBE_R(0.0);
}

static inline vlbe_status vlbe__ale_rule(vlbe_ale_rule *r, int n, int ndef)
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

VLBE_API vlbe_status vlbe_ale_elem_init(vlbe_ale_elem *el, const vlbe_ale_mat *mat,
                                        unsigned flags, int nm, int nl, int nt)
{
    vlbe_status st;
    VLBE_ASSERT(el != NULL && mat != NULL);
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
    /* nothing can fail below: el is written only now */
    if ((st = vlbe__ale_rule(&el->rm, nm, 4)) != VLBE_OK) return st;
    if ((st = vlbe__ale_rule(&el->rl, nl, 5)) != VLBE_OK) return st;
    if ((st = vlbe__ale_rule(&el->rt, nt, 5)) != VLBE_OK) return st;
    vlbe__ale_gp_fill(&el->ends[0], VLBE_R(0.0), VLBE_R(0.0));
    vlbe__ale_gp_fill(&el->ends[1], VLBE_R(1.0), VLBE_R(0.0));
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

/* kmax: highest p-derivative needed; amax0 = 2: second p1/p2 partials at
   k = 0 too (transport terms); u (may be NULL): the rate-like vector to
   contract into V (q' or an acceleration). */
static inline void vlbe__ale_pt_eval(const vlbe_ale_gp *gp, vlbe_real L, int kmax, int amax0,
                                     const vlbe_real *q, const vlbe_real *u,
                                     vlbe__ale_pt *VLBE_RESTRICT pt)
{
    vlbe_real Lp[6]; /* Lp[i] = L^(i - 4) */
    int k, a, j, na;
    Lp[4] = VLBE_R(1.0);
    Lp[5] = L;
    for (k = 3; k >= 0; --k) Lp[k] = Lp[k + 1] / L;
    for (k = 0; k <= kmax; ++k) {
        na = (k == 0 && amax0 == 2) ? VLBE_DA_N : 3;
        for (a = 0; a < na; ++a) {
            const int da = a == 0 ? 0 : (a < 3 ? 1 : 2);
            vlbe_real *x = pt->X[k][a];
            x[0] = x[1] = VLBE_R(0.0);
            for (j = 0; j < 4; ++j) {
                const vlbe_real *e = q + VLBE__ALE_E(j);
                const vlbe_real n = gp->b[k][a][j] * Lp[4 + VLBE__ALE_M(j) - k - da];
                pt->N[k][a][j] = n;
                x[0] += n * e[0];
                x[1] += n * e[1];
            }
            if (u && a < 3) {
                vlbe_real *v = pt->V[k][a];
                v[0] = v[1] = VLBE_R(0.0);
                for (j = 0; j < 4; ++j) {
                    const vlbe_real *ud = u + VLBE__ALE_E(j);
                    v[0] += pt->N[k][a][j] * ud[0];
                    v[1] += pt->N[k][a][j] * ud[1];
                }
            }
        }
    }
}

/* Input checks shared by the eval functions. */
static inline vlbe_status vlbe__ale_check(const vlbe_real *q, const vlbe_real *qd)
{
    if (!vlbe_all_finite(q, VLBE_ALE_NQ)) return VLBE_ENONFINITE;
    if (qd && !vlbe_all_finite(qd, VLBE_ALE_NQ)) return VLBE_ENONFINITE;
    if (!(q[9] - q[4] > VLBE_R(0.0))) return VLBE_ELENGTH;
    return VLBE_OK;
}

/* Which p's are coordinates: bit k set when p_{k+1} is free. */
static inline int vlbe__ale_pmask(unsigned mode)
{
    return ((mode & VLBE_ALE_FIX_P1) ? 0 : 1) | ((mode & VLBE_ALE_FIX_P2) ? 0 : 2);
}

/* Inertia-type term at one point: z the 2-vector field it multiplies and c[j]
   the coefficient with dz/de_j = c_j I (z depends on e through the ALE
   columns only): F += w G^T z and, when J and c are given,
   J[:, e-cols] += w d(G^T z)/de.  G = dr/dq = [N_j I | X_0,1 | X_0,2]. */
static inline void vlbe__ale_gtz(const vlbe__ale_pt *pt, int pm, vlbe_real w, const vlbe_real *z,
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
static inline void vlbe__ale_psi_q(const vlbe__ale_pt *pt, int pm, int ny, const vlbe_real *gy,
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

/* Column (j, b) of psi_qq (the e-column; 10 entries) and the mixed second
   variations mix[k] = d2 psi / de_jb dp_k's non-Hessian part. */
static inline void vlbe__ale_psi_qq_col(const vlbe__ale_pt *pt, int pm, int ny, const vlbe_real *gy,
                                        const vlbe_real *H, int j, int b, vlbe_real *col,
                                        vlbe_real *hc, vlbe_real *mix)
{
    const vlbe_real n1 = pt->N[1][0][j], n2 = ny == 4 ? pt->N[2][0][j] : VLBE_R(0.0);
    int i, k, a, c;
    for (a = 0; a < ny; ++a) hc[a] = n1 * H[a * 4 + b] + (ny == 4 ? n2 * H[a * 4 + 2 + b] : VLBE_R(0.0));
    for (i = 0; i < 4; ++i) {
        const int r = VLBE__ALE_E(i);
        const vlbe_real m1 = pt->N[1][0][i];
        col[r] = m1 * hc[0];
        col[r + 1] = m1 * hc[1];
        if (ny == 4) {
            col[r] += pt->N[2][0][i] * hc[2];
            col[r + 1] += pt->N[2][0][i] * hc[3];
        }
    }
    for (k = 0; k < 2; ++k) {
        vlbe_real v = VLBE_R(0.0);
        mix[k] = pt->N[1][1 + k][j] * gy[b];
        if (ny == 4) mix[k] += pt->N[2][1 + k][j] * gy[2 + b];
        for (c = 0; c < ny; ++c) v += pt->X[1 + c / 2][1 + k][c % 2] * hc[c];
        col[VLBE__ALE_P(k)] = (pm & (1 << k)) ? v + mix[k] : VLBE_R(0.0);
    }
}

/* Strain-type term at one point: psi(y) with gradient gy and Hessian H (ny x
   ny, stored 4 wide).  Q -= w sigma psi_q with sigma = S psi + cS psi';
   with K: the e-columns of -w d(sigma psi_q)/dq; with D: -w cS psi_q psi_q^T.
   pd = (p1', p2') (zero for fixed nodes), yd = material rate of y.
   psq (out, 10): psi_q. */
static inline void vlbe__ale_strain_pt(const vlbe__ale_pt *pt, int pm, int ny, vlbe_real w,
                                       vlbe_real S, vlbe_real cS, vlbe_real psi,
                                       const vlbe_real *gy, const vlbe_real *H,
                                       const vlbe_real *pd, const vlbe_real *yd,
                                       vlbe_real *Q, vlbe_real *K, vlbe_real *D, vlbe_real *psq)
{
    vlbe_real sig, psid = VLBE_R(0.0);
    int i, j, a, b, c;
    vlbe__ale_psi_q(pt, pm, ny, gy, psq);
    if (cS != VLBE_R(0.0))
        for (c = 0; c < ny; ++c) psid += gy[c] * yd[c];
    sig = S * psi + cS * psid;
    for (i = 0; i < 10; ++i) Q[i] -= w * sig * psq[i];
    if (D && cS != VLBE_R(0.0)) {
        const vlbe_real f = w * cS;
        for (i = 0; i < 10; ++i) {
            const vlbe_real fi = f * psq[i];
            if (fi != VLBE_R(0.0))
                for (j = 0; j < 10; ++j) D[i * 10 + j] -= fi * psq[j];
        }
    }
    if (!K) return;
    {
        vlbe_real Hyd[4] = {0, 0, 0, 0};
        if (cS != VLBE_R(0.0))
            for (a = 0; a < ny; ++a)
                for (c = 0; c < ny; ++c) Hyd[a] += H[a * 4 + c] * yd[c];
        for (j = 0; j < 4; ++j) {
            const int cj = VLBE__ALE_E(j);
            const vlbe_real n1 = pt->N[1][0][j], n2 = ny == 4 ? pt->N[2][0][j] : VLBE_R(0.0);
            for (b = 0; b < 2; ++b) {
                vlbe_real hc[4], col[10], mix[2], dsig, dpsid = VLBE_R(0.0);
                vlbe__ale_psi_qq_col(pt, pm, ny, gy, H, j, b, col, hc, mix);
                if (cS != VLBE_R(0.0)) {
                    dpsid = n1 * Hyd[b] + (ny == 4 ? n2 * Hyd[2 + b] : VLBE_R(0.0));
                    dpsid += pd[0] * mix[0] + pd[1] * mix[1];
                }
                dsig = S * psq[cj + b] + cS * dpsid;
                for (i = 0; i < 10; ++i) K[i * 10 + cj + b] -= w * (psq[i] * dsig + sig * col[i]);
            }
        }
    }
}

/* Axial strain at a point: eps, gradient and (constant) Hessian in y. */
static inline vlbe_real vlbe__ale_eps(const vlbe__ale_pt *pt, vlbe_real *gy, vlbe_real *H)
{
    int i;
    gy[0] = pt->X[1][0][0];
    gy[1] = pt->X[1][0][1];
    gy[2] = gy[3] = VLBE_R(0.0);
    if (H) {
        for (i = 0; i < 16; ++i) H[i] = VLBE_R(0.0);
        H[0] = H[5] = VLBE_R(1.0);
    }
    return VLBE_R(0.5) * (vlbe_v2_dot(gy, gy) - VLBE_R(1.0));
}

/* Signed curvature at a point: kap = (r' x r'') |r'|^-3, gradient in
   y = (r', r''), Hessian when H != NULL.  VLBE_ESINGULAR for |r'|^2 <= eps. */
static inline vlbe_status vlbe__ale_kap(const vlbe__ale_pt *pt, vlbe_real *kap, vlbe_real *gy,
                                        vlbe_real *H)
{
    const vlbe_real *r1 = pt->X[1][0], *r2 = pt->X[2][0];
    const vlbe_real gg = vlbe_v2_dot(r1, r1);
    vlbe_real t, g32, k, sy[4], gv[4];
    int a, c;
    if (!(gg > VLBE_EPS)) return VLBE_ESINGULAR;
    t = VLBE_R(1.0) / gg;
    g32 = t * vlbe_sqrt(t);
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
    return VLBE_OK;
}

/* dF = d F for a force of the standard row degrees (1 + m_j on e-rows, 0 on
   p-rows): inertia, loads, bending. */
static inline void vlbe__ale_degree(const vlbe_real *F, vlbe_real *dF)
{
    int j;
    dF[4] = dF[9] = VLBE_R(0.0);
    for (j = 0; j < 4; ++j) {
        const int r = VLBE__ALE_E(j);
        const vlbe_real d = (vlbe_real)(1 + VLBE__ALE_M(j));
        dF[r] = d * F[r];
        dF[r + 1] = d * F[r + 1];
    }
}

/* The p-columns of K = dF/dq from the scaling identity (NOTES):
   L dF/dp2 = dF + sum_slope (K_e e + D_e u) - pd1 D_p1 - pd2 D_p2 and
   dF/dp1 = -dF/dp2, with dF the degree-weighted F, D = dF/du, u the
   rate-like argument (q' for forces; the acceleration a for d(M a)/dq, where
   D = M and pd = (a_p1, a_p2)). */
static inline void vlbe__ale_pcols(vlbe_real L, int pm, const vlbe_real *dF, const vlbe_real *pd,
                                   const vlbe_real *q, const vlbe_real *u, vlbe_real *K,
                                   const vlbe_real *D)
{
    int i, j;
    for (i = 0; i < 10; ++i) {
        const vlbe_real *Ki = K + i * 10, *Di = D + i * 10;
        vlbe_real s = dF[i] - pd[0] * Di[4] - pd[1] * Di[9];
        for (j = 1; j < 4; j += 2) {
            const int cj = VLBE__ALE_E(j);
            s += Ki[cj] * q[cj] + Ki[cj + 1] * q[cj + 1] + Di[cj] * u[cj] + Di[cj + 1] * u[cj + 1];
        }
        s /= L;
        K[i * 10 + 4] = (pm & 1) ? -s : VLBE_R(0.0);
        K[i * 10 + 9] = (pm & 2) ? s : VLBE_R(0.0);
    }
}

/* Energy fluxes through the element ends (VLBE_ALE_CONSERVATIVE): p-rows
   Q_p1 += u(0), Q_p2 -= u(1), u = (EA eps^2 + EI kap^2)/2, their e-columns
   in K, and their degree-weighted part in dQ. */
static inline vlbe_status vlbe__ale_flux(const vlbe_ale_elem *el, int pm, int bend,
                                         const vlbe_real *q, vlbe_real L, vlbe_real *Q,
                                         vlbe_real *K, vlbe_real *dQ)
{
    const vlbe_ale_mat *mt = &el->mat;
    vlbe__ale_pt pt;
    int e, i;
    for (e = 0; e < 2; ++e) {
        const int row = VLBE__ALE_P(e);
        const vlbe_real sgn = e == 0 ? VLBE_R(1.0) : VLBE_R(-1.0);
        vlbe_real gy[4], psq[10], eps, u, du = VLBE_R(0.0);
        if (!(pm & (1 << e))) continue;
        vlbe__ale_pt_eval(&el->ends[e], L, 2, 0, q, NULL, &pt);
        eps = vlbe__ale_eps(&pt, gy, NULL);
        u = VLBE_R(0.5) * mt->EA * eps * eps;
        /* degrees: eps^2 = (a - 1/2)^2 with a = |r'|^2/2 of degree -2 */
        du = -VLBE_R(2.0) * mt->EA * (eps + VLBE_R(0.5)) * eps;
        if (K) {
            vlbe__ale_psi_q(&pt, 0, 2, gy, psq);
            for (i = 0; i < 10; ++i) K[row * 10 + i] += sgn * mt->EA * eps * psq[i];
        }
        if (bend) {
            vlbe_real kap;
            vlbe_status st = vlbe__ale_kap(&pt, &kap, gy, NULL);
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

/* The inertia/load, axial and bending terms: Q always, and K and D when K is
   given (e- and p'-columns directly, then the p-columns by the scaling
   identity).  Q, K, D are the caller's zeroed locals. */
static inline vlbe_status vlbe__ale_forces(const vlbe_ale_elem *el, unsigned mode,
                                           const vlbe_real *q, const vlbe_real *qd,
                                           vlbe_real *Q, vlbe_real *K, vlbe_real *D)
{
    const vlbe_ale_mat *mt = &el->mat;
    const int pm = vlbe__ale_pmask(mode), jac = K != NULL;
    const int damp = !(mode & VLBE_ALE_NO_DAMP);
    const int bend = !(mode & VLBE_ALE_NO_BEND) && mt->EI != VLBE_R(0.0);
    const vlbe_real L = q[9] - q[4];
    vlbe_real pd[2], Ql[10], qb[10], dQ[10], H[16], gy[4], yd[4], psq[10];
    vlbe__ale_pt pt;
    vlbe_status st;
    int g, i, j, k;
    pd[0] = (pm & 1) ? qd[4] : VLBE_R(0.0);
    pd[1] = (pm & 2) ? qd[9] : VLBE_R(0.0);
    for (i = 0; i < 10; ++i) Ql[i] = qb[i] = VLBE_R(0.0);

    /* transport inertia and distributed load: z = f - rhoA r_v (eqs. 15, 19) */
    for (g = 0; g < el->rm.n; ++g) {
        const vlbe_ale_gp *gp = &el->rm.g[g];
        const vlbe_real w = gp->w * L;
        vlbe_real z[2], c[4], dd[4];
        vlbe__ale_pt_eval(gp, L, 0, pm ? 2 : 0, q, qd, &pt);
        z[0] = mt->f[0];
        z[1] = mt->f[1];
        if (pm) {
            for (i = 0; i < 2; ++i)
                z[i] -= mt->rhoA * (VLBE_R(2.0) * (pd[0] * pt.V[0][1][i] + pd[1] * pt.V[0][2][i]) +
                                    pd[0] * pd[0] * pt.X[0][VLBE_DA_11][i] +
                                    VLBE_R(2.0) * pd[0] * pd[1] * pt.X[0][VLBE_DA_12][i] +
                                    pd[1] * pd[1] * pt.X[0][VLBE_DA_22][i]);
            for (j = 0; j < 4; ++j) {
                c[j] = -mt->rhoA * (pd[0] * pd[0] * pt.N[0][VLBE_DA_11][j] +
                                    VLBE_R(2.0) * pd[0] * pd[1] * pt.N[0][VLBE_DA_12][j] +
                                    pd[1] * pd[1] * pt.N[0][VLBE_DA_22][j]);
                dd[j] = -mt->rhoA * VLBE_R(2.0) * (pd[0] * pt.N[0][1][j] + pd[1] * pt.N[0][2][j]);
            }
        }
        vlbe__ale_gtz(&pt, pm, w, z, pm ? c : NULL, Q, K);
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

    /* axial: psi = eps(r') (eqs. 19, 21) */
    if (mt->EA != VLBE_R(0.0))
        for (g = 0; g < el->rl.n; ++g) {
            const vlbe_ale_gp *gp = &el->rl.g[g];
            const vlbe_real w = gp->w * L;
            vlbe_real eps, Qloc[10];
            vlbe__ale_pt_eval(gp, L, 1, 0, q, qd, &pt);
            eps = vlbe__ale_eps(&pt, gy, H);
            for (i = 0; i < 2; ++i)
                yd[i] = pt.V[1][0][i] + pd[0] * pt.X[1][1][i] + pd[1] * pt.X[1][2][i];
            yd[2] = yd[3] = VLBE_R(0.0);
            for (i = 0; i < 10; ++i) Qloc[i] = VLBE_R(0.0);
            vlbe__ale_strain_pt(&pt, pm, 2, w, mt->EA, damp ? mt->c_eps * mt->EA : VLBE_R(0.0),
                                eps, gy, H, pd, yd, Qloc, K, D, psq);
            for (i = 0; i < 10; ++i) {
                Q[i] += Qloc[i];
                Ql[i] += Qloc[i];
                qb[i] += w * VLBE_R(0.5) * mt->EA * psq[i];
            }
        }

    /* bending: psi = kap(r', r'') (eqs. 19, 22 in planar signed form) */
    if (bend)
        for (g = 0; g < el->rt.n; ++g) {
            const vlbe_ale_gp *gp = &el->rt.g[g];
            const vlbe_real w = gp->w * L;
            vlbe_real kap;
            vlbe__ale_pt_eval(gp, L, 2, 0, q, qd, &pt);
            if ((st = vlbe__ale_kap(&pt, &kap, gy, jac ? H : NULL)) != VLBE_OK) return st;
            for (i = 0; i < 2; ++i) {
                yd[i] = pt.V[1][0][i] + pd[0] * pt.X[1][1][i] + pd[1] * pt.X[1][2][i];
                yd[2 + i] = pt.V[2][0][i] + pd[0] * pt.X[2][1][i] + pd[1] * pt.X[2][2][i];
            }
            vlbe__ale_strain_pt(&pt, pm, 4, w, mt->EI, damp ? mt->c_kap * mt->EI : VLBE_R(0.0), kap,
                                gy, H, pd, yd, Q, K, D, psq);
        }

    /* p-columns of K by the scaling identity: standard row degrees for all
       terms, the axial part -4 lower plus 2 for its constant part qb */
    if (jac && pm) {
        vlbe__ale_degree(Q, dQ);
        for (i = 0; i < 10; ++i) dQ[i] += -VLBE_R(4.0) * Ql[i] + VLBE_R(2.0) * qb[i];
    }
    if (mode & VLBE_ALE_CONSERVATIVE)
        if ((st = vlbe__ale_flux(el, pm, bend, q, L, Q, K, jac ? dQ : NULL)) != VLBE_OK) return st;
    if (jac && pm) vlbe__ale_pcols(L, pm, dQ, pd, q, qd, K, D);
    return VLBE_OK;
}

VLBE_API vlbe_status vlbe_ale_force(const vlbe_ale_elem *el, unsigned mode, const vlbe_real *q,
                                    const vlbe_real *qd, vlbe_real *VLBE_RESTRICT Q,
                                    vlbe_real *VLBE_RESTRICT K, vlbe_real *VLBE_RESTRICT D)
{
    vlbe_real Qt[10], Kt[100], Dt[100];
    const int jac = K != NULL || D != NULL;
    vlbe_status st;
    int i;
    VLBE_ASSERT(el != NULL && q != NULL && qd != NULL && Q != NULL);
    mode |= el->flags;
    if ((st = vlbe__ale_check(q, qd)) != VLBE_OK) return st;
    for (i = 0; i < 10; ++i) Qt[i] = VLBE_R(0.0);
    if (jac)
        for (i = 0; i < 100; ++i) Kt[i] = Dt[i] = VLBE_R(0.0);
    st = vlbe__ale_forces(el, mode, q, qd, Qt, jac ? Kt : NULL, jac ? Dt : NULL);
    if (st != VLBE_OK) return st;
    for (i = 0; i < 10; ++i) Q[i] = Qt[i];
    if (K)
        for (i = 0; i < 100; ++i) K[i] = Kt[i];
    if (D)
        for (i = 0; i < 100; ++i) D[i] = Dt[i];
    return VLBE_OK;
}

/* M(q) = rhoA int G^T G dp (eq. 19). */
static inline void vlbe__ale_mass(const vlbe_ale_elem *el, int pm, const vlbe_real *q,
                                  vlbe_real *M)
{
    const vlbe_real L = q[9] - q[4];
    vlbe__ale_pt pt;
    int g, i, j, k, l;
    for (i = 0; i < 100; ++i) M[i] = VLBE_R(0.0);
    for (g = 0; g < el->rm.n; ++g) {
        const vlbe_ale_gp *gp = &el->rm.g[g];
        const vlbe_real w = el->mat.rhoA * gp->w * L;
        vlbe__ale_pt_eval(gp, L, 0, 0, q, NULL, &pt);
        for (i = 0; i < 4; ++i) {
            const int r = VLBE__ALE_E(i);
            const vlbe_real wn = w * pt.N[0][0][i];
            for (j = i; j < 4; ++j) {
                const vlbe_real t = wn * pt.N[0][0][j];
                const int c = VLBE__ALE_E(j);
                M[r * 10 + c] += t;
                M[(r + 1) * 10 + c + 1] += t;
            }
            for (k = 0; k < 2; ++k)
                if (pm & (1 << k)) { /* e-p coupling, stored on the p-row */
                    M[VLBE__ALE_P(k) * 10 + r] += wn * pt.X[0][1 + k][0];
                    M[VLBE__ALE_P(k) * 10 + r + 1] += wn * pt.X[0][1 + k][1];
                }
        }
        for (k = 0; k < 2; ++k)
            for (l = k; l < 2; ++l)
                if ((pm & (1 << k)) && (pm & (1 << l)))
                    M[VLBE__ALE_P(k) * 10 + VLBE__ALE_P(l)] +=
                        w * vlbe_v2_dot(pt.X[0][1 + k], pt.X[0][1 + l]);
    }
    /* e-e blocks and p1-p2 were accumulated for i <= j, the e-p coupling on
       the p-rows: mirror each into its transposed place */
    for (i = 0; i < 10; ++i)
        for (j = 0; j < i; ++j) {
            const int pi = i == 4 || i == 9, pj = j == 4 || j == 9;
            if (pi && !pj)
                M[j * 10 + i] = M[i * 10 + j];
            else
                M[i * 10 + j] = M[j * 10 + i];
        }
}

VLBE_API vlbe_status vlbe_ale_mass(const vlbe_ale_elem *el, unsigned mode, const vlbe_real *q,
                                   vlbe_real *VLBE_RESTRICT M)
{
    vlbe_status st;
    VLBE_ASSERT(el != NULL && q != NULL && M != NULL);
    if ((st = vlbe__ale_check(q, NULL)) != VLBE_OK) return st;
    vlbe__ale_mass(el, vlbe__ale_pmask(mode | el->flags), q, M);
    return VLBE_OK;
}

VLBE_API vlbe_status vlbe_ale_mass_jac(const vlbe_ale_elem *el, unsigned mode, const vlbe_real *q,
                                       const vlbe_real *a, vlbe_real *VLBE_RESTRICT Mq)
{
    vlbe_real M[100], Ma[10], J[100], dF[10], ap[2], L;
    vlbe__ale_pt pt;
    vlbe_status st;
    int g, i, j, pm;
    VLBE_ASSERT(el != NULL && q != NULL && a != NULL && Mq != NULL);
    pm = vlbe__ale_pmask(mode | el->flags);
    if ((st = vlbe__ale_check(q, a)) != VLBE_OK) return st;
    for (i = 0; i < 100; ++i) J[i] = VLBE_R(0.0);
    if (pm) { /* with both p fixed M is constant and J stays zero */
        L = q[9] - q[4];
        ap[0] = (pm & 1) ? a[4] : VLBE_R(0.0);
        ap[1] = (pm & 2) ? a[9] : VLBE_R(0.0);
        for (i = 0; i < 10; ++i) Ma[i] = VLBE_R(0.0);
        for (g = 0; g < el->rm.n; ++g) {
            const vlbe_ale_gp *gp = &el->rm.g[g];
            const vlbe_real w = el->mat.rhoA * gp->w * L;
            vlbe_real z[2], c[4];
            vlbe__ale_pt_eval(gp, L, 0, 0, q, a, &pt);
            for (i = 0; i < 2; ++i) z[i] = pt.V[0][0][i] + ap[0] * pt.X[0][1][i] + ap[1] * pt.X[0][2][i];
            for (j = 0; j < 4; ++j) c[j] = ap[0] * pt.N[0][1][j] + ap[1] * pt.N[0][2][j];
            vlbe__ale_gtz(&pt, pm, w, z, c, Ma, J);
        }
        vlbe__ale_mass(el, pm, q, M);
        vlbe__ale_degree(Ma, dF);
        vlbe__ale_pcols(L, pm, dF, ap, q, a, J, M);
    }
    for (i = 0; i < 100; ++i) Mq[i] = J[i];
    return VLBE_OK;
}

VLBE_API vlbe_status vlbe_ale_energy(const vlbe_ale_elem *el, unsigned mode, const vlbe_real *q,
                                     const vlbe_real *qd, vlbe_real *VLBE_RESTRICT E)
{
    const vlbe_ale_mat *mt = &el->mat;
    vlbe_real L, pd[2], gy[4], T = VLBE_R(0.0), U = VLBE_R(0.0), V = VLBE_R(0.0);
    vlbe__ale_pt pt;
    vlbe_status st;
    int g, i, pm;
    VLBE_ASSERT(el != NULL && q != NULL && qd != NULL && E != NULL);
    mode |= el->flags;
    pm = vlbe__ale_pmask(mode);
    if ((st = vlbe__ale_check(q, qd)) != VLBE_OK) return st;
    L = q[9] - q[4];
    pd[0] = (pm & 1) ? qd[4] : VLBE_R(0.0);
    pd[1] = (pm & 2) ? qd[9] : VLBE_R(0.0);
    for (g = 0; g < el->rm.n; ++g) {
        const vlbe_ale_gp *gp = &el->rm.g[g];
        vlbe_real v[2];
        vlbe__ale_pt_eval(gp, L, 0, 0, q, qd, &pt);
        for (i = 0; i < 2; ++i) v[i] = pt.V[0][0][i] + pd[0] * pt.X[0][1][i] + pd[1] * pt.X[0][2][i];
        T += gp->w * L * VLBE_R(0.5) * mt->rhoA * vlbe_v2_dot(v, v);
        V -= gp->w * L * vlbe_v2_dot(mt->f, pt.X[0][0]);
    }
    for (g = 0; g < el->rl.n; ++g) {
        vlbe_real eps;
        vlbe__ale_pt_eval(&el->rl.g[g], L, 1, 0, q, NULL, &pt);
        eps = vlbe__ale_eps(&pt, gy, NULL);
        U += el->rl.g[g].w * L * VLBE_R(0.5) * mt->EA * eps * eps;
    }
    if (!(mode & VLBE_ALE_NO_BEND) && mt->EI != VLBE_R(0.0))
        for (g = 0; g < el->rt.n; ++g) {
            vlbe_real kap;
            vlbe__ale_pt_eval(&el->rt.g[g], L, 2, 0, q, NULL, &pt);
            if ((st = vlbe__ale_kap(&pt, &kap, gy, NULL)) != VLBE_OK) return st;
            U += el->rt.g[g].w * L * VLBE_R(0.5) * mt->EI * kap * kap;
        }
    E[0] = T;
    E[1] = U;
    E[2] = V;
    return VLBE_OK;
}

/* r(p) and r'(p) of one element (either may be NULL); p may lie outside
   [p1, p2] (the cubic is extrapolated). */
VLBE_API vlbe_status vlbe_ale_point(const vlbe_real *q, vlbe_real p, vlbe_real *VLBE_RESTRICT r,
                                    vlbe_real *VLBE_RESTRICT rp)
{
    vlbe_herm_ale b;
    vlbe_status st;
    int j;
    VLBE_ASSERT(q != NULL);
    if ((st = vlbe__ale_check(q, NULL)) != VLBE_OK) return st;
    if (!vlbe_all_finite(&p, 1)) return VLBE_ENONFINITE;
    vlbe_herm_ale_eval(p, q[4], q[9], 1, 0, &b);
    if (r) r[0] = r[1] = VLBE_R(0.0);
    if (rp) rp[0] = rp[1] = VLBE_R(0.0);
    for (j = 0; j < 4; ++j) {
        const vlbe_real *e = q + VLBE__ALE_E(j);
        if (r) vlbe_v2_axpy(b.h[0][0][j], e, r);
        if (rp) vlbe_v2_axpy(b.h[1][0][j], e, rp);
    }
    return VLBE_OK;
}

/* Green strain and signed curvature at material point p (either output may
   be NULL; the curvature needs |r'|^2 > eps). */
VLBE_API vlbe_status vlbe_ale_strain(const vlbe_real *q, vlbe_real p, vlbe_real *VLBE_RESTRICT eps,
                                     vlbe_real *VLBE_RESTRICT kap)
{
    vlbe_herm_ale b;
    vlbe_real r1[2] = {0, 0}, r2[2] = {0, 0}, gg;
    vlbe_status st;
    int j;
    VLBE_ASSERT(q != NULL);
    if ((st = vlbe__ale_check(q, NULL)) != VLBE_OK) return st;
    if (!vlbe_all_finite(&p, 1)) return VLBE_ENONFINITE;
    vlbe_herm_ale_eval(p, q[4], q[9], 2, 0, &b);
    for (j = 0; j < 4; ++j) {
        const vlbe_real *e = q + VLBE__ALE_E(j);
        vlbe_v2_axpy(b.h[1][0][j], e, r1);
        vlbe_v2_axpy(b.h[2][0][j], e, r2);
    }
    gg = vlbe_v2_dot(r1, r1);
    if (kap && !(gg > VLBE_EPS)) return VLBE_ESINGULAR;
    if (eps) *eps = VLBE_R(0.5) * (gg - VLBE_R(1.0));
    if (kap) *kap = vlbe_v2_cross(r1, r2) / (gg * vlbe_sqrt(gg));
    return VLBE_OK;
}

/* A constant global force F at the material point pf in [p1, p2]:
   Q += N(pf)^T F (planar eq. 45 of [V]), K += d/dq (K may be NULL).  All ten
   rows and columns are written, whatever the element's mode. */
VLBE_API vlbe_status vlbe_ale_point_force(const vlbe_real *q, vlbe_real pf, const vlbe_real *F,
                                          vlbe_real *VLBE_RESTRICT Q, vlbe_real *VLBE_RESTRICT K)
{
    static const int dd[2][2] = {{VLBE_DA_11, VLBE_DA_12}, {VLBE_DA_12, VLBE_DA_22}};
    vlbe_herm_ale b;
    vlbe_real a[2][2] = {{0, 0}, {0, 0}};
    vlbe_status st;
    int j, k, l;
    VLBE_ASSERT(q != NULL && F != NULL && Q != NULL);
    if ((st = vlbe__ale_check(q, NULL)) != VLBE_OK) return st;
    if (!vlbe_all_finite(&pf, 1) || !vlbe_all_finite(F, 2)) return VLBE_ENONFINITE;
    if (pf < q[4] || pf > q[9]) return VLBE_EBOUND;
    vlbe_herm_ale_eval(pf, q[4], q[9], 0, 2, &b);
    for (j = 0; j < 4; ++j) {
        const vlbe_real *e = q + VLBE__ALE_E(j);
        const int r = VLBE__ALE_E(j);
        Q[r] += b.h[0][0][j] * F[0];
        Q[r + 1] += b.h[0][0][j] * F[1];
        for (k = 0; k < 2; ++k) vlbe_v2_axpy(b.h[0][1 + k][j], e, a[k]);
    }
    for (k = 0; k < 2; ++k) Q[VLBE__ALE_P(k)] += vlbe_v2_dot(a[k], F);
    if (!K) return VLBE_OK;
    for (j = 0; j < 4; ++j) {
        const int c = VLBE__ALE_E(j);
        for (k = 0; k < 2; ++k) {
            const int pk = VLBE__ALE_P(k);
            const vlbe_real h = b.h[0][1 + k][j];
            K[c * 10 + pk] += h * F[0];
            K[(c + 1) * 10 + pk] += h * F[1];
            K[pk * 10 + c] += h * F[0];
            K[pk * 10 + c + 1] += h * F[1];
        }
    }
    for (k = 0; k < 2; ++k)
        for (l = 0; l < 2; ++l) {
            vlbe_real s = VLBE_R(0.0);
            for (j = 0; j < 4; ++j) s += b.h[0][dd[k][l]][j] * vlbe_v2_dot(q + VLBE__ALE_E(j), F);
            K[VLBE__ALE_P(k) * 10 + VLBE__ALE_P(l)] += s;
        }
    return VLBE_OK;
}

#endif /* VLBE_ANCF_ALE_H */
