/* bench_scale.c -- time per step of a long clamped chain against its number
   of elements, dense and banded iteration matrices -- part of vlbe
                                                   SPDX-License-Identifier: MIT
   make bench-scale   (or: cc -O2 -I. bench/bench_scale.c -lm && ./a.out [outdir])

   The chain: planar ALE-ANCF, Lagrangian nodes (every p fixed), total
   length 10 m, steel-like section (rhoA 7.85 kg/m, EA 2.1e8 N, EI 1.75e3
   N m^2), gravity through the distributed load, clamped at node 0
   (VLBE_ALE_CON_POS + VLBE_ALE_CON_SLOPE), starting straight and at rest;
   HHT-alpha -0.05 with the default Newton settings, h = 1 ms.  After 20
   warm-up steps, the time of the next steps is measured (at least 0.2 s
   of them, at least 20 steps), median of 5 such blocks; Newton
   iterations and LU factorizations per step are counted over them.
   Dense above 256 elements is left out (its O(n^3) factorizations take
   seconds per step).  Workspace: the real and int workspaces of the
   integrator (vlbe_hht_work_len_sys, vlbe_hht_iwork_len_sys) plus the
   chain's order[] in the banded case.
   Writes bench_scale.csv and bench_scale.svg (log-log, time per step
   against elements, with the fitted slopes) to the output directory
   (default out/bench), and ends with the line
     chain scale: slope S (64-1024 el.), T us/step at 256 el., W MB at 1024 el. */
#define _POSIX_C_SOURCE 199309L
#include "bench_util.h"
#include "clamped_chain.h"
#include "svgplot.h"

#include <stdio.h>
#include <stdlib.h>

int main(int argc, char **argv)
{
    static const int NE[] = {4, 16, 64, 128, 256, 512, 1024};
    enum { NS = sizeof NE / sizeof NE[0] };
    double xd[NS], yd[NS], xb[NS], yb[NS], fitx[NS], fity[NS], slope_b, slope_d, us256 = 0,
                                                                                 mb1024 = 0;
    const char *dir = argc > 1 ? argv[1] : "out/bench";
    char model[128], path[512], ld[64], lb[64];
    double mhz;
    int i, nd = 0, nb = 0, nf = 0;
    FILE *csv;
    svgp_chart ch;
    benchu_cpu_info(model, sizeof model, &mhz);
    printf("chain scale: clamped planar ALE-ANCF chain, 10 m, HHT -0.05, h = 1 ms\n");
    printf("machine: %s (%.0f MHz), %s\n", model, mhz, VLBE_BENCH_FLAGS);
    printf("%6s %6s %4s | %11s %7s %6s %9s | %11s %7s %6s %9s\n", "elem", "n", "kl",
           "dense us", "newton", "lu", "MB", "banded us", "newton", "lu", "MB");
    snprintf(path, sizeof path, "%s/bench_scale.csv", dir);
    csv = svgp_csv_open(path, "elements,n,dense_us,dense_newton,dense_lu,dense_mb,band_us,"
                              "band_newton,band_lu,band_mb,kl");
    for (i = 0; i < NS; ++i) {
        cc_result d, b;
        int ne = NE[i], hd = ne <= CC_DENSE_MAX;
        memset(&d, 0, sizeof d);
        if (hd && cc_time(ne, 0, &d)) {
            fprintf(stderr, "bench_scale: dense run failed at %d elements\n", ne);
            return 1;
        }
        if (cc_time(ne, 1, &b)) {
            fprintf(stderr, "bench_scale: banded run failed at %d elements\n", ne);
            return 1;
        }
        if (hd) {
            printf("%6d %6d %4d | %11.1f %7.2f %6.3f %9.2f | %11.1f %7.2f %6.3f %9.3f\n", ne, b.n,
                   b.kl, d.us, d.newton, d.lu, d.mb, b.us, b.newton,
                   b.lu, b.mb);
            xd[nd] = ne;
            yd[nd++] = d.us;
        } else {
            printf("%6d %6d %4d | %11s %7s %6s %9s | %11.1f %7.2f %6.3f %9.3f\n", ne, b.n,
                   b.kl, "-", "-", "-", "-", b.us, b.newton, b.lu,
                   b.mb);
        }
        xb[nb] = ne;
        yb[nb++] = b.us;
        if (ne >= 64) {
            fitx[nf] = ne;
            fity[nf++] = b.us;
        }
        if (ne == 256) us256 = b.us;
        if (ne == 1024) mb1024 = b.mb;
        if (csv) {
            double row[11];
            row[0] = ne;
            row[1] = b.n;
            row[2] = hd ? d.us : (double)NAN;
            row[3] = hd ? d.newton : (double)NAN;
            row[4] = hd ? d.lu : (double)NAN;
            row[5] = hd ? d.mb : (double)NAN;
            row[6] = b.us;
            row[7] = b.newton;
            row[8] = b.lu;
            row[9] = b.mb;
            row[10] = b.kl;
            svgp_csv_row(csv, 11, row);
        }
        fflush(stdout);
    }
    if (csv) fclose(csv);
    slope_b = cc_slope(nf, fitx, fity);
    slope_d = cc_slope(nd > 2 ? nd - 2 : nd, xd + (nd > 2 ? 2 : 0), yd + (nd > 2 ? 2 : 0));
    snprintf(ld, sizeof ld, "dense (slope %.2f, 64-256)", slope_d);
    snprintf(lb, sizeof lb, "banded (slope %.2f, 64-1024)", slope_b);
    svgp_init(&ch, "clamped chain: time per HHT step", "elements", "us per step", 1, 1);
    svgp_series(&ch, ld, nd, xd, yd, 0);
    svgp_series(&ch, lb, nb, xb, yb, 0);
    snprintf(path, sizeof path, "%s/bench_scale.svg", dir);
    svgp_write_file(&ch, path);
    printf("chain scale: slope %.2f (64-1024 el.), %.0f us/step at 256 el., %.2f MB at 1024 el.\n",
           slope_b, us256, mb1024);
    return 0;
}
