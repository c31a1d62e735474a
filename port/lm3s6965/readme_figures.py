#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The OLED figures of docs/PORTS.md against the firmware's own report.

    python3 port/lm3s6965/readme_figures.py FIRMWARE_LOG docs/PORTS.md

FIRMWARE_LOG is the firmware.log that oled_test.py writes (the RAM map and
the instruction counts the demo prints). Every figure of the document's "On a
real display" section (docs/PORTS.md; README's until 0.3.0) that the firmware reports (work buffer, other .bss, .data,
stack reserved and used, the total and what is free, flash, instructions per
frame, the frame-rate estimate) must be written there as measured; a drift
names the figure and both values, and the exit status is 1. CTest runs it
after oled_display_equals_host (oled_readme_figures), so the document cannot
drift from the firmware; sh port/lm3s6965/readme-frames.sh prints fresh figures.
"""
import re
import sys


def grab(log, pattern, name):
    m = re.search(pattern, log, re.M)
    if not m:
        sys.exit("readme_figures: the firmware log has no %s (pattern %r)" % (name, pattern))
    return m.groups()


def commas(n):
    return "{:,}".format(int(n))


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__.strip().split("\n\n")[1])
    try:
        log = open(sys.argv[1], encoding="utf-8", errors="replace").read()
    except OSError as e:
        sys.exit("readme_figures: cannot read the firmware log (run oled_test.py first): %s" % e)
    doc = sys.argv[2]
    readme = open(doc, encoding="utf-8").read()
    start = readme.find("## On a real display")
    if start < 0:
        sys.exit("readme_figures: %s has no section '## On a real display'" % doc)
    section = readme[start:readme.find("\n## ", start + 1)]

    work, = grab(log, r"^\s*work buffer .*?(\d+) bytes", "work buffer")
    other, = grab(log, r"^\s*other \.bss\s+(\d+) bytes", "other .bss")
    data, = grab(log, r"^\s*\.data\s+(\d+) bytes", ".data")
    stack, = grab(log, r"^\s*stack reserved\s+(\d+) bytes", "stack reserved")
    used, = grab(log, r"^\s*used at most\s+(\d+) bytes", "stack used")
    total, free = grab(log, r"^\s*total\s+(\d+) bytes \((\d+) free\)", "total")
    flash, = grab(log, r"^flash: (\d+) bytes", "flash")
    lo, hi, mean = grab(log, r"min (\d+), max (\d+), mean (\d+)", "instructions per frame")
    fps, = grab(log, r"ESTIMATE at 50 MHz.*?: ([0-9.]+) frames/s", "frame-rate estimate")

    # (what, the README text that must be there)
    want = [
        ("work buffer", r"\| zline work buffer [^|]*\| %s \|" % commas(work)),
        ("other .bss", r"\| other \.bss [^|]*\| %s \|" % commas(other)),
        (".data", r"\| \.data \| %s \|" % commas(data)),
        ("stack reserved", r"\| stack reserved [^|]*\| %s \|" % commas(stack)),
        ("stack used", r"\| of which used at most [^|]*\| %s \|" % commas(used)),
        ("total", r"\*\*%s\*\* \(%s free\)" % (commas(total), commas(free))),
        ("flash", r"\| whole image [^|]*\| %s \|" % commas(flash)),
    ]
    bad = 0
    # Instruction counts: SysTick counts 1.6 ticks an instruction under
    # -icount shift=5, so a count may move by one between runs; 0.1 % as
    # the tolerance, and the estimate derived from them to 0.1 frame/s.
    m = re.search(r"([0-9,]+) to ([0-9,]+) over the \d+ frames, mean ([0-9,]+)\.", section)
    f = re.search(r"at most ([0-9.]+) frames", section)
    got = [int(g.replace(",", "")) for g in m.groups()] if m else None
    if got is None or any(abs(g - int(w)) > int(w) // 1000 for g, w in zip(got, (lo, hi, mean))):
        print("DRIFT %s, On a real display: instructions per frame: document %s, the firmware %s to %s, mean %s" %
              (doc, m.group(0) if m else "(not found)", commas(lo), commas(hi), commas(mean)))
        bad += 1
    if f is None or abs(float(f.group(1)) - float(fps)) > 0.11:
        print("DRIFT %s, On a real display: frame-rate estimate: document %s, the firmware %s" %
              (doc, f.group(1) if f else "(not found)", fps))
        bad += 1
    for what, pattern in want:
        if not re.search(pattern, section):
            print("DRIFT %s, On a real display: %s: the firmware reports %s" %
                  (doc, what, pattern.replace("\\", "")))
            bad += 1
    print("readme_figures: %d of %d figures as the firmware reports them" % (len(want) + 2 - bad, len(want) + 2))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
