#!/bin/sh
# SPDX-License-Identifier: MIT
# core_avr_int16: the core is C99 that holds where int has 16 bits (issue 23).
# Every core/src file is compiled for the ATmega2560 (8-bit AVR, 16-bit int
# and size_t, 1-byte aligned uint64_t) at -Os and -O2 with the warnings that
# catch an expression assuming a 32-bit int: -Wall -Wextra (shift counts >=
# the width of the type, integer overflow of constants, signed/unsigned
# comparisons whose meaning changes when uint16_t no longer promotes to int),
# -pedantic -Wshadow -Wconversion (a uint32_t value narrowed into an
# unsigned or a size_t of 16 bits). Any warning fails the test.
#
#   tools/lint/check-avr-int16.sh [SOURCE_DIR]   check the core (default: this tree)
#   tools/lint/check-avr-int16.sh --self-test    the check must fail on a file
#                                                that shifts 1u by 20
# Exit 77 (CTest: skipped, which CI counts as a failure) when avr-gcc is
# missing (tools/setup-debian.sh installs gcc-avr and avr-libc).
set -eu
cc=${AVR_CC:-avr-gcc}
command -v "$cc" >/dev/null 2>&1 ||
    { echo "core_avr_int16: skipped, $cc not found (tools/setup-debian.sh installs gcc-avr)"; exit 77; }
flags="-mmcu=atmega2560 -std=c99 -Wall -Wextra -pedantic -Wshadow -Wconversion -Werror"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT INT TERM

check_files() { # check_files INCLUDE_DIR FILE... -> 0 when every compile is warning-free
    inc=$1; shift
    status=0
    n=0
    for opt in -Os -O2; do
        for f in "$@"; do
            n=$((n + 1))
            # the object goes to the scratch folder, never /dev/null (gcc
            # deletes its output file when a compile fails)
            $cc $flags $opt -I"$inc" -c "$f" -o "$work/obj.o" 2>"$work/log" || {
                echo "core_avr_int16: $f ($opt):"
                cat "$work/log"
                status=1
            }
        done
    done
    [ "$status" -ne 0 ] || echo "core_avr_int16: $n compiles ($# files at -Os and -O2) warning-free for the ATmega2560"
    return "$status"
}

if [ "${1:-}" = "--self-test" ]; then
    printf '/* SPDX-License-Identifier: MIT */\n#include <stdint.h>\nuint32_t f(void);\nuint32_t f(void) { return 1u << 20; }\n' >"$work/bad.c"
    if check_files "$work" "$work/bad.c" >"$work/out" 2>&1; then
        echo "core_avr_int16 self-test: a 16-bit shift overflow passed the check"
        exit 1
    fi
    echo "core_avr_int16 self-test: the check fails on 1u << 20, as it must"
    exit 0
fi

top=${1:-$(cd "$(dirname "$0")/../.." && pwd)}
# shellcheck disable=SC2046 # the file list: paths without spaces
check_files "$top/core/include" $(find "$top/core/src" -name '*.c' | sort)
