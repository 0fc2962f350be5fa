/* ex_ale.h -- banded mode of an ALE-ANCF chain (ancf_ale.h) and the
   storage of a vlbe_dae with callbacks of one's own over a chain, shared by
   the examples, tests and benchmarks.  A chain's own vlbe_dae is
   vlbe_ale_chain_dae.
   -- part of vlbe                                  SPDX-License-Identifier: MIT */
#ifndef VLBE_EX_ALE_H
#define VLBE_EX_ALE_H

#include "../ancf_ale.h"
#include "../integrators.h"

/* the storage of sys's matrices that of the chain's callbacks, for a system
   whose callbacks wrap the chain's (sys->user not the chain): what
   vlbe_ale_chain_dae gives, the rest of sys kept */
static inline void ex_ale_storage(vlbe_dae *sys, vlbe_ale_chain *ch)
{
    vlbe_dae own;
    if (vlbe_ale_chain_dae(ch, &own) != VLBE_OK) return; /* not laid out: nothing to copy */
    sys->storage = own.storage;
    sys->kl = own.kl;
    sys->ku = own.ku;
    sys->order = own.order;
}

/* Banded mode of a chain set up for its layout (nodes and constraints
   added): vlbe_ale_chain_band with the caller's order (order_cap ints: n +
   m of the largest layout the chain will take, + 4 where length control
   inserts nodes), then the layout.  The coordinates keep their places
   (q, v of the dense layout stay valid); fill the system afterwards
   (vlbe_ale_chain_dae, or ex_ale_storage for a system of one's own). */
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

#endif /* VLBE_EX_ALE_H */
