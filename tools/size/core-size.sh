#!/bin/sh
# SPDX-License-Identifier: MIT
# Flash and static RAM of the whole core library per Cortex-M CPU, float ABI
# and optimisation level: every .c under core/src compiled as the Cortex-M
# toolchain file does (-ffunction-sections -fdata-sections), summed by
# arm-none-eabi-size. It is the library's total: a firmware linked with
# --gc-sections keeps only the functions it calls (docs/CORTEX_M.md has the
# benchmark firmware's linked share).
#
#   sh tools/size/core-size.sh [work-dir]     -> a Markdown table on stdout
set -eu
root=$(cd "$(dirname "$0")/../.." && pwd)
work=${1:-$root/build/core-size}
command -v arm-none-eabi-gcc >/dev/null || { echo "arm-none-eabi-gcc not found" >&2; exit 2; }
srcs=$(find "$root/core/src" -name '*.c' | sort)
inc="-I$root/core/include"
if ls "$root"/core/src/*.h >/dev/null 2>&1; then inc="$inc -I$root/core/src"; fi

echo "| CPU, float ABI | flags | -O2 text (flash) | -Os text (flash) | data + bss (RAM) |"
echo "|---|---|---:|---:|---:|"
while read -r name flags; do
    row="| $name | \`$flags\` |"
    ram=0
    for opt in O2 Os; do
        dir=$work/$name-$opt
        rm -rf "$dir" && mkdir -p "$dir"
        (cd "$dir" && arm-none-eabi-gcc $flags -std=c99 -$opt -ffunction-sections -fdata-sections $inc -c $srcs)
        set -- $(arm-none-eabi-size -t "$dir"/*.o | tail -n 1)
        row="$row $1 |"
        ram=$(($2 + $3))
    done
    echo "$row $ram |"
done <<EOF2
cortex-m0 -mcpu=cortex-m0 -mthumb -mfloat-abi=soft
cortex-m3 -mcpu=cortex-m3 -mthumb -mfloat-abi=soft
cortex-m4 -mcpu=cortex-m4 -mthumb -mfloat-abi=soft
cortex-m4f,hard -mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard
cortex-m7,hard -mcpu=cortex-m7 -mthumb -mfpu=fpv5-d16 -mfloat-abi=hard
cortex-m33,hard -mcpu=cortex-m33 -mthumb -mfpu=fpv5-sp-d16 -mfloat-abi=hard
cortex-m55,hard -mcpu=cortex-m55 -mthumb -mfpu=auto -mfloat-abi=hard
EOF2
