/* spinning_shaft.c -- VLBSE scene 4.3 (paper section 4.3): a simply
   supported shaft spinning at Omega under a constant-magnitude load P that
   travels along the axis at v and turns about it at omega (Katz 2001).
   Four 3D beam-shaft elements (ancf_ale.h, vlbe_ale3_*) in a chain whose
   third node follows the load, so every element changes length, against
   the exact modal series of eq. (59) (examples/ex_katz.h).
   -- part of vlbe                                  SPDX-License-Identifier: MIT

   cc -O2 examples/spinning_shaft.c -lm && ./a.out [outdir]

   Our reading of what the paper leaves implicit (Table 4 and the text):
     beta_1 = pi r_g / l = 0.02 with r_g = r/2 the radius of gyration of the
     solid circular section (r = 2 beta_1 l / pi = 12.7 mm);
     a = v / v_cr with v_cr = omega_1 l / pi the first critical load speed of
     the non-spinning Euler-Bernoulli beam, omega_1 = (pi/l)^2 sqrt(EJ/rhoA);
     k_omega = omega l / (2 pi v), turns of the load per traverse;
     U_s = P l^3 / (48 E J), the static midspan deflection under P at midspan.
   The load starts along X1 (U = U1 + i U2 = deflection in X1 + i X2).

   The model.  Nodes 0..4 at material coordinates 0, p/2, p, (p + l)/2, l
   with p = v t the load's (prescribed through the chain's pfun: the two
   middle ones stay centred, the ALE form of eq. (51)); simple supports:
   r(0) = 0 (a spherical joint, eq. 50) and x = y = 0 at z = l, free
   along the axis (VLBE_ALE_CON_POS with a component mask).  Both ends
   held axially would add membrane tension ~ EA (U/l)^2: at U_s = l/1000
   it stiffens the shaft by 0.6 % and moves the deflection by 0.01-0.05
   U_s (measured), a nonlinear effect the linear eq. (59) does not have.
   The spin angle of
   node 0 is Omega t (VLBE_ALE_CON_SPIN), the others follow through the
   torsional stiffness; the load P (cos omega t, sin omega t, 0) acts on
   node 2's position (eq. 45 at a node).  A node that sits at a moving
   material point of a straight shaft at rest moves with the material
   coordinate: r_i = (U1, U2, p_i), r_i' = (U1_z, U2_z, 1), and their
   rates r_i. = (U_t + U_z p_i', p_i'), r_i'. = (U_zt + U_zz p_i', 0).  The
   load cannot start exactly at the support (the two left elements would
   have zero length): it starts at z0 l at t0 = z0 l / v, with the exact
   solution's state at t0 (ss_exact: 60 modes) as the start state, and
   stops at (1 - z0) l; z0 = 1e-3 for the paper's 4 elements, 1e-2 for
   finer meshes (their end elements of z0 l / 4 and less defeat Newton at
   1e-3: the iteration matrix's conditioning grows as the element length
   ratio cubed).

   Physics the element does not have.  Eq. (59) keeps the rotary inertia of
   the cross-sections in bending and the gyroscopic term -i 2 Omega rhoJ
   U_zzt; the beam-shaft element (an ANCF beam with a spin angle, eq. 27)
   has neither.  With beta_1 = 0.02 they change the response by O(beta^2)
   = 4e-4 of U_s (measured below): the comparison is reported against
   eq. (59) as written (the paper's) and against the same series without
   the rhoJ terms (the continuum the element discretizes). */
#include "../ancf_ale.h"
#include "ex_katz.h"
#include "ex_run.h"
#include "../bench/svgplot.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define SS_NE 4               /* elements of the paper's model             */
#define SS_NE_MAX 16
#define SS_NSAMP_MAX 4096
#define SS_NMODES_START 60    /* modes of the exact start state             */

/* Table 4 */
#define SS_L 1.0
#define SS_BETA1 0.02
#define SS_E 206e9
#define SS_RHO 7700.0
#define SS_OMEGA_SPIN 1.0
#define SS_NU 0.3             /* Poisson's ratio for G (torsion only: not in Table 4) */
#define SS_US 1e-3            /* U_s [m]: sets P (the response is normalised by U_s; at
                                 U_s = l/1000 the geometric nonlinearity is ~1e-6) */
#define SS_Z0 1e-3            /* start / stop margin of the load, times l   */
#define SS_Z0_CONV 1e-2       /* the same for the convergence runs (finer meshes) */
#define SS_ATOL 1e-8          /* HHT Newton atol [m, m/s]: 1e-5 U_s; see ss_run */

/* the paper's maximum absolute errors with four elements, normalised by
   U_s: load point X1, X2, midspan X1, X2 */
static const double ss_paper_err[2][4] = {{0.0085, 0.0033, 0.0049, 0.0053},
                                          {0.0090, 0.0055, 0.0176, 0.0079}};
static const double ss_case_a[2] = {0.5, 1.5}, ss_case_kw[2] = {1.0, 0.5};

typedef struct ss_scene {
    ex_katz ref;      /* load, speeds, section (rot = 1: eq. 59 as written) */
    ex_katz ref0;     /* the same without the rhoJ terms                    */
    int ne;
    vlbe_ale3_elem el;
    vlbe_ale_chain ch;
    vlbe_ale_node node[SS_NE_MAX + 1];
    vlbe_ale_con con[4];
    vlbe_dae sys;
    double t0, t1;    /* load at z0 and at l - z0                           */
    int fixed;        /* 0: the paper's mesh (the load on node ne/2, every
                         element changing length); 1: ne equal fixed
                         elements, the load a moving point force (eq. 45) */
    int iload;        /* index of the load node's x in q (fixed = 0)        */
    /* samples: t, load point U1, U2, midspan U1, U2 (not normalised) */
    int ns;
    double t[SS_NSAMP_MAX], u[4][SS_NSAMP_MAX];
    int every;        /* keep every k-th step                               */
    long step;
} ss_scene;

/* p, p', p'' of node i: the load node at v t, the middle ones centred */
static int ss_pfun(void *user, int i, vlbe_real t, vlbe_real *p3)
{
    const ss_scene *s = (const ss_scene *)user;
    const int half = s->ne / 2;
    const double v = s->ref.v, pl = v * (double)t, l = s->ref.l;
    double p, pd;
    if (i <= half) {
        p = pl * (double)i / (double)half;
        pd = v * (double)i / (double)half;
    } else {
        p = pl + (l - pl) * (double)(i - half) / (double)(s->ne - half);
        pd = v * (1.0 - (double)(i - half) / (double)(s->ne - half));
    }
    p3[0] = (vlbe_real)p;
    p3[1] = (vlbe_real)pd;
    p3[2] = VLBE_R(0.0);
    return 0;
}

/* chain force plus the turning load: on the load node, or (fixed mesh)
   S(z)^T F at the load's material point z = v t (constant in q: no
   Jacobian) */
static int ss_force(void *user, vlbe_real t, const vlbe_real *q, const vlbe_real *v, vlbe_real *Q)
{
    ss_scene *s = (ss_scene *)user;
    const double tt = (double)t + s->t0, w = s->ref.omega * tt; /* chain clock starts at t0 */
    vlbe_real F[3];
    int rc = vlbe_ale_chain_force(&s->ch, t, q, v, Q), e, i, idx[VLBE_ALE3_NQ];
    if (rc) return rc;
    F[0] = (vlbe_real)(s->ref.P * cos(w));
    F[1] = (vlbe_real)(s->ref.P * sin(w));
    F[2] = VLBE_R(0.0);
    if (!s->fixed) {
        Q[s->iload] += F[0];
        Q[s->iload + 1] += F[1];
        return 0;
    } else {
        const vlbe_real z = (vlbe_real)(s->ref.v * tt);
        vlbe_real qe[VLBE_ALE3_NQ], Qe[VLBE_ALE3_NQ];
        unsigned md;
        if (vlbe_ale_chain_locate(&s->ch, t, q, z, &e) ||
            vlbe_ale_chain_gather(&s->ch, e, t, q, NULL, qe, NULL, idx, &md))
            return -1;
        for (i = 0; i < VLBE_ALE3_NQ; ++i) Qe[i] = VLBE_R(0.0);
        if (vlbe_ale3_point_force(md | s->el.flags, qe, z, F, Qe, NULL)) return -1;
        for (i = 0; i < vlbe_ale3_nq(md | s->el.flags); ++i)
            if (idx[i] >= 0) Q[idx[i]] += Qe[i];
        return 0;
    }
}

#define SS_FWD(name, args, call)                                                       \
    static int name args { return call; }
SS_FWD(ss_mass, (void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v, vlbe_real *M),
       vlbe_ale_chain_mass(&((ss_scene *)u)->ch, t, q, v, M))
SS_FWD(ss_force_jac,
       (void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v, vlbe_real *K, vlbe_real *D),
       vlbe_ale_chain_force_jac(&((ss_scene *)u)->ch, t, q, v, K, D))
SS_FWD(ss_mass_jac,
       (void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v, const vlbe_real *a,
        vlbe_real *Mq, vlbe_real *Mv),
       vlbe_ale_chain_mass_jac(&((ss_scene *)u)->ch, t, q, v, a, Mq, Mv))
SS_FWD(ss_constr, (void *u, vlbe_real t, const vlbe_real *q, vlbe_real *C),
       vlbe_ale_chain_constr(&((ss_scene *)u)->ch, t, q, C))
SS_FWD(ss_constr_jac, (void *u, vlbe_real t, const vlbe_real *q, vlbe_real *Cq, vlbe_real *Ct),
       vlbe_ale_chain_constr_jac(&((ss_scene *)u)->ch, t, q, Cq, Ct))
SS_FWD(ss_constr_acc, (void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v, vlbe_real *g),
       vlbe_ale_chain_constr_acc(&((ss_scene *)u)->ch, t, q, v, g))

/* The exact solution at (z, t) from modes 1..nm: u[c] = (U_c, U_c,z, U_c,t,
   U_c,zt, U_c,zz), c = 0 (X1), 1 (X2); the time derivatives by central
   differences of the exact modal coordinates (step 1e-4 / omega_1: error
   ~1e-8 of the mode's rate) */
static void ss_exact(const ex_katz *k, int nm, double z, double t, double u[2][5])
{
    const double PI = 3.14159265358979323846, h = 1e-4 / k->w1;
    int n, c, j;
    for (c = 0; c < 2; ++c)
        for (j = 0; j < 5; ++j) u[c][j] = 0.0;
    for (n = 1; n <= nm; ++n) {
        const double kn = (double)n * PI / k->l, sn = sin(kn * z), cn = cos(kn * z);
        double w[2], wp[2], wm[2];
        if (ex_katz_mode(k, n, t, &w[0], &w[1]) || ex_katz_mode(k, n, t + h, &wp[0], &wp[1]) ||
            ex_katz_mode(k, n, t - h, &wm[0], &wm[1]))
            continue; /* n >= 1 and finite t: not taken */
        for (c = 0; c < 2; ++c) {
            const double wd = (wp[c] - wm[c]) / (2.0 * h);
            u[c][0] += w[c] * sn;
            u[c][1] += w[c] * kn * cn;
            u[c][2] += wd * sn;
            u[c][3] += wd * kn * cn;
            u[c][4] -= w[c] * kn * kn * sn;
        }
    }
}

/* Sets up case (a, kw) with ne elements (even, <= SS_NE_MAX); q0, v0 (the
   chain's n) the start state at t0.  0 on success. */
static int ss_setup(ss_scene *s, double a, double kw, int ne, int fixed, double z0,
                    vlbe_real *q0, vlbe_real *v0)
{
    vlbe_ale3_mat mat;
    vlbe_ale_con c;
    double P;
    int i;
    memset(s, 0, sizeof *s);
    if (ne < 2 || ne > SS_NE_MAX || ne % 2) return -1;
    if (ex_katz_setup(&s->ref, SS_L, SS_BETA1, SS_E, SS_RHO, SS_OMEGA_SPIN, a, kw, 1.0, 1))
        return -1;
    P = SS_US / ex_katz_us(&s->ref); /* U_s is linear in P */
    if (ex_katz_setup(&s->ref, SS_L, SS_BETA1, SS_E, SS_RHO, SS_OMEGA_SPIN, a, kw, P, 1) ||
        ex_katz_setup(&s->ref0, SS_L, SS_BETA1, SS_E, SS_RHO, SS_OMEGA_SPIN, a, kw, P, 0))
        return -1;
    if (vlbe_ale3_mat_circle(&mat, (vlbe_real)SS_RHO, (vlbe_real)SS_E,
                             (vlbe_real)(SS_E / (2.0 * (1.0 + SS_NU))), (vlbe_real)s->ref.r) ||
        vlbe_ale3_elem_init(&s->el, &mat, VLBE_ALE_NO_DAMP, 0, 0))
        return -1;
    s->ne = ne;
    s->fixed = fixed;
    s->t0 = z0 * SS_L / s->ref.v;
    s->t1 = (1.0 - z0) * SS_L / s->ref.v;
    for (i = 0; i <= ne; ++i) {
        s->node[i].pmode = (fixed || i == 0 || i == ne) ? VLBE_ALE_PFIXED : VLBE_ALE_PPRESCRIBED;
        s->node[i].p = (vlbe_real)(fixed ? SS_L * (double)i / (double)ne : (i == ne ? SS_L : 0.0));
    }
    if (vlbe_ale_chain_init3(&s->ch, &s->el, s->node, ne + 1, ne + 1, s->con, 4)) return -1;
    s->ch.pfun = ss_pfun;
    s->ch.user = s;
    memset(&c, 0, sizeof c);
    c.type = VLBE_ALE_CON_POS; /* simple supports */
    c.node = 0;
    if (vlbe_ale_chain_add(&s->ch, &c)) return -1;
    c.node = ne;
    c.which = 3; /* a roller: x, y held, free along the axis */
    if (vlbe_ale_chain_add(&s->ch, &c)) return -1;
    memset(&c, 0, sizeof c);
    c.type = VLBE_ALE_CON_SPIN; /* theta_0 = Omega t */
    c.v[1] = (vlbe_real)SS_OMEGA_SPIN;
    if (vlbe_ale_chain_add(&s->ch, &c) || vlbe_ale_chain_layout(&s->ch)) return -1;
    if (q0 && v0) {
        for (i = 0; i < s->ch.n; ++i) q0[i] = v0[i] = VLBE_R(0.0);
        for (i = 0; i <= ne; ++i) {
            vlbe_real p3[3];
            double u[2][5];
            const int o = s->node[i].ofs;
            int k;
            if (fixed) {
                p3[0] = s->node[i].p;
                p3[1] = VLBE_R(0.0);
            } else if (ss_pfun(s, i, (vlbe_real)s->t0, p3))
                return -1;
            ss_exact(&s->ref0, SS_NMODES_START, (double)p3[0], s->t0, u);
            for (k = 0; k < 2; ++k) { /* the series' state at the moving node */
                q0[o + k] = (vlbe_real)u[k][0];
                q0[o + 3 + k] = (vlbe_real)u[k][1];
                v0[o + k] = (vlbe_real)(u[k][2] + u[k][1] * (double)p3[1]);
                v0[o + 3 + k] = (vlbe_real)(u[k][3] + u[k][4] * (double)p3[1]);
            }
            q0[o + 2] = p3[0];
            v0[o + 2] = p3[1];
            q0[o + 5] = VLBE_R(1.0);
            v0[o + 6] = (vlbe_real)SS_OMEGA_SPIN; /* theta = Omega t from 0 */
        }
    }
    s->iload = s->node[ne / 2].ofs;
    s->sys.n = s->ch.n;
    s->sys.m = s->ch.m;
    s->sys.user = s;
    s->sys.mass = ss_mass;
    s->sys.force = ss_force;
    s->sys.constr = ss_constr;
    s->sys.constr_jac = ss_constr_jac;
    s->sys.constr_acc = ss_constr_acc;
    s->sys.force_jac = ss_force_jac;
    s->sys.mass_jac = ss_mass_jac;
    return 0;
}

/* the observer: samples of the load point and of material midspan */
static vlbe_status ss_obs(void *ctx, double t, const vlbe_real *q, const vlbe_real *v,
                          const vlbe_real *lam)
{
    ss_scene *s = (ss_scene *)ctx;
    vlbe_real r[3];
    vlbe_status st;
    (void)v;
    (void)lam;
    if (s->step++ % s->every != 0 || s->ns >= SS_NSAMP_MAX) return VLBE_OK;
    /* the chain's clock (pfun) runs from 0 at t0 */
    if ((st = vlbe_ale_chain_point(&s->ch, (vlbe_real)t, q, (vlbe_real)(0.5 * SS_L), r, NULL)) !=
        VLBE_OK)
        return st;
    t += s->t0;
    s->t[s->ns] = t;
    {
        vlbe_real rl[3]; /* the load point: material z = v t (on the chain's clock) */
        if ((st = vlbe_ale_chain_point(&s->ch, (vlbe_real)(t - s->t0), q,
                                       (vlbe_real)(s->ref.v * t), rl, NULL)) != VLBE_OK)
            return st;
        s->u[0][s->ns] = (double)rl[0];
        s->u[1][s->ns] = (double)rl[1];
    }
    s->u[2][s->ns] = (double)r[0];
    s->u[3][s->ns] = (double)r[1];
    s->ns++;
    return VLBE_OK;
}

/* the time origin of the chain is t0: shift the pfun and the load */
static int ss_pfun_shift(void *user, int i, vlbe_real t, vlbe_real *p3)
{
    const ss_scene *s = (const ss_scene *)user;
    return ss_pfun(user, i, (vlbe_real)((double)t + s->t0), p3);
}

/* Runs one case with ne elements, the load from z0 l to (1 - z0) l, and
   nsteps HHT steps over that traverse;
   err[0..3]: max |U - U_ref| / U_s (load point X1, X2, midspan X1, X2)
   against ref (rot = 1) and, when err0 != NULL, against ref0; out: the
   run's counters.  Samples are kept in s.  Returns the run status. */
static vlbe_status ss_run(ss_scene *s, double a, double kw, int ne, int fixed, double z0,
                          long nsteps, double alpha, int nmodes, double *err, double *err0,
                          ex_run_out *out)
{
    vlbe_real q0[SS_NE_MAX * 8 + 8], v0[SS_NE_MAX * 8 + 8];
    vlbe_hht_params par;
    ex_method m;
    vlbe_status st;
    double us;
    int i, k;
    if (ss_setup(s, a, kw, ne, fixed, z0, q0, v0)) return VLBE_EARG;
    /* the chain runs on its own clock from 0: shift p(t) and the load */
    s->ch.pfun = ss_pfun_shift;
    if ((st = ex_hht_pick(&par, alpha, 0.0)) != VLBE_OK) return st;
    /* Newton's velocity test sees the position rounding (axial forces of
       size EA eps carry EA EPS of noise, over the bending stiffness) times
       gamma/(beta h) ~ 4e5: at the default atol 1e-11 the iteration stalls
       on that noise near the short end elements (VLBE_ENOCONV, measured);
       1e-8 m (1e-5 U_s) is far below the errors compared */
    par.atol = (vlbe_real)SS_ATOL;
    par.max_halvings = 6; /* the last steps, with end elements of z0 l / 2, may need it */
    memset(&m, 0, sizeof m);
    m.hht = &par;
    m.h = (s->t1 - s->t0) / (double)nsteps;
    s->every = (int)(nsteps / 2000 + 1);
    st = ex_run(&s->sys, &m, q0, v0, s->t1 - s->t0, ss_obs, s, NULL, NULL, NULL, out);
    if (st != VLBE_OK) return st;
    us = ex_katz_us(&s->ref);
    for (k = 0; k < 4; ++k) {
        err[k] = 0.0;
        if (err0) err0[k] = 0.0;
    }
    for (i = 0; i < s->ns; ++i) {
        const double t = s->t[i], z = s->ref.v * t;
        double r[4], r0[4];
        ex_katz_eval(&s->ref, nmodes, z, t, &r[0], &r[1]);
        ex_katz_eval(&s->ref, nmodes, 0.5 * SS_L, t, &r[2], &r[3]);
        ex_katz_eval(&s->ref0, nmodes, z, t, &r0[0], &r0[1]);
        ex_katz_eval(&s->ref0, nmodes, 0.5 * SS_L, t, &r0[2], &r0[3]);
        for (k = 0; k < 4; ++k) {
            err[k] = fmax(err[k], fabs(s->u[k][i] - r[k]) / us);
            if (err0) err0[k] = fmax(err0[k], fabs(s->u[k][i] - r0[k]) / us);
        }
    }
    return VLBE_OK;
}

#ifndef VLBE_EXAMPLE_NO_MAIN
static ss_scene ss_main_scene;

/* histories of the 4-element run against the exact series (CSV and SVG) */
static void ss_plot(const ss_scene *s, int c, int nmodes, const char *dir)
{
    static double t[SS_NSAMP_MAX], y[8][SS_NSAMP_MAX];
    static const char *const lab[4] = {"load point U1/Us", "load point U2/Us", "midspan U1/Us",
                                       "midspan U2/Us"};
    static char names[8][64];
    const double us = ex_katz_us(&s->ref);
    char path[512], title[160];
    const double *cols[9];
    svgp_chart chart;
    int i, k;
    for (i = 0; i < s->ns; ++i) {
        double r[4];
        t[i] = s->ref.v * s->t[i] / s->ref.l; /* load position z / l */
        ex_katz_eval(&s->ref, nmodes, s->ref.v * s->t[i], s->t[i], &r[0], &r[1]);
        ex_katz_eval(&s->ref, nmodes, 0.5 * s->ref.l, s->t[i], &r[2], &r[3]);
        for (k = 0; k < 4; ++k) {
            y[2 * k][i] = s->u[k][i] / us;
            y[2 * k + 1][i] = r[k] / us;
        }
    }
    snprintf(title, sizeof title, "spinning shaft, a = %g, k_omega = %g: 4 ALE beam-shaft elements "
             "vs exact (eq. 59)", ss_case_a[c], ss_case_kw[c]);
    svgp_init(&chart, title, "load position z / l", "U / U_s", 0, 0);
    for (k = 0; k < 4; ++k) {
        snprintf(names[2 * k], sizeof names[0], "%s, 4 elements", lab[k]);
        snprintf(names[2 * k + 1], sizeof names[0], "%s, exact", lab[k]);
        svgp_series(&chart, names[2 * k], s->ns, t, y[2 * k], 0);
        svgp_series(&chart, names[2 * k + 1], s->ns, t, y[2 * k + 1], SVGP_DASH);
    }
    snprintf(path, sizeof path, "%s/spinning_shaft_case%d.svg", dir, c + 1);
    if (svgp_write_file(&chart, path)) printf("could not write %s\n", path);
    cols[0] = t;
    for (k = 0; k < 8; ++k) cols[1 + k] = y[k];
    snprintf(path, sizeof path, "%s/spinning_shaft_case%d.csv", dir, c + 1);
    if (svgp_csv_write(path, "z_over_l,load_U1_fe,load_U1_exact,load_U2_fe,load_U2_exact,"
                       "mid_U1_fe,mid_U1_exact,mid_U2_fe,mid_U2_exact", 9, s->ns, cols))
        printf("could not write %s\n", path);
}

int main(int argc, char **argv)
{
    static const char *names[4] = {"load point U1/Us", "load point U2/Us", "midspan U1/Us",
                                   "midspan U2/Us"};
    const char *outdir = argc > 1 ? argv[1] : "out";
    ss_scene *s = &ss_main_scene;
    int c, k, ine;
    printf("spinning shaft under a moving, turning load (vlbse section 4.3): ALE beam-shaft\n"
           "elements, the load on a node; max |U - U_exact| / U_s over the traverse, exact =\n"
           "eq. (59) [without its rhoJ terms], 30+ modes (series converged to 1e-6 U_s)\n");
    for (c = 0; c < 2; ++c) {
        const double a = ss_case_a[c], kw = ss_case_kw[c];
        double err[4], err0[4];
        ex_run_out out;
        int nm = 0;
        char q[96];
        ex_katz ref;
        if (ex_katz_setup(&ref, SS_L, SS_BETA1, SS_E, SS_RHO, SS_OMEGA_SPIN, a, kw, 1.0, 1) ||
            ex_katz_modes_for(&ref, 1e-6, 400, &nm, NULL)) {
            printf("reference setup failed\n");
            return 1;
        }
        printf("\ncase a = %g, k_omega = %g: v = %.4f m/s, omega = %.3f rad/s, l/v = %.5f s, "
               "%d modes\n", a, kw, ref.v, ref.omega, ref.T, nm);
        printf("  mesh   elements  z0/l   steps  CPU [s]   load U1   load U2    mid U1    mid U2\n");
        for (ine = 0; ine < 7; ++ine) {
            const int fixed = ine >= 4, ne = ine == 0 ? SS_NE : 4 << ((ine - 1) % 3);
            const double z0 = (ine == 0 || fixed) ? SS_Z0 : SS_Z0_CONV;
            const long nsteps = 4000;
            vlbe_status st = ss_run(s, a, kw, ne, fixed, z0, nsteps, -0.05, nm, err, err0, &out);
            if (st != VLBE_OK) {
                printf("  %2d elements: run failed: %s\n", ne, vlbe_status_str(st));
                return 1;
            }
            printf("  %-6s %8d %6.0e %6ld %8.3f  %.2e  %.2e  %.2e  %.2e\n",
                   fixed ? "fixed" : "moving", ne, z0, out.stats.steps, out.cpu, err[0], err[1],
                   err[2], err[3]);
            printf("  %-6s %8s %6s %6s %8s [%.2e  %.2e  %.2e  %.2e]\n", "", "", "", "", "",
                   err0[0], err0[1], err0[2], err0[3]);
            if (ine == 0) {
                printf("  %-6s %8s %6s %6s %8s  %.2e  %.2e  %.2e  %.2e  (paper, 4 elements)\n",
                       "", "", "", "", "", ss_paper_err[c][0], ss_paper_err[c][1],
                       ss_paper_err[c][2], ss_paper_err[c][3]);
                for (k = 0; k < 4; ++k) {
                    snprintf(q, sizeof q, "a=%g kw=%g max abs err %s (4 el.)", a, kw, names[k]);
                    svgp_compare_row(stdout, "spinning shaft", q, ss_paper_err[c][k], err[k],
                                     err[k] / ss_paper_err[c][k] - 1.0, out.cpu);
                }
                ss_plot(s, c, nm, outdir);
            }
            if (ine == 4)
                for (k = 0; k < 4; ++k) {
                    snprintf(q, sizeof q, "a=%g kw=%g max abs err %s (4 fixed el.)", a, kw,
                             names[k]);
                    svgp_compare_row(stdout, "spinning shaft", q, ss_paper_err[c][k], err[k],
                                     err[k] / ss_paper_err[c][k] - 1.0, out.cpu);
                }
        }
    }
    printf("\nmoving: the paper's mesh, the load on the middle node (every element changes\n"
           "length); fixed: equal elements, the load a moving point force (eq. 45).  The load\n"
           "runs from z0 l to (1 - z0) l, the shaft starting in the exact state at z0.\n"
           "[...]: against the series without the rhoJ terms (the element's continuum).\n");
    return 0;
}
#endif /* VLBE_EXAMPLE_NO_MAIN */
