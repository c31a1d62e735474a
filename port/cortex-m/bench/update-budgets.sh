#!/bin/sh
# SPDX-License-Identifier: MIT
# Budgets file update shared by measure.sh (budgets.txt, Cortex-M4) and
# measure-m0.sh (budgets-m0.txt): prints BUDGETS rewritten from SUGGEST (the
# benchmarks' "tag scene value" suggestions, sorted). It only LOWERS budgets
# and adds lines for new scenes: a suggestion above the old budget keeps the
# old one, with a warning, unless REASON is given; then it is raised with a
# "# raised from OLD: REASON" line above it. The header (leading comment
# block) stays; each budget line keeps the comment lines just above it.
#
#   update-budgets.sh BUDGETS SUGGEST [REASON] >NEW
set -eu
raise_reason=${3:-}
awk -v reason="$raise_reason" -v suggest="$2" '
    BEGIN { header = 1 }
    /^#/ { if (header) head = head $0 "\n"; else note = note $0 "\n"; next }
    NF == 3 { header = 0; k = $1 " " $2; old[k] = $3; notes[k] = note; note = ""; keys[k] = 1; next }
    END {
        printf "%s", head
        while ((getline l < suggest) > 0) {
            split(l, f, " "); k = f[1] " " f[2]; v = f[3]; seen[k] = 1
            if (k in old && v > old[k] + 0) {
                if (reason == "") {
                    printf "measure.sh: %s would rise %s -> %s: kept (--allow-raise REASON to raise)\n", k, old[k], v > "/dev/stderr"
                    v = old[k]
                } else {
                    notes[k] = notes[k] "# raised from " old[k] ": " reason "\n"
                }
            }
            out[k] = notes[k] k " " v
        }
        for (k in keys) if (!(k in seen)) out[k] = notes[k] k " " old[k] # not measured here: unchanged
        n = 0; for (k in out) list[++n] = k
        for (i = 2; i <= n; i++) { x = list[i]; for (j = i - 1; j >= 1 && list[j] > x; j--) list[j + 1] = list[j]; list[j + 1] = x }
        for (i = 1; i <= n; i++) print out[list[i]]
    }' "$1"
