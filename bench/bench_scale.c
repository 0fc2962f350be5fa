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
#include "../ancf_ale.h"
#include "../integrators.h"
#include "../examples/ex_ale.h"
#include "bench_util.h"
#include "svgplot.h"

#include <stdio.h>
#include <stdlib.h>

enum { SC_NMAX = 1024, SC_WARM = 20, SC_BLOCKS = 5, SC_DENSE_MAX = 256 };

typedef struct scene {
    vlbe_ale_mat mat;
    vlbe_ale_elem el;
    vlbe_ale_node node[SC_NMAX + 1];
    vlbe_ale_con con[2];
    vlbe_ale_chain ch;
    int *order;
    vlbe_dae sys;
    vlbe_hht st;
    vlbe_real *w, *q0, *v0;
    int *iw;
    size_t lw, liw;
} scene;

typedef struct result {
    double us, newton, lu, mb;
    int kl, n;
} result;

static void scene_free(scene *s)
{
    free(s->w);
    free(s->iw);
    free(s->q0);
    free(s->v0);
    free(s->order);
}

/* builds the chain of ne elements, dense or banded, and starts HHT */
static int scene_init(scene *s, int ne, int band)
{
    vlbe_ale_con c;
    vlbe_hht_params par;
    vlbe_real r0[2] = {0, 0}, dir[2] = {1, 0};
    int i;
    memset(s, 0, sizeof *s);
    s->mat.rhoA = VLBE_R(7.85);
    s->mat.EA = VLBE_R(2.1e8);
    s->mat.EI = VLBE_R(1.75e3);
    s->mat.f[1] = VLBE_R(-9.81) * s->mat.rhoA;
    if (vlbe_ale_elem_init(&s->el, &s->mat, 0, 0, 0, 0)) return -1;
    for (i = 0; i <= ne; ++i) {
        s->node[i].pmode = VLBE_ALE_PFIXED;
        s->node[i].p = (vlbe_real)(10.0 * i / ne);
    }
    if (vlbe_ale_chain_init(&s->ch, &s->el, s->node, ne + 1, SC_NMAX + 1, s->con, 2)) return -1;
    memset(&c, 0, sizeof c);
    c.type = VLBE_ALE_CON_POS;
    c.node = 0;
    if (vlbe_ale_chain_add(&s->ch, &c)) return -1;
    c.type = VLBE_ALE_CON_SLOPE;
    c.v[0] = 1;
    if (vlbe_ale_chain_add(&s->ch, &c)) return -1;
    if (band) {
        int cap = 5 * (ne + 1) + 4;
        s->order = (int *)malloc((size_t)cap * sizeof *s->order);
        if (!s->order || vlbe_ale_chain_band(&s->ch, s->order, cap)) return -1;
    }
    if (vlbe_ale_chain_layout(&s->ch)) return -1;
    ex_ale_wire(&s->sys, &s->ch);
    s->lw = vlbe_hht_work_len_sys(&s->sys);
    s->liw = vlbe_hht_iwork_len_sys(&s->sys);
    s->w = (vlbe_real *)malloc(s->lw * sizeof *s->w);
    s->iw = (int *)malloc(s->liw * sizeof *s->iw);
    s->q0 = (vlbe_real *)calloc((size_t)s->ch.n, sizeof *s->q0);
    s->v0 = (vlbe_real *)calloc((size_t)s->ch.n, sizeof *s->v0);
    if (!s->w || !s->iw || !s->q0 || !s->v0) return -1;
    vlbe_ale_chain_straight(&s->ch, r0, dir, s->q0);
    if (vlbe_hht_params_hht(&par, VLBE_R(-0.05))) return -1;
    return vlbe_hht_init(&s->st, &s->sys, &par, 0, s->q0, s->v0, s->w, s->lw, s->iw, s->liw) ? -1
                                                                                            : 0;
}

static int run(int ne, int band, result *r)
{
    scene *s = (scene *)malloc(sizeof *s);
    double t[SC_BLOCKS];
    long it0, lu0, steps = 0;
    int b, k, ok = 0;
    if (!s) return -1;
    if (scene_init(s, ne, band)) goto out;
    for (k = 0; k < SC_WARM; ++k)
        if (vlbe_hht_step(&s->st, VLBE_R(1e-3))) goto out;
    it0 = s->st.stats.newton_iters;
    lu0 = s->st.stats.lu_factors;
    for (b = 0; b < SC_BLOCKS; ++b) {
        double t0 = benchu_now(), el;
        int nk = 0;
        do {
            for (k = 0; k < 10; ++k)
                if (vlbe_hht_step(&s->st, VLBE_R(1e-3))) goto out;
            nk += 10;
            el = benchu_now() - t0;
        } while (el < 0.2 / SC_BLOCKS && nk < 100000);
        t[b] = el / nk;
        steps += nk;
    }
    qsort(t, SC_BLOCKS, sizeof *t, benchu_cmp_double);
    r->us = 1e6 * t[SC_BLOCKS / 2];
    r->newton = (double)(s->st.stats.newton_iters - it0) / (double)steps;
    r->lu = (double)(s->st.stats.lu_factors - lu0) / (double)steps;
    r->mb = ((double)s->lw * sizeof(vlbe_real) + (double)s->liw * sizeof(int) +
             (band ? (double)(5 * (ne + 1) + 4) * sizeof(int) : 0.0)) / 1048576.0;
    r->kl = band ? s->ch.kl : -1;
    r->n = s->ch.n;
    ok = 1;
out:
    scene_free(s);
    free(s);
    return ok ? 0 : -1;
}

/* least-squares slope of log y against log x */
static double fit_slope(int n, const double *x, const double *y)
{
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    int i;
    for (i = 0; i < n; ++i) {
        double a = log(x[i]), b = log(y[i]);
        sx += a;
        sy += b;
        sxx += a * a;
        sxy += a * b;
    }
    return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

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
        result d, b;
        int ne = NE[i], hd = ne <= SC_DENSE_MAX;
        memset(&d, 0, sizeof d);
        if (hd && run(ne, 0, &d)) {
            fprintf(stderr, "bench_scale: dense run failed at %d elements\n", ne);
            return 1;
        }
        if (run(ne, 1, &b)) {
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
    slope_b = fit_slope(nf, fitx, fity);
    slope_d = fit_slope(nd > 2 ? nd - 2 : nd, xd + (nd > 2 ? 2 : 0), yd + (nd > 2 ? 2 : 0));
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
