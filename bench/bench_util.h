/* bench_util.h -- what the micro-benchmarks share: a monotonic clock and
   the machine's CPU model and clock for the report header, CPU time, and
   the comparison for medians.
   -- part of vlbe                                  SPDX-License-Identifier: MIT

   POSIX (clock_gettime): the including file defines _POSIX_C_SOURCE
   199309L or later before its first #include. */
#ifndef VLBE_BENCH_UTIL_H
#define VLBE_BENCH_UTIL_H

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

/* the compiler flags for the report header (the Makefile passes them) */
#ifndef VLBE_BENCH_FLAGS
#define VLBE_BENCH_FLAGS "(unknown flags)"
#endif

/* The timing method of the per-call benchmarks: BENCHU_BATCHES batches,
   each of enough calls (within [min, BENCHU_MAX_CALLS]) to last
   BENCHU_MIN_BATCH_S; a row whose median / min exceeds BENCHU_NOISY is
   marked as disturbed (another process on the core). */
#define BENCHU_BATCHES 31
#define BENCHU_MAX_CALLS 2000000L
#define BENCHU_MIN_BATCH_S 2e-4
#define BENCHU_NOISY 1.15

/* seconds of CLOCK_MONOTONIC */
static inline double benchu_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* seconds of CPU time of this process (CLOCK_PROCESS_CPUTIME_ID) */
static inline double benchu_cpu_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* qsort comparison of doubles (for medians) */
static inline int benchu_cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* uniform in [-1, 1), xorshift64* on the caller's state (nonzero seed) */
static inline double benchu_urand(unsigned long long *st)
{
    *st ^= *st >> 12;
    *st ^= *st << 25;
    *st ^= *st >> 27;
    return (double)((*st * 2685821657736338717ULL) >> 11) * (2.0 / 9007199254740992.0) - 1.0;
}

/* CPU model name and MHz from /proc/cpuinfo ("unknown cpu", 0 elsewhere) */
static inline void benchu_cpu_info(char *model, size_t len, double *mhz)
{
    char line[256];
    FILE *f = fopen("/proc/cpuinfo", "r");
    int have_model = 0, have_mhz = 0;
    snprintf(model, len, "unknown cpu");
    *mhz = 0.0;
    if (!f) return;
    while ((!have_model || !have_mhz) && fgets(line, sizeof line, f)) {
        const char *c = strchr(line, ':');
        if (!c) continue;
        if (!have_model && strncmp(line, "model name", 10) == 0) {
            snprintf(model, len, "%s", c + 2);
            model[strcspn(model, "\n")] = '\0';
            have_model = 1;
        } else if (!have_mhz && strncmp(line, "cpu MHz", 7) == 0) {
            *mhz = atof(c + 1);
            have_mhz = 1;
        }
    }
    fclose(f);
}

/* Creates the output directory dir (an existing one is fine); 0, or -1
   after a message on stderr naming prog. */
static inline int benchu_mkdir(const char *dir, const char *prog)
{
    if (mkdir(dir, 0777) != 0 && errno != EEXIST) {
        fprintf(stderr, "%s: cannot create %s\n", prog, dir);
        return -1;
    }
    return 0;
}

/* The end of a per-call benchmark: closes the CSV f (may be NULL) at path
   csv and reports it, and the calls that did not return VLBE_OK (bad).
   The exit status: 0, or 1 when bad > 0. */
static inline int benchu_finish(const char *prog, FILE *f, const char *csv, long bad)
{
    if (f) {
        if (fclose(f) != 0) fprintf(stderr, "%s: cannot write %s\n", prog, csv);
        else printf("\nwrote %s\n", csv);
    }
    if (bad) {
        fprintf(stderr, "%s: %ld calls did not return VLBE_OK\n", prog, bad);
        return 1;
    }
    return 0;
}

/* 1-minute load average (/proc/loadavg), -1 when unknown */
static inline double benchu_load_avg(void)
{
    double l = -1.0;
    FILE *f = fopen("/proc/loadavg", "r");
    if (!f) return l;
    if (fscanf(f, "%lf", &l) != 1) l = -1.0;
    fclose(f);
    return l;
}

/* The planar ALE element's benchmark state (bench_ale.c, bench_ale3.c):
   an arc of radius R = 0.5 through the material points p = 1, 1.25,
   stretched by lam, rotating at om about the origin, translating at v0,
   stretching at lamd, material flow p' = 0.30, 0.25; q, qd in the planar
   element's layout [x, y, x', y', p] per node, a an acceleration with some
   of everything (p-rows included). */
static inline void benchu_arc_state(double *q, double *qd, double *a)
{
    const double R = 0.5, lam = 1.002, lamd = 0.01, om = 0.8, v0[2] = {0.4, -0.2};
    const double p[2] = {1.0, 1.25}, pd[2] = {0.30, 0.25}, th0 = 0.3;
    int n;
    for (n = 0; n < 2; ++n) {
        const int o = 5 * n;
        const double th = th0 + (p[n] - p[0]) / R;
        const double c = cos(th), sn = sin(th);
        const double r[2] = {lam * R * sn, lam * R * (1.0 - c)};
        const double rp[2] = {lam * c, lam * sn};
        q[o + 0] = r[0];
        q[o + 1] = r[1];
        q[o + 2] = rp[0];
        q[o + 3] = rp[1];
        q[o + 4] = p[n];
        /* rigid rotation + translation + stretching of the arc */
        qd[o + 0] = v0[0] - om * r[1] + lamd / lam * r[0];
        qd[o + 1] = v0[1] + om * r[0] + lamd / lam * r[1];
        qd[o + 2] = -om * rp[1] + lamd / lam * rp[0];
        qd[o + 3] = om * rp[0] + lamd / lam * rp[1];
        qd[o + 4] = pd[n];
        /* centripetal plus some of everything, p-rows included */
        a[o + 0] = -om * om * r[0] + 0.3;
        a[o + 1] = -om * om * r[1] - 9.81;
        a[o + 2] = -om * om * rp[0] + 0.05;
        a[o + 3] = -om * om * rp[1] - 0.02;
        a[o + 4] = n ? -0.4 : 0.6;
    }
}

#ifdef VLBE_ANCF_ALE_H
/* The material of the planar element benchmarks (bench_ale.c,
   bench_rancf.c): a steel wire, d = 5 mm (rhoA = 0.154 kg/m, EA = 4.1 MN,
   EI = 6.4 N m^2), Kelvin-Voigt times 1 ms, gravity as the load.  Defined
   when ancf_ale.h is included first. */
static inline vlbe_ale_mat benchu_wire(void)
{
    vlbe_ale_mat m;
    memset(&m, 0, sizeof m);
    m.rhoA = VLBE_R(0.154);
    m.EA = VLBE_R(4.1e6);
    m.EI = VLBE_R(6.4);
    m.c_eps = VLBE_R(1e-3);
    m.c_kap = VLBE_R(1e-3);
    m.f[0] = VLBE_R(0.0);
    m.f[1] = VLBE_R(-9.81) * m.rhoA;
    return m;
}
#endif

#endif /* VLBE_BENCH_UTIL_H */
