/* ex_sbeam.h -- a beam sliding through a prismatic joint, co-rotational model
   of corot2d.h (Hsiao et al., section 3): configuration, the constraint and
   element bookkeeping as nodes cross the joint's exit, the initial static
   tip deflection, the time-dependent modal damping of eq. (56) and the run
   loop.  Shared by examples/sliding_beam.c, its tests and bench.
   -- part of vlbe                                  SPDX-License-Identifier: MIT

   Geometry: the joint's exit C at the origin, its axis a = +x; the beam
   lies along x, its inner end A at x = -(L - L0), n_in equal elements
   inside and n_out equal elements outside at t = 0 (node n_in at C).
   Coordinates (u, v, phi) per node (corot2d.h).  Node 0 (end A) has the
   prescribed axial displacement U_A(t) (eq. 54 or 55); every node inside
   the joint (x <= 0) has v = 0 and phi = 0 (prescribed coordinates); the
   element with node e inside and node e + 1 outside is the transition
   element.  With delta = 1e-3 h_out (h_out = L0/n_out), an outside node
   enters at x <= din = delta + 2 h max(0, -U_A'), a step before it would
   reach C (where the outside chord of the transition element would
   vanish), and an inside node leaves at x > din + delta + h max(0, U_A'),
   so that the outside segment of a transition element is never shorter
   than delta (its bending stiffness grows like L2^-3), does not grow by
   more than its own length in the step after a release, and a node does
   not toggle.  When a node
   crosses, the constraint list and the transition element are rebuilt and
   the integrator restarts from the current state; a node that enters has
   its v, phi and their rates set to zero first (the joint takes them: the
   step of that projection is reported).

   Damping (eq. 56): modal ratios xi_i = c_i / (4 L_f^2 omega_i), c = 0.4874,
   3.124 (SI units as printed), omega_i the cantilever frequencies of the
   free length L_f = L0 + U_A(t) (beta_1 L = 1.87510, beta_2 L = 4.69409),
   turned into Rayleigh alpha, beta through xi_i = alpha/(2 omega_i) + beta
   omega_i / 2 and set on every element at each force evaluation.

   Initial state (section 3): at rest, deflected by a lateral tip force,
   solved statically (vlbe_dae_static) and scaled until the tip deflection
   is tip0 to 1e-10 relative; the force is removed at t = 0. */
#ifndef VLBE_EX_SBEAM_H
#define VLBE_EX_SBEAM_H

#include "../corot2d.h"
#include "../integrators.h"
#include "ex_cant.h"
#include "ex_cr2d.h"
#include "ex_run.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define SB_MAXEL 128

typedef struct sb_cfg {
    double L, L0;       /* total length, free length at t = 0          */
    int n_in, n_out;    /* elements inside / outside at t = 0          */
    double A, I, E, rho;
    int motion;         /* 0: U_A = v0 t + a0 t^2/2 (eq. 54); 1: eq. 55 */
    double v0, a0, c0, t0;
    double tip0;        /* initial tip deflection [m]                  */
    int damping;        /* 1: eq. 56                                   */
    unsigned mode;      /* element mode flags (corot2d.h)              */
    double h, t_end;    /* step, end time                              */
    double alpha;       /* HHT alpha (0: trapezoidal Newmark)          */
    double rho_inf;     /* > 0: generalized-alpha with this rho_inf instead */
    int newton_max;     /* Newton iterations per attempt (0: default 10)     */
    int full_newton;    /* 1: fresh iteration matrix every iteration         */
    int max_halvings;   /* step halvings on Newton failure (0: 10)           */
    int fixed_release;  /* 1: release at x > din + delta, without the step's
                           travel h max(0, U_A') (the rule that fails at
                           h >= 2e-3 in case (b); for the tests)            */
    int band;           /* 1: banded matrices (vlbe_cr2d_beam_band; the ALE
                           model of ex_xcheck.h: vlbe_ale_chain_band) and the
                           integrators' banded path; 0: dense (default)     */
} sb_cfg;

/* The paper's section and material, 14 + 10 elements, dt = 1 ms. */
static inline void sb_cfg_paper(sb_cfg *c, char which)
{
    memset(c, 0, sizeof *c);
    c->A = 4.3434e-5;
    c->I = 1.059e-11;
    c->E = 68.96e9;
    c->rho = 3144.3858;
    c->n_in = 14;
    c->n_out = 10;
    c->tip0 = 0.024;
    c->damping = 1;
    c->h = 1e-3;
    c->alpha = -0.05;
    if (which == 'a') {
        c->L = 0.762;
        c->L0 = 0.521;
        c->motion = 0;
        c->v0 = -0.03;
        c->a0 = -0.054;
        c->t_end = 2.5;
    } else {
        c->L = 1.05;
        c->L0 = 0.35;
        c->motion = 1;
        c->c0 = 0.7;
        c->t0 = 1.2;
        c->t_end = 3.0;
    }
}

/* U_A and its two derivatives (eqs. 54, 55) */
static inline void sb_ua(const sb_cfg *c, double t, double *g)
{
    if (c->motion == 0) {
        g[0] = c->v0 * t + 0.5 * c->a0 * t * t;
        g[1] = c->v0 + c->a0 * t;
        g[2] = c->a0;
    } else if (t <= c->t0) {
        const double w = 2.0 * 3.14159265358979323846 / c->t0;
        g[0] = c->c0 / c->t0 * (t - sin(w * t) / w);
        g[1] = c->c0 / c->t0 * (1.0 - cos(w * t));
        g[2] = c->c0 / c->t0 * w * sin(w * t);
    } else {
        g[0] = c->c0;
        g[1] = g[2] = 0.0;
    }
}

/* cantilever frequency i (0, 1) of length Lf */
static inline double sb_omega(const sb_cfg *c, int i, double Lf)
{
    const double bl = ex_cant_b[i];
    return bl * bl / (Lf * Lf) * sqrt(c->E * c->I / (c->rho * c->A));
}

/* Rayleigh alpha, beta of eq. (56) at time t */
static inline void sb_rayleigh(const sb_cfg *c, double t, double *ra, double *rb)
{
    double g[3], Lf, w1, w2, x1, x2;
    sb_ua(c, t, g);
    Lf = c->L0 + g[0];
    w1 = sb_omega(c, 0, Lf);
    w2 = sb_omega(c, 1, Lf);
    x1 = 0.4874 / (4.0 * Lf * Lf * w1);
    x2 = 3.124 / (4.0 * Lf * Lf * w2);
    *ra = 2.0 * w1 * w2 * (x1 * w2 - x2 * w1) / (w2 * w2 - w1 * w1);
    *rb = 2.0 * (x2 * w2 - x1 * w1) / (w2 * w2 - w1 * w1);
}

typedef struct sb_model {
    sb_cfg cfg;
    int ne, nn, n;
    vlbe_cr2d_elem el[SB_MAXEL];
    vlbe_cr2d_fix fix[2 * SB_MAXEL + 2];
    vlbe_cr2d_joint joint;
    vlbe_cr2d_beam beam;
    vlbe_dae sys;
    unsigned char inside[SB_MAXEL + 1];
    double delta;       /* outside once x > delta                       */
    double proj_max;    /* largest |v|, |phi| * h_out zeroed at an entry */
    int events;         /* node crossings                               */
    int order[3 * (SB_MAXEL + 1) + 2 * (SB_MAXEL + 1) + 1]; /* cfg.band: the
                           augmented order, room for every layout (n + 1 + 2 nn) */
} sb_model;

static inline void sb_ua_fun(void *ctx, vlbe_real t, vlbe_real *g3)
{
    double g[3];
    sb_ua((const sb_cfg *)ctx, (double)t, g);
    ex_real3(g, g3);
}

/* damping of eq. 56 set on every element for time t */
static inline void sb_set_damping(sb_model *m, double t)
{
    double ra = 0.0, rb = 0.0;
    int e;
    if (m->cfg.damping) sb_rayleigh(&m->cfg, t, &ra, &rb);
    for (e = 0; e < m->ne; ++e) {
        m->el[e].mat.ray_a = (vlbe_real)ra;
        m->el[e].mat.ray_b = (vlbe_real)rb;
    }
}

static inline int sb_force(void *user, vlbe_real t, const vlbe_real *q, const vlbe_real *v,
                           vlbe_real *Q)
{
    sb_model *m = (sb_model *)user;
    sb_set_damping(m, (double)t);
    return vlbe_cr2d_beam_force(&m->beam, t, q, v, Q);
}

static inline int sb_force_jac(void *user, vlbe_real t, const vlbe_real *q, const vlbe_real *v,
                               vlbe_real *K, vlbe_real *D)
{
    sb_model *m = (sb_model *)user;
    sb_set_damping(m, (double)t);
    return vlbe_cr2d_beam_force_jac(&m->beam, t, q, v, K, D);
}

static inline int sb_mass(void *user, vlbe_real t, const vlbe_real *q, const vlbe_real *v,
                          vlbe_real *M)
{
    return vlbe_cr2d_beam_mass(&((sb_model *)user)->beam, t, q, v, M);
}

static inline int sb_mass_jac(void *user, vlbe_real t, const vlbe_real *q, const vlbe_real *v,
                              const vlbe_real *a, vlbe_real *Mq, vlbe_real *Mv)
{
    return vlbe_cr2d_beam_mass_jac(&((sb_model *)user)->beam, t, q, v, a, Mq, Mv);
}

static inline int sb_constr(void *user, vlbe_real t, const vlbe_real *q, vlbe_real *C)
{
    return vlbe_cr2d_beam_constr(&((sb_model *)user)->beam, t, q, C);
}

static inline int sb_constr_jac(void *user, vlbe_real t, const vlbe_real *q, vlbe_real *Cq,
                                vlbe_real *Ct)
{
    return vlbe_cr2d_beam_constr_jac(&((sb_model *)user)->beam, t, q, Cq, Ct);
}

static inline int sb_constr_acc(void *user, vlbe_real t, const vlbe_real *q, const vlbe_real *v,
                                vlbe_real *gamma)
{
    return vlbe_cr2d_beam_constr_acc(&((sb_model *)user)->beam, t, q, v, gamma);
}

/* node positions along x */
static inline double sb_x(const sb_model *m, const vlbe_real *q, int i)
{
    return (double)m->el[i < m->ne ? i : m->ne - 1].X[i < m->ne ? 0 : 2] + (double)q[3 * i];
}

/* Classify the nodes from q and rebuild the constraints and the transition
   element; returns 1 when something changed. */
static inline int sb_layout(sb_model *m, const vlbe_real *q, double t, int first)
{
    /* a banded beam's order (NULL: dense); cfg.band: the model's from the
       first layout on */
    int *const order = m->beam.order ? m->beam.order : m->cfg.band ? m->order : NULL;
    const int order_cap = m->beam.order ? m->beam.order_cap : m->n + 1 + 2 * m->nn;
    double g[3], din, dout;
    int i, nf = 0, changed = 0, trans = -1;
    sb_ua(&m->cfg, t, g);
    /* an outside node enters at x <= din = delta + 2 h max(0, -U_A'),
       before the step that would carry it across C (where the transition
       element's outside chord would vanish); an inside one leaves at x >
       dout = din + delta + h max(0, U_A') (a band of delta against
       toggling, and an outside chord of at least one step's travel, so
       that the next step does not multiply it) */
    din = m->delta + 2.0 * m->cfg.h * fmax(0.0, -g[1]);
    dout = din + m->delta + (m->cfg.fixed_release ? 0.0 : m->cfg.h * fmax(0.0, g[1]));
    for (i = 0; i < m->nn; ++i) {
        const double x = sb_x(m, q, i);
        const unsigned char in =
            (unsigned char)(first ? x <= m->delta
                                  : (m->inside[i] ? x <= dout : x <= din));
        if (first || in != m->inside[i]) changed = 1;
        m->inside[i] = in;
    }
    if (!changed) return 0;
    /* node 0: axial motion prescribed */
    memset(m->fix, 0, sizeof m->fix);
    m->fix[nf].dof = 0;
    m->fix[nf].fun = sb_ua_fun;
    m->fix[nf].ctx = &m->cfg;
    ++nf;
    for (i = 0; i < m->nn; ++i)
        if (m->inside[i] || i == 0) {
            m->fix[nf++].dof = 3 * i + 1;
            m->fix[nf++].dof = 3 * i + 2;
        }
    for (i = 0; i + 1 < m->nn; ++i)
        if (m->inside[i] && !m->inside[i + 1]) trans = i;
    vlbe_cr2d_beam_init(&m->beam, m->el, m->ne, m->fix, nf);
    m->beam.mode = m->cfg.mode;
    m->beam.joint = &m->joint;
    m->beam.trans = trans;
    /* a banded beam stays banded, with the band of the new constraints
       (order_cap >= n + 1 + 2 nn holds every layout: node 0 has u, v, phi
       prescribed, the others at most v, phi; with less, VLBE_EWORK leaves
       the beam dense as init made it) */
    if (order) (void)vlbe_cr2d_beam_band(&m->beam, order, order_cap);
    m->sys.m = nf;
    ex_cr2d_storage(&m->sys, &m->beam);
    return 1;
}

static inline vlbe_status sb_init(sb_model *m, const sb_cfg *c)
{
    vlbe_cr2d_mat mat;
    const double hin = (c->L - c->L0) / c->n_in, hout = c->L0 / c->n_out;
    int e;
    vlbe_status st;
    memset(m, 0, sizeof *m);
    m->cfg = *c;
    m->ne = c->n_in + c->n_out;
    if (m->ne > SB_MAXEL || c->n_in < 1 || c->n_out < 1) return VLBE_EARG;
    m->nn = m->ne + 1;
    m->n = 3 * m->nn;
    m->delta = 1e-3 * hout;
    mat.EA = (vlbe_real)(c->E * c->A);
    mat.EI = (vlbe_real)(c->E * c->I);
    mat.rhoA = (vlbe_real)(c->rho * c->A);
    mat.rhoI = (vlbe_real)(c->rho * c->I);
    mat.ray_a = mat.ray_b = VLBE_R(0.0);
    for (e = 0; e < m->ne; ++e) {
        const double x1 = e < c->n_in ? -(c->L - c->L0) + e * hin : (e - c->n_in) * hout;
        const double x2 = e + 1 <= c->n_in ? -(c->L - c->L0) + (e + 1) * hin
                                           : (e + 1 - c->n_in) * hout;
        vlbe_real X1[2], X2[2];
        X1[0] = (vlbe_real)x1;
        X2[0] = (vlbe_real)x2;
        X1[1] = X2[1] = VLBE_R(0.0);
        if ((st = vlbe_cr2d_elem_init(&m->el[e], &mat, X1, X2, 0)) != VLBE_OK) return st;
    }
    m->joint.C[0] = m->joint.C[1] = VLBE_R(0.0);
    m->joint.a[0] = VLBE_R(1.0);
    m->joint.a[1] = VLBE_R(0.0);
    m->sys.n = m->n;
    m->sys.user = m;
    m->sys.mass = sb_mass;
    m->sys.force = sb_force;
    m->sys.force_jac = sb_force_jac;
    m->sys.mass_jac = sb_mass_jac;
    m->sys.constr = sb_constr;
    m->sys.constr_jac = sb_constr_jac;
    m->sys.constr_acc = sb_constr_acc;
    return VLBE_OK;
}

/* Static deflection by a lateral tip force, scaled to tip0; q (n) out. */
static inline vlbe_status sb_static(sb_model *m, vlbe_real *q, double *force)
{
    vlbe_static_params sp;
    vlbe_real *P, *lam, *w;
    int *iw;
    size_t lw, liw;
    double F, tip = 0.0;
    vlbe_status st = VLBE_OK;
    int it;
    memset(q, 0, sizeof(vlbe_real) * (size_t)m->n);
    sb_layout(m, q, 0.0, 1);
    vlbe_static_params_default(&sp);
    lw = vlbe_static_work_len_sys(&m->sys);
    liw = vlbe_static_iwork_len_sys(&m->sys);
    P = (vlbe_real *)calloc((size_t)m->n, sizeof *P);
    lam = (vlbe_real *)calloc((size_t)m->sys.m, sizeof *lam);
    w = (vlbe_real *)malloc(lw * sizeof *w);
    iw = (int *)malloc(liw * sizeof *iw);
    if (!P || !lam || !w || !iw) {
        st = VLBE_EWORK;
        goto done;
    }
    m->beam.P = P;
    F = 3.0 * m->cfg.E * m->cfg.I * m->cfg.tip0 / pow(m->cfg.L0, 3.0); /* linear guess */
    for (it = 0; it < 20; ++it) {
        P[m->n - 2] = (vlbe_real)F;
        if ((st = vlbe_dae_static(&m->sys, &sp, VLBE_R(0.0), q, lam, NULL, w, lw, iw, liw)) !=
            VLBE_OK)
            break;
        tip = (double)q[m->n - 2];
        if (fabs(tip - m->cfg.tip0) <= 1e-10 * m->cfg.tip0) break;
        F *= m->cfg.tip0 / tip;
    }
    *force = F;
done:
    m->beam.P = NULL;
    free(P);
    free(lam);
    free(w);
    free(iw);
    return st;
}

/* A node that has just left the joint: its v and phi were held at zero
   by the joint, and the only thing that now holds them is the outside
   segment of the new transition element, at most one step long (its
   stiffness grows like L2^-3).  Released as it is, the node would carry
   the out-of-balance moment of the next element into a spurious
   oscillation at that stiffness, whose consistent start acceleration
   alone ruins the integrator's predictor.  So v and phi of the released
   node are first relaxed to static balance with everything else held
   (Newton on their two rows; the true slope there differs from zero by
   curvature x L2, which this recovers), their rates left at zero.
   (K of a banded beam is its band: sb_at places the entries.) */
static inline size_t sb_at(const sb_model *m, int i, int j)
{
    const vlbe_cr2d_beam *b = &m->beam;
    if (!b->order) return (size_t)i * (size_t)m->n + (size_t)j;
    return VLBE_BAND_IDX(b->kl + b->ku + 1, b->kl, b->order[i], b->order[j]);
}

static inline vlbe_status sb_relax(sb_model *m, double t, int i, vlbe_real *q, const vlbe_real *v)
{
    const vlbe_cr2d_beam *bm = &m->beam;
    const size_t klen = bm->order
                            ? ((size_t)m->n + (size_t)bm->nfix) * (size_t)(bm->kl + bm->ku + 1)
                            : (size_t)m->n * (size_t)m->n;
    vlbe_real *Q = (vlbe_real *)malloc(sizeof(vlbe_real) * (size_t)m->n);
    vlbe_real *K = (vlbe_real *)malloc(sizeof(vlbe_real) * klen);
    vlbe_status st = VLBE_ENOCONV;
    const int r1 = 3 * i + 1, r2 = r1 + 1;
    int it;
    if (!Q || !K) {
        free(Q);
        free(K);
        return VLBE_EWORK;
    }
    for (it = 0; it < 20; ++it) {
        double a, b, c, d, det, d1, d2;
        if (sb_force(m, (vlbe_real)t, q, v, Q) || sb_force_jac(m, (vlbe_real)t, q, v, K, NULL)) {
            st = VLBE_ECALLBACK;
            break;
        }
        /* K = dQ/dq: solve K_ii dx = -Q_i on the two rows */
        a = (double)K[sb_at(m, r1, r1)];
        b = (double)K[sb_at(m, r1, r2)];
        c = (double)K[sb_at(m, r2, r1)];
        d = (double)K[sb_at(m, r2, r2)];
        det = a * d - b * c;
        if (!(fabs(det) > 0.0)) {
            st = VLBE_ESINGULAR;
            break;
        }
        d1 = -((double)Q[r1] * d - b * (double)Q[r2]) / det;
        d2 = -(a * (double)Q[r2] - c * (double)Q[r1]) / det;
        q[r1] += (vlbe_real)d1;
        q[r2] += (vlbe_real)d2;
        if (fabs(d1) <= 1e-14 * m->cfg.L && fabs(d2) <= 1e-14) {
            st = VLBE_OK;
            break;
        }
    }
    free(Q);
    free(K);
    return st;
}

/* Called at t = 0 and after every accepted step. */
typedef void (*sb_observer)(void *ctx, const sb_model *m, double t, const vlbe_real *q,
                            const vlbe_real *v);

typedef struct sb_out {
    vlbe_status status;
    vlbe_dae_stats stats; /* summed over the restarts */
    int restarts;
    double cpu, F0;       /* seconds; the initial tip force */
} sb_out;

/* The whole run: static start, then HHT with restarts at node crossings. */
static inline void sb_run(sb_model *m, const sb_cfg *c, sb_observer obs, void *ctx, sb_out *out)
{
    vlbe_hht_params par;
    vlbe_hht st;
    vlbe_real *q = NULL, *v = NULL, *w = NULL;
    int *iw = NULL;
    size_t lw, liw;
    long k, nsteps;
    unsigned char was[SB_MAXEL + 1];
    clock_t c0 = clock();
    memset(out, 0, sizeof *out);
    if ((out->status = sb_init(m, c)) != VLBE_OK) return;
    q = (vlbe_real *)calloc((size_t)m->n, sizeof *q);
    v = (vlbe_real *)calloc((size_t)m->n, sizeof *v);
    {
        /* the largest system of the run: every node's v, phi and node 0's
           u prescribed; banded, the half-bandwidth of a beam with 3 fixes
           on one node, 5 + 3 (corot2d.h, vlbe_cr2d_beam), the widest any
           layout has */
        vlbe_dae big;
        memset(&big, 0, sizeof big);
        big.n = m->n;
        big.m = 2 * m->nn + 1;
        if (c->band) {
            big.storage = VLBE_DAE_BANDED;
            big.kl = big.ku = 8;
        }
        lw = vlbe_hht_work_len_sys(&big);
        liw = vlbe_hht_iwork_len_sys(&big);
    }
    w = (vlbe_real *)malloc(lw * sizeof *w);
    iw = (int *)malloc(liw * sizeof *iw);
    if (!q || !v || !w || !iw) {
        out->status = VLBE_EWORK;
        goto done;
    }
    if ((out->status = sb_static(m, q, &out->F0)) != VLBE_OK) goto done;
    if ((out->status = ex_hht_pick(&par, c->alpha, c->rho_inf)) != VLBE_OK) goto done;
    par.max_halvings = c->max_halvings > 0 ? c->max_halvings : 10;
    if (c->newton_max > 0) par.newton_max = c->newton_max;
    if (c->full_newton) par.modified = 0;
    nsteps = (long)floor(c->t_end / c->h + 0.5);
    if (obs) obs(ctx, m, 0.0, q, v);
    if ((out->status = vlbe_hht_init(&st, &m->sys, &par, VLBE_R(0.0), q, v, w, lw, iw, liw)) !=
        VLBE_OK)
        goto done;
    for (k = 1; k <= nsteps; ++k) {
        if ((out->status = vlbe_hht_step(&st, (vlbe_real)c->h)) != VLBE_OK) break;
        if (obs) obs(ctx, m, (double)st.t, st.q, st.v);
        if (k == nsteps) break;
        memcpy(was, m->inside, (size_t)m->nn);
        if (sb_layout(m, st.q, (double)st.t, 0)) {
            /* a node crossed the exit: project the entering ones, relax
               the leaving ones, restart */
            const double hout = c->L0 / c->n_out;
            const vlbe_real t = st.t;
            int i;
            vlbe_dae_stats_add(&out->stats, &st.stats); /* the segment ends here */
            memset(&st.stats, 0, sizeof st.stats);
            memcpy(q, st.q, sizeof(vlbe_real) * (size_t)m->n);
            memcpy(v, st.v, sizeof(vlbe_real) * (size_t)m->n);
            for (i = 1; i < m->nn; ++i)
                if (m->inside[i] && !was[i]) {
                    double d = fmax(fabs((double)q[3 * i + 1]), fabs((double)q[3 * i + 2]) * hout);
                    if (d > m->proj_max) m->proj_max = d;
                    q[3 * i + 1] = q[3 * i + 2] = v[3 * i + 1] = v[3 * i + 2] = VLBE_R(0.0);
                }
            for (i = 1; i < m->nn; ++i)
                if (!m->inside[i] && was[i] &&
                    (out->status = sb_relax(m, (double)t, i, q, v)) != VLBE_OK)
                    goto done;
            ++m->events;
            ++out->restarts;
            if ((out->status = vlbe_hht_init(&st, &m->sys, &par, t, q, v, w, lw, iw, liw)) !=
                VLBE_OK)
                break;
        }
    }
    vlbe_dae_stats_add(&out->stats, &st.stats);
done:
    out->cpu = (double)(clock() - c0) / CLOCKS_PER_SEC;
    free(q);
    free(v);
    free(w);
    free(iw);
}

#endif /* VLBE_EX_SBEAM_H */
