#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Writes torus.obj, the ATmega2560 demo's low-poly model (port/avr): a torus
of major radius 1 and minor radius 0.42 in 15 x 10 quads, 150 vertices and
300 triangles, counter-clockwise seen from outside. Our own geometry, MIT
like the rest of the tree. Two arguments give other sizes (quads around the
ring, quads around the tube).

    python3 port/avr/make-torus.py > port/avr/torus.obj
    python3 port/avr/make-torus.py 10 6     (the 120-triangle torus of before)
"""
import math
import sys

MAJOR, MINOR = (int(a) for a in sys.argv[1:3]) if len(sys.argv) > 2 else (15, 10)
R, r = 1.0, 0.42


def main():
    print("# zline port/avr: torus %d x %d (make-torus.py)" % (MAJOR, MINOR))
    for i in range(MAJOR):
        a = 2 * math.pi * i / MAJOR
        for j in range(MINOR):
            b = 2 * math.pi * j / MINOR
            ring = R + r * math.cos(b)
            print("v %.5f %.5f %.5f" % (ring * math.cos(a), r * math.sin(b), ring * math.sin(a)))
    for i in range(MAJOR):
        for j in range(MINOR):
            a = i * MINOR + j + 1
            b = (i + 1) % MAJOR * MINOR + j + 1
            c = (i + 1) % MAJOR * MINOR + (j + 1) % MINOR + 1
            d = i * MINOR + (j + 1) % MINOR + 1
            print("f %d %d %d" % (a, d, c))
            print("f %d %d %d" % (a, c, b))


if __name__ == "__main__":
    main()
