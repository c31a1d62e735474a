#!/bin/sh
# SPDX-License-Identifier: MIT
# The visibility trade-off numbers of docs/VISIBILITY.md, all from one command:
#   tools/visbench/measure.sh [BUILD_DIR] [MODEL_DIR]
# RAM and agreement with the ray caster from zline-visbench; instructions per
# frame on the host counted by callgrind inside vb_measured() (one frame:
# planning, clear and drawing; exact and repeatable for the same binary).
set -eu
build=${1:-build}
models=${2:-../shared/models}
vb=$build/tools/visbench/zline-visbench
command -v valgrind >/dev/null || { echo "measure.sh: valgrind is needed" >&2; exit 2; }
count() { # count SCENE METHOD
    out=$(mktemp)
    valgrind --tool=callgrind --callgrind-out-file="$out" --toggle-collect=vb_measured "$vb" "$models" --only "$1" "$2" 2>&1 >/dev/null |
        awk '/Collected :/ { print $NF; exit }'
    rm -f "$out"
}
echo "### RAM and agreement with the ray caster (320x240)"
echo
"$vb" "$models"
echo
echo "### Instructions per frame on the host, per visibility method (x86-64, callgrind)"
echo
echo "| method | bunny | spider | intersect | layers |"
echo "|---|---:|---:|---:|---:|"
for m in zbuffer scanline band16 aet painter bsp-b2f bsp-f2b raycast; do
    printf "| %s |" "$m"
    for s in bunny spider intersect layers; do
        printf " %s |" "$(count $s $m)"
    done
    echo
done
