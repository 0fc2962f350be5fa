# stack.awk -- worst-case stack of every public vlbe function from gcc's own
# reports: reads the call graph that -fcallgraph-info=su writes (a .ci
# file, VCG format: one node per function with its frame "N bytes
# (static|dynamic...)", one edge per call) and prints one Markdown row per
# public function (a name without the private vlbe__ prefix):
#   | header | function | stack [B] | own [B] | limit [B] | deepest call chain | note |
# stack = own frame + the deepest chain of callees through the graph.
# Calls out of the unit (libc, libm: sqrtf, memset, ...) count 0; an
# indirect call (a user callback: the vlbe_dae functions called by the
# integrators, the element types and prescribed motions of chains and
# beams) counts 0 and is noted "+ callbacks": they add their own stack.
# Recursion is found (a call back into a function on the current path),
# reported as "recursive (f)", and its frames are counted once: the
# figure is then per level, not a bound.  Rows are sorted by header (in
# the order of -v headers="vlbe.h ...") then by function.
# Limits: 1024 B, 2048 B for element kernels (functions matching -v
# kernel_re but not -v system_re), or the figure of the function's line in
# the exceptions file (-v exceptions=FILE: "name bytes reason", # comments).
# A function above its limit is an offender, and so is a recursive one
# that the exceptions file does not list (its line then bounds the
# figure per level); the exit status is 1 when there is an offender or a
# dynamic frame (alloca, VLA).  gcc clones (f.part.0, f.isra.0) are
# counted in their callers, not listed.
# -- part of vlbe                                  SPDX-License-Identifier: MIT
#   awk -v headers="vlbe.h ancf_ale.h" -v kernel_re=RE -v system_re=RE \
#       -v exceptions=FILE -f stack.awk all.ci

function label_field(s, k,    a, n) {     # k-th "\n"-separated field of a label
    n = split(s, a, /\\n/)
    return k <= n ? a[k] : ""
}

# worst stack of f; fills best[f] (callee on the deepest path), rec[f]
# (a function of a cycle below f), ind[f] (an indirect call below f)
function walk(f,    i, c, w, m, b) {
    if (f in done) return ws[f]
    if (onpath[f]) {                     # back edge: recursion
        cyc = f
        return 0
    }
    onpath[f] = 1
    m = 0; b = ""
    for (i = 1; i <= ncall[f]; ++i) {
        c = callee[f, i]
        if (c == "__indirect_call") { ind[f] = 1; continue }
        cyc = ""
        w = walk(c)
        if (cyc != "" && rec[f] == "") rec[f] = cyc
        if (rec[c] != "" && rec[f] == "") rec[f] = rec[c]
        if (ind[c]) ind[f] = 1
        if (w > m) { m = w; b = c }
    }
    onpath[f] = 0
    done[f] = 1
    best[f] = b
    ws[f] = own[f] + m
    return ws[f]
}

function chain(f,    s, k) {
    s = name[f]; k = 0
    while (best[f] != "" && k < 4) { f = best[f]; s = s " > " name[f]; ++k }
    if (best[f] != "") s = s " > ..."
    return s
}

BEGIN {
    nh = split(headers, hlist, " ")
    for (i = 1; i <= nh; ++i) hrank[hlist[i]] = i
    if (exceptions != "") {
        while ((getline line < exceptions) > 0) {
            if (line ~ /^[ \t]*(#|$)/) continue
            split(line, a, " ")
            exc[a[1]] = a[2] + 0
        }
        close(exceptions)
    }
}

/^node: / {
    t = $0; sub(/.*title: "/, "", t); sub(/".*/, "", t)
    l = $0; sub(/.*label: "/, "", l); sub(/".*/, "", l)
    name[t] = label_field(l, 1)
    if (l ~ / bytes \(/) {                # a function of this unit
        loc = label_field(l, 2); sz = label_field(l, 3)
        hdr = loc; sub(/:.*/, "", hdr); sub(/.*\//, "", hdr)
        header[t] = hdr
        own[t] = sz + 0
        q = sz; sub(/.*\(/, "", q); sub(/\).*/, "", q)
        if (q != "static") dyn[t] = q
        defined[t] = 1
    } else own[t] = 0                     # libc, libm, builtins: 0
}
/^edge: / {
    s = $0; sub(/.*sourcename: "/, "", s); sub(/".*/, "", s)
    d = $0; sub(/.*targetname: "/, "", d); sub(/".*/, "", d)
    if (!((s, d) in seen)) { seen[s, d] = 1; callee[s, ++ncall[s]] = d }
}

END {
    n = 0
    for (t in defined) {
        if (name[t] ~ /^vlbe__/ || name[t] ~ /\./) continue   # private, or a gcc clone (.part.0, .isra.0)
        walk(t)
        key[++n] = sprintf("%03d %s", (header[t] in hrank) ? hrank[header[t]] : 999, name[t])
        id[key[n]] = t
    }
    for (i = 2; i <= n; ++i) {            # insertion sort of the keys
        k = key[i]
        for (j = i - 1; j >= 1 && key[j] > k; --j) key[j + 1] = key[j]
        key[j + 1] = k
    }
    print "| header | function | stack [B] | own [B] | limit [B] | deepest call chain | note |"
    print "|---|---|---:|---:|---:|---|---|"
    bad = 0; noff = 0; nexc = 0
    for (i = 1; i <= n; ++i) {
        t = id[key[i]]; f = name[t]
        lim = 1024
        if (f ~ kernel_re && f !~ system_re) lim = 2048
        note = ""
        if (f in exc) {
            note = "exception"
            if (ws[t] <= lim && rec[t] == "") note = "exception no longer needed"
            lim = exc[f]
            ++nexc
        }
        if (ind[t]) note = note (note != "" ? ", " : "") "+ callbacks"
        if (rec[t] != "") {
            note = note (note != "" ? ", " : "") "recursive (" name[rec[t]] "): per level"
            if (!(f in exc)) { off[++noff] = f " " ws[t] " (recursive)"; ++bad }
        }
        if (t in dyn) { note = note (note != "" ? ", " : "") "dynamic frame (" dyn[t] ")"; ++bad }
        if (ws[t] > lim) {
            note = note (note != "" ? ", " : "") "OVER LIMIT"
            off[++noff] = f " " ws[t]
            ++bad
        }
        printf "| %s | %s | %d | %d | %d | %s | %s |\n", header[t], f, ws[t], own[t], lim, chain(t), note
    }
    printf "stack: %d public functions, %d listed in the exceptions file, %d over their limit\n", n, nexc, noff > "/dev/stderr"
    for (i = 1; i <= noff; ++i) print "stack: over the limit: " off[i] > "/dev/stderr"
    exit bad ? 1 : 0
}
