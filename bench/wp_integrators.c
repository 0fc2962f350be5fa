/* wp_integrators.c -- work-precision diagrams of the integrators of
   integrators.h: error against CPU time (log-log), error against the step
   size (order of convergence) and constraint drift against the step size,
   on the index-3 pendulum and Andrews' squeezing mechanism.

   build (from the repository root; `make demo` builds it with -O2, `make
   bench` with -O3 -march=native):
       cc -std=c99 -O2 bench/wp_integrators.c -o build/demo/wp_integrators -lm
   run:  build/demo/wp_integrators [outdir]        (default outdir: out)
   writes <outdir>/wp_pendulum.csv, wp_pendulum.svg, order_pendulum.svg,
   drift_pendulum.svg and the same for andrews; prints one summary line per
   series (best error reached, its CPU time, observed order).

   The problems are the examples' (scenes/pendulum.h, scenes/andrews.h,
   shared with examples/pendulum.c and examples/andrews.c).
   Pendulum: t in [0, 3] s (one full period between the first two crossings
   of x = 0, found on the cubic Hermite interpolant as in the example);
   error = relative error of the period against pend_period_exact() (AGM).
   HHT-alpha (alpha = -0.05), generalized-alpha (rho_inf = 0.8) and trapezoidal
   Newmark (beta 1/4, gamma 1/2) at h = 1e-2 .. 1e-5 with Newton rtol = atol =
   1e-12 (as the example: the default 1e-9 would be the error floor); BDF
   with max_order 5 and 2 at rtol = 1e-3 .. 1e-11, atol = rtol / 100.
   Andrews: t in [0, 0.03] s; error = largest relative error of the seven
   angles at 0.03 s against the Test Set reference of andrews.c.  HHT-alpha,
   generalized-alpha and trapezoidal Newmark at h = 2e-5 .. 2.5e-7 (Newton
   tolerances of andr_params_for: rtol 1e-12, atol 1e-14); BDF (max_order 5)
   at rtol = atol = 1e-4 .. 1e-11.
   A run that fails (Newton failure, ...) is reported in the CSV and left out
   of the charts ("while it works").

   CPU time: CLOCK_PROCESS_CPUTIME_ID around vlbe_*_init plus the integration
   with what the error needs (the crossing detection of the pendulum; the
   final state of Andrews), workspace allocated outside; median of 5 runs
   (3 when one run takes more than 0.05 s).  A separate first run, not timed,
   also records the constraint drift of every step (max |C| and |C_q v| over
   the run) and the counters; the runs are deterministic. */
#define _POSIX_C_SOURCE 199309L
#include "../scenes/pendulum.h"
#include "../scenes/andrews.h"
#include "../scenes/svgplot.h"
#include "bench_util.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define DNAN ((double)NAN)
#define MAXPTS 12
#define MAXSER 6
#define PEND_T_WP 3.0 /* s */

enum { FAM_HHT = 0, FAM_GENA = 1, FAM_NEWMARK = 2, FAM_BDF = 3 };

typedef struct point {
    double x;           /* step size [s] (fixed-step families) or rtol (BDF)  */
    vlbe_status status;
    double err;         /* NaN if the run failed                              */
    double cpu;         /* median CPU seconds per run, NaN if failed          */
    int reps;
    double max_c, max_cv; /* largest |C| and |C_q v| over the accepted steps  */
    double mean_h;      /* t_end / steps [s]                                  */
    vlbe_dae_stats stats;
} point;

typedef struct series {
    const char *name;   /* legend and summary                                 */
    int fam, max_order;
    int full_newton;    /* 1: modified = 0 (a fresh iteration matrix every iteration) */
    int n;
    point p[MAXPTS];
    /* columns for the charts (NaN where failed) */
    double x[MAXPTS], cpu[MAXPTS], err[MAXPTS], c[MAXPTS], cv[MAXPTS], mh[MAXPTS];
} series;

/* a scene: the problem and how to measure the error */
typedef struct scene {
    const char *name;
    const vlbe_dae *sys;
    const vlbe_real *q0, *v0;
    double t_end;
    int nser;
    series s[MAXSER];
} scene;

static ex_method g_ws; /* workspace of all runs (ws_alloc) */

static void fam_params(int fam, vlbe_hht_params *par)
{
    if (fam == FAM_HHT) vlbe_hht_params_alpha(par, VLBE_R(-0.05));
    else if (fam == FAM_GENA) vlbe_hht_params_genalpha(par, VLBE_R(0.8));
    else vlbe_hht_params_newmark(par, VLBE_R(0.25), VLBE_R(0.5));
}

/* The drift of one accepted state: |C| and |C_q v| (inf-norms) into *pt. */
static void drift(const vlbe_dae *sys, vlbe_real t, const vlbe_real *q, const vlbe_real *v,
                  point *pt)
{
    vlbe_real C[ANDR_M], Cq[ANDR_M * ANDR_N], Ct[ANDR_M];
    int i, m = sys->m, n = sys->n;
    sys->constr(sys->user, t, q, C);
    sys->constr_jac(sys->user, t, q, Cq, Ct);
    for (i = 0; i < m; ++i) {
        double c = fabs((double)C[i]);
        double cv = fabs((double)(vlbe_vec_dot(n, Cq + (size_t)i * n, v) + Ct[i]));
        if (c > pt->max_c) pt->max_c = c;
        if (cv > pt->max_cv) pt->max_cv = cv;
    }
}

/* Pendulum error from the crossings; Andrews error from the final state. */
static double scene_err(const scene *sc, const vlbe_real *q, const pend_period *pp)
{
    double e = 0.0;
    int i;
    if (sc->sys->n == 2) {
        double T = pend_period_exact(PEND_L, PEND_G);
        return fabs(pend_period_value(pp) - T) / T;
    }
    for (i = 0; i < ANDR_N; ++i) {
        double ei = fabs((double)q[i] - andr_qref()[i]) / fabs(andr_qref()[i]);
        if (ei > e) e = ei;
    }
    return e;
}

/* Observer of one run: the pendulum's crossings, and the drift if instr. */
typedef struct wp_obs {
    const vlbe_dae *sys;
    pend_period pp;
    int pend, instr;
    point *pt;
} wp_obs;

static vlbe_status wp_obs_step(void *ctx, double t, const vlbe_real *q, const vlbe_real *v,
                               const vlbe_real *lambda)
{
    wp_obs *o = (wp_obs *)ctx;
    (void)lambda;
    if (o->pend) pend_period_add(&o->pp, t, (double)q[0], (double)v[0]);
    if (o->instr && t > 0.0) drift(o->sys, (vlbe_real)t, q, v, o->pt);
    return VLBE_OK;
}

/* One run of series s at x (h or rtol); instr: record the drift.  Returns
   the CPU seconds; status, error (and drift, counters if instr) into *pt. */
static double run(const scene *sc, const series *s, double x, int instr, point *pt)
{
    const vlbe_dae *sys = sc->sys;
    vlbe_hht_params hp;
    vlbe_bdf_params bp;
    ex_method m = g_ws;
    ex_run_out out;
    wp_obs o;
    vlbe_status rc;
    double c0, c1;
    vlbe_real qf[ANDR_N];

    o.sys = sys;
    o.pend = sys->n == 2;
    o.instr = instr;
    o.pt = pt;
    pend_period_init(&o.pp);
    if (s->fam != FAM_BDF) {
        fam_params(s->fam, &hp);
        if (o.pend) {
#ifndef VLBE_USE_FLOAT
            hp.rtol = hp.atol = VLBE_R(1e-12);
#endif
        } else {
            andr_params_for(s->fam, &hp);
        }
        if (s->full_newton) hp.modified = 0;
        m.hht = &hp;
        m.h = x;
    } else {
        vlbe_bdf_params_default(&bp);
        bp.max_order = s->max_order;
        bp.rtol = (vlbe_real)x;
        bp.atol = (vlbe_real)(o.pend ? 1e-2 * x : x);
        m.bdf = &bp;
    }
    c0 = benchu_cpu_now();
    rc = ex_run(sys, &m, sc->q0, sc->v0, sc->t_end, wp_obs_step, &o, qf, NULL, NULL, &out);
    c1 = benchu_cpu_now();
    pt->status = rc;
    pt->err = rc == VLBE_OK ? scene_err(sc, qf, &o.pp) : DNAN;
    if (instr) {
        pt->stats = out.stats;
        pt->mean_h = out.stats.steps > 0 ? sc->t_end / (double)out.stats.steps : DNAN;
    }
    return c1 - c0;
}

/* Measure point i of series s: an instrumented run, then the timed runs. */
static void measure(const scene *sc, series *s, double x)
{
    point *pt = &s->p[s->n++];
    double t[5];
    int k, reps;
    memset(pt, 0, sizeof *pt);
    pt->x = x;
    t[0] = run(sc, s, x, 1, pt);
    pt->cpu = DNAN;
    if (pt->status != VLBE_OK) return;
    reps = t[0] > 0.05 ? 3 : 5;
    for (k = 0; k < reps; ++k) {
        point tmp;
        memset(&tmp, 0, sizeof tmp);
        t[k] = run(sc, s, x, 0, &tmp);
    }
    qsort(t, (size_t)reps, sizeof t[0], benchu_cmp_double);
    pt->cpu = t[reps / 2];
    pt->reps = reps;
}

static void columns(series *s)
{
    int i;
    for (i = 0; i < s->n; ++i) {
        const point *p = &s->p[i];
        int ok = p->status == VLBE_OK;
        s->x[i] = p->x;
        s->cpu[i] = ok ? p->cpu : DNAN;
        s->err[i] = ok ? p->err : DNAN;
        s->c[i] = ok ? p->max_c : DNAN;
        s->cv[i] = ok ? p->max_cv : DNAN;
        s->mh[i] = ok ? p->mean_h : DNAN;
    }
}

/* Least-squares slope of log10(y) over log10(x), points with both > 0,
   among the first n. */
static double loglog_slope(int n, const double *x, const double *y, int *used)
{
    double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
    int i, k = 0;
    for (i = 0; i < n; ++i) {
        double lx, ly;
        if (!(x[i] > 0.0) || !(y[i] > 0.0)) continue;
        lx = log10(x[i]);
        ly = log10(y[i]);
        sx += lx;
        sy += ly;
        sxx += lx * lx;
        sxy += lx * ly;
        ++k;
    }
    *used = k;
    if (k < 2) return DNAN;
    return ((double)k * sxy - sx * sy) / ((double)k * sxx - sx * sx);
}

static void write_csv(const scene *sc, const char *dir)
{
    char path[512];
    FILE *f;
    int i, k;
    snprintf(path, sizeof path, "%s/wp_%s.csv", dir, sc->name);
    f = svgp_csv_open(path, "series,x_kind,x,status,error,cpu_s,reps,steps,rejected,newton_iters,"
                            "jac_evals,lu_factors,force_calls,mean_h_s,max_abs_C,max_abs_Cq_v");
    if (!f) {
        fprintf(stderr, "wp_integrators: cannot write %s\n", path);
        return;
    }
    for (k = 0; k < sc->nser; ++k) {
        const series *s = &sc->s[k];
        for (i = 0; i < s->n; ++i) {
            const point *p = &s->p[i];
            fprintf(f, "\"%s\",%s,%.10g,\"%s\",%.10g,%.10g,%d,%ld,%ld,%ld,%ld,%ld,%ld,%.10g,%.10g,%.10g\n",
                    s->name, s->fam == FAM_BDF ? "rtol" : "h", p->x, vlbe_status_str(p->status),
                    p->err, p->cpu, p->reps, p->stats.steps, p->stats.rejected,
                    p->stats.newton_iters, p->stats.jac_evals, p->stats.lu_factors,
                    p->stats.force_calls, p->mean_h, p->max_c, p->max_cv);
        }
    }
    if (fclose(f) != 0) fprintf(stderr, "wp_integrators: cannot write %s\n", path);
}

static void write_svg(svgp_chart *c, const char *dir, const char *stem, const char *scene_name)
{
    char path[512];
    snprintf(path, sizeof path, "%s/%s_%s.svg", dir, stem, scene_name);
    if (svgp_write_file(c, path) != 0) fprintf(stderr, "wp_integrators: cannot write %s\n", path);
}

/* The three charts of a scene.  errlabel: y label of the error. */
static void charts(scene *sc, const char *dir, const char *title, const char *errlabel,
                   const char *clabel, const char *cname, const char *cvname)
{
    static char names[2 * MAXSER][64];
    static char ttl[3][160];
    static double rx[2], ry[2];
    svgp_chart c;
    int k, nref = 0;
    const series *ref = NULL;
    double lo = 0.0, hi = 0.0;

    for (k = 0; k < sc->nser; ++k) columns(&sc->s[k]);

    /* error vs CPU time */
    snprintf(ttl[0], sizeof ttl[0], "%s: work-precision", title);
    svgp_init(&c, ttl[0], "CPU time per run [s] (median of 3-5 runs, " VLBE_BENCH_FLAGS ")", errlabel, 1, 1);
    for (k = 0; k < sc->nser; ++k)
        svgp_series(&c, sc->s[k].name, sc->s[k].n, sc->s[k].cpu, sc->s[k].err, SVGP_MARKERS);
    svgp_fit_legend_log(&c, 12, 0);
    write_svg(&c, dir, "wp", sc->name);

    /* error vs step size, fixed-step families, with a slope-2 reference */
    snprintf(ttl[1], sizeof ttl[1], "%s: convergence of the Newmark family", title);
    svgp_init(&c, ttl[1], "step size h [s]", errlabel, 1, 1);
    for (k = 0; k < sc->nser; ++k) {
        const series *s = &sc->s[k];
        int i;
        if (s->fam == FAM_BDF) continue;
        svgp_series(&c, s->name, s->n, s->x, s->err, SVGP_MARKERS);
        if (!ref) ref = s;
        for (i = 0; i < s->n; ++i) {
            if (!(s->err[i] > 0.0)) continue;
            if (lo == 0.0 || s->x[i] < lo) lo = s->x[i];
            if (s->x[i] > hi) hi = s->x[i];
        }
    }
    if (ref && hi > lo) {
        /* through the first series' largest-h point, a factor 3 above it */
        int i;
        for (i = 0; i < ref->n; ++i)
            if (ref->err[i] > 0.0) break;
        if (i < ref->n) {
            double e0 = 3.0 * ref->err[i], h0 = ref->x[i];
            rx[0] = hi;
            rx[1] = lo;
            ry[0] = e0 * (hi / h0) * (hi / h0);
            ry[1] = e0 * (lo / h0) * (lo / h0);
            svgp_series(&c, "slope 2 (reference)", 2, rx, ry, SVGP_DASH);
            nref = 1;
        }
    }
    (void)nref;
    svgp_fit_legend_log(&c, 12, 0);
    write_svg(&c, dir, "order", sc->name);

    /* constraint drift vs step size (BDF at its mean step size) */
    snprintf(ttl[2], sizeof ttl[2], "%s: constraint drift (largest over the run)", title);
    svgp_init(&c, ttl[2], "step size h [s] (BDF: mean step t_end / steps)", clabel, 1, 1);
    for (k = 0; k < sc->nser; ++k) { /* velocity level: every series but BDF2 */
        series *s = &sc->s[k];
        if (s->fam == FAM_BDF && s->max_order != 5) continue;
        snprintf(names[2 * k], sizeof names[0], "%s: %s", s->name, cvname);
        svgp_series(&c, names[2 * k], s->n, s->fam == FAM_BDF ? s->mh : s->x, s->cv, SVGP_MARKERS);
    }
    for (k = 0; k < sc->nser; ++k) { /* position level: the first series and BDF5 */
        series *s = &sc->s[k];
        if (!(k == 0 || (s->fam == FAM_BDF && s->max_order == 5))) continue;
        snprintf(names[2 * k + 1], sizeof names[0], "%s: %s", s->name, cname);
        svgp_series(&c, names[2 * k + 1], s->n, s->fam == FAM_BDF ? s->mh : s->x, s->c,
                    SVGP_MARKERS | SVGP_DASH);
    }
    svgp_fit_legend_log(&c, 12, 0);
    write_svg(&c, dir, "drift", sc->name);
}

/* One summary line per series. */
static void summary(const scene *sc)
{
    int k, i;
    for (k = 0; k < sc->nser; ++k) {
        const series *s = &sc->s[k];
        int best = -1, used, nfail = 0, last;
        double slope;
        for (i = 0; i < s->n; ++i) {
            if (s->p[i].status != VLBE_OK) {
                ++nfail;
                continue;
            }
            if (best < 0 || s->p[i].err < s->p[best].err) best = i;
        }
        /* fixed step: the asymptotic range, from the largest h on while the
           error falls and the local slope stays within 0.5 of the previous
           one (beyond it rounding or the Newton iteration sets a floor);
           BDF: every point (error against the tolerance) */
        last = s->n;
        if (s->fam != FAM_BDF) {
            double prev = 0.0;
            for (last = 1; last < s->n; ++last) {
                double sl;
                if (!(s->err[last] > 0.0) || !(s->err[last - 1] > 0.0) ||
                    !(s->err[last] < s->err[last - 1]))
                    break;
                sl = log(s->err[last - 1] / s->err[last]) / log(s->x[last - 1] / s->x[last]);
                if (last >= 2 && fabs(sl - prev) > 0.5) break;
                prev = sl;
            }
        }
        slope = loglog_slope(last, s->x, s->err, &used);
        printf("%-9s %-28s ", sc->name, s->name);
        if (best < 0) {
            printf("no successful run\n");
            continue;
        }
        printf("best err %8.2e at %s %-7.2g cpu %8.2e s", s->p[best].err,
               s->fam == FAM_BDF ? "rtol" : "h", s->p[best].x, s->p[best].cpu);
        if (s->fam == FAM_BDF) printf("  err ~ rtol^%.2f", slope);
        else printf("  order %.2f", slope);
        printf(" (%d pts, %s %.2g..%.2g", used, s->fam == FAM_BDF ? "rtol" : "h", s->x[0],
               s->x[last - 1]);
        if (nfail) printf("; %d failed", nfail);
        printf(")\n");
    }
}

static void ws_alloc(int n, int m)
{
    if (ex_method_reserve(&g_ws, n, m) != 0) {
        fprintf(stderr, "wp_integrators: out of memory\n");
        exit(1);
    }
}

static void add_series(scene *sc, const char *name, int fam, int max_order, int full_newton)
{
    series *s = &sc->s[sc->nser++];
    memset(s, 0, sizeof *s);
    s->name = name;
    s->fam = fam;
    s->max_order = max_order;
    s->full_newton = full_newton;
}

int main(int argc, char **argv)
{
    static const double pend_h[] = {1e-2, 5e-3, 2e-3, 1e-3, 5e-4, 2e-4, 1e-4, 5e-5, 2e-5, 1e-5};
    static const double pend_tol[] = {1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11};
    static const long andr_nsteps[] = {1500, 3000, 6000, 15000, 30000, 60000, 120000};
    static const double andr_tol[] = {1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11};
    static scene pend, andr;
    const char *dir = argc > 1 ? argv[1] : "out";
    pend_par pp = pend_default();
    andr_par ap = andr_default();
    vlbe_dae psys, asys;
    vlbe_real pq0[2], pv0[2], aq0[ANDR_N], av0[ANDR_N];
    double c0 = benchu_cpu_now();
    int k, i;

    if (benchu_mkdir(dir, "wp_integrators")) return 1;
    printf("wp_integrators: work-precision of integrators.h, vlbe %s, %s, compiler %s, %s\n",
           VLBE_VERSION_STRING, sizeof(vlbe_real) == sizeof(double) ? "double" : "float",
           __VERSION__, VLBE_BENCH_FLAGS);

    /* -- pendulum ---------------------------------------------------------- */
    pend_setup(&psys, &pp);
    pend_initial(&pp, pq0, pv0);
    pend.name = "pendulum";
    pend.sys = &psys;
    pend.q0 = pq0;
    pend.v0 = pv0;
    pend.t_end = PEND_T_WP;
    add_series(&pend, "HHT-alpha -0.05", FAM_HHT, 0, 0);
    add_series(&pend, "HHT-alpha, full Newton", FAM_HHT, 0, 1);
    add_series(&pend, "gen-alpha rho_inf 0.8", FAM_GENA, 0, 0);
    add_series(&pend, "Newmark trapezoidal", FAM_NEWMARK, 0, 0);
    add_series(&pend, "BDF max_order 5", FAM_BDF, 5, 0);
    add_series(&pend, "BDF max_order 2", FAM_BDF, 2, 0);
    ws_alloc(2, 1);
    for (k = 0; k < pend.nser; ++k) {
        series *s = &pend.s[k];
        if (s->fam == FAM_BDF)
            for (i = 0; i < (int)(sizeof pend_tol / sizeof *pend_tol); ++i) measure(&pend, s, pend_tol[i]);
        else
            for (i = 0; i < (int)(sizeof pend_h / sizeof *pend_h); ++i) measure(&pend, s, pend_h[i]);
    }
    charts(&pend, dir, "Index-3 pendulum, t in [0, 3] s", "relative error of the period [-]",
           "largest |C_q v| [m^2/s] (solid), |C| [m^2] (dashed)", "|C|", "|C_q v|");
    write_csv(&pend, dir);

    /* -- Andrews ------------------------------------------------------------- */
    andr_setup(&asys, &ap);
    andr_initial(aq0, av0);
    andr.name = "andrews";
    andr.sys = &asys;
    andr.q0 = aq0;
    andr.v0 = av0;
    andr.t_end = ANDR_T_END;
    add_series(&andr, "HHT-alpha -0.05", FAM_HHT, 0, 0);
    add_series(&andr, "HHT-alpha, full Newton", FAM_HHT, 0, 1);
    add_series(&andr, "gen-alpha rho_inf 0.8", FAM_GENA, 0, 0);
    add_series(&andr, "Newmark trapezoidal", FAM_NEWMARK, 0, 0);
    add_series(&andr, "BDF max_order 5", FAM_BDF, 5, 0);
    ws_alloc(ANDR_N, ANDR_M);
    for (k = 0; k < andr.nser; ++k) {
        series *s = &andr.s[k];
        if (s->fam == FAM_BDF)
            for (i = 0; i < (int)(sizeof andr_tol / sizeof *andr_tol); ++i) measure(&andr, s, andr_tol[i]);
        else
            for (i = 0; i < (int)(sizeof andr_nsteps / sizeof *andr_nsteps); ++i)
                measure(&andr, s, ANDR_T_END / (double)andr_nsteps[i]);
    }
    charts(&andr, dir, "Andrews' mechanism, t in [0, 0.03] s",
           "max relative error of the 7 angles at 0.03 s [-]",
           "largest |G q'| [m/s] (solid), |g| [m] (dashed)", "|g|", "|G q'|");
    write_csv(&andr, dir);

    printf("best error reached per series (CPU time: median per run); order: least-squares "
           "slope of log(error) over log(h) in the asymptotic range\n");
    summary(&pend);
    summary(&andr);
    printf("wrote %s/{wp,order,drift}_{pendulum,andrews}.svg, %s/wp_{pendulum,andrews}.csv "
           "(%.1f s CPU)\n",
           dir, dir, benchu_cpu_now() - c0);
    ex_method_release(&g_ws);
    return 0;
}
