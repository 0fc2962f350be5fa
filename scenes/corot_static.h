/* corot_static.h -- the static checks of the planar co-rotational
   cantilever (corot2d.h): the model (cs_build, cs_band), (a) the roll-up by
   an end moment in load steps against the exact arc (cs_rollup,
   cs_arc_exact, cs_arc_errors), (b) the natural frequencies of the
   linearised system at rest (cs_freqs), (c) the forces under rigid
   rotation (cs_rigid); with cs_tip_force, the elastica under a tip force.
   Shared by examples/corot_static.c, which states the scene and its closed
   forms, tests/test_scenes_cr2d.c, tests/test_scenes_band.c,
   tests/test_static_cr2d.c and bench/bench_static.c.
   -- part of vlbe                                  SPDX-License-Identifier: MIT */
#ifndef VLBE_SCENE_COROT_STATIC_H
#define VLBE_SCENE_COROT_STATIC_H

#include "../corot2d.h"
#include "../integrators.h"
#include "ex_cant.h"
#include "ex_cr2d.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define CS_L 1.0
#define CS_A 4.3434e-5
#define CS_I 1.059e-11
#define CS_E 68.96e9
#define CS_RHO 3144.3858
#define CS_NE_MAX 128
#define CS_PI 3.14159265358979323846

typedef struct cs_model {
    vlbe_cr2d_mat mat;
    vlbe_cr2d_elem el[CS_NE_MAX];
    vlbe_cr2d_fix fix[3];
    vlbe_cr2d_beam beam;
    vlbe_real P[3 * (CS_NE_MAX + 1)];
    vlbe_dae sys;
    int ne, n;
    int order[3 * (CS_NE_MAX + 1) + 3]; /* cs_band: the augmented order */
} cs_model;

static inline double cs_EI(void) { return CS_E * CS_I; }
static inline double cs_EA(void) { return CS_E * CS_A; }
static inline double cs_rhoA(void) { return CS_RHO * CS_A; }

/* The cantilever of ne elements along x with the section (EA, EI, rhoA),
   clamped at node 0, tip moment 2 pi EI / L per unit load factor
   (beam.load = 0: unloaded); flags: the elements' mode (0 or
   VLBE_CR2D_LINEAR).  Build it in place: the beam points into the model.
   0 ok, -1 bad ne or element. */
static inline int cs_build_sec(cs_model *m, int ne, unsigned flags, double EA, double EI,
                               double rhoA)
{
    int i;
    if (ne < 1 || ne > CS_NE_MAX) return -1;
    memset(m, 0, sizeof *m);
    m->ne = ne;
    m->n = 3 * (ne + 1);
    m->mat.EA = (vlbe_real)EA;
    m->mat.EI = (vlbe_real)EI;
    m->mat.rhoA = (vlbe_real)rhoA;
    m->mat.rhoI = VLBE_R(0.0);
    for (i = 0; i < ne; ++i) {
        vlbe_real X1[2], X2[2];
        X1[0] = (vlbe_real)(CS_L * i / ne);
        X2[0] = (vlbe_real)(CS_L * (i + 1) / ne);
        X1[1] = X2[1] = VLBE_R(0.0);
        if (vlbe_cr2d_elem_init(&m->el[i], &m->mat, X1, X2, flags | VLBE_CR2D_NO_DAMP))
            return -1;
    }
    for (i = 0; i < 3; ++i) m->fix[i].dof = i; /* g = 0, fun = NULL (memset) */
    if (vlbe_cr2d_beam_init(&m->beam, m->el, ne, m->fix, 3)) return -1;
    m->P[3 * ne + 2] = (vlbe_real)(2.0 * CS_PI * EI / CS_L);
    m->beam.P = m->P;
    m->beam.load = VLBE_R(0.0);
    return vlbe_cr2d_beam_dae(&m->beam, &m->sys) ? -1 : 0;
}

/* The scene's cantilever: the paper's section. */
static inline int cs_build(cs_model *m, int ne, unsigned flags)
{
    return cs_build_sec(m, ne, flags, cs_EA(), cs_EI(), cs_rhoA());
}

/* The elastica load instead of the end moment: a transverse tip force
   -EI / L^2 along y per unit load factor (beam.load = k: the load
   parameter k = P L^2 / EI of the elastica tables). */
static inline void cs_tip_force(cs_model *m)
{
    m->P[3 * m->ne + 2] = VLBE_R(0.0);
    m->P[3 * m->ne + 1] = (vlbe_real)(-cs_EI() / (CS_L * CS_L));
}

/* Banded matrices (vlbe_cr2d_beam_band) and the integrators' banded path
   for a model cs_build made; 0 on success. */
static inline int cs_band(cs_model *m)
{
    if (vlbe_cr2d_beam_band(&m->beam, m->order, (int)(sizeof m->order / sizeof m->order[0])))
        return -1;
    ex_cr2d_storage(&m->sys, &m->beam);
    return 0;
}

/* ===== (a) roll-up ======================================================= */

/* Load steps k = 1..nstep (lambda = k / nstep), each from the previous
   solution.  qh: (nstep + 1) * n, the solutions (row 0: unloaded).  par:
   the solver's parameters, NULL for the defaults (see below).  st (may be NULL) accumulates the solver's
   counters.  VLBE_OK or the first failing status (qh then holds the
   solutions up to the failing step). */
static inline vlbe_status cs_rollup(cs_model *m, int nstep, const vlbe_static_params *ppar,
                                    vlbe_real *qh, vlbe_dae_stats *st)
{
    const int n = m->n;
    vlbe_static_params par;
    size_t lw = vlbe_static_work_len_sys(&m->sys), liw = vlbe_static_iwork_len_sys(&m->sys);
    vlbe_real *w = (vlbe_real *)malloc(lw * sizeof *w), lam[3] = {0, 0, 0};
    int *iw = (int *)malloc(liw * sizeof *iw);
    vlbe_status rc = VLBE_OK;
    int k, i;
    /* the defaults: their watchdog phase takes the full Newton steps,
       which converge from every load step, the same iterates as plain
       Newton (max_halvings = 0).  Backtracking from the first iteration
       (watchdog = 0) rejects them: the first step of a load step rotates
       the elements and the linearised kinematics stretch them, an axial
       residual EA a^2 / 2 (EA / EI = 4e6 m^-2) that dwarfs the moment
       residual; it takes 2 to 4 times the iterations, and fails with
       VLBE_ENOCONV at 4 elements */
    vlbe_static_params_default(&par);
    if (ppar) par = *ppar;
    if (!w || !iw) rc = VLBE_EWORK;
    for (i = 0; i < n; ++i) qh[i] = VLBE_R(0.0);
    for (k = 1; k <= nstep && rc == VLBE_OK; ++k) {
        vlbe_real *q = qh + (size_t)k * (size_t)n;
        for (i = 0; i < n; ++i) q[i] = q[i - n];
        m->beam.load = (vlbe_real)((double)k / nstep);
        rc = vlbe_dae_static(&m->sys, &par, VLBE_R(0.0), q, lam, st, w, lw, iw, liw);
    }
    free(w);
    free(iw);
    return rc;
}

/* Errors of a solution q at load factor lambda against the exact arc (and
   the closed-form discrete solution, see the top of
   examples/corot_static.c). */
typedef struct cs_arc_err {
    double tip;       /* |r_tip - r(L)| / L                                   */
    double node;      /* max over the nodes |r_i - r(s_i)| / L                */
    double rot;       /* |phi_tip - 2 pi lambda|                              */
    double tip_pred;  /* the discrete closed form's tip error (R - R_d) 2 sin(kL/2) / L */
    double disc;      /* max over the nodes |r_i - discrete closed form| / L  */
    double xtip, ytip, phitip;
} cs_arc_err;

static inline void cs_arc_exact(double k, double s, double *x, double *y)
{
    if (k == 0.0) {
        *x = s;
        *y = 0.0;
    } else {
        *x = sin(k * s) / k;
        *y = (1.0 - cos(k * s)) / k;
    }
}

static inline cs_arc_err cs_arc_errors(const cs_model *m, const vlbe_real *q, double lambda)
{
    const int ne = m->ne;
    const double Le = CS_L / ne, k = 2.0 * CS_PI * lambda / CS_L, a = k * Le;
    /* R_d and R - R_d; the difference in a form without cancellation:
       R - R_d = (2 sin(a/2) - a (1 - a^2/24)) / (2 k sin(a/2)) */
    const double sh = sin(0.5 * a);
    double Rd = 0.0, dR = 0.0;
    cs_arc_err e;
    int i;
    memset(&e, 0, sizeof e);
    if (k > 0.0) {
        Rd = Le * (1.0 - a * a / 24.0) / (2.0 * sh);
        dR = (2.0 * sh - a * (1.0 - a * a / 24.0)) / (2.0 * k * sh);
        e.tip_pred = fabs(dR) * 2.0 * fabs(sin(0.5 * k * CS_L)) / CS_L;
    }
    for (i = 0; i <= ne; ++i) {
        const double X = CS_L * i / ne;
        const double x = X + (double)q[3 * i], y = (double)q[3 * i + 1];
        double xe, ye, xd, yd, d;
        cs_arc_exact(k, X, &xe, &ye);
        if (k > 0.0) {
            xd = Rd * sin(i * a);
            yd = Rd * (1.0 - cos(i * a));
        } else {
            xd = X;
            yd = 0.0;
        }
        d = hypot(x - xe, y - ye) / CS_L;
        if (d > e.node) e.node = d;
        if (i == ne) e.tip = d;
        d = hypot(x - xd, y - yd) / CS_L;
        if (d > e.disc) e.disc = d;
    }
    e.xtip = CS_L + (double)q[3 * ne];
    e.ytip = (double)q[3 * ne + 1];
    e.phitip = (double)q[3 * ne + 2];
    e.rot = fabs(e.phitip - k * CS_L);
    return e;
}

/* ===== (b) natural frequencies ========================================== */

/* Frequencies [rad/s] of the clamped beam of ne elements: the first nb
   bending modes into wb, the first axial mode into *wa (either may be
   NULL).  recip = 1: shift-invert with sigma = 0 (see the top of
   examples/corot_static.c); 0: with sigma = -max K0_ii / M_ii, far below
   the spectrum.  Returns VLBE_OK, a
   status of the callbacks (as VLBE_ECALLBACK) or of vlbe_eig_gsym. */
static inline vlbe_status cs_freqs(int ne, int recip, int nb, double *wb, double *wa)
{
    cs_model *m = (cs_model *)malloc(sizeof *m);
    const int n = 3 * (ne + 1), r = n - 3;
    vlbe_real *q = NULL, *K = NULL, *M = NULL, *Kr = NULL, *Mr = NULL, *lam = NULL, *X = NULL,
              *w = NULL, sigma = VLBE_R(0.0);
    vlbe_status st = VLBE_EWORK;
    int i, j, kb = 0, ka = 0;
    if (!m || cs_build(m, ne, 0u)) goto done;
    q = (vlbe_real *)calloc((size_t)n, sizeof *q);
    K = (vlbe_real *)malloc((size_t)n * (size_t)n * sizeof *K);
    M = (vlbe_real *)malloc((size_t)n * (size_t)n * sizeof *M);
    Kr = (vlbe_real *)malloc((size_t)r * (size_t)r * sizeof *Kr);
    Mr = (vlbe_real *)malloc((size_t)r * (size_t)r * sizeof *Mr);
    lam = (vlbe_real *)malloc((size_t)r * sizeof *lam);
    X = (vlbe_real *)malloc((size_t)r * (size_t)r * sizeof *X);
    w = (vlbe_real *)malloc(vlbe_eig_work_len(r) * sizeof *w);
    if (!q || !K || !M || !Kr || !Mr || !lam || !X || !w) goto done;
    st = VLBE_ECALLBACK;
    if (vlbe_cr2d_beam_force_jac(&m->beam, VLBE_R(0.0), q, q, K, NULL)) goto done;
    if (vlbe_cr2d_beam_mass(&m->beam, VLBE_R(0.0), q, q, M)) goto done;
    for (i = 0; i < r; ++i) /* drop the clamped coordinates 0, 1, 2 */
        for (j = 0; j < r; ++j) {
            Kr[i * r + j] = -K[(size_t)(i + 3) * (size_t)n + (size_t)(j + 3)];
            Mr[i * r + j] = M[(size_t)(i + 3) * (size_t)n + (size_t)(j + 3)];
        }
    if (!recip)
        for (i = 0; i < r; ++i)
            if (-Kr[i * r + i] / Mr[i * r + i] < sigma) sigma = -Kr[i * r + i] / Mr[i * r + i];
    st = vlbe_eig_gsym(r, Kr, Mr, sigma, lam, X, NULL, w, vlbe_eig_work_len(r));
    if (st != VLBE_OK) goto done;
    /* modes from the lowest frequency up */
    for (j = 0; j < r; ++j) {
        const int c = j;
        const double om = sqrt((double)lam[c]);
        double su = 0.0, sa = 0.0;
        for (i = 0; i < r; ++i) {
            const double x2 = (double)X[i * r + c] * (double)X[i * r + c];
            sa += x2;
            if (i % 3 == 0) su += x2; /* u of node i/3 + 1 */
        }
        if (su > 0.5 * sa) {
            if (ka++ == 0 && wa) *wa = om;
        } else if (kb < nb) {
            if (wb) wb[kb] = om;
            ++kb;
        }
    }
    if (kb < nb) st = VLBE_EARG; /* fewer bending modes than asked for */
done:
    free(q);
    free(K);
    free(M);
    free(Kr);
    free(Mr);
    free(lam);
    free(X);
    free(w);
    free(m);
    return st;
}

/* ===== (c) rigid rotation =============================================== */

/* The beam of ne elements turned rigidly by psi about the point c (and
   moved by nothing else): largest |Q| of a force coordinate / EA and of a
   moment coordinate / (EI / L_e), over psi = psi0 + j dpsi, j < npsi.
   flags: element mode (0, or VLBE_CR2D_LINEAR for the contrast).
   Returns 0, or -1 when an evaluation failed. */
static inline int cs_rigid(int ne, unsigned flags, double psi0, double dpsi, int npsi,
                           const double *c, double *fmax, double *mmax)
{
    cs_model *m = (cs_model *)malloc(sizeof *m);
    vlbe_real q[3 * (CS_NE_MAX + 1)], v[3 * (CS_NE_MAX + 1)], Q[3 * (CS_NE_MAX + 1)];
    const double Le = CS_L / ne;
    int j, i, rc = 0;
    *fmax = *mmax = 0.0;
    if (!m || cs_build(m, ne, flags)) {
        free(m);
        return -1;
    }
    for (i = 0; i < m->n; ++i) v[i] = VLBE_R(0.0);
    for (j = 0; j < npsi && rc == 0; ++j) {
        const double psi = psi0 + j * dpsi, cp = cos(psi), sp = sin(psi);
        for (i = 0; i <= ne; ++i) {
            const double X = CS_L * i / ne, dx = X - c[0], dy = -c[1];
            q[3 * i] = (vlbe_real)(c[0] + cp * dx - sp * dy - X);
            q[3 * i + 1] = (vlbe_real)(c[1] + sp * dx + cp * dy);
            q[3 * i + 2] = (vlbe_real)psi;
        }
        if (vlbe_cr2d_beam_force(&m->beam, VLBE_R(0.0), q, v, Q)) {
            rc = -1;
            break;
        }
        for (i = 0; i < m->n; ++i) {
            const double a = fabs((double)Q[i]);
            if (i % 3 == 2) {
                if (a * Le / cs_EI() > *mmax) *mmax = a * Le / cs_EI();
            } else if (a / cs_EA() > *fmax)
                *fmax = a / cs_EA();
        }
    }
    free(m);
    return rc;
}

#endif /* VLBE_SCENE_COROT_STATIC_H */
