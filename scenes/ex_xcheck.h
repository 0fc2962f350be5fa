/* ex_xcheck.h -- two models of the sliding beam of scenes/ex_sbeam.h
   (Hsiao et al. section 3) built independently of the co-rotational one,
   for the cross-check examples/sliding_xcheck.c and its tests: the planar
   ALE-ANCF chain of ancf_ale.h (joint = constraints at a moving material
   point) and a linear variable-length assumed-modes model.
   -- part of vlbe                                  SPDX-License-Identifier: MIT

   Both read the scene from the same sb_cfg as sb_run (L, L0, section,
   material, U_A(t) of eq. 54 / 55, damping flag of eq. 56, tip0, HHT step
   and alpha, t_end); the mesh fields n_in, n_out are the co-rotational
   model's and are not used here.  Coordinates as in ex_sbeam.h: the
   joint's exit C at the origin, axis +x, lateral deflection y.

   Physics shared by all three models (and why the part inside the joint
   is left out of the two models here): the joint holds the lateral
   position and the slope of every material point inside it, so the inside
   part moves rigidly along the axis with U_A(t) and carries no lateral
   dynamics.  Its axial inertia (and the axial drag of the damping on it)
   changes only the axial force inside the joint, which the joint's axial
   reaction and the drive at A take; the outside part sees the joint as a
   clamp at C through which material flows with the speed U_A'(t).  So
   both models here are the outside part with a clamped end C whose
   material coordinate moves: exact for the co-rotational model's physics.
   Rotary inertia (rhoI, in the co-rotational element) is left out: it
   shifts the first frequency by about (beta_1 r_g / L_f)^2 / 2 ~ 4e-6
   (r_g = sqrt(I/A) = 0.49 mm), far below everything compared here.

   INITIAL STATE.  Both start from the static deflection by a lateral tip
   force scaled to tip0 (ALE: vlbe_dae_static, nonlinear; modes: the
   Galerkin static solution, linear), as sb_run.  sb_run starts its
   integrator with all nodal velocities zero: the material is at rest at
   t = 0 although U_A'(0) = -0.03 m/s in case (a), so its first step
   imposes an axial velocity jump on the beam (case (b): U_A'(0) = 0,
   nothing jumps).  The models here take the same start, the impulsive
   one: at rest before t = 0, U_A' jumps from 0 to U_A'(0) at t = 0, with
   the velocities just after from the impulse balance of each model (ALE:
   M dv + C_q^T Lambda = -M_qp dp', C_q v = 0; modes: eq. (I) below).
   XC_START_STEADY instead starts with the deflected shape at rest in
   space (the material flowing along it); the difference of the two
   starts measures how much case (a) depends on this choice.

   -- (1) ALE-ANCF model (xc_ale_*) ----------------------------------------
   N planar ALE-ANCF elements (ancf_ale.h, cubic Hermite in the material
   coordinate p, p = 0 at the end A, p = L at the tip) over the outside
   part.  Node 0 sits at the exit: position fixed at C (VLBE_ALE_CON_POS),
   slope direction fixed along the axis (VLBE_ALE_CON_SLOPE_DIR: the joint
   fixes the direction, not the stretch), material coordinate prescribed,
        p_0(t) = (L - L0) - U_A(t)      (the material point at the exit);
   node N is the tip, p_N = L fixed; the interior nodes are equally spaced
   in p, p_i(t) = p_0(t) + (i/N) (L - p_0(t)), prescribed too (the same
   mesh as VLBE_ALE_CON_EQUAL_LEN with both ends known, without the extra
   coordinates and multipliers): every element is ALE, all shrink or grow
   together, no length control is needed.  Axial, bending and Kelvin-Voigt
   forces of the element (Green strain, exact curvature: geometrically
   nonlinear), HHT-alpha with the scene's step and alpha, full Newton
   (par.modified = 0: the default modified Newton contracts slowly on the
   stiff axial mode here, 6 iterations a step and three times as many
   halved steps; full Newton takes 3 to 4, a few steps are halved only
   while the axial waves of case (a)'s impulsive start die out).
   Mesh: 10 elements.  With fewer the element locks in membrane at this
   slenderness (L / r_g ~ 1000): its Green axial strain cannot stay zero
   in a bent cubic, so bending also stretches; the static tip force of the
   start comes out 0.75 % / 0.055 % / 0.001 % too high with 3 / 5 / 10
   elements (cubic Hermite bending alone is exact for a tip load), and 5
   elements miss the tip history by 1-2 % of tip0 in 0.3 s (docs/results.md).
   Damping of eq. (56): the Rayleigh pair alpha(t), beta(t) of ex_sbeam.h
   (sb_rayleigh), as the co-rotational model: the stiffness part as the
   element's Kelvin-Voigt coefficients c_eps = c_kap = beta (material
   rates of strain and curvature: what beta k0 u' damps in a co-rotational
   element of fixed material), the mass part as the force -alpha rhoA r_t on the
   material velocity r_t (generalized force -alpha M_e v_e per element with
   the full element mass, prescribed p' included; Jacobians
   -alpha d(M_e v_e)/dq and -alpha M).

   -- (2) assumed-modes model (xc_am_*) ------------------------------------
   Assumptions: Euler-Bernoulli beam, small deflection (linear in w),
   inextensible, no gravity, no rotary inertia; the part inside the joint
   straight (w = 0).  x = distance from the exit along the axis, free
   length l(t) = L0 + U_A(t), axial speed of all material U = U_A'(t) = l',
   xi = x / l.  Deflection
        w(x, t) = sum_i phi_i(xi) a_i(t),   i = 1..n,
        phi_i(xi) = cosh b_i xi - cos b_i xi - s_i (sinh b_i xi - sin b_i xi),
        s_i = (cosh b_i + cos b_i) / (sinh b_i + sin b_i),
        1 + cos b_i cosh b_i = 0  (b_1 = 1.87510..., b_2 = 4.69409...),
   the clamped-free modes of the instantaneous length (int phi_i phi_j dxi
   = delta_ij, int phi_i'' phi_j'' dxi = b_i^4 delta_ij; ' = d/dxi).
   Velocity of a material point (D/Dt = d/dt at fixed material = d/dt|x +
   U d/dx; at fixed xi, d(xi)/dt = -xi U / l, so D/Dt = d/dt|xi + g eta
   d/dxi with g = U / l, eta = 1 - xi):
        Dw/Dt = sum_i [phi_i a_i' + g eta phi_i' a_i].
   It is zero at the exit (phi(0) = phi'(0) = 0): no lateral momentum or
   kinetic energy is carried through C, and the whole beam (inside part
   included) is a closed system of fixed material with the rheonomic
   Ritz field above, so Lagrange's equations hold with
        T = (rhoA l / 2) int_0^1 (Dw/Dt)^2 dxi
          = (rhoA l / 2) [a'^T M a' + 2 g a'^T G a + g^2 a^T C a],
        V = (EI / 2) int_0^l w_xx^2 dx = (EI / (2 l^3)) a^T K a,
        V_N = (1/2) int_0^l N w_x^2 dx = -(rhoA / 2) (U'' + alpha U) a^T A a,
   M_ij = int phi_i phi_j, G_ij = int phi_i eta phi_j', C_ij = int eta^2
   phi_i' phi_j', K_ij = int phi_i'' phi_j'', A_ij = int eta phi_i' phi_j'
   (all over 0..1, independent of t), U'' = U_A''.  V_N is the work of the axial force
   N(x) = -rhoA (U'' + alpha U)(l - x) (tension +) that accelerates the
   outside part axially (and pulls it against the alpha drag, below) on
   the second-order shortening (1/2) int w_x^2 of the projection: the
   term that makes accelerated deployment soften the beam; it is linear
   in w.  d/dt dT/da' - dT/da + dV/da + dV_N/da = Q_d, with l' = g l,
   G + G^T = M (integration by parts: eta(1) = 0, phi(0) = 0) and
   int phi_j eta^2 phi_i'' = 2 G_ji - C_ji, gives, divided by rhoA l,
        M a'' + 2 g G a' + (g' G + g^2 H) a + (c^2 / l^4) K a
              - ((U'' + alpha U) / l) A a = q_d,                      (E)
        H = G - C,  g' = U''/l - g^2,  c^2 = EI / rhoA.
   (E) is also the Galerkin projection of the axially moving beam equation
   rhoA D^2w/Dt^2 = -EI w_xxxx + (N w_x)_x onto the phi_j (the same
   matrices appear after integrating by parts), which is how it was
   checked.  Damping (eq. 56): the Rayleigh pair alpha(t), beta(t) of
   sb_rayleigh acting as in the other two models, on the material
   velocity (alpha rhoA Dw/Dt per length) and the material rate of the
   curvature (bending moment beta EI D(w_xx)/Dt), i.e. the dissipation
   function R = (1/2) int (alpha rhoA (Dw/Dt)^2 + beta EI (D w_xx/Dt)^2) dx:
        q_d = -alpha (M a' + g G a) - beta (c^2 / l^4) (K a' + g (P - 2 K) a),
   P_ij = int phi_i'' eta phi_j''' (D w_xx/Dt = l^-2 sum [phi_i'' a_i' +
   g (eta phi_i''' - 2 phi_i'') a_i]); the alpha drag on the axial motion
   enters N above.  Without damping alpha = beta = 0.
   Impulsive start (U jumps by dU at t = 0, a continuous): integrating (E)
   over the jump (g' and U'' carry dU delta(t)),
        M da' = (dU / l) (A - G) a,                                   (I)
   the Galerkin form of the string-like impulse response U (w_x -
   (l - x) w_xx) of an inextensible beam pulled by an impulsive tension.
   Steady start (shape at rest in space): M a' = g X a, X_ij = int phi_i
   xi phi_j'.  Static start: a = tip0 K^-1 phi(1) / (phi(1)^T K^-1 phi(1))
   (tip force, Galerkin).  The matrices come from composite Gauss-Legendre
   quadrature (16 panels x 8 points, double, independent of vlbe_real);
   the modes use the overflow-free form with 1 - s_i = (sin b - cos b -
   e^-b) / (sinh b + sin b).  (E) is integrated with classical RK4 at a
   fixed step (stable for omega_n h < 2.8; default h = 1e-4 s).

   References: K. M. Hsiao et al. (corotational-sliding-beam.txt) eqs. 54-56;
   B. Tabarrok, C. M. Leech, Y. I. Kim, On the dynamics of an axially moving
   beam, J. Franklin Inst. 297 (1974) 201-220; P. K. C. Wang, J.-D. Wei,
   Vibrations in a moving flexible robot arm, J. Sound Vib. 116 (1987)
   149-160; M. Stylianou, B. Tabarrok, Finite element analysis of an
   axially moving beam, J. Sound Vib. 178 (1994) 433-453 (the variable-
   length cantilever and its energy flux); L. Meirovitch, Fundamentals of
   Vibrations (2001), ch. 7-8 (assumed modes, Rayleigh dissipation). */
#ifndef VLBE_EX_XCHECK_H
#define VLBE_EX_XCHECK_H

#include "ex_sbeam.h"
#include "ex_cant.h"
#include "../ancf_ale.h"
#include "ex_ale.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define XC_NMAX 64 /* ALE elements, at most */
#define XC_MMAX 8  /* modes, at most        */

/* start of the ALE and assumed-modes runs (header comment) */
enum { XC_START_IMPULSE = 0, XC_START_STEADY = 1 };
/* assumed modes: the stiffness-proportional damping on the rate of the
   curvature at fixed xi = x/l instead of the material rate (drops the
   term g (P - 2K) a of q_d): the convention the co-rotational model
   follows through its transition element, whose beta k0 (eqs. 50-51)
   damps the rates of its coordinates over the outside segment at fixed
   s / L2 (sliding_xcheck.c, docs/results.md) */
#define XC_AM_BETA_FIXED_XI 1u

/* A history: tip deflection y(t) at the recorded instants. */
typedef struct xc_hist {
    int n, cap;
    double *t, *y;
} xc_hist;

static inline int xc_hist_alloc(xc_hist *h, int cap)
{
    memset(h, 0, sizeof *h);
    h->t = (double *)malloc((size_t)(2 * cap) * sizeof *h->t);
    if (!h->t) return -1;
    h->y = h->t + cap;
    h->cap = cap;
    return 0;
}

static inline void xc_hist_free(xc_hist *h)
{
    free(h->t);
    memset(h, 0, sizeof *h);
}

static inline void xc_hist_add(xc_hist *h, double t, double y)
{
    if (h->n < h->cap) {
        h->t[h->n] = t;
        h->y[h->n] = y;
        ++h->n;
    }
}

/* index of the sample of h at time t (within 1e-7 s), -1 if there is none */
static inline int xc_hist_find(const xc_hist *h, double t)
{
    int lo = 0, hi = h->n - 1;
    if (h->n < 1) return -1;
    while (hi - lo > 1) {
        const int mid = (lo + hi) / 2;
        if (h->t[mid] <= t) lo = mid;
        else hi = mid;
    }
    if (fabs(h->t[lo] - t) <= 1e-7) return lo;
    if (fabs(h->t[hi] - t) <= 1e-7) return hi;
    return -1;
}

/* y of h at time t (a sample within 1e-7 s), NaN if h has none there */
static inline double xc_hist_y(const xc_hist *h, double t)
{
    const int j = xc_hist_find(h, t);
    return j < 0 ? (double)NAN : h->y[j];
}

/* Difference s b - a at the instants that a and b both hold (within 1e-7
   s; no interpolation, which would add its own error) with t0 <= t <= t1;
   s scales b (10 for a run started at a tenth of the amplitude): largest
   |.| and root mean square.  Returns the number of instants used (no
   common instant: NaN). */
static inline int xc_diff(const xc_hist *a, const xc_hist *b, double s, double t0, double t1,
                          double *dmax, double *drms)
{
    double mx = 0.0, sq = 0.0;
    int k, n = 0;
    for (k = 0; k < a->n; ++k) {
        const double t = a->t[k];
        double d;
        int j;
        if (t < t0 - 1e-12 || t > t1 + 1e-12 || (j = xc_hist_find(b, t)) < 0) continue;
        d = s * b->y[j] - a->y[k];
        if (!(fabs(d) <= mx)) mx = fabs(d); /* NaN propagates */
        sq += d * d;
        ++n;
    }
    *dmax = n ? mx : (double)NAN;
    *drms = n ? sqrt(sq / n) : (double)NAN;
    return n;
}

/* ======================================================================= */
/* co-rotational model: sb_run with an observer that records the tip         */
/* ======================================================================= */
static inline void xc_cr_observe(void *ctx, const sb_model *m, double t, const vlbe_real *q,
                                 const vlbe_real *v)
{
    (void)v;
    xc_hist_add((xc_hist *)ctx, t, (double)q[m->n - 2]);
}

/* One run of ex_sbeam.h's model; returns its status, *cpu its seconds. */
static inline vlbe_status xc_cr_run(const sb_cfg *c, xc_hist *h, double *cpu)
{
    sb_model *m = (sb_model *)malloc(sizeof *m);
    sb_out out;
    if (!m) return VLBE_EWORK;
    h->n = 0;
    sb_run(m, c, xc_cr_observe, h, &out);
    free(m);
    if (cpu) *cpu = out.cpu;
    return out.status;
}

/* ======================================================================= */
/* (1) ALE-ANCF model                                                       */
/* ======================================================================= */
typedef struct xc_ale {
    sb_cfg cfg;
    int N;
    int stat;         /* 1: static solve (p' = p'' = 0, no damping) */
    double ra;        /* Rayleigh alpha of the current evaluation   */
    double P;         /* lateral tip load (static solve only)       */
    vlbe_ale_mat mat;
    vlbe_ale_elem el;
    vlbe_ale_node node[XC_NMAX + 1];
    vlbe_ale_con con[2];
    vlbe_ale_chain ch;
    vlbe_dae sys;
    int order[4 * (XC_NMAX + 1) + 3]; /* cfg.band: the augmented order */
} xc_ale;

typedef struct xc_ale_out {
    vlbe_status status;
    double cpu, F0;   /* seconds (static solve included); the tip force */
    long steps, newton, lu, rejected;
} xc_ale_out;

/* p, p', p'' of node i (all but the tip are prescribed) */
static inline int xc_ale_pfun(void *user, int i, vlbe_real t, vlbe_real *p3)
{
    const xc_ale *m = (const xc_ale *)user;
    const double f = (double)i / (double)m->N;
    double g[3], p0;
    sb_ua(&m->cfg, (double)t, g);
    p0 = m->cfg.L - m->cfg.L0 - g[0];
    p3[0] = (vlbe_real)(p0 + f * (m->cfg.L - p0));
    p3[1] = (vlbe_real)(m->stat ? 0.0 : -(1.0 - f) * g[1]);
    p3[2] = (vlbe_real)(m->stat ? 0.0 : -(1.0 - f) * g[2]);
    return 0;
}

/* Rayleigh pair of eq. 56 at t into the element (beta) and m->ra (alpha) */
static inline void xc_ale_damping(xc_ale *m, vlbe_real t)
{
    double ra = 0.0, rb = 0.0;
    if (m->cfg.damping && !m->stat) sb_rayleigh(&m->cfg, (double)t, &ra, &rb);
    m->ra = ra;
    m->el.mat.c_eps = m->el.mat.c_kap = (vlbe_real)rb;
}

/* -alpha M_e v_e of every element into Q (rows of coordinates) and, when K
   is given, -alpha d(M_e v_e)/dq into K and -alpha M into D (n x n, or the
   chain's band in banded mode). */
static inline int xc_ale_mass_damping(xc_ale *m, vlbe_real t, const vlbe_real *q,
                                      const vlbe_real *v, vlbe_real *Q, vlbe_real *K,
                                      vlbe_real *D)
{
    const vlbe_real a = (vlbe_real)m->ra;
    vlbe_real qe[10], ve[10], Me[100], Je[100];
    int e, i, j, idx[10];
    unsigned md;
    for (e = 0; e + 1 < m->ch.nn; ++e) {
        if (vlbe_ale_chain_gather(&m->ch, e, t, q, v, qe, ve, idx, &md) != VLBE_OK ||
            vlbe_ale_mass(&m->el, md, qe, Me) != VLBE_OK)
            return 1;
        if (K && vlbe_ale_mass_jac(&m->el, md, qe, ve, Je) != VLBE_OK) return 1;
        for (i = 0; i < 10; ++i) {
            if (idx[i] < 0) continue;
            if (Q) {
                vlbe_real s = VLBE_R(0.0);
                for (j = 0; j < 10; ++j) s += Me[i * 10 + j] * ve[j];
                Q[idx[i]] -= a * s;
            }
            if (K)
                for (j = 0; j < 10; ++j)
                    if (idx[j] >= 0) {
                        K[vlbe_ale_chain_at(&m->ch, idx[i], idx[j])] -= a * Je[i * 10 + j];
                        D[vlbe_ale_chain_at(&m->ch, idx[i], idx[j])] -= a * Me[i * 10 + j];
                    }
        }
    }
    return 0;
}

static inline int xc_ale_force(void *user, vlbe_real t, const vlbe_real *q, const vlbe_real *v,
                               vlbe_real *Q)
{
    xc_ale *m = (xc_ale *)user;
    int rc;
    xc_ale_damping(m, t);
    if ((rc = vlbe_ale_chain_force(&m->ch, t, q, v, Q)) != 0) return rc;
    if (m->ra != 0.0 && xc_ale_mass_damping(m, t, q, v, Q, NULL, NULL)) return 1;
    if (m->P != 0.0) Q[m->node[m->N].ofs + 1] += (vlbe_real)m->P;
    return 0;
}

static inline int xc_ale_force_jac(void *user, vlbe_real t, const vlbe_real *q,
                                   const vlbe_real *v, vlbe_real *K, vlbe_real *D)
{
    xc_ale *m = (xc_ale *)user;
    int rc;
    xc_ale_damping(m, t);
    if ((rc = vlbe_ale_chain_force_jac(&m->ch, t, q, v, K, D)) != 0) return rc;
    if (m->ra != 0.0 && xc_ale_mass_damping(m, t, q, v, NULL, K, D)) return 1;
    return 0;
}

/* vlbe_dae callbacks whose user is the xc_ale (mass, constraints: the chain's) */
static inline int xc_ale_mass(void *user, vlbe_real t, const vlbe_real *q, const vlbe_real *v,
                              vlbe_real *M)
{
    return vlbe_ale_chain_mass(&((xc_ale *)user)->ch, t, q, v, M);
}
static inline int xc_ale_mass_jac(void *user, vlbe_real t, const vlbe_real *q, const vlbe_real *v,
                                  const vlbe_real *a, vlbe_real *Mq, vlbe_real *Mv)
{
    return vlbe_ale_chain_mass_jac(&((xc_ale *)user)->ch, t, q, v, a, Mq, Mv);
}
static inline int xc_ale_constr(void *user, vlbe_real t, const vlbe_real *q, vlbe_real *C)
{
    return vlbe_ale_chain_constr(&((xc_ale *)user)->ch, t, q, C);
}
static inline int xc_ale_constr_jac(void *user, vlbe_real t, const vlbe_real *q, vlbe_real *Cq,
                                    vlbe_real *Ct)
{
    return vlbe_ale_chain_constr_jac(&((xc_ale *)user)->ch, t, q, Cq, Ct);
}
static inline int xc_ale_constr_acc(void *user, vlbe_real t, const vlbe_real *q,
                                    const vlbe_real *v, vlbe_real *gamma)
{
    return vlbe_ale_chain_constr_acc(&((xc_ale *)user)->ch, t, q, v, gamma);
}
static inline int xc_ale_constr_hess(void *user, vlbe_real t, const vlbe_real *q,
                                     const vlbe_real *lambda, vlbe_real *H)
{
    return vlbe_ale_chain_constr_hess(&((xc_ale *)user)->ch, t, q, lambda, H);
}

static inline void xc_ale_wire(xc_ale *m)
{
    vlbe_dae *s = &m->sys;
    memset(s, 0, sizeof *s);
    s->n = m->ch.n;
    s->m = m->ch.m;
    s->user = m;
    s->mass = xc_ale_mass;
    s->mass_jac = xc_ale_mass_jac;
    s->force = xc_ale_force;
    s->force_jac = xc_ale_force_jac;
    s->constr = xc_ale_constr;
    s->constr_jac = xc_ale_constr_jac;
    s->constr_acc = xc_ale_constr_acc;
    s->constr_hess = xc_ale_constr_hess;
    ex_ale_storage(s, &m->ch);
}

/* The chain of the header comment, straight along the axis. */
static inline vlbe_status xc_ale_build(xc_ale *m, const sb_cfg *c, int N, vlbe_real *q0)
{
    vlbe_ale_con k;
    vlbe_real r0[2] = {0, 0}, dir[2] = {1, 0};
    vlbe_real p3[3];
    vlbe_status st;
    int i;
    if (N < 1 || N > XC_NMAX) return VLBE_EARG;
    memset(m, 0, sizeof *m);
    m->cfg = *c;
    m->N = N;
    m->mat.rhoA = (vlbe_real)(c->rho * c->A);
    m->mat.EA = (vlbe_real)(c->E * c->A);
    m->mat.EI = (vlbe_real)(c->E * c->I);
    if ((st = vlbe_ale_elem_init(&m->el, &m->mat, 0u, 0, 0, 0)) != VLBE_OK) return st;
    if ((st = vlbe_ale_chain_init(&m->ch, &m->el, m->node, N + 1, XC_NMAX + 1, m->con, 2)) !=
        VLBE_OK)
        return st;
    m->ch.pfun = xc_ale_pfun;
    m->ch.user = m;
    for (i = 0; i < N; ++i) {
        m->node[i].pmode = VLBE_ALE_PPRESCRIBED;
        xc_ale_pfun(m, i, VLBE_R(0.0), p3);
        m->node[i].p = p3[0];
    }
    m->node[N].pmode = VLBE_ALE_PFIXED;
    m->node[N].p = (vlbe_real)c->L;
    memset(&k, 0, sizeof k);
    k.type = VLBE_ALE_CON_POS; /* node 0 at C = (0, 0) */
    if ((st = vlbe_ale_chain_add(&m->ch, &k)) != VLBE_OK) return st;
    k.type = VLBE_ALE_CON_SLOPE_DIR; /* r' of node 0 along the axis (1, 0) */
    k.d[0] = VLBE_R(1.0);
    if ((st = vlbe_ale_chain_add(&m->ch, &k)) != VLBE_OK) return st;
    if ((st = vlbe_ale_chain_layout(&m->ch)) != VLBE_OK) return st;
    if (c->band &&
        (st = ex_ale_band(&m->ch, m->order, (int)(sizeof m->order / sizeof m->order[0]))) !=
            VLBE_OK)
        return st;
    xc_ale_wire(m);
    vlbe_ale_chain_straight(&m->ch, r0, dir, q0);
    return VLBE_OK;
}

/* Static deflection by a tip force scaled to tip0 (as sb_static). */
static inline vlbe_status xc_ale_static(xc_ale *m, vlbe_real *q, double *force)
{
    const int nc = m->ch.m;
    vlbe_static_params sp;
    const size_t lw = vlbe_static_work_len_sys(&m->sys), liw = vlbe_static_iwork_len_sys(&m->sys);
    vlbe_real *w = (vlbe_real *)malloc((lw + (size_t)nc) * sizeof *w);
    int *iw = (int *)malloc(liw * sizeof *iw);
    vlbe_real *lam = w ? w + lw : NULL;
    vlbe_status st = VLBE_EWORK;
    double F = 3.0 * m->cfg.E * m->cfg.I * m->cfg.tip0 / pow(m->cfg.L0, 3.0), tip;
    int it, i;
    if (w && iw) {
        vlbe_static_params_default(&sp);
        for (i = 0; i < nc; ++i) lam[i] = VLBE_R(0.0);
        m->stat = 1;
        for (it = 0; it < 20; ++it) {
            m->P = F;
            if ((st = vlbe_dae_static(&m->sys, &sp, VLBE_R(0.0), q, lam, NULL, w, lw, iw, liw)) !=
                VLBE_OK)
                break;
            tip = (double)q[m->node[m->N].ofs + 1];
            if (fabs(tip - m->cfg.tip0) <= 1e-10 * m->cfg.tip0) break;
            F *= m->cfg.tip0 / tip;
        }
        m->stat = 0;
        m->P = 0.0;
        *force = F;
    }
    free(w);
    free(iw);
    return st;
}

/* Velocities just after the impulsive start (material at rest before):
   [M C_q^T; C_q 0] [v; Lambda] = [-M_qp p'; -C_t] at t = 0.  A one-off
   dense solve; a banded chain is switched to dense for it and back. */
static inline vlbe_status xc_ale_impulse_dense(xc_ale *m, const vlbe_real *q, vlbe_real *v);
static inline vlbe_status xc_ale_impulse(xc_ale *m, const vlbe_real *q, vlbe_real *v)
{
    int *const order = m->ch.order;
    const int cap = m->ch.order_cap;
    vlbe_status st, sb;
    if (!order) return xc_ale_impulse_dense(m, q, v);
    if ((st = ex_ale_band(&m->ch, NULL, 0)) != VLBE_OK) return st;
    st = xc_ale_impulse_dense(m, q, v);
    sb = ex_ale_band(&m->ch, order, cap);
    return st != VLBE_OK ? st : sb;
}
static inline vlbe_status xc_ale_impulse_dense(xc_ale *m, const vlbe_real *q, vlbe_real *v)
{
    const int n = m->ch.n, nc = m->ch.m, N = n + nc;
    const size_t nn = (size_t)n * (size_t)n, NN = (size_t)N * (size_t)N;
    vlbe_real *A = (vlbe_real *)calloc(2 * NN + nn + (size_t)nc * (size_t)n + (size_t)(N + nc),
                                       sizeof *A);
    vlbe_real *LU = A ? A + NN : NULL, *M = LU ? LU + NN : NULL, *Cq = M ? M + nn : NULL;
    vlbe_real *b = Cq ? Cq + (size_t)nc * (size_t)n : NULL, *Ct = b ? b + N : NULL;
    int *piv = (int *)malloc((size_t)N * sizeof *piv), info, e, i, j, idx[10];
    vlbe_real qe[10], ve[10], Me[100];
    unsigned md;
    vlbe_status st = VLBE_EWORK;
    if (!A || !piv) goto done;
    for (i = 0; i < n; ++i) v[i] = VLBE_R(0.0);
    st = VLBE_ECALLBACK;
    if (vlbe_ale_chain_mass(&m->ch, VLBE_R(0.0), q, v, M) ||
        vlbe_ale_chain_constr_jac(&m->ch, VLBE_R(0.0), q, Cq, Ct))
        goto done;
    for (i = 0; i < n; ++i)
        for (j = 0; j < n; ++j) A[(size_t)i * N + j] = M[(size_t)i * n + j];
    for (i = 0; i < nc; ++i) {
        for (j = 0; j < n; ++j)
            A[(size_t)(n + i) * N + j] = A[(size_t)j * N + n + i] = Cq[(size_t)i * n + j];
        b[n + i] = -Ct[i];
    }
    /* -M_qp p': the element mass columns of the prescribed p's (the chain
       gives them the p' of t = 0 in ve; all other entries of ve are zero) */
    for (e = 0; e + 1 < m->ch.nn; ++e) {
        if (vlbe_ale_chain_gather(&m->ch, e, VLBE_R(0.0), q, v, qe, ve, idx, &md) != VLBE_OK ||
            vlbe_ale_mass(&m->el, md, qe, Me) != VLBE_OK)
            goto done;
        for (i = 0; i < 10; ++i)
            if (idx[i] >= 0)
                for (j = 0; j < 10; ++j)
                    if (idx[j] < 0) b[idx[i]] -= Me[i * 10 + j] * ve[j];
    }
    if ((st = vlbe_lu_factor(N, A, LU, piv, &info)) != VLBE_OK) goto done;
    vlbe_lu_solve(N, LU, piv, 1, b);
    for (i = 0; i < n; ++i) v[i] = b[i];
done:
    free(A);
    free(piv);
    return st;
}

/* The whole run: static start, the start velocities, HHT to t_end; the tip
   deflection of every step into h (may be NULL). */
static inline xc_ale_out xc_ale_run(const sb_cfg *c, int N, int start, xc_hist *h)
{
    xc_ale_out res;
    xc_ale *m = (xc_ale *)malloc(sizeof *m);
    const int nmax = 4 * (XC_NMAX + 1);
    vlbe_real *q = (vlbe_real *)calloc((size_t)(2 * nmax), sizeof *q), *v = q ? q + nmax : NULL;
    vlbe_hht_params par;
    vlbe_hht st;
    vlbe_real *w = NULL;
    int *iw = NULL, tip;
    size_t lw, liw;
    long k, nsteps;
    clock_t c0 = clock();
    memset(&res, 0, sizeof res);
    res.status = VLBE_EWORK;
    if (h) h->n = 0;
    if (!m || !q) goto done;
    if ((res.status = xc_ale_build(m, c, N, q)) != VLBE_OK) goto done;
    if ((res.status = xc_ale_static(m, q, &res.F0)) != VLBE_OK) goto done;
    if (start == XC_START_IMPULSE && (res.status = xc_ale_impulse(m, q, v)) != VLBE_OK) goto done;
    lw = vlbe_hht_work_len_sys(&m->sys);
    liw = vlbe_hht_iwork_len_sys(&m->sys);
    w = (vlbe_real *)malloc(lw * sizeof *w);
    iw = (int *)malloc(liw * sizeof *iw);
    res.status = VLBE_EWORK;
    if (!w || !iw) goto done;
    if ((res.status = ex_hht_pick(&par, c->alpha, c->rho_inf)) != VLBE_OK) goto done;
    par.max_halvings = 6;
    par.modified = 0;
    tip = m->node[N].ofs + 1;
    if (h) xc_hist_add(h, 0.0, (double)q[tip]);
    if ((res.status = vlbe_hht_init(&st, &m->sys, &par, VLBE_R(0.0), q, v, w, lw, iw, liw)) !=
        VLBE_OK)
        goto done;
    nsteps = (long)floor(c->t_end / c->h + 0.5);
    for (k = 1; k <= nsteps; ++k) {
        if ((res.status = vlbe_hht_step(&st, (vlbe_real)c->h)) != VLBE_OK) break;
        if (h) xc_hist_add(h, (double)st.t, (double)st.q[tip]);
    }
    res.steps = st.stats.steps;
    res.newton = st.stats.newton_iters;
    res.lu = st.stats.lu_factors;
    res.rejected = st.stats.rejected;
done:
    res.cpu = (double)(clock() - c0) / CLOCKS_PER_SEC;
    free(m);
    free(q);
    free(w);
    free(iw);
    return res;
}

/* ======================================================================= */
/* (2) assumed-modes model                                                  */
/* ======================================================================= */
#define XC_QP 128 /* quadrature points: 16 panels x 8 Gauss-Legendre */

typedef struct xc_am {
    sb_cfg cfg;
    int nm;
    unsigned flags;                    /* XC_AM_BETA_FIXED_XI or 0         */
    double c2;                         /* EI / rhoA                        */
    double b[XC_MMAX];                 /* b_i = beta_i L                   */
    double tipv[XC_MMAX];              /* phi_i(1)                         */
    double M[XC_MMAX * XC_MMAX], G[XC_MMAX * XC_MMAX], H[XC_MMAX * XC_MMAX];
    double A[XC_MMAX * XC_MMAX], K[XC_MMAX * XC_MMAX], P[XC_MMAX * XC_MMAX];
    double X[XC_MMAX * XC_MMAX], C[XC_MMAX * XC_MMAX];
    double Minv[XC_MMAX * XC_MMAX];
    double xq[XC_QP], wq[XC_QP];       /* composite rule on [0, 1]          */
} xc_am;

typedef struct xc_am_out {
    int status;       /* 0 ok, -1 bad input / singular, -2 non-finite state */
    double cpu;
    long steps;
} xc_am_out;


/* phi and its first three xi-derivatives for root b at xi (overflow-free) */
static inline void xc_am_mode(double b, double xi, double *d)
{
    const double sb = sinh(b) + sin(b);
    const double s = (cosh(b) + cos(b)) / sb, oms = (sin(b) - cos(b) - exp(-b)) / sb; /* 1 - s */
    const double x = b * xi, ep = 0.5 * oms * exp(x), em = 0.5 * (1.0 + s) * exp(-x);
    const double c = cos(x), sn = sin(x);
    d[0] = ep + em - c + s * sn;
    d[1] = b * (ep - em + sn + s * c);
    d[2] = b * b * (ep + em + c - s * sn);
    d[3] = b * b * b * (ep - em - sn - s * c);
}

/* n-point Gauss-Legendre on [-1, 1] (Newton on P_n, double).  Not
   vlbe_gl_rule / vlbe_lu_*: those work in vlbe_real, i.e. in float in the
   float build, and this reference model stays double in every build (its
   tests assert modal orthonormality to 1e-12 there too). */
static inline void xc_gauss(int n, double *x, double *w)
{
    int i, k, it;
    for (i = 0; i < n; ++i) {
        double z = cos(3.14159265358979323846 * (i + 0.75) / (n + 0.5)), dp = 1.0;
        for (it = 0; it < 100; ++it) {
            double p0 = 1.0, p1 = z, dz;
            for (k = 2; k <= n; ++k) {
                const double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
                p0 = p1;
                p1 = p2;
            }
            dp = n * (z * p1 - p0) / (z * z - 1.0);
            dz = p1 / dp;
            z -= dz;
            if (fabs(dz) <= 1e-16) break;
        }
        x[i] = z;
        w[i] = 2.0 / ((1.0 - z * z) * dp * dp);
    }
}

/* inverse of the n x n matrix a (Gauss-Jordan, partial pivoting); 0 ok */
static inline int xc_inv(int n, const double *a, double *inv)
{
    double t[XC_MMAX * 2 * XC_MMAX] = {0};
    int i, j, k;
    for (i = 0; i < n; ++i)
        for (j = 0; j < 2 * n; ++j) t[i * 2 * n + j] = j < n ? a[i * n + j] : (j - n == i);
    for (k = 0; k < n; ++k) {
        int p = k;
        double d;
        for (i = k + 1; i < n; ++i)
            if (fabs(t[i * 2 * n + k]) > fabs(t[p * 2 * n + k])) p = i;
        if (!(fabs(t[p * 2 * n + k]) > 0.0)) return -1;
        for (j = 0; j < 2 * n; ++j) {
            const double s = t[k * 2 * n + j];
            t[k * 2 * n + j] = t[p * 2 * n + j];
            t[p * 2 * n + j] = s;
        }
        d = 1.0 / t[k * 2 * n + k];
        for (j = 0; j < 2 * n; ++j) t[k * 2 * n + j] *= d;
        for (i = 0; i < n; ++i)
            if (i != k) {
                const double f = t[i * 2 * n + k];
                for (j = 0; j < 2 * n; ++j) t[i * 2 * n + j] -= f * t[k * 2 * n + j];
            }
    }
    for (i = 0; i < n; ++i)
        for (j = 0; j < n; ++j) inv[i * n + j] = t[i * 2 * n + n + j];
    return 0;
}

/* Roots, quadrature and the matrices of (E); 0 ok. */
static inline int xc_am_init(xc_am *m, const sb_cfg *c, int nm)
{
    double gx[8], gw[8], d[XC_MMAX][4];
    int i, j, k, p;
    if (nm < 1 || nm > XC_MMAX) return -1;
    memset(m, 0, sizeof *m);
    m->cfg = *c;
    m->nm = nm;
    m->c2 = c->E * c->I / (c->rho * c->A);
    xc_gauss(8, gx, gw);
    for (p = 0; p < 16; ++p)
        for (k = 0; k < 8; ++k) {
            m->xq[p * 8 + k] = (p + 0.5 + 0.5 * gx[k]) / 16.0;
            m->wq[p * 8 + k] = gw[k] / 32.0;
        }
    for (i = 0; i < nm; ++i) {
        m->b[i] = ex_cant_root(i + 1);
        xc_am_mode(m->b[i], 1.0, d[0]);
        m->tipv[i] = d[0][0];
    }
    for (k = 0; k < XC_QP; ++k) {
        const double xi = m->xq[k], w = m->wq[k], eta = 1.0 - xi;
        for (i = 0; i < nm; ++i) xc_am_mode(m->b[i], xi, d[i]);
        for (i = 0; i < nm; ++i)
            for (j = 0; j < nm; ++j) {
                const int ij = i * nm + j;
                m->M[ij] += w * d[i][0] * d[j][0];
                m->G[ij] += w * d[i][0] * eta * d[j][1];
                m->C[ij] += w * eta * eta * d[i][1] * d[j][1];
                m->A[ij] += w * eta * d[i][1] * d[j][1];
                m->K[ij] += w * d[i][2] * d[j][2];
                m->P[ij] += w * d[i][2] * eta * d[j][3];
                m->X[ij] += w * d[i][0] * xi * d[j][1];
            }
    }
    for (i = 0; i < nm * nm; ++i) m->H[i] = m->G[i] - m->C[i];
    return xc_inv(nm, m->M, m->Minv);
}

/* y = A x, n x n */
static inline void xc_mv(int n, const double *A, const double *x, double *y)
{
    int i, j;
    for (i = 0; i < n; ++i) {
        double s = 0.0;
        for (j = 0; j < n; ++j) s += A[i * n + j] * x[j];
        y[i] = s;
    }
}

/* (E): the rates of the state s = (a, a') at t */
static inline void xc_am_rhs(const xc_am *m, double t, const double *s, double *ds)
{
    const int n = m->nm;
    const double *a = s, *ad = s + n;
    double g3[3], l, g, gd, kf, bc, ra = 0.0, rb = 0.0, Ga[XC_MMAX], Gd[XC_MMAX], Ha[XC_MMAX];
    double Ka[XC_MMAX], Kd[XC_MMAX], Aa[XC_MMAX], Pa[XC_MMAX], Md[XC_MMAX], f[XC_MMAX];
    int i;
    sb_ua(&m->cfg, t, g3);
    l = m->cfg.L0 + g3[0];
    g = g3[1] / l;
    gd = g3[2] / l - g * g;
    kf = m->c2 / (l * l * l * l);
    bc = (m->flags & XC_AM_BETA_FIXED_XI) ? 0.0 : 1.0;
    if (m->cfg.damping) sb_rayleigh(&m->cfg, t, &ra, &rb);
    xc_mv(n, m->G, a, Ga);
    xc_mv(n, m->G, ad, Gd);
    xc_mv(n, m->H, a, Ha);
    xc_mv(n, m->K, a, Ka);
    xc_mv(n, m->K, ad, Kd);
    xc_mv(n, m->A, a, Aa);
    xc_mv(n, m->P, a, Pa);
    xc_mv(n, m->M, ad, Md);
    for (i = 0; i < n; ++i)
        f[i] = -2.0 * g * Gd[i] - gd * Ga[i] - g * g * Ha[i] - kf * Ka[i] +
               (g3[2] + ra * g3[1]) / l * Aa[i] - ra * (Md[i] + g * Ga[i]) -
               rb * kf * (Kd[i] + bc * g * (Pa[i] - 2.0 * Ka[i]));
    for (i = 0; i < n; ++i) ds[i] = ad[i];
    xc_mv(n, m->Minv, f, ds + n);
}

/* Start state: static deflection tip0, rates of the chosen start. */
static inline void xc_am_start(const xc_am *m, int start, double *s)
{
    const int n = m->nm;
    double Kinv[XC_MMAX * XC_MMAX], z[XC_MMAX] = {0}, r[XC_MMAX] = {0}, g3[3], l, den = 0.0;
    int i, j;
    xc_inv(n, m->K, Kinv);
    xc_mv(n, Kinv, m->tipv, z);
    for (i = 0; i < n; ++i) den += m->tipv[i] * z[i];
    for (i = 0; i < n; ++i) s[i] = m->cfg.tip0 * z[i] / den;
    sb_ua(&m->cfg, 0.0, g3);
    l = m->cfg.L0 + g3[0];
    for (i = 0; i < n; ++i) {
        double v = 0.0;
        for (j = 0; j < n; ++j)
            v += (start == XC_START_IMPULSE ? m->A[i * n + j] - m->G[i * n + j] : m->X[i * n + j]) *
                 s[j];
        r[i] = g3[1] / l * v;
    }
    xc_mv(n, m->Minv, r, s + n);
}

/* tip deflection sum phi_i(1) a_i */
static inline double xc_am_tip(const xc_am *m, const double *s)
{
    double y = 0.0;
    int i;
    for (i = 0; i < m->nm; ++i) y += m->tipv[i] * s[i];
    return y;
}

/* xc_am_rhs as an ex_rhs (ctx = the xc_am) */
static inline void xc_am_rhs_cb(const void *ctx, double t, const double *s, double *ds)
{
    xc_am_rhs((const xc_am *)ctx, t, s, ds);
}

/* One classical RK4 step of length h from t (ex_rk4_step). */
static inline void xc_am_rk4(const xc_am *m, double t, double h, double *s)
{
    ex_rk4_step(2 * m->nm, xc_am_rhs_cb, m, t, h, s);
}

/* The whole run: nm modes, RK4 step h, the tip recorded every `every`
   steps into hist (may be NULL); flags: XC_AM_BETA_FIXED_XI or 0. */
static inline xc_am_out xc_am_run(const sb_cfg *c, int nm, double h, int every, int start,
                                  unsigned flags, xc_hist *hist)
{
    xc_am_out res;
    xc_am *m = (xc_am *)malloc(sizeof *m);
    double s[2 * XC_MMAX];
    long k, nsteps;
    int i;
    clock_t c0 = clock();
    memset(&res, 0, sizeof res);
    res.status = -1;
    if (hist) hist->n = 0;
    if (!m || !(h > 0.0) || every < 1 || xc_am_init(m, c, nm)) goto done;
    m->flags = flags;
    res.status = 0;
    xc_am_start(m, start, s);
    if (hist) xc_hist_add(hist, 0.0, xc_am_tip(m, s));
    nsteps = (long)floor(c->t_end / h + 0.5);
    for (k = 1; k <= nsteps; ++k) {
        xc_am_rk4(m, (k - 1) * h, h, s);
        for (i = 0; i < 2 * nm; ++i)
            if (!isfinite(s[i])) {
                res.status = -2;
                goto done;
            }
        if (hist && k % every == 0) xc_hist_add(hist, k * h, xc_am_tip(m, s));
        ++res.steps;
    }
done:
    res.cpu = (double)(clock() - c0) / CLOCKS_PER_SEC;
    free(m);
    return res;
}

#endif /* VLBE_EX_XCHECK_H */
