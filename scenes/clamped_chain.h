/* clamped_chain.h -- the clamped chain of the scaling benchmarks
   (bench/bench_scale.c, bench/wp_chain.c): a planar ALE-ANCF chain,
   Lagrangian nodes, 10 m, steel-like section (rhoA 7.85 kg/m, EA 2.1e8 N,
   EI 1.75e3 N m^2), gravity through the distributed load, clamped at node
   0 (VLBE_ALE_CON_POS + VLBE_ALE_CON_SLOPE), straight and at rest at
   t = 0; HHT-alpha -0.05 with the default Newton settings.  Variants:
   CC_DENSE, CC_BAND (banded, vlbe_ale_chain_band, the same Newton
   settings), CC_BAND_REUSE (banded, vlbe_hht_params.reuse_max = 2: a stale
   iteration matrix refreshed when it needs more than two further
   iterations).
   Timed by bench/bench_chain.h.
   -- part of vlbe                                  SPDX-License-Identifier: MIT */
#ifndef VLBE_SCENE_CLAMPED_CHAIN_H
#define VLBE_SCENE_CLAMPED_CHAIN_H

#include "../ancf_ale.h"
#include "../integrators.h"

#include <stdlib.h>

enum { CC_DENSE, CC_BAND, CC_BAND_REUSE };
enum { CC_NMAX = 1024, CC_DENSE_MAX = 256 };

typedef struct cc_scene {
    vlbe_ale_mat mat;
    vlbe_ale_elem el;
    vlbe_ale_node node[CC_NMAX + 1];
    vlbe_ale_con con[2];
    vlbe_ale_chain ch;
    int *order;
    vlbe_dae sys;
    vlbe_hht st;
    vlbe_real *w, *q0, *v0;
    int *iw;
    size_t lw, liw;
} cc_scene;

static inline void cc_free(cc_scene *s)
{
    free(s->w);
    free(s->iw);
    free(s->q0);
    free(s->v0);
    free(s->order);
}

/* builds the chain of ne elements in the variant asked for, and starts HHT */
static inline int cc_init(cc_scene *s, int ne, int variant)
{
    vlbe_ale_con c;
    vlbe_hht_params par;
    vlbe_real r0[2] = {0, 0}, dir[2] = {1, 0};
    int i;
    memset(s, 0, sizeof *s);
    s->mat.rhoA = VLBE_R(7.85);
    s->mat.EA = VLBE_R(2.1e8);
    s->mat.EI = VLBE_R(1.75e3);
    s->mat.f[1] = VLBE_R(-9.81) * s->mat.rhoA;
    if (vlbe_ale_elem_init(&s->el, &s->mat, 0, 0, 0, 0)) return -1;
    for (i = 0; i <= ne; ++i) {
        s->node[i].pmode = VLBE_ALE_PFIXED;
        s->node[i].p = (vlbe_real)(10.0 * i / ne);
    }
    if (vlbe_ale_chain_init(&s->ch, &s->el, s->node, ne + 1, CC_NMAX + 1, s->con, 2)) return -1;
    memset(&c, 0, sizeof c);
    c.type = VLBE_ALE_CON_POS;
    c.node = 0;
    if (vlbe_ale_chain_add(&s->ch, &c)) return -1;
    c.type = VLBE_ALE_CON_SLOPE;
    c.d[0] = 1;
    if (vlbe_ale_chain_add(&s->ch, &c)) return -1;
    if (variant != CC_DENSE) {
        int cap = 5 * (ne + 1) + 4;
        s->order = (int *)malloc((size_t)cap * sizeof *s->order);
        if (!s->order || vlbe_ale_chain_band(&s->ch, s->order, cap)) return -1;
    }
    if (vlbe_ale_chain_layout(&s->ch)) return -1;
    if (vlbe_ale_chain_dae(&s->ch, &s->sys)) return -1;
    s->lw = vlbe_hht_work_len_sys(&s->sys);
    s->liw = vlbe_hht_iwork_len_sys(&s->sys);
    s->w = (vlbe_real *)malloc(s->lw * sizeof *s->w);
    s->iw = (int *)malloc(s->liw * sizeof *s->iw);
    s->q0 = (vlbe_real *)calloc((size_t)s->ch.n, sizeof *s->q0);
    s->v0 = (vlbe_real *)calloc((size_t)s->ch.n, sizeof *s->v0);
    if (!s->w || !s->iw || !s->q0 || !s->v0) return -1;
    vlbe_ale_chain_straight(&s->ch, r0, dir, s->q0);
    if (vlbe_hht_params_alpha(&par, VLBE_R(-0.05))) return -1;
    par.reuse_max = variant == CC_BAND_REUSE ? 2 : 0;
    return vlbe_hht_init(&s->st, &s->sys, &par, 0, s->q0, s->v0, s->w, s->lw, s->iw, s->liw) ? -1
                                                                                            : 0;
}

#endif /* VLBE_SCENE_CLAMPED_CHAIN_H */
