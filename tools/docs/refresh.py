#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Refresh the measured tables of docs/*.md (and README's headline) from the commands that produce them.

    python3 tools/docs/refresh.py [--check] [--cortex-m BUILD_DIR] [--host HOST_BUILD_DIR]
                                  [--riscv BUILD_DIR] [--riscv-only] [--cortex-m0 BUILD_DIR]
                                  [--slots BUILD_PREFIX] [--core-size WORK_DIR] [--config-size WORK_DIR]
    python3 tools/docs/refresh.py --check-headline

Runs port/cortex-m/bench/measure.sh and port/cortex-m/bench/profile.sh (KEY=total and
KEY=total_vcache), with --host also tools/bench/measure.sh on the bunny and
tools/visbench/measure.sh (a host build with the render command's targets, and valgrind), with
--riscv also port/riscv/bench/measure.sh (rv32imac; --riscv-only: that alone, build/rv32imac-bench
unless --riscv names one), with --cortex-m0 also port/cortex-m/bench/measure-m0.sh (a
ZLINE_CPU=cortex-m0 build; without --cortex-m, that alone: the Cortex-M4 measurement runs only
when --cortex-m names its build or no --cortex-m0 is given), with --slots also port/cortex-m/bench/slot-sweep.sh (five Cortex-M4
builds, BUILD_PREFIX-N; the table is not part of --check, which would take minutes), with
--core-size also tools/size/core-size.sh (the whole library's flash per CPU and float ABI, the
table of docs/PORTING.md; about two minutes, not part of --check either), with --config-size also
tools/size/config-size.sh (README's core flash per configuration, issue 23; about three minutes, checked
by CTest config_size_table instead of --check), splits their output into sections ("### title"
plus the markdown table under it) and, in every document:
  * replaces the table under a heading "### title" or "#### title" with the table of the section of that
    title (profile headings match up to their " (" suffix, which names marks that move);
  * replaces the table after a line "<!-- measured: title -->" the same way;
  * replaces the instruction and RAM columns of docs/MEASUREMENTS.md's visibility table (rows
    mapped below);
  * regenerates README's headline table (after the line "<!-- headline: ... -->") from
    docs/MEASUREMENTS.md's tables as refreshed: the bunny's RAM in frame and scanline mode
    ("RAM, benchmark scene"), its instructions per frame on Cortex-M4 and Cortex-M0 (the two
    "Summary" tables), copied, not re-measured (see HEADLINE below).
Nothing else in a document changes; prose that quotes a figure must be edited by hand
(grep for the old value). Prints what it replaced.

With --check nothing is written: every figure of docs/MEASUREMENTS.md's measured tables (the
tables README held until 0.3.0) and of README's headline table is compared with the fresh
measurement, and the exit status is 1 when one drifted: an instruction count (any other
number) by more than 0.5 % (a ratio printed with decimals may also differ by one unit of its
last digit, its rounding), a byte count (a column whose heading names bytes, RAM, flash or
stack) at all. CTest runs it in the Cortex-M4 build (docs_measured_tables), with --cortex-m0
alone in the Cortex-M0 build (docs_measured_tables_m0) and with --riscv-only in the rv32imac
build (docs_measured_tables_riscv), so the documents cannot drift from the code.

--check-headline measures nothing: README's headline table must be exactly the one generated
from docs/MEASUREMENTS.md as it stands (CTest docs_headline_table, host build), so the headline
cannot be edited by hand or left behind when the measured tables are refreshed.
"""
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DOCS = ["docs/MEASUREMENTS.md", "docs/CORTEX_M.md", "docs/VISIBILITY.md", "docs/PORTING.md",
        "port/riscv/README.md", "README.md"]
MEASUREMENTS = "docs/MEASUREMENTS.md"
# What --check compares with the fresh measurement: the measured tables README held until
# 0.3.0, and README's headline generated from them.
CHECKED = [MEASUREMENTS, "README.md"]
# docs/MEASUREMENTS.md visibility table row -> bench_vis.c method
VIS_ROWS = {
    "z-buffer, frame mode": "zbuffer",
    "z-buffer, scanline mode": "scanline",
    "scan-line AET (no depth buffer)": "aet",
    "painter's (sort by farthest vertex)": "painter",
    "BSP, back to front": "bsp-b2f",
    "ray caster (the reference)": "raycast",
}


def run(cmd, env=None):
    e = dict(os.environ)
    e.update(env or {})
    out = subprocess.run(cmd, cwd=ROOT, env=e, check=True, capture_output=True, text=True).stdout
    return out


def key_of(title):
    """Profile headings end in ' (bench_..., marks I..J)': match without it."""
    return re.sub(r" \(bench_[^)]*\)$", "", title.strip())


def sections(text):
    """{key: table lines} for every '### title' followed by a table. A profile
    section (key 'SCENE, ... mode ...') keeps the notes under its table too
    (origin split, libgcc calls, the check line), up to the next heading."""
    found, title, lines = {}, None, text.splitlines()
    for i, line in enumerate(lines):
        if re.match(r"#{3,4} ", line):
            title = key_of(line.split(" ", 1)[1])
        elif title and line.startswith("|"):
            j = i
            while j < len(lines) and lines[j].startswith("|"):
                j += 1
            if is_profile(title):
                while j < len(lines) and not lines[j].startswith("#"):
                    j += 1
                while j > i and lines[j - 1] == "":
                    j -= 1
            found.setdefault(title, lines[i:j])
            title = None
    return found


def is_profile(key):
    return re.match(r"[a-z_]+, (frame|scanline) mode", key) is not None


def replace_table(lines, start, table, through_notes=False):
    """Replace the first table at or after line index start (with through_notes,
    also the lines after it up to the next heading, less trailing blank lines);
    returns the new lines."""
    i = start
    while i < len(lines) and not lines[i].startswith("|"):
        if lines[i].startswith("#") and i > start:
            return lines  # no table before the next heading
        i += 1
    j = i
    while j < len(lines) and lines[j].startswith("|"):
        j += 1
    if through_notes:
        while j < len(lines) and not lines[j].startswith("#"):
            j += 1
        while j > i and lines[j - 1] == "":
            j -= 1
    return lines[:i] + table + lines[j:]


def number(cell):
    """The value of a table cell holding a number (commas, bold, % allowed), else None;
    with the count of decimals printed."""
    c = cell.replace("**", "").replace(",", "").replace("%", "").strip()
    if not re.fullmatch(r"-?\d+(\.\d+)?", c):
        return None
    return float(c), (len(c.split(".")[1]) if "." in c else 0)


def drift(old_lines, new_lines, doc):
    """Figures of the measured tables that drifted (see --check); [] when none."""
    bad = []
    if len(old_lines) != len(new_lines):
        return [f"{doc}: the tables changed shape ({len(old_lines)} lines, fresh {len(new_lines)})"]
    header = []
    for old, new in zip(old_lines, new_lines):
        if not old.startswith("|"):
            header = []
            continue
        cells_o = [c.strip() for c in old.split("|")]
        if not header:
            header = cells_o
            continue
        if old == new:
            continue
        cells_n = [c.strip() for c in new.split("|")]
        if len(cells_o) != len(cells_n):
            bad.append(f"{doc}: row changed shape: {old!r} -> {new!r}")
            continue
        for k, (a, b) in enumerate(zip(cells_o, cells_n)):
            if a == b:
                continue
            col = header[k] if k < len(header) else ""
            na, nb = number(a), number(b)
            if na is None or nb is None:
                bad.append(f"{doc}: {cells_o[1]} / {col}: {a} -> {b}")
                continue
            (va, da), (vb, _) = na, nb
            exact = re.search(r"\b(bytes|RAM|flash|stack)\b", col, re.I) is not None
            rel = abs(vb - va) / max(abs(va), 1e-9)
            ok = not exact and (rel <= 0.005 or (da > 0 and abs(vb - va) <= 10 ** -da + 1e-9))
            if not ok:
                bad.append(f"{doc}: {cells_o[1]} / {col}: written {a}, measured {b}" +
                           ("" if exact else f" ({100 * rel:+.2f} %)"))
    return bad


def read_lines(doc):
    return open(os.path.join(ROOT, doc)).read().split("\n")


def refresh(doc, lines, secs, vis):
    """The document's lines with every measured table replaced; (lines, titles replaced)."""
    lines = list(lines)
    done = []
    i = 0
    while i < len(lines):
        line = lines[i]
        key = None
        if re.match(r"#{3,4} ", line):
            key = key_of(line.split(" ", 1)[1])
        m = re.match(r"<!-- measured: (.*) -->$", line)
        if m:
            key = m.group(1).strip()
        if key in secs:
            lines = replace_table(lines, i + 1, secs[key], is_profile(key))
            done.append(key)
        i += 1
    for n, line in enumerate(lines):
        cells = [c.strip() for c in line.split("|")]
        if doc == MEASUREMENTS and len(cells) > 4 and cells[1] in VIS_ROWS and vis.get(VIS_ROWS[cells[1]]):
            cells[3] = vis[VIS_ROWS[cells[1]]][0]
            if vis[VIS_ROWS[cells[1]]][1]:
                cells[2] = vis[VIS_ROWS[cells[1]]][1]
            lines[n] = "| " + " | ".join(cells[1:-1]) + " |"
    return lines, done


# README's headline: (row label, RAM row of "RAM, benchmark scene", instruction column of the
# two Summary tables' bunny row). Frame mode is the default call (no caller vertex cache), as the
# RAM table's frame row; scanline mode's RAM includes its vertex cache and triangle lists.
HEADLINE_MARK = "<!-- headline: generated from docs/MEASUREMENTS.md by tools/docs/refresh.py -->"
HEADLINE_RAM = "RAM, benchmark scene (bunny, 320x240, RGB565)"
HEADLINE_M4 = "Summary, Cortex-M4 -O2 (README)"
HEADLINE_M0 = "Summary, Cortex-M0 -O2 (README)"
HEADLINE = [
    ("full-frame z-buffer (`zl_draw_mesh`)", "frame (zl_draw_mesh, no vertex cache)", "frame mode"),
    ("scanline mode (one row of depth)", "scanline (band=1)", "scanline mode"),
]


def table_rows(lines, key):
    """Cells of the table under the heading or measured marker titled key."""
    for i, line in enumerate(lines):
        title = key_of(line.split(" ", 1)[1]) if re.match(r"#{3,4} ", line) else None
        m = re.match(r"<!-- measured: (.*) -->$", line)
        if (m.group(1).strip() if m else title) != key:
            continue
        j = i + 1
        while j < len(lines) and not lines[j].startswith("|") and not lines[j].startswith("#"):
            j += 1
        rows = []
        while j < len(lines) and lines[j].startswith("|"):
            rows.append([c.strip() for c in lines[j].split("|")[1:-1]])
            j += 1
        if len(rows) > 2:
            return rows
    sys.exit(f"refresh.py: {MEASUREMENTS} has no table '{key}' (README's headline is made from it)")


def cell(rows, row, col):
    if col not in rows[0]:
        sys.exit(f"refresh.py: {MEASUREMENTS}: no column '{col}' in the table of '{rows[0]}'")
    for r in rows[2:]:
        if r[0] == row:
            return "{:,}".format(int(r[rows[0].index(col)].replace(",", "")))
    sys.exit(f"refresh.py: {MEASUREMENTS}: no row '{row}' for README's headline")


def headline(measurements):
    ram, m4, m0 = (table_rows(measurements, k) for k in (HEADLINE_RAM, HEADLINE_M4, HEADLINE_M0))
    table = ["| bunny, 320x240 | RAM (bytes) | instructions per frame, Cortex-M4 | instructions per frame, Cortex-M0 |",
             "|---|---:|---:|---:|"]
    for label, ram_row, col in HEADLINE:
        table.append(f"| {label} | {cell(ram, ram_row, 'total RAM')} | {cell(m4, 'bunny', col)} | "
                     f"{cell(m0, 'bunny', col)} |")
    return table


def with_headline(readme, measurements):
    """README's lines with the table after HEADLINE_MARK regenerated."""
    if HEADLINE_MARK not in readme:
        sys.exit(f"refresh.py: README.md has no line {HEADLINE_MARK}")
    return replace_table(readme, readme.index(HEADLINE_MARK) + 1, headline(measurements))


def check_headline():
    readme = read_lines("README.md")
    fresh = with_headline(readme, read_lines(MEASUREMENTS))
    if fresh == readme:
        print(f"README.md: the headline table is the one generated from {MEASUREMENTS}")
        return 0
    i = readme.index(HEADLINE_MARK)
    print(f"README.md: the headline table differs from the one generated from {MEASUREMENTS} "
          "(python3 tools/docs/refresh.py with any measurement rewrites it):")
    for old, new in zip(readme[i:i + 6], fresh[i:i + 6]):
        if old != new:
            print(f"  README:    {old}\n  generated: {new}")
    return 1


def m0_profiles(build):
    """profile.sh on the Cortex-M0 build (bunny: the cached frame, the default call and
    scanline mode), its headings marked ", Cortex-M0" so they do not take the M4 tables."""
    out = ""
    for key in ("total_vcache", "total"):
        p = run(["sh", "port/cortex-m/bench/profile.sh", build], {"CPU": "cortex-m0", "KEY": key})
        if key == "total_vcache":
            p = p.replace("frame mode, -O2", "frame mode with the vertex cache, -O2")
        out += "\n" + re.sub(r"^(### .*?, -O2)", r"\1, Cortex-M0", p, flags=re.M)
    return out


def main():
    build, host, riscv, cortex_m = "build/cortex-m4-bench", None, None, True
    cortex_m0, cortex_m_named, slots, core_size, config_size = None, False, None, None, None
    args = sys.argv[1:]
    if args == ["--check-headline"]:
        sys.exit(check_headline())
    check = False
    if args and args[0] == "--check":
        check, args = True, args[1:]
    while args and args[0] in ("--cortex-m", "--host", "--riscv", "--riscv-only", "--cortex-m0", "--slots",
                               "--core-size", "--config-size"):
        if args[0] == "--riscv-only":
            cortex_m, riscv = False, riscv or "build/rv32imac-bench"
            args = args[1:]
            continue
        if len(args) < 2:
            sys.exit(f"refresh.py: {args[0]} needs a build directory")
        if args[0] == "--cortex-m":
            build, cortex_m_named = args[1], True
        elif args[0] == "--cortex-m0":
            cortex_m0 = args[1]
        elif args[0] == "--host":
            host = args[1]
        elif args[0] == "--slots":
            slots = args[1]
        elif args[0] == "--core-size":
            core_size = args[1]
        elif args[0] == "--config-size":
            config_size = args[1]
        else:
            riscv = args[1]
        args = args[2:]
    if (cortex_m0 or core_size or config_size) and not cortex_m_named:
        cortex_m = False
    text = ""
    if cortex_m0:
        text += run(["sh", "port/cortex-m/bench/measure-m0.sh", cortex_m0])
        if not check:  # docs/CORTEX_M.md only: --check compares README
            text += "\n" + m0_profiles(cortex_m0)
    if cortex_m:
        text += run(["sh", "port/cortex-m/bench/measure.sh", build])
    if host:
        text += "\n" + run(["sh", "tools/bench/measure.sh", host, "port/host/models/bunny.obj"])
        text += "\n" + run(["sh", "tools/visbench/measure.sh", host])
    if riscv:
        text += "\n" + run(["sh", "port/riscv/bench/measure.sh", "rv32imac", riscv])
    if slots:
        text += "\n" + run(["sh", "port/cortex-m/bench/slot-sweep.sh", slots])
    if core_size:
        text += "\n### Core size per CPU (tools/size/core-size.sh)\n\n" + run(["sh", "tools/size/core-size.sh", core_size])
    if config_size:
        text += ("\n### Core flash per configuration (tools/size/config-size.sh)\n\n" +
                 run(["sh", "tools/size/config-size.sh", config_size]))
    if cortex_m:
        text += "\n" + run(["sh", "port/cortex-m/bench/profile.sh", build], {"KEY": "total"})
        vc = run(["sh", "port/cortex-m/bench/profile.sh", build], {"KEY": "total_vcache"})
        vc = vc.replace("frame mode, -O2", "frame mode with the vertex cache, -O2")
        text += "\n" + vc
    secs = sections(text)
    vis = {}
    for row in secs.get("Visibility methods on Cortex-M4 (bunny, -O2)", [])[2:]:
        cells = [c.strip() for c in row.split("|")]
        vis[cells[1]] = (cells[2], cells[3] if len(cells) > 4 else "")
    original = {doc: read_lines(doc) for doc in DOCS}
    updated, done = {}, {}
    for doc in DOCS:
        updated[doc], done[doc] = refresh(doc, original[doc], secs, vis)
    updated["README.md"] = with_headline(updated["README.md"], updated[MEASUREMENTS])
    if updated["README.md"] != original["README.md"]:
        done["README.md"].append("headline (from " + MEASUREMENTS + ")")
    if check:
        bad = []
        for doc in CHECKED:
            bad += drift(original[doc], updated[doc], doc)
        for b in bad:
            print("DRIFT " + b)
        names = " and ".join(CHECKED)
        print(f"{names}: {len(bad)} figures drifted from the measurement" if bad else
              f"{names}: every measured figure within its tolerance")
        sys.exit(1 if bad else 0)
    for doc in DOCS:
        open(os.path.join(ROOT, doc), "w").write("\n".join(updated[doc]))
        print(f"{doc}: {len(done[doc])} tables: " + "; ".join(done[doc]))


if __name__ == "__main__":
    main()
