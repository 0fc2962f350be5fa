/* wp_bdf_order.c -- BDF's highest order (vlbe_bdf_params.max_order 1..5)
   on undamped stiff structures: steps, CPU time and error at three
   tolerances, on a flexible slider crank and on the spinning ANCF beam of
   scenes/ex_spin.h.

   build (from the repository root; `make demo` builds it with -O2, `make
   bench` with -O3 -march=native):
       cc -std=c99 -O2 bench/wp_bdf_order.c -o build/demo/wp_bdf_order -lm
   run:  build/demo/wp_bdf_order [outdir]            (default outdir: out)
   writes <outdir>/wp_bdf_order.csv and <outdir>/wp_bdf_order.svg (error
   against CPU time, one series per problem and order); prints the table
   (docs/benchmarks.md quotes it) and the reference checks.

   (a) Slider crank (SC_*): a chain of ancf_ale.h, no damping, no gravity,
   steel (E = 2.1e11 Pa, rho = 7850 kg/m^3) of circular section d = 6 mm
   (EA = 5.94e6 N, EI = 13.4 N m^2, rhoA = 0.222 kg/m): a crank of 0.15 m
   (one element) and a connecting rod of 0.30 m (SC_NROD elements), both
   material (p fixed).  Node 0 is held at the origin (VLBE_ALE_CON_POS)
   with its slope turned at 150 rad/s (VLBE_ALE_CON_SLOPE_ANGLE, law
   (0, 150, 0): the crank angle is 150 t); node 1, the crank pin, is a
   hinge (a node with two slopes, slide = 1, and no constraint between
   them); the last node, the slider, runs on the x axis (VLBE_ALE_CON_POS
   holding y only, which = 2).  Start at the dead centre, all along +x,
   with the rigid-body velocities of that instant (crank turning at 150
   rad/s, rod turning at -75 rad/s about the slider, which is at rest):
   consistent, the rod unstrained.  Run: one crank turn, t in [0, 2 pi /
   150] s; the inertia loads excite the rod's bending (first mode ~850
   rad/s) and its axial modes (~1e5 rad/s in the discretization), none
   damped.  Error: the largest distance of a
   node from its reference position at the 16 sample times t_k = T k / 16
   (the steps land on them), divided by the rod's length.

   (b) Spinning beam (SP_*): scenes/ex_spin.h, SP_ANCF with Gauss points,
   8 elements, spin-up to W = 6 rad/s in Ts = 15 s (sp_cfg_default), the
   beam whose axial modes (up to 3.7e4 rad/s) the max_order comment of
   integrators.h cites.  Run: the first SP_T = 10 s of the spin-up (the
   scene's 20 s cost orders 4 and 5 about 1e6 steps, a minute a run), no
   damping.  Error: the largest transverse tip deflection error in the hub
   frame at the samples t_k = SP_T k / 16, divided by the largest
   transverse deflection of the reference.

   Both: vlbe_bdf_params_default, rtol = atol (m, m/s, and the slopes
   dimensionless) = 1e-4, 1e-5, 1e-6 (the slider crank) and 1e-3, 1e-4,
   1e-5 (the beam, whose scene runs at looser tolerances in wp_spin.c),
   max_order 1 .. 5, the steps landing on the samples (vlbe_bdf_advance).
   A run is capped (vlbe_bdf_params.max_steps: VLBE_EBOUND, reported as
   "cap" with the time reached) at 300000 steps on the slider crank and
   60000 on the beam (whose capped runs would take about 1e6 steps and a
   minute each).
   Reference: slider crank, max_order 5 at rtol = atol = 1e-10, checked
   against max_order 4 at 1e-10; beam, max_order 2 at 1e-9 (its orders 3
   to 5 at such tolerances take minutes), checked against max_order 2 at
   1e-8, whose error is some 5 times that of the reference (order 2: the
   error goes as rtol^(2/3)).  The differences are printed.
   CPU time: CLOCK_PROCESS_CPUTIME_ID around vlbe_bdf_init and the
   integration (model set-up and workspace outside); median of 3 runs (the
   runs are deterministic: only the time varies), a single run when the
   first takes more than 2 s.

   What the runs show (-O2, gcc 12, AMD EPYC 2.1 GHz, 2 cores shared with
   other jobs: CPU times vary by some 30 % between runs; steps and errors
   are deterministic; the whole benchmark 97 s of CPU):
   - slider crank: max_order 5 takes 27846 to 43082 steps at every
     tolerance (the step is held near the stability band of the axial
     modes) and is the cheapest from rtol 1e-5 on: 1e-5, 0.34 s for an
     error 1.3e-7 against order 2's 0.44 s for 6.0e-5; 1e-7, 0.50 s for
     7.2e-9 against 2.4 s (248146 steps) for 2.4e-6.  At 1e-3 order 2 is
     the cheapest (0.053 s, 1.8e-4) and order 5 the most accurate (0.36 s,
     1.2e-5).  Orders 3 and 4 cost most at loose tolerances and give wrong
     answers without failing (1e-3: errors 1.9 and 0.11 of the rod's
     length).  Order 1 needs 104560 steps at 1e-5 and is capped at 1e-7.
   - spinning beam: order 2 takes 534, 1449, 3388 steps (0.11, 0.19, 0.63
     s; errors 2.3e-2, 3.0e-3, 2.5e-4) at rtol 1e-3, 1e-4, 1e-5; orders 4
     and 5 are capped before 10 s at every tolerance, order 3 from 1e-4 on
     (at 1e-3 it takes 327 steps), order 1 from 1e-5 on.
   The advice of vlbe_bdf_params.max_order follows from these two. */
#define _POSIX_C_SOURCE 199309L
#include "../scenes/ex_spin.h"
#include "../scenes/svgplot.h"
#include "bench_util.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define DNAN ((double)NAN)
#define NS 16            /* samples per run */
#define NORD 5
#define NTOL 3
/* steps of a run of the sweep: 300000 on the slider crank (at most ~5 s),
   60000 on the beam (~4 s; its capped runs would take 1e6 steps) */
static const long g_cap[2] = {300000L, 60000L};
#define CAP_REF 2000000L   /* of a reference run */
#define SP_T 10.0        /* s */

/* -- the slider crank -------------------------------------------------------- */
#define SC_NROD 2
#define SC_NE (1 + SC_NROD)
#define SC_R 0.15 /* crank, m */
#define SC_L 0.30 /* rod, m */
#define SC_W 150.0 /* rad/s */
#define SC_D 6e-3 /* section diameter, m */
#define SC_E 2.1e11
#define SC_RHO 7850.0
#define SC_PI 3.14159265358979323846

typedef struct sc_model {
    vlbe_ale_elem el;
    vlbe_ale_node nodes[SC_NE + 1];
    vlbe_ale_con cons[4];
    vlbe_ale_chain ch;
    vlbe_dae sys;
    int n;
} sc_model;

static vlbe_status sc_init(sc_model *m)
{
    vlbe_ale_mat mat;
    vlbe_ale_con k;
    vlbe_status st;
    const double A = 0.25 * SC_PI * SC_D * SC_D, I = SC_PI * pow(SC_D, 4) / 64.0;
    int i;
    memset(&mat, 0, sizeof mat);
    mat.rhoA = (vlbe_real)(SC_RHO * A);
    mat.EA = (vlbe_real)(SC_E * A);
    mat.EI = (vlbe_real)(SC_E * I);
    if ((st = vlbe_ale_elem_init(&m->el, &mat, VLBE_ALE_FIX_P1 | VLBE_ALE_FIX_P2, 0, 0, 0)) !=
        VLBE_OK)
        return st;
    memset(m->nodes, 0, sizeof m->nodes);
    for (i = 0; i <= SC_NE; ++i) {
        m->nodes[i].pmode = VLBE_ALE_PFIXED;
        m->nodes[i].p = (vlbe_real)(i == 0 ? 0.0 : SC_R + SC_L * (i - 1) / SC_NROD);
    }
    m->nodes[1].slide = 1; /* the crank pin: two slopes, a hinge */
    if ((st = vlbe_ale_chain_init(&m->ch, &m->el, m->nodes, SC_NE + 1, SC_NE + 1, m->cons, 4)) !=
        VLBE_OK)
        return st;
    memset(&k, 0, sizeof k);
    k.type = VLBE_ALE_CON_POS; /* the crank's axis */
    if ((st = vlbe_ale_chain_add(&m->ch, &k)) != VLBE_OK) return st;
    k.type = VLBE_ALE_CON_SLOPE_ANGLE; /* the crank angle: 150 t */
    k.law[1] = (vlbe_real)SC_W;
    if ((st = vlbe_ale_chain_add(&m->ch, &k)) != VLBE_OK) return st;
    memset(&k, 0, sizeof k);
    k.type = VLBE_ALE_CON_POS; /* the slider: y = 0 */
    k.node = SC_NE;
    k.which = 2;
    if ((st = vlbe_ale_chain_add(&m->ch, &k)) != VLBE_OK) return st;
    if ((st = vlbe_ale_chain_layout(&m->ch)) != VLBE_OK) return st;
    if ((st = vlbe_ale_chain_dae(&m->ch, &m->sys)) != VLBE_OK) return st;
    m->sys.flags |= VLBE_DAE_MASS_CONST; /* p fixed: M constant */
    m->n = m->ch.n;
    return VLBE_OK;
}

/* the dead centre, rigid-body velocities: node i at x_i on the axis; crank
   points v = (0, W x), slope rate (0, W); rod points v = (0, W R (1 - s /
   L)), s = x - R, slope rate (0, -W R / L) */
static void sc_start(const sc_model *m, vlbe_real *q, vlbe_real *v)
{
    int i, k;
    for (i = 0; i < m->n; ++i) q[i] = v[i] = VLBE_R(0.0);
    for (i = 0; i <= SC_NE; ++i) {
        const int o = m->nodes[i].ofs;
        const double x = (double)m->nodes[i].p;
        const double vy = i <= 1 ? SC_W * x : SC_W * SC_R * (1.0 - (x - SC_R) / SC_L);
        q[o] = (vlbe_real)x;
        v[o + 1] = (vlbe_real)vy;
        for (k = 0; k < 1 + m->nodes[i].slide; ++k) {
            const int rod = i >= 2 || (i == 1 && k == 1);
            q[o + 2 + 2 * k] = VLBE_R(1.0);
            v[o + 3 + 2 * k] = (vlbe_real)(rod ? -SC_W * SC_R / SC_L : SC_W);
        }
    }
}

/* -- one BDF run -------------------------------------------------------------- */
enum { P_SC = 0, P_SP, NPROB };
static const char *const g_pname[NPROB] = {"slider crank", "spinning beam (ex_spin.h ANCF 8 el.)"};
static const double g_tol[NPROB][NTOL] = {{1e-3, 1e-5, 1e-7}, {1e-3, 1e-4, 1e-5}};
/* reference and its check: max_order, rtol */
static const int g_ref_ord[NPROB][2] = {{5, 4}, {2, 2}};
static const double g_ref_tol[NPROB][2] = {{1e-10, 1e-10}, {1e-9, 1e-8}};

typedef struct prob {
    int id;
    sc_model *sc;
    sp_model *sp;
    const vlbe_dae *sys;
    int n;
    vlbe_real *q0, *v0;
    double T;
    int nout; /* sampled values per sample time */
} prob;

/* the sampled values at t: slider crank, the node positions (x, y);
   beam, the tip in the hub frame (axial, transverse) */
static void sample(const prob *p, double t, const vlbe_real *q, double *out)
{
    if (p->id == P_SC) {
        int i;
        for (i = 0; i <= SC_NE; ++i) {
            out[2 * i] = (double)q[p->sc->nodes[i].ofs];
            out[2 * i + 1] = (double)q[p->sc->nodes[i].ofs + 1];
        }
    } else {
        sp_tip(p->sp, t, q, out);
    }
}

typedef struct res {
    vlbe_status status;
    long steps, rejected;
    double cpu, err;
    double t_stop;
    double s[NS][2 * (SC_NE + 1)];
} res;

static void bdf_run(const prob *p, int max_order, double tol, long cap, res *r, int timed_only)
{
    vlbe_bdf_params bp;
    vlbe_bdf st;
    size_t lw = vlbe_bdf_work_len_sys(p->sys), liw = vlbe_bdf_iwork_len_sys(p->sys);
    vlbe_real *w = (vlbe_real *)malloc(lw * sizeof *w);
    int *iw = (int *)malloc(liw * sizeof *iw), k;
    double c0;
    long total = 0;
    memset(&st, 0, sizeof st);
    r->status = VLBE_EWORK;
    r->cpu = r->t_stop = 0.0;
    r->steps = r->rejected = 0;
    if (!w || !iw) goto out;
    vlbe_bdf_params_default(&bp);
    bp.rtol = bp.atol = (vlbe_real)tol;
    bp.max_order = max_order;
    c0 = benchu_cpu_now();
    r->status = vlbe_bdf_init(&st, p->sys, &bp, VLBE_R(0.0), p->q0, p->v0, w, lw, iw, liw);
    r->t_stop = 0.0;
    for (k = 0; k < NS && r->status == VLBE_OK; ++k) {
        const vlbe_real tk = (vlbe_real)(p->T * (k + 1) / NS);
        st.par.max_steps = (int)(cap - total);
        r->status = vlbe_bdf_advance(&st, tk);
        total = st.stats.steps;
        r->t_stop = (double)st.t;
        if (r->status == VLBE_OK && !timed_only) sample(p, (double)st.t, st.q, r->s[k]);
    }
    r->cpu = benchu_cpu_now() - c0;
    r->steps = st.stats.steps;
    r->rejected = st.stats.rejected;
out:
    free(w);
    free(iw);
}

/* error of r against the reference ref: slider crank, max node distance /
   rod length; beam, max |transverse - ref| / max |ref transverse| */
static double run_err(const prob *p, const res *r, const res *ref)
{
    double e = 0.0, sc = 0.0;
    int k, i;
    if (r->status != VLBE_OK) return DNAN;
    for (k = 0; k < NS; ++k) {
        if (p->id == P_SC) {
            for (i = 0; i <= SC_NE; ++i)
                e = fmax(e, hypot(r->s[k][2 * i] - ref->s[k][2 * i],
                                  r->s[k][2 * i + 1] - ref->s[k][2 * i + 1]));
        } else {
            e = fmax(e, fabs(r->s[k][1] - ref->s[k][1]));
            sc = fmax(sc, fabs(ref->s[k][1]));
        }
    }
    return p->id == P_SC ? e / SC_L : e / sc;
}

static vlbe_status prob_init(prob *p, int id)
{
    vlbe_status st;
    memset(p, 0, sizeof *p);
    p->id = id;
    if (id == P_SC) {
        p->sc = (sc_model *)calloc(1, sizeof *p->sc);
        if (!p->sc) return VLBE_EWORK;
        if ((st = sc_init(p->sc)) != VLBE_OK) return st;
        p->sys = &p->sc->sys;
        p->n = p->sc->n;
        p->T = 2.0 * SC_PI / SC_W;
        p->nout = 2 * (SC_NE + 1);
    } else {
        sp_cfg c;
        p->sp = (sp_model *)calloc(1, sizeof *p->sp);
        if (!p->sp) return VLBE_EWORK;
        sp_cfg_default(&c, 6.0, SP_ANCF);
        if ((st = sp_init(p->sp, &c)) != VLBE_OK) return st;
        p->sys = &p->sp->sys;
        p->n = p->sp->n;
        p->T = SP_T;
        p->nout = 2;
    }
    p->q0 = (vlbe_real *)calloc(2 * (size_t)p->n, sizeof *p->q0);
    if (!p->q0) return VLBE_EWORK;
    p->v0 = p->q0 + p->n;
    if (id == P_SC) sc_start(p->sc, p->q0, p->v0);
    else sp_rest(p->sp, p->q0, p->v0);
    return VLBE_OK;
}

static void prob_free(prob *p)
{
    free(p->sc);
    free(p->sp);
    free(p->q0);
}

int main(int argc, char **argv)
{
    const char *outdir = argc > 1 ? argv[1] : "out";
    if (argc == 5) { /* one run: outdir problem max_order rtol (exploration) */
        prob p;
        res r;
        if (prob_init(&p, atoi(argv[2])) != VLBE_OK) return 1;
        bdf_run(&p, atoi(argv[3]), atof(argv[4]), CAP_REF, &r, 0);
        printf("%s order %s rtol %s: %s, %ld steps, %ld rejected, %.3f s, t %.4g\n",
               g_pname[p.id], argv[3], argv[4], vlbe_status_str(r.status), r.steps, r.rejected,
               r.cpu, r.t_stop);
        prob_free(&p);
        return 0;
    }
    static res g_res[NPROB][NORD][NTOL], g_ref[NPROB], g_chk[NPROB];
    char path[512], model[128];
    double mhz;
    FILE *csv;
    int ip, io, it;
    benchu_cpu_info(model, sizeof model, &mhz);
    printf("wp_bdf_order: BDF max_order 1..5 on undamped stiff structures (%s, %s, %.0f MHz)\n",
           VLBE_BENCH_FLAGS, model, mhz);
    if (benchu_mkdir(outdir, "wp_bdf_order") != 0) return 1;
    snprintf(path, sizeof path, "%s/wp_bdf_order.csv", outdir);
    csv = fopen(path, "w");
    if (!csv) {
        perror(path);
        return 1;
    }
    fprintf(csv, "problem,max_order,rtol,status,steps,rejected,cpu_s,error\n");
    for (ip = 0; ip < NPROB; ++ip) {
        prob p;
        if (prob_init(&p, ip) != VLBE_OK) {
            printf("%s: set-up failed\n", g_pname[ip]);
            return 1;
        }
        bdf_run(&p, g_ref_ord[ip][0], g_ref_tol[ip][0], CAP_REF, &g_ref[ip], 0);
        bdf_run(&p, g_ref_ord[ip][1], g_ref_tol[ip][1], CAP_REF, &g_chk[ip], 0);
        printf("\n%s: n = %d, m = %d, T = %.4g s\n  reference (max_order %d, rtol %.0e): %s, %ld "
               "steps, %.2f s; check (max_order %d, rtol %.0e): %s, %ld steps, difference %.2e\n",
               g_pname[ip], p.sys->n, p.sys->m, p.T, g_ref_ord[ip][0], g_ref_tol[ip][0],
               vlbe_status_str(g_ref[ip].status), g_ref[ip].steps, g_ref[ip].cpu,
               g_ref_ord[ip][1], g_ref_tol[ip][1], vlbe_status_str(g_chk[ip].status),
               g_chk[ip].steps, run_err(&p, &g_chk[ip], &g_ref[ip]));
        if (g_ref[ip].status != VLBE_OK) return 1;
        printf("  %-8s %-6s %-16s %10s %9s %9s %10s\n", "rtol", "order", "status", "steps",
               "rejected", "CPU s", "error");
        for (it = 0; it < NTOL; ++it)
            for (io = 0; io < NORD; ++io) {
                res *r = &g_res[ip][io][it];
                double t[3];
                int nrep = 1, j;
                bdf_run(&p, io + 1, g_tol[ip][it], g_cap[ip], r, 0);
                t[0] = r->cpu;
                if (r->cpu <= 2.0) {
                    res tmp;
                    for (j = 1; j < 3; ++j) {
                        bdf_run(&p, io + 1, g_tol[ip][it], g_cap[ip], &tmp, 1);
                        t[j] = tmp.cpu;
                    }
                    nrep = 3;
                    qsort(t, 3, sizeof t[0], benchu_cmp_double);
                }
                r->cpu = t[nrep / 2];
                r->err = run_err(&p, r, &g_ref[ip]);
                {
                    char stat[80];
                    if (r->status == VLBE_OK) snprintf(stat, sizeof stat, "ok");
                    else if (r->status == VLBE_EBOUND)
                        snprintf(stat, sizeof stat, "cap at %.3g s", r->t_stop);
                    else snprintf(stat, sizeof stat, "%s", vlbe_status_str(r->status));
                    printf("  %-8.0e %-6d %-16s %10ld %9ld %9.3f %10.2e%s\n", g_tol[ip][it],
                           io + 1, stat, r->steps, r->rejected, r->cpu, r->err,
                           nrep == 1 ? " (1 run)" : "");
                }
                fprintf(csv, "%s,%d,%.0e,%d,%ld,%ld,%.6f,%.6e\n", ip == P_SC ? "slider_crank" : "spin_beam",
                        io + 1, g_tol[ip][it], (int)r->status, r->steps, r->rejected, r->cpu,
                        r->err);
                fflush(stdout);
            }
        prob_free(&p);
    }
    fclose(csv);
    /* chart: error against CPU, one series per problem and order */
    {
        static svgp_chart c;
        static double xs[NPROB][NORD][NTOL], ys[NPROB][NORD][NTOL];
        static char names[NPROB][NORD][32];
        snprintf(path, sizeof path, "%s/wp_bdf_order.svg", outdir);
        svgp_init(&c, "BDF max_order 1..5: slider crank (SC), spinning beam (SP)", "CPU time [s]",
                  "error", 1, 1);
        for (ip = 0; ip < NPROB; ++ip)
            for (io = 0; io < NORD; ++io) {
                double *x = xs[ip][io], *y = ys[ip][io];
                char *name = names[ip][io];
                int nn = 0;
                for (it = 0; it < NTOL; ++it) {
                    const res *r = &g_res[ip][io][it];
                    if (r->status != VLBE_OK) continue;
                    x[nn] = r->cpu;
                    y[nn] = r->err;
                    ++nn;
                }
                snprintf(name, 32, "%s order %d", ip == P_SC ? "SC" : "SP", io + 1);
                svgp_series(&c, name, nn, x, y, 0);
            }
        if (svgp_write_file(&c, path) != 0) {
            perror(path);
            return 1;
        }
    }
    printf("\nwrote %s/wp_bdf_order.csv, %s/wp_bdf_order.svg\n", outdir, outdir);
    return 0;
}
