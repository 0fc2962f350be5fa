/* pend_faults.h -- the pendulum of scenes/pendulum.h with faults injected
   into its callbacks, shared by the integrator suites -- part of vlbe
                                                   SPDX-License-Identifier: MIT

   Include it after the scene:
       #include "../scenes/pendulum.h"
       #include "pend_faults.h"

   faulty_setup(sys, f, mode) fills sys with the scene's pendulum
   (pend_setup: the analytic Jacobians) whose mass, force and constraint go
   through the wrappers below with f as user data; it starts with no fault
   (mode is not used: arm the fault by setting f->mode).  Armed, the fault
   hits every call after the first f->after counted ones (f->calls counts
   them); after = 0: at once; with f->count > 0 only that many calls (a
   transient fault: one bad Newton iterate).  The callbacks that do not read their user
   data (constr_jac, constr_acc, force_jac, constr_hess) stay the scene's. */
#ifndef VLBE_TEST_PEND_FAULTS_H
#define VLBE_TEST_PEND_FAULTS_H

typedef struct faulty {
    pend_par p;
    int mode;       /* 0 none, 1 NaN force, 2 force returns error, 3 mass returns error,
                       4 constr returns error, 5 force returns +1 (outside the domain:
                       recoverable), 6 force returns -1 (fatal) */
    long after;     /* number of good calls before the fault */
    long count;     /* calls the fault lasts (0: for ever) */
    long calls;
} faulty;

/* is the armed fault on for this call? */
static int faulty_hit(faulty *f)
{
    const long c = f->calls++;
    return c >= f->after && (f->count <= 0 || c < f->after + f->count);
}
static int faulty_force(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v, vlbe_real *Q)
{
    faulty *f = (faulty *)u;
    int rc = pend_force(&f->p, t, q, v, Q);
    if (f->mode != 0 && f->mode != 3 && f->mode != 4 && faulty_hit(f)) {
        if (f->mode == 1) Q[1] = (vlbe_real)NAN;
        if (f->mode == 2) return 7;
        if (f->mode == 5) return 1;
        if (f->mode == 6) return -1;
    }
    return rc;
}
static int faulty_mass(void *u, vlbe_real t, const vlbe_real *q, const vlbe_real *v, vlbe_real *M)
{
    faulty *f = (faulty *)u;
    if (f->mode == 3 && faulty_hit(f)) return -1;
    return pend_mass(&f->p, t, q, v, M);
}
static int faulty_constr(void *u, vlbe_real t, const vlbe_real *q, vlbe_real *C)
{
    faulty *f = (faulty *)u;
    if (f->mode == 4 && faulty_hit(f)) return 7;
    return pend_constr(&f->p, t, q, C);
}

static void faulty_setup(vlbe_dae *sys, faulty *f, int mode)
{
    f->p = pend_default();
    f->mode = 0;
    f->after = 0;
    f->count = 0;
    f->calls = 0;
    pend_setup(sys, &f->p);
    sys->user = f;
    sys->force = faulty_force;
    sys->mass = faulty_mass;
    sys->constr = faulty_constr;
    /* M constant but not declared so: the integrators then call mass at
       every iteration (a declared constant M is evaluated once and kept),
       where a mass fault can hit */
    sys->flags &= ~VLBE_DAE_MASS_CONST;
    (void)mode;
}

#endif /* VLBE_TEST_PEND_FAULTS_H */
