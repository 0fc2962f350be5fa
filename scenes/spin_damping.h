/* spin_damping.h -- the damping models of the spin-up (rotating-beam
   scene 3) on the model and run driver of ex_spin.h: the scene per
   damping model (sd_cfg), the tip record of a run (sd_rec, sd_run), the
   steady state in the hub frame by shooting (sd_ref_tip) and the linear
   cantilever's tip (sd_lin_tip).  Shared by examples/spin_damping.c, which
   states the scene, and tests/test_spin_damping.c.
   -- part of vlbe                                  SPDX-License-Identifier: MIT */
#ifndef VLBE_SCENE_SPIN_DAMPING_H
#define VLBE_SCENE_SPIN_DAMPING_H

#include "ex_spin.h"

#include <stdio.h>

/* damping models */
#define SD_UNDAMPED 0
#define SD_KV 1
#define SD_ABS_K 2
#define SD_ABS_M 3
#define SD_NKIND 4

#define SD_ZETA 0.02  /* first-mode damping ratio at rest              */
#define SD_BOUND 2.0  /* |tip| bound in the hub frame [m]              */
#define SD_NS_REF 2000 /* RK4 steps of the reference (shooting)        */

static inline const char *sd_kind_name(int kind)
{
    static const char *const names[SD_NKIND] = {"undamped", "Kelvin-Voigt", "abs. K0",
                                                "abs. M"};
    return kind >= 0 && kind < SD_NKIND ? names[kind] : "?";
}

/* The scene at final speed W with damping model `kind`. */
static inline void sd_cfg(sp_cfg *c, double W, int kind)
{
    double w1;
    sp_cfg_default(c, W, SP_ANCF);
    c->bound = SD_BOUND;
    w1 = sp_omega1(c);
    if (kind == SD_KV) c->c_kv = 2.0 * SD_ZETA / w1;
    if (kind == SD_ABS_K) c->abs_b = 2.0 * SD_ZETA / w1;
    if (kind == SD_ABS_M) c->abs_a = 2.0 * SD_ZETA * w1;
}

/* The tip record of a run: the history (every `every`-th step) and over
   the window t >= t0 the mean axial tip and the transverse tip's mean,
   least and largest value. */
typedef struct sd_rec {
    sp_hist h; /* the history */
    double t0;
    long cnt;
    double sum_ax, sum, lo, hi;
} sd_rec;

static inline void sd_rec_init(sd_rec *r, long every, double t0)
{
    memset(r, 0, sizeof *r);
    r->h.every = every;
    r->t0 = t0;
    r->lo = HUGE_VAL;
    r->hi = -HUGE_VAL;
}

static inline void sd_rec_obs(void *ctx, const sp_model *m, double t, const double *tip,
                              const vlbe_real *q, const vlbe_real *v)
{
    sd_rec *r = (sd_rec *)ctx;
    sp_hist_obs(&r->h, m, t, tip, q, v);
    if (t >= r->t0 - 1e-9) {
        ++r->cnt;
        r->sum_ax += tip[0];
        r->sum += tip[1];
        r->lo = fmin(r->lo, tip[1]);
        r->hi = fmax(r->hi, tip[1]);
    }
}

/* mean transverse tip over the window (NaN if the run never got there) */
static inline double sd_rec_mean(const sd_rec *r)
{
    return r->cnt ? r->sum / (double)r->cnt : (double)NAN;
}

/* mean axial tip over the window (NaN if the run never got there) */
static inline double sd_rec_mean_ax(const sd_rec *r)
{
    return r->cnt ? r->sum_ax / (double)r->cnt : (double)NAN;
}

/* half the peak-to-peak transverse tip over the window */
static inline double sd_rec_amp(const sd_rec *r)
{
    return r->cnt ? 0.5 * (r->hi - r->lo) : (double)NAN;
}

/* One run of the scene with damping model kind, recorded from Ts on. */
static inline void sd_run(sp_model *m, double W, int kind, long every, sd_rec *rec, sp_out *out)
{
    sp_cfg c;
    sd_cfg(&c, W, kind);
    sd_rec_init(rec, every, c.Ts);
    sp_run(m, &c, sd_rec_obs, rec, out);
}

/* -- reference: the steady state in the hub frame, by shooting -----------
   The beam at rest in the frame turning at W: material coordinate s in
   [0, L], state y = [x, y, phi, nx, ny, mz] (position, angle of the
   tangent, force and moment that the part beyond s exerts on the part
   before it).  Loads per unit length: centrifugal cf (x, y), cf = rhoA W^2,
   and the drag of the absolute mass-proportional damping -abs_a rhoA (W z
   x r) = dr (y, -x), dr = abs_a rhoA W.  Extensible elastica:
        r' = (1 + N/EA)(cos phi, sin phi),  N = n . (cos phi, sin phi),
        phi' = mz / EI,  n' = -f(r),  mz' = -(r' x n)_z,
   clamped at the hub axis (r = 0, phi = 0), free at s = L (n = 0, mz =
   0).  Shooting on the root force and moment, RK4 with ns steps.  (The
   element's Green strain and its curvature per deformed length differ
   from this at O(N/EA) <= 2e-4 of the elastic forces at W = 10.) */
typedef struct sd_ref {
    double L, EA, EI;
    double cf; /* rhoA W^2       [N/m^2] */
    double dr; /* abs_a rhoA W   [N/m^2] */
} sd_ref;

static inline void sd_ref_set(sd_ref *b, const sp_cfg *c, double W, double abs_a)
{
    b->L = c->L;
    b->EA = c->EA;
    b->EI = c->EI;
    b->cf = c->rhoA * W * W;
    b->dr = abs_a * c->rhoA * W;
}

/* the elastica's y' = f(s, y) as an ex_rhs (ctx = the sd_ref; autonomous) */
static inline void sd_ref_rhs(const void *ctx, double s, const double *y, double *dy)
{
    const sd_ref *b = (const sd_ref *)ctx;
    const double cp = cos(y[2]), sp = sin(y[2]);
    const double str = 1.0 + (y[3] * cp + y[4] * sp) / b->EA;
    (void)s;
    dy[0] = str * cp;
    dy[1] = str * sp;
    dy[2] = y[5] / b->EI;
    dy[3] = -(b->cf * y[0] + b->dr * y[1]);
    dy[4] = -(b->cf * y[1] - b->dr * y[0]);
    dy[5] = -(dy[0] * y[4] - dy[1] * y[3]);
}

/* y at s = L from the root force (u[0], u[1]) and moment u[2], ns RK4 steps */
static inline void sd_ref_shoot(const sd_ref *b, const double *u, int ns, double *y)
{
    const double h = b->L / ns;
    int s;
    y[0] = y[1] = y[2] = 0.0;
    y[3] = u[0];
    y[4] = u[1];
    y[5] = u[2];
    for (s = 0; s < ns; ++s) ex_rk4_step(6, sd_ref_rhs, b, s * h, h, y);
}

/* 3 x 3 determinant (Cramer's rule below: the reference stays in double
   whatever vlbe_real is, so the library's vlbe_real LU is not used) */
static inline double sd_det3(const double *A)
{
    return A[0] * (A[4] * A[8] - A[5] * A[7]) - A[1] * (A[3] * A[8] - A[5] * A[6]) +
           A[2] * (A[3] * A[7] - A[4] * A[6]);
}

/* scaled residual: the end force and moment over the load scale */
static inline double sd_ref_res(const sd_ref *b, const double *u, int ns, const double *sc,
                                double *F, double *y)
{
    sd_ref_shoot(b, u, ns, y);
    F[0] = y[3];
    F[1] = y[4];
    F[2] = y[5];
    return fmax(fmax(fabs(F[0]) / sc[0], fabs(F[1]) / sc[1]), fabs(F[2]) / sc[2]);
}

/* The steady tip in the hub frame (axial x(L) - L, transverse y(L)).
   Newton on the root force and moment (Jacobian by central differences,
   Cramer; the step halved while it does not lower the residual) until the
   end force and moment vanish to 1e-11 of the load scale, continued in the
   load (cf, dr scaled by k/SD_REF_NCONT, k = 1 .. SD_REF_NCONT, each from
   the last solution: from the straight beam's reactions alone Newton
   diverges at W = 10, where the tension carries most of the drag).  0 on
   success, -1 if Newton does not converge. */
#define SD_REF_NCONT 8
static inline int sd_ref_tip(const sd_ref *b, int ns, double *tip)
{
    const double fs = (b->cf + b->dr) * b->L * b->L + b->EI / (b->L * b->L); /* force scale */
    const double sc[3] = {fs, fs, fs * b->L};
    double u[3] = {0.0, 0.0, 0.0}, y[6], F[3], res = 0.0;
    int k, it = 0, i, j;
    for (k = 1; k <= SD_REF_NCONT; ++k) {
        sd_ref bk = *b;
        bk.cf = b->cf * k / SD_REF_NCONT;
        bk.dr = b->dr * k / SD_REF_NCONT;
        res = sd_ref_res(&bk, u, ns, sc, F, y);
        for (it = 0; it < 30 && res > 1e-11; ++it) {
            double J[9], A[9], du[3], d, s = 1.0;
            int ls;
            for (j = 0; j < 3; ++j) {
                double up[3], yp[6], ym[6];
                const double h = 1e-6 * sc[j];
                for (i = 0; i < 3; ++i) up[i] = u[i];
                up[j] = u[j] + h;
                sd_ref_shoot(&bk, up, ns, yp);
                up[j] = u[j] - h;
                sd_ref_shoot(&bk, up, ns, ym);
                for (i = 0; i < 3; ++i) J[3 * i + j] = (yp[3 + i] - ym[3 + i]) / (2.0 * h);
            }
            d = sd_det3(J);
            if (!(fabs(d) > 0.0)) return -1;
            for (j = 0; j < 3; ++j) {
                for (i = 0; i < 9; ++i) A[i] = J[i];
                for (i = 0; i < 3; ++i) A[3 * i + j] = F[i];
                du[j] = sd_det3(A) / d;
            }
            for (ls = 0; ls < 20; ++ls, s *= 0.5) {
                double ut[3], Ft[3], rt;
                for (j = 0; j < 3; ++j) ut[j] = u[j] - s * du[j];
                rt = sd_ref_res(&bk, ut, ns, sc, Ft, y);
                if (rt < res) {
                    for (j = 0; j < 3; ++j) u[j] = ut[j], F[j] = Ft[j];
                    res = rt;
                    break;
                }
            }
            if (ls == 20) return -1;
        }
        if (!(res <= 1e-11)) return -1;
    }
    sd_ref_shoot(b, u, ns, y);
    tip[0] = y[0] - b->L;
    tip[1] = y[1];
    return 0;
}

/* linear cantilever under q0 x / L, no centrifugal stiffening: tip
   deflection 11 q0 L^4 / (120 EI), q0 = -abs_a rhoA W L */
static inline double sd_lin_tip(const sp_cfg *c, double W, double abs_a)
{
    const double q0 = -abs_a * c->rhoA * W * c->L;
    return 11.0 * q0 * pow(c->L, 4.0) / (120.0 * c->EI);
}

#endif /* VLBE_SCENE_SPIN_DAMPING_H */
