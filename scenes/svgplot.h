/* svgplot.h -- small SVG line charts and CSV files for the vlbe benchmarks
   and examples -- part of vlbe                   SPDX-License-Identifier: MIT

USAGE
   #include "svgplot.h"     header-only, every function static inline,
                            C99 or C++, link with -lm; no malloc.

       double n[7], gf[7];                   (filled by the caller)
       svgp_chart c;
       svgp_init(&c, "dense LU", "n", "GFLOP/s", 1, 0);  (log x, linear y)
       svgp_series(&c, "vlbe_lu_factor", 7, n, gf, SVGP_MARKERS);
       svgp_write_file(&c, "out/bench/lu.svg");

   The chart keeps pointers to the name and the x, y arrays: keep them alive
   until svgp_write().  Up to SVGP_MAX_SERIES series.  The directory of the
   output file must exist (the Makefile creates out/...).

CHART
   800 x 500 (viewBox, scales in a browser), sans-serif.  Each axis linear or
   log10.  Ranges are automatic: the finite values of all series (positive
   ones only on a log axis), padded and rounded outwards to ticks (1-2-5 steps
   on linear axes; on log axes decades with minor ticks 2..9, and bounds of
   the 1-2-5 sequence when the data span three decades or less).  A point
   that cannot be shown (NaN, Inf, <= 0 on a log axis) breaks the line there.
   svgp_xrange()/svgp_yrange() fix a range instead; the plot area clips.
   Series i gets colour i mod 8 and marker shape i mod 4; series 8..15 are
   dashed unless a dash flag is given.

API
   void svgp_init(c, title, xlabel, ylabel, xlog, ylog)   empty chart
   int  svgp_series(c, name, n, x, y, flags)              add a series (0 ok, -1 full)
   void svgp_xrange(c, lo, hi) / svgp_yrange(c, lo, hi)   fix an axis range
   void svgp_fit_legend_log(c, max_dec, max_xdec)         log-log: whole decades and a
                                                          legend corner that hides no data
   int  svgp_write(c, FILE *f) / svgp_write_file(c, path) SVG out (0 ok, -1 I/O error)
   int  svgp_csv_write(path, header, ncols, nrows, cols)  numeric columns -> CSV
   FILE *svgp_csv_open(path, header); int svgp_csv_row(f, n, v)   row by row
   void svgp_compare_row(f, scene, quantity, published, ours, relerr, cpu_s)
                                                          one row of `make demo`'s table

COMPARISON ROWS
   Every example prints its comparison with a paper as lines
       ROW|<scene>|<quantity [unit]>|<published>|<computed>|<relative error>|<cpu seconds>
   svgp_compare_row() writes one (NaN prints "-": no published value, no
   error).  `make demo` collects the ROW lines of all scenes into one table.
   Fields must not contain '|' (one in the quantity is printed as '/').
*/
#ifndef VLBE_SVGPLOT_H
#define VLBE_SVGPLOT_H

#include <math.h>
#include <stdio.h>
#include <string.h>

#define SVGP_MAX_SERIES 16
#define SVGP_WIDTH 800
#define SVGP_HEIGHT 500
/* plot area inside the viewBox, in pixels */
#define SVGP__PL_L 80.0
#define SVGP__PL_R ((double)SVGP_WIDTH - 24.0)
#define SVGP__PL_T 44.0
#define SVGP__PL_B ((double)SVGP_HEIGHT - 62.0)

/* series style flags (bitwise or) */
enum {
    SVGP_LINE = 0,    /* polyline only (default)              */
    SVGP_MARKERS = 1, /* a marker at every point              */
    SVGP_NOLINE = 2,  /* markers only, no connecting line     */
    SVGP_DASH = 4,    /* dashed line                          */
    SVGP_DOT = 8,     /* dotted line                          */
    SVGP_SOLID = 16   /* solid even for series 8..15          */
};

/* legend placement */
enum { SVGP_LEGEND_TR = 0, SVGP_LEGEND_TL, SVGP_LEGEND_BR, SVGP_LEGEND_BL, SVGP_LEGEND_NONE };

typedef struct svgp_line {
    const char *name;
    const double *x, *y;
    int n, flags;
} svgp_line;

typedef struct svgp_chart {
    const char *title, *xlabel, *ylabel;
    int xlog, ylog;
    int nseries;
    svgp_line s[SVGP_MAX_SERIES];
    int xfixed, yfixed;     /* set by svgp_xrange / svgp_yrange */
    double x0, x1, y0, y1;  /* the fixed ranges                 */
    int legend;             /* SVGP_LEGEND_*, default top right */
} svgp_chart;

/* one axis after range selection */
typedef struct svgp__axis {
    int log;
    double lo, hi;   /* data range shown (linear values, > 0 if log) */
    double step;     /* linear: tick step; log: decades between labels */
    double a, b;     /* pixel = a * t + b with t = value or log10(value) */
} svgp__axis;

static inline void svgp_init(svgp_chart *c, const char *title, const char *xlabel,
                             const char *ylabel, int xlog, int ylog)
{
    memset(c, 0, sizeof *c);
    c->title = title;
    c->xlabel = xlabel;
    c->ylabel = ylabel;
    c->xlog = xlog != 0;
    c->ylog = ylog != 0;
    c->legend = SVGP_LEGEND_TR;
}

static inline int svgp_series(svgp_chart *c, const char *name, int n, const double *x,
                              const double *y, int flags)
{
    svgp_line *l;
    if (c->nseries >= SVGP_MAX_SERIES || n < 0 || (n > 0 && (x == NULL || y == NULL)))
        return -1;
    l = &c->s[c->nseries++];
    l->name = name;
    l->n = n;
    l->x = x;
    l->y = y;
    l->flags = flags;
    return 0;
}

static inline void svgp_xrange(svgp_chart *c, double lo, double hi)
{
    c->xfixed = 1;
    c->x0 = lo;
    c->x1 = hi;
}

static inline void svgp_yrange(svgp_chart *c, double lo, double hi)
{
    c->yfixed = 1;
    c->y0 = lo;
    c->y1 = hi;
}

/* legend box size in pixels */
static inline void svgp__legend_size(const svgp_chart *c, double *lw, double *lh)
{
    size_t wmax = 0;
    int k;
    for (k = 0; k < c->nseries; ++k) {
        size_t w = c->s[k].name ? strlen(c->s[k].name) : 0;
        if (w > wmax) wmax = w;
    }
    *lw = 44.0 + 6.6 * (double)wmax;
    *lh = 8.0 + 17.0 * (double)c->nseries;
}

/* Is any marker or line of chart c (log-log, ranges 10^x0..10^x1,
   10^y0..10^y1) inside the pixel box [bx0, bx1] x [by0, by1]? */
static inline int svgp__box_hit(const svgp_chart *c, double x0, double x1, double y0, double y1,
                                double bx0, double bx1, double by0, double by1)
{
    int k, i, j;
    for (k = 0; k < c->nseries; ++k) {
        const svgp_line *l = &c->s[k];
        double px0 = 0.0, py0 = 0.0;
        int have = 0;
        for (i = 0; i < l->n; ++i) {
            double px, py;
            if (!(l->x[i] > 0.0) || !(l->y[i] > 0.0) || !isfinite(l->x[i]) || !isfinite(l->y[i])) {
                have = 0;
                continue;
            }
            px = SVGP__PL_L + (log10(l->x[i]) - x0) / (x1 - x0) * (SVGP__PL_R - SVGP__PL_L);
            py = SVGP__PL_B - (log10(l->y[i]) - y0) / (y1 - y0) * (SVGP__PL_B - SVGP__PL_T);
            for (j = have ? 0 : 16; j <= 16; ++j) { /* the segment from the last point, sampled */
                double sx = px0 + (px - px0) * (double)j / 16.0, sy = py0 + (py - py0) * (double)j / 16.0;
                if (sx >= bx0 && sx <= bx1 && sy >= by0 && sy <= by1) return 1;
            }
            px0 = px;
            py0 = py;
            have = 1;
        }
    }
    return 0;
}

/* Log-log charts: fix whole-decade ranges on both axes and put the legend in
   a corner where it covers no data, adding the fewest decades (at most
   max_dec in all, at most max_xdec of them on x) that free one: y above for
   the top corners, below for the bottom ones; x on the legend's side.
   Nothing changes when no corner is found. */
static inline void svgp_fit_legend_log(svgp_chart *c, int max_dec, int max_xdec)
{
    static const int corner[4] = {SVGP_LEGEND_TR, SVGP_LEGEND_BR, SVGP_LEGEND_TL, SVGP_LEGEND_BL};
    double x0 = 0.0, x1 = 0.0, y0 = 0.0, y1 = 0.0, lw, lh;
    int k, i, found = 0, tot, xext;
    for (k = 0; k < c->nseries; ++k) {
        const svgp_line *l = &c->s[k];
        for (i = 0; i < l->n; ++i) {
            double lx, ly;
            if (!(l->x[i] > 0.0) || !(l->y[i] > 0.0) || !isfinite(l->x[i]) || !isfinite(l->y[i]))
                continue;
            lx = log10(l->x[i]);
            ly = log10(l->y[i]);
            if (!found || lx < x0) x0 = lx;
            if (!found || lx > x1) x1 = lx;
            if (!found || ly < y0) y0 = ly;
            if (!found || ly > y1) y1 = ly;
            found = 1;
        }
    }
    if (!found) return;
    x0 = floor(x0 + 1e-9);
    x1 = ceil(x1 - 1e-9);
    y0 = floor(y0 + 1e-9);
    y1 = ceil(y1 - 1e-9);
    if (x1 <= x0) x1 = x0 + 1.0;
    if (y1 <= y0) y1 = y0 + 1.0;
    svgp__legend_size(c, &lw, &lh);
    for (tot = 0; tot <= max_dec; ++tot) /* the fewest added decades first */
        for (xext = 0; xext <= (tot < max_xdec ? tot : max_xdec); ++xext)
            for (k = 0; k < 4; ++k) {
                const int ext = tot - xext;
                const int left = corner[k] == SVGP_LEGEND_TL || corner[k] == SVGP_LEGEND_BL;
                const int bottom = corner[k] == SVGP_LEGEND_BR || corner[k] == SVGP_LEGEND_BL;
                const double ya = bottom ? y0 - ext : y0, yb = bottom ? y1 : y1 + ext;
                const double xa = left ? x0 - xext : x0, xb = left ? x1 : x1 + xext;
                const double bx0 = left ? SVGP__PL_L + 10.0 : SVGP__PL_R - 10.0 - lw;
                const double by0 = bottom ? SVGP__PL_B - 10.0 - lh : SVGP__PL_T + 10.0;
                if (svgp__box_hit(c, xa, xb, ya, yb, bx0 - 6.0, bx0 + lw + 6.0, by0 - 6.0,
                                  by0 + lh + 6.0))
                    continue;
                svgp_xrange(c, pow(10.0, xa), pow(10.0, xb));
                svgp_yrange(c, pow(10.0, ya), pow(10.0, yb));
                c->legend = corner[k];
                return;
            }
}

/* -- helpers ---------------------------------------------------------- */
static inline int svgp__usable(double v, int logaxis)
{
    return isfinite(v) && (!logaxis || v > 0.0);
}

static inline double svgp__t(const svgp__axis *ax, double v)
{
    return ax->log ? log10(v) : v;
}

static inline double svgp__px(const svgp__axis *ax, double v)
{
    return ax->a * svgp__t(ax, v) + ax->b;
}

/* 1, 2 or 5 times a power of ten, >= x > 0 */
static inline double svgp__nice_step(double x)
{
    double p = pow(10.0, floor(log10(x))), m = x / p;
    if (m <= 1.0 + 1e-9) return p;
    if (m <= 2.0 + 1e-9) return 2.0 * p;
    if (m <= 5.0 + 1e-9) return 5.0 * p;
    return 10.0 * p;
}

/* the largest (up = 0) or smallest (up = 1) number 1, 2 or 5 times a power
   of ten that is <= x, or >= x; x > 0 */
static inline double svgp__nice_125(double x, int up)
{
    static const double m[4] = {1.0, 2.0, 5.0, 10.0};
    double p = pow(10.0, floor(log10(x)));
    int i;
    if (up) {
        for (i = 0; i < 4; ++i)
            if (m[i] * p >= x * (1.0 - 1e-12)) return m[i] * p;
        return 10.0 * p;
    }
    for (i = 3; i >= 0; --i)
        if (m[i] * p <= x * (1.0 + 1e-12)) return m[i] * p;
    return p;
}

/* Choose the shown range of one axis; which = 0 for x, 1 for y. */
static inline void svgp__range(const svgp_chart *c, int which, svgp__axis *ax)
{
    int logaxis = which ? c->ylog : c->xlog, i, k, found = 0;
    double lo = 0.0, hi = 0.0;
    ax->log = logaxis;
    if (which ? c->yfixed : c->xfixed) {
        lo = which ? c->y0 : c->x0;
        hi = which ? c->y1 : c->x1;
        found = svgp__usable(lo, logaxis) && svgp__usable(hi, logaxis) && hi > lo;
        if (found) {
            ax->lo = lo;
            ax->hi = hi;
            if (logaxis) {
                double dec = log10(hi) - log10(lo);
                ax->step = dec > 10.0 ? ceil(dec / 8.0) : 1.0;
            } else {
                ax->step = svgp__nice_step((hi - lo) / 6.0);
            }
            return;
        }
    }
    found = 0;
    for (k = 0; k < c->nseries; ++k) {
        const svgp_line *l = &c->s[k];
        const double *v = which ? l->y : l->x;
        for (i = 0; i < l->n; ++i) {
            if (!svgp__usable(v[i], logaxis)) continue;
            if (!found || v[i] < lo) lo = v[i];
            if (!found || v[i] > hi) hi = v[i];
            found = 1;
        }
    }
    if (logaxis) {
        double llo, lhi, dec;
        if (!found) {
            lo = 1.0;
            hi = 10.0;
        }
        llo = log10(lo);
        lhi = log10(hi);
        if (lhi - llo > 3.0) { /* wide: whole decades */
            llo = floor(llo + 1e-9);
            lhi = ceil(lhi - 1e-9);
        } else { /* narrow: 1-2-5 bounds */
            llo = log10(svgp__nice_125(lo, 0));
            lhi = log10(svgp__nice_125(hi, 1));
        }
        if (lhi <= llo) lhi = llo + 1.0;
        dec = lhi - llo;
        ax->lo = pow(10.0, llo);
        ax->hi = pow(10.0, lhi);
        ax->step = dec > 10.0 ? ceil(dec / 8.0) : 1.0;
    } else {
        double span, step;
        if (!found) {
            lo = 0.0;
            hi = 1.0;
        }
        if (hi <= lo) { /* one value: a range around it */
            double d = fabs(lo) > 0.0 ? 0.1 * fabs(lo) : 1.0;
            lo -= d;
            hi += d;
        }
        span = hi - lo;
        step = svgp__nice_step(span / 6.0);
        /* pad 3 %, but do not cross zero when the data do not */
        {
            double plo = lo - 0.03 * span, phi = hi + 0.03 * span;
            if (lo >= 0.0 && plo < 0.0) plo = 0.0;
            if (hi <= 0.0 && phi > 0.0) phi = 0.0;
            lo = plo;
            hi = phi;
        }
        ax->lo = floor(lo / step + 1e-9) * step;
        ax->hi = ceil(hi / step - 1e-9) * step;
        if (ax->hi <= ax->lo) ax->hi = ax->lo + step;
        ax->step = step;
    }
}

static inline void svgp__map(svgp__axis *ax, double p0, double p1)
{
    double t0 = svgp__t(ax, ax->lo), t1 = svgp__t(ax, ax->hi);
    ax->a = (p1 - p0) / (t1 - t0);
    ax->b = p0 - ax->a * t0;
}

static inline void svgp__text(FILE *f, const char *s)
{
    if (!s) return;
    for (; *s; ++s) {
        switch (*s) {
        case '&': fputs("&amp;", f); break;
        case '<': fputs("&lt;", f); break;
        case '>': fputs("&gt;", f); break;
        case '"': fputs("&quot;", f); break;
        default: fputc(*s, f);
        }
    }
}

/* tick label of a linear axis value */
static inline void svgp__lin_label(FILE *f, double v, double step)
{
    char buf[32];
    if (fabs(v) < 1e-9 * step) v = 0.0;
    if (v != 0.0 && (fabs(v) >= 1e6 || fabs(v) < 1e-3))
        snprintf(buf, sizeof buf, "%.3g", v);
    else
        snprintf(buf, sizeof buf, "%.6g", v);
    fputs(buf, f);
}

/* tick label 10^e of a log axis */
static inline void svgp__dec_label(FILE *f, int e)
{
    if (e >= -2 && e <= 3)
        fprintf(f, "%g", pow(10.0, (double)e));
    else
        fprintf(f, "10<tspan dy=\"-6\" font-size=\"10\">%d</tspan>", e);
}

static inline const char *svgp__colour(int i)
{
    static const char *const pal[8] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e",
                                       "#9467bd", "#8c564b", "#e377c2", "#17becf"};
    return pal[i % 8];
}

static inline void svgp__marker(FILE *f, int shape, double x, double y, const char *col)
{
    switch (shape % 4) {
    case 0: fprintf(f, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"3.5\" fill=\"%s\"/>\n", x, y, col); break;
    case 1:
        fprintf(f, "<rect x=\"%.1f\" y=\"%.1f\" width=\"7\" height=\"7\" fill=\"%s\"/>\n", x - 3.5,
                y - 3.5, col);
        break;
    case 2:
        fprintf(f, "<path d=\"M%.1f %.1fL%.1f %.1fL%.1f %.1fZ\" fill=\"%s\"/>\n", x, y - 4.5,
                x + 4.0, y + 3.0, x - 4.0, y + 3.0, col);
        break;
    default:
        fprintf(f, "<path d=\"M%.1f %.1fL%.1f %.1fL%.1f %.1fL%.1f %.1fZ\" fill=\"%s\"/>\n", x,
                y - 4.5, x + 4.5, y, x, y + 4.5, x - 4.5, y, col);
        break;
    }
}

static inline const char *svgp__dash(const svgp_line *l, int i)
{
    if (l->flags & SVGP_DASH) return " stroke-dasharray=\"8 4\"";
    if (l->flags & SVGP_DOT) return " stroke-dasharray=\"2 3\"";
    if (!(l->flags & SVGP_SOLID) && i >= 8) return " stroke-dasharray=\"8 4\"";
    return "";
}

/* A major tick at pixel p: grid line, tick mark, and an opened <text> for
   its label (the caller writes the label and closes it); which = 0 for x. */
static inline void svgp__major_tick(FILE *f, int which, double p, double L, double R, double T,
                                    double B)
{
    const char *grid = "stroke=\"#e4e4e4\" stroke-width=\"1\"";
    if (which == 0) {
        fprintf(f, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" %s/>\n", p, T, p, B, grid);
        fprintf(f, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#000\"/>\n", p, B, p, B + 6.0);
        fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\">", p, B + 20.0);
    } else {
        fprintf(f, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" %s/>\n", L, p, R, p, grid);
        fprintf(f, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#000\"/>\n", L - 6.0, p, L, p);
        fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"end\">", L - 9.0, p + 4.0);
    }
}

/* ticks, grid and labels of one axis; which = 0 for x, 1 for y */
static inline void svgp__ticks(FILE *f, const svgp__axis *ax, int which, double L, double R,
                               double T, double B)
{
    if (ax->log) {
        int e0 = (int)floor(log10(ax->lo) + 1e-9), e1 = (int)ceil(log10(ax->hi) - 1e-9), e, m;
        int every = (int)ax->step, few = log10(ax->hi / ax->lo) <= 2.5;
        for (e = e0; e <= e1; ++e) {
            for (m = 1; m <= 9; ++m) {
                double v = (double)m * pow(10.0, (double)e), p;
                if (v < ax->lo * (1.0 - 1e-9) || v > ax->hi * (1.0 + 1e-9)) continue;
                p = svgp__px(ax, v);
                if (m == 1 && e % every == 0) {
                    svgp__major_tick(f, which, p, L, R, T, B);
                    svgp__dec_label(f, e);
                    fputs("</text>\n", f);
                } else if (every == 1) {
                    /* minor tick; on short axes 2 and 5 get labels too */
                    int lab = few && (m == 2 || m == 5);
                    if (which == 0) {
                        fprintf(f, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#000\"/>\n", p, B, p, B + 3.0);
                        if (lab)
                            fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\" font-size=\"10\" fill=\"#555\">%g</text>\n",
                                    p, B + 18.0, v);
                    } else {
                        fprintf(f, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#000\"/>\n", L - 3.0, p, L, p);
                        if (lab)
                            fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"end\" font-size=\"10\" fill=\"#555\">%g</text>\n",
                                    L - 9.0, p + 4.0, v);
                    }
                }
            }
        }
    } else {
        double k0 = ceil(ax->lo / ax->step - 1e-9), k1 = floor(ax->hi / ax->step + 1e-9), k;
        for (k = k0; k <= k1; k += 1.0) {
            double v = k * ax->step, p = svgp__px(ax, v);
            svgp__major_tick(f, which, p, L, R, T, B);
            svgp__lin_label(f, v, ax->step);
            fputs("</text>\n", f);
        }
    }
}

static inline int svgp_write(const svgp_chart *c, FILE *f)
{
    const double H = SVGP_HEIGHT;
    const double L = SVGP__PL_L, R = SVGP__PL_R, T = SVGP__PL_T, B = SVGP__PL_B;
    svgp__axis ax, ay;
    int k, i;
    svgp__range(c, 0, &ax);
    svgp__range(c, 1, &ay);
    svgp__map(&ax, L, R);
    svgp__map(&ay, B, T);

    fprintf(f, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    fprintf(f, "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 %d %d\" width=\"%d\" height=\"%d\" "
               "font-family=\"Helvetica, Arial, sans-serif\" font-size=\"12\">\n",
            SVGP_WIDTH, SVGP_HEIGHT, SVGP_WIDTH, SVGP_HEIGHT);
    fprintf(f, "<rect width=\"100%%\" height=\"100%%\" fill=\"#fff\"/>\n");
    fprintf(f, "<defs><clipPath id=\"svgp-area\"><rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\"/></clipPath></defs>\n",
            L - 6.0, T - 6.0, R - L + 12.0, B - T + 12.0);
    if (c->title) {
        fprintf(f, "<text x=\"%.1f\" y=\"26\" text-anchor=\"middle\" font-size=\"16\" font-weight=\"bold\">", 0.5 * (L + R));
        svgp__text(f, c->title);
        fputs("</text>\n", f);
    }
    svgp__ticks(f, &ax, 0, L, R, T, B);
    svgp__ticks(f, &ay, 1, L, R, T, B);
    fprintf(f, "<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" fill=\"none\" stroke=\"#000\"/>\n",
            L, T, R - L, B - T);
    if (c->xlabel) {
        fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\" font-size=\"13\">", 0.5 * (L + R), H - 18.0);
        svgp__text(f, c->xlabel);
        fputs("</text>\n", f);
    }
    if (c->ylabel) {
        fprintf(f, "<text transform=\"translate(18 %.1f) rotate(-90)\" text-anchor=\"middle\" font-size=\"13\">",
                0.5 * (T + B));
        svgp__text(f, c->ylabel);
        fputs("</text>\n", f);
    }

    /* series */
    fputs("<g clip-path=\"url(#svgp-area)\" fill=\"none\" stroke-width=\"1.8\" stroke-linejoin=\"round\">\n", f);
    for (k = 0; k < c->nseries; ++k) {
        const svgp_line *l = &c->s[k];
        const char *col = svgp__colour(k);
        if (!(l->flags & SVGP_NOLINE)) {
            int pen = 0, any = 0;
            for (i = 0; i < l->n; ++i) {
                if (!svgp__usable(l->x[i], ax.log) || !svgp__usable(l->y[i], ay.log)) {
                    pen = 0;
                    continue;
                }
                if (!any) fprintf(f, "<path stroke=\"%s\"%s d=\"", col, svgp__dash(l, k));
                any = 1;
                fprintf(f, "%c%.2f %.2f", pen ? 'L' : 'M', svgp__px(&ax, l->x[i]), svgp__px(&ay, l->y[i]));
                pen = 1;
            }
            if (any) fputs("\"/>\n", f);
        }
        if (l->flags & (SVGP_MARKERS | SVGP_NOLINE))
            for (i = 0; i < l->n; ++i)
                if (svgp__usable(l->x[i], ax.log) && svgp__usable(l->y[i], ay.log))
                    svgp__marker(f, k, svgp__px(&ax, l->x[i]), svgp__px(&ay, l->y[i]), col);
    }
    fputs("</g>\n", f);

    /* legend */
    if (c->legend != SVGP_LEGEND_NONE && c->nseries > 0) {
        double lw, lh, lx, ly;
        svgp__legend_size(c, &lw, &lh);
        lx = (c->legend == SVGP_LEGEND_TL || c->legend == SVGP_LEGEND_BL) ? L + 10.0 : R - 10.0 - lw;
        ly = (c->legend == SVGP_LEGEND_BR || c->legend == SVGP_LEGEND_BL) ? B - 10.0 - lh : T + 10.0;
        fprintf(f, "<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" fill=\"#fff\" fill-opacity=\"0.85\" stroke=\"#999\"/>\n",
                lx, ly, lw, lh);
        for (k = 0; k < c->nseries; ++k) {
            const svgp_line *l = &c->s[k];
            const char *col = svgp__colour(k);
            double yy = ly + 14.0 + 17.0 * (double)k;
            if (!(l->flags & SVGP_NOLINE))
                fprintf(f, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"%s\" stroke-width=\"1.8\"%s/>\n",
                        lx + 6.0, yy - 4.0, lx + 34.0, yy - 4.0, col, svgp__dash(l, k));
            if (l->flags & (SVGP_MARKERS | SVGP_NOLINE)) svgp__marker(f, k, lx + 20.0, yy - 4.0, col);
            fprintf(f, "<text x=\"%.1f\" y=\"%.1f\">", lx + 40.0, yy);
            svgp__text(f, l->name);
            fputs("</text>\n", f);
        }
    }
    fputs("</svg>\n", f);
    return ferror(f) ? -1 : 0;
}

static inline int svgp_write_file(const svgp_chart *c, const char *path)
{
    FILE *f = fopen(path, "w");
    int rc;
    if (!f) return -1;
    rc = svgp_write(c, f);
    if (fclose(f) != 0) rc = -1;
    return rc;
}

/* -- CSV ---------------------------------------------------------------- */
/* Open path and write the header line (e.g. "n,seconds,gflops"); NULL on error. */
static inline FILE *svgp_csv_open(const char *path, const char *header)
{
    FILE *f = fopen(path, "w");
    if (f && header) fprintf(f, "%s\n", header);
    return f;
}

/* One row of n numbers (%.10g, comma separated); 0 ok, -1 on I/O error. */
static inline int svgp_csv_row(FILE *f, int n, const double *v)
{
    int i;
    for (i = 0; i < n; ++i) fprintf(f, i ? ",%.10g" : "%.10g", v[i]);
    fputc('\n', f);
    return ferror(f) ? -1 : 0;
}

/* Write nrows rows of ncols columns; column j is the array cols[j]. */
static inline int svgp_csv_write(const char *path, const char *header, int ncols, int nrows,
                                 const double *const *cols)
{
    FILE *f = svgp_csv_open(path, header);
    int i, j, rc = 0;
    if (!f) return -1;
    for (i = 0; i < nrows; ++i) {
        for (j = 0; j < ncols; ++j) fprintf(f, j ? ",%.10g" : "%.10g", cols[j][i]);
        fputc('\n', f);
    }
    if (ferror(f)) rc = -1;
    if (fclose(f) != 0) rc = -1;
    return rc;
}

/* -- comparison rows for `make demo` ------------------------------------- */
static inline void svgp__num(FILE *f, const char *fmt, double v)
{
    fputc('|', f);
    if (isnan(v))
        fputc('-', f);
    else
        fprintf(f, fmt, v);
}

static inline void svgp_compare_row(FILE *f, const char *scene, const char *quantity,
                                    double published, double ours, double relerr, double cpu_s)
{
    const char *c;
    fprintf(f, "ROW|%s|", scene);
    for (c = quantity; *c; ++c) fputc(*c == '|' ? '/' : *c, f); /* '|' separates fields */
    svgp__num(f, "%.10g", published);
    svgp__num(f, "%.10g", ours);
    svgp__num(f, "%.2e", relerr);
    svgp__num(f, "%.3g", cpu_s);
    fputc('\n', f);
}

#endif /* VLBE_SVGPLOT_H */
