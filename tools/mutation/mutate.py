#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Mutation testing of zline: does the test suite notice a broken rule?

Each mutation (tools/mutation/mutations.py) names a source file by its
basename (found by searching core/, port/display/, port/host/ and tools/
recursively, so files may move between folders), an exact text that must occur exactly once, its
replacement and a description. For each mutation the tool applies it to a
COPY of the tree (a temporary directory: the working tree is never touched,
so an interruption leaves nothing behind), rebuilds the host build
(Release), runs the CTest subset and records:

  killed    some test failed (or the mutant did not build)
  survived  every test passed: a gap in the tests
  stale     the text was not found exactly once (the code moved on)

Usage:
  python3 tools/mutation/mutate.py                  # every mutation
  python3 tools/mutation/mutate.py --sample 3       # 3, chosen by --seed
  python3 tools/mutation/mutate.py --markdown       # the table for docs/
  python3 tools/mutation/mutate.py --sample 3 --reuse-build build/ci-host
                                                    # CI: start from the host stage's build
Exit status: 1 when a mutation survived or is stale, else 0.
"""
import argparse
import datetime
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
from mutations import MUTATIONS  # noqa: E402

SEARCH_DIRS = ("core", "port/display", "port/host", "tools")
# Slow or unrelated tests left out: the cross-compiler symbol check, the
# tools' own checks and the fuzz corpus replays (the unit tests cover them).
# mutations_current would "kill" every mutant (its text is gone from the copy).
# The arduino_ and avr_ tests (about 25 s and 45 s a run) compile and run the
# core for AVR: the host suite covers the same code. config_size_table (about 60 s a run) only
# compares flash sizes: any edit of core "kills" a mutant there, which says
# nothing of the contract.
DEFAULT_EXCLUDE = ("core_no_float|stack_bound|depthcalc|obj2c|visbench|zline_bsp|mutations_current|arduino_"
                   "|config_size_table|avr_")


def find_file(tree, basename):
    hits = []
    for d in SEARCH_DIRS:
        for dirpath, _, files in os.walk(os.path.join(tree, d)):
            if basename in files:
                hits.append(os.path.join(dirpath, basename))
    return hits


def copy_tree(dst):
    """The worktree's files without build trees and git metadata."""
    def ignore(path, names):
        if os.path.abspath(path) == ROOT:
            return [n for n in names if n.startswith("build") or n in (".git", "out")]
        return []
    shutil.copytree(ROOT, dst, ignore=ignore, symlinks=True)


def cache_value(build, name):
    with open(os.path.join(build, "CMakeCache.txt"), encoding="utf-8") as f:
        for line in f:
            if line.startswith(name + ":"):
                return line.split("=", 1)[1].rstrip("\n")
    return ""


def reuse_build(old_build, tree, build):
    """BUILD: a copy of OLD_BUILD, a build of ROOT, whose absolute paths
    (Makefiles, dependency lists, CMake's cache, CTest's files) are re-pointed
    at TREE and BUILD. Every file keeps its time stamps, as copy_tree's files
    do, so make finds the copy up to date and rebuilds only what a mutation
    touches: the baseline then costs no build (CI's host stage has just built
    and tested the same tree, in Release). Binary files (objects, programs)
    are copied as they are. Returns an error message or ""."""
    old_src = cache_value(old_build, "CMAKE_HOME_DIRECTORY")
    old_bin = cache_value(old_build, "CMAKE_CACHEFILE_DIR")
    if not old_src or os.path.realpath(old_src) != os.path.realpath(ROOT):
        return "%s is not a build of %s (its source: %r)" % (old_build, ROOT, old_src)
    if cache_value(old_build, "CMAKE_BUILD_TYPE") != "Release":
        return "%s is not a Release build" % old_build
    def special(path, names):  # a test's FIFOs and sockets: scratch files it makes again
        return [n for n in names
                if not os.path.islink(os.path.join(path, n)) and not os.path.isdir(os.path.join(path, n))
                and not os.path.isfile(os.path.join(path, n))]
    shutil.copytree(old_build, build, symlinks=True, ignore=special)
    # the build folder first: it is inside the source folder
    pattern = re.compile(b"(" + re.escape(old_bin.encode()) + b"|" + re.escape(old_src.encode()) + b")(?![\\w.+-])")
    new = {old_bin.encode(): build.encode(), old_src.encode(): tree.encode()}
    for dirpath, _, files in os.walk(build):
        for name in files:
            path = os.path.join(dirpath, name)
            if os.path.islink(path):
                target = os.readlink(path)
                if pattern.match(target.encode()):
                    os.remove(path)
                    os.symlink(pattern.sub(lambda m: new[m.group(1)], target.encode()).decode(), path)
                continue
            with open(path, "rb") as f:
                data = f.read()
            if b"\0" in data or not pattern.search(data):
                continue  # binary, or no path of the old trees
            st = os.stat(path)
            with open(path, "wb") as f:
                f.write(pattern.sub(lambda m: new[m.group(1)], data))
            os.utime(path, ns=(st.st_atime_ns, st.st_mtime_ns))
    return ""


def run(cmd, cwd, timeout):
    try:
        p = subprocess.run(cmd, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=timeout)
        return p.returncode, p.stdout.decode(errors="replace")
    except subprocess.TimeoutExpired:
        return 124, "timeout"


def failed_tests(out, status=None):
    """Names in ctest's closing list of failed tests; with STATUS (e.g.
    "Timeout") only those failed that way."""
    names = []
    for line in out.splitlines():
        line = line.strip()
        # ctest's closing list names skipped tests too ("(Skipped)", e.g.
        # budget_raises in the copy, which has no git history): not killers
        if line and line[0].isdigit() and " - " in line and "(" in line and "(Skipped)" not in line \
                and "(Not Run)" not in line and "(Disabled)" not in line \
                and (status is None or "(%s)" % status in line):
            names.append(line.split(" - ", 1)[1].split(" (")[0])
    return names


# ctest's default limit per test (tests with a TIMEOUT property keep theirs),
# and the limit of a timed-out test's second run, alone.
TEST_TIMEOUT = 120
RETRY_TIMEOUT = 600


def run_suite(build, tree, args, stop):
    """The CTest suite of BUILD (--exclude, --tests; STOP: --stop-on-failure).
    Returns (rc, output, names of the failed tests).

    A test that only timed out is not taken as failed at once: with two jobs
    on two cores (and in CI after a long day's load) a slow test can pass
    TEST_TIMEOUT seconds (core_dependencies once did, unmutated). It runs
    again alone with RETRY_TIMEOUT seconds: timing out again (a hang, e.g. a
    mutant's endless loop) is a failure; passing, it is not, and the rest of
    the suite (which --stop-on-failure cut short) runs again without it. A
    test that failed any other way is a failure at once."""
    base = ["ctest", "--test-dir", build, "-j", str(args.jobs), "--timeout", str(TEST_TIMEOUT)]
    sel = ["-R", args.tests] if args.tests else []
    exclude = args.exclude
    log = ""
    for _ in range(3):  # each round settles at least one timed-out test as passing
        rc, out = run(base + ["-E", exclude] + (["--stop-on-failure"] if stop else []) + sel, tree, 3600)
        log += out
        failed = failed_tests(out)
        timed = failed_tests(out, "Timeout")
        if rc == 0 or not failed or len(timed) != len(failed):
            return rc, log, failed
        only = "^(" + "|".join(re.escape(t) for t in timed) + ")$"
        log += "\nmutate: timed out, run again alone with %d s: %s\n" % (RETRY_TIMEOUT, " ".join(timed))
        rc2, out2 = run(["ctest", "--test-dir", build, "-j", "1", "--timeout", str(RETRY_TIMEOUT), "-R", only],
                        tree, 3600)
        log += out2
        if rc2 != 0:
            return rc2, log, failed_tests(out2) or timed
        exclude = "(" + exclude + ")|" + only
    return 1, log + "\nmutate: tests kept timing out under load\n", timed


def check_current(chosen):
    """The CTest mutations_current: a mutation whose text the code no longer
    has would be reported stale by the daily sample in CI, so say so at once,
    where the code was changed."""
    stale = [m for m in chosen
             if len(find_file(ROOT, m[1])) != 1 or open(find_file(ROOT, m[1])[0], encoding="utf-8").read().count(m[2]) != 1]
    for mid, base, find, _repl, _desc in stale:
        print("mutate: %s is stale: %r is not in %s exactly once (update tools/mutation/mutations.py)" % (mid, find, base))
    print("mutate: %d of %d mutations current" % (len(chosen) - len(stale), len(chosen)))
    return 1 if stale else 0


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--sample", type=int, default=0, help="run only N mutations chosen by --seed")
    ap.add_argument("--seed", default=datetime.date.today().isoformat(), help="seed of --sample (default: today)")
    ap.add_argument("--only", default="", help="run the mutations whose id contains this text")
    ap.add_argument("--exclude", default=DEFAULT_EXCLUDE, help="ctest -E regex")
    ap.add_argument("--tests", default="", help="ctest -R regex (default: every test not excluded)")
    ap.add_argument("--jobs", type=int, default=int(os.environ.get("JOBS", "2")))
    ap.add_argument("--markdown", action="store_true", help="print the result as a Markdown table")
    ap.add_argument("--keep", action="store_true", help="keep the temporary tree (for debugging)")
    ap.add_argument("--reuse-build", default="",
                    help="a Release build of this tree (CI: build/ci-host): copied for the baseline instead of a "
                         "build from nothing; its ZLINE_SHARED_DIR is kept (the copy's ../shared is --shared)")
    ap.add_argument("--shared", default=os.path.join(os.path.dirname(ROOT), "shared"), help="ZLINE_SHARED_DIR")
    ap.add_argument("--check-current", action="store_true",
                    help="only check that every mutation's text is still in the tree, once (no build): "
                         "exit 1 naming the stale ones")
    args = ap.parse_args()

    chosen = [m for m in MUTATIONS if args.only in m[0]]
    if args.check_current:
        return check_current(chosen)
    if args.sample:
        chosen = random.Random(args.seed).sample(chosen, min(args.sample, len(chosen)))
    start = time.time()
    tmp = tempfile.mkdtemp(prefix="zline-mutate-")
    tree, build = os.path.join(tmp, "src"), os.path.join(tmp, "build")
    results = []
    try:
        copy_tree(tree)
        # the copy's ../shared, as the tree's: a build configured from the tree
        # names ZLINE_SHARED_DIR as <tree>/../shared
        os.symlink(os.path.abspath(args.shared), os.path.join(tmp, "shared"))
        if args.reuse_build:
            error = reuse_build(os.path.abspath(args.reuse_build), tree, build)
            rc, out = (2, "mutate: --reuse-build: " + error) if error else (0, "")
        else:
            rc, out = run(["cmake", "-S", tree, "-B", build, "-DCMAKE_BUILD_TYPE=Release",
                           "-DZLINE_SHARED_DIR=" + args.shared], tree, 600)
        if rc == 0:
            rc, out = run(["cmake", "--build", build, "-j", str(args.jobs)], tree, 1800)
        if rc != 0:
            print(out)
            print("mutate: the unmutated tree does not build")
            return 2
        rc, out, _ = run_suite(build, tree, args, stop=False)
        if rc != 0:
            print(out)
            print("mutate: the unmutated tree fails its tests: no mutation can be judged")
            return 2
        print("mutate: baseline built and green in %.0f s; %d mutation(s)" % (time.time() - start, len(chosen)),
              flush=True)
        for mid, base, find, repl, desc in chosen:
            hits = find_file(tree, base)
            text = open(hits[0], encoding="utf-8").read() if len(hits) == 1 else ""
            if len(hits) != 1 or text.count(find) != 1:
                results.append((mid, base, desc, "stale", "text not found exactly once"))
                print("%-28s stale" % mid, flush=True)
                continue
            try:
                with open(hits[0], "w", encoding="utf-8") as f:
                    f.write(text.replace(find, repl))
                rc, out = run(["cmake", "--build", build, "-j", str(args.jobs)], tree, 1800)
                if rc != 0:
                    verdict, by = "killed", "(does not build)"
                else:
                    # A mutant is killed by its first failing test: without --markdown
                    # (whose table names the killers) CTest stops there. A survivor still
                    # passes every test: the verdict is the same, only the list is shorter.
                    rc, out, names = run_suite(build, tree, args, stop=not args.markdown)
                    verdict = "killed" if rc != 0 else "survived"
                    by = ", ".join(names[:3]) + (" ..." if len(names) > 3 else "")
            finally:
                with open(hits[0], "w", encoding="utf-8") as f:
                    f.write(text)
            results.append((mid, base, desc, verdict, by))
            print("%-28s %-8s %s" % (mid, verdict, by), flush=True)
        # leave the copy's build as it was (not needed: the copy is removed)
    finally:
        if args.keep:
            print("kept " + tmp)
        else:
            shutil.rmtree(tmp, ignore_errors=True)
    killed = sum(1 for r in results if r[3] == "killed")
    total = len(results)
    if args.markdown:
        print("\n| mutation | file | rule broken | result | killed by |")
        print("|---|---|---|---|---|")
        for mid, base, desc, verdict, by in results:
            print("| `%s` | %s | %s | %s | %s |" % (mid, base, desc, verdict, by.replace("|", "\\|")))
        print("\nKill rate: %d of %d (%d%%)" % (killed, total, (100 * killed // total) if total else 0))
    print("mutate: %d killed, %d survived, %d stale, of %d (%.0f s)" %
          (killed, sum(1 for r in results if r[3] == "survived"), sum(1 for r in results if r[3] == "stale"), total,
           time.time() - start))
    return 0 if killed == total else 1


if __name__ == "__main__":
    sys.exit(main())
