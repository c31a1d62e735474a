#!/bin/sh
# SPDX-License-Identifier: MIT
# Cortex-M0 benchmark tables (issue 13; README's Cortex-M0 table): builds the
# benchmark firmware of a ZLINE_CPU=cortex-m0 build at -O2 (bench_frame_O2,
# bench_scanline_O2, bench_features_O2), runs each under QEMU's microbit
# board with its memory enlarged (port/cortex-m/qemu.cmake) and -icount
# shift=7 (exact instruction counts from the nRF51 TIMER0, see
# bench_timer_nrf51.c) and prints markdown tables. When the host compiler can
# build tools/qemu-m4-timing's plugin, the plugin's own instruction count of
# every interval is compared with the timer's (its cycle estimate is a
# Cortex-M4 model and is not used here).
#
#   port/cortex-m/bench/measure-m0.sh [--update-budgets [--allow-raise REASON]] [BUILD_DIR]
#
# BUILD_DIR defaults to build/cortex-m0-bench. --update-budgets rewrites
# budgets-m0.txt from this measurement (+3 %, rounded up to 1000) under the
# rules of budgets.txt (update-budgets.sh: only lowers unless --allow-raise).
set -eu
cd "$(dirname "$0")/../../.."
update=0
raise_reason=
if [ "${1:-}" = --update-budgets ]; then
    update=1; shift
    if [ "${1:-}" = --allow-raise ]; then
        [ -n "${2:-}" ] || { echo "measure-m0.sh: --allow-raise needs a REASON" >&2; exit 2; }
        raise_reason=$2; shift 2
    fi
fi
build=${1:-build/cortex-m0-bench}
bench=$build/port/cortex-m/bench
out=$build/measure-m0
budgets=port/cortex-m/bench/budgets-m0.txt
mkdir -p "$out"

# ZLINE_CONFIG (environment): the library's zl_config.h macros, as CMake's
# ZLINE_CONFIG takes them (e.g. the flash table's minimal-small speed:
# ZLINE_CONFIG="ZL_SMALL_TRIANGLE_SETUP=0;ZL_FAST_SPANS=0;ZL_DRAW_CACHE_SLOTS=0"
# with a build folder of its own; the budgets are the default build's).
cmake -S . -B "$build" -DCMAKE_TOOLCHAIN_FILE=port/cortex-m/toolchain-arm-none-eabi.cmake \
    -DZLINE_CPU=cortex-m0 -DCMAKE_BUILD_TYPE=Release "-DZLINE_CONFIG=${ZLINE_CONFIG:-}" >/dev/null
cmake --build "$build" -j 2 --target bench_frame_O2 bench_scanline_O2 bench_features_O2 >/dev/null

plugin=$out/m4timing.so
if ! ${CC:-cc} -std=c99 -O2 -shared -fPIC -o "$plugin" tools/qemu-m4-timing/m4timing.c 2>"$out/plugin.log"; then
    echo "measure-m0.sh: cannot build the plugin (see $out/plugin.log): no cross-check of the counts" >&2
    plugin=
fi
# A first measurement: the firmware prints BUDGET_SUGGEST only with a file.
if [ $update -eq 1 ] && [ ! -f "$budgets" ]; then echo "# (being measured)" >"$budgets"; fi

tags="frame-O2 scanline-O2 features-O2"
status=0
for tag in $tags; do
    elf=$bench/bench_${tag%-*}_${tag#*-}.elf
    mark=$(arm-none-eabi-nm "$elf" | awk '$3 == "mark" { print "0x" $1 }')
    rm -f "$out/$tag.marks"
    set -- qemu-system-arm -M microbit -global nrf51-soc.flash-size=4194304 -global nrf51-soc.sram-size=4194304 \
        -nographic -monitor none -serial none \
        -chardev stdio,id=semi -semihosting-config enable=on,target=native,chardev=semi -icount shift=7
    if [ -n "$plugin" ]; then
        set -- "$@" -plugin "$plugin,mark=$mark,out=$out/$tag.marks"
    fi
    "$@" -kernel "$elf" >"$out/$tag.txt" || status=1
done
[ $status -eq 0 ] || echo "measure-m0.sh: a benchmark reported a failure (BUDGET FAIL?): see $out/*.txt" >&2

if [ $update -eq 1 ]; then
    cat "$out"/*.txt | awk '$1 == "BUDGET_SUGGEST" { print $2, $3, $4 }' | sort >"$out/suggest.txt"
    sh port/cortex-m/bench/update-budgets.sh "$budgets" "$out/suggest.txt" "$raise_reason" >"$out/budgets.txt"
    cp "$out/budgets.txt" "$budgets"
    echo "measure-m0.sh: $budgets updated" >&2
fi

# All results as "tag scene key value" lines; with the plugin, an interval
# whose plugin count (marks difference less n empty intervals plus n - 1
# timer overheads, as measure.sh) differs from the timer's is reported.
for tag in frame-O2 scanline-O2; do
    awk -v tag="$tag" -v marks="$out/$tag.marks" '
        BEGIN { while ((getline l < marks) > 0) { split(l, f, " "); if (f[1] == "MARK") mi[f[2]] = f[3] } }
        /^# timer:/ { for (i = 1; i <= NF; i++) if ($i == "overhead") ov = $(i + 1) }
        $1 == "RESULT" { print tag, $3, $4, $5 }
        $1 == "INTERVAL" {
            print tag, $3, $4, $5
            if ((0 in mi) && ($6 in mi) && ($7 in mi)) {
                n = $7 - $6; pi = mi[$7] - mi[$6] - n * (mi[1] - mi[0]) + (n - 1) * ov
                checked++
                if (pi != $5) print tag, $3, $4 "_plugin_insn_mismatch", pi - $5
            }
        }
        END { print tag, "-", "plugin_checked", checked + 0 }' "$out/$tag.txt"
done >"$out/results.txt"

R=$out/results.txt
. port/cortex-m/bench/table-lib.sh
scenes="bunny fill fill_gouraud tris bunny_gouraud bunny_smooth"

echo "### Summary, Cortex-M0 -O2 (README)"
echo
echo "| scene | frame mode | frame mode + vertex cache | scanline mode | clear | per pixel written (frame + cache) | rasterisation per pixel (frame) |"
echo "|---|---:|---:|---:|---:|---:|---:|"
for s in $scenes; do
    tc=$(get frame-O2 $s total_vcache); px=$(get frame-O2 $s pixels)
    raster=$(( $(get frame-O2 $s v3_rows) - $(get frame-O2 $s v2_setup) ))
    echo "| $s | $(num "$(get frame-O2 $s total)") | $(num "$tc") | $(num "$(get scanline-O2 $s total)") | $(num "$(get frame-O2 $s clear)") | $(div "$tc" "$px") | $(div "$raster" "$px") |"
done
echo
echo "### Instructions per pixel of the line and texture loops, Cortex-M0 -O2"
echo
echo "| loop | -O2 |"
echo "|---|---:|"
for f in line line_aa flat tex_affine tex_persp tex_persp16 tex_persp_tilt tex_persp16_tilt tex_alpha blend blend_add tex_bilinear; do
    echo "| $f | $(awk -v f="$f" '$1 == "FEATURE" && $3 == f { printf "%.1f", $6 / 100; exit }' "$out/features-O2.txt") |"
done
mism=$(awk '$3 ~ /_plugin_insn_mismatch$/' "$R")
checked=$(awk '$3 == "plugin_checked" { n += $4 } END { print n + 0 }' "$R")
echo
if [ -n "$mism" ]; then
    echo "Plugin and timer instruction counts differ: $mism"
    status=1
elif [ "$checked" -gt 0 ]; then
    echo "Check: the plugin's instruction count equals the timer's for every interval ($checked intervals)."
fi
exit $status
