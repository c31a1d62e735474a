#!/bin/sh
# SPDX-License-Identifier: MIT
# core_dependencies: the pipeline folders of core/src depend one way.
#
#   tools/depcheck/check-deps.sh [SOURCE_DIR]
#
# Every file of core/src/N_stage/ may use only stages 1..N: its quoted
# includes name a folder of a stage at or below its own, and every function
# or object it uses from another core file (read from the compiled objects'
# symbol tables with nm, so it sees calls, not just declarations) is defined
# at or below its stage. Within a stage the file-level graph of those uses
# must have no cycle. No core file may exceed MAX_LINES (default 800).
# Prints every violation and exits 1 if there is one.
set -eu
top=$(cd "${1:-$(dirname "$0")/../..}" && pwd)
cc=${CC:-cc}
nm=${NM:-nm}
max_lines=${MAX_LINES:-800}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT INT TERM
status=0
fail() { echo "core_dependencies: $*"; status=1; }

stage_of() { # core/src/3_raster/zl_rows.c -> 3
    basename "$(dirname "$1")" | sed 's/_.*//'
}

files=$(cd "$top" && ls core/src/*/*.c core/src/*/*.h)
[ -n "$files" ] || { echo "core_dependencies: no sources under $top/core/src"; exit 1; }

# 1. includes, and file length
for f in $files; do
    s=$(stage_of "$f")
    case $s in [1-9]) ;; *) fail "$f: folder is not named N_stage"; continue ;; esac
    n=$(wc -l < "$top/$f")
    [ "$n" -le "$max_lines" ] || fail "$f: $n lines, more than $max_lines"
    for inc in $(sed -n 's/^#include "\.\.\/\([0-9]\)_[a-z_]*\/.*/\1/p' "$top/$f"); do
        [ "$inc" -le "$s" ] || fail "$f (stage $s) includes a header of stage $inc"
    done
done

# 2. symbols: defined and used per object
for f in $files; do
    case $f in *.c) ;; *) continue ;; esac
    o=$work/$(echo "$f" | tr '/' '_').o
    "$cc" -std=c99 -O2 -I"$top/core/include" -c "$top/$f" -o "$o"
    "$nm" --defined-only "$o" | awk -v f="$f" '$2 ~ /^[TDRBC]$/ {print $3, f}' >> "$work/defs"
    "$nm" --undefined-only "$o" | awk -v f="$f" '{print $NF, f}' >> "$work/uses"
done
sort -k1,1 "$work/defs" > "$work/defs.s"
sort -k1,1 "$work/uses" > "$work/uses.s"
# user file, provider file, symbol (core symbols only)
join "$work/uses.s" "$work/defs.s" | awk '{print $2, $3, $1}' | sort -u > "$work/edges"
while read -r user provider sym; do
    [ "$user" = "$provider" ] && continue
    su=$(stage_of "$user"); sp=$(stage_of "$provider")
    [ "$sp" -le "$su" ] || fail "$user (stage $su) uses $sym of $provider (stage $sp)"
done < "$work/edges"

# 3. no cycle between files (tsort reports one on stderr)
awk '$1 != $2 {print $2, $1}' "$work/edges" | sort -u > "$work/pairs"
if ! tsort "$work/pairs" > /dev/null 2> "$work/tsort.err" || [ -s "$work/tsort.err" ]; then
    fail "a cycle of calls between files:"
    sed 's/^/    /' "$work/tsort.err"
fi

if [ "$status" -eq 0 ]; then
    echo "core_dependencies: OK: $(echo "$files" | wc -l) files, $(wc -l < "$work/edges") cross-file uses, all one way"
fi
exit "$status"
