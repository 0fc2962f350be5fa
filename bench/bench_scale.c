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
#include "bench_chain.h"
#include "../scenes/svgplot.h"

#include <stdio.h>
#include <stdlib.h>

int main(int argc, char **argv)
{
    static const int NE[] = {4, 16, 64, 128, 256, 512, 1024};
    enum { NS = sizeof NE / sizeof NE[0] };
    double x[3][NS], y[3][NS], slope[3], us256[3] = {0, 0, 0}, mb1024 = 0;
    const char *dir = argc > 1 ? argv[1] : "out/bench";
    static const char *const vname[3] = {"dense", "banded", "banded, reuse_max 2"};
    char model[128], path[512], lab[3][80];
    double mhz;
    int i, v, np[3] = {0, 0, 0};
    FILE *csv;
    svgp_chart ch;
    benchu_cpu_info(model, sizeof model, &mhz);
    printf("chain scale: clamped planar ALE-ANCF chain, 10 m, HHT -0.05, h = 1 ms\n");
    printf("machine: %s (%.0f MHz), %s\n", model, mhz, VLBE_BENCH_FLAGS);
    printf("%5s %5s %3s | %9s %6s %5s %7s | %9s %6s %5s %7s | %9s %6s %5s\n", "elem", "n", "kl",
           "dense us", "newton", "lu", "MB", "banded us", "newton", "lu", "MB", "reuse2 us",
           "newton", "lu");
    snprintf(path, sizeof path, "%s/bench_scale.csv", dir);
    csv = svgp_csv_open(path, "elements,n,kl,dense_us,dense_newton,dense_lu,dense_mb,band_us,"
                              "band_newton,band_lu,band_mb,reuse_us,reuse_newton,reuse_lu");
    for (i = 0; i < NS; ++i) {
        cc_result r[3];
        double row[14];
        const int ne = NE[i];
        memset(r, 0, sizeof r);
        for (v = 0; v < 3; ++v) {
            if (v == CC_DENSE && ne > CC_DENSE_MAX) continue;
            if (cc_time(ne, v, &r[v])) {
                fprintf(stderr, "bench_scale: %s run failed at %d elements\n", vname[v], ne);
                return 1;
            }
            x[v][np[v]] = ne;
            y[v][np[v]++] = r[v].us;
            if (ne == 256) us256[v] = r[v].us;
        }
        if (ne == 1024) mb1024 = r[CC_BAND].mb;
        if (ne <= CC_DENSE_MAX)
            printf("%5d %5d %3d | %9.1f %6.2f %5.3f %7.2f |", ne, r[1].n, r[1].kl, r[0].us,
                   r[0].newton, r[0].lu, r[0].mb);
        else
            printf("%5d %5d %3d | %9s %6s %5s %7s |", ne, r[1].n, r[1].kl, "-", "-", "-", "-");
        printf(" %9.1f %6.2f %5.3f %7.3f | %9.1f %6.2f %5.3f\n", r[1].us, r[1].newton, r[1].lu,
               r[1].mb, r[2].us, r[2].newton, r[2].lu);
        row[0] = ne;
        row[1] = r[1].n;
        row[2] = r[1].kl;
        for (v = 0; v < 3; ++v) {
            const int have = v != CC_DENSE || ne <= CC_DENSE_MAX;
            row[3 + 4 * v] = have ? r[v].us : (double)NAN;
            row[4 + 4 * v] = have ? r[v].newton : (double)NAN;
            row[5 + 4 * v] = have ? r[v].lu : (double)NAN;
            if (v < 2) row[6 + 4 * v] = have ? r[v].mb : (double)NAN;
        }
        if (csv) svgp_csv_row(csv, 14, row);
        fflush(stdout);
    }
    if (csv) fclose(csv);
    /* slopes from 64 elements on (the first two sizes are below the
       asymptotic regime: the integrator's fixed cost) */
    for (v = 0; v < 3; ++v) {
        slope[v] = cc_slope(np[v] - 2, x[v] + 2, y[v] + 2);
        snprintf(lab[v], sizeof lab[v], "%s (slope %.2f)", vname[v], slope[v]);
    }
    svgp_init(&ch, "clamped chain: time per HHT step", "elements", "us per step", 1, 1);
    for (v = 0; v < 3; ++v) svgp_series(&ch, lab[v], np[v], x[v], y[v], 0);
    snprintf(path, sizeof path, "%s/bench_scale.svg", dir);
    svgp_write_file(&ch, path);
    printf("banded, reuse_max 2: slope %.2f, %.0f us/step at 256 el.\n", slope[2], us256[2]);
    printf("chain scale: slope %.2f (64-1024 el.), %.0f us/step at 256 el., %.2f MB at 1024 el.\n",
           slope[1], us256[1], mb1024);
    return 0;
}
