/* ex_cable.h -- the long-cable scenes: a uniform cable hanging under gravity
   (its small lateral oscillations against the Bessel closed form) and the
   wiring of a cable chain into a vlbe_dae, shared by examples/hanging_cable.c,
   examples/winch.c (scenes/ex_winch.h), their test tests/test_scenes_cable.c
   and the benchmarks.                             -- part of vlbe
                                                   SPDX-License-Identifier: MIT

   THE WIRING.  ex_cable_wire(sys, ch, banded) plugs a planar chain into a
   vlbe_dae; every scene here builds its problem through it and sizes its
   integrator workspace through ex_cable_hht_work, so the storage of the
   matrices (dense, or banded: O(N) per step and memory) is one argument,
   cfg.banded, passed down to one place.  A banded chain is switched to
   its band (vlbe_ale_chain_band, an order buffer of n + m ints, + 4 where
   the chain grows by insertion) before its layout.

   THE HANGING CABLE.  Length L, mass per length rhoA, gravity g, pinned at
   the top (its position held, its slope free), free at the bottom.  With z
   the distance from the free end the tension is T = rhoA g z, and the small
   lateral oscillations u(z, t) of an inextensible string obey
        rhoA u_tt = (T u_z)_z = rhoA g (z u_z)_z,
   whose modes bounded at z = 0 and zero at z = L are
        u_k(z) = J0(2 omega_k sqrt(z / g)),   omega_k = (j0_k / 2) sqrt(g / L),
   j0_k the zeros of the Bessel function J0 (D. Bernoulli's hanging chain).
   J0(2 sqrt(x)) = sum_k (-x)^k / (k!)^2 is entire in x = omega^2 z / g, so
   the mode shapes are smooth in z and the series gives them with
   derivatives (ex_cable_psi; x <= (j0_3/2)^2 = 18.7 here: terms up to ~200,
   ~1e-14 of cancellation).

   The model: N Lagrangian ALE-ANCF cable elements (ancf_ale.h, every
   material coordinate fixed, p = 0 at the top, p = L at the free end,
   nodes at p_i = i L / N), gravity as the distributed load rhoA g.  The
   physics the closed form leaves out, each a first-order perturbation of
   omega^2 computed with the analytic mode (ex_cable_corrections):
   - extension: the element's force is EA eps r' with the Green strain
     eps, so the tension is T = EA eps |r'|, still rhoA g z (statics), and
     the lateral equation in the material coordinate s = L - p is
     rhoA u_tt = (T / lam u_s)_s with the stretch lam = |r'| ~ 1 + T / EA:
        d omega / omega = -(rhoA g / (2 EA)) int s^2 u_s^2 ds / int s u_s^2 ds
     (between -eps_top / 2 and 0, eps_top = rhoA g L / EA);
   - bending, pinned top: d omega / omega = EI int u_ss^2 ds /
     (2 omega^2 rhoA int u^2 ds).  The free end's boundary layer (where
     T -> 0) and the pin's (u_ss = 0 there) change it at higher order;
   - a clamped top instead: the continuum cable bends within the boundary
     layer l = sqrt(EI / T_top) under the clamp and behaves as a string
     shortened by l: d omega / omega = l / (2 L) (omega ~ L^-1/2).  A mesh
     does not resolve that layer when l << L / N: the slope held at the top
     node then bends the whole first element, an error of the order of the
     element length that the closed form does not have.  The scenes pin
     the top (the closed form's boundary condition); ex_cable_cfg.clamped
     switches to the clamp so that the difference can be shown.
   Static state: the straight vertical cable with the exact stretch of the
   Green-strain law, EA (lam^2 - 1) lam / 2 = rhoA g (L - p), y(p) = -int_0^p
   lam (ex_cable_hanging), then vlbe_dae_static on the discrete model.

   Measurement of omega_k (ex_cable_freq): start at the static state with
   the lateral velocity V u_k (displacement 0, so no axial strain enters at
   first order; amplitude A = V / omega_k at the free end), integrate with
   HHT-alpha at a fixed step of T_k / steps_per_period, and follow the
   projection a(t) = int rhoA u_k(s) x(p, t) dp, a fixed linear form of the
   coordinates (ex_cable_proj: Gauss-Legendre per element, O(N)): the other
   discrete modes are nearly rhoA-orthogonal to u_k, so a(t) is the k-th
   mode with the others suppressed to second order in the difference
   between the discrete and the analytic mode.  Its zero crossings (both
   directions; inside a step the root of the cubic Hermite interpolant of
   (a, a') at its ends, the basis of vlbe_herm_ale_eval: error O(h^4)) are
   fitted by least squares, t_j = t_0 + j pi / Omega.  HHT-alpha turns a
   linear mode of frequency omega into a discrete one of frequency
        Omega = omega (1 - c (omega h)^2 + O((omega h)^4)),
        c = 1/12 - alpha/4 - 3 alpha^2/8
   (the argument of the principal root of its amplification matrix; 1/12 is
   the trapezoidal rule's, checked on the scalar recurrence at alpha = 0,
   -0.02 .. -1/3 to 6 digits and in tests/test_scenes_cable.c on
   vlbe_hht), so the reported omega = Omega (1 + c (Omega h)^2) carries an
   integrator error O((omega h)^4): 0.0085 (omega h)^4 at alpha = -0.05,
   8e-9 at 200 steps per period.  The cost per step is that of the integrator
   and O(N) for the projection: the measurement scales with the banded
   path.  Independent cross-check at small N (ex_cable_eig): the lateral
   block of the linearisation at the static state (it decouples from the
   axial one on a straight vertical cable), -K x = omega^2 M x by
   vlbe_eig_gsym of vlbe.h, shift-invert with sigma = 0 (the lowest modes
   as the largest eigenvalues of the reduced problem, accurate relative to
   them).

   Choice of EA, of the amplitude and of the step control.  A nearly
   inextensible cable is hard on the arithmetic: its nodes sit at |y| ~ L
   and its Green strain is known to EPS |y| / L_e only.  At rest that leaves
   force residuals of ~EA EPS |y| per coordinate, which the slope
   coordinates' inertia (~rhoA L_e^3) turns into large spurious
   accelerations at the start; near the free end, where the tension
   vanishes, the first Newton iterate of HHT then sees compression and
   diverges laterally.  Measured (200 steps per period, no step halving):
   EA = 1e9 fails from 32 elements, 1e8 from 128, 1e7 from 256 (mode 1,
   the longest step), 1e6 runs at 256.  A halved step (its mass term 4
   times larger) converges: ex_cable_run.halvings (default 8) lets HHT
   halve; a halving changes the phase once and the fitted intercept takes
   it.  EA = 1e7 (top strain 9.8e-6, a steel rope's order) with that runs
   to 256 elements (one LU in five steps there, one in thirty at 128; EA =
   1e8 needs one in three at 128); its extension corrections, -2.8e-6 ..
   -1.7e-6, are stated and taken out of the compared error, their
   remainder is of second order (1e-10 .. 1e-9 in the eigen-analysis at 32
   and 64 elements).  The lateral
   motion strains the cable by x_p^2 / 2 ~ (A omega^2 / g)^2 / 2 at second
   order; the elements' cubic axial field cannot follow that quartic
   (membrane locking), and the spurious axial force, proportional to EA
   A^2, shifts omega_3 by 7e-8 at 16 elements, A = 1e-4 m and EA = 1e7, a
   hundred times less at the default A = 1e-5 m (1e-6 L).

   Examples may allocate: the model's nodes and the runs' buffers are
   malloc'ed here, never in the headers of vlbe. */
#ifndef VLBE_EX_CABLE_H
#define VLBE_EX_CABLE_H

#include "../ancf_ale.h"
#include "../integrators.h"
#include "ex_ale.h"
#include "ex_run.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define EX_CABLE_NMODES 3   /* modes with a tabulated zero of J0            */
#define EX_CABLE_MAXCROSS 64 /* zero crossings kept by a frequency run       */
#define EX_CABLE_NGP 6       /* Gauss points per element of the projections  */

/* -- the wiring --------------------------------------------------------- */

/* sys <- the chain's callbacks in the storage asked for: 0 on success, -1
   when a banded system is asked of a chain not in banded mode. */
static inline int ex_cable_wire(vlbe_dae *sys, vlbe_ale_chain *ch, int banded)
{
    if (banded && !ch->order) return -1;
    return vlbe_ale_chain_dae(ch, sys) ? -1 : 0;
}

/* Workspace of HHT (and of the consistent start) on sys, in the storage
   ex_cable_wire chose. */
static inline void ex_cable_hht_work(const vlbe_dae *sys, size_t *lw, size_t *liw)
{
    *lw = vlbe_hht_work_len_sys(sys);
    *liw = vlbe_hht_iwork_len_sys(sys);
}

/* Workspace of vlbe_dae_static on sys, likewise. */
static inline void ex_cable_static_work(const vlbe_dae *sys, size_t *lw, size_t *liw)
{
    *lw = vlbe_static_work_len_sys(sys);
    *liw = vlbe_static_iwork_len_sys(sys);
}

/* q (in: a start; out: the static equilibrium of sys at t = 0, multipliers
   from 0) by vlbe_dae_static with its defaults; the status. */
static inline vlbe_status ex_cable_solve_static(const vlbe_dae *sys, vlbe_real *q)
{
    size_t lw, liw;
    vlbe_real *w;
    int *iw;
    vlbe_static_params sp;
    vlbe_status st = VLBE_EWORK;
    ex_cable_static_work(sys, &lw, &liw);
    w = (vlbe_real *)malloc((lw + (size_t)sys->m) * sizeof *w);
    iw = (int *)malloc(liw * sizeof *iw);
    if (w && iw) {
        int i;
        vlbe_static_params_default(&sp);
        for (i = 0; i < sys->m; ++i) w[lw + (size_t)i] = VLBE_R(0.0);
        st = vlbe_dae_static(sys, &sp, VLBE_R(0.0), q, w + lw, NULL, w, lw, iw, liw);
    }
    free(w);
    free(iw);
    return st;
}

/* -- the closed form ------------------------------------------------------ */

/* k-th zero of J0, k = 1..EX_CABLE_NMODES (0 otherwise) */
static inline double ex_cable_j0_zero(int k)
{
    static const double z[EX_CABLE_NMODES] = {2.404825557695773, 5.520078110286311,
                                              8.653727912911012};
    return k >= 1 && k <= EX_CABLE_NMODES ? z[k - 1] : 0.0;
}

/* omega_k = (j0_k / 2) sqrt(g / L) */
static inline double ex_cable_omega_exact(int k, double g, double L)
{
    return 0.5 * ex_cable_j0_zero(k) * sqrt(g / L);
}

/* psi(x) = J0(2 sqrt(x)) = sum_k (-x)^k / (k!)^2 and its first two
   derivatives in x (any of the outputs may be NULL); x >= 0, x < ~100 */
static inline void ex_cable_psi(double x, double *f, double *df, double *d2f)
{
    /* t_k = (-x)^k / (k!)^2; d/dx t_k = -t_{k-1} / k, d2/dx2 t_k = t_{k-2} /
       (k (k - 1)) (no division by x) */
    double tm2 = 0.0, tm1 = 0.0, t = 1.0, s0 = 1.0, s1 = 0.0, s2 = 0.0;
    int k;
    for (k = 1; k < 400; ++k) {
        tm2 = tm1;
        tm1 = t;
        t *= -x / ((double)k * (double)k);
        s0 += t;
        s1 -= tm1 / k;
        if (k >= 2) s2 += tm2 / ((double)k * (double)(k - 1));
        /* past the largest term (k^2 > x) the terms fall faster than 1/4 */
        if (k >= 3 && (double)k * (double)k > 4.0 * x &&
            fabs(t) + fabs(tm1) + fabs(tm2) < 1e-18 * (1.0 + fabs(s0) + fabs(s1) + fabs(s2)))
            break;
    }
    if (f) *f = s0;
    if (df) *df = s1;
    if (d2f) *d2f = s2;
}

/* Mode k of the inextensible hanging string at the distance z from the
   free end: u = J0(2 omega sqrt(z / g)), du/dz, d2u/dz2 (NULL allowed). */
static inline void ex_cable_mode(double omega, double g, double z, double *u, double *du,
                                 double *d2u)
{
    const double a = omega * omega / g;
    double f, df, d2f;
    ex_cable_psi(a * (z > 0.0 ? z : 0.0), &f, &df, &d2f);
    if (u) *u = f;
    if (du) *du = a * df;
    if (d2u) *d2u = a * a * d2f;
}

/* -- the model ------------------------------------------------------------ */

typedef struct ex_cable_cfg {
    double L, g;          /* length [m], gravity [m/s^2]                       */
    double rhoA, EA, EI;  /* mass per length [kg/m], axial [N], bending [N m^2] */
    int N;                /* elements                                          */
    int clamped;          /* 0: pinned top (the closed form's), 1: clamped     */
    int banded;           /* 1: banded matrices (ex_cable_wire)                */
} ex_cable_cfg;

/* The scene of examples/hanging_cable.c: L = 10 m, g = 9.81, rhoA = 1 kg/m,
   EA = 1e7 N (eps_top = rhoA g L / EA = 9.8e-6), EI = 1e-7 N m^2 (the
   boundary layer under a clamp l = sqrt(EI / T_top) = 3.2e-5 m), pinned,
   dense, N elements. */
static inline void ex_cable_cfg_default(ex_cable_cfg *c, int N)
{
    memset(c, 0, sizeof *c);
    c->L = 10.0;
    c->g = 9.81;
    c->rhoA = 1.0;
    c->EA = 1e7;
    c->EI = 1e-7;
    c->N = N;
}

typedef struct ex_cable {
    ex_cable_cfg cfg;
    vlbe_ale_mat mat;
    vlbe_ale_elem el;
    vlbe_ale_node *node; /* N + 1, malloc'ed */
    int *order;          /* banded: the augmented order, malloc'ed */
    vlbe_ale_con con[2];
    vlbe_ale_chain ch;
    vlbe_dae sys;
} ex_cable;

/* Frees what ex_cable_build allocated (m itself is the caller's). */
static inline void ex_cable_free(ex_cable *m)
{
    free(m->node);
    free(m->order);
    m->node = NULL;
    m->order = NULL;
}

/* The chain of the header comment; 0 on success (m->node then malloc'ed:
   ex_cable_free), -1 on bad input, no memory or storage not available. */
static inline int ex_cable_build(ex_cable *m, const ex_cable_cfg *c)
{
    vlbe_ale_con k;
    int i;
    memset(m, 0, sizeof *m);
    if (c->N < 1 || !(c->L > 0.0) || !(c->rhoA > 0.0) || !(c->EA > 0.0) || c->EI < 0.0) return -1;
    m->cfg = *c;
    m->mat.rhoA = (vlbe_real)c->rhoA;
    m->mat.EA = (vlbe_real)c->EA;
    m->mat.EI = (vlbe_real)c->EI;
    m->mat.f[1] = (vlbe_real)(-c->g * c->rhoA);
    if (vlbe_ale_elem_init(&m->el, &m->mat,
                           VLBE_ALE_NO_DAMP | (c->EI > 0.0 ? 0u : VLBE_ALE_NO_BEND), 0, 0, 0))
        return -1;
    m->node = (vlbe_ale_node *)calloc((size_t)c->N + 1, sizeof *m->node);
    if (!m->node) return -1;
    for (i = 0; i <= c->N; ++i) {
        m->node[i].pmode = VLBE_ALE_PFIXED;
        m->node[i].p = (vlbe_real)(c->L * i / c->N);
    }
    if (vlbe_ale_chain_init(&m->ch, &m->el, m->node, c->N + 1, c->N + 1, m->con, 2)) goto fail;
    m->ch.g[1] = (vlbe_real)-c->g;
    memset(&k, 0, sizeof k);
    k.type = VLBE_ALE_CON_POS; /* the top at the origin */
    if (vlbe_ale_chain_add(&m->ch, &k)) goto fail;
    if (c->clamped) {
        k.type = VLBE_ALE_CON_SLOPE_DIR; /* r' x (0, -1) = 0: the slope held vertical */
        k.d[1] = VLBE_R(-1.0);
        if (vlbe_ale_chain_add(&m->ch, &k)) goto fail;
    }
    if (c->banded) { /* n + m = 4 (N + 1) + 2 (+ 1 clamped) */
        const int cap = 4 * (c->N + 1) + 3;
        m->order = (int *)malloc((size_t)cap * sizeof *m->order);
        if (!m->order || vlbe_ale_chain_band(&m->ch, m->order, cap)) goto fail;
    }
    if (vlbe_ale_chain_layout(&m->ch) || ex_cable_wire(&m->sys, &m->ch, c->banded)) goto fail;
    return 0;
fail:
    ex_cable_free(m);
    return -1;
}

/* Stretch lam of the Green-strain law at the tension T: EA (lam^2 - 1) lam
   / 2 = T (Newton from 1 + T / EA; monotone, converges in a few steps). */
static inline double ex_cable_stretch(double EA, double T)
{
    double lam = 1.0 + T / EA;
    int it;
    for (it = 0; it < 50; ++it) {
        const double f = 0.5 * EA * (lam * lam - 1.0) * lam - T;
        const double d = 0.5 * EA * (3.0 * lam * lam - 1.0);
        const double dl = f / d;
        lam -= dl;
        if (fabs(dl) <= 1e-16 * lam) break;
    }
    return lam;
}

/* int_a^b f by 8-point Gauss-Legendre on n equal pieces (double) */
static inline double ex_cable_quad(double (*f)(const void *, double), const void *ctx, double a,
                                   double b, int n)
{
    const vlbe_real *xi, *w;
    double s = 0.0;
    int i, g;
    if (vlbe_gl_rule(8, &xi, &w)) return (double)NAN;
    for (i = 0; i < n; ++i) {
        const double lo = a + (b - a) * i / n, hi = a + (b - a) * (i + 1) / n;
        for (g = 0; g < 8; ++g)
            s += 0.5 * (hi - lo) * (double)w[g] *
                 f(ctx, 0.5 * (lo + hi) + 0.5 * (hi - lo) * (double)xi[g]);
    }
    return s;
}

/* stretch at material coordinate p of the hanging cable (ctx: its cfg) */
static inline double ex_cable__lam_at(const void *ctx, double p)
{
    const ex_cable_cfg *c = (const ex_cable_cfg *)ctx;
    return ex_cable_stretch(c->EA, c->rhoA * c->g * (c->L - p));
}

/* q <- the straight vertical cable with the exact stretch of the Green-strain
   law: r(p_i) = (0, -int_0^p_i lam), r'(p_i) = (0, -lam(p_i)). */
static inline void ex_cable_hanging(const ex_cable *m, vlbe_real *q)
{
    double y = 0.0;
    int i;
    for (i = 0; i < m->ch.nn; ++i) {
        vlbe_real *x = q + m->node[i].ofs;
        const double p = (double)m->node[i].p;
        if (i > 0) y -= ex_cable_quad(ex_cable__lam_at, &m->cfg, (double)m->node[i - 1].p, p, 1);
        x[0] = VLBE_R(0.0);
        x[1] = (vlbe_real)y;
        x[2] = VLBE_R(0.0);
        x[3] = (vlbe_real)-ex_cable__lam_at(&m->cfg, p);
    }
}

/* q (in: a start such as ex_cable_hanging; out: the discrete static
   equilibrium) by vlbe_dae_static; the status. */
static inline vlbe_status ex_cable_static(ex_cable *m, vlbe_real *q)
{
    return ex_cable_solve_static(&m->sys, q);
}

/* -- the physics corrections --------------------------------------------- */

typedef struct ex_cable__qc {
    const ex_cable_cfg *c;
    double omega;
    int what;
} ex_cable__qc;

/* integrands in s (distance from the free end) of the corrections */
static inline double ex_cable__integrand(const void *ctx, double s)
{
    const ex_cable__qc *q = (const ex_cable__qc *)ctx;
    double u, du, d2u;
    ex_cable_mode(q->omega, q->c->g, s, &u, &du, &d2u);
    switch (q->what) {
    case 0: return s * s * du * du;
    case 1: return s * du * du;
    case 2: return d2u * d2u;
    default: return u * u;
    }
}

/* First-order relative corrections of omega_k (header comment): extension,
   bending with a pinned top, and the clamp's boundary layer l / (2 L). */
static inline void ex_cable_corrections(const ex_cable_cfg *c, int k, double *ext, double *bend,
                                        double *clamp)
{
    ex_cable__qc q;
    double I[4];
    int w;
    q.c = c;
    q.omega = ex_cable_omega_exact(k, c->g, c->L);
    for (w = 0; w < 4; ++w) {
        q.what = w;
        I[w] = ex_cable_quad(ex_cable__integrand, &q, 0.0, c->L, 64);
    }
    if (ext) *ext = -(c->rhoA * c->g / (2.0 * c->EA)) * I[0] / I[1];
    if (bend) *bend = c->EI * I[2] / (2.0 * q.omega * q.omega * c->rhoA * I[3]);
    if (clamp) *clamp = sqrt(c->EI / (c->rhoA * c->g * c->L)) / (2.0 * c->L);
}

/* -- the measurement ------------------------------------------------------- */

/* c (n reals) <- the linear form a(q) = int rhoA u(s) x(p) dp, s = L - p, of
   the lateral positions x(p) = sum_j N_j(p) x_j (x, x' of the nodes), u the
   analytic mode of frequency omega; 6-point Gauss-Legendre per element. */
static inline void ex_cable_proj(const ex_cable *m, double omega, vlbe_real *c)
{
    const vlbe_real *xi, *w;
    int e, g, j;
    for (j = 0; j < m->ch.n; ++j) c[j] = VLBE_R(0.0);
    if (vlbe_gl_rule(EX_CABLE_NGP, &xi, &w)) return;
    for (e = 0; e + 1 < m->ch.nn; ++e) {
        const double p1 = (double)m->node[e].p, p2 = (double)m->node[e + 1].p;
        const int idx[4] = {m->node[e].ofs, m->node[e].ofs + 2, m->node[e + 1].ofs,
                            m->node[e + 1].ofs + 2};
        for (g = 0; g < EX_CABLE_NGP; ++g) {
            const double p = 0.5 * (p1 + p2) + 0.5 * (p2 - p1) * (double)xi[g];
            const double wg = 0.5 * (p2 - p1) * (double)w[g];
            vlbe_herm_ale b;
            double u;
            ex_cable_mode(omega, m->cfg.g, m->cfg.L - p, &u, NULL, NULL);
            vlbe_herm_ale_eval((vlbe_real)p, (vlbe_real)p1, (vlbe_real)p2, 0, 0, &b);
            for (j = 0; j < 4; ++j) c[idx[j]] += (vlbe_real)(wg * m->cfg.rhoA * u) * b.h[0][0][j];
        }
    }
}

/* v <- 0 except the lateral rates of the analytic mode of frequency omega
   scaled to the amplitude amp [m] at the free end: x' = (amp omega) u(s),
   x'_p = -(amp omega) du/ds (node 0's position rate stays 0: u(L) = 0 for a
   mode of the pinned string, and the pin holds it). */
static inline void ex_cable_mode_rates(const ex_cable *m, double omega, double amp, vlbe_real *v)
{
    int i;
    for (i = 0; i < m->ch.n; ++i) v[i] = VLBE_R(0.0);
    for (i = 0; i < m->ch.nn; ++i) {
        double u, du;
        ex_cable_mode(omega, m->cfg.g, m->cfg.L - (double)m->node[i].p, &u, &du, NULL);
        if (i > 0) v[m->node[i].ofs] = (vlbe_real)(amp * omega * u);
        if (!(i == 0 && m->cfg.clamped)) v[m->node[i].ofs + 2] = (vlbe_real)(-amp * omega * du);
    }
}

/* HHT-alpha's relative frequency error coefficient: Omega = omega (1 - c
   (omega h)^2 + ...) */
static inline double ex_cable_hht_c(double alpha)
{
    return 1.0 / 12.0 - alpha / 4.0 - 3.0 * alpha * alpha / 8.0;
}

/* Zero crossings of a sampled a(t) with its rate: inside a step the root of
   the cubic Hermite interpolant of (a, a') at the step's ends (bisection;
   vlbe_herm_ale_eval's basis on [t0, t1]). */
typedef struct ex_cable_cross {
    int have, n;
    double t0, a0, ad0;
    double t[EX_CABLE_MAXCROSS];
} ex_cable_cross;

static inline void ex_cable_cross_add(ex_cable_cross *cr, double t, double a, double ad)
{
    if (cr->have && cr->n < EX_CABLE_MAXCROSS && a != 0.0 &&
        ((cr->a0 > 0.0 && a < 0.0) || (cr->a0 < 0.0 && a > 0.0))) {
        const double s0 = cr->a0 > 0.0 ? 1.0 : -1.0;
        double lo = 0.0, hi = 1.0;
        int k;
        for (k = 0; k < 60; ++k) {
            const double mid = 0.5 * (lo + hi), tau = t - cr->t0;
            vlbe_herm_ale b;
            double y;
            vlbe_herm_ale_eval((vlbe_real)(mid * tau), VLBE_R(0.0), (vlbe_real)tau, 0, 0, &b);
            y = (double)b.h[0][0][0] * cr->a0 + (double)b.h[0][0][1] * cr->ad0 +
                (double)b.h[0][0][2] * a + (double)b.h[0][0][3] * ad;
            if (y * s0 > 0.0) lo = mid;
            else hi = mid;
        }
        cr->t[cr->n++] = cr->t0 + 0.5 * (lo + hi) * (t - cr->t0);
    }
    if (a != 0.0 || !cr->have) { /* an exact zero: wait for the sign after it */
        cr->have = 1;
        cr->t0 = t;
        cr->a0 = a;
        cr->ad0 = ad;
    }
}

/* Omega from the crossings: least-squares line t_j = t_0 + j pi / Omega;
   *rms (may be NULL) its rms residual [s].  NaN with fewer than 2. */
static inline double ex_cable_cross_omega(const ex_cable_cross *cr, double *rms)
{
    double sj = 0.0, st = 0.0, sjj = 0.0, sjt = 0.0, slope, icpt, r = 0.0;
    int j;
    const int n = cr->n;
    if (n < 2) return (double)NAN;
    for (j = 0; j < n; ++j) {
        sj += j;
        st += cr->t[j];
        sjj += (double)j * j;
        sjt += j * cr->t[j];
    }
    slope = (n * sjt - sj * st) / (n * sjj - sj * sj);
    icpt = (st - slope * sj) / n;
    for (j = 0; j < n; ++j) {
        const double d = cr->t[j] - icpt - slope * j;
        r += d * d;
    }
    if (rms) *rms = sqrt(r / n);
    return 3.14159265358979323846 / slope;
}

/* One frequency run. */
typedef struct ex_cable_run {
    double amp;           /* lateral amplitude at the free end [m]           */
    int steps_per_period; /* h = T_k / steps_per_period (T_k of the closed form) */
    int periods;          /* periods measured (2 crossings each)             */
    double alpha;         /* HHT-alpha                                       */
    int halvings;         /* HHT step halvings on a Newton failure           */
} ex_cable_run;

/* The settings of the scenes: amplitude 10 um (1e-6 L), 200 steps per
   period, 2 periods, alpha = -0.05, up to 8 halvings of a step. */
static inline void ex_cable_run_default(ex_cable_run *r)
{
    r->amp = 1e-5;
    r->steps_per_period = 200;
    r->periods = 2;
    r->alpha = -0.05;
    r->halvings = 8;
}

typedef struct ex_cable_freq_out {
    vlbe_status status;
    double omega_raw;  /* from the crossings [rad/s]                         */
    double omega;      /* with HHT's leading frequency error removed [rad/s]  */
    double h;          /* step [s]                                            */
    double rms;        /* rms residual of the crossing fit [s]               */
    int crossings;
    double x_end_max;  /* largest |x| of the free end [m]                    */
    long steps, newton, lu;
    double cpu;        /* seconds                                            */
} ex_cable_freq_out;

typedef struct ex_cable__obs {
    const vlbe_real *c;
    int n, iend;
    ex_cable_cross cr;
    double xmax;
} ex_cable__obs;

static inline vlbe_status ex_cable__observe(void *ctx, double t, const vlbe_real *q,
                                            const vlbe_real *v, const vlbe_real *lam)
{
    ex_cable__obs *o = (ex_cable__obs *)ctx;
    double a = 0.0, ad = 0.0;
    int j;
    (void)lam;
    for (j = 0; j < o->n; ++j) {
        a += (double)o->c[j] * (double)q[j];
        ad += (double)o->c[j] * (double)v[j];
    }
    ex_cable_cross_add(&o->cr, t, a, ad); /* a(0) = 0: the start, not a crossing */
    if (fabs((double)q[o->iend]) > o->xmax) o->xmax = fabs((double)q[o->iend]);
    return VLBE_OK;
}

/* omega_k measured from the start (qs, the lateral rates of mode k) as in
   the header comment, on the model m (any top). */
static inline ex_cable_freq_out ex_cable_freq(ex_cable *m, const vlbe_real *qs, int k,
                                              const ex_cable_run *run)
{
    ex_cable_freq_out r;
    const int n = m->ch.n;
    const double om = ex_cable_omega_exact(k, m->cfg.g, m->cfg.L);
    const double T = 2.0 * 3.14159265358979323846 / om;
    vlbe_real *c = (vlbe_real *)malloc(2 * (size_t)n * sizeof *c), *v0 = c ? c + n : NULL;
    vlbe_hht_params par;
    ex_method meth;
    ex_run_out ro;
    ex_cable__obs obs;
    memset(&r, 0, sizeof r);
    memset(&meth, 0, sizeof meth);
    memset(&obs, 0, sizeof obs);
    r.status = VLBE_EWORK;
    r.omega = r.omega_raw = (double)NAN;
    if (!c || run->steps_per_period < 8 || run->periods < 1) {
        free(c);
        if (c) r.status = VLBE_EARG;
        return r;
    }
    ex_cable_proj(m, om, c);
    ex_cable_mode_rates(m, om, run->amp, v0);
    if ((r.status = vlbe_hht_params_alpha(&par, (vlbe_real)run->alpha)) != VLBE_OK) {
        free(c);
        return r;
    }
    r.h = T / run->steps_per_period;
    par.max_halvings = run->halvings;
    meth.hht = &par;
    meth.h = r.h;
    ex_cable_hht_work(&m->sys, &meth.work_len, &meth.iwork_len);
    meth.work = (vlbe_real *)malloc(meth.work_len * sizeof *meth.work);
    meth.iwork = (int *)malloc(meth.iwork_len * sizeof *meth.iwork);
    if (!meth.work || !meth.iwork) {
        free(meth.work);
        free(meth.iwork);
        free(c);
        r.status = VLBE_EWORK;
        return r;
    }
    obs.c = c;
    obs.n = n;
    obs.iend = m->node[m->ch.nn - 1].ofs;
    /* periods + 1/4: the last crossing at periods T lies inside the run */
    ex_run(&m->sys, &meth, qs, v0, (run->periods + 0.25) * T, ex_cable__observe, &obs, NULL, NULL,
           NULL, &ro);
    r.status = ro.status;
    r.cpu = ro.cpu;
    r.steps = ro.stats.steps;
    r.newton = ro.stats.newton_iters;
    r.lu = ro.stats.lu_factors;
    r.crossings = obs.cr.n;
    r.x_end_max = obs.xmax;
    r.omega_raw = ex_cable_cross_omega(&obs.cr, &r.rms);
    r.omega = r.omega_raw * (1.0 + ex_cable_hht_c(run->alpha) * (r.omega_raw * r.h) *
                                       (r.omega_raw * r.h));
    free(meth.work);
    free(meth.iwork);
    free(c);
    return r;
}

/* -- the cross-check: eigen-analysis of the lateral block ----------------- */

/* The lowest nmodes lateral frequencies [rad/s] of the linearisation at q
   (a static state of the straight vertical cable), dense: M and K from the
   chain's callbacks, the lateral coordinates (x, x' of every node but those
   the top's constraints hold), -K x = omega^2 M x by vlbe_eig_gsym with
   sigma = 0 (shift-invert: the lowest modes to a few EPS).
   shape (may be NULL): nmodes x nn, the lateral positions of the nodes in
   each mode, scaled to 1 at the free end.  Dense models only (cfg.banded =
   0, else VLBE_EARG). */
static inline vlbe_status ex_cable_eig(ex_cable *m, const vlbe_real *q, int nmodes, double *omega,
                                       double *shape)
{
    const int n = m->ch.n;
    int *li = (int *)malloc((size_t)n * sizeof *li);
    vlbe_real *M = (vlbe_real *)malloc(2 * (size_t)n * (size_t)n * sizeof *M);
    vlbe_real *K = M ? M + (size_t)n * (size_t)n : NULL;
    vlbe_real *v = NULL, *A = NULL, *B = NULL, *lam = NULL, *w = NULL;
    vlbe_status st = VLBE_EWORK;
    int i, j, nl = 0;
    if (m->cfg.banded) {
        st = VLBE_EARG;
        goto done;
    }
    if (!li || !M) goto done;
    for (i = 0; i < m->ch.nn; ++i) {
        if (i > 0) li[nl++] = m->node[i].ofs; /* x of node 0: pinned */
        if (!(i == 0 && m->cfg.clamped)) li[nl++] = m->node[i].ofs + 2;
    }
    if (nmodes > nl) {
        st = VLBE_EARG;
        goto done;
    }
    v = (vlbe_real *)calloc((size_t)n, sizeof *v);
    A = (vlbe_real *)malloc((2 * (size_t)nl * (size_t)nl + (size_t)nl) * sizeof *A);
    w = (vlbe_real *)malloc(vlbe_eig_work_len(nl) * sizeof *w);
    if (!v || !A || !w) goto done;
    B = A + (size_t)nl * (size_t)nl;
    lam = B + (size_t)nl * (size_t)nl;
    if (m->sys.mass(m->sys.user, VLBE_R(0.0), q, v, M) ||
        m->sys.force_jac(m->sys.user, VLBE_R(0.0), q, v, K, NULL)) {
        st = m->ch.err != VLBE_OK ? m->ch.err : VLBE_ECALLBACK;
        goto done;
    }
    for (i = 0; i < nl; ++i)
        for (j = 0; j < nl; ++j) {
            A[i * nl + j] = M[(size_t)li[i] * (size_t)n + (size_t)li[j]];
            B[i * nl + j] = -K[(size_t)li[i] * (size_t)n + (size_t)li[j]];
        }
    if ((st = vlbe_eig_gsym(nl, B, A, VLBE_R(0.0), lam, shape ? M : NULL, NULL, w,
                            vlbe_eig_work_len(nl))) != VLBE_OK)
        goto done;
    for (i = 0; i < nmodes; ++i) omega[i] = sqrt((double)lam[i]);
    for (i = 0; shape && i < nmodes; ++i) { /* x of the nodes (M holds the vectors now) */
        const int col = i, nn = m->ch.nn;
        const double xe = (double)M[(size_t)(nl - 2) * (size_t)nl + (size_t)col]; /* free end */
        shape[i * nn] = 0.0;
        for (j = 1; j < nn; ++j) {
            const int a = 2 * j - (m->cfg.clamped ? 2 : 1); /* index of node j's x in li */
            shape[i * nn + j] = (double)M[(size_t)a * (size_t)nl + (size_t)col] / xe;
        }
    }
done:
    free(li);
    free(M);
    free(v);
    free(A);
    free(w);
    return st;
}

#endif /* VLBE_EX_CABLE_H */
