#!/bin/sh
# SPDX-License-Identifier: MIT
# Flash of the core in a firmware that draws, per configuration (issue 23):
# the core's .text + .rodata that a firmware keeps after section garbage
# collection when it calls the drawing API (tools/size/size_probe.c: frame
# mode, scanline mode, lines, outlines, styles; a feature switched off
# answers ZL_ERR_UNSUPPORTED there, and its code goes). Every core/src file
# and the probe are compiled with -ffunction-sections -fdata-sections, then
# partially linked (ld -r --gc-sections, entry zl_size_probe: no C library
# needed); the probe's own sections are subtracted. memset/memcpy and the
# compiler's helpers (libgcc) are not counted.
#
# Configurations: all-on (zl_config.h's defaults) and minimal
# (core/config/minimal.txt: lit flat and Gouraud triangles, RGB565, depth
# LESS or LEQUAL, frame and scanline modes, no split frame); on Cortex-M0+
# also minimal-small, the minimal one without the speed-for-size paths
# (ZL_SMALL_TRIANGLE_SETUP=0, ZL_FAST_SPANS=0, ZL_FAST_PATHS=0,
# ZL_DRAW_CACHE_SLOTS=0: the same pixels, slower; on the ATmega2560 the
# first two are already 0, where int has 16 bits), and its rows -frame and
# -scanline: a firmware that draws in that mode only (the same core, the
# probe without the other mode's calls), and minimal-small-exact-clip: the
# same with ZL_FEATURE_EXACT_CLIP on (the exact planes of clipped
# triangles, which minimal.txt leaves out). Targets: Cortex-M0+, Cortex-M4
# (arm-none-eabi-gcc), rv32imc (riscv64-unknown-elf-gcc with picolibc's
# headers), ATmega2560 (avr-gcc), each at -Os and -O2.
#
#   sh tools/size/config-size.sh [work-dir]    -> a Markdown table on stdout
# Exit 2 when a compiler is missing (tools/setup-debian.sh installs them).
set -eu
root=$(cd "$(dirname "$0")/../.." && pwd)
work=${1:-$root/build/config-size}
for tool in arm-none-eabi-gcc riscv64-unknown-elf-gcc avr-gcc; do
    command -v $tool >/dev/null || { echo "config-size.sh: $tool not found" >&2; exit 2; }
done
srcs=$(find "$root/core/src" -name '*.c' | sort)
minimal=$(sed -n 's/^\(ZL_[A-Z0-9_]*=[0-9]*\).*/-D\1/p' "$root/core/config/minimal.txt" | tr '\n' ' ')
small="-DZL_SMALL_TRIANGLE_SETUP=0 -DZL_FAST_SPANS=0 -DZL_FAST_PATHS=0 -DZL_DRAW_CACHE_SLOTS=0"

# core_objects PREFIX FLAGS... : every core/src file compiled into $work/obj/core
core_objects() {
    prefix=$1; shift
    rm -rf "$work/obj" && mkdir -p "$work/obj/core"
    (cd "$work/obj/core" && "${prefix}gcc" "$@" -std=c99 -ffunction-sections -fdata-sections -I"$root/core/include" -c $srcs)
}
# flash PREFIX LD-EMULATION PROBE-DEFINES FLAGS... : .text + .rodata bytes the
# probe (compiled with FLAGS and PROBE-DEFINES) keeps of core_objects' core
# (LD-EMULATION: ld's -m, or - for its default)
flash() {
    prefix=$1; emulation=$2; probe_defines=$3; shift 3
    dir=$work/obj
    # shellcheck disable=SC2086
    "${prefix}gcc" "$@" $probe_defines -std=c99 -ffunction-sections -fdata-sections -I"$root/core/include" \
        -c "$root/tools/size/size_probe.c" -o "$dir/probe.o"
    if [ "$prefix" = avr- ]; then # avr-ld has no relocatable link: a full one, the core's share from its map
        avr-gcc "$@" -nostartfiles -Wl,--gc-sections -Wl,-e,zl_size_probe -Wl,-Map,"$dir/fw.map" \
            -o "$dir/fw.elf" "$dir/probe.o" "$dir"/core/*.o
        map_core_bytes "$dir/fw.map"
        return
    fi
    set --
    [ "$emulation" = - ] || set -- -m "$emulation"
    "${prefix}ld" "$@" -r --gc-sections -e zl_size_probe -o "$dir/kept.o" "$dir/probe.o" "$dir"/core/*.o
    total=$(code_bytes "$prefix" "$dir/kept.o")
    own=$(code_bytes "$prefix" "$dir/probe.o")
    echo $((total - own))
}
# map_core_bytes MAP: .text* and .rodata* input sections of core/ objects a
# linked image kept (GNU ld's map: name, address, size, file; a long name
# puts the rest on the next line)
map_core_bytes() {
    awk '
        function hex(h,   i, v) { v = 0; h = tolower(substr(h, 3)); for (i = 1; i <= length(h); i++) v = v * 16 + index("0123456789abcdef", substr(h, i, 1)) - 1; return v }
        /^Linker script and memory map/ { on = 1 }
        on && /^ \.(text|rodata)/ { sec = 1; if (NF >= 4) { size = $3; file = $4 } else next }
        on && sec && NF == 3 && $1 ~ /^0x/ { size = $2; file = $3 }
        on && sec && file != "" { if (file ~ /\/core\/[^\/]*\.o$/) core += hex(size); sec = 0; file = "" }
        END { print core + 0 }' "$1"
}
# code_bytes PREFIX OBJECT: sizes of its .text* and .rodata* sections
code_bytes() {
    "${1}objdump" -h "$2" | awk '
        function hex(h,   i, v) { v = 0; h = tolower(h); for (i = 1; i <= length(h); i++) v = v * 16 + index("0123456789abcdef", substr(h, i, 1)) - 1; return v }
        $2 ~ /^\.(text|rodata)/ { s += hex($3) } END { print s + 0 }'
}
kb() { awk -v b="$1" 'BEGIN { printf "%.1f", b / 1024 }'; }

# The targets' rows are computed at once, JOBS of them (default 2, the cores
# of CI's machine) at a time: each target in a background job with its own
# work folder, its rows into $rows_dir/INDEX (and INDEX.ok once complete),
# printed in the table's order when all are done. (One after the other:
# config_size_table took 148 s in the host stage of the last CI run.)
jobs=${JOBS:-2}
rows_dir=$work/rows
rm -rf "$rows_dir" && mkdir -p "$rows_dir"
target_root=$work
i=0
while read -r name prefix emulation flags; do
    i=$((i + 1))
    # a free slot: the job JOBS rows back has finished
    [ "$i" -le "$jobs" ] || wait "$(cat "$rows_dir/$((i - jobs)).pid")" || :
    (
    work=$target_root/target-$i
    configs="all-on minimal"
    [ "$name" = Cortex-M0+ ] && configs="$configs minimal-small minimal-small-exact-clip"
    for config in $configs; do
        case $config in
        all-on) extra= ;;
        minimal) extra=$minimal ;;
        minimal-small) extra="$minimal $small" ;;
        # what the exact planes of clipped triangles cost (ZL_FEATURE_EXACT_CLIP on)
        minimal-small-exact-clip) extra="$(echo "$minimal" | sed 's/-DZL_FEATURE_EXACT_CLIP=0//') $small" ;;
        esac
        # minimal-small: also a firmware that draws in one mode only (the
        # same core objects, a probe without the other mode's calls)
        rows=$config
        [ "$config" = minimal-small ] && rows="$config $config-frame $config-scanline"
        for opt in -Os -O2; do
            core_objects "$prefix" $flags $opt $extra
            for row in $rows; do
                case $row in
                *-frame) defines=-DZL_SIZE_PROBE_SCANLINE=0 ;;
                *-scanline) defines=-DZL_SIZE_PROBE_FRAME=0 ;;
                *) defines= ;;
                esac
                bytes=$(flash "$prefix" "$emulation" "$defines" $flags $opt $extra)
                key=$(echo "$row" | tr '-' '_')
                eval "bytes_${key}_${opt#-}=$bytes"
            done
        done
        for row in $rows; do
            key=$(echo "$row" | tr '-' '_')
            eval "os=\$bytes_${key}_Os o2=\$bytes_${key}_O2"
            # shellcheck disable=SC2154
            echo "| $row | $name | $os | $(kb "$os") | $o2 | $(kb "$o2") |"
        done
    done
    : >"$rows_dir/$i.ok"
    ) <&- >"$rows_dir/$i" &
    echo $! >"$rows_dir/$i.pid"
done <<EOF2
Cortex-M0+ arm-none-eabi- - -mcpu=cortex-m0plus -mthumb
Cortex-M4 arm-none-eabi- - -mcpu=cortex-m4 -mthumb
rv32imc riscv64-unknown-elf- elf32lriscv -march=rv32imc_zicsr -mabi=ilp32 --specs=picolibc.specs
ATmega2560 avr- - -mmcu=atmega2560
EOF2
wait
n=$i
i=0
while [ "$i" -lt "$n" ]; do
    i=$((i + 1))
    [ -e "$rows_dir/$i.ok" ] || { echo "config-size.sh: the rows of target $i failed" >&2; exit 1; }
done
echo "| configuration | target | -Os (bytes) | -Os (KB) | -O2 (bytes) | -O2 (KB) |"
echo "|---|---|---:|---:|---:|---:|"
i=0
while [ "$i" -lt "$n" ]; do
    i=$((i + 1))
    cat "$rows_dir/$i"
done
