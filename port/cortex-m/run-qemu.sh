#!/bin/sh
# SPDX-License-Identifier: MIT
# Run a Cortex-M ELF built with this port under QEMU: semihosting output on
# stdout, and this script's exit status is the program's (main's return
# value, 0 = all tests passed; 240+n = fault exception n, see startup.c).
#
#   port/cortex-m/run-qemu.sh [-M machine] [-s icount-shift] [-t seconds] app.elf
#
# The board follows the ELF's architecture (ARMv7E-M: mps2-an386 Cortex-M4,
# or mps2-an500 Cortex-M7 with an FPv5 FPU; ARMv7-M: mps2-an385 Cortex-M3;
# ARMv6-M: microbit Cortex-M0 with 4 MiB flash and RAM; ARMv8-M Mainline:
# mps2-an505 Cortex-M33; ARMv8.1-M: mps3-an547 Cortex-M55); -M overrides it. -icount shift 0 by default, so runs are
# deterministic. -t kills QEMU after that many seconds (exit 124).
set -u

machine=
shift_=0
limit=
usage() {
    echo "usage: $0 [-M machine] [-s icount-shift] [-t seconds] app.elf" >&2
    exit 2
}
while getopts "M:s:t:h" opt; do
    case $opt in
    M) machine=$OPTARG ;;
    s) shift_=$OPTARG ;;
    t) limit=$OPTARG ;;
    *) usage ;;
    esac
done
shift $((OPTIND - 1))
[ $# -eq 1 ] || usage
elf=$1
[ -f "$elf" ] || { echo "$0: $elf: no such file" >&2; exit 2; }
command -v qemu-system-arm >/dev/null 2>&1 ||
    { echo "$0: qemu-system-arm not found (apt install qemu-system-arm)" >&2; exit 2; }

if [ -z "$machine" ]; then
    arch=
    if command -v arm-none-eabi-readelf >/dev/null 2>&1; then
        arch=$(arm-none-eabi-readelf -A "$elf" | sed -n 's/^ *Tag_CPU_arch: *//p' | head -n 1)
    fi
    fp=
    if [ "$arch" = v7E-M ]; then
        fp=$(arm-none-eabi-readelf -A "$elf" | sed -n 's/^ *Tag_FP_arch: *//p' | head -n 1)
    fi
    case $arch in
    v7E-M) case $fp in FPv5*) machine=mps2-an500 ;; *) machine=mps2-an386 ;; esac ;; # FPv5: Cortex-M7
    v8-M.mainline) machine=mps2-an505 ;;
    v8.1-M.mainline) machine=mps3-an547 ;;
    v7) machine=mps2-an385 ;;   # v7-M reports "v7" with Tag_CPU_arch_profile: Microcontroller
    v6-M | v6S-M) machine=microbit ;;
    "") machine=mps2-an386
        echo "$0: cannot read the ELF's architecture (arm-none-eabi-readelf); assuming Cortex-M4" >&2 ;;
    *) echo "$0: architecture '$arch' is not a Cortex-M this script knows; use -M" >&2; exit 2 ;;
    esac
fi

set -- -M "$machine"
if [ "$machine" = microbit ]; then
    # The real nRF51 has 16 KiB of RAM; the port's linker script wants 4 MiB.
    set -- "$@" -global nrf51-soc.flash-size=4194304 -global nrf51-soc.sram-size=4194304
fi
set -- "$@" -nographic -monitor none -serial none \
    -chardev stdio,id=semi \
    -semihosting-config enable=on,target=native,chardev=semi \
    -icount shift="$shift_" \
    -kernel "$elf"

if [ -n "$limit" ]; then
    exec timeout "$limit" qemu-system-arm "$@"
fi
exec qemu-system-arm "$@"
