/* spin_up.h -- the spin-up scenes' models in the order of the runs,
   tables and CSV columns (sp_models, their names and labels) and the
   largest difference of two runs' transverse tips (sp_sample_diff), over
   the model and run driver of ex_spin.h.  Shared by examples/spin_up.c,
   tests/test_scenes_spin.c and tests/test_scenes_band.c.
   -- part of vlbe                                  SPDX-License-Identifier: MIT */
#ifndef VLBE_SCENE_SPIN_UP_H
#define VLBE_SCENE_SPIN_UP_H

#include "ex_spin.h"

#include <stdio.h>

/* the models in the order of the runs, tables and CSV columns */
#define SP_NMODEL 3
static const int sp_models[SP_NMODEL] = {SP_CR, SP_LINEAR, SP_ANCF};
static const char *const sp_model_name[SP_NMODEL] = {"CR", "linear", "ANCF"};
static const char *const sp_model_label[SP_NMODEL] = {
    "co-rotational (nonlinear)", "linear, floating frame", "ANCF (nonlinear)"};

/* max over the 0.5 s samples both runs reached of |transverse a - b| */
static inline double sp_sample_diff(const sp_out *a, const sp_out *b)
{
    double d = 0.0;
    int k;
    for (k = 0; k < SP_NS; ++k)
        if (!isnan(a->tip_s[k][1]) && !isnan(b->tip_s[k][1]))
            d = fmax(d, fabs(a->tip_s[k][1] - b->tip_s[k][1]));
    return d;
}

#endif /* VLBE_SCENE_SPIN_UP_H */
