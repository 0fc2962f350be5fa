/* bench_eig.c -- speed of the dense eigen-solvers of vlbe.h for n = 20,
   50, 100, 200: vlbe_eig_gsym (K x = lam M x, eigenvectors included),
   vlbe_eig_real (eigenvalues of a general n x n matrix) and vlbe_eig_quad
   ((s^2 M + s D + K) x = 0, 2n eigenvalues; with eigenvectors for n <= 50).

   build (from the repository root; `make bench` does this):
       cc -std=c99 -O3 -march=native bench/bench_eig.c -o build/bench/bench_eig -lm
   run from the repository root:  build/bench/bench_eig [tag]
   writes out/bench/eig[-tag].csv (out/bench must exist): routine, n,
   median and min ns per call.

   Problems (fixed seed): gsym: K = Q1 diag(1 .. 1e4, log-spaced) Q1^T, M =
   Q2 diag(1 .. 2) Q2^T, Q from three Householder reflections of random
   vectors (dense, a spread of 1e4 like a coarse beam), sigma = 0; real: a
   random matrix, entries uniform in [-1, 1] (complex pairs and real
   eigenvalues; each call starts from a fresh copy, the n^2 copy is part of
   the time); quad: M and K those of gsym, D = 0.2 (R - R^T) + 0.05 I
   (gyroscopic plus damping, R uniform in [-1, 1]), sigma = 0.
   Method: a call to warm up and size the samples (k calls per sample, a
   sample >= 50 ms), then SAMPLES samples (CLOCK_MONOTONIC); median and
   min over them.  A call that does not return VLBE_OK counts as bad (exit
   status 1). */
#define _POSIX_C_SOURCE 199309L
#include "../vlbe.h"
#include "bench_util.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define NMAX 200
#define SAMPLES 9

static volatile double sink;
static unsigned long long rng_state = 0x2545F4914F6CDD1DULL;
static double urand(void) { return benchu_urand(&rng_state); }

static vlbe_real K[NMAX * NMAX], M[NMAX * NMAX], D[NMAX * NMAX], A0[NMAX * NMAX],
    A[NMAX * NMAX], X[NMAX * NMAX], lam[NMAX];
static vlbe_real sre[2 * NMAX], sim[2 * NMAX], Xre[2 * NMAX * NMAX], Xim[2 * NMAX * NMAX];
static vlbe_real work[9 * NMAX * NMAX + 20 * NMAX];
static int iwork[4 * NMAX];
static double Q[NMAX * NMAX];
static long bad;

/* Q = H1 H2 H3 (Householder reflections of random vectors) */
static void random_q(int n)
{
    double u[NMAX], t[NMAX];
    int r, i, j;
    for (i = 0; i < n; ++i)
        for (j = 0; j < n; ++j) Q[i * n + j] = i == j ? 1.0 : 0.0;
    for (r = 0; r < 3; ++r) {
        double uu = 0.0;
        for (i = 0; i < n; ++i) {
            u[i] = urand();
            uu += u[i] * u[i];
        }
        for (i = 0; i < n; ++i) {
            t[i] = 0.0;
            for (j = 0; j < n; ++j) t[i] += Q[i * n + j] * u[j];
        }
        for (i = 0; i < n; ++i)
            for (j = 0; j < n; ++j) Q[i * n + j] -= 2.0 * t[i] * u[j] / uu;
    }
}

/* S = Q diag(d) Q^T */
static void sym_from(int n, const double *d, vlbe_real *S)
{
    int i, j, k;
    for (i = 0; i < n; ++i)
        for (j = 0; j < n; ++j) {
            double s = 0.0;
            for (k = 0; k < n; ++k) s += Q[i * n + k] * d[k] * Q[j * n + k];
            S[i * n + j] = (vlbe_real)s;
        }
}

static void setup(int n)
{
    double d[NMAX];
    int i, j;
    random_q(n);
    for (i = 0; i < n; ++i) d[i] = pow(1e4, n > 1 ? (double)i / (n - 1) : 0.0);
    sym_from(n, d, K);
    random_q(n);
    for (i = 0; i < n; ++i) d[i] = 1.0 + urand() * 0.5 + 0.5;
    sym_from(n, d, M);
    for (i = 0; i < n * n; ++i) A0[i] = (vlbe_real)urand();
    for (i = 0; i < n * n; ++i) D[i] = (vlbe_real)(0.2 * urand());
    for (i = 0; i < n; ++i)
        for (j = 0; j < i; ++j) { /* skew part 0.2 (R - R^T), damping 0.05 I */
            const vlbe_real s = D[i * n + j] - D[j * n + i];
            D[i * n + j] = s;
            D[j * n + i] = -s;
        }
    for (i = 0; i < n; ++i) D[i * n + i] = VLBE_R(0.05);
}

enum { R_GSYM, R_REAL, R_QUAD, R_QUADX, NR };
static const char *const rname[NR] = {"gsym", "real", "quad", "quad+vectors"};

/* one call of routine r on the problem of size n */
static void call(int r, int n)
{
    vlbe_status st = VLBE_OK;
    switch (r) {
    case R_GSYM:
        st = vlbe_eig_gsym(n, K, M, VLBE_R(0.0), lam, X, NULL, work, vlbe_eig_work_len(n));
        sink += (double)lam[0];
        break;
    case R_REAL:
        memcpy(A, A0, (size_t)n * (size_t)n * sizeof *A);
        st = vlbe_eig_real(n, A, lam, sre, work, vlbe_eig_real_work_len(n));
        sink += (double)lam[0];
        break;
    case R_QUAD:
    case R_QUADX:
        st = vlbe_eig_quad(n, M, D, K, VLBE_R(0.0), sre, sim, r == R_QUADX ? 2 * n : 0, Xre,
                           Xim, work, vlbe_eig_quad_work_len(n), iwork,
                           vlbe_eig_quad_iwork_len(n));
        sink += (double)sre[0];
        break;
    default: break;
    }
    if (st != VLBE_OK) ++bad;
}

int main(int argc, char **argv)
{
    static const int sizes[] = {20, 50, 100, 200};
    const char *tag = argc > 1 ? argv[1] : NULL;
    char path[256], model[128];
    double mhz;
    FILE *f;
    int s, r;
    benchu_cpu_info(model, sizeof model, &mhz);
    snprintf(path, sizeof path, "out/bench/eig%s%s.csv", tag ? "-" : "", tag ? tag : "");
    f = fopen(path, "w");
    if (!f) fprintf(stderr, "bench_eig: cannot write %s (no CSV)\n", path);
    else fprintf(f, "routine,n,ns_median,ns_min\n");
    printf("# bench_eig: %s, %.0f MHz, %s, vlbe_real %s\n", model, mhz, VLBE_BENCH_FLAGS,
           sizeof(vlbe_real) == sizeof(double) ? "double" : "float");
    printf("# %-14s %5s %14s %14s %6s\n", "routine", "n", "median ns", "min ns", "calls");
    for (s = 0; s < (int)(sizeof sizes / sizeof sizes[0]); ++s) {
        const int n = sizes[s];
        setup(n);
        for (r = 0; r < NR; ++r) {
            double t[SAMPLES], t0, one;
            long k, c;
            int j;
            if (r == R_QUADX && n > 50) continue;
            t0 = benchu_now();
            call(r, n);
            one = benchu_now() - t0;
            k = one >= 0.05 ? 1 : (long)(0.05 / (one > 1e-9 ? one : 1e-9)) + 1;
            for (j = 0; j < SAMPLES; ++j) {
                t0 = benchu_now();
                for (c = 0; c < k; ++c) call(r, n);
                t[j] = (benchu_now() - t0) / (double)k * 1e9;
            }
            qsort(t, SAMPLES, sizeof t[0], benchu_cmp_double);
            printf("  %-14s %5d %14.0f %14.0f %6ld%s\n", rname[r], n, t[SAMPLES / 2], t[0], k,
                   t[SAMPLES / 2] > BENCHU_NOISY * t[0] ? " *" : "");
            if (f) fprintf(f, "%s,%d,%.0f,%.0f\n", rname[r], n, t[SAMPLES / 2], t[0]);
        }
    }
    return benchu_finish("bench_eig", f, path, bad);
}
