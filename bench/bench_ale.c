/* bench_ale.c -- cost of one planar ALE-ANCF element of ancf_ale.h per call:
   vlbe_ale_force (Q only, and Q with K and D), vlbe_ale_mass,
   vlbe_ale_mass_jac and vlbe_ale_energy, for the full element and under each
   mode switch and lower Gauss orders.

   build (from the repository root; `make bench` does this):
       cc -std=c99 -O3 -march=native bench/bench_ale.c -o build/bench/bench_ale -lm
   run from the repository root:  build/bench/bench_ale [tag]
   writes out/bench/ale_elem[-tag].csv (out/bench must exist).

   Performance targets, ns per element call for the full element (bending,
   Kelvin-Voigt damping, both material coordinates free, default Gauss
   orders nm/nl/nt = 4/5/5): forces (K = D = NULL) <= 300, forces with K and
   D <= 1500, mass matrix <= 500.  The other rows carry the same target for
   comparison.  A missed target is reported (last lines: PASS/MISS for the
   full element), not an error: the exit status is 1 only when a call fails.

   State: one element of a steel wire (d = 5 mm: rhoA = 0.154 kg/m, EA = 4.1
   MN, EI = 6.4 N m^2, c_eps = c_kap = 1 ms, gravity as the distributed load)
   on p in [1, 1.25] m, bent to a circular arc of radius 0.5 m and stretched
   by 0.2 %, rotating at 0.8 rad/s and translating, with a stretching rate and
   axial material flow p1' = 0.30 m/s, p2' = 0.25 m/s; acceleration for
   vlbe_ale_mass_jac of the same order, p-rows included.  Every coordinate is
   nonzero, so no term is skipped by a zero test.

   Method: 8 copies of the state, each coordinate perturbed by a relative
   1e-7 (fixed seed); call r uses copy r mod 8.  After each call one output
   entry chosen by r (Q[r mod 10], K[r mod 100], D[(7 r) mod 100], ...) is
   added to an accumulator stored into a volatile sink, so no output can be
   dropped, and the status codes are checked.  The mode is read at run time
   (not a constant the compiler could specialize the kernel for), as in an
   assembly loop.  Per configuration: a warm-up batch, then BENCHU_BATCHES = 31
   batches of k calls each (k = 1e4, raised only if a batch would take less
   than 0.2 ms), CLOCK_MONOTONIC around each batch.  Batches are kept short
   (0.2 .. 4 ms) so that few of them straddle a time slice of another
   process when the machine is shared; the batches of the variants of one
   operation run interleaved (round robin), so that a passing disturbance
   of the machine does not fall on all batches of one row.  Reported: median
   and min over the batches of ns per call; a row whose median exceeds 1.15
   times its min is marked '*' (machine busy: rerun). */
#define _POSIX_C_SOURCE 199309L
#include "../ancf_ale.h"
#include "../scenes/svgplot.h"
#include "bench_util.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define MIN_CALLS 10000L
#define NSTATE 8 /* perturbed copies of the state, cycled through */
#define DNAN ((double)NAN)

static volatile double sink;
static volatile unsigned mode_src; /* modes pass through here: not constants */



static unsigned long long rng_state = 0x9E3779B97F4A7C15ULL;
static double urand(void) { return benchu_urand(&rng_state); }

/* -- the element state ------------------------------------------------------ */
static vlbe_real qs[NSTATE][VLBE_ALE_NQ], qds[NSTATE][VLBE_ALE_NQ], as[NSTATE][VLBE_ALE_NQ];

/* the arc of benchu_arc_state, with NSTATE small perturbations */
static void make_states(void)
{
    double q[10], qd[10], a[10];
    int s, i;
    benchu_arc_state(q, qd, a);
    for (s = 0; s < NSTATE; ++s)
        for (i = 0; i < 10; ++i) {
            qs[s][i] = (vlbe_real)(q[i] * (1.0 + 1e-7 * urand()));
            qds[s][i] = (vlbe_real)(qd[i] * (1.0 + 1e-7 * urand()));
            as[s][i] = (vlbe_real)(a[i] * (1.0 + 1e-7 * urand()));
        }
}

/* -- operations and configurations ---------------------------------------- */
enum { OP_Q, OP_QKD, OP_M, OP_MJ, OP_E, NOP };
static const char *const op_name[NOP] = {"force Q", "force Q+K+D", "mass M", "mass_jac d(Ma)/dq",
                                         "energy T,U,V"};
static const char *const op_csv[NOP] = {"force_q", "force_qkd", "mass", "mass_jac", "energy"};
static const double op_target[NOP] = {300.0, 1500.0, 500.0, DNAN, DNAN};

typedef struct variant {
    const char *name;
    unsigned mode;
    int nm, nl, nt; /* Gauss orders given to vlbe_ale_elem_init (0 = default) */
} variant;

#define ALE_FIX (VLBE_ALE_FIX_P1 | VLBE_ALE_FIX_P2)
static const variant variants[] = {
    {"full ALE beam (4/5/5)", 0u, 0, 0, 0},
    {"NO_BEND (string)", VLBE_ALE_NO_BEND, 0, 0, 0},
    {"NO_DAMP", VLBE_ALE_NO_DAMP, 0, 0, 0},
    {"FIX_P1|FIX_P2 (Lagrangian)", ALE_FIX, 0, 0, 0},
    {"FIX_P1 only", VLBE_ALE_FIX_P1, 0, 0, 0},
    {"CONSERVATIVE", VLBE_ALE_CONSERVATIVE, 0, 0, 0},
    {"Gauss nl 4, nt 3", 0u, 0, 4, 3},
    {"NO_BEND|NO_DAMP|FIX (ANCF cable)", VLBE_ALE_NO_BEND | VLBE_ALE_NO_DAMP | ALE_FIX, 0, 0, 0},
};
#define NVAR ((int)(sizeof variants / sizeof variants[0]))

/* One timed batch of k calls of operation op; seconds per call.  *bad
   counts calls that did not return VLBE_OK. */
static double batch(int op, const vlbe_ale_elem *el, long k, long *bad)
{
    vlbe_real Q[10], K[100], D[100], M[100], E[3];
    const unsigned mode = mode_src;
    double t0, acc = 0.0;
    long r, nbad = 0;
    t0 = benchu_now();
    switch (op) {
    case OP_Q:
        for (r = 0; r < k; ++r) {
            const int s = (int)(r & (NSTATE - 1));
            nbad += vlbe_ale_force(el, mode, qs[s], qds[s], Q, NULL, NULL) != VLBE_OK;
            acc += (double)Q[r % 10];
        }
        break;
    case OP_QKD:
        for (r = 0; r < k; ++r) {
            const int s = (int)(r & (NSTATE - 1));
            nbad += vlbe_ale_force(el, mode, qs[s], qds[s], Q, K, D) != VLBE_OK;
            acc += (double)Q[r % 10] + (double)K[r % 100] + (double)D[(7 * r) % 100];
        }
        break;
    case OP_M:
        for (r = 0; r < k; ++r) {
            const int s = (int)(r & (NSTATE - 1));
            nbad += vlbe_ale_mass(el, mode, qs[s], M) != VLBE_OK;
            acc += (double)M[r % 100];
        }
        break;
    case OP_MJ:
        for (r = 0; r < k; ++r) {
            const int s = (int)(r & (NSTATE - 1));
            nbad += vlbe_ale_mass_jac(el, mode, qs[s], as[s], M) != VLBE_OK;
            acc += (double)M[r % 100];
        }
        break;
    default:
        for (r = 0; r < k; ++r) {
            const int s = (int)(r & (NSTATE - 1));
            nbad += vlbe_ale_energy(el, mode, qs[s], qds[s], E) != VLBE_OK;
            acc += (double)E[r % 3];
        }
        break;
    }
    t0 = benchu_now() - t0;
    sink = acc;
    *bad += nbad;
    return t0 / (double)k;
}

typedef struct result {
    double med_ns, min_ns;
    long calls; /* per batch */
} result;

/* All variants of one operation: warm-up and calibration of k per variant,
   then BENCHU_BATCHES rounds of one batch per variant (interleaved, so that a
   disturbance of the machine spreads over the variants instead of hitting
   all batches of one), median and min per variant. */
static void measure_op(int op, const vlbe_ale_elem *els, const unsigned *modes, result *res,
                       long *bad)
{
    static double s[NVAR][BENCHU_BATCHES];
    long k[NVAR];
    int v, i;
    for (v = 0; v < NVAR; ++v) {
        double t;
        mode_src = modes[v];
        k[v] = MIN_CALLS;
        t = batch(op, &els[v], k[v], bad);
        if (t * (double)k[v] < BENCHU_MIN_BATCH_S) k[v] = (long)(BENCHU_MIN_BATCH_S / (t > 1e-10 ? t : 1e-10)) + 1;
        if (k[v] > BENCHU_MAX_CALLS) k[v] = BENCHU_MAX_CALLS;
        if (k[v] < MIN_CALLS) k[v] = MIN_CALLS;
    }
    for (i = 0; i < BENCHU_BATCHES; ++i)
        for (v = 0; v < NVAR; ++v) {
            mode_src = modes[v];
            s[v][i] = batch(op, &els[v], k[v], bad);
        }
    for (v = 0; v < NVAR; ++v) {
        qsort(s[v], BENCHU_BATCHES, sizeof s[v][0], benchu_cmp_double);
        res[v].med_ns = 1e9 * s[v][BENCHU_BATCHES / 2];
        res[v].min_ns = 1e9 * s[v][0];
        res[v].calls = k[v];
    }
}

/* Largest |difference| of Q, K (flattened) of el2 against el, relative to
   the largest |entry| of el's: the price of lower Gauss orders. */
static void order_error(const vlbe_ale_elem *el, const vlbe_ale_elem *el2, double *eq, double *ek)
{
    vlbe_real Q1[10], K1[100], D1[100], Q2[10], K2[100], D2[100];
    double nq = 0.0, nk = 0.0, dq = 0.0, dk = 0.0;
    int i;
    *eq = *ek = DNAN;
    if (vlbe_ale_force(el, 0u, qs[0], qds[0], Q1, K1, D1) != VLBE_OK) return;
    if (vlbe_ale_force(el2, 0u, qs[0], qds[0], Q2, K2, D2) != VLBE_OK) return;
    for (i = 0; i < 10; ++i) {
        if (fabs((double)Q1[i]) > nq) nq = fabs((double)Q1[i]);
        if (fabs((double)(Q2[i] - Q1[i])) > dq) dq = fabs((double)(Q2[i] - Q1[i]));
    }
    for (i = 0; i < 100; ++i) {
        if (fabs((double)K1[i]) > nk) nk = fabs((double)K1[i]);
        if (fabs((double)(K2[i] - K1[i])) > dk) dk = fabs((double)(K2[i] - K1[i]));
    }
    *eq = dq / nq;
    *ek = dk / nk;
}

int main(int argc, char **argv)
{
    static result res[NOP][NVAR];
    const char *tag = argc > 1 ? argv[1] : NULL;
    const vlbe_ale_mat mat = benchu_wire();
    static vlbe_ale_elem els[NVAR]; /* ~15 kB each */
    unsigned modes[NVAR];
    char model[128], csv[256];
    double mhz, eq, ek;
    long bad = 0;
    int op, v, order_var = -1, nnoisy = 0;
    FILE *f;

    benchu_cpu_info(model, sizeof model, &mhz);
    printf("bench_ale: one planar ALE-ANCF element (ancf_ale.h), vlbe %s, %s\n", VLBE_VERSION_STRING,
           sizeof(vlbe_real) == sizeof(double) ? "double" : "float");
    printf("compiler: %s, flags: %s\n", __VERSION__, VLBE_BENCH_FLAGS);
    printf("cpu: %s, %.0f MHz (/proc/cpuinfo), load average %.2f at start\n", model, mhz,
           benchu_load_avg());
    printf("ns per element call: median (min) of %d batches of >= %ld calls after warm-up, "
           "CLOCK_MONOTONIC\n",
           BENCHU_BATCHES, MIN_CALLS);
    printf("state: bent (R = 0.5 m), stretched (0.2 %%), rotating wire element, L = 0.25 m, "
           "p1' = 0.30, p2' = 0.25 m/s\n\n");

    make_states();
    for (v = 0; v < NVAR; ++v) {
        vlbe_status st = vlbe_ale_elem_init(&els[v], &mat, 0u, variants[v].nm, variants[v].nl,
                                            variants[v].nt);
        if (st != VLBE_OK) {
            fprintf(stderr, "bench_ale: vlbe_ale_elem_init (%s): %s\n", variants[v].name,
                    vlbe_status_str(st));
            return 1;
        }
        if (variants[v].nl != 0 || variants[v].nt != 0) order_var = v;
        modes[v] = variants[v].mode;
    }

    snprintf(csv, sizeof csv, "out/bench/ale_elem%s%s.csv", tag ? "-" : "", tag ? tag : "");
    f = svgp_csv_open(csv, "operation,variant,mode,nm,nl,nt,calls_per_batch,batches,median_ns,"
                           "min_ns,rel_to_full,target_ns,pass");
    if (!f) fprintf(stderr, "bench_ale: cannot write %s\n", csv);

    printf("%-18s %-34s %10s %10s %8s %8s %6s\n", "operation", "variant", "median ns", "min ns",
           "vs full", "target", "");
    for (op = 0; op < NOP; ++op) {
        measure_op(op, els, modes, res[op], &bad);
        for (v = 0; v < NVAR; ++v) {
            const variant *va = &variants[v];
            const double tg = op_target[op];
            const int has_tg = !isnan(tg);
            double rel;
            int pass, noisy;
            rel = res[op][v].med_ns / res[op][0].med_ns;
            pass = has_tg && res[op][v].med_ns <= tg;
            printf("%-18s %-34s %10.1f %10.1f %8.2f ", v == 0 ? op_name[op] : "", va->name,
                   res[op][v].med_ns, res[op][v].min_ns, rel);
            noisy = res[op][v].med_ns > BENCHU_NOISY * res[op][v].min_ns;
            nnoisy += noisy;
            if (has_tg) printf("%8.0f %6s%s\n", tg, pass ? "PASS" : "FAIL", noisy ? " *" : "");
            else printf("%8s %6s%s\n", "-", "", noisy ? " *" : "");
            fflush(stdout);
            if (f)
                fprintf(f, "%s,\"%s\",%u,%d,%d,%d,%ld,%d,%.6g,%.6g,%.4g,%.6g,%s\n", op_csv[op],
                        va->name, va->mode, va->nm ? va->nm : 4, va->nl ? va->nl : 5,
                        va->nt ? va->nt : 5, res[op][v].calls, BENCHU_BATCHES, res[op][v].med_ns,
                        res[op][v].min_ns, rel, tg, has_tg ? (pass ? "yes" : "no") : "");
        }
        printf("\n");
    }

    if (nnoisy)
        printf("* median > %.2f x min: the machine was busy during this row (load average now "
               "%.2f); rerun on a quiet machine\n",
               BENCHU_NOISY, benchu_load_avg());
    if (order_var >= 0) {
        order_error(&els[0], &els[order_var], &eq, &ek);
        printf("%s against 4/5/5: max |dQ| / max |Q| = %.2e, max |dK| / max |K| = %.2e\n",
               variants[order_var].name, eq, ek);
    }
    printf("targets (full element): force Q %.1f <= %.0f ns %s, Q+K+D %.1f <= %.0f ns %s, "
           "mass %.1f <= %.0f ns %s\n",
           res[OP_Q][0].med_ns, op_target[OP_Q], res[OP_Q][0].med_ns <= op_target[OP_Q] ? "PASS" : "MISS",
           res[OP_QKD][0].med_ns, op_target[OP_QKD],
           res[OP_QKD][0].med_ns <= op_target[OP_QKD] ? "PASS" : "MISS", res[OP_M][0].med_ns,
           op_target[OP_M], res[OP_M][0].med_ns <= op_target[OP_M] ? "PASS" : "MISS");
    return benchu_finish("bench_ale", f, csv, bad);
}
