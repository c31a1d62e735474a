#!/bin/sh
# SPDX-License-Identifier: MIT
# Runs an ATmega2560 firmware on qemu-system-avr -M mega2560 until it prints
# a line "done" over USART0, then stops QEMU. What the AVR tests share
# (port/avr/run-avr-model.sh, port/arduino/test/run-avr.sh).
#
#   port/avr/qemu-avr.sh NAME ELF SERIAL TIMEOUT [QEMU-ARGUMENTS...]
#
# SERIAL receives USART0's output. .data's initial image is loaded straight
# into SRAM at its address (0x800000 is where QEMU and the GNU tools put the
# AVR's data space): avr_board.h's SCENE_QEMU_DATA_PRELOAD leaves avr-libc's
# copy out, as QEMU 7.2 reads flash above 64 KB wrongly. Exit status 1 (and
# the end of SERIAL printed) when no "done" came within TIMEOUT seconds.
set -eu
[ $# -ge 4 ] || { echo "usage: $0 NAME ELF SERIAL TIMEOUT [QEMU-ARGUMENTS...]" >&2; exit 2; }
name=$1 elf=$2 serial=$3 timeout=$4
shift 4
avr-objcopy -O binary -j .data "$elf" "$elf.data.bin"
data_addr=0x$(avr-objdump -h "$elf" | awk '$2 == ".data" { print $4 }')
: >"$serial"
qemu-system-avr -M mega2560 -bios "$elf" "$@" \
    -device loader,file="$elf.data.bin",addr="$data_addr",force-raw=on \
    -display none -serial file:"$serial" -monitor none 2>"$serial.qemu.log" &
qemu_pid=$!
trap 'kill "$qemu_pid" 2>/dev/null || true' EXIT INT TERM
waited=0
while ! grep -q '^done' "$serial" 2>/dev/null; do
    if [ "$waited" -ge "$timeout" ] || ! kill -0 "$qemu_pid" 2>/dev/null; then
        tail -c 2000 "$serial" 2>/dev/null || true
        cat "$serial.qemu.log" 2>/dev/null || true
        echo "$name: no 'done' from the firmware after $waited s"
        exit 1
    fi
    sleep 1
    waited=$((waited + 1))
done
kill "$qemu_pid" 2>/dev/null || true
wait "$qemu_pid" 2>/dev/null || true
trap - EXIT INT TERM
echo "$waited" >"$serial.seconds"
