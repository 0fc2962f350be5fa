/* spinning_shaft.h -- the spinning simply supported shaft under an
   axially moving, turning load (vlbse section 4.3, Table 4): the paper's
   errors, the moving mesh and the load (ss_setup, ss_band), the runs
   against the modal series of ex_katz.h (ss_integrate, ss_run, ss_errors),
   and the analysis of the errors (ss_err_at, ss_split) and of the frozen
   mesh's frequencies (ss_frozen_freq).  Shared by
   examples/spinning_shaft.c, which states the scene,
   tests/test_scenes_shaft.c, tests/test_scenes_band.c and
   bench/wp_shaft.c.
   -- part of vlbe                                  SPDX-License-Identifier: MIT */
#ifndef VLBE_SCENE_SPINNING_SHAFT_H
#define VLBE_SCENE_SPINNING_SHAFT_H

#include "../ancf_ale.h"
#include "ex_ale.h"
#include "ex_katz.h"
#include "ex_run.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define SS_NE_MAX 16
#define SS_NSAMP_MAX 4096

/* Table 4 */
#define SS_L 1.0
#define SS_BETA1 0.02
#define SS_E 206e9
#define SS_RHO 7700.0
#define SS_OMEGA_SPIN 1.0
#define SS_NU 0.3             /* Poisson's ratio for G (torsion only: not in Table 4) */
#define SS_US 1e-3            /* U_s [m]: sets P (the response is normalised by U_s; at
                                 U_s = l/1000 the geometric nonlinearity is ~1e-6) */
#define SS_Z0 1e-3            /* start / stop margin of the load, times l   */
#define SS_Z0_COARSE 5e-3     /* the same for fine meshes at coarse steps   */
#define SS_ATOL 1e-8          /* HHT Newton atol [m, m/s]: 1e-5 U_s; see ss_integrate */
#define SS_SPLIT_CYC 6.0      /* ss_split: cycles per traverse              */

/* the paper's largest errors with four elements, (U - U_exact) / U_s, and
   the load positions z / l where they occur: load point X1, X2, midspan
   X1, X2 (section 4.3, cases (1) and (2)) */
static const double ss_paper_err[2][4] = {{-0.0085, -0.0033, -0.0049, -0.0053},
                                          {0.0090, 0.0055, 0.0176, 0.0079}};
static const double ss_paper_z[2][4] = {{0.85, 0.78, 0.80, 0.72}, {0.61, 0.84, 0.99, 1.00}};
static const double ss_case_a[2] = {0.5, 1.5}, ss_case_kw[2] = {1.0, 0.5};

typedef struct ss_scene {
    ex_katz ref;      /* load, speeds, section (rot = 1: eq. 59 as written) */
    ex_katz ref0;     /* the same without the rhoJ terms                    */
    int ne;
    vlbe_ale3_elem el;
    vlbe_ale_chain ch;
    vlbe_ale_node node[SS_NE_MAX + 1];
    vlbe_ale_con con[4];
    vlbe_dae sys;
    int order[SS_NE_MAX * 8 + 8 + 6]; /* ss_band: the augmented order       */
    double t0, t1;    /* load at z0 l and at (1 - z0) l                     */
    int fixed;        /* 0: the paper's mesh (the load on node ne/2, every
                         element changing length); 1: ne equal fixed
                         elements, the load a moving point force (eq. 45) */
    int iload;        /* index of the load node's x in q (fixed = 0)        */
    /* samples: t, load point U1, U2, midspan U1, U2 (not normalised), and
       their errors (U - U_exact) / U_s against eq. 59 */
    int ns;
    double t[SS_NSAMP_MAX], u[4][SS_NSAMP_MAX], e[4][SS_NSAMP_MAX];
    int every;        /* keep every k-th step, and the last               */
    long step;
    double h;         /* the step                                           */
} ss_scene;

/* the largest error of a run: (U - U_exact) / U_s of the largest
   magnitude, with its sign, and the load position z / l where it occurs;
   load point X1, X2, midspan X1, X2 */
typedef struct ss_err {
    double e[4], z[4];
} ss_err;

/* Material coordinate p and rate p' of node i of the paper's mesh (ne
   elements, ne/2 on either side) with the load at pl moving at v. */
static inline void ss_mesh(int ne, double l, double pl, double v, int i, double *p, double *pd)
{
    const int half = ne / 2;
    if (i <= half) {
        *p = pl * (double)i / (double)half;
        *pd = v * (double)i / (double)half;
    } else {
        *p = pl + (l - pl) * (double)(i - half) / (double)(ne - half);
        *pd = v * (1.0 - (double)(i - half) / (double)(ne - half));
    }
}

/* p, p', p'' of node i on the chain's clock, which starts at t0 */
static inline int ss_pfun(void *user, int i, vlbe_real t, vlbe_real *p3)
{
    const ss_scene *s = (const ss_scene *)user;
    double p, pd;
    ss_mesh(s->ne, s->ref.l, s->ref.v * ((double)t + s->t0), s->ref.v, i, &p, &pd);
    p3[0] = (vlbe_real)p;
    p3[1] = (vlbe_real)pd;
    p3[2] = VLBE_R(0.0);
    return 0;
}

/* chain force plus the turning load: on the load node, or (fixed mesh)
   S(z)^T F at the load's material point z = v t (constant in q: no
   Jacobian) */
static inline int ss_force(void *user, vlbe_real t, const vlbe_real *q, const vlbe_real *v,
                           vlbe_real *Q)
{
    ss_scene *s = (ss_scene *)user;
    const double tt = (double)t + s->t0, w = s->ref.omega * tt; /* chain clock starts at t0 */
    vlbe_real F[3];
    int rc = vlbe_ale_chain_force(&s->ch, t, q, v, Q), e, i, idx[VLBE_ALE3_NQ];
    if (rc) return rc;
    F[0] = (vlbe_real)(s->ref.P * cos(w));
    F[1] = (vlbe_real)(s->ref.P * sin(w));
    F[2] = VLBE_R(0.0);
    if (!s->fixed) {
        Q[s->iload] += F[0];
        Q[s->iload + 1] += F[1];
        return 0;
    } else {
        const vlbe_real z = (vlbe_real)(s->ref.v * tt);
        vlbe_real qe[VLBE_ALE3_NQ], Qe[VLBE_ALE3_NQ];
        unsigned md;
        if (vlbe_ale_chain_locate(&s->ch, t, q, z, &e) ||
            vlbe_ale_chain_gather(&s->ch, e, t, q, NULL, qe, NULL, idx, &md))
            return -1;
        for (i = 0; i < VLBE_ALE3_NQ; ++i) Qe[i] = VLBE_R(0.0);
        if (vlbe_ale3_point_force(md | s->el.flags, qe, z, F, Qe, NULL)) return -1;
        for (i = 0; i < vlbe_ale3_nq(md | s->el.flags); ++i)
            if (idx[i] >= 0) Q[idx[i]] += Qe[i];
        return 0;
    }
}

#define SS_FWD(name, args, call)                                                       \
    static int name args { return call; }
SS_FWD(ss_mass, (void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v, vlbe_real *M),
       vlbe_ale_chain_mass(&((ss_scene *)u)->ch, t, q, v, M))
SS_FWD(ss_force_jac,
       (void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v, vlbe_real *K, vlbe_real *D),
       vlbe_ale_chain_force_jac(&((ss_scene *)u)->ch, t, q, v, K, D))
SS_FWD(ss_mass_jac,
       (void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v, const vlbe_real *a,
        vlbe_real *Mq, vlbe_real *Mv),
       vlbe_ale_chain_mass_jac(&((ss_scene *)u)->ch, t, q, v, a, Mq, Mv))
SS_FWD(ss_constr, (void *u, vlbe_real t, const vlbe_real *q, vlbe_real *C),
       vlbe_ale_chain_constr(&((ss_scene *)u)->ch, t, q, C))
SS_FWD(ss_constr_jac, (void *u, vlbe_real t, const vlbe_real *q, vlbe_real *Cq, vlbe_real *Ct),
       vlbe_ale_chain_constr_jac(&((ss_scene *)u)->ch, t, q, Cq, Ct))
SS_FWD(ss_constr_acc, (void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v, vlbe_real *g),
       vlbe_ale_chain_constr_acc(&((ss_scene *)u)->ch, t, q, v, g))

/* Sets up case (a, kw) with ne elements (even, <= SS_NE_MAX), the load
   from z0 l; q0, v0 (the chain's n; may be NULL) the start state at t0:
   the straight shaft at rest, spinning at Omega.  0 on success. */
static inline int ss_setup(ss_scene *s, double a, double kw, int ne, int fixed, double z0,
                           vlbe_real *q0, vlbe_real *v0)
{
    vlbe_ale3_mat mat;
    vlbe_ale_con c;
    double P;
    int i;
    memset(s, 0, sizeof *s);
    if (ne < 2 || ne > SS_NE_MAX || ne % 2) return -1;
    if (ex_katz_setup(&s->ref, SS_L, SS_BETA1, SS_E, SS_RHO, SS_OMEGA_SPIN, a, kw, 1.0, 1))
        return -1;
    P = SS_US / ex_katz_us(&s->ref); /* U_s is linear in P */
    if (ex_katz_setup(&s->ref, SS_L, SS_BETA1, SS_E, SS_RHO, SS_OMEGA_SPIN, a, kw, P, 1) ||
        ex_katz_setup(&s->ref0, SS_L, SS_BETA1, SS_E, SS_RHO, SS_OMEGA_SPIN, a, kw, P, 0))
        return -1;
    if (vlbe_ale3_mat_circle(&mat, (vlbe_real)SS_RHO, (vlbe_real)SS_E,
                             (vlbe_real)(SS_E / (2.0 * (1.0 + SS_NU))), (vlbe_real)s->ref.r) ||
        vlbe_ale3_elem_init(&s->el, &mat, VLBE_ALE_NO_DAMP, 0, 0))
        return -1;
    s->ne = ne;
    s->fixed = fixed;
    s->t0 = z0 * SS_L / s->ref.v;
    s->t1 = (1.0 - z0) * SS_L / s->ref.v;
    for (i = 0; i <= ne; ++i) {
        s->node[i].pmode = (fixed || i == 0 || i == ne) ? VLBE_ALE_PFIXED : VLBE_ALE_PPRESCRIBED;
        s->node[i].p = (vlbe_real)(fixed ? SS_L * (double)i / (double)ne : (i == ne ? SS_L : 0.0));
    }
    if (vlbe_ale_chain_init3(&s->ch, &s->el, s->node, ne + 1, ne + 1, s->con, 4)) return -1;
    s->ch.pfun = ss_pfun;
    s->ch.user = s;
    memset(&c, 0, sizeof c);
    c.type = VLBE_ALE_CON_POS; /* simple supports */
    c.node = 0;
    if (vlbe_ale_chain_add(&s->ch, &c)) return -1;
    c.node = ne;
    c.which = 3; /* a roller: x, y held, free along the axis */
    if (vlbe_ale_chain_add(&s->ch, &c)) return -1;
    memset(&c, 0, sizeof c);
    c.type = VLBE_ALE_CON_SPIN; /* theta_0 = Omega t */
    c.law[1] = (vlbe_real)SS_OMEGA_SPIN;
    if (vlbe_ale_chain_add(&s->ch, &c) || vlbe_ale_chain_layout(&s->ch)) return -1;
    if (q0 && v0) {
        for (i = 0; i < s->ch.n; ++i) q0[i] = v0[i] = VLBE_R(0.0);
        for (i = 0; i <= ne; ++i) { /* r = (0, 0, p), r' = (0, 0, 1), spinning */
            vlbe_real p3[3];
            const int o = s->node[i].ofs;
            if (vlbe_ale_chain_pnode(&s->ch, i, VLBE_R(0.0), NULL, NULL, p3)) return -1;
            q0[o + 2] = p3[0];
            v0[o + 2] = p3[1];
            q0[o + 5] = VLBE_R(1.0);
            v0[o + 6] = (vlbe_real)SS_OMEGA_SPIN; /* theta = Omega t from 0 */
        }
    }
    s->iload = s->node[ne / 2].ofs;
    s->sys.n = s->ch.n;
    s->sys.m = s->ch.m;
    s->sys.user = s;
    s->sys.mass = ss_mass;
    s->sys.force = ss_force;
    s->sys.constr = ss_constr;
    s->sys.constr_jac = ss_constr_jac;
    s->sys.constr_acc = ss_constr_acc;
    s->sys.force_jac = ss_force_jac;
    s->sys.mass_jac = ss_mass_jac;
    return 0;
}

/* Banded matrices (vlbe_ale_chain_band) and the integrators' banded path
   for a scene ss_setup made (its q0, v0 stay valid); 0 on success. */
static inline int ss_band(ss_scene *s)
{
    if (ex_ale_band(&s->ch, s->order, (int)(sizeof s->order / sizeof s->order[0]))) return -1;
    ex_ale_storage(&s->sys, &s->ch);
    return 0;
}

/* the observer: samples of the load point and of material midspan, every
   s->every steps and at the end */
static inline vlbe_status ss_obs(void *ctx, double t, const vlbe_real *q, const vlbe_real *v,
                                 const vlbe_real *lam)
{
    ss_scene *s = (ss_scene *)ctx;
    vlbe_real r[3], rl[3];
    vlbe_status st;
    const long k = s->step++;
    (void)v;
    (void)lam;
    if ((k % s->every != 0 && t < s->t1 - s->t0 - 0.5 * s->h) || s->ns >= SS_NSAMP_MAX)
        return VLBE_OK;
    /* the chain's clock runs from 0 at t0; the load at material z = v t */
    if ((st = vlbe_ale_chain_point(&s->ch, (vlbe_real)t, q, (vlbe_real)(0.5 * SS_L), r, NULL)) !=
            VLBE_OK ||
        (st = vlbe_ale_chain_point(&s->ch, (vlbe_real)t, q, (vlbe_real)(s->ref.v * (t + s->t0)),
                                   rl, NULL)) != VLBE_OK)
        return st;
    s->t[s->ns] = t + s->t0;
    s->u[0][s->ns] = (double)rl[0];
    s->u[1][s->ns] = (double)rl[1];
    s->u[2][s->ns] = (double)r[0];
    s->u[3][s->ns] = (double)r[1];
    s->ns++;
    return VLBE_OK;
}

/* (U - U_exact) / U_s of the samples against ref, into e[k][i] */
static inline void ss_errors(const ss_scene *s, const ex_katz *ref, int nmodes,
                             double (*e)[SS_NSAMP_MAX])
{
    const double us = ex_katz_us(ref);
    int i, k;
    for (i = 0; i < s->ns; ++i) {
        const double t = s->t[i];
        double r[4] = {0.0, 0.0, 0.0, 0.0}; /* gcc 12 -O3: maybe-uninitialized */
        ex_katz_eval(ref, nmodes, ref->v * t, t, &r[0], &r[1]);
        ex_katz_eval(ref, nmodes, 0.5 * ref->l, t, &r[2], &r[3]);
        for (k = 0; k < 4; ++k) e[k][i] = (s->u[k][i] - r[k]) / us;
    }
}

/* the largest errors of e[k][0 .. ns-1] and where they occur */
static inline void ss_maxerr(const ss_scene *s, double (*e)[SS_NSAMP_MAX], ss_err *m)
{
    int i, k;
    for (k = 0; k < 4; ++k) {
        m->e[k] = 0.0;
        m->z[k] = 0.0;
        for (i = 0; i < s->ns; ++i)
            if (fabs(e[k][i]) > fabs(m->e[k])) {
                m->e[k] = e[k][i];
                m->z[k] = s->ref.v * s->t[i] / s->ref.l;
            }
    }
}

/* Integrates the scene set up in s (ss_setup) from the start state q0, v0
   over the traverse in nsteps HHT steps (alpha); err: the largest errors
   against eq. 59 (s->ref, rot = 1), err0 (may be NULL) against the series
   without the rhoJ terms (s->ref0), both from nmodes modes; the error
   history against eq. 59 is left in s->e, the samples in s; out: the
   run's counters.  Returns the run status. */
static inline vlbe_status ss_integrate(ss_scene *s, const vlbe_real *q0, const vlbe_real *v0,
                                       long nsteps, double alpha, int nmodes, ss_err *err,
                                       ss_err *err0, ex_run_out *out)
{
    vlbe_hht_params par;
    ex_method m;
    vlbe_status st;
    if ((st = ex_hht_pick(&par, alpha, 0.0)) != VLBE_OK) return st;
    /* Newton's velocity test sees the position rounding (axial forces of
       size EA eps carry EA EPS of noise, over the bending stiffness) times
       gamma/(beta h) ~ 4e5: at the default atol 1e-11 the iteration stalls
       on that noise near the short end elements (VLBE_ENOCONV); 1e-8 m
       (1e-5 U_s) is far below the errors compared */
    par.atol = (vlbe_real)SS_ATOL;
    par.max_halvings = 6; /* the last steps, with end elements of z0 l / 2, may need it */
    memset(&m, 0, sizeof m);
    m.hht = &par;
    m.h = (s->t1 - s->t0) / (double)nsteps;
    s->ns = 0;
    s->step = 0;
    s->h = m.h;
    s->every = (int)(nsteps / 2000 + 1);
    st = ex_run(&s->sys, &m, q0, v0, s->t1 - s->t0, ss_obs, s, NULL, NULL, NULL, out);
    if (st != VLBE_OK) return st;
    if (err0) {
        ss_errors(s, &s->ref0, nmodes, s->e);
        ss_maxerr(s, s->e, err0);
    }
    ss_errors(s, &s->ref, nmodes, s->e);
    ss_maxerr(s, s->e, err);
    return VLBE_OK;
}

/* Runs case (a, kw) with ne elements (fixed: the fixed mesh), the load from
   z0 l to (1 - z0) l, the shaft starting at rest: ss_setup, ss_integrate. */
static inline vlbe_status ss_run(ss_scene *s, double a, double kw, int ne, int fixed, double z0,
                                 long nsteps, double alpha, int nmodes, ss_err *err, ss_err *err0,
                                 ex_run_out *out)
{
    vlbe_real q0[SS_NE_MAX * 8 + 8], v0[SS_NE_MAX * 8 + 8];
    if (ss_setup(s, a, kw, ne, fixed, z0, q0, v0)) return VLBE_EARG;
    return ss_integrate(s, q0, v0, nsteps, alpha, nmodes, err, err0, out);
}

/* (The analysis functions below are static inline: a file that includes
   this one without using them gets no unused-function warning.) */

/* the error history s->e[k] at the sample nearest the load position z l */
static inline double ss_err_at(const ss_scene *s, int k, double z)
{
    int i, best = 0;
    for (i = 1; i < s->ns; ++i)
        if (fabs(s->ref.v * s->t[i] - z * s->ref.l) < fabs(s->ref.v * s->t[best] - z * s->ref.l))
            best = i;
    return s->e[k][best];
}

/* The error history s->e[k] split at cyc cycles per traverse: low = the
   line through its end values plus the terms below cyc cycles of the sine
   series of the rest (which vanishes at both ends, so the series has no
   jump to smear), high = e - low.  *lo, *hi: the largest |low|, |high|
   over the run, *zlo the load position z / l of the largest |low|.  The
   coefficients by the trapezoid rule over the samples (m = 1, 2, ..: m/2
   cycles per traverse). */
static inline void ss_split(const ss_scene *s, int k, double cyc, double *lo, double *hi,
                            double *zlo)
{
    const double PI = 3.14159265358979323846, ta = s->t[0], tb = s->t[s->ns - 1];
    const double *e = s->e[k];
    double b[64];
    int i, j, nm = 0;
    while (nm < 64 && 0.5 * (double)(nm + 1) < cyc) ++nm;
    for (j = 0; j < nm; ++j) {
        double sum = 0.0;
        for (i = 0; i + 1 < s->ns; ++i) {
            double f[2];
            int c;
            for (c = 0; c < 2; ++c) {
                const double x = (s->t[i + c] - ta) / (tb - ta);
                f[c] = (e[i + c] - e[0] - (e[s->ns - 1] - e[0]) * x) * sin((j + 1) * PI * x);
            }
            sum += 0.5 * (f[0] + f[1]) * (s->t[i + 1] - s->t[i]) / (tb - ta);
        }
        b[j] = 2.0 * sum;
    }
    *lo = *hi = *zlo = 0.0;
    for (i = 0; i < s->ns; ++i) {
        const double x = (s->t[i] - ta) / (tb - ta);
        double low = e[0] + (e[s->ns - 1] - e[0]) * x;
        for (j = 0; j < nm; ++j) low += b[j] * sin((j + 1) * PI * x);
        if (fabs(low) > *lo) {
            *lo = fabs(low);
            *zlo = s->ref.v * s->t[i] / s->ref.l;
        }
        *hi = fmax(*hi, fabs(e[i] - low));
    }
}

/* The paper's mesh (ne elements) frozen with the load node at z l: the
   nodes fixed at their material points, the straight shaft at rest.  M
   and K = -dQ/dq of the chain (n x n, the chain's n; s is set up as a
   fixed mesh).  0 on success. */
static inline int ss_frozen_mk(ss_scene *s, int ne, double z, vlbe_real *M, vlbe_real *K)
{
    const vlbe_real r0[3] = {0, 0, 0}, dir[3] = {0, 0, 1};
    vlbe_real q[SS_NE_MAX * 8 + 8], v[SS_NE_MAX * 8 + 8];
    int i;
    if (ss_setup(s, 0.5, 1.0, ne, 1, SS_Z0, NULL, NULL)) return -1;
    for (i = 0; i <= ne; ++i) {
        double p, pd;
        ss_mesh(ne, SS_L, z * SS_L, 0.0, i, &p, &pd);
        s->node[i].p = (vlbe_real)p;
    }
    vlbe_ale_chain_straight(&s->ch, r0, dir, q);
    for (i = 0; i < s->ch.n; ++i) v[i] = VLBE_R(0.0);
    if (vlbe_ale_chain_mass(&s->ch, VLBE_R(0.0), q, v, M) ||
        vlbe_ale_chain_force_jac(&s->ch, VLBE_R(0.0), q, v, K, NULL))
        return -1;
    for (i = 0; i < s->ch.n * s->ch.n; ++i) K[i] = -K[i];
    return 0;
}

/* The X1 bending coordinates of the frozen chain in s: x, x' of every
   node but x of the two supports (held by the constraints); their
   indices into idx (2 ne of them).  Returns their number. */
static inline int ss_bending_dofs(const ss_scene *s, int *idx)
{
    int i, nb = 0;
    for (i = 0; i <= s->ne; ++i) {
        if (i > 0 && i < s->ne) idx[nb++] = s->node[i].ofs;
        idx[nb++] = s->node[i].ofs + 3;
    }
    return nb;
}

/* The nf lowest bending frequencies w[0 .. nf-1] (rad/s) of the paper's
   mesh (ne elements) frozen with the load node at z l.  At the straight
   state X1 bending decouples from X2 bending, the axial and the torsional
   coordinates (tests/test_scenes_shaft.c checks it), so the X1 block of M
   and K gives them, by vlbe_eig_gsym with sigma = 0 (shift-invert: the
   lowest modes of a stiff system to a few EPS).  0 on success. */
static inline int ss_frozen_freq(ss_scene *s, int ne, double z, int nf, double *w)
{
    const size_t n = (size_t)(SS_NE_MAX + 1) * 7;
    vlbe_real *M = (vlbe_real *)malloc(n * n * sizeof *M);
    vlbe_real *K = (vlbe_real *)malloc(n * n * sizeof *K);
    vlbe_real Mb[4 * SS_NE_MAX * SS_NE_MAX], Kb[4 * SS_NE_MAX * SS_NE_MAX], lam[2 * SS_NE_MAX];
    vlbe_real *wk = NULL;
    int idx[2 * SS_NE_MAX], nb = 0, i, j, info = 0, rc = -1;
    if (M && K && ss_frozen_mk(s, ne, z, M, K) == 0) {
        const int nc = s->ch.n;
        nb = ss_bending_dofs(s, idx);
        for (i = 0; i < nb; ++i)
            for (j = 0; j < nb; ++j) {
                Mb[i * nb + j] = M[idx[i] * nc + idx[j]];
                Kb[i * nb + j] = K[idx[i] * nc + idx[j]];
            }
        wk = (vlbe_real *)malloc(vlbe_eig_work_len(nb) * sizeof *wk);
        if (wk && nf <= nb &&
            vlbe_eig_gsym(nb, Kb, Mb, VLBE_R(0.0), lam, NULL, &info, wk, vlbe_eig_work_len(nb)) ==
                VLBE_OK) {
            for (i = 0; i < nf; ++i) w[i] = sqrt((double)lam[i]);
            rc = 0;
        }
    }
    free(M);
    free(K);
    free(wk);
    return rc;
}

#endif /* VLBE_SCENE_SPINNING_SHAFT_H */
