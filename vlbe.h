/* vlbe.h -- core of vlbe: configuration, status codes, small vector ops,
   Gauss-Legendre rules, the cubic Hermite / linear basis in ALE form, dense
   and banded LU, dense eigen-solvers
   -- part of vlbe v0.1.0                           SPDX-License-Identifier: MIT

USAGE
   #include "vlbe.h"        (every vlbe module includes it; keep the files
                             of vlbe flat in one directory)
   No IMPLEMENTATION macro: every function is static inline.  Link with -lm.
   Vendoring unit: vlbe.h plus the modules you need (ancf_ale.h, rancf.h,
   corot2d.h, integrators.h), copied side by side.

CONFIG (define before the first #include; the first group is GLOBAL: set it
        with -D for every translation unit of a program, never per file)
   VLBE_USE_FLOAT   vlbe_real = float, literals VLBE_R(x) = x##f, libm float
                    names, VLBE_EPS = FLT_EPSILON.  Default: double.
   VLBE_INLINE      prefix of every private function (vlbe__), default
                    `static inline`
   VLBE_API         prefix of every public function, default VLBE_INLINE
   VLBE_RESTRICT    default `restrict` (C99), `__restrict` (C++), empty else
   VLBE_ASSERT(x)   precondition check of the pure kernels.  Default: assert(x)
                    on a hosted system (__unix__, __APPLE__, _WIN32); on bare
                    metal a trap (__builtin_trap, else abort) that links no
                    printf or malloc; nothing under NDEBUG.  Define it to
                    route failures to your own handler
   vlbe_sqrt ... vlbe_floor   the libm names; override all of them or none
   vlbe_frexp, vlbe_ldexp     the same for the two exponent functions (a
                    group of their own: override both or neither)

CONVENTIONS
   Units: any consistent system (SI in all examples); angles in radians.
   Matrices are flat and row-major, A[i*n + j].  Inputs first, then outputs,
   then workspace.  Output pointers are VLBE_RESTRICT: they must not alias
   inputs unless a function says otherwise.
   Errors: functions whose result depends on the data return vlbe_status
   (0 = VLBE_OK, negative = a specific failure); a failed call leaves the
   caller's data as it was before the call.  Programmer errors (NULL, n < 1)
   are caught by VLBE_ASSERT.  Nothing here allocates, prints or aborts.
   Stack: at most 408 bytes per function (vlbe_eig_quad, 384 for
   vlbe_herm_ale_eval; float on a Cortex-M4F, gcc -O2, make check-m4;
   double about twice; docs/embedded.md).

   FAILURE CONTRACT (every vlbe module keeps it).  (1) A routine returning
   vlbe_status never returns VLBE_OK with a NaN or Inf in an output when its
   inputs are finite: it returns VLBE_ENONFINITE, or a more specific code
   when an input is outside its range (VLBE_ELENGTH, VLBE_EWEIGHT, ...).
   (2) Every index and size argument is range-checked before use (without
   overflow in the check) and VLBE_EARG returned when out of range.  (3) A
   call that fails leaves every caller-visible output bitwise as it was:
   arrays, *out scalars, structs passed by pointer, counters; the only
   exceptions are documented at the function (buffers documented as
   scratch, e.g. the LU of vlbe_lu_factor after a failed elimination).
   (4) A NULL where the documentation requires a pointer is a programmer
   error (VLBE_ASSERT); every pointer documented as optional may be NULL.

   ALE basis.  A material point p on an element whose nodes sit at material
   coordinates p1 < p2 (L = p2 - p1, s = (2p - p1 - p2)/L in [-1, 1],
   xi = (p - p1)/L = (s + 1)/2 in [0, 1]).  The cubic Hermite functions
   (vlbse eq. 5, ale-rancf eq. 13 with unit weights) are
        N1 = (s-1)^2 (2+s)/4,   N2 = L (s-1)^2 (s+1)/8,
        N3 = (s+1)^2 (2-s)/4,   N4 = L (s+1)^2 (s-1)/8,
   multiplying r(p1), r'(p1), r(p2), r'(p2) (slopes are d/dp), and the linear
   ones (vlbse eq. 7) H1 = (1-s)/2, H2 = (1+s)/2.  vlbe_herm_ale_eval()
   returns them with their k-th derivatives in p (k <= 3) and their partial
   derivatives with respect to p1 and p2 at fixed p, up to second order,
   mixed included.  Each function is L^m g(xi), and those partials follow
   from the xi-derivatives of g alone (d/dp = D_d, d/dp2 = D_L, d/dp1 =
   -(D_d + D_L) on functions of d = p - p1 and L; formulas above
   vlbe__ale_from_xi), so one routine serves every basis of that form: the
   rational ones of rancf.h use it too.

   Band storage.  An N x N matrix with kl sub- and ku super-diagonals is
   stored by rows of its band, row-major like every vlbe matrix: entry
   (i, j), i - kl <= j <= i + ku, at B[i*ld + (j - i + kl)], leading
   dimension ld >= kl + ku + 1 (VLBE_BAND_IDX(ld, kl, i, j)).  Slots that
   fall outside the matrix (j < 0 or j >= N in the first and last rows)
   exist and are never read.  Storage N ld reals instead of N^2.  A band
   LU factor (vlbe_band_lu_factor) has kl + ku super-diagonals (the fill of
   the row interchanges): ld = vlbe_band_lu_ld(kl, ku) = 2 kl + ku + 1.

API (one line each)
   vlbe_dae                                            the problem (a type): n, m, callbacks,
                                                       flags, storage; filled by a model
                                                       (vlbe_ale_chain_dae, vlbe_cr2d_beam_dae)
                                                       or the user, solved by integrators.h
   const char *vlbe_status_str(vlbe_status s)          name of a status code
   int   vlbe_all_finite(const vlbe_real *x, int n)    1 if no NaN/Inf in x
   vlbe_real vlbe_v2_dot/cross/norm, vlbe_v2_axpy      2D vector ops
   vlbe_real vlbe_v3_dot/norm, vlbe_v3_cross/axpy      3D vector ops
   vlbe_real vlbe_vec_dot/norm2/norm_inf, vlbe_vec_axpy/copy/scale/zero  n-vectors
   void  vlbe_mat_vec(m, n, A, x, y) / vlbe_mat_tvec    y = A x, y = A^T x
   vlbe_status vlbe_gl_rule(n, &xi, &w)                Gauss-Legendre on [-1,1], n = 1..12
   void  vlbe_herm_ale_eval(p, p1, p2, kmax, amax, b)  Hermite + linear ALE basis
   vlbe_status vlbe_lu_factor(n, A, LU, piv, info)      LU with partial pivoting
   void  vlbe_lu_solve(n, LU, piv, nrhs, B)            solve with a factor, never fails
   vlbe_real vlbe_lu_flops(n)                          2/3 n^3 (for benchmarks)
   size_t vlbe_band_lu_ld(kl, ku)                      2 kl + ku + 1: ld of a band factor
   vlbe_status vlbe_band_lu_factor(n, kl, ku, A, lda, LU, piv, info)  band LU, partial pivoting
   void  vlbe_band_lu_solve(n, kl, ku, LU, piv, nrhs, B)  solve with a band factor
   void  vlbe_band_mat_vec(n, kl, ku, A, lda, x, y) / vlbe_band_mat_tvec  y = A x, A^T x (band)
   vlbe_real vlbe_band_lu_flops(n, kl, ku)             ~ n kl (2 ku + 1) (for benchmarks)
   size_t vlbe_eig_work_len(n)                         3 n^2 + n: work of eig_sym, eig_gsym
   vlbe_status vlbe_eig_sym(n, A, lam, X, work, lw)     A x = lam x, A symmetric (Jacobi)
   vlbe_status vlbe_eig_gsym(n, K, M, sigma, lam, X, info, work, lw)  K x = lam M x, shift-invert
   size_t vlbe_eig_real_work_len(n)                    4 n: work of eig_real
   vlbe_status vlbe_eig_real(n, A, wr, wi, work, lw)    eigenvalues of a general real A (QR)
   size_t vlbe_eig_quad_work_len(n), vlbe_eig_quad_iwork_len(n)  9 n^2 + 20 n, 4 n
   vlbe_status vlbe_eig_quad(n, M, D, K, sigma, sre, sim, nvec, Xre, Xim, work, lw, iwork, liw)
                                                       (s^2 M + s D + K) x = 0, shift-invert

REFERENCES
   [V] S. Yang et al., A variable-length beam element incorporating the effect
       of spinning, Lat. Am. J. Solids Struct. 14 (2017): eqs. 2-7, 15, 17.
   [R] ALE-RANCF variable-length rational element, Machines 10 (2022) 174:
       eqs. 12-15.
   Golub & Van Loan, Matrix Computations, 4th ed., alg. 3.4.1 (LU, partial
   pivoting); sec. 4.3, banded systems: alg. 4.3.1 (band Gaussian
   elimination), the band forward and back substitutions, and band
   elimination with partial pivoting (U gains kl super-diagonals).
   Eigenproblems (Golub & Van Loan, 4th ed.): alg. 8.5.1 (2-by-2 symmetric
   Schur decomposition) and 8.5.3 (cyclic Jacobi), with the threshold of
   J. Demmel and K. Veselic, Jacobi's method is more accurate than QR,
   SIAM J. Matrix Anal. Appl. 13 (1992) 1204-1245; alg. 4.2.2 (gaxpy
   Cholesky); sec. 8.7.2 (the symmetric-definite problem by Cholesky);
   sec. 7.5.7 (balancing, after Parlett and Reinsch); alg. 7.4.2
   (Householder reduction to Hessenberg form); alg. 7.5.1 (Francis QR
   step) and 7.5.2 (the QR algorithm with deflation); sec. 7.6.1 (inverse
   iteration).  The quadratic problem and its first-order form:
   F. Tisseur and K. Meerbergen, The quadratic eigenvalue problem, SIAM
   Review 43 (2001) 235-286, sec. 3.4 (linearisation) and 6 (shift-and-
   invert).
*/
#ifndef VLBE_H
#define VLBE_H

#define VLBE_VERSION_MAJOR 0
#define VLBE_VERSION_MINOR 1
#define VLBE_VERSION_PATCH 0
#define VLBE_VERSION_STRING "0.1.0"

#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include <float.h>
#include <math.h>
#include <limits.h>
/* The marker of every function: VLBE_INLINE for the private ones (vlbe__),
   VLBE_API for the public ones; both static inline unless overridden. */
#ifndef VLBE_INLINE
#define VLBE_INLINE static inline
#endif
#ifndef VLBE_API
#define VLBE_API VLBE_INLINE
#endif

/* Preconditions (programmer errors).  On a hosted system: the C assert
   (message, abort; off under NDEBUG).  Elsewhere (a bare-metal target, no
   OS macro): a trap without message, so that an embedded image does not
   link printf and malloc through assert's message; off under NDEBUG too. */
#ifndef VLBE_ASSERT
#if defined(NDEBUG)
#define VLBE_ASSERT(x) ((void)0)
#elif defined(__unix__) || defined(__unix) || defined(__APPLE__) || defined(_WIN32)
#include <assert.h>
#define VLBE_ASSERT(x) assert(x)
#else
#define VLBE_ASSERT(x) ((x) ? (void)0 : vlbe__assert_trap())
#if defined(__GNUC__) || defined(__clang__)
VLBE_INLINE void vlbe__assert_trap(void) { __builtin_trap(); }
#else
#include <stdlib.h>
VLBE_INLINE void vlbe__assert_trap(void) { abort(); }
#endif
#endif
#endif

/* index of entry (i, j) of a band-stored matrix (see Band storage above) */
#define VLBE_BAND_IDX(ld, kl, i, j) \
    ((size_t)(i) * (size_t)(ld) + (size_t)((j) - (i) + (kl)))

/* -- configuration ------------------------------------------------------ */
#ifndef VLBE_RESTRICT
#if defined(__cplusplus)
#define VLBE_RESTRICT __restrict
#elif defined(__STDC_VERSION__) && __STDC_VERSION__ >= 199901L
#define VLBE_RESTRICT restrict
#else
#define VLBE_RESTRICT
#endif
#endif

#if defined(VLBE_USE_FLOAT)
typedef float vlbe_real;
#define VLBE_R(x) x##f
#define VLBE_EPS FLT_EPSILON
#define VLBE_REAL_MAX FLT_MAX
#define VLBE_REAL_MIN FLT_MIN
#ifndef vlbe_sqrt
#define vlbe_sqrt sqrtf
#define vlbe_fabs fabsf
#define vlbe_sin sinf
#define vlbe_cos cosf
#define vlbe_atan2 atan2f
#define vlbe_pow powf
#define vlbe_exp expf
#define vlbe_log logf
#define vlbe_floor floorf
#endif
#ifndef vlbe_frexp
#define vlbe_frexp frexpf
#define vlbe_ldexp ldexpf
#endif
#else
typedef double vlbe_real;
#define VLBE_R(x) x
#define VLBE_EPS DBL_EPSILON
#define VLBE_REAL_MAX DBL_MAX
#define VLBE_REAL_MIN DBL_MIN
#ifndef vlbe_sqrt
#define vlbe_sqrt sqrt
#define vlbe_fabs fabs
#define vlbe_sin sin
#define vlbe_cos cos
#define vlbe_atan2 atan2
#define vlbe_pow pow
#define vlbe_exp exp
#define vlbe_log log
#define vlbe_floor floor
#endif
#ifndef vlbe_frexp
#define vlbe_frexp frexp
#define vlbe_ldexp ldexp
#endif
#endif

/* the bit pattern of a vlbe_real (private: the finiteness scans) and its
   masks: all but the sign, the exponent field, its lowest bit, the sign */
#if defined(VLBE_USE_FLOAT)
typedef uint32_t vlbe__bits;
#define VLBE__BITS_ABS 0x7fffffffu
#define VLBE__BITS_EXP 0x7f800000u
#define VLBE__BITS_EXP1 0x00800000u
#define VLBE__BITS_SIGN 0x80000000u
#else
typedef uint64_t vlbe__bits;
#define VLBE__BITS_ABS 0x7fffffffffffffffu
#define VLBE__BITS_EXP 0x7ff0000000000000u
#define VLBE__BITS_EXP1 0x0010000000000000u
#define VLBE__BITS_SIGN 0x8000000000000000u
#endif

#define VLBE_PI VLBE_R(3.14159265358979323846264338327950288)

/* -- constants and enums ------------------------------------------------ */
/* Status of every call whose outcome depends on the data. */
typedef enum vlbe_status {
    VLBE_OK = 0,
    VLBE_EARG = -1,       /* argument out of range (n < 1, Gauss order, ...)   */
    VLBE_EWORK = -2,      /* workspace too small: see the *_work_len() query   */
    VLBE_ESINGULAR = -3,  /* zero or relatively zero pivot in LU               */
    VLBE_ENOCONV = -4,    /* an iteration (Newton, QR) diverged or hit its limit */
    VLBE_ENONFINITE = -5, /* NaN or Inf in state, residual or Jacobian         */
    VLBE_ESTEP = -6,      /* step size fell below the minimum                  */
    VLBE_ELENGTH = -7,    /* element length p2 - p1 <= 0 or out of range      */
    VLBE_EWEIGHT = -8,    /* non-positive rational weight                      */
    VLBE_EBOUND = -9,     /* a bound set by the caller was exceeded            */
    VLBE_ECALLBACK = -10  /* a user callback reported failure                  */
} vlbe_status;

#define VLBE_GL_MAX 12 /* Gauss-Legendre rules n = 1..VLBE_GL_MAX */

/* Derivative selectors of the ALE basis with respect to the nodal material
   coordinates p1, p2 at fixed p (second index of vlbe_herm_ale.h / .l). */
enum {
    VLBE_DA_0 = 0,  /* the function itself */
    VLBE_DA_1 = 1,  /* d/dp1               */
    VLBE_DA_2 = 2,  /* d/dp2               */
    VLBE_DA_11 = 3, /* d2/dp1^2            */
    VLBE_DA_12 = 4, /* d2/dp1 dp2          */
    VLBE_DA_22 = 5, /* d2/dp2^2            */
    VLBE_DA_N = 6
};

/* -- types -------------------------------------------------------------- */
/* The cubic Hermite and linear bases at one material point (ALE form).
   h[k][a][i]: k-th derivative in p (k = 0..3) of the a-th p1/p2 partial
   (VLBE_DA_*) of N_{i+1}, i = 0..3.  l[k][a][i]: the same for H_{i+1}, k = 0,1.
   Only k <= kmax and the partial orders <= amax requested are written. */
typedef struct vlbe_herm_ale {
    vlbe_real h[4][VLBE_DA_N][4];
    vlbe_real l[2][VLBE_DA_N][2];
    vlbe_real s;  /* local coordinate (2p - p1 - p2)/L */
    vlbe_real L;  /* element length p2 - p1           */
} vlbe_herm_ale;

/* -- the problem: a constrained mechanical system -------------------------
   What a model hands to the solvers of integrators.h (and what a chain or a
   co-rotational beam fills with vlbe_ale_chain_dae, vlbe_cr2d_beam_dae):
        M(t,q,v) q'' + C_q(t,q)^T lambda = Q(t,q,v),      C(t,q) = 0.
   It lives here, below every module, so that a model fills it without
   knowing the integrators and the integrators solve it without knowing the
   model.

   Callback return values, the same for every callback of every model (the
   user's own, chains of ancf_ale.h and rancf.h, beams of corot2d.h):
      0    success;
     > 0   the point asked for lies outside the model's domain (a Newton
           iterate shortened an element below its minimum length, inverted
           it, made a matrix singular or a value non-finite; a beam node left
           its joint): the solver treats the attempt like a Newton
           divergence and may retry with a smaller step;
     < 0   fatal: the solver stops with VLBE_ECALLBACK.
   The library's models return 1 or -1 and keep the vlbe_status behind it
   and the element (or node, constraint) in their err and err_elem fields,
   by one table (vlbe__dae_rc): 1 for VLBE_ELENGTH, VLBE_ESINGULAR,
   VLBE_ENONFINITE and VLBE_EBOUND (a point outside its element: a
   co-rotational beam's node outside the prismatic joint), -1 for any
   other status (VLBE_ECALLBACK of a failing user function, VLBE_EARG).  A
   point load off the structure (VLBE_EBOUND of a load) is fatal, -1,
   in every model: where a load sits does not change with the step.
   The solvers keep the last failing value in vlbe_dae_stats.callback_rc. */
/* vlbe_dae.flags */
#define VLBE_DAE_MASS_CONST 1u /* M does not depend on t, q or v: no dM/dq terms, and
                                  HHT and BDF evaluate M once per init and keep it */
#define VLBE_DAE_MASS_V 2u     /* M depends on v too (FD of M a in v)          */
#define VLBE_DAE_NO_CHESS 4u   /* drop d(C_q^T lambda)/dq from the iteration matrix */

/* vlbe_dae.storage: how the matrix callbacks store their matrices */
#define VLBE_DAE_DENSE 0  /* n x n and m x n row-major (the default)            */
#define VLBE_DAE_BANDED 1 /* (n+m) x (n+m) bands in the augmented order          */

/* The problem: callbacks with a user context.  mass, force are required;
   constr and constr_jac when m > 0.  The rest is optional (NULL). */
typedef struct vlbe_dae {
    int n;        /* number of coordinates q                */
    int m;        /* number of constraints                  */
    unsigned flags;
    void *user;
    /* M(t,q,v), n*n */
    int (*mass)(void *user, vlbe_real t, const vlbe_real *q, const vlbe_real *v, vlbe_real *M);
    /* Q(t,q,v), n */
    int (*force)(void *user, vlbe_real t, const vlbe_real *q, const vlbe_real *v, vlbe_real *Q);
    /* C(t,q), m */
    int (*constr)(void *user, vlbe_real t, const vlbe_real *q, vlbe_real *C);
    /* C_q (m*n) and C_t (m); Ct may be NULL when the caller does not need it */
    int (*constr_jac)(void *user, vlbe_real t, const vlbe_real *q, vlbe_real *Cq, vlbe_real *Ct);
    /* optional: gamma = -( (C_q v)_q v + 2 C_qt v + C_tt ), the right side of
       C_q q'' = gamma; default: central differences of C_q v + C_t along (1, v) */
    int (*constr_acc)(void *user, vlbe_real t, const vlbe_real *q, const vlbe_real *v,
                      vlbe_real *gamma);
    /* optional: K = dQ/dq and D = dQ/dv, n*n each */
    int (*force_jac)(void *user, vlbe_real t, const vlbe_real *q, const vlbe_real *v,
                     vlbe_real *K, vlbe_real *D);
    /* optional: Mq = d(M a)/dq and (if flag MASS_V) Mv = d(M a)/dv, n*n each; Mv may be NULL */
    int (*mass_jac)(void *user, vlbe_real t, const vlbe_real *q, const vlbe_real *v,
                    const vlbe_real *a, vlbe_real *Mq, vlbe_real *Mv);
    /* optional: H = d(C_q^T lambda)/dq, n*n */
    int (*constr_hess)(void *user, vlbe_real t, const vlbe_real *q, const vlbe_real *lambda,
                       vlbe_real *H);
    /* Storage of the matrices (0 = VLBE_DAE_DENSE in a zeroed struct).
       VLBE_DAE_BANDED: the model orders the augmented unknowns (q, lambda)
       so that every constraint row sits next to the coordinates it touches:
       order[i] (i < n) is the row and column of q_i in the augmented matrix
       [M*, C_q^T; C_q, 0] of size NA = n + m, order[n + k] that of
       lambda_k (a permutation of 0..NA-1), and every entry of M, K, D,
       d(Ma)/dq, d(Ma)/dv, d(C_q^T lambda)/dq, d(C_q v)/dq at (order[i],
       order[j]) and of C_q at (order[n+k], order[j]) and (order[j],
       order[n+k]) lies within kl sub- and ku super-diagonals.  Then mass,
       force_jac, mass_jac, constr_jac and constr_hess write NA x NA bands
       (vlbe.h band storage, ld = kl + ku + 1) in that order, zeros
       included: M(i, j) at VLBE_BAND_IDX(ld, kl, order[i], order[j]),
       C_q(k, j) at VLBE_BAND_IDX(ld, kl, order[n+k], order[j]) (C_q only,
       not its transpose); vectors stay in the natural order.  The
       integrators then never form an n x n matrix: workspace and work per
       step O(NA (kl + ku)). */
    int storage;
    int kl, ku;
    const int *order;
    /* optional, any storage: the caller's own linear solver for the
       iteration matrices.  lin_factor receives the assembled matrix A of
       size N (dense: N x N row-major, lda = N; banded: band storage with
       kl, ku, lda, rows and columns in the integrator's order) and returns
       0, > 0 if A is singular (VLBE_ESINGULAR), < 0 on a fatal error
       (VLBE_ECALLBACK); lin_solve then overwrites B (N x nrhs row-major)
       with A^-1 B and cannot fail.  One factorization is live at a time:
       every lin_solve uses the last successful lin_factor.  Both or
       neither. */
    int (*lin_factor)(void *user, int storage, int N, int kl, int ku, const vlbe_real *A,
                      int lda);
    void (*lin_solve)(void *user, int N, int nrhs, vlbe_real *B);
} vlbe_dae;

/* -- API prototypes ----------------------------------------------------- */
VLBE_API const char *vlbe_status_str(vlbe_status s);
VLBE_API int vlbe_all_finite(const vlbe_real *x, int n);

VLBE_API vlbe_real vlbe_v2_dot(const vlbe_real *a, const vlbe_real *b);
VLBE_API vlbe_real vlbe_v2_cross(const vlbe_real *a, const vlbe_real *b);
VLBE_API vlbe_real vlbe_v2_norm(const vlbe_real *a);
VLBE_API void vlbe_v2_axpy(vlbe_real alpha, const vlbe_real *x, vlbe_real *VLBE_RESTRICT y);
VLBE_API vlbe_real vlbe_v3_dot(const vlbe_real *a, const vlbe_real *b);
VLBE_API void vlbe_v3_cross(const vlbe_real *a, const vlbe_real *b, vlbe_real *VLBE_RESTRICT c);
VLBE_API vlbe_real vlbe_v3_norm(const vlbe_real *a);
VLBE_API void vlbe_v3_axpy(vlbe_real alpha, const vlbe_real *x, vlbe_real *VLBE_RESTRICT y);

VLBE_API vlbe_real vlbe_vec_dot(int n, const vlbe_real *a, const vlbe_real *b);
VLBE_API vlbe_real vlbe_vec_norm2(int n, const vlbe_real *a);
VLBE_API vlbe_real vlbe_vec_norm_inf(int n, const vlbe_real *a);
VLBE_API void vlbe_vec_axpy(int n, vlbe_real alpha, const vlbe_real *x, vlbe_real *VLBE_RESTRICT y);
VLBE_API void vlbe_vec_copy(int n, const vlbe_real *x, vlbe_real *VLBE_RESTRICT y);
VLBE_API void vlbe_vec_scale(int n, vlbe_real alpha, vlbe_real *x);
VLBE_API void vlbe_vec_zero(int n, vlbe_real *x);
VLBE_API void vlbe_mat_vec(int m, int n, const vlbe_real *A, const vlbe_real *x,
                           vlbe_real *VLBE_RESTRICT y);
VLBE_API void vlbe_mat_tvec(int m, int n, const vlbe_real *A, const vlbe_real *x,
                            vlbe_real *VLBE_RESTRICT y);

VLBE_API vlbe_status vlbe_gl_rule(int n, const vlbe_real **xi, const vlbe_real **w);

VLBE_API void vlbe_herm_ale_eval(vlbe_real p, vlbe_real p1, vlbe_real p2, int kmax,
                                 int amax, vlbe_herm_ale *VLBE_RESTRICT b);

VLBE_API vlbe_status vlbe_lu_factor(int n, const vlbe_real *A, vlbe_real *LU, int *piv,
                                    int *info);
VLBE_API void vlbe_lu_solve(int n, const vlbe_real *LU, const int *piv, int nrhs,
                            vlbe_real *B);
VLBE_API vlbe_real vlbe_lu_flops(int n);

VLBE_API size_t vlbe_band_lu_ld(int kl, int ku);
VLBE_API vlbe_status vlbe_band_lu_factor(int n, int kl, int ku, const vlbe_real *A, int lda,
                                         vlbe_real *LU, int *piv, int *info);
VLBE_API void vlbe_band_lu_solve(int n, int kl, int ku, const vlbe_real *LU, const int *piv,
                                 int nrhs, vlbe_real *B);
VLBE_API void vlbe_band_mat_vec(int n, int kl, int ku, const vlbe_real *A, int lda,
                                const vlbe_real *x, vlbe_real *VLBE_RESTRICT y);
VLBE_API void vlbe_band_mat_tvec(int n, int kl, int ku, const vlbe_real *A, int lda,
                                 const vlbe_real *x, vlbe_real *VLBE_RESTRICT y);
VLBE_API vlbe_real vlbe_band_lu_flops(int n, int kl, int ku);

VLBE_API size_t vlbe_eig_work_len(int n);
VLBE_API vlbe_status vlbe_eig_sym(int n, const vlbe_real *A, vlbe_real *lam, vlbe_real *X,
                                  vlbe_real *work, size_t work_len);
VLBE_API vlbe_status vlbe_eig_gsym(int n, const vlbe_real *K, const vlbe_real *M,
                                   vlbe_real sigma, vlbe_real *lam, vlbe_real *X, int *info,
                                   vlbe_real *work, size_t work_len);
VLBE_API size_t vlbe_eig_real_work_len(int n);
VLBE_API vlbe_status vlbe_eig_real(int n, vlbe_real *A, vlbe_real *wr, vlbe_real *wi,
                                   vlbe_real *work, size_t work_len);
VLBE_API size_t vlbe_eig_quad_work_len(int n);
VLBE_API size_t vlbe_eig_quad_iwork_len(int n);
VLBE_API vlbe_status vlbe_eig_quad(int n, const vlbe_real *M, const vlbe_real *D,
                                   const vlbe_real *K, vlbe_real sigma, vlbe_real *sre,
                                   vlbe_real *sim, int nvec, vlbe_real *Xre, vlbe_real *Xim,
                                   vlbe_real *work, size_t work_len, int *iwork,
                                   size_t iwork_len);

/* ===== implementation =================================================== */

VLBE_API const char *vlbe_status_str(vlbe_status s)
{
    switch (s) {
    case VLBE_OK: return "ok";
    case VLBE_EARG: return "argument out of range";
    case VLBE_EWORK: return "workspace too small";
    case VLBE_ESINGULAR: return "singular matrix";
    case VLBE_ENOCONV: return "iteration did not converge";
    case VLBE_ENONFINITE: return "non-finite value";
    case VLBE_ESTEP: return "step size below minimum";
    case VLBE_ELENGTH: return "element length out of range (p2 <= p1, too small or too large)";
    case VLBE_EWEIGHT: return "non-positive weight";
    case VLBE_EBOUND: return "bound exceeded";
    case VLBE_ECALLBACK: return "callback failed";
    }
    return "unknown status";
}

/* On the bits, integer operations only (no floating-point exception flag
   is raised) and no early exit, so the loop vectorizes: the exponent field
   plus its lowest bit carries into the sign bit exactly when the field is
   all ones (Inf, NaN), and an OR of numbers below the sign bit stays below
   it.  About twice as fast as comparing |x| with VLBE_REAL_MAX; the
   element kernels scan their outputs with it before they commit them. */
VLBE_INLINE vlbe__bits vlbe__fin_bits(const vlbe_real *x, int n)
{
    vlbe__bits b = 0, u;
    int i;
    for (i = 0; i < n; ++i) {
        memcpy(&u, &x[i], sizeof u);
        b |= (u & VLBE__BITS_EXP) + VLBE__BITS_EXP1;
    }
    return b; /* VLBE__BITS_SIGN set iff some x[i] is NaN or Inf */
}
VLBE_API int vlbe_all_finite(const vlbe_real *x, int n)
{
    VLBE_ASSERT(n >= 0 && (n == 0 || x != NULL));
    return (vlbe__fin_bits(x, n) & VLBE__BITS_SIGN) == 0;
}

/* -- small vectors ------------------------------------------------------ */
VLBE_API vlbe_real vlbe_v2_dot(const vlbe_real *a, const vlbe_real *b)
{
    return a[0] * b[0] + a[1] * b[1];
}
VLBE_API vlbe_real vlbe_v2_cross(const vlbe_real *a, const vlbe_real *b)
{
    return a[0] * b[1] - a[1] * b[0];
}
VLBE_API vlbe_real vlbe_v2_norm(const vlbe_real *a) { return vlbe_sqrt(vlbe_v2_dot(a, a)); }
VLBE_API void vlbe_v2_axpy(vlbe_real alpha, const vlbe_real *x, vlbe_real *VLBE_RESTRICT y)
{
    y[0] += alpha * x[0];
    y[1] += alpha * x[1];
}
VLBE_API vlbe_real vlbe_v3_dot(const vlbe_real *a, const vlbe_real *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
VLBE_API void vlbe_v3_cross(const vlbe_real *a, const vlbe_real *b, vlbe_real *VLBE_RESTRICT c)
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}
VLBE_API vlbe_real vlbe_v3_norm(const vlbe_real *a) { return vlbe_sqrt(vlbe_v3_dot(a, a)); }
VLBE_API void vlbe_v3_axpy(vlbe_real alpha, const vlbe_real *x, vlbe_real *VLBE_RESTRICT y)
{
    y[0] += alpha * x[0];
    y[1] += alpha * x[1];
    y[2] += alpha * x[2];
}

VLBE_API vlbe_real vlbe_vec_dot(int n, const vlbe_real *a, const vlbe_real *b)
{
    vlbe_real s = VLBE_R(0.0);
    int i;
    for (i = 0; i < n; ++i) s += a[i] * b[i];
    return s;
}
VLBE_API vlbe_real vlbe_vec_norm2(int n, const vlbe_real *a)
{
    /* scaled to avoid overflow/underflow of the squares */
    vlbe_real m = vlbe_vec_norm_inf(n, a), s = VLBE_R(0.0);
    int i;
    if (m == VLBE_R(0.0) || !isfinite(m)) return m;
    for (i = 0; i < n; ++i) {
        vlbe_real t = a[i] / m;
        s += t * t;
    }
    return m * vlbe_sqrt(s);
}
VLBE_API vlbe_real vlbe_vec_norm_inf(int n, const vlbe_real *a)
{
    vlbe_real m = VLBE_R(0.0);
    int i;
    for (i = 0; i < n; ++i) {
        vlbe_real t = vlbe_fabs(a[i]);
        if (t > m || t != t) m = t; /* NaN propagates */
    }
    return m;
}
VLBE_API void vlbe_vec_axpy(int n, vlbe_real alpha, const vlbe_real *x, vlbe_real *VLBE_RESTRICT y)
{
    int i;
    for (i = 0; i < n; ++i) y[i] += alpha * x[i];
}
VLBE_API void vlbe_vec_copy(int n, const vlbe_real *x, vlbe_real *VLBE_RESTRICT y)
{
    int i;
    for (i = 0; i < n; ++i) y[i] = x[i];
}
VLBE_API void vlbe_vec_scale(int n, vlbe_real alpha, vlbe_real *x)
{
    int i;
    for (i = 0; i < n; ++i) x[i] *= alpha;
}
VLBE_API void vlbe_vec_zero(int n, vlbe_real *x)
{
    int i;
    for (i = 0; i < n; ++i) x[i] = VLBE_R(0.0);
}
VLBE_API void vlbe_mat_vec(int m, int n, const vlbe_real *A, const vlbe_real *x,
                           vlbe_real *VLBE_RESTRICT y)
{
    int i;
    for (i = 0; i < m; ++i) y[i] = vlbe_vec_dot(n, A + (size_t)i * (size_t)n, x);
}
VLBE_API void vlbe_mat_tvec(int m, int n, const vlbe_real *A, const vlbe_real *x,
                            vlbe_real *VLBE_RESTRICT y)
{
    int i;
    vlbe_vec_zero(n, y);
    for (i = 0; i < m; ++i) vlbe_vec_axpy(n, x[i], A + (size_t)i * (size_t)n, y);
}

/* -- assembly of element matrices (chains, beams) ----------------------- */
/* The places of an element's ne coordinates in a model's assembled n x n
   matrix, as row offsets r and columns c (entry (i, j) at A[r[i] + c[j]]):
   g[i] the global coordinate (< 0: none, its row and column are skipped,
   VLBE__NOMAP); dense storage (order NULL): r = g n, c = g; band storage
   with the augmented order (see Band storage above): entry (order[g_i],
   order[g_j]) at VLBE_BAND_IDX(ld, kl, r, c) = (r (ld - 1) + kl) + c,
   ld = kl + ku + 1. */
#define VLBE__NOMAP ((size_t)-1)
VLBE_INLINE void vlbe__scatter_map(int ne, const int *g, int n, const int *order, int kl, int ku,
                                   size_t *r, size_t *c)
{
    int i;
    for (i = 0; i < ne; ++i)
        if (g[i] < 0)
            r[i] = c[i] = VLBE__NOMAP;
        else if (order) {
            r[i] = (size_t)order[g[i]] * (size_t)(kl + ku) + (size_t)kl;
            c[i] = (size_t)order[g[i]];
        } else {
            r[i] = (size_t)g[i] * (size_t)n;
            c[i] = (size_t)g[i];
        }
}

/* A += Ae (ne x ne) at the places of vlbe__scatter_map; 1 when every entry
   added to is finite afterwards (a NaN or Inf entry stays so under later
   additions; x - x == 0 only for finite x: no branch on the value) */
VLBE_INLINE int vlbe__scatter(int ne, const size_t *r, const size_t *c, const vlbe_real *Ae,
                              vlbe_real *A)
{
    int i, j, ok = 1;
    for (i = 0; i < ne; ++i) {
        if (r[i] == VLBE__NOMAP) continue;
        for (j = 0; j < ne; ++j)
            if (c[j] != VLBE__NOMAP) {
                const vlbe_real x = A[r[i] + c[j]] + Ae[i * ne + j];
                A[r[i] + c[j]] = x;
                ok &= x - x == VLBE_R(0.0);
            }
    }
    return ok;
}

/* -- models' callback values ------------------------------------------- */
/* The value a model's vlbe_dae callback returns for a failure status: the
   table of "Callback return values" at vlbe_dae (1: outside the model's
   domain, the solver may retry smaller; -1: fatal). */
VLBE_INLINE int vlbe__dae_rc(vlbe_status st)
{
    return (st == VLBE_ELENGTH || st == VLBE_ESINGULAR || st == VLBE_ENONFINITE ||
            st == VLBE_EBOUND)
               ? 1
               : -1;
}

/* -- time laws ---------------------------------------------------------- */
/* The time law of prescribed coordinates and constraints (chains of
   ancf_ale.h, beams of corot2d.h): g(t) = g0 + g1 t + g2 t^2 / 2 and its
   two derivatives, g3 = (g, g', g''). */
VLBE_INLINE void vlbe__law(vlbe_real g0, vlbe_real g1, vlbe_real g2, vlbe_real t, vlbe_real *g3)
{
    g3[0] = g0 + (g1 + VLBE_R(0.5) * g2 * t) * t;
    g3[1] = g1 + g2 * t;
    g3[2] = g2;
}

/* -- Gauss-Legendre ----------------------------------------------------- */
/* Nodes ascending on [-1, 1] and weights, 21 significant digits (computed
   with 40-digit Newton iteration on P_n; exact for polynomials of degree
   2n - 1).  Rule n starts at offset n(n-1)/2 of the packed tables. */
VLBE_API vlbe_status vlbe_gl_rule(int n, const vlbe_real **xi, const vlbe_real **w)
{
    static const vlbe_real X[VLBE_GL_MAX * (VLBE_GL_MAX + 1) / 2] = {
        VLBE_R(0.0), VLBE_R(-5.77350269189625764509e-1), VLBE_R(5.77350269189625764509e-1),
        VLBE_R(-7.74596669241483377036e-1), VLBE_R(0.0), VLBE_R(7.74596669241483377036e-1),
        VLBE_R(-8.61136311594052575224e-1), VLBE_R(-3.39981043584856264803e-1), VLBE_R(3.39981043584856264803e-1),
        VLBE_R(8.61136311594052575224e-1), VLBE_R(-9.06179845938663992798e-1), VLBE_R(-5.38469310105683091036e-1),
        VLBE_R(0.0), VLBE_R(5.38469310105683091036e-1), VLBE_R(9.06179845938663992798e-1),
        VLBE_R(-9.32469514203152027812e-1), VLBE_R(-6.61209386466264513661e-1), VLBE_R(-2.38619186083196908631e-1),
        VLBE_R(2.38619186083196908631e-1), VLBE_R(6.61209386466264513661e-1), VLBE_R(9.32469514203152027812e-1),
        VLBE_R(-9.49107912342758524526e-1), VLBE_R(-7.41531185599394439864e-1), VLBE_R(-4.05845151377397166907e-1),
        VLBE_R(0.0), VLBE_R(4.05845151377397166907e-1), VLBE_R(7.41531185599394439864e-1),
        VLBE_R(9.49107912342758524526e-1), VLBE_R(-9.60289856497536231684e-1), VLBE_R(-7.96666477413626739592e-1),
        VLBE_R(-5.25532409916328985818e-1), VLBE_R(-1.83434642495649804939e-1), VLBE_R(1.83434642495649804939e-1),
        VLBE_R(5.25532409916328985818e-1), VLBE_R(7.96666477413626739592e-1), VLBE_R(9.60289856497536231684e-1),
        VLBE_R(-9.68160239507626089836e-1), VLBE_R(-8.36031107326635794299e-1), VLBE_R(-6.13371432700590397309e-1),
        VLBE_R(-3.24253423403808929039e-1), VLBE_R(0.0), VLBE_R(3.24253423403808929039e-1),
        VLBE_R(6.13371432700590397309e-1), VLBE_R(8.36031107326635794299e-1), VLBE_R(9.68160239507626089836e-1),
        VLBE_R(-9.73906528517171720078e-1), VLBE_R(-8.65063366688984510732e-1), VLBE_R(-6.79409568299024406234e-1),
        VLBE_R(-4.33395394129247190799e-1), VLBE_R(-1.48874338981631210885e-1), VLBE_R(1.48874338981631210885e-1),
        VLBE_R(4.33395394129247190799e-1), VLBE_R(6.79409568299024406234e-1), VLBE_R(8.65063366688984510732e-1),
        VLBE_R(9.73906528517171720078e-1), VLBE_R(-9.78228658146056992804e-1), VLBE_R(-8.87062599768095299075e-1),
        VLBE_R(-7.30152005574049324093e-1), VLBE_R(-5.19096129206811815926e-1), VLBE_R(-2.69543155952344972332e-1),
        VLBE_R(0.0), VLBE_R(2.69543155952344972332e-1), VLBE_R(5.19096129206811815926e-1),
        VLBE_R(7.30152005574049324093e-1), VLBE_R(8.87062599768095299075e-1), VLBE_R(9.78228658146056992804e-1),
        VLBE_R(-9.81560634246719250691e-1), VLBE_R(-9.04117256370474856678e-1), VLBE_R(-7.69902674194304687037e-1),
        VLBE_R(-5.87317954286617447297e-1), VLBE_R(-3.67831498998180193753e-1), VLBE_R(-1.25233408511468915472e-1),
        VLBE_R(1.25233408511468915472e-1), VLBE_R(3.67831498998180193753e-1), VLBE_R(5.87317954286617447297e-1),
        VLBE_R(7.69902674194304687037e-1), VLBE_R(9.04117256370474856678e-1), VLBE_R(9.81560634246719250691e-1),
    };
    static const vlbe_real W[VLBE_GL_MAX * (VLBE_GL_MAX + 1) / 2] = {
        VLBE_R(2.0), VLBE_R(1.0), VLBE_R(1.0),
        VLBE_R(5.55555555555555555556e-1), VLBE_R(8.88888888888888888889e-1), VLBE_R(5.55555555555555555556e-1),
        VLBE_R(3.47854845137453857373e-1), VLBE_R(6.52145154862546142627e-1), VLBE_R(6.52145154862546142627e-1),
        VLBE_R(3.47854845137453857373e-1), VLBE_R(2.36926885056189087514e-1), VLBE_R(4.78628670499366468041e-1),
        VLBE_R(5.68888888888888888889e-1), VLBE_R(4.78628670499366468041e-1), VLBE_R(2.36926885056189087514e-1),
        VLBE_R(1.7132449237917034504e-1), VLBE_R(3.6076157304813860757e-1), VLBE_R(4.6791393457269104739e-1),
        VLBE_R(4.6791393457269104739e-1), VLBE_R(3.6076157304813860757e-1), VLBE_R(1.7132449237917034504e-1),
        VLBE_R(1.29484966168869693271e-1), VLBE_R(2.79705391489276667901e-1), VLBE_R(3.8183005050511894495e-1),
        VLBE_R(4.17959183673469387755e-1), VLBE_R(3.8183005050511894495e-1), VLBE_R(2.79705391489276667901e-1),
        VLBE_R(1.29484966168869693271e-1), VLBE_R(1.01228536290376259153e-1), VLBE_R(2.22381034453374470544e-1),
        VLBE_R(3.13706645877887287338e-1), VLBE_R(3.62683783378361982965e-1), VLBE_R(3.62683783378361982965e-1),
        VLBE_R(3.13706645877887287338e-1), VLBE_R(2.22381034453374470544e-1), VLBE_R(1.01228536290376259153e-1),
        VLBE_R(8.12743883615744119719e-2), VLBE_R(1.80648160694857404058e-1), VLBE_R(2.60610696402935462319e-1),
        VLBE_R(3.12347077040002840069e-1), VLBE_R(3.30239355001259763165e-1), VLBE_R(3.12347077040002840069e-1),
        VLBE_R(2.60610696402935462319e-1), VLBE_R(1.80648160694857404058e-1), VLBE_R(8.12743883615744119719e-2),
        VLBE_R(6.66713443086881375936e-2), VLBE_R(1.49451349150580593146e-1), VLBE_R(2.19086362515982043996e-1),
        VLBE_R(2.69266719309996355091e-1), VLBE_R(2.95524224714752870174e-1), VLBE_R(2.95524224714752870174e-1),
        VLBE_R(2.69266719309996355091e-1), VLBE_R(2.19086362515982043996e-1), VLBE_R(1.49451349150580593146e-1),
        VLBE_R(6.66713443086881375936e-2), VLBE_R(5.56685671161736664828e-2), VLBE_R(1.25580369464904624635e-1),
        VLBE_R(1.86290210927734251426e-1), VLBE_R(2.33193764591990479919e-1), VLBE_R(2.62804544510246662181e-1),
        VLBE_R(2.72925086777900630714e-1), VLBE_R(2.62804544510246662181e-1), VLBE_R(2.33193764591990479919e-1),
        VLBE_R(1.86290210927734251426e-1), VLBE_R(1.25580369464904624635e-1), VLBE_R(5.56685671161736664828e-2),
        VLBE_R(4.71753363865118271946e-2), VLBE_R(1.0693932599531843096e-1), VLBE_R(1.60078328543346226335e-1),
        VLBE_R(2.03167426723065921749e-1), VLBE_R(2.33492536538354808761e-1), VLBE_R(2.49147045813402785001e-1),
        VLBE_R(2.49147045813402785001e-1), VLBE_R(2.33492536538354808761e-1), VLBE_R(2.03167426723065921749e-1),
        VLBE_R(1.60078328543346226335e-1), VLBE_R(1.0693932599531843096e-1), VLBE_R(4.71753363865118271946e-2),
    };
    if (n < 1 || n > VLBE_GL_MAX) return VLBE_EARG;
    if (xi) *xi = X + n * (n - 1) / 2;
    if (w) *w = W + n * (n - 1) / 2;
    return VLBE_OK;
}

/* -- ALE basis ---------------------------------------------------------- */
/* A basis function of the ALE form is f = L^m g(xi), xi = (p - p1)/L, L =
   p2 - p1 (m = 0 for positions, 1 for slopes).  At fixed p, with D_d =
   d/dp and D_L = d/dp2 (f depends on p - p1 and p2 - p1, so d/dp1 = -(D_d +
   D_L)), and g^(c) the xi-derivatives:
     D_d^k f       = L^(m-k)   g^(k)
     D_L D_d^k f   = L^(m-k-1) A1(k),  A1(k) = (m-k) g^(k) - xi g^(k+1)
     D_L^2 D_d^k f = L^(m-k-2) A2(k),  A2(k) = (m-k)(m-k-1) g^(k)
                                              - 2 (m-k-1) xi g^(k+1) + xi^2 g^(k+2)
   (D_L maps L^n xi^e g^(c) to L^(n-1) ((n-e) xi^e g^(c) - xi^(e+1) g^(c+1))),
   whence d/dp1 = -L^(m-k-1) (g^(k+1) + A1(k)), d2/dp1dp2 = -L^(m-k-2)
   (A1(k+1) + A2(k)), d2/dp1^2 = L^(m-k-2) (g^(k+2) + 2 A1(k+1) + A2(k)).
   Any basis given by its xi-derivatives goes through here: the Hermite and
   linear ones below, the rational ones of rancf.h.  out[k*VLBE_DA_N + a]
   for k <= kmax, a < na; g[0 .. kmax + amax] must be set; Lp[i] = L^(i-5). */
VLBE_INLINE void vlbe__ale_from_xi(int m, vlbe_real xi, const vlbe_real *Lp, const vlbe_real *g,
                                   int kmax, int na, vlbe_real *out)
{
    int k;
    for (k = 0; k <= kmax; ++k) {
        const int n = m - k;
        vlbe_real *o = out + k * VLBE_DA_N;
        vlbe_real a1, a1n, a2;
        o[VLBE_DA_0] = g[k] * Lp[n + 5];
        if (na == 1) continue;
        a1 = (vlbe_real)n * g[k] - xi * g[k + 1];
        o[VLBE_DA_2] = a1 * Lp[n + 4];
        o[VLBE_DA_1] = -(g[k + 1] + a1) * Lp[n + 4];
        if (na == 3) continue;
        a1n = (vlbe_real)(n - 1) * g[k + 1] - xi * g[k + 2];
        a2 = (vlbe_real)(n * (n - 1)) * g[k] - (vlbe_real)(2 * (n - 1)) * xi * g[k + 1] +
             xi * xi * g[k + 2];
        o[VLBE_DA_22] = a2 * Lp[n + 3];
        o[VLBE_DA_12] = -(a1n + a2) * Lp[n + 3];
        o[VLBE_DA_11] = (g[k + 2] + VLBE_R(2.0) * a1n + a2) * Lp[n + 3];
    }
}

/* xi-derivatives g[c], c = 0..nd-1, of the cubic c[0] + c[1] xi + c[2] xi^2
   + c[3] xi^3 (zero beyond the third). */
VLBE_INLINE void vlbe__cubic_derivs(const vlbe_real *c, vlbe_real xi, int nd, vlbe_real *g)
{
    int i;
    for (i = 0; i < nd; ++i) g[i] = VLBE_R(0.0);
    g[0] = ((c[3] * xi + c[2]) * xi + c[1]) * xi + c[0];
    if (nd > 1) g[1] = (VLBE_R(3.0) * c[3] * xi + VLBE_R(2.0) * c[2]) * xi + c[1];
    if (nd > 2) g[2] = VLBE_R(6.0) * c[3] * xi + VLBE_R(2.0) * c[2];
    if (nd > 3) g[3] = VLBE_R(6.0) * c[3];
}

/* Fill b from the xi-derivatives g[i][c] (c <= kmax + amax) of the four
   functions multiplying r1, r1', r2, r2' (powers of L 0, 1, 0, 1) and the
   linear H1, H2 (k <= 1). */
VLBE_INLINE void vlbe__ale_basis_fill(const vlbe_real (*g)[6], vlbe_real p, vlbe_real p1,
                                      vlbe_real p2, int kmax, int amax,
                                      vlbe_herm_ale *VLBE_RESTRICT b)
{
    static const vlbe_real lin[2][4] = {{1, -1, 0, 0}, {0, 1, 0, 0}};
    vlbe_real L = p2 - p1, xi, Li, Lp[7], out[4 * VLBE_DA_N], gl[6];
    int na, k, a, i;
    VLBE_ASSERT(b != NULL && L > VLBE_R(0.0));
    VLBE_ASSERT(kmax >= 0 && kmax <= 3 && amax >= 0 && amax <= 2);
    Li = VLBE_R(1.0) / L;
    xi = (p - p1) * Li;
    b->L = L;
    b->s = VLBE_R(2.0) * xi - VLBE_R(1.0);
    Lp[6] = L;           /* L^1  */
    Lp[5] = VLBE_R(1.0); /* L^0 */
    for (i = 4; i >= 0; --i) Lp[i] = Lp[i + 1] * Li; /* L^-1 .. L^-5 */
    na = amax == 0 ? 1 : (amax == 1 ? 3 : VLBE_DA_N);
    for (i = 0; i < 4; ++i) {
        vlbe__ale_from_xi(i & 1, xi, Lp, g[i], kmax, na, out);
        for (k = 0; k <= kmax; ++k)
            for (a = 0; a < na; ++a) b->h[k][a][i] = out[k * VLBE_DA_N + a];
    }
    for (i = 0; i < 2; ++i) {
        const int kl = kmax < 1 ? kmax : 1;
        vlbe__cubic_derivs(lin[i], xi, kl + amax + 1, gl);
        vlbe__ale_from_xi(0, xi, Lp, gl, kl, na, out);
        for (k = 0; k <= kl; ++k)
            for (a = 0; a < na; ++a) b->l[k][a][i] = out[k * VLBE_DA_N + a];
    }
}

VLBE_API void vlbe_herm_ale_eval(vlbe_real p, vlbe_real p1, vlbe_real p2, int kmax, int amax,
                                 vlbe_herm_ale *VLBE_RESTRICT b)
{
    /* N1..N4 at L = 1 as cubics in xi (vlbse eq. 5 with s = 2 xi - 1) */
    static const vlbe_real c[4][4] = {{1, 0, -3, 2}, {0, 1, -2, 1}, {0, 0, 3, -2}, {0, 0, -1, 1}};
    vlbe_real g[4][6];
    const vlbe_real xi = (p - p1) * (VLBE_R(1.0) / (p2 - p1)); /* as vlbe__ale_basis_fill */
    int i;
    VLBE_ASSERT(kmax >= 0 && kmax <= 3 && amax >= 0 && amax <= 2);
    for (i = 0; i < 4; ++i) vlbe__cubic_derivs(c[i], xi, kmax + amax + 1, g[i]);
    vlbe__ale_basis_fill((const vlbe_real(*)[6])g, p, p1, p2, kmax, amax, b);
}

/* -- dense LU ----------------------------------------------------------- */
/* The pieces the dense and the band LU share.  vlbe__lu_tol: the pivot
   threshold tol = max(n eps amax, VLBE_REAL_MIN) (a pivot must be above it)
   and whether the overflow scan of the factor is needed: 1 when amax 2^h
   may pass VLBE_REAL_MAX, h the log2 of the growth bound (halvings are
   exact, no libm call, no double in a float build). */
VLBE_INLINE int vlbe__lu_tol(int n, int h, vlbe_real amax, vlbe_real *tol)
{
    vlbe_real t = (vlbe_real)n * VLBE_EPS * amax, lim = VLBE_REAL_MAX;
    int k;
    if (!(t >= VLBE_REAL_MIN)) t = VLBE_REAL_MIN; /* underflow: 1/pivot must stay finite */
    *tol = t;
    for (k = 0; k < h && lim > amax; ++k) lim *= VLBE_R(0.5);
    return !(lim > amax);
}

/* Pivot of one elimination step: r = 0..m maximising |c[r*stride]| (the
   first on ties), c = the diagonal entry, stride = the distance from an
   entry of the column to the one below.  VLBE_OK with *p = r;
   VLBE_ESINGULAR when that maximum is not above tol; VLBE_ENONFINITE when
   it is NaN (only after an overflow of the elimination). */
VLBE_INLINE vlbe_status vlbe__lu_pivot(const vlbe_real *c, size_t stride, int m, vlbe_real tol,
                                       int *p)
{
    vlbe_real pmax = vlbe_fabs(c[0]);
    int r, q = 0;
    for (r = 1; r <= m; ++r) {
        vlbe_real t = vlbe_fabs(c[(size_t)r * stride]);
        if (t > pmax) {
            pmax = t;
            q = r;
        }
    }
    *p = q;
    if (!(pmax > tol)) return pmax != pmax ? VLBE_ENONFINITE : VLBE_ESINGULAR;
    return VLBE_OK;
}

/* Elimination of one step, after the swap: the pivot row at c (c[0] the
   pivot, c[1..len] the columns to its right), rows r = 1..m at c +
   r*stride: l = c_r[0] / c[0] (as c_r[0] times the reciprocal) stored in
   c_r[0], then c_r[1..len] -= l c[1..len], contiguous rows (vectorised). */
VLBE_INLINE void vlbe__lu_eliminate(vlbe_real *c, size_t stride, int m, int len)
{
    const vlbe_real inv = VLBE_R(1.0) / c[0];
    int r, j;
    for (r = 1; r <= m; ++r) {
        vlbe_real *VLBE_RESTRICT ri = c + (size_t)r * stride;
        vlbe_real l = ri[0] * inv;
        ri[0] = l;
        if (l != VLBE_R(0.0))
            for (j = 1; j <= len; ++j) ri[j] -= l * c[j];
    }
}

/* LU = P A with partial pivoting (Golub & Van Loan alg. 3.4.1), right-looking,
   row-major so the rank-1 update runs along contiguous rows.
   A, LU: n*n row-major.  LU may equal A (in-place); otherwise A is untouched.
   piv[k] = row swapped with row k at step k.  *info (if info != NULL) is 0
   on success.
   Fails with
     VLBE_ENONFINITE  A holds NaN or Inf (found before anything is written:
                      LU, piv and *info are untouched), or the elimination
                      overflowed (entries near VLBE_REAL_MAX: the growth of
                      partial pivoting, up to 2^(n-1), passed it);
     VLBE_ESINGULAR   a pivot is 0 or not above tol = max(n eps max|A|,
                      VLBE_REAL_MIN): relatively zero (the computed factor
                      would be noise; the test is relative to the whole
                      matrix, so scale rows of very different units to
                      comparable size first, as the integrators do:
                      vlbe__dae_equil), or below the smallest normal number,
                      whose reciprocal may overflow; the 1-based failing
                      column is written to *info (LAPACK's k+1), which is the
                      only failure that writes *info.
   On either failure after the elimination started, LU and piv hold partial
   results, unspecified (so A is lost when LU == A): the one exception to
   "a failed call leaves the caller's data as it was", since keeping them
   would need a copy of the matrix.  A successful factor is finite and its
   pivots have finite reciprocals, so vlbe_lu_solve cannot produce NaN or
   Inf from it unless B, the solution or a product or partial sum of the
   substitutions overflows (the substitutions are not scaled as LAPACK's
   xLATRS: e.g. u_12 x_2 may pass VLBE_REAL_MAX for a finite x_1).
   Cost of the checks: a comparison per pivot; the overflow scan of the
   factor at the end runs only when max|A| 2^n can pass VLBE_REAL_MAX
   (growth bound of partial pivoting: |l_ik| <= 1, so every elimination step
   at most doubles the largest active entry, rounding included), which
   never happens for matrices of ordinary size and scale. */
VLBE_API vlbe_status vlbe_lu_factor(int n, const vlbe_real *A, vlbe_real *LU, int *piv, int *info)
{
    size_t nn, N, e;
    vlbe_real amax = VLBE_R(0.0), tol;
    int j, k, scan;
    VLBE_ASSERT(n >= 1 && A != NULL && LU != NULL && piv != NULL);
    N = (size_t)n;
    nn = N * N;
    for (e = 0; e < nn; ++e) {
        vlbe_real t = vlbe_fabs(A[e]);
        if (!isfinite(t)) return VLBE_ENONFINITE;
        if (t > amax) amax = t;
    }
    if (LU != A)
        for (e = 0; e < nn; ++e) LU[e] = A[e];
    /* growth <= 2^(n-1) (1 + eps)^(4(n-1)) < 2^n: scan when amax 2^n may
       pass VLBE_REAL_MAX */
    scan = vlbe__lu_tol(n, n, amax, &tol);
    for (k = 0; k < n; ++k) {
        vlbe_real *rk = LU + (size_t)k * N;
        int p;
        vlbe_status st = vlbe__lu_pivot(rk + k, N, n - 1 - k, tol, &p);
        p += k;
        piv[k] = p;
        if (st != VLBE_OK) {
            if (st == VLBE_ESINGULAR && info) *info = k + 1;
            return st;
        }
        if (p != k) {
            vlbe_real *rp = LU + (size_t)p * N;
            for (j = 0; j < n; ++j) {
                vlbe_real t = rk[j];
                rk[j] = rp[j];
                rp[j] = t;
            }
        }
        vlbe__lu_eliminate(rk + k, N, n - 1 - k, n - 1 - k);
    }
    if (scan) {
        vlbe_real z = VLBE_R(0.0);
        for (e = 0; e < nn; ++e) z += LU[e] * VLBE_R(0.0); /* NaN iff an entry is not finite */
        if (z != z) return VLBE_ENONFINITE;
    }
    if (info) *info = 0;
    return VLBE_OK;
}

/* Solve A X = B with the factor of vlbe_lu_factor.  B: n x nrhs row-major,
   overwritten by X.  Cannot fail after a successful factor. */
VLBE_API void vlbe_lu_solve(int n, const vlbe_real *LU, const int *piv, int nrhs, vlbe_real *B)
{
    size_t N = (size_t)n, R = (size_t)nrhs;
    int i, k, r;
    VLBE_ASSERT(n >= 1 && nrhs >= 1 && LU != NULL && piv != NULL && B != NULL);
    for (k = 0; k < n; ++k)
        if (piv[k] != k) {
            vlbe_real *bk = B + (size_t)k * R, *bp = B + (size_t)piv[k] * R;
            for (r = 0; r < nrhs; ++r) {
                vlbe_real t = bk[r];
                bk[r] = bp[r];
                bp[r] = t;
            }
        }
    /* forward: L y = P b, unit diagonal */
    for (i = 1; i < n; ++i) {
        const vlbe_real *li = LU + (size_t)i * N;
        vlbe_real *bi = B + (size_t)i * R;
        for (k = 0; k < i; ++k) {
            vlbe_real l = li[k];
            const vlbe_real *bk = B + (size_t)k * R;
            if (l != VLBE_R(0.0))
                for (r = 0; r < nrhs; ++r) bi[r] -= l * bk[r];
        }
    }
    /* backward: U x = y */
    for (i = n - 1; i >= 0; --i) {
        const vlbe_real *ui = LU + (size_t)i * N;
        vlbe_real *bi = B + (size_t)i * R, inv = VLBE_R(1.0) / ui[i];
        for (k = i + 1; k < n; ++k) {
            vlbe_real u = ui[k];
            const vlbe_real *bk = B + (size_t)k * R;
            if (u != VLBE_R(0.0))
                for (r = 0; r < nrhs; ++r) bi[r] -= u * bk[r];
        }
        for (r = 0; r < nrhs; ++r) bi[r] *= inv;
    }
}

VLBE_API vlbe_real vlbe_lu_flops(int n)
{
    vlbe_real x = (vlbe_real)n;
    return VLBE_R(2.0) / VLBE_R(3.0) * x * x * x;
}

/* -- banded LU ---------------------------------------------------------- */
/* min(cap, i + a) for 0 <= i <= cap, a >= 0, without overflow */
VLBE_INLINE int vlbe__min_add(int i, int a, int cap) { return a > cap - i ? cap : i + a; }

/* the argument check of the band routines: n >= 1, kl, ku >= 0 with
   2 kl + ku + 1 representable in size_t, lda >= kl + ku + 1 */
VLBE_INLINE int vlbe__band_args_ok(int n, int kl, int ku, int lda)
{
    const size_t big = ((size_t)-1 - 1) / 3;
    return n >= 1 && kl >= 0 && ku >= 0 && (size_t)kl <= big && (size_t)ku <= big &&
           lda >= 1 && (size_t)lda >= (size_t)kl + (size_t)ku + 1;
}

/* the largest bit pattern of |x[i]|, i < n: for reals >= 0 the order of the
   patterns (as unsigned integers) is the order of the values, and Inf and
   NaN lie above every finite value (>= VLBE__BITS_EXP); integer max, no
   dependence on floating-point compares, so the loop vectorises */
VLBE_INLINE vlbe__bits vlbe__absmax_bits(const vlbe_real *x, size_t n)
{
    vlbe__bits m = 0, u;
    size_t i;
    for (i = 0; i < n; ++i) {
        memcpy(&u, x + i, sizeof u);
        u &= VLBE__BITS_ABS;
        m = u > m ? u : m;
    }
    return m;
}

VLBE_API size_t vlbe_band_lu_ld(int kl, int ku)
{
    VLBE_ASSERT(kl >= 0 && ku >= 0);
    return 2 * (size_t)kl + (size_t)ku + 1;
}

/* LU = P A of a band matrix with kl sub- and ku super-diagonals: band
   Gaussian elimination with partial pivoting, the row interchanges kept
   inside the band (Golub & Van Loan sec. 4.3: alg. 4.3.1 with partial
   pivoting; the layout of LAPACK's xGBTRF, transposed to rows).  Swapping
   row k with a row p <= k + kl brings entries up to column p + ku into
   row k, so U has kl + ku super-diagonals and LU is a band with kl sub-
   and kl + ku super-diagonals: ld = vlbe_band_lu_ld(kl, ku) = 2 kl + ku +
   1, entry (i, j) at LU[i*ld + j - i + kl] (VLBE_BAND_IDX(ld, kl, i, j)).
   A: band storage (see "Band storage"), lda >= kl + ku + 1; only the
   slots inside the matrix are read.  LU may equal A when lda == ld (in
   place: the last kl slots of each row, columns i+ku+1 .. i+kl+ku, are
   ignored on input and zeroed); otherwise A is untouched.  Slots of LU
   outside the matrix are neither read nor written.  kl, ku >= n are
   allowed (the storage follows them, the elimination stops at the
   matrix).
   Row i of LU holds U(i, i .. i+kl+ku) and, in columns i-kl .. i-1, the
   multipliers of the steps that eliminated those columns from the row
   standing at position i at that step: unlike vlbe_lu_factor, whose L is
   the one of P A, earlier multipliers are not swapped with later rows
   (vlbe_band_lu_solve applies interchanges and multipliers step by step).
   piv[k] = the 0-based row swapped with row k at step k (k <= piv[k] <=
   k + kl), as in vlbe_lu_factor.  Pivots, U and the solution are bitwise
   those of vlbe_lu_factor / vlbe_lu_solve on the full matrix (the same
   operations on the entries inside the band, the zero ones skipped).
   Status, *info, the pivot test and the failure contract are those of
   vlbe_lu_factor: VLBE_ENONFINITE for NaN or Inf in the band of A (found
   before anything is written) or an overflow in the elimination;
   VLBE_ESINGULAR for a pivot not above tol = max(n eps max|A|,
   VLBE_REAL_MIN), its 1-based column in *info; after a failed elimination
   LU and piv hold unspecified partial results.  VLBE_EARG (nothing
   written) for n < 1, kl < 0, ku < 0, lda < kl + ku + 1, and LU == A with
   lda != ld.
   Growth: column j is changed only by the steps k = j-kl-ku .. j-1 (the
   pivot row of step k ends at column k + kl + ku at most), and each of
   them at most doubles the largest active entry of the column (|l| <= 1),
   so max|U| <= 2^s (1 + eps)^(4s) max|A| < 2^(s+1) max|A|, s = min(n - 1,
   kl + ku): the overflow scan of the factor runs only when max|A|
   2^(s+1) may pass VLBE_REAL_MAX.
   Cost: n kl (2 ku + 1) flops without interchanges (vlbe_band_lu_flops),
   up to n kl (2 (kl + ku) + 1) with them; storage n ld reals. */
VLBE_API vlbe_status vlbe_band_lu_factor(int n, int kl, int ku, const vlbe_real *A, int lda,
                                         vlbe_real *LU, int *piv, int *info)
{
    size_t ld, la;
    vlbe_real amax, tol;
    vlbe__bits bmax = 0;
    int i, j, k, ju, scan;
    VLBE_ASSERT(A != NULL && LU != NULL && piv != NULL);
    if (!vlbe__band_args_ok(n, kl, ku, lda)) return VLBE_EARG;
    ld = vlbe_band_lu_ld(kl, ku);
    la = (size_t)lda;
    if (LU == A && la != ld) return VLBE_EARG;
    /* max |a_ij| and finiteness in one pass over the bits; the rows
       kl .. n-1-ku lie inside the matrix, with lda = kl + ku + 1 they are
       one block */
    for (i = 0; i < n; ++i) {
        const int j0 = i > kl ? i - kl : 0, j1 = vlbe__min_add(i, ku, n - 1);
        const vlbe_real *ai = A + (size_t)i * la + (size_t)(j0 - i + kl);
        if (i == kl && la == (size_t)kl + (size_t)ku + 1 && n - 1 - ku > kl) {
            const int nb = n - ku - kl; /* rows kl .. n-1-ku */
            vlbe__bits t = vlbe__absmax_bits(ai, (size_t)nb * la);
            if (t > bmax) bmax = t;
            i += nb - 1;
        } else {
            vlbe__bits t = vlbe__absmax_bits(ai, (size_t)(j1 - j0 + 1));
            if (t > bmax) bmax = t;
        }
    }
    if (bmax >= VLBE__BITS_EXP) return VLBE_ENONFINITE; /* Inf or NaN */
    memcpy(&amax, &bmax, sizeof amax);
    for (i = 0; i < n; ++i) { /* copy, zero the fill columns i+ku+1 .. i+kl+ku */
        const int j0 = i > kl ? i - kl : 0, j1 = vlbe__min_add(i, ku, n - 1);
        const int j2 = vlbe__min_add(j1, kl, n - 1);
        vlbe_real *li = LU + (size_t)i * ld + (size_t)(j0 - i + kl);
        if (LU != A) vlbe_vec_copy(j1 - j0 + 1, A + (size_t)i * la + (size_t)(j0 - i + kl), li);
        vlbe_vec_zero(j2 - j1, li + (j1 - j0 + 1));
    }
    /* growth < 2^(s+1), s = min(n - 1, kl + ku) (see above) */
    scan = vlbe__lu_tol(n, vlbe__min_add(kl < n ? kl : n - 1, ku, n - 1) + 1, amax, &tol);
    ju = 0; /* the last column the rows of U reach so far */
    for (k = 0; k < n; ++k) {
        const int m = vlbe__min_add(k, kl, n - 1) - k; /* rows k+1 .. k+m below */
        vlbe_real *rk = LU + (size_t)k * ld + (size_t)kl; /* (k, k) */
        int p;
        vlbe_status st = vlbe__lu_pivot(rk, ld - 1, m, tol, &p); /* (k+r, k) at rk + r(ld-1) */
        p += k;
        piv[k] = p;
        if (st != VLBE_OK) {
            if (st == VLBE_ESINGULAR && info) *info = k + 1;
            return st;
        }
        j = vlbe__min_add(p, ku, n - 1); /* row p ends at column p + ku or at ju */
        if (j > ju) ju = j;
        if (p != k) { /* columns k .. ju of rows k and p */
            vlbe_real *rp = LU + (size_t)p * ld + (size_t)(k - p + kl);
            for (j = 0; j <= ju - k; ++j) {
                vlbe_real t = rk[j];
                rk[j] = rp[j];
                rp[j] = t;
            }
        }
        vlbe__lu_eliminate(rk, ld - 1, m, ju - k);
    }
    if (scan) {
        vlbe__bits b = 0;
        for (i = 0; i < n; ++i) {
            const int j0 = i > kl ? i - kl : 0;
            const int j2 = vlbe__min_add(vlbe__min_add(i, ku, n - 1), kl, n - 1);
            b |= vlbe__fin_bits(LU + (size_t)i * ld + (size_t)(j0 - i + kl), j2 - j0 + 1);
        }
        if (b & VLBE__BITS_SIGN) return VLBE_ENONFINITE;
    }
    if (info) *info = 0;
    return VLBE_OK;
}

/* Solve A X = B with the factor of vlbe_band_lu_factor (same n, kl, ku).
   B: n x nrhs row-major, overwritten by X.  Forward: the interchange and
   the multipliers of each step in turn (L y = P b in the order of the
   elimination: band forward substitution with the swaps, GvL sec. 4.3);
   backward: U x = y, U with kl + ku super-diagonals.  The numbers are
   those of vlbe_lu_solve on the full factor.  Cannot fail after a
   successful factor. */
VLBE_API void vlbe_band_lu_solve(int n, int kl, int ku, const vlbe_real *LU, const int *piv,
                                 int nrhs, vlbe_real *B)
{
    size_t ld, R = (size_t)nrhs;
    int i, k, r;
    VLBE_ASSERT(n >= 1 && kl >= 0 && ku >= 0 && nrhs >= 1);
    VLBE_ASSERT(LU != NULL && piv != NULL && B != NULL);
    ld = vlbe_band_lu_ld(kl, ku);
    for (k = 0; k < n; ++k) {
        const int iend = vlbe__min_add(k, kl, n - 1);
        vlbe_real *bk = B + (size_t)k * R;
        if (piv[k] != k) {
            vlbe_real *bp = B + (size_t)piv[k] * R;
            for (r = 0; r < nrhs; ++r) {
                vlbe_real t = bk[r];
                bk[r] = bp[r];
                bp[r] = t;
            }
        }
        for (i = k + 1; i <= iend; ++i) {
            vlbe_real l = LU[(size_t)i * ld + (size_t)(k - i + kl)];
            vlbe_real *VLBE_RESTRICT bi = B + (size_t)i * R;
            if (l != VLBE_R(0.0))
                for (r = 0; r < nrhs; ++r) bi[r] -= l * bk[r];
        }
    }
    for (i = n - 1; i >= 0; --i) {
        const int kend = vlbe__min_add(vlbe__min_add(i, ku, n - 1), kl, n - 1);
        const vlbe_real *ui = LU + (size_t)i * ld + (size_t)kl; /* (i, i) */
        vlbe_real *VLBE_RESTRICT bi = B + (size_t)i * R, inv = VLBE_R(1.0) / ui[0];
        for (k = i + 1; k <= kend; ++k) {
            vlbe_real u = ui[k - i];
            const vlbe_real *bk = B + (size_t)k * R;
            if (u != VLBE_R(0.0))
                for (r = 0; r < nrhs; ++r) bi[r] -= u * bk[r];
        }
        for (r = 0; r < nrhs; ++r) bi[r] *= inv;
    }
}

/* y = A x and y = A^T x, A n x n in band storage (lda >= kl + ku + 1,
   slots outside the matrix not read).  Row i of A x is vlbe_vec_dot over
   its band, A^T x accumulates vlbe_vec_axpy of the band rows: for finite x
   the results are bitwise those of vlbe_mat_vec / vlbe_mat_tvec on the
   full matrix (the same sums in the same order, without the zero terms). */
VLBE_API void vlbe_band_mat_vec(int n, int kl, int ku, const vlbe_real *A, int lda,
                                const vlbe_real *x, vlbe_real *VLBE_RESTRICT y)
{
    int i;
    VLBE_ASSERT(vlbe__band_args_ok(n, kl, ku, lda) && A != NULL && x != NULL && y != NULL);
    for (i = 0; i < n; ++i) {
        const int j0 = i > kl ? i - kl : 0, j1 = vlbe__min_add(i, ku, n - 1);
        y[i] = vlbe_vec_dot(j1 - j0 + 1, A + (size_t)i * (size_t)lda + (size_t)(j0 - i + kl),
                            x + j0);
    }
}
VLBE_API void vlbe_band_mat_tvec(int n, int kl, int ku, const vlbe_real *A, int lda,
                                 const vlbe_real *x, vlbe_real *VLBE_RESTRICT y)
{
    int i;
    VLBE_ASSERT(vlbe__band_args_ok(n, kl, ku, lda) && A != NULL && x != NULL && y != NULL);
    vlbe_vec_zero(n, y);
    for (i = 0; i < n; ++i) {
        const int j0 = i > kl ? i - kl : 0, j1 = vlbe__min_add(i, ku, n - 1);
        vlbe_vec_axpy(j1 - j0 + 1, x[i], A + (size_t)i * (size_t)lda + (size_t)(j0 - i + kl),
                      y + j0);
    }
}

/* Flops of vlbe_band_lu_factor without interchanges: step k makes
   m = min(kl, n-1-k) multipliers (one product each) and updates m rows in
   u = min(ku, n-1-k) columns (a product and a difference each): the sum
   over k of m (2u + 1), about n kl (2 ku + 1); 2/3 n^3 + O(n^2) for a
   full band, as vlbe_lu_flops.  Interchanges add up to 2 kl^2 per step
   (the fill). */
VLBE_API vlbe_real vlbe_band_lu_flops(int n, int kl, int ku)
{
    vlbe_real f = VLBE_R(0.0);
    int t, tmax;
    VLBE_ASSERT(n >= 1 && kl >= 0 && ku >= 0);
    tmax = kl > ku ? kl : ku; /* t = n-1-k; from t = max(kl, ku) on, m = kl, u = ku */
    if (tmax > n) tmax = n;
    for (t = 0; t < tmax; ++t) {
        const vlbe_real m = (vlbe_real)(t < kl ? t : kl), u = (vlbe_real)(t < ku ? t : ku);
        f += m * (VLBE_R(2.0) * u + VLBE_R(1.0));
    }
    return f + (vlbe_real)(n - tmax) * (vlbe_real)kl * (VLBE_R(2.0) * (vlbe_real)ku + VLBE_R(1.0));
}

/* -- eigenproblems ------------------------------------------------------ */
/* Dense eigen-solvers on caller storage (sizes from the *_work_len
   queries), in vlbe_real.  Every one checks n (VLBE_EARG for n < 1 and for
   sizes that do not fit size_t or, for the 2n x 2n problems, int), the
   workspace (VLBE_EWORK) and its inputs (VLBE_ENONFINITE for NaN or Inf)
   before it writes anything, computes in the workspace and copies the
   results out at the end, so a failed call leaves every output as it was.
   No recursion, no VLAs.
   Which one:
     vlbe_eig_sym   A x = lam x, A symmetric: cyclic Jacobi
     vlbe_eig_gsym  K x = lam M x, M symmetric positive definite: shift-
                    invert with a Cholesky factor, then Jacobi (the LOWEST
                    modes to a few eps relative)
     vlbe_eig_real  eigenvalues of a general real matrix: Hessenberg +
                    Francis double-shift QR
     vlbe_eig_quad  (s^2 M + s D + K) x = 0: shift-invert of the first-order
                    form by one LU of P(sigma), vlbe_eig_real, eigenvectors
                    by inverse iteration */

#define VLBE__EIG_SWEEPS 60 /* Jacobi: limit of sweeps (6-10 are needed) */

/* a N^2 + b N in *len; 0 when n < 1 or the count overflows size_t */
VLBE_INLINE int vlbe__eig_len(int n, size_t a, size_t b, size_t *len)
{
    size_t N, NN;
    if (n < 1) return 0;
    N = (size_t)n;
    if (N > ((size_t)-1) / N) return 0;
    NN = N * N;
    if (a != 0 && NN > ((size_t)-1) / a) return 0;
    if (b != 0 && N > ((size_t)-1) / b) return 0;
    if (a * NN > ((size_t)-1) - b * N) return 0;
    *len = a * NN + b * N;
    return 1;
}

/* 1 when the n x n matrix A (row-major, rows of int length) is finite */
VLBE_INLINE int vlbe__mat_finite(int n, const vlbe_real *A)
{
    vlbe__bits b = 0;
    size_t i, N = (size_t)n;
    for (i = 0; i < N; ++i) b |= vlbe__fin_bits(A + i * N, n);
    return (b & VLBE__BITS_SIGN) == 0;
}

/* Cholesky B = L L^T in place (Golub & Van Loan alg. 4.2.2, gaxpy form):
   the lower triangle of L holds B on entry and the factor on return, the
   upper triangle is zeroed.  The pivot test: B_jj - sum_k L_jk^2 carries a
   rounding error up to about j EPS B_jj (the sum is at most B_jj for a
   positive definite B), so a pivot not above n EPS |B_jj| cannot be told
   from zero: VLBE_ESINGULAR with *info = j + 1 (1-based, as
   vlbe_lu_factor), L partial. */
VLBE_INLINE vlbe_status vlbe__chol(size_t N, vlbe_real *L, int *info)
{
    size_t i, j, k;
    for (j = 0; j < N; ++j) {
        const vlbe_real bjj = L[j * N + j];
        vlbe_real d = bjj;
        for (k = 0; k < j; ++k) d -= L[j * N + k] * L[j * N + k];
        if (!(d > (vlbe_real)N * VLBE_EPS * vlbe_fabs(bjj))) {
            if (info) *info = (int)j + 1;
            return VLBE_ESINGULAR;
        }
        d = vlbe_sqrt(d);
        L[j * N + j] = d;
        for (i = j + 1; i < N; ++i) {
            vlbe_real s = L[i * N + j];
            for (k = 0; k < j; ++k) s -= L[i * N + k] * L[j * N + k];
            L[i * N + j] = s / d;
        }
        for (i = 0; i < j; ++i) L[i * N + j] = VLBE_R(0.0);
    }
    return VLBE_OK;
}

/* One Jacobi rotation of the symmetric C (N x N, full storage) in the
   plane (p, q), p < q, that zeroes c_pq (GvL alg. 8.5.1, the 2-by-2
   symmetric Schur decomposition); V (or NULL) accumulates the rotations
   as columns. */
VLBE_INLINE void vlbe__eig_rot(size_t N, size_t p, size_t q, vlbe_real *C, vlbe_real *V)
{
    const vlbe_real apq = C[p * N + q];
    const vlbe_real th = (C[q * N + q] - C[p * N + p]) / (VLBE_R(2.0) * apq);
    vlbe_real t, c, s;
    size_t k;
    /* t = tan of the rotation angle, the smaller root of t^2 + 2 th t - 1 = 0,
       written without forming th^2 for large |th| (no overflow) */
    if (vlbe_fabs(th) > VLBE_R(1.0)) {
        const vlbe_real r = VLBE_R(1.0) / th;
        t = VLBE_R(1.0) / (vlbe_fabs(th) * (VLBE_R(1.0) + vlbe_sqrt(VLBE_R(1.0) + r * r)));
    } else
        t = VLBE_R(1.0) / (vlbe_fabs(th) + vlbe_sqrt(VLBE_R(1.0) + th * th));
    if (th < VLBE_R(0.0)) t = -t;
    c = VLBE_R(1.0) / vlbe_sqrt(VLBE_R(1.0) + t * t);
    s = t * c;
    C[p * N + p] -= t * apq;
    C[q * N + q] += t * apq;
    C[p * N + q] = C[q * N + p] = VLBE_R(0.0);
    for (k = 0; k < N; ++k) {
        vlbe_real g, h;
        if (k == p || k == q) continue;
        g = C[k * N + p];
        h = C[k * N + q];
        C[k * N + p] = C[p * N + k] = c * g - s * h;
        C[k * N + q] = C[q * N + k] = s * g + c * h;
    }
    if (V)
        for (k = 0; k < N; ++k) {
            const vlbe_real g = V[k * N + p], h = V[k * N + q];
            V[k * N + p] = c * g - s * h;
            V[k * N + q] = s * g + c * h;
        }
}

/* Cyclic Jacobi on C in place (N x N symmetric; GvL alg. 8.5.3): a sweep
   visits every p < q in row order.  A pair is skipped when |c_pq| <= EPS
   sqrt(|c_pp c_qq|) (the threshold of Demmel and Veselic: it keeps the
   small eigenvalues of a graded positive definite matrix to high relative
   accuracy) or when |c_pq| is below EPS^2 times the largest |c_ij| of the
   input (nothing left at the working precision); converged when a sweep
   rotates nothing (quadratic convergence: 6-10 sweeps).  V (or NULL)
   starts as the identity and ends with the eigenvectors as columns; the
   diagonal of C holds the eigenvalues, unsorted. */
VLBE_INLINE vlbe_status vlbe__eig_jacobi(size_t N, vlbe_real *C, vlbe_real *V)
{
    vlbe_real amax = VLBE_R(0.0), floor_abs;
    size_t i, j;
    int sw;
    for (i = 0; i < N * N; ++i)
        if (vlbe_fabs(C[i]) > amax) amax = vlbe_fabs(C[i]);
    floor_abs = VLBE_EPS * VLBE_EPS * amax;
    if (V)
        for (i = 0; i < N; ++i)
            for (j = 0; j < N; ++j) V[i * N + j] = i == j ? VLBE_R(1.0) : VLBE_R(0.0);
    for (sw = 0; sw < VLBE__EIG_SWEEPS; ++sw) {
        long rotations = 0;
        for (i = 0; i + 1 < N; ++i)
            for (j = i + 1; j < N; ++j) {
                const vlbe_real a = vlbe_fabs(C[i * N + j]);
                if (a <= floor_abs ||
                    a <= VLBE_EPS * vlbe_sqrt(vlbe_fabs(C[i * N + i]) * vlbe_fabs(C[j * N + j])))
                    continue;
                vlbe__eig_rot(N, i, j, C, V);
                ++rotations;
            }
        if (rotations == 0) return VLBE_OK;
    }
    return VLBE_ENOCONV;
}

/* Sorts mu[0..N-1] ascending (desc = 0) or descending (desc = 1) in place
   and the columns of V (or NULL) with it (selection sort: n^2 compares, at
   most n column swaps; the first of equal values stays first) */
VLBE_INLINE void vlbe__eig_sort(size_t N, vlbe_real *mu, vlbe_real *V, int desc)
{
    size_t i, j, k;
    for (i = 0; i + 1 < N; ++i) {
        size_t m = i;
        for (j = i + 1; j < N; ++j)
            if (desc ? mu[j] > mu[m] : mu[j] < mu[m]) m = j;
        if (m == i) continue;
        {
            const vlbe_real t = mu[i];
            mu[i] = mu[m];
            mu[m] = t;
        }
        if (V)
            for (k = 0; k < N; ++k) {
                const vlbe_real t = V[k * N + i];
                V[k * N + i] = V[k * N + m];
                V[k * N + m] = t;
            }
    }
}

/* Reals of workspace for vlbe_eig_sym and vlbe_eig_gsym: 3 n^2 + n (0 for
   n < 1 or a count beyond size_t; the solvers then return VLBE_EARG). */
VLBE_API size_t vlbe_eig_work_len(int n)
{
    size_t len = 0;
    return vlbe__eig_len(n, 3, 1, &len) ? len : 0;
}

/* A x = lam x, A n x n symmetric (both triangles read, used as (A +
   A^T)/2), by cyclic Jacobi (see vlbe__eig_jacobi).
   lam[n]: the eigenvalues ascending; X (n x n, may be NULL): X[i*n + k] =
   component i of the vector of lam[k], columns orthonormal (X^T X = I to
   a few n EPS).  Accuracy: each eigenvalue to a few n EPS ||A||.
   work: vlbe_eig_work_len(n) reals (2 n^2 + n are used).  Status:
   VLBE_EARG, VLBE_EWORK, VLBE_ENONFINITE (A, or an overflow), VLBE_ENOCONV
   (no convergence in 60 sweeps; not seen); on failure lam and X are
   untouched. */
VLBE_API vlbe_status vlbe_eig_sym(int n, const vlbe_real *A, vlbe_real *lam, vlbe_real *X,
                                  vlbe_real *work, size_t work_len)
{
    size_t N, i, j, len = 0;
    vlbe_real *C, *V, *mu;
    vlbe_status st;
    VLBE_ASSERT(A != NULL && lam != NULL && work != NULL);
    if (!vlbe__eig_len(n, 3, 1, &len)) return VLBE_EARG;
    if (work_len < len) return VLBE_EWORK;
    if (!vlbe__mat_finite(n, A)) return VLBE_ENONFINITE;
    N = (size_t)n;
    C = work;
    V = work + N * N;
    mu = work + 3 * N * N;
    for (i = 0; i < N; ++i)
        for (j = 0; j < N; ++j) C[i * N + j] = VLBE_R(0.5) * (A[i * N + j] + A[j * N + i]);
    if ((st = vlbe__eig_jacobi(N, C, X ? V : NULL)) != VLBE_OK) return st;
    for (i = 0; i < N; ++i) mu[i] = C[i * N + i];
    vlbe__eig_sort(N, mu, X ? V : NULL, 0);
    if (!vlbe_all_finite(mu, n) || (X && !vlbe__mat_finite(n, V))) return VLBE_ENONFINITE;
    for (i = 0; i < N; ++i) lam[i] = mu[i];
    if (X)
        for (i = 0; i < N * N; ++i) X[i] = V[i];
    return VLBE_OK;
}

/* K x = lam M x, K and M n x n symmetric (both triangles read, used as
   (K + K^T)/2, (M + M^T)/2), M positive definite, by SHIFT-INVERT: with
   K - sigma M = L L^T (Cholesky; it must be positive definite: sigma
   below the lowest eigenvalue; sigma = 0 for a positive definite K, sigma
   < 0 for a K with rigid modes), Jacobi on the symmetric positive definite
   C = L^-1 M L^-T (GvL sec. 8.7.2, the reduction of the symmetric-definite
   problem, here of the pencil M - mu (K - sigma M)) gives mu = 1/(lam -
   sigma) and y; lam = sigma + 1/mu, x = L^-T y / sqrt(mu).
   Why: Jacobi's error in mu is a few EPS ||C|| = EPS max mu, and the
   largest mu belong to the LOWEST lam, which therefore come out to a few
   EPS relative (times the conditioning of K - sigma M against M).
   Solving K x = lam M x directly (the Cholesky of M, Jacobi on L^-1 K L^-T)
   makes the error EPS lam_max instead, lam_max / lam_1 times larger: 1e4
   and more for the fundamental of a stiff beam, whose axial and high
   bending modes are 1e8 .. 1e11 times its lam.  A sigma far below the
   spectrum does the same harm (mu_k = 1/(lam_k - sigma) all near -1/sigma,
   lam_1 - sigma then has the rounding of |sigma|).
   The other side of it: mu is resolved only down to about EPS max mu
   (often better: Jacobi keeps small eigenvalues of well-scaled blocks to
   high relative accuracy, so small positive mu are kept as computed).
   When a computed mu is not above 0, M is checked by its Cholesky factor
   (VLBE_ESINGULAR below when it is not positive definite: a massless
   coordinate, an infinite lam); M positive definite, such a mu (rounding:
   lam_max / lam_1 beyond the working precision, a stiff structure in
   float) is raised to mu_min = min(n EPS max mu, the smallest positive
   mu): its lam = sigma + 1/mu_min is the largest the working precision
   resolves beside the lowest, a lower bound of the true one.
   lam[n]: ascending; X (n x n, may be NULL): the eigenvectors as columns
   (X[i*n + k], vector of lam[k]), normalised to X^T M X = I (then X^T K X
   = diag(lam)).  info (may be NULL): 0, or the failing column (below).
   work: vlbe_eig_work_len(n) reals.
   Status (on failure lam and X are untouched; *info is written by every
   call that gets past the argument checks):
     VLBE_EARG, VLBE_EWORK
     VLBE_ENONFINITE  NaN or Inf in K, M or sigma, or an overflow
     VLBE_ESINGULAR   K - sigma M is not positive definite: a Cholesky
                      pivot not above n EPS of its diagonal entry, *info =
                      its 1-based column j; or M is not positive definite
                      (found when a computed mu is not above 0, by the
                      Cholesky of M): *info = n + j (as LAPACK's xSYGV)
     VLBE_ENOCONV     Jacobi did not converge in 60 sweeps (not seen). */
VLBE_API vlbe_status vlbe_eig_gsym(int n, const vlbe_real *K, const vlbe_real *M,
                                   vlbe_real sigma, vlbe_real *lam, vlbe_real *X, int *info,
                                   vlbe_real *work, size_t work_len)
{
    size_t N, i, j, k, len = 0;
    vlbe_real *C, *V, *L, *mu, mumax = VLBE_R(0.0), mumin;
    vlbe_status st;
    VLBE_ASSERT(K != NULL && M != NULL && lam != NULL && work != NULL);
    if (!vlbe__eig_len(n, 3, 1, &len) || n > INT_MAX / 2) return VLBE_EARG;
    if (work_len < len) return VLBE_EWORK;
    if (info) *info = 0;
    if (!vlbe__mat_finite(n, K) || !vlbe__mat_finite(n, M) || !vlbe_all_finite(&sigma, 1))
        return VLBE_ENONFINITE;
    N = (size_t)n;
    C = work;
    V = work + N * N;
    L = work + 2 * N * N;
    mu = work + 3 * N * N;
    for (i = 0; i < N; ++i) /* the lower triangle of K - sigma M */
        for (j = 0; j <= i; ++j)
            L[i * N + j] = VLBE_R(0.5) * (K[i * N + j] + K[j * N + i]) -
                           sigma * (VLBE_R(0.5) * (M[i * N + j] + M[j * N + i]));
    if ((st = vlbe__chol(N, L, info)) != VLBE_OK) return st;
    /* V = L^-1 M (forward substitution, column by column of M) */
    for (j = 0; j < N; ++j)
        for (i = 0; i < N; ++i) {
            vlbe_real s = VLBE_R(0.5) * (M[i * N + j] + M[j * N + i]);
            for (k = 0; k < i; ++k) s -= L[i * N + k] * V[k * N + j];
            V[i * N + j] = s / L[i * N + i];
        }
    /* C = L^-1 V^T = L^-1 M L^-T (M symmetric), symmetrised */
    for (j = 0; j < N; ++j)
        for (i = 0; i < N; ++i) {
            vlbe_real s = V[j * N + i];
            for (k = 0; k < i; ++k) s -= L[i * N + k] * C[k * N + j];
            C[i * N + j] = s / L[i * N + i];
        }
    for (i = 0; i < N; ++i)
        for (j = i + 1; j < N; ++j)
            C[i * N + j] = C[j * N + i] = VLBE_R(0.5) * (C[i * N + j] + C[j * N + i]);
    if ((st = vlbe__eig_jacobi(N, C, X ? V : NULL)) != VLBE_OK) return st;
    for (i = 0; i < N; ++i) {
        mu[i] = C[i * N + i];
        if (mu[i] > mumax) mumax = mu[i];
    }
    mumin = (vlbe_real)n * VLBE_EPS * mumax;
    for (i = 0; i < N; ++i) /* the smallest positive mu, if below that */
        if (mu[i] > VLBE_R(0.0) && mu[i] < mumin) mumin = mu[i];
    for (i = 0; i < N; ++i)
        if (!(mu[i] > VLBE_R(0.0))) {
            /* C is positive definite when M is: is M? (C is free here) */
            for (j = 0; j < N; ++j)
                for (k = 0; k <= j; ++k)
                    C[j * N + k] = VLBE_R(0.5) * (M[j * N + k] + M[k * N + j]);
            if (vlbe__chol(N, C, info) != VLBE_OK) {
                if (info) *info += n;
                return VLBE_ESINGULAR;
            }
            if (!(mumax > VLBE_R(0.0))) return VLBE_ENONFINITE; /* not with M definite */
            for (j = 0; j < N; ++j)
                if (!(mu[j] > VLBE_R(0.0))) mu[j] = mumin;
            break;
        }
    /* mu descending = lam ascending */
    vlbe__eig_sort(N, mu, X ? V : NULL, 1);
    if (X) /* x = L^-T y / sqrt(mu): back substitution, column by column */
        for (j = 0; j < N; ++j) {
            const vlbe_real r = VLBE_R(1.0) / vlbe_sqrt(mu[j]);
            for (i = N; i-- > 0;) {
                vlbe_real s = V[i * N + j];
                for (k = i + 1; k < N; ++k) s -= L[k * N + i] * V[k * N + j];
                V[i * N + j] = s / L[i * N + i];
            }
            for (i = 0; i < N; ++i) V[i * N + j] *= r;
        }
    for (i = 0; i < N; ++i) mu[i] = sigma + VLBE_R(1.0) / mu[i];
    if (!vlbe_all_finite(mu, n) || (X && !vlbe__mat_finite(n, V))) return VLBE_ENONFINITE;
    for (i = 0; i < N; ++i) lam[i] = mu[i];
    if (X)
        for (i = 0; i < N * N; ++i) X[i] = V[i];
    return VLBE_OK;
}

/* Reals of workspace for vlbe_eig_real: 4 n (0 for n < 1 or beyond
   size_t). */
VLBE_API size_t vlbe_eig_real_work_len(int n)
{
    size_t len = 0;
    return vlbe__eig_len(n, 0, 4, &len) ? len : 0;
}

/* Balancing of A in place (Parlett and Reinsch; GvL sec. 7.5.7): A <-
   D^-1 A D with D diagonal of powers of 2 (exact), each row and column
   pair scaled towards equal 1-norms off the diagonal until no scaling
   lowers their sum by 5 %.  The eigenvalues are unchanged; the rounding
   of QR, relative to ||A||, gets smaller. */
VLBE_INLINE void vlbe__eig_balance(size_t N, vlbe_real *A)
{
    int changed = 1, sweeps = 0;
    size_t i, j;
    while (changed && sweeps++ < 100) {
        changed = 0;
        for (i = 0; i < N; ++i) {
            vlbe_real c = VLBE_R(0.0), r = VLBE_R(0.0), f = VLBE_R(1.0), g, s;
            int e = 0;
            for (j = 0; j < N; ++j)
                if (j != i) {
                    c += vlbe_fabs(A[j * N + i]);
                    r += vlbe_fabs(A[i * N + j]);
                }
            if (c == VLBE_R(0.0) || r == VLBE_R(0.0)) continue;
            s = c + r;
            g = r * VLBE_R(0.5);
            while (c < g && e < 60) { /* |e| < 60: f^2 stays inside the range */
                f *= VLBE_R(2.0);
                c *= VLBE_R(4.0);
                ++e;
            }
            g = r * VLBE_R(2.0);
            while (c >= g && e > -60) {
                f *= VLBE_R(0.5);
                c *= VLBE_R(0.25);
                --e;
            }
            if ((c + r) / f < VLBE_R(0.95) * s) {
                const vlbe_real fi = VLBE_R(1.0) / f;
                for (j = 0; j < N; ++j) A[i * N + j] *= fi;
                for (j = 0; j < N; ++j) A[j * N + i] *= f;
                changed = 1;
            }
        }
    }
}

/* Householder reduction to upper Hessenberg form in place (GvL alg.
   7.4.2): H = Q^T A Q, entries below the subdiagonal set to 0.  v, w:
   n reals each. */
VLBE_INLINE void vlbe__eig_hess(size_t N, vlbe_real *A, vlbe_real *v, vlbe_real *w)
{
    size_t i, j, k;
    for (k = 0; k + 2 < N; ++k) {
        const size_t m = N - k - 1; /* rows k+1 .. N-1 */
        vlbe_real nrm, alpha, beta, t;
        for (i = 0; i < m; ++i) v[i] = A[(k + 1 + i) * N + k];
        nrm = vlbe_vec_norm2((int)m, v);
        if (nrm == VLBE_R(0.0)) continue;
        /* v scaled to unit norm first: no overflow in v^T v */
        for (i = 0; i < m; ++i) v[i] /= nrm;
        alpha = v[0] >= VLBE_R(0.0) ? -VLBE_R(1.0) : VLBE_R(1.0);
        v[0] -= alpha;                             /* |v0| = 1 + |x0|/|x|: no cancellation */
        beta = VLBE_R(1.0) / vlbe_fabs(v[0]);      /* 2 / v^T v */
        A[(k + 1) * N + k] = alpha * nrm;
        for (i = 1; i < m; ++i) A[(k + 1 + i) * N + k] = VLBE_R(0.0);
        /* left: rows k+1.., columns k+1..: A -= beta v (v^T A) */
        for (j = k + 1; j < N; ++j) w[j] = VLBE_R(0.0);
        for (i = 0; i < m; ++i) {
            const vlbe_real *ai = A + (k + 1 + i) * N;
            for (j = k + 1; j < N; ++j) w[j] += v[i] * ai[j];
        }
        for (i = 0; i < m; ++i) {
            vlbe_real *ai = A + (k + 1 + i) * N;
            t = beta * v[i];
            for (j = k + 1; j < N; ++j) ai[j] -= t * w[j];
        }
        /* right: all rows, columns k+1..: A -= beta (A v) v^T */
        for (i = 0; i < N; ++i) {
            vlbe_real *ai = A + i * N + k + 1;
            vlbe_real s = VLBE_R(0.0);
            for (j = 0; j < m; ++j) s += ai[j] * v[j];
            s *= beta;
            for (j = 0; j < m; ++j) ai[j] -= s * v[j];
        }
    }
}

/* The reflector P = I - beta v v^T, v = (v0, y, z) (z = 0 for 2 rows), that
   maps (x, y, z) to (alpha, 0, 0); 0 when (x, y, z) = 0 (no reflection) */
VLBE_INLINE int vlbe__eig_house3(vlbe_real x, vlbe_real y, vlbe_real z, vlbe_real *v,
                                 vlbe_real *beta, vlbe_real *alpha)
{
    const vlbe_real sc = vlbe_fabs(x) + vlbe_fabs(y) + vlbe_fabs(z);
    vlbe_real nrm, a;
    if (sc == VLBE_R(0.0)) return 0;
    x /= sc;
    y /= sc;
    z /= sc;
    nrm = vlbe_sqrt(x * x + y * y + z * z);
    a = x >= VLBE_R(0.0) ? -nrm : nrm;
    v[0] = x - a;
    v[1] = y;
    v[2] = z;
    *beta = VLBE_R(1.0) / (nrm * vlbe_fabs(v[0]));
    *alpha = a * sc;
    return 1;
}

/* One Francis double-shift step on the active block lo..hi (hi - lo >= 2)
   of the Hessenberg H (GvL alg. 7.5.1): the shifts are the eigenvalues of
   the trailing 2 x 2 (sum s, product t), or an exceptional pair at
   iterations 10 and 20 since the last deflation (the 2 x 2 [a b; c a], a =
   h_hh + 0.75 w, b = -0.4375 w, c = w, w = |h_h,h-1| + |h_h-1,h-2|, the
   values of LAPACK's xLAHQR).  The reflectors are applied to the block's
   rows and columns only (the eigenvalues need no more). */
VLBE_INLINE void vlbe__eig_francis(size_t N, vlbe_real *H, size_t lo, size_t hi, int its)
{
    vlbe_real s, t, x, y, z, v[3], beta, alpha;
    size_t k, j, r, nr;
#define VLBE__H(i, j) H[(i) * N + (j)]
    if (its == 10 || its == 20) {
        const vlbe_real w = vlbe_fabs(VLBE__H(hi, hi - 1)) + vlbe_fabs(VLBE__H(hi - 1, hi - 2));
        const vlbe_real a = VLBE__H(hi, hi) + VLBE_R(0.75) * w;
        s = VLBE_R(2.0) * a;
        t = a * a + VLBE_R(0.4375) * w * w;
    } else {
        const vlbe_real a = VLBE__H(hi - 1, hi - 1), b = VLBE__H(hi - 1, hi);
        const vlbe_real c = VLBE__H(hi, hi - 1), d = VLBE__H(hi, hi);
        s = a + d;
        t = a * d - b * c;
    }
    /* first column of (H - s1 I)(H - s2 I) = H^2 - s H + t I */
    x = VLBE__H(lo, lo) * VLBE__H(lo, lo) + VLBE__H(lo, lo + 1) * VLBE__H(lo + 1, lo) -
        s * VLBE__H(lo, lo) + t;
    y = VLBE__H(lo + 1, lo) * (VLBE__H(lo, lo) + VLBE__H(lo + 1, lo + 1) - s);
    z = VLBE__H(lo + 1, lo) * VLBE__H(lo + 2, lo + 1);
    for (k = lo; k + 1 <= hi; ++k) { /* reflector on rows k .. k+nr-1 */
        nr = k + 2 <= hi ? 3 : 2;
        if (nr == 2) z = VLBE_R(0.0);
        if (vlbe__eig_house3(x, y, z, v, &beta, &alpha)) {
            const size_t j0 = k > lo ? k : lo;
            if (k > lo) { /* column k - 1: the bulge chased down */
                VLBE__H(k, k - 1) = alpha;
                VLBE__H(k + 1, k - 1) = VLBE_R(0.0);
                if (nr == 3) VLBE__H(k + 2, k - 1) = VLBE_R(0.0);
            }
            for (j = j0; j <= hi; ++j) {
                vlbe_real u = v[0] * VLBE__H(k, j) + v[1] * VLBE__H(k + 1, j);
                if (nr == 3) u += v[2] * VLBE__H(k + 2, j);
                u *= beta;
                VLBE__H(k, j) -= u * v[0];
                VLBE__H(k + 1, j) -= u * v[1];
                if (nr == 3) VLBE__H(k + 2, j) -= u * v[2];
            }
            r = k + 3 < hi ? k + 3 : hi;
            for (j = lo; j <= r; ++j) {
                vlbe_real *hj = H + j * N + k;
                vlbe_real u = v[0] * hj[0] + v[1] * hj[1];
                if (nr == 3) u += v[2] * hj[2];
                u *= beta;
                hj[0] -= u * v[0];
                hj[1] -= u * v[1];
                if (nr == 3) hj[2] -= u * v[2];
            }
        }
        if (k + 1 < hi) {
            x = VLBE__H(k + 1, k);
            y = VLBE__H(k + 2, k);
            z = k + 3 <= hi ? VLBE__H(k + 3, k) : VLBE_R(0.0);
        }
    }
#undef VLBE__H
}

/* eigenvalues of the 2 x 2 [a b; c d]: real (wi = 0) or a complex pair
   (w0 = re + i im, w1 = re - i im, im > 0), scaled against overflow */
VLBE_INLINE void vlbe__eig_2x2(vlbe_real a, vlbe_real b, vlbe_real c, vlbe_real d, vlbe_real *wr,
                               vlbe_real *wi)
{
    vlbe_real sc = vlbe_fabs(a), p, bc, disc;
    if (vlbe_fabs(b) > sc) sc = vlbe_fabs(b);
    if (vlbe_fabs(c) > sc) sc = vlbe_fabs(c);
    if (vlbe_fabs(d) > sc) sc = vlbe_fabs(d);
    wi[0] = wi[1] = VLBE_R(0.0);
    if (sc == VLBE_R(0.0)) {
        wr[0] = wr[1] = VLBE_R(0.0);
        return;
    }
    a /= sc;
    b /= sc;
    c /= sc;
    d /= sc;
    p = VLBE_R(0.5) * (a - d);
    bc = b * c;
    disc = p * p + bc; /* (lam - d)^2 - 2 p (lam - d) - bc = 0 */
    if (disc >= VLBE_R(0.0)) {
        const vlbe_real r = vlbe_sqrt(disc), zz = p + (p >= VLBE_R(0.0) ? r : -r);
        wr[0] = (d + zz) * sc;                                 /* no cancellation in zz */
        wr[1] = (zz != VLBE_R(0.0) ? d - bc / zz : d) * sc; /* product of the roots: -bc */
    } else {
        wr[0] = wr[1] = (d + p) * sc;
        wi[0] = vlbe_sqrt(-disc) * sc;
        wi[1] = -wi[0];
    }
}

/* Eigenvalues of a general real n x n matrix A (row-major, OVERWRITTEN:
   scratch on success and failure).  Balancing (vlbe__eig_balance),
   Householder reduction to Hessenberg form (GvL alg. 7.4.2), then the
   Francis implicit double-shift QR iteration with deflation (GvL algs.
   7.5.1 and 7.5.2): a subdiagonal entry with |h_k,k-1| <= EPS (|h_k-1,k-1|
   + |h_kk|) (or below VLBE_REAL_MIN) is set to 0 and the matrix splits;
   a 1 x 1 block is a real eigenvalue, a 2 x 2 block a real pair or a
   complex conjugate pair.
   wr[n], wi[n]: real and imaginary parts, in the order of the diagonal of
   the final quasi-triangular form; a complex pair sits in two adjacent
   entries, the one with positive imaginary part first.
   Accuracy: the QR iteration is backward stable, each eigenvalue is exact
   for a matrix within a few n EPS ||A|| (balanced) of A: its error is
   that times its condition number (a multiple eigenvalue of a defective
   matrix, of multiplicity m, loses a factor 1/m of the digits).
   work: vlbe_eig_real_work_len(n) reals.  Status (wr and wi untouched on
   failure): VLBE_EARG, VLBE_EWORK, VLBE_ENONFINITE (A, before anything is
   written), VLBE_ENOCONV when 30 n double-shift steps pass without a
   deflation (exceptional shifts at the 10th and 20th; not seen);
   VLBE_ENONFINITE also for an overflow in the iteration (entries near
   VLBE_REAL_MAX). */
VLBE_API vlbe_status vlbe_eig_real(int n, vlbe_real *A, vlbe_real *wr, vlbe_real *wi,
                                   vlbe_real *work, size_t work_len)
{
    size_t N, i, lo, hi, len = 0;
    vlbe_real *er, *ei, hnorm = VLBE_R(0.0);
    long its = 0, itmax;
    VLBE_ASSERT(A != NULL && wr != NULL && wi != NULL && work != NULL);
    if (!vlbe__eig_len(n, 0, 4, &len) || !vlbe__eig_len(n, 1, 0, &i)) return VLBE_EARG;
    if (work_len < len) return VLBE_EWORK;
    if (!vlbe__mat_finite(n, A)) return VLBE_ENONFINITE;
    N = (size_t)n;
    er = work + 2 * N;
    ei = work + 3 * N;
    itmax = 30L * (long)n;
    vlbe__eig_balance(N, A);
    vlbe__eig_hess(N, A, work, work + N);
    for (i = 0; i < N * N; ++i)
        if (vlbe_fabs(A[i]) > hnorm) hnorm = vlbe_fabs(A[i]);
    hi = N - 1;
    for (;;) {
        size_t l;
        /* the lowest l <= hi with a negligible h_l,l-1 (l = 0: none) */
        for (l = hi; l > 0; --l) {
            const vlbe_real h = vlbe_fabs(A[l * N + l - 1]);
            vlbe_real tst = vlbe_fabs(A[(l - 1) * N + l - 1]) + vlbe_fabs(A[l * N + l]);
            if (tst == VLBE_R(0.0)) tst = hnorm;
            if (h <= VLBE_EPS * tst || h < VLBE_REAL_MIN) {
                A[l * N + l - 1] = VLBE_R(0.0);
                break;
            }
        }
        lo = l;
        if (lo == hi) { /* 1 x 1 */
            er[hi] = A[hi * N + hi];
            ei[hi] = VLBE_R(0.0);
            its = 0;
            if (hi == 0) break;
            --hi;
        } else if (lo + 1 == hi) { /* 2 x 2 */
            vlbe__eig_2x2(A[lo * N + lo], A[lo * N + hi], A[hi * N + lo], A[hi * N + hi], er + lo,
                          ei + lo);
            its = 0;
            if (lo == 0) break;
            hi = lo - 1;
        } else {
            if (its >= itmax) return VLBE_ENOCONV;
            ++its;
            vlbe__eig_francis(N, A, lo, hi, (int)(its % 30));
        }
    }
    if (!vlbe_all_finite(er, n) || !vlbe_all_finite(ei, n)) return VLBE_ENONFINITE;
    for (i = 0; i < N; ++i) {
        wr[i] = er[i];
        wi[i] = ei[i];
    }
    return VLBE_OK;
}

/* Reals and ints of workspace for vlbe_eig_quad: 9 n^2 + 20 n and 4 n (0
   for n < 1 or when 2n does not fit int or the count size_t). */
VLBE_API size_t vlbe_eig_quad_work_len(int n)
{
    size_t len = 0;
    if (n > INT_MAX / 2) return 0;
    return vlbe__eig_len(n, 9, 20, &len) ? len : 0;
}
VLBE_API size_t vlbe_eig_quad_iwork_len(int n)
{
    size_t len = 0;
    if (n > INT_MAX / 2) return 0;
    return vlbe__eig_len(n, 0, 4, &len) ? len : 0;
}

/* |a + i b| without overflow or underflow of the squares */
VLBE_INLINE vlbe_real vlbe__cabs(vlbe_real a, vlbe_real b)
{
    vlbe_real x = vlbe_fabs(a), y = vlbe_fabs(b), t;
    if (x < y) {
        t = x;
        x = y;
        y = t;
    }
    if (x == VLBE_R(0.0)) return x;
    t = y / x;
    return x * vlbe_sqrt(VLBE_R(1.0) + t * t);
}

/* The order of vlbe_eig_quad's output: 1 when eigenvalue k comes before
   eigenvalue m.  am = |mu| = 1 / |s - sigma| (descending: nearest the
   shift first), then |Im s| descending (a conjugate pair before a real
   eigenvalue of the same distance), Re s ascending, then the pair: grp[k]
   = the index in vlbe_eig_real's output of the pair's first member (of k
   itself when real), ascending, so that a repeated pair comes out as +, -,
   +, -; last Im s descending (+imag first). */
VLBE_INLINE int vlbe__eig_quad_before(const vlbe_real *am, const vlbe_real *sr,
                                      const vlbe_real *si, const int *grp, int k, int m)
{
    if (am[k] != am[m]) return am[k] > am[m];
    if (vlbe_fabs(si[k]) != vlbe_fabs(si[m])) return vlbe_fabs(si[k]) > vlbe_fabs(si[m]);
    if (sr[k] != sr[m]) return sr[k] < sr[m];
    if (grp[k] != grp[m]) return grp[k] < grp[m];
    return si[k] > si[m];
}

/* The eigenvector x of (s^2 M + s D + K) x = 0 at s = a + i b by inverse
   iteration with a fixed shift s' = s + del rho (rho = max(|s|, |s -
   sigma|) > 0, del = EPS^(2/3), times 64 on each retry while P(s') is
   singular to the LU's test), in the nonlinear form of Ruhe (GvL sec.
   7.6.1 for the linear case; A. Ruhe, Algorithms for the nonlinear
   eigenvalue problem, SIAM J. Numer. Anal. 10 (1973) 674-689):
        P(s') x_(k+1) = P'(s') x_k,   P'(s) = 2 s M + D.
   Its fixed point solves P(s') x = nu P'(s') x, nu ~ s' - s, which is
   P(s' - nu) x = O(nu^2): the eigenvector of s to O(del^2) (plain inverse
   iteration, P(s') x_(k+1) = x_k, would settle on the vector of the linear
   problem P(s') x = nu x, an O(del) away).  Each step multiplies the
   component along x by 1/(del rho) against 1/|s_other - s'| for the
   others: three steps leave (del rho / gap)^3.  P(s') as a real system:
   real s (b = 0) the n x n P(s'); else the 2n x 2n [Pr -Pi; Pi Pr] on
   (xr, xi), Pr = (a'^2 - b^2) M + a' D + K, Pi = 2 a' b M + b D (and
   P'(s') alike: Qr = 2 a' M + D, Qi = 2 b M).  The iterate is scaled to
   unit max-norm before each solve.  Result in xr[j*ld], xi[j*ld]: unit
   2-norm, the component of largest modulus real and positive (the first
   of equal moduli).  G: 4 n^2 reals, x: 4n, piv: 2n. */
VLBE_INLINE vlbe_status vlbe__eig_quad_vec(int n, const vlbe_real *M, const vlbe_real *D,
                                           const vlbe_real *K, vlbe_real sigma, vlbe_real a,
                                           vlbe_real b, vlbe_real *G, vlbe_real *x, int *piv,
                                           vlbe_real *xr, vlbe_real *xi, size_t ld)
{
    const size_t N = (size_t)n;
    const int cplx = b != VLBE_R(0.0), m = cplx ? 2 * n : n;
    const size_t Mm = (size_t)m;
    vlbe_real rho = vlbe__cabs(a, b), del, ap = a, nrm, cr, ci, big;
    vlbe_real *y = x + Mm;
    size_t i, j, jm;
    int it, tries;
    vlbe_status st = VLBE_ESINGULAR;
    del = vlbe_pow(VLBE_EPS, VLBE_R(2.0) / VLBE_R(3.0));
    if (vlbe__cabs(a - sigma, b) > rho) rho = vlbe__cabs(a - sigma, b);
    for (tries = 0; tries < 4 && st == VLBE_ESINGULAR; ++tries, del *= VLBE_R(64.0)) {
        vlbe_real c2, c1;
        ap = a + del * rho;
        c2 = ap * ap - b * b;
        c1 = VLBE_R(2.0) * ap * b;
        for (i = 0; i < N; ++i)
            for (j = 0; j < N; ++j) {
                const size_t e = i * N + j;
                const vlbe_real d = D ? D[e] : VLBE_R(0.0);
                const vlbe_real pr = c2 * M[e] + ap * d + K[e];
                G[i * Mm + j] = pr;
                if (cplx) {
                    const vlbe_real pi = c1 * M[e] + b * d;
                    G[i * Mm + N + j] = -pi;
                    G[(N + i) * Mm + j] = pi;
                    G[(N + i) * Mm + N + j] = pr;
                }
            }
        st = vlbe_lu_factor(m, G, G, piv, NULL);
    }
    if (st != VLBE_OK) return st == VLBE_ESINGULAR ? VLBE_ENOCONV : st;
    for (j = 0; j < Mm; ++j) /* start: no symmetry of the problem makes it orthogonal */
        x[j] = j < N ? VLBE_R(1.0) + (vlbe_real)j / (vlbe_real)n : VLBE_R(0.0);
    for (it = 0; it < 3; ++it) {
        for (i = 0; i < N; ++i) { /* y = P'(s') x */
            vlbe_real yr = VLBE_R(0.0), yi = VLBE_R(0.0);
            for (j = 0; j < N; ++j) {
                const size_t e = i * N + j;
                const vlbe_real qr = VLBE_R(2.0) * ap * M[e] + (D ? D[e] : VLBE_R(0.0));
                yr += qr * x[j];
                if (cplx) {
                    const vlbe_real qi = VLBE_R(2.0) * b * M[e];
                    yr -= qi * x[N + j];
                    yi += qi * x[j] + qr * x[N + j];
                }
            }
            y[i] = yr;
            if (cplx) y[N + i] = yi;
        }
        big = vlbe_vec_norm_inf(m, y);
        if (!(big > VLBE_R(0.0)) || !(big <= VLBE_REAL_MAX)) return VLBE_ENONFINITE;
        for (j = 0; j < Mm; ++j) x[j] = y[j] / big;
        vlbe_lu_solve(m, G, piv, 1, x);
    }
    /* the phase: the largest component real positive; then unit 2-norm */
    jm = 0;
    big = VLBE_R(-1.0);
    for (j = 0; j < N; ++j) {
        const vlbe_real t = vlbe__cabs(x[j], cplx ? x[N + j] : VLBE_R(0.0));
        if (t > big) {
            big = t;
            jm = j;
        }
    }
    nrm = vlbe_vec_norm2(m, x);
    if (!(big > VLBE_R(0.0)) || !(nrm <= VLBE_REAL_MAX)) return VLBE_ENONFINITE;
    cr = x[jm] / big; /* conj(x_jm) / |x_jm| = cr - i ci */
    ci = cplx ? x[N + jm] / big : VLBE_R(0.0);
    for (j = 0; j < N; ++j) {
        const vlbe_real u = x[j], v = cplx ? x[N + j] : VLBE_R(0.0);
        xr[j * ld] = (u * cr + v * ci) / nrm;
        xi[j * ld] = (v * cr - u * ci) / nrm;
    }
    xr[jm * ld] = big / nrm;
    xi[jm * ld] = VLBE_R(0.0);
    return VLBE_OK;
}

/* The quadratic eigenproblem (s^2 M + s D + K) x = 0, M, D, K n x n real
   (any structure: M nonsingular, D may be NULL for 0; e.g. a gyroscopic
   G, skew, plus damping), by SHIFT-INVERT of the first-order form.
   With z = (x, s x) the problem is A z = s z, A = [0 I; -M^-1 K, -M^-1 D]
   (2n eigenvalues s = sre + i sim).  Its inverse about sigma,
   T = (A - sigma I)^-1, needs no M^-1: (A - sigma I)(u, v) = (f, g) reads
   v = f + sigma u and -K u - (D + sigma M) v = M g, so
        P(sigma) u = -(M g + (D + sigma M) f),   v = f + sigma u,
   P(sigma) = sigma^2 M + sigma D + K: T = [U; [I 0] + sigma U] with
   U = -P(sigma)^-1 [D + sigma M, M] (n x 2n), from ONE LU of P(sigma)
   (vlbe_lu_factor) and a solve with 2n right-hand sides.  vlbe_eig_real
   on T gives mu = 1/(s - sigma), so s = sigma + 1/mu.
   Why: QR is backward stable, each mu has an error of a few EPS ||T||
   (times its condition), and ||T|| is about the largest |mu| = 1 /
   min|s - sigma|: the eigenvalues NEAREST the shift, the lowest modes of
   a stiff beam for sigma = 0 or just below, come out to a few EPS
   relative, and the far ones (the high modes, 1e4 .. 1e6 times the
   fundamental's |s| in a beam) carry the rounding instead.  QR on A
   itself would make the error EPS max|s| for every eigenvalue, a loss of
   max|s| / |s_1| in the fundamental, and forming M^-1 K more on top.
   sigma: real, not an eigenvalue (VLBE_ESINGULAR when P(sigma) is
   singular to vlbe_lu_factor's test: move the shift).
   sre[2n], sim[2n]: the eigenvalues, by |s - sigma| ascending (nearest
   the shift first); ties: a conjugate pair adjacent, +imag first; then
   |Im s| descending, Re s ascending, then vlbe_eig_real's order of the
   pairs (a repeated pair comes out +, -, +, -) (deterministic).
   nvec (0..2n): the eigenvectors of the first nvec eigenvalues of that
   order, into Xre, Xim (n x nvec each, ld nvec, may be NULL; both are
   computed when either is asked for, each written when non-NULL): column
   k, Xre[i*nvec + k] + i Xim[i*nvec + k], the x of eigenvalue k, unit
   2-norm, its component of largest modulus real and positive (the vector
   of a conjugate s is the conjugate vector), by inverse iteration
   (vlbe__eig_quad_vec): ||P(s) x|| is then a few EPS (|s|^2 ||M|| + |s|
   ||D|| + ||K||) for a well separated eigenvalue.  Cost: an LU of 2n (n
   for real s) per conjugate pair, about 5 n^3 flops each, so that the few
   lowest modes' vectors cost about what the eigenvalues cost (~ 100 n^3)
   and all 2n of them 10 n^4.
   work: vlbe_eig_quad_work_len(n) reals, iwork: vlbe_eig_quad_iwork_len(n)
   ints.  Status (outputs untouched on failure): VLBE_EARG (also nvec
   outside 0..2n), VLBE_EWORK
   (either buffer), VLBE_ENONFINITE (NaN or Inf in M, D, K or sigma; or a
   mu = 0, an infinite s: M singular), VLBE_ESINGULAR (P(sigma)),
   VLBE_ENOCONV (vlbe_eig_real, or inverse iteration whose P(s') stayed
   singular; not seen). */
VLBE_API vlbe_status vlbe_eig_quad(int n, const vlbe_real *M, const vlbe_real *D,
                                   const vlbe_real *K, vlbe_real sigma, vlbe_real *sre,
                                   vlbe_real *sim, int nvec, vlbe_real *Xre, vlbe_real *Xim,
                                   vlbe_real *work, size_t work_len, int *iwork,
                                   size_t iwork_len)
{
    size_t N, N2, i, j, len = 0, ilen = 0;
    vlbe_real *T, *XR, *XI, *PL, *mr, *mi, *sr, *si, *xv, *ew;
    int *piv, *perm, *grp, k, q, m2;
    vlbe_status st;
    VLBE_ASSERT(M != NULL && K != NULL && sre != NULL && sim != NULL);
    VLBE_ASSERT(work != NULL && iwork != NULL);
    if (n > INT_MAX / 2 || !vlbe__eig_len(n, 9, 20, &len) || !vlbe__eig_len(n, 0, 4, &ilen) ||
        nvec < 0 || nvec > 2 * n)
        return VLBE_EARG;
    if (work_len < len || iwork_len < ilen) return VLBE_EWORK;
    if (!vlbe__mat_finite(n, M) || !vlbe__mat_finite(n, K) || (D && !vlbe__mat_finite(n, D)) ||
        !vlbe_all_finite(&sigma, 1))
        return VLBE_ENONFINITE;
    N = (size_t)n;
    N2 = 2 * N;
    m2 = 2 * n;
    T = work;
    XR = T + 4 * N * N;
    XI = XR + 2 * N * N;
    PL = XI + 2 * N * N;
    mr = PL + N * N;
    mi = mr + N2;
    sr = mi + N2;
    si = sr + N2;
    xv = si + N2;
    ew = xv + 2 * N2;
    piv = iwork;
    perm = iwork + N2;
    grp = piv; /* piv is free between the LU of P(sigma) and the vectors */
    /* P(sigma) and its LU */
    for (i = 0; i < N * N; ++i)
        PL[i] = (sigma * M[i] + (D ? D[i] : VLBE_R(0.0))) * sigma + K[i];
    if ((st = vlbe_lu_factor(n, PL, PL, piv, NULL)) != VLBE_OK) return st;
    /* T = [U; [I 0] + sigma U], U = -P^-1 [D + sigma M, M] (rows 0..n-1) */
    for (i = 0; i < N; ++i)
        for (j = 0; j < N; ++j) {
            const size_t e = i * N + j;
            T[i * N2 + j] = -((D ? D[e] : VLBE_R(0.0)) + sigma * M[e]);
            T[i * N2 + N + j] = -M[e];
        }
    vlbe_lu_solve(n, PL, piv, m2, T);
    for (i = 0; i < N; ++i)
        for (j = 0; j < N2; ++j)
            T[(N + i) * N2 + j] = sigma * T[i * N2 + j] + (j == i ? VLBE_R(1.0) : VLBE_R(0.0));
    if ((st = vlbe_eig_real(m2, T, mr, mi, ew, 4 * N2)) != VLBE_OK) return st;
    /* s = sigma + 1/mu (Smith's division), |mu| into mr */
    for (k = 0; k < m2; ++k) {
        const vlbe_real a = mr[k], b = mi[k];
        vlbe_real r, den;
        if (a == VLBE_R(0.0) && b == VLBE_R(0.0)) return VLBE_ENONFINITE;
        if (vlbe_fabs(a) >= vlbe_fabs(b)) {
            r = b / a;
            den = a + b * r;
            sr[k] = sigma + VLBE_R(1.0) / den;
            si[k] = -r / den;
        } else {
            r = a / b;
            den = b + a * r;
            sr[k] = sigma + r / den;
            si[k] = -VLBE_R(1.0) / den;
        }
        mr[k] = vlbe__cabs(a, b);
        perm[k] = k;
        grp[k] = b < VLBE_R(0.0) && k > 0 ? k - 1 : k; /* eig_real: a pair's + first */
    }
    if (!vlbe_all_finite(sr, m2) || !vlbe_all_finite(si, m2)) return VLBE_ENONFINITE;
    for (k = 1; k < m2; ++k) { /* insertion sort of the indices */
        const int p = perm[k];
        for (q = k; q > 0 && vlbe__eig_quad_before(mr, sr, si, grp, p, perm[q - 1]); --q)
            perm[q] = perm[q - 1];
        perm[q] = p;
    }
    if (Xre || Xim)
        for (q = 0; q < nvec; ++q) {
            const int p = perm[q];
            if (q > 0 && si[p] < VLBE_R(0.0) && si[p] == -si[perm[q - 1]] &&
                sr[p] == sr[perm[q - 1]]) { /* the conjugate of the previous one */
                for (i = 0; i < N; ++i) {
                    XR[i * N2 + (size_t)q] = XR[i * N2 + (size_t)q - 1];
                    XI[i * N2 + (size_t)q] = -XI[i * N2 + (size_t)q - 1];
                }
                continue;
            }
            st = vlbe__eig_quad_vec(n, M, D, K, sigma, sr[p], si[p], T, xv, piv, XR + q, XI + q,
                                    N2);
            if (st != VLBE_OK) return st;
        }
    for (q = 0; q < m2; ++q) {
        sre[q] = sr[perm[q]];
        sim[q] = si[perm[q]];
    }
    for (i = 0; i < N; ++i)
        for (j = 0; j < (size_t)nvec; ++j) {
            if (Xre) Xre[i * (size_t)nvec + j] = XR[i * N2 + j];
            if (Xim) Xim[i * (size_t)nvec + j] = XI[i * N2 + j];
        }
    return VLBE_OK;
}

#endif /* VLBE_H */

/*
MIT License

Copyright (c) 2026 the vlbe authors

Permission is hereby granted, free of charge, to any person obtaining a copy of
this software and associated documentation files (the "Software"), to deal in
the Software without restriction, including without limitation the rights to
use, copy, modify, merge, publish, distribute, sublicense, and/or sell copies
of the Software, and to permit persons to whom the Software is furnished to do
so, subject to the following conditions:

The above copyright notice and this permission notice shall be included in all
copies or substantial portions of the Software.

THE SOFTWARE IS PROVIDED "AS IS", WITHOUT WARRANTY OF ANY KIND, EXPRESS OR
IMPLIED, INCLUDING BUT NOT LIMITED TO THE WARRANTIES OF MERCHANTABILITY,
FITNESS FOR A PARTICULAR PURPOSE AND NONINFRINGEMENT. IN NO EVENT SHALL THE
AUTHORS OR COPYRIGHT HOLDERS BE LIABLE FOR ANY CLAIM, DAMAGES OR OTHER
LIABILITY, WHETHER IN AN ACTION OF CONTRACT, TORT OR OTHERWISE, ARISING FROM,
OUT OF OR IN CONNECTION WITH THE SOFTWARE OR THE USE OR OTHER DEALINGS IN THE
SOFTWARE.
*/
