#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Turn a golden frame of port/cortex-m/bench (golden.c: RGB565 colour, then the
16-bit depth buffer, little-endian, 320x240) into a PNG for the docs.

    python3 tools/docs/golden_png.py BUILD/port/cortex-m/bench/target-textured-frame.bin OUT.png

The colour half is expanded to 8 bits a channel by bit replication and written
as a PPM, which netpbm's pnmtopng turns
into the PNG. A file of the wrong size is an error that names it; nothing is written.
"""
import os
import subprocess
import sys

W, H = 320, 240


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: golden_png.py FRAME.bin OUT.png")
    src, out = sys.argv[1], sys.argv[2]
    data = open(src, "rb").read()
    if len(data) != W * H * 4:
        sys.exit(f"golden_png.py: {src}: {len(data)} bytes, not a {W}x{H} colour + depth frame")
    rgb = bytearray()
    for i in range(W * H):
        p = data[2 * i] | (data[2 * i + 1] << 8)
        r, g, b = p >> 11, (p >> 5) & 63, p & 31
        rgb += bytes(((r << 3) | (r >> 2), (g << 2) | (g >> 4), (b << 3) | (b >> 2)))
    ppm = b"P6\n%d %d\n255\n" % (W, H) + bytes(rgb)
    png = subprocess.run(["pnmtopng"], input=ppm, capture_output=True, check=True).stdout
    tmp = out + ".tmp"
    with open(tmp, "wb") as f:
        f.write(png)
    os.replace(tmp, out)


if __name__ == "__main__":
    main()
