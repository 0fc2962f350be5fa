/* ex_spin.h -- spin-up of a flexible cantilever clamped to a hub turning
   about a fixed axis (Simo & Vu-Quoc style), no gravity: the co-rotational
   beam of corot2d.h (nonlinear) and its LINEAR element in a floating frame
   turned by the hub angle (linear FFRF-equivalent: centrifugal softening,
   no stiffening).  Model, hub angle, the run driver that stops with
   VLBE_EBOUND when the tip leaves a bound, the tip in the hub frame.
   Shared by examples/spin_up.c and tests/test_scenes_spin.c.
   -- part of vlbe                                  SPDX-License-Identifier: MIT

   Beam: L = 10 m, EA = 2.8e7 N, EI = 1.4e4 N m^2, rhoA = 1.2 kg/m, rhoI = 0
   (Euler-Bernoulli, no rotary inertia), ne equal elements along +x from
   the hub axis at the origin.  Node 0 is clamped to the hub: u0 = v0 = 0,
   phi0 = theta(t) (prescribed coordinates, index-3 constraints), with
        theta(t) = (W/Ts) [t^2/2 + (Ts/2pi)^2 (cos(2 pi t/Ts) - 1)],  t <= Ts,
                 = W (t - Ts/2),                                      t > Ts
   (theta' rises smoothly from 0 to W in Ts, theta'' = 0 at both ends).
   LINEAR: beam.frame = the same theta(t): every element measures its
   deformation in the hub frame (corot2d.h, floating frame).
   Tip in the hub frame: r = R^T(theta) (X + u) of the last node; axial
   deflection r_x - L, transverse r_y.
   First cantilever bending frequency at rest: 1.8751^2 sqrt(EI/rhoA)/L^2
   = 3.80 rad/s: the linear model loses its first bending stiffness when
   theta' exceeds it (K - theta'^2 M indefinite) and diverges; the
   nonlinear one stiffens (centrifugal tension) and stays bounded.

   Run: HHT-alpha (default alpha = -0.05) with the fixed step h, step
   halvings on Newton failure; after each step the tip displacement in the
   hub frame |(r_x - L, r_y)| is checked against cfg.bound (> 0): beyond it
   the run stops with VLBE_EBOUND (the divergence is a status, not NaN). */
#ifndef VLBE_EX_SPIN_H
#define VLBE_EX_SPIN_H

#include "../corot2d.h"
#include "../integrators.h"
#include "ex_cr2d.h"
#include "ex_run.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define SP_MAXEL 64
#define SP_PI 3.14159265358979323846

typedef struct sp_cfg {
    double L, EA, EI, rhoA, rhoI;
    double ray_a, ray_b; /* Rayleigh damping (0: none)                     */
    int ne;              /* elements                                       */
    double W, Ts;        /* final hub speed [rad/s], spin-up time [s]       */
    int linear;          /* 1: LINEAR elements in the floating hub frame    */
    double h, t_end;     /* step, end time                                 */
    double alpha;        /* HHT alpha (0: trapezoidal Newmark)             */
    double bound;        /* stop with VLBE_EBOUND when |tip| > bound (0: off) */
    int max_halvings;    /* step halvings on Newton failure (0: 10)        */
} sp_cfg;

/* The scene: L = 10 m, EA = 2.8e7 N, EI = 1.4e4 N m^2, rhoA = 1.2 kg/m,
   rhoI = 0, Ts = 15 s, t_end = 20 s; 8 elements, h = 5 ms, HHT alpha =
   -0.05, bound L/10. */
static inline void sp_cfg_default(sp_cfg *c, double W, int linear)
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
    c->linear = linear;
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
    vlbe_cr2d_elem el[SP_MAXEL];
    vlbe_cr2d_fix fix[3]; /* u0 = 0, v0 = 0, phi0 = theta(t) */
    vlbe_cr2d_beam beam;
    vlbe_dae sys;
} sp_model;

static inline vlbe_status sp_init(sp_model *m, const sp_cfg *c)
{
    vlbe_cr2d_mat mat;
    vlbe_status st;
    int e;
    memset(m, 0, sizeof *m);
    if (c->ne < 1 || c->ne > SP_MAXEL) return VLBE_EARG;
    m->cfg = *c;
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
                                      c->linear ? VLBE_CR2D_LINEAR : 0u)) != VLBE_OK)
            return st;
    }
    m->fix[0].dof = 0;
    m->fix[1].dof = 1;
    m->fix[2].dof = 2;
    m->fix[2].fun = sp_theta_fun;
    m->fix[2].ctx = &m->cfg;
    if ((st = vlbe_cr2d_beam_init(&m->beam, m->el, c->ne, m->fix, 3)) != VLBE_OK) return st;
    if (c->linear) m->beam.frame = &m->fix[2]; /* the hub frame */
    ex_cr2d_dae(&m->sys, &m->beam, m->n, 3);
    if (c->linear) m->sys.flags = VLBE_DAE_MASS_CONST;
    return VLBE_OK;
}

/* tip deflection in the hub frame at t: tip[0] axial, tip[1] transverse */
static inline void sp_tip(const sp_model *m, double t, const vlbe_real *q, double *tip)
{
    const int i = m->cfg.ne;
    const double x = m->cfg.L + (double)q[3 * i], y = (double)q[3 * i + 1];
    double g[3];
    sp_theta(&m->cfg, t, g);
    tip[0] = cos(g[0]) * x + sin(g[0]) * y - m->cfg.L;
    tip[1] = -sin(g[0]) * x + cos(g[0]) * y;
}

/* Called at t = 0 and after every accepted step with the tip in the hub
   frame. */
typedef void (*sp_observer)(void *ctx, const sp_model *m, double t, const double *tip,
                            const vlbe_real *q, const vlbe_real *v);

typedef struct sp_out {
    vlbe_status status;   /* VLBE_EBOUND: the tip left the bound        */
    vlbe_dae_stats stats;
    double cpu;           /* seconds                                    */
    double t_stop;        /* time of the last accepted step             */
    double tip_Ts[2];     /* tip at t = Ts (NAN if not reached)         */
    double tip_end[2];    /* tip at the last accepted step              */
    double tip_max[2];    /* max |axial|, max |transverse|              */
} sp_out;

/* ex_run's observer: the tip in the hub frame, its record in out, the
   caller's observer, and the bound (VLBE_EBOUND ends the run). */
typedef struct sp_watch {
    const sp_model *m;
    sp_out *out;
    long kTs;             /* the step that ends at Ts            */
    sp_observer obs;
    void *ctx;
} sp_watch;

static inline vlbe_status sp_watch_step(void *ctx, double t, const vlbe_real *q,
                                        const vlbe_real *v, const vlbe_real *lambda)
{
    sp_watch *w = (sp_watch *)ctx;
    sp_out *out = w->out;
    const sp_cfg *c = &w->m->cfg;
    double tip[2] = {0.0, 0.0};
    (void)lambda;
    if (t > 0.0) {
        sp_tip(w->m, t, q, tip);
        out->t_stop = t;
        out->tip_end[0] = tip[0];
        out->tip_end[1] = tip[1];
        if ((long)floor(t / c->h + 0.5) == w->kTs) {
            out->tip_Ts[0] = tip[0];
            out->tip_Ts[1] = tip[1];
        }
        out->tip_max[0] = fmax(out->tip_max[0], fabs(tip[0]));
        out->tip_max[1] = fmax(out->tip_max[1], fabs(tip[1]));
    }
    if (w->obs) w->obs(w->ctx, w->m, t, tip, q, v);
    if (c->bound > 0.0 && !(hypot(tip[0], tip[1]) <= c->bound)) return VLBE_EBOUND;
    return VLBE_OK;
}

/* The whole run from rest (q = v = 0 is consistent: theta(0) = theta'(0) =
   0), by ex_run with HHT (cfg.alpha) at the fixed step cfg.h. */
static inline void sp_run(sp_model *m, const sp_cfg *c, sp_observer obs, void *ctx, sp_out *out)
{
    vlbe_hht_params par;
    ex_method meth;
    ex_run_out ro;
    sp_watch w;
    vlbe_real *q0 = NULL;
    memset(out, 0, sizeof *out);
    out->tip_Ts[0] = out->tip_Ts[1] = NAN;
    if ((out->status = sp_init(m, c)) != VLBE_OK) return;
    if ((out->status = ex_hht_pick(&par, c->alpha, 0.0)) != VLBE_OK) return;
    par.max_halvings = c->max_halvings > 0 ? c->max_halvings : 10;
    q0 = (vlbe_real *)calloc((size_t)m->n, sizeof *q0);
    if (!q0) {
        out->status = VLBE_EWORK;
        return;
    }
    memset(&meth, 0, sizeof meth);
    meth.hht = &par;
    meth.h = c->h;
    w.m = m;
    w.out = out;
    w.kTs = (long)floor(c->Ts / c->h + 0.5);
    w.obs = obs;
    w.ctx = ctx;
    out->status = ex_run(&m->sys, &meth, q0, q0, c->t_end, sp_watch_step, &w, NULL, NULL, NULL, &ro);
    out->stats = ro.stats;
    out->cpu = ro.cpu;
    free(q0);
}

#endif /* VLBE_EX_SPIN_H */
