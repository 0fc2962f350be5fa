/* ale_harness.h -- the difference harness of the planar element suites
   (test_ancf_ale.c: ancf_ale.h's element, test_rancf.c: rancf.h's): random
   states, the 32 modes, central differences of the element functions and
   the Jacobian check, over a table of the element's calls.
   -- part of vlbe                                  SPDX-License-Identifier: MIT
   Include after test_util.h, the element header and ale_fixtures.h. */
#ifndef VLBE_TEST_ALE_HARNESS_H
#define VLBE_TEST_ALE_HARNESS_H

#include <string.h>

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

/* -- central differences of the element functions ------------------------- */
enum { FD_Q_OF_Q, FD_Q_OF_QD, FD_MA_OF_Q, FD_PF_OF_Q, FD_R_OF_Q, FD_E_OF_Q };

typedef struct fd_ctx {
    const ale_ops *ops;
    const void *el;
    unsigned mode;
    int which, j;
    vlbe_real q[10], qd[10], a[10], pf, F[2];
} fd_ctx;

/* The differenced function: Q, M a, point-force Q, the point r(pf) or E
   (T, U, V, U + V) as a function of q[j] (or qd[j]); returns the argument
   rounded to vlbe_real. */
static inline double fd_fn(void *vc, double x, double *out)
{
    const fd_ctx *c = (const fd_ctx *)vc;
    vlbe_real q[10], qd[10], buf[100];
    const vlbe_real xr = (vlbe_real)x;
    int i, k;
    memcpy(q, c->q, sizeof q);
    memcpy(qd, c->qd, sizeof qd);
    if (c->which == FD_Q_OF_QD)
        qd[c->j] = xr;
    else
        q[c->j] = xr;
    switch (c->which) {
    case FD_Q_OF_Q:
    case FD_Q_OF_QD:
        assert_int_equal(c->ops->force(c->el, c->mode, q, qd, buf), VLBE_OK);
        for (i = 0; i < 10; ++i) out[i] = (double)buf[i];
        break;
    case FD_MA_OF_Q:
        assert_int_equal(c->ops->mass(c->el, c->mode, q, buf), VLBE_OK);
        for (i = 0; i < 10; ++i) {
            out[i] = 0.0;
            for (k = 0; k < 10; ++k) out[i] += (double)buf[i * 10 + k] * (double)c->a[k];
        }
        break;
    case FD_PF_OF_Q:
        fill(10, VLBE_R(0.0), buf);
        assert_int_equal(c->ops->point_force(c->el, q, c->pf, c->F, buf), VLBE_OK);
        for (i = 0; i < 10; ++i) out[i] = (double)buf[i];
        break;
    case FD_R_OF_Q:
        fill(2, VLBE_R(0.0), buf);
        assert_int_equal(c->ops->point(c->el, q, c->pf, buf), VLBE_OK);
        out[0] = (double)buf[0];
        out[1] = (double)buf[1];
        break;
    default:
        assert_int_equal(c->ops->energy(c->el, c->mode, q, qd, buf), VLBE_OK);
        for (i = 0; i < 3; ++i) out[i] = (double)buf[i];
        out[3] = (double)buf[1] + (double)buf[2];
        break;
    }
    return (double)xr;
}

/* J (10 x 10, analytic, d out / d var) against central differences (step
   EPS^(1/3) times max(1, |x|)) over the columns j that are coordinates
   (skip: coordinates fixed in mode), rows likewise.  The error of entry
   (i, j) is measured against the largest entry of the matrix (analytic or
   differenced, so that a Jacobian that is wrongly zero cannot pass): max
   |J_fd - J| / max(|J|, |J_fd|) <= tol.  Returns that measured ratio. */
static inline double check_jac(fd_ctx *c, int which, const vlbe_real *J, unsigned skip,
                               double tol, const char *what)
{
    double Jfd[100], d[10], work[10], scale, worst = 0.0;
    int i, j;
    c->which = which;
    for (j = 0; j < 10; ++j) {
        const double x = which == FD_Q_OF_QD ? (double)c->qd[j] : (double)c->q[j];
        c->j = j;
        if (is_fixed(skip, j)) {
            for (i = 0; i < 10; ++i) Jfd[i * 10 + j] = 0.0;
            continue;
        }
        tu_central_diff(fd_fn, c, x, tu_fd_step((double)VLBE_EPS, fmax(1.0, fabs(x))), 10, work,
                        d);
        for (i = 0; i < 10; ++i) Jfd[i * 10 + j] = is_fixed(skip, i) ? 0.0 : d[i];
    }
    scale = fmax(max_abs(100, J), tu_max_abs(100, Jfd));
    if (scale == 0.0) return 0.0; /* both exactly zero (e.g. D without damping and p') */
    for (i = 0; i < 10; ++i)
        for (j = 0; j < 10; ++j) {
            if (is_fixed(skip, i) || is_fixed(skip, j)) continue;
            worst = fmax(worst, fabs(Jfd[i * 10 + j] - (double)J[i * 10 + j]) / scale);
            ASSERT_CLOSE_CTX(Jfd[i * 10 + j], J[i * 10 + j], 0, tol * scale,
                             "%s: entry (%d, %d), mode %u, max entry %.3g", what, i, j, c->mode,
                             scale);
        }
    return worst;
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
    fd_ctx c;
    double d[4], work[4];
    int j;
    c.ops = ops;
    c.el = el;
    c.mode = mode;
    c.which = FD_E_OF_Q;
    memcpy(c.q, q, sizeof c.q);
    memcpy(c.qd, qd, sizeof c.qd);
    for (j = 0; j < 10; ++j) {
        const double x = (double)q[j];
        c.j = j;
        tu_central_diff(fd_fn, &c, x, tu_fd_step((double)VLBE_EPS, fmax(1.0, fabs(x))), 4, work,
                        d);
        grad[j] = d[which];
    }
}

#endif /* VLBE_TEST_ALE_HARNESS_H */
