/* wp_moving.c -- work-precision of scene 1 of the planar ALE-ANCF issue, the
   axially moving string and beam of examples/moving_string.c (vlbse 4.1):
   relative error of the first frequency, measured from the response as in
   the example, against CPU time (log-log), over the mesh (4, 8, 16, 32
   elements), the time step or tolerance, and the integrator.

   build (from the repository root; `make demo` builds it with -O2, `make
   bench` with -O3 -march=native):
       cc -std=c99 -O2 bench/wp_moving.c -o build/demo/wp_moving -lm
   run:  build/demo/wp_moving [outdir]        (default outdir: out)
   writes <outdir>/wp_moving_string.csv, .svg and wp_moving_beam.csv, .svg;
   prints the best CPU time per integrator to reach 1e-4 and 1e-6.

   Integrators (each on every mesh; 0.5 s of free vibration, the frequency
   of the midpoint deflection by ex_peak_freq of scenes/ex_freq.h):
   - generalized-alpha rho_inf 0.9 (the example's) and HHT-alpha alpha =
     -0.05, fixed step h = 8e-4, 4e-4, 2e-4, 1e-4, 5e-5 s through
     ms_freq_run() of the example ("raw": one run, error O(h^2));
   - the same, Richardson-extrapolated from the runs at h and h/2 as
     ms_freq() does, f = f(h/2) + (f(h/2) - f(h)) / 3, plotted at the sum
     of the two runs' CPU times (for gen-alpha this is ms_freq() itself:
     checked once below);
   - BDF with error control, max_order 2, rtol = 1e-2 .. 1e-6 and atol =
     1e-4 rtol (1e-4 m/s is the amplitude of the transverse velocity that
     the error test should see relative to rtol), the response sampled at
     t_k = k * 5e-4 s with vlbe_bdf_advance() (no dense output: every
     sample ends a step).  A series stops after the first tolerance whose
     run takes more than 0.5 s (BDF_BUDGET), to keep the whole benchmark
     near a minute.  Why order 2: BDF with orders 3..5 is unstable for
     undamped modes near the imaginary axis; with the default max_order 5
     the step control settles at ~1e5 steps per 0.5 s (4 elements) whatever
     rtol, ~1 s for the coarsest mesh already.  BDF resolves the high modes
     that the initial velocity profile excites (gen-alpha damps them
     slightly and steps over them): steps of 1e-5 .. 4e-5 s at rtol 1e-3.
     Sampling every 2e-4 s costs twice the refactorisations for the same
     errors; every 1e-3 s aliases those high modes into the spectral window
     (an error floor near 1e-6 at 16 elements).
   Errors: string against the exact first frequency of the prestretched
   moving string, ms_f1_exact() (the 32-element model converges to it at
   ~2e-9); beam against its own 32-element converged value: gen-alpha, 32
   elements, Romberg from h = 1e-4, 5e-5, 2.5e-5 (two Richardson levels; the
   extra run at 2.5e-5 s is not part of the charts).  The Richardson values
   of the 32-element beam scatter by ~1e-8 (the Newton tolerance and the
   spectral estimate), so the reference holds to about that: smaller beam
   errors are not resolved.
   The error of a coarse mesh levels off at that mesh's spatial error; a
   raw point can dip below it where the time and mesh errors cancel.

   CPU time: CLOCK_PROCESS_CPUTIME_ID around one whole frequency (building
   the model, workspace, integration, sampling, the spectral peak); median
   of 5 runs when the first takes under 0.02 s, of 3 under 0.25 s, else the
   single run (the runs are deterministic: only the time varies). */
#define _POSIX_C_SOURCE 199309L
#include "../scenes/moving_string.h"
#include "../scenes/svgplot.h"
#include "bench_util.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define DNAN ((double)NAN)
#define T_END 0.5          /* s of response per frequency, as the example */
#define NMESH 4
#define NH 5               /* fixed steps                                 */
#define NTOL 5             /* BDF tolerances                              */
#define MAXPTS 5
#define BDF_DT_OUT 5e-4    /* s, BDF sampling interval                    */
#define BDF_ATOL_SCALE 1e-4
#define BDF_MAX_ORDER 2
#define BDF_BUDGET 0.5     /* s: a BDF series stops after a run this long */

static const int g_mesh[NMESH] = {4, 8, 16, 32};
static const double g_h[NH] = {8e-4, 4e-4, 2e-4, 1e-4, 5e-5};
static const double g_tol[NTOL] = {1e-2, 1e-3, 1e-4, 1e-5, 1e-6};

/* the integrator variants: one series per variant and mesh */
enum { V_GA = 0, V_GA_R, V_HHT, V_HHT_R, V_BDF, NVAR };
static const char *const g_var_name[NVAR] = {
    "gen-alpha rho_inf 0.9", "gen-alpha 0.9 + Richardson", "HHT-alpha -0.05",
    "HHT-alpha -0.05 + Richardson", "BDF max_order 2, error control"};
static const char *const g_var_short[NVAR] = {"gen-alpha", "gen-alpha + Rich.", "HHT",
                                              "HHT + Rich.", "BDF2"};

typedef struct point {
    double x;      /* h [s] (the larger of the pair for Richardson) or rtol */
    double f;      /* frequency [Hz], NaN if the run failed                */
    double err;    /* relative error against the scene's reference         */
    double cpu;    /* median CPU seconds (sum of both runs for Richardson) */
    int reps;
    vlbe_status status;
    vlbe_dae_stats st; /* counters (summed over both runs for Richardson) */
} point;

typedef struct series {
    int var, ne, n;
    point p[MAXPTS];
    char name[40];
    double cpu[MAXPTS], err[MAXPTS]; /* chart columns, NaN where failed */
} series;

typedef struct scene {
    const char *name; /* string, beam */
    int bend;
    double fref;
    char refdesc[200];
    series s[NVAR][NMESH];
} scene;

/* The spectral window of ms_freq_run() (string 12..33 Hz, beam 20..45 Hz). */
static double win_lo(int bend) { return bend ? 20.0 : 12.0; }
static double win_hi(int bend) { return bend ? 45.0 : 33.0; }

/* First frequency with BDF: ms_freq_run() with the fixed-step loop replaced
   by vlbe_bdf_advance() to t_k = k dt_out.  -1 on failure (*status says
   why). */
static double bdf_freq_run(int ne, int bend, double rtol, double dt_out, double t_end,
                           vlbe_dae_stats *stats, vlbe_status *status)
{
    ms_model *m = (ms_model *)malloc(sizeof *m);
    size_t nout = (size_t)(t_end / dt_out + 0.5), k;
    size_t lw = 0, liw = 0;
    vlbe_real *q0 = (vlbe_real *)malloc(4 * (MS_NE_MAX + 1) * sizeof *q0);
    vlbe_real *v0 = (vlbe_real *)malloc(4 * (MS_NE_MAX + 1) * sizeof *v0);
    double *y = (double *)malloc((nout + 1) * sizeof *y);
    double *w = (double *)malloc((nout + 1) * sizeof *w);
    vlbe_real *work = NULL;
    int *iwork = NULL, idx;
    vlbe_bdf_params bp;
    vlbe_bdf bs;
    vlbe_dae_stats zero = {0};
    vlbe_status rc = VLBE_EWORK;
    double f = -1.0;

    *stats = zero;
    if (m && q0 && v0 && y && w && ms_build(m, ne, bend, q0, v0) == 0) {
        lw = vlbe_bdf_work_len(m->sys.n, m->sys.m);
        liw = vlbe_bdf_iwork_len(m->sys.n, m->sys.m);
        work = (vlbe_real *)malloc(lw * sizeof *work);
        iwork = (int *)malloc(liw * sizeof *iwork);
    }
    if (work && iwork) {
        idx = m->node[ne / 2].ofs + 1;
        vlbe_bdf_params_default(&bp);
        bp.max_order = BDF_MAX_ORDER;
        bp.rtol = (vlbe_real)rtol;
        bp.atol = (vlbe_real)(BDF_ATOL_SCALE * rtol);
        /* the sweep steps at 1e-5 .. 4e-5 s, 12..50 steps per output; more
           than 5000 (steps below 1e-7 s) is a broken run, not a slow one */
        bp.max_steps = 5000;
        rc = vlbe_bdf_init(&bs, &m->sys, &bp, VLBE_R(0.0), q0, v0, work, lw, iwork, liw);
        if (rc == VLBE_OK) {
            y[0] = (double)bs.q[idx];
            for (k = 1; k <= nout; ++k) {
                if ((rc = vlbe_bdf_advance(&bs, (vlbe_real)((double)k * dt_out))) != VLBE_OK) break;
                y[k] = (double)bs.q[idx];
            }
            *stats = bs.stats;
        }
        if (rc == VLBE_OK) f = ex_peak_freq(y, nout + 1, dt_out, win_lo(bend), win_hi(bend), w);
    }
    *status = rc;
    free(work);
    free(iwork);
    free(y);
    free(w);
    free(q0);
    free(v0);
    free(m);
    return f;
}

/* One frequency: variant var (V_GA, V_HHT or V_BDF) on ne elements at x
   (h or rtol).  Returns the CPU seconds; frequency, status, counters in pt. */
static double run_once(int var, int ne, int bend, double x, point *pt)
{
    vlbe_hht_params par;
    double c0, c1, f;
    c0 = benchu_cpu_now();
    if (var == V_BDF) {
        f = bdf_freq_run(ne, bend, x, BDF_DT_OUT, T_END, &pt->st, &pt->status);
    } else {
        if (var == V_GA) vlbe_hht_params_genalpha(&par, VLBE_R(0.9));
        else vlbe_hht_params_alpha(&par, VLBE_R(-0.05));
        f = ms_freq_run(ne, bend, x, T_END, &par, NULL, &pt->st, NULL);
        pt->status = f > 0.0 ? VLBE_OK : VLBE_ECALLBACK; /* ms_freq_run gives no status */
    }
    c1 = benchu_cpu_now();
    pt->f = f > 0.0 ? f : DNAN;
    return c1 - c0;
}

/* A timed point: the first run, then repeats while cheap; the median. */
static void measure(int var, int ne, int bend, double x, point *pt)
{
    double t[5];
    int k, reps;
    memset(pt, 0, sizeof *pt);
    pt->x = x;
    t[0] = run_once(var, ne, bend, x, pt);
    pt->cpu = t[0];
    pt->reps = 1;
    if (!(pt->f > 0.0)) {
        pt->cpu = DNAN;
        return;
    }
    reps = t[0] < 0.02 ? 5 : t[0] < 0.25 ? 3 : 1;
    for (k = 1; k < reps; ++k) {
        point tmp;
        memset(&tmp, 0, sizeof tmp);
        t[k] = run_once(var, ne, bend, x, &tmp);
    }
    qsort(t, (size_t)reps, sizeof t[0], benchu_cmp_double);
    pt->cpu = t[reps / 2];
    pt->reps = reps;
}

/* Richardson point from the raw points at h (a) and h/2 (b). */
static void richardson(const point *a, const point *b, point *r)
{
    memset(r, 0, sizeof *r);
    r->x = a->x;
    r->status = a->status != VLBE_OK ? a->status : b->status;
    r->f = b->f + (b->f - a->f) / 3.0; /* NaN if either failed */
    r->cpu = a->cpu + b->cpu;
    r->reps = a->reps < b->reps ? a->reps : b->reps;
    r->st = a->st;
    vlbe_dae_stats_add(&r->st, &b->st);
}

/* Every series of a scene (the errors come later, with the reference). */
static void sweep(scene *sc)
{
    int mi, i, v;
    for (mi = 0; mi < NMESH; ++mi) {
        int ne = g_mesh[mi];
        series *ga = &sc->s[V_GA][mi], *hh = &sc->s[V_HHT][mi], *bd = &sc->s[V_BDF][mi];
        for (v = 0; v < NVAR; ++v) {
            sc->s[v][mi].var = v;
            sc->s[v][mi].ne = ne;
            sc->s[v][mi].n = 0;
        }
        for (i = 0; i < NH; ++i) {
            measure(V_GA, ne, sc->bend, g_h[i], &ga->p[ga->n++]);
            measure(V_HHT, ne, sc->bend, g_h[i], &hh->p[hh->n++]);
        }
        for (i = 0; i + 1 < NH; ++i) {
            series *r = &sc->s[V_GA_R][mi];
            richardson(&ga->p[i], &ga->p[i + 1], &r->p[r->n++]);
            r = &sc->s[V_HHT_R][mi];
            richardson(&hh->p[i], &hh->p[i + 1], &r->p[r->n++]);
        }
        for (i = 0; i < NTOL; ++i) {
            point *p = &bd->p[bd->n++];
            measure(V_BDF, ne, sc->bend, g_tol[i], p);
            if (p->status != VLBE_OK || p->cpu > BDF_BUDGET) break;
        }
    }
}

/* Errors against sc->fref and the chart columns. */
static void errors(scene *sc)
{
    int v, mi, i;
    for (v = 0; v < NVAR; ++v)
        for (mi = 0; mi < NMESH; ++mi) {
            series *s = &sc->s[v][mi];
            snprintf(s->name, sizeof s->name, "%s, %d el", g_var_short[v], s->ne);
            for (i = 0; i < s->n; ++i) {
                point *p = &s->p[i];
                p->err = p->f > 0.0 ? fabs(p->f - sc->fref) / sc->fref : DNAN;
                s->err[i] = p->err > 0.0 ? p->err : DNAN;
                s->cpu[i] = p->f > 0.0 ? p->cpu : DNAN;
            }
        }
}

static void write_csv(const scene *sc, const char *dir)
{
    char path[512];
    FILE *f;
    int v, mi, i;
    snprintf(path, sizeof path, "%s/wp_moving_%s.csv", dir, sc->name);
    f = svgp_csv_open(path, "scene,integrator,elements,x_kind,x,status,f1_Hz,f1_ref_Hz,rel_error,"
                            "cpu_s,reps,steps,rejected,newton_iters,jac_evals,lu_factors,"
                            "force_calls");
    if (!f) {
        fprintf(stderr, "wp_moving: cannot write %s\n", path);
        return;
    }
    for (v = 0; v < NVAR; ++v)
        for (mi = 0; mi < NMESH; ++mi) {
            const series *s = &sc->s[v][mi];
            for (i = 0; i < s->n; ++i) {
                const point *p = &s->p[i];
                const char *kind = v == V_BDF ? "rtol" : v == V_GA_R || v == V_HHT_R ? "h_and_h/2" : "h";
                fprintf(f, "%s,\"%s\",%d,%s,%.6g,\"%s\",%.12f,%.12f,%.6e,%.6e,%d,%ld,%ld,%ld,%ld,%ld,%ld\n",
                        sc->name, g_var_name[v], s->ne, kind, p->x, vlbe_status_str(p->status), p->f,
                        sc->fref, p->err, p->cpu, p->reps, p->st.steps, p->st.rejected,
                        p->st.newton_iters, p->st.jac_evals, p->st.lu_factors, p->st.force_calls);
            }
        }
    if (fclose(f) != 0) fprintf(stderr, "wp_moving: cannot write %s\n", path);
}

/* The chart: 16 series (svgplot's limit), one per variant and mesh, in
   the order gen-alpha, gen-alpha + Richardson, HHT-alpha, BDF2: the marker
   (series index mod 4) tells the mesh, the line the variant.  HHT-alpha,
   within ~10 % of gen-alpha in error and cost, is one markers-only series
   per mesh holding its raw and Richardson points (they fall on or next to
   the gen-alpha curves); it gets the colours of raw gen-alpha, BDF2 those
   of gen-alpha + Richardson. */
static void chart(scene *sc, const char *dir, const char *title)
{
    static const int style[4] = {SVGP_MARKERS | SVGP_SOLID, SVGP_MARKERS | SVGP_DASH, SVGP_NOLINE,
                                 SVGP_MARKERS | SVGP_DOT};
    static const char *const label[4] = {"gen-alpha 0.9", "gen-alpha + Richardson",
                                         "HHT -0.05, raw and Rich.", "BDF2"};
    static char names[4][NMESH][48];
    static double hx[NMESH][2 * MAXPTS], hy[NMESH][2 * MAXPTS];
    char path[512];
    svgp_chart c;
    int k, mi, i, n;
    svgp_init(&c, title, "CPU time per frequency [s] (0.5 s of response + spectrum; " VLBE_BENCH_FLAGS ")",
              "relative error of f1 [-]", 1, 1);
    for (k = 0; k < 4; ++k)
        for (mi = 0; mi < NMESH; ++mi) {
            const series *s = &sc->s[k == 0 ? V_GA : k == 1 ? V_GA_R : V_BDF][mi];
            snprintf(names[k][mi], sizeof names[k][mi], "%s, %d el", label[k], g_mesh[mi]);
            if (k != 2) {
                svgp_series(&c, names[k][mi], s->n, s->cpu, s->err, style[k]);
                continue;
            }
            for (i = 0; i < 2 * MAXPTS; ++i) hx[mi][i] = hy[mi][i] = DNAN;
            for (n = 0, s = &sc->s[V_HHT][mi]; n < 2; ++n, s = &sc->s[V_HHT_R][mi])
                for (i = 0; i < s->n; ++i) {
                    hx[mi][n * MAXPTS + i] = s->cpu[i];
                    hy[mi][n * MAXPTS + i] = s->err[i];
                }
            svgp_series(&c, names[k][mi], 2 * MAXPTS, hx[mi], hy[mi], style[k]);
        }
    svgp_fit_legend_log(&c, 8, 3);
    snprintf(path, sizeof path, "%s/wp_moving_%s.svg", dir, sc->name);
    if (svgp_write_file(&c, path) != 0) fprintf(stderr, "wp_moving: cannot write %s\n", path);
}

/* Cheapest point of variant v (over meshes) whose error, and that of every
   finer point of its series, is at most lvl; -1 if none. */
static double best_cpu(const scene *sc, int v, double lvl, int *mesh, double *x)
{
    double best = -1.0;
    int mi, i, j;
    for (mi = 0; mi < NMESH; ++mi) {
        const series *s = &sc->s[v][mi];
        for (i = 0; i < s->n; ++i) {
            int ok = 1;
            for (j = i; j < s->n; ++j)
                if (!(s->p[j].err <= lvl)) ok = 0;
            if (!ok) continue;
            if (best < 0.0 || s->p[i].cpu < best) {
                best = s->p[i].cpu;
                *mesh = s->ne;
                *x = s->p[i].x;
            }
            break; /* finer points of this series cost more */
        }
    }
    return best;
}

static void summary(const scene *sc)
{
    static const double lvl[2] = {1e-4, 1e-6};
    int v, l;
    for (v = 0; v < NVAR; ++v) {
        printf("%-6s %-30s", sc->name, g_var_name[v]);
        for (l = 0; l < 2; ++l) {
            int mesh = 0;
            double x = 0.0, c = best_cpu(sc, v, lvl[l], &mesh, &x);
            char cell[64];
            if (c < 0.0) snprintf(cell, sizeof cell, "not reached");
            else
                snprintf(cell, sizeof cell, "%7.3f s (%2d el, %s %.0e)", c, mesh,
                         v == V_BDF ? "rtol" : "h", x);
            printf("  %-30s", cell);
        }
        printf("\n");
    }
}

int main(int argc, char **argv)
{
    static scene str, beam;
    const char *dir = argc > 1 ? argv[1] : "out";
    double c0 = benchu_cpu_now(), fa, fb, fc, r1, r2, fga;
    char title[2][160];
    vlbe_dae_stats st;
    vlbe_hht_params par;
    int ok;

    if (benchu_mkdir(dir, "wp_moving")) return 1;
    printf("wp_moving: work-precision of the moving string/beam (vlbse 4.1, "
           "examples/moving_string.c), vlbe %s, %s, compiler %s, %s\n",
           VLBE_VERSION_STRING, sizeof(vlbe_real) == sizeof(double) ? "double" : "float",
           __VERSION__, VLBE_BENCH_FLAGS);

    /* the Richardson pair here is ms_freq() of the example */
    vlbe_hht_params_genalpha(&par, VLBE_R(0.9));
    fa = ms_freq_run(4, 0, 2e-4, T_END, &par, NULL, &st, NULL);
    fb = ms_freq_run(4, 0, 1e-4, T_END, &par, NULL, &st, NULL);
    fga = ms_freq(4, 0, 2e-4, T_END, NULL, NULL);
    if (!(fb + (fb - fa) / 3.0 == fga)) {
        fprintf(stderr, "wp_moving: Richardson pair differs from ms_freq() (%.15g vs %.15g)\n",
                fb + (fb - fa) / 3.0, fga);
        return 1;
    }

    str.name = "string";
    str.bend = 0;
    str.fref = ms_f1_exact();
    snprintf(str.refdesc, sizeof str.refdesc, "exact f1 of the prestretched string, %.8f Hz",
             str.fref);
    beam.name = "beam";
    beam.bend = 1;

    sweep(&str);
    errors(&str);
    sweep(&beam);

    /* beam reference: gen-alpha, 32 elements, Romberg over h = 1e-4, 5e-5
       (from the sweep) and 2.5e-5 */
    fa = beam.s[V_GA][NMESH - 1].p[NH - 2].f;
    fb = beam.s[V_GA][NMESH - 1].p[NH - 1].f;
    fc = ms_freq_run(32, 1, 0.5 * g_h[NH - 1], T_END, &par, NULL, &st, NULL);
    ok = fa > 0.0 && fb > 0.0 && fc > 0.0;
    r1 = fb + (fb - fa) / 3.0;
    r2 = fc + (fc - fb) / 3.0;
    beam.fref = ok ? r2 + (r2 - r1) / 15.0 : DNAN;
    snprintf(beam.refdesc, sizeof beam.refdesc,
             "32-element value %.8f Hz (gen-alpha, Romberg h = 1e-4, 5e-5, 2.5e-5;\n"
             "            its last Richardson correction, %.1e relative, says how far it holds)",
             beam.fref, fabs(r2 - r1) / beam.fref);
    errors(&beam);

    snprintf(title[0], sizeof title[0], "Moving string (vlbse 4.1): f1 vs exact %.6f Hz", str.fref);
    snprintf(title[1], sizeof title[1], "Moving beam (vlbse 4.1): f1 vs converged 32-element value %.6f Hz",
             beam.fref);
    chart(&str, dir, title[0]);
    chart(&beam, dir, title[1]);
    write_csv(&str, dir);
    write_csv(&beam, dir);

    printf("references: string: %s\n            beam:   %s\n", str.refdesc, beam.refdesc);
    printf("best CPU time per frequency to reach a relative error of f1 (that point and every "
           "finer one of its series at or below the level; any mesh)\n");
    printf("%-6s %-30s  %-30s  %-30s\n", "scene", "integrator", "<= 1e-4", "<= 1e-6");
    summary(&str);
    summary(&beam);
    printf("wrote %s/wp_moving_{string,beam}.{svg,csv} (%.1f s CPU)\n", dir, benchu_cpu_now() - c0);
    return 0;
}
