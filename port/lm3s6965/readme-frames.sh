#!/bin/sh
# SPDX-License-Identifier: MIT
# docs/PORTS.md's OLED frames and figures, from QEMU's emulated display:
#   sh port/lm3s6965/readme-frames.sh [build-dir]     (default build/lm3s6965)
# Builds the Cortex-M3 firmware and the host reference, runs the display test
# (oled_test.py: every frame is captured with a QMP screendump while the
# firmware waits, reduced to the panel's 128x64 grey levels and compared with
# the host), then turns the captures - not the host's frames - into
#   docs/images/oled-bunny.gif    every frame, 3x, nearest neighbour
#   docs/images/oled-strip.png    frames 0, 4, 8, 12, 16, 20 side by side
# and prints the firmware's RAM map and instruction counts (docs/PORTS.md's
# figures). Needs ImageMagick (convert) besides the build tools.
set -eu
top=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$top/build/lm3s6965}
command -v convert >/dev/null 2>&1 || { echo "$0: ImageMagick's convert not found (apt install imagemagick)" >&2; exit 2; }
cmake -S "$top" -B "$build" -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_TOOLCHAIN_FILE="$top/port/cortex-m/toolchain-arm-none-eabi.cmake" -DZLINE_CPU=cortex-m3 \
    -DZLINE_BUILD_TESTS=OFF >/dev/null
cmake --build "$build" -j "${JOBS:-2}" --target oled_demo zline_lm3s6965_host_tools >/dev/null
run=$build/port/lm3s6965/readme.run
out=$run.log
mkdir -p "$run"
python3 "$top/port/lm3s6965/oled_test.py" --elf "$build/port/lm3s6965/oled_demo.elf" \
    --reference "$build/port/lm3s6965/host/zline-oled-reference" --dir "$run" >"$out" || {
    cat "$out"
    echo "$0: the display test failed: no images written" >&2
    exit 1
}
images=$top/docs/images
mkdir -p "$images"
# -delay is in 1/100 s: 8 frames per second, looping.
convert -delay 12 -loop 0 "$run"/captures/frame-*.pgm -filter point -resize 300% -strip "$images/oled-bunny.gif"
convert "$run"/captures/frame-00.pgm "$run"/captures/frame-04.pgm "$run"/captures/frame-08.pgm \
    "$run"/captures/frame-12.pgm "$run"/captures/frame-16.pgm "$run"/captures/frame-20.pgm \
    -bordercolor white -border 2 +append -filter point -resize 200% -strip "$images/oled-strip.png"
echo "wrote $images/oled-bunny.gif and $images/oled-strip.png from $(ls "$run"/captures/*.pgm | wc -l) QEMU captures"
grep -v '^frame ' "$out"
mesh=$(find "$build/port/lm3s6965" -path '*oled_demo.dir*' -name 'bunny_mesh.c.obj' | head -n 1)
echo "flash used by the bunny's const arrays (arm-none-eabi-size, text): $(arm-none-eabi-size "$mesh" | awk 'NR == 2 { print $1 }') bytes"
