/* integrators.h -- time integration of constrained mechanical systems:
   generalized-alpha family (Newmark, HHT-alpha, Chung-Hulbert generalized-alpha
   in the Arnold-Bruls form, index 3) and variable-step variable-order BDF 1..5
   on the stabilized index-2 (GGL) form -- part of vlbe v0.1.0
                                                   SPDX-License-Identifier: MIT
USAGE
   #include "integrators.h"    (vlbe.h must sit in the same directory)
   No IMPLEMENTATION macro: every function is static inline; link with -lm.

     vlbe_dae sys = {0};  sys.n = ...; sys.m = ...; sys.user = &my;
     sys.mass = my_mass; sys.force = my_force; sys.constr = my_c; sys.constr_jac = my_cq;
       (a chain of ancf_ale.h or rancf.h: vlbe_ale_chain_dae(&ch, &sys); a beam of
       corot2d.h: vlbe_cr2d_beam_dae(&beam, &sys))
     vlbe_hht_params par;  vlbe_hht_params_genalpha(&par, 0.8);
     size_t lw = vlbe_hht_work_len(n, m), liw = vlbe_hht_iwork_len(n, m);
     ... allocate lw vlbe_real and liw int ...
     vlbe_hht st;
     if (vlbe_hht_init(&st, &sys, &par, t0, q0, v0, work, lw, iwork, liw)) fail;
       (q0, v0 off the constraints: par.project = 1 starts from their
       projection, vlbe_dae_project; BDF does so by default)
     while (st.t < t_end - h / 2) if (vlbe_hht_step(&st, h)) break;   (state in st.q, st.v)
       (st.t after k steps is t0 + k h rounded once or twice, never a sum of k
       roundings; the margin h/2 keeps that rounding from adding a step, and
       the loop takes round((t_end - t0)/h) steps)
     or output times without that care: equal steps of at most h that end
     on each t_k exactly (st.t == t_k bit for bit, t_k = 0.1 k or k / 3):
     for (k = 1; k <= nout; ++k) if (vlbe_hht_advance(&st, t0 + k * dt, h)) break;
       (HHT takes the steps it is given: fixed steps for real-time and
       controller loops, halvings only on Newton failure; steps chosen by
       an error estimate are the BDF's, below)

     BDF with error control (same problem, its own workspace sizes):
     vlbe_bdf_params bp;  vlbe_bdf_params_default(&bp);  bp.rtol = bp.atol = 1e-8;
     size_t lw = vlbe_bdf_work_len(n, m), liw = vlbe_bdf_iwork_len(n, m);
     vlbe_bdf bs;
     if (vlbe_bdf_init(&bs, &sys, &bp, t0, q0, v0, work, lw, iwork, liw)) fail;
     for (k = 1; k <= nout; ++k)                       (bs.q, bs.v, bs.lambda at t_k)
         if (vlbe_bdf_advance(&bs, t0 + k * dt)) break;
       (coordinates of very different sizes: bp.atolv, one atol per q and v;
       values between steps without landing on them: vlbe_bdf_step, then
       vlbe_bdf_interp(&bs, t, q, v) for any t in [bs.t - bs.h_last, bs.t])

     Static equilibrium Q(t,q,0) = C_q^T lambda, C = 0 (mass not needed):
     vlbe_static_params sp;  vlbe_static_params_default(&sp);
     size_t lw = vlbe_static_work_len(n, m), liw = vlbe_static_iwork_len(n, m);
     for (k = 1; k <= nload; ++k) {           (load stepping: the caller's job)
         my.load = k * P / nload;               (q, lambda: start in, solution out)
         if (vlbe_dae_static(&sys, &sp, t, q, lambda, NULL, work, lw, iwork, liw)) break;
     }

     Modal analysis about a state (an equilibrium, a steady flow, a steady
     rotation in its turning frame):
     vlbe_dae_consistent_acc(&sys, t, q, v, a, lam, NULL, w, lw, iw, liw);   (or the static lambda)
     int nr;                              (N, Mr, Dr, Kr: n*n reals each; N may be NULL)
     vlbe_dae_linearize(&sys, t, q, v, a, lam, NULL, &nr, N, Mr, Dr, Kr, NULL, w,
                        vlbe_dae_lin_work_len_sys(&sys), iw, vlbe_dae_lin_iwork_len_sys(&sys));
     vlbe_eig_quad(nr, Mr, Dr, Kr, sigma, sre, sim, 0, NULL, NULL, w2, lw2, iw2, liw2);  (vlbe.h)
       (frequencies Im s of the eigenvalues nearest the real shift sigma
       first; undamped and symmetric: vlbe_eig_gsym(nr, Kr, Mr, sigma, ...);
       a turning frame: a vlbe_lin_frame instead of NULL, see
       examples/campbell_rotating.c)

     Long chains: matrices in band form (vlbe_dae.storage).  The model orders
     q and lambda so that each constraint row sits next to the coordinates
     it touches, its callbacks write bands, and the integrators never form
     an n x n matrix: workspace and work per step O((n + m)(kl + ku)).
     Size the workspaces with the _sys queries, which know the storage:
     sys.storage = VLBE_DAE_BANDED;  sys.kl = kl;  sys.ku = ku;  sys.order = order;
     size_t lw = vlbe_hht_work_len_sys(&sys), liw = vlbe_hht_iwork_len_sys(&sys);
     (chains: vlbe_ale_chain_band and vlbe_cr2d_beam_band fill order, kl, ku.)
     A legacy code with its own sparse solver sets sys.lin_factor and
     sys.lin_solve: the integrators hand it the assembled iteration matrix.

CONFIG
   Nothing beyond vlbe.h.

CONVENTIONS
   The system (any consistent units):
        M(t,q,v) q'' + C_q(t,q)^T lambda = Q(t,q,v),      C(t,q) = 0,
   n coordinates q, m holonomic (possibly rheonomic) constraints.  Q is the
   applied-minus-internal generalized force (positive in the sense of q'').
   The problem type vlbe_dae (callbacks, flags, storage) is declared in
   vlbe.h, with the return convention of its callbacks, one for every
   model.  Matrices are row-major.  Callbacks return 0 on success.  A
   positive value says the point asked for lies outside the model's domain
   (a Newton iterate inverted an element, say): the attempt fails like a
   Newton divergence and the step is retried smaller (HHT with max_halvings > 0,
   BDF); when no smaller step is left the integrator stops with
   VLBE_ECALLBACK.  A negative value is fatal: VLBE_ECALLBACK at once.  The
   last failing value is in stats.callback_rc.  Missing Jacobians are formed by
   forward differences (step sqrt(eps) max(|x_j|, 1)).
   The integrators know nothing of elements: they see only the callbacks.
   Failure of a step (Newton divergence, singular iteration matrix,
   non-finite values, step below minimum) is returned as a vlbe_status and
   leaves the state at the last accepted step.
   Failure contract: vlbe.h's; its exceptions here are (a) stats, which
   count the work of failed calls too (rejected, newton_fails, callback_rc
   exist for that); (b) the private iteration-matrix caches of the
   integrator states (a failed step may drop them: the next step forms a
   new matrix); (c) work and iwork of vlbe_hht_init and vlbe_bdf_init when
   the consistent-start solve fails (its scratch; *st and the arguments
   are untouched, and argument errors touch nothing), and of
   vlbe_dae_consistent_acc and vlbe_dae_static (pure scratch); (d)
   vlbe_bdf_advance, a loop of vlbe_bdf_step calls, each all or nothing:
   on failure the state is the last accepted step.  A failed vlbe_hht_step
   or vlbe_bdf_step leaves t, q, v, q'', a, lambda, mu, h, order and the
   method's history bit for bit as before the call.  Parameters are
   validated: every real finite, iteration counts in 1..VLBE_INT_MAX_ITER,
   max_halvings of HHT in 0..VLBE_HHT_MAX_HALVINGS (VLBE_EARG otherwise).
   No allocation: the caller
   gives a real and an int workspace whose sizes the *_work_len() and
   *_iwork_len() queries return.  Stack: about 1 kB per call (float on a
   Cortex-M4F, gcc -O2, make check-m4: vlbe_hht_step 1056 B,
   vlbe_hht_advance 1088 B, the rest at most 1 kB; the figure moves by a
   few words with gcc's inlining in the
   unit), whatever max_halvings, plus what the callbacks use; all arrays
   live in the caller's workspace.

API
   vlbe_status vlbe_dae_check(sys)                        validate a problem
   size_t vlbe_dae_work_len(n, m), vlbe_dae_iwork_len(n, m)   workspace of the next one
   size_t vlbe_*_work_len_sys(sys), vlbe_*_iwork_len_sys(sys)   the same for the problem's
                                                          storage (dae, static, hht, bdf)
   vlbe_status vlbe_dae_consistent_acc(sys,t,q,v,a,lam,st,w,lw,iw,liw)  q'', lambda at start
   size_t vlbe_dae_lin_work_len_sys(sys), vlbe_dae_lin_iwork_len_sys(sys)  linearisation workspace
   vlbe_status vlbe_dae_linearize(sys,t,q,v,a,lam,frame,nr,N,Mr,Dr,Kr,st,w,lw,iw,liw)
                                                          reduced M, D, K about a state
   vlbe_status vlbe_dae_project(sys,t,q,v,tol,st,w,lw,iw,liw)  (q, v) onto the constraints
                                                          (workspace: vlbe_dae_work_len_sys)
   void vlbe_dae_stats_add(a, b)                          a += b, counter by counter (restarts)
   void vlbe_static_params_default(p)                     static solver defaults
   size_t vlbe_static_work_len(n, m), vlbe_static_iwork_len(n, m)
   vlbe_status vlbe_dae_static(sys, par, t, q, lam, st, w, lw, iw, liw)  static equilibrium
   void vlbe_hht_params_newmark(p, beta, gamma)           classic Newmark
   vlbe_status vlbe_hht_params_alpha(p, alpha)            HHT-alpha, alpha in [-1/3, 0]
   vlbe_status vlbe_hht_params_genalpha(p, rho_inf)       generalized-alpha, rho_inf in [0, 1]
   size_t vlbe_hht_work_len(n, m), vlbe_hht_iwork_len(n, m)
   vlbe_status vlbe_hht_init(st, sys, par, t0, q0, v0, w, lw, iw, liw)
   vlbe_status vlbe_hht_step(st, h)                       one step (halving inside if enabled)
   vlbe_status vlbe_hht_advance(st, t_out, h_max)         equal steps <= h_max, ends on t_out exactly
   void vlbe_bdf_params_default(p)                        BDF defaults (rtol 1e-6, order <= 5)
   size_t vlbe_bdf_work_len(n, m), vlbe_bdf_iwork_len(n, m)
   vlbe_status vlbe_bdf_init(st, sys, par, t0, q0, v0, w, lw, iw, liw)  consistent start, order 1
   vlbe_status vlbe_bdf_step(st, t_stop)                  one accepted step, never past t_stop
   vlbe_status vlbe_bdf_advance(st, t_out)                steps until t == t_out exactly
   vlbe_status vlbe_bdf_interp(st, t, q, v)               dense output within the last step

REFERENCES
   M. Arnold, O. Bruls, Convergence of the generalized-alpha scheme for
   constrained mechanical systems, Multibody Syst. Dyn. 18 (2007) 185-202.
   J. Chung, G. Hulbert, J. Appl. Mech. 60 (1993) 371-375.
   H. Hilber, T. Hughes, R. Taylor, Earthq. Eng. Struct. Dyn. 5 (1977) 283-292.
   K.-M. Hsiao et al., co-rotational sliding beam (shared/papers/
   corotational-sliding-beam.txt): eq. 53, the residual test ||Psi||/sqrt(N)
   <= e_tol of vlbe_static_params.ftol and vlbe_hht_params.ftol.
   J. Dennis, R. Schnabel, Numerical Methods for Unconstrained Optimization
   and Nonlinear Equations, SIAM 1996, sec. 6.3 (backtracking on ||F||).
   C. W. Gear, B. Leimkuhler, G. K. Gupta, J. Comput. Appl. Math. 12 (1985).
   K. Brenan, S. Campbell, L. Petzold, Numerical Solution of Initial-Value
   Problems in DAEs (DASSL), SIAM 1996.
   L. Petzold, Differential/algebraic equations are not ODE's, SIAM J. Sci.
   Stat. Comput. 3 (1982) 367-384 (error estimates after step changes).
   L. F. Shampine, Implementation of implicit formulas for the solution of
   ODEs, SIAM J. Sci. Stat. Comput. 1 (1980) 103-118 (the filtered error
   estimate); E. Hairer, G. Wanner, Solving ODEs II, 2nd ed., Springer
   1996, sec. IV.8.
*/
#ifndef VLBE_INTEGRATORS_H
#define VLBE_INTEGRATORS_H
#include "vlbe.h"

#if !defined(VLBE_VERSION_MAJOR) || VLBE_VERSION_MAJOR != 0 || VLBE_VERSION_MINOR < 1
#error "integrators.h needs vlbe.h 0.1 or newer in the same directory"
#endif

/* -- constants ---------------------------------------------------------- */
/* Upper bounds of the iteration parameters (VLBE_EARG above them) */
#define VLBE_HHT_MAX_HALVINGS 30 /* vlbe_hht_params.max_halvings: steps down to h / 2^30 */
#define VLBE_INT_MAX_ITER 1000   /* newton_max of HHT and BDF, max_iter of vlbe_dae_static */
#define VLBE_DAE_PROJECT_ITER 20 /* Gauss-Newton iterations of vlbe_dae_project */

/* Default tolerances follow the arithmetic: each is its double value, or a
   multiple of the unit roundoff VLBE_EPS where that is larger (float).  An
   iterate or a local error is known to a few ulps of the largest
   coordinate at best, so a relative tolerance sits VLBE_RTOL_EPS units of
   roundoff above it (float: 7.6e-6) and an absolute one VLBE_ATOL_EPS
   (float: 9.5e-7, for coordinates of order one).  Double: the values of
   the defaults' comments, bit for bit. */
#define VLBE_RTOL_EPS 64
#define VLBE_ATOL_EPS 8
#define VLBE_TOL_DEFAULT(x, k) ((x) > (k) * VLBE_EPS ? (x) : (k) * VLBE_EPS)

/* -- types -------------------------------------------------------------- */

/* Counters of one run (cumulative from init). */
typedef struct vlbe_dae_stats {
    long steps;          /* accepted steps                                  */
    long rejected;       /* rejected steps (error test or Newton failure)   */
    long newton_iters;   /* Newton iterations                               */
    long newton_fails;   /* Newton failures                                 */
    long force_calls;    /* calls of force                                  */
    long mass_calls;     /* calls of mass                                   */
    long constr_calls;   /* calls of constr, constr_jac, constr_acc         */
    long jac_evals;      /* iteration-matrix (Jacobian) evaluations         */
    long lu_factors;     /* LU factorizations                               */
    long lu_solves;      /* LU solves (one per right-hand side set)         */
    int callback_rc;     /* value returned by the last failing callback     */
} vlbe_dae_stats;

/* A uniformly rotating frame for vlbe_dae_linearize: its angular velocity
   and the coordinates that turn with it (see the linearisation section). */
typedef struct vlbe_lin_frame {
    vlbe_real omega[3]; /* angular velocity of the frame [rad/s] (planar: omega[2]) */
    int dim;            /* 2 (planar vectors, rotation about z) or 3                */
    int nvec;           /* number of vectors of q that turn with the frame          */
    const int *vec;     /* vec[k]: index in q of the first component of vector k
                           (positions, slopes, directions); the other coordinates
                           (angles, material coordinates) are scalars              */
} vlbe_lin_frame;

/* Generalized-alpha family parameters (Arnold-Bruls form):
   (1-alpha_m) a_{n+1} + alpha_m a_n = (1-alpha_f) q''_{n+1} + alpha_f q''_n. */
typedef struct vlbe_hht_params {
    vlbe_real alpha_m, alpha_f, beta, gamma;
    vlbe_real rtol, atol;   /* Newton: estimated error of the position and velocity
                               increments <= atol + rtol |x| (default 1e-9, 1e-11;
                               float 7.6e-6, 9.5e-7: VLBE_TOL_DEFAULT) */
    int newton_max;         /* iterations per attempt, 1..VLBE_INT_MAX_ITER (default 10) */
    int modified;           /* 1: keep the LU while the iteration contracts, 0: full
                               Newton (default 1)                                       */
    int max_halvings;       /* step halvings on Newton failure, 0..VLBE_HHT_MAX_HALVINGS
                               (default 0 = off)                                        */
    int reuse_max;          /* modified Newton: a kept matrix that the observed rate
                               says will not converge within this many further
                               iterations is refreshed at once, 0..VLBE_INT_MAX_ITER;
                               0 (default): the iterations left of newton_max, i.e.
                               kept as long as the budget allows (right where an LU
                               costs O(n^3)).  Banded chains, whose Jacobian and
                               band LU cost about three residual evaluations, run
                               faster with 2 (bench/bench_scale.c).  The storage
                               never changes the iterates: dense and banded runs
                               of one problem agree to rounding                  */
    vlbe_real ftol;         /* residual test (default 0 = off): when > 0 an iterate is
                               converged only if, besides the increment test, the
                               weighted Euclidean norm of the residual
                               Psi = (M q'' + C_q^T lambda - Q, C) at it satisfies
                               ||Psi||_2 / sqrt(n + m) <= ftol (Hsiao et al. eq. 53;
                               absolute, in the units of Q, C unscaled); costs one
                               more residual evaluation (mass, force, constraints)
                               per step, at the accepted iterate, and a fresh
                               iteration matrix when the test fails on a stale one.
                               Set it above the rounding of Psi (eps |Q|, eps |M q''|)
                               or steps fail with VLBE_ENOCONV.  0: the iteration is
                               bit-for-bit that without the field                  */
    int project;            /* 1: vlbe_hht_init starts from (q0, v0) moved onto
                               C = 0 and C_q v + C_t = 0 by vlbe_dae_project (a
                               start on them is left bit for bit); 0 (default):
                               as given.  An index-3 step closes a gap in C
                               within one step, through q'' ~ C/h^2, and a
                               velocity off C_q v + C_t = 0 is never corrected:
                               both stay in the run as a spurious oscillation
                               of lambda and q''.  Off by default because runs
                               that start off C_q v + C_t = 0 on purpose would
                               change: the sliding scenes start at rest under
                               a prescribed material flow (tests/
                               test_scenes_sliding.c, test_sliding_xcheck.c,
                               test_scenes_band.c: residuals 2e-8 .. 3e-2)   */
} vlbe_hht_params;

/* Static equilibrium (vlbe_dae_static).  Converged when every enabled test
   holds at the iterate: the increment test (enabled when rtol + atol > 0) on
   the last full Newton step dq (taken without backtracking),
       |dq_i| <= atol + rtol |q_i|  for every i,   or  max|dq| <= 8 eps max|q|
   (the rounding floor: in float the default rtol is below eps), and the
   residual test (enabled when ftol > 0), eq. 53 of Hsiao et al.,
       ||Psi||_2 / sqrt(n + m) <= ftol,   Psi = (C_q^T lambda - Q, C).
   The multipliers are not in the increment test: they come out of the same
   linear solve as dq and converge with it. */
typedef struct vlbe_static_params {
    vlbe_real ftol;    /* residual test, absolute, in the units of Q and C
                          (C enters unscaled); 0 = off (default 0)                */
    vlbe_real rtol, atol; /* increment test (default 1e-10, 1e-12; float 7.6e-6,
                             9.5e-7); both 0 = off                           */
    int max_iter;      /* Newton iterations, 1..VLBE_INT_MAX_ITER (default 50)     */
    int max_halvings;  /* line search: halvings of a Newton step, 0..50 (default 5);
                          0 = plain Newton, the full step is always taken         */
    int watchdog;      /* full Newton steps first: the iteration returns to the
                          start, and backtracks from there, once this many
                          iterations in a row brought neither a merit nor a
                          step below every one before, 0..VLBE_INT_MAX_ITER
                          (default 4); 0 = backtracking from the first
                          iteration on; without effect when max_halvings = 0 */
} vlbe_static_params;

/* Integrator state.  q, v, qdd (= q''), a (algorithmic acceleration), lambda
   point into the caller's workspace and hold the last accepted step. */
typedef struct vlbe_hht {
    const vlbe_dae *sys;
    vlbe_hht_params par;
    int n, m;
    vlbe_real t;
    vlbe_real *q, *v, *qdd, *a, *lambda;
    vlbe_dae_stats stats;
    /* private */
    vlbe_real *w_;     /* rest of the real workspace */
    int *piv_;
    vlbe_real h_lu_;   /* step size of the stored LU (0 = none) */
    int have_lu_;
    int have_m_;       /* VLBE_DAE_MASS_CONST: M is in the workspace */
    /* time without drift: t = t_base_ + k_run_ h_run_ over a run of equal steps */
    vlbe_real t_base_, h_run_;
    long k_run_;
} vlbe_hht;

/* BDF (orders 1..5, variable step and order, DASSL-style) on the stabilized
   index-2 form of Gear, Gupta and Leimkuhler (GGL):
       q' = v - C_q^T mu,   M v' + C_q^T lambda = Q,   C_q v + C_t = 0,   C = 0,
   unknowns y = (q, v, lambda, mu), 2n + 2m.  The start is moved onto C = 0
   and C_q v + C_t = 0 by vlbe_dae_project when q0, v0 miss them by more
   than the first step can absorb (vlbe_bdf_params.project); lambda0 and
   q''0 come from vlbe_dae_consistent_acc, mu0 = 0.  The first step is
   taken at order 1. */
#define VLBE_BDF_MAXORD 5

typedef struct vlbe_bdf_params {
    vlbe_real rtol, atol; /* local error per step on q and v (lambda, mu excluded):
                             weighted RMS with weights atol + rtol |y_i| <= 1
                             (default 1e-6, 1e-8; float 7.6e-6, 9.5e-7)           */
    vlbe_real h0;         /* first step; 0: estimated from |y'(t0)| (default 0)    */
    vlbe_real h_min;      /* smallest step; 0: 4 eps |t| (default 0)               */
    vlbe_real h_max;      /* largest step; 0: unbounded (default 0)                */
    int max_order;        /* highest order, 1..5 (default 5; 2 keeps A-stability).
                             BDF3..5 are unstable on a band of the imaginary axis
                             (test_bdf.c): an undamped stiff mode (the axial modes
                             of a beam, a stiff spring) in that band grows until
                             the error test holds h near the band's edge (BDF5:
                             w h < 0.71), whatever the tolerance.  Whether that
                             costs depends on the step the accuracy needs
                             (bench/wp_bdf_order.c, -O2, docs/benchmarks.md):
                             on a flexible slider crank (one turn of the crank
                             at 150 rad/s, 0.042 s) 5 is the cheapest and
                             most accurate from rtol 1e-5 on (0.34 s, 28061
                             steps, error 1.3e-7 against 0.44 s, 43872 steps,
                             6.0e-5 at order 2; at 1e-7 0.50 s, 7.2e-9 against
                             2.4 s, 2.4e-6) and 14 times more accurate at 1e-3
                             (1.2e-5 in 0.36 s against 1.8e-4 in 0.053 s): its
                             fast motion needs short steps anyway.  On the
                             scenes/ex_spin.h ANCF beam (10 s of spin-up, axial
                             modes up to 3.7e4 rad/s), whose slow motion allows
                             steps of 1e-2 s, order 2 takes 534 to 3388 steps
                             (0.11 to 0.63 s) at rtol 1e-3 to 1e-5 while 4 and 5
                             did not reach 10 s in 60000 steps at any of them.
                             3 and 4 were the worst on both (the slider crank at
                             rtol 1e-3: errors 1.9 and 0.11 of the rod's length,
                             no failure reported).  So: 2 when the motion allows
                             steps far beyond 0.7 / w of the stiffest undamped
                             mode, 5 when the accuracy asked needs steps of that
                             size anyway                                         */
    int newton_max;       /* Newton iterations per attempt, 1..VLBE_INT_MAX_ITER
                             (default 4, as DASSL)                                 */
    int fixed_step;       /* 1: every step is h0 (h_min, h_max, rtol/atol for the
                             error test unused), order 1, 2, ... up to max_order;
                             for stability studies (default 0)                     */
    int stiff_filter;     /* 1: the error estimate is filtered through the
                             iteration matrix (Shampine's (I - J/cj)^-1), which
                             discounts stiff modes the step does not resolve
                             (see vlbe__bdf_enorm); 0: the plain estimate of
                             DASSL (default 1)                                     */
    int max_steps;        /* steps one vlbe_bdf_advance call may take; 0: no limit
                             (default 0).  A cap turns a run whose steps collapse
                             without reaching h_min (a wrong model, a tolerance
                             below what the arithmetic resolves) into
                             VLBE_EBOUND instead of a hang                         */
    int project;          /* 1 (default): vlbe_bdf_init starts from a copy of
                             (q0, v0) projected by vlbe_dae_project when the
                             correction exceeds what the first step absorbs
                             (see vlbe_bdf_init); 0: (q0, v0) as given.  A start
                             off the constraints by more than the error test
                             allows fails otherwise: the corrector puts the
                             whole violation into the first step's error
                             estimate, whatever h, and the step shrinks to
                             VLBE_ESTEP                                           */
    const vlbe_real *atolv; /* NULL (default): atol for every coordinate; else
                             2n absolute tolerances, q then v, the weights
                             atolv[i] + rtol |y_i| of the error test and of
                             the Newton test of q and v (lambda and mu keep
                             atol).  For coordinates of different sizes
                             (positions of 1 m beside modal amplitudes of
                             1e-5): with one atol above rtol times a small
                             coordinate, that coordinate is only controlled
                             absolutely.  Each >= 0 and finite with atolv[i]
                             + rtol > 0.  The state keeps the pointer: the
                             array must live as long as the state          */
} vlbe_bdf_params;

/* BDF integrator state.  q, v, lambda, mu point into the caller's workspace
   (contiguous, in this order) and hold the last accepted step at time t. */
typedef struct vlbe_bdf {
    const vlbe_dae *sys;
    vlbe_bdf_params par;
    int n, m;
    vlbe_real t;        /* time of the last accepted step                  */
    vlbe_real h;        /* step size the next step will try                */
    vlbe_real h_last;   /* size of the last accepted step (0 before any)   */
    int order;          /* order the next step will use                    */
    int order_last;     /* order of the last accepted step (0 before any)  */
    vlbe_real *q, *v, *lambda, *mu;
    vlbe_dae_stats stats;
    /* private: modified divided differences phi_1..phi_{k+1} (phi_j at
       phi_ + (j-1)(2n+2m)) and the coefficients of Brenan-Campbell-Petzold
       sec. 5.2 (1-based, index 0 unused) */
    vlbe_real *phi_, *w_;
    int *piv_;
    vlbe_real psi_[VLBE_BDF_MAXORD + 2], alpha_[VLBE_BDF_MAXORD + 2],
        beta_[VLBE_BDF_MAXORD + 2], gamma_[VLBE_BDF_MAXORD + 2], sigma_[VLBE_BDF_MAXORD + 2];
    vlbe_real hold_;    /* step size of the last accepted step             */
    vlbe_real cj_;      /* leading coefficient alpha_s/h of the last attempt */
    vlbe_real cj_lu_;   /* cj of the stored iteration matrix               */
    vlbe_real rate_;    /* last Newton rate estimate s (diagnostic only)   */
    int kold_, ns_, phase_, jcalc_; /* jcalc_: -1 matrix needed, 0 fresh, 1 old */
    int have_m_;        /* VLBE_DAE_MASS_CONST: M is in the workspace       */
    vlbe_real t_base_;  /* fixed_step: t = t_base_ + k_run_ h0 (no drift)     */
    long k_run_;
} vlbe_bdf;

/* -- API prototypes ----------------------------------------------------- */
VLBE_API vlbe_status vlbe_dae_check(const vlbe_dae *sys);
VLBE_API size_t vlbe_dae_work_len(int n, int m);
VLBE_API size_t vlbe_dae_iwork_len(int n, int m);
VLBE_API size_t vlbe_dae_work_len_sys(const vlbe_dae *sys);
VLBE_API size_t vlbe_dae_iwork_len_sys(const vlbe_dae *sys);
VLBE_API void vlbe_dae_stats_add(vlbe_dae_stats *a, const vlbe_dae_stats *b);
VLBE_API vlbe_status vlbe_dae_consistent_acc(const vlbe_dae *sys, vlbe_real t, const vlbe_real *q,
                                             const vlbe_real *v, vlbe_real *qdd,
                                             vlbe_real *lambda, vlbe_dae_stats *stats,
                                             vlbe_real *work, size_t work_len, int *iwork,
                                             size_t iwork_len);
VLBE_API size_t vlbe_dae_lin_work_len_sys(const vlbe_dae *sys);
VLBE_API size_t vlbe_dae_lin_iwork_len_sys(const vlbe_dae *sys);
VLBE_API vlbe_status vlbe_dae_linearize(const vlbe_dae *sys, vlbe_real t, const vlbe_real *q,
                                        const vlbe_real *v, const vlbe_real *a,
                                        const vlbe_real *lambda, const vlbe_lin_frame *frame,
                                        int *nr, vlbe_real *N, vlbe_real *Mr, vlbe_real *Dr,
                                        vlbe_real *Kr, vlbe_dae_stats *stats, vlbe_real *work,
                                        size_t work_len, int *iwork, size_t iwork_len);
VLBE_API vlbe_status vlbe_dae_project(const vlbe_dae *sys, vlbe_real t, vlbe_real *q, vlbe_real *v,
                                      vlbe_real tol, vlbe_dae_stats *stats, vlbe_real *work,
                                      size_t work_len, int *iwork, size_t iwork_len);

VLBE_API void vlbe_static_params_default(vlbe_static_params *p);
VLBE_API size_t vlbe_static_work_len(int n, int m);
VLBE_API size_t vlbe_static_iwork_len(int n, int m);
VLBE_API size_t vlbe_static_work_len_sys(const vlbe_dae *sys);
VLBE_API size_t vlbe_static_iwork_len_sys(const vlbe_dae *sys);
VLBE_API vlbe_status vlbe_dae_static(const vlbe_dae *sys, const vlbe_static_params *par,
                                     vlbe_real t, vlbe_real *q, vlbe_real *lambda,
                                     vlbe_dae_stats *stats, vlbe_real *work, size_t work_len,
                                     int *iwork, size_t iwork_len);

VLBE_API void vlbe_hht_params_newmark(vlbe_hht_params *p, vlbe_real beta, vlbe_real gamma);
VLBE_API vlbe_status vlbe_hht_params_alpha(vlbe_hht_params *p, vlbe_real alpha);
VLBE_API vlbe_status vlbe_hht_params_genalpha(vlbe_hht_params *p, vlbe_real rho_inf);
VLBE_API size_t vlbe_hht_work_len(int n, int m);
VLBE_API size_t vlbe_hht_iwork_len(int n, int m);
VLBE_API size_t vlbe_hht_work_len_sys(const vlbe_dae *sys);
VLBE_API size_t vlbe_hht_iwork_len_sys(const vlbe_dae *sys);
VLBE_API vlbe_status vlbe_hht_init(vlbe_hht *st, const vlbe_dae *sys, const vlbe_hht_params *par,
                                   vlbe_real t0, const vlbe_real *q0, const vlbe_real *v0,
                                   vlbe_real *work, size_t work_len, int *iwork,
                                   size_t iwork_len);
VLBE_API vlbe_status vlbe_hht_step(vlbe_hht *st, vlbe_real h);
VLBE_API vlbe_status vlbe_hht_advance(vlbe_hht *st, vlbe_real t_out, vlbe_real h_max);

VLBE_API void vlbe_bdf_params_default(vlbe_bdf_params *p);
VLBE_API size_t vlbe_bdf_work_len(int n, int m);
VLBE_API size_t vlbe_bdf_iwork_len(int n, int m);
VLBE_API size_t vlbe_bdf_work_len_sys(const vlbe_dae *sys);
VLBE_API size_t vlbe_bdf_iwork_len_sys(const vlbe_dae *sys);
VLBE_API vlbe_status vlbe_bdf_init(vlbe_bdf *st, const vlbe_dae *sys, const vlbe_bdf_params *par,
                                   vlbe_real t0, const vlbe_real *q0, const vlbe_real *v0,
                                   vlbe_real *work, size_t work_len, int *iwork,
                                   size_t iwork_len);
VLBE_API vlbe_status vlbe_bdf_step(vlbe_bdf *st, vlbe_real t_stop);
VLBE_API vlbe_status vlbe_bdf_advance(vlbe_bdf *st, vlbe_real t_out);
VLBE_API vlbe_status vlbe_bdf_interp(const vlbe_bdf *st, vlbe_real t, vlbe_real *q, vlbe_real *v);

/* ===== implementation =================================================== */

/* -- counted callback wrappers ------------------------------------------ */
VLBE_INLINE void vlbe__dae_stats_zero(vlbe_dae_stats *c)
{
    c->steps = c->rejected = c->newton_iters = c->newton_fails = 0;
    c->force_calls = c->mass_calls = c->constr_calls = 0;
    c->jac_evals = c->lu_factors = c->lu_solves = 0;
    c->callback_rc = 0;
}
/* A callback's return value as a status; a failure is remembered in
   c->callback_rc (positive: the point is outside the model's domain, the
   step may be retried smaller). */
VLBE_INLINE vlbe_status vlbe__dae_cb(vlbe_dae_stats *c, int rc)
{
    if (rc == 0) return VLBE_OK;
    c->callback_rc = rc;
    return VLBE_ECALLBACK;
}
/* a failed attempt that a smaller step may cure: Newton trouble, or a
   callback that called the iterate outside its domain (return value > 0) */
VLBE_INLINE int vlbe__dae_retry(const vlbe_dae_stats *c, vlbe_status rc)
{
    return rc != VLBE_EARG && (rc != VLBE_ECALLBACK || c->callback_rc > 0);
}
VLBE_INLINE vlbe_status vlbe__dae_mass(const vlbe_dae *s, vlbe_dae_stats *c, vlbe_real t,
                                       const vlbe_real *q, const vlbe_real *v, vlbe_real *M)
{
    ++c->mass_calls;
    return vlbe__dae_cb(c, s->mass(s->user, t, q, v, M));
}
VLBE_INLINE vlbe_status vlbe__dae_force(const vlbe_dae *s, vlbe_dae_stats *c, vlbe_real t,
                                        const vlbe_real *q, const vlbe_real *v, vlbe_real *Q)
{
    ++c->force_calls;
    return vlbe__dae_cb(c, s->force(s->user, t, q, v, Q));
}
VLBE_INLINE vlbe_status vlbe__dae_constr(const vlbe_dae *s, vlbe_dae_stats *c, vlbe_real t,
                                         const vlbe_real *q, vlbe_real *C)
{
    if (s->m == 0) return VLBE_OK;
    ++c->constr_calls;
    return vlbe__dae_cb(c, s->constr(s->user, t, q, C));
}
VLBE_INLINE vlbe_status vlbe__dae_cjac(const vlbe_dae *s, vlbe_dae_stats *c, vlbe_real t,
                                       const vlbe_real *q, vlbe_real *Cq, vlbe_real *Ct)
{
    if (s->m == 0) return VLBE_OK;
    ++c->constr_calls;
    return vlbe__dae_cb(c, s->constr_jac(s->user, t, q, Cq, Ct));
}

/* Forward-difference increment for coordinate x. */
VLBE_INLINE vlbe_real vlbe__dae_fd_step(vlbe_real x)
{
    vlbe_real ax = vlbe_fabs(x);
    return vlbe_sqrt(VLBE_EPS) * (ax > VLBE_R(1.0) ? ax : VLBE_R(1.0));
}

/* -- storage of the matrices -------------------------------------------- */
/* Dense problems: model matrices n x n (M, K, D, Mq, Mv, H) and m x n
   (C_q), iteration matrices N x N.  Banded problems (vlbe_dae.storage):
   every model matrix is an NA x NA band, NA = n + m, in the augmented order
   (ld = kl + ku + 1); an iteration matrix whose unknowns come in f blocks
   -- f = 1: (q, lambda) of HHT, the static solver and the start; f = 2:
   (q, v, lambda, mu) of BDF -- is an (f NA) band in which unknown u of
   block b sits at f order[u] + b, half-bandwidths f kl + f - 1 and
   f ku + f - 1, stored with the kl extra super-diagonals of the banded LU.
   inv[] (NA ints, from vlbe__dae_inv) maps an augmented position back to
   its unknown (< n: q_i, else lambda_{i-n}). */
VLBE_INLINE int vlbe__dae_banded(const vlbe_dae *s) { return s->storage == VLBE_DAE_BANDED; }
VLBE_INLINE int vlbe__dae_bld(const vlbe_dae *s) { return s->kl + s->ku + 1; }
/* reals of one model matrix: n x n (cq = 0) or m x n (cq = 1), or a band */
VLBE_INLINE size_t vlbe__dae_mlen(const vlbe_dae *s, int cq)
{
    if (vlbe__dae_banded(s)) return ((size_t)s->n + (size_t)s->m) * (size_t)vlbe__dae_bld(s);
    return (size_t)(cq ? s->m : s->n) * (size_t)s->n;
}
/* half-bandwidths of an iteration matrix of f blocks */
VLBE_INLINE int vlbe__dae_fkl(const vlbe_dae *s, int f) { return f * s->kl + f - 1; }
VLBE_INLINE int vlbe__dae_fku(const vlbe_dae *s, int f) { return f * s->ku + f - 1; }
/* reals of an iteration matrix of f blocks (N = f (n + m)) and its LU */
VLBE_INLINE size_t vlbe__dae_alen(const vlbe_dae *s, int f)
{
    size_t N = (size_t)f * ((size_t)s->n + (size_t)s->m);
    if (vlbe__dae_banded(s))
        return N * vlbe_band_lu_ld(vlbe__dae_fkl(s, f), vlbe__dae_fku(s, f));
    return N * N;
}
/* leading dimension of that matrix */
VLBE_INLINE size_t vlbe__dae_ald(const vlbe_dae *s, int f)
{
    if (vlbe__dae_banded(s)) return vlbe_band_lu_ld(vlbe__dae_fkl(s, f), vlbe__dae_fku(s, f));
    return (size_t)f * ((size_t)s->n + (size_t)s->m);
}
/* ints after the pivots: inv[] of a banded problem */
VLBE_INLINE size_t vlbe__dae_ilen(const vlbe_dae *s)
{
    return vlbe__dae_banded(s) ? (size_t)s->n + (size_t)s->m : 0;
}

/* inv[] from sys->order; VLBE_EARG when order is not a permutation of
   0..n+m-1 (inv is then scratch). */
VLBE_INLINE vlbe_status vlbe__dae_inv(const vlbe_dae *s, int *inv)
{
    int NA = s->n + s->m, u;
    for (u = 0; u < NA; ++u) inv[u] = -1;
    for (u = 0; u < NA; ++u) {
        int p = s->order[u];
        if (p < 0 || p >= NA || inv[p] != -1) return VLBE_EARG;
        inv[p] = u;
    }
    return VLBE_OK;
}

/* X (f NA, the iteration matrix's order) <-> x (natural: f blocks of n,
   then f blocks of m): unknown u of block b at X[f order[u] + b]. */
VLBE_INLINE void vlbe__dae_perm(const vlbe_dae *s, int f, const vlbe_real *x, vlbe_real *X)
{
    int n = s->n, m = s->m, i, b;
    for (b = 0; b < f; ++b) {
        for (i = 0; i < n; ++i) X[f * s->order[i] + b] = x[b * n + i];
        for (i = 0; i < m; ++i) X[f * s->order[n + i] + b] = x[f * n + b * m + i];
    }
}
VLBE_INLINE void vlbe__dae_unperm(const vlbe_dae *s, int f, const vlbe_real *X, vlbe_real *x)
{
    int n = s->n, m = s->m, i, b;
    for (b = 0; b < f; ++b) {
        for (i = 0; i < n; ++i) x[b * n + i] = X[f * s->order[i] + b];
        for (i = 0; i < m; ++i) x[f * n + b * m + i] = X[f * s->order[n + i] + b];
    }
}

/* Products with a model matrix (banded: through augmented vectors, w: 2 NA
   reals of scratch; dense: vlbe_mat_vec, vlbe_mat_tvec):
     kind 0: y (n) = A x (n)          (M, or any n x n matrix)
     kind 1: y (m) = C_q x (n)
     kind 2: y (n) = C_q^T x (m)                                        */
VLBE_INLINE void vlbe__dae_bprod(const vlbe_dae *s, int kind, const vlbe_real *A,
                                 const vlbe_real *x, vlbe_real *y, vlbe_real *w)
{
    int n = s->n, m = s->m, NA = n + m, i;
    vlbe_real *X = w, *Y = w + NA;
    const int *o = s->order;
    if (!vlbe__dae_banded(s)) {
        if (kind == 0) vlbe_mat_vec(n, n, A, x, y);
        else if (kind == 1) vlbe_mat_vec(m, n, A, x, y);
        else vlbe_mat_tvec(m, n, A, x, y);
        return;
    }
    vlbe_vec_zero(NA, X);
    if (kind == 2)
        for (i = 0; i < m; ++i) X[o[n + i]] = x[i];
    else
        for (i = 0; i < n; ++i) X[o[i]] = x[i];
    if (kind == 2) vlbe_band_mat_tvec(NA, s->kl, s->ku, A, vlbe__dae_bld(s), X, Y);
    else vlbe_band_mat_vec(NA, s->kl, s->ku, A, vlbe__dae_bld(s), X, Y);
    if (kind == 1)
        for (i = 0; i < m; ++i) y[i] = Y[o[n + i]];
    else
        for (i = 0; i < n; ++i) y[i] = Y[o[i]];
}

/* A block of an iteration matrix that Jacobian terms are added to, in the
   coordinates of the model's matrices: rows and columns 0..n-1 are q,
   rows n..n+m-1 the constraints.  Dense (f = 0): A points at the block,
   model entry (r, c) at A[(r + ro) ld + c] (ro shifts constraint rows to
   the block's first row).  Banded: A is the whole band (leading dimension
   ld, kl sub-diagonals), model entry at augmented (r, c) lands at
   (f r + ro, f c + co). */
typedef struct vlbe__dae_blk {
    vlbe_real *A;
    size_t ld;
    int kl, f, ro, co;
} vlbe__dae_blk;
/* a dense block at A with leading dimension ld (constraint rows shifted by ro) */
VLBE_INLINE vlbe__dae_blk vlbe__dae_dblk(vlbe_real *A, int ld, int ro)
{
    vlbe__dae_blk b;
    b.A = A;
    b.ld = (size_t)ld;
    b.kl = b.f = b.co = 0;
    b.ro = ro;
    return b;
}
VLBE_INLINE vlbe_real *vlbe__dae_blk_at(const vlbe__dae_blk *b, int r, int c)
{
    if (b->f == 0) return b->A + (size_t)(r + b->ro) * b->ld + (size_t)c;
    return b->A + VLBE_BAND_IDX(b->ld, b->kl, b->f * r + b->ro, b->f * c + b->co);
}
/* Adds c X to block b, X a model matrix: kind 0 an n x n one (M, K, D,
   Mq, Mv, H), 1 C_q, 2 C_q^T (dense: C_q's m x n array; banded: the band,
   C_q^T read transposed). */
VLBE_INLINE void vlbe__dae_badd(const vlbe_dae *s, const vlbe__dae_blk *b, vlbe_real c,
                                const vlbe_real *X, int kind)
{
    int n = s->n, NA = n + s->m, kl = s->kl, ld = vlbe__dae_bld(s), r, o;
    if (!vlbe__dae_banded(s)) {
        int i, j, rows = kind == 0 ? n : s->m;
        for (i = 0; i < rows; ++i)
            for (j = 0; j < n; ++j) {
                vlbe_real x = c * X[(size_t)i * (size_t)n + (size_t)j];
                if (kind == 0) *vlbe__dae_blk_at(b, i, j) += x;
                else if (kind == 1) *vlbe__dae_blk_at(b, n + i, j) += x;
                else *vlbe__dae_blk_at(b, j, n + i) += x;
            }
        return;
    }
    for (r = 0; r < NA; ++r) {
        const vlbe_real *xr = X + (size_t)r * (size_t)ld;
        int o0 = kl - r > 0 ? kl - r : 0, o1 = NA - 1 - r + kl;
        if (o1 > ld - 1) o1 = ld - 1;
        for (o = o0; o <= o1; ++o) {
            int col = r - kl + o;
            if (xr[o] == VLBE_R(0.0)) continue;
            if (kind == 2) *vlbe__dae_blk_at(b, col, r) += c * xr[o];
            else *vlbe__dae_blk_at(b, r, col) += c * xr[o];
        }
    }
}
/* The whole band A of an iteration matrix of f blocks, as a block. */
VLBE_INLINE vlbe__dae_blk vlbe__dae_band_blk(const vlbe_dae *s, vlbe_real *A, int f)
{
    vlbe__dae_blk b;
    b.A = A;
    b.ld = vlbe__dae_ald(s, f);
    b.kl = vlbe__dae_fkl(s, f);
    b.f = f;
    b.ro = b.co = 0;
    return b;
}
/* Adds c C_q and c C_q^T to the (q, lambda) band B (m > 0). */
VLBE_INLINE void vlbe__dae_bsaddle(const vlbe_dae *s, const vlbe__dae_blk *B, vlbe_real c,
                                   const vlbe_real *Cq)
{
    if (s->m == 0) return;
    vlbe__dae_badd(s, B, c, Cq, 1);
    vlbe__dae_badd(s, B, c, Cq, 2);
}
/* Adds c to the diagonal of the block (u, u), u < n (BDF's identity blocks). */
VLBE_INLINE void vlbe__dae_bdiag(const vlbe_dae *s, const vlbe__dae_blk *b, vlbe_real c)
{
    int i;
    for (i = 0; i < s->n; ++i) *vlbe__dae_blk_at(b, s->order[i], s->order[i]) += c;
}

/* The rows of column c (augmented order; dense: the natural one) that a
   Jacobian may fill: [c - ku, c + kl] within 0..NA-1 (dense: all). */
VLBE_INLINE void vlbe__dae_rows(const vlbe_dae *s, int c, int *r0, int *r1)
{
    int NA = s->n + s->m;
    if (!vlbe__dae_banded(s)) {
        *r0 = 0;
        *r1 = NA - 1;
        return;
    }
    *r0 = c - s->ku < 0 ? 0 : c - s->ku;
    *r1 = c + s->kl > NA - 1 ? NA - 1 : c + s->kl;
}
/* the unknown at augmented position r (dense, inv NULL: r itself) */
VLBE_INLINE int vlbe__dae_unk(const int *inv, int r) { return inv ? inv[r] : r; }
/* columns one forward difference serves (vlbe__dae_group): every
   kl + ku + 1-th of a band, one of a dense matrix */
VLBE_INLINE int vlbe__dae_gstride(const vlbe_dae *s)
{
    return vlbe__dae_banded(s) ? vlbe__dae_bld(s) : s->n + s->m;
}

/* Forward-difference steps of the coordinates of group g (Curtis, Powell,
   Reid: columns kl + ku + 1 apart in the augmented order have disjoint
   rows, so one evaluation serves them all; dense: column g alone):
   x[j] = base[j] + d[j] for the q_j of the group (others base[j]);
   returns 0 if the group is empty.  d receives the exactly representable
   steps. */
VLBE_INLINE int vlbe__dae_group(const vlbe_dae *s, const int *inv, int g, const vlbe_real *base,
                                vlbe_real *x, vlbe_real *d)
{
    int n = s->n, NA = n + s->m, w = vlbe__dae_gstride(s), c, any = 0;
    vlbe_vec_copy(n, base, x);
    for (c = g; c < NA; c += w) {
        int j = vlbe__dae_unk(inv, c);
        if (j >= n) continue;
        x[j] = base[j] + vlbe__dae_fd_step(base[j]);
        d[j] = x[j] - base[j];
        any = 1;
    }
    return any;
}

/* gamma = -( (C_q v)_q v + 2 C_qt v + C_tt ) (m).  From the callback if given,
   else as minus the central difference of g(e) = C_q(t+e, q+e v) v + C_t(t+e, q+e v)
   at e = 0 (g'(0) = (C_q v)_q v + 2 C_qt v + C_tt), step eps^(1/3) scaled.
   w: vlbe__dae_gamma_len(s) reals. */
VLBE_INLINE size_t vlbe__dae_gamma_len(const vlbe_dae *s)
{
    size_t r = vlbe__dae_mlen(s, 1) + 2 * (size_t)s->m + (size_t)s->n;
    return vlbe__dae_banded(s) ? r + (size_t)s->m + 2 * ((size_t)s->n + (size_t)s->m) : r;
}
VLBE_INLINE vlbe_status vlbe__dae_gamma(const vlbe_dae *s, vlbe_dae_stats *c, vlbe_real t,
                                        const vlbe_real *q, const vlbe_real *v, vlbe_real *g,
                                        vlbe_real *w)
{
    int n = s->n, m = s->m, i, k;
    vlbe_real *Cq = w, *Ct = w + vlbe__dae_mlen(s, 1), *gp = Ct + m, *qe = gp + m;
    vlbe_real scale = vlbe_fabs(t), e;
    vlbe_status rc;
    if (m == 0) return VLBE_OK;
    if (s->constr_acc) {
        ++c->constr_calls;
        return vlbe__dae_cb(c, s->constr_acc(s->user, t, q, v, g));
    }
    for (i = 0; i < n; ++i) {
        vlbe_real r = vlbe_fabs(q[i]);
        if (r > scale) scale = r;
    }
    if (scale < VLBE_R(1.0)) scale = VLBE_R(1.0);
    e = vlbe_pow(VLBE_EPS, VLBE_R(1.0) / VLBE_R(3.0)) * scale /
        (VLBE_R(1.0) + vlbe_vec_norm_inf(n, v));
    for (k = 0; k < 2; ++k) {
        vlbe_real sg = k == 0 ? e : -e;
        for (i = 0; i < n; ++i) qe[i] = q[i] + sg * v[i];
        if ((rc = vlbe__dae_cjac(s, c, t + sg, qe, Cq, Ct)) != VLBE_OK) return rc;
        if (vlbe__dae_banded(s)) { /* C_q v into Ct (+= below) */
            vlbe_real *cv = qe + n;
            vlbe__dae_bprod(s, 1, Cq, v, cv, cv + m);
            for (i = 0; i < m; ++i) Ct[i] += cv[i];
        }
        for (i = 0; i < m; ++i) {
            vlbe_real gi = vlbe__dae_banded(s) ? Ct[i] : vlbe_vec_dot(n, Cq + (size_t)i * n, v) + Ct[i];
            if (k == 0) gp[i] = gi;
            else g[i] = -(gp[i] - gi) / (VLBE_R(2.0) * e);
        }
    }
    return VLBE_OK;
}

/* Row j of the constraint quantities used by the Jacobian helpers below:
   f = [C_q^T u_0; ...; C_q^T u_{nu-1}; C_q v + C_t] (the last block only if v). */
VLBE_INLINE void vlbe__dae_constr_vals(int n, int m, const vlbe_real *Cq, const vlbe_real *Ct,
                                       int nu, const vlbe_real *const *u, const vlbe_real *v,
                                       vlbe_real *f)
{
    int k, i;
    for (k = 0; k < nu; ++k) vlbe_mat_tvec(m, n, Cq, u[k], f + (size_t)k * n);
    if (v)
        for (i = 0; i < m; ++i)
            f[(size_t)nu * n + i] = vlbe_vec_dot(n, Cq + (size_t)i * n, v) + Ct[i];
}

/* The Jacobian terms of the iteration matrices, for both storages.
   vlbe__dae_bconstr_q adds the q-derivatives of constraint terms (m > 0):
     cl d(C_q^T lam)/dq   to block Jl   if lam != NULL,
     cu d(C_q^T mu)/dq    to block Ju   if mu != NULL,
     d(C_q v + C_t)/dq    to block Jg   if Jg != NULL (rows n..n+m-1),
   the first two from constr_hess when given, the rest by forward
   differences in q with one constr_jac call per column group shared by all
   terms (plus one at q); VLBE_DAE_NO_CHESS drops the first two.
   vlbe__dae_btangent adds cq d(M a + C_q^T lambda - Q)/dq to block Jq and
   cv d(M a - Q)/dv to block Jv (may be Jq's block; NULL: left out), from
   force_jac and mass_jac or forward differences for those missing; lam ==
   NULL leaves out the C_q^T lambda term; Qbase = Q(t,q,v) and Mbase =
   M(t,q,v) must be given.  Forward differences go by column groups
   (vlbe__dae_group): kl + ku + 1 evaluations for a band, one per
   coordinate for a dense matrix.  inv: from vlbe__dae_inv (dense: NULL).
   w: vlbe__dae_btangent_len(s) reals (scratch). */
VLBE_INLINE size_t vlbe__dae_tlen(size_t ml0, size_t ml1, size_t n, size_t m)
{
    size_t a = 3 * ml0 + 6 * n + 2 * (m + n),                        /* K, D, T, vectors */
        b = ml0 + ml1 + m + 2 * n + 2 * (2 * n + m) + 2 * (n + m); /* H, Cq, Ct, vectors */
    return a > b ? a : b;
}
VLBE_INLINE size_t vlbe__dae_btangent_len(const vlbe_dae *s)
{
    return vlbe__dae_tlen(vlbe__dae_mlen(s, 0), vlbe__dae_mlen(s, 1), (size_t)s->n,
                          (size_t)s->m);
}
/* the same for a dense problem of n coordinates and m constraints */
VLBE_INLINE size_t vlbe__dae_tangent_len(int n, int m)
{
    return vlbe__dae_tlen((size_t)n * (size_t)n, (size_t)m * (size_t)n, (size_t)n, (size_t)m);
}
/* f = [C_q^T u_0; ..; C_q^T u_{nu-1}; C_q v + C_t] (the last if v); pw:
   2 NA scratch of a band */
VLBE_INLINE void vlbe__dae_bconstr_vals(const vlbe_dae *s, const vlbe_real *Cq,
                                        const vlbe_real *Ct, int nu, const vlbe_real *const *u,
                                        const vlbe_real *v, vlbe_real *f, vlbe_real *pw)
{
    int n = s->n, m = s->m, k, i;
    if (!vlbe__dae_banded(s)) {
        vlbe__dae_constr_vals(n, m, Cq, Ct, nu, u, v, f);
        return;
    }
    for (k = 0; k < nu; ++k) vlbe__dae_bprod(s, 2, Cq, u[k], f + (size_t)k * n, pw);
    if (v) {
        vlbe__dae_bprod(s, 1, Cq, v, f + (size_t)nu * n, pw);
        for (i = 0; i < m; ++i) f[(size_t)nu * n + i] += Ct[i];
    }
}
VLBE_INLINE vlbe_status vlbe__dae_bconstr_q(const vlbe_dae *s, vlbe_dae_stats *c, vlbe_real t,
                                            const vlbe_real *q, const vlbe_real *lam,
                                            vlbe_real cl, const vlbe__dae_blk *Jl,
                                            const vlbe_real *mu, vlbe_real cu,
                                            const vlbe__dae_blk *Ju, const vlbe_real *v,
                                            const vlbe__dae_blk *Jg, const int *inv, vlbe_real *w)
{
    int n = s->n, m = s->m, NA = n + m, wd = vlbe__dae_gstride(s), k, g, col, nu = 0;
    vlbe_real *H = w, *Cq = H + vlbe__dae_mlen(s, 0), *Ct = Cq + vlbe__dae_mlen(s, 1),
              *x = Ct + m, *d = x + n, *f0 = d + n, *f = f0 + 2 * n + m, *pw = f + 2 * n + m;
    const vlbe_real *u[2];
    vlbe_real cu_[2];
    const vlbe__dae_blk *Ju_[2];
    vlbe_status rc;
    if ((s->flags & VLBE_DAE_NO_CHESS) || cl == VLBE_R(0.0)) lam = NULL;
    if ((s->flags & VLBE_DAE_NO_CHESS) || cu == VLBE_R(0.0)) mu = NULL;
    for (k = 0; k < 2; ++k) {
        const vlbe_real *uk = k == 0 ? lam : mu;
        if (!uk) continue;
        u[nu] = uk;
        cu_[nu] = k == 0 ? cl : cu;
        Ju_[nu] = k == 0 ? Jl : Ju;
        ++nu;
    }
    if (s->constr_hess && nu > 0) {
        for (k = 0; k < nu; ++k) {
            ++c->constr_calls;
            if ((rc = vlbe__dae_cb(c, s->constr_hess(s->user, t, q, u[k], H))) != VLBE_OK) return rc;
            vlbe__dae_badd(s, Ju_[k], cu_[k], H, 0);
        }
        nu = 0;
    }
    if (nu == 0 && !Jg) return VLBE_OK;
    if (!Jg) v = NULL;
    if ((rc = vlbe__dae_cjac(s, c, t, q, Cq, v ? Ct : NULL)) != VLBE_OK) return rc;
    vlbe__dae_bconstr_vals(s, Cq, Ct, nu, u, v, f0, pw);
    for (g = 0; g < wd; ++g) {
        if (!vlbe__dae_group(s, inv, g, q, x, d)) continue;
        if ((rc = vlbe__dae_cjac(s, c, t, x, Cq, v ? Ct : NULL)) != VLBE_OK) return rc;
        vlbe__dae_bconstr_vals(s, Cq, Ct, nu, u, v, f, pw);
        for (col = g; col < NA; col += wd) {
            int j = vlbe__dae_unk(inv, col), r, r0, r1;
            if (j >= n) continue;
            vlbe__dae_rows(s, col, &r0, &r1);
            for (r = r0; r <= r1; ++r) {
                int i = vlbe__dae_unk(inv, r);
                if (i < n) {
                    for (k = 0; k < nu; ++k)
                        *vlbe__dae_blk_at(Ju_[k], r, col) +=
                            cu_[k] * (f[(size_t)k * n + i] - f0[(size_t)k * n + i]) / d[j];
                } else if (v) {
                    size_t e = (size_t)nu * n + (size_t)(i - n);
                    *vlbe__dae_blk_at(Jg, r, col) += (f[e] - f0[e]) / d[j];
                }
            }
        }
    }
    return VLBE_OK;
}
VLBE_INLINE vlbe_status vlbe__dae_btangent(const vlbe_dae *s, vlbe_dae_stats *c, vlbe_real t,
                                           const vlbe_real *q, const vlbe_real *v,
                                           const vlbe_real *a, const vlbe_real *lam,
                                           const vlbe_real *Qbase, const vlbe_real *Mbase,
                                           vlbe_real cq, const vlbe__dae_blk *Jq, vlbe_real cv,
                                           const vlbe__dae_blk *Jv, const int *inv, vlbe_real *w)
{
    int n = s->n, NA = n + s->m, wd = vlbe__dae_gstride(s), g, col, pass;
    size_t ml = vlbe__dae_mlen(s, 0);
    vlbe_real *K = w, *D = K + ml, *T = D + ml, *x = T + ml, *f = x + n, *f0 = f + n, *d = f0 + n,
              *pw = d + n;
    vlbe_status rc;
    ++c->jac_evals;
    if (!Jv) cv = VLBE_R(0.0);
    /* -K and -D */
    if (s->force_jac) {
        ++c->force_calls;
        if ((rc = vlbe__dae_cb(c, s->force_jac(s->user, t, q, v, K, D))) != VLBE_OK) return rc;
        if (cq != VLBE_R(0.0)) vlbe__dae_badd(s, Jq, -cq, K, 0);
        if (cv != VLBE_R(0.0)) vlbe__dae_badd(s, Jv, -cv, D, 0);
    } else {
        for (pass = 0; pass < 2; ++pass) {
            vlbe_real cc = pass == 0 ? cq : cv;
            const vlbe_real *base = pass == 0 ? q : v;
            const vlbe__dae_blk *J = pass == 0 ? Jq : Jv;
            if (cc == VLBE_R(0.0)) continue;
            for (g = 0; g < wd; ++g) {
                if (!vlbe__dae_group(s, inv, g, base, x, d)) continue;
                rc = pass == 0 ? vlbe__dae_force(s, c, t, x, v, f) : vlbe__dae_force(s, c, t, q, x, f);
                if (rc != VLBE_OK) return rc;
                for (col = g; col < NA; col += wd) {
                    int j = vlbe__dae_unk(inv, col), r, r0, r1;
                    if (j >= n) continue;
                    vlbe__dae_rows(s, col, &r0, &r1);
                    for (r = r0; r <= r1; ++r) {
                        const int i = vlbe__dae_unk(inv, r);
                        if (i < n) *vlbe__dae_blk_at(J, r, col) -= cc * (f[i] - Qbase[i]) / d[j];
                    }
                }
            }
        }
    }
    /* d(M a)/dq, d(M a)/dv */
    if (!(s->flags & VLBE_DAE_MASS_CONST)) {
        int mv = (s->flags & VLBE_DAE_MASS_V) != 0;
        if (s->mass_jac) {
            ++c->mass_calls;
            rc = vlbe__dae_cb(c, s->mass_jac(s->user, t, q, v, a, K, mv ? D : NULL));
            if (rc != VLBE_OK) return rc;
            if (cq != VLBE_R(0.0)) vlbe__dae_badd(s, Jq, cq, K, 0);
            if (mv && cv != VLBE_R(0.0)) vlbe__dae_badd(s, Jv, cv, D, 0);
        } else {
            vlbe__dae_bprod(s, 0, Mbase, a, f0, pw);
            for (pass = 0; pass < 2; ++pass) {
                vlbe_real cc = pass == 0 ? cq : cv;
                const vlbe_real *base = pass == 0 ? q : v;
                const vlbe__dae_blk *J = pass == 0 ? Jq : Jv;
                if (pass == 1 && !mv) break;
                if (cc == VLBE_R(0.0)) continue;
                for (g = 0; g < wd; ++g) {
                    if (!vlbe__dae_group(s, inv, g, base, x, d)) continue;
                    rc = pass == 0 ? vlbe__dae_mass(s, c, t, x, v, T) : vlbe__dae_mass(s, c, t, q, x, T);
                    if (rc != VLBE_OK) return rc;
                    vlbe__dae_bprod(s, 0, T, a, f, pw);
                    for (col = g; col < NA; col += wd) {
                        int j = vlbe__dae_unk(inv, col), r, r0, r1;
                        if (j >= n) continue;
                        vlbe__dae_rows(s, col, &r0, &r1);
                        for (r = r0; r <= r1; ++r) {
                            const int i = vlbe__dae_unk(inv, r);
                            if (i < n) *vlbe__dae_blk_at(J, r, col) += cc * (f[i] - f0[i]) / d[j];
                        }
                    }
                }
            }
        }
    }
    /* d(C_q^T lambda)/dq (scratch: w, the K D T area is free again) */
    if (s->m > 0 && lam && cq != VLBE_R(0.0))
        return vlbe__dae_bconstr_q(s, c, t, q, lam, cq, Jq, NULL, VLBE_R(0.0), NULL, NULL, NULL,
                                   inv, w);
    return VLBE_OK;
}

/* Dense callers: blocks given by their first entry and leading dimension
   (Jg: the block of the m constraint rows). */
VLBE_INLINE vlbe_status vlbe__dae_constr_q(const vlbe_dae *s, vlbe_dae_stats *c, vlbe_real t,
                                           const vlbe_real *q, const vlbe_real *lam,
                                           vlbe_real cl, vlbe_real *Jl, int ldl,
                                           const vlbe_real *mu, vlbe_real cu, vlbe_real *Ju,
                                           int ldu, const vlbe_real *v, vlbe_real *Jg, int ldg,
                                           vlbe_real *w)
{
    vlbe__dae_blk bl = vlbe__dae_dblk(Jl, ldl, 0), bu = vlbe__dae_dblk(Ju, ldu, 0),
                  bg = vlbe__dae_dblk(Jg, ldg, -s->n);
    return vlbe__dae_bconstr_q(s, c, t, q, lam, cl, Jl ? &bl : NULL, mu, cu, Ju ? &bu : NULL, v,
                               Jg ? &bg : NULL, NULL, w);
}
VLBE_INLINE vlbe_status vlbe__dae_tangent2(const vlbe_dae *s, vlbe_dae_stats *c, vlbe_real t,
                                           const vlbe_real *q, const vlbe_real *v,
                                           const vlbe_real *a, const vlbe_real *lam,
                                           const vlbe_real *Qbase, const vlbe_real *Mbase,
                                           vlbe_real cq, vlbe_real *Jq, int ldq, vlbe_real cv,
                                           vlbe_real *Jv, int ldv, vlbe_real *w)
{
    vlbe__dae_blk bq = vlbe__dae_dblk(Jq, ldq, 0), bv = vlbe__dae_dblk(Jv, ldv, 0);
    return vlbe__dae_btangent(s, c, t, q, v, a, lam, Qbase, Mbase, cq, &bq, cv, Jv ? &bv : NULL,
                              NULL, w);
}
/* -- problem checks and consistent start -------------------------------- */
/* need_mass = 0: a problem for the static solver, which never calls mass */
VLBE_INLINE vlbe_status vlbe__dae_check(const vlbe_dae *sys, int need_mass)
{
    if (!sys || sys->n < 1 || sys->m < 0 || sys->m > sys->n || (need_mass && !sys->mass) ||
        !sys->force)
        return VLBE_EARG;
    if (sys->m > 0 && (!sys->constr || !sys->constr_jac)) return VLBE_EARG;
    if ((sys->lin_factor == NULL) != (sys->lin_solve == NULL)) return VLBE_EARG;
    if (sys->storage == VLBE_DAE_BANDED) {
        /* 2 (n+m) rows of BDF must fit an int, bands must fit the matrix */
        if ((size_t)sys->n > (size_t)0x10000000 || !sys->order || sys->kl < 0 || sys->ku < 0 ||
            sys->kl >= sys->n + sys->m || sys->ku >= sys->n + sys->m)
            return VLBE_EARG;
        return VLBE_OK;
    }
    if (sys->storage != VLBE_DAE_DENSE) return VLBE_EARG;
    if ((size_t)sys->n > (size_t)46340) return VLBE_EARG; /* (n+m)^2 must fit an int index */
    return VLBE_OK;
}
VLBE_API vlbe_status vlbe_dae_check(const vlbe_dae *sys) { return vlbe__dae_check(sys, 1); }

/* A dense problem of n coordinates and m constraints, for the (n, m)
   workspace queries: each is the _sys query of that problem. */
VLBE_INLINE vlbe_dae vlbe__dae_dense(int n, int m)
{
    vlbe_dae d;
    memset(&d, 0, sizeof d);
    d.n = n;
    d.m = m;
    return d;
}
VLBE_API size_t vlbe_dae_work_len(int n, int m)
{
    const vlbe_dae d = vlbe__dae_dense(n, m);
    return vlbe_dae_work_len_sys(&d);
}
VLBE_API size_t vlbe_dae_iwork_len(int n, int m) { return (size_t)n + (size_t)m; }
/* the same for the problem's storage: system matrix, rhs, M, Q, C_q, the
   scratch of gamma, and (banded) the right side in the band's order */
VLBE_API size_t vlbe_dae_work_len_sys(const vlbe_dae *sys)
{
    size_t NA;
    VLBE_ASSERT(sys != NULL);
    NA = (size_t)sys->n + (size_t)sys->m;
    return vlbe__dae_alen(sys, 1) + NA + vlbe__dae_mlen(sys, 0) + (size_t)sys->n +
           vlbe__dae_mlen(sys, 1) + vlbe__dae_gamma_len(sys) + (vlbe__dae_banded(sys) ? NA : 0);
}
VLBE_API size_t vlbe_dae_iwork_len_sys(const vlbe_dae *sys)
{
    VLBE_ASSERT(sys != NULL);
    return vlbe_dae_iwork_len(sys->n, sys->m) + vlbe__dae_ilen(sys);
}

/* Row equilibration before an LU (vlbe_lu_factor's pivot test is relative
   to the largest entry of the whole matrix, so a row of small but regular
   entries, e.g. a spin inertia rho I L/3 ~ 1e-7 kg m^2 next to unit
   constraint entries, reads as zero in float): row i of the N x N matrix A
   (leading dimension ld) is multiplied by s_i = 2^-e, max_j |a_ij| = f 2^e
   with f in [1/2, 1).  A power of 2 is exact: the scaled entries are A's
   own, and the factor differs from an unscaled one only where the row
   scales change the choice of pivots (scaled partial pivoting).  A zero,
   subnormal or non-finite row keeps s_i = 1 (vlbe_lu_factor reports it).
   s (N, may be NULL) receives the scales, which the right sides of later
   solves need; b (N, may be NULL) is scaled along.  width: the entries
   of a row, N for a dense matrix, ld for a band (whose slots outside the
   matrix hold zeros). */
VLBE_INLINE void vlbe__dae_equil(int N, vlbe_real *A, size_t ld, int width, vlbe_real *s,
                                 vlbe_real *b)
{
    int i, e;
    for (i = 0; i < N; ++i) {
        vlbe_real *ai = A + (size_t)i * ld, r = vlbe_vec_norm_inf(width, ai), si = VLBE_R(1.0);
        if (r > VLBE_R(0.0) && isfinite(r)) {
            (void)vlbe_frexp(r, &e);
            si = vlbe_ldexp(VLBE_R(1.0), -e);
            if (!isfinite(si)) si = VLBE_R(1.0); /* a subnormal row: 2^-e overflows */
            vlbe_vec_scale(width, si, ai);
            if (b) b[i] *= si;
        }
        if (s) s[i] = si;
    }
}

/* Factors the iteration matrix A of f blocks (N = f (n + m), in the
   problem's storage) in place: the dense or banded LU, or the caller's
   lin_factor. */
VLBE_INLINE vlbe_status vlbe__dae_factor(const vlbe_dae *s, vlbe_dae_stats *c, int f,
                                         vlbe_real *A, int *piv)
{
    int N = f * (s->n + s->m), band = vlbe__dae_banded(s), kl = N - 1, ku = kl, rc;
    if (band) {
        kl = vlbe__dae_fkl(s, f);
        ku = vlbe__dae_fku(s, f);
    }
    if (s->lin_factor) {
        if (!vlbe_all_finite(A, (int)vlbe__dae_alen(s, f))) return VLBE_ENONFINITE;
        rc = s->lin_factor(s->user, s->storage, N, kl, ku, A, (int)vlbe__dae_ald(s, f));
        if (rc == 0) return VLBE_OK;
        if (rc > 0) return VLBE_ESINGULAR;
        c->callback_rc = rc;
        return VLBE_ECALLBACK;
    }
    if (band) return vlbe_band_lu_factor(N, kl, ku, A, (int)vlbe__dae_ald(s, f), A, piv, NULL);
    return vlbe_lu_factor(N, A, A, piv, NULL);
}
/* b <- A^-1 b with the factor of vlbe__dae_factor (b in A's order). */
VLBE_INLINE void vlbe__dae_solve(const vlbe_dae *s, int f, const vlbe_real *A, const int *piv,
                                 vlbe_real *b)
{
    int N = f * (s->n + s->m);
    if (s->lin_solve) s->lin_solve(s->user, N, 1, b);
    else if (vlbe__dae_banded(s))
        vlbe_band_lu_solve(N, vlbe__dae_fkl(s, f), vlbe__dae_fku(s, f), A, piv, 1, b);
    else vlbe_lu_solve(N, A, piv, 1, b);
}

/* Solves [M C_q^T; C_q 0] [qdd; lambda] = [Q; gamma] at (t, q, v). */
/* a += b for every counter (runs made of several integrator starts, e.g.
   restarts after a change of the model); callback_rc: b's when nonzero. */
VLBE_API void vlbe_dae_stats_add(vlbe_dae_stats *a, const vlbe_dae_stats *b)
{
    VLBE_ASSERT(a != NULL && b != NULL);
    a->steps += b->steps;
    a->rejected += b->rejected;
    a->newton_iters += b->newton_iters;
    a->newton_fails += b->newton_fails;
    a->force_calls += b->force_calls;
    a->mass_calls += b->mass_calls;
    a->constr_calls += b->constr_calls;
    a->jac_evals += b->jac_evals;
    a->lu_factors += b->lu_factors;
    a->lu_solves += b->lu_solves;
    if (b->callback_rc != 0) a->callback_rc = b->callback_rc;
}

/* The saddle system [M C_q^T; C_q 0] x = b of the consistent start and of
   vlbe_dae_project, in the problem's storage: assembled into A
   (vlbe__dae_alen(sys, 1) reals) from M and C_q, rows equilibrated
   (vlbe__dae_equil), factored (piv: n + m ints), b (n + m, natural order:
   the q rows, then the constraints) overwritten with x.  X: the right side
   in the band's order (banded: n + m reals; dense: unused).  Returns
   VLBE_ENONFINITE (b or x) or the status of the factorization. */
VLBE_INLINE vlbe_status vlbe__dae_saddle_solve(const vlbe_dae *sys, vlbe_dae_stats *stats,
                                               const vlbe_real *M, const vlbe_real *Cq,
                                               vlbe_real *A, vlbe_real *b, vlbe_real *X, int *piv)
{
    int n = sys->n, m = sys->m, N = n + m, i, j, band = vlbe__dae_banded(sys);
    vlbe_status rc;
    if (band) {
        const vlbe__dae_blk B = vlbe__dae_band_blk(sys, A, 1);
        vlbe_vec_zero((int)vlbe__dae_alen(sys, 1), A);
        vlbe__dae_badd(sys, &B, VLBE_R(1.0), M, 0);
        vlbe__dae_bsaddle(sys, &B, VLBE_R(1.0), Cq);
    } else {
        for (i = 0; i < N; ++i)
            for (j = 0; j < N; ++j) {
                vlbe_real x = VLBE_R(0.0);
                if (i < n && j < n) x = M[(size_t)i * n + j];
                else if (i < n && j >= n) x = Cq[(size_t)(j - n) * n + i];
                else if (i >= n && j < n) x = Cq[(size_t)(i - n) * n + j];
                A[(size_t)i * N + j] = x;
            }
    }
    if (!vlbe_all_finite(b, N)) return VLBE_ENONFINITE;
    if (band) vlbe__dae_perm(sys, 1, b, X);
    else X = b;
    vlbe__dae_equil(N, A, vlbe__dae_ald(sys, 1), band ? (int)vlbe__dae_ald(sys, 1) : N, NULL, X);
    ++stats->lu_factors;
    if ((rc = vlbe__dae_factor(sys, stats, 1, A, piv)) != VLBE_OK) return rc;
    ++stats->lu_solves;
    vlbe__dae_solve(sys, 1, A, piv, X);
    if (band) vlbe__dae_unperm(sys, 1, X, b);
    if (!vlbe_all_finite(b, N)) return VLBE_ENONFINITE;
    return VLBE_OK;
}

VLBE_API vlbe_status vlbe_dae_consistent_acc(const vlbe_dae *sys, vlbe_real t, const vlbe_real *q,
                                             const vlbe_real *v, vlbe_real *qdd,
                                             vlbe_real *lambda, vlbe_dae_stats *stats,
                                             vlbe_real *work, size_t work_len, int *iwork,
                                             size_t iwork_len)
{
    int n, m, N, band;
    vlbe_real *A, *b, *M, *Q, *Cq, *sc, *X;
    vlbe_dae_stats dummy;
    vlbe_status rc;
    if ((rc = vlbe_dae_check(sys)) != VLBE_OK) return rc;
    n = sys->n;
    m = sys->m;
    N = n + m;
    band = vlbe__dae_banded(sys);
    if (work_len < vlbe_dae_work_len_sys(sys) || iwork_len < vlbe_dae_iwork_len_sys(sys))
        return VLBE_EWORK;
    if (band && (rc = vlbe__dae_inv(sys, iwork + N)) != VLBE_OK) return rc;
    if (!stats) {
        stats = &dummy;
        vlbe__dae_stats_zero(&dummy);
    }
    A = work;
    b = A + vlbe__dae_alen(sys, 1);
    M = b + N;
    Q = M + vlbe__dae_mlen(sys, 0);
    Cq = Q + n;
    sc = Cq + vlbe__dae_mlen(sys, 1);
    X = sc + vlbe__dae_gamma_len(sys); /* banded: the right side in A's order */
    if ((rc = vlbe__dae_mass(sys, stats, t, q, v, M)) != VLBE_OK) return rc;
    if ((rc = vlbe__dae_force(sys, stats, t, q, v, Q)) != VLBE_OK) return rc;
    if ((rc = vlbe__dae_cjac(sys, stats, t, q, Cq, NULL)) != VLBE_OK) return rc;
    if ((rc = vlbe__dae_gamma(sys, stats, t, q, v, b + n, sc)) != VLBE_OK) return rc;
    vlbe_vec_copy(n, Q, b);
    if ((rc = vlbe__dae_saddle_solve(sys, stats, M, Cq, A, b, X, iwork)) != VLBE_OK) return rc;
    vlbe_vec_copy(n, b, qdd);
    if (m > 0) vlbe_vec_copy(m, b + n, lambda);
    return VLBE_OK;
}

/* Consistent start (q, v) for the integrators: Gauss-Newton on C(t, q) = 0
   with the minimum-norm correction in the kinetic-energy metric W = M(t, q,
   v) (M at the caller's point, kept through the iteration),
       [ W  C_q^T ] [ dq ]   [  0 ]
       [ C_q  0   ] [ nu ] = [ -C ],      q <- q + dq,
   C_q fresh at each iterate, then the velocities in one exact step onto
   C_q v + C_t = 0 at the new q: the same system with the right side
   (0, -(C_q v + C_t)), v <- v + dv.  Why M and not the Euclidean norm: the
   kinetic-energy norm does not depend on the units of the coordinates
   (ANCF mixes positions in m with dimensionless slopes, whose Euclidean
   sum means nothing), the velocity correction is then the one an impulse
   of the constraint forces gives (Gauss's principle: least change of
   kinetic energy), and the matrix is the one of vlbe_dae_consistent_acc,
   so the dense and banded storages and the caller's lin_factor serve it
   alike (M must be positive definite on the null space of C_q, as there).
   Converged when ||C||_inf <= tol (tol <= 0: VLBE_RTOL_EPS eps max(1,
   max|q_i|), 1.4e-14 for coordinates of order one in double), or when a
   correction is at the rounding floor (max|dq| <= 8 eps max|q|: C is then
   as small as the arithmetic of the model makes it).  A start with
   ||C||_inf <= tol costs one constr call and no solve, and q is left bit for
   bit; v is left bit for bit when ||C_q v + C_t||_inf is already at the
   rounding of its evaluation, VLBE_RTOL_EPS eps (||C_t||_inf + max|C_q|
   max|v_i|).  Returns VLBE_OK; VLBE_EARG (problem, NULL q or v, t or tol
   not finite, an order that is not a permutation); VLBE_EWORK (the
   workspace of vlbe_dae_work_len_sys and vlbe_dae_iwork_len_sys, which is
   large enough); VLBE_ENONFINITE (q, v, C, an iterate); VLBE_ESINGULAR
   (rank-deficient C_q: redundant constraints, or M singular on the null
   space of C_q); VLBE_ECALLBACK; VLBE_ENOCONV (VLBE_DAE_PROJECT_ITER
   iterations without convergence: a start too far from the constraint
   manifold for Gauss-Newton, or no point of it near).  On failure q and v
   are as they were (the iteration runs on copies in work).  stats (may be
   NULL) is added to: newton_iters counts the position iterations,
   newton_fails the VLBE_ENOCONV returns, and the calls, factorizations
   and solves as in the integrators. */
VLBE_API vlbe_status vlbe_dae_project(const vlbe_dae *sys, vlbe_real t, vlbe_real *q, vlbe_real *v,
                                      vlbe_real tol, vlbe_dae_stats *stats, vlbe_real *work,
                                      size_t work_len, int *iwork, size_t iwork_len)
{
    int n, m, N, i, it, band, have_m = 0;
    vlbe_real *qc, *vc, *A, *b, *M, *Cq, *Ct, *C, *X, *pw;
    vlbe_real tolq, tolv, cn, qmax;
    vlbe_dae_stats dummy;
    vlbe_status rc;
    if ((rc = vlbe_dae_check(sys)) != VLBE_OK) return rc;
    if (!q || !v || !isfinite(t) || !isfinite(tol)) return VLBE_EARG;
    n = sys->n;
    m = sys->m;
    N = n + m;
    band = vlbe__dae_banded(sys);
    if (!work || !iwork || work_len < vlbe_dae_work_len_sys(sys) ||
        iwork_len < vlbe_dae_iwork_len_sys(sys))
        return VLBE_EWORK;
    if (!vlbe_all_finite(q, n) || !vlbe_all_finite(v, n)) return VLBE_ENONFINITE;
    if (band && (rc = vlbe__dae_inv(sys, iwork + N)) != VLBE_OK) return rc;
    if (m == 0) return VLBE_OK;
    if (!stats) {
        stats = &dummy;
        vlbe__dae_stats_zero(&dummy);
    }
    qc = work;
    vc = qc + n;
    A = vc + n;
    b = A + vlbe__dae_alen(sys, 1);
    M = b + N;
    Cq = M + vlbe__dae_mlen(sys, 0);
    Ct = Cq + vlbe__dae_mlen(sys, 1);
    C = Ct + m;
    X = C + m;  /* banded: the right side in A's order (N) */
    pw = X + N; /* banded: products (2 N) */
    vlbe_vec_copy(n, q, qc);
    vlbe_vec_copy(n, v, vc);
    qmax = vlbe_vec_norm_inf(n, q);
    tolq = tol > VLBE_R(0.0) ? tol : VLBE_RTOL_EPS * VLBE_EPS * (qmax > VLBE_R(1.0) ? qmax : VLBE_R(1.0));
    if ((rc = vlbe__dae_constr(sys, stats, t, qc, C)) != VLBE_OK) return rc;
    if (!vlbe_all_finite(C, m)) return VLBE_ENONFINITE;
    cn = vlbe_vec_norm_inf(m, C);
    /* positions: Gauss-Newton, minimum W-norm corrections */
    for (it = 0; cn > tolq; ++it) {
        if (it == VLBE_DAE_PROJECT_ITER) {
            ++stats->newton_fails;
            return VLBE_ENOCONV;
        }
        if (!have_m && (rc = vlbe__dae_mass(sys, stats, t, q, v, M)) != VLBE_OK) return rc;
        have_m = 1;
        if ((rc = vlbe__dae_cjac(sys, stats, t, qc, Cq, NULL)) != VLBE_OK) return rc;
        vlbe_vec_zero(n, b);
        for (i = 0; i < m; ++i) b[n + i] = -C[i];
        if ((rc = vlbe__dae_saddle_solve(sys, stats, M, Cq, A, b, X, iwork)) != VLBE_OK) return rc;
        ++stats->newton_iters;
        vlbe_vec_axpy(n, VLBE_R(1.0), b, qc);
        if (!vlbe_all_finite(qc, n)) return VLBE_ENONFINITE;
        if ((rc = vlbe__dae_constr(sys, stats, t, qc, C)) != VLBE_OK) return rc;
        if (!vlbe_all_finite(C, m)) return VLBE_ENONFINITE;
        cn = vlbe_vec_norm_inf(m, C);
        if (vlbe_vec_norm_inf(n, b) <= VLBE_R(8.0) * VLBE_EPS * vlbe_vec_norm_inf(n, qc)) break;
    }
    /* velocities: one exact step onto C_q v + C_t = 0 at the new q */
    if ((rc = vlbe__dae_cjac(sys, stats, t, qc, Cq, Ct)) != VLBE_OK) return rc;
    if (band) vlbe__dae_bprod(sys, 1, Cq, vc, b + n, pw);
    else vlbe_mat_vec(m, n, Cq, vc, b + n);
    vlbe_vec_axpy(m, VLBE_R(1.0), Ct, b + n);
    if (!vlbe_all_finite(b + n, m)) return VLBE_ENONFINITE;
    tolv = VLBE_RTOL_EPS * VLBE_EPS *
           (vlbe_vec_norm_inf(m, Ct) +
            vlbe_vec_norm_inf((int)vlbe__dae_mlen(sys, 1), Cq) * vlbe_vec_norm_inf(n, vc));
    if (vlbe_vec_norm_inf(m, b + n) > tolv) {
        if (!have_m && (rc = vlbe__dae_mass(sys, stats, t, q, v, M)) != VLBE_OK) return rc;
        vlbe_vec_zero(n, b);
        vlbe_vec_scale(m, -VLBE_R(1.0), b + n);
        if ((rc = vlbe__dae_saddle_solve(sys, stats, M, Cq, A, b, X, iwork)) != VLBE_OK) return rc;
        vlbe_vec_axpy(n, VLBE_R(1.0), b, vc);
        if (!vlbe_all_finite(vc, n)) return VLBE_ENONFINITE;
    }
    vlbe_vec_copy(n, qc, q);
    vlbe_vec_copy(n, vc, v);
    return VLBE_OK;
}

/* sqrt(a^2 + b^2) of a, b >= 0 without overflow of the squares; NaN if
   either is NaN. */
VLBE_INLINE vlbe_real vlbe__dae_hypot(vlbe_real a, vlbe_real b)
{
    vlbe_real s = a > b ? a : b;
    if (a != a || b != b) return a + b;
    if (s == VLBE_R(0.0) || !isfinite(s)) return s;
    a /= s;
    b /= s;
    return s * vlbe_sqrt(a * a + b * b);
}

/* Weighted Euclidean norm of a residual Psi = (r, c), r of n and c of m
   components: ||Psi||_2 / sqrt(n + m) (Hsiao et al. eq. 53, N = n + m
   equations); NaN if Psi holds one. */
VLBE_INLINE vlbe_real vlbe__dae_psi_norm(int n, const vlbe_real *r, int m, const vlbe_real *c)
{
    return vlbe__dae_hypot(vlbe_vec_norm2(n, r), vlbe_vec_norm2(m, c)) /
           vlbe_sqrt((vlbe_real)(n + m));
}

/* ===== linearisation ===================================================== */
/* vlbe_dae_linearize: the linearised equations of motion of a vlbe_dae
   about a given state (t, q, v, a = q'', lambda), reduced to the tangent
   space of the constraint manifold -- the matrices of eigen-, stability and
   controller-design studies.

   Perturbing M(q) q'' + C_q(q)^T lambda = Q(q, v) about the reference
   (q, v, a, lambda) at fixed t and fixed multipliers, and writing the
   admissible perturbations as dq = N eta with C_q N = 0 (the columns of N
   span the null space of C_q, so that the reaction C_q^T dlambda drops out
   of N^T times the equations):
       Mr eta'' + Dr eta' + Kr eta = 0,          Mr = N^T M N,
       Dr = N^T ( -dQ/dv + d(M a)/dv ) N,
       Kr = N^T ( -dQ/dq + d(M a)/dq + d(C_q^T lambda)/dq ) N.
   The last term is the geometric stiffness of the constraints: the
   reaction C_q^T lambda turning with the constraint's normal (a pendulum
   owes its g / L to it).  The Jacobians come from the integrators'
   routine vlbe__dae_btangent: force_jac, mass_jac and constr_hess where the
   model gives them, forward differences of force, of M(q) a and of
   C_q^T lambda where it does not (dQ/dv by differences only without
   force_jac; d(M a)/dq only without VLBE_DAE_MASS_CONST, d(M a)/dv only
   with VLBE_DAE_MASS_V).  VLBE_DAE_NO_CHESS is ignored here: it drops the
   constraint term from an iteration matrix, where it only slows Newton,
   whereas here it is physics.

   The basis N.  Householder QR with column pivoting of C_q^T (n x m;
   Golub & Van Loan, Matrix Computations, 4th ed., alg. 5.4.1), C_q^T P =
   Q R, column norms recomputed at each step (the downdating formula of
   the algorithm loses its digits after cancellation; recomputing costs the
   order of the factorisation itself).  Step k picks the trailing column of
   largest norm, which becomes |R_kk|; the rank r is the first k with
       |R_kk| <= n eps |R_11|       (eps = VLBE_EPS),
   the rounding level of a Householder factorisation of a matrix of norm
   about |R_11|.  N = the last n - r columns of Q = H_1 ... H_r: orthonormal
   columns (to rounding), so Mr, Kr keep the conditioning of M and K.
   Redundant constraint rows are allowed and counted out of the rank (their
   multipliers need not be split in any particular way: only C_q^T lambda
   enters).  m = 0: N = I, nr = n.

   Rotating frame (frame != NULL).  A frame turning uniformly at omega
   whose axes are the inertial ones at the instant t: the listed vectors of
   q are q = R(s) q~, R(s) = exp(G (s - t)), G constant and block diagonal
   (omega x . on each listed vector of dim components, 0 on the scalar
   coordinates).  With R G = G R,
       q' = R (q~' + G q~),     q'' = R (q~'' + 2 G q~' + G^2 q~),
   and dq = R dq~ in M dq'' + D dq' + K dq = 0 at s = t (R = I) gives
       M~ = M,   D~ = D + 2 M G,   K~ = K + M G^2 + D G,
   (2 M G: Coriolis, M G^2: centrifugal softening, D G: damping of the
   frame's own motion), then reduced with N.  The caller's state must be a
   rotating steady state, v = G q and a = G^2 q at its reference, with the
   multipliers that hold it.

   Exactness.  About an equilibrium (v = 0, a = 0 of a model that does not
   depend on t) the result is the exact linearisation: small motions dq = N
   eta obey it to first order; so about a frame-steady state of a model
   invariant under the frame's rotation, in the frame.  About a general
   moving state it is the frozen-time linearisation at t: it neglects the
   time variation of N (dq' = N eta' + N' eta: the N' terms, the velocity
   of the state times the curvature of the constraint manifold) and of the
   matrices along the reference motion.

   Banded problems (VLBE_DAE_BANDED) are supported by unpacking the bands of
   M, K, D and C_q into dense n x n and n x m arrays in the workspace (the
   reduced matrices are dense anyway); the Jacobians are formed in band
   form (one evaluation per kl + ku + 1 columns where differences are
   needed).

   Arguments: lambda (m; may be NULL when m = 0) as given, e.g. from
   vlbe_dae_consistent_acc; frame NULL: inertial.  Outputs: *nr = n - r;
   N (may be NULL) n x nr, row-major, leading dimension nr; Mr, Dr, Kr
   nr x nr each, leading dimension nr (the caller sizes N for n*n and the
   others for n*n reals, or for (n - m)^2 when the constraints are known to
   be independent).  stats (may be NULL) is added to.  Workspace:
   vlbe_dae_lin_work_len_sys(sys) reals, vlbe_dae_lin_iwork_len_sys(sys)
   ints (scratch).  Cost: one Jacobian evaluation, O(n^2 m) for the QR and
   O(n^2 nr) for the products.
   Returns VLBE_OK; VLBE_EARG (problem, t not finite, q, v, a, nr, Mr, Dr,
   Kr NULL, lambda NULL with m > 0, m > n, n > 46340 (n^2 must fit an int),
   frame: dim not 2 or 3, nvec < 0, vec NULL with nvec > 0, a vector
   reaching outside 0..n-1 or overlapping another, omega not finite;
   banded: order not a permutation); VLBE_EWORK; VLBE_ENONFINITE (q, v, a,
   lambda, or a matrix or result); VLBE_ECALLBACK (any callback != 0: a
   linearisation has no smaller step to retry with; stats->callback_rc
   holds the value).  Outputs untouched on failure. */

/* at most this many coordinates: n^2 fits an int */
#define VLBE__LIN_NMAX 46340

VLBE_API size_t vlbe_dae_lin_work_len_sys(const vlbe_dae *sys)
{
    size_t n, m, r;
    VLBE_ASSERT(sys != NULL);
    if (sys->n < 1 || sys->n > VLBE__LIN_NMAX || sys->m < 0) return SIZE_MAX;
    n = (size_t)sys->n;
    m = (size_t)sys->m;
    /* M, K, D, scratch T, basis N (n^2 each); Q; C_q^T, tau, column norms;
       Jacobian scratch; banded: the bands of M, K, D and C_q */
    r = 5 * n * n + n + n * m + 2 * m + vlbe__dae_btangent_len(sys);
    if (vlbe__dae_banded(sys)) r += 3 * vlbe__dae_mlen(sys, 0) + vlbe__dae_mlen(sys, 1);
    return r;
}
/* pivots (or the marks of the frame's vectors) n; banded: inv[] */
VLBE_API size_t vlbe_dae_lin_iwork_len_sys(const vlbe_dae *sys)
{
    VLBE_ASSERT(sys != NULL);
    return (size_t)(sys->n > 0 ? sys->n : 0) + vlbe__dae_ilen(sys);
}

/* the frame's generator on one vector: S x = omega x x (planar: omega[2]
   about z) */
VLBE_INLINE void vlbe__lin_skew(const vlbe_lin_frame *f, vlbe_real S[3][3])
{
    int i, j;
    for (i = 0; i < 3; ++i)
        for (j = 0; j < 3; ++j) S[i][j] = VLBE_R(0.0);
    if (f->dim == 2) {
        S[0][1] = -f->omega[2];
        S[1][0] = f->omega[2];
        return;
    }
    S[0][1] = -f->omega[2];
    S[0][2] = f->omega[1];
    S[1][0] = f->omega[2];
    S[1][2] = -f->omega[0];
    S[2][0] = -f->omega[1];
    S[2][1] = f->omega[0];
}

/* Y += c X G (X, Y n x n, row-major; G of the frame, block diagonal) */
VLBE_INLINE void vlbe__lin_xg(int n, const vlbe_lin_frame *f, vlbe_real c, const vlbe_real *X,
                              vlbe_real *Y)
{
    vlbe_real S[3][3];
    int d = f->dim, k, i, a, b;
    vlbe__lin_skew(f, S);
    for (k = 0; k < f->nvec; ++k) {
        const size_t o = (size_t)f->vec[k];
        for (i = 0; i < n; ++i) {
            const vlbe_real *x = X + (size_t)i * (size_t)n + o;
            vlbe_real *y = Y + (size_t)i * (size_t)n + o;
            for (b = 0; b < d; ++b) {
                vlbe_real s = VLBE_R(0.0);
                for (a = 0; a < d; ++a) s += x[a] * S[a][b];
                y[b] += c * s;
            }
        }
    }
}

/* 2-norm of x[0], x[ld], ..., x[(len-1) ld] (scaled: no overflow) */
VLBE_INLINE vlbe_real vlbe__lin_cnorm(int len, const vlbe_real *x, size_t ld)
{
    vlbe_real s = VLBE_R(0.0), sum = VLBE_R(0.0);
    int i;
    for (i = 0; i < len; ++i) {
        vlbe_real ax = vlbe_fabs(x[(size_t)i * ld]);
        if (ax > s) s = ax;
    }
    if (s == VLBE_R(0.0)) return s;
    for (i = 0; i < len; ++i) {
        vlbe_real y = x[(size_t)i * ld] / s;
        sum += y * y;
    }
    return s * vlbe_sqrt(sum);
}

/* Householder QR with column pivoting of A (n x m, row-major, ld m; GvL
   alg. 5.4.1), ended at the numerical rank, which it returns: step k
   reflects the trailing column of largest norm (piv: the columns' order),
   H_k = I - tau_k v v^T on rows k..n-1 with v_k = 1 and v_i (i > k) kept
   in A below the diagonal; R above.  cn: m reals of scratch. */
VLBE_INLINE int vlbe__lin_qrcp(int n, int m, vlbe_real *A, vlbe_real *tau, vlbe_real *cn, int *piv)
{
    int k, j, i, kmax = m < n ? m : n;
    const size_t ld = (size_t)m;
    vlbe_real tol = VLBE_R(0.0);
    for (j = 0; j < m; ++j) piv[j] = j;
    for (k = 0; k < kmax; ++k) {
        vlbe_real best = VLBE_R(-1.0), alpha, beta, sc;
        vlbe_real *ak = A + (size_t)k * ld;
        int p = k;
        for (j = k; j < m; ++j) {
            cn[j] = vlbe__lin_cnorm(n - k, ak + j, ld);
            if (cn[j] > best) {
                best = cn[j];
                p = j;
            }
        }
        if (k == 0) tol = (vlbe_real)n * VLBE_EPS * best; /* n eps |R_11| */
        if (!(best > tol)) return k;
        if (p != k) {
            for (i = 0; i < n; ++i) {
                vlbe_real *ai = A + (size_t)i * ld, x = ai[k];
                ai[k] = ai[p];
                ai[p] = x;
            }
            j = piv[k];
            piv[k] = piv[p];
            piv[p] = j;
        }
        alpha = ak[k];
        beta = alpha >= VLBE_R(0.0) ? -best : best; /* H x = beta e_k */
        tau[k] = (beta - alpha) / beta;
        sc = VLBE_R(1.0) / (alpha - beta);   /* |alpha - beta| >= best: no cancellation */
        for (i = k + 1; i < n; ++i) A[(size_t)i * ld + (size_t)k] *= sc;
        ak[k] = beta;
        for (j = k + 1; j < m; ++j) {
            vlbe_real w = ak[j];
            for (i = k + 1; i < n; ++i) w += A[(size_t)i * ld + (size_t)k] * A[(size_t)i * ld + (size_t)j];
            w *= tau[k];
            ak[j] -= w;
            for (i = k + 1; i < n; ++i) A[(size_t)i * ld + (size_t)j] -= w * A[(size_t)i * ld + (size_t)k];
        }
    }
    return kmax;
}

/* N (n x nr, ld nr, nr = n - r) = H_0 ... H_{r-1} [0; I]: the last nr
   columns of Q of vlbe__lin_qrcp's factor */
VLBE_INLINE void vlbe__lin_basis(int n, int m, int r, const vlbe_real *A, const vlbe_real *tau,
                                 vlbe_real *N)
{
    const int nr = n - r;
    const size_t ld = (size_t)m, ldn = (size_t)nr;
    int k, i, c;
    for (i = 0; i < n; ++i)
        for (c = 0; c < nr; ++c) N[(size_t)i * ldn + (size_t)c] = i == r + c ? VLBE_R(1.0) : VLBE_R(0.0);
    for (k = r - 1; k >= 0; --k)
        for (c = 0; c < nr; ++c) {
            vlbe_real w = N[(size_t)k * ldn + (size_t)c];
            for (i = k + 1; i < n; ++i) w += A[(size_t)i * ld + (size_t)k] * N[(size_t)i * ldn + (size_t)c];
            w *= tau[k];
            N[(size_t)k * ldn + (size_t)c] -= w;
            for (i = k + 1; i < n; ++i) N[(size_t)i * ldn + (size_t)c] -= w * A[(size_t)i * ld + (size_t)k];
        }
}

/* X (n x n) <- N^T X N (nr x nr, ld nr) in place; T: n nr reals of scratch */
VLBE_INLINE void vlbe__lin_reduce(int n, int nr, const vlbe_real *N, vlbe_real *X, vlbe_real *T)
{
    const size_t ln = (size_t)nr, lx = (size_t)n;
    int i, j, k;
    for (i = 0; i < n; ++i)
        for (j = 0; j < nr; ++j) {
            vlbe_real s = VLBE_R(0.0);
            for (k = 0; k < n; ++k) s += X[(size_t)i * lx + (size_t)k] * N[(size_t)k * ln + (size_t)j];
            T[(size_t)i * ln + (size_t)j] = s;
        }
    for (i = 0; i < nr; ++i)
        for (j = 0; j < nr; ++j) {
            vlbe_real s = VLBE_R(0.0);
            for (k = 0; k < n; ++k) s += N[(size_t)k * ln + (size_t)i] * T[(size_t)k * ln + (size_t)j];
            X[(size_t)i * ln + (size_t)j] = s;
        }
}

/* the dense n x n matrix X of a model band B (augmented order; rows and
   columns of q only) */
VLBE_INLINE void vlbe__lin_unband(const vlbe_dae *s, const vlbe_real *B, vlbe_real *X)
{
    const int n = s->n, ld = vlbe__dae_bld(s);
    int i, j;
    for (i = 0; i < n; ++i)
        for (j = 0; j < n; ++j) {
            const int oi = s->order[i], oj = s->order[j];
            X[(size_t)i * (size_t)n + (size_t)j] =
                (oj - oi <= s->ku && oi - oj <= s->kl) ? B[VLBE_BAND_IDX(ld, s->kl, oi, oj)]
                                                       : VLBE_R(0.0);
        }
}

/* a frame of valid dimension and finite angular velocity, nvec >= 0 with
   the indices given */
VLBE_INLINE int vlbe__lin_frame_ok(const vlbe_lin_frame *f)
{
    return (f->dim == 2 || f->dim == 3) && f->nvec >= 0 && (f->nvec == 0 || f->vec) &&
           isfinite(f->omega[0]) && isfinite(f->omega[1]) && isfinite(f->omega[2]);
}

/* 1 when the frame's vectors lie inside q (n coordinates) and none
   overlaps another (marks in mark[0..n-1]) */
VLBE_INLINE int vlbe__lin_frame_vecs(int n, const vlbe_lin_frame *f, int *mark)
{
    int i, j, k;
    for (i = 0; i < n; ++i) mark[i] = 0;
    for (k = 0; k < f->nvec; ++k) {
        const int o = f->vec[k];
        if (o < 0 || o > n - f->dim) return 0;
        for (j = o; j < o + f->dim; ++j) {
            if (mark[j]) return 0;
            mark[j] = 1;
        }
    }
    return 1;
}

/* A = C_q^T (n x m, row-major) from C_q as the constraint Jacobian
   callback wrote it: dense m x n, or its rows in the band of the augmented
   order */
VLBE_INLINE void vlbe__lin_cqt(const vlbe_dae *sys, const vlbe_real *Cq, vlbe_real *A)
{
    const int n = sys->n, m = sys->m, band = vlbe__dae_banded(sys);
    int j, k;
    for (k = 0; k < m; ++k)
        for (j = 0; j < n; ++j) {
            vlbe_real x;
            if (band) {
                const int ok = sys->order[n + k], oj = sys->order[j];
                x = (oj - ok <= sys->ku && ok - oj <= sys->kl)
                        ? Cq[VLBE_BAND_IDX(vlbe__dae_bld(sys), sys->kl, ok, oj)]
                        : VLBE_R(0.0);
            } else {
                x = Cq[(size_t)k * (size_t)n + (size_t)j];
            }
            A[(size_t)j * (size_t)m + (size_t)k] = x;
        }
}

VLBE_API vlbe_status vlbe_dae_linearize(const vlbe_dae *sys, vlbe_real t, const vlbe_real *q,
                                        const vlbe_real *v, const vlbe_real *a,
                                        const vlbe_real *lambda, const vlbe_lin_frame *frame,
                                        int *nr, vlbe_real *N, vlbe_real *Mr, vlbe_real *Dr,
                                        vlbe_real *Kr, vlbe_dae_stats *stats, vlbe_real *work,
                                        size_t work_len, int *iwork, size_t iwork_len)
{
    int n, m, r, nred, band, rot;
    size_t nn, e;
    vlbe_real *M, *K, *D, *T, *Nb, *Q, *A, *tau, *cn, *scr, *Mb = NULL, *Kb = NULL, *Db = NULL,
              *Cqb = NULL;
    int *inv = NULL;
    vlbe__dae_blk bk, bd;
    vlbe_dae sl;
    vlbe_dae_stats dummy;
    vlbe_status rc;
    if (!sys || vlbe_dae_check(sys) != VLBE_OK) return VLBE_EARG;
    n = sys->n;
    m = sys->m;
    if (n > VLBE__LIN_NMAX || !isfinite(t) || !q || !v || !a || (m > 0 && !lambda) || !nr ||
        !Mr || !Dr || !Kr)
        return VLBE_EARG;
    if (frame && !vlbe__lin_frame_ok(frame)) return VLBE_EARG;
    rot = frame && frame->nvec > 0;
    if (!work || !iwork || work_len < vlbe_dae_lin_work_len_sys(sys) ||
        iwork_len < vlbe_dae_lin_iwork_len_sys(sys))
        return VLBE_EWORK;
    if (rot && !vlbe__lin_frame_vecs(n, frame, iwork)) return VLBE_EARG;
    band = vlbe__dae_banded(sys);
    if (band) {
        inv = iwork + n;
        if (vlbe__dae_inv(sys, inv) != VLBE_OK) return VLBE_EARG;
    }
    if (!vlbe_all_finite(q, n) || !vlbe_all_finite(v, n) || !vlbe_all_finite(a, n) ||
        (m > 0 && !vlbe_all_finite(lambda, m)))
        return VLBE_ENONFINITE;
    if (!stats) {
        stats = &dummy;
        vlbe__dae_stats_zero(&dummy);
    }
    nn = (size_t)n * (size_t)n;
    M = work;
    K = M + nn;
    D = K + nn;
    T = D + nn;
    Nb = T + nn;
    Q = Nb + nn;
    A = Q + n;
    tau = A + (size_t)n * (size_t)m;
    cn = tau + m;
    scr = cn + m;
    if (band) {
        Mb = scr + vlbe__dae_btangent_len(sys);
        Kb = Mb + vlbe__dae_mlen(sys, 0);
        Db = Kb + vlbe__dae_mlen(sys, 0);
        Cqb = Db + vlbe__dae_mlen(sys, 0);
    }
    /* the constraint term is physics here (see above) */
    sl = *sys;
    sl.flags &= ~VLBE_DAE_NO_CHESS;
    /* M, Q, C_q (dense C_q into T, m x n, then C_q^T into A) */
    if ((rc = vlbe__dae_mass(&sl, stats, t, q, v, band ? Mb : M)) != VLBE_OK) return rc;
    if ((rc = vlbe__dae_force(&sl, stats, t, q, v, Q)) != VLBE_OK) return rc;
    if ((rc = vlbe__dae_cjac(&sl, stats, t, q, band ? Cqb : T, NULL)) != VLBE_OK) return rc;
    if (!vlbe_all_finite(Q, n)) return VLBE_ENONFINITE;
    vlbe__lin_cqt(sys, band ? Cqb : T, A);
    if (!vlbe_all_finite(A, n * m)) return VLBE_ENONFINITE; /* m <= n <= 46340: fits an int */
    if (band) vlbe__lin_unband(sys, Mb, M); /* (only the entries inside the matrix are read) */
    if (!vlbe__mat_finite(n, M)) return VLBE_ENONFINITE;
    /* K = -dQ/dq + d(M a)/dq + d(C_q^T lambda)/dq, D = -dQ/dv + d(M a)/dv */
    if (band) {
        const size_t ml = vlbe__dae_mlen(sys, 0);
        for (e = 0; e < ml; ++e) Kb[e] = Db[e] = VLBE_R(0.0);
        bk.A = Kb;
        bd.A = Db;
        bk.ld = bd.ld = (size_t)vlbe__dae_bld(sys);
        bk.kl = bd.kl = sys->kl;
        bk.f = bd.f = 1;
        bk.ro = bk.co = bd.ro = bd.co = 0;
    } else {
        for (e = 0; e < nn; ++e) K[e] = D[e] = VLBE_R(0.0);
        bk = vlbe__dae_dblk(K, n, 0);
        bd = vlbe__dae_dblk(D, n, 0);
    }
    rc = vlbe__dae_btangent(&sl, stats, t, q, v, a, m > 0 ? lambda : NULL, Q, band ? Mb : M,
                            VLBE_R(1.0), &bk, VLBE_R(1.0), &bd, inv, scr);
    if (rc != VLBE_OK) return rc;
    if (band) {
        vlbe__lin_unband(sys, Kb, K);
        vlbe__lin_unband(sys, Db, D);
    }
    if (!vlbe__mat_finite(n, K) || !vlbe__mat_finite(n, D)) return VLBE_ENONFINITE;
    /* the rotating frame: D~ = D + 2 M G, K~ = K + M G^2 + D G */
    if (rot) {
        for (e = 0; e < nn; ++e) T[e] = VLBE_R(0.0);
        vlbe__lin_xg(n, frame, VLBE_R(1.0), M, T); /* T = M G */
        vlbe__lin_xg(n, frame, VLBE_R(1.0), T, K); /* K += M G^2 */
        vlbe__lin_xg(n, frame, VLBE_R(1.0), D, K); /* K += D G */
        for (e = 0; e < nn; ++e) D[e] += VLBE_R(2.0) * T[e];
    }
    /* N: null space of C_q from the QR of C_q^T */
    r = m > 0 ? vlbe__lin_qrcp(n, m, A, tau, cn, iwork) : 0;
    nred = n - r;
    vlbe__lin_basis(n, m, r, A, tau, Nb);
    if (nred > 0) {
        vlbe__lin_reduce(n, nred, Nb, M, T);
        vlbe__lin_reduce(n, nred, Nb, D, T);
        vlbe__lin_reduce(n, nred, Nb, K, T);
        e = (size_t)nred * (size_t)nred;
        if (!vlbe__mat_finite(nred, M) || !vlbe__mat_finite(nred, D) ||
            !vlbe__mat_finite(nred, K))
            return VLBE_ENONFINITE;
        vlbe_vec_copy((int)e, M, Mr);
        vlbe_vec_copy((int)e, D, Dr);
        vlbe_vec_copy((int)e, K, Kr);
        if (N) vlbe_vec_copy((int)((size_t)n * (size_t)nred), Nb, N);
    }
    *nr = nred;
    return VLBE_OK;
}

/* ===== static equilibrium ================================================ */
/* Newton's method with a backtracking line search on
       Psi(q, lambda) = ( C_q(t,q)^T lambda - Q(t,q,0),  C(t,q) ) = 0,
   the equations of motion with q' = q'' = 0 (M is never called).  The
   iteration matrix is dPsi/d(q, lambda) = [ -K + H, C_q^T; C_q, 0 ],
   K = dQ/dq, H = d(C_q^T lambda)/dq, formed by vlbe__dae_btangent (the
   integrators' helper: force_jac or forward differences for K, constr_hess
   or forward differences for H, H dropped under VLBE_DAE_NO_CHESS).  The
   constraint rows and multiplier columns are scaled by
   s = max|-K + H| / max|C_q| (a symmetric scaling: the LU's relative pivot
   test then sees blocks of the same size whatever the units), and then
   every row is equilibrated (vlbe__dae_equil), as in the integrators. */

/* Defaults: ftol 0 (off), rtol 1e-10, atol 1e-12 (float: VLBE_TOL_DEFAULT),
   50 iterations, up to 5 halvings of a step, a watchdog of 4 iterations
   (the smallest that lets plain Newton through on every load step of
   bench/bench_static.c: the 64-element co-rotational cantilever in steps
   of k = 2 needs 4). */
VLBE_API void vlbe_static_params_default(vlbe_static_params *p)
{
    if (!p) return;
    p->ftol = VLBE_R(0.0);
    p->rtol = VLBE_TOL_DEFAULT(VLBE_R(1e-10), VLBE_RTOL_EPS);
    p->atol = VLBE_TOL_DEFAULT(VLBE_R(1e-12), VLBE_ATOL_EPS);
    p->max_iter = 50;
    p->max_halvings = 5;
    p->watchdog = 4;
}

/* Workspace layout (reals), N = n + m: x = (q, lambda), trial x, Psi at x,
   Psi at the trial, Newton step (5 N); zero velocity, Q at x, Q at the trial
   (3 n); C_q at x and at the trial (2 m n); iteration matrix (N*N);
   Jacobian scratch (vlbe__dae_tangent_len).  Banded: C_q and the iteration
   matrix as bands, then the step and product vectors in the band's order
   (3 N). */
VLBE_API size_t vlbe_static_work_len(int n, int m)
{
    const vlbe_dae d = vlbe__dae_dense(n, m);
    return vlbe_static_work_len_sys(&d);
}
VLBE_API size_t vlbe_static_iwork_len(int n, int m) { return (size_t)n + (size_t)m; }
VLBE_API size_t vlbe_static_work_len_sys(const vlbe_dae *sys)
{
    size_t N;
    VLBE_ASSERT(sys != NULL);
    N = (size_t)sys->n + (size_t)sys->m;
    return 5 * N + 3 * (size_t)sys->n + 2 * vlbe__dae_mlen(sys, 1) + vlbe__dae_alen(sys, 1) +
           vlbe__dae_btangent_len(sys) + (vlbe__dae_banded(sys) ? 3 * N : 0);
}
VLBE_API size_t vlbe_static_iwork_len_sys(const vlbe_dae *sys)
{
    VLBE_ASSERT(sys != NULL);
    return vlbe_static_iwork_len(sys->n, sys->m) + vlbe__dae_ilen(sys);
}

/* Psi = (C_q^T lambda - Q, C) at x = (q, lambda), v = z = 0; leaves Q(t,q,0)
   in Q and C_q in Cq.  pw: scratch of a banded problem (2 (n + m)). */
VLBE_INLINE vlbe_status vlbe__static_resid(const vlbe_dae *s, vlbe_dae_stats *c, vlbe_real t,
                                        const vlbe_real *x, const vlbe_real *z, vlbe_real *Q,
                                        vlbe_real *Cq, vlbe_real *F, vlbe_real *pw)
{
    int n = s->n, m = s->m, i;
    vlbe_status rc;
    if ((rc = vlbe__dae_force(s, c, t, x, z, Q)) != VLBE_OK) return rc;
    if ((rc = vlbe__dae_cjac(s, c, t, x, Cq, NULL)) != VLBE_OK) return rc;
    if ((rc = vlbe__dae_constr(s, c, t, x, F + n)) != VLBE_OK) return rc;
    if (vlbe__dae_banded(s)) vlbe__dae_bprod(s, 2, Cq, x + n, F, pw); /* pw: 2 (n+m) */
    else vlbe_mat_tvec(m, n, Cq, x + n, F);
    for (i = 0; i < n; ++i) F[i] -= Q[i];
    return VLBE_OK;
}

/* What the static solver's Newton step needs besides the iterate: the
   problem (sys: storage; sl: with M constant), the counters, the time, the
   sizes and the workspace it solves in. */
typedef struct vlbe__static_ws {
    const vlbe_dae *sys, *sl;
    vlbe_dae_stats *stats;
    vlbe_real t;
    int n, m, N, band;
    size_t NN;
    vlbe_real *z, *A, *scr, *X;
    int *inv, *iwork;
} vlbe__static_ws;

/* The Newton step d at x (lambda in x + n, Q, Cq, F of vlbe__static_resid
   there) from the iteration matrix [-K + H, s C_q^T; s C_q, 0], s = *sc
   the ratio of the largest stiffness and constraint entries (1 if either
   is 0 or not finite), and the line search's merit ||(Psi_q, s Psi_c)||
   of F: the constraint rows in the units of force like the matrix (with C
   in its own units a metre of gap would weigh as a newton).  *sc and
   *merit are set whatever the status. */
VLBE_INLINE vlbe_status vlbe__static_newton(const vlbe__static_ws *w, const vlbe_real *x,
                                            const vlbe_real *Q, const vlbe_real *Cq,
                                            const vlbe_real *F, vlbe_real *d, vlbe_real *sc,
                                            vlbe_real *merit)
{
    const vlbe_dae *sys = w->sys;
    const int n = w->n, m = w->m, N = w->N;
    vlbe_real *A = w->A, kmax, cmax;
    vlbe_status rc;
    size_t e;
    int i;
    for (e = 0; e < w->NN; ++e) A[e] = VLBE_R(0.0);
    {
        const vlbe__dae_blk B = w->band ? vlbe__dae_band_blk(sys, A, 1) : vlbe__dae_dblk(A, N, 0);
        rc = vlbe__dae_btangent(w->sl, w->stats, w->t, x, w->z, w->z, x + n, Q, NULL, VLBE_R(1.0),
                                &B, VLBE_R(0.0), NULL, w->inv, w->scr);
        kmax = vlbe_vec_norm_inf((int)w->NN, A); /* only the q block is filled yet */
        cmax = vlbe_vec_norm_inf((int)vlbe__dae_mlen(sys, 1), Cq);
        *sc = (kmax > VLBE_R(0.0) && cmax > VLBE_R(0.0) && isfinite(kmax) && isfinite(cmax))
                  ? kmax / cmax
                  : VLBE_R(1.0);
        if (rc == VLBE_OK) vlbe__dae_bsaddle(sys, &B, *sc, Cq);
    }
    *merit = vlbe__dae_hypot(vlbe_vec_norm2(n, F), *sc * vlbe_vec_norm2(m, F + n));
    if (rc != VLBE_OK) return rc;
    for (i = 0; i < n; ++i) d[i] = -F[i];
    for (i = 0; i < m; ++i) d[n + i] = -*sc * F[n + i];
    if (w->band) {
        vlbe__dae_perm(sys, 1, d, w->X);
        vlbe__dae_equil(N, A, vlbe__dae_ald(sys, 1), (int)vlbe__dae_ald(sys, 1), NULL, w->X);
    } else {
        vlbe__dae_equil(N, A, (size_t)N, N, NULL, d);
    }
    ++w->stats->lu_factors;
    /* reports a non-finite matrix itself (VLBE_ENONFINITE) */
    if ((rc = vlbe__dae_factor(sys, w->stats, 1, A, w->iwork)) != VLBE_OK) return rc;
    ++w->stats->lu_solves;
    ++w->stats->newton_iters;
    if (w->band) {
        vlbe__dae_solve(sys, 1, A, w->iwork, w->X);
        vlbe__dae_unperm(sys, 1, w->X, d);
    } else {
        vlbe__dae_solve(sys, 1, A, w->iwork, d);
    }
    for (i = 0; i < m; ++i) d[n + i] *= *sc;
    return vlbe_all_finite(d, N) ? VLBE_OK : VLBE_ENONFINITE;
}

/* The increment test of vlbe_static_params on the full step d from x: 1
   when |d_i| <= atol + rtol |x_i + d_i| for every i, or max|d| <= 8 eps
   max|x + d| (the rounding floor) */
VLBE_INLINE int vlbe__static_inc_ok(const vlbe_static_params *par, int n, const vlbe_real *x,
                                    const vlbe_real *d)
{
    vlbe_real dmax = VLBE_R(0.0), qmax = VLBE_R(0.0);
    int i, ok = 1;
    for (i = 0; i < n; ++i) {
        vlbe_real qi = vlbe_fabs(x[i] + d[i]), di = vlbe_fabs(d[i]);
        if (di > par->atol + par->rtol * qi) ok = 0;
        if (di > dmax) dmax = di;
        if (qi > qmax) qmax = qi;
    }
    if (dmax <= VLBE_R(8.0) * VLBE_EPS * qmax) ok = 1; /* rounding floor */
    return ok;
}

/* The parameters of vlbe_dae_static in range (see vlbe_static_params) */
VLBE_INLINE int vlbe__static_par_ok(const vlbe_static_params *par)
{
    return par->rtol >= VLBE_R(0.0) && par->atol >= VLBE_R(0.0) && par->ftol >= VLBE_R(0.0) &&
           isfinite(par->rtol) && isfinite(par->atol) && isfinite(par->ftol) &&
           par->rtol + par->atol + par->ftol > VLBE_R(0.0) && par->max_iter >= 1 &&
           par->max_iter <= VLBE_INT_MAX_ITER && par->max_halvings >= 0 &&
           par->max_halvings <= 50 && par->watchdog >= 0 && par->watchdog <= VLBE_INT_MAX_ITER;
}

/* Solves Q(t,q,0) - C_q^T lambda = 0, C(t,q) = 0 for q and lambda, from the
   given q and lambda (both in/out; lambda may be NULL when m = 0).  Newton
   step d from [-K + H, C_q^T; C_q, 0] d = -Psi, in two phases.
   Watchdog phase (par->watchdog > 0 and par->max_halvings > 0): the
   watchdog of Chamberlain et al. with its checkpoint at the start.  Full
   Newton steps, whatever the merit does, as long as the iteration makes
   progress: at every iteration the merit ||(Psi_q, s Psi_c)||_2 (below)
   or the norm of the step's q part ||d_q||_2 below every one before.
   par->watchdog iterations in a row without progress, or at any iterate
   but the start a singular or non-finite iteration matrix or step, or a
   Jacobian or a full step outside the domain or non-finite, send the
   iteration back to the caller's q and lambda, where the backtracking
   phase starts with max_iter iterations of its own.  Why: neither the
   residual nor the step is monotone along a converging Newton iteration
   of a slender structure.  In a co-rotational cantilever (EA L^2/EI =
   4e6) under a tip load, each load step's first Newton step rotates the
   elements and their linearised kinematics stretch them: the axial
   residual, ~EA theta^2 / 2, exceeds the load's by 10^5; the next step
   removes it, and the following ones trade axial against bending residual
   by factors of 10 to 100 while the iterates converge.  Backtracking from
   the first iteration rejects those full steps and accepts short ones
   (1/8 to 1/32 of the step) that lower the merit a little: 2 to 3 times
   the iterations of plain Newton, or VLBE_ENOCONV at max_iter
   (bench/bench_static.c, docs/benchmarks.md).  A Newton iteration that
   diverges or cycles ceases to make progress: it costs the watched
   iterations, and the backtracking phase then takes exactly the steps it
   takes with watchdog = 0.
   Backtracking phase (from the start when par->watchdog = 0; none when
   par->max_halvings = 0: plain Newton throughout): trial points
   x + alpha d, alpha = 1, 1/2, ... (par->max_halvings halvings): a trial
   is accepted when the merit ||(Psi_q, s Psi_c)||_2 decreases (s: the
   scaling of the constraint rows above, so that a gap in C weighs as the
   force that closes it), or at alpha = 1 when d passes the increment
   test.  A callback returning > 0 or a non-finite Psi at a trial point
   counts as no decrease.  When no trial lowers the merit but the full
   step lies inside the domain, the full step is taken (the beam's first
   step above), and max_iter still bounds a divergence.  Otherwise, when
   no halving is left, the call fails with the status of the last trial
   (VLBE_ECALLBACK: outside the domain, VLBE_ENONFINITE).  A full step
   from the start that lies outside the domain or is non-finite ends the
   watchdog phase at once: its halvings are the backtracking phase's
   first iteration.  Convergence (in either phase): see
   vlbe_static_params.
   Returns VLBE_OK; VLBE_EARG (problem, parameters, t, NULL pointers);
   VLBE_EWORK; VLBE_ENONFINITE (start, Psi at the start, iteration matrix,
   step; the last two not at a watched iterate); VLBE_ECALLBACK (a
   callback < 0 anywhere, != 0 at the start or in a Jacobian but at a
   watched iterate, > 0 at the last trial point of a line search);
   VLBE_ESINGULAR (iteration matrix, not at a watched iterate: e.g. a
   structure free to move, or K = 0 with lambda = 0 on a curved
   constraint); VLBE_ENOCONV (max_iter iterations in a phase, or no
   decrease along the step).  On failure q and lambda are as they were.
   stats (may be NULL) is added to, not reset: newton_iters, jac_evals,
   lu_factors, lu_solves, force_calls, constr_calls count as in the
   integrators (the watched iterations included, and the residual at the
   start evaluated again after them); rejected counts rejected trial
   points and returns to the start (one each), newton_fails the
   VLBE_ENOCONV returns, steps the solutions (one per successful call);
   callback_rc holds the last failing callback value (also one backtracked
   or returned from).
   Load stepping (and tracing a path past a limit point with a prescribed
   displacement written as a constraint) is the caller's job: scale the load
   or move the prescribed value in the user data, call again from the last
   solution.
   References: R. Chamberlain, M. Powell, C. Lemarechal, H. Pedersen, The
   watchdog technique for forcing convergence in algorithms for
   constrained optimization, Math. Programming Study 16 (1982) 1-17.
   Measured against it and dropped (docs/benchmarks.md): the non-monotone
   test of L. Grippo, F. Lampariello, S. Lucidi, SIAM J. Numer. Anal. 23
   (1986) 707-716, on the merit with a memory of 5 or 10 iterations (in a
   small load step's first iteration a short step lowers the merit: 20 to
   33 % more iterations than plain Newton in steps of k = 0.1); the natural
   monotonicity test of P. Deuflhard, Newton Methods for Nonlinear
   Problems, Springer 2004, sec. 3.3 (with the Jacobian of the straight
   beam, the residual after the first full step maps to a correction 10^4
   times that step: 3 times the iterations of plain Newton, or
   VLBE_ENOCONV).
   Implementation, about 180 lines: one Newton iteration in two phases,
   whose state (the iterate and the trial point swapped in place, the
   merit and its scale, the watchdog's records, the phase's first
   iteration) every part of the loop shares; what needs none of it is in
   helpers (vlbe__static_par_ok, _resid, _newton, _inc_ok). */
VLBE_API vlbe_status vlbe_dae_static(const vlbe_dae *sys, const vlbe_static_params *par,
                                     vlbe_real t, vlbe_real *q, vlbe_real *lambda,
                                     vlbe_dae_stats *stats, vlbe_real *work, size_t work_len,
                                     int *iwork, size_t iwork_len)
{
    int n, m, N, i, it, it0 = 0, k, inc_on, inc_ok, band, watch, stall = 0;
    size_t NN;
    vlbe_real *x, *xt, *F, *Ft, *d, *z, *Q, *Qt, *Cq, *Cqt, *A, *scr, *tmp, *pw = NULL,
              *X = NULL;
    int *inv = NULL;
    vlbe_real fnorm, sc = VLBE_R(1.0), merit = VLBE_R(0.0), wm = VLBE_R(0.0), ws = VLBE_R(0.0);
    vlbe__static_ws w;
    vlbe_dae sl;
    vlbe_dae_stats dummy;
    vlbe_status rc;
    if (!sys || (rc = vlbe__dae_check(sys, 0)) != VLBE_OK) return VLBE_EARG;
    n = sys->n;
    m = sys->m;
    N = n + m;
    NN = (size_t)N * (size_t)N;
    if (!par || !q || (m > 0 && !lambda) || !isfinite(t)) return VLBE_EARG;
    if (!vlbe__static_par_ok(par)) return VLBE_EARG;
    if (!work || !iwork || work_len < vlbe_static_work_len_sys(sys) ||
        iwork_len < vlbe_static_iwork_len_sys(sys))
        return VLBE_EWORK;
    if (!vlbe_all_finite(q, n) || (m > 0 && !vlbe_all_finite(lambda, m))) return VLBE_ENONFINITE;
    band = vlbe__dae_banded(sys);
    if (band) {
        inv = iwork + N;
        if ((rc = vlbe__dae_inv(sys, inv)) != VLBE_OK) return rc;
        NN = vlbe__dae_alen(sys, 1);
    }
    if (!stats) {
        stats = &dummy;
        vlbe__dae_stats_zero(&dummy);
    }
    x = work;
    xt = x + N;
    F = xt + N;
    Ft = F + N;
    d = Ft + N;
    z = d + N;
    Q = z + n;
    Qt = Q + n;
    Cq = Qt + n;
    Cqt = Cq + vlbe__dae_mlen(sys, 1);
    A = Cqt + vlbe__dae_mlen(sys, 1);
    scr = A + NN;
    if (band) {
        X = scr + vlbe__dae_btangent_len(sys); /* the step in A's order */
        pw = X + N;
    }
    /* M never enters: no dM/dq terms in the tangent */
    sl = *sys;
    sl.flags |= VLBE_DAE_MASS_CONST;
    w.sys = sys;
    w.sl = &sl;
    w.stats = stats;
    w.t = t;
    w.n = n;
    w.m = m;
    w.N = N;
    w.band = band;
    w.NN = NN;
    w.z = z;
    w.A = A;
    w.scr = scr;
    w.X = X;
    w.inv = inv;
    w.iwork = iwork;
    vlbe_vec_zero(n, z);
    vlbe_vec_copy(n, q, x);
    if (m > 0) vlbe_vec_copy(m, lambda, x + n);
    /* the start is the caller's point: no backtracking from it */
    if ((rc = vlbe__static_resid(&sl, stats, t, x, z, Q, Cq, F, pw)) != VLBE_OK) return rc;
    if (!vlbe_all_finite(F, N)) return VLBE_ENONFINITE;
    fnorm = vlbe__dae_psi_norm(n, F, m, F + n); /* residual test, eq. 53 */
    inc_on = par->rtol + par->atol > VLBE_R(0.0);
    inc_ok = !inc_on;
    /* the watchdog phase: full Newton steps from the start (see above) */
    watch = par->max_halvings > 0 && par->watchdog > 0;
    for (it = 0;; ++it) {
        int full_ok = 0, accepted = 0, full_valid = 0, back = 0;
        vlbe_real alpha = VLBE_R(1.0), mt = VLBE_R(0.0);
        vlbe_status last = VLBE_ENOCONV;
        if (inc_ok && (!(par->ftol > VLBE_R(0.0)) || fnorm <= par->ftol)) break;
        if (it - it0 >= par->max_iter) {
            ++stats->newton_fails;
            return VLBE_ENOCONV;
        }
        rc = vlbe__static_newton(&w, x, Q, Cq, F, d, &sc, &merit);
        if (rc != VLBE_OK) {
            /* at a watched iterate a singular or non-finite matrix or step,
               or a point outside the domain, sends the iteration back to
               the start; elsewhere the call fails */
            if (!(watch && it > 0) ||
                !(rc == VLBE_ESINGULAR || rc == VLBE_ENONFINITE ||
                  (rc == VLBE_ECALLBACK && stats->callback_rc > 0)))
                return rc;
            back = 1;
        } else if (watch) {
            /* progress: a merit or a step below every one before */
            vlbe_real sn = vlbe_vec_norm2(n, d);
            if (it == 0 || merit < wm || sn < ws) {
                if (it == 0 || merit < wm) wm = merit;
                if (it == 0 || sn < ws) ws = sn;
                stall = 0;
            } else if (++stall >= par->watchdog) {
                back = 1;
            }
        }
        /* increment test on the full step, at the new point */
        if (inc_on && !back) full_ok = vlbe__static_inc_ok(par, n, x, d);
        /* backtracking line search on the merit (the watchdog phase: the
           full step whatever its merit) */
        for (k = 0; k <= par->max_halvings && !back; ++k) {
            for (i = 0; i < N; ++i) xt[i] = x[i] + alpha * d[i];
            if (!vlbe_all_finite(xt, N)) {
                last = VLBE_ENONFINITE;
            } else if ((rc = vlbe__static_resid(&sl, stats, t, xt, z, Qt, Cqt, Ft, pw)) != VLBE_OK) {
                if (rc != VLBE_ECALLBACK || stats->callback_rc < 0) return rc; /* fatal */
                last = VLBE_ECALLBACK; /* outside the domain: as no decrease */
            } else if (!vlbe_all_finite(Ft, N)) {
                last = VLBE_ENONFINITE;
            } else {
                mt = vlbe__dae_hypot(vlbe_vec_norm2(n, Ft), sc * vlbe_vec_norm2(m, Ft + n));
                if (k == 0) full_valid = 1;
                if (mt < merit || (k == 0 && (full_ok || watch)) || par->max_halvings == 0) {
                    accepted = 1;
                    break;
                }
                last = VLBE_ENOCONV;
            }
            /* a full step that leaves the domain: from a watched iterate
               back to the start, from the start the backtracking */
            if (watch && it > 0) {
                back = 1;
                break;
            }
            watch = 0;
            ++stats->rejected;
            alpha *= VLBE_R(0.5);
        }
        if (back) {
            /* back to the caller's q and lambda; the backtracking search
               takes over from there, with max_iter iterations of its own */
            watch = 0;
            it0 = it + 1;
            ++stats->rejected;
            vlbe_vec_copy(n, q, x);
            if (m > 0) vlbe_vec_copy(m, lambda, x + n);
            if ((rc = vlbe__static_resid(&sl, stats, t, x, z, Q, Cq, F, pw)) != VLBE_OK) return rc;
            fnorm = vlbe__dae_psi_norm(n, F, m, F + n);
            inc_ok = !inc_on;
            continue;
        }
        if (!accepted && last == VLBE_ENOCONV && full_valid) {
            /* every trial was inside the domain but none lowered the
               merit: take the full step (see above) */
            for (i = 0; i < N; ++i) xt[i] = x[i] + d[i];
            if ((rc = vlbe__static_resid(&sl, stats, t, xt, z, Qt, Cqt, Ft, pw)) != VLBE_OK) return rc;
            accepted = 1;
            k = 0;
        }
        if (!accepted) {
            if (last == VLBE_ENOCONV) ++stats->newton_fails;
            return last;
        }
        tmp = x, x = xt, xt = tmp;
        tmp = F, F = Ft, Ft = tmp;
        tmp = Q, Q = Qt, Qt = tmp;
        tmp = Cq, Cq = Cqt, Cqt = tmp;
        fnorm = vlbe__dae_psi_norm(n, F, m, F + n);
        inc_ok = !inc_on || (full_ok && k == 0);
    }
    vlbe_vec_copy(n, x, q);
    if (m > 0) vlbe_vec_copy(m, x + n, lambda);
    ++stats->steps;
    return VLBE_OK;
}

/* ===== generalized-alpha family ========================================= */

VLBE_INLINE void vlbe__hht_defaults(vlbe_hht_params *p)
{
    p->rtol = VLBE_TOL_DEFAULT(VLBE_R(1e-9), VLBE_RTOL_EPS);
    p->atol = VLBE_TOL_DEFAULT(VLBE_R(1e-11), VLBE_ATOL_EPS);
    p->newton_max = 10;
    p->modified = 1;
    p->max_halvings = 0;
    p->reuse_max = 0;
    p->ftol = VLBE_R(0.0);
    p->project = 0;
}

VLBE_API void vlbe_hht_params_newmark(vlbe_hht_params *p, vlbe_real beta, vlbe_real gamma)
{
    VLBE_ASSERT(p != NULL);
    vlbe__hht_defaults(p);
    p->alpha_m = p->alpha_f = VLBE_R(0.0);
    p->beta = beta;
    p->gamma = gamma;
}

/* HHT-alpha (Hilber-Hughes-Taylor) with alpha in [-1/3, 0], expressed in the
   generalized-alpha family: alpha_m = 0, alpha_f = -alpha, gamma = 1/2 - alpha,
   beta = (1 - alpha)^2 / 4.  Spectral radius at infinity (1 + alpha)/(1 - alpha). */
VLBE_API vlbe_status vlbe_hht_params_alpha(vlbe_hht_params *p, vlbe_real alpha)
{
    VLBE_ASSERT(p != NULL);
    if (!(alpha >= -VLBE_R(1.0) / VLBE_R(3.0) && alpha <= VLBE_R(0.0))) return VLBE_EARG;
    vlbe__hht_defaults(p);
    p->alpha_m = VLBE_R(0.0);
    p->alpha_f = -alpha;
    p->gamma = VLBE_R(0.5) - alpha;
    p->beta = VLBE_R(0.25) * (VLBE_R(1.0) - alpha) * (VLBE_R(1.0) - alpha);
    return VLBE_OK;
}

/* Chung-Hulbert generalized-alpha with spectral radius rho_inf in [0, 1]
   (Arnold-Bruls parameters, eq. 10 of their paper):
   alpha_m = (2 rho - 1)/(rho + 1), alpha_f = rho/(rho + 1),
   gamma = 1/2 + alpha_f - alpha_m, beta = (gamma + 1/2)^2 / 4. */
VLBE_API vlbe_status vlbe_hht_params_genalpha(vlbe_hht_params *p, vlbe_real rho_inf)
{
    VLBE_ASSERT(p != NULL);
    if (!(rho_inf >= VLBE_R(0.0) && rho_inf <= VLBE_R(1.0))) return VLBE_EARG;
    vlbe__hht_defaults(p);
    p->alpha_m = (VLBE_R(2.0) * rho_inf - VLBE_R(1.0)) / (rho_inf + VLBE_R(1.0));
    p->alpha_f = rho_inf / (rho_inf + VLBE_R(1.0));
    p->gamma = VLBE_R(0.5) + p->alpha_f - p->alpha_m;
    p->beta = VLBE_R(0.25) * (p->gamma + VLBE_R(0.5)) * (p->gamma + VLBE_R(0.5));
    return VLBE_OK;
}

/* Workspace layout (reals): state q v qdd a (4n) lambda (m); trial q v qdd a
   (4n) lambda (m); backup for halving (4n + m); iteration LU (N*N); rhs (N);
   M (n*n); Q (n); Cq (m*n); C (m); tangent scratch (3n*n + m*n + 3n + m);
   row scales of the LU (N). */
VLBE_API size_t vlbe_hht_work_len(int n, int m)
{
    const vlbe_dae d = vlbe__dae_dense(n, m);
    return vlbe_hht_work_len_sys(&d);
}
VLBE_API size_t vlbe_hht_iwork_len(int n, int m) { return (size_t)n + (size_t)m; }
VLBE_API size_t vlbe_hht_work_len_sys(const vlbe_dae *sys)
{
    size_t n, m, N, a, d;
    VLBE_ASSERT(sys != NULL);
    n = (size_t)sys->n;
    m = (size_t)sys->m;
    N = n + m;
    a = 3 * (4 * n + m) + vlbe__dae_alen(sys, 1) + N + vlbe__dae_mlen(sys, 0) + n +
        vlbe__dae_mlen(sys, 1) + m + vlbe__dae_btangent_len(sys) + N +
        (vlbe__dae_banded(sys) ? 3 * N + n : 0);
    d = 3 * (4 * n + m) + vlbe_dae_work_len_sys(sys); /* the consistent start */
    return a > d ? a : d;
}
VLBE_API size_t vlbe_hht_iwork_len_sys(const vlbe_dae *sys)
{
    VLBE_ASSERT(sys != NULL);
    return vlbe_hht_iwork_len(sys->n, sys->m) + vlbe__dae_ilen(sys);
}

VLBE_INLINE vlbe_real *vlbe__hht_trial(const vlbe_hht *st) { return st->w_; }
VLBE_INLINE vlbe_real *vlbe__hht_backup(const vlbe_hht *st)
{
    return st->w_ + 4 * st->n + st->m;
}
VLBE_INLINE vlbe_real *vlbe__hht_lu(const vlbe_hht *st)
{
    return st->w_ + 2 * (4 * st->n + st->m);
}

/* Parameters of the family: every real finite, alpha_m < 1, alpha_f < 1,
   beta > 0, gamma >= 0; rtol, atol >= 0 with rtol + atol > 0; ftol >= 0;
   newton_max 1..VLBE_INT_MAX_ITER, modified 0 or 1, max_halvings
   0..VLBE_HHT_MAX_HALVINGS, project 0 or 1. */
/* The argument checks of vlbe_hht_init and vlbe_bdf_init, in their order:
   the problem (vlbe_dae_check: VLBE_EARG), both workspaces against the
   method's _sys queries (asked once the problem passed: VLBE_EWORK), the
   method's parameters (pok with the problem's n: VLBE_EARG), t0, q0, v0
   finite (VLBE_ENONFINITE). */
VLBE_INLINE vlbe_status vlbe__dae_init_args(const vlbe_dae *sys, size_t (*lw)(const vlbe_dae *),
                                            size_t (*liw)(const vlbe_dae *),
                                            int (*pok)(const void *par, int n), const void *par,
                                            const vlbe_real *work, size_t work_len,
                                            const int *iwork, size_t iwork_len, vlbe_real t0,
                                            const vlbe_real *q0, const vlbe_real *v0)
{
    vlbe_status rc;
    if ((rc = vlbe_dae_check(sys)) != VLBE_OK) return rc;
    if (!work || !iwork || work_len < lw(sys) || iwork_len < liw(sys)) return VLBE_EWORK;
    if (!pok(par, sys->n)) return VLBE_EARG;
    if (!isfinite(t0) || !vlbe_all_finite(q0, sys->n) || !vlbe_all_finite(v0, sys->n))
        return VLBE_ENONFINITE;
    return VLBE_OK;
}

/* The projected start of both integrators: (q0, v0) copied to (qp, vp) and
   moved onto the constraints by vlbe_dae_project (default tolerance). */
VLBE_INLINE vlbe_status vlbe__dae_init_project(const vlbe_dae *sys, vlbe_real t0,
                                               const vlbe_real *q0, const vlbe_real *v0,
                                               vlbe_real *qp, vlbe_real *vp,
                                               vlbe_dae_stats *stats, vlbe_real *scratch,
                                               size_t scratch_len, int *iwork, size_t iwork_len)
{
    vlbe_vec_copy(sys->n, q0, qp);
    vlbe_vec_copy(sys->n, v0, vp);
    return vlbe_dae_project(sys, t0, qp, vp, VLBE_R(0.0), stats, scratch, scratch_len, iwork,
                            iwork_len);
}

VLBE_INLINE int vlbe__hht_params_ok(const vlbe_hht_params *p)
{
    return isfinite(p->alpha_m) && isfinite(p->alpha_f) && isfinite(p->beta) &&
           isfinite(p->gamma) && isfinite(p->rtol) && isfinite(p->atol) && isfinite(p->ftol) &&
           p->alpha_m < VLBE_R(1.0) && p->alpha_f < VLBE_R(1.0) && p->beta > VLBE_R(0.0) &&
           p->gamma >= VLBE_R(0.0) && p->rtol >= VLBE_R(0.0) && p->atol >= VLBE_R(0.0) &&
           p->rtol + p->atol > VLBE_R(0.0) && p->ftol >= VLBE_R(0.0) && p->newton_max >= 1 &&
           p->newton_max <= VLBE_INT_MAX_ITER && (p->modified == 0 || p->modified == 1) &&
           p->max_halvings >= 0 && p->max_halvings <= VLBE_HHT_MAX_HALVINGS &&
           p->reuse_max >= 0 && p->reuse_max <= VLBE_INT_MAX_ITER &&
           (p->project == 0 || p->project == 1);
}

VLBE_INLINE int vlbe__hht_par_ok(const void *par, int n)
{
    (void)n;
    return vlbe__hht_params_ok((const vlbe_hht_params *)par);
}

/* Consistent start at t0: with par.project = 1, (q0, v0) projected by
   vlbe_dae_project (default tolerance; into the workspace: q0 and v0 are
   never written), then q''_0 and lambda_0 from vlbe_dae_consistent_acc,
   a_0 = q''_0.  Returns VLBE_EARG (problem, parameters: see
   vlbe__hht_params_ok), VLBE_EWORK, VLBE_ENONFINITE (t0, q0, v0, or the
   start solve), the status of the projection when it fails (VLBE_ENOCONV,
   VLBE_ESINGULAR, VLBE_ECALLBACK, VLBE_ENONFINITE: see vlbe_dae_project),
   or the status of the start solve (VLBE_ESINGULAR, VLBE_ECALLBACK).  On
   failure *st is unchanged, and so are work and iwork when the argument
   checks fail; when the projection or the start solve fails, work and
   iwork hold its scratch (unspecified: the solve needs (n+m)^2 reals that
   only work can give), so do not re-initialize into the workspace of a
   state that must survive a failed call. */
VLBE_API vlbe_status vlbe_hht_init(vlbe_hht *st, const vlbe_dae *sys, const vlbe_hht_params *par,
                                   vlbe_real t0, const vlbe_real *q0, const vlbe_real *v0,
                                   vlbe_real *work, size_t work_len, int *iwork,
                                   size_t iwork_len)
{
    int n, m;
    vlbe_status rc;
    vlbe_real *scratch, *tqdd, *tl;
    vlbe_hht s;
    VLBE_ASSERT(st != NULL && par != NULL && q0 != NULL && v0 != NULL);
    rc = vlbe__dae_init_args(sys, vlbe_hht_work_len_sys, vlbe_hht_iwork_len_sys, vlbe__hht_par_ok,
                             par, work, work_len, iwork, iwork_len, t0, q0, v0);
    if (rc != VLBE_OK) return rc;
    n = sys->n;
    m = sys->m;
    s.sys = sys;
    s.par = *par;
    s.n = n;
    s.m = m;
    s.t = t0;
    s.q = work;
    s.v = s.q + n;
    s.qdd = s.v + n;
    s.a = s.qdd + n;
    s.lambda = s.a + n;
    s.w_ = s.lambda + m;
    s.piv_ = iwork;
    s.have_lu_ = 0;
    s.have_m_ = 0;
    s.h_lu_ = VLBE_R(0.0);
    s.t_base_ = t0;
    s.h_run_ = VLBE_R(0.0);
    s.k_run_ = 0;
    vlbe__dae_stats_zero(&s.stats);
    /* consistent q'' and lambda into the trial area (the state area stays
       as it was until the solve succeeded); the scratch after the LU area
       is large enough */
    tqdd = vlbe__hht_trial(&s) + 2 * n;
    tl = vlbe__hht_trial(&s) + 4 * n;
    scratch = vlbe__hht_lu(&s);
    if (par->project && m > 0) { /* the projected copy in the backup area */
        vlbe_real *qp = vlbe__hht_backup(&s), *vp = qp + n;
        rc = vlbe__dae_init_project(sys, t0, q0, v0, qp, vp, &s.stats, scratch,
                                    (size_t)(work + work_len - scratch), iwork, iwork_len);
        if (rc != VLBE_OK) return rc;
        q0 = qp;
        v0 = vp;
    }
    rc = vlbe_dae_consistent_acc(sys, t0, q0, v0, tqdd, tl, &s.stats, scratch,
                                 (size_t)(work + work_len - scratch), iwork, iwork_len);
    if (rc != VLBE_OK) return rc;
    if (q0 != s.q) vlbe_vec_copy(n, q0, s.q); /* a restart may pass the old state */
    if (v0 != s.v) vlbe_vec_copy(n, v0, s.v);
    vlbe_vec_copy(n, tqdd, s.qdd);
    vlbe_vec_copy(n, tqdd, s.a); /* a_0 = q''_0 (Arnold-Bruls) */
    if (m > 0) vlbe_vec_copy(m, tl, s.lambda);
    *st = s;
    return VLBE_OK;
}

/* x^k for a small k >= 0 (cheaper than pow on the Newton path). */
VLBE_INLINE vlbe_real vlbe__dae_powi(vlbe_real x, int k)
{
    vlbe_real r = VLBE_R(1.0);
    for (; k > 0; --k) r *= x;
    return r;
}

/* Weighted RMS norm of x with weights atol + rtol |ref|. */
VLBE_INLINE vlbe_real vlbe__dae_wrms(int n, const vlbe_real *x, const vlbe_real *ref,
                                     vlbe_real rtol, vlbe_real atol)
{
    vlbe_real s = VLBE_R(0.0);
    int i;
    for (i = 0; i < n; ++i) {
        vlbe_real r = x[i] / (atol + rtol * vlbe_fabs(ref[i]));
        s += r * r;
    }
    return vlbe_sqrt(s / (vlbe_real)(n > 0 ? n : 1));
}

/* The residual of an HHT Newton iterate at (t1, tq, tv, tqdd, tl):
   r_q = M q'' + C_q^T lambda - Q, r_c = C / bp (the constraint rows
   scaled like the iteration matrix), with M (unless kept constant), Q,
   C_q and C evaluated there; pw, tmp: banded scratch. */
VLBE_INLINE vlbe_status vlbe__hht_resid(vlbe_hht *st, vlbe_real t1, vlbe_real bp,
                                        const vlbe_real *tq, const vlbe_real *tv,
                                        const vlbe_real *tqdd, const vlbe_real *tl, vlbe_real *M,
                                        vlbe_real *Q, vlbe_real *Cq, vlbe_real *C, vlbe_real *r,
                                        vlbe_real *pw, vlbe_real *tmp)
{
    const vlbe_dae *s = st->sys;
    const int n = st->n, m = st->m;
    int i, j;
    vlbe_status rc;
    if (!st->have_m_) {
        if ((rc = vlbe__dae_mass(s, &st->stats, t1, tq, tv, M)) != VLBE_OK) return rc;
        st->have_m_ = (s->flags & VLBE_DAE_MASS_CONST) != 0; /* constant: kept */
    }
    if ((rc = vlbe__dae_force(s, &st->stats, t1, tq, tv, Q)) != VLBE_OK) return rc;
    if ((rc = vlbe__dae_cjac(s, &st->stats, t1, tq, Cq, NULL)) != VLBE_OK) return rc;
    if ((rc = vlbe__dae_constr(s, &st->stats, t1, tq, C)) != VLBE_OK) return rc;
    if (vlbe__dae_banded(s)) {
        vlbe__dae_bprod(s, 0, M, tqdd, r, pw);
        for (i = 0; i < n; ++i) r[i] -= Q[i];
        if (m > 0) {
            vlbe__dae_bprod(s, 2, Cq, tl, tmp, pw);
            for (i = 0; i < n; ++i) r[i] += tmp[i];
        }
        for (j = 0; j < m; ++j) r[n + j] = C[j] / bp;
    } else {
        vlbe_mat_vec(n, n, M, tqdd, r);
        for (i = 0; i < n; ++i) r[i] -= Q[i];
        for (j = 0; j < m; ++j) {
            vlbe_vec_axpy(n, tl[j], Cq + (size_t)j * n, r);
            r[n + j] = C[j] / bp;
        }
    }
    return vlbe_all_finite(r, n + m) ? VLBE_OK : VLBE_ENONFINITE;
}

/* The HHT iteration matrix [M + bp (Ma + C_q^T l - Q)_q + gp (Ma - Q)_v,
   C_q^T; C_q, 0] at the iterate, its rows equilibrated (scales into rs)
   and factored into LU (pivots in st->piv_); st->have_lu_ and h_lu_ record
   it, a failed factorization drops it. */
VLBE_INLINE vlbe_status vlbe__hht_matrix(vlbe_hht *st, vlbe_real h, vlbe_real t1, vlbe_real bp,
                                         vlbe_real gp, const vlbe_real *tq, const vlbe_real *tv,
                                         const vlbe_real *tqdd, const vlbe_real *tl,
                                         const vlbe_real *Q, const vlbe_real *M,
                                         const vlbe_real *Cq, vlbe_real *LU, vlbe_real *rs,
                                         vlbe_real *scr)
{
    const vlbe_dae *s = st->sys;
    const int n = st->n, m = st->m, N = n + m, band = vlbe__dae_banded(s);
    vlbe__dae_blk B;
    size_t ld = (size_t)N;
    int i, j;
    vlbe_status rc;
    if (band) {
        B = vlbe__dae_band_blk(s, LU, 1);
        ld = B.ld;
        vlbe_vec_zero((int)vlbe__dae_alen(s, 1), LU);
        vlbe__dae_badd(s, &B, VLBE_R(1.0), M, 0);
        vlbe__dae_bsaddle(s, &B, VLBE_R(1.0), Cq);
    } else {
        B = vlbe__dae_dblk(LU, N, 0);
        for (i = 0; i < n; ++i) {
            for (j = 0; j < n; ++j) LU[(size_t)i * N + j] = M[(size_t)i * n + j];
            for (j = 0; j < m; ++j) LU[(size_t)i * N + n + j] = Cq[(size_t)j * n + i];
        }
        for (i = 0; i < m; ++i) {
            for (j = 0; j < n; ++j) LU[(size_t)(n + i) * N + j] = Cq[(size_t)i * n + j];
            for (j = 0; j < m; ++j) LU[(size_t)(n + i) * N + n + j] = VLBE_R(0.0);
        }
    }
    rc = vlbe__dae_btangent(s, &st->stats, t1, tq, tv, tqdd, tl, Q, M, bp, &B, gp, &B,
                            band ? st->piv_ + N : NULL, scr);
    if (rc != VLBE_OK) return rc;
    vlbe__dae_equil(N, LU, ld, band ? (int)ld : N, rs, NULL);
    ++st->stats.lu_factors;
    /* reports a non-finite matrix itself (VLBE_ENONFINITE) */
    rc = vlbe__dae_factor(s, &st->stats, 1, LU, st->piv_);
    if (rc != VLBE_OK) {
        st->have_lu_ = 0;
        return rc;
    }
    st->have_lu_ = 1;
    st->h_lu_ = h;
    return VLBE_OK;
}

/* The predictor of an attempt of size h: q''_{n+1} = q''_n, lambda_{n+1} =
   lambda_n, and from them a (the relation at vlbe_hht_params), q = q_n +
   h v_n + h^2 ((1/2 - beta) a_n + beta a_{n+1}) and v = v_n + h ((1 -
   gamma) a_n + gamma a_{n+1}) (Arnold-Bruls). */
VLBE_INLINE void vlbe__hht_predict(const vlbe_hht *st, vlbe_real h, vlbe_real *tq, vlbe_real *tv,
                                   vlbe_real *tqdd, vlbe_real *ta, vlbe_real *tl)
{
    const vlbe_hht_params *p = &st->par;
    const vlbe_real am = p->alpha_m, af = p->alpha_f;
    int i;
    vlbe_vec_copy(st->n, st->qdd, tqdd);
    if (st->m) vlbe_vec_copy(st->m, st->lambda, tl);
    for (i = 0; i < st->n; ++i) {
        ta[i] = ((VLBE_R(1.0) - af) * tqdd[i] + af * st->qdd[i] - am * st->a[i]) / (VLBE_R(1.0) - am);
        tq[i] = st->q[i] + h * st->v[i] +
                h * h * ((VLBE_R(0.5) - p->beta) * st->a[i] + p->beta * ta[i]);
        tv[i] = st->v[i] + h * ((VLBE_R(1.0) - p->gamma) * st->a[i] + p->gamma * ta[i]);
    }
}

/* One Newton correction: the residual r (N) solved with the factored
   iteration matrix LU (row scaling rs; banded: through X in the matrix's
   order), then q'' -= dx, lambda -= dl and a, q, v along (dq/dq'' = bp,
   dv/dq'' = gp); r[0..n) returns the position increment bp dx, for the
   norm. */
VLBE_INLINE void vlbe__hht_update(vlbe_hht *st, vlbe_real bp, vlbe_real gp, const vlbe_real *LU,
                                  const vlbe_real *rs, vlbe_real *X, vlbe_real *r, vlbe_real *tq,
                                  vlbe_real *tv, vlbe_real *tqdd, vlbe_real *ta, vlbe_real *tl)
{
    const vlbe_dae *s = st->sys;
    const vlbe_real am = st->par.alpha_m, af = st->par.alpha_f;
    const int n = st->n, m = st->m, N = n + m;
    int i, j;
    ++st->stats.lu_solves;
    ++st->stats.newton_iters;
    if (vlbe__dae_banded(s)) {
        vlbe__dae_perm(s, 1, r, X);
        for (i = 0; i < N; ++i) X[i] *= rs[i];
        vlbe__dae_solve(s, 1, LU, st->piv_, X);
        vlbe__dae_unperm(s, 1, X, r);
    } else {
        for (i = 0; i < N; ++i) r[i] *= rs[i];
        vlbe__dae_solve(s, 1, LU, st->piv_, r);
    }
    for (i = 0; i < n; ++i) {
        vlbe_real d = r[i];
        tqdd[i] -= d;
        ta[i] -= d * (VLBE_R(1.0) - af) / (VLBE_R(1.0) - am);
        tq[i] -= bp * d;
        tv[i] -= gp * d;
        r[i] = bp * d; /* position increment, for the norm */
    }
    for (j = 0; j < m; ++j) tl[j] -= r[n + j];
}

/* One attempt of one step of size h from the accepted state at st->t to
   t1 (~ st->t + h, given by the caller without drift) into the trial
   arrays; the accepted state is not touched.  About 150 lines, a third of
   them comments: the Newton loop, whose restarts (a stale matrix, a slow
   contraction, the rounding floor) and residual test (eq. 53) share the
   iteration's state (it, prev, theta, fresh, full, pending); what needs
   none of it is in helpers (vlbe__hht_predict, _resid, _matrix, _update). */
VLBE_INLINE vlbe_status vlbe__hht_attempt(vlbe_hht *st, vlbe_real h, vlbe_real t1)
{
    const vlbe_dae *s = st->sys;
    const vlbe_hht_params *p = &st->par;
    int n = st->n, m = st->m, N = n + m, i, it, fresh, full = !p->modified;
    size_t NN = (size_t)N * (size_t)N;
    vlbe_real *tq = vlbe__hht_trial(st), *tv = tq + n, *tqdd = tv + n, *ta = tqdd + n, *tl = ta + n;
    int band = vlbe__dae_banded(s);
    vlbe_real *LU = vlbe__hht_lu(st), *r = LU + (band ? vlbe__dae_alen(s, 1) : NN), *M = r + N,
              *Q = M + vlbe__dae_mlen(s, 0), *Cq = Q + n, *C = Cq + vlbe__dae_mlen(s, 1),
              *scr = C + m,
              *rs = scr + (band ? vlbe__dae_btangent_len(s) : vlbe__dae_tangent_len(n, m)),
              *X = rs + N, *pw = X + N, *tmp = pw + 2 * N; /* banded only */
    vlbe_real am = p->alpha_m, af = p->alpha_f;
    vlbe_real bp = h * h * p->beta * (VLBE_R(1.0) - af) / (VLBE_R(1.0) - am); /* dq/dq''  */
    vlbe_real gp = h * p->gamma * (VLBE_R(1.0) - af) / (VLBE_R(1.0) - am);    /* dv/dq''  */
    vlbe_real prev = VLBE_R(0.0), theta = VLBE_R(0.0);
    int pending = 0; /* ftol > 0: the increment test passed, the residual is due */
    vlbe_status rc;

    vlbe__hht_predict(st, h, tq, tv, tqdd, ta, tl);
    /* the stored LU belongs to another step size: drop it */
    if (st->have_lu_ && st->h_lu_ != h) st->have_lu_ = 0;
    fresh = 0;
    for (it = 0; it < p->newton_max || pending; ++it) {
        vlbe_real nrm = VLBE_R(0.0), nv, nq = VLBE_R(0.0);
        int conv = 0, left = p->newton_max - 1 - it;
        rc = vlbe__hht_resid(st, t1, bp, tq, tv, tqdd, tl, M, Q, Cq, C, r, pw, tmp);
        if (rc != VLBE_OK) return rc;
        /* residual test (ftol > 0, eq. 53) at an iterate that passed the
           increment test.  If it fails, this residual drives the next
           iteration: with a fresh iteration matrix, if the stored one is
           stale (modified Newton's slow tail would spend the budget on a
           residual its increments no longer see), which gets the full
           budget from this iteration on, as in the refreshes below;
           otherwise within the budget, which the last iteration may
           overrun by this one evaluation. */
        if (pending) {
            if (vlbe__dae_psi_norm(n, r, m, C) <= p->ftol) goto done;
            pending = 0;
            if (!fresh) {
                st->have_lu_ = 0;
                it = 0;
            } else if (it >= p->newton_max) {
                break;
            }
        }
        /* iteration matrix [M + bp (Ma + C_q^T l - Q)_q + gp (Ma - Q)_v, C_q^T; C_q, 0] */
        if (!st->have_lu_ || full) {
            rc = vlbe__hht_matrix(st, h, t1, bp, gp, tq, tv, tqdd, tl, Q, M, Cq, LU, rs, scr);
            if (rc != VLBE_OK) return rc;
            fresh = 1;
            prev = VLBE_R(0.0);
        }
        vlbe__hht_update(st, bp, gp, LU, rs, X, r, tq, tv, tqdd, ta, tl);
        /* the whole trial state q, v, q'', a, lambda (contiguous): a and
           q'' may overflow while q and v stay finite (da/dq'' = (1 -
           alpha_f)/(1 - alpha_m) can be far larger than dq/dq'' = bp) */
        if (!vlbe_all_finite(tq, 4 * n + m)) return VLBE_ENONFINITE;
        if (p->reuse_max > 0 && left > p->reuse_max) left = p->reuse_max;
        /* Convergence is judged on the position and velocity increments
           bp dq'', gp dq'' (the
           multipliers are coupled to it through the same linear solve and
           converge at the same rate), with the contraction estimate theta
           (Hairer-Wanner IV.8): theta/(1-theta) |dx| <= 1 in the weighted norm. */
        /* rounding floor: a position increment of a few ulps of |q| cannot be
           improved on (the velocity increment, gamma/(beta h) times larger,
           may still exceed a tight atol, and in float mode the default rtol is
           below eps): accept rather than stall and report VLBE_ENOCONV.
           This is the index-3 floor: the rounding of C (eps |q|) is divided by
           bp ~ h^2, so q'' carries noise of eps/h^2 that no iteration removes.
           Full Newton ends far below it; modified Newton leaves a bias up to
           that size per step, which sums to O(eps/h^2) over a run: for very
           small steps (pendulum h < 5e-5, Andrews h < 5e-7) use full Newton
           (modified = 0) or BDF, as the work-precision charts show. */
        if (vlbe_vec_norm_inf(n, r) <= VLBE_R(8.0) * VLBE_EPS * vlbe_vec_norm_inf(n, tq)) {
            conv = 1;
        } else {
            nrm = nq = vlbe__dae_wrms(n, r, tq, p->rtol, p->atol);
            for (i = 0; i < n; ++i) r[i] *= gp / bp; /* velocity increment */
            nv = vlbe__dae_wrms(n, r, tv, p->rtol, p->atol);
            if (nv > nrm) nrm = nv;
            if (prev > VLBE_R(0.0)) {
                theta = nrm / prev;
                if (theta >= VLBE_R(0.5)) {
                    /* slow or diverging: a stale LU gets a fresh one */
                    if (!fresh) {
                        st->have_lu_ = 0;
                        prev = VLBE_R(0.0);
                        it = -1; /* the fresh matrix gets the full iteration budget */
                        continue;
                    }
                    /* stalled at the rounding floor: a fresh matrix that
                       no longer contracts while the position increment is
                       within the tolerance sees the rounding of the
                       residual, which no iteration removes (the index-3
                       noise eps/h^2 of q'', larger in long chains, whose
                       conditioning grows with the number of elements; the
                       velocity increment is that noise times gamma/(beta
                       h) and may stay above a tight atol): the iterate is
                       as good as the arithmetic makes it */
                    if (theta >= VLBE_R(0.9) && nq <= VLBE_R(1.0)) {
                        conv = 1;
                    } else if (theta >= VLBE_R(1.0)) {
                        if (full || p->max_halvings > 0) return VLBE_ENOCONV;
                        /* diverging on a matrix of this attempt but of an
                           earlier iterate: the tangent changed along the
                           way (a start far from the solution: in float,
                           the rounding of a stiff axial force, EA eps,
                           makes the consistent start's q'' of the axial
                           coordinates large, the predictor stretches the
                           chain and the geometric stiffness of that
                           stretch leaves with it).  Without halvings the
                           rest of the attempt is full Newton, within the
                           budget; with halvings the smaller step is the
                           remedy (a run that completes is then the same
                           with and without this branch) */
                        full = 1;
                        prev = VLBE_R(0.0);
                        continue;
                    }
                }
                if (conv) {
                    /* the noise floor above */
                } else if (theta / (VLBE_R(1.0) - theta) * nrm <= VLBE_R(1.0)) {
                    conv = 1;
                } else if (!fresh && vlbe__dae_powi(theta, left) / (VLBE_R(1.0) - theta) * nrm >
                                         VLBE_R(1.0)) {
                    /* will it converge within the iterations left (or
                       reuse_max)?  If not, a stale matrix is refreshed now
                       rather than after the budget is spent (bench_scale's
                       chain, reuse_max 2: 4.0-4.4 iterations and 0.2-0.5
                       factorizations per step instead of 5.4-6.1 and
                       0.0-0.4; a Jacobian and band LU cost 3.5 residual
                       evaluations there) */
                    st->have_lu_ = 0;
                    prev = VLBE_R(0.0);
                    it = -1;
                    continue;
                }
            } else if (nrm <= VLBE_R(1e-2)) {
                conv = 1; /* a very small first increment: converged */
            }
        }
        if (conv) {
            if (!(p->ftol > VLBE_R(0.0))) goto done; /* increment test only */
            pending = 1; /* the residual at the new iterate decides */
        }
        prev = nrm;
    }
    return VLBE_ENOCONV;
done:
    return VLBE_OK;
}

VLBE_INLINE void vlbe__hht_copy_state(int n, int m, const vlbe_real *src, vlbe_real *dst)
{
    vlbe_vec_copy(4 * n + m, src, dst);
}

/* Step of size h from st->t to t1, halved on failure down to h /
   2^max_halvings: a failed segment is replaced by its two halves (the
   first ends at its start + half its size, the second at its end), each
   of which may be halved again.  A loop over that binary tree, depth first,
   with the ends of the open segments in end[] and bit l of `second` set
   while the segment of level l is a second half: the stack is the same at
   every depth.  On failure the state is the one before the call. */
VLBE_INLINE vlbe_status vlbe__hht_step_halving(vlbe_hht *st, vlbe_real h, vlbe_real t1)
{
    int n = st->n, m = st->m, depth = st->par.max_halvings, l = 0, k;
    vlbe_real end[VLBE_HHT_MAX_HALVINGS + 1], hs = h, t0 = st->t;
    unsigned long second = 0ul;
    vlbe_real *bk = vlbe__hht_backup(st);
    vlbe_status rc;
    end[0] = t1;
    for (;;) {
        rc = vlbe__hht_attempt(st, hs, end[l]);
        if (rc == VLBE_OK) {
            vlbe__hht_copy_state(n, m, vlbe__hht_trial(st), st->q); /* q v qdd a lambda are contiguous */
            st->t = end[l];
            ++st->stats.steps;
            while (l > 0 && (second >> l & 1ul)) --l; /* climb over finished second halves */
            if (l == 0) return VLBE_OK;
            second |= 1ul << l; /* a finished first half: its sibling ends where the parent does */
            end[l] = end[l - 1];
            for (hs = h, k = 0; k < l; ++k) hs *= VLBE_R(0.5);
            continue;
        }
        if (rc == VLBE_ENOCONV) ++st->stats.newton_fails;
        ++st->stats.rejected;
        st->have_lu_ = 0;
        if (l >= depth || !vlbe__dae_retry(&st->stats, rc)) break;
        if (l == 0) vlbe__hht_copy_state(n, m, st->q, bk);
        ++l;
        second &= ~(1ul << l);
        hs *= VLBE_R(0.5);
        end[l] = st->t + hs;
    }
    if (l > 0) { /* halved: the backup holds the state before the call */
        vlbe__hht_copy_state(n, m, bk, st->q);
        st->t = t0;
    }
    return rc;
}

/* Advances the state by one step of size h > 0 (with halving on Newton
   failure when par.max_halvings > 0).  On failure the state is the one before
   the call and the status says why; a step below h / 2^max_halvings that still
   fails returns its Newton status (VLBE_ENOCONV, VLBE_ESINGULAR, ...).
   h <= 0, NaN or Inf: VLBE_EARG; st->t + h == st->t: VLBE_ESTEP; st->t + h
   overflows: VLBE_ENONFINITE.
   Time: a run of steps of the same h from t_b ends step k at
   t = t_b + k h (one product, no sum of k roundings: |t - (t_b + k h)| is
   a rounding or two of t, whatever k), so a rheonomic constraint is met at
   the time it should be.  A new h (or a t changed by the caller) starts a
   new run from the current t; the halvings inside a step do not. */
/* The step of vlbe_hht_step (h checked), ending at *t_end when t_end is
   given (vlbe_hht_advance's last step); a step that does not end where
   the run's formula puts it starts a new run there. */
VLBE_INLINE vlbe_status vlbe__hht_step_run(vlbe_hht *st, vlbe_real h, const vlbe_real *t_end)
{
    vlbe_real tb, hr, t1;
    long k;
    vlbe_status rc;
    tb = st->t_base_;
    hr = st->h_run_;
    k = st->k_run_;
    /* a new run: other h, t moved by the caller, or k about to lose
       exactness in vlbe_real (float: 2^23 steps) */
    if (h != hr || st->t != tb + (vlbe_real)k * hr || (vlbe_real)(k + 1) * VLBE_EPS >= VLBE_R(1.0)) {
        tb = st->t;
        hr = h;
        k = 0;
    }
    t1 = tb + (vlbe_real)(k + 1) * hr;
    if (!isfinite(t1)) return VLBE_ENONFINITE; /* t + h overflows: nothing evaluated */
    if (t_end && *t_end != t1) {
        t1 = *t_end;
        rc = vlbe__hht_step_halving(st, h, t1);
        if (rc != VLBE_OK) return rc;
        st->t_base_ = t1;
        st->h_run_ = hr;
        st->k_run_ = 0;
        return VLBE_OK;
    }
    rc = vlbe__hht_step_halving(st, h, t1);
    if (rc != VLBE_OK) return rc;
    st->t_base_ = tb;
    st->h_run_ = hr;
    st->k_run_ = k + 1;
    return VLBE_OK;
}

VLBE_API vlbe_status vlbe_hht_step(vlbe_hht *st, vlbe_real h)
{
    VLBE_ASSERT(st != NULL && st->sys != NULL);
    if (!(h > VLBE_R(0.0)) || !isfinite(h)) return VLBE_EARG;
    if (st->t + h == st->t) return VLBE_ESTEP;
    return vlbe__hht_step_run(st, h, NULL);
}

/* Steps from st->t to t_out in k equal steps h = (t_out - t) / k, k the
   smallest count with h <= h_max up to VLBE_RTOL_EPS units of roundoff
   (k = ceil(r (1 - VLBE_RTOL_EPS eps)), r = (t_out - t) / h_max: an
   interval that is a multiple of h_max but for the rounding of its
   operands takes no extra step).  Step j ends at t + j h (vlbe_hht_step's
   time without drift: one product, no sum of roundings; an unbroken run
   of steps of that h goes on), the last one at t_out itself: st->t ==
   t_out bit for bit on return, whatever the rounding of t_out or of h (0.1,
   1/3).  When h_max divides the interval exactly (t_out = t + k h_max in
   vlbe_real) the run is that of k calls of vlbe_hht_step(st, h_max), bit
   for bit.  Each step halves on Newton failure as vlbe_hht_step does.
   t_out == st->t: returns at once.  VLBE_EARG: t_out < st->t or not
   finite, h_max <= 0 or not finite, or more than 1 / (4 eps) steps (2^21
   in float: the step index must stay exact); VLBE_ESTEP: t + h == t.  On
   failure the state is the last accepted step, which may lie past the
   start (st->t says how far the run got): the exception to the failure
   contract that vlbe_bdf_advance makes, for the same reason. */
VLBE_API vlbe_status vlbe_hht_advance(vlbe_hht *st, vlbe_real t_out, vlbe_real h_max)
{
    vlbe_real r, x, h;
    long k, j;
    vlbe_status rc;
    VLBE_ASSERT(st != NULL && st->sys != NULL);
    if (!isfinite(t_out) || !(t_out >= st->t) || !(h_max > VLBE_R(0.0)) || !isfinite(h_max))
        return VLBE_EARG;
    if (t_out == st->t) return VLBE_OK;
    r = (t_out - st->t) / h_max;
    if (!(r < VLBE_R(0.25) / VLBE_EPS)) return VLBE_EARG;
    x = r - VLBE_RTOL_EPS * VLBE_EPS * r;
    k = (long)-vlbe_floor(-x);
    if (k < 1) k = 1;
    h = (t_out - st->t) / (vlbe_real)k;
    if (st->t + h == st->t) return VLBE_ESTEP;
    for (j = 1; j <= k; ++j)
        if ((rc = vlbe__hht_step_run(st, h, j == k ? &t_out : NULL)) != VLBE_OK) return rc;
    return VLBE_OK;
}

/* ===== BDF orders 1..5, variable step and order (GGL index-2 form) ======= */
/* The method is the variable-coefficient, fixed-leading-coefficient BDF in
   modified divided-difference form of DASSL (Brenan, Campbell, Petzold,
   ch. 5): with psi_i = t_{n+1} - t_{n+1-i}, the predictor interpolates the
   last k+1 solution points,
       y_pred = sum_{j=1}^{k+1} phi*_j,   y'_pred = sum_{j=2}^{k+1} gamma_j phi*_j,
   and the corrector solves G(t, y, y') = 0 with
       y' = y'_pred + cj (y - y_pred),   cj = -alpha_s / h,  alpha_s = -sum_{j<=k} 1/j
   (eq. 5.2.8-5.2.13 of the book).  The local error of order k is
   ck |y - y_pred|, and the terms at orders k-2..k+1 (sec. 5.2.2) drive the
   order and step selection; by default their vectors pass through the
   stiff filter of vlbe__bdf_enorm first.  The residual of the GGL form
   (Gear, Gupta, Leimkuhler 1985, eq. 2.6) is
       G_q = q' - v + C_q^T mu,   G_v = M v' + C_q^T lambda - Q,
       G_l = C_q v + C_t,         G_m = C(t, q);
   lambda and mu are algebraic (index 2): they are predicted and corrected
   with the rest and left out of the error test (their local error is not
   O(h^(k+1)); Hairer-Wanner VII.3), but they are in the Newton convergence
   test (scaled by h, as index-2 variables): an unconverged q of size d
   puts an error d / h^2 into lambda, and that noise then spoils the order
   selection through the differences. */

/* Defaults: rtol 1e-6, atol 1e-8 (float: VLBE_TOL_DEFAULT), no atolv, h0,
   h_min, h_max 0 (automatic), order <= 5, 4 Newton iterations, variable
   step, filtered error estimate, projected start. */
VLBE_API void vlbe_bdf_params_default(vlbe_bdf_params *p)
{
    VLBE_ASSERT(p != NULL);
    p->rtol = VLBE_TOL_DEFAULT(VLBE_R(1e-6), VLBE_RTOL_EPS);
    p->atol = VLBE_TOL_DEFAULT(VLBE_R(1e-8), VLBE_ATOL_EPS);
    p->h0 = p->h_min = p->h_max = VLBE_R(0.0);
    p->max_order = VLBE_BDF_MAXORD;
    p->newton_max = 4;
    p->fixed_step = 0;
    p->stiff_filter = 1;
    p->max_steps = 0;
    p->atolv = NULL;
    p->project = 1;
}


/* Size of the backup area of the BDF workspace (see below). */
VLBE_INLINE size_t vlbe__bdf_backup_len(int n, int m)
{
    return (2 * (size_t)n + 2 * (size_t)m) * VLBE_BDF_MAXORD + 5 * (VLBE_BDF_MAXORD + 2);
}

/* Workspace layout (reals), N2 = 2n + 2m: y (N2); phi (MAXORD+1 columns of
   N2); trial y, trial y', e = y - y_pred, delta (4 N2); backup of phi_2 ..
   phi_{MAXORD+1} and of psi, alpha, beta, gamma, sigma, for a failed
   vlbe_bdf_step (MAXORD N2 + 5 (MAXORD+2)); then the tail:
   iteration matrix (N2*N2), M (n*n), Q (n), Cq (m*n), Ct (m), row scales
   of the iteration matrix (N2), scratch. */
VLBE_API size_t vlbe_bdf_work_len(int n, int m)
{
    const vlbe_dae d = vlbe__dae_dense(n, m);
    return vlbe_bdf_work_len_sys(&d);
}
VLBE_API size_t vlbe_bdf_iwork_len(int n, int m) { return 2 * (size_t)n + 2 * (size_t)m; }
/* banded: the tail ends with the vectors of the products in the band's
   order (2 (n+m) + 2 (n+m) + n) */
VLBE_API size_t vlbe_bdf_work_len_sys(const vlbe_dae *sys)
{
    size_t n, m, N2, tail, dae;
    VLBE_ASSERT(sys != NULL);
    n = (size_t)sys->n;
    m = (size_t)sys->m;
    N2 = 2 * n + 2 * m;
    tail = vlbe__dae_alen(sys, 2) + vlbe__dae_mlen(sys, 0) + n + vlbe__dae_mlen(sys, 1) + m + N2 +
           vlbe__dae_btangent_len(sys) + (vlbe__dae_banded(sys) ? 2 * N2 + n : 0);
    dae = vlbe_dae_work_len_sys(sys);
    return N2 * (size_t)(VLBE_BDF_MAXORD + 1 + 5) + vlbe__bdf_backup_len(sys->n, sys->m) +
           (tail > dae ? tail : dae);
}
VLBE_API size_t vlbe_bdf_iwork_len_sys(const vlbe_dae *sys)
{
    VLBE_ASSERT(sys != NULL);
    return vlbe_bdf_iwork_len(sys->n, sys->m) + vlbe__dae_ilen(sys);
}

VLBE_INLINE int vlbe__bdf_n2(const vlbe_bdf *st) { return 2 * st->n + 2 * st->m; }
VLBE_INLINE vlbe_real *vlbe__bdf_phi(const vlbe_bdf *st, int j) /* 1-based column */
{
    return st->phi_ + (size_t)(j - 1) * (size_t)vlbe__bdf_n2(st);
}
/* trial y, trial y', e, delta */
VLBE_INLINE vlbe_real *vlbe__bdf_vec(const vlbe_bdf *st, int i)
{
    return st->w_ + (size_t)i * (size_t)vlbe__bdf_n2(st);
}
VLBE_INLINE vlbe_real *vlbe__bdf_backup(const vlbe_bdf *st) { return vlbe__bdf_vec(st, 4); }
VLBE_INLINE vlbe_real *vlbe__bdf_tail(const vlbe_bdf *st)
{
    return vlbe__bdf_backup(st) + vlbe__bdf_backup_len(st->n, st->m);
}
/* the tail: iteration matrix, then M, Q, Cq, Ct, row scales, scratch, and
   (banded) the vectors in the matrix's order */
VLBE_INLINE vlbe_real *vlbe__bdf_M(const vlbe_bdf *st)
{
    return vlbe__bdf_tail(st) + vlbe__dae_alen(st->sys, 2);
}
VLBE_INLINE vlbe_real *vlbe__bdf_rs(const vlbe_bdf *st)
{
    return vlbe__bdf_M(st) + vlbe__dae_mlen(st->sys, 0) + (size_t)st->n +
           vlbe__dae_mlen(st->sys, 1) + (size_t)st->m;
}
VLBE_INLINE vlbe_real *vlbe__bdf_ext(const vlbe_bdf *st)
{
    return vlbe__bdf_rs(st) + (size_t)vlbe__bdf_n2(st) + vlbe__dae_btangent_len(st->sys);
}

/* Weighted RMS norm of x (nn <= 2n components, q then v) with the
   weights of the error test, atol + rtol |ref_i| (atolv[i] + rtol |ref_i|
   when par.atolv is given). */
VLBE_INLINE vlbe_real vlbe__bdf_wrms(const vlbe_bdf_params *p, int nn, const vlbe_real *x,
                                     const vlbe_real *ref)
{
    vlbe_real s = VLBE_R(0.0);
    int i;
    if (!p->atolv) return vlbe__dae_wrms(nn, x, ref, p->rtol, p->atol);
    for (i = 0; i < nn; ++i) {
        vlbe_real r = x[i] / (p->atolv[i] + p->rtol * vlbe_fabs(ref[i]));
        s += r * r;
    }
    return vlbe_sqrt(s / (vlbe_real)(nn > 0 ? nn : 1));
}

/* Weighted RMS norm of the q and v parts of x (error test); weights from
   the last accepted step. */
VLBE_INLINE vlbe_real vlbe__bdf_norm(const vlbe_bdf *st, const vlbe_real *x)
{
    return vlbe__bdf_wrms(&st->par, 2 * st->n, x, st->q);
}

/* Norm of a Newton correction d: weighted RMS over all 2n + 2m components,
   the index-2 variables lambda and mu scaled by 1/cj ~ h (Hairer-Wanner
   VII.8): they are determined by the iteration only to eps cj (a q
   perturbation of eps|q| moves them by that much), and 1/cj is also how
   the scaled iteration matrix sees them. */
VLBE_INLINE vlbe_real vlbe__bdf_newton_norm(const vlbe_bdf *st, const vlbe_real *d, vlbe_real cj)
{
    int n2 = 2 * st->n, m2 = 2 * st->m;
    vlbe_real a = vlbe__bdf_wrms(&st->par, n2, d, st->q), b;
    if (m2 == 0) return a;
    b = vlbe__dae_wrms(m2, d + n2, st->q + n2, st->par.rtol, st->par.atol) / cj;
    return vlbe_sqrt(((vlbe_real)n2 * a * a + (vlbe_real)m2 * b * b) / (vlbe_real)(n2 + m2));
}

/* vlbe_bdf_params valid for a problem of n coordinates (see vlbe_bdf_init) */
VLBE_INLINE int vlbe__bdf_par_ok(const void *par, int n)
{
    const vlbe_bdf_params *p = (const vlbe_bdf_params *)par;
    int i;
    if (!(p->rtol >= VLBE_R(0.0)) || !(p->atol >= VLBE_R(0.0)) ||
        !(p->rtol + p->atol > VLBE_R(0.0)) || !(p->h0 >= VLBE_R(0.0)) ||
        !(p->h_min >= VLBE_R(0.0)) || !(p->h_max >= VLBE_R(0.0)) || !isfinite(p->rtol) ||
        !isfinite(p->atol) || !isfinite(p->h0) || !isfinite(p->h_min) || !isfinite(p->h_max) ||
        p->max_order < 1 || p->max_order > VLBE_BDF_MAXORD || p->newton_max < 1 ||
        p->newton_max > VLBE_INT_MAX_ITER || p->fixed_step < 0 || p->fixed_step > 1 ||
        p->stiff_filter < 0 || p->stiff_filter > 1 || p->max_steps < 0 || p->project < 0 ||
        p->project > 1 || (p->fixed_step && !(p->h0 > VLBE_R(0.0))) ||
        (p->h_max > VLBE_R(0.0) && p->h_min > p->h_max))
        return 0;
    if (p->atolv)
        for (i = 0; i < 2 * n; ++i)
            if (!(p->atolv[i] >= VLBE_R(0.0)) || !isfinite(p->atolv[i]) ||
                !(p->atolv[i] + p->rtol > VLBE_R(0.0)))
                return 0;
    return 1;
}

/* Consistent start at t0 (see vlbe_bdf).  With par.project (default), a
   copy of (q0, v0) goes through vlbe_dae_project (default tolerance), and
   the run starts from the projected copy when the correction (dq, dv) it
   made exceeds a tenth of the first step's error test, ||(dq, dv)|| > 0.1
   in the weighted RMS norm of the test (weights atol + rtol |y0_i|, or
   atolv): the corrector would make that jump in the first step, and the
   error estimate, which sees it whatever h, could not pass (a jump of a
   tenth leaves the test nine tenths for the step's own error).  Below
   that, and for a start on the constraints (no correction: one constr
   and one constr_jac call), the run starts from (q0, v0) bit for bit as
   without projection.  q0 and v0 themselves are never written.  Returns
   VLBE_EARG (problem, parameters: every real finite and >= 0, rtol + atol
   > 0, atolv as in vlbe_bdf_params, max_order 1..VLBE_BDF_MAXORD,
   newton_max 1..VLBE_INT_MAX_ITER, fixed_step, stiff_filter and project 0
   or 1, max_steps >= 0, h0 > 0 with fixed_step, h_min <= h_max when h_max >
   0), VLBE_EWORK, VLBE_ENONFINITE (t0, q0, v0, or the start solve), the
   status of the projection when it fails (VLBE_ENOCONV: Gauss-Newton did
   not reach the constraints; VLBE_ESINGULAR: C_q rank-deficient at the
   start; VLBE_ECALLBACK, VLBE_ENONFINITE), or the status of the start
   solve.  On failure *st is unchanged, and so are work and iwork when the
   argument checks fail; when the projection or the start solve fails they
   hold its scratch (unspecified), as for vlbe_hht_init. */
VLBE_API vlbe_status vlbe_bdf_init(vlbe_bdf *st, const vlbe_dae *sys, const vlbe_bdf_params *par,
                                   vlbe_real t0, const vlbe_real *q0, const vlbe_real *v0,
                                   vlbe_real *work, size_t work_len, int *iwork,
                                   size_t iwork_len)
{
    int n, m, N2, i;
    vlbe_status rc;
    vlbe_real *tail, *phi2, *phi1, *tq, ypn;
    vlbe_bdf s, *st_out = st;
    VLBE_ASSERT(st != NULL && par != NULL && q0 != NULL && v0 != NULL);
    rc = vlbe__dae_init_args(sys, vlbe_bdf_work_len_sys, vlbe_bdf_iwork_len_sys, vlbe__bdf_par_ok,
                             par, work, work_len, iwork, iwork_len, t0, q0, v0);
    if (rc != VLBE_OK) return rc;
    n = sys->n;
    m = sys->m;
    N2 = 2 * n + 2 * m;
    st = &s; /* built here, copied to *st_out on success */
    st->sys = sys;
    st->par = *par;
    st->n = n;
    st->m = m;
    st->t = t0;
    st->q = work;
    st->v = st->q + n;
    st->lambda = st->v + n;
    st->mu = st->lambda + m;
    st->phi_ = work + N2;
    st->w_ = st->phi_ + (size_t)N2 * (VLBE_BDF_MAXORD + 1);
    st->piv_ = iwork;
    st->t_base_ = t0;
    st->k_run_ = 0;
    vlbe__dae_stats_zero(&st->stats);
    /* y'(t0) = (v0, q''0, 0, 0) into phi_2, with q''0 and lambda0 from the
       consistent-acceleration system (solved into the trial area: the state
       area stays as it was until the solve succeeded); mu0 = 0 */
    phi2 = vlbe__bdf_phi(st, 2);
    tail = vlbe__bdf_tail(st);
    tq = vlbe__bdf_vec(st, 0);
    if (par->project && m > 0) {
        /* projected copy in the trial y' area, its correction in e, the
           caller's y0 = (q0, v0) for the weights in delta */
        vlbe_real *qp = vlbe__bdf_vec(st, 1), *vp = qp + n, *d = vlbe__bdf_vec(st, 2),
                  *y0 = vlbe__bdf_vec(st, 3);
        rc = vlbe__dae_init_project(sys, t0, q0, v0, qp, vp, &st->stats, tail,
                                    (size_t)(work + work_len - tail), iwork, iwork_len);
        if (rc != VLBE_OK) return rc;
        vlbe_vec_copy(n, q0, y0);
        vlbe_vec_copy(n, v0, y0 + n);
        for (i = 0; i < n; ++i) {
            d[i] = qp[i] - q0[i];
            d[n + i] = vp[i] - v0[i];
        }
        if (vlbe__bdf_wrms(par, 2 * n, d, y0) > VLBE_R(0.1)) {
            q0 = qp;
            v0 = vp;
        }
    }
    rc = vlbe_dae_consistent_acc(sys, t0, q0, v0, tq, tq + n, &st->stats, tail,
                                 (size_t)(work + work_len - tail), iwork, iwork_len);
    if (rc != VLBE_OK) return rc;
    if (vlbe__dae_banded(sys)) (void)vlbe__dae_inv(sys, iwork + N2); /* checked by the start */
    if (q0 != st->q) vlbe_vec_copy(n, q0, st->q); /* a restart may pass the old state */
    if (v0 != st->v) vlbe_vec_copy(n, v0, st->v);
    vlbe_vec_copy(n, tq, phi2 + n);
    if (m > 0) vlbe_vec_copy(m, tq + n, st->lambda);
    vlbe_vec_copy(n, v0, phi2);
    for (i = 0; i < 2 * m; ++i) phi2[2 * n + i] = VLBE_R(0.0);
    for (i = 0; i < m; ++i) st->mu[i] = VLBE_R(0.0);
    vlbe_vec_copy(N2, st->q, vlbe__bdf_phi(st, 1));
    phi1 = vlbe__bdf_vec(st, 0);
    /* coefficients: set by the first step; zero until then (a defined,
       comparable state) */
    for (i = 0; i < VLBE_BDF_MAXORD + 2; ++i)
        st->psi_[i] = st->alpha_[i] = st->beta_[i] = st->gamma_[i] = st->sigma_[i] = VLBE_R(0.0);
    /* phi_2 = psi_1 y'(t0): psi_1 = 1 until the first step sets h */
    st->psi_[1] = VLBE_R(1.0);
    /* first step: h0, else from the local error of backward Euler on q,
       h^2/2 |q''| = 1/2 in the weighted norm (DASSL's h |y'| = 1/2 would take
       |v'| = |q''| against atol at a start from rest: absurdly small h);
       without acceleration h |y'| = 1/2; capped by 1e-3 |t_stop - t0| at the
       first step */
    for (i = 0; i < n; ++i) {
        phi1[i] = phi2[n + i]; /* (q'', 0, ..) in the trial-y area */
        phi1[n + i] = VLBE_R(0.0);
    }
    ypn = vlbe__bdf_norm(st, phi1);
    if (par->h0 > VLBE_R(0.0)) st->h = par->h0;
    else if (ypn > VLBE_R(0.0)) st->h = VLBE_R(1.0) / vlbe_sqrt(ypn);
    else {
        ypn = vlbe__bdf_norm(st, phi2);
        st->h = ypn > VLBE_R(0.0) ? VLBE_R(0.5) / ypn : VLBE_REAL_MAX;
    }
    if (par->h_max > VLBE_R(0.0) && st->h > par->h_max) st->h = par->h_max;
    st->h_last = VLBE_R(0.0);
    st->order = 1;
    st->order_last = 0;
    st->hold_ = VLBE_R(0.0);
    st->cj_ = st->cj_lu_ = VLBE_R(0.0);
    st->rate_ = VLBE_R(100.0);
    st->kold_ = 0;
    st->ns_ = 0;
    st->phase_ = 0;
    st->jcalc_ = -1;
    st->have_m_ = 0;
    *st_out = s;
    return VLBE_OK;
}

/* G(t, y, y') of the GGL form into G (N2).  Leaves M, Q, Cq, Ct at (t, y) in
   the workspace tail for the iteration matrix. */
VLBE_INLINE vlbe_status vlbe__bdf_res(vlbe_bdf *st, vlbe_real t, const vlbe_real *y,
                                      const vlbe_real *yp, vlbe_real *G)
{
    const vlbe_dae *s = st->sys;
    int n = st->n, m = st->m, N2 = vlbe__bdf_n2(st), i;
    const vlbe_real *q = y, *v = y + n, *lam = v + n, *mu = lam + m;
    vlbe_real *M = vlbe__bdf_M(st), *Q = M + vlbe__dae_mlen(s, 0), *Cq = Q + n,
              *Ct = Cq + vlbe__dae_mlen(s, 1);
    vlbe_status rc;
    if (!st->have_m_) {
        if ((rc = vlbe__dae_mass(s, &st->stats, t, q, v, M)) != VLBE_OK) return rc;
        st->have_m_ = (s->flags & VLBE_DAE_MASS_CONST) != 0; /* constant: kept */
    }
    if ((rc = vlbe__dae_force(s, &st->stats, t, q, v, Q)) != VLBE_OK) return rc;
    if ((rc = vlbe__dae_cjac(s, &st->stats, t, q, Cq, Ct)) != VLBE_OK) return rc;
    if ((rc = vlbe__dae_constr(s, &st->stats, t, q, G + 2 * n + m)) != VLBE_OK) return rc;
    if (vlbe__dae_banded(s)) {
        vlbe_real *pw = vlbe__bdf_ext(st) + N2, *tmp = pw + N2;
        vlbe__dae_bprod(s, 0, M, yp + n, G + n, pw);
        for (i = 0; i < n; ++i) {
            G[i] = yp[i] - v[i];
            G[n + i] -= Q[i];
        }
        if (m > 0) {
            vlbe__dae_bprod(s, 2, Cq, mu, tmp, pw);
            vlbe_vec_axpy(n, VLBE_R(1.0), tmp, G);
            vlbe__dae_bprod(s, 2, Cq, lam, tmp, pw);
            vlbe_vec_axpy(n, VLBE_R(1.0), tmp, G + n);
            vlbe__dae_bprod(s, 1, Cq, v, G + 2 * n, pw);
            vlbe_vec_axpy(m, VLBE_R(1.0), Ct, G + 2 * n);
        }
        return vlbe_all_finite(G, N2) ? VLBE_OK : VLBE_ENONFINITE;
    }
    vlbe_mat_vec(n, n, M, yp + n, G + n);
    for (i = 0; i < n; ++i) {
        G[i] = yp[i] - v[i];
        G[n + i] -= Q[i];
    }
    for (i = 0; i < m; ++i) {
        const vlbe_real *ci = Cq + (size_t)i * n;
        vlbe_vec_axpy(n, mu[i], ci, G);
        vlbe_vec_axpy(n, lam[i], ci, G + n);
        G[2 * n + i] = vlbe_vec_dot(n, ci, v) + Ct[i];
    }
    return vlbe_all_finite(G, N2) ? VLBE_OK : VLBE_ENONFINITE;
}

/* Iteration matrix dG/dy + cj dG/dy' at (t, y, y') (M, Q, Cq, Ct from the
   residual just evaluated there), scaled for conditioning: the q and v rows
   are divided by cj and the lambda and mu columns multiplied by cj, so that
   every block stays O(1) as h -> 0 (the unscaled matrix has blocks O(1/h)
   next to O(1) constraint rows, and Schur complements O(h)), then every row
   scaled to its largest entry by vlbe__dae_equil (M may be small against
   the identity block, e.g. 1e-6 kg m^2 inertias: without it the LU's
   relative pivot test fails in float):
       [ I + (C_q^T mu)_q/cj     -I/cj                    0      C_q^T ]
       [ (Ma+C_q^T l-Q)_q/cj     M + (Ma-Q)_v/cj          C_q^T  0     ]
       [ (C_q v + C_t)_q         C_q                      0      0     ]
       [ C_q                     0                        0      0     ]
   Factored in place; the solve undoes the scaling (vlbe__bdf_solve). */
VLBE_INLINE vlbe_status vlbe__bdf_matrix(vlbe_bdf *st, vlbe_real t, const vlbe_real *y,
                                         const vlbe_real *yp, vlbe_real cj)
{
    const vlbe_dae *s = st->sys;
    int n = st->n, m = st->m, N2 = vlbe__bdf_n2(st), i, j;
    size_t NN = (size_t)N2 * (size_t)N2, ld = (size_t)N2;
    vlbe_real *A = vlbe__bdf_tail(st), *M = vlbe__bdf_M(st), *Q = M + vlbe__dae_mlen(s, 0),
              *Cq = Q + n, *rs = vlbe__bdf_rs(st), *scr = rs + N2, ic = VLBE_R(1.0) / cj;
    vlbe_status rc;
    st->jcalc_ = -1;
    if (vlbe__dae_banded(s)) {
        vlbe__dae_blk Bqq, Bqv, Bvq, Bvv;
        const int *inv = st->piv_ + N2;
        int b;
        NN = vlbe__dae_alen(s, 2);
        ld = vlbe__dae_ald(s, 2);
        vlbe_vec_zero((int)NN, A);
        Bqq = vlbe__dae_band_blk(s, A, 2);
        Bqv = Bvq = Bvv = Bqq;
        Bqv.co = 1;
        Bvq.ro = 1;
        Bvv.ro = Bvv.co = 1;
        vlbe__dae_bdiag(s, &Bqq, VLBE_R(1.0));
        vlbe__dae_bdiag(s, &Bqv, -ic);
        vlbe__dae_badd(s, &Bvv, VLBE_R(1.0), M, 0);
        if (m > 0) {
            vlbe__dae_badd(s, &Bqv, VLBE_R(1.0), Cq, 2); /* (q, mu)     */
            vlbe__dae_badd(s, &Bvq, VLBE_R(1.0), Cq, 2); /* (v, lambda) */
            vlbe__dae_badd(s, &Bqv, VLBE_R(1.0), Cq, 1); /* (lambda, v) */
            vlbe__dae_badd(s, &Bvq, VLBE_R(1.0), Cq, 1); /* (mu, q)     */
        }
        rc = vlbe__dae_btangent(s, &st->stats, t, y, y + n, yp + n, NULL, Q, M, ic, &Bvq, ic,
                                &Bvv, inv, scr);
        if (rc != VLBE_OK) return rc;
        if (m > 0) {
            /* (v, q) += d(C_q^T lambda)/dq / cj, (q, q) += d(C_q^T mu)/dq / cj,
               (lambda, q) += d(C_q v + C_t)/dq: lambda rows sit at 2 order + 0 */
            rc = vlbe__dae_bconstr_q(s, &st->stats, t, y, y + 2 * n, ic, &Bvq, y + 2 * n + m, ic,
                                     &Bqq, y + n, &Bqq, inv, scr);
            if (rc != VLBE_OK) return rc;
        }
        if (!vlbe_all_finite(A, (int)NN)) return VLBE_ENONFINITE;
        vlbe__dae_equil(N2, A, ld, (int)ld, rs, NULL);
        for (i = 0; i < n; ++i) /* the 1/cj of the q and v rows, for the solve */
            for (b = 0; b < 2; ++b) rs[2 * s->order[i] + b] *= ic;
        ++st->stats.lu_factors;
        if ((rc = vlbe__dae_factor(s, &st->stats, 2, A, st->piv_)) != VLBE_OK) return rc;
        st->cj_lu_ = cj;
        st->jcalc_ = 0;
        return VLBE_OK;
    }
    for (i = 0; i < (int)NN; ++i) A[i] = VLBE_R(0.0);
    for (i = 0; i < n; ++i) {
        A[(size_t)i * ld + (size_t)i] = VLBE_R(1.0);
        A[(size_t)i * ld + (size_t)(n + i)] = -ic;
        for (j = 0; j < n; ++j) A[(size_t)(n + i) * ld + (size_t)(n + j)] = M[(size_t)i * n + j];
        for (j = 0; j < m; ++j) {
            vlbe_real c = Cq[(size_t)j * n + i];
            A[(size_t)i * ld + (size_t)(2 * n + m + j)] = c;   /* (q, mu)     */
            A[(size_t)(n + i) * ld + (size_t)(2 * n + j)] = c; /* (v, lambda) */
            A[(size_t)(2 * n + j) * ld + (size_t)(n + i)] = c; /* (lambda, v) */
            A[(size_t)(2 * n + m + j) * ld + (size_t)i] = c;   /* (mu, q)     */
        }
    }
    rc = vlbe__dae_tangent2(s, &st->stats, t, y, y + n, yp + n, NULL, Q, M, ic, A + ld * n,
                            N2, ic, A + ld * n + n, N2, scr);
    if (rc != VLBE_OK) return rc;
    if (m > 0) {
        rc = vlbe__dae_constr_q(s, &st->stats, t, y, y + 2 * n, ic, A + ld * n, N2,
                                y + 2 * n + m, ic, A, N2, y + n, A + ld * (size_t)(2 * n), N2,
                                scr);
        if (rc != VLBE_OK) return rc;
    }
    if (!vlbe_all_finite(A, (int)NN)) return VLBE_ENONFINITE;
    vlbe__dae_equil(N2, A, ld, N2, rs, NULL);
    for (i = 0; i < 2 * n; ++i) rs[i] *= ic; /* the 1/cj of the q and v rows, for the solve */
    ++st->stats.lu_factors;
    if ((rc = vlbe__dae_factor(s, &st->stats, 2, A, st->piv_)) != VLBE_OK) return rc;
    st->cj_lu_ = cj;
    st->jcalc_ = 0;
    return VLBE_OK;
}

/* delta <- (iteration matrix)^-1 delta, with the scaling of vlbe__bdf_matrix. */
VLBE_INLINE void vlbe__bdf_solve(vlbe_bdf *st, vlbe_real *d)
{
    int n = st->n, m = st->m, N2 = vlbe__bdf_n2(st), i;
    const vlbe_real *rs = vlbe__bdf_rs(st);
    vlbe_real c = st->cj_lu_;
    ++st->stats.lu_solves;
    if (vlbe__dae_banded(st->sys)) {
        vlbe_real *X = vlbe__bdf_ext(st);
        vlbe__dae_perm(st->sys, 2, d, X);
        for (i = 0; i < N2; ++i) X[i] *= rs[i];
        vlbe__dae_solve(st->sys, 2, vlbe__bdf_tail(st), st->piv_, X);
        vlbe__dae_unperm(st->sys, 2, X, d);
    } else {
        for (i = 0; i < N2; ++i) d[i] *= rs[i];
        vlbe__dae_solve(st->sys, 2, vlbe__bdf_tail(st), st->piv_, d);
    }
    for (i = 2 * n; i < 2 * n + 2 * m; ++i) d[i] *= c;
}

/* Norm of an error-estimate vector x (e, or e plus differences): with
   par.stiff_filter the weighted norm vlbe__bdf_norm of the q, v parts of
       F x = A^-1 (c x_q, c M x_v, C_q x_v, C_q x_q),    c = cj_lu,
   A the stored iteration matrix dG/dy + c dG/dy' (the LU of the corrector),
   M, C_q from the last residual; without it, of x itself.  The right side
   is c dG/dy' x in the differential rows and the linearized constraints
   of x in the algebraic ones, so that F x = x when the Jacobian terms of
   the differential rows are small against c dG/dy': F is the filter
   (I - J/c)^-1 of Shampine (1980; Hairer-Wanner IV.8 use it for Radau
   IIA), J the Jacobian of the first-order form, on the tangent space of
   the constraints, whose normal components pass unchanged to first order
   (they keep lambda's accuracy: test_pendulum_period).  A mode of the linearized
   system with eigenvalue z is scaled by c / (c - z): 1 for the modes the
   step resolves (|z| << c, c ~ 1.5/h at order 2), ~ c / |z| for stiff
   ones.  Why: velocities along stiff undamped springs (the axial modes of
   a beam) behave like index-2 variables (in the limit of infinite
   stiffness the springs are constraints, their forces index-3
   multipliers): when h changes their BDF values jump by O(h^k) instead of
   O(h^(k+1)) (Petzold 1982).  On a curved spring manifold -- a rotating
   beam, where BDF1's chord velocity has a radial part w_hub^2 R h / 2 --
   these jumps dominate the plain estimate (scenes/ex_spin.h at t = 10 s
   after fixed steps of 1e-3 s: a doubled h gives 80 times the estimate of
   the same h at order 1, 220 times at order 2, where h changed by 10 %
   already gives 9 times).  Step changes then cause the rejections that
   cause step changes, the order selection, which reads the jumps as
   noise, falls to order 1, and h shrinks until it resolves the stiff
   modes, which the jumps keep excited: on the spin-up scene at rtol
   1e-3, 70 % of the attempts rejected, h ~ 1e-3 s at order 1, 7 times the
   steps of fixed-step BDF2 at h = 1e-2 for a 40 times larger error.
   (Schaub and Simeon's remedy for Radau5 scales the error of stiff
   velocity components by h; here the iteration matrix finds them.)  Costs
   one solve with the stored LU per norm, two to four per attempt.  f (N2)
   is scratch. */
VLBE_INLINE vlbe_real vlbe__bdf_enorm(vlbe_bdf *st, const vlbe_real *x, vlbe_real *f)
{
    int n = st->n, m = st->m, band = vlbe__dae_banded(st->sys);
    const vlbe_real *M = vlbe__bdf_M(st), *Cq = M + vlbe__dae_mlen(st->sys, 0) + (size_t)n;
    vlbe_real *pw = vlbe__bdf_ext(st) + vlbe__bdf_n2(st);
    if (!st->par.stiff_filter) return vlbe__bdf_norm(st, x);
    vlbe_vec_copy(n, x, f);
    vlbe_vec_scale(n, st->cj_lu_, f);
    if (band) vlbe__dae_bprod(st->sys, 0, M, x + n, f + n, pw);
    else vlbe_mat_vec(n, n, M, x + n, f + n);
    vlbe_vec_scale(n, st->cj_lu_, f + n);
    if (m > 0 && band) {
        vlbe__dae_bprod(st->sys, 1, Cq, x + n, f + 2 * n, pw);
        vlbe__dae_bprod(st->sys, 1, Cq, x, f + 2 * n + m, pw);
    } else if (m > 0) {
        vlbe_mat_vec(m, n, Cq, x + n, f + 2 * n);
        vlbe_mat_vec(m, n, Cq, x, f + 2 * n + m);
    }
    vlbe__bdf_solve(st, f);
    return vlbe__bdf_norm(st, f);
}

/* Step-size dependent coefficients for a step h at order k (book sec. 5.2.1)
   and phi -> phi* (phi_j times beta_j).  ns: steps taken with constant h and k
   (counting this one); while ns > k+1 the coefficients do not change. */
VLBE_INLINE void vlbe__bdf_coef(vlbe_bdf *st, vlbe_real h, int k, int ns)
{
    int N2 = vlbe__bdf_n2(st), i, j;
    if (k + 1 >= ns) {
        vlbe_real pn = h; /* psi_i(n+1) */
        st->beta_[1] = st->alpha_[1] = st->sigma_[1] = VLBE_R(1.0);
        st->gamma_[1] = VLBE_R(0.0);
        for (i = 2; i <= k + 1; ++i) {
            vlbe_real po = st->psi_[i - 1]; /* psi_{i-1}(n) */
            st->psi_[i - 1] = pn;
            st->beta_[i] = st->beta_[i - 1] * pn / po;
            pn = po + h;
            st->alpha_[i] = h / pn;
            st->sigma_[i] = (vlbe_real)(i - 1) * st->sigma_[i - 1] * st->alpha_[i];
            st->gamma_[i] = st->gamma_[i - 1] + st->alpha_[i - 1] / h;
        }
        st->psi_[k + 1] = pn;
    }
    for (j = ns + 1; j <= k + 1; ++j) vlbe_vec_scale(N2, st->beta_[j], vlbe__bdf_phi(st, j));
}

/* Undoes vlbe__bdf_coef after a failed attempt (phi* -> phi, psi back). */
VLBE_INLINE void vlbe__bdf_restore(vlbe_bdf *st, vlbe_real h, int k, int ns)
{
    int N2 = vlbe__bdf_n2(st), i, j;
    for (j = ns + 1; j <= k + 1; ++j)
        vlbe_vec_scale(N2, VLBE_R(1.0) / st->beta_[j], vlbe__bdf_phi(st, j));
    for (i = 2; i <= k + 1; ++i) st->psi_[i - 1] = st->psi_[i] - h;
}

/* Predictor and Newton corrector for the step to t1 at order k (coefficients
   set).  The iteration matrix is kept across steps and only re-formed when
   none is stored (jcalc_ = -1: first step, failure, cj/cj_lu outside
   [0.6, 1/0.6]) or when the iteration with the stored one fails to converge
   (then the attempt is repeated from the predictor with a fresh one).
   Convergence (book sec. 5.2.3), in the norm vlbe__bdf_newton_norm of all
   of (q, v, lambda, mu): rate rho = (|d_m| / |d_0|)^(1/m),
   s = rho / (1 - rho), converged when s |d_m| <= 0.03 (DASSL: 0.33; the
   tighter test keeps Newton noise out of the error estimates, which pays
   back in larger steps and higher orders) or the q, v part of d_m is at
   the rounding floor 100 eps |y|;
   rho > 0.9 or newton_max iterations fail.  Every attempt starts from
   s = 100, as DASSL does after a change of cj: a first correction is
   accepted alone only when it is below 3e-4, otherwise a second one
   measures the rate.  (DASSL keeps the s of the last step while cj stays
   the same.  At a constant step with a stored matrix that s is never
   measured again -- every step converges "in one iteration" on a rate
   from a fresh matrix many steps back -- while the matrix goes stale:
   on a rotating structure with stiff springs the stored matrix turns
   with the structure, the true rate of the iteration passes 1 in the
   stiff directions, and the unconverged corrections accepted on the old
   rate put fixed-step BDF2 (h = 1e-3) on the spin-up scene of
   scenes/ex_spin.h into divergence at t = 2.6 s, and test_bdf.c's
   spinning spring 3 rad off.)  With a stale cj the correction is scaled
   by 2 / (1 + cj / cj_lu).  Returns VLBE_OK with trial y, y' and
   e = y - y_pred, or ENOCONV / ENONFINITE / ESINGULAR / ECALLBACK. */
VLBE_INLINE vlbe_status vlbe__bdf_corrector(vlbe_bdf *st, vlbe_real t1, int k)
{
    int N2 = vlbe__bdf_n2(st), i, j, it;
    vlbe_real *y = vlbe__bdf_vec(st, 0), *yp = vlbe__bdf_vec(st, 1), *e = vlbe__bdf_vec(st, 2),
              *d = vlbe__bdf_vec(st, 3);
    vlbe_real cj = st->cj_, s = VLBE_R(100.0), pnorm, dn, dn0 = VLBE_R(1.0);
    vlbe_status rc;
    for (;;) {
        /* predictor */
        vlbe_vec_copy(N2, vlbe__bdf_phi(st, 1), y);
        vlbe_vec_zero(N2, yp);
        for (j = 2; j <= k + 1; ++j) {
            const vlbe_real *pj = vlbe__bdf_phi(st, j);
            vlbe_vec_axpy(N2, VLBE_R(1.0), pj, y);
            vlbe_vec_axpy(N2, st->gamma_[j], pj, yp);
        }
        vlbe_vec_zero(N2, e);
        pnorm = vlbe__bdf_norm(st, y);
        if ((rc = vlbe__bdf_res(st, t1, y, yp, d)) != VLBE_OK) return rc;
        if (st->jcalc_ == -1) {
            if ((rc = vlbe__bdf_matrix(st, t1, y, yp, cj)) != VLBE_OK) return rc;
            s = VLBE_R(100.0);
        }
        for (it = 0;;) {
            ++st->stats.newton_iters;
            vlbe__bdf_solve(st, d);
            if (cj != st->cj_lu_) vlbe_vec_scale(N2, VLBE_R(2.0) / (VLBE_R(1.0) + cj / st->cj_lu_), d);
            for (i = 0; i < N2; ++i) {
                y[i] -= d[i];
                e[i] -= d[i];
                yp[i] -= cj * d[i];
            }
            if (!vlbe_all_finite(y, N2)) return VLBE_ENONFINITE;
            dn = vlbe__bdf_newton_norm(st, d, cj);
            /* rounding floor, judged on q and v: at tiny h the multipliers
               are fixed by the iteration only to eps cj and would stall it */
            if (vlbe__bdf_norm(st, d) <= VLBE_R(100.0) * VLBE_EPS * pnorm) goto converged;
            if (it > 0) {
                vlbe_real rho = vlbe_pow(dn / dn0, VLBE_R(1.0) / (vlbe_real)it);
                if (rho > VLBE_R(0.9)) break;
                s = rho / (VLBE_R(1.0) - rho);
            } else {
                dn0 = dn;
            }
            if (s * dn <= VLBE_R(0.03)) goto converged;
            if (++it >= st->par.newton_max) break;
            if ((rc = vlbe__bdf_res(st, t1, y, yp, d)) != VLBE_OK) return rc;
        }
        /* not converged: a stale matrix is re-formed and the attempt repeated */
        if (st->jcalc_ == 0) {
            st->rate_ = s;
            return VLBE_ENOCONV;
        }
        st->jcalc_ = -1;
    }
converged:
    st->rate_ = s;
    return VLBE_OK;
}

/* Saves the parts of the state that the attempts of a step change before
   it is accepted (phi_2 .. phi_{k+1} scaled by the coefficients, the
   coefficients themselves) to the backup area; vlbe__bdf_unsave puts them
   back bit for bit after a failed step. */
VLBE_INLINE void vlbe__bdf_save(const vlbe_bdf *st, int k)
{
    int N2 = vlbe__bdf_n2(st), L = VLBE_BDF_MAXORD + 2;
    vlbe_real *b = vlbe__bdf_backup(st), *c = b + (size_t)N2 * VLBE_BDF_MAXORD;
    vlbe_vec_copy(N2 * k, vlbe__bdf_phi(st, 2), b);
    vlbe_vec_copy(L, st->psi_, c);
    vlbe_vec_copy(L, st->alpha_, c + L);
    vlbe_vec_copy(L, st->beta_, c + 2 * L);
    vlbe_vec_copy(L, st->gamma_, c + 3 * L);
    vlbe_vec_copy(L, st->sigma_, c + 4 * L);
}
VLBE_INLINE void vlbe__bdf_unsave(vlbe_bdf *st, int k)
{
    int N2 = vlbe__bdf_n2(st), L = VLBE_BDF_MAXORD + 2;
    const vlbe_real *b = vlbe__bdf_backup(st), *c = b + (size_t)N2 * VLBE_BDF_MAXORD;
    vlbe_vec_copy(N2 * k, b, vlbe__bdf_phi(st, 2));
    vlbe_vec_copy(L, c, st->psi_);
    vlbe_vec_copy(L, c + L, st->alpha_);
    vlbe_vec_copy(L, c + 2 * L, st->beta_);
    vlbe_vec_copy(L, c + 3 * L, st->gamma_);
    vlbe_vec_copy(L, c + 4 * L, st->sigma_);
}

/* Order and step for the next step after an accepted step of order *k and
   size h, variable-step mode (Brenan-Campbell-Petzold sec. 5.2.2, the
   strategy of DASSL): the start-up phase (until the order would drop or
   reaches kmax) raises the order and doubles h every step; then the order
   k-1 when knew says so, else k+1 is tried (the last k+1 steps all of
   order k: phi_{k+2} holds the previous e, its norm terk+1) against the
   estimates terk-1, terk; the step from the estimate est of the order
   kept, r = (2 est + 1e-4)^(-1/(k+1)): doubled when r >= 2 (after a step
   cut short for t_stop back up to what the estimate allows, at most the
   planned hnat), cut to h max(0.5, min(0.9, r)) when r <= 1, else kept. */
VLBE_INLINE void vlbe__bdf_next(vlbe_bdf *st, int kmax, int knew, int kdiff, int ns, int shortened,
                                vlbe_real h, vlbe_real hnat, vlbe_real est, vlbe_real erkm1,
                                vlbe_real terk, vlbe_real terkm1, const vlbe_real *e, vlbe_real *d,
                                vlbe_real *yp, int *kk, vlbe_real *hnew)
{
    const int N2 = vlbe__bdf_n2(st);
    int k = *kk, j;
    vlbe_real r;
    if (knew == k - 1 || k == kmax) st->phase_ = 1;
    if (st->phase_ == 0) {
        /* start-up phase: raise the order and double h every step */
        *kk = k + 1;
        *hnew = shortened ? (hnat > VLBE_R(2.0) * h ? hnat : VLBE_R(2.0) * h) : VLBE_R(2.0) * h;
        return;
    }
    if (knew == k - 1) {
        k = knew;
        est = erkm1;
    } else if (k < kmax && k + 1 < ns && kdiff != 1) {
        /* try order k+1: phi_{k+2} holds the previous e */
        vlbe_real *pk2 = vlbe__bdf_phi(st, k + 2), terkp1;
        for (j = 0; j < N2; ++j) d[j] = e[j] - pk2[j];
        terkp1 = vlbe__bdf_enorm(st, d, yp); /* (k+2) * erkp1 */
        if (k == 1) {
            if (terkp1 < VLBE_R(0.5) * terk) {
                ++k;
                est = terkp1 / (vlbe_real)(k + 1);
            }
        } else if (terkm1 <= (terk < terkp1 ? terk : terkp1)) {
            --k;
            est = erkm1;
        } else if (terkp1 < terk) {
            ++k;
            est = terkp1 / (vlbe_real)(k + 1);
        }
    }
    r = vlbe_pow(VLBE_R(2.0) * est + VLBE_R(1e-4), -VLBE_R(1.0) / (vlbe_real)(k + 1));
    if (r >= VLBE_R(2.0)) {
        *hnew = VLBE_R(2.0) * h;
        /* after a step cut short for t_stop, go back up to the step the
           estimate allows, at most the one planned */
        if (shortened && h * r > *hnew) *hnew = h * r < hnat ? h * r : hnat;
    } else if (r <= VLBE_R(1.0)) {
        r = r < VLBE_R(0.5) ? VLBE_R(0.5) : (r > VLBE_R(0.9) ? VLBE_R(0.9) : r);
        *hnew = h * r;
    }
    *kk = k;
}

/* The first attempt of vlbe_bdf_step toward t_stop (t_stop > t): the
   step h (fixed: h0; else the planned one within [h_min, h_max], the first
   without h0 1e-3 of the distance, as DASSL), hnat that step before the
   landing, hmin the smallest step (4 eps |t|, or h_min), the run of fixed
   steps h0 (tb, krun; restarted when t was moved: a shortened step, the
   caller, krun no longer exact in vlbe_real), and the landing: to_stop
   when the step ends on t_stop exactly; a step that would leave a sliver
   (< 10% of h) behind is halved; a fixed step h0 that ends within hmin of
   t_stop ends on it with the coefficients of h0. */
VLBE_INLINE void vlbe__bdf_plan(const vlbe_bdf *st, vlbe_real t_stop, vlbe_real *h,
                                vlbe_real *hnat, vlbe_real *hmin, vlbe_real *tb, long *krun,
                                int *to_stop)
{
    const vlbe_bdf_params *p = &st->par;
    const vlbe_real dist = t_stop - st->t;
    *h = p->fixed_step ? p->h0 : st->h;
    if (!p->fixed_step) {
        if (st->kold_ == 0 && p->h0 == VLBE_R(0.0) && *h > VLBE_R(1e-3) * dist)
            *h = VLBE_R(1e-3) * dist; /* first step without h0 (DASSL) */
        if (p->h_max > VLBE_R(0.0) && *h > p->h_max) *h = p->h_max;
        if (*h < p->h_min) *h = p->h_min;
    }
    *hnat = *h;
    *hmin = VLBE_R(4.0) * VLBE_EPS *
            (vlbe_fabs(st->t) > vlbe_fabs(t_stop) ? vlbe_fabs(st->t) : vlbe_fabs(t_stop));
    if (p->h_min > *hmin) *hmin = p->h_min;
    *tb = st->t_base_;
    *krun = st->k_run_;
    if (p->fixed_step && (st->t != *tb + (vlbe_real)*krun * *h ||
                          (vlbe_real)(*krun + 1) * VLBE_EPS >= VLBE_R(1.0))) {
        *tb = st->t;
        *krun = 0;
    }
    *to_stop = 0;
    if (p->fixed_step && vlbe_fabs(dist - *h) <= *hmin) {
        *to_stop = 1;
    } else if (*h >= dist) {
        *h = dist;
        *to_stop = 1;
    } else if (!p->fixed_step && VLBE_R(1.1) * *h > dist) {
        *h = VLBE_R(0.5) * dist;
    }
}

/* The error estimates of an attempt at order k (book sec. 5.2.2), in the
   filtered norm: the norm of the corrector's change e (returned), est and
   terk at order k, erkm1 and terkm1 at k - 1; knew = k - 1 (est = erkm1)
   when the lower orders' terms say the order should drop, else k.  d, yp:
   scratch (the trial y' is free once the corrector has converged). */
VLBE_INLINE vlbe_real vlbe__bdf_errest(vlbe_bdf *st, int k, const vlbe_real *e, vlbe_real *d,
                                       vlbe_real *yp, vlbe_real *est, vlbe_real *terk,
                                       vlbe_real *erkm1, vlbe_real *terkm1, int *knew)
{
    const int N2 = vlbe__bdf_n2(st);
    const vlbe_real enorm = vlbe__bdf_enorm(st, e, yp);
    int j, lower;
    *knew = k;
    *est = st->sigma_[k + 1] * enorm;
    *terk = (vlbe_real)(k + 1) * *est;
    if (k > 1) {
        vlbe_real *pk1 = vlbe__bdf_phi(st, k + 1);
        for (j = 0; j < N2; ++j) d[j] = pk1[j] + e[j];
        *erkm1 = st->sigma_[k] * vlbe__bdf_enorm(st, d, yp);
        *terkm1 = (vlbe_real)k * *erkm1;
        if (k > 2) {
            vlbe_vec_axpy(N2, VLBE_R(1.0), vlbe__bdf_phi(st, k), d);
            vlbe_real terkm2 = (vlbe_real)(k - 1) * st->sigma_[k - 1] * vlbe__bdf_enorm(st, d, yp);
            lower = (*terkm1 > terkm2 ? *terkm1 : terkm2) <= *terk;
        } else {
            lower = *terkm1 <= VLBE_R(0.5) * *terk;
        }
        if (lower) {
            *knew = k - 1;
            *est = *erkm1;
        }
    }
    return enorm;
}

/* An accepted step of size h at order k to t1: the new state and
   history, then the order and step of the next step (vlbe__bdf_next with
   the attempt's estimates; fixed steps: the order climbs to max_order,
   the run of steps h0 from tb, krun goes on unless this step was cut
   short) and the divided differences phi for it. */
VLBE_INLINE void vlbe__bdf_accept(vlbe_bdf *st, vlbe_real t1, vlbe_real h, int k, int knew,
                                  int ns, int shortened, vlbe_real hnat, vlbe_real tb, long krun,
                                  vlbe_real est, vlbe_real erkm1, vlbe_real terk,
                                  vlbe_real terkm1)
{
    const vlbe_bdf_params *p = &st->par;
    const int N2 = vlbe__bdf_n2(st), kmax = p->max_order;
    int kdiff = k - st->kold_, kstep = k, j;
    vlbe_real hnew = h;
    vlbe_real *y = vlbe__bdf_vec(st, 0), *yp = vlbe__bdf_vec(st, 1), *e = vlbe__bdf_vec(st, 2),
              *d = vlbe__bdf_vec(st, 3);
    vlbe_vec_copy(N2, y, st->q);
    st->t = t1;
    if (p->fixed_step) {
        /* a step cut short for t_stop ends the run */
        st->t_base_ = h == p->h0 ? tb : t1;
        st->k_run_ = h == p->h0 ? krun + 1 : 0;
    }
    ++st->stats.steps;
    st->h_last = h;
    st->order_last = k;
    st->kold_ = k;
    st->hold_ = h;
    st->ns_ = ns;
    if (p->fixed_step) {
        if (k < kmax) ++k;
    } else {
        vlbe__bdf_next(st, kmax, knew, kdiff, ns, shortened, h, hnat, est, erkm1, terk, terkm1, e,
                       d, yp, &k, &hnew);
    }
    /* divided differences for the next step */
    if (kstep < kmax) vlbe_vec_copy(N2, e, vlbe__bdf_phi(st, kstep + 2));
    vlbe_vec_axpy(N2, VLBE_R(1.0), e, vlbe__bdf_phi(st, kstep + 1));
    for (j = kstep; j >= 1; --j)
        vlbe_vec_axpy(N2, VLBE_R(1.0), vlbe__bdf_phi(st, j + 1), vlbe__bdf_phi(st, j));
    st->order = k;
    st->h = hnew;
}

/* One accepted step (several attempts if needed) with t + h <= t_stop.
   t_stop <= t or not finite: VLBE_EARG.  On failure the state is as it was
   before the call (t, h, order, q, v, lambda, mu and the history of
   the method, bit for bit), except stats, which count the failed work, and
   the stored iteration matrix, which is dropped if a failed attempt formed
   a new one.  With fixed_step, a run of
   steps h0 from t_b ends step k at t_b + k h0 (a product, no drift), and a
   step that would end within 4 eps |t| of t_stop ends on it (the same
   method coefficients, no sliver step left). */
VLBE_API vlbe_status vlbe_bdf_step(vlbe_bdf *st, vlbe_real t_stop)
{
    const vlbe_bdf_params *p;
    int N2, k, ns, knew, nef = 0, ncf = 0, nsf = 0, to_stop, shortened, k0, phase0, jcalc0;
    long nlu0;
    vlbe_real h, hnat, hmin, t1, est, terk, terkm1 = VLBE_R(0.0), erkm1 = VLBE_R(0.0), dist;
    vlbe_real cj0, rate0, tb;
    long krun;
    vlbe_real *e, *d, *yp;
    vlbe_status rc;
    VLBE_ASSERT(st != NULL && st->sys != NULL);
    p = &st->par;
    N2 = vlbe__bdf_n2(st);
    yp = vlbe__bdf_vec(st, 1);
    e = vlbe__bdf_vec(st, 2);
    d = vlbe__bdf_vec(st, 3);
    dist = t_stop - st->t;
    if (!(dist > VLBE_R(0.0)) || !isfinite(t_stop)) return VLBE_EARG;
    k = st->order;
    vlbe__bdf_plan(st, t_stop, &h, &hnat, &hmin, &tb, &krun, &to_stop);
    /* what a failure puts back */
    k0 = st->order;
    phase0 = st->phase_;
    jcalc0 = st->jcalc_;
    nlu0 = st->stats.lu_factors;
    cj0 = st->cj_;
    rate0 = st->rate_;
    vlbe__bdf_save(st, k0);
    shortened = h < hnat;
    for (;;) {
        vlbe_real enorm, ck, alphas = VLBE_R(0.0), alpha0 = VLBE_R(0.0), cj;
        int j, failed_newton = 0;
        t1 = to_stop ? t_stop : (p->fixed_step ? tb + (vlbe_real)(krun + 1) * h : st->t + h);
        if (t1 == st->t) {
            rc = VLBE_ESTEP;
            goto fail;
        }
        /* first step: phi_2 = h y'(t0) */
        if (st->kold_ == 0 && st->psi_[1] != h) {
            vlbe_vec_scale(N2, h / st->psi_[1], vlbe__bdf_phi(st, 2));
            st->psi_[1] = h;
        }
        ns = (h == st->hold_ && k == st->kold_) ? st->ns_ + 1 : 1;
        if (ns > st->kold_ + 2) ns = st->kold_ + 2;
        vlbe__bdf_coef(st, h, k, ns);
        for (j = 1; j <= k; ++j) {
            alphas -= VLBE_R(1.0) / (vlbe_real)j;
            alpha0 -= st->alpha_[j];
        }
        cj = -alphas / h;
        ck = vlbe_fabs(st->alpha_[k + 1] + alphas - alpha0);
        if (ck < st->alpha_[k + 1]) ck = st->alpha_[k + 1];
        st->cj_ = cj;
        if (st->jcalc_ != -1) {
            vlbe_real ratio = cj / st->cj_lu_;
            st->jcalc_ = (ratio < VLBE_R(0.6) || ratio > VLBE_R(1.0) / VLBE_R(0.6)) ? -1 : 1;
        }
        rc = vlbe__bdf_corrector(st, t1, k);
        knew = k;
        est = VLBE_R(0.0);
        terk = VLBE_R(0.0);
        if (rc == VLBE_OK) {
            if (p->fixed_step) break; /* accepted, no error test */
            /* error estimates at orders k, k-1, k-2 (book sec. 5.2.2), in the
               filtered norm; the trial y' is free now (scratch) */
            enorm = vlbe__bdf_errest(st, k, e, d, yp, &est, &terk, &erkm1, &terkm1, &knew);
            if (ck * enorm <= VLBE_R(1.0)) break; /* accepted */
        } else {
            if (!vlbe__dae_retry(&st->stats, rc)) goto fail;
            failed_newton = 1;
        }
        /* failed attempt: back to the last accepted step, smaller h */
        vlbe__bdf_restore(st, h, k, ns);
        ++st->stats.rejected;
        st->phase_ = 1;
        if (failed_newton) {
            if (rc == VLBE_ESINGULAR) {
                if (++nsf >= 3) goto fail;
            } else {
                ++st->stats.newton_fails;
                if (++ncf >= 10) goto fail;
            }
            st->jcalc_ = -1;
            if (p->fixed_step) goto fail;
            h *= VLBE_R(0.25);
            if (h < hmin) goto fail;
        } else {
            ++nef;
            if (nef == 1) {
                vlbe_real r;
                k = knew;
                r = VLBE_R(0.9) * vlbe_pow(VLBE_R(2.0) * est + VLBE_R(1e-4),
                                           -VLBE_R(1.0) / (vlbe_real)(k + 1));
                r = r < VLBE_R(0.25) ? VLBE_R(0.25) : (r > VLBE_R(0.9) ? VLBE_R(0.9) : r);
                h *= r;
            } else {
                k = nef == 2 ? knew : 1;
                h *= VLBE_R(0.25);
            }
            if (h < hmin) {
                rc = VLBE_ESTEP;
                goto fail;
            }
        }
        to_stop = 0;
    }

    /* accepted: new state, then order and step for the next step */
    vlbe__bdf_accept(st, t1, h, k, knew, ns, shortened, hnat, tb, krun, est, erkm1, terk, terkm1);
    return VLBE_OK;
fail:
    /* the state of the call's start: phi and the coefficients from the
       backup (the attempts' scaling and its undoing are not exact), the
       scalars from their copies; the stored matrix is kept unless an
       attempt re-formed it (then it may be a failed one) */
    vlbe__bdf_unsave(st, k0);
    st->phase_ = phase0;
    st->cj_ = cj0;
    st->rate_ = rate0;
    st->jcalc_ = st->stats.lu_factors == nlu0 ? jcalc0 : -1;
    return rc;
}

/* Steps until st->t == t_out exactly (the last step is shortened to land
   there).  t_out == t returns at once; t_out < t or not finite is
   VLBE_EARG; par.max_steps > 0 steps without reaching t_out is VLBE_EBOUND
   (call again to go on).  On failure the state is the last accepted step,
   which may lie past the start: a documented exception to the failure
   contract (the steps are vlbe_bdf_step calls, each all or nothing;
   undoing the accepted ones would take a second copy of the whole history
   and throw away valid work -- st->t says how far the run got). */
VLBE_API vlbe_status vlbe_bdf_advance(vlbe_bdf *st, vlbe_real t_out)
{
    vlbe_status rc;
    int k = 0;
    VLBE_ASSERT(st != NULL && st->sys != NULL);
    if (!isfinite(t_out) || t_out < st->t) return VLBE_EARG;
    while (st->t < t_out) {
        if (st->par.max_steps > 0 && k++ == st->par.max_steps) return VLBE_EBOUND;
        if ((rc = vlbe_bdf_step(st, t_out)) != VLBE_OK) return rc;
    }
    return VLBE_OK;
}

/* Dense output: q and v at t within the last step, t in [st->t - h_last,
   st->t], from the interpolating polynomial of that step (DASSL's DDATRP,
   Brenan-Campbell-Petzold sec. 5.4): the polynomial of degree k =
   order_last through the last k + 1 solution points, in the modified
   divided differences phi and the psi of the step,
       y(t) = sum_{j=1}^{k+1} c_j phi_j,  c_1 = 1,
       c_j = c_{j-1} (t - t_n + psi_{j-2}) / psi_{j-1}  (psi_0 = 0).
   Its error is of the order of the step's local error (the error test's
   tolerance) on top of the error of the solution points.  At t == st->t
   the state itself (bit for bit).  No extrapolation: t outside the step,
   or before the first step any t other than st->t, is VLBE_EARG, and so is
   a t that is not finite.  q, v (n each, may be NULL): outputs.  lambda is
   not offered: an index-2 variable, left out of the error test, whose
   interpolant would carry no such error bound.  Reads the state only. */
VLBE_API vlbe_status vlbe_bdf_interp(const vlbe_bdf *st, vlbe_real t, vlbe_real *q, vlbe_real *v)
{
    int n, j, k;
    vlbe_real tt, c = VLBE_R(1.0), gam;
    const vlbe_real *p1;
    VLBE_ASSERT(st != NULL && st->sys != NULL);
    n = st->n;
    if (!isfinite(t)) return VLBE_EARG;
    if (t == st->t) {
        if (q) vlbe_vec_copy(n, st->q, q);
        if (v) vlbe_vec_copy(n, st->v, v);
        return VLBE_OK;
    }
    if (st->order_last < 1 || t > st->t || t < st->t - st->h_last) return VLBE_EARG;
    k = st->order_last;
    tt = t - st->t;
    p1 = vlbe__bdf_phi(st, 1);
    if (q) vlbe_vec_copy(n, p1, q);
    if (v) vlbe_vec_copy(n, p1 + n, v);
    gam = tt / st->psi_[1];
    for (j = 2; j <= k + 1; ++j) {
        const vlbe_real *pj = vlbe__bdf_phi(st, j);
        c *= gam;
        gam = (tt + st->psi_[j - 1]) / st->psi_[j];
        if (q) vlbe_vec_axpy(n, c, pj, q);
        if (v) vlbe_vec_axpy(n, c, pj + n, v);
    }
    return VLBE_OK;
}

#endif /* VLBE_INTEGRATORS_H */
