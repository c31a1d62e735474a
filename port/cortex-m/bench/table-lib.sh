# SPDX-License-Identifier: MIT
# Shell helpers shared by the benchmark table scripts (port/cortex-m/bench/
# measure.sh, measure-m0.sh, port/riscv/bench/measure.sh), sourced after they
# have written $R, their results file of "tag scene key value" lines.
#   get TAG SCENE KEY   the value, or nothing
#   num VALUE           with thousands separators ("n/a" when empty)
#   div A B             A / B to one decimal ("n/a" when either is missing or B is 0)
get() { awk -v t="$1" -v s="$2" -v k="$3" '$1 == t && $2 == s && $3 == k { print $4; exit }' "$R"; }
num() { awk -v v="$1" 'BEGIN { if (v == "") print "n/a"; else { g = v < 0 ? "-" : ""; s = sprintf("%d", v < 0 ? -v : v); o = ""; while (length(s) > 3) { o = "," substr(s, length(s) - 2) o; s = substr(s, 1, length(s) - 3) } print g s o } }'; }
div() { awk -v a="$1" -v b="$2" 'BEGIN { if (a == "" || b == "" || b == 0) print "n/a"; else printf "%.1f", a / b }'; }
