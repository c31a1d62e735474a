#!/bin/sh
# Every test of zline, as CI runs it:
#   1. host build (warnings are errors), all unit tests, tools and benchmark checks
#   2. the same under AddressSanitizer + UndefinedBehaviorSanitizer
#   3. the portable tests cross-compiled for Cortex-M4, M3 and M0, run under QEMU
#      (and for RISC-V rv32imac: port/riscv, the block after the Cortex-M runs)
#   4. static analysis: cppcheck, clang-tidy, gcc -fanalyzer (tools/lint/run.sh)
#   5. fuzzing: each libFuzzer target for FUZZ_SECONDS (default 60) seconds,
#      two at a time, under ASan + UBSan (tests/fuzz/run.sh); any finding
#      fails. Five targets: about 4 minutes with the build.
# Build trees go to build/ci-*. Exit status: non-zero if anything failed.
set -eu
cd "$(dirname "$0")/.."
jobs=${JOBS:-2}
total=0
log=$(mktemp)
trap 'rm -f "$log"' EXIT
run() { # run NAME CMAKE-ARGS...
    name=$1; shift
    echo "=== $name"
    cmake -S . -B "build/ci-$name" "$@" >/dev/null
    cmake --build "build/ci-$name" -j "$jobs" >/dev/null
    ctest --test-dir "build/ci-$name" --output-on-failure -j "$jobs" | tee "$log"
    # set -e does not see a failure inside a pipeline: check ctest's summary
    grep -q "tests passed, 0 tests failed out of" "$log" || exit 1
    total=$((total + $(sed -n 's/.*tests passed, 0 tests failed out of \([0-9]*\).*/\1/p' "$log")))
}
run host -DCMAKE_BUILD_TYPE=Release
run sanitize -DCMAKE_BUILD_TYPE=Debug -DZLINE_SANITIZE=ON
for cpu in cortex-m4 cortex-m3 cortex-m0; do
    run "$cpu" -DCMAKE_BUILD_TYPE=Release -DCMAKE_TOOLCHAIN_FILE=port/cortex-m/toolchain-arm-none-eabi.cmake \
        -DZLINE_CPU="$cpu"
done
# --- RISC-V (port/riscv, issue 17): the portable suite, the golden scenes
# (host equals target) and the benchmark budgets on rv32imac under
# qemu-system-riscv32 (virt).
run rv32imac -DCMAKE_BUILD_TYPE=Release -DCMAKE_TOOLCHAIN_FILE=port/riscv/toolchain-riscv.cmake \
    -DZLINE_RISCV_ARCH=rv32imac
# --- end RISC-V
echo "=== static analysis"
sh tools/lint/run.sh
echo "=== fuzzing, ${FUZZ_SECONDS:-60} s per target"
sh tests/fuzz/run.sh build/ci-fuzz
echo "=== all test suites passed"
# The plain closing line: CTest tests of all builds (lint and fuzz runs not counted).
echo "zline: $total passed, 0 failed"
