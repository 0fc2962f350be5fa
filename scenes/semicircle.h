/* semicircle.h -- the mass sliding down a semicircular arc (ale-rancf
   section 6.3) on the model and run loop of ex_slide.h: the scene's
   configuration (sc_cfg), the start geometry measured (sc_geometry,
   sc_elem_eval), the mass position between steps (sc_mass_at) and one run
   with its history (sc_run).  Shared by examples/semicircle.c, which
   states the scene, tests/test_scenes_semicircle.c,
   tests/test_scenes_band.c and bench/wp_semicircle.c.
   -- part of vlbe                                  SPDX-License-Identifier: MIT */
#ifndef VLBE_SCENE_SEMICIRCLE_H
#define VLBE_SCENE_SEMICIRCLE_H

#include "ex_slide.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define SC_R 2.0       /* radius of the start [m] */
#define SC_NGEOM 1000  /* material points of the geometry check */

/* the scene with N arc elements, rational (1) or ALE-ANCF (0), step h;
   t_end = 2 s (callers may change it) */
static inline void sc_cfg(ex_slide_cfg *c, int N, int rational, double h)
{
    const double PI = 3.14159265358979323846;
    ex_slide_cfg_paper(c, N, EX_SLIDE_PIN_PIN, 0.8, 0.0, 0.0);
    c->R = SC_R;
    c->L = PI * SC_R;
    c->p0 = c->L / 16.0;
    c->r = 0.02;
    c->rho = 7200.0;
    c->E = 200e6;
    c->g = 9.81;
    c->rational = rational;
    c->h = h;
    c->t_end = 2.0;
    c->probe_p = 0.5 * c->L;
}

/* the start state of a scene, measured */
typedef struct sc_geom {
    double rad_err;  /* max | |r(p) - c| - R | over SC_NGEOM points [m]    */
    double eps_max;  /* max |Green axial strain| at those points           */
    double kap_err;  /* max |curvature - 1/R| there [1/m]                  */
    double slope_jump; /* max |r'(p_i-) - r'(p_i+)| at the interior nodes  */
    double U0, E0;   /* strain energy, total T + U + V at t = 0 [J]        */
    double Usum;     /* the elements' strain energies summed [J]          */
    int ne;          /* elements of the chain (N or N + 1)                */
} sc_geom;

/* r, r', Green strain and curvature at p of element e of m's chain */
static inline int sc_elem_eval(const ex_slide *m, const ex_slide_cfg *c, const vlbe_real *q, int e,
                               double p, vlbe_real *r, vlbe_real *rp, vlbe_real *eps,
                               vlbe_real *kap)
{
    vlbe_real qe[VLBE_ALE3_NQ];
    int idx[VLBE_ALE3_NQ];
    unsigned md;
    if (vlbe_ale_chain_gather(&m->ch, e, VLBE_R(0.0), q, NULL, qe, NULL, idx, &md)) return -1;
    if (c->rational)
        return vlbe_rancf_point(&m->els[e], qe, (vlbe_real)p, r, rp) ||
               vlbe_rancf_strain(&m->els[e], qe, (vlbe_real)p, eps, kap);
    return vlbe_ale_point(qe, (vlbe_real)p, r, rp) || vlbe_ale_strain(qe, (vlbe_real)p, eps, kap);
}

/* builds the scene's start and measures it; 0 on success */
static inline int sc_geometry(const ex_slide_cfg *c, sc_geom *g)
{
    ex_slide *m = (ex_slide *)malloc(sizeof *m);
    vlbe_real q[5 * (EX_SLIDE_NMAX + 2)], v[5 * (EX_SLIDE_NMAX + 2)], E[3];
    const double L = c->L;
    int i, e, rc = -1;
    memset(g, 0, sizeof *g);
    if (!m || ex_slide_build(m, c, q, v)) goto done;
    g->ne = m->ch.nn - 1;
    for (i = 0; i < SC_NGEOM; ++i) {
        const double p = L * i / (SC_NGEOM - 1);
        vlbe_real r[2], rp[2], eps, kap;
        if (vlbe_ale_chain_locate(&m->ch, VLBE_R(0.0), q, (vlbe_real)p, &e) ||
            sc_elem_eval(m, c, q, e, p, r, rp, &eps, &kap))
            goto done;
        g->rad_err = fmax(g->rad_err, fabs(hypot((double)r[0] - c->R, (double)r[1]) - c->R));
        g->eps_max = fmax(g->eps_max, fabs((double)eps));
        g->kap_err = fmax(g->kap_err, fabs(fabs((double)kap) - 1.0 / c->R));
    }
    for (i = 1; i + 1 < m->ch.nn; ++i) { /* r' from both sides of node i */
        vlbe_real r[2], a[2], b[2], eps, kap;
        const double p = (double)m->node[i].p;
        if (sc_elem_eval(m, c, q, i - 1, p, r, a, &eps, &kap) ||
            sc_elem_eval(m, c, q, i, p, r, b, &eps, &kap))
            goto done;
        g->slope_jump = fmax(g->slope_jump, hypot((double)(a[0] - b[0]), (double)(a[1] - b[1])));
    }
    if (vlbe_ale_chain_energy(&m->ch, VLBE_R(0.0), q, v, E)) goto done;
    g->U0 = (double)E[1];
    g->E0 = (double)(E[0] + E[1] + E[2]);
    for (e = 0; e + 1 < m->ch.nn; ++e) {
        vlbe_real qe[VLBE_ALE3_NQ], ve[VLBE_ALE3_NQ], Ee[3];
        int idx[VLBE_ALE3_NQ];
        unsigned md;
        if (vlbe_ale_chain_gather(&m->ch, e, VLBE_R(0.0), q, v, qe, ve, idx, &md)) goto done;
        if (c->rational ? vlbe_rancf_energy(&m->els[e], md, qe, ve, Ee)
                        : vlbe_ale_energy(&m->el, md, qe, ve, Ee))
            goto done;
        g->Usum += (double)Ee[1];
    }
    rc = 0;
done:
    free(m);
    return rc;
}

/* the mass position at time t, linear between the recorded steps */
static inline int sc_mass_at(const ex_slide_hist *hi, double t, double *x, double *y)
{
    int k;
    for (k = 1; k < hi->n; ++k)
        if (hi->t[k] >= t - 1e-12) {
            const double s = (t - hi->t[k - 1]) / (hi->t[k] - hi->t[k - 1]);
            *x = hi->mass_x[k - 1] + s * (hi->mass_x[k] - hi->mass_x[k - 1]);
            *y = hi->mass_y[k - 1] + s * (hi->mass_y[k] - hi->mass_y[k - 1]);
            return 0;
        }
    *x = *y = (double)NAN;
    return -1;
}

/* one run with its history (allocated here: free with ex_slide_hist_free) */
static inline ex_slide_out sc_run(const ex_slide_cfg *c, ex_slide_hist *hi)
{
    ex_slide_out r;
    memset(&r, 0, sizeof r);
    r.status = VLBE_EWORK;
    if (ex_slide_hist_alloc(hi, (int)(c->t_end / c->h) + 16)) return r;
    return ex_slide_run(c, hi);
}

#endif /* VLBE_SCENE_SEMICIRCLE_H */
