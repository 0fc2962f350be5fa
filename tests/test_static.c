/* test_static.c -- cmocka suite of vlbe_dae_static (integrators.h): static
   equilibrium by Newton's method with a line search -- part of vlbe
                                                   SPDX-License-Identifier: MIT
   cc -std=c99 -Wall -Wextra -Wpedantic ... -O2 tests/test_static.c -lcmocka -lm

   The problems, each with a closed-form equilibrium:
     springs  three masses in a line, springs wall-1-2-3, mass 3 held at d by a
              constraint (linear, n = 3, m = 1): q and the reaction lambda
              from the 2 x 2 system solved by hand
     bead     a bead on a circle of radius R (C = (|p|^2 - R^2)/2, nonlinear),
              pulled by a zero-length spring to (a, 0) and by a weight:
              p = R b/|b|, lambda = |b|/R - k with b = (k a, -W)
     truss    the two-bar (von Mises) truss, apex height prescribed by a
              constraint y = w and traced through both limit points:
              lambda(w) = -2 N w / l, N = EA (l - L0)/L0, l = sqrt(b^2 + w^2)
     logspr   Q = F - k log(1 + q) (domain q > -1: the callback returns 1
              outside), q* = exp(F/k) - 1
     atan     Q = c - atan(q), q* = tan(c): plain Newton from q = 10 diverges
   Every tolerance says why it has its size; with VLBE_TEST_REPORT=1 the
   measured errors are printed beside them ("measured" below: the double
   -O2 build, tag m:, the float build where quoted, m@flt:;
   tests/measured.sh checks them against the report).

   Tests
     static_params_default     defaults; bad parameters / arguments -> EARG
     static_linear_springs     q, lambda vs the hand solution; 2 iterations;
                               exact counter identities (analytic and FD K)
     static_bead_on_circle     nonlinear constraint: p, lambda vs closed form with
                               constr_hess, with its FD, and under
                               VLBE_DAE_NO_CHESS (slower, same answer)
     static_truss_snapthrough  displacement control through both limit points:
                               lambda(w) vs closed form at 41 heights
     static_fd_jacobian        analytic K of the truss vs central differences;
                               the FD-K solve agrees with the analytic-K one
     static_line_search        log spring: a trial outside the domain is
                               backtracked; atan: non-decrease backtracked;
                               plain Newton (max_halvings = 0) fails, untouched;
                               the defaults' answer is bit for bit that of the
                               backtracking alone (watchdog = 0)
     static_watchdog_return    atan on |q| < 100: the second full step leaves
                               the domain -> back to the start, then the
                               backtracking's steps bit for bit
     static_full_step_fallback Rosenbrock's residual: the full Newton step
                               raises the residual tenfold, no halving lowers
                               it -> the full step is taken, root in 2 steps;
                               the defaults' watchdog takes it at once
     static_snapthrough_load   the truss under a dead load twice its limit
                               load, from the unloaded shape pushed sideways:
                               plain Newton cycles (ENOCONV), the defaults
                               return to the start after the watched steps
                               and backtrack to the inverted equilibrium
                               (closed form by bisection)
     static_residual_test      ftol alone, ftol with the increment test
                               (at least as many iterations, ||Psi||/sqrt(N) <= ftol),
                               ftol below the rounding floor -> ENOCONV
     static_fail_singular      floating structure -> ESINGULAR, untouched
     static_fail_noconv        max_iter too small -> ENOCONV, untouched
     static_fail_callback      callback -1 (force, constraint, Jacobian) ->
                               ECALLBACK with callback_rc, untouched; +1 at the
                               start -> ECALLBACK
     static_fail_work          workspace too small / NULL -> EWORK, untouched
     static_fail_nonfinite     NaN/Inf start, NaN force -> ENONFINITE, untouched */
#include "test_util.h"
#include "../integrators.h"
#include "../scenes/vonmises_truss.h"

#include <string.h>

#define EPS ((double)VLBE_EPS)

/* ------------------------------------------------------------------------ */
/* Solver set-up with a fixed-size workspace (largest problem: n = 3, m = 1). */
enum { WLEN = 512, IWLEN = 16 };
static vlbe_real g_w[WLEN];
static int g_iw[IWLEN];

static vlbe_status solve(const vlbe_dae *sys, const vlbe_static_params *par, vlbe_real *q,
                         vlbe_real *lam, vlbe_dae_stats *st)
{
    size_t lw = vlbe_static_work_len(sys->n, sys->m), liw = vlbe_static_iwork_len(sys->n, sys->m);
    assert_true(lw <= WLEN);
    assert_true(liw <= IWLEN);
    if (st) memset(st, 0, sizeof *st);
    return vlbe_dae_static(sys, par, VLBE_R(0.0), q, lam, st, g_w, lw, g_iw, liw);
}

/* bitwise: a failed call leaves q and lambda exactly as they were */
static void assert_untouched(const vlbe_real *a, const vlbe_real *b, int n)
{
    assert_true(memcmp(a, b, (size_t)n * sizeof(vlbe_real)) == 0);
}

/* ||Psi||_2 / sqrt(n + m), Psi = (C_q^T lambda - Q, C), evaluated here from
   the callbacks (independently of the solver) */
static double psi_norm(const vlbe_dae *s, const vlbe_real *q, const vlbe_real *lam)
{
    vlbe_real Q[8], Cq[8], C[4], z[8] = {0};
    double sum = 0.0;
    int i, j, n = s->n, m = s->m;
    assert_true(n <= 8 && m * n <= 8 && m <= 4);
    assert_int_equal(s->force(s->user, 0, q, z, Q), 0);
    if (m > 0) {
        assert_int_equal(s->constr(s->user, 0, q, C), 0);
        assert_int_equal(s->constr_jac(s->user, 0, q, Cq, NULL), 0);
    }
    for (i = 0; i < n; ++i) {
        double r = -(double)Q[i];
        for (j = 0; j < m; ++j) r += (double)Cq[j * n + i] * (double)lam[j];
        sum += r * r;
    }
    for (j = 0; j < m; ++j) sum += (double)C[j] * (double)C[j];
    return sqrt(sum / (double)(n + m));
}

/* ------------------------------------------------------------------------ */
/* springs: wall -k1- 1 -k2- 2 -k3- 3, loads F1, F2 on 1, 2; C = q3 - d.
   Q = F - K q; the fault field injects errors for the failure tests. */
typedef struct springs {
    vlbe_real k[3], F[2], d;
    int fault;      /* 0 none, 1 force -1, 2 constr -1, 3 constr_jac -1, 4 force_jac -1,
                       5 force NaN, 6 force +1 */
    long after;     /* good calls before the fault */
    long calls;
} springs;

static int spr_hit(springs *s) { return s->fault != 0 && s->calls++ >= s->after; }

static int spr_force(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v, vlbe_real *Q)
{
    springs *s = (springs *)u;
    (void)t;
    (void)v;
    Q[0] = s->F[0] - s->k[0] * q[0] + s->k[1] * (q[1] - q[0]);
    Q[1] = s->F[1] - s->k[1] * (q[1] - q[0]) + s->k[2] * (q[2] - q[1]);
    Q[2] = -s->k[2] * (q[2] - q[1]);
    if ((s->fault == 1 || s->fault == 5 || s->fault == 6) && spr_hit(s)) {
        if (s->fault == 1) return -1;
        if (s->fault == 6) return 1;
        Q[1] = (vlbe_real)NAN;
    }
    return 0;
}
static int spr_force_jac(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v,
                         vlbe_real *K, vlbe_real *D)
{
    springs *s = (springs *)u;
    int i;
    (void)t;
    (void)q;
    (void)v;
    if (s->fault == 4 && spr_hit(s)) return -1;
    for (i = 0; i < 9; ++i) K[i] = D[i] = VLBE_R(0.0);
    K[0] = -(s->k[0] + s->k[1]);
    K[1] = K[3] = s->k[1];
    K[4] = -(s->k[1] + s->k[2]);
    K[5] = K[7] = s->k[2];
    K[8] = -s->k[2];
    return 0;
}
static int spr_constr(void *u, vlbe_real t, const vlbe_real *q, vlbe_real *C)
{
    springs *s = (springs *)u;
    (void)t;
    if (s->fault == 2 && spr_hit(s)) return -1;
    C[0] = q[2] - s->d;
    return 0;
}
static int spr_constr_jac(void *u, vlbe_real t, const vlbe_real *q, vlbe_real *Cq, vlbe_real *Ct)
{
    springs *s = (springs *)u;
    (void)t;
    (void)q;
    if (s->fault == 3 && spr_hit(s)) return -1;
    Cq[0] = Cq[1] = VLBE_R(0.0);
    Cq[2] = VLBE_R(1.0);
    if (Ct) Ct[0] = VLBE_R(0.0);
    return 0;
}

/* k = 100, 200, 300 N/m, F = 10, -20 N, d = 0.05 m.  Hand solution: with
   q3 = d the rows of q1, q2 read 300 q1 - 200 q2 = 10, 200 q1 - 500 q2 = 5,
   so q1 = 4000/110000 = 2/55, q2 = 500/110000 = 1/220 m, and lambda = Q3 =
   -k3 (d - q2) = -150/11 N (the support pulls mass 3 with -lambda = 150/11 N). */
static void spr_setup(vlbe_dae *sys, springs *s)
{
    vlbe_dae z = {0};
    memset(s, 0, sizeof *s);
    s->k[0] = VLBE_R(100.0);
    s->k[1] = VLBE_R(200.0);
    s->k[2] = VLBE_R(300.0);
    s->F[0] = VLBE_R(10.0);
    s->F[1] = VLBE_R(-20.0);
    s->d = VLBE_R(0.05);
    *sys = z;
    sys->n = 3;
    sys->m = 1;
    sys->user = s;
    sys->mass = NULL; /* the static solver never needs M */
    sys->force = spr_force;
    sys->force_jac = spr_force_jac;
    sys->constr = spr_constr;
    sys->constr_jac = spr_constr_jac;
}
static const double SPR_Q[3] = {2.0 / 55.0, 1.0 / 220.0, 0.05};
static const double SPR_LAM = -150.0 / 11.0;

/* ------------------------------------------------------------------------ */
static void test_static_params_default(void **state)
{
    vlbe_static_params p, bad;
    springs s;
    vlbe_dae sys, bsys;
    vlbe_real q[3] = {0, 0, 0}, lam[1] = {0}, q0[3], l0[1];
    (void)state;
    vlbe_static_params_default(&p);
    ASSERT_CLOSE(p.ftol, 0.0, 0.0, 0.0);
#ifdef VLBE_USE_FLOAT /* the double values are below float's resolution: 64 and 8 eps */
    ASSERT_CLOSE(p.rtol, 64.0 * (double)FLT_EPSILON, 0.0, 0.0);
    ASSERT_CLOSE(p.atol, 8.0 * (double)FLT_EPSILON, 0.0, 0.0);
#else
    ASSERT_CLOSE(p.rtol, 1e-10, 0.0, 0.0);
    ASSERT_CLOSE(p.atol, 1e-12, 0.0, 0.0);
#endif
    assert_int_equal(p.max_iter, 50);
    assert_int_equal(p.max_halvings, 5);
    assert_int_equal(p.watchdog, 4);
    vlbe_static_params_default(NULL); /* harmless */
    spr_setup(&sys, &s);
    memcpy(q0, q, sizeof q);
    memcpy(l0, lam, sizeof lam);
#define EXPECT_EARG(parp, sysp, qp, lp)                                                   \
    do {                                                                                  \
        assert_int_equal(solve(sysp, parp, qp, lp, NULL), VLBE_EARG);                     \
        assert_untouched(q, q0, 3);                                                       \
        assert_untouched(lam, l0, 1);                                                     \
    } while (0)
    bad = p, bad.rtol = VLBE_R(-1e-3);
    EXPECT_EARG(&bad, &sys, q, lam);
    bad = p, bad.atol = (vlbe_real)NAN;
    EXPECT_EARG(&bad, &sys, q, lam);
    bad = p, bad.ftol = VLBE_R(-1.0);
    EXPECT_EARG(&bad, &sys, q, lam);
    bad = p, bad.ftol = (vlbe_real)INFINITY;
    EXPECT_EARG(&bad, &sys, q, lam);
    bad = p, bad.rtol = bad.atol = bad.ftol = VLBE_R(0.0); /* no test enabled */
    EXPECT_EARG(&bad, &sys, q, lam);
    bad = p, bad.max_iter = 0;
    EXPECT_EARG(&bad, &sys, q, lam);
    bad = p, bad.max_halvings = -1;
    EXPECT_EARG(&bad, &sys, q, lam);
    bad = p, bad.max_halvings = 51;
    EXPECT_EARG(&bad, &sys, q, lam);
    bad = p, bad.watchdog = -1;
    EXPECT_EARG(&bad, &sys, q, lam);
    bad = p, bad.watchdog = VLBE_INT_MAX_ITER + 1;
    EXPECT_EARG(&bad, &sys, q, lam);
    EXPECT_EARG((const vlbe_static_params *)NULL, &sys, q, lam);
    EXPECT_EARG(&p, &sys, q, (vlbe_real *)NULL); /* m > 0 needs lambda */
    bsys = sys, bsys.n = 0;
    assert_int_equal(vlbe_dae_static(&bsys, &p, 0, q, lam, NULL, g_w, WLEN, g_iw, IWLEN), VLBE_EARG);
    bsys = sys, bsys.force = NULL;
    assert_int_equal(vlbe_dae_static(&bsys, &p, 0, q, lam, NULL, g_w, WLEN, g_iw, IWLEN), VLBE_EARG);
    bsys = sys, bsys.constr = NULL;
    assert_int_equal(vlbe_dae_static(&bsys, &p, 0, q, lam, NULL, g_w, WLEN, g_iw, IWLEN), VLBE_EARG);
    assert_int_equal(vlbe_dae_static(NULL, &p, 0, q, lam, NULL, g_w, WLEN, g_iw, IWLEN), VLBE_EARG);
    assert_int_equal(vlbe_dae_static(&sys, &p, (vlbe_real)NAN, q, lam, NULL, g_w, WLEN, g_iw, IWLEN),
                     VLBE_EARG);
    assert_int_equal(vlbe_dae_static(&sys, &p, 0, NULL, lam, NULL, g_w, WLEN, g_iw, IWLEN),
                     VLBE_EARG);
    assert_untouched(q, q0, 3);
    assert_untouched(lam, l0, 1);
    /* the integrators still insist on mass */
    assert_int_equal(vlbe_dae_check(&sys), VLBE_EARG);
    /* the workspace formula: 5N + 3n + 2mn + N^2 + the Jacobian scratch
       max(3n^2 + 8n + 2m, n^2 + mn + 8n + 5m) = 3n^2 + 8n + 2m here (K, D, T
       and the vectors of the differences) */
    assert_true(vlbe_static_work_len(3, 1) == (size_t)(20 + 9 + 6 + 16 + 27 + 24 + 2));
    assert_true(vlbe_static_iwork_len(3, 1) == 4);
#undef EXPECT_EARG
}

/* ------------------------------------------------------------------------ */
/* A linear problem: Newton's first step solves it up to rounding, the second
   step is at the rounding floor (8 eps |q|) or below rtol |q|: 2 iterations.
   Error: the 4 x 4 solve is backward stable; the reduced stiffness
   [[300, -200], [-200, 500]] has condition 3.5, so the forward error is a
   few eps |q|max; the second Newton step corrects it to the rounding of Psi
   divided by the stiffness, again a few eps: 16 eps |q|max (absolute) for q,
   16 eps |lambda| for lambda.  Measured: 0.2 (m:sp_eps) eps in double,
   0.4 (m@flt:sp_eps) eps in float (q in eps |q|max, lambda in eps
   |lambda|, the worse of the two). */
static void test_static_linear_springs(void **state)
{
    double wsp = 0.0;
    int fd;
    (void)state;
    for (fd = 0; fd < 2; ++fd) {
        springs s;
        vlbe_dae sys;
        vlbe_static_params par;
        vlbe_dae_stats st;
        vlbe_real q[3] = {0, 0, 0}, lam[1] = {0};
        long it;
        spr_setup(&sys, &s);
        if (fd) sys.force_jac = NULL;
        vlbe_static_params_default(&par);
        assert_int_equal(solve(&sys, &par, q, lam, &st), VLBE_OK);
        ASSERT_VEC_CLOSE(q, SPR_Q, 3, 0.0, 16 * EPS * 0.05);
        ASSERT_CLOSE(lam[0], SPR_LAM, 16 * EPS, 0.0);
        tu_report(fd ? "linear springs q (FD K)" : "linear springs q",
                  fmax(fabs((double)q[0] - SPR_Q[0]),
                       fmax(fabs((double)q[1] - SPR_Q[1]), fabs((double)q[2] - SPR_Q[2]))),
                  16 * EPS * 0.05);
        tu_report(fd ? "linear springs lambda (FD K)" : "linear springs lambda",
                  fabs((double)lam[0] - SPR_LAM) / fabs(SPR_LAM), 16 * EPS);
        wsp = fmax(wsp, fmax(fmax(fabs((double)q[0] - SPR_Q[0]),
                                  fmax(fabs((double)q[1] - SPR_Q[1]),
                                       fabs((double)q[2] - SPR_Q[2]))) /
                                 (EPS * 0.05),
                             fabs((double)lam[0] - SPR_LAM) / (EPS * fabs(SPR_LAM))));
        /* with analytic K the first step is exact up to rounding; with
           forward differences of a linear Q the columns carry rounding of
           eps |Q| / (sqrt(eps) |q|) ~ sqrt(eps) relative error, so the
           iteration contracts by ~sqrt(eps) per step: at most 3 */
        it = st.newton_iters;
        if (fd == 0) assert_true(it == 2);
        else assert_true(it >= 2 && it <= 3);
        /* counters: one Jacobian, LU and solve per iteration; no backtracking */
        assert_true(st.jac_evals == it && st.lu_factors == it && st.lu_solves == it);
        assert_true(st.rejected == 0 && st.newton_fails == 0 && st.steps == 1);
        assert_true(st.mass_calls == 0);
        /* force: one at the start, one per trial point, and per Jacobian one
           force_jac call (analytic) or n = 3 forward differences (the
           integrators' helper) */
        assert_true(st.force_calls == 1 + it + it * (fd ? 3 : 1));
        /* constraints: C and C_q at the start and per trial point; per
           Jacobian the FD of d(C_q^T lambda)/dq: n + 1 = 4 constr_jac calls */
        assert_true(st.constr_calls == 2 + 2 * it + 4 * it);
        /* VLBE_DAE_NO_CHESS drops those: 4 fewer per Jacobian, same answer
           (C is linear: the term is zero) */
        {
            vlbe_real q2[3] = {0, 0, 0}, l2[1] = {0};
            vlbe_dae_stats st2;
            sys.flags |= VLBE_DAE_NO_CHESS;
            assert_int_equal(solve(&sys, &par, q2, l2, &st2), VLBE_OK);
            assert_true(st2.constr_calls == 2 + 2 * st2.newton_iters);
            ASSERT_VEC_CLOSE(q2, q, 3, 0.0, 16 * EPS * 0.05);
        }
    }
    /* a start at the solution: ftol alone needs no iteration at all */
    {
        springs s;
        vlbe_dae sys;
        vlbe_static_params par;
        vlbe_dae_stats st;
        vlbe_real q[3], lam[1] = {(vlbe_real)SPR_LAM};
        int i;
        for (i = 0; i < 3; ++i) q[i] = (vlbe_real)SPR_Q[i];
        spr_setup(&sys, &s);
        vlbe_static_params_default(&par);
        par.rtol = par.atol = VLBE_R(0.0);
        /* |Psi| at the rounded solution: k |q| eps ~ 300 * 0.05 * eps per
           row; 1e3 eps bounds it */
        par.ftol = (vlbe_real)(1e3 * EPS);
        assert_int_equal(solve(&sys, &par, q, lam, &st), VLBE_OK);
        assert_true(st.newton_iters == 0 && st.force_calls == 1);
    }
    tu_measured("sp_eps", wsp);
}

/* ------------------------------------------------------------------------ */
/* bead on a circle: C = (x^2 + y^2 - R^2)/2, C_q = (x, y),
   H = d(C_q^T lambda)/dq = lambda I; Q = -k (p - A) + (0, -W). */
typedef struct bead {
    vlbe_real R, k, a, W;
} bead;

static int bead_force(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v, vlbe_real *Q)
{
    const bead *b = (const bead *)u;
    (void)t;
    (void)v;
    Q[0] = -b->k * (q[0] - b->a);
    Q[1] = -b->k * q[1] - b->W;
    return 0;
}
static int bead_force_jac(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v,
                          vlbe_real *K, vlbe_real *D)
{
    const bead *b = (const bead *)u;
    (void)t;
    (void)q;
    (void)v;
    K[0] = K[3] = -b->k;
    K[1] = K[2] = VLBE_R(0.0);
    D[0] = D[1] = D[2] = D[3] = VLBE_R(0.0);
    return 0;
}
static int bead_constr(void *u, vlbe_real t, const vlbe_real *q, vlbe_real *C)
{
    const bead *b = (const bead *)u;
    (void)t;
    C[0] = VLBE_R(0.5) * (q[0] * q[0] + q[1] * q[1] - b->R * b->R);
    return 0;
}
static int bead_constr_jac(void *u, vlbe_real t, const vlbe_real *q, vlbe_real *Cq, vlbe_real *Ct)
{
    (void)u;
    (void)t;
    Cq[0] = q[0];
    Cq[1] = q[1];
    if (Ct) Ct[0] = VLBE_R(0.0);
    return 0;
}
static int bead_constr_hess(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *lam,
                            vlbe_real *H)
{
    (void)u;
    (void)t;
    (void)q;
    H[0] = H[3] = lam[0];
    H[1] = H[2] = VLBE_R(0.0);
    return 0;
}
/* R = 1 m, k = 100 N/m, anchor (1.3, 0) m, weight 30 N: b = (130, -30) N,
   p = R b/|b|, lambda = |b|/R - k = 33.4166 N/m (the rod pulls the bead
   inwards with lambda R = 33.4 N).  Without the Hessian term the iteration
   matrix misses lambda I: the tangential error is multiplied by -lambda/k
   = -0.33 per iteration (linear convergence). */
static void bead_setup(vlbe_dae *sys, bead *b)
{
    vlbe_dae z = {0};
    b->R = VLBE_R(1.0);
    b->k = VLBE_R(100.0);
    b->a = VLBE_R(1.3);
    b->W = VLBE_R(30.0);
    *sys = z;
    sys->n = 2;
    sys->m = 1;
    sys->user = b;
    sys->force = bead_force;
    sys->force_jac = bead_force_jac;
    sys->constr = bead_constr;
    sys->constr_jac = bead_constr_jac;
    sys->constr_hess = bead_constr_hess;
}
static void bead_exact(const bead *b, double p[2], double *lam)
{
    double bx = (double)b->k * (double)b->a, by = -(double)b->W, nb = sqrt(bx * bx + by * by);
    p[0] = (double)b->R * bx / nb;
    p[1] = (double)b->R * by / nb;
    *lam = nb / (double)b->R - (double)b->k;
}

/* Error bound: the last full step passed |dq_i| <= atol + rtol |q_i| (or the
   floor 8 eps |q|max); with a contraction factor theta <= 1/2 (Newton: far
   less; NO_CHESS: 0.33) the remaining error is at most that step.  lambda =
   (Q . p)/R^2 moves by |b| / R^2 per unit of p, |b| = 133 N vs lambda = 33 N/m:
   a relative factor 4.  So q to (atol + (rtol + 8 eps) |q|) plus 16 eps
   rounding, lambda to 4 (rtol + 8 eps) + 16 eps relative. */
static void test_static_bead_on_circle(void **state)
{
    int variant;
    long it_hess = 0;
    (void)state;
    for (variant = 0; variant < 3; ++variant) {
        bead b;
        vlbe_dae sys;
        vlbe_static_params par;
        vlbe_dae_stats st;
        vlbe_real q[2] = {VLBE_R(0.0), VLBE_R(-1.0)}, lam[1] = {VLBE_R(0.0)};
        double pe[2], le, tq, tl;
        static const char *names[3] = {"bead p (constr_hess)", "bead p (FD Hessian)",
                                       "bead p (NO_CHESS)"};
        bead_setup(&sys, &b);
        if (variant == 1) sys.constr_hess = NULL;
        if (variant == 2) sys.flags |= VLBE_DAE_NO_CHESS;
        vlbe_static_params_default(&par);
        bead_exact(&b, pe, &le);
        assert_int_equal(solve(&sys, &par, q, lam, &st), VLBE_OK);
        tq = (double)par.atol + ((double)par.rtol + 8 * EPS) * 1.0 + 16 * EPS;
        tl = 4.0 * ((double)par.rtol + 8 * EPS) + 16 * EPS;
        ASSERT_VEC_CLOSE(q, pe, 2, 0.0, tq);
        ASSERT_CLOSE(lam[0], le, tl, 0.0);
        tu_report(names[variant], fmax(fabs((double)q[0] - pe[0]), fabs((double)q[1] - pe[1])), tq);
        tu_report("  and lambda (relative)", fabs((double)lam[0] - le) / le, tl);
        /* the reaction on the bead, -C_q^T lambda = -lambda p, balances the
           applied force Q at the solution */
        {
            vlbe_real Q[2], z[2] = {0, 0};
            bead_force(&b, 0, q, z, Q);
            ASSERT_CLOSE((double)Q[0] - (double)lam[0] * (double)q[0], 0.0, 0.0,
                         le * tq + 130.0 * tl);
            ASSERT_CLOSE((double)Q[1] - (double)lam[0] * (double)q[1], 0.0, 0.0,
                         le * tq + 130.0 * tl);
        }
        if (variant == 0) it_hess = st.newton_iters;
        /* Newton with the exact Hessian from the bottom of the circle, 77
           degrees away, lambda = 0: measured 9 (m:bead_it) iterations
           (8 (m@flt:bead_it) in float; 0 (m:bead_rej) backtracks: the
           watchdog takes the full steps), bounded by 12; FD Hessian (error
           sqrt(eps) relative): within one of it */
        if (variant == 0) tu_measured("bead_it", (double)st.newton_iters);
        if (variant == 0) tu_measured("bead_rej", (double)st.rejected);
        if (variant == 0) assert_true(st.newton_iters <= 12);
        if (variant == 1) assert_true(st.newton_iters <= it_hess + 1);
        /* without it: linear, factor 0.33 per iteration, so more
           iterations than with it: measured 23 (m:bead_it_nc) vs 9 in
           double (to the 1e-10 increment test), 12 (m@flt:bead_it_nc) vs 8
           in float (to its 7.6e-6 increment test, reached sooner) */
        if (variant == 2) tu_measured("bead_it_nc", (double)st.newton_iters);
        if (variant == 2) assert_true(st.newton_iters > it_hess + 3);
        /* the FD Hessian costs n + 1 = 3 constr_jac calls per Jacobian,
           the analytic one 1 constr_hess call */
        if (variant == 0) assert_true(st.constr_calls == 2 + 2 * st.newton_iters + st.newton_iters + st.rejected * 2);
        if (variant == 1) assert_true(st.constr_calls == 2 + 2 * st.newton_iters + 3 * st.newton_iters + st.rejected * 2);
        if (variant == 2) assert_true(st.constr_calls == 2 + 2 * st.newton_iters + st.rejected * 2);
    }
}

/* ------------------------------------------------------------------------ */
/* The von Mises truss: scenes/vonmises_truss.h. */
/* Rounding of lambda(w): N = EA (l - L0)/L0 carries an absolute error of a
   few eps EA (l and L0 are each rounded to eps relative, ~1 m), times
   2 w/l <= 2 h0/b: 8 eps EA h0/b; 64 eps EA h0/b gives a factor 8.  x stays
   at 0 to the increment tolerance; lambda depends on x only at second order. */
static double truss_lam_tol(const vm_truss *tr) { return 64.0 * EPS * tr->EA * tr->h0 / tr->b; }

/* Trace w = h0 .. -h0 in 40 steps (the caller's stepping: move w, call again
   from the last solution).  The load P(w) = lambda rises to the upper limit
   point, falls through 0 at w = 0 and reaches the lower limit point: a path
   that load control cannot follow. */
static void test_static_truss_snapthrough(void **state)
{
    vm_truss tr;
    vlbe_dae sys;
    vlbe_static_params par;
    vlbe_dae_stats st;
    vlbe_real q[2], lam[1] = {VLBE_R(0.0)};
    double worst = 0.0, lmax = -1.0, lmin = 1.0, tol;
    int k, kmax = -1, kmin = -1;
    long iters = 0, it_min = 1000, it_max = 0;
    (void)state;
    vm_setup(&sys, &tr, 1);
    vlbe_static_params_default(&par);
    tol = truss_lam_tol(&tr);
    q[0] = VLBE_R(0.01); /* off the symmetric solution */
    q[1] = (vlbe_real)tr.h0;
    for (k = 0; k <= 40; ++k) {
        double w = tr.h0 * (1.0 - k / 20.0), le;
        tr.w = (vlbe_real)w;
        assert_int_equal(solve(&sys, &par, q, lam, &st), VLBE_OK);
        iters += st.newton_iters;
        if (st.newton_iters < it_min) it_min = st.newton_iters;
        if (st.newton_iters > it_max) it_max = st.newton_iters;
        le = vm_lambda(&tr, (double)tr.w);
        ASSERT_CLOSE_CTX(lam[0], le, 0.0, tol, "k = %d, w = %g", k, w);
        worst = fmax(worst, fabs((double)lam[0] - le));
        /* x = 0 to the increment test (atol + rtol |x|, or the floor
           8 eps |q|max), y = w to rounding (linear constraint) */
        assert_true(fabs((double)q[0]) <= (double)par.atol + 8 * EPS * tr.h0 + 16 * EPS);
        ASSERT_CLOSE(q[1], tr.w, 0.0, 4 * EPS * tr.h0);
        if ((double)lam[0] > lmax) lmax = (double)lam[0], kmax = k;
        if ((double)lam[0] < lmin) lmin = (double)lam[0], kmin = k;
    }
    tu_report("truss snap-through lambda(w), 41 heights [N]", worst, tol);
    /* the limit points: dP/dw = 0 at w^2 = ... interior of each half; the
       upper one (P > 0) for w in (0, h0), the lower one (P < 0) for w < 0 */
    assert_true(kmax > 0 && kmax < 20 && lmax > 0.0);
    assert_true(kmin > 20 && kmin < 40 && lmin < 0.0);
    ASSERT_CLOSE(lmin, -lmax, 0.0, 2 * tol); /* P(-w) = -P(w) */
    /* Newton from the last solution: a few iterations per height (measured
       2 (m:tr_it_min) to 3 (m:tr_it_max)); 6 bounds them */
    tu_measured("tr_it_min", (double)it_min);
    tu_measured("tr_it_max", (double)it_max);
    assert_true(iters <= 6 * 41);
}

/* ------------------------------------------------------------------------ */
typedef struct truss_fd_ctx {
    vm_truss *tr;
    const vlbe_real *q;
    int j;
} truss_fd_ctx;

static double truss_fd_fn(void *ctx, double x, double *out)
{
    truss_fd_ctx *c = (truss_fd_ctx *)ctx;
    vlbe_real q[2], Q[2], z[2] = {0, 0};
    q[0] = c->q[0];
    q[1] = c->q[1];
    q[c->j] = (vlbe_real)x;
    vm_force(c->tr, 0, q, z, Q);
    out[0] = (double)Q[0];
    out[1] = (double)Q[1];
    return (double)q[c->j];
}

/* The analytic K of the truss against central differences (error
   ~eps^(2/3) relative to the column scale EA/L0: 100 eps^(2/3)), then the
   solve with forward-difference K (the integrators' helper) against the one
   with analytic K at five heights.  Both results lie within the increment
   bound of the exact solution (see the bead test), so they agree to twice
   that; lambda, from the same solve, to the rounding bound of the truss. */
static void test_static_fd_jacobian(void **state)
{
    vm_truss tr;
    vlbe_dae sys, sfd;
    vlbe_static_params par;
    static const double ws[5] = {0.19, 0.1155, 0.0, -0.05, -0.15};
    double worst_q = 0.0, worst_l = 0.0, tq, tl, extra = -1e9;
    int k, i, j;
    (void)state;
    vm_setup(&sys, &tr, 1);
    sfd = sys;
    sfd.force_jac = NULL;
    vlbe_static_params_default(&par);
    /* analytic K vs central differences at a generic point */
    {
        vlbe_real q[2] = {VLBE_R(0.03), VLBE_R(0.07)}, K[4], D[4];
        double d[2], work[2], tol = 100.0 * pow(EPS, 2.0 / 3.0);
        truss_fd_ctx c;
        c.tr = &tr;
        c.q = q;
        vm_force_jac(&tr, 0, q, q, K, D);
        for (j = 0; j < 2; ++j) {
            c.j = j;
            tu_central_diff(truss_fd_fn, &c, (double)q[j], tu_fd_step(EPS, 1.0), 2, work, d);
            for (i = 0; i < 2; ++i) ASSERT_CLOSE(K[i * 2 + j], d[i], tol, tol * tr.EA);
        }
    }
    tq = 2.0 * ((double)par.atol + ((double)par.rtol + 8 * EPS) * tr.h0) + 16 * EPS;
    tl = truss_lam_tol(&tr);
    for (k = 0; k < 5; ++k) {
        vlbe_real qa[2] = {VLBE_R(0.01), (vlbe_real)tr.h0}, qf[2], la[1] = {0}, lf[1] = {0};
        vlbe_dae_stats sa, sf;
        memcpy(qf, qa, sizeof qa);
        tr.w = (vlbe_real)ws[k];
        assert_int_equal(solve(&sys, &par, qa, la, &sa), VLBE_OK);
        assert_int_equal(solve(&sfd, &par, qf, lf, &sf), VLBE_OK);
        ASSERT_VEC_CLOSE(qf, qa, 2, 0.0, tq);
        ASSERT_CLOSE(lf[0], la[0], 0.0, tl);
        ASSERT_CLOSE(la[0], vm_lambda(&tr, (double)tr.w), 0.0, tl);
        worst_q = fmax(worst_q, fmax(fabs((double)qf[0] - (double)qa[0]),
                                     fabs((double)qf[1] - (double)qa[1])));
        worst_l = fmax(worst_l, fabs((double)lf[0] - (double)la[0]));
        /* FD: n = 2 extra force calls per Jacobian instead of one force_jac
           call; K's sqrt(eps) error costs at most one more iteration
           (measured: 0 (m:tr_fd_extra) more in double, 0 (m@flt:tr_fd_extra)
           in float), and the line search is never
           needed (a path start 0.01 m off the symmetric line) */
        extra = fmax(extra, (double)(sf.newton_iters - sa.newton_iters));
        assert_true(sf.newton_iters <= sa.newton_iters + 1);
        assert_true(sf.force_calls == 1 + sf.newton_iters * 3 + sf.rejected);
        assert_true(sa.force_calls == 1 + sa.newton_iters * 2 + sa.rejected);
    }
    tu_report("truss FD-K vs analytic-K q [m]", worst_q, tq);
    tu_report("truss FD-K vs analytic-K lambda [N]", worst_l, tl);
    tu_measured("tr_fd_extra", extra);
}

/* ------------------------------------------------------------------------ */
/* n = 1 scalar problems for the line search. */
typedef struct scal {
    int kind;          /* 0: Q = F - k log(1 + q) (q > -1), 1: Q = c - atan(q),
                          2: Q = -q - 1/2 (q >= 0), -q + 1/2 (q < 0): no root,
                          3: Q = c - atan(q) on |q| < 100 (callback 1 outside) */
    vlbe_real F, k, c;
} scal;

static int scal_force(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v, vlbe_real *Q)
{
    const scal *s = (const scal *)u;
    (void)t;
    (void)v;
    if (s->kind == 0) {
        if (!(q[0] > VLBE_R(-1.0))) return 1; /* outside the domain */
        Q[0] = s->F - s->k * vlbe_log(VLBE_R(1.0) + q[0]);
    } else if (s->kind == 1 || s->kind == 3) {
        if (s->kind == 3 && !(vlbe_fabs(q[0]) < VLBE_R(100.0))) return 1;
        Q[0] = s->c - vlbe_atan2(q[0], VLBE_R(1.0));
    } else {
        Q[0] = -q[0] + (q[0] >= VLBE_R(0.0) ? -VLBE_R(0.5) : VLBE_R(0.5));
    }
    return 0;
}
static int scal_force_jac(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v,
                          vlbe_real *K, vlbe_real *D)
{
    const scal *s = (const scal *)u;
    (void)t;
    (void)v;
    if (s->kind == 0) {
        if (!(q[0] > VLBE_R(-1.0))) return 1;
        K[0] = -s->k / (VLBE_R(1.0) + q[0]);
    } else if (s->kind == 1 || s->kind == 3) {
        if (s->kind == 3 && !(vlbe_fabs(q[0]) < VLBE_R(100.0))) return 1;
        K[0] = -VLBE_R(1.0) / (VLBE_R(1.0) + q[0] * q[0]);
    } else {
        K[0] = -VLBE_R(1.0);
    }
    D[0] = VLBE_R(0.0);
    return 0;
}
static void scal_setup(vlbe_dae *sys, scal *s, int kind)
{
    vlbe_dae z = {0};
    s->kind = kind;
    s->F = VLBE_R(50.0);
    s->k = VLBE_R(100.0); /* q* = exp(1/2) - 1 */
    s->c = VLBE_R(0.5);   /* q* = tan(1/2) */
    *sys = z;
    sys->n = 1;
    sys->m = 0;
    sys->user = s;
    sys->force = scal_force;
    sys->force_jac = scal_force_jac;
}

/* logspr from q = 10: the full step lands at q = 10 - 11 (log 11 - 1/2) =
   -10.9, outside the domain (callback 1), the half step at -0.44 lowers
   |Psi|: accepted.  atan from q = 10: the full step goes to -88 and |Psi|
   grows, as at the halves -39, -14.5, -2.3; the 1/16 step to 3.9 lowers it.
   Both converge quadratically afterwards: q* to atol + (rtol + 8 eps) |q*|
   (bound of the bead test) plus 4 eps for the rounding of exp and tan.
   The defaults against the backtracking alone (watchdog = 0): logspr's
   first full step leaves the domain, which ends the watchdog phase at
   once: the same run, every counter equal.  atan's full steps diverge (q
   = -88, 1.6e4, -2.7e8, ...): neither merit nor step falls below the
   first for 4 iterations, the iteration returns to q = 10 and backtracks
   from there as with watchdog = 0: the same q bit for bit, the 5 watched
   Jacobians and the return (one rejected) on top. */
static void test_static_line_search(void **state)
{
    int kind;
    (void)state;
    for (kind = 0; kind < 2; ++kind) {
        scal s;
        vlbe_dae sys;
        vlbe_static_params par;
        vlbe_dae_stats st;
        vlbe_real q[1] = {VLBE_R(10.0)}, q0[1], *nol = NULL;
        double qe = kind == 0 ? exp(0.5) - 1.0 : tan(0.5), tq;
        vlbe_status rc;
        scal_setup(&sys, &s, kind);
        vlbe_static_params_default(&par);
        q0[0] = q[0];
        assert_int_equal(solve(&sys, &par, q, nol, &st), VLBE_OK);
        {
            vlbe_static_params pb = par;
            vlbe_dae_stats sb;
            vlbe_real qb[1];
            qb[0] = q0[0];
            pb.watchdog = 0;
            assert_int_equal(solve(&sys, &pb, qb, nol, &sb), VLBE_OK);
            assert_untouched(q, qb, 1);
            if (kind == 0) {
                assert_true(memcmp(&st, &sb, sizeof st) == 0);
            } else {
                assert_true(st.newton_iters == sb.newton_iters + 5);
                assert_true(st.jac_evals == sb.jac_evals + 5);
                assert_true(st.rejected == sb.rejected + 1);
            }
        }
        tq = (double)par.atol + ((double)par.rtol + 8 * EPS) * qe + 4 * EPS * qe;
        ASSERT_CLOSE(q[0], qe, 0.0, tq);
        tu_report(kind == 0 ? "log spring (domain backtracking) q" : "atan (backtracking) q",
                  fabs((double)q[0] - qe), tq);
        if (kind == 0) {
            /* the first trial was outside the domain: one rejection, the
               callback's value remembered */
            assert_true(st.rejected >= 1);
            assert_int_equal(st.callback_rc, 1);
        } else {
            assert_true(st.rejected >= 4); /* four halvings in the first iteration */
            assert_int_equal(st.callback_rc, 0);
        }
        assert_true(st.newton_iters <= 12);
        /* plain Newton (no line search) from the same start fails and
           leaves q as it was: logspr's full step is outside the domain
           (ECALLBACK, callback_rc 1); atan's iterates grow like q^2 until
           1 + q^2 overflows and K = -1/(1 + q^2) underflows to 0: a singular
           iteration matrix */
        q[0] = q0[0];
        par.max_halvings = 0;
        rc = solve(&sys, &par, q, nol, &st);
        assert_untouched(q, q0, 1);
        if (kind == 0) {
            assert_int_equal(rc, VLBE_ECALLBACK);
            assert_int_equal(st.callback_rc, 1);
        } else {
            assert_true(rc == VLBE_ESINGULAR || rc == VLBE_ENONFINITE);
        }
        /* too few halvings for atan (3: the 1/16 step is out of reach): no
           trial lowers the merit, all lie inside the domain, so the full
           step is taken (the fallback of vlbe_dae_static) and the iteration
           then diverges as plain Newton does: a failure status, q as it
           was, the four rejected trials of the first iteration counted */
        if (kind == 1) {
            par.max_halvings = 3;
            rc = solve(&sys, &par, q, nol, &st);
            assert_true(rc == VLBE_ENOCONV || rc == VLBE_ESINGULAR || rc == VLBE_ENONFINITE);
            assert_untouched(q, q0, 1);
            assert_true(st.rejected >= 4);
        }
    }
}

/* A full step out of the domain at a watched iterate: atan restricted to
   |q| < 100 (kind 3), from q = 10.  The first full step lands at -88,
   inside; the second would go to 1.6e4, outside (callback 1): the
   iteration returns to q = 10 and backtracks from there, the steps of
   watchdog = 0 (the same q bit for bit; the 2 watched Jacobians and the
   return, one rejected, on top; callback_rc the domain's 1).  q* = tan
   1/2 to the bound of test_static_line_search. */
static void test_static_watchdog_return(void **state)
{
    scal s;
    vlbe_dae sys;
    vlbe_static_params par, pb;
    vlbe_dae_stats st, sb;
    vlbe_real q[1] = {VLBE_R(10.0)}, qb[1] = {VLBE_R(10.0)};
    (void)state;
    scal_setup(&sys, &s, 3);
    vlbe_static_params_default(&par);
    pb = par;
    pb.watchdog = 0;
    assert_int_equal(solve(&sys, &par, q, NULL, &st), VLBE_OK);
    assert_int_equal(solve(&sys, &pb, qb, NULL, &sb), VLBE_OK);
    assert_untouched(q, qb, 1);
    ASSERT_CLOSE(q[0], tan(0.5), 0.0,
                 (double)par.atol + ((double)par.rtol + 12 * EPS) * tan(0.5));
    assert_true(st.newton_iters == sb.newton_iters + 2);
    assert_true(st.rejected == sb.rejected + 1);
    assert_int_equal(st.callback_rc, 1);
    assert_int_equal(sb.callback_rc, 0);
}

/* ------------------------------------------------------------------------ */
/* rosen: Q = -(x - 1, 10 (y - x^2)) (Rosenbrock's residual), root (1, 1).
   From (-1.2, 1) Newton lands on x = 1 in one step with y = -3.84, where
   |Psi| = 48.4 against 4.92 at the start, and on (1, 1) exactly in the
   second; with max_halvings = 3 no trial (1, 1/2, 1/4, 1/8 of the step)
   lowers the merit (1/16 would: 4.78), so the full step is taken. */
static int rosen_force(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v, vlbe_real *Q)
{
    (void)u;
    (void)t;
    (void)v;
    Q[0] = -(q[0] - VLBE_R(1.0));
    Q[1] = -VLBE_R(10.0) * (q[1] - q[0] * q[0]);
    return 0;
}

static int rosen_force_jac(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v,
                           vlbe_real *K, vlbe_real *D)
{
    (void)u;
    (void)t;
    (void)v;
    K[0] = -VLBE_R(1.0);
    K[1] = VLBE_R(0.0);
    K[2] = VLBE_R(20.0) * q[0];
    K[3] = -VLBE_R(10.0);
    if (D) D[0] = D[1] = D[2] = D[3] = VLBE_R(0.0);
    return 0;
}

/* The full-step fallback: no halving lowers the merit, every trial lies in
   the domain -> the full Newton step; two steps land on the root (x = 1
   after the first is exact in floating point, then y solves a linear
   equation).  Tolerance: 4 EPS on q (one rounding of y).  The fallback
   belongs to the backtracking (watchdog = 0); the defaults' watchdog
   takes the same two full steps without a trial: the same root, no
   rejection (the second step's |d_q| = 4.84 is below the first's 5.32:
   progress). */
static void test_static_full_step_fallback(void **state)
{
    vlbe_dae sys;
    vlbe_static_params par;
    vlbe_dae_stats st;
    vlbe_real q[2] = {-VLBE_R(1.2), VLBE_R(1.0)};
    (void)state;
    memset(&sys, 0, sizeof sys);
    sys.n = 2;
    sys.force = rosen_force;
    sys.force_jac = rosen_force_jac;
    vlbe_static_params_default(&par);
    par.max_halvings = 3;
    par.watchdog = 0;
    memset(&st, 0, sizeof st);
    assert_int_equal(solve(&sys, &par, q, NULL, &st), VLBE_OK);
    ASSERT_CLOSE(q[0], 1.0, 0, 4.0 * EPS);
    ASSERT_CLOSE(q[1], 1.0, 0, 4.0 * EPS);
    assert_true(st.rejected >= 4);     /* the four trials of the first step */
    assert_true(st.newton_iters <= 4); /* two steps and the confirming one(s) */
    /* the defaults */
    q[0] = -VLBE_R(1.2);
    q[1] = VLBE_R(1.0);
    vlbe_static_params_default(&par);
    assert_int_equal(solve(&sys, &par, q, NULL, &st), VLBE_OK);
    ASSERT_CLOSE(q[0], 1.0, 0, 4.0 * EPS);
    ASSERT_CLOSE(q[1], 1.0, 0, 4.0 * EPS);
    assert_true(st.rejected == 0);
    assert_true(st.newton_iters <= 4);
}

/* ------------------------------------------------------------------------ */
/* Load control past the limit point: the truss without the height
   constraint, its apex under a dead load P = 2 P_lim (P_lim = max over
   w in [0, h0] of lambda(w), the upper limit point of
   test_static_truss_snapthrough, by a scan of 20001 heights: the factor 2
   needs no more).  No equilibrium lies near the unloaded shape: the apex
   snaps through to the inverted branch, y* < -h0 with x = 0, where
   lambda(y*) = P (a bisection on [-1, -h0] m, where lambda - P goes from
   5.4e5 N - P to -P).  From the unloaded shape pushed 0.1 m sideways, plain Newton
   cycles between the two branches for 50 iterations (VLBE_ENOCONV, q as
   it was); under the defaults the watched full steps cease to make
   progress, the iteration returns to the start and the backtracking
   search finds y* (measured: 27 (m:snap_it) iterations with the watched
   ones, 17 (m:snap_it_bt) for the backtracking alone, whose q the
   defaults return bit for bit).  Tolerance: the increment test's bound
   (bead test) and 64 eps h0 for the rounding of the force balance (bar
   forces 1.2e4 N against a stiffness of 6e4 N/m). */
static void test_static_snapthrough_load(void **state)
{
    vm_truss tr;
    vlbe_dae sys;
    vlbe_static_params par, plain, bt;
    vlbe_dae_stats st, sb;
    vlbe_real q[2], q0[2], qb[2];
    double plim = 0.0, lo = -1.0, hi, ye, tol;
    int k;
    (void)state;
    vm_setup(&sys, &tr, 0);
    plim = vm_limit_load(&tr);
    tr.P = 2.0 * plim;
    hi = -tr.h0;
    for (k = 0; k < 200; ++k) { /* lambda(y) - P: 5.4e5 N - P > 0 at y = -1, -P at y = -h0 */
        const double mid = 0.5 * (lo + hi);
        if (vm_lambda(&tr, mid) - tr.P > 0.0) lo = mid;
        else hi = mid;
    }
    ye = 0.5 * (lo + hi);
    q0[0] = VLBE_R(0.1);
    q0[1] = (vlbe_real)tr.h0;
    vlbe_static_params_default(&par);
    plain = par;
    plain.max_halvings = 0;
    bt = par;
    bt.watchdog = 0;
    memcpy(q, q0, sizeof q);
    assert_int_equal(solve(&sys, &plain, q, NULL, &st), VLBE_ENOCONV);
    assert_untouched(q, q0, 2);
    assert_int_equal(solve(&sys, &par, q, NULL, &st), VLBE_OK);
    tol = (double)par.atol + ((double)par.rtol + 8 * EPS) * fabs(ye) + 64 * EPS * tr.h0;
    ASSERT_CLOSE(q[1], ye, 0.0, tol);
    ASSERT_CLOSE(q[0], 0.0, 0.0, tol);
    tu_report("truss past the limit load: apex y vs bisection [m]", fabs((double)q[1] - ye), tol);
    assert_true(st.rejected >= 1); /* the return to the start */
    memcpy(qb, q0, sizeof qb);
    assert_int_equal(solve(&sys, &bt, qb, NULL, &sb), VLBE_OK);
    assert_untouched(q, qb, 2);
    assert_true(st.newton_iters > sb.newton_iters);
    tu_measured("snap_it", (double)st.newton_iters);
    tu_measured("snap_it_bt", (double)sb.newton_iters);
}

/* ------------------------------------------------------------------------ */
/* The residual test (eq. 53) on the truss at w = 0.1 m. */
static void test_static_residual_test(void **state)
{
    vm_truss tr;
    vlbe_dae sys;
    vlbe_static_params pinc, pres, pboth;
    vlbe_dae_stats si, sr, sb;
    vlbe_real q0[2] = {VLBE_R(0.01), VLBE_R(0.2)}, l0[1] = {0};
    vlbe_real qi[2], li[1], qr[2], lr[1], qb[2], lb[1];
    double ftol, p;
    (void)state;
    vm_setup(&sys, &tr, 1);
    tr.w = VLBE_R(0.1);
    vlbe_static_params_default(&pinc);
    /* ftol: the rounding of Psi is eps times the bar forces (EA (l - L0)/L0
       ~ 1e4 N here) times a few: 1e-8 N in double is 1e4 times that; in
       float 2e-3 N x 1e2 */
#ifndef VLBE_USE_FLOAT
    ftol = 1e-8;
#else
    ftol = 0.2;
#endif
    pres = pinc;
    pres.rtol = pres.atol = VLBE_R(0.0); /* residual test only */
    pres.ftol = (vlbe_real)ftol;
    pboth = pinc;
    pboth.ftol = (vlbe_real)ftol;
    memcpy(qi, q0, sizeof q0), memcpy(li, l0, sizeof l0);
    memcpy(qr, q0, sizeof q0), memcpy(lr, l0, sizeof l0);
    memcpy(qb, q0, sizeof q0), memcpy(lb, l0, sizeof l0);
    assert_int_equal(solve(&sys, &pinc, qi, li, &si), VLBE_OK);
    assert_int_equal(solve(&sys, &pres, qr, lr, &sr), VLBE_OK);
    assert_int_equal(solve(&sys, &pboth, qb, lb, &sb), VLBE_OK);
    /* the residual at the returned point, evaluated here */
    p = psi_norm(&sys, qr, lr);
    assert_true(p <= ftol);
    tu_report("residual test alone: ||Psi||/sqrt(N) [N]", p, ftol);
    p = psi_norm(&sys, qb, lb);
    assert_true(p <= ftol);
    tu_report("residual + increment test: ||Psi||/sqrt(N) [N]", p, ftol);
    /* both tests: at least as many iterations as either alone */
    assert_true(sb.newton_iters >= si.newton_iters);
    assert_true(sb.newton_iters >= sr.newton_iters);
    /* all three reach the same lambda to the truss bound */
    ASSERT_CLOSE(lr[0], vm_lambda(&tr, 0.1), 0.0, truss_lam_tol(&tr) + 2.0 * ftol);
    ASSERT_CLOSE(lb[0], vm_lambda(&tr, 0.1), 0.0, truss_lam_tol(&tr));
    ASSERT_CLOSE(li[0], vm_lambda(&tr, 0.1), 0.0, truss_lam_tol(&tr));
    /* an ftol that cannot be met: the force with a jump (kind 2 of the
       scalar problems) has |Psi| >= 1/2 everywhere; the iterates close in
       on the jump until no halving lowers |Psi|: ENOCONV, q untouched */
    {
        scal s;
        vlbe_dae ssys;
        vlbe_static_params ps;
        vlbe_real q[1] = {VLBE_R(1.0)}, qs0[1] = {VLBE_R(1.0)};
        scal_setup(&ssys, &s, 2);
        vlbe_static_params_default(&ps);
        ps.ftol = VLBE_R(0.1);
        assert_int_equal(solve(&ssys, &ps, q, NULL, &sb), VLBE_ENOCONV);
        assert_untouched(q, qs0, 1);
        assert_true(sb.newton_fails == 1 && sb.steps == 0);
        /* and the increment test alone does not help either */
        ps.ftol = VLBE_R(0.0);
        assert_int_equal(solve(&ssys, &ps, q, NULL, &sb), VLBE_ENOCONV);
        assert_untouched(q, qs0, 1);
    }
}

/* ------------------------------------------------------------------------ */
/* Two masses joined by a spring, no support, and a constraint on their
   distance: the rigid translation is free, K (and the whole iteration
   matrix) singular. */
static int flo_force(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v, vlbe_real *Q)
{
    (void)u;
    (void)t;
    (void)v;
    Q[0] = VLBE_R(100.0) * (q[1] - q[0]) + VLBE_R(1.0);
    Q[1] = -VLBE_R(100.0) * (q[1] - q[0]) - VLBE_R(1.0);
    return 0;
}
static int flo_force_jac(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v,
                         vlbe_real *K, vlbe_real *D)
{
    (void)u;
    (void)t;
    (void)q;
    (void)v;
    K[0] = K[3] = -VLBE_R(100.0);
    K[1] = K[2] = VLBE_R(100.0);
    D[0] = D[1] = D[2] = D[3] = VLBE_R(0.0);
    return 0;
}
static int flo_constr(void *u, vlbe_real t, const vlbe_real *q, vlbe_real *C)
{
    (void)u;
    (void)t;
    C[0] = q[1] - q[0] - VLBE_R(0.5);
    return 0;
}
static int flo_constr_jac(void *u, vlbe_real t, const vlbe_real *q, vlbe_real *Cq, vlbe_real *Ct)
{
    (void)u;
    (void)t;
    (void)q;
    Cq[0] = -VLBE_R(1.0);
    Cq[1] = VLBE_R(1.0);
    if (Ct) Ct[0] = VLBE_R(0.0);
    return 0;
}

static void test_static_fail_singular(void **state)
{
    vlbe_dae sys = {0};
    vlbe_static_params par;
    vlbe_dae_stats st;
    vlbe_real q[2] = {VLBE_R(0.1), VLBE_R(0.3)}, lam[1] = {VLBE_R(2.0)}, q0[2], l0[1];
    int m;
    (void)state;
    vlbe_static_params_default(&par);
    memcpy(q0, q, sizeof q);
    memcpy(l0, lam, sizeof lam);
    for (m = 0; m < 2; ++m) {
        sys.n = 2;
        sys.m = m;
        sys.force = flo_force;
        /* analytic K: the rows cancel exactly (forward differences would
           leave a rounding-size pivot, ~sqrt(eps) |K| in float, that is
           not a structural zero) */
        sys.force_jac = flo_force_jac;
        sys.constr = flo_constr;
        sys.constr_jac = flo_constr_jac;
        assert_int_equal(solve(&sys, &par, q, m ? lam : NULL, &st), VLBE_ESINGULAR);
        assert_untouched(q, q0, 2);
        assert_untouched(lam, l0, 1);
        assert_true(st.lu_factors == 1 && st.newton_iters == 0 && st.steps == 0);
    }
}

static void test_static_fail_noconv(void **state)
{
    bead b;
    vlbe_dae sys;
    vlbe_static_params par;
    vlbe_dae_stats st;
    vlbe_real q[2] = {VLBE_R(0.0), VLBE_R(-1.0)}, lam[1] = {VLBE_R(0.0)}, q0[2], l0[1];
    (void)state;
    bead_setup(&sys, &b);
    vlbe_static_params_default(&par);
    par.max_iter = 2; /* needs 6 */
    memcpy(q0, q, sizeof q);
    memcpy(l0, lam, sizeof lam);
    assert_int_equal(solve(&sys, &par, q, lam, &st), VLBE_ENOCONV);
    assert_untouched(q, q0, 2);
    assert_untouched(lam, l0, 1);
    assert_true(st.newton_iters == 2 && st.newton_fails == 1 && st.steps == 0);
    /* the same with the residual test alone */
    par.rtol = par.atol = VLBE_R(0.0);
    par.ftol = VLBE_R(1e-3);
    assert_int_equal(solve(&sys, &par, q, lam, &st), VLBE_ENOCONV);
    assert_untouched(q, q0, 2);
    assert_untouched(lam, l0, 1);
}

static void test_static_fail_callback(void **state)
{
    int fault;
    long after;
    (void)state;
    /* faults: 1 force, 2 constr, 3 constr_jac, 4 force_jac, each returning
       -1 from its first call (at the start; force_jac: in the first
       iteration) and from its second (first trial point; constr_jac: the
       FD Hessian; force_jac: the second iteration) */
    for (fault = 1; fault <= 4; ++fault)
        for (after = 0; after <= 1; ++after) {
            springs s;
            vlbe_dae sys;
            vlbe_static_params par;
            vlbe_dae_stats st;
            vlbe_real q[3] = {0, 0, 0}, lam[1] = {VLBE_R(1.0)}, q0[3], l0[1];
            spr_setup(&sys, &s);
            s.fault = fault;
            s.after = after;
            vlbe_static_params_default(&par);
            memcpy(q0, q, sizeof q);
            memcpy(l0, lam, sizeof lam);
            assert_int_equal(solve(&sys, &par, q, lam, &st), VLBE_ECALLBACK);
            assert_int_equal(st.callback_rc, -1);
            assert_untouched(q, q0, 3);
            assert_untouched(lam, l0, 1);
            assert_true(st.steps == 0);
        }
    /* +1 (outside the domain) at the start: nothing to backtrack to */
    {
        springs s;
        vlbe_dae sys;
        vlbe_static_params par;
        vlbe_dae_stats st;
        vlbe_real q[3] = {0, 0, 0}, lam[1] = {0}, q0[3], l0[1];
        spr_setup(&sys, &s);
        s.fault = 6;
        vlbe_static_params_default(&par);
        memcpy(q0, q, sizeof q);
        memcpy(l0, lam, sizeof lam);
        assert_int_equal(solve(&sys, &par, q, lam, &st), VLBE_ECALLBACK);
        assert_int_equal(st.callback_rc, 1);
        assert_untouched(q, q0, 3);
        assert_untouched(lam, l0, 1);
    }
}

static void test_static_fail_work(void **state)
{
    springs s;
    vlbe_dae sys;
    vlbe_static_params par;
    vlbe_real q[3] = {0, 0, 0}, lam[1] = {0}, q0[3], l0[1];
    size_t lw = vlbe_static_work_len(3, 1), liw = vlbe_static_iwork_len(3, 1);
    (void)state;
    spr_setup(&sys, &s);
    vlbe_static_params_default(&par);
    memcpy(q0, q, sizeof q);
    memcpy(l0, lam, sizeof lam);
    assert_int_equal(vlbe_dae_static(&sys, &par, 0, q, lam, NULL, g_w, lw - 1, g_iw, liw), VLBE_EWORK);
    assert_int_equal(vlbe_dae_static(&sys, &par, 0, q, lam, NULL, g_w, lw, g_iw, liw - 1), VLBE_EWORK);
    assert_int_equal(vlbe_dae_static(&sys, &par, 0, q, lam, NULL, NULL, lw, g_iw, liw), VLBE_EWORK);
    assert_int_equal(vlbe_dae_static(&sys, &par, 0, q, lam, NULL, g_w, lw, NULL, liw), VLBE_EWORK);
    assert_untouched(q, q0, 3);
    assert_untouched(lam, l0, 1);
    assert_true(s.calls == 0);
    /* exactly the queried sizes suffice (stats NULL is allowed) */
    assert_int_equal(vlbe_dae_static(&sys, &par, 0, q, lam, NULL, g_w, lw, g_iw, liw), VLBE_OK);
}

static void test_static_fail_nonfinite(void **state)
{
    int k;
    (void)state;
    for (k = 0; k < 4; ++k) {
        springs s;
        vlbe_dae sys;
        vlbe_static_params par;
        vlbe_dae_stats st;
        vlbe_real q[3] = {0, 0, 0}, lam[1] = {0}, q0[3], l0[1];
        spr_setup(&sys, &s);
        vlbe_static_params_default(&par);
        if (k == 0) q[1] = (vlbe_real)NAN;
        if (k == 1) lam[0] = (vlbe_real)INFINITY;
        if (k == 2) s.fault = 5; /* NaN in Q at the start */
        if (k == 3) s.fault = 5, s.after = 1; /* NaN in Q at the first trial point */
        memcpy(q0, q, sizeof q);
        memcpy(l0, lam, sizeof lam);
        /* k = 3: a NaN residual at a trial counts as no decrease and is
           backtracked; with the fault lasting, every halving fails the
           same way and the last status is ENONFINITE */
        assert_int_equal(solve(&sys, &par, q, lam, &st), VLBE_ENONFINITE);
        assert_untouched(q, q0, 3);
        assert_untouched(lam, l0, 1);
        if (k < 2) assert_true(st.force_calls == 0);
        if (k == 3) assert_true(st.rejected == par.max_halvings + 1);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_static_params_default),
        cmocka_unit_test(test_static_linear_springs),
        cmocka_unit_test(test_static_bead_on_circle),
        cmocka_unit_test(test_static_truss_snapthrough),
        cmocka_unit_test(test_static_fd_jacobian),
        cmocka_unit_test(test_static_line_search),
        cmocka_unit_test(test_static_watchdog_return),
        cmocka_unit_test(test_static_full_step_fallback),
        cmocka_unit_test(test_static_snapthrough_load),
        cmocka_unit_test(test_static_residual_test),
        cmocka_unit_test(test_static_fail_singular),
        cmocka_unit_test(test_static_fail_noconv),
        cmocka_unit_test(test_static_fail_callback),
        cmocka_unit_test(test_static_fail_work),
        cmocka_unit_test(test_static_fail_nonfinite),
    };
    return cmocka_run_group_tests_name("static", tests, NULL, NULL);
}
