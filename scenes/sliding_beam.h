/* sliding_beam.h -- the observer of the sliding beam's runs (Hsiao et
   al. section 3, the model of ex_sbeam.h): CSV rows, the tip history, the
   upward zero crossings of the tip and the amplitudes between them
   (sb_obs, sb_observe).  Shared by examples/sliding_beam.c,
   tests/test_scenes_sliding.c and bench/bench_cr2d.c.
   -- part of vlbe                                  SPDX-License-Identifier: MIT */
#ifndef VLBE_SCENE_SLIDING_BEAM_H
#define VLBE_SCENE_SLIDING_BEAM_H

#include "ex_sbeam.h"
#include "svgplot.h"

#include <stdio.h>

#define SB_NPER 256

/* what the observer collects */
typedef struct sb_obs {
    FILE *csv;
    long n, cap;
    double *t, *y;
    double ylast, tlast, tcross[SB_NPER], amp[SB_NPER];
    int ncross;
    double amax;
} sb_obs;

static inline void sb_observe(void *ctx, const sb_model *m, double t, const vlbe_real *q,
                              const vlbe_real *v)
{
    sb_obs *o = (sb_obs *)ctx;
    const double y = (double)q[m->n - 2];
    double g[3], E[2] = {0.0, 0.0};
    vlbe_real Er[2];
    sb_ua(&m->cfg, t, g);
    if (vlbe_cr2d_beam_energy(&m->beam, q, v, Er) == VLBE_OK) {
        E[0] = (double)Er[0];
        E[1] = (double)Er[1];
    }
    if (o->csv) {
        double row[6];
        row[0] = t;
        row[1] = sb_x(m, q, m->nn - 1);
        row[2] = y;
        row[3] = m->cfg.L0 + g[0];
        row[4] = E[0];
        row[5] = E[1];
        svgp_csv_row(o->csv, 6, row);
    }
    if (o->n < o->cap) {
        o->t[o->n] = t;
        o->y[o->n] = y;
        ++o->n;
    }
    if (fabs(y) > o->amax) o->amax = fabs(y);
    if (o->n > 1 && o->ylast < 0.0 && y >= 0.0 && o->ncross < SB_NPER) {
        /* upward zero crossing, linear interpolation */
        o->tcross[o->ncross] = o->tlast + (t - o->tlast) * (-o->ylast) / (y - o->ylast);
        o->amp[o->ncross] = o->amax;
        o->amax = 0.0;
        ++o->ncross;
    }
    o->ylast = y;
    o->tlast = t;
}

#endif /* VLBE_SCENE_SLIDING_BEAM_H */
