# SPDX-License-Identifier: Apache-2.0
# Stack bound of every function in a disassembled Arm library (libgcc.a), for
# the compiler helpers the core calls (__aeabi_uldivmod, __aeabi_lmul, ...).
#
#   arm-none-eabi-objdump -dt libgcc.a | awk -f tools/firmware/helpers.awk > helpers.txt
#
# Output: one line "name bytes" per function. A function's own frame is
# bounded by the sum of everything it ever pushes (push/stmdb sp!/sub sp/
# stores with [sp, #-N]! write-back, all
# branches added up, pops ignored), and its bound is that frame plus the
# largest bound of the functions it calls (bl) or tail-branches to (b to
# another function). Recursion is reported as -1 (no bound).
function regs(list,    n, i, parts, a, b) {
    gsub(/[{} ]/, "", list)
    n = split(list, parts, ",")
    for (i = 1; i <= n; i++) {
        if (parts[i] ~ /^[rds][0-9]+-[rds][0-9]+$/) {
            split(parts[i], a, "-"); sub(/^[rds]/, "", a[1]); sub(/^[rds]/, "", a[2])
            n += a[2] - a[1]
        }
    }
    return n
}
# Symbol tables (-t) name the aliases a disassembly label hides
# (__aeabi_uidiv is __udivsi3): same object, section and address.
/file format/ { obj = $1; f = ""; next }
/^Disassembly of section / { sec = $4; sub(/:$/, "", sec); next }
/^[0-9a-f]+ .*\t[0-9a-f]+ .+$/ {
    split($0, half, "\t"); ns = split(half[1], w, " "); nv = split(half[2], v, " ")
    nsym++; sym_name[nsym] = v[nv]; sym_key[nsym] = obj SUBSEP w[ns] SUBSEP $1
    next
}
/^[0-9a-f]+ <[^>]+>:$/ {
    f = $2; gsub(/[<>:]/, "", f); frame[f] += 0
    label[obj SUBSEP sec SUBSEP $1] = f
    next
}
f == "" { next }
/\t(push|push\.w|stmdb(\.w)?)\t/ {
    if ($0 ~ /\tstmdb/ && $0 !~ /sp!/) next
    l = $0; sub(/.*\{/, "{", l); sub(/\}.*/, "}", l)
    frame[f] += 4 * regs(l); next
}
/\tvpush\t/ {
    l = $0; sub(/.*\{/, "{", l); sub(/\}.*/, "}", l)
    frame[f] += ((l ~ /d[0-9]/) ? 8 : 4) * regs(l); next
}
/\[sp, #-[0-9]+\]!/ {
    # pre-indexed store with write-back (e.g. strd ip, lr, [sp, #-16]!)
    l = $0; sub(/.*\[sp, #-/, "", l); sub(/\].*/, "", l); frame[f] += l + 0; next
}
/\tsub(\.w|w)?\tsp, / {
    l = $0; sub(/.*#/, "", l); frame[f] += l + 0; next
}
/\t(bl|blx|b|b\.w|b\.n)\t[0-9a-f]+ <[^>+]+>/ {
    t = $0; sub(/.*</, "", t); sub(/>.*/, "", t)
    if (t != f) { ncall[f]++; callee[f, ncall[f]] = t }
}
function depth(g,    i, d, best) {
    if (g in memo) return memo[g]
    if (g in onpath) return -1
    onpath[g] = 1; best = 0
    for (i = 1; i <= ncall[g]; i++) {
        d = (callee[g, i] in frame) ? depth(callee[g, i]) : 0
        if (d < 0) { delete onpath[g]; memo[g] = -1; return -1 }
        if (d > best) best = d
    }
    delete onpath[g]
    memo[g] = frame[g] + best
    return memo[g]
}
END {
    for (g in frame) print g, depth(g)
    for (i = 1; i <= nsym; i++)
        if (!(sym_name[i] in frame) && (sym_key[i] in label))
            print sym_name[i], depth(label[sym_key[i]])
}
