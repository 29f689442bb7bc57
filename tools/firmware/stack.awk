# SPDX-License-Identifier: Apache-2.0
# Worst-case stack depth of every public entry point (symline_*) of the core,
# from GCC's call-graph files (-fcallgraph-info=su, one .ci per object).
#
#   awk -v budget=512 -f tools/firmware/stack.awk HELPERS.txt build/.../*.ci
#
# Each function's own frame comes from -fstack-usage; the worst case of a
# function is its frame plus the worst case of anything it calls. Calls to
# compiler helpers (libgcc: __aeabi_uldivmod, ...) are charged the bound in
# HELPERS.txt ("name bytes" lines, made by helpers.awk from the disassembly of
# the libgcc.a the target links). The result is a failure (exit 1) when any
# entry point exceeds `budget`, when a frame is dynamic (alloca/VLA), when
# there is recursion or an indirect call, or when a call leaves the core for
# anything but a helper with a known bound.
function strip(s) { gsub(/^"|"$/, "", s); return s }
function field(line, key,    i, rest) {
    i = index(line, key ": \"")
    if (i == 0) return ""
    rest = substr(line, i + length(key) + 3)
    return substr(rest, 1, index(rest, "\"") - 1)
}
FNR == NR && FILENAME ~ /\.txt$/ { hb[$1] = $2; next }
/^node:/ {
    t = field($0, "title"); l = field($0, "label")
    if (l ~ /bytes \(/) {
        n = l; sub(/ bytes \(.*/, "", n); sub(/.*\\n/, "", n)
        kind = l; sub(/.*bytes \(/, "", kind); sub(/\).*/, "", kind)
        frame[t] = n + 0; defined[t] = 1
        if (kind != "static") dyn[t] = kind
        name = l; sub(/\\n.*/, "", name); shown[t] = name
    }
    next
}
/^edge:/ {
    s = field($0, "sourcename"); d = field($0, "targetname")
    key = s SUBSEP d
    if (!(key in seen)) { seen[key] = 1; ncall[s]++; callee[s, ncall[s]] = d }
    next
}
function depth(f,    i, c, w, best, bc) {
    if (f in memo) return memo[f]
    if (f in onpath) { problem["recursion through " f] = 1; return 0 }
    if (!(f in defined)) {
        if ((f in hb) && hb[f] >= 0) { shown[f] = f " (" hb[f] " B)"; return hb[f] }
        problem["call outside the core: " f] = 1
        return 0
    }
    if (f in dyn) problem["dynamic stack frame (" dyn[f] ") in " shown[f]] = 1
    onpath[f] = 1
    best = 0; bc = ""
    for (i = 1; i <= ncall[f]; i++) {
        c = callee[f, i]
        w = depth(c)
        if (w > best) { best = w; bc = c }
    }
    delete onpath[f]
    memo[f] = frame[f] + best
    via[f] = bc
    return memo[f]
}
function chain(f,    s) {
    s = (f in shown) ? shown[f] : f
    if (f in via && via[f] != "") s = s " > " chain(via[f])
    return s
}
END {
    if (budget == "") budget = 512
    fail = 0; count = 0
    for (f in defined) if (f ~ /^symline_/ && f !~ /^symline_i_/ && f !~ /:/) entry[++count] = f
    # sort entry points by name (insertion sort: no gawk extensions)
    for (i = 2; i <= count; i++) {
        v = entry[i]; j = i - 1
        while (j >= 1 && entry[j] > v) { entry[j + 1] = entry[j]; j-- }
        entry[j + 1] = v
    }
    worst = 0
    for (i = 1; i <= count; i++) {
        f = entry[i]; d = depth(f)
        mark = (d > budget) ? "OVER" : "ok"
        if (d > budget) fail = 1
        if (d > worst) worst = d
        printf "  %-40s %5d B  %-4s %s\n", f, d, mark, chain(f)
    }
    for (p in problem) { printf "  problem: %s\n", p; fail = 1 }
    if (count == 0) { print "  problem: no symline_* function found in the call graph"; fail = 1 }
    printf "  worst entry point: %d B (budget %d B, %d public functions)\n", worst, budget, count
    exit fail
}
