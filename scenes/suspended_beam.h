/* suspended_beam.h -- the simply supported beam with a sliding mass
   (ale-rancf section 6.2) on the model and run loop of ex_slide.h: the
   scene's configuration (sb_cfg) and the largest rate of the arc length
   over a time window (sb_rate_max).  Shared by examples/suspended_beam.c,
   which states the scene, tests/test_scenes_ale.c and
   bench/bench_sliding.c.
   -- part of vlbe                                  SPDX-License-Identifier: MIT */
#ifndef VLBE_SCENE_SUSPENDED_BEAM_H
#define VLBE_SCENE_SUSPENDED_BEAM_H

#include "ex_slide.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* the scene: element flags (0 or VLBE_ALE_CONSERVATIVE), step h, end time */
static inline void sb_cfg(ex_slide_cfg *c, unsigned flags, double h, double t_end)
{
    ex_slide_cfg_paper(c, 3, EX_SLIDE_PIN_PIN, 5.0, 0.1, 0.0);
    c->flags = flags;
    c->h = h;
    c->t_end = t_end;
}

/* largest |rate of the arc length| over the recorded rows with t in
   (t0, t1]; 0 when there are none */
static inline double sb_rate_max(const ex_slide_hist *hi, double t0, double t1)
{
    double m = 0.0;
    int k;
    for (k = 0; k < hi->n; ++k)
        if (hi->t[k] > t0 && hi->t[k] <= t1 && fabs(hi->rate[k]) > m) m = fabs(hi->rate[k]);
    return m;
}

#endif /* VLBE_SCENE_SUSPENDED_BEAM_H */
