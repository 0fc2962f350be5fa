/* ex_run.h -- the run loop the examples share: one integrator of
   integrators.h from a start state to t_end, an observer called at the start
   and after every accepted step, counters, CPU time and the end state.
   -- part of vlbe                                  SPDX-License-Identifier: MIT

   Examples include it with #include "../scenes/ex_run.h" (relative to the
   file), so `cc -O2 examples/x.c -lm` still works from anywhere.  The
   benchmarks use the same loop with their own workspace (so nothing is
   allocated inside the timed run) and without an observer.  Otherwise the
   workspace is malloc'ed here: scenes and examples may allocate, the
   library headers never do. */
#ifndef VLBE_EX_RUN_H
#define VLBE_EX_RUN_H

#include "../integrators.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

/* Called at t = t0 and after every accepted step with the state then
   (may be NULL: no observation).  Returns VLBE_OK to go on; any other
   status ends the run with that status (e.g. VLBE_EBOUND from a bound on
   the state that the caller sets), the state of that step kept. */
typedef vlbe_status (*ex_observer)(void *ctx, double t, const vlbe_real *q, const vlbe_real *v,
                                   const vlbe_real *lambda);

/* BDF: the smallest step an example's run may average, relative to t_end,
   when bdf->h_min does not set one.  The examples' stiffest BDF run, the
   undamped ANCF beam of scenes/ex_spin.h at order 5, steps at 2e-5 s over
   20 s, 1e-6 of the run; ten times below that a run is stuck, not resolving
   anything.  ex_run stops a BDF run after t_end / h_floor accepted steps
   (plus one per mark and two) with VLBE_ESTEP and a message. */
#define EX_RUN_BDF_HREL 1e-7

/* The integrator: hht != NULL: that generalized-alpha scheme with the fixed
   step h (t_end - t0 rounded to a whole number of steps); else BDF with bdf,
   whose steps land exactly on the times marks[0 .. n_marks-1] (increasing;
   times the observer wants to see, may be NULL). */
typedef struct ex_method {
    const vlbe_hht_params *hht;
    double h;
    const vlbe_bdf_params *bdf;
    const double *marks;
    int n_marks;
    vlbe_real *work; /* optional caller workspace (NULL: malloc'ed per run) */
    size_t work_len; /* at least vlbe_hht/bdf_work_len_sys(sys)             */
    int *iwork;
    size_t iwork_len;
} ex_method;

/* What a run gives besides the observations. */
typedef struct ex_run_out {
    vlbe_status status;   /* of init or of the first failing step         */
    vlbe_dae_stats stats; /* counters (zero if init failed early)        */
    double cpu;           /* seconds                                      */
} ex_run_out;

/* g (double value, rate, acceleration) into the vlbe_real triple of a
   prescribed-coordinate function (corot2d.h vlbe_cr2d_fix.fun). */
static inline void ex_real3(const double *g, vlbe_real *g3)
{
    g3[0] = (vlbe_real)g[0];
    g3[1] = (vlbe_real)g[1];
    g3[2] = (vlbe_real)g[2];
}

/* The HHT family by the examples' settings: rho_inf > 0: generalized-alpha
   with that rho_inf; else alpha == 0: trapezoidal Newmark (beta 1/4, gamma
   1/2); else HHT-alpha.  The status of the params call. */
static inline vlbe_status ex_hht_pick(vlbe_hht_params *par, double alpha, double rho_inf)
{
    if (rho_inf > 0.0) return vlbe_hht_params_genalpha(par, (vlbe_real)rho_inf);
    if (alpha == 0.0) {
        vlbe_hht_params_newmark(par, VLBE_R(0.25), VLBE_R(0.5));
        return VLBE_OK;
    }
    return vlbe_hht_params_alpha(par, (vlbe_real)alpha);
}

/* y' = f(t, y) for ex_rk4_step: dy (n) from (t, y), ctx the caller's */
typedef void (*ex_rhs)(const void *ctx, double t, const double *y, double *dy);

#define EX_RK4_NMAX 16 /* unknowns of ex_rk4_step, at most */

/* One classical Runge-Kutta step (order 4) of length h from (t, y): y (n
   <= EX_RK4_NMAX) is overwritten with y(t + h).  The reference solutions
   of the examples (assumed modes, a shooting method) use it. */
static inline void ex_rk4_step(int n, ex_rhs f, const void *ctx, double t, double h, double *y)
{
    double k1[EX_RK4_NMAX], k2[EX_RK4_NMAX], k3[EX_RK4_NMAX], k4[EX_RK4_NMAX];
    double z[EX_RK4_NMAX] = {0};
    int i;
    f(ctx, t, y, k1);
    for (i = 0; i < n; ++i) z[i] = y[i] + 0.5 * h * k1[i];
    f(ctx, t + 0.5 * h, z, k2);
    for (i = 0; i < n; ++i) z[i] = y[i] + 0.5 * h * k2[i];
    f(ctx, t + 0.5 * h, z, k3);
    for (i = 0; i < n; ++i) z[i] = y[i] + h * k3[i];
    f(ctx, t + h, z, k4);
    for (i = 0; i < n; ++i) y[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
}

/* Makes the caller workspace of m large enough for either integrator on
   the problem sys (its storage: the _sys queries), growing the buffers m
   already has.  0 on success, -1 when out of memory (m then has none). */
static inline int ex_method_reserve_sys(ex_method *m, const vlbe_dae *sys)
{
    size_t lw = vlbe_hht_work_len_sys(sys), liw = vlbe_hht_iwork_len_sys(sys);
    if (vlbe_bdf_work_len_sys(sys) > lw) lw = vlbe_bdf_work_len_sys(sys);
    if (vlbe_bdf_iwork_len_sys(sys) > liw) liw = vlbe_bdf_iwork_len_sys(sys);
    if (m->work && lw <= m->work_len && liw <= m->iwork_len) return 0;
    free(m->work);
    free(m->iwork);
    m->work = (vlbe_real *)malloc(lw * sizeof *m->work);
    m->iwork = (int *)malloc(liw * sizeof *m->iwork);
    m->work_len = m->work ? lw : 0;
    m->iwork_len = m->iwork ? liw : 0;
    if (m->work && m->iwork) return 0;
    free(m->work);
    free(m->iwork);
    m->work = NULL;
    m->iwork = NULL;
    return -1;
}

/* The same for a dense problem of n coordinates and nm constraints. */
static inline int ex_method_reserve(ex_method *m, int n, int nm)
{
    vlbe_dae sys;
    memset(&sys, 0, sizeof sys);
    sys.n = n;
    sys.m = nm;
    return ex_method_reserve_sys(m, &sys);
}

/* Frees what ex_method_reserve gave m. */
static inline void ex_method_release(ex_method *m)
{
    free(m->work);
    free(m->iwork);
    m->work = NULL;
    m->iwork = NULL;
    m->work_len = m->iwork_len = 0;
}

/* Integrates sys from (0, q0, v0) to t_end.  q_end, v_end (n) and lam_end
   (m) receive the last accepted state when non-NULL. */
static inline vlbe_status ex_run(const vlbe_dae *sys, const ex_method *m, const vlbe_real *q0,
                                 const vlbe_real *v0, double t_end, ex_observer obs, void *ctx,
                                 vlbe_real *q_end, vlbe_real *v_end, vlbe_real *lam_end,
                                 ex_run_out *out)
{
    int n = sys->n, nm = sys->m;
    int own = m->work == NULL;
    size_t lw = own ? (m->hht ? vlbe_hht_work_len_sys(sys) : vlbe_bdf_work_len_sys(sys))
                    : m->work_len;
    size_t liw = own ? (m->hht ? vlbe_hht_iwork_len_sys(sys) : vlbe_bdf_iwork_len_sys(sys))
                     : m->iwork_len;
    vlbe_real *w = own ? (vlbe_real *)malloc(lw * sizeof *w) : m->work;
    int *iw = own ? (int *)malloc(liw * sizeof *iw) : m->iwork;
    vlbe_dae_stats zero_stats = {0};
    clock_t c0 = clock();
    vlbe_hht hs;
    vlbe_bdf bs;
    const vlbe_real *q = NULL, *v = NULL, *lam = NULL;
    vlbe_status rc;
    int mk = 0; /* next BDF mark */

    out->stats = zero_stats;
    out->cpu = 0.0;
    if (!w || !iw) {
        if (own) {
            free(w);
            free(iw);
        }
        return out->status = VLBE_EWORK;
    }
    if (m->hht) {
        long k, nsteps = (long)floor(t_end / m->h + 0.5);
        rc = vlbe_hht_init(&hs, sys, m->hht, VLBE_R(0.0), q0, v0, w, lw, iw, liw);
        if (rc == VLBE_OK) {
            q = hs.q, v = hs.v, lam = hs.lambda;
            if (obs) rc = obs(ctx, 0.0, q, v, lam);
            for (k = 1; k <= nsteps && rc == VLBE_OK; ++k) {
                if ((rc = vlbe_hht_step(&hs, (vlbe_real)m->h)) != VLBE_OK) break;
                if (obs) rc = obs(ctx, (double)k * m->h, q, v, lam);
            }
            out->stats = hs.stats;
        }
    } else {
        /* accepted steps at most: t_end / h_floor, one per mark, two more */
        const double h_floor = m->bdf->h_min > VLBE_R(0.0) ? (double)m->bdf->h_min
                                                            : EX_RUN_BDF_HREL * t_end;
        const double max_steps = ceil(t_end / h_floor) + m->n_marks + 2.0;
        long k = 0;
        rc = vlbe_bdf_init(&bs, sys, m->bdf, VLBE_R(0.0), q0, v0, w, lw, iw, liw);
        if (rc == VLBE_OK) {
            q = bs.q, v = bs.v, lam = bs.lambda;
            if (obs) rc = obs(ctx, 0.0, q, v, lam);
            while (rc == VLBE_OK && (double)bs.t < t_end) {
                double t_stop = t_end;
                if (++k > max_steps) {
                    fprintf(stderr, "ex_run: %ld BDF steps reached only t = %g s of %g s (steps "
                            "averaging below %g s); stopped\n", k - 1, (double)bs.t, t_end, h_floor);
                    rc = VLBE_ESTEP;
                    break;
                }
                while (mk < m->n_marks && m->marks[mk] <= (double)bs.t) ++mk;
                if (mk < m->n_marks && m->marks[mk] < t_end) t_stop = m->marks[mk];
                if ((rc = vlbe_bdf_step(&bs, (vlbe_real)t_stop)) != VLBE_OK) break;
                if (obs) rc = obs(ctx, (double)bs.t, q, v, lam);
            }
            out->stats = bs.stats;
        }
    }
    if (q) {
        if (q_end) vlbe_vec_copy(n, q, q_end);
        if (v_end) vlbe_vec_copy(n, v, v_end);
        if (lam_end && nm > 0) vlbe_vec_copy(nm, lam, lam_end);
    }
    out->cpu = (double)(clock() - c0) / (double)CLOCKS_PER_SEC;
    out->status = rc;
    if (own) {
        free(w);
        free(iw);
    }
    return rc;
}

#endif /* VLBE_EX_RUN_H */
