#!/bin/sh
# measured.sh -- check the numbers that test comments quote as measured
# -- part of vlbe                                 SPDX-License-Identifier: MIT
#
#   sh tests/measured.sh [--update] [BUILD]     (BUILD defaults to build)
#
# A measured number in a comment of tests/test_*.c carries a tag right after
# it (tests/test_util.h, tu_measured):
#     the drift is 1.07e-7 (m:energy_drift) of Tmax
# and the suite, run with VLBE_TEST_REPORT=1, prints "MEASURED energy_drift
# <value>" into its log BUILD/<cfg>/<suite>.log (make test keeps those logs).
# Tag forms: (m:key) the dbl build, (m@cfg:key) the build cfg (dbl, dbl-O0,
# flt, san), (m~:key) and (m@cfg~:key) order of magnitude only.
#
# Checks, each a failure:
#   - a quoted number that does not round to the measurement at the digits
#     it shows (3.3e-5 accepts [3.25e-5, 3.35e-5]; a plain 0 only 0); ~ tags:
#     within a factor 3 and of the same sign (0: exactly 0);
#   - a tag whose key the log does not report (or reports twice, differently);
#   - a line that says "measured" beside a decimal number and carries no tag.
# --update rewrites each quoted number that fails from the log, with the same
# number of significant digits and the same notation, and reports the rest.
# Exit status 0 when everything agrees (after --update: when nothing is left).
set -u
update=0
if [ "${1-}" = "--update" ]; then update=1; shift; fi
BUILD=${1-build}
cd "$(dirname "$0")/.." || exit 2

srcs=$(ls tests/test_*.c 2>/dev/null)
[ -n "$srcs" ] || { echo "measured: no tests/test_*.c"; exit 2; }
logs=$(ls "$BUILD"/*/test_*.log 2>/dev/null | grep -v '\.vg\.log$')

rc=0
for src in $srcs; do
    suite=$(basename "$src" .c)
    # the logs of this suite, one per build: "cfg path" pairs for awk
    slogs=""
    for l in $logs; do
        case "$l" in */"$suite".log)
            cfg=$(basename "$(dirname "$l")")
            slogs="$slogs $cfg=$l";;
        esac
    done
    out=$(mktemp) || exit 2
    awk -v update="$update" -v src="$src" -v slogs="$slogs" -v out="$out" '
    function num_re() { return "[-+]?([0-9]+[.]?[0-9]*|[.][0-9]+)([eE][-+]?[0-9]+)?" }
    # half a unit of the last digit of the quoted number s
    function half_unit(s,   m, e, p, d) {
        m = s; e = 0
        p = index(tolower(m), "e")
        if (p > 0) { e = substr(m, p + 1) + 0; m = substr(m, 1, p - 1) }
        p = index(m, ".")
        d = (p > 0) ? length(m) - p : 0
        return 0.5 * 10 ^ (e - d)
    }
    # significant digits of the quoted number s (at least 1)
    function sig_digits(s,   m, p, t) {
        m = s; sub(/^[-+]/, "", m)
        p = index(tolower(m), "e")
        if (p > 0) m = substr(m, 1, p - 1)
        t = m; gsub(/[.]/, "", t); sub(/^0+/, "", t)
        return length(t) > 0 ? length(t) : 1
    }
    # v printed like the quoted s: same notation, same significant digits
    function like(s, v,   p, d, r, mant, ex) {
        p = index(tolower(s), "e")
        if (p > 0) {
            r = sprintf("%." (sig_digits(s) - 1) "e", v)
            mant = r; sub(/e.*/, "", mant)
            ex = r; sub(/.*e/, "", ex); ex = ex + 0
            return mant "e" ex
        }
        p = index(s, ".")
        d = (p > 0) ? length(s) - p : 0
        r = sprintf("%." d "f", v)
        if (substr(s, 1, 1) == "+" && v >= 0) r = "+" r
        return r
    }
    function agrees(s, v, approx,   c) {
        c = s + 0
        if (approx) {
            if (c == 0) return v == 0
            if ((c > 0) != (v > 0)) return 0
            return v / c <= 3 && c / v <= 3
        }
        if (c == 0 && s !~ /[.eE]/) return v == 0 # a plain 0: exactly zero
        return (v - c <= half_unit(s) * (1 + 1e-9) + 1e-300) && (c - v <= half_unit(s) * (1 + 1e-9) + 1e-300)
    }
    BEGIN {
        n = split(slogs, pairs, " ")
        for (i = 1; i <= n; ++i) {
            split(pairs[i], kv, "=")
            cfg = kv[1]; have[cfg] = 1
            while ((getline line < kv[2]) > 0) {
                if (line !~ /^MEASURED /) continue
                split(line, f, " ")
                k = cfg SUBSEP f[2]
                if ((k in val) && val[k] != f[3]) dup[k] = 1
                val[k] = f[3]
            }
            close(kv[2])
        }
        tagre = num_re() "[ \t]*[(]m(@[A-Za-z0-9-]+)?~?:[A-Za-z0-9_.]+[)]"
        bad = 0; ntag = 0; fixed = 0
    }
    {
        line = $0; rest = line; newline = ""; tagged = 0
        while (match(rest, tagre)) {
            tagged = 1; ntag++
            pre = substr(rest, 1, RSTART - 1)
            tok = substr(rest, RSTART, RLENGTH)
            rest = substr(rest, RSTART + RLENGTH)
            q = tok; sub(/[ \t]*[(]m.*$/, "", q)
            tg = tok; sub(/^[^(]*[(]m/, "", tg); sub(/[)]$/, "", tg)
            # tg is now "[@cfg][~]:key"
            cfg = "dbl"; approx = 0
            if (substr(tg, 1, 1) == "@") { cfg = tg; sub(/^@/, "", cfg); sub(/[~]?:.*$/, "", cfg) }
            if (tg ~ /~:/) approx = 1
            key = tg; sub(/^[^:]*:/, "", key)
            where = src ":" FNR ": (m" (cfg == "dbl" ? "" : "@" cfg) (approx ? "~" : "") ":" key ")"
            k = cfg SUBSEP key
            if (!(cfg in have)) {
                printf "%s: no log of build %s (run make test first)\n", where, cfg
                bad++
            } else if (!(k in val)) {
                printf "%s: the %s log reports no MEASURED %s\n", where, cfg, key
                bad++
            } else if (k in dup) {
                printf "%s: the %s log reports MEASURED %s twice, with different values\n", where, cfg, key
                bad++
            } else if (!agrees(q, val[k] + 0, approx)) {
                if (update) {
                    nq = like(q, val[k] + 0)
                    printf "%s: %s -> %s\n", where, q, nq
                    tok = nq substr(tok, length(q) + 1)
                    fixed++
                } else {
                    printf "%s: quotes %s, %s measures %s\n", where, q, cfg, like(q, val[k] + 0) " (" val[k] ")"
                    bad++
                }
            }
            newline = newline pre tok
        }
        newline = newline rest
        if (!tagged && tolower(line) ~ /measured/ && line !~ /tu_measured[(]/ &&
            line ~ /[0-9][.][0-9]|[0-9][eE][-+]?[0-9]/) {
            printf "%s:%d: says measured beside a number without a (m:key) tag\n", src, FNR
            bad++
        }
        print newline > out
    }
    END {
        close(out)
        printf "%d %d %d\n", ntag, bad, fixed > "/dev/stderr"
        exit bad > 0
    }' "$src" 2>"$out.count" || rc=1
    read -r nt nb nf < "$out.count" || { nt=0; nb=0; nf=0; }
    total_tags=$(( ${total_tags:-0} + nt ))
    total_bad=$(( ${total_bad:-0} + nb ))
    total_fixed=$(( ${total_fixed:-0} + nf ))
    if [ "$update" = 1 ] && [ "$nf" -gt 0 ]; then cat "$out" > "$src"; fi
    rm -f "$out" "$out.count"
done
echo "measured: ${total_tags:-0} tagged numbers, ${total_bad:-0} disagree or untagged$( [ "$update" = 1 ] && echo ", ${total_fixed:-0} rewritten")"
exit $rc
