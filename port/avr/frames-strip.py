#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The ATmega2560 demo's frames as one picture: reads the lines
model_reference (or the firmware over USART0) prints ("frame N", then 128
rows of big-endian RGB565 in hex) and writes a binary PPM (P6) with the
frames side by side, four to a row.

    build/host/tests/avr_model_reference | python3 port/avr/frames-strip.py > strip.ppm
    convert strip.ppm docs/images/avr-torus.png     (ImageMagick)
"""
import sys

W, H, PER_ROW = 160, 128, 4


def frames(lines):
    """Yields each frame's pixels as RGB bytes (565 widened to 8 bits)."""
    i = 0
    while i < len(lines) and lines[i].startswith("frame"):
        px = bytearray()
        for row in lines[i + 1:i + 1 + H]:
            b = bytes.fromhex(row.strip())
            for k in range(0, len(b), 2):
                v = b[k] << 8 | b[k + 1]
                r, g, bl = v >> 11, v >> 5 & 63, v & 31
                px += bytes(((r << 3) | (r >> 2), (g << 2) | (g >> 4), (bl << 3) | (bl >> 2)))
        if len(px) != W * H * 3:
            sys.exit("frames-strip.py: frame at line %d is not %dx%d" % (i + 1, W, H))
        yield px
        i += 1 + H


def main():
    shots = list(frames(sys.stdin.read().split("\n")))
    if not shots:
        sys.exit("frames-strip.py: no frames on standard input")
    cols = min(PER_ROW, len(shots))
    rows = (len(shots) + cols - 1) // cols
    out = bytearray(cols * W * rows * H * 3)
    for n, px in enumerate(shots):
        ox, oy = n % cols * W, n // cols * H
        for y in range(H):
            at = ((oy + y) * cols * W + ox) * 3
            out[at:at + W * 3] = px[y * W * 3:(y + 1) * W * 3]
    sys.stdout.buffer.write(b"P6\n%d %d\n255\n" % (cols * W, rows * H) + out)


if __name__ == "__main__":
    main()
