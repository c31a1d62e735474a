#!/bin/sh
# SPDX-License-Identifier: MIT
# The portable unit suite (tests/test_*.c) on the ATmega2560 under
# qemu-system-avr -M mega2560 (issue 23): CTest avr_lib builds the library
# once, each avr_test_* builds one test against it and runs it.
#
#   port/avr/run-avr-test.sh lib WORK CONFIG
#       compile the core (CONFIG: "minimal", the switches of
#       core/config/minimal.txt off, or "all", every feature on), tests/unity and tests/support
#       with avr-gcc into WORK/CONFIG/libzt.a
#   port/avr/run-avr-test.sh run WORK CONFIG TEST ARENA [CFLAGS...]
#       compile tests/TEST.c with -Dmain=avr_test_main, the project's
#       warnings and CFLAGS (a test's smaller sizes), and tests/support/
#       zt_guard.c with an arena of ARENA bytes (the test's guarded buffers),
#       link it with port/avr/avr_test_main.c and the library,
#       check that it fits the chip (flash: .text + .data <= 262144 bytes;
#       RAM: .data + .bss + the stack's high-water mark <= 8192 bytes) and
#       run it under QEMU with USART0 as its output (port/avr/qemu-avr.sh)
#
# The test's output is printed; its result is its return value, the failure
# count (avr_test_main.c prints it as "# exit N"). Exit 0 when it is 0 and
# the test fits, 1 otherwise, 77 (CTest: skipped, which CI counts as a
# failure) when avr-gcc or qemu-system-avr is missing or when the test
# ignored cases without a failure (Unity's "0 Failures N Ignored").
set -eu
[ $# -ge 3 ] || { echo "usage: $0 lib WORK CONFIG | run WORK CONFIG TEST ARENA [CFLAGS...]" >&2; exit 2; }
mode=$1 work=$2 config=$3
top=$(cd "$(dirname "$0")/../.." && pwd)
for tool in avr-gcc avr-ar avr-objcopy avr-objdump avr-size qemu-system-avr; do
    command -v "$tool" >/dev/null 2>&1 ||
        { echo "avr suite: skipped, $tool not found (tools/setup-debian.sh installs it)"; exit 77; }
done
case $config in
minimal) features=$(sed -n 's/^\(ZL_[A-Z0-9_]*=[0-9]*\).*/-D\1/p' "$top/core/config/minimal.txt" | tr '\n' ' ') ;;
all) features= ;;
*) echo "unknown configuration '$config' (minimal or all)" >&2; exit 2 ;;
esac
lib=$work/$config
# As port/avr/run-avr-model.sh: -Os, section garbage collection; the QEMU
# 7.2 work-arounds of avr_board.h (SCENE_QEMU_DATA_PRELOAD). A draw cache of
# 64 slots (1,040 bytes, not the default 14,480 of 1024 slots: zl_config.h);
# the random rounds of the tests divided by ZT_ROUNDS_DIVISOR
# (tests/support/zt_target.h: QEMU's AVR is slow, 64-bit arithmetic a
# library call there).
cflags="-mmcu=atmega2560 -DF_CPU=16000000UL -DSCENE_QEMU_DATA_PRELOAD -Os -std=c99 $features -DZL_DRAW_CACHE_SLOTS=64 -DZT_ROUNDS_DIVISOR=${AVR_ROUNDS_DIVISOR:-50} -DZT_SMALL_RAM=1
    -ffunction-sections -fdata-sections -I$top/core/include -I$top/port/avr -I$top/tests/unity -I$top/tests/support"
warnings="-Wall -Wextra -pedantic -Werror"

build_library() {
    rm -rf "$lib"
    mkdir -p "$lib/obj"
    # The panel controller model (zt_panel_model.c) holds a 2 x 320 x 240
    # pixel RAM: only test_spi_panel uses it, and it is not built for AVR.
    # zt_guard.c is compiled with each test: its arena's size is the test's.
    for f in $(find "$top/core/src" -name '*.c' | sort) "$top/tests/unity/unity.c" \
        "$top"/tests/support/*.c "$top/port/avr/avr_test_main.c"; do
        case ${f##*/} in zt_panel_model.c | zt_guard.c) continue ;; esac
        o=$lib/obj/$(basename "$f" .c).o
        extra= # avr_board.h's helpers are static: not all are used here
        [ "${f##*/}" != avr_test_main.c ] || extra=-Wno-unused-function
        # shellcheck disable=SC2086 # flag lists split on spaces
        avr-gcc $cflags $warnings $extra -c "$f" -o "$o" 2>"$lib/log" || { cat "$lib/log"; echo "avr suite: $f does not compile"; exit 1; }
    done
    mv "$lib/obj/avr_test_main.o" "$lib/avr_test_main.o"
    avr-ar rcs "$lib/libzt.a" "$lib"/obj/*.o
    echo "avr suite: core ($config configuration), tests/unity and tests/support built for the ATmega2560"
}

run_test() {
    test=$1 arena=$2
    shift 2
    name=avr_$test
    [ "$config" = all ] || name=${name}_$config
    [ -f "$lib/libzt.a" ] || { echo "$name: $lib/libzt.a missing (CTest's avr_lib builds it)"; exit 1; }
    dir=$lib/$test
    mkdir -p "$dir"
    # shellcheck disable=SC2086
    avr-gcc $cflags $warnings -DZT_GUARD_ARENA_BYTES="$arena"u -c "$top/tests/support/zt_guard.c" -o "$dir/zt_guard.o"
    # shellcheck disable=SC2086
    avr-gcc $cflags $warnings -Dmain=avr_test_main -DZLINE_SHARED_DIR='""' -DZLINE_SOURCE_DIR='""' -DZLINE_BINARY_DIR='""' \
        "$@" "$top/tests/$test.c" "$dir/zt_guard.o" "$lib/avr_test_main.o" "$lib/libzt.a" -lm -Wl,--gc-sections \
        -o "$dir/$test.elf"
    # shellcheck disable=SC2046 # three numbers
    set -- $(avr-size "$dir/$test.elf" | awk 'NR == 2 { print $1, $2, $3 }')
    text=$1 data=$2 bss=$3
    echo "$name: flash $((text + data)) B of 262144; RAM before the stack $((data + bss)) B (.data $data + .bss $bss)"
    start=$(date +%s)
    sh "$top/port/avr/qemu-avr.sh" "$name" "$dir/$test.elf" "$dir/serial.txt" "${AVR_TIMEOUT:-120}" || exit 1
    grep -v '^done' "$dir/serial.txt"
    result=$(sed -n 's/^# exit \([0-9]*\)$/\1/p' "$dir/serial.txt")
    stack=$(sed -n 's/^# stack: \([0-9]*\) bytes$/\1/p' "$dir/serial.txt")
    stack=${stack:-0}
    total=$((data + bss + stack))
    echo "$name: RAM used $total B of 8192 (.data $data + .bss $bss + stack $stack); $(($(date +%s) - start)) s under QEMU"
    status=0
    if grep -q '^# stack overflow' "$dir/serial.txt" || [ "$total" -gt 8192 ]; then
        echo "$name: over the ATmega2560's 8192 bytes of SRAM"
        status=1
    fi
    if [ -z "$result" ]; then
        echo "$name: no '# exit' line: the test did not return"
        status=1
    elif [ "$result" != 0 ]; then
        echo "$name: $result failures"
        status=1
    fi
    if [ "$status" -eq 0 ] && grep -q ' 0 Failures [1-9][0-9]* Ignored' "$dir/serial.txt"; then
        echo "$name: skipped, cases ignored"
        exit 77
    fi
    exit "$status"
}

case $mode in
lib) build_library ;;
run) [ $# -ge 5 ] || { echo "usage: $0 run WORK CONFIG TEST ARENA [CFLAGS...]" >&2; exit 2; }
    shift 3
    run_test "$@" ;;
*) echo "usage: $0 lib WORK CONFIG | run WORK CONFIG TEST ARENA [CFLAGS...]" >&2; exit 2 ;;
esac
