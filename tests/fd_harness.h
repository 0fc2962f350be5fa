/* fd_harness.h -- central-difference Jacobians of element functions, the
   harness shared by the element suites: test_ancf_ale.c and test_rancf.c
   (through ale_harness.h), test_ale3.c, test_corot2d.c, test_ale_inv.c.
   -- part of vlbe                                  SPDX-License-Identifier: MIT
   Include after test_util.h and the element header (vlbe_real, VLBE_EPS).

   A suite describes the functions it differences by one callback, eval,
   that maps a state (q, q') to nout numbers (a force Q, M a, a point r(p),
   the energies, ...), the one that c->which selects.  The harness perturbs
   one coordinate x_j of q (or of q' when wrt_qd is set), takes central
   differences with tu_central_diff and compares them with the analytic
   Jacobian.  A suite whose eval needs more than fd_ctx holds (a point load,
   the calls of an element type) makes fd_ctx the first member of its own
   context and casts back in eval.

   fd_init(c, n, eval, el, mode)   zero c; n coordinates; step EPS^(1/3) max(1, |x_j|)
   fd_column(c, j, d)              d = d out / d x_j, nout values
   fd_jac(c, cols, Jfd)            Jfd = d out / d x (nout x n), column by column
   fd_check(c, J, skip, cols, rel, rnd, what, st)
                                   J (n x n, analytic) against Jfd, entry by entry;
                                   returns the worst error / tolerance */
#ifndef VLBE_TEST_FD_HARNESS_H
#define VLBE_TEST_FD_HARNESS_H

#include <string.h>

/* largest n (and nout) of a context: the 3D element with spin */
#define FD_NMAX 16

typedef struct fd_ctx fd_ctx;

/* Writes the c->nout outputs of c->which at (q, qd) to out and returns the
   size of the numbers it rounded (max |out| for most functions), which
   fd_check's rounding term uses. */
typedef double (*fd_eval)(const fd_ctx *c, const vlbe_real *q, const vlbe_real *qd, double *out);

struct fd_ctx {
    int n;       /* coordinates: q, qd, a and the columns of J */
    int nout;    /* outputs of eval (fd_check: n) */
    fd_eval eval;
    const void *el; /* what eval works on: an element, a beam, ... */
    unsigned mode;  /* the element's mode bits, for eval and the messages */
    int which;      /* the function eval computes (the suite's codes) */
    int wrt_qd;     /* 1: difference in qd, 0: in q */
    int j;          /* the coordinate being differenced */
    double h;       /* step: h max(1, |x_j|), or h itself when h_fixed */
    int h_fixed;
    double fmax; /* largest value eval returned since fd_jac began */
    vlbe_real q[FD_NMAX], qd[FD_NMAX], a[FD_NMAX]; /* state; a: of M a */
};

/* c zeroed; n coordinates and n outputs, step EPS^(1/3) max(1, |x_j|) (its
   truncation error h^2/6 |f'''| and rounding error EPS |f| / h balance for
   h ~ EPS^(1/3) on variables O(1) or larger) */
static inline void fd_init(fd_ctx *c, int n, fd_eval eval, const void *el, unsigned mode)
{
    memset(c, 0, sizeof *c);
    assert_true(n > 0 && n <= FD_NMAX);
    c->n = n;
    c->nout = n;
    c->eval = eval;
    c->el = el;
    c->mode = mode;
    c->h = cbrt((double)VLBE_EPS);
}

/* the differenced function of x_j for tu_central_diff; returns the argument
   rounded to vlbe_real (the one really used) */
static inline double fd__fn(void *vc, double x, double *out)
{
    fd_ctx *c = (fd_ctx *)vc;
    vlbe_real q[FD_NMAX], qd[FD_NMAX];
    const vlbe_real xr = (vlbe_real)x;
    memcpy(q, c->q, sizeof q);
    memcpy(qd, c->qd, sizeof qd);
    if (c->wrt_qd)
        qd[c->j] = xr;
    else
        q[c->j] = xr;
    c->fmax = fmax(c->fmax, c->eval(c, q, qd, out));
    return (double)xr;
}

/* d[i] = d out_i / d x_j, i < nout, by central differences; c->fmax takes
   the values eval returns. */
static inline void fd_column(fd_ctx *c, int j, double *d)
{
    double work[FD_NMAX], x;
    assert_true(j >= 0 && j < c->n && c->nout > 0 && c->nout <= FD_NMAX);
    x = c->wrt_qd ? (double)c->qd[j] : (double)c->q[j];
    c->j = j;
    tu_central_diff(fd__fn, c, x, c->h_fixed ? c->h : c->h * fmax(1.0, fabs(x)), c->nout, work,
                    d);
}

/* Jfd (nout x n, row-major) = d out / d x over the columns j with cols[j]
   != 0 (all when cols is NULL); the other columns are zero.  c->fmax starts
   again from 0. */
static inline void fd_jac(fd_ctx *c, const int *cols, double *Jfd)
{
    const int n = c->n;
    double d[FD_NMAX];
    int i, j;
    c->fmax = 0.0;
    for (j = 0; j < n; ++j) {
        if (cols && !cols[j]) {
            for (i = 0; i < c->nout; ++i) Jfd[i * n + j] = 0.0;
            continue;
        }
        fd_column(c, j, d);
        for (i = 0; i < c->nout; ++i) Jfd[i * n + j] = d[i];
    }
}

/* The worst entry of one fd_check: ratio = err / tol, and err, tol
   relative to scale, the largest entry (all zero when scale is zero). */
typedef struct fd_stats {
    double ratio, err, tol, scale;
} fd_stats;

/* J (n x n, analytic, d out / d x) against central differences, entry by
   entry, with the absolute tolerance
       tol = rel scale + rnd fmax / h,
   scale = the largest |entry| of J and Jfd (both, so that a Jacobian that
   is wrongly zero cannot pass), fmax the largest value eval returned (the
   rounding of the outputs; h the step as set, before the max(1, |x_j|)).
   skip (may be NULL): coordinates i with skip[i] != 0 are left out as rows
   and as columns (not coordinates in this mode: their Jfd is zero, their
   J still counts in scale).  cols (may be NULL): only the columns with
   cols[j] != 0 are differenced, counted in scale and checked.  Nothing is
   checked when J and Jfd are both exactly zero.  Returns the worst
   |Jfd - J| / tol; st (may be NULL) gets it with its error and tolerance
   relative to scale. */
static inline double fd_check(fd_ctx *c, const vlbe_real *J, const int *skip, const int *cols,
                              double rel, double rnd, const char *what, fd_stats *st)
{
    const int n = c->n;
    double Jfd[FD_NMAX * FD_NMAX], scale = 0.0, tol, e = 0.0;
    int use[FD_NMAX] = {0}, i, j;
    fd_stats s0 = {0.0, 0.0, 0.0, 0.0};
    c->nout = n;
    for (j = 0; j < n; ++j) use[j] = (!cols || cols[j]) && !(skip && skip[j]);
    fd_jac(c, use, Jfd);
    for (i = 0; i < n; ++i)
        if (skip && skip[i])
            for (j = 0; j < n; ++j) Jfd[i * n + j] = 0.0;
    for (i = 0; i < n; ++i)
        for (j = 0; j < n; ++j)
            if (!cols || cols[j])
                scale = fmax(scale, fmax(fabs((double)J[i * n + j]), fabs(Jfd[i * n + j])));
    if (st) *st = s0;
    if (scale == 0.0) return 0.0; /* both exactly zero (e.g. D undamped, p fixed) */
    tol = rel * scale + rnd * c->fmax / c->h;
    for (i = 0; i < n; ++i)
        for (j = 0; j < n; ++j) {
            if ((skip && (skip[i] || skip[j])) || (cols && !cols[j])) continue;
            e = fmax(e, fabs(Jfd[i * n + j] - (double)J[i * n + j]));
            ASSERT_CLOSE_CTX(Jfd[i * n + j], J[i * n + j], 0, tol,
                             "%s: entry (%d, %d), mode %u, max entry %.3g, tol %.3g", what, i, j,
                             c->mode, scale, tol);
        }
    if (st) {
        st->ratio = e / tol;
        st->err = e / scale;
        st->tol = tol / scale;
        st->scale = scale;
    }
    return e / tol;
}

#endif /* VLBE_TEST_FD_HARNESS_H */
