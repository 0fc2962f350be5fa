/* pendulum.h -- the index-3 Cartesian pendulum: the problem (pend_setup,
   pend_initial), its exact multiplier and period (pend_lambda_exact,
   pend_period_exact), the period measurement and the runs (pend_run,
   pend_run_bdf).  Shared by examples/pendulum.c (the tables), the suites
   tests/test_integrators.c, tests/test_bdf.c, tests/test_dae_project.c,
   tests/pend_faults.h, the Cortex-M4F program tests/m4/m4_bdf.c and the
   benchmarks bench/bench_integrators.c, bench/wp_integrators.c.
   -- part of vlbe                                  SPDX-License-Identifier: MIT

   The problem: a point mass m on a massless rod of length L in gravity g,
   in Cartesian coordinates q = (x, y) (y up), released at rest from the
   horizontal position q0 = (L, 0):

        m q'' + C_q^T lambda = (0, -m g),    C(q) = (x^2 + y^2 - L^2) / 2 = 0,

   an index-3 DAE with C_q = (x, y).  The multiplier follows from the
   constraint differentiated twice, x x'' + y y'' + |v|^2 = 0, which with the
   equations of motion gives  lambda = (m |v|^2 - m g y) / L^2;  energy
   conservation from rest at y = 0 gives |v|^2 = -2 g y, hence

        lambda = -3 m g y / L^2      (rod tension lambda L, >= 0 below y = 0).

   The exact period for the amplitude theta0 = pi/2 is
        T = 4 K(k) sqrt(L/g),  k = sin(theta0/2),  K(k) = pi / (2 AGM(1, sqrt(1-k^2))),
   2.367841947576 s for L = 1 m, g = 9.81 m/s^2; pend_period_exact() computes it
   independently with the arithmetic-geometric mean.

   The period is measured from the crossings of x = 0 in the same direction
   (x from + to -): inside the step where x changes sign the crossing time is
   the root of the cubic Hermite interpolant of (x, x') at both ends of the
   step, whose own error O(h^4) is far below the O(h^2) integration error. */
#ifndef VLBE_SCENE_PENDULUM_H
#define VLBE_SCENE_PENDULUM_H

#include "../integrators.h"
#include "ex_run.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

/* -- the problem ---------------------------------------------------------- */
#define PEND_T_PUBLISHED 2.367841947576 /* s, 4 K(sin(pi/4)) sqrt(L/g), L = 1 m, g = 9.81 */
#define PEND_L 1.0                      /* m      */
#define PEND_G 9.81                     /* m/s^2  */
#define PEND_M 1.0                      /* kg     */

typedef struct pend_par {
    vlbe_real m, L, g; /* kg, m, m/s^2 */
} pend_par;

static inline pend_par pend_default(void)
{
    pend_par p;
    p.m = (vlbe_real)PEND_M;
    p.L = (vlbe_real)PEND_L;
    p.g = (vlbe_real)PEND_G;
    return p;
}

static inline int pend_mass(void *user, vlbe_real t, const vlbe_real *q, const vlbe_real *v, vlbe_real *M)
{
    const pend_par *p = (const pend_par *)user;
    (void)t;
    (void)q;
    (void)v;
    M[0] = p->m;
    M[1] = VLBE_R(0.0);
    M[2] = VLBE_R(0.0);
    M[3] = p->m;
    return 0;
}

static inline int pend_force(void *user, vlbe_real t, const vlbe_real *q, const vlbe_real *v, vlbe_real *Q)
{
    const pend_par *p = (const pend_par *)user;
    (void)t;
    (void)q;
    (void)v;
    Q[0] = VLBE_R(0.0);
    Q[1] = -p->m * p->g;
    return 0;
}

static inline int pend_constr(void *user, vlbe_real t, const vlbe_real *q, vlbe_real *C)
{
    const pend_par *p = (const pend_par *)user;
    (void)t;
    C[0] = VLBE_R(0.5) * (q[0] * q[0] + q[1] * q[1] - p->L * p->L);
    return 0;
}

static inline int pend_constr_jac(void *user, vlbe_real t, const vlbe_real *q, vlbe_real *Cq, vlbe_real *Ct)
{
    (void)user;
    (void)t;
    Cq[0] = q[0];
    Cq[1] = q[1];
    if (Ct) Ct[0] = VLBE_R(0.0);
    return 0;
}

/* gamma = -(C_q v)_q v = -|v|^2 */
static inline int pend_constr_acc(void *user, vlbe_real t, const vlbe_real *q, const vlbe_real *v,
                           vlbe_real *gamma)
{
    (void)user;
    (void)t;
    (void)q;
    gamma[0] = -(v[0] * v[0] + v[1] * v[1]);
    return 0;
}

/* Q is constant: K = D = 0 */
static inline int pend_force_jac(void *user, vlbe_real t, const vlbe_real *q, const vlbe_real *v,
                          vlbe_real *K, vlbe_real *D)
{
    int i;
    (void)user;
    (void)t;
    (void)q;
    (void)v;
    for (i = 0; i < 4; ++i) K[i] = D[i] = VLBE_R(0.0);
    return 0;
}

/* d(C_q^T lambda)/dq = lambda I */
static inline int pend_constr_hess(void *user, vlbe_real t, const vlbe_real *q, const vlbe_real *lambda,
                            vlbe_real *H)
{
    (void)user;
    (void)t;
    (void)q;
    H[0] = H[3] = lambda[0];
    H[1] = H[2] = VLBE_R(0.0);
    return 0;
}

/* Fills sys for the pendulum with parameters *p (p must outlive sys), with
   the analytic Jacobians; a caller may set the optional ones to NULL to use
   the integrator's finite differences instead. */
static inline void pend_setup(vlbe_dae *sys, pend_par *p)
{
    vlbe_dae z = {0};
    *sys = z;
    sys->n = 2;
    sys->m = 1;
    sys->flags = VLBE_DAE_MASS_CONST;
    sys->user = p;
    sys->mass = pend_mass;
    sys->force = pend_force;
    sys->constr = pend_constr;
    sys->constr_jac = pend_constr_jac;
    sys->constr_acc = pend_constr_acc;
    sys->force_jac = pend_force_jac;
    sys->constr_hess = pend_constr_hess;
}

/* At rest, rod horizontal. */
static inline void pend_initial(const pend_par *p, vlbe_real q0[2], vlbe_real v0[2])
{
    q0[0] = p->L;
    q0[1] = VLBE_R(0.0);
    v0[0] = v0[1] = VLBE_R(0.0);
}

/* Exact multiplier at height y (energy from rest at y = 0). */
static inline double pend_lambda_exact(const pend_par *p, double y)
{
    return -3.0 * (double)p->m * (double)p->g * y / ((double)p->L * (double)p->L);
}

/* Exact period for the release from the horizontal (theta0 = pi/2):
   T = 4 K(k) sqrt(L/g) with k = sin(pi/4), K(k) = pi / (2 AGM(1, k')),
   k' = cos(pi/4) = sqrt(1/2).  The AGM converges quadratically; it stops
   when a and b agree to the last bit (or after 64 rounds). */
static inline double pend_period_exact(double L, double g)
{
    const double pi = 3.14159265358979323846;
    double a = 1.0, b = sqrt(0.5);
    int i;
    for (i = 0; i < 64 && a != b; ++i) {
        double an = 0.5 * (a + b), bn = sqrt(a * b);
        if (an == a && bn == b) break;
        a = an;
        b = bn;
    }
    return 4.0 * (pi / (2.0 * a)) * sqrt(L / g);
}

/* -- period measurement --------------------------------------------------- */
/* Crossings of x = 0 from x > 0 to x <= 0.  Feed every accepted step. */
typedef struct pend_period {
    int have_prev, n_cross;
    double t0, x0, v0;        /* previous sample */
    double t_first, t_last;   /* first and last crossing times */
} pend_period;

static inline void pend_period_init(pend_period *pp)
{
    pp->have_prev = 0;
    pp->n_cross = 0;
    pp->t0 = pp->x0 = pp->v0 = 0.0;
    pp->t_first = pp->t_last = 0.0;
}

/* Value of the cubic Hermite interpolant on [t0, t0 + tau] at s in [0, 1]. */
static inline double pend_hermite(double s, double tau, double x0, double v0, double x1, double v1)
{
    double s2 = s * s, s3 = s2 * s;
    return (2.0 * s3 - 3.0 * s2 + 1.0) * x0 + (s3 - 2.0 * s2 + s) * tau * v0 +
           (-2.0 * s3 + 3.0 * s2) * x1 + (s3 - s2) * tau * v1;
}

static inline void pend_period_add(pend_period *pp, double t, double x, double v)
{
    if (pp->have_prev && pp->x0 > 0.0 && x <= 0.0) {
        /* bisection on the Hermite cubic: p(0) = x0 > 0 >= x1 = p(1) */
        double tau = t - pp->t0, lo = 0.0, hi = 1.0, tc;
        int k;
        for (k = 0; k < 200; ++k) {
            double mid = 0.5 * (lo + hi);
            if (mid <= lo || mid >= hi) break;
            if (pend_hermite(mid, tau, pp->x0, pp->v0, x, v) > 0.0) lo = mid;
            else hi = mid;
        }
        tc = pp->t0 + 0.5 * (lo + hi) * tau;
        if (pp->n_cross == 0) pp->t_first = tc;
        pp->t_last = tc;
        ++pp->n_cross;
    }
    pp->have_prev = 1;
    pp->t0 = t;
    pp->x0 = x;
    pp->v0 = v;
}

/* Mean period over the crossings seen; NaN if fewer than two. */
static inline double pend_period_value(const pend_period *pp)
{
    if (pp->n_cross < 2) return NAN;
    return (pp->t_last - pp->t_first) / (double)(pp->n_cross - 1);
}

/* -- one run -------------------------------------------------------------- */
typedef struct pend_result {
    vlbe_status status; /* of the first failing call, VLBE_OK if none     */
    double t_reached;   /* time of the last accepted step [s]            */
    double period;      /* measured period [s] (NaN if < 2 crossings)    */
    double max_c;       /* max |C| over the accepted steps [m^2]         */
    double max_cv;      /* max |C_q v| [m^2/s]                           */
    double max_lam_err; /* max |lambda - (-3 m g y / L^2)| [N/m]         */
    double lam_err_early, lam_err_late; /* the same over t in (0, 1] and
                                            (t_end - 1, t_end] [N/m]     */
    double cpu;         /* seconds                                       */
    vlbe_dae_stats stats;
} pend_result;

/* Empties *res before a run. */
static inline void pend_result_reset(pend_result *res)
{
    vlbe_dae_stats zero_stats = {0};
    res->status = VLBE_OK;
    res->stats = zero_stats;
    res->period = NAN;
    res->max_c = res->max_cv = res->max_lam_err = 0.0;
    res->lam_err_early = res->lam_err_late = 0.0;
    res->t_reached = 0.0;
    res->cpu = 0.0;
}

/* Records one accepted step (t, q, v, lambda) of a run ending at t_end. */
static inline void pend_observe(const pend_par *p, pend_period *pp, pend_result *res, double t,
                                double t_end, const vlbe_real *q, const vlbe_real *v,
                                const vlbe_real *lambda)
{
    double x = (double)q[0], y = (double)q[1], vx = (double)v[0], vy = (double)v[1];
    /* constraint residual in the working precision, as the integrator sees it */
    double c = fabs((double)(VLBE_R(0.5) * (q[0] * q[0] + q[1] * q[1] - p->L * p->L)));
    double cv = fabs(x * vx + y * vy);
    double le = fabs((double)lambda[0] - pend_lambda_exact(p, y));
    res->t_reached = t;
    if (c > res->max_c) res->max_c = c;
    if (cv > res->max_cv) res->max_cv = cv;
    if (le > res->max_lam_err) res->max_lam_err = le;
    if (t <= 1.0 && le > res->lam_err_early) res->lam_err_early = le;
    if (t > t_end - 1.0 && le > res->lam_err_late) res->lam_err_late = le;
    pend_period_add(pp, t, x, vx);
}

/* Observer of a run: feeds pend_observe. */
typedef struct pend_obs {
    const pend_par *p;
    pend_period pp;
    pend_result *res;
    double t_end;
} pend_obs;

static inline vlbe_status pend_obs_step(void *ctx, double t, const vlbe_real *q,
                                        const vlbe_real *v, const vlbe_real *lambda)
{
    pend_obs *o = (pend_obs *)ctx;
    pend_observe(o->p, &o->pp, o->res, t, o->t_end, q, v, lambda);
    return VLBE_OK;
}

/* Runs method m on sys (whose user is a pend_par) to t_end and fills *res,
   also when a step fails (then with the data up to the failure). */
static inline vlbe_status pend_run_method(const vlbe_dae *sys, const ex_method *m, double t_end,
                                          pend_result *res)
{
    pend_obs o;
    ex_run_out out;
    vlbe_real q0[2], v0[2];
    o.p = (const pend_par *)sys->user;
    o.res = res;
    o.t_end = t_end;
    pend_result_reset(res);
    pend_period_init(&o.pp);
    pend_initial(o.p, q0, v0);
    ex_run(sys, m, q0, v0, t_end, pend_obs_step, &o, NULL, NULL, NULL, &out);
    res->period = pend_period_value(&o.pp);
    res->cpu = out.cpu;
    res->stats = out.stats;
    return res->status = out.status;
}

/* Fixed step h of the generalized-alpha scheme par, up to t_end. */
static inline vlbe_status pend_run_sys(const vlbe_dae *sys, const vlbe_hht_params *par, double h,
                                       double t_end, pend_result *res)
{
    ex_method m = {0};
    m.hht = par;
    m.h = h;
    return pend_run_method(sys, &m, t_end, res);
}

/* The same for the default problem (analytic Jacobians). */
static inline vlbe_status pend_run(const vlbe_hht_params *par, double h, double t_end, pend_result *res)
{
    pend_par p = pend_default();
    vlbe_dae sys;
    pend_setup(&sys, &p);
    return pend_run_sys(&sys, par, h, t_end, res);
}

/* The same measurements with the variable-step BDF (GGL index-2 form),
   tolerance rtol, atol = rtol / 100; the crossings use each accepted step. */
static inline vlbe_status pend_run_bdf(double rtol, double t_end, pend_result *res)
{
    pend_par p = pend_default();
    vlbe_dae sys;
    vlbe_bdf_params par;
    ex_method m = {0};
    pend_setup(&sys, &p);
    vlbe_bdf_params_default(&par);
    par.rtol = (vlbe_real)rtol;
    par.atol = (vlbe_real)(rtol * 1e-2);
    m.bdf = &par;
    return pend_run_method(&sys, &m, t_end, res);
}

#endif /* VLBE_SCENE_PENDULUM_H */
