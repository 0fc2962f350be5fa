/* bench_sliding.c -- wall and CPU time of the sliding-mass scenes of the
   planar ALE-ANCF element (ale-rancf 6.1 falling beam, 6.2 suspended beam;
   examples/ex_slide.h), against the target: the falling beam with
   40 elements up to the mass leaving in at most 2 s wall (the paper's
   ALE-ANCF motion time, Table 1: 325 s).

   build (from the repository root; `make bench` does this):
       cc -std=c99 -O3 -march=native bench/bench_sliding.c -o build/bench/bench_sliding -lm
   run from the repository root:  build/bench/bench_sliding [tag]
   writes out/bench/sliding[-tag].csv (out/bench must exist).

   Method: each configuration (scene, elements, element form) is run REPS
   times without histories (nothing is recorded or allocated inside the
   run but its workspace, once); reported: the median wall time
   (CLOCK_MONOTONIC) and CPU time, and the step, rejected-step, Newton,
   LU and length-control counts of the run (identical between repetitions:
   the runs are deterministic).  The falling beam runs HHT-alpha -0.05 at
   h = 1e-3 s to the mass leaving; the suspended beam 2 s at h = 1e-3 s. */
#define _POSIX_C_SOURCE 199309L
#define VLBE_EXAMPLE_NO_MAIN
#include "../examples/falling_beam.c"
#include "../examples/suspended_beam.c"
#include "svgplot.h"
#include "bench_util.h"

#include <stdio.h>
#include <stdlib.h>

#define REPS 5
#define TARGET_40_S 2.0

typedef struct bs_row {
    double wall, cpu;
    ex_slide_out out;
} bs_row;

static bs_row bs_measure(const ex_slide_cfg *cfg)
{
    double wall[REPS], cpu[REPS];
    bs_row row;
    int k;
    for (k = 0; k < REPS; ++k) {
        const double w0 = benchu_now(), c0 = benchu_cpu_now();
        row.out = ex_slide_run(cfg, NULL);
        wall[k] = benchu_now() - w0;
        cpu[k] = benchu_cpu_now() - c0;
    }
    qsort(wall, REPS, sizeof wall[0], benchu_cmp_double);
    qsort(cpu, REPS, sizeof cpu[0], benchu_cmp_double);
    row.wall = wall[REPS / 2];
    row.cpu = cpu[REPS / 2];
    return row;
}

int main(int argc, char **argv)
{
    static const int Ns[FB_NRUN] = {5, 10, 20, 30, 40};
    static const double paper_motion[FB_NRUN] = {34.6, 58.3, 103.1, 192.4, 325.0};
    const char *tag = argc > 1 ? argv[1] : NULL;
    char model[128], csv[256];
    double mhz, wall40 = -1.0;
    FILE *f;
    int k, form, fail = 0;
    benchu_cpu_info(model, sizeof model, &mhz);
    printf("bench_sliding: %s, %.0f MHz, %s; median of %d runs\n", model, mhz, VLBE_BENCH_FLAGS,
           REPS);
    snprintf(csv, sizeof csv, "out/bench/sliding%s%s.csv", tag ? "-" : "", tag ? tag : "");
    f = svgp_csv_open(csv, "scene,elements,form,status,median_wall_s,median_cpu_s,steps,rejected,"
                           "newton,lu,lc_events,t_leave_s,paper_motion_s");
    if (!f) fprintf(stderr, "bench_sliding: cannot write %s\n", csv);
    printf("%-10s %3s %-12s %9s %9s %6s %5s %7s %5s %4s %8s %8s\n", "scene", "N", "form", "wall s",
           "cpu s", "steps", "rej", "Newton", "LU", "LC", "t_leave", "paper s");
    for (form = 0; form < 2; ++form)
        for (k = 0; k < FB_NRUN + 1; ++k) {
            ex_slide_cfg cfg;
            bs_row r;
            const int susp = k == FB_NRUN;
            const char *scene = susp ? "suspended" : "falling";
            const unsigned fl = form ? VLBE_ALE_CONSERVATIVE : 0u;
            if (susp) sb_cfg(&cfg, fl, 1e-3, 2.0);
            else fb_cfg(&cfg, Ns[k], fl, 1e-3);
            r = bs_measure(&cfg);
            if (r.out.status != VLBE_OK) fail = 1;
            if (!susp && form == 0 && Ns[k] == 40) wall40 = r.wall;
            printf("%-10s %3d %-12s %9.4f %9.4f %6ld %5ld %7ld %5ld %4ld %8.4f %8.1f\n", scene,
                   cfg.N, form ? "conservative" : "paper", r.wall, r.cpu, r.out.steps,
                   r.out.rejected, r.out.newton, r.out.lu, r.out.lc_events, r.out.t_leave,
                   susp ? 0.0 : paper_motion[k]);
            if (f)
                fprintf(f, "%s,%d,%s,%s,%.6g,%.6g,%ld,%ld,%ld,%ld,%ld,%.6g,%.6g\n", scene, cfg.N,
                        form ? "conservative" : "paper", vlbe_status_str(r.out.status), r.wall,
                        r.cpu, r.out.steps, r.out.rejected, r.out.newton, r.out.lu,
                        r.out.lc_events, r.out.t_leave, susp ? (double)NAN : paper_motion[k]);
        }
    if (f) {
        if (fclose(f) != 0) fprintf(stderr, "bench_sliding: cannot write %s\n", csv);
        else printf("wrote %s\n", csv);
    }
    printf("target: falling beam, 40 elements, paper form, to the mass leaving <= %.1f s wall: "
           "%.3f s %s\n", TARGET_40_S, wall40, wall40 >= 0.0 && wall40 <= TARGET_40_S ? "PASS" : "MISS");
    return fail;
}
