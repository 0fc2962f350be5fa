/* ex_run.h -- the run loop the examples share: one integrator of
   integrators.h from a start state to t_end, an observer called at the start
   and after every accepted step, counters, CPU time and the end state.
   -- part of vlbe                                  SPDX-License-Identifier: MIT

   Examples include it with #include "ex_run.h" (it sits beside them), so
   `cc -O2 examples/x.c -lm` still works from anywhere.  The workspace is
   malloc'ed here: examples may allocate, the headers never do. */
#ifndef VLBE_EX_RUN_H
#define VLBE_EX_RUN_H

#include "../integrators.h"

#include <stdlib.h>
#include <time.h>

/* Called at t = t0 and after every accepted step with the state then. */
typedef void (*ex_observer)(void *ctx, double t, const vlbe_real *q, const vlbe_real *v,
                            const vlbe_real *lambda);

/* The integrator: hht != NULL: that generalized-alpha scheme with the fixed
   step h (t_end - t0 rounded to a whole number of steps); else BDF with bdf. */
typedef struct ex_method {
    const vlbe_hht_params *hht;
    double h;
    const vlbe_bdf_params *bdf;
} ex_method;

/* What a run gives besides the observations. */
typedef struct ex_run_out {
    vlbe_status status;   /* of init or of the first failing step         */
    vlbe_dae_stats stats; /* counters (zero if init failed early)        */
    double cpu;           /* seconds                                      */
} ex_run_out;

/* Integrates sys from (0, q0, v0) to t_end.  q_end, v_end (n) and lam_end
   (m) receive the last accepted state when non-NULL. */
static inline vlbe_status ex_run(const vlbe_dae *sys, const ex_method *m, const vlbe_real *q0,
                                 const vlbe_real *v0, double t_end, ex_observer obs, void *ctx,
                                 vlbe_real *q_end, vlbe_real *v_end, vlbe_real *lam_end,
                                 ex_run_out *out)
{
    int n = sys->n, nm = sys->m;
    size_t lw = m->hht ? vlbe_hht_work_len(n, nm) : vlbe_bdf_work_len(n, nm);
    size_t liw = m->hht ? vlbe_hht_iwork_len(n, nm) : vlbe_bdf_iwork_len(n, nm);
    vlbe_real *w = (vlbe_real *)malloc(lw * sizeof *w);
    int *iw = (int *)malloc(liw * sizeof *iw);
    vlbe_dae_stats zero_stats = {0};
    clock_t c0 = clock();
    vlbe_hht hs;
    vlbe_bdf bs;
    const vlbe_real *q = NULL, *v = NULL, *lam = NULL;
    vlbe_status rc;

    out->stats = zero_stats;
    out->cpu = 0.0;
    if (!w || !iw) {
        free(w);
        free(iw);
        return out->status = VLBE_EWORK;
    }
    if (m->hht) {
        long k, nsteps = (long)floor(t_end / m->h + 0.5);
        rc = vlbe_hht_init(&hs, sys, m->hht, VLBE_R(0.0), q0, v0, w, lw, iw, liw);
        if (rc == VLBE_OK) {
            q = hs.q, v = hs.v, lam = hs.lambda;
            obs(ctx, 0.0, q, v, lam);
            for (k = 1; k <= nsteps; ++k) {
                if ((rc = vlbe_hht_step(&hs, (vlbe_real)m->h)) != VLBE_OK) break;
                obs(ctx, (double)k * m->h, q, v, lam);
            }
            out->stats = hs.stats;
        }
    } else {
        rc = vlbe_bdf_init(&bs, sys, m->bdf, VLBE_R(0.0), q0, v0, w, lw, iw, liw);
        if (rc == VLBE_OK) {
            q = bs.q, v = bs.v, lam = bs.lambda;
            obs(ctx, 0.0, q, v, lam);
            while ((double)bs.t < t_end) {
                if ((rc = vlbe_bdf_step(&bs, (vlbe_real)t_end)) != VLBE_OK) break;
                obs(ctx, (double)bs.t, q, v, lam);
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
    free(w);
    free(iw);
    return rc;
}

#endif /* VLBE_EX_RUN_H */
