/* m4_out.h -- output of the vlbe Cortex-M4F test programs (tests/m4/m4_x.c),
   the same on the target and on the host, without printf: printf("%g") of
   a float promotes it to double and newlib's printf links the double
   soft-float code, which would hide double arithmetic of the library from
   the `__aeabi_d*` check of make check-m4.  Lines:
     V <name> <bits> <decimal>   a real: the 8 hex digits of its float bit
                                 pattern (what tests/m4/compare.awk reads)
                                 and a readable decimal of 7 digits, made
                                 with float operations only (it may be off
                                 by a unit in its last digit; the bits are
                                 exact)
     I <name> <integer>          a count or a status (compared exactly)
   Names are <group> or <group>[<index>]: compare.awk scales the difference
   of a value by the largest magnitude of its group.  Output goes through
   fputs only.  m4_fail counts failed checks; main returns m4_exit().
   M4_HOST_DOUBLE: a double build on the host (m4_hht against its float
   runs), whose V lines carry the float of the value and its %.9e.
   -- part of vlbe                                  SPDX-License-Identifier: MIT */
#ifndef VLBE_M4_OUT_H
#define VLBE_M4_OUT_H

#include "../../vlbe.h"

#include <stdint.h>
#include <stdio.h>
#include <string.h>

#if !defined(VLBE_USE_FLOAT) && !defined(M4_HOST_DOUBLE)
#error "the M4 programs are float programs: build them with -DVLBE_USE_FLOAT"
#endif

static int m4_fail = 0;

static inline void m4_puts(const char *s) { fputs(s, stdout); }

/* decimal of v into the end of buf (>= 24 chars); returns the first char */
static inline char *m4_fmt_long(long v, char *buf, int len)
{
    char *p = buf + len - 1;
    unsigned long u = v < 0 ? 0ul - (unsigned long)v : (unsigned long)v;
    *p = '\0';
    do {
        *--p = (char)('0' + (int)(u % 10u));
        u /= 10u;
    } while (u);
    if (v < 0) *--p = '-';
    return p;
}

static inline void m4_put_long(long v)
{
    char buf[24];
    m4_puts(m4_fmt_long(v, buf, (int)sizeof buf));
}

static inline uint32_t m4_bits(float x)
{
    uint32_t u;
    memcpy(&u, &x, sizeof u);
    return u;
}

static inline void m4_put_hex(uint32_t u)
{
    char buf[9];
    int i;
    for (i = 7; i >= 0; --i) {
        buf[i] = "0123456789abcdef"[u & 15u];
        u >>= 4;
    }
    buf[8] = '\0';
    m4_puts(buf);
}

/* d.dddddde+XX from float operations only (scaling by 10 costs a few
   roundings: the last digit may be off by one; the bits are the result) */
static inline void m4_put_dec(float x)
{
    char buf[16], *p = buf;
    uint32_t m;
    int e = 0, i;
    if (x != x) {
        m4_puts("nan");
        return;
    }
    if (x < 0.0f) {
        *p++ = '-';
        x = -x;
    }
    if (x > FLT_MAX) {
        *p = '\0';
        m4_puts(buf);
        m4_puts("inf");
        return;
    }
    if (x != 0.0f) {
        while (x >= 10.0f) {
            x /= 10.0f;
            ++e;
        }
        while (x < 1.0f) {
            x *= 10.0f;
            --e;
        }
    }
    m = (uint32_t)(x * 1e6f + 0.5f);
    if (m >= 10000000u) {
        m /= 10u;
        ++e;
    }
    for (i = 7; i >= 1; --i) {
        p[i] = (char)('0' + (int)(m % 10u));
        m /= 10u;
    }
    p[0] = p[1];
    p[1] = '.';
    p += 8;
    *p++ = 'e';
    *p++ = e < 0 ? '-' : '+';
    if (e < 0) e = -e;
    *p++ = (char)('0' + e / 10);
    *p++ = (char)('0' + e % 10);
    *p = '\0';
    m4_puts(buf);
}

static inline void m4_put_name(const char *name, int i)
{
    m4_puts(name);
    if (i >= 0) {
        m4_puts("[");
        m4_put_long(i);
        m4_puts("]");
    }
}

/* V <name>[i] <bits> <decimal>; i < 0: no index */
static inline void m4_val(const char *name, int i, vlbe_real x)
{
    m4_puts("V ");
    m4_put_name(name, i);
    m4_puts(" ");
#ifdef VLBE_USE_FLOAT
    m4_put_hex(m4_bits(x));
    m4_puts(" ");
    m4_put_dec(x);
#else /* M4_HOST_DOUBLE */
    m4_put_hex(m4_bits((float)x));
    printf(" %.9e", x);
#endif
    m4_puts("\n");
}

static inline void m4_vec(const char *name, const vlbe_real *x, int n)
{
    int i;
    for (i = 0; i < n; ++i) m4_val(name, i, x[i]);
}

/* I <name> <v> */
static inline void m4_int(const char *name, long v)
{
    m4_puts("I ");
    m4_puts(name);
    m4_puts(" ");
    m4_put_long(v);
    m4_puts("\n");
}

/* a status: printed, and counted as a failure unless VLBE_OK */
static inline int m4_status(const char *what, vlbe_status st)
{
    m4_int(what, (long)st);
    if (st != VLBE_OK) {
        m4_puts("FAIL ");
        m4_puts(what);
        m4_puts(": ");
        m4_puts(vlbe_status_str(st));
        m4_puts("\n");
        ++m4_fail;
    }
    return st != VLBE_OK;
}

static inline int m4_exit(void)
{
    m4_puts(m4_fail ? "END fail\n" : "END ok\n");
    return m4_fail ? 1 : 0;
}

#ifdef VLBE_INTEGRATORS_H
/* the counters of an integrator run, one I line each */
static inline void m4_stats(const vlbe_dae_stats *c)
{
    m4_int("steps", c->steps);
    m4_int("rejected", c->rejected);
    m4_int("newton_iters", c->newton_iters);
    m4_int("newton_fails", c->newton_fails);
    m4_int("force_calls", c->force_calls);
    m4_int("mass_calls", c->mass_calls);
    m4_int("constr_calls", c->constr_calls);
    m4_int("jac_evals", c->jac_evals);
    m4_int("lu_factors", c->lu_factors);
    m4_int("lu_solves", c->lu_solves);
}
#endif

#endif /* VLBE_M4_OUT_H */
