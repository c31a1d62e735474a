#!/bin/sh
# SPDX-License-Identifier: MIT
# Consumer tests: zline used as a firmware project would use it, each case a
# tiny project outside the source tree that renders a small scene through
# zline and checks the pixels against its own reference (app/consumer.c).
#
#   headers_*        every public header alone, in a consumer's strict C99 and
#                    C++11 builds (gcc, g++, and clang/clang++ when present)
#   subdir_host      add_subdirectory on the host: only libzline.a and
#                    libzline_panel.a are built, no zline warning flag reaches
#                    the consumer's compiler
#   subdir_<cpu>     the same in a Cortex-M cross build with zline's toolchain
#                    file: the M4F, and each float ABI no CI stage links (the
#                    per-ABI link tests: the core links into firmware of that
#                    ABI), each run under QEMU on its board (the other pairs:
#                    CONSUMER_CPUS, see lane_a)
#   install          cmake --install of a host build without tests or tools:
#                    the library, components host and panel, the converters
#   find_package     find_package(zline 0.1 CONFIG REQUIRED) from that prefix,
#                    COMPONENTS host, panel and tools, and 1.0 refused
#                    (same-major versions)
#   version          zl_version.h == CMake package version == zline.pc version
#   fetchcontent     FetchContent from a local path
#   pkg_config       pkg-config --cflags --libs zline with a plain cc command
#   pkg_config_panel the same for zline-panel: a program calling the driver
#   assets_host      tests/consumer/assets (a cube and a texture converted at
#                    build time by zline_add_mesh / zline_add_texture, drawn
#                    and sent through zline::panel to a recording bus) against
#                    the installed host package: the reference frame
#   install_cortex-m4f          a hard-float Cortex-M4F build installed
#   assets_find_package_cortex-m4f  the asset firmware against that package,
#                    converters from the host install (ZLINE_HOST_TOOLS_DIR),
#                    run under QEMU: its frame must equal assets_host's;
#                    a wrong ZLINE_HOST_TOOLS_DIR fails with a message
#   assets_fetchcontent_cortex-m4f  the same through FetchContent: the
#                    converters built for the host by ExternalProject
#   debug_opt_levels every preset CPU and float ABI: the core compiles at -O0
#                    and -Og with arm-none-eabi-gcc / riscv64-unknown-elf-gcc,
#                    and the Cortex-M ones with clang --target=thumbv*-none-eabi
#                    (a compile whose objects are another's is not repeated)
#   vendor_host      core/src/**/*.c compiled into the consumer with its own
#                    flags, no CMake at all; vendor_cortex-m4f the same with
#                    arm-none-eabi-gcc for a hard-float Cortex-M4F
#   abi_mismatch     a soft-float core into a hard-float firmware must fail to
#                    link (the per-ABI link tests can fail)
#   abi_config_match, abi_config_mismatch  (issue 23) a consumer with the
#                    installed package's flags passes zl_init's ABI check; with
#                    -DZL_DRAW_CACHE_SLOTS=256 against the default library,
#                    zl_init and zl_frame_begin return ZL_ERR_ABI
#   abi_config_recorded  a library configured with ZLINE_CONFIG records it
#                    (zl_build_config.h): a find_package consumer sees it
#   presets          CMakePresets.json: every preset README names is a
#                    configure, build and test preset; host and cortex-m4f
#                    configure
#
#   tests/consumer/run.sh [work-dir]     (default build/consumer; JOBS=2;
#                                        CONSUMER_ONLY="case ..." runs those)
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
    case " ${CONSUMER_ONLY:-$name} " in *" $name "*) ;; *) return 0 ;; esac
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
    for h in "$root"/core/include/zline/*.h "$root"/port/fpu/include/zline/*.h; do
        printf '#include "zline/%s"\ntypedef int consumer_not_empty;\n' "$(basename "$h")" >"$out/hdr.$3"
        "$1" $2 -I"$root/core/include" -I"$root/port/fpu/include" -fsyntax-only "$out/hdr.$3" || fail "$(basename "$h") with $1 $2"
    done
    printf '#include "zline/zline.h"\n#include "zline/zl_visibility.h"\nint main(void) { return ZL_VERSION_MAJOR; }\n' >"$out/hdr.$3"
    "$1" $2 -I"$root/core/include" -fsyntax-only "$out/hdr.$3" || fail "all headers with $1"
    echo "$1: every public header compiles cleanly with $2"
}

# Only zline's libraries (the core and the panel component) are built in the
# consumer's tree: no test, tool, port or firmware target, no ExternalProject.
only_library_built() { # BUILD-DIR
    libs=$(cd "$1" && find . -name '*.a' | sort | tr '\n' ' ')
    [ "$libs" = "./zline/core/libzline.a ./zline/port/display/libzline_panel.a " ] || fail "libraries built: $libs"
    for d in tests tools port/host port/cortex-m port/riscv; do
        [ ! -e "$1/zline/$d" ] || fail "zline/$d was configured in the consumer's build"
    done
    [ ! -e "$1/zline-host-converters" ] || fail "the host converters were built though nothing used them"
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
    for f in include/zline/zline.h include/zline/zl_version.h include/zline/zl_float.h lib/libzline.a lib/cmake/zline/zlineConfig.cmake \
        lib/cmake/zline/zlineConfigVersion.cmake lib/cmake/zline/zlineTargets.cmake lib/pkgconfig/zline.pc \
        lib/libzline_host.a include/zline/host/zl_obj.h lib/pkgconfig/zline-host.pc \
        lib/libzline_panel.a include/zline/panel/zl_spi_panel.h include/zline/panel/zl_grey4.h \
        lib/pkgconfig/zline-panel.pc lib/cmake/zline/zlinePanelTargets.cmake \
        lib/cmake/zline/zlineToolsTargets.cmake lib/cmake/zline/zlineAssets.cmake; do
        [ -f "$prefix/$f" ] || fail "not installed: $f"
    done
    # The programs: the two converters, nothing else (no test, no benchmark).
    [ "$(ls "$prefix/bin" | tr '\n' ' ')" = "zline-img2c zline-obj2c zline-size " ] || fail "programs installed: $(ls "$prefix/bin")"
    "$prefix/bin/zline-obj2c" --bogus 2>&1 | grep -q usage || fail "the installed zline-obj2c does not run"
}

find_package_case() {
    [ -f "$prefix/lib/cmake/zline/zlineConfig.cmake" ] || fail "no installed tree (the install case failed)"
    b=$out/find-package
    cmake -S "$here/find_package" -B "$b" -DCMAKE_PREFIX_PATH="$prefix" -DCONSUMER_EXPECT_HOST=ON \
        -DCMAKE_BUILD_TYPE=Release && cmake --build "$b" -j "$jobs" || fail "build"
    "$b/consumer" || fail "the consumer's pixel check"
    "$b/panel_probe" || fail "zline::panel's configuration"
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
    libs=$(cd "$b" && find . -name '*.a' | sort | tr '\n' ' ')
    [ "$libs" = "./_deps/zline-build/core/libzline.a ./_deps/zline-build/port/display/libzline_panel.a " ] ||
        fail "libraries built: $libs"
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

pkg_config_panel() {
    need pkg-config
    export PKG_CONFIG_PATH="$prefix/lib/pkgconfig"
    flags="$(pkg-config --cflags zline-panel)" && libs="$(pkg-config --libs zline-panel)" || fail "pkg-config zline-panel"
    echo "pkg-config zline-panel: $flags $libs"
    printf '%s\n' '#include "zl_spi_panel.h"' '#include "zl_grey4.h"' \
        'int main(void) { zl_panel_config c = zl_panel_config_ili9341_320x240(); zl_panel p;' \
        '    return c.width == 320u && c.height == 240u && zl_panel_init(&p, &c, 0) == ZL_ERR_ARG ? 0 : 1; }' \
        >"$out/panel-pc.c"
    cc $strict_c $flags "$out/panel-pc.c" $libs -o "$out/panel-pc" || fail "compile"
    "$out/panel-pc" || fail "the panel driver's configuration or argument check"
}

# --- the ABI check (issue 23) --------------------------------------------------
# abi_config_match: the installed package's flags (pkg-config) give the
# library's configuration: zl_init passes the key check. abi_config_mismatch:
# the same consumer with -DZL_DRAW_CACHE_SLOTS=256 against a 1024-slot
# library: zl_init and zl_frame_begin return ZL_ERR_ABI.
abi_probe_build() { # abi_probe_build OUT EXTRA-FLAGS...
    need pkg-config
    o=$1; shift
    export PKG_CONFIG_PATH="$prefix/lib/pkgconfig"
    flags="$(pkg-config --cflags zline)" && libs="$(pkg-config --libs zline)" || fail "pkg-config zline"
    echo "$flags" | grep -q -- -DZL_BUILD_CONFIG || fail "zline.pc's Cflags lack -DZL_BUILD_CONFIG"
    [ -f "$prefix/include/zline/zl_build_config.h" ] || fail "zl_build_config.h not installed"
    cc $strict_c $flags "$@" "$here/app/abi_probe.c" $libs -o "$o" || fail "compile"
}
abi_config_match() {
    abi_probe_build "$out/abi-match" && "$out/abi-match" || fail "the key check refused the package's own flags"
}
abi_config_mismatch() {
    abi_probe_build "$out/abi-mismatch" -DZL_DRAW_CACHE_SLOTS=256 -DEXPECT_ABI_ERROR=1 && "$out/abi-mismatch" ||
        fail "a consumer built with another ZL_DRAW_CACHE_SLOTS was not refused with ZL_ERR_ABI"
}
# abi_config_recorded: a library configured with ZLINE_CONFIG=ZL_DRAW_CACHE_SLOTS=256,
# installed: its CMake package gives a find_package consumer the same value
# (zl_build_config.h), and zl_init passes.
abi_config_recorded() {
    b=$out/zline-lib-256
    p=$out/prefix-256
    cmake -S "$root" -B "$b" -DCMAKE_BUILD_TYPE=Release -DZLINE_BUILD_TESTS=OFF -DZLINE_BUILD_TOOLS=OFF \
        -DZLINE_BUILD_BENCHMARKS=OFF -DZLINE_BUILD_PORTS=OFF -DZLINE_CONFIG=ZL_DRAW_CACHE_SLOTS=256 &&
        cmake --build "$b" -j "$jobs" && cmake --install "$b" --prefix "$p" || fail "build and install"
    grep -q 'define ZL_DRAW_CACHE_SLOTS 256' "$p/include/zline/zl_build_config.h" || fail "the value is not recorded"
    mkdir -p "$out/abi-recorded-src"
    cat >"$out/abi-recorded-src/CMakeLists.txt" <<EOF2
# SPDX-License-Identifier: MIT
cmake_minimum_required(VERSION 3.16)
project(abi_recorded C)
find_package(zline CONFIG REQUIRED)
add_executable(abi_probe $here/app/abi_probe.c)
target_compile_definitions(abi_probe PRIVATE EXPECT_SLOTS=256)
target_link_libraries(abi_probe PRIVATE zline::zline)
EOF2
    cmake -S "$out/abi-recorded-src" -B "$out/abi-recorded" -DCMAKE_PREFIX_PATH="$p" &&
        cmake --build "$out/abi-recorded" || fail "the find_package consumer"
    "$out/abi-recorded/abi_probe" || fail "the consumer does not see the library's configuration"
}

# --- asset conversion and the panel component in firmware -------------------
# assets_build NAME CONSUMER_ZLINE [cmake args...]: build tests/consumer/assets
assets_build() {
    b=$out/$1; how=$2; shift 2
    cmake -S "$here/assets" -B "$b" -DCONSUMER_ZLINE="$how" -DCMAKE_BUILD_TYPE=Release "$@" &&
        cmake --build "$b" -j "$jobs" || fail "build"
    ls "$b/zline_assets"
}
# assets_compare OUTPUT: the frame lines equal the host's, byte for byte
assets_compare() {
    [ -s "$out/assets-host.txt" ] || fail "no host reference (the assets_host case failed)"
    grep '^assets:' "$1" >"$1.frame"
    if ! cmp "$out/assets-host.txt" "$1.frame"; then
        diff "$out/assets-host.txt" "$1.frame" | head -n 6
        fail "the frame differs from the host's"
    fi
    echo "$(grep -c '^assets: row' "$1.frame") rows equal the host's: $(tail -n 1 "$1.frame")"
}
assets_host() {
    [ -f "$prefix/lib/cmake/zline/zlineConfig.cmake" ] || fail "no installed tree (the install case failed)"
    assets_build assets-host find_package -DCMAKE_PREFIX_PATH="$prefix"
    "$out/assets-host/assets" >"$out/assets-host.out" || { cat "$out/assets-host.out"; fail "the frame's own checks"; }
    grep '^assets:' "$out/assets-host.out" >"$out/assets-host.txt"
    tail -n 1 "$out/assets-host.txt"
}
m4f_args() {
    echo "-DCMAKE_TOOLCHAIN_FILE=$toolchain -DZLINE_CPU=cortex-m4f -DCONSUMER_PORT_DIR=$root/port/cortex-m -DCONSUMER_LD=mps2.ld"
}
prefix_m4f=$out/prefix-cortex-m4f
install_m4f() {
    need arm-none-eabi-gcc
    b=$out/zline-lib-cortex-m4f
    cmake -S "$root" -B "$b" -DCMAKE_BUILD_TYPE=Release $(m4f_args) -DZLINE_BUILD_TESTS=OFF -DZLINE_BUILD_TOOLS=OFF \
        -DZLINE_BUILD_BENCHMARKS=OFF -DZLINE_BUILD_PORTS=OFF &&
        cmake --build "$b" -j "$jobs" && cmake --install "$b" --prefix "$prefix_m4f" || fail "build and install"
    (cd "$prefix_m4f" && find . -type f | sort)
    for f in lib/libzline.a lib/libzline_panel.a include/zline/panel/zl_spi_panel.h lib/cmake/zline/zlineAssets.cmake; do
        [ -f "$prefix_m4f/$f" ] || fail "not installed: $f"
    done
    # A cross build has no host programs to install: the firmware uses the host's.
    [ ! -e "$prefix_m4f/bin" ] && [ ! -e "$prefix_m4f/lib/libzline_host.a" ] || fail "host parts in a cross install"
}
assets_find_package_m4f() {
    need qemu-system-arm
    [ -f "$prefix_m4f/lib/libzline.a" ] || fail "no Cortex-M4F install (the install_cortex-m4f case failed)"
    # A cross package has no converters: a wrong host tools folder is an error that says so.
    if cmake -S "$here/assets" -B "$out/assets-no-tools" -DCMAKE_PREFIX_PATH="$prefix_m4f" \
        -DZLINE_HOST_TOOLS_DIR="$out/no-such-prefix" $(m4f_args) >"$out/assets-no-tools.log" 2>&1; then
        fail "configured without converters"
    fi
    grep -q "zline-obj2c not found" "$out/assets-no-tools.log" || { cat "$out/assets-no-tools.log"; fail "no clear message"; }
    assets_build assets-fp-m4f find_package -DCMAKE_PREFIX_PATH="$prefix_m4f" -DZLINE_HOST_TOOLS_DIR="$prefix" $(m4f_args)
    grep -q "$prefix/bin/zline-obj2c" "$out/assets-fp-m4f/CMakeCache.txt" || fail "the converters are not the host install's"
    run_elf "$out/assets-fp-m4f/assets.elf" mps2-an386 >"$out/assets-fp-m4f.out" 2>&1 ||
        { cat "$out/assets-fp-m4f.out"; fail "the frame's own checks under QEMU"; }
    assets_compare "$out/assets-fp-m4f.out"
}
assets_fetchcontent_m4f() {
    need arm-none-eabi-gcc
    need qemu-system-arm
    assets_build assets-fc-m4f fetchcontent -DZLINE_SOURCE_DIR="$root" $(m4f_args)
    [ -x "$out/assets-fc-m4f/zline-host-converters/tools/obj2c/zline-obj2c" ] ||
        fail "the converters were not built for the host by ExternalProject"
    run_elf "$out/assets-fc-m4f/assets.elf" mps2-an386 >"$out/assets-fc-m4f.out" 2>&1 ||
        { cat "$out/assets-fc-m4f.out"; fail "the frame's own checks under QEMU"; }
    assets_compare "$out/assets-fc-m4f.out"
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
# -O0 and -Og (what firmware is debugged at) with the core's own warnings as
# errors, for every CPU and float ABI of CMakePresets.json. An asm path must
# compile at every level or step aside for the C loop (issue 24: the M4F's
# fill_blocks_stm had 'impossible constraints' at -O0). Compiled, not linked
# or run here: the -O0 suite runs on the M4F in tests/run-all.sh. gcc's
# warnings are errors (the project's compiler); clang's are listed, not fatal
# (zline's builds do not use clang for Cortex-M).
debug_flags="-std=c99 -Wall -Wextra -pedantic -Wshadow -Wconversion -Wsign-conversion -ffunction-sections"
# debug_compile_at LABEL OPT COMPILER FLAGS...: every core source at OPT
debug_compile_at() {
    label=$1; opt=$2; cc=$3; shift 3
    werror=-Werror
    case $cc in clang*) werror= ;; esac
    d=$out/debug/$label$opt
    mkdir -p "$d" && (cd "$d" && "$cc" "$@" $opt $debug_flags $werror $(vendor_includes) -c $(vendor_sources)) \
        >"$d.log" 2>&1 || { cat "$d.log"; fail "$label $opt: $cc $* $opt"; }
    n=$(ls "$d" | wc -l)
    [ "$n" -eq "$(vendor_sources | wc -l)" ] || fail "$label $opt: $n objects"
    echo "$label $opt: $n objects, $(grep -c 'warning:' "$d.log") warnings"
    grep 'warning:' "$d.log" | sed 's/^/    /'
}
# debug_compile LABEL COMPILER FLAGS...: every core source at -O0 and at -Og,
# the two at once (one compiler process each, one per core of CI's machine:
# compiled one after the other they took 222 s, the longest consumer case);
# their lines in that order, and a failure of either fails the case.
debug_compile() {
    label=$1; shift
    mkdir -p "$out/debug"
    (debug_compile_at "$label" -O0 "$@") >"$out/debug/$label-O0.out" 2>&1 &
    o0=$!
    (debug_compile_at "$label" -Og "$@") >"$out/debug/$label-Og.out" 2>&1 &
    og=$!
    wait $o0; s0=$?
    wait $og; sg=$?
    cat "$out/debug/$label-O0.out" "$out/debug/$label-Og.out"
    [ $s0 -eq 0 ] && [ $sg -eq 0 ] || fail "$label: see above"
}
# Compiles that would repeat another are left out: cortex-m0plus's objects
# are cortex-m0's, cortex-m4f-softfp's are cortex-m4f's, and clang's
# cortex-m4f objects are its cortex-m4 ones, at -O0 and at -Og, with gcc and
# clang (the same instructions and .rodata in all 41 objects: objdump -d and
# objdump -s -j .rodata of every compile of the case, compared when they
# were left out). Same instruction set and registers, and the float ABI
# only passes float arguments, of which the core has none. Those 10 of the
# case's 40 compiles had taken 61 of its 228 CPU seconds (user + sys of
# each compiler command, on a loaded machine).
debug_opt_levels() {
    # Every compiler the case names must be there: without one the case is
    # skipped (reported), never passed on the others alone.
    need arm-none-eabi-gcc
    need clang
    need riscv64-unknown-elf-gcc
    for cpu_flags in "cortex-m0:-mcpu=cortex-m0 -mfloat-abi=soft:thumbv6m-none-eabi" \
        "cortex-m3:-mcpu=cortex-m3 -mfloat-abi=soft:thumbv7m-none-eabi" \
        "cortex-m4:-mcpu=cortex-m4 -mfloat-abi=soft:thumbv7em-none-eabi" \
        "cortex-m4f:-mcpu=cortex-m4 -mfpu=fpv4-sp-d16 -mfloat-abi=hard:-" \
        "cortex-m7:-mcpu=cortex-m7 -mfpu=fpv5-d16 -mfloat-abi=hard:thumbv7em-none-eabihf" \
        "cortex-m33:-mcpu=cortex-m33 -mfpu=fpv5-sp-d16 -mfloat-abi=hard:thumbv8m.main-none-eabihf" \
        "cortex-m55:-mcpu=cortex-m55 -mfpu=auto -mfloat-abi=hard:thumbv8.1m.main-none-eabihf"; do
        cpu=${cpu_flags%%:*}; rest=${cpu_flags#*:}; flags=${rest%%:*}; triple=${rest#*:}
        debug_compile "gcc-$cpu" arm-none-eabi-gcc $flags -mthumb
        [ "$triple" != - ] || continue # no clang compile of its own (above)
        # clang has no -mfpu=auto: the M55's FPU and MVE follow -mcpu there.
        debug_compile "clang-$cpu" clang --target="$triple" $(echo "$flags" | sed 's/ -mfpu=auto//') -mthumb \
            --sysroot=/usr/lib/arm-none-eabi
    done
    for arch in rv32imac rv32imc; do
        debug_compile "gcc-$arch" riscv64-unknown-elf-gcc -march=${arch}_zicsr -mabi=ilp32 -mcmodel=medany \
            --specs=picolibc.specs
    done
}

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

# Three lanes at once (CI's machine has two cores, and most of a case is a
# single-threaded CMake configure): the cases that need the installed host
# package follow the install in lane B, in order; debug_opt_levels, which
# compiles the core 30 times (40 times, before the repeated compiles were
# left out: about 220 s on one core, 120 s on two), is lane
# C alone from the start; the rest are lane A. (In the last two-lane run, lane
# B was done after 97 s, lane A after 396 s, 222 s of them debug_opt_levels.)
# Each lane's lines go to its own file, shown in order when all are done.
lane_a() {
    check headers_c99_gcc headers gcc "$strict_c" c
    check headers_c99_clang headers clang "$strict_c" c
    check headers_cxx11_gxx headers g++ "$strict_cxx" cpp
    check headers_cxx11_clangxx headers clang++ "$strict_cxx" cpp
    check subdir_host subdir_host
    # add_subdirectory into a cross build: the hard-float M4F, and the float
    # ABIs no CI stage links (M4F and M7 softfp, M55 soft). The other
    # CPU/ABI pairs (M0, M3 and M4 soft, M7, M33 and M55 hard) are linked
    # from the same core, toolchain file and flags, and run on the same
    # QEMU boards, by their cross stage of tests/run-all.sh; CONSUMER_CPUS
    # names any of them (about 20 CPU seconds each). The M0+ needs no case of
    # its own: its build was the M0's byte for byte (libzline.a and the
    # firmware image), and config_size_table compiles -mcpu=cortex-m0plus.
    for cpu_abi in ${CONSUMER_CPUS:-cortex-m4f:hard cortex-m4f:softfp cortex-m7:softfp cortex-m55:soft}; do
        cpu=${cpu_abi%%:*}
        abi=
        [ "$cpu" = "$cpu_abi" ] || abi=${cpu_abi#*:}
        check "subdir_$cpu${abi:+_$abi}" subdir_cross "$cpu" "$abi"
    done
    check vendor_host vendor_host
    check vendor_cortex-m4f vendor_m4f
    check abi_mismatch abi_mismatch
    check presets presets
}
lane_c() {
    check debug_opt_levels debug_opt_levels
}
lane_b() {
    check install install_tree
    check find_package find_package_case
    check version version_case
    check fetchcontent fetchcontent
    check pkg_config pkg_config
    check pkg_config_panel pkg_config_panel
    check abi_config_match abi_config_match
    check abi_config_mismatch abi_config_mismatch
    check abi_config_recorded abi_config_recorded
    check assets_host assets_host
    check install_cortex-m4f install_m4f
    check assets_find_package_cortex-m4f assets_find_package_m4f
    check assets_fetchcontent_cortex-m4f assets_fetchcontent_m4f
}
lane_c >"$out/lane-c.out" 2>&1 &
lane_c_pid=$!
lane_a >"$out/lane-a.out" 2>&1 &
lane_a_pid=$!
lane_b >"$out/lane-b.out" 2>&1
wait $lane_a_pid
wait $lane_c_pid
lanes="$out/lane-a.out $out/lane-b.out $out/lane-c.out"
# shellcheck disable=SC2086
cat $lanes
# the counters were kept in the lanes' subshells: count their lines
# shellcheck disable=SC2086
passed=$(grep -c '^consumer: PASS ' $lanes | awk -F: '{ n += $NF } END { print n + 0 }')
# shellcheck disable=SC2086
failed=$(grep -c '^consumer: FAIL ' $lanes | awk -F: '{ n += $NF } END { print n + 0 }')
# shellcheck disable=SC2086
skipped=$(grep -c '^consumer: SKIP ' $lanes | awk -F: '{ n += $NF } END { print n + 0 }')

echo "consumer: $passed passed, $failed failed, $skipped skipped"
[ "$failed" -eq 0 ]
