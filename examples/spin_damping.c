/* spin_damping.c -- spin-up of a flexible cantilever on a hub (rotating-beam
   scene 3): internal damping computed from the deformation (Kelvin-Voigt on
   the strain rates, frame invariant) against damping on the absolute nodal
   velocities, Q_d = -(abs_a M + abs_b K0) v, for final hub speeds W = 2, 6,
   10 rad/s.  The planar ANCF beam of ancf_ale.h (SP_ANCF of ex_spin.h).
   -- part of vlbe                                  SPDX-License-Identifier: MIT

   cc -O2 examples/spin_damping.c -lm && ./a.out [outdir]

   Scene of spin_up.c: L = 10 m, EA = 2.8e7 N, EI = 1.4e4 N m^2, rhoA = 1.2
   kg/m; hub speed rising smoothly from 0 to W in Ts = 15 s, run to 20 s; 8
   elements, HHT alpha = -0.05, h = 5 ms.  Four damping models, all tuned
   to damp the first bending mode of the beam at rest by zeta = 2 %
   (omega_1 = 3.80 rad/s):
     undamped
     Kelvin-Voigt   c_kv = 2 zeta / omega_1 on axial strain and curvature
     abs. K0        abs_b = the same c: -c K0 v, K0 the stiffness of the
                    straight beam at rest (at rest the same damping matrix
                    as Kelvin-Voigt)
     abs. M         abs_a = 2 zeta omega_1: -abs_a M v
   Kelvin-Voigt damping sees strain rates only: a rigid rotation costs no
   power, and after the spin-up the beam settles to the undamped steady
   state (transverse tip 0 in the hub frame).  Absolute damping also brakes
   the rigid rotation:
     abs. M   at the steady speed W a point at radius x moves at W x, so the
              beam carries the drag q(x) = -abs_a rhoA W x per length
              (against the rotation), a steady load in the hub frame that
              the hub torque balances: a steady lag of the tip.  Reference:
              the static equilibrium of the beam in the hub frame under the
              drag and the centrifugal load rhoA W^2 r (both on the deformed
              beam), an extensible elastica solved by shooting below (no
              element in it).  Without centrifugal stiffening the linear
              cantilever under the triangular load q0 x / L, q0 = -abs_a
              rhoA W L, deflects by 11 q0 L^4 / (120 EI): the bound printed
              beside it (the tension rhoA W^2 (L^2 - x^2)/2 stiffens the
              beam and the spinning beam deflects less).
     abs. K0  K0 is fixed in space: a beam turned by theta moving rigidly
              at W has the axial (x) velocity -W x sin(theta), a strain
              rate of -W sin(theta) in K0's eyes: it dissipates abs_b EA L
              W^2 sin^2(theta) (tests/test_spin_damping.c), a braking
              torque abs_b EA L W sin^2(theta) on a rigid beam, 7e4 N m at
              theta = 0.29 rad, W = 0.3 rad/s, against a bending strength
              of 3 EI/L^2 = 420 N m per metre of tip deflection.  The beam
              is held back and folds long before the spin-up ends, at every
              W: the run stops when the tip leaves |tip| <= SD_BOUND in the
              hub frame, at a hub angle of about 0.29 rad whatever W (with
              the bound off the tip ends up behind the hub, up to 19 m from
              its place).
   Bound SD_BOUND = 2 m (L/5) instead of spin_up's L/10: the abs. M lag at
   W = 10 peaks at 1.25 m during the spin-up.

   No published numbers: the ROW lines compare the abs. M steady tip (axial
   and transverse) with the elastica reference and show the Kelvin-Voigt
   steady tip against 0.
   "Steady" is the mean over [Ts, t_end] (the residual vibration that the
   spin-up leaves, about 1e-3 m, averages out); the tip at t = 20 s and
   the residual amplitude (half the peak-to-peak over the window) are
   printed too, and the abs. M steady tip's convergence in mesh and step.
   Output: <outdir>/spin_damping_w<W>.csv (t, axial and transverse tip of
   each model, nan after a stop) and <outdir>/spin_damping_w<W>.svg
   (transverse tip, all models, and the abs. M reference). */
#include "../scenes/ex_spin.h"
#include "../scenes/svgplot.h"

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

#ifndef VLBE_EXAMPLE_NO_MAIN

static void print_run(int kind, const sp_out *o, const sd_rec *r)
{
    printf("  %-12s %-14s %6.2f  %+.4e %+.4e  %+.4e %.2e  %.3e  %6ld %6ld %7.3f\n",
           sd_kind_name(kind), vlbe_status_str(o->status), o->t_stop, o->tip_end[0],
           o->tip_end[1], sd_rec_mean(r), sd_rec_amp(r), o->tip_max[1], o->stats.steps,
           o->stats.newton_iters, o->cpu);
}

/* one ROW line "W=<W>: what"; the relative error where the reference is
   a nonzero number */
static void row(double W, const char *what, double ref, double ours, const sp_out *o)
{
    char q[192];
    snprintf(q, sizeof q, "W=%g: %s", W, what);
    svgp_compare_row(stdout, "spin damping", q, ref, ours,
                     isnan(ref) || ref == 0.0 ? (double)NAN : ours / ref - 1.0, o->cpu);
}

static void write_scene(const char *dir, double W, const sd_rec *rec, const sp_out *out,
                        double ref_tr, double t_end)
{
    static char names[SD_NKIND][96];
    static const char *const cols[SD_NKIND] = {"undamped", "kelvin_voigt", "abs_K0", "abs_M"};
    char path[512], title[160], head[512];
    double rx[2], ry[2];
    svgp_chart ch;
    FILE *csv;
    int k, j, len = 0;
    len += snprintf(head + len, sizeof head - (size_t)len, "t");
    for (j = 0; j < SD_NKIND; ++j)
        len += snprintf(head + len, sizeof head - (size_t)len, ",%s_axial,%s_transverse", cols[j],
                        cols[j]);
    /* the undamped run reaches t_end: its time grid is every run's */
    snprintf(path, sizeof path, "%s/spin_damping_w%g.csv", dir, W);
    csv = svgp_csv_open(path, head);
    if (csv) {
        for (k = 0; k < rec[0].h.n; ++k) {
            double row[1 + 2 * SD_NKIND];
            row[0] = rec[0].h.t[k];
            for (j = 0; j < SD_NKIND; ++j) {
                row[1 + 2 * j] = k < rec[j].h.n ? rec[j].h.ax[k] : (double)NAN;
                row[2 + 2 * j] = k < rec[j].h.n ? rec[j].h.tr[k] : (double)NAN;
            }
            svgp_csv_row(csv, 1 + 2 * SD_NKIND, row);
        }
        fclose(csv);
    } else
        printf("could not write %s\n", path);
    snprintf(title, sizeof title,
             "spin-up W = %g rad/s, damping 2%% of mode 1 at rest: transverse tip (hub frame)", W);
    svgp_init(&ch, title, "t [s]", "transverse tip deflection [m]", 0, 0);
    svgp_xrange(&ch, 0.0, t_end);
    ch.legend = SVGP_LEGEND_BR; /* below the steady tips, right of the abs. K0 stop */
    for (j = 0; j < SD_NKIND; ++j) {
        if (out[j].status == VLBE_EBOUND)
            snprintf(names[j], sizeof names[j], "%s (|tip| > %g m at t = %.2f s)",
                     sd_kind_name(j), SD_BOUND, out[j].t_stop);
        else
            snprintf(names[j], sizeof names[j], "%s", sd_kind_name(j));
        svgp_series(&ch, names[j], rec[j].h.n, rec[j].h.t, rec[j].h.tr, 0);
    }
    rx[0] = rec[0].t0;
    rx[1] = t_end;
    ry[0] = ry[1] = ref_tr;
    svgp_series(&ch, "abs. M: static reference (elastica)", 2, rx, ry, SVGP_DASH);
    snprintf(path, sizeof path, "%s/spin_damping_w%g.svg", dir, W);
    if (svgp_write_file(&ch, path)) printf("could not write %s\n", path);
}

int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : "out";
    static const double Ws[3] = {2.0, 6.0, 10.0};
    static sp_model m;
    static sd_rec rec[SD_NKIND];
    int iw, k, ok = 1;
    sp_cfg c;
    sd_cfg(&c, 2.0, SD_UNDAMPED);
    printf("spin-up of a cantilever on a hub with internal damping: L = %g m, EA = %g N, EI = "
           "%g N m^2, rhoA = %g kg/m; Ts = %g s, t_end = %g s\n",
           c.L, c.EA, c.EI, c.rhoA, c.Ts, c.t_end);
    printf("ANCF, %d elements, h = %g s, HHT alpha = %g, bound |tip| <= %g m (hub frame); "
           "omega_1 = %.4f rad/s, zeta = %g at rest:\n",
           c.ne, c.h, c.alpha, SD_BOUND, sp_omega1(&c), SD_ZETA);
    printf("  c_kv = abs_b = 2 zeta/omega_1 = %.5f s, abs_a = 2 zeta omega_1 = %.5f 1/s\n",
           2.0 * SD_ZETA / sp_omega1(&c), 2.0 * SD_ZETA * sp_omega1(&c));
    printf("  steady = mean transverse tip over [Ts, t_end], amp = half its peak-to-peak there\n");
    printf("  %-12s %-14s %6s  %-23s  %-21s  %-9s  %6s %6s %7s\n", "damping", "status", "t_stop",
           "tip at end: ax., tr. [m]", "steady tr., amp [m]", "max|tr|", "steps", "Newton",
           "cpu [s]");
    for (iw = 0; iw < 3; ++iw) {
        const double W = Ws[iw];
        sp_out out[SD_NKIND];
        sd_ref rb;
        double ref[2] = {NAN, NAN}, lin, g[3], aa;
        printf("W = %g rad/s\n", W);
        for (k = 0; k < SD_NKIND; ++k) {
            sd_run(&m, W, k, 10, &rec[k], &out[k]);
            print_run(k, &out[k], &rec[k]);
            if (out[k].status != VLBE_OK && !(k == SD_ABS_K && out[k].status == VLBE_EBOUND))
                ok = 0;
        }
        sd_cfg(&c, W, SD_ABS_M);
        aa = c.abs_a;
        sd_ref_set(&rb, &c, W, aa);
        if (sd_ref_tip(&rb, SD_NS_REF, ref)) {
            printf("  reference: shooting did not converge\n");
            ok = 0;
        }
        lin = sd_lin_tip(&c, W, aa);
        printf("  abs. M reference (elastica, drag + centrifugal): tip (%+.5e, %+.5e) m; "
               "|steady tr. - ref| = %.2e m (%.3f%% of |ref|); no stiffening 11 q0 L^4/(120 "
               "EI) = %+.4f m\n",
               ref[0], ref[1], fabs(sd_rec_mean(&rec[SD_ABS_M]) - ref[1]),
               100.0 * fabs(sd_rec_mean(&rec[SD_ABS_M]) / ref[1] - 1.0), lin);
        sp_theta(&c, out[SD_ABS_K].t_stop, g);
        printf("  abs. K0 left the bound at t = %.3f s: hub angle %.3f rad, speed %.3f rad/s\n",
               out[SD_ABS_K].t_stop, g[0], g[1]);
        write_scene(dir, W, rec, out, ref[1], c.t_end);

        row(W, "abs. M steady transverse tip [m] (static elastica)", ref[1],
            sd_rec_mean(&rec[SD_ABS_M]), &out[SD_ABS_M]);
        row(W, "abs. M steady axial tip [m] (static elastica)", ref[0],
            sd_rec_mean_ax(&rec[SD_ABS_M]), &out[SD_ABS_M]);
        row(W, "abs. M max abs. transverse tip [m]", NAN, out[SD_ABS_M].tip_max[1],
            &out[SD_ABS_M]);
        row(W, "Kelvin-Voigt steady transverse tip [m] (0)", 0.0, sd_rec_mean(&rec[SD_KV]),
            &out[SD_KV]);
        row(W, "Kelvin-Voigt transverse tip at t=20 s [m]", NAN, out[SD_KV].tip_end[1],
            &out[SD_KV]);
        row(W, "Kelvin-Voigt max abs. transverse tip [m]", NAN, out[SD_KV].tip_max[1],
            &out[SD_KV]);
        row(W, "undamped steady transverse tip [m] (0)", 0.0, sd_rec_mean(&rec[SD_UNDAMPED]),
            &out[SD_UNDAMPED]);
        row(W, "abs. K0: tip leaves the bound (2 m) at t [s]", NAN, out[SD_ABS_K].t_stop,
            &out[SD_ABS_K]);
    }

    /* the abs. M steady tip in mesh and step (the error budget of
       tests/test_spin_damping.c) */
    printf("\nconvergence (abs. M): steady transverse and axial tip against the elastica\n");
    printf("  %4s %4s %8s  %-13s %-10s  %-13s %-10s  %7s\n", "W", "ne", "h [s]", "steady tr.",
           "rel. err", "steady ax.", "rel. err", "cpu [s]");
    for (iw = 1; iw < 3; ++iw) {
        static const int nes[4] = {4, 8, 16, 8};
        static const double hs[4] = {5e-3, 5e-3, 5e-3, 2.5e-3};
        sd_ref rb;
        double ref[2];
        sd_cfg(&c, Ws[iw], SD_ABS_M);
        sd_ref_set(&rb, &c, Ws[iw], c.abs_a);
        if (sd_ref_tip(&rb, SD_NS_REF, ref)) ok = 0;
        for (k = 0; k < 4; ++k) {
            sp_out o;
            sd_cfg(&c, Ws[iw], SD_ABS_M);
            c.ne = nes[k];
            c.h = hs[k];
            sd_rec_init(&rec[0], 1000000, c.Ts);
            sp_run(&m, &c, sd_rec_obs, &rec[0], &o);
            if (o.status != VLBE_OK) ok = 0;
            printf("  %4g %4d %8g  %+.6e %+.2e  %+.6e %+.2e  %7.3f\n", Ws[iw], c.ne, c.h,
                   sd_rec_mean(&rec[0]), sd_rec_mean(&rec[0]) / ref[1] - 1.0,
                   sd_rec_mean_ax(&rec[0]), sd_rec_mean_ax(&rec[0]) / ref[0] - 1.0, o.cpu);
        }
    }
    return ok ? 0 : 1;
}
#endif
