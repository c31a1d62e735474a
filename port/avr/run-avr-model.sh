#!/bin/sh
# SPDX-License-Identifier: MIT
# avr_model_mega2560 (issue 23): 3D in the 8 KB of an ATmega2560. The torus
# of model_scene.c (torus.obj through zline-obj2c, its arrays in flash),
# 160x128, scanline mode, over capacity, on qemu-system-avr -M mega2560;
# every row of 8 frames streamed over USART0 must equal the host's rendering
# of the same frames (model_reference.c, within capacity) byte for byte, the
# firmware must replan as often as the host counts for its capacities, and
# all the firmware's RAM (.data, .bss with zline's work buffer, and the
# stack's high-water mark) must fit the chip's 8192 bytes.
# Prints the flash, the RAM map and, when the QEMU plugin can be built
# (tools/qemu-m4-timing: its instruction counts hold for any CPU), the AVR
# instructions per frame.
#
#   port/avr/run-avr-model.sh OBJ2C HOST_REFERENCE
#
# OBJ2C is the host's zline-obj2c and HOST_REFERENCE model_reference built
# for the host (CTest passes both). Exit 77 (CTest: skipped, which CI counts
# as a failure) when avr-gcc or qemu-system-avr is missing
# (tools/setup-debian.sh installs them).
set -eu
[ $# -eq 2 ] || { echo "usage: $0 OBJ2C HOST_REFERENCE" >&2; exit 2; }
obj2c=$1
reference=$2
top=$(cd "$(dirname "$0")/../.." && pwd)
name=avr_model_mega2560
for tool in avr-gcc avr-objcopy avr-objdump avr-size avr-nm qemu-system-avr; do
    command -v "$tool" >/dev/null 2>&1 ||
        { echo "$name: skipped, $tool not found (tools/setup-debian.sh installs it)"; exit 77; }
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT INT TERM

"$obj2c" --normalize --no-colors --name torus "$top/port/avr/torus.obj" "$work/torus_mesh.c" "$work/torus_mesh.h"
# The mesh's arrays in flash (PROGMEM), read through zline's mesh read hook
# (zl_avr_flash.h); the zl_mesh that points at them stays in SRAM.
sed -e '1i #include <avr/pgmspace.h>' \
    -e 's/^\(const [a-z0-9_]* torus_[a-z]*\[[^]]*\]\) = {$/\1 PROGMEM = {/' \
    "$work/torus_mesh.c" >"$work/torus_flash.c"
[ "$(grep -c ' PROGMEM = {$' "$work/torus_flash.c")" -eq 2 ] ||
    { echo "$name: torus_mesh.c's positions and indices not found to place in flash"; exit 1; }
# As the Arduino core compiles a sketch: -Os, LTO, section garbage
# collection; SCENE_QEMU_DATA_PRELOAD: avr_board.h's QEMU 7.2 work-arounds.
# The minimal configuration (core/config/minimal.txt, issue 23): lit flat and
# Gouraud triangles, RGB565 (big-endian, as panels take it), depth through the
# snapped vertices (its 8-byte cached vertices): what the scene draws, which
# uses the default depth mapping.
minimal=$(sed -n 's/^\(ZL_[A-Z0-9_]*=[0-9]*\).*/-D\1/p' "$top/core/config/minimal.txt" | tr '\n' ' ')
avr-gcc -mmcu=atmega2560 -DF_CPU=16000000UL -DSCENE_QEMU_DATA_PRELOAD -Os -std=c99 -w $minimal \
    -DZL_CONFIG_HEADER='"zl_avr_flash.h"' \
    -ffunction-sections -fdata-sections -flto \
    -I"$top/core/include" -I"$top/port/avr" -I"$work" \
    "$top/port/avr/avr_model.c" "$top/port/avr/model_scene.c" "$work/torus_flash.c" \
    $(find "$top/core/src" -name '*.c' | sort) \
    -Wl,--gc-sections -o "$work/fw.elf"
set -- $(avr-size "$work/fw.elf" | awk 'NR == 2 { print $1, $2, $3 }')
text=$1 data=$2 bss=$3
echo "$name: flash $((text + data)) B; RAM before the stack $((data + bss)) B (.data $data + .bss $bss)"
avr-nm -S --size-sort "$work/fw.elf" | awk -v n="$name" '
    $3 ~ /^[dDbB]$/ && ("0x" $2) + 0 >= 64 { printf "%s:   %6d B  %s\n", n, ("0x" $2) + 0, $4 }'
avr-nm -S "$work/fw.elf" | awk -v n="$name" '
    $4 ~ /^torus_(positions|indices)$/ { printf "%s:   %6d B  %s (in flash)\n", n, ("0x" $2) + 0, $4 }'
mark=0x$(avr-nm "$work/fw.elf" | awk '$3 == "mark" { print $1 }')

plugin=
if cc -std=c99 -O2 -shared -fPIC -o "$work/count.so" "$top/tools/qemu-m4-timing/m4timing.c" 2>"$work/plugin.log"; then
    plugin="-plugin $work/count.so,mark=$mark,out=$work/marks.txt,any=1"
else
    echo "$name: no instruction counts (the QEMU plugin does not build: $(head -n 1 "$work/plugin.log"))"
fi
# shellcheck disable=SC2086 # $plugin splits on spaces
sh "$top/port/avr/qemu-avr.sh" "$name" "$work/fw.elf" "$work/serial.txt" "${AVR_TIMEOUT:-300}" $plugin
waited=$(cat "$work/serial.txt.seconds")

grep '^# ' "$work/serial.txt" | sed "s/^# /$name: ATmega2560 /"
stack=$(sed -n 's/^# stack: \([0-9]*\) bytes.*/\1/p' "$work/serial.txt")
grep -v '^# ' "$work/serial.txt" | grep -v '^done' >"$work/avr.txt"
"$reference" >"$work/host.txt" 2>"$work/host.log" ||
    { cat "$work/host.log"; echo "$name: the host reference failed"; exit 1; }
status=0
if ! cmp -s "$work/avr.txt" "$work/host.txt"; then
    echo "$name: the ATmega2560's frames differ from the host's:"
    cmp "$work/avr.txt" "$work/host.txt" || true
    grep -n 'error' "$work/avr.txt" | head -n 5 || true
    status=1
else
    echo "$name: $(grep -c '^frame' "$work/host.txt") frames of 160x128 equal the host's, byte for byte (after $waited s)"
fi
# The firmware renders over capacity (model_scene.h): as many replans as
# the host counts for the same frames with the same capacities.
replans=$(sed -n 's/^# replans: \([0-9]*\)$/\1/p' "$work/serial.txt")
expected=$("$reference" --needs | sed -n 's/.*; \([0-9]*\) in the [0-9]* frames the test compares$/\1/p')
if [ -z "$replans" ] || [ "$replans" != "$expected" ]; then
    echo "$name: the ATmega2560 replanned ${replans:-?} times, the host ${expected:-?} times"
    status=1
fi
total=$((data + bss + stack))
echo "$name: RAM used $total B of 8192 (.data $data + .bss $bss + stack $stack)"
[ "$total" -le 8192 ] || { echo "$name: over the ATmega2560's 8192 bytes of SRAM"; status=1; }
if [ -s "$work/marks.txt" ]; then
    # marks 2i and 2i + 1 bracket frame i's silent render
    awk -v n="$name" '$1 == "MARK" { m[$2] = $3; k = $2 }
        END { for (i = 0; i + 1 <= k; i += 2) { d = m[i + 1] - m[i]; s += d; c++; if (d > x) x = d }
              if (c) printf "%s: AVR instructions per frame (QEMU plugin, render only): mean %d, max %d over %d frames\n", n, s / c, x, c }' \
        "$work/marks.txt"
fi
exit $status
