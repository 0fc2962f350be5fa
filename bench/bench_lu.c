/* bench_lu.c -- speed of the dense LU of vlbe.h: vlbe_lu_factor (+ vlbe_lu_solve)
   for n = 10 .. 500, GFLOP/s with 2/3 n^3 flops, share of the machine's peak.

   build (from the repository root; `make bench` does this):
       cc -std=c99 -O3 -march=native bench/bench_lu.c -o build/bench/bench_lu -lm
   run from the repository root:  build/bench/bench_lu [tag]
   writes out/bench/lu[-tag].csv and out/bench/lu[-tag].svg (out/bench must exist).

   Method: random matrix with entries uniform in [-1, 1] (fixed seed), the call
   as a user makes it (A untouched, factor written to a second buffer), warm-up,
   then samples of k calls each (k chosen so a sample takes >= 1 ms), enough
   samples for >= 0.2 s per size, CLOCK_MONOTONIC, median over samples.
   Peak = 16 double flops/cycle (two 256-bit FMA pipes, e.g. AMD Zen 4) times
   the "cpu MHz" of /proc/cpuinfo.  The residual check solves A x = b with
   x = (1, ..., 1) and reports ||A x - b||_inf / (||A||_inf ||x||_inf n eps). */
#define _POSIX_C_SOURCE 199309L
#include "../vlbe.h"
#include "svgplot.h"
#include "bench_util.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define NSIZES 7
#define FLOPS_PER_CYCLE 16.0

static volatile double sink;

static unsigned long long rng_state = 0x9E3779B97F4A7C15ULL;
static double urand(void) { return benchu_urand(&rng_state); }

static double cpu_mhz(void)
{
    char line[256];
    double mhz = 0.0;
    FILE *f = fopen("/proc/cpuinfo", "r");
    if (!f) return 0.0;
    while (fgets(line, sizeof line, f)) {
        if (strncmp(line, "cpu MHz", 7) == 0) {
            const char *c = strchr(line, ':');
            if (c) mhz = atof(c + 1);
            break;
        }
    }
    fclose(f);
    return mhz;
}

static void cpu_model(char *buf, size_t len)
{
    char line[256];
    FILE *f = fopen("/proc/cpuinfo", "r");
    snprintf(buf, len, "unknown cpu");
    if (!f) return;
    while (fgets(line, sizeof line, f)) {
        if (strncmp(line, "model name", 10) == 0) {
            const char *c = strchr(line, ':');
            if (c) {
                snprintf(buf, len, "%s", c + 2);
                buf[strcspn(buf, "\n")] = '\0';
            }
            break;
        }
    }
    fclose(f);
}

/* one timed batch of k factorizations (what = 0) or solves (what = 1); seconds per call */
static double batch(int what, int k, int n, const vlbe_real *A, vlbe_real *LU, int *piv,
                    vlbe_real *B, const vlbe_real *B0)
{
    double t0, acc = 0.0;
    int r, info;
    t0 = benchu_now();
    for (r = 0; r < k; ++r) {
        if (what == 0) {
            if (vlbe_lu_factor(n, A, LU, piv, &info) != VLBE_OK) {
                fprintf(stderr, "bench_lu: factor failed at n = %d (info %d)\n", n, info);
                exit(1);
            }
            acc += (double)LU[(size_t)(r % n) * (size_t)(n + 1)];
        } else {
            memcpy(B, B0, (size_t)n * sizeof *B);
            vlbe_lu_solve(n, LU, piv, 1, B);
            acc += (double)B[r % n];
        }
    }
    t0 = benchu_now() - t0;
    sink = acc;
    return t0 / (double)k;
}

/* median seconds per call, >= min_total seconds of samples */
static double measure(int what, int n, const vlbe_real *A, vlbe_real *LU, int *piv, vlbe_real *B,
                      const vlbe_real *B0, double min_total)
{
    enum { MAXS = 401 };
    static double s[MAXS];
    double t1, t;
    int k = 1, ns, i;
    /* warm-up and calibration: grow k until one batch takes >= 1 ms (a
       batch of 2^24 calls of >= 10 flops each takes longer on any machine;
       the cap only guards against a clock that does not advance) */
    for (;;) {
        t = batch(what, k, n, A, LU, piv, B, B0) * (double)k;
        if (t >= 1e-3 || k >= (1 << 24)) break;
        k *= 2;
    }
    t1 = t / (double)k;
    ns = (int)(min_total / (t1 * (double)k)) + 1;
    if (ns < 11) ns = 11;
    if (ns > MAXS) ns = MAXS;
    for (i = 0; i < ns; ++i) s[i] = batch(what, k, n, A, LU, piv, B, B0);
    qsort(s, (size_t)ns, sizeof s[0], benchu_cmp_double);
    return s[ns / 2];
}

int main(int argc, char **argv)
{
    static const int sizes[NSIZES] = {10, 20, 50, 100, 200, 300, 500};
    double xs[NSIZES], gf[NSIZES], tf[NSIZES], ts[NSIZES], pk[NSIZES], res[NSIZES], nd[NSIZES];
    double mhz = cpu_mhz(), peak = FLOPS_PER_CYCLE * mhz * 1e-3; /* GFLOP/s */
    const char *tag = argc > 1 ? argv[1] : NULL;
    char model[128], csv[256], svg[256], title[256];
    int si, bad = 0;

    cpu_model(model, sizeof model);
    printf("bench_lu: vlbe_lu_factor + vlbe_lu_solve, vlbe %s, %s\n", VLBE_VERSION_STRING,
           sizeof(vlbe_real) == sizeof(double) ? "double" : "float");
    printf("compiler: %s, flags: %s\n", __VERSION__, VLBE_BENCH_FLAGS);
    if (mhz > 0.0)
        printf("cpu: %s, %.0f MHz (/proc/cpuinfo), peak %.1f GFLOP/s per core (%.0f flops/cycle)\n",
               model, mhz, peak, FLOPS_PER_CYCLE);
    else
        printf("cpu: %s, clock unknown: %% of peak not reported\n", model);
    printf("\n%5s %12s %10s %8s %12s %10s\n", "n", "factor [us]", "GFLOP/s", "% peak", "solve [us]",
           "residual");

    for (si = 0; si < NSIZES; ++si) {
        int n = sizes[si], i, j, info;
        size_t N = (size_t)n;
        vlbe_real *A = (vlbe_real *)malloc(N * N * sizeof *A);
        vlbe_real *LU = (vlbe_real *)malloc(N * N * sizeof *LU);
        vlbe_real *B = (vlbe_real *)malloc(N * sizeof *B);
        vlbe_real *B0 = (vlbe_real *)malloc(N * sizeof *B0);
        int *piv = (int *)malloc(N * sizeof *piv);
        double anorm = 0.0, rmax = 0.0, xmax = 0.0;
        if (!A || !LU || !B || !B0 || !piv) {
            fprintf(stderr, "bench_lu: out of memory\n");
            return 1;
        }
        for (i = 0; i < n * n; ++i) A[i] = (vlbe_real)urand();
        for (i = 0; i < n; ++i) {
            double row = 0.0, b = 0.0;
            for (j = 0; j < n; ++j) {
                row += fabs((double)A[i * n + j]);
                b += (double)A[i * n + j];
            }
            if (row > anorm) anorm = row;
            B0[i] = (vlbe_real)b; /* b = A * ones */
        }

        tf[si] = measure(0, n, A, LU, piv, B, B0, 0.2);
        ts[si] = measure(1, n, A, LU, piv, B, B0, 0.05);

        /* residual of the solve with the last factor */
        if (vlbe_lu_factor(n, A, LU, piv, &info) != VLBE_OK) return 1;
        memcpy(B, B0, N * sizeof *B);
        vlbe_lu_solve(n, LU, piv, 1, B);
        for (i = 0; i < n; ++i) {
            double r = -(double)B0[i];
            for (j = 0; j < n; ++j) r += (double)A[i * n + j] * (double)B[j];
            if (fabs(r) > rmax) rmax = fabs(r);
            if (fabs((double)B[i]) > xmax) xmax = fabs((double)B[i]);
        }
        res[si] = rmax / (anorm * xmax * (double)n * (double)VLBE_EPS);

        nd[si] = xs[si] = (double)n;
        gf[si] = (double)vlbe_lu_flops(n) / tf[si] * 1e-9;
        pk[si] = peak > 0.0 ? 100.0 * gf[si] / peak : 0.0;
        if (!(res[si] < 10.0)) bad = 1;
        if (peak > 0.0)
            printf("%5d %12.2f %10.2f %7.1f%% %12.2f %10.2g%s\n", n, tf[si] * 1e6, gf[si], pk[si],
                   ts[si] * 1e6, res[si], res[si] < 10.0 ? "" : "  FAIL");
        else
            printf("%5d %12.2f %10.2f %8s %12.2f %10.2g%s\n", n, tf[si] * 1e6, gf[si], "-",
                   ts[si] * 1e6, res[si], res[si] < 10.0 ? "" : "  FAIL");
        fflush(stdout);
        free(A);
        free(LU);
        free(B);
        free(B0);
        free(piv);
    }

    snprintf(csv, sizeof csv, "out/bench/lu%s%s.csv", tag ? "-" : "", tag ? tag : "");
    snprintf(svg, sizeof svg, "out/bench/lu%s%s.svg", tag ? "-" : "", tag ? tag : "");
    {
        const double *cols[6];
        cols[0] = nd;
        cols[1] = tf;
        cols[2] = gf;
        cols[3] = pk;
        cols[4] = ts;
        cols[5] = res;
        if (svgp_csv_write(csv, "n,factor_s,gflops,pct_peak,solve_s,residual", 6, NSIZES, cols) != 0)
            fprintf(stderr, "bench_lu: cannot write %s\n", csv);
    }
    {
        svgp_chart c;
        double tx[2], ty[2];
        snprintf(title, sizeof title, "vlbe_lu_factor, %s, %s", sizeof(vlbe_real) == sizeof(double) ? "double" : "float",
                 VLBE_BENCH_FLAGS);
        svgp_init(&c, title, "matrix size n", "GFLOP/s (2/3 n^3 flops / median time)", 1, 0);
        svgp_series(&c, "vlbe_lu_factor", NSIZES, xs, gf, SVGP_MARKERS);
        tx[0] = xs[0];
        tx[1] = xs[NSIZES - 1];
        ty[0] = ty[1] = 5.0;
        svgp_series(&c, "target 5 GFLOP/s at n = 100", 2, tx, ty, SVGP_DASH);
        c.legend = SVGP_LEGEND_BR;
        if (svgp_write_file(&c, svg) != 0) fprintf(stderr, "bench_lu: cannot write %s\n", svg);
    }
    printf("\nwrote %s, %s\n", csv, svg);
    if (bad) {
        fprintf(stderr, "bench_lu: residual check failed\n");
        return 1;
    }
    return 0;
}
