#!/bin/sh
# SPDX-License-Identifier: MIT
# Budget integrity (issue 13): fails when budgets.txt (Cortex-M4) or
# budgets-m0.txt (Cortex-M0) raises a budget above the base branch's without
# a "# raised from OLD: REASON" line directly above it (what
# `measure.sh --update-budgets --allow-raise REASON` writes; measure-m0.sh
# likewise). A file the base branch does not have yet raises nothing.
#
#   port/cortex-m/bench/check-budget-raises.sh [BASE_REF]
#
# BASE_REF defaults to $ZLINE_BUDGET_BASE, else main; when that ref does not
# exist (a clone with another branch checked out), origin/main, then HEAD (so a
# raise not yet committed is still caught). Exit 77 (CTest: skipped) outside a
# git checkout.
set -eu
cd "$(dirname "$0")/../../.."
base=${1:-${ZLINE_BUDGET_BASE:-main}}
tmp=${TMPDIR:-/tmp}/zl-budgets-base.$$
trap 'rm -f "$tmp"' EXIT
for ref in "$base" "origin/$base" HEAD; do
    if git rev-parse --verify -q "$ref^{commit}" >/dev/null 2>&1; then
        base=$ref
        break
    fi
done
if ! git rev-parse --verify -q "$base^{commit}" >/dev/null 2>&1; then
    echo "check-budget-raises: no git ref $base: skipped"
    exit 77
fi
status=0
for f in port/cortex-m/bench/budgets.txt port/cortex-m/bench/budgets-m0.txt; do
    git show "$base:$f" >"$tmp" 2>/dev/null || : >"$tmp"
    awk -v base="$base" '
        FILENAME == ARGV[1] { if ($0 !~ /^#/ && NF == 3) old[$1 " " $2] = $3; next }
        /^#/ { reason = ($0 ~ /^# raised from [0-9]+: [^ ]/); next }
        NF == 3 {
            k = $1 " " $2
            if ((k in old) && $3 + 0 > old[k] + 0) {
                if (reason) printf "raised with a reason: %s %s -> %s\n", k, old[k], $3
                else { printf "RAISED WITHOUT A REASON: %s %s -> %s (over %s)\n", k, old[k], $3, base; bad = 1 }
            }
            reason = 0
        }
        END { if (!bad) print "check-budget-raises: " FILENAME ": no budget raised without a reason (against " base ")"; exit bad }' "$tmp" "$f" || status=1
done
exit $status
