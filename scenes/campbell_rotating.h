/* campbell_rotating.h -- the rotating cantilever of the Campbell diagram:
   its planar and 3D (no spin angle) ANCF chains clamped on the hub axis
   (cr_build), the steady rotating state, the linearisation in the turning
   frame and the lag and flap frequencies (cr_freqs), the sweep over the
   spin speed (cr_sweep).  Shared by examples/campbell_rotating.c, which
   states the beam, the method and the exact frequencies, and
   tests/test_modal.c.
   -- part of vlbe                                  SPDX-License-Identifier: MIT */
#ifndef VLBE_SCENE_CAMPBELL_ROTATING_H
#define VLBE_SCENE_CAMPBELL_ROTATING_H

#include "../ancf_ale.h"
#include "../integrators.h"
#include "ex_cant.h"

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
static inline void cr_proj(const cr_model *c, const vlbe_real *q, vlbe_real *Pq)
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
static inline int cr_force(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v,
                           vlbe_real *Q)
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

static inline int cr_force_jac(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v,
                               vlbe_real *K, vlbe_real *D)
{
    cr_model *c = (cr_model *)((vlbe_ale_chain *)u)->user;
    int rc = c->sys.force_jac(c->sys.user, t, q, v, K, D), i, k;
    if (rc) return rc;
    if ((rc = c->sys.mass(c->sys.user, t, q, v, c->M)) != 0) return rc;
    for (i = 0; i < c->n; ++i) /* d(Om^2 M P q)/dq = Om^2 M P */
        for (k = 0; k < 2 * (c->ne + 1); ++k) {
            const int j = c->vec[k];
            K[(size_t)i * (size_t)c->n + (size_t)j] +=
                c->Om * c->Om * c->M[(size_t)i * (size_t)c->n + (size_t)j];
            K[(size_t)i * (size_t)c->n + (size_t)j + 1] +=
                c->Om * c->Om * c->M[(size_t)i * (size_t)c->n + (size_t)j + 1];
        }
    return 0;
}

/* ne elements, planar (d = 2) or 3D without spin angle (d = 3), along x
   from the origin, clamped there; the axial stiffness is eaf EA (eaf = 1:
   the scene's). */
static inline int cr_build(cr_model *c, int ne, int d, double eaf)
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
static inline vlbe_status cr_freqs(cr_model *c, vlbe_real Om, const vlbe_real *q,
                                   const vlbe_real *lam, double *lag, double *flap, double *remax)
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
static inline int cr_sweep(int ne, int d, double eaf, int stressed, int nom, const double *Om,
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

#endif /* VLBE_SCENE_CAMPBELL_ROTATING_H */
