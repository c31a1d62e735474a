#!/bin/sh
# SPDX-License-Identifier: MIT
# RISC-V benchmark tables (docs/MEASUREMENTS.md, port/riscv/README.md): builds the
# benchmark firmware (port/cortex-m/bench/bench.c with this port's minstret
# counter) at -O2 and -Os in frame and scanline mode, runs each under
# qemu-system-riscv32 (virt, -icount shift=0: exact instruction counts) and
# prints markdown tables: instructions per frame, flash and RAM.
#
#   port/riscv/bench/measure.sh [--update-budgets [--allow-raise REASON]] [ARCH [BUILD_DIR]]
#
# ARCH rv32imac (default) or rv32imc; BUILD_DIR defaults to
# build/ARCH-bench. --update-budgets rewrites budgets-ARCH.txt from this
# measurement (+3 %, rounded up to 1000: the BUDGET_SUGGEST lines) by the
# Cortex-M rule (port/cortex-m/bench/update-budgets.sh): it only lowers, a
# budget that would rise is kept with a warning unless --allow-raise REASON
# is given, and every comment line (the "# raised from OLD: REASON" lines)
# stays above its budget line.
set -eu
cd "$(dirname "$0")/../../.."
update=0
raise_reason=
if [ "${1:-}" = --update-budgets ]; then
    update=1
    shift
    if [ "${1:-}" = --allow-raise ]; then
        [ -n "${2:-}" ] || { echo "measure.sh: --allow-raise needs a REASON" >&2; exit 2; }
        raise_reason=$2
        shift 2
    fi
fi
arch=${1:-rv32imac}
build=${2:-build/$arch-bench}
bench=$build/port/riscv/bench
out=$build/measure
mkdir -p "$out"

cmake -S . -B "$build" -DCMAKE_TOOLCHAIN_FILE=port/riscv/toolchain-riscv.cmake \
    -DZLINE_RISCV_ARCH="$arch" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j 2 --target bench_frame_O2 bench_frame_Os bench_scanline_O2 bench_scanline_Os \
    bench_features_O2 bench_features_Os bench_vis_O2 >/dev/null
# The QEMU command CTest uses (the toolchain file's CMAKE_CROSSCOMPILING_EMULATOR).
emulator=$(cat "$build/port/riscv/qemu-command")

budgets=port/riscv/bench/budgets-$arch.txt
# A first measurement of an ISA: the firmware prints its BUDGET_SUGGEST lines
# only when it can read a budgets file.
if [ $update -eq 1 ] && [ ! -f "$budgets" ]; then echo "# (being measured)" >"$budgets"; fi

tags="frame-O2 frame-Os scanline-O2 scanline-Os"
status=0
for tag in $tags; do
    mode=${tag%-*}; opt=${tag#*-}
    elf=$bench/bench_${mode}_${opt}.elf
    # shellcheck disable=SC2086 # the command line splits on spaces
    $emulator "$elf" >"$out/$tag.txt" || status=1
    riscv64-unknown-elf-size -A "$elf" >"$out/$tag.size"
done
# The per-pixel loops of lines and textures (bench_features.c) and one bunny
# frame per visibility method (bench_vis.c).
for b in features-O2 features-Os vis-O2; do
    # shellcheck disable=SC2086
    $emulator "$bench/bench_${b%-*}_${b#*-}.elf" >"$out/$b.txt" || status=1
done
[ $status -eq 0 ] || echo "measure.sh: a benchmark reported a failure (BUDGET FAIL?): see $out/*.txt" >&2

if [ $update -eq 1 ]; then
    cat "$out"/*.txt | awk '$1 == "BUDGET_SUGGEST" { print $2, $3, $4 }' | sort >"$out/suggest.txt"
    if ! grep -q '^# Instruction budgets' "$budgets"; then # a first measurement: the header
        { echo "# Instruction budgets of the $arch benchmarks (port/cortex-m/bench/bench.c built by"
          echo "# port/riscv/bench), checked by the CTest tests bench_*_budgets of a ZLINE_RISCV_ARCH=$arch"
          echo "# cross build: a scene whose frame takes more instructions than its budget fails CI."
          echo "#   tag (mode-optimisation) scene budget (instructions per frame, minstret under -icount, exact)"
          echo "# Written by \`port/riscv/bench/measure.sh --update-budgets $arch\` (the measurement + 3 %,"
          echo "# rounded up to 1000). It only lowers a budget; --allow-raise REASON raises one with a"
          echo "# \"# raised from OLD: REASON\" line above it."; } >"$budgets"
    fi
    sh port/cortex-m/bench/update-budgets.sh "$budgets" "$out/suggest.txt" "$raise_reason" >"$out/budgets.txt"
    cp "$out/budgets.txt" "$budgets"
    echo "measure.sh: $budgets updated" >&2
fi

# All results as "tag scene key value" lines.
for tag in $tags; do
    awk -v tag="$tag" '$1 == "RESULT" || $1 == "INTERVAL" { print tag, $3, $4, $5 }' "$out/$tag.txt"
    # flash (everything loaded from the image: .init, .text with .rodata, the
    # .data initialisers) and RAM (.data, .tbss, .bss; the stack is separate)
    awk -v tag="$tag" '$1 == ".init" || $1 == ".text" { f += $2 } $1 == ".data" { f += $2; r += $2 }
        $1 == ".bss" || $1 == ".tbss" { r += $2 }
        END { print tag, "-", "flash_elf", f; print tag, "-", "ram_data_bss", r }' "$out/$tag.size"
    mode=${tag%-*}; opt=${tag#*-}
    # the core's and the meshes' share of flash, from the link map
    awk -v tag="$tag" -v lib="libzline_$opt.a" '
        function hex(h,   i, v) { v = 0; h = tolower(substr(h, 3)); for (i = 1; i <= length(h); i++) v = v * 16 + index("0123456789abcdef", substr(h, i, 1)) - 1; return v }
        /^Linker script and memory map/ { on = 1 }
        on && /^ \.(text|s?rodata)/ { sec = 1; if (NF >= 4) { size = $3; file = $4 } else next }
        on && sec && NF == 3 && $1 ~ /^0x/ { size = $2; file = $3 }
        on && sec && file != "" {
            if (index(file, lib)) core += hex(size)
            else if (file ~ /_mesh\.c\.obj/) mesh += hex(size)
            sec = 0; file = ""
        }
        END { print tag, "-", "flash_core", core; print tag, "-", "flash_meshes", mesh }' \
        "$bench/bench_${mode}_${opt}.elf.map"
done >"$out/results.txt"

R=$out/results.txt
. port/cortex-m/bench/table-lib.sh
scenes="bunny fill fill_gouraud tris"

echo "### Summary, $arch -O2 (README)"
echo
echo "| scene | frame mode | frame mode + vertex cache | scanline mode | per pixel written (frame + cache) | rasterisation per pixel (frame) |"
echo "|---|---:|---:|---:|---:|---:|"
for s in $scenes; do
    tc=$(get frame-O2 $s total_vcache); px=$(get frame-O2 $s pixels)
    raster=$(( $(get frame-O2 $s v3_rows) - $(get frame-O2 $s v2_setup) ))
    echo "| $s | $(num "$(get frame-O2 $s total)") | $(num "$tc") | $(num "$(get scanline-O2 $s total)") | $(div "$tc" "$px") | $(div "$raster" "$px") |"
done
echo
echo "### Instructions per frame, $arch, -O2 and -Os"
echo
echo "| scene | opt | frame mode | frame mode + vertex cache | scanline mode |"
echo "|---|---|---:|---:|---:|"
for s in $scenes; do
    for opt in O2 Os; do
        echo "| $s | -$opt | $(num "$(get frame-$opt $s total)") | $(num "$(get frame-$opt $s total_vcache)") | $(num "$(get scanline-$opt $s total)") |"
    done
done
echo
echo "### Frame mode by phase, $arch (instructions; the stages run separately, see bench.c)"
echo
echo "| scene | opt | clear | transform/clip | setup | rasterisation | general path, whole | transform/clip per triangle | setup per drawn triangle | rasterisation per pixel |"
echo "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|"
for s in $scenes; do
    for opt in O2 Os; do
        tag=frame-$opt
        v1=$(get $tag $s v1_polygons); v2=$(get $tag $s v2_setup); v3=$(get $tag $s v3_rows)
        clear=$(get $tag $s clear)
        tris=$(get $tag $s triangles); drawn=$(get $tag $s drawn); px=$(get $tag $s pixels)
        setup=$((v2 - v1)); raster=$((v3 - v2))
        echo "| $s | -$opt | $(num $clear) | $(num $v1) | $(num $setup) | $(num $raster) | $(num $v3) | $(div $v1 $tris) | $(div $setup $drawn) | $(div $raster $px) |"
    done
done
echo
echo "### Flash and RAM, $arch (bytes; riscv64-unknown-elf-size and the link map)"
echo
echo "| firmware | flash: core (.text+.rodata) | flash: meshes | flash: whole image | RAM: .data+.bss | stack high-water (deepest scene) |"
echo "|---|---:|---:|---:|---:|---:|"
for tag in $tags; do
    stack=$(awk -v t="$tag" '$1 == t && $3 == "stack" && $4 > m { m = $4 } END { print m }' "$R")
    echo "| bench_${tag%-*}_${tag#*-} | $(num "$(get $tag - flash_core)") | $(num "$(get $tag - flash_meshes)") | $(num "$(get $tag - flash_elf)") | $(num "$(get $tag - ram_data_bss)") | $(num "$stack") |"
done
echo
echo "### Instructions per pixel of the line and texture loops, $arch (bench_features.c, whole draw call / pixels)"
echo
echo "| loop | -O2 | -Os |"
echo "|---|---:|---:|"
for f in line line_aa flat tex_affine tex_persp tex_persp16; do
    per() { awk -v f="$f" '$1 == "FEATURE" && $3 == f { printf "%.1f", $6 / 100; exit }' "$out/features-$1.txt"; }
    echo "| $f | $(per O2) | $(per Os) |"
done
echo
echo "### Visibility methods, $arch (bunny, -O2)"
echo
echo "One frame of the bunny benchmark scene per method (bench_vis.c), as in docs/VISIBILITY.md."
echo
echo "| method | instructions per frame | RAM bytes | of which work buffer |"
echo "|---|---:|---:|---:|"
for m in zbuffer scanline aet painter bsp-b2f bsp-f2b raycast; do
    t=$(awk -v m="$m" '$1 == "INTERVAL" && $3 == m && $4 == "total" { print $5; exit }' "$out/vis-O2.txt")
    r=$(awk -v m="$m" '$1 == "RESULT" && $3 == m && $4 == "ram_bytes" { print $5; exit }' "$out/vis-O2.txt")
    w=$(awk -v m="$m" '$1 == "RESULT" && $3 == m && $4 == "work_bytes" { print $5; exit }' "$out/vis-O2.txt")
    echo "| $m | $(num "$t") | $(num "$r") | $(num "$w") |"
done
exit $status
