#!/bin/sh
# SPDX-License-Identifier: MIT
# Rewrite the golden images after an intended change of the output, then look
# at every one of them (tests/golden/*.png are made for that) before committing.
# Each image is checked by the test reference (golden_check) first; CTest runs
# the same check on the committed images (golden_<name>_reference).
#   tests/golden/regenerate.sh [BUILD_DIR]
set -eu
cd "$(dirname "$0")/../.."
render=${1:-build}/port/host/zline-render
grep -v '^#' tests/golden/golden.txt | while IFS= read -r line; do
    name=${line%%|*}; rest=${line#*|}; model=${rest%%|*}; args=${rest#*|}
    [ "$args" = "$rest" ] && args=""
    # shellcheck disable=SC2086
    "$render" $(echo "$args" | tr '|' ' ') "$model" "tests/golden/$name.ppm"
    # the reference (tests/support/zt_ref) must agree before the image is kept
    # shellcheck disable=SC2086
    "${1:-build}/tests/host/golden_check" "tests/golden/$name.ppm" "$model" $(echo "$args" | tr '|' ' ') ||
        { echo "golden_check rejects tests/golden/$name.ppm: not kept"; git checkout -- "tests/golden/$name.ppm"; exit 1; }
    pnmtopng "tests/golden/$name.ppm" > "tests/golden/$name.png"
    echo "wrote tests/golden/$name.ppm (look at tests/golden/$name.png)"
done
