#!/bin/sh
# tests/mutate.sh -- mutation testing: apply each deliberate bug of
# tests/mutations.txt to a copy of the tree, build the suites the entry
# names in the double -O2 configuration (the Makefile's build/dbl/test_x
# rule, run in the copy) and run them; a mutation is killed when a suite
# fails, crashes or hangs.  POSIX sh + awk; the working copy is never edited.
#
#   sh tests/mutate.sh [id ...]       (make mutate [MUTATIONS="id ..."])
#
# Work area build/mutate/ (MUTATE_DIR): tree/ the copy (headers, Makefile,
# tests/, scenes/, fuzz/), logs/ every build and run
# log, report.txt the table
#     id | description | caught by (suite:test, ...) | verdict
# with verdicts killed, SURVIVED, survived (explained: the entry carries
# "survivor: <reason>"), no-compile (the edit does not build with the
# Makefile's flags, -Werror included: fix the entry, it is not a kill),
# stale (a find text does not occur exactly once in its header).
# Before the mutations the unmutated copy is built and every suite in use
# run once: a suite that fails there makes the run stop (exit 2), since
# every mutation would look killed.  Each run has a timeout of
# MUTATE_TIMEOUT_FACTOR (10) times the suite's unmutated run time plus
# MUTATE_TIMEOUT_ADD (30) seconds; a timeout counts as caught, as does a
# crash (the run ends before cmocka's closing line: signal, abort,
# exit).  Every listed suite runs for every mutation, so the table shows
# all the tests that catch it.
# Exit status: 0 when every mutation is killed or an explained survivor;
# 1 for an unexplained survivor, a stale or no-compile entry, or an
# explained survivor that is in fact killed (its reason is wrong); 2 for a
# bad list, unknown ids or a failing unmutated suite.
# Parallel builds: make -j2 mutate passes make's job server to the builds
# in the copy (each mutation's suites compile in parallel).

set -u
LC_ALL=C
export LC_ALL

root=$(cd "$(dirname "$0")/.." && pwd) || exit 2
list=${MUTATIONS_FILE:-$root/tests/mutations.txt}
work=${MUTATE_DIR:-$root/build/mutate}
make_cmd=${MAKE:-make}
tfac=${MUTATE_TIMEOUT_FACTOR:-10}
tadd=${MUTATE_TIMEOUT_ADD:-30}
headers="vlbe.h ancf_ale.h rancf.h corot2d.h integrators.h"

die() {
    echo "mutate: $*" >&2
    exit 2
}

command -v timeout >/dev/null 2>&1 || die "needs timeout(1) (coreutils)"
[ -f "$list" ] || die "no list $list"
case $work in /*) ;; *) work=$(pwd)/$work ;; esac
tree=$work/tree
logs=$work/logs
ent=$work/entries
rm -rf "$logs" "$ent" "$tree"
mkdir -p "$logs" "$ent/pairs" || die "cannot create $work"

# -- the list: index (id TAB file TAB suites TAB description TAB survivor)
# and per entry the find/replace texts, one line each, alternating --------
awk -v dir="$ent" -v hdrs=" $headers " -v tdir="$root/tests" '
function err(m) { printf "%s:%d: %s\n", FILENAME, FNR, m > "/dev/stderr"; bad = 1 }
function flush(   i, s, n, a) {
    if (id == "") return
    if (file == "") err("entry " id ": no file:")
    if (suites == "") err("entry " id ": no suites:")
    if (desc == "") err("entry " id ": no desc:")
    if (np == 0) err("entry " id ": no find:/replace: pair")
    if (want) err("entry " id ": find: without replace:")
    n = split(suites, a, " ")
    for (i = 1; i <= n; ++i)
        if (system("test -f \"" tdir "/" a[i] ".c\"") != 0) err("entry " id ": no suite tests/" a[i] ".c")
    printf "%s\t%s\t%s\t%s\t%s\n", id, file, suites, desc, surv > (dir "/index")
    for (i = 1; i <= np; ++i) printf "%s\n%s\n", F[i], R[i] > (dir "/pairs/" id)
    close(dir "/pairs/" id)
    id = ""
}
/^#/ || /^[ \t]*$/ { next }
{
    c = index($0, ":")
    if (c < 2) { err("not a \"key: value\" line"); next }
    key = substr($0, 1, c - 1)
    val = substr($0, c + 1)
    if (substr(val, 1, 1) == " ") val = substr(val, 2)
    if (index(val, "\t") && key != "find" && key != "replace") err("tab in " key)
    if (key == "id") {
        flush()
        if (val !~ /^[A-Za-z0-9_.-]+$/) err("bad id \"" val "\"")
        if (val in seen) err("duplicate id " val)
        seen[val] = 1
        id = val; file = suites = desc = surv = ""; np = 0; want = 0
        next
    }
    if (id == "") { err(key ": outside an entry (no id: before it)"); next }
    if (key == "file") {
        if (index(hdrs, " " val " ") == 0) err("file " val " is not one of the headers")
        file = val
    } else if (key == "find") {
        if (want) err("find: twice without replace:")
        if (val == "") err("empty find:")
        F[++np] = val; want = 1
    } else if (key == "replace") {
        if (!want) err("replace: without find:")
        if (val == F[np]) err("replace: equals its find:")
        R[np] = val; want = 0
    } else if (key == "suites") {
        gsub(/[ \t]+/, " ", val); sub(/^ /, "", val); sub(/ $/, "", val)
        suites = val
    } else if (key == "desc") {
        desc = val
    } else if (key == "survivor") {
        if (val == "") err("survivor: needs a reason")
        surv = val
    } else err("unknown key \"" key "\"")
}
END { flush(); if (bad) exit 1 }
' "$list" || die "errors in $list"
[ -s "$ent/index" ] || die "no entries in $list"

# -- selection ------------------------------------------------------------
if [ $# -gt 0 ]; then
    : > "$ent/sel"
    for i in "$@"; do
        awk -F'\t' -v i="$i" '$1 == i { f = 1; print } END { exit !f }' "$ent/index" >> "$ent/sel" ||
            die "no mutation $i in $list"
    done
else
    cp "$ent/index" "$ent/sel"
fi
total=$(awk 'END { print NR }' "$ent/sel")
all_suites=$(awk -F'\t' '{ n = split($3, a, " "); for (i = 1; i <= n; ++i) if (!(a[i] in s)) { s[a[i]] = 1; print a[i] } }' "$ent/sel")

# -- the copy of the tree -------------------------------------------------
fresh_tree() {
    rm -rf "$tree" && mkdir -p "$tree" || return 1
    (cd "$root" && cp $headers Makefile "$tree/" && cp -R tests scenes fuzz "$tree/")
}

# builds the suites $2.. in the copy; log $1; prints the suites not built
build() {
    blog=$1
    shift
    tg=""
    for s in "$@"; do tg="$tg build/dbl/$s"; done
    rm -rf "$tree/build/dbl"
    # shellcheck disable=SC2086
    $make_cmd -C "$tree" -k $tg > "$blog" 2>&1 < /dev/null
    for s in "$@"; do [ -x "$tree/build/dbl/$s" ] || printf '%s ' "$s"; done
}

now() { date +%s; }

# runs suite $1 with timeout $2, log $3; prints what caught the mutation
# (suite:test ... for cmocka's "[  FAILED  ] test" lines; suite:timeout;
# suite:crash(signal N) or crash(exit N) when the run ends before cmocka's
# closing "[==========] N test(s) run."; suite:exit N), nothing when it passed
run_suite() {
    t0=$(now)
    # the status inside the subshell: no "Killed" notice from this shell
    rc=$( (cd "$tree" && timeout -k 5 "$2" "./build/dbl/$1" > "$3" 2>&1 < /dev/null; echo $?) 2>/dev/null)
    [ "$rc" -eq 0 ] && return 0
    # 124: timed out; 137 (KILL) is a timeout only when the time was up
    to=0
    [ "$rc" -eq 124 ] && to=1
    [ "$rc" -eq 137 ] && [ $(($(now) - t0)) -ge "$2" ] && to=1
    awk -v s="$1" -v rc="$rc" -v to=$to '
        /^\[==========\] Running [0-9]+ test/ { ++run }
        /^\[==========\] [0-9]+ test\(s\) run\./ { ++ended }
        /^\[  FAILED  \] / && $0 !~ /^\[  FAILED  \] [0-9]+ test/ {
            t = $0; sub(/^\[  FAILED  \] /, "", t); sub(/[ \t]+$/, "", t)
            if (!(t in seen)) { seen[t] = 1; printf "%s%s:%s", n++ ? ", " : "", s, t }
        }
        END {
            if (to) w = "timeout"
            else if (run == 0 || ended < run) w = rc > 128 ? "crash(signal " (rc - 128) ")" : "crash(exit " rc ")"
            else if (n == 0) w = "exit " rc
            if (w != "") printf "%s%s:%s", n ? ", " : "", s, w
            printf "\n"
        }' "$3"
}

t_start=$(now)

# -- baseline: the unmutated copy must pass --------------------------------
echo "mutate: $total mutation(s), baseline build and run of: $(echo $all_suites)"
fresh_tree || die "cannot copy the tree to $tree"
# shellcheck disable=SC2086
miss=$(build "$logs/baseline.build.log" $all_suites)
[ -z "$miss" ] || die "the unmutated tree does not build ${miss}(log $logs/baseline.build.log)"
: > "$ent/tmo"
for s in $all_suites; do
    t0=$(now)
    c=$(run_suite "$s" 3600 "$logs/baseline.$s.log")
    t1=$(now)
    [ -z "$c" ] || die "unmutated suite $s fails: $c (log $logs/baseline.$s.log)"
    echo "$s $(( (t1 - t0 + 1) * tfac + tadd ))" >> "$ent/tmo"
done

# -- the mutations ---------------------------------------------------------
: > "$ent/result"
k=0
tab=$(printf '\t')
while IFS="$tab" read -r id file suites desc surv; do
    k=$((k + 1))
    caught=""
    note=""
    fresh_tree || die "cannot copy the tree to $tree"
    if ! msg=$(awk -v pf="$ent/pairs/$id" -v out="$tree/$file.mut" '
        { txt = txt $0 "\n" }
        END {
            np = 0
            while ((getline f < pf) > 0) { getline r < pf; ++np
                c = 0; s = txt
                while ((i = index(s, f)) > 0) { ++c; s = substr(s, i + length(f)) }
                if (c != 1) { printf "find #%d occurs %d times in the header: %s", np, c, f; exit 1 }
                i = index(txt, f)
                txt = substr(txt, 1, i - 1) r substr(txt, i + length(f))
            }
            printf "%s", txt > out
        }' "$tree/$file"); then
        verdict=stale
        note=$msg
    else
        mv "$tree/$file.mut" "$tree/$file"
        # shellcheck disable=SC2086
        miss=$(build "$logs/$id.build.log" $suites)
        if [ -n "$miss" ]; then
            verdict=no-compile
            note="not built: ${miss}(log $logs/$id.build.log)"
        else
            for s in $suites; do
                tmo=$(awk -v s="$s" '$1 == s { print $2 }' "$ent/tmo")
                c=$(run_suite "$s" "$tmo" "$logs/$id.$s.log")
                [ -z "$c" ] || caught="${caught:+$caught, }$c"
            done
            if [ -n "$caught" ]; then
                verdict=killed
                [ -z "$surv" ] || { verdict="killed(!)"; note="listed as survivor (\"$surv\") but killed"; }
            elif [ -n "$surv" ]; then
                verdict="survived (explained)"
                note=$surv
            else
                verdict=SURVIVED
            fi
        fi
    fi
    printf '%s\t%s\t%s\t%s\t%s\n' "$id" "$desc" "$caught" "$verdict" "$note" >> "$ent/result"
    echo "[$k/$total] $id: $verdict${caught:+ by $caught}${note:+ -- $note}"
done < "$ent/sel"
t_end=$(now)

# -- report ------------------------------------------------------------------
awk -F'\t' -v secs=$((t_end - t_start)) '
function out(a, b, c, d,   s) { s = sprintf(fmt, a, b, c, d); sub(/ +$/, "", s); print s }
{ n++; I[n] = $1; Ds[n] = $2; C[n] = $3; V[n] = $4; N[n] = $5
  if (length($1) > wi) wi = length($1); if (length($2) > wd) wd = length($2)
  if (length($4) > wv) wv = length($4)
  if ($4 == "killed") kil++; else if ($4 == "SURVIVED") sur++
  else if ($4 ~ /^survived/) exp_++; else if ($4 == "no-compile") nc++
  else if ($4 == "stale") st++; else bad++ }
END {
  wc = 60
  if (wi < 2) wi = 2; if (wd < 11) wd = 11; if (wv < 7) wv = 7
  fmt = "%-" wi "s | %-" wd "s | %-" wc "s | %s"
  printf fmt "\n", "id", "description", "caught by", "verdict"
  line = ""; for (i = 0; i < wi + wd + wc + wv + 9; ++i) line = line "-"; print line
  for (r = 1; r <= n; ++r) {
    m = split(C[r], a, ", "); cell = ""; first = 1
    if (m == 0) cell = "-"
    for (j = 1; j <= m; ++j) {
      item = a[j] (j < m ? "," : "")
      if (cell != "" && length(cell) + 1 + length(item) > wc) {
        out(first ? I[r] : "", first ? Ds[r] : "", cell, first ? V[r] : "")
        first = 0; cell = item
      } else cell = cell (cell == "" ? "" : " ") item
    }
    out(first ? I[r] : "", first ? Ds[r] : "", cell, first ? V[r] : "")
  }
  print line
  for (r = 1; r <= n; ++r) if (N[r] != "") printf "note %s: %s\n", I[r], N[r]
  printf "mutate: %d mutations: %d killed, %d SURVIVED, %d survived (explained), %d no-compile, %d stale%s; %d s\n", \
    n, kil, sur, exp_, nc, st, bad ? ", " bad " explained survivors killed" : "", secs
}' "$ent/result" > "$work/report.txt"
echo
cat "$work/report.txt"
echo "mutate: report in $work/report.txt, logs in $logs/"
if awk -F'\t' '$4 != "killed" && $4 !~ /^survived/ { f = 1 } END { exit !f }' "$ent/result"; then
    exit 1
fi
exit 0
