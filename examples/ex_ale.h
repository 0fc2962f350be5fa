/* ex_ale.h -- wiring an ALE-ANCF chain (ancf_ale.h) into the vlbe_dae of
   integrators.h, shared by the examples, tests and benchmarks.
   -- part of vlbe                                  SPDX-License-Identifier: MIT

   ancf_ale.h does not include integrators.h (the integrators know nothing of
   elements and the element module nothing of integrators); its chain
   callbacks have the vlbe_dae signatures, and this is the one place that
   plugs all of them in.  Call after vlbe_ale_chain_layout() and again after
   every change of the chain's layout (length control).  A chain in banded
   mode (vlbe_ale_chain_band) passes its band on: storage, kl, ku, order. */
#ifndef VLBE_EX_ALE_H
#define VLBE_EX_ALE_H

#include "../ancf_ale.h"
#include "../integrators.h"

#include <string.h>

static inline void ex_ale_wire(vlbe_dae *sys, vlbe_ale_chain *ch)
{
    int i;
    memset(sys, 0, sizeof *sys);
    sys->n = ch->n;
    sys->m = ch->m;
    sys->user = ch;
    sys->mass = vlbe_ale_chain_mass;
    sys->force = vlbe_ale_chain_force;
    sys->force_jac = vlbe_ale_chain_force_jac;
    sys->mass_jac = vlbe_ale_chain_mass_jac;
    sys->constr = vlbe_ale_chain_constr;
    sys->constr_jac = vlbe_ale_chain_constr_jac;
    sys->constr_acc = vlbe_ale_chain_constr_acc;
    sys->constr_hess = vlbe_ale_chain_constr_hess;
    /* a planar chain whose material coordinates are all fixed has the
       classic constant ANCF mass matrix (point masses included): no
       d(Ma)/dq, and the integrators evaluate M once */
    for (i = 0; i < ch->nn && ch->node[i].pmode == VLBE_ALE_PFIXED; ++i) continue;
    if (ch->d == 2 && i == ch->nn) sys->flags |= VLBE_DAE_MASS_CONST;
    if (ch->order) { /* banded mode (vlbe_ale_chain_band): the layout's band */
        sys->storage = VLBE_DAE_BANDED;
        sys->kl = ch->kl;
        sys->ku = ch->ku;
        sys->order = ch->order;
    }
}

#endif /* VLBE_EX_ALE_H */
