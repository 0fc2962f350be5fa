/* fuzz_util.h -- what the libFuzzer harnesses of vlbe share: a byte reader,
   decoders of reals and indices, snapshots of caller-visible data and the
   contract check FUZZ_CHECK      -- part of vlbe   SPDX-License-Identifier: MIT

   Each harness fuzz/fuzz_<name>.c includes this file and the headers it
   tests and defines LLVMFuzzerTestOneInput, which starts with
   fz_begin("<name>", &rd, data, size).  Two
   builds:
     libFuzzer (make fuzz): clang -fsanitize=fuzzer,address,undefined; a
        failed FUZZ_CHECK prints "FUZZ VIOLATION [name] file:line: msg" with
        the context of fz_note() and calls abort(), which libFuzzer reports
        as a crash and saves the input.
     replay (tests/test_fuzz_corpus.c, -DVLBE_FUZZ_REPLAY): a failed
        FUZZ_CHECK calls vlbe_fuzz_fail_hook(), defined by the test, which
        records harness, file, line and message and longjmps back to the
        replay loop (the harnesses hold no resources: no malloc).
   The contract checked (vlbe.h, FAILURE CONTRACT):
     1. status OK and all inputs finite => every output finite;
     2. an index or size out of range => VLBE_EARG;
     3. status != OK => every caller-visible output and state bitwise as
        before the call (outputs are pre-filled with a sentinel, state
        snapshotted), except an output the header documents as unspecified
        on failure: a harness skips such an output with a comment citing
        the header's sentence.
   Harnesses respect the VLBE_ASSERT preconditions (NULL where the docs
   require a pointer, shape arguments of pure kernels); data arguments,
   indices, sizes, lengths and weights of status-returning routines are
   fuzzed.

   Input format: a flat byte string read front to back; a read past the end
   gives zeros, so every input is valid.  A real is one class byte and a
   payload (fz_real): class (c & 7)
     0 zero (sign: c & 8)         1 moderate: (int32) u / 2^24, |x| < 128
     2 any exponent of vlbe_real   3 subnormal / near the underflow
     4 small integer or half       5 1 + k eps (k int16)
     6 an extreme of the type (max, min normal, denorm min, eps, 1/eps, ...;
       NaN and +-Inf when the harness allows non-finite values)
     7 raw IEEE double, 8 bytes little-endian (for hand-written seeds),
       converted to vlbe_real; out of range -> +-max (finite mode: NaN ->
       0, +-Inf -> +-max)
   classes 0-6 carry a 4-byte little-endian payload u. */
#ifndef VLBE_FUZZ_UTIL_H
#define VLBE_FUZZ_UTIL_H

#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../vlbe.h"

#ifdef VLBE_USE_FLOAT
#define FZ_MANT_DIG FLT_MANT_DIG
#define FZ_MIN_EXP FLT_MIN_EXP
#define FZ_MAX_EXP FLT_MAX_EXP
#define FZ_REAL_MIN FLT_MIN
#else
#define FZ_MANT_DIG DBL_MANT_DIG
#define FZ_MIN_EXP DBL_MIN_EXP
#define FZ_MAX_EXP DBL_MAX_EXP
#define FZ_REAL_MIN DBL_MIN
#endif

/* -- reporting ------------------------------------------------------------ */
static char fz_ctx[256];           /* context of the current call (fz_note)  */
static const char *fz_harness = "?"; /* set by fz_begin                      */

/* Sets the context printed with a violation: the routine and arguments. */
static inline void fz_note(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(fz_ctx, sizeof fz_ctx, fmt, ap);
    va_end(ap);
}

#ifdef VLBE_FUZZ_REPLAY
/* defined by the replay test: records the failure and longjmps back */
void vlbe_fuzz_fail_hook(const char *harness, const char *file, int line, const char *msg,
                         const char *ctx);
#define FUZZ_CHECK(cond, msg)                                                            \
    do {                                                                                 \
        if (!(cond)) vlbe_fuzz_fail_hook(fz_harness, __FILE__, __LINE__, (msg), fz_ctx); \
    } while (0)
#else
static inline void fz_violation(const char *file, int line, const char *msg)
{
    fprintf(stderr, "FUZZ VIOLATION [%s] %s:%d: %s (in %s)\n", fz_harness, file, line, msg,
            fz_ctx);
    fflush(stderr);
    abort();
}
#define FUZZ_CHECK(cond, msg)                                 \
    do {                                                      \
        if (!(cond)) fz_violation(__FILE__, __LINE__, (msg)); \
    } while (0)
#endif

/* -- byte reader ------------------------------------------------------------ */
typedef struct fz_rd {
    const uint8_t *p;
    size_t n, i;
    int nf; /* 1: the real decoder may give NaN and +-Inf */
} fz_rd;

static inline void fz_init(fz_rd *r, const uint8_t *data, size_t size)
{
    fz_ctx[0] = 0;
    r->p = data;
    r->n = size;
    r->i = 0;
    r->nf = 0;
}

static inline unsigned fz_u8(fz_rd *r);
/* start of every harness: names it, resets reader, snapshots, context;
   returns the first byte (the harness's flags), bit 0 = non-finite reals */
static inline unsigned fz_begin(const char *name, fz_rd *r, const uint8_t *data, size_t size)
{
    unsigned f;
    fz_harness = name;
    fz_init(r, data, size);
    f = fz_u8(r);
    r->nf = (int)(f & 1u);
    return f;
}

static inline unsigned fz_u8(fz_rd *r) { return r->i < r->n ? r->p[r->i++] : 0u; }

static inline uint32_t fz_u32(fz_rd *r)
{
    uint32_t u = 0;
    int k;
    for (k = 0; k < 4; ++k) u |= (uint32_t)fz_u8(r) << (8 * k);
    return u;
}

/* integer in [lo, hi] from one byte (hi - lo < 256) */
static inline int fz_int(fz_rd *r, int lo, int hi)
{
    return lo + (int)(fz_u8(r) % (unsigned)(hi - lo + 1));
}

/* An index argument for a range of n valid values 0..n-1: mostly valid,
   often at or just past the edges, sometimes extreme. */
static inline int fz_index(fz_rd *r, int n)
{
    const unsigned c = fz_u8(r);
    switch (c % 16) {
    case 0: return -1;
    case 1: return n;
    case 2: return n - 1;
    case 3: return n + 1;
    case 4: return INT_MAX;
    case 5: return INT_MIN;
    case 6: return n - 2;
    case 7: return INT_MAX - 1;
    case 8: return (int)fz_u32(r);
    default: return n > 0 ? (int)(fz_u8(r) % (unsigned)n) : 0;
    }
}

/* A size argument (count of elements, nodes, ...): mostly small and valid,
   sometimes zero, negative or huge (products with it overflow). */
static inline int fz_size(fz_rd *r, int lo, int hi)
{
    const unsigned c = fz_u8(r);
    switch (c % 16) {
    case 0: return 0;
    case 1: return -1;
    case 2: return INT_MAX;
    case 3: return INT_MAX / 2;
    case 4: return INT_MAX / 3 + 1;
    case 5: return INT_MIN;
    case 6: return hi + 1;
    case 7: return (int)fz_u32(r);
    default: return lo + (int)(fz_u8(r) % (unsigned)(hi - lo + 1));
    }
}

static inline vlbe_real fz_clamp(double d, int nf)
{
    if (d != d) return nf ? (vlbe_real)d : VLBE_R(0.0);
    if (d > (double)VLBE_REAL_MAX) return (nf && isinf(d)) ? (vlbe_real)d : VLBE_REAL_MAX;
    if (d < -(double)VLBE_REAL_MAX) return (nf && isinf(d)) ? (vlbe_real)d : -VLBE_REAL_MAX;
    return (vlbe_real)d;
}

/* A real (see the input format above). */
static inline vlbe_real fz_real(fz_rd *r)
{
    const unsigned c = fz_u8(r);
    const double sg = (c & 8u) ? -1.0 : 1.0;
    uint32_t u;
    double d;
    if ((c & 7u) == 7u) {
        uint64_t b = 0;
        int k;
        for (k = 0; k < 8; ++k) b |= (uint64_t)fz_u8(r) << (8 * k);
        memcpy(&d, &b, sizeof d);
        return fz_clamp(d, r->nf);
    }
    u = fz_u32(r);
    switch (c & 7u) {
    case 0: d = sg * 0.0; break;
    case 1: d = (double)(int32_t)u / 16777216.0; break;
    case 2: { /* mantissa in [1, 2), exponent over the whole range of the type */
        const int lo = FZ_MIN_EXP - FZ_MANT_DIG, span = FZ_MAX_EXP - 1 - lo + 1;
        d = sg * ldexp(1.0 + (double)(u & 0xFFFFFu) / 1048576.0, lo + (int)((u >> 20) % (unsigned)span));
        break;
    }
    case 3: /* subnormal or just above the underflow threshold */
        d = sg * ldexp((double)(u & 0xFFFFFFu) + 1.0,
                       FZ_MIN_EXP - FZ_MANT_DIG - 24 + (int)((u >> 24) % (unsigned)(FZ_MANT_DIG + 8)));
        if (d > 0.0 ? d < (double)FZ_REAL_MIN * 16.0 : d > -(double)FZ_REAL_MIN * 16.0) break;
        d = sg * (double)FZ_REAL_MIN * (double)(u & 0xFu);
        break;
    case 4: d = (double)(int8_t)(u & 0xFFu) / (double)(1u << ((u >> 8) & 3u)); break;
    case 5: d = sg * (1.0 + (double)(int16_t)(u & 0xFFFFu) * (double)VLBE_EPS); break;
    default: { /* 6: extremes */
        const unsigned k = u % (r->nf ? 13u : 10u);
        switch (k) {
        case 0: d = (double)VLBE_REAL_MAX; break;
        case 1: d = (double)FZ_REAL_MIN; break;
        case 2: d = ldexp(1.0, FZ_MIN_EXP - FZ_MANT_DIG); break; /* denorm min */
        case 3: d = (double)VLBE_EPS; break;
        case 4: d = 1.0 / (double)VLBE_EPS; break;
        case 5: d = sqrt((double)VLBE_REAL_MAX); break;
        case 6: d = sqrt((double)FZ_REAL_MIN); break;
        case 7: d = (double)VLBE_REAL_MAX / 2.0; break;
        case 8: d = cbrt((double)VLBE_REAL_MAX); break;
        case 9: d = cbrt((double)FZ_REAL_MIN); break;
        case 10: d = NAN; break;
        case 11: d = HUGE_VAL; break;
        default: d = -HUGE_VAL; break;
        }
        d *= sg;
        break;
    }
    }
    return fz_clamp(d, r->nf);
}

/* A moderate real in [-a, a] (positions, rates of a state the fuzzer should
   mostly keep near the physical range) -- or, one time in 8, any real. */
static inline vlbe_real fz_mod(fz_rd *r, double a)
{
    const unsigned c = fz_u8(r);
    if (c % 8u == 7u) return fz_real(r);
    return (vlbe_real)(a * ((double)(int32_t)fz_u32(r) / 2147483648.0));
}

static inline void fz_reals(fz_rd *r, vlbe_real *x, int n)
{
    int i;
    for (i = 0; i < n; ++i) x[i] = fz_real(r);
}

static inline void fz_mods(fz_rd *r, vlbe_real *x, int n, double a)
{
    int i;
    for (i = 0; i < n; ++i) x[i] = fz_mod(r, a);
}

/* one status value known to vlbe (catches garbage statuses) */
static inline int fz_status_known(vlbe_status s)
{
    return strcmp(vlbe_status_str(s), "unknown status") != 0;
}

/* -- outputs, snapshots ------------------------------------------------------ */
#define FZ_SENTINEL 0xA5 /* every byte of an unwritten output: a finite real */

static inline void fz_fill(void *p, size_t bytes) { memset(p, FZ_SENTINEL, bytes); }

static inline int fz_finite(const vlbe_real *x, size_t n)
{
    size_t i;
    for (i = 0; i < n; ++i)
        if (!isfinite(x[i])) return 0;
    return 1;
}

/* Snapshots of caller-visible memory, taken before a call, compared after
   it.  Storage from a static pool (no malloc: a replay may longjmp out). */
#define FZ_POOL (1u << 20)
#define FZ_NSNAP 32
typedef struct fz_snap_ent {
    const void *p;
    size_t n;
    size_t off;
    const char *what;
    int kind; /* 0 output or state, 1 input (const: never changes), 2 real output */
} fz_snap_ent;
static unsigned char fz_pool[FZ_POOL];
static fz_snap_ent fz_snaps[FZ_NSNAP];
static size_t fz_pool_used;
static int fz_nsnap;

static inline void fz_snap_reset(void)
{
    fz_pool_used = 0;
    fz_nsnap = 0;
}

/* remembers n bytes at p (what: its name in a violation message); NULL or
   n == 0 is ignored */
/* Under valgrind (replay build with VLBE_FUZZ_MEMCHECK, set by the Makefile
   where valgrind's memcheck.h is installed) the bytes of a snapshotted
   object are marked defined before they are copied and compared: state
   structs carry padding and unused table entries that no one writes, and a
   byte comparison of them is no use of an uninitialised value by the
   library.  Real outputs are still read as values (finiteness), where
   valgrind sees any undefined one. */
#if defined(VLBE_FUZZ_REPLAY) && defined(VLBE_FUZZ_MEMCHECK)
#include <valgrind/memcheck.h>
#define FZ_DEFINED(p, n) ((void)VALGRIND_MAKE_MEM_DEFINED((p), (n)))
#else
#define FZ_DEFINED(p, n) ((void)0)
#endif

static inline void fz_snap_kind(const void *p, size_t n, const char *what, int kind)
{
    if (!p || !n) return;
    if (fz_nsnap >= FZ_NSNAP || n > FZ_POOL - fz_pool_used) {
        fprintf(stderr, "fuzz_util: snapshot pool exhausted (%s)\n", what);
        abort();
    }
    FZ_DEFINED(p, n);
    memcpy(fz_pool + fz_pool_used, p, n);
    fz_snaps[fz_nsnap].p = p;
    fz_snaps[fz_nsnap].n = n;
    fz_snaps[fz_nsnap].off = fz_pool_used;
    fz_snaps[fz_nsnap].what = what;
    fz_snaps[fz_nsnap].kind = kind;
    fz_pool_used += n;
    ++fz_nsnap;
}

/* state or non-real output: bitwise unchanged on failure */
static inline void fz_snap(const void *p, size_t n, const char *what) { fz_snap_kind(p, n, what, 0); }
/* const input: never changes */
static inline void fz_in(const void *p, size_t n, const char *what) { fz_snap_kind(p, n, what, 1); }
/* array of n reals written by the call: pre-filled with the sentinel here;
   finite on success, unchanged on failure */
static inline void fz_out(vlbe_real *p, size_t n, const char *what)
{
    if (!p) return;
    fz_fill(p, n * sizeof *p);
    fz_snap_kind(p, n * sizeof *p, what, 2);
}
/* the same without the sentinel (an accumulating output: Q += ...) */
static inline void fz_acc(vlbe_real *p, size_t n, const char *what)
{
    if (p) fz_snap_kind(p, n * sizeof *p, what, 2);
}

/* NULL if every snapshot (inputs only: only_in) is bitwise unchanged, else
   the first changed name */
static inline const char *fz_snap_changed_k(int only_in)
{
    int k;
    for (k = 0; k < fz_nsnap; ++k) {
        if (only_in && fz_snaps[k].kind != 1) continue;
        FZ_DEFINED(fz_snaps[k].p, fz_snaps[k].n);
        if (memcmp(fz_snaps[k].p, fz_pool + fz_snaps[k].off, fz_snaps[k].n) != 0)
            return fz_snaps[k].what;
    }
    return NULL;
}
static inline const char *fz_snap_changed(void) { return fz_snap_changed_k(0); }

static inline void fz_ctx_add(const char *what, const char *name)
{
    size_t l = strlen(fz_ctx);
    snprintf(fz_ctx + l, sizeof fz_ctx - l, " [%s: %s]", what, name);
}

/* The contract after a call whose outputs and state were registered with
   fz_out / fz_acc / fz_snap / fz_in: a known status; inputs unchanged;
   VLBE_OK: every real output finite when the inputs were (in_finite: the
   contract owes finite outputs only from finite inputs; a routine that only
   copies what it is given need not look at it); otherwise: everything
   unchanged. */
static inline int fz_skip(const char *id);
static inline void fz_post_in(vlbe_status st, int in_finite)
{
    const char *w;
    char id[64];
    int k;
    FUZZ_CHECK(fz_status_known(st), "unknown status value");
    if ((w = fz_snap_changed_k(1)) != NULL) fz_ctx_add("changed", w);
    FUZZ_CHECK(w == NULL, "a const input changed");
    if (st == VLBE_OK) {
        snprintf(id, sizeof id, "%s-finite", fz_harness);
        if (!in_finite || fz_skip(id)) return;
        for (k = 0; k < fz_nsnap; ++k)
            if (fz_snaps[k].kind == 2 &&
                !fz_finite((const vlbe_real *)fz_snaps[k].p, fz_snaps[k].n / sizeof(vlbe_real))) {
                fz_ctx_add("non-finite", fz_snaps[k].what);
                FUZZ_CHECK(0, "status OK but an output holds NaN/Inf");
            }
        return;
    }
    snprintf(id, sizeof id, "%s-unchanged", fz_harness);
    if (fz_skip(id)) return;
    if ((w = fz_snap_changed()) != NULL) fz_ctx_add("changed", w);
    FUZZ_CHECK(w == NULL, "non-OK status but a caller-visible output changed");
}
/* the same for a call given finite inputs (or one that must reject others) */
static inline void fz_post(vlbe_status st) { fz_post_in(st, 1); }

/* Contract 3 after a failed call: names the first changed output in the
   context, then checks. */
#define FZ_CHECK_UNCHANGED()                                                       \
    do {                                                                           \
        const char *fz_w_ = fz_snap_changed();                                     \
        if (fz_w_) fz_ctx_add("changed", fz_w_);                                   \
        FUZZ_CHECK(fz_w_ == NULL, "non-OK status but a caller-visible output changed"); \
    } while (0)

/* Development aid: VLBE_FUZZ_SKIP="id1,id2" in the environment skips the
   checks of those ids (a known violation that would otherwise stop every
   run at the same place): "<harness>-finite" (OK with NaN/Inf outputs),
   "<harness>-unchanged" (outputs written on failure) and the ids named in
   the harnesses.  Never set by make fuzz or the replay test. */
static inline int fz_skip(const char *id)
{
    static const char *env;
    static int init;
    const char *p;
    size_t l = strlen(id);
    if (!init) {
        env = getenv("VLBE_FUZZ_SKIP");
        init = 1;
    }
    if (!env) return 0;
    for (p = env; (p = strstr(p, id)) != NULL; p += l)
        if ((p == env || p[-1] == ',') && (p[l] == ',' || p[l] == 0)) return 1;
    return 0;
}

/* VLBE_FUZZ_VERBOSE set: print a decoded array (reproductions in reports) */
static inline void fz_dump(const char *name, const vlbe_real *x, int n)
{
    static int on = -1;
    int i;
    if (on < 0) on = getenv("VLBE_FUZZ_VERBOSE") != NULL;
    if (!on) return;
    fprintf(stderr, "%s =", name);
    for (i = 0; i < n; ++i) fprintf(stderr, " %.17g", (double)x[i]);
    fprintf(stderr, "\n");
}


#endif /* VLBE_FUZZ_UTIL_H */
