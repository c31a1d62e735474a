#!/bin/sh
# Static analysis of core/ and port/host; CI fails on any finding.
#   cppcheck     warning, style, performance, portability; suppressions in
#                tools/lint/cppcheck-suppressions.txt, each explained there
#   clang-tidy   bugprone, cert, clang-analyzer, misc, portability
#                (configuration and the few disabled checks: .clang-tidy)
#   gcc -fanalyzer  interprocedural checks (leaks, double free, FILE
#                handling, use of uninitialised memory) over port/host, where
#                the heap and files are. core/ has neither; there GCC 12's
#                analyzer only reports NULL paths that contradict invariants
#                it cannot follow through accessor functions, and
#                clang-analyzer (via clang-tidy) already walks every path.
# core/ is also built with -Wconversion -Wsign-conversion -Werror by CMake
# (cmake/Warnings.cmake). Usage: tools/lint/run.sh (no arguments).
# Environment: JOBS (parallel jobs, default 2), CPPCHECK, CLANG_TIDY, GCC.
set -eu
top=$(cd "$(dirname "$0")/../.." && pwd)
cd "$top"
jobs=${JOBS:-2}
cppcheck=${CPPCHECK:-cppcheck}
tidy=${CLANG_TIDY:-clang-tidy}
gcc=${GCC:-gcc}
inc="-Icore/include -Icore/src -Iport/host"
files=$(ls core/src/*.c port/host/*.c)
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
status=0

echo "--- cppcheck"
# shellcheck disable=SC2086
if ! "$cppcheck" --std=c99 --enable=warning,style,performance,portability --inline-suppr \
    --error-exitcode=1 --quiet -UZL_CONFIG_HEADER -D__GNUC__ \
    --suppressions-list=tools/lint/cppcheck-suppressions.txt $inc core/src port/host; then
    status=1
fi

echo "--- clang-tidy"
# shellcheck disable=SC2086
if ! printf '%s\n' $files | xargs -P "$jobs" -I{} sh -c \
    '"$1" --quiet "$2" -- -std=c99 $3 >"$4/$(basename "$2").tidy" 2>&1 || { cat "$4/$(basename "$2").tidy"; exit 1; }' \
    sh "$tidy" {} "$inc" "$out"; then
    status=1
fi

echo "--- gcc -fanalyzer (port/host)"
# shellcheck disable=SC2086
if ! printf '%s\n' port/host/*.c | xargs -P "$jobs" -I{} sh -c \
    '"$1" -std=c99 -O1 -fanalyzer -Werror $3 -c "$2" -o /dev/null' sh "$gcc" {} "$inc"; then
    status=1
fi

[ $status -eq 0 ] && echo "--- static analysis: no findings"
exit $status
