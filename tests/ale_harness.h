/* ale_harness.h -- the difference harness of the planar element suites
   (test_ancf_ale.c: ancf_ale.h's element, test_rancf.c: rancf.h's): random
   states, the 32 modes, central differences of the element functions and
   the Jacobian check, over a table of the element's calls.
   -- part of vlbe                                  SPDX-License-Identifier: MIT
   The differences themselves are fd_harness.h's (included here).
   Include after test_util.h, the element header and ale_fixtures.h. */
#ifndef VLBE_TEST_ALE_HARNESS_H
#define VLBE_TEST_ALE_HARNESS_H

#include <string.h>

#include "fd_harness.h"

/* The calls of one planar element type (el: that type, as the suite's
   adapters cast it back): Q alone, M, a point force's Q (added to a zeroed
   Q), the point r(p), E = {T, U, V}. */
typedef struct ale_ops {
    vlbe_status (*force)(const void *el, unsigned mode, const vlbe_real *q, const vlbe_real *qd,
                         vlbe_real *Q);
    vlbe_status (*mass)(const void *el, unsigned mode, const vlbe_real *q, vlbe_real *M);
    vlbe_status (*point_force)(const void *el, const vlbe_real *q, vlbe_real pf,
                               const vlbe_real *F, vlbe_real *Q);
    vlbe_status (*point)(const void *el, const vlbe_real *q, vlbe_real p, vlbe_real *r);
    vlbe_status (*energy)(const void *el, unsigned mode, const vlbe_real *q, const vlbe_real *qd,
                          vlbe_real *E);
} ale_ops;

static inline int is_p(int i) { return i == 4 || i == 9; }

/* 1 when coordinate i is a fixed material coordinate in mode */
static inline int is_fixed(unsigned mode, int i)
{
    return (i == 4 && (mode & VLBE_ALE_FIX_P1)) || (i == 9 && (mode & VLBE_ALE_FIX_P2));
}

/* All 32 combinations of the five mode bits (NO_BEND, NO_DAMP, FIX_P1,
   FIX_P2, CONSERVATIVE). */
#define N_MODES 32
static inline unsigned mode_of(int k) { return (unsigned)k; }

/* A random deformed state: chord of material length L in [1.0, 1.4] at an
   arbitrary angle, stretched by up to +-stretch, slopes turned by up to
   +-curv rad from the chord (curv = 0.6: clearly curved, |kap| ~ 1) with
   magnitudes varying by +-10 %, velocities O(1), p' O(0.5).  qd may be NULL. */
static inline void make_state(tu_rng *g, double curv, double stretch, vlbe_real *q,
                              vlbe_real *qd)
{
    const double pi = 3.14159265358979323846;
    const double p1 = 0.3 + 0.2 * tu_rng_uniform(g), L = 1.2 + 0.2 * tu_rng_uniform(g);
    const double th = pi * tu_rng_uniform(g), s = 1.0 + stretch * tu_rng_uniform(g);
    const double x1 = tu_rng_uniform(g), y1 = tu_rng_uniform(g);
    const double a1 = th + curv * tu_rng_uniform(g), a2 = th + curv * tu_rng_uniform(g);
    const double s1 = s * (1.0 + 0.1 * tu_rng_uniform(g)), s2 = s * (1.0 + 0.1 * tu_rng_uniform(g));
    int i;
    ale_chord_q(p1, L, x1, y1, th, s, a1, a2, s1, s2, q);
    if (qd)
        for (i = 0; i < 10; ++i) qd[i] = (vlbe_real)((is_p(i) ? 0.5 : 1.0) * tu_rng_uniform(g));
}

/* -- central differences of the element functions (fd_harness.h) -------- */
enum { FD_Q_OF_Q, FD_Q_OF_QD, FD_MA_OF_Q, FD_PF_OF_Q, FD_R_OF_Q, FD_E_OF_Q };

/* The harness context of a planar element: fd (first, fd_harness.h's;
   el, mode, q, qd, a there), the element's calls, the point load. */
typedef struct ale_fd {
    fd_ctx fd;
    const ale_ops *ops;
    vlbe_real pf, F[2];
} ale_fd;

/* The differenced function (fd_eval): Q, M a, point-force Q, the point
   r(pf) or E (T, U, V, U + V). */
static inline double ale_fd_eval(const fd_ctx *fc, const vlbe_real *q, const vlbe_real *qd,
                                 double *out)
{
    const ale_fd *c = (const ale_fd *)fc;
    vlbe_real buf[100];
    int i, k;
    switch (fc->which) {
    case FD_Q_OF_Q:
    case FD_Q_OF_QD:
        assert_int_equal(c->ops->force(fc->el, fc->mode, q, qd, buf), VLBE_OK);
        for (i = 0; i < 10; ++i) out[i] = (double)buf[i];
        break;
    case FD_MA_OF_Q:
        assert_int_equal(c->ops->mass(fc->el, fc->mode, q, buf), VLBE_OK);
        for (i = 0; i < 10; ++i) {
            out[i] = 0.0;
            for (k = 0; k < 10; ++k) out[i] += (double)buf[i * 10 + k] * (double)fc->a[k];
        }
        break;
    case FD_PF_OF_Q:
        fill(10, VLBE_R(0.0), buf);
        assert_int_equal(c->ops->point_force(fc->el, q, c->pf, c->F, buf), VLBE_OK);
        for (i = 0; i < 10; ++i) out[i] = (double)buf[i];
        break;
    case FD_R_OF_Q:
        fill(2, VLBE_R(0.0), buf);
        assert_int_equal(c->ops->point(fc->el, q, c->pf, buf), VLBE_OK);
        out[0] = (double)buf[0];
        out[1] = (double)buf[1];
        break;
    default:
        assert_int_equal(c->ops->energy(fc->el, fc->mode, q, qd, buf), VLBE_OK);
        for (i = 0; i < 3; ++i) out[i] = (double)buf[i];
        out[3] = (double)buf[1] + (double)buf[2];
        break;
    }
    return tu_max_abs(fc->nout, out);
}

/* c zeroed, for the element el (NULL for the point functions of
   ancf_ale.h) with the calls ops, in mode; step EPS^(1/3) max(1, |x|). */
static inline void ale_fd_init(ale_fd *c, const ale_ops *ops, const void *el, unsigned mode)
{
    memset(c, 0, sizeof *c);
    fd_init(&c->fd, 10, ale_fd_eval, el, mode);
    c->ops = ops;
}

/* Selects the differenced function: which of FD_*, in q or in qd. */
static inline void ale_fd_use(ale_fd *c, int which)
{
    c->fd.which = which;
    c->fd.wrt_qd = which == FD_Q_OF_QD;
    c->fd.nout = which == FD_R_OF_Q ? 2 : which == FD_E_OF_Q ? 4 : 10;
}

/* J (10 x 10, analytic, d out / d var) against central differences
   (fd_check: step EPS^(1/3) times max(1, |x|)) over the columns j that are
   coordinates (skip: coordinates fixed in mode), rows likewise.  The error
   of entry (i, j) is measured against the scale of its row and column
   (analytic or differenced, so that a Jacobian that is wrongly zero cannot
   pass; fd_check, with its rounding floor): |J_fd - J| / scale_ij <= tol.
   Returns the worst measured ratio. */
static inline double check_jac(ale_fd *c, int which, const vlbe_real *J, unsigned skip,
                               double tol, const char *what)
{
    fd_stats st;
    int sk[10], i;
    for (i = 0; i < 10; ++i) sk[i] = is_fixed(skip, i);
    ale_fd_use(c, which);
    (void)fd_check(&c->fd, J, sk, NULL, tol, 0.0, what, &st);
    return st.err;
}

/* Rows and columns of fixed p are exactly zero. */
static inline void check_fixed_zero(unsigned mode, const vlbe_real *Q, const vlbe_real *J)
{
    int i, k;
    for (k = 4; k < 10; k += 5) {
        if (!is_fixed(mode, k)) continue;
        if (Q) ASSERT_CLOSE_CTX(Q[k], 0.0, 0, 0, "Q[%d], mode %u", k, mode);
        for (i = 0; i < 10; ++i) {
            ASSERT_CLOSE_CTX(J[k * 10 + i], 0.0, 0, 0, "row %d col %d, mode %u", k, i, mode);
            ASSERT_CLOSE_CTX(J[i * 10 + k], 0.0, 0, 0, "row %d col %d, mode %u", i, k, mode);
        }
    }
}

/* d(E[which])/dq by central differences, all ten columns (which: 0 T, 1 U,
   2 V, 3 U + V). */
static inline void energy_grad(const ale_ops *ops, const void *el, unsigned mode,
                               const vlbe_real *q, const vlbe_real *qd, int which, double *grad)
{
    ale_fd c;
    double Jfd[4 * 10];
    int j;
    ale_fd_init(&c, ops, el, mode);
    memcpy(c.fd.q, q, 10 * sizeof *q);
    memcpy(c.fd.qd, qd, 10 * sizeof *qd);
    ale_fd_use(&c, FD_E_OF_Q);
    fd_jac(&c.fd, NULL, Jfd);
    for (j = 0; j < 10; ++j) grad[j] = Jfd[which * 10 + j];
}

#endif /* VLBE_TEST_ALE_HARNESS_H */
