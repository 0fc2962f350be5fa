/* test_dae_band.c -- cmocka suite of the banded path of integrators.h
   (vlbe_dae.storage = VLBE_DAE_BANDED) and of the caller's own linear
   solver (lin_factor, lin_solve) -- part of vlbe
                                                   SPDX-License-Identifier: MIT
   cc -std=c99 -Wall -Wextra -Wpedantic ... -O2 tests/test_dae_band.c -lcmocka -lm

   The problem: a chain of P point masses hanging from the origin by rigid
   links (constraint k: |r_k - r_{k-1}|^2 - l^2 = 0, r_{-1} = 0), with
   springs between every mass and the next but one (a bending-like coupling
   that widens the band), gravity, a viscous damper on each mass, and a
   mass matrix that depends on q (m_i (1 + e x_i^2) on both coordinates of
   mass i), so that every Jacobian term of the iteration matrices is
   present: K, D, d(Ma)/dq, d(C_q^T lambda)/dq, d(C_q v)/dq.  The same
   element loop fills the dense matrices and the band ones (augmented order
   node by node: x_i, y_i, lambda_i at 3i, 3i+1, 3i+2: kl = ku = 7 from the
   springs i..i+2, whatever P).  The banded path must give the dense path's
   answer to rounding: every comparison below bounds the difference by a
   multiple of eps times the size of the quantity and the conditioning of
   the run, stated at each.

   Tests
     band_consistent_acc      q'', lambda at a start: banded = dense
     band_static              static equilibrium: banded = dense, and the
                              analytic straight hanging chain (lambda_k)
     band_hht_run             200 HHT steps: banded = dense (analytic and
                              difference Jacobians, the latter by column
                              groups), counters equal; reuse_max bounds
     band_bdf_run             BDF to t = 1: banded = dense
     band_user_solver         lin_factor / lin_solve (a dense LU of the
                              expanded band) = the built-in band LU path;
                              a singular report -> ESINGULAR, a fatal one ->
                              ECALLBACK
     band_args                order not a permutation, kl out of range,
                              storage unknown, only one of lin_factor and
                              lin_solve -> EARG; workspace of the (n, m)
                              query is enough, the _sys query smaller */
#include "test_util.h"
#include "../integrators.h"

#include <string.h>

#define EPS ((double)VLBE_EPS)

enum { PMAX = 24, NMAX = 2 * PMAX, MMAX = PMAX, NAMAX = NMAX + MMAX };

typedef struct chain {
    int P, band;       /* masses; 1: callbacks write bands */
    int order[NAMAX];  /* x_i -> 3i, y_i -> 3i+1, lambda_i -> 3i+2 */
    vlbe_real l, mass, e, ks, c, g;
} chain;

/* one entry (i, j) of an n x n matrix (row i of C_q: i = n + k) */
static void put(const chain *ch, vlbe_real *A, int i, int j, vlbe_real x)
{
    int n = 2 * ch->P;
    if (ch->band) {
        A[VLBE_BAND_IDX(15, 7, ch->order[i], ch->order[j])] += x;
    } else if (i >= n) {
        A[(size_t)(i - n) * (size_t)n + (size_t)j] += x;
    } else {
        A[(size_t)i * (size_t)n + (size_t)j] += x;
    }
}
static void clear(const chain *ch, vlbe_real *A, int cq)
{
    int n = 2 * ch->P, m = ch->P;
    size_t len = ch->band ? (size_t)(n + m) * 15u : (size_t)(cq ? m : n) * (size_t)n;
    memset(A, 0, len * sizeof *A);
}

static int ch_mass(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v, vlbe_real *M)
{
    const chain *ch = (const chain *)u;
    int i;
    (void)t, (void)v;
    clear(ch, M, 0);
    for (i = 0; i < 2 * ch->P; ++i) {
        vlbe_real x = q[2 * (i / 2)];
        put(ch, M, i, i, ch->mass * (VLBE_R(1.0) + ch->e * x * x));
    }
    return 0;
}
static int ch_mass_jac(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v,
                       const vlbe_real *a, vlbe_real *Mq, vlbe_real *Mv)
{
    const chain *ch = (const chain *)u;
    int i;
    (void)t, (void)v, (void)Mv;
    clear(ch, Mq, 0);
    for (i = 0; i < 2 * ch->P; ++i) {
        int jx = 2 * (i / 2);
        put(ch, Mq, i, jx, ch->mass * VLBE_R(2.0) * ch->e * q[jx] * a[i]);
    }
    return 0;
}
/* spring i -- i+2: Q, and K = dQ/dq */
static void spring(const chain *ch, const vlbe_real *q, int i, vlbe_real *Q, vlbe_real *K)
{
    int a = 2 * i, b = 2 * (i + 2), r, s;
    vlbe_real d[2], len, L0 = VLBE_R(2.0) * ch->l, f, kk[2][2];
    d[0] = q[b] - q[a];
    d[1] = q[b + 1] - q[a + 1];
    len = vlbe_sqrt(d[0] * d[0] + d[1] * d[1]);
    f = ch->ks * (len - L0); /* tension */
    if (Q) {
        for (r = 0; r < 2; ++r) {
            Q[a + r] += f * d[r] / len;
            Q[b + r] -= f * d[r] / len;
        }
    }
    if (K) {
        for (r = 0; r < 2; ++r)
            for (s = 0; s < 2; ++s)
                kk[r][s] = ch->ks * d[r] * d[s] / (len * len) +
                           f / len * ((r == s ? VLBE_R(1.0) : VLBE_R(0.0)) - d[r] * d[s] / (len * len));
        for (r = 0; r < 2; ++r)
            for (s = 0; s < 2; ++s) {
                put(ch, K, a + r, a + s, -kk[r][s]);
                put(ch, K, a + r, b + s, kk[r][s]);
                put(ch, K, b + r, a + s, kk[r][s]);
                put(ch, K, b + r, b + s, -kk[r][s]);
            }
    }
}
static int ch_force(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v, vlbe_real *Q)
{
    const chain *ch = (const chain *)u;
    int i;
    (void)t;
    for (i = 0; i < ch->P; ++i) {
        Q[2 * i] = -ch->c * v[2 * i];
        Q[2 * i + 1] = -ch->mass * ch->g - ch->c * v[2 * i + 1];
    }
    for (i = 0; i + 2 < ch->P; ++i) spring(ch, q, i, Q, NULL);
    return 0;
}
static int ch_force_jac(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v,
                        vlbe_real *K, vlbe_real *D)
{
    const chain *ch = (const chain *)u;
    int i;
    (void)t, (void)v;
    clear(ch, K, 0);
    clear(ch, D, 0);
    for (i = 0; i < 2 * ch->P; ++i) put(ch, D, i, i, -ch->c);
    for (i = 0; i + 2 < ch->P; ++i) spring(ch, q, i, NULL, K);
    return 0;
}
/* link k: C_k = (|r_k - r_{k-1}|^2 - l^2) / 2 */
static int ch_constr(void *u, vlbe_real t, const vlbe_real *q, vlbe_real *C)
{
    const chain *ch = (const chain *)u;
    int k;
    (void)t;
    for (k = 0; k < ch->P; ++k) {
        vlbe_real dx = q[2 * k] - (k ? q[2 * k - 2] : VLBE_R(0.0));
        vlbe_real dy = q[2 * k + 1] - (k ? q[2 * k - 1] : VLBE_R(0.0));
        C[k] = VLBE_R(0.5) * (dx * dx + dy * dy - ch->l * ch->l);
    }
    return 0;
}
static int ch_constr_jac(void *u, vlbe_real t, const vlbe_real *q, vlbe_real *Cq, vlbe_real *Ct)
{
    const chain *ch = (const chain *)u;
    int k, n = 2 * ch->P, r;
    (void)t;
    clear(ch, Cq, 1);
    for (k = 0; k < ch->P; ++k) {
        for (r = 0; r < 2; ++r) {
            vlbe_real d = q[2 * k + r] - (k ? q[2 * k - 2 + r] : VLBE_R(0.0));
            put(ch, Cq, n + k, 2 * k + r, d);
            if (k) put(ch, Cq, n + k, 2 * k - 2 + r, -d);
        }
        if (Ct) Ct[k] = VLBE_R(0.0);
    }
    return 0;
}
static int ch_constr_hess(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *lam,
                          vlbe_real *H)
{
    const chain *ch = (const chain *)u;
    int k, r;
    (void)t, (void)q;
    clear(ch, H, 0);
    for (k = 0; k < ch->P; ++k)
        for (r = 0; r < 2; ++r) {
            put(ch, H, 2 * k + r, 2 * k + r, lam[k]);
            if (k) {
                put(ch, H, 2 * k - 2 + r, 2 * k - 2 + r, lam[k]);
                put(ch, H, 2 * k + r, 2 * k - 2 + r, -lam[k]);
                put(ch, H, 2 * k - 2 + r, 2 * k + r, -lam[k]);
            }
        }
    return 0;
}

/* analytic: every Jacobian callback; fd: force_jac, mass_jac, constr_hess
   and constr_acc left to the integrators' differences */
static void ch_setup(chain *ch, vlbe_dae *sys, int P, int band, int analytic)
{
    int i;
    memset(ch, 0, sizeof *ch);
    ch->P = P;
    ch->band = band;
    ch->l = VLBE_R(0.5);
    ch->mass = VLBE_R(2.0);
    ch->e = VLBE_R(0.3);
    ch->ks = VLBE_R(40.0);
    ch->c = VLBE_R(0.7);
    ch->g = VLBE_R(9.81);
    for (i = 0; i < P; ++i) {
        ch->order[2 * i] = 3 * i;
        ch->order[2 * i + 1] = 3 * i + 1;
        ch->order[2 * P + i] = 3 * i + 2;
    }
    memset(sys, 0, sizeof *sys);
    sys->n = 2 * P;
    sys->m = P;
    sys->user = ch;
    sys->mass = ch_mass;
    sys->force = ch_force;
    sys->constr = ch_constr;
    sys->constr_jac = ch_constr_jac;
    if (analytic) {
        sys->force_jac = ch_force_jac;
        sys->mass_jac = ch_mass_jac;
        sys->constr_hess = ch_constr_hess;
    }
    if (band) {
        sys->storage = VLBE_DAE_BANDED;
        sys->kl = sys->ku = 7;
        sys->order = ch->order;
    }
}
/* a start: the chain bent into an arc, at rest except for a swing of the
   last link that keeps C_q v = 0 (v = 0 everywhere but along the normal of
   link P-1 at its end) */
static void ch_start(const chain *ch, vlbe_real *q, vlbe_real *v)
{
    int i, P = ch->P;
    vlbe_real x = VLBE_R(0.0), y = VLBE_R(0.0);
    for (i = 0; i < P; ++i) {
        vlbe_real a = VLBE_R(0.35) + VLBE_R(0.05) * (vlbe_real)i;
        x += ch->l * vlbe_sin(a);
        y -= ch->l * vlbe_cos(a);
        q[2 * i] = x;
        q[2 * i + 1] = y;
        v[2 * i] = v[2 * i + 1] = VLBE_R(0.0);
    }
    {
        vlbe_real dx = q[2 * P - 2] - q[2 * P - 4], dy = q[2 * P - 1] - q[2 * P - 3];
        v[2 * P - 2] = -dy * VLBE_R(0.8);
        v[2 * P - 1] = dx * VLBE_R(0.8);
    }
}

/* multipliers of a start for the static solver (with lambda = 0 the links
   carry no tension and the chain has no stiffness across them: singular):
   half the hanging values */
static void ch_lambda0(const chain *ch, vlbe_real *l)
{
    int k;
    for (k = 0; k < ch->P; ++k)
        l[k] = VLBE_R(0.5) * (vlbe_real)(ch->P - k) * ch->mass * ch->g / ch->l;
}

static double maxdiff(int n, const vlbe_real *a, const vlbe_real *b)
{
    double d = 0.0;
    int i;
    for (i = 0; i < n; ++i) {
        double e = fabs((double)a[i] - (double)b[i]);
        if (e > d) d = e;
    }
    return d;
}
static double maxabs(int n, const vlbe_real *a)
{
    double d = 0.0;
    int i;
    for (i = 0; i < n; ++i)
        if (fabs((double)a[i]) > d) d = fabs((double)a[i]);
    return d;
}

enum { P0 = 12, WL = 200000, IWL = 1000 };
static vlbe_real wd[WL], wb[WL];
static int iwd[IWL], iwb[IWL];

static void test_band_consistent_acc(void **state)
{
    chain cd, cb;
    vlbe_dae sd, sb;
    vlbe_real q[NMAX] = {0}, v[NMAX] = {0}, ad[NMAX], ab[NMAX], ld[MMAX], lb[MMAX];
    int an;
    (void)state;
    for (an = 0; an < 2; ++an) {
        double da, dl;
        ch_setup(&cd, &sd, P0, 0, an);
        ch_setup(&cb, &sb, P0, 1, an);
        ch_start(&cd, q, v);
        assert_int_equal(vlbe_dae_consistent_acc(&sd, 0, q, v, ad, ld, NULL, wd, WL, iwd, IWL),
                         VLBE_OK);
        assert_int_equal(vlbe_dae_consistent_acc(&sb, 0, q, v, ab, lb, NULL, wb, WL, iwb, IWL),
                         VLBE_OK);
        /* two LUs of the same well-conditioned 36 x 36 system with
           different pivot orders: backward stable, so the solutions differ
           by cond eps |x|; the saddle-point matrix of the chain has a
           condition ~1e3 (mass 2 against unit link gradients, P = 12):
           bound 1e4 eps relative */
        da = maxdiff(2 * P0, ad, ab) / maxabs(2 * P0, ad);
        dl = maxdiff(P0, ld, lb) / maxabs(P0, ld);
        tu_report(an ? "consistent_acc qdd" : "consistent_acc qdd (fd gamma)", da, 1e4 * EPS);
        assert_true(da <= 1e4 * EPS);
        assert_true(dl <= 1e4 * EPS);
    }
}

static void test_band_static(void **state)
{
    chain cd, cb;
    vlbe_dae sd, sb;
    vlbe_real qd[NMAX] = {0}, qb[NMAX], v[NMAX] = {0}, ld[MMAX], lb[MMAX];
    vlbe_static_params sp;
    int an, k;
    (void)state;
    vlbe_static_params_default(&sp);
    for (an = 0; an < 2; ++an) {
        double dq, dl;
        ch_setup(&cd, &sd, P0, 0, an);
        ch_setup(&cb, &sb, P0, 1, an);
        ch_start(&cd, qd, v);
        memcpy(qb, qd, sizeof qd);
        ch_lambda0(&cd, ld);
        ch_lambda0(&cd, lb);
        assert_int_equal(vlbe_dae_static(&sd, &sp, 0, qd, ld, NULL, wd, WL, iwd, IWL), VLBE_OK);
        assert_int_equal(vlbe_dae_static(&sb, &sp, 0, qb, lb, NULL, wb, WL, iwb, IWL), VLBE_OK);
        /* both converge to the increment test (rtol 1e-10): the answers
           agree to that tolerance, far above the rounding of either */
        dq = maxdiff(2 * P0, qd, qb);
        dl = maxdiff(P0, ld, lb) / maxabs(P0, ld);
        tu_report("static q banded vs dense", dq, 1e-9);
        assert_true(dq <= 1e-9);
        assert_true(dl <= 1e-8);
        /* the hanging chain is straight down (the springs i..i+2 at rest
           length 2l are then unstressed) and link k carries the weight of
           the masses k..P-1: with C = (|d|^2 - l^2)/2, d_k = (0, -l),
           C_q^T lambda = Q gives lambda_k = (P - k) m g / l; tolerances:
           the increment test rtol 1e-10 times the condition of the
           chain's stiffness (~1e3 between the first and last link) */
        for (k = 0; k < P0; ++k) {
            double ex = (double)(P0 - k) * (double)cb.mass * (double)cb.g / (double)cb.l;
            assert_true(fabs((double)lb[k] - ex) <= 1e-7 * fabs(ex));
            assert_true(fabs((double)qb[2 * k]) <= 1e-9);
            assert_true(fabs((double)qb[2 * k + 1] + (double)(k + 1) * (double)cb.l) <= 1e-9);
        }
    }
}

static void test_band_hht_run(void **state)
{
    chain cd, cb;
    vlbe_dae sd, sb;
    vlbe_real q[NMAX] = {0}, v[NMAX] = {0};
    vlbe_hht_params par;
    vlbe_hht hd, hb;
    int an, k;
    (void)state;
    assert_int_equal(vlbe_hht_params_alpha(&par, VLBE_R(-0.1)), VLBE_OK);
    /* the automatic reuse_max differs with the storage (banded refreshes a
       stale matrix sooner): the same explicit value for both makes the two
       runs take the same decisions */
    par.reuse_max = 2;
    for (an = 0; an < 2; ++an) {
        double dq, qs;
        ch_setup(&cd, &sd, P0, 0, an);
        ch_setup(&cb, &sb, P0, 1, an);
        ch_start(&cd, q, v);
        assert_int_equal(vlbe_hht_init(&hd, &sd, &par, 0, q, v, wd, WL, iwd, IWL), VLBE_OK);
        assert_int_equal(vlbe_hht_init(&hb, &sb, &par, 0, q, v, wb, WL, iwb, IWL), VLBE_OK);
        for (k = 0; k < 200; ++k) {
            assert_int_equal(vlbe_hht_step(&hd, VLBE_R(2e-3)), VLBE_OK);
            assert_int_equal(vlbe_hht_step(&hb, VLBE_R(2e-3)), VLBE_OK);
        }
        /* the two runs solve the same Newton iterations with the same
           increment test; their iterates differ by rounding of the LU
           solves (cond eps) per iteration, which the convergence test can
           amplify only when it flips a decision (then the difference would
           be the test's own tolerance, rtol |q| = 1e-9): equal counters show
           none flipped, and the rounding of 200 steps of a system of
           condition ~1e3 is below 200 x 1e3 eps: bound 4.5e5 eps (1e-10 in
           double) */
        qs = maxabs(2 * P0, hd.q);
        dq = maxdiff(2 * P0, hd.q, hb.q) / qs;
        tu_report(an ? "hht 200 steps q" : "hht 200 steps q (fd jacobians)", dq, 4.5e5 * EPS);
        assert_true(dq <= 4.5e5 * EPS);
        /* lambda (index 3): a rounding e |q| of the positions moves it by
           e |q| m / h^2 against its size P m g / l, a factor l |q| /
           (P g h^2) ~ 1.3e2 over the bound of q */
        dq = maxdiff(P0, hd.lambda, hb.lambda) / maxabs(P0, hd.lambda);
        tu_report("hht 200 steps lambda", dq, 1.3e2 * 4.5e5 * EPS);
        assert_true(dq <= 1.3e2 * 4.5e5 * EPS);
#ifndef VLBE_USE_FLOAT /* float: increments near the rounding floor, a decision may flip */
        assert_int_equal(hd.stats.newton_iters, hb.stats.newton_iters);
        assert_int_equal(hd.stats.lu_factors, hb.stats.lu_factors);
#endif
        /* the band forms its difference Jacobians by column groups:
           kl + ku + 1 = 15 force calls per matrix instead of n = 24 */
        if (!an) assert_true(hb.stats.force_calls < hd.stats.force_calls);
    }
    par.reuse_max = -1;
    assert_int_equal(vlbe_hht_init(&hb, &sb, &par, 0, q, v, wb, WL, iwb, IWL), VLBE_EARG);
    par.reuse_max = VLBE_INT_MAX_ITER + 1;
    assert_int_equal(vlbe_hht_init(&hb, &sb, &par, 0, q, v, wb, WL, iwb, IWL), VLBE_EARG);
}

static void test_band_bdf_run(void **state)
{
    chain cd, cb;
    vlbe_dae sd, sb;
    vlbe_real q[NMAX] = {0}, v[NMAX] = {0};
    vlbe_bdf_params bp;
    vlbe_bdf bd, bb;
    (void)state;
    vlbe_bdf_params_default(&bp);
    bp.rtol = bp.atol = VLBE_R(1e-6);
#ifdef VLBE_USE_FLOAT
    TU_SKIP("BDF at rtol 1e-6 is below what float resolves in this chain");
    return;
#endif
    ch_setup(&cd, &sd, P0, 0, 1);
    ch_setup(&cb, &sb, P0, 1, 1);
    ch_start(&cd, q, v);
    assert_int_equal(vlbe_bdf_init(&bd, &sd, &bp, 0, q, v, wd, WL, iwd, IWL), VLBE_OK);
    assert_int_equal(vlbe_bdf_init(&bb, &sb, &bp, 0, q, v, wb, WL, iwb, IWL), VLBE_OK);
    assert_int_equal(vlbe_bdf_advance(&bd, VLBE_R(1.0)), VLBE_OK);
    assert_int_equal(vlbe_bdf_advance(&bb, VLBE_R(1.0)), VLBE_OK);
    {
        /* the step and order decisions are the same (equal step counts):
           the states then differ by the rounding of the solves, summed over
           the steps (~100, condition ~1e3 of the scaled GGL matrix):
           bound 1e-10 as for HHT */
        double dq = maxdiff(2 * P0, bd.q, bb.q) / maxabs(2 * P0, bd.q);
        tu_report("bdf t=1 q banded vs dense", dq, 1e-10);
        assert_true(dq <= 1e-10);
        assert_int_equal(bd.stats.steps, bb.stats.steps);
    }
}

/* the caller's solver: expands the band into a dense matrix and uses the
   dense LU; `fail` makes the factor report singular (1) or fatal (-1) */
typedef struct usolver {
    vlbe_real A[NAMAX * NAMAX * 4];
    int piv[2 * NAMAX], N, calls, fail;
    chain *ch;
} usolver;
static usolver us;
static int us_factor(void *u, int storage, int N, int kl, int ku, const vlbe_real *A, int lda)
{
    int i, j;
    (void)u;
    ++us.calls;
    if (us.fail) return us.fail;
    us.N = N;
    for (i = 0; i < N; ++i)
        for (j = 0; j < N; ++j) {
            vlbe_real x = VLBE_R(0.0);
            if (storage == VLBE_DAE_DENSE) x = A[(size_t)i * (size_t)lda + (size_t)j];
            else if (j >= i - kl && j <= i + ku) x = A[VLBE_BAND_IDX(lda, kl, i, j)];
            us.A[(size_t)i * (size_t)N + (size_t)j] = x;
        }
    return vlbe_lu_factor(N, us.A, us.A, us.piv, NULL) == VLBE_OK ? 0 : 1;
}
static void us_solve(void *u, int N, int nrhs, vlbe_real *B)
{
    (void)u;
    vlbe_lu_solve(N, us.A, us.piv, nrhs, B);
}

static void test_band_user_solver(void **state)
{
    chain cb, cu;
    vlbe_dae sb, su;
    vlbe_real q[NMAX] = {0}, v[NMAX] = {0};
    vlbe_hht_params par;
    vlbe_hht hb, hu;
    vlbe_bdf_params bp;
    vlbe_bdf bu;
    int k, band;
    (void)state;
    assert_int_equal(vlbe_hht_params_alpha(&par, VLBE_R(-0.1)), VLBE_OK);
    for (band = 0; band < 2; ++band) {
        double dq;
        ch_setup(&cb, &sb, P0, band, 1);
        ch_setup(&cu, &su, P0, band, 1);
        su.lin_factor = us_factor;
        su.lin_solve = us_solve;
        us.fail = 0;
        us.calls = 0;
        ch_start(&cb, q, v);
        assert_int_equal(vlbe_hht_init(&hb, &sb, &par, 0, q, v, wb, WL, iwb, IWL), VLBE_OK);
        assert_int_equal(vlbe_hht_init(&hu, &su, &par, 0, q, v, wd, WL, iwd, IWL), VLBE_OK);
        for (k = 0; k < 50; ++k) {
            assert_int_equal(vlbe_hht_step(&hb, VLBE_R(2e-3)), VLBE_OK);
            assert_int_equal(vlbe_hht_step(&hu, VLBE_R(2e-3)), VLBE_OK);
        }
        /* the same matrices factored by another LU: rounding of the solves
           only (see hht_run) */
        dq = maxdiff(2 * P0, hb.q, hu.q) / maxabs(2 * P0, hb.q);
        assert_true(dq <= 4.5e5 * EPS);
        assert_int_equal(us.calls, (int)hu.stats.lu_factors);
        /* BDF (f = 2 blocks) through the same callbacks (double: the BDF
           defaults ask for more than float resolves) */
        vlbe_bdf_params_default(&bp);
        assert_int_equal(vlbe_bdf_init(&bu, &su, &bp, 0, q, v, wd, WL, iwd, IWL), VLBE_OK);
#ifndef VLBE_USE_FLOAT
        assert_int_equal(vlbe_bdf_advance(&bu, VLBE_R(0.05)), VLBE_OK);
        assert_int_equal(us.N, 2 * (3 * P0));
#endif
        /* failures of the caller's factor */
        us.fail = 1;
        assert_int_equal(vlbe_hht_init(&hu, &su, &par, 0, q, v, wd, WL, iwd, IWL),
                         VLBE_ESINGULAR);
        us.fail = -3;
        assert_int_equal(vlbe_hht_init(&hu, &su, &par, 0, q, v, wd, WL, iwd, IWL),
                         VLBE_ECALLBACK);
        us.fail = 0;
    }
}

static void test_band_args(void **state)
{
    chain cb, cd;
    vlbe_dae sb, sd;
    vlbe_real q[NMAX] = {0}, v[NMAX] = {0}, a[NMAX], l[MMAX];
    int k;
    (void)state;
    ch_setup(&cb, &sb, P0, 1, 1);
    ch_start(&cb, q, v);
    assert_int_equal(vlbe_dae_check(&sb), VLBE_OK);
    /* not a permutation */
    k = cb.order[3];
    cb.order[3] = cb.order[4];
    assert_int_equal(vlbe_dae_consistent_acc(&sb, 0, q, v, a, l, NULL, wb, WL, iwb, IWL),
                     VLBE_EARG);
    cb.order[3] = k;
    cb.order[5] = 3 * P0 + 2; /* out of range */
    assert_int_equal(vlbe_dae_consistent_acc(&sb, 0, q, v, a, l, NULL, wb, WL, iwb, IWL),
                     VLBE_EARG);
    ch_setup(&cb, &sb, P0, 1, 1);
    sb.kl = 3 * P0;
    assert_int_equal(vlbe_dae_check(&sb), VLBE_EARG);
    sb.kl = -1;
    assert_int_equal(vlbe_dae_check(&sb), VLBE_EARG);
    sb.kl = 7;
    sb.order = NULL;
    assert_int_equal(vlbe_dae_check(&sb), VLBE_EARG);
    sb.order = cb.order;
    sb.storage = 2;
    assert_int_equal(vlbe_dae_check(&sb), VLBE_EARG);
    sb.storage = VLBE_DAE_BANDED;
    sb.lin_factor = us_factor;
    assert_int_equal(vlbe_dae_check(&sb), VLBE_EARG);
    sb.lin_factor = NULL;
    /* workspace: the band needs O(n (kl + ku)), the dense query O(n^2) */
    ch_setup(&cd, &sd, P0, 0, 1);
    assert_true(vlbe_hht_work_len_sys(&sb) < vlbe_hht_work_len_sys(&sd));
    assert_true(vlbe_hht_work_len_sys(&sd) == vlbe_hht_work_len(sd.n, sd.m));
    assert_true(vlbe_bdf_work_len_sys(&sd) == vlbe_bdf_work_len(sd.n, sd.m));
    assert_true(vlbe_static_work_len_sys(&sd) == vlbe_static_work_len(sd.n, sd.m));
    assert_true(vlbe_dae_work_len_sys(&sd) == vlbe_dae_work_len(sd.n, sd.m));
    {
        vlbe_hht st;
        vlbe_hht_params par;
        size_t lw = vlbe_hht_work_len_sys(&sb), liw = vlbe_hht_iwork_len_sys(&sb);
        assert_int_equal(vlbe_hht_params_alpha(&par, VLBE_R(-0.1)), VLBE_OK);
        assert_int_equal(vlbe_hht_init(&st, &sb, &par, 0, q, v, wb, lw - 1, iwb, liw), VLBE_EWORK);
        assert_int_equal(vlbe_hht_init(&st, &sb, &par, 0, q, v, wb, lw, iwb, liw - 1), VLBE_EWORK);
        assert_int_equal(vlbe_hht_init(&st, &sb, &par, 0, q, v, wb, lw, iwb, liw), VLBE_OK);
        assert_int_equal(vlbe_hht_step(&st, VLBE_R(1e-3)), VLBE_OK);
    }
    {
        vlbe_bdf st;
        vlbe_bdf_params bp;
        size_t lw = vlbe_bdf_work_len_sys(&sb), liw = vlbe_bdf_iwork_len_sys(&sb);
        vlbe_bdf_params_default(&bp);
        assert_int_equal(vlbe_bdf_init(&st, &sb, &bp, 0, q, v, wb, lw - 1, iwb, liw), VLBE_EWORK);
        assert_int_equal(vlbe_bdf_init(&st, &sb, &bp, 0, q, v, wb, lw, iwb, liw), VLBE_OK);
#ifndef VLBE_USE_FLOAT /* the BDF defaults ask for more than float resolves */
        assert_int_equal(vlbe_bdf_advance(&st, VLBE_R(0.01)), VLBE_OK);
#endif
    }
    {
        vlbe_static_params sp;
        size_t lw = vlbe_static_work_len_sys(&sb), liw = vlbe_static_iwork_len_sys(&sb);
        vlbe_static_params_default(&sp);
        ch_lambda0(&cb, l);
        assert_int_equal(vlbe_dae_static(&sb, &sp, 0, q, l, NULL, wb, lw - 1, iwb, liw), VLBE_EWORK);
        assert_int_equal(vlbe_dae_static(&sb, &sp, 0, q, l, NULL, wb, lw, iwb, liw), VLBE_OK);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_band_consistent_acc), cmocka_unit_test(test_band_static),
        cmocka_unit_test(test_band_hht_run),        cmocka_unit_test(test_band_bdf_run),
        cmocka_unit_test(test_band_user_solver),    cmocka_unit_test(test_band_args),
    };
    return cmocka_run_group_tests_name("dae_band", tests, NULL, NULL);
}
