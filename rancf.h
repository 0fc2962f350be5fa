/* rancf.h -- rational ANCF: the planar RANCF (fixed length) and ALE-RANCF
   (variable length) beam elements of Ding & Ouyang, rational Bezier <->
   nodal coordinates, exact segmentation by homogeneous de Casteljau,
   least-squares weights for merging, circular-arc elements
   -- part of vlbe v0.1.0                          SPDX-License-Identifier: MIT

USAGE
   #include "rancf.h"       (vlbe.h and ancf_ale.h must sit in the same
                             directory; rancf.h builds on ancf_ale.h)

     vlbe_ale_mat mat = {0};  mat.rhoA = ...; mat.EA = ...; mat.EI = ...;
     const vlbe_real w[4] = {1, w1, w2, 1};           (the element's weights)
     vlbe_rancf_elem el;                              (one per weight set)
     if (vlbe_rancf_elem_init(&el, &mat, w, 0, 0, 0, 0)) fail;
     vlbe_real q[10] = {x1,y1,x1',y1',p1, x2,y2,x2',y2',p2}, qd[10] = ...;
     vlbe_rancf_mass(&el, 0, q, M);
     vlbe_rancf_force(&el, 0, q, qd, Q, K, D);        (K, D may be NULL)

CONFIG
   Nothing beyond vlbe.h.

CONVENTIONS
   Coordinates, mode flags, units, signs, matrix layout and statuses are
   those of the planar element of ancf_ale.h (10 coordinates per element,
   q = [r1, r1', p1, r2, r2', p2], slopes ' = d/dp, M q'' = Q, K = dQ/dq,
   D = dQ/dq').  What differs is the basis: with u = (p - p1)/L, L = p2 -
   p1 (eq. 13), the rational cubic Bezier curve with weights w0..w3 > 0
   (eqs. 1-3) written in the nodal coordinates (eq. 9):
        s1 = (w0 (1-u)^3 + 3 w1 u (1-u)^2) / W,   s2 = L w0 u (1-u)^2 / W,
        s3 = (w3 u^3 + 3 w2 u^2 (1-u)) / W,       s4 = -L w3 u^2 (1-u) / W,
        W  = w0 (1-u)^3 + 3 w1 u (1-u)^2 + 3 w2 u^2 (1-u) + w3 u^3.
   Only the ratios of the weights matter; the element keeps k_i = w_i / w3
   (eq. 33).  Unit weights give the cubic Hermite basis: RANCF is ANCF.
   Weights are attributes of the element, not coordinates (section 2), so
   each function is L^m g(u) with g fixed, exactly as in ancf_ale.h: the
   element reuses every kernel of the planar ALE-ANCF element (mass,
   transport inertia Q_a, axial and bending Kelvin-Voigt forces Q_l, Q_t,
   load Q_g, eqs. 14-19, their analytic Jacobians and the scaling identity
   of its p-columns), with Gauss tables filled from the rational basis.
   vlbe_rancf_elem holds a vlbe_ale_elem (about 16 kB): make one per
   distinct weight set (a chain whose elements carry different weights
   needs one per element).
   Quadrature: the integrands are rational, so no Gauss order is exact;
   the defaults are the planar element's (nm 4, nl 5, nt 5).  The mass
   matrix of an arc element of central angle pi/2 (w1 = 0.805) differs from
   the 8-point one by 1.3e-3, 7.9e-5, 4.6e-6, 2.6e-7 of its largest entry
   at nm = 4, 5, 6, 7 (tests/test_rancf.c, quadrature); a pi/4 arc at the
   defaults: 6e-5 (forces), 1e-4 (mass), 1e-8 at 6/7/7 (bench_rancf.c).
   Pass larger orders to init when a scene needs it.
   VLBE_ALE_CONSERVATIVE: the end fluxes make the p-forces the gradient of
   the element's strain energy only up to the Gauss error of the rational
   integrand (with polynomial integrands, exactly): at the default orders
   1e-5 of the force scale for arc weights, 4e-3 for weights {0.7, 1.3,
   0.9, 1.1} (test_rancf.c, energy_gradient, predicts it).
   Segmentation (vlbe_rancf_split) keeps every material point's position
   and slope; with moving ends (p1' or p2' != 0) the parts' velocity
   fields differ from the original's, because the restriction of the
   original to [p1, ph] would have weights that change with (ph - p1) /
   (p2 - p1), while the parts' weights are constants (7e-3 relative in
   the test); with p' = 0 at both ends they agree to rounding.
   Not available: VLBE_ALE_INV_AXIAL (its invariant tables are those of
   the polynomial basis): every element call with it returns VLBE_EARG.
   Chains: vlbe_rancf_chain_init makes a planar vlbe_ale_chain whose
   element e is els[e] (per-element types, vlbe_ale_etype of ancf_ale.h):
   constraints, sliding nodes, the vlbe_dae callbacks and length control
   are the chain's; an insertion splits exactly (both parts get weights
   by eq. 21), a removal gives the merged element the weights of
   vlbe_rancf_merge.  Those weights put the merged curve through the
   removed node but say nothing of its parametrization: on a nearly
   straight, bent pair they can be far from 1 (0.03..2 in the falling
   beam of the paper's 6.1 with 5 elements), and the strain energy of the
   merged element jumps accordingly (examples/falling_beam.c reports it).
   Bezier form (any dimension d = 1..3): control points P0..P3 (4 d reals)
   and weights; element nodal form x = [rA, rA', rB, rB'] (4 d reals) and
   reference length l, related by eqs. 5-6.
   Errors: as ancf_ale.h, plus VLBE_EWEIGHT for a non-positive or
   non-finite weight, for weights whose smallest is below REAL_MIN (the
   smallest normal number) times the largest (their ratios would
   over/underflow), for weights so uneven that the element's basis
   tables overflow (vlbe_rancf_elem_init) and for a split whose part
   would get a weight that underflows to 0.  Every routine checks its
   outputs before it writes them (VLBE_ENONFINITE when finite input
   overflows); on failure no output is written.

API
   vlbe_status vlbe_rancf_basis_eval(w, p, p1, p2, kmax, amax, b)  rational basis in
                                            ALE form (the struct of vlbe_herm_ale_eval)
   vlbe_status vlbe_rancf_elem_init(el, mat, w, flags, nm, nl, nt)  element type, tables
   vlbe_status vlbe_rancf_mass(el, mode, q, M)              M(q), eq. 19
   vlbe_status vlbe_rancf_mass_jac(el, mode, q, a, Mq)      d(M a)/dq
   vlbe_status vlbe_rancf_force(el, mode, q, qd, Q, K, D)   Q and (optional) K, D
   vlbe_status vlbe_rancf_energy(el, mode, q, qd, E)        E = {T, U, V}
   vlbe_status vlbe_rancf_point(el, q, p, r, rp)            r(p), r'(p)
   vlbe_status vlbe_rancf_strain(el, q, p, eps, kap)        strain, curvature at p
   vlbe_status vlbe_rancf_point_force(el, q, pf, F, Q, K)   Q += N(pf)^T F, K += d/dq
   vlbe_status vlbe_rancf_to_bezier(d, w, l, x, P)          nodal -> control points (eq. 6)
   vlbe_status vlbe_rancf_from_bezier(d, w, l, P, x)        control points -> nodal (eq. 5)
   vlbe_status vlbe_rancf_bezier_eval(d, w, P, u, r)        point of the curve (de Casteljau)
   vlbe_status vlbe_rancf_bezier_split(d, w, P, u, wl, Pl, wr, Pr)  eq. 21
   vlbe_status vlbe_rancf_split(el, q, qd, ph, qh, qhd, wl, wr)  element segmentation at
                                            ph: new node, weights of both parts (eqs. 21-28)
   vlbe_status vlbe_rancf_merge(d, na, nh, nb, k, info)     merged weights (eqs. 29-38)
   vlbe_status vlbe_rancf_arc(c, R, a0, theta, w, x)        circular-arc element (eq. 43)
   vlbe_status vlbe_rancf_nurbs(d, deg, nc, P, wc, U, len, cap, &ne, w, x, p)  a NURBS
                                            curve as elements (exact geometry)
   vlbe_status vlbe_rancf_chain_init(ch, els, nodes, nn, cap, cons, ccap)  a planar
                                            chain of ALE-RANCF elements (vlbe_ale_chain)
   const vlbe_ale_etype *vlbe_rancf_etype()  the element-type table of such a
                                            chain (to wrap in a table of one's own)

REFERENCES
   [R] Z. Ding, B. Ouyang, A variable-length rational finite element based on
       the absolute nodal coordinate formulation, Machines 10 (2022) 174,
       eqs. 1-38, 43.
   G. G. Sanborn, A. A. Shabana, A rational finite element method based on
       the absolute nodal coordinate formulation, Nonlinear Dyn. 58 (2009).
   L. Piegl, W. Tiller, The NURBS Book, 2nd ed., Springer 1997 (de
       Casteljau in homogeneous coordinates, circular arcs).
*/
#ifndef VLBE_RANCF_H
#define VLBE_RANCF_H
#include "vlbe.h"
#include "ancf_ale.h"

#if !defined(VLBE_VERSION_MAJOR) || VLBE_VERSION_MAJOR != 0 || VLBE_VERSION_MINOR < 1
#error "rancf.h needs vlbe.h 0.1 or newer in the same directory"
#endif

/* -- constants ---------------------------------------------------------- */
#define VLBE_RANCF_DMAX 3 /* largest dimension of the Bezier/merge helpers */

/* -- types -------------------------------------------------------------- */
/* An element type with its weights: the planar ALE-ANCF element type whose
   Gauss tables hold the rational basis, and k_i = w_i / w3 (k[3] = 1). */
typedef struct vlbe_rancf_elem {
    vlbe_ale_elem ale;
    vlbe_real k[4];
} vlbe_rancf_elem;

/* -- API prototypes ----------------------------------------------------- */
VLBE_API vlbe_status vlbe_rancf_basis_eval(const vlbe_real *w, vlbe_real p, vlbe_real p1,
                                           vlbe_real p2, int kmax, int amax,
                                           vlbe_herm_ale *VLBE_RESTRICT b);
VLBE_API vlbe_status vlbe_rancf_elem_init(vlbe_rancf_elem *el, const vlbe_ale_mat *mat,
                                          const vlbe_real *w, unsigned flags, int nm, int nl,
                                          int nt);
VLBE_API vlbe_status vlbe_rancf_mass(const vlbe_rancf_elem *el, unsigned mode,
                                     const vlbe_real *q, vlbe_real *VLBE_RESTRICT M);
VLBE_API vlbe_status vlbe_rancf_mass_jac(const vlbe_rancf_elem *el, unsigned mode,
                                         const vlbe_real *q, const vlbe_real *a,
                                         vlbe_real *VLBE_RESTRICT Mq);
VLBE_API vlbe_status vlbe_rancf_force(const vlbe_rancf_elem *el, unsigned mode,
                                      const vlbe_real *q, const vlbe_real *qd,
                                      vlbe_real *VLBE_RESTRICT Q, vlbe_real *VLBE_RESTRICT K,
                                      vlbe_real *VLBE_RESTRICT D);
VLBE_API vlbe_status vlbe_rancf_energy(const vlbe_rancf_elem *el, unsigned mode,
                                       const vlbe_real *q, const vlbe_real *qd,
                                       vlbe_real *VLBE_RESTRICT E);
VLBE_API vlbe_status vlbe_rancf_point(const vlbe_rancf_elem *el, const vlbe_real *q, vlbe_real p,
                                      vlbe_real *VLBE_RESTRICT r, vlbe_real *VLBE_RESTRICT rp);
VLBE_API vlbe_status vlbe_rancf_strain(const vlbe_rancf_elem *el, const vlbe_real *q,
                                       vlbe_real p, vlbe_real *VLBE_RESTRICT eps,
                                       vlbe_real *VLBE_RESTRICT kap);
VLBE_API vlbe_status vlbe_rancf_point_force(const vlbe_rancf_elem *el, const vlbe_real *q,
                                            vlbe_real pf, const vlbe_real *F,
                                            vlbe_real *VLBE_RESTRICT Q, vlbe_real *VLBE_RESTRICT K);
VLBE_API vlbe_status vlbe_rancf_to_bezier(int d, const vlbe_real *w, vlbe_real l,
                                          const vlbe_real *x, vlbe_real *VLBE_RESTRICT P);
VLBE_API vlbe_status vlbe_rancf_from_bezier(int d, const vlbe_real *w, vlbe_real l,
                                            const vlbe_real *P, vlbe_real *VLBE_RESTRICT x);
VLBE_API vlbe_status vlbe_rancf_bezier_eval(int d, const vlbe_real *w, const vlbe_real *P,
                                            vlbe_real u, vlbe_real *VLBE_RESTRICT r);
VLBE_API vlbe_status vlbe_rancf_bezier_split(int d, const vlbe_real *w, const vlbe_real *P,
                                             vlbe_real u, vlbe_real *VLBE_RESTRICT wl,
                                             vlbe_real *VLBE_RESTRICT Pl,
                                             vlbe_real *VLBE_RESTRICT wr,
                                             vlbe_real *VLBE_RESTRICT Pr);
VLBE_API vlbe_status vlbe_rancf_split(const vlbe_rancf_elem *el, const vlbe_real *q,
                                      const vlbe_real *qd, vlbe_real ph,
                                      vlbe_real *VLBE_RESTRICT qh, vlbe_real *VLBE_RESTRICT qhd,
                                      vlbe_real *VLBE_RESTRICT wl, vlbe_real *VLBE_RESTRICT wr);
VLBE_API vlbe_status vlbe_rancf_merge(int d, const vlbe_real *na, const vlbe_real *nh,
                                      const vlbe_real *nb, vlbe_real *VLBE_RESTRICT k,
                                      int *VLBE_RESTRICT info);
VLBE_API vlbe_status vlbe_rancf_arc(const vlbe_real *c, vlbe_real R, vlbe_real a0,
                                    vlbe_real theta, vlbe_real *VLBE_RESTRICT w,
                                    vlbe_real *VLBE_RESTRICT x);
VLBE_API vlbe_status vlbe_rancf_nurbs(int d, int deg, int nc, const vlbe_real *P,
                                      const vlbe_real *wc, const vlbe_real *U, vlbe_real len,
                                      int cap, int *VLBE_RESTRICT ne, vlbe_real *VLBE_RESTRICT w,
                                      vlbe_real *VLBE_RESTRICT x, vlbe_real *VLBE_RESTRICT p);
VLBE_API vlbe_status vlbe_rancf_chain_init(vlbe_ale_chain *ch, vlbe_rancf_elem *els,
                                           vlbe_ale_node *nodes, int nn, int nn_cap,
                                           vlbe_ale_con *cons, int ncon_cap);
VLBE_API const vlbe_ale_etype *vlbe_rancf_etype(void);

/* ===== implementation =================================================== */

/* smallest normal vlbe_real */
#ifdef VLBE_USE_FLOAT
#define VLBE__RANCF_RMIN FLT_MIN
#else
#define VLBE__RANCF_RMIN DBL_MIN
#endif

/* Weights: all finite and > 0, and the smallest at least REAL_MIN (the
   smallest normal number) times the largest (so that no k_i = w_i / w3
   and no quotient k_i / k_j overflows or underflows); VLBE_EWEIGHT
   otherwise.  k = w / w3. */
VLBE_INLINE vlbe_status vlbe__rancf_wnorm(const vlbe_real *w, vlbe_real *k)
{
    vlbe_real lo, hi;
    int i;
    for (i = 0; i < 4; ++i)
        if (!isfinite(w[i]) || !(w[i] > VLBE_R(0.0))) return VLBE_EWEIGHT;
    lo = hi = w[0];
    for (i = 1; i < 4; ++i) {
        if (w[i] < lo) lo = w[i];
        if (w[i] > hi) hi = w[i];
    }
    if (!(lo / hi >= VLBE__RANCF_RMIN)) return VLBE_EWEIGHT;
    for (i = 0; i < 3; ++i) k[i] = w[i] / w[3];
    k[3] = VLBE_R(1.0);
    return VLBE_OK;
}

/* The entries of a basis that vlbe__ale_basis_fill wrote for kmax, amax
   are finite (the rational basis divides by W, which may vanish outside
   [p1, p2] or overflow); copy them to b then. */
VLBE_INLINE vlbe_status vlbe__rancf_b_out(const vlbe_herm_ale *t, int kmax, int amax,
                                            vlbe_herm_ale *b)
{
    const int na = amax == 0 ? 1 : (amax == 1 ? 3 : VLBE_DA_N), kl = kmax < 1 ? kmax : 1;
    int k, a, ok = isfinite(t->L) && isfinite(t->s);
    if (na == VLBE_DA_N) { /* all partials: the rows k <= kmax are contiguous */
        const size_t nh = (size_t)(kmax + 1) * VLBE_DA_N * 4, nl = (size_t)(kl + 1) * VLBE_DA_N * 2;
        if (!ok || !vlbe_all_finite(&t->h[0][0][0], (int)nh) ||
            !vlbe_all_finite(&t->l[0][0][0], (int)nl))
            return VLBE_ENONFINITE;
        b->L = t->L;
        b->s = t->s;
        memcpy(&b->h[0][0][0], &t->h[0][0][0], nh * sizeof(vlbe_real));
        memcpy(&b->l[0][0][0], &t->l[0][0][0], nl * sizeof(vlbe_real));
        return VLBE_OK;
    }
    for (k = 0; k <= kmax; ++k)
        for (a = 0; a < na; ++a) ok &= vlbe_all_finite(t->h[k][a], 4);
    for (k = 0; k <= kl; ++k)
        for (a = 0; a < na; ++a) ok &= vlbe_all_finite(t->l[k][a], 2);
    if (!ok) return VLBE_ENONFINITE;
    b->L = t->L;
    b->s = t->s;
    for (k = 0; k <= kmax; ++k)
        for (a = 0; a < na; ++a) {
            b->h[k][a][0] = t->h[k][a][0];
            b->h[k][a][1] = t->h[k][a][1];
            b->h[k][a][2] = t->h[k][a][2];
            b->h[k][a][3] = t->h[k][a][3];
        }
    for (k = 0; k <= kl; ++k)
        for (a = 0; a < na; ++a) {
            b->l[k][a][0] = t->l[k][a][0];
            b->l[k][a][1] = t->l[k][a][1];
        }
    return VLBE_OK;
}

/* xi-derivatives g[j][c], c < nd (nd <= 6), of the four functions of eq. 9
   at L = 1 from the weights k.  Each is a cubic numerator n_j over the
   cubic W; by Leibniz on n = g W: g^(c) = (n^(c) - sum_{i<c} C(c,i) g^(i)
   W^(c-i)) / W (the derivatives of n and W vanish beyond the third). */
VLBE_INLINE void vlbe__rancf_g(const vlbe_real *k, vlbe_real xi, int nd, vlbe_real (*g)[6])
{
    static const vlbe_real binom[6][6] = {{1, 0, 0, 0, 0, 0},  {1, 1, 0, 0, 0, 0},
                                          {1, 2, 1, 0, 0, 0},  {1, 3, 3, 1, 0, 0},
                                          {1, 4, 6, 4, 1, 0},  {1, 5, 10, 10, 5, 1}};
    const vlbe_real k0 = k[0], k1 = k[1], k2 = k[2], k3 = k[3];
    /* monomial coefficients: (1-u)^3, u(1-u)^2, u^2(1-u), u^3 weighted */
    const vlbe_real c[4][4] = {
        {k0, VLBE_R(3.0) * (k1 - k0), VLBE_R(3.0) * k0 - VLBE_R(6.0) * k1,
         VLBE_R(3.0) * k1 - k0},                                     /* n1 */
        {VLBE_R(0.0), k0, VLBE_R(-2.0) * k0, k0},                     /* n2 */
        {VLBE_R(0.0), VLBE_R(0.0), VLBE_R(3.0) * k2, k3 - VLBE_R(3.0) * k2}, /* n3 */
        {VLBE_R(0.0), VLBE_R(0.0), -k3, k3}};                         /* n4 */
    vlbe_real cw[4], wd[6], iw;
    int j, i, m;
    for (i = 0; i < 4; ++i) cw[i] = c[0][i] + c[2][i]; /* W = n1 + n3 */
    vlbe__cubic_derivs(cw, xi, nd, wd);
    iw = VLBE_R(1.0) / wd[0];
    for (j = 0; j < 4; ++j) {
        vlbe__cubic_derivs(c[j], xi, nd, g[j]);
        for (m = 0; m < nd; ++m) {
            vlbe_real s = g[j][m];
            for (i = 0; i < m; ++i) s -= binom[m][i] * g[j][i] * wd[m - i];
            g[j][m] = s * iw;
        }
    }
}

/* The basis of normalized weights k at p (weights already checked). */
VLBE_INLINE void vlbe__rancf_eval(const vlbe_real *k, vlbe_real p, vlbe_real p1,
                                    vlbe_real p2, int kmax, int amax, vlbe_herm_ale *b)
{
    vlbe_real g[4][6];
    vlbe__rancf_g(k, (p - p1) * (VLBE_R(1.0) / (p2 - p1)), kmax + amax + 1, g);
    vlbe__ale_basis_fill((const vlbe_real(*)[6])g, p, p1, p2, kmax, amax, b);
}

VLBE_API vlbe_status vlbe_rancf_basis_eval(const vlbe_real *w, vlbe_real p, vlbe_real p1,
                                           vlbe_real p2, int kmax, int amax,
                                           vlbe_herm_ale *VLBE_RESTRICT b)
{
    vlbe_real k[4];
    vlbe_herm_ale t;
    vlbe_status st;
    VLBE_ASSERT(w != NULL && b != NULL);
    VLBE_ASSERT(kmax >= 0 && kmax <= 3 && amax >= 0 && amax <= 2);
    if ((st = vlbe__rancf_wnorm(w, k)) != VLBE_OK) return st;
    if (!isfinite(p) || !isfinite(p1) || !isfinite(p2)) return VLBE_ENONFINITE;
    if ((st = vlbe__ale_len(p1, p2)) != VLBE_OK) return st;
    vlbe__rancf_eval(k, p, p1, p2, kmax, amax, &t);
    return vlbe__rancf_b_out(&t, kmax, amax, b);
}

/* Refill one rule point of the planar tables with the rational basis. */
VLBE_INLINE void vlbe__rancf_gp(const vlbe_real *k, vlbe_ale_gp *gp)
{
    vlbe_herm_ale b;
    vlbe__rancf_eval(k, gp->xi, VLBE_R(0.0), VLBE_R(1.0), 3, 2, &b);
    vlbe__ale_gp_set(gp, gp->xi, gp->w, &b);
}

/* the rational numbers of one rule point are finite */
VLBE_INLINE int vlbe__rancf_gp_ok(const vlbe_ale_gp *gp)
{
    return vlbe_all_finite(&gp->b[0][0][0], 3 * VLBE_DA_N * 4) & vlbe_all_finite(gp->b3, 4);
}

/* 1 if the rational numbers at xi are finite (one scratch point; the
   weights are so uneven otherwise that the basis overflows) */
VLBE_INLINE int vlbe__rancf_xi_ok(const vlbe_real *k, vlbe_real xi)
{
    vlbe_ale_gp gp;
    gp.xi = xi;
    gp.w = VLBE_R(0.0);
    vlbe__rancf_gp(k, &gp);
    return vlbe__rancf_gp_ok(&gp);
}

/* Two passes, so that the element (12 kB in float) is never copied: every
   check first (the planar element's arguments, the rational numbers at the
   abscissae of the three rules and at the ends, on one scratch point),
   then the planar tables written into *el and their Hermite numbers
   replaced in place, which cannot fail. */
VLBE_API vlbe_status vlbe_rancf_elem_init(vlbe_rancf_elem *el, const vlbe_ale_mat *mat,
                                          const vlbe_real *w, unsigned flags, int nm, int nl,
                                          int nt)
{
    vlbe_real k[4];
    const int nr[3] = {nm != 0 ? nm : 4, nl != 0 ? nl : 5, nt != 0 ? nt : 5};
    vlbe_ale_rule *ru[3];
    vlbe_status st;
    int r, g, ok = 1;
    VLBE_ASSERT(el != NULL && mat != NULL && w != NULL);
    if ((st = vlbe__rancf_wnorm(w, k)) != VLBE_OK) return st;
    if (flags & VLBE_ALE_INV_AXIAL) return VLBE_EARG;
    if ((st = vlbe__ale_elem_check(mat, nm, nl, nt)) != VLBE_OK) return st;
    for (r = 0; r < 3; ++r) {
        const vlbe_real *x, *wg;
        if (vlbe_gl_rule(nr[r], &x, &wg)) return VLBE_EARG;
        for (g = 0; g < nr[r]; ++g) ok &= vlbe__rancf_xi_ok(k, VLBE_R(0.5) * (x[g] + VLBE_R(1.0)));
    }
    ok &= vlbe__rancf_xi_ok(k, VLBE_R(0.0)) & vlbe__rancf_xi_ok(k, VLBE_R(1.0));
    if (!ok) return VLBE_EWEIGHT;
    /* nothing can fail below: el is written only now */
    if ((st = vlbe_ale_elem_init(&el->ale, mat, flags, nm, nl, nt)) != VLBE_OK) return st;
    for (r = 0; r < 4; ++r) el->k[r] = k[r];
    ru[0] = &el->ale.rm;
    ru[1] = &el->ale.rl;
    ru[2] = &el->ale.rt;
    for (r = 0; r < 3; ++r)
        for (g = 0; g < ru[r]->n; ++g) vlbe__rancf_gp(k, &ru[r]->g[g]);
    vlbe__rancf_gp(k, &el->ale.ends[0]);
    vlbe__rancf_gp(k, &el->ale.ends[1]);
    el->ale.bmax = vlbe__ale_rule_bmax(&el->ale.rm);
    return VLBE_OK;
}

/* Element calls: the planar kernels on the rational tables. */
VLBE_INLINE vlbe_status vlbe__rancf_mode(const vlbe_rancf_elem *el, unsigned mode)
{
    return ((mode | el->ale.flags) & VLBE_ALE_INV_AXIAL) ? VLBE_EARG : VLBE_OK;
}

VLBE_API vlbe_status vlbe_rancf_mass(const vlbe_rancf_elem *el, unsigned mode,
                                     const vlbe_real *q, vlbe_real *VLBE_RESTRICT M)
{
    VLBE_ASSERT(el != NULL);
    if (vlbe__rancf_mode(el, mode)) return VLBE_EARG;
    return vlbe_ale_mass(&el->ale, mode, q, M);
}

VLBE_API vlbe_status vlbe_rancf_mass_jac(const vlbe_rancf_elem *el, unsigned mode,
                                         const vlbe_real *q, const vlbe_real *a,
                                         vlbe_real *VLBE_RESTRICT Mq)
{
    VLBE_ASSERT(el != NULL);
    if (vlbe__rancf_mode(el, mode)) return VLBE_EARG;
    return vlbe_ale_mass_jac(&el->ale, mode, q, a, Mq);
}

VLBE_API vlbe_status vlbe_rancf_force(const vlbe_rancf_elem *el, unsigned mode,
                                      const vlbe_real *q, const vlbe_real *qd,
                                      vlbe_real *VLBE_RESTRICT Q, vlbe_real *VLBE_RESTRICT K,
                                      vlbe_real *VLBE_RESTRICT D)
{
    VLBE_ASSERT(el != NULL);
    if (vlbe__rancf_mode(el, mode)) return VLBE_EARG;
    return vlbe_ale_force(&el->ale, mode, q, qd, Q, K, D);
}

VLBE_API vlbe_status vlbe_rancf_energy(const vlbe_rancf_elem *el, unsigned mode,
                                       const vlbe_real *q, const vlbe_real *qd,
                                       vlbe_real *VLBE_RESTRICT E)
{
    VLBE_ASSERT(el != NULL);
    if (vlbe__rancf_mode(el, mode)) return VLBE_EARG;
    return vlbe_ale_energy(&el->ale, mode, q, qd, E);
}

/* r(p) and r'(p) (either may be NULL); p may lie outside [p1, p2] as long
   as W > 0 there (the curve is extrapolated). */
VLBE_API vlbe_status vlbe_rancf_point(const vlbe_rancf_elem *el, const vlbe_real *q, vlbe_real p,
                                      vlbe_real *VLBE_RESTRICT r, vlbe_real *VLBE_RESTRICT rp)
{
    vlbe_herm_ale b;
    vlbe_status st;
    VLBE_ASSERT(el != NULL && q != NULL);
    if ((st = vlbe__ale_check(q, NULL)) != VLBE_OK) return st;
    if (!isfinite(p)) return VLBE_ENONFINITE;
    vlbe__rancf_eval(el->k, p, q[4], q[9], 1, 0, &b);
    return vlbe__ale_point_b(&b, q, r, rp);
}

VLBE_API vlbe_status vlbe_rancf_strain(const vlbe_rancf_elem *el, const vlbe_real *q,
                                       vlbe_real p, vlbe_real *VLBE_RESTRICT eps,
                                       vlbe_real *VLBE_RESTRICT kap)
{
    vlbe_herm_ale b;
    vlbe_status st;
    VLBE_ASSERT(el != NULL && q != NULL);
    if ((st = vlbe__ale_check(q, NULL)) != VLBE_OK) return st;
    if (!isfinite(p)) return VLBE_ENONFINITE;
    vlbe__rancf_eval(el->k, p, q[4], q[9], 2, 0, &b);
    return vlbe__ale_strain_b(&b, q, eps, kap);
}

VLBE_API vlbe_status vlbe_rancf_point_force(const vlbe_rancf_elem *el, const vlbe_real *q,
                                            vlbe_real pf, const vlbe_real *F,
                                            vlbe_real *VLBE_RESTRICT Q, vlbe_real *VLBE_RESTRICT K)
{
    vlbe_herm_ale b;
    vlbe_status st;
    VLBE_ASSERT(el != NULL && q != NULL && F != NULL && Q != NULL);
    if ((st = vlbe__ale_check(q, NULL)) != VLBE_OK) return st;
    if (!isfinite(pf) || !vlbe_all_finite(F, 2)) return VLBE_ENONFINITE;
    if (pf < q[4] || pf > q[9]) return VLBE_EBOUND;
    vlbe__rancf_eval(el->k, pf, q[4], q[9], 0, 2, &b);
    return vlbe__ale_point_force_c(&b, q, F, Q, K);
}

/* -- Bezier form ---------------------------------------------------------- */
VLBE_INLINE vlbe_status vlbe__rancf_bz_check(int d, const vlbe_real *w, vlbe_real *k)
{
    if (d < 1 || d > VLBE_RANCF_DMAX) return VLBE_EARG;
    return vlbe__rancf_wnorm(w, k);
}

/* the arguments of the conversions: dimension, weights, length, the 4 d
   input numbers */
VLBE_INLINE vlbe_status vlbe__rancf_conv_check(int d, const vlbe_real *w, vlbe_real l,
                                                 const vlbe_real *in, vlbe_real *k)
{
    vlbe_status st;
    if ((st = vlbe__rancf_bz_check(d, w, k)) != VLBE_OK) return st;
    if (!isfinite(l) || !vlbe_all_finite(in, 4 * d)) return VLBE_ENONFINITE;
    if (!(l > VLBE_R(0.0))) return VLBE_ELENGTH;
    return VLBE_OK;
}

/* eq. 6: P0 = rA, P1 = rA + l w0/(3 w1) rA', P2 = rB - l w3/(3 w2) rB', P3 = rB */
VLBE_API vlbe_status vlbe_rancf_to_bezier(int d, const vlbe_real *w, vlbe_real l,
                                          const vlbe_real *x, vlbe_real *VLBE_RESTRICT P)
{
    vlbe_real k[4], t[4 * VLBE_RANCF_DMAX];
    vlbe_status st;
    int i;
    VLBE_ASSERT(w != NULL && x != NULL && P != NULL);
    if ((st = vlbe__rancf_conv_check(d, w, l, x, k)) != VLBE_OK) return st;
    for (i = 0; i < d; ++i) {
        t[i] = x[i];
        t[d + i] = x[i] + l * k[0] / (VLBE_R(3.0) * k[1]) * x[d + i];
        t[2 * d + i] = x[2 * d + i] - l * k[3] / (VLBE_R(3.0) * k[2]) * x[3 * d + i];
        t[3 * d + i] = x[2 * d + i];
    }
    if (!vlbe_all_finite(t, 4 * d)) return VLBE_ENONFINITE;
    for (i = 0; i < 4 * d; ++i) P[i] = t[i];
    return VLBE_OK;
}

/* eq. 5: rA' = 3 w1/(l w0) (P1 - P0), rB' = 3 w2/(l w3) (P3 - P2) */
VLBE_API vlbe_status vlbe_rancf_from_bezier(int d, const vlbe_real *w, vlbe_real l,
                                            const vlbe_real *P, vlbe_real *VLBE_RESTRICT x)
{
    vlbe_real k[4], t[4 * VLBE_RANCF_DMAX];
    vlbe_status st;
    int i;
    VLBE_ASSERT(w != NULL && x != NULL && P != NULL);
    if ((st = vlbe__rancf_conv_check(d, w, l, P, k)) != VLBE_OK) return st;
    for (i = 0; i < d; ++i) {
        t[i] = P[i];
        t[d + i] = VLBE_R(3.0) * k[1] / (l * k[0]) * (P[d + i] - P[i]);
        t[2 * d + i] = P[3 * d + i];
        t[3 * d + i] = VLBE_R(3.0) * k[2] / (l * k[3]) * (P[3 * d + i] - P[2 * d + i]);
    }
    if (!vlbe_all_finite(t, 4 * d)) return VLBE_ENONFINITE;
    for (i = 0; i < 4 * d; ++i) x[i] = t[i];
    return VLBE_OK;
}

/* de Casteljau on the homogeneous points H_i = (w_i P_i, w_i) at u: the
   triangle t[level][i] (level 0: the H_i), d + 1 numbers each. */
VLBE_INLINE void vlbe__rancf_casteljau(int d, const vlbe_real *k, const vlbe_real *P,
                                         vlbe_real u, vlbe_real (*t)[4][VLBE_RANCF_DMAX + 1])
{
    int i, j, lv;
    for (i = 0; i < 4; ++i) {
        for (j = 0; j < d; ++j) t[0][i][j] = k[i] * P[i * d + j];
        t[0][i][d] = k[i];
    }
    for (lv = 1; lv < 4; ++lv)
        for (i = 0; i < 4 - lv; ++i)
            for (j = 0; j <= d; ++j)
                t[lv][i][j] = (VLBE_R(1.0) - u) * t[lv - 1][i][j] + u * t[lv - 1][i + 1][j];
}

VLBE_API vlbe_status vlbe_rancf_bezier_eval(int d, const vlbe_real *w, const vlbe_real *P,
                                            vlbe_real u, vlbe_real *VLBE_RESTRICT r)
{
    vlbe_real k[4], t[4][4][VLBE_RANCF_DMAX + 1], x[VLBE_RANCF_DMAX];
    vlbe_status st;
    int j;
    VLBE_ASSERT(w != NULL && P != NULL && r != NULL);
    if ((st = vlbe__rancf_bz_check(d, w, k)) != VLBE_OK) return st;
    if (!isfinite(u) || !vlbe_all_finite(P, 4 * d)) return VLBE_ENONFINITE;
    vlbe__rancf_casteljau(d, k, P, u, t);
    if (!(t[3][0][d] > VLBE_R(0.0))) return VLBE_EWEIGHT; /* W <= 0 outside [0, 1] */
    for (j = 0; j < d; ++j) x[j] = t[3][0][j] / t[3][0][d];
    if (!vlbe_all_finite(x, d)) return VLBE_ENONFINITE;
    for (j = 0; j < d; ++j) r[j] = x[j];
    return VLBE_OK;
}

/* eq. 21: the left curve's homogeneous points are the triangle's first
   column t[0][0], t[1][0], t[2][0], t[3][0], the right one's its diagonal
   t[3][0], t[2][1], t[1][2], t[0][3]; weights the last component, points
   the first d divided by it.  Output weights are normalized (w3 = 1). */
VLBE_API vlbe_status vlbe_rancf_bezier_split(int d, const vlbe_real *w, const vlbe_real *P,
                                             vlbe_real u, vlbe_real *VLBE_RESTRICT wl,
                                             vlbe_real *VLBE_RESTRICT Pl,
                                             vlbe_real *VLBE_RESTRICT wr,
                                             vlbe_real *VLBE_RESTRICT Pr)
{
    vlbe_real k[4], t[4][4][VLBE_RANCF_DMAX + 1], a[2][4], B[2][4 * VLBE_RANCF_DMAX];
    vlbe_real lo = VLBE_REAL_MAX;
    vlbe_status st;
    int i, j, ok = 1;
    VLBE_ASSERT(w != NULL && P != NULL);
    if ((st = vlbe__rancf_bz_check(d, w, k)) != VLBE_OK) return st;
    if (!isfinite(u) || !vlbe_all_finite(P, 4 * d)) return VLBE_ENONFINITE;
    if (!(u > VLBE_R(0.0) && u < VLBE_R(1.0))) return VLBE_EBOUND;
    vlbe__rancf_casteljau(d, k, P, u, t);
    for (i = 0; i < 4; ++i) {
        const vlbe_real *hl = t[i][0], *hr = t[3 - i][i];
        a[0][i] = hl[d] / t[3][0][d];
        a[1][i] = hr[d] / t[0][3][d];
        for (j = 0; j < d; ++j) {
            B[0][i * d + j] = hl[j] / hl[d];
            B[1][i * d + j] = hr[j] / hr[d];
        }
    }
    /* the parts' weights (those asked for) must be weights (finite, > 0:
       a homogeneous weight that underflowed gives 0), their points finite */
    for (i = 0; i < 4; ++i) {
        if (wl) lo = a[0][i] < lo ? a[0][i] : lo;
        if (wr) lo = a[1][i] < lo ? a[1][i] : lo;
        if ((wl && !isfinite(a[0][i])) || (wr && !isfinite(a[1][i]))) ok = 0;
    }
    if (!ok || !(lo > VLBE_R(0.0))) return VLBE_EWEIGHT;
    if ((Pl && !vlbe_all_finite(B[0], 4 * d)) || (Pr && !vlbe_all_finite(B[1], 4 * d)))
        return VLBE_ENONFINITE;
    for (i = 0; i < 4; ++i) {
        if (wl) wl[i] = a[0][i];
        if (wr) wr[i] = a[1][i];
    }
    for (i = 0; i < 4 * d; ++i) {
        if (Pl) Pl[i] = B[0][i];
        if (Pr) Pr[i] = B[1][i];
    }
    return VLBE_OK;
}

/* Segmentation of an element at the material point ph in (p1, p2) (eqs.
   21-28): the new node qh = [r, r', ph] is the point and slope of the
   element at ph (eq. 27: both parts share it, and every material point
   keeps its position), qhd its material rate (p' = 0: the new node is
   fixed in the material); wl, wr the weights of the parts [p1, ph] and
   [ph, p2], normalized (w3 = 1).  qd, qhd, wl, wr may be NULL. */
VLBE_API vlbe_status vlbe_rancf_split(const vlbe_rancf_elem *el, const vlbe_real *q,
                                      const vlbe_real *qd, vlbe_real ph,
                                      vlbe_real *VLBE_RESTRICT qh, vlbe_real *VLBE_RESTRICT qhd,
                                      vlbe_real *VLBE_RESTRICT wl, vlbe_real *VLBE_RESTRICT wr)
{
    vlbe_real P[8], x[8], wlo[4], wro[4];
    vlbe_herm_ale b;
    vlbe_status st;
    int k;
    VLBE_ASSERT(el != NULL && q != NULL && qh != NULL);
    if ((st = vlbe__ale_check(q, qd)) != VLBE_OK) return st;
    if (!isfinite(ph)) return VLBE_ENONFINITE;
    if (!(ph > q[4] && ph < q[9])) return VLBE_EBOUND;
    for (k = 0; k < 4; ++k) { /* x = [r1, r1', r2, r2'] */
        x[2 * k] = q[VLBE__ALE_E(k)];
        x[2 * k + 1] = q[VLBE__ALE_E(k) + 1];
    }
    if ((st = vlbe_rancf_to_bezier(2, el->k, q[9] - q[4], x, P)) != VLBE_OK) return st;
    if ((st = vlbe_rancf_bezier_split(2, el->k, P, (ph - q[4]) / (q[9] - q[4]), wlo, NULL, wro,
                                      NULL)) != VLBE_OK)
        return st;
    vlbe__rancf_eval(el->k, ph, q[4], q[9], 1, 1, &b);
    if ((st = vlbe__ale_split_node(&b, q, qd, ph, qh, qhd)) != VLBE_OK) return st;
    for (k = 0; k < 4; ++k) {
        if (wl) wl[k] = wlo[k];
        if (wr) wr[k] = wro[k];
    }
    return VLBE_OK;
}

/* Minimum-norm least-squares solution of A x = B, A d x 3 (d <= 3, row
   major), by one-sided Jacobi (Hestenes): rotations V make the columns of
   A V orthogonal, their norms are the singular values s_j, and x = V
   diag(1/s_j) (A V)^T B over the s_j above 8 EPS max s (smaller ones are
   rank deficiency: their directions get no component, hence the minimum
   norm).  A pair with a column of rounding size (squared norm <= EPS^2
   times that of A) is not rotated: in the planar 2 x 3 case one column of
   A V is such noise, and rotating against it never meets the stopping
   test.  VLBE_ESINGULAR when A is zero. */
VLBE_INLINE vlbe_status vlbe__rancf_minnorm(int d, const vlbe_real *A, const vlbe_real *B,
                                              vlbe_real *x)
{
    vlbe_real U[VLBE_RANCF_DMAX][3], V[3][3], s[3], smax = VLBE_R(0.0), fro = VLBE_R(0.0);
    int i, j, a, b, sweep;
    for (i = 0; i < d; ++i)
        for (j = 0; j < 3; ++j) {
            U[i][j] = A[i * 3 + j];
            fro += U[i][j] * U[i][j];
        }
    for (i = 0; i < 3; ++i)
        for (j = 0; j < 3; ++j) V[i][j] = i == j ? VLBE_R(1.0) : VLBE_R(0.0);
    for (sweep = 0; sweep < 30; ++sweep) {
        int rot = 0;
        for (a = 0; a < 2; ++a)
            for (b = a + 1; b < 3; ++b) {
                vlbe_real al = VLBE_R(0.0), be = VLBE_R(0.0), ga = VLBE_R(0.0), ze, t, cs, sn;
                for (i = 0; i < d; ++i) {
                    al += U[i][a] * U[i][a];
                    be += U[i][b] * U[i][b];
                    ga += U[i][a] * U[i][b];
                }
                if (vlbe_fabs(ga) <= VLBE_EPS * vlbe_sqrt(al * be) ||
                    al <= VLBE_EPS * VLBE_EPS * fro || be <= VLBE_EPS * VLBE_EPS * fro)
                    continue;
                rot = 1;
                ze = (be - al) / (VLBE_R(2.0) * ga);
                t = (ze >= VLBE_R(0.0) ? VLBE_R(1.0) : VLBE_R(-1.0)) /
                    (vlbe_fabs(ze) + vlbe_sqrt(VLBE_R(1.0) + ze * ze));
                cs = VLBE_R(1.0) / vlbe_sqrt(VLBE_R(1.0) + t * t);
                sn = cs * t;
                for (i = 0; i < d; ++i) {
                    const vlbe_real ua = U[i][a], ub = U[i][b];
                    U[i][a] = cs * ua - sn * ub;
                    U[i][b] = sn * ua + cs * ub;
                }
                for (i = 0; i < 3; ++i) {
                    const vlbe_real va = V[i][a], vb = V[i][b];
                    V[i][a] = cs * va - sn * vb;
                    V[i][b] = sn * va + cs * vb;
                }
            }
        if (!rot) break;
    }
    for (j = 0; j < 3; ++j) {
        vlbe_real n2 = VLBE_R(0.0);
        for (i = 0; i < d; ++i) n2 += U[i][j] * U[i][j];
        s[j] = vlbe_sqrt(n2);
        if (s[j] > smax) smax = s[j];
    }
    if (!(smax > VLBE_R(0.0))) return VLBE_ESINGULAR;
    for (i = 0; i < 3; ++i) x[i] = VLBE_R(0.0);
    for (j = 0; j < 3; ++j) {
        vlbe_real c = VLBE_R(0.0);
        if (!(s[j] > VLBE_R(8.0) * VLBE_EPS * smax)) continue;
        for (i = 0; i < d; ++i) c += U[i][j] * B[i];
        c /= s[j] * s[j];
        for (i = 0; i < 3; ++i) x[i] += V[i][j] * c;
    }
    return VLBE_OK;
}

/* Weights of the element AB that replaces AH and HB (eqs. 29-38).  na, nh,
   nb: the nodes [r, r', p] (2 d + 1 reals each, d = 2 or 3) with pA < pH <
   pB.  The merged element keeps the nodes A and B; its weights k (k[3] =
   1, eq. 33) are chosen so that it passes through r_H at u_H = (pH -
   pA)/(pB - pA) (eqs. 31-32).  Times W, eq. 34 is linear in k:
     k0 [(1-u)^3 (rA - rH) + l u (1-u)^2 rA'] + k1 3u(1-u)^2 (rA - rH)
     + k2 3u^2(1-u) (rB - rH) + [u^3 (rB - rH) - l u^2 (1-u) rB'] = 0,
   with k = 1 + x (eq. 35) the minimum-norm least-squares x (eq. 37); if a
   k_i is not positive, k = 1 (eq. 38).  info (may be NULL): 0 the least
   squares weights, 1 the fallback of eq. 38.  VLBE_ESINGULAR when the
   system is degenerate (its matrix is zero: r_H coincides with both ends
   and the end slopes vanish). */
VLBE_API vlbe_status vlbe_rancf_merge(int d, const vlbe_real *na, const vlbe_real *nh,
                                      const vlbe_real *nb, vlbe_real *VLBE_RESTRICT k,
                                      int *VLBE_RESTRICT info)
{
    vlbe_real A[VLBE_RANCF_DMAX * 3], B[VLBE_RANCF_DMAX], x[3], u, l, a3, b3, c1, c2;
    vlbe_status st;
    int i, j, fb = 0;
    VLBE_ASSERT(na != NULL && nh != NULL && nb != NULL && k != NULL);
    if (d < 2 || d > 3) return VLBE_EARG;
    if (!vlbe_all_finite(na, 2 * d + 1) || !vlbe_all_finite(nh, 2 * d + 1) ||
        !vlbe_all_finite(nb, 2 * d + 1))
        return VLBE_ENONFINITE;
    if (!(nh[2 * d] > na[2 * d] && nb[2 * d] > nh[2 * d])) return VLBE_ELENGTH;
    l = nb[2 * d] - na[2 * d];
    u = (nh[2 * d] - na[2 * d]) / l;
    a3 = (VLBE_R(1.0) - u) * (VLBE_R(1.0) - u) * (VLBE_R(1.0) - u);
    b3 = u * u * u;
    c1 = u * (VLBE_R(1.0) - u) * (VLBE_R(1.0) - u);
    c2 = u * u * (VLBE_R(1.0) - u);
    for (i = 0; i < d; ++i) {
        const vlbe_real dA = na[i] - nh[i], dB = nb[i] - nh[i];
        A[i * 3 + 0] = a3 * dA + l * c1 * na[d + i];
        A[i * 3 + 1] = VLBE_R(3.0) * c1 * dA;
        A[i * 3 + 2] = VLBE_R(3.0) * c2 * dB;
        /* B = -(A 1 + c): the residual of unit weights, with the sign */
        B[i] = -(A[i * 3 + 0] + A[i * 3 + 1] + A[i * 3 + 2] + b3 * dB - l * c2 * nb[d + i]);
    }
    if ((st = vlbe__rancf_minnorm(d, A, B, x)) != VLBE_OK) return st;
    for (j = 0; j < 3; ++j)
        if (!(x[j] + VLBE_R(1.0) > VLBE_R(0.0)) || !isfinite(x[j])) fb = 1;
    for (j = 0; j < 3; ++j) k[j] = fb ? VLBE_R(1.0) : x[j] + VLBE_R(1.0);
    k[3] = VLBE_R(1.0);
    if (info) *info = fb;
    return VLBE_OK;
}

/* A circular-arc element (eq. 43): centre c (2), radius R > 0, the arc
   from polar angle a0 through the central angle theta (0 < |theta| < pi;
   negative: clockwise).  w = {1, w1, w1, 1}, w1 = (1 + 2 cos(theta/2))/3
   (the rational quadratic arc of weight cos(theta/2) raised to degree 3),
   x = [rA, rA', rB, rB'] with the slopes for the reference length l = R
   |theta| (the arc length): rA' = 2 cos(theta/2)/(|theta| R) (rC - rA),
   rB' = 2 cos(theta/2)/(|theta| R) (rB - rC), rC the tangents' crossing,
   so |rA'| = |rB'| = 2 sin(|theta|/2)/|theta|. */
VLBE_API vlbe_status vlbe_rancf_arc(const vlbe_real *c, vlbe_real R, vlbe_real a0,
                                    vlbe_real theta, vlbe_real *VLBE_RESTRICT w,
                                    vlbe_real *VLBE_RESTRICT x)
{
    vlbe_real h, ch, sg, f, tA[2], tB[2], a1, xt[8];
    int i;
    VLBE_ASSERT(c != NULL && w != NULL && x != NULL);
    if (!vlbe_all_finite(c, 2) || !isfinite(R) || !isfinite(a0) || !isfinite(theta))
        return VLBE_ENONFINITE;
    if (!(R > VLBE_R(0.0))) return VLBE_ELENGTH;
    h = VLBE_R(0.5) * vlbe_fabs(theta);
    if (!(h > VLBE_R(0.0) && VLBE_R(2.0) * h < VLBE_PI)) return VLBE_EARG;
    ch = vlbe_cos(h);
    sg = theta > VLBE_R(0.0) ? VLBE_R(1.0) : VLBE_R(-1.0);
    a1 = a0 + theta;
    xt[0] = c[0] + R * vlbe_cos(a0);
    xt[1] = c[1] + R * vlbe_sin(a0);
    xt[4] = c[0] + R * vlbe_cos(a1);
    xt[5] = c[1] + R * vlbe_sin(a1);
    /* unit tangents in the direction of travel; |rC - rA| = R tan(h) */
    tA[0] = -sg * vlbe_sin(a0);
    tA[1] = sg * vlbe_cos(a0);
    tB[0] = -sg * vlbe_sin(a1);
    tB[1] = sg * vlbe_cos(a1);
    f = vlbe_sin(h) / h; /* 2 cos(h)/(2 h R) R tan(h) */
    xt[2] = f * tA[0];
    xt[3] = f * tA[1];
    xt[6] = f * tB[0];
    xt[7] = f * tB[1];
    if (!vlbe_all_finite(xt, 8)) return VLBE_ENONFINITE; /* |c| + R overflowed */
    w[0] = w[3] = VLBE_R(1.0);
    w[1] = w[2] = (VLBE_R(1.0) + VLBE_R(2.0) * ch) / VLBE_R(3.0);
    for (i = 0; i < 8; ++i) x[i] = xt[i];
    return VLBE_OK;
}

/* A NURBS curve as a chain of elements (the geometry exactly): degree deg
   = 1..3 in d = 1..3 dimensions, nc >= deg + 1 control points P (nc d
   reals) with weights wc > 0, clamped knots U (nc + deg + 1, non-decreasing,
   the first and the last deg + 1 equal).  Each non-empty knot span
   [U_i, U_i+1) is one rational Bezier piece: its homogeneous control
   points are the blossom values f(U_i^(deg-j), U_i+1^j), j = 0..deg (de
   Boor's algorithm with one argument per level, Piegl & Tiller ch. 5),
   raised to degree 3 (Q_j of the cubic = the combinations of the
   degree-elevation formula, in homogeneous coordinates) and converted to
   nodal form by eq. 5 with the reference length l_e = len (U_i+1 - U_i) /
   (U_end - U_start): the material coordinate is an affine function of the
   knot parameter, so the slopes of neighbours agree at every node where the
   curve is C1 in that parameter (with a knot of multiplicity deg they may
   not: compare x of the two elements).  len > 0: the material length of
   the whole curve (for an unstressed reference, its arc length).
   Output, ne <= cap elements: w (4 per element, w3 = 1), x (4 d per
   element: [rA, rA', rB, rB']), p (ne + 1 nodal material coordinates from
   0).  Errors: VLBE_EARG (d, deg, nc, knots), VLBE_EWEIGHT, VLBE_ENONFINITE,
   VLBE_ELENGTH (len <= 0), VLBE_EWORK (more than cap spans); nothing is
   written then. */
VLBE_API vlbe_status vlbe_rancf_nurbs(int d, int deg, int nc, const vlbe_real *P,
                                      const vlbe_real *wc, const vlbe_real *U, vlbe_real len,
                                      int cap, int *VLBE_RESTRICT ne, vlbe_real *VLBE_RESTRICT w,
                                      vlbe_real *VLBE_RESTRICT x, vlbe_real *VLBE_RESTRICT p)
{
    /* degree elevation to 3: Q_j = sum_i E[deg-1][j][i] H_i */
    static const vlbe_real E[3][4][4] = {
        {{3, 0, 0, 0}, {2, 1, 0, 0}, {1, 2, 0, 0}, {0, 3, 0, 0}},
        {{3, 0, 0, 0}, {1, 2, 0, 0}, {0, 2, 1, 0}, {0, 0, 3, 0}},
        {{3, 0, 0, 0}, {0, 3, 0, 0}, {0, 0, 3, 0}, {0, 0, 0, 3}}};
    const int D = d + 1;
    vlbe_real S, Pb[4 * VLBE_RANCF_DMAX], wb[4], xb[4 * VLBE_RANCF_DMAX], pe;
    vlbe_status st;
    int i, j, m, r, nk, pass, cnt = 0, e = 0;
    VLBE_ASSERT(P != NULL && wc != NULL && U != NULL && ne != NULL);
    if (d < 1 || d > VLBE_RANCF_DMAX || deg < 1 || deg > 3 || nc < deg + 1) return VLBE_EARG;
    if (nc > (INT_MAX - 4) / VLBE_RANCF_DMAX) return VLBE_EARG; /* nc d, nc + deg + 1 */
    nk = nc + deg + 1;
    if (!vlbe_all_finite(P, nc * d) || !vlbe_all_finite(U, nk) || !isfinite(len))
        return VLBE_ENONFINITE;
    for (i = 0; i < nc; ++i)
        if (!isfinite(wc[i]) || !(wc[i] > VLBE_R(0.0))) return VLBE_EWEIGHT;
    for (i = 0; i + 1 < nk; ++i)
        if (U[i + 1] < U[i]) return VLBE_EARG;
    for (i = 1; i <= deg; ++i)
        if (U[i] != U[0] || U[nk - 1 - i] != U[nk - 1]) return VLBE_EARG;
    if (!(U[nk - 1] > U[0])) return VLBE_EARG;
    if (!(len > VLBE_R(0.0))) return VLBE_ELENGTH;
    for (i = deg; i < nc; ++i)
        if (U[i + 1] > U[i]) ++cnt;
    if (cnt > cap) return VLBE_EWORK;
    VLBE_ASSERT(w != NULL && x != NULL && p != NULL);
    S = len / (U[nk - 1] - U[0]);
    if (!isfinite(S) || !(S > VLBE_R(0.0))) return VLBE_ENONFINITE;
    /* pass 0 computes and validates every element, pass 1 writes them */
    for (pass = 0; pass < 2; ++pass) {
        pe = VLBE_R(0.0);
        e = 0;
        if (pass) p[0] = VLBE_R(0.0);
        for (i = deg; i < nc; ++i) { /* span [U_i, U_i+1) with points deg..i */
            const vlbe_real a = U[i], b = U[i + 1];
            vlbe_real H[4][VLBE_RANCF_DMAX + 1], Q[4][VLBE_RANCF_DMAX + 1], l;
            if (!(b > a)) continue;
            for (j = 0; j <= deg; ++j) { /* blossom f(a^(deg-j), b^j) */
                vlbe_real t[4][VLBE_RANCF_DMAX + 1];
                for (m = 0; m <= deg; ++m) {
                    const int c = i - deg + m;
                    for (r = 0; r < d; ++r) t[m][r] = wc[c] * P[c * d + r];
                    t[m][d] = wc[c];
                }
                for (r = 1; r <= deg; ++r) {
                    const vlbe_real arg = r <= deg - j ? a : b;
                    for (m = deg; m >= r; --m) {
                        const int c = i - deg + m; /* knot index of point c */
                        const vlbe_real al = (arg - U[c]) / (U[c + deg - r + 1] - U[c]);
                        int q;
                        for (q = 0; q < D; ++q)
                            t[m][q] = (VLBE_R(1.0) - al) * t[m - 1][q] + al * t[m][q];
                    }
                }
                for (r = 0; r < D; ++r) H[j][r] = t[deg][r];
            }
            for (j = 0; j < 4; ++j)
                for (r = 0; r < D; ++r) {
                    vlbe_real s = VLBE_R(0.0);
                    for (m = 0; m <= deg; ++m) s += E[deg - 1][j][m] * H[m][r];
                    Q[j][r] = s / VLBE_R(3.0);
                }
            for (j = 0; j < 4; ++j) {
                wb[j] = Q[j][d] / Q[3][d];
                for (r = 0; r < d; ++r) Pb[j * d + r] = Q[j][r] / Q[j][d];
            }
            l = S * (b - a);
            /* weights and points of extreme data may not convert: VLBE_EWEIGHT,
               VLBE_ENONFINITE, VLBE_ELENGTH (l underflowed) from pass 0 */
            if ((st = vlbe_rancf_from_bezier(d, wb, l, Pb, xb)) != VLBE_OK) return st;
            pe += l;
            if (!isfinite(pe)) return VLBE_ENONFINITE;
            if (pass) {
                for (j = 0; j < 4 * d; ++j) x[4 * d * e + j] = xb[j];
                for (j = 0; j < 4; ++j) w[4 * e + j] = wb[j];
                p[e + 1] = p[e] + l;
            }
            ++e;
        }
    }
    *ne = e;
    return VLBE_OK;
}

/* ===== chains of rational elements ====================================== */
/* The per-element types of a planar chain (vlbe_ale_etype) over an array of
   vlbe_rancf_elem, one per element, each with its weights. */
VLBE_INLINE const vlbe_ale_elem *vlbe__rancf_et_elem(const void *els, int e)
{
    return &((const vlbe_rancf_elem *)els)[e].ale;
}

VLBE_INLINE void vlbe__rancf_et_basis(const void *els, int e, vlbe_real p, vlbe_real p1,
                                        vlbe_real p2, int kmax, int amax, vlbe_herm_ale *b)
{
    vlbe__rancf_eval(((const vlbe_rancf_elem *)els)[e].k, p, p1, p2, kmax, amax, b);
}

/* aux = [weights of the left part (4), of the right part (4)] */
VLBE_INLINE vlbe_status vlbe__rancf_et_split(const void *els, int e, const vlbe_real *q,
                                               const vlbe_real *qd, vlbe_real ph, vlbe_real *qh,
                                               vlbe_real *qhd, vlbe_real *aux)
{
    return vlbe_rancf_split(&((const vlbe_rancf_elem *)els)[e], q, qd, ph, qh, qhd, aux, aux + 4);
}

/* aux = [merged weights (4), info of vlbe_rancf_merge] */
VLBE_INLINE vlbe_status vlbe__rancf_et_merge(const void *els, int e, const vlbe_real *na,
                                               const vlbe_real *nh, const vlbe_real *nb,
                                               vlbe_real *aux)
{
    int info = 0;
    const vlbe_status st = vlbe_rancf_merge(2, na, nh, nb, aux, &info);
    (void)els;
    (void)e;
    aux[4] = (vlbe_real)info;
    return st;
}

/* The new elements take the material, flags and Gauss orders of element e
   (the one split, or the left one of a merge). */
VLBE_INLINE void vlbe__rancf_et_commit(void *els, int ne, int e, int op, const vlbe_real *aux)
{
    vlbe_rancf_elem *el = (vlbe_rancf_elem *)els;
    const vlbe_ale_mat mat = el[e].ale.mat;
    const unsigned fl = el[e].ale.flags;
    const int nm = el[e].ale.rm.n, nl = el[e].ale.rl.n, nt = el[e].ale.rt.n;
    int j;
    if (op > 0) {
        for (j = ne; j > e + 1; --j) el[j] = el[j - 1];
        (void)vlbe_rancf_elem_init(&el[e], &mat, aux, fl, nm, nl, nt);
        (void)vlbe_rancf_elem_init(&el[e + 1], &mat, aux + 4, fl, nm, nl, nt);
    } else {
        for (j = e + 1; j + 1 < ne; ++j) el[j] = el[j + 1];
        (void)vlbe_rancf_elem_init(&el[e], &mat, aux, fl, nm, nl, nt);
    }
}

/* The element-type table of rational elements (vlbe_ale_etype; els: an
   array of vlbe_rancf_elem), the one vlbe_rancf_chain_init installs: a
   caller's table may wrap its calls, e.g. to watch segmentation's commits. */
VLBE_API const vlbe_ale_etype *vlbe_rancf_etype(void)
{
    static const vlbe_ale_etype t = {vlbe__rancf_et_elem, vlbe__rancf_et_basis,
                                     vlbe__rancf_et_split, vlbe__rancf_et_merge,
                                     vlbe__rancf_et_commit};
    return &t;
}

/* A planar chain of ALE-RANCF elements: element e (between nodes e and
   e+1) is els[e], initialized by the caller (vlbe_rancf_elem_init, e.g.
   unit weights, or the weights of vlbe_rancf_arc / vlbe_rancf_nurbs); els
   holds nn_cap - 1 elements, the chain keeps them in step with its nodes.
   Everything else is vlbe_ale_chain's (constraints, sliding nodes, the
   vlbe_dae callbacks, length control): vlbe_ale_chain_insert splits an
   element exactly (eqs. 21-28: both parts get their own weights) and
   vlbe_ale_chain_remove gives the merged element the least-squares
   weights through the removed node (eqs. 29-38).  ch->mode must not hold
   VLBE_ALE_INV_AXIAL.  Bad sizes: VLBE_EARG. */
VLBE_API vlbe_status vlbe_rancf_chain_init(vlbe_ale_chain *ch, vlbe_rancf_elem *els,
                                           vlbe_ale_node *nodes, int nn, int nn_cap,
                                           vlbe_ale_con *cons, int ncon_cap)
{
    vlbe_status st;
    VLBE_ASSERT(ch != NULL && els != NULL);
    if ((st = vlbe_ale_chain_init(ch, &els[0].ale, nodes, nn, nn_cap, cons, ncon_cap)) !=
        VLBE_OK)
        return st;
    return vlbe_ale_chain_types(ch, vlbe_rancf_etype(), els);
}

#endif /* VLBE_RANCF_H */
