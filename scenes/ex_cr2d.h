/* ex_cr2d.h -- the storage of a vlbe_dae with callbacks of one's own over a
   co-rotational beam (corot2d.h), shared by the examples; a beam's own
   vlbe_dae is vlbe_cr2d_beam_dae.
   -- part of vlbe                                  SPDX-License-Identifier: MIT */
#ifndef VLBE_EX_CR2D_H
#define VLBE_EX_CR2D_H

#include "../corot2d.h"
#include "../integrators.h"

/* the storage of sys's matrices that of the beam's callbacks (what
   vlbe_cr2d_beam_dae gives), the rest of sys kept */
static inline void ex_cr2d_storage(vlbe_dae *sys, vlbe_cr2d_beam *b)
{
    vlbe_dae own;
    if (vlbe_cr2d_beam_dae(b, &own) != VLBE_OK) return; /* order of another nfix */
    sys->storage = own.storage;
    sys->kl = own.kl;
    sys->ku = own.ku;
    sys->order = own.order;
}

#endif /* VLBE_EX_CR2D_H */
