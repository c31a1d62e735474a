#!/bin/sh
# SPDX-License-Identifier: MIT
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
# Environment: JOBS (parallel jobs, default 2), CPPCHECK, CLANG_TIDY, GCC,
# LINT_BUILD (where CMake writes compile_commands.json, default build/lint).
set -eu
top=$(cd "$(dirname "$0")/../.." && pwd)
cd "$top"
jobs=${JOBS:-2}
cppcheck=${CPPCHECK:-cppcheck}
tidy=${CLANG_TIDY:-clang-tidy}
gcc=${GCC:-gcc}
build=${LINT_BUILD:-$top/build/lint}
inc="-Icore/include -Iport/host"
files=$(ls core/src/*/*.c port/host/*.c)
status=0

# The compile commands of the real build (include paths, defines, the
# project's warnings) come from CMake's compile_commands.json; nothing is
# built.
cmake -S "$top" -B "$build" -DCMAKE_C_COMPILER="$gcc" -DCMAKE_BUILD_TYPE=Debug >/dev/null
db="$build/compile_commands.json"

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
    'out=$("$1" --quiet -p "$2" --extra-arg=-Wno-unknown-warning-option "$3" 2>&1) || { printf "%s\n" "$out"; exit 1; }' \
    sh "$tidy" "$build" {}; then
    status=1
fi

echo "--- gcc -fanalyzer (port/host)"
for f in port/host/*.c; do
    # the file's own compile command, its output sent nowhere
    cmd=$(grep -B1 "\"file\": \"$top/$f\"" "$db" | sed -n 's/^ *"command": "\(.*\)",$/\1/p' |
        sed 's/ -o [^ ]*/ -o \/dev\/null/')
    if [ -z "$cmd" ]; then
        echo "$f: not in $db"
        status=1
        continue
    fi
    if ! (cd "$build" && eval "$cmd -fanalyzer"); then
        status=1
    fi
done

[ $status -eq 0 ] && echo "--- static analysis: no findings"
exit $status
