/* bench_util.h -- what the micro-benchmarks share: a monotonic clock and
   the machine's CPU model and clock for the report header, CPU time, and
   the comparison for medians.
   -- part of vlbe                                  SPDX-License-Identifier: MIT

   POSIX (clock_gettime): the including file defines _POSIX_C_SOURCE
   199309L or later before its first #include. */
#ifndef VLBE_BENCH_UTIL_H
#define VLBE_BENCH_UTIL_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

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

#endif /* VLBE_BENCH_UTIL_H */
