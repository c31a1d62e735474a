#!/bin/sh
# SPDX-License-Identifier: MIT
# arduino_qemu_mega2560: the RotatingModel example's frames on an ATmega2560
# (8-bit AVR, 16-bit int, 8 KB of SRAM) under qemu-system-avr -M mega2560
# equal the host's, byte for byte (an FNV-1a sum per frame).
#
#   port/arduino/test/run-avr.sh HOST_REFERENCE
#
# HOST_REFERENCE is scene_reference.c built for the host (CTest passes it).
# The firmware (avr_scene.c + the example's rotating_scene.c + core/src) is
# compiled with avr-gcc as the Arduino core compiles a sketch (-Os, LTO,
# section garbage collection), without the Arduino core itself. It prints
# "frame N SUM" lines over USART0 (QEMU's -serial), its work-buffer size and
# stack high-water mark as "# " lines, then "done"; QEMU is stopped there.
# Exit 77 (CTest: skipped, which CI counts as a failure) when avr-gcc or
# qemu-system-avr is missing (tools/setup-debian.sh installs them).
set -eu
[ $# -eq 1 ] || { echo "usage: $0 HOST_REFERENCE" >&2; exit 2; }
reference=$1
top=$(cd "$(dirname "$0")/../../.." && pwd)
for tool in avr-gcc avr-objcopy avr-objdump avr-size qemu-system-avr; do
    command -v "$tool" >/dev/null 2>&1 ||
        { echo "arduino_qemu_mega2560: skipped, $tool not found (tools/setup-debian.sh installs it)"; exit 77; }
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT INT TERM

# SCENE_QEMU_DATA_PRELOAD: avr_scene.c works around two bugs of QEMU 7.2's
# AVR emulation (ELPM above 64 KB, a skipped RET); see there.
avr-gcc -mmcu=atmega2560 -DF_CPU=16000000UL -DSCENE_QEMU_DATA_PRELOAD -Os -std=c99 -w \
    -ffunction-sections -fdata-sections -flto \
    -I"$top/core/include" -I"$top/port/arduino/examples/RotatingModel" -I"$top/port/arduino/test" -I"$top/port/avr" \
    "$top/port/arduino/test/avr_scene.c" "$top/port/arduino/examples/RotatingModel/rotating_scene.c" \
    $(find "$top/core/src" -name '*.c' | sort) \
    -Wl,--gc-sections -o "$work/fw.elf"
avr-size "$work/fw.elf" | awk 'NR == 2 {
    printf "arduino_qemu_mega2560: firmware flash %d B, RAM %d B (.data %d + .bss %d) before the stack\n",
        $1 + $2, $2 + $3, $2, $3 }'
sh "$top/port/avr/qemu-avr.sh" arduino_qemu_mega2560 "$work/fw.elf" "$work/serial.txt" "${AVR_TIMEOUT:-120}"
waited=$(cat "$work/serial.txt.seconds")

grep '^# ' "$work/serial.txt" | sed 's/^# /arduino_qemu_mega2560: ATmega2560 /'
grep -v '^# ' "$work/serial.txt" | grep -v '^done' >"$work/avr.txt"
"$reference" >"$work/host.txt" 2>"$work/host.log" ||
    { cat "$work/host.log"; echo "arduino_qemu_mega2560: the host reference failed"; exit 1; }
if ! cmp -s "$work/avr.txt" "$work/host.txt"; then
    echo "arduino_qemu_mega2560: the ATmega2560's frames differ from the host's"
    echo "--- ATmega2560 (QEMU)"; cat "$work/avr.txt"
    echo "--- host"; cat "$work/host.txt"
    exit 1
fi
echo "arduino_qemu_mega2560: $(wc -l <"$work/host.txt") frames equal the host's (after $waited s):"
cat "$work/avr.txt"
