/* bench_inv.c -- cost of the axial (cable) force of fixed-length planar ANCF
   elements by three routes of ancf_ale.h: Gauss points (vlbe_ale_force,
   5 points), element invariants (vlbe_ale_inv_force: unit tables B, I
   scaled to L) and system invariants (vlbe_ale_inv_sys_force: the tables
   of a whole chain assembled once), per element and for whole chains.

   build (from the repository root; `make bench` does this):
       cc -std=c99 -O3 -march=native bench/bench_inv.c -o build/bench/bench_inv -lm
   run from the repository root:  build/bench/bench_inv [tag]
   writes out/bench/inv[-tag].csv, inv[-tag].svg (element, chains) and
   out/bench/inv_step[-tag].csv, inv_step[-tag].svg (per step of scene 1;
   out/bench must exist).

   Element: a steel wire cable (d = 5 mm: rhoA = 0.154 kg/m, EA = 4.1 MN,
   c_eps = 1 ms, gravity as the load), NO_BEND, both p fixed, L = 0.25 m,
   bent to an arc of radius 0.5 m, stretched 0.2 %, rotating at 0.8 rad/s;
   with Kelvin-Voigt damping unless the row says undamped.  Chains: ne
   such elements along a circle of radius 0.5 ne L / pi (half a turn), same
   stretch and rotation; K and D in band storage (VLBE_ALE_INV_BW per row)
   for all three routes, so that they produce the same output.  The chain
   rows of Gauss and element invariants are vlbe_ale_inv_chain_force (an
   element loop: gather, element call, scatter into the band).

   Method as in bench_ale.c: NSTATE perturbed copies of each state cycled
   through, one output entry per call summed into a volatile sink, the mode
   read at run time; per configuration a warm-up and calibration, then
   BENCHU_BATCHES rounds of one batch per configuration (interleaved round robin,
   so that a disturbance of the shared machine spreads over all rows), each
   batch >= 0.2 ms.  Reported: median (min) ns per call over the batches; a
   row whose median exceeds 1.15 times its min is marked '*'.

   Per step of scene 1 (scenes/ex_spin.h: the ANCF beam with bending, L
   = 10 m, spin-up to W = 6 rad/s; cfg.inv = SP_GAUSS, SP_INV_ELEM,
   SP_INV_SYS; the invariant routes take the axial force from the tables
   and keep bending on Gauss points, the system route with a second element
   type with EA = 0 for it), HHT-alpha -0.05 at the scene's h = 5 ms, for
   4..64 elements, each route with dense and with banded matrices
   (cfg.band: the chain's band in the augmented order, the integrator's
   band LU; workspace from the _sys queries).  A warm-up run from rest to
   STEP_T1 = 10 s (sp_run's loop) records the tip at every step (the routes
   and storages must agree: max difference to the dense Gauss route
   reported) and the state at STEP_T0 = 8 s;
   the timed window restarts from that state (vlbe_hht_init at 8 s) and
   takes the 400 steps to 10 s.  The window sits in the spin-up, where the
   scene spends its work from t = 4 s on: about 4 Newton iterations and one
   LU (so one K, D evaluation) per step; the first 2 s are not
   representative (2.8 Newton iterations and 0.015 LU per step).  Each
   callback of the vlbe_dae is timed inside the runs (force; force_jac;
   the mass matrix, which the HHT iteration assembles at every Newton
   iteration; constraints); the rest is the integrator's own work (dense
   LU, solves, residual).  A first window run calibrates how many runs
   make one sample (>= 50 ms), then STEP_ROUNDS interleaved rounds; median
   (min) us per step.  A route whose run fails is reported with its status
   (and ns per call of the calls it made) and not timed.  Then the whole
   scene (20 s, sp_run) with each route at 4, 8, 16 elements: max tip
   difference over the 40 samples.

   Measured (-O3 -march=native, gcc 12.2.0, AMD EPYC Zen 4 2.6 GHz, 2
   cores, one used; interleaved rounds), us per step in the window, Gauss /
   element invariants / system invariants:
       4 el. 14.5 / 16.5 / 16.0,  8 el. 30.3 / 34.4 / 32.8,
      16 el. 73.1 / 81.2 / 78.0, 32 el. 208.3 / 224.5 / 218.2,
      64 el. 733.9 / 768.0 / 756.0.
   The element invariants cost 5-14 % more per step than Gauss points, the
   system invariants 3-10 % more; system vs element invariants 1.02-1.05
   per step, nowhere near the paper's order of magnitude.  Why: with
   bending the invariant routes still evaluate r', r'' at the Gauss points
   for the curvature, which is most of the Gauss route's work (it takes the
   axial strain from the same points), and add the axial contraction on
   top.  And the force callbacks are only 16-46 % of a step (the share
   falls with ne): the rest is the mass matrix, which the HHT iteration
   assembles at every Newton iteration (2.0 -> 54 us per step), and the
   integrator's dense LU (one per step in the spin-up) and solves (36 % of
   the step at 4 el., 75 % at 64).  Over 0..10 s the tips agree with the
   Gauss route's to 7e-13 (element invariants) and 3e-13 .. 6e-13 (system
   invariants) at every size.  (Before the system route moved to
   translation-free slots, its rounding grew with the chain: 1e-5 of max
   |Q| at 64 el., and HHT's Newton failed at 32 and 64 el.)  So Gauss
   points stay the default (vlbe_ale_force, and cfg.inv = SP_GAUSS in
   ex_spin.h): faster per step at every size here.
   Banded (one run on a shared machine, us per step, Gauss dense /
   banded): 4 el. 14.0 / 16.2, 8 el. 30.5 / 27.0, 16 el. 79.0 / 52.9,
   32 el. 246.0 / 99.5, 64 el. 874.3 / 198.3 (target <= 200 us at 64
   elements; a busier run: 966 / 230).  Banded wins from 8 elements on,
   4.4x at 64; the callbacks are then half of the step (Q 51, K and D 58
   us), the integrator's band LU, solves and products the other half
   (87 us); the clamp's rows set kl = ku = 10 for the whole chain. */
#define _POSIX_C_SOURCE 199309L
#include "../ancf_ale.h"
#include "../scenes/ex_spin.h"
#include "../scenes/svgplot.h"
#include "bench_util.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MIN_CALLS 2000L
#define NSTATE 8
#define NE_MAX 64
#define N_MAX (4 * (NE_MAX + 1))
#define NCH 5 /* chain sizes */

static const int chain_ne[NCH] = {4, 8, 16, 32, 64};
static volatile double sink;
static volatile unsigned mode_src;

static unsigned long long rng_state = 0x9E3779B97F4A7C15ULL;
static double urand(void) { return benchu_urand(&rng_state); }

/* -- states ------------------------------------------------------------------ */
#define LEL 0.25
static vlbe_real qs[NSTATE][10], qds[NSTATE][10];
static vlbe_real xs[NCH][NSTATE][N_MAX], vs[NCH][NSTATE][N_MAX];
static vlbe_real Ls[NE_MAX];

/* node k of ne on an arc of radius R (material spacing LEL), stretched by
   lam, rotating at om about the origin: x[4], v[4] */
static void arc_node(double R, int k, double *x, double *v)
{
    const double lam = 1.002, om = 0.8, th = 0.3 + k * LEL / R;
    const double r[2] = {lam * R * sin(th), lam * R * (1.0 - cos(th))};
    const double rp[2] = {lam * cos(th), lam * sin(th)};
    x[0] = r[0];
    x[1] = r[1];
    x[2] = rp[0];
    x[3] = rp[1];
    v[0] = 0.4 - om * r[1];
    v[1] = -0.2 + om * r[0];
    v[2] = -om * rp[1];
    v[3] = om * rp[0];
}

static void make_states(void)
{
    double x[4], v[4];
    int s, c, k, i;
    for (s = 0; s < NSTATE; ++s) {
        for (k = 0; k < 2; ++k) {
            arc_node(0.5, k, x, v);
            for (i = 0; i < 4; ++i) {
                qs[s][5 * k + i] = (vlbe_real)(x[i] * (1.0 + 1e-7 * urand()));
                qds[s][5 * k + i] = (vlbe_real)(v[i] * (1.0 + 1e-7 * urand()));
            }
        }
        qs[s][4] = VLBE_R(1.0);
        qs[s][9] = (vlbe_real)(1.0 + LEL);
        qds[s][4] = qds[s][9] = VLBE_R(0.0);
        for (c = 0; c < NCH; ++c) {
            const double R = 0.5 * chain_ne[c] * LEL / 3.14159265358979323846;
            for (k = 0; k <= chain_ne[c]; ++k) {
                arc_node(R, k, x, v);
                for (i = 0; i < 4; ++i) {
                    xs[c][s][4 * k + i] = (vlbe_real)(x[i] * (1.0 + 1e-7 * urand()));
                    vs[c][s][4 * k + i] = (vlbe_real)(v[i] * (1.0 + 1e-7 * urand()));
                }
            }
        }
    }
    for (k = 0; k < NE_MAX; ++k) Ls[k] = (vlbe_real)LEL;
}

/* -- configurations -------------------------------------------------------------- */
enum { R_GAUSS, R_ELEM, R_SYS, NROUTE };
static const char *const route_name[NROUTE] = {"Gauss points", "element invariants",
                                                "system invariants"};
static const char *const route_csv[NROUTE] = {"gauss", "elem_inv", "sys_inv"};

typedef struct cfg {
    int route, jac, ch; /* ch: chain index, -1 for one element */
    unsigned mode;      /* NO_DAMP or 0 */
    double med, min;
    long calls;
} cfg;

static vlbe_ale_elem el;
static vlbe_ale_inv_sys sys_d[NCH], sys_1[2]; /* damped chains; one element damped, undamped */
static vlbe_real work_d[NCH][158 * NE_MAX + 40], work_1[2][158 + 40];

/* one timed batch of k calls; seconds per call */
static double batch(const cfg *c, long k, long *bad)
{
    static vlbe_real Q[N_MAX], K[N_MAX * VLBE_ALE_INV_BW], D[N_MAX * VLBE_ALE_INV_BW];
    const unsigned mode = mode_src;
    const int jac = c->jac;
    double t0, acc = 0.0;
    long r, nbad = 0;
    t0 = benchu_now();
    if (c->ch < 0) {
        for (r = 0; r < k; ++r) {
            const int s = (int)(r & (NSTATE - 1));
            vlbe_status st;
            if (c->route == R_GAUSS)
                st = vlbe_ale_force(&el, mode, qs[s], qds[s], Q, jac ? K : NULL, jac ? D : NULL);
            else if (c->route == R_ELEM)
                st = vlbe_ale_inv_force(&el, mode, qs[s], qds[s], Q, jac ? K : NULL, jac ? D : NULL);
            else {
                /* one element as a system: same layout as a chain of 1 */
                vlbe_real x[8], v[8];
                int i;
                for (i = 0; i < 4; ++i) {
                    x[i] = qs[s][i];
                    x[4 + i] = qs[s][5 + i];
                    v[i] = qds[s][i];
                    v[4 + i] = qds[s][5 + i];
                }
                st = vlbe_ale_inv_sys_force(&sys_1[(mode & VLBE_ALE_NO_DAMP) != 0], x, v, Q,
                                            jac ? K : NULL, jac ? D : NULL);
            }
            nbad += st != VLBE_OK;
            acc += (double)Q[r % 8] + (jac ? (double)K[r % 100] + (double)D[(7 * r) % 100] : 0.0);
        }
    } else {
        const int ne = chain_ne[c->ch], n = 4 * (ne + 1);
        for (r = 0; r < k; ++r) {
            const int s = (int)(r & (NSTATE - 1));
            vlbe_status st;
            if (c->route == R_SYS)
                st = vlbe_ale_inv_sys_force(&sys_d[c->ch], xs[c->ch][s], vs[c->ch][s], Q,
                                            jac ? K : NULL, jac ? D : NULL);
            else
                st = vlbe_ale_inv_chain_force(&el, mode | (c->route == R_ELEM ? VLBE_ALE_INV_AXIAL : 0u),
                                              ne, Ls, xs[c->ch][s], vs[c->ch][s], Q, jac ? K : NULL,
                                              jac ? D : NULL);
            nbad += st != VLBE_OK;
            acc += (double)Q[r % n] + (jac ? (double)K[(5 * r) % (n * VLBE_ALE_INV_BW)] : 0.0);
        }
    }
    t0 = benchu_now() - t0;
    sink = acc;
    *bad += nbad;
    return t0 / (double)k;
}

static unsigned cfg_mode(const cfg *c)
{
    return c->mode | VLBE_ALE_NO_BEND | VLBE_ALE_FIX_P1 | VLBE_ALE_FIX_P2;
}

/* calibration, then BENCHU_BATCHES interleaved rounds over all configurations */
static void measure(cfg *cs, int nc, long *bad)
{
    static double t[128][BENCHU_BATCHES];
    int i, b;
    for (i = 0; i < nc; ++i) {
        double s;
        mode_src = cfg_mode(&cs[i]);
        cs[i].calls = MIN_CALLS;
        s = batch(&cs[i], cs[i].calls, bad);
        if (s * (double)cs[i].calls < BENCHU_MIN_BATCH_S)
            cs[i].calls = (long)(BENCHU_MIN_BATCH_S / (s > 1e-10 ? s : 1e-10)) + 1;
        if (cs[i].calls > BENCHU_MAX_CALLS) cs[i].calls = BENCHU_MAX_CALLS;
        if (cs[i].calls < MIN_CALLS) cs[i].calls = MIN_CALLS;
    }
    for (b = 0; b < BENCHU_BATCHES; ++b)
        for (i = 0; i < nc; ++i) {
            mode_src = cfg_mode(&cs[i]);
            t[i][b] = batch(&cs[i], cs[i].calls, bad);
        }
    for (i = 0; i < nc; ++i) {
        qsort(t[i], BENCHU_BATCHES, sizeof t[i][0], benchu_cmp_double);
        cs[i].med = 1e9 * t[i][BENCHU_BATCHES / 2];
        cs[i].min = 1e9 * t[i][0];
    }
}

/* -- per step of scene 1 (scenes/ex_spin.h) -------------------------------- */
#define STEP_W 6.0       /* rad/s, scene 1                                  */
#define STEP_T0 8.0      /* s: the timed window of the scene: from here     */
#define STEP_T1 10.0     /* s: to here (400 steps of 5 ms)                   */
#define STEP_ROUNDS 11   /* interleaved rounds over all configurations       */
#define STEP_MIN_S 0.05  /* s: a round's sample repeats the run up to this   */
#define STEP_NOBS 2048   /* tip records per run (>= STEP_T1 / h + 1)         */
#define STEP_NFULL 3     /* the whole-scene check runs: chain_ne[0 .. 2]      */
#define NSTO 2           /* storage of the matrices: dense, banded (cfg.band) */
static const char *const sto_name[NSTO] = {"", " banded"};
static const char *const sto_csv[NSTO] = {"dense", "banded"};

static const int step_route[NROUTE] = {SP_GAUSS, SP_INV_ELEM, SP_INV_SYS};

/* The model's vlbe_dae with every callback timed (CLOCK_MONOTONIC around
   each call, ~2 x 20 ns) and passed through. */
enum { TM_FORCE, TM_JAC, TM_MASS, TM_OTHER, NTM }; /* Q; K, D; M; constraints, mass_jac */
typedef struct dae_timer {
    vlbe_dae in;
    double s[NTM]; /* seconds per kind of callback */
    long n[NTM];   /* calls                        */
} dae_timer;

static int tm_done(void *u, int kind, double t0, int rc)
{
    dae_timer *w = (dae_timer *)u;
    w->s[kind] += benchu_now() - t0;
    ++w->n[kind];
    return rc;
}

#define TM_IN ((const dae_timer *)u)->in
static int tm_mass(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v, vlbe_real *M)
{
    const double t0 = benchu_now();
    return tm_done(u, TM_MASS, t0, TM_IN.mass(TM_IN.user, t, q, v, M));
}

static int tm_force(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v, vlbe_real *Q)
{
    const double t0 = benchu_now();
    return tm_done(u, TM_FORCE, t0, TM_IN.force(TM_IN.user, t, q, v, Q));
}

static int tm_force_jac(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v,
                        vlbe_real *K, vlbe_real *D)
{
    const double t0 = benchu_now();
    return tm_done(u, TM_JAC, t0, TM_IN.force_jac(TM_IN.user, t, q, v, K, D));
}

static int tm_constr(void *u, vlbe_real t, const vlbe_real *q, vlbe_real *C)
{
    const double t0 = benchu_now();
    return tm_done(u, TM_OTHER, t0, TM_IN.constr(TM_IN.user, t, q, C));
}

static int tm_constr_jac(void *u, vlbe_real t, const vlbe_real *q, vlbe_real *Cq, vlbe_real *Ct)
{
    const double t0 = benchu_now();
    return tm_done(u, TM_OTHER, t0, TM_IN.constr_jac(TM_IN.user, t, q, Cq, Ct));
}

static int tm_constr_acc(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v,
                         vlbe_real *g)
{
    const double t0 = benchu_now();
    return tm_done(u, TM_OTHER, t0, TM_IN.constr_acc(TM_IN.user, t, q, v, g));
}

static int tm_mass_jac(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v,
                       const vlbe_real *a, vlbe_real *Mq, vlbe_real *Mv)
{
    const double t0 = benchu_now();
    return tm_done(u, TM_OTHER, t0, TM_IN.mass_jac(TM_IN.user, t, q, v, a, Mq, Mv));
}

static int tm_constr_hess(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *lam,
                          vlbe_real *H)
{
    const double t0 = benchu_now();
    return tm_done(u, TM_OTHER, t0, TM_IN.constr_hess(TM_IN.user, t, q, lam, H));
}
#undef TM_IN

/* sys: the timed copy of w->in (a callback the model leaves out stays out);
   the timers keep running until the next tm_wire */
static void tm_wire(dae_timer *w, vlbe_dae *sys)
{
    int k;
    *sys = w->in;
    sys->user = w;
    for (k = 0; k < NTM; ++k) {
        w->s[k] = 0.0;
        w->n[k] = 0;
    }
    sys->mass = w->in.mass ? tm_mass : NULL;
    sys->force = w->in.force ? tm_force : NULL;
    sys->force_jac = w->in.force_jac ? tm_force_jac : NULL;
    sys->constr = w->in.constr ? tm_constr : NULL;
    sys->constr_jac = w->in.constr_jac ? tm_constr_jac : NULL;
    sys->constr_acc = w->in.constr_acc ? tm_constr_acc : NULL;
    sys->mass_jac = w->in.mass_jac ? tm_mass_jac : NULL;
    sys->constr_hess = w->in.constr_hess ? tm_constr_hess : NULL;
}

/* tip (hub frame) after every step of a run, and the state at STEP_T0 */
typedef struct tip_rec {
    const sp_model *m;
    int n, have_x0;
    double t_last;  /* time of the last record [s] */
    vlbe_real *x0;  /* q, v at STEP_T0 (2 n)       */
    double tip[STEP_NOBS][2];
} tip_rec;

static vlbe_status tip_obs(void *ctx, double t, const vlbe_real *q, const vlbe_real *v,
                           const vlbe_real *lambda)
{
    tip_rec *r = (tip_rec *)ctx;
    (void)lambda;
    r->t_last = t;
    if (r->n < STEP_NOBS) sp_tip(r->m, t, q, r->tip[r->n++]);
    if (fabs(t - STEP_T0) <= 1e-9) {
        vlbe_vec_copy(r->m->n, q, r->x0);
        vlbe_vec_copy(r->m->n, v, r->x0 + r->m->n);
        r->have_x0 = 1;
    }
    return VLBE_OK;
}

/* one configuration: chain size index, route, storage; medians over the
   rounds */
typedef struct step_cfg {
    int ch, route, band, reps;         /* reps: window runs per sample   */
    double s[STEP_ROUNDS][NTM + 1];    /* seconds per run: callbacks, total */
    double us[NTM + 1], us_min;        /* us per step: medians; min total */
    long calls[NTM];                   /* calls per window run           */
    double ns_call[NTM];               /* ns per call: median; failed runs: the warm-up */
    vlbe_dae_stats st;                 /* the window; failed: the warm-up */
    vlbe_status status;                /* warm-up, then window           */
    double t_stop, dtip; /* dtip: max |tip - tip of dense Gauss| / max |tip|, 0..STEP_T1 */
    vlbe_real x0[2 * SP_NMAX];         /* q, v at STEP_T0                */
} step_cfg;

static sp_model step_m;
static ex_method step_meth;
static tip_rec step_tips[NSTO][NROUTE];

/* Scene 1 with ANCF at chain_ne[ch] elements, route r, dense or banded
   matrices (HHT-alpha -0.05, h = 5 ms, as sp_run) into step_m and *par;
   -1 on failure. */
static int step_setup(int ch, int r, int band, vlbe_hht_params *par, double *h)
{
    sp_cfg c;
    sp_cfg_default(&c, STEP_W, SP_ANCF);
    c.ne = chain_ne[ch];
    c.inv = step_route[r];
    c.band = band;
    if (sp_init(&step_m, &c) != VLBE_OK || ex_hht_pick(par, c.alpha, c.rho_inf) != VLBE_OK ||
        ex_method_reserve_sys(&step_meth, &step_m.sys) != 0)
        return -1;
    par->max_halvings = 10;
    *h = c.h;
    return 0;
}

/* From rest to STEP_T1 (sp_run's loop), the tips into rec, the state at
   STEP_T0 into p->x0, callbacks timed in *tm; -1 on setup failure. */
static int step_warmup(step_cfg *p, tip_rec *rec, dae_timer *tm, ex_run_out *ro)
{
    static vlbe_real q0[2 * SP_NMAX];
    vlbe_hht_params par;
    vlbe_dae sys;
    if (step_setup(p->ch, p->route, p->band, &par, &step_meth.h) != 0) return -1;
    step_meth.hht = &par;
    sp_rest(&step_m, q0, q0 + step_m.n);
    rec->m = &step_m;
    rec->n = rec->have_x0 = 0;
    rec->x0 = p->x0;
    tm->in = step_m.sys;
    tm_wire(tm, &sys);
    ex_run(&sys, &step_meth, q0, q0 + step_m.n, STEP_T1, tip_obs, rec, NULL, NULL, NULL, ro);
    step_meth.hht = NULL;
    return 0;
}

/* The timed window: from p->x0 at STEP_T0 to STEP_T1, reps times (a fresh
   vlbe_hht_init each); seconds per run, -1 on setup failure.  Callback
   times summed in *tm, counters of the (last) run in *st. */
static double step_window(const step_cfg *p, int reps, dae_timer *tm, vlbe_dae_stats *st,
                          vlbe_status *rc)
{
    vlbe_hht_params par;
    vlbe_hht hs;
    vlbe_dae sys;
    double h, t = 0.0;
    long j, nsteps;
    int k;
    *rc = VLBE_EARG;
    if (step_setup(p->ch, p->route, p->band, &par, &h) != 0) return -1.0;
    nsteps = (long)floor((STEP_T1 - STEP_T0) / h + 0.5);
    tm->in = step_m.sys;
    tm_wire(tm, &sys);
    for (k = 0; k < reps; ++k) {
        const double t0 = benchu_now();
        *rc = vlbe_hht_init(&hs, &sys, &par, (vlbe_real)STEP_T0, p->x0, p->x0 + step_m.n,
                            step_meth.work, step_meth.work_len, step_meth.iwork,
                            step_meth.iwork_len);
        for (j = 0; j < nsteps && *rc == VLBE_OK; ++j) *rc = vlbe_hht_step(&hs, (vlbe_real)h);
        t += benchu_now() - t0;
        *st = hs.stats;
    }
    return t / reps;
}

/* max over the records of |a - b| (both components) / max |b|; NaN when
   the runs differ in length */
static double tip_diff(const tip_rec *a, const tip_rec *b)
{
    double d = 0.0, s = 0.0;
    int k, j;
    if (a->n != b->n) return (double)NAN;
    for (k = 0; k < a->n; ++k)
        for (j = 0; j < 2; ++j) {
            d = fmax(d, fabs(a->tip[k][j] - b->tip[k][j]));
            s = fmax(s, fabs(b->tip[k][j]));
        }
    return d / s;
}

/* Warm-up from rest to STEP_T1 with the tip record (status, tip
   difference, the state at STEP_T0), one window run (counters, calls, ns
   per call, runs per sample), then STEP_ROUNDS interleaved rounds of the
   configurations that ran through.  The dense Gauss route of a size must
   come before the others.  -1 on setup failure, else the number of failed
   runs. */
static int step_measure(step_cfg *sc, int nsc)
{
    ex_run_out ro;
    dae_timer tm;
    vlbe_dae_stats st;
    vlbe_status rc = VLBE_OK;
    int i, b, k, fail = 0;
    for (i = 0; i < nsc; ++i) {
        step_cfg *p = &sc[i];
        double t1;
        tip_rec *rec = &step_tips[p->band][p->route];
        if (step_warmup(p, rec, &tm, &ro) != 0) return -1;
        for (k = 0; k < NTM; ++k) p->ns_call[k] = tm.n[k] ? 1e9 * tm.s[k] / (double)tm.n[k] : 0.0;
        p->status = ro.status;
        p->st = ro.stats;
        p->t_stop = rec->t_last;
        p->dtip = rec == &step_tips[0][0] ? 0.0 : tip_diff(rec, &step_tips[0][0]);
        if (p->status == VLBE_OK && !rec->have_x0) p->status = VLBE_EARG;
        if (p->status != VLBE_OK) {
            ++fail;
            continue;
        }
        if ((t1 = step_window(p, 1, &tm, &p->st, &p->status)) < 0.0) return -1;
        for (k = 0; k < NTM; ++k) {
            p->calls[k] = tm.n[k];
            p->ns_call[k] = tm.n[k] ? 1e9 * tm.s[k] / (double)tm.n[k] : 0.0;
        }
        p->reps = t1 > 0.0 && t1 < STEP_MIN_S ? (int)(STEP_MIN_S / t1) + 1 : 1;
        fail += p->status != VLBE_OK;
    }
    for (b = 0; b < STEP_ROUNDS; ++b)
        for (i = 0; i < nsc; ++i) {
            step_cfg *p = &sc[i];
            if (p->status != VLBE_OK) continue;
            p->s[b][NTM] = step_window(p, p->reps, &tm, &st, &rc);
            for (k = 0; k < NTM; ++k) p->s[b][k] = tm.s[k] / p->reps;
            fail += rc != VLBE_OK;
        }
    for (i = 0; i < nsc; ++i) {
        step_cfg *p = &sc[i];
        const double per = 1e6 / (double)(p->st.steps > 0 ? p->st.steps : 1);
        double col[STEP_ROUNDS];
        for (k = 0; k <= NTM; ++k) {
            p->us[k] = (double)NAN;
            if (p->status != VLBE_OK) continue;
            for (b = 0; b < STEP_ROUNDS; ++b) col[b] = p->s[b][k];
            qsort(col, STEP_ROUNDS, sizeof col[0], benchu_cmp_double);
            p->us[k] = per * col[STEP_ROUNDS / 2];
            if (k == NTM) p->us_min = per * col[0];
            else if (p->calls[k] > 0)
                p->ns_call[k] = 1e9 * col[STEP_ROUNDS / 2] / (double)p->calls[k];
        }
    }
    return fail;
}

/* a / b of the median times per step, "failed" if either run failed */
static void step_ratio(const step_cfg *a, const step_cfg *b)
{
    if (a->status != VLBE_OK || b->status != VLBE_OK) printf(" %6s", "failed");
    else printf(" %6.2f", a->us[NTM] / b->us[NTM]);
}

/* The per-step table, CSV and chart, and the whole scene with the routes
   at the smaller sizes.  Returns the number of failed runs other than the
   system route's (reported), -1 if a setup failed. */
static int step_bench(const char *tag)
{
    /* configuration (c, b, r) at SC(c, b, r): size, storage, route */
#define SC(c, b, r) (((c) * NSTO + (b)) * NROUTE + (r))
    static step_cfg sc[NCH * NSTO * NROUTE];
    static sp_model fm;
    char csv[256], svg[256];
    int c, r, b, i, nnoisy = 0, fail, fail_other = 0;
    FILE *f;
    for (c = 0; c < NCH; ++c)
        for (b = 0; b < NSTO; ++b)
            for (r = 0; r < NROUTE; ++r) {
                sc[SC(c, b, r)].ch = c;
                sc[SC(c, b, r)].band = b;
                sc[SC(c, b, r)].route = r;
            }
    fail = step_measure(sc, NCH * NSTO * NROUTE);
    if (fail < 0) return -1;
    printf("\nscene 1 per step: ANCF beam with bending (scenes/ex_spin.h, W = %g rad/s), "
           "HHT-alpha -0.05, h = 5 ms, timed t in [%g, %g] s (from the state of a run from rest); "
           "us per step: median (min) of %d interleaved rounds; callbacks timed inside the runs\n",
           STEP_W, STEP_T0, STEP_T1, STEP_ROUNDS);
    printf("%4s %-26s %15s %8s %8s %8s %8s %8s %6s %6s %6s %8s %8s %8s\n", "ne", "route",
           "us/step", "Q", "K,D", "M", "constr", "rest", "force", "Nwt/st", "LU/st", "Q ns/el",
           "QKD ns/el", "max dtip");
    for (i = 0; i < NCH * NSTO * NROUTE; ++i) {
        const step_cfg *p = &sc[i];
        const double steps = (double)p->st.steps, ne = chain_ne[p->ch];
        char rn[64];
        snprintf(rn, sizeof rn, "%s%s", route_name[p->route], sto_name[p->band]);
        if (p->status != VLBE_OK) {
            printf("%4d %-26s %s at t = %.3f s (%ld steps, %ld rejected, %ld Newton, %ld LU); "
                   "%.0f / %.0f ns per element per Q / Q,K,D call\n",
                   chain_ne[p->ch], rn, vlbe_status_str(p->status), p->t_stop,
                   p->st.steps, p->st.rejected, p->st.newton_iters, p->st.lu_factors,
                   p->ns_call[TM_FORCE] / ne, p->ns_call[TM_JAC] / ne);
            if (p->route != R_SYS) ++fail_other;
            continue;
        }
        nnoisy += p->us[NTM] > BENCHU_NOISY * p->us_min;
        printf("%4d %-26s %7.1f (%5.1f) %8.2f %8.2f %8.2f %8.2f %8.2f %5.1f%% %6.2f %6.3f %8.0f "
               "%8.0f %8.1e%s\n",
               chain_ne[p->ch], rn, p->us[NTM], p->us_min, p->us[TM_FORCE],
               p->us[TM_JAC], p->us[TM_MASS], p->us[TM_OTHER],
               p->us[NTM] - p->us[TM_FORCE] - p->us[TM_JAC] - p->us[TM_MASS] - p->us[TM_OTHER],
               100.0 * (p->us[TM_FORCE] + p->us[TM_JAC]) / p->us[NTM],
               (double)p->st.newton_iters / steps, (double)p->st.lu_factors / steps,
               p->ns_call[TM_FORCE] / ne, p->ns_call[TM_JAC] / ne, p->dtip,
               p->us[NTM] > BENCHU_NOISY * p->us_min ? " *" : "");
    }
    printf("%4s %-26s", "", "per step / Gauss (dense):");
    for (c = 0; c < NCH; ++c) printf(" %6d", chain_ne[c]);
    printf("\n");
    for (r = 1; r < NROUTE; ++r) {
        printf("%4s %-26s", "", route_name[r]);
        for (c = 0; c < NCH; ++c) step_ratio(&sc[SC(c, 0, r)], &sc[SC(c, 0, 0)]);
        printf("\n");
    }
    printf("%4s %-26s", "", "elem / system inv.");
    for (c = 0; c < NCH; ++c) step_ratio(&sc[SC(c, 0, R_ELEM)], &sc[SC(c, 0, R_SYS)]);
    printf("\n");
    printf("%4s %-26s\n", "", "per step, banded / dense:");
    for (r = 0; r < NROUTE; ++r) {
        printf("%4s %-26s", "", route_name[r]);
        for (c = 0; c < NCH; ++c) step_ratio(&sc[SC(c, 1, r)], &sc[SC(c, 0, r)]);
        printf("\n");
    }
    if (nnoisy)
        printf("* median > %.2f x min: the machine was busy; rerun on a quiet machine\n", BENCHU_NOISY);

    /* the whole scene (20 s) with each route: tips at the 40 samples */
    printf("whole scene (0..20 s, sp_run, one run each): per route us per step (out.cpu / "
           "steps), steps, rejected; max |tip - tip of Gauss| / max |tip| over the 40 samples\n");
    for (c = 0; c < STEP_NFULL; ++c) {
        sp_out o[NROUTE];
        int k, j;
        for (r = 0; r < NROUTE; ++r) {
            sp_cfg cf;
            sp_cfg_default(&cf, STEP_W, SP_ANCF);
            cf.ne = chain_ne[c];
            cf.inv = step_route[r];
            sp_run(&fm, &cf, NULL, NULL, &o[r]);
        }
        printf("  ne = %2d:", chain_ne[c]);
        for (r = 0; r < NROUTE; ++r) {
            double d = 0.0, s = 0.0;
            for (k = 0; k < SP_NS; ++k)
                for (j = 0; j < 2; ++j) {
                    d = fmax(d, fabs(o[r].tip_s[k][j] - o[0].tip_s[k][j]));
                    s = fmax(s, fabs(o[0].tip_s[k][j]));
                }
            printf(" %s %.1f, %ld, %ld%s%s", route_csv[r],
                   1e6 * o[r].cpu / (double)o[r].stats.steps, o[r].stats.steps,
                   o[r].stats.rejected, o[r].status != VLBE_OK ? ", " : "",
                   o[r].status != VLBE_OK ? vlbe_status_str(o[r].status) : "");
            if (r > 0) printf(", %.1e", d / s);
            printf(r + 1 < NROUTE ? ";" : "\n");
            if (o[r].status != VLBE_OK && r != R_SYS) ++fail_other;
        }
    }

    snprintf(csv, sizeof csv, "out/bench/inv_step%s%s.csv", tag ? "-" : "", tag ? tag : "");
    snprintf(svg, sizeof svg, "out/bench/inv_step%s%s.svg", tag ? "-" : "", tag ? tag : "");
    f = svgp_csv_open(csv, "elements,route,storage,status,steps,rejected,newton_iters,lu_factors,rounds,"
                           "runs_per_sample,median_us_per_step,min_us_per_step,force_us_per_step,"
                           "force_jac_us_per_step,mass_us_per_step,constraints_us_per_step,"
                           "ns_per_elem_force_call,ns_per_elem_force_jac_call,max_tip_diff_rel");
    if (f) {
        for (i = 0; i < NCH * NSTO * NROUTE; ++i) {
            const step_cfg *p = &sc[i];
            const double ne = chain_ne[p->ch];
            fprintf(f, "%d,%s,%s,\"%s\",%ld,%ld,%ld,%ld,%d,%d,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,"
                       "%.6g,%.3e\n",
                    chain_ne[p->ch], route_csv[p->route], sto_csv[p->band],
                    vlbe_status_str(p->status), p->st.steps,
                    p->st.rejected, p->st.newton_iters, p->st.lu_factors, STEP_ROUNDS, p->reps,
                    p->us[NTM], p->status == VLBE_OK ? p->us_min : (double)NAN, p->us[TM_FORCE],
                    p->us[TM_JAC], p->us[TM_MASS], p->us[TM_OTHER], p->ns_call[TM_FORCE] / ne,
                    p->ns_call[TM_JAC] / ne, p->dtip);
        }
        if (fclose(f) != 0) fprintf(stderr, "bench_inv: cannot write %s\n", csv);
        else printf("wrote %s\n", csv);
    } else
        fprintf(stderr, "bench_inv: cannot write %s\n", csv);
    {
        /* j = 0, 1: the whole step dense, banded; j = 2: the Q and K, D
           callbacks (dense) */
        static double xv[NCH], yv[3][NROUTE][NCH];
        static char name[3][NROUTE][96];
        static const char *const what[3] = {"whole step", "whole step, banded",
                                            "Q and K, D callbacks"};
        svgp_chart ch;
        int j;
        svgp_init(&ch,
                  "spin-up W = 6, ANCF beam: time per HHT step (h = 5 ms), Gauss vs invariants, "
                  "dense vs banded",
                  "elements", "us per step (median)", 1, 1);
        for (j = 0; j < 3; ++j)
            for (r = 0; r < NROUTE; ++r) {
                char failed[40] = "";
                size_t lf = 0;
                for (c = 0; c < NCH; ++c) {
                    const step_cfg *p = &sc[SC(c, j == 1, r)];
                    xv[c] = chain_ne[c];
                    yv[j][r][c] = j == 2 ? p->us[TM_FORCE] + p->us[TM_JAC] : p->us[NTM];
                    if (p->status != VLBE_OK && lf + 8 < sizeof failed)
                        lf += (size_t)snprintf(failed + lf, sizeof failed - lf, "%s%d",
                                               lf ? ", " : " (fails at ", chain_ne[c]);
                }
                snprintf(name[j][r], sizeof name[j][r], "%s, %s%s%s", route_name[r], what[j],
                         failed, lf ? " el.)" : "");
                svgp_series(&ch, name[j][r], NCH, xv, yv[j][r],
                            j == 2 ? SVGP_MARKERS | SVGP_DASH : SVGP_MARKERS);
            }
        svgp_fit_legend_log(&ch, 12, 0);
        if (svgp_write_file(&ch, svg) != 0) fprintf(stderr, "bench_inv: cannot write %s\n", svg);
        else printf("wrote %s\n", svg);
    }
#undef SC
    ex_method_release(&step_meth);
    return fail_other;
}

int main(int argc, char **argv)
{
    static cfg cs[128];
    const char *tag = argc > 1 ? argv[1] : NULL;
    vlbe_ale_mat mat;
    char model[128], csv[256], svg[256];
    double mhz;
    long bad = 0;
    int nc = 0, i, c, r, j, nnoisy = 0;
    FILE *f;

    memset(&mat, 0, sizeof mat);
    mat.rhoA = VLBE_R(0.154);
    mat.EA = VLBE_R(4.1e6);
    mat.c_eps = VLBE_R(1e-3);
    mat.f[1] = VLBE_R(-9.81) * mat.rhoA;
    benchu_cpu_info(model, sizeof model, &mhz);
    printf("bench_inv: axial (cable) force of fixed-length planar ANCF elements, vlbe %s, %s\n",
           VLBE_VERSION_STRING, sizeof(vlbe_real) == sizeof(double) ? "double" : "float");
    printf("compiler: %s, flags: %s\n", __VERSION__, VLBE_BENCH_FLAGS);
    printf("cpu: %s, %.0f MHz (/proc/cpuinfo)\n", model, mhz);
    printf("ns per call: median (min) of %d interleaved batches; K, D in band storage\n\n", BENCHU_BATCHES);
    if (vlbe_ale_elem_init(&el, &mat, 0u, 0, 0, 0) != VLBE_OK) return 1;
    make_states();
    for (c = 0; c < NCH; ++c)
        if (vlbe_ale_inv_sys_init(&sys_d[c], &el, 0u, chain_ne[c], Ls, work_d[c],
                                  sizeof work_d[c] / sizeof work_d[c][0]) != VLBE_OK)
            return 1;
    for (i = 0; i < 2; ++i)
        if (vlbe_ale_inv_sys_init(&sys_1[i], &el, i ? VLBE_ALE_NO_DAMP : 0u, 1, Ls, work_1[i],
                                  sizeof work_1[i] / sizeof work_1[i][0]) != VLBE_OK)
            return 1;

    /* one element: damped and undamped; chains: damped */
    for (j = 0; j < 2; ++j)
        for (i = 0; i < 2; ++i)
            for (r = 0; r < NROUTE; ++r) {
                cfg *p = &cs[nc++];
                p->route = r;
                p->jac = j;
                p->ch = -1;
                p->mode = i ? VLBE_ALE_NO_DAMP : 0u;
            }
    for (j = 0; j < 2; ++j)
        for (c = 0; c < NCH; ++c)
            for (r = 0; r < NROUTE; ++r) {
                cfg *p = &cs[nc++];
                p->route = r;
                p->jac = j;
                p->ch = c;
                p->mode = 0u;
            }
    measure(cs, nc, &bad);

    snprintf(csv, sizeof csv, "out/bench/inv%s%s.csv", tag ? "-" : "", tag ? tag : "");
    snprintf(svg, sizeof svg, "out/bench/inv%s%s.svg", tag ? "-" : "", tag ? tag : "");
    f = svgp_csv_open(csv, "what,route,damped,elements,calls_per_batch,batches,median_ns,min_ns,"
                           "ns_per_element");
    if (!f) fprintf(stderr, "bench_inv: cannot write %s\n", csv);

    printf("one element (ns per element call)\n%-24s %-20s %14s %14s\n", "", "", "damped",
           "undamped");
    for (j = 0; j < 2; ++j)
        for (r = 0; r < NROUTE; ++r) {
            const cfg *a = &cs[j * 6 + r], *u = &cs[j * 6 + 3 + r];
            printf("%-24s %-20s %7.1f (%5.1f) %7.1f (%5.1f)%s\n", r == 0 ? (j ? "force Q+K+D" : "force Q") : "",
                   route_name[r], a->med, a->min, u->med, u->min,
                   (a->med > BENCHU_NOISY * a->min || u->med > BENCHU_NOISY * u->min) ? " *" : "");
            nnoisy += a->med > BENCHU_NOISY * a->min || u->med > BENCHU_NOISY * u->min;
        }
    printf("\nchains of ne elements, damped (ns per evaluation; per element in [])\n");
    for (j = 0; j < 2; ++j) {
        printf("%-12s %-20s", j ? "Q+K+D" : "Q", "ne:");
        for (c = 0; c < NCH; ++c) printf(" %16d", chain_ne[c]);
        printf("\n");
        for (r = 0; r < NROUTE; ++r) {
            int noisy = 0;
            printf("%-12s %-20s", "", route_name[r]);
            for (c = 0; c < NCH; ++c) {
                const cfg *p = &cs[12 + j * NCH * NROUTE + c * NROUTE + r];
                printf(" %8.0f [%5.1f]", p->med, p->med / chain_ne[c]);
                noisy |= p->med > BENCHU_NOISY * p->min;
            }
            nnoisy += noisy;
            printf("%s\n", noisy ? " *" : "");
        }
        printf("%-12s %-20s", "", "elem inv / system");
        for (c = 0; c < NCH; ++c)
            printf(" %16.2f", cs[12 + j * NCH * NROUTE + c * NROUTE + R_ELEM].med /
                                  cs[12 + j * NCH * NROUTE + c * NROUTE + R_SYS].med);
        printf("\n%-12s %-20s", "", "Gauss / system");
        for (c = 0; c < NCH; ++c)
            printf(" %16.2f", cs[12 + j * NCH * NROUTE + c * NROUTE + R_GAUSS].med /
                                  cs[12 + j * NCH * NROUTE + c * NROUTE + R_SYS].med);
        printf("\n");
    }
    if (nnoisy) printf("* median > %.2f x min: the machine was busy; rerun on a quiet machine\n", BENCHU_NOISY);

    if (f) {
        for (i = 0; i < nc; ++i) {
            const cfg *p = &cs[i];
            const int ne = p->ch < 0 ? 1 : chain_ne[p->ch];
            fprintf(f, "%s,%s,%d,%d,%ld,%d,%.6g,%.6g,%.6g\n", p->jac ? "force_qkd" : "force_q",
                    route_csv[p->route], !(p->mode & VLBE_ALE_NO_DAMP), p->ch < 0 ? 0 : ne,
                    p->calls, BENCHU_BATCHES, p->med, p->min, p->med / ne);
        }
        if (fclose(f) != 0) fprintf(stderr, "bench_inv: cannot write %s\n", csv);
        else printf("\nwrote %s\n", csv);
    }
    {
        static const int style[NROUTE] = {SVGP_MARKERS, SVGP_MARKERS | SVGP_DASH,
                                          SVGP_MARKERS | SVGP_DOT};
        svgp_chart ch;
        double xv[NCH], yv[NCH];
        char name[64];
        svgp_init(&ch, "cable axial force of a chain: Gauss vs invariants", "elements",
                  "ns per evaluation", 1, 1);
        for (j = 0; j < 2; ++j)
            for (r = 0; r < NROUTE; ++r) {
                for (c = 0; c < NCH; ++c) {
                    xv[c] = chain_ne[c];
                    yv[c] = cs[12 + j * NCH * NROUTE + c * NROUTE + r].med;
                }
                snprintf(name, sizeof name, "%s, %s", j ? "Q+K+D" : "Q", route_name[r]);
                svgp_series(&ch, name, NCH, xv, yv, style[r]);
            }
        svgp_fit_legend_log(&ch, 12, 0);
        if (svgp_write_file(&ch, svg) != 0) fprintf(stderr, "bench_inv: cannot write %s\n", svg);
        else printf("wrote %s\n", svg);
    }
    if (benchu_finish("bench_inv", NULL, NULL, bad)) return 1;
    if ((i = step_bench(tag)) != 0) {
        fprintf(stderr, "bench_inv: %s\n", i < 0 ? "scene 1 setup failed" : "a scene 1 run failed");
        return 1;
    }
    return 0;
}
