/* sliding_xcheck.c -- cross-check of the sliding beam through a prismatic
   joint (Hsiao et al. section 3, cases (a) and (b); the co-rotational model
   of scenes/ex_sbeam.h, run with sb_run) by two models built otherwise:
   the planar ALE-ANCF chain of ancf_ale.h with the joint as constraints at
   a moving material point, and a linear variable-length assumed-modes
   model (Lagrange's equations of the axially moving cantilever).
   -- part of vlbe                                  SPDX-License-Identifier: MIT

   cc -O2 examples/sliding_xcheck.c -lm && ./a.out [outdir] [--undamped | --budget]

   The models, their assumptions and the derivation of the assumed-modes
   equations are in scenes/ex_xcheck.h.  The scene: sb_cfg_paper (A =
   4.3434e-5 m^2, I = 1.059e-11 m^4, E = 68.96 GPa, rho = 3144.3858 kg/m^3;
   (a) L = 0.762 m, L0 = 0.521 m, U_A = -0.03 t - 0.027 t^2, 2.5 s;
   (b) L = 1.05 m, L0 = 0.35 m, eq. (55) with c0 = 0.7 m, t0 = 1.2 s, 3 s),
   tip deflected statically by tip0 = 0.024 m at t = 0, modal damping of
   eq. (56) as the Rayleigh pair of ex_sbeam.h in all three models.

   Runs per case
     paper settings  co-rotational (CR) 14 + 10 elements, ALE-ANCF 10
                     elements, both HHT-alpha -0.05 at h = 1 ms; assumed
                     modes (AM) 4 modes, RK4 at 0.1 ms
     refined         CR and ALE at h = 0.25 ms, AM 6 modes at 0.05 ms
     convergence     each model against its own refinement: CR 21 + 15
                     elements at 0.25 ms (28 + 20 runs too, at twice the
                     CPU; its numbers in docs/results.md), ALE 20 elements at 1 ms, AM
                     3 and 6 modes and half the step
     nonlinearity    CR and ALE started at tip0 / 10 and scaled by 10: the
                     part of each nonlinear run that the linear AM cannot
                     have (geometric nonlinearity, second order in tip/L)
     damping         AM with the stiffness-proportional damping on the rate
                     of the curvature at fixed x / l instead of the material
                     rate (XC_AM_BETA_FIXED_XI), against the refined CR
     start (a)       ALE and AM started with the shape at rest in space
                     instead of the impulsive start of sb_run's v = 0
   --undamped: the three models without damping instead (CR and ALE at
   0.25 ms and 62.5 us, AM 6 modes): without damping the second mode
   keeps its share of the tip motion (2.5 % of tip0 from the static tip
   load), and HHT's phase error on it needs the small step.
   --budget: the error budget of the test configuration of
   tests/test_sliding_xcheck.c (0.3 s; CR 7 + 5 elements and ALE 10
   elements at h = 0.5 ms, AM 4 modes at 0.1 ms), which the test computes
   itself from the same runs (with the factors of its convergence
   arguments; these printed values are its regression pins): each model's
   step error (Richardson from h / 4), mesh error (CR 14 + 10, ALE 20
   elements), the modes left out (8 modes), the nonlinear part of CR and
   ALE (tip0 / 10 runs) and the effect of the damping convention (AM with
   XC_AM_BETA_FIXED_XI).

   Differences are of the tip deflection y(t) at the instants both runs
   hold (every 1 ms; two refined runs every 0.25 ms), as the largest |.|
   and the RMS over each 0.5 s window and over the run, in % of tip0.
   Output: the tables, ROW lines for `make demo` (no published value: the
   paper gives plots only), out/sliding_xcheck_{a,b}.csv (t and the tip of
   each model, paper settings and refined), out/sliding_xcheck_{a,b}.svg
   (the three curves) and out/sliding_xcheck_{a,b}_diff.svg (the
   differences against CR). */
#include "../scenes/ex_xcheck.h"
#include "../scenes/svgplot.h"

#include <stdio.h>

enum {
    R_CR, R_ALE, R_AM,       /* paper settings */
    R_CR4, R_ALE4, R_AM6,    /* refined        */
    R_CRM, R_ALEN, R_AM3, R_AMH,
    R_CRS, R_ALES,           /* tip0 / 10      */
    R_AMX,                   /* beta at fixed x/l */
    R_AMST, R_ALEST,         /* steady start   */
    R_N
};

typedef struct xs_run {
    const char *name;
    xc_hist h;
    double cpu;
    int ok, used;
} xs_run;

static double xs_pct(double d, double tip0) { return 100.0 * d / tip0; }

/* one line: max / rms (in % of tip0) of s b - a per 0.5 s window and the run */
static void xs_line(const char *label, const xs_run *a, const xs_run *b, double s, double t_end,
                    double tip0)
{
    double t0, mx, rm;
    printf("  %-34s", label);
    if (!a->ok || !b->ok) {
        printf(" (run failed)\n");
        return;
    }
    for (t0 = 0.0; t0 < t_end - 1e-9; t0 += 0.5) {
        xc_diff(&a->h, &b->h, s, t0, fmin(t0 + 0.5, t_end), &mx, &rm);
        printf(" %5.3f/%5.3f", xs_pct(mx, tip0), xs_pct(rm, tip0));
    }
    xc_diff(&a->h, &b->h, s, 0.0, t_end, &mx, &rm);
    printf(" | %5.3f/%5.3f\n", xs_pct(mx, tip0), xs_pct(rm, tip0));
}

static void xs_head(const char *what, double t_end)
{
    double t0;
    printf("  %-34s", what);
    for (t0 = 0.0; t0 < t_end - 1e-9; t0 += 0.5)
        printf("  %3.1f-%3.1f s   ", t0, fmin(t0 + 0.5, t_end));
    printf(" | whole run\n");
}

/* y of run r at t (NaN if the run failed or has no sample there) */
static double xs_y(const xs_run *r, double t) { return r->ok ? xc_hist_y(&r->h, t) : (double)NAN; }

static double xs_max(const xs_run *a, const xs_run *b, double t_end)
{
    double mx, rm;
    if (!a->ok || !b->ok) return (double)NAN;
    xc_diff(&a->h, &b->h, 1.0, 0.0, t_end, &mx, &rm);
    return mx;
}

static void xs_cr(xs_run *r, const char *name, const sb_cfg *c)
{
    vlbe_status st;
    r->name = name;
    r->used = 1;
    st = xc_cr_run(c, &r->h, &r->cpu);
    r->ok = st == VLBE_OK;
    if (!r->ok) printf("  %s: failed (%s) at t = %g s\n", name, vlbe_status_str(st),
                       r->h.n ? r->h.t[r->h.n - 1] : 0.0);
}

static void xs_ale(xs_run *r, const char *name, const sb_cfg *c, int N, int start)
{
    xc_ale_out o = xc_ale_run(c, N, start, &r->h);
    r->name = name;
    r->used = 1;
    r->cpu = o.cpu;
    r->ok = o.status == VLBE_OK;
    if (!r->ok) printf("  %s: failed (%s) at t = %g s\n", name, vlbe_status_str(o.status),
                       r->h.n ? r->h.t[r->h.n - 1] : 0.0);
}

/* AM run recorded every dt_out (a multiple of h) */
static void xs_am(xs_run *r, const char *name, const sb_cfg *c, int nm, double h, double dt_out,
                  int start, unsigned flags)
{
    xc_am_out o = xc_am_run(c, nm, h, (int)floor(dt_out / h + 0.5), start, flags, &r->h);
    r->name = name;
    r->used = 1;
    r->cpu = o.cpu;
    r->ok = o.status == 0;
    if (!r->ok) printf("  %s: failed (%d)\n", name, o.status);
}

static int xs_case(char which, const char *dir, int undamped)
{
    static xs_run run[R_N];
    static double dd[5][8001];
    sb_cfg c, cf;
    const double hp = 1e-3;
    int k, rc = 0, cap;
    char path[512], q[200];
    sb_cfg_paper(&c, which);
    if (undamped) c.damping = 0;
    cap = (int)(c.t_end / (hp / 16.0)) + 8;
    for (k = 0; k < R_N; ++k) {
        memset(&run[k], 0, sizeof run[k]);
        if (xc_hist_alloc(&run[k].h, cap)) return 1;
    }
    printf("== case (%c): L = %g m, L0 = %g m, %s, %g s, tip0 = %g m, %s\n", which, c.L, c.L0,
           c.motion ? "deployment (eq. 55)" : "retraction (eq. 54)", c.t_end, c.tip0,
           undamped ? "undamped" : "damping of eq. (56)");
    if (!undamped) {
        xs_cr(&run[R_CR], "CR 14+10, h = 1 ms", &c);
        xs_ale(&run[R_ALE], "ALE 10 el., h = 1 ms", &c, 10, XC_START_IMPULSE);
        xs_am(&run[R_AM], "AM 4 modes, h = 0.1 ms", &c, 4, 1e-4, hp, XC_START_IMPULSE, 0u);
    }
    cf = c;
    cf.h = hp / 4.0;
    xs_cr(&run[R_CR4], "CR 14+10, h = 0.25 ms", &cf);
    xs_ale(&run[R_ALE4], "ALE 10 el., h = 0.25 ms", &cf, 10, XC_START_IMPULSE);
    xs_am(&run[R_AM6], "AM 6 modes, h = 0.05 ms", &c, 6, 5e-5, hp / 4.0, XC_START_IMPULSE, 0u);
    if (undamped) {
        cf.h = hp / 16.0;
        xs_cr(&run[R_CR], "CR 14+10, h = 62.5 us", &cf);
        xs_ale(&run[R_ALE], "ALE 10 el., h = 62.5 us", &cf, 10, XC_START_IMPULSE);
        printf("  differences, undamped, max/RMS in %% of tip0 per window:\n");
        xs_head("", c.t_end);
        xs_line("AM6 - CR, h = 0.25 ms", &run[R_CR4], &run[R_AM6], 1.0, c.t_end, c.tip0);
        xs_line("ALE - CR, h = 0.25 ms", &run[R_CR4], &run[R_ALE4], 1.0, c.t_end, c.tip0);
        xs_line("ALE - AM6, h = 0.25 ms", &run[R_ALE4], &run[R_AM6], 1.0, c.t_end, c.tip0);
        xs_line("AM6 - CR, h = 62.5 us", &run[R_CR], &run[R_AM6], 1.0, c.t_end, c.tip0);
        xs_line("ALE - CR, h = 62.5 us", &run[R_CR], &run[R_ALE], 1.0, c.t_end, c.tip0);
        xs_line("ALE - AM6, h = 62.5 us", &run[R_ALE], &run[R_AM6], 1.0, c.t_end, c.tip0);
        printf("  cpu [s]: CR %.2f / %.2f, ALE %.2f / %.2f (h = 0.25 ms / 62.5 us), AM6 %.3f\n",
               run[R_CR4].cpu, run[R_CR].cpu, run[R_ALE4].cpu, run[R_ALE].cpu, run[R_AM6].cpu);
        rc = !(run[R_CR].ok && run[R_ALE].ok && run[R_AM6].ok && run[R_CR4].ok && run[R_ALE4].ok);
        goto done;
    }
    cf = c;
    cf.h = hp / 4.0;
    cf.n_in = 21; /* 28 + 20 runs too, at twice the CPU (docs/results.md) */
    cf.n_out = 15;
    xs_cr(&run[R_CRM], "CR 21+15, h = 0.25 ms", &cf);
    xs_ale(&run[R_ALEN], "ALE 20 el., h = 1 ms", &c, 20, XC_START_IMPULSE);
    xs_am(&run[R_AM3], "AM 3 modes, h = 0.1 ms", &c, 3, 1e-4, hp, XC_START_IMPULSE, 0u);
    xs_am(&run[R_AMH], "AM 4 modes, h = 0.05 ms", &c, 4, 5e-5, hp, XC_START_IMPULSE, 0u);
    cf = c;
    cf.tip0 = c.tip0 / 10.0;
    xs_cr(&run[R_CRS], "CR at tip0/10", &cf);
    xs_ale(&run[R_ALES], "ALE at tip0/10", &cf, 10, XC_START_IMPULSE);
    xs_am(&run[R_AMX], "AM 6, beta at fixed x/l", &c, 6, 5e-5, hp / 4.0, XC_START_IMPULSE,
          XC_AM_BETA_FIXED_XI);
    if (which == 'a') {
        xs_am(&run[R_AMST], "AM 4, steady start", &c, 4, 1e-4, hp, XC_START_STEADY, 0u);
        xs_ale(&run[R_ALEST], "ALE 10, steady start", &c, 10, XC_START_STEADY);
    }

    printf("  model differences of the tip deflection, max/RMS in %% of tip0 per window:\n");
    xs_head("", c.t_end);
    xs_line("AM - CR    (paper settings)", &run[R_CR], &run[R_AM], 1.0, c.t_end, c.tip0);
    xs_line("ALE - CR   (paper settings)", &run[R_CR], &run[R_ALE], 1.0, c.t_end, c.tip0);
    xs_line("ALE - AM   (paper settings)", &run[R_ALE], &run[R_AM], 1.0, c.t_end, c.tip0);
    xs_line("AM6 - CR   (refined)", &run[R_CR4], &run[R_AM6], 1.0, c.t_end, c.tip0);
    xs_line("ALE - CR   (refined)", &run[R_CR4], &run[R_ALE4], 1.0, c.t_end, c.tip0);
    xs_line("ALE - AM6  (refined)", &run[R_ALE4], &run[R_AM6], 1.0, c.t_end, c.tip0);
    printf("  each model against its refinement:\n");
    xs_line("CR  step: 1 ms -> 0.25 ms", &run[R_CR], &run[R_CR4], 1.0, c.t_end, c.tip0);
    xs_line("CR  mesh: 14+10 -> 21+15 (0.25 ms)", &run[R_CR4], &run[R_CRM], 1.0, c.t_end, c.tip0);
    xs_line("ALE step: 1 ms -> 0.25 ms", &run[R_ALE], &run[R_ALE4], 1.0, c.t_end, c.tip0);
    xs_line("ALE mesh: 10 -> 20 el. (1 ms)", &run[R_ALE], &run[R_ALEN], 1.0, c.t_end, c.tip0);
    xs_line("AM  modes: 4 -> 6 (0.05 ms)", &run[R_AMH], &run[R_AM6], 1.0, c.t_end, c.tip0);
    xs_line("AM  modes: 4 -> 3 (0.1 ms)", &run[R_AM], &run[R_AM3], 1.0, c.t_end, c.tip0);
    xs_line("AM  step: 0.1 -> 0.05 ms", &run[R_AM], &run[R_AMH], 1.0, c.t_end, c.tip0);
    printf("  geometric nonlinearity (run - 10 x run at tip0/10), damping, start:\n");
    xs_line("CR  nonlinear part", &run[R_CR], &run[R_CRS], 10.0, c.t_end, c.tip0);
    xs_line("ALE nonlinear part", &run[R_ALE], &run[R_ALES], 10.0, c.t_end, c.tip0);
    xs_line("(ALE - CR) at tip0/10, x 10", &run[R_CRS], &run[R_ALES], 1.0, c.t_end, c.tip0 / 10.0);
    xs_line("AM6(beta fixed x/l) - CR refined", &run[R_CR4], &run[R_AMX], 1.0, c.t_end, c.tip0);
    xs_line("AM6(beta fixed x/l) - AM6", &run[R_AM6], &run[R_AMX], 1.0, c.t_end, c.tip0);
    if (which == 'a') {
        xs_line("AM  steady - impulsive start", &run[R_AM], &run[R_AMST], 1.0, c.t_end, c.tip0);
        xs_line("ALE steady - impulsive start", &run[R_ALE], &run[R_ALEST], 1.0, c.t_end, c.tip0);
        xs_line("AM  steady start - CR", &run[R_CR], &run[R_AMST], 1.0, c.t_end, c.tip0);
    }
    printf("  cpu [s]:");
    for (k = 0; k < R_N; ++k)
        if (run[k].used) printf("%s %s %.3f", k ? "," : "", run[k].name, run[k].cpu);
    printf("\n");

    /* rows for make demo: largest differences over the run, in m */
    snprintf(q, sizeof q, "case %c: largest tip difference AM - CR [m], paper settings", which);
    svgp_compare_row(stdout, "sliding xcheck", q, NAN, xs_max(&run[R_CR], &run[R_AM], c.t_end),
                     NAN, run[R_CR].cpu + run[R_AM].cpu);
    snprintf(q, sizeof q, "case %c: largest tip difference ALE - CR [m], paper settings", which);
    svgp_compare_row(stdout, "sliding xcheck", q, NAN, xs_max(&run[R_CR], &run[R_ALE], c.t_end),
                     NAN, run[R_CR].cpu + run[R_ALE].cpu);
    snprintf(q, sizeof q, "case %c: largest tip difference ALE - AM [m], 0.25 ms, 6 modes",
             which);
    svgp_compare_row(stdout, "sliding xcheck", q, NAN, xs_max(&run[R_ALE4], &run[R_AM6], c.t_end),
                     NAN, run[R_ALE4].cpu + run[R_AM6].cpu);
    snprintf(q, sizeof q, "case %c: largest tip difference AM (beta fixed x/l) - CR [m], 0.25 ms",
             which);
    svgp_compare_row(stdout, "sliding xcheck", q, NAN, xs_max(&run[R_CR4], &run[R_AMX], c.t_end),
                     NAN, run[R_CR4].cpu + run[R_AMX].cpu);
    snprintf(q, sizeof q, "case %c: cpu, co-rotational 14+10, h = 1 ms [s]", which);
    svgp_compare_row(stdout, "sliding xcheck", q, NAN, run[R_CR].cpu, NAN, run[R_CR].cpu);
    snprintf(q, sizeof q, "case %c: cpu, ALE-ANCF 10 el., h = 1 ms [s]", which);
    svgp_compare_row(stdout, "sliding xcheck", q, NAN, run[R_ALE].cpu, NAN, run[R_ALE].cpu);
    snprintf(q, sizeof q, "case %c: cpu, assumed modes 4, RK4 0.1 ms [s]", which);
    svgp_compare_row(stdout, "sliding xcheck", q, NAN, run[R_AM].cpu, NAN, run[R_AM].cpu);

    /* CSV and charts (paper-settings grid: every millisecond) */
    if (run[R_CR].ok) {
        FILE *f;
        const xc_hist *g = &run[R_CR].h;
        static const int cols[6] = {R_CR, R_ALE, R_AM, R_CR4, R_ALE4, R_AM6};
        snprintf(path, sizeof path, "%s/sliding_xcheck_%c.csv", dir, which);
        f = svgp_csv_open(path, "t_s,cr_m,ale_m,am_m,cr_fine_m,ale_fine_m,am6_fine_m");
        if (f) {
            for (k = 0; k < g->n; ++k) {
                double row[7];
                int j;
                row[0] = g->t[k];
                for (j = 0; j < 6; ++j)
                    row[j + 1] = xs_y(&run[cols[j]], g->t[k]);
                svgp_csv_row(f, 7, row);
            }
            fclose(f);
        }
        if (g->n <= 8001) {
            svgp_chart ch, cd;
            for (k = 0; k < g->n; ++k) {
                dd[0][k] = xs_y(&run[R_ALE], g->t[k]) - g->y[k];
                dd[1][k] = xs_y(&run[R_AM], g->t[k]) - g->y[k];
                dd[2][k] = xs_y(&run[R_ALE4], g->t[k]) - xs_y(&run[R_CR4], g->t[k]);
                dd[3][k] = xs_y(&run[R_AM6], g->t[k]) - xs_y(&run[R_CR4], g->t[k]);
                dd[4][k] = xs_y(&run[R_AMX], g->t[k]) - xs_y(&run[R_CR4], g->t[k]);
            }
            snprintf(q, sizeof q, "sliding beam case (%c): tip deflection, three models", which);
            svgp_init(&ch, q, "t [s]", "tip deflection [m]", 0, 0);
            svgp_series(&ch, "co-rotational (ex_sbeam.h), 14+10 el., h = 1 ms", g->n, g->t, g->y,
                        0);
            if (run[R_ALE].ok)
                svgp_series(&ch, "ALE-ANCF, 10 el., h = 1 ms", run[R_ALE].h.n, run[R_ALE].h.t,
                            run[R_ALE].h.y, SVGP_DASH);
            if (run[R_AM].ok)
                svgp_series(&ch, "assumed modes (linear), 4 modes", run[R_AM].h.n, run[R_AM].h.t,
                            run[R_AM].h.y, SVGP_DOT);
            snprintf(path, sizeof path, "%s/sliding_xcheck_%c.svg", dir, which);
            if (svgp_write_file(&ch, path)) printf("  could not write %s\n", path);
            snprintf(q, sizeof q, "sliding beam case (%c): differences against co-rotational",
                     which);
            svgp_init(&cd, q, "t [s]", "tip deflection difference [m]", 0, 0);
            svgp_series(&cd, "ALE - CR, h = 1 ms", g->n, g->t, dd[0], 0);
            svgp_series(&cd, "AM - CR, h = 1 ms", g->n, g->t, dd[1], 0);
            svgp_series(&cd, "ALE - CR, h = 0.25 ms", g->n, g->t, dd[2], SVGP_DASH);
            svgp_series(&cd, "AM6 - CR, h = 0.25 ms", g->n, g->t, dd[3], SVGP_DASH);
            svgp_series(&cd, "AM6 (beta at fixed x/l) - CR, 0.25 ms", g->n, g->t, dd[4], SVGP_DOT);
            snprintf(path, sizeof path, "%s/sliding_xcheck_%c_diff.svg", dir, which);
            if (svgp_write_file(&cd, path)) printf("  could not write %s\n", path);
        }
    }
    for (k = 0; k < R_N; ++k)
        if (run[k].used && !run[k].ok) rc = 1;
done:
    for (k = 0; k < R_N; ++k) xc_hist_free(&run[k].h);
    return rc;
}

/* the budget of the test configuration (header comment) */
static int xs_budget(char which)
{
    const double T = 0.3, h = 5e-4;
    xs_run r[11];
    sb_cfg c, cf;
    int k, rc = 0;
    double e[7];
    sb_cfg_paper(&c, which);
    c.t_end = T;
    for (k = 0; k < 11; ++k) {
        memset(&r[k], 0, sizeof r[k]);
        if (xc_hist_alloc(&r[k].h, 4000)) return 1;
    }
    xs_am(&r[0], "AM 4", &c, 4, 1e-4, 5e-4, XC_START_IMPULSE, 0u);
    xs_am(&r[1], "AM 4 beta fixed x/l", &c, 4, 1e-4, 5e-4, XC_START_IMPULSE, XC_AM_BETA_FIXED_XI);
    xs_am(&r[2], "AM 8", &c, 8, 2.5e-5, 5e-4, XC_START_IMPULSE, 0u);
    cf = c;
    cf.h = h;
    cf.n_in = 7;
    cf.n_out = 5;
    xs_cr(&r[3], "CR 7+5", &cf);
    xs_ale(&r[4], "ALE 10", &cf, 10, XC_START_IMPULSE);
    cf.h = h / 4.0;
    xs_cr(&r[5], "CR 7+5, h/4", &cf);
    xs_ale(&r[6], "ALE 10, h/4", &cf, 10, XC_START_IMPULSE);
    cf = c;
    cf.h = h;
    xs_cr(&r[7], "CR 14+10", &cf);
    xs_ale(&r[8], "ALE 20", &cf, 20, XC_START_IMPULSE);
    cf.n_in = 7;
    cf.n_out = 5;
    cf.tip0 = c.tip0 / 10.0;
    xs_cr(&r[9], "CR 7+5 at tip0/10", &cf);
    xs_ale(&r[10], "ALE 10 at tip0/10", &cf, 10, XC_START_IMPULSE);
    e[0] = xs_max(&r[3], &r[5], T) * 16.0 / 15.0; /* HHT: second order */
    e[1] = xs_max(&r[4], &r[6], T) * 16.0 / 15.0;
    e[2] = xs_max(&r[3], &r[7], T);
    e[3] = xs_max(&r[4], &r[8], T);
    e[4] = xs_max(&r[0], &r[2], T);
    {
        double d, rm;
        xc_diff(&r[3].h, &r[9].h, 10.0, 0.0, T, &e[5], &rm);
        xc_diff(&r[4].h, &r[10].h, 10.0, 0.0, T, &e[6], &rm);
        printf("case (%c), 0-%.1f s, max |.| in %% of tip0:\n", which, T);
        printf("  step   CR %.4f  ALE %.4f   (|y(h) - y(h/4)| x 16/15, h = 0.5 ms)\n",
               xs_pct(e[0], c.tip0), xs_pct(e[1], c.tip0));
        printf("  mesh   CR %.4f  ALE %.4f   (7+5 vs 14+10; 10 vs 20 elements)\n",
               xs_pct(e[2], c.tip0), xs_pct(e[3], c.tip0));
        printf("  modes  AM %.4f               (4 vs 8 modes)\n", xs_pct(e[4], c.tip0));
        printf("  nonlinear part  CR %.4f  ALE %.4f\n", xs_pct(e[5], c.tip0),
               xs_pct(e[6], c.tip0));
        d = xs_max(&r[0], &r[1], T);
        printf("  damping convention (AM beta at fixed x/l vs material rate) %.4f\n",
               xs_pct(d, c.tip0));
        printf("  observed: AM - CR %.4f, ALE - CR %.4f, ALE - AM %.4f\n",
               xs_pct(xs_max(&r[3], &r[0], T), c.tip0), xs_pct(xs_max(&r[3], &r[4], T), c.tip0),
               xs_pct(xs_max(&r[4], &r[0], T), c.tip0));
    }
    for (k = 0; k < 11; ++k) {
        if (!r[k].ok) rc = 1;
        xc_hist_free(&r[k].h);
    }
    return rc;
}

int main(int argc, char **argv)
{
    const char *dir = "out";
    int i, undamped = 0, budget = 0, rc = 0;
    for (i = 1; i < argc; ++i) {
        if (!strcmp(argv[i], "--undamped")) undamped = 1;
        else if (!strcmp(argv[i], "--budget")) budget = 1;
        else dir = argv[i];
    }
    if (budget) return xs_budget('a') | xs_budget('b');
    printf("# sliding beam cross-check: co-rotational (sb_run of ex_sbeam.h) vs ALE-ANCF "
           "(ancf_ale.h) vs linear assumed modes; max/RMS of tip-deflection differences in %% of "
           "tip0 = 0.024 m\n");
    rc |= xs_case('a', dir, undamped);
    rc |= xs_case('b', dir, undamped);
    return rc;
}
