/* bench_integrators.c -- cost per step of the integrators of integrators.h on
   the index-3 pendulum and on Andrews' squeezing mechanism, with the counters
   of every run.

   build (from the repository root; `make bench` does this):
       cc -std=c99 -O3 -march=native bench/bench_integrators.c -o build/bench/bench_integrators -lm
   run from the repository root:  build/bench/bench_integrators [tag]
   writes out/bench/integrators[-tag].csv (out/bench must exist).

   The problems are the examples' (scenes/pendulum.h, scenes/andrews.h,
   shared with examples/pendulum.c and examples/andrews.c); this file adds
   only the timing.

   Pendulum: t in [0, 3] s (one full period between the first two crossings
   of x = 0), HHT-alpha (alpha = -0.05) at h = 1e-3 with the analytic
   Jacobians of pend_setup() and the library's default Newton tolerances,
   then the variants: Newton tolerance 1e-12 (the example's), finite-difference
   Jacobians (force_jac, constr_hess, constr_acc left NULL), full Newton
   (modified = 0), generalized-alpha rho_inf = 0.8, BDF orders 1..5 at rtol
   1e-6 and 1e-8 (atol = rtol / 100, as pend_run_bdf).  Performance target:
   <= 2 us per step for HHT-alpha at h = 1e-3.
   Andrews: t in [0, 0.03] s, HHT-alpha and generalized-alpha at h = 1e-5 ..
   1e-6 (Newton tolerances of andr_params_for: rtol 1e-12, atol 1e-14) and BDF
   at rtol = atol = 1e-8, 1e-10; error = largest relative error of the seven
   angles at 0.03 s against the Test Set reference.

   Method: a run is vlbe_*_init plus the whole integration (workspace
   allocated once, outside), no output inside the loop.  Warm-up runs first
   (>= 2 and >= 0.05 s), then samples of one run each, CLOCK_MONOTONIC,
   median: >= 11 samples and >= 0.3 s per pendulum configuration, >= 5 and
   >= 0.3 s per Andrews configuration.  The runs are deterministic, so the
   counters are those of any one run.  The period error of the pendulum rows
   comes from a separate run with pend_run_sys / pend_run_bdf of the example
   (crossings of x = 0), not from the timed runs. */
#define _POSIX_C_SOURCE 199309L
#include "../scenes/pendulum.h"
#include "../scenes/andrews.h"
#include "../scenes/svgplot.h"
#include "bench_util.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define TARGET_NS_PER_STEP 2000.0 /* HHT-alpha, pendulum, h = 1e-3 */
#define PEND_T_BENCH 3.0          /* s */
#define MAX_SAMPLES 401
#define NQ 8                      /* >= the largest n of the problems */
#define DNAN ((double)NAN)


/* -- one configuration: problem, integrator, step or tolerance ------------- */
typedef struct job {
    const char *scene, *name;
    const vlbe_dae *sys;
    int bdf;                  /* 0: generalized-alpha family (fixed h), 1: BDF */
    vlbe_hht_params hp;
    vlbe_bdf_params bp;
    double h;                 /* fixed step [s] (bdf = 0)                   */
    long nsteps;              /* number of fixed steps (bdf = 0)            */
    double t_end;             /* [s]                                        */
    double rtol;              /* BDF tolerance (for the table)              */
    int min_samples;
    /* results */
    vlbe_status status;
    vlbe_dae_stats stats;
    vlbe_real q[NQ];          /* state at t_end                             */
    double median_s, ns_step, us_sim_s, err;
    int samples;
} job;

/* the workspace of all runs, allocated outside the timed loop */
static ex_method ws;

static void ws_need(int n, int m)
{
    if (ex_method_reserve(&ws, n, m) != 0) {
        fprintf(stderr, "bench_integrators: out of memory\n");
        exit(1);
    }
}

/* One run: init + the whole integration (the examples' loop, ex_run, with
   the preallocated workspace and no observer), the final state into j->q. */
static void run_job(job *j, const vlbe_real *q0, const vlbe_real *v0)
{
    ex_method m = ws;
    ex_run_out out;
    if (j->bdf) m.bdf = &j->bp;
    else m.hht = &j->hp;
    m.h = j->h;
    j->status = ex_run(j->sys, &m, q0, v0, j->t_end, NULL, NULL, j->q, NULL, NULL, &out);
    j->stats = out.stats;
}

/* Warm-up, then >= min_samples runs and >= 0.3 s; median seconds per run. */
static void time_job(job *j, const vlbe_real *q0, const vlbe_real *v0)
{
    static double s[MAX_SAMPLES];
    double t0 = benchu_now(), t1;
    int k, ns;
    ws_need(j->sys->n, j->sys->m);
    for (k = 0; k < 2 || benchu_now() - t0 < 0.05; ++k) run_job(j, q0, v0);
    t1 = benchu_now();
    run_job(j, q0, v0);
    t1 = benchu_now() - t1;
    ns = (int)(0.3 / (t1 > 1e-9 ? t1 : 1e-9)) + 1;
    if (ns < j->min_samples) ns = j->min_samples;
    if (ns > MAX_SAMPLES) ns = MAX_SAMPLES;
    for (k = 0; k < ns; ++k) {
        t1 = benchu_now();
        run_job(j, q0, v0);
        s[k] = benchu_now() - t1;
    }
    qsort(s, (size_t)ns, sizeof s[0], benchu_cmp_double);
    j->samples = ns;
    j->median_s = s[ns / 2];
    j->ns_step = j->stats.steps > 0 ? 1e9 * j->median_s / (double)j->stats.steps : DNAN;
    j->us_sim_s = 1e6 * j->median_s / j->t_end;
}

/* -- output ------------------------------------------------------------------ */
static void print_head(const char *errname)
{
    printf("%-40s %7s %6s %4s %7s %7s %7s %7s %5s %5s %7s %9s %9s %9s %9s\n", "configuration",
           "h|rtol", "steps", "rej", "newton", "force", "mass", "constr", "jac", "LU", "solves",
           "run [ms]", "ns/step", "us/sim-s", errname);
}

static void print_job(const job *j)
{
    const vlbe_dae_stats *c = &j->stats;
    printf("%-40s %7.0e %6ld %4ld %7ld %7ld %7ld %7ld %5ld %5ld %7ld %9.3f %9.1f %9.4g %9.2e%s%s\n",
           j->name, j->bdf ? j->rtol : j->h, c->steps, c->rejected, c->newton_iters,
           c->force_calls, c->mass_calls, c->constr_calls, c->jac_evals, c->lu_factors,
           c->lu_solves, 1e3 * j->median_s, j->ns_step, j->us_sim_s, j->err,
           j->status == VLBE_OK ? "" : "  FAILED: ",
           j->status == VLBE_OK ? "" : vlbe_status_str(j->status));
    fflush(stdout);
}

static void csv_job(FILE *f, const job *j)
{
    const vlbe_dae_stats *c = &j->stats;
    if (!f) return;
    fprintf(f, "%s,\"%s\",%s,%.10g,%.10g,%.10g,%ld,%ld,%ld,%ld,%ld,%ld,%ld,%ld,%ld,%ld,%d,%.10g,%.10g,%.10g,%.10g\n",
            j->scene, j->name, j->bdf ? "bdf" : "genalpha", j->bdf ? DNAN : j->h,
            j->bdf ? j->rtol : DNAN, j->t_end, c->steps, c->rejected, c->newton_iters,
            c->newton_fails, c->force_calls, c->mass_calls, c->constr_calls, c->jac_evals,
            c->lu_factors, c->lu_solves, j->samples, j->median_s, j->ns_step, j->us_sim_s, j->err);
}

/* -- pendulum ------------------------------------------------------------------ */
/* Relative period error of an untimed run with the example's runner. */
static double pend_period_err(const job *j)
{
    pend_result r;
    double T = pend_period_exact(PEND_L, PEND_G);
    if (j->bdf) pend_run_bdf(j->rtol, j->t_end, &r);
    else pend_run_sys(j->sys, &j->hp, j->h, j->t_end, &r);
    return r.status == VLBE_OK ? fabs(r.period - T) / T : DNAN;
}

/* -- Andrews ------------------------------------------------------------------- */
static double andr_err(const job *j)
{
    double e = 0.0;
    int i;
    if (j->status != VLBE_OK) return NAN;
    for (i = 0; i < ANDR_N; ++i) {
        double ei = fabs((double)j->q[i] - andr_qref()[i]) / fabs(andr_qref()[i]);
        if (ei > e) e = ei;
    }
    return e;
}

int main(int argc, char **argv)
{
    enum { NPEND = 7, NANDR_H = 4, NANDR_BDF = 2 };
    static const long andr_nsteps[NANDR_H] = {3000, 6000, 15000, 30000}; /* h = 1e-5 .. 1e-6 */
    static const double andr_rtol[NANDR_BDF] = {1e-8, 1e-10};
    static char names[2 * NANDR_H + NANDR_BDF][64];
    const char *tag = argc > 1 ? argv[1] : NULL;
    char model[128], csv[256];
    double mhz;
    pend_par pp = pend_default();
    andr_par ap = andr_default();
    vlbe_dae psys, psys_fd, asys;
    vlbe_real pq0[2], pv0[2], aq0[ANDR_N], av0[ANDR_N];
    job jobs[NPEND], aj;
    FILE *f;
    int i, im, miss = 0, failed = 0;

    benchu_cpu_info(model, sizeof model, &mhz);
    printf("bench_integrators: integrators.h, vlbe %s, %s\n", VLBE_VERSION_STRING,
           sizeof(vlbe_real) == sizeof(double) ? "double" : "float");
    printf("compiler: %s, flags: %s\n", __VERSION__, VLBE_BENCH_FLAGS);
    printf("cpu: %s, %.0f MHz (/proc/cpuinfo)\n", model, mhz);
    printf("time per run: median of >= 11 (pendulum) / >= 5 (Andrews) runs after warm-up, "
           "CLOCK_MONOTONIC\n\n");

    snprintf(csv, sizeof csv, "out/bench/integrators%s%s.csv", tag ? "-" : "", tag ? tag : "");
    f = svgp_csv_open(csv, "scene,configuration,family,h_s,rtol,t_end_s,steps,rejected,"
                           "newton_iters,newton_fails,force_calls,mass_calls,constr_calls,"
                           "jac_evals,lu_factors,lu_solves,samples,run_s,ns_per_step,"
                           "us_per_sim_s,error");
    if (!f) fprintf(stderr, "bench_integrators: cannot write %s\n", csv);

    /* -- pendulum ---------------------------------------------------------- */
    pend_setup(&psys, &pp);
    psys_fd = psys;
    psys_fd.force_jac = NULL;
    psys_fd.constr_hess = NULL;
    psys_fd.constr_acc = NULL;
    pend_initial(&pp, pq0, pv0);
    memset(jobs, 0, sizeof jobs);
    for (i = 0; i < NPEND; ++i) {
        job *j = &jobs[i];
        j->scene = "pendulum";
        j->sys = &psys;
        j->t_end = PEND_T_BENCH;
        j->h = 1e-3;
        j->nsteps = (long)floor(j->t_end / j->h + 0.5);
        j->min_samples = 11;
        vlbe_hht_params_alpha(&j->hp, VLBE_R(-0.05));
    }
    jobs[0].name = "HHT-a -0.05, analytic Jacobians";
    jobs[1].name = "HHT-a, analytic, Newton tol 1e-12";
#ifndef VLBE_USE_FLOAT
    jobs[1].hp.rtol = jobs[1].hp.atol = VLBE_R(1e-12);
#endif
    jobs[2].name = "HHT-a, finite-difference Jacobians";
    jobs[2].sys = &psys_fd;
    jobs[3].name = "HHT-a, analytic, full Newton";
    jobs[3].hp.modified = 0;
    jobs[4].name = "gen-a rho_inf 0.8, analytic";
    vlbe_hht_params_genalpha(&jobs[4].hp, VLBE_R(0.8));
    for (i = 5; i < 7; ++i) {
        job *j = &jobs[i];
        j->bdf = 1;
        j->rtol = i == 5 ? 1e-6 : 1e-8;
        j->name = i == 5 ? "BDF 1..5, rtol 1e-6, atol 1e-8" : "BDF 1..5, rtol 1e-8, atol 1e-10";
        vlbe_bdf_params_default(&j->bp);
        j->bp.rtol = (vlbe_real)j->rtol;
        j->bp.atol = (vlbe_real)(j->rtol * 1e-2);
    }
    printf("Pendulum (index 3, n = 2, m = 1), t in [0, %g] s; Newton tolerances the library's "
           "defaults (rtol 1e-9, atol 1e-11) unless stated\n",
           PEND_T_BENCH);
    print_head("period err");
    for (i = 0; i < NPEND; ++i) {
        time_job(&jobs[i], pq0, pv0);
        jobs[i].err = pend_period_err(&jobs[i]);
        print_job(&jobs[i]);
        csv_job(f, &jobs[i]);
        if (jobs[i].status != VLBE_OK) failed = 1;
    }
    if (jobs[0].status != VLBE_OK || !(jobs[0].ns_step <= TARGET_NS_PER_STEP)) miss = 1;
    printf("target: HHT-alpha, h = 1e-3, analytic Jacobians: %.1f ns/step <= %.0f ns/step: %s\n\n",
           jobs[0].ns_step, TARGET_NS_PER_STEP, miss ? "MISS" : "PASS");

    /* -- Andrews ------------------------------------------------------------- */
    andr_setup(&asys, &ap);
    andr_initial(aq0, av0);
    printf("Andrews' squeezing mechanism (index 3, n = 7, m = 6), t in [0, %g] s; "
           "generalized-alpha family: Newton rtol 1e-12, atol 1e-14; BDF: atol = rtol\n",
           ANDR_T_END);
    print_head("max q err");
    for (im = 0; im < 3; ++im) {
        int nj = im < 2 ? NANDR_H : NANDR_BDF;
        for (i = 0; i < nj; ++i) {
            char *nm = names[im * NANDR_H + i];
            memset(&aj, 0, sizeof aj);
            aj.scene = "andrews";
            aj.sys = &asys;
            aj.t_end = ANDR_T_END;
            aj.min_samples = 5;
            if (im < 2) {
                andr_params_for(im, &aj.hp);
                aj.nsteps = andr_nsteps[i];
                aj.h = ANDR_T_END / (double)aj.nsteps;
                snprintf(nm, sizeof names[0], "%s, analytic",
                         im == 0 ? "HHT-a -0.05" : "gen-a rho_inf 0.8");
            } else {
                aj.bdf = 1;
                aj.rtol = andr_rtol[i];
                vlbe_bdf_params_default(&aj.bp);
                aj.bp.rtol = aj.bp.atol = (vlbe_real)aj.rtol;
                snprintf(nm, sizeof names[0], "BDF 1..5, atol = rtol, analytic");
            }
            aj.name = nm;
            time_job(&aj, aq0, av0);
            aj.err = andr_err(&aj);
            print_job(&aj);
            csv_job(f, &aj);
            if (aj.status != VLBE_OK) failed = 1;
        }
    }
    printf("\nerror: pendulum: relative error of the period (crossings of x = 0, example runner) "
           "against the AGM value;\nAndrews: largest relative error of the 7 angles at 0.03 s "
           "against the Test Set.  us/sim-s: microseconds per simulated second.\n"
           "constr counts constr, constr_jac and constr_acc calls; solves = LU solves.\n");
    if (f) {
        if (fclose(f) != 0) fprintf(stderr, "bench_integrators: cannot write %s\n", csv);
        else printf("\nwrote %s\n", csv);
    }
    ex_method_release(&ws);
    if (failed) fprintf(stderr, "bench_integrators: a run failed (see the table)\n");
    return failed;
}
