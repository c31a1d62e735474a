#!/bin/sh
# SPDX-License-Identifier: MIT
# arduino_mega2560: build the Arduino library (make-library.sh) into a
# temporary folder and compile its RotatingModel example for the Arduino
# Mega 2560 with Debian's arduino-builder and arduino-core-avr, as the
# Arduino IDE does (the library's sources with the core's flags: -Os, LTO).
# Fails on any compile error; prints the flash and RAM use (avr-size of the
# linked ELF: flash = .text + .data, RAM = .data + .bss, the rest of the 8 KB
# is the stack).
#
#   tools/arduino/check.sh [KEEP_DIR]   KEEP_DIR: keep the build there
#                                       (the ELF is KEEP_DIR/build/RotatingModel.ino.elf)
# Exit 77 (CTest: skipped, which CI counts as a failure) when arduino-builder,
# the AVR core or avr-size is missing: tools/setup-debian.sh installs them.
set -eu
top=$(cd "$(dirname "$0")/../.." && pwd)
hardware=${ARDUINO_HARDWARE:-/usr/share/arduino/hardware}
builder_dir=${ARDUINO_BUILDER_DIR:-/usr/share/arduino-builder}
for tool in arduino-builder avr-gcc avr-size; do
    command -v "$tool" >/dev/null 2>&1 ||
        { echo "arduino_mega2560: skipped, $tool not found (tools/setup-debian.sh installs it)"; exit 77; }
done
[ -f "$hardware/arduino/avr/boards.txt" ] ||
    { echo "arduino_mega2560: skipped, no Arduino AVR core in $hardware (arduino-core-avr)"; exit 77; }

if [ $# -ge 1 ]; then
    work=$1
    rm -rf "$work"
    mkdir -p "$work"
else
    work=$(mktemp -d)
    trap 'rm -rf "$work"' EXIT INT TERM
fi
sh "$top/tools/arduino/make-library.sh" "$work/libraries" >/dev/null
mkdir -p "$work/build"

# -hardware $builder_dir: Debian keeps the ctags recipe arduino-builder needs
# in its own platform.txt there. DECIMAL_DIG: Debian's Arduino core 1.8.7
# (WString.cpp) needs it in C++, which the float.h of Debian's avr-gcc 5.4
# gives to C99 only (every sketch, Blink included, fails without it; the
# Arduino IDE's own avr-gcc 7.3 has it); it is the compiler's own value.
# -warnings default: the core's warnings are shown (none are errors).
arduino-builder -compile \
    -hardware "$builder_dir" -hardware "$hardware" -tools /usr/bin \
    -libraries "$work/libraries" \
    -fqbn arduino:avr:mega:cpu=atmega2560 \
    -prefs "compiler.cpp.extra_flags=-DDECIMAL_DIG=__DECIMAL_DIG__" \
    -warnings default \
    -build-path "$work/build" \
    "$work/libraries/zline/examples/RotatingModel/RotatingModel.ino" >"$work/log" 2>&1 || {
    cat "$work/log"
    echo "arduino_mega2560: the RotatingModel example does not compile for the Mega 2560"
    exit 1
}
grep -c "warning:" "$work/log" | sed 's/^/arduino_mega2560: compiler warnings: /'
elf=$work/build/RotatingModel.ino.elf
[ -f "$elf" ] || { echo "arduino_mega2560: no $elf"; exit 1; }
avr-size "$elf"
avr-size "$elf" | awk 'NR == 2 {
    printf "arduino_mega2560: flash %d B (.text %d + .data %d) of 253952; RAM %d B (.data %d + .bss %d) of 8192, %d B left for the stack\n",
        $1 + $2, $1, $2, $2 + $3, $2, $3, 8192 - $2 - $3
    if ($2 + $3 > 8192 || $1 + $2 > 253952) { print "arduino_mega2560: does not fit the Mega 2560"; exit 1 }
}'
