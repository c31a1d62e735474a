#!/bin/sh
# SPDX-License-Identifier: MIT
# Each core's instructions in the two-core frame on QEMU mps2-an521 (issue
# 27): runs dual.elf (dual.c) with the vcpucount plugin (tools/qemu-vcpu-count,
# built here with the host compiler), which notes every core's count at each
# mark(); prints the table and checks budgets-an521.txt.
#
#   port/cortex-m/bench/measure-an521.sh [--update-budgets [--allow-raise REASON]] DUAL_ELF
#
# Per scene (bunny, tris), from dual.c's marks: one core = the single-core
# frame on core 0 (m1 - m0); serial = submission + split (m3 - m2); prepare
# per core (m4 - m3, n1 - n0); the barrier's cost = the smaller of the two
# cores' barrier intervals (m5 - m4, n2 - n1: the core arriving last waits
# no round; the other's spinning is waiting, not work); bands per core
# (m6 - m5, n3 - n2). Critical path = serial + the larger prepare + the
# barrier + the larger bands. Budget lines "an521 SCENE_KEY N" for core0
# (serial + prepare + bands), core1 (prepare + bands) and critical: a
# measurement above its budget fails (exit 1). --update-budgets rewrites
# budgets-an521.txt (+3 %, rounded up to 1000) through update-budgets.sh:
# it only lowers, unless --allow-raise REASON.
set -eu
here=$(pwd)
cd "$(dirname "$0")/../../.."
update=0
raise_reason=
if [ "${1:-}" = --update-budgets ]; then
    update=1; shift
    if [ "${1:-}" = --allow-raise ]; then
        [ -n "${2:-}" ] || { echo "measure-an521.sh: --allow-raise needs a REASON" >&2; exit 2; }
        raise_reason=$2; shift 2
    fi
fi
elf=${1:?usage: measure-an521.sh [--update-budgets [--allow-raise REASON]] DUAL_ELF}
case $elf in /*) ;; *) elf=$here/$elf ;; esac
budgets=port/cortex-m/bench/budgets-an521.txt
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
${CC:-cc} -std=c99 -O2 -shared -fPIC -o "$out/vcpucount.so" tools/qemu-vcpu-count/vcpucount.c
mark=$(arm-none-eabi-nm "$elf" | awk '$3 == "mark" { print "0x" $1 }')
[ -n "$mark" ] || { echo "measure-an521.sh: no mark() in $elf" >&2; exit 2; }
(cd "$out" && qemu-system-arm -M mps2-an521 -nographic -monitor none -serial none \
    -chardev stdio,id=semi -semihosting-config enable=on,target=native,chardev=semi \
    -plugin "$out/vcpucount.so,mark=$mark,out=$out/marks.txt" -kernel "$elf" \
    >"$out/run.txt") || { cat "$out/run.txt"; echo "measure-an521.sh: the firmware failed" >&2; exit 1; }

# core 0 marks 7 a scene (m0..m6), core 1 marks 4 (n0..n3); scenes in dual.c's order
awk -v scenes="bunny tris" '
    $1 == "MARK" { c[$2, $3] = $4 }
    END {
        n = split(scenes, s, " ")
        print "### Two cores, one frame, Cortex-M33 (mps2-an521, each core counted by the vcpucount plugin)"
        print ""
        print "| scene | one core | serial: submit + split | prepare, core 0 | prepare, core 1 | barrier | bands, core 0 | bands, core 1 | critical path | critical / one core |"
        print "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
        for (i = 1; i <= n; i++) {
            a = (i - 1) * 7; b = (i - 1) * 4
            if (!((0 SUBSEP (a + 6)) in c) || !((1 SUBSEP (b + 3)) in c)) { print "measure-an521.sh: marks missing" > "/dev/stderr"; exit 1 }
            one = c[0, a + 1] - c[0, a]; serial = c[0, a + 3] - c[0, a + 2]
            p0 = c[0, a + 4] - c[0, a + 3]; p1 = c[1, b + 1] - c[1, b]
            w0 = c[0, a + 5] - c[0, a + 4]; w1 = c[1, b + 2] - c[1, b + 1]; wait = w0 < w1 ? w0 : w1
            b0 = c[0, a + 6] - c[0, a + 5]; b1 = c[1, b + 3] - c[1, b + 2]
            crit = serial + (p0 > p1 ? p0 : p1) + wait + (b0 > b1 ? b0 : b1)
            printf "| %s | %d | %d | %d | %d | %d | %d | %d | %d | %.3f |\n", s[i], one, serial, p0, p1, wait, b0, b1, crit, crit / one
            printf "VALUE an521 %s_core0 %d\nVALUE an521 %s_core1 %d\nVALUE an521 %s_critical %d\n", s[i], serial + p0 + b0, s[i], p1 + b1, s[i], crit > "'"$out"'/values.txt"
        }
    }' "$out/marks.txt" >"$out/table.txt"
sed 's/ \([0-9]\{1,3\}\)\([0-9]\{3\}\)\([0-9]\{3\}\) |/ \1,\2,\3 |/g; s/ \([0-9]\{1,3\}\)\([0-9]\{3\}\) |/ \1,\2 |/g' "$out/table.txt" |
    sed 's/ \([0-9]\{1,3\}\)\([0-9]\{3\}\)\([0-9]\{3\}\) |/ \1,\2,\3 |/g; s/ \([0-9]\{1,3\}\)\([0-9]\{3\}\) |/ \1,\2 |/g'

status=0
while read -r _ tag key value; do
    budget=$(awk -v t="$tag" -v k="$key" '$1 == t && $2 == k { print $3 }' "$budgets")
    suggest=$(( (value * 103 / 100 + 999) / 1000 * 1000 ))
    echo "$tag $key $suggest" >>"$out/suggest.txt"
    if [ -z "$budget" ]; then
        echo "BUDGET FAIL $tag $key: no budget in $budgets (measured $value)"; status=1
    elif [ "$value" -gt "$budget" ]; then
        echo "BUDGET FAIL $tag $key: $value > $budget"; status=1
    else
        echo "BUDGET ok $tag $key: $value <= $budget"
    fi
done <"$out/values.txt"
if [ $update -eq 1 ]; then
    sort "$out/suggest.txt" >"$out/suggest.sorted"
    sh port/cortex-m/bench/update-budgets.sh "$budgets" "$out/suggest.sorted" "$raise_reason" >"$out/budgets.new"
    cp "$out/budgets.new" "$budgets"
    echo "measure-an521.sh: $budgets updated" >&2
    status=0
fi
exit $status
