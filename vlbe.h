/* vlbe.h -- core of vlbe: configuration, status codes, small vector ops,
   Gauss-Legendre rules, the cubic Hermite / linear basis in ALE form, dense LU
   -- part of vlbe v0.1.0                          SPDX-License-Identifier: MIT

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
   VLBE_ASSERT(x)   default assert(x); pure kernels check preconditions with it
   vlbe_sqrt ... vlbe_floor   the libm names; override all of them or none

CONVENTIONS
   Units: any consistent system (SI in all examples); angles in radians.
   Matrices are flat and row-major, A[i*n + j].  Inputs first, then outputs,
   then workspace.  Output pointers are VLBE_RESTRICT: they must not alias
   inputs unless a function says otherwise.
   Errors: functions whose result depends on the data return vlbe_status
   (0 = VLBE_OK, negative = a specific failure); a failed call leaves the
   caller's data as it was before the call.  Programmer errors (NULL, n < 1)
   are caught by VLBE_ASSERT.  Nothing here allocates, prints or aborts.
   Stack: every function here uses less than 256 bytes of stack.

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
   mixed included.  Written as polynomials in d = p - p1 and L, those
   partials are exact operators: d/dp = D_d, d/dp2 = D_L, d/dp1 = -(D_d + D_L).

API (one line each)
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

REFERENCES
   [V] S. Yang et al., A variable-length beam element incorporating the effect
       of spinning, Lat. Am. J. Solids Struct. 14 (2017): eqs. 2-7, 15, 17.
   [R] ALE-RANCF variable-length rational element, Machines 10 (2022) 174:
       eqs. 12-15.
   Golub & Van Loan, Matrix Computations, 4th ed., alg. 3.4.1 (LU, partial
   pivoting).
*/
#ifndef VLBE_H
#define VLBE_H

#define VLBE_VERSION_MAJOR 0
#define VLBE_VERSION_MINOR 1
#define VLBE_VERSION_PATCH 0
#define VLBE_VERSION_STRING "0.1.0"

#include <stddef.h>
#include <float.h>
#include <math.h>
#ifndef VLBE_ASSERT
#include <assert.h>
#define VLBE_ASSERT(x) assert(x)
#endif

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
#else
typedef double vlbe_real;
#define VLBE_R(x) x
#define VLBE_EPS DBL_EPSILON
#define VLBE_REAL_MAX DBL_MAX
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
    VLBE_ELENGTH = -7,    /* element length p2 - p1 <= 0 (material coords)     */
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
    case VLBE_ELENGTH: return "non-positive element length (p2 <= p1)";
    case VLBE_EWEIGHT: return "non-positive weight";
    case VLBE_EBOUND: return "bound exceeded";
    case VLBE_ECALLBACK: return "callback failed";
    }
    return "unknown status";
}

VLBE_API int vlbe_all_finite(const vlbe_real *x, int n)
{
    int i;
    VLBE_ASSERT(n >= 0 && (n == 0 || x != NULL));
    for (i = 0; i < n; ++i) {
        if (!isfinite(x[i])) return 0;
    }
    return 1;
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
/* Each basis function is sum c * d^m * L^e with d = p - p1 (m + e = 0 for
   N1, N3, H1, H2 and 1 for N2, N4).  The partial derivative
   D_d^a D_L^b (d^m L^e) = ff(m,a) ff(e,b) d^(m-a) L^(e-b) = ff ff xi^(m-a) L^(m+e-a-b),
   with ff the falling factorial, is exact; d/dp1 = -(D_d + D_L). */
VLBE_INLINE vlbe_real vlbe__falling(int x, int k)
{
    vlbe_real r = VLBE_R(1.0);
    int i;
    for (i = 0; i < k; ++i) r *= (vlbe_real)(x - i);
    return r;
}

/* Value of D_p^k D_p1^k1 D_p2^k2 of one function given as nt terms c d^m L^e. */
VLBE_INLINE vlbe_real vlbe__ale_term_deriv(int nt, const signed char *c, const signed char *m,
                                           const signed char *e, int k, int k1, int k2,
                                           const vlbe_real *xip, const vlbe_real *Lp)
{
    /* D_p^k (-(D_d + D_L))^k1 D_L^k2 = (-1)^k1 sum_j C(k1,j) D_d^(k+j) D_L^(k1-j+k2) */
    static const signed char binom[3][3] = {{1, 0, 0}, {1, 1, 0}, {1, 2, 1}};
    vlbe_real sum = VLBE_R(0.0);
    int t, j;
    for (t = 0; t < nt; ++t) {
        for (j = 0; j <= k1; ++j) {
            int a = k + j, bb = k1 - j + k2;
            int pe;
            vlbe_real f;
            if (a > m[t]) continue;
            f = (vlbe_real)c[t] * (vlbe_real)binom[k1][j] * vlbe__falling(m[t], a) *
                vlbe__falling(e[t], bb);
            if (f == VLBE_R(0.0)) continue;
            pe = m[t] + e[t] - a - bb; /* power of L, in [-5, 1] */
            sum += f * xip[m[t] - a] * Lp[pe + 5];
        }
    }
    return (k1 % 2) ? -sum : sum;
}

VLBE_API void vlbe_herm_ale_eval(vlbe_real p, vlbe_real p1, vlbe_real p2, int kmax, int amax,
                                 vlbe_herm_ale *VLBE_RESTRICT b)
{
    /* terms c d^m L^e of N1..N4 (vlbse eq. 5 with s = 2 xi - 1) and H1, H2 (eq. 7) */
    static const signed char nt[6] = {3, 3, 2, 2, 2, 1};
    static const signed char c[6][3] = {{1, -3, 2}, {1, -2, 1}, {3, -2, 0},
                                        {-1, 1, 0}, {1, -1, 0}, {1, 0, 0}};
    static const signed char m[6][3] = {{0, 2, 3}, {1, 2, 3}, {2, 3, 0},
                                        {2, 3, 0}, {0, 1, 0}, {1, 0, 0}};
    static const signed char e[6][3] = {{0, -2, -3}, {0, -1, -2}, {-2, -3, 0},
                                        {-1, -2, 0}, {0, -1, 0}, {-1, 0, 0}};
    /* (k1, k2) of each VLBE_DA_* selector */
    static const signed char da[VLBE_DA_N][2] = {{0, 0}, {1, 0}, {0, 1}, {2, 0}, {1, 1}, {0, 2}};
    vlbe_real L = p2 - p1, xi, Li, xip[4], Lp[7];
    int na, k, a, i;
    VLBE_ASSERT(b != NULL && L > VLBE_R(0.0));
    VLBE_ASSERT(kmax >= 0 && kmax <= 3 && amax >= 0 && amax <= 2);
    Li = VLBE_R(1.0) / L;
    xi = (p - p1) * Li;
    b->L = L;
    b->s = VLBE_R(2.0) * xi - VLBE_R(1.0);
    xip[0] = VLBE_R(1.0);
    xip[1] = xi;
    xip[2] = xi * xi;
    xip[3] = xip[2] * xi;
    Lp[6] = L;       /* L^1  */
    Lp[5] = VLBE_R(1.0); /* L^0 */
    for (i = 4; i >= 0; --i) Lp[i] = Lp[i + 1] * Li; /* L^-1 .. L^-5 */
    na = amax == 0 ? 1 : (amax == 1 ? 3 : VLBE_DA_N);
    for (k = 0; k <= kmax; ++k) {
        for (a = 0; a < na; ++a) {
            for (i = 0; i < 4; ++i)
                b->h[k][a][i] = vlbe__ale_term_deriv(nt[i], c[i], m[i], e[i], k, da[a][0], da[a][1],
                                                    xip, Lp);
            if (k < 2)
                for (i = 0; i < 2; ++i)
                    b->l[k][a][i] = vlbe__ale_term_deriv(nt[4 + i], c[4 + i], m[4 + i], e[4 + i], k,
                                                        da[a][0], da[a][1], xip, Lp);
        }
    }
}

/* -- dense LU ----------------------------------------------------------- */
/* LU = P A with partial pivoting (Golub & Van Loan alg. 3.4.1), right-looking,
   row-major so the rank-1 update runs along contiguous rows.
   A, LU: n*n row-major.  LU may equal A (in-place); otherwise A is untouched.
   piv[k] = row swapped with row k at step k.
   Fails with VLBE_ESINGULAR when a pivot is 0 or |pivot| <= n eps max|A|
   (relatively zero: the computed factor would be noise; the test is
   relative to the whole matrix, so scale rows of very different units to
   comparable size first, as the integrators do with constraint rows) and writes the
   1-based failing column to *info (if info != NULL; 0 on success);
   VLBE_ENONFINITE when A holds NaN/Inf.  On failure LU holds no factor;
   A is unchanged unless LU == A. */
VLBE_API vlbe_status vlbe_lu_factor(int n, const vlbe_real *A, vlbe_real *LU, int *piv, int *info)
{
    size_t nn, N, e;
    vlbe_real amax = VLBE_R(0.0), tol;
    int i, j, k;
    VLBE_ASSERT(n >= 1 && A != NULL && LU != NULL && piv != NULL);
    N = (size_t)n;
    nn = N * N;
    if (info) *info = 0;
    for (e = 0; e < nn; ++e) {
        vlbe_real t = vlbe_fabs(A[e]);
        if (!isfinite(t)) return VLBE_ENONFINITE;
        if (t > amax) amax = t;
    }
    if (LU != A)
        for (e = 0; e < nn; ++e) LU[e] = A[e];
    tol = (vlbe_real)n * VLBE_EPS * amax;
    for (k = 0; k < n; ++k) {
        vlbe_real *rk = LU + (size_t)k * N, pmax = vlbe_fabs(rk[k]), inv;
        int p = k;
        for (i = k + 1; i < n; ++i) {
            vlbe_real t = vlbe_fabs(LU[(size_t)i * N + (size_t)k]);
            if (t > pmax) {
                pmax = t;
                p = i;
            }
        }
        piv[k] = p;
        if (pmax <= tol || pmax == VLBE_R(0.0)) {
            if (info) *info = k + 1;
            return VLBE_ESINGULAR;
        }
        if (p != k) {
            vlbe_real *rp = LU + (size_t)p * N;
            for (j = 0; j < n; ++j) {
                vlbe_real t = rk[j];
                rk[j] = rp[j];
                rp[j] = t;
            }
        }
        inv = VLBE_R(1.0) / rk[k];
        for (i = k + 1; i < n; ++i) {
            vlbe_real *VLBE_RESTRICT ri = LU + (size_t)i * N;
            vlbe_real lik = ri[k] * inv;
            ri[k] = lik;
            if (lik != VLBE_R(0.0))
                for (j = k + 1; j < n; ++j) ri[j] -= lik * rk[j];
        }
    }
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
