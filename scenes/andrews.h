/* andrews.h -- Andrews' squeezing mechanism (seven bodies, index 3): the
   problem with analytic Jacobians (andr_setup; andr_setup_fd without
   them), its consistent start (andr_initial), the Test Set's reference
   solution at t = 0.03 s and the runs (andr_run, andr_run_bdf).  Shared by
   examples/andrews.c (the tables), tests/test_integrators.c,
   tests/test_bdf.c and the benchmarks bench/bench_integrators.c,
   bench/wp_integrators.c.
   -- part of vlbe                                  SPDX-License-Identifier: MIT

   The problem as defined in
     E. Hairer, G. Wanner, Solving Ordinary Differential Equations II,
     2nd ed., Springer 1996, section VII.7 ("Seven body mechanism"), and
     F. Mazzia, C. Magherini, Test Set for IVP Solvers, release 2.4 (2008),
     problem "andrews" (index-3 formulation; reference solution by PSIDE,
     rtol = atol = 1e-14):
   q = (beta, Theta, gamma, Phi, delta, Omega, epsilon) [rad], 6 holonomic
   constraints (the loops closed at the fixed points A and B), all SI:

        M(q) q'' + G(q)^T lambda = f(q, q'),   g(q) = 0,   t in [0, 0.03] s,

   M: 7 x 7 symmetric, depending on Theta, Phi and Omega; f: the driving
   torque mom = 0.033 N m on beta, the spring c0 = 4530 N/m of rest length
   l0 = 0.07785 m between C and the point D of body 3, and the velocity
   terms.  Signs as in the Test Set (its residual is M w + G^T lambda - f),
   which is also vlbe's convention, so lambda compares directly.  Initial
   values: consistent positions, zero velocities; the Test Set's initial
   accelerations (14222.44.., -10666.83.., 0, ..) and multipliers
   (98.5668.., -6.1226.., 0, 0, 0, 0) check vlbe_dae_consistent_acc.

   All Jacobians are analytic (force_jac, mass_jac, constr_hess and the
   constraint acceleration term constr_acc); andr_setup_fd() leaves them to
   the integrator's finite differences instead. */
#ifndef VLBE_SCENE_ANDREWS_H
#define VLBE_SCENE_ANDREWS_H

#include "../integrators.h"
#include "ex_run.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

/* -- the problem ---------------------------------------------------------- */
#define ANDR_N 7
#define ANDR_M 6
#define ANDR_T_END 0.03 /* s */

/* Constants of the Test Set / Hairer-Wanner (SI units). */
typedef struct andr_par {
    vlbe_real m1, m2, m3, m4, m5, m6, m7;      /* kg      */
    vlbe_real i1, i2, i3, i4, i5, i6, i7;      /* kg m^2  */
    vlbe_real xa, ya, xb, yb, xc, yc;          /* m       */
    vlbe_real d, da, e, ea, rr, ra, ss, sa, sb, sc, sd, ta, tb, u, ua, ub, zf, zt, fa; /* m */
    vlbe_real mom;                             /* N m     */
    vlbe_real c0, l0;                          /* N/m, m  */
} andr_par;

static inline andr_par andr_default(void)
{
    andr_par p;
    p.m1 = VLBE_R(0.04325);
    p.m2 = VLBE_R(0.00365);
    p.m3 = VLBE_R(0.02373);
    p.m4 = VLBE_R(0.00706);
    p.m5 = VLBE_R(0.07050);
    p.m6 = VLBE_R(0.00706);
    p.m7 = VLBE_R(0.05498);
    p.i1 = VLBE_R(2.194e-6);
    p.i2 = VLBE_R(4.410e-7);
    p.i3 = VLBE_R(5.255e-6);
    p.i4 = VLBE_R(5.667e-7);
    p.i5 = VLBE_R(1.169e-5);
    p.i6 = VLBE_R(5.667e-7);
    p.i7 = VLBE_R(1.912e-5);
    p.xa = VLBE_R(-0.06934);
    p.ya = VLBE_R(-0.00227);
    p.xb = VLBE_R(-0.03635);
    p.yb = VLBE_R(0.03273);
    p.xc = VLBE_R(0.014);
    p.yc = VLBE_R(0.072);
    p.d = VLBE_R(0.028);
    p.da = VLBE_R(0.0115);
    p.e = VLBE_R(0.02);
    p.ea = VLBE_R(0.01421);
    p.rr = VLBE_R(0.007);
    p.ra = VLBE_R(0.00092);
    p.ss = VLBE_R(0.035);
    p.sa = VLBE_R(0.01874);
    p.sb = VLBE_R(0.01043);
    p.sc = VLBE_R(0.018);
    p.sd = VLBE_R(0.02);
    p.ta = VLBE_R(0.02308);
    p.tb = VLBE_R(0.00916);
    p.u = VLBE_R(0.04);
    p.ua = VLBE_R(0.01228);
    p.ub = VLBE_R(0.00449);
    p.zf = VLBE_R(0.02);
    p.zt = VLBE_R(0.04);
    p.fa = VLBE_R(0.01421);
    p.mom = VLBE_R(0.033);
    p.c0 = VLBE_R(4530.0);
    p.l0 = VLBE_R(0.07785);
    return p;
}

/* Test Set initial values (t = 0) and reference solution (t = 0.03 s):
   positions, velocities, multipliers (inside accessors, so that a file that
   includes this one without using them gets no unused-variable warning). */
static inline const double *andr_q0(void)
{
    static const double r[ANDR_N] = {
        -0.0617138900142764496358948458001, 0.0, 0.455279819163070380255912382449,
        0.222668390165885884674473185609,   0.487364979543842550225598953530,
        -0.222668390165885884674473185609,  1.23054744454982119249735015568};
    return r;
}
static inline const double *andr_qdd0(void)
{
    static const double r[ANDR_N] = {14222.4439199541138705911625887,
                                     -10666.8329399655854029433719415, 0.0, 0.0, 0.0, 0.0, 0.0};
    return r;
}
static inline const double *andr_lambda0(void)
{
    static const double r[ANDR_M] = {98.5668703962410896057654982170,
                                     -6.12268834425566265503114393122, 0.0, 0.0, 0.0, 0.0};
    return r;
}
static inline const double *andr_qref(void)
{
    static const double r[ANDR_N] = {0.1581077119629904e+2, -0.1575637105984298e+2,
                                     0.4082224013073101e-1, -0.5347301163226948e+0,
                                     0.5244099658805304e+0, 0.5347301163226948e+0,
                                     0.1048080741042263e+1};
    return r;
}
static inline const double *andr_vref(void)
{
    static const double r[ANDR_N] = {0.1139920302151208e+4, -0.1424379294994111e+4,
                                     0.1103291221937134e+2, 0.1929337464421385e+2,
                                     0.5735699284790808e+0, -0.1929337464421385e+2,
                                     0.3231791658026955e+0};
    return r;
}
static inline const double *andr_lambda_ref(void)
{
    static const double r[ANDR_M] = {0.1991753333731910e+3, -0.2975531228015052e+2,
                                     0.2306654119098399e+2, 0.3145271365475927e+2,
                                     0.2264249232082739e+2, 0.1161740700019673e+2};
    return r;
}

/* Sines and cosines of one configuration. */
typedef struct andr_trig {
    vlbe_real sbe, cbe, sth, cth, sga, cga, sph, cph, sde, cde, som, com, sep, cep;
    vlbe_real sbt, cbt, spd, cpd, soe, coe; /* of beta+Theta, Phi+delta, Omega+epsilon */
} andr_trig;

static inline void andr_trig_eval(const vlbe_real *q, andr_trig *c)
{
    c->sbe = vlbe_sin(q[0]);
    c->cbe = vlbe_cos(q[0]);
    c->sth = vlbe_sin(q[1]);
    c->cth = vlbe_cos(q[1]);
    c->sga = vlbe_sin(q[2]);
    c->cga = vlbe_cos(q[2]);
    c->sph = vlbe_sin(q[3]);
    c->cph = vlbe_cos(q[3]);
    c->sde = vlbe_sin(q[4]);
    c->cde = vlbe_cos(q[4]);
    c->som = vlbe_sin(q[5]);
    c->com = vlbe_cos(q[5]);
    c->sep = vlbe_sin(q[6]);
    c->cep = vlbe_cos(q[6]);
    c->sbt = vlbe_sin(q[0] + q[1]);
    c->cbt = vlbe_cos(q[0] + q[1]);
    c->spd = vlbe_sin(q[3] + q[4]);
    c->cpd = vlbe_cos(q[3] + q[4]);
    c->soe = vlbe_sin(q[5] + q[6]);
    c->coe = vlbe_cos(q[5] + q[6]);
}

static inline void andr_zero(int n, vlbe_real *x)
{
    int i;
    for (i = 0; i < n; ++i) x[i] = VLBE_R(0.0);
}

static inline int andr_mass(void *user, vlbe_real t, const vlbe_real *q, const vlbe_real *v, vlbe_real *M)
{
    const andr_par *p = (const andr_par *)user;
    vlbe_real cth = vlbe_cos(q[1]), sph = vlbe_sin(q[3]), som = vlbe_sin(q[5]);
    vlbe_real e4 = p->e - p->ea, z6 = p->zf - p->fa;
    int i, j;
    (void)t;
    (void)v;
    andr_zero(ANDR_N * ANDR_N, M);
    M[0 * 7 + 0] = p->m1 * p->ra * p->ra +
                   p->m2 * (p->rr * p->rr - VLBE_R(2.0) * p->da * p->rr * cth + p->da * p->da) +
                   p->i1 + p->i2;
    M[1 * 7 + 0] = p->m2 * (p->da * p->da - p->da * p->rr * cth) + p->i2;
    M[1 * 7 + 1] = p->m2 * p->da * p->da + p->i2;
    M[2 * 7 + 2] = p->m3 * (p->sa * p->sa + p->sb * p->sb) + p->i3;
    M[3 * 7 + 3] = p->m4 * e4 * e4 + p->i4;
    M[4 * 7 + 3] = p->m4 * (e4 * e4 + p->zt * e4 * sph) + p->i4;
    M[4 * 7 + 4] = p->m4 * (p->zt * p->zt + VLBE_R(2.0) * p->zt * e4 * sph + e4 * e4) +
                   p->m5 * (p->ta * p->ta + p->tb * p->tb) + p->i4 + p->i5;
    M[5 * 7 + 5] = p->m6 * z6 * z6 + p->i6;
    M[6 * 7 + 5] = p->m6 * (z6 * z6 - p->u * z6 * som) + p->i6;
    M[6 * 7 + 6] = p->m6 * (z6 * z6 - VLBE_R(2.0) * p->u * z6 * som + p->u * p->u) +
                   p->m7 * (p->ua * p->ua + p->ub * p->ub) + p->i6 + p->i7;
    for (i = 0; i < 7; ++i)
        for (j = i + 1; j < 7; ++j) M[i * 7 + j] = M[j * 7 + i];
    return 0;
}

/* Spring between C and D (D on body 3 at angle gamma): length L, its
   derivative S/L in gamma and the derivative S' of S = (D - C) . dD/dgamma. */
static inline void andr_spring(const andr_par *p, vlbe_real sga, vlbe_real cga, vlbe_real *L,
                        vlbe_real *S, vlbe_real *Sp)
{
    vlbe_real dx = p->sd * cga + p->sc * sga + p->xb - p->xc;
    vlbe_real dy = p->sd * sga - p->sc * cga + p->yb - p->yc;
    vlbe_real px = -p->sd * sga + p->sc * cga; /* d xd / d gamma */
    vlbe_real py = p->sd * cga + p->sc * sga;  /* d yd / d gamma */
    *L = vlbe_sqrt(dx * dx + dy * dy);
    *S = dx * px + dy * py;
    *Sp = px * px + py * py - dx * py + dy * px; /* px' = -py, py' = px */
}

static inline int andr_force(void *user, vlbe_real t, const vlbe_real *q, const vlbe_real *v, vlbe_real *f)
{
    const andr_par *p = (const andr_par *)user;
    vlbe_real sth = vlbe_sin(q[1]), sga = vlbe_sin(q[2]), cga = vlbe_cos(q[2]);
    vlbe_real cph = vlbe_cos(q[3]), com = vlbe_cos(q[5]);
    vlbe_real bep = v[0], thp = v[1], php = v[3], dep = v[4], omp = v[5], epp = v[6];
    vlbe_real k2 = p->m2 * p->da * p->rr, k4 = p->m4 * p->zt * (p->e - p->ea),
              k6 = p->m6 * p->u * (p->zf - p->fa);
    vlbe_real L, S, Sp;
    (void)t;
    andr_spring(p, sga, cga, &L, &S, &Sp);
    f[0] = p->mom - k2 * thp * (thp + VLBE_R(2.0) * bep) * sth;
    f[1] = k2 * bep * bep * sth;
    f[2] = -p->c0 * (L - p->l0) * S / L; /* = fx dxd/dgamma + fy dyd/dgamma */
    f[3] = k4 * dep * dep * cph;
    f[4] = -k4 * php * (php + VLBE_R(2.0) * dep) * cph;
    f[5] = -k6 * epp * epp * com;
    f[6] = k6 * omp * (omp + VLBE_R(2.0) * epp) * com;
    return 0;
}

/* K = df/dq, D = df/dq' */
static inline int andr_force_jac(void *user, vlbe_real t, const vlbe_real *q, const vlbe_real *v,
                          vlbe_real *K, vlbe_real *D)
{
    const andr_par *p = (const andr_par *)user;
    vlbe_real sth = vlbe_sin(q[1]), cth = vlbe_cos(q[1]), sga = vlbe_sin(q[2]),
              cga = vlbe_cos(q[2]), sph = vlbe_sin(q[3]), cph = vlbe_cos(q[3]),
              som = vlbe_sin(q[5]), com = vlbe_cos(q[5]);
    vlbe_real bep = v[0], thp = v[1], php = v[3], dep = v[4], omp = v[5], epp = v[6];
    vlbe_real k2 = p->m2 * p->da * p->rr, k4 = p->m4 * p->zt * (p->e - p->ea),
              k6 = p->m6 * p->u * (p->zf - p->fa);
    vlbe_real L, S, Sp, Lp;
    (void)t;
    andr_zero(49, K);
    andr_zero(49, D);
    andr_spring(p, sga, cga, &L, &S, &Sp);
    Lp = S / L;
    /* f3 = -c0 (L - l0) L',  L'' = S'/L - S^2/L^3 */
    K[2 * 7 + 2] = -p->c0 * (Lp * Lp + (L - p->l0) * (Sp / L - S * S / (L * L * L)));
    K[0 * 7 + 1] = -k2 * thp * (thp + VLBE_R(2.0) * bep) * cth;
    D[0 * 7 + 0] = -VLBE_R(2.0) * k2 * thp * sth;
    D[0 * 7 + 1] = -VLBE_R(2.0) * k2 * (thp + bep) * sth;
    K[1 * 7 + 1] = k2 * bep * bep * cth;
    D[1 * 7 + 0] = VLBE_R(2.0) * k2 * bep * sth;
    K[3 * 7 + 3] = -k4 * dep * dep * sph;
    D[3 * 7 + 4] = VLBE_R(2.0) * k4 * dep * cph;
    K[4 * 7 + 3] = k4 * php * (php + VLBE_R(2.0) * dep) * sph;
    D[4 * 7 + 3] = -VLBE_R(2.0) * k4 * (php + dep) * cph;
    D[4 * 7 + 4] = -VLBE_R(2.0) * k4 * php * cph;
    K[5 * 7 + 5] = k6 * epp * epp * som;
    D[5 * 7 + 6] = -VLBE_R(2.0) * k6 * epp * com;
    K[6 * 7 + 5] = -k6 * omp * (omp + VLBE_R(2.0) * epp) * som;
    D[6 * 7 + 5] = VLBE_R(2.0) * k6 * (omp + epp) * com;
    D[6 * 7 + 6] = VLBE_R(2.0) * k6 * omp * com;
    return 0;
}

/* Mq = d(M a)/dq (M depends on Theta, Phi, Omega only); Mv unused */
static inline int andr_mass_jac(void *user, vlbe_real t, const vlbe_real *q, const vlbe_real *v,
                         const vlbe_real *a, vlbe_real *Mq, vlbe_real *Mv)
{
    const andr_par *p = (const andr_par *)user;
    vlbe_real k2 = p->m2 * p->da * p->rr * vlbe_sin(q[1]);
    vlbe_real k4 = p->m4 * p->zt * (p->e - p->ea) * vlbe_cos(q[3]);
    vlbe_real k6 = -p->m6 * p->u * (p->zf - p->fa) * vlbe_cos(q[5]);
    (void)t;
    (void)v;
    (void)Mv;
    andr_zero(49, Mq);
    Mq[0 * 7 + 1] = VLBE_R(2.0) * k2 * a[0] + k2 * a[1]; /* dM11, dM21 / dTheta */
    Mq[1 * 7 + 1] = k2 * a[0];
    Mq[3 * 7 + 3] = k4 * a[4]; /* dM54 / dPhi */
    Mq[4 * 7 + 3] = k4 * a[3] + VLBE_R(2.0) * k4 * a[4];
    Mq[5 * 7 + 5] = k6 * a[6]; /* dM76 / dOmega */
    Mq[6 * 7 + 5] = k6 * a[5] + VLBE_R(2.0) * k6 * a[6];
    return 0;
}

static inline int andr_constr(void *user, vlbe_real t, const vlbe_real *q, vlbe_real *g)
{
    const andr_par *p = (const andr_par *)user;
    andr_trig c;
    vlbe_real x0, y0;
    (void)t;
    andr_trig_eval(q, &c);
    x0 = p->rr * c.cbe - p->d * c.cbt; /* the joint common to the three loops */
    y0 = p->rr * c.sbe - p->d * c.sbt;
    g[0] = x0 - p->ss * c.sga - p->xb;
    g[1] = y0 + p->ss * c.cga - p->yb;
    g[2] = x0 - p->e * c.spd - p->zt * c.cde - p->xa;
    g[3] = y0 + p->e * c.cpd - p->zt * c.sde - p->ya;
    g[4] = x0 - p->zf * c.coe - p->u * c.sep - p->xa;
    g[5] = y0 - p->zf * c.soe + p->u * c.cep - p->ya;
    return 0;
}

static inline int andr_constr_jac(void *user, vlbe_real t, const vlbe_real *q, vlbe_real *G, vlbe_real *Ct)
{
    const andr_par *p = (const andr_par *)user;
    andr_trig c;
    int k;
    (void)t;
    andr_trig_eval(q, &c);
    andr_zero(42, G);
    for (k = 0; k < 3; ++k) {
        G[(2 * k) * 7 + 0] = -p->rr * c.sbe + p->d * c.sbt;
        G[(2 * k) * 7 + 1] = p->d * c.sbt;
        G[(2 * k + 1) * 7 + 0] = p->rr * c.cbe - p->d * c.cbt;
        G[(2 * k + 1) * 7 + 1] = -p->d * c.cbt;
    }
    G[0 * 7 + 2] = -p->ss * c.cga;
    G[1 * 7 + 2] = -p->ss * c.sga;
    G[2 * 7 + 3] = -p->e * c.cpd;
    G[2 * 7 + 4] = -p->e * c.cpd + p->zt * c.sde;
    G[3 * 7 + 3] = -p->e * c.spd;
    G[3 * 7 + 4] = -p->e * c.spd - p->zt * c.cde;
    G[4 * 7 + 5] = p->zf * c.soe;
    G[4 * 7 + 6] = p->zf * c.soe - p->u * c.cep;
    G[5 * 7 + 5] = -p->zf * c.coe;
    G[5 * 7 + 6] = -p->zf * c.coe - p->u * c.sep;
    if (Ct) andr_zero(6, Ct);
    return 0;
}

/* gamma_k = -v^T (d^2 g_k / dq^2) v */
static inline int andr_constr_acc(void *user, vlbe_real t, const vlbe_real *q, const vlbe_real *v,
                           vlbe_real *gam)
{
    const andr_par *p = (const andr_par *)user;
    andr_trig c;
    vlbe_real b2 = v[0] * v[0], bt2 = (v[0] + v[1]) * (v[0] + v[1]), g2 = v[2] * v[2],
              pd2 = (v[3] + v[4]) * (v[3] + v[4]), d2 = v[4] * v[4],
              oe2 = (v[5] + v[6]) * (v[5] + v[6]), e2 = v[6] * v[6];
    vlbe_real cx, cy;
    (void)t;
    andr_trig_eval(q, &c);
    cx = -p->rr * c.cbe * b2 + p->d * c.cbt * bt2;
    cy = -p->rr * c.sbe * b2 + p->d * c.sbt * bt2;
    gam[0] = -(cx + p->ss * c.sga * g2);
    gam[1] = -(cy - p->ss * c.cga * g2);
    gam[2] = -(cx + p->e * c.spd * pd2 + p->zt * c.cde * d2);
    gam[3] = -(cy - p->e * c.cpd * pd2 + p->zt * c.sde * d2);
    gam[4] = -(cx + p->zf * c.coe * oe2 + p->u * c.sep * e2);
    gam[5] = -(cy + p->zf * c.soe * oe2 - p->u * c.cep * e2);
    return 0;
}

/* H = d(G^T lambda)/dq = sum_k lambda_k d^2 g_k / dq^2 */
static inline int andr_constr_hess(void *user, vlbe_real t, const vlbe_real *q, const vlbe_real *l,
                            vlbe_real *H)
{
    const andr_par *p = (const andr_par *)user;
    andr_trig c;
    vlbe_real a = l[0] + l[2] + l[4], b = l[1] + l[3] + l[5], x;
    (void)t;
    andr_trig_eval(q, &c);
    andr_zero(49, H);
    x = p->d * (a * c.cbt + b * c.sbt);
    H[0 * 7 + 0] = x - p->rr * (a * c.cbe + b * c.sbe);
    H[0 * 7 + 1] = H[1 * 7 + 0] = H[1 * 7 + 1] = x;
    H[2 * 7 + 2] = p->ss * (l[0] * c.sga - l[1] * c.cga);
    x = p->e * (l[2] * c.spd - l[3] * c.cpd);
    H[3 * 7 + 3] = H[3 * 7 + 4] = H[4 * 7 + 3] = x;
    H[4 * 7 + 4] = x + p->zt * (l[2] * c.cde + l[3] * c.sde);
    x = p->zf * (l[4] * c.coe + l[5] * c.soe);
    H[5 * 7 + 5] = H[5 * 7 + 6] = H[6 * 7 + 5] = x;
    H[6 * 7 + 6] = x + p->u * (l[4] * c.sep - l[5] * c.cep);
    return 0;
}

/* Fills sys (p must outlive it) with the analytic Jacobians. */
static inline void andr_setup(vlbe_dae *sys, andr_par *p)
{
    vlbe_dae z = {0};
    *sys = z;
    sys->n = ANDR_N;
    sys->m = ANDR_M;
    sys->flags = 0u; /* M depends on q (not on v) */
    sys->user = p;
    sys->mass = andr_mass;
    sys->force = andr_force;
    sys->constr = andr_constr;
    sys->constr_jac = andr_constr_jac;
    sys->constr_acc = andr_constr_acc;
    sys->force_jac = andr_force_jac;
    sys->mass_jac = andr_mass_jac;
    sys->constr_hess = andr_constr_hess;
}

/* The same problem with every optional Jacobian left to finite differences. */
static inline void andr_setup_fd(vlbe_dae *sys, andr_par *p)
{
    andr_setup(sys, p);
    sys->constr_acc = NULL;
    sys->force_jac = NULL;
    sys->mass_jac = NULL;
    sys->constr_hess = NULL;
}

static inline void andr_initial(vlbe_real q0[ANDR_N], vlbe_real v0[ANDR_N])
{
    int i;
    for (i = 0; i < ANDR_N; ++i) {
        q0[i] = (vlbe_real)andr_q0()[i];
        v0[i] = VLBE_R(0.0);
    }
}

/* -- one run -------------------------------------------------------------- */
typedef struct andr_result {
    vlbe_status status;
    double q[ANDR_N], v[ANDR_N], lambda[ANDR_M]; /* at t_end             */
    double rel_err[ANDR_N];    /* |q_i - ref_i| / |ref_i|                     */
    double max_rel_err;        /* max over the 7 positions                    */
    double max_c;              /* max |g| over the run [m]                    */
    double cpu;                /* seconds                                     */
    vlbe_dae_stats stats;
} andr_result;

static inline void andr_result_reset(andr_result *res)
{
    vlbe_dae_stats zero_stats = {0};
    res->status = VLBE_OK;
    res->stats = zero_stats;
    res->max_rel_err = NAN;
    res->max_c = 0.0;
    res->cpu = 0.0;
}

/* Observer of a run: largest |g_i| of the constraints into res->max_c. */
typedef struct andr_obs {
    const vlbe_dae *sys;
    andr_result *res;
} andr_obs;

static inline vlbe_status andr_obs_step(void *ctx, double t, const vlbe_real *q,
                                        const vlbe_real *v, const vlbe_real *lambda)
{
    andr_obs *o = (andr_obs *)ctx;
    vlbe_real g[ANDR_M];
    int i;
    (void)v, (void)lambda;
    o->sys->constr(o->sys->user, (vlbe_real)t, q, g);
    for (i = 0; i < ANDR_M; ++i)
        if (fabs((double)g[i]) > o->res->max_c) o->res->max_c = fabs((double)g[i]);
    return VLBE_OK;
}

/* Runs method m on sys from the Test Set start to t = 0.03 s and compares
   the end state with the reference. */
static inline vlbe_status andr_run_method(const vlbe_dae *sys, const ex_method *m, andr_result *res)
{
    andr_obs o;
    ex_run_out out;
    vlbe_real q0[ANDR_N], v0[ANDR_N], q[ANDR_N], v[ANDR_N], lam[ANDR_M];
    int i;
    o.sys = sys;
    o.res = res;
    andr_result_reset(res);
    andr_initial(q0, v0);
    ex_run(sys, m, q0, v0, ANDR_T_END, andr_obs_step, &o, q, v, lam, &out);
    res->cpu = out.cpu;
    res->stats = out.stats;
    res->status = out.status;
    if (out.status != VLBE_OK) return out.status;
    res->max_rel_err = 0.0;
    for (i = 0; i < ANDR_N; ++i) {
        res->q[i] = (double)q[i];
        res->v[i] = (double)v[i];
        res->rel_err[i] = fabs(res->q[i] - andr_qref()[i]) / fabs(andr_qref()[i]);
        if (res->rel_err[i] > res->max_rel_err) res->max_rel_err = res->rel_err[i];
    }
    for (i = 0; i < ANDR_M; ++i) res->lambda[i] = (double)lam[i];
    return VLBE_OK;
}

/* Fixed step 0.03 / nsteps of the generalized-alpha scheme par. */
static inline vlbe_status andr_run_sys(const vlbe_dae *sys, const vlbe_hht_params *par, long nsteps,
                                       andr_result *res)
{
    ex_method m = {0};
    m.hht = par;
    m.h = ANDR_T_END / (double)nsteps;
    return andr_run_method(sys, &m, res);
}

static inline vlbe_status andr_run(const vlbe_hht_params *par, long nsteps, andr_result *res)
{
    andr_par p = andr_default();
    vlbe_dae sys;
    andr_setup(&sys, &p);
    return andr_run_sys(&sys, par, nsteps, res);
}

/* The same with the variable-step, variable-order BDF (GGL index-2 form) at
   tolerance rtol = atol, analytic Jacobians; it lands exactly on t = 0.03 s. */
static inline vlbe_status andr_run_bdf(double rtol, andr_result *res)
{
    andr_par p = andr_default();
    vlbe_dae sys;
    vlbe_bdf_params par;
    ex_method m = {0};
    andr_setup(&sys, &p);
    vlbe_bdf_params_default(&par);
    par.rtol = par.atol = (vlbe_real)rtol;
    m.bdf = &par;
    return andr_run_method(&sys, &m, res);
}

/* Integrator parameters used for this problem: 0 HHT-alpha (alpha = -0.05),
   1 generalized-alpha (rho_inf = 0.8), 2 trapezoidal Newmark; Newton
   tolerances tightened to rtol 1e-12, atol 1e-14 (double only): with the
   defaults the Newton errors of 1e4..1e5 steps add up to about 1e-6. */
static inline void andr_params_for(int method, vlbe_hht_params *par)
{
    if (method == 0) vlbe_hht_params_alpha(par, VLBE_R(-0.05));
    else if (method == 1) vlbe_hht_params_genalpha(par, VLBE_R(0.8));
    else vlbe_hht_params_newmark(par, VLBE_R(0.25), VLBE_R(0.5));
#ifndef VLBE_USE_FLOAT
    par->rtol = VLBE_R(1e-12);
    par->atol = VLBE_R(1e-14);
#endif
}

#endif /* VLBE_SCENE_ANDREWS_H */
