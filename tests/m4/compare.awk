# compare.awk -- one M4 output of make check-m4 against the host float run
# of the same program (lines of tests/m4/m4_out.h).  Both files must have
# the same lines in the same order: the same names, equal I lines (counts,
# statuses) and equal END lines.  A V value (a float as its bit pattern)
# passes when it is bit-identical to the host's, or when
#     |m4 - host| <= tol * FLT_EPSILON * scale,
# scale = the largest host magnitude of its group (the name without its
# [index]).  Prints one line: values, bit-identical count, the worst
# distance in ulps (count of floats between the two) and in units of
# FLT_EPSILON * scale; exit status 1 on any failure.
#   awk -v tol=16 -v prog=m4_lu -f compare.awk host.txt m4.txt
# -- part of vlbe                                  SPDX-License-Identifier: MIT

function hex2num(h,    i, v) {
    v = 0
    for (i = 1; i <= length(h); ++i) v = v * 16 + index("0123456789abcdef", substr(h, i, 1)) - 1
    return v
}
# the float of bit pattern u (0 <= u < 2^32)
function fval(u,    s, e, m, v) {
    s = u >= 2147483648 ? -1 : 1
    if (s < 0) u -= 2147483648
    e = int(u / 8388608); m = u - e * 8388608
    if (e == 255) return s * 3.4e38 * 10   # Inf or NaN: beyond any float
    v = e == 0 ? m * 2 ^ -149 : (1 + m / 8388608) * 2 ^ (e - 127)
    return s * v
}
# position of u on the line of floats (neighbours differ by 1, -0 == +0)
function ford(u) { return u >= 2147483648 ? -(u - 2147483648) : u }
function group(n) { sub(/\[.*/, "", n); return n }
function abs(x) { return x < 0 ? -x : x }

FNR == 1 { ++file }
file == 1 { hl[++nh] = $0; if ($1 == "V") { g = group($2); a = abs(fval(hex2num($3))); if (a > sc[g]) sc[g] = a } next }
file == 2 { ml[++nm] = $0 }

END {
    eps = 2 ^ -23
    bad = 0; nv = 0; nid = 0; wu = 0; we = 0; wn = "-"
    if (nh != nm) { printf "%s: %d lines on the host, %d on the M4\n", prog, nh, nm; bad = 1 }
    n = nh < nm ? nh : nm
    for (i = 1; i <= n; ++i) {
        split(hl[i], h, " "); split(ml[i], m, " ")
        if (h[1] != m[1] || h[2] != m[2]) {
            printf "%s: line %d differs: host \"%s\", M4 \"%s\"\n", prog, i, hl[i], ml[i]; bad = 1; continue
        }
        if (h[1] != "V") {
            if (hl[i] != ml[i]) { printf "%s: host \"%s\", M4 \"%s\"\n", prog, hl[i], ml[i]; bad = 1 }
            continue
        }
        ++nv
        if (h[3] == m[3]) { ++nid; continue }
        uh = hex2num(h[3]); um = hex2num(m[3])
        du = abs(ford(uh) - ford(um))
        s = sc[group(h[2])]
        de = s > 0 ? abs(fval(uh) - fval(um)) / (eps * s) : (du ? 1e30 : 0)
        if (du > wu) { wu = du; wn = h[2] }
        if (de > we) we = de
        if (de > tol) {
            printf "%s: %s host %s M4 %s: %d ulp, %.3g eps * scale (bound %s)\n", prog, h[2], h[3], m[3], du, de, tol
            bad = 1
        }
    }
    printf "%s: %d values, %d bit-identical, worst %d ulp (%s), %.3g FLT_EPSILON * scale (bound %s)%s\n", \
        prog, nv, nid, wu, wn, we, tol, bad ? ": FAILED" : ""
    exit bad
}
