/* vonmises_truss.h -- the von Mises truss, the static solver's limit-point
   problem: the model (vm_setup, vm_force, vm_force_jac, the height
   constraint vm_constr, vm_constr_jac), its equilibrium load lambda(w) and
   the upper limit load (vm_lambda, vm_limit_load).  Shared by
   tests/test_static.c and bench/bench_static.c.
   -- part of vlbe                                  SPDX-License-Identifier: MIT

   Anchors (-b, 0), (b, 0), apex (x, y), two bars of axial stiffness EA and
   length L0 = sqrt(b^2 + h0^2); N = EA (l - L0)/L0 (tension > 0); the bar
   pulls the apex with -N e/l, e = apex - anchor, and a dead load P acts
   downward on it.  The constraint C = y - w holds the apex at the height
   w (displacement control); the x coordinate is free (x = 0 by symmetry).
   Equilibrium at height w, x = 0: the load lambda(w) = -2 EA (l - L0)/L0
   w/l, l = sqrt(b^2 + w^2), which rises to the upper limit point, falls
   through 0 at w = 0 and reaches the lower limit point. */
#ifndef VLBE_SCENE_VONMISES_TRUSS_H
#define VLBE_SCENE_VONMISES_TRUSS_H

#include "../integrators.h"

#include <math.h>

typedef struct vm_truss {
    double b, h0, EA; /* m, m, N */
    vlbe_real w;      /* prescribed height (vm_constr) */
    double P;         /* dead load on the apex, downward [N] */
} vm_truss;

/* bar i (0: left anchor, 1: right): e = apex - anchor, its length l and
   axial force N */
static inline void vm_bar(const vm_truss *tr, const vlbe_real *q, int i, vlbe_real e[2],
                          vlbe_real *l, vlbe_real *N)
{
    vlbe_real b = (vlbe_real)tr->b, L0 = (vlbe_real)sqrt(tr->b * tr->b + tr->h0 * tr->h0);
    e[0] = q[0] - (i == 0 ? -b : b);
    e[1] = q[1];
    *l = vlbe_sqrt(e[0] * e[0] + e[1] * e[1]);
    *N = (vlbe_real)tr->EA * (*l - L0) / L0;
}

static inline int vm_force(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v,
                           vlbe_real *Q)
{
    const vm_truss *tr = (const vm_truss *)u;
    int i;
    (void)t;
    (void)v;
    Q[0] = Q[1] = VLBE_R(0.0);
    for (i = 0; i < 2; ++i) {
        vlbe_real e[2], l, N;
        vm_bar(tr, q, i, e, &l, &N);
        Q[0] -= N * e[0] / l;
        Q[1] -= N * e[1] / l;
    }
    Q[1] -= (vlbe_real)tr->P;
    return 0;
}

/* K = dQ/dq = -sum (EA/L0) n n^T + (N/l) (I - n n^T), n = e/l; D = 0 */
static inline int vm_force_jac(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v,
                               vlbe_real *K, vlbe_real *D)
{
    const vm_truss *tr = (const vm_truss *)u;
    vlbe_real L0 = (vlbe_real)sqrt(tr->b * tr->b + tr->h0 * tr->h0);
    int i, r, c;
    (void)t;
    (void)v;
    for (i = 0; i < 4; ++i) K[i] = D[i] = VLBE_R(0.0);
    for (i = 0; i < 2; ++i) {
        vlbe_real e[2], l, N, n[2];
        vm_bar(tr, q, i, e, &l, &N);
        n[0] = e[0] / l;
        n[1] = e[1] / l;
        for (r = 0; r < 2; ++r)
            for (c = 0; c < 2; ++c)
                K[r * 2 + c] -= (vlbe_real)tr->EA / L0 * n[r] * n[c] +
                                N / l * ((r == c ? VLBE_R(1.0) : VLBE_R(0.0)) - n[r] * n[c]);
    }
    return 0;
}

static inline int vm_constr(void *u, vlbe_real t, const vlbe_real *q, vlbe_real *C)
{
    (void)t;
    C[0] = q[1] - ((const vm_truss *)u)->w;
    return 0;
}

static inline int vm_constr_jac(void *u, vlbe_real t, const vlbe_real *q, vlbe_real *Cq,
                                vlbe_real *Ct)
{
    (void)u;
    (void)t;
    (void)q;
    Cq[0] = VLBE_R(0.0);
    Cq[1] = VLBE_R(1.0);
    if (Ct) Ct[0] = VLBE_R(0.0);
    return 0;
}

/* b = 1 m, h0 = 0.2 m, EA = 1e6 N, no dead load; the apex held at w = h0
   (constrained = 1) or free under the dead load P (constrained = 0) */
static inline void vm_setup(vlbe_dae *sys, vm_truss *tr, int constrained)
{
    vlbe_dae z = {0};
    tr->b = 1.0;
    tr->h0 = 0.2;
    tr->EA = 1e6;
    tr->w = (vlbe_real)tr->h0;
    tr->P = 0.0;
    *sys = z;
    sys->n = 2;
    sys->user = tr;
    sys->force = vm_force;
    sys->force_jac = vm_force_jac;
    if (constrained) {
        sys->m = 1;
        sys->flags = VLBE_DAE_NO_CHESS; /* C is linear */
        sys->constr = vm_constr;
        sys->constr_jac = vm_constr_jac;
    }
}

/* the load (downward, N) that holds the apex at height w: lambda(w) */
static inline double vm_lambda(const vm_truss *tr, double w)
{
    double L0 = sqrt(tr->b * tr->b + tr->h0 * tr->h0), l = sqrt(tr->b * tr->b + w * w);
    return -2.0 * tr->EA * (l - L0) / L0 * w / l;
}

/* the upper limit load: the largest lambda(w), w in [0, h0], on a grid of
   20001 heights */
static inline double vm_limit_load(const vm_truss *tr)
{
    double plim = 0.0;
    int k;
    for (k = 0; k <= 20000; ++k) plim = fmax(plim, vm_lambda(tr, tr->h0 * k / 20000.0));
    return plim;
}

#endif /* VLBE_SCENE_VONMISES_TRUSS_H */
