/* campbell_rotating.c -- Campbell diagram of a rotating cantilever: its
   in-plane (lag) and out-of-plane (flap) bending frequencies against the
   spin speed, from the linearisation of ANCF chains about the steady
   rotating state (vlbe_dae_linearize in the turning frame, integrators.h)
   and the gyroscopic eigenproblem (vlbe_eig_quad, vlbe.h), against the
   exact frequencies of the rotating Euler-Bernoulli beam (ex_cant_rot of
   scenes/ex_cant.h).  -- part of vlbe          SPDX-License-Identifier: MIT

   cc -O2 examples/campbell_rotating.c -lm && ./a.out [outdir]

   Beam: that of the spin-up scene (scenes/ex_spin.h): L = 10 m,
   EA = 2.8e7 N, EI = 1.4e4 N m^2, rhoA = 1.2 kg/m, no rotary inertia,
   clamped on the hub axis (position and slope held); first bending
   frequency at rest w0 = 1.8751^2 sqrt(EI / (rhoA L^4)) = 3.80 rad/s.
   Spin Om = 0 .. 13 rad/s about z, i.e. 0 .. 12 in the unit
   u = sqrt(EI / (rhoA L^4)) = 1.080 rad/s of the classical tables.

   Steady state.  In the frame turning with the hub the beam is at rest
   under its elastic forces and the centrifugal load -M G^2 q, where
   G = Om [e_z x] acts on every position and slope vector of q: the
   static solve (vlbe_dae_static) of the chain with that load added
   (continuation in Om from the straight beam).  In the inertial frame the
   same state moves with v = G q, q'' = G^2 q, and the multipliers are
   the same.
   Linearisation.  vlbe_dae_linearize about (q, G q, G^2 q, lambda) with
   the turning frame (vlbe_lin_frame: Om about z, the position and slope
   vectors of every node): M, D = 2 M G (Coriolis), K = K_t + M G^2 (the
   tangent stiffness with the centrifugal tension, and the centrifugal
   softening), reduced on the null space of the clamp.  Then
   (s^2 M + s D + K) x = 0 by vlbe_eig_quad with the shift sigma = -w0/2
   (shift-invert: the lowest |s| first); w = Im s.
   Models: the planar chain (in-plane modes only) and the 3D beam-shaft
   chain without its spin angle (VLBE_ALE3_NO_SPIN; the section is round
   and nothing twists), whose modes are told apart by their eigenvectors
   (flap: the z components carry most of the mode; lag: x and y).
   For contrast the LINEAR FLOATING FRAME: the same linearisation about the
   straight UNSTRESSED beam (no centrifugal tension, lambda = 0): lag
   w^2 = w0^2 - Om^2 (to the Coriolis coupling with the axial modes), zero
   at Om = w0 -- the divergence that ends the linear model's run in
   examples/spin_up.c -- while the nonlinear beam stiffens.

   Exact: the rotating uniform cantilever, w_lag^2 = w_flap^2 - Om^2 with
   the flap frequencies by shooting (ex_cant_rot; the classical 3.6816,
   4.1373, ... at Om = 1, 2, ...).  That theory is inextensible; the ANCF
   beam is not (EA L^2 / EI = 2e5; first axial mode 762 rad/s): its
   centrifugal stretch and the Coriolis coupling of the lag modes with the
   axial ones lower them, at Om = 10 rad/s the lag by 5.4e-4 relative and
   the flap by 5e-5, beside the discretisation error of 16 consistent-mass
   Hermite elements (1e-4, from above).  The rows with EA x 10, 100, 1000
   separate the two: the difference to the inextensible value falls as
   1/EA onto the discretisation error.

   Rows ROW|campbell rotating|<quantity>|<exact>|<ours>|<rel.err>|<cpu s>;
   with an output directory campbell_rotating.csv / .svg. */
#include "../ancf_ale.h"
#include "../integrators.h"
#include "../scenes/ex_cant.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define CR_L 10.0
#define CR_EA 2.8e7
#define CR_EI 1.4e4
#define CR_RHOA 1.2
#define CR_NE_MAX 16
#define CR_NQ (6 * (CR_NE_MAX + 1))
#define CR_NW 3 /* frequencies kept per family */

typedef struct cr_model {
    vlbe_ale_elem el;
    vlbe_ale3_elem el3;
    vlbe_ale_node node[CR_NE_MAX + 1];
    vlbe_ale_con con[2];
    vlbe_ale_chain ch;
    vlbe_dae sys; /* the chain                                          */
    vlbe_dae rot; /* the chain with the centrifugal load (steady state) */
    int d, ne, n, m;
    vlbe_real Om;
    int vec[2 * (CR_NE_MAX + 1)];
    vlbe_real M[CR_NQ * CR_NQ], Pq[CR_NQ];
} cr_model;

static inline double cr_unit(void) { return sqrt(CR_EI / (CR_RHOA * CR_L * CR_L * CR_L * CR_L)); }

/* Pq = the components of q that G^2 acts on (x and y of every vector),
   times -1/Om^2 G^2 = +1: the centrifugal load is Om^2 M Pq. */
static void cr_proj(const cr_model *c, const vlbe_real *q, vlbe_real *Pq)
{
    int i, k;
    for (i = 0; i < c->n; ++i) Pq[i] = 0;
    for (k = 0; k < 2 * (c->ne + 1); ++k) {
        Pq[c->vec[k]] = q[c->vec[k]];
        Pq[c->vec[k] + 1] = q[c->vec[k] + 1];
    }
}

/* The steady-state problem is the chain's with force and force_jac
   replaced: its user stays the chain (every other callback is the
   chain's), whose own pointer (ch.user, for pfun / afun, unused here)
   leads to the model. */
static int cr_force(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v, vlbe_real *Q)
{
    cr_model *c = (cr_model *)((vlbe_ale_chain *)u)->user;
    int rc = c->sys.force(c->sys.user, t, q, v, Q), i;
    if (rc) return rc;
    if ((rc = c->sys.mass(c->sys.user, t, q, v, c->M)) != 0) return rc;
    cr_proj(c, q, c->Pq);
    for (i = 0; i < c->n; ++i)
        Q[i] += c->Om * c->Om * vlbe_vec_dot(c->n, c->M + (size_t)i * (size_t)c->n, c->Pq);
    return 0;
}

static int cr_force_jac(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v,
                        vlbe_real *K, vlbe_real *D)
{
    cr_model *c = (cr_model *)((vlbe_ale_chain *)u)->user;
    int rc = c->sys.force_jac(c->sys.user, t, q, v, K, D), i, k;
    if (rc) return rc;
    if ((rc = c->sys.mass(c->sys.user, t, q, v, c->M)) != 0) return rc;
    for (i = 0; i < c->n; ++i) /* d(Om^2 M P q)/dq = Om^2 M P */
        for (k = 0; k < 2 * (c->ne + 1); ++k) {
            const int j = c->vec[k];
            K[(size_t)i * (size_t)c->n + (size_t)j] += c->Om * c->Om * c->M[(size_t)i * (size_t)c->n + (size_t)j];
            K[(size_t)i * (size_t)c->n + (size_t)j + 1] +=
                c->Om * c->Om * c->M[(size_t)i * (size_t)c->n + (size_t)j + 1];
        }
    return 0;
}

/* ne elements, planar (d = 2) or 3D without spin angle (d = 3), along x
   from the origin, clamped there; the axial stiffness is eaf EA (eaf = 1:
   the scene's). */
static int cr_build(cr_model *c, int ne, int d, double eaf)
{
    vlbe_ale_con k;
    int i;
    memset(c, 0, sizeof *c);
    c->d = d;
    c->ne = ne;
    if (d == 2) {
        vlbe_ale_mat mat;
        memset(&mat, 0, sizeof mat);
        mat.rhoA = (vlbe_real)CR_RHOA;
        mat.EA = (vlbe_real)(CR_EA * eaf);
        mat.EI = (vlbe_real)CR_EI;
        if (vlbe_ale_elem_init(&c->el, &mat, VLBE_ALE_NO_DAMP, 0, 0, 0)) return -1;
    } else {
        vlbe_ale3_mat m3;
        memset(&m3, 0, sizeof m3);
        m3.rhoA = (vlbe_real)CR_RHOA;
        m3.EA = (vlbe_real)(CR_EA * eaf);
        m3.EJ = (vlbe_real)CR_EI;
        if (vlbe_ale3_elem_init(&c->el3, &m3, VLBE_ALE_NO_DAMP | VLBE_ALE3_NO_SPIN, 0, 0))
            return -1;
    }
    for (i = 0; i <= ne; ++i) c->node[i].p = (vlbe_real)(CR_L * i / ne);
    if (d == 2 ? vlbe_ale_chain_init(&c->ch, &c->el, c->node, ne + 1, ne + 1, c->con, 2)
               : vlbe_ale_chain_init3(&c->ch, &c->el3, c->node, ne + 1, ne + 1, c->con, 2))
        return -1;
    memset(&k, 0, sizeof k);
    k.type = VLBE_ALE_CON_POS;
    vlbe_ale_chain_add(&c->ch, &k);
    k.type = VLBE_ALE_CON_SLOPE;
    k.d[0] = 1;
    vlbe_ale_chain_add(&c->ch, &k);
    if (vlbe_ale_chain_layout(&c->ch) || vlbe_ale_chain_dae(&c->ch, &c->sys)) return -1;
    c->n = c->ch.n;
    c->m = c->ch.m;
    if (c->n > CR_NQ) return -1;
    for (i = 0; i <= ne; ++i) {
        c->vec[2 * i] = c->node[i].ofs;         /* r  */
        c->vec[2 * i + 1] = c->node[i].ofs + d; /* r' */
    }
    c->rot = c->sys;
    c->ch.user = c;
    c->rot.force = cr_force;
    c->rot.force_jac = c->sys.force_jac ? cr_force_jac : NULL;
    return 0;
}

/* Frequencies at spin Om about the state q, lambda (the steady state, or
   the straight unstressed beam with lambda = 0): the lowest CR_NW lag and
   flap frequencies (flap: 3D only, else -1); *remax (may be NULL) the
   largest real part of the eigenvalues (> 0: unstable). */
static vlbe_status cr_freqs(cr_model *c, vlbe_real Om, const vlbe_real *q, const vlbe_real *lam,
                            double *lag, double *flap, double *remax)
{
    const int n = c->n;
    vlbe_lin_frame fr;
    vlbe_real *v = NULL, *a = NULL, *N = NULL, *Mr = NULL, *Dr = NULL, *Kr = NULL, *sre = NULL,
              *sim = NULL, *Xre = NULL, *Xim = NULL, *w = NULL;
    int *iw = NULL, nr = 0, i, k, nl = 0, nf = 0, prevflap = 0, nv = 0;
    vlbe_real wprev = -1;
    size_t lw, liw;
    vlbe_status st = VLBE_EWORK;
    for (k = 0; k < CR_NW; ++k) lag[k] = flap[k] = -1.0;
    memset(&fr, 0, sizeof fr);
    fr.omega[2] = Om;
    fr.dim = c->d;
    fr.nvec = 2 * (c->ne + 1);
    fr.vec = c->vec;
    v = (vlbe_real *)calloc((size_t)n, sizeof *v);
    a = (vlbe_real *)calloc((size_t)n, sizeof *a);
    for (k = 0; v && a && k < fr.nvec; ++k) { /* v = G q, a = G^2 q */
        const int j = c->vec[k];
        v[j] = -Om * q[j + 1];
        v[j + 1] = Om * q[j];
        a[j] = -Om * Om * q[j];
        a[j + 1] = -Om * Om * q[j + 1];
    }
    lw = vlbe_dae_lin_work_len_sys(&c->sys);
    liw = vlbe_dae_lin_iwork_len_sys(&c->sys);
    N = (vlbe_real *)malloc((size_t)n * (size_t)n * sizeof *N);
    Mr = (vlbe_real *)malloc((size_t)n * (size_t)n * sizeof *Mr);
    Dr = (vlbe_real *)malloc((size_t)n * (size_t)n * sizeof *Dr);
    Kr = (vlbe_real *)malloc((size_t)n * (size_t)n * sizeof *Kr);
    w = (vlbe_real *)malloc((lw > vlbe_eig_quad_work_len(n) ? lw : vlbe_eig_quad_work_len(n)) *
                            sizeof *w);
    iw = (int *)malloc((liw > vlbe_eig_quad_iwork_len(n) ? liw : vlbe_eig_quad_iwork_len(n)) *
                       sizeof *iw + sizeof *iw);
    sre = (vlbe_real *)malloc(2 * (size_t)n * sizeof *sre);
    sim = (vlbe_real *)malloc(2 * (size_t)n * sizeof *sim);
    Xre = (vlbe_real *)malloc(2 * (size_t)n * (size_t)n * sizeof *Xre);
    Xim = (vlbe_real *)malloc(2 * (size_t)n * (size_t)n * sizeof *Xim);
    if (!v || !a || !N || !Mr || !Dr || !Kr || !w || !iw || !sre || !sim || !Xre || !Xim)
        goto done;
    st = vlbe_dae_linearize(&c->sys, 0, q, v, a, lam, &fr, &nr, N, Mr, Dr, Kr, NULL, w, lw, iw,
                            liw);
    if (st != VLBE_OK) goto done;
    /* 3D: the vectors of the lowest 2 CR_NW conjugate pairs, enough for
       CR_NW flap and CR_NW lag modes (the axial modes lie far above) */
    nv = c->d == 3 ? (4 * CR_NW < 2 * nr ? 4 * CR_NW : 2 * nr) : 0;
    st = vlbe_eig_quad(nr, Mr, Dr, Kr, (vlbe_real)(-0.5 * 3.516 * cr_unit()), sre, sim, nv, Xre,
                       Xim, w, vlbe_eig_quad_work_len(nr), iw, vlbe_eig_quad_iwork_len(nr));
    if (st != VLBE_OK) goto done;
    if (remax)
        for (k = 0, *remax = -HUGE_VAL; k < 2 * nr; ++k) *remax = fmax(*remax, (double)sre[k]);
    for (k = 0; k < (c->d == 3 ? nv : 2 * nr) && (nl < CR_NW || (c->d == 3 && nf < CR_NW)); ++k) {
        int isflap = 0;
        if (sim[k] <= 0) continue;
        if (c->d == 3) { /* mode in q: N x; share of the z components */
            double ez = 0, et = 0;
            for (i = 0; i < n; ++i) {
                double xr = 0, xi = 0, e;
                int j;
                for (j = 0; j < nr; ++j) {
                    xr += (double)N[(size_t)i * (size_t)nr + (size_t)j] *
                          (double)Xre[(size_t)j * (size_t)nv + (size_t)k];
                    xi += (double)N[(size_t)i * (size_t)nr + (size_t)j] *
                          (double)Xim[(size_t)j * (size_t)nv + (size_t)k];
                }
                e = xr * xr + xi * xi;
                et += e;
                if (i % 3 == 2) ez += e; /* nodes [r(3), r'(3)]: z at 2 mod 3 */
            }
            isflap = ez > 0.5 * et;
            /* a double frequency (Om = 0: flap and lag coincide, and the
               solver returns any two vectors of their plane): one each */
            if (k > 0 && fabs((double)(sim[k] - wprev)) <= 1e-9 * (double)sim[k])
                isflap = !prevflap;
            wprev = sim[k];
            prevflap = isflap;
        }
        if (isflap) {
            if (nf < CR_NW) flap[nf++] = (double)sim[k];
        } else if (nl < CR_NW) {
            lag[nl++] = (double)sim[k];
        }
    }
done:
    free(v), free(a), free(N), free(Mr), free(Dr), free(Kr), free(w), free(iw);
    free(sre), free(sim), free(Xre), free(Xim);
    return st;
}

#define CR_NOM 27 /* Om = 0, 0.5, ..., 13 rad/s */

/* The sweep over Om[0..nom-1] of ne elements, dimension d, axial
   stiffness eaf EA: steady states
   by continuation (stressed) or the straight unstressed beam; lag and
   flap frequencies per speed, remax (may be NULL) the largest real part
   of the eigenvalues per speed, the CPU time of the sweep. */
static int cr_sweep(int ne, int d, double eaf, int stressed, int nom, const double *Om,
                    double (*lag)[CR_NW], double (*flap)[CR_NW], double *remax, double *cpu)
{
    cr_model *c = (cr_model *)malloc(sizeof *c);
    vlbe_static_params sp;
    vlbe_real q[CR_NQ], lam[8] = {0}, *w = NULL;
    const vlbe_real r0[3] = {0, 0, 0}, dir[3] = {1, 0, 0};
    int *iw = NULL, j, rc = -1;
    size_t lw = 0, liw = 0;
    const clock_t t0 = clock();
    vlbe_static_params_default(&sp);
    if (!c || cr_build(c, ne, d, eaf)) goto done;
    lw = vlbe_static_work_len_sys(&c->rot);
    liw = vlbe_static_iwork_len_sys(&c->rot);
    w = (vlbe_real *)malloc(lw * sizeof *w);
    iw = (int *)malloc(liw * sizeof *iw + sizeof *iw);
    if (!w || !iw || c->m > 8) goto done;
    vlbe_ale_chain_straight(&c->ch, r0, dir, q);
    for (j = 0; j < nom; ++j) {
        c->Om = (vlbe_real)Om[j];
        if (stressed && vlbe_dae_static(&c->rot, &sp, 0, q, lam, NULL, w, lw, iw, liw) != VLBE_OK)
            goto done;
        if (cr_freqs(c, c->Om, q, lam, lag[j], flap[j], remax ? remax + j : NULL) != VLBE_OK)
            goto done;
    }
    rc = 0;
done:
    if (cpu) *cpu = (double)(clock() - t0) / (double)CLOCKS_PER_SEC;
    free(w);
    free(iw);
    free(c);
    return rc;
}

#ifndef VLBE_EXAMPLE_NO_MAIN
#include "../scenes/svgplot.h"

static void cr_row(const char *what, double exact, double ours, double cpu)
{
    svgp_compare_row(stdout, "campbell rotating", what, exact, ours, fabs(ours - exact) / exact,
                     cpu);
}

int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : "out";
    const double u = cr_unit();
    static double Om[CR_NOM], ex[4][CR_NOM], l2[CR_NOM][CR_NW], f2[CR_NOM][CR_NW],
        l3[CR_NOM][CR_NW], f3[CR_NOM][CR_NW], lu[CR_NOM][CR_NW], fu[CR_NOM][CR_NW], reu[CR_NOM];
    static double col[12][CR_NOM];
    double cpu2 = 0, cpu3 = 0, cpuu = 0, cpue, w0;
    char what[160], path[512];
    int j, k, ne;
    clock_t t0;
    for (j = 0; j < CR_NOM; ++j) Om[j] = 0.5 * j;
    t0 = clock();
    for (j = 0; j < CR_NOM; ++j) { /* exact, physical units */
        ex[0][j] = u * ex_cant_rot(1, Om[j] / u, 0);
        ex[1][j] = u * ex_cant_rot(2, Om[j] / u, 0);
        ex[2][j] = u * ex_cant_rot(1, Om[j] / u, 1);
        ex[3][j] = u * ex_cant_rot(2, Om[j] / u, 1);
    }
    cpue = (double)(clock() - t0) / (double)CLOCKS_PER_SEC;
    w0 = ex[0][0];
    printf("Campbell diagram of a rotating cantilever (L = 10 m, EI = 1.4e4 N m^2, rhoA = 1.2 "
           "kg/m; w0 = %.6f rad/s, unit sqrt(EI/(rhoA L^4)) = %.6f rad/s)\n", w0, u);
    if (cr_sweep(16, 2, 1.0, 1, CR_NOM, Om, l2, f2, NULL, &cpu2) || cr_sweep(16, 3, 1.0, 1, CR_NOM, Om, l3, f3, NULL, &cpu3) ||
        cr_sweep(16, 2, 1.0, 0, CR_NOM, Om, lu, fu, reu, &cpuu)) {
        printf("campbell_rotating: a sweep failed\n");
        return 1;
    }
    printf("exact frequencies by shooting: %.3f s for %d roots\n", cpue, 4 * CR_NOM);
    printf("16 elements; CPU of a sweep of %d speeds (steady state, linearisation, eigen): "
           "planar %.3f s, 3D %.3f s, unstressed planar %.3f s\n", CR_NOM, cpu2, cpu3, cpuu);
    printf("  Om [rad/s]   flap1 exact / 3D      flap2 exact / 3D      lag1 exact / 3D / planar"
           "          lag2 exact / 3D / planar        lag1 unstressed\n");
    for (j = 0; j < CR_NOM; j += 2)
        printf("  %5.1f   %9.5f %9.5f   %9.5f %9.5f   %9.5f %9.5f %9.5f   %9.5f %9.5f %9.5f   %9.5f\n",
               Om[j], ex[0][j], f3[j][0], ex[1][j], f3[j][1], ex[2][j], l3[j][0], l2[j][0], ex[3][j],
               l3[j][1], l2[j][1], lu[j][0]);
    for (j = 0; j < CR_NOM; j += 8) {
        snprintf(what, sizeof what, "flap 1 [rad/s] at Om = %g rad/s (3D, 16 el.)", Om[j]);
        cr_row(what, ex[0][j], f3[j][0], cpu3 / CR_NOM);
        snprintf(what, sizeof what, "flap 2 [rad/s] at Om = %g rad/s (3D, 16 el.)", Om[j]);
        cr_row(what, ex[1][j], f3[j][1], cpu3 / CR_NOM);
        snprintf(what, sizeof what, "lag 1 [rad/s] at Om = %g rad/s (3D, 16 el.)", Om[j]);
        cr_row(what, ex[2][j], l3[j][0], cpu3 / CR_NOM);
        snprintf(what, sizeof what, "lag 1 [rad/s] at Om = %g rad/s (planar, 16 el.)", Om[j]);
        cr_row(what, ex[2][j], l2[j][0], cpu2 / CR_NOM);
    }
    j = CR_NOM - 1;
    snprintf(what, sizeof what, "flap 1 [rad/s] at Om = %g rad/s (3D, 16 el.)", Om[j]);
    cr_row(what, ex[0][j], f3[j][0], cpu3 / CR_NOM);
    snprintf(what, sizeof what, "lag 1 [rad/s] at Om = %g rad/s (planar, 16 el.)", Om[j]);
    cr_row(what, ex[2][j], l2[j][0], cpu2 / CR_NOM);
    for (j = 2; j <= 6; j += 4) {
        const double e = sqrt(w0 * w0 - Om[j] * Om[j]);
        snprintf(what, sizeof what,
                 "linear floating frame: lag 1 [rad/s] at Om = %g rad/s vs sqrt(w0^2 - Om^2)", Om[j]);
        cr_row(what, e, lu[j][0], cpuu / CR_NOM);
    }
    printf("mesh convergence at Om = 10 rad/s (3D; flap 1, lag 1; relative errors):\n");
    for (ne = 2; ne <= 16; ne *= 2) {
        double o = 10.0, l[1][CR_NW], f[1][CR_NW], cpu = 0;
        if (cr_sweep(ne, 3, 1.0, 1, 1, &o, l, f, NULL, &cpu)) return 1;
        printf("  %2d elements  flap1 %.9f (%.2e)  lag1 %.9f (%.2e)\n", ne, f[0][0],
               fabs(f[0][0] - ex[0][20]) / ex[0][20], l[0][0], fabs(l[0][0] - ex[2][20]) / ex[2][20]);
        snprintf(what, sizeof what, "flap 1 [rad/s] at Om = 10 rad/s, %d elements", ne);
        cr_row(what, ex[0][20], f[0][0], cpu);
    }
    printf("extensibility: lag 1 at Om = 10 rad/s (planar, 16 elements) against the "
           "inextensible exact %.9f rad/s:\n", ex[2][20]);
    for (k = 0; k < 4; ++k) {
        const double eaf = k == 0 ? 1.0 : k == 1 ? 10.0 : k == 2 ? 100.0 : 1000.0;
        double o = 10.0, l[1][CR_NW], f[1][CR_NW], cpu = 0;
        if (cr_sweep(16, 2, eaf, 1, 1, &o, l, f, NULL, &cpu)) return 1;
        printf("  EA x %6g  lag1 %.9f (%.2e)\n", eaf, l[0][0], fabs(l[0][0] - ex[2][20]) / ex[2][20]);
        snprintf(what, sizeof what, "lag 1 [rad/s] at Om = 10 rad/s, planar 16 el., EA x %g", eaf);
        cr_row(what, ex[2][20], l[0][0], cpu);
    }
    for (j = 1; j < CR_NOM && reu[j] <= 1e-3 * w0; ++j) {}
    if (j < CR_NOM)
        printf("linear floating frame: stable (max Re s = %.2e) up to Om = %g rad/s, unstable "
               "(max Re s = %.4f 1/s) from Om = %g rad/s; w0 = %.6f rad/s\n", reu[j - 1], Om[j - 1],
               reu[j], Om[j], w0);
    for (j = 0; j < CR_NOM; ++j) {
        col[0][j] = Om[j];
        for (k = 0; k < 4; ++k) col[1 + k][j] = ex[k][j];
        col[5][j] = f3[j][0];
        col[6][j] = f3[j][1];
        col[7][j] = l3[j][0];
        col[8][j] = l3[j][1];
        col[9][j] = l2[j][0];
        col[10][j] = l2[j][1];
        col[11][j] = lu[j][0];
    }
    {
        const double *cols[12];
        svgp_chart ch;
        static double y1[2] = {0, 13}, x1[2] = {0, 13}, X[2 * CR_NOM + 1], Y[5][2 * CR_NOM + 1];
        for (k = 0; k < 12; ++k) cols[k] = col[k];
        snprintf(path, sizeof path, "%s/campbell_rotating.csv", dir);
        if (svgp_csv_write(path,
                           "Om,flap1_exact,flap2_exact,lag1_exact,lag2_exact,flap1_3d,flap2_3d,"
                           "lag1_3d,lag2_3d,lag1_planar,lag2_planar,lag1_unstressed",
                           12, CR_NOM, cols))
            printf("# could not write %s\n", path);
        for (k = 0; k < 5; ++k) { /* modes 1 and 2 as one series, NaN between */
            static const int src[5][2] = {{1, 2}, {3, 4}, {5, 6}, {7, 8}, {9, 10}};
            for (j = 0; j < CR_NOM; ++j) {
                X[j] = X[CR_NOM + 1 + j] = Om[j];
                Y[k][j] = col[src[k][0]][j];
                Y[k][CR_NOM + 1 + j] = col[src[k][1]][j];
            }
            X[CR_NOM] = Y[k][CR_NOM] = NAN;
        }
        svgp_init(&ch, "Rotating cantilever: Campbell diagram (16 ANCF elements vs exact)",
                  "spin speed Om [rad/s]", "frequency [rad/s]", 0, 0);
        svgp_series(&ch, "flap 1, 2 exact", 2 * CR_NOM + 1, X, Y[0], 0);
        svgp_series(&ch, "lag 1, 2 exact (w^2 = w_flap^2 - Om^2)", 2 * CR_NOM + 1, X, Y[1],
                    SVGP_DASH);
        svgp_series(&ch, "flap, 3D beam-shaft", 2 * CR_NOM + 1, X, Y[2], SVGP_NOLINE);
        svgp_series(&ch, "lag, 3D beam-shaft", 2 * CR_NOM + 1, X, Y[3], SVGP_NOLINE);
        svgp_series(&ch, "lag, planar", 2 * CR_NOM + 1, X, Y[4], SVGP_NOLINE);
        svgp_series(&ch, "lag 1, linear floating frame (no stiffening)", 8, Om, col[11], SVGP_DOT);
        svgp_series(&ch, "w = Om (once per revolution)", 2, x1, y1, SVGP_DOT);
        ch.legend = SVGP_LEGEND_TL;
        svgp_xrange(&ch, 0, 13);
        svgp_yrange(&ch, 0, 60);
        snprintf(path, sizeof path, "%s/campbell_rotating.svg", dir);
        if (svgp_write_file(&ch, path)) printf("# could not write %s\n", path);
    }
    return 0;
}
#endif /* VLBE_EXAMPLE_NO_MAIN */
