#!/bin/sh
# tests/vgcover.sh -- the library lines each suite executes, and the lines a
# subset of the suites leaves: the argument for make test's valgrind set
# (VALGRIND_SUITES in the Makefile).  POSIX sh + awk + gcov.
# -- part of vlbe                                 SPDX-License-Identifier: MIT
#
#   sh tests/vgcover.sh suite ...       (make vg-cover: the VALGRIND_SUITES set)
#
# Builds every tests/test_*.c with --coverage into BUILD/cover/<suite>/
# ($CC $CFLAGS ... $LIBS, which the Makefile passes: the dbl-O0 flags, whose
# runs take the same slow-build variants as a run under valgrind), runs it,
# and reads gcov's count of each line of vlbe.h, ancf_ale.h, rancf.h,
# corot2d.h and integrators.h.  Prints, per header, the lines that all
# suites execute and the lines the named suites execute, then each line
# that the named suites leave, with the suites that execute it.
# Exit status 0 when the suites ran (a suite that fails still counts its
# lines but is named), 2 on a build error.
set -u
LC_ALL=C
export LC_ALL
root=$(cd "$(dirname "$0")/.." && pwd) || exit 2
cd "$root" || exit 2
CC=${CC:-cc}
CFLAGS=${CFLAGS:--std=c99 -O0 -I.}
LIBS=${LIBS:--lcmocka -lm}
BUILD=${BUILD:-build}
case $BUILD in /*) ;; *) BUILD=$root/$BUILD ;; esac
dir=$BUILD/cover
headers="vlbe.h ancf_ale.h rancf.h corot2d.h integrators.h"
rm -rf "$dir"
mkdir -p "$dir" || exit 2
rows=$dir/lines.txt
: > "$rows"
for src in tests/test_*.c; do
    s=$(basename "$src" .c)
    mkdir -p "$dir/$s"
    # shellcheck disable=SC2086
    $CC $CFLAGS --coverage "$root/$src" -o "$dir/$s/$s" $LIBS || { echo "vgcover: $s does not build" >&2; exit 2; }
    "$dir/$s/$s" > "$dir/$s/run.log" 2>&1 < /dev/null || echo "vgcover: $s failed (its lines still count; log $dir/$s/run.log)"
    # gcov's text: "count:line:source", count "-" (no code) or "#####" (not run)
    (cd "$dir/$s" && gcov -t ./*.gcda 2> /dev/null) | awk -v s="$s" -v hdrs=" $headers " '
        { c = $0; sub(/:.*/, "", c); gsub(/ /, "", c)
          r = $0; sub(/^[^:]*:/, "", r); n = r; sub(/:.*/, "", n); n = n + 0
          if (n == 0) { if (r ~ /^ *0:Source:/) { f = r; sub(/^ *0:Source:/, "", f); sub(/.*\//, "", f)
                          keep = index(hdrs, " " f " ") > 0 }; next }
          if (keep && c ~ /^[0-9]+\*?$/ && c + 0 > 0) printf "%s\t%s\t%d\n", s, f, n }' >> "$rows"
done
awk -F'\t' -v sel=" $* " -v hdrs="$headers" -v root="$root" '
    { k = $2 ":" $3; if (!(k in all)) { all[k] = 1; nh[$2]++; order[++no] = k }
      who[k] = (k in who) ? who[k] " " $1 : $1
      if (index(sel, " " $1 " ") && !(k in got)) { got[k] = 1; ng[$2]++ } }
    END {
        nn = split(hdrs, H, " ")
        printf "%-14s %9s %9s\n", "header", "all", "selected"
        for (i = 1; i <= nn; ++i) { printf "%-14s %9d %9d\n", H[i], nh[H[i]], ng[H[i]]; ta += nh[H[i]]; tg += ng[H[i]] }
        printf "%-14s %9d %9d\n", "total", ta, tg
        for (i = 1; i <= no; ++i) {
            k = order[i]; if (k in got) continue
            split(k, a, ":"); line = ""
            cmd = "sed -n " a[2] "p " root "/" a[1]; cmd | getline line; close(cmd)
            gsub(/^[ \t]+/, "", line)
            printf "left: %s  [%s]  %s\n", k, who[k], substr(line, 1, 60)
        }
    }' "$rows"
