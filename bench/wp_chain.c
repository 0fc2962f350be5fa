/* wp_chain.c -- the clamped chain of scenes/clamped_chain.h: work-precision
   of HHT with dense and with banded iteration matrices, and the time per
   step against the number of elements (run by make demo)
   -- part of vlbe                                  SPDX-License-Identifier: MIT

   cc -O2 -I. bench/wp_chain.c -lm && ./a.out [outdir]

   Work-precision: 64 elements, t in [0, 0.2] s, HHT-alpha -0.05 with the
   default Newton settings, h = 4 ms ... 0.25 ms; the error is the distance
   of the free end at t = 0.2 s from a banded run at h = 1/32 ms (the
   scheme is second order: the error of the reference is 64^-2 of the
   finest point's).  Three runs per step size: dense, banded (the same
   Newton iterates: equal to rounding), and banded with
   vlbe_hht_params.reuse_max = 2 (a stale iteration matrix refreshed
   sooner: other iterates, within the Newton tolerance): the errors must
   match to far below the error itself.  Scale: the median time per step
   after 20 warm-up steps (bench_scale's measure), dense up to 256 and
   banded up to 1024 elements, with the least-squares slopes.
   Writes outdir/wp_chain.csv, wp_chain.svg, chain_scale.csv,
   chain_scale.svg (default outdir: out). */
#define _POSIX_C_SOURCE 199309L
#include "bench_chain.h"
#include "../scenes/svgplot.h"

#include <stdio.h>

enum { WP_NE = 64, WP_NH = 5 };
#define WP_TEND 0.2

/* the free end at WP_TEND with step h; cpu seconds, Newton iterations and
   LU factorizations of the run; 0 on success */
static int wp_run(int variant, double h, double tip[2], double *cpu, long *newton, long *lu)
{
    cc_scene *s = (cc_scene *)malloc(sizeof *s);
    long k, nk = (long)floor(WP_TEND / h + 0.5);
    double t0;
    int rc = -1;
    if (!s) return -1;
    if (cc_init(s, WP_NE, variant)) goto out;
    t0 = benchu_cpu_now();
    for (k = 0; k < nk; ++k)
        if (vlbe_hht_step(&s->st, (vlbe_real)h)) goto out;
    *cpu = benchu_cpu_now() - t0;
    tip[0] = (double)s->st.q[s->ch.n - 4];
    tip[1] = (double)s->st.q[s->ch.n - 3];
    *newton = s->st.stats.newton_iters;
    *lu = s->st.stats.lu_factors;
    rc = 0;
out:
    cc_free(s);
    free(s);
    return rc;
}

int main(int argc, char **argv)
{
    static const double H[WP_NH] = {4e-3, 2e-3, 1e-3, 5e-4, 2.5e-4};
    static const int NE[] = {16, 64, 256, 1024};
    static const char *const vname[3] = {"HHT, dense", "HHT, banded", "HHT, banded, reuse_max 2"};
    enum { NS = sizeof NE / sizeof NE[0] };
    const char *dir = argc > 1 ? argv[1] : "out";
    double ref[2], err[3][WP_NH], cpu[3][WP_NH], xd[NS], yd[NS], xb[NS], yb[NS], sd, sb;
    double worst[3] = {0.0, 0.0, 0.0};
    char path[512], ld[80], lb[80];
    svgp_chart ch;
    FILE *csv;
    int v, i, nd = 0, nb = 0;
    long nw, lu;
    double c;
    if (wp_run(CC_BAND, 1.0 / 32000.0, ref, &c, &nw, &lu)) {
        fprintf(stderr, "wp_chain: the reference run failed\n");
        return 1;
    }
    printf("# clamped chain, %d elements, HHT-alpha -0.05, t = %g s: error of the free end "
           "against h = 1/32 ms; dense, banded, banded with reuse_max 2 (%s)\n",
           WP_NE, WP_TEND, VLBE_BENCH_FLAGS);
    printf("# %8s | %10s %8s %6s %4s | %10s %8s %6s %4s %9s | %10s %8s %6s %4s %9s\n", "h [s]",
           "dense err", "cpu s", "newton", "LU", "banded err", "cpu s", "newton", "LU", "|b - d|",
           "reuse err", "cpu s", "newton", "LU", "|r - d|");
    snprintf(path, sizeof path, "%s/wp_chain.csv", dir);
    csv = svgp_csv_open(path, "h,dense_err,dense_cpu,band_err,band_cpu,reuse_err,reuse_cpu,"
                              "band_diff,reuse_diff");
    for (i = 0; i < WP_NH; ++i) {
        double tip[3][2], row[9], diff[3] = {0.0, 0.0, 0.0};
        long nwt[3], lut[3];
        for (v = 0; v < 3; ++v) {
            if (wp_run(v, H[i], tip[v], &cpu[v][i], &nwt[v], &lut[v])) {
                fprintf(stderr, "wp_chain: %s failed at h = %g\n", vname[v], H[i]);
                return 1;
            }
            err[v][i] = hypot(tip[v][0] - ref[0], tip[v][1] - ref[1]);
            diff[v] = hypot(tip[v][0] - tip[0][0], tip[v][1] - tip[0][1]);
            if (diff[v] / err[0][i] > worst[v]) worst[v] = diff[v] / err[0][i];
        }
        printf("  %8.2e | %10.3e %8.4f %6ld %4ld | %10.3e %8.4f %6ld %4ld %9.2e | %10.3e %8.4f %6ld "
               "%4ld %9.2e\n", H[i], err[0][i], cpu[0][i], nwt[0], lut[0], err[1][i], cpu[1][i],
               nwt[1], lut[1], diff[1], err[2][i], cpu[2][i], nwt[2], lut[2], diff[2]);
        row[0] = H[i];
        for (v = 0; v < 3; ++v) {
            row[1 + 2 * v] = err[v][i];
            row[2 + 2 * v] = cpu[v][i];
        }
        row[7] = diff[1];
        row[8] = diff[2];
        if (csv) svgp_csv_row(csv, 9, row);
    }
    if (csv) fclose(csv);
    printf("# largest difference from the dense run / its error: banded %.2e (rounding), with "
           "reuse_max 2 %.2e (the Newton tolerance)\n", worst[1], worst[2]);
    svgp_init(&ch, "clamped chain, 64 elements: work-precision", "CPU time [s]",
              "error of the free end [m]", 1, 1);
    for (v = 0; v < 3; ++v) svgp_series(&ch, vname[v], WP_NH, cpu[v], err[v], 0);
    snprintf(path, sizeof path, "%s/wp_chain.svg", dir);
    if (svgp_write_file(&ch, path)) printf("# could not write %s\n", path);

    printf("#\n# time per HHT step, h = 1 ms (median, after 20 warm-up steps)\n");
    printf("# %6s | %6s | %12s | %12s\n", "elem", "n", "dense us", "banded us");
    snprintf(path, sizeof path, "%s/chain_scale.csv", dir);
    csv = svgp_csv_open(path, "elements,dense_us,band_us");
    for (i = 0; i < NS; ++i) {
        cc_result rd, rb;
        double row[3];
        const int hd = NE[i] <= CC_DENSE_MAX;
        if ((hd && cc_time(NE[i], CC_DENSE, &rd)) || cc_time(NE[i], CC_BAND, &rb)) {
            fprintf(stderr, "wp_chain: timing failed at %d elements\n", NE[i]);
            return 1;
        }
        if (hd) {
            xd[nd] = NE[i];
            yd[nd++] = rd.us;
        }
        xb[nb] = NE[i];
        yb[nb++] = rb.us;
        printf("  %6d | %6d | %12.1f | %12.1f\n", NE[i], rb.n, hd ? rd.us : 0.0, rb.us);
        row[0] = NE[i];
        row[1] = hd ? rd.us : 0.0;
        row[2] = rb.us;
        if (csv) svgp_csv_row(csv, 3, row);
    }
    if (csv) fclose(csv);
    sd = cc_slope(nd - 1, xd + 1, yd + 1);
    sb = cc_slope(nb - 1, xb + 1, yb + 1);
    printf("# slopes (64 elements and up): dense %.2f, banded %.2f\n", sd, sb);
    snprintf(ld, sizeof ld, "dense (slope %.2f)", sd);
    snprintf(lb, sizeof lb, "banded (slope %.2f)", sb);
    svgp_init(&ch, "clamped chain: time per HHT step", "elements", "us per step", 1, 1);
    svgp_series(&ch, ld, nd, xd, yd, 0);
    svgp_series(&ch, lb, nb, xb, yb, 0);
    snprintf(path, sizeof path, "%s/chain_scale.svg", dir);
    if (svgp_write_file(&ch, path)) printf("# could not write %s\n", path);
    return 0;
}
