# vs_double.awk -- the float runs of tests/m4/m4_hht.c (host and M4)
# against its double run on the host (make check-m4): the tip position
# x, y at every printed time (V lines tip_q[0], tip_q[1]; the decimal in
# field 4) within tol relative of the double value, |f - d| <= tol |d|,
# i.e. the deflection y to 1e-3 of itself; the same lines in the same
# order.  (The slopes, tip_q[2..3], are not compared.)
# Prints the worst relative difference; exit status 1 beyond tol.
#   awk -v tol=1e-3 -v what="m4_hht M4 float" -f vs_double.awk dbl.txt flt.txt
# -- part of vlbe                                  SPDX-License-Identifier: MIT
function abs(x) { return x < 0 ? -x : x }
FNR == 1 { ++file }
$1 == "V" && $2 ~ /^tip_q\[[01]\]$/ { v[file, ++n[file]] = $4 + 0; name[file, n[file]] = $2 }
END {
    bad = 0; worst = 0; wn = "-"
    if (n[1] != n[2] || n[1] == 0) { printf "%s: %d tip values in double, %d in float\n", what, n[1], n[2]; exit 1 }
    for (i = 1; i <= n[1]; ++i) {
        if (name[1, i] != name[2, i]) { printf "%s: line %d: %s vs %s\n", what, i, name[1, i], name[2, i]; exit 1 }
        d = v[1, i]; r = d != 0 ? abs(v[2, i] - d) / abs(d) : abs(v[2, i])
        if (r > worst) { worst = r; wn = name[1, i] " (value " i ")" }
        if (r > tol) bad = 1
    }
    printf "%s vs double: %d tip values, worst relative difference %.2e at %s (bound %s)%s\n", \
        what, n[1], worst, wn, tol, bad ? ": FAILED" : ""
    exit bad
}
