/* ex_winch.h -- a winch paying out a rope with an end mass under gravity:
   the model and the run loop of examples/winch.c and its test
   (tests/test_scenes_cable.c).                    -- part of vlbe
                                                   SPDX-License-Identifier: MIT

   The rope: N0 = L0 / Lstd planar ALE-ANCF cable elements (ancf_ale.h, no
   bending: VLBE_ALE_NO_BEND), mass per length rhoA, axial stiffness EA,
   gravity g, an end mass m at its last node.  Material coordinate p along
   the rope, the end mass at p = L0 for ever; node 0 sits at the winch, held
   at the origin (VLBE_ALE_CON_POS), and its material coordinate is
   prescribed, p0(t) = -V t: unstretched rope leaves the winch at V per
   second, and element 0, between the winch node and the first material
   node, is an ALE element that grows as it goes.  Every other node is
   Lagrangian (fixed p).  Length control at the winch: after each step, when
   element 0 is longer than 1.5 Lstd it is split (vlbe_ale_chain_insert,
   exact segmentation: the curve, the strains and the energy do not change)
   at Lstd from its far end, so the new material node starts a standard
   element and element 0 restarts at 0.5 Lstd; the integrator restarts from
   the mapped state.  (vlbe_ale_chain_length_control keeps the two elements
   of an interior sliding node between 0.5 and 1.5 Lstd, trading a node for
   a node; at a chain end, where rope is only added, the split is all there
   is to do.)  Hence, with the paid-out length d = V t, the number of
   elements is exactly
        ne(t) = N0 + floor(d / Lstd + 1/2)
   (element 0 reaches 1.5 Lstd at d = (k - 1/2) Lstd, k = 1, 2, ...), up to
   the step at which a split falls due.

   The independent facts checked along the run:
   - the end mass against the steady rope.  The rope below material point
     p is the same material whatever has been paid out, so its tension
     T(p), and the stretch lam(p) of the Green-strain law, EA (lam^2 - 1)
     lam / 2 = T (ex_cable_stretch), are fixed functions of p, and every
     material point moves with the rope leaving the winch, at v_qs =
     -lam(p0(t)) V.  That speed grows slowly (lam(p0) with the weight
     hanging below the winch): every point accelerates at the same
     -d lam(p0)/dt V = -rhoA g V^2 / EA (to first order in the strain), so
     T(p) = (m + rhoA (L0 - p)) g_eff, the weight below p under
        g_eff = g (1 - rhoA V^2 / EA)     (V^2 / c^2, c the axial wave speed).
     The steady rope with that tension hangs its end at
        y_qs(t) = -int_{p0(t)}^{L0} lam(p) dp ~ -(L0 + V t) - (g_eff / EA)
        (m l + rhoA l^2 / 2),   l = L0 + V t.
     The run starts on it (cfg.steady: the discrete static equilibrium
     under g_eff with the winch node's p held, then those velocities), so
     what separates the end from y_qs is the transient the discretisation
     and the splits leave.  From the static rope under g instead (steady =
     0) the end oscillates about y_qs by the dynamic stretch (rhoA V^2 /
     EA) times the stretch, the axial mode the start excites;
   - the energy balance of the hanging rope, a control volume whose top is
     the winch exit: d(T + U + V)/dt = V (rhoA |v0|^2 / 2 + u0) - T0 |v0|
     (the kinetic and strain energy carried in by the rope, u0 = EA eps0^2
     / 2 per unit material length, and the work of the winch holding the
     tension T0 = EA eps0 lam0 back against the material speed |v0| = lam0
     V at its exit; the rope enters at y = 0, with no potential energy),
     integrated by the trapezoidal rule over the steps from the model's
     state at the winch (strain eps0 and stretch lam0 of element 0 at
     p0(t)).  Its error is the integrator's dissipation (HHT-alpha) and the
     quadrature's;
   - the mass: sum over the elements of the translation mass u^T M_e u
     (vlbe_ale_mass; Hermite partition of unity: rhoA times the element's
     material length) plus m, against m + rhoA (L0 + V t);
   - the number of elements against ne(t) above.

   Storage: cfg.banded goes to ex_cable_wire (scenes/ex_cable.h). */
#ifndef VLBE_EX_WINCH_H
#define VLBE_EX_WINCH_H

#include "ex_cable.h"

typedef struct ex_winch_cfg {
    double L0, Lstd, V;    /* initial hanging length, element length [m], pay-out [m/s] */
    double g, rhoA, EA;    /* gravity, mass per length, axial stiffness      */
    double mass;           /* end mass [kg]                                  */
    double h, alpha, t_end; /* HHT-alpha step, alpha, end time [s]           */
    int nmax;              /* elements, at most (capacity)                   */
    int steady;            /* 1: start on the steady rope (g_eff), 0: on the
                              static one (g): the end then oscillates about
                              the steady state by the dynamic stretch        */
    int banded;            /* ex_cable_wire                                  */
} ex_winch_cfg;

/* nmax for the length paid out by t_end (after changing L0, Lstd, V or
   t_end) */
static inline void ex_winch_cfg_capacity(ex_winch_cfg *c)
{
    c->nmax = (int)ceil((c->L0 + c->V * c->t_end) / c->Lstd) + 2;
}

/* The scene of examples/winch.c: 10 m of rope (1 kg/m, EA = 1e6 N) with
   a 10 kg end mass hanging from the winch, elements of 0.5 m, paid out at
   0.9 m/s for t_end seconds; HHT-alpha -0.05, h = 2 ms. */
static inline void ex_winch_cfg_default(ex_winch_cfg *c, double t_end)
{
    memset(c, 0, sizeof *c);
    c->L0 = 10.0;
    c->Lstd = 0.5;
    c->V = 0.9;
    c->g = 9.81;
    c->rhoA = 1.0;
    c->EA = 1e6;
    c->mass = 10.0;
    c->h = 2e-3;
    c->alpha = -0.05;
    c->t_end = t_end;
    c->steady = 1;
    ex_winch_cfg_capacity(c);
}

/* ne(t) of the header comment: the elements after a paid-out length d */
static inline int ex_winch_ne(const ex_winch_cfg *c, double d)
{
    return (int)floor(c->L0 / c->Lstd + 0.5) + (int)floor(d / c->Lstd + 0.5);
}

/* the effective gravity of the steady pay-out, g (1 - rhoA V^2 / EA): the
   weight less the force that gives the rope its (uniform) acceleration */
static inline double ex_winch_geff(const ex_winch_cfg *c)
{
    return c->g * (1.0 - c->rhoA * c->V * c->V / c->EA);
}

/* stretch at material coordinate p (ctx: the cfg) */
static inline double ex_winch__lam_at(const void *ctx, double p)
{
    const ex_winch_cfg *c = (const ex_winch_cfg *)ctx;
    return ex_cable_stretch(c->EA, (c->mass + c->rhoA * (c->L0 - p)) * ex_winch_geff(c));
}

/* The quasi-static end position y_qs and velocity v_qs at time t. */
static inline void ex_winch_qs(const ex_winch_cfg *c, double t, double *y, double *v)
{
    const double p0 = -c->V * t;
    *y = -ex_cable_quad(ex_winch__lam_at, c, p0, c->L0, 8);
    *v = -ex_winch__lam_at(c, p0) * c->V;
}

typedef struct ex_winch {
    ex_winch_cfg cfg;
    vlbe_ale_mat mat;
    vlbe_ale_elem el;
    vlbe_ale_node *node; /* nmax + 1, malloc'ed */
    int *order;          /* banded: the augmented order, malloc'ed */
    vlbe_ale_con con[1];
    vlbe_ale_chain ch;
    vlbe_dae sys;
} ex_winch;

/* One row per accepted step (and t = 0). */
typedef struct ex_winch_hist {
    int n, cap;
    double *t, *ne, *ne_pred, *y, *y_qs, *v, *v_qs, *dE, *mass;
} ex_winch_hist;

typedef struct ex_winch_out {
    vlbe_status status;
    double t_stop;
    int ne0, ne_end, splits;
    int ne_bad;          /* steps whose element count is not ne(t) (outside the
                            step a split falls due in)                       */
    long steps, newton, lu;
    double dy_max, dv_max; /* largest |y - y_qs| [m], |v - v_qs| [m/s]      */
    double stretch_end;  /* y_qs + (L0 + V t) at the end: minus the stretch [m] */
    double dE_max;       /* largest |E - E0 - W| [J]                         */
    double W_abs;        /* int |work rate of the winch| dt [J]              */
    double dm_max;       /* largest |mass - (m + rhoA (L0 + V t))| [kg]      */
    double cpu, cpu_split; /* seconds: all; the splits and restarts          */
} ex_winch_out;

static inline int ex_winch_hist_alloc(ex_winch_hist *hi, int cap)
{
    double **col[9];
    int k;
    memset(hi, 0, sizeof *hi);
    hi->t = (double *)malloc((size_t)(9 * cap) * sizeof *hi->t);
    if (!hi->t) return -1;
    hi->cap = cap;
    col[0] = &hi->t;
    col[1] = &hi->ne;
    col[2] = &hi->ne_pred;
    col[3] = &hi->y;
    col[4] = &hi->y_qs;
    col[5] = &hi->v;
    col[6] = &hi->v_qs;
    col[7] = &hi->dE;
    col[8] = &hi->mass;
    for (k = 1; k < 9; ++k) *col[k] = hi->t + (size_t)k * (size_t)cap;
    return 0;
}

static inline void ex_winch_hist_free(ex_winch_hist *hi)
{
    free(hi->t);
    memset(hi, 0, sizeof *hi);
}

static inline void ex_winch_free(ex_winch *m)
{
    free(m->node);
    free(m->order);
    m->node = NULL;
    m->order = NULL;
}

/* The chain at rest in its discrete static equilibrium (the winch node's p
   held at 0 for the solve), then set moving: node 0's p prescribed at -V t,
   the material nodes at v_qs(0), the slope of node 0 at its material rate.
   q, v: 4 (nmax + 1) reals.  0 on success. */
static inline int ex_winch_build(ex_winch *m, const ex_winch_cfg *c, vlbe_real *q, vlbe_real *v)
{
    const int N0 = (int)floor(c->L0 / c->Lstd + 0.5);
    const double g0 = c->steady ? ex_winch_geff(c) : c->g;
    vlbe_ale_con k;
    double y = 0.0;
    int i;
    memset(m, 0, sizeof *m);
    if (N0 < 1 || c->nmax < N0 || fabs(N0 * c->Lstd - c->L0) > 1e-12 * c->L0 || !(c->EA > 0.0))
        return -1;
    m->cfg = *c;
    m->mat.rhoA = (vlbe_real)c->rhoA;
    m->mat.EA = (vlbe_real)c->EA;
    m->mat.f[1] = (vlbe_real)(-g0 * c->rhoA); /* the start's gravity, below */
    if (vlbe_ale_elem_init(&m->el, &m->mat, VLBE_ALE_NO_BEND | VLBE_ALE_NO_DAMP, 0, 0, 0))
        return -1;
    m->node = (vlbe_ale_node *)calloc((size_t)c->nmax + 1, sizeof *m->node);
    if (!m->node) return -1;
    for (i = 0; i <= N0; ++i) {
        m->node[i].pmode = i == 0 ? VLBE_ALE_PPRESCRIBED : VLBE_ALE_PFIXED;
        m->node[i].p = (vlbe_real)(c->Lstd * i);
    }
    m->node[N0].mass = (vlbe_real)c->mass;
    if (vlbe_ale_chain_init(&m->ch, &m->el, m->node, N0 + 1, c->nmax + 1, m->con, 1)) goto fail;
    m->ch.g[1] = (vlbe_real)-g0;
    memset(&k, 0, sizeof k);
    k.type = VLBE_ALE_CON_POS; /* the winch at the origin */
    if (c->banded) { /* n + m <= 4 (nmax + 1) + 2, + 4 for an insertion */
        const int cap = 4 * (c->nmax + 1) + 6;
        m->order = (int *)malloc((size_t)cap * sizeof *m->order);
        if (!m->order || vlbe_ale_chain_band(&m->ch, m->order, cap)) goto fail;
    }
    if (vlbe_ale_chain_add(&m->ch, &k) || vlbe_ale_chain_layout(&m->ch) ||
        ex_cable_wire(&m->sys, &m->ch, c->banded))
        goto fail;
    for (i = 0; i <= N0; ++i) { /* the quasi-static start, refined below */
        vlbe_real *x = q + m->node[i].ofs;
        const double p = (double)m->node[i].p;
        if (i > 0) y -= ex_cable_quad(ex_winch__lam_at, c, (double)m->node[i - 1].p, p, 1);
        x[0] = x[2] = VLBE_R(0.0);
        x[1] = (vlbe_real)y;
        x[3] = (vlbe_real)-ex_winch__lam_at(c, p);
    }
    if (ex_cable_solve_static(&m->sys, q) != VLBE_OK) goto fail;
    m->node[0].pd = (vlbe_real)-c->V;
    m->mat.f[1] = (vlbe_real)(-c->g * c->rhoA); /* the true gravity from here on */
    if (vlbe_ale_elem_init(&m->el, &m->mat, VLBE_ALE_NO_BEND | VLBE_ALE_NO_DAMP, 0, 0, 0))
        goto fail;
    m->ch.g[1] = (vlbe_real)-c->g;
    for (i = 0; i < m->ch.n; ++i) v[i] = VLBE_R(0.0);
    {
        /* lam'(p) = dlam/dT dT/dp = -rhoA g / (EA (3 lam^2 - 1) / 2) */
        const double lam0 = ex_winch__lam_at(c, 0.0);
        const double dlam = -c->rhoA * c->g / (0.5 * c->EA * (3.0 * lam0 * lam0 - 1.0));
        v[m->node[0].ofs + 3] = (vlbe_real)(dlam * c->V); /* d/dt (-lam(p0)) = -lam' p0' */
        for (i = 1; i <= N0; ++i) v[m->node[i].ofs + 1] = (vlbe_real)(-lam0 * c->V);
    }
    return 0;
fail:
    ex_winch_free(m);
    return -1;
}

/* the rope's translation mass plus the point masses, from the element mass
   matrices (x-translation: rows and columns x1, x2 of each element) */
static inline double ex_winch_mass(const ex_winch *m, vlbe_real t, const vlbe_real *q)
{
    double s = 0.0;
    int e, i;
    for (e = 0; e + 1 < m->ch.nn; ++e) {
        vlbe_real qe[10], Me[100];
        int idx[10];
        unsigned md;
        if (vlbe_ale_chain_gather(&m->ch, e, t, q, NULL, qe, NULL, idx, &md) ||
            vlbe_ale_mass(&m->el, md, qe, Me))
            return (double)NAN;
        s += (double)(Me[0] + Me[5] + Me[50] + Me[55]);
    }
    for (i = 0; i < m->ch.nn; ++i) s += (double)m->node[i].mass;
    return s;
}

/* the energy inflow rate at the winch (header comment) from the state */
static inline double ex_winch_inflow(const ex_winch *m, vlbe_real t, const vlbe_real *q,
                                     const vlbe_real *v)
{
    vlbe_real qe[10], ve[10], r[2], rp[2], eps, kap;
    int idx[10];
    unsigned md;
    double lam, EA = m->cfg.EA, V = m->cfg.V;
    if (vlbe_ale_chain_gather(&m->ch, 0, t, q, v, qe, ve, idx, &md) ||
        vlbe_ale_point(qe, qe[4], r, rp) || vlbe_ale_strain(qe, qe[4], &eps, &kap))
        return (double)NAN;
    lam = hypot((double)rp[0], (double)rp[1]);
    return V * (0.5 * m->cfg.rhoA * lam * lam * V * V + 0.5 * EA * (double)eps * (double)eps) -
           EA * (double)eps * lam * lam * V;
}

static inline double ex_winch_energy(ex_winch *m, vlbe_real t, const vlbe_real *q,
                                     const vlbe_real *v)
{
    vlbe_real E[3];
    if (vlbe_ale_chain_energy(&m->ch, t, q, v, E)) return (double)NAN;
    return (double)E[0] + (double)E[1] + (double)E[2];
}

/* The run of the header comment; hist may be NULL. */
static inline ex_winch_out ex_winch_run(const ex_winch_cfg *c, ex_winch_hist *hist)
{
    ex_winch_out r;
    ex_winch *m = (ex_winch *)malloc(sizeof *m);
    const int nq = 4 * (c->nmax + 2);
    vlbe_real *q = (vlbe_real *)malloc((size_t)(4 * nq) * sizeof *q);
    vlbe_real *v = q ? q + nq : NULL, *qn = q ? q + 2 * nq : NULL, *vn = q ? q + 3 * nq : NULL;
    vlbe_real *w = NULL;
    int *iw = NULL;
    size_t lw = 0, liw = 0;
    vlbe_hht_params par;
    vlbe_hht st;
    const long nsteps = (long)floor(c->t_end / c->h + 0.5);
    double E0 = 0.0, W = 0.0, P_prev = 0.0;
    clock_t c0 = clock();
    long k;
    memset(&r, 0, sizeof r);
    memset(&st, 0, sizeof st);
    r.status = VLBE_EWORK;
    if (!m || !q || ex_winch_build(m, c, q, v)) goto done;
    { /* the workspace of the largest chain of the run */
        vlbe_dae big = m->sys;
        big.n = 4 * (c->nmax + 1);
        ex_cable_hht_work(&big, &lw, &liw);
    }
    w = (vlbe_real *)malloc(lw * sizeof *w);
    iw = (int *)malloc(liw * sizeof *iw);
    if (!w || !iw) goto done;
    r.ne0 = m->ch.nn - 1;
    if ((r.status = vlbe_hht_params_alpha(&par, (vlbe_real)c->alpha)) != VLBE_OK) goto done;
    r.status = vlbe_hht_init(&st, &m->sys, &par, VLBE_R(0.0), q, v, w, lw, iw, liw);
    E0 = ex_winch_energy(m, VLBE_R(0.0), q, v);
    P_prev = ex_winch_inflow(m, VLBE_R(0.0), q, v);
    for (k = 0; r.status == VLBE_OK && k <= nsteps; ++k) {
        const double t = (double)st.t, d = c->V * t, len = c->L0 + d;
        double yqs, vqs, E, P, mass, dE;
        const int ie = m->node[m->ch.nn - 1].ofs, ne = m->ch.nn - 1, pred = ex_winch_ne(c, d);
        if (k > 0) {
            P = ex_winch_inflow(m, st.t, st.q, st.v);
            W += 0.5 * c->h * (P + P_prev);
            r.W_abs += 0.5 * c->h * (fabs(P) + fabs(P_prev));
            P_prev = P;
        }
        ex_winch_qs(c, t, &yqs, &vqs);
        E = ex_winch_energy(m, st.t, st.q, st.v);
        mass = ex_winch_mass(m, st.t, st.q);
        dE = E - E0 - W;
        r.dy_max = fmax(r.dy_max, fabs((double)st.q[ie + 1] - yqs));
        r.dv_max = fmax(r.dv_max, fabs((double)st.v[ie + 1] - vqs));
        r.dE_max = fmax(r.dE_max, fabs(dE));
        r.dm_max = fmax(r.dm_max, fabs(mass - (c->mass + c->rhoA * len)));
        if (ne != pred) { /* tolerated only in the step a split falls due */
            const double f = d / c->Lstd + 0.5;
            if (fabs(f - floor(f + 0.5)) > c->V * c->h / c->Lstd) r.ne_bad++;
        }
        if (!(fabs(dE) <= 1e300) || !(mass == mass)) {
            r.status = VLBE_ENONFINITE;
            break;
        }
        if (hist && hist->n < hist->cap) {
            const int j = hist->n++;
            hist->t[j] = t;
            hist->ne[j] = ne;
            hist->ne_pred[j] = pred;
            hist->y[j] = (double)st.q[ie + 1];
            hist->y_qs[j] = yqs;
            hist->v[j] = (double)st.v[ie + 1];
            hist->v_qs[j] = vqs;
            hist->dE[j] = dE;
            hist->mass[j] = mass;
        }
        r.t_stop = t;
        r.stretch_end = yqs + len;
        r.ne_end = ne;
        if (k == nsteps) break;
        if ((r.status = vlbe_hht_step(&st, (vlbe_real)c->h)) != VLBE_OK) break;
        r.steps++;
        { /* length control at the winch */
            vlbe_real p3[3];
            clock_t c1 = clock();
            r.status = vlbe_ale_chain_pnode(&m->ch, 0, st.t, st.q, st.v, p3);
            if (r.status != VLBE_OK) break;
            if ((double)(m->node[1].p - p3[0]) > 1.5 * c->Lstd) {
                if (m->ch.nn - 1 >= c->nmax) {
                    r.status = VLBE_EWORK;
                    break;
                }
                if ((r.status = vlbe_ale_chain_insert(&m->ch, 0, m->node[1].p - (vlbe_real)c->Lstd,
                                                      st.t, st.q, st.v, qn, vn)) != VLBE_OK)
                    break;
                r.newton += st.stats.newton_iters;
                r.lu += st.stats.lu_factors;
                if (ex_cable_wire(&m->sys, &m->ch, c->banded)) {
                    r.status = VLBE_EARG;
                    break;
                }
                r.status = vlbe_hht_init(&st, &m->sys, &par, st.t, qn, vn, w, lw, iw, liw);
                r.splits++;
            }
            r.cpu_split += (double)(clock() - c1) / CLOCKS_PER_SEC;
        }
    }
    r.newton += st.stats.newton_iters;
    r.lu += st.stats.lu_factors;
done:
    r.cpu = (double)(clock() - c0) / CLOCKS_PER_SEC;
    if (m) ex_winch_free(m);
    free(m);
    free(q);
    free(w);
    free(iw);
    return r;
}

#endif /* VLBE_EX_WINCH_H */
