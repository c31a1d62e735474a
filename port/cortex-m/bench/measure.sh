#!/bin/sh
# SPDX-License-Identifier: MIT
# Cortex-M4 benchmark tables for docs/CORTEX_M.md (issue 4): builds the
# benchmark firmware (bench.c) at -O2 and -Os in frame and scanline mode, runs
# each under QEMU mps2-an386 with -icount shift=6 (exact instruction counts
# from TIMER0) and, when the host compiler can build it, the m4timing plugin
# (a Cortex-M4 cycle ESTIMATE), and prints markdown tables.
#
#   port/cortex-m/bench/measure.sh [--update-budgets [--allow-raise REASON]] [BUILD_DIR]
#
# BUILD_DIR defaults to build/cortex-m4-bench. --update-budgets rewrites
# budgets.txt from this measurement (+3 %, rounded up to 1000), but only
# LOWERS budgets (and adds lines for new scenes): a budget the measurement
# would raise is kept, with a warning. --allow-raise REASON raises them too
# and writes "# raised from OLD: REASON" above each raised line (the
# budget_raises test fails on a raise without such a line).
set -eu
cd "$(dirname "$0")/../../.."
update=0
raise_reason=
if [ "${1:-}" = --update-budgets ]; then
    update=1; shift
    if [ "${1:-}" = --allow-raise ]; then
        [ -n "${2:-}" ] || { echo "measure.sh: --allow-raise needs a REASON" >&2; exit 2; }
        raise_reason=$2; shift 2
    fi
fi
build=${1:-build/cortex-m4-bench}
bench=$build/port/cortex-m/bench
out=$build/measure
mkdir -p "$out"

cmake -S . -B "$build" -DCMAKE_TOOLCHAIN_FILE=port/cortex-m/toolchain-arm-none-eabi.cmake \
    -DZLINE_CPU=cortex-m4 -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j 2 --target bench_frame_O2 bench_frame_Os bench_scanline_O2 bench_scanline_Os \
    bench_features_O2 bench_features_Os bench_vis_O2 bench_smooth_O2 bench_smooth_Os >/dev/null

plugin=$out/m4timing.so
if ! ${CC:-cc} -std=c99 -O2 -shared -fPIC -o "$plugin" tools/qemu-m4-timing/m4timing.c 2>"$out/plugin.log"; then
    echo "measure.sh: cannot build the cycle-estimate plugin (see $out/plugin.log): instructions only" >&2
    plugin=
fi

tags="frame-O2 frame-Os scanline-O2 scanline-Os"
status=0
for tag in $tags; do
    mode=${tag%-*}; opt=${tag#*-}
    elf=$bench/bench_${mode}_${opt}.elf
    mark=$(arm-none-eabi-nm "$elf" | awk '$3 == "mark" { print "0x" $1 }')
    rm -f "$out/$tag.marks"
    set -- qemu-system-arm -M mps2-an386 -nographic -monitor none -serial none \
        -chardev stdio,id=semi -semihosting-config enable=on,target=native,chardev=semi -icount shift=6
    if [ -n "$plugin" ]; then
        set -- "$@" -plugin "$plugin,mark=$mark,out=$out/$tag.marks"
    fi
    "$@" -kernel "$elf" >"$out/$tag.txt" || status=1
    arm-none-eabi-size -A "$elf" >"$out/$tag.size"
done
# The per-pixel loops of lines and textures (bench_features.c).
for opt in O2 Os; do
    qemu-system-arm -M mps2-an386 -nographic -monitor none -serial none \
        -chardev stdio,id=semi -semihosting-config enable=on,target=native,chardev=semi -icount shift=6 \
        -kernel "$bench/bench_features_$opt.elf" >"$out/features-$opt.txt" || status=1
done
# The smooth-lit bunny (bench_smooth.c, issue 15).
for opt in O2 Os; do
    qemu-system-arm -M mps2-an386 -nographic -monitor none -serial none \
        -chardev stdio,id=semi -semihosting-config enable=on,target=native,chardev=semi -icount shift=6 \
        -kernel "$bench/bench_smooth_$opt.elf" >"$out/smooth-$opt.txt" || status=1
done
# One bunny frame per visibility method (bench_vis.c).
qemu-system-arm -M mps2-an386 -nographic -monitor none -serial none \
    -chardev stdio,id=semi -semihosting-config enable=on,target=native,chardev=semi -icount shift=6 \
    -kernel "$bench/bench_vis_O2.elf" >"$out/vis-O2.txt" || status=1
[ $status -eq 0 ] || echo "measure.sh: a benchmark reported a failure (BUDGET FAIL?): see $out/*.txt" >&2

if [ $update -eq 1 ]; then
    # The header (leading comment block) stays; each budget line keeps the
    # comment lines just above it (its raise reasons); lines follow in sort
    # order. A suggestion above the old budget is a raise: kept out without
    # --allow-raise, else written with its reason.
    cat "$out"/*.txt | awk '$1 == "BUDGET_SUGGEST" { print $2, $3, $4 }' | sort >"$out/suggest.txt"
    sh port/cortex-m/bench/update-budgets.sh port/cortex-m/bench/budgets.txt "$out/suggest.txt" "$raise_reason" \
        >"$out/budgets.txt"
    cp "$out/budgets.txt" port/cortex-m/bench/budgets.txt
    echo "measure.sh: budgets.txt updated" >&2
fi

# All results as "tag scene key value" lines (cycles from the plugin's marks:
# an interval's cycles are the difference of its marks minus the cost of the
# empty interval per mark inside it, the same correction as the timer's).
for tag in $tags; do
    awk -v tag="$tag" -v marks="$out/$tag.marks" '
        BEGIN { while ((getline l < marks) > 0) { split(l, f, " "); if (f[1] == "MARK") { mi[f[2]] = f[3]; mc[f[2]] = f[4] } } }
        /^# timer:/ { for (i = 1; i <= NF; i++) if ($i == "overhead") ov = $(i + 1) }
        $1 == "RESULT" { print tag, $3, $4, $5 }
        $1 == "INTERVAL" {
            print tag, $3, $4, $5
            if ((0 in mi) && ($6 in mc) && ($7 in mc)) {
                n = $7 - $6
                e_i = mi[1] - mi[0]; e_c = mc[1] - mc[0]
                pi = mi[$7] - mi[$6] - n * e_i + (n - 1) * ov
                print tag, $3, $4 "_cycles", mc[$7] - mc[$6] - n * e_c
                if (pi != $5) print tag, $3, $4 "_plugin_insn_mismatch", pi - $5
            }
        }' "$out/$tag.txt"
    # flash and RAM of the ELF, and the core's share of flash from the map
    awk -v tag="$tag" '$1 == ".text" { t = $2 } $1 == ".data" { d = $2 } $1 == ".bss" { b = $2 }
        END { print tag, "-", "flash_elf", t; print tag, "-", "ram_data_bss", d + b }' "$out/$tag.size"
    mode=${tag%-*}; opt=${tag#*-}
    awk -v tag="$tag" -v lib="libzline_$opt.a" '
        function hex(h,   i, v) { v = 0; h = tolower(substr(h, 3)); for (i = 1; i <= length(h); i++) v = v * 16 + index("0123456789abcdef", substr(h, i, 1)) - 1; return v }
        /^Linker script and memory map/ { on = 1 }
        on && /^ \.(text|rodata)/ { sec = 1; if (NF >= 4) { size = $3; file = $4 } else next }
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
scenes="bunny fill fill_gouraud tris bunny_clip bunny_gouraud bunny_smooth"

echo "### Instructions per frame (exact: QEMU -icount, TIMER0), Cortex-M4 (mps2-an386)"
echo
echo "One frame: frame mode = zl_clear + zl_draw_mesh; scanline mode = zl_frame_begin + zl_frame_add_mesh + 240 one-row bands. Cycles: m4timing plugin, an ESTIMATE (Cortex-M4 TRM table, P = 2, division 12)."
echo
echo "| scene | mode | opt | instructions | per triangle submitted | per pixel written | cycles (ESTIMATE) | estimated cycles / instruction |"
echo "|---|---|---|---:|---:|---:|---:|---:|"
for s in $scenes; do
    tris=$(get frame-O2 $s triangles); px=$(get frame-O2 $s pixels)
    for tag in $tags; do
        mode=${tag%-*}; opt=${tag#*-}
        t=$(get $tag $s total); c=$(get $tag $s total_cycles)
        echo "| $s | $mode | -$opt | $(num "$t") | $(div "$t" "$tris") | $(div "$t" "$px") | $(num "$c") | $(awk -v a="$c" -v b="$t" 'BEGIN { if (a == "") print "n/a"; else printf "%.2f", a / b }') |"
    done
done
echo
echo "### Summary, Cortex-M4 -O2 (README)"
echo
echo "| scene | frame mode | frame mode + vertex cache | scanline mode | per pixel written (frame + cache) | rasterisation per pixel (frame) | cycles, frame + cache (ESTIMATE) |"
echo "|---|---:|---:|---:|---:|---:|---:|"
for s in $scenes; do
    tc=$(get frame-O2 $s total_vcache); px=$(get frame-O2 $s pixels)
    raster=$(( $(get frame-O2 $s v3_rows) - $(get frame-O2 $s v2_setup) ))
    echo "| $s | $(num "$(get frame-O2 $s total)") | $(num "$tc") | $(num "$(get scanline-O2 $s total)") | $(div "$tc" "$px") | $(div "$raster" "$px") | $(num "$(get frame-O2 $s total_vcache_cycles)") |"
done
echo
echo "### Frame mode with the optional vertex cache (ctx.vertex_cache: each vertex transformed once)"
echo
echo "| scene | opt | instructions per frame | without the cache | vertex cache RAM (bytes) |"
echo "|---|---|---:|---:|---:|"
for s in $scenes; do
    for opt in O2 Os; do
        t=$(get frame-$opt $s total_vcache); p=$(get frame-$opt $s total)
        echo "| $s | -$opt | $(num "$t") | $(num "$p") | $(num "$(get frame-$opt $s vertices_x8)") |"
    done
done
echo
echo "### zl_draw_mesh's caches, Cortex-M4 -O2 (issue 23)"
echo
echo "| scene | no cache (zl_init's default: the general path) | draw cache (ctx.draw_cache) | vertex cache (ctx.vertex_cache) | draw cache RAM (bytes) | vertex cache RAM (bytes) |"
echo "|---|---:|---:|---:|---:|---:|"
for s in bunny bunny_gouraud bunny_clip; do
    echo "| $s | $(num "$(get frame-O2 $s total_nocache)") | $(num "$(get frame-O2 $s total)") | $(num "$(get frame-O2 $s total_vcache)") | $(num "$(get frame-O2 $s draw_cache_bytes)") | $(num "$(get frame-O2 $s vertices_x8)") |"
done
echo
echo "### Frame mode by phase (instructions; the stages run separately, see bench.c)"
echo
echo "| scene | opt | triangles | drawn | pixels written | clear | transform/clip | setup | rasterisation | general path, whole | transform/clip per triangle | setup per drawn triangle | rasterisation per pixel |"
echo "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
for s in $scenes; do
    for opt in O2 Os; do
        tag=frame-$opt
        v1=$(get $tag $s v1_polygons); v2=$(get $tag $s v2_setup); v3=$(get $tag $s v3_rows)
        clear=$(get $tag $s clear)
        tris=$(get $tag $s triangles); drawn=$(get $tag $s drawn); px=$(get $tag $s pixels)
        setup=$((v2 - v1)); raster=$((v3 - v2))
        echo "| $s | -$opt | $tris | $drawn | $(num $px) | $(num $clear) | $(num $v1) | $(num $setup) | $(num $raster) | $(num $v3) | $(div $v1 $tris) | $(div $setup $drawn) | $(div $raster $px) |"
    done
done
echo
echo "### Scanline mode by phase (instructions)"
echo
echo "| scene | opt | plan + row 0 | rows 1..239 | total | rows per pixel written | work buffer bytes |"
echo "|---|---|---:|---:|---:|---:|---:|"
for s in $scenes; do
    for opt in O2 Os; do
        tag=scanline-$opt
        echo "| $s | -$opt | $(num "$(get $tag $s plan_row0)") | $(num "$(get $tag $s rows)") | $(num "$(get $tag $s total)") | $(div "$(get $tag $s rows)" "$(get frame-O2 $s pixels)") | $(num "$(get $tag $s work_bytes)") |"
    done
done
echo
echo "### Two cores, one frame, Cortex-M4"
echo
echo "zl_frame_split's halves (issue 27, bench.c run_split), cfg.parts = 2, each part counted on this core: the"
echo "critical path is serial + the larger zl_frame_prepare + the larger part's bands."
echo
echo "| scene | opt | one core (scanline) | serial: submit + split | prepare, core 0 | prepare, core 1 | bands, core 0 | bands, core 1 | critical path | critical / one core | split row | second core's work buffer (bytes) |"
echo "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
for s in bunny tris; do
    for opt in O2 Os; do
        tag=scanline-$opt
        one=$(get $tag $s total)
        crit=$(get $tag $s split_critical)
        echo "| $s | -$opt | $(num "$one") | $(num "$(get $tag $s split_serial)") | $(num "$(get $tag $s split_prepare1)") | $(num "$(get $tag $s split_prepare2)") | $(num "$(get $tag $s split_first)") | $(num "$(get $tag $s split_second)") | $(num "$crit") | $(awk -v a="$crit" -v b="$one" 'BEGIN { printf "%.3f", a / b }') | $(get $tag $s split_row) | $(num "$(get $tag $s split_part_bytes)") |"
    done
done
echo
echo "### Flash and RAM (bytes; arm-none-eabi-size and the link map)"
echo
echo "| firmware | flash: core (.text+.rodata) | flash: meshes | flash: whole ELF | RAM: .data+.bss | stack high-water (deepest scene) |"
echo "|---|---:|---:|---:|---:|---:|"
for tag in $tags; do
    stack=$(awk -v t="$tag" '$1 == t && $3 == "stack" && $4 > m { m = $4 } END { print m }' "$R")
    echo "| bench_${tag%-*}_${tag#*-} | $(num "$(get $tag - flash_core)") | $(num "$(get $tag - flash_meshes)") | $(num "$(get $tag - flash_elf)") | $(num "$(get $tag - ram_data_bss)") | $(num "$stack") |"
done
echo
echo "### Instructions per pixel of the line and texture loops (bench_features.c, whole draw call / pixels)"
echo
echo "| loop | -O2 | -Os |"
echo "|---|---:|---:|"
for f in line line_aa flat tex_affine tex_persp tex_persp16 tex_persp_tilt tex_persp16_tilt tex_alpha blend blend_add tex_bilinear; do
    per() { awk -v f="$f" '$1 == "FEATURE" && $3 == f { printf "%.1f", $6 / 100; exit }' "$out/features-$1.txt"; }
    echo "| $f | $(per O2) | $(per Os) |"
done
echo
echo "### Visibility methods on Cortex-M4 (bunny, -O2)"
echo
echo "One frame of the bunny benchmark scene per method (bench_vis.c): begin and planning to the last row. RAM: the work buffer plus the caller's colour and depth frames (2 bytes a pixel each where used); the BSP tree is const data in flash."
echo
echo "| method | instructions per frame | RAM bytes | of which work buffer |"
echo "|---|---:|---:|---:|"
for m in zbuffer scanline aet painter bsp-b2f bsp-f2b raycast; do
    t=$(awk -v m="$m" '$1 == "INTERVAL" && $3 == m && $4 == "total" { print $5; exit }' "$out/vis-O2.txt")
    r=$(awk -v m="$m" '$1 == "RESULT" && $3 == m && $4 == "ram_bytes" { print $5; exit }' "$out/vis-O2.txt")
    w=$(awk -v m="$m" '$1 == "RESULT" && $3 == m && $4 == "work_bytes" { print $5; exit }' "$out/vis-O2.txt")
    echo "| $m | $(num "$t") | $(num "$r") | $(num "$w") |"
done
echo
echo "### Smooth lighting on Cortex-M4 (bunny_smooth, bench_smooth.c)"
echo
echo "The bunny scene's camera, lit per vertex by zl_light_vertices (1839 vertices, area-weighted normals, a key light with Blinn-Phong specular, exponent 24, and a fill light, in eye space), Gouraud-interpolated. light: zl_light_vertices alone; draw: zl_clear + zl_draw_mesh of the lit mesh with the vertex cache (the bunny with per-vertex colours); frame: light + draw; scanline: light + the zl_frame frame with one-row bands."
echo
echo "| interval | -O2 | -Os |"
echo "|---|---:|---:|"
for k in light draw frame scanline; do
    sm() { awk -v k="$k" '$1 == "INTERVAL" && $3 == "bunny_smooth" && $4 == k { print $5; exit }' "$out/smooth-$1.txt"; }
    echo "| $k | $(num "$(sm O2)") | $(num "$(sm Os)") |"
done
lv=$(awk '$1 == "RESULT" && $4 == "vertices" { print $5; exit }' "$out/smooth-O2.txt")
li=$(awk '$1 == "INTERVAL" && $4 == "light" { print $5; exit }' "$out/smooth-O2.txt")
[ -n "$lv" ] && [ -n "$li" ] && echo && echo "Lighting per vertex at -O2: $((li / lv)) instructions (2 lights, one with specular)."
# the bunny with per-vertex colours against the flat bunny frame (issue 13: at most 1.3 x)
sd=$(awk '$1 == "INTERVAL" && $3 == "bunny_smooth" && $4 == "draw" { print $5; exit }' "$out/smooth-O2.txt")
fv=$(awk '$1 == "INTERVAL" && $3 == "bunny" && $4 == "total_vcache" { print $5; exit }' "$out/frame-O2.txt")
[ -n "$sd" ] && [ -n "$fv" ] && echo && echo "The bunny with per-vertex colours (draw, -O2) against the flat bunny frame with the vertex cache ($(num "$fv")): $(awk -v a="$sd" -v b="$fv" 'BEGIN { printf "%.2f", a / b }') x."
mism=$(awk '$3 ~ /_plugin_insn_mismatch$/' "$R")
echo
if [ -n "$plugin" ] && [ -z "$mism" ]; then
    echo "Check: the plugin's instruction count equals the timer's for every interval."
elif [ -n "$mism" ]; then
    echo "Plugin and timer instruction counts differ: $mism"
fi
exit $status
