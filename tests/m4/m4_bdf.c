/* m4_bdf.c -- BDF of integrators.h on the Cortex-M4F (make check-m4): the
   index-3 Cartesian pendulum of scenes/pendulum.h (mass 1 kg, rod 1 m,
   g = 9.81, released at rest from the horizontal; C = (x^2 + y^2 - L^2)/2,
   analytic Jacobians) to t = 1 s, twice: fixed steps of 1/128 s (orders
   1..5), printing q, v, lambda, mu at t = 0.25, 0.5, 0.75, 1 (step and
   order too) and the counters; then variable step and order with
   vlbe_bdf_params_default, checked against the invariants (see run()).
   A failure prints its status and the program exits nonzero.
   -- part of vlbe                                  SPDX-License-Identifier: MIT */
#include "../../integrators.h"
#include "m4_out.h"
/* the problem: the callbacks of scenes/pendulum.h */
#include "../../scenes/pendulum.h"

#define WORK_CAP 1024
#define IWORK_CAP 64

static vlbe_dae sys;
static vlbe_bdf st;
static vlbe_real work[WORK_CAP];
static int iwork[IWORK_CAP];

/* BDF from the start to t = 1 s; print: the states at t = 0.25 .. 1 and
   the counters (bitwise comparison with the host) or, for the variable
   step run, whether the constraint |q| = L holds to 100 rtol at those
   times and whether energy is within 1e3 rtol of its start (an I line:
   equal on both sides when both runs are right) */
static int run(const vlbe_bdf_params *bp, const vlbe_real *q0, const vlbe_real *v0, size_t lw,
               size_t liw, int print)
{
    const pend_par *par = (const pend_par *)sys.user;
    int k, ok = 1;
    if (m4_status("bdf_init", vlbe_bdf_init(&st, &sys, bp, VLBE_R(0.0), q0, v0, work, lw, iwork,
                                            liw)))
        return 1;
    for (k = 1; k <= 4; ++k) {
        vlbe_real r, e;
        if (m4_status("bdf_advance", vlbe_bdf_advance(&st, VLBE_R(0.25) * (vlbe_real)k))) return 1;
        r = vlbe_sqrt(st.q[0] * st.q[0] + st.q[1] * st.q[1]) - par->L;
        /* energy per unit mass: v^2 / 2 + g y, 0 at the start */
        e = VLBE_R(0.5) * (st.v[0] * st.v[0] + st.v[1] * st.v[1]) + par->g * st.q[1];
        if (print) {
            m4_val("t", -1, st.t);
            m4_vec("q", st.q, 2);
            m4_vec("v", st.v, 2);
            m4_vec("lambda", st.lambda, 1);
            m4_vec("mu", st.mu, 1);
            m4_val("h", -1, st.h);
            m4_int("order", st.order);
        } else {
            ok &= vlbe_fabs(r) <= VLBE_R(100.0) * bp->rtol * par->L;
            ok &= vlbe_fabs(e) <= VLBE_R(1e3) * bp->rtol * par->g * par->L;
        }
    }
    if (print) {
        m4_stats(&st.stats);
    } else {
        m4_int("variable_step_invariants_ok", ok);
    }
    return 0;
}

int main(void)
{
    pend_par par;
    vlbe_bdf_params bp;
    vlbe_real q0[2], v0[2];
    size_t lw, liw;
    par = pend_default();
    pend_setup(&sys, &par);
    pend_initial(&par, q0, v0);
    lw = vlbe_bdf_work_len_sys(&sys);
    liw = vlbe_bdf_iwork_len_sys(&sys);
    m4_int("work_len", (long)lw);
    m4_int("iwork_len", (long)liw);
    if (lw > WORK_CAP || liw > IWORK_CAP) {
        m4_status("workspace", VLBE_EWORK);
        return m4_exit();
    }
    /* fixed steps (h = 1/128 s, orders 1..5): no step-size control, the
       same operations on both sides */
    vlbe_bdf_params_default(&bp);
    bp.fixed_step = 1;
    bp.h0 = VLBE_R(0.0078125);
    if (run(&bp, q0, v0, lw, liw, 1)) return m4_exit();
    /* variable step and order with the defaults: the step-size rule takes
       powf, which newlib and glibc may round differently by an ulp, and
       one different step changes the rest of the run: checked on each
       side against the pendulum's invariants, not against the host */
    vlbe_bdf_params_default(&bp);
    if (run(&bp, q0, v0, lw, liw, 0)) return m4_exit();
    return m4_exit();
}
