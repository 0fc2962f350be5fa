/* vlbe.h -- core of vlbe: configuration, status codes, small vector ops,
   Gauss-Legendre rules, the cubic Hermite / linear basis in ALE form, dense
   and banded LU -- part of vlbe v0.1.0            SPDX-License-Identifier: MIT

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
   VLBE_INLINE      default `static inline`
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
   Stack: at most 384 bytes per function (vlbe_herm_ale_eval; float on a
   Cortex-M4F, gcc -O2, make check-m4; double about twice; README, Embedded).

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

REFERENCES
   [V] S. Yang et al., A variable-length beam element incorporating the effect
       of spinning, Lat. Am. J. Solids Struct. 14 (2017): eqs. 2-7, 15, 17.
   [R] ALE-RANCF variable-length rational element, Machines 10 (2022) 174:
       eqs. 12-15.
   Golub & Van Loan, Matrix Computations, 4th ed., alg. 3.4.1 (LU, partial
   pivoting); sec. 4.3, banded systems: alg. 4.3.1 (band Gaussian
   elimination), the band forward and back substitutions, and band
   elimination with partial pivoting (U gains kl super-diagonals).
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
static inline void vlbe__assert_trap(void) { __builtin_trap(); }
#else
#include <stdlib.h>
static inline void vlbe__assert_trap(void) { abort(); }
#endif
#endif
#endif

/* index of entry (i, j) of a band-stored matrix (see Band storage above) */
#define VLBE_BAND_IDX(ld, kl, i, j) \
    ((size_t)(i) * (size_t)(ld) + (size_t)((j) - (i) + (kl)))

/* -- configuration ------------------------------------------------------ */
#ifndef VLBE_INLINE
#define VLBE_INLINE static inline
#endif
#ifndef VLBE_API
#define VLBE_API VLBE_INLINE
#endif
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
    VLBE_ENOCONV = -4,    /* Newton iteration diverged or hit max_iter         */
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
   and the element (or node, constraint) in their err and err_elem fields:
   1 for VLBE_ELENGTH, VLBE_ESINGULAR and VLBE_ENONFINITE (co-rotational
   beams: also VLBE_EBOUND, a node outside the prismatic joint), -1 for any
   other status (VLBE_ECALLBACK of a failing user function, VLBE_EARG, a
   chain's point load off the chain: VLBE_EBOUND).
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

/* ===== implementation =================================================== */

VLBE_API const char *vlbe_status_str(vlbe_status s)
{
    switch (s) {
    case VLBE_OK: return "ok";
    case VLBE_EARG: return "argument out of range";
    case VLBE_EWORK: return "workspace too small";
    case VLBE_ESINGULAR: return "singular matrix";
    case VLBE_ENOCONV: return "Newton iteration did not converge";
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
                      vlbe__int_equil), or below the smallest normal number,
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
