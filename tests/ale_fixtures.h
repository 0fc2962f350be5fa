/* ale_fixtures.h -- what the ALE-ANCF suites share: the O(1) material of
   the random tests and small reductions over vlbe_real arrays.
   -- part of vlbe                                  SPDX-License-Identifier: MIT
   Include after test_util.h and ../ancf_ale.h. */
#ifndef VLBE_TEST_ALE_FIXTURES_H
#define VLBE_TEST_ALE_FIXTURES_H

#include "fixtures_common.h"
#include "ale_material.h"

#include <string.h>

/* Element coordinates of a chord from (x1, y1) at angle th, stretch s,
   material length L from p1, nodal slopes at angles a1, a2 with magnitudes
   s1, s2 (the random states of the suites draw these numbers). */
static inline void ale_chord_q(double p1, double L, double x1, double y1, double th, double s,
                               double a1, double a2, double s1, double s2, vlbe_real *q)
{
    q[0] = (vlbe_real)x1;
    q[1] = (vlbe_real)y1;
    q[2] = (vlbe_real)(s1 * cos(a1));
    q[3] = (vlbe_real)(s1 * sin(a1));
    q[4] = (vlbe_real)p1;
    q[5] = (vlbe_real)(x1 + s * L * cos(th));
    q[6] = (vlbe_real)(y1 + s * L * sin(th));
    q[7] = (vlbe_real)(s2 * cos(a2));
    q[8] = (vlbe_real)(s2 * sin(a2));
    q[9] = (vlbe_real)(p1 + L);
}

static inline double max_abs(int n, const vlbe_real *a)
{
    double m = 0.0;
    int i;
    for (i = 0; i < n; ++i) m = fmax(m, fabs((double)a[i]));
    return m;
}

/* a chain node with material coordinate p in mode pmode, nothing else */
static inline vlbe_ale_node node_make(int pmode, double p)
{
    vlbe_ale_node nd;
    memset(&nd, 0, sizeof nd);
    nd.pmode = pmode;
    nd.p = (vlbe_real)p;
    return nd;
}

/* The 7 nodes of the mixed planar chains of the assembly suites:
     0 fixed p = 0.1, 1 free 0.35, 2 free 0.6 sliding with a point mass
     0.6, 3 prescribed p = 0.8 + 0.3 t - 0.35 t^2, 4 free 1.05, 5 free 1.3,
     6 fixed p = 1.5 with a point mass 0.25 */
static inline void nodes_mixed7(vlbe_ale_node *node)
{
    node[0] = node_make(VLBE_ALE_PFIXED, 0.1);
    node[1] = node_make(VLBE_ALE_PFREE, 0.35);
    node[2] = node_make(VLBE_ALE_PFREE, 0.6);
    node[2].slide = 1;
    node[2].mass = VLBE_R(0.6);
    node[3] = node_make(VLBE_ALE_PPRESCRIBED, 0.8);
    node[3].pd = VLBE_R(0.3);
    node[3].pdd = VLBE_R(-0.7);
    node[4] = node_make(VLBE_ALE_PFREE, 1.05);
    node[5] = node_make(VLBE_ALE_PFREE, 1.3);
    node[6] = node_make(VLBE_ALE_PFIXED, 1.5);
    node[6].mass = VLBE_R(0.25);
}

/* a chain constraint; v0, v1, v2 go to the field its type reads: the
   position r (POS), the slope or direction d (SLOPE, SLOPE_DIR), the law
   g0, g1, g2 (P, SPIN, SLOPE_ANGLE); nothing for the others */
static inline vlbe_ale_con con_make(int type, int node, int node2, int which, double v0,
                                    double v1, double v2)
{
    vlbe_ale_con c;
    vlbe_real *f = NULL;
    memset(&c, 0, sizeof c);
    c.type = type;
    c.node = node;
    c.node2 = node2;
    c.which = which;
    switch (type) {
    case VLBE_ALE_CON_POS: f = c.r; break;
    case VLBE_ALE_CON_SLOPE: case VLBE_ALE_CON_SLOPE_DIR: f = c.d; break;
    case VLBE_ALE_CON_P: case VLBE_ALE_CON_SPIN: case VLBE_ALE_CON_SLOPE_ANGLE: f = c.law; break;
    default: break;
    }
    if (f) {
        f[0] = (vlbe_real)v0;
        f[1] = (vlbe_real)v1;
        f[2] = (vlbe_real)v2;
    }
    return c;
}

/* a 3D slope-rotation constraint (VLBE_ALE_CON_SLOPE_ROT) at node: e0, the
   axis k and the law g0, g1, g2 of the angle */
static inline vlbe_ale_con con_rot(int node, const double *e0, const double *k, double g0,
                                   double g1, double g2)
{
    vlbe_ale_con c;
    int i;
    memset(&c, 0, sizeof c);
    c.type = VLBE_ALE_CON_SLOPE_ROT;
    c.node = node;
    for (i = 0; i < 3; ++i) {
        c.d[i] = (vlbe_real)e0[i];
        c.axis[i] = (vlbe_real)k[i];
    }
    c.law[0] = (vlbe_real)g0;
    c.law[1] = (vlbe_real)g1;
    c.law[2] = (vlbe_real)g2;
    return c;
}

#endif /* VLBE_TEST_ALE_FIXTURES_H */
