#!/bin/sh
# SPDX-License-Identifier: MIT
# core_no_float_symbols: compile every core/src/*/*.c for a Cortex-M0 (no FPU,
# soft float: any float or double arithmetic becomes a libgcc call) and fail
# if an object references
#   - a floating-point helper: __aeabi_f*, __aeabi_d*, __aeabi_c[fd]*cmp*,
#     __aeabi_[u][il]2[fd], or a libgcc soft-float routine (__addsf3,
#     __muldf3, __floatsidf, __fixdfsi, __extendsfdf2, __eqsf2, ...);
#   - the heap or stdio: malloc calloc realloc free (and friends), printf
#     and the rest of stdio, exit/abort/assert's __assert_func.
# memcpy, memset, memmove, memcmp and integer helpers (__aeabi_idiv,
# __aeabi_uldivmod, __aeabi_lmul, ...) are allowed.
#
#   check-core-symbols.sh [project-source-dir]
# Environment: ARM_GCC, ARM_NM (default arm-none-eabi-gcc / -nm on PATH),
# CORE_CFLAGS (extra flags, e.g. -DZL_SUBPIXEL_BITS=6).
set -u

src=${1:-$(cd "$(dirname "$0")/../.." && pwd)}
gcc=${ARM_GCC:-arm-none-eabi-gcc}
nm=${ARM_NM:-arm-none-eabi-nm}

fail() {
    echo "core_no_float_symbols: FAIL: $*" >&2
    exit 1
}

command -v "$gcc" >/dev/null 2>&1 ||
    fail "'$gcc' not found: install the Arm bare-metal toolchain (Debian: apt install gcc-arm-none-eabi libnewlib-arm-none-eabi) or set ARM_GCC"
command -v "$nm" >/dev/null 2>&1 ||
    fail "'$nm' not found (binutils-arm-none-eabi) or set ARM_NM"

set -- "$src"/core/src/*/*.c
[ -f "$1" ] || fail "no C sources in $src/core/src"

tmp=$(mktemp -d) || fail "mktemp"
trap 'rm -rf "$tmp"' EXIT INT TERM

bad_float='^__aeabi_[fd]|^__aeabi_c[fd]|^__aeabi_u?[il]2[fdh]$|^__aeabi_[hf]2|^__.*(sf|df|tf|xf|hf)[0-9]*$|^__(fix|float|extend|trunc|unord|pow|mul|div|add|sub|neg|cmp|eq|ne|lt|le|gt|ge)[a-z]*(sf|df|tf|xf|hf)|^__[a-z]*[sdxt]c3$'
bad_libc='^(malloc|calloc|realloc|free|aligned_alloc|memalign|posix_memalign|valloc|_malloc_r|_calloc_r|_realloc_r|_free_r|printf|fprintf|sprintf|snprintf|vprintf|vfprintf|vsprintf|vsnprintf|iprintf|fiprintf|siprintf|sniprintf|_printf_r|_fprintf_r|puts|fputs|putchar|fputc|putc|fwrite|fread|fopen|fclose|fflush|fseek|ftell|fgets|fgetc|getchar|scanf|sscanf|fscanf|perror|exit|_exit|abort|__assert_func|__assert|atof|strtod|strtof)$'

status=0
nobj=0
for c in "$@"; do
    o=$tmp/$(basename "$c" .c).o
    # shellcheck disable=SC2086
    if ! "$gcc" -mcpu=cortex-m0 -mthumb -mfloat-abi=soft -O2 -std=c99 \
        -I"$src/core/include" ${CORE_CFLAGS:-} -c "$c" -o "$o"; then
        echo "core_no_float_symbols: FAIL: $c does not compile for Cortex-M0" >&2
        status=1
        continue
    fi
    nobj=$((nobj + 1))
    undef=$("$nm" -u "$o" | awk '{print $NF}')
    hits=$(printf '%s\n' "$undef" | grep -E "$bad_float" || true)
    if [ -n "$hits" ]; then
        echo "core_no_float_symbols: FAIL: $(basename "$c") uses floating point (soft-float helpers):" >&2
        printf '    %s\n' $hits >&2
        status=1
    fi
    hits=$(printf '%s\n' "$undef" | grep -E "$bad_libc" || true)
    if [ -n "$hits" ]; then
        echo "core_no_float_symbols: FAIL: $(basename "$c") uses the heap, stdio or exit:" >&2
        printf '    %s\n' $hits >&2
        status=1
    fi
done

# For the record: every symbol the core needs from outside itself.
"$nm" -u -A "$tmp"/*.o 2>/dev/null | awk '{print $NF}' | sort -u > "$tmp/undef"
"$nm" --defined-only -A "$tmp"/*.o 2>/dev/null | awk 'NF == 3 {print $3}' | sort -u > "$tmp/def"
ext=$(comm -23 "$tmp/undef" "$tmp/def" | tr '\n' ' ')
echo "core_no_float_symbols: $nobj objects (Cortex-M0, -O2); external symbols: ${ext:-none}"

if [ "$status" -eq 0 ]; then
    echo "core_no_float_symbols: OK: no floating point, heap or stdio in core/src"
fi
exit "$status"
