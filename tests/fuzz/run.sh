#!/bin/sh
# Build the libFuzzer targets (clang, ASan + UBSan) and fuzz each for a
# bounded time; fail on any finding.
#   tests/fuzz/run.sh [BUILD_DIR]          (default build/fuzz)
# Environment:
#   FUZZ_SECONDS   seconds per target (default 60)
#   FUZZ_TARGETS   which targets (default: all of tests/fuzz/fuzz_*.c)
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
targets=${FUZZ_TARGETS:-$(cd "$top/tests/fuzz" && ls fuzz_*.c | sed 's/^fuzz_//; s/\.c$//')}
cc=${FUZZ_CC:-clang}

cmake -S "$top" -B "$build" -DCMAKE_C_COMPILER="$cc" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DZLINE_FUZZ=ON \
    >/dev/null
for t in $targets; do
    cmake --build "$build" -j "$jobs" --target "fuzz_$t" >/dev/null
done
mkdir -p "$build/artifacts"
status=0
for t in $targets; do
    corpus="$build/corpus/$t"
    mkdir -p "$corpus"
    dict=""
    [ -f "$top/tests/fuzz/$t.dict" ] && dict="-dict=$top/tests/fuzz/$t.dict"
    echo "--- fuzz_$t for ${secs}s"
    # shellcheck disable=SC2086
    if "$build/tests/fuzz/fuzz_$t" -max_total_time="$secs" -timeout=10 -rss_limit_mb=2048 -max_len=4096 \
        -print_final_stats=1 -artifact_prefix="$build/artifacts/$t-" $dict "$corpus" \
        "$top/tests/fuzz/corpus/$t" >"$build/fuzz_$t.log" 2>&1; then
        grep -E "^stat::number_of_executed_units|^stat::new_units_added|^Done " "$build/fuzz_$t.log" || true
    else
        status=1
        echo "fuzz_$t: FINDING (log $build/fuzz_$t.log, input in $build/artifacts/):"
        grep -E "ERROR|SUMMARY|runtime error|guard|Test unit written" "$build/fuzz_$t.log" | head -20 || true
    fi
done
exit $status
