#!/bin/sh
# SPDX-License-Identifier: MIT
# Install what zline's build, tests and tools need on Debian (12 or later).
# Everything comes from Debian's own archive. clang and libclang-rt-dev (libFuzzer,
# sanitizer runtimes) build the fuzz targets; clang-tidy and cppcheck are the
# static analysers of tools/lint/run.sh. python3 drives QEMU's display for the
# LM3S6965 OLED test; imagemagick makes docs/PORTS.md's frames from its captures.
# gcc-riscv64-unknown-elf, picolibc and qemu-system-misc (qemu-system-riscv32)
# build and run the RISC-V port.
set -eu
pkgs="cmake make gcc libc6-dev gcc-arm-none-eabi libnewlib-arm-none-eabi binutils-arm-none-eabi
qemu-system-arm netpbm libpng-dev valgrind clang libclang-rt-dev clang-tidy cppcheck
python3 imagemagick
gcc-riscv64-unknown-elf picolibc-riscv64-unknown-elf qemu-system-misc"
# Consumer tests (tests/consumer): pkg-config, and g++ for the C++ header build.
pkgs="$pkgs pkg-config g++"
# Arduino library check (tools/arduino/check.sh): arduino-builder and the AVR
# core compile the RotatingModel example for the Mega 2560 with avr-gcc.
pkgs="$pkgs arduino-builder arduino-core-avr gcc-avr avr-libc binutils-avr"
missing=""
for p in $pkgs; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
[ -z "$missing" ] && exit 0
if [ "$(id -u)" -eq 0 ]; then sudo=""; else sudo="sudo"; fi
$sudo apt-get update
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y --no-install-recommends $missing
