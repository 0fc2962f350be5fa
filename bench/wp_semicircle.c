/* wp_semicircle.c -- work-precision of ale-rancf scene 6.3, the mass sliding
   down a hanging semicircular beam (examples/semicircle.c): error of the
   mass position at t = 1 s against CPU time (log-log) over elements x step,
   HHT-alpha -0.05, ALE-RANCF arc elements (eq. 43) and ALE-ANCF.

   build (from the repository root; `make demo` builds it with -O2, `make
   bench` with -O3 -march=native):
       cc -std=c99 -O2 -I. bench/wp_semicircle.c -o build/demo/wp_semicircle -lm
   run:  build/demo/wp_semicircle [outdir]              (default outdir: out)
   writes <outdir>/wp_semicircle.csv and <outdir>/wp_semicircle.svg.

   Runs: sc_run (scenes/semicircle.h, the model and loop of
   scenes/ex_slide.h) for 1 s with N = 4, 8, 16 elements x h = 2e-3,
   1e-3, 5e-4 s, both element forms.  CPU: the median of 3 runs (the whole
   run: integration and length control).
   Error of a run: the distance of the mass position at t = 1 s from that of
   the reference, the rational run with N = 32 and h = 2.5e-4 s (finer than
   every run of the sweep in both).  The same run in ALE-ANCF is printed
   beside it: the distance of the two references is the floor below which
   an error says nothing.  A run that stops before 1 s has no error (NaN,
   not drawn; its status is printed).  The error at t = 0.5 s is given too
   (CSV column err_half_m, <outdir>/wp_semicircle_half.svg): at t = 1 s the
   step alone moves the finest rational run by 0.12 m (h = 1e-3 against
   2.5e-4) -- the energy jumps of the length-control merges and their
   timing make the motion sensitive -- so t = 1 s measures little more than
   that sensitivity; t = 0.5 s, before most events, shows convergence. */
#define _POSIX_C_SOURCE 199309L
#include "../scenes/semicircle.h"
#include "../scenes/svgplot.h"
#include "bench_util.h"

#define WC_NNE 3
#define WC_NH 3
#define WC_REPS 3
#define WC_T 1.0

static const int wc_ne[WC_NNE] = {4, 8, 16};
static const double wc_h[WC_NH] = {2e-3, 1e-3, 5e-4};

/* one run to WC_T: the mass position there and the CPU time (median of
   reps); the status of the last run */
static vlbe_status wc_run(int N, int rational, double h, int reps, double *x, double *y,
                          double *x5, double *y5, double *cpu, ex_slide_out *o)
{
    double t[WC_REPS] = {0};
    int r;
    *x = *y = *x5 = *y5 = (double)NAN;
    if (reps < 1 || reps > WC_REPS) return VLBE_EARG;
    for (r = 0; r < reps; ++r) {
        ex_slide_cfg cfg;
        ex_slide_hist hi;
        sc_cfg(&cfg, N, rational, h);
        cfg.t_end = WC_T;
        *o = sc_run(&cfg, &hi);
        t[r] = o->cpu;
        if (o->status != VLBE_OK || sc_mass_at(&hi, WC_T, x, y) ||
            sc_mass_at(&hi, 0.5 * WC_T, x5, y5)) {
            ex_slide_hist_free(&hi);
            if (o->status == VLBE_OK) o->status = VLBE_EBOUND;
            *x = *y = *x5 = *y5 = (double)NAN;
            *cpu = o->cpu;
            return o->status;
        }
        ex_slide_hist_free(&hi);
    }
    qsort(t, (size_t)reps, sizeof t[0], benchu_cmp_double);
    *cpu = t[reps / 2];
    return VLBE_OK;
}

int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : "out";
    static const char *form[2] = {"ALE-ANCF", "rational"};
    static double cx[2][WC_NNE][WC_NH], ey[2][2][WC_NNE][WC_NH];
    static char names[2 * WC_NNE][64];
    char path[512], model[128];
    double mhz, c0 = benchu_cpu_now(), xr, yr, xa, ya, cr, ca, xr5, yr5, xa5, ya5;
    ex_slide_out o;
    svgp_chart chart;
    FILE *csv;
    int f, i, j, k;
    if (benchu_mkdir(dir, "wp_semicircle")) return 1;
    benchu_cpu_info(model, sizeof model, &mhz);
    printf("wp_semicircle: semicircle with a sliding 0.8 kg mass (ale-rancf 6.3), HHT-alpha -0.05,\n"
           "error = |mass position at t = %g s - reference| [m]; %s, %.0f MHz, %s\n", WC_T, model,
           mhz, VLBE_BENCH_FLAGS);
    if (wc_run(32, 1, 2.5e-4, 1, &xr, &yr, &xr5, &yr5, &cr, &o) != VLBE_OK) {
        fprintf(stderr, "wp_semicircle: reference run failed: %s\n", vlbe_status_str(o.status));
        return 1;
    }
    printf("reference: rational N = 32, h = 2.5e-4 s: mass at (%.6f, %.6f) m, %.2f s CPU\n", xr,
           yr, cr);
    if (wc_run(32, 0, 2.5e-4, 1, &xa, &ya, &xa5, &ya5, &ca, &o) == VLBE_OK)
        printf("           ALE-ANCF N = 32, h = 2.5e-4 s: (%.6f, %.6f) m, %.3e m from it (the "
               "floor; at t = %g s: %.3e m), %.2f s CPU\n", xa, ya, hypot(xa - xr, ya - yr),
               0.5 * WC_T, hypot(xa5 - xr5, ya5 - yr5), ca);
    else
        printf("           ALE-ANCF N = 32, h = 2.5e-4 s: %s\n", vlbe_status_str(o.status));
    snprintf(path, sizeof path, "%s/wp_semicircle.csv", dir);
    csv = svgp_csv_open(path, "rational,elements,h_s,cpu_s,err_m,mass_x_m,mass_y_m,steps,"
                              "newton,lc_events,status,err_half_m");
    printf("\n  form      elements  h [s]    CPU [s]   error [m]  (t = %g s)  Newton  events  "
           "status\n", 0.5 * WC_T);
    for (f = 1; f >= 0; --f)
        for (i = 0; i < WC_NNE; ++i)
            for (j = 0; j < WC_NH; ++j) {
                double x, y, x5, y5, c, e, e5;
                const vlbe_status st =
                    wc_run(wc_ne[i], f, wc_h[j], WC_REPS, &x, &y, &x5, &y5, &c, &o);
                e = st == VLBE_OK ? hypot(x - xr, y - yr) : (double)NAN;
                e5 = st == VLBE_OK ? hypot(x5 - xr5, y5 - yr5) : (double)NAN;
                cx[f][i][j] = st == VLBE_OK ? c : (double)NAN;
                ey[0][f][i][j] = e;
                ey[1][f][i][j] = e5;
                printf("  %-8s %8d  %.1e  %8.4f   %.3e  %.3e   %6ld  %6ld  %s", form[f],
                       wc_ne[i], wc_h[j], c, e, e5, o.newton, o.lc_events, vlbe_status_str(st));
                if (st != VLBE_OK) printf(" at t = %.4f s", o.t_stop);
                printf("\n");
                if (csv) {
                    const double row[12] = {(double)f, (double)wc_ne[i], wc_h[j], c, e, x, y,
                                            (double)o.steps, (double)o.newton,
                                            (double)o.lc_events, (double)st, e5};
                    svgp_csv_row(csv, 12, row);
                }
            }
    if (csv) fclose(csv);
    for (k = 0; k < 2; ++k) {
        svgp_init(&chart, k ? "semicircle, sliding mass (ale-rancf 6.3): error of the mass position "
                              "at t = 0.5 s vs CPU, h = 2e-3 / 1e-3 / 5e-4 s"
                            : "semicircle, sliding mass (ale-rancf 6.3): error of the mass position "
                              "at t = 1 s vs CPU, h = 2e-3 / 1e-3 / 5e-4 s",
                  "CPU time per run [s] (" VLBE_BENCH_FLAGS ")",
                  "|mass position - reference| [m]", 1, 1);
        for (f = 1; f >= 0; --f)
            for (i = 0; i < WC_NNE; ++i) {
                char *nm = names[f * WC_NNE + i];
                snprintf(nm, sizeof names[0], "%s, %d elements", form[f], wc_ne[i]);
                svgp_series(&chart, nm, WC_NH, cx[f][i], ey[k][f][i],
                            SVGP_MARKERS | (f ? 0 : SVGP_DASH));
            }
        svgp_fit_legend_log(&chart, 8, 3);
        snprintf(path, sizeof path, "%s/wp_semicircle%s.svg", dir, k ? "_half" : "");
        if (svgp_write_file(&chart, path)) fprintf(stderr, "wp_semicircle: cannot write %s\n", path);
    }
    printf("\nwp_semicircle: %.1f s CPU; wrote %s/wp_semicircle.csv, %s/wp_semicircle.svg, "
           "%s/wp_semicircle_half.svg\n", benchu_cpu_now() - c0, dir, dir, dir);
    return 0;
}
