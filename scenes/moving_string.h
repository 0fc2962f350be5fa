/* moving_string.h -- the axially moving string and beam of vlbse
   section 4.1 in a fixed window: the planar and 3D chains (ms_build,
   ms_build_at), the exact first frequency, the runs and their frequency
   (ms_freq_run, ms_freq), the comparison of two models (ms_compare), the
   eigen route (ms_linearize, ms_eig), the Galerkin continuum reference
   (ms_galerkin) and the divergence speed (ms_diverged, ms_divergence).
   Shared by examples/moving_string.c, which states the scene and its
   closed forms, tests/test_chain_ale.c, tests/test_modal.c,
   tests/test_scenes_moving3d.c, tests/test_scenes_band.c and
   bench/wp_moving.c.
   -- part of vlbe                                  SPDX-License-Identifier: MIT */
#ifndef VLBE_SCENE_MOVING_STRING_H
#define VLBE_SCENE_MOVING_STRING_H

#include "../ancf_ale.h"
#include "ex_ale.h"
#include "ex_freq.h"
#include "ex_run.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MS_L 1.0
#define MS_R 0.005
#define MS_RHO 2700.0
#define MS_E 70e9
#define MS_F 1000.0
#define MS_V0 40.0
#define MS_F1_PAPER_EXACT 22.6857  /* eq. (56), as printed               */
#define MS_F1_PAPER_VLBE 22.6786   /* VLBE, 4 elements (string)          */
#define MS_F1_PAPER_VLBSE 22.6723  /* VLBSE, 4 elements (string)         */
#define MS_F1_PAPER_BEAM 32.2425   /* VLBE, 4 elements (beam)            */
#define MS_F1_PAPER_BEAM3 32.2097  /* VLBSE, 4 elements (beam)           */
#define MS_NU 0.3                  /* Poisson's ratio for G (twist only)  */
#define MS_NE_MAX 64
#define MS_NQ_NODE 8               /* coordinates per node, at most (3D: r, r', theta, p) */

/* Model kinds (the `kind` argument; 0 and 1 are the planar string, beam). */
#define MS_BEND 1   /* the beam (EI); otherwise the string                 */
#define MS_3D 2     /* 3D beam-shaft chain (VLBSE) instead of the planar one */
#define MS_NOSPIN 4 /* 3D: without the spin angle (VLBE_ALE3_NO_SPIN)      */
#define MS_XZ 8     /* 3D: vibration in the x-z plane (else x-y)           */
#define MS_BAND 16  /* banded matrices (vlbe_ale_chain_band) and the
                       integrators' banded path; else dense             */

typedef struct ms_model {
    vlbe_ale_mat mat;
    vlbe_ale_elem el;
    vlbe_ale3_elem el3;
    vlbe_ale_node node[MS_NE_MAX + 1];
    vlbe_ale_con con[2];
    vlbe_ale_chain ch;
    vlbe_dae sys;
    int order[MS_NQ_NODE * (MS_NE_MAX + 1) + 6]; /* MS_BAND: the augmented order */
    double lam, eps, T; /* prestretch and tension */
    int ne, bend, kind;
    int tr;             /* component of the transverse motion: 1 (y) or 2 (z) */
} ms_model;

/* Section and prestretch: T = EA eps sqrt(1 + 2 eps) = F (vlbe_ale_prestretch). */
static inline void ms_section(double *rhoA, double *EA, double *EI, double *eps, double *lam)
{
    const double PI = 3.14159265358979323846, A = PI * MS_R * MS_R;
    vlbe_real e = 0, l = 1;
    *rhoA = MS_RHO * A;
    *EA = MS_E * A;
    *EI = MS_E * PI * MS_R * MS_R * MS_R * MS_R / 4.0;
    (void)vlbe_ale_prestretch((vlbe_real)*EA, (vlbe_real)MS_F, &e, &l); /* EA > 0, F > 0: VLBE_OK */
    *eps = (double)e;
    *lam = (double)l;
}

/* The exact first frequency of the prestretched moving string (see the
   top of examples/moving_string.c). */
static inline double ms_f1_exact(void)
{
    double rhoA, EA, EI, eps, lam, c;
    ms_section(&rhoA, &EA, &EI, &eps, &lam);
    c = sqrt(MS_F * lam / rhoA);
    return (c * c - MS_V0 * MS_V0) / (2.0 * MS_L * c);
}

/* Builds the window of ne elements of the given kind (MS_*), the material
   flowing through at `speed` (ms_build: the paper's v0); q0, v0 (size
   m->ch.n, at most MS_NQ_NODE (ne + 1)) get the straight prestretched state
   with the initial transverse velocities. */
static inline int ms_build_at(ms_model *m, int ne, int kind, double speed, vlbe_real *q0,
                              vlbe_real *v0)
{
    const double PI = 3.14159265358979323846;
    const int d3 = (kind & MS_3D) != 0;
    const unsigned flags = ((kind & MS_BEND) ? 0u : VLBE_ALE_NO_BEND) | VLBE_ALE_NO_DAMP;
    double rhoA, EA, EI;
    vlbe_real r0[3] = {0, 0, 0}, dir[3] = {0, 0, 0}, s[MS_NE_MAX + 1];
    vlbe_ale_con c;
    int i;
    if (ne < 2 || ne > MS_NE_MAX || kind < 0 || kind > 31 || (!d3 && (kind & ~MS_BAND) > 1))
        return -1;
    memset(m, 0, sizeof *m);
    ms_section(&rhoA, &EA, &EI, &m->eps, &m->lam);
    m->T = MS_F;
    m->ne = ne;
    m->bend = kind & MS_BEND;
    m->kind = kind;
    m->tr = (kind & MS_XZ) ? 2 : 1;
    m->mat.rhoA = (vlbe_real)rhoA;
    m->mat.EA = (vlbe_real)EA;
    m->mat.EI = (vlbe_real)EI;
    if (d3) {
        const double Ip = 2.0 * EI / MS_E; /* polar: pi r^4 / 2 */
        vlbe_ale3_mat m3;
        memset(&m3, 0, sizeof m3);
        m3.rhoA = m->mat.rhoA;
        m3.EA = m->mat.EA;
        m3.EJ = m->mat.EI;
        m3.rhoI = (vlbe_real)(MS_RHO * Ip);
        m3.GI = (vlbe_real)(MS_E / (2.0 * (1.0 + MS_NU)) * Ip);
        if (vlbe_ale3_elem_init(&m->el3, &m3, flags | ((kind & MS_NOSPIN) ? VLBE_ALE3_NO_SPIN : 0u),
                                0, 0))
            return -1;
    } else if (vlbe_ale_elem_init(&m->el, &m->mat, flags, 0, 0, 0)) {
        return -1;
    }
    if ((d3 ? vlbe_ale_chain_init3(&m->ch, &m->el3, m->node, ne + 1, MS_NE_MAX + 1, m->con, 2)
            : vlbe_ale_chain_init(&m->ch, &m->el, m->node, ne + 1, MS_NE_MAX + 1, m->con, 2)))
        return -1;
    /* the window: nodes at x_i = l i / ne, the material flowing through at
       v0 with the stretch lam (p_i = (x_i - v0 t) / lam) */
    for (i = 0; i <= ne; ++i) s[i] = (vlbe_real)(MS_L * i / ne);
    if (vlbe_ale_chain_window(&m->ch, s, (vlbe_real)m->lam, (vlbe_real)speed)) return -1;
    memset(&c, 0, sizeof c);
    c.type = VLBE_ALE_CON_POS; /* supports: positions fixed (pinned; 3D: all 3 components) */
    c.node = 0;
    vlbe_ale_chain_add(&m->ch, &c);
    c.node = ne;
    c.r[0] = (vlbe_real)MS_L;
    vlbe_ale_chain_add(&m->ch, &c);
    if (vlbe_ale_chain_layout(&m->ch)) return -1;
    if ((kind & MS_BAND) &&
        ex_ale_band(&m->ch, m->order, (int)(sizeof m->order / sizeof m->order[0])))
        return -1;
    if (vlbe_ale_chain_dae(&m->ch, &m->sys)) return -1;
    if (q0) {
        dir[0] = (vlbe_real)m->lam;
        vlbe_ale_chain_straight(&m->ch, r0, dir, q0); /* theta = 0 */
    }
    if (v0) {
        for (i = 0; i < m->ch.n; ++i) v0[i] = 0;
        for (i = 1; i < ne; ++i) v0[m->node[i].ofs + m->tr] = (vlbe_real)(1e-4 * sin(PI * i / ne));
    }
    return 0;
}

static inline int ms_build(ms_model *m, int ne, int kind, vlbe_real *q0, vlbe_real *v0)
{
    return ms_build_at(m, ne, kind, MS_V0, q0, v0);
}

/* Samples of one run: the transverse displacement of the middle node (y),
   and with `all` set by the caller before the run (ms_freq_run's keep)
   every node's position in the frame of the vibration plane, r[3 (s nn +
   i) + k] at sample s, node i: k = 0 axial, 1 transverse in the plane of
   vibration, 2 out of that plane (0 in a planar chain), and the largest
   |out-of-plane| position or slope and |theta| (3D) over the run. */
typedef struct ms_obs {
    int idx;        /* coordinate observed (transverse, middle node) */
    size_t n, cap;
    double *y;
    int all;        /* in: record r, oop, th                         */
    const ms_model *m;
    double *r;
    double oop, th;
} ms_obs;

static inline vlbe_status ms_observe(void *ctx, double t, const vlbe_real *q, const vlbe_real *v,
                                     const vlbe_real *lam)
{
    ms_obs *o = (ms_obs *)ctx;
    (void)t, (void)v, (void)lam;
    if (o->n >= o->cap) return VLBE_OK;
    if (o->r) {
        const ms_model *m = o->m;
        const int d = m->ch.d, nn = m->ne + 1, tr = m->tr, oo = 3 - tr;
        int i;
        for (i = 0; i < nn; ++i) {
            const int a = m->node[i].ofs;
            double *ri = o->r + 3 * (o->n * (size_t)nn + (size_t)i);
            ri[0] = (double)q[a];
            ri[1] = (double)q[a + tr];
            ri[2] = d == 3 ? (double)q[a + oo] : 0.0;
            if (d == 3) {
                o->oop = fmax(o->oop, fmax(fabs(ri[2]), fabs((double)q[a + 3 + oo])));
                if (m->ch.spin) o->th = fmax(o->th, fabs((double)q[a + 6]));
            }
        }
    }
    o->y[o->n++] = (double)q[o->idx];
    return VLBE_OK;
}

/* One run: first frequency from the response of ne elements of the given
   kind (MS_*; 0 string, 1 beam) with step h over t_end (HHT family par);
   *cpu gets the run time, *stats the counters, *keep (if not NULL, zeroed
   by the caller, keep->all set for the whole history) the samples.
   Returns the frequency, or -1 on failure. */
static inline double ms_freq_run(int ne, int kind, double h, double t_end,
                                 const vlbe_hht_params *par, double *cpu, vlbe_dae_stats *stats,
                                 ms_obs *keep)
{
    const int bend = kind & MS_BEND;
    ms_model *m = (ms_model *)malloc(sizeof *m);
    vlbe_real *q0 = NULL, *v0 = NULL;
    double f = -1.0, *w = NULL;
    ex_method meth;
    ex_run_out out;
    ms_obs o;
    memset(&o, 0, sizeof o);
    memset(&meth, 0, sizeof meth);
    if (!m) return -1.0;
    q0 = (vlbe_real *)malloc(MS_NQ_NODE * (MS_NE_MAX + 1) * sizeof *q0);
    v0 = (vlbe_real *)malloc(MS_NQ_NODE * (MS_NE_MAX + 1) * sizeof *v0);
    o.cap = (size_t)(t_end / h + 2.5);
    o.y = (double *)malloc(o.cap * sizeof *o.y);
    w = (double *)malloc(o.cap * sizeof *w);
    if (keep && keep->all) {
        o.r = (double *)malloc(3 * (size_t)(ne + 1) * o.cap * sizeof *o.r);
        if (!o.r) o.cap = 0; /* nothing to record into: fail below */
    }
    if (q0 && v0 && o.y && w && o.cap && ms_build(m, ne, kind, q0, v0) == 0) {
        o.idx = m->node[ne / 2].ofs + m->tr;
        o.m = m;
        meth.hht = par;
        meth.h = h;
        if (ex_run(&m->sys, &meth, q0, v0, t_end, ms_observe, &o, NULL, NULL, NULL, &out) ==
            VLBE_OK)
            f = ex_peak_freq(o.y, o.n, h, bend ? 20.0 : 12.0, bend ? 45.0 : 33.0, w);
        if (cpu) *cpu = out.cpu;
        if (stats) *stats = out.stats;
    }
    o.m = NULL; /* freed below */
    if (keep && f > 0) {
        o.all = keep->all;
        *keep = o;
        o.y = NULL;
        o.r = NULL;
    }
    free(o.y);
    free(o.r);
    free(w);
    free(q0);
    free(v0);
    free(m);
    return f;
}

/* Richardson-extrapolated frequency from steps h and h/2. */
static inline double ms_freq(int ne, int kind, double h, double t_end, double *cpu,
                             vlbe_dae_stats *st)
{
    vlbe_hht_params par;
    double c1 = 0, c2 = 0, f1, f2;
    vlbe_hht_params_genalpha(&par, VLBE_R(0.9));
    f1 = ms_freq_run(ne, kind, h, t_end, &par, &c1, NULL, NULL);
    f2 = ms_freq_run(ne, kind, 0.5 * h, t_end, &par, &c2, st, NULL);
    if (cpu) *cpu = c1 + c2;
    if (f1 < 0 || f2 < 0) return -1.0;
    return f2 + (f2 - f1) / 3.0;
}

/* Two models of one scene, same ne, h, t_end and integrator (generalized-
   alpha rho 0.9), sample by sample: d[k] = max |r_a - r_b| over the nodes
   and samples per component (axial, transverse, out of plane; see ms_obs),
   amax[k] = max |r_b|, oop and th of run a, both frequencies, CPU times. */
typedef struct ms_cmp {
    double d[3], amax[3];
    double oop, th;
    double fa, fb, cpu_a, cpu_b;
    size_t n;
} ms_cmp;

static inline int ms_compare(int ne, int kind_a, int kind_b, double h, double t_end, ms_cmp *c)
{
    vlbe_hht_params par;
    ms_obs a, b;
    size_t s;
    int rc = -1, k;
    memset(c, 0, sizeof *c);
    memset(&a, 0, sizeof a);
    memset(&b, 0, sizeof b);
    a.all = b.all = 1;
    vlbe_hht_params_genalpha(&par, VLBE_R(0.9));
    c->fa = ms_freq_run(ne, kind_a, h, t_end, &par, &c->cpu_a, NULL, &a);
    c->fb = ms_freq_run(ne, kind_b, h, t_end, &par, &c->cpu_b, NULL, &b);
    if (c->fa > 0 && c->fb > 0 && a.n == b.n) {
        c->n = a.n;
        for (s = 0; s < 3 * (size_t)(ne + 1) * a.n; ++s) {
            k = (int)(s % 3);
            c->d[k] = fmax(c->d[k], fabs(a.r[s] - b.r[s]));
            c->amax[k] = fmax(c->amax[k], fabs(b.r[s]));
        }
        c->oop = a.oop;
        c->th = a.th;
        rc = 0;
    }
    free(a.y);
    free(a.r);
    free(b.y);
    free(b.r);
    return rc;
}

/* -- the eigen route -------------------------------------------------------
   Frequencies of the window without a time history: the straight
   prestretched state at rest (q0, v = 0) is a steady state of the flowing
   chain; q'' and lambda there by vlbe_dae_consistent_acc, then the
   linearisation (vlbe_dae_linearize: M, D with the transport's Coriolis
   term 2 rhoA v0 w_xt, K with the tension and the -rhoA v0^2 w_xx of eq.
   54, the supports' null space) and the gyroscopic eigenproblem
   (vlbe_eig_quad, shift sigma = -2 pi 5 rad/s: the lowest |s| first). */
typedef struct ms_lin {
    int nr;                        /* reduced size                          */
    double amax;                   /* largest |q''| of the steady state     */
    vlbe_real *Mr, *Dr, *Kr;       /* nr x nr each (n x n allocated)        */
    vlbe_real *sre, *sim, *w;      /* 2n, 2n, lw: eigenvalues and workspace */
    int *iw;
    size_t lw, liw;
} ms_lin;

static inline void ms_lin_free(ms_lin *L)
{
    free(L->Mr), free(L->Dr), free(L->Kr), free(L->sre), free(L->sim), free(L->w), free(L->iw);
    memset(L, 0, sizeof *L);
}

/* The reduced M, D, K of the window of ne elements (kind) at `speed`, with
   the workspace an eigen-solve of them needs; *L freed by ms_lin_free
   (also after a failure). */
static inline vlbe_status ms_linearize(int ne, int kind, double speed, ms_lin *L)
{
    ms_model *m = (ms_model *)malloc(sizeof *m);
    vlbe_real *q = (vlbe_real *)malloc(MS_NQ_NODE * (MS_NE_MAX + 1) * sizeof *q);
    vlbe_real *v = (vlbe_real *)calloc(MS_NQ_NODE * (MS_NE_MAX + 1), sizeof *v);
    vlbe_real *a = NULL, *lam = NULL;
    vlbe_status st = VLBE_EWORK;
    size_t N2;
    int n;
    memset(L, 0, sizeof *L);
    if (!m || !q || !v) goto done;
    if (ms_build_at(m, ne, kind, speed, q, NULL)) {
        st = VLBE_EARG;
        goto done;
    }
    n = m->sys.n;
    N2 = (size_t)n * (size_t)n;
    L->lw = vlbe_dae_lin_work_len_sys(&m->sys);
    if (vlbe_dae_work_len_sys(&m->sys) > L->lw) L->lw = vlbe_dae_work_len_sys(&m->sys);
    if (vlbe_eig_quad_work_len(n) > L->lw) L->lw = vlbe_eig_quad_work_len(n);
    L->liw = vlbe_dae_lin_iwork_len_sys(&m->sys);
    if (vlbe_dae_iwork_len_sys(&m->sys) > L->liw) L->liw = vlbe_dae_iwork_len_sys(&m->sys);
    if (vlbe_eig_quad_iwork_len(n) > L->liw) L->liw = vlbe_eig_quad_iwork_len(n);
    a = (vlbe_real *)malloc((size_t)n * sizeof *a);
    lam = (vlbe_real *)malloc(((size_t)m->sys.m + 1) * sizeof *lam);
    L->Mr = (vlbe_real *)malloc(N2 * sizeof *L->Mr);
    L->Dr = (vlbe_real *)malloc(N2 * sizeof *L->Dr);
    L->Kr = (vlbe_real *)malloc(N2 * sizeof *L->Kr);
    L->sre = (vlbe_real *)malloc(2 * (size_t)n * sizeof *L->sre);
    L->sim = (vlbe_real *)malloc(2 * (size_t)n * sizeof *L->sim);
    L->w = (vlbe_real *)malloc(L->lw * sizeof *L->w);
    L->iw = (int *)malloc(L->liw * sizeof *L->iw + sizeof *L->iw);
    if (!a || !lam || !L->Mr || !L->Dr || !L->Kr || !L->sre || !L->sim || !L->w || !L->iw)
        goto done;
    st = vlbe_dae_consistent_acc(&m->sys, 0, q, v, a, lam, NULL, L->w, L->lw, L->iw, L->liw);
    if (st != VLBE_OK) goto done;
    L->amax = (double)vlbe_vec_norm_inf(n, a);
    st = vlbe_dae_linearize(&m->sys, 0, q, v, a, lam, NULL, &L->nr, NULL, L->Mr, L->Dr, L->Kr,
                            NULL, L->w, L->lw, L->iw, L->liw);
done:
    free(q), free(v), free(a), free(lam), free(m);
    return st;
}

/* f[0..nf-1]: the lowest frequencies Im s / 2 pi [Hz] of the window (-1 if
   fewer), *amax (may be NULL) the largest |q''| of the steady state (0 to
   rounding: it is an equilibrium of the flowing chain). */
static inline vlbe_status ms_eig(int ne, int kind, double speed, int nf, double *f, double *amax,
                                 double *cpu)
{
    const clock_t c0 = clock();
    ms_lin L;
    vlbe_status st = ms_linearize(ne, kind, speed, &L);
    int k, j;
    for (k = 0; k < nf; ++k) f[k] = -1.0;
    if (amax) *amax = L.amax;
    if (st == VLBE_OK)
        st = vlbe_eig_quad(L.nr, L.Mr, L.Dr, L.Kr, (vlbe_real)(-2.0 * 3.14159265358979323846 * 5.0),
                           L.sre, L.sim, 0, NULL, NULL, L.w, L.lw, L.iw, L.liw);
    for (k = j = 0; st == VLBE_OK && k < 2 * L.nr && j < nf; ++k)
        if (L.sim[k] > 0) f[j++] = (double)L.sim[k] / (2.0 * 3.14159265358979323846);
    ms_lin_free(&L);
    if (cpu) *cpu = (double)(clock() - c0) / (double)CLOCKS_PER_SEC;
    return st;
}

/* The continuum reference of the pinned-pinned moving beam (eq. 54 in the
   prestretched window: per length in space the mass rhoA / lam, the
   tension T and the bending stiffness EI / lam, since the element's p is
   the unstretched length; at v = 0, w^2 = k^2 (lam T + EI k^2) / rhoA,
   which the elements converge to as h^4): Galerkin on
   nm sine modes phi_k = sin(k pi x / l) (Wickert and Mote 1990):
        M = (rho l / 2) I,   K = diag((l / 2) [EI (k pi/l)^4 + (T - rho v^2)(k pi/l)^2]),
        G_jk = 2 rho v int phi_j phi_k' dx = 2 rho v 2 j k / (j^2 - k^2)  (j + k odd),
   (s^2 M + s G + K) a = 0 by vlbe_eig_quad; the lowest nf frequencies
   [Hz].  EI = 0: the string, whose every mode is exact in closed form,
   f_k = k (c^2 - v^2) / (2 l c); the sine modes are then exact for v = 0
   only (G couples them) and the series converges as 1/nm^2 (at nm = 48
   and v = 40..60 m/s: f1 1.6e-6 .. 3.7e-6, f3 1.4e-5 .. 3.4e-5 from the
   closed form).  The beam's series converges faster (its stiffness grows
   as k^4): 24 and 48 modes differ by 3e-8 .. 6e-8 in f1 and up to 8e-7 in
   f3 at those speeds, its error at 48 modes a third of that. */
#define MS_GAL_MAX 48
static inline vlbe_status ms_galerkin(int bend, double speed, int nm, int nf, double *f)
{
    static vlbe_real M[MS_GAL_MAX * MS_GAL_MAX], G[MS_GAL_MAX * MS_GAL_MAX],
        K[MS_GAL_MAX * MS_GAL_MAX], sre[2 * MS_GAL_MAX], sim[2 * MS_GAL_MAX];
    const double PI = 3.14159265358979323846, l = MS_L;
    double rhoA, EA, EI, eps, lam, rho;
    vlbe_real *w;
    int *iw, j, k;
    vlbe_status st;
    if (nm < 1 || nm > MS_GAL_MAX) return VLBE_EARG;
    ms_section(&rhoA, &EA, &EI, &eps, &lam);
    EI = bend ? EI / lam : 0.0; /* per length in space (p is the unstretched length) */
    rho = rhoA / lam;
    for (j = 0; j < nm; ++j)
        for (k = 0; k < nm; ++k) {
            const double kj = (j + 1) * PI / l;
            const int a = j + 1, b = k + 1;
            M[j * nm + k] = (vlbe_real)(j == k ? 0.5 * rho * l : 0.0);
            K[j * nm + k] = (vlbe_real)(j == k ? 0.5 * l * (EI * kj * kj * kj * kj +
                                                            (MS_F - rho * speed * speed) * kj * kj)
                                               : 0.0);
            G[j * nm + k] =
                (vlbe_real)((a + b) % 2 ? 2.0 * rho * speed * 2.0 * a * b / (double)(a * a - b * b)
                                        : 0.0);
        }
    w = (vlbe_real *)malloc(vlbe_eig_quad_work_len(nm) * sizeof *w);
    iw = (int *)malloc(vlbe_eig_quad_iwork_len(nm) * sizeof *iw + sizeof *iw);
    st = w && iw ? vlbe_eig_quad(nm, M, G, K, (vlbe_real)(-2.0 * PI * 5.0), sre, sim, 0, NULL, NULL, w,
                                 vlbe_eig_quad_work_len(nm), iw, vlbe_eig_quad_iwork_len(nm))
                 : VLBE_EWORK;
    for (k = j = 0; st == VLBE_OK && k < 2 * nm && j < nf; ++k)
        if (sim[k] > 0) f[j++] = (double)sim[k] / (2.0 * PI);
    free(w);
    free(iw);
    return st;
}

/* Has the window of ne elements (kind) lost its static stiffness at
   `speed`: an eigenvalue of the reduced K with a negative real part?  (The
   divergence: at that speed the lowest frequency is 0.  The beam's
   gyroscopic system then has a real pair +-s; the string's stays on the
   imaginary axis beyond it, the gyroscopic stabilisation of a string, so
   the test is on K and not on the growth of the motion.)  -1 if the
   analysis fails. */
static inline int ms_diverged(int ne, int kind, double speed)
{
    ms_lin L;
    int k, rc = -1;
    if (ms_linearize(ne, kind, speed, &L) == VLBE_OK &&
        vlbe_eig_real(L.nr, L.Kr, L.sre, L.sim, L.w, L.lw) == VLBE_OK)
        for (k = 0, rc = 0; k < L.nr; ++k)
            if (L.sre[k] < 0) rc = 1;
    ms_lin_free(&L);
    return rc;
}

/* The divergence speed of the model by bisection between lo (below) and
   hi (above), to 1e-9 relative; -1 if the bracket is not one. */
static inline double ms_divergence(int ne, int kind, double lo, double hi)
{
    int it;
    if (ms_diverged(ne, kind, lo) != 0 || ms_diverged(ne, kind, hi) != 1) return -1.0;
    for (it = 0; it < 60 && hi - lo > 1e-9 * hi; ++it) {
        const double mid = 0.5 * (lo + hi);
        const int u = ms_diverged(ne, kind, mid);
        if (u < 0) return -1.0;
        if (u) hi = mid;
        else lo = mid;
    }
    return 0.5 * (lo + hi);
}

#endif /* VLBE_SCENE_MOVING_STRING_H */
