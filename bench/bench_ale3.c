/* bench_ale3.c -- cost of one 3D ALE beam-shaft element with spin of
   ancf_ale.h per call: vlbe_ale3_force (Q only, and Q with K and D) for the
   full element and under each mode switch, vlbe_ale3_mass and
   vlbe_ale3_mass_jac, and the planar element (vlbe_ale_force, the same
   material in its plane) for comparison.

   build (from the repository root; `make bench` does this):
       cc -std=c99 -O3 -march=native bench/bench_ale3.c -o build/bench/bench_ale3 -lm
   run from the repository root:  build/bench/bench_ale3 [tag]
   writes out/bench/ale3_elem[-tag].csv (out/bench must exist).

   Targets of the 3D beam-shaft, ns per element call for the full element (spin,
   both material coordinates free, bending, twist, Kelvin-Voigt damping,
   default Gauss orders nm/ns = 4/5): forces (K = D = NULL) <= 1000,
   forces with K and D <= 5000; and the element without spin
   (VLBE_ALE3_NO_SPIN, 14 coordinates) at least 1.5 times faster than the
   element with spin under the same other switches (full / NO_SPIN; also
   reported for the Lagrangian pair).  The other 3D force rows carry the
   same targets for comparison.  A missed target is reported (last lines:
   PASS/MISS), not an error: the exit status is 1 only when a call fails.

   State: one element of a steel shaft (d = 5 mm, the wire of bench_ale.c:
   rho = 7850 kg/m^3, E = 210 GPa, G = 81 GPa by vlbe_ale3_mat_circle: rhoA
   = 0.154 kg/m, EA = 4.1 MN, EJ = 6.4 N m^2, c_eps = c_kap = c_phi = 1 ms,
   gravity -y as the distributed load) on p in [1, 1.25] m, bent to a helix
   (radius 0.4 m, pitch 2 pi 0.2 m: curvature 2/m, torsion 1/m), stretched by
   0.2 % and twisted by 0.05 rad/m, spinning at 100 rad/s, rotating rigidly
   at (0.3, -0.2, 0.8) rad/s and translating, with a stretching and
   twisting rate and axial material flow p1' = 0.30 m/s, p2' = 0.25 m/s;
   acceleration for vlbe_ale3_mass_jac of the same order, p-rows included.
   Every coordinate is nonzero, so no term is skipped by a zero test.  The
   planar rows use the planar arc of bench_ale.c (radius 0.5 m, same
   stretch, flow and material in the plane); the 3D element without spin
   on that arc (z = 0) gives the planar element's Q (checked, last lines).

   Method as in bench_ale.c: 8 copies of the state, each coordinate
   perturbed by a relative 1e-7 (fixed seed); call r uses copy r mod 8.
   After each call one output entry chosen by r (Q[r mod n], K[r mod n^2],
   D[(7 r) mod n^2], ...) is added to an accumulator stored into a volatile
   sink, so no output can be dropped, and the status codes are checked.
   The mode is read at run time (not a constant the compiler could
   specialize the kernel for), as in an assembly loop.  Per row: a warm-up
   batch, then BENCHU_BATCHES = 31 batches of k calls each (k = 500, raised
   only if a batch would take less than 0.2 ms), CLOCK_MONOTONIC around each
   batch; the batches of the rows of one operation run interleaved (round
   robin), so that a passing disturbance of the machine does not fall on
   all batches of one row.  Reported: median and min over the batches of ns
   per call, and the ratio of the median to the full 3D element's (same
   operation: the first row of each); a row whose median exceeds
   1.15 times its min is marked '*' (machine busy: rerun). */
#define _POSIX_C_SOURCE 199309L
#include "../ancf_ale.h"
#include "../scenes/svgplot.h"
#include "bench_util.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define MIN_CALLS 500L
#define NSTATE 8 /* perturbed copies of the state, cycled through */
#define DNAN ((double)NAN)
#define NQ3 VLBE_ALE3_NQ
#define NQ2 VLBE_ALE_NQ

static volatile double sink;
static volatile unsigned mode_src; /* modes pass through here: not constants */


static unsigned long long rng_state = 0x9E3779B97F4A7C15ULL;
static double urand(void) { return benchu_urand(&rng_state); }

/* -- the element states ------------------------------------------------------ */
/* [0]: 3D with spin (16), [1]: 3D without spin (14 used), planar (10) */
static vlbe_real q3[2][NSTATE][NQ3], qd3[2][NSTATE][NQ3], a3[2][NSTATE][NQ3];
static vlbe_real q2[NSTATE][NQ2], qd2[NSTATE][NQ2], a2[NSTATE][NQ2];

static void shaft(vlbe_ale3_mat *m3, vlbe_ale_mat *m2)
{
    if (vlbe_ale3_mat_circle(m3, VLBE_R(7850.0), VLBE_R(2.1e11), VLBE_R(8.1e10),
                             VLBE_R(2.5e-3)) != VLBE_OK)
        exit(1);
    m3->c_eps = m3->c_kap = m3->c_phi = VLBE_R(1e-3);
    m3->f[0] = VLBE_R(0.0);
    m3->f[1] = VLBE_R(-9.81) * m3->rhoA;
    m3->f[2] = VLBE_R(0.0);
    /* the planar element: the same section in its plane */
    memset(m2, 0, sizeof *m2);
    m2->rhoA = m3->rhoA;
    m2->EA = m3->EA;
    m2->EI = m3->EJ;
    m2->c_eps = m3->c_eps;
    m2->c_kap = m3->c_kap;
    m2->f[0] = m3->f[0];
    m2->f[1] = m3->f[1];
}

static void cross(const double *a, const double *b, double *c)
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}

/* 3D: helix of radius ha and pitch parameter hb (arclength s from p = 1 +
   offset), stretched by lam, twisted, spinning at Om; rigid rotation om and
   translation v0, stretching rate lamd, twist rate, flow pd.  q, qd, a in
   the layout with spin (16); nospin drops theta (14). */
static void helix_state(int nospin, double *q, double *qd, double *a)
{
    const double ha = 0.4, hb = 0.2, hl = sqrt(ha * ha + hb * hb), s0 = 0.3;
    const double lam = 1.002, lamd = 0.01, om[3] = {0.3, -0.2, 0.8}, v0[3] = {0.4, -0.2, 0.1};
    const double th0 = 0.7, phi = 0.05, Om = 100.0, phid = 0.5;
    const double p[2] = {1.0, 1.25}, pd[2] = {0.30, 0.25}, pdd[2] = {0.6, -0.4};
    const int ns = nospin ? 7 : 8;
    int n, c;
    for (n = 0; n < 2; ++n) {
        const int o = ns * n;
        const double u = (s0 + p[n] - p[0]) / hl;
        const double r[3] = {lam * ha * cos(u), lam * ha * sin(u), lam * hb * u};
        const double rp[3] = {-lam * ha / hl * sin(u), lam * ha / hl * cos(u), lam * hb / hl};
        double wr[3], wrp[3];
        cross(om, r, wr);
        cross(om, rp, wrp);
        for (c = 0; c < 3; ++c) {
            q[o + c] = r[c];
            q[o + 3 + c] = rp[c];
            qd[o + c] = v0[c] + wr[c] + lamd / lam * r[c];
            qd[o + 3 + c] = wrp[c] + lamd / lam * rp[c];
            /* some of everything */
            a[o + c] = -0.64 * r[c] + 0.1 * (c + 1);
            a[o + 3 + c] = -0.64 * rp[c] - 0.03 * (c + 1);
        }
        a[o + 1] -= 9.81;
        if (!nospin) {
            q[o + 6] = th0 + phi * (p[n] - p[0]);
            qd[o + 6] = Om + phid * (p[n] - p[0]);
            a[o + 6] = n ? 2.0 : -1.5;
        }
        q[o + ns - 1] = p[n];
        qd[o + ns - 1] = pd[n];
        a[o + ns - 1] = pdd[n];
    }
}

static void make_states(void)
{
    double q[NQ3], qd[NQ3], a[NQ3];
    int v, s, i;
    for (v = 0; v < 2; ++v) {
        helix_state(v, q, qd, a);
        for (s = 0; s < NSTATE; ++s)
            for (i = 0; i < NQ3 - 2 * v; ++i) {
                q3[v][s][i] = (vlbe_real)(q[i] * (1.0 + 1e-7 * urand()));
                qd3[v][s][i] = (vlbe_real)(qd[i] * (1.0 + 1e-7 * urand()));
                a3[v][s][i] = (vlbe_real)(a[i] * (1.0 + 1e-7 * urand()));
            }
    }
    benchu_arc_state(q, qd, a);
    for (s = 0; s < NSTATE; ++s)
        for (i = 0; i < NQ2; ++i) {
            q2[s][i] = (vlbe_real)(q[i] * (1.0 + 1e-7 * urand()));
            qd2[s][i] = (vlbe_real)(qd[i] * (1.0 + 1e-7 * urand()));
            a2[s][i] = (vlbe_real)(a[i] * (1.0 + 1e-7 * urand()));
        }
}

/* -- operations and rows ---------------------------------------------------- */
enum { OP_Q, OP_QKD, OP_M, OP_MJ, NOP };
static const char *const op_name[NOP] = {"force Q", "force Q+K+D", "mass M", "mass_jac d(Ma)/dq"};
static const char *const op_csv[NOP] = {"force_q", "force_qkd", "mass", "mass_jac"};
static const double op_target[NOP] = {1000.0, 5000.0, DNAN, DNAN};

#define FIX (VLBE_ALE_FIX_P1 | VLBE_ALE_FIX_P2)
#define NOSPIN VLBE_ALE3_NO_SPIN

typedef struct row {
    int op, planar;
    unsigned mode;
    const char *name;
} row;

/* Rows of one operation are measured together (interleaved); the first row
   of each force operation is the full 3D element. */
static const row rows[] = {
    {OP_Q, 0, 0u, "full (spin, ALE, bend, twist, damp)"},
    {OP_Q, 0, NOSPIN, "NO_SPIN (14 coordinates)"},
    {OP_Q, 0, VLBE_ALE_NO_BEND, "NO_BEND"},
    {OP_Q, 0, VLBE_ALE3_NO_TWIST, "NO_TWIST"},
    {OP_Q, 0, VLBE_ALE_NO_DAMP, "NO_DAMP"},
    {OP_Q, 0, FIX, "FIX_P1|FIX_P2 (Lagrangian)"},
    {OP_Q, 0, FIX | NOSPIN, "Lagrangian, NO_SPIN"},
    {OP_Q, 0, FIX | NOSPIN | VLBE_ALE_NO_DAMP, "Lagrangian, NO_SPIN, NO_DAMP (lean)"},
    {OP_Q, 1, 0u, "planar ALE (vlbe_ale_force)"},
    {OP_Q, 1, FIX, "planar Lagrangian"},
    {OP_Q, 1, FIX | VLBE_ALE_NO_DAMP, "planar Lagrangian, NO_DAMP"},
    {OP_QKD, 0, 0u, "full (spin, ALE, bend, twist, damp)"},
    {OP_QKD, 0, NOSPIN, "NO_SPIN (14 coordinates)"},
    {OP_QKD, 0, VLBE_ALE_NO_BEND, "NO_BEND"},
    {OP_QKD, 0, VLBE_ALE3_NO_TWIST, "NO_TWIST"},
    {OP_QKD, 0, VLBE_ALE_NO_DAMP, "NO_DAMP"},
    {OP_QKD, 0, FIX, "FIX_P1|FIX_P2 (Lagrangian)"},
    {OP_QKD, 0, FIX | NOSPIN, "Lagrangian, NO_SPIN"},
    {OP_QKD, 0, FIX | NOSPIN | VLBE_ALE_NO_DAMP, "Lagrangian, NO_SPIN, NO_DAMP (lean)"},
    {OP_QKD, 1, 0u, "planar ALE (vlbe_ale_force)"},
    {OP_QKD, 1, FIX, "planar Lagrangian"},
    {OP_QKD, 1, FIX | VLBE_ALE_NO_DAMP, "planar Lagrangian, NO_DAMP"},
    {OP_M, 0, 0u, "ALE (spin)"},
    {OP_M, 0, NOSPIN, "ALE, NO_SPIN"},
    {OP_M, 0, FIX, "FIX_P1|FIX_P2 (Lagrangian)"},
    {OP_M, 1, 0u, "planar ALE (vlbe_ale_mass)"},
    {OP_MJ, 0, 0u, "ALE (spin)"},
    {OP_MJ, 0, NOSPIN, "ALE, NO_SPIN"},
    {OP_MJ, 1, 0u, "planar ALE (vlbe_ale_mass_jac)"},
};
#define NROW ((int)(sizeof rows / sizeof rows[0]))

static vlbe_ale3_elem el3;
static vlbe_ale_elem el2;

/* One timed batch of k calls of row rw; seconds per call.  *bad counts
   calls that did not return VLBE_OK. */
static double batch(const row *rw, long k, long *bad)
{
    vlbe_real Q[NQ3], K[NQ3 * NQ3], D[NQ3 * NQ3], M[NQ3 * NQ3];
    const unsigned mode = mode_src;
    const int v = (mode & NOSPIN) ? 1 : 0;
    const long n = rw->planar ? NQ2 : vlbe_ale3_nq(mode), nn = n * n;
    double t0, acc = 0.0;
    long r, nbad = 0;
    t0 = benchu_now();
    if (!rw->planar) switch (rw->op) {
        case OP_Q:
            for (r = 0; r < k; ++r) {
                const int s = (int)(r & (NSTATE - 1));
                nbad += vlbe_ale3_force(&el3, mode, q3[v][s], qd3[v][s], Q, NULL, NULL) != VLBE_OK;
                acc += (double)Q[r % n];
            }
            break;
        case OP_QKD:
            for (r = 0; r < k; ++r) {
                const int s = (int)(r & (NSTATE - 1));
                nbad += vlbe_ale3_force(&el3, mode, q3[v][s], qd3[v][s], Q, K, D) != VLBE_OK;
                acc += (double)Q[r % n] + (double)K[r % nn] + (double)D[(7 * r) % nn];
            }
            break;
        case OP_M:
            for (r = 0; r < k; ++r) {
                const int s = (int)(r & (NSTATE - 1));
                nbad += vlbe_ale3_mass(&el3, mode, q3[v][s], M) != VLBE_OK;
                acc += (double)M[r % nn];
            }
            break;
        default:
            for (r = 0; r < k; ++r) {
                const int s = (int)(r & (NSTATE - 1));
                nbad += vlbe_ale3_mass_jac(&el3, mode, q3[v][s], a3[v][s], M) != VLBE_OK;
                acc += (double)M[r % nn];
            }
            break;
        }
    else switch (rw->op) {
        case OP_Q:
            for (r = 0; r < k; ++r) {
                const int s = (int)(r & (NSTATE - 1));
                nbad += vlbe_ale_force(&el2, mode, q2[s], qd2[s], Q, NULL, NULL) != VLBE_OK;
                acc += (double)Q[r % 10];
            }
            break;
        case OP_QKD:
            for (r = 0; r < k; ++r) {
                const int s = (int)(r & (NSTATE - 1));
                nbad += vlbe_ale_force(&el2, mode, q2[s], qd2[s], Q, K, D) != VLBE_OK;
                acc += (double)Q[r % 10] + (double)K[r % 100] + (double)D[(7 * r) % 100];
            }
            break;
        case OP_M:
            for (r = 0; r < k; ++r) {
                const int s = (int)(r & (NSTATE - 1));
                nbad += vlbe_ale_mass(&el2, mode, q2[s], M) != VLBE_OK;
                acc += (double)M[r % 100];
            }
            break;
        default:
            for (r = 0; r < k; ++r) {
                const int s = (int)(r & (NSTATE - 1));
                nbad += vlbe_ale_mass_jac(&el2, mode, q2[s], a2[s], M) != VLBE_OK;
                acc += (double)M[r % 100];
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

/* All rows of operation op: warm-up and calibration of k per row, then
   BENCHU_BATCHES rounds of one batch per row (interleaved), median and min
   per row. */
static void measure_op(int op, result *res, long *bad)
{
    static double s[NROW][BENCHU_BATCHES];
    long k[NROW];
    int v, i;
    for (v = 0; v < NROW; ++v) {
        double t;
        if (rows[v].op != op) continue;
        mode_src = rows[v].mode;
        k[v] = MIN_CALLS;
        t = batch(&rows[v], k[v], bad);
        if (t * (double)k[v] < BENCHU_MIN_BATCH_S)
            k[v] = (long)(BENCHU_MIN_BATCH_S / (t > 1e-10 ? t : 1e-10)) + 1;
        if (k[v] > BENCHU_MAX_CALLS) k[v] = BENCHU_MAX_CALLS;
        if (k[v] < MIN_CALLS) k[v] = MIN_CALLS;
    }
    for (i = 0; i < BENCHU_BATCHES; ++i)
        for (v = 0; v < NROW; ++v) {
            if (rows[v].op != op) continue;
            mode_src = rows[v].mode;
            s[v][i] = batch(&rows[v], k[v], bad);
        }
    for (v = 0; v < NROW; ++v) {
        if (rows[v].op != op) continue;
        qsort(s[v], BENCHU_BATCHES, sizeof s[v][0], benchu_cmp_double);
        res[v].med_ns = 1e9 * s[v][BENCHU_BATCHES / 2];
        res[v].min_ns = 1e9 * s[v][0];
        res[v].calls = k[v];
    }
}

/* the row of operation op, element kind planar and mode (-1 if none) */
static int find_row(int op, int planar, unsigned mode)
{
    int v;
    for (v = 0; v < NROW; ++v)
        if (rows[v].op == op && rows[v].planar == planar && rows[v].mode == mode) return v;
    return -1;
}

/* The 3D element without spin on the planar arc (z = 0) against
   vlbe_ale_force, both p free, damped: max |dQ| / max |Q| (the two rows
   compare like with like). */
static double planar_check(void)
{
    vlbe_real q[14], qd[14], Q3[14], Q2[10];
    double nq = 0.0, dq = 0.0;
    int n, c;
    for (n = 0; n < 2; ++n) {
        for (c = 0; c < 2; ++c) {
            q[7 * n + c] = q2[0][5 * n + c];
            q[7 * n + 3 + c] = q2[0][5 * n + 2 + c];
            qd[7 * n + c] = qd2[0][5 * n + c];
            qd[7 * n + 3 + c] = qd2[0][5 * n + 2 + c];
        }
        q[7 * n + 2] = q[7 * n + 5] = qd[7 * n + 2] = qd[7 * n + 5] = VLBE_R(0.0);
        q[7 * n + 6] = q2[0][5 * n + 4];
        qd[7 * n + 6] = qd2[0][5 * n + 4];
    }
    if (vlbe_ale3_force(&el3, NOSPIN, q, qd, Q3, NULL, NULL) != VLBE_OK) return DNAN;
    if (vlbe_ale_force(&el2, 0u, q2[0], qd2[0], Q2, NULL, NULL) != VLBE_OK) return DNAN;
    for (n = 0; n < 2; ++n) {
        const int m3[5] = {0, 1, 3, 4, 6};
        for (c = 0; c < 5; ++c) {
            const double a = (double)Q2[5 * n + c], b = (double)Q3[7 * n + m3[c]];
            if (fabs(a) > nq) nq = fabs(a);
            if (fabs(a - b) > dq) dq = fabs(a - b);
        }
        if (fabs((double)Q3[7 * n + 2]) > dq) dq = fabs((double)Q3[7 * n + 2]);
        if (fabs((double)Q3[7 * n + 5]) > dq) dq = fabs((double)Q3[7 * n + 5]);
    }
    return dq / nq;
}

static const char *pf(int ok) { return ok ? "PASS" : "MISS"; }

/* spin-off ratio line: rows with spin (mode) and without (mode | NO_SPIN) */
static void spin_line(const char *what, const result *res, unsigned mode)
{
    const int a = find_row(OP_Q, 0, mode), b = find_row(OP_Q, 0, mode | NOSPIN);
    const int c = find_row(OP_QKD, 0, mode), d = find_row(OP_QKD, 0, mode | NOSPIN);
    const double rq = res[a].med_ns / res[b].med_ns, rk = res[c].med_ns / res[d].med_ns;
    printf("  spin-off >= 1.5x faster, %s: with spin / NO_SPIN: Q %.1f / %.1f = %.2f %s, "
           "Q+K+D %.1f / %.1f = %.2f %s\n",
           what, res[a].med_ns, res[b].med_ns, rq, pf(rq >= 1.5), res[c].med_ns, res[d].med_ns,
           rk, pf(rk >= 1.5));
}

int main(int argc, char **argv)
{
    static result res[NROW];
    const char *tag = argc > 1 ? argv[1] : NULL;
    vlbe_ale3_mat mat3;
    vlbe_ale_mat mat2;
    char model[128], csv[256];
    double mhz;
    long bad = 0;
    int op, v, nnoisy = 0, full[NOP];
    FILE *f;
    vlbe_status st;

    benchu_cpu_info(model, sizeof model, &mhz);
    printf("bench_ale3: one 3D ALE beam-shaft element with spin (ancf_ale.h), vlbe %s, %s\n",
           VLBE_VERSION_STRING, sizeof(vlbe_real) == sizeof(double) ? "double" : "float");
    printf("compiler: %s, flags: %s\n", __VERSION__, VLBE_BENCH_FLAGS);
    printf("cpu: %s, %.0f MHz (/proc/cpuinfo), load average %.2f at start\n", model, mhz,
           benchu_load_avg());
    printf("ns per element call: median (min) of %d batches of >= %ld calls after warm-up, "
           "CLOCK_MONOTONIC\n",
           BENCHU_BATCHES, MIN_CALLS);
    printf("state: helical (curvature 2/m, torsion 1/m), stretched (0.2 %%), twisted, spinning "
           "(100 rad/s), rotating shaft element, L = 0.25 m, p1' = 0.30, p2' = 0.25 m/s, "
           "Gauss nm/ns = 4/5; planar rows: bench_ale.c's arc, nm/nl/nt = 4/5/5\n\n");

    shaft(&mat3, &mat2);
    make_states();
    if ((st = vlbe_ale3_elem_init(&el3, &mat3, 0u, 0, 0)) != VLBE_OK ||
        (st = vlbe_ale_elem_init(&el2, &mat2, 0u, 0, 0, 0)) != VLBE_OK) {
        fprintf(stderr, "bench_ale3: element init: %s\n", vlbe_status_str(st));
        return 1;
    }
    for (op = 0; op < NOP; ++op) full[op] = find_row(op, 0, 0u);

    snprintf(csv, sizeof csv, "out/bench/ale3_elem%s%s.csv", tag ? "-" : "", tag ? tag : "");
    f = svgp_csv_open(csv, "operation,element,variant,mode,nq,calls_per_batch,batches,median_ns,"
                           "min_ns,rel_to_full,target_ns,pass");
    if (!f) fprintf(stderr, "bench_ale3: cannot write %s\n", csv);

    printf("%-18s %-37s %10s %10s %8s %8s %6s\n", "operation", "variant", "median ns", "min ns",
           "vs full", "target", "");
    for (op = 0; op < NOP; ++op) {
        int first = 1;
        measure_op(op, res, &bad);
        for (v = 0; v < NROW; ++v) {
            const row *rw = &rows[v];
            const double tg = rw->planar ? DNAN : op_target[op];
            const int has_tg = !isnan(tg);
            double rel;
            int pass, noisy;
            if (rw->op != op) continue;
            rel = res[v].med_ns / res[full[op]].med_ns;
            pass = has_tg && res[v].med_ns <= tg;
            printf("%-18s %-37s %10.1f %10.1f %8.2f ", first ? op_name[op] : "", rw->name,
                   res[v].med_ns, res[v].min_ns, rel);
            first = 0;
            noisy = res[v].med_ns > BENCHU_NOISY * res[v].min_ns;
            nnoisy += noisy;
            if (has_tg) printf("%8.0f %6s%s\n", tg, pass ? "PASS" : "FAIL", noisy ? " *" : "");
            else printf("%8s %6s%s\n", "-", "", noisy ? " *" : "");
            fflush(stdout);
            if (f)
                fprintf(f, "%s,%s,\"%s\",%u,%d,%ld,%d,%.6g,%.6g,%.4g,%.6g,%s\n", op_csv[op],
                        rw->planar ? "planar" : "3d", rw->name, rw->mode,
                        rw->planar ? NQ2 : vlbe_ale3_nq(rw->mode), res[v].calls, BENCHU_BATCHES,
                        res[v].med_ns, res[v].min_ns, rel, tg,
                        has_tg ? (pass ? "yes" : "no") : "");
        }
        printf("\n");
    }

    if (nnoisy)
        printf("* median > %.2f x min: the machine was busy during this row (load average now "
               "%.2f); rerun on a quiet machine\n",
               BENCHU_NOISY, benchu_load_avg());
    printf("3D NO_SPIN on the planar arc (z = 0) against vlbe_ale_force: max |dQ| / max |Q| = "
           "%.2e\n",
           planar_check());
    {
        const int a = find_row(OP_Q, 0, FIX | NOSPIN), b = find_row(OP_Q, 1, FIX);
        const int c = find_row(OP_QKD, 0, FIX | NOSPIN), d = find_row(OP_QKD, 1, FIX);
        printf("3D Lagrangian NO_SPIN / planar Lagrangian (both damped, bending): Q %.2f, "
               "Q+K+D %.2f\n",
               res[a].med_ns / res[b].med_ns, res[c].med_ns / res[d].med_ns);
    }
    printf("targets:\n");
    printf("  full element (spin, ALE, bend, twist, damp): force Q %.1f <= %.0f ns %s, "
           "Q+K+D %.1f <= %.0f ns %s\n",
           res[full[OP_Q]].med_ns, op_target[OP_Q], pf(res[full[OP_Q]].med_ns <= op_target[OP_Q]),
           res[full[OP_QKD]].med_ns, op_target[OP_QKD],
           pf(res[full[OP_QKD]].med_ns <= op_target[OP_QKD]));
    spin_line("full (ALE, bend, twist, damp)", res, 0u);
    spin_line("Lagrangian (bend, twist, damp)", res, FIX);
    return benchu_finish("bench_ale3", f, csv, bad);
}
