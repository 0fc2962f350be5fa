#!/bin/sh
# doc_blocks.sh -- every ```c block of README.md and docs/*.md compiled
# (make check-docs, part of make test), the relative links of those pages
# and the vlbe_ / VLBE_ / svgp_ names they quote checked.
#
#   sh tests/doc_blocks.sh           check (from the repository root)
#   sh tests/doc_blocks.sh --sync    rewrite the blocks that mirror a file
#                                    (see 1.) from that file, then check
#
# A block is one of three kinds:
#   1. a mirror: the line before its fence (blank lines aside) is
#      <!-- name.c --> and the block is examples/name.c verbatim; that file
#      is compiled (its includes are relative to examples/), unless its name
#      is in MIRRORS_BUILT (a target of its own builds and runs it with the
#      same flags: make check-first for first_chain.c).  A mirror whose
#      file does not exist yet must be the one line /* examples/name.c */
#      and is reported as waiting for it;
#   2. a fragment: its first line names the program it is part of,
#      docs/snippets/<x>.c, which includes it with `#include DOC_BLOCK`;
#      that program is compiled with the block in place;
#   3. a program: it has main() and is compiled as it is.
# Anything else fails: a piece of C that is not compiled has no place in a
# c fence (shell, tables and output take other fences).  Each program is
# compiled and linked twice, double and -DVLBE_USE_FLOAT, with the
# project's warnings (CC, CSTD, WARN from the Makefile), -O2, -I. and -lm.
# Links: every [text](target) and ![alt](target) whose target is not a URL
# must name an existing file relative to its page, and an anchor (#...) a
# heading of that file.
# Names: every vlbe_*, VLBE_*, svgp_*, SVGP_* identifier on the pages must
# occur in the sources (*.h, *.c, Makefile).
set -u
CC=${CC:-cc}
CSTD=${CSTD:--std=c99}
WARN=${WARN:--Wall -Wextra -Wpedantic -Wshadow -Wstrict-prototypes -Wmissing-prototypes -Wcast-qual -Wvla -Wdouble-promotion -Wfloat-conversion -Werror}
BUILD=${BUILD:-build}
OUT=$BUILD/docs
PAGES="README.md $(ls docs/*.md 2>/dev/null)"
sync=0
[ "${1:-}" = "--sync" ] && sync=1

[ -f README.md ] || { echo "doc_blocks.sh: run from the repository root" >&2; exit 2; }
rm -rf "$OUT"
mkdir -p "$OUT"
fail=0

# -- 1. mirrors rewritten from their files (--sync) -------------------------
if [ $sync = 1 ]; then
    for p in $PAGES; do
        awk -v dir=examples '
            function flush_marker(l) { if (l ~ /^<!-- [A-Za-z0-9_]+\.c -->$/) { m = l; sub(/^<!-- /, "", m); sub(/ -->$/, "", m) } else if (l != "") m = "" }
            skip { if ($0 == "```") { skip = 0; print } ; next }
            /^```c$/ && m != "" && (getline tst < (dir "/" m)) > 0 {
                print; print tst; while ((getline l < (dir "/" m)) > 0) print l; close(dir "/" m)
                skip = 1; m = ""; next }
            { flush_marker($0); print }' "$p" > "$OUT/sync.tmp" || exit 2
        if ! cmp -s "$p" "$OUT/sync.tmp"; then cp "$OUT/sync.tmp" "$p"; echo "doc_blocks: $p: mirrors rewritten"; fi
    done
fi

# -- blocks -----------------------------------------------------------------
# manifest lines: <block file>|<page>|<line>|<mirror name or empty>
for p in $PAGES; do
    tag=$(echo "$p" | sed 's/[^A-Za-z0-9]/_/g')
    awk -v out="$OUT" -v tag="$tag" -v page="$p" '
        inb && $0 == "```" { inb = 0; close(f); next }
        inb { print > f; next }
        /^```c$/ { ++k; f = out "/" tag "_" k ".c"; inb = 1; printf "" > f
                   print f "|" page "|" NR "|" m >> (out "/manifest"); m = ""; next }
        /^<!-- [A-Za-z0-9_]+\.c -->$/ { m = $0; sub(/^<!-- /, "", m); sub(/ -->$/, "", m); next }
        $0 != "" { m = "" }
        END { if (inb) { print page ": a ```c block is not closed" > "/dev/stderr"; exit 1 } }' "$p" || fail=1
done

# compile <what> <source> [extra flags]: double and float, -O2, linked
compile() {
    what=$1; src=$2; shift 2
    for cfg in dbl flt; do
        def=""; [ $cfg = flt ] && def=-DVLBE_USE_FLOAT
        bin=$OUT/$(basename "$src" .c)_$cfg
        # shellcheck disable=SC2086
        if ! $CC $CSTD $WARN -O2 $def -I. "$@" "$src" -o "$bin" -lm 2> "$bin.err"; then
            echo "FAILED: $what ($cfg): $CC $CSTD ... $def -I. $* $src -lm"; sed 's/^/    /' "$bin.err"; fail=1
            return
        fi
    done
    echo "doc_blocks: $what: compiled and linked, double and float"
}

nb=0
if [ -f "$OUT/manifest" ]; then
    while IFS='|' read -r blk page line mirror; do
        nb=$((nb + 1))
        at="$page:$line"
        first=$(sed -n 1p "$blk")
        if [ -n "$mirror" ]; then
            src=examples/$mirror
            if [ -f "$src" ]; then
                if ! cmp -s "$blk" "$src"; then :
                elif [ -n "${MIRRORS_BUILT-}" ] && case " $MIRRORS_BUILT " in *" $mirror "*) true;; *) false;; esac; then
                    echo "doc_blocks: $at: examples/$mirror verbatim (compiled by its own target)"
                else compile "$at (examples/$mirror)" "$src"; fi
                if cmp -s "$blk" "$src"; then :
                else echo "FAILED: $at: the block is not examples/$mirror verbatim (sh tests/doc_blocks.sh --sync)"; fail=1; fi
            elif [ "$first" = "/* examples/$mirror */" ] && [ "$(wc -l < "$blk")" -eq 1 ]; then
                echo "doc_blocks: $at: waiting for examples/$mirror (placeholder block)"
            else
                echo "FAILED: $at: mirror of examples/$mirror, which does not exist"; fail=1
            fi
            continue
        fi
        ctx=$(printf '%s\n' "$first" | sed -n 's|^/\*.*\(docs/snippets/[A-Za-z0-9_]*\.c\).*\*/$|\1|p')
        if [ -n "$ctx" ]; then
            if [ ! -f "$ctx" ]; then echo "FAILED: $at: $ctx does not exist"; fail=1; continue; fi
            if ! grep -q '^#include DOC_BLOCK' "$ctx"; then echo "FAILED: $ctx has no #include DOC_BLOCK"; fail=1; continue; fi
            cp "$blk" "$blk.inc"
            compile "$at (in $ctx)" "$ctx" -DDOC_BLOCK="\"$(pwd)/$blk.inc\""
        elif grep -q '\bmain *(' "$blk"; then
            compile "$at" "$blk"
        else
            echo "FAILED: $at: a fragment whose first line names no docs/snippets/*.c, and no main()"; fail=1
        fi
    done < "$OUT/manifest"
fi

# -- links --------------------------------------------------------------------
# anchors: GitHub's rule for headings in ASCII (lower case, punctuation but
# - and _ dropped, spaces to -); non-ASCII characters are dropped, which is
# right for the dashes and arrows of these headings, not for letters
slugs() { sed -n 's/^#\{1,6\} \{1,\}//p' "$1" | LC_ALL=C tr 'A-Z' 'a-z' | LC_ALL=C sed 's/[^a-z0-9 _-]//g; s/ /-/g'; }
nl=0
for p in $PAGES; do
    d=$(dirname "$p")
    for t in $(grep -o '](\([^) ]*\))' "$p" | sed 's/^](//; s/)$//' | grep -v -E '^(https?:|mailto:)'); do
        nl=$((nl + 1))
        file=${t%%#*}; anchor=""
        case $t in *'#'*) anchor=${t#*#};; esac
        if [ -z "$file" ]; then file=$p; else file=$d/$file; fi
        if [ ! -e "$file" ]; then echo "FAILED: $p: link to $t: no such file ($file)"; fail=1; continue; fi
        if [ -n "$anchor" ] && ! slugs "$file" | grep -q -x -F -- "$anchor"; then
            echo "FAILED: $p: link to $t: no heading with that anchor in $file"; fail=1
        fi
    done
done

# -- names ------------------------------------------------------------------
# (a name followed by _* or * is a family: vlbe_ale_*, not checked)
NAME_RE='\b(vlbe|VLBE|svgp|SVGP)_[A-Za-z0-9_]*[*]?'
find . -path ./build -prune -o -path ./out -prune -o \( -name '*.h' -o -name '*.c' -o -name Makefile \) -type f -print |
    xargs grep -h -o -E "$NAME_RE" | sed "s/[*]$//" | sort -u > "$OUT/names.src"
# shellcheck disable=SC2086
grep -h -o -E "$NAME_RE" $PAGES | grep -v '[_*]$' | sort -u > "$OUT/names.doc"
comm -23 "$OUT/names.doc" "$OUT/names.src" > "$OUT/names.missing"
if [ -s "$OUT/names.missing" ]; then
    echo "FAILED: names on the pages that no source has:"; sed 's/^/    /' "$OUT/names.missing"
    for n in $(cat "$OUT/names.missing"); do grep -n -w -- "$n" $PAGES | head -3 | sed 's/^/      /'; done
    fail=1
fi

echo "doc_blocks: $nb c blocks, $nl links, $(wc -l < "$OUT/names.doc") names on $(echo $PAGES | wc -w) pages: $([ $fail = 0 ] && echo ok || echo FAILED)"
exit $fail
