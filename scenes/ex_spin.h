/* ex_spin.h -- spin-up of a flexible cantilever clamped to a hub turning
   about a fixed axis (Simo & Vu-Quoc style), no gravity, in three models:
     SP_CR      the co-rotational beam of corot2d.h (nonlinear),
     SP_LINEAR  its LINEAR element in a floating frame turned by the hub
                angle (linear FFRF-equivalent: centrifugal softening, no
                stiffening),
     SP_ANCF    the planar ANCF beam of ancf_ale.h with both p fixed (ALE
                off; nonlinear: Green axial strain, exact curvature).
   Model, hub angle, the run driver that stops with VLBE_EBOUND when the tip
   leaves a bound, the tip in the hub frame.  Shared by examples/spin_up.c,
   tests/test_scenes_spin.c and bench/wp_spin.c.
   -- part of vlbe                                  SPDX-License-Identifier: MIT

   Beam: L = 10 m, EA = 2.8e7 N, EI = 1.4e4 N m^2, rhoA = 1.2 kg/m, rhoI = 0
   (Euler-Bernoulli, no rotary inertia), ne equal elements along +x from
   the hub axis at the origin.  The hub angle
        theta(t) = (W/Ts) [t^2/2 + (Ts/2pi)^2 (cos(2 pi t/Ts) - 1)],  t <= Ts,
                 = W (t - Ts/2),                                      t > Ts
   (theta' rises smoothly from 0 to W in Ts, theta'' = 0 at both ends).
   CR / LINEAR: node 0 is clamped to the hub: u0 = v0 = 0, phi0 = theta(t)
   (prescribed coordinates, index-3 constraints).  LINEAR: beam.frame = the
   same theta(t): every element measures its deformation in the hub frame
   (corot2d.h, floating frame).
   ANCF: node 0 at the origin (VLBE_ALE_CON_POS) with its slope along the
   hub direction (VLBE_ALE_CON_SLOPE_ANGLE, a = theta(t) through the chain's
   afun): 3 constraint rows as in CR; the slope's length (axial strain at
   the root) stays free.  Force routes (cfg.inv): Gauss points, element
   invariants (VLBE_ALE_INV_AXIAL) or the system invariants of the whole
   chain (axial force from vlbe_ale_inv_sys_force, bending on Gauss points
   by a second element type with EA = 0).
   Tip in the hub frame: r = R^T(theta) r_tip, axial deflection r_x - L,
   transverse r_y.
   First cantilever bending frequency at rest: 1.8751^2 sqrt(EI/rhoA)/L^2
   = 3.80 rad/s: the linear model loses its first bending stiffness when
   theta' exceeds it (K - theta'^2 M indefinite) and diverges; the
   nonlinear ones stiffen (centrifugal tension) and stay bounded.

   Damping (scene 3; all off by default):
     cfg.ray_a, ray_b  CR / LINEAR: Rayleigh of corot2d.h
     cfg.c_kv          ANCF: Kelvin-Voigt time of axial strain and
                       curvature (mat.c_eps = mat.c_kap): strain rates,
                       frame invariant
     cfg.abs_a, abs_b  ANCF: damping on the absolute nodal velocities,
                       Q_d = -(abs_a M + abs_b K0) v with M the (constant)
                       mass matrix and K0 the stiffness of the straight
                       beam at rest (the classic Rayleigh damping of a
                       linear code applied to absolute coordinates)
   At rest (theta = 0, small motion) c_kv = c and abs_b = c are the same
   damping (the Kelvin-Voigt damping matrix of the straight beam is c K0);
   under a rigid rotation the first dissipates nothing, the second does.

   Run: HHT-alpha (default alpha = -0.05; or generalized-alpha, BDF) with
   the fixed step h, step halvings on Newton failure; after each step the
   tip displacement in the hub frame |(r_x - L, r_y)| is checked against
   cfg.bound (> 0): beyond it the run stops with VLBE_EBOUND (the
   divergence is a status, not NaN). */
#ifndef VLBE_EX_SPIN_H
#define VLBE_EX_SPIN_H

#include "../ancf_ale.h"
#include "../corot2d.h"
#include "../integrators.h"
#include "ex_ale.h"
#include "ex_cr2d.h"
#include "ex_run.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define SP_MAXEL 64
#define SP_NMAX (4 * (SP_MAXEL + 1)) /* coordinates at most (ANCF)        */
#define SP_NAMAX (SP_NMAX + 3)       /* coordinates and constraint rows    */
#define SP_PI 3.14159265358979323846

/* models (cfg.model) */
#define SP_CR 0
#define SP_LINEAR 1
#define SP_ANCF 2

/* ANCF force routes (cfg.inv) */
#define SP_GAUSS 0
#define SP_INV_ELEM 1
#define SP_INV_SYS 2

typedef struct sp_cfg {
    double L, EA, EI, rhoA, rhoI;
    double ray_a, ray_b; /* Rayleigh damping (0: none)                     */
    int ne;              /* elements                                       */
    double W, Ts;        /* final hub speed [rad/s], spin-up time [s]       */
    int model;           /* SP_CR, SP_LINEAR, SP_ANCF                      */
    int inv;             /* ANCF: SP_GAUSS, SP_INV_ELEM, SP_INV_SYS        */
    double c_kv;         /* ANCF: Kelvin-Voigt time [s]                    */
    double abs_a, abs_b; /* ANCF: damping -(a M + b K0) v on absolute rates */
    double h, t_end;     /* step, end time (HHT family)                    */
    double alpha;        /* HHT alpha (0: trapezoidal Newmark)             */
    double rho_inf;      /* > 0: generalized-alpha with this rho_inf       */
    double bdf_rtol;     /* > 0: BDF (variable order and step) with this
                            rtol (and atol = rtol in m, m/s), instead of the HHT
                            family                                         */
    int bdf_max_order;   /* BDF: highest order (0: the default, 5)          */
    double bound;        /* stop with VLBE_EBOUND when |tip| > bound (0: off) */
    int max_halvings;    /* step halvings on Newton failure (0: 10)        */
    int band;            /* 1: banded matrices (vlbe_ale_chain_band,
                            vlbe_cr2d_beam_band), the integrators' banded
                            path; 0: dense (default)                       */
} sp_cfg;

/* The scene: L = 10 m, EA = 2.8e7 N, EI = 1.4e4 N m^2, rhoA = 1.2 kg/m,
   rhoI = 0, Ts = 15 s, t_end = 20 s; 8 elements, h = 5 ms, HHT alpha =
   -0.05, bound L/10; no damping. */
static inline void sp_cfg_default(sp_cfg *c, double W, int model)
{
    memset(c, 0, sizeof *c);
    c->L = 10.0;
    c->EA = 2.8e7;
    c->EI = 1.4e4;
    c->rhoA = 1.2;
    c->rhoI = 0.0;
    c->ne = 8;
    c->W = W;
    c->Ts = 15.0;
    c->model = model;
    c->h = 5e-3;
    c->t_end = 20.0;
    c->alpha = -0.05;
    c->bound = 1.0;
}

/* theta, theta', theta'' of the hub at t */
static inline void sp_theta(const sp_cfg *c, double t, double *g)
{
    if (t <= c->Ts) {
        const double w = 2.0 * SP_PI / c->Ts, k = c->W / c->Ts;
        g[0] = k * (0.5 * t * t + (cos(w * t) - 1.0) / (w * w));
        g[1] = k * (t - sin(w * t) / w);
        g[2] = k * (1.0 - cos(w * t));
    } else {
        g[0] = c->W * (t - 0.5 * c->Ts);
        g[1] = c->W;
        g[2] = 0.0;
    }
}

/* first bending frequency of the cantilever at rest [rad/s] */
static inline double sp_omega1(const sp_cfg *c)
{
    return 1.87510407 * 1.87510407 * sqrt(c->EI / c->rhoA) / (c->L * c->L);
}

static inline void sp_theta_fun(void *ctx, vlbe_real t, vlbe_real *g3)
{
    double g[3];
    sp_theta((const sp_cfg *)ctx, (double)t, g);
    ex_real3(g, g3);
}

typedef struct sp_model {
    sp_cfg cfg;
    int n;
    /* CR / LINEAR */
    vlbe_cr2d_elem el[SP_MAXEL];
    vlbe_cr2d_fix fix[3]; /* u0 = 0, v0 = 0, phi0 = theta(t) */
    vlbe_cr2d_beam beam;
    /* ANCF */
    vlbe_ale_elem ael;       /* the beam's element type                  */
    vlbe_ale_elem abend;     /* SP_INV_SYS: the same with EA = 0 (bending) */
    vlbe_ale_node nodes[SP_MAXEL + 1];
    vlbe_ale_con cons[2];
    vlbe_ale_chain ch;
    vlbe_ale_inv_sys isys;   /* SP_INV_SYS: the axial system invariants    */
    vlbe_real Lel[SP_MAXEL];
    vlbe_real isys_work[158 * SP_MAXEL + 40];
    vlbe_real band[2][SP_NMAX * VLBE_ALE_INV_BW];
    vlbe_real *Dabs;         /* abs_a, abs_b: -(abs_a M + abs_b K0), n x n
                                (cfg.band: the chain's band)                */
    vlbe_real Dabs_buf[SP_NMAX * SP_NMAX];
    vlbe_real scratch[SP_NMAX * SP_NMAX];
    vlbe_real vtmp[SP_NMAX];
    vlbe_real vaug[2][SP_NAMAX]; /* cfg.band: Dabs v in the augmented order */
    int order[SP_NAMAX];     /* cfg.band: the augmented order (chain, beam) */
    vlbe_dae sys;
} sp_model;

/* a = theta(t) of the ANCF hub clamp (chain afun; the chain's user is the
   sp_model) */
static inline int sp_afun(void *user, int con, vlbe_real t, vlbe_real *a3)
{
    (void)con;
    sp_theta_fun(&((sp_model *)user)->cfg, t, a3);
    return 0;
}

/* vlbe_dae force callbacks of the ANCF model (user = the sp_model): the
   chain's forces, with SP_INV_SYS the chain carries bending only and the
   axial force comes from the system invariants; then the absolute-velocity
   damping when set.  user = the chain (as for the chain's own callbacks),
   whose user is the sp_model.
   sp_band_add: the invariants' band B (natural order, VLBE_ALE_INV_BW per
   row) added to a matrix of the chain's callbacks (n x n, or in banded
   mode the chain's band: the entries B couples lie in an element, inside
   the chain's band; the zeros between elements outside it are skipped). */
static inline void sp_band_add(const vlbe_ale_chain *ch, const vlbe_real *B, vlbe_real *A)
{
    const int n = ch->n;
    int i, j;
    for (i = 0; i < n; ++i)
        for (j = i - VLBE_ALE_INV_KD; j <= i + VLBE_ALE_INV_KD; ++j)
            if (j >= 0 && j < n) {
                const vlbe_real b = B[(size_t)i * VLBE_ALE_INV_BW + (size_t)(j - i + VLBE_ALE_INV_KD)];
                if (ch->order && (ch->order[j] - ch->order[i] > ch->ku ||
                                  ch->order[i] - ch->order[j] > ch->kl)) {
                    VLBE_ASSERT(b == VLBE_R(0.0));
                    continue;
                }
                A[vlbe_ale_chain_at(ch, i, j)] += b;
            }
}

/* y = Dabs v (n): dense, or in banded mode through the augmented vectors
   (the constraint rows' slots zero) */
static inline void sp_dabs_v(sp_model *m, const vlbe_real *v, vlbe_real *y)
{
    const vlbe_ale_chain *ch = &m->ch;
    const int n = m->n, na = ch->n + ch->m;
    int i;
    if (!ch->order) {
        vlbe_mat_vec(n, n, m->Dabs, v, y);
        return;
    }
    vlbe_vec_zero(na, m->vaug[0]);
    for (i = 0; i < n; ++i) m->vaug[0][ch->order[i]] = v[i];
    vlbe_band_mat_vec(na, ch->kl, ch->ku, m->Dabs, ch->kl + ch->ku + 1, m->vaug[0], m->vaug[1]);
    for (i = 0; i < n; ++i) y[i] = m->vaug[1][ch->order[i]];
}

static inline int sp_ancf_force(void *user, vlbe_real t, const vlbe_real *q, const vlbe_real *v,
                                vlbe_real *Q)
{
    sp_model *m = (sp_model *)((vlbe_ale_chain *)user)->user;
    const int n = m->n;
    int rc, i;
    if ((rc = vlbe_ale_chain_force(&m->ch, t, q, v, Q)) != 0) return rc;
    if (m->cfg.inv == SP_INV_SYS) {
        if (vlbe_ale_inv_sys_force(&m->isys, q, v, m->vtmp, NULL, NULL) != VLBE_OK) return -1;
        for (i = 0; i < n; ++i) Q[i] += m->vtmp[i];
    }
    if (m->Dabs) {
        sp_dabs_v(m, v, m->vtmp);
        for (i = 0; i < n; ++i) Q[i] += m->vtmp[i];
    }
    return 0;
}

static inline int sp_ancf_force_jac(void *user, vlbe_real t, const vlbe_real *q,
                                    const vlbe_real *v, vlbe_real *K, vlbe_real *D)
{
    sp_model *m = (sp_model *)((vlbe_ale_chain *)user)->user;
    const size_t len = vlbe_ale_chain_mat_len(&m->ch); /* n x n, or the band */
    size_t i;
    int rc;
    if ((rc = vlbe_ale_chain_force_jac(&m->ch, t, q, v, K, D)) != 0) return rc;
    if (m->cfg.inv == SP_INV_SYS) {
        if (vlbe_ale_inv_sys_force(&m->isys, q, v, m->vtmp, m->band[0], m->band[1]) != VLBE_OK)
            return -1;
        sp_band_add(&m->ch, m->band[0], K);
        sp_band_add(&m->ch, m->band[1], D);
    }
    if (m->Dabs)
        for (i = 0; i < len; ++i) D[i] += m->Dabs[i];
    return 0;
}

static inline vlbe_status sp_init_ancf(sp_model *m, const sp_cfg *c)
{
    vlbe_ale_mat mat;
    vlbe_ale_con k;
    vlbe_status st;
    int i;
    memset(&mat, 0, sizeof mat);
    mat.rhoA = (vlbe_real)c->rhoA;
    mat.EA = (vlbe_real)c->EA;
    mat.EI = (vlbe_real)c->EI;
    mat.c_eps = mat.c_kap = (vlbe_real)c->c_kv;
    if (c->inv < SP_GAUSS || c->inv > SP_INV_SYS || c->c_kv < 0.0 || c->abs_a < 0.0 ||
        c->abs_b < 0.0 || c->rhoI != 0.0)
        return VLBE_EARG;
    if ((st = vlbe_ale_elem_init(&m->ael, &mat, VLBE_ALE_FIX_P1 | VLBE_ALE_FIX_P2 |
                                 (c->inv == SP_INV_ELEM ? VLBE_ALE_INV_AXIAL : 0u), 0, 0, 0)) !=
        VLBE_OK)
        return st;
    if (c->inv == SP_INV_SYS) {
        mat.EA = VLBE_R(0.0);
        mat.c_eps = VLBE_R(0.0);
        if ((st = vlbe_ale_elem_init(&m->abend, &mat,
                                     VLBE_ALE_FIX_P1 | VLBE_ALE_FIX_P2 | VLBE_ALE_INV_AXIAL, 0, 0,
                                     0)) != VLBE_OK)
            return st;
    }
    for (i = 0; i <= c->ne; ++i) {
        memset(&m->nodes[i], 0, sizeof m->nodes[i]);
        m->nodes[i].pmode = VLBE_ALE_PFIXED;
        m->nodes[i].p = (vlbe_real)(c->L * i / c->ne);
        if (i < c->ne) m->Lel[i] = (vlbe_real)(c->L / c->ne);
    }
    if ((st = vlbe_ale_chain_init(&m->ch, c->inv == SP_INV_SYS ? &m->abend : &m->ael, m->nodes,
                                  c->ne + 1, c->ne + 1, m->cons, 2)) != VLBE_OK)
        return st;
    m->ch.afun = sp_afun;
    m->ch.user = m;
    memset(&k, 0, sizeof k);
    k.type = VLBE_ALE_CON_POS; /* node 0 on the axis */
    if ((st = vlbe_ale_chain_add(&m->ch, &k)) != VLBE_OK) return st;
    k.type = VLBE_ALE_CON_SLOPE_ANGLE; /* its slope along the hub: a = theta(t) */
    if ((st = vlbe_ale_chain_add(&m->ch, &k)) != VLBE_OK) return st;
    if ((st = vlbe_ale_chain_layout(&m->ch)) != VLBE_OK) return st;
    if (c->band && (st = ex_ale_band(&m->ch, m->order, SP_NAMAX)) != VLBE_OK) return st;
    m->n = m->ch.n;
    if (c->inv == SP_INV_SYS &&
        (st = vlbe_ale_inv_sys_init(&m->isys, &m->ael, 0u, c->ne, m->Lel, m->isys_work,
                                    sizeof m->isys_work / sizeof m->isys_work[0])) != VLBE_OK)
        return st;
    if ((st = vlbe_ale_chain_dae(&m->ch, &m->sys)) != VLBE_OK) return st;
    m->sys.flags = VLBE_DAE_MASS_CONST; /* p fixed: M constant */
    if (c->inv == SP_INV_SYS || c->abs_a > 0.0 || c->abs_b > 0.0) {
        m->sys.force = sp_ancf_force;
        m->sys.force_jac = sp_ancf_force_jac;
    }
    if (c->abs_a > 0.0 || c->abs_b > 0.0) {
        /* -(abs_a M + abs_b K0) = -abs_a M + abs_b dQ/dq of the straight
           beam at rest (dQ/dq at v = 0 does not depend on c_kv) */
        const size_t nn = vlbe_ale_chain_mat_len(&m->ch); /* n x n, or the band */
        /* r0, dir static: gcc 12 at -O3 -march=native reports automatic
           arrays here as maybe-uninitialized (as in sp_rest) */
        static const vlbe_real r0[2] = {VLBE_R(0.0), VLBE_R(0.0)};
        static const vlbe_real dir[2] = {VLBE_R(1.0), VLBE_R(0.0)};
        vlbe_real q0[SP_NMAX], v0[SP_NMAX];
        size_t j;
        vlbe_ale_chain_straight(&m->ch, r0, dir, q0);
        for (i = 0; i < m->n; ++i) v0[i] = VLBE_R(0.0);
        if (sp_ancf_force_jac(&m->ch, VLBE_R(0.0), q0, v0, m->Dabs_buf, m->scratch) ||
            vlbe_ale_chain_mass(&m->ch, VLBE_R(0.0), q0, v0, m->scratch))
            return m->ch.err != VLBE_OK ? m->ch.err : VLBE_ECALLBACK;
        for (j = 0; j < nn; ++j)
            m->Dabs_buf[j] = -(vlbe_real)c->abs_a * m->scratch[j] + (vlbe_real)c->abs_b * m->Dabs_buf[j];
        m->Dabs = m->Dabs_buf;
    }
    return VLBE_OK;
}
static inline vlbe_status sp_init(sp_model *m, const sp_cfg *c)
{
    vlbe_cr2d_mat mat;
    vlbe_status st;
    int e;
    memset(m, 0, sizeof *m);
    if (c->ne < 1 || c->ne > SP_MAXEL || c->model < SP_CR || c->model > SP_ANCF)
        return VLBE_EARG;
    m->cfg = *c;
    if (c->model == SP_ANCF) return sp_init_ancf(m, c);
    if (c->c_kv != 0.0 || c->abs_a != 0.0 || c->abs_b != 0.0 || c->inv != SP_GAUSS)
        return VLBE_EARG; /* ANCF settings on a co-rotational model */
    m->n = 3 * (c->ne + 1);
    memset(&mat, 0, sizeof mat);
    mat.EA = (vlbe_real)c->EA;
    mat.EI = (vlbe_real)c->EI;
    mat.rhoA = (vlbe_real)c->rhoA;
    mat.rhoI = (vlbe_real)c->rhoI;
    mat.ray_a = (vlbe_real)c->ray_a;
    mat.ray_b = (vlbe_real)c->ray_b;
    for (e = 0; e < c->ne; ++e) {
        vlbe_real X1[2], X2[2];
        X1[0] = (vlbe_real)(c->L * e / c->ne);
        X2[0] = (vlbe_real)(c->L * (e + 1) / c->ne);
        X1[1] = X2[1] = VLBE_R(0.0);
        if ((st = vlbe_cr2d_elem_init(&m->el[e], &mat, X1, X2,
                                      c->model == SP_LINEAR ? VLBE_CR2D_LINEAR : 0u)) !=
            VLBE_OK)
            return st;
    }
    m->fix[0].dof = 0;
    m->fix[1].dof = 1;
    m->fix[2].dof = 2;
    m->fix[2].fun = sp_theta_fun;
    m->fix[2].ctx = &m->cfg;
    if ((st = vlbe_cr2d_beam_init(&m->beam, m->el, c->ne, m->fix, 3)) != VLBE_OK) return st;
    if (c->band && (st = vlbe_cr2d_beam_band(&m->beam, m->order, SP_NAMAX)) != VLBE_OK) return st;
    if (c->model == SP_LINEAR) m->beam.frame = &m->fix[2]; /* the hub frame */
    if ((st = vlbe_cr2d_beam_dae(&m->beam, &m->sys)) != VLBE_OK) return st;
    if (c->model == SP_LINEAR) m->sys.flags = VLBE_DAE_MASS_CONST;
    return VLBE_OK;
}

/* The state at rest at t = 0 (consistent: theta(0) = theta'(0) = 0):
   CR / LINEAR displacements zero, ANCF the straight beam along +x. */
static inline void sp_rest(const sp_model *m, vlbe_real *q, vlbe_real *v)
{
    int i;
    for (i = 0; i < m->n; ++i) q[i] = v[i] = VLBE_R(0.0);
    if (m->cfg.model == SP_ANCF) {
        /* static: gcc 12 at -O3 -march=native reports automatic arrays here
           as maybe-uninitialized (a false positive of its vectorizer) */
        static const vlbe_real r0[2] = {VLBE_R(0.0), VLBE_R(0.0)};
        static const vlbe_real dir[2] = {VLBE_R(1.0), VLBE_R(0.0)};
        vlbe_ale_chain_straight(&m->ch, r0, dir, q);
    }
}

/* tip deflection in the hub frame at t: tip[0] axial, tip[1] transverse */
static inline void sp_tip(const sp_model *m, double t, const vlbe_real *q, double *tip)
{
    const int i = m->cfg.ne, anc = m->cfg.model == SP_ANCF;
    const double x = anc ? (double)q[4 * i] : m->cfg.L + (double)q[3 * i];
    const double y = anc ? (double)q[4 * i + 1] : (double)q[3 * i + 1];
    double g[3];
    sp_theta(&m->cfg, t, g);
    tip[0] = cos(g[0]) * x + sin(g[0]) * y - m->cfg.L;
    tip[1] = -sin(g[0]) * x + cos(g[0]) * y;
}

/* Called at t = 0 and after every accepted step with the tip in the hub
   frame. */
typedef void (*sp_observer)(void *ctx, const sp_model *m, double t, const double *tip,
                            const vlbe_real *q, const vlbe_real *v);

/* the tip is sampled every SP_DTS seconds (t = SP_DTS k, k = 1..SP_NS):
   the record the work-precision chart compares */
#define SP_DTS 0.5
#define SP_NS 40

typedef struct sp_out {
    vlbe_status status;   /* VLBE_EBOUND: the tip left the bound        */
    vlbe_dae_stats stats;
    double cpu;           /* seconds                                    */
    double t_stop;        /* time of the last accepted step             */
    double tip_Ts[2];     /* tip at t = Ts (NAN if not reached)         */
    double tip_end[2];    /* tip at the last accepted step              */
    double tip_max[2];    /* max |axial|, max |transverse|              */
    double tip_s[SP_NS][2]; /* tip at t = SP_DTS (k + 1) (NAN if not reached) */
} sp_out;

/* ex_run's observer: the tip in the hub frame, its record in out, the
   caller's observer, and the bound (VLBE_EBOUND ends the run). */
typedef struct sp_watch {
    const sp_model *m;
    sp_out *out;
    sp_observer obs;
    void *ctx;
} sp_watch;

/* index k of the sample time SP_DTS (k + 1) that t is (to 1e-9 s), else -1 */
static inline int sp_sample(double t)
{
    const double k = floor(t / SP_DTS + 0.5);
    return (k >= 1.0 && k <= SP_NS && fabs(t - SP_DTS * k) <= 1e-9) ? (int)k - 1 : -1;
}

static inline vlbe_status sp_watch_step(void *ctx, double t, const vlbe_real *q,
                                        const vlbe_real *v, const vlbe_real *lambda)
{
    sp_watch *w = (sp_watch *)ctx;
    sp_out *out = w->out;
    const sp_cfg *c = &w->m->cfg;
    double tip[2] = {0.0, 0.0};
    (void)lambda;
    if (t > 0.0) {
        const int k = sp_sample(t);
        sp_tip(w->m, t, q, tip);
        out->t_stop = t;
        out->tip_end[0] = tip[0];
        out->tip_end[1] = tip[1];
        if (fabs(t - c->Ts) <= 1e-9) {
            out->tip_Ts[0] = tip[0];
            out->tip_Ts[1] = tip[1];
        }
        if (k >= 0) {
            out->tip_s[k][0] = tip[0];
            out->tip_s[k][1] = tip[1];
        }
        out->tip_max[0] = fmax(out->tip_max[0], fabs(tip[0]));
        out->tip_max[1] = fmax(out->tip_max[1], fabs(tip[1]));
    }
    if (w->obs) w->obs(w->ctx, w->m, t, tip, q, v);
    if (c->bound > 0.0 && !(hypot(tip[0], tip[1]) <= c->bound)) return VLBE_EBOUND;
    return VLBE_OK;
}

/* The whole run from rest, by ex_run: the HHT family (cfg.alpha, rho_inf)
   at the fixed step cfg.h, or BDF (cfg.bdf_rtol > 0) landing on Ts and on
   the sample times.  The HHT step must divide SP_DTS and Ts for those
   records (the scene's steps do). */
static inline void sp_run(sp_model *m, const sp_cfg *c, sp_observer obs, void *ctx, sp_out *out)
{
    vlbe_hht_params par;
    vlbe_bdf_params bp;
    ex_method meth;
    ex_run_out ro;
    sp_watch w;
    double marks[SP_NS + 1];
    vlbe_real *q0 = NULL;
    int k, j, ins = 0;
    memset(out, 0, sizeof *out);
    out->tip_Ts[0] = out->tip_Ts[1] = NAN;
    for (k = 0; k < SP_NS; ++k) out->tip_s[k][0] = out->tip_s[k][1] = NAN;
    if ((out->status = sp_init(m, c)) != VLBE_OK) return;
    memset(&meth, 0, sizeof meth);
    if (c->bdf_rtol > 0.0) {
        vlbe_bdf_params_default(&bp);
        bp.rtol = (vlbe_real)c->bdf_rtol;
        bp.atol = (vlbe_real)c->bdf_rtol;
        if (c->bdf_max_order > 0) bp.max_order = c->bdf_max_order;
        meth.bdf = &bp;
        /* the sample times with Ts in order */
        for (k = j = 0; k < SP_NS; ++k) {
            const double tk = SP_DTS * (k + 1);
            if (!ins && c->Ts < tk - 1e-9) marks[j++] = c->Ts, ins = 1;
            if (fabs(c->Ts - tk) <= 1e-9) ins = 1;
            marks[j++] = tk;
        }
        meth.marks = marks;
        meth.n_marks = j;
    } else {
        if ((out->status = ex_hht_pick(&par, c->alpha, c->rho_inf)) != VLBE_OK) return;
        par.max_halvings = c->max_halvings > 0 ? c->max_halvings : 10;
        meth.hht = &par;
        meth.h = c->h;
    }
    q0 = (vlbe_real *)calloc(2 * (size_t)m->n, sizeof *q0);
    if (!q0) {
        out->status = VLBE_EWORK;
        return;
    }
    sp_rest(m, q0, q0 + m->n);
    w.m = m;
    w.out = out;
    w.obs = obs;
    w.ctx = ctx;
    out->status = ex_run(&m->sys, &meth, q0, q0 + m->n, c->t_end, sp_watch_step, &w, NULL, NULL,
                         NULL, &ro);
    out->stats = ro.stats;
    out->cpu = ro.cpu;
    free(q0);
}

#define SP_NHIST 4096

/* tip history, every `every`-th observation (an sp_observer: pass
   sp_hist_obs with an sp_hist zeroed and its `every` set) */
typedef struct sp_hist {
    long k, every;
    int n;
    double t[SP_NHIST], ax[SP_NHIST], tr[SP_NHIST];
} sp_hist;

static inline void sp_hist_obs(void *ctx, const sp_model *m, double t, const double *tip,
                               const vlbe_real *q, const vlbe_real *v)
{
    sp_hist *hh = (sp_hist *)ctx;
    (void)m;
    (void)q;
    (void)v;
    if (hh->k++ % hh->every == 0 && hh->n < SP_NHIST) {
        hh->t[hh->n] = t;
        hh->ax[hh->n] = tip[0];
        hh->tr[hh->n] = tip[1];
        ++hh->n;
    }
}

#endif /* VLBE_EX_SPIN_H */
