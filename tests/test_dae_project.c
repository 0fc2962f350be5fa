/* test_dae_project.c -- cmocka suite of vlbe_dae_project, the consistent
   start of integrators.h, and of the projection in vlbe_hht_init and
   vlbe_bdf_init -- part of vlbe                   SPDX-License-Identifier: MIT
   cc -std=c99 -Wall -Wextra -Wpedantic ... -O2 tests/test_dae_project.c -lcmocka -lm

   Tests
     pendulum_closest        the pendulum of scenes/pendulum.h (M = m I)
                             started 20 % off the circle with a radial
                             velocity: q -> L q / |q| (the closest point of
                             the circle: every Gauss-Newton correction lies
                             along the current q), v -> its part tangent
                             there, in a few iterations, ||C|| <= the default
                             tolerance
     linear_mass_metric      linear constraints A q = c0 + s t with a full
                             mass matrix, dense and banded: one iteration
                             lands on the closed-form M-orthogonal projection
                             dq = -M^-1 A^T (A M^-1 A^T)^-1 (A q - c), v on
                             the one of A v = s (C_t used); the Euclidean
                             projection is another point
     consistent_untouched    a start on the constraints: q, v bit for bit,
                             one constr and one constr_jac call, no solve
     failures                redundant constraints -> ESINGULAR, no point of
                             the constraint near -> ENOCONV after
                             VLBE_DAE_PROJECT_ITER iterations, callback ->
                             ECALLBACK, NaN -> ENONFINITE, EARG, EWORK; q and
                             v bit for bit as they were each time
     hht_init_projects       vlbe_hht_init (project = 1) from an off start is
                             vlbe_hht_init (project = 0, the default) from
                             the projected start, bit for bit, and project =
                             0 keeps the off start; a consistent start: the
                             same run with project 0 and 1, bit for bit */
#include "test_util.h"
#include "../integrators.h"

#include "../scenes/pendulum.h"

#include <string.h>

#define EPS ((double)VLBE_EPS)

enum { WLEN = 4096, IWLEN = 64 };
static vlbe_real g_work[WLEN];
static int g_iwork[IWLEN];

/* vlbe_dae_project with the suite's workspace (the _sys query of sys) */
static vlbe_status project(const vlbe_dae *s, vlbe_real t, vlbe_real *q, vlbe_real *v,
                           vlbe_real tol, vlbe_dae_stats *st)
{
    assert_true(vlbe_dae_work_len_sys(s) <= WLEN && vlbe_dae_iwork_len_sys(s) <= IWLEN);
    return vlbe_dae_project(s, t, q, v, tol, st, g_work, vlbe_dae_work_len_sys(s), g_iwork,
                            vlbe_dae_iwork_len_sys(s));
}

/* -- the pendulum ----------------------------------------------------------
   The closest point of the circle |q| = L to q is L q / |q|; Gauss-Newton
   with W = m I corrects along C_q^T = q, so every iterate stays on the ray
   of q0 and the limit is that point.  The velocity projection at it
   removes the radial part: v - (v.e) e, e = q / L. */
static void test_pendulum_closest(void **state)
{
    pend_par p = pend_default();
    vlbe_dae s;
    vlbe_dae_stats st;
    const double a = -0.5, r0 = 1.2; /* angle [rad], radius / L */
    double e[2], vr, dq, dv;
    vlbe_real q[2], v[2], v0[2] = {VLBE_R(0.3), VLBE_R(2.0)};
    int i;
    (void)state;
    pend_setup(&s, &p);
    q[0] = (vlbe_real)(r0 * PEND_L * cos(a));
    q[1] = (vlbe_real)(r0 * PEND_L * sin(a));
    v[0] = v0[0];
    v[1] = v0[1];
    memset(&st, 0, sizeof st);
    assert_int_equal(project(&s, VLBE_R(0.0), q, v, VLBE_R(0.0), &st), VLBE_OK);
    e[0] = cos(a);
    e[1] = sin(a);
    vr = e[0] * (double)v0[0] + e[1] * (double)v0[1];
    /* q: C <= 64 eps (default tol) moves q by 64 eps / L along e; the
       iterates' rounding adds a few eps: 100 eps L.  v: the projection
       is one solve, its rounding a few eps |v| (cond of [I q; q^T 0] ~ 1):
       100 eps |v| */
    for (i = 0; i < 2; ++i) {
        dq = fabs((double)q[i] - PEND_L * e[i]);
        dv = fabs((double)v[i] - ((double)v0[i] - vr * e[i]));
        tu_report("pendulum projected q - closest point", dq, 100.0 * EPS * PEND_L);
        tu_report("pendulum projected v - tangential part", dv, 100.0 * EPS * 2.1);
        assert_true(dq <= 100.0 * EPS * PEND_L);
        assert_true(dv <= 100.0 * EPS * 2.1);
    }
    /* Gauss-Newton converges quadratically from 20 % off: the radial error
       0.2, then ~0.02, 2e-4, 2e-8, 4e-16 (C = (r^2 - 1)/2, one Newton step
       on r^2 squares the relative error): at most 6 iterations */
    assert_true(st.newton_iters >= 1 && st.newton_iters <= 6);
    assert_true(st.lu_factors == st.newton_iters + 1); /* + the velocity solve */
    assert_true(st.mass_calls == 1);                   /* the metric, once */
    assert_true(st.newton_fails == 0);
}

/* -- linear constraints with a full mass matrix ------------------------------
   n = 3, m = 2: C = A q - c0 - s t, C_q = A, C_t = -s; M a fixed SPD
   matrix.  Gauss-Newton on linear constraints lands on them in one
   iteration, at the M-orthogonal projection. */
static const double LM_M[3][3] = {{4.0, 1.0, 0.5}, {1.0, 3.0, 1.0}, {0.5, 1.0, 2.0}};
static const double LM_A[2][3] = {{1.0, 1.0, 1.0}, {1.0, -1.0, 2.0}};
static const double LM_C0[2] = {1.0, 0.5}, LM_S[2] = {0.25, -0.75};

typedef struct lin {
    int band;
    int order[5]; /* banded: q0 q1 q2 lambda0 lambda1 -> 0 2 4 1 3 */
} lin;
#define LM_LD 9 /* banded: kl = ku = 4 (the whole 5 x 5 matrix) */

static void lin_put(const lin *l, vlbe_real *A, int i, int j, double x)
{
    if (l->band) A[VLBE_BAND_IDX(LM_LD, 4, l->order[i], l->order[j])] = (vlbe_real)x;
    else if (i >= 3) A[(i - 3) * 3 + j] = (vlbe_real)x;
    else A[i * 3 + j] = (vlbe_real)x;
}
static int lin_mass(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v, vlbe_real *M)
{
    const lin *l = (const lin *)u;
    int i, j;
    (void)t, (void)q, (void)v;
    memset(M, 0, (l->band ? 5 * LM_LD : 9) * sizeof *M);
    for (i = 0; i < 3; ++i)
        for (j = 0; j < 3; ++j) lin_put(l, M, i, j, LM_M[i][j]);
    return 0;
}
static int lin_force(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v, vlbe_real *Q)
{
    (void)u, (void)t, (void)q, (void)v;
    Q[0] = Q[1] = Q[2] = VLBE_R(0.0);
    return 0;
}
static int lin_constr(void *u, vlbe_real t, const vlbe_real *q, vlbe_real *C)
{
    int k;
    (void)u;
    for (k = 0; k < 2; ++k)
        C[k] = (vlbe_real)LM_A[k][0] * q[0] + (vlbe_real)LM_A[k][1] * q[1] +
               (vlbe_real)LM_A[k][2] * q[2] - (vlbe_real)LM_C0[k] - (vlbe_real)LM_S[k] * t;
    return 0;
}
static int lin_cjac(void *u, vlbe_real t, const vlbe_real *q, vlbe_real *Cq, vlbe_real *Ct)
{
    const lin *l = (const lin *)u;
    int k, j;
    (void)t, (void)q;
    memset(Cq, 0, (l->band ? 5 * LM_LD : 6) * sizeof *Cq);
    for (k = 0; k < 2; ++k) {
        for (j = 0; j < 3; ++j) lin_put(l, Cq, 3 + k, j, LM_A[k][j]);
        if (Ct) Ct[k] = (vlbe_real)-LM_S[k];
    }
    return 0;
}
static void lin_setup(vlbe_dae *s, lin *l, int band)
{
    static const int ord[5] = {0, 2, 4, 1, 3};
    memset(s, 0, sizeof *s);
    memcpy(l->order, ord, sizeof ord);
    l->band = band;
    s->n = 3;
    s->m = 2;
    s->flags = VLBE_DAE_MASS_CONST;
    s->user = l;
    s->mass = lin_mass;
    s->force = lin_force;
    s->constr = lin_constr;
    s->constr_jac = lin_cjac;
    if (band) {
        s->storage = VLBE_DAE_BANDED;
        s->kl = s->ku = 4;
        s->order = l->order;
    }
}

/* x = W^-1 A^T (A W^-1 A^T)^-1 r in double (W 3 x 3 SPD, A 2 x 3), by
   Cramer's rule: independent of integrators.h's LU */
static void lin_proj(const double W[3][3], const double r[2], double *x)
{
    double Wi[3][3], B[2][3], S[2][2], det, y[2];
    int i, j, k;
    det = W[0][0] * (W[1][1] * W[2][2] - W[1][2] * W[2][1]) -
          W[0][1] * (W[1][0] * W[2][2] - W[1][2] * W[2][0]) +
          W[0][2] * (W[1][0] * W[2][1] - W[1][1] * W[2][0]);
    for (i = 0; i < 3; ++i)
        for (j = 0; j < 3; ++j) {
            /* cofactor of (j, i) */
            int r0 = (j + 1) % 3, r1 = (j + 2) % 3, c0 = (i + 1) % 3, c1 = (i + 2) % 3;
            Wi[i][j] = (W[r0][c0] * W[r1][c1] - W[r0][c1] * W[r1][c0]) / det;
        }
    for (k = 0; k < 2; ++k) /* B = A W^-1 (2 x 3) */
        for (j = 0; j < 3; ++j) {
            B[k][j] = 0.0;
            for (i = 0; i < 3; ++i) B[k][j] += LM_A[k][i] * Wi[i][j];
        }
    for (k = 0; k < 2; ++k)
        for (j = 0; j < 2; ++j) {
            S[k][j] = 0.0;
            for (i = 0; i < 3; ++i) S[k][j] += B[k][i] * LM_A[j][i];
        }
    det = S[0][0] * S[1][1] - S[0][1] * S[1][0];
    y[0] = (S[1][1] * r[0] - S[0][1] * r[1]) / det;
    y[1] = (S[0][0] * r[1] - S[1][0] * r[0]) / det;
    for (j = 0; j < 3; ++j) x[j] = B[0][j] * y[0] + B[1][j] * y[1];
}

static void test_linear_mass_metric(void **state)
{
    static const double I3[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const vlbe_real q0[3] = {VLBE_R(0.7), VLBE_R(-0.2), VLBE_R(0.9)},
                    v0[3] = {VLBE_R(0.5), VLBE_R(1.5), VLBE_R(-1.0)};
    const double t = 0.5;
    double r[2], dq[3], dv[3], de[3], qx[3], vx[3], dist = 0.0;
    int band, k, i;
    (void)state;
    for (k = 0; k < 2; ++k) { /* residuals at the start */
        r[k] = -LM_C0[k] - LM_S[k] * t;
        for (i = 0; i < 3; ++i) r[k] += LM_A[k][i] * (double)q0[i];
    }
    lin_proj(LM_M, r, dq);
    lin_proj(I3, r, de);
    for (k = 0; k < 2; ++k) { /* A v - s */
        double g = -LM_S[k];
        for (i = 0; i < 3; ++i) g += LM_A[k][i] * (double)v0[i];
        r[k] = g;
    }
    lin_proj(LM_M, r, dv);
    for (i = 0; i < 3; ++i) {
        qx[i] = (double)q0[i] - dq[i];
        vx[i] = (double)v0[i] - dv[i];
        dist = fmax(dist, fabs(de[i] - dq[i]));
    }
    /* the Euclidean closest point is another one (0.23 away): the test
       below tells the metrics apart */
    assert_true(dist > 0.1);
    for (band = 0; band < 2; ++band) {
        vlbe_dae s;
        lin l;
        vlbe_dae_stats st;
        vlbe_real q[3], v[3];
        lin_setup(&s, &l, band);
        memcpy(q, q0, sizeof q);
        memcpy(v, v0, sizeof v);
        memset(&st, 0, sizeof st);
        assert_int_equal(project(&s, (vlbe_real)t, q, v, VLBE_R(0.0), &st), VLBE_OK);
        /* one correction (the second iterate is on the constraint to
           rounding, or the correction at the rounding floor stops it):
           the saddle system of cond ~ 30 solved to a few eps: 100 eps of
           the sizes (|q|, |v| ~ 1) */
        assert_true(st.newton_iters == 1 || st.newton_iters == 2);
        ASSERT_VEC_CLOSE(q, qx, 3, 0.0, 100.0 * EPS);
        ASSERT_VEC_CLOSE(v, vx, 3, 0.0, 100.0 * EPS);
    }
}

/* -- a consistent start ---------------------------------------------------- */
static void test_consistent_untouched(void **state)
{
    pend_par p = pend_default();
    vlbe_dae s;
    vlbe_dae_stats st;
    vlbe_real q[2], v[2], q1[2], v1[2];
    (void)state;
    pend_setup(&s, &p);
    q[0] = (vlbe_real)cos(-0.7);
    q[1] = (vlbe_real)sin(-0.7);
    v[0] = (vlbe_real)(1.5 * -sin(-0.7));
    v[1] = (vlbe_real)(1.5 * cos(-0.7));
    memcpy(q1, q, sizeof q);
    memcpy(v1, v, sizeof v);
    memset(&st, 0, sizeof st);
    assert_int_equal(project(&s, VLBE_R(0.0), q, v, VLBE_R(0.0), &st), VLBE_OK);
    assert_memory_equal(q, q1, sizeof q);
    assert_memory_equal(v, v1, sizeof v);
    assert_true(st.constr_calls == 2 && st.mass_calls == 0 && st.lu_factors == 0 &&
                st.newton_iters == 0);
    /* no constraints: nothing to do */
    s.m = 0;
    assert_int_equal(project(&s, VLBE_R(0.0), q, v, VLBE_R(0.0), &st), VLBE_OK);
    assert_memory_equal(q, q1, sizeof q);
}

/* -- failures ---------------------------------------------------------------- */
/* the pendulum's constraint twice (rank 1), or C = (x^2 + 1)/2 (no real
   point), or a failing constr */
static int bad_mode;
static int bad_constr(void *u, vlbe_real t, const vlbe_real *q, vlbe_real *C)
{
    (void)u, (void)t;
    if (bad_mode == 2) return 3;
    if (bad_mode == 1) {
        C[0] = VLBE_R(0.5) * (q[0] * q[0] + VLBE_R(1.0));
        return 0;
    }
    C[0] = C[1] = VLBE_R(0.5) * (q[0] * q[0] + q[1] * q[1] - VLBE_R(1.0));
    return 0;
}
static int bad_cjac(void *u, vlbe_real t, const vlbe_real *q, vlbe_real *Cq, vlbe_real *Ct)
{
    (void)u, (void)t;
    if (bad_mode == 1) {
        Cq[0] = q[0];
        Cq[1] = VLBE_R(0.0);
        if (Ct) Ct[0] = VLBE_R(0.0);
        return 0;
    }
    Cq[0] = Cq[2] = q[0];
    Cq[1] = Cq[3] = q[1];
    if (Ct) Ct[0] = Ct[1] = VLBE_R(0.0);
    return 0;
}

static void test_failures(void **state)
{
    pend_par p = pend_default();
    vlbe_dae s;
    vlbe_dae_stats st;
    vlbe_real q[2] = {VLBE_R(0.7), VLBE_R(-0.9)}, v[2] = {VLBE_R(0.3), VLBE_R(0.1)};
    vlbe_real q1[2], v1[2];
    (void)state;
    memcpy(q1, q, sizeof q);
    memcpy(v1, v, sizeof v);
    pend_setup(&s, &p);
    s.constr = bad_constr;
    s.constr_jac = bad_cjac;
    s.constr_acc = NULL;
    s.constr_hess = NULL;
    /* redundant constraints: [M C_q^T; C_q 0] singular */
    s.m = 2;
    bad_mode = 0;
    memset(&st, 0, sizeof st);
    assert_int_equal(project(&s, VLBE_R(0.0), q, v, VLBE_R(0.0), &st), VLBE_ESINGULAR);
    assert_memory_equal(q, q1, sizeof q);
    assert_memory_equal(v, v1, sizeof v);
    /* no real point: Newton on x^2 + 1 = 0 wanders (x -> (x - 1/x)/2) */
    s.m = 1;
    bad_mode = 1;
    memset(&st, 0, sizeof st);
    assert_int_equal(project(&s, VLBE_R(0.0), q, v, VLBE_R(0.0), &st), VLBE_ENOCONV);
    assert_true(st.newton_iters == VLBE_DAE_PROJECT_ITER && st.newton_fails == 1);
    assert_memory_equal(q, q1, sizeof q);
    assert_memory_equal(v, v1, sizeof v);
    /* a callback fails */
    bad_mode = 2;
    memset(&st, 0, sizeof st);
    assert_int_equal(project(&s, VLBE_R(0.0), q, v, VLBE_R(0.0), &st), VLBE_ECALLBACK);
    assert_int_equal(st.callback_rc, 3);
    assert_memory_equal(q, q1, sizeof q);
    /* arguments: NaN in q, tol NaN, NULL, workspace */
    pend_setup(&s, &p);
    q[1] = (vlbe_real)NAN;
    assert_int_equal(project(&s, VLBE_R(0.0), q, v, VLBE_R(0.0), NULL), VLBE_ENONFINITE);
    q[1] = q1[1];
    assert_int_equal(project(&s, VLBE_R(0.0), q, v, (vlbe_real)NAN, NULL), VLBE_EARG);
    assert_int_equal(project(&s, (vlbe_real)INFINITY, q, v, VLBE_R(0.0), NULL), VLBE_EARG);
    assert_int_equal(project(&s, VLBE_R(0.0), NULL, v, VLBE_R(0.0), NULL), VLBE_EARG);
    assert_int_equal(vlbe_dae_project(&s, VLBE_R(0.0), q, v, VLBE_R(0.0), NULL, g_work,
                                      vlbe_dae_work_len_sys(&s) - 1, g_iwork, IWLEN),
                     VLBE_EWORK);
    assert_int_equal(vlbe_dae_project(&s, VLBE_R(0.0), q, v, VLBE_R(0.0), NULL, g_work, WLEN,
                                      g_iwork, vlbe_dae_iwork_len_sys(&s) - 1),
                     VLBE_EWORK);
    assert_memory_equal(q, q1, sizeof q);
    assert_memory_equal(v, v1, sizeof v);
    /* a user tolerance is honoured: tol = 1e-3 stops at the first iterate
       below it (the pendulum 20 % off: one iteration leaves |C| ~ 0.02, a
       second ~ 2e-4, a third below 1e-3 */
    {
        vlbe_real qa[2] = {VLBE_R(1.2), VLBE_R(0.0)}, va[2] = {VLBE_R(0.0), VLBE_R(0.0)};
        memset(&st, 0, sizeof st);
        assert_int_equal(project(&s, VLBE_R(0.0), qa, va, VLBE_R(1e-3), &st), VLBE_OK);
        assert_true(fabs(0.5 * ((double)qa[0] * (double)qa[0] - 1.0)) <= 1e-3);
        assert_true(fabs((double)qa[0] - 1.0) > 100.0 * EPS); /* not converged further */
    }
}

/* -- the integrators' start ---------------------------------------------- */
enum { HW = 1024 };
static vlbe_real g_hw[2][HW];
static int g_hiw[2][16];

static void test_hht_init_projects(void **state)
{
    pend_par p = pend_default();
    vlbe_dae s;
    vlbe_hht_params par;
    vlbe_hht a, b;
    vlbe_real q0[2] = {VLBE_R(1.01), VLBE_R(-0.02)}, v0[2] = {VLBE_R(0.1), VLBE_R(0.2)};
    vlbe_real qp[2], vp[2];
    size_t lw, liw;
    int k;
    (void)state;
    pend_setup(&s, &p);
    lw = vlbe_hht_work_len(2, 1);
    liw = vlbe_hht_iwork_len(2, 1);
    assert_true(lw <= HW && liw <= 16);
    memcpy(qp, q0, sizeof qp);
    memcpy(vp, v0, sizeof vp);
    assert_int_equal(project(&s, VLBE_R(0.0), qp, vp, VLBE_R(0.0), NULL), VLBE_OK);
    assert_int_equal(vlbe_hht_params_genalpha(&par, VLBE_R(0.8)), VLBE_OK);
    assert_int_equal(par.project, 0); /* the default: starts as given */
    par.project = 1;
    assert_int_equal(vlbe_hht_init(&a, &s, &par, VLBE_R(0.0), q0, v0, g_hw[0], lw, g_hiw[0], liw),
                     VLBE_OK);
    /* the caller's q0, v0 are not written */
    assert_true(q0[0] == VLBE_R(1.01) && v0[1] == VLBE_R(0.2));
    par.project = 0;
    assert_int_equal(vlbe_hht_init(&b, &s, &par, VLBE_R(0.0), qp, vp, g_hw[1], lw, g_hiw[1], liw),
                     VLBE_OK);
    for (k = 0; k < 20; ++k) {
        assert_memory_equal(a.q, b.q, (4 * 2 + 1) * sizeof(vlbe_real)); /* q v qdd a lambda */
        assert_int_equal(vlbe_hht_step(&a, VLBE_R(1e-2)), VLBE_OK);
        assert_int_equal(vlbe_hht_step(&b, VLBE_R(1e-2)), VLBE_OK);
    }
    /* project = 0 keeps the start as given */
    assert_int_equal(vlbe_hht_init(&b, &s, &par, VLBE_R(0.0), q0, v0, g_hw[1], lw, g_hiw[1], liw),
                     VLBE_OK);
    assert_memory_equal(b.q, q0, sizeof q0);
    assert_memory_equal(b.v, v0, sizeof v0);
    /* a consistent start: the same run with and without projection */
    pend_initial(&p, q0, v0);
    assert_int_equal(vlbe_hht_init(&b, &s, &par, VLBE_R(0.0), q0, v0, g_hw[1], lw, g_hiw[1], liw),
                     VLBE_OK);
    par.project = 1;
    assert_int_equal(vlbe_hht_init(&a, &s, &par, VLBE_R(0.0), q0, v0, g_hw[0], lw, g_hiw[0], liw),
                     VLBE_OK);
    for (k = 0; k < 20; ++k) {
        assert_int_equal(vlbe_hht_step(&a, VLBE_R(1e-2)), VLBE_OK);
        assert_int_equal(vlbe_hht_step(&b, VLBE_R(1e-2)), VLBE_OK);
    }
    assert_memory_equal(a.q, b.q, (4 * 2 + 1) * sizeof(vlbe_real));
    /* project out of range */
    par.project = 2;
    assert_int_equal(vlbe_hht_init(&a, &s, &par, VLBE_R(0.0), q0, v0, g_hw[0], lw, g_hiw[0], liw),
                     VLBE_EARG);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_pendulum_closest),
        cmocka_unit_test(test_linear_mass_metric),
        cmocka_unit_test(test_consistent_untouched),
        cmocka_unit_test(test_failures),
        cmocka_unit_test(test_hht_init_projects),
    };
    return cmocka_run_group_tests_name("dae_project", tests, NULL, NULL);
}
