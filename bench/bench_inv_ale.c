/* bench_inv_ale.c -- cost of one planar ALE-ANCF element of ancf_ale.h with
   its axial force from Gauss points (vlbe_ale_force) or from the invariant
   tables (the same call with VLBE_ALE_INV_AXIAL), for ALE elements (p2
   free, both p free) and, for reference, the fixed-length element; Q
   alone and Q with K and D; cable (NO_BEND) and beam; with and without
   Kelvin-Voigt damping.  Bending, transport inertia and (ALE) the load stay
   on Gauss points on both routes: only the axial part differs.

   build (from the repository root; `make bench` does this):
       cc -std=c99 -O3 -march=native bench/bench_inv_ale.c -o build/bench/bench_inv_ale -lm
   run from the repository root:  build/bench/bench_inv_ale [tag]
   writes out/bench/inv_ale[-tag].csv (out/bench must exist).

   Element: the steel wire of bench_ale.c (d = 5 mm: rhoA = 0.154 kg/m,
   EA = 4.1 MN, EI = 6.4 N m^2, c_eps = c_kap = 1 ms, gravity as the load)
   on p in [1, 1.25] m, bent to an arc of radius 0.5 m, stretched 0.2 %,
   rotating at 0.8 rad/s, translating and stretching, material flow p1' =
   0.30 m/s, p2' = 0.25 m/s (ignored where a p is fixed).  Default Gauss
   orders nm/nl/nt = 4/5/5.

   Method as in bench_inv.c: NSTATE perturbed copies of the state cycled
   through, one output entry per call summed into a volatile sink, the mode
   read at run time; per configuration a warm-up and calibration, then
   BENCHU_BATCHES rounds of one batch per configuration (interleaved round robin,
   so that a disturbance of the shared machine spreads over all rows), each
   batch >= 0.2 ms.  Reported: median (min) ns per call over the batches
   and the ratio Gauss / invariants of the medians (> 1: invariants
   faster); a row whose median exceeds 1.15 times its min is marked '*'.
   That both routes give the same numbers is tests/test_ale_inv.c's part. */
#define _POSIX_C_SOURCE 199309L
#include "../ancf_ale.h"
#include "../scenes/svgplot.h"
#include "bench_util.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MIN_CALLS 2000L
#define NSTATE 8

static volatile double sink;
static volatile unsigned mode_src;

static unsigned long long rng_state = 0x2545F4914F6CDD1DULL;

/* -- the element state ---------------------------------------------------- */
static vlbe_real qs[NSTATE][10], qds[NSTATE][10];

/* node n (0, 1) of the arc at material p: position, slope and their rates
   (rotation om, translation v0, stretch rate lamd) and p' into q, qd */
static void arc_state(int n, double p, double pd, double *q, double *qd)
{
    const double R = 0.5, lam = 1.002, lamd = 0.01, om = 0.8, v0x = 0.4, v0y = -0.2;
    const double th = 0.3 + (p - 1.0) / R, g = lamd / lam;
    const double x = lam * R * sin(th), y = lam * R * (1.0 - cos(th));
    const double tx = lam * cos(th), ty = lam * sin(th);
    double *o = q + 5 * n, *od = qd + 5 * n;
    o[0] = x;
    o[1] = y;
    o[2] = tx;
    o[3] = ty;
    o[4] = p;
    od[0] = v0x - om * y + g * x;
    od[1] = v0y + om * x + g * y;
    od[2] = -om * ty + g * tx;
    od[3] = om * tx + g * ty;
    od[4] = pd;
}

static void make_states(void)
{
    double q[10], qd[10];
    int s, i;
    arc_state(0, 1.0, 0.30, q, qd);
    arc_state(1, 1.25, 0.25, q, qd);
    for (s = 0; s < NSTATE; ++s)
        for (i = 0; i < 10; ++i) {
            qs[s][i] = (vlbe_real)(q[i] * (1.0 + 1e-7 * benchu_urand(&rng_state)));
            qds[s][i] = (vlbe_real)(qd[i] * (1.0 + 1e-7 * benchu_urand(&rng_state)));
        }
}

/* -- configurations --------------------------------------------------------- */
enum { NPM = 3, NBEND = 2, NDAMP = 2, NJAC = 2, NROUTE = 2 };
static const unsigned pm_flags[NPM] = {VLBE_ALE_FIX_P1, 0u, VLBE_ALE_FIX_P1 | VLBE_ALE_FIX_P2};
static const char *const pm_name[NPM] = {"p2 free", "p1, p2 free", "fixed length"};
static const char *const pm_csv[NPM] = {"p2_free", "both_free", "fixed"};

typedef struct cfg {
    unsigned mode; /* the whole mode word of the call */
    int jac;
    double med, min;
    long calls;
} cfg;

/* index of a configuration: route fastest */
static int cfg_index(int pm, int bend, int damp, int jac, int route)
{
    return (((pm * NBEND + bend) * NDAMP + damp) * NJAC + jac) * NROUTE + route;
}

static vlbe_ale_elem el;

/* one timed batch of k calls; seconds per call */
static double run_batch(const cfg *c, long k, long *bad)
{
    static vlbe_real Q[10], K[100], D[100];
    const unsigned mode = mode_src;
    const int jac = c->jac;
    double t0, acc = 0.0;
    long r, nbad = 0;
    t0 = benchu_now();
    for (r = 0; r < k; ++r) {
        const int s = (int)(r & (NSTATE - 1));
        nbad += vlbe_ale_force(&el, mode, qs[s], qds[s], Q, jac ? K : NULL, jac ? D : NULL) !=
                VLBE_OK;
        acc += (double)Q[r % 10] + (jac ? (double)K[r % 100] + (double)D[(7 * r) % 100] : 0.0);
    }
    t0 = benchu_now() - t0;
    sink = acc;
    *bad += nbad;
    return t0 / (double)k;
}

/* calibrate each configuration's batch size, then BENCHU_BATCHES interleaved
   rounds; median and min in ns */
static void run_all(cfg *cs, int nc, long *bad)
{
    static double t[NPM * NBEND * NDAMP * NJAC * NROUTE][BENCHU_BATCHES];
    int i, b;
    for (i = 0; i < nc; ++i) {
        double s;
        long n;
        mode_src = cs[i].mode;
        (void)run_batch(&cs[i], MIN_CALLS, bad); /* warm-up */
        s = run_batch(&cs[i], MIN_CALLS, bad);
        n = (long)(BENCHU_MIN_BATCH_S / (s > 1e-10 ? s : 1e-10)) + 1;
        cs[i].calls = n < MIN_CALLS ? MIN_CALLS : (n > BENCHU_MAX_CALLS ? BENCHU_MAX_CALLS : n);
    }
    for (b = 0; b < BENCHU_BATCHES; ++b)
        for (i = 0; i < nc; ++i) {
            mode_src = cs[i].mode;
            t[i][b] = run_batch(&cs[i], cs[i].calls, bad);
        }
    for (i = 0; i < nc; ++i) {
        qsort(t[i], BENCHU_BATCHES, sizeof t[i][0], benchu_cmp_double);
        cs[i].med = 1e9 * t[i][BENCHU_BATCHES / 2];
        cs[i].min = 1e9 * t[i][0];
    }
}

int main(int argc, char **argv)
{
    static cfg cs[NPM * NBEND * NDAMP * NJAC * NROUTE];
    const char *tag = argc > 1 ? argv[1] : NULL;
    const int nc = NPM * NBEND * NDAMP * NJAC * NROUTE;
    vlbe_ale_mat mat;
    char model[128], csv[256];
    double mhz;
    long bad = 0;
    int pm, bend, damp, jac, route, nnoisy = 0;
    FILE *f;

    memset(&mat, 0, sizeof mat);
    mat.rhoA = VLBE_R(0.154);
    mat.EA = VLBE_R(4.1e6);
    mat.EI = VLBE_R(6.4);
    mat.c_eps = VLBE_R(1e-3);
    mat.c_kap = VLBE_R(1e-3);
    mat.f[1] = VLBE_R(-9.81) * mat.rhoA;
    if (vlbe_ale_elem_init(&el, &mat, 0u, 0, 0, 0) != VLBE_OK) return 1;
    make_states();
    benchu_cpu_info(model, sizeof model, &mhz);
    printf("bench_inv_ale: planar ALE-ANCF element, axial force by Gauss points or invariants,"
           " vlbe %s, %s\n",
           VLBE_VERSION_STRING, sizeof(vlbe_real) == sizeof(double) ? "double" : "float");
    printf("compiler: %s, flags: %s\n", __VERSION__, VLBE_BENCH_FLAGS);
    printf("cpu: %s, %.0f MHz (/proc/cpuinfo)\n", model, mhz);
    printf("ns per element call: median (min) of %d interleaved batches\n\n", BENCHU_BATCHES);

    for (pm = 0; pm < NPM; ++pm)
        for (bend = 0; bend < NBEND; ++bend)
            for (damp = 0; damp < NDAMP; ++damp)
                for (jac = 0; jac < NJAC; ++jac)
                    for (route = 0; route < NROUTE; ++route) {
                        cfg *c = &cs[cfg_index(pm, bend, damp, jac, route)];
                        c->mode = pm_flags[pm] | (bend ? 0u : VLBE_ALE_NO_BEND) |
                                  (damp ? 0u : VLBE_ALE_NO_DAMP) |
                                  (route ? VLBE_ALE_INV_AXIAL : 0u);
                        c->jac = jac;
                    }
    run_all(cs, nc, &bad);

    printf("%-13s %-6s %-9s %22s %22s %8s\n", "element", "model", "damping", "Gauss", "invariants",
           "G / inv");
    for (jac = 0; jac < NJAC; ++jac) {
        printf("%s\n", jac ? "force Q+K+D" : "force Q");
        for (pm = 0; pm < NPM; ++pm)
            for (bend = 0; bend < NBEND; ++bend)
                for (damp = NDAMP - 1; damp >= 0; --damp) {
                    const cfg *g = &cs[cfg_index(pm, bend, damp, jac, 0)];
                    const cfg *v = &cs[cfg_index(pm, bend, damp, jac, 1)];
                    const int noisy = g->med > BENCHU_NOISY * g->min || v->med > BENCHU_NOISY * v->min;
                    printf("  %-11s %-6s %-9s %12.1f (%7.1f) %12.1f (%7.1f) %8.2f%s\n", pm_name[pm],
                           bend ? "beam" : "cable", damp ? "damped" : "undamped", g->med, g->min,
                           v->med, v->min, g->med / v->med, noisy ? " *" : "");
                    nnoisy += noisy;
                }
    }
    if (nnoisy)
        printf("* median > %.2f x min: the machine was busy; rerun on a quiet machine\n", BENCHU_NOISY);

    snprintf(csv, sizeof csv, "out/bench/inv_ale%s%s.csv", tag ? "-" : "", tag ? tag : "");
    f = svgp_csv_open(csv, "what,element,model,damped,route,calls_per_batch,batches,median_ns,"
                           "min_ns");
    if (!f) fprintf(stderr, "bench_inv_ale: cannot write %s\n", csv);
    else {
        for (pm = 0; pm < NPM; ++pm)
            for (bend = 0; bend < NBEND; ++bend)
                for (damp = 0; damp < NDAMP; ++damp)
                    for (jac = 0; jac < NJAC; ++jac)
                        for (route = 0; route < NROUTE; ++route) {
                            const cfg *c = &cs[cfg_index(pm, bend, damp, jac, route)];
                            fprintf(f, "%s,%s,%s,%d,%s,%ld,%d,%.6g,%.6g\n",
                                    jac ? "force_qkd" : "force_q", pm_csv[pm],
                                    bend ? "beam" : "cable", damp, route ? "inv" : "gauss",
                                    c->calls, BENCHU_BATCHES, c->med, c->min);
                        }
    }
    return benchu_finish("bench_inv_ale", f, csv, bad);
}
