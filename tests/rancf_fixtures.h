/* rancf_fixtures.h -- what the suites of rational chains share: an
   element written byte for byte defined, for memcmp snapshots.
   -- part of vlbe                                  SPDX-License-Identifier: MIT
   Include after test_util.h and ../rancf.h. */
#ifndef VLBE_TEST_RANCF_FIXTURES_H
#define VLBE_TEST_RANCF_FIXTURES_H

#include <string.h>

/* An element with weights w and Gauss orders ng (0: defaults), written to
   dst through a zeroed object so that every byte of it is defined (the
   library's init leaves the unused rule points and the padding as they
   were in its local, which memcmp would read under valgrind). */
static inline void rancf_el_init(vlbe_rancf_elem *dst, const vlbe_ale_mat *mat, const vlbe_real *w,
                                 int ng)
{
    static vlbe_rancf_elem tmp;
    vlbe_ale_rule *rd[3];
    const vlbe_ale_rule *rs[3];
    int r;
    assert_int_equal(vlbe_rancf_elem_init(&tmp, mat, w, 0u, ng, ng, ng), VLBE_OK);
    memset(dst, 0, sizeof *dst);
    memcpy(dst->k, tmp.k, sizeof tmp.k);
    dst->ale.mat = tmp.ale.mat;
    dst->ale.flags = tmp.ale.flags;
    rd[0] = &dst->ale.rm;
    rd[1] = &dst->ale.rl;
    rd[2] = &dst->ale.rt;
    rs[0] = &tmp.ale.rm;
    rs[1] = &tmp.ale.rl;
    rs[2] = &tmp.ale.rt;
    for (r = 0; r < 3; ++r) {
        rd[r]->n = rs[r]->n;
        memcpy(rd[r]->g, rs[r]->g, (size_t)rs[r]->n * sizeof rs[r]->g[0]);
    }
    memcpy(dst->ale.ends, tmp.ale.ends, sizeof tmp.ale.ends);
    memcpy(&dst->ale.inv, &tmp.ale.inv, sizeof tmp.ale.inv);
}

#endif /* VLBE_TEST_RANCF_FIXTURES_H */
