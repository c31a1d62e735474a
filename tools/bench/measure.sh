#!/bin/sh
# SPDX-License-Identifier: MIT
# Host measurements quoted in docs/MEASUREMENTS.md (scanline mode, issue #3): RAM per mode
# from the library's size function, and instructions per frame counted by
# callgrind (exact and repeatable for the same binary and inputs).
#   tools/bench/measure.sh [BUILD_DIR] [MODEL]
set -eu
build=${1:-build}
model=${2:-port/host/models/bunny.obj}
bench=$build/tools/bench
command -v valgrind >/dev/null || { echo "measure.sh: valgrind is needed (apt-get install valgrind)" >&2; exit 2; }

count() { # count FUNCTION COMMAND...: instructions executed inside FUNCTION
    fn=$1; shift
    out=$(mktemp)
    valgrind --tool=callgrind --callgrind-out-file="$out" --toggle-collect="$fn" "$@" 2>&1 >/dev/null |
        awk '/Collected :/ { print $NF; exit }'
    rm -f "$out"
}

echo "### RAM, benchmark scene (bunny, 320x240, RGB565)"
echo
"$bench/zline-bench-modes" "$model"
echo
echo "### Instructions per frame on the host (x86-64, callgrind)"
echo
echo "| mode | instructions per frame |"
echo "|---|---:|"
echo "| frame (zl_draw_mesh, the default call: no caller vertex cache; clear included) | $(count render_frame_once "$bench/zline-bench-modes" "$model" --only frame) |"
for m in scanline band=8 band=60 band=240; do
    echo "| $m | $(count render_once "$bench/zline-bench-modes" "$model" --only $m) |"
done
echo
echo "### Host time per frame (bunny, 320x240 RGB565, clear included)"
echo
"$bench/zline-bench-time" "$model" 2001
echo
echo "### Per-row cost against triangles elsewhere (scanline mode, rows 1..119)"
echo
base=$(count render_top_rows "$bench/zline-bench-offrow" base)
crowded=$(count render_top_rows "$bench/zline-bench-offrow" crowded)
echo "| scene | triangles | instructions for rows 1..119 |"
echo "|---|---:|---:|"
echo "| base | 1000 | $base |"
echo "| crowded (10000 more below row 130) | 11000 | $crowded |"
echo
echo "ratio crowded/base: $(awk -v a="$crowded" -v b="$base" 'BEGIN { printf "%.4f", a / b }')"
