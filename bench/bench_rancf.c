/* bench_rancf.c -- cost of one planar ALE-RANCF element of rancf.h per call,
   against the planar ALE-ANCF element of ancf_ale.h it is built on:
   the element calls (force Q only and Q with K and D, mass, mass_jac,
   energy) with non-unit weights at the default and at higher Gauss orders,
   and the one-off operations of segmentation, merging and length control
   (element type init, basis evaluation, split, merge, arc element, point).

   build (from the repository root; `make bench` does this):
       cc -std=c99 -O3 -march=native bench/bench_rancf.c -o build/bench/bench_rancf -lm
   run from the repository root:  build/bench/bench_rancf [tag]
   writes out/bench/rancf_elem[-tag].csv (out/bench must exist).

   Performance target: one ALE-RANCF element, forces + Jacobians (force
   with K and D, default Gauss orders nm/nl/nt = 4/5/5), at most 1.3 times
   the ALE-ANCF element.  Checked for both weight sets (last lines:
   PASS/MISS); a missed target is reported, not an error: the exit status is
   1 only when a call fails.

   Element types (rows of the element calls): the ALE-ANCF element and the
   ALE-RANCF element with the weights of a circular-arc element of central
   angle pi/4, w = {1, (1 + 2 cos(pi/8))/3, same, 1} ("arc"), and with the
   general set w = {0.9, 0.8, 1.2, 1.1} ("general"), each at the Gauss
   orders 4/5/5 (default), 6/7/7 and 8/8/8 (the rational integrands are not
   exact at any order; the lines after the table give what 4/5/5 and 6/7/7
   cost in accuracy against 8/8/8 -- the general weights, on the nodal
   coordinates of the arc, make a strongly strained element whose forces
   converge slowly in the Gauss order).  Columns: median and min ns per
   call, the ratio to the ALE-ANCF row at default orders of the same
   operation ("vs ANCF") and to the ALE-ANCF row at the same orders ("vs
   same n": what the basis costs, apart from the number of points).  For the
   one-off operations "vs ANCF" is the ALE-ANCF counterpart (vlbe_ale_elem_init,
   vlbe_herm_ale_eval, vlbe_ale_split, vlbe_ale_point), "-" where there is
   none (merge, arc).

   State: the element of bench_ale.c (benchu_arc_state of bench_util.h):
   a steel wire (d = 5 mm: rhoA = 0.154 kg/m, EA = 4.1 MN, EI = 6.4 N m^2,
   c_eps = c_kap = 1 ms, gravity) on p in [1, 1.25] m, bent to a circular
   arc of radius 0.5 m, stretched by 0.2 %, rotating, translating,
   stretching, with axial material flow p1' = 0.30, p2' = 0.25 m/s; the same
   nodal coordinates for both elements (the RANCF element interpolates them
   with its rational basis).  One-off operations: basis and point at p ~
   1.1 (basis with kmax = 2, amax = 2), split at ph ~ 1.1 with the rates and
   both weight sets written, merge of the nodes p = 1, 1.125, 1.25 of the
   same arc (d = 2; d = 3: the arc lifted to a helix, z = 0.2 (p - 1)), arc
   element of central angle pi/4.

   Method (that of bench_ale.c): 8 copies of every input, each number
   perturbed by a relative 1e-7 (fixed seed); call r uses copy r mod 8.
   After each call one output entry chosen by r is added to an accumulator
   stored into a volatile sink, and the status codes are checked.  The mode
   of the element calls is read at run time (volatile).  Per row: a
   warm-up and calibration batch, then BENCHU_BATCHES = 31 batches,
   CLOCK_MONOTONIC around each; the batches of the rows of one operation run
   interleaved (round robin).  Calls per batch: 1e4, raised if a batch would
   last less than 0.2 ms and -- unlike bench_ale.c -- lowered (not below
   200) if it would last more than 4 ms, so that few batches straddle a time
   slice of another process (the init rows take microseconds per call).
   Reported: median and min over the batches of ns per call; '*' marks a row
   whose median exceeds 1.15 times its min (machine busy: rerun). */
#define _POSIX_C_SOURCE 199309L
#include "../rancf.h"
#include "../scenes/svgplot.h"
#include "bench_util.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define MIN_CALLS 10000L
#define FLOOR_CALLS 200L     /* fewest calls per batch for slow rows     */
#define MAX_BATCH_S 4e-3     /* target upper bound of one batch (local)   */
#define NSTATE 8             /* perturbed copies of the inputs, cycled    */
#define DNAN ((double)NAN)
#define PI_D 3.14159265358979323846

static volatile double sink;
static volatile unsigned mode_src; /* modes pass through here: not constants */

static unsigned long long rng_state = 0x9E3779B97F4A7C15ULL;
static double urand(void) { return benchu_urand(&rng_state); }
static double pert(double x) { return x * (1.0 + 1e-7 * urand()); }

/* -- inputs ------------------------------------------------------------------ */
enum { W_ARC, W_GEN, NWSET };
static const char *const wset_name[NWSET] = {"arc", "general"};
static double wset_base[NWSET][4]; /* filled in make_states */

static vlbe_real qs[NSTATE][VLBE_ALE_NQ], qds[NSTATE][VLBE_ALE_NQ], as[NSTATE][VLBE_ALE_NQ];
static vlbe_real ws[NWSET][NSTATE][4];        /* weights (basis, init)            */
static vlbe_real pps[NSTATE], phs[NSTATE];    /* point / basis p, split ph        */
static vlbe_real m2[3][NSTATE][5], m3[3][NSTATE][7]; /* merge nodes A, H, B      */
static vlbe_real arc_c[NSTATE][2], arc_a0[NSTATE], arc_th[NSTATE];
static vlbe_ale_mat mat, mats[NSTATE]; /* the wire; perturbed copies (init) */

/* Node [r, r', p] of the arc of benchu_arc_state at p, in d = 2 or 3
   (d = 3: lifted to a helix, z = 0.2 (p - 1)). */
static void arc_node(double p, int d, double *nd)
{
    const double R = 0.5, lam = 1.002, th = 0.3 + (p - 1.0) / R;
    nd[0] = lam * R * sin(th);
    nd[1] = lam * R * (1.0 - cos(th));
    if (d == 3) nd[2] = 0.2 * (p - 1.0);
    nd[d + 0] = lam * cos(th);
    nd[d + 1] = lam * sin(th);
    if (d == 3) nd[d + 2] = 0.2;
    nd[2 * d] = p;
}

static void make_states(void)
{
    double q[10], qd[10], a[10], nd[7];
    const double pn[3] = {1.0, 1.125, 1.25};
    int s, i, j, n;
    wset_base[W_ARC][0] = wset_base[W_ARC][3] = 1.0;
    wset_base[W_ARC][1] = wset_base[W_ARC][2] = (1.0 + 2.0 * cos(PI_D / 8.0)) / 3.0;
    wset_base[W_GEN][0] = 0.9;
    wset_base[W_GEN][1] = 0.8;
    wset_base[W_GEN][2] = 1.2;
    wset_base[W_GEN][3] = 1.1;
    benchu_arc_state(q, qd, a);
    for (s = 0; s < NSTATE; ++s) {
        for (i = 0; i < 10; ++i) {
            qs[s][i] = (vlbe_real)pert(q[i]);
            qds[s][i] = (vlbe_real)pert(qd[i]);
            as[s][i] = (vlbe_real)pert(a[i]);
        }
        for (j = 0; j < NWSET; ++j)
            for (i = 0; i < 4; ++i) ws[j][s][i] = (vlbe_real)pert(wset_base[j][i]);
        pps[s] = (vlbe_real)pert(1.1);
        phs[s] = (vlbe_real)pert(1.1);
        for (n = 0; n < 3; ++n) {
            arc_node(pn[n], 2, nd);
            for (i = 0; i < 5; ++i) m2[n][s][i] = (vlbe_real)pert(nd[i]);
            arc_node(pn[n], 3, nd);
            for (i = 0; i < 7; ++i) m3[n][s][i] = (vlbe_real)pert(nd[i]);
        }
        arc_c[s][0] = (vlbe_real)pert(0.1);
        arc_c[s][1] = (vlbe_real)pert(0.5);
        arc_a0[s] = (vlbe_real)pert(-1.2);
        arc_th[s] = (vlbe_real)pert(PI_D / 4.0);
        mats[s] = benchu_wire();
        mats[s].rhoA = (vlbe_real)pert((double)mats[s].rhoA);
        mats[s].EA = (vlbe_real)pert((double)mats[s].EA);
        mats[s].EI = (vlbe_real)pert((double)mats[s].EI);
    }
}

/* -- element types -------------------------------------------------------------- */
typedef struct etype {
    const char *name;
    int rancf, wset; /* wset: W_* for rancf */
    int nm, nl, nt;  /* Gauss orders given to init (0 = default 4/5/5) */
} etype;

static const etype etypes[] = {
    {"ALE-ANCF 4/5/5", 0, -1, 0, 0, 0},        {"ALE-RANCF arc 4/5/5", 1, W_ARC, 0, 0, 0},
    {"ALE-RANCF general 4/5/5", 1, W_GEN, 0, 0, 0}, {"ALE-ANCF 6/7/7", 0, -1, 6, 7, 7},
    {"ALE-RANCF arc 6/7/7", 1, W_ARC, 6, 7, 7}, {"ALE-RANCF general 6/7/7", 1, W_GEN, 6, 7, 7},
    {"ALE-ANCF 8/8/8", 0, -1, 8, 8, 8},        {"ALE-RANCF arc 8/8/8", 1, W_ARC, 8, 8, 8},
    {"ALE-RANCF general 8/8/8", 1, W_GEN, 8, 8, 8},
};
#define NET ((int)(sizeof etypes / sizeof etypes[0]))
#define ET_PER_ORDER 3 /* etypes come in groups of one order: ANCF first */

static vlbe_ale_elem ael[NET];   /* ~16 kB each; used where !rancf */
static vlbe_rancf_elem rel[NET]; /* used where rancf */
static vlbe_ale_elem init_adst;  /* destinations of the init rows */
static vlbe_rancf_elem init_rdst;

/* -- operations and rows ------------------------------------------------------ */
enum { OP_Q, OP_QKD, OP_M, OP_MJ, OP_E, NELOP, OP_INIT = NELOP, OP_BASIS, OP_SPLIT, OP_MERGE,
       OP_ARC, OP_POINT, NOP };
static const char *const op_name[NOP] = {"force Q", "force Q+K+D", "mass M",
                                         "mass_jac d(Ma)/dq", "energy T,U,V", "elem_init",
                                         "basis_eval k2 a2", "split", "merge", "arc",
                                         "point r, r'"};
static const char *const op_csv[NOP] = {"force_q", "force_qkd", "mass",  "mass_jac",
                                        "energy",  "elem_init", "basis_eval", "split",
                                        "merge",   "arc",       "point"};

/* A one-off row: ANCF counterpart (rancf 0) or RANCF call, weight set, d
   (merge), Gauss orders (init), element type index (split, point). */
typedef struct orow {
    int op;
    const char *name;
    int rancf, wset, d, nm, nl, nt, et;
} orow;

static const orow orows[] = {
    {OP_INIT, "ALE-ANCF vlbe_ale_elem_init 4/5/5", 0, -1, 0, 0, 0, 0, -1},
    {OP_INIT, "ALE-RANCF arc 4/5/5", 1, W_ARC, 0, 0, 0, 0, -1},
    {OP_INIT, "ALE-RANCF general 4/5/5", 1, W_GEN, 0, 0, 0, 0, -1},
    {OP_INIT, "ALE-ANCF vlbe_ale_elem_init 8/8/8", 0, -1, 0, 8, 8, 8, -1},
    {OP_INIT, "ALE-RANCF general 8/8/8", 1, W_GEN, 0, 8, 8, 8, -1},
    {OP_BASIS, "ALE-ANCF vlbe_herm_ale_eval", 0, -1, 0, 0, 0, 0, -1},
    {OP_BASIS, "ALE-RANCF arc", 1, W_ARC, 0, 0, 0, 0, -1},
    {OP_BASIS, "ALE-RANCF general", 1, W_GEN, 0, 0, 0, 0, -1},
    {OP_SPLIT, "ALE-ANCF vlbe_ale_split", 0, -1, 0, 0, 0, 0, -1},
    {OP_SPLIT, "ALE-RANCF arc", 1, W_ARC, 0, 0, 0, 0, 1},
    {OP_SPLIT, "ALE-RANCF general", 1, W_GEN, 0, 0, 0, 0, 2},
    {OP_MERGE, "ALE-RANCF d = 2", 1, -1, 2, 0, 0, 0, -1},
    {OP_MERGE, "ALE-RANCF d = 3", 1, -1, 3, 0, 0, 0, -1},
    {OP_ARC, "ALE-RANCF theta = pi/4", 1, -1, 0, 0, 0, 0, -1},
    {OP_POINT, "ALE-ANCF vlbe_ale_point", 0, -1, 0, 0, 0, 0, -1},
    {OP_POINT, "ALE-RANCF arc", 1, W_ARC, 0, 0, 0, 0, 1},
    {OP_POINT, "ALE-RANCF general", 1, W_GEN, 0, 0, 0, 0, 2},
};
#define NOROW ((int)(sizeof orows / sizeof orows[0]))
#define MAXROW 16 /* rows of one operation, at most */

/* Row of the table: an element call (op < NELOP, et the element type) or a
   one-off row (orows[oi]). */
typedef struct row {
    int op, et, oi;
    const char *name;
    int ref, ref_same; /* global row indices of the ratios, -1: none */
    int rancf, nm, nl, nt;
    double med_ns, min_ns;
    long calls;
} row;

#define NROWS (NELOP * NET + NOROW)
static row rows[NROWS];

/* the per-call loop: CALL returns a status, ACC the number to accumulate */
#define LOOP(CALL, ACC)                                                                            \
    for (r = 0; r < k; ++r) {                                                                      \
        const int s = (int)(r & (NSTATE - 1));                                                     \
        nbad += (CALL) != VLBE_OK;                                                                 \
        acc += (ACC);                                                                              \
    }

/* One timed batch of k calls of an element operation; seconds per call. */
static double batch_elem(const row *rw, long k, long *bad)
{
    vlbe_real Q[10], K[100], D[100], M[100], E[3];
    const vlbe_ale_elem *ae = &ael[rw->et];
    const vlbe_rancf_elem *re = &rel[rw->et];
    const unsigned mode = mode_src;
    double t0, acc = 0.0;
    long r, nbad = 0;
    memset(Q, 0, sizeof Q); /* failed calls leave them unwritten */
    memset(K, 0, sizeof K);
    memset(D, 0, sizeof D);
    memset(M, 0, sizeof M);
    memset(E, 0, sizeof E);
    t0 = benchu_now();
    switch (rw->op * 2 + rw->rancf) {
    case OP_Q * 2:
        LOOP(vlbe_ale_force(ae, mode, qs[s], qds[s], Q, NULL, NULL), (double)Q[r % 10]);
        break;
    case OP_Q * 2 + 1:
        LOOP(vlbe_rancf_force(re, mode, qs[s], qds[s], Q, NULL, NULL), (double)Q[r % 10]);
        break;
    case OP_QKD * 2:
        LOOP(vlbe_ale_force(ae, mode, qs[s], qds[s], Q, K, D),
             (double)Q[r % 10] + (double)K[r % 100] + (double)D[(7 * r) % 100]);
        break;
    case OP_QKD * 2 + 1:
        LOOP(vlbe_rancf_force(re, mode, qs[s], qds[s], Q, K, D),
             (double)Q[r % 10] + (double)K[r % 100] + (double)D[(7 * r) % 100]);
        break;
    case OP_M * 2:
        LOOP(vlbe_ale_mass(ae, mode, qs[s], M), (double)M[r % 100]);
        break;
    case OP_M * 2 + 1:
        LOOP(vlbe_rancf_mass(re, mode, qs[s], M), (double)M[r % 100]);
        break;
    case OP_MJ * 2:
        LOOP(vlbe_ale_mass_jac(ae, mode, qs[s], as[s], M), (double)M[r % 100]);
        break;
    case OP_MJ * 2 + 1:
        LOOP(vlbe_rancf_mass_jac(re, mode, qs[s], as[s], M), (double)M[r % 100]);
        break;
    case OP_E * 2:
        LOOP(vlbe_ale_energy(ae, mode, qs[s], qds[s], E), (double)E[r % 3]);
        break;
    default:
        LOOP(vlbe_rancf_energy(re, mode, qs[s], qds[s], E), (double)E[r % 3]);
        break;
    }
    t0 = benchu_now() - t0;
    sink = acc;
    *bad += nbad;
    return t0 / (double)k;
}

/* One timed batch of k calls of a one-off operation; seconds per call. */
static double batch_once(const row *rw, long k, long *bad)
{
    const orow *o = &orows[rw->oi];
    const int w = o->wset < 0 ? 0 : o->wset;
    const vlbe_rancf_elem *re = o->et >= 0 ? &rel[o->et] : &rel[1];
    vlbe_herm_ale b;
    vlbe_real qh[5], qhd[5], wl[4], wr[4], kk[4], aw[4], ax[8], pr[2], prp[2];
    double t0, acc = 0.0;
    long r, nbad = 0;
    int info = 0;
    memset(&b, 0, sizeof b); /* failed calls leave the outputs unwritten */
    memset(qh, 0, sizeof qh);
    memset(qhd, 0, sizeof qhd);
    memset(wl, 0, sizeof wl);
    memset(wr, 0, sizeof wr);
    memset(kk, 0, sizeof kk);
    memset(aw, 0, sizeof aw);
    memset(ax, 0, sizeof ax);
    memset(pr, 0, sizeof pr);
    memset(prp, 0, sizeof prp);
    t0 = benchu_now();
    switch (o->op * 2 + o->rancf) {
    case OP_INIT * 2:
        LOOP(vlbe_ale_elem_init(&init_adst, &mats[s], 0u, o->nm, o->nl, o->nt),
             (double)init_adst.rt.g[r % init_adst.rt.n].b[2][r % 3][(r >> 2) & 3] +
                 (double)init_adst.rm.g[(r >> 1) % init_adst.rm.n].b[0][r % 6][r & 3] +
                 (double)init_adst.inv.t[r % 100]);
        break;
    case OP_INIT * 2 + 1:
        LOOP(vlbe_rancf_elem_init(&init_rdst, &mats[s], ws[w][s], 0u, o->nm, o->nl, o->nt),
             (double)init_rdst.ale.rt.g[r % init_rdst.ale.rt.n].b[2][r % 3][(r >> 2) & 3] +
                 (double)init_rdst.ale.rm.g[(r >> 1) % init_rdst.ale.rm.n].b[0][r % 6][r & 3] +
                 (double)init_rdst.k[r & 3]);
        break;
    case OP_BASIS * 2:
        for (r = 0; r < k; ++r) { /* vlbe_herm_ale_eval cannot fail */
            const int s = (int)(r & (NSTATE - 1));
            vlbe_herm_ale_eval(pps[s], qs[s][4], qs[s][9], 2, 2, &b);
            acc += (double)b.h[0][r % 6][r & 3] + (double)b.h[r % 3][0][(r >> 2) & 3];
        }
        break;
    case OP_BASIS * 2 + 1:
        LOOP(vlbe_rancf_basis_eval(ws[w][s], pps[s], qs[s][4], qs[s][9], 2, 2, &b),
             (double)b.h[0][r % 6][r & 3] + (double)b.h[r % 3][0][(r >> 2) & 3]);
        break;
    case OP_SPLIT * 2:
        LOOP(vlbe_ale_split(qs[s], qds[s], phs[s], qh, qhd), (double)qh[r % 5] + (double)qhd[r % 5]);
        break;
    case OP_SPLIT * 2 + 1:
        LOOP(vlbe_rancf_split(re, qs[s], qds[s], phs[s], qh, qhd, wl, wr),
             (double)qh[r % 5] + (double)qhd[r % 5] + (double)wl[r & 3] + (double)wr[(r >> 2) & 3]);
        break;
    case OP_MERGE * 2 + 1:
        if (o->d == 2) {
            LOOP(vlbe_rancf_merge(2, m2[0][s], m2[1][s], m2[2][s], kk, &info),
                 (double)kk[r & 3] + (double)info);
        } else {
            LOOP(vlbe_rancf_merge(3, m3[0][s], m3[1][s], m3[2][s], kk, &info),
                 (double)kk[r & 3] + (double)info);
        }
        break;
    case OP_ARC * 2 + 1:
        LOOP(vlbe_rancf_arc(arc_c[s], VLBE_R(0.5), arc_a0[s], arc_th[s], aw, ax),
             (double)aw[1 + (r & 1)] + (double)ax[r & 7]);
        break;
    case OP_POINT * 2:
        LOOP(vlbe_ale_point(qs[s], pps[s], pr, prp), (double)pr[r & 1] + (double)prp[(r >> 1) & 1]);
        break;
    default: /* OP_POINT * 2 + 1 */
        LOOP(vlbe_rancf_point(re, qs[s], pps[s], pr, prp),
             (double)pr[r & 1] + (double)prp[(r >> 1) & 1]);
        break;
    }
    t0 = benchu_now() - t0;
    sink = acc;
    *bad += nbad;
    return t0 / (double)k;
}

static double batch(const row *rw, long k, long *bad)
{
    return rw->op < NELOP ? batch_elem(rw, k, bad) : batch_once(rw, k, bad);
}

/* The n rows idx[] of one operation: warm-up and calibration per row, then
   BENCHU_BATCHES rounds of one batch per row (interleaved), median and min. */
static void measure_op(const int *idx, int n, long *bad)
{
    static double s[MAXROW][BENCHU_BATCHES];
    long k[MAXROW];
    int v, i;
    mode_src = 0u;
    for (v = 0; v < n; ++v) {
        const double t = batch(&rows[idx[v]], MIN_CALLS / 10, bad); /* warm-up */
        double tt = batch(&rows[idx[v]], t * (double)MIN_CALLS > MAX_BATCH_S ? FLOOR_CALLS : MIN_CALLS, bad);
        if (tt < 1e-10) tt = 1e-10;
        k[v] = MIN_CALLS;
        if (tt * (double)k[v] < BENCHU_MIN_BATCH_S) k[v] = (long)(BENCHU_MIN_BATCH_S / tt) + 1;
        if (tt * (double)k[v] > MAX_BATCH_S) k[v] = (long)(MAX_BATCH_S / tt);
        if (k[v] > BENCHU_MAX_CALLS) k[v] = BENCHU_MAX_CALLS;
        if (k[v] < FLOOR_CALLS) k[v] = FLOOR_CALLS;
    }
    for (i = 0; i < BENCHU_BATCHES; ++i)
        for (v = 0; v < n; ++v) s[v][i] = batch(&rows[idx[v]], k[v], bad);
    for (v = 0; v < n; ++v) {
        qsort(s[v], BENCHU_BATCHES, sizeof s[v][0], benchu_cmp_double);
        rows[idx[v]].med_ns = 1e9 * s[v][BENCHU_BATCHES / 2];
        rows[idx[v]].min_ns = 1e9 * s[v][0];
        rows[idx[v]].calls = k[v];
    }
}

/* -- accuracy of the Gauss orders ------------------------------------------------ */
static double rel_diff(const vlbe_real *a, const vlbe_real *b, int n)
{
    double na = 0.0, d = 0.0;
    int i;
    for (i = 0; i < n; ++i) {
        if (fabs((double)a[i]) > na) na = fabs((double)a[i]);
        if (fabs((double)(b[i] - a[i])) > d) d = fabs((double)(b[i] - a[i]));
    }
    return na > 0.0 ? d / na : DNAN;
}

/* Q, K, M of the RANCF element type e against those of the type ref (the
   same weights at 8/8/8): max |difference| / max |entry|. */
static void order_error(int e, int ref, double *eq, double *ek, double *em)
{
    vlbe_real Q1[10], K1[100], D1[100], M1[100], Q2[10], K2[100], D2[100], M2[100];
    *eq = *ek = *em = DNAN;
    if (vlbe_rancf_force(&rel[ref], 0u, qs[0], qds[0], Q1, K1, D1) != VLBE_OK ||
        vlbe_rancf_force(&rel[e], 0u, qs[0], qds[0], Q2, K2, D2) != VLBE_OK ||
        vlbe_rancf_mass(&rel[ref], 0u, qs[0], M1) != VLBE_OK ||
        vlbe_rancf_mass(&rel[e], 0u, qs[0], M2) != VLBE_OK)
        return;
    *eq = rel_diff(Q1, Q2, 10);
    *ek = rel_diff(K1, K2, 100);
    *em = rel_diff(M1, M2, 100);
}

static void print_ratio(double x)
{
    if (isnan(x)) printf(" %8s", "-");
    else printf(" %8.2f", x);
}

int main(int argc, char **argv)
{
    const char *tag = argc > 1 ? argv[1] : NULL;
    char model[128], csv[256];
    double mhz, load0;
    long bad = 0;
    int op, e, i, nr = 0, nnoisy = 0, rc;
    FILE *f;

    benchu_cpu_info(model, sizeof model, &mhz);
    load0 = benchu_load_avg();
    printf("bench_rancf: one planar ALE-RANCF element (rancf.h) against the ALE-ANCF element "
           "(ancf_ale.h), vlbe %s, %s\n",
           VLBE_VERSION_STRING, sizeof(vlbe_real) == sizeof(double) ? "double" : "float");
    printf("compiler: %s, flags: %s\n", __VERSION__, VLBE_BENCH_FLAGS);
    printf("cpu: %s, %.0f MHz (/proc/cpuinfo), load average %.2f at start\n", model, mhz, load0);
    printf("ns per call: median (min) of %d batches of %ld..%ld calls (0.2..%.0f ms) after "
           "warm-up, CLOCK_MONOTONIC\n",
           BENCHU_BATCHES, FLOOR_CALLS, (long)BENCHU_MAX_CALLS, 1e3 * MAX_BATCH_S);
    printf("state: bent (R = 0.5 m), stretched (0.2 %%), rotating wire element, L = 0.25 m, "
           "p1' = 0.30, p2' = 0.25 m/s\n");
    make_states();
    printf("weights: arc w = {1, %.6f, %.6f, 1} (theta = pi/4), general w = {%.1f, %.1f, %.1f, "
           "%.1f}\n\n",
           wset_base[W_ARC][1], wset_base[W_ARC][2], wset_base[W_GEN][0], wset_base[W_GEN][1],
           wset_base[W_GEN][2], wset_base[W_GEN][3]);

    mat = benchu_wire();
    for (e = 0; e < NET; ++e) {
        const etype *t = &etypes[e];
        vlbe_status st;
        if (t->rancf) {
            vlbe_real w[4];
            for (i = 0; i < 4; ++i) w[i] = (vlbe_real)wset_base[t->wset][i];
            st = vlbe_rancf_elem_init(&rel[e], &mat, w, 0u, t->nm, t->nl, t->nt);
        } else {
            st = vlbe_ale_elem_init(&ael[e], &mat, 0u, t->nm, t->nl, t->nt);
        }
        if (st != VLBE_OK) {
            fprintf(stderr, "bench_rancf: init of %s: %s\n", t->name, vlbe_status_str(st));
            return 1;
        }
    }

    /* the rows: element calls, then the one-off operations */
    for (op = 0; op < NELOP; ++op)
        for (e = 0; e < NET; ++e) {
            row *rw = &rows[nr];
            const etype *t = &etypes[e];
            memset(rw, 0, sizeof *rw);
            rw->op = op;
            rw->et = e;
            rw->oi = -1;
            rw->name = t->name;
            rw->rancf = t->rancf;
            rw->nm = t->nm ? t->nm : 4;
            rw->nl = t->nl ? t->nl : 5;
            rw->nt = t->nt ? t->nt : 5;
            rw->ref = op * NET; /* ALE-ANCF 4/5/5 */
            rw->ref_same = op * NET + e - e % ET_PER_ORDER;
            ++nr;
        }
    for (i = 0; i < NOROW; ++i) {
        row *rw = &rows[nr];
        const orow *o = &orows[i];
        int j;
        memset(rw, 0, sizeof *rw);
        rw->op = o->op;
        rw->et = -1;
        rw->oi = i;
        rw->name = o->name;
        rw->rancf = o->rancf;
        rw->nm = o->nm ? o->nm : 4;
        rw->nl = o->nl ? o->nl : 5;
        rw->nt = o->nt ? o->nt : 5;
        rw->ref = rw->ref_same = -1;
        /* the ANCF counterpart: the first ANCF row of the operation; at the
           same Gauss orders (init): the ANCF row with this row's orders */
        for (j = 0; j < NOROW; ++j) {
            const orow *oj = &orows[j];
            if (oj->op != o->op || oj->rancf) continue;
            if (rw->ref < 0) rw->ref = NELOP * NET + j;
            if (o->op == OP_INIT && oj->nm == o->nm && oj->nl == o->nl && oj->nt == o->nt)
                rw->ref_same = NELOP * NET + j;
        }
        ++nr;
    }

    snprintf(csv, sizeof csv, "out/bench/rancf_elem%s%s.csv", tag ? "-" : "", tag ? tag : "");
    f = svgp_csv_open(csv, "operation,variant,rancf,nm,nl,nt,calls_per_batch,batches,median_ns,"
                           "min_ns,rel_to_ancf,rel_to_ancf_same_orders,busy");
    if (!f) fprintf(stderr, "bench_rancf: cannot write %s\n", csv);

    printf("%-18s %-34s %10s %10s %8s %8s\n", "operation", "variant", "median ns", "min ns",
           "vs ANCF", "vs same n");
    for (op = 0; op < NOP; ++op) {
        int idx[MAXROW], n = 0, v;
        for (i = 0; i < NROWS; ++i)
            if (rows[i].op == op && n < MAXROW) idx[n++] = i;
        measure_op(idx, n, &bad);
        for (v = 0; v < n; ++v) {
            const row *rw = &rows[idx[v]];
            const double r1 = rw->ref >= 0 ? rw->med_ns / rows[rw->ref].med_ns : DNAN;
            const double r2 = rw->ref_same >= 0 ? rw->med_ns / rows[rw->ref_same].med_ns : DNAN;
            const int noisy = rw->med_ns > BENCHU_NOISY * rw->min_ns;
            nnoisy += noisy;
            printf("%-18s %-34s %10.1f %10.1f", v == 0 ? op_name[op] : "", rw->name, rw->med_ns,
                   rw->min_ns);
            print_ratio(r1);
            print_ratio(r2);
            printf("%s\n", noisy ? " *" : "");
            fflush(stdout);
            if (f)
                fprintf(f, "%s,\"%s\",%d,%d,%d,%d,%ld,%d,%.6g,%.6g,%.4g,%.4g,%s\n", op_csv[op],
                        rw->name, rw->rancf, rw->nm, rw->nl, rw->nt, rw->calls, BENCHU_BATCHES,
                        rw->med_ns, rw->min_ns, r1, r2, noisy ? "yes" : "no");
        }
        printf("\n");
    }

    if (nnoisy)
        printf("* median > %.2f x min: the machine was busy during this row; rerun on a quiet "
               "machine\n",
               BENCHU_NOISY);
    printf("load average: %.2f at start, %.2f at end (%d rows marked busy)\n", load0,
           benchu_load_avg(), nnoisy);
    for (e = 0; e < 2 * ET_PER_ORDER; ++e) { /* 4/5/5 and 6/7/7 against 8/8/8 */
        double eq, ek, em;
        if (!etypes[e].rancf) continue;
        order_error(e, e % ET_PER_ORDER + 2 * ET_PER_ORDER, &eq, &ek, &em);
        printf("%-24s against 8/8/8: max |dQ|/max |Q| = %.1e, |dK|/|K| = %.1e, |dM|/|M| = %.1e\n",
               etypes[e].name, eq, ek, em);
    }
    for (e = 1; e < ET_PER_ORDER; ++e)
        printf("%s weights, 4/5/5: force Q only %.2f, mass %.2f, mass_jac %.2f, energy %.2f x "
               "ALE-ANCF\n",
               wset_name[etypes[e].wset], rows[OP_Q * NET + e].med_ns / rows[OP_Q * NET].med_ns,
               rows[OP_M * NET + e].med_ns / rows[OP_M * NET].med_ns,
               rows[OP_MJ * NET + e].med_ns / rows[OP_MJ * NET].med_ns,
               rows[OP_E * NET + e].med_ns / rows[OP_E * NET].med_ns);
    rc = benchu_finish("bench_rancf", f, csv, bad);
    printf("\ntarget (default Gauss orders 4/5/5):\n");
    for (e = 1; e < ET_PER_ORDER; ++e) {
        const double rk = rows[OP_QKD * NET + e].med_ns / rows[OP_QKD * NET].med_ns;
        printf("ALE-RANCF Q+K+D / ALE-ANCF Q+K+D = %.2f (target <= 1.3): %s  [%s weights]\n", rk,
               rk <= 1.3 ? "PASS" : "MISS", wset_name[etypes[e].wset]);
    }
    return rc;
}
