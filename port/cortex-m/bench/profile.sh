#!/bin/sh
# SPDX-License-Identifier: MIT
# Per-function instruction profile of the Cortex-M4 benchmark (issue 4: "where
# the instructions go"). Builds bench_frame_O2 and bench_scanline_O2 (the
# firmware of measure.sh), runs each under QEMU mps2-an386 with -icount
# shift=6 and the m4timing plugin with profile=FILE,from=I,to=J, where I and J
# are the marks of one scene's measured frame ("INTERVAL ... SCENE total I J"),
# maps every executed instruction address to the function containing it (FUNC
# symbols of the ELF, readelf) and the object it came from (the link map), and
# prints a markdown table per firmware: the TOP functions by instructions
# executed inside that frame.
#
#   port/cortex-m/bench/profile.sh [BUILD_DIR]  (env: SCENE=bunny TOP=20 KEY=total; KEY=total_vcache
#   profiles the frame-mode frame drawn through the vertex cache; TAGS=smooth-O2 SCENE=bunny_smooth
#   KEY=draw the bunny with per-vertex colours of bench_smooth.c; TAGS=features-O2 SCENE=line one per-pixel loop
#   of bench_features.c (line, line_aa, tex_affine, blend, ...)
#
# CPU=cortex-m0 profiles the Cortex-M0 build instead (QEMU microbit, -icount
# shift=7, the nRF51 timer: bench_timer_nrf51.c; the plugin's instruction
# counts hold for any Thumb code, its cycle model is the M4's and unused here).
# BUILD_DIR defaults to build/CPU-profile (cortex-m4 unless CPU says). Check: the profile's total is
# the plugin's count between the two marks, which includes mark()'s own
# instructions; the timer's interval subtracts them (calibrated overhead), so
#   profile total - timer interval = n * e - (n - 1) * overhead
# with n = J - I marks, e = the plugin's count of an empty interval (marks 0
# and 1) and overhead the timer's ("# timer:" line). The script checks both.
set -eu
cd "$(dirname "$0")/../../.."
cpu=${CPU:-cortex-m4}
build=${1:-build/$cpu-profile}
scene=${SCENE:-bunny}
top=${TOP:-20}
key=${KEY:-total}
tags=${TAGS:-frame-O2 scanline-O2}
bench=$build/port/cortex-m/bench
out=$build/profile
mkdir -p "$out"

cmake -S . -B "$build" -DCMAKE_TOOLCHAIN_FILE=port/cortex-m/toolchain-arm-none-eabi.cmake \
    -DZLINE_CPU="$cpu" -DCMAKE_BUILD_TYPE=Release >/dev/null
# bench_smooth is a Cortex-M4/M3 firmware only
smooth=; [ "$cpu" = cortex-m0 ] || smooth=bench_smooth_O2
cmake --build "$build" -j 2 --target bench_frame_O2 bench_scanline_O2 bench_features_O2 $smooth >/dev/null
if [ "$cpu" = cortex-m0 ]; then
    board="-M microbit -global nrf51-soc.flash-size=4194304 -global nrf51-soc.sram-size=4194304"; shift=7
else
    board="-M mps2-an386"; shift=6
fi

plugin=$out/m4timing.so
if ! ${CC:-cc} -std=c99 -O2 -shared -fPIC -o "$plugin" tools/qemu-m4-timing/m4timing.c 2>"$out/plugin.log"; then
    echo "profile.sh: cannot build the plugin (see $out/plugin.log)" >&2
    exit 1
fi

tab=$(printf '\t')
status=0
for tag in $tags; do
    mode=${tag%-*}; opt=${tag#*-}
    elf=$bench/bench_${mode}_${opt}.elf
    mark=$(arm-none-eabi-nm "$elf" | awk '$3 == "mark" { print "0x" $1 }')
    # shellcheck disable=SC2086 # $board splits on spaces
    set -- qemu-system-arm $board -nographic -monitor none -serial none \
        -chardev stdio,id=semi -semihosting-config enable=on,target=native,chardev=semi -icount shift=$shift
    # first run: the mark numbers of the scene's frame (runs are deterministic)
    "$@" -kernel "$elf" >"$out/$tag.pass1.txt" || true
    iv=$(awk -v s="$scene" -v key="$key" '$1 == "INTERVAL" && $3 == s && $4 == key { print $6, $7; exit }' "$out/$tag.pass1.txt")
    if [ -z "$iv" ] && [ "$key" != total ]; then
        continue # only frame mode has the vertex-cache interval
    fi
    if [ -z "$iv" ]; then
        echo "profile.sh: no interval '$scene $key' in $out/$tag.pass1.txt" >&2
        exit 1
    fi
    from=${iv% *}; to=${iv#* }
    "$@" -plugin "$plugin,mark=$mark,out=$out/$tag.marks,profile=$out/$tag.prof,from=$from,to=$to" \
        -kernel "$elf" >"$out/$tag.txt" || true

    arm-none-eabi-readelf -sW "$elf" | awk '$4 == "FUNC" { print $2, $3, $8 }' >"$out/$tag.syms"
    # per function (tab-separated): name, object, instructions, entries (executions of its first instruction)
    awk -v syms="$out/$tag.syms" -v map="$elf.map" -v prof="$out/$tag.prof" '
        function hex(h,   i, v) { v = 0; h = tolower(h); sub(/^0x/, "", h); for (i = 1; i <= length(h); i++) v = v * 16 + index("0123456789abcdef", substr(h, i, 1)) - 1; return v }
        function short(f) {
            if (f ~ /libgcc\.a\(/) { sub(/.*libgcc\.a\(/, "", f); sub(/\.o\)$/, "", f); return "libgcc " f }
            if (f ~ /libzline_[A-Za-z0-9]*\.a\(/) { sub(/.*libzline_[A-Za-z0-9]*\.a\(/, "", f); sub(/\.obj\)$/, "", f); return "core " f }
            if (f ~ /lib(c|c_nano|g|nosys)\.a\(/) { sub(/.*\.a\(/, "", f); sub(/\)$/, "", f); return "newlib " f }
            sub(/.*\//, "", f); sub(/\.obj$/, "", f); return f
        }
        BEGIN {
            # function symbols: start (Thumb bit off), size; aliases joined
            while ((getline l < syms) > 0) {
                split(l, f, " "); a = hex(f[1]); a -= a % 2
                if (a in nm) { if (index("/" nm[a] "/", "/" f[3] "/") == 0) nm[a] = nm[a] "/" f[3]; if (f[2] + 0 > sz[a]) sz[a] = f[2] + 0 }
                else { nm[a] = f[3]; sz[a] = f[2] + 0; st[++n] = a }
            }
            # sort starts (insertion sort, a few hundred symbols)
            for (i = 2; i <= n; i++) { v = st[i]; for (j = i - 1; j > 0 && st[j] > v; j--) st[j + 1] = st[j]; st[j + 1] = v }
            # input sections of the link map: address range -> object
            on = 0
            while ((getline l < map) > 0) {
                if (l ~ /^Linker script and memory map/) on = 1
                if (!on) continue
                k = split(l, f, " ")
                if (l ~ /^ \.(text|rodata)/) { pend = (k < 4); if (k >= 4) { ra[++m] = hex(f[2]); rs[m] = hex(f[3]); rf[m] = f[4] } continue }
                if (pend && k == 3 && f[1] ~ /^0x/) { ra[++m] = hex(f[1]); rs[m] = hex(f[2]); rf[m] = f[3] }
                pend = 0
            }
        }
        function find(pc,   lo, hi, mid) {
            lo = 1; hi = n
            if (n == 0 || pc < st[1]) return 0
            while (lo < hi) { mid = int((lo + hi + 1) / 2); if (st[mid] <= pc) lo = mid; else hi = mid - 1 }
            return lo
        }
        END {
            while ((getline l < prof) > 0) {
                if (l ~ /^#/) { if (l ~ /^# total/) { split(l, f, " "); ptotal = f[3] } continue }
                split(l, f, " "); pc = hex(f[1]); c = f[2] + 0
                i = find(pc)
                if (i == 0) name = "(below all symbols)"
                else {
                    a = st[i]
                    if (sz[a] > 0 && pc >= a + sz[a]) name = "(after " nm[a] ")"
                    else name = nm[a]
                    if (pc == a) ent[name] += c
                    if (!(name in obj)) {
                        obj[name] = "?"
                        for (r = 1; r <= m; r++) if (rs[r] > 0 && a >= ra[r] && a < ra[r] + rs[r]) { obj[name] = short(rf[r]); break }
                    }
                }
                ins[name] += c; sum += c
            }
            for (name in ins) printf "%s\t%s\t%d\t%d\n", name, (name in obj) ? obj[name] : "?", ins[name], ent[name]
            printf "TOTAL - %d %d\n", sum, ptotal > "/dev/stderr"
        }' 2>"$out/$tag.total" | sort -t "$tab" -k3,3nr >"$out/$tag.functions"

    # checks: the profile against the plugin marks and against the timer
    T=$(awk -v s="$scene" -v key="$key" '$1 == "INTERVAL" && $3 == s && $4 == key { print $5; exit }' "$out/$tag.txt")
    ov=$(awk '/^# timer:/ { for (i = 1; i <= NF; i++) if ($i == "overhead") print $(i + 1) }' "$out/$tag.txt")
    P=$(awk '{ print $3 }' "$out/$tag.total")
    Pfile=$(awk '{ print $4 }' "$out/$tag.total")
    chk=$(awk -v from="$from" -v to="$to" -v P="$P" -v T="$T" -v ov="$ov" '
        $1 == "MARK" { mi[$2] = $3 }
        END {
            n = to - from; e = mi[1] - mi[0]; d = mi[to] - mi[from]
            xd = n * e - (n - 1) * ov
            printf "%d %d %d %d", d, e, xd, (P == d && P - T == xd) ? 1 : 0
        }' "$out/$tag.marks")
    set -- $chk
    d=$1; e=$2; expd=$3; ok=$4
    [ "$P" = "$Pfile" ] || ok=0
    [ "$ok" = 1 ] || status=1

    num() { awk -v v="$1" 'BEGIN { s = sprintf("%d", v); o = ""; while (length(s) > 3) { o = "," substr(s, length(s) - 2) o; s = substr(s, 1, length(s) - 3) } print s o }'; }
    echo "### $scene, $mode mode, -$opt (bench_${mode}_${opt}.elf, marks $from..$to)"
    echo
    echo "| function | from | instructions | share | entries | instructions per entry |"
    echo "|---|---|---:|---:|---:|---:|"
    awk -F "$tab" -v top="$top" -v P="$P" '
        function num(v,   s, o) { s = sprintf("%d", v); o = ""; while (length(s) > 3) { o = "," substr(s, length(s) - 2) o; s = substr(s, 1, length(s) - 3) } return s o }
        NR <= top { printf "| `%s` | %s | %s | %.1f %% | %s | %s |\n", $1, $2, num($3), 100 * $3 / P, num($4), ($4 > 0 ? sprintf("%.1f", $3 / $4) : "-"); s += $3 }
        NR > top { rest += $3; nrest++ }
        $2 ~ /^libgcc/ { lg += $3; lgl = lgl (lgl == "" ? "" : ", ") "`" $1 "` " num($3) }
        $2 ~ /^core/ { core += $3 }
        END {
            if (nrest) printf "| (%d other functions) | | %s | %.1f %% | | |\n", nrest, num(rest), 100 * rest / P
            printf "| **total** | | **%s** | 100 %% | | |\n", num(P)
            printf "\nBy origin: core %s (%.1f %%), libgcc %s (%.1f %%), the rest (newlib, benchmark, mark()) %s (%.1f %%).\n", num(core), 100 * core / P, num(lg), 100 * lg / P, num(P - core - lg), 100 * (P - core - lg) / P
            printf "\nlibgcc functions executed: %s.\n", (lgl == "" ? "none" : lgl)
        }' "$out/$tag.functions"
    echo
    if [ "$ok" = 1 ]; then
        echo "Check: profile total $(num "$P") = plugin count between marks $from and $to; timer interval $(num "$T") = profile total - $expd ($((to - from)) x $e, the plugin's count of an empty interval, - $((to - from - 1)) x $ov, the timer's: all of it in mark(), see docs/CORTEX_M.md)."
    else
        echo "CHECK FAILED: profile total $P (file $Pfile), plugin marks $d, timer $T, expected difference $expd"
    fi
    echo
done
exit $status
