/* wp_sliding.c -- work-precision of scene 2, the beam sliding through a
   prismatic joint (Hsiao et al., section 3; scenes/ex_sbeam.h,
   examples/sliding_beam.c): error of the tip deflection against CPU time
   (log-log) over the step size and the integrator, cases (a) and (b).

   build (from the repository root; `make demo` builds it with -O2, `make
   bench` with -O3 -march=native):
       cc -std=c99 -O2 bench/wp_sliding.c -o build/demo/wp_sliding -lm
   run:  build/demo/wp_sliding [outdir [full]]        (default outdir: out)
   writes <outdir>/wp_sliding.csv, wp_sliding_a.svg, wp_sliding_b.svg;
   prints the error and CPU time of every run, the failures, and the best
   CPU time per integrator to reach 1e-2 and 1e-3.  "full" adds the
   trapezoidal Newmark runs left out by default (below) and a check of the
   reference against h = 3.125e-5 s (about 45 s more).

   The scene is the example's: sb_cfg_paper(&c, 'a' or 'b'), 14 + 10 = 24
   elements, (a) retraction, t in [0, 2.5] s, (b) deployment, t in [0, 3] s,
   modal damping of eq. (56), static start with a tip deflection of 0.024 m;
   every run is one sb_run() (static start, integration with restarts at
   node crossings).  Integrators (sb_cfg.alpha, sb_cfg.rho_inf):
   HHT-alpha -0.05 (the example's), HHT-alpha -0.3, generalized-alpha
   rho_inf 0.8, trapezoidal Newmark (alpha = 0: beta 1/4, gamma 1/2), at
   h = 4e-3, 2e-3, 1e-3, 5e-4, 2.5e-4 s.  The Newton settings are
   sb_run()'s defaults (those of integrators.h, rtol 1e-9, atol 1e-11,
   newton_max 10, modified Newton, and max_halvings = 10; sb_cfg can change
   the last three): not swept here, since the step and the integrator set
   the error and they only decide whether a hard step gets through.

   Error: max over the grid t_k = k * 4e-3 s in [0, t_end] of |tip y(t_k)
   - tip y_ref(t_k)| / 0.024 (the initial deflection); tip y = q[n - 2].
   4e-3 s is a whole multiple of every step used, so the grid points are
   accepted steps (no interpolation; the observer checks that every grid
   point is met exactly once).  Reference: the same model, HHT-alpha -0.05
   at h_ref = 6.25e-5 s.  Its accuracy: the differences between successive
   halvings of HHT-alpha -0.05 (5e-4 -> 2.5e-4 -> 1.25e-4 -> 6.25e-5) fall
   by 4.00, 4.00 (a) and 3.90, 3.98 (b) -- second order, printed as
   "ratio" --, so its error is about |y(2 h_ref) - y(h_ref)| / 3 = 1.9e-5
   (a) and 5.2e-5 (b).  The `full` run measured it against h = 3.125e-5 s:
   1.4e-5 (a), 3.9e-5 (b), the same within the error of that run (a
   quarter).  So errors below ~5e-5 are not resolved; the smallest one
   charted is 2.6e-4.

   Measured (-O2, gcc 12.2.0, AMD EPYC (Zen 4) 2.6 GHz, 2 cores, one used;
   CPU times below are medians over 4 invocations: one invocation's times
   vary by up to 50% when other jobs load the second core of this shared
   machine (e.g. HHT-alpha -0.05, (b), h = 2.5e-4: 1.18-1.87 s); the whole
   benchmark took 49.5, 53.2, 53.8 and 58.6 s CPU, 92 s with `full`):
   - Error (HHT-alpha -0.05) at h = 4e-3, 2e-3, 1e-3, 5e-4, 2.5e-4:
     (a) 7.1e-2, 1.9e-2, 4.7e-3, 1.2e-3, 2.8e-4 (second order);
     (b) 3.4e-2, 2.5e-2, 1.15e-2, 3.2e-3, 7.7e-4 (second order from 1e-3
     down; above it the steps rejected at the releases, 302 at 4e-3,
     dominate).  HHT-alpha -0.3 has 1.3 times, gen-alpha 0.8 0.93 times
     that error, at the same cost within the timing noise.  CPU per run
     0.25-0.30 s at 4e-3, 1.14-1.30 s at 2.5e-4: 14x the steps cost 5x,
     because the Newton iterations per step fall from 7.4 to 4.5 and the
     LU factorisations do not grow (CSV).
   - Best CPU to a tip error <= 1e-2: (a) 0.50-0.58 s at h = 1e-3, (b)
     0.70-0.89 s at 5e-4; <= 1e-3: (a) 1.17-1.23 s, (b) 1.14-1.15 s, both
     at 2.5e-4 (HHT-alpha -0.3 in (b): 1.03e-3, not reached).
   - Releases in case (b): a node that leaves the joint starts the outside
     segment of a new transition element (bending stiffness ~ L2^-3),
     which grows by U_A' h within the next step.  Released at a fixed 2
     delta = 2e-3 h_out past C, that segment grew up to 27 times its length
     at h = 2e-3 (U_A' up to 1.03 m/s), and h = 4e-3 and 2e-3 failed with
     every HHT-family integrator (VLBE_ENOCONV after 6 halvings, at t =
     0.032 s and 0.734 s).  ex_sbeam.h now releases a node only once it is
     h max(0, U_A') further out, so the segment at most doubles in that
     step; both steps run, and the errors at h <= 1e-3 are unchanged.
   - Trapezoidal Newmark (no damping of the high / multiplier modes) gets
     through only by sb_run's halvings: rejected attempts are about as many
     as accepted (sub)steps, e.g. (a) h = 4e-3: 16458 steps, 15833
     rejected, mean accepted step 1.5e-4 s.  It ends with a small error,
     and neither error nor cost depends much on h: `full` run, h = 4e-3 ..
     2.5e-4: (a) 4.3e-4, 4.3e-4, 4.3e-4, 6.2e-4, 1.6e-4 at 5.8-9.6 s; (b)
     2.0e-3, 7.3e-3, 7.4e-3, 2.0e-3, 5.9e-4 at 2.2-3.7 s.  Against
     HHT-alpha -0.05 at the same h: (a) 27 and 14 times the CPU at 4e-3
     and 1e-3 (7.6 s, 7.9 s), (b) 8 times at 1e-3 (4.0 s), falling to 2
     times at 2.5e-4 in the `full` run.  By default it runs at h = 4e-3 and
     1e-3 only (to keep the benchmark under a minute); `full` runs all five.

   CPU time: CLOCK_PROCESS_CPUTIME_ID around sb_run() (allocation, the
   static start -- ~0.01 s, printed --, integration, the observer storing
   the grid samples); median of 5 runs when the first takes under 0.05 s,
   of 3 under 0.2 s, else the single run (runs are deterministic: only the
   time varies).  Failed runs are timed to the failure (CSV), not charted; the
   legend of each series names its failed steps. */
#define _POSIX_C_SOURCE 199309L
#include "../scenes/ex_sbeam.h"
#include "../scenes/svgplot.h"
#include "bench_util.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define DNAN ((double)NAN)
#define GRID 4e-3        /* s, the comparison grid                          */
#define MAXGRID 1024     /* grid points (t_end <= 4 s)                       */
#define NH 5
#define H_REF 6.25e-5    /* s, reference step                                */
#define H_CHK 1.25e-4    /* s, 2 h_ref: accuracy of the reference            */
#define H_FULL 3.125e-5  /* s, h_ref / 2: the `full` check of the reference  */
#define NLVL 2

static const double g_h[NH] = {4e-3, 2e-3, 1e-3, 5e-4, 2.5e-4};
static const double g_lvl[NLVL] = {1e-2, 1e-3};

enum { I_HHT05 = 0, I_HHT3, I_GA, I_NM, NINT };
static const char *const g_int_name[NINT] = {"HHT-alpha -0.05", "HHT-alpha -0.3",
                                              "gen-alpha rho_inf 0.8", "Newmark trapezoidal"};
/* trapezoidal Newmark by default only at 4e-3 and 1e-3 (2-9 s per run) */
static const int g_nm_default[NH] = {1, 0, 1, 0, 0};

/* what the observer collects: tip y on the grid */
typedef struct wps_obs {
    double y[MAXGRID];
    int n;        /* grid points met so far                     */
    int bad;      /* a grid point missed or met twice           */
    double t_last;
    int events;   /* node crossings before the last accepted step */
    double x_out; /* x of the first node outside C at it [m]    */
} wps_obs;

typedef struct point {
    double h;
    int run;             /* 0: not run (cost), 1: run          */
    vlbe_status status;
    double t_reached;    /* last accepted time [s]             */
    double err;          /* NaN if failed or not run           */
    double cpu;          /* median CPU seconds per run         */
    int reps;
    int restarts, err_elem, callback_rc;
    vlbe_status elem_err;
    int after_crossing;  /* failed: the first step after a node crossing */
    double x_out, ua_dot; /* failed: first node outside C [m], U_A' [m/s] */
    vlbe_dae_stats st;   /* as summed by sb_run               */
} point;

typedef struct scene {
    char which;          /* 'a', 'b'                            */
    sb_cfg cfg;
    int ngrid;
    wps_obs ref, chk, fine; /* h_ref, 2 h_ref, h_ref / 2 (full)  */
    double ref_cpu, chk_cpu, ref_acc, ref_vs_fine, static_cpu;
    double diff_chain[3]; /* |y(h) - y(h/2)| / tip0 for h = 5e-4, 2.5e-4, 1.25e-4 */
    point p[NINT][NH];
    char name[NINT][96];
    double cpu[NINT][NH], err[NINT][NH]; /* chart columns: successful points */
    int npt[NINT];
} scene;

static sb_model g_model; /* one model for every run (large: static) */
static wps_obs g_run, g_rep, g_keep; /* samples: the measured run, repeats, HHT -0.05 at 5e-4 */

static void wps_observe(void *ctx, const sb_model *m, double t, const vlbe_real *q,
                        const vlbe_real *v)
{
    wps_obs *o = (wps_obs *)ctx;
    const double k = floor(t / GRID + 0.5);
    int i;
    (void)v;
    o->t_last = t;
    o->events = m->events;
    o->x_out = DNAN;
    for (i = 0; i < m->nn; ++i) {
        const double x = sb_x(m, q, i);
        if (x > 0.0 && !(x >= o->x_out)) o->x_out = x;
    }
    if (fabs(t - k * GRID) > 1e-9) return;
    if ((int)k != o->n || o->n >= MAXGRID) {
        o->bad = 1;
        return;
    }
    o->y[o->n++] = (double)q[m->n - 2];
}

static void cfg_for(const scene *sc, int integ, double h, sb_cfg *c)
{
    *c = sc->cfg;
    c->h = h;
    c->alpha = integ == I_HHT3 ? -0.3 : integ == I_NM ? 0.0 : -0.05;
    c->rho_inf = integ == I_GA ? 0.8 : 0.0;
}

/* One run; returns the CPU seconds, samples into *o, result into *out. */
static double run_once(const sb_cfg *c, wps_obs *o, sb_out *out)
{
    double c0, c1;
    memset(o, 0, sizeof *o);
    c0 = benchu_cpu_now();
    sb_run(&g_model, c, wps_observe, o, out);
    c1 = benchu_cpu_now();
    if (out->status == VLBE_OK && (o->bad || o->n < 1)) out->status = VLBE_EARG;
    return c1 - c0;
}

/* max_k |y - ref| / tip0 over the first n grid points of both */
static double max_err(const scene *sc, const wps_obs *a, const wps_obs *b)
{
    double e = 0.0;
    int k, n = a->n < b->n ? a->n : b->n;
    for (k = 0; k < n; ++k) {
        double d = fabs(a->y[k] - b->y[k]);
        if (d > e) e = d;
    }
    return e / sc->cfg.tip0;
}

/* A timed point: the first run gives the samples, then repeats while cheap. */
static void measure(scene *sc, int integ, double h, point *pt, wps_obs *o)
{
    sb_cfg c;
    sb_out out;
    double t[5];
    int k, reps;
    memset(pt, 0, sizeof *pt);
    pt->h = h;
    pt->run = 1;
    cfg_for(sc, integ, h, &c);
    t[0] = run_once(&c, o, &out);
    pt->status = out.status;
    pt->t_reached = o->t_last;
    pt->st = out.stats;
    pt->restarts = out.restarts;
    pt->callback_rc = out.stats.callback_rc;
    pt->err_elem = out.status == VLBE_OK ? -1 : g_model.beam.err_elem;
    pt->elem_err = out.status == VLBE_OK ? VLBE_OK : g_model.beam.err;
    pt->err = out.status == VLBE_OK && o->n == sc->ngrid ? max_err(sc, o, &sc->ref) : DNAN;
    if (out.status != VLBE_OK) {
        double g[3];
        sb_ua(&c, o->t_last, g);
        pt->after_crossing = g_model.events > o->events;
        pt->x_out = o->x_out;
        pt->ua_dot = g[1];
    }
    reps = t[0] < 0.05 ? 5 : t[0] < 0.2 ? 3 : 1;
    for (k = 1; k < reps; ++k) {
        sb_out tmp;
        t[k] = run_once(&c, &g_rep, &tmp);
    }
    qsort(t, (size_t)reps, sizeof t[0], benchu_cmp_double);
    pt->cpu = t[reps / 2];
    pt->reps = reps;
}

/* The reference of a scene and its check (full: also h_ref / 2). */
static int reference(scene *sc, int full)
{
    sb_cfg c;
    sb_out out;
    double t[5];
    int k;
    cfg_for(sc, I_HHT05, H_REF, &c);
    /* the fixed cost of a run: t_end = 0 is the static start and the
       integrator's init only */
    c.t_end = 0.0;
    for (k = 0; k < 5; ++k) t[k] = run_once(&c, &g_rep, &out);
    qsort(t, 5, sizeof t[0], benchu_cmp_double);
    sc->static_cpu = t[2];
    c.t_end = sc->cfg.t_end;
    sc->ngrid = (int)floor(c.t_end / GRID + 0.5) + 1;
    sc->ref_cpu = run_once(&c, &sc->ref, &out);
    if (out.status != VLBE_OK || sc->ref.n != sc->ngrid) {
        fprintf(stderr, "wp_sliding: reference of case (%c) failed: %s at t = %g\n", sc->which,
                vlbe_status_str(out.status), sc->ref.t_last);
        return -1;
    }
    c.h = H_CHK;
    sc->chk_cpu = run_once(&c, &sc->chk, &out);
    if (out.status != VLBE_OK || sc->chk.n != sc->ngrid) {
        fprintf(stderr, "wp_sliding: check run of case (%c) failed: %s at t = %g\n", sc->which,
                vlbe_status_str(out.status), sc->chk.t_last);
        return -1;
    }
    sc->diff_chain[2] = max_err(sc, &sc->chk, &sc->ref);
    sc->ref_acc = sc->diff_chain[2] / 3.0; /* second order: e(h_ref) ~ |y(2h) - y(h)| / 3 */
    sc->ref_vs_fine = DNAN;
    if (full) {
        c.h = H_FULL;
        run_once(&c, &sc->fine, &out);
        if (out.status == VLBE_OK && sc->fine.n == sc->ngrid)
            sc->ref_vs_fine = max_err(sc, &sc->ref, &sc->fine);
    }
    return 0;
}

static void sweep(scene *sc, int full)
{
    int i, h;
    for (i = 0; i < NINT; ++i)
        for (h = 0; h < NH; ++h) {
            point *pt = &sc->p[i][h];
            wps_obs *o = &g_run;
            if (i == I_NM && !full && !g_nm_default[h]) {
                memset(pt, 0, sizeof *pt);
                pt->h = g_h[h];
                pt->err = pt->cpu = DNAN;
                continue;
            }
            measure(sc, i, g_h[h], pt, o);
            if (i == I_HHT05 && h == NH - 2) g_keep = *o; /* 5e-4 */
            if (i == I_HHT05 && h == NH - 1 && pt->status == VLBE_OK) {
                /* the chain of halvings 5e-4 -> 2.5e-4 -> 1.25e-4 (-> 6.25e-5) */
                sc->diff_chain[0] = max_err(sc, &g_keep, o);
                sc->diff_chain[1] = max_err(sc, o, &sc->chk);
            }
            fflush(stdout);
        }
}

/* chart columns (the successful points, largest h first: a failure or a
   step not run leaves no gap) and legend names, which list the failures */
static void columns(scene *sc)
{
    int i, h;
    for (i = 0; i < NINT; ++i) {
        char fail[64] = "", ran[64] = "";
        size_t lf = 0, lr = 0;
        int skipped = 0;
        sc->npt[i] = 0;
        for (h = 0; h < NH; ++h) {
            const point *p = &sc->p[i][h];
            const int ok = p->run && p->status == VLBE_OK && p->err >= 0.0;
            if (ok) {
                sc->cpu[i][sc->npt[i]] = p->cpu;
                sc->err[i][sc->npt[i]] = p->err;
                ++sc->npt[i];
            }
            if (!p->run) skipped = 1;
            if (p->run && !ok && lf < sizeof fail - 12)
                lf += (size_t)snprintf(fail + lf, sizeof fail - lf, "%s%g", lf ? ", " : "", p->h);
            if (p->run && lr < sizeof ran - 12)
                lr += (size_t)snprintf(ran + lr, sizeof ran - lr, "%s%g", lr ? ", " : "", p->h);
        }
        snprintf(sc->name[i], sizeof sc->name[i], "%s%s%s%s%s%s%s", g_int_name[i],
                 lf ? " (failed: h = " : "", fail, lf ? ")" : "", skipped ? " (h = " : "",
                 skipped ? ran : "", skipped ? " only)" : "");
    }
}

static void chart(scene *sc, const char *dir)
{
    static char title[2][200];
    char path[512];
    svgp_chart c;
    int i, k = sc->which == 'a' ? 0 : 1;
    snprintf(title[k], sizeof title[k],
             "Sliding beam (%c): %s, %d el., t in [0, %g] s; h = %g (left) .. %g s", sc->which,
             sc->which == 'a' ? "retraction" : "deployment", sc->cfg.n_in + sc->cfg.n_out,
             sc->cfg.t_end, g_h[0], g_h[NH - 1]);
    svgp_init(&c, title[k], "CPU time per run [s] (sb_run: static start + integration; " VLBE_BENCH_FLAGS ")",
              "max |tip y - y_ref| / 0.024 [-]", 1, 1);
    for (i = 0; i < NINT; ++i) svgp_series(&c, sc->name[i], sc->npt[i], sc->cpu[i], sc->err[i], SVGP_MARKERS);
    svgp_fit_legend_log(&c, 8, 3);
    snprintf(path, sizeof path, "%s/wp_sliding_%c.svg", dir, sc->which);
    if (svgp_write_file(&c, path) != 0) fprintf(stderr, "wp_sliding: cannot write %s\n", path);
}

static void write_csv(const scene *const *scs, int nsc, const char *dir)
{
    char path[512];
    FILE *f;
    int s, i, h;
    snprintf(path, sizeof path, "%s/wp_sliding.csv", dir);
    f = svgp_csv_open(path, "case,integrator,h_s,status,t_reached_s,tip_rel_error,ref_accuracy,cpu_s,"
                            "reps,steps,rejected,newton_iters,lu_factors,force_calls,restarts,"
                            "callback_rc,failing_element,element_status,first_step_after_crossing,"
                            "x_first_node_outside_m,UA_dot_m_s");
    if (!f) {
        fprintf(stderr, "wp_sliding: cannot write %s\n", path);
        return;
    }
    for (s = 0; s < nsc; ++s)
        for (i = 0; i < NINT; ++i)
            for (h = 0; h < NH; ++h) {
                const point *p = &scs[s]->p[i][h];
                if (!p->run) {
                    fprintf(f, "%c,\"%s\",%g,\"not run (cost; `full` runs it)\",,,,,,,,,,,,,,,,,\n",
                            scs[s]->which, g_int_name[i], p->h);
                    continue;
                }
                fprintf(f, "%c,\"%s\",%g,\"%s\",%.6g,%.6e,%.3e,%.6e,%d,%ld,%ld,%ld,%ld,%ld,%d,%d,%d,\"%s\","
                        "%d,%.6g,%.6g\n",
                        scs[s]->which, g_int_name[i], p->h, vlbe_status_str(p->status), p->t_reached,
                        p->err, scs[s]->ref_acc, p->cpu, p->reps, p->st.steps, p->st.rejected,
                        p->st.newton_iters, p->st.lu_factors, p->st.force_calls, p->restarts,
                        p->callback_rc, p->err_elem, vlbe_status_str(p->elem_err),
                        p->after_crossing, p->status == VLBE_OK ? DNAN : p->x_out,
                        p->status == VLBE_OK ? DNAN : p->ua_dot);
            }
    if (fclose(f) != 0) fprintf(stderr, "wp_sliding: cannot write %s\n", path);
}

/* the table of one case: error / CPU per integrator and step, then steps */
static void table(const scene *sc)
{
    int i, h;
    printf("\ncase (%c): max |tip y - y_ref| / 0.024, CPU s per run (steps, rejected)\n", sc->which);
    printf("%-22s", "integrator \\ h [s]");
    for (h = 0; h < NH; ++h) printf(" %22g", g_h[h]);
    printf("\n");
    for (i = 0; i < NINT; ++i) {
        printf("%-22s", g_int_name[i]);
        for (h = 0; h < NH; ++h) {
            const point *p = &sc->p[i][h];
            char cell[64];
            if (!p->run) snprintf(cell, sizeof cell, "not run");
            else if (p->status != VLBE_OK) snprintf(cell, sizeof cell, "failed after t=%.3f", p->t_reached);
            else snprintf(cell, sizeof cell, "%.2e %7.3fs", p->err, p->cpu);
            printf(" %22s", cell);
        }
        printf("\n%-22s", "");
        for (h = 0; h < NH; ++h) {
            const point *p = &sc->p[i][h];
            char cell[64] = "";
            if (p->run) snprintf(cell, sizeof cell, "(%ld, %ld)", p->st.steps, p->st.rejected);
            printf(" %22s", cell);
        }
        printf("\n");
    }
    for (i = 0; i < NINT; ++i)
        for (h = 0; h < NH; ++h) {
            const point *p = &sc->p[i][h];
            if (!p->run || p->status == VLBE_OK) continue;
            printf("  failed: %s, h = %g: %s after t = %.4f s, %s (node %.1e m outside C, "
                   "U_A' = %.3g m/s; last callback rc %d",
                   g_int_name[i], p->h, vlbe_status_str(p->status), p->t_reached,
                   p->after_crossing ? "the first step after a node crossing" : "not at a crossing",
                   p->x_out, p->ua_dot, p->callback_rc);
            if (p->err_elem >= 0) printf(", element %d: %s", p->err_elem, vlbe_status_str(p->elem_err));
            printf("; %.3f s CPU)\n", p->cpu);
        }
}

/* Cheapest point of integrator i whose error, and that of every finer
   point run, is at most lvl; -1 if none. */
static double best_cpu(const scene *sc, int i, double lvl, double *h_at)
{
    int h, j;
    for (h = 0; h < NH; ++h) {
        int ok = sc->p[i][h].run;
        for (j = h; j < NH && ok; ++j)
            if (sc->p[i][j].run && !(sc->p[i][j].err <= lvl)) ok = 0;
        if (ok) {
            *h_at = g_h[h];
            return sc->p[i][h].cpu;
        }
    }
    return -1.0;
}

static void summary(const scene *sc)
{
    int i, l;
    for (i = 0; i < NINT; ++i) {
        printf("(%c)  %-22s", sc->which, g_int_name[i]);
        for (l = 0; l < NLVL; ++l) {
            double hh = 0.0, c = best_cpu(sc, i, g_lvl[l], &hh);
            char cell[64];
            if (c < 0.0) snprintf(cell, sizeof cell, "not reached");
            else snprintf(cell, sizeof cell, "%7.3f s (h = %g)", c, hh);
            printf("  %-24s", cell);
        }
        printf("\n");
    }
}

int main(int argc, char **argv)
{
    static scene sa, sb;
    scene *scs[2];
    const char *dir = argc > 1 ? argv[1] : "out";
    const int full = argc > 2 && strcmp(argv[2], "full") == 0;
    double c0 = benchu_cpu_now(), mhz;
    char model[128];
    int s;

    if (benchu_mkdir(dir, "wp_sliding")) return 1;
    benchu_cpu_info(model, sizeof model, &mhz);
    printf("wp_sliding: work-precision of the sliding beam (Hsiao et al. section 3, "
           "scenes/ex_sbeam.h), vlbe %s, %s, compiler %s, %s, %s, %.0f MHz%s\n",
           VLBE_VERSION_STRING, sizeof(vlbe_real) == sizeof(double) ? "double" : "float",
           __VERSION__, VLBE_BENCH_FLAGS, model, mhz, full ? ", full" : "");
    scs[0] = &sa;
    scs[1] = &sb;
    sa.which = 'a';
    sb.which = 'b';
    for (s = 0; s < 2; ++s) {
        scene *sc = scs[s];
        sb_cfg_paper(&sc->cfg, sc->which);
        if (reference(sc, full) != 0) return 1;
        sweep(sc, full);
        columns(sc);
        chart(sc, dir);
    }
    write_csv((const scene *const *)scs, 2, dir);

    printf("reference: HHT-alpha -0.05 at h = %g s on the grid t_k = k * %g s; accuracy estimate "
           "|y(%g) - y(%g)| / 3 (second order)\n", H_REF, GRID, H_CHK, H_REF);
    for (s = 0; s < 2; ++s) {
        const scene *sc = scs[s];
        printf("  (%c) %d grid points, reference %.2f s CPU, accuracy ~%.1e; differences of "
               "successive halvings 5e-4..6.25e-5: %.2e %.2e %.2e (ratio %.2f %.2f); static start "
               "%.4f s",
               sc->which, sc->ngrid, sc->ref_cpu, sc->ref_acc, sc->diff_chain[0],
               sc->diff_chain[1], sc->diff_chain[2], sc->diff_chain[0] / sc->diff_chain[1],
               sc->diff_chain[1] / sc->diff_chain[2], sc->static_cpu);
        if (full) printf("; against h = %g: %.2e", H_FULL, sc->ref_vs_fine);
        printf("\n");
    }
    for (s = 0; s < 2; ++s) table(scs[s]);
    printf("\nbest CPU time per run to reach a relative tip error (that point and every finer one "
           "of its series at or below the level)\n");
    printf("%-27s  %-24s  %-24s\n", "case integrator", "<= 1e-2", "<= 1e-3");
    for (s = 0; s < 2; ++s) summary(scs[s]);
    printf("wrote %s/wp_sliding.csv, %s/wp_sliding_{a,b}.svg (%.1f s CPU)\n", dir, dir,
           benchu_cpu_now() - c0);
    return 0;
}
