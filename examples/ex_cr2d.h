/* ex_cr2d.h -- a vlbe_dae over a co-rotational beam (corot2d.h): the
   beam's callbacks wired into the system of integrators.h, shared by the
   examples that integrate or solve a vlbe_cr2d_beam as it is.
   -- part of vlbe                                  SPDX-License-Identifier: MIT */
#ifndef VLBE_EX_CR2D_H
#define VLBE_EX_CR2D_H

#include "../corot2d.h"
#include "../integrators.h"

/* the storage of sys's matrices that of the beam's callbacks: banded with
   the beam's order and half-bandwidths when it is in banded mode
   (vlbe_cr2d_beam_band), else dense */
static inline void ex_cr2d_storage(vlbe_dae *sys, const vlbe_cr2d_beam *b)
{
    sys->storage = b->order ? VLBE_DAE_BANDED : VLBE_DAE_DENSE;
    sys->kl = b->order ? b->kl : 0;
    sys->ku = b->order ? b->ku : 0;
    sys->order = b->order;
}

/* sys: n coordinates, m constraint equations (the beam's prescribed
   coordinates), every callback the beam's, user = b; flags 0; the
   storage of the beam (ex_cr2d_storage). */
static inline void ex_cr2d_dae(vlbe_dae *sys, vlbe_cr2d_beam *b, int n, int m)
{
    sys->n = n;
    sys->m = m;
    sys->flags = 0u;
    sys->user = b;
    sys->mass = vlbe_cr2d_beam_mass;
    sys->force = vlbe_cr2d_beam_force;
    sys->force_jac = vlbe_cr2d_beam_force_jac;
    sys->mass_jac = vlbe_cr2d_beam_mass_jac;
    sys->constr = vlbe_cr2d_beam_constr;
    sys->constr_jac = vlbe_cr2d_beam_constr_jac;
    sys->constr_acc = vlbe_cr2d_beam_constr_acc;
    sys->constr_hess = NULL; /* finite differences (prescribed coordinates: 0) */
    ex_cr2d_storage(sys, b);
}

#endif /* VLBE_EX_CR2D_H */
