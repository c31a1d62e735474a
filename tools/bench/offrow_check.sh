#!/bin/sh
# SPDX-License-Identifier: MIT
# The claim of docs/MEASUREMENTS.md's "Per-row cost against triangles elsewhere": rendering
# rows 1..119 costs the same instructions whether or not 10000 more triangles
# lie below row 130 (callgrind, exact and repeatable). Fails when crowded
# costs more than base by over 0.1 %, or when either run fails (each run
# checks that every row was produced).
#   offrow_check.sh ZLINE_BENCH_OFFROW
set -eu
bench=$1
if ! command -v valgrind >/dev/null; then
    echo "SKIP: valgrind is needed (tools/setup-debian.sh installs it)"
    exit 0
fi
count() { # instructions inside render_top_rows for one scene
    out=$(mktemp)
    n=$(valgrind --tool=callgrind --callgrind-out-file="$out" --toggle-collect=render_top_rows "$bench" "$1" 2>&1 >/dev/null |
        awk '/Collected :/ { print $NF; exit }')
    rm -f "$out"
    echo "$n"
}
base=$(count base)
crowded=$(count crowded)
echo "rows 1..119: base $base, crowded $crowded instructions"
[ -n "$base" ] && [ -n "$crowded" ] || { echo "no instruction count (did a run fail?)"; exit 1; }
if [ "$crowded" -gt $((base + base / 1000)) ]; then
    echo "FAIL: the per-row cost grows with triangles on other rows"
    exit 1
fi
echo "per-row cost independent of triangles elsewhere"
