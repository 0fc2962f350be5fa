/* test_contract_core.c -- the failure contract of vlbe.h (dense LU) and
   integrators.h: no OK with a non-finite output, arguments range-checked, a
   failed call leaves the caller's data as it was, time without drift
   -- part of vlbe                                 SPDX-License-Identifier: MIT

   Build and run from the repository root (add -DVLBE_USE_FLOAT for the
   float build; the same source passes in both precisions):
       cc -std=c99 -Wall -Wextra -Wpedantic -O2 tests/test_contract_core.c -o t -lcmocka -lm

   Every test below is a regression test: its comment says what happened on
   77b73ad.  "Untouched" is checked with memcmp against snapshots taken
   before the call, outputs pre-filled with a sentinel byte pattern.

   Groups: LU pivot test and outputs | HHT init/step arguments and failure |
   BDF init/step failure | time without drift (HHT, fixed-step BDF). */
#include "test_util.h"
#include "../integrators.h"

#include <float.h>
#include <string.h>

#define EPS ((double)VLBE_EPS)
#define SENTINEL 0xA5

/* ======================================================================= */
/* dense LU                                                                */
/* ======================================================================= */

/* The elimination of 77b73ad, verbatim but for the pivot test: the
   reference for "valid input gives bit-identical factors". */
static int ref_lu(int n, vlbe_real *LU, int *piv)
{
    int i, j, k;
    for (k = 0; k < n; ++k) {
        vlbe_real *rk = LU + (size_t)k * (size_t)n, pmax = vlbe_fabs(rk[k]), inv;
        int p = k;
        for (i = k + 1; i < n; ++i) {
            vlbe_real t = vlbe_fabs(LU[(size_t)i * (size_t)n + (size_t)k]);
            if (t > pmax) {
                pmax = t;
                p = i;
            }
        }
        piv[k] = p;
        if (pmax == VLBE_R(0.0)) return -1;
        if (p != k) {
            vlbe_real *rp = LU + (size_t)p * (size_t)n;
            for (j = 0; j < n; ++j) {
                vlbe_real t = rk[j];
                rk[j] = rp[j];
                rp[j] = t;
            }
        }
        inv = VLBE_R(1.0) / rk[k];
        for (i = k + 1; i < n; ++i) {
            vlbe_real *ri = LU + (size_t)i * (size_t)n;
            vlbe_real lik = ri[k] * inv;
            ri[k] = lik;
            if (lik != VLBE_R(0.0))
                for (j = k + 1; j < n; ++j) ri[j] -= lik * rk[j];
        }
    }
    return 0;
}

/* Random matrices n = 1..40 at scales 1, 1e-30, 1e30 (float: 1e-15, 1e15,
   so that n 2^n max|A| stays finite and the overflow scan is skipped for
   the small n and run for the large): the factor and pivots are bitwise
   those of the 77b73ad elimination, in place and out of place.  (On
   77b73ad this passes too: it pins that the new checks changed nothing.) */
static void test_lu_valid_bit_identical(void **state)
{
    static vlbe_real A[40 * 40], LU[40 * 40], R[40 * 40];
    int piv[40], pr[40], n, i, s, info;
#ifdef VLBE_USE_FLOAT
    static const double scales[3] = {1.0, 1e-15, 1e15};
#else
    static const double scales[3] = {1.0, 1e-30, 1e30};
#endif
    tu_rng rng;
    (void)state;
    rng = tu_rng_seed(7u);
    for (s = 0; s < 3; ++s)
        for (n = 1; n <= 40; ++n) {
            for (i = 0; i < n * n; ++i) A[i] = (vlbe_real)(scales[s] * tu_rng_uniform(&rng));
            memcpy(R, A, sizeof(vlbe_real) * (size_t)(n * n));
            assert_int_equal(ref_lu(n, R, pr), 0);
            info = -7;
            assert_int_equal(vlbe_lu_factor(n, A, LU, piv, &info), VLBE_OK);
            assert_int_equal(info, 0);
            assert_memory_equal(LU, R, sizeof(vlbe_real) * (size_t)(n * n));
            assert_memory_equal(piv, pr, sizeof(int) * (size_t)n);
            assert_int_equal(vlbe_lu_factor(n, A, A, piv, NULL), VLBE_OK); /* in place */
            assert_memory_equal(A, R, sizeof(vlbe_real) * (size_t)(n * n));
        }
}

/* A 2x2 whose first pivot is subnormal: 1/pivot overflows.  Fails on
   77b73ad: VLBE_OK with LU = [1e-322 0 nan nan] (tol = n eps max|A|
   underflowed to 0, the NaN pivot passed `pmax <= tol`), and a solve gave
   x = [inf nan]; float: [[1e-39f, 0], [0, 0]] gave OK. */
static void test_lu_subnormal_pivot(void **state)
{
    vlbe_real A[4], A0[4];
    int piv[2], info;
    (void)state;
#ifndef VLBE_USE_FLOAT
    A[0] = 1e-322;
#else
    A[0] = 1e-39f;
#endif
    A[1] = A[2] = A[3] = VLBE_R(0.0);
    memcpy(A0, A, sizeof A);
    info = -7;
    assert_int_equal(vlbe_lu_factor(2, A, A, piv, &info), VLBE_ESINGULAR);
    assert_int_equal(info, 1);
    /* the same alone on the diagonal with a regular second pivot */
    A[0] = A0[0];
    A[1] = A[2] = VLBE_R(0.0);
    A[3] = A0[0];
    info = -7;
    assert_int_equal(vlbe_lu_factor(2, A, A, piv, &info), VLBE_ESINGULAR);
    assert_int_equal(info, 1);
    /* a subnormal pivot next to a regular matrix is relatively zero */
    A[0] = A0[0];
    A[1] = A[2] = VLBE_R(0.0);
    A[3] = VLBE_R(1.0);
    assert_int_equal(vlbe_lu_factor(2, A, A, piv, &info), VLBE_ESINGULAR);
    assert_int_equal(info, 1);
    /* every entry tiny but normal: a valid, finite factor */
    A[0] = VLBE_R(4.0) * VLBE_REAL_MIN;
    A[1] = VLBE_R(0.0);
    A[2] = VLBE_R(2.0) * VLBE_REAL_MIN;
    A[3] = VLBE_R(8.0) * VLBE_REAL_MIN;
    assert_int_equal(vlbe_lu_factor(2, A, A, piv, &info), VLBE_OK);
    assert_true(vlbe_all_finite(A, 4));
}

/* Overflow in the update: [[M, M], [-M, M]], M near VLBE_REAL_MAX, gives
   U22 = 2M = Inf.  Fails on 77b73ad: VLBE_OK with U22 = Inf.  An overflow
   off the pivots (U row 0 fine, the Inf only in U[1][2] of a 3x3 with a
   zero multiplier elsewhere) is caught by the final scan. */
static void test_lu_overflow(void **state)
{
    const vlbe_real M = VLBE_REAL_MAX / VLBE_R(1.5);
    vlbe_real A[9], LU[9];
    int piv[3], info = -7;
    (void)state;
    A[0] = M, A[1] = M, A[2] = -M, A[3] = M;
    assert_int_equal(vlbe_lu_factor(2, A, LU, piv, &info), VLBE_ENONFINITE);
    assert_int_equal(info, -7); /* only ESINGULAR reports a column */
    /* 3x3: l10 = -1; U[1][2] = M + M overflows, the pivot U[1][1] = M/2
       stays finite, and row 2 never sees row 1 (l21 = 0): U22 = M */
    A[0] = M, A[1] = M / VLBE_R(4.0), A[2] = M;
    A[3] = -M, A[4] = M / VLBE_R(4.0), A[5] = M;
    A[6] = VLBE_R(0.0), A[7] = VLBE_R(0.0), A[8] = M;
    assert_int_equal(vlbe_lu_factor(3, A, LU, piv, &info), VLBE_ENONFINITE);
    assert_int_equal(info, -7);
}

/* A non-finite A is found before anything is written: LU, piv and *info
   keep their sentinels (bitwise).  Fails on 77b73ad: *info was set to 0.
   A singular A writes *info = column and nothing else is promised (LU,
   piv: unspecified scratch, documented); A itself is untouched when LU is
   a different buffer. */
static void test_lu_failure_outputs(void **state)
{
    vlbe_real A[9], A0[9], LU[9], LU0[9];
    int piv[3], piv0[3], info = -7;
    (void)state;
    A[0] = 1, A[1] = 2, A[2] = 3, A[3] = 4, A[4] = 5, A[5] = 6, A[6] = 7, A[7] = 8, A[8] = 9;
    A[4] = (vlbe_real)NAN;
    memset(LU, SENTINEL, sizeof LU);
    memset(piv, SENTINEL, sizeof piv);
    memcpy(LU0, LU, sizeof LU);
    memcpy(piv0, piv, sizeof piv);
    memcpy(A0, A, sizeof A);
    assert_int_equal(vlbe_lu_factor(3, A, LU, piv, &info), VLBE_ENONFINITE);
    assert_int_equal(info, -7);
    assert_memory_equal(LU, LU0, sizeof LU);
    assert_memory_equal(piv, piv0, sizeof piv);
    assert_memory_equal(A, A0, sizeof A);
    /* in place: A untouched too (nothing written) */
    A[4] = (vlbe_real)INFINITY;
    memcpy(A0, A, sizeof A);
    assert_int_equal(vlbe_lu_factor(3, A, A, piv, &info), VLBE_ENONFINITE);
    assert_memory_equal(A, A0, sizeof A);
    assert_memory_equal(piv, piv0, sizeof piv);
    /* singular (rank 2): *info = 3, A untouched out of place */
    A[4] = 5;
    memcpy(A0, A, sizeof A);
    assert_int_equal(vlbe_lu_factor(3, A, LU, piv, &info), VLBE_ESINGULAR);
    assert_int_equal(info, 3);
    assert_memory_equal(A, A0, sizeof A);
}

/* ======================================================================= */
/* small problems for the integrators                                      */
/* ======================================================================= */

/* Rheonomic point mass: q = (x, y), M = I, Q = (0, -g) (or 0), C = x - c t
   (C_q = [1 0], C_t = -c, gamma = 0).  Records the last time at which C was
   evaluated; force returns fail_rc for t > t_fail; mass_zero: M = 0
   (singular start). */
typedef struct rh_user {
    double c, g, t_fail, t_last_c;
    int fail_rc, mass_zero;
    int fail_count; /* > 0: only so many force calls past t_fail fail */
} rh_user;

static int rh_mass(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v, vlbe_real *M)
{
    const rh_user *r = (const rh_user *)u;
    vlbe_real d = r->mass_zero ? VLBE_R(0.0) : VLBE_R(1.0);
    (void)t, (void)q, (void)v;
    M[0] = d, M[1] = VLBE_R(0.0), M[2] = VLBE_R(0.0), M[3] = d;
    return 0;
}
static int rh_force(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v, vlbe_real *Q)
{
    const rh_user *r = (const rh_user *)u;
    Q[0] = -VLBE_R(0.5) * q[0] - VLBE_R(0.01) * v[0];
    Q[1] = -(vlbe_real)r->g - q[1];
    if (!((double)t > r->t_fail)) return 0;
    if (r->fail_count > 0 && --((rh_user *)u)->fail_count == 0) ((rh_user *)u)->t_fail = HUGE_VAL;
    return r->fail_rc;
}
static int rh_constr(void *u, vlbe_real t, const vlbe_real *q, vlbe_real *C)
{
    rh_user *r = (rh_user *)u;
    r->t_last_c = (double)t;
    C[0] = q[0] - (vlbe_real)r->c * t;
    return 0;
}
static int rh_cjac(void *u, vlbe_real t, const vlbe_real *q, vlbe_real *Cq, vlbe_real *Ct)
{
    const rh_user *r = (const rh_user *)u;
    (void)t, (void)q;
    Cq[0] = VLBE_R(1.0), Cq[1] = VLBE_R(0.0);
    if (Ct) Ct[0] = -(vlbe_real)r->c;
    return 0;
}
static int rh_cacc(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v, vlbe_real *g)
{
    (void)u, (void)t, (void)q, (void)v;
    g[0] = VLBE_R(0.0);
    return 0;
}

static void rh_sys(vlbe_dae *s, rh_user *u)
{
    memset(s, 0, sizeof *s);
    memset(u, 0, sizeof *u);
    u->c = 1.0;
    u->g = 9.81;
    u->t_fail = HUGE_VAL;
    s->n = 2;
    s->m = 1;
    s->flags = VLBE_DAE_MASS_CONST;
    s->user = u;
    s->mass = rh_mass;
    s->force = rh_force;
    s->constr = rh_constr;
    s->constr_jac = rh_cjac;
    s->constr_acc = rh_cacc;
}

enum { RH_LW = 512, RH_LIW = 16 };

/* the HHT state, its work arrays and the time run: what must survive */
typedef struct hht_snap {
    vlbe_hht st;
    vlbe_real w[RH_LW];
    int iw[RH_LIW];
} hht_snap;

/* caller-visible part of an HHT state: everything but stats and the
   private LU cache (have_lu_, h_lu_), which the contract exempts.  Field
   by field: a whole-struct memcmp would read padding bytes, which struct
   assignment need not copy (valgrind: uninitialised). */
static void assert_hht_same(const vlbe_hht *a, const vlbe_hht *b)
{
    int n = b->n, m = b->m;
    assert_memory_equal(&a->t, &b->t, sizeof a->t);
    assert_ptr_equal(a->q, b->q);
    assert_ptr_equal(a->sys, b->sys);
    assert_int_equal(a->n, b->n);
    assert_int_equal(a->m, b->m);
    assert_memory_equal(a->q, b->q, sizeof(vlbe_real) * (size_t)(4 * n + m));
    assert_memory_equal(&a->par.alpha_m, &b->par.alpha_m, 6 * sizeof(vlbe_real));
    assert_int_equal(a->par.newton_max, b->par.newton_max);
    assert_int_equal(a->par.modified, b->par.modified);
    assert_int_equal(a->par.max_halvings, b->par.max_halvings);
    assert_memory_equal(&a->par.ftol, &b->par.ftol, sizeof(vlbe_real));
    assert_memory_equal(&a->t_base_, &b->t_base_, sizeof a->t_base_);
    assert_memory_equal(&a->h_run_, &b->h_run_, sizeof a->h_run_);
    assert_true(a->k_run_ == b->k_run_);
}

/* ======================================================================= */
/* HHT                                                                     */
/* ======================================================================= */

/* Every parameter is checked: NaN and Inf in any real, gamma < 0,
   newton_max above VLBE_INT_MAX_ITER, modified not 0/1, max_halvings above
   VLBE_HHT_MAX_HALVINGS, t0 NaN/Inf.  On failure *st, work and iwork are
   bitwise unchanged (argument checks come before any write).  Fails on
   77b73ad: gamma = NaN, beta = Inf, max_halvings = 31, newton_max = 1001
   and t0 = NaN were accepted (t0 = NaN then stepped with st.t = NaN
   returning OK). */
static void test_hht_init_args(void **state)
{
    static vlbe_real w[RH_LW], w0[RH_LW];
    int iw[RH_LIW], iw0[RH_LIW], k;
    vlbe_dae sys;
    rh_user u;
    vlbe_hht st, st0;
    vlbe_hht_params p, bad;
    const vlbe_real q0[2] = {0, 1}, v0[2] = {1, 0};
    const vlbe_real nan = (vlbe_real)NAN, inf = (vlbe_real)INFINITY;
    (void)state;
    rh_sys(&sys, &u);
    assert_true(vlbe_hht_work_len(2, 1) <= RH_LW && vlbe_hht_iwork_len(2, 1) <= RH_LIW);
    assert_int_equal(vlbe_hht_params_genalpha(&p, VLBE_R(0.8)), VLBE_OK);
    memset(&st, SENTINEL, sizeof st);
    memset(w, SENTINEL, sizeof w);
    memset(iw, SENTINEL, sizeof iw);
    memcpy(&st0, &st, sizeof st);
    memcpy(w0, w, sizeof w);
    memcpy(iw0, iw, sizeof iw);
    for (k = 0; k < 16; ++k) {
        vlbe_status want = VLBE_EARG;
        vlbe_real t0 = VLBE_R(0.0);
        bad = p;
        switch (k) {
        case 0: bad.gamma = nan; break;
        case 1: bad.beta = inf; break;
        case 2: bad.alpha_m = -inf; break;
        case 3: bad.alpha_f = nan; break;
        case 4: bad.rtol = inf; break;
        case 5: bad.atol = nan; break;
        case 6: bad.gamma = VLBE_R(-0.5); break;
        case 7: bad.newton_max = VLBE_INT_MAX_ITER + 1; break;
        case 8: bad.newton_max = 0; break;
        case 9: bad.modified = 2; break;
        case 10: bad.max_halvings = VLBE_HHT_MAX_HALVINGS + 1; break;
        case 11: bad.max_halvings = -1; break;
        case 12: bad.ftol = inf; break;
        case 13: t0 = nan, want = VLBE_ENONFINITE; break;
        case 14: t0 = inf, want = VLBE_ENONFINITE; break;
        default: t0 = -inf, want = VLBE_ENONFINITE; break;
        }
        assert_int_equal(vlbe_hht_init(&st, &sys, &bad, t0, q0, v0, w, RH_LW, iw, RH_LIW), want);
        assert_memory_equal(&st, &st0, sizeof st);
        assert_memory_equal(w, w0, sizeof w);
        assert_memory_equal(iw, iw0, sizeof iw);
    }
    /* the bounds themselves are accepted */
    bad = p;
    bad.max_halvings = VLBE_HHT_MAX_HALVINGS;
    bad.newton_max = VLBE_INT_MAX_ITER;
    assert_int_equal(vlbe_hht_init(&st, &sys, &bad, 0, q0, v0, w, RH_LW, iw, RH_LIW), VLBE_OK);
}

/* A singular start (M = 0, no constraint on y: the consistent-acceleration
   matrix is singular) fails with *st bitwise unchanged; work/iwork are
   documented scratch then, but the state area a live state keeps in the
   same buffers (q, v, qdd, a, lambda) is untouched too.  Fails on 77b73ad:
   st->t, st->q, ... were written before VLBE_ESINGULAR. */
static void test_hht_init_failure_untouched(void **state)
{
    static vlbe_real w[RH_LW], w0[RH_LW];
    int iw[RH_LIW];
    vlbe_dae sys;
    rh_user u;
    vlbe_hht st, st0;
    vlbe_hht_params p;
    const vlbe_real q0[2] = {0, 1}, v0[2] = {1, 0};
    (void)state;
    rh_sys(&sys, &u);
    vlbe_hht_params_genalpha(&p, VLBE_R(0.8));
    /* a live state first, one step taken */
    assert_int_equal(vlbe_hht_init(&st, &sys, &p, 0, q0, v0, w, RH_LW, iw, RH_LIW), VLBE_OK);
    assert_int_equal(vlbe_hht_step(&st, VLBE_R(0.01)), VLBE_OK);
    memcpy(&st0, &st, sizeof st);
    memcpy(w0, w, sizeof w);
    u.mass_zero = 1;
    assert_int_equal(vlbe_hht_init(&st, &sys, &p, 0, q0, v0, w, RH_LW, iw, RH_LIW), VLBE_ESINGULAR);
    assert_hht_same(&st, &st0);
    assert_true(st.stats.steps == st0.stats.steps && st.stats.mass_calls == st0.stats.mass_calls);
    assert_memory_equal(w, w0, sizeof(vlbe_real) * (size_t)(4 * 2 + 1));
    /* the same from a sentinel-filled struct */
    memset(&st, SENTINEL, sizeof st);
    memcpy(&st0, &st, sizeof st);
    assert_int_equal(vlbe_hht_init(&st, &sys, &p, 0, q0, v0, w, RH_LW, iw, RH_LIW), VLBE_ESINGULAR);
    assert_memory_equal(&st, &st0, sizeof st);
}

/* vlbe_hht_step with h NaN, +-Inf, 0, < 0: VLBE_EARG and the whole state
   (fields, stats and LU cache included, and the work arrays) bitwise
   unchanged.  (77b73ad already returned
   EARG here; the test pins it.) */
static void test_hht_step_bad_h(void **state)
{
    static hht_snap a, b;
    vlbe_dae sys;
    rh_user u;
    vlbe_hht_params p;
    const vlbe_real q0[2] = {0, 1}, v0[2] = {1, 0};
    const vlbe_real hs[5] = {(vlbe_real)NAN, (vlbe_real)INFINITY, -(vlbe_real)INFINITY,
                             VLBE_R(0.0), VLBE_R(-0.01)};
    int k;
    (void)state;
    rh_sys(&sys, &u);
    vlbe_hht_params_genalpha(&p, VLBE_R(0.8));
    assert_int_equal(vlbe_hht_init(&a.st, &sys, &p, 0, q0, v0, a.w, RH_LW, a.iw, RH_LIW), VLBE_OK);
    assert_int_equal(vlbe_hht_step(&a.st, VLBE_R(0.01)), VLBE_OK);
    memcpy(&b, &a, sizeof a);
    for (k = 0; k < 5; ++k) {
        assert_int_equal(vlbe_hht_step(&a.st, hs[k]), VLBE_EARG);
        assert_hht_same(&a.st, &b.st);
        assert_memory_equal(&a.st.stats.steps, &b.st.stats.steps, 10 * sizeof(long));
        assert_int_equal(a.st.have_lu_, b.st.have_lu_);
        assert_memory_equal(a.w, b.w, sizeof a.w);
        assert_memory_equal(a.iw, b.iw, sizeof a.iw);
    }
}

/* A step that fails after its first half succeeded (max_halvings = 3,
   force callback outside its domain for t > t_fail): the state is the one
   before the call, bit for bit (t, q, v, q'', a, lambda, the time run), and
   the next steps continue as if the failed call had not been made.
   (77b73ad restored q..lambda and t too; the time run is new.) */
static void test_hht_step_failure_untouched(void **state)
{
    static vlbe_real w[RH_LW];
    int iw[RH_LIW], k;
    vlbe_dae sys;
    rh_user u;
    vlbe_hht st, st0;
    static vlbe_real w0[RH_LW];
    vlbe_hht_params p;
    const vlbe_real q0[2] = {0, 1}, v0[2] = {1, 0};
    (void)state;
    rh_sys(&sys, &u);
    vlbe_hht_params_genalpha(&p, VLBE_R(0.8));
    p.max_halvings = 3;
    assert_int_equal(vlbe_hht_init(&st, &sys, &p, 0, q0, v0, w, RH_LW, iw, RH_LIW), VLBE_OK);
    for (k = 0; k < 10; ++k) assert_int_equal(vlbe_hht_step(&st, VLBE_R(0.01)), VLBE_OK);
    memcpy(&st0, &st, sizeof st);
    memcpy(w0, w, sizeof w);
    u.t_fail = (double)st.t + 0.006; /* the half step to t + 0.005 succeeds */
    u.fail_rc = 1;
    assert_int_equal(vlbe_hht_step(&st, VLBE_R(0.01)), VLBE_ECALLBACK);
    assert_true(st.stats.steps > st0.stats.steps); /* the first half was taken */
    assert_hht_same(&st, &st0);
    /* fatal callback: at once, the same */
    u.fail_rc = -1;
    assert_int_equal(vlbe_hht_step(&st, VLBE_R(0.01)), VLBE_ECALLBACK);
    assert_hht_same(&st, &st0);
    /* one level of halving: the second half fails at the deepest level
       there is, the first half is undone all the same */
    u.fail_rc = 1;
    st.par.max_halvings = st0.par.max_halvings = 1;
    assert_int_equal(vlbe_hht_step(&st, VLBE_R(0.01)), VLBE_ECALLBACK);
    assert_true(st.stats.steps > st0.stats.steps);
    assert_hht_same(&st, &st0);
}

/* A step that succeeds after one halving (the force callback refuses the
   full step's end once): it ends at the run's time 11 h exactly, and its
   state is that of two half steps taken one by one, bit for bit in double
   (the same attempts from the same states: the failed attempt evaluates
   nothing else; the half steps by hand end at t0 + 2 (h/2), equal to 11 h
   in double).  Float: 11 h and t0 + 2 (h/2) differ by a rounding, which
   the rheonomic constraint turns into q by c dt: q within 64 eps. */
static void test_hht_step_halved_lands(void **state)
{
    static vlbe_real w[RH_LW], wb[RH_LW];
    int iw[RH_LIW], iwb[RH_LIW], k;
    vlbe_dae sys, sysb;
    rh_user u, ub;
    vlbe_hht st, sb;
    vlbe_hht_params p;
    const vlbe_real q0[2] = {0, 1}, v0[2] = {1, 0};
    vlbe_real t0;
    (void)state;
    rh_sys(&sys, &u);
    rh_sys(&sysb, &ub);
    vlbe_hht_params_genalpha(&p, VLBE_R(0.8));
    p.max_halvings = 3;
    assert_int_equal(vlbe_hht_init(&st, &sys, &p, 0, q0, v0, w, RH_LW, iw, RH_LIW), VLBE_OK);
    assert_int_equal(vlbe_hht_init(&sb, &sysb, &p, 0, q0, v0, wb, RH_LW, iwb, RH_LIW), VLBE_OK);
    for (k = 0; k < 10; ++k) {
        assert_int_equal(vlbe_hht_step(&st, VLBE_R(0.01)), VLBE_OK);
        assert_int_equal(vlbe_hht_step(&sb, VLBE_R(0.01)), VLBE_OK);
    }
    t0 = st.t;
    u.t_fail = (double)t0 + 0.006; /* past the first half's end */
    u.fail_rc = 1;
    u.fail_count = 1;
    assert_int_equal(vlbe_hht_step(&st, VLBE_R(0.01)), VLBE_OK);
    assert_int_equal(st.stats.rejected, 1);
    assert_true(st.t == VLBE_R(11.0) * VLBE_R(0.01));
    assert_int_equal(vlbe_hht_step(&sb, VLBE_R(0.005)), VLBE_OK);
    assert_int_equal(vlbe_hht_step(&sb, VLBE_R(0.005)), VLBE_OK);
#ifdef VLBE_USE_FLOAT
    for (k = 0; k < 2; ++k) ASSERT_CLOSE(st.q[k], sb.q[k], 0.0, 64.0 * (double)VLBE_EPS);
#else
    assert_true(sb.t == st.t);
    assert_memory_equal(st.q, sb.q, (4 * 2 + 1) * sizeof(vlbe_real)); /* q v qdd a lambda */
#endif
}

/* Finite parameters at the edge of the accepted range (beta = the
   smallest normal number, alpha_f = -0.01/beta, gamma = 0: dq/dq'' =
   h^2 beta (1 - alpha_f) ~ 1e-8 stays moderate, but da/dq'' = (1 -
   alpha_f) ~ 1e-2/beta) and an initial constraint violation C = 0.5: the
   first Newton update moves q'' by ~C/bp, which times da/dq'' overflows
   the trial a while q, v, lambda stay finite.  The step fails with
   VLBE_ENONFINITE, the state bitwise unchanged.  Fails on bc748ae: the
   Newton loop checked only q, v, lambda, and vlbe_hht_step returned
   VLBE_OK with a = -Inf (found by fuzz_step). */
static int tn_constr(void *u, vlbe_real t, const vlbe_real *q, vlbe_real *C)
{
    (void)u, (void)t;
    C[0] = q[0]; /* scleronomic: blind to t */
    return 0;
}
static void test_hht_step_trial_acc_overflow(void **state)
{
    static vlbe_real w[RH_LW];
    int iw[RH_LIW];
    vlbe_dae sys;
    rh_user u;
    vlbe_hht st, st0;
    static vlbe_real w0[RH_LW];
    vlbe_hht_params p;
    const vlbe_real q0[2] = {VLBE_R(0.5), 1}, v0[2] = {0, 0};
    (void)state;
    rh_sys(&sys, &u);
    u.c = 0.0;
    sys.constr = tn_constr;
    vlbe_hht_params_newmark(&p, VLBE_REAL_MIN, VLBE_R(0.0));
    p.alpha_f = -VLBE_R(0.01) / VLBE_REAL_MIN;
    assert_true(isfinite(p.alpha_f));
    assert_int_equal(vlbe_hht_init(&st, &sys, &p, 0, q0, v0, w, RH_LW, iw, RH_LIW), VLBE_OK);
    memcpy(&st0, &st, sizeof st);
    memcpy(w0, w, sizeof w);
    assert_int_equal(vlbe_hht_step(&st, VLBE_R(1e-3)), VLBE_ENONFINITE);
    assert_hht_same(&st, &st0);
    /* with halvings the smaller steps overflow too: the same */
    st.par.max_halvings = 3;
    st0.par.max_halvings = 3;
    assert_int_equal(vlbe_hht_step(&st, VLBE_R(1e-3)), VLBE_ENONFINITE);
    assert_hht_same(&st, &st0);
}

/* A step whose end time overflows (t = 0.75 max, h = 0.5 max, a system
   blind to t) fails with VLBE_ENONFINITE before any callback, the state
   bitwise unchanged.  Fails on bc748ae: t + h != t passed the step-size
   test and the callbacks were evaluated at t = +Inf (the step then failed
   with VLBE_ENONFINITE only because h^2 overflowed in the predictor). */
static void test_hht_step_time_overflow(void **state)
{
    static vlbe_real w[RH_LW];
    int iw[RH_LIW];
    vlbe_dae sys;
    rh_user u;
    vlbe_hht st, st0;
    vlbe_hht_params p;
    const vlbe_real q0[2] = {0, 1}, v0[2] = {0, 0};
    (void)state;
    rh_sys(&sys, &u);
    u.c = 0.0;
    sys.constr = tn_constr;
    vlbe_hht_params_genalpha(&p, VLBE_R(0.8));
    assert_int_equal(vlbe_hht_init(&st, &sys, &p, VLBE_R(0.75) * VLBE_REAL_MAX, q0, v0, w, RH_LW,
                                   iw, RH_LIW),
                     VLBE_OK);
    memcpy(&st0, &st, sizeof st);
    assert_int_equal(vlbe_hht_step(&st, VLBE_R(0.5) * VLBE_REAL_MAX), VLBE_ENONFINITE);
    assert_hht_same(&st, &st0);
    assert_true(st.stats.mass_calls == st0.stats.mass_calls);
}

/* ======================================================================= */
/* BDF                                                                     */
/* ======================================================================= */

enum { BD_LW = 2048, BD_LIW = 16 };

/* caller-visible BDF state and the method's history (phi, coefficients):
   everything but stats and the private iteration-matrix cache */
static void assert_bdf_same(const vlbe_bdf *a, const vlbe_bdf *b)
{
    int N2 = 2 * b->n + 2 * b->m;
    assert_memory_equal(&a->t, &b->t, sizeof a->t);
    assert_memory_equal(&a->h, &b->h, sizeof a->h);
    assert_memory_equal(&a->h_last, &b->h_last, sizeof a->h_last);
    assert_int_equal(a->order, b->order);
    assert_int_equal(a->order_last, b->order_last);
    assert_memory_equal(a->q, b->q, sizeof(vlbe_real) * (size_t)N2);
    assert_memory_equal(a->phi_, b->phi_, sizeof(vlbe_real) * (size_t)(N2 * (VLBE_BDF_MAXORD + 1)));
    assert_memory_equal(a->psi_, b->psi_, sizeof a->psi_);
    assert_memory_equal(a->alpha_, b->alpha_, sizeof a->alpha_);
    assert_memory_equal(a->beta_, b->beta_, sizeof a->beta_);
    assert_memory_equal(a->gamma_, b->gamma_, sizeof a->gamma_);
    assert_memory_equal(a->sigma_, b->sigma_, sizeof a->sigma_);
    assert_memory_equal(&a->hold_, &b->hold_, sizeof a->hold_);
    assert_memory_equal(&a->cj_, &b->cj_, sizeof a->cj_);
    assert_int_equal(a->kold_, b->kold_);
    assert_int_equal(a->ns_, b->ns_);
    assert_int_equal(a->phase_, b->phase_);
}

/* Parameters: rtol, atol, h_min = Inf, newton_max above VLBE_INT_MAX_ITER,
   fixed_step = 2: VLBE_EARG, *st, work, iwork untouched.  A singular start:
   VLBE_ESINGULAR with *st untouched.  Fails on 77b73ad: rtol = Inf, h_min =
   Inf, newton_max = 1001, fixed_step = 2 were accepted; the singular start
   wrote st. */
static void test_bdf_init_failure(void **state)
{
    static vlbe_real w[BD_LW], w0[BD_LW];
    int iw[BD_LIW], iw0[BD_LIW], k;
    vlbe_dae sys;
    rh_user u;
    vlbe_bdf st, st0;
    vlbe_bdf_params p, bad;
    const vlbe_real q0[2] = {0, 1}, v0[2] = {1, 0};
    (void)state;
    rh_sys(&sys, &u);
    assert_true(vlbe_bdf_work_len(2, 1) <= BD_LW && vlbe_bdf_iwork_len(2, 1) <= BD_LIW);
    vlbe_bdf_params_default(&p);
    memset(&st, SENTINEL, sizeof st);
    memset(w, SENTINEL, sizeof w);
    memset(iw, SENTINEL, sizeof iw);
    memcpy(&st0, &st, sizeof st);
    memcpy(w0, w, sizeof w);
    memcpy(iw0, iw, sizeof iw);
    for (k = 0; k < 7; ++k) {
        bad = p;
        switch (k) {
        case 0: bad.rtol = (vlbe_real)INFINITY; break;
        case 1: bad.atol = (vlbe_real)INFINITY; break;
        case 2: bad.h_min = (vlbe_real)INFINITY; break;
        case 3: bad.newton_max = VLBE_INT_MAX_ITER + 1; break;
        case 4: bad.fixed_step = 2, bad.h0 = VLBE_R(0.01); break;
        case 5: bad.max_steps = -1; break;
        default: bad.fixed_step = -1, bad.h0 = VLBE_R(0.01); break;
        }
        assert_int_equal(vlbe_bdf_init(&st, &sys, &bad, 0, q0, v0, w, BD_LW, iw, BD_LIW),
                         VLBE_EARG);
        assert_memory_equal(&st, &st0, sizeof st);
        assert_memory_equal(w, w0, sizeof w);
        assert_memory_equal(iw, iw0, sizeof iw);
    }
    u.mass_zero = 1;
    assert_int_equal(vlbe_bdf_init(&st, &sys, &p, 0, q0, v0, w, BD_LW, iw, BD_LIW), VLBE_ESINGULAR);
    assert_memory_equal(&st, &st0, sizeof st);
}

/* A failed vlbe_bdf_step (fatal callback, and a callback outside its
   domain for every step > hmin ahead) after a variable-step run has built
   up order and history: state and history bit for bit as before, and (no
   new iteration matrix was formed by the failed attempts: their residual
   failed first) the run continues exactly as a twin run that never made
   the failed call.
   Fails on 77b73ad: phi was put back as phi beta (1/beta) and psi as
   psi - h, off by ulps. */
static void test_bdf_step_failure_untouched(void **state)
{
    static vlbe_real w[BD_LW], w2[BD_LW];
    int iw[BD_LIW], iw2[BD_LIW], k, rcs;
    vlbe_dae sys, sys2;
    rh_user u, u2;
    vlbe_bdf st, st2, st0;
    vlbe_bdf_params p;
    const vlbe_real q0[2] = {0, 1}, v0[2] = {1, 0};
    (void)state;
    rh_sys(&sys, &u);
    rh_sys(&sys2, &u2);
    vlbe_bdf_params_default(&p);
    assert_int_equal(vlbe_bdf_init(&st, &sys, &p, 0, q0, v0, w, BD_LW, iw, BD_LIW), VLBE_OK);
    assert_int_equal(vlbe_bdf_init(&st2, &sys2, &p, 0, q0, v0, w2, BD_LW, iw2, BD_LIW), VLBE_OK);
    for (k = 0; k < 40; ++k) {
        assert_int_equal(vlbe_bdf_step(&st, VLBE_R(100.0)), VLBE_OK);
        assert_int_equal(vlbe_bdf_step(&st2, VLBE_R(100.0)), VLBE_OK);
    }
    assert_true(st.order >= 2);
    for (rcs = 0; rcs < 2; ++rcs) {
        memcpy(&st0, &st, sizeof st);
        u.t_fail = (double)st.t; /* every attempt fails */
        u.fail_rc = rcs == 0 ? -1 : 1;
        assert_int_not_equal(vlbe_bdf_step(&st, VLBE_R(100.0)), VLBE_OK);
        assert_bdf_same(&st, &st0);
        u.t_fail = HUGE_VAL;
    }
    /* the failed calls left no trace: the twin runs agree bit for bit */
    for (k = 0; k < 20; ++k) {
        assert_int_equal(vlbe_bdf_step(&st, VLBE_R(100.0)), VLBE_OK);
        assert_int_equal(vlbe_bdf_step(&st2, VLBE_R(100.0)), VLBE_OK);
        assert_memory_equal(&st.t, &st2.t, sizeof st.t);
        assert_memory_equal(st.q, st2.q, sizeof(vlbe_real) * 6);
    }
}

/* consistent_acc and the static solver: outputs untouched on failure
   (77b73ad already kept them; pinned here with sentinels). */
static void test_start_solvers_failure_untouched(void **state)
{
    static vlbe_real w[BD_LW];
    int iw[BD_LIW];
    vlbe_dae sys;
    rh_user u;
    vlbe_real qdd[2], lam[1], qdd0[2], lam0[1], q[2] = {0, 1}, q0[2];
    const vlbe_real v[2] = {1, 0};
    vlbe_static_params sp;
    (void)state;
    rh_sys(&sys, &u);
    u.mass_zero = 1;
    memset(qdd, SENTINEL, sizeof qdd);
    memset(lam, SENTINEL, sizeof lam);
    memcpy(qdd0, qdd, sizeof qdd);
    memcpy(lam0, lam, sizeof lam);
    assert_int_equal(vlbe_dae_consistent_acc(&sys, 0, q, v, qdd, lam, NULL, w, BD_LW, iw, BD_LIW),
                     VLBE_ESINGULAR);
    assert_memory_equal(qdd, qdd0, sizeof qdd);
    assert_memory_equal(lam, lam0, sizeof lam);
    /* static: max_iter above the bound is EARG (fails on 77b73ad: accepted) */
    vlbe_static_params_default(&sp);
    sp.max_iter = VLBE_INT_MAX_ITER + 1;
    memcpy(q0, q, sizeof q);
    lam[0] = VLBE_R(0.0);
    memcpy(lam0, lam, sizeof lam);
    assert_int_equal(vlbe_dae_static(&sys, &sp, 0, q, lam, NULL, w, BD_LW, iw, BD_LIW), VLBE_EARG);
    assert_memory_equal(q, q0, sizeof q);
    assert_memory_equal(lam, lam0, sizeof lam);
    /* fatal force callback: ECALLBACK, q and lambda as they were */
    vlbe_static_params_default(&sp);
    u.t_fail = -1.0;
    u.fail_rc = -1;
    assert_int_equal(vlbe_dae_static(&sys, &sp, 0, q, lam, NULL, w, BD_LW, iw, BD_LIW),
                     VLBE_ECALLBACK);
    assert_memory_equal(q, q0, sizeof q);
    assert_memory_equal(lam, lam0, sizeof lam);
}

/* ======================================================================= */
/* time without drift                                                      */
/* ======================================================================= */

/* The documented loop `while (st.t < t_end - h/2) vlbe_hht_step(&st, h)`
   over 60 (t_end, h) pairs: it takes round(t_end/h) steps and, where t_end
   is a multiple of h, ends with |t - t_end| <= 2 eps |t_end| (t = N h
   rounded once; h carries one or two roundings, N times: <= 3 u |t_end|,
   u = eps/2).  For the other pairs t = N h within one rounding of
   N h computed in long double.  Fails on 77b73ad: the loop
   `while (st.t < t_end)` of its docs took one step too many in 31 of the
   60 pairs (t_end = 3, h = 0.01 stopped at 3.01; t_end = 1, h = 1/7 at
   1.143), since st->t += h summed the roundings; with the loop below, the
   summed t missed the bound (10 steps of 0.01: t = 0.10000000000000007). */
static void test_hht_time_loop(void **state)
{
    static vlbe_real w[RH_LW];
    int iw[RH_LIW], a, b;
    static const double tends[6] = {0.1, 1.0, 2.0, 3.0, 10.0, 0.7};
    const double hs[10] = {0.01,      0.001, 1.0 / 7.0, 1.0 / 3.0, 0.1,
                           1e-3 / 3.0, 0.02,  0.05,      1.0 / 9.0, 0.025};
    /* t_end / h an integer (exactly, before rounding) */
    static const int mult[6][10] = {{1, 1, 0, 0, 1, 1, 1, 1, 0, 1}, {1, 1, 1, 1, 1, 1, 1, 1, 1, 1},
                                    {1, 1, 1, 1, 1, 1, 1, 1, 1, 1}, {1, 1, 1, 1, 1, 1, 1, 1, 1, 1},
                                    {1, 1, 1, 1, 1, 1, 1, 1, 1, 1}, {1, 1, 0, 0, 1, 1, 1, 1, 0, 1}};
    vlbe_dae sys;
    rh_user u;
    vlbe_hht_params p;
    const vlbe_real q0[2] = {0, 1}, v0[2] = {1, 0};
    double worst = 0.0;
    (void)state;
    rh_sys(&sys, &u);
    vlbe_hht_params_genalpha(&p, VLBE_R(0.8));
    for (a = 0; a < 6; ++a)
        for (b = 0; b < 10; ++b) {
            vlbe_hht st;
            const vlbe_real tend = (vlbe_real)tends[a], h = (vlbe_real)hs[b];
            const long nexp = (long)floor((double)tend / (double)h + 0.5);
            long cnt = 0;
            assert_int_equal(vlbe_hht_init(&st, &sys, &p, 0, q0, v0, w, RH_LW, iw, RH_LIW),
                             VLBE_OK);
            while (st.t < tend - h / 2 && cnt <= nexp) { /* one step past nexp fails below */
                assert_int_equal(vlbe_hht_step(&st, h), VLBE_OK);
                ++cnt;
            }
            assert_true(cnt == nexp);
            if (mult[a][b]) {
                double err = fabs((double)st.t - (double)tend) / (EPS * (double)tend);
                if (err > worst) worst = err;
                ASSERT_CLOSE_CTX((double)st.t, (double)tend, 2.0 * EPS, 0.0, "t_end %g h %g",
                                 tends[a], hs[b]);
            } else {
                long double ref = (long double)nexp * (long double)h;
                ASSERT_CLOSE_CTX((double)st.t, (double)ref, EPS, 0.0, "t_end %g h %g", tends[a],
                                 hs[b]);
            }
            /* the constraint was last evaluated at the final time */
            if (cnt > 0) assert_true(u.t_last_c == (double)st.t);
        }
    tu_report("HHT loop |t - t_end| / (eps t_end), worst of 60", worst, 2.0);
}

/* 1e5 steps of 1e-6 on the rheonomic constraint x = t: t lands on 0.1
   within eps 0.1 (N h rounded once, h = 1e-6 rounded once), the constraint
   is evaluated there, and x = 0.1 to the Newton tolerance (index 3: C / bp
   is the residual; |x - t| <= 1e-9 relative, rtol of the parameters).
   float: 1e4 steps of 1e-5 (1e5 steps of 1e-6 would ask x to 1e-6
   relative, below float's Newton floor).  Fails on 77b73ad: t =
   0.1 + 7.9e-14 (double), and the constraint was enforced there. */
static void test_hht_time_rheonomic(void **state)
{
    static vlbe_real w[RH_LW];
    int iw[RH_LIW];
    long k;
    vlbe_dae sys;
    rh_user u;
    vlbe_hht_params p;
    vlbe_hht st;
    const vlbe_real q0[2] = {0, 1}, v0[2] = {1, 0};
#ifdef VLBE_USE_FLOAT
    const long N = 10000;
    const vlbe_real h = VLBE_R(1e-5);
#else
    const long N = 100000;
    const vlbe_real h = VLBE_R(1e-6);
#endif
    (void)state;
    rh_sys(&sys, &u);
    u.g = 0.0;
    vlbe_hht_params_genalpha(&p, VLBE_R(0.8));
    assert_int_equal(vlbe_hht_init(&st, &sys, &p, 0, q0, v0, w, RH_LW, iw, RH_LIW), VLBE_OK);
    for (k = 0; k < N; ++k) assert_int_equal(vlbe_hht_step(&st, h), VLBE_OK);
    ASSERT_CLOSE((double)st.t, 0.1, EPS, 0.0);
    assert_true(u.t_last_c == (double)st.t);
    /* x = c t with c = 1: Newton-tolerance level, 100 eps relative */
    ASSERT_CLOSE((double)st.q[0], (double)st.t, 100.0 * EPS, 0.0);
    tu_report("HHT 0.1 after N steps: |t - 0.1| / (eps 0.1)", fabs((double)st.t - 0.1) / (EPS * 0.1),
              1.0);
}

/* Fixed-step BDF: h0 = 1e-3, 1000 steps with a far t_stop end at 1 within
   eps (t = N h0 once rounded), and vlbe_bdf_advance to the outputs k/10
   with h0 = 0.01 takes exactly 10 steps per output, no sliver step (a step
   ending within 4 eps |t| of t_out ends on it).  Fails on 77b73ad: t was a
   sum (1.0000000000000007 after 1000 steps). */
static void test_bdf_fixed_step_time(void **state)
{
    static vlbe_real w[BD_LW];
    int iw[BD_LIW], k, j;
    vlbe_dae sys;
    rh_user u;
    vlbe_bdf st;
    vlbe_bdf_params p;
    const vlbe_real q0[2] = {0, 1}, v0[2] = {1, 0};
    (void)state;
    rh_sys(&sys, &u);
    vlbe_bdf_params_default(&p);
    p.fixed_step = 1;
    p.max_order = 2;
    p.h0 = VLBE_R(1e-3);
    assert_int_equal(vlbe_bdf_init(&st, &sys, &p, 0, q0, v0, w, BD_LW, iw, BD_LIW), VLBE_OK);
    for (k = 0; k < 1000; ++k) assert_int_equal(vlbe_bdf_step(&st, VLBE_R(100.0)), VLBE_OK);
    ASSERT_CLOSE((double)st.t, 1.0, EPS, 0.0);
    assert_true(u.t_last_c == (double)st.t);
    p.h0 = VLBE_R(0.01);
    assert_int_equal(vlbe_bdf_init(&st, &sys, &p, 0, q0, v0, w, BD_LW, iw, BD_LIW), VLBE_OK);
    for (k = 1; k <= 30; ++k) {
        long s0 = st.stats.steps;
        const vlbe_real tout = (vlbe_real)k / VLBE_R(10.0);
        assert_int_equal(vlbe_bdf_advance(&st, tout), VLBE_OK);
        assert_true(st.t == tout);
        j = (int)(st.stats.steps - s0);
        assert_int_equal(j, 10);
    }
}

/* max_steps caps the steps of one vlbe_bdf_advance call: with h0 = 0.01
   fixed, advancing to 1 takes 100 steps; a cap of 30 stops after exactly 30
   with VLBE_EBOUND at t = 0.3 (the last accepted step, whose history goes
   on: three more calls reach 1 with the twin run's state bit for bit), and
   a cap of 100 is not hit. */
static void test_bdf_advance_max_steps(void **state)
{
    static vlbe_real w[BD_LW], w2[BD_LW];
    int iw[BD_LIW], iw2[BD_LIW], k;
    vlbe_dae sys, sys2;
    rh_user u, u2;
    vlbe_bdf st, st2;
    vlbe_bdf_params p;
    const vlbe_real q0[2] = {0, 1}, v0[2] = {1, 0};
    (void)state;
    rh_sys(&sys, &u);
    rh_sys(&sys2, &u2);
    vlbe_bdf_params_default(&p);
    p.fixed_step = 1;
    p.max_order = 2;
    p.h0 = VLBE_R(0.01);
    p.max_steps = 30;
    assert_int_equal(vlbe_bdf_init(&st, &sys, &p, 0, q0, v0, w, BD_LW, iw, BD_LIW), VLBE_OK);
    p.max_steps = 100;
    assert_int_equal(vlbe_bdf_init(&st2, &sys2, &p, 0, q0, v0, w2, BD_LW, iw2, BD_LIW), VLBE_OK);
    assert_int_equal(vlbe_bdf_advance(&st, VLBE_R(1.0)), VLBE_EBOUND);
    assert_int_equal((int)st.stats.steps, 30);
    ASSERT_CLOSE((double)st.t, 0.3, 4 * EPS, 0.0);
    for (k = 0; k < 3; ++k) {
        const vlbe_status rc = vlbe_bdf_advance(&st, VLBE_R(1.0));
        assert_int_equal(rc, k < 2 ? VLBE_EBOUND : VLBE_OK);
    }
    assert_int_equal(vlbe_bdf_advance(&st2, VLBE_R(1.0)), VLBE_OK);
    assert_int_equal((int)st2.stats.steps, 100);
    assert_true(st.t == VLBE_R(1.0) && st2.t == VLBE_R(1.0));
    assert_memory_equal(st.q, st2.q, 2 * sizeof st.q[0]);
    assert_memory_equal(st.v, st2.v, 2 * sizeof st.v[0]);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_lu_valid_bit_identical),
        cmocka_unit_test(test_lu_subnormal_pivot),
        cmocka_unit_test(test_lu_overflow),
        cmocka_unit_test(test_lu_failure_outputs),
        cmocka_unit_test(test_hht_init_args),
        cmocka_unit_test(test_hht_init_failure_untouched),
        cmocka_unit_test(test_hht_step_bad_h),
        cmocka_unit_test(test_hht_step_failure_untouched),
        cmocka_unit_test(test_hht_step_halved_lands),
        cmocka_unit_test(test_hht_step_trial_acc_overflow),
        cmocka_unit_test(test_hht_step_time_overflow),
        cmocka_unit_test(test_bdf_init_failure),
        cmocka_unit_test(test_bdf_step_failure_untouched),
        cmocka_unit_test(test_start_solvers_failure_untouched),
        cmocka_unit_test(test_hht_time_loop),
        cmocka_unit_test(test_hht_time_rheonomic),
        cmocka_unit_test(test_bdf_fixed_step_time),
        cmocka_unit_test(test_bdf_advance_max_steps),
    };
    return cmocka_run_group_tests_name("test_contract_core", tests, NULL, NULL);
}
