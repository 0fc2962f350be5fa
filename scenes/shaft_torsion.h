/* shaft_torsion.h -- the free torsional vibration of the clamped shaft
   (vlbse section 4.2, Tables 2 and 3): the paper's table, the closed forms
   (st_f_exact, st_f_lin, st_f_trap), the VLBSE chain (st_build, st_band),
   the linearised frequencies (st_linear, st_geig, st_eigen) and the time
   histories with their spectral peaks (st_history, st_hist_freqs,
   st_dft_peak).  Shared by examples/shaft_torsion.c, which states the
   scene and its closed forms, tests/test_scenes_torsion.c and
   tests/test_scenes_band.c.
   -- part of vlbe                                  SPDX-License-Identifier: MIT */
#ifndef VLBE_SCENE_SHAFT_TORSION_H
#define VLBE_SCENE_SHAFT_TORSION_H

#include "../ancf_ale.h"
#include "ex_ale.h"
#include "ex_freq.h"
#include "ex_run.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

/* Table 2 */
#define ST_L 1.0
#define ST_R 0.005
#define ST_RHO 2700.0
#define ST_E 70e9
#define ST_NU 0.3

#define ST_NMODE 5      /* modes compared (Table 3)                              */
#define ST_NE_MAX 40    /* elements, at most                                    */
#define ST_NQ (7 * (ST_NE_MAX + 1)) /* coordinates, at most                     */
#define ST_AMP 1e-2     /* twist amplitude of each excited mode [rad]           */
#define ST_DT 1e-5      /* sampling of the histories [s] (the paper's, as read) */
#define ST_T 0.1        /* record length [s] (the paper's, as read)             */
#define ST_BAND 0.05    /* half width of the search band, relative              */
#define ST_PI 3.14159265358979323846

/* Table 3 of the paper (0: "--") */
static const double st_paper[10][ST_NMODE] = {
    {869.9, 0, 0, 0, 0},
    {809.9, 2829.7, 0, 0, 0},
    {799.9, 2609.7, 4739.5, 0, 0},
    {789.9, 2509.7, 4549.5, 6589.3, 0},
    {789.9, 2459.8, 4349.6, 6529.3, 8399.2},
    {789.9, 2429.8, 4229.6, 6279.4, 8489.2},
    {789.9, 2409.8, 4159.6, 6089.4, 8249.2},
    {789.9, 2399.8, 4109.6, 5959.4, 8019.2},
    {789.9, 2389.8, 4069.6, 5869.4, 7839.2},
    {789.9, 2389.8, 4049.6, 5809.4, 7699.2}};

/* -- the continuum and the closed form of the linear element ------------ */
static inline double st_c(void) { return sqrt(ST_E / (2.0 * (1.0 + ST_NU)) / ST_RHO); }

/* eq. 58 */
static inline double st_f_exact(int i) { return (2.0 * i - 1.0) * st_c() / (4.0 * ST_L); }

/* f_i of N linear elements with consistent mass (see the top of
   examples/shaft_torsion.c) */
static inline double st_f_lin(int ne, int i)
{
    const double h = ST_L / ne, s = sin((2.0 * i - 1.0) * ST_PI * h / (4.0 * ST_L));
    return st_c() / (ST_PI * h) * s * sqrt(3.0 / (3.0 - 2.0 * s * s));
}

/* the trapezoidal rule's frequency of a mode f at step h (see the top of
   examples/shaft_torsion.c) */
static inline double st_f_trap(double f, double h) { return atan(ST_PI * f * h) / (ST_PI * h); }

/* the DFT bin of the paper's record as we read it: 1/(10001 x 10 us) */
static inline double st_bin(void) { return 1.0 / ((ST_T / ST_DT + 1.0) * ST_DT); }

/* -- the model ----------------------------------------------------------- */
typedef struct st_model {
    vlbe_ale3_elem el;
    vlbe_ale_node node[ST_NE_MAX + 1];
    vlbe_ale_con con[3];
    vlbe_ale_chain ch;
    vlbe_dae sys;
    int ne;
    int order[ST_NQ + 7]; /* st_band: the augmented order (7 constraint rows) */
} st_model;

/* ne elements; q0 (may be NULL): the straight state; v0 (may be NULL): at
   rest, or with `excite` the twist rates of the first five modes. */
static inline int st_build(st_model *m, int ne, vlbe_real *q0, vlbe_real *v0, int excite)
{
    vlbe_ale3_mat mat;
    vlbe_ale_con c;
    int i, k;
    if (ne < 1 || ne > ST_NE_MAX) return -1;
    memset(m, 0, sizeof *m);
    m->ne = ne;
    if (vlbe_ale3_mat_circle(&mat, (vlbe_real)ST_RHO, (vlbe_real)ST_E,
                             (vlbe_real)(ST_E / (2.0 * (1.0 + ST_NU))), (vlbe_real)ST_R) ||
        vlbe_ale3_elem_init(&m->el, &mat, VLBE_ALE_NO_DAMP, 0, 0))
        return -1;
    for (i = 0; i <= ne; ++i) {
        m->node[i].pmode = VLBE_ALE_PFIXED;
        m->node[i].p = (vlbe_real)(ST_L * i / ne);
    }
    if (vlbe_ale_chain_init3(&m->ch, &m->el, m->node, ne + 1, ST_NE_MAX + 1, m->con, 3))
        return -1;
    memset(&c, 0, sizeof c);
    c.type = VLBE_ALE_CON_POS; /* r_0 = 0 */
    if (vlbe_ale_chain_add(&m->ch, &c)) return -1;
    c.type = VLBE_ALE_CON_SLOPE; /* r_0' = e_x: with POS a clamp */
    c.d[0] = VLBE_R(1.0);
    if (vlbe_ale_chain_add(&m->ch, &c)) return -1;
    memset(&c, 0, sizeof c);
    c.type = VLBE_ALE_CON_SPIN; /* theta_0 = 0 */
    if (vlbe_ale_chain_add(&m->ch, &c) || vlbe_ale_chain_layout(&m->ch)) return -1;
    if (vlbe_ale_chain_dae(&m->ch, &m->sys)) return -1;
    m->sys.flags = VLBE_DAE_MASS_CONST; /* every p fixed: M constant */
    if (q0) {
        const vlbe_real r0[3] = {0, 0, 0}, dir[3] = {1, 0, 0};
        vlbe_ale_chain_straight(&m->ch, r0, dir, q0);
    }
    if (v0) {
        for (i = 0; i < m->ch.n; ++i) v0[i] = VLBE_R(0.0);
        for (i = 1; excite && i <= ne; ++i) {
            const double x = ST_L * i / ne;
            double s = 0.0;
            for (k = 1; k <= ST_NMODE && k <= ne; ++k) {
                const double kk = (2.0 * k - 1.0) * ST_PI / (2.0 * ST_L);
                s += ST_AMP * st_c() * kk * sin(kk * x);
            }
            v0[m->node[i].ofs + 6] = (vlbe_real)s;
        }
    }
    return 0;
}

/* Banded matrices (vlbe_ale_chain_band) and the integrators' banded path
   for a model st_build made (its q0, v0 stay valid); 0 on success. */
static inline int st_band(st_model *m)
{
    if (ex_ale_band(&m->ch, m->order, (int)(sizeof m->order / sizeof m->order[0]))) return -1;
    ex_ale_storage(&m->sys, &m->ch);
    return 0;
}

/* index of node i's theta */
static inline int st_theta(const st_model *m, int i) { return m->node[i].ofs + 6; }

/* The linearisation at the straight state: K0 = -dQ/dq, M, Q (n x n, n x
   n, n; the chain's n); fr[0..*nf-1]: the coordinates the constraints leave
   free (each constraint row must fix one coordinate: a single entry 1 in
   C_q).  0 on success. */
static inline int st_linear(st_model *m, vlbe_real *K0, vlbe_real *M, vlbe_real *Q, int *fr,
                            int *nf)
{
    const int n = m->ch.n, nc = m->ch.m;
    vlbe_real q[ST_NQ], v[ST_NQ], *D = (vlbe_real *)malloc((size_t)n * n * sizeof *D);
    vlbe_real *Cq = (vlbe_real *)malloc((size_t)nc * n * sizeof *Cq);
    const vlbe_real r0[3] = {0, 0, 0}, dir[3] = {1, 0, 0};
    int i, j, rc = -1, fixed[ST_NQ];
    if (!D || !Cq) goto done;
    vlbe_ale_chain_straight(&m->ch, r0, dir, q);
    for (i = 0; i < n; ++i) v[i] = VLBE_R(0.0), fixed[i] = 0;
    if (vlbe_ale_chain_force_jac(&m->ch, VLBE_R(0.0), q, v, K0, D) ||
        vlbe_ale_chain_mass(&m->ch, VLBE_R(0.0), q, v, M) ||
        vlbe_ale_chain_force(&m->ch, VLBE_R(0.0), q, v, Q) ||
        vlbe_ale_chain_constr_jac(&m->ch, VLBE_R(0.0), q, Cq, NULL))
        goto done;
    for (i = 0; i < n * n; ++i) K0[i] = -K0[i];
    for (i = 0; i < nc; ++i) {
        int cnt = 0, col = -1;
        for (j = 0; j < n; ++j)
            if (Cq[(size_t)i * n + j] != VLBE_R(0.0)) ++cnt, col = j;
        if (cnt != 1 || Cq[(size_t)i * n + col] != VLBE_R(1.0) || fixed[col]) goto done;
        fixed[col] = 1;
    }
    for (*nf = 0, i = 0; i < n; ++i)
        if (!fixed[i]) fr[(*nf)++] = i;
    rc = 0;
done:
    free(D);
    free(Cq);
    return rc;
}

/* Generalized eigenproblem K x = w^2 M x on the coordinates idx[0..k-1]
   (vlbe_eig_gsym, shift-invert with sigma = 0: the lowest modes accurately);
   f[0..k-1] ascending [Hz]; share (may be NULL): the share of x^T M x
   of each mode on the theta coordinates (tmask[i] != 0 for coordinate i).
   0 on success. */
static inline int st_geig(int n, const vlbe_real *K0, const vlbe_real *M, const int *idx, int k,
                          const int *tmask, double *f, double *share)
{
    const size_t K = (size_t)k, lw = vlbe_eig_work_len(k);
    vlbe_real *A = (vlbe_real *)calloc(K * K, sizeof *A); /* calloc: gcc -O1 cannot see */
    vlbe_real *B = (vlbe_real *)calloc(K * K, sizeof *B); /* the loops below fill them  */
    vlbe_real *X = (vlbe_real *)malloc(K * K * sizeof *X);
    vlbe_real *lam = (vlbe_real *)malloc(K * sizeof *lam);
    vlbe_real *w = (vlbe_real *)malloc(lw * sizeof *w);
    size_t a, b, j;
    int info, rc = -1;
    if (k < 1 || !A || !B || !lam || !X || !w) goto done;
    for (a = 0; a < K; ++a)
        for (b = 0; b < K; ++b) {
            A[a * K + b] = M[(size_t)idx[a] * (size_t)n + (size_t)idx[b]];
            B[a * K + b] = K0[(size_t)idx[a] * (size_t)n + (size_t)idx[b]];
        }
    if (vlbe_eig_gsym(k, B, A, VLBE_R(0.0), lam, share ? X : NULL, &info, w, lw) != VLBE_OK)
        goto done;
    for (j = 0; j < K; ++j) { /* lam = w^2 ascending */
        const size_t c = j;
        f[j] = sqrt((double)lam[c]) / (2.0 * ST_PI);
        if (share) {
            double all = 0.0, th = 0.0;
            for (a = 0; a < K; ++a)
                for (b = 0; b < K; ++b) {
                    const double e =
                        (double)X[a * K + c] * (double)A[a * K + b] * (double)X[b * K + c];
                    all += e;
                    if (tmask[idx[a]] && tmask[idx[b]]) th += e;
                }
            share[j] = th / all;
        }
    }
    rc = 0;
done:
    free(A);
    free(B);
    free(lam);
    free(X);
    free(w);
    return rc;
}

/* What the linearised chain of ne elements gives: the torsional
   frequencies from the theta block (ft[0..ne-1]), and, when fa != NULL,
   the full reduced problem: the torsional frequencies picked by theta
   share > 1/2 (fa[0..*na-1]), the largest deviation of any share from 0 or
   1 (*dshare); coupling (may be NULL): max |entry| of the K0 and M blocks
   between theta and the other coordinates, relative to max |K0|, max |M|;
   *qmax: max |Q| at the straight state.  0 on success. */
typedef struct st_eig_out {
    double ft[ST_NE_MAX], fa[ST_NE_MAX];
    int na, nfree;
    double dshare, kc, mc, qmax;
} st_eig_out;

static inline int st_eigen(int ne, int full, st_eig_out *o)
{
    st_model *m = (st_model *)malloc(sizeof *m);
    vlbe_real *K0 = NULL, *M = NULL, Q[ST_NQ];
    int fr[ST_NQ], tm[ST_NQ], ti[ST_NE_MAX], i, j, n, nf, nt = 0, rc = -1;
    double *fall = NULL, *sh = NULL, kmax = 0.0, mmax = 0.0;
    memset(o, 0, sizeof *o);
    if (!m || st_build(m, ne, NULL, NULL, 0)) goto done;
    n = m->ch.n;
    K0 = (vlbe_real *)malloc((size_t)n * n * sizeof *K0);
    M = (vlbe_real *)malloc((size_t)n * n * sizeof *M);
    fall = (double *)malloc((size_t)n * sizeof *fall);
    sh = (double *)malloc((size_t)n * sizeof *sh);
    if (!K0 || !M || !fall || !sh || st_linear(m, K0, M, Q, fr, &nf)) goto done;
    o->nfree = nf;
    for (i = 0; i < n; ++i) tm[i] = 0;
    for (i = 0; i <= ne; ++i) tm[st_theta(m, i)] = 1;
    for (j = 0; j < nf; ++j)
        if (tm[fr[j]]) ti[nt++] = fr[j];
    if (nt != ne || st_geig(n, K0, M, ti, nt, tm, o->ft, NULL)) goto done;
    for (i = 0; i < n; ++i) {
        o->qmax = fmax(o->qmax, fabs((double)Q[i]));
        for (j = 0; j < n; ++j) {
            const double k = fabs((double)K0[i * n + j]), mm = fabs((double)M[i * n + j]);
            kmax = fmax(kmax, k);
            mmax = fmax(mmax, mm);
            if (tm[i] != tm[j]) o->kc = fmax(o->kc, k), o->mc = fmax(o->mc, mm);
        }
    }
    o->kc /= kmax;
    o->mc /= mmax;
    if (full) {
        if (st_geig(n, K0, M, fr, nf, tm, fall, sh)) goto done;
        for (j = 0; j < nf; ++j) {
            o->dshare = fmax(o->dshare, fmin(sh[j], fabs(1.0 - sh[j])));
            if (sh[j] > 0.5 && o->na < ST_NE_MAX) o->fa[o->na++] = fall[j];
        }
    }
    rc = 0;
done:
    free(K0);
    free(M);
    free(fall);
    free(sh);
    free(m);
    return rc;
}

/* -- time histories ------------------------------------------------------ */
typedef struct st_hist {
    double dt;            /* sampling interval               */
    size_t n, cap;        /* samples                         */
    double *y;            /* theta at the free end [rad]     */
    int idx, every;       /* coordinate, steps per sample    */
    long k;
    double cpu;
    vlbe_dae_stats stats;
} st_hist;

static inline vlbe_status st_observe(void *ctx, double t, const vlbe_real *q, const vlbe_real *v,
                                     const vlbe_real *lam)
{
    st_hist *o = (st_hist *)ctx;
    (void)t, (void)v, (void)lam;
    if (o->k++ % o->every == 0 && o->n < o->cap) o->y[o->n++] = (double)q[o->idx];
    return VLBE_OK;
}

/* Free vibration of ne elements from the five-mode start, trapezoidal rule
   with step h = dt / every over T, theta at the free end every dt (o->y is
   malloc'ed: free it); band: banded matrices (st_band).  Returns the run
   status. */
static inline vlbe_status st_history_run(int ne, double dt, int every, double T, int band,
                                         st_hist *o)
{
    st_model *m = (st_model *)malloc(sizeof *m);
    vlbe_real q0[ST_NQ], v0[ST_NQ];
    vlbe_hht_params par;
    ex_method meth;
    ex_run_out out;
    vlbe_status st = VLBE_EWORK;
    memset(o, 0, sizeof *o);
    o->dt = dt;
    o->every = every;
    o->cap = (size_t)(T / dt + 1.5);
    o->y = (double *)malloc(o->cap * sizeof *o->y);
    if (!m || !o->y) goto done;
    st = VLBE_EARG;
    if (st_build(m, ne, q0, v0, 1) || (band && st_band(m))) goto done;
    o->idx = st_theta(m, ne);
    ex_hht_pick(&par, 0.0, 0.0); /* trapezoidal Newmark */
    memset(&meth, 0, sizeof meth);
    meth.hht = &par;
    meth.h = dt / every;
    st = ex_run(&m->sys, &meth, q0, v0, T, st_observe, o, NULL, NULL, NULL, &out);
    o->cpu = out.cpu;
    o->stats = out.stats;
done:
    free(m);
    return st;
}

/* the scene's run: dense matrices */
static inline vlbe_status st_history(int ne, double dt, int every, double T, st_hist *o)
{
    return st_history_run(ne, dt, every, T, 0, o);
}

/* frequencies of the history near fe[0..nm-1] (ex_peak_freq in the bands
   fe (1 +- ST_BAND)); 0 on success */
static inline int st_hist_freqs(const st_hist *o, const double *fe, int nm, double *f)
{
    double *w = (double *)malloc(o->n * sizeof *w);
    int i;
    if (!w) return -1;
    for (i = 0; i < nm; ++i)
        f[i] = ex_peak_freq(o->y, o->n, o->dt, fe[i] * (1.0 - ST_BAND), fe[i] * (1.0 + ST_BAND), w);
    free(w);
    return 0;
}

/* The plain DFT (rectangular window) of the record at its bins k/(n dt):
   the bin frequency of the largest |X_k| in [flo, fhi]. */
static inline double st_dft_peak(const st_hist *o, double flo, double fhi)
{
    const size_t n = o->n;
    const double df = 1.0 / ((double)n * o->dt);
    size_t k, j, kb = 0;
    double best = -1.0;
    for (k = (size_t)ceil(flo / df); (double)k * df <= fhi; ++k) {
        double re = 0.0, im = 0.0, p;
        for (j = 0; j < n; ++j) { /* exact phase: (k j) mod n */
            const double a = 2.0 * ST_PI * (double)((k * j) % n) / (double)n;
            re += o->y[j] * cos(a);
            im -= o->y[j] * sin(a);
        }
        p = re * re + im * im;
        if (p > best) best = p, kb = k;
    }
    return (double)kb * df;
}

#endif /* VLBE_SCENE_SHAFT_TORSION_H */
