#!/bin/sh
# SPDX-License-Identifier: MIT
# Every test of zline, as CI runs it:
#   1. host build (warnings are errors), all unit tests, tools and benchmark checks
#      (and the Arduino library, issue 24: its manifests, its example compiled
#      for the Mega 2560 by arduino-builder, its frames on an ATmega2560 under
#      qemu-system-avr against the host's; CTest arduino_*, about 25 s; and
#      the portable tests that fit an ATmega2560 under qemu-system-avr,
#      port/avr/run-avr-test.sh: CTest avr_lib, avr_test_*, about 43 s)
#   2. the same under AddressSanitizer + UndefinedBehaviorSanitizer, built
#      with clang: its -fsanitize=undefined includes float-cast-overflow,
#      which GCC's does not (the OBJ normalisation finding of issue 16)
#   3. the portable tests cross-compiled for Cortex-M3 and M0, run under QEMU,
#      and the Cortex-M4's benchmark budgets, golden scenes and port tests
#      (the M3 build also runs the LM3S6965 OLED firmware on QEMU's emulated
#      display against the host's frames: port/lm3s6965, about 10 s)
#   3b. a sample of 3 mutations (tools/mutation/mutate.py, chosen by the date):
#       each must make the host suite fail
#      (and, issue 11: for the hard-float M4F and M55 on their boards, the
#      golden scenes and port tests of the M7 and M33 on theirs, the M4F once
#      more at -O0 (issue 24: all built, the faster tests run), the two-core
#      firmware on the dual Cortex-M33 mps2-an521 (issue 27); then the consumer tests of tests/consumer/run.sh)
#      (and for RISC-V rv32imac: port/riscv, the block after the Cortex-M runs)
#   4. fuzzing: each libFuzzer target for FUZZ_SECONDS (default 25 here, 60 in
#      tests/fuzz/run.sh alone: CI had reached 30 minutes, then 40 minutes)
#      seconds, two at a time, under ASan + UBSan (tests/fuzz/run.sh); any
#      finding fails. Nine targets: about 3 minutes with the build.
#   5. static analysis: cppcheck (beside the last fuzz target), clang-tidy,
#      gcc -fanalyzer (tools/lint/run.sh)
# A test that CTest reports skipped (Not Run, Disabled) fails CI as well.
# Build trees go to build/ci-*. Exit status: non-zero if anything failed.
set -eu
cd "$(dirname "$0")/.."
jobs=${JOBS:-2}
ci_start=$(date +%s)
total=0
log=$(mktemp)
trap 'rm -f "$log"' EXIT
run() { # run NAME CMAKE-ARGS...
    name=$1; shift
    echo "=== $name"
    stage_start=$(date +%s)
    cmake -S . -B "build/ci-$name" "$@" >/dev/null
    # BUILD_TARGET: one target or several, separated by spaces (default: all)
    # shellcheck disable=SC2086
    cmake --build "build/ci-$name" -j "$jobs" ${BUILD_TARGET:+--target $BUILD_TARGET} >/dev/null
    ctest --test-dir "build/ci-$name" --output-on-failure -j "$jobs" ${CTEST_EXCLUDE:+-E "$CTEST_EXCLUDE"} \
        ${CTEST_INCLUDE:+-R "$CTEST_INCLUDE"} | tee "$log"
    # set -e does not see a failure inside a pipeline: check ctest's summary
    grep -q "tests passed, 0 tests failed out of" "$log" || exit 1
    # A skipped test (missing ../shared models, an ignored Unity case) is
    # not a pass: CI fails and names it (issue 16).
    if grep -q "(Skipped)\|(Not Run)\|(Disabled)" "$log"; then
        echo "zline: tests skipped in $name (CI runs every test):"
        grep "(Skipped)\|(Not Run)\|(Disabled)" "$log"
        exit 1
    fi
    total=$((total + $(sed -n 's/.*tests passed, 0 tests failed out of \([0-9]*\).*/\1/p' "$log")))
    echo "=== $name: $(($(date +%s) - stage_start)) s, build and tests"
}
# stage_time NAME START: what a stage that is not a run took (the CI time table)
stage_time() { echo "=== $1: $(($(date +%s) - $2)) s"; }
run host -DCMAKE_BUILD_TYPE=Release
# What runs no host code under the sanitizers is left to the host stage,
# which runs it already: the flash table (config_size_table, about 60 s), the
# AVR builds and QEMU runs (avr_*, arduino_*, core_avr_int16), the cross
# compilers' checks (stack_bound_*, core_dependencies, core_no_float_symbols).
# At -O1, as AddressSanitizer's documentation advises for speed: its checks
# and UBSan's are inserted before optimisation; at -O0 this stage's tests had
# taken 249 s of CI's 58 minutes.
CTEST_EXCLUDE='^(config_size_table|avr_.*|arduino_.*|core_avr_int16.*|stack_bound_.*|core_dependencies|core_no_float_symbols)$' run sanitize -DCMAKE_C_COMPILER=clang -DCMAKE_BUILD_TYPE=Debug -DCMAKE_C_FLAGS_DEBUG="-g -O1" -DZLINE_SANITIZE=ON
CTEST_EXCLUDE=
# The host tools of the cross builds' benchmark and golden firmware
# (port/cortex-m/bench/host: zline-obj2c, zline-img2c, zline-bsp,
# zline-golden-host), built here once for every cross stage below
# (ZLINE_BENCH_HOST_TOOLS, port/cortex-m/bench/host-tools.cmake) instead of by
# an ExternalProject in each of the ten: the same sources, arguments and host
# compiler, so the same programs (about 20 CPU seconds a build).
t0=$(date +%s)
bench_tools=$PWD/build/ci-bench-host-tools
cmake -DOUT="$bench_tools/grid.obj" -P port/cortex-m/bench/grid_obj.cmake
cmake -S port/cortex-m/bench/host -B "$bench_tools" -DCMAKE_BUILD_TYPE=Release \
    -DZLINE_GRID_OBJ="$bench_tools/grid.obj" >/dev/null
cmake --build "$bench_tools" -j "$jobs" >/dev/null
stage_time bench-host-tools "$t0"
cross="-DZLINE_BENCH_HOST_TOOLS=$bench_tools"
# One CPU of each instruction set runs the portable suite (tests/test_*.c
# with its minimal and no-cache builds): ARMv7E-M the hard-float M4F (below,
# and again at -O0), ARMv7-M the M3, ARMv6-M the M0, ARMv8.1-M the M55 and
# RV32 rv32imac. The core takes the same source paths on every CPU of an
# instruction set (its inline assembly is chosen by __ARM_ARCH_6M__ / 7M /
# 7EM and __ARM_FEATURE_DSP, core/src/3_raster/zl_span.c), only the
# compiler's code differs (scheduled for the CPU; with an FPU, GCC also keeps
# integers in its registers: 33 of the core's 41 -O3 objects differ between
# the M4 and the M4F, objdump -d). So the other CPUs of an instruction set (the
# soft-float M4 and the M7 beside the M4F, the M33 beside the M55) build and
# run what is theirs alone: the golden scenes, their frames equal to the
# host's (frame, scanline and band mode; flat, Gouraud, smooth-lit, textured
# and blended: the core as compiled for that CPU), test_float (zl_float.h on
# that CPU's FPU or soft float), the port's self-tests and fault reports on
# its board, and on the M4 the benchmark budgets and README's measured
# tables. What they no longer build and run, the rest of the portable suite
# (37 tests; 38 programs and the no-cache and minimal cores), had taken 73
# test-seconds on the M4, 59 on the M7 and 75 on the M33 in the last CI run
# (CTest's per-test times), and its build 48, 49 and 53 CPU seconds (user +
# sys of cmake --build of all after the stage's own targets); the stages'
# builds now take 55 (with the benchmarks), 22 and 22.
same_isa_tests='golden_host_equals_target|test_float|port_selftest|port_fault_.*'
same_isa_targets='golden test_float port_selftest port_fault_undefined_instruction port_fault_division_by_zero
    port_fault_stack_overflow port_fault_division_by_zero_64'
m4_bench_targets='bench_frame_O2 bench_frame_Os bench_scanline_O2 bench_scanline_Os bench_features_O2
    bench_features_Os bench_smooth_O2 bench_smooth_Os bench_vis_O2'
for cpu in cortex-m4 cortex-m3 cortex-m0; do
    targets= include=
    if [ "$cpu" = cortex-m4 ]; then
        targets="$same_isa_targets $m4_bench_targets"
        include="^($same_isa_tests|bench_.*|docs_measured_tables)\$"
    fi
    BUILD_TARGET=$targets CTEST_INCLUDE=$include run "$cpu" -DCMAKE_BUILD_TYPE=Release \
        -DCMAKE_TOOLCHAIN_FILE=port/cortex-m/toolchain-arm-none-eabi.cmake "$cross" -DZLINE_CPU="$cpu"
done
BUILD_TARGET= CTEST_INCLUDE=
# --- RISC-V (port/riscv, issue 17): the portable suite, the golden scenes
# (host equals target) and the benchmark budgets on rv32imac under
# qemu-system-riscv32 (virt).
run rv32imac -DCMAKE_BUILD_TYPE=Release -DCMAKE_TOOLCHAIN_FILE=port/riscv/toolchain-riscv.cmake "$cross" \
    -DZLINE_RISCV_ARCH=rv32imac
# --- end RISC-V
# --- issue 11: real-part Cortex-M targets and consumer tests ------------------
# The hard-float parts, each on its QEMU board: Cortex-M4F (mps2-an386) and
# M55 (mps3-an547) the portable suite, the M55 but for test_watertight and
# test_frame_modes (up to a minute each there; test_frame_modes renders
# every random scene over capacity too), which run on the M4F, M3, M0 and
# rv32imac. The M55 is ARMv8.1-M's: GCC vectorises the core's loops with
# MVE and uses the low-overhead loops there (vadd.i32, vmul.i32 on q
# registers, dls/le in its -O3 objects), code no other CPU runs. The M7
# (mps2-an500, ARMv7E-M as the M4F) and the M33 (mps2-an505, ARMv8-M
# Mainline, the M55's source paths without MVE) build and run their own
# tests alone (same_isa_tests above). (A clean clone's run had reached 44
# minutes here.)
for cpu in cortex-m4f cortex-m7 cortex-m33 cortex-m55; do
    targets= include= exclude=
    case $cpu in
    cortex-m7 | cortex-m33) targets=$same_isa_targets include="^($same_isa_tests)\$" ;;
    cortex-m55) exclude='^(test_watertight|test_frame_modes)$' ;;
    esac
    BUILD_TARGET=$targets CTEST_INCLUDE=$include CTEST_EXCLUDE=$exclude run "$cpu" -DCMAKE_BUILD_TYPE=Release \
        -DCMAKE_TOOLCHAIN_FILE=port/cortex-m/toolchain-arm-none-eabi.cmake "$cross" -DZLINE_CPU="$cpu"
done
BUILD_TARGET= CTEST_INCLUDE= CTEST_EXCLUDE=
# Issue 27: two cores, one frame on QEMU mps2-an521 (two Cortex-M33 without
# an FPU: soft float): the firmware (port/cortex-m/bench/dual.c) and its
# comparison with the host's single-core frames (CTest dual_an521) and each
# core's instruction budgets (dual_an521_budgets) alone; about 45 s.
BUILD_TARGET=dual CTEST_INCLUDE='^dual_an521' run cortex-m33-an521 -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_TOOLCHAIN_FILE=port/cortex-m/toolchain-arm-none-eabi.cmake "$cross" -DZLINE_CPU=cortex-m33 -DZLINE_FLOAT_ABI=soft
BUILD_TARGET= CTEST_INCLUDE=
# Issue 24: the portable suite built without optimisation (CMake's Debug:
# -g, no -O, the compiler's -O0) on the hard-float Cortex-M4F, where the
# inline assembly once failed to compile ('impossible constraints' in
# fill_blocks_stm): every program of the stage is still compiled and linked
# at -O0. It runs the golden scenes (host equals target at -O0: every mode
# and style through the span assembly), the paths against their reference
# (test_paths_match_reference), the Gouraud bound (test_gouraud_bound, the
# DSP assembly's RGB565 spans) and every other test under 5 s there (33
# tests, 41 CPU seconds: user + sys of the ctest command). The eleven slow
# ones (test_depth_state, test_lines, test_raster_mask, test_fastdiv and
# _minimal, test_smooth_light, test_fast_paths, _minimal and _general,
# test_sizing, test_blend: 165 of the 205 test-seconds of this stage in the
# last CI run, CTest's per-test times) run optimised on the M4F above and on M3, M0, M55 and rv32imac;
# test_frame_modes and test_watertight on those but the M55.
o0_slow='test_depth_state|test_lines|test_raster_mask|test_fastdiv|test_fastdiv_minimal|test_smooth_light'
o0_slow="$o0_slow|test_fast_paths|test_fast_paths_minimal|test_fast_paths_general|test_sizing|test_blend"
CTEST_EXCLUDE="^(test_frame_modes|test_watertight|$o0_slow)\$" run cortex-m4f-O0 -DCMAKE_BUILD_TYPE=Debug \
    -DCMAKE_TOOLCHAIN_FILE=port/cortex-m/toolchain-arm-none-eabi.cmake "$cross" -DZLINE_CPU=cortex-m4f
CTEST_EXCLUDE=
# zline as a consumer uses it: add_subdirectory (host and every CPU/ABI under
# QEMU), install + find_package, FetchContent, pkg-config, vendored sources,
# strict C/C++ header builds, build-time assets and the panel component on
# the host and a Cortex-M4F, the core at -O0/-Og for every preset CPU
# (tests/consumer/run.sh; 3 min 41 s and 4 min 3 s of CPU in two runs, user +
# sys of `time sh tests/consumer/run.sh`, on a loaded machine, issue 24's work).
echo "=== consumer tests"
t0=$(date +%s)
sh tests/consumer/run.sh build/ci-consumer | tee "$log"
grep -q "^consumer: [0-9]* passed, 0 failed" "$log" || exit 1
total=$((total + $(sed -n 's/^consumer: \([0-9]*\) passed, 0 failed.*/\1/p' "$log" | tail -n 1)))
stage_time consumer "$t0"
# --- mutation sample (issue 16) ---------------------------------------------
# Three mutations of tools/mutation/mutations.py, chosen by the date (a
# different three each day), applied to a copy of the tree; each must make the
# host suite fail. Every mutation counts as one test in the closing line.
# The copy starts from the host stage's green Release build (--reuse-build:
# its tree copied, its paths re-pointed, time stamps kept, so make rebuilds
# only what a mutation touches) instead of building the same tree again (the
# host stage's configure and build took 82 s of its 288 s in the last CI
# run); the baseline's suite still runs in the copy before any mutation.
echo "=== mutation sample"
t0=$(date +%s)
mut_log=$(mktemp)
python3 tools/mutation/mutate.py --sample "${MUTATION_SAMPLE:-3}" --jobs "$jobs" --reuse-build build/ci-host |
    tee "$mut_log"
mut_killed=$(sed -n 's/^mutate: \([0-9]*\) killed, 0 survived, 0 stale.*/\1/p' "$mut_log")
rm -f "$mut_log"
[ -n "$mut_killed" ] || { echo "zline: a sampled mutation survived (tools/mutation/mutate.py)"; exit 1; }
total=$((total + mut_killed))
stage_time mutation "$t0"
# ------------------------------------------------------------------------------
# --- fuzzing and static analysis ---------------------------------------------
# Each libFuzzer target for FUZZ_SECONDS, FUZZ_JOBS (2) at a time, one a core.
# With an odd number of targets (nine) the last one would run alone, a core
# idle for its FUZZ_SECONDS: lint's cppcheck (single-threaded, about 54 s of
# CPU, tools/lint/run.sh) runs on that core beside it instead of squeezed in
# beside clang-tidy's two jobs; clang-tidy and gcc -fanalyzer follow when the
# last target is done. Every target still has its seconds on a core of its
# own, and every analyser runs as before.
# 25 s a target (40 s before; five rounds, four of two targets and the last
# beside cppcheck: 75 s of CI's time and 135 CPU seconds less): each run starts by executing every input of
# its committed corpus, seeds and former findings (tests/fuzz/corpus/NAME),
# before it mutates them, and CTest's fuzz_replay_NAME replays that corpus
# in the host stage and, under ASan + UBSan, in the sanitize stage; what the
# shorter time gives up is only the newly generated inputs after 25 s
# (fuzz_light, the fastest, had run 1.3 million inputs in 40 s).
FUZZ_SECONDS=${FUZZ_SECONDS:-25}
export FUZZ_SECONDS
echo "=== fuzzing, $FUZZ_SECONDS s per target"
t0=$(date +%s)
# shellcheck disable=SC2046
set -- $(cd tests/fuzz && ls fuzz_*.c | sed 's/^fuzz_//; s/\.c$//')
fuzz_last=
if [ "${FUZZ_JOBS:-2}" -eq 2 ] && [ $(($# % 2)) -eq 1 ]; then
    eval "fuzz_last=\${$#}"
fi
fuzz_first=
for t; do [ "$t" = "$fuzz_last" ] || fuzz_first="$fuzz_first $t"; done
FUZZ_TARGETS=$fuzz_first sh tests/fuzz/run.sh build/ci-fuzz
lint_cppcheck=$(mktemp)
LINT_STEPS=cppcheck sh tools/lint/run.sh >"$lint_cppcheck" 2>&1 &
cppcheck_pid=$!
if [ -n "$fuzz_last" ]; then
    FUZZ_TARGETS=$fuzz_last sh tests/fuzz/run.sh build/ci-fuzz
fi
stage_time fuzzing "$t0"
echo "=== static analysis (cppcheck since the last fuzz target began)"
t0=$(date +%s)
LINT_STEPS="clang-tidy analyzer" sh tools/lint/run.sh
cppcheck_status=0
wait $cppcheck_pid || cppcheck_status=$?
cat "$lint_cppcheck"
rm -f "$lint_cppcheck"
[ $cppcheck_status -eq 0 ] || exit 1
stage_time "static analysis" "$t0"
echo "=== all test suites passed"
stage_time total "$ci_start"
# The plain closing line: CTest tests of all the builds, the consumer tests
# and the sampled mutations (lint and fuzz runs not counted).
echo "zline: $total passed, 0 failed"
