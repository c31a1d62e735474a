#!/bin/sh
# SPDX-License-Identifier: MIT
# Lay out zline as an Arduino library (1.5 format, also what PlatformIO
# installs) from the tree, and zip it:
#
#   tools/arduino/make-library.sh OUT_DIR   -> OUT_DIR/zline/ and OUT_DIR/zline-VERSION.zip
#
# Why a script and not manifests over the tree as it is: the Arduino tools
# compile only a library's src/ folder (recursively) and add only src/ to
# the include path, and they find a library by a header at the top of src/.
# The tree keeps the core in core/src and core/include/zline and the panel
# driver in port/display, so the library is this copy:
#   library.properties, library.json, LICENSE, README.md (docs/ARDUINO.md)
#   src/zline.h             #include "zline/zline.h": what sketches include
#   src/zline/*.h           the public headers, as installed by CMake
#   src/zline_core/N_stage/ core/src as it is (its "../1_base/..." includes hold)
#   src/zl_spi_panel.[ch]   the ST7789/ILI9341 driver (port/display)
#   examples/RotatingModel/ port/arduino/examples/RotatingModel
# Nothing is edited on the way: every file is the tree's, byte for byte,
# except src/zline.h, written here.
set -eu
[ $# -eq 1 ] || { echo "usage: $0 OUT_DIR" >&2; exit 2; }
top=$(cd "$(dirname "$0")/../.." && pwd)
out=$1
lib=$out/zline
version=$(sed -n 's/^version=//p' "$top/library.properties")
[ -n "$version" ] || { echo "make-library: no version in library.properties" >&2; exit 1; }

rm -rf "$lib"
mkdir -p "$lib/src/zline" "$lib/src/zline_core" "$lib/examples"
cp "$top/library.properties" "$top/library.json" "$top/LICENSE" "$lib/"
cp "$top/docs/ARDUINO.md" "$lib/README.md"
cp "$top"/core/include/zline/*.h "$top"/port/fpu/include/zline/*.h "$lib/src/zline/"
(cd "$top/core/src" && find . -name '*.[ch]' | while IFS= read -r f; do
    mkdir -p "$lib/src/zline_core/$(dirname "$f")"
    cp "$f" "$lib/src/zline_core/$f"
done)
cp "$top/port/display/zl_spi_panel.c" "$top/port/display/zl_spi_panel.h" "$lib/src/"
cat >"$lib/src/zline.h" <<'HEADER'
/* SPDX-License-Identifier: MIT */
/* zline for Arduino: the header a sketch includes (the Arduino tools find a
 * library by a header at the top of its src/ folder). */
#include "zline/zline.h"
HEADER
cp -R "$top/port/arduino/examples/RotatingModel" "$lib/examples/"

zip=$out/zline-$version.zip
rm -f "$zip"
(cd "$out" && python3 -m zipfile -c "zline-$version.zip" zline)
echo "make-library: $lib and $zip ($(find "$lib/src" -type f | wc -l) source files)"
