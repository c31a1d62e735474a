#!/bin/sh
# SPDX-License-Identifier: MIT
# Build the libFuzzer targets (clang, ASan + UBSan) and fuzz each for a
# bounded time; fail on any finding.
#   tests/fuzz/run.sh [BUILD_DIR]          (default build/fuzz)
# Environment:
#   FUZZ_SECONDS   seconds per target (default 60)
#   FUZZ_TARGETS   which targets (default: all of tests/fuzz/fuzz_*.c)
#   FUZZ_JOBS      targets fuzzed at once (default 2)
#   JOBS           build parallelism (default 2)
# Each target starts from its committed corpus (tests/fuzz/corpus/NAME/,
# read only) plus what earlier runs in BUILD_DIR found. A crash, leak,
# sanitizer report, timeout (10 s per input) or out-of-memory leaves its
# input in BUILD_DIR/artifacts/; commit it to tests/fuzz/corpus/NAME/ with the
# fix (CTest replays that corpus in every host build) and add a unit test.
set -eu
top=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$top/build/fuzz}
secs=${FUZZ_SECONDS:-60}
jobs=${JOBS:-2}
fjobs=${FUZZ_JOBS:-2}
targets=${FUZZ_TARGETS:-$(cd "$top/tests/fuzz" && ls fuzz_*.c | sed 's/^fuzz_//; s/\.c$//')}
cc=${FUZZ_CC:-clang}

cmake -S "$top" -B "$build" -DCMAKE_C_COMPILER="$cc" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DZLINE_FUZZ=ON \
    >/dev/null
# every target in one build: their own files compile side by side
# shellcheck disable=SC2046
cmake --build "$build" -j "$jobs" --target $(for t in $targets; do echo "fuzz_$t"; done) >/dev/null
mkdir -p "$build/artifacts"
# run_one NAME: fuzz one target; its log goes to BUILD_DIR/fuzz_NAME.log and
# a line "NAME ok|FINDING" to BUILD_DIR/fuzz_NAME.status.
run_one() {
    t=$1
    corpus="$build/corpus/$t"
    mkdir -p "$corpus"
    dict=""
    [ -f "$top/tests/fuzz/$t.dict" ] && dict="-dict=$top/tests/fuzz/$t.dict"
    # shellcheck disable=SC2086
    if "$build/tests/fuzz/fuzz_$t" -max_total_time="$secs" -timeout=10 -rss_limit_mb=2048 -max_len=4096 \
        -print_final_stats=1 -artifact_prefix="$build/artifacts/$t-" $dict "$corpus" \
        "$top/tests/fuzz/corpus/$t" >"$build/fuzz_$t.log" 2>&1; then
        echo ok >"$build/fuzz_$t.status"
    else
        echo FINDING >"$build/fuzz_$t.status"
    fi
}
# FUZZ_JOBS targets at a time (default 2: one per core of the CI machine).
status=0
set -- $targets
while [ $# -gt 0 ]; do
    batch=""
    n=0
    while [ $# -gt 0 ] && [ $n -lt "$fjobs" ]; do
        batch="$batch $1"
        n=$((n + 1))
        shift
    done
    echo "--- fuzzing${batch} for ${secs}s"
    for t in $batch; do
        run_one "$t" &
    done
    wait
    for t in $batch; do
        if [ "$(cat "$build/fuzz_$t.status")" = ok ]; then
            printf 'fuzz_%s: ' "$t"
            grep -E "^stat::number_of_executed_units" "$build/fuzz_$t.log" | sed 's/.*: *//; s/$/ inputs, no finding/' || true
        else
            status=1
            echo "fuzz_$t: FINDING (log $build/fuzz_$t.log, input in $build/artifacts/):"
            grep -E "ERROR|SUMMARY|runtime error|guard|Test unit written|: .*==|FZ_REQUIRE|\.c:[0-9]+: " \
                "$build/fuzz_$t.log" | head -20 || true
        fi
    done
done
exit $status
