/* bench_lu.c -- speed of the LU of vlbe.h: the dense vlbe_lu_factor (+
   vlbe_lu_solve) for n = 10 .. 500, GFLOP/s with 2/3 n^3 flops, share of
   the machine's peak; the banded vlbe_band_lu_factor (+ vlbe_band_lu_solve)
   for n = 64 .. 4100 at kl = ku = 7 (a planar cable chain) and 13 (a 3D
   chain), beside the dense LU at the same n up to 1028.

   build (from the repository root; `make bench` does this):
       cc -std=c99 -O3 -march=native bench/bench_lu.c -o build/bench/bench_lu -lm
   run from the repository root:  build/bench/bench_lu [tag]
   writes out/bench/lu[-tag].csv, lu[-tag].svg (dense) and
   out/bench/lu_band[-tag].csv, lu_band[-tag].svg (banded; out/bench must
   exist).
   With LAPACKE (Debian: liblapacke-dev; the Makefile builds it when
   /usr/include/lapacke.h exists, as build/bench/bench_lu_lapacke):
       cc -std=c99 -O3 -march=native -DVLBE_BENCH_LAPACKE bench/bench_lu.c \
          -o build/bench/bench_lu_lapacke -llapacke -lm
   times only the banded rows, side by side with LAPACKE_dgbtrf and
   LAPACKE_dgbtrs_work (column-major band, ldab = 2 kl + ku + 1, the LAPACK
   that liblapacke links): the factor with LAPACKE's NaN check of the
   input, as ours checks it, the solve without (LAPACKE_dgbtrs would scan
   the whole factor, ours does not), and writes
   out/bench/lu_band_lapacke[-tag].csv; the pivots must agree.

   Method: random matrix with entries uniform in [-1, 1] (fixed seed; the
   band ones pivot at most steps), the call as a user makes it (A
   untouched, factor written to a second buffer; LAPACK factors in place,
   so its batch restores the band from a copy first, the counterpart of
   our copy into LU), warm-up, then samples of k calls each (k chosen so a
   sample takes >= 1 ms), enough samples for >= 0.2 s per size,
   CLOCK_MONOTONIC, median over samples.
   Peak = 16 double flops/cycle (two 256-bit FMA pipes, e.g. AMD Zen 4) times
   the "cpu MHz" of /proc/cpuinfo.  The residual check solves A x = b with
   x = (1, ..., 1) and reports ||A x - b||_inf / (||A||_inf ||x||_inf w eps),
   w = n (dense) or kl + ku + 1 (band).  Band GFLOP/s count
   vlbe_band_lu_flops (the flops without interchanges, n kl (2 ku + 1)). */
#define _POSIX_C_SOURCE 199309L
#include "../vlbe.h"
#include "../scenes/svgplot.h"
#include "bench_util.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#if defined(VLBE_BENCH_LAPACKE) && defined(VLBE_USE_FLOAT)
#error "bench_lu: the LAPACKE comparison is for the double build"
#endif
#ifdef VLBE_BENCH_LAPACKE
#include <lapacke.h>
#endif

#define NSIZES 7
#define NBAND 7   /* band sizes */
#define NBW 2     /* half-bandwidths */
#define DENSE_MAX 1028 /* the dense LU beside the band one up to this n */
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

/* What a timed batch calls: dense factor / solve, band factor / solve,
   LAPACK's band factor / solve. */
enum { JOB_LU, JOB_LU_SOLVE, JOB_BAND, JOB_BAND_SOLVE, JOB_GB, JOB_GB_SOLVE };

typedef struct job {
    int what, n, kl, ku, lda;
    const vlbe_real *A; /* dense n x n, or band with lda */
    vlbe_real *LU;
    int *piv;
    vlbe_real *B;        /* right-hand side, restored from B0 before each solve */
    const vlbe_real *B0;
#ifdef VLBE_BENCH_LAPACKE
    double *AB;          /* LAPACK's band (factored in place), restored from AB0 */
    const double *AB0;
    lapack_int *ipiv;
    int ldab;
#endif
} job;

static void fail(const job *jb, int info)
{
    fprintf(stderr, "bench_lu: factor %d failed at n = %d, kl = %d, ku = %d (info %d)\n", jb->what,
            jb->n, jb->kl, jb->ku, info);
    exit(1);
}

/* one timed batch of k calls of job jb; seconds per call */
static double batch(const job *jb, int k)
{
    const int n = jb->n;
    const size_t N = (size_t)n;
    double t0, acc = 0.0;
    int r, info = 0;
    t0 = benchu_now();
    for (r = 0; r < k; ++r) {
        switch (jb->what) {
        case JOB_LU:
            if (vlbe_lu_factor(n, jb->A, jb->LU, jb->piv, &info) != VLBE_OK) fail(jb, info);
            acc += (double)jb->LU[(size_t)(r % n) * (N + 1)];
            break;
        case JOB_BAND:
            if (vlbe_band_lu_factor(n, jb->kl, jb->ku, jb->A, jb->lda, jb->LU, jb->piv, &info) !=
                VLBE_OK)
                fail(jb, info);
            acc += (double)jb->LU[(size_t)(r % n) * vlbe_band_lu_ld(jb->kl, jb->ku) +
                                  (size_t)jb->kl];
            break;
        case JOB_LU_SOLVE:
        case JOB_BAND_SOLVE:
            memcpy(jb->B, jb->B0, N * sizeof *jb->B);
            if (jb->what == JOB_LU_SOLVE) vlbe_lu_solve(n, jb->LU, jb->piv, 1, jb->B);
            else vlbe_band_lu_solve(n, jb->kl, jb->ku, jb->LU, jb->piv, 1, jb->B);
            acc += (double)jb->B[r % n];
            break;
#ifdef VLBE_BENCH_LAPACKE
        case JOB_GB:
            memcpy(jb->AB, jb->AB0, N * (size_t)jb->ldab * sizeof *jb->AB);
            info = (int)LAPACKE_dgbtrf(LAPACK_COL_MAJOR, n, n, jb->kl, jb->ku, jb->AB, jb->ldab,
                                       jb->ipiv);
            if (info != 0) fail(jb, info);
            acc += jb->AB[(size_t)(r % n) * (size_t)jb->ldab + (size_t)(jb->kl + jb->ku)];
            break;
        case JOB_GB_SOLVE:
            memcpy(jb->B, jb->B0, N * sizeof *jb->B);
            LAPACKE_dgbtrs_work(LAPACK_COL_MAJOR, 'N', n, jb->kl, jb->ku, 1, jb->AB, jb->ldab,
                                jb->ipiv, jb->B, n);
            acc += jb->B[r % n];
            break;
#endif
        default: fail(jb, -1);
        }
    }
    t0 = benchu_now() - t0;
    sink = acc;
    return t0 / (double)k;
}

#ifndef VLBE_BENCH_LAPACKE
/* median seconds per call, >= min_total seconds of samples */
static double measure(const job *jb, double min_total)
{
    enum { MAXS = 401 };
    static double s[MAXS];
    double t1, t;
    int k = 1, ns, i;
    /* warm-up and calibration: grow k until one batch takes >= 1 ms (a
       batch of 2^24 calls of >= 10 flops each takes longer on any machine;
       the cap only guards against a clock that does not advance) */
    for (;;) {
        t = batch(jb, k) * (double)k;
        if (t >= 1e-3 || k >= (1 << 24)) break;
        k *= 2;
    }
    t1 = t / (double)k;
    ns = (int)(min_total / (t1 * (double)k)) + 1;
    if (ns < 11) ns = 11;
    if (ns > MAXS) ns = MAXS;
    for (i = 0; i < ns; ++i) s[i] = batch(jb, k);
    qsort(s, (size_t)ns, sizeof s[0], benchu_cmp_double);
    return s[ns / 2];
}
#endif

#ifdef VLBE_BENCH_LAPACKE
/* medians of jobs a and b (seconds per call) from samples taken in turn,
   a, b, a, b, ..., so that a load that comes and goes on a shared machine
   hits both alike; >= min_total seconds of samples each */
static void measure_pair(const job *a, const job *b, double min_total, double *ta, double *tb)
{
    enum { MAXS = 401 };
    static double sa[MAXS], sb[MAXS];
    const job *jb[2];
    double t[2];
    int k[2], ns = 11, i, w;
    jb[0] = a, jb[1] = b;
    for (w = 0; w < 2; ++w) { /* warm-up and calibration as in measure() */
        k[w] = 1;
        for (;;) {
            t[w] = batch(jb[w], k[w]) * (double)k[w];
            if (t[w] >= 1e-3 || k[w] >= (1 << 24)) break;
            k[w] *= 2;
        }
        i = (int)(min_total / t[w]) + 1;
        if (i > ns) ns = i;
    }
    if (ns > MAXS) ns = MAXS;
    for (i = 0; i < ns; ++i) {
        sa[i] = batch(a, k[0]);
        sb[i] = batch(b, k[1]);
    }
    qsort(sa, (size_t)ns, sizeof sa[0], benchu_cmp_double);
    qsort(sb, (size_t)ns, sizeof sb[0], benchu_cmp_double);
    *ta = sa[ns / 2];
    *tb = sb[ns / 2];
}
#endif

/* ||A x - b||_inf / (||A||_inf ||x||_inf w eps), A dense (lda = 0) or band */
static double residual(int n, int kl, int ku, int lda, const vlbe_real *A, const vlbe_real *x,
                       const vlbe_real *b, int w)
{
    double anorm = 0.0, rmax = 0.0, xmax = 0.0;
    int i, j;
    for (i = 0; i < n; ++i) {
        const int j0 = lda ? (i > kl ? i - kl : 0) : 0;
        const int j1 = lda ? (i + ku < n ? i + ku : n - 1) : n - 1;
        double r = -(double)b[i], row = 0.0;
        for (j = j0; j <= j1; ++j) {
            const double a = (double)(lda ? A[VLBE_BAND_IDX(lda, kl, i, j)] : A[i * n + j]);
            r += a * (double)x[j];
            row += fabs(a);
        }
        if (row > anorm) anorm = row;
        if (fabs(r) > rmax) rmax = fabs(r);
        if (fabs((double)x[i]) > xmax) xmax = fabs((double)x[i]);
    }
    return rmax / (anorm * xmax * (double)w * (double)VLBE_EPS);
}

/* b = A * ones (A dense when lda = 0) */
static void rhs_ones(int n, int kl, int ku, int lda, const vlbe_real *A, vlbe_real *b)
{
    int i, j;
    for (i = 0; i < n; ++i) {
        const int j0 = lda ? (i > kl ? i - kl : 0) : 0;
        const int j1 = lda ? (i + ku < n ? i + ku : n - 1) : n - 1;
        double s = 0.0;
        for (j = j0; j <= j1; ++j)
            s += (double)(lda ? A[VLBE_BAND_IDX(lda, kl, i, j)] : A[i * n + j]);
        b[i] = (vlbe_real)s;
    }
}

static void *xmalloc(size_t bytes)
{
    void *p = malloc(bytes ? bytes : 1);
    if (!p) {
        fprintf(stderr, "bench_lu: out of memory\n");
        exit(1);
    }
    return p;
}

#ifndef VLBE_BENCH_LAPACKE
/* The dense table (n = 10 .. 500), its CSV and chart; 1 if a residual
   check failed. */
static int dense_sweep(double peak, const char *tag)
{
    static const int sizes[NSIZES] = {10, 20, 50, 100, 200, 300, 500};
    double xs[NSIZES], gf[NSIZES], tf[NSIZES], ts[NSIZES], pk[NSIZES], res[NSIZES], nd[NSIZES];
    char csv[256], svg[256], title[256];
    int si, bad = 0;

    printf("\n%5s %12s %10s %8s %12s %10s\n", "n", "factor [us]", "GFLOP/s", "% peak", "solve [us]",
           "residual");
    for (si = 0; si < NSIZES; ++si) {
        int n = sizes[si], i, info;
        size_t N = (size_t)n;
        job jb;
        vlbe_real *A = (vlbe_real *)xmalloc(N * N * sizeof *A);
        vlbe_real *LU = (vlbe_real *)xmalloc(N * N * sizeof *LU);
        vlbe_real *B = (vlbe_real *)xmalloc(N * sizeof *B);
        vlbe_real *B0 = (vlbe_real *)xmalloc(N * sizeof *B0);
        int *piv = (int *)xmalloc(N * sizeof *piv);
        for (i = 0; i < n * n; ++i) A[i] = (vlbe_real)urand();
        rhs_ones(n, 0, 0, 0, A, B0);
        memset(&jb, 0, sizeof jb);
        jb.n = n, jb.A = A, jb.LU = LU, jb.piv = piv, jb.B = B, jb.B0 = B0;
        jb.what = JOB_LU;
        tf[si] = measure(&jb, 0.2);
        jb.what = JOB_LU_SOLVE;
        ts[si] = measure(&jb, 0.05);

        /* residual of the solve with the last factor */
        if (vlbe_lu_factor(n, A, LU, piv, &info) != VLBE_OK) return 1;
        memcpy(B, B0, N * sizeof *B);
        vlbe_lu_solve(n, LU, piv, 1, B);
        res[si] = residual(n, 0, 0, 0, A, B, B0, n);

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
    return bad;
}
#endif

/* The band table: n = 64 .. 4100 at kl = ku = 7 and 13 (without LAPACKE:
   with the dense LU beside it up to DENSE_MAX; with it: beside dgbtrf /
   dgbtrs), the CSV (and without LAPACKE the chart); 1 if a check failed. */
static int band_sweep(const char *tag)
{
    static const int sizes[NBAND] = {64, 128, 260, 516, 1028, 2052, 4100};
    static const int bws[NBW] = {7, 13};
    enum { NR = NBAND * NBW, NCOL = 9 };
    double col[NCOL][NR];
    char csv[256];
    int si, bi, row = 0, bad = 0;
#ifdef VLBE_BENCH_LAPACKE
    printf("\nbanded LU beside LAPACK (LAPACKE_dgbtrf, LAPACKE_dgbtrs_work; column-major "
           "band)\n");
    printf("%5s %3s %3s %12s %12s %8s %12s %12s %8s %6s\n", "n", "kl", "ku", "factor [us]",
           "dgbtrf [us]", "ours/LA", "solve [us]", "dgbtrs [us]", "ours/LA", "piv");
#else
    printf("\nbanded LU (random band, pivoting), the dense LU at the same n\n");
    printf("%5s %3s %3s %12s %9s %12s %10s %14s %11s\n", "n", "kl", "ku", "factor [us]", "GFLOP/s",
           "solve [us]", "residual", "dense f. [us]", "dense/band");
#endif
    for (bi = 0; bi < NBW; ++bi)
        for (si = 0; si < NBAND; ++si, ++row) {
            const int n = sizes[si], kl = bws[bi], ku = bws[bi], lda = kl + ku + 1;
            const size_t N = (size_t)n, ld = vlbe_band_lu_ld(kl, ku);
            double tf = 0.0, ts = 0.0, res, gf, td = 0.0, tg = 0.0, tgs = 0.0;
            int i, j, info, piv_ok = 1;
            job jb;
            vlbe_real *A = (vlbe_real *)xmalloc(N * (size_t)lda * sizeof *A);
            vlbe_real *LU = (vlbe_real *)xmalloc(N * ld * sizeof *LU);
            vlbe_real *B = (vlbe_real *)xmalloc(N * sizeof *B);
            vlbe_real *B0 = (vlbe_real *)xmalloc(N * sizeof *B0);
            int *piv = (int *)xmalloc(N * sizeof *piv);
            for (i = 0; i < n; ++i)
                for (j = 0; j < lda; ++j) /* the slots outside the matrix too: never read */
                    A[(size_t)i * (size_t)lda + (size_t)j] = (vlbe_real)urand();
            rhs_ones(n, kl, ku, lda, A, B0);
            memset(&jb, 0, sizeof jb);
            jb.n = n, jb.kl = kl, jb.ku = ku, jb.lda = lda;
            jb.A = A, jb.LU = LU, jb.piv = piv, jb.B = B, jb.B0 = B0;
#ifndef VLBE_BENCH_LAPACKE
            jb.what = JOB_BAND;
            tf = measure(&jb, 0.2);
            jb.what = JOB_BAND_SOLVE;
            ts = measure(&jb, 0.05);
#endif
            if (vlbe_band_lu_factor(n, kl, ku, A, lda, LU, piv, &info) != VLBE_OK) return 1;
            memcpy(B, B0, N * sizeof *B);
            vlbe_band_lu_solve(n, kl, ku, LU, piv, 1, B);
            res = residual(n, kl, ku, lda, A, B, B0, lda);
            if (!(res < 10.0)) bad = 1;
#ifdef VLBE_BENCH_LAPACKE
            {
                const int ldab = (int)ld;
                double *AB = (double *)xmalloc(N * ld * sizeof *AB);
                double *AB0 = (double *)xmalloc(N * ld * sizeof *AB0);
                lapack_int *ipiv = (lapack_int *)xmalloc(N * sizeof *ipiv);
                job jg;
                /* A(i, j) at AB(kl + ku + i - j, j), 0-based, column-major */
                for (j = 0; j < n; ++j)
                    for (i = 0; i < ldab; ++i) AB0[(size_t)j * ld + (size_t)i] = 0.0;
                for (i = 0; i < n; ++i)
                    for (j = (i > kl ? i - kl : 0); j <= (i + ku < n ? i + ku : n - 1); ++j)
                        AB0[(size_t)j * ld + (size_t)(kl + ku + i - j)] =
                            (double)A[VLBE_BAND_IDX(lda, kl, i, j)];
                jb.AB = AB, jb.AB0 = AB0, jb.ipiv = ipiv, jb.ldab = ldab;
                jg = jb;
                jb.what = JOB_BAND, jg.what = JOB_GB;
                measure_pair(&jb, &jg, 0.2, &tf, &tg);
                jb.what = JOB_BAND_SOLVE, jg.what = JOB_GB_SOLVE;
                measure_pair(&jb, &jg, 0.05, &ts, &tgs);
                for (i = 0; i < n; ++i) piv_ok &= ipiv[i] == piv[i] + 1;
                if (!piv_ok) bad = 1;
                free(ipiv);
                free(AB0);
                free(AB);
            }
            gf = (double)vlbe_band_lu_flops(n, kl, ku) / tf * 1e-9;
            printf("%5d %3d %3d %12.2f %12.2f %8.2f %12.2f %12.2f %8.2f %6s\n", n, kl, ku, tf * 1e6,
                   tg * 1e6, tf / tg, ts * 1e6, tgs * 1e6, ts / tgs, piv_ok ? "same" : "DIFFER");
#else
            (void)piv_ok;
            gf = (double)vlbe_band_lu_flops(n, kl, ku) / tf * 1e-9;
            if (n <= DENSE_MAX) {
                vlbe_real *D = (vlbe_real *)xmalloc(N * N * sizeof *D);
                vlbe_real *DLU = (vlbe_real *)xmalloc(N * N * sizeof *DLU);
                for (i = 0; i < n; ++i)
                    for (j = 0; j < n; ++j)
                        D[i * n + j] = j >= i - kl && j <= i + ku
                                           ? A[VLBE_BAND_IDX(lda, kl, i, j)] : VLBE_R(0.0);
                jb.what = JOB_LU, jb.A = D, jb.LU = DLU;
                td = measure(&jb, 0.2);
                free(DLU);
                free(D);
            }
            if (td > 0.0)
                printf("%5d %3d %3d %12.2f %9.2f %12.2f %10.2g %14.1f %11.0f%s\n", n, kl, ku,
                       tf * 1e6, gf, ts * 1e6, res, td * 1e6, td / tf, res < 10.0 ? "" : "  FAIL");
            else
                printf("%5d %3d %3d %12.2f %9.2f %12.2f %10.2g %14s %11s%s\n", n, kl, ku, tf * 1e6,
                       gf, ts * 1e6, res, "-", "-", res < 10.0 ? "" : "  FAIL");
#endif
            fflush(stdout);
            col[0][row] = n, col[1][row] = kl, col[2][row] = ku;
            col[3][row] = tf, col[4][row] = gf, col[5][row] = ts, col[6][row] = res;
            col[7][row] = td > 0.0 ? td : tg, col[8][row] = tgs;
            free(A);
            free(LU);
            free(B);
            free(B0);
            free(piv);
        }
    {
        const double *cols[NCOL];
        int c;
        for (c = 0; c < NCOL; ++c) cols[c] = col[c];
#ifdef VLBE_BENCH_LAPACKE
        snprintf(csv, sizeof csv, "out/bench/lu_band_lapacke%s%s.csv", tag ? "-" : "",
                 tag ? tag : "");
        if (svgp_csv_write(csv, "n,kl,ku,factor_s,gflops,solve_s,residual,dgbtrf_s,dgbtrs_s",
                           NCOL, NR, cols) != 0)
            fprintf(stderr, "bench_lu: cannot write %s\n", csv);
        printf("\nwrote %s\n", csv);
#else
        char svg[256], title[256], names[NBW][64];
        svgp_chart ch; /* keeps pointers to the names and data below */
        double bx[NBW][NBAND], by[NBW][NBAND], dx[NBAND], dy[NBAND];
        int nd = 0;
        snprintf(csv, sizeof csv, "out/bench/lu_band%s%s.csv", tag ? "-" : "", tag ? tag : "");
        snprintf(svg, sizeof svg, "out/bench/lu_band%s%s.svg", tag ? "-" : "", tag ? tag : "");
        if (svgp_csv_write(csv, "n,kl,ku,factor_s,gflops,solve_s,residual,dense_factor_s",
                           NCOL - 1, NR, cols) != 0)
            fprintf(stderr, "bench_lu: cannot write %s\n", csv);
        snprintf(title, sizeof title, "banded LU, %s, %s",
                 sizeof(vlbe_real) == sizeof(double) ? "double" : "float", VLBE_BENCH_FLAGS);
        svgp_init(&ch, title, "matrix size n", "factor time [us] (median)", 1, 1);
        for (bi = 0; bi < NBW; ++bi) {
            for (si = 0; si < NBAND; ++si) {
                bx[bi][si] = col[0][bi * NBAND + si];
                by[bi][si] = col[3][bi * NBAND + si] * 1e6;
            }
            snprintf(names[bi], sizeof names[bi], "vlbe_band_lu_factor, kl = ku = %d", bws[bi]);
            svgp_series(&ch, names[bi], NBAND, bx[bi], by[bi], SVGP_MARKERS);
        }
        for (si = 0; si < NBAND; ++si) /* the dense LU on the kl = 7 matrices */
            if (col[7][si] > 0.0) {
                dx[nd] = col[0][si];
                dy[nd++] = col[7][si] * 1e6;
            }
        svgp_series(&ch, "vlbe_lu_factor (dense)", nd, dx, dy, SVGP_MARKERS | SVGP_DASH);
        ch.legend = SVGP_LEGEND_TL;
        if (svgp_write_file(&ch, svg) != 0) fprintf(stderr, "bench_lu: cannot write %s\n", svg);
        printf("\nwrote %s, %s\n", csv, svg);
#endif
    }
    return bad;
}

int main(int argc, char **argv)
{
    double mhz = cpu_mhz(), peak = FLOPS_PER_CYCLE * mhz * 1e-3; /* GFLOP/s */
    const char *tag = argc > 1 ? argv[1] : NULL;
    char model[128];
    int bad = 0;

    cpu_model(model, sizeof model);
    printf("bench_lu: vlbe_lu_factor + vlbe_lu_solve, vlbe_band_lu_factor + vlbe_band_lu_solve, "
           "vlbe %s, %s\n",
           VLBE_VERSION_STRING, sizeof(vlbe_real) == sizeof(double) ? "double" : "float");
    printf("compiler: %s, flags: %s\n", __VERSION__, VLBE_BENCH_FLAGS);
    if (mhz > 0.0)
        printf("cpu: %s, %.0f MHz (/proc/cpuinfo), peak %.1f GFLOP/s per core (%.0f flops/cycle)\n",
               model, mhz, peak, FLOPS_PER_CYCLE);
    else
        printf("cpu: %s, clock unknown: %% of peak not reported\n", model);
#ifndef VLBE_BENCH_LAPACKE
    bad |= dense_sweep(peak, tag);
#endif
    bad |= band_sweep(tag);
    if (bad) {
        fprintf(stderr, "bench_lu: residual (or pivot) check failed\n");
        return 1;
    }
    return 0;
}
