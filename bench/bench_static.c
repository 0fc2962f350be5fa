/* bench_static.c -- Newton iterations, failures and CPU time of the static
   solver vlbe_dae_static (integrators.h) on load-stepped beams, for three
   settings of its step control: plain Newton (max_halvings = 0), the
   backtracking line search from the first iteration on (watchdog = 0),
   and the defaults (vlbe_static_params_default: backtracking after a
   watchdog phase of full Newton steps).
                                   -- part of vlbe  SPDX-License-Identifier: MIT

   build (from the repository root; `make bench` does this):
       cc -std=c99 -O3 -march=native bench/bench_static.c -o build/bench/bench_static -lm
   run from the repository root:  build/bench/bench_static [tag]
   writes out/bench/static[-tag].csv (out/bench must exist).

   Cases (each load step solved from the solution of the one before, the
   multipliers carried along, the load factor stepped from 0):
   cr2d     the co-rotational cantilever of examples/corot_static.c (the
            sliding-beam paper's section, EA = 2.995e6 N, EI = 0.7303 N m^2,
            L = 1 m, EA L^2 / EI = 4.1e6), clamped, N = 16, 32, 64, 128
            elements, banded matrices, a dead tip load P = k EI / L^2 (k =
            P L^2 / EI) from k = 0 to 10 in steps dk = 0.25, 0.5 and 1 (the
            large-deflection elastica: tip deflection 0.81 L at k = 10);
   ale      the cantilever of examples/first_chain.c (a steel flat bar,
            1 m, 100 x 10 mm: EA = 2.1e8 N, EI = 1750 N m^2), N = 4, 8, 16
            Lagrangian ALE-ANCF elements, clamped (position and slope), a
            dead tip load (vlbe_ale_chain_loads) k EI / L^2, k = 0 .. 10 in
            steps of 0.25, 0.5 and 1;
   cable    the same bar pinned at both ends 1 m apart (positions held,
            slopes free), under a distributed dead load k EI / L^3 per
            length, k = 0 .. 2000 in 40, 20 and 10 equal steps: the beam
            sags 0.092 L at k = 2000, where the axial force carries most
            of the load (catenary-like; the linear theory's midspan sag,
            5 k L / 384 = 26 L, is off by a factor 280);
   truss    where plain Newton fails: the two-bar (von Mises) truss of
            tests/test_static.c (half span 1 m, rise 0.2 m, EA = 1e6 N), its
            apex under a dead load f P_lim past the limit load P_lim, one
            solve from the unloaded shape with the apex moved sideways by
            x0 (f = 1.02, 1.1, 1.3, 2, 4, 8; x0 = 0, 0.1, 0.5, 0.9 m; 24
            solves): the equilibrium lies on the inverted branch.
   Per case and setting: the Newton iterations of all load steps, the most
   in one step, the load factor of the first failure (its status; the
   run ends there) and the CPU time of the whole run (best of REPS). */
#define _POSIX_C_SOURCE 199309L
#include "../corot2d.h"
#include "../ancf_ale.h"
#include "../integrators.h"
#include "../scenes/svgplot.h"
#include "../scenes/corot_static.h"
#include "../scenes/vonmises_truss.h"
#include "bench_util.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define REPS 3
#define NE_MAX 128

enum { S_PLAIN, S_BACKTRACK, S_DEFAULT, NS };
static const char *const sname[NS] = {"plain Newton", "backtracking (watchdog 0)", "defaults"};

static vlbe_static_params solver_params(int s)
{
    vlbe_static_params p;
    vlbe_static_params_default(&p);
    if (s == S_PLAIN) p.max_halvings = 0;
    if (s == S_BACKTRACK) p.watchdog = 0;
    return p;
}

/* -- the models ------------------------------------------------------------ */

typedef struct bs_model {
    int kind; /* 0 cr2d, 1 ale tip load, 2 ale pinned-pinned */
    int ne;
    vlbe_dae sys;
    cs_model cs; /* cr2d: the cantilever of scenes/corot_static.h */
    /* ale */
    vlbe_ale_mat amat;
    vlbe_ale_elem ael;
    vlbe_ale_node node[NE_MAX + 1];
    vlbe_ale_con con[4];
    vlbe_ale_chain ch;
    vlbe_ale_load load;
    double EI, L, kscale; /* load factor = k * kscale */
} bs_model;

static int bs_build(bs_model *m, int kind, int ne)
{
    int i;
    memset(m, 0, sizeof *m);
    m->kind = kind;
    m->ne = ne;
    m->L = 1.0;
    if (kind == 0) { /* the elastica: beam.load = k directly */
        if (cs_build(&m->cs, ne, 0) || cs_band(&m->cs)) return -1;
        cs_tip_force(&m->cs);
        m->EI = cs_EI();
        m->kscale = 1.0;
        m->sys = m->cs.sys;
        return 0;
    }
    /* the flat bar of examples/first_chain.c */
    m->EI = 1.75e3;
    m->amat.rhoA = VLBE_R(7.85);
    m->amat.EA = VLBE_R(2.1e8);
    m->amat.EI = (vlbe_real)m->EI;
    if (kind == 2) m->amat.f[1] = VLBE_R(-1.0); /* N/m times the load factor */
    if (vlbe_ale_elem_init(&m->ael, &m->amat, VLBE_ALE_NO_DAMP, 0, 0, 0)) return -1;
    for (i = 0; i <= ne; ++i) m->node[i].p = (vlbe_real)((double)i / ne);
    if (vlbe_ale_chain_init(&m->ch, &m->ael, m->node, ne + 1, ne + 1, m->con, 4)) return -1;
    {
        vlbe_ale_con c;
        memset(&c, 0, sizeof c);
        c.type = VLBE_ALE_CON_POS;
        c.node = 0;
        if (vlbe_ale_chain_add(&m->ch, &c)) return -1;
        if (kind == 1) {
            c.type = VLBE_ALE_CON_SLOPE;
            c.d[0] = VLBE_R(1.0);
        } else {
            c.node = ne;
            c.r[0] = VLBE_R(1.0);
        }
        if (vlbe_ale_chain_add(&m->ch, &c)) return -1;
    }
    if (vlbe_ale_chain_layout(&m->ch)) return -1;
    if (kind == 1) {
        m->load.kind = VLBE_ALE_LOAD_FORCE;
        m->load.p[0] = VLBE_R(1.0);
        m->load.f[1] = VLBE_R(-1.0); /* N times the load factor */
        if (vlbe_ale_chain_loads(&m->ch, &m->load, 1)) return -1;
        m->kscale = m->EI / (m->L * m->L);
    } else {
        m->kscale = m->EI / (m->L * m->L * m->L);
    }
    m->ch.load_factor = VLBE_R(0.0);
    return vlbe_ale_chain_dae(&m->ch, &m->sys) ? -1 : 0;
}

static void bs_start(const bs_model *m, vlbe_real *q)
{
    const vlbe_real r0[2] = {0, 0}, dir[2] = {1, 0};
    if (m->kind == 0) memset(q, 0, (size_t)m->sys.n * sizeof *q);
    else vlbe_ale_chain_straight(&m->ch, r0, dir, q);
}

static void bs_load(bs_model *m, double k)
{
    if (m->kind == 0) m->cs.beam.load = (vlbe_real)(k * m->kscale);
    else m->ch.load_factor = (vlbe_real)(k * m->kscale);
}

/* -- a run --------------------------------------------------------------- */

typedef struct bs_result {
    double defl; /* the last solution's tip (cantilevers) or midspan (pinned) deflection / L */
    long iters, max_step, rejected, lu;
    double k_fail; /* NaN: no failure */
    vlbe_status st;
    double cpu;
} bs_result;

static bs_result bs_run(bs_model *m, const vlbe_static_params *par, double kmax, int nstep,
                        vlbe_real *q, vlbe_real *lam, vlbe_real *w, size_t lw, int *iw, size_t liw)
{
    bs_result r;
    int j, rep;
    memset(&r, 0, sizeof r);
    for (rep = 0; rep < REPS; ++rep) {
        double c0 = benchu_cpu_now(), cpu;
        bs_result x;
        memset(&x, 0, sizeof x);
        x.k_fail = (double)NAN;
        bs_start(m, q);
        for (j = 0; j < m->sys.m; ++j) lam[j] = VLBE_R(0.0);
        for (j = 1; j <= nstep; ++j) {
            vlbe_dae_stats st;
            const double k = kmax * j / nstep;
            memset(&st, 0, sizeof st);
            bs_load(m, k);
            x.st = vlbe_dae_static(&m->sys, par, VLBE_R(0.0), q, lam, &st, w, lw, iw, liw);
            x.iters += st.newton_iters;
            x.rejected += st.rejected;
            x.lu += st.lu_factors;
            if (st.newton_iters > x.max_step) x.max_step = st.newton_iters;
            if (x.st != VLBE_OK) {
                x.k_fail = k;
                break;
            }
        }
        cpu = benchu_cpu_now() - c0;
        if (m->kind == 0) x.defl = -(double)q[3 * m->ne + 1] / m->L;
        else x.defl = -(double)q[m->node[m->kind == 1 ? m->ne : m->ne / 2].ofs + 1] / m->L;
        if (rep == 0 || cpu < r.cpu) {
            r = x;
            r.cpu = cpu;
        }
    }
    return r;
}

/* -- the truss (scenes/vonmises_truss.h) --------------------------------- */

/* the 24 truss solves under one setting: iterations, failures, CPU */
static void bs_truss_run(int s, long *iters, long *fails, double *cpu)
{
    static const double fs[6] = {1.02, 1.1, 1.3, 2.0, 4.0, 8.0}, xs[4] = {0.0, 0.1, 0.5, 0.9};
    const vlbe_static_params par = solver_params(s);
    vm_truss tr;
    vlbe_dae sys;
    vlbe_real w[256];
    int iw[8], a, b;
    double plim, c0 = benchu_cpu_now();
    vm_setup(&sys, &tr, 0);
    plim = vm_limit_load(&tr);
    *iters = *fails = 0;
    for (a = 0; a < 6; ++a)
        for (b = 0; b < 4; ++b) {
            vlbe_real q[2];
            vlbe_dae_stats st;
            q[0] = (vlbe_real)xs[b];
            q[1] = (vlbe_real)tr.h0;
            tr.P = fs[a] * plim;
            memset(&st, 0, sizeof st);
            if (vlbe_dae_static(&sys, &par, VLBE_R(0.0), q, NULL, &st, w, 256, iw, 8) != VLBE_OK)
                ++*fails;
            *iters += st.newton_iters;
        }
    *cpu = benchu_cpu_now() - c0;
}

int main(int argc, char **argv)
{
    static const char *const cname[3] = {"cr2d cantilever: tip load", "ale cantilever: tip load",
                                         "ale pinned-pinned: distributed load"};
    static const int nes[3][4] = {{16, 32, 64, 128}, {4, 8, 16, 0}, {4, 8, 16, 0}};
    static const double kmax[3] = {10.0, 10.0, 2000.0};
    static const int nsteps[3] = {40, 20, 10};
    const char *tag = argc > 1 ? argv[1] : NULL;
    static bs_model model;
    char cpu_model[128], csv[256];
    double mhz;
    FILE *f;
    int c, i, j, s;
    long tot[NS] = {0, 0, 0}, fails[NS] = {0, 0, 0};
    benchu_cpu_info(cpu_model, sizeof cpu_model, &mhz);
    printf("bench_static: %s, %.0f MHz, %s\n", cpu_model, mhz, VLBE_BENCH_FLAGS);
    snprintf(csv, sizeof csv, "out/bench/static%s%s.csv", tag ? "-" : "", tag ? tag : "");
    f = svgp_csv_open(csv, "case,elements,steps,kmax,solver,iterations,max_per_step,rejected,"
                           "lu,k_fail,cpu_ms");
    printf("%-36s %4s %5s  %-26s %6s %4s %6s %10s %9s  %s\n", "case", "N", "steps", "solver",
           "iters", "max", "rej.", "fails at k", "cpu [ms]", "deflection / L");
    for (c = 0; c < 3; ++c)
        for (i = 0; i < 4 && nes[c][i] > 0; ++i)
            for (j = 0; j < 3; ++j) {
                size_t lw, liw;
                vlbe_real *w, *q, *lam;
                int *iw;
                if (bs_build(&model, c, nes[c][i])) {
                    printf("model %d, N = %d: set-up failed\n", c, nes[c][i]);
                    return 1;
                }
                lw = vlbe_static_work_len_sys(&model.sys);
                liw = vlbe_static_iwork_len_sys(&model.sys);
                w = (vlbe_real *)malloc(lw * sizeof *w);
                iw = (int *)malloc(liw * sizeof *iw);
                q = (vlbe_real *)malloc((size_t)model.sys.n * sizeof *q);
                lam = (vlbe_real *)malloc(((size_t)model.sys.m + 1) * sizeof *lam);
                if (!w || !iw || !q || !lam) return 1;
                for (s = 0; s < NS; ++s) {
                    const vlbe_static_params par = solver_params(s);
                    const int nst = nsteps[j];
                    bs_result r = bs_run(&model, &par, kmax[c], nst, q, lam, w, lw, iw, liw);
                    char fl[48];
                    if (r.st == VLBE_OK) snprintf(fl, sizeof fl, "-");
                    else snprintf(fl, sizeof fl, "%g (%d)", r.k_fail, (int)r.st);
                    printf("%-36s %4d %5d  %-26s %6ld %4ld %6ld %10s %9.2f  %.6f\n", cname[c],
                           nes[c][i], nst, sname[s], r.iters, r.max_step, r.rejected, fl,
                           1e3 * r.cpu, r.defl);
                    tot[s] += r.iters;
                    if (r.st != VLBE_OK) ++fails[s];
                    if (f) {
                        fprintf(f, "%s,%d,%d,%g,%s,%ld,%ld,%ld,%ld,%g,%.3f\n", cname[c], nes[c][i],
                                nst, kmax[c], sname[s], r.iters, r.max_step, r.rejected, r.lu,
                                r.k_fail, 1e3 * r.cpu);
                    }
                }
                free(w);
                free(iw);
                free(q);
                free(lam);
            }
    for (s = 0; s < NS; ++s)
        printf("# %-26s %ld iterations in all runs, %ld runs failed\n", sname[s], tot[s], fails[s]);
    printf("\n%-36s %5s  %-26s %6s %6s %9s\n", "case", "runs", "solver", "iters", "failed",
           "cpu [ms]");
    for (s = 0; s < NS; ++s) {
        long it, fl;
        double cpu;
        bs_truss_run(s, &it, &fl, &cpu);
        printf("%-36s %5d  %-26s %6ld %6ld %9.2f\n", "truss past the limit load", 24, sname[s], it,
               fl, 1e3 * cpu);
        if (f)
            fprintf(f, "truss past the limit load,2,1,0,%s,%ld,0,0,0,%ld,%.3f\n", sname[s], it, fl,
                    1e3 * cpu);
    }
    return benchu_finish("bench_static", f, csv, 0);
}
