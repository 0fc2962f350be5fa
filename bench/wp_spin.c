/* wp_spin.c -- work-precision of the rotating-beam scene 1, the spin-up of a
   cantilever on a hub at W = 6 rad/s (scenes/ex_spin.h,
   examples/spin_up.c): error of the tip deflection in the hub frame
   against CPU time (log-log) over model x mesh x step x integrator.

   build (from the repository root; `make demo` builds it with -O2, `make
   bench` with -O3 -march=native):
       cc -std=c99 -O2 bench/wp_spin.c -o build/demo/wp_spin -lm
   run:  build/demo/wp_spin [outdir [full]]           (default outdir: out)
   writes <outdir>/wp_spin.csv and <outdir>/wp_spin.svg; prints every run
   (errors, CPU, counters), the reference and its checks, and the cheapest
   run per model and integrator that reaches 1e-2, 1e-3, 1e-4.  "full"
   adds the 32- and 64-element checks of the reference at h = 6.25e-4
   (about 35 s more).

   The scene is the example's: sp_cfg_default(&c, 6, model), L = 10 m,
   spin-up to W = 6 rad/s in Ts = 15 s, run to 20 s, no damping; every run
   is one sp_run() from rest.  Models: SP_CR (co-rotational, corot2d.h) and
   SP_ANCF with Gauss points (cfg.inv = SP_GAUSS).  The linear model
   (SP_LINEAR) has no stiffening and diverges once theta' passes omega_1 =
   3.80 rad/s: it is run once (8 elements, h = 5 ms), listed as a failed run
   (VLBE_EBOUND) and charted as an empty legend entry.
   Meshes 4, 8, 16, 32 elements; steps h = 1e-2, 5e-3, 2.5e-3, 1.25e-3 s
   (each divides the 0.5 s sampling interval and Ts); integrators HHT-alpha
   -0.05 (the scene's) and generalized-alpha rho_inf = 0.8 at every mesh and
   step, BDF (variable step and order, rtol = atol, sp_run's setting) with
   max_order 2 at 4, 8, 16 elements, rtol = 1e-2 .. 1e-5, and max_order 5
   (the default) only where a run stays under ~2 s (table g_bdf_last).

   Error of a run: max over the 40 samples t_k = 0.5 k s (k = 1..40; the
   HHT steps land on them, BDF steps are made to) of |transverse tip -
   reference| / max_k |reference transverse tip| (0.571 m); the same for
   the axial tip (scale max |axial| = 0.0186 m: the foreshortening during
   the spin-up) in the table and CSV.  A failed run has no error.

   Reference: SP_ANCF (Gauss), 32 elements, HHT-alpha -0.05, h = 3.125e-4
   s.  Chosen over the co-rotational model because the ANCF beam is
   converged in the mesh at this size and the CR beam is not (measured with
   "full", h = 6.25e-4: ANCF 32 vs 64 elements 1e-7, CR 32 vs 64 2.4e-5);
   its step error, from the grid run at h = 1.25e-3 (second order: diff /
   15), is 1.7e-6.  The co-rotational beam at the same resolution differs
   from it by 8.1e-5 (largest at t = 10 s, in the spin-up), and still by
   5.8e-5 at 64 elements while CR moves by only 2.4e-5 from 32 to 64: the
   two models seem to converge to limits some 5e-5 apart, the order of the
   axial strain (rhoA W^2 L^2 / 2EA = 7.7e-5 at the root), where their
   strain measures differ (Green vs engineering strain, curvature per
   deformed vs reference length); not resolved further here.  That
   difference, 8.1e-5, is the reference's uncertainty as a solution of the
   physical problem; below it, errors are distances to the ANCF model's
   solution, and the CR runs level off there.

   What the runs show (-O2, gcc 12.2.0, AMD EPYC Zen 4 2.6 GHz, 2 cores,
   one used; errors are deterministic, CPU times vary by ~20 % with the
   load of the other core; the whole benchmark took 71 s CPU on a quiet
   machine):
   - HHT-alpha is second order in h: at 32 elements (ANCF) the errors at
     h = 1e-2 .. 1.25e-3 are 1.79e-3, 4.42e-4, 1.09e-4, 2.58e-5 (ratios
     4.05, 4.06, 4.2).  Generalized-alpha 0.8 gives the same error to
     within 10 % (mostly slightly smaller) at the same cost.
   - Mesh error (h = 1.25e-3): ANCF 1.76e-3 at 4 elements, then 2.8e-5,
     2.4e-5, 2.6e-5 at 8, 16, 32: from 8 elements on only the step error is
     left (the cubic ANCF beam with exact curvature converges fast in the
     mesh).  CR 2.16e-3, 5.31e-4, 1.49e-4, 5.52e-5 at 4..32 elements (against
     the CR 32 run instead: 2.08e-3, 4.5e-4, 7.3e-5: second order, plus the
     model difference above).  On the coarse CR meshes mesh and step errors
     have opposite signs: the error grows as h falls (4 el.: 6.6e-4 at h =
     1e-2, 2.2e-3 at 1.25e-3), so a coarse step can look accurate by luck;
     the summary below only counts a run whose finer steps stay below the
     level too.
   - Cheapest run to a transverse tip error of 1e-3: CR 8 el., h = 5e-3,
     0.11 s; ANCF 8 el., h = 5e-3, 0.15 s.  To 1e-4: ANCF 8 el., h =
     2.5e-3, 0.30 s; CR needs 32 el. (h = 2.5e-3, 1.6 s): the ANCF beam is
     the cheaper model below 1e-3.
   - BDF with max_order 2 (with the filtered error estimate of
     integrators.h): few rejected steps (at most 156 of 924, at rtol 1e-2),
     error falling with rtol to 2.2e-3 (4 el.), 6.2e-4 / 1.8e-3 (CR / ANCF
     8 el.), 2.4e-4 / 8.1e-4 (16 el.) at rtol 1e-5 -- no better than the
     mesh error there, and at 5-15 times the CPU of an HHT run of the same
     error: 1e-3 costs 0.8 s (CR 8 el., 20037 steps) and 2.3 s (ANCF 16
     el.) against 0.11-0.15 s with HHT.  With the default max_order 5 the
     undamped stiff axial modes pin the step (CR 4 el.: 35750 steps at rtol
     1e-2, 113935 at 1e-3, errors 1.3e-1, 2.4e-2); the ANCF runs at rtol
     1e-2 leave the bound (VLBE_EBOUND at 9.6 / 8.8 s, 4 / 8 el.), and
     tighter or finer runs take more than 8 s each, so they are not run.

   CPU time: CLOCK_PROCESS_CPUTIME_ID around sp_run() (model setup,
   allocation, integration, the sampling observer); median of 5 runs when
   the first takes under 0.05 s, of 3 under 0.2 s, else the single run
   (the runs are deterministic: only the time varies). */
#define _POSIX_C_SOURCE 199309L
#include "../scenes/ex_spin.h"
#include "../scenes/svgplot.h"
#include "bench_util.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define DNAN ((double)NAN)
#define W_SCENE 6.0
#define NMESH 4
#define NSTEP 4
#define NRTOL 4
#define NBMESH 3
#define REF_NE 32
#define REF_H 3.125e-4
#define CHK_H 6.25e-4 /* `full`: the 32-, 64-element checks */
#define NLVL 3

static const int g_ne[NMESH] = {4, 8, 16, 32};
static const double g_h[NSTEP] = {1e-2, 5e-3, 2.5e-3, 1.25e-3};
static const double g_rtol[NRTOL] = {1e-2, 1e-3, 1e-4, 1e-5};
static const int g_bne[NBMESH] = {4, 8, 16};
static const double g_lvl[NLVL] = {1e-2, 1e-3, 1e-4};

enum { M_CR = 0, M_ANCF, NMODEL };
static const int g_sp_model[NMODEL] = {SP_CR, SP_ANCF};
static const char *const g_model_name[NMODEL] = {"CR", "ANCF"};

enum { I_HHT = 0, I_GA, I_BDF2, I_BDF5, NINT };
static const char *const g_int_name[NINT] = {"HHT-alpha -0.05", "gen-alpha rho_inf 0.8",
                                              "BDF max order 2", "BDF max order 5"};

/* BDF: index in g_rtol of the tightest rtol run, per model, mesh and order
   (2, 5); -1: none.  Order 2 runs everywhere (at most 2.5 s, CR and ANCF
   16 el. at 1e-5).  Order 5 only where a run stays under ~2 s (measured,
   -O2): CR 4 el. at 1e-4, 1e-5 takes 1.9, 2.3 s; CR 8 and 16 el. take more
   than 8 s already at 1e-2; the ANCF runs at 1e-2 leave the bound (0.2,
   0.6 s at 4, 8 el.) and take more than 8 s at 1e-3. */
static const int g_bdf_last[NMODEL][NBMESH][2] = {{{3, 1}, {3, -1}, {3, -1}},
                                                  {{3, 0}, {3, 0}, {3, -1}}};

/* one run of the sweep */
typedef struct run {
    int model, integ, ne; /* model: M_*, or -1 for the linear model   */
    double x;             /* h [s] (HHT family) or rtol (BDF)         */
    int done;             /* 0: not run (cost, see g_bdf_last)        */
    vlbe_status status;
    double t_stop;        /* last accepted time [s]                   */
    double err_tr, err_ax; /* NaN if failed                           */
    double cpu;           /* median CPU seconds per run               */
    int reps;
    vlbe_dae_stats st;
    double tip[SP_NS][2];
} run;

#define NRUN_MAX (NMODEL * 2 * NMESH * NSTEP + NMODEL * 2 * NBMESH * NRTOL + 1)

typedef struct sweep {
    run r[NRUN_MAX];
    int n;
    run ref, ref_cr;          /* ANCF and CR at REF_NE, REF_H            */
    run chk[4];               /* `full`: ANCF 32, 64, CR 32, 64 at CHK_H */
    int nchk;
    double s_tr, s_ax;        /* max |reference| transverse, axial        */
} sweep;

static sp_model g_m; /* one model for every run (large: static) */

static void cfg_for(const run *r, sp_cfg *c)
{
    sp_cfg_default(c, W_SCENE, r->model < 0 ? SP_LINEAR : g_sp_model[r->model]);
    c->ne = r->ne;
    if (r->integ >= I_BDF2) {
        c->bdf_rtol = r->x;
        c->bdf_max_order = r->integ == I_BDF2 ? 2 : 0;
    } else {
        c->h = r->x;
        c->rho_inf = r->integ == I_GA ? 0.8 : 0.0;
    }
}

static double run_once(const sp_cfg *c, sp_out *o)
{
    double c0 = benchu_cpu_now();
    sp_run(&g_m, c, NULL, NULL, o);
    return benchu_cpu_now() - c0;
}

/* max_k |a_k - b_k| of component j over the samples, divided by scale;
   NaN if a sample is missing in either */
static double rec_err(const run *a, const run *b, int j, double scale)
{
    double e = 0.0;
    int k;
    for (k = 0; k < SP_NS; ++k) {
        const double d = fabs(a->tip[k][j] - b->tip[k][j]);
        if (!(d == d)) return DNAN;
        if (d > e) e = d;
    }
    return e / scale;
}

/* sample time [s] of the largest transverse difference of a and b */
static double rec_err_at(const run *a, const run *b)
{
    double e = -1.0, t = DNAN;
    int k;
    for (k = 0; k < SP_NS; ++k) {
        const double d = fabs(a->tip[k][1] - b->tip[k][1]);
        if (d > e) e = d, t = SP_DTS * (k + 1);
    }
    return t;
}

/* The run r describes; repeats while cheap.  Errors against sw->ref when
   it is set (sw->s_tr > 0). */
static void measure(const sweep *sw, run *r)
{
    sp_cfg c;
    sp_out o;
    double t[5];
    int k, reps;
    cfg_for(r, &c);
    t[0] = run_once(&c, &o);
    r->done = 1;
    r->status = o.status;
    r->t_stop = o.t_stop;
    r->st = o.stats;
    memcpy(r->tip, o.tip_s, sizeof r->tip);
    r->err_tr = r->err_ax = DNAN;
    if (o.status == VLBE_OK && sw->s_tr > 0.0) {
        r->err_tr = rec_err(r, &sw->ref, 1, sw->s_tr);
        r->err_ax = rec_err(r, &sw->ref, 0, sw->s_ax);
    }
    reps = t[0] < 0.05 ? 5 : t[0] < 0.2 ? 3 : 1;
    for (k = 1; k < reps; ++k) t[k] = run_once(&c, &o);
    qsort(t, (size_t)reps, sizeof t[0], benchu_cmp_double);
    r->cpu = t[reps / 2];
    r->reps = reps;
}

static run *add(sweep *sw, int model, int integ, int ne, double x)
{
    run *r = &sw->r[sw->n++];
    memset(r, 0, sizeof *r);
    r->model = model;
    r->integ = integ;
    r->ne = ne;
    r->x = x;
    r->err_tr = r->err_ax = r->cpu = DNAN;
    return r;
}

static int reference(sweep *sw, int full)
{
    int k;
    memset(&sw->ref, 0, sizeof sw->ref);
    sw->ref.model = M_ANCF;
    sw->ref.integ = I_HHT;
    sw->ref.ne = REF_NE;
    sw->ref.x = REF_H;
    sw->ref_cr = sw->ref;
    sw->ref_cr.model = M_CR;
    sw->s_tr = sw->s_ax = 0.0;
    measure(sw, &sw->ref);
    if (sw->ref.status != VLBE_OK) {
        fprintf(stderr, "wp_spin: reference run failed: %s at t = %g\n",
                vlbe_status_str(sw->ref.status), sw->ref.t_stop);
        return -1;
    }
    for (k = 0; k < SP_NS; ++k) {
        sw->s_tr = fmax(sw->s_tr, fabs(sw->ref.tip[k][1]));
        sw->s_ax = fmax(sw->s_ax, fabs(sw->ref.tip[k][0]));
    }
    sw->ref.err_tr = sw->ref.err_ax = 0.0;
    measure(sw, &sw->ref_cr);
    sw->nchk = 0;
    if (full) {
        static const int model[4] = {M_ANCF, M_ANCF, M_CR, M_CR}, ne[4] = {32, 64, 32, 64};
        for (k = 0; k < 4; ++k) {
            run *r = &sw->chk[sw->nchk++];
            memset(r, 0, sizeof *r);
            r->model = model[k];
            r->integ = I_HHT;
            r->ne = ne[k];
            r->x = CHK_H;
            measure(sw, r);
        }
    }
    return 0;
}

static void sweep_all(sweep *sw)
{
    int md, i, e, s, o;
    run *r;
    sw->n = 0;
    r = add(sw, -1, I_HHT, 8, 5e-3); /* the linear model: diverges */
    measure(sw, r);
    for (md = 0; md < NMODEL; ++md)
        for (i = I_HHT; i <= I_GA; ++i)
            for (e = 0; e < NMESH; ++e)
                for (s = 0; s < NSTEP; ++s) {
                    measure(sw, add(sw, md, i, g_ne[e], g_h[s]));
                    fflush(stdout);
                }
    for (md = 0; md < NMODEL; ++md)
        for (o = 0; o < 2; ++o)
            for (e = 0; e < NBMESH; ++e)
                for (s = 0; s < NRTOL; ++s) {
                    r = add(sw, md, o ? I_BDF5 : I_BDF2, g_bne[e], g_rtol[s]);
                    if (s <= g_bdf_last[md][e][o]) measure(sw, r);
                }
}

static const run *find(const sweep *sw, int model, int integ, int ne, double x)
{
    int i;
    for (i = 0; i < sw->n; ++i) {
        const run *r = &sw->r[i];
        if (r->model == model && r->integ == integ && r->ne == ne && r->x == x) return r;
    }
    return NULL;
}

static int run_ok(const run *r) { return r->done && r->status == VLBE_OK && r->err_tr >= 0.0; }

/* -- chart --------------------------------------------------------------- */
/* Series i and i + 8 share colour and marker: CR in 0..7 (solid; BDF
   dotted), ANCF in 8..15 (dashed); per model: HHT-alpha one series per mesh
   (lines over h), gen-alpha markers only, BDF per order with the meshes as
   separate lines (NaN between them breaks the line). */
#define NSER 16
#define NPT (NMESH * (NSTEP + 1))
typedef struct chart_data {
    double x[NSER][NPT], y[NSER][NPT];
    int n[NSER];
    char name[NSER][128];
} chart_data;

static void push(chart_data *d, int s, double x, double y)
{
    if (d->n[s] < NPT) {
        d->x[s][d->n[s]] = x;
        d->y[s][d->n[s]] = y;
        ++d->n[s];
    }
}

/* BDF legend: the meshes run, and the failed rtols */
static void bdf_name(const sweep *sw, int md, int integ, char *buf, size_t len)
{
    size_t l = (size_t)snprintf(buf, len, "%s BDF%d, el.", g_model_name[md],
                                integ == I_BDF2 ? 2 : 5);
    double seen[NRTOL];
    int i, j, e, nf = 0;
    for (e = 0; e < NBMESH; ++e) {
        const run *r = find(sw, md, integ, g_bne[e], g_rtol[0]);
        if (r && r->done && l + 8 < len)
            l += (size_t)snprintf(buf + l, len - l, "%s %d", e ? "," : "", g_bne[e]);
    }
    for (i = 0; i < sw->n && l + 24 < len && nf < NRTOL; ++i) {
        const run *r = &sw->r[i];
        if (r->model != md || r->integ != integ || !r->done || r->status == VLBE_OK) continue;
        for (j = 0; j < nf && seen[j] != r->x; ++j) {
        }
        if (j < nf) continue; /* the same rtol failed on the other mesh */
        seen[nf] = r->x;
        l += (size_t)snprintf(buf + l, len - l, "%s%g", nf++ ? ", " : " (failed: rtol ", r->x);
    }
    if (nf && l + 2 < len) strcat(buf, ")");
}

static void chart(const sweep *sw, const char *dir)
{
    static chart_data d;
    static char title[200];
    char path[512];
    const run *lin = &sw->r[0];
    svgp_chart c;
    int md, e, s, i, k;
    memset(&d, 0, sizeof d);
    for (md = 0; md < NMODEL; ++md) {
        const int base = 8 * md;
        for (e = 0; e < NMESH; ++e) {
            snprintf(d.name[base + e], sizeof d.name[0], "%s HHT-alpha, %d el.", g_model_name[md],
                     g_ne[e]);
            for (s = 0; s < NSTEP; ++s) {
                const run *r = find(sw, md, I_HHT, g_ne[e], g_h[s]);
                if (r && run_ok(r)) push(&d, base + e, r->cpu, r->err_tr);
            }
        }
        snprintf(d.name[base + 4], sizeof d.name[0], "%s gen-alpha, all meshes", g_model_name[md]);
        for (e = 0; e < NMESH; ++e)
            for (s = 0; s < NSTEP; ++s) {
                const run *r = find(sw, md, I_GA, g_ne[e], g_h[s]);
                if (r && run_ok(r)) push(&d, base + 4, r->cpu, r->err_tr);
            }
        for (i = I_BDF2; i <= I_BDF5; ++i) {
            const int ser = base + 5 + (i - I_BDF2);
            bdf_name(sw, md, i, d.name[ser], sizeof d.name[0]);
            for (e = 0; e < NBMESH; ++e) {
                if (e > 0) push(&d, ser, DNAN, DNAN);
                for (k = 0; k < NRTOL; ++k) {
                    const run *r = find(sw, md, i, g_bne[e], g_rtol[k]);
                    if (r && run_ok(r)) push(&d, ser, r->cpu, r->err_tr);
                }
            }
        }
    }
    snprintf(d.name[7], sizeof d.name[0], "linear 8 el.: %s at t = %.2f s",
             vlbe_status_str(lin->status), lin->t_stop);
    snprintf(title, sizeof title,
             "Spin-up W = %g rad/s: h %g..%g s, BDF rtol %g..%g, ref. ANCF %d el.", W_SCENE,
             g_h[0], g_h[NSTEP - 1], g_rtol[0], g_rtol[NRTOL - 1], REF_NE);
    svgp_init(&c, title, "CPU time per run [s] (sp_run, 20 s simulated; " VLBE_BENCH_FLAGS ")",
              "transverse tip: max |y - y_ref| / max |y_ref| [-]", 1, 1);
    for (i = 0; i < 15; ++i) {
        int fl = SVGP_MARKERS;
        if (i % 8 == 4 || i == 7) fl = SVGP_MARKERS | SVGP_NOLINE;
        else if (i % 8 >= 5 && i < 8) fl |= SVGP_DOT;
        svgp_series(&c, d.name[i], d.n[i], d.x[i], d.y[i], fl);
    }
    svgp_fit_legend_log(&c, 8, 3);
    snprintf(path, sizeof path, "%s/wp_spin.svg", dir);
    if (svgp_write_file(&c, path) != 0) fprintf(stderr, "wp_spin: cannot write %s\n", path);
}

/* -- CSV and tables ------------------------------------------------------ */
static const char *model_name(const run *r)
{
    return r->model < 0 ? "linear" : g_model_name[r->model];
}

static void csv_row(FILE *f, const char *what, const run *r)
{
    if (!r->done) {
        fprintf(f, "%s,%s,\"%s\",%d,%s,%g,\"not run (cost)\",,,,,,,,,,,\n", what,
                model_name(r), g_int_name[r->integ], r->ne, r->integ >= I_BDF2 ? "rtol" : "h",
                r->x);
        return;
    }
    fprintf(f, "%s,%s,\"%s\",%d,%s,%g,\"%s\",%.6g,%.6e,%.6e,%.6e,%d,%ld,%ld,%ld,%ld,%ld,%ld\n",
            what, model_name(r), g_int_name[r->integ], r->ne, r->integ >= I_BDF2 ? "rtol" : "h",
            r->x, vlbe_status_str(r->status), r->t_stop, r->err_tr, r->err_ax, r->cpu, r->reps,
            r->st.steps, r->st.rejected, r->st.newton_iters, r->st.jac_evals, r->st.lu_factors,
            r->st.force_calls);
}

static void write_csv(const sweep *sw, const char *dir)
{
    char path[512];
    FILE *f;
    int i;
    snprintf(path, sizeof path, "%s/wp_spin.csv", dir);
    f = svgp_csv_open(path, "role,model,integrator,elements,x_kind,x,status,t_reached_s,"
                            "tip_tr_rel_error,tip_ax_rel_error,cpu_s,reps,steps,rejected,"
                            "newton_iters,jac_evals,lu_factors,force_calls");
    if (!f) {
        fprintf(stderr, "wp_spin: cannot write %s\n", path);
        return;
    }
    csv_row(f, "reference", &sw->ref);
    csv_row(f, "reference_check", &sw->ref_cr);
    for (i = 0; i < sw->nchk; ++i) csv_row(f, "reference_check", &sw->chk[i]);
    for (i = 0; i < sw->n; ++i) csv_row(f, "run", &sw->r[i]);
    if (fclose(f) != 0) fprintf(stderr, "wp_spin: cannot write %s\n", path);
}

static void print_head(void)
{
    printf("%-6s %-22s %3s %9s  %-14s %6s %9s %9s %8s %4s %7s %6s %7s %6s\n", "model",
           "integrator", "el.", "h / rtol", "status", "t [s]", "err tr.", "err ax.", "cpu [s]",
           "reps", "steps", "rej.", "Newton", "LU");
}

static void print_run(const run *r)
{
    if (!r->done) {
        printf("%-6s %-22s %3d %9g  not run (cost)\n", model_name(r),
               g_int_name[r->integ], r->ne, r->x);
        return;
    }
    printf("%-6s %-22s %3d %9g  %-14s %6.2f %9.2e %9.2e %8.3f %4d %7ld %6ld %7ld %6ld\n",
           model_name(r), g_int_name[r->integ], r->ne, r->x,
           r->status == VLBE_OK ? "ok" : vlbe_status_str(r->status), r->t_stop, r->err_tr,
           r->err_ax, r->cpu, r->reps, r->st.steps, r->st.rejected, r->st.newton_iters,
           r->st.lu_factors);
}

/* Does r reach lvl for good: its error and that of every finer step (or
   tighter rtol) run on its mesh at most lvl?  (Errors are not monotone in
   h on coarse meshes: step and mesh errors can cancel.) */
static int reaches(const sweep *sw, const run *r, double lvl)
{
    int i;
    if (!run_ok(r) || !(r->err_tr <= lvl)) return 0;
    for (i = 0; i < sw->n; ++i) {
        const run *o = &sw->r[i];
        if (o->model == r->model && o->integ == r->integ && o->ne == r->ne && o->x < r->x &&
            o->done && !(run_ok(o) && o->err_tr <= lvl))
            return 0;
    }
    return 1;
}

/* the cheapest run of a model and integrator that reaches lvl */
static const run *cheapest(const sweep *sw, int md, int integ, double lvl)
{
    const run *best = NULL;
    int i;
    for (i = 0; i < sw->n; ++i) {
        const run *r = &sw->r[i];
        if (r->model == md && r->integ == integ && reaches(sw, r, lvl) &&
            (!best || r->cpu < best->cpu))
            best = r;
    }
    return best;
}

static void report(const sweep *sw)
{
    const run *a16 = find(sw, M_ANCF, I_HHT, 16, g_h[NSTEP - 1]);
    const run *a32 = find(sw, M_ANCF, I_HHT, 32, g_h[NSTEP - 1]);
    int i, md, l;
    printf("reference: ANCF (Gauss), %d el., HHT-alpha -0.05, h = %g s: %.2f s CPU, %ld steps; "
           "scales max |transverse| %.4f m, max |axial| %.5f m over the %d samples\n",
           REF_NE, REF_H, sw->ref.cpu, sw->ref.st.steps, sw->s_tr, sw->s_ax, SP_NS);
    printf("  vs CR %d el. at the same h (the reference's uncertainty): %.2e transverse (at t = "
           "%.1f s), %.2e axial; %.2f s CPU\n",
           REF_NE, sw->ref_cr.err_tr, rec_err_at(&sw->ref_cr, &sw->ref), sw->ref_cr.err_ax,
           sw->ref_cr.cpu);
    if (a32 && run_ok(a32))
        printf("  step error ~ |ANCF %d el. h = %g - ref| / 15 (second order) = %.1e\n", REF_NE,
               a32->x, a32->err_tr / 15.0);
    if (a16 && a32 && run_ok(a16) && run_ok(a32))
        printf("  mesh: |ANCF 16 - 32 el.| at h = %g: %.1e\n", a32->x,
               rec_err(a16, a32, 1, sw->s_tr));
    for (md = 0; md < NMODEL; ++md) {
        printf("  %s HHT-alpha, %d el.: error at h = %g..%g:", g_model_name[md], REF_NE, g_h[0],
               g_h[NSTEP - 1]);
        for (l = 0; l < NSTEP; ++l) {
            const run *r = find(sw, md, I_HHT, REF_NE, g_h[l]);
            printf(" %.2e", r ? r->err_tr : DNAN);
        }
        printf("\n");
    }
    for (i = 0; i < sw->nchk; ++i)
        printf("  full: %s %d el. at h = %g: %.2e from the reference (%.2f s CPU)\n",
               g_model_name[sw->chk[i].model], sw->chk[i].ne, sw->chk[i].x, sw->chk[i].err_tr,
               sw->chk[i].cpu);
    if (sw->nchk == 4)
        printf("  full: ANCF 32 vs 64 el. %.1e, CR 32 vs 64 el. %.1e, CR vs ANCF at 64 el. %.1e "
               "(h = %g)\n",
               rec_err(&sw->chk[0], &sw->chk[1], 1, sw->s_tr),
               rec_err(&sw->chk[2], &sw->chk[3], 1, sw->s_tr),
               rec_err(&sw->chk[3], &sw->chk[1], 1, sw->s_tr), CHK_H);
    printf("\nruns (err: max over the samples of |tip - ref| / max |ref|; cpu: median per run)\n");
    print_head();
    for (i = 0; i < sw->n; ++i) print_run(&sw->r[i]);
    printf("\ncheapest run reaching a transverse tip error (that run and every finer step or "
           "tighter rtol on its mesh at or below the level; CPU s, elements, h or rtol)\n");
    printf("%-6s %-22s", "model", "integrator");
    for (l = 0; l < NLVL; ++l) printf("  <= %-22g", g_lvl[l]);
    printf("\n");
    for (md = 0; md < NMODEL; ++md)
        for (i = 0; i < NINT; ++i) {
            printf("%-6s %-22s", g_model_name[md], g_int_name[i]);
            for (l = 0; l < NLVL; ++l) {
                const run *r = cheapest(sw, md, i, g_lvl[l]);
                char cell[64];
                if (!r) snprintf(cell, sizeof cell, "not reached");
                else snprintf(cell, sizeof cell, "%.3f s (%d el., %g)", r->cpu, r->ne, r->x);
                printf("  %-25s", cell);
            }
            printf("\n");
        }
}

int main(int argc, char **argv)
{
    static sweep sw;
    const char *dir = argc > 1 ? argv[1] : "out";
    const int full = argc > 2 && strcmp(argv[2], "full") == 0;
    double c0 = benchu_cpu_now(), w0 = benchu_now(), mhz;
    char model[128];

    if (benchu_mkdir(dir, "wp_spin")) return 1;
    benchu_cpu_info(model, sizeof model, &mhz);
    printf("wp_spin: work-precision of the spin-up, W = %g rad/s (scenes/ex_spin.h), vlbe %s, "
           "%s, compiler %s, %s, %s, %.0f MHz%s\n",
           W_SCENE, VLBE_VERSION_STRING, sizeof(vlbe_real) == sizeof(double) ? "double" : "float",
           __VERSION__, VLBE_BENCH_FLAGS, model, mhz, full ? ", full" : "");
    if (reference(&sw, full) != 0) return 1;
    sweep_all(&sw);
    chart(&sw, dir);
    write_csv(&sw, dir);
    report(&sw);
    printf("wrote %s/wp_spin.csv, %s/wp_spin.svg (%.1f s CPU, %.1f s wall)\n", dir, dir,
           benchu_cpu_now() - c0, benchu_now() - w0);
    return 0;
}
