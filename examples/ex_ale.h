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

/* the storage of sys's matrices that of the chain's callbacks: banded
   with the layout's order and half-bandwidths when the chain is in banded
   mode (vlbe_ale_chain_band), else dense (kl = ku = 0, order NULL) */
static inline void ex_ale_storage(vlbe_dae *sys, const vlbe_ale_chain *ch)
{
    sys->storage = ch->order ? VLBE_DAE_BANDED : VLBE_DAE_DENSE;
    sys->kl = ch->order ? ch->kl : 0;
    sys->ku = ch->order ? ch->ku : 0;
    sys->order = ch->order;
}

/* Banded mode of a chain set up for its layout (nodes and constraints
   added): vlbe_ale_chain_band with the caller's order (order_cap ints: n +
   m of the largest layout the chain will take, + 4 where length control
   inserts nodes), then the layout.  The coordinates keep their places
   (q, v of the dense layout stay valid); wire the system afterwards
   (ex_ale_wire, or ex_ale_storage for a system of one's own). */
static inline vlbe_status ex_ale_band(vlbe_ale_chain *ch, int *order, int order_cap)
{
    vlbe_status st = vlbe_ale_chain_band(ch, order, order_cap);
    return st != VLBE_OK ? st : vlbe_ale_chain_layout(ch);
}

/* Half-bandwidth bound of a planar or 3D chain whose nodes carry at most
   nc coordinates and that has m constraint rows and no equal-length
   groups: an element couples two nodes, and the rows of its first node sit
   between their coordinates, so kl = ku <= 2 nc + m - 1 in every layout of
   it (vlbe_ale_chain).  Sizes the workspace of a chain that re-layouts. */
static inline int ex_ale_kl_bound(int nc, int m) { return 2 * nc + m - 1; }

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
    ex_ale_storage(sys, ch); /* banded mode (vlbe_ale_chain_band): the layout's band */
}

#endif /* VLBE_EX_ALE_H */
