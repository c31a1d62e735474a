#!/bin/sh
# SPDX-License-Identifier: MIT
# licence_spdx: zline is MIT (LICENSE); every source, header, build and
# script file of the tree says so in an SPDX line near its top, so a file
# copied out of the tree alone (vendoring, the Arduino library) still carries
# its licence.
#
#   tools/lint/check-spdx.sh [SOURCE_DIR]    check the tree (default: this one)
#   tools/lint/check-spdx.sh --self-test     the check itself must fail on a
#                                            tree with one unmarked file
# Files checked: *.c *.h *.cpp *.ino *.ld *.cmake *.sh *.py *.in CMakeLists.txt .ci/run,
# outside build folders. The SPDX line must be within the first 3 lines
# (after a #! line). Prints every file without it; exits 1 if there is one.
set -eu
spdx='SPDX-License-Identifier: MIT'

check_tree() { # check_tree DIR -> 0 when every file is marked
    top=$1
    status=0
    [ -f "$top/LICENSE" ] && head -n 1 "$top/LICENSE" | grep -q '^MIT License$' ||
        { echo "licence_spdx: $top/LICENSE missing or not the MIT licence"; status=1; }
    list=$(mktemp)
    (cd "$top" && find . \( -name 'build*' -o -name '.git' \) -prune -o -type f \
        \( -name '*.[ch]' -o -name '*.cpp' -o -name '*.ino' -o -name '*.ld' -o -name '*.cmake' -o -name '*.sh' -o -name '*.py' \
        -o -name '*.in' -o -name CMakeLists.txt -o -path ./.ci/run \) -print) >"$list"
    count=0
    while IFS= read -r f; do
        count=$((count + 1))
        head -n 3 "$top/$f" | grep -q "$spdx" || { echo "licence_spdx: no '$spdx' line in $f"; status=1; }
    done <"$list"
    rm -f "$list"
    [ "$count" -gt 0 ] || { echo "licence_spdx: no source files under $top"; status=1; }
    [ "$status" -ne 0 ] || echo "licence_spdx: $count files carry the MIT SPDX line"
    return "$status"
}

if [ "${1:-}" = "--self-test" ]; then
    t=$(mktemp -d)
    trap 'rm -rf "$t"' EXIT INT TERM
    printf 'MIT License\n' >"$t/LICENSE"
    printf '/* SPDX-License-Identifier: MIT */\nint a;\n' >"$t/good.c"
    if ! check_tree "$t" >/dev/null; then echo "licence_spdx self-test: a marked tree failed"; exit 1; fi
    printf 'int b;\n' >"$t/bad.h"
    if check_tree "$t" >/dev/null; then echo "licence_spdx self-test: an unmarked header passed"; exit 1; fi
    echo "licence_spdx self-test: an unmarked header fails the check"
    exit 0
fi
check_tree "$(cd "${1:-$(dirname "$0")/../..}" && pwd)"
