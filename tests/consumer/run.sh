#!/bin/sh
# SPDX-License-Identifier: MIT
# Consumer tests: zline used as a firmware project would use it, each case a
# tiny project outside the source tree that renders a small scene through
# zline and checks the pixels against its own reference (app/consumer.c).
#
#   headers_*        every public header alone, in a consumer's strict C99 and
#                    C++11 builds (gcc, g++, and clang/clang++ when present)
#   subdir_host      add_subdirectory on the host: only libzline.a is built,
#                    no zline warning flag reaches the consumer's compiler
#   subdir_<cpu>     the same in a Cortex-M cross build with zline's toolchain
#                    file, one per CPU and float ABI (the per-ABI link tests:
#                    the core links into firmware of that ABI), each run under
#                    QEMU on its board
#   install          cmake --install of a library-only build; what it installs
#   find_package     find_package(zline 0.1 CONFIG REQUIRED) from that prefix,
#                    COMPONENTS host, and 1.0 refused (same-major versions)
#   version          zl_version.h == CMake package version == zline.pc version
#   fetchcontent     FetchContent from a local path
#   pkg_config       pkg-config --cflags --libs zline with a plain cc command
#   vendor_host      core/src/**/*.c compiled into the consumer with its own
#                    flags, no CMake at all; vendor_cortex-m4f the same with
#                    arm-none-eabi-gcc for a hard-float Cortex-M4F
#   abi_mismatch     a soft-float core into a hard-float firmware must fail to
#                    link (the per-ABI link tests can fail)
#   presets          CMakePresets.json: every preset README names is a
#                    configure, build and test preset; host and cortex-m4f
#                    configure
#
#   tests/consumer/run.sh [work-dir]     (default build/consumer; JOBS=2)
# Last line: "consumer: N passed, M failed, K skipped"; exit status 1 if any
# failed. A case whose tool is missing reports itself skipped, never passed.
set -u
root=$(cd "$(dirname "$0")/../.." && pwd)
here=$root/tests/consumer
out=${1:-$root/build/consumer}
jobs=${JOBS:-2}
toolchain=$root/port/cortex-m/toolchain-arm-none-eabi.cmake
strict_c="-std=c99 -Wall -Wextra -Wpedantic -Wconversion -Wshadow -Wsign-conversion -Wundef -Wstrict-prototypes -Werror"
strict_cxx="-std=c++11 -Wall -Wextra -Wpedantic -Wconversion -Wshadow -Wsign-conversion -Wundef -Werror"
passed=0 failed=0 skipped=0
rm -rf "$out"
mkdir -p "$out"
out=$(cd "$out" && pwd) # absolute: the cases configure projects in other folders

SKIP=77
# check NAME COMMAND...: run a case, its output in $out/NAME.log
check() {
    name=$1; shift
    if ( "$@" ) >"$out/$name.log" 2>&1; then
        echo "consumer: PASS $name"; passed=$((passed + 1))
    elif [ $? -eq $SKIP ]; then
        echo "consumer: SKIP $name ($(tail -n 1 "$out/$name.log"))"; skipped=$((skipped + 1))
    else
        echo "consumer: FAIL $name"; sed 's/^/    /' "$out/$name.log" | tail -n 30
        failed=$((failed + 1))
    fi
}
need() { # need TOOL: skip the case without it
    command -v "$1" >/dev/null 2>&1 || { echo "SKIP: $1 not found"; exit $SKIP; }
}
fail() { echo "FAIL: $*"; exit 1; }

# --- CPU table: cpu[:abi] -> cmake args, QEMU board, linker script ----------
board_of() {
    case $1 in
    cortex-m0*) echo microbit ;;
    cortex-m3) echo mps2-an385 ;;
    cortex-m4*) echo mps2-an386 ;;
    cortex-m7*) echo mps2-an500 ;;
    cortex-m33*) echo mps2-an505 ;;
    cortex-m55*) echo mps3-an547 ;;
    esac
}
ld_of() {
    case $1 in
    cortex-m33*) echo mps2-an505.ld ;;
    cortex-m55*) echo mps3-an547.ld ;;
    *) echo mps2.ld ;;
    esac
}
run_elf() { # run_elf ELF BOARD: the program's exit status is the result
    "$root/port/cortex-m/run-qemu.sh" -M "$2" -t 60 "$1"
}

# --- the cases ----------------------------------------------------------------
headers() { # headers CC FLAGS LANG-SUFFIX
    need "$1"
    for h in "$root"/core/include/zline/*.h; do
        printf '#include "zline/%s"\ntypedef int consumer_not_empty;\n' "$(basename "$h")" >"$out/hdr.$3"
        "$1" $2 -I"$root/core/include" -fsyntax-only "$out/hdr.$3" || fail "$(basename "$h") with $1 $2"
    done
    printf '#include "zline/zline.h"\n#include "zline/zl_visibility.h"\nint main(void) { return ZL_VERSION_MAJOR; }\n' >"$out/hdr.$3"
    "$1" $2 -I"$root/core/include" -fsyntax-only "$out/hdr.$3" || fail "all headers with $1"
    echo "$1: every public header compiles cleanly with $2"
}

# Only zline's library is built in the consumer's tree: no test, tool,
# port or firmware target, no ExternalProject.
only_library_built() { # BUILD-DIR
    libs=$(cd "$1" && find . -name '*.a' | sort)
    [ "$libs" = "./zline/core/libzline.a" ] || fail "libraries built: $libs"
    for d in tests tools port; do
        [ ! -e "$1/zline/$d" ] || fail "zline/$d was configured in the consumer's build"
    done
    # zline's flags never on a consumer file: the probe has no flags of its own.
    # (CMake writes each entry's "command" on the line before its "file")
    grep -B1 '"file": ".*/probe.c"' "$1/compile_commands.json" | grep '"command"' >"$1/probe.cmd" ||
        fail "no probe in compile_commands.json"
    cat "$1/probe.cmd"
    ! grep -q -- ' -W' "$1/probe.cmd" || fail "warning flags reached the consumer: $(cat "$1/probe.cmd")"
    echo "built: $libs and the consumer; no zline flag on the consumer's files"
}

subdir_host() {
    b=$out/subdir-host
    cmake -S "$here/subdir" -B "$b" -DZLINE_SOURCE_DIR="$root" -DCMAKE_BUILD_TYPE=Release &&
        cmake --build "$b" -j "$jobs" || fail "build"
    only_library_built "$b"
    "$b/consumer" || fail "the consumer's pixel check"
}

subdir_cross() { # subdir_cross CPU [ABI]
    need arm-none-eabi-gcc
    need qemu-system-arm
    b=$out/subdir-$1${2:+-$2}
    cmake -S "$here/subdir" -B "$b" -DZLINE_SOURCE_DIR="$root" -DCMAKE_BUILD_TYPE=Release \
        -DCMAKE_TOOLCHAIN_FILE="$toolchain" -DZLINE_CPU="$1" -DZLINE_FLOAT_ABI="${2:-}" \
        -DCONSUMER_PORT_DIR="$root/port/cortex-m" -DCONSUMER_LD="$(ld_of "$1")" &&
        cmake --build "$b" -j "$jobs" || fail "build"
    only_library_built "$b"
    arm-none-eabi-readelf -A "$b/consumer.elf" | grep -E "Tag_CPU_name|Tag_FP_arch|Tag_ABI_VFP_args" || true
    run_elf "$b/consumer.elf" "$(board_of "$1")" || fail "the consumer's pixel check under QEMU ($(board_of "$1"))"
}

prefix=$out/prefix
install_tree() {
    b=$out/zline-lib
    cmake -S "$root" -B "$b" -DCMAKE_BUILD_TYPE=Release -DZLINE_BUILD_TESTS=OFF -DZLINE_BUILD_TOOLS=OFF \
        -DZLINE_BUILD_BENCHMARKS=OFF -DZLINE_BUILD_PORTS=ON &&
        cmake --build "$b" -j "$jobs" && cmake --install "$b" --prefix "$prefix" || fail "build and install"
    (cd "$prefix" && find . -type f | sort) | tee "$out/installed.txt"
    for f in include/zline/zline.h include/zline/zl_version.h lib/libzline.a lib/cmake/zline/zlineConfig.cmake \
        lib/cmake/zline/zlineConfigVersion.cmake lib/cmake/zline/zlineTargets.cmake lib/pkgconfig/zline.pc \
        lib/libzline_host.a include/zline/host/zl_obj.h lib/pkgconfig/zline-host.pc; do
        [ -f "$prefix/$f" ] || fail "not installed: $f"
    done
    [ ! -d "$prefix/bin" ] || fail "a library-only build installed programs: $(ls "$prefix/bin")"
}

find_package_case() {
    [ -f "$prefix/lib/cmake/zline/zlineConfig.cmake" ] || fail "no installed tree (the install case failed)"
    b=$out/find-package
    cmake -S "$here/find_package" -B "$b" -DCMAKE_PREFIX_PATH="$prefix" -DCONSUMER_EXPECT_HOST=ON \
        -DCMAKE_BUILD_TYPE=Release && cmake --build "$b" -j "$jobs" || fail "build"
    "$b/consumer" || fail "the consumer's pixel check"
}

version_case() {
    need pkg-config
    printf '#include <stdio.h>\n#include "zline/zl_version.h"\nint main(void) { printf("%%s %%d.%%d.%%d\\n", ZL_VERSION_STRING, ZL_VERSION_MAJOR, ZL_VERSION_MINOR, ZL_VERSION_PATCH); return 0; }\n' >"$out/version.c"
    cc -I"$root/core/include" "$out/version.c" -o "$out/version" || fail "compile"
    set -- $("$out/version")
    [ "$1" = "$2" ] || fail "ZL_VERSION_STRING $1 is not the numbers $2"
    pc=$(PKG_CONFIG_PATH=$prefix/lib/pkgconfig pkg-config --modversion zline) || fail "pkg-config zline"
    cm=$(sed -n 's/^set(PACKAGE_VERSION "\(.*\)")$/\1/p' "$prefix/lib/cmake/zline/zlineConfigVersion.cmake")
    echo "zl_version.h $1, zline.pc $pc, zlineConfigVersion.cmake $cm"
    [ "$1" = "$pc" ] && [ "$1" = "$cm" ] || fail "versions differ"
}

fetchcontent() {
    b=$out/fetchcontent
    cmake -S "$here/fetchcontent" -B "$b" -DZLINE_SOURCE_DIR="$root" -DCMAKE_BUILD_TYPE=Release &&
        cmake --build "$b" -j "$jobs" || fail "build"
    libs=$(cd "$b" && find . -name '*.a' | sort)
    [ "$libs" = "./_deps/zline-build/core/libzline.a" ] || fail "libraries built: $libs"
    "$b/consumer" || fail "the consumer's pixel check"
}

pkg_config() {
    need pkg-config
    export PKG_CONFIG_PATH="$prefix/lib/pkgconfig"
    flags="$(pkg-config --cflags zline)" && libs="$(pkg-config --libs zline)" || fail "pkg-config zline"
    echo "cc $strict_c $flags app/consumer.c $libs"
    cc $strict_c -DCONSUMER_HOW='"pkg-config"' $flags "$here/app/consumer.c" $libs -o "$out/consumer-pc" || fail "compile"
    "$out/consumer-pc" || fail "the consumer's pixel check"
}

# The vendored sources: every .c under core/src, recursively (the stage
# folders of the core's layout). Before that layout the internal headers sat
# beside the sources in core/src and were included by name, hence -I core/src
# only while core/src itself holds headers; after it, -I core/include is all.
vendor_sources() { find "$root/core/src" -name '*.c' | sort; }
vendor_includes() {
    echo "-I$root/core/include"
    if ls "$root"/core/src/*.h >/dev/null 2>&1; then echo "-I$root/core/src"; fi
}

vendor_host() {
    cc $strict_c -O2 -DCONSUMER_HOW='"vendored sources"' $(vendor_includes) $(vendor_sources) \
        "$here/app/consumer.c" -o "$out/consumer-vendored" || fail "compile"
    "$out/consumer-vendored" || fail "the consumer's pixel check"
}

arm_m4f="-mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard"
port=$root/port/cortex-m
vendor_m4f() {
    need arm-none-eabi-gcc
    need qemu-system-arm
    arm-none-eabi-gcc $arm_m4f $strict_c -O2 --specs=nosys.specs -ffunction-sections -fdata-sections \
        -DCONSUMER_HOW='"vendored sources, Cortex-M4F hard float"' $(vendor_includes) $(vendor_sources) \
        "$here/app/consumer.c" -I"$port" "$port/startup.c" "$port/semihosting.c" "$port/syscalls.c" \
        "$port/stack.c" -nostartfiles -L"$port" -T"$port/mps2.ld" -Wl,--gc-sections \
        -o "$out/consumer-vendored-m4f.elf" 2>&1 | grep -v 'has a LOAD segment with RWX' ; [ -f "$out/consumer-vendored-m4f.elf" ] || fail "compile"
    run_elf "$out/consumer-vendored-m4f.elf" mps2-an386 || fail "the consumer's pixel check under QEMU"
}

abi_mismatch() {
    need arm-none-eabi-gcc
    mkdir -p "$out/abi" && cd "$out/abi" || exit 1
    arm-none-eabi-gcc -mcpu=cortex-m4 -mthumb -mfloat-abi=soft -O2 -std=c99 $(vendor_includes) -c $(vendor_sources) ||
        fail "compile"
    arm-none-eabi-ar rcs libzline-soft.a ./*.o
    if arm-none-eabi-gcc $arm_m4f -O2 --specs=nosys.specs -I"$root/core/include" "$here/app/consumer.c" \
        -I"$port" "$port/startup.c" "$port/semihosting.c" "$port/syscalls.c" "$port/stack.c" \
        -nostartfiles -L"$port" -T"$port/mps2.ld" libzline-soft.a -o mixed.elf >link.log 2>&1; then
        fail "a soft-float core linked into a hard-float firmware"
    fi
    grep -q "VFP register arguments" link.log || { cat link.log; fail "the link failed for another reason"; }
    echo "refused as expected: $(grep -m1 'VFP register arguments' link.log)"
}

# The presets of README: every configure, build and test preset parses and
# names a configure preset that exists (cmake --list-presets=all fails
# otherwise), each preset README names is listed, and two of them configure
# (host, and the hard-float cortex-m4f) into a scratch folder (-B overrides
# the preset's build/<name>). CI's own cross runs use the same toolchain flags.
presets() {
    cd "$root"
    cmake --list-presets=all >"$out/presets.list" || fail "cmake --list-presets=all"
    for p in host host-sanitize cortex-m0 cortex-m0plus cortex-m3 cortex-m4 cortex-m4f cortex-m4f-softfp \
        cortex-m7 cortex-m33 cortex-m55 rv32imac rv32imc; do
        [ "$(grep -c "\"$p\"" "$out/presets.list")" -eq 3 ] || fail "preset $p is not a configure, build and test preset"
    done
    for p in host cortex-m4f; do
        cmake --preset "$p" -B "$out/preset-$p" >"$out/preset-$p.log" 2>&1 || { cat "$out/preset-$p.log"; fail "cmake --preset $p"; }
    done
    echo "presets: every preset listed three times (configure, build, test); host and cortex-m4f configure"
}

check headers_c99_gcc headers gcc "$strict_c" c
check headers_c99_clang headers clang "$strict_c" c
check headers_cxx11_gxx headers g++ "$strict_cxx" cpp
check headers_cxx11_clangxx headers clang++ "$strict_cxx" cpp
check subdir_host subdir_host
for cpu_abi in ${CONSUMER_CPUS:-cortex-m0 cortex-m0plus cortex-m3 cortex-m4 cortex-m4f:softfp cortex-m4f:hard \
    cortex-m7:softfp cortex-m7:hard cortex-m33:hard cortex-m55:hard cortex-m55:soft}; do
    cpu=${cpu_abi%%:*}
    abi=
    [ "$cpu" = "$cpu_abi" ] || abi=${cpu_abi#*:}
    check "subdir_$cpu${abi:+_$abi}" subdir_cross "$cpu" "$abi"
done
check install install_tree
check find_package find_package_case
check version version_case
check fetchcontent fetchcontent
check pkg_config pkg_config
check vendor_host vendor_host
check vendor_cortex-m4f vendor_m4f
check abi_mismatch abi_mismatch
check presets presets

echo "consumer: $passed passed, $failed failed, $skipped skipped"
[ "$failed" -eq 0 ]
