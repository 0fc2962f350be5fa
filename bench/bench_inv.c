/* bench_inv.c -- cost of the axial (cable) force of fixed-length planar ANCF
   elements by three routes of ancf_ale.h: Gauss points (vlbe_ale_force,
   5 points), element invariants (vlbe_ale_inv_force: unit tables B, I
   scaled to L) and system invariants (vlbe_ale_inv_sys_force: the tables
   of a whole chain assembled once), per element and for whole chains.

   build (from the repository root; `make bench` does this):
       cc -std=c99 -O3 -march=native bench/bench_inv.c -o build/bench/bench_inv -lm
   run from the repository root:  build/bench/bench_inv [tag]
   writes out/bench/inv[-tag].csv and out/bench/inv[-tag].svg (out/bench
   must exist).

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
   BATCHES rounds of one batch per configuration (interleaved round robin,
   so that a disturbance of the shared machine spreads over all rows), each
   batch >= 0.2 ms.  Reported: median (min) ns per call over the batches; a
   row whose median exceeds 1.15 times its min is marked '*'. */
#define _POSIX_C_SOURCE 199309L
#include "../ancf_ale.h"
#include "svgplot.h"
#include "bench_util.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifndef VLBE_BENCH_FLAGS
#define VLBE_BENCH_FLAGS "(unknown flags)"
#endif

#define BATCHES 31
#define MIN_CALLS 2000L
#define MAX_CALLS 2000000L
#define MIN_BATCH_S 2e-4
#define NOISY 1.15
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

/* calibration, then BATCHES interleaved rounds over all configurations */
static void measure(cfg *cs, int nc, long *bad)
{
    static double t[128][BATCHES];
    int i, b;
    for (i = 0; i < nc; ++i) {
        double s;
        mode_src = cfg_mode(&cs[i]);
        cs[i].calls = MIN_CALLS;
        s = batch(&cs[i], cs[i].calls, bad);
        if (s * (double)cs[i].calls < MIN_BATCH_S)
            cs[i].calls = (long)(MIN_BATCH_S / (s > 1e-10 ? s : 1e-10)) + 1;
        if (cs[i].calls > MAX_CALLS) cs[i].calls = MAX_CALLS;
        if (cs[i].calls < MIN_CALLS) cs[i].calls = MIN_CALLS;
    }
    for (b = 0; b < BATCHES; ++b)
        for (i = 0; i < nc; ++i) {
            mode_src = cfg_mode(&cs[i]);
            t[i][b] = batch(&cs[i], cs[i].calls, bad);
        }
    for (i = 0; i < nc; ++i) {
        qsort(t[i], BATCHES, sizeof t[i][0], benchu_cmp_double);
        cs[i].med = 1e9 * t[i][BATCHES / 2];
        cs[i].min = 1e9 * t[i][0];
    }
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
    printf("ns per call: median (min) of %d interleaved batches; K, D in band storage\n\n", BATCHES);
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
                   (a->med > NOISY * a->min || u->med > NOISY * u->min) ? " *" : "");
            nnoisy += a->med > NOISY * a->min || u->med > NOISY * u->min;
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
                noisy |= p->med > NOISY * p->min;
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
    if (nnoisy) printf("* median > %.2f x min: the machine was busy; rerun on a quiet machine\n", NOISY);

    if (f) {
        for (i = 0; i < nc; ++i) {
            const cfg *p = &cs[i];
            const int ne = p->ch < 0 ? 1 : chain_ne[p->ch];
            fprintf(f, "%s,%s,%d,%d,%ld,%d,%.6g,%.6g,%.6g\n", p->jac ? "force_qkd" : "force_q",
                    route_csv[p->route], !(p->mode & VLBE_ALE_NO_DAMP), p->ch < 0 ? 0 : ne,
                    p->calls, BATCHES, p->med, p->min, p->med / ne);
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
    if (bad) {
        fprintf(stderr, "bench_inv: %ld calls did not return VLBE_OK\n", bad);
        return 1;
    }
    return 0;
}
