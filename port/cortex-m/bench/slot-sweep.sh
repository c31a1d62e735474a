#!/bin/sh
# SPDX-License-Identifier: MIT
# README's slot sweep (issue 13): zl_draw_mesh without a caller vertex
# cache keeps recent window vertices in a direct-mapped cache of
# ZL_DRAW_CACHE_SLOTS entries in the draw cache the caller gives
# (zl_context.draw_cache, issue 23; the benchmark gives zl_draw_cache_bytes()).
# For each slot count this builds bench_frame_O2 (Cortex-M4, -O2) with
# -DZL_DRAW_CACHE_SLOTS=N, runs it under QEMU (exact instruction counts, as
# measure.sh) and prints the bunny frame's count next to the draw cache's
# bytes (ZL_DRAW_CACHE_BYTES(N) compiled for the target; 0 slots: no cache,
# the general path).
#
#   port/cortex-m/bench/slot-sweep.sh [BUILD_PREFIX]     (build/slots-N)
#
# tools/docs/refresh.py --slots BUILD_PREFIX puts the table in README.
set -eu
cd "$(dirname "$0")/../../.."
prefix=${1:-build/slots}
mkdir -p "$prefix-probe"

cache_bytes() { # cache_bytes N: ZL_DRAW_CACHE_BYTES(N) on the target (+ 1: no empty array)
    printf '#include "zline/zline.h"\nchar zl_probe[ZL_DRAW_CACHE_BYTES(ZL_DRAW_CACHE_SLOTS) + 1];\n' >"$prefix-probe/probe.c"
    arm-none-eabi-gcc -mcpu=cortex-m4 -mthumb -std=c99 -fno-common -Icore/include \
        -DZL_DRAW_CACHE_SLOTS="$1" -c -o "$prefix-probe/probe.o" "$prefix-probe/probe.c"
    size=$(arm-none-eabi-nm -S "$prefix-probe/probe.o" | awk '$4 == "zl_probe" { print $2 }')
    echo $((0x$size))
}

bunny_frame() { # bunny_frame N: the default call's bunny frame, instructions
    b=$prefix-$1
    # CFLAGS, not CMAKE_C_FLAGS: the latter would replace the toolchain's CPU flags.
    CFLAGS="-DZL_DRAW_CACHE_SLOTS=$1" cmake -S . -B "$b" -DCMAKE_TOOLCHAIN_FILE=port/cortex-m/toolchain-arm-none-eabi.cmake \
        -DZLINE_CPU=cortex-m4 -DCMAKE_BUILD_TYPE=Release >/dev/null
    cmake --build "$b" -j 2 --target bench_frame_O2 >/dev/null
    # The budget check fails for slot counts other than the default; only
    # the count is wanted here.
    ctest --test-dir "$b" -R '^bench_frame_O2_budgets$' -V 2>/dev/null |
        awk '$2 == "INTERVAL" && $4 == "bunny" && $5 == "total" { print $6 }'
}

base=$(cache_bytes 0)
echo "### Default zl_draw_mesh by cache slots (bunny, Cortex-M4 -O2)"
echo
echo "| slots | draw cache RAM (bytes) | bunny frame (instructions) |"
echo "|---:|---:|---:|"
for n in 0 256 512 1024 2048; do
    label=$n
    [ "$n" = 0 ] && label="0 (the general path for every triangle)"
    [ "$n" = 1024 ] && label="1024 (default)"
    count=$(bunny_frame "$n")
    [ -n "$count" ] || { echo "slot-sweep.sh: no bunny count from $prefix-$n" >&2; exit 1; }
    printf '| %s | %s | %s |\n' "$label" \
        "$(printf "%d" $(($(cache_bytes "$n") - base)) | sed ':a;s/\B[0-9]\{3\}\>/,&/;ta')" \
        "$(printf "%d" "$count" | sed ':a;s/\B[0-9]\{3\}\>/,&/;ta')"
done
