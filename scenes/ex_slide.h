/* ex_slide.h -- a lumped mass sliding without friction along a planar
   ALE-ANCF beam (ancf_ale.h) under gravity, with the length control of
   ale-rancf Figure 7: the model and the run loop shared by the sliding-mass
   scenes (examples/falling_beam.c, examples/suspended_beam.c) and their
   tests.                                          -- part of vlbe
                                                   SPDX-License-Identifier: MIT

   The beam: N elements of L_std = L/N on a straight horizontal start, nodes
   at k L_std; the node nearest to the mass (never an end node) becomes the
   sliding node: free material coordinate p0, carrying the mass, one slope
   vector (at a point mass the slope is continuous: eq. (40)'s continuous
   case with the two slopes merged).  Elements next to the sliding node are
   ALE, all others Lagrangian (fixed p), as in the paper.  Supports:
   clamped-free (position and slope direction at the left end) or pinned-
   pinned (positions at both ends).

   Elements: ALE-ANCF (ancf_ale.h) or, with cfg.rational, ALE-RANCF
   (rancf.h: a chain of vlbe_rancf_elem, unit weights on the straight
   start; length control then splits exactly and gives merged elements
   least-squares weights, eqs. 21-38 of the paper).  Every weight set
   made by length control is collected (ex_slide_out.wall / .wmerge: the
   paper's Table 2 statistics, eq. 42).
   Start shape: straight, or with cfg.R > 0 a semicircle of radius R
   hanging below the supports (0, 0) and (2R, 0) (pinned-pinned; ale-rancf
   6.3; L = pi R): N arcs of central angle pi/N and reference length R pi/N
   (vlbe_rancf_arc, eq. 43: exact with rational elements; ALE-ANCF: the
   Hermite cubics through the same nodes and unit tangents).  The sliding
   node is made by exact segmentation of the element holding p0 (unless p0
   is a node), so the chain has N or N + 1 elements.  The arc's
   parametrisation is not by arc length (|r'| = 2 sin(th/2)/th at the
   nodes, more inside), so the start is not stress-free: the reference is
   straight and the start carries that axial strain and the bending
   EI/R^2 of the curve.

   The run: HHT-alpha with a fixed step (halving when Newton fails or an
   iterate leaves the chain's domain); after every step the length control
   (vlbe_ale_chain_length_control) and, after a change, a restart of the
   integrator from the mapped state (positions and velocities exact).  The
   energy T + U + V is tracked: the drift within the steps (the jumps of
   the length control taken out) and every jump, with the jump of the beam's
   arc length.  For the clamped-free beam the run ends when the mass reaches
   the free end: the element ahead of it, the last one, shorter than
   stop L_std (there is no node left to remove there, the element shrinks
   to nothing and its bending frequency grows as 1/L^2); the leaving time is
   p(t) extrapolated to p = L with p' and p''.  A run that would need more
   than ceil(t_end / h) + 2 steps stops with VLBE_ESTEP and a message on
   stderr.  Examples may allocate; the run mallocs its workspace. */
#ifndef VLBE_EX_SLIDE_H
#define VLBE_EX_SLIDE_H

#include "../rancf.h"
#include "ex_ale.h"

#include <stddef.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define EX_SLIDE_NMAX 64   /* elements, at most                         */
#define EX_SLIDE_MAXEV 256 /* length-control events recorded, at most   */
#define EX_SLIDE_MAXSHAPE 4 /* length-control events whose shapes are sampled, at most */
/* coordinates at most: nodes of [r, r'] and the slider's p; constraint rows
   at most (clamp: 3, pins: 4) */
#define EX_SLIDE_NQ (4 * (EX_SLIDE_NMAX + 2) + 1)
#define EX_SLIDE_MROWS 4

enum { EX_SLIDE_CLAMP_FREE = 0, EX_SLIDE_PIN_PIN = 1 };

typedef struct ex_slide_cfg {
    int N;            /* elements                                            */
    int support;      /* EX_SLIDE_CLAMP_FREE or EX_SLIDE_PIN_PIN              */
    unsigned flags;   /* element flags: 0 (the paper's) or VLBE_ALE_CONSERVATIVE */
    double L, r, rho, E, g; /* beam length, section radius, density, modulus, gravity */
    double mass, p0, v0;    /* lumped mass, its start and start speed along the beam */
    double h, alpha, t_end; /* HHT step, alpha, end time                     */
    int halvings;           /* HHT step halvings                            */
    double probe_p;         /* material point whose y is recorded           */
    double stop;            /* clamped-free: end at an element ahead < stop L_std */
    int rational;           /* 1: ALE-RANCF elements (rancf.h)              */
    double R;               /* > 0: semicircle start of radius R (pinned-pinned) */
    int band;               /* 1: banded matrices (vlbe_ale_chain_band) and the
                               integrator's banded path; 0: dense (default) */
} ex_slide_cfg;

/* one row per accepted step (and t = 0); optionally (ex_slide_hist_shapes)
   the beam sampled at shape_pts material points, uniform on [0, L], just
   before and just after each of the first shape_events length-control
   events (ale-rancf Figure 12): shape + (4 k + j) shape_pts, j = 0, 1: x, y
   before event k, j = 2, 3: x, y after it; shape_t[k] its time, shape_done
   the events sampled. */
typedef struct ex_slide_hist {
    int n, cap;
    double *t, *probe_y, *mass_x, *mass_y, *mass_p, *energy, *length, *rate;
    int shape_events, shape_pts, shape_done;
    double shape_t[EX_SLIDE_MAXSHAPE];
    double *shape;
} ex_slide_hist;

typedef struct ex_slide_event {
    double t, dE, dlen; /* time, jump of T + U + V [J] and of the arc length [m] */
    int changed;        /* 1: node inserted, 2: inserted and one removed (merge) */
} ex_slide_event;

/* a set of weights k_i (eq. 33) made by length control: size, extremes and
   the deviation sigma = sqrt(sum (k - 1)^2 / n) of eq. (42) */
typedef struct ex_slide_wset {
    long n;
    double kmax, kmin, ss;
} ex_slide_wset;

typedef struct ex_slide_out {
    vlbe_status status;
    double t_leave;      /* clamped-free: the mass leaves the beam (-1: not reached) */
    double t_stop, p_stop; /* time and material coordinate of the mass at the end */
    double cpu, cpu_lc;  /* CPU seconds: all; length control and restarts (not the
                            diagnostics around them)                     */
    long steps, rejected, newton, lu, lc_events;
    double E0, T_max;    /* energy at t = 0, largest kinetic energy [J]    */
    double dE_gain, dE_loss; /* extremes of E - E0 within the steps, jumps out [J] */
    double dE_lc;        /* largest |energy jump| at a length-control event [J] */
    int nev;
    ex_slide_event ev[EX_SLIDE_MAXEV];
    /* rational: k0, k1, k2 (k3 = 1) of every element made by length control
       (wall: split parts and merged elements; wmerge: merged only) and the
       merges that fell back to unit weights (eq. 38) */
    ex_slide_wset wall, wmerge;
    long merge_fallbacks;
} ex_slide_out;

typedef struct ex_slide {
    vlbe_ale_mat mat;
    vlbe_ale_elem el;
    vlbe_ale_node node[EX_SLIDE_NMAX + 2];
    vlbe_ale_con con[4];
    vlbe_ale_chain ch;
    vlbe_dae sys;
    int slider;
    double Lstd;
    ex_slide_wset wall, wmerge; /* rational: weights made by length control */
    long merge_fallbacks;
    vlbe_ale_etype et;          /* rational: rancf.h's calls, commit recorded */
    vlbe_rancf_elem els[EX_SLIDE_NMAX + 1];
    /* cfg.band: the augmented order, room for the largest layout and the
       4 more an insertion needs */
    int order[EX_SLIDE_NQ + EX_SLIDE_MROWS + 4];
} ex_slide;

static inline double ex_slide_sigma(const ex_slide_wset *w)
{
    return w->n > 0 ? sqrt(w->ss / (double)w->n) : 0.0;
}

static inline void ex_slide_wadd(ex_slide_wset *w, const vlbe_real *k)
{
    int i;
    for (i = 0; i < 3; ++i) {
        const double x = (double)k[i];
        if (w->n == 0 || x > w->kmax) w->kmax = x;
        if (w->n == 0 || x < w->kmin) w->kmin = x;
        w->ss += (x - 1.0) * (x - 1.0);
        w->n++;
    }
}

/* rancf.h's commit, recording the new weights (els is m->els) */
static inline void ex_slide_commit(void *els, int ne, int e, int op, const vlbe_real *aux)
{
    ex_slide *m = (ex_slide *)(void *)((char *)els - offsetof(ex_slide, els));
    ex_slide_wadd(&m->wall, aux);
    if (op > 0) {
        ex_slide_wadd(&m->wall, aux + 4);
    } else {
        ex_slide_wadd(&m->wmerge, aux);
        if (aux[4] != VLBE_R(0.0)) m->merge_fallbacks++;
    }
    vlbe_rancf_etype()->commit(els, ne, e, op, aux);
}

/* A scene on the paper's beam (ale-rancf 6.1 and 6.2: L = 1 m, r = 0.01 m,
   rho = 7200, E = 20 MPa, gravity 9.81), HHT-alpha -0.05 at h = 1e-3 with 8
   halvings, the paper's element (flags 0), t_end = 1 s; the probe at the
   free end (clamped-free) or at midspan (pinned-pinned). */
static inline void ex_slide_cfg_paper(ex_slide_cfg *c, int N, int support, double mass, double p0,
                                      double v0)
{
    memset(c, 0, sizeof *c);
    c->N = N;
    c->support = support;
    c->L = 1.0;
    c->r = 0.01;
    c->rho = 7200.0;
    c->E = 20e6;
    c->g = 9.81;
    c->mass = mass;
    c->p0 = p0;
    c->v0 = v0;
    c->h = 1e-3;
    c->alpha = -0.05;
    c->t_end = 1.0;
    c->halvings = 8;
    c->probe_p = support == EX_SLIDE_CLAMP_FREE ? c->L : 0.5 * c->L;
    c->stop = 0.1;
}

/* Node coordinates [r, r'] of the start shape, material coordinates p[],
   and (rational) the elements' weights; returns the number of nodes and
   the sliding node (*ks), -1 on bad input.  scratch: an element object the
   rational segmentation may overwrite. */
static inline int ex_slide_shape(const ex_slide_cfg *c, const vlbe_ale_mat *mat,
                                 vlbe_rancf_elem *scratch, double Lstd, vlbe_real (*x)[4],
                                 vlbe_real *p, vlbe_real (*w)[4], int *ks)
{
    const double PI = 3.14159265358979323846;
    int i, k, nn = c->N + 1, e0;
    for (i = 0; i <= c->N; ++i) {
        p[i] = (vlbe_real)(i * Lstd);
        for (k = 0; k < 4; ++k) w[i][k] = VLBE_R(1.0);
    }
    if (c->R <= 0.0) { /* straight: the node nearest to p0 moves there */
        *ks = (int)floor(c->p0 / Lstd + 0.5);
        if (*ks < 1) *ks = 1;
        if (*ks > c->N - 1) *ks = c->N - 1;
        p[*ks] = (vlbe_real)c->p0;
        for (i = 0; i < nn; ++i) {
            x[i][0] = p[i];
            x[i][1] = x[i][3] = VLBE_R(0.0);
            x[i][2] = VLBE_R(1.0);
        }
        return nn;
    }
    { /* semicircle from polar angle pi, counterclockwise (below the x axis) */
        const vlbe_real cen[2] = {(vlbe_real)c->R, VLBE_R(0.0)};
        const double th = PI / c->N;
        vlbe_real xe[8], wa[4];
        for (i = 0; i < c->N; ++i) {
            if (vlbe_rancf_arc(cen, (vlbe_real)c->R, (vlbe_real)(PI + i * th), (vlbe_real)th, wa,
                               xe))
                return -1;
            for (k = 0; k < 4; ++k) {
                x[i][k] = xe[k];
                x[i + 1][k] = xe[4 + k];
                if (c->rational) w[i][k] = wa[k];
            }
            if (!c->rational) /* ALE-ANCF: unit tangents (arc-length slopes) */
                for (k = 0; k < 2; ++k) {
                    const double n0 = hypot((double)xe[2], (double)xe[3]);
                    const double n1 = hypot((double)xe[6], (double)xe[7]);
                    x[i][2 + k] = (vlbe_real)((double)xe[2 + k] / n0);
                    x[i + 1][2 + k] = (vlbe_real)((double)xe[6 + k] / n1);
                }
        }
    }
    e0 = (int)floor(c->p0 / Lstd);
    if (e0 < 0 || e0 >= c->N) return -1;
    if (fabs(c->p0 - e0 * Lstd) < 1e-12 * Lstd || fabs(c->p0 - (e0 + 1) * Lstd) < 1e-12 * Lstd) {
        *ks = fabs(c->p0 - e0 * Lstd) < 1e-12 * Lstd ? e0 : e0 + 1; /* p0 is a node */
        return *ks > 0 && *ks < c->N ? nn : -1;
    }
    { /* exact segmentation of element e0 at p0: a new node there */
        vlbe_real qe[10], qh[5], wl[4], wr[4];
        for (k = 0; k < 4; ++k) {
            qe[k] = x[e0][k];
            qe[5 + k] = x[e0 + 1][k];
        }
        qe[4] = p[e0];
        qe[9] = p[e0 + 1];
        if (c->rational) {
            if (vlbe_rancf_elem_init(scratch, mat, w[e0], 0, 0, 0, 0) ||
                vlbe_rancf_split(scratch, qe, NULL, (vlbe_real)c->p0, qh, NULL, wl, wr))
                return -1;
        } else {
            for (k = 0; k < 4; ++k) wl[k] = wr[k] = VLBE_R(1.0);
            if (vlbe_ale_split(qe, NULL, (vlbe_real)c->p0, qh, NULL)) return -1;
        }
        for (i = nn; i > e0 + 1; --i) { /* nodes e0+1.. and elements e0+1.. move up */
            p[i] = p[i - 1];
            for (k = 0; k < 4; ++k) {
                x[i][k] = x[i - 1][k];
                w[i][k] = w[i - 1][k];
            }
        }
        p[e0 + 1] = (vlbe_real)c->p0;
        for (k = 0; k < 4; ++k) {
            x[e0 + 1][k] = qh[k];
            w[e0][k] = wl[k];
            w[e0 + 1][k] = wr[k];
        }
        *ks = e0 + 1;
        return nn + 1;
    }
}

static inline int ex_slide_build(ex_slide *m, const ex_slide_cfg *c, vlbe_real *q0, vlbe_real *v0)
{
    const double PI = 3.14159265358979323846, A = PI * c->r * c->r;
    const double L = c->R > 0.0 ? PI * c->R : c->L;
    vlbe_real x[EX_SLIDE_NMAX + 2][4], p[EX_SLIDE_NMAX + 2], w[EX_SLIDE_NMAX + 2][4], sn;
    vlbe_ale_con k;
    int i, j, ks, nn, st;
    if (c->N < 2 || c->N > EX_SLIDE_NMAX || (c->R > 0.0 && c->support != EX_SLIDE_PIN_PIN))
        return -1;
    memset(m, 0, sizeof *m);
    m->mat.rhoA = (vlbe_real)(c->rho * A);
    m->mat.EA = (vlbe_real)(c->E * A);
    m->mat.EI = (vlbe_real)(c->E * PI * c->r * c->r * c->r * c->r / 4.0);
    m->mat.f[1] = (vlbe_real)(-c->g * c->rho * A);
    if (vlbe_ale_elem_init(&m->el, &m->mat, VLBE_ALE_NO_DAMP | c->flags, 0, 0, 0)) return -1;
    m->Lstd = L / c->N;
    /* m->els[0] is scratch here, initialized for the chain below */
    if ((nn = ex_slide_shape(c, &m->mat, &m->els[0], m->Lstd, x, p, w, &ks)) < 0) return -1;
    for (i = 0; i < nn; ++i) {
        m->node[i].pmode = i == ks ? VLBE_ALE_PFREE : VLBE_ALE_PFIXED;
        m->node[i].p = p[i];
    }
    m->node[ks].mass = (vlbe_real)c->mass;
    m->slider = ks;
    if (c->rational) {
        for (i = 0; i + 1 < nn; ++i)
            if (vlbe_rancf_elem_init(&m->els[i], &m->mat, w[i], VLBE_ALE_NO_DAMP | c->flags, 0, 0,
                                     0))
                return -1;
        m->et = *vlbe_rancf_etype();
        m->et.commit = ex_slide_commit;
        st = vlbe_rancf_chain_init(&m->ch, m->els, m->node, nn, EX_SLIDE_NMAX + 2, m->con, 4) ||
             vlbe_ale_chain_types(&m->ch, &m->et, m->els);
    } else {
        st = vlbe_ale_chain_init(&m->ch, &m->el, m->node, nn, EX_SLIDE_NMAX + 2, m->con, 4);
    }
    if (st) return -1;
    m->ch.g[1] = (vlbe_real)-c->g;
    memset(&k, 0, sizeof k);
    k.type = VLBE_ALE_CON_POS; /* left end at the origin */
    if (vlbe_ale_chain_add(&m->ch, &k)) return -1;
    if (c->support == EX_SLIDE_CLAMP_FREE) {
        k.type = VLBE_ALE_CON_SLOPE_DIR; /* clamp: slope direction (1, 0) */
        k.d[0] = 1;
    } else {
        k.node = nn - 1; /* pin at the right end of the start shape: (L, 0), (2R, 0) */
        k.r[0] = c->R > 0.0 ? x[nn - 1][0] : (vlbe_real)c->L;
        k.r[1] = c->R > 0.0 ? x[nn - 1][1] : VLBE_R(0.0);
    }
    if (vlbe_ale_chain_add(&m->ch, &k) || vlbe_ale_chain_layout(&m->ch)) return -1;
    if (c->band && ex_ale_band(&m->ch, m->order, (int)(sizeof m->order / sizeof m->order[0])))
        return -1;
    if (vlbe_ale_chain_dae(&m->ch, &m->sys)) return -1;
    for (i = 0; i < m->ch.n; ++i) v0[i] = 0;
    for (i = 0; i < nn; ++i) {
        const int o = m->node[i].ofs;
        for (j = 0; j < 4; ++j) q0[o + j] = x[i][j];
        if (i == ks) q0[o + 4] = p[i];
    }
    /* the mass slides at v0 over the resting beam: p' = v0 / |r'|, the
       node's velocity p' r'(p) */
    sn = vlbe_sqrt(x[ks][2] * x[ks][2] + x[ks][3] * x[ks][3]);
    v0[m->node[ks].ofs + 4] = (vlbe_real)c->v0 / sn;
    for (j = 0; j < 2; ++j) v0[m->node[ks].ofs + j] = (vlbe_real)c->v0 * x[ks][2 + j] / sn;
    return 0;
}

/* total energy; *T: the kinetic part (may be NULL) */
static inline double ex_slide_energy(vlbe_ale_chain *ch, vlbe_real t, const vlbe_real *q,
                                     const vlbe_real *v, double *T)
{
    vlbe_real E[3];
    if (vlbe_ale_chain_energy(ch, t, q, v, E) != VLBE_OK) return (double)NAN;
    if (T) *T = (double)E[0];
    return (double)(E[0] + E[1] + E[2]);
}

static inline double ex_slide_len(const vlbe_ale_chain *ch, vlbe_real t, const vlbe_real *q,
                                  const vlbe_real *v, double *rate)
{
    vlbe_real len, ld = VLBE_R(0.0);
    if (vlbe_ale_chain_length(ch, t, q, v, &len, &ld) != VLBE_OK) return (double)NAN;
    if (rate) *rate = (double)ld;
    return (double)len;
}

static inline int ex_slide_hist_alloc(ex_slide_hist *hi, int cap)
{
    int k;
    double **col[8];
    memset(hi, 0, sizeof *hi);
    hi->t = (double *)malloc((size_t)(8 * cap) * sizeof *hi->t);
    if (!hi->t) return -1;
    hi->cap = cap;
    col[0] = &hi->t;
    col[1] = &hi->probe_y;
    col[2] = &hi->mass_x;
    col[3] = &hi->mass_y;
    col[4] = &hi->mass_p;
    col[5] = &hi->energy;
    col[6] = &hi->length;
    col[7] = &hi->rate;
    for (k = 1; k < 8; ++k) *col[k] = hi->t + (size_t)k * (size_t)cap;
    return 0;
}

/* Asks for the shapes of the first K (<= EX_SLIDE_MAXSHAPE) length-control
   events at pts points each (after ex_slide_hist_alloc); 0 on success. */
static inline int ex_slide_hist_shapes(ex_slide_hist *hi, int K, int pts)
{
    if (K < 1 || K > EX_SLIDE_MAXSHAPE || pts < 2) return -1;
    hi->shape = (double *)malloc((size_t)(4 * K * pts) * sizeof *hi->shape);
    if (!hi->shape) return -1;
    hi->shape_events = K;
    hi->shape_pts = pts;
    hi->shape_done = 0;
    return 0;
}

/* the beam at hi->shape_pts material points into x[], y[] (NaN where the
   chain cannot be evaluated) */
static inline void ex_slide_sample(const ex_slide *m, const ex_slide_cfg *c, double t,
                                   const vlbe_real *q, const ex_slide_hist *hi, double *x,
                                   double *y)
{
    const double L = m->Lstd * c->N;
    int j;
    for (j = 0; j < hi->shape_pts; ++j) {
        vlbe_real r[2];
        const double p = L * j / (hi->shape_pts - 1);
        if (vlbe_ale_chain_point(&m->ch, (vlbe_real)t, q, (vlbe_real)p, r, NULL) == VLBE_OK) {
            x[j] = (double)r[0];
            y[j] = (double)r[1];
        } else {
            x[j] = y[j] = (double)NAN;
        }
    }
}

static inline void ex_slide_hist_free(ex_slide_hist *hi)
{
    free(hi->shape);
    free(hi->t);
    memset(hi, 0, sizeof *hi);
}

/* Writes the histories as CSV; 0 on success. */
static inline int ex_slide_hist_csv(const ex_slide_hist *hi, const char *path)
{
    FILE *f = fopen(path, "w");
    int k;
    if (!f) return -1;
    fprintf(f, "t_s,probe_y_m,mass_x_m,mass_y_m,mass_p_m,energy_J,length_m,length_rate_m_s\n");
    for (k = 0; k < hi->n; ++k)
        fprintf(f, "%.6f,%.9g,%.9g,%.9g,%.9g,%.9g,%.10g,%.6g\n", hi->t[k], hi->probe_y[k],
                hi->mass_x[k], hi->mass_y[k], hi->mass_p[k], hi->energy[k], hi->length[k],
                hi->rate[k]);
    return fclose(f) ? -1 : 0;
}

static inline void ex_slide_record(ex_slide *m, const ex_slide_cfg *c, double t, const vlbe_real *q,
                                   const vlbe_real *v, double E, ex_slide_hist *hi)
{
    vlbe_real r[2];
    const int k = hi->n++, o = m->node[m->slider].ofs;
    hi->t[k] = t;
    hi->probe_y[k] = vlbe_ale_chain_point(&m->ch, (vlbe_real)t, q, (vlbe_real)c->probe_p, r, NULL)
                         ? (double)NAN
                         : (double)r[1];
    hi->mass_x[k] = (double)q[o];
    hi->mass_y[k] = (double)q[o + 1];
    hi->mass_p[k] = (double)q[o + 4];
    hi->energy[k] = E;
    hi->length[k] = ex_slide_len(&m->ch, (vlbe_real)t, q, v, &hi->rate[k]);
}

/* A system as large as the largest chain of the run (nmax coordinates),
   for the workspace queries: every layout the length control makes fits.
   Banded: at most EX_SLIDE_MROWS rows, nodes of at most 5 coordinates
   (the slider's p), the half-bandwidth bound of ex_ale_kl_bound. */
static inline vlbe_dae ex_slide_big(const ex_slide_cfg *c, int nmax)
{
    vlbe_dae big;
    memset(&big, 0, sizeof big);
    big.n = nmax;
    big.m = 2;
    if (c->band) {
        big.m = EX_SLIDE_MROWS;
        big.storage = VLBE_DAE_BANDED;
        big.kl = big.ku = ex_ale_kl_bound(5, EX_SLIDE_MROWS);
    }
    return big;
}

/* The run of the header comment; hist may be NULL. */
static inline ex_slide_out ex_slide_run(const ex_slide_cfg *c, ex_slide_hist *hist)
{
    ex_slide_out res;
    ex_slide *m = (ex_slide *)malloc(sizeof *m);
    const int nmax = 5 * (EX_SLIDE_NMAX + 2);
    vlbe_real *q = (vlbe_real *)malloc((size_t)(4 * nmax) * sizeof *q);
    vlbe_real *v = q ? q + nmax : NULL, *qn = q ? q + 2 * nmax : NULL, *vn = q ? q + 3 * nmax : NULL;
    vlbe_hht_params par;
    vlbe_hht st;
    const vlbe_dae big = ex_slide_big(c, nmax);
    size_t lw = vlbe_hht_work_len_sys(&big), liw = vlbe_hht_iwork_len_sys(&big);
    vlbe_real *w = (vlbe_real *)malloc(lw * sizeof *w);
    int *iw = (int *)malloc(liw * sizeof *iw);
    /* every step advances t by h (the halvings stay inside it), so
       round(t_end / h) steps reach t_end: more than ceil(t_end / h) + 2
       mean that time has stopped advancing as it should */
    const double max_steps = ceil(c->t_end / c->h) + 2.0;
    double t = 0.0, Eref;
    clock_t c0 = clock();
    memset(&res, 0, sizeof res);
    res.t_leave = -1.0;
    res.status = VLBE_EWORK;
    if (!m || !q || !w || !iw || ex_slide_build(m, c, q, v)) goto done;
    Eref = res.E0 = ex_slide_energy(&m->ch, 0, q, v, &res.T_max);
    if (hist && hist->n < hist->cap) ex_slide_record(m, c, 0.0, q, v, res.E0, hist);
    vlbe_hht_params_alpha(&par, (vlbe_real)c->alpha);
    par.max_halvings = c->halvings;
    res.status = vlbe_hht_init(&st, &m->sys, &par, 0, q, v, w, lw, iw, liw);
    while (res.status == VLBE_OK && t < c->t_end - 0.5 * c->h) {
        const int ps = m->node[m->slider].ofs + 4;
        double ps_now, E, T = 0.0;
        int changed = 0;
        if ((double)res.steps >= max_steps) {
            fprintf(stderr, "ex_slide_run: %ld steps of h = %g s reached only t = %g s of %g s; "
                    "stopped\n", res.steps, c->h, t, c->t_end);
            res.status = VLBE_ESTEP;
            break;
        }
        if ((res.status = vlbe_hht_step(&st, (vlbe_real)c->h)) != VLBE_OK) break;
        t = (double)st.t;
        res.steps++;
        ps_now = (double)st.q[ps];
        E = ex_slide_energy(&m->ch, st.t, st.q, st.v, &T);
        if (T > res.T_max) res.T_max = T;
        if (E - Eref > res.dE_gain) res.dE_gain = E - Eref;
        if (E - Eref < res.dE_loss) res.dE_loss = E - Eref;
        if (hist && hist->n < hist->cap) ex_slide_record(m, c, t, st.q, st.v, E, hist);
        if (c->support == EX_SLIDE_CLAMP_FREE && m->slider + 1 == m->ch.nn - 1 &&
            (double)m->node[m->slider + 1].p - ps_now < c->stop * m->Lstd) {
            /* p(t) extrapolated to the end of the beam with p', p'' */
            const double pd = (double)st.v[ps], pdd = (double)st.qdd[ps], d = c->L - ps_now;
            const double disc = pd * pd + 2.0 * pdd * d;
            res.t_leave = t + (disc >= 0.0 && pd > 0.0 ? 2.0 * d / (pd + sqrt(disc)) : 0.0);
            break;
        }
        {
            /* cpu_lc times the length control and the restart after a
               change only; the diagnostics (arc length and energy before
               and after, the shapes) are not counted in it */
            const double len0 = ex_slide_len(&m->ch, st.t, st.q, NULL, NULL);
            double *shp = hist && hist->shape && hist->shape_done < hist->shape_events
                              ? hist->shape + (size_t)(4 * hist->shape_done * hist->shape_pts)
                              : NULL;
            clock_t c1;
            if (shp) /* before: overwritten every step until an event happens */
                ex_slide_sample(m, c, t, st.q, hist, shp, shp + hist->shape_pts);
            c1 = clock();
            vlbe_vec_copy(m->ch.n, st.q, q);
            vlbe_vec_copy(m->ch.n, st.v, v);
            res.status = vlbe_ale_chain_length_control(&m->ch, (vlbe_real)m->Lstd, st.t, q, v,
                                                       &m->slider, qn, vn, &changed);
            res.cpu_lc += (double)(clock() - c1) / CLOCKS_PER_SEC;
            if (res.status == VLBE_OK && changed) {
                const double jump = ex_slide_energy(&m->ch, st.t, qn, vn, NULL) - E;
                Eref += jump; /* the drift of the steps is measured without it */
                if (fabs(jump) > res.dE_lc) res.dE_lc = fabs(jump);
                if (res.nev < EX_SLIDE_MAXEV) {
                    ex_slide_event *ev = &res.ev[res.nev++];
                    ev->t = t;
                    ev->dE = jump;
                    ev->dlen = ex_slide_len(&m->ch, st.t, qn, NULL, NULL) - len0;
                    ev->changed = changed;
                }
                if (shp) {
                    ex_slide_sample(m, c, t, qn, hist, shp + 2 * hist->shape_pts,
                                    shp + 3 * hist->shape_pts);
                    hist->shape_t[hist->shape_done++] = t;
                }
                c1 = clock();
                /* the counters of st restart with it: bank them first */
                res.newton += st.stats.newton_iters;
                res.lu += st.stats.lu_factors;
                res.rejected += st.stats.rejected;
                (void)vlbe_ale_chain_dae(&m->ch, &m->sys); /* laid out: VLBE_OK */
                res.lc_events++;
                res.status = vlbe_hht_init(&st, &m->sys, &par, (vlbe_real)t, qn, vn, w, lw, iw, liw);
                res.cpu_lc += (double)(clock() - c1) / CLOCKS_PER_SEC;
            }
        }
    }
    if (res.steps > 0 || res.status == VLBE_OK) {
        res.newton += st.stats.newton_iters;
        res.lu += st.stats.lu_factors;
        res.rejected += st.stats.rejected;
        res.t_stop = (double)st.t;
        res.p_stop = (double)st.q[m->node[m->slider].ofs + 4];
    }
    res.wall = m->wall;
    res.wmerge = m->wmerge;
    res.merge_fallbacks = m->merge_fallbacks;
done:
    res.cpu = (double)(clock() - c0) / CLOCKS_PER_SEC;
    free(m);
    free(q);
    free(w);
    free(iw);
    return res;
}

#endif /* VLBE_EX_SLIDE_H */
