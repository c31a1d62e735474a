#!/bin/sh
# SPDX-License-Identifier: MIT
# Worst-case stack depth of zline's entry points, from GCC's call graph with
# per-function stack use (-fcallgraph-info=su), for a Cortex-M build of core/.
#   tools/stack/stack-bound.sh [CPU [LIMIT [PREFIX=LIMIT ...]]]
# Prints the deepest path in bytes of each function declared in
# core/include/zline/*.h; exits 1 if any
# exceeds LIMIT (bytes), if the graph has recursion, or if a function's stack
# use is dynamic. Calls into libgcc (64-bit division helpers) are leaves the
# graph cannot see into: each is charged LIBGCC_ALLOWANCE bytes.
# PREFIX=LIMIT arguments give the functions whose name starts with PREFIX
# their own limit (the longest matching prefix wins), e.g. zl_vis_=2560.
set -eu
cpu=${1:-cortex-m4}
limit=${2:-2048}
[ $# -ge 2 ] && shift 2 || shift $#
overrides="$*"
allowance=${LIBGCC_ALLOWANCE:-64}
top=$(cd "$(dirname "$0")/../.." && pwd)
cc=${ARM_GCC:-arm-none-eabi-gcc}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for f in "$top"/core/src/*/*.c; do
    "$cc" -mcpu="$cpu" -mthumb -mfloat-abi=soft -O2 -std=c99 -I"$top/core/include" \
        -fcallgraph-info=su -c "$f" -o "$work/$(basename "$f" .c).o" -dumpdir "$work/"
done
# Entry points: every function the public headers declare (so new API is
# covered as it is added); inline helpers have no node and are skipped.
entries=$(sed -n 's/^[a-z_0-9 ]*[ *]\(zl_[a-z0-9_]*\)(.*/\1/p' "$top"/core/include/zline/*.h | sort -u | tr '\n' ' ')
cat "$work"/*.ci | awk -v limit="$limit" -v allowance="$allowance" -v entry_list="$entries" -v overrides="$overrides" '
function title(s) { sub(/^.*title: "/, "", s); sub(/".*$/, "", s); return s }
function field(s, name) { sub("^.*" name ": \"", "", s); sub(/".*$/, "", s); return s }
function bare(t) { sub(/^.*:/, "", t); return t }
/^node:/ {
    t = title($0)
    if (match($0, /[0-9]+ bytes \((static|dynamic[^)]*)\)/)) {
        s = substr($0, RSTART, RLENGTH)
        if (s ~ /dynamic/) dynamic[t] = 1
        split(s, parts, " "); stack[t] = parts[1] + 0; defined[t] = 1
    }
    next
}
/^edge:/ { src = field($0, "sourcename"); dst = field($0, "targetname"); calls[src] = calls[src] " " dst; next }
function resolve(t) { return (t in defined) ? t : ((bare(t) in defined) ? bare(t) : "") }
function worst(t,    r, n, i, c, w, best, list) {
    r = resolve(t)
    if (r == "") { if (t ~ /^__/) return allowance; return 0 }
    if (r in memo) return memo[r]
    if (r in onstack) { print "recursion through " r; bad = 1; return 0 }
    if (r in dynamic) { print "dynamic stack in " r; bad = 1 }
    onstack[r] = 1; best = 0; deepest[r] = ""
    n = split(calls[r], list, " ")
    for (i = 1; i <= n; i++) { w = worst(list[i]); if (w > best) { best = w; deepest[r] = resolve(list[i]) } }
    delete onstack[r]
    memo[r] = stack[r] + best
    return memo[r]
}
function path(t,    s) { s = bare(t); while (deepest[t] != "") { t = deepest[t]; s = s " > " bare(t) } return s }
END {
    n = split(entry_list, entries, " ")
    no = split(overrides, ov, " ")
    printf "| entry point | worst stack (bytes) | limit | deepest path |\n|---|---:|---:|---|\n"
    for (i = 1; i <= n; i++) {
        if (!(entries[i] in defined)) continue
        w = worst(entries[i])
        lim = limit; best = 0
        for (j = 1; j <= no; j++) {
            split(ov[j], kv, "=")
            if (index(entries[i], kv[1]) == 1 && length(kv[1]) > best) { best = length(kv[1]); lim = kv[2] + 0 }
        }
        printf "| %s | %d | %d | %s |\n", entries[i], w, lim, path(entries[i])
        if (w > lim) { print "over the limit of " lim " bytes: " entries[i]; bad = 1 }
    }
    exit bad
}'
