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
# LINT_BUILD (where CMake writes compile_commands.json, default build/lint),
# LINT_STEPS (which of "cppcheck clang-tidy analyzer" to run, default all
# three; tests/run-all.sh runs cppcheck beside the last fuzz target, on the
# core that target leaves free, and the other two after it).
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
db="$build/compile_commands.json"
steps=" ${LINT_STEPS:-cppcheck clang-tidy analyzer} "
has() { case $steps in *" $1 "*) return 0 ;; esac; return 1; } # has STEP: STEP is to run
status=0
# gcc -fanalyzer, one file; the script runs itself with --analyse for it.
analyse() { # analyse FILE: gcc -fanalyzer with FILE's own compile command, its output sent nowhere
    cmd=$(grep -B1 "\"file\": \"$top/$1\"" "$db" | sed -n 's/^ *"command": "\(.*\)",$/\1/p' |
        sed 's/ -o [^ ]*/ -o \/dev\/null/')
    if [ -z "$cmd" ]; then
        echo "$1: not in $db"
        return 1
    fi
    (cd "$build" && eval "$cmd -fanalyzer")
}
if [ "${1:-}" = --analyse ]; then # a worker of the gcc -fanalyzer step below
    analyse "$2"
    exit
fi

for step in $steps; do
    case $step in cppcheck | clang-tidy | analyzer) ;; *) echo "lint: unknown step '$step' (LINT_STEPS)"; exit 2 ;; esac
done
mkdir -p "$build"

# The compile commands of the real build (include paths, defines, the
# project's warnings) come from CMake's compile_commands.json; nothing is
# built. (cppcheck alone does not need them.)
if has clang-tidy || has analyzer; then
    cmake -S "$top" -B "$build" -DCMAKE_C_COMPILER="$gcc" -DCMAKE_BUILD_TYPE=Debug >/dev/null
fi

# cppcheck runs on one core in the background while clang-tidy and gcc
# -fanalyzer share the cores (cppcheck took 54 s of CPU alone; its own -j
# would leave out the whole-program checks without a build folder); its lines
# are shown at the end.
cppcheck_pid=
if has cppcheck; then
    # shellcheck disable=SC2086
    "$cppcheck" --std=c99 --enable=warning,style,performance,portability --inline-suppr \
        --error-exitcode=1 --quiet -UZL_CONFIG_HEADER -D__GNUC__ \
        --suppressions-list=tools/lint/cppcheck-suppressions.txt $inc core/src port/host >"$build/cppcheck.log" 2>&1 &
    cppcheck_pid=$!
fi

if has clang-tidy; then
echo "--- clang-tidy"
# clang-tidy analyses a file once per compile command of it, and the tests
# build the core in seven variants (default, minimal, no cache, 32-bit
# multiply, small code, fast paths off, mesh read hook): seven analyses of
# every core file took 12 of CI's 58 minutes. It reads a filtered database:
# the default library (every feature on, so every switched branch is seen)
# and the minimal one (where the switches compile code out: the dead stores
# and unused values that leaves are found there), plus every other file's
# commands.
tidy_db="$build/tidy"
mkdir -p "$tidy_db"
python3 - "$db" "$tidy_db/compile_commands.json" <<'PY'
import json, sys
keep = ("CMakeFiles/zline.dir/", "CMakeFiles/zline_minimal.dir/")
entries = json.load(open(sys.argv[1]))
def wanted(e):
    if "/core/src/" not in e["file"]:
        return True
    out = e.get("output") or e["command"].split(" -o ", 1)[1].split()[0]
    return out.startswith(keep)
kept = [e for e in entries if wanted(e)]
json.dump(kept, open(sys.argv[2], "w"), indent=1)
core = {e["file"] for e in entries if "/core/src/" in e["file"]}
missing = core - {e["file"] for e in kept}
if missing:
    sys.exit("lint: core files without a default or minimal command: " + " ".join(sorted(missing)))
PY
# shellcheck disable=SC2086
if ! printf '%s\n' $files | xargs -P "$jobs" -I{} sh -c \
    'out=$("$1" --quiet -p "$2" --extra-arg=-Wno-unknown-warning-option "$3" 2>&1) || { printf "%s\n" "$out"; exit 1; }' \
    sh "$tidy" "$tidy_db" {}; then
    status=1
fi
fi

if has analyzer; then
    echo "--- gcc -fanalyzer (port/host)"
    # JOBS files at a time (xargs -P: each a worker, this script with --analyse).
    if ! printf '%s\n' port/host/*.c | xargs -P "$jobs" -I{} sh "$top/tools/lint/run.sh" --analyse {}; then
        status=1
    fi
fi

if [ -n "$cppcheck_pid" ]; then
    echo "--- cppcheck"
    wait $cppcheck_pid || status=1
    cat "$build/cppcheck.log"
fi

[ $status -eq 0 ] && echo "--- static analysis ($(echo $steps)): no findings"
exit $status
