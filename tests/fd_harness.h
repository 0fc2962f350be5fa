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
   fd_compare(c, J, skip, cols, rel, rnd, Jfd, st)
                                   J (n x n, analytic) against Jfd, entry by entry,
                                   each at the scale of its row and column;
                                   returns the worst error / tolerance
   fd_check(c, J, skip, cols, rel, rnd, what, st)
                                   the same, failing the test when it is > 1 */
#ifndef VLBE_TEST_FD_HARNESS_H
#define VLBE_TEST_FD_HARNESS_H

#include <string.h>

/* largest n (and nout) of a context: the 3D element with spin */
#define FD_NMAX 16

/* the least rounding term of fd_compare, in units of EPS fmax / h */
#define FD_RND 16.0

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

/* The worst entry of one comparison (fd_compare, fd_check): ratio = err /
   tol there, i, j its row and column, sij its effective scale tol_ij / rel
   (s_ij of fd_compare, or more where the rounding term decides; s_ij when
   rel = 0), err and tol relative to sij (so tol = rel when rel > 0: err <=
   rel exactly when the entry passes); scale = the largest |entry| of J and
   Jfd over the whole matrix (zero when both are exactly zero: nothing
   checked). */
typedef struct fd_stats {
    double ratio, err, tol, scale, sij;
    int i, j;
} fd_stats;

/* J (n x n, analytic, d out / d x) against central differences, entry by
   entry, each at its own scale: the absolute tolerance of entry (i, j) is
       tol_ij = min(rel s_ij + max(rnd, FD_RND EPS) fmax / h,
                    rel scale + rnd fmax / h),     s_ij = max(R_i, C_j),
   R_i (C_j) the largest |entry| of row i (column j) of J and Jfd over the
   entries checked (both matrices, so that a Jacobian that is wrongly zero
   cannot pass), scale the largest over the whole matrix, fmax the largest
   value eval returned (the size of the outputs it rounded; h the step as
   set, before the max(1, |x_j|)).
   The truncation error h^2/6 |d3 out_i / dx_j^3| of a difference follows
   the size of the derivatives of out_i and in x_j, not that of the
   largest entry of the matrix: a block of small entries (a spin inertia
   rhoI ~ 1e-5 rhoA, a p-row, a slope column) is checked at its own size
   instead of hiding behind the largest one (the whole-matrix form, the
   second term of the min, was the tolerance of every entry before).
   Rounding: every difference divides the rounding of outputs of size fmax
   by h, EPS fmax / h, whatever the size of the entry; the whole-matrix
   form hid it in rel scale, so at the entry's own scale it needs a term of
   its own: at least FD_RND = 16 EPS fmax / h (a sum of a dozen rounded
   terms).  Found necessary, both rounding: test_ale3.c curvature, K of a
   straight element, row r2_x and column r1_x zero in exact arithmetic (J
   1e-15, Jfd 9.9e-11 = 2.0 EPS fmax / h); test_rancf.c force_jacobians, D
   entry (2, 5) of 1.7e-3 in a row and column of 1.6e-2, differenced 6.1e-11
   = 0.34 EPS fmax / h off (fmax 4.9).  The min keeps every
   tolerance at or below the whole-matrix one: no check is looser.
   skip (may be NULL): coordinates i with skip[i] != 0 are left out as rows
   and as columns (not coordinates in this mode: their Jfd is zero; their J
   counts only in scale).  cols (may be NULL): only the columns with
   cols[j] != 0 are differenced, counted and checked.  Returns the worst
   |Jfd - J| / tol_ij (0 when J and Jfd are both exactly zero); st (may be
   NULL) gets that entry.  Jfd (n x n): the differences.  Asserts nothing:
   fd_check does. */
static inline double fd_compare(fd_ctx *c, const vlbe_real *J, const int *skip, const int *cols,
                                double rel, double rnd, double *Jfd, fd_stats *st)
{
    const int n = c->n;
    double R[FD_NMAX], C[FD_NMAX], scale = 0.0, floor_, old_tol, worst = 0.0;
    int use[FD_NMAX] = {0}, i, j;
    fd_stats s0 = {0.0, 0.0, 0.0, 0.0, 0.0, -1, -1};
    c->nout = n;
    for (j = 0; j < n; ++j) use[j] = (!cols || cols[j]) && !(skip && skip[j]);
    fd_jac(c, use, Jfd);
    for (i = 0; i < n; ++i) {
        R[i] = C[i] = 0.0;
        if (skip && skip[i])
            for (j = 0; j < n; ++j) Jfd[i * n + j] = 0.0;
    }
    for (i = 0; i < n; ++i)
        for (j = 0; j < n; ++j) {
            const double a = fmax(fabs((double)J[i * n + j]), fabs(Jfd[i * n + j]));
            if (!cols || cols[j]) scale = fmax(scale, a);
            if (!use[j] || (skip && skip[i])) continue;
            R[i] = fmax(R[i], a);
            C[j] = fmax(C[j], a);
        }
    if (st) *st = s0;
    if (scale == 0.0) return 0.0; /* both exactly zero (e.g. D undamped, p fixed) */
    floor_ = fmax(rnd, FD_RND * (double)VLBE_EPS) * c->fmax / c->h;
    old_tol = rel * scale + rnd * c->fmax / c->h;
    for (i = 0; i < n; ++i)
        for (j = 0; j < n; ++j) {
            const double sij = fmax(R[i], C[j]), tol = fmin(rel * sij + floor_, old_tol);
            const double e = fabs(Jfd[i * n + j] - (double)J[i * n + j]);
            double r;
            if (!use[j] || (skip && skip[i])) continue;
            r = tu_err_ratio(Jfd[i * n + j], (double)J[i * n + j], 0.0, tol);
            if (!(r <= worst) || (st && st->i < 0)) { /* NaN counts as the worst */
                worst = r;
                if (st) {
                    /* relative to the entry's effective scale tol / rel
                       (s_ij, or more where the rounding term decides), so
                       that err <= tol = rel exactly when it passes */
                    const double se = rel > 0.0 ? tol / rel : sij;
                    st->ratio = r;
                    st->err = se > 0.0 ? e / se : 0.0;
                    st->tol = se > 0.0 ? tol / se : 0.0;
                    st->sij = se;
                    st->i = i;
                    st->j = j;
                }
                if (r != r) goto out;
            }
        }
out:
    if (st) st->scale = scale;
    return worst;
}

/* fd_compare, then fails (with the entry, mode and scales) when the worst
   entry is outside its tolerance.  Returns the worst ratio. */
static inline double fd_check(fd_ctx *c, const vlbe_real *J, const int *skip, const int *cols,
                              double rel, double rnd, const char *what, fd_stats *st)
{
    double Jfd[FD_NMAX * FD_NMAX];
    fd_stats s;
    const double r = fd_compare(c, J, skip, cols, rel, rnd, Jfd, &s);
    if (st) *st = s;
    if (!(r <= 1.0)) {
        const int n = c->n, k = s.i * n + s.j;
        fail_msg("%s: entry (%d, %d), mode %u: Jfd %.17g, J %.17g, error %.3g, tol %.3g (both "
                 "relative to the entry's scale %.3g; largest entry %.3g)",
                 what, s.i, s.j, c->mode, Jfd[k], (double)J[k], s.err, s.tol, s.sij, s.scale);
    }
    return r;
}

#endif /* VLBE_TEST_FD_HARNESS_H */
