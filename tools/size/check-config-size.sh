#!/bin/sh
# SPDX-License-Identifier: MIT
# config_size_table: README's "Core flash per configuration" table is what
# tools/size/config-size.sh measures now, byte for byte (the compilers are
# deterministic). Refresh it with
#   python3 tools/docs/refresh.py --config-size build/config-size
#
#   tools/size/check-config-size.sh [work-dir]
# Exit 77 (CTest: skipped, which CI counts as a failure) when a compiler is
# missing.
set -eu
root=$(cd "$(dirname "$0")/../.." && pwd)
work=${1:-$root/build/config-size-check}
mkdir -p "$work"
status=0
sh "$root/tools/size/config-size.sh" "$work" >"$work/measured.md" 2>"$work/err.txt" || status=$?
[ "$status" -ne 2 ] || { cat "$work/err.txt"; echo "config_size_table: skipped, a compiler is missing"; exit 77; }
[ "$status" -eq 0 ] || { cat "$work/err.txt"; echo "config_size_table: config-size.sh failed"; exit 1; }
awk '/^<!-- measured: Core flash per configuration \(tools\/size\/config-size.sh\) -->$/ { on = 1; next }
     on && /^\|/ { print; next } on { exit }' "$root/README.md" >"$work/readme.md"
[ -s "$work/readme.md" ] || { echo "config_size_table: README.md has no such table"; exit 1; }
if ! cmp -s "$work/readme.md" "$work/measured.md"; then
    echo "config_size_table: README.md's table differs from the measurement:"
    diff "$work/readme.md" "$work/measured.md" || true
    exit 1
fi
echo "config_size_table: README.md's table is the measurement ($(($(wc -l <"$work/measured.md") - 2)) rows)"
