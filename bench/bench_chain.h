/* bench_chain.h -- timing of the clamped chain of scenes/clamped_chain.h
   for bench/bench_scale.c and bench/wp_chain.c: cc_time (median
   microseconds per HHT step over CC_BLOCKS blocks after CC_WARM steps,
   Newton iterations and factorizations per step, workspace) and cc_slope
   (the log-log slope of a scaling series).
   -- part of vlbe                                  SPDX-License-Identifier: MIT */
#ifndef VLBE_BENCH_CHAIN_H
#define VLBE_BENCH_CHAIN_H

#include "bench_util.h"
#include "../scenes/clamped_chain.h"

#include <math.h>
#include <stdlib.h>

enum { CC_WARM = 20, CC_BLOCKS = 5 };

typedef struct cc_result {
    double us, newton, lu, mb;
    int kl, n;
} cc_result;

static inline int cc_time(int ne, int variant, cc_result *r)
{
    cc_scene *s = (cc_scene *)malloc(sizeof *s);
    double t[CC_BLOCKS];
    long it0, lu0, steps = 0;
    int b, k, ok = 0;
    if (!s) return -1;
    if (cc_init(s, ne, variant)) goto out;
    for (k = 0; k < CC_WARM; ++k)
        if (vlbe_hht_step(&s->st, VLBE_R(1e-3))) goto out;
    it0 = s->st.stats.newton_iters;
    lu0 = s->st.stats.lu_factors;
    for (b = 0; b < CC_BLOCKS; ++b) {
        double t0 = benchu_now(), el;
        int nk = 0;
        do {
            for (k = 0; k < 10; ++k)
                if (vlbe_hht_step(&s->st, VLBE_R(1e-3))) goto out;
            nk += 10;
            el = benchu_now() - t0;
        } while (el < 0.2 / CC_BLOCKS && nk < 100000);
        t[b] = el / nk;
        steps += nk;
    }
    qsort(t, CC_BLOCKS, sizeof *t, benchu_cmp_double);
    r->us = 1e6 * t[CC_BLOCKS / 2];
    r->newton = (double)(s->st.stats.newton_iters - it0) / (double)steps;
    r->lu = (double)(s->st.stats.lu_factors - lu0) / (double)steps;
    r->mb = ((double)s->lw * sizeof(vlbe_real) + (double)s->liw * sizeof(int) +
             (variant != CC_DENSE ? (double)(5 * (ne + 1) + 4) * sizeof(int) : 0.0)) /
            1048576.0;
    r->kl = variant != CC_DENSE ? s->ch.kl : -1;
    r->n = s->ch.n;
    ok = 1;
out:
    cc_free(s);
    free(s);
    return ok ? 0 : -1;
}

/* least-squares slope of log y against log x */
static inline double cc_slope(int n, const double *x, const double *y)
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

#endif /* VLBE_BENCH_CHAIN_H */
