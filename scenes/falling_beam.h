/* falling_beam.h -- the falling cantilever with a sliding mass
   (ale-rancf section 6.1) on the model and run loop of ex_slide.h: the
   scene's configuration (fb_cfg) and the statuses that count as outcomes
   of a run (fb_dynamic_status).  Shared by examples/falling_beam.c, which
   states the scene, tests/test_scenes_ale.c, tests/test_scenes_band.c and
   bench/bench_sliding.c.
   -- part of vlbe                                  SPDX-License-Identifier: MIT */
#ifndef VLBE_SCENE_FALLING_BEAM_H
#define VLBE_SCENE_FALLING_BEAM_H

#include "ex_slide.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define FB_NRUN 5

/* the scene: N elements, element flags (0 or VLBE_ALE_CONSERVATIVE), step h */
static inline void fb_cfg(ex_slide_cfg *c, int N, unsigned flags, double h)
{
    ex_slide_cfg_paper(c, N, EX_SLIDE_CLAMP_FREE, 0.8, 0.1, 0.4);
    c->flags = flags;
    c->h = h;
}

/* a status with which a run may end as a measured outcome of the model
   (Newton failure, step halvings exhausted, inverted element, bad weight
   ...), as opposed to a set-up or programming error */
static inline int fb_dynamic_status(vlbe_status s)
{
    return s != VLBE_EARG && s != VLBE_EWORK && s != VLBE_ECALLBACK;
}

#endif /* VLBE_SCENE_FALLING_BEAM_H */
