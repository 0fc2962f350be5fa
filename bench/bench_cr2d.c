/* bench_cr2d.c -- cost of the planar co-rotational element of corot2d.h per
   call, and wall time of the sliding-beam scene (Hsiao et al. section 3,
   scenes/ex_sbeam.h), against the performance targets: one conventional
   element, forces + tangent + mass, at most 0.5 us; case (b) with 24
   elements to t = 3 s at dt = 1 ms in at most 0.5 s wall.

   build (from the repository root; `make bench` does this):
       cc -std=c99 -O3 -march=native bench/bench_cr2d.c -o build/bench/bench_cr2d -lm
   run from the repository root:  build/bench/bench_cr2d [tag]
   writes out/bench/cr2d[-tag].csv (out/bench must exist).

   Element: the paper's section (EA = 3.0 MN, EI = 0.73 N m^2, rhoA =
   0.137 kg/m, rhoI = 3.3e-8 kg m), L = 35 mm, Rayleigh damping on, a
   deformed state at 0.3 rad with velocities everywhere; 8 copies of the
   state perturbed by 1e-7 relative, cycled; one output entry per call
   summed into a volatile sink; the mode passes through a volatile (no
   specialisation).  Per variant: 31 batches of >= 1e4 calls (>= 0.2 ms),
   median and min ns per call; rows marked '*' when median > 1.15 min.
   Scene: REPS runs of each case, median wall (CLOCK_MONOTONIC) and CPU,
   with the step, rejected-step, Newton, LU and restart counts. */
#define _POSIX_C_SOURCE 199309L
#include "../scenes/sliding_beam.h"
#include "../scenes/svgplot.h"
#include "bench_util.h"

#include <stdio.h>
#include <stdlib.h>

#define MIN_CALLS 10000L
#define NSTATE 8
#define REPS 5
#define TARGET_ELEM_NS 500.0
#define TARGET_SCENE_S 0.5

static volatile double sink;
static volatile unsigned mode_src;
static vlbe_real qs[NSTATE][6], qds[NSTATE][6];

enum { V_FULL, V_Q, V_NONLI, V_LIN, V_TRANS, NV };
static const char *const vname[NV] = {
    "conventional: Q + K + D + M (full)", "conventional: Q only",
    "conventional: Q + K + D + M, NO_NLI|NO_DAMP", "conventional: Q + K + D + M, LINEAR",
    "transition:   Q + K + D + M"};

static double batch(int v, const vlbe_cr2d_elem *el, const vlbe_cr2d_joint *jt, long k)
{
    vlbe_real Q[6], K[36], D[36], M[36];
    const unsigned base = mode_src;
    const unsigned mode = base | (v == V_NONLI ? VLBE_CR2D_NO_NLI | VLBE_CR2D_NO_DAMP : 0u) |
                          (v == V_LIN ? VLBE_CR2D_LINEAR : 0u);
    double t0 = benchu_now(), acc = 0.0;
    long r;
    for (r = 0; r < k; ++r) {
        const int s = (int)(r & (NSTATE - 1));
        if (v == V_Q) {
            vlbe_cr2d_force(el, mode, qs[s], qds[s], Q, NULL, NULL);
            acc += (double)Q[r % 6];
        } else if (v == V_TRANS) {
            vlbe_cr2d_trans_force(el, jt, mode, qs[s], qds[s], Q, K, D);
            vlbe_cr2d_trans_mass(el, jt, mode, qs[s], M);
            acc += (double)Q[r % 6] + (double)K[r % 36] + (double)M[(7 * r) % 36];
        } else {
            vlbe_cr2d_force(el, mode, qs[s], qds[s], Q, K, D);
            vlbe_cr2d_mass(el, mode, qs[s], M);
            acc += (double)Q[r % 6] + (double)K[r % 36] + (double)M[(7 * r) % 36];
        }
    }
    sink = acc;
    return (benchu_now() - t0) / (double)k;
}

int main(int argc, char **argv)
{
    const char *tag = argc > 1 ? argv[1] : NULL;
    static double s[NV][BENCHU_BATCHES];
    vlbe_cr2d_mat mat;
    vlbe_cr2d_elem el, elt;
    vlbe_cr2d_joint jt;
    vlbe_real X1[2] = {0, 0}, X2[2] = {0.035, 0};
    char model[128], csv[256];
    double mhz, med[NV], full_ns = 0.0, scene_b = 0.0;
    unsigned long long rng = 0x9E3779B97F4A7C15ULL;
    long kc[NV];
    FILE *f;
    int v, i, b, fail = 0;
    benchu_cpu_info(model, sizeof model, &mhz);
    printf("bench_cr2d: %s, %.0f MHz, %s\n", model, mhz, VLBE_BENCH_FLAGS);
    snprintf(csv, sizeof csv, "out/bench/cr2d%s%s.csv", tag ? "-" : "", tag ? tag : "");
    f = svgp_csv_open(csv, "what,median,min,unit,steps,rejected,newton,lu,restarts");
    memset(&mat, 0, sizeof mat);
    mat.EA = VLBE_R(68.96e9 * 4.3434e-5);
    mat.EI = VLBE_R(68.96e9 * 1.059e-11);
    mat.rhoA = VLBE_R(3144.3858 * 4.3434e-5);
    mat.rhoI = VLBE_R(3144.3858 * 1.059e-11);
    mat.ray_a = VLBE_R(0.2);
    mat.ray_b = VLBE_R(5e-4);
    if (vlbe_cr2d_elem_init(&el, &mat, X1, X2, 0)) return 1;
    /* the transition element: node 1 10 mm inside a joint at x = 10 mm */
    jt.C[0] = VLBE_R(0.01);
    jt.C[1] = VLBE_R(0.0);
    jt.a[0] = VLBE_R(1.0);
    jt.a[1] = VLBE_R(0.0);
    elt = el;
    for (i = 0; i < NSTATE; ++i) {
        static const double q0[6] = {1e-4, 0.0, 0.0, 1.2e-4, 4e-3, 0.3};
        static const double qd0[6] = {0.1, 0.3, 1.0, 0.12, 0.5, 1.3};
        int j;
        for (j = 0; j < 6; ++j) {
            rng ^= rng >> 12;
            rng ^= rng << 25;
            rng ^= rng >> 27;
            qs[i][j] = (vlbe_real)(q0[j] * (1.0 + 1e-7 * ((double)(rng >> 11) * 0x1.0p-53 - 0.5)));
            qds[i][j] = (vlbe_real)(qd0[j] * (1.0 + 1e-7 * ((double)(rng >> 11) * 0x1.0p-53 - 0.5)));
        }
    }
    for (v = 0; v < NV; ++v) { /* calibration */
        double t = batch(v, v == V_TRANS ? &elt : &el, &jt, MIN_CALLS);
        kc[v] = MIN_CALLS;
        if (t * (double)kc[v] < BENCHU_MIN_BATCH_S) kc[v] = (long)(BENCHU_MIN_BATCH_S / t) + 1;
    }
    for (b = 0; b < BENCHU_BATCHES; ++b)
        for (v = 0; v < NV; ++v) s[v][b] = batch(v, v == V_TRANS ? &elt : &el, &jt, kc[v]);
    printf("%-46s %10s %10s\n", "element call", "median ns", "min ns");
    for (v = 0; v < NV; ++v) {
        qsort(s[v], BENCHU_BATCHES, sizeof s[v][0], benchu_cmp_double);
        med[v] = 1e9 * s[v][BENCHU_BATCHES / 2];
        printf("%-46s %10.1f %10.1f%s\n", vname[v], med[v], 1e9 * s[v][0],
               med[v] > BENCHU_NOISY * 1e9 * s[v][0] ? " *" : "");
        if (f) fprintf(f, "%s,%.2f,%.2f,ns,,,,,\n", vname[v], med[v], 1e9 * s[v][0]);
    }
    full_ns = med[V_FULL];

    printf("\nsliding beam, HHT alpha -0.05, dt = 1 ms, 14 + 10 elements; median of %d runs\n",
           REPS);
    printf("%-6s %9s %9s %6s %5s %7s %5s %8s\n", "case", "wall s", "cpu s", "steps", "rej",
           "Newton", "LU", "restarts");
    for (i = 0; i < 2; ++i) {
        static sb_model m;
        double wall[REPS], cpu[REPS];
        sb_cfg c;
        sb_out out;
        int r;
        sb_cfg_paper(&c, i == 0 ? 'a' : 'b');
        memset(&out, 0, sizeof out);
        for (r = 0; r < REPS; ++r) {
            const double w0 = benchu_now(), c0 = benchu_cpu_now();
            sb_run(&m, &c, NULL, NULL, &out);
            wall[r] = benchu_now() - w0;
            cpu[r] = benchu_cpu_now() - c0;
        }
        qsort(wall, REPS, sizeof wall[0], benchu_cmp_double);
        qsort(cpu, REPS, sizeof cpu[0], benchu_cmp_double);
        if (out.status != VLBE_OK) {
            printf("case %c failed: %s\n", 'a' + i, vlbe_status_str(out.status));
            fail = 1;
            continue;
        }
        printf("(%c)    %9.3f %9.3f %6ld %5ld %7ld %5ld %8d\n", 'a' + i, wall[REPS / 2],
               cpu[REPS / 2], out.stats.steps, out.stats.rejected, out.stats.newton_iters,
               out.stats.lu_factors, out.restarts);
        if (f)
            fprintf(f, "scene %c wall,%.4f,%.4f,s,%ld,%ld,%ld,%ld,%d\n", 'a' + i, wall[REPS / 2],
                    wall[0], out.stats.steps, out.stats.rejected, out.stats.newton_iters,
                    out.stats.lu_factors, out.restarts);
        if (i == 1) scene_b = wall[REPS / 2];
    }
    if (f) fclose(f);
    printf("\ntargets: element Q+K+D+M %.1f <= %.0f ns %s, scene (b) %.3f <= %.1f s %s\n", full_ns,
           TARGET_ELEM_NS, full_ns <= TARGET_ELEM_NS ? "PASS" : "MISS", scene_b, TARGET_SCENE_S,
           scene_b > 0.0 && scene_b <= TARGET_SCENE_S ? "PASS" : "MISS");
    printf("wrote %s\n", csv);
    return fail;
}
